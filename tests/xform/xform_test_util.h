/* SPDX-License-Identifier: MIT */
/*
 * xform_test_util.h -- small helpers for the gks_xform tests (cmocka).
 */
#ifndef XFORM_TEST_UTIL_H
#define XFORM_TEST_UTIL_H
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <fenv.h>
#include <math.h>
#include <stdio.h>

#include "gks_xform.h"

#define XT_PI 3.14159265358979323846

/* Deterministic PRNG (xorshift64*), so failures reproduce. */
typedef struct { uint64_t s; } xt_rng;

static inline double xt_uniform(xt_rng *r, double lo, double hi)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    uint64_t v = r->s * 2685821657736338717ULL;
    return lo + (hi - lo) * ((double)(v >> 11) * (1.0 / 9007199254740992.0));
}

/* Assert |a − b| <= tol, printing the values on failure. */
#define XT_NEAR(a, b, tol) do {                                                          \
        double xt_a_ = (a), xt_b_ = (b), xt_t_ = (tol);                                  \
        if (!(fabs(xt_a_ - xt_b_) <= xt_t_)) {                                           \
            print_error("%s:%d: %s = %.17g, expected %s = %.17g (tol %g)\n", __FILE__,  \
                        __LINE__, #a, xt_a_, #b, xt_b_, xt_t_);                          \
            fail();                                                                      \
        }                                                                                \
    } while (0)

static inline void xt_mat4_near(const double a[4][4], const double b[4][4], double tol)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            XT_NEAR(a[i][j], b[i][j], tol);
}

/* Trap invalid / divide-by-zero / overflow (SIGFPE, reported by cmocka as a failure) in
 * tests whose input is valid and finite: no hidden NaN or infinity on the normal path.
 * (feenableexcept is a glibc extension; the tests are built with _GNU_SOURCE.) */
static inline void xt_traps_on(void)
{
    feclearexcept(FE_ALL_EXCEPT);
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
}

static inline void xt_traps_off(void)
{
    fedisableexcept(FE_ALL_EXCEPT);
    feclearexcept(FE_ALL_EXCEPT);
}

/* Apply m to (x,y,z,1) and divide; asserts w > 0. */
static inline void xt_map(const double m[4][4], double x, double y, double z, double out[3])
{
    const double p[3] = { x, y, z };
    double w = gks_xform_point(m, p, out);
    if (!(w > 0.0)) {
        print_error("w = %g <= 0 for (%g,%g,%g)\n", w, x, y, z);
        fail();
    }
}

/* Helpers the library itself does not need (tests only): the direction d = (x,y,z,0) by
 * the upper-left 3x3 block of m; the identities of 3x4 and 2x3 affine matrices; the
 * pipeline product out = ws · mapping · orientation · seg4 (seg, ws NULL: identity). */
static inline void xt_direction(const double m[4][4], const double d[3], double out[3])
{
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = m[i][0] * d[0] + m[i][1] * d[1] + m[i][2] * d[2];
    for (int i = 0; i < 3; i++)
        out[i] = t[i];
}

static inline void xt_mat34_identity(double m[3][4])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = (i == j) ? 1.0 : 0.0;
}

static inline void xt_mat23_identity(double m[2][3])
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            m[i][j] = (i == j) ? 1.0 : 0.0;
}

static inline void xt_compose_pipeline(const double seg[3][4], const double orientation[4][4],
                                       const double mapping[4][4], const double ws[4][4],
                                       double out[4][4])
{
    double r[4][4];
    if (seg)
        gks_xform_mat34_to_mat4(seg, r);
    else
        gks_xform_identity(r);
    gks_xform_multiply(orientation, r, r);
    gks_xform_multiply(mapping, r, r);
    if (ws)
        gks_xform_multiply(ws, r, r);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            out[i][j] = r[i][j];
}
#endif
