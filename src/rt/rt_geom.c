/* SPDX-License-Identifier: MIT */
/*
 * rt_geom.c -- the front normal of a committed triangle (rt_prim_ng_tri), at its hits and in
 * the grid's build (rt_trace.c, rt_render.c, rt_build.c). A leaf below the scene and the
 * grid, so that neither calls the other back.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"

#include <math.h>
#include <string.h>

/* rt_tri_unit_normal's fallback (slivers, extreme coordinates), out of line: inlined, its
   scaled computation made the compiler load and spill the vertices for it ahead of the
   common path's test, about 70 instructions per hit of a ray */
__attribute__((noinline, cold)) void rt_tri_unit_normal_slow(const double *v0, const double *v1,
                                                             const double *v2, double n[3])
{
    (void)rt_tri_normal_sane(v0, v1, v2, n);
}

void rt_prim_ng_tri(const rt_scene *sc, size_t i, double ng[3])
{
    const double *v[3];
    rt_tri_verts(sc, i, v);
    rt_tri_unit_normal(v[0], v[1], v[2], ng);
}

/* fmax(a, b) inline, the same value for every input: b if a is NaN, a if b is NaN (fmax is
   a libm call here) */
static inline double rt_fmax2(double a, double b)
{
    return (a > b || b != b) ? a : b;
}

/* An upper bound of the largest coordinate magnitude of primitive i's vertices (p: a point
   of it, the hit): a triangle's or quad's vertices; a polygon's 2-D bounds and, along the
   dropped (dominant normal) axis, p's coordinate plus the 2-D extents (|n_u|, |n_v| <= |n_w|);
   a cell array's corner P plus its edges. */
static double rt_prim_mag(const rt_scene *sc, size_t i, const double p[3])
{
    const rt_prim geo = rt_prim_geo(sc, i), *pr = &geo;
    switch (pr->kind) {
    case RT_KIND_TRI:
        return fmax(rt_absmax(rt_tri_vert(sc, pr->data, 0), 3),
                    fmax(rt_absmax(rt_tri_vert(sc, pr->data, 1), 3),
                         rt_absmax(rt_tri_vert(sc, pr->data, 2), 3)));
    case RT_KIND_QUAD:
        return rt_absmax(&sc->quad[pr->data].v[0][0], 12);
    case RT_KIND_POLY: {
        const rt_poly *q = &sc->poly[pr->data];
        const double uv[4] = {q->umin, q->umax, q->vmin, q->vmax};
        return fmax(rt_absmax(uv, 4),
                    rt_absmax(p, 3) + (q->umax - q->umin) + (q->vmax - q->vmin));
    }
    default: {
        const rt_cell *c = &sc->cell[pr->data];
        double m = 0.0;
        for (int k = 0; k < 3; k++)
            m = fmax(m, fabs(c->p[k]) + fabs(c->a[k]) + fabs(c->b[k]));
        return m;
    }
    }
}

/* The error bound of the distance t computed for a hit of primitive i: the computed t is the
   exact distance to the surface displaced along its unit normal by at most K u S (S: the
   largest coordinate magnitude involved: the primitive's vertices, the ray's origin and the
   hit point; a hit inside the primitive moves by a convex combination of its vertices'
   displacements), which moves t by K u S / |n . d|. Infinite for a ray in the primitive's
   plane. Inline in rt_nearest_update, its one caller (gcc made it a call: 3 % of gears'
   instructions go through it). */
static inline __attribute__((always_inline)) double rt_hit_err(const rt_scene *sc,
                                                                const rt_rayx *r, size_t i,
                                                                double t)
{
    double ng[3], p[3], den, s;
    const rt_prim geo = rt_prim_geo(sc, i), *pr = &geo;
    for (int k = 0; k < 3; k++)
        p[k] = r->o[k] + t * r->d[k];
    int done = 0; /* den and s set */
    if (pr->kind == RT_KIND_TRI) {
        const double e = rt_tri_hit_err_v(r, t, rt_tri_vert(sc, pr->data, 0),
                                          rt_tri_vert(sc, pr->data, 1),
                                          rt_tri_vert(sc, pr->data, 2));
        if (e >= 0.0)
            return e;
    } else if (pr->kind == RT_KIND_QUAD || pr->kind == RT_KIND_POLY) {
        /* rt_prim_ng's normal and rt_prim_mag's bound read in place, without the calls
           (the eye lists' and the walks' hits on quads and polygons: gears, mount): the
           general path's values, bit for bit */
        const double *n;
        double mg;
        if (pr->kind == RT_KIND_QUAD) {
            const rt_quad *q = &sc->quad[pr->data];
            n = q->n;
            mg = q->vmax; /* rt_absmax(&q->v[0][0], 12), kept with the quad */
        } else {
            const rt_poly *q = &sc->poly[pr->data];
            n = q->n;
            mg = rt_fmax2(q->uvmax, /* rt_absmax of its bounds, kept with the polygon */
                          rt_absmax(p, 3) + (q->umax - q->umin) + (q->vmax - q->vmin));
        }
        den = fabs(n[0] * r->d[0] + n[1] * r->d[1] + n[2] * r->d[2]);
        s = rt_max2(mg, rt_max2(rt_absmax(r->o, 3), rt_absmax(p, 3)));
        done = 1;
    }
    if (!done) { /* a degenerate triangle's cross product, a cell array */
        rt_prim_ng(sc, i, ng);
        den = fabs(ng[0] * r->d[0] + ng[1] * r->d[1] + ng[2] * r->d[2]);
        s = rt_max2(rt_prim_mag(sc, i, p), rt_max2(rt_absmax(r->o, 3), rt_absmax(p, 3)));
    }
    if (!(den > 0.0)) /* no division by zero (the tests trap it) */
        return INFINITY;
    const double e = RT_HIT_K * s / den;
    return e >= 0.0 ? e : INFINITY;
}

void rt_tri_err_init(const rt_scene *sc, uint32_t i, rt_tri_err *q)
{
    const double *a = rt_tri_vert(sc, i, 0), *b = rt_tri_vert(sc, i, 1),
                 *c = rt_tri_vert(sc, i, 2);
    /* rt_hit_err's operations for a triangle, in its order */
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double ng[3];
    ng[0] = e1[1] * e2[2] - e1[2] * e2[1];
    ng[1] = e1[2] * e2[0] - e1[0] * e2[2];
    ng[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double m = rt_absmax(ng, 3);
    q->ok = m > 0.0 && isfinite(m);
    if (!q->ok)
        return;
    const double im = 1.0 / m;
    q->x = ng[0] * im;
    q->y = ng[1] * im;
    q->z = ng[2] * im;
    q->nrm = sqrt(q->x * q->x + q->y * q->y + q->z * q->z);
    /* a maximum of magnitudes is exact: with the ray's o and p below, rt_absmax5's value */
    q->vmax = rt_max2(rt_absmax(a, 3), rt_max2(rt_absmax(b, 3), rt_absmax(c, 3)));
}

/* rt_hit_err of a triangle whose own part is q (q->ok) */
static inline double rt_tri_hit_err(const rt_tri_err *q, const rt_rayx *r, double t)
{
    double p[3];
    for (int k = 0; k < 3; k++)
        p[k] = r->o[k] + t * r->d[k];
    const double den = fabs(q->x * r->d[0] + q->y * r->d[1] + q->z * r->d[2]) / q->nrm;
    const double s = rt_max2(q->vmax, rt_max2(rt_absmax(r->o, 3), rt_absmax(p, 3)));
    if (!(den > 0.0))
        return INFINITY;
    const double e = RT_HIT_K * s / den;
    return e >= 0.0 ? e : INFINITY;
}

/* the order of primitive i in the tie rule: its index, or for a mesh triangle of meshes in
   spatial order (compared only with triangles of its own mesh) its given position */
static inline size_t rt_prim_given(const rt_scene *sc, size_t i)
{
    if (sc->vmask != UINT32_MAX && i >= sc->ntri_plain && i < sc->ntri)
        return rt_ctri_given(sc->ctri[i - sc->ntri_plain]);
    return i;
}

/* Two hits tie when their distances differ by at most twice the smaller bound: the same
   plane's distance computed twice (coplanar faces: equal bounds), and a surface crossed at a
   grazing angle (a large bound) does not tie with one far behind it. A tie goes to the larger
   id (drawn later), as in the z-buffer and painter modes; between primitives of one id (the
   triangles of a mesh) to the nearer, at equal distance to the one given first (rt_prim_given). */
static inline void rt_nearest_take(const rt_scene *sc, uint32_t i, double t, double e,
                                   double *best, long *bi, double *eb)
{
    if (*bi >= 0) {
        const double tie = 2.0 * (e < *eb ? e : *eb);
        if (t > *best + tie)
            return;
        if (t >= *best - tie) { /* a tie: the later area; within one area the nearer,
                                   at equal distance the primitive given first */
            const int id = rt_prim_id(sc, i), idb = rt_prim_id(sc, (size_t)*bi);
            if (id < idb ||
                (id == idb && (t > *best || (t == *best && rt_prim_given(sc, i) >
                                                               rt_prim_given(sc, (size_t)*bi)))))
                return;
        }
    }
    *best = t;
    *bi = (long)i;
    *eb = e;
}

void rt_nearest_update(const rt_scene *sc, const rt_rayx *r, uint32_t i, double t, double *best,
                       long *bi, double *eb)
{
    rt_nearest_take(sc, i, t, rt_hit_err(sc, r, i, t), best, bi, eb);
}

void rt_nearest_take_e(const rt_scene *sc, uint32_t i, double t, double e, double *best, long *bi,
                       double *eb)
{
    rt_nearest_take(sc, i, t, e, best, bi, eb);
}

void rt_nearest_update_tri(const rt_scene *sc, const rt_rayx *r, uint32_t i, double t,
                           const rt_tri_err *q, double *best, long *bi, double *eb)
{
    /* beyond the best's window at its own bound: beyond it at the lesser bound of the two
       too (2 * min(e, *eb) <= 2 * *eb, the sums rounded monotonically), so rt_nearest_update
       returns without a change; e is not needed */
    if (*bi >= 0 && t > *best + 2.0 * *eb)
        return;
    if (!q->ok) {
        rt_nearest_update(sc, r, i, t, best, bi, eb);
        return;
    }
    rt_nearest_take(sc, i, t, rt_tri_hit_err(q, r, t), best, bi, eb);
}
