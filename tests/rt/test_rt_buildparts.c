/* SPDX-License-Identifier: MIT */
/*
 * test_rt_buildparts.c -- the second level of the grid build runs in chunks of top cells taken
 * dynamically (rt_build.c, rt_sub_take: part 0 from the front, the other parts from the back;
 * docs/RAYTRACING.md, "Acceleration"). The grid must not depend on the chunks: the grid hash
 * of one scene on 1 thread equals the hash on 2, 3 and 4 threads with the default chunks,
 * with chunks of one reference (hundreds of chunks) and with part 0 limited to 1 or 3 chunks
 * of the front (rt_build_set_chunks), so that the back chunks, which are copied behind part
 * 0's arrays, exist on any machine (rt_build_back_chunks counts them). Scenes: random
 * triangles in clusters (crowded top cells, sub-grids) with large ones through them, as
 * separate triangles and as one indexed mesh, and a scene of sub-grids whose lists exceed
 * the 2-byte offsets (the 4-byte layout).
 * Also rt_kth_smallest, the median of the top level's extent sample: the value qsort puts at
 * place k, for every k, on samples with repeats, zeros, tiny and huge values and infinity,
 * and on samples that take qsort itself (a negative zero, a negative value).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <math.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_testutil.h"

static double rnd(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* n triangles: most of them small, in 6 clusters; every 50th spans the scene */
static double *cluster_tris(size_t n, uint64_t seed)
{
    double *v = malloc(n * 9 * sizeof(double));
    assert_non_null(v);
    uint64_t s = seed;
    double cen[6][3];
    for (int c = 0; c < 6; c++)
        for (int a = 0; a < 3; a++)
            cen[c][a] = 10.0 * rnd(&s);
    for (size_t k = 0; k < n; k++) {
        const int c = (int)(k % 6);
        const double r = k % 50 == 0 ? 5.0 : 0.05;
        for (int q = 0; q < 3; q++)
            for (int a = 0; a < 3; a++)
                v[9 * k + 3 * q + a] = cen[c][a] + (k % 50 == 0 ? 0.0 : 1.5 * (rnd(&s) - 0.5)) +
                                       r * (rnd(&s) - 0.5);
    }
    return v;
}

static rt_scene *make_scene(const double *v, size_t n, int mesh)
{
    int surf;
    rt_scene *sc = rtu_scene_one_surface(&surf);
    assert_non_null(sc);
    if (mesh) {
        uint32_t *idx = malloc(3 * n * sizeof(uint32_t));
        assert_non_null(idx);
        for (size_t k = 0; k < 3 * n; k++)
            idx[k] = (uint32_t)k;
        assert_true(rt_scene_add_mesh(sc, 3 * n, v, NULL, NULL, n, idx, surf, surf) >= 0);
        free(idx);
    } else {
        const int three = 3;
        for (size_t k = 0; k < n; k++)
            assert_true(rt_scene_add_polygon(sc, 1, &three, v + 9 * k, surf, surf) >= 0);
    }
    return sc;
}

/* commits sc on 1 thread, then on 2..4 threads with each chunk setting; every hash equals
   the first; back chunks were made */
static void check(rt_scene *sc, const rt_build_options *base, const char *name)
{
    static const struct {
        size_t min_refs;
        int front_max;
    } set[] = {{0, 0}, {1, 0}, {1, 1}, {1, 3}, {64, 1}};
    uint64_t hash = 0;
    const uint64_t back0 = rt_build_back_chunks();
    for (int threads = 1; threads <= 4; threads++)
        for (size_t q = 0; q < sizeof set / sizeof set[0]; q++) {
            if (threads == 1 && q > 0)
                continue;
            rt_build_options o = *base;
            o.threads = threads;
            rt_build_set_chunks(set[q].min_refs, set[q].front_max);
            const uint64_t b0 = rt_build_back_chunks();
            const int rc = rt_scene_commit(sc, &o);
            const uint64_t b1 = rt_build_back_chunks();
            rt_build_set_chunks(0, 0);
            assert_int_equal(rc, RT_OK);
            rt_grid_info gi;
            assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
            assert_true(gi.subgrids > 0);
            printf("%s, %d thread(s), chunks of >= %zu refs, front <= %d: grid %016llx, "
                   "%llu sub-grids, %llu sub refs, %llu back chunks\n",
                   name, threads, set[q].min_refs, set[q].front_max,
                   (unsigned long long)gi.hash, (unsigned long long)gi.subgrids,
                   (unsigned long long)gi.subrefs, (unsigned long long)(b1 - b0));
            if (threads > 1 && set[q].front_max)
                assert_true(b1 > b0); /* part 0 left the rest to the back */
            if (hash == 0)
                hash = gi.hash;
            else if (gi.hash != hash)
                fail_msg("%s: grid %016llx on %d threads (chunks >= %zu, front <= %d), "
                         "%016llx on 1", name, (unsigned long long)gi.hash, threads,
                         set[q].min_refs, set[q].front_max, (unsigned long long)hash);
        }
    assert_true(rt_build_back_chunks() > back0);
}

/* n clustered triangles from seed as separate triangles or as one mesh, built every way */
static void check_cluster(size_t n, uint64_t seed, int mesh, const char *name)
{
    double *v = cluster_tris(n, seed);
    rt_scene *sc = make_scene(v, n, mesh);
    /* the default factor given explicitly: its triangles (up to 1.5 across in cells of about
       0.8) would widen the default top level (rt_top_coarsen) to a few sub-grids, too few
       chunks for part 0 to be sure to leave some to the back; this keeps about 100 */
    rt_build_options o = {.brute_threshold = 0, .grid_factor = RT_GRID_FACTOR_DEFAULT};
    check(sc, &o, name);
    assert_true(sc->grid.nsubs >= 32);
    rt_scene_free(sc);
    free(v);
}

static void test_separate(void **state)
{
    (void)state;
    check_cluster(8000, 11, 0, "separate triangles");
}

static void test_mesh(void **state)
{
    (void)state;
    check_cluster(8000, 23, 1, "mesh");
}

/* a coarse top level and many cells per reference below: sub-grids of more than 65535
   references, so the 4-byte offsets stay */
static void test_wide(void **state)
{
    (void)state;
    const size_t n = 15000;
    double *v = cluster_tris(n, 5);
    rt_scene *sc = make_scene(v, n, 0);
    rt_build_options o = {.brute_threshold = 0, .grid_res = {2, 2, 2}, .sub_factor = 8.0};
    check(sc, &o, "wide sub-grids");
    assert_null(sc->grid.soff16);
    rt_scene_free(sc);
    free(v);
}

static int cmp_d(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* rt_kth_smallest against qsort for every k of sample v (n values) */
static void check_kth(const double *v, size_t n)
{
    double *s = malloc(n * sizeof *s), *w = malloc(n * sizeof *w);
    assert_non_null(s);
    assert_non_null(w);
    memcpy(s, v, n * sizeof *s);
    qsort(s, n, sizeof *s, cmp_d);
    for (size_t k = 0; k < n; k++) {
        memcpy(w, v, n * sizeof *w);
        const double got = rt_kth_smallest(w, n, k);
        assert_memory_equal(&got, &s[k], sizeof got); /* the same bits */
    }
    free(s);
    free(w);
}

static void test_kth_smallest(void **state)
{
    (void)state;
    enum { M = 300 };
    double v[M];
    uint64_t seed = 7;
    for (int t = 0; t < 6; t++) {
        for (int i = 0; i < M; i++) {
            const double x = rnd(&seed);
            /* t 0: spread over 40 binades; 1: few distinct values (repeats); 2: values
               differing in their last bits only; 3: zeros, subnormals, huge, infinity */
            v[i] = t == 0   ? ldexp(x, (int)(40 * rnd(&seed)) - 20)
                   : t == 1 ? floor(8 * x)
                   : t == 2 ? 1.0 + (double)(int)(16 * x) * DBL_EPSILON
                   : t == 3 ? (x < 0.2 ? 0.0 : x < 0.3 ? 4.9e-324 * (1 + i) : x < 0.4 ? INFINITY
                                                         : x < 0.5 ? 1e300 : x)
                   : t == 4 ? (i == 17 ? -0.0 : x) /* a negative zero: qsort */
                            : (i == 5 ? -x : x);   /* a negative value: qsort */
        }
        check_kth(v, M);
        check_kth(v, 1 + (size_t)t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_separate),
        cmocka_unit_test(test_mesh),
        cmocka_unit_test(test_wide),
        cmocka_unit_test(test_kth_smallest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
