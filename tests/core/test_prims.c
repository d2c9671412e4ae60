/* SPDX-License-Identifier: MIT */
/*
 * test_prims.c -- output primitives as the drivers receive them (through the core's test
 * hook): marker clipping by centres, polyline breaking at non-finite points, TEXT (3)
 * strokes (placement, alignment, path, clipping, text plane), FILL AREA SET with a hole and
 * its edges, CELL ARRAY corners and colours, GDP errors, the standard's errors for bad
 * counts, and hostile input (NaN/Inf, 1e30, 10^7 points): never a crash, never a
 * non-finite coordinate at a driver.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "prim_capture.h"
#include "core_util.h"
#include "png_util.h"
#include "cap_fixture.h"

/* ------------------------------------------------------------------ POLYMARKER */
static void test_markers_clipped_by_centre(void **state)
{
    (void)state;
    Gpoint p[4] = { { 0.2, 0.3 }, { 1.5, 0.5 }, { 0.7, 0.8 }, { NAN, 0.5 } };
    Gpoint_list l = { 4, p };
    gpolymarker(&l);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    const gks_prim *r = &cap.rec[0].p;
    assert_int_equal(r->kind, GKS_PRIM_POLYMARKER);
    assert_int_equal(r->n_points, 2); /* (1.5, .5) outside, NaN dropped */
    assert_true(fabs(r->pts[0].x - 0.2) < 1e-15 && fabs(r->pts[0].y - 0.3) < 1e-15);
    assert_true(fabs(r->pts[1].x - 0.7) < 1e-15 && fabs(r->pts[1].y - 0.8) < 1e-15);
    /* Clipping off: the centre outside the viewport survives (the ws window still clips). */
    gset_clip_ind(GIND_NO_CLIP);
    cap.n = 0;
    gpolymarker(&l);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_points, 3);
    /* A viewport: centres are mapped and clipped against it. */
    gset_clip_ind(GIND_CLIP);
    Glimit w = { 0, 10, 0, 10 }, v = { 0.5, 1, 0.5, 1 };
    gset_win(1, &w);
    gset_vp(1, &v);
    gsel_norm_tran(1);
    Gpoint q[3] = { { 5, 5 }, { 10, 10 }, { 10.0001, 5 } };
    Gpoint_list lq = { 3, q };
    cap.n = 0;
    gpolymarker(&lq);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_points, 2); /* the corner (10,10) is inside (closed box) */
    assert_true(fabs(cap.rec[0].pts[0].x - 0.75) < 1e-15);
    assert_true(fabs(cap.rec[0].pts[1].y - 1.0) < 1e-15);
    /* All outside: nothing reaches the driver, no error. */
    Gpoint o[1] = { { -1, -1 } };
    Gpoint_list lo = { 1, o };
    cap.n = 0;
    gpolymarker(&lo);
    expect_no_error();
    assert_int_equal(cap.n, 0);
    assert_false(cap.nonfinite);
}

static void test_marker_errors(void **state)
{
    (void)state;
    Gpoint p[1] = { { 0.5, 0.5 } };
    Gpoint_list l0 = { 0, p }, ln = { 1, NULL };
    gpolymarker(&l0);
    expect_error(100, GFN_PM);
    gpolymarker(&ln);
    expect_error(100, GFN_PM);
    gpolymarker(NULL);
    expect_error(100, GFN_PM);
    Gpoint_list3 l3 = { -5, NULL };
    gpolymarker3(&l3);
    expect_error(100, GFN_PM3);
    assert_int_equal(cap.n, 0);
}

static void test_marker3_z(void **state)
{
    (void)state;
    Glimit3 w = { 0, 1, 0, 1, -1, 1 }, v = { 0, 1, 0, 1, 0, 1 };
    gset_win3(1, &w);
    gset_vp3(1, &v);
    gsel_norm_tran(1);
    Gpoint3 p[3] = { { 0.5, 0.5, 0 }, { 0.5, 0.5, -1 }, { 0.5, 0.5, 1.5 } };
    Gpoint_list3 l = { 3, p };
    gpolymarker3(&l);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_points, 2); /* z = 1.5 is outside the viewport 3 */
    assert_true(fabs(cap.rec[0].pts[0].z - 0.5) < 1e-15);
    assert_true(fabs(cap.rec[0].pts[1].z - 0.0) < 1e-15);
}

/* ------------------------------------------------------------------ POLYLINE */
static void test_polyline_breaks_at_nonfinite(void **state)
{
    (void)state;
    Gpoint p[6] = { { 0.1, 0.1 }, { 0.2, 0.2 }, { INFINITY, 0.3 }, { 0.4, 0.4 },
                    { 0.5, 0.5 }, { 0.6, 0.6 } };
    Gpoint_list l = { 6, p };
    gpolyline(&l);
    expect_no_error();
    assert_int_equal(cap.n, 2);
    assert_int_equal(cap.rec[0].p.n_points, 2);
    assert_int_equal(cap.rec[1].p.n_points, 3);
    assert_true(cap.rec[1].pts[0].x == 0.4 && cap.rec[1].pts[2].y == 0.6);
    assert_false(cap.nonfinite);
}

static void test_polyline_huge_coordinates(void **state)
{
    (void)state;
    Gpoint p[3] = { { -1e30, 0.5 }, { 1e30, 0.5 }, { 0.5, 1e30 } };
    Gpoint_list l = { 3, p };
    gpolyline(&l);
    expect_no_error();
    assert_false(cap.nonfinite);
    assert_true(cap.n >= 1);
    for (int k = 0; k < cap.n; k++)
        for (int i = 0; i < cap.rec[k].p.n_points; i++) {
            const Gpoint3 *q = &cap.rec[k].pts[i];
            assert_true(q->x >= -1e-9 && q->x <= 1 + 1e-9 && q->y >= -1e-9 && q->y <= 1 + 1e-9);
        }
    /* The horizontal line at y = 0.5 is clipped to x in [0, 1]. */
    assert_true(fabs(cap.rec[0].pts[0].x) < 1e-9 && fabs(cap.rec[0].pts[1].x - 1) < 1e-9);
}

/* A continuous polyline crossing the viewport boundary several times keeps its inside
 * parts as separate pieces; inside parts that continue are one piece. */
static void test_polyline_pieces(void **state)
{
    (void)state;
    Gpoint p[5] = { { 0.2, 0.2 }, { 0.4, 0.2 }, { 0.6, 0.2 }, { 1.5, 0.2 }, { 0.8, 0.8 } };
    Gpoint_list l = { 5, p };
    gpolyline(&l);
    assert_int_equal(cap.n, 2);
    assert_int_equal(cap.rec[0].p.n_points, 4); /* .2 .4 .6 then the exit point x = 1 */
    assert_true(cap.rec[0].pts[1].x == 0.4 && cap.rec[0].pts[2].x == 0.6);
    assert_true(fabs(cap.rec[0].pts[3].x - 1) < 1e-12);
    assert_int_equal(cap.rec[1].p.n_points, 2);
    assert_true(cap.rec[0].p.attrs.text == 0);
}

static void test_large_polyline_and_markers(void **state)
{
    (void)state;
    const int n = 10000000;
    Gpoint *p = malloc((size_t)n * sizeof *p);
    assert_non_null(p);
    /* A zig-zag mostly outside the viewport: pieces where it crosses the unit square. */
    for (int i = 0; i < n; i++)
        p[i] = (Gpoint){ (double)(i % 1000) * 0.01 - 4.005,
                         i % 1000 == 999 ? 5.0 : (i & 1) ? 0.5 : 0.6 };
    Gpoint_list l = { n, p };
    gpolyline(&l);
    expect_no_error();
    assert_false(cap.nonfinite);
    /* each period of 1000 points enters the unit square once (the return at y = 5 stays
     * outside): 10^4 pieces of 100 inside points plus the entry and exit points */
    assert_int_equal(cap.n, n / 1000);
    assert_int_equal(cap.rec[0].p.n_points, 102);
    cap.n = 0;
    cap.total_points = 0;
    gpolymarker(&l);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    assert_int_equal((long)cap.total_points, (long)(n / 1000) * 100); /* x in (0, 1) */
    free(p);
}

/* ------------------------------------------------------------------ TEXT */
static void bbox(double b[4])
{
    b[0] = b[2] = INFINITY;
    b[1] = b[3] = -INFINITY;
    for (int k = 0; k < cap.n && k < CAP_MAX_PRIMS; k++)
        for (int i = 0; i < cap.rec[k].p.n_points; i++) {
            const Gpoint3 *q = &cap.rec[k].pts[i];
            b[0] = dmin(b[0], q->x); b[1] = dmax(b[1], q->x);
            b[2] = dmin(b[2], q->y); b[3] = dmax(b[3], q->y);
        }
}

static void test_text_strokes_in_extent(void **state)
{
    (void)state;
    gset_char_ht(0.1);
    Gtext_align al = { GHOR_CTR, GVERT_HALF };
    gset_text_align(&al);
    gset_text_colr_ind(2);
    Gpoint pos = { 0.5, 0.5 };
    gtext(&pos, "HELLO");
    expect_no_error();
    assert_true(cap.n >= 5);
    for (int k = 0; k < cap.n; k++) {
        assert_int_equal(cap.rec[k].p.kind, GKS_PRIM_POLYLINE);
        assert_int_equal(cap.rec[k].p.attrs.text, 1);
        assert_true(cap.rec[k].p.n_points >= 2);
        /* text colour 2 on the null workstation: index 2 is not defined there -> 1 black */
        assert_true(same_rgb(cap.rec[k].p.colour, (Grgb){ 0, 0, 0 }));
    }
    double b[4];
    bbox(b);
    Gint err;
    Gtext_extent ex;
    ginq_text_extent(1, &pos, "HELLO", &err, &ex);
    assert_int_equal(err, 0);
    /* Strokes lie within the extent rectangle (axis-aligned here). */
    assert_true(b[0] >= ex.paral[0].x - 1e-12 && b[1] <= ex.paral[1].x + 1e-12);
    assert_true(b[2] >= ex.paral[0].y - 1e-12 && b[3] <= ex.paral[2].y + 1e-12);
    /* Centred horizontally; the half line (cap/2 above the base line) at y = 0.5: the cap
     * letters span base .. cap = 0.5 -/+ 0.05. */
    assert_true(fabs(0.5 * (ex.paral[0].x + ex.paral[1].x) - 0.5) < 1e-12);
    assert_true(fabs(b[2] - 0.45) < 1e-3 && fabs(b[3] - 0.55) < 1e-3);
    /* The extent's height is the body height (top - bottom = 32 units for cap 21). */
    assert_true(fabs((ex.paral[3].y - ex.paral[0].y) - 0.1 * 32.0 / 21.0) < 1e-12);
}

static void test_text_up_vector_and_path(void **state)
{
    (void)state;
    gset_char_ht(0.05);
    Gvec up = { -1, 0 }; /* text runs upwards (base vector = (0, 1)) */
    gset_char_up_vec(&up);
    Gpoint pos = { 0.5, 0.2 };
    gtext(&pos, "ABC");
    double b[4];
    bbox(b);
    assert_true(b[3] - b[2] > 2 * (b[1] - b[0])); /* taller than wide */
    assert_true(b[2] >= 0.2 - 1e-12);              /* starts at the position */
    assert_true(b[1] <= 0.5 + 1e-12);              /* baseline at x = 0.5, glyphs to its left */
    /* Path DOWN with the default up vector: a column below the position (TOP aligned). */
    up = (Gvec){ 0, 1 };
    gset_char_up_vec(&up);
    gset_text_path(GPATH_DOWN);
    cap.n = 0;
    pos = (Gpoint){ 0.5, 0.9 };
    gtext(&pos, "ABC");
    bbox(b);
    assert_true(b[3] <= 0.9 + 1e-12 && b[2] < 0.9 - 3 * 0.05);
    assert_true(b[3] - b[2] > 2 * (b[1] - b[0]));
    assert_true(fabs(0.5 * (b[0] + b[1]) - 0.5) < 0.02); /* centred on the position */
}

static void test_text_clipped(void **state)
{
    (void)state;
    gset_char_ht(0.2);
    Gpoint pos = { 0.8, 0.5 };
    gtext(&pos, "WWWW"); /* runs far beyond x = 1 */
    assert_true(cap.n > 0);
    double b[4];
    bbox(b);
    assert_true(b[1] <= 1.0 + 1e-12);
    assert_true(b[0] >= 0.8 - 1e-12);
    assert_false(cap.nonfinite);
    /* Entirely outside: nothing. */
    cap.n = 0;
    pos = (Gpoint){ 2, 2 };
    gtext(&pos, "X");
    assert_int_equal(cap.n, 0);
}

static void test_text3_plane(void **state)
{
    (void)state;
    Glimit3 w = { 0, 1, 0, 1, 0, 1 };
    gset_win3(1, &w);
    gset_vp3(1, &w);
    gsel_norm_tran(1);
    gset_char_ht(0.1);
    Gpoint3 pos = { 0.2, 0.3, 0.1 };
    Gvec3 dir[2] = { { 1, 0, 0 }, { 0, 0, 1 } }; /* text plane y = 0.3, up = +z */
    gtext3(&pos, dir, "GKS");
    expect_no_error();
    assert_true(cap.n > 0);
    double zmax = -1;
    for (int k = 0; k < cap.n; k++)
        for (int i = 0; i < cap.rec[k].p.n_points; i++) {
            assert_true(fabs(cap.rec[k].pts[i].y - 0.3) < 1e-12);
            zmax = dmax(zmax, cap.rec[k].pts[i].z);
        }
    assert_true(fabs(zmax - 0.2) < 1e-3); /* cap line 0.1 above the base line z = 0.1 */
    /* Parallel or zero direction vectors: nothing drawn, no error. */
    cap.n = 0;
    Gvec3 par[2] = { { 1, 0, 0 }, { 2, 0, 0 } };
    gtext3(&pos, par, "GKS");
    Gvec3 zero[2] = { { 0, 0, 0 }, { 0, 1, 0 } };
    gtext3(&pos, zero, "GKS");
    expect_no_error();
    assert_int_equal(cap.n, 0);
}

static void test_text_errors(void **state)
{
    (void)state;
    Gpoint pos = { 0.5, 0.5 };
    gtext(&pos, "bad\001char");
    expect_error(101, GFN_TX);
    gtext(&pos, NULL);
    expect_error(101, GFN_TX);
    gtext(&pos, "\xe9t\xe9");
    expect_error(101, GFN_TX);
    Gpoint bad = { NAN, 0.5 };
    gtext(&bad, "NaN position");
    expect_no_error();
    gtext(&pos, "");
    expect_no_error();
    assert_int_equal(cap.n, 0);
}

/* ------------------------------------------------------------------ FILL AREA (SET) */
static void test_fill_area_set_hole_and_edges(void **state)
{
    (void)state;
    Gpoint outer[4] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.9, 0.9 }, { 0.1, 0.9 } };
    Gpoint inner[4] = { { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 }, { 0.4, 0.6 } };
    Gpoint_list loops[2] = { { 4, outer }, { 4, inner } };
    Gpoint_list_list set = { 2, loops };
    gset_fill_int_style(GSTYLE_SOLID);
    gset_edge_flag(GEDGE_ON);
    gset_edgetype(2);
    gset_edgewidth(2.5);
    gset_edge_colr_ind(1);
    gfill_area_set(&set);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    const gks_prim *r = &cap.rec[0].p;
    assert_int_equal(r->kind, GKS_PRIM_FILL_AREA);
    assert_int_equal(r->n_loops, 2);
    assert_int_equal(r->loop_counts[0], 4);
    assert_int_equal(r->loop_counts[1], 4);
    assert_int_equal(r->n_points, 8);
    assert_int_equal(r->attrs.int_style, GSTYLE_SOLID);
    assert_int_equal(r->attrs.edge_flag, 1);
    assert_int_equal(r->attrs.edgetype, 2);
    assert_true(fabs(r->attrs.edgewidth - 2.5) < 1e-15);
    assert_true(cap.rec[0].pts[5].x == 0.6 && cap.rec[0].pts[6].y == 0.6);
    /* FILL AREA carries no edges (GKS-3D edges belong to FILL AREA SET). */
    cap.n = 0;
    Gpoint_list fa = { 4, outer };
    gfill_area(&fa);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.attrs.edge_flag, 0);
    /* Partly outside: clipped to the viewport, the hole outside vanishes. */
    Gpoint big[4] = { { 0.5, 0.5 }, { 1.5, 0.5 }, { 1.5, 1.5 }, { 0.5, 1.5 } };
    Gpoint hole[3] = { { 2, 2 }, { 3, 2 }, { 2, 3 } };
    Gpoint_list l2[2] = { { 4, big }, { 3, hole } };
    Gpoint_list_list s2 = { 2, l2 };
    cap.n = 0;
    gfill_area_set(&s2);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_loops, 1);
    for (int i = 0; i < cap.rec[0].p.n_points; i++)
        assert_true(cap.rec[0].pts[i].x <= 1 + 1e-12 && cap.rec[0].pts[i].y <= 1 + 1e-12);
}

/* FILL AREA 3 maps its points by the diagonal of an axis-aligned normalization
 * (gks_pipe_prim.c, axis_aligned); FILL AREA SET 3 of the same loop by the full matrix
 * rows. Both must give the same NDC3 points bit for bit (signed zeros, subnormals,
 * overflow) and drop the same areas (non-finite points), with clipping off and on. */
static void test_fill_area3_mapping_exact(void **state)
{
    (void)state;
    const double inf = INFINITY;
    const double v[] = { 0.0, -0.0, 5e-324, -5e-324, 0.25, -3, 1e300, -1e300, 1e308, inf, NAN };
    const int nv = (int)(sizeof v / sizeof v[0]);
    const Glimit3 wins[] = { { 0, 1, 0, 1, 0, 1 }, { -2, 2, -1, 3, -0.5, 0.5 },
                             { 0, 1e-3, 0, 1e5, 0, 1 }, { 0, 1, 0, 1, 0, 1 } };
    const Glimit3 vps[] = { { 0, 1, 0, 1, 0, 1 }, { 0, 1, 0, 1, 0, 1 },
                            { 0.25, 0.5, 0, 1, 0.5, 1 }, { -0.0, 1, -0.0, 0.5, -0.0, 1 } };
    gset_fill_int_style(GSTYLE_SOLID);
    int drawn = 0, dropped = 0;
    for (int clip = 0; clip < 2; clip++) {
        gset_clip_ind(clip ? GIND_CLIP : GIND_NO_CLIP);
        for (int w = 0; w < 4; w++) {
            gset_win3(1, &wins[w]);
            gset_vp3(1, &vps[w]);
            gsel_norm_tran(1);
            for (int a = 0; a < nv; a++)
                for (int b = 0; b < nv; b++) {
                    Gpoint3 t[3] = { { v[a], v[b], v[a] }, { v[b], v[a], 0.5 },
                                     { 0.5, -0.0, v[b] } };
                    Gpoint_list3 l = { 3, t };
                    Gpoint_list_list3 set = { 1, &l };
                    cap.n = 0;
                    gfill_area3(&l);
                    int n1 = cap.n;
                    gfill_area_set3(&set);
                    expect_no_error();
                    assert_int_equal(cap.n, 2 * n1);
                    if (n1 == 0) {
                        dropped++;
                        continue;
                    }
                    assert_int_equal(n1, 1);
                    const gks_prim *p = &cap.rec[0].p, *q = &cap.rec[1].p;
                    assert_int_equal(p->n_points, q->n_points);
                    assert_memory_equal(p->pts, q->pts, (size_t)p->n_points * sizeof *p->pts);
                    drawn++;
                }
        }
    }
    assert_true(drawn > 100 && dropped > 100); /* both outcomes were tested */
}

/* The normalization's context is kept between primitives while the current window and
 * viewport 3, clipping indicator and transformation number give the same one
 * (gks_pipe_norm.c): a change of any one of the twelve limits, or of the clipping
 * indicator, between two FILL AREA 3 must reach the next area's NDC3 points. */
static void fill_area3_expect(const Glimit3 *w, const Glimit3 *v)
{
    const Gpoint3 t[3] = { { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0.5 } };
    Gpoint_list3 l = { 3, (Gpoint3 *)t };
    cap.n = 0;
    gfill_area3(&l);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    const gks_prim *p = &cap.rec[0].p;
    assert_int_equal(p->n_points, 3);
    for (int i = 0; i < 3; i++) {
        const double c[3] = { t[i].x, t[i].y, t[i].z };
        const double wl[3][2] = { { w->x_min, w->x_max }, { w->y_min, w->y_max },
                                  { w->z_min, w->z_max } };
        const double vl[3][2] = { { v->x_min, v->x_max }, { v->y_min, v->y_max },
                                  { v->z_min, v->z_max } };
        const double got[3] = { p->pts[i].x, p->pts[i].y, p->pts[i].z };
        for (int k = 0; k < 3; k++) {
            const double s = (vl[k][1] - vl[k][0]) / (wl[k][1] - wl[k][0]);
            assert_true(fabs(got[k] - (vl[k][0] + (c[k] - wl[k][0]) * s)) < 1e-12);
        }
    }
}

static void test_fill_area3_norm_context_fresh(void **state)
{
    (void)state;
    const Glimit3 unit = { 0, 1, 0, 1, 0, 1 };
    gset_fill_int_style(GSTYLE_SOLID);
    for (int k = 0; k < 12; k++) {
        Glimit3 w = unit, v = unit;
        gset_win3(1, &w);
        gset_vp3(1, &v);
        gsel_norm_tran(1);
        fill_area3_expect(&w, &v); /* the context of the unit limits, kept */
        double *lim = k < 6 ? &w.x_min + k : &v.x_min + (k - 6);
        if (k < 6) /* a larger window, a smaller viewport: the points stay inside */
            *lim = k % 2 ? 2.0 : -1.0;
        else
            *lim = k % 2 ? 0.75 : 0.25;
        gset_win3(1, &w);
        gset_vp3(1, &v);
        fill_area3_expect(&w, &v);
    }
    /* the clipping indicator alone: the area reaches x = 2 beyond the viewport */
    const Glimit3 right = { 0, 0.5, 0, 1, 0, 1 };
    gset_win3(2, &unit);
    gset_vp3(2, &right);
    gsel_norm_tran(2);
    const Gpoint3 t[3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 } };
    Gpoint_list3 l = { 3, (Gpoint3 *)t };
    for (int clip = 1; clip >= 0; clip--)
        for (int again = 0; again < 2; again++) {
            gset_clip_ind(clip ? GIND_CLIP : GIND_NO_CLIP);
            cap.n = 0;
            gfill_area3(&l);
            expect_no_error();
            assert_int_equal(cap.n, 1);
            double xmax = 0;
            for (int i = 0; i < cap.rec[0].p.n_points; i++)
                xmax = fmax(xmax, cap.rec[0].p.pts[i].x);
            assert_true(clip ? xmax <= 0.5 : xmax == 1.0);
        }
}

static void test_fill_area_errors_and_hostile(void **state)
{
    (void)state;
    Gpoint p[4] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.9, 0.9 }, { 0.1, 0.9 } };
    Gpoint_list two = { 2, p };
    gfill_area(&two);
    expect_error(100, GFN_FA);
    Gpoint_list loops[2] = { { 4, p }, { 2, p } };
    Gpoint_list_list bad = { 2, loops }, none = { 0, loops };
    gfill_area_set(&bad);
    expect_error(100, GFN_FAS);
    gfill_area_set(&none);
    expect_error(100, GFN_FAS);
    gfill_area_set(NULL);
    expect_error(100, GFN_FAS);
    gfill_area_set3(NULL);
    expect_error(100, GFN_FAS3);
    /* NaN vertex: not drawn, no error; 1e30 vertices: drawn clipped, finite. */
    Gpoint n[3] = { { 0.1, 0.1 }, { NAN, 0.1 }, { 0.5, 0.9 } };
    Gpoint_list ln = { 3, n };
    gfill_area(&ln);
    expect_no_error();
    assert_int_equal(cap.n, 0);
    Gpoint h[4] = { { -1e30, -1e30 }, { 1e30, -1e30 }, { 1e30, 1e30 }, { -1e30, 1e30 } };
    Gpoint_list lh = { 4, h };
    gfill_area(&lh);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    assert_false(cap.nonfinite);
    /* ... exactly: reaching 1e30 on one side, the quad clips to [0,.6] x [.2,.8] (every
     * crossing interpolated from its near end; from the far end it would be off by .6). */
    Gpoint hl[4] = { { -1e30, 0.2 }, { 0.6, 0.2 }, { 0.6, 0.8 }, { -1e30, 0.8 } };
    Gpoint_list lhl = { 4, hl };
    cap.n = 0;
    gfill_area(&lhl);
    assert_int_equal(cap.n, 1);
    double area = 0.0, xmin = 1.0;
    for (int i = 0, m = cap.rec[0].p.n_points, j = m - 1; i < m; j = i++) {
        const Gpoint3 *a = &cap.rec[0].pts[j], *b = &cap.rec[0].pts[i];
        area += a->x * b->y - b->x * a->y;
        if (b->x < xmin)
            xmin = b->x;
    }
    assert_true(fabs(0.5 * fabs(area) - 0.36) < 1e-12);
    assert_true(fabs(xmin) < 1e-12);
    /* Concave, self-intersecting and repeated vertices pass to the driver unchanged. */
    Gpoint bow[6] = { { 0.1, 0.1 }, { 0.9, 0.9 }, { 0.9, 0.9 }, { 0.9, 0.1 }, { 0.1, 0.9 }, { 0.5, 0.5 } };
    Gpoint_list lb = { 6, bow };
    cap.n = 0;
    gfill_area(&lb);
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_points, 6);
}

/* A 10^6-vertex circle: inside (no clipping pass) and half outside (clipped), always
 * finite; the clipped area lies within the viewport. */
static void test_large_fill_area(void **state)
{
    (void)state;
    const int n = 1000000;
    Gpoint *p = malloc((size_t)n * sizeof *p);
    assert_non_null(p);
    /* unit circle by rotation (no libm): step d = 2 pi / n, cos/sin of d by their series */
    const double d = 6.283185307179586 / n;
    const double cd = 1 - d * d / 2 + d * d * d * d / 24, sd = d - d * d * d / 6;
    double c = 1, sn = 0;
    for (int i = 0; i < n; i++) {
        p[i] = (Gpoint){ 0.5 + 0.4 * c, 0.5 + 0.4 * sn };
        double c2 = c * cd - sn * sd;
        sn = sn * cd + c * sd;
        c = c2;
    }
    Gpoint_list l = { n, p };
    gfill_area(&l);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    assert_int_equal(cap.rec[0].p.n_points, n);
    for (int i = 0; i < n; i++)
        p[i].x += 0.5; /* centre (1, 0.5): half outside */
    cap.n = 0;
    gfill_area(&l);
    expect_no_error();
    assert_int_equal(cap.n, 1);
    assert_false(cap.nonfinite);
    assert_true(cap.rec[0].p.n_points > n / 2 - 10 && cap.rec[0].p.n_points < n / 2 + 10);
    for (int i = 0; i < CAP_MAX_PTS && i < cap.rec[0].p.n_points; i++)
        assert_true(cap.rec[0].pts[i].x <= 1.0 + 1e-12);
    free(p);
}

/* ------------------------------------------------------------------ CELL ARRAY, GDP */
static void test_cell_array(void **state)
{
    (void)state;
    gopen_ws(2, "test_prims_cells", GWS_TYPE_PNG);
    gactivate_ws(2);
    Gint c[6] = { 2, 3, 4, 5, 6, 999 };
    Gpat_rep a = { { 3, 2 }, c };
    Grect r = { { 0.1, 0.2 }, { 0.7, 0.4 } };
    cap.n = 0;
    gcell_array(&r, &a);
    expect_no_error();
    assert_int_equal(cap.n, 2); /* null and PNG workstation */
    const cap_prim *pn = cap.rec[0].ws_id == 2 ? &cap.rec[0] : &cap.rec[1];
    const gks_prim *p = &pn->p;
    assert_int_equal(p->kind, GKS_PRIM_CELL_ARRAY);
    assert_int_equal(p->cell_nx, 3);
    assert_int_equal(p->cell_ny, 2);
    assert_true(p->cell_p.x == 0.1 && p->cell_p.y == 0.2);
    assert_true(p->cell_q.x == 0.7 && p->cell_q.y == 0.4);
    assert_true(p->cell_r.x == 0.7 && p->cell_r.y == 0.2); /* end of P's first row */
    assert_int_equal(p->clip, 1);
    assert_true(p->clip_box[0] == 0 && p->clip_box[1] == 1);
    /* PNG colours: 2 red, 3 green, 4 blue, 5 yellow, 6 cyan, 999 -> 1 black */
    assert_true(same_rgb(pn->cells[0], (Grgb){ 1, 0, 0 }));
    assert_true(same_rgb(pn->cells[2], (Grgb){ 0, 0, 1 }));
    assert_true(same_rgb(pn->cells[5], (Grgb){ 0, 0, 0 }));
    Gpat_rep bad = { { 0, 2 }, c };
    gcell_array(&r, &bad);
    expect_error(91, GFN_CA);
    gcell_array(&r, NULL);
    expect_error(91, GFN_CA);
    Gparal par = { { 0, 0, 0 }, { 1, 1, 1 }, { 1, 0, 0 } };
    Gpat_rep neg = { { 2, -1 }, c };
    gcell_array3(&par, &neg);
    expect_error(91, GFN_CA3);
    cap.n = 0;
    gset_clip_ind(GIND_NO_CLIP);
    gcell_array3(&par, &a);
    assert_int_equal(cap.n, 2);
    assert_int_equal(cap.rec[0].p.clip, 0);
    assert_true(cap.rec[0].p.cell_q.z == 1);
    Gparal nan = { { NAN, 0, 0 }, { 1, 1, 1 }, { 1, 0, 0 } };
    cap.n = 0;
    gcell_array3(&nan, &a);
    expect_no_error();
    assert_int_equal(cap.n, 0);
    gdeactivate_ws(2);
    gclose_ws(2);
    remove("test_prims_cells.png");
}

static void test_gdp(void **state)
{
    (void)state;
    Gpoint p[2] = { { 0, 0 }, { 1, 1 } };
    Gpoint_list l = { 2, p }, neg = { -1, p };
    ggdp(&l, 1, NULL);
    expect_error(102, GFN_GDP);
    ggdp(&neg, 1, NULL);
    expect_error(100, GFN_GDP);
    Gpoint_list3 l3 = { 0, NULL };
    ggdp3(&l3, -7, NULL);
    expect_error(102, GFN_GDP3);
    ggdp3(&l3, GGDP_PIE, NULL); /* a GDP of this library (tests/bindings/test_gdp.c) */
    expect_error(100, GFN_GDP3);
    assert_int_equal(cap.n, 0);
    Gint err, len;
    Gint_list gl = { 0, NULL };
    ginq_list_avail_gdps(GWS_TYPE_PNG, 0, 0, &err, &gl, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 5);
}

/* ------------------------------------------------------------------ pixels (PNG ws) */
static int dark(const image *img, int x, int y)
{
    const unsigned char *c = px(img, x, y);
    return c[0] < 128 || c[1] < 128 || c[2] < 128;
}

/* Markers are clipped by their centres: a big marker just outside the viewport leaves no
 * pixel; one just inside is drawn whole (also beyond the viewport). Text strokes are
 * clipped exactly: no pixel outside the viewport (1-pixel lines: tolerance 1 pixel for
 * the pixel holding a clipped end point). */
static void test_clipping_in_pixels(void **state)
{
    (void)state;
    gdeactivate_ws(1);
    gopen_ws(2, "test_prims_clip", GWS_TYPE_PNG);
    gactivate_ws(2);
    Glimit dc = { 0, 64, 0, 64 }, vp = { 0.25, 0.75, 0.25, 0.75 };
    gset_ws_vp(2, &dc);
    gset_vp(1, &vp);
    gsel_norm_tran(1); /* window = unit square -> viewport [16, 48] pixels */
    gset_marker_type(2);
    gset_marker_size(4); /* 28 pixels */
    Gpoint out[1] = { { 1.02, 0.5 } }; /* centre at x = 48.6 px: outside */
    Gpoint_list lo = { 1, out };
    gpolymarker(&lo);
    gupd_ws(2, GFLAG_PERFORM);
    image img;
    assert_true(read_png("test_prims_clip.png", &img));
    int n = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++)
            n += dark(&img, x, y);
    assert_int_equal(n, 0);
    free(img.rgb);
    Gpoint in[1] = { { 0.98, 0.5 } }; /* centre at x = 47.4 px: inside */
    Gpoint_list li = { 1, in };
    gpolymarker(&li);
    gupd_ws(2, GFLAG_PERFORM);
    assert_true(read_png("test_prims_clip.png", &img));
    int right = 0, left = 0;
    for (int x = 49; x < 64; x++)
        right += dark(&img, x, 32);
    for (int x = 30; x < 47; x++)
        left += dark(&img, x, 32);
    assert_true(right > 5 && left > 5);
    free(img.rgb);
    gclear_ws(2, GFLAG_ALWAYS);
    gset_char_ht(0.4);
    Gpoint pos = { 0.6, 0.1 };
    gtext(&pos, "WM"); /* reaches far beyond the viewport on the right and top */
    gupd_ws(2, GFLAG_PERFORM);
    assert_true(read_png("test_prims_clip-002.png", &img) || read_png("test_prims_clip.png", &img));
    int inside = 0, outside = 0;
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            if (!dark(&img, x, y))
                continue;
            if (x >= 15 && x <= 48 && y >= 15 && y <= 48)
                inside++;
            else
                outside++;
        }
    assert_true(inside > 20);
    assert_int_equal(outside, 0);
    free(img.rgb);
    gdeactivate_ws(2);
    gclose_ws(2);
    remove("test_prims_clip.png");
    remove("test_prims_clip-002.png");
}

/* Storage failure inside a primitive: error 300, nothing half-drawn, state unchanged. */
void gks_alloc_fail_after(long n);
static void test_alloc_failure(void **state)
{
    (void)state;
    Gpoint p[4] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.9, 0.9 }, { 0.1, 0.9 } };
    Gpoint_list l = { 4, p };
    int saw300 = 0;
    for (long k = 1; k <= 8; k++) {
        n_captured = 0;
        cap.n = 0;
        gks_alloc_fail_after(k);
        gpolyline(&l);
        gks_alloc_fail_after(0);
        if (n_captured) {
            assert_int_equal(captured[0].err, 300);
            assert_int_equal(cap.n, 0);
            saw300 = 1;
        }
    }
    assert_true(saw300);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_markers_clipped_by_centre, setup, teardown),
        cmocka_unit_test_setup_teardown(test_marker_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_marker3_z, setup, teardown),
        cmocka_unit_test_setup_teardown(test_polyline_breaks_at_nonfinite, setup, teardown),
        cmocka_unit_test_setup_teardown(test_polyline_huge_coordinates, setup, teardown),
        cmocka_unit_test_setup_teardown(test_polyline_pieces, setup, teardown),
        cmocka_unit_test_setup_teardown(test_large_polyline_and_markers, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text_strokes_in_extent, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text_up_vector_and_path, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text_clipped, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text3_plane, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fill_area_set_hole_and_edges, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fill_area3_mapping_exact, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fill_area3_norm_context_fresh, setup, teardown),
        cmocka_unit_test_setup_teardown(test_fill_area_errors_and_hostile, setup, teardown),
        cmocka_unit_test_setup_teardown(test_large_fill_area, setup, teardown),
        cmocka_unit_test_setup_teardown(test_cell_array, setup, teardown),
        cmocka_unit_test_setup_teardown(test_gdp, setup, teardown),
        cmocka_unit_test_setup_teardown(test_clipping_in_pixels, setup, teardown),
        cmocka_unit_test_setup_teardown(test_alloc_failure, setup, teardown),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    cap_free();
    return r;
}
