/* SPDX-License-Identifier: MIT */
/*
 * test_xform_clip.c -- homogeneous clipping: lines (plane by plane), polylines, polygons with
 * several loops (Sutherland–Hodgman): pieces inside, lengths/areas preserved, the even-odd
 * interior preserved, a triangle through the eye plane under perspective, bad input.
 */
#include "xform_test_util.h"

#include <string.h>

static const double unit_box[6] = { 0, 1, 0, 1, 0, 1 };

static gks_xform_clip box_region(const double box[6], unsigned flags)
{
    gks_xform_clip c;
    gks_xform_clip_init(&c);
    assert_int_equal(gks_xform_clip_add_box(&c, box, flags), 0);
    return c;
}

static int in_box(const double p[3], const double b[6], double tol)
{
    for (int i = 0; i < 3; i++)
        if (p[i] < b[2 * i] - tol || p[i] > b[2 * i + 1] + tol)
            return 0;
    return 1;
}

/* gks_xform_clip_segment on copies of a, b, the clipped part given as the parameters
 * t0 <= t1 of the original segment (homogeneous p(t) = a + t(b − a)), recovered from the
 * moved ends along the coordinate that changes most (an unmoved end: 0 or 1). */
static void clip_line_t(const gks_xform_clip *c, const double a[4], const double b[4],
                        double *t0, double *t1, int *vis)
{
    double p[4], q[4];
    int ma, mb, j = 0;
    memcpy(p, a, sizeof p);
    memcpy(q, b, sizeof q);
    *vis = gks_xform_clip_segment(c, p, q, &ma, &mb);
    for (int i = 1; i < 4; i++)
        if (fabs(b[i] - a[i]) > fabs(b[j] - a[j]))
            j = i;
    const double ab = b[j] - a[j];
    *t0 = ma ? (p[j] - a[j]) / ab : 0.0;
    *t1 = mb ? (q[j] - a[j]) / ab : 1.0;
}

static void test_clip_line(void **state)
{
    (void)state;
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    assert_int_equal(c.n, 6);
    double t0, t1;
    int vis;
    const double a[4] = { -1, 0.5, 0.5, 1 }, b[4] = { 2, 0.5, 0.5, 1 };
    clip_line_t(&c, a, b, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 1.0 / 3, 1e-15);
    XT_NEAR(t1, 2.0 / 3, 1e-15);
    /* the same segment with w = 2 (homogeneous scaling does not change the result) */
    const double a2[4] = { -2, 1, 1, 2 }, b2[4] = { 4, 1, 1, 2 };
    clip_line_t(&c, a2, b2, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 1.0 / 3, 1e-15);
    XT_NEAR(t1, 2.0 / 3, 1e-15);
    /* fully outside; touching a corner in one point; a zero-length segment inside */
    const double o0[4] = { 2, 2, 0.5, 1 }, o1[4] = { 3, 0.5, 0.5, 1 };
    clip_line_t(&c, o0, o1, &t0, &t1, &vis);
    assert_false(vis);
    /* touching the corner (0, 1): plane by plane, the segment keeps that one point */
    const double k0[4] = { -0.5, 0.5, 0.5, 1 }, k1[4] = { 0.5, 1.5, 0.5, 1 };
    clip_line_t(&c, k0, k1, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 0.5, 0);
    XT_NEAR(t1, 0.5, 0);
    const double z0[4] = { 0.5, 0.5, 0.5, 1 };
    clip_line_t(&c, z0, z0, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 0, 0);
    XT_NEAR(t1, 1, 0);
    /* flags: only x/y faces: z outside the box is kept */
    gks_xform_clip cxy = box_region(unit_box, GKS_XFORM_CLIP_XY);
    assert_int_equal(cxy.n, 4);
    const double zz0[4] = { 0.5, 0.5, -3, 1 }, zz1[4] = { 0.5, 0.5, 4, 1 };
    clip_line_t(&cxy, zz0, zz1, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 0, 0);
    XT_NEAR(t1, 1, 0);
    gks_xform_clip cf = box_region(unit_box, GKS_XFORM_CLIP_FRONT);   /* z <= 1 only */
    clip_line_t(&cf, zz0, zz1, &t0, &t1, &vis);
    XT_NEAR(t0, 0, 0);
    XT_NEAR(t1, 4.0 / 7, 1e-15);
    gks_xform_clip cb = box_region(unit_box, GKS_XFORM_CLIP_BACK);    /* z >= 0 only */
    clip_line_t(&cb, zz0, zz1, &t0, &t1, &vis);
    XT_NEAR(t0, 3.0 / 7, 1e-15);
    XT_NEAR(t1, 1, 0);
    /* no planes: only w >= wmin. A segment from behind the eye (w = −1) to w = 1 */
    gks_xform_clip cw;
    gks_xform_clip_init(&cw);
    const double e0[4] = { 0, 0, 0, -1 }, e1[4] = { 0, 0, 0, 1 };
    clip_line_t(&cw, e0, e1, &t0, &t1, &vis);
    assert_true(vis);
    assert_true(t0 > 0.5 && t0 < 0.5 + 1e-8);
    cw.wmin = 0;    /* disabled */
    clip_line_t(&cw, e0, e1, &t0, &t1, &vis);
    XT_NEAR(t0, 0, 0);
    /* bad input (gks_xform_clip_polyline reports it as 308): nothing visible, no crash */
    const double nn[4] = { 0, NAN, 0, 1 };
    const double nx[4] = { NAN, 0.5, 0.5, 1 };
    clip_line_t(&c, nn, b, &t0, &t1, &vis);
    assert_false(vis);
    clip_line_t(&c, nx, b, &t0, &t1, &vis);
    assert_false(vis);
    gks_xform_clip bad = c;
    bad.p[0][0] = INFINITY;
    clip_line_t(&bad, a, b, &t0, &t1, &vis);
    assert_false(vis);
    bad = c;
    bad.n = 99;
    clip_line_t(&bad, a, b, &t0, &t1, &vis);
    assert_false(vis);
    bad = c;
    bad.wmin = NAN;
    clip_line_t(&bad, a, b, &t0, &t1, &vis);
    assert_false(vis);
}

/* Huge segments: plane by plane, each crossing from the segment the previous planes have
 * shortened, the segment from x = -1e30 to x = 1e30 keeps its visible part, the clipped
 * coordinates exactly on the planes (Liang-Barsky on the original segment's parameter lost
 * it: t = 1/2 and 1/2 + 5e-31 are one double). A diagonal one keeps its other coordinates
 * (the crossing is interpolated from the nearer end). The pipeline's polylines
 * (tests/core/test_prims.c, test_polyline_huge_coordinates) and the rasterizer's pixel
 * clip (tests/raster/test_raster.c, huge lines) keep them too. */
static void test_clip_line_huge(void **state)
{
    (void)state;
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    double a[4] = { -1e30, 0.5, 0.5, 1 }, b[4] = { 1e30, 0.5, 0.5, 1 };
    int ma, mb;
    assert_int_equal(gks_xform_clip_segment(&c, a, b, &ma, &mb), 1);
    assert_true(ma && mb);
    const double ea[4] = { 0, 0.5, 0.5, 1 }, eb[4] = { 1, 0.5, 0.5, 1 };
    assert_memory_equal(a, ea, sizeof a);
    assert_memory_equal(b, eb, sizeof b);
    /* the same through gks_xform_clip_polyline (the drivers' view clip) */
    const double pl[2][4] = { { -1e30, 0.5, 0.5, 1 }, { 1e30, 0.5, 0.5, 1 } };
    double out[2][4];
    size_t len[1], no, np;
    assert_int_equal(gks_xform_clip_polyline(&c, 2, pl, out, 2, len, 1, &no, &np), 0);
    assert_int_equal(np, 1);
    assert_memory_equal(out[0], ea, sizeof ea);
    assert_memory_equal(out[1], eb, sizeof eb);
    /* diagonal from (-1e30, -1e30) to (0.5, 0.2): y = 0.2 + (x - 0.5)(1e30 + 0.2)/(1e30 +
     * 0.5), which is -0.3 at x = 0 (to 1e-30); from the far end it would come out 0 */
    double d0[4] = { -1e30, -1e30, 0.5, 1 }, d1[4] = { 0.5, 0.2, 0.5, 1 };
    gks_xform_clip cx;
    gks_xform_clip_init(&cx);
    const double xpos[4] = { 1, 0, 0, 0 };
    assert_int_equal(gks_xform_clip_add_plane(&cx, xpos), 0);
    assert_int_equal(gks_xform_clip_segment(&cx, d0, d1, &ma, &mb), 1);
    assert_true(ma && !mb);
    XT_NEAR(d0[0], 0, 0);
    XT_NEAR(d0[1], -0.3, 1e-15);
}

static void test_clip_region_build(void **state)
{
    (void)state;
    gks_xform_clip c;
    gks_xform_clip_init(&c);
    XT_NEAR(c.wmin, GKS_XFORM_WMIN_DEFAULT, 0);
    const double badbox[6] = { 0, 1, 1, 1, 0, 1 }, flat[6] = { 0, 1, 0, 1, 0.5, 0.5 };
    const double nanbox[6] = { 0, 1, 0, 1, NAN, 1 }, zinv[6] = { 0, 1, 0, 1, 1, 0 };
    assert_int_equal(gks_xform_clip_add_box(&c, badbox, GKS_XFORM_CLIP_ALL), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_clip_add_box(&c, nanbox, GKS_XFORM_CLIP_ALL), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_clip_add_box(&c, zinv, GKS_XFORM_CLIP_ALL), GKS_E_RECT_INVALID);
    assert_int_equal(c.n, 0);
    assert_int_equal(gks_xform_clip_add_box(&c, flat, GKS_XFORM_CLIP_ALL), 0);
    assert_int_equal(gks_xform_clip_add_box(&c, unit_box, GKS_XFORM_CLIP_ALL), 0);
    assert_int_equal(c.n, 12);
    assert_int_equal(gks_xform_clip_add_box(&c, unit_box, GKS_XFORM_CLIP_BACK),
                     GKS_E_STORAGE_OVERFLOW);
    const double pl[4] = { 1, 0, 0, 0 }, zero[4] = { 0, 0, 0, 0 }, np[4] = { NAN, 0, 0, 0 };
    assert_int_equal(gks_xform_clip_add_plane(&c, pl), GKS_E_STORAGE_OVERFLOW);
    gks_xform_clip_init(&c);
    assert_int_equal(gks_xform_clip_add_plane(&c, zero), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_clip_add_plane(&c, np), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_clip_add_plane(&c, pl), 0);
    assert_int_equal(c.n, 1);
    /* two boxes = their intersection */
    gks_xform_clip two = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    const double b2[6] = { 0.5, 2, -1, 0.25, -1, 2 };
    assert_int_equal(gks_xform_clip_add_box(&two, b2, GKS_XFORM_CLIP_ALL), 0);
    double t0, t1;
    int vis;
    const double a[4] = { -1, 0.1, 0.5, 1 }, b[4] = { 3, 0.1, 0.5, 1 };
    clip_line_t(&two, a, b, &t0, &t1, &vis);
    assert_true(vis);
    XT_NEAR(t0, 1.5 / 4, 1e-15);
    XT_NEAR(t1, 2.0 / 4, 1e-15);
}

/* The faces of a box given in another space A (here the GKS clipping rectangle in NDC)
 * appended to a region whose points live in space B (homogeneous NPC), given b_to_a: B -> A
 * (the inverse of the A -> B matrix): each face plane q (in A) becomes q * b_to_a, scaled
 * to unit max-norm; valid for points with w > 0 in both spaces. 0 or the error of
 * gks_xform_clip_add_box / gks_xform_clip_add_plane. */
static int add_box_mapped(gks_xform_clip *c, const double box[6], unsigned flags,
                          const double b_to_a[4][4])
{
    gks_xform_clip t;
    gks_xform_clip_init(&t);
    int err = gks_xform_clip_add_box(&t, box, flags);
    for (int i = 0; i < t.n && !err; i++) {
        double q[4], mx = 0.0;
        gks_xform_plane_pullback(t.p[i], b_to_a, q);
        for (int j = 0; j < 4; j++)
            mx = fmax(mx, fabs(q[j]));
        for (int j = 0; j < 4; j++)
            q[j] /= mx;
        err = gks_xform_clip_add_plane(c, q);
    }
    return err;
}

/* A box in NDC (the GKS clipping rectangle) applied in homogeneous NPC through the
 * inverse of a perspective view matrix, checked by sampling segments. */
static void test_clip_box_mapped(void **state)
{
    (void)state;
    xt_traps_on();
    gks_xform_view_map3 mp = {
        .window = { -0.4, 0.6, -0.5, 0.5 }, .viewport = { 0.1, 0.9, 0, 1, 0, 1 },
        .proj_type = GKS_XFORM_PERSPECTIVE, .prp = { 0.2, 0.1, 3 }, .vpd = 0, .bpd = -1,
        .fpd = 1,
    };
    const double vrp[3] = { 0.5, 0.5, 0.5 }, vpn[3] = { 0.3, 0.2, 1 }, vup[3] = { 0, 1, 0 };
    double mo[4][4], mm[4][4], m[4][4], inv[4][4];
    assert_int_equal(gks_xform_eval_view_orientation3(vrp, vpn, vup, mo), 0);
    assert_int_equal(gks_xform_eval_view_mapping3(&mp, mm), 0);
    gks_xform_multiply(mm, mo, m);
    assert_int_equal(gks_xform_invert(m, inv), 0);
    const double ndcbox[6] = { 0.2, 0.7, 0.1, 0.8, 0, 1 };
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    assert_int_equal(add_box_mapped(&c, ndcbox, GKS_XFORM_CLIP_XY, inv), 0);
    assert_int_equal(c.n, 10);
    xt_rng r = { 8080 };
    int seen = 0;
    for (int it = 0; it < 300; it++) {
        double a[4] = { 0, 0, 0, 1 }, b[4] = { 0, 0, 0, 1 }, ha[4], hb[4], t0, t1;
        for (int j = 0; j < 3; j++) {
            a[j] = xt_uniform(&r, -0.3, 1.3);
            b[j] = xt_uniform(&r, -0.3, 1.3);
        }
        gks_xform_apply(m, a, ha);
        gks_xform_apply(m, b, hb);
        int vis;
        clip_line_t(&c, ha, hb, &t0, &t1, &vis);
        /* sample the NDC segment: visible iff in the NDC box (x, y) and in the NPC cube */
        int hits = 0;
        const int S = 400;
        for (int s = 0; s < S; s++) {
            const double t = (s + 0.5) / S;
            double x[3], n[3];
            for (int j = 0; j < 3; j++)
                x[j] = a[j] + t * (b[j] - a[j]);
            double w = gks_xform_point(m, x, n);
            hits += w > 0 && in_box(n, unit_box, 0) && x[0] >= ndcbox[0] && x[0] <= ndcbox[1]
                    && x[1] >= ndcbox[2] && x[1] <= ndcbox[3];
        }
        /* homogeneous t is not NDC t; compare the visible measure in NDC instead */
        double vis_ndc = 0;
        if (vis) {
            double q0[4], q1[4], x0[4], x1[4];
            for (int j = 0; j < 4; j++) {
                q0[j] = ha[j] + t0 * (hb[j] - ha[j]);
                q1[j] = ha[j] + t1 * (hb[j] - ha[j]);
            }
            gks_xform_apply(inv, q0, x0);
            gks_xform_apply(inv, q1, x1);
            double d = 0, dab = 0;
            for (int j = 0; j < 3; j++) {
                d += pow(x1[j] / x1[3] - x0[j] / x0[3], 2);
                dab += pow(b[j] - a[j], 2);
            }
            vis_ndc = sqrt(d / dab);
            seen++;
        }
        XT_NEAR((double)hits / S, vis_ndc, 1.5 / S);
    }
    assert_true(seen > 20);
    xt_traps_off();
}

static void test_polyline_join(void **state)
{
    (void)state;
    xt_traps_on();
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    const double pts[6][4] = { { -1, .5, .5, 1 }, { .5, .5, .5, 1 }, { .5, .8, .5, 1 },
                               { 2, .8, .5, 1 }, { 2, .2, .5, 1 }, { .7, .2, .5, 1 } };
    const double expect[6][4] = { { 0, .5, .5, 1 }, { .5, .5, .5, 1 }, { .5, .8, .5, 1 },
                                  { 1, .8, .5, 1 }, { 1, .2, .5, 1 }, { .7, .2, .5, 1 } };
    double out[11][4];
    size_t len[5], no, np;
    /* counting call */
    assert_int_equal(gks_xform_clip_polyline(&c, 6, pts, NULL, 0, NULL, 0, &no, &np),
                     GKS_E_STORAGE_OVERFLOW);
    assert_int_equal(no, 6);
    assert_int_equal(np, 2);
    assert_int_equal(gks_xform_clip_polyline(&c, 6, pts, NULL, 100, NULL, 100, &no, &np),
                     GKS_E_STORAGE_OVERFLOW);   /* NULL buffers count as capacity 0 */
    assert_int_equal(gks_xform_clip_polyline(&c, 6, pts, out, 10, len, 5, &no, &np), 0);
    assert_int_equal(no, 6);
    assert_int_equal(np, 2);
    assert_int_equal(len[0], 4);
    assert_int_equal(len[1], 2);
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 4; j++)
            XT_NEAR(out[i][j], expect[i][j], 1e-15);
    /* too small: nothing written beyond the capacities */
    for (int i = 0; i < 11; i++)
        out[i][0] = -7;
    len[1] = 77;
    assert_int_equal(gks_xform_clip_polyline(&c, 6, pts, out, 3, len, 1, &no, &np),
                     GKS_E_STORAGE_OVERFLOW);
    assert_int_equal(no, 6);
    XT_NEAR(out[2][1], .8, 0);
    XT_NEAR(out[3][0], -7, 0);
    assert_int_equal(len[1], 77);
    xt_traps_off();
    /* errors */
    assert_int_equal(gks_xform_clip_polyline(&c, 1, pts, out, 10, len, 5, &no, &np),
                     GKS_E_NPOINTS_INVALID);
    double bad[3][4] = { { 0, 0, 0, 1 }, { 0.5, NAN, 0, 1 }, { 1, 1, 1, 1 } };
    assert_int_equal(gks_xform_clip_polyline(&c, 3, (const double (*)[4])bad, out, 10, len, 5,
                                             &no, &np), GKS_E_ARITHMETIC);
    bad[1][1] = INFINITY;
    assert_int_equal(gks_xform_clip_polyline(&c, 3, (const double (*)[4])bad, out, 10, len, 5,
                                             &no, &np), GKS_E_ARITHMETIC);
    /* overflowing magnitudes: an error, not NaN output */
    const double huge[2][4] = { { -1e308, 0.5, 0.5, 1 }, { 1e308, 0.5, 0.5, 1 } };
    int err = gks_xform_clip_polyline(&c, 2, huge, out, 10, len, 5, &no, &np);
    assert_true(err == 0 || err == GKS_E_ARITHMETIC);
    for (size_t i = 0; err == 0 && i < no; i++)
        for (int j = 0; j < 4; j++)
            assert_true(isfinite(out[i][j]));
}

static double seg_len3(const double a[4], const double b[4])
{
    double d = 0;
    for (int i = 0; i < 3; i++) {
        double x = a[i] / a[3] - b[i] / b[3];
        d += x * x;
    }
    return sqrt(d);
}

static void test_polyline_random(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 31337 };
    enum { N = 40 };
    double pts[N][4], out[2 * N][4];
    size_t len[N], no, np;
    for (int it = 0; it < 150; it++) {
        const int inside = it < 20;
        gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
        for (int i = 0; i < N; i++) {
            double w = inside ? 1.0 : xt_uniform(&r, 0.3, 3);
            for (int j = 0; j < 3; j++)
                pts[i][j] = w * (inside ? xt_uniform(&r, 0.05, 0.95) : xt_uniform(&r, -0.7, 1.7));
            pts[i][3] = w;
        }
        assert_int_equal(gks_xform_clip_polyline(&c, N, (const double (*)[4])pts, out, 2 * N,
                                                 len, N, &no, &np), 0);
        if (inside) {   /* unchanged: one piece, same points, same length */
            assert_int_equal(np, 1);
            assert_int_equal(no, N);
            assert_memory_equal(out, pts, sizeof pts);
            continue;
        }
        /* every output point is inside; pieces have >= 2 points */
        size_t sum = 0;
        for (size_t k = 0; k < np; k++) {
            assert_true(len[k] >= 2);
            sum += len[k];
        }
        assert_int_equal(sum, no);
        for (size_t i = 0; i < no; i++) {
            double q[3];
            assert_int_equal(gks_xform_divide(out[i], q), 0);
            assert_true(in_box(q, unit_box, 1e-12));
        }
        /* visible length: pieces vs the per-segment clip, and the per-segment parameter
         * interval vs brute-force sampling of the segment */
        double lp = 0, ls = 0;
        size_t base = 0, runs = 0;
        for (size_t k = 0; k < np; k++) {
            for (size_t i = 1; i < len[k]; i++)
                lp += seg_len3(out[base + i - 1], out[base + i]);
            base += len[k];
        }
        int open = 0;
        for (int i = 0; i + 1 < N; i++) {
            double t0, t1, q0[4], q1[4];
            int vis;
            clip_line_t(&c, pts[i], pts[i + 1], &t0, &t1, &vis);
            int hits = 0;
            const int S = 1000;
            for (int s = 0; s < S; s++) {
                double t = (s + 0.5) / S, h[4], q[3];
                for (int j = 0; j < 4; j++)
                    h[j] = pts[i][j] + t * (pts[i + 1][j] - pts[i][j]);
                for (int j = 0; j < 3; j++)
                    q[j] = h[j] / h[3];
                hits += in_box(q, unit_box, 0);
            }
            XT_NEAR((double)hits / S, vis ? t1 - t0 : 0.0, 1.5 / S);
            if (!vis) {
                open = 0;
                continue;
            }
            for (int j = 0; j < 4; j++) {
                q0[j] = pts[i][j] + t0 * (pts[i + 1][j] - pts[i][j]);
                q1[j] = pts[i][j] + t1 * (pts[i + 1][j] - pts[i][j]);
            }
            ls += seg_len3(q0, q1);
            if (!(open && t0 == 0))
                runs++;
            open = t1 == 1;
        }
        assert_int_equal(runs, np);
        XT_NEAR(lp, ls, 1e-12 * (1 + ls));
    }
}

/* ---- polygons ----------------------------------------------------------------------------- */

/* Even-odd test of (x, y) against loops given as divided 2-D points (x = h0/h3, y = h1/h3). */
static int evenodd(double x, double y, size_t nloops, const size_t *len, const double (*p)[4])
{
    int in = 0;
    size_t base = 0;
    for (size_t l = 0; l < nloops; l++) {
        const size_t n = len[l];
        for (size_t i = 0, j = n - 1; n > 0 && i < n; j = i++) {
            const double xi = p[base + i][0] / p[base + i][3], yi = p[base + i][1] / p[base + i][3];
            const double xj = p[base + j][0] / p[base + j][3], yj = p[base + j][1] / p[base + j][3];
            if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
                in = !in;
        }
        base += n;
    }
    return in;
}

static double shoelace(size_t n, const double (*p)[4])
{
    double a = 0;
    for (size_t i = 0, j = n - 1; i < n; j = i++)
        a += (p[j][0] / p[j][3]) * (p[i][1] / p[i][3]) - (p[i][0] / p[i][3]) * (p[j][1] / p[j][3]);
    return 0.5 * a;
    xt_traps_off();
}

/* Attributes ride along: with attributes that are affine functions of the homogeneous
 * point (what linear interpolation reproduces exactly, up to rounding), every output
 * vertex, kept or new, carries the function's value at its own point. */
static void test_polygon_attr(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 4242 };
    enum { N = 9, NA = 3, CAP = 200 };
    double pts[2 * N][4], at[2 * N][NA], out[CAP][4], oat[CAP][NA];
    size_t len[2] = { N, N }, ol[2], no;
    int moved = 0;
    for (int it = 0; it < 100; it++) {
        gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
        for (int i = 0; i < 2 * N; i++) {
            double w = xt_uniform(&r, 0.5, 2);
            for (int j = 0; j < 3; j++)
                pts[i][j] = w * xt_uniform(&r, -0.7, 1.7);
            pts[i][3] = w;
            at[i][0] = pts[i][0];
            at[i][1] = 2 * pts[i][1] - pts[i][2] + 3 * pts[i][3];
            at[i][2] = -pts[i][3];
        }
        int e = gks_xform_clip_polygon_attr(&c, 2, len, (const double (*)[4])pts, &at[0][0],
                                            NA, NULL, NULL, 0, ol, &no); /* counting call */
        assert_int_equal(e, no ? GKS_E_STORAGE_OVERFLOW : 0);
        size_t want = no;
        assert_int_equal(gks_xform_clip_polygon_attr(&c, 2, len, (const double (*)[4])pts,
                                                     &at[0][0], NA, out, &oat[0][0], CAP, ol,
                                                     &no), 0);
        assert_int_equal(no, want);
        /* the points are those of the clipper without attributes */
        double out0[CAP][4];
        size_t ol0[2], no0;
        assert_int_equal(gks_xform_clip_polygon(&c, 2, len, (const double (*)[4])pts, out0, CAP,
                                                ol0, &no0), 0);
        assert_int_equal(no0, no);
        assert_memory_equal(out0, out, no * sizeof out[0]);
        for (size_t i = 0; i < no; i++) {
            XT_NEAR(oat[i][0], out[i][0], 1e-12);
            XT_NEAR(oat[i][1], 2 * out[i][1] - out[i][2] + 3 * out[i][3], 1e-12);
            XT_NEAR(oat[i][2], -out[i][3], 1e-12);
            moved += out[i][3] != pts[0][3];
        }
    }
    assert_true(moved > 100);
    xt_traps_off();
    /* bad arguments: too many attributes, attributes missing */
    size_t l3 = 3;
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    double big[3 * (GKS_XFORM_CLIP_MAX_ATTR + 1)] = { 0 };
    assert_int_equal(gks_xform_clip_polygon_attr(&c, 1, &l3, (const double (*)[4])pts, big,
                                                 GKS_XFORM_CLIP_MAX_ATTR + 1, out, &oat[0][0],
                                                 CAP, ol, &no), GKS_E_NPOINTS_INVALID);
    assert_int_equal(gks_xform_clip_polygon_attr(&c, 1, &l3, (const double (*)[4])pts, NULL, 2,
                                                 out, &oat[0][0], CAP, ol, &no),
                     GKS_E_NPOINTS_INVALID);
    assert_int_equal(gks_xform_clip_polygon_attr(&c, 1, &l3, (const double (*)[4])pts, big, 2,
                                                 out, NULL, CAP, ol, &no), GKS_E_NPOINTS_INVALID);
}

static void test_polygon_simple(void **state)
{
    (void)state;
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    double out[64][4];
    size_t ol[2], no;
    /* inside: unchanged */
    const double in[4][4] = { { .2, .2, .5, 1 }, { .8, .2, .5, 1 }, { .8, .7, .5, 1 },
                              { .2, .7, .5, 1 } };
    const size_t l4[1] = { 4 };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, in, out, 64, ol, &no), 0);
    assert_int_equal(no, 4);
    assert_int_equal(ol[0], 4);
    assert_memory_equal(out, in, sizeof in);
    /* half outside: [−0.5,0.5]² → [0,0.5]², area 0.25 */
    const double sq[4][4] = { { -.5, -.5, .5, 1 }, { .5, -.5, .5, 1 }, { .5, .5, .5, 1 },
                              { -.5, .5, .5, 1 } };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, sq, out, 64, ol, &no), 0);
    XT_NEAR(shoelace(ol[0], out), 0.25, 1e-15);
    for (size_t i = 0; i < no; i++) {
        double q[3];
        assert_int_equal(gks_xform_divide(out[i], q), 0);
        assert_true(in_box(q, unit_box, 0));
    }
    /* vertices exactly on a clip plane, their neighbour outside: no duplicate vertices */
    const double on[4][4] = { { 0, .2, .5, 1 }, { -.5, .5, .5, 1 }, { 0, .8, .5, 1 },
                              { .5, .5, .5, 1 } };
    const double on_expect[3][4] = { { 0, .2, .5, 1 }, { 0, .8, .5, 1 }, { .5, .5, .5, 1 } };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, on, out, 64, ol, &no), 0);
    assert_int_equal(no, 3);
    assert_memory_equal(out, on_expect, sizeof on_expect);
    /* fully outside loop → 0 points; counting and capacity */
    const double far[3][4] = { { 2, 2, .5, 1 }, { 3, 2, .5, 1 }, { 2, 3, .5, 1 } };
    const size_t l3[1] = { 3 };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l3, far, out, 64, ol, &no), 0);
    assert_int_equal(no, 0);
    assert_int_equal(ol[0], 0);
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, sq, NULL, 0, ol, &no),
                     GKS_E_STORAGE_OVERFLOW);
    assert_int_equal(no, 4);
    for (int i = 0; i < 64; i++)
        out[i][0] = -9;
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, sq, out, 2, ol, &no),
                     GKS_E_STORAGE_OVERFLOW);
    XT_NEAR(out[2][0], -9, 0);
    /* errors */
    assert_int_equal(gks_xform_clip_polygon(&c, 0, l4, sq, out, 64, ol, &no),
                     GKS_E_NPOINTS_INVALID);
    const size_t l2[2] = { 4, 2 };
    const double six[6][4] = { { 0 } };
    assert_int_equal(gks_xform_clip_polygon(&c, 2, l2, six, out, 64, ol, &no),
                     GKS_E_NPOINTS_INVALID);
    double nanp[4][4];
    memcpy(nanp, sq, sizeof nanp);
    nanp[2][2] = NAN;
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, (const double (*)[4])nanp, out, 64, ol,
                                            &no), GKS_E_ARITHMETIC);
    const size_t lhuge[1] = { (size_t)-1 / 2 };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, lhuge, sq, out, 64, ol, &no),
                     GKS_E_NPOINTS_INVALID);
}

/* Huge coordinates: a quad from (-1e30, .2) to (.6, .8) clipped to the unit box is the
 * rectangle [0,.6] x [.2,.8] (area .36) with every vertex on or inside the box within
 * 1e-15 -- interpolating from the far end would put the crossing at the inside vertex,
 * off the plane x = 0 by 0.6. Also the mirror image and a quad reaching +-1e30 in x and y. */
static void test_polygon_huge(void **state)
{
    (void)state;
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    double out[64][4];
    size_t ol[1], no;
    const size_t l4[1] = { 4 };
    const double left[4][4] = { { -1e30, .2, .5, 1 }, { .6, .2, .5, 1 }, { .6, .8, .5, 1 },
                                { -1e30, .8, .5, 1 } };
    const double right[4][4] = { { .4, .2, .5, 1 }, { 1e30, .2, .5, 1 }, { 1e30, .8, .5, 1 },
                                 { .4, .8, .5, 1 } };
    const double all[4][4] = { { -1e30, -1e30, .5, 1 }, { 1e30, -1e30, .5, 1 },
                               { 1e30, 1e30, .5, 1 }, { -1e30, 1e30, .5, 1 } };
    const double *cases[3] = { &left[0][0], &right[0][0], &all[0][0] };
    const double area[3] = { .36, .36, 1.0 };
    /* the same for a polyline: (-1e30,.3) -> (.6,.3) -> (1e30,.7) keeps (0,.3), (.6,.3)
     * and the crossing of x = 1 on the second segment (y = .3 + .4 * .4/(1e30-.6)) */
    const double line[3][4] = { { -1e30, .3, .5, 1 }, { .6, .3, .5, 1 }, { 1e30, .7, .5, 1 } };
    size_t pl[4], npieces;
    assert_int_equal(gks_xform_clip_polyline(&c, 3, line, out, 64, pl, 4, &no, &npieces), 0);
    assert_int_equal(npieces, 1);
    assert_int_equal(no, 3);
    XT_NEAR(out[0][0], 0, 1e-15);
    XT_NEAR(out[0][1], .3, 1e-15);
    XT_NEAR(out[1][0], .6, 0);
    XT_NEAR(out[2][0], 1, 1e-15);
    XT_NEAR(out[2][1], .3, 1e-15);
    for (int k = 0; k < 3; k++) {
        assert_int_equal(gks_xform_clip_polygon(&c, 1, l4, (const double (*)[4])cases[k], out,
                                                64, ol, &no), 0);
        XT_NEAR(shoelace(ol[0], out), area[k], 1e-15);
        for (size_t i = 0; i < no; i++) {
            assert_true(out[i][0] >= -1e-15 && out[i][0] <= 1 + 1e-15);
            assert_true(out[i][1] >= -1e-15 && out[i][1] <= 1 + 1e-15);
        }
    }
}

/* Compare the even-odd interior of the clipped loops with (input interior ∩ region) on a
 * grid of generic points (offsets avoid the boundary lines). Returns mismatches. */
static int compare_evenodd(size_t nl, const size_t *len, const double (*pts)[4],
                           const size_t *ol, const double (*out)[4], const double box[6])
{
    int bad = 0;
    for (int i = 0; i < 157; i++)
        for (int j = 0; j < 149; j++) {
            const double x = -0.6 + 2.2 * (i + 0.3183) / 157, y = -0.6 + 2.2 * (j + 0.4142) / 149;
            const int inr = x >= box[0] && x <= box[1] && y >= box[2] && y <= box[3];
            const int expect = inr && evenodd(x, y, nl, len, pts);
            bad += expect != evenodd(x, y, nl, ol, out);
        }
    return bad;
}

static void test_polygon_evenodd(void **state)
{
    (void)state;
    xt_traps_on();
    /* a pentagram (self-intersecting: its centre is outside under even-odd) plus a square
     * hole loop, clipped by x in [0.3, 1] */
    double pts[9][4];
    for (int k = 0; k < 5; k++) {
        const double a = XT_PI / 2 + k * 4 * XT_PI / 5;
        pts[k][0] = 0.5 + 0.45 * cos(a);
        pts[k][1] = 0.5 + 0.45 * sin(a);
        pts[k][2] = 0.5;
        pts[k][3] = 1;
    }
    const double hole[4][2] = { { .55, .1 }, { .95, .1 }, { .95, .3 }, { .55, .3 } };
    for (int k = 0; k < 4; k++) {
        pts[5 + k][0] = hole[k][0];
        pts[5 + k][1] = hole[k][1];
        pts[5 + k][2] = 0.5;
        pts[5 + k][3] = 1;
    }
    const size_t len[2] = { 5, 4 };
    const double box[6] = { 0.3, 1, 0, 1, 0, 1 };
    gks_xform_clip c = box_region(box, GKS_XFORM_CLIP_ALL);
    double out[128][4];
    size_t ol[2], no;
    assert_int_equal(gks_xform_clip_polygon(&c, 2, len, (const double (*)[4])pts, out, 128,
                                            ol, &no), 0);
    assert_int_equal(compare_evenodd(2, len, (const double (*)[4])pts, ol,
                                     (const double (*)[4])out, box), 0);
    assert_true(evenodd(0.5, 0.5, 2, len, (const double (*)[4])pts) == 0);   /* star centre */

    /* random self-intersecting loops, random boxes, random homogeneous scale per vertex */
    xt_rng r = { 2718 };
    for (int it = 0; it < 200; it++) {
        double p[24][4], o[400][4];   /* loops of up to 10 + 11 points */
        size_t l[2] = { 3 + (size_t)(it % 8), 3 + (size_t)((it / 8) % 9) }, on[2], nout;
        size_t total = l[0] + l[1];
        for (size_t i = 0; i < total; i++) {
            double w = xt_uniform(&r, 0.5, 2);
            p[i][0] = w * xt_uniform(&r, -0.5, 1.5);
            p[i][1] = w * xt_uniform(&r, -0.5, 1.5);
            p[i][2] = w * xt_uniform(&r, 0.2, 0.8);
            p[i][3] = w;
        }
        double b[6] = { xt_uniform(&r, -0.2, 0.4), xt_uniform(&r, 0.6, 1.2),
                        xt_uniform(&r, -0.2, 0.4), xt_uniform(&r, 0.6, 1.2), 0, 1 };
        gks_xform_clip cr = box_region(b, GKS_XFORM_CLIP_ALL);
        int err = gks_xform_clip_polygon(&cr, 2, l, (const double (*)[4])p, o, 400, on, &nout);
        assert_int_equal(err, 0);
        for (size_t i = 0; i < nout; i++) {
            double q[3];
            assert_int_equal(gks_xform_divide(o[i], q), 0);
            assert_true(in_box(q, b, 1e-12));
        }
        int mism = compare_evenodd(2, l, (const double (*)[4])p, on, (const double (*)[4])o, b);
        if (mism != 0) {
            print_error("iteration %d: %d mismatches\n", it, mism);
            fail();
        }
    }
    xt_traps_off();
}

/* A triangle with one vertex behind the PRP under a perspective mapping: clipping in
 * homogeneous coordinates before the division keeps exactly the visible part. */
static void test_polygon_perspective_eye(void **state)
{
    (void)state;
    xt_traps_on();
    gks_xform_view_map3 mp = {
        .window = { -1, 1, -1, 1 }, .viewport = { 0, 1, 0, 1, 0, 1 },
        .proj_type = GKS_XFORM_PERSPECTIVE, .prp = { 0, 0, 5 }, .vpd = 0, .bpd = -5,
        .fpd = 2,
    };
    double m[4][4], inv[4][4];
    assert_int_equal(gks_xform_eval_view_mapping3(&mp, m), 0);
    assert_int_equal(gks_xform_invert(m, inv), 0);
    const double tri[3][3] = { { 0.1, 0.2, 8 }, { -0.5, -0.5, -2 }, { 0.6, -0.3, 0 } };
    double h[3][4];
    for (int i = 0; i < 3; i++) {
        const double p[4] = { tri[i][0], tri[i][1], tri[i][2], 1 };
        gks_xform_apply(m, p, h[i]);
    }
    assert_true(h[0][3] < 0);   /* behind the eye */
    assert_true(h[1][3] > 0 && h[2][3] > 0);
    gks_xform_clip c = box_region(unit_box, GKS_XFORM_CLIP_ALL);
    double out[32][4];
    size_t ol[1], no;
    const size_t l3[1] = { 3 };
    assert_int_equal(gks_xform_clip_polygon(&c, 1, l3, (const double (*)[4])h, out, 32, ol, &no),
                     0);
    assert_true(no >= 3);
    /* every output vertex: w > 0, inside the NPC cube, and back in VRC on the triangle,
     * between the back and front planes */
    const double *A = tri[0], *B = tri[1], *C = tri[2];
    double e1[3], e2[3], nrm[3];
    for (int i = 0; i < 3; i++) {
        e1[i] = B[i] - A[i];
        e2[i] = C[i] - A[i];
    }
    nrm[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nrm[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nrm[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double area2 = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    for (size_t i = 0; i < no; i++) {
        double q[3], v[3], hh[4];
        assert_true(out[i][3] > 0);
        assert_int_equal(gks_xform_divide(out[i], q), 0);
        assert_true(in_box(q, unit_box, 1e-12));
        gks_xform_apply(inv, out[i], hh);
        assert_int_equal(gks_xform_divide(hh, v), 0);
        assert_true(v[2] >= mp.bpd - 1e-9 && v[2] <= mp.fpd + 1e-9);
        /* barycentric coordinates (signed sub-areas along the normal) */
        double bary[3];
        for (int k = 0; k < 3; k++) {
            const double *P = tri[(k + 1) % 3], *Q = tri[(k + 2) % 3];
            double a[3] = { P[0] - v[0], P[1] - v[1], P[2] - v[2] };
            double b[3] = { Q[0] - v[0], Q[1] - v[1], Q[2] - v[2] };
            double cr[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                             a[0] * b[1] - a[1] * b[0] };
            bary[k] = (cr[0] * nrm[0] + cr[1] * nrm[1] + cr[2] * nrm[2]) / (area2 * area2);
        }
        XT_NEAR(bary[0] + bary[1] + bary[2], 1.0, 1e-9);
        for (int k = 0; k < 3; k++)
            assert_true(bary[k] >= -1e-9);
    }
    /* every visible sample of the triangle lands inside the clipped polygon (NPC x, y),
     * and samples behind the eye, which a divide-then-clip pipeline would wrongly draw
     * (vertex A divides to the screen centre), are not visible */
    int visible = 0, behind_in_box = 0;
    for (int i = 0; i <= 60; i++)
        for (int j = 0; i + j <= 60; j++) {
            const double a = (i + 0.1) / 61, b = (j + 0.2) / 61, g = 1 - a - b;   /* g > 0 */
            double p[4] = { 0, 0, 0, 1 }, hp[4], q[3];
            for (int k = 0; k < 3; k++)
                p[k] = g * A[k] + a * B[k] + b * C[k];
            gks_xform_apply(m, p, hp);
            for (int k = 0; k < 3; k++)
                q[k] = hp[k] / hp[3];
            if (hp[3] <= 0) {   /* divided x, y fall on the screen: a divide-first bug */
                const double qxy[3] = { q[0], q[1], 0.5 };
                behind_in_box += in_box(qxy, unit_box, 0);
                continue;
            }
            if (!in_box(q, unit_box, -1e-6))   /* skip samples within 1e-6 of the box */
                continue;
            visible++;
            if (!evenodd(q[0], q[1], 1, ol, (const double (*)[4])out)) {
                print_error("sample (%d,%d) at NPC (%.17g, %.17g, %.17g) w %g not inside\n", i,
                            j, q[0], q[1], q[2], hp[3]);
                fail();
            }
        }
    assert_true(visible > 100);
    assert_true(behind_in_box > 0);   /* the test does exercise the eye-plane case */

    /* view clipping off (x/y only, then nothing but w >= wmin): still w > 0 and finite */
    const unsigned flags[2] = { GKS_XFORM_CLIP_XY, 0 };
    for (int f = 0; f < 2; f++) {
        gks_xform_clip cf;
        gks_xform_clip_init(&cf);
        if (flags[f])
            assert_int_equal(gks_xform_clip_add_box(&cf, unit_box, flags[f]), 0);
        assert_int_equal(gks_xform_clip_polygon(&cf, 1, l3, (const double (*)[4])h, out, 32, ol,
                                                &no), 0);
        assert_true(no >= 3);
        for (size_t i = 0; i < no; i++) {
            double q[3];
            assert_true(out[i][3] >= cf.wmin * (1 - 1e-12));
            assert_int_equal(gks_xform_divide(out[i], q), 0);
            if (flags[f])
                assert_true(q[0] >= -1e-12 && q[0] <= 1 + 1e-12 && q[1] >= -1e-12
                            && q[1] <= 1 + 1e-12);
        }
    }
    xt_traps_off();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clip_line),
        cmocka_unit_test(test_clip_line_huge),
        cmocka_unit_test(test_clip_region_build),
        cmocka_unit_test(test_clip_box_mapped),
        cmocka_unit_test(test_polyline_join),
        cmocka_unit_test(test_polyline_random),
        cmocka_unit_test(test_polygon_simple),
        cmocka_unit_test(test_polygon_attr),
        cmocka_unit_test(test_polygon_huge),
        cmocka_unit_test(test_polygon_evenodd),
        cmocka_unit_test(test_polygon_perspective_eye),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
