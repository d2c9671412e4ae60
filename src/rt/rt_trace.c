/* SPDX-License-Identifier: MIT */
/*
 * rt_trace.c -- 3D-DDA traversal of the two-level uniform grid and the batch ray API.
 *
 * Mailboxes (per thread): nearest-hit and any-hit rays use a small direct-mapped one that
 * stays in L1 (a collision only repeats a test, which cannot change the result: same t, same
 * primitive, and the tie rule keeps it); transmittance through transparent surfaces uses the
 * exact one (each primitive's kt counted once). The nearest hit so far is kept even when it
 * lies beyond the current cell; traversal leaves at the first cell boundary beyond it.
 * Primitives are referenced by every cell their surface
 * overlaps with the cell box enlarged by a relative epsilon (rt_build.c), so a hit computed
 * near a cell face is found from either cell. Hits equal in t within their error bound go
 * to the larger primitive id (drawn later; rt_nearest_update), so grid and brute force
 * return identical hits. The DDA runs on the ray taken into the grid
 * frame (rotated or not, rt_build.c); hits are always computed on the original ray. In a cell
 * with a second-level grid the cell's own list (large primitives) is tested first, then the
 * second-level grid is walked over the part of the ray inside its box. In an empty top cell
 * far from any occupied one the walk jumps to where the ray leaves the empty block around it.
 * The walk covers only the ray's part inside the grid box and a k-DOP of the occupied space
 * (rt_kdop_clip).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"
#include "rt_internal.h"
#include "rt_packet.h"
#include "rt_prim.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* ---- ray setup ---- */

#define RT_RAY_MAX 1e100
#define RT_MIN(a, b) ((a) < (b) ? (a) : (b))
#define RT_MAX(a, b) ((a) > (b) ? (a) : (b))

static inline double rt_max3(double a, double b, double c)
{
    double m = a > b ? a : b; /* operands are never NaN here */
    return m > c ? m : c;
}

/* |x| as the bits of a double: for every x, NaN included, ordered like |x| with NaN above
   infinity, which is above every finite value (the checks below in integer compares: no
   branch per component, and no floating compare that a NaN would make raise FE_INVALID) */
static inline uint64_t rt_abits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u & ~((uint64_t)1 << 63);
}

static inline uint64_t rt_umax(uint64_t a, uint64_t b)
{
    return a > b ? a : b;
}

/* the checks of rt_rayx_setup and the ray's origin, direction and range; the shear for
   the primitive tests (rt_rayx_shear) not yet */
static inline __attribute__((always_inline)) int rt_rayx_valid(const double o[3],
                                                               const double d[3], double tmin,
                                                               double tmax, uint64_t *bdo)
{
    /* origin, direction and tmin finite with |x| <= RT_RAY_MAX, tmax not NaN, tmin <= tmax,
       and a direction whose largest component is >= 1e-100 (the t range stays meaningful):
       the same answers as the tests one by one, in integer compares of the bits */
    static const double lim[2] = {RT_RAY_MAX, 1e-100};
    uint64_t blim[2];
    memcpy(blim, lim, sizeof blim);
    const uint64_t bd = rt_umax(rt_abits(d[0]), rt_umax(rt_abits(d[1]), rt_abits(d[2])));
    const uint64_t bo = rt_umax(rt_abits(o[0]), rt_umax(rt_abits(o[1]), rt_abits(o[2])));
    if ((rt_umax(bd, rt_umax(bo, rt_abits(tmin))) > blim[0]) | (bd < blim[1]) |
        (rt_abits(tmax) > rt_abits(INFINITY)))
        return 0;
    if (tmin > tmax) /* both not NaN here */
        return 0;
    *bdo = bd; /* the bits of the largest |d[i]| */
    return 1;
}

static inline __attribute__((always_inline)) int rt_rayx_check(rt_rayx *r, const double o[3],
                                                               const double d[3], double tmin,
                                                               double tmax)
{
    uint64_t bd;
    if (!rt_rayx_valid(o, d, tmin, tmax, &bd))
        return 0;
    double dm;
    memcpy(&dm, &bd, sizeof dm); /* the largest |d[i]| */
    const double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
    memcpy(r->o, o, sizeof r->o);
    /* components below 1e-150 of the largest are flushed to 0 (finite 1/d everywhere);
       selects, not branches */
    const double tiny = 1e-150 * dm;
    r->d[0] = ax < tiny ? 0.0 : d[0];
    r->d[1] = ay < tiny ? 0.0 : d[1];
    r->d[2] = az < tiny ? 0.0 : d[2];
    r->tmin = tmin;
    r->tmax = tmax;
    r->skip = RT_NO_SKIP;
    return 1;
}

/* the ray's shear for the watertight primitive tests (rt_prim.h) */
static inline __attribute__((always_inline)) void rt_rayx_shear(rt_rayx *r)
{
    const double *d = r->d;
    const double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
    /* dominant axis kz, the other two swapped for a negative d[kz] (winding kept); written
       branch-free: the outcome is random for incoherent rays */
    const int kz = ((ax < ay) | (ax < az)) * (1 + (ay < az));
    const int neg = d[kz] < 0.0;
    /* (kz + 1 + neg) % 3 and (kz + 2 - neg) % 3 */
    static const int8_t next[2][3][2] = {{{1, 2}, {2, 0}, {0, 1}}, {{2, 1}, {0, 2}, {1, 0}}};
    const int kx = next[neg][kz][0], ky = next[neg][kz][1];
    r->kx = kx;
    r->ky = ky;
    r->kz = kz;
    r->sz = 1.0 / d[kz];
    r->sx = d[kx] * r->sz;
    r->sy = d[ky] * r->sz;
}

int rt_rayx_setup(rt_rayx *r, const double o[3], const double d[3], double tmin, double tmax)
{
    if (!rt_rayx_check(r, o, d, tmin, tmax))
        return 0;
    rt_rayx_shear(r);
    return 1;
}

/* rt_rayx_setup(r, o, d, tmin, tmax) for r whose o, d, tmin and tmax are already what it
   would make of them (d's flushed components change neither its largest one nor a check) */
int rt_rayx_setup_made(rt_rayx *r)
{
    uint64_t bd;
    if (!rt_rayx_valid(r->o, r->d, r->tmin, r->tmax, &bd))
        return 0;
    r->skip = RT_NO_SKIP;
    rt_rayx_shear(r);
    return 1;
}

/* the ray in the grid frame: identity copy or rotated (tiny components flushed to 0) */
static inline __attribute__((always_inline)) void rt_gray_init(const rt_grid *g, const rt_rayx *r, rt_gray *out)
{
    if (!g->rotated) {
        memcpy(out->o, r->o, sizeof out->o);
        memcpy(out->d, r->d, sizeof out->d);
#if defined(__SSE2__)
        /* the same reciprocals in two SSE2 divisions (lanes 0-1, lane 2) instead of three
           tests and divisions: a 0 component divides by 1 and is masked to +0 */
        const __m128d one = _mm_set1_pd(1.0), z = _mm_setzero_pd();
        const __m128d d01 = _mm_loadu_pd(r->d), d2 = _mm_load_sd(r->d + 2);
        const __m128d m01 = _mm_cmpneq_pd(d01, z), m2 = _mm_cmpneq_pd(d2, z);
        const __m128d q01 =
            _mm_div_pd(one, _mm_or_pd(_mm_and_pd(m01, d01), _mm_andnot_pd(m01, one)));
        const __m128d q2 = _mm_div_sd(one, _mm_or_pd(_mm_and_pd(m2, d2), _mm_andnot_pd(m2, one)));
        _mm_storeu_pd(out->invd, _mm_and_pd(q01, m01));
        _mm_store_sd(out->invd + 2, _mm_and_pd(q2, m2));
#else
        for (int i = 0; i < 3; i++)
            out->invd[i] = r->d[i] != 0.0 ? 1.0 / r->d[i] : 0.0;
#endif
        return;
    }
    const double q[3] = {r->o[0] - g->c[0], r->o[1] - g->c[1], r->o[2] - g->c[2]};
    for (int a = 0; a < 3; a++) {
        out->o[a] = g->R[a][0] * q[0] + g->R[a][1] * q[1] + g->R[a][2] * q[2];
        out->d[a] = g->R[a][0] * r->d[0] + g->R[a][1] * r->d[1] + g->R[a][2] * r->d[2];
    }
    double dm = rt_max3(fabs(out->d[0]), fabs(out->d[1]), fabs(out->d[2]));
    for (int i = 0; i < 3; i++) {
        if (fabs(out->d[i]) < 1e-150 * dm)
            out->d[i] = 0.0;
        out->invd[i] = out->d[i] != 0.0 ? 1.0 / out->d[i] : 0.0;
    }
}

/* ---- mailbox context ---- */

int rt_ctx_init(rt_ctx *c, const rt_scene *sc)
{
    c->nprim = sc->nprim;
    c->stamp = 0;
    c->beside = 0;
    c->mbox = rt_calloc_array(sc->nprim ? sc->nprim : 1, sizeof(uint32_t));
    c->hbox = rt_calloc_array(RT_HBOX, sizeof(uint64_t));
    if (c->mbox && c->hbox)
        return RT_OK;
    rt_ctx_free(c);
    return RT_ERR_NOMEM;
}

/* a context for nearest-hit and any-hit rays only (the batch API): the small mailbox, no
   exact one (nprim entries, zeroed for every call: 4 B per primitive written per rt_intersect
   call, however few its rays) */
static int rt_ctx_init_small(rt_ctx *c)
{
    c->nprim = 0;
    c->stamp = 0;
    c->beside = 0;
    c->mbox = NULL;
    c->hbox = rt_calloc_array(RT_HBOX, sizeof(uint64_t));
    return c->hbox ? RT_OK : RT_ERR_NOMEM;
}

void rt_ctx_free(rt_ctx *c)
{
    free(c->mbox);
    free(c->hbox);
    c->mbox = NULL;
    c->hbox = NULL;
}

static inline uint32_t rt_ctx_next(rt_ctx *c)
{
    if (++c->stamp == 0) {
        if (c->mbox)
            memset(c->mbox, 0, c->nprim * sizeof(uint32_t));
        memset(c->hbox, 0, RT_HBOX * sizeof(uint64_t));
        c->stamp = 1;
    }
    return c->stamp;
}

/* ---- DDA ---- */

typedef struct rt_dda {
    int c[3], step[3];
    double tnext[3];
    double t0, t1;
} rt_dda;

/* the parameter where the ray crosses boundary b (0 .. n) of axis a */
static inline double rt_dda_bound(const rt_box *g, const rt_gray *r, int b, int a)
{
    double x = b == g->n[a] ? g->hi[a] : g->lo[a] + (double)b * g->cw[a];
    return (x - r->o[a]) * r->invd[a];
}

/* the cell of axis a holding the ray point at t, clamped into the box */
static inline int rt_dda_cell(const rt_box *g, const rt_gray *r, double t, int a)
{
    double p = r->o[a] + t * r->d[a];
    double f = (p - g->lo[a]) * g->inv_cw[a];
    return f <= 0.0 ? 0 : (f >= (double)(g->n[a] - 1) ? g->n[a] - 1 : (int)f);
}

/* rt_box_clip's loop: any ray (a direction component 0 is a slab test) */
static inline __attribute__((always_inline)) int rt_box_clip_loop(const rt_box *g, const rt_gray *r,
                                                                  double *t0p, double *t1p)
{
    double t0 = *t0p, t1 = *t1p;
    for (int a = 0; a < 3; a++) {
        if (r->d[a] == 0.0) { /* +0.0 and -0.0 */
            if (r->o[a] < g->lo[a] || r->o[a] > g->hi[a])
                return 0;
            continue;
        }
        /* min / max as selects, not branches: which slab plane is the near one
           depends on the direction's sign, random for incoherent rays */
        const double ta = (g->lo[a] - r->o[a]) * r->invd[a];
        const double tb = (g->hi[a] - r->o[a]) * r->invd[a];
        const double tn = RT_MIN(ta, tb), tf = tb < ta ? ta : tb;
        t0 = tn > t0 ? tn : t0;
        t1 = RT_MIN(tf, t1);
    }
    if (!(t0 <= t1) || !isfinite(t0))
        return 0;
    *t0p = t0;
    *t1p = t1;
    return 1;
}

/* rt_box_clip for a ray known to have no direction component 0 (the four-ray set-up's rays:
   the walk's sub-grid clips skip the test) */
static inline __attribute__((always_inline)) int rt_box_clip_nz(const rt_box *g, const rt_gray *r,
                                                                double *t0p, double *t1p)
{
#if defined(__SSE2__)
    /* the same operations as the loop with axes 0-1 in two SSE2 lanes, the range cut axis by
       axis in the loop's order (max_sd / min_sd keep the loop's pick between +0 and -0) */
    double t0 = *t0p, t1 = *t1p;
    const __m128d o01 = _mm_loadu_pd(r->o), i01 = _mm_loadu_pd(r->invd);
    const __m128d o2 = _mm_load_sd(r->o + 2), i2 = _mm_load_sd(r->invd + 2);
    const __m128d ta01 = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(g->lo), o01), i01);
    const __m128d tb01 = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(g->hi), o01), i01);
    const __m128d ta2 = _mm_mul_sd(_mm_sub_sd(_mm_load_sd(g->lo + 2), o2), i2);
    const __m128d tb2 = _mm_mul_sd(_mm_sub_sd(_mm_load_sd(g->hi + 2), o2), i2);
    const __m128d tn01 = _mm_min_pd(ta01, tb01), tf01 = _mm_max_pd(ta01, tb01);
    const __m128d tn2 = _mm_min_sd(ta2, tb2), tf2 = _mm_max_sd(ta2, tb2);
    __m128d v0 = _mm_max_sd(tn01, _mm_set_sd(t0)), v1 = _mm_min_sd(tf01, _mm_set_sd(t1));
    v0 = _mm_max_sd(_mm_unpackhi_pd(tn01, tn01), v0);
    v1 = _mm_min_sd(_mm_unpackhi_pd(tf01, tf01), v1);
    t0 = _mm_cvtsd_f64(_mm_max_sd(tn2, v0));
    t1 = _mm_cvtsd_f64(_mm_min_sd(tf2, v1));
    if (!(t0 <= t1) || !isfinite(t0))
        return 0;
    *t0p = t0;
    *t1p = t1;
    return 1;
#else
    return rt_box_clip_loop(g, r, t0p, t1p);
#endif
}

/* cuts the ray part [*t0, *t1] to box g: 0 if nothing remains */
static inline __attribute__((always_inline)) int rt_box_clip(const rt_box *g, const rt_gray *r,
                                                             double *t0p, double *t1p)
{
#if defined(__SSE2__)
    /* no component 0 (the usual ray): the SSE2 lanes */
    const __m128d z = _mm_setzero_pd(), d01 = _mm_loadu_pd(r->d), d2 = _mm_load_sd(r->d + 2);
    if (!_mm_movemask_pd(_mm_or_pd(_mm_cmpeq_pd(d01, z), _mm_cmpeq_sd(d2, z))))
        return rt_box_clip_nz(g, r, t0p, t1p);
#endif
    return rt_box_clip_loop(g, r, t0p, t1p);
}

/* The cut of the ray part [*t0, *t1] (clipped to the grid box) to the slabs of the occupied
 * space's k-DOP (rt_grid.kd_lo, kd_hi): 0 if nothing remains. Every primitive point lies in
 * the slabs with the k-DOP's pad to spare, which is larger than the roundings of these
 * sums, products and quotients, as the grid box's pad is for rt_box_clip: so the cut part
 * holds every point where the ray meets a primitive, and the walk from its start to its end
 * meets every primitive the ray hits. A slab the ray runs (nearly) parallel to, |s_j(d)|
 * below RT_KDOP_PAR of |d|'s 1-norm, does not cut (no overflow, no division by 0). The
 * four-ray set-up does the same in lanes. */
#define RT_KDOP_PAR 0x1p-20
/* rt_kdop_clip's loop: any ray (a slab it runs nearly parallel to does not cut) */
static int rt_kdop_clip_loop(const rt_grid *g, const rt_gray *r, double *t0p, double *t1p)
{
    double po[RT_KDOP], pd[RT_KDOP], t0 = *t0p, t1 = *t1p;
    RT_KDOP_PROJ(po, r->o[0], r->o[1], r->o[2]);
    RT_KDOP_PROJ(pd, r->d[0], r->d[1], r->d[2]);
    const double dn = RT_KDOP_PAR * (fabs(r->d[0]) + fabs(r->d[1]) + fabs(r->d[2]));
    for (int j = 0; j < RT_KDOP; j++) {
        if (!(fabs(pd[j]) >= dn))
            continue;
        const double iv = 1.0 / pd[j];
        const double ta = (g->kd_lo[j] - po[j]) * iv, tb = (g->kd_hi[j] - po[j]) * iv;
        const double tn = RT_MIN(ta, tb), tf = tb < ta ? ta : tb;
        t0 = tn > t0 ? tn : t0;
        t1 = RT_MIN(tf, t1);
    }
    if (!(t0 <= t1))
        return 0;
    *t0p = t0;
    *t1p = t1;
    return 1;
}

#if defined(__SSE2__)
/* the projections of (x, y, z) on the k-DOP's directions (RT_KDOP_PROJ) in the pairs s0 s1,
   s2 s3, s4 s5, s6 s7, s8 s9, the same sums (a - b as a + (-b): the same IEEE result) */
static inline __attribute__((always_inline)) void rt_kdop_proj2(const double v[3], __m128d s[5])
{
    const __m128d sg1 = _mm_set_pd(-0.0, 0.0); /* the sign of lane 1 flipped */
    const __m128d xx = _mm_set1_pd(v[0]), yy = _mm_set1_pd(v[1]), zz = _mm_set1_pd(v[2]);
    const __m128d zn = _mm_xor_pd(zz, sg1);
    const __m128d s45 = _mm_add_pd(xx, _mm_xor_pd(yy, sg1)); /* x + y, x - y */
    s[0] = _mm_add_pd(_mm_unpacklo_pd(s45, s45), zn);
    s[1] = _mm_add_pd(_mm_unpackhi_pd(s45, s45), zn);
    s[2] = s45;
    s[3] = _mm_add_pd(xx, zn);
    s[4] = _mm_add_pd(yy, zn);
}
#endif

static inline __attribute__((always_inline)) int rt_kdop_clip(const rt_grid *g, const rt_gray *r,
                                                              double *t0p, double *t1p)
{
#if defined(__SSE2__)
    /* rt_kdop_clip_loop with the slabs in pairs in SSE2 lanes when the ray cuts by all ten (no
       slab it runs nearly parallel to, the usual ray): the same operations per slab, and the
       range cut slab by slab in the loop's order (max_sd / min_sd pick as its selects do) */
    _Static_assert(RT_KDOP == 10, "rt_kdop_clip: five pairs of slabs");
    __m128d po[5], pd[5];
    rt_kdop_proj2(r->d, pd);
    const __m128d dn = _mm_set1_pd(RT_KDOP_PAR * (fabs(r->d[0]) + fabs(r->d[1]) + fabs(r->d[2])));
    const __m128d sgn = _mm_set1_pd(-0.0);
    __m128d use = _mm_cmpge_pd(_mm_andnot_pd(sgn, pd[0]), dn);
    for (int k = 1; k < 5; k++)
        use = _mm_and_pd(use, _mm_cmpge_pd(_mm_andnot_pd(sgn, pd[k]), dn));
    if (_mm_movemask_pd(use) == 3) {
        rt_kdop_proj2(r->o, po);
        const __m128d one = _mm_set1_pd(1.0);
        __m128d v0 = _mm_set_sd(*t0p), v1 = _mm_set_sd(*t1p);
        for (int k = 0; k < 5; k++) {
            const __m128d iv = _mm_div_pd(one, pd[k]);
            const __m128d ta = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(g->kd_lo + 2 * k), po[k]), iv);
            const __m128d tb = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(g->kd_hi + 2 * k), po[k]), iv);
            const __m128d tn = _mm_min_pd(ta, tb), tf = _mm_max_pd(ta, tb);
            v0 = _mm_max_sd(tn, v0);
            v1 = _mm_min_sd(tf, v1);
            v0 = _mm_max_sd(_mm_unpackhi_pd(tn, tn), v0);
            v1 = _mm_min_sd(_mm_unpackhi_pd(tf, tf), v1);
        }
        const double t0 = _mm_cvtsd_f64(v0), t1 = _mm_cvtsd_f64(v1);
        if (!(t0 <= t1))
            return 0;
        *t0p = t0;
        *t1p = t1;
        return 1;
    }
#endif
    return rt_kdop_clip_loop(g, r, t0p, t1p);
}

/* Sets up the DDA over box g for the ray part [t0, t1]. clip = 1: the range is first cut
 * to the box (0 if nothing remains); clip = 0 (the range is already inside the box up to
 * rounding, or cut by rt_box_clip): the start cell is clamped into the box instead. step:
 * the ray's steps when known (rt_walkstate.step, the sign of each direction component as
 * computed here), else NULL. */
static inline __attribute__((always_inline)) int rt_dda_init(const rt_box *g, const rt_gray *r, double t0, double t1, int clip,
                              const int *step, rt_dda *s)
{
    if (clip && !rt_box_clip(g, r, &t0, &t1))
        return 0;
    s->t0 = t0;
    s->t1 = t1;
    int a = 0;
#if defined(__SSE2__)
    {
        /* axes 0 and 1 in two SSE2 lanes, the same operations: the start cell (a clamp of
           f to [0, n - 1] before the truncation picks what rt_dda_cell's tests pick), the
           next boundary c + 1 (d > 0) or c (d < 0) at hi when it is n, INFINITY for d = 0 */
        const __m128d z = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
        const __m128d o = _mm_loadu_pd(r->o), d = _mm_loadu_pd(r->d);
        const __m128d nd = _mm_cvtepi32_pd(_mm_loadl_epi64((const __m128i *)g->n));
        const __m128d p = _mm_add_pd(o, _mm_mul_pd(_mm_set1_pd(t0), d));
        const __m128d f = _mm_mul_pd(_mm_sub_pd(p, _mm_loadu_pd(g->lo)), _mm_loadu_pd(g->inv_cw));
        const __m128i c = _mm_cvttpd_epi32(_mm_min_pd(_mm_max_pd(f, z), _mm_sub_pd(nd, one)));
        _mm_storel_epi64((__m128i *)s->c, c);
        const __m128d pos = _mm_cmpgt_pd(d, z), zero = _mm_cmpeq_pd(d, z);
        const __m128d b = _mm_add_pd(_mm_cvtepi32_pd(c), _mm_and_pd(pos, one));
        const __m128d xl = _mm_add_pd(_mm_loadu_pd(g->lo), _mm_mul_pd(b, _mm_loadu_pd(g->cw)));
        const __m128d top = _mm_cmpeq_pd(b, nd);
        const __m128d x = _mm_or_pd(_mm_and_pd(top, _mm_loadu_pd(g->hi)), _mm_andnot_pd(top, xl));
        const __m128d tn = _mm_mul_pd(_mm_sub_pd(x, o), _mm_loadu_pd(r->invd));
        _mm_storeu_pd(s->tnext, _mm_or_pd(_mm_and_pd(zero, _mm_set1_pd(INFINITY)),
                                          _mm_andnot_pd(zero, tn)));
        if (step) {
            s->step[0] = step[0];
            s->step[1] = step[1];
        } else {
            s->step[0] = (r->d[0] > 0.0) - (r->d[0] < 0.0);
            s->step[1] = (r->d[1] > 0.0) - (r->d[1] < 0.0);
        }
        a = 2;
    }
#endif
    for (; a < 3; a++) {
        const int c = rt_dda_cell(g, r, t0, a);
        s->c[a] = c;
        if (step ? step[a] > 0 : r->d[a] > 0.0) {
            s->step[a] = 1;
            s->tnext[a] = rt_dda_bound(g, r, c + 1, a);
        } else if (step ? step[a] < 0 : r->d[a] < 0.0) {
            s->step[a] = -1;
            s->tnext[a] = rt_dda_bound(g, r, c, a);
        } else {
            s->step[a] = 0;
            s->tnext[a] = INFINITY;
        }
    }
    return 1;
}

/* ---- the batch API's set-up of four rays at a time ---- */

/* What rt_rayx_check, rt_gray_init, rt_box_clip (the grid box), rt_kdop_clip, rt_dda_init and
 * the walk's constants of rt_walk_box compute for one ray, for four rays in structure-of-arrays
 * lanes (rt_setup4: GCC vector extensions and AVX2 intrinsics, 4 lanes in one register, chosen
 * at run time). Every lane does the same IEEE operations in the same order as the one-ray
 * code, and where that code picks between equal values it picks the same operand, so the walk
 * starts from the same cell with the same boundaries, bit for bit. Lanes whose ray is unusual
 * take the one-ray code instead: state 0 (a check fails, a direction component is 0 or flushed
 * to 0 by rt_rayx_check or by the rotation into the grid frame, which the one-ray clip treats
 * as a slab, or the ray runs parallel to a slab of the k-DOP, which the one-ray cut skips);
 * state 1: a usable ray that misses the grid box or the k-DOP; state 2: it enters both, and
 * the start below holds (no direction component 0). */
typedef struct rt_pre4 {
    int state[4];
    int oct[4];            /* octant: bit a set for d[a] < 0 */
    int c[3][4];           /* start cell */
    int step[3][4];        /* 1 or -1 */
    int ci[4];             /* the start cell's index (c2 n1 + c1) n0 + c0 */
    int dy[4], dz[4];      /* the index's steps along y and z, step[1] n0 and step[2] n0 n1
                              (32 bits: the set-up is taken for top grids of fewer than 2^31
                              cells only, rt_setup4_choose) */
    double invd[3][4];     /* 1 / d */
    double t0[4], t1[4];   /* the range clipped to the grid box */
    double tn[3][4];       /* next cell boundary in ray parameter */
    double dt[3][4];       /* a cell's width in ray parameter */
    double it[3][4];       /* about 1 / dt (the jumps' counts) */
    double o[3][4], d[3][4]; /* the ray in the grid frame (rt_gray_init) */
    int kx[4], ky[4], kz[4]; /* rt_rayx_shear of the input direction */
    int ord[4];              /* its axis order in rt_list_order's numbering, 2 kz + (the
                                order swapped for a negative d[kz]) */
    double sx[4], sy[4], sz[4];
} rt_pre4;

typedef double rt_v4d __attribute__((vector_size(32)));
typedef int64_t rt_v4l __attribute__((vector_size(32)));
typedef int32_t rt_v4i __attribute__((vector_size(16)));

/* m ? a : b for the compare masks (all bits set or clear per lane); |x| as bits (macros: a
   function returning a 32-byte vector has a different ABI with and without AVX) */
#define rt_v4sel(m, a, b) ((rt_v4d)(((m) & (rt_v4l)(a)) | (~(m) & (rt_v4l)(b))))
#define rt_v4abits(x) ((rt_v4l)(x) & (rt_v4l){INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX})

#if defined(__x86_64__) && defined(__GNUC__)
#define RT_SETUP4_AVX2 1
#include <immintrin.h>

/* a < b ? a : b and a > b ? a : b (either NaN: b) as one instruction each (GCC's vectors
   make a compare and a blend) */
#define rt_v4min(a, b) ((rt_v4d)_mm256_min_pd((__m256d)(a), (__m256d)(b)))
#define rt_v4max(a, b) ((rt_v4d)_mm256_max_pd((__m256d)(a), (__m256d)(b)))

/* the low 32 bits of each 64-bit lane of x (__builtin_convertvector's truncation to rt_v4i):
   one lane permutation (GCC narrows with an extract and two shuffles) */
#define rt_v4narrow(x)                                                                     \
    ((rt_v4i)_mm256_castsi256_si128(                                                       \
        _mm256_permutevar8x32_epi32((__m256i)(x), _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6))))

/* rt_kdop_clip's cut of the four lanes' [t0, t1] to the occupied space's slabs (o, d: the
   rays in the grid frame); a lane with a slab it runs (nearly) parallel to is marked in
   *par and left to the one-ray code, which skips that slab (rare: |s_j(d)| below
   RT_KDOP_PAR of |d|'s 1-norm). Intrinsics: GCC's vectors give min, max and blends as
   three operations each. */
static inline __attribute__((always_inline, target("avx2"))) void
rt_kdop4(const rt_grid *g, const rt_v4d o[3], const rt_v4d d[3], rt_v4d *t0, rt_v4d *t1,
         rt_v4l *par)
{
    rt_v4d po[RT_KDOP], pd[RT_KDOP];
    RT_KDOP_PROJ(po, o[0], o[1], o[2]);
    RT_KDOP_PROJ(pd, d[0], d[1], d[2]);
    const __m256d sgn = _mm256_set1_pd(-0.0), one = _mm256_set1_pd(1.0);
    const __m256d dn = _mm256_mul_pd(
        _mm256_set1_pd(RT_KDOP_PAR),
        _mm256_add_pd(_mm256_add_pd(_mm256_andnot_pd(sgn, (__m256d)d[0]),
                                    _mm256_andnot_pd(sgn, (__m256d)d[1])),
                      _mm256_andnot_pd(sgn, (__m256d)d[2])));
    __m256d k0 = (__m256d)*t0, k1 = (__m256d)*t1, pm = _mm256_setzero_pd();
#pragma GCC unroll 10
    for (int j = 0; j < RT_KDOP; j++) {
        const __m256d pj = (__m256d)pd[j], oj = (__m256d)po[j];
        const __m256d pl = _mm256_cmp_pd(_mm256_andnot_pd(sgn, pj), dn, _CMP_LT_OQ);
        pm = _mm256_or_pd(pm, pl);
        const __m256d iv = _mm256_div_pd(one, _mm256_blendv_pd(pj, one, pl));
        const __m256d ta = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(g->kd_lo[j]), oj), iv);
        const __m256d tb = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(g->kd_hi[j]), oj), iv);
        k0 = _mm256_max_pd(_mm256_min_pd(ta, tb), k0);
        k1 = _mm256_min_pd(_mm256_max_pd(ta, tb), k1);
    }
    *t0 = (rt_v4d)k0;
    *t1 = (rt_v4d)k1;
    *par = (rt_v4l)pm;
}

/* rt_rayx_shear of the four lanes' directions d (the input directions: no component of a
   lane in state 2 is flushed), the same rule and operations: kz the first of the largest
   |d| ((ax < ay) | (ax < az)) * (1 + (ay < az)), kx and ky after it in cyclic order, swapped
   for a negative d[kz]; sz = 1 / d[kz], sx = d[kx] sz, sy = d[ky] sz. One set of lanes
   instead of a shear per walked ray (some 40 instructions each). */
static inline __attribute__((always_inline, target("avx2"))) void rt_shear4(const rt_v4d d[3],
                                                                          rt_pre4 *p)
{
    const rt_v4d ax = (rt_v4d)rt_v4abits(d[0]), ay = (rt_v4d)rt_v4abits(d[1]),
                 az = (rt_v4d)rt_v4abits(d[2]);
    const rt_v4l one = {1, 1, 1, 1};
    const rt_v4l m1 = (ax < ay) | (ax < az), m2 = ay < az;
    const rt_v4l kz = (m1 & one) + (m1 & m2 & one);
    const rt_v4d dz = rt_v4sel(kz == 0, d[0], rt_v4sel(kz == 1, d[1], d[2]));
    const rt_v4l ng = (dz < (rt_v4d){0.0, 0.0, 0.0, 0.0}) & one;
    /* (kz + 1 + neg) % 3 and (kz + 2 - neg) % 3 */
    rt_v4l kx = kz + one + ng, ky = kz + 2 * one - ng;
    kx -= (kx >= 3 * one) & (3 * one);
    ky -= (ky >= 3 * one) & (3 * one);
    const rt_v4d dx = rt_v4sel(kx == 0, d[0], rt_v4sel(kx == 1, d[1], d[2]));
    const rt_v4d dy = rt_v4sel(ky == 0, d[0], rt_v4sel(ky == 1, d[1], d[2]));
    const rt_v4d sz = (rt_v4d){1.0, 1.0, 1.0, 1.0} / dz, sx = dx * sz, sy = dy * sz;
    const rt_v4i ord4 = rt_v4narrow(kz + kz + ng);
    memcpy(p->ord, &ord4, sizeof p->ord);
    const rt_v4i kx4 = rt_v4narrow(kx), ky4 = rt_v4narrow(ky), kz4 = rt_v4narrow(kz);
    memcpy(p->kx, &kx4, sizeof p->kx);
    memcpy(p->ky, &ky4, sizeof p->ky);
    memcpy(p->kz, &kz4, sizeof p->kz);
    memcpy(p->sx, &sx, sizeof p->sx);
    memcpy(p->sy, &sy, sizeof p->sy);
    memcpy(p->sz, &sz, sizeof p->sz);
}

/* two fields of the four rays' records, the doubles at k and k + 1 (org[0..2], dir[0..2],
   tmin, tmax), in lanes: the pairs of rays 0 and 2 and of rays 1 and 3 in the halves of two
   registers, unpacked (6 instructions for two fields; lane by lane the bits of the input) */
_Static_assert(sizeof(rt_ray) == 8 * sizeof(double) && offsetof(rt_ray, tmax) == 7 * sizeof(double),
               "rt_ray: eight doubles");
static inline __attribute__((always_inline, target("avx2"))) void
rt_rays4_pair(const rt_ray *ray, int k, rt_v4d *lo, rt_v4d *hi)
{
#define RT_RAY_AT(j) ((const double *)(const void *)(ray + (j)) + k)
    const __m256d e = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(RT_RAY_AT(0))),
                                           _mm_loadu_pd(RT_RAY_AT(2)), 1);
    const __m256d f = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(RT_RAY_AT(1))),
                                           _mm_loadu_pd(RT_RAY_AT(3)), 1);
#undef RT_RAY_AT
    *lo = (rt_v4d)_mm256_unpacklo_pd(e, f);
    *hi = (rt_v4d)_mm256_unpackhi_pd(e, f);
}

static inline __attribute__((always_inline, target("avx2"))) void
rt_setup4_body(const rt_grid *g, const rt_ray *ray, rt_pre4 *p)
{
    rt_v4d o[3], d[3], tmin, tmax;
    rt_rays4_pair(ray, 0, &o[0], &o[1]);
    rt_rays4_pair(ray, 2, &o[2], &d[0]);
    rt_rays4_pair(ray, 4, &d[1], &d[2]);
    rt_rays4_pair(ray, 6, &tmin, &tmax);
    /* rt_rayx_check's tests on the bits (signed compares: the sign bits are cleared) */
    const double lim[3] = {RT_RAY_MAX, 1e-100, INFINITY};
    int64_t blim[3];
    memcpy(blim, lim, sizeof blim);
    const rt_v4l big = {blim[0], blim[0], blim[0], blim[0]};
    const rt_v4l small = {blim[1], blim[1], blim[1], blim[1]};
    const rt_v4l inf = {blim[2], blim[2], blim[2], blim[2]};
    const rt_v4l ad0 = rt_v4abits(d[0]), ad1 = rt_v4abits(d[1]), ad2 = rt_v4abits(d[2]);
    rt_v4l bad = (ad0 > big) | (ad1 > big) | (ad2 > big) | (rt_v4abits(o[0]) > big) |
                 (rt_v4abits(o[1]) > big) | (rt_v4abits(o[2]) > big) |
                 (rt_v4abits(tmin) > big) | (rt_v4abits(tmax) > inf) |
                 ((ad0 < small) & (ad1 < small) & (ad2 < small));
    /* rt_rayx_check's flush: a component below 1e-150 of the largest |d| (a ray with one is
       left to the one-ray code, as is one with a 0 component), compared as bits (no NaN
       compared: the tests trap FE_INVALID; the largest of a failed lane set to 1) */
    rt_v4l dm = ((ad0 > ad1) & ad0) | (~(ad0 > ad1) & ad1);
    dm = ((dm > ad2) & dm) | (~(dm > ad2) & ad2);
    const rt_v4d zero = {0.0, 0.0, 0.0, 0.0}, one = {1.0, 1.0, 1.0, 1.0};
    const rt_v4l tiny = rt_v4abits(1e-150 * rt_v4sel(bad, one, dm));
    bad |= (ad0 < tiny) | (ad1 < tiny) | (ad2 < tiny);
    /* unusable lanes get a harmless ray before any other floating operation (no NaN
       compared, no division by 0) */
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        o[a] = rt_v4sel(bad, zero, o[a]);
        d[a] = rt_v4sel(bad, one, d[a]);
    }
    tmin = rt_v4sel(bad, zero, tmin);
    tmax = rt_v4sel(bad, one, tmax);
    bad |= tmin > tmax;
    const rt_v4d din[3] = {d[0], d[1], d[2]}; /* the rt_rayx's direction (rt_pre_ray) */
    const rt_box *b = &g->b;
    if (g->rotated) {
        /* rt_gray_init's rotation, the same sums in the same order; a lane whose rotated
           direction has a component below 1e-150 of its largest (flushed there) is left to
           the one-ray code, and gets the harmless ray again */
        rt_v4d q[3], gd[3];
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++)
            q[a] = o[a] - g->c[a];
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++) {
            gd[a] = g->R[a][0] * d[0] + g->R[a][1] * d[1] + g->R[a][2] * d[2];
            o[a] = g->R[a][0] * q[0] + g->R[a][1] * q[1] + g->R[a][2] * q[2];
        }
        const rt_v4l g0 = rt_v4abits(gd[0]), g1 = rt_v4abits(gd[1]), g2 = rt_v4abits(gd[2]);
        rt_v4l gm = ((g0 > g1) & g0) | (~(g0 > g1) & g1);
        gm = ((gm > g2) & gm) | (~(gm > g2) & g2);
        const rt_v4l gt = rt_v4abits(1e-150 * (rt_v4d)gm);
        bad |= (g0 < gt) | (g1 < gt) | (g2 < gt);
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++) {
            o[a] = rt_v4sel(bad, zero, o[a]);
            d[a] = rt_v4sel(bad, one, gd[a]);
        }
    }
    /* rt_gray_init's reciprocals and rt_box_clip's cut, axis by axis in its order */
    rt_v4d invd[3], t0 = tmin, t1 = tmax;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        invd[a] = one / d[a];
        const rt_v4d ta = (b->lo[a] - o[a]) * invd[a], tb = (b->hi[a] - o[a]) * invd[a];
        /* min (a, b) and max (a, b) pick a where a < b (a > b), else b: the selects' picks */
        const rt_v4d tn = rt_v4min(ta, tb), tf = rt_v4max(ta, tb);
        t0 = rt_v4max(tn, t0);
        t1 = rt_v4min(tf, t1);
    }
    /* no usable lane enters the box (rows of eye rays beside the scene): the k-DOP can only
       shorten the ranges, so every usable lane misses (state 1; a lane the k-DOP would have
       left to the one-ray code as parallel to a slab misses the box there as well), and
       nothing more is read */
    rt_v4l in = (t0 <= t1) & (rt_v4abits(t0) < inf); /* no NaN here */
    if (!_mm256_movemask_pd((__m256d)(in & ~bad))) {
        const rt_v4i st4 = rt_v4narrow((~bad & (rt_v4l){1, 1, 1, 1}));
        memcpy(p->state, &st4, sizeof p->state);
        return;
    }
    /* and rt_kdop_clip's cut to the occupied space's slabs */
    rt_v4l par;
    rt_kdop4(g, o, d, &t0, &t1, &par);
    bad |= par;
    in = (t0 <= t1) & (rt_v4abits(t0) < inf);
    const rt_v4l st = ~bad & ((in & (rt_v4l){2, 2, 2, 2}) | (~in & (rt_v4l){1, 1, 1, 1}));
    const rt_v4i st4 = rt_v4narrow(st);
    memcpy(p->state, &st4, sizeof p->state);
    /* no lane enters the k-DOP: nothing more is read */
    if (!_mm256_movemask_pd((__m256d)(in & ~bad)))
        return;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        memcpy(p->o[a], &o[a], sizeof p->o[a]);
        memcpy(p->d[a], &d[a], sizeof p->d[a]);
    }
    t0 = rt_v4sel(in, t0, zero); /* lanes that miss: a finite start (unused) */
    /* rt_dda_init's start cell and next boundary, rt_walk_box's constants */
    rt_v4i neg = {0, 0, 0, 0};
    rt_v4i cs[3], ss[3];
    /* the steps and the octant from the sign bits in 32-bit lanes (the high halves of d's
       lanes; d[a] < 0 is its sign bit here: no lane in state 2 has a component 0 or NaN):
       AVX2 has no narrowing of 64-bit lanes to 32 in one instruction */
    const __m256i hi32 = _mm256_setr_epi32(1, 3, 5, 7, 1, 3, 5, 7);
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        const rt_v4d na = {(double)b->n[a] - 1.0, (double)b->n[a] - 1.0,
                           (double)b->n[a] - 1.0, (double)b->n[a] - 1.0};
        const rt_v4d pa = o[a] + t0 * d[a];
        rt_v4d f = (pa - b->lo[a]) * b->inv_cw[a];
        f = rt_v4min(rt_v4max(f, zero), na);
        const rt_v4i c = __builtin_convertvector(f, rt_v4i);
        const rt_v4l pos = d[a] > zero;
        /* (GCC converts rt_v4i to four doubles in two halves) */
        const rt_v4d bd = (rt_v4d)_mm256_cvtepi32_pd((__m128i)c) + rt_v4sel(pos, one, zero);
        const rt_v4d nd = na + 1.0;
        const rt_v4d hi = {b->hi[a], b->hi[a], b->hi[a], b->hi[a]};
        const rt_v4d x = rt_v4sel(bd == nd, hi, b->lo[a] + bd * b->cw[a]);
        const rt_v4d tn = (x - o[a]) * invd[a];
        const rt_v4d ai = (rt_v4d)rt_v4abits(invd[a]), ad = (rt_v4d)rt_v4abits(d[a]);
        memcpy(p->c[a], &c, sizeof p->c[a]);
        memcpy(p->invd[a], &invd[a], sizeof p->invd[a]);
        const rt_v4d dt = b->cw[a] * ai, it = ad * b->inv_cw[a];
        memcpy(p->tn[a], &tn, sizeof p->tn[a]);
        memcpy(p->dt[a], &dt, sizeof p->dt[a]);
        memcpy(p->it[a], &it, sizeof p->it[a]);
        const rt_v4i ng = (rt_v4i)_mm_srai_epi32(
            _mm256_castsi256_si128(_mm256_permutevar8x32_epi32((__m256i)d[a], hi32)), 31);
        neg |= ng & (rt_v4i){1 << a, 1 << a, 1 << a, 1 << a};
        const rt_v4i step = ng | (rt_v4i){1, 1, 1, 1};
        memcpy(p->step[a], &step, sizeof p->step[a]);
        cs[a] = c;
        ss[a] = step;
    }
    const int32_t n0 = b->n[0], n01 = b->n[0] * b->n[1];
    const rt_v4i ci = (cs[2] * b->n[1] + cs[1]) * n0 + cs[0], dy = ss[1] * n0, dz = ss[2] * n01;
    memcpy(p->ci, &ci, sizeof p->ci);
    memcpy(p->dy, &dy, sizeof p->dy);
    memcpy(p->dz, &dz, sizeof p->dz);
    memcpy(p->t0, &t0, sizeof p->t0);
    memcpy(p->t1, &t1, sizeof p->t1);
    memcpy(p->oct, &neg, sizeof p->oct);
    rt_shear4(din, p);
}

static __attribute__((target("avx2"), noinline)) void rt_setup4_avx2(const rt_grid *g,
                                                                    const rt_ray *ray,
                                                                    rt_pre4 *p)
{
    rt_setup4_body(g, ray, p);
}

/* ---- the same set-up for eight rays in AVX-512's 8 double lanes ---- */

/* rt_setup4_body for eight rays at once (rt_setup8_avx512, CPUs of rt_simd_level 3): the same
   operations per lane in the same order, the lanes' selects as mask registers, min and max as
   the same instructions at twice the width; the results stored as two rt_pre4 records (rays
   0-3, 4-7), so the walks read what the four-ray set-up writes. A group of eight rays that
   all miss the grid box stops after the box clip, as a group of four does. */
#define RT_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq")))

/* eight doubles of v into field f of the two records (lanes 0-3, 4-7); eight 32-bit ints */
#define RT_ST8D(p, f, v)                                                                   \
    (_mm256_storeu_pd((p)[0].f, _mm512_castpd512_pd256(v)),                               \
     _mm256_storeu_pd((p)[1].f, _mm512_extractf64x4_pd((v), 1)))
#define RT_ST8I(p, f, v)                                                                   \
    (_mm_storeu_si128((__m128i *)(void *)(p)[0].f, _mm256_castsi256_si128(v)),            \
     _mm_storeu_si128((__m128i *)(void *)(p)[1].f, _mm256_extracti128_si256((v), 1)))

/* |x| as 64-bit integers (the sign bit cleared) */
static inline __attribute__((always_inline)) RT_AVX512 __m512i rt_v8abits(__m512d x)
{
    return _mm512_and_si512(_mm512_castpd_si512(x), _mm512_set1_epi64(INT64_MAX));
}

/* rt_kdop4 in 8 lanes */
static inline __attribute__((always_inline)) RT_AVX512 void
rt_kdop8(const rt_grid *g, const __m512d o[3], const __m512d d[3], __m512d *t0, __m512d *t1,
         __mmask8 *par)
{
    __m512d po[RT_KDOP], pd[RT_KDOP];
    RT_KDOP_PROJ(po, o[0], o[1], o[2]);
    RT_KDOP_PROJ(pd, d[0], d[1], d[2]);
    const __m512d one = _mm512_set1_pd(1.0);
    const __m512d dn = _mm512_mul_pd(
        _mm512_set1_pd(RT_KDOP_PAR),
        _mm512_add_pd(_mm512_add_pd(_mm512_abs_pd(d[0]), _mm512_abs_pd(d[1])),
                      _mm512_abs_pd(d[2])));
    __m512d k0 = *t0, k1 = *t1;
    __mmask8 pm = 0;
#pragma GCC unroll 10
    for (int j = 0; j < RT_KDOP; j++) {
        const __m512d pj = pd[j], oj = po[j];
        const __mmask8 pl = _mm512_cmp_pd_mask(_mm512_abs_pd(pj), dn, _CMP_LT_OQ);
        pm |= pl;
        const __m512d iv = _mm512_div_pd(one, _mm512_mask_blend_pd(pl, pj, one));
        const __m512d ta = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(g->kd_lo[j]), oj), iv);
        const __m512d tb = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(g->kd_hi[j]), oj), iv);
        k0 = _mm512_max_pd(_mm512_min_pd(ta, tb), k0);
        k1 = _mm512_min_pd(_mm512_max_pd(ta, tb), k1);
    }
    *t0 = k0;
    *t1 = k1;
    *par = pm;
}

/* rt_shear4 in 8 lanes (kz, kx, ky and the order in 32-bit lanes) */
static inline __attribute__((always_inline)) RT_AVX512 void rt_shear8(const __m512d d[3],
                                                                     rt_pre4 *p)
{
    const __m512d ax = _mm512_abs_pd(d[0]), ay = _mm512_abs_pd(d[1]), az = _mm512_abs_pd(d[2]);
    const __mmask8 m1 = _mm512_cmp_pd_mask(ax, ay, _CMP_LT_OQ) |
                        _mm512_cmp_pd_mask(ax, az, _CMP_LT_OQ),
                   m2 = _mm512_cmp_pd_mask(ay, az, _CMP_LT_OQ);
    const __mmask8 z1 = m1 & ~m2, z2 = m1 & m2; /* kz == 1, kz == 2 */
    const __m512d dz = _mm512_mask_blend_pd(z2, _mm512_mask_blend_pd(z1, d[0], d[1]), d[2]);
    const __mmask8 ng = _mm512_cmp_pd_mask(dz, _mm512_setzero_pd(), _CMP_LT_OQ);
    const __m256i one = _mm256_set1_epi32(1), three = _mm256_set1_epi32(3);
    const __m256i kz = _mm256_add_epi32(_mm256_maskz_mov_epi32(m1, one),
                                        _mm256_maskz_mov_epi32(z2, one));
    const __m256i n = _mm256_maskz_mov_epi32(ng, one);
    __m256i kx = _mm256_add_epi32(_mm256_add_epi32(kz, one), n);
    __m256i ky = _mm256_sub_epi32(_mm256_add_epi32(kz, _mm256_set1_epi32(2)), n);
    kx = _mm256_mask_sub_epi32(kx, _mm256_cmpge_epi32_mask(kx, three), kx, three);
    ky = _mm256_mask_sub_epi32(ky, _mm256_cmpge_epi32_mask(ky, three), ky, three);
    const __mmask8 x1 = _mm256_cmpeq_epi32_mask(kx, one),
                   x2 = _mm256_cmpeq_epi32_mask(kx, _mm256_set1_epi32(2)),
                   y1 = _mm256_cmpeq_epi32_mask(ky, one),
                   y2 = _mm256_cmpeq_epi32_mask(ky, _mm256_set1_epi32(2));
    const __m512d dx = _mm512_mask_blend_pd(x2, _mm512_mask_blend_pd(x1, d[0], d[1]), d[2]);
    const __m512d dy = _mm512_mask_blend_pd(y2, _mm512_mask_blend_pd(y1, d[0], d[1]), d[2]);
    const __m512d sz = _mm512_div_pd(_mm512_set1_pd(1.0), dz), sx = _mm512_mul_pd(dx, sz),
                  sy = _mm512_mul_pd(dy, sz);
    const __m256i ord = _mm256_add_epi32(_mm256_add_epi32(kz, kz), n);
    RT_ST8I(p, ord, ord);
    RT_ST8I(p, kx, kx);
    RT_ST8I(p, ky, ky);
    RT_ST8I(p, kz, kz);
    RT_ST8D(p, sx, sx);
    RT_ST8D(p, sy, sy);
    RT_ST8D(p, sz, sz);
}

/* the eight rays' records in lanes: org[0..2], dir[0..2], tmin, tmax as v[0..7] (rays j and
   j + 4 in the halves of a register, two unpacks and a permutation of two per field pair) */
static inline __attribute__((always_inline)) RT_AVX512 void rt_rays8(const rt_ray *ray,
                                                                    __m512d v[8])
{
    __m512d a[4], b[4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; j++) {
        const double *r = (const double *)(const void *)(ray + j);
        const double *s = (const double *)(const void *)(ray + j + 4);
        a[j] = _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(r)),
                                  _mm256_loadu_pd(s), 1);
        b[j] = _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(r + 4)),
                                  _mm256_loadu_pd(s + 4), 1);
    }
    const __m512i lo = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13),
                  hi = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
#pragma GCC unroll 2
    for (int h = 0; h < 2; h++) {
        const __m512d *x = h ? b : a;
        const __m512d l01 = _mm512_unpacklo_pd(x[0], x[1]), h01 = _mm512_unpackhi_pd(x[0], x[1]);
        const __m512d l23 = _mm512_unpacklo_pd(x[2], x[3]), h23 = _mm512_unpackhi_pd(x[2], x[3]);
        v[4 * h + 0] = _mm512_permutex2var_pd(l01, lo, l23);
        v[4 * h + 1] = _mm512_permutex2var_pd(h01, lo, h23);
        v[4 * h + 2] = _mm512_permutex2var_pd(l01, hi, l23);
        v[4 * h + 3] = _mm512_permutex2var_pd(h01, hi, h23);
    }
}

static __attribute__((noinline)) RT_AVX512 void rt_setup8_avx512(const rt_grid *g,
                                                                const rt_ray *ray, rt_pre4 *p)
{
    __m512d v[8];
    rt_rays8(ray, v);
    __m512d o[3] = {v[0], v[1], v[2]}, d[3] = {v[3], v[4], v[5]}, tmin = v[6], tmax = v[7];
    const double lim[3] = {RT_RAY_MAX, 1e-100, INFINITY};
    int64_t blim[3];
    memcpy(blim, lim, sizeof blim);
    const __m512i vbig = _mm512_set1_epi64(blim[0]), vsmall = _mm512_set1_epi64(blim[1]),
                  vinf = _mm512_set1_epi64(blim[2]);
    const __m512i ad0 = rt_v8abits(d[0]), ad1 = rt_v8abits(d[1]), ad2 = rt_v8abits(d[2]);
    __mmask8 bad = _mm512_cmpgt_epi64_mask(ad0, vbig) | _mm512_cmpgt_epi64_mask(ad1, vbig) |
                   _mm512_cmpgt_epi64_mask(ad2, vbig) |
                   _mm512_cmpgt_epi64_mask(rt_v8abits(o[0]), vbig) |
                   _mm512_cmpgt_epi64_mask(rt_v8abits(o[1]), vbig) |
                   _mm512_cmpgt_epi64_mask(rt_v8abits(o[2]), vbig) |
                   _mm512_cmpgt_epi64_mask(rt_v8abits(tmin), vbig) |
                   _mm512_cmpgt_epi64_mask(rt_v8abits(tmax), vinf) |
                   (_mm512_cmplt_epi64_mask(ad0, vsmall) & _mm512_cmplt_epi64_mask(ad1, vsmall) &
                    _mm512_cmplt_epi64_mask(ad2, vsmall));
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    const __m512i dm = _mm512_max_epi64(_mm512_max_epi64(ad0, ad1), ad2);
    const __m512i tiny = rt_v8abits(_mm512_mul_pd(
        _mm512_set1_pd(1e-150), _mm512_mask_blend_pd(bad, _mm512_castsi512_pd(dm), one)));
    bad |= _mm512_cmplt_epi64_mask(ad0, tiny) | _mm512_cmplt_epi64_mask(ad1, tiny) |
           _mm512_cmplt_epi64_mask(ad2, tiny);
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        o[a] = _mm512_mask_blend_pd(bad, o[a], zero);
        d[a] = _mm512_mask_blend_pd(bad, d[a], one);
    }
    tmin = _mm512_mask_blend_pd(bad, tmin, zero);
    tmax = _mm512_mask_blend_pd(bad, tmax, one);
    bad |= _mm512_cmp_pd_mask(tmin, tmax, _CMP_GT_OQ);
    const __m512d din[3] = {d[0], d[1], d[2]};
    const rt_box *b = &g->b;
    if (g->rotated) {
        __m512d q[3], gd[3];
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++)
            q[a] = _mm512_sub_pd(o[a], _mm512_set1_pd(g->c[a]));
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++) {
            const __m512d r0 = _mm512_set1_pd(g->R[a][0]), r1 = _mm512_set1_pd(g->R[a][1]),
                          r2 = _mm512_set1_pd(g->R[a][2]);
            gd[a] = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r0, d[0]), _mm512_mul_pd(r1, d[1])),
                                  _mm512_mul_pd(r2, d[2]));
            o[a] = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r0, q[0]), _mm512_mul_pd(r1, q[1])),
                                 _mm512_mul_pd(r2, q[2]));
        }
        const __m512i g0 = rt_v8abits(gd[0]), g1 = rt_v8abits(gd[1]), g2 = rt_v8abits(gd[2]);
        const __m512i gm = _mm512_max_epi64(_mm512_max_epi64(g0, g1), g2);
        const __m512i gt =
            rt_v8abits(_mm512_mul_pd(_mm512_set1_pd(1e-150), _mm512_castsi512_pd(gm)));
        bad |= _mm512_cmplt_epi64_mask(g0, gt) | _mm512_cmplt_epi64_mask(g1, gt) |
               _mm512_cmplt_epi64_mask(g2, gt);
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++) {
            o[a] = _mm512_mask_blend_pd(bad, o[a], zero);
            d[a] = _mm512_mask_blend_pd(bad, gd[a], one);
        }
    }
    __m512d invd[3], t0 = tmin, t1 = tmax;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        invd[a] = _mm512_div_pd(one, d[a]);
        const __m512d ta = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(b->lo[a]), o[a]), invd[a]);
        const __m512d tb = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(b->hi[a]), o[a]), invd[a]);
        t0 = _mm512_max_pd(_mm512_min_pd(ta, tb), t0);
        t1 = _mm512_min_pd(_mm512_max_pd(ta, tb), t1);
    }
    __mmask8 in = _mm512_cmp_pd_mask(t0, t1, _CMP_LE_OQ) &
                  _mm512_cmplt_epi64_mask(rt_v8abits(t0), vinf);
    const __m256i one32 = _mm256_set1_epi32(1);
    if (!(in & ~bad)) {
        const __m256i st = _mm256_maskz_mov_epi32((__mmask8)~bad, one32);
        RT_ST8I(p, state, st);
        return;
    }
    __mmask8 par;
    rt_kdop8(g, o, d, &t0, &t1, &par);
    bad |= par;
    in = _mm512_cmp_pd_mask(t0, t1, _CMP_LE_OQ) & _mm512_cmplt_epi64_mask(rt_v8abits(t0), vinf);
    const __m256i st = _mm256_maskz_mov_epi32(
        (__mmask8)~bad, _mm256_mask_blend_epi32(in, one32, _mm256_set1_epi32(2)));
    RT_ST8I(p, state, st);
    if (!(in & ~bad))
        return;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        RT_ST8D(p, o[a], o[a]);
        RT_ST8D(p, d[a], d[a]);
    }
    t0 = _mm512_maskz_mov_pd(in, t0);
    __m256i neg = _mm256_setzero_si256(), cs[3], ss[3];
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        const __m512d na = _mm512_set1_pd((double)b->n[a] - 1.0);
        const __m512d lo = _mm512_set1_pd(b->lo[a]), icw = _mm512_set1_pd(b->inv_cw[a]),
                      cw = _mm512_set1_pd(b->cw[a]);
        const __m512d pa = _mm512_add_pd(o[a], _mm512_mul_pd(t0, d[a]));
        __m512d f = _mm512_mul_pd(_mm512_sub_pd(pa, lo), icw);
        f = _mm512_min_pd(_mm512_max_pd(f, zero), na);
        const __m256i c = _mm512_cvttpd_epi32(f);
        const __mmask8 pos = _mm512_cmp_pd_mask(d[a], zero, _CMP_GT_OQ);
        const __m512d bd = _mm512_add_pd(_mm512_cvtepi32_pd(c), _mm512_maskz_mov_pd(pos, one));
        const __m512d nd = _mm512_add_pd(na, one);
        const __m512d x = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(bd, nd, _CMP_EQ_OQ),
                                               _mm512_add_pd(lo, _mm512_mul_pd(bd, cw)),
                                               _mm512_set1_pd(b->hi[a]));
        const __m512d tn = _mm512_mul_pd(_mm512_sub_pd(x, o[a]), invd[a]);
        const __m512d dt = _mm512_mul_pd(cw, _mm512_abs_pd(invd[a])),
                      it = _mm512_mul_pd(_mm512_abs_pd(d[a]), icw);
        RT_ST8I(p, c[a], c);
        RT_ST8D(p, invd[a], invd[a]);
        RT_ST8D(p, tn[a], tn);
        RT_ST8D(p, dt[a], dt);
        RT_ST8D(p, it[a], it);
        /* d[a] < 0 is its sign bit here (no lane in state 2 has a component 0 or NaN) */
        const __mmask8 ng = _mm512_movepi64_mask(_mm512_castpd_si512(d[a]));
        neg = _mm256_mask_or_epi32(neg, ng, neg, _mm256_set1_epi32(1 << a));
        const __m256i step = _mm256_mask_blend_epi32(ng, one32, _mm256_set1_epi32(-1));
        RT_ST8I(p, step[a], step);
        cs[a] = c;
        ss[a] = step;
    }
    const __m256i n0 = _mm256_set1_epi32(b->n[0]), n1 = _mm256_set1_epi32(b->n[1]),
                  n01 = _mm256_set1_epi32(b->n[0] * b->n[1]);
    const __m256i ci = _mm256_add_epi32(
        _mm256_mullo_epi32(_mm256_add_epi32(_mm256_mullo_epi32(cs[2], n1), cs[1]), n0), cs[0]);
    const __m256i dy = _mm256_mullo_epi32(ss[1], n0), dz = _mm256_mullo_epi32(ss[2], n01);
    RT_ST8I(p, ci, ci);
    RT_ST8I(p, dy, dy);
    RT_ST8I(p, dz, dz);
    RT_ST8D(p, t0, t0);
    RT_ST8D(p, t1, t1);
    RT_ST8I(p, oct, neg);
    rt_shear8(din, p);
}
#undef RT_ST8D
#undef RT_ST8I
#endif

typedef void (*rt_setup4_fn)(const rt_grid *g, const rt_ray *ray, rt_pre4 *p);

/* the batch's set-up: four rays into p[0] (four), and where the CPU has AVX-512 eight rays
   into p[0] and p[1] (eight; else NULL) */
typedef struct rt_setup {
    rt_setup4_fn four, eight;
} rt_setup;

#ifdef RT_SETUP4_AVX2
/* the CPU's level, read once per process as the packet path's (rt_simd_level reads the
   environment: too slow for every call of a small batch) */
static pthread_once_t rt_setup4_once = PTHREAD_ONCE_INIT;
static int rt_setup4_level, rt_setup4_bmi;
static void rt_setup4_pick(void)
{
    rt_setup4_level = rt_simd_level();
    __builtin_cpu_init();
    rt_setup4_bmi = __builtin_cpu_supports("bmi"); /* the any-hit lists' andn */
}
#endif

/* the four-ray set-up where the CPU has AVX2 and GKS_RT_SIMD allows it (rt_simd_level), and the
   eight-ray one where it has AVX-512 (level 3), with a
   grid of fewer than 2^31 top cells (rt_pre4's 32-bit cell indices; a grid that large, with
   its 4-byte offset per cell, is far beyond what the build chooses); otherwise NULL: every ray
   through the one-ray code. The same lanes in the build's own
   SSE2 (two registers of 2, no 64-bit compare) cost more than the one-ray code: 1400
   instructions per four rays against 360 (docs/bench/rt_tuning.md). */
static const rt_setup *rt_setup4_choose(const rt_scene *sc)
{
#ifdef RT_SETUP4_AVX2
    static const rt_setup avx2 = {rt_setup4_avx2, NULL},
                          avx512 = {rt_setup4_avx2, rt_setup8_avx512};
    pthread_once(&rt_setup4_once, rt_setup4_pick);
    if (sc->use_grid && rt_setup4_level >= 2 && sc->grid.ncells < (size_t)INT32_MAX)
        return rt_setup4_level >= 3 ? &avx512 : &avx2;
#else
    (void)sc;
#endif
    return NULL;
}

/* empty-space jumps from top cells whose empty cube in the ray's octant (rt_grid.odist) has
   an edge >= RT_JUMP_MIN; a restart costs a few steps, so shorter jumps do not pay
   (docs/bench/rt_tuning.md) */
#define RT_JUMP_MIN 4

static inline __attribute__((always_inline)) int rt_transmit_prim(rt_ctx *c, const rt_scene *sc, const rt_rayx *r, size_t i, int any_hit,
                                   double *T)
{
    double t;
    if (!rt_isect_prim(sc, r, i, r->tmin, r->tmax, &t))
        return 1;
    const rt_prim *p = rt_prim_rec(sc, i); /* (opacity and surfaces) */
    if (any_hit || p->opaque) {
        *T = 0.0;
        c->blocker = p->opaque ? (long)i : -1;
        return 0;
    }
    double ng[3];
    rt_prim_ng(sc, i, ng);
    double den = ng[0] * r->d[0] + ng[1] * r->d[1] + ng[2] * r->d[2];
    *T *= rt_prim_surf(sc, p, den > 0.0 ? 1 : 0)->transparency;
    return *T > 0.0;
}

#define RT_INLINE static inline __attribute__((always_inline))

/* nearest-hit update for primitive i (mailboxed by the caller): the tests up to where a hit
   could still tie with the best (2 * eb beyond it), the choice in rt_nearest_update (ties in
   distance go to the area drawn later, equal distances within one area (a mesh's triangles
   share its id) to the primitive given first, so the picture does not depend on the
   order of the cell lists) */
RT_INLINE void rt_nearest_prim(const rt_scene *sc, const rt_rayx *r, uint32_t i, double *best,
                               long *bi, double *eb)
{
    double t;
    if (rt_isect_prim(sc, r, i, r->tmin, RT_MIN(*best + 2.0 * *eb, r->tmax), &t))
        rt_nearest_update(sc, r, i, t, best, bi, eb);
}

enum { RT_WALK_CONT = 0, RT_WALK_BLOCKED = 2 };

/* rt_walkstate.any_hit: 0 transmittance; RT_ANY_HIT the first hit blocks; RT_ANY_MESH (bit 0
   kept, so every other test takes it as RT_ANY_HIT) also every primitive a mesh triangle, no
   skipped primitive and a CPU with AVX2 and BMI (rt_occluded's rays, rt_anyhit_kind): the walks
   of modes RT_MODE_ANYTOP + O, their second-level walks and cell lists inlined
   (rt_occluded_top_O, rt_transmit_top_O) */
enum { RT_ANY_HIT = 1, RT_ANY_MESH = 3 };

/* AVX2's encoding for the RT_ANY_MESH walks: three-operand instructions, no register copies
   (with the lists' constant axis order 12-15 % fewer instructions on the meshes' shadow rays);
   no FMA is formed, so the operations and their bits are the SSE2 code's
   (docs/bench/rt_tuning.md); BMI for the lists' andn (rt_word_offset) */
#ifdef RT_SETUP4_AVX2
#define RT_ANYHIT_TARGET __attribute__((target("avx2,bmi")))
#else
#define RT_ANYHIT_TARGET
#endif

/* rt_box_clip_nz with the three axes in three lanes of GCC's four-double vectors (one AVX2
   register in the mode-3 top walk, rt_intersect_mesh's encoding): the same operations, the range
   cut axis by axis in the same order (the same picks between +0 and -0). Lane 3 holds the field
   after each array (d[0], d[2] rotated in after invd, hi[0], cw[0]: finite), not read. Besides
   being shorter than the SSE2 form (no scalar third axis), it has no scalar zero-extended into
   a register, which GCC does with a vmovq that valgrind 3.19 cannot decode in AVX2's encoding
   (rt_nearest_apart). */
static inline __attribute__((always_inline)) int rt_box_clip_nz4(const rt_box *g, const rt_gray *r,
                                                                 double *t0p, double *t1p)
{
    rt_v4d o, di, lo, hi;
    memcpy(&o, r->o, sizeof o);
    memcpy(&di, r->d + 2, sizeof di); /* d[2], invd[0..2]: the struct's last 32 bytes */
    memcpy(&lo, g->lo, sizeof lo);
    memcpy(&hi, g->hi, sizeof hi);
    const rt_v4d invd = __builtin_shufflevector(di, di, 1, 2, 3, 0);
    const rt_v4d ta = (lo - o) * invd, tb = (hi - o) * invd;
    const rt_v4d tn = rt_v4sel(ta < tb, ta, tb), tf = rt_v4sel(ta > tb, ta, tb);
    double t0 = *t0p, t1 = *t1p;
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        t0 = tn[a] > t0 ? tn[a] : t0;
        t1 = tf[a] < t1 ? tf[a] : t1;
    }
    if (!(t0 <= t1) || !isfinite(t0))
        return 0;
    *t0p = t0;
    *t1p = t1;
    return 1;
}

typedef struct rt_walkstate rt_walkstate;
/* a nearest-hit cell list of mesh triangles (rt_nearest_lists) */
typedef int (*rt_anyhit_list_fn)(rt_walkstate *w, const uint32_t *refs, uint32_t n);
/* a second-level walk of mode 3 (nearest hit, mesh triangles only) of a ray of axis order O:
   rt_walk_sub_nearest_O */
typedef int (*rt_sub_walk_fn)(rt_walkstate *w, const rt_subgrid *sg, double t0, double t1);

/* rt_walk_box's modes 8 + O: the second-level walks of RT_ANY_MESH rays of axis order O
   (rt_list_order's number), mode 1 with the any-hit list of that order inlined in the walk
   (rt_cell_mesh_k), so the list's call and register saves are not paid per cell list */
#define RT_MODE_ANYK 8
/* rt_walk_box's modes 16 + O: the top-level walk of an RT_ANY_MESH ray of axis order O (AVX2's
   encoding: rt_occluded_top_O from the four-ray set-up, rt_transmit_top_O without): mode 1
   with the cell lists of that order inlined, the sub-grid clip in lanes (rt_box_clip_nz4) and
   the second-level walk of that order inlined (rt_walk_sub_anyhit_o) */
#define RT_MODE_ANYTOP 16
/* rt_walk_box's modes 24 + O: the second-level walks of mode 3 (nearest hit, mesh triangles
   only) of rays of axis order O, the nearest-hit list of that order inlined likewise. Their
   boxes have no second level, so the tests of modes RT_MODE_ANYTOP + O on a cell's sub-grid
   (mode >= RT_MODE_ANYTOP) never meet them */
#define RT_MODE_NEARK 24
/* rt_walk_box's mode 4: mode 3 for a batch whose rays run mostly along z (rt_rays_along_z:
   eye rays), its top-level step comparing tx with tz first as the nearest-hit second-level
   walks of kz = 2 do (RT_ADV_TREE); everything else mode 3's */
#define RT_MODE_NEARZ 4
#define RT_MODE3(mode) ((mode) == 3 || (mode) == RT_MODE_NEARZ)

struct rt_walkstate {
    const rt_scene *sc;
    rt_ctx *c;
    const rt_rayx *r;
    rt_gray gr;
    uint32_t stamp;
    int any_hit;
    int step[3]; /* the ray's DDA steps (-1, 0, 1 per axis: the sign of its grid-frame
                    direction), set by the top-level walks of modes 1, 3 and
                    RT_MODE_ANYTOP + O for their second-level walks (mode 0's compute
                    their own) */
    rt_anyhit_list_fn list; /* nearest-hit walks of a scene of mesh triangles only
                               (rt_mesh_only): the cell list's copy for the ray's axis order
                               (rt_nearest_lists), chosen once per ray; NULL: the general
                               lists */
    rt_sub_walk_fn sub; /* mode 3: the second-level walk for the ray's axis order
                           (rt_walk_sub_nearest_O), chosen with list */
    uint32_t vnmask; /* RT_ANY_MESH walks: ~rt_scene.vmask, read from memory by the lists so
                        that BMI's andn masks an index word in one instruction (no copy of
                        the mask per vertex) */
    /* RT_ANY_MESH walks of a grid with flat sub-grids (rt_grid.subplane, else NULL): the
       segment's ends p0, p1, and S, S^3 and the ends' rounding pe of the planes' margin
       (rt_subplane) */
    const uint32_t *spl;
    const rt_subplane *spp;
    rt_flatseg fs;
    double best;
    long bi;
    double ebest; /* the best hit's error bound (rt_nearest_update) */
    double T;
};

/* an RT_ANY_MESH walk's data for the flat sub-grids' test (rt_sub_flat): none when the
   grid has no flat sub-grid */
RT_INLINE void rt_walk_flat_init(rt_walkstate *w, const rt_scene *sc, const rt_rayx *r)
{
    w->spl = sc->grid.subplane;
    if (!w->spl)
        return;
    w->spp = sc->grid.splanes;
    rt_flatseg_init(&w->fs, r->o, r->d, r->tmin, r->tmax, sc->scale);
}

/* 1 when the ray's segment [tmin, tmax] lies beyond plane j - 1 of rt_grid.splanes (a flat
   sub-grid's) by its margin on one side: none of the sub-grid's triangles can be hit
   (rt_subplane), so its walk is not needed (the walk would only mark its triangles in the
   mailbox: a later test of one of them misses as well). A segment with an infinite end has
   an infinite or NaN margin and skips nothing. Out of line: inlined in the top walks it took
   registers from them (bunny and armadillo shadow rays, without flat sub-grids, +1.9 %) */
static __attribute__((noinline)) int rt_sub_flat(const rt_walkstate *w, uint32_t j)
{
    return rt_flat_beyond(&w->spp[j - 1], &w->fs);
}

/* The part of [t0, t1] that a nearest-hit walk must cover in the flat sub-grid of plane
   j - 1 ([t0, t1]: its range in the top cell, clipped to the sub-grid's box and to the best
   hit's window); an empty range (lo > hi) when it need not walk it at all. Guards: the
   origin lies within 64 times the scene's scale S0 and the ray is not grazing the plane
   (|n . d| at least 2^-9 plus k_a of sqrt(3) max |d[k]|), so that a hit's error along the
   ray stays below the cells' enlargement; without them [t0, t1] is returned whole. Empty:
   both ends of [t0, t1] lie beyond the slab by the margin on one side (the ends' rounding
   term doubled, 32 u S'), so no triangle of the sub-grid has a computed hit or a crossing
   in it. Else the range meets the slab, and its parts before and after the slab are cut off
   where the same test proves them empty: the cut points are where the height reaches the
   slab widened by twice the margin, and a part is cut only when its two ends pass the test
   above (the proof is that of the skip, on a part of the range, whose S' is at most the
   whole range's). The walk then covers the ray's few cells around its crossing of the
   plane instead of every cell from the sub-grid's box on. The proof that the answer stays
   the same: docs/RAYTRACING.md, "Flat sub-grids". The ray's values (S, S^3) are computed
   here, not per ray: most rays never call it. Out of line as rt_sub_flat; the range comes
   back by value, in two registers (through pointers the top walk kept the range in memory
   and slowed the walks of meshes without flat sub-grids: docs/bench/rt_tuning.md). */
typedef struct {
    double lo, hi;
} rt_trange;
static __attribute__((noinline)) rt_trange rt_sub_flat_near(const rt_walkstate *w, uint32_t j,
                                                           double t0, double t1)
{
    const rt_subplane *p = &w->sc->grid.splanes[j - 1];
    const double *o = w->r->o, *d = w->r->d, S0 = w->sc->scale;
    /* the heights n . (o + t d) of the ends as n . o + t (n . d): within 25 u S' of the exact
       ones, S' = S + max(|t0|, |t1|) max |d[k]| (>= the ends' coordinates) */
    const double nd = p->n[0] * d[0] + p->n[1] * d[1] + p->n[2] * d[2];
    const double no = p->n[0] * o[0] + p->n[1] * o[1] + p->n[2] * o[2];
    const double s0 = no + t0 * nd, s1 = no + t1 * nd;
    const double S = RT_MAX(S0, RT_MAX(fabs(o[0]), RT_MAX(fabs(o[1]), fabs(o[2])))),
                 dm = RT_MAX(fabs(d[0]), RT_MAX(fabs(d[1]), fabs(d[2])));
    if (!(S <= 64.0 * S0) ||
        !(fabs(nd) >= (0x1p-9 + p->ka) * 1.7320508075688772 * dm * (1.0 + 0x1p-40)))
        return (rt_trange){t0, t1};
    const double Su = S * (1.0 + 0x1p-40), Sp = Su + RT_MAX(fabs(t0), fabs(t1)) * dm;
    const double m = p->ka * Su + p->kb * (Su * Su * Su * (1.0 + 0x1p-40)) +
                     32.0 * 0x1p-53 * Sp * (1.0 + 0x1p-40);
    const double hi = p->hi + m, lo = p->lo - m;
    if ((s0 > hi && s1 > hi) | (s0 < lo && s1 < lo))
        return (rt_trange){1.0, 0.0};
    /* the range meets the slab: t where the height is lo - m and hi + m (nd != 0 by the
       guard), the nearer one a cut of the range's start, the farther one of its end */
    const double ta = (lo - m - no) / nd, tb = (hi + m - no) / nd;
    const double ca = RT_MIN(ta, tb), cb = RT_MAX(ta, tb);
    rt_trange r = {t0, t1};
    if (ca > t0) {
        const double sa = no + ca * nd;
        if ((s0 > hi && sa > hi) | (s0 < lo && sa < lo))
            r.lo = ca;
    }
    if (cb < t1) {
        const double sb = no + cb * nd;
        if ((s1 > hi && sb > hi) | (s1 < lo && sb < lo))
            r.hi = cb;
    }
    return r;
}

static int rt_walk_sub_nearest(rt_walkstate *w, const rt_subgrid *sg, double t0, double t1);
static int rt_walk_sub_transmit(rt_walkstate *w, const rt_subgrid *sg, double t0, double t1);
static inline RT_ANYHIT_TARGET int rt_walk_sub_anyhit_o(rt_walkstate *w, int o,
                                                       const rt_subgrid *sg, double t0, double t1);

/* 3D-DDA over one box (top level: with second-level cells in sub and the cells' bytes of the
 * ray's octant in dist, rt_grid.odist, never NULL there; second level: both NULL). mode 0:
 * nearest hit, leaves at the first cell boundary beyond the best hit (t1 lowered to it);
 * mode 3: mode 0 of a scene of mesh triangles only, its cell lists through rt_walkstate.list
 * (rt_nearest_lists), its second-level walks through rt_walkstate.sub; mode 1: transmittance,
 * BLOCKED when an opaque primitive is hit; modes RT_MODE_ANYK + O: mode 1 of an RT_ANY_MESH
 * second-level walk of a ray of axis order O, its cell lists inlined; modes RT_MODE_NEARK + O:
 * mode 3's second-level walk of a ray of axis order O, its cell lists inlined.
 * Mailboxes: see the top of the file. Direction components exactly +0.0 or -0.0 never step.
 * step: NULL, or
 * for a second-level walk of modes 1 and RT_MODE_ANYK + O the ray's steps, which their top
 * level stores in rt_walkstate.step (rt_dda_init). */
/* An empty-space jump along one stepping axis (rt_walk_box): the cell boundaries of the axis
 * that the ray crosses up to the jump parameter tj, from its next boundary t on (cell width dt
 * in ray parameter, it about 1 / dt); j = t + k dt is the cube's far face. The exit axis
 * (j == tj, the smallest of the three) crosses k + 1; another at most that many (k + 1 only by
 * rounding, where the ray passes within a rounding of a cell edge: either cell may be taken,
 * see the jump's comment). A count short by rounding only costs ordinary steps after the jump,
 * which catch up before any other axis steps (this axis' next boundary is still below tj). */
static inline int rt_jump_cells(double t, double j, double tj, double it, int k)
{
    if (j <= tj)
        return k + 1;
    if (t > tj)
        return 0;
    if (!(t < tj))
        return 1; /* tj on this axis' next boundary */
    const double f = (tj - t) * it; /* > 0, or +inf (no NaN: tj - t > 0) */
    return f < (double)k ? (int)f + 1 : k + 1;
}

/* one DDA step to the next cell: the axis with the smallest boundary parameter (ties: x, y, z);
   leaves the walk past t1 (nearest mode: lowered to the best hit) or the box. Registers
   only, no array indexed by the axis: a table version waits on store-to-load latency
   (docs/bench/rt_tuning.md). The next boundary is the last one plus the cell's width in
   ray parameter (dt*, one addition, short latency ahead of the next step's branch): it
   drifts from the exact boundary by a few roundings per step, far below the eps the cells
   are enlarged by at build (a ray passing a cell corner by a rounding-sized piece may take
   the other cell of the corner, which references every primitive it could hit there), so
   the walk still meets every primitive the ray hits and the hits stay the same. */
#define RT_STEP_AXIS(T, C, S, NN, D, DT)                                   \
    do {                                                                    \
        if (T > t1)                                                         \
            return RT_WALK_CONT;                                            \
        C += S;                                                             \
        if ((unsigned)C >= (unsigned)NN)                                    \
            return RT_WALK_CONT;                                            \
        ci += D;                                                            \
        tent = T;                                                           \
        T += DT;                                                            \
    } while (0)
#define RT_STEP_X() RT_STEP_AXIS(tx, cx, sx, nn0, dx, RT_DT(0, dtx))
#define RT_STEP_Y() RT_STEP_AXIS(ty, cy, sy, nn1, dy, RT_DT(1, dty))
#define RT_STEP_Z() RT_STEP_AXIS(tz, cz, sz, nn2, dz, RT_DT(2, dtz))
/* the order of RT_ADVANCE's two compares for the walks whose axis order O is known at
   compile time (rt_walk_box's modes RT_MODE_ANYK, RT_MODE_ANYTOP, RT_MODE_NEARK + O; kz =
   O >> 1, the direction's largest component): 0 tx against ty first, the smaller against tz;
   1 tx against tz first; 2 ty against tz first. Every order takes the same axis (ties: x, y,
   z); the first compare with the axis that steps most often is the better predicted one
   (docs/bench/rt_tuning.md). Any-hit walks by kz: 0, 2, 1; nearest-hit: 0, 0, 1 (measured);
   the nearest-hit top walk: 0 (mode 3, the ray's order not compiled in), 1 for a batch of
   rays along z (mode RT_MODE_NEARZ). */
#define RT_ADV_TREE                                                                    \
    (mode >= RT_MODE_NEARK   ? (((mode & 7) >> 1) == 2 ? 1 : 0)                        \
     : mode >= RT_MODE_ANYK ? (((mode & 7) >> 1) == 0 ? 0 : ((mode & 7) >> 1) == 1 ? 2 : 1) \
                            : mode == RT_MODE_NEARZ ? 1 : 0)
#define RT_ADVANCE()                                                        \
    do {                                                                    \
        if (RT_ADV_TREE == 1) {                                             \
            if (tx <= tz) {                                                 \
                if (tx <= ty)                                               \
                    RT_STEP_X();                                            \
                else                                                        \
                    RT_STEP_Y();                                            \
            } else if (tz < ty)                                             \
                RT_STEP_Z();                                                \
            else                                                            \
                RT_STEP_Y();                                                \
        } else if (RT_ADV_TREE == 2) {                                      \
            if (ty <= tz) {                                                 \
                if (tx <= ty)                                               \
                    RT_STEP_X();                                            \
                else                                                        \
                    RT_STEP_Y();                                            \
            } else if (tx <= tz)                                            \
                RT_STEP_X();                                                \
            else                                                            \
                RT_STEP_Z();                                                \
        } else if (tx <= ty && tx <= tz)                                    \
            RT_STEP_X();                                                    \
        else if (ty <= tz)                                                  \
            RT_STEP_Y();                                                    \
        else                                                                \
            RT_STEP_Z();                                                    \
    } while (0)

/* starts loading the triangles of a cell list (rt_tri_prefetch)
   before they are tested one after the other: the misses of large meshes overlap */
static inline void rt_prefetch_tris(const rt_scene *sc, const uint32_t *refs, uint32_t n)
{
    if (n < 2) /* a single triangle is loaded by its test at once */
        return;
    for (uint32_t k = 0; k < n; k++)
        if (refs[k] < sc->ntri)
            rt_tri_prefetch(sc, refs[k]);
}

/* the primitives of one cell list (kept out of the DDA loop: its registers stay free) */
static __attribute__((noinline)) void rt_cell_nearest(rt_walkstate *w, const uint32_t *refs,
                                                      uint32_t n)
{
    const rt_scene *sc = w->sc;
    const rt_rayx *r = w->r;
    uint64_t *const hbox = w->c->hbox;
    const uint64_t key = (uint64_t)w->stamp << 32;
    const uint32_t skip = r->skip;
    rt_prefetch_tris(sc, refs, n);
    for (uint32_t k = 0; k < n; k++) {
        uint32_t i = refs[k];
        if (hbox[i % RT_HBOX] == (key | i) || i == skip)
            continue;
        hbox[i % RT_HBOX] = key | i;
        rt_nearest_prim(sc, r, i, &w->best, &w->bi, &w->ebest);
    }
}

/* the vertex offset of index word *p, ~nm & *p (nm: ~rt_scene.vmask), in one BMI andn from
   memory (a plain & costs a copy of the mask per word: and is destructive); as 64 bits, the
   32-bit andn having cleared the upper half */
RT_INLINE uint64_t rt_word_offset(uint32_t nm, const uint32_t *p)
{
#ifdef RT_SETUP4_AVX2
    uint64_t r;
    __asm__("andn %2, %k1, %k0" : "=r"(r) : "r"(nm), "m"(*p));
    return r;
#else
    return ~nm & *p;
#endif
}

/* rt_nearest_update of w's ray for mesh triangle i hit at t, with the bound from its vertices
   v0 v1 v2 at hand (rt_tri_hit_err_v) rather than fetched again, the choice of a first hit (a
   primary ray's usual one) without the tie rule's call. Out of line: inlined into the lists'
   loops, it cost their registers more than it saved (inside rays +2 %). */
static __attribute__((noinline)) RT_ANYHIT_TARGET void
rt_nearest_mesh(rt_walkstate *w, uint32_t i, double t, const double *v0, const double *v1,
                const double *v2)
{
    const double e = rt_tri_hit_err_v(w->r, t, v0, v1, v2);
    if (e < 0.0)
        rt_nearest_update(w->sc, w->r, i, t, &w->best, &w->bi, &w->ebest);
    else if (w->bi < 0) {
        w->best = t;
        w->bi = i;
        w->ebest = e;
    } else
        rt_nearest_take_e(w->sc, i, t, e, &w->best, &w->bi, &w->ebest);
}

/* a cell list of mesh triangles only, the ray's axis order (kx, ky, kz) and the kind known at
   compile time: the vertices' components at constant offsets, the ray's origin in registers
   for the whole list, the mesh's index triples and vertices read directly, no primitive kind
   to tell, no skipped primitive. nearest 0: an any-hit list (RT_ANY_MESH), the tests, their
   order and the blocker rt_cell_transmit's, 1 if blocked; nearest 1: a nearest-hit list
   (rt_walk_box's mode 3), the tests, their order, their search bound and the choice
   rt_cell_nearest's (rt_nearest_prim), so the hits are the same bits, 0 (the list type of
   rt_walkstate.list). */
RT_INLINE int rt_cell_mesh_k(rt_walkstate *w, const uint32_t *refs, const uint16_t *r16,
                             const uint32_t *loc, uint32_t n, int kx, int ky, int kz, int nearest)
{
    const rt_scene *sc = w->sc;
    const rt_rayx *r = w->r;
    const uint32_t(*ct)[3] = sc->ctri, nm = w->vnmask;
    const double *X = sc->mv_xyz.p;
    const double ox = r->o[kx], oy = r->o[ky], oz = r->o[kz];
    const double tmin = r->tmin, tmax = r->tmax;
    uint64_t *const hbox = w->c->hbox;
    const uint64_t key = (uint64_t)w->stamp << 32;
    /* the list: refs, or 2-byte references r16 into a sub-grid's table loc (rt_grid.sref16) */
#define RT_REF(k) (r16 ? loc[r16[k]] : refs[k])
    /* no pass prefetching the list's index triples ahead of the tests (rt_prefetch_tris):
       it cost about 7 instructions per reference and a mispredicted loop exit per list
       (bunny primary 3 % of instructions, 9 % of mispredicts) and timed no faster
       (docs/bench/rt_tuning.md) */
    for (uint32_t k = 0; k < n; k++) {
        const uint32_t i = RT_REF(k);
        if (hbox[i % RT_HBOX] == (key | i))
            continue;
        hbox[i % RT_HBOX] = key | i;
        const uint32_t *ix = ct[i];
        const double *v0 = X + rt_word_offset(nm, ix), *v1 = X + rt_word_offset(nm, ix + 1),
                     *v2 = X + rt_word_offset(nm, ix + 2);
        double t;
        if (!rt_isect_tri_k(r, kx, ky, kz, ox, oy, oz, v0, v1, v2, tmin,
                            nearest ? RT_MIN(w->best + 2.0 * w->ebest, tmax) : tmax, &t))
            continue;
        if (nearest) {
            rt_nearest_mesh(w, i, t, v0, v1, v2);
        } else {
            w->T = 0.0;
            w->c->blocker = rt_prim_opaque(sc, i) ? (long)i : -1;
            return 1;
        }
    }
#undef RT_REF
    return 0;
}

/* one copy of each list per axis order of the shear (ky = 3 - kx - kz) */
#define RT_CELL_LISTS(KX, KY, KZ)                                                               \
    static __attribute__((noinline)) RT_ANYHIT_TARGET int rt_cell_nearest_##KX##KY##KZ(      \
        rt_walkstate *w, const uint32_t *refs, uint32_t n)                                    \
    {                                                                                         \
        return rt_cell_mesh_k(w, refs, NULL, NULL, n, KX, KY, KZ, 1);                         \
    }
RT_CELL_LISTS(1, 2, 0)
RT_CELL_LISTS(2, 1, 0)
RT_CELL_LISTS(2, 0, 1)
RT_CELL_LISTS(0, 2, 1)
RT_CELL_LISTS(0, 1, 2)
RT_CELL_LISTS(1, 0, 2)
#undef RT_CELL_LISTS

/* the copies by the axis order of the shear, in rt_list_order's numbering */
static const rt_anyhit_list_fn rt_nearest_lists[6] = {
    rt_cell_nearest_120, rt_cell_nearest_210, rt_cell_nearest_201,
    rt_cell_nearest_021, rt_cell_nearest_012, rt_cell_nearest_102};

/* the number of r's axis order (sheared: rt_rayx_shear) among the lists' copies; the copy is
   taken once per ray rather than per list (a switch per list cost about 10 instructions of
   some 4 lists per shadow ray, with the register saves of a function holding all six) */
static int rt_list_order(const rt_rayx *r)
{
    switch (r->kz * 4 + r->kx) {
    case 0 * 4 + 1:
        return 0;
    case 0 * 4 + 2:
        return 1;
    case 1 * 4 + 2:
        return 2;
    case 1 * 4 + 0:
        return 3;
    case 2 * 4 + 0:
        return 4;
    default:
        return 5;
    }
}

/* 1 if blocked */
static __attribute__((noinline)) int rt_cell_transmit(rt_walkstate *w, const uint32_t *refs,
                                                      uint32_t n)
{
    const rt_scene *sc = w->sc;
    const rt_rayx *r = w->r;
    const uint32_t skip = r->skip;
    rt_prefetch_tris(sc, refs, n);
    if (w->any_hit) {
        uint64_t *const hbox = w->c->hbox;
        const uint64_t key = (uint64_t)w->stamp << 32;
        for (uint32_t k = 0; k < n; k++) {
            uint32_t i = refs[k];
            if (hbox[i % RT_HBOX] == (key | i) || i == skip)
                continue;
            hbox[i % RT_HBOX] = key | i;
            if (!rt_transmit_prim(w->c, sc, r, i, 1, &w->T))
                return 1;
        }
        return 0;
    }
    uint32_t *const mbox = w->c->mbox;
    const uint32_t stamp = w->stamp;
    for (uint32_t k = 0; k < n; k++) {
        uint32_t i = refs[k];
        if (mbox[i] == stamp || i == skip)
            continue;
        mbox[i] = stamp;
        if (!rt_transmit_prim(w->c, sc, r, i, 0, &w->T))
            return 1;
    }
    return 0;
}

/* lanes per call of the float test (its candidates on the stack) */
#define RT_LEAF_CHUNK 64

/* the triangles of a float leaf: the float test rules lanes out, the double test decides
   the candidates, mailboxed as in rt_cell_nearest and rt_cell_transmit: for nearest-hit rays
   (any 0) rt_nearest_prim; for any-hit rays (any 1: the first hit blocks, in whatever order
   the lanes come) rt_transmit_prim, 1 if blocked */
static __attribute__((noinline)) int rt_leaf_walk(rt_walkstate *w, const rt_leaf *lf, int any)
{
    const rt_scene *sc = w->sc;
    const rt_grid *g = &sc->grid;
    const rt_rayx *r = w->r;
    uint64_t *const hbox = w->c->hbox;
    const uint64_t key = (uint64_t)w->stamp << 32;
    const uint32_t *ids = g->lid + lf->lane0;
    const float *rows = g->lf + (size_t)9 * lf->lane0;
    rt_fray f;
    const int ok = rt_fray_leaf(r, lf, &f);
    uint32_t cand[RT_LEAF_CHUNK];
    for (uint32_t c0 = 0; c0 < lf->n; c0 += RT_LEAF_CHUNK) {
        const uint32_t nc = lf->n - c0 < RT_LEAF_CHUNK ? lf->n - c0 : RT_LEAF_CHUNK;
        uint32_t m = nc;
        if (ok)
            m = (nc <= 4 ? g->leaf_fn4 : g->leaf_fn)(rows + c0, lf->L, nc, &f, cand);
        for (uint32_t j = 0; j < m; j++) {
            const uint32_t i = ids[c0 + (ok ? cand[j] : j)];
            if (hbox[i % RT_HBOX] == (key | i) || i == r->skip)
                continue;
            hbox[i % RT_HBOX] = key | i;
            if (!any)
                rt_nearest_prim(sc, r, i, &w->best, &w->bi, &w->ebest);
            else if (!rt_transmit_prim(w->c, sc, r, i, 1, &w->T))
                return 1;
        }
    }
    return 0;
}

/* the n > 0 primitives of one cell list (lf: 1 + its float leaf, 0: none): 1 when an opaque
   primitive blocks a transmittance ray (mode 1, and modes RT_MODE_ANYK + O, RT_MODE_ANYTOP + O:
   mode 1 for a walk known to be RT_ANY_MESH's with the ray's axis order O; modes
   RT_MODE_NEARK + O, mode 3's walks of axis order O, rt_walk_sub_nearest_O, never block) */
/* the references of a cell of a sub-grid with a table of primitives (rt_grid.sref16) made
   into primitive indices at a time, on the stack */
#define RT_LOCAL_CHUNK 32

RT_INLINE int rt_walk_cell(rt_walkstate *w, int mode, const uint32_t *refs, const uint16_t *r16,
                           const uint32_t *loc, uint32_t n, uint32_t lf)
{
    if (mode >= RT_MODE_ANYK) { /* the axis order's numbering as rt_list_order's */
        const int nearest = mode >= RT_MODE_NEARK;
        const int o = mode & 7, kz = o >> 1;
        const int kx = o == 0 || o == 5 ? 1 : o == 1 || o == 2 ? 2 : 0;
        return lf ? rt_leaf_walk(w, &w->sc->grid.leaves[lf - 1], !nearest)
                  : rt_cell_mesh_k(w, refs, r16, loc, n, kx, 3 - kx - kz, kz, nearest);
    }
    if (RT_MODE3(mode))
        return lf ? rt_leaf_walk(w, &w->sc->grid.leaves[lf - 1], 0) : w->list(w, refs, n);
    if (mode == 0 && lf)
        (void)rt_leaf_walk(w, &w->sc->grid.leaves[lf - 1], 0);
    else if (mode == 0)
        rt_cell_nearest(w, refs, n);
    else if (w->any_hit && lf)
        return rt_leaf_walk(w, &w->sc->grid.leaves[lf - 1], 1);
    else
        return rt_cell_transmit(w, refs, n);
    return 0;
}

RT_INLINE int rt_walk_box(rt_walkstate *w, int mode, const rt_box *g, const uint32_t *off,
                          const uint16_t *off16, const uint32_t *refs, const uint16_t *refs16,
                          const uint32_t *loc, const uint32_t *leaf,
                          const int32_t *sub, const rt_subgrid *subs, const uint8_t *dist, double t0, double t1,
                          int clip, const rt_pre4 *pre, int lane, const int *step)
{
    const rt_gray *gr = &w->gr;
    const int nn0 = g->n[0], nn1 = g->n[1], nn2 = g->n[2];
    int sx, sy, sz, cx, cy, cz;
    double dtx, dty, dtz, itx, ity, itz, tx, ty, tz, tent;
    if (pre) {
        /* the start, steps and constants of the batch's four-ray set-up (rt_pre4: the
           same values as below; no direction component is 0 there) */
        sx = pre->step[0][lane], sy = pre->step[1][lane], sz = pre->step[2][lane];
        cx = pre->c[0][lane], cy = pre->c[1][lane], cz = pre->c[2][lane];
        tx = pre->tn[0][lane], ty = pre->tn[1][lane], tz = pre->tn[2][lane];
        dtx = pre->dt[0][lane], dty = pre->dt[1][lane], dtz = pre->dt[2][lane];
        itx = pre->it[0][lane], ity = pre->it[1][lane], itz = pre->it[2][lane];
        tent = pre->t0[lane];
        t1 = pre->t1[lane];
    } else {
        rt_dda s;
        if (!rt_dda_init(g, gr, t0, t1, clip, step, &s))
            return RT_WALK_CONT;
        sx = s.step[0], sy = s.step[1], sz = s.step[2];
        /* a cell's width in ray parameter per axis (0 for an axis that does not step) */
        dtx = g->cw[0] * fabs(gr->invd[0]), dty = g->cw[1] * fabs(gr->invd[1]),
        dtz = g->cw[2] * fabs(gr->invd[2]);
        /* about 1 / dt* (cells per unit of ray parameter): the jumps' boundary counts */
        itx = fabs(gr->d[0]) * g->inv_cw[0], ity = fabs(gr->d[1]) * g->inv_cw[1],
        itz = fabs(gr->d[2]) * g->inv_cw[2];
        cx = s.c[0], cy = s.c[1], cz = s.c[2];
        tx = s.tnext[0], ty = s.tnext[1], tz = s.tnext[2];
        tent = s.t0;
        t1 = s.t1;
    }
    if (sub && (mode == 1 || RT_MODE3(mode) || mode >= RT_MODE_ANYTOP)) { /* any-hit,
                               transmittance and mesh nearest-hit walks' top level: the
                               steps for their second-level walks (rt_dda_init) */
        w->step[0] = sx;
        w->step[1] = sy;
        w->step[2] = sz;
    }
    /* the set-up's walks read the cells' widths in ray parameter and their inverses from its
       record where they are used: held in registers, they were spilled at the ray's start
       and around every second-level walk's call */
#define RT_DT(a, v) (pre ? pre->dt[a][lane] : (v))
#define RT_IT(a, v) (pre ? pre->it[a][lane] : (v))
    const ptrdiff_t dx = sx, dy = pre ? pre->dy[lane] : (ptrdiff_t)sy * nn0,
                    dz = pre ? pre->dz[lane] : (ptrdiff_t)sz * nn0 * nn1;
    size_t ci = pre ? (size_t)(uint32_t)pre->ci[lane]
                    : ((size_t)cz * (size_t)nn1 + (size_t)cy) * (size_t)nn0 + (size_t)cx;
    for (;;) {
        /* top level: the cell's byte in dist (rt_grid.odist). Below RT_CUBE_OCC an empty cell
           without a second-level grid, passed with one load (the best hit cannot have
           changed there), the byte its empty cube's edge in the ray's octant; else what the
           cell holds, so that only the offsets or the sub-grid index it has are loaded */
        unsigned kind = RT_CUBE_LIST | RT_CUBE_SUB;
        if (dist && (kind = dist[ci]) < RT_CUBE_OCC) {
            if (kind < RT_JUMP_MIN)
                goto advance;
            /* empty-space jump: the cells from this one to dist - 1 further on each axis in
               the ray's step directions are empty, and the ray stays in that cube (it moves
               in the cube's directions) until it leaves through the nearest far face of a
               stepping axis; the walk restarts from the cell holding that point. A cell the
               exact ray would cross only for a rounding-sized piece near the cube's edge may be
               passed over: a primitive hit there lies within rounding of the next cell,
               which references it (cells are enlarged by eps at build, rt_build.c).
               A parameter that overflows (extreme directions): ordinary steps instead.
               The far faces are the walk's next boundaries plus k cell widths. */
            const int k = (int)kind - 1;
            const double jx = tx + (double)k * RT_DT(0, dtx), jy = ty + (double)k * RT_DT(1, dty),
                         jz = tz + (double)k * RT_DT(2, dtz);
            const double tj = RT_MIN(jx, RT_MIN(jy, jz));
            if (isfinite(tj)) {
                if (tj > t1)
                    return RT_WALK_CONT;
                /* each stepping axis moves on by the boundaries it crosses up to tj,
                   counted from its next one (rt_jump_cells), its next boundary as many
                   widths further: the walk's own drifted boundaries, as RT_ADVANCE keeps
                   them; an axis that does not step keeps its cell and INFINITY */
                if (sx) {
                    const int m = rt_jump_cells(tx, jx, tj, RT_IT(0, itx), k);
                    cx += sx * m;
                    tx += (double)m * RT_DT(0, dtx);
                }
                if (sy) {
                    const int m = rt_jump_cells(ty, jy, tj, RT_IT(1, ity), k);
                    cy += sy * m;
                    ty += (double)m * RT_DT(1, dty);
                }
                if (sz) {
                    const int m = rt_jump_cells(tz, jz, tj, RT_IT(2, itz), k);
                    cz += sz * m;
                    tz += (double)m * RT_DT(2, dtz);
                }
                if ((unsigned)cx >= (unsigned)nn0 || (unsigned)cy >= (unsigned)nn1 ||
                    (unsigned)cz >= (unsigned)nn2)
                    return RT_WALK_CONT; /* the ray has left the box */
                tent = tj;
                ci = ((size_t)cz * (size_t)nn1 + (size_t)cy) * (size_t)nn0 + (size_t)cx;
                continue;
            }
            goto advance;
        }
        /* the cell's list: 4-byte offsets (off) or a sub-grid's 2-byte ones (off16); a top
           cell whose byte says it has none is not looked up */
        if (kind & RT_CUBE_LIST) {
            const uint32_t k0 = off16 ? off16[ci] : off[ci],
                           k1 = off16 ? off16[ci + 1] : off[ci + 1];
            if (refs16 && mode >= RT_MODE_ANYK) { /* a sub-grid's table of primitives
                             (rt_grid.sref16) read by the mesh lists themselves */
                if (k0 == k1)
                    goto advance;
                if (rt_walk_cell(w, mode, NULL, refs16 + k0, loc, k1 - k0, 0))
                    return RT_WALK_BLOCKED;
            } else if (refs16) { /* the others' lists made from it in pieces, each tested in
                             order as the whole would be */
                if (k0 == k1)
                    goto advance;
                for (uint32_t k = k0; k < k1; k += RT_LOCAL_CHUNK) {
                    uint32_t buf[RT_LOCAL_CHUNK];
                    const uint32_t m = RT_MIN(k1 - k, (uint32_t)RT_LOCAL_CHUNK);
                    for (uint32_t j = 0; j < m; j++)
                        buf[j] = loc[refs16[k + j]];
                    if (rt_walk_cell(w, mode, buf, NULL, NULL, m, 0))
                        return RT_WALK_BLOCKED;
                }
            } else if (dist || k0 != k1) {
                if (rt_walk_cell(w, mode, refs + k0, NULL, NULL, k1 - k0, leaf ? leaf[ci] : 0))
                    return RT_WALK_BLOCKED;
            } else if (!sub) /* an empty second-level cell: no test, the best hit unchanged */
                goto advance;
        }
        if (sub && (dist ? (kind & RT_CUBE_SUB) != 0 : sub[ci] >= 0) &&
            !(mode >= RT_MODE_ANYTOP && __builtin_expect(w->spl != NULL, 0) &&
              w->spl[sub[ci]] && rt_sub_flat(w, w->spl[sub[ci]]))) {
            /* the sub-grid's box clip here: a third of the rays that cross a crowded top
               cell miss its sub-grid's box, and then need no call */
            const rt_subgrid *sg = &subs[sub[ci]];
            double s0 = tent, s1 = RT_MIN(tx, RT_MIN(ty, tz));
            s1 = RT_MIN(s1, t1);
            /* AVX2's encoding (modes 3, RT_MODE_ANYTOP + O): the clip in lanes, a direction
               component 0 (a step 0) to the loop; rt_box_clip's SSE2 zero test would load
               d[2] with a register vmovq (rt_nearest_apart) */
            if ((RT_MODE3(mode) || mode >= RT_MODE_ANYTOP) && pre ? rt_box_clip_nz4(&sg->b, gr, &s0, &s1)
                : pre ? rt_box_clip_nz(&sg->b, gr, &s0, &s1)
                : mode >= RT_MODE_ANYTOP
                    ? (sx && sy && sz ? rt_box_clip_nz4(&sg->b, gr, &s0, &s1)
                                      : rt_box_clip_loop(&sg->b, gr, &s0, &s1))
                    : rt_box_clip(&sg->b, gr, &s0, &s1)) {
                /* nearest-hit walks: a flat sub-grid whose plane the range does not cross
                   (rt_sub_flat_near) is not walked, one whose plane it crosses is walked
                   around the crossing */
                if ((mode == 0 || RT_MODE3(mode)) && __builtin_expect(w->spl != NULL, 0) &&
                    w->spl[sub[ci]]) {
                    const rt_trange r = rt_sub_flat_near(w, w->spl[sub[ci]], s0, s1);
                    if (!(r.lo <= r.hi))
                        goto lower;
                    s0 = r.lo;
                    s1 = r.hi;
                }
                int st = mode == 0   ? rt_walk_sub_nearest(w, sg, s0, s1)
                         : RT_MODE3(mode) ? w->sub(w, sg, s0, s1)
                         : mode >= RT_MODE_ANYTOP ? rt_walk_sub_anyhit_o(w, mode & 7, sg, s0, s1)
                                                  : rt_walk_sub_transmit(w, sg, s0, s1);
                if (st != RT_WALK_CONT)
                    return st;
            }
        }
        /* nearest mode: nothing beyond the best hit's tie window (best + 2 ebest) matters.
           Once a cell is left whose exit is beyond it, every primitive hit up to there has
           been tested (the cells that hold the ray points up to it were all visited, and
           each holds every primitive crossing it). */
    lower:
        if ((mode == 0 || RT_MODE3(mode) || mode >= RT_MODE_NEARK) && w->best + 2.0 * w->ebest < t1)
            t1 = w->best + 2.0 * w->ebest;
    advance:
        RT_ADVANCE();
    }
#undef RT_DT
#undef RT_IT
}

/* the walk of second-level grid sg over [t0, t1] in mode mode (rt_walk_box's; step: NULL, or
   the ray's steps that the top walk of modes 1, 3 and RT_MODE_ANYTOP + O stored); local: 1 the
   references' 2-byte layout (rt_grid.sref16), 0 the 4-byte one, -1 the grid's */
RT_INLINE int rt_walk_sub(rt_walkstate *w, int mode, const rt_subgrid *sg, double t0, double t1,
                          const int *step, int local)
{
    const rt_grid *g = &w->sc->grid;
    const uint32_t *leaf = g->sleaf ? g->sleaf + sg->first : NULL;
    if (local > 0 || (local < 0 && g->sref16)) /* 2-byte references into the sub-grid's
                                                  table (rt_internal.h) */
        return rt_walk_box(w, mode, &sg->b, NULL, g->soff16 + sg->first16, NULL,
                           g->sref16 + sg->ref0, g->sloc + sg->loc0, NULL, NULL, NULL, NULL,
                           t0, t1, 0, NULL, 0, step);
    if (g->soff16) /* the 2-byte layout (rt_internal.h) */
        return rt_walk_box(w, mode, &sg->b, NULL, g->soff16 + sg->first16,
                           g->srefs + sg->ref0, NULL, NULL, leaf, NULL, NULL, NULL, t0, t1, 0,
                           NULL, 0, step);
    return rt_walk_box(w, mode, &sg->b, g->soff + sg->first, NULL, g->srefs, NULL, NULL, leaf,
                       NULL, NULL, NULL, t0, t1, 0, NULL, 0, step);
}

static __attribute__((noinline)) int rt_walk_sub_nearest(rt_walkstate *w, const rt_subgrid *sg,
                                                         double t0, double t1)
{
    return rt_walk_sub(w, 0, sg, t0, t1, NULL, -1);
}

/* the same for the nearest-hit walks of a scene of mesh triangles only (mode 3's second
   level, modes RT_MODE_NEARK + O: the lists' axis order known and their bodies inlined), in
   AVX2's encoding as the any-hit ones below, one per axis order in rt_list_order's numbering,
   and one per axis order for the references' 2-byte layout (rt_grid.sref16), the layout
   chosen with the copy, once per ray, not per sub-grid */
#define RT_SUB_NEAREST(O)                                                                     \
    static __attribute__((noinline)) RT_ANYHIT_TARGET int rt_walk_sub_nearest_##O(            \
        rt_walkstate *w, const rt_subgrid *sg, double t0, double t1)                           \
    {                                                                                         \
        return rt_walk_sub(w, RT_MODE_NEARK + O, sg, t0, t1, w->step, 0);                     \
    }                                                                                         \
    static __attribute__((noinline)) RT_ANYHIT_TARGET int rt_walk_sub_nearest_local_##O(      \
        rt_walkstate *w, const rt_subgrid *sg, double t0, double t1)                           \
    {                                                                                         \
        return rt_walk_sub(w, RT_MODE_NEARK + O, sg, t0, t1, w->step, 1);                     \
    }
RT_SUB_NEAREST(0)
RT_SUB_NEAREST(1)
RT_SUB_NEAREST(2)
RT_SUB_NEAREST(3)
RT_SUB_NEAREST(4)
RT_SUB_NEAREST(5)
#undef RT_SUB_NEAREST
static const rt_sub_walk_fn rt_sub_nearest[6] = {rt_walk_sub_nearest_0, rt_walk_sub_nearest_1,
                                                 rt_walk_sub_nearest_2, rt_walk_sub_nearest_3,
                                                 rt_walk_sub_nearest_4, rt_walk_sub_nearest_5};
static const rt_sub_walk_fn rt_sub_nearest_local[6] = {
    rt_walk_sub_nearest_local_0, rt_walk_sub_nearest_local_1, rt_walk_sub_nearest_local_2,
    rt_walk_sub_nearest_local_3, rt_walk_sub_nearest_local_4, rt_walk_sub_nearest_local_5};

static __attribute__((noinline)) int rt_walk_sub_transmit(rt_walkstate *w, const rt_subgrid *sg,
                                                          double t0, double t1)
{
    return rt_walk_sub(w, 1, sg, t0, t1, w->step, -1);
}

/* the second-level walk of an RT_ANY_MESH ray of axis order o known at compile time (modes
   RT_MODE_ANYK + o: the lists' kind and axis order known), for the top walk of mode
   RT_MODE_ANYTOP + o, which inlines it (rt_occluded_top_O's flatten: one encoding, no call, no
   register saves of a callee). Not always_inline: rt_walk_box calls it and it calls
   rt_walk_box, a cycle GCC refuses to inline by force; flatten inlines it once (the inner
   walk's own call of it is dead code, its mode being RT_MODE_ANYK + o), and the walk's copies
   in the build's own encoding keep a dead call rather than a target mismatch. */
static inline RT_ANYHIT_TARGET int rt_walk_sub_anyhit_o(rt_walkstate *w, int o,
                                                       const rt_subgrid *sg, double t0, double t1)
{
    return rt_walk_sub(w, RT_MODE_ANYK + o, sg, t0, t1, w->step, -1);
}

/* the top level's cubes of octant o: a built grid always has them (rt_build.c builds them
   before use_grid is set), and saying so lets the top walk's inlined copies drop their tests
   of dist against NULL */
static inline const uint8_t *rt_cubes_of(const rt_grid *g, size_t o)
{
    const uint8_t *d = g->odist + o * g->ncells;
    __asm__("" : "+r"(d)); /* one value: not split into base and offset in the walk */
    if (!d)
        __builtin_unreachable();
    return d;
}

/* the top level's empty cubes for the ray's octant (the signs of its steps: a component
   +0.0 or -0.0 does not step, and the cube covers its slice either way) */
static inline const uint8_t *rt_octant_cubes(const rt_grid *g, const rt_gray *gr)
{
    const size_t o = (size_t)(gr->d[0] < 0.0) | (size_t)(gr->d[1] < 0.0) << 1 |
                     (size_t)(gr->d[2] < 0.0) << 2;
    return rt_cubes_of(g, o);
}

/* the walk state of a ray r: no hit yet (fields one by one: an initialiser would also
   clear the grid-frame ray, which rt_gray_init writes) */
RT_INLINE void rt_walkstate_init(rt_walkstate *w, const rt_scene *sc, rt_ctx *c,
                                 const rt_rayx *r, int any_hit)
{
    w->sc = sc;
    w->c = c;
    w->r = r;
    w->stamp = 0;
    w->any_hit = any_hit;
    w->list = NULL;
    w->best = INFINITY;
    w->bi = -1;
    w->ebest = 0.0;
    w->T = 1.0;
}

/* the nearest hit of r; rs: NULL, or r itself when its shear (rt_rayx_shear) is still to be
   computed: the batch API's rays that miss the grid's box never need it */
RT_INLINE long rt_nearest_core(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, rt_rayx *rs,
                               double *tout)
{
    rt_walkstate w;
    rt_walkstate_init(&w, sc, c, r, 0);
    if (!sc->use_grid) {
        if (rs)
            rt_rayx_shear(rs);
        for (size_t i = 0; i < sc->nprim; i++)
            if (i != r->skip)
                rt_nearest_prim(sc, r, (uint32_t)i, &w.best, &w.bi, &w.ebest);
    } else {
        const rt_grid *g = &sc->grid;
        double t0 = r->tmin, t1 = r->tmax;
        rt_gray_init(g, r, &w.gr);
        if (rt_box_clip(&g->b, &w.gr, &t0, &t1) && rt_kdop_clip(g, &w.gr, &t0, &t1)) {
            if (rs)
                rt_rayx_shear(rs);
            w.stamp = rt_ctx_next(c);
            w.spl = g->subplane_near; /* rt_sub_flat_near */
            rt_walk_box(&w, 0, &g->b, g->off, NULL, g->refs, NULL, NULL, g->tleaf, g->sub, g->subs,
                        rt_octant_cubes(g, &w.gr), t0, t1, 0, NULL, 0, NULL);
        }
    }
    *tout = w.best;
    return w.bi;
}

long rt_trace_nearest(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, double *tout)
{
    return rt_nearest_core(sc, c, r, NULL, tout);
}

long rt_trace_list(const rt_scene *sc, const rt_rayx *r, const uint32_t *ids, size_t n,
                   double *tout)
{
    double best = INFINITY, eb = 0.0;
    long bi = -1;
    for (size_t k = 0; k < n; k++)
        if (ids[k] != r->skip)
            rt_nearest_prim(sc, r, ids[k], &best, &bi, &eb);
    *tout = best;
    return bi;
}

/* the top-level walk of an RT_ANY_MESH ray of axis order O over [t0, t1] (its part in the
   grid's box and k-DOP), without a four-ray set-up (rt_transmit_core: the packet path's rays
   traced singly, the batch's rays left to the one-ray code): mode RT_MODE_ANYTOP + O with its
   second-level walks inlined (flatten), in AVX2's encoding; 1 if blocked */
#define RT_TRANSMIT_TOP(O)                                                                    \
    static __attribute__((noinline, flatten)) RT_ANYHIT_TARGET int rt_transmit_top_##O(      \
        rt_walkstate *w, double t0, double t1)                                               \
    {                                                                                         \
        const rt_grid *g = &w->sc->grid;                                                      \
        return rt_walk_box(w, RT_MODE_ANYTOP + O, &g->b, g->off, NULL, g->refs, NULL, NULL,  \
                           g->tleaf, g->sub, g->subs, rt_octant_cubes(g, &w->gr), t0, t1, 0,  \
                           NULL, 0, NULL) == RT_WALK_BLOCKED;                                 \
    }
RT_TRANSMIT_TOP(0)
RT_TRANSMIT_TOP(1)
RT_TRANSMIT_TOP(2)
RT_TRANSMIT_TOP(3)
RT_TRANSMIT_TOP(4)
RT_TRANSMIT_TOP(5)
#undef RT_TRANSMIT_TOP
typedef int (*rt_transmit_top_fn)(rt_walkstate *w, double t0, double t1);
static const rt_transmit_top_fn rt_transmit_top[6] = {rt_transmit_top_0, rt_transmit_top_1,
                                                      rt_transmit_top_2, rt_transmit_top_3,
                                                      rt_transmit_top_4, rt_transmit_top_5};

/* transmittance along r; rs as in rt_nearest_core */
RT_INLINE double rt_transmit_core(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, rt_rayx *rs,
                                  int any_hit)
{
    c->blocker = -1;
    rt_walkstate w;
    rt_walkstate_init(&w, sc, c, r, any_hit);
    const rt_grid *g = &sc->grid;
    /* only opaque primitives: the first hit blocks, as for any-hit rays (small mailbox) */
    w.any_hit |= sc->use_grid && g->all_opaque;
    /* no grid, or a transparency walk with a context that has no exact mailbox (the batch
       API's): every primitive once */
    if (!sc->use_grid || (!w.any_hit && !c->mbox)) {
        if (rs)
            rt_rayx_shear(rs);
        for (size_t i = 0; i < sc->nprim; i++)
            if (i != r->skip && !rt_transmit_prim(c, sc, r, i, any_hit, &w.T))
                return 0.0;
        return w.T;
    }
    double t0 = r->tmin, t1 = r->tmax;
    rt_gray_init(g, r, &w.gr);
    if (!rt_box_clip(&g->b, &w.gr, &t0, &t1) || !rt_kdop_clip(g, &w.gr, &t0, &t1))
        return w.T;
    if (rs)
        rt_rayx_shear(rs);
    w.stamp = rt_ctx_next(c);
    if (w.any_hit == RT_ANY_MESH) {
        w.vnmask = ~sc->vmask;
        rt_walk_flat_init(&w, sc, r);
        return rt_transmit_top[rt_list_order(r)](&w, t0, t1) ? 0.0 : w.T;
    }
    if (rt_walk_box(&w, 1, &g->b, g->off, NULL, g->refs, NULL, NULL, g->tleaf, g->sub, g->subs,
                    rt_octant_cubes(g, &w.gr), t0, t1, 0, NULL, 0, NULL) == RT_WALK_BLOCKED)
        return 0.0;
    return w.T;
}

static int rt_anyhit_kind(const rt_scene *sc);
static int rt_mesh_only(const rt_scene *sc);

double rt_trace_transmit(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, int any_hit)
{
    /* any-hit rays without a skipped primitive (the packet path's rays traced singly) as
       rt_occluded's */
    if (any_hit && r->skip == RT_NO_SKIP)
        any_hit = rt_anyhit_kind(sc);
    return rt_transmit_core(sc, c, r, NULL, any_hit);
}

double rt_trace_transmit_list(const rt_scene *sc, rt_ctx *c, const rt_rayx *r,
                              const uint32_t *ids, uint32_t n, const uint16_t *zb, uint32_t zbo)
{
    c->blocker = -1;
    double T = 1.0;
    for (uint32_t k = 0; k < n && zb[ids[k]] <= zbo; k++)
        if (ids[k] != r->skip && !rt_transmit_prim(c, sc, r, ids[k], 0, &T))
            return 0.0;
    return T;
}

int rt_hits_prim(const rt_scene *sc, const rt_rayx *r, long i)
{
    double t;
    return i >= 0 && (size_t)i < sc->nprim && rt_isect_prim(sc, r, (size_t)i, r->tmin, r->tmax, &t);
}

/* ---- batch API ---- */

/* also the packet path's (rt_packet.h) */
void rt_fill_hit(const rt_scene *sc, const rt_rayx *r, long i, double t, rt_hit *h)
{
    h->t = t;
    h->prim = rt_prim_id(sc, (size_t)i);
    rt_prim_ng(sc, (size_t)i, h->ng);
    for (int j = 0; j < 3; j++)
        h->p[j] = r->o[j] + t * r->d[j];
    double den = h->ng[0] * r->d[0] + h->ng[1] * r->d[1] + h->ng[2] * r->d[2];
    h->side = den > 0.0 ? 1 : 0;
}

/* the checks and the traversal context of a batch call (out: its output array): the batch
   API's here and rt_packet.c's */
int rt_batch_begin(const rt_scene *sc, size_t n, const rt_ray *rays, const void *out, rt_ctx *c)
{
    if (!sc || (n && (!rays || !out)))
        return RT_ERR_ARG;
    if (!sc->committed)
        return RT_ERR_STATE;
    return rt_ctx_init_small(c);
}

/* the rt_rayx (its shear from the set-up: rt_shear4) and grid-frame ray of lane j of a
   four-ray set-up in state 2 (ray: its input; no component is flushed there) */
RT_INLINE void rt_pre_ray(rt_rayx *r, rt_gray *gr, const rt_pre4 *p, int j, const rt_ray *ray)
{
    memcpy(r->o, ray->org, sizeof r->o);
    memcpy(r->d, ray->dir, sizeof r->d);
    r->tmin = ray->tmin;
    r->tmax = ray->tmax;
    r->skip = RT_NO_SKIP;
    r->kx = p->kx[j];
    r->ky = p->ky[j];
    r->kz = p->kz[j];
    r->sx = p->sx[j];
    r->sy = p->sy[j];
    r->sz = p->sz[j];
    for (int a = 0; a < 3; a++) {
        gr->o[a] = p->o[a][j];
        gr->d[a] = p->d[a][j];
    }
    gr->invd[0] = p->invd[0][j];
    gr->invd[1] = p->invd[1][j];
    gr->invd[2] = p->invd[2][j];
}

/* the top grid's values that a batch's walks read (rt_walk_pre), copied once per batch
   (rt_topgrid_of): read from the grid, they were reloaded and spilled again for every ray,
   since the compiler must assume that the walk's stores (the mailbox, the hits) and calls
   may change the grid */
typedef struct rt_topgrid {
    rt_box b;
    const uint32_t *off, *refs, *leaf;
    const int32_t *sub;
    const rt_subgrid *subs;
    const uint8_t *odist;
    size_t ncells;
    const rt_sub_walk_fn *subn; /* the nearest-hit second-level walks of the grid's layout */
    const uint32_t *splnear;    /* rt_grid.subplane_near */
} rt_topgrid;

RT_INLINE rt_topgrid rt_topgrid_of(const rt_grid *g)
{
    return (rt_topgrid){.b = g->b, .off = g->off, .refs = g->refs, .leaf = g->tleaf,
                        .sub = g->sub, .subs = g->subs, .odist = g->odist, .ncells = g->ncells,
                        .subn = g->sref16 ? rt_sub_nearest_local : rt_sub_nearest,
                        .splnear = g->subplane_near};
}

/* the top-level walk of lane j of a four-ray set-up in state 2 (mode as rt_walk_box's; tg:
   the grid's values, rt_topgrid_of) */
RT_INLINE int rt_walk_pre(rt_walkstate *w, int mode, const rt_topgrid *tg, const rt_pre4 *p,
                          int j)
{
    const uint8_t *dist = tg->odist + (size_t)p->oct[j] * tg->ncells; /* as rt_cubes_of */
    __asm__("" : "+r"(dist));
    if (!dist)
        __builtin_unreachable();
    return rt_walk_box(w, mode, &tg->b, tg->off, NULL, tg->refs, NULL, NULL, tg->leaf, tg->sub,
                       tg->subs, dist, 0.0, 0.0, 0, p, j, NULL);
}

/* the answer of a ray that misses: every field written once (the output array is cold) */
static inline void rt_miss_hit(rt_hit *h)
{
    *h = (rt_hit){.t = INFINITY, .prim = -1};
}

/* rt_nearest_core of a ray that rt_intersect_mesh leaves to the one-ray code (the set-up's
   state 0, the batch's last rays), out of line: that walk (mode 0) and its SSE2 clips stay in
   the build's own encoding. In the mesh loop's AVX2 encoding GCC zero-extends the clips' scalars
   with a register-to-register vmovq, which GNU as encodes as VEX 66 0F D6 when the source is
   xmm8-15, and valgrind 3.19 cannot decode that ("unhandled instruction bytes: 0xC5 0x79 0xD6"):
   callgrind could not measure the loop. */
static __attribute__((noinline)) long rt_nearest_apart(const rt_scene *sc, rt_ctx *c, rt_rayx *r,
                                                       double *tout)
{
    return rt_nearest_core(sc, c, r, r, tout);
}

/* rt_fill_hit of mesh triangle i in a scene of mesh triangles only (rt_mesh_only: no plain
   triangle, so the triangle's index triple is ctri[i]), inline: rt_prim_id's mesh record and
   rt_prim_ng_tri's normal (rt_tri_unit_normal), the same operations in the same order, without
   the call, its register saves and the primitive kind's and storage's tests (about 160
   instructions per hit before) */
RT_INLINE void rt_fill_hit_mesh(const rt_scene *sc, const rt_rayx *r, long i, double t, rt_hit *h)
{
    const uint32_t *ix = sc->ctri[i], vm = sc->vmask;
    const double *X = sc->mv_xyz.p;
    double ng[3];
    rt_tri_unit_normal(X + (ix[0] & vm), X + (ix[1] & vm), X + (ix[2] & vm), ng);
    const double den = ng[0] * r->d[0] + ng[1] * r->d[1] + ng[2] * r->d[2];
    *h = (rt_hit){.t = t,
                  .prim = rt_cmesh_rec(sc, (size_t)i)->id,
                  .side = den > 0.0 ? 1 : 0,
                  .p = {r->o[0] + t * r->d[0], r->o[1] + t * r->d[1], r->o[2] + t * r->d[2]},
                  .ng = {ng[0], ng[1], ng[2]}};
}

/* one ray of rt_intersect; p: NULL, or its four-ray set-up (lane j), tg the grid's values
   (rt_topgrid_of); mesh: 0, or in a scene where rt_mesh_only holds the set-up's walk mode
   (3, RT_MODE_NEARZ) */
RT_INLINE void rt_intersect_one(const rt_scene *sc, rt_ctx *c, const rt_ray *ray, rt_hit *h,
                                const rt_topgrid *tg, const rt_pre4 *p, int j, int mesh)
{
    rt_rayx r;
    double t;
    long i = -1;
    /* written after the trace: its lines arrive meanwhile */
    __builtin_prefetch(h, 1);
    __builtin_prefetch((const char *)h + sizeof *h - 1, 1);
    if (p && p->state[j] == 2) {
        rt_walkstate w;
        rt_pre_ray(&r, &w.gr, p, j, ray);
        rt_walkstate_init(&w, sc, c, &r, 0);
        if (mesh) {
            const int o = p->ord[j]; /* rt_list_order(&r) */
            w.list = rt_nearest_lists[o];
            w.sub = tg->subn[o];
            w.vnmask = ~sc->vmask;
        }
        w.stamp = rt_ctx_next(c);
        w.spl = tg->splnear; /* rt_sub_flat_near */
        rt_walk_pre(&w, mesh, tg, p, j);
        t = w.best;
        i = w.bi;
    } else if ((!p || p->state[j] == 0) &&
               rt_rayx_check(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
        i = mesh ? rt_nearest_apart(sc, c, &r, &t) : rt_nearest_core(sc, c, &r, &r, &t);
    if (i >= 0) {
        if (mesh)
            rt_fill_hit_mesh(sc, &r, i, t, h);
        else
            rt_fill_hit(sc, &r, i, t, h);
    } else
        rt_miss_hit(h);
}

/* the set-up of rays k.. of n (n - k >= 4) into p: eight rays where su has the eight-ray set-up
   and eight are left, else four; the number of records filled (2 or 1) */
static inline int rt_setup_next(const rt_setup *su, const rt_grid *g, const rt_ray *rays,
                                size_t k, size_t n, rt_pre4 p[2])
{
    if (su->eight && k + 8 <= n) {
        su->eight(g, rays + k, p);
        return 2;
    }
    su->four(g, rays + k, p);
    return 1;
}

/* 1 if every lane of a four-ray set-up is a usable ray that misses (state 1) */
static inline int rt_pre4_all_miss(const rt_pre4 *p)
{
    _Static_assert(sizeof p->state == 2 * sizeof(uint64_t), "four 32-bit states");
    uint64_t s[2];
    memcpy(s, p->state, sizeof s);
    const uint64_t one2 = (uint64_t)1 << 32 | 1;
    return ((s[0] ^ one2) | (s[1] ^ one2)) == 0; /* one branch */
}

/* rt_intersect's rays (setup4: NULL, or the four-ray set-up; mesh: as rt_intersect_one's) */
RT_INLINE void rt_intersect_rays(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays,
                                 rt_hit *hits, const rt_setup *setup4, int mesh)
{
    size_t k = 0;
    if (setup4) {
        const rt_topgrid tg = rt_topgrid_of(&sc->grid);
        rt_pre4 p[2];
        while (k + 4 <= n) {
            const int m = rt_setup_next(setup4, &sc->grid, rays, k, n, p);
            for (int h = 0; h < m; h++, k += 4) {
                if (rt_pre4_all_miss(p + h)) { /* rows of eye rays beside the scene */
                    for (int j = 0; j < 4; j++)
                        rt_miss_hit(hits + k + j);
                    continue;
                }
                for (int j = 0; j < 4; j++)
                    rt_intersect_one(sc, c, rays + k + j, hits + k + j, &tg, p + h, j, mesh);
            }
        }
    }
    for (; k < n; k++)
        rt_intersect_one(sc, c, rays + k, hits + k, NULL, NULL, 0, mesh);
}

static __attribute__((noinline)) void rt_intersect_any(const rt_scene *sc, rt_ctx *c, size_t n,
                                                       const rt_ray *rays, rt_hit *hits,
                                                       const rt_setup *setup4)
{
    rt_intersect_rays(sc, c, n, rays, hits, setup4, 0);
}

/* the same for a scene of mesh triangles only (rt_mesh_only): the walks of mode 3, the top
   level's too in AVX2's encoding (RT_ANYHIT_TARGET: the CPU has AVX2 and BMI here) */
static __attribute__((noinline)) RT_ANYHIT_TARGET void
rt_intersect_mesh(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays, rt_hit *hits,
                  const rt_setup *setup4)
{
    rt_intersect_rays(sc, c, n, rays, hits, setup4, 3);
}

/* the same for a batch of rays along z (rt_rays_along_z): mode RT_MODE_NEARZ */
static __attribute__((noinline)) RT_ANYHIT_TARGET void
rt_intersect_mesh_z(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays, rt_hit *hits,
                    const rt_setup *setup4)
{
    rt_intersect_rays(sc, c, n, rays, hits, setup4, RT_MODE_NEARZ);
}

/* 1 when the batch's first rays (up to 8) all have |d_z| above |d_x| and |d_y|: eye rays
   along VRC3 z, whose top-level steps are mostly along z, as a guess for the whole batch
   (only the order of the step's compares follows from it, never the cells walked) */
static int rt_rays_along_z(size_t n, const rt_ray *rays)
{
    const size_t m = n < 8 ? n : 8;
    for (size_t k = 0; k < m; k++) {
        const double *d = rays[k].dir;
        if (!(fabs(d[2]) > fabs(d[0]) && fabs(d[2]) > fabs(d[1])))
            return 0;
    }
    return m > 0;
}

int rt_intersect(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits)
{
    rt_ctx c;
    const int rc = rt_batch_begin(sc, n, rays, hits, &c);
    if (rc != RT_OK)
        return rc;
    const rt_setup *setup4 = n >= 4 ? rt_setup4_choose(sc) : NULL;
    if (rt_mesh_only(sc))
        (rt_rays_along_z(n, rays) ? rt_intersect_mesh_z : rt_intersect_mesh)(sc, &c, n, rays,
                                                                             hits, setup4);
    else
        rt_intersect_any(sc, &c, n, rays, hits, setup4);
    rt_ctx_free(&c);
    return RT_OK;
}

/* one ray of rt_occluded, as rt_intersect_one; ah: rt_anyhit_kind's */
RT_INLINE unsigned char rt_occluded_one(const rt_scene *sc, rt_ctx *c, const rt_ray *ray,
                                        const rt_topgrid *tg, const rt_pre4 *p, int j, int ah)
{
    rt_rayx r;
    if (p && p->state[j] == 2) {
        c->blocker = -1;
        rt_walkstate w;
        rt_pre_ray(&r, &w.gr, p, j, ray);
        rt_walkstate_init(&w, sc, c, &r, ah); /* RT_ANY_HIT: rt_occluded_mesh has the others */
        w.stamp = rt_ctx_next(c);
        if (rt_walk_pre(&w, 1, tg, p, j) == RT_WALK_BLOCKED)
            return 1;
        return w.T == 0.0;
    }
    if ((p && p->state[j] != 0) ||
        !rt_rayx_check(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
        return 0;
    return rt_transmit_core(sc, c, &r, &r, ah) == 0.0;
}

/* the top-level walk of an RT_ANY_MESH ray of axis order O in lane j of its four-ray set-up
   (rt_walk_box's mode RT_MODE_ANYTOP + O) with its second-level walks inlined (flatten), in
   AVX2's encoding: 1 if blocked (the lists of mesh triangles never lower the transmittance
   without blocking) */
#define RT_OCC_TOP(O)                                                                         \
    static __attribute__((noinline, flatten)) RT_ANYHIT_TARGET int rt_occluded_top_##O(      \
        rt_walkstate *w, const rt_topgrid *tg, const rt_pre4 *p, int j)                      \
    {                                                                                         \
        return rt_walk_pre(w, RT_MODE_ANYTOP + O, tg, p, j) == RT_WALK_BLOCKED;               \
    }
RT_OCC_TOP(0)
RT_OCC_TOP(1)
RT_OCC_TOP(2)
RT_OCC_TOP(3)
RT_OCC_TOP(4)
RT_OCC_TOP(5)
#undef RT_OCC_TOP
typedef int (*rt_occ_top_fn)(rt_walkstate *w, const rt_topgrid *tg, const rt_pre4 *p, int j);
static const rt_occ_top_fn rt_occ_top[6] = {rt_occluded_top_0, rt_occluded_top_1,
                                            rt_occluded_top_2, rt_occluded_top_3,
                                            rt_occluded_top_4, rt_occluded_top_5};

/* rt_occluded_one of a ray that rt_occluded_mesh leaves to the one-ray code (the set-up's
   state 0, the batch's last rays), out of line in the build's own encoding, as
   rt_nearest_apart and for its reason */
static __attribute__((noinline)) unsigned char rt_occluded_apart(const rt_scene *sc, rt_ctx *c,
                                                                 const rt_ray *ray)
{
    return rt_occluded_one(sc, c, ray, NULL, NULL, 0, RT_ANY_MESH);
}

/* rt_occluded's rays in a scene of mesh triangles only (rt_mesh_only, so RT_ANY_MESH walks),
   in AVX2's encoding: the set-up's rays take the top walk of their axis order */
static __attribute__((noinline)) RT_ANYHIT_TARGET void
rt_occluded_mesh(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays,
                 unsigned char *occluded, const rt_setup *setup4)
{
    size_t k = 0;
    if (setup4) {
        rt_pre4 pp[2];
        const rt_topgrid tg = rt_topgrid_of(&sc->grid);
        while (k + 4 <= n) {
            const int m = rt_setup_next(setup4, &sc->grid, rays, k, n, pp);
            for (int h = 0; h < m; h++, k += 4) {
                const rt_pre4 *p = pp + h;
                for (int j = 0; j < 4; j++) {
                    unsigned char o = 0;
                    if (p->state[j] == 2) {
                        c->blocker = -1;
                        rt_rayx r;
                        rt_walkstate w;
                        rt_pre_ray(&r, &w.gr, p, j, rays + k + j);
                        rt_walkstate_init(&w, sc, c, &r, RT_ANY_MESH);
                        w.vnmask = ~sc->vmask;
                        rt_walk_flat_init(&w, sc, &r);
                        w.stamp = rt_ctx_next(c);
                        o = (unsigned char)rt_occ_top[p->ord[j]](&w, &tg, p, j);
                    } else if (p->state[j] == 0)
                        o = rt_occluded_apart(sc, c, rays + k + j);
                    occluded[k + j] = o;
                }
            }
        }
    }
    for (; k < n; k++)
        occluded[k] = rt_occluded_apart(sc, c, rays + k);
}

/* 1 where the batch API's walks take the cell lists of mesh triangles (rt_cell_mesh_k's
   copies per axis order): a grid over mesh triangles only and a CPU with AVX2 and BMI (the batch
   API's rays never skip a primitive) */
static int rt_mesh_only(const rt_scene *sc)
{
#ifdef RT_SETUP4_AVX2
    pthread_once(&rt_setup4_once, rt_setup4_pick);
    return rt_setup4_level >= 2 && rt_setup4_bmi && sc->use_grid && sc->ntri_plain == 0 &&
           sc->ntri == sc->nprim;
#else
    (void)sc;
    return 0;
#endif
}

/* the any-hit kind of rt_occluded's walks: RT_ANY_MESH where rt_mesh_only */
static int rt_anyhit_kind(const rt_scene *sc)
{
    return rt_mesh_only(sc) ? RT_ANY_MESH : RT_ANY_HIT;
}

void rt_occluded_rays(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays,
                      unsigned char *occluded)
{
    const rt_setup *setup4 = n >= 4 ? rt_setup4_choose(sc) : NULL;
    const int ah = rt_anyhit_kind(sc);
    if (ah == RT_ANY_MESH) {
        rt_occluded_mesh(sc, c, n, rays, occluded, setup4);
        return;
    }
    size_t k = 0;
    if (setup4) {
        const rt_topgrid tg = rt_topgrid_of(&sc->grid);
        rt_pre4 p[2];
        while (k + 4 <= n) {
            const int m = rt_setup_next(setup4, &sc->grid, rays, k, n, p);
            for (int h = 0; h < m; h++, k += 4)
                for (int j = 0; j < 4; j++)
                    occluded[k + j] = rt_occluded_one(sc, c, rays + k + j, &tg, p + h, j, ah);
        }
    }
    for (; k < n; k++)
        occluded[k] = rt_occluded_one(sc, c, rays + k, NULL, NULL, 0, ah);
}

int rt_occluded(const rt_scene *sc, size_t n, const rt_ray *rays, unsigned char *occluded)
{
    rt_ctx c;
    const int rc = rt_batch_begin(sc, n, rays, occluded, &c);
    if (rc != RT_OK)
        return rc;
    rt_occluded_rays(sc, &c, n, rays, occluded);
    rt_ctx_free(&c);
    return RT_OK;
}
