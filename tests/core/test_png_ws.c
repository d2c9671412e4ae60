/* SPDX-License-Identifier: MIT */
/*
 * test_png_ws.c -- the PNG workstation: image size from the workstation viewport, exact
 * pixel colours (no tolerance: solid fills without anti-aliasing are exact), clipping at
 * the normalization viewport, the frame/file naming rule and ESCAPE "set file name".
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

#include "png_util.h"

static void assert_colour(const image *img, int x, int y, int r, int g, int b)
{
    const unsigned char *p = px(img, x, y);
    if (p[0] != r || p[1] != g || p[2] != b)
        fail_msg("pixel (%d,%d) = %d %d %d, want %d %d %d", x, y, p[0], p[1], p[2], r, g, b);
}

static void test_fill_and_clip(void **u)
{
    (void)u;
    reset_gks();
    unlink("t_fill.png");
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    gopen_ws(1, "t_fill.png", GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit vp = { 0, 40, 0, 20 }, wsw = { 0, 1, 0, 0.5 };
    gset_ws_win(1, &wsw);
    gset_ws_vp(1, &vp);
    /* tnr 1: WC [0,10]^2 -> NDC [0,0.5]x[0,0.5], clipping on */
    Glimit win = { 0, 10, 0, 10 }, nvp = { 0, 0.5, 0, 0.5 };
    gset_win(1, &win);
    gset_vp(1, &nvp);
    gsel_norm_tran(1);
    /* a rectangle reaching far beyond the viewport: clipped to NDC x < 0.5 = pixel 20 */
    Gpoint r[4] = { { 2.5, 2.5 }, { 100, 2.5 }, { 100, 7.5 }, { 2.5, 7.5 } };
    Gpoint_list rl = { 4, r };
    gset_fill_colr_ind(2);
    gfill_area(&rl);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(n_captured, 0);

    image img;
    assert_true(read_png("t_fill.png", &img));
    assert_int_equal(img.w, 40);
    assert_int_equal(img.h, 20);
    /* WC 2.5..7.5 -> NDC 0.125..0.375 -> pixels 5..15 (centres 5.5..14.5 inside) */
    int red = 0;
    for (int y = 0; y < img.h; y++)
        for (int x = 0; x < img.w; x++) {
            const unsigned char *p = px(&img, x, y);
            int inside = x >= 5 && x < 20 && y >= 5 && y < 15;
            if (inside)
                assert_colour(&img, x, y, 255, 0, 0);
            else
                assert_colour(&img, x, y, 255, 255, 255);
            red += p[1] == 0;
        }
    assert_int_equal(red, 15 * 10);
    free(img.rgb);
    unlink("t_fill.png");
}

static void test_frames_and_names(void **u)
{
    (void)u;
    reset_gks();
    unlink("t_frame.png");
    unlink("t_frame-002.png");
    unlink("t_renamed.png");
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    gopen_ws(1, "t_frame", GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit vp = { 0, 8, 0, 8 };
    gset_ws_vp(1, &vp);
    Gpoint l[2] = { { 0, 0.5 }, { 1, 0.5 } };
    Gpoint_list ll = { 2, l };
    gpolyline(&ll);
    gclear_ws(1, GFLAG_COND);  /* writes frame 1, starts frame 2 */
    gpolyline(&ll);
    gupd_ws(1, GFLAG_PERFORM); /* writes frame 2 */
    Gint ws = 1;
    Gescape_in_data in = { { 1, &ws, 0, NULL, 9, "t_renamed" } };
    gclear_ws(1, GFLAG_ALWAYS);
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    gpolyline(&ll);
    gdeactivate_ws(1);
    gclose_ws(1);              /* writes frame 3 under the new name */
    gclose_gks();
    assert_int_equal(n_captured, 0);
    image img;
    assert_true(read_png("t_frame.png", &img));
    assert_colour(&img, 3, 4, 0, 0, 0); /* the black line across y = 4 */
    assert_colour(&img, 3, 1, 255, 255, 255);
    free(img.rgb);
    assert_true(read_png("t_frame-002.png", &img));
    free(img.rgb);
    assert_int_equal(access("t_renamed-003.png", F_OK), 0);
    unlink("t_frame.png");
    unlink("t_frame-002.png");
    unlink("t_renamed-003.png");
}

/* Several workstations without a connection identifier: the first writes gks.png, each
 * further one gks-wsW.png (W its identifier) while gks.png is taken, so none gets 21. */
static void test_default_names(void **u)
{
    (void)u;
    reset_gks();
    const char *files[] = { "gks.png", "gks-ws2.png", "gks-ws7.png", "gks-ws3.png" };
    for (int i = 0; i < 4; i++)
        unlink(files[i]);
    gopen_gks(NULL, 0);
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gopen_ws(2, "", GWS_TYPE_PNG);
    gopen_ws(7, NULL, GWS_TYPE_PNG);
    assert_int_equal(n_captured, 0);
    gclose_ws(2);
    gclose_ws(7);
    gclose_ws(1);
    /* alone again, a workstation without identifier gets gks.png as before */
    gopen_ws(3, NULL, GWS_TYPE_PNG);
    gclose_ws(3);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    for (int i = 0; i < 3; i++) {
        assert_int_equal(access(files[i], F_OK), 0);
        unlink(files[i]);
    }
    assert_int_equal(access(files[3], F_OK), -1);
}

static void test_unwritable_file(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    n_captured = 0;
    /* issue 20: checked at OPEN WORKSTATION (26), not first noticed at UPDATE or CLOSE */
    gopen_ws(1, "/nonexistent-dir/pic.png", GWS_TYPE_PNG);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 26);
    Gop_st op;
    ginq_op_st(&op);
    assert_int_equal(op, GST_GKOP); /* not opened */
    gclose_gks();
}

/* Two squares crossing at x = 0.5: A (red) has z = x, B (blue) z = 1 - x (NPC front =
 * larger z). Z-buffer: blue left of the crossing, red right of it, whatever the order;
 * HLHSR NONE: the last drawn wins. Exact pixels: the crossing lies between pixel centres. */
static void draw_crossing(int mode, int a_first, image *img)
{
    Gpoint3 a[4] = { { 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 0 } };
    Gpoint3 b[4] = { { 0, 0, 1 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 1 } };
    Gpoint_list3 la = { 4, a }, lb = { 4, b };
    reset_gks();
    unlink("t_z.png");
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    gopen_ws(1, "t_z.png", GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit vp = { 0, 16, 0, 8 }, win = { 0, 1, 0, 0.5 };
    gset_ws_win(1, &win);
    gset_ws_vp(1, &vp);
    gset_hlhsr_mode(1, mode);
    for (int k = 0; k < 2; k++) {
        int first = (k == 0) == a_first;
        gset_fill_colr_ind(first ? 2 : 4);
        gfill_area3(first ? &la : &lb);
    }
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    assert_true(read_png("t_z.png", img));
    unlink("t_z.png");
}

static void test_zbuffer_interpenetrating(void **u)
{
    (void)u;
    for (int order = 0; order < 2; order++) {
        image img;
        draw_crossing(GHLHSR_ZBUFFER, order, &img);
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 16; x++) {
                if (x < 8)
                    assert_colour(&img, x, y, 0, 0, 255);
                else
                    assert_colour(&img, x, y, 255, 0, 0);
            }
        free(img.rgb);
        draw_crossing(GHLHSR_NONE, order, &img);
        int last_red = order == 0 ? 0 : 1; /* order 1: A (red) first, so blue last */
        assert_colour(&img, 3, 3, last_red ? 0 : 255, 0, last_red ? 255 : 0);
        assert_colour(&img, 12, 3, last_red ? 0 : 255, 0, last_red ? 255 : 0);
        free(img.rgb);
    }
    /* ray tracing and the other modes not yet available: 511, mode unchanged */
    reset_gks();
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    gopen_ws(1, NULL, GWS_TYPE_NULL);
    gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 511);
    Gint err, mode = -1;
    ginq_hlhsr_mode(1, &err, &mode);
    assert_int_equal(mode, GHLHSR_NONE);
    reset_gks();
}

/* A view representation: a parallel mapping of the view window [0,0.5]^2 onto the whole
 * NPC unit square magnifies by 2; with the xy view clip on, what lies beyond it vanishes. */
static void test_view_representation(void **u)
{
    (void)u;
    reset_gks();
    unlink("t_view.png");
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID); /* the standard's default is HOLLOW */
    gopen_ws(1, "t_view.png", GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit vp = { 0, 20, 0, 20 };
    gset_ws_vp(1, &vp);
    Gview_rep3 r = { .clip_limit = { 0, 1, 0, 1, 0, 1 }, .xy_clip = GIND_CLIP,
                     .back_clip = GIND_CLIP, .front_clip = GIND_CLIP };
    Gpoint3 vrp = { 0, 0, 0 };
    Gvec3 vpn = { 0, 0, 1 }, vup = { 0, 1, 0 };
    Gint err;
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, r.ori_matrix);
    Gview_map3 map = { { 0, 0.5, 0, 0.5 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PARAL,
                       { 0.25, 0.25, 5 }, 0, 0, 1 };
    geval_view_map_matrix3(&map, &err, r.map_matrix);
    assert_int_equal(err, 0);
    gset_view_rep3(1, 1, &r);
    gset_view_ind(1);
    /* NDC square 0.1..0.2 at z 0.5 -> NPC 0.2..0.4 -> pixels 4..8 */
    Gpoint3 sq[4] = { { 0.1, 0.1, 0.5 }, { 0.2, 0.1, 0.5 }, { 0.2, 0.2, 0.5 }, { 0.1, 0.2, 0.5 } };
    Gpoint_list3 l = { 4, sq };
    gset_fill_colr_ind(3);
    gfill_area3(&l);
    /* a square at NDC 0.6..0.7 maps to NPC 1.2..1.4: clipped away entirely */
    for (int i = 0; i < 4; i++) { sq[i].x += 0.5; }
    gfill_area3(&l);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    image img;
    assert_true(read_png("t_view.png", &img));
    int green = 0;
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 20; x++) {
            const unsigned char *p = px(&img, x, y);
            int in = x >= 4 && x < 8 && y >= 4 && y < 8;
            green += p[0] == 0 && p[1] == 255;
            if (in)
                assert_colour(&img, x, y, 0, 255, 0);
        }
    assert_int_equal(green, 16);
    free(img.rgb);
    unlink("t_view.png");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fill_and_clip),
        cmocka_unit_test(test_frames_and_names),
        cmocka_unit_test(test_default_names),
        cmocka_unit_test(test_unwritable_file),
        cmocka_unit_test(test_zbuffer_interpenetrating),
        cmocka_unit_test(test_view_representation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
