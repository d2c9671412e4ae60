/* SPDX-License-Identifier: MIT */
/*
 * test_rt_shade.c -- the frame loop against an independent evaluation through the public ray
 * API: rt_camera_ray bit for bit equal to the direct formula (NPC point through the inverse
 * view mapping, front and back planes, unit direction); every eye ray of rt_render must be exactly the ray of rt_camera_ray (same primitive
 * hit as rt_intersect on it, for flat-coloured triangles), corner pictures must be the exact
 * mean of their four corner colours (also for rasters not a multiple of the tile size, a
 * single pixel or a single row, and for any thread count), and lights close to the surface
 * plane must be lit or unlit exactly by the sign of N.L (the renderer rejects lights behind
 * the surface early). Tolerances: exact (bit-identical floats) where the expected value is
 * formed with the same float conversions; 1e-7 relative (float output) for the grazing light.
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

/* Scene 0: a tilted sheet of 2*NX*NY flat triangles of distinct colours over [-1,1]^2 (z from
   -3 to -2.5) and a smaller sheet in front of it. Scene 1 (eye ray culling near small
   primitives, all primitive kinds): the first sheet, NSMALL scattered triangles of a few
   pixels, a concave polygon with a hole, a convex quad and a one-colour cell array. Scene 2
   (eye ray culling by a mask: more than 16 primitives per ray, rt_render.c): the first sheet
   behind NSTACK large tilted quads that end left of its right edge. Colour of primitive id k
   in col[k]. */
enum { NX = 11, NY = 7, NTRI = 2 * NX * NY * 2, NSMALL = 40, NPRIM = NTRI + NSMALL + 3, NSTACK = 40 };

typedef struct shade_scene {
    rt_scene *sc;
    double col[NPRIM][3];
    int ntri;
} shade_scene;

/* a flat surface of a new colour for primitive id s->ntri */
static int new_surface(shade_scene *s)
{
    int k = s->ntri;
    rt_surface su;
    rt_surface_default(&su);
    su.refl_eq = RT_REFL_NONE;
    for (int i = 0; i < 3; i++)
        su.diffuse[i] = s->col[k][i] = fmod(0.1234567 * (k + 1) * (i + 2) + 0.01 * i, 1.0);
    int sid = rt_scene_add_surface(s->sc, &su);
    assert_true(sid >= 0);
    return sid;
}

static void add_poly(shade_scene *s, int nloops, const int *counts, const double *v)
{
    int sid = new_surface(s);
    assert_int_equal(rt_scene_add_polygon(s->sc, nloops, counts, v, sid, sid), s->ntri);
    s->ntri++;
}

static void add_tri(shade_scene *s, const double *a, const double *b, const double *c)
{
    double v[9];
    memcpy(v, a, 3 * sizeof(double));
    memcpy(v + 3, b, 3 * sizeof(double));
    memcpy(v + 6, c, 3 * sizeof(double));
    int n = 3;
    add_poly(s, 1, &n, v);
}

static void add_others(shade_scene *s)
{
    uint32_t r = 12345;
    for (int k = 0; k < NSMALL; k++) {
        double q[3];
        for (int i = 0; i < 3; i++) {
            r = r * 1664525u + 1013904223u;
            q[i] = (double)(r >> 8) / 16777216.0;
        }
        double cx = -0.9 + 1.9 * q[0], cy = -0.85 + 1.8 * q[1], z = -1.2 - 0.5 * q[2];
        double e = 0.01 + 0.02 * q[2];
        double a[3] = {cx, cy, z}, b[3] = {cx + e, cy + 0.3 * e, z}, c[3] = {cx + 0.2 * e, cy + e, z + e};
        add_tri(s, a, b, c);
    }
    /* concave outline (an L) with a square hole, slightly tilted */
    double pl[] = {-0.8, 0.3, -1.6,  -0.3, 0.3, -1.62, -0.3, 0.45, -1.62, -0.6, 0.45, -1.61,
                   -0.6, 0.8, -1.61, -0.8, 0.8, -1.6,
                   -0.75, 0.5, -1.6, -0.65, 0.5, -1.6, -0.65, 0.6, -1.6, -0.75, 0.6, -1.6};
    int cnt[2] = {6, 4};
    add_poly(s, 2, cnt, pl);
    double qd[] = {0.3, -0.8, -1.4, 0.5, -0.78, -1.45, 0.48, -0.6, -1.45, 0.32, -0.62, -1.4};
    int four = 4;
    add_poly(s, 1, &four, qd);
    int sid = new_surface(s);
    float rgb[3 * 6];
    for (int i = 0; i < 6; i++)
        for (int c = 0; c < 3; c++)
            rgb[3 * i + c] = (float)s->col[s->ntri][c];
    for (int c = 0; c < 3; c++)
        s->col[s->ntri][c] = rgb[c];
    const double P[3] = {0.55, 0.35, -1.3}, R[3] = {0.75, 0.4, -1.35}, Q[3] = {0.7, 0.6, -1.35};
    assert_int_equal(rt_scene_add_cell_array(s->sc, P, Q, R, 3, 2, rgb, sid, sid), s->ntri);
    s->ntri++;
}

static void add_sheet(shade_scene *s, double x0, double x1, double y0, double y1, double z0, double dz)
{
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            double xa = x0 + (x1 - x0) * i / NX, xb = x0 + (x1 - x0) * (i + 1) / NX;
            double ya = y0 + (y1 - y0) * j / NY, yb = y0 + (y1 - y0) * (j + 1) / NY;
            double p00[3] = {xa, ya, z0 + dz * xa}, p10[3] = {xb, ya, z0 + dz * xb};
            double p01[3] = {xa, yb, z0 + dz * xa}, p11[3] = {xb, yb, z0 + dz * xb};
            add_tri(s, p00, p10, p11);
            add_tri(s, p00, p11, p01);
        }
}

static void add_stack(shade_scene *s)
{
    for (int k = 0; k < NSTACK; k++) {
        const double z = -1.5 - 0.04 * k, t = 0.01 * (k % 5 - 2);
        const double q[] = {-4.0, -4.0, z - 4.0 * t, 0.6, -4.0, z + 0.6 * t,
                            0.6, 4.0, z + 0.6 * t + 0.02, -4.0, 4.0, z - 4.0 * t + 0.02};
        int four = 4;
        add_poly(s, 1, &four, q);
    }
}

static void make_scene(shade_scene *s, int which)
{
    memset(s, 0, sizeof *s);
    s->sc = rt_scene_new();
    assert_non_null(s->sc);
    add_sheet(s, -1.0, 1.0, -1.0, 1.0, -2.75, 0.25);
    if (which == 0) {
        add_sheet(s, -0.4, 0.5, -0.3, 0.6, -2.0, -0.1);
        assert_int_equal(s->ntri, NTRI);
    } else if (which == 1) {
        add_others(s);
    } else {
        add_stack(s);
    }
    assert_int_equal(rt_scene_commit(s->sc, NULL), RT_OK);
}

/* Cameras: 0 perspective at the origin looking down -z, the window wider than the sheets (some
   rays miss); 1 oblique perspective from off the axis; 2 parallel; 3 perspective with the eye
   between the scattered triangles and the sheet (primitives behind the eye plane); 4 as 1
   with a display volume that is a part of NPC space. */
enum { NCAM = 5 };
static void make_camera(rt_camera *cam, int w, int h, int variant)
{
    rtu_view v = {.win = {-0.5, 0.55, -0.45, 0.5}, .prp = {0.02, -0.01, 0.0}, .vpd = -1.0,
                  .bpd = -10.0, .fpd = -0.5, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    if (variant == 1 || variant == 4) {
        v.prp[0] = 0.35;
        v.prp[1] = 0.2;
        v.prp[2] = 0.3;
        v.win[0] = -0.6;
        v.win[3] = 0.4;
    } else if (variant == 2) {
        v.perspective = 0;
        v.prp[2] = 50.0;
        v.win[0] = -1.1;
        v.win[1] = 1.05;
        v.win[2] = -1.0;
        v.win[3] = 1.1;
    } else if (variant == 3) {
        v.prp[2] = -1.3;
        v.vpd = -1.8;
        v.fpd = -1.35;
        v.win[0] = -0.3;
        v.win[1] = 0.25;
        v.win[2] = -0.2;
        v.win[3] = 0.3;
    }
    double m[4][4];
    rtu_view_matrix(&v, m);
    const double sub[6] = {0.1, 0.8, 0.25, 0.9, 0.1, 0.95};
    assert_int_equal(rt_camera_from_view(cam, m, variant == 4 ? sub : v.vp, w, h), RT_OK);
}

/* colour (as the renderer stores it, float) of the ray through raster point (px, py) */
static void ray_colour(const shade_scene *s, const rt_camera *cam, const double bg[3], double px,
                       double py, float out[3])
{
    rt_ray r;
    rt_hit h;
    assert_int_equal(rt_camera_ray(cam, px, py, &r), RT_OK);
    assert_int_equal(rt_intersect(s->sc, 1, &r, &h), RT_OK);
    for (int c = 0; c < 3; c++)
        out[c] = (float)(h.prim < 0 ? bg[c] : s->col[h.prim][c]);
}

/* corner picture w x h of scene s through camera variant cam: exact mean of corner colours,
   1 to 3 threads; counts background and hit corners */
static void check_corners(const shade_scene *s, int camv, int w, int h, size_t *nbg, size_t *nhit)
{
    const double bg[3] = {0.3, 0.2, 0.1};
    rt_camera cam;
    make_camera(&cam, w, h, camv);
    float *corner = malloc((size_t)(w + 1) * (h + 1) * 3 * sizeof(float));
    float *expect = malloc((size_t)w * h * 3 * sizeof(float));
    float *got = malloc((size_t)w * h * 3 * sizeof(float));
    assert_true(corner && expect && got);
    for (int y = 0; y <= h; y++)
        for (int x = 0; x <= w; x++) {
            float *k = corner + 3 * ((size_t)y * (w + 1) + x);
            ray_colour(s, &cam, bg, x, y, k);
            if (k[0] == (float)bg[0] && k[1] == (float)bg[1])
                (*nbg)++;
            else
                (*nhit)++;
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int c = 0; c < 3; c++) {
                const float *k = corner + 3 * ((size_t)y * (w + 1) + x) + c;
                size_t r = 3 * (size_t)(w + 1);
                double v = 0.25 * ((double)k[0] + k[3] + k[r] + k[r + 3]);
                expect[3 * ((size_t)y * w + x) + c] = (float)v;
            }
    rt_render_options o;
    rtu_options_plain(&o);
    o.corner_rays = 1;
    memcpy(o.background, bg, sizeof bg);
    for (int t = 1; t <= 3; t++) {
        rt_stats st;
        o.threads = t;
        memset(got, 0xff, (size_t)w * h * 3 * sizeof(float)); /* NaN: all must be written */
        rtc_traps_on();
        assert_int_equal(rt_render(s->sc, &cam, &o, got, &st), RT_OK);
        rtc_traps_off();
        assert_memory_equal(got, expect, (size_t)w * h * 3 * sizeof(float));
        assert_int_equal(st.eye_rays, (uint64_t)(w + 1) * (h + 1));
    }
    free(corner);
    free(expect);
    free(got);
}

static void test_corner_pictures(void **state)
{
    (void)state;
    static const int sizes[][2] = {{37, 23}, {1, 1}, {1, 7}, {17, 1}, {16, 16}, {33, 18}};
    for (int which = 0; which < 3; which++) {
        shade_scene s;
        make_scene(&s, which);
        for (int camv = 0; camv < NCAM; camv++) {
            size_t nbg = 0, nhit = 0;
            for (size_t z = 0; z < sizeof sizes / sizeof sizes[0]; z++)
                check_corners(&s, camv, sizes[z][0], sizes[z][1], &nbg, &nhit);
            check_corners(&s, camv, 160, 120, &nbg, &nhit); /* small primitives: a few pixels */
            assert_true(nhit > 0);
            assert_true(nbg > 0 || (which == 2 && camv >= 3)); /* the stack fills views 3, 4 */
        }
        rt_scene_free(s.sc);
    }
}

static void test_centre_pictures(void **state)
{
    (void)state;
    const double bg[3] = {0.0, 0.5, 1.0};
    const int w = 141, h = 99;
    float *expect = malloc((size_t)w * h * 3 * sizeof(float));
    float *got = malloc((size_t)w * h * 3 * sizeof(float));
    assert_true(expect && got);
    for (int which = 0; which < 3; which++) {
        shade_scene s;
        make_scene(&s, which);
        for (int camv = 0; camv < NCAM; camv++) {
            rt_camera cam;
            make_camera(&cam, w, h, camv);
            for (int y = 0; y < h; y++)
                for (int x = 0; x < w; x++)
                    ray_colour(&s, &cam, bg, x + 0.5, y + 0.5, expect + 3 * ((size_t)y * w + x));
            rt_render_options o;
            rtu_options_plain(&o);
            memcpy(o.background, bg, sizeof bg);
            for (int t = 1; t <= 2; t++) {
                rt_stats st;
                o.threads = t;
                rtc_traps_on();
                assert_int_equal(rt_render(s.sc, &cam, &o, got, &st), RT_OK);
                rtc_traps_off();
                assert_memory_equal(got, expect, (size_t)w * h * 3 * sizeof(float));
                assert_int_equal(st.eye_rays, (uint64_t)w * h);
            }
        }
        rt_scene_free(s.sc);
    }
    free(expect);
    free(got);
}

/* a large picture (prefaulted output, several tiles) equals the same picture rendered into a
   buffer whose pages were already written */
static void test_large_picture(void **state)
{
    (void)state;
    shade_scene s;
    make_scene(&s, 1);
    const int w = 211, h = 157;
    rt_camera cam;
    make_camera(&cam, w, h, 0);
    size_t n = (size_t)w * h * 3;
    float *a = malloc(n * sizeof(float)), *b = malloc(n * sizeof(float));
    assert_true(a && b);
    memset(b, 0, n * sizeof(float));
    rt_render_options o;
    rtu_options_plain(&o);
    o.corner_rays = 1;
    o.threads = 2;
    assert_int_equal(rt_render(s.sc, &cam, &o, a, NULL), RT_OK);
    o.threads = 1;
    assert_int_equal(rt_render(s.sc, &cam, &o, b, NULL), RT_OK);
    assert_memory_equal(a, b, n * sizeof(float));
    assert_int_equal(rtc_nonfinite(a, n), 0);
    /* spot checks against the corner colours */
    const double bg[3] = {0, 0, 0};
    for (int y = 0; y < h; y += 39)
        for (int x = 0; x < w; x += 47) {
            float k[4][3];
            ray_colour(&s, &cam, bg, x, y, k[0]);
            ray_colour(&s, &cam, bg, x + 1, y, k[1]);
            ray_colour(&s, &cam, bg, x, y + 1, k[2]);
            ray_colour(&s, &cam, bg, x + 1, y + 1, k[3]);
            for (int c = 0; c < 3; c++) {
                double v = 0.25 * ((double)k[0][c] + k[1][c] + k[2][c] + k[3][c]);
                assert_true(a[3 * ((size_t)y * w + x) + c] == (float)v);
            }
        }
    free(a);
    free(b);
    rt_scene_free(s.sc);
}

/* Plane z = 0 (normal +z), kd = 1, white, ambient 0.25; a positional light at height hz above
   the origin, seen by an orthographic camera from above over [1,3]x[-1,1]: N.L = hz / dist,
   tiny for hz = +-1e-6. Lit exactly when hz > 0; shadow rays exactly for lit pixels. */
static void test_grazing_light(void **state)
{
    (void)state;
    const int w = 8, h = 8;
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        const double hz = sgn * 1e-6;
        rt_scene *sc = rt_scene_new();
        rt_surface su;
        rt_surface_default(&su);
        su.ka = 1.0;
        su.kd = 1.0;
        int sid = rt_scene_add_surface(sc, &su);
        double v[12] = {-5, -5, 0, 5, -5, 0, 5, 5, 0, -5, 5, 0};
        int n = 4;
        assert_true(rt_scene_add_polygon(sc, 1, &n, v, sid, sid) >= 0);
        rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.25, 0.25, 0.25}};
        rt_light pl = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .position = {0, 0, hz},
                       .c1 = 1.0};
        assert_true(rt_scene_add_light(sc, &amb) >= 0);
        assert_true(rt_scene_add_light(sc, &pl) >= 0);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rtu_view vw = {.win = {1, 3, -1, 1}, .prp = {2, 0, 110}, .vpd = 10, .bpd = -10,
                       .fpd = 10, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
        double m[4][4];
        rtu_view_matrix(&vw, m);
        rt_camera cam;
        assert_int_equal(rt_camera_from_view(&cam, m, vw.vp, w, h), RT_OK);
        rt_render_options o;
        rtu_options_plain(&o);
        o.threads = 1;
        float rgb[8 * 8 * 3];
        rt_stats st;
        rtc_traps_on();
        assert_int_equal(rt_render(sc, &cam, &o, rgb, &st), RT_OK);
        rtc_traps_off();
        assert_int_equal(st.shadow_rays, sgn > 0 ? (uint64_t)w * h : 0);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double px = 1.0 + (x + 0.5) * 2.0 / w, py = 1.0 - (y + 0.5) * 2.0 / h;
                double d = sqrt(px * px + py * py + hz * hz);
                double expect = 0.25 + (sgn > 0 ? hz / d : 0.0);
                for (int c = 0; c < 3; c++) {
                    double got = rgb[3 * (y * w + x) + c];
                    assert_true(fabs(got - expect) <= 1e-7 * expect);
                    if (sgn > 0)
                        assert_true(got > 0.25f);
                }
            }
        rt_scene_free(sc);
    }
}

/* rt_camera_ray evaluated as written in the paper's terms: x, y in NPC, the projector's
   points on the front and back planes through minv (sums left to right), unit direction. The
   renderer computes the products with x once per column and with y once per row; the sums
   keep this order, so the rays must be bit for bit these. */
static void direct_ray(const rt_camera *cam, double px, double py, rt_ray *r)
{
    double x = cam->box[0] + px * (cam->box[1] - cam->box[0]) / cam->width;
    double y = cam->box[3] - py * (cam->box[3] - cam->box[2]) / cam->height;
    double p[2][3];
    for (int e = 0; e < 2; e++) {
        double v[4] = {x, y, cam->box[e == 0 ? 5 : 4], 1.0}, hh[4];
        for (int i = 0; i < 4; i++)
            hh[i] = cam->minv[i][0] * v[0] + cam->minv[i][1] * v[1] + cam->minv[i][2] * v[2] +
                    cam->minv[i][3] * v[3];
        for (int i = 0; i < 3; i++)
            p[e][i] = hh[i] / hh[3];
    }
    double d[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    double m = fmax(fabs(d[0]), fmax(fabs(d[1]), fabs(d[2])));
    double u[3] = {d[0] / m, d[1] / m, d[2] / m};
    double l = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; i++) {
        r->org[i] = p[0][i];
        r->dir[i] = u[i] / l;
    }
    r->tmin = 0.0;
    r->tmax = m * l;
}

static void test_camera_bits(void **state)
{
    (void)state;
    rt_camera cams[3];
    make_camera(&cams[0], 37, 23, 1);
    rtu_view par = {.win = {-2, 3, -1, 1.5}, .prp = {0.3, 0.2, 50}, .vpd = 1, .bpd = -7, .fpd = 2,
                    .vp = {0.1, 0.9, 0.2, 0.7, 0.25, 0.75}, .perspective = 0};
    rtu_view obl = {.win = {-2, 3, -1, 1.5}, .prp = {4, -3, 9}, .vpd = 1, .bpd = -7, .fpd = 2,
                    .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    double m[4][4];
    rtu_view_matrix(&par, m);
    assert_int_equal(rt_camera_from_view(&cams[1], m, par.vp, 64, 48), RT_OK);
    rtu_view_matrix(&obl, m);
    assert_int_equal(rt_camera_from_view(&cams[2], m, obl.vp, 19, 31), RT_OK);
    for (int k = 0; k < 3; k++)
        for (int y = 0; y <= cams[k].height; y++)
            for (int x = 0; x <= cams[k].width; x++)
                for (int half = 0; half < 2; half++) {
                    rt_ray a, b;
                    double px = x + 0.5 * half, py = y + 0.5 * half;
                    assert_int_equal(rt_camera_ray(&cams[k], px, py, &a), RT_OK);
                    direct_ray(&cams[k], px, py, &b);
                    assert_memory_equal(a.org, b.org, sizeof a.org);
                    assert_memory_equal(a.dir, b.dir, sizeof a.dir);
                    assert_true(a.tmax == b.tmax && a.tmin == 0.0);
                }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_corner_pictures),
        cmocka_unit_test(test_centre_pictures),
        cmocka_unit_test(test_large_picture),
        cmocka_unit_test(test_grazing_light),
        cmocka_unit_test(test_camera_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
