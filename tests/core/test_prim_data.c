/* SPDX-License-Identifier: MIT */
/*
 * test_prim_data.c -- the PHIGS PLUS primitives with data as drivers receive them (test
 * prim hook): vertex and facet normals through the inverse transpose of a non-uniform
 * normalization and segment transformation, colours by index and RGB, clipping that
 * interpolates vertex colours and normals, the shading methods carried by every
 * primitive, and the error numbers for bad arguments.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#define GKS3D_BUILDING 1
#include "gks_context.h" /* gks_prim_hook, and ws_driver.h */
#undef GKS3D_BUILDING
#include "core_util.h"
#include <math.h>
#include <stdlib.h>

void gks_test_set_prim_hook(gks_prim_hook hook, void *ctx);

/* ------------------------------------------------------------------ capture */
#define DMAX_PRIMS 512
#define DMAX_PTS 64
typedef struct {
    gks_prim p;
    Gpoint3 pts[DMAX_PTS];
    Gvec3 vn[DMAX_PTS];
    Grgb vc[DMAX_PTS];
    int loops[8];
} dprim;

static dprim *rec;
static int n_rec;

static void hook(void *ctx, int ws_id, const gks_prim *p)
{
    (void)ctx;
    if (ws_id != 1 || n_rec >= DMAX_PRIMS) /* workstation 1 only (not a WISS) */
        return;
    dprim *r = &rec[n_rec++];
    memset(r, 0, sizeof *r);
    r->p = *p;
    int n = p->n_points < DMAX_PTS ? p->n_points : DMAX_PTS;
    memcpy(r->pts, p->pts, (size_t)n * sizeof *r->pts);
    r->p.pts = r->pts;
    if (p->vnormals) {
        memcpy(r->vn, p->vnormals, (size_t)n * sizeof *r->vn);
        r->p.vnormals = r->vn;
    }
    if (p->vcolours) {
        memcpy(r->vc, p->vcolours, (size_t)n * sizeof *r->vc);
        r->p.vcolours = r->vc;
    }
    for (int k = 0; k < p->n_loops && k < 8; k++)
        r->loops[k] = p->loop_counts[k];
    r->p.loop_counts = r->loops;
}

static int setup(void **state)
{
    (void)state;
    enter_state(GST_WSAC);
    if (!rec)
        rec = calloc(DMAX_PRIMS, sizeof *rec);
    n_rec = 0;
    gks_test_set_prim_hook(hook, NULL);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    gks_test_set_prim_hook(NULL, NULL);
    reset_gks();
    return 0;
}

static void expect_error(int err, int fct)
{
    if (n_captured != 1 || captured[0].err != err || captured[0].fct != fct)
        fail_msg("got %d errors, first %d (fct %d); want %d (fct %d)", n_captured,
                 n_captured ? captured[0].err : 0, n_captured ? captured[0].fct : -1, err, fct);
    n_captured = 0;
}

static void expect_no_error(void)
{
    if (n_captured)
        fail_msg("unexpected error %d (fct %d)", captured[0].err, captured[0].fct);
}

static void near3(double x, double y, double z, double ex, double ey, double ez, double tol)
{
    if (!(fabs(x - ex) <= tol && fabs(y - ey) <= tol && fabs(z - ez) <= tol))
        fail_msg("(%.17g, %.17g, %.17g) != (%.17g, %.17g, %.17g) within %g", x, y, z, ex, ey,
                 ez, tol);
}

/* unit(v) */
static void unit3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

/* ------------------------------------------------------------------ tests */
/* A triangle in the plane x/10 + y = 1 (WC window x 0..10, y 0..1, z 0..1 onto the unit
 * cube: scale (0.1, 1, 1)). Its WC normal (1, 10, 0)/|.| is perpendicular to the WC edges;
 * in NDC3 the triangle lies in x + y = 1, normal (1, 1, 0)/sqrt 2: the inverse transpose
 * diag(10, 1, 1) maps one to the other. The plain transformation would give (0.1, 10, 0). */
static void test_normals_nonuniform_normalization(void **state)
{
    (void)state;
    Glimit3 w = { 0, 10, 0, 1, 0, 1 }, v = { 0, 1, 0, 1, 0, 1 };
    gset_win3(1, &w);
    gset_vp3(1, &v);
    gsel_norm_tran(1);
    Gpoint3 p[3] = { { 10, 0, 0.2 }, { 0, 1, 0.2 }, { 5, 0.5, 0.8 } };
    double wn[3] = { 1, 10, 0 };
    unit3(wn);
    Gvec3 n[3];
    for (int i = 0; i < 3; i++)
        n[i] = (Gvec3){ wn[0], wn[1], wn[2] };
    Gfacet_data3 fd = { .norm = { wn[0], wn[1], wn[2] } };
    Gfacet_vdata3 vd = { 3, p, NULL, n };
    gfill_area3_data(GFACET_NORM, GVERT_COORD_NORM, GCOLR_INDIRECT, &fd, &vd);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    const gks_prim *r = &rec[0].p;
    assert_int_equal(r->kind, GKS_PRIM_FILL_AREA);
    assert_int_equal(r->n_points, 3);
    assert_non_null(r->vnormals);
    assert_null(r->vcolours);
    assert_true(r->has_fnormal);
    const double s = sqrt(0.5);
    for (int i = 0; i < 3; i++)
        near3(r->vnormals[i].delta_x, r->vnormals[i].delta_y, r->vnormals[i].delta_z, s, s, 0,
              1e-15);
    near3(r->fnormal.delta_x, r->fnormal.delta_y, r->fnormal.delta_z, s, s, 0, 1e-15);
    near3(r->pts[0].x, r->pts[0].y, r->pts[0].z, 1, 0, 0.2, 1e-15);
    /* The normal stays perpendicular to the NDC3 edges. */
    for (int i = 1; i < 3; i++) {
        double e[3] = { r->pts[i].x - r->pts[0].x, r->pts[i].y - r->pts[0].y,
                        r->pts[i].z - r->pts[0].z };
        double d = e[0] * r->fnormal.delta_x + e[1] * r->fnormal.delta_y +
                   e[2] * r->fnormal.delta_z;
        assert_true(fabs(d) < 1e-15);
    }
}

/* Colours: RGB vertex colours pass as given, indices resolve through the colour table, a
 * facet colour replaces the fill colour; no flags: no data. */
static void test_colours(void **state)
{
    (void)state;
    Gcolr_rep c5 = { { 0.25, 0.5, 0.75 } };
    Gcolr_rep white = { { 1, 1, 1 } };
    gset_colr_rep(1, 5, &c5);
    gset_colr_rep(1, 1, &white);
    Gpoint3 p[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gcoval rgb[3] = { { .rgb = { 1, 0, 0 } }, { .rgb = { 0, 1, 0 } }, { .rgb = { 0, 0, 1 } } };
    Gfacet_vdata3 vd = { 3, p, rgb, NULL };
    gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR, GCOLR_RGB, NULL, &vd);
    Gcoval ind[3] = { { .ind = 5 }, { .ind = 1 }, { .ind = 0 } };
    Gfacet_data3 fd = { .colr = { .ind = 5 } };
    vd.colrs = ind;
    gfill_area3_data(GFACET_COLR, GVERT_COORD_COLR, GCOLR_INDIRECT, &fd, &vd);
    vd.colrs = NULL;
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, &vd);
    expect_no_error();
    assert_int_equal(n_rec, 3);
    const gks_prim *a = &rec[0].p, *b = &rec[1].p, *c = &rec[2].p;
    assert_non_null(a->vcolours);
    near3(a->vcolours[1].red, a->vcolours[1].green, a->vcolours[1].blue, 0, 1, 0, 0);
    assert_non_null(b->vcolours);
    near3(b->vcolours[0].red, b->vcolours[0].green, b->vcolours[0].blue, 0.25, 0.5, 0.75, 0);
    near3(b->vcolours[1].red, b->vcolours[1].green, b->vcolours[1].blue, 1, 1, 1, 0);
    near3(b->colour.red, b->colour.green, b->colour.blue, 0.25, 0.5, 0.75, 0);
    assert_null(c->vcolours);
    assert_null(c->vnormals);
    assert_false(c->has_fnormal);
    assert_int_equal(c->attrs.edge_flag, 0);
}

/* Clipping at the viewport interpolates colours and normals at the new vertices: the
 * triangle (0,0.5)-(2,0.5)-(0,0.9) cut at x = 1 gets vertices at the edge midpoints of its
 * first two edges; their colours and (renormalised) normals are the means. */
static void test_clip_interpolates(void **state)
{
    (void)state;
    Gpoint3 p[3] = { { 0, 0.5, 0.5 }, { 2, 0.5, 0.5 }, { 0, 0.9, 0.5 } };
    Gcoval c[3] = { { .rgb = { 0, 0, 0 } }, { .rgb = { 1, 0.5, 0 } }, { .rgb = { 0, 0, 1 } } };
    Gvec3 n[3] = { { 0, 0, 1 }, { 1, 0, 0 }, { 0, 0, 1 } };
    Gfacet_vdata3 vd = { 3, p, c, n };
    gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_RGB, NULL, &vd);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    const gks_prim *r = &rec[0].p;
    assert_int_equal(r->n_points, 4);
    assert_non_null(r->vcolours);
    assert_non_null(r->vnormals);
    int found = 0;
    const double s = sqrt(0.5);
    for (int i = 0; i < 4; i++) {
        if (fabs(r->pts[i].x - 1) < 1e-15 && fabs(r->pts[i].y - 0.5) < 1e-15) {
            found |= 1; /* midpoint of edge 0-1 */
            near3(r->vcolours[i].red, r->vcolours[i].green, r->vcolours[i].blue, 0.5, 0.25, 0,
                  1e-15);
            near3(r->vnormals[i].delta_x, r->vnormals[i].delta_y, r->vnormals[i].delta_z, s, 0,
                  s, 1e-15);
        }
        if (fabs(r->pts[i].x - 1) < 1e-15 && fabs(r->pts[i].y - 0.7) < 1e-15) {
            found |= 2; /* midpoint of edge 1-2 */
            near3(r->vcolours[i].red, r->vcolours[i].green, r->vcolours[i].blue, 0.5, 0.25, 0.5,
                  1e-15);
        }
    }
    assert_int_equal(found, 3);
}

/* The shading methods: defaults none, set, inquired, carried by every primitive. */
static void test_shading_methods(void **state)
{
    (void)state;
    Gint e = -1, f = 0, b = 0;
    ginq_int_shad_meth(&e, &f, &b);
    assert_int_equal(e, 0);
    assert_int_equal(f, GSHAD_NONE);
    assert_int_equal(b, GSHAD_NONE);
    gset_int_shad_meth(GSHAD_NORM);
    gset_back_int_shad_meth(GSHAD_COLR);
    expect_no_error();
    ginq_int_shad_meth(&e, &f, &b);
    assert_int_equal(f, GSHAD_NORM);
    assert_int_equal(b, GSHAD_COLR);
    gset_int_shad_meth(0);
    expect_error(523, GFN_SISM);
    gset_back_int_shad_meth(4);
    expect_error(523, GFN_SBISM);
    ginq_int_shad_meth(&e, &f, &b);
    assert_int_equal(f, GSHAD_NORM);
    assert_int_equal(b, GSHAD_COLR);
    Gpoint3 p[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gpoint_list3 l = { 3, p };
    gfill_area3(&l);
    Gfacet_vdata3 vd = { 3, p, NULL, NULL };
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    assert_int_equal(n_rec, 2);
    for (int i = 0; i < 2; i++) {
        assert_int_equal(rec[i].p.shading[0], GSHAD_NORM);
        assert_int_equal(rec[i].p.shading[1], GSHAD_COLR);
    }
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    expect_no_error();
    ginq_int_shad_meth(&e, &f, &b);
    assert_int_equal(e, 8);
}

/* Bad arguments: the error numbers, nothing drawn. */
static void test_errors(void **state)
{
    (void)state;
    Gpoint3 p[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gcoval c[3] = { { .ind = 1 }, { .ind = -1 }, { .ind = 1 } };
    Gcoval rgb[3] = { { .rgb = { 1, 0, 0 } }, { .rgb = { 0, 1.5, 0 } }, { .rgb = { 0, 0, 1 } } };
    Gfacet_vdata3 vd = { 3, p, NULL, NULL };
    gfill_area3_data(4, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    expect_error(2000, GFN_FA3D);
    gfill_area3_data(GFACET_NONE, -1, GCOLR_INDIRECT, NULL, &vd);
    expect_error(2000, GFN_FA3D);
    gfill_area3_data(GFACET_NONE, GVERT_COORD, 2, NULL, &vd);
    expect_error(2000, GFN_FA3D);
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, NULL);
    expect_error(2003, GFN_FA3D);
    vd.num_vertices = 2;
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    expect_error(100, GFN_FA3D);
    vd.num_vertices = 3;
    vd.points = NULL;
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    expect_error(100, GFN_FA3D);
    vd.points = p;
    gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
    expect_error(2003, GFN_FA3D);
    gfill_area3_data(GFACET_COLR, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    expect_error(2003, GFN_FA3D);
    vd.colrs = c;
    gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR, GCOLR_INDIRECT, NULL, &vd);
    expect_error(92, GFN_FA3D);
    vd.colrs = rgb;
    gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR, GCOLR_RGB, NULL, &vd);
    expect_error(96, GFN_FA3D);
    Gfacet_data3 fd = { .colr = { .rgb = { NAN, 0, 0 } } };
    gfill_area3_data(GFACET_COLR, GVERT_COORD, GCOLR_RGB, &fd, &vd);
    expect_error(96, GFN_FA3D);
    assert_int_equal(n_rec, 0);
    /* Non-finite point or normal: not drawn, no error. */
    Gvec3 n[3] = { { 0, 0, 1 }, { 0, 0, NAN }, { 0, 0, 1 } };
    vd.norms = n;
    gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_RGB, NULL, &vd);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    assert_null(rec[0].p.vnormals); /* a degenerate normal: drawn without vertex normals */
    p[1].x = INFINITY;
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, &vd);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    /* Wrong state. */
    gdeactivate_ws(1);
    gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd);
    expect_error(5, GFN_FA3D);
}


/* Segments: a stored primitive with data redrawn through a non-uniform segment
 * transformation S (x * 2, y * 0.5) gets its normals through S's inverse transpose, then
 * renormalised: n = (1, 1, 0)/sqrt 2 becomes (0.5, 2, 0)/|.|; the points through S. INSERT
 * SEGMENT with a non-uniform matrix likewise (into the open segment and drawn). */
static void test_segment_normals_nonuniform(void **state)
{
    (void)state;
    Gpoint3 p[3] = { { 0.2, 0.6, 0.5 }, { 0.4, 0.4, 0.5 }, { 0.3, 0.5, 0.9 } };
    const double s = sqrt(0.5);
    Gvec3 n[3] = { { s, s, 0 }, { s, s, 0 }, { 0, 0, 1 } };
    Gfacet_data3 fd = { .norm = { s, s, 0 } };
    gopen_ws(2, NULL, GWS_TYPE_WISS);
    gactivate_ws(2);
    gcreate_seg(1);
    gfill_area3_data(GFACET_NORM, GVERT_COORD_NORM, GCOLR_INDIRECT, &fd,
                     &(Gfacet_vdata3){ 3, p, NULL, n });
    gclose_seg();
    expect_no_error();
    assert_int_equal(n_rec, 1);
    Gtran_matrix3 m = { { 2, 0, 0, -0.2 }, { 0, 0.5, 0, 0.1 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(1, m);
    n_rec = 0;
    gredraw_all_seg_ws(1);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    const gks_prim *r = &rec[0].p;
    assert_non_null(r->vnormals);
    assert_true(r->has_fnormal);
    double e[3] = { 0.5, 2, 0 };
    unit3(e);
    near3(r->vnormals[0].delta_x, r->vnormals[0].delta_y, r->vnormals[0].delta_z, e[0], e[1],
          e[2], 1e-15);
    near3(r->vnormals[1].delta_x, r->vnormals[1].delta_y, r->vnormals[1].delta_z, e[0], e[1],
          e[2], 1e-15);
    near3(r->vnormals[2].delta_x, r->vnormals[2].delta_y, r->vnormals[2].delta_z, 0, 0, 1,
          1e-15);
    near3(r->fnormal.delta_x, r->fnormal.delta_y, r->fnormal.delta_z, e[0], e[1], e[2], 1e-15);
    near3(r->pts[0].x, r->pts[0].y, r->pts[0].z, 0.2, 0.4, 0.5, 1e-15);
    /* The normal is perpendicular to the transformed edge p0 -> p1. */
    double ex = r->pts[1].x - r->pts[0].x, ey = r->pts[1].y - r->pts[0].y;
    assert_true(fabs(ex * r->fnormal.delta_x + ey * r->fnormal.delta_y) < 1e-15);
    /* INSERT SEGMENT with a non-uniform matrix: x * 0.5, y * 3 (after S). */
    Gtran_matrix3 ins = { { 0.5, 0, 0, 0.1 }, { 0, 3, 0, -0.8 }, { 0, 0, 1, 0 } };
    gcreate_seg(2);
    n_rec = 0;
    ginsert_seg3(1, ins);
    gclose_seg();
    expect_no_error();
    assert_int_equal(n_rec, 1);
    double e2[3] = { 0.5 / 0.5, 2 / 3.0, 0 }; /* (S then ins)^-T n ~ (0.5 / 0.5, 2 / 3, 0) */
    unit3(e2);
    near3(rec[0].p.vnormals[0].delta_x, rec[0].p.vnormals[0].delta_y,
          rec[0].p.vnormals[0].delta_z, e2[0], e2[1], e2[2], 1e-15);
    /* Segment 2 holds the inserted primitive mapped by S then ins: redrawn unchanged. */
    gset_vis(1, GSEG_INVIS);
    n_rec = 0;
    gredraw_all_seg_ws(1);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    near3(rec[0].p.vnormals[0].delta_x, rec[0].p.vnormals[0].delta_y,
          rec[0].p.vnormals[0].delta_z, e2[0], e2[1], e2[2], 1e-15);
    near3(rec[0].p.pts[0].x, rec[0].p.pts[0].y, rec[0].p.pts[0].z, 0.2, 0.4, 0.5, 1e-15);
}

/* The other primitives with data: their facets as drivers receive them. */
static void test_strip_mesh_sets(void **state)
{
    (void)state;
    Gpoint3 p[6] = { { 0.1, 0.1, 0.5 }, { 0.1, 0.3, 0.5 }, { 0.3, 0.1, 0.5 },
                     { 0.3, 0.3, 0.5 }, { 0.5, 0.1, 0.5 }, { 0.5, 0.3, 0.5 } };
    Gcoval c[6];
    for (int i = 0; i < 6; i++)
        c[i].rgb = (Grgb){ i / 5.0, 0, 1 - i / 5.0 };
    Gfacet_data3 fd[4] = { { .colr = { .ind = 1 } }, { .colr = { .ind = 0 } },
                           { .colr = { .ind = 1 } }, { .colr = { .ind = 0 } } };
    gtri_strip3_data(GFACET_COLR, GVERT_COORD, GCOLR_INDIRECT, fd,
                     &(Gfacet_vdata3){ 6, p, NULL, NULL });
    expect_no_error();
    assert_int_equal(n_rec, 4);
    /* Triangle 1 is (2, 1, 3): reversed, keeping the orientation of triangle 0. */
    assert_true(rec[1].p.pts[0].x == 0.3 && rec[1].p.pts[0].y == 0.1);
    assert_true(rec[1].p.pts[1].x == 0.1 && rec[1].p.pts[1].y == 0.3);
    for (int i = 0; i < 4; i++) {
        const Gpoint3 *q = rec[i].p.pts;
        double z = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
        assert_true(z > 0 || z < 0);
        if (i > 0) {
            const Gpoint3 *q0 = rec[0].p.pts;
            double z0 = (q0[1].x - q0[0].x) * (q0[2].y - q0[0].y) -
                        (q0[1].y - q0[0].y) * (q0[2].x - q0[0].x);
            assert_true((z > 0) == (z0 > 0));
        }
    }
    /* Quadrilateral mesh 3 x 2: two quadrilaterals (i,j), (i+1,j), (i+1,j+1), (i,j+1). */
    n_rec = 0;
    Gpoint3 m[6] = { { 0.1, 0.1, 0.5 }, { 0.2, 0.1, 0.5 }, { 0.3, 0.1, 0.5 },
                     { 0.1, 0.2, 0.5 }, { 0.2, 0.2, 0.5 }, { 0.3, 0.2, 0.5 } };
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD_COLR, GCOLR_RGB, &(Gint_size){ 3, 2 }, NULL,
                     &(Gfacet_vdata3){ 6, m, c, NULL });
    expect_no_error();
    assert_int_equal(n_rec, 2);
    assert_int_equal(rec[1].p.n_points, 4);
    assert_true(rec[1].p.pts[0].x == 0.2 && rec[1].p.pts[2].x == 0.3 && rec[1].p.pts[2].y == 0.2);
    near3(rec[1].p.vcolours[3].red, rec[1].p.vcolours[3].green, rec[1].p.vcolours[3].blue,
          c[4].rgb.red, 0, c[4].rgb.blue, 0);
    /* Set of fill area sets: set 1 has two loops, edges as FILL AREA SET. */
    n_rec = 0;
    gset_edge_flag(GEDGE_ON);
    Gint a0[3] = { 0, 2, 1 }, a1[4] = { 0, 4, 5, 1 }, a2[3] = { 2, 4, 3 };
    Gint_list l0[1] = { { 3, a0 } }, l1[2] = { { 4, a1 }, { 3, a2 } };
    Gint_list_list sets[2] = { { 1, l0 }, { 2, l1 } };
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 2, NULL, sets,
                                &(Gfacet_vdata3){ 6, p, NULL, NULL });
    expect_no_error();
    assert_int_equal(n_rec, 2);
    assert_int_equal(rec[1].p.n_loops, 2);
    assert_int_equal(rec[1].p.loop_counts[0], 4);
    assert_int_equal(rec[1].p.loop_counts[1], 3);
    assert_int_equal(rec[1].p.attrs.edge_flag, 1);
    assert_true(rec[1].p.pts[4].x == 0.3 && rec[1].p.pts[4].y == 0.1);
    /* Fill area set with data: one facet, the loops in order. */
    n_rec = 0;
    Gfacet_vdata3 loops[2] = { { 3, p, NULL, NULL }, { 3, p + 3, NULL, NULL } };
    gfill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, 2, loops);
    expect_no_error();
    assert_int_equal(n_rec, 1);
    assert_int_equal(rec[0].p.n_loops, 2);
    assert_int_equal(rec[0].p.n_points, 6);
    assert_int_equal(rec[0].p.attrs.edge_flag, 1);
}

/* Errors of the other primitives. */
static void test_errors_others(void **state)
{
    (void)state;
    Gpoint3 p[4] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.1, 0.9, 0.5 }, { 0.9, 0.9, 0.5 } };
    Gfacet_vdata3 v4 = { 4, p, NULL, NULL }, v2 = { 2, p, NULL, NULL };
    gtri_strip3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, &v2);
    expect_error(100, GFN_TS3D);
    gtri_strip3_data(GFACET_NORM, GVERT_COORD, GCOLR_RGB, NULL, &v4);
    expect_error(2003, GFN_TS3D);
    gtri_strip3_data(GFACET_NONE, GVERT_COORD, 7, NULL, &v4);
    expect_error(2000, GFN_TS3D);
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, &(Gint_size){ 2, 1 }, NULL, &v4);
    expect_error(100, GFN_QM3D);
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, &(Gint_size){ 3, 2 }, NULL, &v4);
    expect_error(100, GFN_QM3D); /* 6 vertices required, 4 given */
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, NULL, &v4);
    expect_error(2003, GFN_QM3D);
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, &(Gint_size){ 65536, 65536 }, NULL,
                     &v4);
    expect_error(100, GFN_QM3D);
    Gfacet_data3 bad = { .colr = { .ind = -3 } };
    Gfacet_data3 fd1[1] = { { .colr = { .ind = 1 } } };
    gquad_mesh3_data(GFACET_COLR, GVERT_COORD, GCOLR_INDIRECT, &(Gint_size){ 2, 2 }, &bad, &v4);
    expect_error(92, GFN_QM3D);
    gfill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, 0, &v4);
    expect_error(100, GFN_FAS3D);
    gfill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, 2,
                         (Gfacet_vdata3[]){ v4, v2 });
    expect_error(100, GFN_FAS3D);
    gfill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, NULL, 1, NULL);
    expect_error(2003, GFN_FAS3D);
    Gint a[3] = { 0, 1, 4 }, b[2] = { 0, 1 }, c[3] = { 0, 1, -1 };
    Gint_list la = { 3, a }, lb = { 2, b }, lc = { 3, c };
    Gint_list_list sa = { 1, &la }, sb = { 1, &lb }, sc = { 1, &lc }, s0 = { 0, NULL };
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 1, NULL, &sa, &v4);
    expect_error(904, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 1, NULL, &sc, &v4);
    expect_error(904, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 1, NULL, &sb, &v4);
    expect_error(100, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 1, NULL, &s0, &v4);
    expect_error(100, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 0, NULL, &sa, &v4);
    expect_error(100, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_RGB, 1, NULL, NULL, &v4);
    expect_error(2003, GFN_SFA3D);
    gset_of_fill_area_set3_data(GFACET_COLR, GVERT_COORD, GCOLR_INDIRECT, 1, fd1, &sa, &v4);
    expect_error(904, GFN_SFA3D);
    assert_int_equal(n_rec, 0);
}

/* Hostile coordinates: huge but finite points clipped at the viewport never give a driver
 * a non-finite coordinate, normal or colour. */
static void test_hostile_coordinates(void **state)
{
    (void)state;
    const double big = 1.5e308;
    Gpoint3 p[4] = { { -big, 0.5, 0.5 }, { big, 0.4, 0.5 }, { 0.5, big, -big }, { 0.5, 0.5, 0.5 } };
    Gcoval c[4] = { { .rgb = { 1, 0, 0 } }, { .rgb = { 0, 1, 0 } }, { .rgb = { 0, 0, 1 } },
                    { .rgb = { 1, 1, 1 } } };
    Gvec3 n[4] = { { 1e300, 0, 1 }, { 0, -1e300, 1 }, { 0, 0, 1 }, { 1e-300, 0, 0 } };
    for (int k = 0; k < 2; k++) {
        gset_clip_ind(k ? GIND_NO_CLIP : GIND_CLIP);
        gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_RGB, NULL,
                         &(Gfacet_vdata3){ 4, p, c, n });
        gtri_strip3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_RGB, NULL,
                         &(Gfacet_vdata3){ 4, p, c, n });
    }
    expect_no_error();
    assert_true(n_rec >= 4); /* clipped and unclipped, area and strip */
    for (int i = 0; i < n_rec; i++) {
        const gks_prim *r = &rec[i].p;
        for (int j = 0; j < r->n_points && j < DMAX_PTS; j++) {
            assert_true(isfinite(r->pts[j].x) && isfinite(r->pts[j].y) && isfinite(r->pts[j].z));
            if (r->vnormals) {
                double l = hypot(hypot(r->vnormals[j].delta_x, r->vnormals[j].delta_y),
                                 r->vnormals[j].delta_z);
                assert_true(fabs(l - 1) < 1e-12);
            }
            if (r->vcolours)
                assert_true(r->vcolours[j].red >= 0 && r->vcolours[j].red <= 1);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_normals_nonuniform_normalization, setup, teardown),
        cmocka_unit_test_setup_teardown(test_colours, setup, teardown),
        cmocka_unit_test_setup_teardown(test_clip_interpolates, setup, teardown),
        cmocka_unit_test_setup_teardown(test_shading_methods, setup, teardown),
        cmocka_unit_test_setup_teardown(test_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_segment_normals_nonuniform, setup, teardown),
        cmocka_unit_test_setup_teardown(test_strip_mesh_sets, setup, teardown),
        cmocka_unit_test_setup_teardown(test_errors_others, setup, teardown),
        cmocka_unit_test_setup_teardown(test_hostile_coordinates, setup, teardown),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    free(rec);
    return r;
}
