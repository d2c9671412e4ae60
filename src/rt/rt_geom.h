/* SPDX-License-Identifier: MIT */
/*
 * rt_geom.h -- the normal of a triangle, inline: the scene checks every triangle added with
 * rt_tri_normal_sane (rt_scene.c, a hot path), rt_geom.c gives rt_tri_unit_normal at hits;
 * and the front normal of any committed primitive (rt_prim_ng).
 * Private to src/rt.
 */
#ifndef GKS3D_RT_GEOM_H
#define GKS3D_RT_GEOM_H
#include "rt_internal.h"
#include "rt_shade.h"

#include <math.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* The unit normal of the triangle v0 v1 v2 (sane vertices): rt_points_frame and rt_poly_normal
   for 3 points, unrolled, the same operations in the same order (the same bits); 0 if it is
   degenerate. The add-time check of a triangle, and the fallback of rt_tri_unit_normal. */
static inline int rt_tri_normal_sane(const double *v0, const double *v1, const double *v2,
                                     double n[3])
{
    const double *v[3] = {v0, v1, v2};
    double pb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY}, c[3];
    rt_bbox_add(pb, v0);
    rt_bbox_add(pb, v1);
    rt_bbox_add(pb, v2);
    const double ext = fmax(pb[3] - pb[0], fmax(pb[4] - pb[1], pb[5] - pb[2]));
    if (!(ext > 0.0) || !isfinite(ext))
        return 0;
    for (int j = 0; j < 3; j++) {
        c[j] = 0.0;
        c[j] += (v0[j] - pb[j]) / 3.0;
        c[j] += (v1[j] - pb[j]) / 3.0;
        c[j] += (v2[j] - pb[j]) / 3.0;
        c[j] += pb[j];
    }
    n[0] = n[1] = n[2] = 0.0;
    for (int i = 0; i < 3; i++) {
        const double *a = v[i], *b = v[i == 2 ? 0 : i + 1];
        double ax = a[0] - c[0], ay = a[1] - c[1], az = a[2] - c[2];
        double bx = b[0] - c[0], by = b[1] - c[1], bz = b[2] - c[2];
        n[0] += (ay - by) * (az + bz);
        n[1] += (az - bz) * (ax + bx);
        n[2] += (ax - bx) * (ay + by);
    }
    const double tol = 1e-12 * ext * ext;
    const double m = rt_sh_absmax3(n);
    if (m != 0.0 && isfinite(m)) {
        const double x = n[0] / m, y = n[1] / m, z = n[2] / m;
        const double len = m * sqrt(x * x + y * y + z * z);
        if (len > tol && isfinite(len)) {
            for (int i = 0; i < 3; i++)
                n[i] /= len;
            return 1;
        }
    }
    static const int three = 3; /* nearly degenerate: the general fallback */
    double vv[9];
    for (int i = 0; i < 3; i++)
        memcpy(vv + 3 * i, v[i], 3 * sizeof(double));
    return rt_newell_normal(vv, 3, &three, 1, c, ext, n);
}

/* The front unit normal of a committed triangle v0 v1 v2 (one that rt_tri_normal_sane finds
   not degenerate) at its hits and in the grid's build: one cross product of two edges and one
   square root. It points the same way as rt_tri_normal_sane's (both are the Newell normal of
   v0 v1 v2) and differs from it by a few roundings (relative 1e-15). Where the cross product
   is ill-conditioned (the sine of the angle at v0 below 1e-11: a sliver, whose cross product
   loses digits), or its square leaves the range of normal doubles (coordinates beyond about
   1e75 or below 1e-75), rt_tri_normal_sane's scaled computation is taken instead. */
void rt_tri_unit_normal_slow(const double *v0, const double *v1, const double *v2, double n[3]);
static inline void rt_tri_unit_normal(const double *v0, const double *v1, const double *v2,
                                      double n[3])
{
    const double e1[3] = {v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]};
    const double e2[3] = {v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2]};
    const double c0 = e1[1] * e2[2] - e1[2] * e2[1], c1 = e1[2] * e2[0] - e1[0] * e2[2],
                 c2 = e1[0] * e2[1] - e1[1] * e2[0];
    const double l2 = c0 * c0 + c1 * c1 + c2 * c2;
    const double a2 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    const double b2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    /* l2 = a2 b2 sin^2: sin > 1e-11, and all three squares normal and finite */
    if (l2 > 1e-22 * (a2 * b2) && l2 > 1e-290 && a2 * b2 < 1e290) {
        const double len = sqrt(l2);
        n[0] = c0 / len;
        n[1] = c1 / len;
        n[2] = c2 / len;
        return;
    }
    rt_tri_unit_normal_slow(v0, v1, v2, n);
}

/* The bound K * u of the relative position error behind a computed distance
   (docs/RAYTRACING.md, "Coplanar surfaces"): u = 2^-53; 16 roundings counted (vertices into
   VRC3: 4; the test's origin subtraction and shear: 2; edge functions or plane numerator: 3;
   T or numerator with the shear scale: 4; denominator: 2; division: 1), times sqrt(3) from the
   maximum norms used for the magnitudes to the Euclidean length. */
#define RT_HIT_K (16.0 * 1.7320508075688772 * 0x1p-53)

/* max(a, b) of non-negative values, inline (fmax is a libm call) */
static inline double rt_max2(double a, double b)
{
    return a > b ? a : b;
}

/* the largest |v[k]| of n values, from 0 in their order */
static inline double rt_absmax(const double *v, int n)
{
    double m = 0.0;
    for (int k = 0; k < n; k++)
        m = rt_max2(m, fabs(v[k]));
    return m;
}

/* The largest coordinate magnitude of the five points a, b, c, o, p (a hit's triangle, the
   ray's origin and the hit point): with SSE2 (every x86-64) two lanes at a time. A maximum
   of magnitudes is exact, so the order does not change the value (finite inputs: committed
   vertices, a checked ray); the scalar loop where SSE2 is absent. */
static inline double rt_absmax5(const double *a, const double *b, const double *c,
                                const double *o, const double *p)
{
#if defined(__SSE2__)
    const __m128d sg = _mm_set1_pd(-0.0);
    __m128d m = _mm_max_pd(_mm_andnot_pd(sg, _mm_loadu_pd(a)), _mm_andnot_pd(sg, _mm_loadu_pd(b)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_loadu_pd(c)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_loadu_pd(o)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_loadu_pd(p)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_loadh_pd(_mm_load_sd(a + 2), b + 2)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_loadh_pd(_mm_load_sd(c + 2), o + 2)));
    m = _mm_max_pd(m, _mm_andnot_pd(sg, _mm_load_sd(p + 2)));
    return _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
#else
    return rt_max2(rt_max2(rt_absmax(a, 3), rt_max2(rt_absmax(b, 3), rt_absmax(c, 3))),
                   rt_max2(rt_absmax(o, 3), rt_absmax(p, 3)));
#endif
}

/* The error bound of a hit at t of the triangle a b c (rt_nearest_update's, rt_geom.c): |n . d| / |n|
   of the plain cross product (scaled by its largest component, so that nothing overflows):
   the unit normal's cosine up to a few roundings, far cheaper than rt_prim_ng's robust
   normal; -1 for a degenerate cross product, which takes the general bound. Inline for the
   mesh lists of rt_trace.c, which hold the vertices of the triangle they just tested. */
static inline double rt_tri_hit_err_v(const rt_rayx *r, double t, const double *a,
                                      const double *b, const double *c)
{
    double ng[3], p[3];
    for (int k = 0; k < 3; k++)
        p[k] = r->o[k] + t * r->d[k];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    ng[0] = e1[1] * e2[2] - e1[2] * e2[1];
    ng[1] = e1[2] * e2[0] - e1[0] * e2[2];
    ng[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double m = rt_absmax(ng, 3);
    if (!(m > 0.0 && isfinite(m)))
        return -1.0;
    const double im = 1.0 / m, x = ng[0] * im, y = ng[1] * im, z = ng[2] * im;
    const double den = fabs(x * r->d[0] + y * r->d[1] + z * r->d[2]) / sqrt(x * x + y * y + z * z);
    const double s = rt_absmax5(a, b, c, r->o, p);
    if (!(den > 0.0)) /* no division by zero (the tests trap it) */
        return INFINITY;
    const double e = RT_HIT_K * s / den;
    return e >= 0.0 ? e : INFINITY;
}

/* rt_nearest_update's choice with the hit's bound e already computed (rt_tri_hit_err_v) */
void rt_nearest_take_e(const rt_scene *sc, uint32_t i, double t, double e, double *best, long *bi,
                       double *eb);

/* the front unit normal of committed triangle primitive i (rt_geom.c) */
void rt_prim_ng_tri(const rt_scene *sc, size_t i, double ng[3]);
/* the front unit normal of committed primitive i: a triangle's computed (rt_prim_ng_tri), the
   stored one of a quad, polygon or cell array copied inline (no call: the shading of every
   hit asks for it) */
static inline void rt_prim_ng(const rt_scene *sc, size_t i, double ng[3])
{
    if (i < sc->ntri) {
        rt_prim_ng_tri(sc, i, ng);
        return;
    }
    const rt_prim *p = rt_prim_rest(sc, i);
    const double *n;
    switch (p->kind) {
    case RT_KIND_QUAD:
        n = sc->quad[p->data].n;
        break;
    case RT_KIND_POLY:
        n = sc->poly[p->data].n;
        break;
    default:
        n = sc->cell[p->data].n;
        break;
    }
    memcpy(ng, n, 3 * sizeof(double));
}
#endif
