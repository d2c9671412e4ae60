/* SPDX-License-Identifier: MIT */
/*
 * test_xform_view.c -- view orientation and view mapping (BINDINGS.md §3.2, §3.3):
 * hand-computed matrices, the standard's defining properties on random and PVT-style
 * parameter sets, an independent implementation of OpenPHIGS's matrix entries, every
 * error condition and their order, camera recovery.
 */
#include "xform_test_util.h"

#include <float.h>
#include <string.h>

/* ---- orientation ---------------------------------------------------------------------- */

static void test_orientation_known(void **state)
{
    (void)state;
    double m[4][4];
    const double vrp[3] = { 1, 2, 3 }, vpn[3] = { 0, 0, 5 }, vup[3] = { 0, 7, 0 };
    assert_int_equal(gks_xform_eval_view_orientation3(vrp, vpn, vup, m), 0);
    const double e1[4][4] = { { 1, 0, 0, -1 }, { 0, 1, 0, -2 }, { 0, 0, 1, -3 }, { 0, 0, 0, 1 } };
    xt_mat4_near(m, e1, 1e-15);

    /* VPN = +x, VUP = +z: u = VUP×VPN = +y, v = n×u = +z. */
    const double vpn2[3] = { 2, 0, 0 }, vup2[3] = { 0, 0, 1 }, vrp2[3] = { 1, 2, 3 };
    assert_int_equal(gks_xform_eval_view_orientation3(vrp2, vpn2, vup2, m), 0);
    const double e2[4][4] = { { 0, 1, 0, -2 }, { 0, 0, 1, -3 }, { 1, 0, 0, -1 }, { 0, 0, 0, 1 } };
    xt_mat4_near(m, e2, 1e-15);

    /* VUP not perpendicular to VPN: only its component perpendicular to VPN matters. */
    const double vup3[3] = { 5, 0, 1 };
    assert_int_equal(gks_xform_eval_view_orientation3(vrp2, vpn2, vup3, m), 0);
    xt_mat4_near(m, e2, 1e-15);
}

static void test_orientation_properties(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 0x9e3779b97f4a7c15ULL };
    for (int it = 0; it < 500; it++) {
        double vrp[3], vpn[3], vup[3], m[4][4];
        for (int i = 0; i < 3; i++) {
            vrp[i] = xt_uniform(&r, -100, 100);
            vpn[i] = xt_uniform(&r, -3, 3);
            vup[i] = xt_uniform(&r, -3, 3);
        }
        int err = gks_xform_eval_view_orientation3(vrp, vpn, vup, m);
        assert_int_equal(err, 0);
        /* rows orthonormal, right-handed (u × v = n) */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) {
                double d = m[i][0] * m[j][0] + m[i][1] * m[j][1] + m[i][2] * m[j][2];
                XT_NEAR(d, i == j ? 1.0 : 0.0, 1e-13);
            }
        XT_NEAR(m[0][1] * m[1][2] - m[0][2] * m[1][1], m[2][0], 1e-13);
        XT_NEAR(m[0][2] * m[1][0] - m[0][0] * m[1][2], m[2][1], 1e-13);
        XT_NEAR(m[0][0] * m[1][1] - m[0][1] * m[1][0], m[2][2], 1e-13);
        /* VRP → origin; VPN → +n; VUP → v > 0 with u = 0 */
        double o[3], d[3];
        xt_map(m, vrp[0], vrp[1], vrp[2], o);
        for (int i = 0; i < 3; i++)
            XT_NEAR(o[i], 0.0, 1e-12);
        xt_direction(m, vpn, d);
        double ln = sqrt(vpn[0] * vpn[0] + vpn[1] * vpn[1] + vpn[2] * vpn[2]);
        XT_NEAR(d[0], 0.0, 1e-13);
        XT_NEAR(d[1], 0.0, 1e-13);
        XT_NEAR(d[2], ln, 1e-13);
        xt_direction(m, vup, d);
        XT_NEAR(d[0], 0.0, 1e-13);
        assert_true(d[1] > 0.0);
    }
    xt_traps_off();
}

static void test_orientation_errors(void **state)
{
    (void)state;
    double m[4][4], keep[4][4];
    const double z[3] = { 0, 0, 0 }, ok[3] = { 0, 0, 1 }, up[3] = { 0, 1, 0 };
    const double nan3[3] = { NAN, 0, 1 }, inf3[3] = { 0, INFINITY, 1 };
    gks_xform_identity(m);
    memcpy(keep, m, sizeof m);
    assert_int_equal(gks_xform_eval_view_orientation3(z, z, up, m), GKS_E_VPN_ZERO);
    assert_int_equal(gks_xform_eval_view_orientation3(z, z, z, m), GKS_E_VPN_ZERO); /* order */
    assert_int_equal(gks_xform_eval_view_orientation3(z, ok, z, m), GKS_E_VUP_ZERO);
    assert_int_equal(gks_xform_eval_view_orientation3(z, nan3, up, m), GKS_E_VPN_ZERO);
    assert_int_equal(gks_xform_eval_view_orientation3(z, ok, inf3, m), GKS_E_VUP_ZERO);
    const double par[3] = { 0, 0, -3 };
    assert_int_equal(gks_xform_eval_view_orientation3(z, ok, par, m), GKS_E_VIEW_UP_PARALLEL);
    /* parallel up to rounding: 0.1(1,1,1) and 0.7(1,1,1) */
    const double a[3] = { 0.1, 0.1, 0.1 }, b[3] = { 0.7, 0.7, 0.7 };
    assert_int_equal(gks_xform_eval_view_orientation3(z, b, a, m), GKS_E_VIEW_UP_PARALLEL);
    /* parallel, but the normalized cross product is ~8e-17, not 0, in floating point */
    const double pn[3] = { 0.1, 0.1, 0.3 };
    const double pu[3] = { pn[0] * 0.7, pn[1] * 0.7, pn[2] * 0.7 };
    assert_int_equal(gks_xform_eval_view_orientation3(z, pn, pu, m), GKS_E_VIEW_UP_PARALLEL);
    /* tiny but valid vectors are accepted (no absolute tolerance) */
    const double tn[3] = { 0, 0, 1e-300 }, tu[3] = { 0, 1e-300, 0 };
    assert_int_equal(gks_xform_eval_view_orientation3(z, tn, tu, m), 0);
    gks_xform_identity(keep);
    xt_mat4_near(m, keep, 0.0);
    /* huge vectors: no overflow */
    const double hn[3] = { 0, 0, 1e300 }, hu[3] = { 1e300, 1e300, 0 };
    assert_int_equal(gks_xform_eval_view_orientation3(z, hn, hu, m), 0);
    /* non-finite VRP → 308, but only after the vector errors */
    assert_int_equal(gks_xform_eval_view_orientation3(nan3, ok, up, m), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_eval_view_orientation3(nan3, ok, par, m),
                     GKS_E_VIEW_UP_PARALLEL);
    /* output untouched on error */
    double before[4][4];
    memcpy(before, m, sizeof m);
    assert_int_equal(gks_xform_eval_view_orientation3(z, z, up, m), GKS_E_VPN_ZERO);
    assert_memory_equal(before, m, sizeof m);
}

/* ---- mapping: hand values ---------------------------------------------------------------- */

static gks_xform_view_map3 unit_map(int type)
{
    gks_xform_view_map3 p = {
        .window = { -1, 1, -1, 1 }, .viewport = { 0, 1, 0, 1, 0, 1 }, .proj_type = type,
        .prp = { 0, 0, 2 }, .vpd = 1, .bpd = -2, .fpd = 1,
    };
    return p;
}

static void test_mapping_hand(void **state)
{
    (void)state;
    xt_traps_on();
    double m[4][4];
    /* orthographic parallel: window [0,2]x[0,4], PRP over the window centre */
    gks_xform_view_map3 p = {
        .window = { 0, 2, 0, 4 }, .viewport = { 0, 1, 0, 1, 0, 1 },
        .proj_type = GKS_XFORM_PARALLEL, .prp = { 1, 2, 10 }, .vpd = 0, .bpd = -10, .fpd = 0,
    };
    assert_int_equal(gks_xform_eval_view_mapping3(&p, m), 0);
    const double e1[4][4] = { { 0.5, 0, 0, 0 }, { 0, 0.25, 0, 0 }, { 0, 0, 0.1, 1 },
                              { 0, 0, 0, 1 } };
    xt_mat4_near(m, e1, 1e-15);

    /* oblique parallel: PRP (1,0,1), VPD 0 → hx = −1 */
    gks_xform_view_map3 q = unit_map(GKS_XFORM_PARALLEL);
    q.prp[0] = 1; q.prp[1] = 0; q.prp[2] = 1; q.vpd = 0; q.bpd = -1; q.fpd = 0.5;
    assert_int_equal(gks_xform_eval_view_mapping3(&q, m), 0);
    const double e2[4][4] = { { 0.5, 0, -0.5, 0.5 }, { 0, 0.5, 0, 0.5 },
                              { 0, 0, 1 / 1.5, 1 / 1.5 }, { 0, 0, 0, 1 } };
    xt_mat4_near(m, e2, 1e-15);

    /* perspective: window [−1,1]², PRP (0,0,2), VPD 1, B −2, F 1:
     * s = 1/4, Sx = 1/2, ax = 1/2, Kz = 1·(1/4)(1)/3 = 1/12 */
    gks_xform_view_map3 r = unit_map(GKS_XFORM_PERSPECTIVE);
    assert_int_equal(gks_xform_eval_view_mapping3(&r, m), 0);
    const double e3[4][4] = { { 0.125, 0, -0.125, 0.25 }, { 0, 0.125, -0.125, 0.25 },
                              { 0, 0, 1.0 / 12, 1.0 / 6 }, { 0, 0, -0.25, 0.5 } };
    xt_mat4_near(m, e3, 1e-15);

    /* F == B with a flat viewport: every z → zmin */
    gks_xform_view_map3 f = unit_map(GKS_XFORM_PARALLEL);
    f.fpd = f.bpd = -1;
    f.viewport[4] = f.viewport[5] = 0.25;
    assert_int_equal(gks_xform_eval_view_mapping3(&f, m), 0);
    double o[3];
    xt_map(m, 0.3, 0.2, 17.0, o);
    XT_NEAR(o[2], 0.25, 0.0);
    f.proj_type = GKS_XFORM_PERSPECTIVE;
    assert_int_equal(gks_xform_eval_view_mapping3(&f, m), 0);
    xt_map(m, 0.3, 0.2, -0.5, o);
    XT_NEAR(o[2], 0.25, 1e-15);
}

/* OpenPHIGS's matrix entries as listed in BINDINGS.md §3.3, an independent oracle. */
static void openphigs_map(const gks_xform_view_map3 *p, double r[4][4])
{
    const double *w = p->window, *v = p->viewport;
    const double pu = p->prp[0], pv = p->prp[1], pn = p->prp[2];
    const double dx = v[1] - v[0], dy = v[3] - v[2], dz = v[5] - v[4];
    const double cu = 0.5 * (w[0] + w[1]), cv = 0.5 * (w[2] + w[3]);
    memset(r, 0, 16 * sizeof r[0][0]);
    if (p->proj_type == GKS_XFORM_PARALLEL) {
        const double sx = dx / (w[1] - w[0]), sy = dy / (w[3] - w[2]);
        const double hx = (pu - cu) / (p->vpd - pn), hy = (pv - cv) / (p->vpd - pn);
        const double vvz = p->fpd - p->bpd;
        r[0][0] = sx; r[0][2] = sx * hx; r[0][3] = v[0] - sx * (hx * p->vpd + w[0]);
        r[1][1] = sy; r[1][2] = sy * hy; r[1][3] = v[2] - sy * (hy * p->vpd + w[2]);
        r[2][2] = vvz != 0 ? dz / vvz : 0; r[2][3] = v[4] - r[2][2] * p->bpd;
        r[3][3] = 1;
        return;
    }
    const double d = pn - p->vpd, s = 1.0 / (pn - p->bpd);
    const double sx = 2 * s * d / (w[1] - w[0]), sy = 2 * s * d / (w[3] - w[2]);
    const double hx = (pu - cu) / d, hy = (pv - cv) / d, zf = (pn - p->fpd) / (pn - p->bpd);
    r[0][0] = 0.5 * dx * sx;
    r[0][2] = -(0.5 * dx * (sx * hx + s) + s * v[0]);
    r[0][3] = -(0.5 * dx * sx * (pu - hx * pn) - s * pn * (0.5 * dx + v[0]));
    r[1][1] = 0.5 * dy * sy;
    r[1][2] = -(0.5 * dy * (sy * hy + s) + s * v[2]);
    r[1][3] = -(0.5 * dy * sy * (pv - hy * pn) - s * pn * (0.5 * dy + v[2]));
    r[2][2] = s * (dz / (1 - zf) - v[5]);
    r[2][3] = s * pn * v[5] - (dz / (1 - zf)) * (s * pn - zf);
    r[3][2] = -s;
    r[3][3] = s * pn;
}

/* ---- mapping: the standard's defining properties ---------------------------------------- */

/* A point of the view volume's boundary: window corner (cu, cv) (in the view plane) carried
 * along its projector to the plane n. */
static void along_projector(const gks_xform_view_map3 *p, double u, double v, double n,
                            double out[3])
{
    const double pu = p->prp[0], pv = p->prp[1], pn = p->prp[2];
    if (p->proj_type == GKS_XFORM_PERSPECTIVE) {
        const double t = (pn - n) / (pn - p->vpd);
        out[0] = pu + (u - pu) * t;
        out[1] = pv + (v - pv) * t;
    } else {
        const double cu = 0.5 * (p->window[0] + p->window[1]);
        const double cv = 0.5 * (p->window[2] + p->window[3]);
        const double du = cu - pu, dv = cv - pv, dn = p->vpd - pn;
        out[0] = u + du / dn * (n - p->vpd);
        out[1] = v + dv / dn * (n - p->vpd);
    }
    out[2] = n;
}

static void check_properties(const gks_xform_view_map3 *p, xt_rng *r, double tol)
{
    double m[4][4], o[3], q[3];
    assert_int_equal(gks_xform_eval_view_mapping3(p, m), 0);
    const double *w = p->window, *v = p->viewport;
    /* corners of the view volume → corners of the projection viewport (B → zmin, F → zmax) */
    for (int c = 0; c < 8; c++) {
        const double u = w[c & 1], vv = w[2 + ((c >> 1) & 1)];
        const double n = (c & 4) ? p->fpd : p->bpd;
        along_projector(p, u, vv, n, q);
        xt_map(m, q[0], q[1], q[2], o);
        XT_NEAR(o[0], v[c & 1], tol);
        XT_NEAR(o[1], v[2 + ((c >> 1) & 1)], tol);
        XT_NEAR(o[2], v[4 + ((c >> 2) & 1)], tol);
    }
    /* a projector maps to constant NPC x, y; z is monotonic in n (increasing towards F) */
    for (int k = 0; k < 20; k++) {
        const double u = xt_uniform(r, w[0], w[1]), vv = xt_uniform(r, w[2], w[3]);
        double x0 = 0, y0 = 0, zprev = -INFINITY;
        for (int j = 0; j <= 6; j++) {
            const double n = p->bpd + (p->fpd - p->bpd) * j / 6.0;
            along_projector(p, u, vv, n, q);
            xt_map(m, q[0], q[1], q[2], o);
            if (j == 0) {
                x0 = o[0];
                y0 = o[1];
                XT_NEAR(x0, v[0] + (u - w[0]) * (v[1] - v[0]) / (w[1] - w[0]), tol);
                XT_NEAR(y0, v[2] + (vv - w[2]) * (v[3] - v[2]) / (w[3] - w[2]), tol);
            }
            XT_NEAR(o[0], x0, tol);
            XT_NEAR(o[1], y0, tol);
            assert_true(o[2] >= zprev - tol);
            zprev = o[2];
        }
    }
    /* same matrix as OpenPHIGS's entries (relative to the row's size) */
    double e[4][4];
    openphigs_map(p, e);
    for (int i = 0; i < 4; i++) {
        double sc = 0;
        for (int j = 0; j < 4; j++)
            sc = fmax(sc, fabs(e[i][j]));
        for (int j = 0; j < 4; j++)
            XT_NEAR(m[i][j], e[i][j], 1e-12 * sc);
    }
}

static void random_map(xt_rng *r, gks_xform_view_map3 *p, int type)
{
    for (;;) {
        double a = xt_uniform(r, -500, 500), b = xt_uniform(r, -500, 500);
        double c = xt_uniform(r, -5000, 5000), d = xt_uniform(r, -5000, 5000);
        p->window[0] = fmin(a, b); p->window[1] = fmax(a, b);
        p->window[2] = fmin(c, d); p->window[3] = fmax(c, d);
        for (int i = 0; i < 3; i++) {
            double x = xt_uniform(r, 0, 1), y = xt_uniform(r, 0, 1);
            p->viewport[2 * i] = fmin(x, y);
            p->viewport[2 * i + 1] = fmax(x, y);
        }
        p->proj_type = type;
        for (int i = 0; i < 3; i++)
            p->prp[i] = xt_uniform(r, -50, 50);
        p->vpd = xt_uniform(r, -20, 20);
        double B = xt_uniform(r, -20, 20), F = xt_uniform(r, -20, 20);
        p->bpd = fmin(B, F);
        p->fpd = fmax(B, F);
        if (p->fpd - p->bpd < 0.5 || fabs(p->prp[2] - p->vpd) < 0.5)
            continue;
        /* keep the PRP clearly away from the front/back planes for a well-posed test */
        if (type == GKS_XFORM_PERSPECTIVE
            && (p->prp[2] > p->bpd - 1 && p->prp[2] < p->fpd + 1))
            continue;
        if (p->window[1] - p->window[0] < 1 || p->window[3] - p->window[2] < 1)
            continue;
        double m[4][4];
        if (gks_xform_eval_view_mapping3(p, m) == 0)
            return;
    }
    xt_traps_off();
}

static void test_mapping_random(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 12345 };
    for (int it = 0; it < 400; it++) {
        gks_xform_view_map3 p;
        random_map(&r, &p, (it & 1) ? GKS_XFORM_PERSPECTIVE : GKS_XFORM_PARALLEL);
        check_properties(&p, &r, 1e-9);
    }
    xt_traps_off();
}

/* The NIST PVT 06.02.01 p02 awkward numbers, parallel and perspective, several viewports. */
static void test_mapping_pvt(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 777 };
    const double vps[3][6] = { { 0, 1, 0, 1, 0, 1 }, { 0.1, 0.9, 0.2, 0.7, 0.3, 0.6 },
                               { 0.013, 0.0131, 0.5, 0.99, 0.4, 0.4 + 1e-6 } };
    for (int t = 0; t < 2; t++)
        for (int k = 0; k < 3; k++) {
            gks_xform_view_map3 p = {
                .window = { -462.27, -80.95, -4891.85, -94.78 }, .proj_type = t,
                .prp = { -15.044, 1.318, 34.873 }, .vpd = -1.213, .bpd = -3.311,
                .fpd = 15.332,
            };
            memcpy(p.viewport, vps[k], sizeof p.viewport);
            check_properties(&p, &r, 1e-10);
        }
    xt_traps_off();
}

/* ---- mapping: errors and their order ----------------------------------------------------- */

static void test_mapping_errors(void **state)
{
    (void)state;
    double m[4][4], before[4][4];
    gks_xform_identity(m);
    memcpy(before, m, sizeof m);
    const int P = GKS_XFORM_PERSPECTIVE, A = GKS_XFORM_PARALLEL;
    struct {
        const char *what;
        int type;
        double win0, vpx1, vpz0, pn, vpd, B, F;
        int expect;
    } cases[] = {
        /* base (unit_map): win0 −1, vp xmax 1, vp zmin 0, pn 2, VPD 1, B −2, F 1 */
        { "valid persp", P, -1, 1, 0, 2, 1, -2, 1, 0 },
        { "valid parallel", A, -1, 1, 0, 2, 1, -2, 1, 0 },
        { "bad type", 7, 5, 1, 0, 2, 1, -2, 1, GKS_E_ENUM_RANGE },
        { "window", P, 1, 1, 0, 2, 1, -2, 1, GKS_E_VIEW_WINDOW_INVALID },
        { "window+viewport", P, 5, -1, 0, 2, 1, -2, 1, GKS_E_VIEW_WINDOW_INVALID },
        { "viewport x", P, -1, 0, 0, 2, 1, -2, 1, GKS_E_PROJ_VIEWPORT_INVALID },
        { "viewport z", P, -1, 1, 1.5, 2, 1, -2, 1, GKS_E_PROJ_VIEWPORT_INVALID },
        { "viewport+F==B", P, -1, 0, 0, 2, 1, 1, 1, GKS_E_PROJ_VIEWPORT_INVALID },
        { "F==B", A, -1, 1, 0, 2, 1, 1, 1, GKS_E_FRONT_BACK_EQUAL },
        { "F==B+pn==B", P, -1, 1, 0, 1, 1, 1, 1, GKS_E_FRONT_BACK_EQUAL },
        { "between", P, -1, 1, 0, 0, 1, -2, 1, GKS_E_PRP_BETWEEN_PLANES },
        { "between parallel ok", A, -1, 1, 0, 0, 1, -2, 1, 0 },
        { "between+on VP", P, -1, 1, 0, 0.5, 0.5, -2, 1, GKS_E_PRP_BETWEEN_PLANES },
        { "pn==B", P, -1, 1, 0, -2, 1, -2, 1, GKS_E_PRP_BETWEEN_PLANES },
        { "pn==F", P, -1, 1, 0, 1, 0, -2, 1, GKS_E_PRP_BETWEEN_PLANES },
        { "pn==B parallel ok", A, -1, 1, 0, -2, 1, -2, 1, 0 },
        { "on view plane", P, -1, 1, 0, 3, 3, -2, 1, GKS_E_PRP_ON_VIEW_PLANE },
        { "on view plane par", A, -1, 1, 0, 3, 3, -2, 1, GKS_E_PRP_ON_VIEW_PLANE },
        { "on VP+F<B", A, -1, 1, 0, 3, 3, 1, -2, GKS_E_PRP_ON_VIEW_PLANE },
        { "F<B", A, -1, 1, 0, 3, 1, 1, -2, GKS_E_BACK_IN_FRONT },
        { "F<B persp", P, -1, 1, 0, 3, 1, 1, -2, GKS_E_BACK_IN_FRONT },
        { "F<B+outside NPC", A, -1, 1.5, 0, 3, 1, 1, -2, GKS_E_BACK_IN_FRONT },
        { "outside NPC", A, -1, 1.5, 0, 3, 1, -2, 1, GKS_E_PROJ_VIEWPORT_NOT_IN_NPC },
        { "outside NPC z", P, -1, 1, -0.5, 3, 1, -2, 1, GKS_E_PROJ_VIEWPORT_NOT_IN_NPC },
        { "PRP behind B", P, -1, 1, 0, -5, 1, -2, 1, 0 },
        { "NaN window", P, NAN, 1, 0, 2, 1, -2, 1, GKS_E_VIEW_WINDOW_INVALID },
        { "-Inf window", P, -INFINITY, 1, 0, 2, 1, -2, 1, GKS_E_VIEW_WINDOW_INVALID },
        { "NaN viewport", P, -1, NAN, 0, 2, 1, -2, 1, GKS_E_PROJ_VIEWPORT_INVALID },
        { "NaN PRP", P, -1, 1, 0, NAN, 1, -2, 1, GKS_E_ARITHMETIC },
        { "Inf VPD", P, -1, 1, 0, 2, INFINITY, -2, 1, GKS_E_ARITHMETIC },
        { "NaN B", A, -1, 1, 0, 2, 1, NAN, 1, GKS_E_ARITHMETIC },
        { "NaN F+window", A, 3, 1, 0, 2, 1, -2, NAN, GKS_E_VIEW_WINDOW_INVALID },
        { "NaN F+F==B?", A, -1, 1, 0, 2, 1, 1, NAN, GKS_E_ARITHMETIC },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        gks_xform_view_map3 p = unit_map(cases[i].type);
        p.window[0] = cases[i].win0;
        p.viewport[1] = cases[i].vpx1;
        p.viewport[4] = cases[i].vpz0;
        p.prp[2] = cases[i].pn;
        p.vpd = cases[i].vpd;
        p.bpd = cases[i].B;
        p.fpd = cases[i].F;
        double r[4][4];
        memcpy(r, before, sizeof r);
        int err = gks_xform_eval_view_mapping3(&p, r);
        if (err != cases[i].expect) {
            print_error("case '%s': got %d, expected %d\n", cases[i].what, err,
                        cases[i].expect);
            fail();
        }
        if (err)
            assert_memory_equal(r, before, sizeof r);
        else
            for (int a = 0; a < 4; a++)
                for (int b = 0; b < 4; b++)
                    assert_true(isfinite(r[a][b]));
    }
    /* a window so narrow that the scale overflows: 308, not an infinite matrix */
    gks_xform_view_map3 p = unit_map(GKS_XFORM_PARALLEL);
    p.window[0] = 0;
    p.window[1] = 1e-320;
    assert_int_equal(gks_xform_eval_view_mapping3(&p, m), GKS_E_ARITHMETIC);
}

/* ---- camera recovery ---------------------------------------------------------------------- */

static void test_camera(void **state)
{
    (void)state;
    xt_traps_on();
    xt_rng r = { 4242 };
    for (int it = 0; it < 200; it++) {
        const int type = (it & 1) ? GKS_XFORM_PERSPECTIVE : GKS_XFORM_PARALLEL;
        gks_xform_view_map3 p;
        random_map(&r, &p, type);
        double vrp[3], vpn[3], vup[3], mo[4][4], mm[4][4], full[4][4], moi[4][4];
        for (int i = 0; i < 3; i++) {
            vrp[i] = xt_uniform(&r, -10, 10);
            vpn[i] = xt_uniform(&r, -1, 1);
            vup[i] = xt_uniform(&r, -1, 1);
        }
        assert_int_equal(gks_xform_eval_view_orientation3(vrp, vpn, vup, mo), 0);
        assert_int_equal(gks_xform_eval_view_mapping3(&p, mm), 0);
        gks_xform_multiply(mm, mo, full);
        assert_int_equal(gks_xform_invert(mo, moi), 0);
        double eye[3];
        int persp = -1;
        assert_int_equal(gks_xform_view_camera(full, eye, &persp), 0);
        assert_int_equal(persp, type);
        double expect[3];
        if (type == GKS_XFORM_PERSPECTIVE) {
            xt_map(moi, p.prp[0], p.prp[1], p.prp[2], expect);
            for (int i = 0; i < 3; i++)
                XT_NEAR(eye[i], expect[i], 1e-8 * (1 + fabs(expect[i])));
        } else {
            /* direction from the window centre to the PRP (towards the viewer), in world */
            double d[3] = { p.prp[0] - 0.5 * (p.window[0] + p.window[1]),
                            p.prp[1] - 0.5 * (p.window[2] + p.window[3]), p.prp[2] - p.vpd };
            if (p.prp[2] < p.vpd)       /* the viewer is on +n; F >= B, and +n maps to +z */
                for (int i = 0; i < 3; i++)
                    d[i] = -d[i];
            xt_direction(moi, d, expect);
            double l = sqrt(expect[0] * expect[0] + expect[1] * expect[1]
                            + expect[2] * expect[2]);
            for (int i = 0; i < 3; i++)
                XT_NEAR(eye[i], expect[i] / l, 1e-9);
        }
    }
    xt_traps_off();
    double sing[4][4] = { { 0 } }, eye[3];
    int persp;
    assert_int_equal(gks_xform_view_camera(sing, eye, &persp), GKS_E_ARITHMETIC);
    /* flat projection viewport: M is singular, the camera is still found */
    gks_xform_view_map3 fl = unit_map(GKS_XFORM_PERSPECTIVE);
    fl.viewport[4] = fl.viewport[5] = 0.5;
    fl.prp[0] = 0.3;
    double mf[4][4], inv[4][4];
    assert_int_equal(gks_xform_eval_view_mapping3(&fl, mf), 0);
    assert_int_equal(gks_xform_invert(mf, inv), GKS_E_ARITHMETIC);
    assert_int_equal(gks_xform_view_camera(mf, eye, &persp), 0);
    assert_int_equal(persp, 1);
    XT_NEAR(eye[0], 0.3, 1e-14); XT_NEAR(eye[1], 0, 1e-14); XT_NEAR(eye[2], 2, 1e-14);
    fl.proj_type = GKS_XFORM_PARALLEL;   /* DOP ∝ PRP − window centre = (0.3, 0, 1) */
    assert_int_equal(gks_xform_eval_view_mapping3(&fl, mf), 0);
    assert_int_equal(gks_xform_view_camera(mf, eye, &persp), 0);
    assert_int_equal(persp, 0);
    const double l = sqrt(0.09 + 1);
    XT_NEAR(fabs(eye[0]), 0.3 / l, 1e-14); XT_NEAR(eye[1], 0, 1e-14);
    XT_NEAR(fabs(eye[2]), 1 / l, 1e-14);
    XT_NEAR(eye[0] * eye[2], 0.3 / (l * l), 1e-14);   /* same direction up to sign */
    double nanm[4][4];
    gks_xform_identity(nanm);
    nanm[3][2] = NAN;
    assert_int_equal(gks_xform_view_camera(nanm, eye, &persp), GKS_E_ARITHMETIC);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_orientation_known),
        cmocka_unit_test(test_orientation_properties),
        cmocka_unit_test(test_orientation_errors),
        cmocka_unit_test(test_mapping_hand),
        cmocka_unit_test(test_mapping_random),
        cmocka_unit_test(test_mapping_pvt),
        cmocka_unit_test(test_mapping_errors),
        cmocka_unit_test(test_camera),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
