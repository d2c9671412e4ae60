/* SPDX-License-Identifier: MIT */
/*
 * test_rt_leaf.c -- the float leaves' test (rt_leaf.c) against the exact double test
 * (rt_isect_tri): every triangle the double test hits must stay a candidate of the float
 * test, for each kernel this CPU has (scalar, SSE, AVX2, chosen by GKS_RT_SIMD), on every
 * leaf of the bunny's grid (leaves of 2 .. 23 triangles) with rays aimed exactly at its
 * triangles' vertices, at their edges (points on the edge, rounded) and inside, from origins
 * near and far, and at scales from 1e-9 to 1e9 (the bound's range). The filter must also do
 * its work: of rays aimed well beside a leaf (its box widened 4 times, the triangles missed
 * by the double test), at least 80 % of the lanes must be ruled out.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_prim.h"
#include "rt_testutil.h"

static rt_scene *bunny(double scale)
{
    rtu_mesh m;
    assert_int_equal(rtu_load_off(RT_DATA_DIR "/meshes/bunny00.off.gz", &m), 0);
    for (int k = 0; k < 3 * m.nv; k++)
        m.xyz[k] *= scale;
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    int si = rt_scene_add_surface(sc, &s);
    assert_int_equal(rtu_mesh_add(&m, sc, si), 0);
    /* leaves from 2 triangles on: leaves of 2 .. 23 lanes, every kernel's tails */
    const rt_build_options bo = {.brute_threshold = -1, .leaf_min = 2};
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    rtu_mesh_free(&m);
    assert_non_null(sc->grid.leaves);
    return sc;
}

/* is lane k among the candidates of the float test of ray r on leaf lf? */
static int is_cand(rt_leaf_fn fn, const rt_grid *g, const rt_leaf *lf, const rt_rayx *r,
                   uint32_t k)
{
    rt_fray f;
    if (!rt_fray_leaf(r, lf, &f))
        return 1;
    uint32_t cand[64];
    const float *rows = g->lf + (size_t)9 * lf->lane0;
    const uint32_t c0 = k / 64 * 64, nc = lf->n - c0 < 64 ? lf->n - c0 : 64;
    const uint32_t m = fn(rows + c0, lf->L, nc, &f, cand);
    for (uint32_t j = 0; j < m; j++)
        if (c0 + cand[j] == k)
            return 1;
    return 0;
}

static void check_kernel(const char *simd, double scale)
{
    setenv("GKS_RT_SIMD", simd, 1);
    const char *name;
    rt_leaf_fn fn4, fn = rt_leaf_kernel(&name, &fn4);
    rt_scene *sc = bunny(scale);
    const rt_grid *g = &sc->grid;
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_true(gi.float_leaves == g->nleaves && gi.float_lanes == g->nlanes);
    assert_string_equal(gi.simd, name); /* the kernel the build chose */
    uint64_t s = 1234;
    size_t hits = 0, missed = 0, far = 0, culled = 0;
    for (size_t li = 0; li < g->nleaves; li += 16) {
        const rt_leaf *lf = &g->leaves[li];
        const rt_leaf_fn f = lf->n <= 4 ? fn4 : fn;
        for (uint32_t k = 0; k < lf->n; k++) {
            const uint32_t i = g->lid[lf->lane0 + k];
            const double *v[3];
            rt_tri_verts(sc, i, v);
            for (int rep = 0; rep < 6; rep++) {
                /* target: a vertex, a point on an edge, or inside */
                const int e = rep % 3;
                const double w = rep < 3 ? 0.0 : rtu_rand(&s);
                double tgt[3], dir[3], o[3];
                for (int a = 0; a < 3; a++)
                    tgt[a] = v[e][a] + w * (v[(e + 1) % 3][a] - v[e][a]);
                if (rep == 5)
                    for (int a = 0; a < 3; a++)
                        tgt[a] = (v[0][a] + v[1][a] + v[2][a]) / 3.0;
                rtu_rand_dir(&s, dir);
                const double dist = lf->r * pow(10.0, 4.0 * rtu_rand(&s) - 1.0);
                for (int a = 0; a < 3; a++) {
                    o[a] = tgt[a] - dist * dir[a];
                    dir[a] = tgt[a] - o[a];
                }
                rt_rayx r;
                assert_true(rt_rayx_setup(&r, o, dir, -1e99, 1e99));
                double t;
                if (rt_isect_tri(&r, v[0], v[1], v[2], -1e99, 1e99, &t)) {
                    hits++;
                    if (!is_cand(f, g, lf, &r, k)) {
                        missed++;
                        fprintf(stderr, "%s: leaf %zu lane %u: a hit ruled out\n", name, li, k);
                    }
                }
                /* beside the leaf: aimed at a point of its box widened 4 times, outside
                   the box, with the triangle missed by the double test */
                double side[3];
                for (int a = 0; a < 3; a++)
                    side[a] = lf->a[a] + (rtu_rand(&s) < 0.5 ? -1.0 : 1.0) * lf->r *
                                             (1.5 + 2.5 * rtu_rand(&s));
                for (int a = 0; a < 3; a++)
                    dir[a] = side[a] - o[a];
                assert_true(rt_rayx_setup(&r, o, dir, -1e99, 1e99));
                if (!rt_isect_tri(&r, v[0], v[1], v[2], -1e99, 1e99, &t)) {
                    far++;
                    culled += !is_cand(f, g, lf, &r, k);
                }
            }
        }
    }
    printf("kernel %s (asked %s), scale %g: %zu hits, %zu ruled out; %zu misses beside, "
           "%zu culled\n", name, simd, scale, hits, missed, far, culled);
    assert_true(hits > 1000);
    assert_int_equal(missed, 0);
    assert_true(culled >= far * 8 / 10);
    rt_scene_free(sc);
    unsetenv("GKS_RT_SIMD");
}

static void test_leaf_kernels(void **state)
{
    (void)state;
    const char *k[3] = {"scalar", "sse", "avx2"};
    const double scales[3] = {1.0, 1e-9, 1e9};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            check_kernel(k[i], scales[j]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_leaf_kernels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
