/* SPDX-License-Identifier: MIT */
/* prim_capture.h -- the core tests' view of what drivers receive: a hook (exported test
 * API gks_test_set_prim_hook) records deep copies of the primitives the core dispatches,
 * so tests can assert on resolved attributes, clipped points and loop structure. */
#ifndef PRIM_CAPTURE_H
#define PRIM_CAPTURE_H
#define GKS3D_BUILDING 1
#include "gks_context.h" /* gks_prim_hook, and ws_driver.h */
#undef GKS3D_BUILDING
#include <math.h>
#include <stdlib.h>
#include <string.h>

void gks_test_set_prim_hook(gks_prim_hook hook, void *ctx);

#define CAP_MAX_PRIMS 4096
#define CAP_MAX_PTS 4096
typedef struct {
    int ws_id;
    gks_prim p;                 /* pointers below point into this record */
    Gpoint3 pts[CAP_MAX_PTS];   /* first CAP_MAX_PTS points */
    int loops[16];
    Grgb cells[64];
    Grgb pattern[64];
} cap_prim;

typedef struct {
    cap_prim *rec;              /* CAP_MAX_PRIMS records */
    int n;                      /* primitives received (may exceed CAP_MAX_PRIMS) */
    size_t total_points;
    int nonfinite;              /* a non-finite coordinate was received */
} capture;

static capture cap;

static inline int finite3(const Gpoint3 *p)
{
    return isfinite(p->x) && isfinite(p->y) && isfinite(p->z);
}

static void cap_hook(void *ctx, int ws_id, const gks_prim *p)
{
    capture *c = ctx;
    for (int i = 0; i < p->n_points; i++)
        if (!finite3(&p->pts[i]))
            c->nonfinite = 1;
    c->total_points += (size_t)(p->n_points > 0 ? p->n_points : 0);
    if (c->n < CAP_MAX_PRIMS) {
        cap_prim *r = &c->rec[c->n];
        r->ws_id = ws_id;
        r->p = *p;
        int n = p->n_points < CAP_MAX_PTS ? p->n_points : CAP_MAX_PTS;
        if (n > 0)
            memcpy(r->pts, p->pts, (size_t)n * sizeof *p->pts);
        r->p.pts = r->pts;
        for (int k = 0; k < p->n_loops && k < 16 && p->loop_counts; k++)
            r->loops[k] = p->loop_counts[k];
        r->p.loop_counts = r->loops;
        if (p->kind == GKS_PRIM_CELL_ARRAY && p->cells) {
            int nc = p->cell_nx * p->cell_ny;
            memcpy(r->cells, p->cells, (size_t)(nc < 64 ? nc : 64) * sizeof(Grgb));
            r->p.cells = r->cells;
        }
        if (p->attrs.pattern) {
            int np = p->attrs.pat_nx * p->attrs.pat_ny;
            memcpy(r->pattern, p->attrs.pattern, (size_t)(np < 64 ? np : 64) * sizeof(Grgb));
            r->p.attrs.pattern = r->pattern;
        }
    }
    c->n++;
}

static inline void cap_start(void)
{
    if (!cap.rec)
        cap.rec = calloc(CAP_MAX_PRIMS, sizeof *cap.rec);
    cap.n = 0;
    cap.total_points = 0;
    cap.nonfinite = 0;
    gks_test_set_prim_hook(cap_hook, &cap);
}

static inline void cap_stop(void)
{
    gks_test_set_prim_hook(NULL, NULL);
}

static inline void cap_free(void)
{
    cap_stop();
    free(cap.rec);
    cap.rec = NULL;
}

static inline double dmin(double a, double b) { return a < b ? a : b; }
static inline double dmax(double a, double b) { return a > b ? a : b; }

static inline int same_rgb(Grgb a, Grgb b)
{
    return fabs(a.red - b.red) < 1e-12 && fabs(a.green - b.green) < 1e-12 &&
           fabs(a.blue - b.blue) < 1e-12;
}
#endif
