/* SPDX-License-Identifier: MIT */
/*
 * test_rt_isect.c -- ray/primitive intersection and the grid: watertightness (closed mesh,
 * shared diagonals at growing offsets), grid == brute force bit for bit (walls exactly on cell
 * boundaries, +0.0/-0.0 direction components), even-odd rule, degenerate and NaN/Inf input.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gksrt.h"
#include "rt_check.h"
#include "rt_testutil.h"

static uint64_t rng_state = 12345;
static double rnd(void) /* deterministic uniform [0,1) */
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(rng_state >> 11) * 0x1.0p-53;
}

static int add_surface(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    return rt_scene_add_surface(sc, &s);
}

static void ray_set(rt_ray *r, double ox, double oy, double oz, double dx, double dy, double dz)
{
    r->org[0] = ox; r->org[1] = oy; r->org[2] = oz;
    r->dir[0] = dx; r->dir[1] = dy; r->dir[2] = dz;
    r->tmin = 0.0;
    r->tmax = INFINITY;
}

/* ---- watertightness on a closed mesh ---- */

static void test_watertight_mesh(void **state)
{
    (void)state;
    rtu_mesh m;
    assert_int_equal(rtu_load_off(RT_DATA_DIR "/meshes/fandisk_large.off.gz", &m), 0);
    rt_scene *sc = rt_scene_new();
    int s = add_surface(sc);
    assert_int_equal(rtu_mesh_add(&m, sc, s), 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtc_traps_on();
    /* an inside point: just behind the centroid of a face, confirmed by odd crossing parity */
    double in[3] = {0, 0, 0};
    int found = 0;
    for (int f = 0; f < m.np && !found; f += 97) {
        const int *ix = m.idx + 3 * f;
        double c[3], e1[3], e2[3], n[3];
        for (int i = 0; i < 3; i++) {
            c[i] = (m.xyz[3 * ix[0] + i] + m.xyz[3 * ix[1] + i] + m.xyz[3 * ix[2] + i]) / 3;
            e1[i] = m.xyz[3 * ix[1] + i] - m.xyz[3 * ix[0] + i];
            e2[i] = m.xyz[3 * ix[2] + i] - m.xyz[3 * ix[0] + i];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int sgn = -1; sgn <= 1 && !found; sgn += 2) {
            double p[3];
            for (int i = 0; i < 3; i++)
                p[i] = c[i] + sgn * 1e-3 * n[i] / l;
            /* parity along a skew direction: count hits by stepping tmin */
            rt_ray r;
            ray_set(&r, p[0], p[1], p[2], 0.31, 0.77, 0.55);
            int cnt = 0;
            rt_hit h;
            for (;;) {
                rt_intersect(sc, 1, &r, &h);
                if (h.prim < 0)
                    break;
                cnt++;
                r.tmin = h.t * (1 + 1e-12) + 1e-12;
            }
            if (cnt % 2 == 1) {
                memcpy(in, p, sizeof in);
                found = 1;
            }
        }
    }
    assert_true(found);
    /* rays to every vertex, every edge midpoint, and 1e5 random directions */
    size_t nr = (size_t)m.nv + 3 * (size_t)m.np + 100000, k = 0;
    rt_ray *rays = malloc(nr * sizeof *rays);
    rt_hit *hits = malloc(nr * sizeof *hits);
    assert_non_null(rays);
    assert_non_null(hits);
    for (int v = 0; v < m.nv; v++, k++)
        ray_set(&rays[k], in[0], in[1], in[2], m.xyz[3 * v] - in[0], m.xyz[3 * v + 1] - in[1],
                m.xyz[3 * v + 2] - in[2]);
    for (int f = 0; f < m.np; f++)
        for (int e = 0; e < 3; e++, k++) {
            const double *a = m.xyz + 3 * m.idx[3 * f + e], *b = m.xyz + 3 * m.idx[3 * f + (e + 1) % 3];
            ray_set(&rays[k], in[0], in[1], in[2], 0.5 * (a[0] + b[0]) - in[0], 0.5 * (a[1] + b[1]) - in[1],
                    0.5 * (a[2] + b[2]) - in[2]);
        }
    for (; k < nr; k++) {
        double d[3];
        do {
            for (int i = 0; i < 3; i++)
                d[i] = 2 * rnd() - 1;
        } while (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > 1.0 || d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1e-6);
        ray_set(&rays[k], in[0], in[1], in[2], d[0], d[1], d[2]);
    }
    assert_int_equal(rt_intersect(sc, nr, rays, hits), RT_OK);
    size_t misses = 0;
    for (k = 0; k < nr; k++)
        misses += hits[k].prim < 0;
    assert_int_equal(misses, 0);
    /* the same rays against the brute-force scene give identical answers (a sample) */
    rt_scene *bf = rt_scene_new();
    s = add_surface(bf);
    rtu_mesh_add(&m, bf, s);
    rt_build_options bo = {.brute_force = 1};
    assert_int_equal(rt_scene_commit(bf, &bo), RT_OK);
    rt_hit hb[200];
    assert_int_equal(rt_intersect(bf, 200, rays + nr - 200, hb), RT_OK);
    for (int i = 0; i < 200; i++) {
        assert_int_equal(hb[i].prim, hits[nr - 200 + i].prim);
        assert_true(hb[i].t == hits[nr - 200 + i].t);
    }
    rtc_traps_off();
    free(rays);
    free(hits);
    rt_scene_free(sc);
    rt_scene_free(bf);
    rtu_mesh_free(&m);
}

/* two triangles (and two quads, two concave polygons) sharing an edge; rays exactly through
   points of the shared edge, geometry offset by 0, 1e3, 1e6 */
static void test_shared_diagonal(void **state)
{
    (void)state;
    rtc_traps_on();
    const double offs[3] = {0.0, 1e3, 1e6};
    for (int oi = 0; oi < 3; oi++) {
        double o = offs[oi];
        for (int kind = 0; kind < 3; kind++) {
            rt_scene *sc = rt_scene_new();
            int s = add_surface(sc);
            if (kind == 0) { /* square split along the diagonal (0,0)-(1,1) */
                double t1[9] = {o, o, o, o + 1, o, o, o + 1, o + 1, o};
                double t2[9] = {o, o, o, o + 1, o + 1, o, o, o + 1, o};
                int n = 3;
                assert_true(rt_scene_add_polygon(sc, 1, &n, t1, s, s) >= 0);
                assert_true(rt_scene_add_polygon(sc, 1, &n, t2, s, s) >= 0);
            } else if (kind == 1) { /* two convex quads sharing the diagonal */
                double q1[12] = {o, o, o, o + 1, o, o, o + 1.5, o + 0.5, o, o + 1, o + 1, o};
                double q2[12] = {o, o, o, o + 1, o + 1, o, o + 0.5, o + 1.5, o, o - 0.2, o + 0.6, o};
                int n = 4;
                assert_true(rt_scene_add_polygon(sc, 1, &n, q1, s, s) >= 0);
                assert_true(rt_scene_add_polygon(sc, 1, &n, q2, s, s) >= 0);
            } else { /* two concave pentagons sharing the diagonal */
                double p1[15] = {o, o, o, o + 1, o, o, o + 0.8, o + 0.4, o, o + 1.2, o + 0.6, o, o + 1, o + 1, o};
                double p2[15] = {o, o, o, o + 1, o + 1, o, o + 0.4, o + 0.8, o, o + 0.6, o + 1.2, o, o - 0.3, o + 0.5, o};
                int n = 5;
                assert_true(rt_scene_add_polygon(sc, 1, &n, p1, s, s) >= 0);
                assert_true(rt_scene_add_polygon(sc, 1, &n, p2, s, s) >= 0);
            }
            assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
            int miss = 0;
            for (int k = 1; k < 64; k++) {
                double x = o + k / 64.0;
                rt_ray r[3];
                ray_set(&r[0], x, x, o + 1, 0, 0, -1);                  /* perpendicular */
                ray_set(&r[1], x - 0.25, x - 0.25, o + 1, 0.25, 0.25, -1); /* in the diagonal's plane */
                ray_set(&r[2], x + 0.3, x - 0.1, o + 2, -0.15, 0.05, -1);
                rt_hit h[3];
                assert_int_equal(rt_intersect(sc, 3, r, h), RT_OK);
                for (int j = 0; j < 3; j++)
                    miss += h[j].prim < 0;
            }
            assert_int_equal(miss, 0);
            rt_scene_free(sc);
        }
    }
    rtc_traps_off();
}

/* ---- grid == brute force ---- */

static void build_test_scene(rt_scene *sc)
{
    int s = add_surface(sc);
    int n3 = 3, n4 = 4;
    /* walls exactly on the cell boundaries of a 4x4x4 grid over [0,1]^3 */
    for (int k = 1; k < 4; k++) {
        double c = 0.25 * k;
        double wx[12] = {c, 0.1, 0.1, c, 0.9, 0.1, c, 0.9, 0.9, c, 0.1, 0.9};
        double wy[12] = {0.1, c, 0.1, 0.1, c, 0.9, 0.9, c, 0.9, 0.9, c, 0.1};
        double wz[12] = {0.1, 0.1, c, 0.9, 0.1, c, 0.9, 0.9, c, 0.1, 0.9, c};
        /* holes: the walls are small patches so rays pass between them */
        for (int i = 0; i < 12; i++) {
            wx[i] = i % 3 == 0 ? wx[i] : 0.5 * wx[i] + (k & 1) * 0.2;
            wy[i] = i % 3 == 1 ? wy[i] : 0.5 * wy[i] + 0.25;
            wz[i] = i % 3 == 2 ? wz[i] : 0.5 * wz[i] + (k >> 1) * 0.3;
        }
        rt_scene_add_polygon(sc, 1, &n4, wx, s, s);
        rt_scene_add_polygon(sc, 1, &n4, wy, s, s);
        rt_scene_add_polygon(sc, 1, &n4, wz, s, s);
    }
    /* a wall covering a whole boundary plane and the box faces */
    double full[12] = {0.5, 0, 0, 0.5, 1, 0, 0.5, 1, 1, 0.5, 0, 1};
    double floor_[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    rt_scene_add_polygon(sc, 1, &n4, full, s, s);
    rt_scene_add_polygon(sc, 1, &n4, floor_, s, s);
    /* random triangles */
    for (int i = 0; i < 300; i++) {
        double v[9], c[3] = {rnd(), rnd(), rnd()};
        for (int j = 0; j < 9; j++)
            v[j] = c[j % 3] + 0.15 * (rnd() - 0.5);
        for (int j = 0; j < 9; j++)
            v[j] = fmin(1.0, fmax(0.0, v[j]));
        rt_scene_add_polygon(sc, 1, &n3, v, s, s);
    }
    /* concave polygon with a hole (fill area set), a star, a cell array */
    int cnt[2] = {6, 4};
    double fas[30] = {0.1, 0.1, 0.6, 0.9, 0.1, 0.6, 0.9, 0.9, 0.6, 0.5, 0.5, 0.6, 0.5, 0.7, 0.6, 0.1, 0.9, 0.6,
                      0.2, 0.2, 0.6, 0.4, 0.2, 0.6, 0.4, 0.4, 0.6, 0.2, 0.4, 0.6};
    rt_scene_add_polygon(sc, 2, cnt, fas, s, s);
    double star[15];
    for (int k = 0; k < 5; k++) {
        double a = 2 * M_PI * (2 * k) / 5;
        star[3 * k] = 0.5 + 0.4 * cos(a);
        star[3 * k + 1] = 0.3;
        star[3 * k + 2] = 0.5 + 0.4 * sin(a);
    }
    int n5 = 5;
    rt_scene_add_polygon(sc, 1, &n5, star, s, s);
    double P[3] = {0.05, 0.95, 0.05}, Q[3] = {0.95, 0.75, 0.95}, R[3] = {0.95, 0.95, 0.05};
    float rgb[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    rt_scene_add_cell_array(sc, P, Q, R, 2, 2, rgb, s, s);
}

static void test_grid_equals_brute(void **state)
{
    (void)state;
    rt_scene *g = rt_scene_new(), *b = rt_scene_new(), *g2 = rt_scene_new(), *g3 = rt_scene_new();
    rng_state = 99;
    build_test_scene(g);
    rng_state = 99;
    build_test_scene(b);
    rng_state = 99;
    build_test_scene(g2);
    rng_state = 99;
    build_test_scene(g3);
    rt_build_options og = {.brute_threshold = 0, .grid_res = {4, 4, 4}, .grid_box = {0, 0, 0, 1, 1, 1}};
    rt_build_options ob = {.brute_force = 1};
    /* a fine grid without, a coarse one with a second level in every occupied cell */
    rt_build_options og2 = {.brute_threshold = 0, .grid_factor = 20.0, .no_subgrids = 1};
    rt_build_options og3 = {.brute_threshold = 0, .grid_factor = 0.05, .sub_min = 1, .sub_factor = 8};
    assert_int_equal(rt_scene_commit(g, &og), RT_OK);
    assert_int_equal(rt_scene_commit(b, &ob), RT_OK);
    assert_int_equal(rt_scene_commit(g2, &og2), RT_OK);
    assert_int_equal(rt_scene_commit(g3, &og3), RT_OK);
    rtc_traps_on();
    enum { N = 20000 };
    rt_ray *rays = malloc(N * sizeof *rays);
    rt_hit *h1 = malloc(N * sizeof *h1), *h2 = malloc(N * sizeof *h2), *h3 = malloc(N * sizeof *h3);
    rt_hit *h4 = malloc(N * sizeof *h4);
    rng_state = 7;
    for (int k = 0; k < N; k++) {
        double o[3], d[3];
        for (int i = 0; i < 3; i++) {
            o[i] = 1.4 * rnd() - 0.2;
            d[i] = 2 * rnd() - 1;
        }
        if (k % 4 == 1) { /* axis-aligned with +0.0 / -0.0 components, on cell boundaries */
            int a = k % 3;
            for (int i = 0; i < 3; i++)
                d[i] = (k / 8) % 2 ? -0.0 : 0.0;
            d[a] = (k / 16) % 2 ? -1.0 : 1.0;
            for (int i = 0; i < 3; i++)
                if (i != a && (k / 32) % 2)
                    o[i] = 0.25 * (double)((k / 64) % 5);
        }
        if (k % 4 == 2) /* one zero component */
            d[k % 3] = (k / 4) % 2 ? -0.0 : 0.0;
        ray_set(&rays[k], o[0], o[1], o[2], d[0], d[1], d[2]);
        if (k % 5 == 3)
            rays[k].tmax = 0.5;
    }
    assert_int_equal(rt_intersect(g, N, rays, h1), RT_OK);
    assert_int_equal(rt_intersect(b, N, rays, h2), RT_OK);
    assert_int_equal(rt_intersect(g2, N, rays, h3), RT_OK);
    assert_int_equal(rt_intersect(g3, N, rays, h4), RT_OK);
    int nhit = 0;
    for (int k = 0; k < N; k++) {
        nhit += h2[k].prim >= 0;
        assert_int_equal(h1[k].prim, h2[k].prim);
        assert_int_equal(h3[k].prim, h2[k].prim);
        assert_int_equal(h4[k].prim, h2[k].prim);
        if (h2[k].prim < 0)
            continue;
        assert_memory_equal(&h1[k].t, &h2[k].t, sizeof(double));
        assert_memory_equal(&h3[k].t, &h2[k].t, sizeof(double));
        assert_memory_equal(&h4[k].t, &h2[k].t, sizeof(double));
        assert_memory_equal(h1[k].p, h2[k].p, sizeof h1[k].p);
        assert_int_equal(h1[k].side, h2[k].side);
    }
    assert_true(nhit > N / 4); /* the comparison is not vacuous */
    /* occlusion agrees too */
    unsigned char o1[64], o2[64], o3[64];
    assert_int_equal(rt_occluded(g, 64, rays, o1), RT_OK);
    assert_int_equal(rt_occluded(b, 64, rays, o2), RT_OK);
    assert_int_equal(rt_occluded(g3, 64, rays, o3), RT_OK);
    assert_memory_equal(o1, o2, 64);
    assert_memory_equal(o3, o2, 64);
    for (int k = 0; k < 64; k++)
        assert_int_equal(o1[k], h2[k].prim >= 0);
    rtc_traps_off();
    /* g3 really has a second level: more cells than the same top grid alone */
    rt_scene *g4 = rt_scene_new();
    rng_state = 99;
    build_test_scene(g4);
    rt_build_options og4 = og3;
    og4.no_subgrids = 1;
    assert_int_equal(rt_scene_commit(g4, &og4), RT_OK);
    double id[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, box[6] = {0, 1, 0, 1, 0, 1};
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, id, box, 2, 2), RT_OK);
    float px[12];
    rt_stats s3, s4;
    assert_int_equal(rt_render(g3, &cam, NULL, px, &s3), RT_OK);
    assert_int_equal(rt_render(g4, &cam, NULL, px, &s4), RT_OK);
    assert_true(s3.grid_cells > 8 * s4.grid_cells);
    rt_scene_free(g4);
    free(rays);
    free(h1);
    free(h2);
    free(h3);
    free(h4);
    rt_scene_free(g3);
    rt_scene_free(g);
    rt_scene_free(b);
    rt_scene_free(g2);
}

/* ---- even-odd rule ---- */

static int hit_at(const rt_scene *sc, double x, double y)
{
    rt_ray r;
    ray_set(&r, x, y, 1, 0, 0, -1);
    rt_hit h;
    rt_intersect(sc, 1, &r, &h);
    return h.prim;
}

static void test_even_odd(void **state)
{
    (void)state;
    rtc_traps_on();
    rt_scene *sc = rt_scene_new();
    int s = add_surface(sc);
    int cnt[2] = {4, 4};
    double ring[24] = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 1, 1, 0, 3, 1, 0, 3, 3, 0, 1, 3, 0};
    int id_ring = rt_scene_add_polygon(sc, 2, cnt, ring, s, s);
    double star[15];
    for (int k = 0; k < 5; k++) { /* pentagram centred at (10, 2): centre is outside (even-odd) */
        double a = M_PI / 2 + 2 * M_PI * (2 * k) / 5;
        star[3 * k] = 10 + 2 * cos(a);
        star[3 * k + 1] = 2 + 2 * sin(a);
        star[3 * k + 2] = 0;
    }
    int n5 = 5, n4 = 4, n6 = 6;
    int id_star = rt_scene_add_polygon(sc, 1, &n5, star, s, s);
    double bow[12] = {20, 0, 0, 24, 4, 0, 24, 0, 0, 20, 4, 0}; /* bow tie: Newell normal 0 */
    int id_bow = rt_scene_add_polygon(sc, 1, &n4, bow, s, s);
    /* repeated and collinear vertices */
    double rep[18] = {30, 0, 0, 30, 0, 0, 32, 0, 0, 34, 0, 0, 34, 4, 0, 30, 4, 0};
    int id_rep = rt_scene_add_polygon(sc, 1, &n6, rep, s, s);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_int_equal(hit_at(sc, 0.5, 0.5), id_ring);
    assert_int_equal(hit_at(sc, 3.5, 2.0), id_ring);
    assert_int_equal(hit_at(sc, 2.0, 2.0), -1); /* in the hole */
    assert_int_equal(hit_at(sc, 5.0, 2.0), -1);
    assert_int_equal(hit_at(sc, 10.0, 2.0), -1); /* star centre: winding 2 */
    assert_int_equal(hit_at(sc, 10.0, 3.7), id_star); /* top tip */
    assert_int_equal(hit_at(sc, 21.0, 2.0), id_bow);
    assert_int_equal(hit_at(sc, 23.0, 2.0), id_bow);
    assert_int_equal(hit_at(sc, 22.0, 0.5), -1);
    assert_int_equal(hit_at(sc, 22.0, 3.5), -1);
    assert_int_equal(hit_at(sc, 31.0, 1.0), id_rep);
    assert_int_equal(hit_at(sc, 33.9, 3.9), id_rep);
    rtc_traps_off();
    rt_scene_free(sc);
}

/* ---- huge polygons: a 100000-gon circle and a 20000-spike star (long edges) ---- */
static void test_big_polygons(void **state)
{
    (void)state;
    enum { NC = 100000, NS = 20000 };
    double *c = malloc(3 * NC * sizeof(double)), *s = malloc(3 * 2 * NS * sizeof(double));
    assert_non_null(c);
    assert_non_null(s);
    for (int k = 0; k < NC; k++) {
        double a = 2 * M_PI * k / NC;
        c[3 * k] = cos(a);
        c[3 * k + 1] = sin(a);
        c[3 * k + 2] = 0;
    }
    for (int k = 0; k < 2 * NS; k++) { /* spikes between radius 0.01 and 1 around (5, 0) */
        double a = 2 * M_PI * k / (2 * NS), r = k % 2 ? 1.0 : 0.01;
        s[3 * k] = 5 + r * cos(a);
        s[3 * k + 1] = r * sin(a);
        s[3 * k + 2] = 0;
    }
    rt_scene *sc = rt_scene_new();
    int sid = add_surface(sc), nc = NC, ns = 2 * NS;
    int idc = rt_scene_add_polygon(sc, 1, &nc, c, sid, sid);
    int ids = rt_scene_add_polygon(sc, 1, &ns, s, sid, sid);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtc_traps_on();
    assert_int_equal(hit_at(sc, 0.0, 0.0), idc);
    assert_int_equal(hit_at(sc, 0.7, 0.7), idc);
    assert_int_equal(hit_at(sc, 0.72, 0.72), -1);
    assert_int_equal(hit_at(sc, 5.0, 0.0), ids);  /* inner disc of the star */
    assert_int_equal(hit_at(sc, 5.0, 1.01), -1);
    rtc_traps_off();
    double id[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}, box[6] = {0, 1, 0, 1, 0, 1};
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, id, box, 1, 1), RT_OK);
    float px[3];
    rt_stats st;
    assert_int_equal(rt_render(sc, &cam, NULL, px, &st), RT_OK);
    assert_true(st.memory_bytes < 64u * 1024 * 1024); /* edge lists stay bounded */
    rt_scene_free(sc);
    free(c);
    free(s);
}

/* ---- degenerate, NaN/Inf geometry and rays ---- */

static void test_bad_input(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    int s = add_surface(sc);
    int n3 = 3, n4 = 4, zero = 0, neg = -2;
    double good[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    double nanv[9] = {0, 0, 0, NAN, 0, 0, 0, 1, 0};
    double infv[9] = {0, 0, 0, INFINITY, 0, 0, 0, 1, 0};
    double huge[9] = {0, 0, 0, 1e300, 0, 0, 0, 1, 0};
    double line[12] = {0, 0, 0, 1, 1, 0, 2, 2, 0, 3, 3, 0};
    double point[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
    assert_int_equal(rt_scene_add_polygon(sc, 1, &zero, good, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_polygon(sc, 1, &neg, good, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_polygon(sc, 0, &n3, good, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_polygon(sc, 1, &n3, good, s, 7), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_polygon(sc, 1, &n3, NULL, s, s), RT_ERR_ARG);
    int ids[6];
    ids[0] = rt_scene_add_polygon(sc, 1, &n3, nanv, s, s);
    ids[1] = rt_scene_add_polygon(sc, 1, &n3, infv, s, s);
    ids[2] = rt_scene_add_polygon(sc, 1, &n3, huge, s, s);
    ids[3] = rt_scene_add_polygon(sc, 1, &n4, line, s, s);
    ids[4] = rt_scene_add_polygon(sc, 1, &n3, point, s, s);
    ids[5] = rt_scene_add_polygon(sc, 1, &n3, good, s, s);
    for (int i = 0; i < 6; i++)
        assert_true(ids[i] >= 0);
    float badrgb[3] = {NAN, 0, 0};
    double P[3] = {0, 0, 0}, Q[3] = {1, 1, 0}, R[3] = {1, 0, 0}, Rd[3] = {2, 2, 0};
    assert_int_equal(rt_scene_add_cell_array(sc, P, Q, R, 1, 1, badrgb, s, s), RT_ERR_ARG);
    float rgb[3] = {1, 0, 0};
    assert_int_equal(rt_scene_add_cell_array(sc, P, Q, R, 0, 1, rgb, s, s), RT_ERR_ARG);
    assert_true(rt_scene_add_cell_array(sc, P, Q, Rd, 1, 1, rgb, s, s) >= 0); /* collinear: dropped */
    rt_surface bs;
    rt_surface_default(&bs);
    bs.kd = NAN;
    assert_int_equal(rt_scene_add_surface(sc, &bs), RT_ERR_ARG);
    rt_surface_default(&bs);
    bs.transparency = 1.5;
    assert_int_equal(rt_scene_add_surface(sc, &bs), RT_ERR_ARG);
    rt_surface_default(&bs);
    bs.refr_index = 0;
    assert_int_equal(rt_scene_add_surface(sc, &bs), RT_ERR_ARG);
    rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {0, 0, 0}};
    assert_int_equal(rt_scene_add_light(sc, &l), RT_ERR_ARG);
    l.direction[2] = -INFINITY;
    assert_int_equal(rt_scene_add_light(sc, &l), RT_ERR_ARG);
    l.type = RT_LIGHT_POSITIONAL;
    l.c1 = l.c2 = 0;
    assert_int_equal(rt_scene_add_light(sc, &l), RT_ERR_ARG);
    rt_ray r;
    rt_hit h;
    ray_set(&r, 0.2, 0.2, 1, 0, 0, -1);
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_ERR_STATE);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
    assert_int_equal(h.prim, ids[5]); /* only the good triangle survived */
    assert_true(h.t == 1.0);
    /* rays along the degenerate ones miss */
    ray_set(&r, 1.5, 1.5, 1, 0, 0, -1);
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    ray_set(&r, 2.0, 0.5, 1, 0, 0, -1); /* inside the Inf / huge triangles only */
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    rtc_traps_off();
    /* slivers: twice the area 2e-11 and 5e-12 of the extent squared (the add-time shortcut
       decides the first, the Newell normal the second: both above its tolerance 1e-12), at
       the origin and at 1e6; kept. Collinear ones: dropped. */
    rt_scene *sv = rt_scene_new();
    const int ss = add_surface(sv);
    const double hs[2] = {2e-11, 5e-12}, offs[2] = {0.0, 1e6};
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) {
            const double o = offs[b], e = b ? 1e4 : 1.0; /* (at 1e6 an extent of 1e4) */
            double tri[9] = {o, o, o, o + e, o, o, o + 0.5 * e, o + hs[a] * e, o};
            assert_true(rt_scene_add_polygon(sv, 1, &n3, tri, ss, ss) >= 0);
            double col[9] = {o, o, o, o + 1, o + 2, o + 3, o + 2, o + 4, o + 6};
            assert_true(rt_scene_add_polygon(sv, 1, &n3, col, ss, ss) >= 0);
        }
    assert_int_equal(rt_scene_commit(sv, NULL), RT_OK);
    rt_grid_info svi;
    assert_int_equal(rt_scene_grid_info(sv, &svi), RT_OK);
    assert_int_equal(svi.prims, 4);
    rt_scene_free(sv);
    rtc_traps_on();
    /* NaN / Inf / zero rays: misses, no traps */
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 6; c++) {
            ray_set(&r, 0.2, 0.2, 1, 0, 0, -1);
            if (c < 3)
                r.org[c] = bad[i];
            else
                r.dir[c - 3] = bad[i];
            assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
            assert_int_equal(h.prim, -1);
            unsigned char oc = 9;
            assert_int_equal(rt_occluded(sc, 1, &r, &oc), RT_OK);
            assert_int_equal(oc, 0);
        }
    ray_set(&r, 0.2, 0.2, 1, 0, 0, 0);
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    ray_set(&r, 0.2, 0.2, 1, 0, -0.0, -1e-320); /* denormal direction */
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    ray_set(&r, 0.2, 0.2, 1, 0, 0, -1);
    r.tmax = NAN;
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    r.tmax = 0.5; /* range ends before the triangle */
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    rtc_traps_off();
    assert_int_equal(rt_intersect(NULL, 1, &r, &h), RT_ERR_ARG);
    rt_scene_free(sc);
    /* empty scene */
    sc = rt_scene_new();
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_intersect(sc, 1, &r, &h);
    assert_int_equal(h.prim, -1);
    rt_scene_free(sc);
    rt_scene_free(NULL);
}

/* The commit on several threads (rt_build_options.threads) gives the scene of one thread:
 * the same grid statistics and, bit for bit, the same hits. 30000 small random triangles (so
 * the build splits into parts), a large quad and polygon crossing many cells, and a few
 * degenerate triangles (dropped at commit: the serial gap-closing pass). */
static void test_threads_same_scene(void **state)
{
    (void)state;
    enum { NT = 30000, NR = 20000, NS = 3 };
    rt_scene *sc[NS];
    rt_grid_info gi[NS];
    rt_hit *h[NS];
    const int threads[NS] = {1, 2, 3};
    rt_ray *rays = malloc(NR * sizeof *rays);
    assert_non_null(rays);
    for (int s = 0; s < NS; s++) {
        sc[s] = rt_scene_new();
        assert_non_null(sc[s]);
        rt_surface su;
        rt_surface_default(&su);
        int sid = rt_scene_add_surface(sc[s], &su);
        assert_true(sid >= 0);
        rng_state = 4242;
        const int three = 3, four = 4;
        for (int t = 0; t < NT; t++) {
            double c[3] = {rnd(), rnd(), rnd()}, v[9];
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < 3; i++)
                    v[3 * k + i] = t % 1000 == 7 ? c[i] : c[i] + 0.04 * (rnd() - 0.5);
            assert_true(rt_scene_add_polygon(sc[s], 1, &three, v, sid, sid) >= 0 || t % 1000 == 7);
        }
        const double quad[12] = {-0.1, -0.1, 0.5, 1.1, -0.1, 0.45, 1.1, 1.1, 0.45, -0.1, 1.1, 0.5};
        const double poly[15] = {0.5, -0.1, -0.1, 0.55, 1.1, -0.1, 0.5, 1.2, 0.6, 0.45, 0.6, 1.1,
                                 0.5, -0.1, 1.1};
        const int five = 5;
        assert_true(rt_scene_add_polygon(sc[s], 1, &four, quad, sid, sid) >= 0);
        assert_true(rt_scene_add_polygon(sc[s], 1, &five, poly, sid, sid) >= 0);
        rt_build_options o = {.brute_threshold = -1, .threads = threads[s]};
        assert_int_equal(rt_scene_commit(sc[s], &o), RT_OK);
        assert_int_equal(rt_scene_grid_info(sc[s], &gi[s]), RT_OK);
        h[s] = malloc(NR * sizeof *h[s]);
        assert_non_null(h[s]);
    }
    rng_state = 77;
    for (int k = 0; k < NR; k++) {
        double o[3], d[3];
        for (int i = 0; i < 3; i++) {
            o[i] = 1.4 * rnd() - 0.2;
            d[i] = 2 * rnd() - 1;
        }
        ray_set(&rays[k], o[0], o[1], o[2], d[0], d[1], d[2]);
    }
    int nhit = 0;
    for (int s = 0; s < NS; s++)
        assert_int_equal(rt_intersect(sc[s], NR, rays, h[s]), RT_OK);
    for (int s = 1; s < NS; s++) {
        assert_true(gi[s].prims == gi[0].prims && gi[s].cells == gi[0].cells &&
                    gi[s].refs == gi[0].refs && gi[s].subgrids == gi[0].subgrids &&
                    gi[s].subcells == gi[0].subcells && gi[s].subrefs == gi[0].subrefs &&
                    gi[s].empty_cells == gi[0].empty_cells &&
                    gi[s].max_leaf_refs == gi[0].max_leaf_refs && gi[s].rotated == gi[0].rotated);
        assert_true(gi[s].hash == gi[0].hash && gi[0].hash != 0);
        for (int k = 0; k < NR; k++) {
            assert_int_equal(h[s][k].prim, h[0][k].prim);
            assert_memory_equal(&h[s][k].t, &h[0][k].t, sizeof h[0][k].t);
            nhit += s == 1 && h[0][k].prim >= 0;
        }
    }
    assert_true(gi[0].prims < NT + 2); /* the degenerate ones were dropped */
    assert_true(gi[0].subgrids > 0);   /* the second level was built in parts */
    assert_true(nhit > NR / 10);
    for (int s = 0; s < NS; s++) {
        free(h[s]);
        rt_scene_free(sc[s]);
    }
    free(rays);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_watertight_mesh), cmocka_unit_test(test_shared_diagonal),
        cmocka_unit_test(test_grid_equals_brute), cmocka_unit_test(test_even_odd),
        cmocka_unit_test(test_big_polygons), cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_threads_same_scene),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
