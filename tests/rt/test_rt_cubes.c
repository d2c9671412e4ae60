/* SPDX-License-Identifier: MIT */
/*
 * test_rt_cubes.c -- the top level's empty cubes (rt_grid.odist, rt_build.c), checked cell by
 * cell against a brute-force search: for every cell and octant, the largest edge m such that
 * the m^3 cells from the cell on in the octant's directions (those inside the grid) hold no
 * references and no second-level grid, capped at 255; 0 for an occupied cell. Scenes: sparse
 * clusters in a large box (wide empty regions, long cubes) with 1 and 2 build threads and a
 * grid of unequal axes; a single triangle (cubes reach the box's faces).
 * The occupied space's k-DOP (rt_grid.kd_lo, kd_hi, from the cells or from a mesh's
 * vertices): every vertex lies inside its slabs, the slabs cut the box's corners, and rays
 * clipped to it (in-box misses, exact diagonals that run parallel to slabs, rays aimed at
 * vertices) find the same hits as the brute-force test of every primitive.
 */
#include <math.h>
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
    size_t nempty = 0, nlong = 0, nlist = 0, nsub = 0;
    for (int o = 0; o < 8; o++)
        for (int z = 0; z < g->b.n[2]; z++)
            for (int y = 0; y < g->b.n[1]; y++)
                for (int x = 0; x < g->b.n[0]; x++) {
                    const size_t ci = ((size_t)z * g->b.n[1] + y) * g->b.n[0] + x;
                    /* an occupied cell: what it holds; an empty one: its cube, capped */
                    const int list = g->off[ci + 1] != g->off[ci];
                    const int sub = g->sub && g->sub[ci] >= 0;
                    const int cube = occupied(g, x, y, z) ? 0 : brute_cube(g, x, y, z, o);
                    const int want = cube == 0 ? RT_CUBE_OCC | (list ? RT_CUBE_LIST : 0) |
                                                     (sub ? RT_CUBE_SUB : 0)
                                     : cube < RT_CUBE_MAX ? cube
                                                          : RT_CUBE_MAX;
                    const int got = g->odist[(size_t)o * g->ncells + ci];
                    if (got != want)
                        fail_msg("cell (%d,%d,%d) octant %d: byte %d, brute force %d", x, y, z,
                                 o, got, want);
                    nempty += cube > 0;
                    nlong += cube >= 4;
                    nlist += list;
                    nsub += sub;
                }
    /* the scenes have empty cells and cubes long enough for jumps, cells with lists, and
       second-level grids where the grid has any */
    assert_true(nempty > 0);
    assert_true(nlong > 0);
    assert_true(nlist > 0);
    assert_true(!g->sub || nsub > 0);
}

/* every vertex (n of them, in the grid frame) inside the k-DOP's slabs; the slabs cut off a
   corner of the box */
static void check_kdop(const rt_scene *sc, const double *v, size_t n)
{
    const rt_grid *g = &sc->grid;
    for (size_t k = 0; k < n; k++) {
        double p[3], s[RT_KDOP];
        rt_grid_point(g, v + 3 * k, p);
        RT_KDOP_PROJ(s, p[0], p[1], p[2]);
        for (int j = 0; j < RT_KDOP; j++)
            if (!(g->kd_lo[j] < s[j] && s[j] < g->kd_hi[j]))
                fail_msg("vertex %zu outside slab %d: %g not in [%g, %g]", k, j, s[j],
                         g->kd_lo[j], g->kd_hi[j]);
    }
    int cut = 0;
    for (int q = 0; q < 8; q++) {
        double s[RT_KDOP];
        RT_KDOP_PROJ(s, q & 1 ? g->b.hi[0] : g->b.lo[0], q & 2 ? g->b.hi[1] : g->b.lo[1],
                     q & 4 ? g->b.hi[2] : g->b.lo[2]);
        for (int j = 0; j < RT_KDOP; j++)
            cut += s[j] < g->kd_lo[j] || s[j] > g->kd_hi[j];
    }
    assert_true(cut > 0);
}

static double cl_v[5 * 40 * 9];

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
            memcpy(cl_v + 9 * (40 * c + k), v, sizeof v);
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
        if (!opts[k].grid_res[0])
            check_kdop(sc, cl_v, 5 * 40 * 3);
        rt_scene_free(sc);
    }
}

/* one triangle in the middle of a small grid, and at one end of a long row of cells (cubes
   beyond RT_CUBE_MAX, stored capped) */
static void test_cubes_one_triangle(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        rt_scene *sc = rt_scene_new();
        assert_non_null(sc);
        rt_surface s;
        rt_surface_default(&s);
        const int surf = rt_scene_add_surface(sc, &s);
        const double x = k ? 9.95 : 5.0;
        const double v[9] = {x - 0.01, 5.0, 5.0, x + 0.01, 5.0, 5.0, x, 5.1, 5.05};
        const int n = 3;
        assert_true(rt_scene_add_polygon(sc, 1, &n, v, surf, surf) >= 0);
        const rt_build_options o = {.brute_threshold = 0, .threads = 1,
                                    .grid_res = {k ? 200 : 12, k ? 3 : 10, k ? 2 : 8},
                                    .grid_box = {0, 0, 0, 10, 10, 10}};
        assert_int_equal(rt_scene_commit(sc, &o), RT_OK);
        if (!k) {
            check_cubes(sc);
        } else {
            /* the brute force is too slow for cubes this long: the first cell's cube towards
               the triangle (about 198 cells) is stored as RT_CUBE_MAX, and every empty cell's
               byte is a cube edge */
            const rt_grid *g = &sc->grid;
            assert_int_equal(g->odist[0], RT_CUBE_MAX);
            for (size_t i = 0; i < 8 * g->ncells; i++)
                if (!occupied(g, (int)(i % g->ncells % 200), (int)(i % g->ncells / 200 % 3),
                              (int)(i % g->ncells / 600)))
                    assert_true(g->odist[i] >= 1 && g->odist[i] <= RT_CUBE_MAX);
        }
        rt_scene_free(sc);
    }
}

/* the clusters as one indexed mesh, with the options o */
static rt_scene *clusters_mesh(const rt_build_options *o)
{
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    add_clusters(sc); /* fills cl_v; the scene is dropped */
    rt_scene_free(sc);
    sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    const int surf = rt_scene_add_surface(sc, &s);
    static uint32_t idx[5 * 40 * 3];
    for (uint32_t k = 0; k < 5 * 40 * 3; k++)
        idx[k] = k;
    assert_true(rt_scene_add_mesh(sc, 5 * 40 * 3, cl_v, NULL, NULL, 5 * 40, idx, surf, surf) >= 0);
    assert_int_equal(rt_scene_commit(sc, o), RT_OK);
    return sc;
}

static void test_kdop_mesh(void **state)
{
    (void)state;
    enum { NR = 20000 };
    const rt_build_options og = {.brute_threshold = 0, .threads = 1};
    const rt_build_options ob = {.brute_force = 1};
    rt_scene *sc = clusters_mesh(&og), *bf = clusters_mesh(&ob);
    check_kdop(sc, cl_v, 5 * 40 * 3);
    rt_ray *r = malloc(NR * sizeof *r);
    rt_hit *h = malloc(NR * sizeof *h), *hb = malloc(NR * sizeof *hb);
    assert_true(r && h && hb);
    uint64_t st = 5;
    for (int k = 0; k < NR; k++) {
        /* from a sphere around the box into it; every third along an exact diagonal (slabs
           it runs parallel to), every third aimed at a vertex */
        double u[3], n2 = 0.0;
        for (int i = 0; i < 3; i++) {
            u[i] = rtu_rand(&st) - 0.5;
            n2 += u[i] * u[i];
        }
        for (int i = 0; i < 3; i++) {
            r[k].org[i] = 5.0 + 20.0 * u[i] / sqrt(n2);
            const double at = k % 3 == 2 ? cl_v[9 * (k % 200) + i] : 10.0 * rtu_rand(&st);
            r[k].dir[i] = at - r[k].org[i];
            if (k % 3 == 1)
                r[k].dir[i] = r[k].dir[i] < 0.0 ? -1.0 : 1.0;
        }
        if (k % 6 == 1)
            r[k].dir[k % 18 / 6] = 0.0;
        r[k].tmin = 0.0;
        r[k].tmax = INFINITY;
    }
    assert_int_equal(rt_intersect(sc, NR, r, h), RT_OK);
    assert_int_equal(rt_intersect(bf, NR, r, hb), RT_OK);
    /* one ray per call (the one-ray set-up and its shear, rt_rayx_shear) against the batch's
       four-ray set-up (rt_shear4): the same hits, bit for bit */
    for (int k = 0; k < NR; k += 7) {
        rt_hit h1;
        assert_int_equal(rt_intersect(sc, 1, &r[k], &h1), RT_OK);
        if (h1.prim != h[k].prim || memcmp(&h1.t, &h[k].t, sizeof h1.t) != 0)
            fail_msg("ray %d alone: prim %d t %.17g, in the batch prim %d t %.17g", k, h1.prim,
                     h1.t, h[k].prim, h[k].t);
    }
    int nhit = 0, nmiss = 0;
    for (int k = 0; k < NR; k++) {
        if (h[k].prim != hb[k].prim || memcmp(&h[k].t, &hb[k].t, sizeof h[k].t) != 0)
            fail_msg("ray %d: prim %d t %.17g, brute force prim %d t %.17g", k, h[k].prim,
                     h[k].t, hb[k].prim, hb[k].t);
        nhit += h[k].prim >= 0;
        nmiss += h[k].prim < 0;
    }
    assert_true(nhit > NR / 20 && nmiss > NR / 20);
    free(r);
    free(h);
    free(hb);
    rt_scene_free(sc);
    rt_scene_free(bf);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubes_clusters),
        cmocka_unit_test(test_cubes_one_triangle),
        cmocka_unit_test(test_kdop_mesh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
