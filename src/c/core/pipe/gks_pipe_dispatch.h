/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_dispatch.h -- the last stage of the output pipeline: the workstations a
 * primitive goes to (the active ones with the current attributes, or one workstation with
 * a segment's stored binding at replay) and the hand-over to their drivers (after the test
 * hook).
 */
#ifndef GKS_PIPE_DISPATCH_H
#define GKS_PIPE_DISPATCH_H
#include "gks_private.h"
#include "gks_context.h"
#include "gks_pipe_norm.h"

typedef struct gks_pipe_target {
    const gks_cur_attrs *a;
    const double (*pat_m)[4];  /* WC3 -> final NDC3, for pattern boxes */
    gks_ws *only;              /* regeneration target; NULL: the active workstations */
    int k, done;
} gks_pipe_target;

/* The active workstations with the current attributes (none if the open segment of nc is
 * invisible); t refers to nc's pattern matrix. */
static inline void gks_pipe_target_current(gks_pipe_target *t, const gks_pipe_norm *nc)
{
    const gks_segment *seg = nc->seg;
    *t = (gks_pipe_target){ .a = &gks_ctx()->sl->attrs, .pat_m = (const double (*)[4])nc->pat,
                            .done = seg && !seg->vis }; /* invisible: stored, not drawn */
}
/* Hands p to ws's driver (after the test hook). 0 or the driver's error. */
int gks_pipe_send(gks_ws *ws, const gks_prim *p);
/* Hands the mesh m to ws's driver entry mesh: 0, the driver's error, or GKS_WS_MESH_FACETS
 * when the driver has no such entry, declines, or a test hook watches the primitives (it
 * sees the facets): then the caller sends the facets. */
int gks_pipe_send_mesh(gks_ws *ws, const gks_mesh *m);

/* The next workstation of the target, or NULL when there is none left. Inline with the
 * next one: they run for every primitive and workstation. */
static inline gks_ws *gks_pipe_next_ws(gks_pipe_target *t)
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

/* The attributes every primitive carries (view index, lighting, shading methods). */
static inline void gks_pipe_prim_common(gks_prim *p, const gks_cur_attrs *a)
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
#endif
