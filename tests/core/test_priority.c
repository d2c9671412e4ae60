/* SPDX-License-Identifier: MIT */
/*
 * test_priority.c -- SET VIEWPORT INPUT PRIORITY and SET VIEW TRANSFORMATION INPUT
 * PRIORITY (orderings and their inquiries, errors), SET WORKSTATION WINDOW 3 / VIEWPORT 3
 * (requested/current values, deferral, errors 51/53/54).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "core_util.h"

static void list_of(void (*f)(Gint, Gint, Gint *, Gint_list *, Gint *), int n, Gint *out)
{
    Gint err, len;
    Gint_list l = { 0, out };
    f(n, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, n);
}

static void test_viewport_priority(void **u)
{
    (void)u;
    enter_state(GST_GKOP);
    Gint p[32];
    list_of(ginq_list_norm_tran_nums, 32, p);
    for (int i = 0; i < 32; i++)
        assert_int_equal(p[i], i); /* 0 highest, then ascending */
    gset_vp_in_pri(5, 1, GPRI_HIGHER); /* 0 5 1 2 3 4 6 ... */
    gset_vp_in_pri(0, 31, GPRI_LOWER); /* 5 1 2 3 4 6 ... 31 0 */
    gset_vp_in_pri(7, 7, GPRI_LOWER);  /* no effect */
    assert_int_equal(n_captured, 0);
    list_of(ginq_list_norm_tran_nums, 32, p);
    const Gint want[6] = { 5, 1, 2, 3, 4, 6 };
    for (int i = 0; i < 6; i++)
        assert_int_equal(p[i], want[i]);
    assert_int_equal(p[30], 31);
    assert_int_equal(p[31], 0);
    gset_vp_in_pri(32, 1, GPRI_HIGHER);
    gset_vp_in_pri(1, -1, GPRI_HIGHER);
    gset_vp_in_pri(1, 2, (Grel_pri)5);
    assert_int_equal(n_captured, 3);
    assert_int_equal(captured[0].err, 50);
    assert_int_equal(captured[1].err, 50);
    assert_int_equal(captured[2].err, 2000);
    Gint q[32];
    list_of(ginq_list_norm_tran_nums, 32, q);
    assert_memory_equal(p, q, sizeof p); /* errors changed nothing */
    reset_gks();
}

static void view_list(Gint ws, Gint *out)
{
    Gint err, len;
    Gint_list l = { 0, out };
    ginq_list_view_inds(ws, GKS_MAX_VIEW_IND + 1, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, GKS_MAX_VIEW_IND + 1);
}

static void test_view_priority(void **u)
{
    (void)u;
    enter_state(GST_WSOP);
    Gint v[GKS_MAX_VIEW_IND + 1];
    view_list(1, v);
    assert_int_equal(v[0], 0);
    assert_int_equal(v[GKS_MAX_VIEW_IND], GKS_MAX_VIEW_IND);
    gset_view_tran_in_pri(1, 3, 0, GPRI_HIGHER);
    view_list(1, v);
    assert_int_equal(v[0], 3);
    assert_int_equal(v[1], 0);
    assert_int_equal(v[3], 2);
    gset_view_tran_in_pri(1, 21, 0, GPRI_HIGHER);
    gset_view_tran_in_pri(2, 1, 0, GPRI_HIGHER);
    assert_int_equal(n_captured, 2);
    assert_int_equal(captured[0].err, 515);
    assert_int_equal(captured[1].err, 25);
    reset_gks();
}

static void test_ws_window3(void **u)
{
    (void)u;
    enter_state(GST_WSAC);
    const Glimit3 w = { 0.25, 0.75, 0, 0.5, 0.1, 0.9 }, v = { 0, 512, 0, 512, 0, 1 };
    gset_ws_win3(1, &w);
    gset_ws_vp3(1, &v);
    assert_int_equal(n_captured, 0);
    Gint err;
    Gupd_st st;
    Glimit3 rw, cw, rv, cv;
    ginq_ws_tran3(1, &err, &st, &rw, &cw, &rv, &cv);
    assert_int_equal(err, 0);
    assert_memory_equal(&rw, &w, sizeof w);
    assert_memory_equal(&rv, &v, sizeof v);
    /* the display was empty: the new transformation is current at once */
    assert_int_equal(st, GUPD_NOT_PEND);
    assert_memory_equal(&cw, &w, sizeof w);
    const Glimit3 bad_z = { 0, 1, 0, 1, 0.5, 1.5 }, flat = { 0, 1, 0.5, 0.5, 0, 1 };
    const Glimit3 big = { 0, 5000, 0, 10, 0, 1 };
    gset_ws_win3(1, &bad_z);
    gset_ws_win3(1, &flat);
    gset_ws_vp3(1, &big);
    assert_int_equal(n_captured, 3);
    assert_int_equal(captured[0].err, 53);
    assert_int_equal(captured[1].err, 51);
    assert_int_equal(captured[2].err, 54);
    ginq_ws_tran3(1, &err, &st, &rw, &cw, &rv, &cv);
    assert_memory_equal(&rw, &w, sizeof w);
    reset_gks();
}

/* The priority lists answer by the one list rule of the other list inquiries (they had a
 * copier of their own that refused start 0 on an empty list): part from the 0-based start,
 * as much as the application's list holds, the whole length; 2002 for a start outside.
 * An empty list (here: no segments) accepts start 0. */
static void test_list_rule(void **u)
{
    (void)u;
    enter_state(GST_WSOP);
    Gint buf[4] = { -1, -1, -1, -1 }, err = -1, len = -1;
    Gint_list l = { 0, buf };
    ginq_list_norm_tran_nums(2, 30, &err, &l, &len); /* the last two of 32 */
    assert_int_equal(err, 0);
    assert_int_equal(len, 32);
    assert_int_equal(l.num_ints, 2);
    assert_int_equal(buf[0], 30);
    assert_int_equal(buf[1], 31);
    assert_int_equal(buf[2], -1);
    ginq_list_norm_tran_nums(4, 32, &err, &l, &len);
    assert_int_equal(err, 2002);
    ginq_list_norm_tran_nums(4, -1, &err, &l, &len);
    assert_int_equal(err, 2002);
    ginq_list_view_inds(1, 1, GKS_MAX_VIEW_IND, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, GKS_MAX_VIEW_IND + 1);
    assert_int_equal(l.num_ints, 1);
    assert_int_equal(buf[0], GKS_MAX_VIEW_IND);
    ginq_list_view_inds(1, 1, GKS_MAX_VIEW_IND + 1, &err, &l, &len);
    assert_int_equal(err, 2002);
    l.num_ints = -1;
    ginq_set_seg_names(4, 0, &err, &l, &len); /* empty: start 0 gives the length */
    assert_int_equal(err, 0);
    assert_int_equal(len, 0);
    assert_int_equal(l.num_ints, 0);
    ginq_set_seg_names(4, 1, &err, &l, &len);
    assert_int_equal(err, 2002);
    ginq_set_seg_names_ws(1, 4, 0, &err, &l, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, 0);
    ginq_set_seg_names_ws(1, 4, 1, &err, &l, &len);
    assert_int_equal(err, 2002);
    /* a list of another element type: the text font and precision pairs (9 on PNG) */
    Gtext_font_prec fp[4] = { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } };
    Gtext_facs tf = { .num_font_precs = -1, .font_precs = fp };
    ginq_text_facs(GWS_TYPE_PNG, 4, 7, &err, &tf, &len); /* the last two */
    assert_int_equal(err, 0);
    assert_int_equal(len, 9);
    assert_int_equal(tf.num_font_precs, 2);
    assert_true(fp[0].font == -106 && fp[2].font == 0);
    tf.num_font_precs = -1;
    ginq_text_facs(GWS_TYPE_PNG, 4, 9, &err, &tf, &len);
    assert_int_equal(err, 2002);
    assert_int_equal(len, 9);
    assert_int_equal(tf.num_font_precs, -1); /* nothing written on error */
    ginq_text_facs(GWS_TYPE_PNG, 0, 3, &err, &tf, &len); /* no room: the length only */
    assert_int_equal(err, 0);
    assert_int_equal(tf.num_font_precs, 0);
    assert_int_equal(n_captured, 0); /* inquiries report nothing */
    reset_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_viewport_priority),
        cmocka_unit_test(test_view_priority),
        cmocka_unit_test(test_ws_window3),
        cmocka_unit_test(test_list_rule),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
