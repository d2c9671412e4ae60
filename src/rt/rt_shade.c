/* SPDX-License-Identifier: MIT */
/*
 * rt_shade.c -- local shading shared by the tracer and the classic HLHSR modes (rt_shade.h).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_shade.h"

#include <math.h>
#include <string.h>

/* length without overflow or underflow in the squares */
static double len3(const double v[3])
{
    double m = rt_sh_absmax3(v);
    if (m == 0.0 || !isfinite(m))
        return m;
    double a = v[0] / m, b = v[1] / m, c = v[2] / m;
    return m * sqrt(a * a + b * b + c * c);
}

int rt_newell_normal(const double *v, size_t nv, const int *counts, int nloops, const double c[3],
                     double ext, double n[3])
{
    n[0] = n[1] = n[2] = 0.0;
    size_t base = 0;
    for (int k = 0; k < nloops; k++) {
        size_t m = (size_t)counts[k];
        for (size_t i = 0; i < m; i++) {
            const double *a = v + 3 * (base + i), *b = v + 3 * (base + (i + 1) % m);
            double ax = a[0] - c[0], ay = a[1] - c[1], az = a[2] - c[2];
            double bx = b[0] - c[0], by = b[1] - c[1], bz = b[2] - c[2];
            n[0] += (ay - by) * (az + bz);
            n[1] += (az - bz) * (ax + bx);
            n[2] += (ax - bx) * (ay + by);
        }
        base += m;
    }
    double tol = 1e-12 * ext * ext;
    double len = len3(n);
    if (len > tol && isfinite(len)) {
        for (int i = 0; i < 3; i++)
            n[i] /= len;
        return 1;
    }
    double best = 0.0, bn[3] = {0, 0, 0};
    for (size_t i = 1; i + 1 < nv; i++) {
        double e1[3], e2[3], x[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = v[3 * i + j] - v[j];
            e2[j] = v[3 * (i + 1) + j] - v[j];
        }
        x[0] = e1[1] * e2[2] - e1[2] * e2[1];
        x[1] = e1[2] * e2[0] - e1[0] * e2[2];
        x[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double l = len3(x);
        if (l > best) {
            best = l;
            memcpy(bn, x, sizeof bn);
        }
    }
    if (!(best > tol) || !isfinite(best))
        return 0;
    for (int i = 0; i < 3; i++)
        n[i] = bn[i] / best;
    return 1;
}
