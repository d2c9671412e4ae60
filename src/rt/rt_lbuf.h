/* SPDX-License-Identifier: MIT */
/*
 * rt_lbuf.h -- a light buffer's query inline (rt_lbuf.c describes the buffers): the
 * projection of a shadow ray's origin, its footprint's cell and the list's first candidate,
 * for the shadow rays of rt_render.c without a call (rt_lbuf_query is the same, out of line).
 */
#ifndef GKS3D_RT_LBUF_H
#define GKS3D_RT_LBUF_H

#include "rt_internal.h"
#include "rt_prim.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#define RT_LBUF_BUCKETS 4096 /* depth order of the lists (uint16_t) */

static inline double rt_lbuf_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* projection of p onto the plane (u, v) and its depth z; 0 if not in front (perspective) */
static inline int rt_lbuf_proj(const rt_lbuf *lb, const double p[3], double *u, double *v,
                               double *z)
{
    const double w[3] = {p[0] - lb->L[0], p[1] - lb->L[1], p[2] - lb->L[2]};
    *z = rt_lbuf_dot3(w, lb->ez);
    *u = rt_lbuf_dot3(w, lb->ex);
    *v = rt_lbuf_dot3(w, lb->ey);
    if (lb->ortho)
        return 1;
    if (!(*z > 0.0))
        return 0;
    *u /= *z;
    *v /= *z;
    return 1;
}

/* depth bucket of z: non-decreasing in z */
static inline uint32_t rt_lbuf_bucket(const rt_lbuf *lb, double z)
{
    const double f = (z - lb->zlo) * lb->zscale;
    return f > 0.0 ? (f < (double)(RT_LBUF_BUCKETS - 1) ? (uint32_t)f : RT_LBUF_BUCKETS - 1) : 0;
}

/* rt_lbuf_find, rt_lbuf_find_z and rt_lbuf_query: *zo the depth of the ray's origin, (*uo,
   *vo) its projection, *mo the footprint's half side */
static inline __attribute__((always_inline)) int
rt_lbuf_find_at(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n, double *zo,
                double *uo, double *vo, double *mo)
{
#if defined(__SSE2__)
    /* rt_lbuf_proj and the footprint below with u and v in two SSE2 lanes: the same
       operations lane by lane (rt_lbuf.exy: the pairs of ex and ey; u0 v0, su sv and nu nv
       pairs in the record); the finiteness test in quiet compares (no FE_INVALID) */
    _Static_assert(offsetof(rt_lbuf, v0) == offsetof(rt_lbuf, u0) + sizeof(double) &&
                       offsetof(rt_lbuf, sv) == offsetof(rt_lbuf, su) + sizeof(double) &&
                       offsetof(rt_lbuf, nv) == offsetof(rt_lbuf, nu) + sizeof(int),
                   "rt_lbuf: (u0, v0), (su, sv), (nu, nv) in pairs");
    const double w[3] = {r->o[0] - lb->L[0], r->o[1] - lb->L[1], r->o[2] - lb->L[2]};
    const double z = rt_lbuf_dot3(w, lb->ez);
    __m128d uv = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(w[0]), _mm_loadu_pd(lb->exy[0])),
                                       _mm_mul_pd(_mm_set1_pd(w[1]), _mm_loadu_pd(lb->exy[1]))),
                            _mm_mul_pd(_mm_set1_pd(w[2]), _mm_loadu_pd(lb->exy[2])));
    if (!lb->ortho) {
        if (!(z > 0.0))
            return -1;
        uv = _mm_div_pd(uv, _mm_set1_pd(z));
    }
    if (_mm_movemask_pd(_mm_or_pd(_mm_cmpunord_pd(uv, uv),
                                  _mm_cmpeq_pd(_mm_andnot_pd(_mm_set1_pd(-0.0), uv),
                                               _mm_set1_pd(INFINITY)))))
        return -1;
    double m = lb->slack;
    if (!lb->ortho) { /* as below */
        const double c[3] = {w[1] * r->d[2] - w[2] * r->d[1], w[2] * r->d[0] - w[0] * r->d[2],
                             w[0] * r->d[1] - w[1] * r->d[0]};
        const double dev2 = rt_lbuf_dot3(c, c) / rt_lbuf_dot3(r->d, r->d);
        m += 2.0 * sqrt(dev2) * lb->kdev;
    }
    const __m128d mm = _mm_set1_pd(m), o0 = _mm_loadu_pd(&lb->u0), s = _mm_loadu_pd(&lb->su);
    const __m128d lo = _mm_mul_pd(_mm_sub_pd(_mm_sub_pd(uv, mm), o0), s);
    const __m128d hi = _mm_mul_pd(_mm_sub_pd(_mm_add_pd(uv, mm), o0), s);
    const __m128d nn = _mm_cvtepi32_pd(_mm_loadl_epi64((const __m128i *)(const void *)&lb->nu));
    const __m128d zero = _mm_setzero_pd();
    if (_mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(lo, zero), _mm_cmplt_pd(hi, nn))) != 3) {
        if (_mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(hi, zero), _mm_cmplt_pd(lo, nn))) == 3)
            return -1;
        *n = 0; /* wholly outside: the projections of all primitives lie inside */
        return 0;
    }
    const __m128i c0 = _mm_cvttpd_epi32(lo), c1 = _mm_cvttpd_epi32(hi);
    if (_mm_movemask_epi8(_mm_cmpeq_epi32(c0, c1)) != 0xffff)
        return -1;
    const int cx = _mm_cvtsi128_si32(c0), cy = _mm_cvtsi128_si32(_mm_shuffle_epi32(c0, 1));
    const size_t ci = (size_t)cy * (size_t)lb->nu + (size_t)cx;
    *ids = lb->ids + lb->off[ci];
    *n = lb->off[ci + 1] - lb->off[ci];
    *zo = z;
    *uo = _mm_cvtsd_f64(uv);
    *vo = _mm_cvtsd_f64(_mm_unpackhi_pd(uv, uv));
    *mo = m;
    return 1;
#else
    double u, v, z;
    if (!rt_lbuf_proj(lb, r->o, &u, &v, &z) || !isfinite(u) || !isfinite(v))
        return -1;
    double m = lb->slack;
    if (!lb->ortho) {
        /* distance of the light from the ray line (d need not be a unit vector); w = o - L as
           rt_lbuf_proj computes it (shared), the negation of L - o bit for bit, so c is
           negated exactly and dev2 is the same */
        const double w[3] = {r->o[0] - lb->L[0], r->o[1] - lb->L[1], r->o[2] - lb->L[2]};
        const double c[3] = {w[1] * r->d[2] - w[2] * r->d[1], w[2] * r->d[0] - w[0] * r->d[2],
                             w[0] * r->d[1] - w[1] * r->d[0]};
        const double dev2 = rt_lbuf_dot3(c, c) / rt_lbuf_dot3(r->d, r->d);
        /* 2x for the rounding of dev itself (~1e-16 |w|, far below the slack) */
        m += 2.0 * sqrt(dev2) * lb->kdev;
    }
    const double x0 = (u - m - lb->u0) * lb->su, x1 = (u + m - lb->u0) * lb->su;
    const double y0 = (v - m - lb->v0) * lb->sv, y1 = (v + m - lb->v0) * lb->sv;
    /* wholly inside first (most rays); x0 <= x1 and y0 <= y1 (m >= 0), so that test and
       the one for wholly outside never hold both */
    if (!(x0 >= 0.0 && y0 >= 0.0 && x1 < (double)lb->nu && y1 < (double)lb->nv)) {
        if (x1 >= 0.0 && y1 >= 0.0 && x0 < (double)lb->nu && y0 < (double)lb->nv)
            return -1;
        *n = 0; /* wholly outside: the projections of all primitives lie inside */
        return 0;
    }
    const int cx = (int)x0, cy = (int)y0;
    if (cx != (int)x1 || cy != (int)y1)
        return -1;
    const size_t ci = (size_t)cy * (size_t)lb->nu + (size_t)cx;
    *ids = lb->ids + lb->off[ci];
    *n = lb->off[ci + 1] - lb->off[ci];
    *zo = z;
    *uo = u;
    *vo = v;
    *mo = m;
    return 1;
#endif
}

/* 1 when the plane part of primitive i's exact test (rt_prim_plane_t) rejects ray r, with
   the same values: a quad or polygon whose plane r does not cross within [tmin, tmax]; 0
   otherwise (a triangle's test needs the ray's shear, rt_rayx_setup) */
static inline int rt_lbuf_plane_misses(const rt_scene *sc, const rt_rayx *r, uint32_t i)
{
    double t = 0.0;
    const int p = rt_prim_plane_t(sc, r, i, &t);
    return p == 0 || (p > 0 && !(t >= r->tmin && t <= r->tmax));
}

/* The footprint: every point of the ray at a primitive's depth projects within m of (u, v)
   on each axis, within 1.5 m in any direction. A ray that the primitive tests take to hit a
   primitive meets its projection there, to far less than the build's margin e; the lines
   are those of the projection as the build computed it (the cells' lists were made from
   the same points, enlarged by e), and their float rounding is below emargin - e. So a
   primitive with a line below -(1.5 m + emargin) at (u, v) cannot be hit: thr. With sc
   (the query's first candidate, r's range set), a quad or polygon whose exact test would
   reject r at its plane is passed over as well (rt_lbuf_plane_misses): 55 % of gears'
   exact shadow tests, which then often leave no candidate and no set-up. */
static inline __attribute__((always_inline)) uint32_t
rt_lbuf_next_at(const rt_lbuf *lb, const rt_lbuf_q *q, uint32_t skip, uint32_t k,
                const rt_scene *sc, const rt_rayx *r);

static inline __attribute__((always_inline)) int
rt_lbuf_query_at(const rt_scene *sc, const rt_lbuf *lb, const rt_rayx *r, uint32_t skip,
                 rt_lbuf_q *q, uint32_t *k0)
{
    double z, m, u, v;
    q->n = 0;
    const int f = rt_lbuf_find_at(lb, r, &q->ids, &q->n, &z, &u, &v, &m);
    if (f > 0) {
        q->zb = rt_lbuf_bucket(lb, z + lb->zeps);
        /* in float for the lines' arithmetic (its rounding: emargin); thr rounded up */
        q->u = (float)u;
        q->v = (float)v;
        q->thr = (float)((1.5 * m + lb->emargin) * (1.0 + 0x1p-20));
        *k0 = rt_lbuf_next_at(lb, q, skip, 0, sc, r);
    }
    return f;
}

static inline __attribute__((always_inline)) uint32_t
rt_lbuf_next_at(const rt_lbuf *lb, const rt_lbuf_q *q, uint32_t skip, uint32_t k,
                const rt_scene *sc, const rt_rayx *r)
{
    const uint16_t *zb = lb->zb;
#if defined(__SSE2__) /* the 4 lines at once */
    const __m128 vu = _mm_set1_ps(q->u), vv = _mm_set1_ps(q->v), vt = _mm_set1_ps(-q->thr);
#endif
    for (; k < q->n; k++) {
        const uint32_t i = q->ids[k];
        if (zb[i] > q->zb)
            return q->n;
        const float *e = lb->edge + 12 * (size_t)i;
#if defined(__SSE2__)
        const __m128 val = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(e), vu),
                                                 _mm_mul_ps(_mm_loadu_ps(e + 4), vv)),
                                      _mm_loadu_ps(e + 8));
        const int miss = _mm_movemask_ps(_mm_cmplt_ps(val, vt));
#else
        int miss = 0;
        for (int c = 0; c < 4; c++)
            miss |= (e[c] * q->u + e[4 + c] * q->v) + e[8 + c] < -q->thr;
#endif
        if (!(miss | (i == skip)) && !(sc && i >= sc->ntri && rt_lbuf_plane_misses(sc, r, i)))
            return k;
    }
    return q->n;
}

#endif
