/* SPDX-License-Identifier: MIT */
/*
 * test_rt_packet.c -- the coherent path (src/rt/rt_packet.c) against the single-ray path:
 * rt_intersect_packet must return rt_intersect's hits bit for bit (primitive, t, side, point,
 * normal) and rt_occluded_packet rt_occluded's answers, on
 *  - the test meshes (tests/data/meshes; every triangle its own primitive id, so rays through
 *    shared edges and vertices meet ties between ids) seen from random cameras, in 8 x 8
 *    blocks of pixel rays at pitches from a tiny fraction of a grid cell to diverging, and
 *    in packets of rays aimed exactly at neighbouring vertices and edge midpoints;
 *  - coplanar and overlapping areas (the tie rule decides), a box resting on a floor, with
 *    shadow rays to a point light;
 *  - rays that cannot form a packet (zero direction components, NaN, mixed octants);
 *  - packets beside the grid box (most of a frame around a mesh), and looking away from it.
 * Each check counts its rays and the rays whose answers differ (required 0), and that the
 * packet path was taken (packets traced as packets > 0): a test that could not fail if the
 * packet path were never used would prove nothing.
 */
#define GKS3D_RT_BUILDING 1
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_check.h"
#include "rt_internal.h"
#include "rt_packet.h"
#include "rt_testutil.h"

typedef struct tally {
    size_t rays, hits, differ, shadow, occluded, sdiffer;
    rt_packet_stats ps;
} tally;

/* traces rays both ways (nearest hit, then shadow rays from the hits toward light) and counts */
static void compare(const rt_scene *sc, size_t n, const rt_ray *rays, const double light[3],
                    tally *ta)
{
    rt_hit *h1 = malloc(n * sizeof *h1), *h2 = malloc(n * sizeof *h2);
    rt_ray *sr = malloc(n * sizeof *sr);
    unsigned char *o1 = malloc(n), *o2 = malloc(n);
    assert_true(h1 && h2 && sr && o1 && o2);
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, n, rays, h1), RT_OK);
    assert_int_equal(rt_intersect_packet_stats(sc, n, rays, h2, &ta->ps), RT_OK);
    rtc_traps_off();
    size_t ns = 0;
    for (size_t k = 0; k < n; k++) {
        ta->rays++;
        ta->hits += h1[k].prim >= 0;
        if (!rtu_same_hit(&h1[k], &h2[k])) {
            if (ta->differ < 5)
                printf("  ray %zu differs: prim %d t %.17g vs prim %d t %.17g\n", k, h1[k].prim,
                       h1[k].t, h2[k].prim, h2[k].t);
            ta->differ++;
        }
        if (h1[k].prim < 0 || !light)
            continue;
        /* shadow ray: from the hit, moved off the surface toward the light's side, to it */
        const double sg = h1[k].side ? -1.0 : 1.0;
        rt_ray *r = &sr[ns++];
        for (int i = 0; i < 3; i++) {
            r->org[i] = h1[k].p[i] + sg * 1e-9 * h1[k].ng[i];
            r->dir[i] = light[i] - r->org[i];
        }
        r->tmin = 0.0;
        r->tmax = 1.0 - 1e-9;
    }
    rtc_traps_on();
    assert_int_equal(rt_occluded(sc, ns, sr, o1), RT_OK);
    assert_int_equal(rt_occluded_packet_stats(sc, ns, sr, o2, &ta->ps), RT_OK);
    rtc_traps_off();
    for (size_t k = 0; k < ns; k++) {
        ta->shadow++;
        ta->occluded += o1[k];
        ta->sdiffer += o1[k] != o2[k];
    }
    free(h1);
    free(h2);
    free(sr);
    free(o1);
    free(o2);
}

static void report(const char *what, const tally *ta)
{
    printf("%s: %zu rays (%zu hit), %zu differ; %zu shadow rays (%zu occluded), %zu differ; "
           "packets %llu traced (%llu beside the grid box), %llu to the single-ray path, %llu "
           "rays re-traced\n",
           what, ta->rays, ta->hits, ta->differ, ta->shadow, ta->occluded, ta->sdiffer,
           (unsigned long long)ta->ps.packets, (unsigned long long)ta->ps.beside,
           (unsigned long long)ta->ps.fallback_packets, (unsigned long long)ta->ps.fallback_rays);
    assert_int_equal(ta->differ, 0);
    assert_int_equal(ta->sdiffer, 0);
    assert_true(ta->ps.packets > 0);
    /* the rays' records the packet path writes itself are rt_rayx_setup's, byte for byte
       (checked in builds without NDEBUG, such as the tests') */
    assert_int_equal(rt_packet_make_differ(), 0);
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static void unit(double v[3])
{
    const double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++)
        v[i] /= l;
}

/* W x H pinhole rays (W, H multiples of 8) from eye toward at, pixel pitch pitch (radians),
   in 8 x 8 blocks (one packet each), row by row within a block */
static void camera_rays(const double eye[3], const double at[3], double pitch, int W, int H,
                        double tmax, rt_ray *out)
{
    double f[3] = {at[0] - eye[0], at[1] - eye[1], at[2] - eye[2]}, u[3], v[3];
    const double up[3] = {0.3, 1.0, 0.2};
    unit(f);
    cross(f, up, u);
    unit(u);
    cross(u, f, v);
    size_t k = 0;
    for (int by = 0; by < H; by += 8)
        for (int bx = 0; bx < W; bx += 8)
            for (int j = 0; j < 64; j++) {
                const double x = (bx + j % 8 - W / 2 + 0.5) * pitch;
                const double y = (by + j / 8 - H / 2 + 0.5) * pitch;
                rt_ray *r = &out[k++];
                for (int i = 0; i < 3; i++) {
                    r->org[i] = eye[i];
                    r->dir[i] = f[i] + x * u[i] + y * v[i];
                }
                r->tmin = 0.0;
                r->tmax = tmax;
            }
}

/* a random point in the box bb grown by g times its size around its centre */
static void box_point(const double bb[6], double g, uint64_t *rng, double p[3])
{
    for (int i = 0; i < 3; i++) {
        const double c = 0.5 * (bb[i] + bb[3 + i]), h = 0.5 * (bb[3 + i] - bb[i]) * g;
        p[i] = c + h * (2.0 * rtu_rand(rng) - 1.0);
    }
}

/* the mesh of the OFF file path (into *m) committed as a scene of its own, with its box bb
   and the box's diagonal *diag */
static rt_scene *mesh_scene(const char *path, rtu_mesh *m, double bb[6], double *diag)
{
    assert_int_equal(rtu_load_off(path, m), 0);
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    assert_int_equal(rtu_mesh_add(m, sc, rt_scene_add_surface(sc, &s)), 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtu_mesh_bbox(m, bb);
    *diag = sqrt((bb[3] - bb[0]) * (bb[3] - bb[0]) + (bb[4] - bb[1]) * (bb[4] - bb[1]) +
                 (bb[5] - bb[2]) * (bb[5] - bb[2]));
    return sc;
}

static void mesh_case(const char *path, int ncam)
{
    rtu_mesh m;
    double bb[6], diag;
    rt_scene *sc = mesh_scene(path, &m, bb, &diag);
    enum { W = 32, H = 32 };
    rt_ray *rays = malloc((size_t)W * H * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 12345;
    tally ta = {0};
    for (int c = 0; c < ncam; c++) {
        /* eye outside (mostly) or inside the box; pitch from 1e-5 to 0.05 rad */
        double eye[3], at[3], light[3];
        box_point(bb, c % 5 == 4 ? 0.8 : 3.0, &rng, eye);
        box_point(bb, 0.5, &rng, at);
        box_point(bb, 2.5, &rng, light);
        const double pitch = 1e-5 * pow(5000.0, rtu_rand(&rng));
        const double tmax = c % 7 == 3 ? 0.6 * diag : INFINITY;
        camera_rays(eye, at, pitch, W, H, tmax, rays);
        compare(sc, (size_t)W * H, rays, light, &ta);
    }
    /* packets of rays aimed exactly at 16 consecutive vertices (neighbours in the file) and
       at the midpoints of the edges of 16 consecutive faces: hits on shared edges and
       vertices, where triangles of different ids tie */
    size_t nv = (size_t)m.nv < 4096 ? (size_t)m.nv : 4096;
    rt_ray *aim = malloc(nv * sizeof *aim);
    assert_non_null(aim);
    for (int c = 0; c < 4; c++) {
        double eye[3];
        box_point(bb, 2.5, &rng, eye);
        const size_t v0 = (size_t)(rtu_rand(&rng) * (double)(m.nv - (int)nv));
        for (size_t k = 0; k < nv; k++) {
            const double *p = &m.xyz[3 * (v0 + k)];
            for (int i = 0; i < 3; i++) {
                aim[k].org[i] = eye[i];
                aim[k].dir[i] = p[i] - eye[i];
            }
            aim[k].tmin = 0.0;
            aim[k].tmax = INFINITY;
        }
        compare(sc, nv, aim, NULL, &ta);
        size_t ne = 0;
        for (size_t f = 0; f + 1 < (size_t)m.np && ne + 3 <= nv; f++) {
            const int *ix = &m.idx[3 * f];
            for (int e = 0; e < 3; e++) {
                const double *a = &m.xyz[3 * ix[e]], *b = &m.xyz[3 * ix[(e + 1) % 3]];
                for (int i = 0; i < 3; i++) {
                    aim[ne].org[i] = eye[i];
                    aim[ne].dir[i] = 0.5 * a[i] + 0.5 * b[i] - eye[i];
                }
                aim[ne].tmin = 0.0;
                aim[ne].tmax = INFINITY;
                ne++;
            }
        }
        compare(sc, ne, aim, NULL, &ta);
    }
    report(path, &ta);
    free(aim);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

/* packets beside the grid box (rt_pk_beside, tried after a packet without a ray in the box):
   cameras whose frame holds the mesh with much room around it, so that most packets lie
   beside the box, many of them next to its outline (the bounds' margins are far below a
   pixel: a packet a pixel off the box is still judged by them), and cameras looking away
   from it (the box behind the rays); on a rotated grid (fandisk) and one in VRC3 (bunny).
   With the AVX2 and AVX-512 kernels packets must have been found beside the box. */
static void beside_case(const char *path)
{
    rtu_mesh m;
    double bb[6], diag, mid[3];
    rt_scene *sc = mesh_scene(path, &m, bb, &diag);
    for (int i = 0; i < 3; i++)
        mid[i] = 0.5 * (bb[i] + bb[3 + i]);
    enum { W = 96, H = 96 };
    rt_ray *rays = malloc((size_t)W * H * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 777;
    tally ta = {0};
    for (int c = 0; c < 12; c++) {
        double eye[3], at[3];
        box_point(bb, 4.0, &rng, eye);
        const double dist = sqrt((eye[0] - mid[0]) * (eye[0] - mid[0]) +
                                 (eye[1] - mid[1]) * (eye[1] - mid[1]) +
                                 (eye[2] - mid[2]) * (eye[2] - mid[2]));
        for (int i = 0; i < 3; i++) /* toward the mesh, or away from it (c % 4 == 3) */
            at[i] = c % 4 == 3 ? 2.0 * eye[i] - mid[i] : mid[i];
        /* the mesh's diagonal over two thirds to a third of the frame */
        const double pitch = diag / dist / (double)W * (1.5 + 1.5 * rtu_rand(&rng));
        camera_rays(eye, at, pitch, W, H, INFINITY, rays);
        compare(sc, (size_t)W * H, rays, NULL, &ta);
    }
    report(path, &ta);
    const char *k = rt_packet_kernel_name();
    if (!strcmp(k, "avx2") || !strcmp(k, "avx512"))
        assert_true(ta.ps.beside > 0);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

static void test_beside(void **state)
{
    (void)state;
    beside_case(RT_DATA_DIR "/meshes/fandisk_large.off.gz");
    beside_case(RT_DATA_DIR "/meshes/bunny00.off.gz");
}

static void test_meshes(void **state)
{
    (void)state;
    mesh_case(RT_DATA_DIR "/meshes/bunny00.off.gz", 40);
    mesh_case(RT_DATA_DIR "/meshes/armadillo.off.gz", 25);
    mesh_case(RT_DATA_DIR "/meshes/fandisk_large.off.gz", 25);
}

/* the coplanar scene's rotation (identity, or oblique: then the grid is laid out in a
   rotated frame) applied to n points */
static double rot[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
static void xf(double *v, int n)
{
    for (int k = 0; k < n; k++) {
        const double p[3] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
        for (int a = 0; a < 3; a++)
            v[3 * k + a] = rot[a][0] * p[0] + rot[a][1] * p[1] + rot[a][2] * p[2];
    }
}

/* an axis-aligned rectangle [x0,x1] x [y0,y1] at height z (counter-clockwise from +z) */
static int add_rect(rt_scene *sc, double x0, double y0, double x1, double y1, double z, int s)
{
    double v[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
    const int n = 4;
    xf(v, 4);
    return rt_scene_add_polygon(sc, 1, &n, v, s, s);
}

/* a box [x0,x1] x [y0,y1] x [z0,z1] as 12 triangles */
static void add_box(rt_scene *sc, const double lo[3], const double hi[3], int s)
{
    static const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int q = 0; q < 6; q++)
        for (int t = 0; t < 2; t++) {
            double v[9];
            const int c[3] = {f[q][0], f[q][1 + t], f[q][2 + t]};
            for (int j = 0; j < 3; j++)
                for (int a = 0; a < 3; a++)
                    v[3 * j + a] = (c[j] >> a) & 1 ? hi[a] : lo[a];
            const int n = 3;
            xf(v, 3);
            assert_true(rt_scene_add_polygon(sc, 1, &n, v, s, s) >= 0);
        }
}

/* coplanar and overlapping areas: a floor of 20 x 20 tiles, overlapping coplanar rectangles
   of later ids, triangles sharing the floor's plane, and boxes resting on the floor (their
   bottoms coplanar with it), traced from random cameras with shadow rays; as it is, and
   turned obliquely (rotated != 0: the grid in a rotated frame) */
static void coplanar_case(int rotated)
{
    if (rotated) { /* 35 degrees about x, then 50 about z */
        const double a = 35.0 * 3.14159265358979 / 180.0, b = 50.0 * 3.14159265358979 / 180.0;
        const double r[3][3] = {{cos(b), -sin(b) * cos(a), sin(b) * sin(a)},
                                {sin(b), cos(b) * cos(a), -cos(b) * sin(a)},
                                {0.0, sin(a), cos(a)}};
        memcpy(rot, r, sizeof rot);
    }
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    const int si = rt_scene_add_surface(sc, &s);
    for (int i = 0; i < 20; i++)
        for (int j = 0; j < 20; j++)
            assert_true(add_rect(sc, i, j, i + 1, j + 1, 0.0, si) >= 0);
    uint64_t rng = 777;
    for (int k = 0; k < 60; k++) { /* overlapping coplanar rectangles at z = 0 and z = 1 */
        const double x = 18.0 * rtu_rand(&rng), y = 18.0 * rtu_rand(&rng);
        const double w = 0.5 + 3.0 * rtu_rand(&rng), h = 0.5 + 3.0 * rtu_rand(&rng);
        assert_true(add_rect(sc, x, y, x + w, y + h, k % 2 ? 1.0 : 0.0, si) >= 0);
    }
    for (int k = 0; k < 30; k++) {
        const double lo[3] = {18.0 * rtu_rand(&rng), 18.0 * rtu_rand(&rng), 0.0};
        const double hi[3] = {lo[0] + 0.3 + 2.0 * rtu_rand(&rng), lo[1] + 0.3 + 2.0 * rtu_rand(&rng),
                              0.2 + 2.0 * rtu_rand(&rng)};
        add_box(sc, lo, hi, si);
    }
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_int_equal(gi.rotated, rotated);
    const double bb[6] = {0, 0, 0, 20, 20, 3};
    enum { W = 32, H = 32 };
    rt_ray *rays = malloc((size_t)W * H * sizeof *rays);
    assert_non_null(rays);
    tally ta = {0};
    for (int c = 0; c < 60; c++) {
        double eye[3], at[3], light[3];
        box_point(bb, 1.5, &rng, eye);
        eye[2] = 0.5 + 30.0 * rtu_rand(&rng) * rtu_rand(&rng); /* also grazing the floor */
        box_point(bb, 0.8, &rng, at);
        at[2] = 0.0;
        box_point(bb, 1.0, &rng, light);
        light[2] = 10.0;
        xf(eye, 1);
        xf(at, 1);
        xf(light, 1);
        camera_rays(eye, at, 1e-4 * pow(500.0, rtu_rand(&rng)), W, H, INFINITY, rays);
        compare(sc, (size_t)W * H, rays, light, &ta);
    }
    report(rotated ? "coplanar, rotated grid" : "coplanar", &ta);
    free(rays);
    rt_scene_free(sc);
    const double id[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memcpy(rot, id, sizeof rot);
}

static void test_coplanar(void **state)
{
    (void)state;
    coplanar_case(0);
    coplanar_case(1);
}

/* rays that cannot form a packet: zero direction components, NaN, opposite octants in one
   packet, a packet of fewer than RT_PACKET rays, empty batches and bad arguments */
static void test_incoherent(void **state)
{
    (void)state;
    int si;
    rt_scene *sc = rtu_scene_one_surface(&si);
    assert_non_null(sc);
    const double c[3] = {0, 0, 0};
    assert_int_equal(rtu_add_sphere(sc, c, 1.0, 48, 24, si), 0);
    rt_hit h;
    rt_ray r0 = {{0, 0, 5}, {0, 0, -1}, 0, INFINITY};
    assert_int_equal(rt_intersect_packet(sc, 1, &r0, &h), RT_ERR_STATE);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_int_equal(rt_intersect_packet(NULL, 1, &r0, &h), RT_ERR_ARG);
    assert_int_equal(rt_intersect_packet(sc, 1, NULL, &h), RT_ERR_ARG);
    assert_int_equal(rt_occluded_packet(sc, 1, &r0, NULL), RT_ERR_ARG);
    assert_int_equal(rt_intersect_packet(sc, 0, NULL, NULL), RT_OK);
    enum { N = RT_PACKET * 12 + 7 };
    rt_ray *rays = malloc(N * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 99;
    double e[3] = {0.0, 0.0, 5.0};
    for (int k = 0; k < N; k++) {
        rt_ray *r = &rays[k];
        if (k % RT_PACKET == 0) { /* each packet from its own eye */
            e[0] = 4.0 * rtu_rand(&rng) - 2.0;
            e[1] = 4.0 * rtu_rand(&rng) - 2.0;
        }
        memcpy(r->org, e, sizeof e);
        r->dir[0] = 0.5 - e[0] + 0.02 * (rtu_rand(&rng) - 0.5);
        r->dir[1] = 0.5 - e[1] + 0.02 * (rtu_rand(&rng) - 0.5);
        r->dir[2] = -5.0;
        r->tmin = 0.0;
        r->tmax = INFINITY;
        const int kind = (k / RT_PACKET) % 6;
        if (kind == 1 && k % RT_PACKET == 3)
            r->dir[0] = 0.0;                /* a zero component */
        if (kind == 2 && k % RT_PACKET == 5)
            r->dir[1] = NAN;                /* an unusable ray: a miss */
        if (kind == 3 && k % RT_PACKET == 7)
            r->dir[2] = 5.0, r->org[2] = -5.0; /* the other octant */
        if (kind == 4)
            rtu_rand_dir(&rng, r->dir);     /* random directions */
    }
    tally ta = {0};
    compare(sc, N, rays, (const double[3]){3.0, 4.0, 5.0}, &ta);
    report("incoherent", &ta);
    assert_true(ta.ps.fallback_packets > 0);
    free(rays);
    rt_scene_free(sc);
}

/* 64 shadow rays from the points org[k] (just outside a sphere) to light, tmin 0, tmax 1:
   the packet path answers as rt_occluded does, as one packet traced (single 0) or handed
   whole to the single-ray walk (single 1) */
/* the shadow rays from the points org to the light: segments ending at it */
static void shadow_rays(const double light[3], const double org[RT_PACKET][3],
                        rt_ray rays[RT_PACKET])
{
    for (int k = 0; k < RT_PACKET; k++) {
        for (int i = 0; i < 3; i++) {
            rays[k].org[i] = org[k][i];
            rays[k].dir[i] = light[i] - org[k][i];
        }
        rays[k].tmin = 0.0;
        rays[k].tmax = 1.0;
    }
}

/* a scene of one surface (*si) holding the unit sphere at the origin in slices x stacks
   triangles, not committed */
static rt_scene *sphere_scene(int slices, int stacks, int *si)
{
    rt_scene *sc = rtu_scene_one_surface(si);
    assert_non_null(sc);
    const double c[3] = {0, 0, 0};
    assert_int_equal(rtu_add_sphere(sc, c, 1.0, slices, stacks, *si), 0);
    return sc;
}

static void check_shadow_patch(rt_scene *sc, const double light[3],
                               const double org[RT_PACKET][3], int single, const char *what)
{
    rt_ray rays[RT_PACKET];
    unsigned char o1[RT_PACKET], o2[RT_PACKET];
    shadow_rays(light, org, rays);
    rt_packet_stats ps = {0};
    rtc_traps_on();
    assert_int_equal(rt_occluded(sc, RT_PACKET, rays, o1), RT_OK);
    assert_int_equal(rt_occluded_packet_stats(sc, RT_PACKET, rays, o2, &ps), RT_OK);
    rtc_traps_off();
    printf("%s: %llu packets traced, %llu to the single-ray path\n", what,
           (unsigned long long)ps.packets, (unsigned long long)ps.fallback_packets);
    assert_memory_equal(o1, o2, RT_PACKET);
    assert_int_equal(ps.packets, single ? 0 : 1);
    assert_int_equal(ps.fallback_packets, single ? 1 : 0);
}

/* shadow packets by the spread of their origins against the grid's cells there: 64 shadow
   rays from a small patch of a finely tessellated sphere are traced as a packet; 64 from
   points along a line across many second-level cells (yet few top cells), and 64 from a
   square patch narrower than the width limit but of more cells than the area limit (traced
   as a packet without that limit: checked), are handed to the single-ray walk (their
   packet's tests would cost more than their single walks); the answers are rt_occluded's
   either way */
static void test_spread(void **state)
{
    (void)state;
    int si;
    rt_scene *sc = sphere_scene(256, 128, &si);
    const double light[3] = {5.0, 6.0, 100.0};
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    printf("spread: grid %llu cells, %llu sub-grids of %llu cells\n",
           (unsigned long long)gi.cells, (unsigned long long)gi.subgrids,
           (unsigned long long)gi.subcells);
    static const char *const name[3] = {"spread: small patch", "spread: wide patch",
                                        "spread: square patch"};
    for (int wide = 0; wide < 3; wide++) {
        /* the square's spacing 0.015: about 9 second-level cells across, below the width
           limit, above the area limit (without that limit 0.018 stays a packet) */
        const double sq = wide == 2 ? 0.015 : 0.001;
        double org[RT_PACKET][3];
        for (int k = 0; k < RT_PACKET; k++) { /* just outside the sphere near its top */
            const double x = wide == 1 ? 0.2 + 0.005 * k : 0.3 + sq * (k % 8);
            const double y = wide == 1 ? 0.3 : 0.3 + sq * (k / 8);
            org[k][0] = x, org[k][1] = y, org[k][2] = sqrt(1.0 - x * x - y * y) + 1e-6;
        }
        check_shadow_patch(sc, light, org, wide != 0, name[wide]);
    }
    rt_scene_free(sc);
}

/* shadow packets on a coarse mesh, whose top cells have no second-level grids: 64 shadow
   rays from a small patch are traced as a packet; 64 from a patch whose frustum at the
   start covers 3 or more top cells (a few cells wide, far below the limits counted in
   second-level cells) are handed to the single-ray walk (traced as a packet without that
   limit: checked); the answers are rt_occluded's either way */
static void test_spread_top(void **state)
{
    (void)state;
    int si;
    rt_scene *sc = sphere_scene(48, 24, &si);
    const double light[3] = {5.0, 6.0, 100.0};
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    printf("spread_top: grid %llu cells, %llu sub-grids\n", (unsigned long long)gi.cells,
           (unsigned long long)gi.subgrids);
    assert_int_equal(gi.subgrids, 0);
    for (int wide = 0; wide < 2; wide++) {
        /* the wide patch's spacing 0.014, about 1.3 top cells across (without the top
           cells' area limit it stays a packet: checked) */
        const double sq = wide ? 0.014 : 0.002;
        double org[RT_PACKET][3];
        for (int k = 0; k < RT_PACKET; k++) { /* just outside the sphere near its top */
            const double x = 0.05 + sq * (k % 8), y = 0.05 + sq * (k / 8);
            org[k][0] = x, org[k][1] = y, org[k][2] = sqrt(1.0 - x * x - y * y) + 1e-3;
        }
        check_shadow_patch(sc, light, org, wide, wide ? "spread_top: wide patch"
                                                      : "spread_top: small patch");
    }
    rt_scene_free(sc);
}

/* an any-hit packet tests a primitive for all its rays still walking, those that start
   beyond it too: 64 shadow rays toward a light above, from points at 8 heights over a finely
   tessellated sphere (second-level grids), under a square at a height between them. The rays
   that start below the square are occluded, those above it are not (the square lies behind
   their origins, where the packet tests it for them too); one packet is traced and answers
   as rt_occluded does, with both kinds of rays in it */
static void test_shadow_depths(void **state)
{
    (void)state;
    int si;
    rt_scene *sc = sphere_scene(256, 128, &si);
    const double light[3] = {0.4, 0.45, 40.0};
    /* the square at z = 1.04 over the patch, and a triangle far aside at z = 1.2 that
       takes the grid box above the rays' origins */
    const double v[7 * 3] = {0.2,  0.2,  1.04, 0.5,  0.2,  1.04, 0.5, 0.5, 1.04, 0.2, 0.5, 1.04,
                             -0.9, -0.9, 1.2,  -0.8, -0.9, 1.2,  -0.9, -0.8, 1.2};
    const uint32_t idx[3 * 3] = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    assert_true(rt_scene_add_mesh(sc, 7, v, NULL, NULL, 3, idx, si, si) >= 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    double org[RT_PACKET][3];
    for (int k = 0; k < RT_PACKET; k++) { /* row k / 8 at 1.005 + 0.01 (k / 8): 4 below */
        org[k][0] = 0.3 + 0.002 * (k % 8);
        org[k][1] = 0.3 + 0.002 * (k / 8);
        org[k][2] = 1.005 + 0.01 * (k / 8);
    }
    rt_ray rays[RT_PACKET];
    unsigned char o[RT_PACKET];
    shadow_rays(light, org, rays);
    assert_int_equal(rt_occluded(sc, RT_PACKET, rays, o), RT_OK);
    int n = 0;
    for (int k = 0; k < RT_PACKET; k++) {
        assert_int_equal(o[k], k / 8 < 4); /* under the square: occluded */
        n += o[k];
    }
    assert_int_equal(n, 32);
    check_shadow_patch(sc, light, org, 0, "shadow_depths");
    rt_scene_free(sc);
}

/* the renderer's eye rays in packets (rt_render.c: one-ray modes without candidate lists,
   i.e. more than 16 candidates per ray on average): the same picture, bit for bit, as every
   eye ray alone (GKS_RT_PACKETS=0), with corner rays and pixel-centre rays, and the packet
   path taken */
static void test_render(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    s.refl_eq = RT_REFL_SPECULAR;
    s.ks = 0.3;
    s.transparency = 0.0;
    const int si = rt_scene_add_surface(sc, &s);
    s.transparency = 0.4;
    s.refr_index = 1.3;
    const int st = rt_scene_add_surface(sc, &s);
    uint64_t rng = 5;
    for (int k = 0; k < 40; k++) { /* 40 layers of tilted triangles over the whole view */
        const double z = -1.0 - 0.1 * k, a = 0.3 * (rtu_rand(&rng) - 0.5);
        const double v[9] = {-4, -4, z - a, 4, -4, z + a, 0, 5, z};
        const int n = 3;
        assert_true(rt_scene_add_polygon(sc, 1, &n, v, k % 3 ? si : st, si) >= 0);
    }
    const double c[3] = {0.3, -0.2, -0.6};
    assert_int_equal(rtu_add_sphere(sc, c, 0.3, 32, 16, si), 0);
    rt_light l = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .position = {1, 2, 2}, .c1 = 1};
    assert_true(rt_scene_add_light(sc, &l) >= 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtu_view v = {.win = {-1, 1, -1, 1}, .prp = {0, 0, 4}, .vpd = 0, .bpd = -6, .fpd = 0.9,
                  .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    double vm[4][4];
    rtu_view_matrix(&v, vm);
    rt_camera cam;
    const double box[6] = {0, 1, 0, 1, 0, 1};
    assert_int_equal(rt_camera_from_view(&cam, vm, box, 61, 47), RT_OK);
    const size_t np = 61 * 47 * 3;
    float *a = malloc(np * sizeof *a), *b = malloc(np * sizeof *b);
    assert_true(a && b);
    for (int corner = 0; corner < 2; corner++) {
        rt_render_options o;
        rt_render_options_default(&o);
        o.corner_rays = corner;
        o.threads = 2;
        const unsigned long long before = rt_packet_count();
        assert_int_equal(rt_render(sc, &cam, &o, a, NULL), RT_OK);
        const unsigned long long used = rt_packet_count() - before;
        setenv("GKS_RT_PACKETS", "0", 1);
        assert_int_equal(rt_render(sc, &cam, &o, b, NULL), RT_OK);
        unsetenv("GKS_RT_PACKETS");
        const int same = !memcmp(a, b, np * sizeof *a);
        printf("render (corner rays %d): %llu packets, pictures %s\n", corner, used,
               same ? "identical" : "DIFFER");
        assert_true(used > 0);
        assert_true(same);
    }
    free(a);
    free(b);
    rt_scene_free(sc);
}

int main(void)
{
    printf("packet kernel: %s\n", rt_packet_kernel_name());
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_incoherent),
        cmocka_unit_test(test_spread),
        cmocka_unit_test(test_spread_top),
        cmocka_unit_test(test_shadow_depths),
        cmocka_unit_test(test_coplanar),
        cmocka_unit_test(test_render),
        cmocka_unit_test(test_meshes),
        cmocka_unit_test(test_beside),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
