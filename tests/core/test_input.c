/* SPDX-License-Identifier: MIT */
/*
 * test_input.c -- the checks of the input functions (gks_input.c) before any device is
 * reached: every function reports exactly the standard's first applicable error with its
 * own function identification (7 state, 20, 25, 38 on every category without input
 * devices, 150, 151), sets its outputs to "no input" (REQUEST: status NONE) even on error,
 * changes no state list, and the inquiries report through the error indicator only
 * (7/8, 20, 22, 23, 25, 38, 148) and never call the handler. The devices themselves:
 * test_input_script.c.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <time.h>
#include <cmocka.h>
#include "core_util.h"

enum { WS_NULL = 1, WS_WISS = 2, WS_MO = 3, WS_MI = 4, WS_CLOSED = 7 };

/* Outputs of the last call, filled with garbage before it. */
static Gin_status st;
static Gloc loc;
static Gpoint pts[4];
static Gstroke stroke;
static Gfloat val;
static Gint choice;
static Gpick pick;
static char str[16];

static void garbage(void)
{
    st = GIN_STATUS_OK;
    loc = (Gloc){ 5, { 0.25, 0.75 } };
    stroke = (Gstroke){ 5, 4, pts };
    val = 0.5;
    choice = 3;
    pick = (Gpick){ 4, 5 };
    memcpy(str, "garbage", 8);
}

static const Glimit earea = { 0, 10, 0, 10 };

/* Every function that names a workstation, with its identification. */
typedef struct { void (*call)(Gint ws); int fct; int status; } ws_fn;
static void f_inlc(Gint ws) { ginit_loc(ws, 1, &loc, 1, &earea, NULL); }
static void f_insk(Gint ws) { ginit_stroke(ws, 1, &stroke, 1, &earea, 4, NULL); }
static void f_invl(Gint ws) { ginit_val(ws, 1, 0.5, 1, &earea, 0, 1, NULL); }
static void f_inch(Gint ws) { ginit_choice(ws, 1, GIN_STATUS_OK, 2, 1, &earea, NULL); }
static void f_inpk(Gint ws) { ginit_pick(ws, 1, GIN_STATUS_OK, &pick, 1, &earea, NULL); }
static void f_inst(Gint ws) { ginit_string(ws, 1, "abc", 1, &earea, 10, 1, NULL); }
static void f_slcm(Gint ws) { gset_loc_mode(ws, 1, GOP_EVENT, GSWITCH_ECHO); }
static void f_sskm(Gint ws) { gset_stroke_mode(ws, 1, GOP_SAMPLE, GSWITCH_ECHO); }
static void f_svlm(Gint ws) { gset_val_mode(ws, 1, GOP_REQ, GSWITCH_NO_ECHO); }
static void f_schm(Gint ws) { gset_choice_mode(ws, 1, GOP_REQ, GSWITCH_ECHO); }
static void f_spkm(Gint ws) { gset_pick_mode(ws, 1, GOP_REQ, GSWITCH_ECHO); }
static void f_sstm(Gint ws) { gset_string_mode(ws, 1, GOP_REQ, GSWITCH_ECHO); }
static void f_rqlc(Gint ws) { greq_loc(ws, 1, &st, &loc); }
static void f_rqsk(Gint ws) { greq_stroke(ws, 1, &st, &stroke); }
static void f_rqvl(Gint ws) { greq_val(ws, 1, &st, &val); }
static void f_rqch(Gint ws) { greq_choice(ws, 1, &st, &choice); }
static void f_rqpk(Gint ws) { greq_pick(ws, 1, &st, &pick); }
static void f_rqst(Gint ws) { greq_string(ws, 1, &st, str); }
static void f_smlc(Gint ws) { gsample_loc(ws, 1, &loc); }
static void f_smsk(Gint ws) { gsample_stroke(ws, 1, &stroke); }
static void f_smvl(Gint ws) { gsample_val(ws, 1, &val); }
static void f_smch(Gint ws) { gsample_choice(ws, 1, &st, &choice); }
static void f_smpk(Gint ws) { gsample_pick(ws, 1, &st, &pick); }
static void f_smst(Gint ws) { gsample_string(ws, 1, str); }
static void f_flush(Gint ws) { gflush_events(ws, GIN_LOC, 1); }

static const ws_fn ws_fns[] = {
    { f_inlc, GFN_INLC, 0 }, { f_insk, GFN_INSK, 0 }, { f_invl, GFN_INVL, 0 },
    { f_inch, GFN_INCH, 0 }, { f_inpk, GFN_INPK, 0 }, { f_inst, GFN_INST, 0 },
    { f_slcm, GFN_SLCM, 0 }, { f_sskm, GFN_SSKM, 0 }, { f_svlm, GFN_SVLM, 0 },
    { f_schm, GFN_SCHM, 0 }, { f_spkm, GFN_SPKM, 0 }, { f_sstm, GFN_SSTM, 0 },
    { f_rqlc, GFN_RQLC, 1 }, { f_rqsk, GFN_RQSK, 1 }, { f_rqvl, GFN_RQVL, 1 },
    { f_rqch, GFN_RQCH, 1 }, { f_rqpk, GFN_RQPK, 1 }, { f_rqst, GFN_RQST, 1 },
    { f_smlc, GFN_SMLC, 0 }, { f_smsk, GFN_SMSK, 0 }, { f_smvl, GFN_SMVL, 0 },
    { f_smch, GFN_SMCH, 1 }, { f_smpk, GFN_SMPK, 1 }, { f_smst, GFN_SMST, 0 },
    { f_flush, GFN_FLUSH, 0 },
};
enum { N_WS_FNS = sizeof ws_fns / sizeof ws_fns[0] };

/* The outputs of function i after a call hold "no input". */
static void check_no_input(size_t i)
{
    if (ws_fns[i].status)
        assert_int_equal(st, GIN_STATUS_NONE);
    int fct = ws_fns[i].fct;
    if (fct == GFN_RQLC || fct == GFN_SMLC) {
        assert_int_equal(loc.norm_tran_num, 0);
        assert_true(loc.position.x == 0 && loc.position.y == 0);
    }
    if (fct == GFN_RQSK || fct == GFN_SMSK)
        assert_true(stroke.num_points == 0 && stroke.norm_tran_num == 0);
    if (fct == GFN_RQVL || fct == GFN_SMVL)
        assert_true(val == 0);
    if (fct == GFN_RQCH || fct == GFN_SMCH)
        assert_int_equal(choice, 0);
    if (fct == GFN_RQPK || fct == GFN_SMPK)
        assert_true(pick.seg_name == 0 && pick.pick_id == 0);
    if (fct == GFN_RQST || fct == GFN_SMST)
        assert_string_equal(str, "");
}

/* Calls every workstation function on ws and expects exactly error `want`. */
static void expect_all(Gint ws, int want)
{
    for (size_t i = 0; i < N_WS_FNS; i++) {
        snapshot before, after;
        take_snapshot(&before);
        garbage();
        n_captured = 0;
        ws_fns[i].call(ws);
        take_snapshot(&after);
        if (n_captured != 1 || captured[0].err != want || captured[0].fct != ws_fns[i].fct)
            fail_msg("%s on ws %d: %d errors, first %d (fct %d), want %d",
                     gks_function_name(ws_fns[i].fct), ws, n_captured,
                     n_captured ? captured[0].err : 0, n_captured ? captured[0].fct : -1,
                     want);
        check_no_input(i);
        assert_memory_equal(&before, &after, sizeof before);
    }
}

static void test_state_errors_reset_outputs(void **unused)
{
    (void)unused;
    enter_state(GST_GKCL);
    expect_all(1, 7);
    enter_state(GST_GKOP);
    expect_all(1, 7);
    reset_gks();
}

/* 20 and 25 come before the category. */
static void test_workstation_identifier(void **unused)
{
    (void)unused;
    enter_state(GST_WSOP);
    expect_all(-1, 20);
    expect_all(WS_CLOSED, 25);
    reset_gks();
}

/* The categories without input devices give 38 in every state that allows the
 * functions, on OUTPUT, WISS, MO and MI workstations alike. */
static void test_every_category_is_38(void **unused)
{
    (void)unused;
    enter_state(GST_GKOP);
    gopen_ws(WS_MO, "input_test.gksm", GWS_TYPE_MO);
    gclose_ws(WS_MO);
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gopen_ws(WS_WISS, NULL, GWS_TYPE_WISS);
    gopen_ws(WS_MO, "input_test2.gksm", GWS_TYPE_MO);
    gopen_ws(WS_MI, "input_test.gksm", GWS_TYPE_MI);
    assert_int_equal(n_captured, 0);
    Gws_cat cat;
    Gint err;
    const Gint ids[4] = { WS_NULL, WS_WISS, WS_MO, WS_MI };
    const Gws_cat cats[4] = { GCAT_OUT, GCAT_WISS, GCAT_MO, GCAT_MI };
    for (int k = 0; k < 4; k++) {
        Gint type;
        char conn[64];
        ginq_ws_conn_type(ids[k], (Gint)sizeof conn, &err, conn, &type);
        ginq_ws_cat(type, &err, &cat);
        assert_int_equal(cat, cats[k]);
        expect_all(ids[k], 38);
    }
    gactivate_ws(WS_NULL);
    expect_all(WS_WISS, 38);
    gcreate_seg(1);
    expect_all(WS_NULL, 38);
    reset_gks();
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void test_await_event(void **unused)
{
    (void)unused;
    Gint ws = 9, num = 9;
    Gin_class cls = GIN_STRING;
    enter_state(GST_GKOP);
    gawait_event(0, &ws, &cls, &num);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 7);
    assert_int_equal(captured[0].fct, GFN_WAIT);
    assert_true(ws == 0 && cls == GIN_NONE && num == 0);

    enter_state(GST_WSAC);
    const double bad[4] = { -1, -1e-30, NAN, INFINITY };
    for (int i = 0; i < 4; i++) {
        n_captured = 0;
        ws = num = 9;
        cls = GIN_PICK;
        gawait_event(bad[i], &ws, &cls, &num);
        assert_int_equal(n_captured, 1);
        assert_int_equal(captured[0].err, 151);
        assert_int_equal(captured[0].fct, GFN_WAIT);
        assert_true(ws == 0 && cls == GIN_NONE && num == 0);
    }
    /* A valid timeout with no input workstation: class NONE after the timeout. */
    const double good[2] = { 0, 0.02 };
    for (int i = 0; i < 2; i++) {
        n_captured = 0;
        ws = num = 9;
        cls = GIN_LOC;
        double t0 = now();
        gawait_event(good[i], &ws, &cls, &num);
        assert_true(now() - t0 < 0.5 && now() - t0 >= good[i]);
        assert_int_equal(n_captured, 0);
        assert_true(ws == 0 && cls == GIN_NONE && num == 0);
    }
    reset_gks();
}

/* GET ...: 7, then 150 even right after AWAIT EVENT. */
static void test_get(void **unused)
{
    (void)unused;
    const int fcts[6] = { GFN_GTLC, GFN_GTSK, GFN_GTVL, GFN_GTCH, GFN_GTPK, GFN_GTST };
    for (Gop_st s = GST_GKCL; s <= GST_SGOP; s++) {
        enter_state(s);
        Gint ws, num;
        Gin_class cls;
        if (s >= GST_WSOP)
            gawait_event(0.01, &ws, &cls, &num);
        garbage(); /* each GET resets its own outputs */
        for (int i = 0; i < 6; i++) {
            n_captured = 0;
            switch (i) {
            case 0: gget_loc(&loc); break;
            case 1: gget_stroke(&stroke); break;
            case 2: gget_val(&val); break;
            case 3: gget_choice(&st, &choice); break;
            case 4: gget_pick(&st, &pick); break;
            default: gget_string(str); break;
            }
            assert_int_equal(n_captured, 1);
            assert_int_equal(captured[0].err, s >= GST_WSOP ? 150 : 7);
            assert_int_equal(captured[0].fct, fcts[i]);
        }
        assert_int_equal(loc.norm_tran_num, 0);
        assert_int_equal(stroke.num_points, 0);
        assert_true(val == 0 && choice == 0 && st == GIN_STATUS_NONE);
        assert_true(pick.seg_name == 0 && str[0] == '\0');
    }
    reset_gks();
}

/* The device state inquiries: 7, 20, 25, 38; the outputs are not written. */
static Gint inq_state(int k, Gint ws)
{
    Gint err = -1;
    Gloc_st ls;
    Gstroke_st ks;
    Gval_st vs;
    Gchoice_st cs;
    Gpick_st ps;
    Gstring_st ss;
    memset(&ls, 0x5a, sizeof ls);
    Gloc_st ref = ls;
    switch (k) {
    case 0: ginq_loc_st(ws, 1, GINQ_SET, &err, &ls); break;
    case 1: ginq_stroke_st(ws, 1, GINQ_REALIZED, &err, &ks); break;
    case 2: ginq_val_st(ws, 1, &err, &vs); break;
    case 3: ginq_choice_st(ws, 1, &err, &cs); break;
    case 4: ginq_pick_st(ws, 1, GINQ_SET, &err, &ps); break;
    default: ginq_string_st(ws, 1, &err, &ss); break;
    }
    assert_memory_equal(&ls, &ref, sizeof ls);
    return err;
}

static Gint inq_default(int k, Gint type)
{
    Gint err = -1;
    Gdef_loc dl = { 0 };
    Gdef_stroke dk = { 0 };
    Gdef_val dv = { 0 };
    Gdef_choice dc = { 0 };
    Gdef_in dp = { 0 };
    Gdef_string ds = { 0 };
    switch (k) {
    case 0: ginq_def_loc_data(type, 1, &err, &dl); break;
    case 1: ginq_def_stroke_data(type, 1, &err, &dk); break;
    case 2: ginq_def_val_data(type, 1, &err, &dv); break;
    case 3: ginq_def_choice_data(type, 1, &err, &dc); break;
    case 4: ginq_def_pick_data(type, 1, &err, &dp); break;
    default: ginq_def_string_data(type, 1, &err, &ds); break;
    }
    return err;
}

static void test_inquiries(void **unused)
{
    (void)unused;
    Gint err, ws, num;
    Gin_class cls;
    Gsimult_events more;
    Gnum_in nin = { 7, 7, 7, 7, 7, 7 };

    enter_state(GST_GKCL);
    for (int k = 0; k < 6; k++) {
        assert_int_equal(inq_state(k, 1), 7);
        assert_int_equal(inq_default(k, GWS_TYPE_NULL), 8);
    }
    ginq_num_avail_in(GWS_TYPE_NULL, &err, &nin);
    assert_int_equal(err, 8);

    enter_state(GST_GKOP);
    for (int k = 0; k < 6; k++) {
        assert_int_equal(inq_state(k, 1), 7);
        assert_int_equal(inq_default(k, 0), 22);
        assert_int_equal(inq_default(k, 12345), 23);
        assert_int_equal(inq_default(k, GWS_TYPE_PNG), 0);
        assert_int_equal(inq_default(k, GWS_TYPE_NULL), 38);
        assert_int_equal(inq_default(k, GWS_TYPE_WISS), 38);
    }
    ginq_in_overf(&err, &ws, &cls, &num);
    assert_int_equal(err, 7);
    ginq_more_simult_events(&err, &more);
    assert_int_equal(err, 7);
    ginq_num_avail_in(GWS_TYPE_PNG, &err, &nin);
    assert_int_equal(err, 0);
    assert_true(nin.loc == 2 && nin.stroke == 2 && nin.val == 2 && nin.choice == 2 &&
                nin.pick == 2 && nin.string == 2);
    nin = (Gnum_in){ 7, 7, 7, 7, 7, 7 };
    const Gint types[4] = { GWS_TYPE_NULL, GWS_TYPE_WISS, GWS_TYPE_MO, GWS_TYPE_MI };
    for (int i = 0; i < 4; i++) {
        err = -1;
        ginq_num_avail_in(types[i], &err, &nin);
        assert_int_equal(err, 38);
    }
    ginq_num_avail_in(-3, &err, &nin);
    assert_int_equal(err, 22);
    ginq_num_avail_in(12345, &err, &nin);
    assert_int_equal(err, 23);
    assert_int_equal(nin.loc, 7); /* not written on error */

    enter_state(GST_SGOP);
    for (int k = 0; k < 6; k++) {
        assert_int_equal(inq_state(k, -1), 20);
        assert_int_equal(inq_state(k, WS_CLOSED), 25);
        assert_int_equal(inq_state(k, 1), 38);
    }
    ws = num = 5;
    cls = GIN_VAL;
    ginq_in_overf(&err, &ws, &cls, &num);
    assert_int_equal(err, 148);
    assert_true(ws == 5 && cls == GIN_VAL && num == 5);
    more = GSIMULT_MORE;
    ginq_more_simult_events(&err, &more);
    assert_int_equal(err, 0);
    assert_int_equal(more, GSIMULT_NO_MORE);
    /* Level 2c: full output, WISS, input in REQUEST, SAMPLE and EVENT mode. */
    Glevel level;
    ginq_level_gks(&err, &level);
    assert_int_equal(level, GLEVEL_2C);
    assert_int_equal(n_captured, 0); /* inquiries never call the handler */
    reset_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_state_errors_reset_outputs),
        cmocka_unit_test(test_workstation_identifier),
        cmocka_unit_test(test_every_category_is_38),
        cmocka_unit_test(test_await_event),
        cmocka_unit_test(test_get),
        cmocka_unit_test(test_inquiries),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
