/* SPDX-License-Identifier: MIT */
/*
 * test_rt_cubes.c -- the top level's empty cubes (rt_grid.odist, rt_build.c), checked cell by
 * cell against a brute-force search: for every cell and octant, the largest edge m such that
 * the m^3 cells from the cell on in the octant's directions (those inside the grid) hold no
 * references and no second-level grid, capped at 255; 0 for an occupied cell. Scenes: sparse
 * clusters in a large box (wide empty regions, long cubes) with 1 and 2 build threads and a
 * grid of unequal axes; a single triangle (cubes reach the box's faces).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_testutil.h"

static int occupied(const rt_grid *g, int x, int y, int z)
{
    const size_t ci = ((size_t)z * g->b.n[1] + y) * g->b.n[0] + x;
    return g->off[ci + 1] != g->off[ci] || (g->sub && g->sub[ci] >= 0);
}

/* the largest empty cube at (x, y, z) in octant o, cells beyond the grid counting as empty */
static int brute_cube(const rt_grid *g, int x, int y, int z, int o)
{
    const int s[3] = {o & 1 ? -1 : 1, o & 2 ? -1 : 1, o & 4 ? -1 : 1};
    int m = 0;
    while (m < 255) {
        /* grow to m + 1: the new shell has one coordinate offset equal to m */
        int ok = 1;
        for (int k = 0; k <= m && ok; k++)
            for (int j = 0; j <= m && ok; j++)
                for (int i = 0; i <= m && ok; i++) {
                    if (i != m && j != m && k != m)
                        continue;
                    const int cx = x + s[0] * i, cy = y + s[1] * j, cz = z + s[2] * k;
                    if (cx < 0 || cy < 0 || cz < 0 || cx >= g->b.n[0] || cy >= g->b.n[1] ||
                        cz >= g->b.n[2])
                        continue;
                    ok = !occupied(g, cx, cy, cz);
                }
        if (!ok)
            break;
        m++;
        /* past the grid on every axis: every larger cube is empty too */
        if ((x + s[0] * m < 0 || x + s[0] * m >= g->b.n[0]) &&
            (y + s[1] * m < 0 || y + s[1] * m >= g->b.n[1]) &&
            (z + s[2] * m < 0 || z + s[2] * m >= g->b.n[2]))
            return 255;
    }
    return m;
}

static void check_cubes(const rt_scene *sc)
{
    const rt_grid *g = &sc->grid;
    assert_true(sc->use_grid);
    assert_non_null(g->odist);
    size_t nempty = 0, nlong = 0;
    for (int o = 0; o < 8; o++)
        for (int z = 0; z < g->b.n[2]; z++)
            for (int y = 0; y < g->b.n[1]; y++)
                for (int x = 0; x < g->b.n[0]; x++) {
                    const size_t ci = ((size_t)z * g->b.n[1] + y) * g->b.n[0] + x;
                    const int want = occupied(g, x, y, z) ? 0 : brute_cube(g, x, y, z, o);
                    const int got = g->odist[(size_t)o * g->ncells + ci];
                    if (got != want)
                        fail_msg("cell (%d,%d,%d) octant %d: cube %d, brute force %d", x, y, z, o,
                                 got, want);
                    nempty += want > 0;
                    nlong += want >= 4;
                }
    /* the scenes have empty cells and cubes long enough for jumps */
    assert_true(nempty > 0);
    assert_true(nlong > 0);
}

static void add_clusters(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    const int surf = rt_scene_add_surface(sc, &s);
    assert_true(surf >= 0);
    uint64_t st = 77;
    for (int c = 0; c < 5; c++) {
        double ctr[3];
        for (int i = 0; i < 3; i++)
            ctr[i] = 10.0 * rtu_rand(&st);
        for (int k = 0; k < 40; k++) {
            double v[9];
            for (int j = 0; j < 9; j++)
                v[j] = ctr[j % 3] + 0.6 * (rtu_rand(&st) - 0.5);
            const int n = 3;
            assert_true(rt_scene_add_polygon(sc, 1, &n, v, surf, surf) >= 0);
        }
    }
}

static void test_cubes_clusters(void **state)
{
    (void)state;
    const rt_build_options opts[] = {
        {.brute_threshold = 0, .threads = 1},
        {.brute_threshold = 0, .threads = 2},
        {.brute_threshold = 0, .threads = 2, .grid_res = {19, 7, 13}, .no_subgrids = 1},
        {.brute_threshold = 0, .threads = 1, .grid_res = {16, 16, 16},
         .grid_box = {-2, -2, -2, 12, 12, 12}},
    };
    for (size_t k = 0; k < sizeof opts / sizeof opts[0]; k++) {
        rt_scene *sc = rt_scene_new();
        assert_non_null(sc);
        add_clusters(sc);
        assert_int_equal(rt_scene_commit(sc, &opts[k]), RT_OK);
        check_cubes(sc);
        rt_scene_free(sc);
    }
}

static void test_cubes_one_triangle(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    const int surf = rt_scene_add_surface(sc, &s);
    const double v[9] = {4.9, 5.0, 5.0, 5.1, 5.0, 5.0, 5.0, 5.1, 5.05};
    const int n = 3;
    assert_true(rt_scene_add_polygon(sc, 1, &n, v, surf, surf) >= 0);
    const rt_build_options o = {.brute_threshold = 0, .threads = 1, .grid_res = {12, 10, 8},
                                .grid_box = {0, 0, 0, 10, 10, 10}};
    assert_int_equal(rt_scene_commit(sc, &o), RT_OK);
    check_cubes(sc);
    rt_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubes_clusters),
        cmocka_unit_test(test_cubes_one_triangle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
