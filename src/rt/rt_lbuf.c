/* SPDX-License-Identifier: MIT */
/*
 * rt_lbuf.c -- light buffers: per light, the primitives that can lie between it and a point.
 *
 * A shadow ray runs from a surface point toward a light, so every point of it projects from
 * the light (perspective, positional and spot lights) or along the light's direction
 * (orthographic, directional lights) to nearly the same 2-D point: the ray's own point on the
 * light's projection plane. A light buffer is a 2-D grid over the projection of the scene box
 * on that plane whose cells list every primitive whose projection, enlarged by a margin,
 * reaches the cell (a primitive in front of the light projects to the polygon of its
 * projected vertices: per row of cells the range of its edges clipped to the row). A shadow ray whose 2-D footprint (its origin's projection plus the bound below) lies
 * in one cell can hit only primitives of that cell's list: the list is a superset, so testing
 * it with the same primitive tests gives the traversal's answer (rt_trace_transmit_list).
 * Lists are in order of the nearest depth (distance from the light along the projection axis)
 * of the primitive, in 4096 buckets (a counting sort): a ray only approaches the light, so the
 * test stops at the first primitive of a bucket beyond the one of the ray's origin. This
 * replaces the grid walk of shadow rays, most of a frame in the SPD scenes.
 *
 * The footprint: a shadow ray leaves the point P from o = P + eps N in the direction of
 * L - P, so it passes the light at the distance dev = |(L - o) x d| (eps and rounding). A ray
 * point at depth z then projects within dev (1 + U) / z of the projection of o on each axis
 * (U the largest |u|, |v| on the plane over the scene box: the derivative of the gnomonic
 * projection), and primitives lie at depth >= zmin of the scene box; plus a slack for the
 * rounding of the projections (1e-9 of the plane extent, the primitives another 1e-7).
 * Orthographic: the ray is parallel to the axis, only rounding remains. A footprint that
 * crosses a cell boundary (rare: the bound is ~1e-9 of a cell) or leaves the buffer partly
 * falls back to the grid walk; one entirely outside the buffer meets no primitive.
 *
 * Built per rendering (rt_render) for the lights whose buffer pays: perspective needs the
 * scene box in front of the light (nearest depth above 1/100 of the farthest; a light inside
 * or next to the scene keeps the grid walk), and the primitives must not outnumber the rays
 * that will use it (about one per eye ray and light). Build: one pass projecting and
 * counting, which keeps the row spans, then the fill in depth order (build times:
 * docs/bench/rt_tuning.md).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"
#include "rt_internal.h"
#include "rt_lbuf.h"
#include "rt_prim.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RT_LBUF_CELLS_PER_PRIM 16.0 /* measured: docs/bench/rt_tuning.md (2026-12-05) */
#define RT_LBUF_MIN_CELLS 4096
#define RT_LBUF_MAX_CELLS (1 << 20)
#define RT_LBUF_MAX_ENTRIES (1u << 24) /* 64 MB of lists per light: beyond, no buffer */
#define RT_LBUF_NEAR 1e-2              /* perspective: nearest / farthest depth of the scene box */
#define RT_LBUF_BOX_MARGIN 1e-7        /* primitive boxes, relative to the plane extent */
#define RT_LBUF_QUERY_SLACK 1e-9       /* query rounding, relative to the plane extent */
#define RT_LBUF_PART_PRIMS 1024        /* primitives per part of the build at least */

static inline double rt_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void rt_lbuf_free(rt_lbuf *lb)
{
    free(lb->off);
    free(lb->ids);
    free(lb->zb);
    free(lb->edge);
    memset(lb, 0, sizeof *lb);
}

/* 2-D box r (u0, v0, u1, v1) of the projection of box bb and its nearest and farthest
   depth; 0 if a corner is not in front (the projection of a box in front is the hull of its
   corners') */
static int rt_lbuf_proj_box(const rt_lbuf *lb, const double bb[6], double r[4], double *zmin,
                            double *zmax)
{
    r[0] = r[1] = *zmin = INFINITY;
    r[2] = r[3] = *zmax = -INFINITY;
    for (int k = 0; k < 8; k++) {
        const double p[3] = {bb[k & 1 ? 3 : 0], bb[k & 2 ? 4 : 1], bb[k & 4 ? 5 : 2]};
        double u, v, z;
        if (!rt_lbuf_proj(lb, p, &u, &v, &z) || !isfinite(u) || !isfinite(v))
            return 0;
        r[0] = u < r[0] ? u : r[0];
        r[1] = v < r[1] ? v : r[1];
        r[2] = u > r[2] ? u : r[2];
        r[3] = v > r[3] ? v : r[3];
        *zmin = z < *zmin ? z : *zmin;
        *zmax = z > *zmax ? z : *zmax;
    }
    return 1;
}

static int rt_lbuf_clampi(double x, int n)
{
    return x > 0.0 ? (x < (double)(n - 1) ? (int)x : n - 1) : 0;
}

/* the plane axes: ez along the light's direction (ortho) or toward the box centre */
static int rt_lbuf_axes(rt_lbuf *lb, const double bb[6], const rt_light *l)
{
    double ez[3];
    for (int a = 0; a < 3; a++) {
        const double c = 0.5 * (bb[a] + bb[3 + a]);
        lb->L[a] = lb->ortho ? c : l->position[a];
        ez[a] = lb->ortho ? l->direction[a] : c - l->position[a];
    }
    double n = sqrt(rt_dot3(ez, ez));
    if (!(n > 0.0) || !isfinite(n))
        return 0;
    for (int a = 0; a < 3; a++)
        ez[a] /= n;
    /* ex: ez x (the axis ez is least aligned with), ey = ez x ex */
    const double ax = fabs(ez[0]), ay = fabs(ez[1]), az = fabs(ez[2]);
    const int m = ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2);
    double e[3] = {0.0, 0.0, 0.0}, ex[3];
    e[m] = 1.0;
    ex[0] = ez[1] * e[2] - ez[2] * e[1];
    ex[1] = ez[2] * e[0] - ez[0] * e[2];
    ex[2] = ez[0] * e[1] - ez[1] * e[0];
    n = sqrt(rt_dot3(ex, ex));
    for (int a = 0; a < 3; a++)
        ex[a] /= n;
    memcpy(lb->ez, ez, sizeof ez);
    memcpy(lb->ex, ex, sizeof ex);
    lb->ey[0] = ez[1] * ex[2] - ez[2] * ex[1];
    lb->ey[1] = ez[2] * ex[0] - ez[0] * ex[2];
    lb->ey[2] = ez[0] * ex[1] - ez[1] * ex[0];
    for (int a = 0; a < 3; a++) {
        lb->exy[a][0] = lb->ex[a];
        lb->exy[a][1] = lb->ey[a];
    }
    return 1;
}

/* a primitive on the plane, in cell units: its projected vertices (the loops of a polygon
   one after the other) and their box */
typedef struct rt_lbuf_proj2 {
    double *q;      /* 2 per vertex (grown as needed: cap doubles) */
    size_t n, cap;
    const uint32_t *loops; /* vertex counts of the nloops loops; NULL: one loop of n */
    uint32_t nloops;
    double *span;   /* per row of the box: u-range lo, hi (grown as needed: scap doubles) */
    size_t scap;
    int32_t *rs;    /* the row spans found (y, x0, x1), all primitives (rscap ints) */
    size_t nrs, rscap;
    double bb[4];   /* x0, y0, x1, y1 */
    double zmin;    /* nearest vertex depth */
} rt_lbuf_proj2;

/* 0 if a vertex is not in front of the light (cannot happen: primitives lie in the box), -1
   without memory */
static int rt_lbuf_project(const rt_lbuf *lb, const rt_scene *sc, size_t i, rt_lbuf_proj2 *pp)
{
    pp->n = rt_prim_nverts(sc, i);
    pp->loops = NULL;
    pp->nloops = 1;
    const rt_prim geo = rt_prim_geo(sc, i);
    if (geo.kind == RT_KIND_POLY) {
        const rt_poly *po = &sc->poly[geo.data];
        pp->loops = sc->loops + po->loop0;
        pp->nloops = po->nloops;
    }
    if (!rt_grow((void **)&pp->q, &pp->cap, 2 * pp->n, sizeof(double)))
        return -1;
    pp->bb[0] = pp->bb[1] = pp->zmin = INFINITY;
    pp->bb[2] = pp->bb[3] = -INFINITY;
    /* a quad's vertices read in place (rt_prim_vertex's, without a call per vertex) */
    const double *qv = geo.kind == RT_KIND_QUAD ? &sc->quad[geo.data].v[0][0] : NULL;
    for (size_t k = 0; k < pp->n; k++) {
        double p[3], u, v, z;
        if (qv)
            memcpy(p, qv + 3 * k, sizeof p);
        else
            rt_prim_vertex(sc, i, k, p);
        if (!rt_lbuf_proj(lb, p, &u, &v, &z) || !isfinite(u) || !isfinite(v))
            return 0;
        const double x = (u - lb->u0) * lb->su, y = (v - lb->v0) * lb->sv;
        pp->q[2 * k] = x;
        pp->q[2 * k + 1] = y;
        pp->bb[0] = x < pp->bb[0] ? x : pp->bb[0];
        pp->bb[1] = y < pp->bb[1] ? y : pp->bb[1];
        pp->bb[2] = x > pp->bb[2] ? x : pp->bb[2];
        pp->bb[3] = y > pp->bb[3] ? y : pp->bb[3];
        pp->zmin = z < pp->zmin ? z : pp->zmin;
    }
    return 1;
}

/* Primitive i's lines (rt_lbuf.edge) from its projection pp: a triangle's, quad's or cell
   array's convex polygon of projected vertices (its edges, turned so that the inside is
   positive), a polygon's box; an edge or polygon without length or area: no line (0, 0, 1).
   On the plane (u, v), from the cell units of pp (rounding ~1e-16 of the coordinates, far
   below the build's margin). */
static void rt_lbuf_edges(const rt_lbuf *lb, const rt_scene *sc, size_t i, const rt_lbuf_proj2 *pp,
                          float *out)
{
    double q[4][2], L[4][3];
    int n = 0;
    const int kind = rt_prim_geo(sc, i).kind;
    if (kind != RT_KIND_POLY && pp->n >= 3 && pp->n <= 4) {
        n = (int)pp->n;
        for (int k = 0; k < n; k++) {
            q[k][0] = pp->q[2 * k] / lb->su + lb->u0;
            q[k][1] = pp->q[2 * k + 1] / lb->sv + lb->v0;
        }
    } else { /* the box, counter-clockwise */
        n = 4;
        const double u0 = pp->bb[0] / lb->su + lb->u0, u1 = pp->bb[2] / lb->su + lb->u0;
        const double v0 = pp->bb[1] / lb->sv + lb->v0, v1 = pp->bb[3] / lb->sv + lb->v0;
        q[0][0] = u0, q[0][1] = v0, q[1][0] = u1, q[1][1] = v0;
        q[2][0] = u1, q[2][1] = v1, q[3][0] = u0, q[3][1] = v1;
    }
    double area = 0.0;
    for (int k = 0; k < n; k++) {
        const double *p0 = q[k], *p1 = q[(k + 1) % n];
        area += p0[0] * p1[1] - p1[0] * p0[1];
    }
    const double sg = area > 0.0 ? 1.0 : -1.0;
    for (int k = 0; k < 4; k++) {
        L[k][0] = L[k][1] = 0.0;
        L[k][2] = 1.0;
        if (k >= n || !(fabs(area) > 0.0) || !isfinite(area))
            continue;
        const double *p0 = q[k], *p1 = q[(k + 1) % n];
        const double a = -sg * (p1[1] - p0[1]), b = sg * (p1[0] - p0[0]);
        const double l = sqrt(a * a + b * b);
        if (!(l > 0.0) || !isfinite(l))
            continue;
        L[k][0] = a / l;
        L[k][1] = b / l;
        L[k][2] = -(L[k][0] * p0[0] + L[k][1] * p0[1]);
    }
    for (int k = 0; k < 4; k++) /* a[4], b[4], c[4] */
        for (int c = 0; c < 3; c++)
            out[4 * c + k] = (float)L[k][c];
}

/* The cells the projection, enlarged by (mx, my) cell units, reaches; per row y (the strip
   [y - my, y + 1 + my]) from the u-range of the primitive within the strip: the u-range of
   its edges (every loop's, closed) clipped to the strip (the boundary of the part inside the
   strip is made of those pieces and of strip border pieces ending on them), gathered edge
   by edge over the rows each edge meets. Appends the row spans to pp->rs. Returns the number
   of cells, SIZE_MAX without memory. */
static size_t rt_lbuf_cells(const rt_lbuf *lb, rt_lbuf_proj2 *pp, double mx, double my)
{
    const int y0 = rt_lbuf_clampi(pp->bb[1] - my, lb->nv), y1 = rt_lbuf_clampi(pp->bb[3] + my, lb->nv);
    const size_t rows = (size_t)(y1 - y0 + 1);
    if (!rt_grow((void **)&pp->span, &pp->scap, 2 * rows, sizeof(double)) ||
        !rt_grow((void **)&pp->rs, &pp->rscap, pp->nrs + 3 * rows, sizeof(int32_t)))
        return SIZE_MAX;
    double *span = pp->span;
    for (size_t r = 0; r < rows; r++) {
        span[2 * r] = INFINITY;
        span[2 * r + 1] = -INFINITY;
    }
    /* edge by edge (loop by loop) over the rows whose strip it meets: y - my <= yhi and
       ylo <= y + 1 + my */
    for (uint32_t l = 0, base = 0; l < pp->nloops; base += pp->loops ? pp->loops[l] : 0, l++) {
        const size_t len = pp->loops ? pp->loops[l] : pp->n;
        for (size_t k = 0; k < len; k++) {
            const double *p0 = pp->q + 2 * (base + k), *p1 = pp->q + 2 * (base + (k + 1) % len);
            const double ylo = p0[1] < p1[1] ? p0[1] : p1[1], yhi = p0[1] < p1[1] ? p1[1] : p0[1];
            /* (floor, clamped: a row more at most, where nothing is found) */
            const int ra0 = rt_lbuf_clampi(ylo - 1.0 - my, lb->nv), rb0 = rt_lbuf_clampi(yhi + my, lb->nv);
            const int ra = ra0 > y0 ? ra0 : y0, rb = rb0 < y1 ? rb0 : y1;
            for (int y = ra; y <= rb; y++) {
                const double sl = y - my, sh = y + 1 + my;
                double xs[4];
                int m = 0;
                if (p0[1] >= sl && p0[1] <= sh)
                    xs[m++] = p0[0];
                if (p1[1] >= sl && p1[1] <= sh)
                    xs[m++] = p1[0];
                for (int c = 0; c < 2; c++) { /* crossings of the strip's borders */
                    const double yc = c ? sh : sl;
                    if (ylo < yc && yc < yhi)
                        xs[m++] = p0[0] + (yc - p0[1]) / (p1[1] - p0[1]) * (p1[0] - p0[0]);
                }
                double *sp = span + 2 * (size_t)(y - y0);
                for (int c = 0; c < m; c++) {
                    sp[0] = xs[c] < sp[0] ? xs[c] : sp[0];
                    sp[1] = xs[c] > sp[1] ? xs[c] : sp[1];
                }
            }
        }
    }
    size_t total = 0;
    for (int y = y0; y <= y1; y++) {
        double lo = span[2 * (size_t)(y - y0)], hi = span[2 * (size_t)(y - y0) + 1];
        if (!(lo <= hi)) { /* no piece (rounding at the box's border rows): the box */
            lo = pp->bb[0];
            hi = pp->bb[2];
        }
        const int x0 = rt_lbuf_clampi(lo - mx, lb->nu), x1 = rt_lbuf_clampi(hi + mx, lb->nu);
        int32_t *r = pp->rs + pp->nrs;
        r[0] = y;
        r[1] = x0;
        r[2] = x1;
        pp->nrs += 3;
        total += (size_t)(x1 - x0 + 1);
    }
    return total;
}

static void rt_lbuf_proj2_free(rt_lbuf_proj2 *pp)
{
    free(pp->q);
    free(pp->span);
    free(pp->rs);
}

/* The build's passes on the pool. Projection (part k: the primitives of rt_par_range(k, n)):
   each part projects its primitives, keeps their row spans in its own rs (first[i]: the
   first span of primitive i, local, then global once the parts' spans are put one after the
   other) and counts its depth buckets. Lists (part k: the rows of rt_par_range(k, n) over
   nv): each part counts, sums and fills the cells of its rows from all spans, the primitives
   in depth order, so every list is the one a single pass would make. */
typedef struct rt_lbuf_part {
    rt_lbuf_proj2 pp;
    size_t total;    /* cells of its primitives */
    size_t nspans;   /* its spans */
    size_t base;     /* spans of the parts before it; lists: entries of the rows before */
    int rc;          /* 1, 0 (a vertex not in front: no buffer), -1 (no memory), 2 (too many) */
    uint32_t bcount[RT_LBUF_BUCKETS + 1];
    char pad[RT_LINE];
} rt_lbuf_part;

typedef struct rt_lbuf_job {
    const rt_scene *sc;
    rt_lbuf *lb;
    const uint8_t *omit; /* NULL, or per primitive: 1 to leave it out of every list */
    double mx, my;
    uint32_t *first, *order;
    int32_t *rs;     /* all spans */
    rt_lbuf_part *part;
} rt_lbuf_job;

static void rt_lbuf_project_part(void *arg, int k, int n)
{
    rt_lbuf_job *j = arg;
    rt_lbuf_part *pt = &j->part[k];
    size_t lo, hi;
    rt_par_range(j->sc->nprim, k, n, &lo, &hi);
    pt->rc = 1;
    for (size_t i = lo; i < hi; i++) {
        if (j->omit && j->omit[i]) { /* no spans; in bucket 0 of the order, filling nothing */
            j->first[i] = (uint32_t)(pt->pp.nrs / 3);
            j->lb->zb[i] = 0;
            pt->bcount[1]++;
            for (int k = 0; j->lb->edge && k < 12; k++) /* no lines: (0, 0, 1) */
                j->lb->edge[12 * i + (size_t)k] = k >= 8 ? 1.0f : 0.0f;
            continue;
        }
        const int pr = rt_lbuf_project(j->lb, j->sc, i, &pt->pp);
        j->first[i] = (uint32_t)(pt->pp.nrs / 3);
        const size_t nc_i = pr > 0 ? rt_lbuf_cells(j->lb, &pt->pp, j->mx, j->my) : SIZE_MAX;
        if (pr <= 0 || nc_i == SIZE_MAX || pt->pp.nrs / 3 > UINT32_MAX - 1) {
            pt->rc = pr == 0 ? 0 : -1;
            return;
        }
        if (j->lb->edge)
            rt_lbuf_edges(j->lb, j->sc, i, &pt->pp, j->lb->edge + 12 * i);
        pt->total += nc_i;
        if (pt->total > RT_LBUF_MAX_ENTRIES) {
            pt->rc = 2;
            return;
        }
        const uint32_t b = rt_lbuf_bucket(j->lb, pt->pp.zmin - j->lb->zeps);
        j->lb->zb[i] = (uint16_t)b;
        pt->bcount[b + 1]++;
    }
    pt->nspans = pt->pp.nrs / 3;
}

/* part k's spans into the common array, its first[] made global */
static void rt_lbuf_gather_part(void *arg, int k, int n)
{
    rt_lbuf_job *j = arg;
    rt_lbuf_part *pt = &j->part[k];
    size_t lo, hi;
    rt_par_range(j->sc->nprim, k, n, &lo, &hi);
    if (pt->nspans)
        memcpy(j->rs + 3 * pt->base, pt->pp.rs, 3 * pt->nspans * sizeof(int32_t));
    for (size_t i = lo; i < hi; i++)
        j->first[i] += (uint32_t)pt->base;
}

/* off[c + 1] = entries of cell c, for the cells of part k's rows, then their running sum
   within the rows (the parts' totals are summed between the passes) */
static void rt_lbuf_count_part(void *arg, int k, int n)
{
    rt_lbuf_job *j = arg;
    rt_lbuf *lb = j->lb;
    size_t r0, r1;
    rt_par_range((size_t)lb->nv, k, n, &r0, &r1);
    const size_t nspans = j->first[j->sc->nprim], nu = (size_t)lb->nu;
    for (size_t q = 0; q < nspans; q++) {
        const int32_t *r = j->rs + 3 * q;
        if ((size_t)r[0] < r0 || (size_t)r[0] >= r1)
            continue;
        uint32_t *o = lb->off + (size_t)r[0] * nu + 1;
        for (int32_t x = r[1]; x <= r[2]; x++)
            o[x]++;
    }
    for (size_t c = r0 * nu + 1; c < r1 * nu; c++)
        lb->off[c + 1] += lb->off[c];
    j->part[k].base = r1 > r0 ? lb->off[r1 * nu] : 0; /* the rows' entries */
}

/* off[c + 1] becomes cell c's list end; the lists are filled from the back, the primitives
   in reverse depth order, which leaves off[c + 1] at the start of cell c's list */
static void rt_lbuf_fill_part(void *arg, int k, int n)
{
    rt_lbuf_job *j = arg;
    rt_lbuf *lb = j->lb;
    size_t r0, r1;
    rt_par_range((size_t)lb->nv, k, n, &r0, &r1);
    const size_t nu = (size_t)lb->nu, base = j->part[k].base;
    for (size_t c = r0 * nu; c < r1 * nu; c++)
        lb->off[c + 1] += (uint32_t)base;
    for (size_t jj = j->sc->nprim; jj > 0; jj--) {
        const uint32_t i = j->order[jj - 1];
        for (uint32_t q = j->first[i + 1]; q > j->first[i]; q--) {
            const int32_t *r = j->rs + 3 * (size_t)(q - 1);
            if ((size_t)r[0] < r0 || (size_t)r[0] >= r1)
                continue;
            uint32_t *o = lb->off + (size_t)r[0] * nu + 1;
            for (int32_t x = r[2]; x >= r[1]; x--)
                lb->ids[--o[x]] = i;
        }
    }
}

/* The frame of light l's buffer over the scene box: axes, projected box, cells, depth
 * buckets; *mx, *my the box margin in cell units. 0: no buffer for this light (no axes, the
 * scene not wholly in front of the light, an empty extent). */
static int rt_lbuf_layout(const rt_scene *sc, const rt_light *l, rt_lbuf *lb, double *mx,
                          double *my)
{
    lb->ortho = l->type == RT_LIGHT_DIRECTIONAL;
    const double *B = sc->bbox;
    if (!rt_lbuf_axes(lb, B, l))
        return 0;
    double R[4], zmin, zmax;
    if (!rt_lbuf_proj_box(lb, B, R, &zmin, &zmax))
        return 0;
    if (!lb->ortho && !(zmin > RT_LBUF_NEAR * zmax))
        return 0;
    const double wu = R[2] - R[0], wv = R[3] - R[1], ext = wu > wv ? wu : wv;
    if (!(ext > 0.0) || !isfinite(ext))
        return 0;
    /* cells: about square, a degenerate extent (flat scene seen edge-on) gets one row */
    double target = RT_LBUF_CELLS_PER_PRIM * (double)sc->nprim;
    target = target < RT_LBUF_MIN_CELLS ? RT_LBUF_MIN_CELLS : target;
    target = target > RT_LBUF_MAX_CELLS ? RT_LBUF_MAX_CELLS : target;
    const double cu = wu > 1e-3 * ext ? wu : 1e-3 * ext, cv = wv > 1e-3 * ext ? wv : 1e-3 * ext;
    const double s = sqrt(target / (cu * cv));
    lb->nu = (int)fmin(cu * s + 1.0, 4096.0);
    lb->nv = (int)fmin(cv * s + 1.0, 4096.0);
    const double e = RT_LBUF_BOX_MARGIN * ext;
    lb->u0 = R[0] - 2.0 * e;
    lb->v0 = R[1] - 2.0 * e;
    lb->su = (double)lb->nu / (wu + 4.0 * e);
    lb->sv = (double)lb->nv / (wv + 4.0 * e);
    lb->slack = RT_LBUF_QUERY_SLACK * ext;
    const double U = fmax(fmax(fabs(R[0]), fabs(R[2])), fmax(fabs(R[1]), fabs(R[3])));
    lb->kdev = lb->ortho ? 0.0 : (1.0 + U) / zmin;
    lb->zeps = RT_LBUF_BOX_MARGIN * (fabs(zmax) + fabs(zmin));
    lb->zlo = zmin;
    lb->zscale = zmax > zmin ? (double)RT_LBUF_BUCKETS / (zmax - zmin) : 0.0;
    /* the lines' margin: e, and the float rounding of the lines (2^-24 of |a u| + |b v| +
       |c| <= 4 A for points and vertices in the buffer, |u|, |v| <= A: 2^-22 A) and of their
       evaluation in float (u, v rounded, two products, two sums: below 2^-20 A), taken 4
       times */
    const double A = fmax(fmax(fabs(lb->u0), fabs(lb->u0 + (double)lb->nu / lb->su)),
                          fmax(fabs(lb->v0), fabs(lb->v0 + (double)lb->nv / lb->sv)));
    lb->emargin = e + 0x1p-18 * A;
    *mx = e * lb->su; /* the margin e in cell units */
    *my = e * lb->sv;
    return 1;
}

/* the primitives projected by nt parts: their spans counted (*total list entries, *nspans) */
static int rt_lbuf_project_all(rt_lbuf_job *j, int nt, size_t *total, size_t *nspans)
{
    int rc = RT_OK;
    rt_par_run(nt, rt_lbuf_project_part, j);
    for (int k = 0; k < nt; k++) {
        const int prc = j->part[k].rc;
        if (prc != 1 && rc == RT_OK)
            rc = prc == -1 ? RT_ERR_NOMEM : RT_ERR_LIMIT; /* LIMIT here: no buffer */
        j->part[k].base = *nspans;
        *nspans += j->part[k].nspans;
        *total += j->part[k].total;
    }
    return rc;
}

/* the cells' lists from the gathered spans (nt parts; nc cells, total entries) */
static void rt_lbuf_lists(rt_lbuf_job *j, int nt, size_t nc, size_t total)
{
    const rt_scene *sc = j->sc;
    rt_lbuf *lb = j->lb;
    uint32_t *order = j->order;
    rt_par_run(nt, rt_lbuf_gather_part, j);
    /* the primitives in bucket order (counting sort): each list is in that order */
    uint32_t *bcount = order + sc->nprim;
    for (uint32_t b = 0; b <= RT_LBUF_BUCKETS; b++)
        for (int k = 0; k < nt; k++)
            bcount[b] += j->part[k].bcount[b];
    for (uint32_t b = 0; b < RT_LBUF_BUCKETS; b++)
        bcount[b + 1] += bcount[b];
    for (size_t i = 0; i < sc->nprim; i++)
        order[bcount[lb->zb[i]]++] = (uint32_t)i;
    int nr = nt < lb->nv ? nt : lb->nv; /* parts of rows */
    rt_par_run(nr, rt_lbuf_count_part, j);
    size_t run = 0;
    for (int k = 0; k < nr; k++) {
        const size_t t = j->part[k].base;
        j->part[k].base = run;
        run += t;
    }
    rt_par_run(nr, rt_lbuf_fill_part, j);
    memmove(lb->off, lb->off + 1, nc * sizeof(uint32_t)); /* off[c]: cell c's start */
    lb->off[nc] = (uint32_t)total;
    lb->ok = 1;
}

/* The light buffer of light l over the scene: RT_LBUF_CELLS_PER_PRIM cells per primitive
 * (chosen on SPD gears, docs/bench/rt_tuning.md). */
int rt_lbuf_build(const rt_scene *sc, const rt_light *l, int threads, rt_lbuf *lb)
{
    return rt_lbuf_build_omit(sc, l, NULL, 1, threads, lb);
}

int rt_lbuf_build_omit(const rt_scene *sc, const rt_light *l, const uint8_t *omit, int lines,
                       int threads, rt_lbuf *lb)
{
    memset(lb, 0, sizeof *lb);
    if (l->type != RT_LIGHT_POSITIONAL && l->type != RT_LIGHT_SPOT &&
        l->type != RT_LIGHT_DIRECTIONAL)
        return RT_OK;
    double mx, my;
    if (!rt_lbuf_layout(sc, l, lb, &mx, &my))
        return RT_OK;
    const size_t nc = (size_t)lb->nu * (size_t)lb->nv;
    /* order: the primitives sorted by bucket, then RT_LBUF_BUCKETS + 1 counters */
    uint32_t *order = rt_calloc_array(sc->nprim + RT_LBUF_BUCKETS + 1, sizeof(uint32_t));
    lb->off = rt_calloc_array(nc + 1, sizeof(uint32_t));
    lb->zb = rt_alloc_array(sc->nprim, sizeof(uint16_t));
    if (lines)
        lb->edge = rt_alloc_array(sc->nprim, 12 * sizeof(float));
    if (!order || !lb->off || !lb->zb || (lines && !lb->edge)) {
        free(order);
        rt_lbuf_free(lb);
        return RT_ERR_NOMEM;
    }
    rt_lbuf_job j = {sc, lb, omit, mx, my, rt_alloc_array(sc->nprim + 1, sizeof(uint32_t)), order,
                     NULL, NULL};
    int nt = threads < 1 ? 1 : threads; /* parts: a bucket count and spans of their own */
    if ((size_t)nt > sc->nprim / RT_LBUF_PART_PRIMS + 1)
        nt = (int)(sc->nprim / RT_LBUF_PART_PRIMS + 1);
    j.part = rt_calloc_array((size_t)nt, sizeof *j.part);
    int rc = j.first && j.part ? RT_OK : RT_ERR_NOMEM;
    size_t total = 0, nspans = 0;
    if (rc == RT_OK)
        rc = rt_lbuf_project_all(&j, nt, &total, &nspans);
    if (rc == RT_OK && (total > RT_LBUF_MAX_ENTRIES || nspans > UINT32_MAX - 1))
        rc = RT_ERR_LIMIT;
    if (rc == RT_OK) {
        j.first[sc->nprim] = (uint32_t)nspans;
        j.rs = rt_alloc_array(nspans ? 3 * nspans : 1, sizeof(int32_t));
        lb->ids = rt_alloc_array(total ? total : 1, sizeof(uint32_t));
        if (!j.rs || !lb->ids)
            rc = RT_ERR_NOMEM;
    }
    if (rc == RT_OK)
        rt_lbuf_lists(&j, nt, nc, total);
    for (int k = 0; j.part && k < nt; k++)
        rt_lbuf_proj2_free(&j.part[k].pp);
    free(j.part);
    free(j.first);
    free(j.rs);
    free(order);
    if (rc != RT_OK) {
        rt_lbuf_free(lb);
        return rc == RT_ERR_LIMIT ? RT_OK : rc; /* not in front or too large: no buffer */
    }
    return RT_OK;
}

int rt_lbuf_find(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n,
                 uint32_t *zb)
{
    double z, u, v, m;
    const int f = rt_lbuf_find_at(lb, r, ids, n, &z, &u, &v, &m);
    if (f > 0)
        *zb = rt_lbuf_bucket(lb, z + lb->zeps);
    return f;
}

int rt_lbuf_find_z(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n,
                   double *z)
{
    double u, v, m;
    return rt_lbuf_find_at(lb, r, ids, n, z, &u, &v, &m);
}

int rt_lbuf_query(const rt_scene *sc, const rt_lbuf *lb, const rt_rayx *r, uint32_t skip,
                  rt_lbuf_q *q, uint32_t *k0)
{
    return rt_lbuf_query_at(sc, lb, r, skip, q, k0);
}

uint32_t rt_lbuf_next(const rt_lbuf *lb, const rt_lbuf_q *q, uint32_t skip, uint32_t k)
{
    return rt_lbuf_next_at(lb, q, skip, k, NULL, NULL);
}

double rt_lbuf_transmit(const rt_scene *sc, const rt_lbuf *lb, const rt_lbuf_q *q,
                        const rt_rayx *r, uint32_t k, long *blocker)
{
    double T = 1.0;
    *blocker = -1;
    for (; k < q->n; k = rt_lbuf_next_at(lb, q, r->skip, k + 1, NULL, NULL)) {
        const uint32_t i = q->ids[k];
        double t;
        if (!rt_isect_prim(sc, r, i, r->tmin, r->tmax, &t))
            continue;
        const rt_prim *p = rt_prim_rec(sc, i);
        if (p->opaque) {
            *blocker = (long)i;
            return 0.0;
        }
        /* the transparency of the side hit; the side (the normal) only where they differ */
        double tr = rt_prim_surf(sc, p, 0)->transparency;
        const double tb = rt_prim_surf(sc, p, 1)->transparency;
        if (tb != tr) {
            double ng[3];
            rt_prim_ng(sc, i, ng);
            const double den = ng[0] * r->d[0] + ng[1] * r->d[1] + ng[2] * r->d[2];
            tr = den > 0.0 ? tb : tr;
        }
        T *= tr;
        if (!(T > 0.0))
            return 0.0;
    }
    return T;
}
