/* SPDX-License-Identifier: MIT */
/*
 * test_rt_hard.c -- numerical stability of the gksrt ray tracer on hard cases (issue
 * "Numerical stability: hard cases", items 1-10). Each test counts what it checks and asserts
 * the count (misses, self-hits, mismatches, non-finite pixels: required 0):
 *  1 closed-mesh leak probe (tests/data/meshes/ OFF files: rays at every vertex, every edge
 *    midpoint, plus random directions; the full 10^6 random rays: bench/rt/rt_leak),
 *  2 shared diagonal at offsets 0, 1e3, 1e6,  3 re-intersection at scales 1e-3..1e6 and the
 *    89/89.9/89.99 degree shadow-acne sweep (also translated by 1e6),  4 axis-aligned box room
 *    on grid-cell boundaries with +-0 direction components: grid == brute force bit for bit
 *    (also the rotated grid frame, on SPD gears seen obliquely),
 *  5 coplanar/overlapping polygons (also through random rotations: the later area wins),
 *  6 concave, self-intersecting, repeated-vertex, collinear,
 *    non-planar polygons and the 144-vertex polygons of SPD gears,  7 teapot in a stadium
 *    (grid statistics),  8 dielectrics (TIR, nested media by relative indices, index 1),
 *  9 near-singular viewing input,  10 NaN/Inf in primitives, rays and matrices.
 * Floating-point traps (invalid, division by zero) are on while tracing where IEEE
 * infinities are not intended.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gksrt.h"
#include "rt_check.h"
#include "rt_testutil.h"

#define PI 3.14159265358979323846

/* ---- helpers ---- */

static int surf_plain(rt_scene *sc)
{
    rt_surface s;
    rt_surface_default(&s);
    return rt_scene_add_surface(sc, &s);
}

static int surf_flat(rt_scene *sc, double r, double g, double b)
{
    rt_surface s;
    rt_surface_default(&s);
    s.refl_eq = RT_REFL_NONE;
    s.diffuse[0] = r;
    s.diffuse[1] = g;
    s.diffuse[2] = b;
    return rt_scene_add_surface(sc, &s);
}

static void ray_set(rt_ray *r, const double o[3], const double d[3])
{
    memcpy(r->org, o, sizeof r->org);
    memcpy(r->dir, d, sizeof r->dir);
    r->tmin = 0.0;
    r->tmax = INFINITY;
}

static int add_poly(rt_scene *sc, int n, const double *v, int s)
{
    return rt_scene_add_polygon(sc, 1, &n, v, s, s);
}

static int add_tri(rt_scene *sc, const double a[3], const double b[3], const double c[3], int s)
{
    double v[9];
    memcpy(v, a, 3 * sizeof(double));
    memcpy(v + 3, b, 3 * sizeof(double));
    memcpy(v + 6, c, 3 * sizeof(double));
    return add_poly(sc, 3, v, s);
}

/* axis-aligned rectangle [x0,x1]x[y0,y1] at z; up: counter-clockwise seen from +z */
static int add_rect_z(rt_scene *sc, double x0, double y0, double x1, double y1, double z, int up, int s)
{
    double v[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
    if (!up) {
        double t[3];
        memcpy(t, v + 3, sizeof t);
        memcpy(v + 3, v + 9, sizeof t);
        memcpy(v + 9, t, sizeof t);
    }
    return add_poly(sc, 4, v, s);
}

/* intersects the rays with sc committed as grid (opts) and as brute force: mismatches */
static size_t grid_vs_brute(rt_scene *sc, const rt_build_options *opts, const rt_ray *rays, size_t n,
                            size_t *nhit)
{
    rt_hit *hg = calloc(n, sizeof *hg), *hb = calloc(n, sizeof *hb);
    unsigned char *og = calloc(n, 1), *ob = calloc(n, 1);
    assert_non_null(hg);
    assert_non_null(hb);
    assert_non_null(og);
    assert_non_null(ob);
    rt_build_options bo = {.brute_force = 1};
    assert_int_equal(rt_scene_commit(sc, opts), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_true(gi.cells > 0); /* the grid is really used */
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, n, rays, hg), RT_OK);
    assert_int_equal(rt_occluded(sc, n, rays, og), RT_OK);
    rtc_traps_off();
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, n, rays, hb), RT_OK);
    assert_int_equal(rt_occluded(sc, n, rays, ob), RT_OK);
    rtc_traps_off();
    size_t bad = 0, hits = 0;
    for (size_t k = 0; k < n; k++) {
        bad += !rtu_same_hit(&hg[k], &hb[k]) || og[k] != ob[k];
        hits += hg[k].prim >= 0;
    }
    if (nhit)
        *nhit = hits;
    free(hg);
    free(hb);
    free(og);
    free(ob);
    return bad;
}

static void render_checked(const rt_scene *sc, const rt_camera *cam, const rt_render_options *o,
                           float *rgb, rt_stats *st)
{
    rt_render_options plain;
    if (!o) { /* the tests' defaults: pixel-centre rays, no cut-off */
        rtu_options_plain(&plain);
        o = &plain;
    }
    rtc_traps_on();
    assert_int_equal(rt_render(sc, cam, o, rgb, st), RT_OK);
    rtc_traps_off();
    /* every render: non-finite pixels, required 0 */
    assert_int_equal(rtc_nonfinite(rgb, (size_t)cam->width * (size_t)cam->height * 3), 0);
}

/* parallel camera over the window [u0,u1]x[v0,v1] of VRC3, looking down -n (n from nf down to
   nb), direction of projection through prp (oblique when prp is not above the centre) */
static int cam_parallel(rt_camera *cam, const double win[4], double nf, double nb,
                        const double prp[3], int w, int h)
{
    rtu_view v = {.win = {win[0], win[1], win[2], win[3]}, .prp = {prp[0], prp[1], prp[2]},
                  .vpd = nf, .bpd = nb, .fpd = nf, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    double m[4][4];
    rtu_view_matrix(&v, m);
    return rt_camera_from_view(cam, m, v.vp, w, h);
}

static void cross3(const double a[3], const double b[3], double r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static void unit3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++)
        v[i] /= l;
}

/* ---- 1: closed-mesh leak probe ---- */

#ifndef RT_LEAK_RANDOM
#define RT_LEAK_RANDOM 5000 /* per mesh in CI; bench/rt/rt_leak runs 10^6 */
#endif

static void leak_probe(const char *path)
{
    rtu_mesh m;
    assert_int_equal(rtu_load_off(path, &m), 0);
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    int s = surf_plain(sc);
    assert_int_equal(rtu_mesh_add(&m, sc, s), 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    double p[3];
    int inner;
    assert_int_equal(rtu_interior_point(&m, sc, p, &inner), 0);
    rt_ray *rays;
    size_t n, nv, ne;
    assert_int_equal(rtu_leak_rays(&m, p, RT_LEAK_RANDOM, 7, &rays, &n, &nv, &ne), 0);
    assert_int_equal(nv, (size_t)m.nv);
    assert_true(ne >= (size_t)m.nv); /* closed triangle mesh: E = 3F/2 > V */
    rt_hit *h = malloc(n * sizeof *h);
    assert_non_null(h);
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, n, rays, h), RT_OK);
    rtc_traps_off();
    /* a leak shows as a miss (escaped) or as a first hit on the outer side (went out through
       a crack and met the surface again from outside). At its target (t = 1) an aimed ray
       meets several faces at the same t, facing either way where the surface folds around
       the ray (ties go to the smallest id), so an outer side there is no leak. An aimed ray
       may also legitimately pass its target where it only touches the surface (grazing a
       reflex vertex): such hits beyond the target are reported, not counted as leaks. */
    size_t miss = 0, outer = 0, beyond = 0;
    for (size_t k = 0; k < n; k++) {
        int aimed = k < nv + ne;
        miss += h[k].prim < 0;
        outer += h[k].prim >= 0 && h[k].side != inner && !(aimed && fabs(h[k].t - 1.0) <= 1e-9);
        beyond += aimed && h[k].prim >= 0 && !(h[k].t <= 1.0 + 1e-9);
    }
    printf("leak probe %s: %zu vertex + %zu edge + %d random rays: %zu misses, %zu outer-side "
           "first hits (%zu aimed rays pass their target inside)\n",
           path, nv, ne, RT_LEAK_RANDOM, miss, outer, beyond);
    assert_int_equal(miss, 0);
    assert_int_equal(outer, 0);
    free(h);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

static void test_leak_probe(void **state)
{
    (void)state;
    leak_probe(RT_DATA_DIR "/meshes/fandisk_large.off.gz");
    leak_probe(RT_DATA_DIR "/meshes/armadillo.off.gz");
    leak_probe(RT_DATA_DIR "/meshes/bunny00.off.gz");
}

/* ---- 2: shared diagonal at offsets 0, 1e3, 1e6 ---- */

static void test_shared_diagonal(void **state)
{
    (void)state;
    const double offs[3] = {0.0, 1e3, 1e6};
    const int N = 1000;
    rt_ray *rays = malloc(3 * (size_t)N * sizeof *rays);
    rt_hit *h = malloc(3 * (size_t)N * sizeof *h);
    assert_non_null(rays);
    assert_non_null(h);
    for (int oi = 0; oi < 3; oi++) {
        const double o = offs[oi];
        for (int form = 0; form < 3; form++) { /* two flat triangles, two tilted, one quad */
            rt_scene *sc = rt_scene_new();
            int s = surf_plain(sc);
            double z0 = o, z1 = o + (form == 1 ? 0.3 : 0.0), z2 = o + (form == 1 ? 0.7 : 0.0);
            double a[3] = {o, o, z0}, b[3] = {o + 1, o, z1}, c[3] = {o + 1, o + 1, z1 + z2 - z0},
                   d[3] = {o, o + 1, z2};
            if (form < 2) {
                add_tri(sc, a, b, c, s);
                add_tri(sc, a, c, d, s);
            } else {
                double q[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
                add_poly(sc, 4, q, s);
            }
            /* padding primitives far away so that the grid is built */
            for (int k = 0; k < 6; k++) {
                double e[3] = {o + 5 + k, o + 5, o}, f[3] = {o + 5.5 + k, o + 5, o}, g[3] = {o + 5, o + 5.5, o};
                add_tri(sc, e, f, g, s);
            }
            uint64_t rng = 11;
            for (int k = 0; k < N; k++) {
                /* x = y exactly: vertical rays exactly on the shared edge; oblique rays through
                   the diagonal; vertical rays a few ulps to either side */
                double sx = (k + 0.5) / N, X = o + sx;
                double org[3] = {X, X, o + 10}, dv[3] = {0, 0, -1};
                ray_set(&rays[k], org, dv);
                double dob[3] = {0.3 * (rtu_rand(&rng) - 0.5), 0.3 * (rtu_rand(&rng) - 0.5), -1};
                double zt = z0 + sx * (z1 + z2 - 2 * z0); /* height of the diagonal at X */
                double org2[3] = {X - 10 * dob[0], X - 10 * dob[1], zt + 10};
                ray_set(&rays[N + k], org2, dob);
                double u = nextafter(X, INFINITY), w = nextafter(X, -INFINITY);
                double org3[3] = {k & 1 ? u : w, k & 1 ? w : u, o + 10};
                ray_set(&rays[2 * N + k], org3, dv);
            }
            size_t nhit = 0;
            size_t bad = grid_vs_brute(sc, NULL, rays, 3 * (size_t)N, &nhit);
            assert_int_equal(bad, 0);
            assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
            assert_int_equal(rt_intersect(sc, 3 * (size_t)N, rays, h), RT_OK);
            size_t miss = 0;
            for (int k = 0; k < 3 * N; k++)
                miss += h[k].prim < 0 || h[k].prim > 1;
            printf("shared diagonal offset %g form %d: %d rays, %zu misses\n", o, form, 3 * N, miss);
            assert_int_equal(miss, 0);
            rt_scene_free(sc);
        }
    }
    free(rays);
    free(h);
}

/* ---- 3: re-intersection and shadow acne ---- */

/* A secondary ray from hit h as the renderer spawns it (rt_render.c, rt_eps): origin = hit
 * point moved off the surface along the geometric normal, to the side dir points to, by
 * 1e-12 * (max |hit coordinate| + t) + 1e-9 * ext + 1e-300, ext the scene's largest
 * bounding-box extent; dir copied; tmin 0, tmax +inf. */
static void spawn(const rt_hit *h, const double dir[3], double ext, rt_ray *out)
{
    double m = fmax(fabs(h->p[0]), fmax(fabs(h->p[1]), fabs(h->p[2])));
    double eps = 1e-12 * (m + fabs(h->t)) + 1e-9 * ext + 1e-300;
    if (h->ng[0] * dir[0] + h->ng[1] * dir[1] + h->ng[2] * dir[2] < 0.0)
        eps = -eps;
    for (int i = 0; i < 3; i++) {
        out->org[i] = h->p[i] + eps * h->ng[i];
        out->dir[i] = dir[i];
    }
    out->tmin = 0.0;
    out->tmax = INFINITY;
}

static void test_reintersection(void **state)
{
    (void)state;
    const double scales[5] = {1e-3, 1.0, 1e3, 1e6, 1.0};
    const int NT = 200, NR = 2000; /* 5 x 2000 = 10^4 spawned rays */
    rt_ray *prim_rays = malloc((size_t)NR * sizeof *prim_rays);
    rt_ray *sec = malloc((size_t)NR * sizeof *sec);
    rt_hit *h = malloc((size_t)NR * sizeof *h), *h2 = malloc((size_t)NR * sizeof *h2);
    int *want = malloc((size_t)NR * sizeof *want);
    assert_non_null(prim_rays);
    assert_non_null(sec);
    assert_non_null(h);
    assert_non_null(h2);
    assert_non_null(want);
    size_t total_self = 0, total_spawned = 0, naive_self = 0;
    for (int si = 0; si < 5; si++) {
        const double S = scales[si], off = si == 4 ? 1e6 : 0.0; /* last: scale 1 at offset 1e6 */
        uint64_t rng = 1234 + (uint64_t)si;
        rt_scene *sc = rt_scene_new();
        int s = surf_plain(sc);
        double *tv = malloc(9 * (size_t)NT * sizeof *tv);
        assert_non_null(tv);
        for (int t = 0; t < NT; t++) {
            double c[3];
            for (int i = 0; i < 3; i++)
                c[i] = off + S * (20.0 * rtu_rand(&rng) - 10.0);
            for (int v = 0; v < 3; v++)
                for (int i = 0; i < 3; i++)
                    tv[9 * t + 3 * v + i] = c[i] + S * (2.0 * rtu_rand(&rng) - 1.0);
            add_poly(sc, 3, tv + 9 * t, s);
        }
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        double lo[3], hi[3], ext = 0.0; /* the scene's bounding box: its triangles' */
        for (int i = 0; i < 3; i++) {
            lo[i] = hi[i] = tv[i];
            for (int v = 0; v < 3 * NT; v++) {
                lo[i] = fmin(lo[i], tv[3 * v + i]);
                hi[i] = fmax(hi[i], tv[3 * v + i]);
            }
            ext = fmax(ext, hi[i] - lo[i]);
        }
        /* primary rays aimed at random points of random triangles */
        for (int k = 0; k < NR; k++) {
            int t = (int)(rtu_rand(&rng) * NT);
            double b0 = rtu_rand(&rng), b1 = rtu_rand(&rng);
            if (b0 + b1 > 1.0) {
                b0 = 1.0 - b0;
                b1 = 1.0 - b1;
            }
            double target[3], d[3], org[3];
            for (int i = 0; i < 3; i++)
                target[i] = tv[9 * t + i] + b0 * (tv[9 * t + 3 + i] - tv[9 * t + i]) +
                            b1 * (tv[9 * t + 6 + i] - tv[9 * t + i]);
            rtu_rand_dir(&rng, d);
            for (int i = 0; i < 3; i++)
                org[i] = target[i] - 30.0 * S * d[i];
            ray_set(&prim_rays[k], org, d);
        }
        rtc_traps_on();
        assert_int_equal(rt_intersect(sc, (size_t)NR, prim_rays, h), RT_OK);
        rtc_traps_off();
        /* secondary rays: random directions on either side, down to 0.01 degrees above the
           surface (half of them grazing), spawned like the renderer does */
        size_t n2 = 0;
        for (int k = 0; k < NR; k++) {
            if (h[k].prim < 0)
                continue;
            double t1[3], t2[3], a[3] = {1, 0, 0};
            if (fabs(h[k].ng[0]) > 0.9)
                a[0] = 0, a[1] = 1;
            cross3(h[k].ng, a, t1);
            unit3(t1);
            cross3(h[k].ng, t1, t2);
            double elev = (k & 1) ? (0.01 + 5.0 * rtu_rand(&rng)) * PI / 180.0 : rtu_rand(&rng) * PI / 2;
            double az = 2 * PI * rtu_rand(&rng), sgn = (k & 2) ? 1.0 : -1.0, d[3];
            for (int i = 0; i < 3; i++)
                d[i] = sgn * sin(elev) * h[k].ng[i] + cos(elev) * (cos(az) * t1[i] + sin(az) * t2[i]);
            spawn(&h[k], d, ext, &sec[n2]);
            want[n2] = h[k].prim;
            /* the same ray without the offset (for the report: what the offset prevents) */
            rt_ray naive = sec[n2];
            memcpy(naive.org, h[k].p, sizeof naive.org);
            rt_hit hn;
            rt_intersect(sc, 1, &naive, &hn);
            naive_self += hn.prim == h[k].prim;
            n2++;
        }
        rtc_traps_on();
        assert_int_equal(rt_intersect(sc, n2, sec, h2), RT_OK);
        rtc_traps_off();
        size_t self = 0;
        for (size_t k = 0; k < n2; k++)
            self += h2[k].prim == want[k];
        printf("re-intersection scale %g offset %g: %zu spawned rays, %zu self-hits\n", S, off, n2, self);
        total_self += self;
        total_spawned += n2;
        free(tv);
        rt_scene_free(sc);
    }
    printf("re-intersection: %zu spawned, %zu self-hits (%zu without the origin offset)\n",
           total_spawned, total_self, naive_self);
    assert_true(total_spawned >= 9000);
    assert_int_equal(total_self, 0);
    free(prim_rays);
    free(sec);
    free(h);
    free(h2);
    free(want);
}

/* A tilted plane lit by a directional light at 89, 89.9, 89.99 degrees from its normal (plus an
 * ambient light 0.1), as two triangles, a quad and a pentagon, at offsets 0 and 1e6: every pixel
 * must show the plane unshadowed: 0.1 + cos(angle). A self-shadowed pixel shows 0.1.
 * Tolerance 1e-4 * cos(angle) (float output, double shading). */
static void test_shadow_acne(void **state)
{
    (void)state;
    enum { SW = 24, SH = 24 };
    const double angles[3] = {89.0, 89.9, 89.99};
    float *rgb = malloc(SW * SH * 3 * sizeof(float));
    assert_non_null(rgb);
    size_t total_bad = 0, total_px = 0;
    for (int oi = 0; oi < 2; oi++) {
        const double off = oi ? 1e6 : 0.0;
        double n[3] = {0.3, -0.2, 0.9}, t1[3], t2[3], a[3] = {1, 0, 0};
        unit3(n);
        cross3(n, a, t1);
        unit3(t1);
        cross3(n, t1, t2);
        for (int ai = 0; ai < 3; ai++)
            for (int form = 0; form < 3; form++) {
                rt_scene *sc = rt_scene_new();
                rt_surface su;
                rt_surface_default(&su);
                su.ka = 1.0;
                su.kd = 1.0;
                int s = rt_scene_add_surface(sc, &su);
                double th = angles[ai] * PI / 180.0;
                rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.1, 0.1, 0.1}};
                rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}};
                for (int i = 0; i < 3; i++)
                    dl.direction[i] = -(cos(th) * n[i] + sin(th) * (0.6 * t1[i] + 0.8 * t2[i]));
                assert_true(rt_scene_add_light(sc, &amb) >= 0);
                assert_true(rt_scene_add_light(sc, &dl) >= 0);
                /* plane through (off,off,off) spanning +-20 along t1, t2 */
                const int nv = form == 0 ? 3 : form == 1 ? 4 : 5;
                double v[15];
                for (int k = 0; k < nv; k++) {
                    double ang = 2 * PI * k / nv + 0.1;
                    for (int i = 0; i < 3; i++)
                        v[3 * k + i] = off + 40.0 * (cos(ang) * t1[i] + sin(ang) * t2[i]);
                }
                if (form == 0) { /* two triangles over the square */
                    double q[12];
                    for (int k = 0; k < 4; k++) {
                        double ang = PI / 2 * k + 0.1;
                        for (int i = 0; i < 3; i++)
                            q[3 * k + i] = off + 40.0 * (cos(ang) * t1[i] + sin(ang) * t2[i]);
                    }
                    add_tri(sc, q, q + 3, q + 6, s);
                    add_tri(sc, q, q + 6, q + 9, s);
                } else {
                    add_poly(sc, nv, v, s);
                }
                for (int k = 0; k < 4; k++) /* small blockers far away: the grid is built */
                    add_rect_z(sc, off + 100 + k, off + 100, off + 100.5 + k, off + 100.5, off + 100, 1, s);
                assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
                rt_camera cam;
                double win[4] = {off - 3, off + 3, off - 3, off + 3};
                double prp[3] = {off, off, off + 100};
                assert_int_equal(cam_parallel(&cam, win, off + 50, off - 50, prp, SW, SH), RT_OK);
                rt_render_options ro;
                rtu_options_plain(&ro);
                ro.threads = 1;
                rt_stats st;
                render_checked(sc, &cam, &ro, rgb, &st);
                double want = 0.1 + cos(th);
                size_t bad = 0;
                for (int k = 0; k < SW * SH; k++)
                    bad += !(fabs(rgb[3 * k] - want) <= 1e-4 * cos(th));
                assert_int_equal(st.eye_hits, (uint64_t)(SW * SH));
                total_bad += bad;
                total_px += SW * SH;
                rt_scene_free(sc);
            }
    }
    printf("shadow acne: %zu pixels at 89/89.9/89.99 degrees, offsets 0 and 1e6: %zu self-shadowed\n",
           total_px, total_bad);
    assert_int_equal(total_bad, 0);
    free(rgb);
}

/* ---- 4: axis-aligned box room on grid-cell boundaries ---- */

static void box_room(rt_scene *sc, int s)
{
    /* room [0,4]^3, walls facing inwards */
    add_rect_z(sc, 0, 0, 4, 4, 0, 1, s);
    add_rect_z(sc, 0, 0, 4, 4, 4, 0, s);
    double w[6][12] = {
        {0, 0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4}, {4, 0, 0, 4, 0, 4, 4, 4, 4, 4, 4, 0},
        {0, 0, 0, 0, 0, 4, 4, 0, 4, 4, 0, 0}, {0, 4, 0, 4, 4, 0, 4, 4, 4, 0, 4, 4},
        /* inner wall x = 3 over y in [0,2], a box [1,2]^2 x [0,1] (top and two sides) */
        {3, 0, 0, 3, 2, 0, 3, 2, 4, 3, 0, 4}, {1, 1, 1, 2, 1, 1, 2, 2, 1, 1, 2, 1}};
    for (int k = 0; k < 6; k++)
        add_poly(sc, 4, w[k], s);
    double sides[2][12] = {{1, 1, 0, 2, 1, 0, 2, 1, 1, 1, 1, 1}, {2, 1, 0, 2, 2, 0, 2, 2, 1, 2, 1, 1}};
    add_poly(sc, 4, sides[0], s);
    add_poly(sc, 4, sides[1], s);
    /* two triangles on the plane y = 3 and a polygon on z = 2 (other primitive kinds) */
    double t0[3] = {0, 3, 0}, t1[3] = {2, 3, 0}, t2[3] = {0, 3, 2};
    add_tri(sc, t0, t1, t2, s);
    double p5[15] = {2, 2, 2, 3, 2, 2, 3, 3, 2, 2.5, 3.5, 2, 2, 3, 2};
    add_poly(sc, 5, p5, s);
}

static void test_box_room(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    box_room(sc, s);
    const double comp[6] = {-1.0, -0.0, 0.0, 1.0, 0.5, -0.25};
    const double pos[7] = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5};
    size_t n = 0, cap = 7 * 7 * 7 * 215;
    rt_ray *rays = malloc(cap * sizeof *rays);
    assert_non_null(rays);
    for (int a = 0; a < 7; a++)
        for (int b = 0; b < 7; b++)
            for (int c = 0; c < 7; c++)
                for (int i = 0; i < 6; i++)
                    for (int j = 0; j < 6; j++)
                        for (int k = 0; k < 6; k++) {
                            double d[3] = {comp[i], comp[j], comp[k]};
                            if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
                                continue;
                            if ((i + 2 * j + 3 * k + a + b + c) % 3) /* a third of them */
                                continue;
                            double o[3] = {pos[a], pos[b], pos[c]};
                            assert_true(n < cap);
                            ray_set(&rays[n++], o, d);
                        }
    /* rays along grid planes and edges, starting on the room walls and grid lines */
    for (int a = 0; a <= 4 && n < cap; a++)
        for (int b = 0; b <= 4; b++) {
            double o1[3] = {a, b, 0.0}, d1[3] = {-0.0, 0.0, 1.0};
            double o2[3] = {0.0, a, b}, d2[3] = {1.0, -0.0, -0.0};
            double o3[3] = {a, 0.0, b}, d3[3] = {0.0, 1.0, 0.0};
            if (n + 3 <= cap) {
                ray_set(&rays[n++], o1, d1);
                ray_set(&rays[n++], o2, d2);
                ray_set(&rays[n++], o3, d3);
            }
        }
    for (int k = 0; k < (int)n; k += 7) /* some finite ranges too */
        rays[k].tmax = 1.5;
    const rt_build_options cfg[3] = {
        {.grid_res = {4, 4, 4}, .grid_box = {0, 0, 0, 4, 4, 4}, .no_subgrids = 1},
        {.grid_res = {8, 8, 8}, .grid_box = {0, 0, 0, 4, 4, 4}, .sub_min = 1},
        {.grid_factor = 0.0}};
    for (int c = 0; c < 3; c++) {
        size_t nhit = 0;
        size_t bad = grid_vs_brute(sc, &cfg[c], rays, n, &nhit);
        printf("box room config %d: %zu rays, %zu hits, %zu grid/brute mismatches\n", c, n, nhit, bad);
        assert_int_equal(bad, 0);
        assert_true(nhit > n / 2);
    }
    free(rays);
    rt_scene_free(sc);
}

/* The SPD gears seen obliquely (in VRC3 as rt_bench traces them): the grid is laid out in a
 * rotated frame; still bit-identical to brute force, for eye rays and random rays. */
static void test_rotated_grid(void **state)
{
    (void)state;
    rtu_mesh m;
    assert_int_equal(rtu_load_nff(RT_DATA_DIR "/spd/gears.nff.gz", &m), 0);
    double vo[4][4];
    rtu_lookat(m.from, m.at, m.up, vo);
    rtu_mesh_transform(&m, vo);
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    m.nsurfs = 0;
    m.nlights = 0;
    assert_int_equal(rtu_mesh_add(&m, sc, s), 0);
    double bb[6];
    rtu_mesh_bbox(&m, bb);
    enum { NR = 20000 };
    rt_ray *rays = malloc(NR * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 3;
    for (int k = 0; k < NR; k++) {
        double o[3] = {0, 0, 0}, d[3], tg[3];
        for (int i = 0; i < 3; i++)
            tg[i] = bb[i] + (bb[3 + i] - bb[i]) * rtu_rand(&rng);
        if (k & 1) { /* from inside the scene box in random directions */
            rtu_rand_dir(&rng, d);
            memcpy(o, tg, sizeof o);
        } else { /* from the eye (VRC3 origin) */
            for (int i = 0; i < 3; i++)
                d[i] = tg[i];
        }
        ray_set(&rays[k], o, d);
    }
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_int_equal(gi.rotated, 1);
    /* brute force on a subset (9345 primitives per ray), rotated == VRC3-aligned on all */
    size_t nhit = 0;
    size_t bad = grid_vs_brute(sc, NULL, rays, 300, NULL);
    rt_build_options vrc = {.grid_frame = 1};
    size_t bad2 = grid_vs_brute(sc, &vrc, rays, 300, NULL);
    rt_hit *h1 = malloc(NR * sizeof *h1), *h2 = malloc(NR * sizeof *h2);
    assert_non_null(h1);
    assert_non_null(h2);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_int_equal(rt_intersect(sc, NR, rays, h1), RT_OK);
    assert_int_equal(rt_scene_commit(sc, &vrc), RT_OK);
    assert_int_equal(rt_intersect(sc, NR, rays, h2), RT_OK);
    for (int k = 0; k < NR; k++) {
        bad2 += !rtu_same_hit(&h1[k], &h2[k]);
        nhit += h1[k].prim >= 0;
    }
    free(h1);
    free(h2);
    printf("gears in VRC3, rotated grid %dx%dx%d: %d rays, %zu hits; mismatches: %zu against brute "
           "force (300 rays), %zu against the VRC3-aligned grid\n", gi.res[0], gi.res[1], gi.res[2],
           NR, nhit, bad, bad2);
    assert_true(nhit > NR / 4);
    assert_int_equal(bad, 0);
    assert_int_equal(bad2, 0);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

/* A cloud of nt small triangles in the box [-hx,hx] x [-hy,hy] x [-hz,hz] of a frame turned by
 * ay about y, then ax about x (VRC3 = R p), plus one large square on the box face z = -hz (its
 * frame, the turned one, is the grid frame candidate). aligned = 1: every small triangle lies in a plane of the
 * turned frame (normals along its axes); 0: random orientations. */
static void frame_cloud(rt_scene *sc, int s, int nt, double hx, double hy, double hz, double ay,
                        double ax, int aligned, uint64_t seed)
{
    const double cy = cos(ay), sy = sin(ay), cx = cos(ax), sx = sin(ax);
    /* R = Rx(ax) Ry(ay), rows */
    const double R[3][3] = {{cy, 0, sy}, {sx * sy, cx, -sx * cy}, {-cx * sy, sx, cx * cy}};
    uint64_t rng = seed;
    for (int k = 0; k <= nt; k++) {
        double q[3][3], v[3][3];
        if (k == nt) { /* the large square: one 4-gon (first edge along the frame's x) */
            const double sq[4][3] = {{-hx, -hy, -hz}, {hx, -hy, -hz}, {hx, hy, -hz}, {-hx, hy, -hz}};
            double xyz[12];
            for (int j = 0; j < 4; j++)
                for (int a = 0; a < 3; a++)
                    xyz[3 * j + a] = R[a][0] * sq[j][0] + R[a][1] * sq[j][1] + R[a][2] * sq[j][2];
            const int four = 4;
            assert_true(rt_scene_add_polygon(sc, 1, &four, xyz, s, s) >= 0);
            break;
        }
        const double h = 0.01, c[3] = {(2 * rtu_rand(&rng) - 1) * (hx - h),
                                       (2 * rtu_rand(&rng) - 1) * (hy - h),
                                       (2 * rtu_rand(&rng) - 1) * (hz - h)};
        const int ax0 = (int)(3 * rtu_rand(&rng)) % 3; /* aligned: the normal's axis */
        for (int j = 0; j < 3; j++) {
            double d[3];
            rtu_rand_dir(&rng, d);
            if (aligned)
                d[ax0] = 0.0;
            for (int a = 0; a < 3; a++)
                q[j][a] = c[a] + h * d[a];
        }
        for (int j = 0; j < 3; j++)
            for (int a = 0; a < 3; a++)
                v[j][a] = R[a][0] * q[j][0] + R[a][1] * q[j][1] + R[a][2] * q[j][2];
        assert_true(add_tri(sc, v[0], v[1], v[2], s) >= 0);
    }
}

/* The grid frame rule (rt_build.c): a rotation is taken for what it saves eye rays (which run
 * along VRC3 -z) or secondary rays (surfaces near grid planes), not for the box volume alone.
 * Each case: the frame chosen, and grid == brute force bit for bit on eye rays. */
static void test_grid_frame_choice(void **state)
{
    (void)state;
    const double deg = 3.14159265358979323846 / 180.0;
    const struct {
        double hx, hy, hz, ay, ax;
        int aligned, rotated;
        const char *what;
    } cases[] = {
        /* cube turned 30 degrees: VRC3 box volume 1.87x, but the view direction would leave
           the grid axes (E = 0.54^(2/3) * 1.37 = 0.90): VRC3 axes (the volume rule rotated) */
        {0.5, 0.5, 0.5, 30 * deg, 0, 0, 0, "turned cube, random triangles"},
        /* thin slab turned 30 degrees: E = 0.10^(2/3) * 1.37 = 0.30: rotated */
        {0.5, 0.5, 0.025, 30 * deg, 0, 0, 1, "turned thin slab"},
        /* cube turned 30 and 20 degrees, triangles in its planes: S = 0.69 (E 1.2): rotated */
        {0.5, 0.5, 0.5, 30 * deg, 20 * deg, 1, 1, "turned cube, triangles in its planes"},
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        rt_scene *sc = rt_scene_new();
        assert_non_null(sc);
        int s = surf_plain(sc);
        frame_cloud(sc, s, 3000, cases[c].hx, cases[c].hy, cases[c].hz, cases[c].ay, cases[c].ax,
                    cases[c].aligned, 11 + c);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_grid_info gi;
        assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
        enum { NR = 400 };
        rt_ray rays[NR];
        uint64_t rng = 5;
        for (int k = 0; k < NR; k++) { /* eye at z = 3 looking down -z over the cloud */
            const double o[3] = {0, 0, 3}, d[3] = {1.6 * rtu_rand(&rng) - 0.8,
                                                   1.6 * rtu_rand(&rng) - 0.8, -3};
            ray_set(&rays[k], o, d);
        }
        size_t nhit = 0, bad = grid_vs_brute(sc, NULL, rays, NR, &nhit);
        printf("%s: grid %dx%dx%d %s; %d eye rays, %zu hits, %zu grid/brute mismatches\n",
               cases[c].what, gi.res[0], gi.res[1], gi.res[2],
               gi.rotated ? "rotated" : "in VRC3 axes", NR, nhit, bad);
        assert_int_equal(gi.rotated, cases[c].rotated);
        assert_int_equal(bad, 0);
        assert_true(nhit > NR / 4);
        rt_scene_free(sc);
    }
}

/* Second level or one fine level (rt_build.c, RT_UNIFORM_SHARE): a terrain (a height field of
 * small triangles) crowds every top cell it crosses, so the default build takes one fine level;
 * explicit second-level options keep two levels; both bit-identical to brute force. */
static void test_grid_levels(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    int s = surf_plain(sc);
    enum { N = 40 };
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double p[4][3];
            for (int k = 0; k < 4; k++) {
                const double x = (double)(i + (k == 1 || k == 2)) / N, y = (double)(j + (k >= 2)) / N;
                p[k][0] = x;
                p[k][1] = y;
                p[k][2] = 0.1 * sin(7.0 * x) * cos(5.0 * y);
            }
            assert_true(add_tri(sc, p[0], p[1], p[2], s) >= 0);
            assert_true(add_tri(sc, p[0], p[2], p[3], s) >= 0);
        }
    enum { NR = 2000 };
    rt_ray rays[NR];
    uint64_t rng = 9;
    for (int k = 0; k < NR; k++) { /* at points of the terrain's square, from above or grazing */
        const double o[3] = {rtu_rand(&rng), rtu_rand(&rng), k & 1 ? 2.0 : 0.12};
        const double d[3] = {rtu_rand(&rng) - o[0], rtu_rand(&rng) - o[1], -o[2]};
        ray_set(&rays[k], o, d);
    }
    rt_grid_info gi, g2;
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    const rt_build_options two = {.sub_factor = 3.0};
    assert_int_equal(rt_scene_commit(sc, &two), RT_OK);
    assert_int_equal(rt_scene_grid_info(sc, &g2), RT_OK);
    size_t nhit = 0, bad = grid_vs_brute(sc, NULL, rays, NR, &nhit);
    size_t bad2 = grid_vs_brute(sc, &two, rays, NR, NULL);
    printf("terrain of %d triangles: default grid %dx%dx%d, %llu subgrids; explicit sub_factor 3: "
           "%dx%dx%d, %llu subgrids; %d rays, %zu hits, mismatches %zu / %zu\n", 2 * N * N,
           gi.res[0], gi.res[1], gi.res[2], (unsigned long long)gi.subgrids, g2.res[0], g2.res[1],
           g2.res[2], (unsigned long long)g2.subgrids, NR, nhit, bad, bad2);
    assert_int_equal(gi.subgrids, 0);
    assert_true(gi.cells >= 4 * gi.prims); /* the fine level: ~8 cells per primitive */
    assert_true(g2.subgrids > 0);
    assert_true(g2.cells < gi.cells / 8);
    assert_int_equal(bad, 0);
    assert_int_equal(bad2, 0);
    assert_true(nhit > NR / 3);
    rt_scene_free(sc);
}

/* ---- 5: coplanar and overlapping polygons ---- */

static void test_coplanar(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    /* on z = 1 exactly: ids 0..3; on a tilted plane: ids 4..7 (two copies of each shape) */
    add_rect_z(sc, 0, 0, 2, 2, 1, 1, s);                       /* 0: quad */
    add_rect_z(sc, 1, 1, 3, 3, 1, 0, s);                       /* 1: quad, facing down */
    double pent[15] = {0.5, 0.5, 1, 2.5, 0.5, 1, 2.5, 2.0, 1, 1.5, 2.5, 1, 0.5, 2.0, 1};
    add_poly(sc, 5, pent, s);                                  /* 2: pentagon */
    double ta[3] = {0, 0, 1}, tb[3] = {3, 0, 1}, tc[3] = {0, 3, 1};
    add_tri(sc, ta, tb, tc, s);                                /* 3: triangle */
    double nrm[3] = {0.2, -0.3, 0.9}, u[3], v[3], ax[3] = {1, 0, 0};
    unit3(nrm);
    cross3(nrm, ax, u);
    unit3(u);
    cross3(nrm, u, v);
    for (int copy = 0; copy < 2; copy++) {
        double q[12], tri[9];
        for (int k = 0; k < 4; k++)
            for (int i = 0; i < 3; i++)
                q[3 * k + i] = 10 + ((k == 1 || k == 2) ? 2.0 : 0.0) * u[i] + (k >= 2 ? 2.0 : 0.0) * v[i] +
                               copy * 0.5 * u[i];
        add_poly(sc, 4, q, s);                                 /* 4, 6: tilted quads */
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++)
                tri[3 * k + i] = 10 + (k == 1 ? 3.0 : 0.0) * u[i] + (k == 2 ? 3.0 : 0.0) * v[i];
        add_poly(sc, 3, tri, s);                               /* 5, 7: tilted triangles */
    }
    enum { NG = 60 };
    rt_ray *rays = malloc(2 * NG * NG * sizeof *rays);
    assert_non_null(rays);
    size_t n = 0;
    for (int i = 0; i < NG; i++)
        for (int j = 0; j < NG; j++) {
            double x = -0.25 + 3.5 * (i + 0.37) / NG, y = -0.25 + 3.5 * (j + 0.61) / NG;
            double o[3] = {x, y, 5}, d[3] = {0, 0, -1};
            ray_set(&rays[n++], o, d);
            double o2[3], d2[3] = {-nrm[0], -nrm[1], -nrm[2]};
            for (int k = 0; k < 3; k++)
                o2[k] = 10 + (x - 0.25) * u[k] + (y - 0.25) * v[k] + 5 * nrm[k];
            ray_set(&rays[n++], o2, d2);
        }
    size_t bad = grid_vs_brute(sc, NULL, rays, n, NULL);
    assert_int_equal(bad, 0);
    /* analytic on z = 1: all four give t = 4 exactly, so the largest covering id (drawn
       last) wins, as in the z-buffer and painter modes */
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_hit *h = malloc(n * sizeof *h), *h2 = malloc(n * sizeof *h2);
    assert_non_null(h);
    assert_non_null(h2);
    assert_int_equal(rt_intersect(sc, n, rays, h), RT_OK);
    size_t wrong = 0, nondet = 0;
    for (size_t k = 0; k < n; k += 2) {
        double x = rays[k].org[0], y = rays[k].org[1];
        int in0 = x > 0 && x < 2 && y > 0 && y < 2, in1 = x > 1 && x < 3 && y > 1 && y < 3;
        int in3 = x > 0 && y > 0 && x + y < 3;
        /* pentagon: inside test by the crossing rule in double (points are far from edges) */
        int in2 = 0;
        for (int e = 0, f = 4; e < 5; f = e++) {
            double xe = pent[3 * e], ye = pent[3 * e + 1], xf = pent[3 * f], yf = pent[3 * f + 1];
            if ((ye > y) != (yf > y) && x < xe + (y - ye) * (xf - xe) / (yf - ye))
                in2 ^= 1;
        }
        int want = in3 ? 3 : in2 ? 2 : in1 ? 1 : in0 ? 0 : -1;
        wrong += h[k].prim != want || (want >= 0 && h[k].t != 4.0);
    }
    /* deterministic: again, one by one, and after re-committing */
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    for (size_t k = 0; k < n; k++) {
        assert_int_equal(rt_intersect(sc, 1, &rays[k], &h2[k]), RT_OK);
        nondet += !rtu_same_hit(&h[k], &h2[k]);
    }
    printf("coplanar: %zu rays, %zu wrong on z = 1, %zu not reproducible\n", n, wrong, nondet);
    assert_int_equal(wrong, 0);
    assert_int_equal(nondet, 0);
    /* pictures: 1 thread and 2 threads give the same bits */
    rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.2, 0.2, 0.2}};
    rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {0.1, 0.2, -1}};
    rt_scene_add_light(sc, &amb);
    rt_scene_add_light(sc, &dl);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    double win[4] = {-0.5, 3.5, -0.5, 3.5}, prp[3] = {1.5, 1.5, 100};
    assert_int_equal(cam_parallel(&cam, win, 5, -5, prp, 48, 48), RT_OK);
    float *a = malloc(48 * 48 * 3 * sizeof(float)), *b = malloc(48 * 48 * 3 * sizeof(float));
    assert_non_null(a);
    assert_non_null(b);
    rt_render_options ro;
    rtu_options_plain(&ro);
    ro.threads = 1;
    render_checked(sc, &cam, &ro, a, NULL);
    ro.threads = 2;
    render_checked(sc, &cam, &ro, b, NULL);
    assert_memory_equal(a, b, 48 * 48 * 3 * sizeof(float));
    free(a);
    free(b);
    free(h);
    free(h2);
    free(rays);
    rt_scene_free(sc);
}

/* coplanar areas through random rotations, translations and scales (docs/RAYTRACING.md,
   "Coplanar surfaces"): each vertex is rotated in double, so the areas are coplanar only up to
   rounding. A: a floor (two triangles) and three rugs in its plane drawn after it (a quad, a
   pentagon, a triangle): every ray aimed inside a rug must hit the rug (the later area wins a
   tie). B: a mat lifted 1e-10 of the scene's magnitude above the floor (far above the tie
   bound, 16 sqrt(3) 2^-53 / cos) and drawn first: every ray aimed inside it must hit the mat
   (the bound does not make real gaps tie). */
static void rot_point(const double R[3][3], const double T[3], double sc, const double p[3],
                      double out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = T[i] + sc * (R[i][0] * p[0] + R[i][1] * p[1] + R[i][2] * p[2]);
}

static int add_local(rt_scene *sc, int n, const double *lp, const double R[3][3], const double T[3],
                     double scale, int s)
{
    double v[15];
    for (int k = 0; k < n; k++)
        rot_point(R, T, scale, lp + 3 * k, v + 3 * k);
    return add_poly(sc, n, v, s);
}

static void test_coplanar_rotated(void **state)
{
    (void)state;
    uint64_t st = 0x243F6A8885A308D3ULL;
    size_t nrays = 0, wrong_a = 0, wrong_b = 0;
    for (int trial = 0; trial < 120; trial++) {
        double a = 2 * PI * rtu_rand(&st), b = PI * rtu_rand(&st), c = 2 * PI * rtu_rand(&st);
        const double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b), cc = cos(c), sc2 = sin(c);
        /* R = Rz(a) Rx(b) Rz(c): orthonormal rows */
        const double R[3][3] = {{ca * cc - sa * cb * sc2, -ca * sc2 - sa * cb * cc, sa * sb},
                                {sa * cc + ca * cb * sc2, -sa * sc2 + ca * cb * cc, -ca * sb},
                                {sb * sc2, sb * cc, cb}};
        const double mag = pow(10.0, (double)(trial % 4)), scale = trial % 3 == 0 ? 1e3 : 1.0;
        double T[3];
        for (int i = 0; i < 3; i++)
            T[i] = mag * (2 * rtu_rand(&st) - 1);
        const double delta = 1e-10 * fmax(mag, 2.0 * scale) / scale; /* B's lift, local units */
        for (int part = 0; part < 2; part++) {
            rt_scene *sc = rt_scene_new();
            int s = surf_plain(sc);
            const double fl[2][9] = {{-2, -2, 0, 2, -2, 0, 2, 2, 0}, {-2, -2, 0, 2, 2, 0, -2, 2, 0}};
            const double quad[12] = {-1.5, -1, 0, -0.5, -1, 0, -0.5, 1, 0, -1.5, 1, 0};
            const double pent[15] = {0, 0, 0, 1, 0, 0, 1.3, 0.8, 0, 0.5, 1.4, 0, -0.2, 0.8, 0};
            const double tri[9] = {1, -1.5, 0, 1.8, -1.5, 0, 1.4, -0.5, 0};
            const double mat[12] = {-1, -1, delta, 1, -1, delta, 1, 1, delta, -1, 1, delta};
            int want[3];
            if (part == 0) {
                add_local(sc, 3, fl[0], R, T, scale, s);
                add_local(sc, 3, fl[1], R, T, scale, s);
                want[0] = add_local(sc, 4, quad, R, T, scale, s);
                want[1] = add_local(sc, 5, pent, R, T, scale, s);
                want[2] = add_local(sc, 3, tri, R, T, scale, s);
            } else {
                want[0] = want[1] = want[2] = add_local(sc, 4, mat, R, T, scale, s);
                add_local(sc, 3, fl[0], R, T, scale, s);
                add_local(sc, 3, fl[1], R, T, scale, s);
            }
            assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
            /* targets well inside each rug (part B: inside the mat) */
            const double tg[3][2] = {{-1.0, 0.0}, {0.55, 0.6}, {1.4, -1.2}};
            const double rad[3] = {0.4, 0.35, 0.15};
            for (int k = 0; k < 60; k++) {
                const int r = k % 3;
                double lt[3] = {tg[r][0] + rad[r] * (2 * rtu_rand(&st) - 1),
                                tg[r][1] + rad[r] * (2 * rtu_rand(&st) - 1), part ? delta : 0.0};
                if (part)
                    lt[0] = 1.8 * rtu_rand(&st) - 0.9, lt[1] = 1.8 * rtu_rand(&st) - 0.9;
                const double h = 0.5 + 2.5 * rtu_rand(&st);
                double lo[3] = {lt[0] + 3 * h * (2 * rtu_rand(&st) - 1), lt[1] + 3 * h * (2 * rtu_rand(&st) - 1), h};
                double o[3], p[3], d[3];
                rot_point(R, T, scale, lo, o);
                rot_point(R, T, scale, lt, p);
                for (int i = 0; i < 3; i++)
                    d[i] = p[i] - o[i];
                rt_ray ray;
                ray_set(&ray, o, d);
                rt_hit hit;
                assert_int_equal(rt_intersect(sc, 1, &ray, &hit), RT_OK);
                nrays++;
                if (hit.prim != want[r]) {
                    if (part == 0)
                        wrong_a++;
                    else
                        wrong_b++;
                }
            }
            rt_scene_free(sc);
        }
    }
    printf("coplanar, rotated: %zu rays, %zu not on the later rug (A), %zu not on the lifted mat (B)\n",
           nrays, wrong_a, wrong_b);
    assert_int_equal(wrong_a, 0);
    assert_int_equal(wrong_b, 0);
}

/* ---- 6: difficult polygons ---- */

/* even-odd reference in 2-D (x, y) over all loops; distance of (x,y) to the outline in *dmin */
static int ref_inside(int nloops, const int *cnt, const double *v, double x, double y, double *dmin)
{
    int in = 0;
    double dm = INFINITY;
    size_t base = 0;
    for (int l = 0; l < nloops; l++) {
        int m = cnt[l];
        for (int e = 0, f = m - 1; e < m; f = e++) {
            const double *a = v + 3 * (base + (size_t)e), *b = v + 3 * (base + (size_t)f);
            if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
                in ^= 1;
            double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
            double s = l2 > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / l2 : 0.0;
            s = s < 0 ? 0 : s > 1 ? 1 : s;
            double dx = a[0] + s * ex - x, dy = a[1] + s * ey - y;
            double d = sqrt(dx * dx + dy * dy);
            if (d < dm)
                dm = d;
        }
        base += (size_t)m;
    }
    *dmin = dm;
    return in;
}

/* vertical rays over [x0,x1]x[y0,y1] against one polygon (z given per vertex): hits must
   agree with the 2-D even-odd reference away from the outline (margin); returns mismatches */
static size_t poly_check(const char *name, int nloops, const int *cnt, const double *v, double margin,
                         int expect_dropped)
{
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    assert_true(rt_scene_add_polygon(sc, nloops, cnt, v, s, s) >= 0);
    size_t nv = 0;
    double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (int l = 0; l < nloops; l++)
        nv += (size_t)cnt[l];
    for (size_t k = 0; k < nv; k++) {
        bb[0] = fmin(bb[0], v[3 * k]);
        bb[1] = fmax(bb[1], v[3 * k]);
        bb[2] = fmin(bb[2], v[3 * k + 1]);
        bb[3] = fmax(bb[3], v[3 * k + 1]);
    }
    for (int k = 0; k < 5; k++) { /* far padding so that the grid path is taken too */
        double a[3] = {100 + k, 100, 0}, b[3] = {101 + k, 100, 0}, c[3] = {100 + k, 101, 0};
        add_tri(sc, a, b, c, s);
    }
    enum { NP = 70 };
    rt_ray *rays = malloc(NP * NP * sizeof *rays);
    assert_non_null(rays);
    double wx = bb[1] - bb[0], wy = bb[3] - bb[2];
    for (int i = 0; i < NP; i++)
        for (int j = 0; j < NP; j++) {
            double o[3] = {bb[0] - 0.05 * wx + 1.1 * wx * (i + 0.31) / NP,
                           bb[2] - 0.05 * wy + 1.1 * wy * (j + 0.73) / NP, v[2] + 1e3}, d[3] = {0, 0, -1};
            ray_set(&rays[i * NP + j], o, d);
        }
    size_t bad = grid_vs_brute(sc, NULL, rays, NP * NP, NULL);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    rt_scene_grid_info(sc, &gi);
    rt_hit *h = malloc(NP * NP * sizeof *h);
    assert_non_null(h);
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, NP * NP, rays, h), RT_OK);
    rtc_traps_off();
    size_t checked = 0, wrong = 0, hits = 0;
    for (int k = 0; k < NP * NP; k++) {
        double dmin;
        int in = ref_inside(nloops, cnt, v, rays[k].org[0], rays[k].org[1], &dmin);
        if (expect_dropped)
            in = 0;
        hits += h[k].prim == 0;
        if (dmin < margin)
            continue;
        checked++;
        wrong += (h[k].prim == 0) != in;
    }
    printf("polygon %-22s: %zu rays checked, %zu hits, %zu wrong, %zu grid/brute mismatches%s\n", name,
           checked, hits, wrong, bad, expect_dropped ? " (dropped at commit)" : "");
    if (expect_dropped)
        assert_int_equal(gi.prims, 5);
    free(h);
    free(rays);
    rt_scene_free(sc);
    return wrong + bad;
}

static void test_polygons(void **state)
{
    (void)state;
    size_t bad = 0;
    double L[18] = {0, 0, 0, 3, 0, 0, 3, 1, 0, 1, 1, 0, 1, 3, 0, 0, 3, 0};
    int n6 = 6;
    bad += poly_check("concave L", 1, &n6, L, 1e-9, 0);
    double bow[12] = {0, 0, 0, 2, 2, 0, 2, 0, 0, 0, 2, 0};
    int n4 = 4;
    bad += poly_check("bow tie", 1, &n4, bow, 1e-9, 0);
    double star[15];
    for (int k = 0; k < 5; k++) { /* pentagram: the centre is outside by even-odd */
        double a = PI / 2 + 4 * PI * k / 5;
        star[3 * k] = cos(a);
        star[3 * k + 1] = sin(a);
        star[3 * k + 2] = 0.0;
    }
    int n5 = 5;
    bad += poly_check("pentagram", 1, &n5, star, 1e-9, 0);
    double rep[24] = {0, 0, 0, 0, 0, 0, 2, 0, 0, 2, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 0, 2, 0};
    int n8 = 8;
    bad += poly_check("repeated vertices", 1, &n8, rep, 1e-9, 0);
    double col[3 * 16];
    for (int k = 0; k < 16; k++) { /* square with 4 vertices on each edge, all collinear runs */
        int e = k / 4, j = k % 4;
        double t = j / 4.0;
        double pts[4][2] = {{t, 0}, {1, t}, {1 - t, 1}, {0, 1 - t}};
        col[3 * k] = 2 * pts[e][0];
        col[3 * k + 1] = 2 * pts[e][1];
        col[3 * k + 2] = 0.0;
    }
    int n16 = 16;
    bad += poly_check("collinear runs", 1, &n16, col, 1e-9, 0);
    double line[12] = {0, 0, 0, 1, 1, 0, 2, 2, 0, 3, 3, 0};
    bad += poly_check("all collinear", 1, &n4, line, 1e-9, 1);
    double np[18] = {0, 0, 1e-9, 2, 0, -1e-9, 3, 1, 2e-9, 2, 2, -1e-9, 0, 2, 1e-9, -1, 1, 0};
    bad += poly_check("non-planar 1e-9", 1, &n6, np, 1e-6, 0);
    double ring[24] = {0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0, 1, 1, 0, 1, 3, 0, 3, 3, 0, 3, 1, 0};
    int cnt2[2] = {4, 4};
    bad += poly_check("fill area set, hole", 2, cnt2, ring, 1e-9, 0);
    double hugev[12] = {1e6, 1e6, 1e6, 1e6 + 1, 1e6, 1e6, 1e6 + 1, 1e6 + 1, 1e6, 1e6 + 0.5, 1e6 + 0.2, 1e6};
    bad += poly_check("concave quad at 1e6", 1, &n4, hugev, 1e-6, 0);
    /* the 144-vertex polygons of SPD gears (in their own coordinates: horizontal) */
    rtu_mesh m;
    assert_int_equal(rtu_load_nff(RT_DATA_DIR "/spd/gears.nff.gz", &m), 0);
    size_t off = 0;
    int ngear = 0;
    double *buf = malloc(3 * 144 * sizeof *buf);
    assert_non_null(buf);
    for (int p = 0; p < m.np; p++) {
        int nv = m.counts[p];
        if (nv == 144 && ngear < 8) {
            for (int k = 0; k < nv; k++)
                memcpy(buf + 3 * k, m.xyz + 3 * (size_t)m.idx[off + (size_t)k], 3 * sizeof(double));
            bad += poly_check("gears 144-gon", 1, &nv, buf, 1e-9, 0);
            ngear++;
        }
        off += (size_t)nv;
    }
    assert_int_equal(ngear, 8);
    free(buf);
    rtu_mesh_free(&m);
    assert_int_equal(bad, 0);
}

/* all 128 gear polygons in one scene seen from above, against the 2-D reference */
static void test_gears_polygons(void **state)
{
    (void)state;
    rtu_mesh m;
    assert_int_equal(rtu_load_nff(RT_DATA_DIR "/spd/gears.nff.gz", &m), 0);
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    int *first = malloc((size_t)m.np * sizeof *first);
    assert_non_null(first);
    size_t off = 0;
    int np = 0;
    for (int p = 0; p < m.np; p++) {
        int nv = m.counts[p];
        first[p] = -1;
        if (nv == 144) {
            double *buf = malloc(3 * 144 * sizeof *buf);
            assert_non_null(buf);
            for (int k = 0; k < nv; k++)
                memcpy(buf + 3 * k, m.xyz + 3 * (size_t)m.idx[off + (size_t)k], 3 * sizeof(double));
            assert_int_equal(add_poly(sc, nv, buf, s), np);
            first[p] = (int)off;
            np++;
            free(buf);
        }
        off += (size_t)nv;
    }
    assert_int_equal(np, 128);
    enum { NR = 12000 };
    rt_ray *rays = malloc(NR * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 5;
    for (int k = 0; k < NR; k++) {
        double o[3] = {-2 + 4 * rtu_rand(&rng), -2 + 4 * rtu_rand(&rng), 10}, d[3] = {0, 0, -1};
        ray_set(&rays[k], o, d);
    }
    size_t bad = grid_vs_brute(sc, NULL, rays, NR, NULL);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_hit *h = malloc(NR * sizeof *h);
    assert_non_null(h);
    assert_int_equal(rt_intersect(sc, NR, rays, h), RT_OK);
    size_t wrong = 0, checked = 0, inside = 0;
    double *pv = malloc(128 * 3 * 144 * sizeof *pv), (*box)[4] = malloc(128 * sizeof *box);
    assert_non_null(pv);
    assert_non_null(box);
    for (int p = 0, id = 0; p < m.np; p++) {
        if (first[p] < 0)
            continue;
        double *buf = pv + 3 * 144 * id;
        box[id][0] = box[id][2] = INFINITY;
        box[id][1] = box[id][3] = -INFINITY;
        for (int q = 0; q < 144; q++) {
            memcpy(buf + 3 * q, m.xyz + 3 * (size_t)m.idx[(size_t)first[p] + (size_t)q], 3 * sizeof(double));
            box[id][0] = fmin(box[id][0], buf[3 * q]);
            box[id][1] = fmax(box[id][1], buf[3 * q]);
            box[id][2] = fmin(box[id][2], buf[3 * q + 1]);
            box[id][3] = fmax(box[id][3], buf[3 * q + 1]);
        }
        id++;
    }
    for (int k = 0; k < NR; k++) {
        double x = rays[k].org[0], y = rays[k].org[1], best = -INFINITY, dm_all = INFINITY;
        int want = -1;
        for (int id = 0; id < 128; id++) {
            if (x < box[id][0] - 1e-6 || x > box[id][1] + 1e-6 || y < box[id][2] - 1e-6 || y > box[id][3] + 1e-6)
                continue; /* outside its box: neither inside nor near its outline */
            const double *buf = pv + 3 * 144 * id;
            int n144 = 144;
            double dm;
            if (ref_inside(1, &n144, buf, x, y, &dm) && buf[2] > best) {
                best = buf[2];
                want = id;
            }
            if (dm < dm_all)
                dm_all = dm;
        }
        if (dm_all < 1e-9)
            continue;
        checked++;
        inside += want >= 0;
        wrong += h[k].prim != want;
    }
    printf("gears 144-gons: %zu rays checked (%zu inside), %zu wrong, %zu grid/brute mismatches\n",
           checked, inside, wrong, bad);
    assert_true(inside > NR / 10);
    assert_int_equal(wrong, 0);
    assert_int_equal(bad, 0);
    free(pv);
    free(box);
    free(h);
    free(rays);
    free(first);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

/* ---- 7: teapot in a stadium ---- */

static void test_teapot_stadium(void **state)
{
    (void)state;
    rtu_mesh m;
    assert_int_equal(rtu_load_nff(RT_DATA_DIR "/spd/teapot.nff.gz", &m), 0);
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    m.nsurfs = 0; /* one plain surface for all */
    m.nlights = 0;
    assert_int_equal(rtu_mesh_add(&m, sc, s), 0);
    double bb[6];
    rtu_mesh_bbox(&m, bb);
    double ext = fmax(bb[3] - bb[0], fmax(bb[4] - bb[1], bb[5] - bb[2]));
    /* ground 10^4 times the teapot, and four stadium walls */
    double G = 1e4 * ext, z = bb[2] - 1e-3 * ext;
    add_rect_z(sc, -G, -G, G, G, z, 1, s);
    double walls[4][12] = {{-G, -G, z, G, -G, z, G, -G, z + 0.1 * G, -G, -G, z + 0.1 * G},
                           {G, -G, z, G, G, z, G, G, z + 0.1 * G, G, -G, z + 0.1 * G},
                           {G, G, z, -G, G, z, -G, G, z + 0.1 * G, G, G, z + 0.1 * G},
                           {-G, G, z, -G, -G, z, -G, -G, z + 0.1 * G, -G, G, z + 0.1 * G}};
    for (int k = 0; k < 4; k++)
        add_poly(sc, 4, walls[k], s);
    enum { NR = 3000 };
    rt_ray *rays = malloc(NR * sizeof *rays);
    assert_non_null(rays);
    uint64_t rng = 77;
    double c[3] = {0.5 * (bb[0] + bb[3]), 0.5 * (bb[1] + bb[4]), 0.5 * (bb[2] + bb[5])};
    for (int k = 0; k < NR; k++) {
        double d[3], o[3], tg[3];
        rtu_rand_dir(&rng, d);
        for (int i = 0; i < 3; i++)
            tg[i] = c[i] + ext * (rtu_rand(&rng) - 0.5);
        double R = (k % 3 == 0) ? 0.05 * G : 3 * ext; /* from the stands / from close by */
        for (int i = 0; i < 3; i++)
            o[i] = tg[i] - R * d[i];
        if (o[2] < z)
            o[2] = z + 0.01 * ext;
        for (int i = 0; i < 3; i++)
            d[i] = tg[i] - o[i];
        ray_set(&rays[k], o, d);
    }
    size_t nhit = 0;
    size_t bad = grid_vs_brute(sc, NULL, rays, NR, &nhit);
    rt_grid_info gi, g1;
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    rt_build_options one = {.no_subgrids = 1};
    assert_int_equal(rt_scene_commit(sc, &one), RT_OK);
    assert_int_equal(rt_scene_grid_info(sc, &g1), RT_OK);
    printf("teapot in a stadium: %llu prims; grid %dx%dx%d (%s), %llu cells (%llu empty), refs/prim "
           "%.2f, %llu subgrids (%llu cells), max refs in a leaf %llu (single level: %llu), "
           "non-empty volume %.2e; %zu rays, %zu hits, %zu grid/brute mismatches\n",
           (unsigned long long)gi.prims, gi.res[0], gi.res[1], gi.res[2],
           gi.rotated ? "rotated" : "VRC3 axes", (unsigned long long)gi.cells,
           (unsigned long long)gi.empty_cells, (double)(gi.refs + gi.subrefs) / (double)gi.prims,
           (unsigned long long)gi.subgrids, (unsigned long long)gi.subcells,
           (unsigned long long)gi.max_leaf_refs, (unsigned long long)g1.max_leaf_refs,
           gi.volume_fill, (size_t)NR, nhit, bad);
    assert_int_equal(bad, 0);
    assert_true(nhit > NR / 2);
    /* not pathological: the dense teapot is resolved by the second level (a single level puts
       hundreds of triangles into one cell) and references stay bounded */
    assert_true(g1.max_leaf_refs > 4 * gi.max_leaf_refs);
    assert_true(gi.max_leaf_refs <= 96); /* second level: at most 32 cells per axis */
    assert_true(gi.refs + gi.subrefs <= 40 * gi.prims);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

/* ---- 8: dielectrics ---- */

/* A glass prism (index 1.5, kt 1, flat black, Fresnel off) seen from above: its top face z = 0
 * over x in [0,1]; its bottom face descends from (1,0) to (0,-tan a). Vertical rays enter
 * unbent and meet the bottom face at incidence a. For a = 40 deg (< critical 41.81) they leave
 * steeply downwards (34.6 deg from the vertical), pass below the green wall (x = -1,
 * z in [-1, 5]) and see the red floor z = -10; for a = 42.5 and 45 deg they are totally
 * reflected, leave nearly horizontally through the side face x = 0 and see the green wall. */
static void test_tir(void **state)
{
    (void)state;
    enum { TW = 16, TH = 16 };
    const double angles[3] = {40.0, 42.5, 45.0};
    float *rgb = malloc(TW * TH * 3 * sizeof(float));
    assert_non_null(rgb);
    for (int ai = 0; ai < 3; ai++) {
        double a = angles[ai] * PI / 180.0, hgt = tan(a);
        rt_scene *sc = rt_scene_new();
        rt_surface gl;
        rt_surface_default(&gl);
        gl.refl_eq = RT_REFL_NONE;
        gl.diffuse[0] = gl.diffuse[1] = gl.diffuse[2] = 0.0;
        gl.transparency = 1.0;
        gl.refr_index = 1.5;
        int g = rt_scene_add_surface(sc, &gl);
        int red = surf_flat(sc, 1, 0, 0), green = surf_flat(sc, 0, 1, 0);
        /* prism faces, outward normals (front = outside, entering glass) */
        double top[12] = {0, -2, 0, 1, -2, 0, 1, 2, 0, 0, 2, 0};
        double bot[12] = {0, -2, -hgt, 0, 2, -hgt, 1, 2, 0, 1, -2, 0};
        double side[12] = {0, -2, 0, 0, 2, 0, 0, 2, -hgt, 0, -2, -hgt};
        double cap0[9] = {0, -2, 0, 0, -2, -hgt, 1, -2, 0}, cap1[9] = {0, 2, 0, 1, 2, 0, 0, 2, -hgt};
        add_poly(sc, 4, top, g);
        add_poly(sc, 4, bot, g);
        add_poly(sc, 4, side, g);
        add_poly(sc, 3, cap0, g);
        add_poly(sc, 3, cap1, g);
        add_rect_z(sc, -50, -5, 50, 5, -10, 1, red); /* floor */
        double wall[12] = {-1, -5, -1, -1, 5, -1, -1, 5, 5, -1, -5, 5};
        add_poly(sc, 4, wall, green);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_camera cam;
        double win[4] = {0.3, 0.7, -0.2, 0.2}, prp[3] = {0.5, 0, 100};
        assert_int_equal(cam_parallel(&cam, win, 1, -30, prp, TW, TH), RT_OK);
        rt_render_options ro;
        rtu_options_plain(&ro);
        ro.threads = 1;
        ro.fresnel = RT_FRESNEL_NONE;
        ro.max_depth = 8;
        rt_stats st;
        render_checked(sc, &cam, &ro, rgb, &st);
        int tir = ai > 0;
        size_t wrong = 0;
        for (int k = 0; k < TW * TH; k++) {
            double want[3] = {tir ? 0.0 : 1.0, tir ? 1.0 : 0.0, 0.0};
            for (int c = 0; c < 3; c++)
                wrong += !(fabs(rgb[3 * k + c] - want[c]) <= 1e-6);
        }
        printf("TIR prism %.1f deg: %s, %zu wrong pixel values, refraction rays %llu, reflection %llu\n",
               angles[ai], tir ? "total internal reflection" : "refracted", wrong,
               (unsigned long long)st.refraction_rays, (unsigned long long)st.reflection_rays);
        assert_int_equal(wrong, 0);
        /* per eye ray: enter (1 refraction); TIR: 1 reflection + exit (1 refraction);
           otherwise exit (1 refraction) */
        assert_int_equal(st.refraction_rays, (uint64_t)(TW * TH * 2));
        assert_int_equal(st.reflection_rays, (uint64_t)(tir ? TW * TH : 0));
        rt_scene_free(sc);
    }
    free(rgb);
}

/* Nested media by relative indices: air | water 1.33 (z in [-1, 0]) containing a glass layer
 * 1.5 (z in [-0.6, -0.4]); the water/glass interfaces carry the index 1.5/1.33. Oblique
 * parallel rays (slope s = dx/dz) must reach the floor z = -2 displaced as Snell's law gives
 * layer by layer: x = x0 + sum thickness * tan(theta_layer). The floor is a cell array of 400
 * columns with distinct colours, so the column seen tells where the ray landed. */
static void test_nested_media(void **state)
{
    (void)state;
    enum { NW = 24, NH = 8, NC = 400 };
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    su.refl_eq = RT_REFL_NONE;
    su.diffuse[0] = su.diffuse[1] = su.diffuse[2] = 0.0;
    su.transparency = 1.0;
    su.refr_index = 1.33;
    int water = rt_scene_add_surface(sc, &su);
    su.refr_index = 1.5 / 1.33;
    int glass = rt_scene_add_surface(sc, &su);
    int floor_s = surf_flat(sc, 1, 1, 1);
    add_rect_z(sc, -20, -20, 20, 20, 0.0, 1, water);   /* air -> water, front up */
    add_rect_z(sc, -20, -20, 20, 20, -0.4, 1, glass);  /* water -> glass, front up */
    add_rect_z(sc, -20, -20, 20, 20, -0.6, 0, glass);  /* glass -> water: back side hit */
    add_rect_z(sc, -20, -20, 20, 20, -1.0, 0, water);  /* water -> air: back side hit */
    float *cols = malloc(3 * NC * sizeof(float));
    assert_non_null(cols);
    for (int i = 0; i < NC; i++) {
        cols[3 * i] = (float)(i % 20) / 19.0f;
        cols[3 * i + 1] = (float)(i / 20) / 19.0f;
        cols[3 * i + 2] = 0.5f;
    }
    double P[3] = {-4, -1, -2}, R[3] = {4, -1, -2}, Q[3] = {4, 1, -2};
    assert_true(rt_scene_add_cell_array(sc, P, Q, R, NC, 1, cols, floor_s, floor_s) >= 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    /* oblique parallel projection: direction of projection (dx, 0, -1) with dx = 0.7 */
    const double sl = 0.7;
    rt_camera cam;
    double win[4] = {-1.5, -0.5, -0.2, 0.2}, prp[3] = {-1.0 - sl * 10, 0, 10.5}; /* vpd 0.5 */
    assert_int_equal(cam_parallel(&cam, win, 0.5, -3, prp, NW, NH), RT_OK);
    rt_render_options ro;
    rtu_options_plain(&ro);
    ro.threads = 1;
    ro.fresnel = RT_FRESNEL_NONE;
    ro.max_depth = 8;
    float *rgb = malloc(NW * NH * 3 * sizeof(float));
    assert_non_null(rgb);
    rt_stats st;
    render_checked(sc, &cam, &ro, rgb, &st);
    double s0 = sl / sqrt(1 + sl * sl); /* sin of the incidence angle in air */
    double tw = tan(asin(s0 / 1.33)), tg = tan(asin(s0 / 1.5));
    size_t wrong = 0, checked = 0;
    for (int r = 0; r < NH; r++)
        for (int i = 0; i < NW; i++) {
            rt_ray ray;
            assert_int_equal(rt_camera_ray(&cam, i + 0.5, r + 0.5, &ray), RT_OK);
            double t0 = -ray.org[2] / ray.dir[2];
            double x0 = ray.org[0] + t0 * ray.dir[0];
            double x = x0 + 0.4 * tw + 0.2 * tg + 0.4 * tw + 1.0 * sl; /* water, glass, water, air */
            double f = (x + 4.0) / 8.0 * NC;
            if (fabs(f - floor(f + 0.5)) < 1e-6)
                continue;
            int col = (int)floor(f);
            checked++;
            const float *px = rgb + 3 * (r * NW + i);
            wrong += px[0] != cols[3 * col] || px[1] != cols[3 * col + 1];
        }
    printf("nested media: %zu pixels checked, %zu land in the wrong column (refraction rays %llu)\n",
           checked, wrong, (unsigned long long)st.refraction_rays);
    assert_true(checked > NW * NH / 2);
    assert_int_equal(wrong, 0);
    assert_int_equal(st.refraction_rays, (uint64_t)(4 * NW * NH));
    free(rgb);
    free(cols);
    rt_scene_free(sc);
}

/* Index exactly 1: a transparent (kt = 1) flat black sheet with index 1 in front of a lit scene
 * leaves the image behind unchanged. Tolerance 1e-9 relative: the ray continues on its own
 * line from a new origin, which moves the hit points behind by rounding only. */
static void test_index_one(void **state)
{
    (void)state;
    enum { IW = 32, IH = 32 };
    float *a = malloc(IW * IH * 3 * sizeof(float)), *b = malloc(IW * IH * 3 * sizeof(float));
    assert_non_null(a);
    assert_non_null(b);
    for (int with = 0; with < 2; with++) {
        rt_scene *sc = rt_scene_new();
        rt_surface lit;
        rt_surface_default(&lit);
        lit.ka = 0.2;
        lit.kd = 0.7;
        lit.diffuse[1] = 0.5;
        int s = rt_scene_add_surface(sc, &lit);
        rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
        rt_light pl = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .position = {1, 2, 6}, .c1 = 1};
        rt_scene_add_light(sc, &amb);
        rt_scene_add_light(sc, &pl);
        add_rect_z(sc, -3, -3, 3, 3, -1, 1, s);
        double t0[3] = {-1, -1, 0}, t1[3] = {1, -0.5, 0.5}, t2[3] = {0, 1, 1};
        add_tri(sc, t0, t1, t2, s);
        if (with) {
            rt_surface gl;
            rt_surface_default(&gl);
            gl.refl_eq = RT_REFL_NONE;
            gl.diffuse[0] = gl.diffuse[1] = gl.diffuse[2] = 0.0;
            gl.transparency = 1.0;
            gl.refr_index = 1.0;
            int g = rt_scene_add_surface(sc, &gl);
            double sheet[12] = {-4, -4, 2, 4, -4, 2.5, 4, 4, 2.5, -4, 4, 2};
            add_poly(sc, 4, sheet, g); /* tilted, also crossed by the shadow rays */
        }
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_camera cam;
        double win[4] = {-2, 2, -2, 2}, prp[3] = {0.3, 0.2, 20};
        assert_int_equal(cam_parallel(&cam, win, 4, -4, prp, IW, IH), RT_OK);
        rt_render_options ro;
        rtu_options_plain(&ro);
        ro.threads = 1;
        render_checked(sc, &cam, &ro, with ? b : a, NULL);
        rt_scene_free(sc);
    }
    size_t diff = 0;
    for (int k = 0; k < IW * IH * 3; k++)
        diff += !(fabs(a[k] - b[k]) <= 1e-9 * fmax(1.0, fabs(a[k])));
    printf("index 1 sheet: %d values, %zu differ\n", IW * IH * 3, diff);
    assert_int_equal(diff, 0);
    free(a);
    free(b);
}

/* ---- 9: near-singular viewing ---- */

/* camera rays must be finite with unit direction and agree with the projector computed
   directly from the view parameters (relative tolerance tol) */
static size_t check_rays(const rt_camera *cam, const rtu_view *v, double tol)
{
    size_t bad = 0;
    for (int k = 0; k <= 8; k++)
        for (int j = 0; j <= 8; j++) {
            double px = cam->width * k / 8.0, py = cam->height * j / 8.0;
            rt_ray r;
            if (rt_camera_ray(cam, px, py, &r) != RT_OK) {
                bad++;
                continue;
            }
            double l = sqrt(r.dir[0] * r.dir[0] + r.dir[1] * r.dir[1] + r.dir[2] * r.dir[2]);
            int fin = isfinite(r.tmax) && r.tmax > 0;
            for (int i = 0; i < 3; i++)
                fin &= isfinite(r.org[i]) && isfinite(r.dir[i]);
            if (!fin || fabs(l - 1.0) > 1e-12) {
                bad++;
                continue;
            }
            double x = v->vp[0] + px / cam->width * (v->vp[1] - v->vp[0]);
            double y = v->vp[3] - py / cam->height * (v->vp[3] - v->vp[2]);
            double f[3], b[3];
            rtu_view_projector(v, x, y, f, b);
            double sc = fmax(1.0, fmax(fabs(f[0]), fmax(fabs(f[1]), fabs(f[2]))));
            double sb = fmax(1.0, fmax(fabs(b[0]), fmax(fabs(b[1]), fabs(b[2]))));
            for (int i = 0; i < 3; i++) {
                bad += !(fabs(r.org[i] - f[i]) <= tol * sc);
                bad += !(fabs(r.org[i] + r.tmax * r.dir[i] - b[i]) <= tol * sb);
            }
        }
    return bad;
}

static void test_near_singular_view(void **state)
{
    (void)state;
    rt_camera cam;
    double m[4][4];
    size_t bad = 0;
    /* near/far ratio 1e-7: PRP at n = 1, front plane 1e-7 below it, back plane at n = 0 */
    rtu_view v1 = {.win = {-0.5, 0.5, -0.5, 0.5}, .prp = {0, 0, 1}, .vpd = 0.5, .fpd = 1 - 1e-7,
                   .bpd = 0.0, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    rtu_view_matrix(&v1, m);
    int rc = rt_camera_from_view(&cam, m, v1.vp, 64, 64);
    printf("near/far 1e-7: rc %d\n", rc);
    assert_true(rc == RT_OK || rc == RT_ERR_SINGULAR);
    if (rc == RT_OK)
        bad += check_rays(&cam, &v1, 1e-6);
    /* window aspect 1e4 */
    rtu_view v2 = {.win = {-1e2, 1e2, -1e-2, 1e-2}, .prp = {0, 0, 10}, .vpd = 0, .fpd = 1,
                   .bpd = -1, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    rtu_view_matrix(&v2, m);
    rc = rt_camera_from_view(&cam, m, v2.vp, 256, 16);
    printf("window aspect 1e4: rc %d\n", rc);
    assert_int_equal(rc, RT_OK);
    bad += check_rays(&cam, &v2, 1e-9);
    /* PRP at 1e8: nearly parallel */
    rtu_view v3 = {.win = {-1, 1, -1, 1}, .prp = {0.1, 0.2, 1e8}, .vpd = 0, .fpd = 0.5, .bpd = -0.5,
                   .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    rtu_view_matrix(&v3, m);
    rc = rt_camera_from_view(&cam, m, v3.vp, 32, 32);
    printf("PRP at 1e8: rc %d\n", rc);
    assert_true(rc == RT_OK || rc == RT_ERR_SINGULAR);
    if (rc == RT_OK) {
        bad += check_rays(&cam, &v3, 1e-6);
        /* a picture: a quad seen through it covers the pixels it projects to */
        rt_scene *sc = rt_scene_new();
        int s = surf_flat(sc, 1, 1, 1);
        add_rect_z(sc, -0.5, -0.5, 0.5, 0.5, 0.0, 1, s);
        for (int k = 0; k < 5; k++)
            add_rect_z(sc, 10 + k, 10, 10.5 + k, 10.5, 0, 1, s);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        float *rgb = malloc(32 * 32 * 3 * sizeof(float));
        assert_non_null(rgb);
        rt_render_options ro;
        rtu_options_plain(&ro);
        ro.threads = 1;
        render_checked(sc, &cam, &ro, rgb, NULL);
        size_t wrong = 0;
        for (int r = 0; r < 32; r++)
            for (int i = 0; i < 32; i++) {
                /* window [-1,1]^2 at n = 0 maps to the raster; the quad is [-0.5,0.5]^2 */
                double x = -1 + 2 * (i + 0.5) / 32, y = 1 - 2 * (r + 0.5) / 32;
                int in = fabs(x) < 0.5 && fabs(y) < 0.5;
                if (fabs(fabs(x) - 0.5) < 0.07 || fabs(fabs(y) - 0.5) < 0.07)
                    continue; /* pixels at the quad's outline */
                wrong += (rgb[3 * (r * 32 + i)] == 1.0f) != in;
            }
        printf("PRP at 1e8 picture: %zu wrong pixels\n", wrong);
        assert_int_equal(wrong, 0);
        free(rgb);
        rt_scene_free(sc);
    }
    /* view orientation with up 1e-10 rad from the view plane normal: still orthonormal */
    double from[3] = {0, 0, 5}, at[3] = {0, 0, 0}, up[3] = {1e-10, 0, 1}, vo[4][4];
    rtu_lookat(from, at, up, vo);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            bad += !isfinite(vo[i][j]);
    /* singular and nearly singular view mapping matrices: clean error, never garbage */
    double sing[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}};
    double box[6] = {0, 1, 0, 1, 0, 1};
    assert_int_equal(rt_camera_from_view(&cam, sing, box, 8, 8), RT_ERR_SINGULAR);
    sing[2][2] = 1e-300;
    rc = rt_camera_from_view(&cam, sing, box, 8, 8);
    assert_true(rc == RT_ERR_SINGULAR || rc == RT_OK);
    if (rc == RT_OK)
        for (int k = 0; k < 8; k++)
            for (int i = 0; i < 3; i++)
                bad += !isfinite(cam.corner[k][i]);
    /* PRP inside the view volume (between front and back planes): w changes sign */
    rtu_view v4 = {.win = {-1, 1, -1, 1}, .prp = {0, 0, 0}, .vpd = -1, .fpd = 1, .bpd = -2,
                   .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    rtu_view_matrix(&v4, m);
    rc = rt_camera_from_view(&cam, m, v4.vp, 8, 8);
    printf("PRP between front and back planes: rc %d\n", rc);
    assert_true(rc != RT_OK);
    printf("near-singular viewing: %zu bad rays/values\n", bad);
    assert_int_equal(bad, 0);
}

/* ---- 10: NaN / Inf ---- */

static void test_nan_inf(void **state)
{
    (void)state;
    const double nan = NAN, inf = INFINITY;
    rt_scene *sc = rt_scene_new();
    int s = surf_plain(sc);
    /* surfaces, lights, cell arrays with NaN/Inf: refused */
    rt_surface bs;
    rt_surface_default(&bs);
    bs.kd = nan;
    assert_int_equal(rt_scene_add_surface(sc, &bs), RT_ERR_ARG);
    rt_surface_default(&bs);
    bs.refr_index = inf;
    assert_int_equal(rt_scene_add_surface(sc, &bs), RT_ERR_ARG);
    rt_light l = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .position = {0, nan, 0}, .c1 = 1};
    assert_int_equal(rt_scene_add_light(sc, &l), RT_ERR_ARG);
    rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, inf, 1}, .direction = {0, 0, -1}};
    assert_int_equal(rt_scene_add_light(sc, &dl), RT_ERR_ARG);
    dl.color[1] = 1.0;
    dl.direction[0] = inf;
    assert_int_equal(rt_scene_add_light(sc, &dl), RT_ERR_ARG);
    dl.direction[0] = 0.3;
    assert_true(rt_scene_add_light(sc, &dl) >= 0);
    rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.1, 0.1, 0.1}};
    assert_true(rt_scene_add_light(sc, &amb) >= 0);
    float badcol[3] = {0.5f, NAN, 0.5f};
    double P[3] = {0, 0, 0}, Q[3] = {1, 1, 0}, R[3] = {1, 0, 0};
    assert_int_equal(rt_scene_add_cell_array(sc, P, Q, R, 1, 1, badcol, s, s), RT_ERR_ARG);
    /* primitives with NaN, Inf, huge coordinates: accepted, dropped at commit */
    double good[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    const double poison[5] = {NAN, INFINITY, -INFINITY, 1e300, -1e101};
    int kept = 0;
    assert_true(add_poly(sc, 4, good, s) >= 0);
    kept++;
    for (int k = 0; k < 5; k++)
        for (int v = 0; v < 3; v++) {
            double t[9] = {0, 0, 0.5, 1, 0, 0.5, 0, 1, 0.5};
            t[3 * v + k % 3] = poison[k];
            assert_true(add_poly(sc, 3, t, s) >= 0);
        }
    double ok_big[9] = {-1e100, -1e100, -2, 1e100, -1e100, -2, 0, 1e100, -2}; /* huge, finite */
    assert_true(add_poly(sc, 3, ok_big, s) >= 0);
    kept++;
    for (int k = 0; k < 6; k++) {
        double t[9] = {5 + k, 5, 0, 6 + k, 5, 0, 5 + k, 6, 0};
        add_poly(sc, 3, t, s);
        kept++;
    }
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_grid_info gi;
    assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
    assert_int_equal(gi.prims, (uint64_t)kept);
    /* rays with NaN/Inf anywhere: misses, never a crash (traps on: no invalid operation) */
    const double o0[3] = {0, 0, 5}, d0[3] = {0, 0, -1};
    rt_ray rays[16];
    for (int k = 0; k < 16; k++)
        ray_set(&rays[k], o0, d0);
    rays[0].org[0] = nan;
    rays[1].org[1] = inf;
    rays[2].dir[2] = nan;
    rays[3].dir[0] = -inf;
    rays[4].tmin = nan;
    rays[5].tmax = nan;
    rays[6].tmin = inf;
    rays[7].tmin = 3.0;
    rays[7].tmax = 1.0;
    rays[8].dir[2] = 0.0; /* zero direction */
    rays[9].dir[2] = -1e-300;
    rays[10].org[2] = 1e200;
    rays[11].tmin = -inf;
    rays[12].dir[0] = 1e-320; /* subnormal component: fine */
    rt_hit h[16];
    unsigned char occ[16];
    rtc_traps_on();
    assert_int_equal(rt_intersect(sc, 16, rays, h), RT_OK);
    assert_int_equal(rt_occluded(sc, 16, rays, occ), RT_OK);
    rtc_traps_off();
    for (int k = 0; k <= 11; k++) {
        assert_int_equal(h[k].prim, -1);
        assert_int_equal(occ[k], 0);
    }
    assert_int_equal(h[12].prim, 0);
    assert_int_equal(h[13].prim, 0);
    assert_true(isfinite(h[12].t) && isfinite(h[12].p[0]));
    /* matrices with NaN/Inf: clean errors */
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    double box[6] = {0, 1, 0, 1, 0, 1};
    rt_camera cam;
    m[1][2] = nan;
    assert_int_equal(rt_camera_from_view(&cam, m, box, 8, 8), RT_ERR_SINGULAR);
    m[1][2] = inf;
    assert_int_equal(rt_camera_from_view(&cam, m, box, 8, 8), RT_ERR_SINGULAR);
    m[1][2] = 0.0;
    double bbox_nan[6] = {0, 1, nan, 1, 0, 1};
    assert_int_equal(rt_camera_from_view(&cam, m, bbox_nan, 8, 8), RT_ERR_ARG);
    /* a picture of it all: no NaN pixels (huge triangle included) */
    rt_camera cam2;
    double win[4] = {-2, 2, -2, 2}, prp[3] = {0, 0, 50};
    assert_int_equal(cam_parallel(&cam2, win, 5, -5, prp, 24, 24), RT_OK);
    rt_ray out;
    assert_int_equal(rt_camera_ray(&cam2, nan, 1.0, &out), RT_ERR_ARG);
    float *rgb = malloc(24 * 24 * 3 * sizeof(float));
    assert_non_null(rgb);
    rt_render_options ro;
    rtu_options_plain(&ro);
    ro.threads = 1;
    ro.background[0] = nan;
    assert_int_equal(rt_render(sc, &cam2, &ro, rgb, NULL), RT_ERR_ARG);
    ro.background[0] = 0.0;
    ro.cutoff = inf;
    assert_int_equal(rt_render(sc, &cam2, &ro, rgb, NULL), RT_ERR_ARG);
    ro.cutoff = 0.0;
    render_checked(sc, &cam2, &ro, rgb, NULL);
    free(rgb);
    rt_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_leak_probe),        cmocka_unit_test(test_shared_diagonal),
        cmocka_unit_test(test_reintersection),    cmocka_unit_test(test_shadow_acne),
        cmocka_unit_test(test_box_room),          cmocka_unit_test(test_rotated_grid),
        cmocka_unit_test(test_grid_frame_choice),
        cmocka_unit_test(test_grid_levels),
        cmocka_unit_test(test_coplanar),          cmocka_unit_test(test_coplanar_rotated),
        cmocka_unit_test(test_polygons),          cmocka_unit_test(test_gears_polygons),
        cmocka_unit_test(test_teapot_stadium),    cmocka_unit_test(test_tir),
        cmocka_unit_test(test_nested_media),      cmocka_unit_test(test_index_one),
        cmocka_unit_test(test_near_singular_view), cmocka_unit_test(test_nan_inf),
    };
    const char *filter = getenv("RT_TEST_FILTER"); /* e.g. RT_TEST_FILTER=test_tir */
    if (filter)
        cmocka_set_test_filter(filter);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
