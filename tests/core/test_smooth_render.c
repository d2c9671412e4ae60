/* SPDX-License-Identifier: MIT */
/*
 * test_smooth_render.c -- areas WITH DATA through the PNG workstation (issue 19): a sphere of
 * 48 x 24 lat-long triangles drawn with FILL AREA 3 WITH DATA (exact vertex normals, interior
 * shading method NORMAL) reproduces the exact sphere's Lambert shading in the ray-traced, the
 * z-buffer and the painter mode; drawn flat (FILL AREA 3) it does not. The same through a view
 * orientation that scales y by 1/2: the picture is then the ellipsoid's, whose normals are
 * the sphere's through the inverse transpose (the drivers' normal transformation), lit by the
 * light's direction through the same orientation.
 *
 * Tolerance: 4/255 per channel, over pixels whose exact normal is at least 0.3 towards the
 * viewer and whose N.L is not within 0.1 of 0 (the terminator band, decided by shadow rays in
 * the tracer). Why: normal interpolation over cells of h = pi/24 rad is off the exact normal by
 * about h^2/8 = 2.1e-3 rad (the ellipsoid's cells are bent twice as much in y: 4.3e-3), the
 * compared exact normal is taken up to that / 0.3 away along the view ray, kd = 0.9: a loose
 * bound (worst cases added) of 0.9 * 4.3e-3 * (1 + 1/0.3) = 0.017; measured (printed)
 * 2.3/255 (1.7/255 squashed), rounding to 8 bits included. Flat facets are off by up to
 * h/2 = 0.065 rad (measured 0.055-0.064 in colour). 4/255 = 0.016 lies between the two with
 * margin on both sides.
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

enum { SZ = 96, NU = 48, NV = 24 };
static const double PI = 3.14159265358979323846, R = 0.4, TOL = 4.0 / 255.0;
static const double OD[3] = { 0.9, 0.7, 0.5 }, LDIR[3] = { -0.5, -0.3, -0.81 };

/* vertex (i, j) of the lat-long sphere about (0.5, 0.5, 0.5): point and unit normal */
static void vertex(int i, int j, Gpoint3 *p, Gvec3 *n)
{
    double th = PI * j / NV, ph = 2 * PI * (i % NU) / NU;
    *n = (Gvec3){ sin(th) * cos(ph), sin(th) * sin(ph), cos(th) };
    *p = (Gpoint3){ 0.5 + R * n->delta_x, 0.5 + R * n->delta_y, 0.5 + R * n->delta_z };
}

static void sphere(int with_data)
{
    for (int j = 0; j < NV; j++)
        for (int i = 0; i < NU; i++) {
            Gpoint3 p[4];
            Gvec3 n[4];
            vertex(i, j, &p[0], &n[0]);
            vertex(i + 1, j, &p[1], &n[1]);
            vertex(i + 1, j + 1, &p[2], &n[2]);
            vertex(i, j + 1, &p[3], &n[3]);
            for (int t = 0; t < 2; t++) {
                if ((t == 0 && j == 0) || (t == 1 && j == NV - 1))
                    continue;
                Gpoint3 q[3] = { p[0], p[1 + t], p[2 + t] };
                Gvec3 m[3] = { n[0], n[1 + t], n[2 + t] };
                if (with_data) {
                    Gfacet_vdata3 vd = { 3, q, NULL, m };
                    gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
                } else {
                    Gpoint_list3 l = { 3, q };
                    gfill_area3(&l);
                }
            }
        }
}

/* Draws the sphere on a 96 x 96 PNG in `mode`; squash: view 1 scales y by 1/2 about 0.5.
 * Returns the largest error over the compared pixels. */
/* XCLIP: the view's xy clip at x = XCLIP (NPC), through the sphere (centre 0.5, radius R):
 * facets crossing it are clipped, and must stay smooth up to the boundary. */
static const double XCLIP = 0.63;

static double picture(int mode, int with_data, int squash, int clip)
{
    const char *file = "t_smooth_render.png";
    png_ws_open(file, SZ, mode, 1); /* ray tracing: one ray per pixel centre, no cut-off */
    Gview_rep3 v = { .clip_limit = { 0, 1, 0, 1, 0, 1 }, .xy_clip = GIND_NO_CLIP,
                     .back_clip = GIND_NO_CLIP, .front_clip = GIND_NO_CLIP };
    for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++)
            v.ori_matrix[a][b] = v.map_matrix[a][b] = a == b;
    if (clip) {
        v.clip_limit.x_max = XCLIP;
        v.xy_clip = GIND_CLIP;
    }
    if (squash) {
        v.ori_matrix[1][1] = 0.5;
        v.ori_matrix[1][3] = 0.25;
    }
    gset_view_rep3(1, 1, &v);
    gset_view_ind(1);
    Gcolr_rep c = { { OD[0], OD[1], OD[2] } };
    gset_colr_rep(1, 2, &c);
    gset_fill_colr_ind(2);
    gset_fill_int_style(GSTYLE_SOLID);
    Garea_props pr = { 1, 0.9, 0, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&pr);
    gset_back_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF);
    gset_back_refl_eq(GREFL_AMB_DIFF);
    gset_int_shad_meth(GSHAD_NORM);
    gset_back_int_shad_meth(GSHAD_NORM);
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 0.1, 0.1, 0.1 }, { 0, 0, 0 }, { 0, 0, -1 },
                           { 1, 0 }, 0, 0 };
    Glight_src_rep dl = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 },
                          { LDIR[0], LDIR[1], LDIR[2] }, { 1, 0 }, 0, 0 };
    gset_light_src_rep(1, 2, &amb);
    gset_light_src_rep(1, 3, &dl);
    Gint on[2] = { 2, 3 };
    Gint_list act = { 2, on };
    gset_light_src_state(&act, NULL);
    sphere(with_data);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    image img;
    assert_true(read_png(file, &img));
    assert_int_equal(img.w, SZ);
    /* the light's direction goes through the view orientation too (into VRC3) */
    double L[3] = { -LDIR[0], -LDIR[1] * (squash ? 0.5 : 1.0), -LDIR[2] };
    double l = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    for (int k = 0; k < 3; k++)
        L[k] /= l;
    const double b = squash ? 0.5 * R : R; /* semi-axis in y */
    double worst = 0;
    int n = 0;
    for (int y = 0; y < SZ; y++)
        for (int x = 0; x < SZ; x++) {
            double dx = (x + 0.5) / SZ - 0.5, dy = (y + 0.5) / SZ - 0.5;
            double q = 1 - (dx / R) * (dx / R) - (dy / b) * (dy / b);
            if (q <= 0 || (clip && (x + 1.0) / SZ > XCLIP)) /* pixels wholly inside */
                continue;
            double dz = R * sqrt(q);
            double N[3] = { dx / (R * R), dy / (b * b), dz / (R * R) };
            double ln = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
            for (int k = 0; k < 3; k++)
                N[k] /= ln;
            double nl = N[0] * L[0] + N[1] * L[1] + N[2] * L[2];
            if (N[2] < 0.3 || fabs(nl) < 0.1)
                continue;
            const unsigned char *p = px(&img, x, y);
            for (int k = 0; k < 3; k++) {
                double want = 0.1 * OD[k] + (nl > 0 ? 0.9 * OD[k] * nl : 0);
                worst = fmax(worst, fabs(p[k] / 255.0 - want));
            }
            n++;
        }
    assert_true(n > SZ * SZ / (squash || clip ? 8 : 4));
    free(img.rgb);
    remove(file);
    return worst;
}

static void check(int mode, int squash, int clip)
{
    double smooth = picture(mode, 1, squash, clip), flat = picture(mode, 0, squash, clip);
    print_message("%s%s: largest error smooth %.4f (%.1f/255), flat %.4f\n",
                  mode == GHLHSR_RAYTRACE ? "ray traced"
                  : mode == GHLHSR_ZBUFFER ? "z-buffer"
                                           : "painter",
                  squash ? ", y scaled by 1/2" : clip ? ", xy-clipped" : "", smooth, smooth * 255, flat);
    assert_true(smooth <= TOL);
    assert_true(flat > TOL);
}

static void test_raytrace(void **u) { (void)u; check(GHLHSR_RAYTRACE, 0, 0); }
static void test_zbuffer(void **u) { (void)u; check(GHLHSR_ZBUFFER, 0, 0); }
static void test_painter(void **u) { (void)u; check(GHLHSR_PAINTER, 0, 0); }
/* the same tolerance across the clip boundary (old code: flat facets along it) */
static void test_zbuffer_clipped(void **u) { (void)u; check(GHLHSR_ZBUFFER, 0, 1); }
static void test_painter_clipped(void **u) { (void)u; check(GHLHSR_PAINTER, 0, 1); }
static void test_raytrace_squashed(void **u) { (void)u; check(GHLHSR_RAYTRACE, 1, 0); }
static void test_zbuffer_squashed(void **u) { (void)u; check(GHLHSR_ZBUFFER, 1, 0); }

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_raytrace),
        cmocka_unit_test(test_zbuffer),
        cmocka_unit_test(test_painter),
        cmocka_unit_test(test_raytrace_squashed),
        cmocka_unit_test(test_zbuffer_squashed),
        cmocka_unit_test(test_zbuffer_clipped),
        cmocka_unit_test(test_painter_clipped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
