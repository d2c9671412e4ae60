/* SPDX-License-Identifier: MIT */
/*
 * rt_prim.h -- ray/primitive intersection tests (inline, shared by the traversal).
 * Private to src/rt.
 */
#ifndef GKS3D_RT_PRIM_H
#define GKS3D_RT_PRIM_H

#include "rt_internal.h"

#include <math.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif


/* Watertight ray/triangle test (Woop, Benthin, Wald 2013) of the triangle v0 v1 v2, double precision
 * with a long double fallback for edge functions that evaluate to exactly 0. rt_isect_tri_k:
 * the ray's axis order (kx, ky, kz, as r's) and its origin's components in that order (ox, oy,
 * oz) given as values, so that a caller that knows the order at compile time (rt_trace.c's
 * any-hit lists of mesh triangles) loads the vertices' components at constant offsets. */
static inline __attribute__((always_inline)) int
rt_isect_tri_k(const rt_rayx *r, int kx, int ky, int kz, double ox, double oy, double oz,
               const double *v0, const double *v1, const double *v2, double tmin, double tmax,
               double *tout)
{
    const double Az = v0[kz] - oz, Bz = v1[kz] - oz, Cz = v2[kz] - oz;
#if defined(__SSE2__)
    /* The same IEEE operations in SSE2 lanes (every x86-64 has SSE2; no FMA is formed
       without -march): a vertex's (x, y) pair in one register, the pairs of U, V and of the
       two products of W likewise; the signs and the zero test as compare masks. Each lane's
       value is the scalar code's (below), bit for bit, so the hits are unchanged. */
    const __m128d oxy = _mm_set_pd(oy, ox), sxy = _mm_loadu_pd(&r->sx);
    const __m128d A = _mm_sub_pd(_mm_sub_pd(_mm_loadh_pd(_mm_load_sd(v0 + kx), v0 + ky), oxy),
                                 _mm_mul_pd(sxy, _mm_set1_pd(Az)));
    const __m128d B = _mm_sub_pd(_mm_sub_pd(_mm_loadh_pd(_mm_load_sd(v1 + kx), v1 + ky), oxy),
                                 _mm_mul_pd(sxy, _mm_set1_pd(Bz)));
    const __m128d C = _mm_sub_pd(_mm_sub_pd(_mm_loadh_pd(_mm_load_sd(v2 + kx), v2 + ky), oxy),
                                 _mm_mul_pd(sxy, _mm_set1_pd(Cz)));
    /* (U, V) = (Cx By - Cy Bx, Ax Cy - Ay Cx); W = Bx Ay - By Ax from (Bx Ay, By Ax) */
    __m128d UV = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(C, A), _mm_unpackhi_pd(B, C)),
                            _mm_mul_pd(_mm_unpackhi_pd(C, A), _mm_unpacklo_pd(B, C)));
    const __m128d Wp = _mm_mul_pd(B, _mm_shuffle_pd(A, A, 1));
    __m128d W2 = _mm_sub_pd(_mm_unpacklo_pd(Wp, Wp), _mm_unpackhi_pd(Wp, Wp)); /* (W, W) */
    const __m128d z = _mm_setzero_pd();
    if (__builtin_expect(_mm_movemask_pd(_mm_or_pd(_mm_cmpeq_pd(UV, z), _mm_cmpeq_pd(W2, z))),
                         0)) {
        const double Ax = _mm_cvtsd_f64(A), Ay = _mm_cvtsd_f64(_mm_unpackhi_pd(A, A));
        const double Bx = _mm_cvtsd_f64(B), By = _mm_cvtsd_f64(_mm_unpackhi_pd(B, B));
        const double Cx = _mm_cvtsd_f64(C), Cy = _mm_cvtsd_f64(_mm_unpackhi_pd(C, C));
        UV = _mm_set_pd((double)((long double)Ax * Cy - (long double)Ay * Cx),
                        (double)((long double)Cx * By - (long double)Cy * Bx));
        W2 = _mm_set1_pd((double)((long double)Bx * Ay - (long double)By * Ax));
        const int neg = _mm_movemask_pd(_mm_or_pd(_mm_cmplt_pd(UV, z), _mm_cmplt_pd(W2, z)));
        const int pos = _mm_movemask_pd(_mm_or_pd(_mm_cmpgt_pd(UV, z), _mm_cmpgt_pd(W2, z)));
        const double U0 = _mm_cvtsd_f64(UV), V0 = _mm_cvtsd_f64(_mm_unpackhi_pd(UV, UV));
        if (((neg != 0) & (pos != 0)) | (U0 + V0 + _mm_cvtsd_f64(W2) == 0.0))
            return 0;
    } else if (_mm_movemask_pd(_mm_xor_pd(UV, W2))) {
        /* no edge function is +-0 here: the signs are mixed exactly when U's or V's sign
           bit differs from W's (a NaN, whatever its sign bit, ends at t = NaN below and is
           rejected either way), and U + V + W of three nonzero values of one sign is not 0:
           the same answers as the general test above, in four instructions */
        return 0;
    }
    const double U = _mm_cvtsd_f64(UV), V = _mm_cvtsd_f64(_mm_unpackhi_pd(UV, UV));
    const double W = _mm_cvtsd_f64(W2);
    const double det = U + V + W;
#else
    const double Ax = (v0[kx] - ox) - r->sx * Az, Ay = (v0[ky] - oy) - r->sy * Az;
    const double Bx = (v1[kx] - ox) - r->sx * Bz, By = (v1[ky] - oy) - r->sy * Bz;
    const double Cx = (v2[kx] - ox) - r->sx * Cz, Cy = (v2[ky] - oy) - r->sy * Cz;
    double U = Cx * By - Cy * Bx;
    double V = Ax * Cy - Ay * Cx;
    double W = Bx * Ay - By * Ax;
    if (U == 0.0 || V == 0.0 || W == 0.0) {
        U = (double)((long double)Cx * By - (long double)Cy * Bx);
        V = (double)((long double)Ax * Cy - (long double)Ay * Cx);
        W = (double)((long double)Bx * Ay - (long double)By * Ax);
    }
    /* the edge test as one data-dependent branch; the division only for rays through the
       triangle */
    const int mixed = ((U < 0.0) | (V < 0.0) | (W < 0.0)) & ((U > 0.0) | (V > 0.0) | (W > 0.0));
    const double det = U + V + W;
    if (mixed | (det == 0.0))
        return 0;
#endif
    const double T = U * (r->sz * Az) + V * (r->sz * Bz) + W * (r->sz * Cz);
    const double t = T / det;
    if (!(t >= tmin) | !(t <= tmax))
        return 0;
    *tout = t;
    return 1;
}

static inline __attribute__((always_inline)) int rt_isect_tri(const rt_rayx *r, const double *v0,
                                                              const double *v1, const double *v2,
                                                              double tmin, double tmax,
                                                              double *tout)
{
    const int kx = r->kx, ky = r->ky, kz = r->kz;
    /* only the components in the ray's axis order are formed (loaded by index straight from
       the triangle, no gather through a stack copy) */
    return rt_isect_tri_k(r, kx, ky, kz, r->o[kx], r->o[ky], r->o[kz], v0, v1, v2, tmin, tmax,
                          tout);
}

/* edge function of the sheared 2-D edge p -> q: exactly negated for q -> p (watertight) */
static inline __attribute__((always_inline)) double rt_edge(double px, double py, double qx,
                                                            double qy)
{
    double e = qx * py - qy * px;
    if (e == 0.0)
        e = (double)((long double)qx * py - (long double)qy * px);
    return e;
}

/* convex planar quad: the 4 edge functions of Woop et al. must agree in sign. The plane's t
   is checked first: a quad is often crossed behind the origin (the floor tiles around the
   point a shadow or reflection ray leaves) or beyond the nearest hit so far, and then its
   edge functions are not needed (the same hits and t as testing the edges first). */
/* the t at which ray r crosses a quad's plane: 0 when it is parallel (den == 0) */
static inline __attribute__((always_inline)) int rt_quad_plane_t(const rt_rayx *r, const rt_quad *q,
                                                                 double *t)
{
    const double *o = r->o;
    const double den = q->n[0] * r->d[0] + q->n[1] * r->d[1] + q->n[2] * r->d[2];
    if (den == 0.0)
        return 0;
    double A[3];
    for (int j = 0; j < 3; j++)
        A[j] = q->v[0][j] - o[j];
    *t = (q->n[0] * A[0] + q->n[1] * A[1] + q->n[2] * A[2]) / den;
    return 1;
}

static inline __attribute__((always_inline)) int rt_isect_quad(const rt_rayx *r, const rt_quad *q,
                                                               double tmin, double tmax,
                                                               double *tout)
{
    const double *o = r->o;
    double t;
    if (!rt_quad_plane_t(r, q, &t))
        return 0;
    if (!(t >= tmin) | !(t <= tmax))
        return 0;
    const int kx = r->kx, ky = r->ky, kz = r->kz;
#if defined(__SSE2__)
    {
        /* the same operations with a vertex's (x, y) in two SSE2 lanes and two edge functions
           a register (e0 e1, e2 e3), each value the scalar code's below, bit for bit; when
           none is 0 or NaN, each is < 0 or > 0 as its sign bit says, so the signs are mixed
           exactly when the four sign bits are; otherwise the scalar code decides */
        const __m128d oxy = _mm_set_pd(o[ky], o[kx]), sxy = _mm_loadu_pd(&r->sx);
        __m128d P[4];
        for (int k = 0; k < 4; k++) {
            const double *v = q->v[k];
            P[k] = _mm_sub_pd(_mm_sub_pd(_mm_loadh_pd(_mm_load_sd(v + kx), v + ky), oxy),
                              _mm_mul_pd(sxy, _mm_set1_pd(v[kz] - o[kz])));
        }
        /* e_k = x_k+1 y_k - y_k+1 x_k (rt_edge) */
        const __m128d E01 = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(P[1], P[2]), _mm_unpackhi_pd(P[0], P[1])),
                                       _mm_mul_pd(_mm_unpackhi_pd(P[1], P[2]), _mm_unpacklo_pd(P[0], P[1])));
        const __m128d E23 = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(P[3], P[0]), _mm_unpackhi_pd(P[2], P[3])),
                                       _mm_mul_pd(_mm_unpackhi_pd(P[3], P[0]), _mm_unpacklo_pd(P[2], P[3])));
        const __m128d z = _mm_setzero_pd();
        const __m128d sp = _mm_or_pd(_mm_or_pd(_mm_cmpeq_pd(E01, z), _mm_cmpeq_pd(E23, z)),
                                     _mm_cmpunord_pd(E01, E23));
        if (__builtin_expect(!_mm_movemask_pd(sp), 1)) {
            const int m = _mm_movemask_pd(E01) | _mm_movemask_pd(E23) << 2;
            if (m != 0 && m != 15)
                return 0;
            *tout = t;
            return 1;
        }
    }
#endif
    double x[4], y[4];
    for (int k = 0; k < 4; k++) {
        double az = q->v[k][kz] - o[kz];
        x[k] = (q->v[k][kx] - o[kx]) - r->sx * az;
        y[k] = (q->v[k][ky] - o[ky]) - r->sy * az;
    }
    double e0 = rt_edge(x[0], y[0], x[1], y[1]);
    double e1 = rt_edge(x[1], y[1], x[2], y[2]);
    double e2 = rt_edge(x[2], y[2], x[3], y[3]);
    double e3 = rt_edge(x[3], y[3], x[0], y[0]);
    const int mixed = ((e0 < 0.0) | (e1 < 0.0) | (e2 < 0.0) | (e3 < 0.0)) &
                      ((e0 > 0.0) | (e1 > 0.0) | (e2 > 0.0) | (e3 > 0.0));
    if (mixed)
        return 0;
    *tout = t;
    return 1;
}

/* the t at which ray r crosses a polygon's plane: 0 when it is parallel (den == 0) */
static inline __attribute__((always_inline)) int rt_poly_plane_t(const rt_rayx *r, const rt_poly *p,
                                                                 double *t)
{
    const double den = p->n[0] * r->d[0] + p->n[1] * r->d[1] + p->n[2] * r->d[2];
    if (den == 0.0)
        return 0;
    *t = (p->d - (p->n[0] * r->o[0] + p->n[1] * r->o[1] + p->n[2] * r->o[2])) / den;
    return 1;
}

/* plane hit + exact-sign even-odd crossing test on the dominant-axis projection */
static inline int rt_isect_poly(const rt_scene *sc, const rt_rayx *r, const rt_poly *p,
                                double tmin, double tmax, double *tout)
{
    double t;
    if (!rt_poly_plane_t(r, p, &t))
        return 0;
    if (!(t >= tmin && t <= tmax))
        return 0;
    const double pu = r->o[p->ku] + t * r->d[p->ku];
    const double pv = r->o[p->kv] + t * r->d[p->kv];
    /* exact rejects: no edge straddles v = pv outside [vmin,vmax]; right of umax no crossing
       lies to the right, left of umin every straddling edge does (an even number) */
    if (!(pv >= p->vmin && pv <= p->vmax && pu >= p->umin && pu <= p->umax))
        return 0;
    const double du = pu - p->cu, dv = pv - p->cv;
    if (du * du + dv * dv < p->rin2) { /* inside the edge-free disk: its parity */
        if (!p->cin)
            return 0;
        *tout = t;
        return 1;
    }
    if (du * du + dv * dv > p->rout2) /* beyond the disk holding all vertices: outside */
        return 0;
    if (p->pgrid) { /* a big polygon: its point-in-polygon grid, the same rule */
        if (!rt_pgrid_parity(&sc->pgrid[p->pgrid - 1], pu, pv))
            return 0;
        *tout = t;
        return 1;
    }
    uint32_t s = 0;
    if (p->nslab > 1) {
        double f = (pv - p->vmin) * p->inv_h;
        s = f > 0.0 ? (f >= (double)(p->nslab - 1) ? p->nslab - 1 : (uint32_t)f) : 0;
    }
    const size_t e0 = sc->slab_off[p->slab0 + s], e1 = sc->slab_off[p->slab0 + s + 1];
    const double *e = sc->edges + RT_EDGE_STRIDE * e0;
    /* branch-free even-odd count: edge (u0,v0)-(u1,v1), v0 < v1, straddles v = pv
       half-open (v0 <= pv < v1) and crosses it right of pu: (pv - v0)(u1 - u0) >
       (pu - u0)(v1 - v0), the differences u1 - u0, v1 - v0 stored (e[3], e[4]) */
    int inside = 0;
    size_t k = e0;
#if defined(__SSE2__)
    /* two edges at a time in SSE2 lanes: the same compares, differences and products as the
       scalar loop below, bit for bit */
    const __m128d vpv = _mm_set1_pd(pv), vpu = _mm_set1_pd(pu);
    for (; k + 2 <= e1; k += 2, e += 2 * RT_EDGE_STRIDE) {
        const double *f = e + RT_EDGE_STRIDE;
        const __m128d u0 = _mm_loadh_pd(_mm_load_sd(e), f);
        const __m128d v0 = _mm_loadh_pd(_mm_load_sd(e + 1), f + 1);
        const __m128d v1 = _mm_loadh_pd(_mm_load_sd(e + 2), f + 2);
        const __m128d du = _mm_loadh_pd(_mm_load_sd(e + 3), f + 3);
        const __m128d dv = _mm_loadh_pd(_mm_load_sd(e + 4), f + 4);
        const __m128d st = _mm_and_pd(_mm_cmple_pd(v0, vpv), _mm_cmplt_pd(vpv, v1));
        const __m128d cr = _mm_cmpgt_pd(_mm_mul_pd(_mm_sub_pd(vpv, v0), du),
                                        _mm_mul_pd(_mm_sub_pd(vpu, u0), dv));
        const int m = _mm_movemask_pd(_mm_and_pd(st, cr));
        inside ^= (m ^ (m >> 1)) & 1;
    }
#endif
    for (; k < e1; k++, e += RT_EDGE_STRIDE) {
        const int st = (e[1] <= pv) & (pv < e[2]);
        const int cr = (pv - e[1]) * e[3] > (pu - e[0]) * e[4];
        inside ^= st & cr;
    }
    if (!inside)
        return 0;
    *tout = t;
    return 1;
}

static inline int rt_isect_cell(const rt_rayx *r, const rt_cell *c, double tmin, double tmax,
                                double *tout)
{
    const double den = c->n[0] * r->d[0] + c->n[1] * r->d[1] + c->n[2] * r->d[2];
    if (den == 0.0)
        return 0;
    const double t = (c->d - (c->n[0] * r->o[0] + c->n[1] * r->o[1] + c->n[2] * r->o[2])) / den;
    if (!(t >= tmin && t <= tmax))
        return 0;
    const double qu = r->o[c->ku] + t * r->d[c->ku] - c->p[c->ku];
    const double qv = r->o[c->kv] + t * r->d[c->kv] - c->p[c->kv];
    const double s = c->inv[0][0] * qu + c->inv[0][1] * qv;
    const double w = c->inv[1][0] * qu + c->inv[1][1] * qv;
    if (!(s >= 0.0 && s <= 1.0 && w >= 0.0 && w <= 1.0))
        return 0;
    *tout = t;
    return 1;
}

/* The plane part of primitive i's test (rt_isect_prim), which needs only the ray's origin
   and direction: for a quad or polygon 1 with *t where r crosses its plane (the test then
   rejects t outside [tmin, tmax]), or 0 when r is parallel to it (the test rejects); -1
   for a triangle or cell array (not computed here) */
static inline __attribute__((always_inline)) int rt_prim_plane_t(const rt_scene *sc, const rt_rayx *r,
                                                                 size_t i, double *t)
{
    if (i < sc->ntri)
        return -1;
    if (i - sc->ntri < sc->nquad)
        return rt_quad_plane_t(r, &sc->quad[i - sc->ntri], t);
    const rt_prim *p = rt_prim_rest(sc, i);
    switch (p->kind) {
    case RT_KIND_QUAD:
        return rt_quad_plane_t(r, &sc->quad[p->data], t);
    case RT_KIND_POLY:
        return rt_poly_plane_t(r, &sc->poly[p->data], t);
    default:
        return -1;
    }
}

static inline __attribute__((always_inline)) int rt_isect_prim(const rt_scene *sc, const rt_rayx *r, size_t i, double tmin,
                                double tmax, double *t)
{
    if (i < sc->ntri) {
        const double *v[3];
        rt_tri_verts(sc, i, v);
        return rt_isect_tri(r, v[0], v[1], v[2], tmin, tmax, t);
    }
    if (i - sc->ntri < sc->nquad)
        return rt_isect_quad(r, &sc->quad[i - sc->ntri], tmin, tmax, t);
    const rt_prim *p = rt_prim_rest(sc, i);
    switch (p->kind) {
    case RT_KIND_TRI: {
        const double *v[3];
        rt_tri_verts(sc, p->data, v);
        return rt_isect_tri(r, v[0], v[1], v[2], tmin, tmax, t);
    }
    case RT_KIND_QUAD:
        return rt_isect_quad(r, &sc->quad[p->data], tmin, tmax, t);
    case RT_KIND_POLY:
        return rt_isect_poly(sc, r, &sc->poly[p->data], tmin, tmax, t);
    default:
        return rt_isect_cell(r, &sc->cell[p->data], tmin, tmax, t);
    }
}


#endif
