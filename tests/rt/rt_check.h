/* SPDX-License-Identifier: MIT */
/* rt_check.h -- small shared test helpers (header-only) for the gksrt tests */
#ifndef GKS3D_RT_CHECK_H
#define GKS3D_RT_CHECK_H

#include <fenv.h>
#include <math.h>
#include <stddef.h>

/* trap invalid operations and divisions by zero: infinities are not intended in the tracer
   (only +inf ray ends, which never meet 0 * inf or inf - inf) */
static inline void rtc_traps_on(void)
{
    feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(FE_INVALID | FE_DIVBYZERO);
}

static inline void rtc_traps_off(void)
{
    fedisableexcept(FE_INVALID | FE_DIVBYZERO);
}

/* number of non-finite values in an image */
static inline size_t rtc_nonfinite(const float *rgb, size_t n)
{
    size_t bad = 0;
    for (size_t i = 0; i < n; i++)
        bad += !isfinite(rgb[i]);
    return bad;
}

static inline double rtc_reldiff(double a, double b)
{
    double s = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
    return fabs(a - b) / (s > 1.0 ? s : 1.0);
}

#endif
