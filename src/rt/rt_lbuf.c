/*
 * rt_lbuf.c -- light buffers: per light, the primitives that can lie between it and a point.
 *
 * A shadow ray runs from a surface point toward a light, so every point of it projects from
 * the light (perspective, positional and spot lights) or along the light's direction
 * (orthographic, directional lights) to nearly the same 2-D point: the ray's own point on the
 * light's projection plane. A light buffer is a 2-D grid over the projection of the scene box
 * on that plane whose cells list every primitive whose box projects, with a margin, onto the
 * cell. A shadow ray whose 2-D footprint (its origin's projection plus the bound below) lies
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
 * rounding of the projections (1e-9 of the plane extent, the primitive boxes another 1e-7).
 * Orthographic: the ray is parallel to the axis, only rounding remains. A footprint that
 * crosses a cell boundary (rare: the bound is ~1e-9 of a cell) or leaves the buffer partly
 * falls back to the grid walk; one entirely outside the buffer meets no primitive.
 *
 * Built per rendering (rt_render) for the lights whose buffer pays: perspective needs the
 * scene box in front of the light (nearest depth above 1/100 of the farthest; a light inside
 * or next to the scene keeps the grid walk), and the primitives (projected boxes: ~100 ns
 * each) must not outnumber the rays that will use it (about one per eye ray and light).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define RT_LBUF_CELLS_PER_PRIM 4.0 /* measured: see rt_lbuf_build */
#define RT_LBUF_MIN_CELLS 4096
#define RT_LBUF_MAX_CELLS (1 << 20)
#define RT_LBUF_MAX_ENTRIES (1u << 24) /* 64 MB of lists per light: beyond, no buffer */
#define RT_LBUF_NEAR 1e-2              /* perspective: nearest / farthest depth of the scene box */
#define RT_LBUF_BOX_MARGIN 1e-7        /* primitive boxes, relative to the plane extent */
#define RT_LBUF_QUERY_SLACK 1e-9       /* query rounding, relative to the plane extent */
#define RT_LBUF_BUCKETS 4096           /* depth order of the lists (uint16_t) */

static inline double rt_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void rt_lbuf_free(rt_lbuf *lb)
{
    free(lb->off);
    free(lb->ids);
    free(lb->zb);
    memset(lb, 0, sizeof *lb);
}

/* projection of p onto the plane (u, v) and its depth z; 0 if not in front (perspective) */
static inline int rt_lbuf_proj(const rt_lbuf *lb, const double p[3], double *u, double *v,
                               double *z)
{
    const double w[3] = {p[0] - lb->L[0], p[1] - lb->L[1], p[2] - lb->L[2]};
    *z = rt_dot3(w, lb->ez);
    *u = rt_dot3(w, lb->ex);
    *v = rt_dot3(w, lb->ey);
    if (lb->ortho)
        return 1;
    if (!(*z > 0.0))
        return 0;
    *u /= *z;
    *v /= *z;
    return 1;
}

/* 2-D box r (u0, v0, u1, v1) of the projection of box bb and its nearest depth; 0 if a
   corner is not in front (the projection of a box in front is the hull of its corners') */
static int rt_lbuf_proj_box(const rt_lbuf *lb, const double bb[6], double r[4], double *zmin)
{
    r[0] = r[1] = *zmin = INFINITY;
    r[2] = r[3] = -INFINITY;
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
    return 1;
}

/* depth bucket of z: non-decreasing in z */
static inline uint32_t rt_lbuf_bucket(const rt_lbuf *lb, double z)
{
    const double f = (z - lb->zlo) * lb->zscale;
    return f > 0.0 ? (f < (double)(RT_LBUF_BUCKETS - 1) ? (uint32_t)f : RT_LBUF_BUCKETS - 1) : 0;
}

static void rt_lbuf_fail(rt_lbuf *lb, int32_t *rng, double *pts, uint32_t *order)
{
    free(rng);
    free(pts);
    free(order);
    rt_lbuf_free(lb);
}

/* Cells: RT_LBUF_CELLS_PER_PRIM per primitive (SPD scenes, rt_bench -s 513 -corner, frame s
 * for 1 / 4 / 16 per primitive: gears 0.47 / 0.45 / 0.50, teapot 0.100 / 0.095 / 0.101; 16
 * makes the caps of gears' cog wheels long entries of many cells). */
int rt_lbuf_build(const rt_scene *sc, const rt_light *l, rt_lbuf *lb)
{
    memset(lb, 0, sizeof *lb);
    if (l->type != RT_LIGHT_POSITIONAL && l->type != RT_LIGHT_SPOT &&
        l->type != RT_LIGHT_DIRECTIONAL)
        return RT_OK;
    lb->ortho = l->type == RT_LIGHT_DIRECTIONAL;
    const double *B = sc->bbox;
    if (!rt_lbuf_axes(lb, B, l))
        return RT_OK;
    double R[4], zmin, zmax = -INFINITY;
    if (!rt_lbuf_proj_box(lb, B, R, &zmin))
        return RT_OK;
    for (int k = 0; k < 8; k++) {
        const double p[3] = {B[k & 1 ? 3 : 0], B[k & 2 ? 4 : 1], B[k & 4 ? 5 : 2]};
        double u, v, z;
        rt_lbuf_proj(lb, p, &u, &v, &z);
        zmax = z > zmax ? z : zmax;
    }
    if (!lb->ortho && !(zmin > RT_LBUF_NEAR * zmax))
        return RT_OK;
    const double wu = R[2] - R[0], wv = R[3] - R[1], ext = wu > wv ? wu : wv;
    if (!(ext > 0.0) || !isfinite(ext))
        return RT_OK;
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

    const size_t nc = (size_t)lb->nu * (size_t)lb->nv;
    int32_t *rng = rt_alloc_array(sc->nprim, 4 * sizeof(int32_t));
    uint32_t *order = rt_calloc_array(sc->nprim + RT_LBUF_BUCKETS + 1, sizeof(uint32_t));
    lb->off = rt_calloc_array(nc + 1, sizeof(uint32_t));
    lb->zb = rt_alloc_array(sc->nprim, sizeof(uint16_t));
    double *pts = NULL;
    size_t cap = 0;
    if (!rng || !order || !lb->off || !lb->zb) {
        rt_lbuf_fail(lb, rng, pts, order);
        return RT_ERR_NOMEM;
    }
    /* per primitive: the cells its projected vertices' box (with margin e) reaches and the
       bucket of its nearest vertex (less zeps); the projection of a planar polygon in front of
       the light is the polygon of its projected vertices */
    uint32_t *bcount = order + sc->nprim; /* RT_LBUF_BUCKETS + 1 counters */
    size_t total = 0;
    for (size_t i = 0; i < sc->nprim; i++) {
        const size_t nv = rt_prim_vertices(sc, i, &pts, &cap);
        if (nv == 0) {
            rt_lbuf_fail(lb, rng, pts, order);
            return RT_ERR_NOMEM;
        }
        double r0 = INFINITY, r1 = INFINITY, r2 = -INFINITY, r3 = -INFINITY, zm = INFINITY;
        for (size_t k = 0; k < nv; k++) {
            double u, v, z;
            if (!rt_lbuf_proj(lb, pts + 3 * k, &u, &v, &z) || !isfinite(u) || !isfinite(v)) {
                rt_lbuf_fail(lb, rng, pts, order); /* cannot happen: inside the box */
                return RT_OK;
            }
            r0 = u < r0 ? u : r0;
            r1 = v < r1 ? v : r1;
            r2 = u > r2 ? u : r2;
            r3 = v > r3 ? v : r3;
            zm = z < zm ? z : zm;
        }
        int32_t *q = rng + 4 * i;
        q[0] = rt_lbuf_clampi((r0 - e - lb->u0) * lb->su, lb->nu);
        q[1] = rt_lbuf_clampi((r2 + e - lb->u0) * lb->su, lb->nu);
        q[2] = rt_lbuf_clampi((r1 - e - lb->v0) * lb->sv, lb->nv);
        q[3] = rt_lbuf_clampi((r3 + e - lb->v0) * lb->sv, lb->nv);
        total += (size_t)(q[1] - q[0] + 1) * (size_t)(q[3] - q[2] + 1);
        lb->zb[i] = (uint16_t)rt_lbuf_bucket(lb, zm - lb->zeps);
        bcount[lb->zb[i] + 1]++;
    }
    free(pts);
    pts = NULL;
    if (total > RT_LBUF_MAX_ENTRIES) {
        rt_lbuf_fail(lb, rng, pts, order);
        return RT_OK;
    }
    /* primitives in bucket order (counting sort), then the lists filled in that order */
    for (uint32_t b = 0; b < RT_LBUF_BUCKETS; b++)
        bcount[b + 1] += bcount[b];
    uint32_t *sorted = rt_alloc_array(sc->nprim, sizeof(uint32_t));
    lb->ids = rt_alloc_array(total ? total : 1, sizeof(uint32_t));
    if (!sorted || !lb->ids) {
        free(sorted);
        rt_lbuf_fail(lb, rng, pts, order);
        return RT_ERR_NOMEM;
    }
    for (size_t i = 0; i < sc->nprim; i++)
        sorted[bcount[lb->zb[i]]++] = (uint32_t)i;
    for (size_t i = 0; i < sc->nprim; i++) {
        const int32_t *q = rng + 4 * i;
        for (int y = q[2]; y <= q[3]; y++)
            for (int x = q[0]; x <= q[1]; x++)
                lb->off[(size_t)y * (size_t)lb->nu + (size_t)x + 1]++;
    }
    for (size_t k = 0; k < nc; k++)
        lb->off[k + 1] += lb->off[k];
    for (size_t j = 0; j < sc->nprim; j++) {
        const uint32_t i = sorted[j];
        const int32_t *q = rng + 4 * i;
        for (int y = q[2]; y <= q[3]; y++)
            for (int x = q[0]; x <= q[1]; x++)
                lb->ids[lb->off[(size_t)y * (size_t)lb->nu + (size_t)x]++] = i;
    }
    for (size_t k = nc; k > 0; k--)
        lb->off[k] = lb->off[k - 1];
    lb->off[0] = 0;
    free(sorted);
    free(rng);
    free(order);
    lb->ok = 1;
    return RT_OK;
}

int rt_lbuf_find(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n,
                 uint32_t *zb)
{
    double u, v, z;
    if (!rt_lbuf_proj(lb, r->o, &u, &v, &z) || !isfinite(u) || !isfinite(v))
        return -1;
    double m = lb->slack;
    if (!lb->ortho) {
        /* distance of the light from the ray line (d need not be a unit vector) */
        const double w[3] = {lb->L[0] - r->o[0], lb->L[1] - r->o[1], lb->L[2] - r->o[2]};
        const double c[3] = {w[1] * r->d[2] - w[2] * r->d[1], w[2] * r->d[0] - w[0] * r->d[2],
                             w[0] * r->d[1] - w[1] * r->d[0]};
        const double dev2 = rt_dot3(c, c) / rt_dot3(r->d, r->d);
        /* 2x for the rounding of dev itself (~1e-16 |w|, far below the slack) */
        m += 2.0 * sqrt(dev2) * lb->kdev;
    }
    const double x0 = (u - m - lb->u0) * lb->su, x1 = (u + m - lb->u0) * lb->su;
    const double y0 = (v - m - lb->v0) * lb->sv, y1 = (v + m - lb->v0) * lb->sv;
    if (!(x1 >= 0.0 && y1 >= 0.0 && x0 < (double)lb->nu && y0 < (double)lb->nv)) {
        *n = 0; /* wholly outside: the projections of all primitives lie inside */
        return 0;
    }
    if (!(x0 >= 0.0 && y0 >= 0.0 && x1 < (double)lb->nu && y1 < (double)lb->nv))
        return -1;
    const int cx = (int)x0, cy = (int)y0;
    if (cx != (int)x1 || cy != (int)y1)
        return -1;
    const size_t ci = (size_t)cy * (size_t)lb->nu + (size_t)cx;
    *ids = lb->ids + lb->off[ci];
    *n = lb->off[ci + 1] - lb->off[ci];
    *zb = rt_lbuf_bucket(lb, z + lb->zeps);
    return 1;
}
