/* SPDX-License-Identifier: MIT */
/*
 * test_xform_matrix.c -- 4x4 utilities, inversion, conversions and composition,
 * EVALUATE / ACCUMULATE TRANSFORMATION MATRIX (3-D and 2-D), normalization and workstation
 * transformations and their checks.
 */
#include "xform_test_util.h"

#include <string.h>

static void apply34(const double m[3][4], const double p[3], double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
}

static void apply23(const double m[2][3], const double p[2], double o[2])
{
    for (int i = 0; i < 2; i++)
        o[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2];
}

static void test_multiply_apply(void **state)
{
    (void)state;
    const double a[4][4] = { { 1, 2, 3, 4 }, { 5, 6, 7, 8 }, { 9, 10, 11, 12 }, { 13, 14, 15, 16 } };
    const double b[4][4] = { { 2, 0, 0, 1 }, { 0, 3, 0, 0 }, { 1, 0, 1, 0 }, { 0, 0, 0, 1 } };
    /* a·b by hand */
    const double e[4][4] = { { 5, 6, 3, 5 }, { 17, 18, 7, 13 }, { 29, 30, 11, 21 },
                             { 41, 42, 15, 29 } };
    double r[4][4], x[4][4];
    gks_xform_multiply(a, b, r);
    xt_mat4_near(r, e, 0.0);
    memcpy(x, a, sizeof x);
    gks_xform_multiply(x, b, x);        /* aliasing */
    xt_mat4_near(x, e, 0.0);
    gks_xform_identity(x);
    gks_xform_multiply(a, x, r);
    xt_mat4_near(r, a, 0.0);

    const double in[4] = { 1, 2, 3, 4 };
    double out[4];
    gks_xform_apply(b, in, out);
    XT_NEAR(out[0], 6, 0); XT_NEAR(out[1], 6, 0); XT_NEAR(out[2], 4, 0); XT_NEAR(out[3], 4, 0);
    const double p[3] = { 1, 2, 3 };
    double o3[3];
    const double persp[4][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 1, 0 } };
    double w = gks_xform_point(persp, p, o3);
    XT_NEAR(w, 3, 0);
    XT_NEAR(o3[0], 1.0 / 3, 1e-16); XT_NEAR(o3[2], 1.0, 0);
    xt_direction(b, p, o3);     /* translation ignored */
    XT_NEAR(o3[0], 2, 0); XT_NEAR(o3[1], 6, 0); XT_NEAR(o3[2], 4, 0);
    const double h[4] = { 2, 4, 6, 2 };
    assert_int_equal(gks_xform_divide(h, o3), 0);
    XT_NEAR(o3[0], 1, 0); XT_NEAR(o3[1], 2, 0); XT_NEAR(o3[2], 3, 0);
    const double h0[4] = { 2, 4, 6, 0 }, hn[4] = { 2, NAN, 6, 1 };
    assert_int_equal(gks_xform_divide(h0, o3), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_divide(hn, o3), GKS_E_ARITHMETIC);
}

static void check_inverse(const double m[4][4], double tol)
{
    double inv[4][4], p[4][4], id[4][4];
    assert_int_equal(gks_xform_invert(m, inv), 0);
    gks_xform_multiply(inv, m, p);
    gks_xform_identity(id);
    xt_mat4_near(p, id, tol);
}

static void test_invert(void **state)
{
    (void)state;
    xt_rng r = { 99 };
    for (int it = 0; it < 1000; it++) {
        double m[4][4];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                m[i][j] = xt_uniform(&r, -10, 10);
        double inv[4][4], p[4][4], id[4][4];
        if (gks_xform_invert(m, inv) != 0)
            continue;                    /* (random near-singular: allowed to refuse) */
        gks_xform_multiply(inv, m, p);
        gks_xform_identity(id);
        xt_mat4_near(p, id, 1e-9);
    }
    /* badly scaled but regular: diagonal and affine with tiny scale, huge translation */
    const double d[4][4] = { { 1e-10, 0, 0, 0 }, { 0, 1e10, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    check_inverse(d, 1e-15);
    const double a[4][4] = { { 1e-7, 0, 0, 1e7 }, { 0, 1e-7, 0, -1e7 }, { 0, 0, 1, 0 },
                             { 0, 0, 0, 1 } };
    check_inverse(a, 1e-9);
    /* the PVT perspective mapping */
    gks_xform_view_map3 pv = {
        .window = { -462.27, -80.95, -4891.85, -94.78 }, .viewport = { 0, 1, 0, 1, 0, 1 },
        .proj_type = GKS_XFORM_PERSPECTIVE, .prp = { -15.044, 1.318, 34.873 }, .vpd = -1.213,
        .bpd = -3.311, .fpd = 15.332,
    };
    double mm[4][4];
    assert_int_equal(gks_xform_eval_view_mapping3(&pv, mm), 0);
    double inv[4][4], back[4][4];
    assert_int_equal(gks_xform_invert(mm, inv), 0);
    assert_int_equal(gks_xform_invert(inv, back), 0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            XT_NEAR(back[i][j], mm[i][j], 1e-12 * (1 + fabs(mm[i][j])));
    /* a point through M and back */
    double q[3], o[3], b2[3];
    xt_map(mm, -200, -1000, 2, q);
    xt_map(inv, q[0], q[1], q[2], o);
    (void)b2;
    XT_NEAR(o[0], -200, 1e-9); XT_NEAR(o[1], -1000, 1e-9); XT_NEAR(o[2], 2, 1e-11);

    /* singular and non-finite → 308, output untouched */
    const double s1[4][4] = { { 1, 2, 3, 4 }, { 2, 4, 6, 8 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    const double s2[4][4] = { { 1, 0, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    double keep[4][4], out[4][4];
    gks_xform_identity(keep);
    memcpy(out, keep, sizeof out);
    assert_int_equal(gks_xform_invert(s1, out), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_invert(s2, out), GKS_E_ARITHMETIC);
    double n1[4][4];
    gks_xform_identity(n1);
    n1[2][1] = NAN;
    assert_int_equal(gks_xform_invert(n1, out), GKS_E_ARITHMETIC);
    n1[2][1] = INFINITY;
    assert_int_equal(gks_xform_invert(n1, out), GKS_E_ARITHMETIC);
    assert_memory_equal(out, keep, sizeof out);
    /* rank-deficient up to rounding: rows of a rotation and a combination of them */
    double rr[4][4] = { { 0.6, 0.8, 0, 0 }, { -0.8, 0.6, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 1 } };
    for (int j = 0; j < 4; j++)
        rr[2][j] = 0.1 * rr[0][j] + 0.7 * rr[1][j];
    assert_int_equal(gks_xform_invert(rr, out), GKS_E_ARITHMETIC);
    double r3[4][4] = { { 0.3, 0.7, 0.11, 0.2 }, { 0.13, -0.5, 0.9, 0.4 }, { 0 },
                        { 0.2, 0.3, 0.5, 0.7 } };
    for (int j = 0; j < 4; j++)
        r3[2][j] = 0.1 * r3[0][j] + 0.7 * r3[1][j];
    assert_int_equal(gks_xform_invert(r3, out), GKS_E_ARITHMETIC);
}

static void test_conversions(void **state)
{
    (void)state;
    const double m23[2][3] = { { 1, 2, 3 }, { 4, 5, 6 } };
    double m34[3][4], m4[4][4];
    gks_xform_mat23_to_mat34(m23, m34);
    const double e34[3][4] = { { 1, 2, 0, 3 }, { 4, 5, 0, 6 }, { 0, 0, 1, 0 } };
    assert_memory_equal(m34, e34, sizeof e34);
    gks_xform_mat34_to_mat4(m34, m4);
    const double e4[4][4] = { { 1, 2, 0, 3 }, { 4, 5, 0, 6 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    assert_memory_equal(m4, e4, sizeof e4);

    /* 3x4 and 2x3 products against the 4x4 product */
    const double a[3][4] = { { 1, 2, 3, 4 }, { 0, 1, 0, -1 }, { 2, 0, 1, 5 } };
    const double b[3][4] = { { 0, 1, 0, 2 }, { 1, 0, 0, 3 }, { 0, 0, 2, 1 } };
    double r34[3][4], a4[4][4], b4[4][4], r4[4][4], c4[4][4];
    gks_xform_mat34_multiply(a, b, r34);
    gks_xform_mat34_to_mat4(a, a4);
    gks_xform_mat34_to_mat4(b, b4);
    gks_xform_multiply(a4, b4, r4);
    gks_xform_mat34_to_mat4(r34, c4);
    xt_mat4_near(c4, r4, 0.0);
    const double c[2][3] = { { 0, -1, 2 }, { 1, 0, 0 } };
    double r23[2][3], p[2] = { 3, 4 }, t[2], u[2], v[2];
    gks_xform_mat23_multiply(m23, c, r23);   /* c first, then m23 */
    apply23(c, p, t);
    apply23(m23, t, u);
    apply23(r23, p, v);
    XT_NEAR(v[0], u[0], 0); XT_NEAR(v[1], u[1], 0);
    double q3[3], q3b[3];
    const double x3[3] = { 0.5, -2, 3 };
    gks_xform_mat34_point(a, x3, q3);
    apply34(a, x3, q3b);
    assert_memory_equal(q3, q3b, sizeof q3);
    XT_NEAR(q3[0], 0.5 - 4 + 9 + 4, 0);
    double id34[3][4], id23[2][3];
    xt_mat34_identity(id34);
    gks_xform_mat34_multiply(a, id34, r34);
    assert_memory_equal(r34, a, sizeof r34);
    xt_mat23_identity(id23);
    gks_xform_mat23_multiply(id23, m23, r23);
    assert_memory_equal(r23, m23, sizeof r23);
}

static void test_compose_and_pullback(void **state)
{
    (void)state;
    xt_traps_on();
    const double seg[3][4] = { { 0.5, 0, 0, 0.1 }, { 0, 0.5, 0, 0.2 }, { 0, 0, 0.5, 0.3 } };
    const double vrp[3] = { 0.5, 0.5, 0.5 }, vpn[3] = { 1, 1, 1 }, vup[3] = { 0, 1, 0 };
    double mo[4][4], mm[4][4], ws[4][4], full[4][4];
    assert_int_equal(gks_xform_eval_view_orientation3(vrp, vpn, vup, mo), 0);
    gks_xform_view_map3 p = {
        .window = { -0.5, 0.5, -0.5, 0.5 }, .viewport = { 0, 1, 0, 1, 0, 1 },
        .proj_type = GKS_XFORM_PERSPECTIVE, .prp = { 0.1, 0, 3 }, .vpd = 0, .bpd = -1,
        .fpd = 1,
    };
    assert_int_equal(gks_xform_eval_view_mapping3(&p, mm), 0);
    const double win[6] = { 0, 1, 0, 1, 0, 1 }, vp[6] = { 10, 810, 0, 600, 0, 1 };
    assert_int_equal(gks_xform_ws_tran3(win, vp, ws), 0);
    xt_compose_pipeline(seg, mo, mm, ws, full);
    const double x[3] = { 0.3, 0.7, 0.2 };
    double s[3], h[4], o[3];
    apply34(seg, x, s);
    double hv[4] = { s[0], s[1], s[2], 1 };
    gks_xform_apply(mo, hv, h);
    gks_xform_apply(mm, h, h);
    gks_xform_apply(ws, h, h);
    double w = gks_xform_point(full, x, o);
    XT_NEAR(w, h[3], 1e-15);
    for (int i = 0; i < 3; i++)
        XT_NEAR(o[i], h[i] / h[3], 1e-12 * (1 + fabs(o[i])));
    /* NULL segment and ws: identity */
    double npc[4][4], pm[4][4];
    xt_compose_pipeline(NULL, mo, mm, NULL, npc);
    gks_xform_multiply(mm, mo, pm);
    xt_mat4_near(npc, pm, 0.0);

    /* plane pull-back: a plane in NPC, pulled back to NDC, has the same sign at the
     * corresponding points */
    const double plane[4] = { 1, -0.5, 0.25, -0.3 };
    double back[4];
    gks_xform_plane_pullback(plane, npc, back);
    xt_rng r = { 5 };
    for (int it = 0; it < 100; it++) {
        double X[4] = { xt_uniform(&r, -1, 2), xt_uniform(&r, -1, 2), xt_uniform(&r, -1, 2), 1 };
        double Y[4];
        gks_xform_apply(npc, X, Y);
        double a = plane[0] * Y[0] + plane[1] * Y[1] + plane[2] * Y[2] + plane[3] * Y[3];
        double b = back[0] * X[0] + back[1] * X[1] + back[2] * X[2] + back[3] * X[3];
        XT_NEAR(a, b, 1e-12);
    }
    xt_traps_off();
}

static void test_eval_tran3(void **state)
{
    (void)state;
    double m[3][4], o[3];
    const double f[3] = { 1, 0, 0 }, sh[3] = { 0, 0, 1 }, ang[3] = { 0, 0, XT_PI / 2 },
                 sc[3] = { 2, 2, 2 };
    assert_int_equal(gks_xform_eval_tran3(f, sh, ang, sc, m), 0);
    /* (2,0,0): scale about (1,0,0) → (3,0,0); rotate 90° about z there → (1,2,0); shift */
    const double p[3] = { 2, 0, 0 };
    apply34(m, p, o);
    XT_NEAR(o[0], 1, 1e-15); XT_NEAR(o[1], 2, 1e-15); XT_NEAR(o[2], 1, 1e-15);
    /* the fixed point moves by the shift only */
    apply34(m, f, o);
    XT_NEAR(o[0], 1, 1e-15); XT_NEAR(o[1], 0, 1e-15); XT_NEAR(o[2], 1, 1e-15);

    /* rotation order: x first, then y. (0,1,0) −Rx(90°)→ (0,0,1) −Ry(90°)→ (1,0,0);
     * y first would give (0,0,1). */
    const double zero[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 }, a2[3] = { XT_PI / 2, XT_PI / 2, 0 };
    assert_int_equal(gks_xform_eval_tran3(zero, zero, a2, one, m), 0);
    const double y[3] = { 0, 1, 0 };
    apply34(m, y, o);
    XT_NEAR(o[0], 1, 1e-15); XT_NEAR(o[1], 0, 1e-15); XT_NEAR(o[2], 0, 1e-15);
    /* y then z: (1,0,0) −Ry(90°)→ (0,0,−1) −Rz(90°)→ (0,0,−1); z first would give (0,0,−1)
     * too, so use (0,0,1): −Ry→ (1,0,0) −Rz→ (0,1,0) (z first: (0,0,1)→(1,0,0)). */
    const double a3[3] = { 0, XT_PI / 2, XT_PI / 2 }, zz[3] = { 0, 0, 1 };
    assert_int_equal(gks_xform_eval_tran3(zero, zero, a3, one, m), 0);
    apply34(m, zz, o);
    XT_NEAR(o[0], 0, 1e-15); XT_NEAR(o[1], 1, 1e-15); XT_NEAR(o[2], 0, 1e-15);
    /* scale before rotation: scale (2,1,1), rotate z 90°: (1,0,0) → (2,0,0) → (0,2,0) */
    const double s2[3] = { 2, 1, 1 }, az[3] = { 0, 0, XT_PI / 2 }, x1[3] = { 1, 0, 0 };
    assert_int_equal(gks_xform_eval_tran3(zero, zero, az, s2, m), 0);
    apply34(m, x1, o);
    XT_NEAR(o[0], 0, 1e-15); XT_NEAR(o[1], 2, 1e-15); XT_NEAR(o[2], 0, 1e-15);

    const double bad[3] = { 0, NAN, 0 }, inf[3] = { INFINITY, 1, 1 };
    double keep[3][4];
    memcpy(keep, m, sizeof keep);
    assert_int_equal(gks_xform_eval_tran3(bad, zero, az, one, m), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_eval_tran3(zero, bad, az, one, m), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_eval_tran3(zero, zero, inf, one, m), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_eval_tran3(zero, zero, az, inf, m), GKS_E_ARITHMETIC);
    const double huge[3] = { 1e308, 1e308, 1e308 }, big[3] = { 1e308, 0, 0 };
    assert_int_equal(gks_xform_eval_tran3(big, zero, az, huge, m), GKS_E_ARITHMETIC);
    assert_memory_equal(m, keep, sizeof keep);
}

static void test_eval_tran2(void **state)
{
    (void)state;
    double m[2][3], o[2];
    const double f[2] = { 1, 1 }, sh[2] = { 1, 0 }, sc[2] = { 2, 3 };
    assert_int_equal(gks_xform_eval_tran(f, sh, XT_PI / 2, sc, m), 0);
    const double p1[2] = { 2, 1 }, p2[2] = { 1, 2 };
    apply23(m, p1, o);           /* scale → (3,1); rotate about (1,1) → (1,3); shift → (2,3) */
    XT_NEAR(o[0], 2, 1e-15); XT_NEAR(o[1], 3, 1e-15);
    apply23(m, p2, o);           /* scale → (1,4); rotate → (−2,1); shift → (−1,1) */
    XT_NEAR(o[0], -1, 1e-15); XT_NEAR(o[1], 1, 1e-15);
    const double n[2] = { NAN, 0 };
    assert_int_equal(gks_xform_eval_tran(n, sh, 0, sc, m), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_eval_tran(f, sh, INFINITY, sc, m), GKS_E_ARITHMETIC);
}

static void test_accumulate(void **state)
{
    (void)state;
    /* 3-D: input = translate by (5,0,0); new = rotate 90° about z at the origin;
     * input first: (1,0,0) → (6,0,0) → (0,6,0) */
    double in[3][4], out[3][4], o[3];
    xt_mat34_identity(in);
    in[0][3] = 5;
    const double zero[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 }, az[3] = { 0, 0, XT_PI / 2 };
    assert_int_equal(gks_xform_accum_tran3(in, zero, zero, az, one, out), 0);
    const double x1[3] = { 1, 0, 0 };
    apply34(out, x1, o);
    XT_NEAR(o[0], 0, 1e-14); XT_NEAR(o[1], 6, 1e-14); XT_NEAR(o[2], 0, 1e-15);
    /* in place, and equal to eval then product */
    double n[3][4], ref[3][4];
    const double f[3] = { 1, 2, 3 }, sh[3] = { -1, 0.5, 2 }, ang[3] = { 0.3, -1.1, 2.2 },
                 sc[3] = { 0.5, 2, -1 };
    assert_int_equal(gks_xform_eval_tran3(f, sh, ang, sc, n), 0);
    gks_xform_mat34_multiply(n, in, ref);
    assert_int_equal(gks_xform_accum_tran3(in, f, sh, ang, sc, in), 0);
    assert_memory_equal(in, ref, sizeof ref);
    in[1][1] = NAN;
    assert_int_equal(gks_xform_accum_tran3(in, f, sh, ang, sc, out), GKS_E_ARITHMETIC);

    /* 2-D: input = scale x by 2 about the origin; new = shift (0,1): (1,1) → (2,1) → (2,2) */
    double i2[2][3], o2[2][3], q[2];
    xt_mat23_identity(i2);
    i2[0][0] = 2;
    const double z2[2] = { 0, 0 }, s1[2] = { 0, 1 }, one2[2] = { 1, 1 }, p[2] = { 1, 1 };
    assert_int_equal(gks_xform_accum_tran(i2, z2, s1, 0.0, one2, o2), 0);
    apply23(o2, p, q);
    XT_NEAR(q[0], 2, 0); XT_NEAR(q[1], 2, 0);
    /* order matters: new = rotate 90° (not commuting with the scale): (1,1) → (2,1) → (−1,2) */
    assert_int_equal(gks_xform_accum_tran(i2, z2, z2, XT_PI / 2, one2, o2), 0);
    apply23(o2, p, q);
    XT_NEAR(q[0], -1, 1e-15); XT_NEAR(q[1], 2, 1e-15);
    i2[0][2] = INFINITY;
    assert_int_equal(gks_xform_accum_tran(i2, z2, z2, 0, one2, o2), GKS_E_ARITHMETIC);
}

static void test_norm_tran3(void **state)
{
    (void)state;
    double m[3][4], o[3];
    const double win[6] = { 0, 10, -5, 5, 0, 2 }, vp[6] = { 0, 1, 0, 0.5, 0.5, 1 };
    assert_int_equal(gks_xform_norm_tran3(win, vp, m), 0);
    const double e[3][4] = { { 0.1, 0, 0, 0 }, { 0, 0.05, 0, 0.25 }, { 0, 0, 0.25, 0.5 } };
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            XT_NEAR(m[i][j], e[i][j], 1e-16);
    const double c[3] = { 10, 5, 2 };
    apply34(m, c, o);
    XT_NEAR(o[0], 1, 1e-15); XT_NEAR(o[1], 0.5, 1e-15); XT_NEAR(o[2], 1, 1e-15);
    /* zero z-extent window: all z → viewport zmin */
    const double wz[6] = { 0, 1, 0, 1, 3, 3 };
    assert_int_equal(gks_xform_norm_tran3(wz, vp, m), 0);
    const double c2[3] = { 0.5, 0.5, 17 };
    apply34(m, c2, o);
    XT_NEAR(o[2], 0.5, 0);
    /* errors: window first, then viewport 51, then 52 */
    const double bw[6] = { 1, 1, 0, 1, 0, 1 }, bwz[6] = { 0, 1, 0, 1, 1, 0 };
    const double bv[6] = { 0, 1, 0.5, 0.5, 0, 1 }, ov[6] = { 0, 1, 0, 1, 0, 1.5 };
    const double nv[6] = { 0, 1, 0, NAN, 0, 1 };
    assert_int_equal(gks_xform_norm_tran3(bw, ov, m), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_norm_tran3(bwz, vp, m), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_norm_tran3(win, bv, m), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_norm_tran3(win, ov, m), GKS_E_VIEWPORT_NOT_IN_NDC);
    assert_int_equal(gks_xform_norm_tran3(win, nv, m), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_check_window3(win), 0);
    assert_int_equal(gks_xform_check_viewport3(vp), 0);
    assert_int_equal(gks_xform_check_viewport3(ov), GKS_E_VIEWPORT_NOT_IN_NDC);
    const double w2[4] = { 0, 1, 2, 3 }, b2[4] = { 0, 1, 3, 2 }, o2[4] = { -0.1, 1, 0, 1 };
    assert_int_equal(gks_xform_check_window(w2), 0);
    assert_int_equal(gks_xform_check_window(b2), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_check_viewport(w2), GKS_E_VIEWPORT_NOT_IN_NDC);
    assert_int_equal(gks_xform_check_viewport(b2), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_check_viewport(o2), GKS_E_VIEWPORT_NOT_IN_NDC);
    const double cl[6] = { 0, 1, 0.2, 0.3, 0.5, 0.5 }, cbad[6] = { 0, 1, 0.3, 0.3, 0, 1 };
    const double cz[6] = { 0, 1, 0, 1, 0.6, 0.5 }, cout[6] = { 0, 1, 0, 1.01, 0, 1 };
    const double cnan[6] = { 0, NAN, 0, 1, 0, 1 };
    assert_int_equal(gks_xform_check_view_clip_limits(cl), 0);
    assert_int_equal(gks_xform_check_view_clip_limits(cbad), GKS_E_CLIP_LIMITS_INVALID);
    assert_int_equal(gks_xform_check_view_clip_limits(cz), GKS_E_CLIP_LIMITS_INVALID);
    assert_int_equal(gks_xform_check_view_clip_limits(cnan), GKS_E_CLIP_LIMITS_INVALID);
    assert_int_equal(gks_xform_check_view_clip_limits(cout), GKS_E_CLIP_LIMITS_NOT_IN_NPC);
    /* overflow of the scale → 308 */
    const double tw[6] = { 0, 1e-320, 0, 1, 0, 1 };
    assert_int_equal(gks_xform_norm_tran3(tw, vp, m), GKS_E_ARITHMETIC);
}

static void test_ws_tran3(void **state)
{
    (void)state;
    xt_traps_on();
    double m[4][4], o[3];
    /* window 1 × 0.5 into 800 × 600: s = min(800, 1200) = 800 → x 0..800, y 0..400 */
    const double win[6] = { 0, 1, 0, 0.5, 0, 1 }, vp[6] = { 0, 800, 0, 600, 0, 1 };
    assert_int_equal(gks_xform_ws_tran3(win, vp, m), 0);
    xt_map(m, 1, 0.5, 1, o);
    XT_NEAR(o[0], 800, 1e-12); XT_NEAR(o[1], 400, 1e-12); XT_NEAR(o[2], 1, 0);
    xt_map(m, 0, 0, 0, o);
    XT_NEAR(o[0], 0, 0); XT_NEAR(o[1], 0, 0); XT_NEAR(o[2], 0, 0);
    /* tall window, offset viewport, z range: lower-left placement, z linear */
    const double w2[6] = { 0.25, 0.5, 0, 1, 0.2, 0.6 }, v2[6] = { 100, 300, 50, 250, 0, 10 };
    assert_int_equal(gks_xform_ws_tran3(w2, v2, m), 0);   /* s = min(800, 200) = 200 */
    xt_map(m, 0.25, 0, 0.2, o);
    XT_NEAR(o[0], 100, 1e-12); XT_NEAR(o[1], 50, 1e-12); XT_NEAR(o[2], 0, 1e-12);
    xt_map(m, 0.5, 1, 0.6, o);
    XT_NEAR(o[0], 150, 1e-12); XT_NEAR(o[1], 250, 1e-12); XT_NEAR(o[2], 10, 1e-12);
    xt_map(m, 0.5, 1, 0.4, o);
    XT_NEAR(o[2], 5, 1e-12);
    /* checks */
    const double ds[3] = { 800, 600, 1 };
    assert_int_equal(gks_xform_check_ws_window3(win), 0);
    const double bw[6] = { 0, 1, 0, 1, 0.7, 0.6 }, ow[6] = { 0, 1.2, 0, 1, 0, 1 };
    assert_int_equal(gks_xform_check_ws_window3(bw), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_check_ws_window3(ow), GKS_E_WS_WINDOW_NOT_IN_NDC);
    assert_int_equal(gks_xform_check_ws_viewport3(vp, ds), 0);
    const double ov[6] = { 0, 801, 0, 600, 0, 1 }, bv[6] = { 5, 5, 0, 1, 0, 1 };
    assert_int_equal(gks_xform_check_ws_viewport3(ov, ds), GKS_E_WS_VIEWPORT_NOT_IN_DS);
    assert_int_equal(gks_xform_check_ws_viewport3(bv, ds), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_ws_tran3(bw, vp, m), GKS_E_RECT_INVALID);
    assert_int_equal(gks_xform_ws_tran3(win, bv, m), GKS_E_RECT_INVALID);
    const double nw[6] = { 0, 1, 0, INFINITY, 0, 1 };
    assert_int_equal(gks_xform_ws_tran3(nw, vp, m), GKS_E_RECT_INVALID);
    xt_traps_off();
}

/* Normals map with the inverse transpose (non-uniform scale), renormalised; a singular
 * matrix, a zero or a non-finite result is refused (0) with a zero vector. */
static void test_normal(void **state)
{
    (void)state;
    double m[4][4] = { { 2, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 } };
    double nm[3][3], o[3];
    assert_int_equal(gks_xform_normal_matrix(m, nm), 0);
    /* the plane x + y = 1 scaled by 2 in x is x/2 + y = 1: normal (1, 2, 0)/sqrt(5) */
    assert_int_equal(gks_xform_normal(nm, (double[3]){ 1, 1, 0 }, o), 1);
    assert_true(fabs(o[0] - 1 / sqrt(5.0)) < 1e-15 && fabs(o[1] - 2 / sqrt(5.0)) < 1e-15);
    assert_true(o[2] == 0.0);
    assert_int_equal(gks_xform_normal(nm, (double[3]){ 0, 0, 0 }, o), 0);
    assert_int_equal(gks_xform_normal(nm, (double[3]){ NAN, 1, 0 }, o), 0);
    assert_true(o[0] == 0.0 && o[1] == 0.0 && o[2] == 0.0);
    assert_int_equal(gks_xform_normal(nm, (double[3]){ INFINITY, 1, 0 }, o), 0);
    m[1][1] = 0;
    assert_int_equal(gks_xform_normal_matrix(m, nm), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_multiply_apply),
        cmocka_unit_test(test_invert),
        cmocka_unit_test(test_conversions),
        cmocka_unit_test(test_compose_and_pullback),
        cmocka_unit_test(test_eval_tran3),
        cmocka_unit_test(test_eval_tran2),
        cmocka_unit_test(test_accumulate),
        cmocka_unit_test(test_norm_tran3),
        cmocka_unit_test(test_ws_tran3),
        cmocka_unit_test(test_normal),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
