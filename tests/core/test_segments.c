/* SPDX-License-Identifier: MIT */
/*
 * test_segments.c -- segments through the C binding on PNG workstations: the operating
 * state machine, every segment error number, the inquiries, and the picture after
 * regeneration (segment transformation, visibility, priority, CLEAR WORKSTATION), checked
 * pixel by pixel. Solid fills without anti-aliasing are exact, so colours are compared
 * exactly; the transformed-text comparison allows 2 differing pixels for rounding of
 * the translated stroke end points.
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

void gks_alloc_fail_after(long n);

static const Glimit vp40 = { 0, 40, 0, 40 };

/* GKS open, PNG workstation 1 (40x40 pixels, NDC unit square) active, WC = NDC, solid
 * fills, colours 2 red, 3 green, 4 blue. */
static void open_png40(const char *file)
{
    reset_gks();
    unlink(file);
    gopen_gks(NULL, 0);
    gset_fill_int_style(GSTYLE_SOLID);
    gopen_ws(1, file, GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_vp(1, &vp40);
    const Gcolr_rep c[3] = { { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { 0, 0, 1 } } };
    for (int i = 0; i < 3; i++)
        gset_colr_rep(1, 2 + i, &c[i]);
}

static void square(double x0, double y0, double s, int colr)
{
    Gpoint p[4] = { { x0, y0 }, { x0 + s, y0 }, { x0 + s, y0 + s }, { x0, y0 + s } };
    Gpoint_list l = { 4, p };
    gset_fill_colr_ind(colr);
    gfill_area(&l);
}

static void finish(const char *file, image *img)
{
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    if (n_captured)
        fail_msg("%d errors, first %d in function %d", n_captured, captured[0].err,
                 captured[0].fct);
    assert_true(read_png(file, img));
}

static void assert_px(const image *img, int x, int y, int r, int g, int b)
{
    const unsigned char *p = px(img, x, y);
    if (p[0] != r || p[1] != g || p[2] != b)
        fail_msg("pixel (%d,%d) = %d %d %d, want %d %d %d", x, y, p[0], p[1], p[2], r, g, b);
}

/* Background: the corner pixel (39,39), which no test draws. */
static void assert_bg(const image *img, int x, int y)
{
    const unsigned char *b = px(img, 39, 39);
    assert_px(img, x, y, b[0], b[1], b[2]);
}

static void test_states_and_errors(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    Gop_st st;
    Gint err, name;
    gcreate_seg(7);
    ginq_op_st(&st);
    assert_int_equal(st, GST_SGOP);
    ginq_name_open_seg(&err, &name);
    assert_int_equal(err, 0);
    assert_int_equal(name, 7);
    gcreate_seg(8); /* only in WSAC */
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 3);
    n_captured = 0;
    gdel_seg(7); /* the open segment */
    assert_int_equal(captured[0].err, 125);
    n_captured = 0;
    grename_seg(7, 9); /* renaming the open segment renames what is open */
    ginq_name_open_seg(&err, &name);
    assert_int_equal(name, 9);
    gclose_seg();
    ginq_op_st(&st);
    assert_int_equal(st, GST_WSAC);
    ginq_name_open_seg(&err, &name);
    assert_int_equal(err, 4);

#define EXPECT(call, e)                                                                  \
    do {                                                                                 \
        n_captured = 0;                                                                  \
        call;                                                                            \
        assert_int_equal(n_captured, 1);                                                 \
        assert_int_equal(captured[0].err, (e));                                          \
    } while (0)
    EXPECT(gcreate_seg(0), 120);
    EXPECT(gcreate_seg(-3), 120);
    EXPECT(gcreate_seg(9), 121);
    EXPECT(grename_seg(9, 0), 120);
    EXPECT(grename_seg(5, 6), 122);
    gcreate_seg(10);
    gclose_seg();
    EXPECT(grename_seg(9, 10), 121);
    EXPECT(gdel_seg(11), 122);
    EXPECT(gset_seg_pri(9, 1.5), 126);
    EXPECT(gset_seg_pri(9, -0.1), 126);
    EXPECT(gset_vis(11, GSEG_VIS), 122);
    EXPECT(gset_vis(9, (Gseg_vis)7), 2000);
    EXPECT(gset_highl(0, GSEG_HIGHL), 120);
    EXPECT(gset_det(11, GSEG_DET), 122);
    EXPECT(gdel_seg_ws(2, 9), 25);
    EXPECT(gdel_seg_ws(1, 11), 123);

    /* attributes round trip; errors leave them unchanged */
    const Gtran_matrix3 m = { { 2, 0, 0, 0.25 }, { 0, 1, 0, -0.5 }, { 0, 0, 1, 0.125 } };
    n_captured = 0;
    gset_seg_tran3(9, m);
    gset_vis(9, GSEG_INVIS);
    gset_highl(9, GSEG_HIGHL);
    gset_seg_pri(9, 0.75);
    gset_det(9, GSEG_DET);
    assert_int_equal(n_captured, 0);
    Gseg_attrs3 a;
    ginq_seg_attrs3(9, &err, &a);
    assert_int_equal(err, 0);
    assert_int_equal(a.seg_name, 9);
    assert_memory_equal(a.tran_matrix, m, sizeof m);
    assert_int_equal(a.vis, GSEG_INVIS);
    assert_int_equal(a.highl, GSEG_HIGHL);
    assert_true(a.pri == 0.75);
    assert_int_equal(a.det, GSEG_DET);
    ginq_seg_attrs3(11, &err, &a);
    assert_int_equal(err, 122);
    const Gtran_matrix m2 = { { 1, 0, 0.5 }, { 0, 3, 0 } };
    gset_seg_tran(9, m2);
    ginq_seg_attrs3(9, &err, &a);
    assert_true(a.tran_matrix[0][3] == 0.5 && a.tran_matrix[1][1] == 3 &&
                a.tran_matrix[2][2] == 1 && a.tran_matrix[0][2] == 0);

    Gint names[4], len;
    Gint_list l = { 0, names };
    ginq_set_seg_names(4, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 2);
    assert_int_equal(names[0], 9);
    assert_int_equal(names[1], 10);
    ginq_set_assoc_wss(9, 4, 0, &err, &l, &len);
    assert_int_equal(len, 1);
    assert_int_equal(names[0], 1);
    ginq_set_seg_names_ws(1, 4, 0, &err, &l, &len);
    assert_int_equal(len, 2);

    /* DELETE SEGMENT FROM WORKSTATION of its only workstation deletes the segment */
    n_captured = 0;
    gdel_seg_ws(1, 10);
    assert_int_equal(n_captured, 0);
    ginq_set_seg_names(4, 0, &err, &l, &len);
    assert_int_equal(len, 1);
    /* CLEAR WORKSTATION removes the segments stored on it */
    gclear_ws(1, GFLAG_ALWAYS);
    ginq_set_seg_names(4, 0, &err, &l, &len);
    assert_int_equal(len, 0);

    /* storage overflow at CREATE SEGMENT: 301, still WSAC, nothing created */
    gks_alloc_fail_after(1);
    EXPECT(gcreate_seg(20), 301);
    gks_alloc_fail_after(0);
    ginq_op_st(&st);
    assert_int_equal(st, GST_WSAC);
    ginq_set_seg_names(4, 0, &err, &l, &len);
    assert_int_equal(len, 0);
    reset_gks();
}

/* A segment moved by SET SEGMENT TRANSFORMATION appears moved after UPDATE (PERFORM);
 * a primitive outside segments is lost by the regeneration, as ISO 7942 says. */
static void test_transform_regenerates(void **u)
{
    (void)u;
    open_png40("t_seg_tran.png");
    gcreate_seg(1);
    square(0.1, 0.1, 0.2, 2); /* pixels 4..11 */
    gclose_seg();
    square(0.6, 0.6, 0.2, 3); /* not in a segment */
    const Gtran_matrix3 m = { { 1, 0, 0, 0.5 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(1, m);
    Gint err;
    Gdefer_mode dm;
    Girg_mode im;
    Gdisp_space_empty de;
    Gnew_frame_nec_upd nf;
    ginq_ws_defer_upd_sts(1, &err, &dm, &im, &de, &nf);
    assert_int_equal(nf, GNEW_YES); /* implicit regeneration suppressed by default */
    gupd_ws(1, GFLAG_PERFORM);
    ginq_ws_defer_upd_sts(1, &err, &dm, &im, &de, &nf);
    assert_int_equal(nf, GNEW_NO);
    image img;
    finish("t_seg_tran.png", &img);
    assert_bg(&img, 8, 8);       /* old place: background */
    assert_px(&img, 28, 8, 255, 0, 0);    /* moved by 0.5 = 20 pixels */
    assert_px(&img, 27, 7, 255, 0, 0);
    assert_bg(&img, 32, 8);      /* right edge: pixels 24..31 */
    assert_bg(&img, 28, 28);     /* the non-segment square is gone */
    free(img.rgb);
}

/* Higher priority is drawn over lower after REDRAW ALL SEGMENTS, whatever the creation
 * order; before it, the later primitive covers the earlier one. */
static void test_priority(void **u)
{
    (void)u;
    open_png40("t_seg_pri.png");
    gcreate_seg(1);
    square(0.2, 0.2, 0.4, 2); /* red */
    gclose_seg();
    gcreate_seg(2);
    square(0.4, 0.4, 0.4, 4); /* blue, overlapping */
    gclose_seg();
    gset_seg_pri(1, 0.9);
    gset_seg_pri(2, 0.1);
    gredraw_all_seg_ws(1);
    image img;
    finish("t_seg_pri.png", &img);
    assert_px(&img, 20, 20, 255, 0, 0); /* overlap: red on top */
    assert_px(&img, 10, 10, 255, 0, 0);
    assert_px(&img, 28, 28, 0, 0, 255);
    free(img.rgb);
}

/* With implicit regeneration allowed, SET VISIBILITY takes effect at once. */
static void test_visibility_immediate(void **u)
{
    (void)u;
    open_png40("t_seg_vis.png");
    gset_defer_st(1, GDEFER_ASAP, GIRG_ALLOWED);
    gcreate_seg(1);
    square(0.1, 0.1, 0.3, 2);
    gclose_seg();
    gcreate_seg(2);
    gset_vis(2, GSEG_INVIS); /* an invisible open segment: stored, not drawn */
    square(0.5, 0.5, 0.3, 3);
    gclose_seg();
    gset_vis(1, GSEG_INVIS);
    image img;
    finish("t_seg_vis.png", &img);
    assert_bg(&img, 8, 8);
    assert_bg(&img, 26, 26);
    free(img.rgb);

    open_png40("t_seg_vis2.png");
    gset_defer_st(1, GDEFER_ASAP, GIRG_ALLOWED);
    gcreate_seg(2);
    gset_vis(2, GSEG_INVIS);
    square(0.5, 0.5, 0.3, 3);
    gclose_seg();
    gset_vis(2, GSEG_VIS); /* now it appears */
    finish("t_seg_vis2.png", &img);
    assert_px(&img, 26, 26, 0, 255, 0);
    free(img.rgb);
}

/* TEXT, hatch-free pattern-free areas and cell arrays in a segment: the regenerated,
 * translated picture equals the picture drawn directly at the translated place. */
static void draw_mixed(double dx)
{
    gset_char_ht(0.08);
    gset_text_colr_ind(3);
    Gpoint tp = { 0.05 + dx, 0.6 };
    gtext(&tp, "GKS");
    Gint cells[4] = { 2, 3, 4, 2 };
    Gpat_rep ca = { { 2, 2 }, cells };
    Grect r = { { 0.05 + dx, 0.05 }, { 0.45 + dx, 0.45 } };
    gcell_array(&r, &ca);
}

static void test_text_and_cells_replayed(void **u)
{
    (void)u;
    open_png40("t_seg_direct.png");
    draw_mixed(0.25);
    image want;
    finish("t_seg_direct.png", &want);

    open_png40("t_seg_replay.png");
    gcreate_seg(3);
    draw_mixed(0.0);
    gclose_seg();
    const Gtran_matrix m = { { 1, 0, 0.25 }, { 0, 1, 0 } };
    gset_seg_tran(3, m);
    gupd_ws(1, GFLAG_PERFORM);
    image got;
    finish("t_seg_replay.png", &got);
    assert_int_equal(got.w, want.w);
    int diff = 0, lit = 0;
    for (int i = 0; i < got.w * got.h * 3; i++) {
        diff += got.rgb[i] != want.rgb[i];
        lit += want.rgb[i] != 0;
    }
    assert_true(lit > 100); /* the picture is not empty */
    if (diff > 6)
        fail_msg("%d channel values differ", diff);
    free(got.rgb);
    free(want.rgb);
}


/* WISS: a segment stored only on the WISS reaches a PNG workstation by ASSOCIATE (stored
 * there, redrawn on regeneration), COPY (drawn once) and INSERT (new primitives, here into
 * an open segment, mapped by the segment and insert transformations). */
static void test_wiss(void **u)
{
    (void)u;
    open_png40("t_wiss.png");
    gdeactivate_ws(1);
    n_captured = 0;
    /* 27: no WISS yet */
    const Gtran_matrix id = { { 1, 0, 0 }, { 0, 1, 0 } };
    gassoc_seg_ws(1, 1);
    assert_int_equal(captured[0].err, 27);
    gopen_ws(2, NULL, GWS_TYPE_WISS);
    gopen_ws(3, NULL, GWS_TYPE_WISS); /* one WISS only */
    assert_int_equal(captured[1].err, 28);
    gactivate_ws(2);
    gcreate_seg(1);
    square(0.1, 0.1, 0.2, 2); /* red, pixels 4..11 */
    gclose_seg();
    gdeactivate_ws(2);
    n_captured = 0;
    gassoc_seg_ws(1, 5); /* no such segment on the WISS */
    gcopy_seg_ws(2, 1);  /* copy onto the WISS itself */
    assert_int_equal(n_captured, 2);
    assert_int_equal(captured[0].err, 124);
    assert_int_equal(captured[1].err, 36);
    n_captured = 0;
    gassoc_seg_ws(1, 1);
    Gint err, names[2], len;
    Gint_list l = { 0, names };
    ginq_set_seg_names_ws(1, 2, 0, &err, &l, &len);
    assert_int_equal(len, 1);
    assert_int_equal(names[0], 1);
    gactivate_ws(1);
    gcreate_seg(2);
    const Gtran_matrix shift = { { 1, 0, 0.5 }, { 0, 1, 0 } };
    ginsert_seg(1, shift); /* a second square at pixels 24..31 */
    gclose_seg();
    ginsert_seg(2, id);
    assert_int_equal(captured[0].err, 124); /* segment 2 is not on the WISS */
    n_captured = 0;
    /* segment 2 holds the inserted primitive: moving it moves the copy only */
    const Gtran_matrix up = { { 1, 0, 0 }, { 0, 1, 0.5 } };
    gset_seg_tran(2, up);
    gupd_ws(1, GFLAG_PERFORM);
    image img;
    gdeactivate_ws(1);
    gclose_ws(2);
    gclose_ws(1);
    gclose_gks();
    if (n_captured)
        fail_msg("%d errors, first %d", n_captured, captured[0].err);
    assert_true(read_png("t_wiss.png", &img));
    assert_px(&img, 8, 8, 255, 0, 0);   /* segment 1, associated: redrawn */
    assert_px(&img, 28, 28, 255, 0, 0); /* inserted copy, moved up with segment 2 */
    assert_bg(&img, 28, 8);
    free(img.rgb);

    /* COPY draws the segment once; it is not stored on the workstation */
    open_png40("t_wiss_copy.png");
    gopen_ws(2, NULL, GWS_TYPE_WISS);
    gactivate_ws(2);
    gdeactivate_ws(1);
    gcreate_seg(1);
    square(0.5, 0.5, 0.2, 4);
    gclose_seg();
    gcopy_seg_ws(1, 1);
    ginq_set_seg_names_ws(1, 2, 0, &err, &l, &len);
    assert_int_equal(len, 0);
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    assert_true(read_png("t_wiss_copy.png", &img));
    assert_px(&img, 24, 24, 0, 0, 255);
    free(img.rgb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_states_and_errors),
        cmocka_unit_test(test_transform_regenerates),
        cmocka_unit_test(test_priority),
        cmocka_unit_test(test_visibility_immediate),
        cmocka_unit_test(test_text_and_cells_replayed),
        cmocka_unit_test(test_wiss),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
