/* SPDX-License-Identifier: MIT */
/* test_gdp.c -- the GDPs (issue 17 item 4): RAL's ARC, CHORD, PIE, CIRCLE and the ELLIPSE
 * drawn on a 200x200 PNG workstation and measured by pixel counts against the exact
 * areas; RAL gdpex's pie sectors; 3-D circles; replay from a segment; the description
 * table; the errors; degenerate and hostile points. Pictures: gdp_*.png in the test's
 * build folder. */
#include <gks.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <cmocka.h>

#define PX 200
#define PI 3.14159265358979323846

static Gint last_err;
static void catch_err(Gint err, Gint fn, const char *f)
{
    (void)fn;
    (void)f;
    last_err = err;
}

static void open_png(const char *name)
{
    gemergency_close_gks();
    gset_err_hand(catch_err, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(1, name, GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_vp(1, &(Glimit){ 0, PX, 0, PX });
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gset_line_colr_ind(4);
    last_err = 0;
}

static void close_png(void)
{
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
}

/* Pixels of colour index ci on the whole raster. */
static int count(Gint ci)
{
    static Gint buf[PX * PX];
    Gint e = -1, len = 0;
    Gpres_inval inv;
    Gint_list l = { 0, buf };
    ginq_pixel_array(1, &(Gpoint){ 0.5 / PX, 1 - 0.5 / PX }, &(Gint_size){ PX, PX }, PX * PX, 0,
                     &e, &inv, &l, &len);
    assert_int_equal(e, 0);
    int n = 0;
    for (int i = 0; i < PX * PX; i++)
        n += buf[i] == ci;
    return n;
}

static Gint pixel(double x, double y)
{
    Gint e = -1, c = -9;
    ginq_pixel(1, &(Gpoint){ x, y }, &e, &c);
    assert_int_equal(e, 0);
    return c;
}

/* Pixel areas match the exact ones within 1%: scan conversion decides each boundary
 * pixel by its centre, an error of a fraction of the ~400-pixel perimeter (measured well
 * under 0.5%); the tessellation's own error is 4e-5 of the radius. */
static void assert_area(int got, double want)
{
    if (fabs(got - want) > 0.01 * want)
        fail_msg("area %d pixels, exact %.1f", got, want);
}

static void test_circle_ellipse(void **state)
{
    (void)state;
    open_png("gdp_circle");
    /* Circle by centre and a point: radius 0.3 -> 60 pixels. */
    ggdp(&(Gpoint_list){ 2, (Gpoint[]){ { 0.5, 0.5 }, { 0.8, 0.5 } } }, GGDP_CIRCLE, NULL);
    assert_int_equal(last_err, 0);
    assert_area(count(2), PI * 60 * 60);
    assert_int_equal(pixel(0.5, 0.79), 2);
    assert_int_equal(pixel(0.5, 0.81), 0);
    gclear_ws(1, GFLAG_ALWAYS);
    /* The same circle through three of its points. */
    double r = 0.3;
    Gpoint on[3] = { { 0.5 + r, 0.5 }, { 0.5, 0.5 + r }, { 0.5 + r * cos(4.0), 0.5 + r * sin(4.0) } };
    ggdp(&(Gpoint_list){ 3, on }, GGDP_CIRCLE, NULL);
    assert_area(count(2), PI * 60 * 60);
    gclear_ws(1, GFLAG_ALWAYS);
    /* Ellipse: semi-axes 0.4 and 0.15 (80 and 30 pixels), given by conjugate points. */
    gset_fill_colr_ind(3);
    ggdp(&(Gpoint_list){ 3, (Gpoint[]){ { 0.5, 0.5 }, { 0.9, 0.5 }, { 0.5, 0.65 } } },
         GGDP_ELLIPSE, NULL);
    assert_int_equal(last_err, 0);
    assert_area(count(3), PI * 80 * 30);
    assert_int_equal(pixel(0.88, 0.5), 3);
    assert_int_equal(pixel(0.5, 0.67), 0);
    close_png();
}

/* RAL gdpex: three sectors of 150, 115 and 95 degrees, radius 0.375, clockwise from 12
 * o'clock, each given by its first, middle and last point on the circle. */
static void test_pie_gdpex(void **state)
{
    (void)state;
    open_png("gdp_pie");
    const double xc = 0.5, yc = 0.5, rad = 0.375, deg[3] = { 150, 115, 95 };
    double th = 0;
    Gpoint p[3] = { { xc + rad * sin(th), yc + rad * cos(th) } };
    for (int i = 0; i < 3; i++) {
        double half = deg[i] * PI / 360.0;
        for (int j = 1; j < 3; j++) {
            th += half;
            p[j] = (Gpoint){ xc + rad * sin(th), yc + rad * cos(th) };
        }
        gset_fill_colr_ind(2 + i);
        ggdp(&(Gpoint_list){ 3, p }, GGDP_PIE, NULL);
        assert_int_equal(last_err, 0);
        p[0] = p[2];
    }
    for (int i = 0; i < 3; i++)
        assert_area(count(2 + i), deg[i] / 360.0 * PI * 75 * 75);
    /* The first sector (clockwise from 12 o'clock over 150 degrees) holds 2 o'clock. */
    assert_int_equal(pixel(xc + 0.2 * sin(PI / 3), yc + 0.2 * cos(PI / 3)), 2);
    assert_int_equal(pixel(xc - 0.2, yc + 0.05), 4); /* 284 degrees: the third sector */
    assert_int_equal(pixel(xc + 0.2 * sin(200 * PI / 180), yc + 0.2 * cos(200 * PI / 180)), 3);
    assert_int_equal(pixel(xc + 0.39, yc), 0);       /* outside the radius */
    close_png();
}

static void test_arc_chord(void **state)
{
    (void)state;
    open_png("gdp_arc");
    /* Upper half circle: P1 right, P2 top, P3 left. The chord closes it: half the disc. */
    Gpoint h[3] = { { 0.8, 0.5 }, { 0.5, 0.8 }, { 0.2, 0.5 } };
    ggdp(&(Gpoint_list){ 3, h }, GGDP_CHORD, NULL);
    assert_area(count(2), PI * 60 * 60 / 2);
    assert_int_equal(pixel(0.5, 0.6), 2);
    assert_int_equal(pixel(0.5, 0.4), 0);
    gclear_ws(1, GFLAG_ALWAYS);
    /* The arc is a line: drawn on the circle, nothing inside; the lower half stays empty. */
    ggdp(&(Gpoint_list){ 3, h }, GGDP_ARC, NULL);
    assert_true(pixel(0.5, 0.8 - 0.25 / PX) == 4 || pixel(0.5, 0.8 + 0.25 / PX) == 4);
    assert_int_equal(pixel(0.5 + 0.3 * cos(PI / 4), 0.5 + 0.3 * sin(PI / 4)), 4);
    assert_int_equal(pixel(0.5, 0.6), 0);
    assert_int_equal(pixel(0.5, 0.2), 0);
    int line = count(4);
    assert_true(line > 0.8 * PI * 60 && line < 3 * PI * 60); /* about one pixel wide */
    close_png();
}

/* GDP 3: a circle through three points in the plane z = 0.5 tilted nowhere, and one in
 * a plane seen edge-on (x = 0.5) that covers only a line. */
static void test_gdp3(void **state)
{
    (void)state;
    open_png("gdp_3d");
    double r = 0.25;
    Gpoint3 q[3] = { { 0.5 + r, 0.5, 0.5 }, { 0.5, 0.5 + r, 0.5 }, { 0.5 - r, 0.5, 0.5 } };
    ggdp3(&(Gpoint_list3){ 3, q }, GGDP_CIRCLE, NULL);
    assert_int_equal(last_err, 0);
    assert_area(count(2), PI * 50 * 50);
    gclear_ws(1, GFLAG_ALWAYS);
    Gpoint3 e[3] = { { 0.5, 0.5 + r, 0.5 }, { 0.5, 0.5, 0.5 + r }, { 0.5, 0.5 - r, 0.5 } };
    ggdp3(&(Gpoint_list3){ 3, e }, GGDP_PIE, NULL);
    assert_int_equal(last_err, 0);
    assert_true(count(2) < 3 * 2 * 50); /* edge-on: a line at most a few pixels wide */
    close_png();
}

/* Ray traced: a GDP 3 is an area to the tracer (the disc covers its pixels). */
static void test_raytraced(void **state)
{
    (void)state;
    open_png("gdp_rt");
    gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
    double r = 0.3;
    Gpoint3 q[3] = { { 0.5 + r, 0.5, 0.5 }, { 0.5, 0.5 + r, 0.5 }, { 0.5 - r, 0.5, 0.5 } };
    ggdp3(&(Gpoint_list3){ 3, q }, GGDP_CIRCLE, NULL);
    gupd_ws(1, GFLAG_PERFORM);
    assert_int_equal(last_err, 0);
    /* The tracer's pixels on the rim mix disc and background (neither index 0 nor 2):
     * counted as half covered, the rim's average. */
    int bg = count(0), red = count(2), rim = PX * PX - bg - red;
    assert_true(rim < 2 * 2 * PI * 60); /* a rim about one pixel wide */
    assert_area(red + rim / 2, PI * 60 * 60);
    close_png();
}

/* A GDP in a segment is drawn again by REDRAW ALL SEGMENTS ON WORKSTATION. */
static void test_segment_replay(void **state)
{
    (void)state;
    open_png("gdp_seg");
    gcreate_seg(7);
    ggdp(&(Gpoint_list){ 2, (Gpoint[]){ { 0.5, 0.5 }, { 0.7, 0.5 } } }, GGDP_CIRCLE, NULL);
    gclose_seg();
    int before = count(2);
    assert_area(before, PI * 40 * 40);
    gredraw_all_seg_ws(1);
    assert_int_equal(last_err, 0);
    assert_int_equal(count(2), before);
    close_png();
}

static void test_desc_table(void **state)
{
    (void)state;
    open_png("gdp_desc");
    Gint buf[8], len = 0, e = -1;
    Gint_list l = { 0, buf };
    ginq_list_avail_gdps(GWS_TYPE_PNG, 8, 0, &e, &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 5);
    for (int i = 0; i < 5; i++)
        assert_int_equal(buf[i], -1 - i);
    ginq_list_avail_gdps3(GWS_TYPE_NULL, 8, 0, &e, &l, &len);
    assert_int_equal(len, 5);
    Gint na = 0;
    Gattrs at[5];
    ginq_gdp(GWS_TYPE_PNG, GGDP_PIE, &e, &na, at);
    assert_int_equal(e, 0);
    assert_int_equal(na, 1);
    assert_int_equal(at[0], GATTR_FILL);
    ginq_gdp3(GWS_TYPE_PNG, GGDP_PIE, &e, &na, at);
    assert_int_equal(na, 2);
    assert_int_equal(at[1], GATTR_EDGE);
    ginq_gdp3(GWS_TYPE_PNG, GGDP_ARC, &e, &na, at);
    assert_int_equal(na, 1);
    assert_int_equal(at[0], GATTR_LINE);
    ginq_gdp(GWS_TYPE_PNG, 1, &e, &na, at);
    assert_int_equal(e, 41);
    ginq_gdp(GWS_TYPE_PNG, -6, &e, &na, at);
    assert_int_equal(e, 41);
    ginq_list_avail_gdps(GWS_TYPE_MO, 8, 0, &e, &l, &len);
    assert_int_equal(e, 39); /* no output description table */
    close_png();
}

static void test_errors_hostile(void **state)
{
    (void)state;
    open_png("gdp_err");
    Gpoint p[3] = { { 0.2, 0.2 }, { 0.5, 0.5 }, { 0.8, 0.8 } };
    ggdp(&(Gpoint_list){ 3, p }, 1, NULL);
    assert_int_equal(last_err, 102);
    last_err = 0;
    ggdp(&(Gpoint_list){ 3, p }, -6, NULL);
    assert_int_equal(last_err, 102);
    last_err = 0;
    ggdp(&(Gpoint_list){ 2, p }, GGDP_PIE, NULL);
    assert_int_equal(last_err, 100);
    last_err = 0;
    ggdp(&(Gpoint_list){ 4, (Gpoint[4]){ { 0 } } }, GGDP_CIRCLE, NULL);
    assert_int_equal(last_err, 100);
    last_err = 0;
    ggdp(NULL, GGDP_PIE, NULL);
    assert_int_equal(last_err, 100);
    last_err = 0;
    assert_int_equal(count(2), 0); /* errors have no other effect */
    /* Collinear and coincident points: no circle, no error, nothing filled. */
    for (int id = -1; id >= -5; id--) {
        ggdp(&(Gpoint_list){ 3, p }, id, NULL);
        assert_int_equal(last_err, 0);
        Gpoint same[3] = { { 0.3, 0.3 }, { 0.3, 0.3 }, { 0.3, 0.3 } };
        ggdp(&(Gpoint_list){ 3, same }, id, NULL);
        assert_int_equal(last_err, 0);
    }
    ggdp(&(Gpoint_list){ 2, (Gpoint[]){ { 0.4, 0.4 }, { 0.4, 0.4 } } }, GGDP_CIRCLE, NULL);
    assert_int_equal(last_err, 0);
    assert_true(count(2) < 4 * PX);
    /* Non-finite and huge coordinates: whatever FILL AREA does with them, no crash. */
    Gpoint bad[3] = { { NAN, 0.5 }, { 0.5, INFINITY }, { 1e300, -1e300 } };
    for (int id = -1; id >= -5; id--) {
        ggdp(&(Gpoint_list){ 3, bad }, id, NULL);
        Gpoint far[3] = { { 1e30, 0 }, { 0, 1e30 }, { -1e30, 1 } };
        ggdp(&(Gpoint_list){ 3, far }, id, NULL);
        Gpoint tiny[3] = { { 0.5, 0.5 }, { 0.5 + 1e-300, 0.5 }, { 0.5, 0.5 + 1e-300 } };
        ggdp(&(Gpoint_list){ 3, tiny }, id, NULL);
    }
    close_png();
    /* State: GDP needs an active workstation (5). */
    gopen_gks(NULL, 0);
    last_err = 0;
    ggdp(&(Gpoint_list){ 3, p }, GGDP_PIE, NULL);
    assert_int_equal(last_err, 5);
    gclose_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_circle_ellipse), cmocka_unit_test(test_pie_gdpex),
        cmocka_unit_test(test_arc_chord),      cmocka_unit_test(test_gdp3),
        cmocka_unit_test(test_raytraced),
        cmocka_unit_test(test_segment_replay), cmocka_unit_test(test_desc_table),
        cmocka_unit_test(test_errors_hostile),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
