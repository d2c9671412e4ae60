/* SPDX-License-Identifier: MIT */
/*
 * test_rt_render.c -- analytic pictures: Lambert values, positional/spot lights, a shadow
 * rectangle, a mirror, Snell's shift through a glass slab, total internal reflection and the
 * Fresnel value, index 1 = no change, cell array colours, clipping of secondary rays (paper
 * figs. 4/5), adaptive depth, thread-count independence. Every render is checked for
 * non-finite pixels. Tolerances: 1e-6 relative where the value is analytic (output is float,
 * 6e-8 relative rounding, plus double shading arithmetic); pixels whose footprint touches an
 * edge of a predicted region are skipped (their colour depends on sub-pixel position).
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

#define W 32
#define H 32

/* parallel orthographic camera looking down -z over [x0,x1]x[y0,y1], front plane z = zf,
   back plane z = zb */
static void cam_top(rt_camera *cam, double x0, double x1, double y0, double y1, double zf, double zb,
                    int w, int h)
{
    rtu_view v = {.win = {x0, x1, y0, y1}, .prp = {0.5 * (x0 + x1), 0.5 * (y0 + y1), zf + 100},
                  .vpd = zf, .bpd = zb, .fpd = zf, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    double m[4][4];
    rtu_view_matrix(&v, m);
    assert_int_equal(rt_camera_from_view(cam, m, v.vp, w, h), RT_OK);
}

static double px_x(double x0, double x1, int i, int w) { return x0 + (i + 0.5) * (x1 - x0) / w; }
static double px_y(double y0, double y1, int r, int h) { return y1 - (r + 0.5) * (y1 - y0) / h; }

static void render(const rt_scene *sc, const rt_camera *cam, const rt_render_options *o, float *rgb,
                   rt_stats *st)
{
    rt_render_options plain;
    if (!o) { /* the tests' defaults: pixel-centre rays, no cut-off */
        rtu_options_plain(&plain);
        o = &plain;
    }
    rtc_traps_on();
    assert_int_equal(rt_render(sc, cam, o, rgb, st), RT_OK);
    rtc_traps_off();
    assert_int_equal(rtc_nonfinite(rgb, (size_t)cam->width * cam->height * 3), 0);
}

static int add_quad(rt_scene *sc, double x0, double y0, double x1, double y1, double z, int up, int s)
{
    double v[12] = {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z};
    if (!up) { /* clockwise seen from above: normal -z */
        double t[3];
        memcpy(t, v + 3, sizeof t);
        memcpy(v + 3, v + 9, sizeof t);
        memcpy(v + 9, t, sizeof t);
    }
    int n = 4;
    return rt_scene_add_polygon(sc, 1, &n, v, s, s);
}

static rt_surface flat(double r, double g, double b)
{
    rt_surface s;
    rt_surface_default(&s);
    s.refl_eq = RT_REFL_NONE;
    s.diffuse[0] = r; s.diffuse[1] = g; s.diffuse[2] = b;
    return s;
}

static void norm3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++)
        v[i] /= l;
}

/* ---- Lambert: every pixel analytic, also with the scene 1e6 away (no shadow acne) ---- */
static void test_lambert(void **state)
{
    (void)state;
    const double offs[2] = {0.0, 1e6};
    for (int oi = 0; oi < 2; oi++) {
        double o = offs[oi];
        for (int grazing = 0; grazing < 2; grazing++) {
            rt_scene *sc = rt_scene_new();
            rt_surface s;
            rt_surface_default(&s);
            s.ka = 0.2; s.kd = 0.7;
            s.diffuse[0] = 0.9; s.diffuse[1] = 0.5; s.diffuse[2] = 0.25;
            int sid = rt_scene_add_surface(sc, &s);
            double dir[3] = {-0.3, -0.4, grazing ? -0.04 : -1.0};
            rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 0.8, 0.6}};
            memcpy(l.direction, dir, sizeof dir);
            rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {0.1, 0.2, 0.3}};
            assert_int_equal(rt_scene_add_light(sc, &l), 0);
            assert_int_equal(rt_scene_add_light(sc, &a), 1);
            add_quad(sc, o - 1, o - 1, o + 3, o + 3, o, 1, sid);
            assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
            rt_camera cam;
            cam_top(&cam, o, o + 2, o, o + 2, o + 1, o - 1, W, H);
            float rgb[W * H * 3];
            rt_stats st;
            render(sc, &cam, NULL, rgb, &st);
            norm3(dir);
            double NL = -dir[2];
            for (int k = 0; k < W * H; k++)
                for (int c = 0; c < 3; c++) {
                    double e = s.ka * s.diffuse[c] * a.color[c] + s.kd * s.diffuse[c] * l.color[c] * NL;
                    assert_true(fabs(rgb[3 * k + c] - e) <= 1e-6 * e);
                }
            assert_int_equal(st.eye_rays, W * H);
            assert_int_equal(st.eye_hits, W * H);
            assert_int_equal(st.shadow_rays, W * H); /* none for the ambient light */
            rt_scene_free(sc);
        }
    }
}

/* ---- positional light attenuation, spot cone, light mask, back side ---- */
static void test_lights(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    s.ka = 0.0; s.kd = 0.8;
    s.light_mask = 1u | 2u; /* light 2 is masked out */
    int sid = rt_scene_add_surface(sc, &s);
    rt_light p = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .position = {0.5, 0.5, 1.5}, .c1 = 0.5, .c2 = 0.25};
    rt_light sp = {.type = RT_LIGHT_SPOT, .color = {0, 1, 0}, .position = {1.5, 1.5, 2}, .direction = {0, 0, -1},
                   .c1 = 1, .c2 = 0, .concentration = 2, .spread = 0.2};
    rt_light masked = {.type = RT_LIGHT_AMBIENT, .color = {5, 5, 5}};
    assert_int_equal(rt_scene_add_light(sc, &p), 0);
    assert_int_equal(rt_scene_add_light(sc, &sp), 1);
    assert_int_equal(rt_scene_add_light(sc, &masked), 2);
    add_quad(sc, -1, -1, 3, 3, 0, 1, sid);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 2, 0, 2, 1, -1, W, H);
    float rgb[W * H * 3];
    render(sc, &cam, NULL, rgb, NULL);
    int inside = 0;
    for (int r = 0; r < H; r++)
        for (int i = 0; i < W; i++) {
            double x = px_x(0, 2, i, W), y = px_y(0, 2, r, H);
            double L[3] = {0.5 - x, 0.5 - y, 1.5};
            double d = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
            double e = 0.8 * (L[2] / d) / (0.5 + 0.25 * d);
            double S[3] = {1.5 - x, 1.5 - y, 2};
            double ds = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
            double ca = S[2] / ds, ang = acos(ca);
            double g = e;
            if (fabs(ang - 0.2) < 0.01)
                continue; /* at the cone's edge */
            if (ang < 0.2) {
                g += 0.8 * ca * pow(ca, 2);
                inside++;
            }
            const float *px = rgb + 3 * (r * W + i);
            assert_true(fabs(px[0] - e) <= 1e-6 * e);
            assert_true(fabs(px[2] - e) <= 1e-6 * e);
            assert_true(fabs(px[1] - g) <= 1e-6 * g);
        }
    assert_true(inside > 10 && inside < W * H / 2);
    rt_scene_free(sc);
}

/* ---- shadow rectangle ---- */
static void test_shadow(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface g;
    rt_surface_default(&g);
    g.ka = 0.25; g.kd = 0.5;
    int gs = rt_scene_add_surface(sc, &g);
    rt_surface oc = flat(0, 0, 1);
    int os = rt_scene_add_surface(sc, &oc);
    double dir[3] = {1, 0, -1};
    rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {1, 0, -1}};
    rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
    rt_scene_add_light(sc, &l);
    rt_scene_add_light(sc, &a);
    add_quad(sc, -5, -5, 5, 5, 0, 1, gs);
    add_quad(sc, 0.25, 0.25, 0.75, 0.75, 1, 1, os); /* shadow: [1.25,1.75]x[0.25,0.75] */
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 2, 0, 2, 2, -1, W, H);
    float rgb[W * H * 3];
    render(sc, &cam, NULL, rgb, NULL);
    norm3(dir);
    double lit = 0.25 + 0.5 * -dir[2], dark = 0.25, pix = 2.0 / W;
    int nshadow = 0;
    for (int r = 0; r < H; r++)
        for (int i = 0; i < W; i++) {
            double x = px_x(0, 2, i, W), y = px_y(0, 2, r, H);
            const float *px = rgb + 3 * (r * W + i);
            int in_occ = x > 0.25 && x < 0.75 && y > 0.25 && y < 0.75;
            int in_sh = x > 1.25 && x < 1.75 && y > 0.25 && y < 0.75;
            int edge = fabs(x - 0.25) < pix || fabs(x - 0.75) < pix || fabs(x - 1.25) < pix ||
                       fabs(x - 1.75) < pix || fabs(y - 0.25) < pix || fabs(y - 0.75) < pix;
            if (edge)
                continue;
            if (in_occ) {
                assert_true(px[0] == 0.0f && px[2] == 1.0f);
            } else if (in_sh) {
                assert_true(fabs(px[0] - dark) < 1e-6);
                nshadow++;
            } else {
                assert_true(fabs(px[0] - lit) < 1e-6);
            }
        }
    assert_true(nshadow >= 16);
    rt_scene_free(sc);
}

/* ---- mirror at 45 degrees shows a flat wall: ks * Cs * wall colour ---- */
static void test_mirror(void **state)
{
    (void)state;
    const double offs[2] = {0.0, 1e6}; /* a self-hit of the reflected ray would give black */
    for (int oi = 0; oi < 2; oi++) {
        double o = offs[oi];
        rt_scene *sc = rt_scene_new();
        rt_surface m;
        rt_surface_default(&m);
        m.refl_eq = RT_REFL_SPECULAR;
        m.ka = m.kd = 0; m.ks = 0.8;
        m.specular[0] = 0.5; m.specular[1] = 1; m.specular[2] = 1;
        int ms = rt_scene_add_surface(sc, &m);
        rt_surface wall = flat(1, 0.25, 0);
        int ws = rt_scene_add_surface(sc, &wall);
        /* mirror through the x axis with normal (0,1,1)/sqrt2 */
        double mv[12] = {-1, -1, 1, 3, -1, 1, 3, 3, -3, -1, 3, -3};
        double wv[12] = {-10, 5, -10, -10, 5, 10, 10, 5, 10, 10, 5, -10}; /* plane y = 5 */
        for (int k = 0; k < 12; k++) {
            mv[k] += o;
            wv[k] += o;
        }
        int n = 4;
        rt_scene_add_polygon(sc, 1, &n, mv, ms, ms);
        rt_scene_add_polygon(sc, 1, &n, wv, ws, ws);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_camera cam;
        cam_top(&cam, o, o + 2, o, o + 2, o + 4, o - 4, W, H);
        float rgb[W * H * 3];
        rt_stats st;
        render(sc, &cam, NULL, rgb, &st);
        for (int k = 0; k < W * H; k++) {
            assert_true(fabs(rgb[3 * k] - 0.8 * 0.5 * 1.0) < 1e-6);
            assert_true(fabs(rgb[3 * k + 1] - 0.8 * 0.25) < 1e-6);
            assert_true(rgb[3 * k + 2] == 0.0f);
        }
        assert_int_equal(st.reflection_rays, W * H);
        assert_int_equal(st.refraction_rays, 0);
        rt_scene_free(sc);
    }
}

/* ---- glass slab: lateral shift by Snell's law ---- */
static void refract(const double d[3], const double n[3], double eta, double t[3])
{
    double ci = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
    double ct = sqrt(1 - eta * eta * (1 - ci * ci));
    for (int i = 0; i < 3; i++)
        t[i] = eta * d[i] + (eta * ci - ct) * n[i];
}

static void test_glass_slab(void **state)
{
    (void)state;
    const double alpha = 30.0 * M_PI / 180.0, eta = 1.5, h = 1.0, edge = 1.0;
    double n[3] = {sin(alpha), 0, cos(alpha)};
    rt_scene *sc = rt_scene_new();
    rt_surface gl;
    rt_surface_default(&gl);
    gl.refl_eq = RT_REFL_AMBIENT;
    gl.ka = 0;
    gl.transparency = 1.0;
    gl.refr_index = eta;
    int gs = rt_scene_add_surface(sc, &gl);
    rt_surface red = flat(1, 0, 0), green = flat(0, 1, 0);
    int rs = rt_scene_add_surface(sc, &red), g2 = rt_scene_add_surface(sc, &green);
    /* slab planes through (0,0,2) and (0,0,2) - h n, spanning far beyond the view */
    double u[3] = {cos(alpha), 0, -sin(alpha)}, vv[3] = {0, 1, 0};
    double top[12], bot[12];
    const double cs[4][2] = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
    for (int k = 0; k < 4; k++)
        for (int i = 0; i < 3; i++) {
            double p = (i == 2 ? 2.0 : 0.0) + cs[k][0] * u[i] + cs[k][1] * vv[i];
            top[3 * k + i] = p;                       /* counter-clockwise about +n */
            bot[3 * (3 - k) + i] = p - h * n[i];      /* reversed: normal -n (outward) */
        }
    int four = 4;
    rt_scene_add_polygon(sc, 1, &four, top, gs, gs);
    rt_scene_add_polygon(sc, 1, &four, bot, gs, gs);
    add_quad(sc, -30, -30, edge, 30, -1, 1, rs);
    add_quad(sc, edge, -30, 30, 30, -1, 1, g2);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 2, 0, 2, 5, -2, 64, 4);
    float rgb[64 * 4 * 3];
    rt_render_options o;
    rtu_options_plain(&o);
    o.fresnel = RT_FRESNEL_NONE;
    rt_stats st;
    render(sc, &cam, &o, rgb, &st);
    /* analytic landing point of a vertical ray */
    double d[3] = {0, 0, -1}, t1[3], t2[3];
    refract(d, n, 1.0 / eta, t1);
    /* from the entry point on the top plane at x = 0: p1 = (x1,0,z1) with n.(p1-(0,0,2)) = 0 */
    double z1 = 2.0, x1 = 0.0; /* entry at x=0 is (0, 0, 2) */
    double s = h / -(t1[0] * n[0] + t1[2] * n[2]);
    double x2 = x1 + s * t1[0], z2 = z1 + s * t1[2];
    refract(t1, n, eta, t2); /* inside -> out: the lower face (normal -n) seen from its back */
    double x3 = x2 + (z2 - (-1.0)) / -t2[2] * t2[0];
    double shift = x3 - 0.0;
    assert_true(fabs(t2[0]) < 1e-12 && fabs(t2[2] + 1) < 1e-12); /* leaves parallel */
    assert_true(fabs(shift) > 0.15);                             /* about 6 pixels */
    int checked = 0;
    for (int r = 0; r < 4; r++)
        for (int i = 0; i < 64; i++) {
            double x = px_x(0, 2, i, 64) + shift;
            if (fabs(x - edge) < 2.0 / 64)
                continue;
            const float *px = rgb + 3 * (r * 64 + i);
            if (x < edge)
                assert_true(px[0] == 1.0f && px[1] == 0.0f);
            else
                assert_true(px[0] == 0.0f && px[1] == 1.0f);
            checked++;
        }
    assert_true(checked > 200);
    assert_int_equal(st.refraction_rays, 2 * 64 * 4);
    assert_int_equal(st.reflection_rays, 0);
    rt_scene_free(sc);
}

/* ---- total internal reflection past the critical angle; exact Fresnel below it ---- */
static double fresnel_exact(double ci, double n1, double n2)
{
    double st2 = (n1 / n2) * (n1 / n2) * (1 - ci * ci);
    double ct = sqrt(1 - st2);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct), rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 0.5 * (rs * rs + rp * rp);
}

static void test_tir(void **state)
{
    (void)state;
    const double angles[2] = {60.0, 30.0};
    for (int k = 0; k < 2; k++) {
        double a = angles[k] * M_PI / 180.0;
        rt_scene *sc = rt_scene_new();
        rt_surface front = flat(0, 0, 0), back;
        rt_surface_default(&back);
        back.refl_eq = RT_REFL_AMBIENT;
        back.ka = 0;
        back.transparency = 1.0;
        back.refr_index = 1.5; /* the ray leaves glass of index 1.5 */
        int fs = rt_scene_add_surface(sc, &front), bs = rt_scene_add_surface(sc, &back);
        rt_surface blue = flat(0, 0, 1), red = flat(1, 0, 0);
        int bl = rt_scene_add_surface(sc, &blue), rd = rt_scene_add_surface(sc, &red);
        /* interface through the origin, front normal -(sin a, 0, cos a): seen from its back */
        double u[3] = {cos(a), 0, -sin(a)};
        double v[12];
        const double cs[4][2] = {{-4, -4}, {-4, 4}, {4, 4}, {4, -4}}; /* clockwise about +n */
        for (int c = 0; c < 4; c++)
            for (int i = 0; i < 3; i++)
                v[3 * c + i] = cs[c][0] * u[i] + (i == 1 ? cs[c][1] : 0.0);
        int four = 4;
        rt_scene_add_polygon(sc, 1, &four, v, fs, bs);
        double wall[12] = {10, -20, -20, 10, 20, -20, 10, 20, -1, 10, -20, -1};
        rt_scene_add_polygon(sc, 1, &four, wall, bl, bl);
        add_quad(sc, -5, -20, 5, 20, -5, 1, rd);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_camera cam;
        cam_top(&cam, 0, 1, 0, 1, 5, -10, 8, 8);
        float rgb[8 * 8 * 3];
        rt_stats st;
        for (int mode = 0; mode < 2; mode++) {
            rt_render_options o;
            rtu_options_plain(&o);
            o.fresnel = mode ? RT_FRESNEL_SCHLICK : RT_FRESNEL_EXACT;
            render(sc, &cam, &o, rgb, &st);
            double ci = cos(a);
            for (int p = 0; p < 64; p++) {
                if (k == 0) { /* 60 > 41.8 degrees: all light reflected onto the blue wall */
                    assert_true(rgb[3 * p] == 0.0f && rgb[3 * p + 2] == 1.0f);
                } else {
                    double F;
                    if (mode == 0) {
                        F = fresnel_exact(ci, 1.5, 1.0);
                    } else {
                        double r0 = 0.04, ct = sqrt(1 - 2.25 * (1 - ci * ci));
                        F = r0 + (1 - r0) * pow(1 - ct, 5);
                    }
                    assert_true(fabs(rgb[3 * p] - (1 - F)) < 1e-6);
                    assert_true(rgb[3 * p + 2] == 0.0f); /* reflection goes up: background */
                }
            }
            if (k == 0) {
                assert_int_equal(st.refraction_rays, 0);
                assert_int_equal(st.reflection_rays, 64);
            } else {
                assert_int_equal(st.refraction_rays, 64);
                assert_int_equal(st.reflection_rays, 64);
            }
        }
        rt_scene_free(sc);
    }
}

/* ---- refraction index exactly 1 leaves the image behind unchanged ---- */
static void test_index_one(void **state)
{
    (void)state;
    float img[2][W * H * 3];
    for (int with = 0; with < 2; with++) {
        rt_scene *sc = rt_scene_new();
        rt_surface c1 = flat(0.9, 0.1, 0.3), c2 = flat(0.2, 0.7, 0.4);
        int s1 = rt_scene_add_surface(sc, &c1), s2 = rt_scene_add_surface(sc, &c2);
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++) /* checker edges on pixel boundaries */
                add_quad(sc, 0.5 * i, 0.5 * j, 0.5 * i + 0.5, 0.5 * j + 0.5, 0, 1, (i + j) & 1 ? s1 : s2);
        if (with) {
            rt_surface g;
            rt_surface_default(&g);
            g.refl_eq = RT_REFL_AMBIENT;
            g.ka = 0;
            g.transparency = 1;
            g.refr_index = 1.0;
            int gs = rt_scene_add_surface(sc, &g);
            double tv[12] = {-1, -1, 1, 3, -1, 1.6, 3, 3, 1.2, -1, 3, 0.6}; /* tilted, non-planar-ish */
            int n = 4;
            rt_scene_add_polygon(sc, 1, &n, tv, gs, gs);
            add_quad(sc, -1, -1, 3, 3, 0.5, 0, gs);
        }
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rt_camera cam;
        cam_top(&cam, 0, 2, 0, 2, 3, -1, W, H);
        render(sc, &cam, NULL, img[with], NULL);
        rt_scene_free(sc);
    }
    assert_memory_equal(img[0], img[1], sizeof img[0]);
}

/* ---- cell array: P, R, Q corners and cell order ---- */
static void test_cell_array(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface s = flat(0.5, 0.5, 0.5);
    int sid = rt_scene_add_surface(sc, &s);
    double P[3] = {0, 0, 0}, R[3] = {2, 0, 0}, Q[3] = {2, 2, 0};
    float rgb[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}; /* (0,0) red (1,0) green (0,1) blue (1,1) white */
    assert_true(rt_scene_add_cell_array(sc, P, Q, R, 2, 2, rgb, sid, sid) >= 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 2, 0, 2, 1, -1, 4, 4);
    float img[4 * 4 * 3];
    render(sc, &cam, NULL, img, NULL);
    const float *tl = img, *tr = img + 3 * 3, *bl = img + 3 * 12, *br = img + 3 * 15;
    assert_true(bl[0] == 1 && bl[1] == 0 && bl[2] == 0); /* bottom left: cell (0,0) at P */
    assert_true(br[0] == 0 && br[1] == 1 && br[2] == 0);
    assert_true(tl[0] == 0 && tl[1] == 0 && tl[2] == 1);
    assert_true(tr[0] == 1 && tr[1] == 1 && tr[2] == 1);
    rt_scene_free(sc);
}

/* ---- clip_secondary: an occluder above the front plane (fig. 4 vs fig. 5) ---- */
static void test_clip_secondary(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface g;
    rt_surface_default(&g);
    g.ka = 0.25; g.kd = 0.5;
    int gs = rt_scene_add_surface(sc, &g);
    rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {0, 0, -1}};
    rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
    rt_scene_add_light(sc, &l);
    rt_scene_add_light(sc, &a);
    add_quad(sc, -5, -5, 5, 5, 0, 1, gs);
    add_quad(sc, 0.5, 0.5, 1.5, 1.5, 3, 1, gs);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 2, 0, 2, 1, -1, 8, 8);
    float img[8 * 8 * 3];
    rt_render_options o;
    rtu_options_plain(&o);
    for (int clip = 0; clip < 2; clip++) {
        o.clip_secondary = clip;
        render(sc, &cam, &o, img, NULL);
        for (int r = 0; r < 8; r++)
            for (int i = 0; i < 8; i++) {
                double x = px_x(0, 2, i, 8), y = px_y(0, 2, r, 8);
                int under = x > 0.5 && x < 1.5 && y > 0.5 && y < 1.5;
                double e = (under && !clip) ? 0.25 : 0.75;
                assert_true(fabs(img[3 * (r * 8 + i)] - e) < 1e-6);
            }
    }
    rt_scene_free(sc);
}

/* ---- adaptive depth and depth limit: two facing mirrors, ks = 0.5 ---- */
static void test_depth(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface m;
    rt_surface_default(&m);
    m.refl_eq = RT_REFL_SPECULAR;
    m.ka = m.kd = 0;
    m.ks = 0.5;
    int ms = rt_scene_add_surface(sc, &m);
    add_quad(sc, -5, -5, 5, 5, 0, 1, ms);
    add_quad(sc, -5, -5, 5, 5, 0.5, 0, ms); /* above the front plane z = 0.4 */
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    cam_top(&cam, 0, 1, 0, 1, 0.4, -1, 4, 4);
    float img[4 * 4 * 3];
    rt_render_options o;
    rtu_options_plain(&o);
    rt_stats st;
    o.max_depth = 64;
    o.cutoff = 0.1; /* weights 0.5, 0.25, 0.125 spawn; 0.0625 does not */
    render(sc, &cam, &o, img, &st);
    assert_int_equal(st.reflection_rays, 3 * 16);
    o.cutoff = 0;
    o.max_depth = 6;
    render(sc, &cam, &o, img, &st);
    assert_int_equal(st.reflection_rays, 5 * 16);
    o.max_depth = 1;
    render(sc, &cam, &o, img, &st);
    assert_int_equal(st.reflection_rays, 0);
    o.max_depth = 6;
    o.clip_secondary = 1; /* the upper mirror is outside the display volume */
    render(sc, &cam, &o, img, &st);
    assert_int_equal(st.reflection_rays, 16);
    rt_scene_free(sc);
}

/* ---- picture independent of the thread count; corner rays; options ---- */
static void test_threads(void **state)
{
    (void)state;
    rt_camera cam;
    rt_scene *sc = rtu_nff_scene(RT_DATA_DIR "/spd/mount-tessellated.nff.gz", 0, 24, 20, &cam);
    assert_non_null(sc);
    enum { N = 24 * 20 * 3 };
    float *a = malloc(N * sizeof(float)), *b = malloc(N * sizeof(float));
    rt_render_options o;
    rtu_options_plain(&o);
    o.samples = 4;
    o.jitter = 1;
    o.threads = 1;
    rt_stats s1, s3;
    render(sc, &cam, &o, a, &s1);
    o.threads = 3;
    render(sc, &cam, &o, b, &s3);
    assert_memory_equal(a, b, N * sizeof(float));
    assert_int_equal(s1.eye_rays, 24 * 20 * 4);
    assert_int_equal(s1.shadow_rays, s3.shadow_rays);
    assert_int_equal(s1.refraction_rays, s3.refraction_rays);
    assert_true(s1.refraction_rays > 0 && s1.reflection_rays > 0);
    o.corner_rays = 1;
    o.threads = 2;
    render(sc, &cam, &o, a, &s1);
    o.threads = 1;
    render(sc, &cam, &o, b, &s3);
    assert_memory_equal(a, b, N * sizeof(float));
    assert_int_equal(s1.eye_rays, 25 * 21);
    /* corner rays resolved to pixels in parts of rows on the pool (rt_corner_part, each part's
       last row reading the next part's first as traced): the same pixels and cover for 1 to 5
       parts, i.e. up to 4 part boundaries in the 20 rows */
    unsigned short ca[24 * 20], cb[24 * 20];
    o.threads = 1;
    assert_int_equal(rt_render_cover(sc, &cam, &o, a, ca, NULL), RT_OK);
    for (int t = 2; t <= 5; t++) {
        o.threads = t;
        memset(b, 0, N * sizeof(float));
        memset(cb, 0xff, sizeof cb);
        assert_int_equal(rt_render_cover(sc, &cam, &o, b, cb, NULL), RT_OK);
        assert_memory_equal(a, b, N * sizeof(float));
        assert_memory_equal(ca, cb, sizeof ca);
    }
    /* bad options */
    o.samples = 3;
    assert_int_equal(rt_render(sc, &cam, &o, a, NULL), RT_ERR_ARG);
    o.samples = 1;
    o.max_depth = 0;
    assert_int_equal(rt_render(sc, &cam, &o, a, NULL), RT_ERR_ARG);
    o.max_depth = 5;
    o.background[1] = NAN;
    assert_int_equal(rt_render(sc, &cam, &o, a, NULL), RT_ERR_ARG);
    o.background[1] = 0;
    o.cutoff = -1;
    assert_int_equal(rt_render(sc, &cam, &o, a, NULL), RT_ERR_ARG);
    rt_scene *un = rt_scene_new();
    assert_int_equal(rt_render(un, &cam, NULL, a, NULL), RT_ERR_STATE);
    assert_int_equal(rt_render(NULL, &cam, NULL, a, NULL), RT_ERR_ARG);
    rt_scene_free(un);
    free(a);
    free(b);
    rt_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert),       cmocka_unit_test(test_lights),
        cmocka_unit_test(test_shadow),        cmocka_unit_test(test_mirror),
        cmocka_unit_test(test_glass_slab),    cmocka_unit_test(test_tir),
        cmocka_unit_test(test_index_one),     cmocka_unit_test(test_cell_array),
        cmocka_unit_test(test_clip_secondary), cmocka_unit_test(test_depth),
        cmocka_unit_test(test_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
