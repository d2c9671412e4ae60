/* SPDX-License-Identifier: MIT */
/*
 * test_rt_normal.c -- a triangle's unit normal at its hits (rt_tri_unit_normal, rt_geom.h:
 * one cross product and one square root) against the add-time Newell normal
 * (rt_tri_normal_sane): the same direction within 1e-13 (both round by ~1e-16 per operation;
 * the bound leaves room for the ill-conditioned but accepted triangles), unit length within
 * 1e-15, and rt_tri_normal_sane's own result where the cross product would lose digits (a
 * sliver) or leave the double range (coordinates of 1e150 and 1e-150), bit for bit.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"

static double urand(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) * 0x1p-53;
}

static void check_close(const double *v0, const double *v1, const double *v2)
{
    double a[3], b[3];
    if (!rt_tri_normal_sane(v0, v1, v2, a))
        return; /* degenerate: never committed */
    rt_tri_unit_normal(v0, v1, v2, b);
    const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const double len = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    assert_true(dot > 1.0 - 1e-13);
    assert_true(fabs(len - 1.0) < 1e-15);
}

/* random triangles of all shapes and scales and offsets */
static void test_normal_random(void **state)
{
    (void)state;
    uint64_t s = 42;
    for (int k = 0; k < 200000; k++) {
        const double scale = pow(10.0, -6.0 + 12.0 * urand(&s));
        const double off = (urand(&s) - 0.5) * pow(10.0, 4.0 * urand(&s));
        double v[3][3];
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                v[i][j] = off + scale * (urand(&s) - 0.5);
        if (k % 4 == 0) /* thin: the third vertex near the first edge */
            for (int j = 0; j < 3; j++)
                v[2][j] = v[0][j] + 0.5 * (v[1][j] - v[0][j]) + 1e-6 * scale * (urand(&s) - 0.5);
        check_close(v[0], v[1], v[2]);
    }
}

/* where the cross product is not used: rt_tri_normal_sane's bits */
static void test_normal_fallback(void **state)
{
    (void)state;
    const double big[3][3] = {{1e150, 0, 0}, {0, 1e150, 0}, {0, 0, 1e150}};
    const double tiny[3][3] = {{1e-150, 0, 0}, {0, 1e-150, 0}, {0, 0, 1e-150}};
    const double sliver[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, 3e-12, 0}};
    const double(*const tris[3])[3] = {big, tiny, sliver};
    for (int k = 0; k < 3; k++) {
        double a[3], b[3];
        assert_true(rt_tri_normal_sane(tris[k][0], tris[k][1], tris[k][2], a));
        rt_tri_unit_normal(tris[k][0], tris[k][1], tris[k][2], b);
        assert_memory_equal(a, b, sizeof a);
    }
    /* and an ordinary one takes the cross product: exactly (0, 0, 1) */
    const double v[3][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
    double n[3];
    rt_tri_unit_normal(v[0], v[1], v[2], n);
    assert_true(n[0] == 0.0 && n[1] == 0.0 && n[2] == 1.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_normal_random),
        cmocka_unit_test(test_normal_fallback),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
