/* SPDX-License-Identifier: MIT */
/*
 * ws_render.c -- the routing by HLHSR mode between the classic renderer and the tracer,
 * for every drawing workstation (ws_render.h).
 */
#include "ws_render.h"
#include "gks_alloc.h"

ws_route ws_render_route(const gks_ws *ws, const gks_prim *prim)
{
    if (ws->hlhsr_mode == GHLHSR_RAYTRACE &&
        (prim->kind == GKS_PRIM_FILL_AREA || prim->kind == GKS_PRIM_CELL_ARRAY))
        return WS_ROUTE_TRACE;
    return WS_ROUTE_CLASSIC;
}

ws_render *ws_render_new(void)
{
    ws_render *r = gks_calloc_array(1, sizeof *r);
    if (!r)
        return NULL;
    r->dl = ws_dlist_new();
    if (!r->dl) {
        gks_free(r);
        return NULL;
    }
    r->rt = ws_rt_new(r->dl);
    r->classic = ws_classic_new(r->dl);
    if (!r->classic || !r->rt) {
        ws_render_free(r);
        return NULL;
    }
    return r;
}

void ws_render_free(ws_render *r)
{
    if (!r)
        return;
    ws_rt_free(r->rt); /* stops the recording worker, which reads the list */
    ws_classic_free(r->classic);
    ws_dlist_free(r->dl);
    gks_free(r);
}

void ws_render_reset(ws_render *r)
{
    ws_rt_reset(r->rt); /* first: no worker reads the list afterwards */
    ws_classic_reset(r->classic);
    ws_dlist_reset(r->dl);
}

int ws_render_prim(ws_render *r, gks_ws *ws, gks_raster_fb *fb, const gks_prim *prim)
{
    if (ws_render_route(ws, prim) == WS_ROUTE_TRACE)
        return ws_rt_record(r->rt, ws, prim);
    return ws_classic_prim(r->classic, ws, fb, prim);
}

int ws_render_mesh(ws_render *r, gks_ws *ws, const gks_mesh *m)
{
    if (ws_render_route(ws, &m->prim) == WS_ROUTE_TRACE)
        return ws_rt_record_mesh(r->rt, ws, m);
    return GKS_WS_MESH_FACETS;
}
