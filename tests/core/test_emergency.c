/* SPDX-License-Identifier: MIT */
/*
 * test_emergency.c -- the error path re-checks the world (issue 20 A, B): an error
 * handler that calls EMERGENCY CLOSE GKS, with a failure injected
 *  - at every allocation of a workload (the allocation funnel's fail-the-Nth hook), and
 *  - at every write (the file size limit RLIMIT_FSIZE, SIGXFSZ ignored: each write past
 *    the limit fails with EFBIG, so every PNG, metafile and log write fails in turn),
 * through a workload that calls every kind of function the issue found unsafe (output
 * primitives 2-D and 3-D, workstation transformation, REDRAW, SET DEFERRAL STATE,
 * MESSAGE, segment functions with implicit regeneration, INSERT SEGMENT, metafile output,
 * READ/INTERPRET ITEM) on PNG (classic and ray-traced), MO, WISS and null workstations.
 * After each failed run GKS must be closed (once: the workload opens it once), the first
 * error must be the injected one, and the run must end without a crash; under ASan/UBSan (GKS_SANITIZE) any use of freed state fails.
 * The same run with a passive handler must leave GKS open and consistent.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <cmocka.h>
#include <gks.h>
#include "item_util.h"

void gks_alloc_fail_after(long n);
long gks_alloc_count(void);

static int n_errors, n_closes, first_err;

static void closing_handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    if (n_errors++ == 0)
        first_err = err;
    Gop_st st;
    ginq_op_st(&st);
    if (st != GST_GKCL)
        n_closes++;
    gemergency_close_gks();
}

static void passive_handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    if (n_errors++ == 0)
        first_err = err;
}

static void square(double x0, double y0, double s)
{
    Gpoint p[4] = { { x0, y0 }, { x0 + s, y0 }, { x0 + s, y0 + s }, { x0, y0 + s } };
    Gpoint_list l = { 4, p };
    gfill_area(&l);
}

/* Every unsafe site of issue 20 A and B, in one program. Plain GKS use: no call here is
 * an error by itself (checked by test_workload_clean). */
static void workload(void)
{
    static const Glimit vp32 = { 0, 32, 0, 32 };
    static const Glimit win = { 0, 1, 0, 1 };
    static const Glimit3 win3 = { 0, 1, 0, 1, 0, 1 };
    static const Glimit3 vp3 = { 0, 32, 0, 32, 0, 1 };
    gopen_gks(NULL, 0);
    /* each PNG workstation made small as soon as it is open: an emergency close writes its
       picture at the size it has then (1024 x 1024 pixels before), which made most of the
       test's time, under ASan mostly page faults */
    gopen_ws(1, "emerg_a.png", GWS_TYPE_PNG);
    gset_ws_vp(1, &vp32);
    gopen_ws(2, "emerg_b.png", GWS_TYPE_PNG);
    gset_ws_vp(2, &vp32);
    gopen_ws(3, "emerg.gksm", GWS_TYPE_MO);
    gopen_ws(4, NULL, GWS_TYPE_WISS);
    gopen_ws(5, NULL, GWS_TYPE_NULL);
    gset_hlhsr_mode(2, GHLHSR_RAYTRACE);
    gset_defer_st(1, GDEFER_ASAP, GIRG_ALLOWED);
    for (int ws = 1; ws <= 5; ws++)
        gactivate_ws(ws);
    const Gcolr_rep red = { { 1, 0, 0 } };
    gset_colr_rep(1, 2, &red);
    gset_colr_rep(3, 2, &red);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);

    gcreate_seg(1);
    square(0.1, 0.1, 0.3);
    Gpoint pl[3] = { { 0.1, 0.9 }, { 0.5, 0.5 }, { 0.9, 0.9 } };
    Gpoint_list l = { 3, pl };
    gpolyline(&l);
    gpolymarker(&l);
    Gpoint at = { 0.2, 0.6 };
    gtext(&at, "AB");
    gclose_seg();
    gcreate_seg(2);
    Gpoint3 p3[4] = { { 0.5, 0.5, 0.5 }, { 0.9, 0.5, 0.5 }, { 0.9, 0.9, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gpoint_list3 l3 = { 4, p3 };
    gfill_area3(&l3);
    gpolyline3(&l3);
    Gpoint_list loops[2] = { { 3, pl }, { 3, (Gpoint[]){ { 0, 0 }, { 0.2, 0 }, { 0, 0.2 } } } };
    Gpoint_list_list set = { 2, loops };
    gfill_area_set(&set);
    Gint colr[4] = { 1, 2, 2, 1 };
    Gpat_rep ca = { { 2, 2 }, colr };
    Grect r = { { 0.6, 0.1 }, { 0.9, 0.4 } };
    gcell_array(&r, &ca);
    gclose_seg();

    /* picture changes with implicit regeneration on workstation 1 */
    Gtran_matrix m = { { 1, 0, 0.05 }, { 0, 1, 0.05 } };
    gset_seg_tran(1, m);
    Gtran_matrix3 m3 = { { 1, 0, 0, 0 }, { 0, 1, 0, 0.01 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(2, m3);
    gset_vis(2, GSEG_INVIS);
    gset_vis(2, GSEG_VIS);
    gset_seg_pri(1, 0.7);
    gset_highl(1, GSEG_HIGHL);
    gset_det(1, GSEG_DET);
    grename_seg(2, 3);
    gset_ws_win(1, &win);
    gset_ws_vp(1, &vp32);
    gset_ws_win3(1, &win3);
    gset_ws_vp3(1, &vp3);
    gredraw_all_seg_ws(1);
    gset_defer_st(2, GDEFER_ASAP, GIRG_ALLOWED);
    gmessage(3, "hello");
    ginsert_seg(1, m);
    gupd_ws(1, GFLAG_PERFORM);
    gupd_ws(2, GFLAG_PERFORM);
    gupd_ws(3, GFLAG_PERFORM);
    gdel_seg_ws(1, 3);
    gdel_seg(1);
    gclear_ws(1, GFLAG_ALWAYS);
    for (int ws = 1; ws <= 5; ws++)
        gdeactivate_ws(ws);
    for (int ws = 1; ws <= 5; ws++)
        gclose_ws(ws);

    /* the metafile back: every item read and interpreted on a PNG workstation */
    gopen_ws(6, "emerg.gksm", GWS_TYPE_MI);
    gopen_ws(7, "emerg_c.png", GWS_TYPE_PNG);
    gset_ws_vp(7, &vp32);
    gactivate_ws(7);
    char buf[4096];
    for (int k = 0; k < 200; k++) {
        Gint type = -1, len = 0;
        gget_item_type(6, &type, &len);
        if (type <= 0 || len < 0 || len > (Gint)sizeof buf)
            break;
        gread_item(6, (Gint)sizeof buf, RBUF(buf));
        ginterpret_item(type, len, ITEMN(buf, len));
    }
    gdeactivate_ws(7);
    gclose_ws(7);
    gclose_ws(6);
    gclose_gks();
}

static void reset(Gerr_handler h)
{
    gks_alloc_fail_after(0);
    gset_err_hand(passive_handler, NULL);
    gemergency_close_gks();
    n_errors = n_closes = first_err = 0;
    gset_err_hand(h, NULL);
}

/* One run with a failure injected; checks what the handler saw. Returns whether any
 * error was reported. */
static int checked_run(const char *what, long k)
{
    reset(closing_handler);
    workload();
    Gop_st st;
    ginq_op_st(&st);
    if (st != GST_GKCL)
        fail_msg("%s %ld: GKS still open after the workload", what, k);
    if (n_closes > 1)
        fail_msg("%s %ld: %d errors closed GKS %d times", what, k, n_errors, n_closes);
    return n_errors > 0;
}

static void test_workload_clean(void **u)
{
    (void)u;
    reset(passive_handler);
    workload();
    if (n_errors)
        fail_msg("the workload itself reported %d errors, first %d", n_errors, first_err);
}

static void test_every_allocation(void **u)
{
    (void)u;
    reset(passive_handler);
    long before = gks_alloc_count();
    workload();
    long total = gks_alloc_count() - before;
    assert_true(total > 100);
    long failed_runs = 0;
    for (long k = 1; k <= total; k++) {
        reset(closing_handler);
        gks_alloc_fail_after(k);
        workload();
        gks_alloc_fail_after(0);
        Gop_st st;
        ginq_op_st(&st);
        if (st != GST_GKCL)
            fail_msg("allocation %ld: GKS still open", k);
        if (n_closes > 1)
            fail_msg("allocation %ld: %d errors closed GKS %d times", k, n_errors, n_closes);
        if (n_errors > 0 && first_err != 300 && first_err != 301 && first_err != 26)
            fail_msg("allocation %ld: first error %d, want 300/301 (26: a file not opened)",
                     k, first_err);
        failed_runs += n_errors > 0;
    }
    /* Every failed allocation is reported (a run whose k lies beyond its own allocation
     * count, because a file left by an earlier run changes the count, reports none). */
    print_message("fault injection: %ld allocations, %ld runs reported an error\n", total,
                  failed_runs);
    assert_true(failed_runs >= total * 9 / 10);
}

static void test_every_write(void **u)
{
    (void)u;
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit old;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    long runs = 0, failed_runs = 0;
    /* File offsets at which the first write fails: every 256 bytes up to 8 KiB (the
     * headers, the first buffer flushes), then coarser up to where nothing fails. */
    for (rlim_t lim = 0; lim < 1u << 22; lim += lim < 8192 ? 256 : lim / 4) {
        struct rlimit r = { lim, old.rlim_max };
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &r), 0);
        int failed = checked_run("file size limit", (long)lim);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
        runs++;
        failed_runs += failed;
        if (!failed && lim > 65536)
            break;
    }
    print_message("write failures: %ld runs, %ld reported an error\n", runs, failed_runs);
    assert_true(failed_runs > 10);
}

/* A passive handler: every allocation fails once, GKS stays open and usable, and the
 * closing sequence works afterwards. */
static void test_passive_every_allocation(void **u)
{
    (void)u;
    reset(passive_handler);
    long before = gks_alloc_count();
    workload();
    long total = gks_alloc_count() - before;
    for (long k = 1; k <= total; k += 7) {
        reset(passive_handler);
        gks_alloc_fail_after(k);
        workload();
        gks_alloc_fail_after(0);
        gemergency_close_gks();
    }
}

/* The Fortran binding's storage overflow goes through the core's error path
 * (gks_binding_error): the error state is ON while the handler runs (issue 16 item 4). */
void gks_binding_error(int err_num, int fctid);
static int seen_in_handling, seen_err;

static void state_handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    Gint last = 0;
    ginq_err_st(&seen_in_handling, &last);
    seen_err = err == last ? err : -1;
}

static void test_binding_error_path(void **u)
{
    (void)u;
    reset(state_handler);
    gopen_gks(NULL, 0);
    gks_binding_error(300, 12);
    assert_int_equal(seen_in_handling, 1);
    assert_int_equal(seen_err, 300);
    Gint in = -1, last = -1;
    ginq_err_st(&in, &last);
    assert_int_equal(in, 0);
    assert_int_equal(last, 300);
    gclose_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_workload_clean),
        cmocka_unit_test(test_every_allocation),
        cmocka_unit_test(test_every_write),
        cmocka_unit_test(test_passive_every_allocation),
        cmocka_unit_test(test_binding_error_path),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
