/* SPDX-License-Identifier: MIT */
/* gks_pipe_dispatch.c -- targets and the send to a driver (gks_pipe_dispatch.h). */
#include "gks_pipe_dispatch.h"
#include "gks_export.h"
#include "gks_state.h"
#include <string.h>

void gks_pipe_target_current(gks_pipe_target *t, const gks_pipe_norm *nc)
{
    const gks_segment *seg = nc->seg;
    memset(t, 0, sizeof *t);
    t->a = &gks_ctx()->sl->attrs;
    memcpy(t->pat_m, nc->pat, sizeof t->pat_m);
    t->done = seg && !seg->vis; /* an invisible open segment: stored, not drawn */
}

gks_ws *gks_pipe_next_ws(gks_pipe_target *t)
{
    if (t->done)
        return NULL;
    if (t->only) {
        t->done = 1;
        return t->only;
    }
    gks_context *c = gks_ctx();
    while (t->k < c->sl->n_open) {
        gks_ws *ws = c->ws[t->k++];
        if (ws->state == GWS_ACTIVE)
            return ws;
    }
    t->done = 1;
    return NULL;
}

void gks_pipe_prim_common(gks_prim *p, const gks_cur_attrs *a)
{
    p->view_ind = a->view_ind;
    p->area_props[0] = a->area_props[0];
    p->area_props[1] = a->area_props[1];
    p->refl_eq[0] = a->refl_eq[0];
    p->refl_eq[1] = a->refl_eq[1];
    p->light_mask = a->light_mask;
    p->shading[0] = a->int_shad[0];
    p->shading[1] = a->int_shad[1];
}

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
