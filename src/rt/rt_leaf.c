/* SPDX-License-Identifier: MIT */
/*
 * rt_leaf.c -- float leaves of the grid: the triangles of a cell list as float offsets from an
 * anchor in structure-of-arrays rows (rt_leaf, rt_internal.h), built after the grid, and the
 * float test of a leaf's lanes (scalar, SSE: 4 lanes, AVX2: 8 lanes, chosen at run time).
 *
 * The float test is a filter: it rules out a lane only where the exact double test
 * (rt_isect_tri, rt_prim.h) surely finds the edge functions' signs mixed, so every triangle
 * the double test hits stays a candidate and is decided by it: the hits are the double test's
 * bit for bit. The bound behind "surely" is derived in docs/RAYTRACING.md ("Float leaves");
 * in short, with u = 2^-24 and S >= |v - o| (max norm) for every vertex v of the leaf and the
 * ray origin o, each float sheared vertex coordinate lies within e1 = 8.5 u S of the exact
 * one of the double test's ray, and each edge function within
 *     E = 4 e1 P + 2 e1^2 + 4 u P^2     (P the largest |sheared coordinate| of the lane)
 * of the exact value, which the double computation approaches 2^29 times closer; the code
 * takes 1 % more, and a floor of 1e-36 for roundings below the normal range.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define RT_LEAF_X86 1
#endif


/* ---- the float test of one lane, as every kernel computes it ---- */

/* candidate (1) unless the float edge functions' signs are surely mixed */
static inline int rt_lane_scalar(const float *rows, uint32_t L, uint32_t k, const rt_fray *f)
{
    float x[3], y[3], P = 0.0f;
    for (int v = 0; v < 3; v++) {
        const float X = rows[(size_t)(f->rx + 3 * v) * L + k] + f->q[0];
        const float Y = rows[(size_t)(f->ry + 3 * v) * L + k] + f->q[1];
        const float Z = rows[(size_t)(f->rz + 3 * v) * L + k] + f->q[2];
        x[v] = X - f->sx * Z;
        y[v] = Y - f->sy * Z;
        P = fmaxf(P, fmaxf(fabsf(x[v]), fabsf(y[v])));
    }
    const float U = x[2] * y[1] - y[2] * x[1];
    const float V = x[0] * y[2] - y[0] * x[2];
    const float W = x[1] * y[0] - y[1] * x[0];
    const float E = P * (f->ka + f->kc * P) + f->kb;
    const int neg = (U < -E) | (V < -E) | (W < -E);
    const int pos = (U > E) | (V > E) | (W > E);
    return !(neg & pos);
}

static uint32_t rt_leaf_scalar(const float *rows, uint32_t L, uint32_t n, const rt_fray *f,
                               uint32_t *cand)
{
    uint32_t m = 0;
    for (uint32_t k = 0; k < n; k++)
        if (rt_lane_scalar(rows, L, k, f))
            cand[m++] = k;
    return m;
}

#ifdef RT_LEAF_X86
/* the candidates of a lane mask (bit k: lane base + k) appended to cand, below n */
static inline uint32_t rt_mask_cand(unsigned mask, uint32_t base, uint32_t n, uint32_t *cand,
                                    uint32_t m)
{
    while (mask) {
        const uint32_t k = base + (uint32_t)__builtin_ctz(mask);
        mask &= mask - 1;
        if (k < n)
            cand[m++] = k;
    }
    return m;
}

/* SSE2 (every x86-64): 4 lanes at a time, the scalar operations in the same order */
static uint32_t rt_leaf_sse(const float *rows, uint32_t L, uint32_t n, const rt_fray *f,
                            uint32_t *cand)
{
    const __m128 qx = _mm_set1_ps(f->q[0]), qy = _mm_set1_ps(f->q[1]), qz = _mm_set1_ps(f->q[2]);
    const __m128 sx = _mm_set1_ps(f->sx), sy = _mm_set1_ps(f->sy);
    const __m128 ka = _mm_set1_ps(f->ka), kc = _mm_set1_ps(f->kc), kb = _mm_set1_ps(f->kb);
    const __m128 sign = _mm_set1_ps(-0.0f);
    uint32_t m = 0;
    for (uint32_t k = 0; k < n; k += 4) {
        __m128 x[3], y[3], P = _mm_setzero_ps();
        for (int v = 0; v < 3; v++) {
            const __m128 X = _mm_add_ps(_mm_load_ps(rows + (size_t)(f->rx + 3 * v) * L + k), qx);
            const __m128 Y = _mm_add_ps(_mm_load_ps(rows + (size_t)(f->ry + 3 * v) * L + k), qy);
            const __m128 Z = _mm_add_ps(_mm_load_ps(rows + (size_t)(f->rz + 3 * v) * L + k), qz);
            x[v] = _mm_sub_ps(X, _mm_mul_ps(sx, Z));
            y[v] = _mm_sub_ps(Y, _mm_mul_ps(sy, Z));
            P = _mm_max_ps(P, _mm_max_ps(_mm_andnot_ps(sign, x[v]), _mm_andnot_ps(sign, y[v])));
        }
        const __m128 U = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
        const __m128 V = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
        const __m128 W = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
        const __m128 E = _mm_add_ps(_mm_mul_ps(P, _mm_add_ps(ka, _mm_mul_ps(kc, P))), kb);
        const __m128 nE = _mm_xor_ps(E, sign);
        const __m128 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, nE), _mm_cmplt_ps(V, nE)),
                                     _mm_cmplt_ps(W, nE));
        const __m128 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, E), _mm_cmpgt_ps(V, E)),
                                     _mm_cmpgt_ps(W, E));
        const unsigned keep = ~(unsigned)_mm_movemask_ps(_mm_and_ps(neg, pos)) & 15u;
        m = rt_mask_cand(keep, k, n, cand, m);
    }
    return m;
}

/* AVX2: 8 lanes at a time while more than 4 are left (k + 4 < n: then L, a multiple of 4,
   is at least k + 8, so the loads stay in the row; unaligned: rows are 16-byte aligned), the
   tail of at most 4 lanes by the SSE code */
__attribute__((target("avx2"))) static uint32_t rt_leaf_avx2(const float *rows, uint32_t L,
                                                             uint32_t n, const rt_fray *f,
                                                             uint32_t *cand)
{
    const __m256 qx = _mm256_set1_ps(f->q[0]), qy = _mm256_set1_ps(f->q[1]),
                 qz = _mm256_set1_ps(f->q[2]);
    const __m256 sx = _mm256_set1_ps(f->sx), sy = _mm256_set1_ps(f->sy);
    const __m256 ka = _mm256_set1_ps(f->ka), kc = _mm256_set1_ps(f->kc),
                 kb = _mm256_set1_ps(f->kb);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    uint32_t m = 0, k = 0;
    for (; k + 4 < n; k += 8) {
        __m256 x[3], y[3], P = _mm256_setzero_ps();
        for (int v = 0; v < 3; v++) {
            const __m256 X = _mm256_add_ps(_mm256_loadu_ps(rows + (size_t)(f->rx + 3 * v) * L + k), qx);
            const __m256 Y = _mm256_add_ps(_mm256_loadu_ps(rows + (size_t)(f->ry + 3 * v) * L + k), qy);
            const __m256 Z = _mm256_add_ps(_mm256_loadu_ps(rows + (size_t)(f->rz + 3 * v) * L + k), qz);
            x[v] = _mm256_sub_ps(X, _mm256_mul_ps(sx, Z));
            y[v] = _mm256_sub_ps(Y, _mm256_mul_ps(sy, Z));
            P = _mm256_max_ps(P, _mm256_max_ps(_mm256_andnot_ps(sign, x[v]),
                                               _mm256_andnot_ps(sign, y[v])));
        }
        const __m256 U = _mm256_sub_ps(_mm256_mul_ps(x[2], y[1]), _mm256_mul_ps(y[2], x[1]));
        const __m256 V = _mm256_sub_ps(_mm256_mul_ps(x[0], y[2]), _mm256_mul_ps(y[0], x[2]));
        const __m256 W = _mm256_sub_ps(_mm256_mul_ps(x[1], y[0]), _mm256_mul_ps(y[1], x[0]));
        const __m256 E = _mm256_add_ps(_mm256_mul_ps(P, _mm256_add_ps(ka, _mm256_mul_ps(kc, P))), kb);
        const __m256 nE = _mm256_xor_ps(E, sign);
        const __m256 neg = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(U, nE, _CMP_LT_OQ),
                                                     _mm256_cmp_ps(V, nE, _CMP_LT_OQ)),
                                        _mm256_cmp_ps(W, nE, _CMP_LT_OQ));
        const __m256 pos = _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(U, E, _CMP_GT_OQ),
                                                     _mm256_cmp_ps(V, E, _CMP_GT_OQ)),
                                        _mm256_cmp_ps(W, E, _CMP_GT_OQ));
        const unsigned keep = ~(unsigned)_mm256_movemask_ps(_mm256_and_ps(neg, pos)) & 255u;
        m = rt_mask_cand(keep, k, n, cand, m);
    }
    if (k < n) { /* 1 .. 4 lanes left: L >= k + 4 */
        uint32_t t[4];
        const uint32_t mt = rt_leaf_sse(rows + k, L, n - k, f, t);
        for (uint32_t j = 0; j < mt; j++)
            cand[m++] = k + t[j];
    }
    return m;
}
#endif

int rt_simd_level(void)
{
    const char *force = getenv("GKS_RT_SIMD");
    int level = 3; /* 0 scalar, 1 SSE, 2 AVX2, 3 AVX-512: the widest allowed */
    if (force && !strcmp(force, "scalar"))
        level = 0;
    else if (force && !strcmp(force, "sse"))
        level = 1;
    else if (force && !strcmp(force, "avx2"))
        level = 2;
#ifdef RT_LEAF_X86
    __builtin_cpu_init();
    /* AVX-512 as the kernels use it: foundation, 128/256-bit forms (VL) and the 64-bit
       integer and mask forms (DQ) */
    if (level >= 3 && !(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                        __builtin_cpu_supports("avx512dq")))
        level = 2;
    if (level >= 2 && !__builtin_cpu_supports("avx2"))
        level = 1;
#else
    level = 0;
#endif
    return level;
}

rt_leaf_fn rt_leaf_kernel(const char **name, rt_leaf_fn *fn4)
{
    const int level = rt_simd_level();
#ifdef RT_LEAF_X86
    if (level >= 1)
        *fn4 = rt_leaf_sse;
    if (level >= 2) {
        *name = "avx2";
        return rt_leaf_avx2;
    }
    if (level >= 1) {
        *name = "sse";
        return rt_leaf_sse;
    }
#endif
    *name = "scalar";
    *fn4 = rt_leaf_scalar;
    return rt_leaf_scalar;
}

/* ---- the build ---- */

/* the leaf of a cell list refs[0..n-1] with its lanes from lane0 on (the rows filled) */
static void rt_leaf_fill(const rt_scene *sc, const uint32_t *refs, uint32_t n, uint32_t lane0,
                         rt_leaf *lf, float *fl, uint32_t *lid)
{
    double bb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (uint32_t k = 0; k < n; k++) {
        const double *v[3];
        rt_tri_verts(sc, refs[k], v);
        for (int j = 0; j < 3; j++)
            rt_bbox_add(bb, v[j]);
    }
    lf->n = n;
    lf->L = (n + 3) & ~3u;
    lf->lane0 = lane0;
    double r = 0.0;
    for (int a = 0; a < 3; a++) {
        lf->a[a] = 0.5 * bb[a] + 0.5 * bb[3 + a];
        r = fmax(r, fmax(fabs(bb[a] - lf->a[a]), fabs(bb[3 + a] - lf->a[a])));
    }
    /* r rounded up past the roundings of v - a (relative 2^-53 each) */
    lf->r = nextafterf((float)(r * (1.0 + 0x1p-40)), INFINITY);
    float *rows = fl + (size_t)9 * lane0;
    for (uint32_t k = 0; k < lf->L; k++) {
        const uint32_t i = refs[k < n ? k : 0];
        const double *v[3];
        rt_tri_verts(sc, i, v);
        for (int j = 0; j < 9; j++)
            rows[(size_t)j * lf->L + k] = (float)(v[j / 3][j % 3] - lf->a[j % 3]);
        lid[lane0 + k] = i;
    }
}

/* 1 if the list refs[0..n-1] becomes a leaf: leaf_min or more triangles, nothing else */
static int rt_leaf_wanted(const rt_scene *sc, const uint32_t *refs, uint32_t n, uint32_t leaf_min)
{
    if (n < leaf_min)
        return 0;
    for (uint32_t k = 0; k < n; k++)
        if (refs[k] >= sc->ntri)
            return 0;
    return 1;
}

/* counts (fill = 0) or makes (fill = 1) the leaves of the cell lists off[0..nc] over refs,
   their indices into map */
static void rt_leaves_pass(const rt_scene *sc, rt_grid *g, const uint32_t *off,
                           const uint32_t *refs, size_t nc, uint32_t *map, size_t *nl,
                           size_t *lanes, int fill, uint32_t leaf_min)
{
    for (size_t c = 0; c < nc; c++) {
        const uint32_t n = off[c + 1] - off[c];
        if (!rt_leaf_wanted(sc, refs + off[c], n, leaf_min)) {
            if (fill)
                map[c] = 0;
            continue;
        }
        if (fill) {
            rt_leaf_fill(sc, refs + off[c], n, (uint32_t)*lanes, &g->leaves[*nl], g->lf, g->lid);
            map[c] = (uint32_t)(*nl + 1);
        }
        *nl += 1;
        *lanes += ((size_t)n + 3) & ~(size_t)3; /* L: lane0 stays a multiple of 4 */
    }
}

/* GKS_RT_LEAF_MIN=N (1 .. 2^20) in the environment: float leaves from N triangles where the
   build options leave the default (tests and experiments); else none (-1). */
static int rt_leaf_min_env(void)
{
    const char *s = getenv("GKS_RT_LEAF_MIN");
    char *end = NULL;
    long v = s && *s ? strtol(s, &end, 10) : 0;
    return s && *s && end && !*end && v >= 1 && v <= (1L << 20) ? (int)v : -1;
}

/* the second level's absolute cell offsets (soff's layout) from its 2-byte layout, for the
   passes below; NULL: no memory */
static uint32_t *rt_sub_offsets(const rt_grid *g)
{
    uint32_t *o = rt_alloc_array(g->nsubcells + 1, sizeof(uint32_t));
    for (size_t k = 0; o && k < g->nsubs; k++) {
        const rt_box *b = &g->subs[k].b;
        const size_t nc = (size_t)b->n[0] * (size_t)b->n[1] * (size_t)b->n[2];
        for (size_t c = 0; c < nc; c++)
            o[g->subs[k].first + c] = rt_sub_off(g, k, c);
    }
    if (o)
        o[g->nsubcells] = (uint32_t)g->nsrefs;
    return o;
}

static int rt_leaves_make(const rt_scene *sc, rt_grid *g, const uint32_t *soff, uint32_t lm);

int rt_leaves_min(int leaf_min)
{
    return leaf_min == 0 ? rt_leaf_min_env() : leaf_min;
}

int rt_leaves_build(const rt_scene *sc, rt_grid *g, int leaf_min)
{
    g->leaf_fn = rt_leaf_kernel(&g->leaf_name, &g->leaf_fn4);
    leaf_min = rt_leaves_min(leaf_min);
    if (leaf_min <= 0)
        return RT_OK;
    const uint32_t lm = (uint32_t)leaf_min;
    if (!g->soff16)
        return rt_leaves_make(sc, g, g->soff, lm);
    uint32_t *soff = rt_sub_offsets(g);
    if (!soff)
        return RT_ERR_NOMEM;
    const int rc = rt_leaves_make(sc, g, soff, lm);
    free(soff);
    return rc;
}

/* the leaves of the top cells and of the sub cells (soff: their absolute offsets) */
static int rt_leaves_make(const rt_scene *sc, rt_grid *g, const uint32_t *soff, uint32_t lm)
{
    size_t nl = 0, lanes = 0;
    const uint32_t *top_refs = g->refs;
    rt_leaves_pass(sc, g, g->off, top_refs, g->ncells, NULL, &nl, &lanes, 0, lm);
    if (g->nsubcells)
        rt_leaves_pass(sc, g, soff, g->srefs, g->nsubcells, NULL, &nl, &lanes, 0, lm);
    if (nl == 0 || nl >= UINT32_MAX || lanes >= UINT32_MAX)
        return RT_OK; /* no leaves: every list in double */
    g->tleaf = rt_alloc_array(g->ncells, sizeof(uint32_t));
    g->sleaf = g->nsubcells ? rt_alloc_array(g->nsubcells, sizeof(uint32_t)) : NULL;
    g->leaves = rt_alloc_array(nl, sizeof(rt_leaf));
    /* malloc's 16-byte alignment with lane0 % 4 == 0 and L % 4 == 0 aligns every row for
       the 4-lane loads */
    g->lf = rt_calloc_array(lanes * 9, sizeof(float));
    g->lid = rt_alloc_array(lanes, sizeof(uint32_t));
    if (!g->tleaf || (g->nsubcells && !g->sleaf) || !g->leaves || !g->lf || !g->lid) {
        rt_leaves_free(g);
        return RT_ERR_NOMEM;
    }
    g->nleaves = nl;
    g->nlanes = lanes;
    nl = lanes = 0;
    rt_leaves_pass(sc, g, g->off, top_refs, g->ncells, g->tleaf, &nl, &lanes, 1, lm);
    if (g->nsubcells)
        rt_leaves_pass(sc, g, soff, g->srefs, g->nsubcells, g->sleaf, &nl, &lanes, 1, lm);
    return RT_OK;
}

size_t rt_leaves_bytes(const rt_grid *g)
{
    if (!g->leaves)
        return 0;
    return (g->ncells + g->nsubcells) * sizeof(uint32_t) + g->nleaves * sizeof(rt_leaf) +
           g->nlanes * (9 * sizeof(float) + sizeof(uint32_t));
}

void rt_leaves_free(rt_grid *g)
{
    free(g->tleaf);
    free(g->sleaf);
    free(g->leaves);
    free(g->lf);
    free(g->lid);
    g->tleaf = g->sleaf = NULL;
    g->leaves = NULL;
    g->lf = NULL;
    g->lid = NULL;
    g->nleaves = g->nlanes = 0;
}
