/* SPDX-License-Identifier: MIT */
/*
 * test_rt_alloc.c -- the tracer's allocation funnel (src/rt/rt_alloc.c): arrays grown by
 * rt_grow and rt_big_grow keep their values; an rt_big, once large, never moves again and
 * (on Linux) is one mapping, so growing it touches only the pages it newly uses; sizes that
 * overflow are refused without changing anything; rt_alloc_lines' arrays start on a cache
 * line.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_testutil.h"

/* lines of /proc/self/maps that overlap [p, p + n); -1 if the file cannot be read */
static int mappings_over(const void *p, size_t n)
{
    FILE *f = fopen("/proc/self/maps", "r");
    if (!f)
        return -1;
    const uintptr_t a = (uintptr_t)p, e = a + n;
    unsigned long lo, hi;
    char line[512];
    int k = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "%lx-%lx", &lo, &hi) == 2 && lo < e && hi > a)
            k++;
    fclose(f);
    return k;
}

static uint32_t val(size_t i) { return (uint32_t)(i * 2654435761u); }

static void test_big(void **u)
{
    (void)u;
    rt_big b = { 0 };
    const size_t n = (size_t)24 << 20; /* 96 MB at the end */
    void *fixed = NULL;
    for (size_t i = 0; i < n; i++) {
        if (i == b.cap) {
            assert_true(rt_big_grow(&b, i + 1, sizeof(uint32_t)));
            assert_true(b.cap > i);
            if (fixed) /* reserved: it grows in place */
                assert_ptr_equal(b.p, fixed);
            else if (b.map_bytes) {
                fixed = b.p;
                int m = mappings_over(b.p, b.map_bytes);
                if (m >= 0)
                    assert_int_equal(m, 1);
            }
        }
        ((uint32_t *)b.p)[i] = val(i);
    }
    assert_true(rt_big_grow(&b, n, sizeof(uint32_t))); /* room already: nothing to do */
    for (size_t i = 0; i < n; i += 4099)
        assert_int_equal(((uint32_t *)b.p)[i], val(i));
#if defined(__linux__)
    assert_non_null(fixed); /* Linux reserves address space for it (unless refused) */
#endif
    rt_big_free(&b);
    assert_null(b.p);
    assert_int_equal(b.cap, 0);
    rt_big_free(&b); /* twice: harmless */
    rt_big e = { 0 };
    assert_false(rt_big_grow(&e, SIZE_MAX / 2, 8));
    assert_null(e.p);
}

static void test_grow(void **u)
{
    (void)u;
    uint32_t *v = NULL;
    size_t cap = 0;
    const size_t n = (size_t)3 << 20;
    for (size_t i = 0; i < n; i++) {
        if (i == cap)
            assert_true(rt_grow((void **)&v, &cap, i + 1, sizeof *v));
        v[i] = val(i);
    }
    for (size_t i = 0; i < n; i += 997)
        assert_int_equal(v[i], val(i));
    free(v);
}

static void test_sizes(void **u)
{
    (void)u;
    assert_null(rt_alloc_array(SIZE_MAX / 2, 4));
    assert_null(rt_calloc_array(SIZE_MAX / 2, 4));
    void *p = rt_alloc_array(0, 8);
    assert_non_null(p);
    free(p);
    void *q = NULL;
    size_t cap = 0;
    assert_false(rt_grow(&q, &cap, SIZE_MAX / 2, 8));
    assert_null(q);
    assert_int_equal(cap, 0);
    assert_null(rt_alloc_lines(SIZE_MAX / 2, 4));
    assert_null(rt_alloc_lines(1, SIZE_MAX - 8));
    const size_t n[] = {0, 1, 3, 17, 1000};
    for (size_t k = 0; k < sizeof n / sizeof n[0]; k++) {
        unsigned char *l = rt_alloc_lines(n[k], sizeof(rt_subgrid));
        assert_non_null(l);
        assert_int_equal((uintptr_t)l % RT_LINE, 0);
        memset(l, 0xA5, n[k] * sizeof(rt_subgrid)); /* all of it usable (valgrind, ASan) */
        free(l);
    }
}

/* rt_scene_input_next: no ranges while the triangle arrays are on malloc; once they are
 * reserved, where the next triangles go, moving on by one triangle's bytes per triangle */
static void test_input_next(void **u)
{
    (void)u;
    int surf;
    rt_scene *sc = rtu_scene_one_surface(&surf);
    assert_non_null(sc);
    void *lo[2], *hi[2];
    const int cnt[1] = { 3 };
    const size_t big = ((size_t)8 << 20) / sizeof(rt_prim); /* both arrays beyond 4 MiB */
    for (size_t i = 0; i <= big; i++) {
        const double x = (double)(i % 1000), y = (double)(i / 1000);
        const double v[9] = { x, y, 0, x + 1, y, 0, x, y + 1, 0 };
        if (i == 10)
            assert_int_equal(rt_scene_input_next(sc, 100, lo, hi), 0);
        assert_true(rt_scene_add_polygon(sc, 1, cnt, v, surf, surf) >= 0);
    }
#if defined(__linux__) /* the arrays are reserved mappings there (rt_big) */
    assert_int_equal(rt_scene_input_next(sc, 100, lo, hi), 2);
    assert_int_equal((char *)hi[0] - (char *)lo[0], 100 * sizeof(rt_tri));
    assert_int_equal((char *)hi[1] - (char *)lo[1], 100 * sizeof(rt_prim));
    void *lo2[2], *hi2[2];
    const double v[9] = { 0, 0, 1, 1, 0, 1, 0, 1, 1 };
    assert_true(rt_scene_add_polygon(sc, 1, cnt, v, surf, surf) >= 0);
    assert_int_equal(rt_scene_input_next(sc, 100, lo2, hi2), 2);
    assert_ptr_equal(lo2[0], (char *)lo[0] + sizeof(rt_tri));
    assert_ptr_equal(lo2[1], (char *)lo[1] + sizeof(rt_prim));
#endif
    rt_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_big),
        cmocka_unit_test(test_grow),
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_input_next),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
