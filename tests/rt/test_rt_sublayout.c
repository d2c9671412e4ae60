/* SPDX-License-Identifier: MIT */
/*
 * test_rt_sublayout.c -- the two layouts of the second level's cell offsets (rt_grid.soff16
 * and soff, rt_build.c: rt_sub_narrow): 2-byte offsets relative to each sub-grid's first
 * reference where no sub-grid has more than 65535 references, else the 4-byte absolute ones.
 * A cluster of triangles in one top cell of a large box (a few triangles at its corners)
 * gets a sub-grid; with 1500 triangles its references fit in 16 bits, with 20000 larger ones
 * they do not. For each scene (1 and 2 build threads): the layout chosen is the one expected;
 * every sub cell's list read through rt_sub_off is the list that the 4-byte layout of the same
 * build held (rebuilt from the sub-grids' own counts: offsets ascending, ending at nsrefs,
 * every reference a primitive); and rays through the cluster get the brute-force scene's hits
 * bit for bit (rt_intersect, rt_occluded), the packet path the single-ray path's
 * (rt_intersect_packet, rt_occluded_packet), so the walk reads either layout. The sub-grid
 * records start on cache lines. And the references' 2-byte layout of widened top levels
 * (rt_grid.sref16: indices into each sub-grid's table of primitives), test_local; a widened
 * level whose sub-grid has more than 65535 references keeps primitive indices,
 * test_wide_coarse.
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
#include "rt_packet.h"
#include "rt_testutil.h"

/* the triangles at the 8 corners of [0, 10]^3 */
static void add_corners(rt_scene *sc, int surf)
{
    const int three = 3;
    for (int k = 0; k < 8; k++) {
        const double x = k & 1 ? 10.0 : 0.0, y = k & 2 ? 10.0 : 0.0, z = k & 4 ? 10.0 : 0.0;
        const double dx = x > 0 ? -0.1 : 0.1, dy = y > 0 ? -0.1 : 0.1;
        const double v[9] = {x, y, z, x + dx, y, z, x, y + dy, z};
        assert_true(rt_scene_add_polygon(sc, 1, &three, v, surf, surf) >= 0);
    }
}

/* n triangles around random centres in [4.5, 5.5]^3, edges up to 2 * half, and one triangle
   at each of the 8 corners of [0, 10]^3 (the box whose top cell holds the cluster), after the
   cluster or, with corners_first, before it (the cluster's primitive indices then differ from
   their places in a table of the sub-grid's primitives) */
static rt_scene *cluster_scene(int n, double half, int corners_first)
{
    int surf;
    rt_scene *sc = rtu_scene_one_surface(&surf);
    assert_non_null(sc);
    const int three = 3;
    uint64_t st = 4711;
    if (corners_first)
        add_corners(sc, surf);
    for (int k = 0; k < n; k++) {
        double c[3], v[9];
        for (int i = 0; i < 3; i++)
            c[i] = 4.5 + rtu_rand(&st);
        for (int j = 0; j < 9; j++)
            v[j] = c[j % 3] + half * (2.0 * rtu_rand(&st) - 1.0);
        assert_true(rt_scene_add_polygon(sc, 1, &three, v, surf, surf) >= 0);
    }
    if (!corners_first)
        add_corners(sc, surf);
    return sc;
}

/* the sub-grids' lists through rt_sub_off: contiguous, ascending, covering srefs once */
static void check_lists(const rt_scene *sc)
{
    const rt_grid *g = &sc->grid;
    assert_true(g->nsubs > 0);
    /* the records on cache lines, two each (rt_internal.h: the walk reads one or two) */
    assert_int_equal((uintptr_t)g->subs % RT_LINE, 0);
    assert_int_equal(sizeof *g->subs, 2 * RT_LINE);
    uint32_t at = 0;
    size_t cells = 0;
    for (size_t k = 0; k < g->nsubs; k++) {
        const rt_subgrid *sg = &g->subs[k];
        const size_t nc = (size_t)sg->b.n[0] * sg->b.n[1] * sg->b.n[2];
        assert_int_equal(sg->first, cells);
        assert_int_equal(sg->ref0, at);
        for (size_t c = 0; c < nc; c++) {
            const uint32_t a = rt_sub_off(g, k, c), e = rt_sub_off(g, k, c + 1);
            assert_int_equal(a, at);
            assert_true(e >= a);
            for (uint32_t r = a; r < e; r++)
                assert_true(g->srefs[r] < sc->nprim);
            at = e;
        }
        cells += nc;
    }
    assert_int_equal(cells, g->nsubcells);
    assert_int_equal(at, g->nsrefs);
}

/* 32 x 32 rays from an eye toward the middle of the cluster, in 8 x 8 blocks (one packet
   each). The window (0.6 wide at z = 5, the cluster's middle) keeps a block's footprint in
   the sub-grids small enough that about half the packets of test_wide are traced as
   packets (16 of 32, the shadow packets falling back), also with sub-grids 1.5 times finer;
   with a window 1.2 wide only 1 of 32 was, and a finer second level left none
   (docs/bench/rt_tuning.md, "A finer second level in non-flat sub-grids") */
#define SIDE 32
static void make_rays(rt_ray *rays, const double eye[3])
{
    size_t n = 0;
    for (int by = 0; by < SIDE; by += 8)
        for (int bx = 0; bx < SIDE; bx += 8)
            for (int j = 0; j < 8; j++)
                for (int i = 0; i < 8; i++) {
                    const double tx = 4.7 + 0.6 * (bx + i + 0.5) / SIDE,
                                 ty = 4.7 + 0.6 * (by + j + 0.5) / SIDE, tz = 5.0;
                    rt_ray *r = &rays[n++];
                    r->org[0] = eye[0];
                    r->org[1] = eye[1];
                    r->org[2] = eye[2];
                    r->dir[0] = tx - eye[0];
                    r->dir[1] = ty - eye[1];
                    r->dir[2] = tz - eye[2];
                    r->tmin = 0.0;
                    r->tmax = INFINITY;
                }
}

/* sc's answers against the brute-force scene's, bit for bit: the nearest hits of rays[0..nr-1]
   (hb, brute force) by single rays and by packets, and the occlusion of shadows[0..ns-1] (ob)
   by single rays and by packets; returns the packet paths' statistics */
static rt_packet_stats check_answers(rt_scene *sc, size_t nr, const rt_ray *rays,
                                     const rt_hit *hb, size_t ns, const rt_ray *shadows,
                                     const unsigned char *ob)
{
    rt_hit *hg = malloc(nr * sizeof *hg), *hp = malloc(nr * sizeof *hp);
    unsigned char *og = malloc(ns ? ns : 1), *op = malloc(ns ? ns : 1);
    assert_true(hg && hp && og && op);
    rt_packet_stats ps;
    memset(&ps, 0, sizeof ps);
    assert_int_equal(rt_intersect(sc, nr, rays, hg), RT_OK);
    assert_int_equal(rt_intersect_packet_stats(sc, nr, rays, hp, &ps), RT_OK);
    for (size_t k = 0; k < nr; k++) {
        if (!rtu_same_hit(&hb[k], &hg[k]))
            fail_msg("ray %zu: grid prim %d, brute force %d", k, hg[k].prim, hb[k].prim);
        if (!rtu_same_hit(&hg[k], &hp[k]))
            fail_msg("ray %zu: packet prim %d, single %d", k, hp[k].prim, hg[k].prim);
    }
    assert_int_equal(rt_occluded(sc, ns, shadows, og), RT_OK);
    assert_int_equal(rt_occluded_packet_stats(sc, ns, shadows, op, &ps), RT_OK);
    for (size_t k = 0; k < ns; k++) {
        assert_int_equal(og[k], ob[k]);
        assert_int_equal(op[k], ob[k]);
    }
    free(hg);
    free(hp);
    free(og);
    free(op);
    return ps;
}

/* n triangles of cluster_scene(n, half, coarse) with the grid of 1 and 2 threads: the
   offsets' layout (want_narrow: the 2-byte one), with coarse a widened top level (fewer than
   100 cells) whose references are primitive indices (srefs, no tables), the lists and the
   answers */
static void check_scene(int n, double half, int want_narrow, int coarse)
{
    rt_scene *br = cluster_scene(n, half, coarse);
    const rt_build_options bo = {.brute_force = 1};
    assert_int_equal(rt_scene_commit(br, &bo), RT_OK);
    const size_t nr = SIDE * SIDE;
    rt_ray *rays = malloc(nr * sizeof *rays), *sr = malloc(nr * sizeof *sr);
    rt_hit *hb = malloc(nr * sizeof *hb);
    unsigned char *ob = malloc(nr);
    assert_true(rays && sr && hb && ob);
    const double eye[3] = {5.3, 4.6, -3.0};
    make_rays(rays, eye);
    assert_int_equal(rt_intersect(br, nr, rays, hb), RT_OK);
    /* shadow rays from the hits toward a point light beside the eye */
    size_t ns = 0, hits = 0;
    for (size_t k = 0; k < nr; k++) {
        if (hb[k].prim < 0)
            continue;
        hits++;
        const double light[3] = {3.0, 7.0, -2.0}, sg = hb[k].side ? -1.0 : 1.0;
        rt_ray *r = &sr[ns++];
        for (int i = 0; i < 3; i++) {
            r->org[i] = hb[k].p[i] + sg * 1e-9 * hb[k].ng[i];
            r->dir[i] = light[i] - r->org[i];
        }
        r->tmin = 0.0;
        r->tmax = 1.0 - 1e-9;
    }
    printf("%zu of %zu rays hit, %zu shadow rays\n", hits, nr, ns);
    assert_true(hits > nr / 10); /* the rays meet the cluster */
    assert_int_equal(rt_occluded(br, ns, sr, ob), RT_OK);
    size_t occl = 0;
    for (size_t k = 0; k < ns; k++)
        occl += ob[k];
    assert_true(occl > 0 && occl < ns);
    for (int threads = 1; threads <= 2; threads++) {
        rt_scene *sc = cluster_scene(n, half, coarse);
        const rt_build_options o = {.brute_threshold = 0, .threads = threads};
        assert_int_equal(rt_scene_commit(sc, &o), RT_OK);
        assert_true(sc->use_grid);
        printf("%d triangles, %d thread(s): %zu top cells, %zu sub-grids, %zu sub cells, %zu "
               "references, %s offsets\n", n, threads, sc->grid.ncells, sc->grid.nsubs,
               sc->grid.nsubcells, sc->grid.nsrefs, sc->grid.soff16 ? "2-byte" : "4-byte");
        assert_int_equal(sc->grid.soff16 != NULL, want_narrow);
        assert_int_equal(sc->grid.soff != NULL, !want_narrow);
        if (coarse) {
            assert_true(sc->grid.ncells < 100);
            assert_true(sc->grid.srefs && !sc->grid.sref16 && !sc->grid.sloc);
        }
        check_lists(sc);
        const rt_packet_stats ps = check_answers(sc, nr, rays, hb, ns, sr, ob);
        assert_true(ps.packets > 0); /* the packet path itself walked the sub-grid */
        rt_scene_free(sc);
    }
    free(rays);
    free(sr);
    free(hb);
    free(ob);
    rt_scene_free(br);
}

static void test_narrow(void **state)
{
    (void)state;
    check_scene(1500, 0.08, 1, 0);
}

static void test_wide(void **state)
{
    (void)state;
    check_scene(20000, 0.06, 0, 0);
}

/* a widened top level (rt_build.c: rt_top_coarsen; larger triangles: 27 top cells) whose one
   sub-grid has more than 65535 references: its build made 2-byte-able table indices
   (rt_sub_csr), which become primitive indices again with the 4-byte offsets (rt_sub_local) */
static void test_wide_coarse(void **state)
{
    (void)state;
    check_scene(20000, 0.3, 0, 1);
}

/* n random triangles in the unit cube, each within a cube of side 2 n^(-1/3) around its
   centre (the build benchmark's), large against the default rule's top cells, as separate
   triangles or as one mesh of 3 n unshared vertices */
static rt_scene *big_scene(int n, int mesh)
{
    int surf;
    rt_scene *sc = rtu_scene_one_surface(&surf);
    assert_non_null(sc);
    double *v = malloc((size_t)n * 9 * sizeof *v);
    uint32_t *ix = malloc((size_t)n * 3 * sizeof *ix);
    assert_true(v && ix);
    uint64_t st = 99;
    const double side = 2.0 * pow((double)n, -1.0 / 3.0);
    const int three = 3;
    for (int t = 0; t < n; t++) {
        double c[3];
        for (int i = 0; i < 3; i++)
            c[i] = rtu_rand(&st);
        for (int j = 0; j < 9; j++)
            v[9 * t + j] = c[j % 3] + side * (rtu_rand(&st) - 0.5);
        for (int k = 0; k < 3; k++)
            ix[3 * t + k] = (uint32_t)(3 * t + k);
        if (!mesh)
            assert_true(rt_scene_add_polygon(sc, 1, &three, v + 9 * t, surf, surf) >= 0);
    }
    if (mesh)
        assert_true(rt_scene_add_mesh(sc, 3 * (size_t)n, v, NULL, NULL, (size_t)n, ix, surf,
                                      surf) >= 0);
    free(v);
    free(ix);
    return sc;
}

/* A widened top level's sub-grids (rt_build.c: rt_top_coarsen, rt_sub_local) hold 2-byte
   references into a table of each sub-grid's primitives: the layout is chosen (srefs gone),
   each table names distinct primitives, every reference is inside its table, the grid's
   bytes count 2 per reference; rays from inside the cloud in all directions get the
   brute-force scene's hits and occlusion bit for bit, single rays and packets, as separate
   triangles (the general lists) and as one mesh (the mesh lists), on 1 and 2 threads. */
static void test_local(void **state)
{
    (void)state;
    enum { N = 3000, NR = 1024 };
    rt_ray *rays = malloc(NR * sizeof *rays);
    rt_hit *hb = malloc(NR * sizeof *hb);
    unsigned char *ob = malloc(NR);
    assert_true(rays && hb && ob);
    uint64_t st = 7;
    for (int k = 0; k < NR; k++) { /* 8 x 8 blocks of rays from one point each */
        rt_ray *r = &rays[k];
        if (k % 64 == 0)
            for (int i = 0; i < 3; i++)
                r->org[i] = 0.2 + 0.6 * rtu_rand(&st);
        else
            memcpy(r->org, rays[k - 1].org, sizeof r->org);
        for (int i = 0; i < 3; i++)
            r->dir[i] = 2.0 * rtu_rand(&st) - 1.0;
        r->tmin = 0.0;
        r->tmax = k % 2 ? INFINITY : 0.05;
    }
    for (int mesh = 0; mesh <= 1; mesh++) {
        rt_scene *br = big_scene(N, mesh);
        const rt_build_options bo = {.brute_force = 1};
        assert_int_equal(rt_scene_commit(br, &bo), RT_OK);
        assert_int_equal(rt_intersect(br, NR, rays, hb), RT_OK);
        assert_int_equal(rt_occluded(br, NR, rays, ob), RT_OK);
        size_t hits = 0;
        for (int k = 0; k < NR; k++)
            hits += hb[k].prim >= 0;
        assert_true(hits > NR / 4 && hits < NR);
        for (int threads = 1; threads <= 2; threads++) {
            rt_scene *sc = big_scene(N, mesh);
            const rt_build_options o = {.brute_threshold = 0, .threads = threads};
            assert_int_equal(rt_scene_commit(sc, &o), RT_OK);
            const rt_grid *g = &sc->grid;
            assert_true(sc->use_grid && g->ncells < 100 && g->nsubs > 0);
            /* float leaves (GKS_RT_LEAF_MIN, the _leaves runs) read srefs: kept then */
            const int local = g->tleaf == NULL;
            assert_int_equal(g->sref16 != NULL, local);
            assert_int_equal(g->srefs == NULL, local);
            assert_non_null(g->soff16);
            unsigned char *seen = calloc(sc->nprim, 1);
            assert_non_null(seen);
            size_t at = 0;
            for (size_t k = 0; local && k < g->nsubs; k++) {
                const rt_subgrid *sg = &g->subs[k];
                const size_t nc = (size_t)sg->b.n[0] * sg->b.n[1] * sg->b.n[2];
                const uint32_t l1 = k + 1 < g->nsubs ? g->subs[k + 1].loc0 : (uint32_t)g->nsloc;
                assert_int_equal(sg->loc0, at);
                assert_true(l1 > sg->loc0);
                for (uint32_t q = sg->loc0; q < l1; q++) {
                    assert_true(g->sloc[q] < sc->nprim);
                    assert_false(seen[g->sloc[q]]);
                    seen[g->sloc[q]] = 1;
                }
                for (uint32_t r = 0; r < rt_sub_off(g, k, nc) - sg->ref0; r++)
                    assert_true(g->sref16[sg->ref0 + r] < l1 - sg->loc0);
                for (uint32_t q = sg->loc0; q < l1; q++)
                    seen[g->sloc[q]] = 0;
                at = l1;
            }
            free(seen);
            assert_true(!local || sc->grid_bytes < g->nsrefs * sizeof(uint32_t));
            printf("%s, %d thread(s): %zu sub-grids, %zu references, %zu in tables, %.1f grid "
                   "B/tri\n", mesh ? "mesh" : "triangles", threads, g->nsubs, g->nsrefs,
                   g->nsloc, (double)sc->grid_bytes / N);
            check_answers(sc, NR, rays, hb, NR, rays, ob);
            rt_scene_free(sc);
        }
        rt_scene_free(br);
    }
    free(rays);
    free(hb);
    free(ob);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_narrow),
        cmocka_unit_test(test_wide),
        cmocka_unit_test(test_wide_coarse),
        cmocka_unit_test(test_local),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
