/* SPDX-License-Identifier: MIT */
/* gks_pipe_dispatch.c -- targets and the send to a driver (gks_pipe_dispatch.h). */
#include "gks_pipe_dispatch.h"
#include "gks_export.h"
#include "gks_state.h"
#include <string.h>

#ifdef GKS_FAULT_INJECTION
/* Test hook, only in the test build of the modules (gks3d_test): every primitive a
 * driver receives is first passed to hook (NULL = none). */
GKS_TEST_API void gks_test_set_prim_hook(gks_prim_hook hook, void *ctx)
{
    gks_ctx()->prim_hook = hook;
    gks_ctx()->prim_hook_ctx = ctx;
}
#endif

int gks_pipe_send(gks_ws *ws, const gks_prim *p)
{
#ifdef GKS_FAULT_INJECTION
    gks_context *c = gks_ctx();
    if (c->prim_hook)
        c->prim_hook(c->prim_hook_ctx, ws->id, p);
#endif
    if (!ws->drv->primitive)
        return 0;
    int err = ws->drv->primitive(ws, p);
    if (!err)
        ws->disp_empty = GDISP_NOT_EMPTY;
    return err;
}

int gks_pipe_send_mesh(gks_ws *ws, const gks_mesh *m)
{
#ifdef GKS_FAULT_INJECTION
    if (gks_ctx()->prim_hook)
        return GKS_WS_MESH_FACETS;
#endif
    if (!ws->drv->mesh)
        return GKS_WS_MESH_FACETS;
    int err = ws->drv->mesh(ws, m);
    if (!err)
        ws->disp_empty = GDISP_NOT_EMPTY;
    return err;
}
