/* SPDX-License-Identifier: MIT */
/*
 * test_record.c -- GKS3D_RECORD (README, "Recording"): OPEN GKS opens a hidden metafile
 * output workstation that records what the program draws, frames included, while the
 * program's own workstations and every inquiry behave as without it:
 * - the sets of open and active workstations, the operating state and the workstation
 *   state inquiries show only the program's workstations; no error is reported;
 * - the recorded file holds the two polylines, the CLEAR WORKSTATION the program called
 *   and the CLEAR that ends the frame at CLOSE WORKSTATION, the HLHSR mode set on the
 *   program's workstation, and the sample-count escape but not the file-name escape;
 * - nothing is recorded while only a WISS is active; unset, no file is written;
 * - a recorder file that cannot be opened leaves GKS working without it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"
#include "item_util.h"

#define REC "test_record.gksm"

/* Counts of the item types of metafile `path` read by GET ITEM / READ ITEM. */
static void count_items(const char *path, int counts[1000])
{
    memset(counts, 0, 1000 * sizeof counts[0]);
    gopen_gks(NULL, 0);
    gopen_ws(9, path, GWS_TYPE_MI);
    for (;;) {
        Gint type = -1, len = 0, err = 0;
        gget_item_type(9, &type, &len);
        ginq_ws_st(9, &err, &(Gws_st){ 0 });
        if (type < 0 || type >= 1000)
            break;
        counts[type]++;
        if (type == 0)
            break;
        char buf[64];
        gread_item(9, (Gint)sizeof buf, RBUF(buf));
    }
    gclose_ws(9);
    gclose_gks();
}

static void escape_ints(int func, Gint ws, Gint v)
{
    Gint ints[2] = { ws, v };
    Gescape_in_data in = { { 2, ints, 0, NULL, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

static void test_recorded_and_hidden(void **state)
{
    (void)state;
    remove(REC);
    setenv("GKS3D_RECORD", REC, 1);
    capture_reset();
    gopen_gks(NULL, 0);
    capture_reset();
    Gop_st op;
    ginq_op_st(&op);
    assert_int_equal(op, GST_GKOP); /* the recorder does not open GKS's workstations state */
    gopen_ws(1, "test_record_pic", GWS_TYPE_PNG);
    gset_hlhsr_mode(1, GHLHSR_ZBUFFER);
    escape_ints(GESC_RT_SAMPLES, 1, 4);
    Gescape_in_data fn = { { 1, (Gint[]){ 1 }, 0, NULL, 15, "test_record_pic" } };
    gescape(GESC_SET_FILE_NAME, &fn, NULL, NULL);
    gactivate_ws(1);
    Gint err = -1, len = -1, ids[4] = { 0 };
    Gint_list l = { 0, ids };
    ginq_set_open_wss(4, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 1);
    assert_int_equal(ids[0], 1);
    ginq_set_active_wss(4, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 1);
    assert_int_equal(ids[0], 1);
    ginq_ws_st(-1, &err, &(Gws_st){ 0 });
    assert_int_equal(err, 20); /* the recorder has no identifier a program can name */
    Gpoint p[2] = { { 0.1f, 0.1f }, { 0.9f, 0.9f } };
    gpolyline(&(Gpoint_list){ 2, p });
    gclear_ws(1, GFLAG_ALWAYS);
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(1);
    ginq_op_st(&op);
    assert_int_equal(op, GST_WSOP);
    gclose_ws(1);
    ginq_op_st(&op);
    assert_int_equal(op, GST_GKOP);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    unsetenv("GKS3D_RECORD");
    int c[1000];
    count_items(REC, c);
    assert_int_equal(c[17], 2);  /* POLYLINE 3 */
    assert_int_equal(c[1], 2);   /* CLEAR: the program's and the end of the last frame */
    assert_int_equal(c[67], 1);  /* HLHSR MODE of the mirrored workstation */
    assert_int_equal(c[6], 1);   /* ESCAPE: the samples; the file name is not recorded */
    assert_int_equal(c[0], 1);   /* END */
}

static void test_wiss_only_and_unset(void **state)
{
    (void)state;
    remove(REC);
    setenv("GKS3D_RECORD", REC, 1);
    gopen_gks(NULL, 0);
    capture_reset();
    gopen_ws(2, NULL, GWS_TYPE_WISS);
    gactivate_ws(2);
    Gpoint p[2] = { { 0.1f, 0.1f }, { 0.9f, 0.9f } };
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_gks();
    assert_int_equal(n_captured, 0);
    unsetenv("GKS3D_RECORD");
    int c[1000];
    count_items(REC, c);
    assert_int_equal(c[17], 0);
    assert_int_equal(c[1], 0);
    assert_int_equal(c[0], 1);
    remove(REC);
    gopen_gks(NULL, 0);
    gopen_ws(1, "test_record_pic2", GWS_TYPE_PNG);
    gactivate_ws(1);
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(access(REC, F_OK), -1); /* unset: nothing recorded */
}

static void test_unopenable(void **state)
{
    (void)state;
    setenv("GKS3D_RECORD", "no_such_dir/x.gksm", 1);
    gopen_gks(NULL, 0);
    capture_reset();
    gopen_ws(1, "test_record_pic3", GWS_TYPE_PNG);
    gactivate_ws(1);
    Gpoint p[2] = { { 0.1f, 0.1f }, { 0.9f, 0.9f } };
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    unsetenv("GKS3D_RECORD");
    assert_int_equal(n_captured, 0);
    assert_int_equal(access("test_record_pic3.png", F_OK), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recorded_and_hidden),
        cmocka_unit_test(test_wiss_only_and_unset),
        cmocka_unit_test(test_unopenable),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
