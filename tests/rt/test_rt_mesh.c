/* SPDX-License-Identifier: MIT */
/*
 * test_rt_mesh.c -- indexed meshes (rt_scene_add_mesh, rt_scene_mesh_begin/end): a bumpy
 * height field with vertex normals and colours, stored once as a mesh, traces the same
 * picture bit for bit as its triangles given one by one (rt_scene_add_polygon_data) and the
 * same hits (distance, side), with a lone triangle beside it, whole and with culling (a degenerate triangle among them: the
 * commit's compacted copy); it needs fewer bytes per triangle; bad input is rejected with
 * nothing added; truncation and an abandoned reservation leave the scene as before. Shadow
 * rays over a scene of mesh triangles only (rt_occluded's any-hit lists of mesh triangles, one
 * per axis order of the rays) answer as without a grid. Ties between a mesh's triangles go to
 * the one given first although the mesh is stored in spatial order. Vertices that no kept
 * triangle uses leave the grid of a rotated frame as it is. Mesh triangles keep no record of
 * their own: each takes its mesh's id and surfaces, also when culling leaves a mesh out or in
 * part.
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
#define GKS3D_RT_BUILDING 1 /* the scene's mesh order and its vertex limit (test_given_order_back) */
#include "rt_internal.h"
#include "rt_testutil.h"

enum { N = 13, SZ = 64 }; /* N x N vertices */

static double xyz[N * N * 3], nrm[N * N * 3], col[N * N * 3];
static uint32_t idx[(N - 1) * (N - 1) * 6];

static void field(void)
{
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double x = -1 + 2.0 * i / (N - 1) + 0.013, y = -1 + 2.0 * j / (N - 1) + 0.007;
            double z = 0.3 * sin(2.1 * x) * cos(1.7 * y), zx = 0.63 * cos(2.1 * x) * cos(1.7 * y),
                   zy = -0.51 * sin(2.1 * x) * sin(1.7 * y);
            double *p = xyz + 3 * (j * N + i), *n = nrm + 3 * (j * N + i), *c = col + 3 * (j * N + i);
            p[0] = x, p[1] = y, p[2] = z;
            n[0] = -zx, n[1] = -zy, n[2] = 1; /* not unit: the tracer normalises */
            c[0] = 0.5 + 0.5 * x, c[1] = 0.5 + 0.5 * y, c[2] = 0.4;
        }
    for (int j = 0; j + 1 < N; j++)
        for (int i = 0; i + 1 < N; i++) {
            uint32_t k = (uint32_t)(j * N + i), *t = idx + 6 * (j * (N - 1) + i);
            t[0] = k, t[1] = k + 1, t[2] = k + N + 1, t[3] = k, t[4] = k + N + 1, t[5] = k + N;
        }
    idx[3 * 40 + 2] = idx[3 * 40 + 1]; /* one degenerate triangle: dropped at commit */
}

/* The field as one mesh (mesh = 1) or as lone triangles, lit (a shadow-casting light),
 * committed (cull: without the primitives wholly left of x = -0.3). */
static rt_scene *scene(int mesh, int cull)
{
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface su;
    rt_surface_default(&su);
    su.ka = 0.2;
    su.kd = 0.8;
    int s = rt_scene_add_surface(sc, &su);
    const size_t nt = (N - 1) * (N - 1) * 2;
    /* a lone triangle below, which the field shadows: plain and mesh triangles together */
    const double floor[9] = { -1.6, -1.6, -0.6, 1.6, -1.6, -0.6, 0, 1.6, -0.6 };
    const int three = 3;
    assert_int_equal(rt_scene_add_polygon(sc, 1, &three, floor, s, s), 0);
    if (mesh == 1) {
        assert_int_equal(rt_scene_add_mesh(sc, N * N, xyz, nrm, col, nt, idx, s, s), 1);
    } else if (mesh >= 2) { /* 3 vertices of its own per triangle, EXTRA unused ones last */
        enum { EXTRA = 50 };
        const size_t nv = 3 * nt + EXTRA;
        double *v = malloc(nv * 3 * sizeof(double)), *vn = malloc(nv * 3 * sizeof(double)),
               *vc = malloc(nv * 3 * sizeof(double));
        uint32_t *ix = malloc(nt * 3 * sizeof(uint32_t));
        assert_true(v && vn && vc && ix);
        for (size_t i = 0; i < nv; i++) {
            const uint32_t g = i < 3 * nt ? idx[i] : (uint32_t)(i % (N * N));
            for (int q = 0; q < 3; q++) {
                v[3 * i + q] = xyz[3 * g + q];
                vn[3 * i + q] = nrm[3 * g + q];
                vc[3 * i + q] = col[3 * g + q];
            }
            if (i < 3 * nt) /* (the degenerate triangle: two vertices at one place) */
                ix[i] = (uint32_t)i;
        }
        if (mesh == 2) {
            assert_int_equal(rt_scene_add_mesh(sc, nv, v, vn, vc, nt, ix, s, s), 1);
        } else {
            rt_mesh_fill f;
            assert_int_equal(rt_scene_mesh_begin(sc, nv, 1, 1, nt, &f), RT_OK);
            memcpy(f.xyz, v, nv * 3 * sizeof(double));
            memcpy(f.idx, ix, nt * 3 * sizeof(uint32_t));
            for (size_t i = 0; i < nv; i++) {
                rt_mesh_store_normal(f.normals + 3 * i, vn + 3 * i);
                rt_mesh_store_colour(f.colours + 3 * i, vc + 3 * i);
            }
            assert_int_equal(rt_scene_mesh_end(sc, s, s), 1);
        }
        free(v);
        free(vn);
        free(vc);
        free(ix);
    } else {
        for (size_t t = 0; t < nt; t++) {
            double v[9], vn[9], vc[9];
            for (int k = 0; k < 3; k++)
                for (int q = 0; q < 3; q++) {
                    v[3 * k + q] = xyz[3 * idx[3 * t + k] + q];
                    vn[3 * k + q] = nrm[3 * idx[3 * t + k] + q];
                    vc[3 * k + q] = col[3 * idx[3 * t + k] + q];
                }
            const rt_vertex_data vd = { vn, vc };
            assert_int_equal(rt_scene_add_polygon_data(sc, 1, &three, v, &vd, s, s), (int)t + 1);
            /* (the degenerate one takes its id and is not kept) */
        }
    }
    const rt_light amb = { .type = RT_LIGHT_AMBIENT, .color = { 1, 1, 1 } };
    const rt_light dl = { .type = RT_LIGHT_DIRECTIONAL, .color = { 1, 1, 1 },
                          .direction = { 0.5, -0.4, -0.6 } };
    assert_true(rt_scene_add_light(sc, &amb) >= 0);
    assert_true(rt_scene_add_light(sc, &dl) >= 0);
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = -1;
    bo.threads = 2;
    if (cull) {
        bo.ncull = 1;
        bo.cull[0][0] = 1;
        bo.cull[0][3] = 0.3;
        bo.cull_eps = 1e-9;
    }
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    return sc;
}

static void camera(rt_camera *cam)
{
    rtu_view vw = { .win = { -1.4, 1.4, -1.4, 1.4 }, .prp = { 0.3, -0.4, 10 }, .vpd = 0,
                    .bpd = -5, .fpd = 5, .vp = { 0, 1, 0, 1, 0, 1 }, .perspective = 1 };
    double m[4][4];
    rtu_view_matrix(&vw, m);
    assert_int_equal(rt_camera_from_view(cam, m, vw.vp, SZ, SZ), RT_OK);
}

static void same_picture_of(int mesh, int cull)
{
    field();
    rt_scene *a = scene(mesh, cull), *b = scene(0, cull);
    rt_camera cam;
    camera(&cam);
    rt_render_options o;
    rt_render_options_default(&o); /* corner rays: samples on the mesh lines too */
    o.threads = 2;
    float *pa = malloc(3 * SZ * SZ * sizeof(float)), *pb = malloc(3 * SZ * SZ * sizeof(float));
    assert_non_null(pa);
    assert_non_null(pb);
    rt_stats sa, sb;
    assert_int_equal(rt_render(a, &cam, &o, pa, &sa), RT_OK);
    assert_int_equal(rt_render(b, &cam, &o, pb, &sb), RT_OK);
    assert_memory_equal(pa, pb, 3 * SZ * SZ * sizeof(float));
    assert_true(sa.eye_hits > SZ * SZ / (cull ? 4 : 2));
    assert_int_equal(sa.prims, sb.prims);
    print_message("%s: %llu triangles kept; bytes per triangle: mesh %.1f, lone triangles %.1f\n",
                  cull ? "culled" : "whole", (unsigned long long)sa.prims,
                  (double)sa.tri_bytes / (double)sa.prims, (double)sb.tri_bytes / (double)sb.prims);
    if (cull)
        assert_true(sa.prims < (N - 1) * (N - 1) * 2 - (N - 1) * 2);
    else
        assert_int_equal(sa.prims, (N - 1) * (N - 1) * 2); /* less 1 degenerate, 1 floor */
    assert_true(sa.tri_bytes < sb.tri_bytes / 2 + sb.tri_bytes / 8 || cull || mesh != 1);
    /* the same hits, ray by ray (ids aside: the mesh has one) */
    rt_ray r[SZ];
    rt_hit ha[SZ], hb[SZ];
    for (int y = 0; y < SZ; y += 7) {
        for (int x = 0; x < SZ; x++)
            assert_int_equal(rt_camera_ray(&cam, x + 0.25, y + 0.5, &r[x]), RT_OK);
        assert_int_equal(rt_intersect(a, SZ, r, ha), RT_OK);
        assert_int_equal(rt_intersect(b, SZ, r, hb), RT_OK);
        for (int x = 0; x < SZ; x++) {
            assert_int_equal(ha[x].prim >= 0, hb[x].prim >= 0);
            if (ha[x].prim >= 0) {
                assert_true(ha[x].prim == 1 || hb[x].prim == 0);
                assert_int_equal(ha[x].prim == 0, hb[x].prim == 0); /* the floor */
                assert_true(ha[x].t == hb[x].t);
                assert_int_equal(ha[x].side, hb[x].side);
            }
        }
    }
    free(pa);
    free(pb);
    rt_scene_free(a);
    rt_scene_free(b);
}

static void same_picture(int cull)
{
    same_picture_of(1, cull);
}

static void test_same_picture(void **state)
{
    (void)state;
    same_picture(0);
}

/* Triangles with vertices of their own (more vertices than triangles, as N separate
   triangles given as one mesh, and unused ones), with normals and colours, by
   rt_scene_add_mesh and by rt_scene_mesh_begin/end: the add's sort block is made of parts
   sized by each use (the vertices' copy, the normals' and colours' copies by vertex count,
   the sums by triangle count) and must hold each: the same picture and hits as the lone
   triangles. */
static void test_same_picture_unshared(void **state)
{
    (void)state;
    same_picture_of(2, 0);
    same_picture_of(3, 0);
    same_picture_of(3, 1);
}

/* with culling, and the degenerate triangle: the commit's compacted copy of the indices */
static void test_same_picture_culled(void **state)
{
    (void)state;
    same_picture(1);
}

static void test_bad_input(void **state)
{
    (void)state;
    field();
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    int s = rt_scene_add_surface(sc, &su);
    const double tri[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 }, bad[9] = { 0, 0, 1, NAN, 0, 1, 0, 0, 1 };
    const uint32_t ok3[3] = { 0, 1, 2 }, out[3] = { 0, 1, 3 };
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, NULL, NULL, 1, out, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, bad, NULL, 1, ok3, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, NULL, bad, 1, ok3, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, NULL, NULL, 1, ok3, s, s + 7), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_mesh(sc, 3, NULL, NULL, NULL, 1, ok3, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, NULL, NULL, 1, NULL, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_mesh_end(sc, s, s), RT_ERR_STATE);
    assert_int_equal(rt_scene_count(sc), 0);
    /* an abandoned reservation adds nothing; the next mesh is whole */
    rt_mesh_fill f;
    /* every vertex's offset 3 v fits in an index word: (2^32 - 1) / 3 vertices at most */
    assert_int_equal(rt_scene_mesh_begin(sc, (size_t)UINT32_MAX / 3 + 1, 0, 0, 1, &f),
                     RT_ERR_LIMIT);
    assert_int_equal(rt_scene_mesh_begin(sc, 3, 1, 0, 1, &f), RT_OK);
    assert_non_null(f.xyz);
    assert_non_null(f.normals);
    assert_null(f.colours);
    memcpy(f.xyz, tri, sizeof tri);
    assert_int_equal(rt_scene_add_mesh(sc, 3, tri, NULL, NULL, 1, ok3, s, s), 0);
    assert_int_equal(rt_scene_mesh_end(sc, s, s), RT_ERR_STATE);
    /* truncation drops the mesh */
    assert_int_equal(rt_scene_add_mesh(sc, N * N, xyz, nrm, col, 2, idx, s, s), 1);
    assert_int_equal(rt_scene_truncate(sc, 1), RT_OK);
    assert_int_equal(rt_scene_count(sc), 1);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_ray r = { .org = { 0.25, 0.25, 1 }, .dir = { 0, 0, -1 }, .tmin = 0, .tmax = 10 };
    rt_hit h;
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
    assert_int_equal(h.prim, 0);
    rt_scene_free(sc);
}

/* triangles with a vertex that is not finite or lies beyond RT_COORD_MAX on an axis are
   not kept, whichever coordinate it is and in either direction (the check tests them through
   the triangle's box and vertex sums) */
static void test_bad_vertices_dropped(void **state)
{
    (void)state;
    const double big = 2 * RT_COORD_MAX;
    double v[3 * 28] = {0, 0, 0, 1, 0, 0, 0, 1, 0, /* 0-2: a sane triangle */
                        NAN, 0.5, 0, 0.5, INFINITY, 0, 0.5, 0.5, -INFINITY,
                        big, 0.5, 0, 0.5, -big, 0, 0.5, 0.5, big,
                        -1, 0, 0}; /* 9: sane */
    uint32_t ix[3 * 16] = {0, 1, 2, 0, 1, 3, 0, 1, 4, 0, 2, 5, 3, 4, 5,
                           0, 1, 6, 0, 1, 7, 0, 2, 8, 1, 2, 6, 2, 0, 9};
    /* 10-27: six well-shaped triangles (edges 1e90) at +-2 RT_COORD_MAX on one axis each */
    for (int k = 0; k < 6; k++) {
        for (int q = 0; q < 3; q++) {
            double *p = v + 3 * (10 + 3 * k + q);
            p[0] = p[1] = p[2] = 0.0;
            p[(k / 2 + 1) % 3] = q == 1 ? 1e90 : 0.0;
            p[(k / 2 + 2) % 3] = q == 2 ? 1e90 : 0.0;
            p[k / 2] = k % 2 ? -big : big;
            ix[3 * (10 + k) + q] = (uint32_t)(10 + 3 * k + q);
        }
    }
    int s;
    rt_scene *sc = rtu_scene_one_surface(&s);
    assert_non_null(sc);
    assert_int_equal(rt_scene_add_mesh(sc, 28, v, NULL, NULL, 16, ix, s, s), 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_int_equal(gi.prims, 2); /* (0, 1, 2) and (2, 0, 9) */
    rt_ray r = {.org = {0.25, 0.25, 1}, .dir = {0, 0, -1}, .tmin = 0, .tmax = 10};
    rt_hit h;
    assert_int_equal(rt_intersect(sc, 1, &r, &h), RT_OK);
    assert_true(h.t > 0.99 && h.t < 1.01);
    rt_scene_free(sc);
}

/* one mesh of nv vertices xyz and nt index triples ix, committed with a grid or without one
   (brute) */
static rt_scene *one_mesh(size_t nv, const double *v, size_t nt, const uint32_t *ix, int brute)
{
    int s;
    rt_scene *sc = rtu_scene_one_surface(&s);
    assert_non_null(sc);
    assert_int_equal(rt_scene_add_mesh(sc, nv, v, NULL, NULL, nt, ix, s, s), 0);
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = -1;
    bo.brute_force = brute;
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    return sc;
}

/* the field alone as a mesh, committed with a grid or without one (brute) */
static rt_scene *mesh_only(int brute)
{
    return one_mesh(N * N, xyz, (N - 1) * (N - 1) * 2, idx, brute);
}

/* the field's triangles as lone polygons (plain triangles, ids 0 ..; the degenerate one takes
   its id and is dropped), committed with a grid: hits whose records take the general path
   (rt_fill_hit), against which the mesh-only scenes' records (made inline) are checked */
static rt_scene *lone_only(void)
{
    int s;
    rt_scene *sc = rtu_scene_one_surface(&s);
    assert_non_null(sc);
    const int three = 3;
    for (size_t t = 0; t < (N - 1) * (N - 1) * 2; t++) {
        double v[9];
        for (int k = 0; k < 3; k++)
            for (int q = 0; q < 3; q++)
                v[3 * k + q] = xyz[3 * idx[3 * t + k] + q];
        assert_int_equal(rt_scene_add_polygon(sc, 1, &three, v, s, s), (int)t);
    }
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = -1;
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    return sc;
}

/* Shadow rays from points of the field (hits of rays from above) to lights on four sides and
 * above and below, the origin moved towards the light by 1e-6 of the way (the ray starts beside
 * its own triangle, which it crosses behind itself), and rays up and down through the field:
 * every axis order of the rays' shear occurs; each set also one ray a call, and rays straight
 * down. The same answers with the grid as without, and per light and direction blocked rays
 * where the field can block them. */
static void test_occluded_mesh_only(void **state)
{
    (void)state;
    field();
    rt_scene *g = mesh_only(0), *b = mesh_only(1);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(g, &gi), RT_OK);
    assert_true(gi.cells + gi.subcells > 1);
    enum { M = 29, NL = 6, NS = NL + 2 };
    static const double light[NL][3] = {{3, 0.3, 0.2},  {-3, -0.2, 0.15}, {0.2, 3, 0.25},
                                        {-0.1, -3, 0.3}, {0.3, 0.1, 3},   {-0.2, 0.3, -3}};
    static rt_ray down[M * M], rays[NS][M * M];
    static rt_hit hit[M * M];
    static unsigned char og[M * M], ob[M * M];
    for (int j = 0; j < M; j++)
        for (int i = 0; i < M; i++)
            down[j * M + i] = (rt_ray){.org = {-0.95 + 1.9 * i / (M - 1), -0.95 + 1.9 * j / (M - 1), 2},
                                       .dir = {0, 0, -1},
                                       .tmin = 0,
                                       .tmax = INFINITY};
    assert_int_equal(rt_intersect(b, M * M, down, hit), RT_OK);
    size_t n[NS] = {0};
    for (int l = 0; l < NL; l++)
        for (int k = 0; k < M * M; k++) {
            if (hit[k].prim < 0)
                continue;
            rt_ray *r = &rays[l][n[l]++];
            for (int q = 0; q < 3; q++) {
                r->org[q] = hit[k].p[q] + 1e-6 * (light[l][q] - hit[k].p[q]);
                r->dir[q] = light[l][q] - r->org[q];
            }
            r->tmin = 0;
            r->tmax = 1 - 1e-6;
        }
    for (int k = 0; k < M * M; k++) { /* through the field, up and down, ending before or past it */
        const double x = 0.6 * down[k].org[0], y = 0.6 * down[k].org[1], e = k % 3 ? 1.0 : 0.1;
        rays[NL][n[NL]++] = (rt_ray){.org = {x, y, -2}, .dir = {0.3, -0.2, 4}, .tmin = 0, .tmax = e};
        rays[NL + 1][n[NL + 1]++] = (rt_ray){.org = {x, y, 2}, .dir = {-0.2, 0.3, -4}, .tmin = 0, .tmax = e};
    }
    for (int l = 0; l < NS; l++) {
        assert_true(n[l] > M * M / 2);
        rtc_traps_on();
        assert_int_equal(rt_occluded(g, n[l], rays[l], og), RT_OK);
        assert_int_equal(rt_occluded(b, n[l], rays[l], ob), RT_OK);
        rtc_traps_off();
        size_t blocked = 0;
        for (size_t k = 0; k < n[l]; k++) {
            assert_int_equal(og[k], ob[k]);
            blocked += ob[k];
        }
        /* one ray a call: no four-ray set-up, the one-ray code's walk (rt_transmit_core) */
        for (size_t k = 0; k < n[l]; k++) {
            unsigned char o1 = 2;
            assert_int_equal(rt_occluded(g, 1, rays[l] + k, &o1), RT_OK);
            assert_int_equal(o1, ob[k]);
        }
        /* the lights above and below the height field light every point; the others are low */
        if (l == 4 || l == 5)
            assert_int_equal(blocked, 0);
        else
            assert_true(blocked > n[l] / 50 && blocked < n[l]);
    }
    /* straight down (two direction components 0: no step on x and y, the sub-grids' clip
       without lanes), ending above the field or past it */
    for (int k = 0; k < M * M; k++)
        down[k].tmax = k % 2 ? 1.0 : 3.0;
    rtc_traps_on();
    assert_int_equal(rt_occluded(g, M * M, down, og), RT_OK);
    assert_int_equal(rt_occluded(b, M * M, down, ob), RT_OK);
    rtc_traps_off();
    size_t blocked = 0;
    for (int k = 0; k < M * M; k++) {
        assert_int_equal(og[k], ob[k]);
        blocked += ob[k];
    }
    assert_true(blocked > 0 && blocked < M * M / 2 + 1);
    rt_scene_free(g);
    rt_scene_free(b);
}

/* The tilted plane of the flat sub-grid tests: an FLAT_F x FLAT_F mesh of z = 0.37 x -
   0.21 y + 0.1 s over [-s, s]^2 moved by (off, -off / 2), as g (a grid with a coarse top
   level, so that its cells have second-level grids, some of them flat) and b (no grid). */
enum { FLAT_F = 48 };
static void flat_plane(double s, double off, rt_scene **gp, rt_scene **bp)
{
    enum { F = FLAT_F };
    static double v[F * F * 3];
    static uint32_t ix[(F - 1) * (F - 1) * 6];
    for (int j = 0; j < F; j++)
        for (int i = 0; i < F; i++) {
            double *p = v + 3 * (j * F + i);
            p[0] = s * (-1 + 2.0 * i / (F - 1)) + off;
            p[1] = s * (-1 + 2.0 * j / (F - 1)) - 0.5 * off;
            p[2] = 0.37 * p[0] - 0.21 * p[1] + 0.1 * s;
        }
    for (int j = 0; j + 1 < F; j++)
        for (int i = 0; i + 1 < F; i++) {
            uint32_t k = (uint32_t)(j * F + i), *t = ix + 6 * (j * (F - 1) + i);
            t[0] = k, t[1] = k + 1, t[2] = k + F + 1, t[3] = k, t[4] = k + F + 1, t[5] = k + F;
        }
    int sf;
    rt_scene *g = rtu_scene_one_surface(&sf), *b = one_mesh(F * F, v, (F - 1) * (F - 1) * 2, ix, 1);
    assert_non_null(g);
    assert_int_equal(rt_scene_add_mesh(g, F * F, v, NULL, NULL, (F - 1) * (F - 1) * 2, ix, sf, sf), 0);
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = -1;
    bo.grid_res[0] = bo.grid_res[1] = bo.grid_res[2] = 4;
    bo.sub_min = 8;
    assert_int_equal(rt_scene_commit(g, &bo), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(g, &gi), RT_OK);
    assert_true(gi.flat_subgrids > 0);
    *gp = g;
    *bp = b;
}

/* A tilted plane as one mesh (scales 1 and 1000, the latter moved off the origin): its
 * sub-grids are flat (rt_grid_info.flat_subgrids), and rt_occluded skips the walk of one where
 * the ray's segment stays beyond its plane (rt_subplane). Against the scene without a grid:
 * shadow rays from points just above the plane to lights above it (never blocked), rays that
 * end exactly at their nearest hit (tmax its t, from above and from below: always blocked,
 * the end lying on the plane within the test's roundings, which a margin too small would
 * put beyond the plane's slab), ending just short of it, and crossing it; in batches, as
 * packets and one ray a call. */
static void test_occluded_flat(void **state)
{
    (void)state;
    enum { F = FLAT_F, M = 600, NL = 5 };
    static rt_ray down[M], rays[4][M];
    static rt_hit hit[M];
    static unsigned char og[M], ob[M];
    static const double light[NL][3] = {{0.3, 0.2, 3}, {-2, 0.5, 1.5}, {0.4, -2, 1.2},
                                        {1.5, 1.9, 1.4}, {-0.1, 0.2, 9}};
    for (int sc = 0; sc < 2; sc++) {
        const double s = sc ? 1000.0 : 1.0, off = sc ? 3217.0 : 0.0;
        rt_scene *g, *b;
        flat_plane(s, off, &g, &b);
        uint64_t st = 0x9E3779B97F4A7C15ull;
        for (int k = 0; k < M; k++) { /* from above to points of the plane */
            double q[3];
            for (int a = 0; a < 3; a++) {
                st = st * 6364136223846793005ull + 1442695040888963407ull;
                q[a] = (double)(st >> 11) * 0x1p-53 * 1.8 - 0.9;
            }
            const double x = s * q[0] + off, y = s * q[1] - 0.5 * off,
                         z = 0.37 * x - 0.21 * y + 0.1 * s;
            const double h = (k % 2 ? 1.0 : -1.0) * s * (0.5 + fabs(q[2])); /* above, below */
            down[k] = (rt_ray){.org = {x + 0.3 * h * q[2], y - 0.2 * h, z + h},
                               .dir = {-0.3 * h * q[2], 0.2 * h, -h},
                               .tmin = 0,
                               .tmax = INFINITY};
            down[k].org[0] += 0.01 * s * q[1]; /* not quite at the aimed point: any slope */
        }
        assert_int_equal(rt_intersect(g, M, down, hit), RT_OK);
        size_t n = 0;
        for (int k = 0; k < M; k++) {
            if (hit[k].prim < 0)
                continue;
            rays[0][n] = down[k]; /* ending exactly at the hit */
            rays[0][n].tmax = hit[k].t;
            rays[1][n] = down[k]; /* ending just short of it */
            rays[1][n].tmax = hit[k].t * (1 - 1e-9);
            rays[2][n] = down[k]; /* through it */
            rays[2][n].tmax = 2 * hit[k].t;
            const double *L = light[k % NL];
            rt_ray *r = &rays[3][n]; /* from just above the plane to a light above it */
            for (int a = 0; a < 3; a++) {
                const double la = s * L[a] + (a == 0 ? off : a == 1 ? -0.5 * off : 0.0);
                r->org[a] = hit[k].p[a];
                r->dir[a] = la - hit[k].p[a];
            }
            r->org[2] += (0.37 * r->dir[0] - 0.21 * r->dir[1] < r->dir[2] ? 1e-6 : -1e-6) * s;
            for (int a = 0; a < 3; a++)
                r->dir[a] = (s * L[a] + (a == 0 ? off : a == 1 ? -0.5 * off : 0.0)) - r->org[a];
            r->tmin = 0;
            r->tmax = 1 - 1e-6;
            n++;
        }
        assert_true(n > M / 2);
        for (int l = 0; l < 4; l++) {
            rtc_traps_on();
            assert_int_equal(rt_occluded(g, n, rays[l], og), RT_OK);
            assert_int_equal(rt_occluded(b, n, rays[l], ob), RT_OK);
            rtc_traps_off();
            size_t blocked = 0;
            for (size_t k = 0; k < n; k++) {
                assert_int_equal(og[k], ob[k]);
                blocked += ob[k];
            }
            /* the packet path (its rays given up are traced singly, with the same walks) */
            rtc_traps_on();
            assert_int_equal(rt_occluded_packet(g, n, rays[l], og), RT_OK);
            rtc_traps_off();
            for (size_t k = 0; k < n; k++) {
                assert_int_equal(og[k], ob[k]);
                unsigned char o1 = 2;
                assert_int_equal(rt_occluded(g, 1, rays[l] + k, &o1), RT_OK);
                assert_int_equal(o1, ob[k]);
            }
            if (l == 0 || l == 2)
                assert_int_equal(blocked, n);
            if (l == 3)
                assert_int_equal(blocked, 0);
        }
        /* coherent packets (rt_occluded_packet's own walks, which leave the rays of a
           flat sub-grid out of its walk when their segments stay beyond its plane): 8 x 8
           blocks of rays from a light to neighbouring points of the plane, ending exactly
           at their nearest hit, and from just above those hits back to the light */
        static rt_ray pk[2][M];
        size_t np = 0;
        for (int blk = 0; blk < M / 64 && np + 64 <= M; blk++) {
            const double *L = light[blk % NL];
            const double la[3] = {s * L[0] + off, s * L[1] - 0.5 * off, s * L[2]};
            const double cx = s * (-0.8 + 1.6 * ((blk * 7) % 9) / 8.0) + off,
                         cy = s * (-0.8 + 1.6 * ((blk * 4) % 9) / 8.0) - 0.5 * off;
            rt_ray blkr[64];
            for (int q = 0; q < 64; q++) {
                const double x = cx + s * 0.013 * (q % 8), y = cy + s * 0.011 * (q / 8),
                             z = 0.37 * x - 0.21 * y + 0.1 * s;
                blkr[q] = (rt_ray){.org = {la[0], la[1], la[2]},
                                   .dir = {x - la[0], y - la[1], z - la[2]},
                                   .tmin = 0,
                                   .tmax = INFINITY};
            }
            assert_int_equal(rt_intersect(b, 64, blkr, hit), RT_OK);
            for (int q = 0; q < 64; q++) {
                assert_true(hit[q].prim >= 0);
                pk[0][np + q] = blkr[q];
                pk[0][np + q].tmax = hit[q].t;
                rt_ray *r = &pk[1][np + q];
                for (int a = 0; a < 3; a++)
                    r->org[a] = hit[q].p[a];
                r->org[2] += (la[2] > 0.37 * la[0] - 0.21 * la[1] ? 1e-6 : -1e-6) * s;
                for (int a = 0; a < 3; a++)
                    r->dir[a] = la[a] - r->org[a];
                r->tmin = 0;
                r->tmax = 1 - 1e-6;
            }
            np += 64;
        }
        for (int l = 0; l < 2; l++) {
            rtc_traps_on();
            assert_int_equal(rt_occluded_packet(g, np, pk[l], og), RT_OK);
            assert_int_equal(rt_occluded(b, np, pk[l], ob), RT_OK);
            rtc_traps_off();
            for (size_t k = 0; k < np; k++)
                assert_int_equal(og[k], l == 0 ? 1 : 0);
            for (size_t k = 0; k < np; k++)
                assert_int_equal(ob[k], l == 0 ? 1 : 0);
        }
        rt_scene_free(g);
        rt_scene_free(b);
    }
}

/* the hits of rays n rays through g and b, in a batch (the four-ray set-up's walks) and one
   ray a call (the one-ray walk): bit for bit the same; the number of rays that hit */
static size_t same_hits(rt_scene *g, rt_scene *b, size_t n, const rt_ray *rays, rt_hit *hg,
                        rt_hit *hb)
{
    rtc_traps_on();
    assert_int_equal(rt_intersect(g, n, rays, hg), RT_OK);
    assert_int_equal(rt_intersect(b, n, rays, hb), RT_OK);
    rtc_traps_off();
    size_t hits = 0;
    for (size_t k = 0; k < n; k++) {
        assert_memory_equal(&hg[k], &hb[k], sizeof hg[k]);
        hits += hb[k].prim >= 0;
        rt_hit h1;
        assert_int_equal(rt_intersect(g, 1, rays + k, &h1), RT_OK);
        assert_memory_equal(&h1, &hb[k], sizeof h1);
    }
    return hits;
}

/* The nearest-hit walks skip a flat sub-grid whose plane their range in the top cell does not
 * cross (rt_grid.subplane_near, a scene of one mesh). A tilted plane as one mesh (scales 1 and
 * 1000, off the origin) against the scene without a grid, bit for bit: rays from above and
 * below to points of the plane, steep and nearly grazing (slopes 0.02 and 0.004: they pass
 * many flat sub-grids before their hit; the second is inside the skip's grazing limit), and
 * each of them again ending exactly at its hit (tmax its t: the range's end lies on the plane
 * within the roundings, which a margin too small puts beyond the slab, and the hit is lost),
 * starting exactly at it (tmin its t) and ending just short of it; and from far out ending
 * exactly at it (the only case where the skip's margin beyond the slab's own widening decides:
 * without it the hit is lost); in batches and one ray a call. The triangles' shared edges and
 * vertices give ties between triangles. */
static void test_intersect_flat(void **state)
{
    (void)state;
    enum { F = FLAT_F, M = 800 };
    static rt_ray rays[4][M];
    static rt_hit hg[M], hb[M];
    for (int sc = 0; sc < 2; sc++) {
        const double s = sc ? 1000.0 : 1.0, off = sc ? 3217.0 : 0.0;
        rt_scene *g, *b;
        flat_plane(s, off, &g, &b);
        uint64_t st = 0x2545F4914F6CDD1Dull;
        for (int k = 0; k < M; k++) { /* to points of the plane, some on its edges */
            double q[4];
            for (int a = 0; a < 4; a++) {
                st = st * 6364136223846793005ull + 1442695040888963407ull;
                q[a] = (double)(st >> 11) * 0x1p-53 * 1.8 - 0.9;
            }
            if (k % 5 == 0) /* on a vertex of the mesh */
                q[0] = round(q[0] * (F - 1) / 2) * 2.0 / (F - 1);
            const double x = s * q[0] + off, y = s * q[1] - 0.5 * off,
                         z = 0.37 * x - 0.21 * y + 0.1 * s;
            /* along the plane (its unit vectors in x and y, turned by q[3]) and off it by
               slope: steep, shallow (0.02) or grazing (0.004) */
            const double c = cos(3.2 * q[3]), sn = sin(3.2 * q[3]);
            const double slope = k % 3 == 0 ? 1.5 : k % 3 == 1 ? 0.02 : 0.004;
            double dir[3] = {c, sn, 0.37 * c - 0.21 * sn}, nrm[3] = {-0.37, 0.21, 1.0};
            const double side = k % 2 ? 1.0 : -1.0, len = 1.2 * s;
            for (int a = 0; a < 3; a++)
                dir[a] = dir[a] - side * slope * nrm[a];
            const double pt[3] = {x, y, z};
            rt_ray *r = &rays[0][k];
            for (int a = 0; a < 3; a++) {
                r->org[a] = pt[a] - len * dir[a];
                r->dir[a] = dir[a] * (0.5 + fabs(q[2]));
            }
            r->tmin = 0;
            r->tmax = INFINITY;
        }
        assert_true(same_hits(g, b, M, rays[0], hg, hb) > M / 2);
        size_t n = 0;
        for (int k = 0; k < M; k++) {
            if (hb[k].prim < 0)
                continue;
            rays[1][n] = rays[2][n] = rays[3][n] = rays[0][k];
            rays[1][n].tmax = hb[k].t;           /* ending exactly at the hit */
            rays[2][n].tmin = hb[k].t;           /* starting exactly at it */
            rays[3][n].tmax = hb[k].t * (1 - 1e-9); /* ending just short of it */
            n++;
        }
        assert_int_equal(same_hits(g, b, n, rays[1], hg, hb), n);
        (void)same_hits(g, b, n, rays[2], hg, hb);
        assert_int_equal(same_hits(g, b, n, rays[3], hg, hb), 0);
        /* the same rays from far out (30 times the plane's extent back along the ray, inside
           the skip's 64 S0) and ending exactly at their hits: the ends' heights n . o + t
           (n . d) now round by more than the slab's own widening (8 u S), so that only the
           skip's margin (rt_sub_flat_near) keeps the hit's sub-grid walked */
        const double far = 30.0 * (s + off);
        for (int k = 0; k < M; k++) {
            rays[1][k] = rays[0][k];
            const double *d = rays[0][k].dir, dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (int a = 0; a < 3; a++)
                rays[1][k].org[a] -= far / dl * d[a];
        }
        assert_true(same_hits(g, b, M, rays[1], hg, hb) > M / 2);
        n = 0;
        for (int k = 0; k < M; k++) {
            if (hb[k].prim < 0)
                continue;
            rays[2][n] = rays[1][k];
            rays[2][n++].tmax = hb[k].t;
        }
        assert_int_equal(same_hits(g, b, n, rays[2], hg, hb), n);
        rt_scene_free(g);
        rt_scene_free(b);
    }
}

/* Rays of every axis order of the shear (each axis the largest component, either sign) at
 * points of the field's box from 3 units away, in batches (the four-ray set-up, whose lanes
 * take the nearest-hit lists of mesh triangles on a CPU with AVX2): the same answers with the
 * grid as without, bit for bit, and hits in every order; and the hit records of the mesh-only
 * scene (made inline, rt_fill_hit_mesh) those of the same triangles given alone (rt_fill_hit). */
static void test_intersect_mesh_only(void **state)
{
    (void)state;
    field();
    rt_scene *g = mesh_only(0), *b = mesh_only(1), *l = lone_only();
    enum { M = 400 };
    static rt_ray rays[M];
    static rt_hit hg[M], hb[M], hl[M];
    uint32_t seed = 12345;
#define RND() ((seed = seed * 1664525u + 1013904223u) >> 8) * (1.0 / 16777216.0)
    for (int a = 0; a < 3; a++)
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            for (int k = 0; k < M; k++) {
                double d[3], p[3] = {-0.8 + 1.6 * RND(), -0.8 + 1.6 * RND(), -0.25 + 0.5 * RND()};
                for (int q = 0; q < 3; q++)
                    d[q] = q == a ? sgn * (1.0 + RND()) : -0.6 + 1.2 * RND();
                for (int q = 0; q < 3; q++) {
                    rays[k].org[q] = p[q] - 3.0 * d[q];
                    rays[k].dir[q] = d[q];
                }
                rays[k].tmin = 0;
                rays[k].tmax = INFINITY;
            }
            rtc_traps_on();
            assert_int_equal(rt_intersect(g, M, rays, hg), RT_OK);
            assert_int_equal(rt_intersect(b, M, rays, hb), RT_OK);
            assert_int_equal(rt_intersect(l, M, rays, hl), RT_OK);
            rtc_traps_off();
            int hits = 0;
            for (int k = 0; k < M; k++) {
                assert_int_equal(hg[k].prim, hb[k].prim);
                assert_true(hg[k].t == hb[k].t || (isinf(hg[k].t) && isinf(hb[k].t)));
                assert_int_equal(hg[k].side, hb[k].side);
                assert_memory_equal(hg[k].ng, hb[k].ng, sizeof hg[k].ng);
                /* the record as the general path makes it for the same triangle given alone
                   (none of these rays meets a shared edge, where the tie rules of one mesh and
                   of lone areas could pick different neighbours): the same distance, point,
                   normal and side, bit for bit */
                assert_int_equal(hg[k].prim >= 0, hl[k].prim >= 0);
                if (hg[k].prim >= 0) {
                    assert_true(hg[k].t == hl[k].t);
                    assert_memory_equal(hg[k].p, hl[k].p, sizeof hg[k].p);
                    assert_memory_equal(hg[k].ng, hl[k].ng, sizeof hg[k].ng);
                    assert_int_equal(hg[k].side, hl[k].side);
                }
                hits += hg[k].prim >= 0;
            }
            assert_true(hits > M / 10);
        }
#undef RND
    rt_scene_free(g);
    rt_scene_free(b);
    rt_scene_free(l);
}

/* Two coplanar triangles of one mesh facing opposite ways, overlapping where a ray hits them
 * both at the same distance (exact: small integers, an axis-parallel ray): the hit is the
 * triangle given first, in either order, although the mesh is stored in spatial order (the
 * second triangle's centre comes first in it), with a grid and without one. */
static void test_tie_given_first(void **state)
{
    (void)state;
    /* up: normal +z, centre (0, 0); down: normal -z, centre (-8/3, -8/3); (-1, -1) in both */
    static const double v[6 * 3] = {-2, -2, 0, 4, -2, 0, -2, 4, 0,
                                    -8, -8, 0, -8, 8, 0, 8, -8, 0};
    static const uint32_t up_down[6] = {0, 1, 2, 3, 4, 5}, down_up[6] = {3, 4, 5, 0, 1, 2};
    const rt_ray ray = {.org = {-1, -1, 5}, .dir = {0, 0, -1}, .tmin = 0, .tmax = INFINITY};
    for (int order = 0; order < 2; order++)
        for (int brute = 0; brute < 2; brute++) {
            rt_scene *sc = one_mesh(6, v, 2, order ? down_up : up_down, brute);
            rt_hit h;
            assert_int_equal(rt_intersect(sc, 1, &ray, &h), RT_OK);
            assert_int_equal(h.prim, 0);
            assert_true(h.t == 5.0);
            assert_true(h.ng[2] == (order ? -1.0 : 1.0));
            rt_scene_free(sc);
        }
}


/* The scene's meshes put back in their given order when a mesh beyond the limits of the
   spatial order is added (here a lowered vertex limit): every triangle of the first mesh back
   at its given position with its vertices in their roles, the index words without positions,
   a later mesh left in its given order, and the same answers as a scene in spatial order. */
static void test_given_order_back(void **state)
{
    (void)state;
    enum { N = 12 }; /* a bumpy N x N vertex sheet at z near -10, triangles row by row */
    static double sheet[N * N * 3];
    static uint32_t six[2 * (N - 1) * (N - 1) * 3];
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double *p = sheet + 3 * (j * N + i);
            p[0] = -6.0 + i;
            p[1] = -6.0 + j;
            p[2] = -10.0 + 0.25 * ((i * 7 + j * 3) % 5);
        }
    size_t nt = 0;
    for (int j = 0; j + 1 < N; j++)
        for (int i = 0; i + 1 < N; i++) {
            const uint32_t a = (uint32_t)(j * N + i), b = a + 1, c = a + N, d = c + 1;
            const uint32_t q[6] = {a, b, d, a, d, c};
            memcpy(six + 3 * nt, q, sizeof q);
            nt += 2;
        }
    /* the tie pair of test_tie_given_first, the later-given triangle facing down */
    static const double v[6 * 3] = {-2, -2, 0, 4, -2, 0, -2, 4, 0, -8, -8, 0, -8, 8, 0, 8, -8, 0};
    static const uint32_t down_up[6] = {3, 4, 5, 0, 1, 2};
    rt_scene *sc[2];
    for (int k = 0; k < 2; k++) {
        int s;
        sc[k] = rtu_scene_one_surface(&s);
        assert_non_null(sc[k]);
        assert_int_equal(rt_scene_add_mesh(sc[k], N * N, sheet, NULL, NULL, nt, six, s, s), 0);
        if (k == 1) { /* the spatial order moved the sheet's triangles */
            assert_int_equal(sc[k]->vmask, RT_VMASK);
            size_t moved = 0;
            for (size_t t = 0; t < nt; t++)
                moved += rt_ctri_given(((const uint32_t (*)[3])sc[k]->mtri.p)[t]) != t;
            assert_true(moved > nt / 2);
            sc[k]->vlimit = N * N + 5; /* the next mesh goes beyond it */
        }
        assert_int_equal(rt_scene_add_mesh(sc[k], 6, v, NULL, NULL, 2, down_up, s, s), 1);
        assert_int_equal(rt_scene_add_mesh(sc[k], N * N, sheet, NULL, NULL, nt, six, s, s), 2);
    }
    assert_int_equal(sc[0]->vmask, RT_VMASK);
    assert_int_equal(sc[1]->vmask, UINT32_MAX);
    const uint32_t (*T)[3] = (const uint32_t (*)[3])sc[1]->mtri.p;
    const double *X = sc[1]->mv_xyz.p; /* the words are the vertices' offsets 3 v */
    for (size_t t = 0; t < nt; t++) /* both sheets: the given triangles, vertices in their roles */
        for (int k = 0; k < 3; k++) {
            assert_memory_equal(X + T[t][k], sheet + 3 * six[3 * t + k], 3 * sizeof(double));
            assert_memory_equal(X + T[nt + 2 + t][k], sheet + 3 * six[3 * t + k],
                                3 * sizeof(double));
        }
    for (int k = 0; k < 2; k++)
        assert_int_equal(rt_scene_commit(sc[k], NULL), RT_OK);
    for (int j = 0; j < 40; j++) /* the same answers, the tie included */
        for (int i = 0; i < 40; i++) {
            const rt_ray ray = {.org = {-7.0 + 0.35 * i, -7.0 + 0.35 * j, 5},
                                .dir = {0.01 * (i % 3), -0.01 * (j % 2), -1},
                                .tmin = 0,
                                .tmax = INFINITY};
            rt_hit h[2];
            for (int k = 0; k < 2; k++)
                assert_int_equal(rt_intersect(sc[k], 1, &ray, &h[k]), RT_OK);
            assert_int_equal(h[0].prim, h[1].prim);
            assert_memory_equal(&h[0].t, &h[1].t, sizeof h[0].t);
            assert_memory_equal(h[0].ng, h[1].ng, sizeof h[0].ng);
        }
    const rt_ray tie = {.org = {-1, -1, 5}, .dir = {0, 0, -1}, .tmin = 0, .tmax = INFINITY};
    for (int k = 0; k < 2; k++) {
        rt_hit h;
        assert_int_equal(rt_intersect(sc[k], 1, &tie, &h), RT_OK);
        assert_int_equal(h.prim, 1);
        assert_true(h.ng[2] == -1.0); /* the triangle given first faces down */
        rt_scene_free(sc[k]);
    }
}

/* A tilted sheet laid out in a rotated grid frame: the frame's box is that of the vertices the
 * triangles use, so vertices no triangle uses (one never named, three named only by a
 * degenerate triangle, which is dropped) leave the grid as it is, however far away they lie
 * (the frame choice reads a spatially ordered mesh's used vertices in place). */
static void test_unused_vertices_frame(void **state)
{
    (void)state;
    enum { M = 12, NX = 4 }; /* M x M sheet vertices, NX extra ones first */
    static double v[(NX + M * M) * 3];
    static uint32_t ix[(2 * (M - 1) * (M - 1) + 1) * 3];
    const double far[NX][3] = {{100, 100, 100}, {200, 200, 200}, {300, 300, 300}, {-50, 80, 20}};
    memcpy(v, far, sizeof far);
    const double ca = cos(0.5), sa = sin(0.5), cb = cos(0.3), sb = sin(0.3);
    for (int j = 0; j < M; j++)
        for (int i = 0; i < M; i++) {
            const double x = -3.0 + 0.5 * i, y = -3.0 + 0.5 * j, z = 0.05 * ((i * 7 + j * 3) % 5);
            const double y1 = ca * y - sa * z, z1 = sa * y + ca * z; /* tilted about x, then z */
            double *p = v + 3 * (NX + j * M + i);
            p[0] = cb * x - sb * y1;
            p[1] = sb * x + cb * y1;
            p[2] = z1;
        }
    size_t nt = 0;
    for (int j = 0; j + 1 < M; j++)
        for (int i = 0; i + 1 < M; i++) {
            const uint32_t a = (uint32_t)(NX + j * M + i), b = a + 1, c = a + M, d = c + 1;
            const uint32_t q[6] = {a, b, d, a, d, c};
            memcpy(ix + 3 * nt, q, sizeof q);
            nt += 2;
        }
    rt_grid_info gi[2];
    for (int k = 0; k < 2; k++) {
        int s;
        rt_scene *sc = rtu_scene_one_surface(&s);
        assert_non_null(sc);
        if (k == 0) { /* the sheet's vertices only */
            static uint32_t ix0[2 * (M - 1) * (M - 1) * 3];
            for (size_t e = 0; e < 3 * nt; e++)
                ix0[e] = ix[e] - NX;
            assert_int_equal(rt_scene_add_mesh(sc, M * M, v + 3 * NX, NULL, NULL, nt, ix0, s, s), 0);
        } else { /* the far ones too, the degenerate triangle among the others */
            static uint32_t ix1[(2 * (M - 1) * (M - 1) + 1) * 3];
            memcpy(ix1, ix, 3 * 40 * sizeof(uint32_t));
            const uint32_t deg[3] = {0, 1, 2}; /* three points on a line */
            memcpy(ix1 + 3 * 40, deg, sizeof deg);
            memcpy(ix1 + 3 * 41, ix + 3 * 40, 3 * (nt - 40) * sizeof(uint32_t));
            assert_int_equal(rt_scene_add_mesh(sc, NX + M * M, v, NULL, NULL, nt + 1, ix1, s, s), 0);
        }
        rt_build_options bo;
        memset(&bo, 0, sizeof bo);
        bo.brute_threshold = -1;
        assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
        assert_int_equal(rt_scene_grid_info(sc, &gi[k]), RT_OK);
        rt_scene_free(sc);
    }
    assert_int_equal(gi[0].rotated, 1); /* the case at hand: a rotated frame */
    assert_int_equal(gi[1].prims, gi[0].prims);
    assert_true(gi[1].hash == gi[0].hash);
}

/* Meshes keep no record per triangle: their committed triangles take their mesh's id and
 * surfaces (rt_prim_at). Five meshes of four triangles side by side (two unit squares each,
 * mesh k over x in [3k, 3k + 2]; mesh 3 transparent), a lone triangle before them and a
 * quad after them, whole and culled at x = 7.5 (meshes 0 and 1 wholly left out, mesh 2 half):
 * every committed primitive's record, the scene's bytes of triangle records, and the ids the
 * rays down onto each triangle hit, with the grid and by brute force, single and in packets. */
enum { NMESH = 5 };

static rt_scene *meshes_scene(int cull, int grid, int *mid)
{
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface su;
    rt_surface_default(&su);
    int s[NMESH];
    for (int k = 0; k < NMESH; k++) {
        su.transparency = k == 3 ? 0.5 : 0.0;
        s[k] = rt_scene_add_surface(sc, &su);
        assert_true(s[k] >= 0);
    }
    const int three = 3, four = 4;
    const double lone[9] = {15, 0, 0, 16, 0, 0, 15, 1, 0};
    assert_int_equal(rt_scene_add_polygon(sc, 1, &three, lone, s[0], s[0]), 0);
    for (int k = 0; k < NMESH; k++) {
        double v[6][3];
        for (int j = 0; j < 6; j++) { /* 0 1 2 along y = 0, 3 4 5 along y = 1 */
            v[j][0] = 3.0 * k + j % 3;
            v[j][1] = j / 3;
            v[j][2] = 0.0;
        }
        const uint32_t ix[12] = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
        mid[k] = rt_scene_add_mesh(sc, 6, &v[0][0], NULL, NULL, 4, ix, s[k], s[k]);
        assert_int_equal(mid[k], k + 1);
    }
    const double quad[12] = {18, 0, 0, 19, 0, 0, 19, 1, 0, 18, 1, 0};
    assert_int_equal(rt_scene_add_polygon(sc, 1, &four, quad, s[1], s[1]), NMESH + 1);
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = grid ? -1 : 1000;
    bo.threads = 2;
    if (cull) {
        bo.ncull = 1;
        bo.cull[0][0] = 1;
        bo.cull[0][3] = -7.5;
        bo.cull_eps = 1e-9;
    }
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    return sc;
}

static void test_mesh_records(void **state)
{
    (void)state;
    for (int c = 0; c < 4; c++) {
        const int cull = c & 1, grid = c >> 1;
        int mid[NMESH];
        rt_scene *sc = meshes_scene(cull, grid, mid);
        /* the kept triangles per mesh, in mesh order after the lone one */
        const size_t kept[NMESH] = {cull ? 0 : 4, cull ? 0 : 4, cull ? 2 : 4, 4, 4};
        size_t nmt = 0;
        for (int k = 0; k < NMESH; k++)
            nmt += kept[k];
        assert_int_equal(sc->ntri_plain, 1);
        assert_int_equal(sc->ntri, 1 + nmt);
        assert_int_equal(sc->nprim, 2 + nmt);
        size_t i = 1;
        for (int k = 0; k < NMESH; k++)
            for (size_t t = 0; t < kept[k]; t++, i++) {
                const rt_prim p = rt_prim_at(sc, i);
                assert_int_equal(p.id, mid[k]);
                assert_int_equal(p.kind, RT_KIND_TRI);
                assert_int_equal(p.data, i);
                assert_int_equal(p.opaque, k != 3);
                assert_int_equal(rt_prim_id(sc, i), mid[k]);
                assert_int_equal(rt_prim_opaque(sc, i), k != 3);
                assert_true(rt_prim_surf(sc, &p, 0)->transparency == (k == 3 ? 0.5 : 0.0));
            }
        assert_int_equal(rt_prim_at(sc, 0).id, 0);
        assert_int_equal(rt_prim_at(sc, i).id, NMESH + 1);
        assert_int_equal(rt_prim_at(sc, i).kind, RT_KIND_QUAD);
        assert_int_equal(rt_prim_geo(sc, i).kind, RT_KIND_QUAD);
        /* the records' bytes: the lone triangle's (record and vertices) and one per mesh */
        assert_int_equal(sc->tri_bytes, sizeof(rt_prim) + sizeof(rt_tri) + NMESH * sizeof(rt_cmesh) +
                                            nmt * 3 * sizeof(uint32_t) + NMESH * 6 * 3 * sizeof(double));
        /* rays down onto the centre of each triangle */
        rt_ray r[4 * NMESH + 2];
        int want[4 * NMESH + 2];
        int n = 0;
        for (int k = 0; k < NMESH; k++)
            for (int q = 0; q < 4; q++) {
                const double x = 3.0 * k + (q >= 2) + (q % 2 ? 0.3 : 0.7), y = q % 2 ? 0.7 : 0.3;
                r[n] = (rt_ray){.org = {x, y, 5}, .dir = {0, 0, -1}, .tmin = 0, .tmax = INFINITY};
                want[n++] = cull && (k < 2 || (k == 2 && q < 2)) ? -1 : mid[k];
            }
        r[n] = (rt_ray){.org = {15.3, 0.3, 5}, .dir = {0, 0, -1}, .tmin = 0, .tmax = INFINITY};
        want[n++] = 0;
        r[n] = (rt_ray){.org = {18.5, 0.5, 5}, .dir = {0, 0, -1}, .tmin = 0, .tmax = INFINITY};
        want[n++] = NMESH + 1;
        rt_hit h[4 * NMESH + 2], hp[4 * NMESH + 2];
        assert_int_equal(rt_intersect(sc, (size_t)n, r, h), RT_OK);
        assert_int_equal(rt_intersect_packet(sc, (size_t)n, r, hp), RT_OK);
        for (int k = 0; k < n; k++) {
            assert_int_equal(h[k].prim, want[k]);
            assert_int_equal(hp[k].prim, want[k]);
        }
        rt_scene_free(sc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_occluded_mesh_only),
        cmocka_unit_test(test_occluded_flat),
        cmocka_unit_test(test_intersect_flat),
        cmocka_unit_test(test_intersect_mesh_only),
        cmocka_unit_test(test_same_picture),
        cmocka_unit_test(test_same_picture_culled),
        cmocka_unit_test(test_same_picture_unshared),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_bad_vertices_dropped),
        cmocka_unit_test(test_tie_given_first),
        cmocka_unit_test(test_given_order_back),
        cmocka_unit_test(test_unused_vertices_frame),
        cmocka_unit_test(test_mesh_records),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
