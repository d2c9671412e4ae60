/* SPDX-License-Identifier: MIT */
/*
 * test_control.c -- argument errors of the control, transformation and output functions
 * (standard error numbers, no other effect), inquiry error indicators, the error file
 * written by the default ERROR LOGGING, and storage-overflow injection (error 300,
 * state lists unchanged).
 */
#include <stdarg.h>
#include <math.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

/* Test hook of the library (exported for tests only). */
void gks_alloc_fail_after(long n);

#define EXPECT_ERROR(call, errnum, fctid)                                          \
    do {                                                                           \
        snapshot b_, a_;                                                           \
        take_snapshot(&b_);                                                        \
        n_captured = 0;                                                            \
        call;                                                                      \
        assert_int_equal(n_captured, 1);                                           \
        assert_int_equal(captured[0].err, (errnum));                               \
        assert_int_equal(captured[0].fct, (fctid));                                \
        take_snapshot(&a_);                                                        \
        assert_memory_equal(&b_, &a_, sizeof b_);                                  \
    } while (0)

static void test_workstation_arguments(void **u)
{
    (void)u;
    enter_state(GST_WSAC); /* ws 1 (null) open and active */
    EXPECT_ERROR(gopen_ws(-1, NULL, GWS_TYPE_NULL), 20, GFN_OPWK);
    EXPECT_ERROR(gopen_ws(1, NULL, GWS_TYPE_NULL), 24, GFN_OPWK);
    EXPECT_ERROR(gopen_ws(2, NULL, 0), 22, GFN_OPWK);
    EXPECT_ERROR(gopen_ws(2, NULL, 12345), 23, GFN_OPWK);
    EXPECT_ERROR(gclose_ws(1), 29, GFN_CLWK);
    EXPECT_ERROR(gclose_ws(5), 25, GFN_CLWK);
    EXPECT_ERROR(gclose_ws(-3), 20, GFN_CLWK);
    EXPECT_ERROR(gactivate_ws(1), 29, GFN_ACWK);
    EXPECT_ERROR(gactivate_ws(9), 25, GFN_ACWK);
    EXPECT_ERROR(gdeactivate_ws(9), 30, GFN_DAWK);
    EXPECT_ERROR(gclear_ws(9, GFLAG_ALWAYS), 25, GFN_CLRWK);
    EXPECT_ERROR(gupd_ws(9, GFLAG_PERFORM), 25, GFN_UWK);
    EXPECT_ERROR(gmessage(9, "x"), 25, GFN_MSG);
    /* maximum numbers: 16 open, 16 active */
    n_captured = 0;
    for (int id = 2; id <= 16; id++)
        gopen_ws(id, NULL, GWS_TYPE_NULL);
    assert_int_equal(n_captured, 0);
    EXPECT_ERROR(gopen_ws(17, NULL, GWS_TYPE_NULL), 42, GFN_OPWK);
    for (int id = 2; id <= 16; id++)
        gactivate_ws(id);
    gdeactivate_ws(16);
    gopen_ws(17, NULL, GWS_TYPE_NULL); /* still 42: 16 open */
    assert_int_equal(captured[0].err, 42);
    reset_gks();
}

static void test_max_active(void **u)
{
    (void)u;
    enter_state(GST_GKOP);
    for (int id = 1; id <= 16; id++) {
        gopen_ws(id, NULL, GWS_TYPE_NULL);
        gactivate_ws(id);
    }
    gdeactivate_ws(16);
    gclose_ws(16);
    gopen_ws(16, NULL, GWS_TYPE_NULL);
    gactivate_ws(16);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

static void test_transformation_and_output_arguments(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    Glimit bad = { 1, 0, 0, 1 }, ok = { 0, 1, 0, 1 }, out = { 0, 1.5, 0, 1 };
    EXPECT_ERROR(gset_win(0, &ok), 50, GFN_SWN);
    EXPECT_ERROR(gset_win(32, &ok), 50, GFN_SWN);
    EXPECT_ERROR(gset_win(1, &bad), 51, GFN_SWN);
    EXPECT_ERROR(gset_vp(1, &out), 52, GFN_SVP);
    EXPECT_ERROR(gsel_norm_tran(-1), 50, GFN_SELNT);
    EXPECT_ERROR(gset_ws_win(1, &out), 53, GFN_SWKWN);
    Glimit big = { 0, 2000, 0, 10 };
    EXPECT_ERROR(gset_ws_vp(1, &big), 54, GFN_SWKVP);
    /* the xform module's checks: 51 (order, NaN, NULL) before containment */
    Glimit nan_r = { 0, NAN, 0, 1 }, bad_out = { 1.5, 0, 0, 1 };
    EXPECT_ERROR(gset_win(1, &nan_r), 51, GFN_SWN);
    EXPECT_ERROR(gset_win(1, NULL), 51, GFN_SWN);
    EXPECT_ERROR(gset_vp(1, &bad_out), 51, GFN_SVP);
    EXPECT_ERROR(gset_vp(1, &nan_r), 51, GFN_SVP);
    EXPECT_ERROR(gset_ws_win(1, &bad_out), 51, GFN_SWKWN);
    EXPECT_ERROR(gset_ws_win(1, NULL), 51, GFN_SWKWN);
    EXPECT_ERROR(gset_ws_vp(1, &nan_r), 51, GFN_SWKVP);
    EXPECT_ERROR(gset_ws_vp(1, &bad), 51, GFN_SWKVP);
    EXPECT_ERROR(gset_line_colr_ind(-1), 92, GFN_SPLCI);
    Gcolr_rep c = { { 0.5, 1.5, 0 } };
    EXPECT_ERROR(gset_colr_rep(1, 2, &c), 96, GFN_SCR);
    c.rgb.green = 0.5;
    EXPECT_ERROR(gset_colr_rep(1, 256, &c), 93, GFN_SCR);
    Gpoint p[2] = { { 0, 0 }, { 1, 1 } };
    Gpoint_list one = { 1, p }, two = { 2, p };
    EXPECT_ERROR(gpolyline(&one), 100, GFN_PL);
    EXPECT_ERROR(gfill_area(&two), 100, GFN_FA);
    EXPECT_ERROR(gescape(12345, NULL, NULL, NULL), 180, GFN_ESC);
    EXPECT_ERROR(gescape(GESC_SET_FILE_NAME, NULL, NULL, NULL), 182, GFN_ESC);
    /* hostile coordinates: no error, no crash */
    Gpoint h[3] = { { 0, 0 }, { 1e300, -1e300 }, { 0.0 / 0.0, 1 } };
    Gpoint_list hl = { 3, h };
    n_captured = 0;
    gfill_area(&hl);
    gpolyline(&hl);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

static void test_inquiries(void **u)
{
    (void)u;
    reset_gks();
    Gint err = -1, lvl = -1;
    Glevel level;
    ginq_level_gks(&err, &level);
    assert_int_equal(err, 8);
    assert_int_equal(n_captured, 0); /* inquiries never call the handler */
    gopen_gks(NULL, 0);
    ginq_level_gks(&err, &level);
    assert_int_equal(err, 0);
    Gint types[16], len;
    Gint_list tl = { 0, types };
    Gws_cat x11cat;
    ginq_ws_cat(GWS_TYPE_X11, &err, &x11cat);
#ifdef GKS_HAVE_CAIRO
    const int n_cairo = 4; /* PDF, SVG, PS, EPS after MI */
#else
    const int n_cairo = 0;
#endif
    /* X11 exists with GKS_WITH_X11; the OUTPUT PNG type comes last */
    const int ntypes = (err == 0 ? 8 : 7) + n_cairo;
    ginq_list_avail_ws_types(16, 0, &err, &tl, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, ntypes);
    assert_int_equal(tl.num_ints, ntypes);
    assert_int_equal(types[3], GWS_TYPE_WISS);
    assert_int_equal(types[4], GWS_TYPE_MO);
    assert_int_equal(types[5], GWS_TYPE_MI);
    if (n_cairo) {
        assert_int_equal(types[6], GWS_TYPE_PDF);
        assert_int_equal(types[9], GWS_TYPE_EPS);
    }
    assert_int_equal(level, GLEVEL_2C);
    ginq_list_avail_ws_types(16, ntypes, &err, &tl, &len);
    assert_int_equal(err, 2002);
    Gws_st st;
    ginq_ws_st(1, &err, &st);
    assert_int_equal(err, 7);
    gopen_ws(3, "pic.png", GWS_TYPE_NULL);
    ginq_ws_st(1, &err, &st);
    assert_int_equal(err, 25);
    char conn[4];
    Gint type;
    ginq_ws_conn_type(3, (Gint)sizeof conn, &err, conn, &type);
    assert_int_equal(err, 0);
    assert_string_equal(conn, "pic"); /* truncated to the buffer */
    assert_int_equal(type, GWS_TYPE_NULL);
    Gws_cat cat;
    ginq_ws_cat(GWS_TYPE_PNG, &err, &cat);
    assert_int_equal(err, 0);
    assert_int_equal(cat, GCAT_OUTIN);
    ginq_ws_cat(GWS_TYPE_PNG_OUTPUT, &err, &cat); /* the same picture, no input */
    assert_int_equal(err, 0);
    assert_int_equal(cat, GCAT_OUT);
    assert_int_equal(types[ntypes - 1], GWS_TYPE_PNG_OUTPUT);
    ginq_ws_cat(777, &err, &cat);
    assert_int_equal(err, 23);
    Gdisp_space_size ds;
    ginq_disp_space_size(GWS_TYPE_PNG_LARGE, &err, &ds);
    assert_int_equal(ds.size_raster.size_x, 8192);
    Gcolr_rep cr;
    ginq_colr_rep(3, 1, GINQ_SET, &err, &cr); /* null ws predefines 0 and 1 */
    assert_int_equal(err, 0);
    ginq_colr_rep(3, 200, GINQ_SET, &err, &cr);
    assert_int_equal(err, 94);
    assert_int_equal(n_captured, 0);
    (void)lvl;
    reset_gks();
}

static void test_error_file(void **u)
{
    (void)u;
    char path[] = "/tmp/gks_errfile_XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    gemergency_close_gks();
    gset_err_hand(NULL, NULL); /* default handler: gerr_hand -> gerr_log */
    gopen_gks(path, 0);
    gopen_ws(1, NULL, 4242);
    gactivate_ws(9);
    gopen_gks(NULL, 0);
    gclose_gks();
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char buf[4096] = { 0 };
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    unlink(path);
    assert_true(n > 0);
    assert_non_null(strstr(buf, "GKS ERROR 23 in OPEN WORKSTATION: Specified workstation type does not exist"));
    assert_non_null(strstr(buf, "GKS ERROR 6 in ACTIVATE WORKSTATION"));
    assert_non_null(strstr(buf, "GKS ERROR 1 in OPEN GKS"));
    /* an error file that cannot be opened: 200, GKS stays closed */
    capture_reset();
    gopen_gks("/nonexistent-dir/x/err.txt", 0);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 200);
    Gop_st op;
    ginq_op_st(&op);
    assert_int_equal(op, GST_GKCL);
}

/* Fail the 1st, 2nd, ... allocation of a call: error 300 and nothing changed, until the
 * call succeeds. */
static void test_storage_overflow(void **u)
{
    (void)u;
    int saw300 = 0;
    for (long k = 1; k < 50; k++) {
        enter_state(GST_GKCL);
        gks_alloc_fail_after(k);
        gopen_gks(NULL, 0);
        gks_alloc_fail_after(0);
        Gop_st op;
        ginq_op_st(&op);
        if (n_captured == 0) {
            assert_int_equal(op, GST_GKOP);
            break;
        }
        assert_int_equal(captured[0].err, 300);
        assert_int_equal(op, GST_GKCL);
        saw300++;
    }
    for (long k = 1; k < 100; k++) {
        enter_state(GST_WSAC);
        snapshot b, a;
        take_snapshot(&b);
        gks_alloc_fail_after(k);
        gopen_ws(2, "x", GWS_TYPE_PNG);
        gks_alloc_fail_after(0);
        if (n_captured == 0)
            break;
        assert_int_equal(captured[0].err, 300);
        take_snapshot(&a);
        assert_memory_equal(&a, &b, sizeof a);
        saw300++;
    }
    assert_true(saw300 >= 3);
    reset_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_workstation_arguments),
        cmocka_unit_test(test_max_active),
        cmocka_unit_test(test_transformation_and_output_arguments),
        cmocka_unit_test(test_inquiries),
        cmocka_unit_test(test_error_file),
        cmocka_unit_test(test_storage_overflow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
