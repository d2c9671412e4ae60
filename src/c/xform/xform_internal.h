/* SPDX-License-Identifier: MIT */
/*
 * xform_internal.h -- helpers shared by the xform sources only.
 */
#ifndef XFORM_INTERNAL_H
#define XFORM_INTERNAL_H
#include <math.h>
#include <stddef.h>

/* 1 if all n values are finite. */
static inline int xform_finite_n(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}
#endif
