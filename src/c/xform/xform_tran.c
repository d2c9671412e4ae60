/* SPDX-License-Identifier: MIT */
/*
 * xform_tran.c -- EVALUATE / ACCUMULATE TRANSFORMATION MATRIX (3-D and 2-D): segment and
 * insert transformations built from fixed point, shift, rotation and scale.
 */
#include "gks_xform.h"
#include "xform_internal.h"

#include <math.h>
#include <string.h>

/* 3x3 product r = a·b (r must not alias). */
static void mul33(const double a[3][3], const double b[3][3], double r[3][3])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
}

int gks_xform_eval_tran3(const double fixed[3], const double shift[3], const double angles[3],
                         const double scale[3], double m[3][4])
{
    if (!xform_finite_n(fixed, 3) || !xform_finite_n(shift, 3) || !xform_finite_n(angles, 3)
        || !xform_finite_n(scale, 3))
        return GKS_E_ARITHMETIC;
    const double cx = cos(angles[0]), sx = sin(angles[0]);
    const double cy = cos(angles[1]), sy = sin(angles[1]);
    const double cz = cos(angles[2]), sz = sin(angles[2]);
    const double rx[3][3] = { { 1, 0, 0 }, { 0, cx, -sx }, { 0, sx, cx } };
    const double ry[3][3] = { { cy, 0, sy }, { 0, 1, 0 }, { -sy, 0, cy } };
    const double rz[3][3] = { { cz, -sz, 0 }, { sz, cz, 0 }, { 0, 0, 1 } };
    double t[3][3], l[3][3];
    mul33(ry, rx, t);
    mul33(rz, t, l);               /* L = Rz·Ry·Rx (x first) */
    for (int i = 0; i < 3; i++)    /* L = L·S (scale first of all) */
        for (int j = 0; j < 3; j++)
            l[i][j] *= scale[j];
    double r[3][4];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            r[i][j] = l[i][j];
        /* translation: fixed + shift − L·fixed */
        r[i][3] = fixed[i] + shift[i]
                  - (l[i][0] * fixed[0] + l[i][1] * fixed[1] + l[i][2] * fixed[2]);
    }
    if (!xform_finite_n(&r[0][0], 12))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}

int gks_xform_eval_tran(const double fixed[2], const double shift[2], double angle,
                        const double scale[2], double m[2][3])
{
    if (!xform_finite_n(fixed, 2) || !xform_finite_n(shift, 2) || !isfinite(angle)
        || !xform_finite_n(scale, 2))
        return GKS_E_ARITHMETIC;
    const double c = cos(angle), s = sin(angle);
    const double l[2][2] = { { c * scale[0], -s * scale[1] }, { s * scale[0], c * scale[1] } };
    double r[2][3];
    for (int i = 0; i < 2; i++) {
        r[i][0] = l[i][0];
        r[i][1] = l[i][1];
        r[i][2] = fixed[i] + shift[i] - (l[i][0] * fixed[0] + l[i][1] * fixed[1]);
    }
    if (!xform_finite_n(&r[0][0], 6))
        return GKS_E_ARITHMETIC;
    memcpy(m, r, sizeof r);
    return 0;
}

int gks_xform_accum_tran3(const double in[3][4], const double fixed[3], const double shift[3],
                          const double angles[3], const double scale[3], double out[3][4])
{
    double n[3][4], r[3][4];
    if (!xform_finite_n(&in[0][0], 12))
        return GKS_E_ARITHMETIC;
    int err = gks_xform_eval_tran3(fixed, shift, angles, scale, n);
    if (err)
        return err;
    gks_xform_mat34_multiply(n, in, r);
    if (!xform_finite_n(&r[0][0], 12))
        return GKS_E_ARITHMETIC;
    memcpy(out, r, sizeof r);
    return 0;
}

int gks_xform_accum_tran(const double in[2][3], const double fixed[2], const double shift[2],
                         double angle, const double scale[2], double out[2][3])
{
    double n[2][3], r[2][3];
    if (!xform_finite_n(&in[0][0], 6))
        return GKS_E_ARITHMETIC;
    int err = gks_xform_eval_tran(fixed, shift, angle, scale, n);
    if (err)
        return err;
    gks_xform_mat23_multiply(n, in, r);
    if (!xform_finite_n(&r[0][0], 6))
        return GKS_E_ARITHMETIC;
    memcpy(out, r, sizeof r);
    return 0;
}
