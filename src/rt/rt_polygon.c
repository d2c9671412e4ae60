/* SPDX-License-Identifier: MIT */
/*
 * rt_polygon.c -- the point-in-polygon grid of big polygons (rt_polygon.h).
 *
 * The rule (rt_isect_poly): edge e = (u0,v0)-(u1,v1) stored with v0 <= v1 counts for the
 * point q when it straddles, S(q) = v0 <= qv < v1, and L(q) = (qv - v0)(u1 - u0) >
 * (qu - u0)(v1 - v0) (its crossing lies right of q); parity P(q) = XOR of S & L. This is
 * the exact parity of q moved by (d, e), 0 < e << d infinitesimal, so any path's crossings
 * in that perturbed picture give parity differences. For q = p in cell (i, j), X = xs[i+1],
 * vj = vs[j]:
 *   P(p) ^ P(X, pv)  = XOR S(pv) & (L(p) ^ L(X, pv))      (same height: the rule itself)
 *   P(X, pv) ^ P(X, vj) = crossings of the vertical path u = X + d: a non-horizontal edge
 *     with (u0 <= X) != (u1 <= X) crosses it iff L(X, pv) ^ L(X, vj) (L is monotone in qv
 *     along the line, rounding included); a horizontal edge at height h iff h lies in
 *     (min(pv, vj), max(pv, vj)] (the rule never sees horizontal edges, but their ends
 *     change which non-horizontal edges straddle).
 * Only edges meeting the cell change either term (the others are decided far from a
 * tie), so each cell lists the edges meeting it enlarged by a margin far above rounding.
 * P(X, vj) itself is the rule at the corner, computed at build time per row line: L at
 * (xs[c], vj) is monotone in c, so each straddling edge toggles a prefix of the corners.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void rt_pgrid_free(rt_pgrid *g)
{
    free(g->xs);
    free(g->vs);
    free(g->corner);
    free(g->off);
    free(g->ids);
    free(g->e);
    memset(g, 0, sizeof *g);
}

size_t rt_pgrid_bytes(const rt_pgrid *g)
{
    size_t cells = (size_t)g->gu * (size_t)g->gv;
    return (size_t)(g->gu + g->gv + 2) * sizeof(double) + cells + (cells + 1) * sizeof(uint32_t) +
           g->nref * sizeof(uint32_t) + g->ne * 4 * sizeof(double);
}

static int clampi(double f, int n)
{
    if (!(f > 0.0))
        return 0;
    if (f >= (double)(n - 1))
        return n - 1;
    return (int)f;
}

/* L of edge e at (qu, qv) */
static inline int rt_pg_left(const double *e, double qu, double qv)
{
    return (qv - e[1]) * (e[2] - e[0]) > (qu - e[0]) * (e[3] - e[1]);
}

/* Cells [i0,i1] x [j0,j1] ranges of edge e per row: calls f for each cell. Used twice
 * (count, fill) with the same arithmetic, so both passes agree. */
typedef struct pg_pass {
    rt_pgrid *g;
    uint32_t *cnt; /* count pass: per cell */
    uint32_t *cur; /* fill pass: cursor per cell */
    uint32_t id;
    size_t total;
} pg_pass;

static void pg_visit(pg_pass *ps, int i0, int i1, int j)
{
    rt_pgrid *g = ps->g;
    for (int i = i0; i <= i1; i++) {
        size_t c = (size_t)j * (size_t)g->gu + (size_t)i;
        if (ps->cur)
            g->ids[ps->cur[c]++] = ps->id;
        else
            ps->cnt[c]++;
        ps->total++;
    }
}

static void pg_edge_cells(pg_pass *ps, const double *e, double m)
{
    const rt_pgrid *g = ps->g;
    const double du = 1.0 / g->inv_du, dv = 1.0 / g->inv_dv;
    double ulo = fmin(e[0], e[2]) - m, uhi = fmax(e[0], e[2]) + m;
    int j0 = clampi((e[1] - m - g->v0) * g->inv_dv, g->gv);
    int j1 = clampi((e[3] + m - g->v0) * g->inv_dv, g->gv);
    for (int j = j0; j <= j1; j++) {
        double a = ulo, b = uhi;
        if (e[3] > e[1]) { /* the edge's u range within the row band (with margins) */
            double blo = fmax(e[1], g->v0 + j * dv - m), bhi = fmin(e[3], g->v0 + (j + 1) * dv + m);
            if (blo > bhi) {
                blo = e[1];
                bhi = e[3];
            }
            double s = (e[2] - e[0]) / (e[3] - e[1]);
            double ua = e[0] + (blo - e[1]) * s, ub = e[0] + (bhi - e[1]) * s;
            a = fmax(ulo, fmin(ua, ub) - m);
            b = fmin(uhi, fmax(ua, ub) + m);
        }
        int i0 = clampi((a - g->u0) * g->inv_du, g->gu);
        int i1 = clampi((b - g->u0) * g->inv_du, g->gu);
        (void)du;
        pg_visit(ps, i0, i1, j);
    }
}

/* the polygon's edges (zero-length ones left out) into g->e, stored with v0 <= v1 */
static void pg_edges(rt_pgrid *g, const double *uv, const uint32_t *counts, uint32_t nloops)
{
    const double *lu = uv;
    for (uint32_t l = 0; l < nloops; l++) {
        uint32_t cnt = counts[l];
        const double *q = lu + 2 * (size_t)(cnt - 1);
        for (uint32_t i = 0; i < cnt; i++) {
            const double *a = lu + 2 * (size_t)i;
            if (a[0] != q[0] || a[1] != q[1]) { /* zero-length edges never count */
                const double *lo = q[1] <= a[1] ? q : a, *hi = q[1] <= a[1] ? a : q;
                double *e = g->e + 4 * g->ne++;
                e[0] = lo[0]; e[1] = lo[1]; e[2] = hi[0]; e[3] = hi[1];
            }
            q = a;
        }
        lu += 2 * (size_t)cnt;
    }
}

/* the grid's size and the per-cell counts (ps->cnt, ps->total): about one cell per edge,
   shaped like the box (w x h from umin, vmin; margin m); long edges meet many cells, so the
   grid shrinks until the lists hold at most 48 entries per edge (the slabs' budget of 256
   bytes per edge, in 4-byte entries plus the edge copy). -1: no memory */
static int pg_size(rt_pgrid *g, pg_pass *ps, double umin, double vmin, double w, double h,
                   double m)
{
    double cells = (double)g->ne;
    const size_t budget = 48 * g->ne + 4096;
    for (;;) {
        double gu = ceil(sqrt(cells * w / h)), gv = ceil(cells / gu);
        g->gu = (int)fmin(fmax(gu, 1.0), 2048.0);
        g->gv = (int)fmin(fmax(gv, 1.0), 2048.0);
        g->u0 = umin - 2 * m;
        g->v0 = vmin - 2 * m;
        g->inv_du = (double)g->gu / (w + 4 * m);
        g->inv_dv = (double)g->gv / (h + 4 * m);
        size_t nc = (size_t)g->gu * (size_t)g->gv;
        ps->cnt = rt_calloc_array(nc, sizeof *ps->cnt);
        if (!ps->cnt)
            return -1;
        ps->total = 0;
        for (size_t k = 0; k < g->ne && ps->total <= budget; k++)
            pg_edge_cells(ps, g->e + 4 * k, m);
        if (ps->total <= budget || nc == 1)
            return 0;
        free(ps->cnt);
        ps->cnt = NULL;
        cells = fmax(1.0, (double)nc * 0.5);
    }
}

/* corner parities: per row line j, each straddling edge toggles the corners c = 1..k with L
   true at (xs[c], vs[j]) (L falls as c grows); then a suffix XOR per row */
static void pg_corners(rt_pgrid *g)
{
    for (size_t k = 0; k < g->ne; k++) {
        const double *e = g->e + 4 * k;
        if (!(e[3] > e[1]))
            continue;
        int j = clampi((e[1] - g->v0) * g->inv_dv, g->gv);
        while (j > 0 && g->vs[j] >= e[1])
            j--;
        while (j < g->gv && g->vs[j] < e[1])
            j++;
        for (; j < g->gv && g->vs[j] < e[3]; j++) { /* e[1] <= vs[j] < e[3] */
            const double vj = g->vs[j];
            double uc = e[0] + (vj - e[1]) * ((e[2] - e[0]) / (e[3] - e[1]));
            int c = clampi((uc - g->u0) * g->inv_du, g->gu + 1);
            while (c < g->gu && rt_pg_left(e, g->xs[c + 1], vj))
                c++;
            while (c >= 1 && !rt_pg_left(e, g->xs[c], vj))
                c--;
            if (c >= 1) /* corners of cells 0..c-1 (right side xs[1..c]) */
                g->corner[(size_t)j * (size_t)g->gu + (size_t)(c - 1)] ^= 1;
        }
    }
    for (int j = 0; j < g->gv; j++) {
        uint8_t *row = g->corner + (size_t)j * (size_t)g->gu;
        for (int i = g->gu - 2; i >= 0; i--)
            row[i] ^= row[i + 1];
    }
}

int rt_pgrid_build(rt_pgrid *g, const double *uv, const uint32_t *counts, uint32_t nloops,
                   double umin, double umax, double vmin, double vmax)
{
    memset(g, 0, sizeof *g);
    size_t nv = 0;
    for (uint32_t l = 0; l < nloops; l++)
        nv += counts[l];
    const double w = umax - umin, h = vmax - vmin;
    if (!(w > 0.0) || !(h > 0.0) || !isfinite(w * h) || nv < 3 || nv > UINT32_MAX / 4)
        return -1;
    /* margin: far above the rounding of the coordinates, far below a cell */
    const double m = 1e-9 * (w + h + fabs(umin) + fabs(umax) + fabs(vmin) + fabs(vmax));
    g->e = rt_alloc_array(nv, 4 * sizeof *g->e);
    if (!g->e)
        return -1;
    pg_edges(g, uv, counts, nloops);
    pg_pass ps = { .g = g };
    if (pg_size(g, &ps, umin, vmin, w, h, m) != 0) {
        rt_pgrid_free(g);
        return -1;
    }
    const size_t nc = (size_t)g->gu * (size_t)g->gv;
    g->nref = ps.total;
    g->off = rt_alloc_array(nc + 1, sizeof *g->off);
    g->ids = rt_alloc_array(g->nref ? g->nref : 1, sizeof *g->ids);
    g->corner = rt_calloc_array(nc, 1);
    g->xs = rt_alloc_array((size_t)g->gu + 1, sizeof *g->xs);
    g->vs = rt_alloc_array((size_t)g->gv + 1, sizeof *g->vs);
    if (!g->off || !g->ids || !g->corner || !g->xs || !g->vs || ps.total > UINT32_MAX) {
        free(ps.cnt);
        rt_pgrid_free(g);
        return -1;
    }
    g->off[0] = 0;
    for (size_t c = 0; c < nc; c++)
        g->off[c + 1] = g->off[c] + ps.cnt[c];
    for (size_t c = 0; c < nc; c++)
        ps.cnt[c] = g->off[c];
    ps.cur = ps.cnt;
    for (size_t k = 0; k < g->ne; k++) {
        ps.id = (uint32_t)k;
        pg_edge_cells(&ps, g->e + 4 * k, m);
    }
    free(ps.cnt);
    for (int i = 0; i <= g->gu; i++)
        g->xs[i] = g->u0 + (double)i / g->inv_du;
    for (int j = 0; j <= g->gv; j++)
        g->vs[j] = g->v0 + (double)j / g->inv_dv;
    pg_corners(g);
    return 0;
}

int rt_pgrid_parity(const rt_pgrid *g, double pu, double pv)
{
    const int i = clampi((pu - g->u0) * g->inv_du, g->gu);
    const int j = clampi((pv - g->v0) * g->inv_dv, g->gv);
    const size_t c = (size_t)j * (size_t)g->gu + (size_t)i;
    const double X = g->xs[i + 1], vj = g->vs[j];
    const double lo = fmin(pv, vj), hi = fmax(pv, vj);
    int par = g->corner[c];
    for (uint32_t k = g->off[c]; k < g->off[c + 1]; k++) {
        const double *e = g->e + 4 * (size_t)g->ids[k];
        const int ust = (e[0] <= X) != (e[2] <= X);
        if (e[3] > e[1]) {
            const double du = e[2] - e[0], dv = e[3] - e[1];
            const double A = (pv - e[1]) * du, BX = (X - e[0]) * dv;
            const int lp = A > (pu - e[0]) * dv, lx = A > BX;
            const int lj = (vj - e[1]) * du > BX;
            const int s = (e[1] <= pv) & (pv < e[3]);
            par ^= (s & (lp ^ lx)) ^ (ust & (lx ^ lj));
        } else {
            par ^= ust & (e[1] > lo) & (e[1] <= hi);
        }
    }
    return par;
}
