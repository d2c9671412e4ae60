/* SPDX-License-Identifier: MIT */
/*
 * xform_matrix.c -- 4x4 / 3x4 / 2x3 matrix utilities, normalization and workstation
 * transformations, pipeline composition. Pure functions (see gks_xform.h).
 */
#include "gks_xform.h"
#include "xform_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

void gks_xform_identity(double m[4][4])
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = (i == j) ? 1.0 : 0.0;
}

void gks_xform_multiply(const double a[4][4], const double b[4][4], double r[4][4])
{
    double t[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++)
                s += a[i][k] * b[k][j];
            t[i][j] = s;
        }
    memcpy(r, t, sizeof t);
}

/* Power of two nearest (from above) to 1/x for x > 0, so that x·result is in [0.5, 1). */
static double pow2_recip(double x)
{
    int e;
    (void)frexp(x, &e);
    return ldexp(1.0, -e);
}

int gks_xform_invert(const double m[4][4], double inv[4][4])
{
    double a[4][4], b[4][4], rs[4], cs[4];

    if (!xform_finite_n(&m[0][0], 16))
        return GKS_E_ARITHMETIC;
    /* Equilibrate: A = Dr·M·Dc with power-of-two factors (exact), so that every row and
     * column has its largest entry in [0.5, 1); then M⁻¹ = Dc·A⁻¹·Dr. */
    for (int i = 0; i < 4; i++) {
        double mx = 0.0;
        for (int j = 0; j < 4; j++)
            mx = fmax(mx, fabs(m[i][j]));
        if (mx == 0.0)
            return GKS_E_ARITHMETIC;
        rs[i] = pow2_recip(mx);
    }
    for (int j = 0; j < 4; j++) {
        double mx = 0.0;
        for (int i = 0; i < 4; i++)
            mx = fmax(mx, fabs(m[i][j] * rs[i]));
        if (mx == 0.0)
            return GKS_E_ARITHMETIC;
        cs[j] = pow2_recip(mx);
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            a[i][j] = m[i][j] * rs[i] * cs[j];
            b[i][j] = (i == j) ? 1.0 : 0.0;
        }
    /* Gauss-Jordan with partial pivoting: reduce a to I, applying the same steps to b. */
    for (int col = 0; col < 4; col++) {
        int piv = col;
        for (int i = col + 1; i < 4; i++)
            if (fabs(a[i][col]) > fabs(a[piv][col]))
                piv = i;
        if (!(fabs(a[piv][col]) > 64.0 * DBL_EPSILON))
            return GKS_E_ARITHMETIC;
        if (piv != col)
            for (int j = 0; j < 4; j++) {
                double t = a[col][j]; a[col][j] = a[piv][j]; a[piv][j] = t;
                t = b[col][j]; b[col][j] = b[piv][j]; b[piv][j] = t;
            }
        double p = a[col][col];
        for (int j = 0; j < 4; j++) {
            a[col][j] /= p;
            b[col][j] /= p;
        }
        for (int i = 0; i < 4; i++) {
            if (i == col || a[i][col] == 0.0)
                continue;
            double f = a[i][col];
            for (int j = 0; j < 4; j++) {
                a[i][j] -= f * a[col][j];
                b[i][j] -= f * b[col][j];
            }
        }
    }
    /* inverse = Dc · b · Dr */
    double r[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            r[i][j] = cs[i] * b[i][j] * rs[j];
    if (!xform_finite_n(&r[0][0], 16))
        return GKS_E_ARITHMETIC;
    memcpy(inv, r, sizeof r);
    return 0;
}

void gks_xform_apply(const double m[4][4], const double in[4], double out[4])
{
    double t[4];
    for (int i = 0; i < 4; i++)
        t[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2] + m[i][3] * in[3];
    memcpy(out, t, sizeof t);
}

double gks_xform_point(const double m[4][4], const double p[3], double out[3])
{
    double h[4] = { p[0], p[1], p[2], 1.0 };
    gks_xform_apply(m, h, h);
    if (h[3] != 0.0) {
        out[0] = h[0] / h[3];
        out[1] = h[1] / h[3];
        out[2] = h[2] / h[3];
    } else {
        out[0] = h[0];
        out[1] = h[1];
        out[2] = h[2];
    }
    return h[3];
}

int gks_xform_normal_matrix(const double m[4][4], double nm[3][3])
{
    double c[3][3]; /* cofactors: inverse transpose = cofactor matrix / det */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
    if (!isfinite(det) || det == 0.0)
        return -1;
    double s = det > 0 ? 1.0 : -1.0, mx = 0.0; /* the sign keeps the sense of p x q */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mx = fmax(mx, fabs(c[i][j]));
    if (!(mx > 0.0) || !isfinite(mx))
        return -1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            nm[i][j] = s * c[i][j] / mx;
    return 0;
}

int gks_xform_normal(const double nm[3][3], const double v[3], double out[3])
{
    double r[3], mx = 0.0;
    int finite = 1;
    for (int i = 0; i < 3; i++) { /* all of v is read before out is written: out may be v */
        r[i] = nm[i][0] * v[0] + nm[i][1] * v[1] + nm[i][2] * v[2];
        finite &= isfinite(r[i]) != 0; /* fmax would pass a NaN over */
        mx = fmax(mx, fabs(r[i]));
    }
    out[0] = out[1] = out[2] = 0.0;
    if (!finite || !(mx > 0.0))
        return 0;
    double a = r[0] / mx, b = r[1] / mx, c = r[2] / mx, l = sqrt(a * a + b * b + c * c);
    out[0] = a / l;
    out[1] = b / l;
    out[2] = c / l;
    return 1;
}

void gks_xform_mat34_to_mat4(const double m[3][4], double r[4][4])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            r[i][j] = m[i][j];
    r[3][0] = r[3][1] = r[3][2] = 0.0;
    r[3][3] = 1.0;
}

void gks_xform_mat23_to_mat34(const double m[2][3], double r[3][4])
{
    for (int i = 0; i < 2; i++) {
        r[i][0] = m[i][0];
        r[i][1] = m[i][1];
        r[i][2] = 0.0;
        r[i][3] = m[i][2];
    }
    r[2][0] = r[2][1] = r[2][3] = 0.0;
    r[2][2] = 1.0;
}

void gks_xform_mat34_point(const double m[3][4], const double p[3], double out[3])
{
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    memcpy(out, t, sizeof t);
}

void gks_xform_mat34_multiply(const double a[3][4], const double b[3][4], double r[3][4])
{
    double t[3][4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            double s = (j == 3) ? a[i][3] : 0.0;
            for (int k = 0; k < 3; k++)
                s += a[i][k] * b[k][j];
            t[i][j] = s;
        }
    memcpy(r, t, sizeof t);
}

void gks_xform_mat23_multiply(const double a[2][3], const double b[2][3], double r[2][3])
{
    double t[2][3];
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++) {
            double s = (j == 2) ? a[i][2] : 0.0;
            for (int k = 0; k < 2; k++)
                s += a[i][k] * b[k][j];
            t[i][j] = s;
        }
    memcpy(r, t, sizeof t);
}

void gks_xform_plane_pullback(const double p[4], const double m[4][4], double out[4])
{
    double t[4];
    for (int j = 0; j < 4; j++)
        t[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + p[3] * m[3][j];
    memcpy(out, t, sizeof t);
}

/* ---- windows and viewports -------------------------------------------------------------- */

/* x/y strictly increasing, z (if any) non-decreasing, all finite. */
static int box_ordered(const double *b, int dims)
{
    if (!xform_finite_n(b, (size_t)(2 * dims)))
        return 0;
    if (!(b[0] < b[1]) || !(b[2] < b[3]))
        return 0;
    return dims < 3 || b[4] <= b[5];
}

/* Every limit within [lo_i, hi_i] (lo = 0). */
static int box_within(const double *b, int dims, const double *hi)
{
    for (int i = 0; i < 2 * dims; i++)
        if (!(b[i] >= 0.0 && b[i] <= hi[i / 2]))
            return 0;
    return 1;
}

static const double unit3[3] = { 1.0, 1.0, 1.0 };

int gks_xform_check_window(const double win[4])
{
    return box_ordered(win, 2) ? 0 : GKS_E_RECT_INVALID;
}

int gks_xform_check_viewport(const double vp[4])
{
    if (!box_ordered(vp, 2))
        return GKS_E_RECT_INVALID;
    return box_within(vp, 2, unit3) ? 0 : GKS_E_VIEWPORT_NOT_IN_NDC;
}

int gks_xform_check_window3(const double win[6])
{
    return box_ordered(win, 3) ? 0 : GKS_E_RECT_INVALID;
}

int gks_xform_check_viewport3(const double vp[6])
{
    if (!box_ordered(vp, 3))
        return GKS_E_RECT_INVALID;
    return box_within(vp, 3, unit3) ? 0 : GKS_E_VIEWPORT_NOT_IN_NDC;
}

int gks_xform_check_ws_window3(const double win[6])
{
    if (!box_ordered(win, 3))
        return GKS_E_RECT_INVALID;
    return box_within(win, 3, unit3) ? 0 : GKS_E_WS_WINDOW_NOT_IN_NDC;
}

int gks_xform_check_ws_viewport3(const double vp[6], const double dsmax[3])
{
    if (!box_ordered(vp, 3))
        return GKS_E_RECT_INVALID;
    if (!xform_finite_n(dsmax, 3))
        return GKS_E_WS_VIEWPORT_NOT_IN_DS;
    return box_within(vp, 3, dsmax) ? 0 : GKS_E_WS_VIEWPORT_NOT_IN_DS;
}

int gks_xform_check_view_clip_limits(const double lim[6])
{
    if (!box_ordered(lim, 3))
        return GKS_E_CLIP_LIMITS_INVALID;
    return box_within(lim, 3, unit3) ? 0 : GKS_E_CLIP_LIMITS_NOT_IN_NPC;
}

/* Scale of the linear map [w0,w1] → [v0,v1]; 0 for a zero-extent window. */
static double lin_scale(double w0, double w1, double v0, double v1)
{
    return (w1 > w0) ? (v1 - v0) / (w1 - w0) : 0.0;
}

int gks_xform_norm_tran3(const double win[6], const double vp[6], double m[3][4])
{
    int err = gks_xform_check_window3(win);
    if (err)
        return err;
    err = gks_xform_check_viewport3(vp);
    if (err)
        return err;
    double r[3][4] = { { 0 } };
    for (int i = 0; i < 3; i++) {
        double w = win[2 * i + 1] - win[2 * i], v = vp[2 * i + 1] - vp[2 * i];
        double s = lin_scale(win[2 * i], win[2 * i + 1], vp[2 * i], vp[2 * i + 1]);
        /* Not representable: an extent that overflows (a window of +-1e308 would map
         * everything to one point), or a scale that overflows or underflows to 0 where
         * both extents are positive (a window 4.9e-324 wide). */
        if (!isfinite(w) || (w > 0 && v > 0 && !(s > 0)))
            return GKS_E_ARITHMETIC;
        r[i][i] = s;
        r[i][3] = vp[2 * i] - s * win[2 * i];
    }
    if (!xform_finite_n(&r[0][0], 12))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}

int gks_xform_ws_tran3(const double win[6], const double vp[6], double m[4][4])
{
    if (!box_ordered(win, 3) || !box_ordered(vp, 3))
        return GKS_E_RECT_INVALID;
    double sx = (vp[1] - vp[0]) / (win[1] - win[0]);
    double sy = (vp[3] - vp[2]) / (win[3] - win[2]);
    double s = fmin(sx, sy);
    double sz = lin_scale(win[4], win[5], vp[4], vp[5]);
    double r[4][4];
    gks_xform_identity(r);
    r[0][0] = s;
    r[0][3] = vp[0] - s * win[0];
    r[1][1] = s;
    r[1][3] = vp[2] - s * win[2];
    r[2][2] = sz;
    r[2][3] = vp[4] - sz * win[4];
    if (!xform_finite_n(&r[0][0], 16))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}
