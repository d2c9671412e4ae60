/* SPDX-License-Identifier: MIT */
/*
 * test_hostile.c -- the hostile cases of issue 20 as regression tests: files shared by
 * two workstations (21), files that cannot be created, FIFOs and directories as
 * connection identifiers (26, without blocking), a failed PNG write that must not remove
 * the user's symbolic link, extreme windows (308 at the primitive instead of a silent
 * empty picture), non-finite segment transformations (308, nothing stored), and NULL
 * arguments (a clean error, no crash).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

static void expect_errors(int n, int err)
{
    if (n_captured != n || (n > 0 && captured[0].err != err))
        fail_msg("%d errors (first %d), want %d of %d", n_captured,
                 n_captured ? captured[0].err : 0, n, err);
    n_captured = 0;
}

static int n_open_ws(void)
{
    Gint err, n = -1, id;
    Gint_list l = { 1, &id };
    ginq_set_open_wss(1, 0, &err, &l, &n);
    return n;
}

static void test_two_workstations_one_file(void **u)
{
    (void)u;
    enter_state(GST_GKOP);
    unlink("h_same.gksm");
    unlink("h_same.png");
    gopen_ws(1, "h_same.gksm", GWS_TYPE_MO);
    expect_errors(0, 0);
    gopen_ws(2, "h_same.gksm", GWS_TYPE_MO);
    expect_errors(1, 21);
    gopen_ws(3, "./h_same.gksm", GWS_TYPE_MO); /* canonical paths are compared */
    expect_errors(1, 21);
    gopen_ws(4, "h_same.gksm", GWS_TYPE_MI);   /* reading what an MO writes */
    expect_errors(1, 21);
    gopen_ws(5, "h_same", GWS_TYPE_PNG);       /* writes h_same.png */
    expect_errors(0, 0);
    gopen_ws(6, "h_same.png", GWS_TYPE_PNG);
    expect_errors(1, 21);
    gupd_ws(5, GFLAG_PERFORM); /* h_same.png exists now */
    unlink("h_link.png");
    assert_int_equal(symlink("h_same.png", "h_link.png"), 0);
    gopen_ws(7, "h_link.png", GWS_TYPE_PNG);   /* the same file through a link */
    expect_errors(1, 21);
    assert_int_equal(n_open_ws(), 2);
    gclose_ws(5);
    gopen_ws(6, "h_same.png", GWS_TYPE_PNG);   /* free again once 5 is closed */
    expect_errors(0, 0);
    gclose_ws(6);
    gclose_ws(1);
    gclose_gks();
    expect_errors(0, 0);
    unlink("h_link.png");
    unlink("h_same.png");
    unlink("h_same.gksm");
}

static void test_files_that_cannot_be_used(void **u)
{
    (void)u;
    enter_state(GST_GKOP);
    gopen_ws(1, "h_no_such_dir/x.png", GWS_TYPE_PNG);
    expect_errors(1, 26);
    gopen_ws(1, "h_no_such_dir/x.gksm", GWS_TYPE_MO);
    expect_errors(1, 26);
    gopen_ws(1, "h_missing.gksm", GWS_TYPE_MI);
    expect_errors(1, 26);
    mkdir("h_dir.png", 0755);
    gopen_ws(1, "h_dir", GWS_TYPE_PNG);        /* h_dir.png is a directory */
    expect_errors(1, 26);
    rmdir("h_dir.png");
    unlink("h_fifo.png");
    unlink("h_fifo.gksm");
    assert_int_equal(mkfifo("h_fifo.png", 0644), 0);
    assert_int_equal(mkfifo("h_fifo.gksm", 0644), 0);
    alarm(20); /* a hang would be the bug: fail instead of blocking the suite */
    gopen_ws(1, "h_fifo", GWS_TYPE_PNG);
    expect_errors(1, 26);
    gopen_ws(1, "h_fifo.gksm", GWS_TYPE_MI);
    expect_errors(1, 26);
    gopen_ws(1, "h_fifo.gksm", GWS_TYPE_MO);
    expect_errors(1, 26);
    gopen_ws(1, "/dev/null", GWS_TYPE_MO);     /* a device */
    expect_errors(1, 26);
    alarm(0);
    assert_int_equal(n_open_ws(), 0);
    gclose_gks();
    unlink("h_fifo.png");
    unlink("h_fifo.gksm");
}

/* A PNG write that fails (file size limit) keeps the user's symbolic link and reports
 * 303; the library removes only a file it created itself. */
static void test_failed_write_keeps_symlink(void **u)
{
    (void)u;
    unlink("h_target.png");
    unlink("h_user_link.png");
    FILE *f = fopen("h_target.png", "w");
    assert_non_null(f);
    fclose(f);
    assert_int_equal(symlink("h_target.png", "h_user_link.png"), 0);
    enter_state(GST_GKOP);
    gopen_ws(1, "h_user_link", GWS_TYPE_PNG);
    gactivate_ws(1);
    Gpoint p[3] = { { 0, 0 }, { 1, 1 }, { 1, 0 } };
    Gpoint_list l = { 3, p };
    gpolyline(&l);
    expect_errors(0, 0);
    signal(SIGXFSZ, SIG_IGN);
    struct rlimit old, r;
    getrlimit(RLIMIT_FSIZE, &old);
    r = (struct rlimit){ 16, old.rlim_max };
    setrlimit(RLIMIT_FSIZE, &r);
    gupd_ws(1, GFLAG_PERFORM);
    setrlimit(RLIMIT_FSIZE, &old);
    expect_errors(1, 303);
    struct stat st;
    assert_int_equal(lstat("h_user_link.png", &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    expect_errors(0, 0);
    assert_int_equal(lstat("h_user_link.png", &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    unlink("h_user_link.png");
    unlink("h_target.png");
}

/* Counts the primitives the null workstation receives. */
static int n_prims;
void gks_test_set_prim_hook(void (*hook)(void *, int, const void *), void *ctx);
static void count_prim(void *ctx, int ws, const void *p)
{
    (void)ctx;
    (void)ws;
    (void)p;
    n_prims++;
}

static void polyline_with_window(double x0, double x1)
{
    const Glimit win = { x0, x1, 0, 1 };
    gset_win(1, &win);
    expect_errors(0, 0);
    gsel_norm_tran(1);
    Gpoint p[2] = { { 0, 0.5 }, { x1, 0.5 } };
    Gpoint_list l = { 2, p };
    gpolyline(&l);
}

static void test_extreme_windows(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    gks_test_set_prim_hook(count_prim, NULL);
    n_prims = 0;
    polyline_with_window(-1.7e308, 1.7e308); /* width overflows: was the zero matrix */
    expect_errors(1, 308);
    polyline_with_window(0, 4.9e-324);       /* scale overflows: was silently dropped */
    expect_errors(1, 308);
    assert_int_equal(n_prims, 0);
    polyline_with_window(-1e307, 1e307);     /* representable: drawn */
    expect_errors(0, 0);
    polyline_with_window(0, 1e-300);
    expect_errors(0, 0);
    assert_int_equal(n_prims, 2);
    gks_test_set_prim_hook(NULL, NULL);
    reset_gks();
}

static void test_nonfinite_segment_transformation(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    gcreate_seg(1);
    gclose_seg();
    Gtran_matrix3 m3 = { { 1, 0, 0, 0 }, { 0, NAN, 0, 0 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(1, m3);
    expect_errors(1, 308);
    Gtran_matrix m = { { 1, 0, INFINITY }, { 0, 1, 0 } };
    gset_seg_tran(1, m);
    expect_errors(1, 308);
    Gint err;
    Gseg_attrs3 a;
    ginq_seg_attrs3(1, &err, &a);
    assert_int_equal(err, 0);
    for (int i = 0; i < 3; i++) /* still the identity */
        for (int j = 0; j < 4; j++)
            assert_true(a.tran_matrix[i][j] == (i == j ? 1.0 : 0.0));
    reset_gks();
}

/* The eight functions that crashed on a NULL argument (issue 20 I) now report 2003;
 * inquiries with a NULL error indicator return without effect. */
static void test_null_arguments(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    gopen_ws(2, NULL, GWS_TYPE_WISS);
    gactivate_ws(2);
    gcreate_seg(1);
    gclose_seg();
    n_captured = 0;
    Gint err = -1;
    Gmatrix3 m3;
    Gtran_matrix tm;
    const Gpoint3 p3 = { 0, 0, 0 };
    const Gvec3 v3 = { 0, 0, 1 }, up = { 0, 1, 0 };
    geval_view_ori_matrix3(NULL, &v3, &up, GCOORD_NDC, &err, m3);
    expect_errors(1, 2003);
    assert_int_equal(err, 2003);
    geval_view_ori_matrix3(&p3, &v3, &up, GCOORD_NDC, &err, NULL);
    expect_errors(1, 2003);
    geval_view_map_matrix3(NULL, &err, m3);
    expect_errors(1, 2003);
    geval_view_ori_matrix3(&p3, &v3, &up, GCOORD_NDC, NULL, m3); /* no err_ind: no crash */
    n_captured = 0;
    const Gpoint fixed = { 0, 0 };
    const Gvec shift = { 0, 0 }, scale = { 1, 1 };
    geval_tran_matrix(NULL, &shift, 0, &scale, GCOORD_NDC, tm);
    expect_errors(1, 2003);
    geval_tran_matrix(&fixed, &shift, 0, &scale, GCOORD_NDC, NULL);
    expect_errors(1, 2003);
    const Gvec3 shift3 = { 0, 0, 0 }, scale3 = { 1, 1, 1 };
    Gtran_matrix3 t3;
    geval_tran_matrix3(&p3, NULL, 0, 0, 0, &scale3, GCOORD_NDC, t3);
    expect_errors(1, 2003);
    gaccum_tran_matrix(NULL, &fixed, &shift, 0, &scale, GCOORD_NDC, tm);
    expect_errors(1, 2003);
    gaccum_tran_matrix3(NULL, &p3, &shift3, 0, 0, 0, &scale3, GCOORD_NDC, t3);
    expect_errors(1, 2003);
    gset_seg_tran(1, NULL);
    expect_errors(1, 2003);
    gset_seg_tran3(1, NULL);
    expect_errors(1, 2003);
    ginsert_seg(1, NULL);
    expect_errors(1, 2003);
    ginsert_seg3(1, NULL);
    expect_errors(1, 2003);
    /* inquiries: a NULL error indicator is not written, nothing else happens */
    Gop_st st;
    ginq_op_st(&st);
    Gint n;
    ginq_cur_norm_tran_num(NULL, &n);
    ginq_name_open_seg(NULL, &n);
    ginq_seg_attrs3(1, NULL, NULL);
    ginq_set_seg_names(1, 0, NULL, NULL, NULL);
    expect_errors(0, 0);
    reset_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_two_workstations_one_file),
        cmocka_unit_test(test_files_that_cannot_be_used),
        cmocka_unit_test(test_failed_write_keeps_symlink),
        cmocka_unit_test(test_extreme_windows),
        cmocka_unit_test(test_nonfinite_segment_transformation),
        cmocka_unit_test(test_null_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
