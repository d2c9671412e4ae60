/* SPDX-License-Identifier: MIT */
/*
 * test_rt_polygon.c -- the point-in-polygon grid of big polygons (src/rt/rt_polygon.c)
 * answers exactly as the crossing rule of rt_isect_poly over all edges: self-intersecting
 * stars with long edges, a many-turn spiral, random chords, and a lattice polygon whose
 * horizontal and vertical edges and vertices lie on each other's lines, queried at random
 * points and at the hard ones (vertices, edge midpoints, the grid's own lines and corners).
 * No tolerance: every answer must be the rule's.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>
#include "rt_polygon.h"

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* the rule of rt_isect_poly over every edge of the loops */
static int brute(const double *uv, const uint32_t *counts, uint32_t nloops, double pu, double pv)
{
    int in = 0;
    const double *lu = uv;
    for (uint32_t l = 0; l < nloops; l++) {
        const double *q = lu + 2 * (size_t)(counts[l] - 1);
        for (uint32_t i = 0; i < counts[l]; i++) {
            const double *a = lu + 2 * (size_t)i;
            if (a[1] != q[1]) {
                const double *lo = q[1] < a[1] ? q : a, *hi = q[1] < a[1] ? a : q;
                int st = (lo[1] <= pv) & (pv < hi[1]);
                int cr = (pv - lo[1]) * (hi[0] - lo[0]) > (pu - lo[0]) * (hi[1] - lo[1]);
                in ^= st & cr;
            }
            q = a;
        }
        lu += 2 * (size_t)counts[l];
    }
    return in;
}

static void check(const double *uv, const uint32_t *counts, uint32_t nloops, int nrand,
                  const char *what)
{
    size_t nv = 0;
    for (uint32_t l = 0; l < nloops; l++)
        nv += counts[l];
    double b[4] = { INFINITY, -INFINITY, INFINITY, -INFINITY };
    for (size_t i = 0; i < nv; i++) {
        b[0] = fmin(b[0], uv[2 * i]);
        b[1] = fmax(b[1], uv[2 * i]);
        b[2] = fmin(b[2], uv[2 * i + 1]);
        b[3] = fmax(b[3], uv[2 * i + 1]);
    }
    rt_pgrid g;
    assert_int_equal(rt_pgrid_build(&g, uv, counts, nloops, b[0], b[1], b[2], b[3]), 0);
    assert_true(g.gu * g.gv > 1);
    long n = 0, bad = 0, inside = 0;
#define Q(U, V)                                                                          \
    do {                                                                                 \
        double qu_ = (U), qv_ = (V);                                                     \
        if (qu_ >= b[0] && qu_ <= b[1] && qv_ >= b[2] && qv_ <= b[3]) {                  \
            int w_ = brute(uv, counts, nloops, qu_, qv_);                                \
            inside += w_;                                                                \
            n++;                                                                         \
            if (rt_pgrid_parity(&g, qu_, qv_) != w_ && bad++ < 5)                        \
                fprintf(stderr, "%s: (%.17g, %.17g) grid %d, rule %d\n", what, qu_, qv_, \
                        !w_, w_);                                                        \
        }                                                                                \
    } while (0)
    for (int k = 0; k < nrand; k++)
        Q(b[0] + (b[1] - b[0]) * rnd(), b[2] + (b[3] - b[2]) * rnd());
    for (size_t i = 0; i < nv; i += 1 + nv / 500) { /* vertices, edge midpoints, neighbours */
        size_t j = (i + 1) % nv;
        Q(uv[2 * i], uv[2 * i + 1]);
        Q(0.5 * (uv[2 * i] + uv[2 * j]), 0.5 * (uv[2 * i + 1] + uv[2 * j + 1]));
        Q(nextafter(uv[2 * i], INFINITY), uv[2 * i + 1]);
        Q(uv[2 * i], nextafter(uv[2 * i + 1], -INFINITY));
    }
    for (int k = 0; k < 600; k++) { /* the grid's lines and corners */
        int i = (int)(rnd() * (g.gu + 1)), j = (int)(rnd() * (g.gv + 1));
        if (i > g.gu) i = g.gu;
        if (j > g.gv) j = g.gv;
        Q(g.xs[i], b[2] + (b[3] - b[2]) * rnd());
        Q(b[0] + (b[1] - b[0]) * rnd(), g.vs[j]);
        Q(g.xs[i], g.vs[j]);
    }
#undef Q
    printf("%s: %zu edges, grid %d x %d, %zu entries (%.1f per edge), %ld queries (%ld "
           "inside), %ld differ\n", what, g.ne, g.gu, g.gv, g.nref,
           (double)g.nref / (double)g.ne, n, inside, bad);
    rt_pgrid_free(&g);
    assert_int_equal(bad, 0);
    assert_true(inside > 0 && inside < n);
}

static void star(double *uv, uint32_t n, uint32_t k)
{
    for (uint32_t i = 0; i < n; i++) {
        double a = 6.283185307179586 * (double)(((uint64_t)i * k) % n) / (double)n;
        uv[2 * i] = 0.5 + 0.45 * cos(a);
        uv[2 * i + 1] = 0.5 + 0.45 * sin(a);
    }
}

static void test_stars(void **u)
{
    (void)u;
    uint32_t n = 2003; /* prime */
    double *uv = malloc(2 * sizeof(double) * n);
    assert_non_null(uv);
    star(uv, n, n / 2 - 1);
    check(uv, &n, 1, 15000, "star n/2-1");
    star(uv, n, 7);
    check(uv, &n, 1, 15000, "star 7 turns");
    uint32_t m = 1201;
    star(uv, m, 500);
    check(uv, &m, 1, 15000, "star 1201/500");
    free(uv);
}

static void test_spiral_and_random(void **u)
{
    (void)u;
    uint32_t n = 4000;
    double *uv = malloc(2 * sizeof(double) * n);
    assert_non_null(uv);
    for (uint32_t i = 0; i < n; i++) {
        double s = (double)i / n, a = 6.283185307179586 * 40.0 * s, r = 1.0 - 0.5 * s;
        uv[2 * i] = 3.0 + r * cos(a);
        uv[2 * i + 1] = -2.0 + r * sin(a);
    }
    check(uv, &n, 1, 15000, "spiral 40 turns");
    for (uint32_t i = 0; i < 2 * n; i++)
        uv[i] = 100.0 * rnd();
    check(uv, &n, 1, 15000, "random chords");
    free(uv);
}

/* Two loops on an integer lattice (the second a hole crossing the first): horizontal and
 * vertical edges, vertices on the lines of other edges, many at the same u or v. */
static void test_lattice(void **u)
{
    (void)u;
    enum { N = 1500 };
    double *uv = malloc(2 * sizeof(double) * 2 * N);
    assert_non_null(uv);
    uint32_t counts[2] = { N, N };
    for (int l = 0; l < 2; l++) {
        int x = l * 3, y = l * 2;
        for (int i = 0; i < N; i++) { /* a staircase walk, horizontal and vertical steps */
            uv[2 * (l * N + i)] = x;
            uv[2 * (l * N + i) + 1] = y;
            int step = (int)(rnd() * 11.0) - 5;
            if (i % 2)
                x = abs(x + step) % 64;
            else
                y = abs(y + step) % 48;
        }
    }
    check(uv, counts, 2, 15000, "lattice, two loops");
    free(uv);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stars),
        cmocka_unit_test(test_spiral_and_random),
        cmocka_unit_test(test_lattice),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
