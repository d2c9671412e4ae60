/* SPDX-License-Identifier: MIT */
/*
 * test_coplanar.c -- coplanar areas in every HLHSR mode (issue 39, item 5; docs/RAYTRACING.md,
 * "Coplanar surfaces"): a blue floor and a red rug lying exactly in the floor's plane, drawn
 * after it, seen through a rotated view orientation (the VRC3 vertices of the two areas are
 * rounded apart, so their computed distances differ by a few units in the last place, either
 * way). The area drawn later wins at equal depth in the z-buffer and painter modes (and
 * trivially in mode none); the tracer must agree: every pixel of the rug's interior is red in
 * the ray-traced picture as well, with no blue speckle. In hidden-line mode the areas are
 * outlines: the rug's outline, lying in the floor, is not hidden by it. The same with a box
 * resting on the floor (top and sides green, bottom red, drawn after the floor and last of the
 * box's faces), seen from below through the floor: the box's bottom shows in every mode.
 *
 * Tolerance: the pixels checked lie at least 0.03 (3 pixels) inside the rug's projected
 * outline, so no sample of an edge pixel is counted; a pixel is red when its red channel
 * exceeds 100 and its blue channel is below 50 (the floor: blue 255, red 0; ambient light
 * only, so shading does not mix the two). Zero wrong pixels are allowed: a single blue
 * pixel inside the rug is the speckle.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "png_util.h"

enum { SZ = 128, NS = 24 };
static const double FLOOR_LO = 0.15, FLOOR_HI = 0.85, RUG_LO = 0.32, RUG_HI = 0.68, ZF = 0.5;
static const double MARGIN = 0.03;

/* 0: the rug on the floor, seen from above; 1: a box resting on the floor (its bottom the rug's
   square), seen from below through the floor */
static int g_box;

/* the view orientation: rotations about x (55 deg; the box: 125 deg, from below) and z (25 deg)
   about the NPC centre */
static void orientation(double m[4][4])
{
    const double a = (g_box ? 125.0 : 55.0) * 3.14159265358979323846 / 180.0,
                 b = 25.0 * 3.14159265358979323846 / 180.0;
    const double ca = cos(a), sa = sin(a), cb = cos(b), sb = sin(b);
    /* R = Rx(a) Rz(b) */
    const double r[3][3] = { { cb, -sb, 0 }, { ca * sb, ca * cb, -sa }, { sa * sb, sa * cb, ca } };
    for (int i = 0; i < 3; i++) {
        double t = 0.5;
        for (int j = 0; j < 3; j++) {
            m[i][j] = r[i][j];
            t -= r[i][j] * 0.5;
        }
        m[i][3] = t;
        m[3][i] = 0.0;
    }
    m[3][3] = 1.0;
}

static void square(double lo, double hi)
{
    Gpoint3 p[4] = { { lo, lo, ZF }, { hi, lo, ZF }, { hi, hi, ZF }, { lo, hi, ZF } };
    Gpoint_list3 l = { 4, p };
    gfill_area3(&l);
}

/* the box over the rug's square, height 0.3: its top and four sides (the bottom is the red
   square, drawn after them) */
static void box_top_sides(double lo, double hi)
{
    const double z0 = ZF, z1 = ZF + 0.3;
    Gpoint3 top[4] = { { lo, lo, z1 }, { hi, lo, z1 }, { hi, hi, z1 }, { lo, hi, z1 } };
    Gpoint_list3 l = { 4, top };
    gfill_area3(&l);
    const double xy[5][2] = { { lo, lo }, { hi, lo }, { hi, hi }, { lo, hi }, { lo, lo } };
    for (int k = 0; k < 4; k++) {
        Gpoint3 q[4] = { { xy[k][0], xy[k][1], z0 }, { xy[k + 1][0], xy[k + 1][1], z0 },
                         { xy[k + 1][0], xy[k + 1][1], z1 }, { xy[k][0], xy[k][1], z1 } };
        Gpoint_list3 side = { 4, q };
        gfill_area3(&side);
    }
}

static void draw(int mode, const char *file)
{
    png_ws_open(file, SZ, mode, 1); /* ray tracing: one ray per pixel centre, no cut-off */
    Gview_rep3 v = { .clip_limit = { 0, 1, 0, 1, 0, 1 }, .xy_clip = GIND_NO_CLIP,
                     .back_clip = GIND_NO_CLIP, .front_clip = GIND_NO_CLIP };
    orientation(v.ori_matrix);
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++)
            v.map_matrix[a][b] = a == b;
    gset_view_rep3(1, 1, &v);
    gset_view_ind(1);
    Gcolr_rep blue = { { 0, 0, 1 } }, red = { { 1, 0, 0 } };
    gset_colr_rep(1, 2, &blue);
    gset_colr_rep(1, 3, &red);
    gset_fill_int_style(GSTYLE_SOLID);
    Garea_props pr = { 1, 0, 0, { 1, 1, 1 }, 1, 0, 1 }; /* ambient only */
    gset_area_props(&pr);
    gset_back_area_props(&pr);
    gset_refl_eq(GREFL_AMBIENT);
    gset_back_refl_eq(GREFL_AMBIENT);
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 1, 1, 1 }, { 0, 0, 0 }, { 0, 0, -1 }, { 1, 0 }, 0, 0 };
    gset_light_src_rep(1, 2, &amb);
    Gint on[1] = { 2 };
    Gint_list act = { 1, on };
    gset_light_src_state(&act, NULL);
    gset_fill_colr_ind(2);
    square(FLOOR_LO, FLOOR_HI);
    if (g_box) {
        Gcolr_rep green = { { 0, 1, 0 } };
        gset_colr_rep(1, 4, &green);
        gset_fill_colr_ind(4);
        box_top_sides(RUG_LO, RUG_HI);
    }
    gset_fill_colr_ind(3);
    square(RUG_LO, RUG_HI);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
}

/* the pixel (column, row from the top) of WC point (x, y, ZF) */
static void pixel(double x, double y, int *c, int *r)
{
    double m[4][4];
    orientation(m);
    const double p[3] = { x, y, ZF };
    double q[2];
    for (int i = 0; i < 2; i++)
        q[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    *c = (int)floor(q[0] * SZ);
    *r = SZ - 1 - (int)floor(q[1] * SZ);
}

static int is_red(const image *im, int c, int r)
{
    const unsigned char *p = im->rgb + 3 * ((size_t)r * (size_t)im->w + (size_t)c);
    return p[0] > 100 && p[2] < 50;
}

/* filled modes: blue pixels inside the rug; hidden line: pixels of the rug's outline drawn */
static void check(int mode, const char *name)
{
    char file[64]; /* t_coplanar_<mode>.png, removed unless TEST_KEEP_PNG is set */
    snprintf(file, sizeof file, "t_coplanar_%s%d.png", g_box ? "box_" : "", mode);
    draw(mode, file);
    image im;
    assert_true(read_png(file, &im));
    assert_int_equal(im.w, SZ);
    if (mode == GHLHSR_HIDDEN_LINE) {
        /* the outline's pixels (the side's midpoints' neighbourhoods): something drawn */
        int seen = 0, n = 0;
        for (int s = 0; s < 4; s++)
            for (int k = 1; k < NS; k++) {
                double f = RUG_LO + (RUG_HI - RUG_LO) * k / NS;
                double x = s == 0 ? f : s == 1 ? RUG_HI : s == 2 ? f : RUG_LO;
                double y = s == 0 ? RUG_LO : s == 1 ? f : s == 2 ? RUG_HI : f;
                int c, r, hit = 0;
                pixel(x, y, &c, &r);
                for (int dr = -1; dr <= 1; dr++)
                    for (int dc = -1; dc <= 1; dc++)
                        hit |= is_red(&im, c + dc, r + dr);
                seen += hit;
                n++;
            }
        print_message("%s: %d of %d points of the rug's outline drawn red\n", name, seen, n);
        assert_int_equal(seen, n);
    } else {
        int wrong = 0, n = 0;
        for (int i = 0; i <= NS; i++)
            for (int j = 0; j <= NS; j++) {
                double x = RUG_LO + MARGIN + (RUG_HI - RUG_LO - 2 * MARGIN) * i / NS;
                double y = RUG_LO + MARGIN + (RUG_HI - RUG_LO - 2 * MARGIN) * j / NS;
                int c, r;
                pixel(x, y, &c, &r);
                wrong += !is_red(&im, c, r);
                n++;
            }
        /* and the floor around the rug is blue (the picture is the expected one) */
        int c, r;
        pixel(0.5 * (FLOOR_LO + RUG_LO), 0.5, &c, &r);
        const unsigned char *p = im.rgb + 3 * ((size_t)r * (size_t)im.w + (size_t)c);
        print_message("%s: %d of %d pixels inside the rug not red\n", name, wrong, n);
        assert_true(p[2] > 200 && p[0] < 50);
        assert_int_equal(wrong, 0);
    }
    free(im.rgb);
    if (!getenv("TEST_KEEP_PNG"))
        remove(file);
}

static void test_none(void **u) { (void)u; g_box = 0; check(GHLHSR_NONE, "none"); }
static void test_hidden_line(void **u) { (void)u; g_box = 0; check(GHLHSR_HIDDEN_LINE, "hidden line"); }
static void test_zbuffer(void **u) { (void)u; g_box = 0; check(GHLHSR_ZBUFFER, "z-buffer"); }
static void test_painter(void **u) { (void)u; g_box = 0; check(GHLHSR_PAINTER, "painter"); }
static void test_raytrace(void **u) { (void)u; g_box = 0; check(GHLHSR_RAYTRACE, "ray traced"); }
/* the box on the floor, from below: its bottom (drawn after the floor) shows */
static void test_box_none(void **u) { (void)u; g_box = 1; check(GHLHSR_NONE, "box, none"); }
static void test_box_hidden_line(void **u) { (void)u; g_box = 1; check(GHLHSR_HIDDEN_LINE, "box, hidden line"); }
static void test_box_zbuffer(void **u) { (void)u; g_box = 1; check(GHLHSR_ZBUFFER, "box, z-buffer"); }
static void test_box_painter(void **u) { (void)u; g_box = 1; check(GHLHSR_PAINTER, "box, painter"); }
static void test_box_raytrace(void **u) { (void)u; g_box = 1; check(GHLHSR_RAYTRACE, "box, ray traced"); }

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_none),
        cmocka_unit_test(test_hidden_line),
        cmocka_unit_test(test_zbuffer),
        cmocka_unit_test(test_painter),
        cmocka_unit_test(test_raytrace),
        cmocka_unit_test(test_box_none),
        cmocka_unit_test(test_box_hidden_line),
        cmocka_unit_test(test_box_zbuffer),
        cmocka_unit_test(test_box_painter),
        cmocka_unit_test(test_box_raytrace),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
