/* SPDX-License-Identifier: MIT */
/*
 * test_metafile_loss.c -- metafile output that fails and metafile input that is untrusted
 * (issue 20 C, G, J):
 * - a full metafile (a file size limit) costs a healthy second metafile no item: both
 *   receive every item, the healthy file is byte for byte the file written alone, and the
 *   loss is reported once (303) for the failing workstation;
 * - a write that fails at CLOSE WORKSTATION (the END item and fclose, under a file size limit)
 *   is reported as 303, once;
 * - INTERPRET ITEM of an ESCAPE item refuses by default to change file names or threads
 *   (error 180, no file created) and caps the ray-tracing sample count; after
 *   GESC_MI_ALLOW_ESCAPES the recorded escapes are performed as recorded.
 */
#include <math.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>
#include <string.h>
#include "core_util.h"
#include "item_util.h"

enum { WS_A = 1, WS_B = 2, WS_MI = 3, WS_PNG = 4 };

static int count_errors(int err, int fct)
{
    int n = 0;
    for (int i = 0; i < n_captured && i < MAX_CAPTURED; i++)
        n += captured[i].err == err && (fct < 0 || captured[i].fct == fct);
    return n;
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

/* The whole file, NUL-terminated; *n its size. */
static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long sz = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)sz + 1);
    assert_non_null(b);
    assert_int_equal(fread(b, 1, (size_t)sz, f), (size_t)sz);
    b[sz] = 0;
    fclose(f);
    *n = (size_t)sz;
    return b;
}

/* 2000 segments of one polyline each: many more items than one stdio buffer holds. */
static void many_segments(void)
{
    for (int s = 1; s <= 2000; s++) {
        double y = s / 2001.0;
        Gpoint p[2] = { { 0.1, y }, { 0.9, y } };
        gcreate_seg(s);
        gset_line_colr_ind(1 + s % 2);
        gpolyline(&(Gpoint_list){ 2, p });
        gclose_seg();
    }
}

/* C: a file size limit that only the first MO reaches (its workstation-addressed MESSAGE
 * items make it large) stands for a full disk. The healthy MO gets every item: its file is
 * byte for byte the file written alone; the loss is reported once. */
static void test_full_file_keeps_healthy(void **u)
{
    (void)u;
    const long limit = 1L << 20;
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(WS_B, "loss_alone.gksm", GWS_TYPE_MO);
    gactivate_ws(WS_B);
    many_segments();
    gdeactivate_ws(WS_B);
    gclose_ws(WS_B);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    long alone = file_size("loss_alone.gksm");
    assert_true(alone > 100000 && alone < limit);

    struct rlimit old, lim;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    if (old.rlim_cur != RLIM_INFINITY && old.rlim_cur < (rlim_t)limit)
        skip();
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
    lim = old;
    lim.rlim_cur = (rlim_t)limit;
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    capture_reset();
    gopen_gks(NULL, 0);
    gopen_ws(WS_A, "loss_full.gksm", GWS_TYPE_MO);
    gopen_ws(WS_B, "loss_healthy.gksm", GWS_TYPE_MO);
    gactivate_ws(WS_A);
    gactivate_ws(WS_B);
    static char msg[1001];
    memset(msg, 'm', 1000);
    for (int i = 0; i < 2000; i++) /* 2 MB for A only */
        gmessage(WS_A, msg);
    many_segments();
    gdeactivate_ws(WS_A);
    gdeactivate_ws(WS_B);
    gclose_ws(WS_A);
    gclose_ws(WS_B);
    gclose_gks();
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
    signal(SIGXFSZ, prev);
    /* one report for the full file, none for the healthy one */
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 303);
    assert_int_equal(captured[0].fct, GFN_MSG);
    assert_true(file_size("loss_full.gksm") <= limit);

    size_t na, nb;
    char *a = slurp("loss_alone.gksm", &na), *b = slurp("loss_healthy.gksm", &nb);
    assert_int_equal(na, nb);
    assert_memory_equal(a, b, na);
    free(a);
    free(b);
}

/* G: the END item and fclose at CLOSE WORKSTATION are checked. The file size limit is the
 * size after UPDATE WORKSTATION, so only the END item fails to reach the file. */
static void test_close_write_failure(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(WS_A, "loss_close.gksm", GWS_TYPE_MO);
    gactivate_ws(WS_A);
    Gpoint p[2] = { { 0.1, 0.1 }, { 0.9, 0.9 } };
    gpolyline(&(Gpoint_list){ 2, p });
    gupd_ws(WS_A, GFLAG_PERFORM);
    gdeactivate_ws(WS_A);
    long sz = file_size("loss_close.gksm");
    assert_true(sz > 0);

    struct rlimit old, lim;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    if (old.rlim_cur != RLIM_INFINITY && old.rlim_cur < (rlim_t)sz + 1)
        skip();
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
    lim = old;
    lim.rlim_cur = (rlim_t)sz;
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    n_captured = 0;
    gclose_ws(WS_A);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
    signal(SIGXFSZ, prev);

    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 303);
    assert_int_equal(captured[0].fct, GFN_CLWK);
    assert_int_equal(file_size("loss_close.gksm"), sz); /* the END item is what was lost */
    gclose_gks();
}

/* A metafile with the escapes a hostile file would record: a file name outside the build
 * directory, 256 samples per pixel, 256 threads; then a square to ray trace. */
static void write_hostile_escapes(const char *path)
{
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(WS_A, path, GWS_TYPE_MO);
    gactivate_ws(WS_A);
    Gint name[1] = { WS_A };
    const char *evil = "loss_escaped_name";
    gescape(GESC_SET_FILE_NAME, &(Gescape_in_data){ { 1, name, 0, NULL, strlen(evil), evil } },
            NULL, NULL);
    Gint samples[3] = { WS_A, 256, 0 }, threads[2] = { WS_A, 256 };
    gescape(GESC_RT_SAMPLES, &(Gescape_in_data){ { 3, samples, 0, NULL, 0, NULL } }, NULL, NULL);
    gescape(GESC_RT_THREADS, &(Gescape_in_data){ { 2, threads, 0, NULL, 0, NULL } }, NULL, NULL);
    Gpoint sq[4] = { { 0.2, 0.2 }, { 0.8, 0.2 }, { 0.8, 0.8 }, { 0.2, 0.8 } };
    gset_fill_int_style(GSTYLE_SOLID);
    gfill_area(&(Gpoint_list){ 4, sq });
    gdeactivate_ws(WS_A);
    gclose_ws(WS_A);
    gclose_gks();
    assert_int_equal(n_captured, 0);
}

/* Interprets every item of `path` onto a 16 x 16 ray-traced PNG workstation; returns the
 * eye rays of the picture (GESC_RT_STATS). allow: GESC_MI_ALLOW_ESCAPES first. */
static long interpret_all(const char *path, const char *png, int allow)
{
    capture_reset();
    gopen_gks(NULL, 0);
    gopen_ws(WS_PNG, png, GWS_TYPE_PNG);
    gset_ws_vp(WS_PNG, &(Glimit){ 0, 16, 0, 16 });
    gset_hlhsr_mode(WS_PNG, GHLHSR_RAYTRACE);
    gactivate_ws(WS_PNG);
    gopen_ws(WS_MI, path, GWS_TYPE_MI);
    if (allow) {
        Gint a[2] = { WS_MI, 1 };
        gescape(GESC_MI_ALLOW_ESCAPES, &(Gescape_in_data){ { 2, a, 0, NULL, 0, NULL } }, NULL, NULL);
    }
    assert_int_equal(n_captured, 0);
    for (;;) {
        Gint type = -1, len = 0;
        int before = n_captured;
        gget_item_type(WS_MI, &type, &len);
        if (n_captured != before || type == 0)
            break;
        char *data = malloc((size_t)len + 1);
        assert_non_null(data);
        gread_item(WS_MI, len, ITEMN(data, len));
        ginterpret_item(type, len, ITEMN(data, len));
        free(data);
    }
    gupd_ws(WS_PNG, GFLAG_PERFORM);
    Gint d[1] = { WS_PNG }, oi[8] = { 0 }, serr;
    Gstore store = NULL;
    Gescape_out_data *out = NULL;
    gcreate_store(&serr, &store);
    gescape(GESC_RT_STATS, &(Gescape_in_data){ { 1, d, 0, NULL, 0, NULL } }, &store, &out);
    if (out)
        memcpy(oi, out->ints, sizeof oi);
    gdel_store(store);
    gclose_ws(WS_MI);
    gdeactivate_ws(WS_PNG);
    gclose_ws(WS_PNG);
    gclose_gks();
    return oi[0];
}

/* J: by default the file name and thread escapes are refused (180 from INTERPRET ITEM), no
 * file of the metafile's choosing appears, and 256 samples per pixel become 16. */
static void test_untrusted_escapes(void **u)
{
    (void)u;
    write_hostile_escapes("loss_escapes.gksm");
    remove("loss_escaped_name.png");
    long eye = interpret_all("loss_escapes.gksm", "loss_viewer.png", 0);
    assert_int_equal(count_errors(180, GFN_IITM), 2); /* file name, threads */
    assert_int_equal(n_captured, 2);
    assert_int_equal(file_size("loss_escaped_name.png"), -1);
    assert_true(file_size("loss_viewer.png") > 0);
    assert_true(eye > 0);
    assert_true(eye <= 16L * 17 * 17); /* 16 samples per pixel at most (corners included) */
}

/* J: an application that trusts the file allows the escapes explicitly. */
static void test_allowed_escapes(void **u)
{
    (void)u;
    write_hostile_escapes("loss_escapes.gksm");
    remove("loss_escaped_name.png");
    long eye = interpret_all("loss_escapes.gksm", "loss_viewer2.png", 1);
    assert_int_equal(n_captured, 0);
    assert_true(file_size("loss_escaped_name.png") > 0); /* the recorded name is used */
    assert_true(eye >= 256L * 16 * 16);
}

/* GESC_MI_ALLOW_ESCAPES is for MI workstations, with 0 or 1. */
static void test_allow_escape_errors(void **u)
{
    (void)u;
    write_hostile_escapes("loss_escapes.gksm");
    capture_reset();
    gopen_gks(NULL, 0);
    gopen_ws(WS_MI, "loss_escapes.gksm", GWS_TYPE_MI);
    gopen_ws(WS_B, NULL, GWS_TYPE_NULL);
    Gint bad[2] = { WS_MI, 2 }, other[2] = { WS_B, 1 }, short1[1] = { WS_MI };
    gescape(GESC_MI_ALLOW_ESCAPES, &(Gescape_in_data){ { 2, bad, 0, NULL, 0, NULL } }, NULL, NULL);
    gescape(GESC_MI_ALLOW_ESCAPES, &(Gescape_in_data){ { 1, short1, 0, NULL, 0, NULL } }, NULL, NULL);
    gescape(GESC_MI_ALLOW_ESCAPES, &(Gescape_in_data){ { 2, other, 0, NULL, 0, NULL } }, NULL, NULL);
    assert_int_equal(n_captured, 3);
    assert_int_equal(captured[0].err, 182);
    assert_int_equal(captured[1].err, 182);
    assert_int_equal(captured[2].err, 180);
    gclose_ws(WS_B);
    gclose_ws(WS_MI);
    gclose_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_full_file_keeps_healthy),
        cmocka_unit_test(test_close_write_failure),
        cmocka_unit_test(test_untrusted_escapes),
        cmocka_unit_test(test_allowed_escapes),
        cmocka_unit_test(test_allow_escape_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
