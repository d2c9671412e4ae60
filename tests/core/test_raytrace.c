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

static void open_png(int ws, const char *file, int mode)
{
    unlink(file);
    gopen_ws(ws, file, GWS_TYPE_PNG);
    gactivate_ws(ws);
    gset_ws_win(ws, &unit_win);
    gset_ws_vp(ws, &vp64);
    gset_hlhsr_mode(ws, mode);
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

static void test_lambert(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_png(1, "t_rt_lambert.png", GHLHSR_RAYTRACE);
    /* Light travels along (0,-0.8,-0.6): cos between normal +z and -dir = 0.6. */
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, -0.8, -0.6 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Grgb c = { 0.8, 0.6, 0.4 };
    lit_setup(&c);
    square(0.2, 0.8, 0.5);
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
    Gescape_in_data in = { 2, d, 0, NULL, 0, NULL };
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &in, NULL), 180, GFN_ESC);
    EXPECT(gescape(-999, &in, NULL), 180, GFN_ESC);
    Gescape_in_data short_rec = { 0, d, 0, NULL, 0, NULL };
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &short_rec, NULL), 182, GFN_ESC);
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
    Gescape_in_data in = { 2, d, 0, NULL, 0, NULL };
    d[1] = 2; /* a bad record on a workstation that supports the escape: 182, no effect */
    EXPECT(gescape(GESC_RT_CLIP_SECONDARY, &in, NULL), 182, GFN_ESC);
    d[1] = 1;
    n_captured = 0;
    gescape(GESC_RT_CLIP_SECONDARY, &in, NULL);
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lambert),
        cmocka_unit_test(test_shadow),
        cmocka_unit_test(test_silhouettes_match_zbuffer),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_escape_png),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
