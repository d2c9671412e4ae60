/* SPDX-License-Identifier: MIT */
/*
 * test_rt_core.c -- the grid traversal against brute force under the build settings the
 * defaults do not exercise, and the small mailbox of nearest / any-hit rays.
 *
 * Scenes are made so that the small direct-mapped mailbox (RT_HBOX entries, indexed by
 * primitive index modulo RT_HBOX) collides on purpose: many triangles whose indices differ by
 * multiples of 256 share cells, and exact duplicates (same vertices, other id) force the tie
 * rule. Every setting must give the brute-force hit bit for bit (prim, t, side) and the same
 * occlusion flags; a triangle fan around a ray-pierced vertex must never be missed; rays with
 * a direction component exactly 0 in a cell plane must find what lies in that plane.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "gksrt.h"
#include "rt_check.h"
#include "rt_testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint64_t rng_state = 1;

static double rnd(void) /* deterministic uniform [0,1) */
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

static void add_tri(rt_scene *sc, const double v[9], int surf)
{
    static const int cnt[1] = {3};
    assert_true(rt_scene_add_polygon(sc, 1, cnt, v, surf, surf) >= 0);
}

/* 1200 small random triangles in the unit cube, every 5th one copied about 256 ids later
   (same vertices: the tie rule decides, and the copies tend to collide in the small mailbox),
   plus a fan of 8 triangles around the vertex (0.5,0.5,0.5) */
static void build_scene(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    int surf = rt_scene_add_surface(sc, &s);
    assert_true(surf >= 0);
    enum { NT = 1200 };
    static double v[NT][9];
    rng_state = 12345;
    for (int k = 0; k < NT; k++) {
        double c[3];
        for (int i = 0; i < 3; i++)
            c[i] = 0.05 + 0.9 * rnd();
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                v[k][3 * j + i] = c[i] + 0.12 * (rnd() - 0.5);
    }
    for (int k = 0; k < NT; k++) {
        add_tri(sc, v[k], surf);
        if (k >= 256 && k % 5 == 0) /* copy of triangle k - 256, about 256 ids later */
            add_tri(sc, v[k - 256], surf);
    }
    for (int j = 0; j < 8; j++) { /* fan around (0.5,0.5,0.5) in the plane z = 0.5 */
        double a0 = 2.0 * M_PI * j / 8.0, a1 = 2.0 * M_PI * (j + 1) / 8.0;
        double t[9] = {0.5, 0.5, 0.5, 0.5 + 0.2 * cos(a0), 0.5 + 0.2 * sin(a0), 0.5,
                       0.5 + 0.2 * cos(a1), 0.5 + 0.2 * sin(a1), 0.5};
        add_tri(sc, t, surf);
    }
}

static void make_rays(rt_ray *rays, int n)
{
    rng_state = 777;
    for (int k = 0; k < n; k++) {
        rt_ray *r = &rays[k];
        for (int i = 0; i < 3; i++) {
            r->org[i] = 1.4 * rnd() - 0.2;
            r->dir[i] = 2.0 * rnd() - 1.0;
        }
        if (k % 7 == 3) { /* through the fan's centre vertex */
            for (int i = 0; i < 3; i++)
                r->dir[i] = 0.5 - r->org[i];
        }
        if (k % 7 == 5) { /* axis-aligned, signed zeros */
            int a = k % 3;
            for (int i = 0; i < 3; i++)
                r->dir[i] = (k / 7) % 2 ? -0.0 : 0.0;
            r->dir[a] = (k / 14) % 2 ? -1.0 : 1.0;
        }
        r->tmin = 0.0;
        r->tmax = k % 11 == 4 ? 0.4 : INFINITY;
    }
}

/* Brute-force results of n rays on the scene that build() makes, then the same rays on a grid
 * built with each of the ns settings: the same primitive and occluded flag for every ray, side
 * and t bit for bit, and the grid really used. FP traps are on while tracing. */
typedef struct brute_ref {
    rt_hit *hb, *hg;
    unsigned char *ob, *og;
} brute_ref;

static void brute_ref_init(brute_ref *br, size_t n)
{
    br->hb = malloc(n * sizeof *br->hb);
    br->hg = malloc(n * sizeof *br->hg);
    br->ob = malloc(n);
    br->og = malloc(n);
    assert_non_null(br->hb);
    assert_non_null(br->hg);
    assert_non_null(br->ob);
    assert_non_null(br->og);
}

static void brute_ref_trace(brute_ref *br, void (*build)(rt_scene *), const rt_ray *rays, size_t n)
{
    rt_scene *b = rt_scene_new();
    build(b);
    rt_build_options ob = {.brute_force = 1};
    assert_int_equal(rt_scene_commit(b, &ob), RT_OK);
    rtc_traps_on();
    assert_int_equal(rt_intersect(b, n, rays, br->hb), RT_OK);
    assert_int_equal(rt_occluded(b, n, rays, br->ob), RT_OK);
    rtc_traps_off();
    rt_scene_free(b);
}

static void brute_ref_check(brute_ref *br, void (*build)(rt_scene *), const rt_build_options *opts,
                            int ns, const rt_ray *rays, size_t n)
{
    rtc_traps_on();
    for (int s = 0; s < ns; s++) {
        rt_scene *g = rt_scene_new();
        build(g);
        assert_int_equal(rt_scene_commit(g, &opts[s]), RT_OK);
        rt_grid_info gi;
        assert_int_equal(rt_scene_grid_info(g, &gi), RT_OK);
        assert_true(gi.cells + gi.subcells > 1);
        assert_int_equal(rt_intersect(g, n, rays, br->hg), RT_OK);
        assert_int_equal(rt_occluded(g, n, rays, br->og), RT_OK);
        for (size_t k = 0; k < n; k++) {
            assert_int_equal(br->hg[k].prim, br->hb[k].prim);
            assert_int_equal(br->og[k], br->ob[k]);
            if (br->hb[k].prim < 0)
                continue;
            assert_memory_equal(&br->hg[k].t, &br->hb[k].t, sizeof(double));
            assert_int_equal(br->hg[k].side, br->hb[k].side);
        }
        rt_scene_free(g);
    }
    rtc_traps_off();
}

static void brute_ref_free(brute_ref *br)
{
    free(br->hb);
    free(br->hg);
    free(br->ob);
    free(br->og);
}

static void test_settings_equal_brute(void **state)
{
    (void)state;
    enum { N = 20000, NS = 6 };
    const rt_build_options opts[NS] = {
        {.brute_threshold = 0},                                         /* defaults */
        {.brute_threshold = 0, .grid_factor = 0.002},                   /* one coarse top level */
        {.brute_threshold = 0, .grid_factor = 0.01, .sub_factor = 1.0}, /* coarse second level */
        {.brute_threshold = 0, .grid_factor = 0.01, .sub_factor = 64.0, .sub_min = 1},
        {.brute_threshold = 0, .grid_factor = 4.0, .no_subgrids = 1},   /* fine, one level */
        {.brute_threshold = 0, .grid_res = {3, 5, 2}, .grid_box = {0, 0, 0, 1, 1, 1}},
    };
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    make_rays(rays, N);
    brute_ref br;
    brute_ref_init(&br, N);
    brute_ref_trace(&br, build_scene, rays, N);
    const rt_hit *hb = br.hb;
    int nhit = 0, nfan = 0;
    for (int k = 0; k < N; k++) {
        nhit += hb[k].prim >= 0;
        /* rays aimed at the fan's centre from below / above z = 0.5 hit something no later
           than the fan (the vertex shared by 8 triangles must not leak) */
        if (k % 7 == 3 && fabs(rays[k].org[2] - 0.5) > 1e-3 && rays[k].tmax > 1.0) {
            nfan++;
            assert_true(hb[k].prim >= 0);
            assert_true(hb[k].t <= 1.0 + 1e-12);
        }
    }
    assert_true(nhit > N / 4);
    assert_true(nfan > 1000);
    brute_ref_check(&br, build_scene, opts, NS, rays, N);
    brute_ref_free(&br);
    free(rays);
}

/* big_n random triangles in the unit cube, each within a cube of side big_side * big_n^(-1/3)
   around its centre (big_side 2: the random triangles of the build benchmark, large against
   the top cells of the default rule) */
enum { NB = 12000 };
static int big_n = NB;
static double big_side;

static void build_big(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    int surf = rt_scene_add_surface(sc, &s);
    assert_true(surf >= 0);
    rng_state = 4242;
    const double side = big_side * pow((double)big_n, -1.0 / 3.0);
    for (int k = 0; k < big_n; k++) {
        double c[3], v[9];
        for (int i = 0; i < 3; i++)
            c[i] = rnd();
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++)
                v[3 * j + i] = c[i] + side * (rnd() - 0.5);
        add_tri(sc, v, surf);
    }
}

/* n random triangles of build_big (side 2) committed with default options get a widened top
   level (fewer than 100 cells, with sub-grids; with sub_max, fewer second-level cells than
   that many per triangle) and brute force's answers; triangles a third the size keep the
   rule's top level (more than 1000 cells) */
static void check_coarse_top(int n, double sub_max)
{
    enum { N = 2000 };
    const rt_build_options dflt = {.brute_threshold = 0};
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    make_rays(rays, N);
    big_n = n;
    big_side = 2.0;
    rt_scene *sc = rt_scene_new();
    build_big(sc);
    assert_int_equal(rt_scene_commit(sc, &dflt), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_true(gi.cells < 100);
    assert_true(gi.subgrids > 0);
    if (sub_max > 0)
        assert_true((double)gi.subcells < sub_max * n);
    rt_scene_free(sc);
    brute_ref br;
    brute_ref_init(&br, N);
    brute_ref_trace(&br, build_big, rays, N);
    int nhit = 0;
    for (int k = 0; k < N; k++)
        nhit += br.hb[k].prim >= 0;
    assert_true(nhit > N / 4);
    brute_ref_check(&br, build_big, &dflt, 1, rays, N);
    brute_ref_free(&br);
    big_side = 2.0 / 3.0;
    sc = rt_scene_new();
    build_big(sc);
    assert_int_equal(rt_scene_commit(sc, &dflt), RT_OK);
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_true(gi.cells > 1000);
    rt_scene_free(sc);
    big_n = NB;
    free(rays);
}

/* primitives large against the default rule's top cells get a coarser top level (rt_build.c,
   RT_TOP_EXT_LARGE): far fewer top cells than the 14^3 of the rule for 12000 primitives */
static void test_large_prims_coarse_top(void **state)
{
    (void)state;
    check_coarse_top(NB, 0.0);
}

/* the same at or below 10^4 primitives (RT_TOP_EXT_LARGE_SMALL): 5000 such triangles (the
   rule alone gives 11^3 top cells, and the uniform level of RT_UNIFORM_SHARE 40,000) with
   RT_SUB_FACTOR_COARSE second-level cells per reference (fewer than 4 sub cells per
   triangle; RT_SUB_FACTOR_LARGE would give 4.4); triangles a third of their size (median
   box 0.2 of a top cell, as the SPD scenes' 0.20-0.26) keep the rule's grid */
static void test_large_prims_coarse_top_small(void **state)
{
    (void)state;
    check_coarse_top(5000, 4.0);
}

/* duplicates: the tie rule must pick the larger id (drawn later) whichever copy the grid
   meets first */
static void test_duplicate_tie(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    int surf = rt_scene_add_surface(sc, &s);
    const double t[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const double far_tri[9] = {0, 0, 5, 1, 0, 5, 0, 1, 5};
    /* 600 filler triangles, then copies of t at ids 600, 856 (= 600 + 256), 1112 */
    for (int k = 0; k < 600; k++)
        add_tri(sc, far_tri, surf);
    add_tri(sc, t, surf);
    for (int k = 0; k < 255; k++)
        add_tri(sc, far_tri, surf);
    add_tri(sc, t, surf);
    for (int k = 0; k < 255; k++)
        add_tri(sc, far_tri, surf);
    add_tri(sc, t, surf);
    rt_build_options o = {.brute_threshold = 0, .grid_factor = 1.0};
    assert_int_equal(rt_scene_commit(sc, &o), RT_OK);
    rt_ray r = {{0.2, 0.3, -1.0}, {0.0, 0.0, 1.0}, 0.0, INFINITY};
    rt_hit h;
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
    assert_int_equal(h.prim, 1112);
    assert_true(fabs(h.t - 1.0) < 1e-12);
    r.org[2] = 2.0; /* from between: the far stack (largest id 1111) */
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
    assert_int_equal(h.prim, 1111);
    assert_true(fabs(h.t - 3.0) < 1e-12);
    rt_scene_free(sc);
}

/* sparse clusters in a large box: the top level has wide empty regions the traversal jumps
   over (rt_grid.odist); rays along exact diagonals leave the jump cubes through their corners */
static double sparse_v[7 * 60][9];

static void build_sparse(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    int surf = rt_scene_add_surface(sc, &s);
    assert_true(surf >= 0);
    rng_state = 4242;
    for (int c = 0; c < 7; c++) {
        double ctr[3];
        for (int i = 0; i < 3; i++)
            ctr[i] = 10.0 * rnd();
        for (int k = 0; k < 60; k++) {
            double *v = sparse_v[60 * c + k];
            for (int j = 0; j < 9; j++)
                v[j] = ctr[j % 3] + 0.8 * (rnd() - 0.5);
            add_tri(sc, v, surf);
        }
    }
    const double big[9] = {0, 0, 0, 10, 0, 0, 0, 10, 0}; /* floor corner piece */
    add_tri(sc, big, surf);
}

static void test_empty_space_jumps(void **state)
{
    (void)state;
    enum { N = 30000, NS = 4 };
    const rt_build_options opts[NS] = {
        {.brute_threshold = 0},
        {.brute_threshold = 0, .grid_res = {48, 48, 48}, .grid_box = {-1, -1, -1, 11, 11, 11}},
        {.brute_threshold = 0, .grid_res = {61, 7, 33}, .no_subgrids = 1},
        {.brute_threshold = 0, .grid_factor = 8.0},
    };
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    rng_state = 99;
    for (int k = 0; k < N; k++) {
        rt_ray *r = &rays[k];
        for (int i = 0; i < 3; i++) {
            r->org[i] = 12.0 * rnd() - 1.0;
            r->dir[i] = 2.0 * rnd() - 1.0;
        }
        if (k % 3 == 1) /* exact diagonals: equal steps on all axes */
            for (int i = 0; i < 3; i++)
                r->dir[i] = ((k >> (i + 2)) & 1) ? -1.0 : 1.0;
        if (k % 3 == 2) { /* aimed at a vertex of a cluster triangle */
            const double *v = sparse_v[(k / 3) % (7 * 60)] + 3 * (k % 9 / 3);
            for (int i = 0; i < 3; i++)
                r->dir[i] = v[i] - r->org[i];
        }
        r->tmin = 0.0;
        r->tmax = k % 13 == 5 ? 3.0 : INFINITY;
    }
    brute_ref br;
    brute_ref_init(&br, N);
    brute_ref_trace(&br, build_sparse, rays, N);
    int nhit = 0;
    for (int k = 0; k < N; k++)
        nhit += br.hb[k].prim >= 0;
    assert_true(nhit > N / 20);
    brute_ref_check(&br, build_sparse, opts, NS, rays, N);
    brute_ref_free(&br);
    free(rays);
}

/* A lat-long triangle sphere standing on a floor of quads, both symmetric about x = 0 and
   y = 0, so a top-level cell plane falls on (or within rounding of: -1.6 + 6 * 3.2 / 12 is
   2.2e-16) the planes x = 0 and y = 0 that hold meridian edges of the sphere. */
static void build_symsphere(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    const int sid = rt_scene_add_surface(sc, &s);
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++) {
            const double x0 = -1.6 + 0.4 * i, y0 = -1.6 + 0.4 * j;
            const double v[12] = {x0, y0, -2.5, x0 + 0.4, y0, -2.5, x0 + 0.4, y0 + 0.4, -2.5,
                                  x0, y0 + 0.4, -2.5};
            const int n = 4;
            assert_true(rt_scene_add_polygon(sc, 1, &n, v, sid, sid) >= 0);
        }
    assert_int_equal(rtu_add_sphere(sc, (const double[3]){0.0, 0.0, -1.9}, 0.55, 48, 24, sid), 0);
}

/* rays in the planes x = 0 and y = 0 with that direction component exactly +0.0 or -0.0:
   the top-level walk places them in the cell on one side of the plane, whose second-level
   grid must not reject them for lying 2.2e-16 outside its box (it did: the sphere was
   missed through its meridian triangles, rt_build_subgrids) */
static void test_zero_component_on_cell_plane(void **state)
{
    (void)state;
    enum { N = 8000, NS = 3 };
    const rt_build_options opts[NS] = {
        {.brute_threshold = 0},
        {.brute_threshold = 0, .grid_factor = 4.0},
        {.brute_threshold = 0, .sub_min = 1, .sub_factor = 16.0},
    };
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    rng_state = 7;
    for (int k = 0; k < N; k++) {
        rt_ray *r = &rays[k];
        const int a = k & 1;               /* the zero axis: x or y */
        const double zero = k & 2 ? -0.0 : 0.0;
        const double s = 3.0 * rnd() - 1.5, ang = M_PI * (0.05 + 0.9 * rnd());
        r->org[a] = 0.0;
        r->org[1 - a] = s;
        r->org[2] = k % 5 == 0 ? -2.49 : -0.5;
        r->dir[a] = zero;
        r->dir[1 - a] = cos(ang);
        r->dir[2] = r->org[2] < -1.0 ? sin(ang) : -sin(ang);
        r->tmin = 0.0;
        r->tmax = INFINITY;
    }
    brute_ref br;
    brute_ref_init(&br, N);
    brute_ref_trace(&br, build_symsphere, rays, N);
    int nsphere = 0;
    for (int k = 0; k < N; k++)
        nsphere += br.hb[k].prim >= 64;
    assert_true(nsphere > N / 10);
    brute_ref_check(&br, build_symsphere, opts, NS, rays, N);
    brute_ref_free(&br);
    free(rays);
}

/* 900 small triangles and two large ones near the oblique plane through (0.5, 0.5, 0.5)
   spanned by (0.8, 0.6, 0) and (-0.36, 0.48, 0.8): a scene whose grid is laid out in a
   rotated frame (checked below) */
static void build_tilted(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    int surf = rt_scene_add_surface(sc, &s);
    assert_true(surf >= 0);
    static const double e1[3] = {0.8, 0.6, 0.0}, e2[3] = {-0.36, 0.48, 0.8},
                        n[3] = {0.48, -0.64, 0.6};
    rng_state = 777;
    for (int k = 0; k < 902; k++) {
        const double size = k < 2 ? 1.6 : 0.06;
        const double cu = k < 2 ? 0.0 : 1.6 * (rnd() - 0.5), cv = k < 2 ? 0.0 : 1.6 * (rnd() - 0.5);
        double v[9];
        for (int j = 0; j < 3; j++) {
            const double u = cu + size * (k < 2 ? (j == 1) - 0.4 + 0.2 * k : rnd() - 0.5);
            const double w = cv + size * (k < 2 ? (j == 2) - 0.4 : rnd() - 0.5);
            const double h = k < 2 ? 0.0 : 0.05 * (rnd() - 0.5);
            for (int i = 0; i < 3; i++)
                v[3 * j + i] = 0.5 + u * e1[i] + w * e2[i] + h * n[i];
        }
        add_tri(sc, v, surf);
    }
}

/* The batch API sets rays up four at a time (rt_trace.c, rt_pre4) and gives the unusual ones
   to the one-ray code: groups of four that mix ordinary rays with non-finite values (quiet
   and signalling NaN, infinities), zero, tiny and flushed direction components, empty or
   reversed ranges, origins beyond the range limit and rays that miss the grid box must give
   the brute-force answers, also with a batch length that is not a multiple of four, and in a
   rotated grid frame. Run with the AVX2 lanes where the CPU has them (rt_core) and without
   (rt_core_scalar: one ray at a time). */
static void test_batch_of_four_unusual_rays(void **state)
{
    (void)state;
    enum { N = 4003 };
    uint64_t snan_bits = 0x7ff0000000000001ULL;
    double snan;
    memcpy(&snan, &snan_bits, sizeof snan);
    const double odd[] = {NAN, -NAN, snan, INFINITY, -INFINITY, 0.0, -0.0, 1e-160, -1e-170,
                          1e-101, 2e100, -1e101, 1e300};
    const int nodd = (int)(sizeof odd / sizeof odd[0]);
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    rng_state = 4242;
    for (int k = 0; k < N; k++) {
        rt_ray *r = &rays[k];
        for (int i = 0; i < 3; i++) {
            r->org[i] = 3.0 * rnd() - 1.0;
            r->dir[i] = (0.5 + 0.5 * rnd() - r->org[i]) * (rnd() < 0.5 ? 1.0 : 0.3);
        }
        r->tmin = 0.0;
        r->tmax = k % 7 == 3 ? 0.8 : INFINITY;
        const int kind = (int)(rnd() * 12.0);
        const double v = odd[(int)(rnd() * nodd)];
        const int a = (int)(rnd() * 3.0);
        switch (kind) {
        case 0: r->dir[a] = v; break;
        case 1: r->org[a] = v; break;
        case 2: r->tmin = v; break;
        case 3: r->tmax = v; break;
        case 4: r->dir[0] = r->dir[1] = r->dir[2] = v; break;
        case 5: r->tmin = r->tmax + 1.0; break; /* reversed range (inf + 1: tmin = inf) */
        case 6: r->org[a] = a == 0 ? 5.0 : -4.0; break; /* outside the box, mostly missing it */
        case 7: r->dir[a] = 1e-155 * fabs(r->dir[(a + 1) % 3]); break; /* flushed to 0 */
        default: break; /* an ordinary ray */
        }
    }
    brute_ref br;
    brute_ref_init(&br, N);
    brute_ref_trace(&br, build_scene, rays, N);
    const rt_build_options opts[2] = {{.brute_threshold = 0},
                                      {.brute_threshold = 0, .grid_factor = 6.0}};
    brute_ref_check(&br, build_scene, opts, 2, rays, N);
    /* the groups of four from another start (other rays share a group) */
    brute_ref sh;
    brute_ref_init(&sh, N - 2);
    brute_ref_trace(&sh, build_scene, rays + 2, N - 2);
    brute_ref_check(&sh, build_scene, opts, 1, rays + 2, N - 2);
    int nhit = 0;
    for (int k = 0; k < N; k++)
        nhit += br.hb[k].prim >= 0;
    assert_true(nhit > N / 10);
    /* and in a rotated grid frame */
    rt_scene *t = rt_scene_new();
    build_tilted(t);
    assert_int_equal(rt_scene_commit(t, &opts[0]), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(t, &gi), RT_OK);
    assert_int_equal(gi.rotated, 1);
    rt_scene_free(t);
    brute_ref tr;
    brute_ref_init(&tr, N);
    brute_ref_trace(&tr, build_tilted, rays, N);
    brute_ref_check(&tr, build_tilted, opts, 1, rays, N);
    nhit = 0;
    for (int k = 0; k < N; k++)
        nhit += tr.hb[k].prim >= 0;
    assert_true(nhit > N / 20);
    brute_ref_free(&tr);
    brute_ref_free(&sh);
    brute_ref_free(&br);
    free(rays);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_settings_equal_brute),
        cmocka_unit_test(test_large_prims_coarse_top),
        cmocka_unit_test(test_large_prims_coarse_top_small),
        cmocka_unit_test(test_duplicate_tie),
        cmocka_unit_test(test_empty_space_jumps),
        cmocka_unit_test(test_zero_component_on_cell_plane),
        cmocka_unit_test(test_batch_of_four_unusual_rays),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
