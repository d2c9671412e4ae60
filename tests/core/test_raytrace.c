/* SPDX-License-Identifier: MIT */
/*
 * test_raytrace.c -- lighting functions and HLHSR mode 4 (ray tracing) on the PNG
 * workstation: exact Lambert shading, a shadow where geometry puts it, silhouettes equal
 * to the z-buffer mode, and the argument errors of the lighting functions.
 * Tolerance of shaded pixels: +-1 of 8 bits (the only rounding is float -> 8 bit).
 * All views are the identity (NDC3 = VRC3 = NPC3), workstation window the unit cube,
 * viewport 64x64 pixels: NDC x -> pixel x*64.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

#include "png_util.h"
#include "ws_raytrace.h"
#include "ws_render.h"
#include "ws_shade.h"
#include "gks_alloc.h"
#include "gks_context.h" /* gks_ws_lookup: the view table's number */

static void assert_near(const image *img, int x, int y, double r, double g, double b)
{
    const unsigned char *p = px(img, x, y);
    double want[3] = { r * 255, g * 255, b * 255 };
    for (int q = 0; q < 3; q++)
        if (fabs(p[q] - want[q]) > 1.0)
            fail_msg("pixel (%d,%d) = %d %d %d, want %.1f %.1f %.1f", x, y, p[0], p[1], p[2],
                     want[0], want[1], want[2]);
}

static void no_errors(void)
{
    if (n_captured)
        fail_msg("%d errors, first %d in function %d", n_captured, captured[0].err,
                 captured[0].fct);
}

static const Glimit unit_win = { 0, 1, 0, 1 };
static const Glimit vp64 = { 0, 64, 0, 64 };

/* Pixel-centre rays (ESCAPE -103 with 1 sample) and no cut-off (-105 with 0) instead of
 * the workstation's defaults (corner rays, cut-off 0.01; test_default_sampling): most tests
 * here compare pixels and ray counts with closed forms for one ray per pixel centre. */
static void plain_sampling(int ws)
{
    Gint ints[2] = { ws, 1 };
    Gfloat zero[1] = { 0.0 };
    Gescape_in_data in = { .num_ints = 2, .ints = ints, .num_floats = 1, .floats = zero };
    gescape(GESC_RT_SAMPLES, &in, NULL, NULL);
    gescape(GESC_RT_CUTOFF, &in, NULL, NULL);
}

/* A 64 x 64 PNG workstation in HLHSR mode `mode` with the workstation's defaults. */
static void open_png_defaults(int ws, const char *file, int mode)
{
    unlink(file);
    gopen_ws(ws, file, GWS_TYPE_PNG);
    gactivate_ws(ws);
    gset_ws_win(ws, &unit_win);
    gset_ws_vp(ws, &vp64);
    gset_hlhsr_mode(ws, mode);
}

static void open_png(int ws, const char *file, int mode)
{
    open_png_defaults(ws, file, mode);
    plain_sampling(ws);
}

/* A driver-level recorder with plain_sampling's settings. */
static ws_rt *rt_new_plain(void)
{
    ws_rt *r = ws_rt_new(NULL);
    assert_non_null(r);
    Gint ints[2] = { 0, 1 };
    Gfloat zero[1] = { 0.0 };
    Gescape_in_data in = { .num_ints = 2, .ints = ints, .num_floats = 1, .floats = zero };
    assert_int_equal(ws_rt_escape(r, GESC_RT_SAMPLES, &in, NULL), 0);
    assert_int_equal(ws_rt_escape(r, GESC_RT_CUTOFF, &in, NULL), 0);
    return r;
}

/* Counter-clockwise square [a,b]^2 at depth z (front side towards +z, the viewer). */
static void square(double a, double b, double z)
{
    Gpoint3 p[4] = { { a, a, z }, { b, a, z }, { b, b, z }, { a, b, z } };
    Gpoint_list3 l = { 4, p };
    gfill_area3(&l);
}

static void lit_setup(const Grgb *c)
{
    Gcolr_rep cr = { *c };
    gset_colr_rep(1, 2, &cr);
    gset_fill_colr_ind(2);
    Garea_props pr = { 0, 1, 0, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF);
    Gint on = 2;
    Gint_list a = { 1, &on };
    gset_light_src_state(&a, NULL);
}

/* The Lambert square: colour (0.8, 0.6, 0.4) over [0.2,0.8]^2 at z = 0.5, lit by light 2
 * travelling along (0,-0.8,-0.6): the cosine between the normal +z and -dir is 0.6. */
static void lambert_square(void)
{
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, -0.8, -0.6 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.8, 0.6, 0.4 };
    lit_setup(&c);
    square(0.2, 0.8, 0.5);
}

static void test_lambert(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_lambert.png", GHLHSR_RAYTRACE);
    lambert_square();
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_lambert.png", &img));
    assert_int_equal(img.w, 64);
    /* [0.2,0.8]*64 = [12.8,51.2]: pixel centres 13.5..50.5 covered. */
    for (int y = 13; y <= 50; y++)
        for (int x = 13; x <= 50; x++)
            assert_near(&img, x, y, 0.8 * 0.6, 0.6 * 0.6, 0.4 * 0.6);
    for (int k = 0; k < 64; k++) { /* outside: background (colour 0, white) */
        assert_near(&img, k, 12, 1, 1, 1);
        assert_near(&img, 12, k, 1, 1, 1);
        assert_near(&img, k, 51, 1, 1, 1);
        assert_near(&img, 51, k, 1, 1, 1);
    }
    free(img.rgb);
}

static void test_shadow(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_shadow.png", GHLHSR_RAYTRACE);
    Glight_src_rep l = { GLIGHT_POSITIONAL, { 1, 1, 1 }, { 0.5, 0.5, 0.9 }, { 0, 0, -1 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 1, 1, 1 };
    lit_setup(&c);
    square(0.1, 0.9, 0.3);   /* receiver */
    square(0.45, 0.55, 0.7); /* occluder: shadow on the receiver is [0.35,0.65]^2 */
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_shadow.png", &img));
    /* Pixel 25: centre 25.5/64 = 0.398 -- in the shadow, not under the occluder: black
     * (ka = 0, no ambient light active). */
    assert_near(&img, 25, 25, 0, 0, 0);
    assert_near(&img, 38, 25, 0, 0, 0);
    /* Pixel 12: centre 0.1953 -- lit: cos = (0.9-0.3)/distance to the light, att = 1. */
    double x = 12.5 / 64, d[3] = { 0.5 - x, 0.5 - x, 0.6 };
    double cosv = d[2] / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    assert_near(&img, 12, 12, cosv, cosv, cosv);
    /* Just outside the shadow edge 0.35*64 = 22.4: pixel 21 lit, 23 dark. */
    assert_true(px(&img, 21, 32)[0] > 100);
    assert_near(&img, 23, 32, 0, 0, 0);
    /* The occluder itself is lit head-on at distance 0.2 (cos 1). */
    assert_near(&img, 32, 32, 1, 1, 1);
    free(img.rgb);
}

/* ---- INQUIRE PIXEL (ARRAY) of a ray-traced frame ---------------------------------------
 * The shadow scene of test_shadow with the workstation's default sampling (corner rays:
 * anti-aliased edges, soft shading) read back before the frame is written. The readback
 * must equal the written PNG exactly: both are the same trace resolved to 8 bits, so no
 * tolerance. A 12 x 12 pixel region across the shadow's and the occluder's edges holds at
 * most 144 colours; each is made a colour table entry so that the colour indices the
 * inquiry returns name the pixels exactly. */
enum { INQ_X0 = 18, INQ_Y0 = 18, INQ_N = 12 };

static void shadow_receiver(void)
{
    Glight_src_rep l = { GLIGHT_POSITIONAL, { 1, 1, 1 }, { 0.5, 0.5, 0.9 }, { 0, 0, -1 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 1, 1, 1 };
    lit_setup(&c);
    square(0.1, 0.9, 0.3);
}

static void shadow_occluder(void) { square(0.45, 0.55, 0.7); }

static void assert_same_file(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    assert_non_null(fa);
    assert_non_null(fb);
    int ca, cb;
    long n = 0;
    do {
        ca = getc(fa);
        cb = getc(fb);
        if (ca != cb)
            fail_msg("%s and %s differ at byte %ld", a, b, n);
        n++;
    } while (ca != EOF);
    fclose(fa);
    fclose(fb);
}

/* The lowest entry of tab[0..n) equal to the 8-bit colour p, -1 if none (the rule of
 * the pixel inquiries). */
static int tab_index(const unsigned char (*tab)[3], int n, const unsigned char *p)
{
    for (int i = 0; i < n; i++)
        if (memcmp(tab[i], p, 3) == 0)
            return i;
    return -1;
}

static void test_inquire_traced(void **u)
{
    (void)u;
    /* 1: the frame written without an inquiry. */
    reset_gks();
    gopen_gks(NULL, 0);
    open_png_defaults(1, "t_rt_inq1.png", GHLHSR_RAYTRACE);
    shadow_receiver();
    shadow_occluder();
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_inq1.png", &img));
    /* The colour table: the predefined colours (2 redefined by lit_setup), then every
     * other colour of the region. */
    unsigned char tab[256][3] = { { 255, 255, 255 }, { 0, 0, 0 }, { 255, 255, 255 },
                                  { 0, 255, 0 }, { 0, 0, 255 }, { 255, 255, 0 },
                                  { 0, 255, 255 }, { 255, 0, 255 } };
    int n = 8;
    for (int y = INQ_Y0; y < INQ_Y0 + INQ_N; y++)
        for (int x = INQ_X0; x < INQ_X0 + INQ_N; x++)
            if (tab_index((const unsigned char (*)[3])tab, n, px(&img, x, y)) < 0)
                memcpy(tab[n++], px(&img, x, y), 3);
    assert_true(n > 8 + 10); /* shaded and anti-aliased: many colours */

    /* 2: the same frame inquired before it is written. */
    reset_gks();
    gopen_gks(NULL, 0);
    open_png_defaults(1, "t_rt_inq2.png", GHLHSR_RAYTRACE);
    for (int i = 8; i < n; i++) {
        Gcolr_rep cr = { { tab[i][0] / 255.0, tab[i][1] / 255.0, tab[i][2] / 255.0 } };
        gset_colr_rep(1, i, &cr);
    }
    shadow_receiver();
    shadow_occluder();
    Gint e, c;
    Gint_size d;
    const double s = 1.0 / 64;
    ginq_pixel_array_dims(1, &(Grect){ { INQ_X0 * s, (INQ_Y0 + INQ_N) * s },
                                       { (INQ_X0 + INQ_N) * s, INQ_Y0 * s } }, &e, &d);
    assert_int_equal(e, 0);
    assert_int_equal(d.size_x, INQ_N);
    assert_int_equal(d.size_y, INQ_N);
    Gint idx[INQ_N * INQ_N], len;
    Gint_list l = { 0, idx };
    Gpres_inval inv;
    ginq_pixel_array(1, &(Gpoint){ (INQ_X0 + 0.5) * s, (INQ_Y0 + INQ_N - 0.5) * s }, &d,
                     INQ_N * INQ_N, 0, &e, &inv, &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(l.num_ints, INQ_N * INQ_N);
    assert_int_equal(inv, GINVAL_ABSENT);
    for (int j = 0; j < INQ_N; j++) /* rows from the top */
        for (int i = 0; i < INQ_N; i++) {
            int x = INQ_X0 + i, y = INQ_Y0 + INQ_N - 1 - j;
            int want = tab_index((const unsigned char (*)[3])tab, n, px(&img, x, y));
            if (idx[j * INQ_N + i] != want)
                fail_msg("pixel (%d,%d): index %d, the PNG's %d", x, y, idx[j * INQ_N + i],
                         want);
        }
    ginq_pixel(1, &(Gpoint){ 25.5 * s, 25.5 * s }, &e, &c); /* in the shadow: black */
    assert_int_equal(e, 0);
    assert_int_equal(c, 1);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    assert_same_file("t_rt_inq2.png", "t_rt_inq1.png");

    /* 3: an inquiry between the two areas leaves the written frame as it is (the receiver
     * alone is seen then; the occluder is traced with it into the frame). */
    reset_gks();
    gopen_gks(NULL, 0);
    open_png_defaults(1, "t_rt_inq3.png", GHLHSR_RAYTRACE);
    shadow_receiver();
    ginq_pixel(1, &(Gpoint){ 25.5 * s, 25.5 * s }, &e, &c);
    assert_int_equal(e, 0);
    assert_int_equal(c, -1); /* lit, not yet in the shadow: no entry has its colour */
    shadow_occluder();
    ginq_pixel(1, &(Gpoint){ 25.5 * s, 25.5 * s }, &e, &c);
    assert_int_equal(c, 1);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    assert_same_file("t_rt_inq3.png", "t_rt_inq1.png");
    free(img.rgb);
}

static void quad(const double q[4][3])
{
    Gpoint3 p[4];
    for (int i = 0; i < 4; i++)
        p[i] = (Gpoint3){ q[i][0], q[i][1], q[i][2] };
    Gpoint_list3 l = { 4, p };
    gfill_area3(&l);
}

static void test_silhouettes_match_zbuffer(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_zb.png", GHLHSR_ZBUFFER);
    open_png(2, "t_rt_rt.png", GHLHSR_RAYTRACE);
    static const double a[4][3] = { { 0.13, 0.17, 0.3 }, { 0.71, 0.23, 0.3 },
                                    { 0.66, 0.74, 0.3 }, { 0.19, 0.61, 0.3 } };
    static const double b[4][3] = { { 0.37, 0.31, 0.55 }, { 0.87, 0.41, 0.6 },
                                    { 0.79, 0.89, 0.65 }, { 0.33, 0.83, 0.6 } };
    gset_fill_int_style(GSTYLE_SOLID); /* the tracer ignores the style; z-buffer does not */
    gset_fill_colr_ind(2); /* red, flat (reflectance equation NONE by default) */
    quad(b);
    gset_fill_colr_ind(4); /* blue, behind b but drawn later */
    quad(a);
    gdeactivate_ws(1);
    gclose_ws(1);
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_gks();
    no_errors();
    image z, r;
    assert_true(read_png("t_rt_zb.png", &z));
    assert_true(read_png("t_rt_rt.png", &r));
    assert_int_equal(z.w, r.w);
    assert_int_equal(z.h, r.h);
    int covered = 0, red = 0, blue = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            const unsigned char *p = px(&z, x, y), *q = px(&r, x, y);
            if (memcmp(p, q, 3) != 0)
                fail_msg("pixel (%d,%d): z-buffer %d %d %d, ray traced %d %d %d", x, y, p[0],
                         p[1], p[2], q[0], q[1], q[2]);
            covered += !(p[0] == 255 && p[1] == 255 && p[2] == 255);
            red += p[0] == 255 && p[1] == 0 && p[2] == 0;
            blue += p[0] == 0 && p[1] == 0 && p[2] == 255;
        }
    assert_true(covered > 1000);
    assert_true(red > 500 && blue > 300);
    assert_int_equal(covered, red + blue);
    free(z.rgb);
    free(r.rgb);
}

/* Silhouettes in an oblique-perspective and an oblique-parallel view with view clipping and a
 * workstation window smaller than the clip volume: the ray-traced picture and the z-buffer
 * picture agree in >= 99.9 % of the pixels (differences only where a pixel centre lies on an
 * edge within rounding). */
static void silhouettes_view(Gproj_type proj, const char *zb, const char *rt)
{
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, zb, GHLHSR_ZBUFFER);
    open_png(2, rt, GHLHSR_RAYTRACE);
    Glimit win = { 0.05, 0.95, 0.1, 0.9 };
    gset_ws_win(1, &win);
    gset_ws_win(2, &win);
    Gint err;
    Gview_rep3 v;
    Gpoint3 vrp = { 0.5, 0.5, 0.4 };
    Gvec3 vpn = { 0.3, -0.4, 1 }, vup = { 0, 1, 0 };
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, v.ori_matrix);
    assert_int_equal(err, 0);
    Gview_map3 map = { { -0.6, 0.6, -0.6, 0.6 }, { 0, 1, 0, 1, 0, 1 }, proj,
                       { 0.15, -0.1, 2 }, 0.5, -0.6, 0.6 };
    geval_view_map_matrix3(&map, &err, v.map_matrix);
    assert_int_equal(err, 0);
    v.clip_limit = (Glimit3){ 0.1, 0.85, 0.05, 1, 0, 1 };
    v.xy_clip = v.back_clip = v.front_clip = GIND_CLIP;
    gset_view_rep3(1, 1, &v);
    gset_view_rep3(2, 1, &v);
    gset_view_ind(1);
    gset_fill_int_style(GSTYLE_SOLID);
    static const double a[4][3] = { { 0.13, 0.17, 0.3 }, { 0.71, 0.23, 0.3 },
                                    { 0.66, 0.74, 0.3 }, { 0.19, 0.61, 0.3 } };
    /* planar, z = -0.05 + 0.5x + 0.1y: it cuts through a (z = 0.3) near x = 0.6 */
    static const double b[4][3] = { { 0.37, 0.31, 0.166 }, { 0.87, 0.41, 0.426 },
                                    { 0.79, 0.89, 0.434 }, { 0.33, 0.83, 0.198 } };
    gset_fill_colr_ind(2);
    quad(b);
    gset_fill_colr_ind(4);
    quad(a);
    gdeactivate_ws(1);
    gclose_ws(1);
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_gks();
    no_errors();
    image z, r;
    assert_true(read_png(zb, &z));
    assert_true(read_png(rt, &r));
    int same = 0, red = 0, blue = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            const unsigned char *p = px(&z, x, y), *q = px(&r, x, y);
            same += memcmp(p, q, 3) == 0;
            red += q[0] == 255 && q[1] == 0;
            blue += q[2] == 255 && q[0] == 0;
        }
    print_message("%s: %d of 4096 pixels agree (red %d, blue %d)\n", rt, same, red, blue);
    assert_true(red > 200 && blue > 200); /* both areas visible, partly hidden */
    assert_true(same >= 4092);            /* >= 99.9 % */
    free(z.rgb);
    free(r.rgb);
}

static void test_silhouettes_views(void **u)
{
    (void)u;
    silhouettes_view(GPROJ_PERSPECT, "t_rt_zb_persp.png", "t_rt_rt_persp.png");
    silhouettes_view(GPROJ_PARAL, "t_rt_zb_par.png", "t_rt_rt_par.png");
}

#define EXPECT(call, errnum, fctid)                                                \
    do {                                                                           \
        n_captured = 0;                                                            \
        call;                                                                      \
        assert_int_equal(n_captured, 1);                                           \
        assert_int_equal(captured[0].err, (errnum));                               \
        assert_int_equal(captured[0].fct, (fctid));                                \
    } while (0)

static void test_errors(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(1, NULL, GWS_TYPE_NULL);
    Garea_props ok = { 0.2, 0.8, 0.5, { 1, 1, 1 }, 10, 0.5, 1.5 }, bad;
    bad = ok; bad.ambient_coef = -0.1;
    EXPECT(gset_area_props(&bad), 2000, GFN_SAPR);
    bad = ok; bad.diffuse_coef = 1.5;
    EXPECT(gset_back_area_props(&bad), 2000, GFN_SBAPR);
    bad = ok; bad.transpar_coef = NAN;
    EXPECT(gset_area_props(&bad), 2000, GFN_SAPR);
    bad = ok; bad.specular_exp = -1;
    EXPECT(gset_area_props(&bad), 2000, GFN_SAPR);
    bad = ok; bad.refr_index = 0;
    EXPECT(gset_area_props(&bad), 2000, GFN_SAPR);
    bad = ok; bad.specular_colr.green = 1.01;
    EXPECT(gset_area_props(&bad), 96, GFN_SAPR);
    EXPECT(gset_area_props(NULL), 2000, GFN_SAPR);
    EXPECT(gset_refl_eq(0), 524, GFN_SRFEQ);
    EXPECT(gset_back_refl_eq(5), 524, GFN_SBRFEQ);

    n_captured = 0;
    gset_area_props(&ok);
    gset_back_refl_eq(GREFL_AMB_DIFF_SPEC);
    Garea_props f, b;
    Gint err, fr, br;
    ginq_area_props(&err, &f, &b);
    assert_int_equal(err, 0);
    assert_memory_equal(&f, &ok, sizeof ok);
    assert_true(b.ambient_coef == 1 && b.diffuse_coef == 1 && b.specular_coef == 0);
    ginq_refl_eq(&err, &fr, &br);
    assert_int_equal(fr, GREFL_NONE);
    assert_int_equal(br, GREFL_AMB_DIFF_SPEC);
    assert_int_equal(n_captured, 0);

    Glight_src_rep l = { GLIGHT_SPOT, { 1, 0.5, 0 }, { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0.5 }, 2, 0.5 }, lb;
    EXPECT(gset_light_src_rep(1, 0, &l), 529, GFN_SLSR);
    EXPECT(gset_light_src_rep(1, 65, &l), 529, GFN_SLSR);
    lb = l; lb.type = 5;
    EXPECT(gset_light_src_rep(1, 3, &lb), 531, GFN_SLSR);
    lb = l; lb.spread_angle = 3.2;
    EXPECT(gset_light_src_rep(1, 3, &lb), 532, GFN_SLSR);
    lb = l; lb.colr.red = -0.5;
    EXPECT(gset_light_src_rep(1, 3, &lb), 96, GFN_SLSR);
    EXPECT(gset_light_src_rep(2, 3, &l), 25, GFN_SLSR);
    ginq_light_src_rep(1, 3, &err, &lb);
    assert_int_equal(err, 2002);
    n_captured = 0;
    gset_light_src_rep(1, 64, &l);
    assert_int_equal(n_captured, 0);
    ginq_light_src_rep(1, 64, &err, &lb);
    assert_int_equal(err, 0);
    assert_memory_equal(&lb, &l, sizeof l);
    ginq_light_src_rep(1, 1, &err, &lb); /* predefined: white ambient */
    assert_int_equal(err, 0);
    assert_int_equal(lb.type, GLIGHT_AMBIENT);
    ginq_light_src_rep(1, 65, &err, &lb);
    assert_int_equal(err, 529);

    Gint on[3] = { 5, 64, 1 }, off[2] = { 2, 5 }, zero = 0;
    Gint_list lon = { 3, on }, loff = { 2, off }, lz = { 1, &zero };
    EXPECT(gset_light_src_state(&lz, NULL), 533, GFN_SLSS);
    EXPECT(gset_light_src_state(NULL, &lz), 533, GFN_SLSS);
    EXPECT(gset_light_src_state(&lon, &loff), 535, GFN_SLSS);
    n_captured = 0;
    loff.num_ints = 1; /* deactivate 2 */
    gset_light_src_state(&lon, &loff);
    assert_int_equal(n_captured, 0);
    Gint out[4], len;
    Gint_list lout = { 0, out };
    ginq_light_src_state(4, 0, &err, &lout, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 3);
    assert_int_equal(lout.num_ints, 3);
    assert_int_equal(out[0], 1);
    assert_int_equal(out[1], 5);
    assert_int_equal(out[2], 64);
    ginq_light_src_state(4, 2, &err, &lout, &len);
    assert_int_equal(lout.num_ints, 1);
    assert_int_equal(out[0], 64);

    /* ESCAPE: clipped secondary rays; the null workstation does not support it. */
    Gint d[2] = { 1, 1 };
    Gescape_in_data in = { { 2, d, 0, NULL, 0, NULL } };
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &in, NULL, NULL), 180, GFN_ESC);
    EXPECT(gescape(-999, &in, NULL, NULL), 180, GFN_ESC);
    Gescape_in_data short_rec = { { 0, d, 0, NULL, 0, NULL } };
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &short_rec, NULL, NULL), 182, GFN_ESC);
    /* SET HLHSR MODE 4 is refused by the null workstation. */
    EXPECT(gset_hlhsr_mode(1, GHLHSR_RAYTRACE), 511, GFN_SHRM);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
}

/* The escape is accepted by the PNG workstation and the picture still traces. */
static void test_escape_png(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_esc.png", GHLHSR_RAYTRACE);
    Gint d[2] = { 1, 1 };
    Gescape_in_data in = { { 2, d, 0, NULL, 0, NULL } };
    d[1] = 2; /* a bad record on a workstation that supports the escape: 182, no effect */
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &in, NULL, NULL), 182, GFN_ESC);
    d[1] = 1;
    n_captured = 0;
    gescape(GESC_RT_CLIP_SECONDARY, &in, NULL, NULL);
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, 0, -1 }, { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.5, 0.5, 0.5 };
    lit_setup(&c);
    square(0.2, 0.8, 0.5);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_esc.png", &img));
    assert_near(&img, 32, 32, 0.5, 0.5, 0.5);
    free(img.rgb);
}


/* ---- ray-tracing ESCAPEs ------------------------------------------------------------- */

/* ESCAPE fid on workstation ws with ints[1..n] = v[0..n-1]; returns the error reported
 * (0 if none). */
static int esc_ints(int fid, int ws, int n, const Gint *v)
{
    Gint d[4] = { ws, 0, 0, 0 };
    for (int k = 0; k < n && k < 3; k++)
        d[k + 1] = v[k];
    Gescape_in_data in = { { n + 1, d, 0, NULL, 0, NULL } };
    n_captured = 0;
    gescape(fid, &in, NULL, NULL);
    return n_captured ? captured[0].err : 0;
}

static int esc1(int fid, int ws, Gint v) { return esc_ints(fid, ws, 1, &v); }

static int esc_cutoff(int ws, Gfloat c)
{
    Gint d[1] = { ws };
    Gescape_in_data in = { { 1, d, 1, &c, 0, NULL } };
    n_captured = 0;
    gescape(GESC_RT_CUTOFF, &in, NULL, NULL);
    return n_captured ? captured[0].err : 0;
}

typedef struct { Gint i[8]; Gfloat f[2]; } rt_stat_rec;

static void get_stats(int ws, rt_stat_rec *s)
{
    Gint d[1] = { ws };
    Gescape_in_data in = { { 1, d, 0, NULL, 0, NULL } };
    Gstore store = NULL;
    Gescape_out_data *out = NULL;
    Gint e;
    gcreate_store(&e, &store);
    assert_int_equal(e, 0);
    n_captured = 0;
    gescape(GESC_RT_STATS, &in, &store, &out);
    no_errors();
    assert_non_null(out);
    assert_int_equal(out->num_ints, 8);
    assert_int_equal(out->num_floats, 2);
    memcpy(s->i, out->ints, sizeof s->i);
    memcpy(s->f, out->floats, sizeof s->f);
    gdel_store(store);
}

enum { ST_EYE, ST_HIT, ST_REFL, ST_REFR, ST_SHADOW, ST_CELLS, ST_REFS, ST_PRIMS };

/* The workstation's default sampling: rays at the 65 x 65 pixel corners of a 64 x 64
 * image, each pixel the mean of its 4 corners. The square [0.2,0.8]^2 covers corners
 * 13..51 (12.8 and 51.2 px): pixels 13..50 are the lit colour as with centre rays, pixels
 * 12 and 51 of an edge half lit and half background (2 of 4 corners), the corner pixels
 * (12,12) and (51,51) a quarter. ESCAPE -103 (1 sample) switches to 64 x 64 centre rays,
 * -109 back to corner rays. */
static void test_default_sampling(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png_defaults(1, "t_rt_default.png", GHLHSR_RAYTRACE);
    lambert_square();
    gupd_ws(1, GFLAG_PERFORM);
    rt_stat_rec s;
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 65 * 65);
    assert_int_equal(s.i[ST_HIT], 39 * 39);
    image img;
    assert_true(read_png("t_rt_default.png", &img));
    const double lit[3] = { 0.8 * 0.6, 0.6 * 0.6, 0.4 * 0.6 };
    for (int k = 13; k <= 50; k++) {
        assert_near(&img, k, 30, lit[0], lit[1], lit[2]);
        for (int e = 12; e <= 51; e += 39) {
            assert_near(&img, e, k, 0.5 * lit[0] + 0.5, 0.5 * lit[1] + 0.5, 0.5 * lit[2] + 0.5);
            assert_near(&img, k, e, 0.5 * lit[0] + 0.5, 0.5 * lit[1] + 0.5, 0.5 * lit[2] + 0.5);
        }
        assert_near(&img, k, 11, 1, 1, 1);
        assert_near(&img, 52, k, 1, 1, 1);
    }
    assert_near(&img, 12, 12, 0.25 * lit[0] + 0.75, 0.25 * lit[1] + 0.75, 0.25 * lit[2] + 0.75);
    assert_near(&img, 51, 51, 0.25 * lit[0] + 0.75, 0.25 * lit[1] + 0.75, 0.25 * lit[2] + 0.75);
    free(img.rgb);
    /* one centre ray per pixel, then corner rays again */
    Gint d[2] = { 1, 1 };
    Gescape_in_data in = { { 2, d, 0, NULL, 0, NULL } };
    gescape(GESC_RT_SAMPLES, &in, NULL, NULL);
    gclear_ws(1, GFLAG_ALWAYS);
    square(0.2, 0.8, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 64 * 64);
    assert_int_equal(s.i[ST_HIT], 38 * 38);
    gescape(GESC_RT_SPD, &in, NULL, NULL);
    gclear_ws(1, GFLAG_ALWAYS);
    square(0.2, 0.8, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 65 * 65);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
}

/* A 64x64 window fully covered by one square lit by one directional light (plus ambient
 * light 1 when ambient is set): every count of the statistics is known. */
static void test_stats_counts(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_stats.png", GHLHSR_RAYTRACE);
    rt_stat_rec s;
    get_stats(1, &s); /* nothing traced yet: zeros */
    for (int k = 0; k < 8; k++)
        assert_int_equal(s.i[k], 0);
    /* no store for the output record: 182 */
    Gint d[1] = { 1 };
    Gescape_in_data in = { { 1, d, 0, NULL, 0, NULL } };
    EXPECT(gescape(GESC_RT_STATS, &in, NULL, NULL), 182, GFN_ESC);
    n_captured = 0;

    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, 0, -1 }, { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.5, 0.5, 0.5 };
    lit_setup(&c);
    Gint both[2] = { 1, 2 };
    Gint_list a = { 2, both };
    gset_light_src_state(&a, NULL); /* ambient light 1: no shadow ray */
    square(0, 1, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 4096);
    assert_int_equal(s.i[ST_HIT], 4096);
    assert_int_equal(s.i[ST_SHADOW], 4096);
    assert_int_equal(s.i[ST_REFL], 0);
    assert_int_equal(s.i[ST_REFR], 0);
    assert_int_equal(s.i[ST_PRIMS], 1);
    assert_int_equal(s.i[ST_CELLS], 0); /* one primitive: brute force, no grid */
    assert_int_equal(s.i[ST_REFS], 0);
    assert_true(s.f[0] >= 0 && s.f[1] >= 0 && s.f[1] < 60);

    /* Second frame: the left half specular (every eye hit spawns one reflection ray,
     * which leaves the scene), the right half transparent of index 1 (one refraction ray
     * straight through, no Fresnel reflection), a third area clipped away in the core. */
    gclear_ws(1, GFLAG_ALWAYS);
    Garea_props sp = { 0, 1, 0.5, { 1, 1, 1 }, 10, 0, 1 };
    gset_area_props(&sp);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    Gpoint3 left[4] = { { 0, 0, 0.5 }, { 0.5, 0, 0.5 }, { 0.5, 1, 0.5 }, { 0, 1, 0.5 } };
    Gpoint_list3 pl = { 4, left };
    gfill_area3(&pl);
    Garea_props tr = { 0, 1, 0, { 1, 1, 1 }, 1, 0.5, 1 };
    gset_area_props(&tr);
    gset_refl_eq(GREFL_AMB_DIFF);
    Gpoint3 right[4] = { { 0.5, 0, 0.5 }, { 1, 0, 0.5 }, { 1, 1, 0.5 }, { 0.5, 1, 0.5 } };
    pl.points = right;
    gfill_area3(&pl);
    Gpoint3 tiny[3] = { { 2, 2, 2 }, { 3, 2, 2 }, { 3, 3, 2 } }; /* clipped away entirely */
    pl = (Gpoint_list3){ 3, tiny };
    gfill_area3(&pl);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 4096);
    assert_int_equal(s.i[ST_HIT], 4096);
    assert_int_equal(s.i[ST_SHADOW], 4096);  /* one directional light per hit */
    assert_int_equal(s.i[ST_REFL], 2048);    /* the specular half */
    assert_int_equal(s.i[ST_REFR], 2048);    /* the transparent half (index 1: no Fresnel) */
    assert_int_equal(s.i[ST_PRIMS], 2);
    /* depth 1: no secondary rays at all */
    assert_int_equal(esc1(GESC_RT_MAX_DEPTH, 1, 1), 0);
    gclear_ws(1, GFLAG_ALWAYS);
    pl = (Gpoint_list3){ 4, left };
    gset_area_props(&sp);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    gfill_area3(&pl);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 4096);
    assert_int_equal(s.i[ST_HIT], 2048);
    assert_int_equal(s.i[ST_SHADOW], 2048);
    assert_int_equal(s.i[ST_REFL], 0);
    /* SPD procedure: (64+1)^2 corner rays; corners 13..51 lie on [0.2,0.8] = [12.8,51.2] */
    assert_int_equal(esc1(GESC_RT_SPD, 1, 1), 0);
    gclear_ws(1, GFLAG_ALWAYS);
    square(0.2, 0.8, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_EYE], 65 * 65);
    assert_int_equal(s.i[ST_HIT], 39 * 39);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
}

/* A mirror tilted 45 degrees (normal (0,1,1)) sends the vertical eye rays along +y onto a
 * green wall edge-on to the viewer: depth >= 2 shows green, depth 1 only the mirror's own
 * (unlit: black) colour. */
static void mirror_scene(int ws, int depth, int clip_secondary)
{
    if (depth > 0)
        assert_int_equal(esc1(GESC_RT_MAX_DEPTH, ws, depth), 0);
    assert_int_equal(esc1(GESC_RT_CLIP_SECONDARY, ws, clip_secondary), 0);
    Garea_props m = { 0, 0, 1, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&m);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    static const double mirror[4][3] = { { 0.2, 0.2, 0.7 }, { 0.8, 0.2, 0.7 },
                                         { 0.8, 0.6, 0.3 }, { 0.2, 0.6, 0.3 } };
    quad(mirror);
    gset_refl_eq(GREFL_NONE);
    gset_fill_colr_ind(3); /* green */
    static const double wall[4][3] = { { 0, 0.9, 0 }, { 1, 0.9, 0 }, { 1, 0.9, 1 }, { 0, 0.9, 1 } };
    quad(wall);
}

static void test_depth_mirror(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_mirror5.png", GHLHSR_RAYTRACE);
    open_png(2, "t_rt_mirror1.png", GHLHSR_RAYTRACE);
    /* bad depth records: 182, no effect */
    assert_int_equal(esc1(GESC_RT_MAX_DEPTH, 2, 0), 182);
    assert_int_equal(esc1(GESC_RT_MAX_DEPTH, 2, 65), 182);
    Gint d[1] = { 2 };
    Gescape_in_data in = { { 1, d, 0, NULL, 0, NULL } };
    EXPECT(gescape(GESC_RT_MAX_DEPTH, &in, NULL, NULL), 182, GFN_ESC);
    n_captured = 0;
    gdeactivate_ws(2);
    mirror_scene(1, 0, 0); /* default depth 5 */
    gdeactivate_ws(1);
    gactivate_ws(2);
    mirror_scene(2, 1, 0);
    gdeactivate_ws(2);
    gclose_ws(1);
    gclose_ws(2);
    gclose_gks();
    no_errors();
    image a, b;
    assert_true(read_png("t_rt_mirror5.png", &a));
    assert_true(read_png("t_rt_mirror1.png", &b));
    /* mirror pixels: x 13..50, y 13..37 (y in [0.2,0.6]) */
    for (int y = 14; y <= 36; y += 2)
        for (int x = 14; x <= 49; x += 5) {
            assert_near(&a, x, y, 0, 1, 0);
            assert_near(&b, x, y, 0, 0, 0);
        }
    assert_near(&a, 5, 5, 1, 1, 1); /* background */
    free(a.rgb);
    free(b.rgb);
}

/* The same picture for 1 and 2 threads (and 0 = all CPUs), with shadows, a mirror and
 * jittered 4 samples per pixel: bit-identical files. */
static void threads_picture(const char *file, int threads)
{
    open_png(1, file, GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, threads), 0);
    Gint sj[2] = { 4, 1 };
    assert_int_equal(esc_ints(GESC_RT_SAMPLES, 1, 2, sj), 0);
    Glight_src_rep l = { GLIGHT_POSITIONAL, { 1, 1, 1 }, { 0.5, 0.3, 0.95 }, { 0, 0, -1 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.9, 0.7, 0.3 };
    lit_setup(&c);
    square(0.05, 0.95, 0.1);
    square(0.3, 0.45, 0.5);
    mirror_scene(1, 0, 0);
    gdeactivate_ws(1);
    gclose_ws(1);
}

static void test_threads_identical(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, 1), 182); /* ws 1 not open */
    threads_picture("t_rt_thr1.png", 1);
    threads_picture("t_rt_thr2.png", 2);
    threads_picture("t_rt_thr0.png", 0);
    open_png(1, "t_rt_thr_bad.png", GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, -1), 182);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, 257), 182);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    n_captured = 0;
    image a, b, c;
    assert_true(read_png("t_rt_thr1.png", &a));
    assert_true(read_png("t_rt_thr2.png", &b));
    assert_true(read_png("t_rt_thr0.png", &c));
    assert_memory_equal(a.rgb, b.rgb, (size_t)a.w * a.h * 3);
    assert_memory_equal(a.rgb, c.rgb, (size_t)a.w * a.h * 3);
    /* the picture is not trivial: lit floor, shadows (of mirror and wall), mirror */
    assert_true(px(&a, 32, 48)[0] > 100);
    int greenish = 0, dark = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            const unsigned char *p = px(&a, x, y);
            greenish += p[1] > p[0] + 50;
            dark += p[0] < 30 && p[1] < 30 && p[2] < 30;
        }
    assert_true(greenish > 50);
    assert_true(dark > 10);
    free(a.rgb);
    free(b.rgb);
    free(c.rgb);
}

/* Areas queued with 2 threads under view orientations other than the identity: view 1
 * turns NDC3 by 90 degrees, scales it by 2 and shifts it (its mapping takes it back into the
 * picture); view 2 scales x by 3e100, so the areas reaching x > 1/3 are beyond the tracer's
 * coordinate range (clipped at the call to the display volume, x in [0, 1] of VRC3) and the
 * others not; the last area, in view 2 from x 0 to 1, is in sight once clipped. With 2 threads the areas are queued (with the orientation of each area's view,
 * the views alternating area by area: view 1's points mapped by the worker, view 2's mapped
 * at the call, where the range is decided, then recorded by the worker): the file is
 * bit-identical to the one thread's. */
static void oriented_picture(const char *file, int threads)
{
    open_png(1, file, GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, threads), 0);
    Gview_rep3 v;
    memset(&v, 0, sizeof v);
    const double ori[4][4] = { { 0, -2, 0, 1.5 }, { 2, 0, 0, -0.5 }, { 0, 0, 1, 0 },
                               { 0, 0, 0, 1 } };
    const double map[4][4] = { { 0.5, 0, 0, 0.25 }, { 0, 0.5, 0, 0.25 }, { 0, 0, 1, 0 },
                               { 0, 0, 0, 1 } };
    memcpy(v.ori_matrix, ori, sizeof ori);
    memcpy(v.map_matrix, map, sizeof map);
    v.clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    v.xy_clip = v.back_clip = v.front_clip = GIND_CLIP;
    gset_view_rep3(1, 1, &v);
    memset(&v, 0, sizeof v);
    for (int i = 0; i < 4; i++)
        v.ori_matrix[i][i] = v.map_matrix[i][i] = 1;
    v.ori_matrix[0][0] = 3e100; /* its display volume stays x in [0, 1] of VRC3 */
    v.clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    v.xy_clip = v.back_clip = v.front_clip = GIND_CLIP;
    gset_view_rep3(1, 2, &v);
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0.3, -0.5, -0.8 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.9, 0.6, 0.3 };
    lit_setup(&c);
    for (int k = 0; k < 40; k++) {
        const double x = 0.02 * k, y = 0.3 + 0.01 * k, z = 0.2 + 0.015 * k;
        Gpoint3 t[4] = { { x, y, z }, { x + 0.3, y - 0.1, z + 0.1 }, { x + 0.1, y + 0.4, z },
                         { x, y + 0.3, z + 0.05 } };
        Gpoint_list3 pl = { 3 + k % 2, t };
        gset_view_ind(1 + k % 2);
        gfill_area3(&pl);
    }
    /* beyond the range too, and in sight once clipped: a band across the bottom */
    Gpoint3 far[3] = { { 0, 0.05, 0.5 }, { 1, 0.05, 0.5 }, { 0, 0.25, 0.5 } };
    gset_view_ind(2);
    gfill_area3(&(Gpoint_list3){ 3, far });
    gdeactivate_ws(1);
    gclose_ws(1);
}

static void test_threads_oriented(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    oriented_picture("t_rt_ori1.png", 1);
    oriented_picture("t_rt_ori2.png", 2);
    gclose_gks();
    no_errors();
    assert_same_file("t_rt_ori1.png", "t_rt_ori2.png");
    image a;
    assert_true(read_png("t_rt_ori1.png", &a));
    int lit = 0;
    for (int y = 0; y < a.h; y++)
        for (int x = 0; x < a.w; x++)
            lit += px(&a, x, y)[2] < 200; /* not the white background */
    assert_true(lit > 200);
    for (int x = 4; x < 60; x += 8) /* the band clipped at the call */
        assert_true(px(&a, x, 9)[2] < 200);
    free(a.rgb);
}

/* The view table's number (gks_ws.views_gen): not 0, a new one at each SET VIEW
 * REPRESENTATION 3 (an equal representation too), none at other calls, different on two
 * workstations. */
static void test_views_gen(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    n_captured = 0;
    open_png(1, "t_rt_vg1.png", GHLHSR_RAYTRACE);
    open_png(2, "t_rt_vg2.png", GHLHSR_RAYTRACE);
    const gks_ws *w1 = gks_ws_lookup(1), *w2 = gks_ws_lookup(2);
    assert_non_null(w1);
    assert_non_null(w2);
    const uint64_t g1 = w1->views_gen, g2 = w2->views_gen;
    assert_true(g1 != 0 && g2 != 0 && g1 != g2);
    Gview_rep3 v;
    Gint err;
    ginq_view_rep3(1, 1, &err, &v);
    assert_int_equal(err, 0);
    gset_view_ind(1);
    Gpoint3 t[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    gfill_area3(&(Gpoint_list3){ 3, t });
    gset_fill_colr_ind(2);
    assert_true(w1->views_gen == g1 && w2->views_gen == g2);
    gset_view_rep3(1, 1, &v); /* the same representation: a new number all the same */
    const uint64_t h1 = w1->views_gen;
    assert_true(h1 != g1 && h1 != g2 && w2->views_gen == g2);
    v.ori_matrix[1][3] = 0.25;
    gset_view_rep3(2, 3, &v);
    assert_true(w2->views_gen != g2 && w2->views_gen != h1 && w1->views_gen == h1);
    no_errors();
    EXPECT(gset_view_rep3(1, 0, &v), 515, GFN_SVWR); /* refused: the table unchanged */
    assert_true(w1->views_gen == h1);
    gdeactivate_ws(1);
    gdeactivate_ws(2);
    gclose_ws(1);
    gclose_ws(2);
    gclose_gks();
}

/* Queued areas of one attribute setting whose view's orientation changes between calls:
 * with 2 threads the worker maps their points with the orientation the display list's
 * record keeps, whose key follows the view table's number (gks_ws.views_gen) as well as
 * the attributes'. Eight columns of two triangles each, the same attributes, view 1
 * shifted in y by -0.05 more before each column. The file equals the one thread's (which
 * maps each area at its call), and each column's pixels differ from the one before. */
static void view_changes_picture(const char *file, int threads)
{
    open_png(1, file, GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, threads), 0);
    Grgb c = { 0.9, 0.6, 0.3 };
    lit_setup(&c);
    Gview_rep3 v;
    memset(&v, 0, sizeof v);
    for (int i = 0; i < 4; i++)
        v.ori_matrix[i][i] = v.map_matrix[i][i] = 1;
    v.clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    v.xy_clip = v.back_clip = v.front_clip = GIND_CLIP;
    gset_view_ind(1);
    for (int k = 0; k < 8; k++) {
        v.ori_matrix[1][3] = -0.05 * k;
        gset_view_rep3(1, 1, &v);
        const double x0 = 0.125 * k, x1 = x0 + 0.125;
        Gpoint3 t0[3] = { { x0, 0.3, 0.5 }, { x1, 0.3, 0.5 }, { x1, 0.9, 0.5 } };
        Gpoint3 t1[3] = { { x0, 0.3, 0.5 }, { x1, 0.9, 0.5 }, { x0, 0.9, 0.5 } };
        gfill_area3(&(Gpoint_list3){ 3, t0 });
        gfill_area3(&(Gpoint_list3){ 3, t1 });
    }
    gdeactivate_ws(1);
    gclose_ws(1);
}

static void test_threads_view_changes(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    view_changes_picture("t_rt_view1.png", 1);
    view_changes_picture("t_rt_view2.png", 2);
    gclose_gks();
    no_errors();
    assert_same_file("t_rt_view1.png", "t_rt_view2.png");
    image a;
    assert_true(read_png("t_rt_view1.png", &a));
    for (int k = 1; k < 8; k++) { /* the columns' centres, top to bottom */
        int same = 1;
        for (int y = 0; y < a.h; y++)
            same &= memcmp(px(&a, 8 * k - 4, y), px(&a, 8 * k + 4, y), 3) == 0;
        if (same)
            fail_msg("column %d equals column %d", k, k - 1);
    }
    free(a.rgb);
}

/* Queued areas whose attributes change between calls: with 2 threads the display list's
 * record after one of the same attribute number (gks_prim.attr_gen) shares its attributes
 * unseen, so each kind of change that feeds the tracer's attributes must reach the next
 * area. Eight columns of two triangles each, one change before each column: an individual
 * colour, the colour table, an aspect source flag, a fill bundle, the area properties, the
 * light sources' state (the ambient light off), the reflectance equation. The file equals
 * the one thread's (which records each area with its own attributes), and each column
 * differs from the one before it. */
static Gasfs asfs_with(Gasf fill_colr)
{
    Gasfs a;
    memset(&a, 0, sizeof a);
    for (Gasf *f = &a.linetype; f <= &a.fill_colr_ind; f++)
        *f = GASF_INDIV;
    a.fill_colr_ind = fill_colr;
    return a;
}

static void attr_changes_picture(const char *file, int threads)
{
    open_png(1, file, GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_THREADS, 1, threads), 0);
    const Gasfs indiv = asfs_with(GASF_INDIV), bundled = asfs_with(GASF_BUNDLED);
    gset_asfs(&indiv); /* as the picture before left them */
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 0.3, 0.3, 0.3 }, { 0, 0, 0 }, { 0, 0, 0 },
                           { 1, 0 }, 0, 1 };
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, -0.6, -0.8 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 1, &amb);
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.9, 0.6, 0.3 };
    lit_setup(&c);
    gset_colr_rep(1, 3, &(Gcolr_rep){ { 0.2, 0.8, 0.4 } });
    gset_colr_rep(1, 4, &(Gcolr_rep){ { 0.3, 0.3, 0.9 } });
    gset_fill_rep(1, 5, &(Gfill_bundle){ GSTYLE_SOLID, 1, 4 });
    gset_fill_ind(5);
    Gint both[2] = { 1, 2 }, one = 1;
    gset_light_src_state(&(Gint_list){ 2, both }, NULL);
    for (int k = 0; k < 8; k++) {
        switch (k) {
        case 1: gset_fill_colr_ind(3); break;
        case 2: gset_colr_rep(1, 3, &(Gcolr_rep){ { 0.8, 0.2, 0.7 } }); break;
        case 3: gset_asfs(&bundled); break;
        case 4: gset_fill_rep(1, 5, &(Gfill_bundle){ GSTYLE_SOLID, 1, 2 }); break;
        case 5: gset_area_props(&(Garea_props){ 0.2, 0.5, 0, { 1, 1, 1 }, 1, 0, 1 }); break;
        case 6: gset_light_src_state(NULL, &(Gint_list){ 1, &one }); break;
        case 7: gset_refl_eq(GREFL_NONE); break;
        default: break;
        }
        const double x0 = 0.125 * k, x1 = x0 + 0.125;
        Gpoint3 t0[3] = { { x0, 0.1, 0.5 }, { x1, 0.1, 0.5 }, { x1, 0.9, 0.5 } };
        Gpoint3 t1[3] = { { x0, 0.1, 0.5 }, { x1, 0.9, 0.5 }, { x0, 0.9, 0.5 } };
        gfill_area3(&(Gpoint_list3){ 3, t0 });
        gfill_area3(&(Gpoint_list3){ 3, t1 });
    }
    gdeactivate_ws(1);
    gclose_ws(1);
}

static void test_threads_attr_changes(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    attr_changes_picture("t_rt_attr1.png", 1);
    attr_changes_picture("t_rt_attr2.png", 2);
    gclose_gks();
    no_errors();
    assert_same_file("t_rt_attr1.png", "t_rt_attr2.png");
    image a;
    assert_true(read_png("t_rt_attr1.png", &a));
    for (int k = 1; k < 8; k++) { /* the columns' centres, above and below the diagonal */
        for (int y = 16; y <= 48; y += 32) {
            const unsigned char *p = px(&a, 8 * k - 4, y), *q = px(&a, 8 * k + 4, y);
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
                fail_msg("column %d equals column %d at y %d", k, k - 1, y);
        }
    }
    free(a.rgb);
}

/* Samples per pixel: a red square over [0.2,0.8]^2 (edge at pixel 12.8): 1 sample leaves
 * pixel 12 white, 16 samples cover 1 of its 4 strata columns: 1/4 red over white. Workstation
 * 3 also has a polyline (an annotation) far from the square, so its picture is composed by
 * the coverage of the sample rays instead of taken as traced: the same pixels result. */
static void test_samples_edges(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_s1.png", GHLHSR_RAYTRACE);
    open_png(2, "t_rt_s16.png", GHLHSR_RAYTRACE);
    open_png(3, "t_rt_s16c.png", GHLHSR_RAYTRACE);
    static const Gint bad[][2] = { { 0, 0 }, { 3, 0 }, { 257, 0 }, { 289, 0 }, { 4, 2 }, { 4, -1 } };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
        assert_int_equal(esc_ints(GESC_RT_SAMPLES, 2, 2, bad[k]), 182);
    assert_int_equal(esc1(GESC_RT_SAMPLES, 2, 16), 0); /* jitter omitted: off */
    assert_int_equal(esc1(GESC_RT_SAMPLES, 3, 16), 0);
    assert_int_equal(esc_ints(GESC_RT_SAMPLES, 2, 2, bad[3]), 182); /* no effect */
    n_captured = 0;
    gset_fill_colr_ind(2);
    square(0.2, 0.8, 0.5);
    gdeactivate_ws(1);
    gdeactivate_ws(2);
    Gpoint3 line[2] = { { 0.1, 0.03, 0.5 }, { 0.9, 0.03, 0.5 } };
    Gpoint_list3 pl = { 2, line };
    gpolyline3(&pl); /* on workstation 3 only */
    gdeactivate_ws(3);
    gclose_ws(1);
    gclose_ws(2);
    gclose_ws(3);
    gclose_gks();
    no_errors();
    image a, b, c;
    assert_true(read_png("t_rt_s1.png", &a));
    assert_true(read_png("t_rt_s16.png", &b));
    assert_true(read_png("t_rt_s16c.png", &c));
    assert_near(&a, 12, 30, 1, 1, 1);
    assert_near(&b, 12, 30, 1, 0.75, 0.75);
    assert_near(&b, 51, 30, 1, 0.75, 0.75); /* 51.2: 1 of 4 columns (51.125) */
    assert_near(&b, 12, 12, 1, 1 - 1.0 / 16, 1 - 1.0 / 16); /* corner: 1 of 16 */
    assert_near(&a, 30, 30, 1, 0, 0);
    assert_near(&b, 30, 30, 1, 0, 0);
    int diff = 0, line_px = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            diff += memcmp(px(&a, x, y), px(&b, x, y), 3) != 0;
            if (y >= 5) /* away from the polyline: composed = traced */
                assert_memory_equal(px(&b, x, y), px(&c, x, y), 3);
            else
                line_px += memcmp(px(&b, x, y), px(&c, x, y), 3) != 0;
        }
    assert_int_equal(diff, 4 * 38 + 4); /* exactly the edge pixels: 4 sides + 4 corners */
    assert_true(line_px >= 40);        /* the annotation is there */
    free(a.rgb);
    free(b.rgb);
    free(c.rgb);
}

/* Cut-off: a mirror of weight ks = 0.5 spawns reflection rays below cut-off 0.5 only. */
static void test_cutoff(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_cut.png", GHLHSR_RAYTRACE);
    assert_int_equal(esc_cutoff(1, -0.1), 182);
    assert_int_equal(esc_cutoff(1, 1.0), 182);
    assert_int_equal(esc_cutoff(1, NAN), 182);
    Gint d[1] = { 1 };
    Gescape_in_data nofl = { { 1, d, 0, NULL, 0, NULL } };
    EXPECT(gescape(GESC_RT_CUTOFF, &nofl, NULL, NULL), 182, GFN_ESC);
    n_captured = 0;
    Garea_props sp = { 0, 1, 0.5, { 1, 1, 1 }, 10, 0, 1 };
    gset_area_props(&sp);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    square(0, 1, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    rt_stat_rec s;
    get_stats(1, &s);
    assert_int_equal(s.i[ST_REFL], 4096);
    assert_int_equal(esc_cutoff(1, 0.6), 0);
    gclear_ws(1, GFLAG_ALWAYS);
    square(0, 1, 0.5);
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, &s);
    assert_int_equal(s.i[ST_REFL], 0);
    assert_int_equal(s.i[ST_HIT], 4096);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
}

/* Progress on stderr: never by default, on with the ESCAPE or GKS3D_RT_PROGRESS=1. */
static int progress_lines(int by_escape, const char *env)
{
    char name[] = "t_rt_progXXXXXX";
    int fd = mkstemp(name);
    assert_true(fd >= 0);
    fflush(stderr);
    int saved = dup(2);
    dup2(fd, 2);
    if (env)
        setenv("GKS3D_RT_PROGRESS", env, 1);
    else
        unsetenv("GKS3D_RT_PROGRESS");
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_prog.png", GHLHSR_RAYTRACE);
    if (by_escape)
        assert_int_equal(esc1(GESC_RT_PROGRESS, 1, 1), 0);
    assert_int_equal(esc1(GESC_RT_PROGRESS, 1, 2), 182);
    n_captured = 0;
    square(0.1, 0.9, 0.5);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    unsetenv("GKS3D_RT_PROGRESS");
    char buf[4096] = { 0 };
    ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    close(fd);
    unlink(name);
    assert_true(n >= 0);
    no_errors();
    return strstr(buf, "rt: 16 tiles done in ") != NULL && strstr(buf, " Mrays/s\n") != NULL;
}

static void test_progress(void **u)
{
    (void)u;
    assert_false(progress_lines(0, NULL));
    assert_false(progress_lines(0, "0"));
    assert_true(progress_lines(1, NULL));
    assert_true(progress_lines(0, "1"));
}


/* ---- the recording and the tracer path with constructed primitives --------------------- */

static const Grgb fake_colr[2] = { { 1, 1, 1 }, { 0, 0, 0 } };

/* A workstation state list with identity views (NDC3 = VRC3 = NPC3), unit window, clipping
 * on, colour 0 white, no lights. */
static void fake_ws(gks_ws *ws)
{
    memset(ws, 0, sizeof *ws);
    ws->cur_win = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    ws->colr = (Grgb *)fake_colr;
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++) {
        Gview_rep3 *r = &ws->views[v];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                r->ori_matrix[i][j] = r->map_matrix[i][j] = i == j;
        r->clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
        r->xy_clip = r->back_clip = r->front_clip = GIND_CLIP;
    }
}

static gks_prim fake_prim(gks_prim_kind kind, Grgb colour)
{
    gks_prim p;
    memset(&p, 0, sizeof p);
    p.kind = kind;
    p.colour = colour;
    p.refl_eq[0] = p.refl_eq[1] = GREFL_NONE;
    p.area_props[0] = p.area_props[1] = (Garea_props){ 1, 1, 0, { 1, 1, 1 }, 1, 0, 1 };
    return p;
}

static const double wsm64[4][4] = { { 64, 0, 0, 0 }, { 0, 64, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };

static gks_raster_fb *white_fb(void)
{
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    assert_non_null(fb);
    const float w[3] = { 1, 1, 1 };
    gks_raster_fb_clear(fb, w);
    return fb;
}

/* fb pixel (x, y), y from the bottom */
static const float *fbpx(const gks_raster_fb *fb, int x, int y)
{
    return fb->rgb + 3 * ((size_t)y * (size_t)fb->w + (size_t)x);
}

static void assert_fb(const gks_raster_fb *fb, int x, int y, double r, double g, double b)
{
    const float *p = fbpx(fb, x, y);
    if (fabs(p[0] - r) > 1e-6 || fabs(p[1] - g) > 1e-6 || fabs(p[2] - b) > 1e-6)
        fail_msg("fb (%d,%d) = %g %g %g, want %g %g %g", x, y, p[0], p[1], p[2], r, g, b);
}

static int is_rgb(const float *p, double r, double g, double b)
{
    return fabs(p[0] - r) < 1e-6 && fabs(p[1] - g) < 1e-6 && fabs(p[2] - b) < 1e-6;
}

/* FILL AREA SET with a hole (even-odd), a degenerate 2-point loop and an empty loop, both
 * left out. Outer [0.1,0.9]^2 -> pixels 6..57 (centres 6.5..57.5 in [6.4,57.6]), hole
 * [0.4,0.6]^2 -> pixels 26..37. */
static void test_fill_area_set_hole(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    ws_rt *r = rt_new_plain();
    assert_non_null(r);
    Gpoint3 pts[10] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.9, 0.9, 0.5 }, { 0.1, 0.9, 0.5 },
                        { 0.4, 0.4, 0.5 }, { 0.6, 0.4, 0.5 }, { 0.6, 0.6, 0.5 }, { 0.4, 0.6, 0.5 },
                        { 0.2, 0.2, 0.5 }, { 0.3, 0.3, 0.5 } };
    int counts[4] = { 4, 4, 0, 2 };
    gks_prim p = fake_prim(GKS_PRIM_FILL_AREA, (Grgb){ 1, 0, 0 });
    p.n_loops = 4;
    p.loop_counts = counts;
    p.n_points = 10;
    p.pts = pts;
    assert_int_equal(ws_rt_record(r, &ws, &p), 0);
    assert_int_equal(ws_rt_count(r), 1);
    counts[0] = 5; /* inconsistent: counts sum to 11 points: ignored */
    assert_int_equal(ws_rt_record(r, &ws, &p), 0);
    assert_int_equal(ws_rt_count(r), 1);
    gks_raster_fb *fb = white_fb();
    assert_int_equal(ws_rt_render(r, &ws, wsm64, fb), 0);
    int red = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            const float *q = fbpx(fb, x, y);
            int in_outer = x >= 6 && x <= 57 && y >= 6 && y <= 57;
            int in_hole = x >= 26 && x <= 37 && y >= 26 && y <= 37;
            int want_red = in_outer && !in_hole;
            if (is_rgb(q, 1, 0, 0) != want_red || (!want_red && !is_rgb(q, 1, 1, 1)))
                fail_msg("pixel (%d,%d) = %g %g %g", x, y, q[0], q[1], q[2]);
            red += want_red;
        }
    assert_int_equal(red, 52 * 52 - 12 * 12);
    Gint ints[1] = { 0 }, st[8]; /* GESC_RT_STATS: eye rays, eye hits, ..., primitives */
    Gfloat secs[2];
    Gescape_in_data in = { .num_ints = 1, .ints = ints };
    Gescape_out_data out = { .num_ints = 8, .ints = st, .num_floats = 2, .floats = secs };
    assert_int_equal(ws_rt_escape(r, GESC_RT_STATS, &in, &out), 0);
    assert_int_equal(st[7], 1);
    assert_int_equal(st[0], 4096);
    assert_int_equal(st[1], 52 * 52 - 12 * 12);
    gks_raster_fb_free(fb);
    ws_rt_free(r);
}

/* One display list per frame for both renderers (ws_render): in ray-tracing mode with two
 * recording threads, a red FILL AREA goes to the tracer through the list while a green
 * POLYLINE on either side of it with HLHSR identifier 1 is retained there by the classic
 * renderer. After the frame is traced, ws_rt_reset alone (as the X11 and cairo drivers call
 * it) keeps the classic records: the composed picture has the traced square and both lines
 * over it; ws_render_reset then forgets them. */
static void test_shared_list(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    ws.cur_vp = (Glimit3){ 0, 64, 0, 64, 0, 1 };
    ws.hlhsr_mode = GHLHSR_RAYTRACE;
    ws_render *R = ws_render_new();
    assert_non_null(R);
    Gint ints[2] = { 0, 1 };
    Gfloat zero[1] = { 0.0 };
    Gescape_in_data in = { .num_ints = 2, .ints = ints, .num_floats = 1, .floats = zero };
    assert_int_equal(ws_rt_escape(R->rt, GESC_RT_SAMPLES, &in, NULL), 0);
    assert_int_equal(ws_rt_escape(R->rt, GESC_RT_CUTOFF, &in, NULL), 0);
    ints[1] = 2;
    assert_int_equal(ws_rt_escape(R->rt, GESC_RT_THREADS, &in, NULL), 0);
    gks_raster_fb *fb = white_fb();
    Gpoint3 sq[4] = { { 0.25, 0.25, 0.5 }, { 0.75, 0.25, 0.5 }, { 0.75, 0.75, 0.5 },
                      { 0.25, 0.75, 0.5 } };
    Gpoint3 l1[2] = { { 0.1, 0.4, 0.5 }, { 0.9, 0.4, 0.5 } };
    Gpoint3 l2[2] = { { 0.1, 0.6, 0.5 }, { 0.9, 0.6, 0.5 } };
    int n4 = 4, n2 = 2;
    gks_prim area = fake_prim(GKS_PRIM_FILL_AREA, (Grgb){ 1, 0, 0 });
    area.n_loops = 1, area.loop_counts = &n4, area.n_points = 4, area.pts = sq;
    gks_prim line = fake_prim(GKS_PRIM_POLYLINE, (Grgb){ 0, 1, 0 });
    line.n_loops = 1, line.loop_counts = &n2, line.n_points = 2, line.pts = l1;
    line.attrs.linetype = 1, line.attrs.linewidth = 1, line.attrs.hlhsr_id = 1;
    assert_int_equal(ws_render_prim(R, &ws, fb, &line), 0);
    assert_int_equal(ws_render_prim(R, &ws, fb, &area), 0);
    line.pts = l2;
    assert_int_equal(ws_render_prim(R, &ws, fb, &line), 0);
    assert_int_equal(ws_classic_retained(R->classic), 2);
    assert_int_equal(ws_rt_count(R->rt), 1);
    assert_int_equal(ws_dlist_count(R->dl, WS_DL_CLASSIC | WS_DL_TRACER), 3);
    assert_int_equal(ws_rt_render(R->rt, &ws, wsm64, fb), 0);
    ws_rt_reset(R->rt); /* traced into fb: the tracer forgets its areas, the list stays */
    assert_int_equal(ws_rt_count(R->rt), 0);
    assert_int_equal(ws_classic_retained(R->classic), 2);
    gks_raster_fb *pic = NULL;
    assert_int_equal(ws_classic_compose(R->classic, &ws, fb, &pic), 0);
    assert_non_null(pic);
    assert_fb(pic, 32, 36, 1, 0, 0);  /* the traced square between the lines */
    assert_fb(pic, 4, 36, 1, 1, 1);   /* outside it */
    int green[2] = { 0, 0 };
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++)
            if (is_rgb(fbpx(pic, x, y), 0, 1, 0))
                green[y >= 32]++;
    if (green[0] < 40 || green[1] < 40)
        fail_msg("green line pixels below / above the middle: %d / %d", green[0], green[1]);
    ws_render_reset(R);
    assert_int_equal(ws_classic_retained(R->classic), 0);
    assert_null(ws_dlist_first(R->dl));
    gks_raster_fb_free(fb);
    ws_render_free(R);
}

/* CELL ARRAY 2x2 over [0.25,0.75]^2: cell (i,j) colour at pixel centres of each quarter;
 * P (0.25,0.25), R (0.75,0.25) (first row), Q (0.75,0.75). */
static const Grgb cells4[4] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 } };

static gks_prim cell_prim(double x0, double x1, int nx, int ny, const Grgb *cells)
{
    gks_prim p = fake_prim(GKS_PRIM_CELL_ARRAY, (Grgb){ 0, 0, 0 });
    p.cell_p = (Gpoint3){ x0, x0, 0.5 };
    p.cell_r = (Gpoint3){ x1, x0, 0.5 };
    p.cell_q = (Gpoint3){ x1, x1, 0.5 };
    p.cell_nx = nx;
    p.cell_ny = ny;
    p.cells = cells;
    return p;
}

static void test_cell_array(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    ws_rt *r = rt_new_plain();
    gks_prim p = cell_prim(0.25, 0.75, 2, 2, cells4);
    p.clip = 1; /* the clip box contains the whole array: one record */
    memcpy(p.clip_box, (const double[6]){ 0, 1, 0, 1, 0, 1 }, sizeof p.clip_box);
    assert_int_equal(ws_rt_record(r, &ws, &p), 0);
    assert_int_equal(ws_rt_count(r), 1);
    gks_prim bad = p;
    bad.cell_nx = 0;
    assert_int_equal(ws_rt_record(r, &ws, &bad), 0);
    bad = p;
    bad.cell_q.x = NAN;
    assert_int_equal(ws_rt_record(r, &ws, &bad), 0);
    assert_int_equal(ws_rt_count(r), 1);
    gks_raster_fb *fb = white_fb();
    assert_int_equal(ws_rt_render(r, &ws, wsm64, fb), 0);
    assert_fb(fb, 20, 20, 1, 0, 0);
    assert_fb(fb, 43, 20, 0, 1, 0);
    assert_fb(fb, 20, 43, 0, 0, 1);
    assert_fb(fb, 43, 43, 1, 1, 0);
    assert_fb(fb, 10, 10, 1, 1, 1);
    assert_fb(fb, 48, 48, 1, 1, 1); /* 0.75*64 = 48: pixel 48 outside */
    assert_fb(fb, 47, 47, 1, 1, 0);
    gks_raster_fb_free(fb);
    ws_rt_free(r);
}

/* A CELL ARRAY partly outside its clip box x in [0.3,0.6]: 4x4 cells over [0.2,0.8]^2
 * (boundaries 0.2, 0.35, 0.5, 0.65, 0.8): per row cell 1 inside (a one-row cell array),
 * cells 0 and 2 crossing (clipped polygons), cell 3 outside: 3 records per row. Inside the
 * box the picture equals the unclipped one, outside it is background. */
static void test_cell_array_clipped(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    Grgb cells[16];
    for (int k = 0; k < 16; k++)
        cells[k] = (Grgb){ (k % 4) / 3.0, (k / 4) / 3.0, 0.5 };
    ws_rt *full = rt_new_plain(), *clip = rt_new_plain();
    gks_prim p = cell_prim(0.2, 0.8, 4, 4, cells);
    assert_int_equal(ws_rt_record(full, &ws, &p), 0);
    p.clip = 1;
    memcpy(p.clip_box, (const double[6]){ 0.3, 0.6, 0, 1, 0, 1 }, sizeof p.clip_box);
    assert_int_equal(ws_rt_record(clip, &ws, &p), 0);
    assert_int_equal(ws_rt_count(clip), 12);
    gks_raster_fb *a = white_fb(), *b = white_fb();
    assert_int_equal(ws_rt_render(full, &ws, wsm64, a), 0);
    assert_int_equal(ws_rt_render(clip, &ws, wsm64, b), 0);
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            double cx = (x + 0.5) / 64;
            const float *pa = fbpx(a, x, y), *pb = fbpx(b, x, y);
            if (cx >= 0.3 && cx <= 0.6) {
                if (memcmp(pa, pb, 3 * sizeof(float)) != 0)
                    fail_msg("(%d,%d): clipped %g %g %g, unclipped %g %g %g", x, y, pb[0],
                             pb[1], pb[2], pa[0], pa[1], pa[2]);
            } else if (!is_rgb(pb, 1, 1, 1)) {
                fail_msg("(%d,%d) outside the clip box: %g %g %g", x, y, pb[0], pb[1], pb[2]);
            }
        }
    assert_fb(b, 20, 20, 0, 0, 0.5);            /* cell (0,0), clipped polygon */
    assert_fb(b, 25, 20, 1 / 3.0f, 0, 0.5);     /* cell (1,0), inside */
    assert_fb(b, 37, 40, 2 / 3.0f, 2 / 3.0f, 0.5); /* cell (2,2), clipped polygon */
    gks_raster_fb_free(a);
    gks_raster_fb_free(b);
    ws_rt_free(full);
    ws_rt_free(clip);
}

/* Storage failure while recording (300) leaves the recording unchanged: a cell count beyond
 * what the recording can index (2^32 cells), after a recorded primitive. */
static void test_record_limits(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    ws_rt *r = rt_new_plain();
    Grgb one = { 1, 0, 0 };
    gks_prim ok = cell_prim(0.2, 0.8, 1, 1, &one);
    assert_int_equal(ws_rt_record(r, &ws, &ok), 0);
    gks_prim p = cell_prim(0.2, 0.8, 1 << 20, 1 << 12, &one); /* 2^32 cells: refused */
    assert_int_equal(ws_rt_record(r, &ws, &p), 300);
    p.clip = 1; /* the clipped path refuses it too, before any partial recording */
    memcpy(p.clip_box, (const double[6]){ 0.3, 0.6, 0, 1, 0, 1 }, sizeof p.clip_box);
    assert_int_equal(ws_rt_record(r, &ws, &p), 300);
    assert_int_equal(ws_rt_count(r), 1);
    gks_raster_fb *fb = white_fb();
    assert_int_equal(ws_rt_render(r, &ws, wsm64, fb), 0);
    assert_fb(fb, 32, 32, 1, 0, 0);
    assert_fb(fb, 5, 5, 1, 1, 1);
    gks_raster_fb_free(fb);
    ws_rt_free(r);
}

/* FILL AREA SET 3 through the GKS entry point: the hole shows what is behind it. */
static void test_fill_area_set_e2e(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_fas.png", GHLHSR_RAYTRACE);
    gset_fill_colr_ind(4); /* blue floor behind */
    square(0.05, 0.95, 0.2);
    Gpoint3 outer[4] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.9, 0.9, 0.5 }, { 0.1, 0.9, 0.5 } };
    Gpoint3 hole[4] = { { 0.4, 0.4, 0.5 }, { 0.4, 0.6, 0.5 }, { 0.6, 0.6, 0.5 }, { 0.6, 0.4, 0.5 } };
    Gpoint_list3 loops[2] = { { 4, outer }, { 4, hole } };
    Gpoint_list_list3 fas = { 2, loops };
    gset_fill_colr_ind(2);
    gfill_area_set3(&fas);
    gupd_ws(1, GFLAG_PERFORM);
    rt_stat_rec s;
    get_stats(1, &s);
    assert_int_equal(s.i[ST_PRIMS], 2);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_fas.png", &img));
    assert_near(&img, 32, 32, 0, 0, 1); /* through the hole: the floor */
    assert_near(&img, 26, 37, 0, 0, 1);
    assert_near(&img, 25, 32, 1, 0, 0); /* ring */
    assert_near(&img, 10, 10, 1, 0, 0);
    assert_near(&img, 4, 4, 0, 0, 1);   /* floor outside the ring */
    assert_near(&img, 1, 1, 1, 1, 1);
    free(img.rgb);
}

/* Every allocation of recording and rendering failing in turn: 300, the recording as before
 * the call, no leak (ASan build), no crash. */
static void test_alloc_failures(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    Grgb cells[16];
    for (int k = 0; k < 16; k++)
        cells[k] = (Grgb){ k / 15.0, 0.5, 0.5 };
    gks_prim clipped = cell_prim(0.2, 0.8, 4, 4, cells);
    clipped.clip = 1;
    memcpy(clipped.clip_box, (const double[6]){ 0.3, 0.6, 0, 1, 0, 1 }, sizeof clipped.clip_box);
    Grgb one = { 1, 0, 0 };
    gks_prim ok = cell_prim(0.1, 0.9, 1, 1, &one);
    /* allocations of one successful record + render (with one coverage thread per CPU) */
    ws_rt *r0 = rt_new_plain();
    gks_raster_fb *fb0 = white_fb();
    long c0 = gks_alloc_count();
    assert_int_equal(ws_rt_record(r0, &ws, &clipped), 0);
    assert_int_equal(ws_rt_render(r0, &ws, wsm64, fb0), 0);
    long used = gks_alloc_count() - c0;
    gks_raster_fb_free(fb0);
    ws_rt_free(r0);
    assert_true(used > 3);
    int failures = 0;
    for (long n = 1; n <= used + 1; n++) {
        ws_rt *r = rt_new_plain();
        assert_non_null(r);
        assert_int_equal(ws_rt_record(r, &ws, &ok), 0);
        gks_alloc_fail_after(n);
        int e = ws_rt_record(r, &ws, &clipped);
        gks_alloc_fail_after(0);
        assert_true(e == 0 || e == 300);
        assert_int_equal(ws_rt_count(r), e ? 1 : 13);
        failures += e != 0;
        gks_raster_fb *fb = white_fb();
        gks_alloc_fail_after(n);
        e = ws_rt_render(r, &ws, wsm64, fb);
        gks_alloc_fail_after(0);
        assert_true(e == 0 || e == 300);
        failures += e != 0;
        gks_raster_fb_free(fb);
        ws_rt_free(r);
    }
    assert_true(failures > 3);
}

/* Every ray-tracing ESCAPE: bad records report 182 and leave all options as they were,
 * good ones set exactly their option. */
static void test_escape_records(void **u)
{
    (void)u;
    ws_rt *r = ws_rt_new(NULL);
    rt_render_options def, o;
    rt_render_options_default(&def);
    ws_rt_options(r, &o);
    assert_memory_equal(&o, &def, sizeof o);
    /* the workstation's defaults are the library's: corner rays, cut-off 0.01 (on the
     * speed/error Pareto front, README) */
    assert_int_equal(o.corner_rays, 1);
    assert_true(o.cutoff == 0.01);
    assert_int_equal(o.samples, 1);
    static const struct { int id, n, v[2]; } bad[] = {
        { GESC_RT_CLIP_SECONDARY, 2, { 2 } }, { GESC_RT_CLIP_SECONDARY, 1, { 0 } },
        { GESC_RT_SAMPLES, 2, { 2 } },        { GESC_RT_SAMPLES, 3, { 9, 3 } },
        { GESC_RT_SAMPLES, 2, { 1024 } },     { GESC_RT_MAX_DEPTH, 2, { 0 } },
        { GESC_RT_MAX_DEPTH, 2, { 99 } },     { GESC_RT_THREADS, 2, { -2 } },
        { GESC_RT_THREADS, 2, { 100000 } },   { GESC_RT_PROGRESS, 2, { -1 } },
        { GESC_RT_SPD, 2, { 7 } },            { GESC_RT_SPD, 1, { 0 } },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        Gint d[3] = { 1, bad[k].v[0], bad[k].v[1] };
        Gescape_in_data in = { { bad[k].n, d, 0, NULL, 0, NULL } };
        assert_int_equal(ws_rt_escape(r, bad[k].id, &in, NULL), 182);
    }
    Gint d[3] = { 1, 1, 0 };
    Gescape_in_data in = { { 2, d, 0, NULL, 0, NULL } };
    Gfloat f[1] = { 0.5 };
    Gescape_in_data fin = { { 1, d, 1, f, 0, NULL } };
    assert_int_equal(ws_rt_escape(r, GESC_RT_CUTOFF, &in, NULL), 182); /* no float */
    f[0] = 1.5;
    assert_int_equal(ws_rt_escape(r, GESC_RT_CUTOFF, &fin, NULL), 182);
    assert_int_equal(ws_rt_escape(r, GESC_RT_SAMPLES, NULL, NULL), 182);
    assert_int_equal(ws_rt_escape(r, GESC_SET_FILE_NAME, &in, NULL), 180);
    assert_int_equal(ws_rt_escape(r, GESC_RT_SPD - 1, &in, NULL), 180);
    Gint oi[8];
    Gfloat of[2];
    Gescape_out_data out = { { 8, oi, 2, of } }, small = { { 7, oi, 2, of } };
    assert_int_equal(ws_rt_escape(r, GESC_RT_STATS, &in, &small), 182); /* room < 8 ints */
    small.num_ints = 8, small.num_floats = 1;
    assert_int_equal(ws_rt_escape(r, GESC_RT_STATS, &in, &small), 182); /* < 2 reals */
    assert_int_equal(ws_rt_escape(r, GESC_RT_STATS, &in, &out), 0); /* zeros, untouched opts */
    ws_rt_options(r, &o);
    assert_memory_equal(&o, &def, sizeof o);
    /* good records: one option each */
    f[0] = 0.25;
    assert_int_equal(ws_rt_escape(r, GESC_RT_CUTOFF, &fin, NULL), 0);
    d[1] = 9, d[2] = 1, in.num_ints = 3;
    assert_int_equal(ws_rt_escape(r, GESC_RT_SAMPLES, &in, NULL), 0);
    ws_rt_options(r, &o);
    assert_int_equal(o.corner_rays, 0); /* samples per pixel replace the corner rays */
    in.num_ints = 2;
    d[1] = 64;
    assert_int_equal(ws_rt_escape(r, GESC_RT_MAX_DEPTH, &in, NULL), 0);
    d[1] = 3;
    assert_int_equal(ws_rt_escape(r, GESC_RT_THREADS, &in, NULL), 0);
    d[1] = 1;
    assert_int_equal(ws_rt_escape(r, GESC_RT_PROGRESS, &in, NULL), 0);
    assert_int_equal(ws_rt_escape(r, GESC_RT_SPD, &in, NULL), 0);
    assert_int_equal(ws_rt_escape(r, GESC_RT_CLIP_SECONDARY, &in, NULL), 0);
    ws_rt_options(r, &o);
    def.cutoff = 0.25;
    def.samples = 9;
    def.jitter = 1;
    def.max_depth = 64;
    def.threads = 3;
    def.progress = 1;
    def.corner_rays = 1;
    def.clip_secondary = 1;
    assert_memory_equal(&o, &def, sizeof o);
    ws_rt_reset(r); /* a new frame keeps the options */
    ws_rt_options(r, &o);
    assert_memory_equal(&o, &def, sizeof o);
    ws_rt_free(r);
}

/* ---- several views in one frame ------------------------------------------------------- */

static void set_view(int ws, int vi, double xmin, double xmax, double sx, double tx)
{
    Gview_rep3 v;
    memset(&v, 0, sizeof v);
    for (int i = 0; i < 4; i++)
        v.ori_matrix[i][i] = v.map_matrix[i][i] = 1;
    v.map_matrix[0][0] = sx; /* NPC x = sx * VRC x + tx */
    v.map_matrix[0][3] = tx;
    v.clip_limit = (Glimit3){ xmin, xmax, 0, 1, 0, 1 };
    v.xy_clip = v.back_clip = v.front_clip = GIND_CLIP;
    gset_view_rep3(ws, vi, &v);
}

/* View 2 (display volume x in [0.25,1], mapping x -> 0.5x + 0.5) is traced after view 1
 * (x in [0,0.75], identity) although its primitives come first: in the overlap view 2's
 * square covers view 1's, elsewhere in the overlap view 1's picture stays. */
static void test_multiple_views(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_views.png", GHLHSR_RAYTRACE);
    set_view(1, 1, 0, 0.75, 1, 0);
    set_view(1, 2, 0.25, 1, 0.5, 0.5);
    gset_view_ind(2);
    gset_fill_colr_ind(4); /* blue: VRC x [0.2,0.4] -> NPC x [0.6,0.7] */
    Gpoint3 b[4] = { { 0.2, 0.3, 0.5 }, { 0.4, 0.3, 0.5 }, { 0.4, 0.7, 0.5 }, { 0.2, 0.7, 0.5 } };
    Gpoint_list3 l = { 4, b };
    gfill_area3(&l);
    gset_view_ind(1);
    gset_fill_colr_ind(2); /* red: the whole window, clipped by view 1 to x < 0.75 */
    square(0, 1, 0.3);
    gupd_ws(1, GFLAG_PERFORM);
    rt_stat_rec s;
    get_stats(1, &s);
    /* view 1: 48 x 64 pixels all hit; view 2: 48 x 64 pixels, [38.4,44.8] x [19.2,44.8]
     * hit: 7 x 26 pixel centres */
    assert_int_equal(s.i[ST_EYE], 2 * 48 * 64);
    assert_int_equal(s.i[ST_HIT], 48 * 64 + 7 * 26);
    assert_int_equal(s.i[ST_PRIMS], 2);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_views.png", &img));
    assert_near(&img, 10, 32, 1, 0, 0);  /* view 1 only */
    assert_near(&img, 30, 32, 1, 0, 0);  /* overlap, view 2 misses: view 1 stays */
    assert_near(&img, 41, 32, 0, 0, 1);  /* overlap, view 2's square over view 1 */
    assert_near(&img, 41, 10, 1, 0, 0);
    assert_near(&img, 55, 32, 1, 1, 1);  /* view 2 only, nothing hit: background */
    free(img.rgb);
}

/* The paper's Fig. 4 / 5: an occluder outside the display volume (view clip x <= 0.5)
 * casts its shadow into the picture when secondary rays are not clipped, not when they are;
 * with clipped secondary rays it is not even part of the traced scene. */
static void fig45_frame(int clip, rt_stat_rec *s)
{
    assert_int_equal(esc1(GESC_RT_CLIP_SECONDARY, 1, clip), 0);
    if (clip)
        gclear_ws(1, GFLAG_ALWAYS);    /* second frame */
    square(0, 1, 0.2);                 /* floor */
    Gpoint3 o[4] = { { 0.6, 0.3, 0.6 }, { 0.9, 0.3, 0.6 }, { 0.9, 0.7, 0.6 }, { 0.6, 0.7, 0.6 } };
    Gpoint_list3 l = { 4, o };
    gfill_area3(&l);                   /* occluder, clipped away by the view */
    gupd_ws(1, GFLAG_PERFORM);
    get_stats(1, s);
}

static void test_clip_secondary_fig45(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_fig4.png", GHLHSR_RAYTRACE);
    set_view(1, 1, 0, 0.5, 1, 0);
    gset_view_ind(1);
    /* light travels along (-1,0,-1): the shadow of x [0.6,0.9] at z 0.6 on z 0.2 is
     * x [0.2,0.5] */
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { -1, 0, -1 }, { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 1, 1, 1 };
    lit_setup(&c);
    rt_stat_rec s;
    fig45_frame(0, &s);
    assert_int_equal(s.i[ST_PRIMS], 2);
    fig45_frame(1, &s);                /* frame 2: t_rt_fig4-002.png */
    assert_int_equal(s.i[ST_PRIMS], 1);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image a, b;
    assert_true(read_png("t_rt_fig4.png", &a));
    assert_true(read_png("t_rt_fig4-002.png", &b));
    double lit = sqrt(0.5);
    assert_near(&a, 22, 32, 0, 0, 0);       /* Fig. 4: the clipped occluder's shadow */
    assert_near(&b, 22, 32, lit, lit, lit); /* Fig. 5: no shadow */
    assert_near(&a, 8, 32, lit, lit, lit);  /* outside the shadow: lit in both */
    assert_near(&b, 8, 32, lit, lit, lit);
    assert_near(&a, 48, 32, 1, 1, 1);       /* outside the view's display volume */
    free(a.rgb);
    free(b.rgb);
}

/* ---- flat shading agrees with the tracer's local shading -------------------------------- */

static void lit_fake(gks_ws *ws, gks_prim *p)
{
    ws->lights[0] = (Glight_src_rep){ GLIGHT_AMBIENT, { 0.2, 0.25, 0.3 }, { 0, 0, 0 },
                                      { 0, 0, 0 }, { 1, 0 }, 0, 1 };
    ws->lights[1] = (Glight_src_rep){ GLIGHT_DIRECTIONAL, { 0.5, 0.4, 0.3 }, { 0, 0, 0 },
                                      { 0.2, -0.3, -0.9 }, { 1, 0 }, 0, 1 };
    ws->lights[2] = (Glight_src_rep){ GLIGHT_SPOT, { 0.3, 0.3, 0.3 }, { 0.5, 0.5, 2 },
                                      { 0, 0, -1 }, { 0.5, 0.5 }, 3, 0.8 };
    ws->lights[3] = (Glight_src_rep){ GLIGHT_SPOT, { 1, 1, 1 }, { 0.5, 0.5, 2 },
                                      { 0, 0, -1 }, { 1, 0 }, 1, 0 }; /* spread 0: rejected */
    ws->light_defined[0] = ws->light_defined[1] = ws->light_defined[2] = 1;
    ws->light_defined[3] = 1;
    p->light_mask = 0xF;
    p->refl_eq[0] = GREFL_AMB_DIFF_SPEC;
    p->refl_eq[1] = GREFL_AMB_DIFF;
    p->area_props[0] = (Garea_props){ 0.5, 0.7, 0.3, { 1, 0.9, 0.8 }, 5, 0, 1 };
    p->area_props[1] = (Garea_props){ 0.3, 0.4, 0, { 1, 1, 1 }, 1, 0, 1 };
}

/* max |preview - traced| over the pixels whose 8-bit values both are fully covered */
static double shade_vs_trace(gks_ws *ws, const gks_prim *p, int px, int py, Grgb *preview)
{
    ws_shade sh;
    assert_int_equal(ws_shade_area(ws, p, &sh), 0);
    *preview = ws_shade_apply(&sh, &p->colour);
    ws_rt *r = rt_new_plain();
    Gint d[2] = { 1, 1 }; /* depth 1: local shading only (no mirrored background) */
    Gescape_in_data in = { { 2, d, 0, NULL, 0, NULL } };
    assert_int_equal(ws_rt_escape(r, GESC_RT_MAX_DEPTH, &in, NULL), 0);
    assert_int_equal(ws_rt_record(r, ws, p), 0);
    gks_raster_fb *fb = white_fb();
    assert_int_equal(ws_rt_render(r, ws, wsm64, fb), 0);
    const float *t = fbpx(fb, px, py);
    double e = fmax(fabs(t[0] - preview->red),
                    fmax(fabs(t[1] - preview->green), fabs(t[2] - preview->blue)));
    gks_raster_fb_free(fb);
    ws_rt_free(r);
    return e;
}

static void test_flat_shading_matches_tracer(void **u)
{
    (void)u;
    gks_ws ws;
    fake_ws(&ws);
    Gpoint3 sq[4] = { { 0.2, 0.2, 0.5 }, { 0.8, 0.2, 0.5 }, { 0.8, 0.8, 0.5 }, { 0.2, 0.8, 0.5 } };
    int four = 4;
    gks_prim p = fake_prim(GKS_PRIM_FILL_AREA, (Grgb){ 0.8, 0.6, 0.4 });
    p.n_loops = 1;
    p.loop_counts = &four;
    p.n_points = 4;
    p.pts = sq;
    ws_shade sh;
    /* unlit: identity, the flat colour */
    assert_int_equal(ws_shade_area(&ws, &p, &sh), 0);
    Grgb c = ws_shade_apply(&sh, &p.colour);
    assert_true(c.red == 0.8 && c.green == 0.6 && c.blue == 0.4);
    lit_fake(&ws, &p);
    /* parallel projection: the same colour in every covered pixel (directional + ambient),
     * spot at the centre only (its cone and distance vary over the square) */
    Grgb pre;
    double e = shade_vs_trace(&ws, &p, 32, 32, &pre);
    assert_true(e <= 1.0 / 255);
    assert_true(pre.red > 0.2 && pre.red < 1); /* not trivially saturated */
    /* expected by hand without the spot: */
    ws.light_defined[2] = 0;
    assert_int_equal(ws_shade_area(&ws, &p, &sh), 0);
    double L[3] = { -0.2, 0.3, 0.9 }, n = sqrt(0.04 + 0.09 + 0.81);
    double NL = L[2] / n, RE = 2 * NL - NL; /* R.E with N = E = +z: 2 NL Nz - Lz */
    double spec = 0.3 * pow(RE, 5);
    assert_true(fabs(sh.mul[0] - (0.5 * 0.2 + 0.5 * 0.7 * NL)) < 1e-12);
    assert_true(fabs(sh.add[1] - 0.4 * spec * 0.9) < 1e-12);
    assert_true(shade_vs_trace(&ws, &p, 15, 50, &pre) <= 1.0 / 255);
    ws.light_defined[2] = 1;
    /* seen from the back (clockwise square): back properties, normal turned to the eye */
    Gpoint3 cw[4] = { sq[0], sq[3], sq[2], sq[1] };
    p.pts = cw;
    assert_int_equal(ws_shade_area(&ws, &p, &sh), 0);
    assert_int_equal(sh.side, 1);
    assert_true(shade_vs_trace(&ws, &p, 32, 32, &pre) <= 1.0 / 255);
    p.pts = sq;
    /* perspective view (PRP on the axis through the centroid): at the centroid's pixels */
    gopen_gks(NULL, 0);
    Gview_map3 map = { { 0, 1, 0, 1 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PERSPECT, { 0.5, 0.5, 3 },
                       1, 0, 1 };
    Gint err;
    geval_view_map_matrix3(&map, &err, ws.views[0].map_matrix);
    gclose_gks();
    assert_int_equal(err, 0);
    assert_true(shade_vs_trace(&ws, &p, 31, 31, &pre) <= 1.0 / 255);
    assert_true(shade_vs_trace(&ws, &p, 32, 32, &pre) <= 1.0 / 255);
    /* cell array: one evaluation, per-cell diffuse colours */
    gks_prim cp = cell_prim(0.25, 0.75, 2, 2, cells4);
    lit_fake(&ws, &cp);
    memcpy(ws.views[0].map_matrix, ws.views[1].map_matrix, sizeof ws.views[0].map_matrix);
    assert_int_equal(ws_shade_area(&ws, &cp, &sh), 0);
    assert_int_equal(sh.side, 0);
    cp.colour = cells4[3];
    assert_true(shade_vs_trace(&ws, &cp, 32, 32, &pre) <= 1.0 / 255); /* cell (1,1) at the centroid */
    /* a 300-gon (beyond the fixed vertex buffer) in the square's plane and around its
     * centroid, directional + ambient light: the square's shading */
    ws.light_defined[2] = 0;
    gks_prim circ = p;
    Gpoint3 ring[300];
    for (int k = 0; k < 300; k++)
        ring[k] = (Gpoint3){ 0.5 + 0.3 * cos(2 * M_PI * k / 300), 0.5 + 0.3 * sin(2 * M_PI * k / 300),
                             0.5 };
    int n300 = 300;
    circ.pts = ring;
    circ.n_points = 300;
    circ.loop_counts = &n300;
    ws_shade s300;
    assert_int_equal(ws_shade_area(&ws, &circ, &s300), 0);
    assert_int_equal(ws_shade_area(&ws, &p, &sh), 0);
    for (int q = 0; q < 3; q++)
        assert_true(fabs(s300.mul[q] - sh.mul[q]) < 1e-12 && fabs(s300.add[q] - sh.add[q]) < 1e-12);
    ws.light_defined[2] = 1;
    /* degenerate area: identity, 1 */
    Gpoint3 line[3] = { { 0.1, 0.1, 0.5 }, { 0.5, 0.5, 0.5 }, { 0.9, 0.9, 0.5 } };
    int three = 3;
    p.pts = line;
    p.n_points = 3;
    p.loop_counts = &three;
    assert_int_equal(ws_shade_area(&ws, &p, &sh), 1);
    assert_true(sh.mul[0] == 1 && sh.add[0] == 0);
}

/* ---- Fresnel: exact dielectric vs Schlick on a glass scene (gksrt directly) ---------- */

/* Adds an axis-aligned box [lo,hi] rotated by angle a about the x axis through (0.5,0.5,0.5),
 * faces counter-clockwise seen from outside (front = outside). */
static void glass_box(rt_scene *sc, const double lo[3], const double hi[3], double a, int f, int b)
{
    static const int face[6][4] = { { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, { 0, 4, 5, 1 },
                                    { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 6, 7, 5 } };
    double v[8][3];
    for (int k = 0; k < 8; k++) {
        double p[3] = { k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2] };
        double y = p[1] - 0.5, z = p[2] - 0.5;
        v[k][0] = p[0];
        v[k][1] = 0.5 + cos(a) * y - sin(a) * z;
        v[k][2] = 0.5 + sin(a) * y + cos(a) * z;
    }
    for (int i = 0; i < 6; i++) {
        double xyz[12];
        for (int j = 0; j < 4; j++)
            memcpy(xyz + 3 * j, v[face[i][j]], sizeof v[0]);
        int four = 4;
        assert_true(rt_scene_add_polygon(sc, 1, &four, xyz, f, b) >= 0);
    }
}

/* Renders the glass scene with Fresnel mode fm into rgb (n x n x 3); glass[k] = 1 where
 * pixel k's eye ray hits glass. */
static void glass_render(const double vmap[4][4], int n, int fm, float *rgb, unsigned char *glass)
{
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    s.refl_eq = RT_REFL_NONE;
    float board[64 * 3];
    for (int k = 0; k < 64; k++)
        for (int c = 0; c < 3; c++)
            board[3 * k + c] = ((k % 8) + (k / 8)) % 2 ? 0.9f : (c == 0 ? 0.8f : 0.1f);
    int fs = rt_scene_add_surface(sc, &s);
    assert_true(rt_scene_add_cell_array(sc, (const double[3]){ -0.5, -0.5, 0.05 },
                                        (const double[3]){ 1.5, 1.5, 0.05 },
                                        (const double[3]){ 1.5, -0.5, 0.05 }, 8, 8, board, fs,
                                        fs) >= 0);
    rt_surface g;
    rt_surface_default(&g);
    g.refl_eq = RT_REFL_AMBIENT;
    g.ka = 0.05;
    g.transparency = 0.95;
    g.refr_index = 1.5;
    int gs = rt_scene_add_surface(sc, &g);
    rt_light amb = { .type = RT_LIGHT_AMBIENT, .color = { 1, 1, 1 } };
    assert_true(rt_scene_add_light(sc, &amb) >= 0);
    glass_box(sc, (const double[3]){ 0.05, 0.05, 0.44 }, (const double[3]){ 0.48, 0.95, 0.56 }, 1.0, gs, gs);
    glass_box(sc, (const double[3]){ 0.52, 0.05, 0.44 }, (const double[3]){ 0.95, 0.95, 0.56 }, 1.35, gs, gs);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, vmap, (const double[6]){ 0, 1, 0, 1, 0, 1 }, n, n), RT_OK);
    rt_render_options o;
    rt_render_options_default(&o);
    o.max_depth = 10;
    o.fresnel = fm;
    o.background[0] = o.background[1] = o.background[2] = 0.3;
    assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_OK);
    for (int k = 0; k < n * n; k++) {
        rt_ray ray;
        rt_hit hit;
        assert_int_equal(rt_camera_ray(&cam, k % n + 0.5, k / n + 0.5, &ray), RT_OK);
        assert_int_equal(rt_intersect(sc, 1, &ray, &hit), RT_OK);
        glass[k] = hit.prim > 0; /* primitive 0 is the board */
    }
    rt_scene_free(sc);
}

/* Measured difference of Schlick's approximation against the exact dielectric Fresnel
 * reflectance (docs/RAYTRACING.md): two glass slabs (index 1.5, kt 0.95) tilted 57 and 77
 * degrees over a checkerboard, perspective view, depth 10, 128 x 128 pixels, 8-bit values.
 * The reflectance curves differ by at most 0.036 (at 85 degrees outside, 41.6 degrees inside
 * the glass); pixels must differ, but little. */
static void test_fresnel_schlick_vs_exact(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    Gview_map3 map = { { -0.2, 1.2, -0.2, 1.2 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PERSPECT,
                       { 0.5, 0.5, 2.5 }, 1, -0.2, 1.2 };
    Gint err;
    Gmatrix3 vmap;
    geval_view_map_matrix3(&map, &err, vmap);
    gclose_gks();
    assert_int_equal(err, 0);
    enum { N = 128 };
    float *ex = malloc(sizeof(float) * N * N * 3), *sc = malloc(sizeof(float) * N * N * 3);
    unsigned char *glass = malloc(N * N), *g2 = malloc(N * N);
    assert_true(ex && sc && glass && g2);
    glass_render((const double (*)[4])vmap, N, RT_FRESNEL_EXACT, ex, glass);
    glass_render((const double (*)[4])vmap, N, RT_FRESNEL_SCHLICK, sc, g2);
    int maxd = 0, changed = 0, ng = 0;
    double sum = 0, fmaxd = 0;
    for (int k = 0; k < N * N * 3; k++) {
        if (!glass[k / 3])
            continue;
        ng++;
        int a = (int)lround(fmin(1, fmax(0, ex[k])) * 255);
        int b = (int)lround(fmin(1, fmax(0, sc[k])) * 255);
        int d = abs(a - b);
        maxd = d > maxd ? d : maxd;
        fmaxd = fmax(fmaxd, fabs((double)ex[k] - sc[k]));
        sum += d;
        changed += d != 0;
    }
    assert_true(ng > 3 * 1000); /* the slabs cover a good part of the picture */
    double mean = sum / ng;
    print_message("Fresnel exact vs Schlick on %d glass pixels: 8-bit max %d, mean %.3f, "
                  "values changed %.1f %%, float max %.4f\n",
                  ng / 3, maxd, mean, 100.0 * changed / ng, fmaxd);
    assert_true(maxd > 0);    /* the two modes are really different */
    assert_true(maxd <= 12);  /* 0.036 * 255 = 9.2 per bounce */
    assert_true(mean < 2.0);
    free(ex);
    free(sc);
    free(glass);
    free(g2);
}

/* CELL ARRAY 3 through the GKS entry point in mode 4: one tracer primitive, the cell colours
 * from the colour table at the pixel centres of each quarter. */
static void test_cell_array_e2e(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_ca.png", GHLHSR_RAYTRACE);
    Gint colrs[4] = { 2, 3, 4, 5 }; /* red green / blue yellow */
    Gpat_rep ca = { { 2, 2 }, colrs };
    Gparal par = { { 0.25, 0.25, 0.5 }, { 0.75, 0.75, 0.5 }, { 0.75, 0.25, 0.5 } };
    gcell_array3(&par, &ca);
    gupd_ws(1, GFLAG_PERFORM);
    rt_stat_rec s;
    get_stats(1, &s);
    assert_int_equal(s.i[ST_PRIMS], 1);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    no_errors();
    image img;
    assert_true(read_png("t_rt_ca.png", &img));
    assert_near(&img, 20, 20, 1, 0, 0);
    assert_near(&img, 43, 20, 0, 1, 0);
    assert_near(&img, 20, 43, 0, 0, 1);
    assert_near(&img, 43, 43, 1, 1, 0);
    assert_near(&img, 10, 10, 1, 1, 1);
    free(img.rgb);
}

/* The z-buffer preview of a lit square (flat shading, ws_shade) equals the ray-traced picture
 * within 1/255 in a shadow-free scene: directional + ambient light, specular, depth 1. */
static void test_preview_equals_traced(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_prev_zb.png", GHLHSR_ZBUFFER);
    open_png(2, "t_rt_prev_rt.png", GHLHSR_RAYTRACE);
    assert_int_equal(esc1(GESC_RT_MAX_DEPTH, 2, 1), 0);
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 0.6, 0.5, 0.4 }, { 0, 0, 0 }, { 0.2, -0.3, -0.9 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    gset_light_src_rep(2, 2, &l);
    Gcolr_rep cr = { { 0.8, 0.6, 0.4 } };
    gset_colr_rep(1, 2, &cr);
    gset_colr_rep(2, 2, &cr);
    gset_fill_colr_ind(2);
    gset_fill_int_style(GSTYLE_SOLID);
    Garea_props pr = { 0.3, 0.7, 0.4, { 1, 0.9, 0.8 }, 5, 0, 1 };
    gset_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    Gint on[2] = { 1, 2 };
    Gint_list a = { 2, on };
    gset_light_src_state(&a, NULL);
    square(0.2, 0.8, 0.5);
    Gint colrs[4] = { 2, 3, 4, 5 };
    Gpat_rep ca = { { 2, 2 }, colrs };
    Gparal par = { { 0.05, 0.85, 0.6 }, { 0.95, 0.95, 0.6 }, { 0.95, 0.85, 0.6 } };
    gcell_array3(&par, &ca);
    gdeactivate_ws(1);
    gdeactivate_ws(2);
    gclose_ws(1);
    gclose_ws(2);
    gclose_gks();
    no_errors();
    image z, r;
    assert_true(read_png("t_rt_prev_zb.png", &z));
    assert_true(read_png("t_rt_prev_rt.png", &r));
    for (int y = 14; y < 50; y++)
        for (int x = 14; x < 50; x++)
            for (int q = 0; q < 3; q++)
                if (abs(px(&z, x, y)[q] - px(&r, x, y)[q]) > 1)
                    fail_msg("(%d,%d): preview %d, traced %d", x, y, px(&z, x, y)[q], px(&r, x, y)[q]);
    assert_true(px(&z, 32, 32)[0] > 60 && px(&z, 32, 32)[0] < 250); /* lit, not saturated */
    for (int x = 5; x < 60; x += 3) /* the lit cell array above the square: y 0.85..0.95 */
        for (int q = 0; q < 3; q++)
            if (abs(px(&z, x, 58)[q] - px(&r, x, 58)[q]) > 1)
                fail_msg("cell (%d,58): preview %d, traced %d", x, px(&z, x, 58)[q], px(&r, x, 58)[q]);
    free(z.rgb);
    free(r.rgb);
}


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert),
        cmocka_unit_test(test_shadow),
        cmocka_unit_test(test_silhouettes_match_zbuffer),
        cmocka_unit_test(test_silhouettes_views),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_escape_png),
        cmocka_unit_test(test_stats_counts),
        cmocka_unit_test(test_default_sampling),
        cmocka_unit_test(test_depth_mirror),
        cmocka_unit_test(test_threads_identical),
        cmocka_unit_test(test_threads_oriented),
        cmocka_unit_test(test_threads_attr_changes),
        cmocka_unit_test(test_views_gen),
        cmocka_unit_test(test_threads_view_changes),
        cmocka_unit_test(test_samples_edges),
        cmocka_unit_test(test_cutoff),
        cmocka_unit_test(test_progress),
        cmocka_unit_test(test_fill_area_set_hole),
        cmocka_unit_test(test_shared_list),
        cmocka_unit_test(test_cell_array),
        cmocka_unit_test(test_cell_array_clipped),
        cmocka_unit_test(test_record_limits),
        cmocka_unit_test(test_alloc_failures),
        cmocka_unit_test(test_escape_records),
        cmocka_unit_test(test_fill_area_set_e2e),
        cmocka_unit_test(test_multiple_views),
        cmocka_unit_test(test_clip_secondary_fig45),
        cmocka_unit_test(test_flat_shading_matches_tracer),
        cmocka_unit_test(test_fresnel_schlick_vs_exact),
        cmocka_unit_test(test_cell_array_e2e),
        cmocka_unit_test(test_preview_equals_traced),
        cmocka_unit_test(test_inquire_traced),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
