/* SPDX-License-Identifier: MIT */
/*
 * test_gksm.c -- the GKS metafile codec: exact round trips of integers, reals and strings,
 * reading RAL-format files, and untrusted input (truncation, bad headers, wrong lengths,
 * garbage) giving the standard's errors 162/163/165, never a crash.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include "gks_mf_codec.h"

/* A metafile in memory as a FILE (tmpfile, so the reader can seek). */
static FILE *mem_file(const char *data, size_t n)
{
    FILE *fp = tmpfile();
    assert_non_null(fp);
    if (n)
        assert_int_equal(fwrite(data, 1, n, fp), n);
    rewind(fp);
    return fp;
}

static char *slurp(FILE *fp, size_t *n)
{
    long end;
    assert_int_equal(fseek(fp, 0, SEEK_END), 0);
    end = ftell(fp);
    rewind(fp);
    char *b = malloc((size_t)end + 1);
    assert_non_null(b);
    assert_int_equal(fread(b, 1, (size_t)end, fp), (size_t)end);
    *n = (size_t)end;
    return b;
}

static void test_round_trip(void **u)
{
    (void)u;
    FILE *fp = tmpfile();
    assert_non_null(fp);
    assert_int_equal(gksm_write_header(fp, "test", "26/11/24"), 0);
    assert_int_equal(ftell(fp), GKSM_HEADER_LEN);
    const double reals[] = { 0.0, -0.0, 1.0, 1.0 / 3.0, -2.5e-300, 1.7976931348623157e308,
                             4.9e-324, 0.1 + 0.2, -123456.789 };
    const long ints[] = { 0, 1, -1, 2147483647L, -2147483647L, 12345 };
    gksm_rec r;
    gksm_rec_init(&r);
    for (size_t i = 0; i < sizeof ints / sizeof *ints; i++)
        gksm_rec_int(&r, ints[i]);
    for (size_t i = 0; i < sizeof reals / sizeof *reals; i++)
        gksm_rec_real(&r, reals[i]);
    gksm_rec_str(&r, "Hello, GKSM\n", 12);
    assert_int_equal(gksm_write_item(fp, 11, &r), 0);
    assert_int_equal(gksm_write_item(fp, 0, NULL), 0); /* END item: empty record */
    assert_int_equal(gksm_write_item(fp, 1000, &r), 161);
    gksm_rec_free(&r);

    rewind(fp);
    gksm_in m;
    assert_int_equal(gksm_in_open(&m, fp), 0);
    int type;
    size_t len, got;
    assert_int_equal(gksm_in_peek(&m, &type, &len), 0);
    assert_int_equal(type, 11);
    assert_int_equal(gksm_in_peek(&m, &type, &len), 0); /* peek is idempotent */
    assert_int_equal(type, 11);
    char *buf = malloc(len);
    assert_non_null(buf);
    assert_int_equal(gksm_in_read(&m, buf, len, &got), 0);
    assert_int_equal(got, len);
    gksm_cur c;
    gksm_cur_init(&c, &m, buf, got);
    for (size_t i = 0; i < sizeof ints / sizeof *ints; i++) {
        long v;
        assert_int_equal(gksm_get_int(&c, &v), 0);
        assert_int_equal(v, ints[i]);
    }
    for (size_t i = 0; i < sizeof reals / sizeof *reals; i++) {
        double v;
        assert_int_equal(gksm_get_real(&c, &v), 0);
        /* bit-exact, including the sign of zero */
        assert_memory_equal(&v, &reals[i], sizeof v);
    }
    const char *s;
    size_t n;
    assert_int_equal(gksm_get_str(&c, &s, &n), 0);
    assert_int_equal(n, 12);
    assert_memory_equal(s, "Hello, GKSM\n", 12);
    assert_int_equal(gksm_cur_left(&c), 0);
    long v;
    assert_int_equal(gksm_get_int(&c, &v), 165);
    free(buf);
    assert_int_equal(gksm_in_peek(&m, &type, &len), 0);
    assert_int_equal(type, 0);
    assert_int_equal(len, 0);
    assert_int_equal(gksm_in_skip(&m), 0);
    assert_int_equal(gksm_in_peek(&m, &type, &len), 162);
    fclose(fp);
}

/* A file in RAL's layout (H=1, T=3, L=7, I=4, R=9 as F9.6): polyline of two points. */
static void test_ral_layout(void **u)
{
    (void)u;
    char f[512];
    int k = snprintf(f, sizeof f, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", "RAL GKS",
                     "92/01/01", 1, 1, 3, 7, 4, 9, 1, 1, 0, 1);
    assert_int_equal(k, GKSM_HEADER_LEN);
    k += snprintf(f + k, sizeof f - (size_t)k, "G 11%7d%4d%9.6f%9.6f%9.6f%9.6f", 40, 2, 0.125,
                  0.25, 0.875, -0.5);
    FILE *fp = mem_file(f, (size_t)k);
    gksm_in m;
    assert_int_equal(gksm_in_open(&m, fp), 0);
    int type;
    size_t len, got;
    assert_int_equal(gksm_in_peek(&m, &type, &len), 0);
    assert_int_equal(type, 11);
    assert_int_equal(len, 40);
    char buf[40];
    assert_int_equal(gksm_in_read(&m, buf, sizeof buf, &got), 0);
    gksm_cur c;
    gksm_cur_init(&c, &m, buf, got);
    long n;
    double x[4];
    assert_int_equal(gksm_get_int(&c, &n), 0);
    assert_int_equal(n, 2);
    for (int i = 0; i < 4; i++)
        assert_int_equal(gksm_get_real(&c, &x[i]), 0);
    assert_true(x[0] == 0.125 && x[1] == 0.25 && x[2] == 0.875 && x[3] == -0.5);
    assert_int_equal(gksm_in_peek(&m, &type, &len), 162);
    fclose(fp);
}

/* Reading a short buffer stores the prefix and skips the rest of the record. */
static void test_short_buffer(void **u)
{
    (void)u;
    FILE *fp = tmpfile();
    gksm_rec r;
    gksm_rec_init(&r);
    gksm_rec_raw(&r, "abcdefghij", 10);
    assert_int_equal(gksm_write_header(fp, NULL, NULL), 0);
    assert_int_equal(gksm_write_item(fp, 101, &r), 0);
    assert_int_equal(gksm_write_item(fp, 102, &r), 0);
    gksm_rec_free(&r);
    rewind(fp);
    gksm_in m;
    assert_int_equal(gksm_in_open(&m, fp), 0);
    char buf[4];
    size_t got;
    assert_int_equal(gksm_in_read(&m, buf, sizeof buf, &got), 0);
    assert_int_equal(got, 4);
    assert_memory_equal(buf, "abcd", 4);
    int type;
    size_t len;
    assert_int_equal(gksm_in_peek(&m, &type, &len), 0);
    assert_int_equal(type, 102);
    fclose(fp);
}

/* A valid two-item file, then every truncation of it and corrupted bytes at every
 * position: the reader returns 0/162/163/165 and never reads out of bounds (ASan). */
static void test_hostile(void **u)
{
    (void)u;
    FILE *fp = tmpfile();
    gksm_rec r;
    gksm_rec_init(&r);
    gksm_rec_int(&r, 3);
    for (int i = 0; i < 6; i++)
        gksm_rec_real(&r, i * 0.25);
    gksm_rec_str(&r, "xyz", 3);
    assert_int_equal(gksm_write_header(fp, "hostile", "26/11/24"), 0);
    assert_int_equal(gksm_write_item(fp, 11, &r), 0);
    assert_int_equal(gksm_write_item(fp, 0, NULL), 0);
    gksm_rec_free(&r);
    size_t n;
    char *good = slurp(fp, &n);
    fclose(fp);

    int n_ok = 0, n_err = 0;
    for (size_t cut = 0; cut <= n; cut++) {
        for (int mode = 0; mode < 4; mode++) {
            char *b = malloc(n + 1);
            memcpy(b, good, n);
            size_t len = cut;
            if (mode > 0) { /* corrupt one byte at `cut`, full length */
                len = n;
                if (cut == n) {
                    free(b);
                    continue;
                }
                b[cut] = mode == 1 ? 'X' : mode == 2 ? '9' : '\0';
            }
            FILE *f = mem_file(b, len);
            gksm_in m;
            int e = gksm_in_open(&m, f);
            int items = 0;
            while (e == 0 && items < 10) {
                int type;
                size_t il;
                e = gksm_in_peek(&m, &type, &il);
                if (e)
                    break;
                assert_true(il <= n); /* never more than the file holds */
                char *rec = malloc(il ? il : 1);
                size_t got;
                e = gksm_in_read(&m, rec, il, &got);
                if (!e) {
                    gksm_cur c;
                    gksm_cur_init(&c, &m, rec, got);
                    long k;
                    double x;
                    const char *s;
                    size_t sn;
                    int de = 0;
                    if (type == 11) {
                        de |= gksm_get_int(&c, &k);
                        for (int i = 0; i < 6; i++)
                            de |= gksm_get_real(&c, &x);
                        de |= gksm_get_str(&c, &s, &sn);
                        assert_true(de == 0 || de == 165);
                        if (!de)
                            assert_true(isfinite(x) && sn <= got);
                    }
                }
                free(rec);
                items++;
            }
            assert_true(items < 10);
            assert_true(e == 0 || e == 162 || e == 163);
            if (e == 162)
                n_ok++;
            else
                n_err++;
            fclose(f);
            free(b);
        }
    }
    /* The untouched full file reads to its end; truncations inside items fail. */
    assert_true(n_ok >= 1);
    assert_true(n_err > (int)n);
    free(good);
}

/* Header fields out of their ranges are refused (163), as is a non-GKSM file. */
static void test_bad_headers(void **u)
{
    (void)u;
    const int bad[][8] = {
        { 1, 5, 3, 7, 4, 9, 1, 1 },  /* H > 4 */
        { 1, 1, 0, 7, 4, 9, 1, 1 },  /* T = 0 */
        { 1, 1, 3, 11, 4, 9, 1, 1 }, /* L > 10 */
        { 1, 1, 3, 7, 0, 9, 1, 1 },  /* I = 0 */
        { 1, 1, 3, 7, 4, 41, 1, 1 }, /* R > 40 */
        { 1, 1, 3, 7, 4, 9, 2, 1 },  /* F != 1 (binary) */
        { 1, 1, 3, 7, 4, 9, 1, 3 },  /* RI not 1 or 2 */
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        char f[128];
        const int *v = bad[i];
        int k = snprintf(f, sizeof f, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", "", "",
                         v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], 0, 1);
        FILE *fp = mem_file(f, (size_t)k);
        gksm_in m;
        assert_int_equal(gksm_in_open(&m, fp), 163);
        fclose(fp);
    }
    FILE *fp = mem_file("%PDF-1.4 not a metafile at all, but long enough to hold a header "
                        "of ninety characters......", 90);
    gksm_in m;
    assert_int_equal(gksm_in_open(&m, fp), 163);
    fclose(fp);
    /* A declared data length beyond the end of the file: 163 before any allocation. */
    char f[256];
    int k = snprintf(f, sizeof f, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", "", "", 1, 4,
                     3, 10, 11, 24, 1, 1, 0, 1);
    k += snprintf(f + k, sizeof f - (size_t)k, "GKSM 11%10d", 999999999);
    fp = mem_file(f, (size_t)k);
    assert_int_equal(gksm_in_open(&m, fp), 0);
    int type;
    size_t len;
    assert_int_equal(gksm_in_peek(&m, &type, &len), 163);
    fclose(fp);
}

/* Decoding refuses nan/inf/hex reals and malformed integers (165). */
static void test_bad_fields(void **u)
{
    (void)u;
    gksm_in m = { .iw = 4, .rw = 9, .ri = 1 };
    const char *reals[] = { "      nan", "     -inf", "   0x1p3", "  0x1p3  ", "  12\0  3", "  1.0.0  ", "         ",
                            "1e999    " };
    for (size_t i = 0; i < sizeof reals / sizeof *reals; i++) {
        gksm_cur c;
        double x;
        gksm_cur_init(&c, &m, reals[i], 9);
        assert_int_equal(gksm_get_real(&c, &x), 165);
    }
    const char *ints[] = { "    ", " 1 2", "  -+", "abcd", " 1e3" };
    for (size_t i = 0; i < sizeof ints / sizeof *ints; i++) {
        gksm_cur c;
        long v;
        gksm_cur_init(&c, &m, ints[i], 4);
        assert_int_equal(gksm_get_int(&c, &v), 165);
    }
    gksm_cur c;
    const char *s;
    size_t n;
    gksm_cur_init(&c, &m, "   5abc", 7); /* string longer than the record */
    assert_int_equal(gksm_get_str(&c, &s, &n), 165);
    assert_int_equal(gksm_cur_left(&c), 7); /* cursor unchanged */
    gksm_cur_init(&c, &m, "  -1abc", 7);
    assert_int_equal(gksm_get_str(&c, &s, &n), 165);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),  cmocka_unit_test(test_ral_layout),
        cmocka_unit_test(test_short_buffer), cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_bad_headers), cmocka_unit_test(test_bad_fields),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
