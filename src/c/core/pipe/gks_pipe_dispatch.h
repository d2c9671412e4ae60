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
    double pat_m[3][4];        /* WC3 -> final NDC3, for pattern boxes */
    gks_ws *only;              /* regeneration target; NULL: the active workstations */
    int k, done;
} gks_pipe_target;

/* The active workstations with the current attributes (none if the open segment of nc is
 * invisible). */
void gks_pipe_target_current(gks_pipe_target *t, const gks_pipe_norm *nc);
/* The next workstation of the target, or NULL when there is none left. */
gks_ws *gks_pipe_next_ws(gks_pipe_target *t);
/* The attributes every primitive carries (view index, lighting, shading methods). */
void gks_pipe_prim_common(gks_prim *p, const gks_cur_attrs *a);
/* Hands p to ws's driver (after the test hook). 0 or the driver's error. */
int gks_pipe_send(gks_ws *ws, const gks_prim *p);
#endif
