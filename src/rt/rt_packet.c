/* SPDX-License-Identifier: MIT */
/*
 * rt_packet.c -- the coherent path: packets of up to RT_PACKET rays (an 8 x 8 block of primary
 * rays, or shadow rays of neighbouring pixels toward one light) traced together through the
 * two-level grid by slices, as in coherent grid traversal (Wald, Ize, Kensler, Knoll, Parker
 * 2006, "Ray Tracing Animated Scenes using Coherent Grid Traversal").
 *
 * Walk: the rays of a packet share the axes of the exact test (kx, ky, kz: the dominant axis
 * of the direction and its sign) and the sign of every component of their directions in the
 * grid frame (rotated or not, rt_build.c), else the packet is not coherent and its rays take
 * the single-ray walk (rt_trace.c). The grid is walked slice by slice along the first ray's
 * dominant grid axis K in the rays' direction; in each slice the packet's footprint is the
 * rectangle of cells between the bounds of the frustum of its rays at the slice's two planes:
 * each ray crosses a plane z at x(z0) + (z - z0) m (z0 the first plane, m its slope), which
 * lies between the rays' least x(z0) plus (z - z0) times their least slope and the greatest
 * likewise (exact for rays from one point, as primary rays are), widened by 2^-20 of a cell
 * for the roundings (far below the eps by which the build enlarges every cell, rt_build.c).
 * A cell with a second-level grid is walked the same way, by the second level's slices. Each
 * primitive met is loaded once per packet and tested for the rays whose extent along K meets
 * the slice (an any-hit packet: for all its rays still walking, below) and that have not
 * tested it yet (the small mailbox, each entry with the rays it was tested for; an entry
 * taken by another primitive only repeats tests): a kernel tests 8 (AVX-512), 4 (AVX2) or
 * 2 (SSE2) rays at a time with the very operations of the exact double
 * test's edge functions (rt_isect_tri, rt_prim.h), so its signs are that test's bit for bit
 * (no FMA: the kernels are built for AVX2 without FMA, and the build has no -march), and only
 * rules out rays whose signs are mixed and non-zero; the exact test decides every other ray.
 * Before it, a triangle beyond one of the bounds of the packet's frustum is skipped, and with
 * AVX2 the kernel runs only the 4-ray steps whose own frusta it may meet (rt_pk_steps).
 * An any-hit packet's AVX2 kernel also takes the exact test's t and range test for the rays
 * whose edge functions are non-zero with one sign, with its operations: it decides those rays
 * itself (a shadow ray's own surface, crossed behind its origin, is ruled out there). So an
 * any-hit packet tests a primitive once for all its rays still walking, the rays whose
 * extent has not reached the slice yet too (shadow rays start at different depths; a test
 * only finds hits within a ray's range, whatever the cell, and occluded does not depend on
 * the order of tests): else the primitive, which spans several slices, was tested again as
 * those rays reached it (armadillo's shadow packets at 1024^2: 23 % of the tests), and its
 * second-level slices are walked between the packet's first start and last end without the
 * rays' extents one by one.
 * A packet whose footprint in one slice exceeds RT_PK_MAXC top cells (RT_PK_MAXCA for an
 * any-hit packet; or RT_PK_MAXS second-level cells) is handed to the single-ray walk as a
 * whole, and so is an any-hit packet whose frustum is RT_PK_SPREAD cells wide or more, or
 * covers RT_PK_AREA cells or more (RT_PK_AREAT top cells or more where the start's middle
 * top cell has no second level), in the grid where its walk starts (rt_pk_spread); an
 * any-hit packet's rays of other axes or another octant than its first ray walked are
 * traced singly, the others stay a packet.
 *
 * Same hits as the single-ray walk: every primitive is tested on the whole range
 * [tmin, tmax] of each ray, so a ray's computed hits are those of the exact test, each t bit
 * for bit. A ray stops walking at the first slice beyond its best hit plus 4 times that hit's
 * error bound (rt_nearest_update), so every hit within its tie window is found (a new best
 * hit whose window reaches further than the one before sends the ray to the single-ray walk:
 * cells up to the new end may have been passed over for it). The
 * single-ray walk picks its hit by rt_nearest_update in the order of its cells, the packet in
 * another order; the tie rule is not transitive in general (docs/RAYTRACING.md, "Coplanar
 * surfaces"), so the packet's hit W is kept only when it wins the rule against every other
 * hit X it found, in both roles (W as the new hit against best X, and X against best W):
 * then every order of tests ends with W (W is accepted whenever it is tested, and nothing
 * after it displaces it), and the hits not found lie beyond W's window and lose to it. A ray
 * whose check fails, or that found more than RT_PK_REC hits, is traced again by the
 * single-ray walk. Any-hit rays need no such check: occluded is "some primitive is hit in the
 * range", whatever the order.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_packet.h"
#include "rt_prim.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define RT_PK_X86 1
#endif

#define RT_PK_REC 8      /* hits recorded per ray (more: the ray is traced singly) */
#define RT_PK_MAXC 12    /* top cells per slice at most (16 before the steps' frusta) */
#define RT_PK_MAXCA 10   /* any-hit: top cells per slice at most (with RT_PK_SPREAD) */
#define RT_PK_MAXS 64    /* second-level cells per slice at most */
#define RT_PK_SPREAD 16.0 /* any-hit: the frustum's width at the start, in cells, below */
#define RT_PK_AREA 48.0  /* any-hit: (width + 1) (height + 1) there, in cells, below */
#define RT_PK_AREAT 3.0  /* ... in top cells, if the start's middle top cell has no sub-grid */
#define RT_PK_MARGIN 0x1p-20 /* of a cell: the crossings' roundings */

typedef struct rt_pk_rec {
    uint32_t i;
    double t;
} rt_pk_rec;

typedef struct rt_pk {
    const rt_scene *sc;
    int n, any;
    int K, a1, a2;           /* the slicing axis and the two others */
    int sg;                  /* step along K: +1 or -1 */
    uint64_t live;           /* rays still walking */
    uint64_t hit;            /* rays that hit (any: occluded; nearest: a hit recorded) */
    uint64_t over;           /* nearest: rays with more than RT_PK_REC hits */
    uint64_t cand;           /* rays in the current slice: they test what it holds */
    uint64_t *hbox;          /* the packet's mailbox (the context's small one) ... */
    uint64_t key;
    uint64_t tmask[RT_HBOX]; /* ... and the rays each entry's primitive was tested for */
    /* each ray's extent along K times sg (u = sg z): from its start to the end of its walk
       (the box exit, or its best hit plus 4 error bounds) */
    double us[RT_PACKET], ue[RT_PACKET];
    double umg;              /* margin: 2^-20 of a top cell along K */
    double t1[RT_PACKET];    /* the end of the part in the grid box */
    double best[RT_PACKET], eb[RT_PACKET];
    long bi[RT_PACKET];
    uint8_t nh[RT_PACKET];
    /* ray k's j-th hit in rec[j][k]: the first hits of a packet's rays on 16 lines, not 64 */
    rt_pk_rec rec[RT_PK_REC][RT_PACKET];
    /* each ray's line: o[a1] + (z - o[K]) * m1, o[a2] + (z - o[K]) * m2 at z along K */
    double oK[RT_PACKET], o1[RT_PACKET], o2[RT_PACKET], m1[RT_PACKET], m2[RT_PACKET];
    double dK[RT_PACKET];    /* each ray's direction along K (rt_pk_hit's end of its walk) */
    double nf[2][3];         /* the grid box's near and far plane per axis (rt_pk_clip) */
    /* the frustum of the rays of fmask: their crossings of z = z0 within [lo, hi] and their
       slopes within [mlo, mhi], per axis a1 (index 0) and a2 (1) */
    uint64_t fmask;
    double z0, lo[2], hi[2], mlo[2], mhi[2];
    double xmg[2];           /* margins along a1, a2: 2^-20 of a top cell */
    /* the frustum's bounds in the lanes of rt_pk_outside_avx2 (set by rt_pk_frustum_avx2):
       lo[0], -hi[0], lo[1], -hi[1]; their slopes for z >= z0 and z < z0; the margins */
    double ob[4], osp[4], osn[4], omg[4];
    /* and in rt_pk_rect_avx2's: lo[0], hi[0], lo[1], hi[1] and their slopes likewise */
    double rb[4], rsp[4], rsn[4];
    /* any-hit packets in a grid with flat sub-grids: ray k's segment values for their
       planes' test (rt_flatseg), made at its first flat sub-grid, for the rays of fsok */
    uint64_t fsok;
    rt_flatseg fs[RT_PACKET];
    /* the frusta of the kernel's steps (rays 4s .. 4s+3, AVX2 only; rt_pk_steps): for
       bound b (lo[0], -hi[0], lo[1], -hi[1] as ob) and step s, the bound at z0 less the
       margin and its slopes for z >= z0 and z < z0; made once per packet at z0 from the rays
       walked then (a superset of the rays of any later mask: still bounds) */
    double stb[4][RT_PACKET / 4], stp[4][RT_PACKET / 4], stn[4][RT_PACKET / 4];
    int steps;               /* stb, stp, stn are made: the cull takes its steps' test */
    int sax;                 /* ... along a1 (0) or a2 (1): where the steps are narrower
                                against the packet */
    /* the cull kernel's inputs in the rays' common axis order kx, ky, kz */
    double ox[RT_PACKET], oy[RT_PACKET], oz[RT_PACKET], sx[RT_PACKET], sy[RT_PACKET];
    /* and the exact test's sz, tmin, tmax (the AVX2 kernel's range test) */
    double sz[RT_PACKET], tn[RT_PACKET], tx[RT_PACKET];
    int kx, ky, kz;
    double uemin, usmax;     /* min of ue, max of us over the rays (fast paths of rt_pk_in) */
    double usmin, uemax;     /* the first start and the last end of the rays (rt_pk_ends) */
    const double *go[RT_PACKET], *gd[RT_PACKET]; /* the rays in the grid frame (the general
                                                    set-up's): the rt_rayx's own, or in rot */
    double rot[RT_PACKET][2][3];
    rt_rayx *r;              /* the rays as the tests take them (the caller's storage) */
    const rt_ray *rays;      /* the rays as given */
    uint64_t alone;          /* any-hit: rays left to the single-ray walk by the set-up (not
                                of the packet's axes and octant) */
    uint64_t made;           /* rays whose r[k] is made (rt_pk_make; all but after
                                rt_pk_setup_avx2, which leaves them to the first exact test) */
    int beside;              /* every ray found beside the grid box (rt_pk_beside) */
} rt_pk;

/* ---- the cull kernels: rays of mask whose edge functions may not be mixed ---- */

typedef uint64_t (*rt_pk_cull_fn)(const rt_pk *p, const double *v0, const double *v1,
                                  const double *v2, uint64_t mask);

/* 1 unless the exact test's edge functions (the same operations) are non-zero and mixed */
static inline int rt_pk_lane(const rt_pk *p, int k, const double *v0, const double *v1,
                             const double *v2)
{
    const int kx = p->kx, ky = p->ky, kz = p->kz;
    const double ox = p->ox[k], oy = p->oy[k], oz = p->oz[k], sx = p->sx[k], sy = p->sy[k];
    const double Az = v0[kz] - oz, Bz = v1[kz] - oz, Cz = v2[kz] - oz;
    const double Ax = (v0[kx] - ox) - sx * Az, Ay = (v0[ky] - oy) - sy * Az;
    const double Bx = (v1[kx] - ox) - sx * Bz, By = (v1[ky] - oy) - sy * Bz;
    const double Cx = (v2[kx] - ox) - sx * Cz, Cy = (v2[ky] - oy) - sy * Cz;
    const double U = Cx * By - Cy * Bx, V = Ax * Cy - Ay * Cx, W = Bx * Ay - By * Ax;
    const int zero = (U == 0.0) | (V == 0.0) | (W == 0.0);
    const int mixed = ((U < 0.0) | (V < 0.0) | (W < 0.0)) & ((U > 0.0) | (V > 0.0) | (W > 0.0));
    return zero | !mixed;
}

static uint64_t rt_pk_cull_scalar(const rt_pk *p, const double *v0, const double *v1,
                                  const double *v2, uint64_t mask)
{
    uint64_t out = 0;
    for (uint64_t m = mask; m; m &= m - 1) {
        const int k = __builtin_ctzll(m);
        if (rt_pk_lane(p, k, v0, v1, v2))
            out |= (uint64_t)1 << k;
    }
    return out;
}

#ifdef RT_PK_X86
/* SSE2: 2 rays at a time */
static uint64_t rt_pk_cull_sse(const rt_pk *p, const double *v0, const double *v1,
                               const double *v2, uint64_t mask)
{
    const int kx = p->kx, ky = p->ky, kz = p->kz;
    const __m128d ax = _mm_set1_pd(v0[kx]), ay = _mm_set1_pd(v0[ky]), az = _mm_set1_pd(v0[kz]);
    const __m128d bx = _mm_set1_pd(v1[kx]), by = _mm_set1_pd(v1[ky]), bz = _mm_set1_pd(v1[kz]);
    const __m128d cx = _mm_set1_pd(v2[kx]), cy = _mm_set1_pd(v2[ky]), cz = _mm_set1_pd(v2[kz]);
    const __m128d z = _mm_setzero_pd();
    uint64_t out = 0;
    for (int k = 0; k < p->n; k += 2) {
        if (!((mask >> k) & 3u))
            continue;
        const __m128d ox = _mm_loadu_pd(p->ox + k), oy = _mm_loadu_pd(p->oy + k),
                      oz = _mm_loadu_pd(p->oz + k), sx = _mm_loadu_pd(p->sx + k),
                      sy = _mm_loadu_pd(p->sy + k);
        const __m128d Az = _mm_sub_pd(az, oz), Bz = _mm_sub_pd(bz, oz), Cz = _mm_sub_pd(cz, oz);
        const __m128d Ax = _mm_sub_pd(_mm_sub_pd(ax, ox), _mm_mul_pd(sx, Az));
        const __m128d Ay = _mm_sub_pd(_mm_sub_pd(ay, oy), _mm_mul_pd(sy, Az));
        const __m128d Bx = _mm_sub_pd(_mm_sub_pd(bx, ox), _mm_mul_pd(sx, Bz));
        const __m128d By = _mm_sub_pd(_mm_sub_pd(by, oy), _mm_mul_pd(sy, Bz));
        const __m128d Cx = _mm_sub_pd(_mm_sub_pd(cx, ox), _mm_mul_pd(sx, Cz));
        const __m128d Cy = _mm_sub_pd(_mm_sub_pd(cy, oy), _mm_mul_pd(sy, Cz));
        const __m128d U = _mm_sub_pd(_mm_mul_pd(Cx, By), _mm_mul_pd(Cy, Bx));
        const __m128d V = _mm_sub_pd(_mm_mul_pd(Ax, Cy), _mm_mul_pd(Ay, Cx));
        const __m128d W = _mm_sub_pd(_mm_mul_pd(Bx, Ay), _mm_mul_pd(By, Ax));
        const __m128d zero = _mm_or_pd(_mm_or_pd(_mm_cmpeq_pd(U, z), _mm_cmpeq_pd(V, z)),
                                       _mm_cmpeq_pd(W, z));
        const __m128d neg = _mm_or_pd(_mm_or_pd(_mm_cmplt_pd(U, z), _mm_cmplt_pd(V, z)),
                                      _mm_cmplt_pd(W, z));
        const __m128d pos = _mm_or_pd(_mm_or_pd(_mm_cmpgt_pd(U, z), _mm_cmpgt_pd(V, z)),
                                      _mm_cmpgt_pd(W, z));
        const __m128d keep = _mm_or_pd(zero, _mm_andnot_pd(_mm_and_pd(neg, pos), _mm_cmpeq_pd(z, z)));
        out |= (uint64_t)_mm_movemask_pd(keep) << k;
    }
    return out & mask;
}

/* the lanes of mask as an AVX2 mask of four doubles, lanes k .. k+3 */
__attribute__((target("avx2"))) static inline __m256d rt_pk_lanes(uint64_t mask, int k)
{
    const __m256i bit = _mm256_set_epi64x(8, 4, 2, 1);
    const __m256i m = _mm256_set1_epi64x((long long)((mask >> k) & 15u));
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(_mm256_and_si256(m, bit), bit));
}

/* AVX2 (no FMA): 4 rays at a time. any: an any-hit packet's kernel, which also decides the
   rays whose edge functions are non-zero with one sign: their t by the exact test's
   operations, a hit within its range (*sure), no hit outside (ruled out) */
static inline __attribute__((target("avx2"), always_inline)) uint64_t
rt_pk_cull_avx2_body(const rt_pk *p, const double *v0, const double *v1, const double *v2,
                     uint64_t mask, const int any, uint64_t *sure)
{
    const int kx = p->kx, ky = p->ky, kz = p->kz;
    const __m256d ax = _mm256_set1_pd(v0[kx]), ay = _mm256_set1_pd(v0[ky]), az = _mm256_set1_pd(v0[kz]);
    const __m256d bx = _mm256_set1_pd(v1[kx]), by = _mm256_set1_pd(v1[ky]), bz = _mm256_set1_pd(v1[kz]);
    const __m256d cx = _mm256_set1_pd(v2[kx]), cy = _mm256_set1_pd(v2[ky]), cz = _mm256_set1_pd(v2[kz]);
    const __m256d z = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    uint64_t out = 0, hit = 0;
    /* the steps with a ray of mask: bit 4s set for step s (no branch per step: the steps'
       test leaves sparse masks) */
    uint64_t st = mask | mask >> 1;
    st = (st | st >> 2) & UINT64_C(0x1111111111111111);
    for (; st; st &= st - 1) {
        const int k = __builtin_ctzll(st);
        const __m256d ox = _mm256_loadu_pd(p->ox + k), oy = _mm256_loadu_pd(p->oy + k),
                      oz = _mm256_loadu_pd(p->oz + k), sx = _mm256_loadu_pd(p->sx + k),
                      sy = _mm256_loadu_pd(p->sy + k);
        const __m256d Az = _mm256_sub_pd(az, oz), Bz = _mm256_sub_pd(bz, oz),
                      Cz = _mm256_sub_pd(cz, oz);
        const __m256d Ax = _mm256_sub_pd(_mm256_sub_pd(ax, ox), _mm256_mul_pd(sx, Az));
        const __m256d Ay = _mm256_sub_pd(_mm256_sub_pd(ay, oy), _mm256_mul_pd(sy, Az));
        const __m256d Bx = _mm256_sub_pd(_mm256_sub_pd(bx, ox), _mm256_mul_pd(sx, Bz));
        const __m256d By = _mm256_sub_pd(_mm256_sub_pd(by, oy), _mm256_mul_pd(sy, Bz));
        const __m256d Cx = _mm256_sub_pd(_mm256_sub_pd(cx, ox), _mm256_mul_pd(sx, Cz));
        const __m256d Cy = _mm256_sub_pd(_mm256_sub_pd(cy, oy), _mm256_mul_pd(sy, Cz));
        const __m256d U = _mm256_sub_pd(_mm256_mul_pd(Cx, By), _mm256_mul_pd(Cy, Bx));
        const __m256d V = _mm256_sub_pd(_mm256_mul_pd(Ax, Cy), _mm256_mul_pd(Ay, Cx));
        const __m256d W = _mm256_sub_pd(_mm256_mul_pd(Bx, Ay), _mm256_mul_pd(By, Ax));
        /* kept: a lane with a zero (or NaN: the exact test decides it) edge function, or
           whose three sign bits agree. Without zeros and NaNs the sign bits are the signs,
           so the lanes ruled out are exactly rt_pk_lane's "non-zero and mixed"; a NaN lane
           is kept where rt_pk_lane's ordered compares might rule it out, which only leaves
           one more ray to the exact test (its own ordered compares decide it the same). */
        const __m256d zero = _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(U, z, _CMP_EQ_UQ),
                                                       _mm256_cmp_pd(V, z, _CMP_EQ_UQ)),
                                          _mm256_cmp_pd(W, z, _CMP_EQ_UQ));
        const unsigned differ = (unsigned)_mm256_movemask_pd(
            _mm256_or_pd(_mm256_xor_pd(U, V), _mm256_xor_pd(U, W)));
        const unsigned zb = (unsigned)_mm256_movemask_pd(zero);
        unsigned keep = zb;
        if (!any)
            keep |= ~differ & 15u;
        else if (~differ & ~zb & 15u) {
            /* the rays of mask whose three edge functions are non-zero with one sign (the
               exact test passes its edge test for them): the exact test's det = U + V + W,
               T and t = T / det with its operations, and its range test. The other lanes take
               harmless values first (U = V = W = 1, Az = Bz = Cz = sz = 0), so no operation
               is made that the exact test would not make on its own rays. A ray within
               [tmin, tmax] is a hit of the exact test (its t these bits), one outside is not. */
            const __m256d dm = _mm256_castsi256_pd(_mm256_cmpgt_epi64(
                _mm256_setzero_si256(),
                _mm256_castpd_si256(_mm256_or_pd(_mm256_xor_pd(U, V), _mm256_xor_pd(U, W)))));
            const __m256d ss = _mm256_andnot_pd(_mm256_or_pd(dm, zero), rt_pk_lanes(mask, k));
            const __m256d u = _mm256_blendv_pd(one, U, ss), vv = _mm256_blendv_pd(one, V, ss),
                          w = _mm256_blendv_pd(one, W, ss);
            const __m256d sz = _mm256_and_pd(ss, _mm256_loadu_pd(p->sz + k));
            const __m256d az = _mm256_and_pd(ss, Az), bz2 = _mm256_and_pd(ss, Bz),
                          cz2 = _mm256_and_pd(ss, Cz);
            const __m256d det = _mm256_add_pd(_mm256_add_pd(u, vv), w);
            const __m256d T = _mm256_add_pd(
                _mm256_add_pd(_mm256_mul_pd(u, _mm256_mul_pd(sz, az)),
                              _mm256_mul_pd(vv, _mm256_mul_pd(sz, bz2))),
                _mm256_mul_pd(w, _mm256_mul_pd(sz, cz2)));
            const __m256d t = _mm256_div_pd(T, det);
            const __m256d tin = _mm256_and_pd(
                _mm256_cmp_pd(t, _mm256_and_pd(ss, _mm256_loadu_pd(p->tn + k)), _CMP_GE_OQ),
                _mm256_cmp_pd(t, _mm256_and_pd(ss, _mm256_loadu_pd(p->tx + k)), _CMP_LE_OQ));
            const unsigned h = (unsigned)_mm256_movemask_pd(_mm256_and_pd(ss, tin));
            keep |= h;
            hit |= (uint64_t)h << k;
        }
        out |= (uint64_t)keep << k;
    }
    *sure = hit & mask;
    return out & mask;
}

__attribute__((target("avx2"))) static uint64_t rt_pk_cull_avx2(const rt_pk *p, const double *v0,
                                                                const double *v1,
                                                                const double *v2, uint64_t mask)
{
    uint64_t sure;
    return rt_pk_cull_avx2_body(p, v0, v1, v2, mask, 0, &sure);
}

/* the any-hit kernel: the rays to give the exact test; the hits it found in *sure */
__attribute__((target("avx2"))) static uint64_t rt_pk_cull_any_avx2(const rt_pk *p,
                                                                    const double *v0,
                                                                    const double *v1,
                                                                    const double *v2,
                                                                    uint64_t mask, uint64_t *sure)
{
    return rt_pk_cull_avx2_body(p, v0, v1, v2, mask, 1, sure);
}

/* AVX-512 (F, VL, DQ; no FMA): the AVX2 kernel's operations on 8 rays at a time, in mask
   registers. The lanes of rays not in mask are loaded as 0 (masked loads: harmless values,
   never in the result). */
#define RT_PK_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq")))
static inline RT_PK_AVX512 __attribute__((always_inline)) uint64_t
rt_pk_cull_avx512_body(const rt_pk *p, const double *v0, const double *v1, const double *v2,
                       uint64_t mask, const int any, uint64_t *sure)
{
    const int kx = p->kx, ky = p->ky, kz = p->kz;
    const __m512d ax = _mm512_set1_pd(v0[kx]), ay = _mm512_set1_pd(v0[ky]), az = _mm512_set1_pd(v0[kz]);
    const __m512d bx = _mm512_set1_pd(v1[kx]), by = _mm512_set1_pd(v1[ky]), bz = _mm512_set1_pd(v1[kz]);
    const __m512d cx = _mm512_set1_pd(v2[kx]), cy = _mm512_set1_pd(v2[ky]), cz = _mm512_set1_pd(v2[kz]);
    const __m512d z = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    uint64_t out = 0, hit = 0;
    /* the 8-ray steps with a ray of mask: bit 8s set for step s */
    uint64_t st = mask | mask >> 1;
    st |= st >> 2;
    st = (st | st >> 4) & UINT64_C(0x0101010101010101);
    for (; st; st &= st - 1) {
        const int k = __builtin_ctzll(st);
        const __mmask8 lm = (__mmask8)(mask >> k);
        const __m512d ox = _mm512_maskz_loadu_pd(lm, p->ox + k),
                      oy = _mm512_maskz_loadu_pd(lm, p->oy + k),
                      oz = _mm512_maskz_loadu_pd(lm, p->oz + k),
                      sx = _mm512_maskz_loadu_pd(lm, p->sx + k),
                      sy = _mm512_maskz_loadu_pd(lm, p->sy + k);
        const __m512d Az = _mm512_sub_pd(az, oz), Bz = _mm512_sub_pd(bz, oz),
                      Cz = _mm512_sub_pd(cz, oz);
        const __m512d Ax = _mm512_sub_pd(_mm512_sub_pd(ax, ox), _mm512_mul_pd(sx, Az));
        const __m512d Ay = _mm512_sub_pd(_mm512_sub_pd(ay, oy), _mm512_mul_pd(sy, Az));
        const __m512d Bx = _mm512_sub_pd(_mm512_sub_pd(bx, ox), _mm512_mul_pd(sx, Bz));
        const __m512d By = _mm512_sub_pd(_mm512_sub_pd(by, oy), _mm512_mul_pd(sy, Bz));
        const __m512d Cx = _mm512_sub_pd(_mm512_sub_pd(cx, ox), _mm512_mul_pd(sx, Cz));
        const __m512d Cy = _mm512_sub_pd(_mm512_sub_pd(cy, oy), _mm512_mul_pd(sy, Cz));
        const __m512d U = _mm512_sub_pd(_mm512_mul_pd(Cx, By), _mm512_mul_pd(Cy, Bx));
        const __m512d V = _mm512_sub_pd(_mm512_mul_pd(Ax, Cy), _mm512_mul_pd(Ay, Cx));
        const __m512d W = _mm512_sub_pd(_mm512_mul_pd(Bx, Ay), _mm512_mul_pd(By, Ax));
        /* kept: as the AVX2 kernel (a zero or NaN edge function, or three equal sign bits) */
        const __mmask8 zb = _mm512_cmp_pd_mask(U, z, _CMP_EQ_UQ) |
                            _mm512_cmp_pd_mask(V, z, _CMP_EQ_UQ) |
                            _mm512_cmp_pd_mask(W, z, _CMP_EQ_UQ);
        const __mmask8 differ = _mm512_movepi64_mask(_mm512_castpd_si512(
            _mm512_or_pd(_mm512_xor_pd(U, V), _mm512_xor_pd(U, W))));
        unsigned keep = zb;
        if (!any)
            keep |= (unsigned)(__mmask8)~differ;
        else {
            /* the rays of mask whose edge functions are non-zero with one sign: the exact
               test's det, T, t and range test, as the AVX2 kernel (other lanes: U = V = W =
               1, Az = Bz = Cz = sz = 0, harmless) */
            const __mmask8 ss = (__mmask8)(~differ & ~zb & lm);
            if (ss) {
                const __m512d u = _mm512_mask_blend_pd(ss, one, U),
                              vv = _mm512_mask_blend_pd(ss, one, V),
                              w = _mm512_mask_blend_pd(ss, one, W);
                const __m512d sz = _mm512_maskz_loadu_pd(ss, p->sz + k);
                const __m512d az2 = _mm512_maskz_mov_pd(ss, Az), bz2 = _mm512_maskz_mov_pd(ss, Bz),
                              cz2 = _mm512_maskz_mov_pd(ss, Cz);
                const __m512d det = _mm512_add_pd(_mm512_add_pd(u, vv), w);
                const __m512d T = _mm512_add_pd(
                    _mm512_add_pd(_mm512_mul_pd(u, _mm512_mul_pd(sz, az2)),
                                  _mm512_mul_pd(vv, _mm512_mul_pd(sz, bz2))),
                    _mm512_mul_pd(w, _mm512_mul_pd(sz, cz2)));
                const __m512d t = _mm512_div_pd(T, det);
                const __mmask8 h =
                    _mm512_mask_cmp_pd_mask(ss, t, _mm512_maskz_loadu_pd(ss, p->tn + k), _CMP_GE_OQ) &
                    _mm512_mask_cmp_pd_mask(ss, t, _mm512_maskz_loadu_pd(ss, p->tx + k), _CMP_LE_OQ);
                keep |= h;
                hit |= (uint64_t)h << k;
            }
        }
        out |= (uint64_t)(keep & 0xffu) << k;
    }
    *sure = hit & mask;
    return out & mask;
}

RT_PK_AVX512 static uint64_t rt_pk_cull_avx512(const rt_pk *p, const double *v0,
                                                const double *v1, const double *v2,
                                                uint64_t mask)
{
    uint64_t sure;
    return rt_pk_cull_avx512_body(p, v0, v1, v2, mask, 0, &sure);
}

/* the any-hit kernel: the rays to give the exact test; the hits it found in *sure */
RT_PK_AVX512 static uint64_t rt_pk_cull_any_avx512(const rt_pk *p, const double *v0,
                                                    const double *v1, const double *v2,
                                                    uint64_t mask, uint64_t *sure)
{
    return rt_pk_cull_avx512_body(p, v0, v1, v2, mask, 1, sure);
}
#endif

/* the kernel for this CPU, or the one GKS_RT_SIMD forces (rt_simd_level, as the leaves) */
static rt_pk_cull_fn rt_pk_kernel(const char **name)
{
    const int level = rt_simd_level();
#ifdef RT_PK_X86
    if (level >= 3) {
        *name = "avx512";
        return rt_pk_cull_avx512;
    }
    if (level >= 2) {
        *name = "avx2";
        return rt_pk_cull_avx2;
    }
    if (level >= 1) {
        *name = "sse";
        return rt_pk_cull_sse;
    }
#endif
    *name = "scalar";
    return rt_pk_cull_scalar;
}

const char *rt_packet_kernel_name(void)
{
    const char *name;
    (void)rt_pk_kernel(&name);
    return name;
}

static rt_pk_cull_fn rt_pk_cull;
static pthread_once_t rt_pk_once = PTHREAD_ONCE_INIT;
static const char *rt_pk_cull_name;
static int rt_pk_avx2;   /* the AVX2 or AVX-512 kernel was chosen: the set-up's box test,
                            the frustum's and the steps' are AVX2 (or AVX-512) too */
static int rt_pk_avx512; /* the AVX-512 kernel was chosen (rt_simd_level() >= 3) */
static void rt_pk_choose(void)
{
    rt_pk_cull = rt_pk_kernel(&rt_pk_cull_name);
    rt_pk_avx512 = !strcmp(rt_pk_cull_name, "avx512");
    rt_pk_avx2 = rt_pk_avx512 || !strcmp(rt_pk_cull_name, "avx2");
}

/* ---- set-up ---- */

/* point p in a rotated grid's frame: rt_grid_point's operations (rt_build.c), the same
   values, inline here (three calls per triangle tested were 7 % of fandisk's primary
   packets' instructions) */
static inline void rt_pk_gpoint(const rt_grid *g, const double p[3], double out[3])
{
    const double q[3] = {p[0] - g->c[0], p[1] - g->c[1], p[2] - g->c[2]};
    for (int a = 0; a < 3; a++)
        out[a] = g->R[a][0] * q[0] + g->R[a][1] * q[1] + g->R[a][2] * q[2];
}

/* the cell of coordinate x along axis a of box g, lowered (dir -1) or raised (+1) by the
   margin, clamped into the box */
static inline int rt_pk_cell(const rt_box *g, int a, double x, double dir)
{
    const double f = (x - g->lo[a]) * g->inv_cw[a] + dir * RT_PK_MARGIN;
    return f <= 0.0 ? 0 : (f >= (double)(g->n[a] - 1) ? g->n[a] - 1 : (int)f);
}

/* ray k's extent along K from its range [t0, t1] in the grid box: 0 if nothing is left */
static inline int rt_pk_range(rt_pk *p, int k, double t0, double t1)
{
    const double *o = p->go[k], *d = p->gd[k];
    if (!(t0 <= t1) || !isfinite(t0))
        return 0;
    p->t1[k] = t1;
    p->us[k] = p->sg * (o[p->K] + t0 * d[p->K]);
    p->ue[k] = p->sg * (o[p->K] + t1 * d[p->K]);
    return 1;
}

/* ray k's range cut to the grid box (as rt_dda_init clips): 0 if nothing is left. The
   packet's octant gives each axis's near and far plane (nf: the box's lo and hi, swapped for a
   negative component), so the slab's entry is (near - o) / d without a comparison, the same
   value as the min of the two. */
static int rt_pk_clip(rt_pk *p, int k)
{
    const double *o = p->go[k], *d = p->gd[k];
    const double i0 = 1.0 / d[0], i1 = 1.0 / d[1], i2 = 1.0 / d[2];
    const double n0 = (p->nf[0][0] - o[0]) * i0, f0 = (p->nf[1][0] - o[0]) * i0;
    const double n1 = (p->nf[0][1] - o[1]) * i1, f1 = (p->nf[1][1] - o[1]) * i1;
    const double n2 = (p->nf[0][2] - o[2]) * i2, f2 = (p->nf[1][2] - o[2]) * i2;
    double t0 = p->r[k].tmin, t1 = p->r[k].tmax;
    t0 = n0 > t0 ? n0 : t0;
    t0 = n1 > t0 ? n1 : t0;
    t0 = n2 > t0 ? n2 : t0;
    t1 = f0 < t1 ? f0 : t1;
    t1 = f1 < t1 ? f1 : t1;
    t1 = f2 < t1 ? f2 : t1;
    return rt_pk_range(p, k, t0, t1);
}

/* ray q (as given) against the grid box b of a grid that is not rotated: 1 and its range
   t[0..1] in the box (t[0] > t[1]: it misses the box), or 0 if not judged here: rays with a
   non-finite value or a component below 1e-250 (no operation below may raise an exception;
   the tests trap them), which rt_rayx_setup or the packet's octant rejects. A ray that misses
   the box is a miss on the single-ray walk too (every primitive lies inside the box, by the
   build's eps; rt_rayx_setup flushes only components below 1e-150 of the largest, which turn
   no miss of the box into a hit of a primitive), and needs neither rt_rayx_setup nor the
   packet's per-ray data; for a ray walked, whose components are then all kept, the range is
   the one rt_pk_clip computes, bit for bit (the entry and exit of each slab are the min and
   max of the same two products). */
static inline int rt_pk_tbox(const rt_box *b, const rt_ray *q, double t[2])
{
    const double *o = q->org, *d = q->dir;
    if (!(isfinite(o[0]) & isfinite(o[1]) & isfinite(o[2]) & isfinite(d[0]) & isfinite(d[1]) &
          isfinite(d[2]) & isfinite(q->tmin) & !isnan(q->tmax)))
        return 0;
    if (!((fabs(d[0]) >= 1e-250) & (fabs(d[1]) >= 1e-250) & (fabs(d[2]) >= 1e-250)))
        return 0;
    double t0 = q->tmin, t1 = q->tmax;
    for (int a = 0; a < 3; a++) {
        const double inv = 1.0 / d[a];
        const double ta = (b->lo[a] - o[a]) * inv, tb = (b->hi[a] - o[a]) * inv;
        const double tn = ta < tb ? ta : tb, tf = ta < tb ? tb : ta;
        t0 = tn > t0 ? tn : t0;
        t1 = tf < t1 ? tf : t1;
    }
    t[0] = t0;
    t[1] = t1;
    return 1;
}

#ifdef RT_PK_X86
/* rt_pk_tbox for the four rays q[0..3] at once (AVX2, no FMA): the same operations in each
   lane, so the same ranges bit for bit. The checks are made on the bits (integer compares:
   no floating operation on a non-finite value), and the lanes of rays not judged get the
   harmless values o = 0, d = 1 before any floating operation. Returns the judged rays (bit j:
   ray j), their ranges in t0[0..3], t1[0..3]. */
static inline __attribute__((target("avx2"), always_inline)) unsigned
rt_pk_tbox4_body(const rt_grid *g, const int rotated, const rt_ray *q, double *t0, double *t1)
{
    const rt_box *b = &g->b;
    __m256d x[4], y[4]; /* per ray: org[0..2], dir[0]; dir[1..2], tmin, tmax */
    for (int j = 0; j < 4; j++) {
        x[j] = _mm256_loadu_pd(q[j].org);
        y[j] = _mm256_loadu_pd(q[j].dir + 1);
    }
    /* 4 x 4 transposes: v[0..7] = o0, o1, o2, d0, d1, d2, tmin, tmax of the four rays */
    __m256d v[8];
    for (int h = 0; h < 2; h++) {
        const __m256d *w = h ? y : x;
        const __m256d l01 = _mm256_unpacklo_pd(w[0], w[1]), h01 = _mm256_unpackhi_pd(w[0], w[1]);
        const __m256d l23 = _mm256_unpacklo_pd(w[2], w[3]), h23 = _mm256_unpackhi_pd(w[2], w[3]);
        v[4 * h + 0] = _mm256_permute2f128_pd(l01, l23, 0x20);
        v[4 * h + 1] = _mm256_permute2f128_pd(h01, h23, 0x20);
        v[4 * h + 2] = _mm256_permute2f128_pd(l01, l23, 0x31);
        v[4 * h + 3] = _mm256_permute2f128_pd(h01, h23, 0x31);
    }
    const __m256i absm = _mm256_set1_epi64x(INT64_MAX);
    const __m256i inf = _mm256_set1_epi64x(INT64_C(0x7ff0000000000000));
    double lim = 1e-250;
    int64_t blim;
    memcpy(&blim, &lim, sizeof blim);
    const __m256i small = _mm256_set1_epi64x(blim);
    __m256i ok = _mm256_cmpeq_epi64(absm, absm);
    for (int c = 0; c < 7; c++) { /* finite: |bits| < inf's */
        const __m256i a = _mm256_and_si256(_mm256_castpd_si256(v[c]), absm);
        ok = _mm256_and_si256(ok, _mm256_cmpgt_epi64(inf, a));
        if (c >= 3 && c < 6) /* direction components of at least 1e-250 */
            ok = _mm256_andnot_si256(_mm256_cmpgt_epi64(small, a), ok);
    }
    ok = _mm256_andnot_si256( /* tmax not NaN */
        _mm256_cmpgt_epi64(_mm256_and_si256(_mm256_castpd_si256(v[7]), absm), inf), ok);
    __m256d okd = _mm256_castsi256_pd(ok);
    const __m256d one = _mm256_set1_pd(1.0);
    if (rotated) { /* into the grid frame as rt_grid_point, rt_grid_dir (finite inputs
                         only), and the checks again on the results */
        __m256d q3[3], w[6];
        for (int a = 0; a < 3; a++)
            q3[a] = _mm256_sub_pd(_mm256_and_pd(okd, v[a]), _mm256_set1_pd(g->c[a]));
        for (int a = 0; a < 3; a++) {
            const __m256d r0 = _mm256_set1_pd(g->R[a][0]), r1 = _mm256_set1_pd(g->R[a][1]),
                          r2 = _mm256_set1_pd(g->R[a][2]);
            w[a] = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, q3[0]), _mm256_mul_pd(r1, q3[1])),
                                 _mm256_mul_pd(r2, q3[2]));
            const __m256d d0 = _mm256_and_pd(okd, v[3]), d1 = _mm256_and_pd(okd, v[4]),
                          d2 = _mm256_and_pd(okd, v[5]);
            w[3 + a] = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, d0), _mm256_mul_pd(r1, d1)),
                                     _mm256_mul_pd(r2, d2));
        }
        for (int c = 0; c < 6; c++) {
            const __m256i a = _mm256_and_si256(_mm256_castpd_si256(w[c]), absm);
            ok = _mm256_and_si256(ok, _mm256_cmpgt_epi64(inf, a));
            if (c >= 3)
                ok = _mm256_andnot_si256(_mm256_cmpgt_epi64(small, a), ok);
            v[c] = w[c];
        }
        okd = _mm256_castsi256_pd(ok);
    }
    __m256d T0 = _mm256_and_pd(okd, v[6]), T1 = _mm256_and_pd(okd, v[7]);
    for (int a = 0; a < 3; a++) {
        const __m256d o = _mm256_and_pd(okd, v[a]);
        const __m256d d = _mm256_blendv_pd(one, v[3 + a], okd);
        const __m256d inv = _mm256_div_pd(one, d);
        const __m256d ta = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(b->lo[a]), o), inv);
        const __m256d tb = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(b->hi[a]), o), inv);
        /* tn = ta < tb ? ta : tb, tf = ta < tb ? tb : ta; t0 = tn > t0 ? tn : t0,
           t1 = tf < t1 ? tf : t1 (min_pd(x, y) = x < y ? x : y, max_pd likewise) */
        const __m256d tn = _mm256_min_pd(ta, tb), tf = _mm256_max_pd(tb, ta);
        T0 = _mm256_max_pd(tn, T0);
        T1 = _mm256_min_pd(tf, T1);
    }
    _mm256_storeu_pd(t0, T0);
    _mm256_storeu_pd(t1, T1);
    return (unsigned)_mm256_movemask_pd(okd);
}

/* the two cases in functions of their own (the grid frame's copies stay out of the other) */
__attribute__((target("avx2"))) static unsigned rt_pk_tbox4_avx2(const rt_grid *g, const rt_ray *q,
                                                                 double *t0, double *t1)
{
    return rt_pk_tbox4_body(g, 0, q, t0, t1);
}

__attribute__((target("avx2"))) static unsigned rt_pk_tbox4_rot_avx2(const rt_grid *g,
                                                                     const rt_ray *q, double *t0,
                                                                     double *t1)
{
    return rt_pk_tbox4_body(g, 1, q, t0, t1);
}
#endif

/* rt_pk_tbox in the grid frame of g: the ray as given taken into a rotated grid's frame
   (rt_grid_point, rt_grid_dir: only finite values, no operation on a non-finite one) and
   judged there; the range of a rotated ray serves only to find misses of the box (the rays
   walked are clipped by rt_pk_clip, from the rt_rayx) */
static inline int rt_pk_tbox_g(const rt_grid *g, const rt_ray *q, double t[2])
{
    if (!g->rotated)
        return rt_pk_tbox(&g->b, q, t);
    const double *o = q->org, *d = q->dir;
    if (!(isfinite(o[0]) & isfinite(o[1]) & isfinite(o[2]) & isfinite(d[0]) & isfinite(d[1]) &
          isfinite(d[2]) & isfinite(q->tmin) & !isnan(q->tmax)))
        return 0;
    rt_ray w = *q;
    rt_grid_point(g, q->org, w.org);
    rt_grid_dir(g, q->dir, w.dir);
    return rt_pk_tbox(&g->b, &w, t);
}

/* rt_pk_tbox_g for rays[0..n-1]: the mask of the rays judged, their ranges in t0[], t1[] */
static uint64_t rt_pk_tboxes(const rt_grid *g, const rt_ray *rays, int n, double *t0, double *t1)
{
    uint64_t judged = 0;
    int k = 0;
#ifdef RT_PK_X86
    if (rt_pk_avx2 && !g->rotated)
        for (; k + 4 <= n; k += 4)
            judged |= (uint64_t)rt_pk_tbox4_avx2(g, rays + k, t0 + k, t1 + k) << k;
    else if (rt_pk_avx2)
        for (; k + 4 <= n; k += 4)
            judged |= (uint64_t)rt_pk_tbox4_rot_avx2(g, rays + k, t0 + k, t1 + k) << k;
#endif
    for (; k < n; k++) {
        double t[2];
        if (rt_pk_tbox_g(g, &rays[k], t)) {
            judged |= (uint64_t)1 << k;
            t0[k] = t[0];
            t1[k] = t[1];
        }
    }
    return judged;
}

/* the signs of a direction's components (bit a: negative), -1 if one is zero (or their
   product underflows: then the packet takes the single-ray path, which is always right) */
static inline int rt_pk_octant(const double d[3])
{
    uint64_t b[3];
    memcpy(b, d, sizeof b);
    const int o = (int)(b[0] >> 63 | (b[1] >> 63) << 1 | (b[2] >> 63) << 2);
    return d[0] * d[1] * d[2] != 0.0 ? o : -1;
}

/* ray k's per-ray data; 0 if it does not share the packet's axes (of the exact test, in
   VRC3) and octant (of the walk, in the grid frame) */
static int rt_pk_ray(rt_pk *p, int k, int *oct)
{
    const rt_rayx *r = &p->r[k];
    const rt_grid *g = &p->sc->grid;
    const double *go = r->o, *gd = r->d;
    if (g->rotated) {
        rt_grid_point(g, r->o, p->rot[k][0]);
        rt_grid_dir(g, r->d, p->rot[k][1]);
        go = p->rot[k][0];
        gd = p->rot[k][1];
    }
    p->go[k] = go;
    p->gd[k] = gd;
    const int o = rt_pk_octant(gd);
    if (o < 0 || (*oct >= 0 && (o != *oct || r->kx != p->kx || r->ky != p->ky || r->kz != p->kz)))
        return 0;
    if (*oct < 0) {
        *oct = o;
        p->kx = r->kx;
        p->ky = r->ky;
        p->kz = r->kz;
        const double ax = fabs(gd[0]), ay = fabs(gd[1]), az = fabs(gd[2]);
        p->K = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
        p->a1 = (p->K + 1) % 3;
        p->a2 = (p->K + 2) % 3;
        p->sg = gd[p->K] > 0.0 ? 1 : -1;
        const rt_box *b = &g->b;
        for (int a = 0; a < 3; a++) {
            p->nf[0][a] = gd[a] < 0.0 ? b->hi[a] : b->lo[a];
            p->nf[1][a] = gd[a] < 0.0 ? b->lo[a] : b->hi[a];
        }
    }
    p->ox[k] = r->o[p->kx];
    p->oy[k] = r->o[p->ky];
    p->oz[k] = r->o[p->kz];
    p->sx[k] = r->sx;
    p->sz[k] = r->sz;
    p->tn[k] = r->tmin;
    p->tx[k] = r->tmax;
    p->sy[k] = r->sy;
    p->oK[k] = go[p->K];
    p->dK[k] = gd[p->K];
    p->o1[k] = go[p->a1];
    p->o2[k] = go[p->a2];
    if (g->rotated) {
        p->m1[k] = gd[p->a1] / gd[p->K];
        p->m2[k] = gd[p->a2] / gd[p->K];
    } else { /* K is kz and a1, a2 are kx, ky (in this order for a positive d[kz]): the
                slopes are the exact test's sx, sy (d * (1 / d[kz]), within an ulp of the
                quotient, far inside the frustum's margin) */
        const int pos = p->a1 == r->kx;
        p->m1[k] = pos ? r->sx : r->sy;
        p->m2[k] = pos ? r->sy : r->sx;
    }
    return 1;
}

#ifdef RT_PK_X86
/* The plain-ray set-ups' shared scalar parts (rt_pk_setup_avx2_body, rt_pk_setup_avx512_body):
   the packet's axes from ray 0 (rt_rayx_shear's rule: kz, kx, ky, neg), its octant in the
   grid frame (sgn) and the slicing axis K with the other two a1, a2 ... */
typedef struct rt_pk_axes {
    int kx, ky, kz, neg, K, a1, a2, sgn[3];
} rt_pk_axes;

static inline __attribute__((always_inline)) rt_pk_axes rt_pk_axes_of(const rt_grid *g,
                                                                     const double *d0,
                                                                     const int rotated)
{
    static const int8_t next[2][3][2] = {{{1, 2}, {2, 0}, {0, 1}}, {{2, 1}, {0, 2}, {1, 0}}};
    rt_pk_axes x;
    const double ax0 = fabs(d0[0]), ay0 = fabs(d0[1]), az0 = fabs(d0[2]);
    x.kz = ((ax0 < ay0) | (ax0 < az0)) * (1 + (ay0 < az0));
    x.neg = d0[x.kz] < 0.0;
    x.kx = next[x.neg][x.kz][0];
    x.ky = next[x.neg][x.kz][1];
    double gd0[3] = {d0[0], d0[1], d0[2]};
    if (rotated)
        rt_grid_dir(g, d0, gd0);
    for (int a = 0; a < 3; a++)
        x.sgn[a] = gd0[a] < 0.0;
    x.K = x.kz;
    if (rotated) {
        const double gx = fabs(gd0[0]), gy = fabs(gd0[1]), gz = fabs(gd0[2]);
        x.K = gx >= gy && gx >= gz ? 0 : (gy >= gz ? 1 : 2);
    }
    x.a1 = (x.K + 1) % 3;
    x.a2 = (x.K + 2) % 3;
    return x;
}

/* ... and, once every ray is set up, the packet's fields from them (the rays walked: live) */
static inline __attribute__((always_inline)) void rt_pk_setup_end(rt_pk *p, const rt_pk_axes *x,
                                                                  uint64_t live)
{
    const rt_box *b = &p->sc->grid.b;
    p->live = live;
    p->made = 0;
    p->kx = x->kx;
    p->ky = x->ky;
    p->kz = x->kz;
    p->K = x->K;
    p->a1 = x->a1;
    p->a2 = x->a2;
    p->sg = x->sgn[x->K] ? -1 : 1;
    for (int a = 0; a < 3; a++) {
        p->nf[0][a] = x->sgn[a] ? b->hi[a] : b->lo[a];
        p->nf[1][a] = x->sgn[a] ? b->lo[a] : b->hi[a];
    }
    if (!p->any) {
        memset(p->bi, 0xff, (size_t)p->n * sizeof p->bi[0]); /* -1: no hit */
        memset(p->nh, 0, (size_t)p->n * sizeof p->nh[0]);
    }
}

/* The set-up of a packet of rays that are all plain (every check of rt_rayx_setup passed by
   a wide margin, no component flushed), 4 rays a step with AVX2 (no FMA), and without the
   rays' rt_rayx: those are made by rt_pk_make when a ray first reaches an exact test (most
   walked rays never do: the cull rules them out). Every quantity is computed with the
   operations of the general set-up, lane by lane:
   - the checks, in integer compares of the bits before any floating operation: origin and
     tmin within 1e30, direction components within [1e-100, 1e30] (in the grid frame too),
     tmax not NaN, and then tmin <= tmax. Such a ray passes rt_rayx_check (RT_RAY_MAX 1e100,
     largest component at least 1e-100) and keeps every component (none is below 1e-150 of
     the largest), so its rt_rayx has the ray's own o and d; the product of its components
     in the grid frame is not 0 (at least 1e-300: rt_pk_octant);
   - the exact test's axes (rt_rayx_shear's rule: kz the first of the largest |d|, kx and
     ky swapped for a negative d[kz]) and the signs of the components in the grid frame, the
     same in every lane (else the general set-up decides); sz = 1 / d[kz], sx = d[kx] sz,
     sy = d[ky] sz;
   - on a rotated grid the ray in the grid frame as rt_grid_point and rt_grid_dir compute it
     (rt_pk_make computes it again for the rays it makes, the same values), the slicing axis
     K, the first of the largest components in the grid frame, from ray 0 (rt_pk_ray takes
     it from the first ray walked: any K of the common octant walks right), the slopes
     gd[a] / gd[K]; on a grid that is not rotated K = kz and the slopes are sx, sy (rt_pk_ray);
   - the grid box's range (rt_pk_tbox's operations, as rt_pk_tbox4_body: the same values as
     rt_pk_clip's) and the extent along K (rt_pk_range's).
   Returns 0 if a ray is not plain or the rays do not share the axes and octant: then the
   general set-up runs (and decides coherence as before). */
/* the set-up's per-ray fields that a ray not walked has 0 in (rt_pk_lanes0_avx2 and
   rt_pk_lanes0_avx512) */
#define RT_PK_LANES0(p)                                                                    \
    {(p)->ox, (p)->oy, (p)->oz, (p)->sx, (p)->sy, (p)->oK, (p)->dK, (p)->o1, (p)->o2, (p)->m1, \
     (p)->m2, (p)->us, (p)->ue}

/* the lanes of rays k .. k + 3 when none of them is walked: what the set-up stores for a
   ray not walked (0 in the kernels' and the walk's lanes; a nearest-hit ray's records as
   for any ray: no hit; its end t1 is never read), without the divisions of the rays walked */
static inline __attribute__((target("avx2"), always_inline)) void rt_pk_lanes0_avx2(rt_pk *p,
                                                                                  int k,
                                                                                  const int any)
{
    const __m256d z = _mm256_setzero_pd();
    double *const f[] = RT_PK_LANES0(p);
    for (size_t j = 0; j < sizeof f / sizeof f[0]; j++)
        _mm256_storeu_pd(f[j] + k, z);
    if (any) {
        _mm256_storeu_pd(p->sz + k, z);
        _mm256_storeu_pd(p->tn + k, z);
        _mm256_storeu_pd(p->tx + k, z);
    } else {
        _mm256_storeu_pd(p->t1 + k, z);
        _mm256_storeu_pd(p->best + k, _mm256_set1_pd(INFINITY));
        _mm256_storeu_pd(p->eb + k, z);
    }
}

static inline __attribute__((target("avx2"), always_inline)) int
rt_pk_setup_avx2_body(rt_pk *p, const rt_ray *rays, const int rotated)
{
    const rt_grid *g = &p->sc->grid;
    const rt_box *b = &g->b;
    const int n = p->n, any = p->any;
    const rt_pk_axes x = rt_pk_axes_of(g, rays[0].dir, rotated);
    const int kx = x.kx, ky = x.ky, kz = x.kz, neg = x.neg, K = x.K, a1 = x.a1, a2 = x.a2;
    const int *sgn = x.sgn;
    const double lim[3] = {1e30, 1e-100, INFINITY};
    int64_t blim[3];
    memcpy(blim, lim, sizeof blim);
    const __m256i absm = _mm256_set1_epi64x(INT64_MAX);
    const __m256d fabsm = _mm256_castsi256_pd(absm);
    const __m256i big = _mm256_set1_epi64x(blim[0]), small = _mm256_set1_epi64x(blim[1]),
                  inf = _mm256_set1_epi64x(blim[2]);
    const __m256d one = _mm256_set1_pd(1.0), sg = _mm256_set1_pd(sgn[K] ? -1.0 : 1.0);
    const __m256d pinf = _mm256_set1_pd(INFINITY), ninf = _mm256_set1_pd(-INFINITY);
    __m256d usmin = pinf, usmax = ninf, uemin = pinf, uemax = ninf;
    uint64_t live = 0;
    for (int k = 0; k < n; k += 4) {
        const rt_ray *q = rays + k;
        __m256d x[4], y[4], v[8];
        for (int j = 0; j < 4; j++) {
            x[j] = _mm256_loadu_pd(q[j].org);
            y[j] = _mm256_loadu_pd(q[j].dir + 1);
        }
        for (int h = 0; h < 2; h++) { /* v[0..7] = o0, o1, o2, d0, d1, d2, tmin, tmax */
            const __m256d *w = h ? y : x;
            const __m256d l01 = _mm256_unpacklo_pd(w[0], w[1]),
                          h01 = _mm256_unpackhi_pd(w[0], w[1]);
            const __m256d l23 = _mm256_unpacklo_pd(w[2], w[3]),
                          h23 = _mm256_unpackhi_pd(w[2], w[3]);
            v[4 * h + 0] = _mm256_permute2f128_pd(l01, l23, 0x20);
            v[4 * h + 1] = _mm256_permute2f128_pd(h01, h23, 0x20);
            v[4 * h + 2] = _mm256_permute2f128_pd(l01, l23, 0x31);
            v[4 * h + 3] = _mm256_permute2f128_pd(h01, h23, 0x31);
        }
        __m256i bad = _mm256_setzero_si256();
        for (int c = 0; c < 7; c++) {
            const __m256i a = _mm256_and_si256(_mm256_castpd_si256(v[c]), absm);
            bad = _mm256_or_si256(bad, _mm256_cmpgt_epi64(a, big));
            if (c >= 3 && c < 6)
                bad = _mm256_or_si256(bad, _mm256_cmpgt_epi64(small, a));
        }
        bad = _mm256_or_si256(bad, _mm256_cmpgt_epi64(_mm256_and_si256(_mm256_castpd_si256(v[7]),
                                                                       absm), inf));
        if (!_mm256_testz_si256(bad, bad))
            return 0;
        /* every value checked: floating operations from here on */
        if (_mm256_movemask_pd(_mm256_cmp_pd(v[6], v[7], _CMP_LE_OQ)) != 15)
            return 0;
        const __m256d ax = _mm256_and_pd(v[3], fabsm), ay = _mm256_and_pd(v[4], fabsm),
                      az = _mm256_and_pd(v[5], fabsm);
        const int c1 = _mm256_movemask_pd(_mm256_or_pd(_mm256_cmp_pd(ax, ay, _CMP_LT_OQ),
                                                       _mm256_cmp_pd(ax, az, _CMP_LT_OQ)));
        const int c2 = _mm256_movemask_pd(_mm256_cmp_pd(ay, az, _CMP_LT_OQ));
        if (kz == 0 ? c1 != 0 : (c1 != 15 || c2 != (kz == 2 ? 15 : 0)))
            return 0; /* not the axes of ray 0 */
        if (rotated && _mm256_movemask_pd(v[3 + kz]) != (neg ? 15 : 0))
            return 0; /* (else the octant's check below) */
        /* the ray in the grid frame: go[0..2], gd[0..2] (v's own on a grid not rotated) */
        __m256d rv[6];
#define RT_PK_GO(a) (rotated ? rv[a] : v[a])
#define RT_PK_GD(a) (rotated ? rv[3 + (a)] : v[3 + (a)])
        if (rotated) {
            __m256d c3[3];
            for (int a = 0; a < 3; a++)
                c3[a] = _mm256_sub_pd(v[a], _mm256_set1_pd(g->c[a]));
            for (int a = 0; a < 3; a++) {
                const __m256d r0 = _mm256_set1_pd(g->R[a][0]), r1 = _mm256_set1_pd(g->R[a][1]),
                              r2 = _mm256_set1_pd(g->R[a][2]);
                rv[a] = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, c3[0]),
                                                    _mm256_mul_pd(r1, c3[1])),
                                      _mm256_mul_pd(r2, c3[2]));
                rv[3 + a] = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, v[3]),
                                                        _mm256_mul_pd(r1, v[4])),
                                          _mm256_mul_pd(r2, v[5]));
                const __m256i m = _mm256_and_si256(_mm256_castpd_si256(rv[3 + a]), absm);
                if (!_mm256_testz_si256(_mm256_or_si256(_mm256_cmpgt_epi64(m, big),
                                                        _mm256_cmpgt_epi64(small, m)),
                                        _mm256_set1_epi64x(-1)))
                    return 0; /* a component in the grid frame below 1e-100 */
            }
        }
        for (int a = 0; a < 3; a++) /* the octant in the grid frame */
            if (_mm256_movemask_pd(RT_PK_GD(a)) != (sgn[a] ? 15 : 0))
                return 0;
        /* the box (rt_pk_tbox4_body's operations) */
        __m256d T0 = v[6], T1 = v[7];
        for (int a = 0; a < 3; a++) {
            const __m256d inv = _mm256_div_pd(one, RT_PK_GD(a));
            const __m256d ta = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(b->lo[a]), RT_PK_GO(a)), inv);
            const __m256d tb = _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(b->hi[a]), RT_PK_GO(a)), inv);
            const __m256d tn = _mm256_min_pd(ta, tb), tf = _mm256_max_pd(tb, ta);
            T0 = _mm256_max_pd(tn, T0);
            T1 = _mm256_min_pd(tf, T1);
        }
        /* walked: t0 <= t1 and t0 finite (rt_pk_range) */
        const __m256i a0 = _mm256_and_si256(_mm256_castpd_si256(T0), absm);
        const __m256d in = _mm256_and_pd(_mm256_cmp_pd(T0, T1, _CMP_LE_OQ),
                                         _mm256_castsi256_pd(_mm256_cmpgt_epi64(inf, a0)));
        if (!_mm256_movemask_pd(in)) { /* none walked (rays beside the box): their lanes */
            rt_pk_lanes0_avx2(p, k, any);
            continue;
        }
        const __m256d sz = _mm256_div_pd(one, v[3 + kz]);
        const __m256d sx = _mm256_mul_pd(v[3 + kx], sz), sy = _mm256_mul_pd(v[3 + ky], sz);
        const __m256d oK = RT_PK_GO(K), dK = RT_PK_GD(K);
        const __m256d us = _mm256_mul_pd(sg, _mm256_add_pd(oK, _mm256_mul_pd(T0, dK)));
        const __m256d ue = _mm256_mul_pd(sg, _mm256_add_pd(oK, _mm256_mul_pd(T1, dK)));
        __m256d m1, m2;
        if (rotated) {
            m1 = _mm256_div_pd(RT_PK_GD(a1), dK);
            m2 = _mm256_div_pd(RT_PK_GD(a2), dK);
        } else { /* K = kz; a1, a2 = kx, ky, swapped for a negative d[kz] (rt_pk_ray) */
            m1 = neg ? sy : sx;
            m2 = neg ? sx : sy;
        }
        /* rays not walked: 0 in every lane (harmless, never in a mask) */
        _mm256_storeu_pd(p->ox + k, _mm256_and_pd(in, v[kx]));
        _mm256_storeu_pd(p->oy + k, _mm256_and_pd(in, v[ky]));
        _mm256_storeu_pd(p->oz + k, _mm256_and_pd(in, v[kz]));
        _mm256_storeu_pd(p->sx + k, _mm256_and_pd(in, sx));
        _mm256_storeu_pd(p->sy + k, _mm256_and_pd(in, sy));
        if (any) { /* the any-hit kernel's range test */
            _mm256_storeu_pd(p->sz + k, _mm256_and_pd(in, sz));
            _mm256_storeu_pd(p->tn + k, _mm256_and_pd(in, v[6]));
            _mm256_storeu_pd(p->tx + k, _mm256_and_pd(in, v[7]));
        } else { /* the nearest hit's records (an any-hit packet's rays only end) */
            _mm256_storeu_pd(p->t1 + k, T1);
            _mm256_storeu_pd(p->best + k, pinf);
            _mm256_storeu_pd(p->eb + k, _mm256_setzero_pd());
        }
        _mm256_storeu_pd(p->oK + k, _mm256_and_pd(in, oK));
        _mm256_storeu_pd(p->dK + k, _mm256_and_pd(in, dK));
        _mm256_storeu_pd(p->o1 + k, _mm256_and_pd(in, RT_PK_GO(a1)));
        _mm256_storeu_pd(p->o2 + k, _mm256_and_pd(in, RT_PK_GO(a2)));
#undef RT_PK_GO
#undef RT_PK_GD
        _mm256_storeu_pd(p->m1 + k, _mm256_and_pd(in, m1));
        _mm256_storeu_pd(p->m2 + k, _mm256_and_pd(in, m2));
        _mm256_storeu_pd(p->us + k, _mm256_and_pd(in, us));
        _mm256_storeu_pd(p->ue + k, _mm256_and_pd(in, ue));
        usmin = _mm256_min_pd(usmin, _mm256_blendv_pd(pinf, us, in));
        usmax = _mm256_max_pd(usmax, _mm256_blendv_pd(ninf, us, in));
        uemin = _mm256_min_pd(uemin, _mm256_blendv_pd(pinf, ue, in));
        uemax = _mm256_max_pd(uemax, _mm256_blendv_pd(ninf, ue, in));
        live |= (uint64_t)_mm256_movemask_pd(in) << k;
    }
    double e[4][4];
    _mm256_storeu_pd(e[0], usmin);
    _mm256_storeu_pd(e[1], usmax);
    _mm256_storeu_pd(e[2], uemin);
    _mm256_storeu_pd(e[3], uemax);
    p->usmin = fmin(fmin(e[0][0], e[0][1]), fmin(e[0][2], e[0][3]));
    p->usmax = fmax(fmax(e[1][0], e[1][1]), fmax(e[1][2], e[1][3]));
    p->uemin = fmin(fmin(e[2][0], e[2][1]), fmin(e[2][2], e[2][3]));
    p->uemax = fmax(fmax(e[3][0], e[3][1]), fmax(e[3][2], e[3][3]));
    rt_pk_setup_end(p, &x, live);
    return 1;
}

/* the two cases in functions of their own (the grid frame's operations stay out of the
   other) */
__attribute__((target("avx2"))) static int rt_pk_setup_avx2(rt_pk *p, const rt_ray *rays)
{
    return rt_pk_setup_avx2_body(p, rays, 0);
}

__attribute__((target("avx2"))) static int rt_pk_setup_rot_avx2(rt_pk *p, const rt_ray *rays)
{
    return rt_pk_setup_avx2_body(p, rays, 1);
}

/* rt_pk_setup_avx2_body with AVX-512: 8 rays a step (n a multiple of 8), the same checks and
   operations per lane, in mask registers */
/* rt_pk_lanes0_avx2 for rays k .. k + 7 */
static inline RT_PK_AVX512 __attribute__((always_inline)) void rt_pk_lanes0_avx512(rt_pk *p,
                                                                                  int k,
                                                                                  const int any)
{
    const __m512d z = _mm512_setzero_pd();
    double *const f[] = RT_PK_LANES0(p);
    for (size_t j = 0; j < sizeof f / sizeof f[0]; j++)
        _mm512_storeu_pd(f[j] + k, z);
    if (any) {
        _mm512_storeu_pd(p->sz + k, z);
        _mm512_storeu_pd(p->tn + k, z);
        _mm512_storeu_pd(p->tx + k, z);
    } else {
        _mm512_storeu_pd(p->t1 + k, z);
        _mm512_storeu_pd(p->best + k, _mm512_set1_pd(INFINITY));
        _mm512_storeu_pd(p->eb + k, z);
    }
}

static inline RT_PK_AVX512 __attribute__((always_inline)) int
rt_pk_setup_avx512_body(rt_pk *p, const rt_ray *rays, const int rotated)
{
    const rt_grid *g = &p->sc->grid;
    const rt_box *b = &g->b;
    const int n = p->n, any = p->any;
    const rt_pk_axes x = rt_pk_axes_of(g, rays[0].dir, rotated);
    const int kx = x.kx, ky = x.ky, kz = x.kz, neg = x.neg, K = x.K, a1 = x.a1, a2 = x.a2;
    const int *sgn = x.sgn;
    const double lim[3] = {1e30, 1e-100, INFINITY};
    int64_t blim[3];
    memcpy(blim, lim, sizeof blim);
    const __m512i absm = _mm512_set1_epi64(INT64_MAX);
    const __m512i big = _mm512_set1_epi64(blim[0]), small = _mm512_set1_epi64(blim[1]),
                  inf = _mm512_set1_epi64(blim[2]);
    const __m512d one = _mm512_set1_pd(1.0), sg = _mm512_set1_pd(sgn[K] ? -1.0 : 1.0);
    const __m512d pinf = _mm512_set1_pd(INFINITY), ninf = _mm512_set1_pd(-INFINITY);
    const __mmask8 negk = neg ? 0xff : 0;
    __m512d usmin = pinf, usmax = ninf, uemin = pinf, uemax = ninf;
    uint64_t live = 0;
    for (int k = 0; k < n; k += 8) {
        const rt_ray *q = rays + k;
        /* 8 x 8 transpose: v[0..7] = o0, o1, o2, d0, d1, d2, tmin, tmax of the eight rays */
        __m512d r[8], t[8], h[8], v[8];
        for (int j = 0; j < 8; j++)
            r[j] = _mm512_loadu_pd(q[j].org); /* org, dir, tmin, tmax: 8 doubles */
        for (int j = 0; j < 4; j++) { /* t[2j]: even components of rays 2j, 2j+1; t[2j+1] odd */
            t[2 * j] = _mm512_unpacklo_pd(r[2 * j], r[2 * j + 1]);
            t[2 * j + 1] = _mm512_unpackhi_pd(r[2 * j], r[2 * j + 1]);
        }
        for (int e = 0; e < 2; e++) { /* per parity e: rays 0-3 and 4-7 by 256-bit halves */
            h[4 * e + 0] = _mm512_shuffle_f64x2(t[e], t[2 + e], 0x44);
            h[4 * e + 1] = _mm512_shuffle_f64x2(t[4 + e], t[6 + e], 0x44);
            h[4 * e + 2] = _mm512_shuffle_f64x2(t[e], t[2 + e], 0xee);
            h[4 * e + 3] = _mm512_shuffle_f64x2(t[4 + e], t[6 + e], 0xee);
        }
        for (int e = 0; e < 2; e++) {
            v[e] = _mm512_shuffle_f64x2(h[4 * e], h[4 * e + 1], 0x88);
            v[2 + e] = _mm512_shuffle_f64x2(h[4 * e], h[4 * e + 1], 0xdd);
            v[4 + e] = _mm512_shuffle_f64x2(h[4 * e + 2], h[4 * e + 3], 0x88);
            v[6 + e] = _mm512_shuffle_f64x2(h[4 * e + 2], h[4 * e + 3], 0xdd);
        }
        __mmask8 bad = 0;
        for (int c = 0; c < 7; c++) {
            const __m512i a = _mm512_and_si512(_mm512_castpd_si512(v[c]), absm);
            bad |= _mm512_cmpgt_epi64_mask(a, big);
            if (c >= 3 && c < 6)
                bad |= _mm512_cmpgt_epi64_mask(small, a);
        }
        bad |= _mm512_cmpgt_epi64_mask(_mm512_and_si512(_mm512_castpd_si512(v[7]), absm), inf);
        if (bad)
            return 0;
        /* every value checked: floating operations from here on */
        if (_mm512_cmp_pd_mask(v[6], v[7], _CMP_LE_OQ) != 0xff)
            return 0;
        const __m512d ax = _mm512_abs_pd(v[3]), ay = _mm512_abs_pd(v[4]), az = _mm512_abs_pd(v[5]);
        const __mmask8 c1 = _mm512_cmp_pd_mask(ax, ay, _CMP_LT_OQ) |
                            _mm512_cmp_pd_mask(ax, az, _CMP_LT_OQ);
        const __mmask8 c2 = _mm512_cmp_pd_mask(ay, az, _CMP_LT_OQ);
        if (kz == 0 ? c1 != 0 : (c1 != 0xff || c2 != (kz == 2 ? 0xff : 0)))
            return 0; /* not the axes of ray 0 */
        if (rotated && _mm512_movepi64_mask(_mm512_castpd_si512(v[3 + kz])) != negk)
            return 0; /* (else the octant's check below) */
        /* the ray in the grid frame: go[0..2], gd[0..2] (v's own on a grid not rotated) */
        __m512d rv[6];
#define RT_PK_GO(a) (rotated ? rv[a] : v[a])
#define RT_PK_GD(a) (rotated ? rv[3 + (a)] : v[3 + (a)])
        if (rotated) {
            __m512d c3[3];
            for (int a = 0; a < 3; a++)
                c3[a] = _mm512_sub_pd(v[a], _mm512_set1_pd(g->c[a]));
            for (int a = 0; a < 3; a++) {
                const __m512d r0 = _mm512_set1_pd(g->R[a][0]), r1 = _mm512_set1_pd(g->R[a][1]),
                              r2 = _mm512_set1_pd(g->R[a][2]);
                rv[a] = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r0, c3[0]),
                                                    _mm512_mul_pd(r1, c3[1])),
                                      _mm512_mul_pd(r2, c3[2]));
                rv[3 + a] = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(r0, v[3]),
                                                        _mm512_mul_pd(r1, v[4])),
                                          _mm512_mul_pd(r2, v[5]));
                const __m512i m = _mm512_and_si512(_mm512_castpd_si512(rv[3 + a]), absm);
                if (_mm512_cmpgt_epi64_mask(m, big) | _mm512_cmpgt_epi64_mask(small, m))
                    return 0; /* a component in the grid frame below 1e-100 */
            }
        }
        for (int a = 0; a < 3; a++) /* the octant in the grid frame */
            if (_mm512_movepi64_mask(_mm512_castpd_si512(RT_PK_GD(a))) != (sgn[a] ? 0xff : 0))
                return 0;
        /* the box (rt_pk_tbox4_body's operations) */
        __m512d T0 = v[6], T1 = v[7];
        for (int a = 0; a < 3; a++) {
            const __m512d inv = _mm512_div_pd(one, RT_PK_GD(a));
            const __m512d ta = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(b->lo[a]), RT_PK_GO(a)), inv);
            const __m512d tb = _mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(b->hi[a]), RT_PK_GO(a)), inv);
            const __m512d tn = _mm512_min_pd(ta, tb), tf = _mm512_max_pd(tb, ta);
            T0 = _mm512_max_pd(tn, T0);
            T1 = _mm512_min_pd(tf, T1);
        }
        /* walked: t0 <= t1 and t0 finite (rt_pk_range) */
        const __m512i a0 = _mm512_and_si512(_mm512_castpd_si512(T0), absm);
        const __mmask8 in = _mm512_cmp_pd_mask(T0, T1, _CMP_LE_OQ) & _mm512_cmpgt_epi64_mask(inf, a0);
        if (!in) { /* none walked (rays beside the box): their lanes */
            rt_pk_lanes0_avx512(p, k, any);
            continue;
        }
        const __m512d sz = _mm512_div_pd(one, v[3 + kz]);
        const __m512d sx = _mm512_mul_pd(v[3 + kx], sz), sy = _mm512_mul_pd(v[3 + ky], sz);
        const __m512d oK = RT_PK_GO(K), dK = RT_PK_GD(K);
        const __m512d us = _mm512_mul_pd(sg, _mm512_add_pd(oK, _mm512_mul_pd(T0, dK)));
        const __m512d ue = _mm512_mul_pd(sg, _mm512_add_pd(oK, _mm512_mul_pd(T1, dK)));
        __m512d m1, m2;
        if (rotated) {
            m1 = _mm512_div_pd(RT_PK_GD(a1), dK);
            m2 = _mm512_div_pd(RT_PK_GD(a2), dK);
        } else { /* K = kz; a1, a2 = kx, ky, swapped for a negative d[kz] (rt_pk_ray) */
            m1 = neg ? sy : sx;
            m2 = neg ? sx : sy;
        }
        /* rays not walked: 0 in every lane (harmless, never in a mask) */
        _mm512_storeu_pd(p->ox + k, _mm512_maskz_mov_pd(in, v[kx]));
        _mm512_storeu_pd(p->oy + k, _mm512_maskz_mov_pd(in, v[ky]));
        _mm512_storeu_pd(p->oz + k, _mm512_maskz_mov_pd(in, v[kz]));
        _mm512_storeu_pd(p->sx + k, _mm512_maskz_mov_pd(in, sx));
        _mm512_storeu_pd(p->sy + k, _mm512_maskz_mov_pd(in, sy));
        if (any) { /* the any-hit kernel's range test */
            _mm512_storeu_pd(p->sz + k, _mm512_maskz_mov_pd(in, sz));
            _mm512_storeu_pd(p->tn + k, _mm512_maskz_mov_pd(in, v[6]));
            _mm512_storeu_pd(p->tx + k, _mm512_maskz_mov_pd(in, v[7]));
        } else { /* the nearest hit's records (an any-hit packet's rays only end) */
            _mm512_storeu_pd(p->t1 + k, T1);
            _mm512_storeu_pd(p->best + k, pinf);
            _mm512_storeu_pd(p->eb + k, _mm512_setzero_pd());
        }
        _mm512_storeu_pd(p->oK + k, _mm512_maskz_mov_pd(in, oK));
        _mm512_storeu_pd(p->dK + k, _mm512_maskz_mov_pd(in, dK));
        _mm512_storeu_pd(p->o1 + k, _mm512_maskz_mov_pd(in, RT_PK_GO(a1)));
        _mm512_storeu_pd(p->o2 + k, _mm512_maskz_mov_pd(in, RT_PK_GO(a2)));
#undef RT_PK_GO
#undef RT_PK_GD
        _mm512_storeu_pd(p->m1 + k, _mm512_maskz_mov_pd(in, m1));
        _mm512_storeu_pd(p->m2 + k, _mm512_maskz_mov_pd(in, m2));
        _mm512_storeu_pd(p->us + k, _mm512_maskz_mov_pd(in, us));
        _mm512_storeu_pd(p->ue + k, _mm512_maskz_mov_pd(in, ue));
        usmin = _mm512_min_pd(usmin, _mm512_mask_blend_pd(in, pinf, us));
        usmax = _mm512_max_pd(usmax, _mm512_mask_blend_pd(in, ninf, us));
        uemin = _mm512_min_pd(uemin, _mm512_mask_blend_pd(in, pinf, ue));
        uemax = _mm512_max_pd(uemax, _mm512_mask_blend_pd(in, ninf, ue));
        live |= (uint64_t)in << k;
    }
    p->usmin = _mm512_reduce_min_pd(usmin);
    p->usmax = _mm512_reduce_max_pd(usmax);
    p->uemin = _mm512_reduce_min_pd(uemin);
    p->uemax = _mm512_reduce_max_pd(uemax);
    rt_pk_setup_end(p, &x, live);
    return 1;
}

RT_PK_AVX512 static int rt_pk_setup_avx512(rt_pk *p, const rt_ray *rays)
{
    return rt_pk_setup_avx512_body(p, rays, 0);
}

RT_PK_AVX512 static int rt_pk_setup_rot_avx512(rt_pk *p, const rt_ray *rays)
{
    return rt_pk_setup_avx512_body(p, rays, 1);
}
#endif

/* ---- packets beside the grid box ---- */

/* x pushed outward (down: lo, up: hi) by more than the rounding of the operation that made
   it (2^-53 of |x|, or an underflow below 1e-300): the bounds below then hold in exact
   arithmetic */
static inline double rt_pk_dn(double x)
{
    return x - (fabs(x) * 0x1p-40 + 1e-300);
}

static inline double rt_pk_up(double x)
{
    return x + (fabs(x) * 0x1p-40 + 1e-300);
}

/* 1 if every ray of a nearest-hit packet misses the grid box, from the bounds of its rays'
   components (lo[c] .. hi[c] for c = o0, o1, o2, d0, d1, d2, tmin in VRC3; no NaN): the
   components within the plain set-up's limits (origin and tmin within 1e30, direction
   components within [1e-100, 1e30], so rt_rayx_setup keeps every component), each
   direction component of one sign in the grid frame, and in the grid frame, with s the
   sign of d[a], the near plane's distance A_a = s (near_a - o_a) and the far plane's
   F_b = s (far_b - o_b) (entry and exit: t = A_a / |d_a|, F_b / |d_b|), either
   - some exit behind every ray (F_b < 0 <= tmin), or
   - for some axes a != b, the entry into slab a after the exit from slab b for every ray:
     A_a |d_b| > F_b |d_a| (the two slabs' ranges of t are disjoint: the line misses the box).
   Every bound is made by interval arithmetic pushed outward past its rounding (rt_pk_dn,
   rt_pk_up), so the test holds for the exact rays and the exact box in the stored frame
   (rt_grid.R, c). A ray that misses the box is a miss on the single-ray walk (every
   primitive lies inside the box, by the build's pad, rt_pk_tbox); such a packet needs no
   set-up (45-51 % of the primary packets of the three meshes at 1024^2, whose frames show
   the mesh with room around it). */
static int rt_pk_beside(const rt_grid *g, const double lo[7], const double hi[7])
{
    for (int c = 0; c < 7; c++)
        if (!(fabs(lo[c]) <= 1e30 && fabs(hi[c]) <= 1e30))
            return 0;
    for (int a = 0; a < 3; a++)
        if (!(lo[3 + a] >= 1e-100 || hi[3 + a] <= -1e-100))
            return 0; /* a direction component of both signs or below 1e-100 */
    double olo[3], ohi[3], dlo[3], dhi[3];
    if (g->rotated) {
        /* o' = R (o - c), d' = R d: each component's bounds are sums of the least (greatest)
           products at the ends, made with 4 roundings of at most 2^-53 of M = the sum of the
           components' greatest magnitudes (R's rows are unit vectors, rt_prim_frame: each
           |R[a][i]| within a few ulps of 1 at most): pushed outward by 2^-40 M */
        double qlo[3], qhi[3], mo = 0.0, md = 0.0;
        for (int i = 0; i < 3; i++) {
            qlo[i] = lo[i] - g->c[i];
            qhi[i] = hi[i] - g->c[i];
            mo += fmax(fabs(qlo[i]), fabs(qhi[i]));
            md += fmax(fabs(lo[3 + i]), fabs(hi[3 + i]));
        }
        const double wo = mo * 0x1p-40 + 1e-300, wd = md * 0x1p-40 + 1e-300;
        for (int a = 0; a < 3; a++) {
            double sl = 0.0, sh = 0.0, tl = 0.0, th = 0.0;
            for (int i = 0; i < 3; i++) {
                const double r = g->R[a][i];
                const double p0 = r * qlo[i], p1 = r * qhi[i];
                const double e0 = r * lo[3 + i], e1 = r * hi[3 + i];
                sl += p0 < p1 ? p0 : p1;
                sh += p0 < p1 ? p1 : p0;
                tl += e0 < e1 ? e0 : e1;
                th += e0 < e1 ? e1 : e0;
            }
            olo[a] = sl - wo;
            ohi[a] = sh + wo;
            dlo[a] = tl - wd;
            dhi[a] = th + wd;
        }
    } else {
        memcpy(olo, lo, sizeof olo);
        memcpy(ohi, hi, sizeof ohi);
        memcpy(dlo, lo + 3, sizeof dlo);
        memcpy(dhi, hi + 3, sizeof dhi);
    }
    const rt_box *b = &g->b;
    double Alo[3], Fhi[3], elo[3], ehi[3];
    for (int a = 0; a < 3; a++) {
        int pos;
        if (dlo[a] > 0.0)
            pos = 1;
        else if (dhi[a] < 0.0)
            pos = 0;
        else
            return 0; /* of both signs in the grid frame */
        /* |d_a| within [elo, ehi]; A_a >= Alo, F_a <= Fhi */
        elo[a] = pos ? dlo[a] : -dhi[a];
        ehi[a] = pos ? dhi[a] : -dlo[a];
        Alo[a] = pos ? rt_pk_dn(b->lo[a] - ohi[a]) : rt_pk_dn(olo[a] - b->hi[a]);
        Fhi[a] = pos ? rt_pk_up(b->hi[a] - olo[a]) : rt_pk_up(ohi[a] - b->lo[a]);
    }
    for (int a = 0; a < 3; a++)
        if (Fhi[a] < 0.0 && lo[6] >= 0.0)
            return 1; /* the box behind every ray */
    for (int a = 0; a < 3; a++)
        for (int c = 0; c < 3; c++) {
            if (c == a)
                continue;
            /* the least A_a |d_c| against the greatest F_c |d_a| (|d| > 0) */
            const double l0 = Alo[a] * elo[c], l1 = Alo[a] * ehi[c];
            const double u0 = Fhi[c] * elo[a], u1 = Fhi[c] * ehi[a];
            if (rt_pk_dn(l0 < l1 ? l0 : l1) > rt_pk_up(u0 > u1 ? u0 : u1))
                return 1;
        }
    return 0;
}

#ifdef RT_PK_X86
/* the bounds of rays[0..n-1]'s components o0 .. tmin for rt_pk_beside (n a multiple of 4);
   0 if one of them is beyond 1e30 (tmax: is NaN). The checks are made on the bits before
   the floating compares (no operation on a NaN: none raises an exception); a value that
   fails them is taken as 0 */
__attribute__((target("avx2"))) static int rt_pk_bounds_avx2(const rt_ray *rays, int n,
                                                             double lo[8], double hi[8])
{
    const double lim[2] = {1e30, INFINITY};
    int64_t bl[2];
    memcpy(bl, lim, sizeof bl);
    const __m256i absm = _mm256_set1_epi64x(INT64_MAX), lx = _mm256_set1_epi64x(bl[0]),
                  ly = _mm256_set_epi64x(bl[1], bl[0], bl[0], bl[0]);
    const __m256d pinf = _mm256_set1_pd(INFINITY), ninf = _mm256_set1_pd(-INFINITY);
    __m256d l0 = pinf, l1 = pinf, h0 = ninf, h1 = ninf;
    __m256i bad = _mm256_setzero_si256();
    for (int k = 0; k < n; k++) {
        __m256d x = _mm256_loadu_pd(rays[k].org), y = _mm256_loadu_pd(rays[k].dir + 1);
        const __m256i bx = _mm256_cmpgt_epi64(_mm256_and_si256(_mm256_castpd_si256(x), absm), lx);
        const __m256i by = _mm256_cmpgt_epi64(_mm256_and_si256(_mm256_castpd_si256(y), absm), ly);
        bad = _mm256_or_si256(bad, _mm256_or_si256(bx, by));
        x = _mm256_andnot_pd(_mm256_castsi256_pd(bx), x);
        y = _mm256_andnot_pd(_mm256_castsi256_pd(by), y);
        l0 = _mm256_min_pd(l0, x);
        h0 = _mm256_max_pd(h0, x);
        l1 = _mm256_min_pd(l1, y);
        h1 = _mm256_max_pd(h1, y);
    }
    _mm256_storeu_pd(lo, l0);
    _mm256_storeu_pd(lo + 4, l1);
    _mm256_storeu_pd(hi, h0);
    _mm256_storeu_pd(hi + 4, h1);
    return _mm256_testz_si256(bad, bad);
}

/* rt_pk_bounds_avx2 with AVX-512: a ray's eight doubles in one register (n even) */
RT_PK_AVX512 static int rt_pk_bounds_avx512(const rt_ray *rays, int n, double lo[8],
                                            double hi[8])
{
    const double lim[2] = {1e30, INFINITY};
    int64_t bl[2];
    memcpy(bl, lim, sizeof bl);
    const __m512i absm = _mm512_set1_epi64(INT64_MAX),
                  lv = _mm512_set_epi64(bl[1], bl[0], bl[0], bl[0], bl[0], bl[0], bl[0], bl[0]);
    /* two rays a step in two chains */
    __m512d l = _mm512_set1_pd(INFINITY), h = _mm512_set1_pd(-INFINITY), l2 = l, h2 = h;
    __mmask8 bad = 0;
    for (int k = 0; k < n; k += 2) {
        const __m512d x = _mm512_loadu_pd(rays[k].org), y = _mm512_loadu_pd(rays[k + 1].org);
        const __mmask8 bx = _mm512_cmpgt_epi64_mask(_mm512_and_si512(_mm512_castpd_si512(x), absm), lv);
        const __mmask8 by = _mm512_cmpgt_epi64_mask(_mm512_and_si512(_mm512_castpd_si512(y), absm), lv);
        bad |= bx | by;
        const __m512d xs = _mm512_maskz_mov_pd((__mmask8)~bx, x),
                      ys = _mm512_maskz_mov_pd((__mmask8)~by, y);
        l = _mm512_min_pd(l, xs);
        h = _mm512_max_pd(h, xs);
        l2 = _mm512_min_pd(l2, ys);
        h2 = _mm512_max_pd(h2, ys);
    }
    _mm512_storeu_pd(lo, _mm512_min_pd(l, l2));
    _mm512_storeu_pd(hi, _mm512_max_pd(h, h2));
    return !bad;
}
#endif

/* the kernels' lane k for a ray not walked: harmless values */
static inline void rt_pk_lane0(rt_pk *p, int k)
{
    p->ox[k] = p->oy[k] = p->oz[k] = p->sx[k] = p->sy[k] = 0.0;
    p->sz[k] = p->tn[k] = p->tx[k] = 0.0;
}

/* the packet's rays: 1, or 0 if they are not coherent (different axes or octants, a zero
   direction component) */
static int rt_pk_setup(rt_pk *p, const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays,
                       int any, rt_rayx *rx)
{
    const rt_grid *g = &sc->grid;
    if (!sc->use_grid || n == 0 || n > RT_PACKET)
        return 0;
    p->sc = sc;
    p->n = (int)n;
    p->any = any;
    p->hit = p->over = p->fmask = p->alone = 0;
    p->steps = 0;
    p->beside = 0;
    p->hbox = ctx->hbox;
    p->r = rx;
    p->rays = rays;
    p->fsok = 0;
    for (int k = p->n; k < RT_PACKET; k++) /* lanes without a ray: harmless, never in a mask */
        rt_pk_lane0(p, k);
#ifdef RT_PK_X86
    /* a nearest-hit packet after one without a ray in the grid box (such packets come in
       runs: the parts of the frame around the scene) may lie beside the box too */
    double blo[8], bhi[8];
    if (!any && ctx->beside && rt_pk_avx2 && n % 4 == 0 &&
        (rt_pk_avx512 ? rt_pk_bounds_avx512(rays, p->n, blo, bhi)
                      : rt_pk_bounds_avx2(rays, p->n, blo, bhi)) &&
        rt_pk_beside(g, blo, bhi)) { /* every ray a miss: no set-up */
        p->live = 0;
        p->beside = 1;
        for (int k = 0; k < p->n; k++) {
            p->bi[k] = -1;
            p->best[k] = INFINITY;
        }
        return 1;
    }
    if (rt_pk_avx2 && n % 4 == 0 &&
        (rt_pk_avx512 && n % 8 == 0
             ? (g->rotated ? rt_pk_setup_rot_avx512(p, rays) : rt_pk_setup_avx512(p, rays))
             : (g->rotated ? rt_pk_setup_rot_avx2(p, rays) : rt_pk_setup_avx2(p, rays)))) {
        if (p->live) {
            p->umg = g->b.cw[p->K] * RT_PK_MARGIN;
            p->xmg[0] = g->b.cw[p->a1] * RT_PK_MARGIN;
            p->xmg[1] = g->b.cw[p->a2] * RT_PK_MARGIN;
        }
        return 1;
    }
#endif
    p->live = 0;
    p->made = ~(uint64_t)0;
    p->uemin = INFINITY;
    p->usmax = p->uemax = -INFINITY;
    p->usmin = INFINITY;
    p->K = 0; /* set by the first ray that may be walked; if none: a packet of misses */
    p->a1 = 1;
    p->a2 = 2;
    p->sg = 1;
    int oct = -1;
    /* the lanes the AVX2 steps read for rays not walked: finite values (rt_pk_in_avx2,
       rt_pk_frustum_avx2) */
    memset(p->us, 0, sizeof p->us);
    memset(p->ue, 0, sizeof p->ue);
    memset(p->oK, 0, sizeof p->oK);
    memset(p->o1, 0, sizeof p->o1);
    memset(p->o2, 0, sizeof p->o2);
    memset(p->m1, 0, sizeof p->m1);
    memset(p->m2, 0, sizeof p->m2);
    /* the box test of the rays as given: not for any-hit rays (shadow rays start at surfaces
       inside the box, the test would only add its cost: armadillo's shadow rays, +83
       instructions per ray) */
    double tb0[RT_PACKET], tb1[RT_PACKET];
    const uint64_t judged_m = !any ? rt_pk_tboxes(g, rays, p->n, tb0, tb1) : 0;
    for (int k = 0; k < p->n; k++) {
        const rt_ray *q = &rays[k];
        p->best[k] = INFINITY;
        p->eb[k] = 0.0;
        p->bi[k] = -1;
        p->nh[k] = 0;
        const int judged = (judged_m >> k) & 1u;
        const double t[2] = {judged ? tb0[k] : 0.0, judged ? tb1[k] : 0.0};
        if (judged && !(t[0] <= t[1])) {
            rt_pk_lane0(p, k);
            continue; /* a miss: the rest of the set-up only for rays that may be walked */
        }
        if (!rt_rayx_setup(&p->r[k], q->org, q->dir, q->tmin, q->tmax)) {
            rt_pk_lane0(p, k);
            continue; /* a miss, as on the single-ray walk */
        }
        if (!rt_pk_ray(p, k, &oct)) {
            if (!any)
                return 0;
            /* an any-hit ray of other axes or another octant: traced singly, the others
               stay a packet (shadow rays toward a light near a diagonal of the grid) */
            p->alone |= (uint64_t)1 << k;
            rt_pk_lane0(p, k);
            continue;
        }
        if (!(judged && !g->rotated ? rt_pk_range(p, k, t[0], t[1]) : rt_pk_clip(p, k)))
            continue; /* misses the grid box */
        p->live |= (uint64_t)1 << k;
        p->uemin = p->ue[k] < p->uemin ? p->ue[k] : p->uemin;
        p->usmax = p->us[k] > p->usmax ? p->us[k] : p->usmax;
        p->usmin = p->us[k] < p->usmin ? p->us[k] : p->usmin;
        p->uemax = p->ue[k] > p->uemax ? p->ue[k] : p->uemax;
    }
    if (p->live) {
        p->umg = g->b.cw[p->K] * RT_PK_MARGIN;
        p->xmg[0] = g->b.cw[p->a1] * RT_PK_MARGIN;
        p->xmg[1] = g->b.cw[p->a2] * RT_PK_MARGIN;
    }
    return 1;
}

/* ---- tests ---- */

/* the rt_rayx of the rays of m not made yet (after rt_pk_setup_avx2: plain rays walked).
   For a plain ray rt_rayx_setup passes every check and flushes nothing, so it makes the ray's
   own o, d, tmin, tmax, no skip, the packet's axes, sz = 1 / d[kz] and the sx, sy the set-up
   computed with its operations: written here directly. A build without NDEBUG (the tests')
   compares them with rt_rayx_setup's byte for byte, takes rt_rayx_setup's on a difference
   and counts it (rt_packet_make_differ: test_rt_packet requires 0), so that a change of
   rt_rayx or rt_rayx_setup that this copy misses is caught; it also checks the set-up's oK,
   dK against the ray's o[K], d[K] in the grid frame. The ray is not taken into the grid
   frame here: rt_pk_hit needs only its K components, oK and dK (on fandisk's packets the
   rotation of every ray made was 3 % of the instructions). */
#ifndef NDEBUG
static atomic_ullong rt_pk_make_differ;
#endif

unsigned long long rt_packet_make_differ(void)
{
#ifndef NDEBUG
    return atomic_load_explicit(&rt_pk_make_differ, memory_order_relaxed);
#else
    return 0;
#endif
}

static inline void rt_pk_make(rt_pk *p, uint64_t m)
{
    for (uint64_t w = m & ~p->made; w; w &= w - 1) {
        const int k = __builtin_ctzll(w);
        const rt_ray *q = &p->rays[k];
        rt_rayx *r = &p->r[k];
#ifndef NDEBUG
        /* the padding zeroed for the byte comparison below; a release build writes the
           fields only (every one of them: the comparison catches a field missed here) */
        memset(r, 0, sizeof *r);
#endif
        memcpy(r->o, q->org, sizeof r->o);
        memcpy(r->d, q->dir, sizeof r->d);
        r->tmin = q->tmin;
        r->tmax = q->tmax;
        r->kx = p->kx;
        r->ky = p->ky;
        r->kz = p->kz;
        r->sz = 1.0 / q->dir[p->kz];
        r->sx = p->sx[k];
        r->sy = p->sy[k];
        r->skip = RT_NO_SKIP;
#ifndef NDEBUG
        rt_rayx ref;
        memset(&ref, 0, sizeof ref);
        if (!rt_rayx_setup(&ref, q->org, q->dir, q->tmin, q->tmax) || memcmp(&ref, r, sizeof ref)) {
            atomic_fetch_add_explicit(&rt_pk_make_differ, 1, memory_order_relaxed);
            *r = ref;
        }
        /* the set-up's oK, dK: the ray's o[K], d[K] in the grid frame, as rt_pk_ray takes
           them (rt_grid_point's and rt_grid_dir's operations on a rotated grid) */
        double go[3], gd[3];
        memcpy(go, r->o, sizeof go);
        memcpy(gd, r->d, sizeof gd);
        if (p->sc->grid.rotated) {
            rt_grid_point(&p->sc->grid, r->o, go);
            rt_grid_dir(&p->sc->grid, r->d, gd);
        }
        if (memcmp(&go[p->K], &p->oK[k], sizeof go[0]) ||
            memcmp(&gd[p->K], &p->dK[k], sizeof gd[0])) {
            atomic_fetch_add_explicit(&rt_pk_make_differ, 1, memory_order_relaxed);
            p->oK[k] = go[p->K];
            p->dK[k] = gd[p->K];
        }
#endif
    }
    p->made |= m;
}

/* a hit of primitive i at t on ray k (q: triangle i's part of the error bound, made once
   for the packet's rays by rt_tri_err_init; NULL for another kind) */
static void rt_pk_hit(rt_pk *p, int k, uint32_t i, double t, const rt_tri_err *q)
{
    if (p->any) {
        p->hit |= (uint64_t)1 << k;
        p->live &= ~((uint64_t)1 << k);
        p->cand &= ~((uint64_t)1 << k);
        return;
    }
    p->hit |= (uint64_t)1 << k; /* nearest: rays with a hit */
    if (p->nh[k] < RT_PK_REC)
        p->rec[p->nh[k]++][k] = (rt_pk_rec){i, t};
    else
        p->over |= (uint64_t)1 << k;
    const long old = p->bi[k];
    if (q)
        rt_nearest_update_tri(p->sc, &p->r[k], i, t, q, &p->best[k], &p->bi[k], &p->eb[k]);
    else
        rt_nearest_update(p->sc, &p->r[k], i, t, &p->best[k], &p->bi[k], &p->eb[k]);
    if (p->bi[k] != old) { /* the walk's end: beyond the best hit's window (4 bounds) */
        const double te = p->best[k] + 4.0 * p->eb[k];
        const double tend = te < p->t1[k] ? te : p->t1[k];
        const double ue = p->sg * (p->oK[k] + tend * p->dK[k]);
        /* a new best whose window reaches further than the last one's (a larger error
           bound): cells between the two ends may have been passed over for this ray, so its
           hits are not known to be complete: the single-ray walk decides */
        if (ue > p->ue[k])
            p->over |= (uint64_t)1 << k;
        else
            p->ue[k] = ue;
        p->uemin = p->ue[k] < p->uemin ? p->ue[k] : p->uemin;
    }
}

/* 1 if triangle v lies wholly outside the packet's frustum (of the rays still walking) on
   one side along a1 or a2: the frustum's crossings of the plane z along K lie between
   xl(z) = lo + (z - z0) * (z >= z0 ? mlo : mhi) and xh(z) likewise with mhi, mlo; xl is
   concave and xh convex, so the points below xl (above xh) form a convex set, and a triangle
   whose three vertices lie there (by the margin of 2^-20 of a top cell, for the roundings)
   lies there whole and meets no ray of the frustum. In the grid frame: a rotated grid's
   vertices are taken into it first (their roundings far below the margin). */
#ifdef RT_PK_X86
static uint64_t rt_pk_pre_avx2(rt_pk *p, const double *const v[3], uint64_t m);
static uint64_t rt_pk_pre_avx512(rt_pk *p, const double *const v[3], uint64_t m);
static void rt_pk_steps(rt_pk *p);
#endif
static inline int rt_pk_outside(const rt_pk *p, const double *const v[3])
{
    int below[2] = {1, 1}, above[2] = {1, 1};
    for (int j = 0; j < 3; j++) {
        const double dz = v[j][p->K] - p->z0;
        for (int a = 0; a < 2; a++) {
            const double x = v[j][a ? p->a2 : p->a1];
            const double xl = p->lo[a] + dz * (dz >= 0.0 ? p->mlo[a] : p->mhi[a]);
            const double xh = p->hi[a] + dz * (dz >= 0.0 ? p->mhi[a] : p->mlo[a]);
            below[a] &= x < xl - p->xmg[a];
            above[a] &= x > xh + p->xmg[a];
        }
    }
    return below[0] | below[1] | above[0] | above[1];
}

/* primitive i for the rays of m (rt_pk_prim: those of the slice that have not tested it) */
static __attribute__((noinline)) void rt_pk_test(rt_pk *p, rt_pk_cull_fn cull, uint32_t i,
                                                 uint64_t m)
{
    const rt_scene *sc = p->sc;
    if (i < sc->ntri) {
        const double *v[3];
        rt_tri_verts(sc, i, v);
        /* the vertices in the grid frame (a rotated grid's: their roundings far below the
           frustum's margin) */
        const rt_grid *g = &sc->grid;
        double w[3][3];
        const double *gv[3] = {v[0], v[1], v[2]};
        if (g->rotated)
            for (int j = 0; j < 3; j++) {
                rt_pk_gpoint(g, v[j], w[j]);
                gv[j] = w[j];
            }
#ifdef RT_PK_X86
        if (rt_pk_avx512) /* the frustum, then its steps' frusta */
            m = rt_pk_pre_avx512(p, gv, m);
        else if (rt_pk_avx2)
            m = rt_pk_pre_avx2(p, gv, m);
        else
#endif
            if (rt_pk_outside(p, gv))
            m = 0;
        if (!m)
            return;
#ifdef RT_PK_X86
        if (p->any && rt_pk_avx2) {
            uint64_t sure;
            m = rt_pk_avx512 ? rt_pk_cull_any_avx512(p, v[0], v[1], v[2], m, &sure)
                             : rt_pk_cull_any_avx2(p, v[0], v[1], v[2], m, &sure);
            if (sure) { /* hits, as the exact test finds them */
                p->hit |= sure;
                p->live &= ~sure;
                p->cand &= ~sure;
                m &= ~sure;
            }
        } else
#endif
            m = cull(p, v[0], v[1], v[2], m);
        rt_pk_make(p, m);
        rt_tri_err q;
        int haveq = 0; /* q made at the first nearest hit */
        for (; m; m &= m - 1) {
            const int k = __builtin_ctzll(m);
            double t;
            if (rt_isect_tri(&p->r[k], v[0], v[1], v[2], p->r[k].tmin, p->r[k].tmax, &t)) {
                if (!haveq && !p->any) {
                    rt_tri_err_init(sc, i, &q);
                    haveq = 1;
                }
                rt_pk_hit(p, k, i, t, &q);
            }
        }
        return;
    }
    rt_pk_make(p, m);
    for (; m; m &= m - 1) {
        const int k = __builtin_ctzll(m);
        double t;
        if (rt_isect_prim(sc, &p->r[k], i, p->r[k].tmin, p->r[k].tmax, &t))
            rt_pk_hit(p, k, i, t, NULL);
    }
}

/* primitive i for the rays of p->cand (an any-hit packet's: p->live) that have not tested
   it in this packet (the small mailbox with the rays each entry was tested for; an entry
   taken by another primitive only repeats tests, which give the same hits). Inline: most
   visits are repeats (64 % of bunny's primary ones), which end here without a call. An
   any-hit packet (any, a constant: the walk is made for each kind of packet) tests for
   p->live, a subset of the rays of every earlier test of the packet, so an entry that holds
   i ends the visit and its rays are neither read nor kept (6 % fewer D1 misses). */
static inline __attribute__((always_inline)) void rt_pk_prim(rt_pk *p, rt_pk_cull_fn cull,
                                                             uint32_t i, const int any)
{
    const uint64_t key = p->key | i;
    const uint32_t j = i % RT_HBOX;
    uint64_t m = p->cand;
    if (any) {
        if (p->hbox[j] == key)
            return;
        p->hbox[j] = key;
        rt_pk_test(p, cull, i, m);
        return;
    }
    if (p->hbox[j] == key) {
        m &= ~p->tmask[j];
        if (!m)
            return;
        p->tmask[j] |= m;
    } else {
        p->hbox[j] = key;
        p->tmask[j] = m;
    }
    rt_pk_test(p, cull, i, m);
}

static inline __attribute__((always_inline)) void
rt_pk_list(rt_pk *p, rt_pk_cull_fn cull, const uint32_t *refs, uint32_t n, const int any)
{
    for (uint32_t k = 0; k < n && p->cand; k++)
        rt_pk_prim(p, cull, refs[k], any);
}

#ifdef RT_PK_X86
/* the rays k of mask with us[k] <= ub and ue[k] >= ua (AVX2, 8 rays a step without a
   branch per step, then 4; the lanes of the packet's rays not in the mask hold finite
   values, set by rt_pk_setup) */
__attribute__((target("avx2"))) static uint64_t rt_pk_in_avx2(const rt_pk *p, uint64_t mask,
                                                              double ua, double ub)
{
    const __m256d va = _mm256_set1_pd(ua), vb = _mm256_set1_pd(ub);
    uint64_t in = 0;
    int k = 0;
    for (; k + 8 <= p->n; k += 8) {
        const __m256d a0 = _mm256_cmp_pd(_mm256_loadu_pd(p->us + k), vb, _CMP_LE_OQ);
        const __m256d b0 = _mm256_cmp_pd(_mm256_loadu_pd(p->ue + k), va, _CMP_GE_OQ);
        const __m256d a1 = _mm256_cmp_pd(_mm256_loadu_pd(p->us + k + 4), vb, _CMP_LE_OQ);
        const __m256d b1 = _mm256_cmp_pd(_mm256_loadu_pd(p->ue + k + 4), va, _CMP_GE_OQ);
        const unsigned m = (unsigned)_mm256_movemask_pd(_mm256_and_pd(a0, b0)) |
                           (unsigned)_mm256_movemask_pd(_mm256_and_pd(a1, b1)) << 4;
        in |= (uint64_t)m << k;
    }
    for (; k < p->n; k += 4) {
        const __m256d a = _mm256_cmp_pd(_mm256_loadu_pd(p->us + k), vb, _CMP_LE_OQ);
        const __m256d b = _mm256_cmp_pd(_mm256_loadu_pd(p->ue + k), va, _CMP_GE_OQ);
        in |= (uint64_t)_mm256_movemask_pd(_mm256_and_pd(a, b)) << k;
    }
    return in & mask;
}

/* the frustum of the rays of mask (rt_pk_frustum; the same values: the least and the
   greatest of the same crossings, in another order) */
__attribute__((target("avx2"))) static void rt_pk_frustum_avx2(rt_pk *p, uint64_t mask)
{
    const __m256d z0 = _mm256_set1_pd(p->z0), pinf = _mm256_set1_pd(INFINITY),
                  ninf = _mm256_set1_pd(-INFINITY);
    __m256d lo1 = pinf, lo2 = pinf, hi1 = ninf, hi2 = ninf, ml1 = pinf, ml2 = pinf,
            mh1 = ninf, mh2 = ninf;
    for (int k = 0; k < p->n; k += 4) {
        if (!((mask >> k) & 15u))
            continue;
        const __m256d sel = rt_pk_lanes(mask, k);
        const __m256d dz = _mm256_sub_pd(z0, _mm256_loadu_pd(p->oK + k));
        const __m256d m1 = _mm256_loadu_pd(p->m1 + k), m2 = _mm256_loadu_pd(p->m2 + k);
        const __m256d x1 = _mm256_add_pd(_mm256_loadu_pd(p->o1 + k), _mm256_mul_pd(dz, m1));
        const __m256d x2 = _mm256_add_pd(_mm256_loadu_pd(p->o2 + k), _mm256_mul_pd(dz, m2));
        lo1 = _mm256_min_pd(lo1, _mm256_blendv_pd(pinf, x1, sel));
        lo2 = _mm256_min_pd(lo2, _mm256_blendv_pd(pinf, x2, sel));
        hi1 = _mm256_max_pd(hi1, _mm256_blendv_pd(ninf, x1, sel));
        hi2 = _mm256_max_pd(hi2, _mm256_blendv_pd(ninf, x2, sel));
        ml1 = _mm256_min_pd(ml1, _mm256_blendv_pd(pinf, m1, sel));
        ml2 = _mm256_min_pd(ml2, _mm256_blendv_pd(pinf, m2, sel));
        mh1 = _mm256_max_pd(mh1, _mm256_blendv_pd(ninf, m1, sel));
        mh2 = _mm256_max_pd(mh2, _mm256_blendv_pd(ninf, m2, sel));
    }
    double v[8][4];
    _mm256_storeu_pd(v[0], lo1);
    _mm256_storeu_pd(v[1], lo2);
    _mm256_storeu_pd(v[2], hi1);
    _mm256_storeu_pd(v[3], hi2);
    _mm256_storeu_pd(v[4], ml1);
    _mm256_storeu_pd(v[5], ml2);
    _mm256_storeu_pd(v[6], mh1);
    _mm256_storeu_pd(v[7], mh2);
    for (int a = 0; a < 2; a++) {
        p->lo[a] = fmin(fmin(v[a][0], v[a][1]), fmin(v[a][2], v[a][3]));
        p->hi[a] = fmax(fmax(v[2 + a][0], v[2 + a][1]), fmax(v[2 + a][2], v[2 + a][3]));
        p->mlo[a] = fmin(fmin(v[4 + a][0], v[4 + a][1]), fmin(v[4 + a][2], v[4 + a][3]));
        p->mhi[a] = fmax(fmax(v[6 + a][0], v[6 + a][1]), fmax(v[6 + a][2], v[6 + a][3]));
    }
    for (int a = 0; a < 2; a++) { /* rt_pk_outside_avx2's lanes */
        p->ob[2 * a] = p->lo[a];
        p->ob[2 * a + 1] = -p->hi[a];
        p->osp[2 * a] = p->mlo[a];
        p->osp[2 * a + 1] = -p->mhi[a];
        p->osn[2 * a] = p->mhi[a];
        p->osn[2 * a + 1] = -p->mlo[a];
        p->omg[2 * a] = p->omg[2 * a + 1] = p->xmg[a];
        p->rb[2 * a] = p->lo[a];
        p->rb[2 * a + 1] = p->hi[a];
        p->rsp[2 * a] = p->mlo[a];
        p->rsp[2 * a + 1] = p->mhi[a];
        p->rsn[2 * a] = p->mhi[a];
        p->rsn[2 * a + 1] = p->mlo[a];
    }
}

/* rt_pk_rect with the four bounds in lanes (lo1, hi1, lo2, hi2), the same values: the
   lower bounds the min of their values at za and zb, the upper ones the max (min_pd and
   max_pd select as the scalar compares do), then rt_pk_cell's operations and clamps */
__attribute__((target("avx2"))) static void rt_pk_rect_avx2(const rt_pk *p, const rt_box *g,
                                                            double za, double zb, int c[4])
{
    const double da = za - p->z0, db = zb - p->z0;
    const __m256d b = _mm256_loadu_pd(p->rb), sp = _mm256_loadu_pd(p->rsp),
                  sn = _mm256_loadu_pd(p->rsn);
    const __m256d xa = _mm256_add_pd(b, _mm256_mul_pd(_mm256_set1_pd(da), da >= 0.0 ? sp : sn));
    const __m256d xb = _mm256_add_pd(b, _mm256_mul_pd(_mm256_set1_pd(db), db >= 0.0 ? sp : sn));
    /* lanes 0, 2: min; 1, 3: max */
    const __m256d x = _mm256_blend_pd(_mm256_min_pd(xa, xb), _mm256_max_pd(xa, xb), 10);
    const int a1 = p->a1, a2 = p->a2;
    const __m256d lo = _mm256_set_pd(g->lo[a2], g->lo[a2], g->lo[a1], g->lo[a1]);
    const __m256d iw = _mm256_set_pd(g->inv_cw[a2], g->inv_cw[a2], g->inv_cw[a1], g->inv_cw[a1]);
    const __m256d top = _mm256_set_pd((double)(g->n[a2] - 1), (double)(g->n[a2] - 1),
                                      (double)(g->n[a1] - 1), (double)(g->n[a1] - 1));
    const __m256d mg = _mm256_set_pd(RT_PK_MARGIN, -RT_PK_MARGIN, RT_PK_MARGIN, -RT_PK_MARGIN);
    /* f = (x - lo) * inv_cw + dir * margin; f <= 0: 0, f >= n - 1: n - 1, else (int)f */
    const __m256d f = _mm256_add_pd(_mm256_mul_pd(_mm256_sub_pd(x, lo), iw), mg);
    const __m256d fc = _mm256_min_pd(_mm256_max_pd(f, _mm256_setzero_pd()), top);
    _mm_storeu_si128((__m128i *)c, _mm256_cvttpd_epi32(fc));
}

/* rt_pk_outside for the vertices v (in the grid frame) with the same values: lanes 0 and 2
   test x < xl - mg along a1 and a2, lanes 1 and 3 x > xh + mg as -x < -(xh + mg), which is
   (-hi + dz (-m)) - mg with the same roundings (negation is exact and rounding is symmetric) */
static inline __attribute__((target("avx2"), always_inline)) int
rt_pk_outside_avx2(const rt_pk *p, const double *const v[3])
{
    const __m256d b = _mm256_loadu_pd(p->ob), sp = _mm256_loadu_pd(p->osp),
                  sn = _mm256_loadu_pd(p->osn), mg = _mm256_loadu_pd(p->omg);
    const __m256d flip = _mm256_set_pd(-0.0, 0.0, -0.0, 0.0); /* lanes 1 and 3 negated */
    __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    for (int j = 0; j < 3; j++) {
        const double dz = v[j][p->K] - p->z0;
        const __m256d bound =
            _mm256_sub_pd(_mm256_add_pd(b, _mm256_mul_pd(_mm256_set1_pd(dz), dz >= 0.0 ? sp : sn)),
                          mg);
        const __m256d x = _mm256_xor_pd(
            _mm256_set_pd(v[j][p->a2], v[j][p->a2], v[j][p->a1], v[j][p->a1]), flip);
        all = _mm256_and_pd(all, _mm256_cmp_pd(x, bound, _CMP_LT_OQ));
    }
    return _mm256_movemask_pd(all) != 0;
}

/* lane j of the result: the least (mx 0) or greatest (1) of the four lanes of a[j] */
__attribute__((target("avx2"))) static inline __m256d rt_pk_hred(const __m256d a[4], int mx)
{
    const __m256d l01 = _mm256_unpacklo_pd(a[0], a[1]), h01 = _mm256_unpackhi_pd(a[0], a[1]);
    const __m256d l23 = _mm256_unpacklo_pd(a[2], a[3]), h23 = _mm256_unpackhi_pd(a[2], a[3]);
    const __m256d t0 = mx ? _mm256_max_pd(l01, h01) : _mm256_min_pd(l01, h01);
    const __m256d t1 = mx ? _mm256_max_pd(l23, h23) : _mm256_min_pd(l23, h23);
    const __m256d u0 = _mm256_permute2f128_pd(t0, t1, 0x20),
                  u1 = _mm256_permute2f128_pd(t0, t1, 0x31);
    return mx ? _mm256_max_pd(u0, u1) : _mm256_min_pd(u0, u1);
}

/* the axis of the steps' test (p->sax): the one where the first step with a ray walked is
   narrower against the packet (widths at z0 plus the slopes' spread times the walk's
   greatest distance from z0; a step of an 8x8 block is a half row, thin across it). Only a choice: values
   beyond 1e100 (none is NaN) leave a1. */
static int rt_pk_steps_axis(const rt_pk *p)
{
    const double far = fmin(fmax(fabs(p->sg * p->uemax - p->z0), fabs(p->sg * p->usmin - p->z0)),
                            1e100);
    const int s0 = __builtin_ctzll(p->live) / 4;
    double r[2];
    for (int a = 0; a < 2; a++) {
        const double *o = a ? p->o2 : p->o1, *m = a ? p->m2 : p->m1;
        double lo = INFINITY, hi = -INFINITY, ml = INFINITY, mh = -INFINITY;
        for (int k = 4 * s0; k < 4 * s0 + 4 && k < p->n; k++) {
            if (!((p->live >> k) & 1u))
                continue;
            const double x = o[k] + (p->z0 - p->oK[k]) * m[k];
            lo = x < lo ? x : lo;
            hi = x > hi ? x : hi;
            ml = m[k] < ml ? m[k] : ml;
            mh = m[k] > mh ? m[k] : mh;
        }
        if (!((fabs(lo) <= 1e100) & (fabs(hi) <= 1e100) & (fabs(ml) <= 1e100) &
              (fabs(mh) <= 1e100) & (fabs(p->lo[a]) <= 1e100) & (fabs(p->hi[a]) <= 1e100) &
              (fabs(p->mlo[a]) <= 1e100) & (fabs(p->mhi[a]) <= 1e100)))
            return 0;
        const double pw = (p->hi[a] - p->lo[a]) + far * (p->mhi[a] - p->mlo[a]);
        if (!(pw > 0.0))
            return 0;
        r[a] = ((hi - lo) + far * (mh - ml)) / pw;
    }
    return r[1] < r[0];
}

/* the frusta of the cull kernel's steps along p->sax (p->stb, stp, stn) from the rays of
   p->live at p->z0: for each step the frustum of rt_pk_frustum (the same crossings of z0
   and slopes) of its rays walked; a step without one gets bounds of +inf (every triangle
   outside it) */
__attribute__((target("avx2"))) static void rt_pk_steps(rt_pk *p)
{
    const __m256d z0 = _mm256_set1_pd(p->z0), pinf = _mm256_set1_pd(INFINITY),
                  ninf = _mm256_set1_pd(-INFINITY), zero = _mm256_setzero_pd();
    const __m256d neg = _mm256_set1_pd(-0.0);
    p->sax = rt_pk_steps_axis(p);
    const int a = p->sax;
    const double *oa = a ? p->o2 : p->o1, *ma = a ? p->m2 : p->m1;
    const __m256d mg = _mm256_set1_pd(p->xmg[a]);
    for (int k0 = 0; k0 < RT_PACKET; k0 += 16) { /* all 16 steps: the AVX-512 test reads 8 */
        /* q[c][i]: quantity c of the rays of step k0 / 4 + i (lanes: its four rays), set to
           +inf (c even: a least) or -inf (odd: a greatest) for rays not walked */
        __m256d q[4][4];
        for (int i = 0; i < 4; i++) {
            const int k = k0 + 4 * i;
            if (k >= p->n) { /* no rays (lanes past n may hold anything) */
                for (int c = 0; c < 4; c++)
                    q[c][i] = c & 1 ? ninf : pinf;
                continue;
            }
            const __m256d sel = rt_pk_lanes(p->live, k);
            const __m256d dz = _mm256_sub_pd(z0, _mm256_loadu_pd(p->oK + k));
            const __m256d m = _mm256_loadu_pd(ma + k);
            const __m256d x = _mm256_add_pd(_mm256_loadu_pd(oa + k), _mm256_mul_pd(dz, m));
            q[0][i] = _mm256_blendv_pd(pinf, x, sel);
            q[1][i] = _mm256_blendv_pd(ninf, x, sel);
            q[2][i] = _mm256_blendv_pd(pinf, m, sel);
            q[3][i] = _mm256_blendv_pd(ninf, m, sel);
        }
        /* lo, hi, mlo, mhi per step */
        const __m256d lo = rt_pk_hred(q[0], 0), hi = rt_pk_hred(q[1], 1),
                      ml = rt_pk_hred(q[2], 0), mh = rt_pk_hred(q[3], 1);
        /* a step without rays walked: lo = +inf: bounds +inf, slopes 0 */
        const __m256d none = _mm256_cmp_pd(lo, pinf, _CMP_EQ_OQ);
        const int s = k0 / 4;
        _mm256_storeu_pd(p->stb[2 * a] + s, _mm256_blendv_pd(_mm256_sub_pd(lo, mg), pinf, none));
        _mm256_storeu_pd(p->stb[2 * a + 1] + s,
                         _mm256_blendv_pd(_mm256_sub_pd(_mm256_xor_pd(hi, neg), mg), pinf, none));
        _mm256_storeu_pd(p->stp[2 * a] + s, _mm256_blendv_pd(ml, zero, none));
        _mm256_storeu_pd(p->stp[2 * a + 1] + s,
                         _mm256_blendv_pd(_mm256_xor_pd(mh, neg), zero, none));
        _mm256_storeu_pd(p->stn[2 * a] + s, _mm256_blendv_pd(mh, zero, none));
        _mm256_storeu_pd(p->stn[2 * a + 1] + s,
                         _mm256_blendv_pd(_mm256_xor_pd(ml, neg), zero, none));
    }
    p->steps = 1;
}

/* the rays of m in the steps whose frustum may meet triangle v (in the grid frame): a step
   is ruled out when the three vertices lie beyond one of its two bounds along p->sax, by the
   margin (rt_pk_outside's test and argument, on the step's frustum; the margin is taken
   from the bound at z0 before the slope's part is added, a rounding apart, far below it).
   Four steps without a ray of m are skipped (shadow packets: rays that ended). */
static inline __attribute__((target("avx2"), always_inline)) uint64_t
rt_pk_steps_in(const rt_pk *p, const double *const v[3], uint64_t m)
{
    /* bit i of a 4-bit mask to bit 4i: the rays of step i */
    static const uint16_t spread[16] = {0x0000, 0x000f, 0x00f0, 0x00ff, 0x0f00, 0x0f0f,
                                        0x0ff0, 0x0fff, 0xf000, 0xf00f, 0xf0f0, 0xf0ff,
                                        0xff00, 0xff0f, 0xfff0, 0xffff};
    double dz[3];
    const double *sl[3];
    __m256d x[3][2];
    const int b0 = 2 * p->sax, ax = p->sax ? p->a2 : p->a1;
    for (int j = 0; j < 3; j++) {
        dz[j] = v[j][p->K] - p->z0;
        sl[j] = dz[j] >= 0.0 ? &p->stp[b0][0] : &p->stn[b0][0];
        x[j][0] = _mm256_set1_pd(v[j][ax]);
        x[j][1] = _mm256_set1_pd(-v[j][ax]);
    }
    uint64_t in = 0;
    const int ns = (p->n + 3) / 4;
    for (int s = 0; s < ns; s += 4) {
        if (!((m >> (4 * s)) & 0xffffu))
            continue; /* no ray of m in these four steps */
        __m256d out = _mm256_setzero_pd();
        for (int b = 0; b < 2; b++) {
            const __m256d base = _mm256_loadu_pd(p->stb[b0 + b] + s);
            __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
            for (int j = 0; j < 3; j++) {
                const __m256d bound = _mm256_add_pd(
                    base, _mm256_mul_pd(_mm256_set1_pd(dz[j]),
                                        _mm256_loadu_pd(sl[j] + b * (RT_PACKET / 4) + s)));
                all = _mm256_and_pd(all, _mm256_cmp_pd(x[j][b], bound, _CMP_LT_OQ));
            }
            out = _mm256_or_pd(out, all);
        }
        in |= (uint64_t)spread[~_mm256_movemask_pd(out) & 15] << (4 * s);
    }
    return in & m;
}

/* the rays of m that may meet triangle v (in the grid frame): none if it lies outside the
   packet's frustum (rt_pk_outside), else those of the steps whose frusta it may meet
   (rt_pk_steps_in, once rt_pk_ends made the steps' frusta) */
__attribute__((target("avx2"))) static uint64_t rt_pk_pre_avx2(rt_pk *p, const double *const v[3],
                                                               uint64_t m)
{
    if (rt_pk_outside_avx2(p, v))
        return 0;
    return p->steps ? rt_pk_steps_in(p, v, m) : m;
}

/* rt_pk_steps_in with AVX-512: 8 steps at a time (the same bounds and compares per step) */
static inline RT_PK_AVX512 __attribute__((always_inline)) uint64_t
rt_pk_steps_in_avx512(const rt_pk *p, const double *const v[3], uint64_t m)
{
    /* bit i of a 4-bit mask to bit 4i: the rays of step i */
    static const uint16_t spread[16] = {0x0000, 0x000f, 0x00f0, 0x00ff, 0x0f00, 0x0f0f,
                                        0x0ff0, 0x0fff, 0xf000, 0xf00f, 0xf0f0, 0xf0ff,
                                        0xff00, 0xff0f, 0xfff0, 0xffff};
    double dz[3];
    const double *sl[3];
    __m512d x[3][2];
    const int b0 = 2 * p->sax, ax = p->sax ? p->a2 : p->a1;
    for (int j = 0; j < 3; j++) {
        dz[j] = v[j][p->K] - p->z0;
        sl[j] = dz[j] >= 0.0 ? &p->stp[b0][0] : &p->stn[b0][0];
        x[j][0] = _mm512_set1_pd(v[j][ax]);
        x[j][1] = _mm512_set1_pd(-v[j][ax]);
    }
    uint64_t in = 0;
    const int ns = (p->n + 3) / 4;
    for (int s = 0; s < ns; s += 8) {
        if (!((m >> (4 * s)) & 0xffffffffu))
            continue; /* no ray of m in these eight steps */
        __mmask8 out = 0;
        for (int b = 0; b < 2; b++) {
            const __m512d base = _mm512_loadu_pd(p->stb[b0 + b] + s);
            __mmask8 all = 0xff;
            for (int j = 0; j < 3; j++) {
                const __m512d bound = _mm512_add_pd(
                    base, _mm512_mul_pd(_mm512_set1_pd(dz[j]),
                                        _mm512_loadu_pd(sl[j] + b * (RT_PACKET / 4) + s)));
                all = _mm512_mask_cmp_pd_mask(all, x[j][b], bound, _CMP_LT_OQ);
            }
            out |= all;
        }
        const unsigned i8 = (unsigned)(__mmask8)~out;
        in |= ((uint64_t)spread[i8 & 15u] | (uint64_t)spread[i8 >> 4] << 16) << (4 * s);
    }
    return in & m;
}

/* rt_pk_pre_avx2 with the steps' test in AVX-512 */
RT_PK_AVX512 static uint64_t rt_pk_pre_avx512(rt_pk *p, const double *const v[3], uint64_t m)
{
    if (rt_pk_outside_avx2(p, v))
        return 0;
    return p->steps ? rt_pk_steps_in_avx512(p, v, m) : m;
}
#endif

/* ---- the walk by slices ---- */

/* the frustum of the rays of mask (kept while the mask stays) */
static void rt_pk_frustum(rt_pk *p, uint64_t mask)
{
    if (mask == p->fmask)
        return;
    p->fmask = mask;
#ifdef RT_PK_X86
    if (rt_pk_avx2) {
        rt_pk_frustum_avx2(p, mask);
        return;
    }
#endif
    const double z0 = p->z0;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    double mlo[2] = {INFINITY, INFINITY}, mhi[2] = {-INFINITY, -INFINITY};
    for (; mask; mask &= mask - 1) {
        const int k = __builtin_ctzll(mask);
        const double x[2] = {p->o1[k] + (z0 - p->oK[k]) * p->m1[k],
                             p->o2[k] + (z0 - p->oK[k]) * p->m2[k]};
        const double m[2] = {p->m1[k], p->m2[k]};
        for (int a = 0; a < 2; a++) {
            lo[a] = x[a] < lo[a] ? x[a] : lo[a];
            hi[a] = x[a] > hi[a] ? x[a] : hi[a];
            mlo[a] = m[a] < mlo[a] ? m[a] : mlo[a];
            mhi[a] = m[a] > mhi[a] ? m[a] : mhi[a];
        }
    }
    memcpy(p->lo, lo, sizeof lo);
    memcpy(p->hi, hi, sizeof hi);
    memcpy(p->mlo, mlo, sizeof mlo);
    memcpy(p->mhi, mhi, sizeof mhi);
}

/* the rectangle of cells along a1, a2 of box g that holds the frustum between the planes
   z = za and z = zb (each ray x(z) = x(z0) + (z - z0) m is bounded by the frustum's
   x range at z0 and its slope range): c[0..3] = lo1, hi1, lo2, hi2 */
static void rt_pk_rect(const rt_pk *p, const rt_box *g, double za, double zb, int c[4])
{
#ifdef RT_PK_X86
    if (rt_pk_avx2) {
        rt_pk_rect_avx2(p, g, za, zb, c);
        return;
    }
#endif
    const double da = za - p->z0, db = zb - p->z0;
    for (int a = 0; a < 2; a++) {
        const double la = p->lo[a] + da * (da >= 0.0 ? p->mlo[a] : p->mhi[a]);
        const double lb = p->lo[a] + db * (db >= 0.0 ? p->mlo[a] : p->mhi[a]);
        const double ha = p->hi[a] + da * (da >= 0.0 ? p->mhi[a] : p->mlo[a]);
        const double hb = p->hi[a] + db * (db >= 0.0 ? p->mhi[a] : p->mlo[a]);
        const int ax = a ? p->a2 : p->a1;
        c[2 * a] = rt_pk_cell(g, ax, la < lb ? la : lb, -1.0);
        c[2 * a + 1] = rt_pk_cell(g, ax, ha > hb ? ha : hb, 1.0);
    }
}

/* plane b (0 .. n) of axis a of box g, as the single-ray walk computes it */
static inline double rt_pk_plane(const rt_box *g, int a, int b)
{
    return b == g->n[a] ? g->hi[a] : g->lo[a] + (double)b * g->cw[a];
}

/* the rays of mask whose extent along K meets the slice between za and zb */
static inline uint64_t rt_pk_in(const rt_pk *p, uint64_t mask, double za, double zb)
{
    const double ua = p->sg > 0 ? za : -zb, ub = p->sg > 0 ? zb : -za;
    if (p->usmax <= ub + p->umg && p->uemin >= ua - p->umg)
        return mask; /* every ray meets it (the common case) */
#ifdef RT_PK_X86
    if (rt_pk_avx2)
        return rt_pk_in_avx2(p, mask, ua - p->umg, ub + p->umg);
#endif
    uint64_t in = 0;
    for (; mask; mask &= mask - 1) {
        const int k = __builtin_ctzll(mask);
        if (p->us[k] <= ub + p->umg && p->ue[k] >= ua - p->umg)
            in |= (uint64_t)1 << k;
    }
    return in;
}

/* a second-level grid's cell lists in either layout (rt_internal.h): 4-byte offsets into
   srefs, or 2-byte ones (off16) into srefs or into 2-byte references r16 to its table loc */
typedef struct rt_pk_lists {
    const uint16_t *off16;
    const uint32_t *off, *srefs;
    const uint16_t *r16;
    const uint32_t *loc;
} rt_pk_lists;

/* the references of cells c0 .. c1 - 1 of a second-level grid, consecutive in its lists */
static inline __attribute__((always_inline)) void
rt_pk_cells(rt_pk *p, rt_pk_cull_fn cull, const rt_pk_lists *l, size_t c0, size_t c1,
            const int any)
{
    const uint32_t k0 = l->off16 ? l->off16[c0] : l->off[c0],
                   k1 = l->off16 ? l->off16[c1] : l->off[c1];
    if (l->r16)
        for (uint32_t k = k0; k < k1; k++)
            rt_pk_prim(p, cull, l->loc[l->r16[k]], any);
    else
        rt_pk_list(p, cull, l->srefs + k0, k1 - k0, any);
}

/* the second-level grid sg inside a top cell: its slices along K in the rays' direction,
   for the rays of the top slice (in) that meet each (an any-hit packet: for its rays still
   walking of in, those that may hit the sub-grid's triangles). 0 if a slice's footprint is
   too large (not coherent). */
static inline __attribute__((always_inline)) int
rt_pk_sub(rt_pk *p, rt_pk_cull_fn cull, const rt_subgrid *sg, uint64_t in, const int any)
{
    const rt_grid *g = &p->sc->grid;
    const rt_box *b = &sg->b;
    const int K = p->K, nK = b->n[K];
    const rt_pk_lists l = {
        .off16 = g->soff16 ? g->soff16 + sg->first16 : NULL,
        .off = g->soff16 ? NULL : g->soff + sg->first,
        .srefs = g->sref16 ? NULL : g->soff16 ? g->srefs + sg->ref0 : g->srefs,
        .r16 = g->sref16 ? g->sref16 + sg->ref0 : NULL,
        .loc = g->sref16 ? g->sloc + sg->loc0 : NULL,
    };
    /* a cell's index (rt_cell_index) in steps along each axis */
    const size_t st[3] = {1, (size_t)b->n[0], (size_t)b->n[0] * (size_t)b->n[1]};
    for (int j = 0; j < nK; j++) {
        const int s = p->sg > 0 ? j : nK - 1 - j;
        const double za = rt_pk_plane(b, K, s), zb = rt_pk_plane(b, K, s + 1);
        if (any) { /* between the first start and the last end; every ray walking */
            const double ua = p->sg > 0 ? za : -zb, ub = p->sg > 0 ? zb : -za;
            if (!(p->usmin <= ub + p->umg && p->uemax >= ua - p->umg))
                continue;
            p->cand = p->live & in;
            if (!p->cand)
                continue;
        } else {
            p->cand = rt_pk_in(p, in & p->live, za, zb);
            if (!p->cand)
                continue;
        }
        int c[4];
        rt_pk_rect(p, b, za, zb, c);
        if ((c[1] - c[0] + 1) * (c[3] - c[2] + 1) > RT_PK_MAXS)
            return 0;
        /* the rectangle by rows along the inner axis ia: along the grid's x axis (a1, or
           a2 for an any-hit packet, whose answers do not depend on the order of its tests)
           a row's cells are consecutive and their lists lie one after another, read as one
           list (the same primitives in the same order as cell by cell, without the loop's
           branches per cell: most of the cells met are empty) */
        const int swap = any && p->a2 == 0;
        const int ia = swap ? p->a2 : p->a1, oa = swap ? p->a1 : p->a2;
        const int ilo = c[2 * swap], ihi = c[2 * swap + 1];
        const int olo = c[2 - 2 * swap], ohi = c[3 - 2 * swap];
        const size_t si = st[ia], so = st[oa];
        size_t row = (size_t)s * st[K] + (size_t)olo * so + (size_t)ilo * si;
        for (int o = olo; o <= ohi; o++, row += so) {
            if (ia == 0) { /* the row as one list */
                rt_pk_cells(p, cull, &l, row, row + (size_t)(ihi - ilo + 1), any);
                continue;
            }
            size_t ci = row;
            for (int i = ilo; i <= ihi; i++, ci += si)
                rt_pk_cells(p, cull, &l, ci, ci + 1, any);
        }
    }
    return 1;
}

/* the rays of mask whose segment [tmin, tmax] may cross the flat sub-grid of plane j - 1 of
   rt_grid.splanes: those of the others lie beyond its slab by the margin on one side, so
   they cannot hit its triangles anywhere (rt_flat_beyond, as rt_trace.c's rt_sub_flat;
   docs/RAYTRACING.md, "Flat sub-grids"). The any-hit mailbox (rt_pk_prim) then
   holds a primitive tested for the rays of the test, each ray still walking either tested
   it or cannot hit it: a ray left out that meets one of those triangles in another cell
   skips it there too, rightly. Out of line: most cells have no flat sub-grid. */
static __attribute__((noinline)) uint64_t rt_pk_flat(rt_pk *p, uint32_t j, uint64_t mask)
{
    const rt_subplane *pl = &p->sc->grid.splanes[j - 1];
    /* a ray's segment values once per packet: an any-hit ray's segment does not change */
    for (uint64_t m = mask & ~p->fsok; m; m &= m - 1) {
        const int k = __builtin_ctzll(m);
        const rt_ray *r = &p->rays[k];
        rt_flatseg_init(&p->fs[k], r->org, r->dir, r->tmin, r->tmax, p->sc->scale);
    }
    p->fsok |= mask;
    uint64_t keep = 0;
    for (; mask; mask &= mask - 1) {
        const int k = __builtin_ctzll(mask);
        if (!rt_flat_beyond(pl, &p->fs[k]))
            keep |= (uint64_t)1 << k;
    }
    return keep;
}

/* one top cell for the rays of the slice (in): its own list, then its second-level grid;
   0: not coherent */
static inline __attribute__((always_inline)) int
rt_pk_cell_visit(rt_pk *p, rt_pk_cull_fn cull, size_t ci, uint64_t in, const int any)
{
    const rt_grid *g = &p->sc->grid;
    /* the cell's byte (rt_grid.odist, built with the grid): empty, or what it holds */
    const unsigned kind = g->odist[ci];
    if (kind < RT_CUBE_OCC)
        return 1; /* empty, no second level */
    p->cand = any ? p->live : in & p->live;
    if (kind & RT_CUBE_LIST)
        rt_pk_list(p, cull, g->refs + g->off[ci], g->off[ci + 1] - g->off[ci], any);
    if ((kind & RT_CUBE_SUB) && (in & p->live)) {
        if (!any)
            return rt_pk_sub(p, cull, &g->subs[g->sub[ci]], in, 0);
        /* an any-hit packet: its rays still walking, less those a flat sub-grid's plane
           rules out (rt_pk_flat) */
        const uint32_t j = g->subplane ? g->subplane[g->sub[ci]] : 0;
        const uint64_t keep = j ? rt_pk_flat(p, j, p->live) : ~(uint64_t)0;
        return keep ? rt_pk_sub(p, cull, &g->subs[g->sub[ci]], keep, 1) : 1;
    }
    return 1;
}

/* the rays still walking at top slice za..zb: drops those whose walk ended before it */
static void rt_pk_drop(rt_pk *p, double za, double zb)
{
    const double ua = p->sg > 0 ? za : -zb;
    if (p->uemin >= ua - p->umg)
        return; /* none ended */
#ifdef RT_PK_X86
    if (rt_pk_avx2)
        p->live = rt_pk_in_avx2(p, p->live, ua - p->umg, INFINITY);
    else
#endif
    for (uint64_t m = p->live; m; m &= m - 1) {
        const int k = __builtin_ctzll(m);
        if (p->ue[k] < ua - p->umg)
            p->live &= ~((uint64_t)1 << k);
    }
    p->uemin = INFINITY; /* over the rays left */
    for (uint64_t m = p->live; m; m &= m - 1)
        p->uemin = p->ue[__builtin_ctzll(m)] < p->uemin ? p->ue[__builtin_ctzll(m)] : p->uemin;
}

/* an any-hit packet's frustum plane: where its first ray walked ends (o + tmax d, in the
   grid frame), if that is within 16 extents of the grid box along K of the near plane zn;
   else zn. Shadow rays toward one point light end there together, so their crossings of
   that plane nearly coincide and the frustum is the cone from the light: at every slice at
   most as wide as the one from the near plane, whose width there is the spread of the rays'
   origins (armadillo's shadow packets at 1024: 1.4 % fewer instructions, bunny's 2.6 %,
   fandisk's 3.0 %). Any plane gives bounds (rt_pk_outside); within that distance the
   roundings of the crossings stay far below the margin. Only finite operations: a tmax
   beyond 1e100 (or NaN) keeps zn. */
static double rt_pk_zend(const rt_pk *p, double zn)
{
    const rt_ray *q = &p->rays[__builtin_ctzll(p->live)];
    if (!(fabs(q->tmax) <= 1e100))
        return zn;
    double e[3], ge[3];
    for (int a = 0; a < 3; a++)
        e[a] = q->org[a] + q->tmax * q->dir[a];
    if (p->sc->grid.rotated)
        rt_pk_gpoint(&p->sc->grid, e, ge);
    else
        memcpy(ge, e, sizeof ge);
    const rt_box *b = &p->sc->grid.b;
    const double z = ge[p->K];
    return fabs(z - zn) <= 16.0 * (b->hi[p->K] - b->lo[p->K]) ? z : zn;
}

/* 1 if an any-hit packet's rays are too spread to be walked together: its frustum where its
   walk starts (the near plane of top slice s0), measured in cells of the grid found there
   (the second-level grid of the top cell at the frustum's middle, or the top level's), is
   RT_PK_SPREAD or more cells wide along a1 or a2, or covers (w1 + 1) (w2 + 1) >= RT_PK_AREA
   cells: the spread of the rays' origins against the density of the primitives around
   them. Such rays share few cells and primitives, and the packet's tests cost more than the
   rays' single walks (callgrind, shadow rays of 8x8 pixel blocks: packets 12 or more cells
   wide mostly took 1.3-2.2 times their rays' single walks on armadillo and bunny, 0.9-1.5
   times on fandisk, whose larger triangles span more cells; by the area, at 1024^2 pixels
   packets of 64-96 cells took 1.24 times (armadillo), 0.83 (bunny), 0.76 (fandisk), of 96
   or more 1.43, 1.18, 0.90, and at 256^2 pixels, where an 8x8 block covers 16 times the
   surface, 1.4-2.0 times on all three; the width alone passes square patches that the area
   catches). Where the middle top cell has no second-level grid its cells hold several
   primitives each, and the limit is (w1 + 1) (w2 + 1) >= RT_PK_AREAT top cells (at 256^2
   pixels such packets cost more than their rays alone, at 1024^2 mostly less: 4 top cells
   gave 3.6-4.4 % fewer instructions on armadillo and bunny at 256^2, 0.4 % on fandisk,
   and 0.03-2.6 % fewer at 1024^2). The area limits 48 and 3 (80 and 4 before) are those of
   the rays given up going to rt_occluded's walks, which cost less than the single-ray code
   they took before (rt_packet_occluded). 0 if the bounds there are not finite (only
   operations that raise no exception). */
static int rt_pk_spread(const rt_pk *p, int s0)
{
    const rt_grid *g = &p->sc->grid;
    const rt_box *b = &g->b;
    const double dz = rt_pk_plane(b, p->K, p->sg > 0 ? s0 : s0 + 1) - p->z0;
    double lo[2], hi[2];
    for (int a = 0; a < 2; a++) {
        lo[a] = p->lo[a] + dz * (dz >= 0.0 ? p->mlo[a] : p->mhi[a]);
        hi[a] = p->hi[a] + dz * (dz >= 0.0 ? p->mhi[a] : p->mlo[a]);
        if (!(fabs(lo[a]) <= 1e100 && fabs(hi[a]) <= 1e100))
            return 0; /* bounds not finite (a grid of few cells): left as they were */
    }
    int q[3];
    q[p->K] = s0;
    q[p->a1] = rt_pk_cell(b, p->a1, 0.5 * (lo[0] + hi[0]), 1.0);
    q[p->a2] = rt_pk_cell(b, p->a2, 0.5 * (lo[1] + hi[1]), 1.0);
    const size_t ci = rt_cell_index(b, q);
    const rt_box *cb = g->sub && g->sub[ci] >= 0 ? &g->subs[g->sub[ci]].b : b;
    const double w1 = (hi[0] - lo[0]) * cb->inv_cw[p->a1], w2 = (hi[1] - lo[1]) * cb->inv_cw[p->a2];
    return (w1 > w2 ? w1 : w2) >= RT_PK_SPREAD ||
           (w1 + 1.0) * (w2 + 1.0) >= (cb == b ? RT_PK_AREAT : RT_PK_AREA);
}

/* the first top slice of the walk (index along K), with the frustum's plane z0 at its near
   end (exact there for rays from one point, as primary rays are; a frustum from the far
   end, where shadow rays toward a light converge, gave more instructions on the three
   meshes), or -1 if the footprint of the first or the last slice exceeds RT_PK_MAXC
   (any-hit: RT_PK_MAXCA, or rt_pk_spread): the packet is not coherent, known before the
   walk (the frustum's width is convex along K, so its widest slices are at the ends; the
   walk itself may narrow it as rays end). The steps' frusta are made only for a packet that
   is walked. */
static int rt_pk_ends(rt_pk *p)
{
    const rt_box *b = &p->sc->grid.b;
    const int K = p->K;
    const int s0 = rt_pk_cell(b, K, p->sg * p->usmin, -p->sg);
    const int s1 = rt_pk_cell(b, K, p->sg * p->uemax, p->sg);
    p->z0 = rt_pk_plane(b, K, p->sg > 0 ? s0 : s0 + 1);
    if (p->any)
        p->z0 = rt_pk_zend(p, p->z0);
    rt_pk_frustum(p, p->live);
    int c[4];
    for (int e = 0; e < 2; e++) {
        const int s = e ? s1 : s0;
        rt_pk_rect(p, b, rt_pk_plane(b, K, s), rt_pk_plane(b, K, s + 1), c);
        if ((c[1] - c[0] + 1) * (c[3] - c[2] + 1) > (p->any ? RT_PK_MAXCA : RT_PK_MAXC))
            return -1;
    }
    if (p->any && rt_pk_spread(p, s0))
        return -1;
#ifdef RT_PK_X86
    if (rt_pk_avx2) /* only for a packet that is walked */
        rt_pk_steps(p);
#endif
    return s0;
}

/* the walk over the top level: 1, or 0 if the packet is not coherent; made for each kind of
   packet (any: any-hit) */
static inline __attribute__((always_inline)) int rt_pk_walk_body(rt_pk *p, rt_ctx *ctx,
                                                                 const int any)
{
    const rt_box *b = &p->sc->grid.b;
    const int K = p->K, nK = b->n[K];
    pthread_once(&rt_pk_once, rt_pk_choose);
    const rt_pk_cull_fn cull = rt_pk_cull;
    if (++ctx->stamp == 0) {
        memset(ctx->hbox, 0, RT_HBOX * sizeof(uint64_t));
        ctx->stamp = 1;
    }
    p->key = (uint64_t)ctx->stamp << 32;
    if (!p->live)
        return 1;
    const int s0 = rt_pk_ends(p);
    if (s0 < 0)
        return 0;
    for (int j = p->sg > 0 ? s0 : nK - 1 - s0; j < nK && p->live; j++) {
        const int s = p->sg > 0 ? j : nK - 1 - j;
        const double za = rt_pk_plane(b, K, s), zb = rt_pk_plane(b, K, s + 1);
        rt_pk_drop(p, za, zb);
        const uint64_t in = rt_pk_in(p, p->live, za, zb);
        if (!in)
            continue;
        rt_pk_frustum(p, p->live); /* of the rays still walking: kept over many slices */
        int c[4];
        rt_pk_rect(p, b, za, zb, c);
        if ((c[1] - c[0] + 1) * (c[3] - c[2] + 1) > (any ? RT_PK_MAXCA : RT_PK_MAXC))
            return 0;
        int q[3];
        q[K] = s;
        for (q[p->a2] = c[2]; q[p->a2] <= c[3]; q[p->a2]++)
            for (q[p->a1] = c[0]; q[p->a1] <= c[1]; q[p->a1]++)
                if (!rt_pk_cell_visit(p, cull, rt_cell_index(b, q), in, any))
                    return 0;
    }
    return 1;
}

static __attribute__((noinline)) int rt_pk_walk_any(rt_pk *p, rt_ctx *ctx)
{
    return rt_pk_walk_body(p, ctx, 1);
}

static __attribute__((noinline)) int rt_pk_walk_nearest(rt_pk *p, rt_ctx *ctx)
{
    return rt_pk_walk_body(p, ctx, 0);
}

static int rt_pk_walk(rt_pk *p, rt_ctx *ctx)
{
    return p->any ? rt_pk_walk_any(p, ctx) : rt_pk_walk_nearest(p, ctx);
}

/* ---- the result ---- */

/* 1 if hit (wi, wt) wins the tie rule against hit (xi, xt) of ray r in both roles: as the
   new hit against best x, and x as the new hit against best w */
static int rt_pk_beats(const rt_scene *sc, const rt_rayx *r, uint32_t wi, double wt, uint32_t xi,
                       double xt)
{
    double b = INFINITY, eb = 0.0;
    long bi = -1;
    rt_nearest_update(sc, r, xi, xt, &b, &bi, &eb); /* x alone: its error bound */
    rt_nearest_update(sc, r, wi, wt, &b, &bi, &eb);
    if (bi != (long)wi)
        return 0;
    rt_nearest_update(sc, r, xi, xt, &b, &bi, &eb);
    return bi == (long)wi;
}

/* 1 if ray k's hit is the one every order of tests gives (see the top of the file) */
static int rt_pk_sure(const rt_pk *p, int k)
{
    if ((p->over >> k) & 1u)
        return 0;
    const uint32_t wi = (uint32_t)p->bi[k];
    for (int j = 0; j < p->nh[k]; j++) {
        const rt_pk_rec *x = &p->rec[j][k];
        if (x->i != wi && !rt_pk_beats(p->sc, &p->r[k], wi, p->best[k], x->i, x->t))
            return 0;
    }
    return 1;
}

/* packets traced as packets since the process started (tests) */
static atomic_ullong rt_pk_traced;

unsigned long long rt_packet_count(void)
{
    return atomic_load_explicit(&rt_pk_traced, memory_order_relaxed);
}

/* rt_packet_nearest, and in *hm the rays that may have a hit: i[k] = -1 for the others */
static int rt_pk_nearest(const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays, long *i,
                         double *t, rt_rayx *rx, rt_packet_stats *ps, uint64_t *hm)
{
    rt_pk p;
    pthread_once(&rt_pk_once, rt_pk_choose);
    if (!rt_pk_setup(&p, sc, ctx, n, rays, 0, rx)) {
        ctx->beside = 0;
        ps->fallback_packets++;
        return 0;
    }
    ctx->beside = !p.live;
    if (!rt_pk_walk(&p, ctx)) {
        ps->fallback_packets++;
        return 0;
    }
    ps->packets++;
    ps->beside += (uint64_t)p.beside;
    atomic_fetch_add_explicit(&rt_pk_traced, 1, memory_order_relaxed);
    memcpy(i, p.bi, (size_t)p.n * sizeof *i);
    memcpy(t, p.best, (size_t)p.n * sizeof *t);
    for (uint64_t m = p.hit; m; m &= m - 1) { /* the rays with a hit */
        const int k = __builtin_ctzll(m);
        if (!rt_pk_sure(&p, k)) {
            ps->fallback_rays++;
            i[k] = rt_trace_nearest(sc, ctx, &rx[k], &t[k]);
        }
    }
    *hm = p.hit;
    return 1;
}

int rt_packet_nearest(const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays, long *i,
                      double *t, rt_rayx *rx, rt_packet_stats *ps)
{
    uint64_t hm;
    return rt_pk_nearest(sc, ctx, n, rays, i, t, rx, ps, &hm);
}

int rt_packet_occluded(const rt_scene *sc, rt_ctx *ctx, size_t n, const rt_ray *rays,
                       unsigned char *occ, rt_packet_stats *ps)
{
    rt_pk p;
    rt_rayx rx[RT_PACKET];
    pthread_once(&rt_pk_once, rt_pk_choose);
    if (!rt_pk_setup(&p, sc, ctx, n, rays, 1, rx)) {
        ps->fallback_packets++;
        return 0;
    }
    /* the rays not finished by a walk given up take the single-ray walk; a ray that hit
       is occluded, one whose walk ended is not */
    const uint64_t left = (rt_pk_walk(&p, ctx) ? 0 : p.live) | p.alone;
    if (left) {
        ps->fallback_packets++;
    } else {
        ps->packets++;
        atomic_fetch_add_explicit(&rt_pk_traced, 1, memory_order_relaxed);
    }
    ps->fallback_rays += (uint64_t)__builtin_popcountll(left);
    /* the rays left go to rt_occluded's walks as a batch (its four-ray set-up and top walks:
       a given-up shadow ray of armadillo's at 1024^2 took 2,228 instructions through
       rt_trace_transmit, 1,862 so), which answer every ray as the packet would: all of the
       packet's rays when at most 4 others are in it (a packet given up before its walk),
       else the rays left, gathered */
    if (left && __builtin_popcountll(left) + 4 >= p.n) {
        rt_occluded_rays(sc, ctx, (size_t)p.n, rays, occ);
        return 1;
    }
    for (int k = 0; k < p.n; k++)
        occ[k] = (p.hit >> k) & 1u;
    if (left) {
        rt_ray q[RT_PACKET];
        unsigned char o[RT_PACKET];
        int m = 0;
        for (uint64_t w = left; w; w &= w - 1)
            q[m++] = rays[__builtin_ctzll(w)];
        rt_occluded_rays(sc, ctx, (size_t)m, q, o);
        m = 0;
        for (uint64_t w = left; w; w &= w - 1)
            occ[__builtin_ctzll(w)] = o[m++];
    }
    return 1;
}

/* ---- the batch API ---- */

/* rt_fill_hit (rt_trace.c) with the normal of primitive i given: the one rt_prim_ng gave
   for the last hit of the same primitive (the same value: it depends on the primitive
   only); the point and the side as rt_fill_hit computes them */
static void rt_pk_fill_ng(const rt_scene *sc, const rt_rayx *r, long i, double t,
                          const double ng[3], rt_hit *h)
{
    h->t = t;
    h->prim = rt_prim_id(sc, (size_t)i);
    memcpy(h->ng, ng, sizeof h->ng);
    for (int j = 0; j < 3; j++)
        h->p[j] = r->o[j] + t * r->d[j];
    double den = h->ng[0] * r->d[0] + h->ng[1] * r->d[1] + h->ng[2] * r->d[2];
    h->side = den > 0.0 ? 1 : 0;
}

/* entries of the output's table of normals per packet (a power of 2) */
#define RT_PK_NGC 16

/* the nearest hits of a batch in packets of RT_PACKET rays; ps may be NULL */
int rt_intersect_packet_stats(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits,
                              rt_packet_stats *ps)
{
    rt_packet_stats own = {0};
    rt_ctx c;
    const int rc = rt_batch_begin(sc, n, rays, hits, &c);
    if (rc != RT_OK)
        return rc;
    for (size_t k0 = 0; k0 < n; k0 += RT_PACKET) {
        const size_t m = n - k0 < RT_PACKET ? n - k0 : RT_PACKET;
        long pi[RT_PACKET];
        double pt[RT_PACKET];
        rt_rayx rx[RT_PACKET];
        uint64_t hm = 0;
        const int packed =
            rt_pk_nearest(sc, &c, m, rays + k0, pi, pt, rx, ps ? ps : &own, &hm);
        /* the primitives whose normal this packet's output already holds, by the low bits
           of their index, and a hit written with it (the rays of a packet hit a few
           triangles, each several times, not always in a row) */
        long ci[RT_PK_NGC];
        const rt_hit *ch[RT_PK_NGC];
        for (int s = 0; s < RT_PK_NGC; s++)
            ci[s] = -1;
        /* a packet: its misses first (most rays of a frame), then the rays that may have a
           hit in their order (the same records: a miss's does not depend on the others) */
        const uint64_t all = m == RT_PACKET ? ~(uint64_t)0 : ((uint64_t)1 << m) - 1;
        if (packed)
            for (uint64_t w = all & ~hm; w; w &= w - 1)
                hits[k0 + (size_t)__builtin_ctzll(w)] = (rt_hit){.t = INFINITY, .prim = -1};
        for (uint64_t w = packed ? hm : all; w; w &= w - 1) {
            const size_t j = (size_t)__builtin_ctzll(w);
            const rt_ray *q = &rays[k0 + j];
            long i = -1;
            if (packed)
                i = pi[j];
            else if (rt_rayx_setup(&rx[j], q->org, q->dir, q->tmin, q->tmax))
                i = rt_trace_nearest(sc, &c, &rx[j], &pt[j]);
            const int s = (int)((unsigned long)i % RT_PK_NGC);
            if (i >= 0 && i == ci[s]) {
                rt_pk_fill_ng(sc, &rx[j], i, pt[j], ch[s]->ng, &hits[k0 + j]);
            } else if (i >= 0) {
                rt_fill_hit(sc, &rx[j], i, pt[j], &hits[k0 + j]);
                ci[s] = i;
                ch[s] = &hits[k0 + j];
            } else
                hits[k0 + j] = (rt_hit){.t = INFINITY, .prim = -1};
        }
    }
    rt_ctx_free(&c);
    return RT_OK;
}

int rt_intersect_packet(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits)
{
    return rt_intersect_packet_stats(sc, n, rays, hits, NULL);
}

/* any-hit answers of a batch in packets of RT_PACKET rays; ps may be NULL */
int rt_occluded_packet_stats(const rt_scene *sc, size_t n, const rt_ray *rays,
                             unsigned char *occluded, rt_packet_stats *ps)
{
    rt_packet_stats own = {0};
    rt_ctx c;
    const int rc = rt_batch_begin(sc, n, rays, occluded, &c);
    if (rc != RT_OK)
        return rc;
    for (size_t k0 = 0; k0 < n; k0 += RT_PACKET) {
        const size_t m = n - k0 < RT_PACKET ? n - k0 : RT_PACKET;
        if (rt_packet_occluded(sc, &c, m, rays + k0, occluded + k0, ps ? ps : &own))
            continue;
        for (size_t j = 0; j < m; j++) {
            rt_rayx r;
            const rt_ray *q = &rays[k0 + j];
            occluded[k0 + j] = rt_rayx_setup(&r, q->org, q->dir, q->tmin, q->tmax) &&
                               rt_trace_transmit(sc, &c, &r, 1) == 0.0;
        }
    }
    rt_ctx_free(&c);
    return RT_OK;
}

int rt_occluded_packet(const rt_scene *sc, size_t n, const rt_ray *rays, unsigned char *occluded)
{
    return rt_occluded_packet_stats(sc, n, rays, occluded, NULL);
}
