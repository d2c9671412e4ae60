/* SPDX-License-Identifier: MIT */
/*
 * xform_view.c -- view orientation and view mapping matrices (EVALUATE VIEW ORIENTATION
 * MATRIX 3, EVALUATE VIEW MAPPING MATRIX 3 and their 2-D forms), camera recovery.
 * Formulas: BINDINGS.md §3.2, §3.3 (closed forms; the matrix entries are derived from them).
 */
#include "gks_xform.h"
#include "xform_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* out = a / |a| computed without overflow; 0 if a is zero or not finite. */
static int unit_vec(const double *a, int n, double *out)
{
    if (!xform_finite_n(a, (size_t)n))
        return 0;
    double mx = 0.0;
    for (int i = 0; i < n; i++)
        mx = fmax(mx, fabs(a[i]));
    if (mx == 0.0)
        return 0;
    double s[3], len = 0.0;
    for (int i = 0; i < n; i++) {
        s[i] = a[i] / mx;
        len += s[i] * s[i];
    }
    len = sqrt(len);
    for (int i = 0; i < n; i++)
        out[i] = s[i] / len;
    return 1;
}

static void cross(const double a[3], const double b[3], double r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int gks_xform_eval_view_orientation3(const double vrp[3], const double vpn[3],
                                     const double vup[3], double m[4][4])
{
    double n[3], up[3], c[3], u[3], v[3];
    if (!unit_vec(vpn, 3, n))
        return GKS_E_VPN_ZERO;
    if (!unit_vec(vup, 3, up))
        return GKS_E_VUP_ZERO;
    cross(up, n, c);
    if (!(sqrt(dot3(c, c)) > 16.0 * DBL_EPSILON))
        return GKS_E_VIEW_UP_PARALLEL;
    if (!xform_finite_n(vrp, 3))
        return GKS_E_ARITHMETIC;
    (void)unit_vec(c, 3, u);
    cross(n, u, v);
    double r[4][4] = {
        { u[0], u[1], u[2], -dot3(u, vrp) },
        { v[0], v[1], v[2], -dot3(v, vrp) },
        { n[0], n[1], n[2], -dot3(n, vrp) },
        { 0.0, 0.0, 0.0, 1.0 },
    };
    if (!xform_finite_n(&r[0][0], 16))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}

/* Window umin < umax, vmin < vmax, finite. */
static int window_ok(const double w[4])
{
    return xform_finite_n(w, 4) && w[0] < w[1] && w[2] < w[3];
}

/* Viewport x/y strictly ordered, zmin <= zmax (dims 3), finite. */
static int viewport_ok(const double *p, int dims)
{
    if (!xform_finite_n(p, (size_t)(2 * dims)) || !(p[0] < p[1]) || !(p[2] < p[3]))
        return 0;
    return dims < 3 || p[4] <= p[5];
}

static int viewport_in_npc(const double *p, int dims)
{
    for (int i = 0; i < 2 * dims; i++)
        if (!(p[i] >= 0.0 && p[i] <= 1.0))
            return 0;
    return 1;
}

/* The error checks of EVALUATE VIEW MAPPING MATRIX 3 in their documented order. */
static int view_mapping3_check(const gks_xform_view_map3 *mp)
{
    const double pn = mp->prp[2], B = mp->bpd, F = mp->fpd;
    const int persp = mp->proj_type == GKS_XFORM_PERSPECTIVE;

    if (mp->proj_type != GKS_XFORM_PARALLEL && !persp)
        return GKS_E_ENUM_RANGE;
    if (!window_ok(mp->window))
        return GKS_E_VIEW_WINDOW_INVALID;
    if (!viewport_ok(mp->viewport, 3))
        return GKS_E_PROJ_VIEWPORT_INVALID;
    if (!xform_finite_n(mp->prp, 3) || !isfinite(mp->vpd) || !isfinite(B) || !isfinite(F))
        return GKS_E_ARITHMETIC;
    if (F == B && mp->viewport[4] != mp->viewport[5])
        return GKS_E_FRONT_BACK_EQUAL;
    if (persp && (pn == B || pn == F || (B < pn && pn < F)))
        return GKS_E_PRP_BETWEEN_PLANES;
    if (pn == mp->vpd)
        return GKS_E_PRP_ON_VIEW_PLANE;
    if (F < B)
        return GKS_E_BACK_IN_FRONT;
    if (!viewport_in_npc(mp->viewport, 3))
        return GKS_E_PROJ_VIEWPORT_NOT_IN_NPC;
    return 0;
}

int gks_xform_eval_view_mapping3(const gks_xform_view_map3 *mp, double m[4][4])
{
    int err = view_mapping3_check(mp);
    if (err)
        return err;

    const double *w = mp->window, *p = mp->viewport;
    const double pu = mp->prp[0], pv = mp->prp[1], pn = mp->prp[2];
    const double vpd = mp->vpd, B = mp->bpd, F = mp->fpd;
    const double cu = 0.5 * w[0] + 0.5 * w[1], cv = 0.5 * w[2] + 0.5 * w[3];
    const double sx = (p[1] - p[0]) / (w[1] - w[0]);
    const double sy = (p[3] - p[2]) / (w[3] - w[2]);
    const double dz = p[5] - p[4];
    double r[4][4] = { { 0 } };

    if (mp->proj_type == GKS_XFORM_PARALLEL) {
        /* Shear along the direction of projection onto the view plane, then window →
         * viewport in x, y; n linear from B → zmin to F → zmax. */
        const double hx = (pu - cu) / (vpd - pn), hy = (pv - cv) / (vpd - pn);
        const double szn = (F != B) ? dz / (F - B) : 0.0;
        r[0][0] = sx;
        r[0][2] = sx * hx;
        r[0][3] = p[0] - sx * (hx * vpd + w[0]);
        r[1][1] = sy;
        r[1][2] = sy * hy;
        r[1][3] = p[2] - sy * (hy * vpd + w[2]);
        r[2][2] = szn;
        r[2][3] = p[4] - szn * B;
        r[3][3] = 1.0;
    } else {
        /* w = s(pn − n), s = 1/(pn − B). With ax = xmin − Sx·umin and d = pn − VPD:
         * w·x = s[Sx·d·u − (Sx·pu + ax)·n + Sx·pu·VPD + ax·pn] (projection through the PRP
         * onto the view plane, then window → viewport); w·z = s(pn − n)·zmin + Kz(n − B)
         * with Kz = Dz·s·(pn − F)/(F − B), so that B → zmin, F → zmax. */
        const double s = 1.0 / (pn - B), d = pn - vpd;
        const double ax = p[0] - sx * w[0], ay = p[2] - sy * w[2];
        const double kz = (F != B) ? dz * s * (pn - F) / (F - B) : 0.0;
        r[0][0] = s * sx * d;
        r[0][2] = -s * (sx * pu + ax);
        r[0][3] = s * (sx * pu * vpd + ax * pn);
        r[1][1] = s * sy * d;
        r[1][2] = -s * (sy * pv + ay);
        r[1][3] = s * (sy * pv * vpd + ay * pn);
        r[2][2] = kz - s * p[4];
        r[2][3] = s * pn * p[4] - kz * B;
        r[3][2] = -s;
        r[3][3] = s * pn;
    }
    if (!xform_finite_n(&r[0][0], 16))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}

/* 3x3 determinant of columns c0, c1, c2 of the 3x4 rows r. */
static double det3_cols(const double r[3][4], int c0, int c1, int c2)
{
    return r[0][c0] * (r[1][c1] * r[2][c2] - r[1][c2] * r[2][c1])
           - r[0][c1] * (r[1][c0] * r[2][c2] - r[1][c2] * r[2][c0])
           + r[0][c2] * (r[1][c0] * r[2][c1] - r[1][c1] * r[2][c0]);
}

int gks_xform_view_camera(const double m[4][4], double eye[3], int *perspective)
{
    /* P spans the null space of the x, y and w rows: M·P = (0, 0, c, 0), i.e. the point (or
     * direction) every projector passes through. Computed as the generalized cross product
     * of the three rows (signed 3x3 minors), after scaling each row to unit max-norm. This
     * needs no inverse, so it also works for a flat projection viewport (zmin == zmax),
     * where M is singular. */
    if (!xform_finite_n(&m[0][0], 16))
        return GKS_E_ARITHMETIC;
    const int rows[3] = { 0, 1, 3 };
    double r[3][4];
    for (int i = 0; i < 3; i++) {
        double mx = 0.0;
        for (int j = 0; j < 4; j++)
            mx = fmax(mx, fabs(m[rows[i]][j]));
        if (mx == 0.0)
            return GKS_E_ARITHMETIC;
        for (int j = 0; j < 4; j++)
            r[i][j] = m[rows[i]][j] / mx;
    }
    double P[4] = { det3_cols(r, 1, 2, 3), -det3_cols(r, 0, 2, 3), det3_cols(r, 0, 1, 3),
                    -det3_cols(r, 0, 1, 2) };
    const double mx = fmax(fabs(P[0]), fmax(fabs(P[1]), fmax(fabs(P[2]), fabs(P[3]))));
    if (!(mx > 64.0 * DBL_EPSILON))   /* the rows are (numerically) dependent */
        return GKS_E_ARITHMETIC;
    const double mxyz = fmax(fabs(P[0]), fmax(fabs(P[1]), fabs(P[2])));
    if (fabs(P[3]) > 1e-12 * mxyz) {
        double e[3] = { P[0] / P[3], P[1] / P[3], P[2] / P[3] };
        if (!xform_finite_n(e, 3))
            return GKS_E_ARITHMETIC;
        memcpy(eye, e, sizeof e);
        *perspective = 1;
        return 0;
    }
    /* parallel: orient towards NPC +z (the viewer) when the z row allows it */
    const double cz = m[2][0] * P[0] + m[2][1] * P[1] + m[2][2] * P[2];
    if (cz < 0.0)
        for (int i = 0; i < 3; i++)
            P[i] = -P[i];
    double dir[3];
    if (!unit_vec(P, 3, dir))
        return GKS_E_ARITHMETIC;
    memcpy(eye, dir, sizeof dir);
    *perspective = 0;
    return 0;
}
