/* SPDX-License-Identifier: MIT */
/*
 * test_input_script.c -- the logical input devices driven by input scripts (docs/INPUT.md)
 * on the PNG workstation (category OUTIN, display space 1024 x 1024 DC): every class in
 * REQUEST, SAMPLE and EVENT mode with every prompt/echo type; break and an exhausted
 * script give status NONE at once; locator and stroke through overlapping viewports by
 * viewport input priority and LOCATOR 3 through the view transformation input priority;
 * PICK of overlapping segments by priority, visibility and detectability; the event queue
 * (order, FLUSH, overflow 147/148/149, GET 150); AWAIT EVENT's timeout; the INITIALISE
 * checks and the device state and default data inquiries.
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <cmocka.h>
#include "core_util.h"

enum { WS = 1 };

static void write_script(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* GKS open with PNG workstation WS active and `script` as its input script. */
static void open_with_script(const char *script)
{
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(WS, "input_script_out", GWS_TYPE_PNG);
    gactivate_ws(WS);
    write_script("input_script.txt", script);
    Gint id = WS;
    Gescape_in_data in = { { 1, &id, 0, NULL, 16, "input_script.txt" } };
    gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
    assert_int_equal(n_captured, 0);
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const Glimit earea = { 0, 1024, 0, 1024 };

/* Initialises device 1 of class cls with prompt/echo type pet (default values). */
static void init_dev(Gin_class cls, Gint pet)
{
    Gloc l = { 0, { 0.5, 0.5 } };
    Gpoint p0 = { 0.5, 0.5 };
    Gstroke s = { 0, 1, &p0 };
    Gpick pk = { 1, 1 };
    switch (cls) {
    case GIN_LOC: ginit_loc(WS, 1, &l, pet, &earea, NULL); break;
    case GIN_STROKE: ginit_stroke(WS, 1, &s, pet, &earea, 16, NULL); break;
    case GIN_VAL: ginit_val(WS, 1, 5, pet, &earea, 0, 10, NULL); break;
    case GIN_CHOICE: ginit_choice(WS, 1, GIN_STATUS_OK, 1, pet, &earea, NULL); break;
    case GIN_PICK: ginit_pick(WS, 1, GIN_STATUS_NO_IN, &pk, pet, &earea, NULL); break;
    default: ginit_string(WS, 1, "", pet, &earea, 20, 1, NULL); break;
    }
}

static void set_mode(Gin_class cls, Gop_mode m, Gecho_switch e)
{
    switch (cls) {
    case GIN_LOC: gset_loc_mode(WS, 1, m, e); break;
    case GIN_STROKE: gset_stroke_mode(WS, 1, m, e); break;
    case GIN_VAL: gset_val_mode(WS, 1, m, e); break;
    case GIN_CHOICE: gset_choice_mode(WS, 1, m, e); break;
    case GIN_PICK: gset_pick_mode(WS, 1, m, e); break;
    default: gset_string_mode(WS, 1, m, e); break;
    }
}

/* One value of each class as a script line, and its check. The pick line hits the
 * square of segment 7 (pick id 3) drawn by draw_pick_square. */
static const char *const class_line[6] = {
    "locator 1 256 768\n", "stroke 1 0 0 512 512 1024 1024\n", "valuator 1 7.25\n",
    "choice 1 4\n", "pick 1 512 512\n", "string 1 hello world\n",
};

static void draw_pick_square(void)
{
    Gpoint sq[4] = { { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 }, { 0.4, 0.6 } };
    Gpoint_list pl = { 4, sq };
    gcreate_seg(7);
    gset_pick_id(3);
    gfill_area(&pl);
    gclose_seg();
    gset_det(7, GSEG_DET);
}

typedef struct {
    Gin_status st;
    Gloc loc;
    Gpoint pts[16];
    Gstroke stroke;
    Gfloat val;
    Gint choice;
    Gpick pick;
    char str[32];
} values;

static void check_value(Gin_class cls, const values *v)
{
    switch (cls) {
    case GIN_LOC:
        assert_int_equal(v->loc.norm_tran_num, 0);
        assert_float_equal(v->loc.position.x, 0.25, 1e-12);
        assert_float_equal(v->loc.position.y, 0.75, 1e-12);
        break;
    case GIN_STROKE:
        assert_int_equal(v->stroke.num_points, 3);
        assert_float_equal(v->pts[1].x, 0.5, 1e-12);
        assert_float_equal(v->pts[2].y, 1.0, 1e-12);
        break;
    case GIN_VAL: assert_float_equal(v->val, 7.25, 0); break;
    case GIN_CHOICE: assert_int_equal(v->choice, 4); break;
    case GIN_PICK:
        assert_int_equal(v->pick.seg_name, 7);
        assert_int_equal(v->pick.pick_id, 3);
        break;
    default: assert_string_equal(v->str, "hello world"); break;
    }
}

static void request(Gin_class cls, values *v)
{
    v->stroke = (Gstroke){ 0, 16, v->pts };
    switch (cls) {
    case GIN_LOC: greq_loc(WS, 1, &v->st, &v->loc); break;
    case GIN_STROKE: greq_stroke(WS, 1, &v->st, &v->stroke); break;
    case GIN_VAL: greq_val(WS, 1, &v->st, &v->val); break;
    case GIN_CHOICE: greq_choice(WS, 1, &v->st, &v->choice); break;
    case GIN_PICK: greq_pick(WS, 1, &v->st, &v->pick); break;
    default: greq_string(WS, 1, &v->st, v->str); break;
    }
}

static void sample(Gin_class cls, values *v)
{
    v->stroke = (Gstroke){ 0, 16, v->pts };
    v->st = GIN_STATUS_OK;
    switch (cls) {
    case GIN_LOC: gsample_loc(WS, 1, &v->loc); break;
    case GIN_STROKE: gsample_stroke(WS, 1, &v->stroke); break;
    case GIN_VAL: gsample_val(WS, 1, &v->val); break;
    case GIN_CHOICE: gsample_choice(WS, 1, &v->st, &v->choice); break;
    case GIN_PICK: gsample_pick(WS, 1, &v->st, &v->pick); break;
    default: gsample_string(WS, 1, v->str); break;
    }
}

static void get(Gin_class cls, values *v)
{
    v->stroke = (Gstroke){ 0, 16, v->pts };
    v->st = GIN_STATUS_OK;
    switch (cls) {
    case GIN_LOC: gget_loc(&v->loc); break;
    case GIN_STROKE: gget_stroke(&v->stroke); break;
    case GIN_VAL: gget_val(&v->val); break;
    case GIN_CHOICE: gget_choice(&v->st, &v->choice); break;
    case GIN_PICK: gget_pick(&v->st, &v->pick); break;
    default: gget_string(v->str); break;
    }
}

/* Every class x mode x prompt/echo type x echo switch. */
static void test_class_mode_pet(void **u)
{
    (void)u;
    const int max_pet[6] = { 6, 4, 3, 3, 3, 1 };
    for (Gin_class cls = GIN_LOC; cls <= GIN_STRING; cls++)
        for (Gop_mode m = GOP_REQ; m <= GOP_EVENT; m++)
            for (int pet = 1; pet <= max_pet[cls - GIN_LOC]; pet++)
                for (int echo = 0; echo < 2; echo++) {
                    if (cls == GIN_LOC && m == GOP_REQ && pet == 1 && echo == 0) {
                        open_with_script("");
                        draw_pick_square();
                    }
                    write_script("input_script.txt", class_line[cls - GIN_LOC]);
                    Gint id = WS;
                    Gescape_in_data in = { { 1, &id, 0, NULL, 16, "input_script.txt" } };
                    gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
                    init_dev(cls, pet);
                    set_mode(cls, m, echo ? GSWITCH_ECHO : GSWITCH_NO_ECHO);
                    assert_int_equal(n_captured, 0);
                    values v;
                    memset(&v, 0, sizeof v);
                    if (m == GOP_REQ) {
                        request(cls, &v);
                        assert_int_equal(v.st, GIN_STATUS_OK);
                    } else if (m == GOP_SAMPLE) {
                        sample(cls, &v);
                    } else {
                        Gint ws, num;
                        Gin_class c;
                        gawait_event(0, &ws, &c, &num);
                        assert_int_equal(c, cls);
                        assert_true(ws == WS && num == 1);
                        get(cls, &v);
                        assert_int_equal(v.st, GIN_STATUS_OK);
                    }
                    assert_int_equal(n_captured, 0);
                    check_value(cls, &v);
                    if (m == GOP_SAMPLE) { /* the measure stays until the next action */
                        memset(&v, 0, sizeof v);
                        sample(cls, &v);
                        check_value(cls, &v);
                    }
                }
    reset_gks();
}

/* Break, no choice, no pick; an exhausted script: status NONE at once. */
static void test_break_and_exhausted(void **u)
{
    (void)u;
    open_with_script("break locator 1\nchoice 1 0\npick 1 10 10\n# comment\n\n"
                     "bogus line\nlocator 1 512 512\n");
    Gin_status st;
    Gloc l;
    greq_loc(WS, 1, &st, &l);
    assert_int_equal(st, GIN_STATUS_NONE);
    Gint c;
    greq_choice(WS, 1, &st, &c);
    assert_int_equal(st, GIN_STATUS_NO_IN);
    Gpick p;
    greq_pick(WS, 1, &st, &p);
    assert_int_equal(st, GIN_STATUS_NO_IN);
    greq_loc(WS, 1, &st, &l); /* the bogus line is skipped */
    assert_int_equal(st, GIN_STATUS_OK);
    assert_float_equal(l.position.x, 0.5, 1e-12);
    double t0 = now();
    for (int i = 0; i < 100; i++) {
        greq_loc(WS, 1, &st, &l);
        assert_int_equal(st, GIN_STATUS_NONE);
        greq_string(WS, 1, &st, (char[81]){ 0 });
        assert_int_equal(st, GIN_STATUS_NONE);
    }
    assert_true(now() - t0 < 2.0);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

/* Overlapping viewports: the one of higher viewport input priority takes the position. */
static void test_viewport_priority(void **u)
{
    (void)u;
    open_with_script("locator 1 512 512\nlocator 1 512 512\nlocator 1 100 100\n"
                     "stroke 1 400 400 600 600\n");
    Glimit w1 = { 0, 10, 0, 10 }, v1 = { 0, 0.75, 0, 0.75 };
    Glimit w2 = { 100, 200, 100, 200 }, v2 = { 0.25, 1, 0.25, 1 };
    gset_win(1, &w1);
    gset_vp(1, &v1);
    gset_win(2, &w2);
    gset_vp(2, &v2);
    gset_vp_in_pri(1, 0, GPRI_HIGHER);
    gset_vp_in_pri(2, 1, GPRI_HIGHER); /* 2 > 1 > 0 */
    Gin_status st;
    Gloc l;
    greq_loc(WS, 1, &st, &l);
    assert_int_equal(l.norm_tran_num, 2);
    assert_float_equal(l.position.x, 100 + 100 * (0.5 - 0.25) / 0.75, 1e-9);
    gset_vp_in_pri(1, 2, GPRI_HIGHER); /* 1 > 2 > 0 */
    greq_loc(WS, 1, &st, &l);
    assert_int_equal(l.norm_tran_num, 1);
    assert_float_equal(l.position.y, 10 * 0.5 / 0.75, 1e-9);
    greq_loc(WS, 1, &st, &l); /* (0.098, 0.098): only 1 and 0 hold it */
    assert_int_equal(l.norm_tran_num, 1);
    gset_vp_in_pri(0, 1, GPRI_HIGHER);
    Gpoint pts[4];
    Gstroke s = { 0, 4, pts };
    greq_stroke(WS, 1, &st, &s);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(s.norm_tran_num, 0);
    assert_int_equal(s.num_points, 2);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

/* LOCATOR 3 / STROKE 3: back through the view of highest view transformation input
 * priority whose clip limits hold the point. */
static void test_view_priority3(void **u)
{
    (void)u;
    open_with_script("locator3 1 512 512 0.5\nlocator3 1 512 512 0.5\nlocator3 1 100 100 0.5\n"
                     "stroke3 1 512 512 0.5 600 600 0.25\n");
    /* View 1: a translation by +0.25 in x; clip limits the upper right part. */
    Gview_rep3 r;
    memset(&r, 0, sizeof r);
    for (int i = 0; i < 4; i++)
        r.ori_matrix[i][i] = r.map_matrix[i][i] = 1;
    r.map_matrix[0][3] = 0.25;
    r.clip_limit = (Glimit3){ 0.3, 1, 0.3, 1, 0, 1 };
    r.xy_clip = r.back_clip = r.front_clip = GIND_CLIP;
    gset_view_rep3(WS, 1, &r);
    gset_view_tran_in_pri(WS, 1, 0, GPRI_HIGHER);
    Gin_status st;
    Gint vi = -1;
    Gloc3 l;
    greq_loc3(WS, 1, &st, &vi, &l);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(vi, 1);
    assert_float_equal(l.position.x, 0.25, 1e-9);
    assert_float_equal(l.position.z, 0.5, 1e-9);
    gset_view_tran_in_pri(WS, 0, 1, GPRI_HIGHER);
    greq_loc3(WS, 1, &st, &vi, &l);
    assert_int_equal(vi, 0);
    assert_float_equal(l.position.x, 0.5, 1e-9);
    gset_view_tran_in_pri(WS, 1, 0, GPRI_HIGHER);
    greq_loc3(WS, 1, &st, &vi, &l); /* outside view 1's clip limits */
    assert_int_equal(vi, 0);
    Gpoint3 p[4];
    Gstroke3 s = { 0, 4, p };
    greq_stroke3(WS, 1, &st, &vi, &s);
    assert_int_equal(vi, 1);
    assert_int_equal(s.num_points, 2);
    assert_float_equal(p[1].z, 0.25, 1e-9);
    /* The 2-D REQUEST LOCATOR on the same device gives the x, y of the same result. */
    assert_int_equal(n_captured, 0);
    reset_gks();
}

/* Overlapping segments: the higher segment priority wins; invisible or undetectable
 * segments are never picked; equal priority: the later one (drawn on top). */
static void test_pick_priority(void **u)
{
    (void)u;
    open_with_script("pick 1 512 512\npick 1 512 512\npick 1 512 512\npick 1 512 512\n"
                     "pick 1 512 512\npick 1 900 900\npick 1 716 512\n");
    Gpoint a[4] = { { 0.2, 0.2 }, { 0.7, 0.2 }, { 0.7, 0.7 }, { 0.2, 0.7 } };
    Gpoint b[4] = { { 0.4, 0.4 }, { 0.9, 0.4 }, { 0.9, 0.9 }, { 0.4, 0.9 } };
    Gpoint ln[2] = { { 0.7, 0.1 }, { 0.7, 0.95 } };
    Gpoint_list pa = { 4, a }, pb = { 4, b }, pl = { 2, ln };
    gcreate_seg(1);
    gset_pick_id(11);
    gfill_area(&pa);
    gclose_seg();
    gcreate_seg(2);
    gset_pick_id(21);
    gfill_area(&pb);
    gset_pick_id(22);
    gpolyline(&pl);
    gclose_seg();
    gset_det(1, GSEG_DET);
    gset_det(2, GSEG_DET);
    gset_seg_pri(1, 0.8);
    gset_seg_pri(2, 0.2);
    Gin_status st;
    Gpick p;
    greq_pick(WS, 1, &st, &p);
    assert_true(st == GIN_STATUS_OK && p.seg_name == 1 && p.pick_id == 11);
    gset_seg_pri(2, 0.9);
    greq_pick(WS, 1, &st, &p);
    assert_true(p.seg_name == 2 && p.pick_id == 21);
    gset_det(2, GSEG_UNDET);
    greq_pick(WS, 1, &st, &p);
    assert_int_equal(p.seg_name, 1);
    gset_det(2, GSEG_DET);
    gset_vis(2, GSEG_INVIS);
    greq_pick(WS, 1, &st, &p);
    assert_int_equal(p.seg_name, 1);
    gset_vis(2, GSEG_VIS);
    gset_seg_pri(2, 0.8); /* equal priority: 2 was created later */
    greq_pick(WS, 1, &st, &p);
    assert_int_equal(p.seg_name, 2);
    greq_pick(WS, 1, &st, &p); /* (0.879, 0.879): segment 2 only */
    assert_true(st == GIN_STATUS_OK && p.seg_name == 2 && p.pick_id == 21);
    greq_pick(WS, 1, &st, &p); /* on the line x = 0.7 (within the aperture) */
    assert_true(p.seg_name == 2 && p.pick_id == 22);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

static int err_count(int err)
{
    int k = 0;
    for (int i = 0; i < n_captured; i++)
        k += captured[i].err == err;
    return k;
}

/* Queue order across classes, FLUSH, GET 150, SAMPLE lines skipped by AWAIT. */
static void test_queue_order_flush(void **u)
{
    (void)u;
    open_with_script("valuator 1 1\nchoice 1 2\nvaluator 2 0.25\nstring 1 abc\n"
                     "choice 1 3\nvaluator 1 0.5\n");
    gset_val_mode(WS, 1, GOP_EVENT, GSWITCH_ECHO);
    gset_val_mode(WS, 2, GOP_SAMPLE, GSWITCH_ECHO);
    gset_choice_mode(WS, 1, GOP_EVENT, GSWITCH_ECHO);
    gset_string_mode(WS, 1, GOP_EVENT, GSWITCH_ECHO);
    Gint ws, num;
    Gin_class c;
    const Gin_class want[4] = { GIN_VAL, GIN_CHOICE, GIN_STRING, GIN_CHOICE };
    for (int i = 0; i < 4; i++) {
        gawait_event(0, &ws, &c, &num);
        assert_int_equal(c, want[i]);
        if (i == 1) {
            Gin_status st;
            Gint ch;
            gget_choice(&st, &ch);
            assert_int_equal(ch, 2);
            Gfloat v;
            gget_val(&v); /* not the class of the report */
            assert_int_equal(err_count(150), 1);
            gsample_val(WS, 2, &v); /* valuator 2 took its line on the way */
            assert_float_equal(v, 0.25, 0);
        }
        if (i == 2) {
            /* Flush the rest of the choice events: one queued by now? The script is read
             * as events are awaited, so nothing more is queued yet. */
            gflush_events(WS, GIN_CHOICE, 1);
        }
    }
    gawait_event(0, &ws, &c, &num);
    assert_int_equal(c, GIN_VAL);
    gawait_event(0, &ws, &c, &num);
    assert_int_equal(c, GIN_NONE);
    Gfloat v;
    gget_val(&v); /* the report is empty now */
    assert_int_equal(err_count(150), 2);
    /* FLUSH removes a device's queued events (queue filled by AWAIT of another). */
    reset_gks();
    open_with_script("choice 1 1\nchoice 1 2\nchoice 2 1\n");
    gset_choice_mode(WS, 1, GOP_EVENT, GSWITCH_ECHO);
    gset_choice_mode(WS, 2, GOP_EVENT, GSWITCH_ECHO);
    gawait_event(0, &ws, &c, &num); /* 1/1 current; 1/1 line 2 not yet read */
    gset_choice_mode(WS, 2, GOP_EVENT, GSWITCH_ECHO);
    Gint err = 0;
    n_captured = 0;
    gflush_events(WS, GIN_CHOICE, 3);
    assert_int_equal(err_count(140), 1);
    gflush_events(WS, (Gin_class)9, 1);
    assert_int_equal(err_count(2000), 1);
    (void)err;
    reset_gks();
}

/* Overflow: events beyond the capacity are lost until the queue is emptied; AWAIT
 * reports 147 once; INQUIRE INPUT QUEUE OVERFLOW names the device (then 148); closing
 * that workstation gives 149. */
static void test_queue_overflow(void **u)
{
    (void)u;
    char *script = malloc(40 * (GKS_IN_QUEUE_CAPACITY + 10));
    size_t at = 0;
    for (int i = 0; i < GKS_IN_QUEUE_CAPACITY + 5; i++)
        at += (size_t)sprintf(script + at, "choice 2 %d\n", 1 + i % 9);
    open_with_script(script);
    free(script);
    gset_choice_mode(WS, 2, GOP_EVENT, GSWITCH_NO_ECHO);
    gset_loc_mode(WS, 1, GOP_REQ, GSWITCH_NO_ECHO);
    /* Fill the queue: the script is read by AWAIT until an event is queued, so push
     * everything in with a SAMPLE-free loop of zero-timeout AWAITs that leave events
     * queued: each AWAIT takes one off and reads more. Instead read all lines at once
     * through REQUEST of another device, which delivers every line on its way. */
    Gin_status st;
    Gloc l;
    greq_loc(WS, 1, &st, &l); /* runs through the whole script: status NONE */
    assert_int_equal(st, GIN_STATUS_NONE);
    Gint err, ws, num;
    Gin_class c;
    ginq_in_overf(&err, &ws, &c, &num);
    assert_int_equal(err, 0);
    assert_true(ws == WS && c == GIN_CHOICE && num == 2);
    ginq_in_overf(&err, &ws, &c, &num);
    assert_int_equal(err, 148);
    n_captured = 0;
    gawait_event(0, &ws, &c, &num);
    assert_int_equal(c, GIN_CHOICE);
    assert_int_equal(err_count(147), 1);
    int n = 1;
    for (;;) {
        gawait_event(0, &ws, &c, &num);
        if (c == GIN_NONE)
            break;
        n++;
    }
    assert_int_equal(n, GKS_IN_QUEUE_CAPACITY);
    assert_int_equal(err_count(147), 1);
    reset_gks();

    /* 149: the workstation of the overflow is closed. */
    script = malloc(40 * (GKS_IN_QUEUE_CAPACITY + 10));
    at = 0;
    for (int i = 0; i < GKS_IN_QUEUE_CAPACITY + 1; i++)
        at += (size_t)sprintf(script + at, "valuator 1 0.5\n");
    open_with_script(script);
    free(script);
    gset_val_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    greq_loc(WS, 1, &st, &l);
    gdeactivate_ws(WS);
    gopen_ws(2, NULL, GWS_TYPE_NULL);
    gclose_ws(WS);
    ginq_in_overf(&err, &ws, &c, &num);
    assert_int_equal(err, 149);
    gawait_event(0, &ws, &c, &num); /* its events went with it */
    assert_int_equal(c, GIN_NONE);
    reset_gks();
}

/* AWAIT EVENT waits at least the timeout when nothing comes, and not much longer (the
 * upper bound is generous: a loaded machine delays wake-ups). */
static void test_await_timeout(void **u)
{
    (void)u;
    open_with_script("locator 1 10 10\n");
    gset_choice_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    const double t[3] = { 0, 0.01, 0.05 };
    for (int i = 0; i < 3; i++) {
        Gint ws, num;
        Gin_class c;
        double t0 = now();
        gawait_event(t[i], &ws, &c, &num);
        double dt = now() - t0;
        assert_int_equal(c, GIN_NONE);
        assert_true(dt >= t[i]);
        assert_true(dt < t[i] + 0.5);
        printf("AWAIT EVENT timeout %.3f s: returned after %.4f s\n", t[i], dt);
    }
    /* The locator line (REQUEST mode) stays for the REQUEST. */
    Gin_status st;
    Gloc l;
    greq_loc(WS, 1, &st, &l);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(n_captured, 0);
    reset_gks();
}

static int last_err(void) { return n_captured ? captured[n_captured - 1].err : 0; }

/* INITIALISE checks; 141, 142; the state inquiries see what was set; default data. */
static void test_init_checks_and_inquiries(void **u)
{
    (void)u;
    open_with_script("");
    Gloc l = { 0, { 0.5, 0.5 } };
    Glimit bad = { 10, 5, 0, 1 }, outside = { 0, 2000, 0, 10 };
    ginit_loc(WS, 1, &l, 7, &earea, NULL);
    assert_int_equal(last_err(), 144);
    ginit_loc(WS, 1, &l, 1, &bad, NULL);
    assert_int_equal(last_err(), 51);
    ginit_loc(WS, 1, &l, 1, &outside, NULL);
    assert_int_equal(last_err(), 145);
    Gin_data rec = { -1, NULL, 0, NULL, 0, NULL };
    ginit_loc(WS, 1, &l, 1, &earea, &rec);
    assert_int_equal(last_err(), 146);
    Gloc far = { 0, { 2, 0.5 } };
    ginit_loc(WS, 1, &far, 1, &earea, NULL);
    assert_int_equal(last_err(), 152);
    ginit_loc(WS, 3, &l, 1, &earea, NULL);
    assert_int_equal(last_err(), 140);
    Gpoint pts[5] = { { 0, 0 }, { 1, 1 }, { 0, 1 }, { 1, 0 }, { 0.5, 0.5 } };
    Gstroke s = { 0, 5, pts };
    ginit_stroke(WS, 1, &s, 1, &earea, 4, NULL);
    assert_int_equal(last_err(), 153);
    ginit_val(WS, 1, 11, 1, &earea, 0, 10, NULL);
    assert_int_equal(last_err(), 152);
    ginit_val(WS, 1, 1, 1, &earea, 10, 0, NULL);
    assert_int_equal(last_err(), 146);
    ginit_choice(WS, 1, GIN_STATUS_OK, 0, 1, &earea, NULL);
    assert_int_equal(last_err(), 152);
    ginit_string(WS, 1, "too long", 1, &earea, 4, 1, NULL);
    assert_int_equal(last_err(), 154);
    ginit_string(WS, 1, "ab", 1, &earea, 4, 5, NULL);
    assert_int_equal(last_err(), 152);
    Gfloat v;
    gsample_val(WS, 1, &v);
    assert_int_equal(last_err(), 142);
    gset_val_mode(WS, 1, GOP_SAMPLE, GSWITCH_ECHO);
    Gin_status st;
    greq_val(WS, 1, &st, &v);
    assert_int_equal(last_err(), 141);
    gset_val_mode(WS, 1, (Gop_mode)5, GSWITCH_ECHO);
    assert_int_equal(last_err(), 2000);
    int errors = n_captured;

    /* Valid initialisations, read back. */
    Gint ints[2] = { 4, 5 };
    Gin_data r2 = { 2, ints, 0, NULL, 3, "abc" };
    Glimit ea = { 10, 500, 20, 600 };
    Gloc l2 = { 0, { 0.25, 0.75 } };
    ginit_loc(WS, 2, &l2, 4, &ea, &r2);
    ginit_string(WS, 2, "xy", 1, &ea, 30, 3, NULL);
    ginit_val(WS, 2, 2, 2, &ea, -1, 3, NULL);
    assert_int_equal(n_captured, errors);
    gset_loc_mode(WS, 2, GOP_EVENT, GSWITCH_NO_ECHO);
    Gint err;
    Gloc_st ls;
    ginq_loc_st(WS, 2, GINQ_SET, &err, &ls);
    assert_int_equal(err, 0);
    assert_true(ls.dev.op_mode == GOP_EVENT && ls.dev.echo_switch == GSWITCH_NO_ECHO &&
                ls.dev.pet == 4);
    assert_float_equal(ls.dev.echo_area.y_max, 600, 0);
    assert_int_equal(ls.dev.in_data.num_ints, 2);
    assert_int_equal(ls.dev.in_data.ints[1], 5);
    assert_memory_equal(ls.dev.in_data.str, "abc", 3);
    assert_float_equal(ls.init_loc.position.y, 0.75, 0);
    Gloc_st3 l3;
    ginq_loc_st3(WS, 2, GINQ_REALIZED, &err, &l3);
    assert_int_equal(err, 0);
    assert_float_equal(l3.echo_vol.z_max, 1, 0);
    /* STROKE 3 state: the initial stroke, capped at the caller's capacity */
    Gpoint3 ip[2] = { { 0.1, 0.2, 0.3 }, { 0.4, 0.5, 0.6 } }, op[2];
    Gstroke3 is3 = { 0, 2, ip };
    Glimit3 ev = { 0, 512, 0, 256, 0, 0.5 };
    ginit_stroke3(WS, 2, 0, &is3, 1, &ev, 40, NULL);
    Gstroke_st3 k3 = { .init_stroke = { 0, 1, op } };
    ginq_stroke_st3(WS, 2, GINQ_SET, &err, &k3);
    assert_int_equal(err, 0);
    assert_true(k3.in_buf_size == 40 && k3.init_stroke.num_points == 1 && k3.pet == 1);
    assert_float_equal(op[0].z, 0.3, 1e-12);
    assert_float_equal(k3.echo_vol.y_max, 256, 0);
    k3.init_stroke = (Gstroke3){ 0, 2, op };
    ginq_stroke_st3(WS, 2, GINQ_REALIZED, &err, &k3);
    assert_true(err == 0 && k3.init_stroke.num_points == 2);
    assert_float_equal(op[1].y, 0.5, 1e-12);
    ginq_stroke_st3(WS, 2, (Ginq_type)9, &err, &k3);
    assert_int_equal(err, 2000);
    char buf[8];
    Gstring_st ss = { .init_string = buf, .init_string_size = sizeof buf };
    ginq_string_st(WS, 2, &err, &ss);
    assert_string_equal(buf, "xy");
    assert_true(ss.in_buf_size == 30 && ss.init_cur_pos == 3);
    Gval_st vs;
    ginq_val_st(WS, 2, &err, &vs);
    assert_true(vs.init_value == 2 && vs.low_value == -1 && vs.high_value == 3 &&
                vs.dev.pet == 2);
    ginq_loc_st(WS, 2, (Ginq_type)7, &err, &ls);
    assert_int_equal(err, 2000);

    Gint pets[8];
    Gdef_loc dl = { .dev.pets = { 8, pets } };
    ginq_def_loc_data(GWS_TYPE_PNG, 1, &err, &dl);
    assert_int_equal(err, 0);
    assert_int_equal(dl.dev.pets.num_ints, 6);
    assert_int_equal(pets[5], 6);
    assert_float_equal(dl.dev.echo_area.x_max, 1024, 0);
    Gdef_stroke3 dk = { .pets = { 8, pets } };
    ginq_def_stroke_data3(GWS_TYPE_PNG, 2, &err, &dk);
    assert_int_equal(err, 0);
    assert_true(dk.buf_size == 64 && dk.max_buf_size >= dk.buf_size && dk.pets.num_ints == 4);
    Gdef_loc3 dl3 = { .pets = { 8, pets } };
    ginq_def_loc_data3(GWS_TYPE_PNG, 3, &err, &dl3);
    assert_int_equal(err, 140);
    Gdef_choice dc = { .dev.pets = { 8, pets } };
    ginq_def_choice_data(GWS_TYPE_PNG, 1, &err, &dc);
    assert_int_equal(dc.max_choices, 9);
    /* The 3-D forms of the other classes: echo volumes. */
    Glimit3 vol = { 10, 20, 30, 40, 0.25, 0.75 }, badvol = { 10, 20, 30, 40, 0.5, 2 };
    ginit_val3(WS, 1, 3, 1, &vol, 0, 4, NULL);
    ginit_choice3(WS, 1, GIN_STATUS_OK, 2, 3, &vol, NULL);
    ginit_pick3(WS, 1, GIN_STATUS_NO_IN, NULL, 2, &vol, NULL);
    ginit_string3(WS, 1, "q", 1, &vol, 5, 2, NULL);
    assert_int_equal(n_captured, errors);
    ginit_val3(WS, 1, 3, 1, &badvol, 0, 4, NULL);
    assert_int_equal(last_err(), 145);
    errors = n_captured;
    Gval_st3 v3;
    ginq_val_st3(WS, 1, &err, &v3);
    assert_true(err == 0 && v3.init_value == 3 && v3.echo_vol.z_min == 0.25);
    Gchoice_st3 c3;
    ginq_choice_st3(WS, 1, &err, &c3);
    assert_true(err == 0 && c3.init_choice == 2 && c3.pet == 3);
    Gpick_st3 p3;
    ginq_pick_st3(WS, 1, GINQ_SET, &err, &p3);
    assert_true(err == 0 && p3.init_status == GIN_STATUS_NO_IN && p3.pet == 2);
    char b3[4];
    Gstring_st3 s3 = { .init_string = b3, .init_string_size = sizeof b3 };
    ginq_string_st3(WS, 1, &err, &s3);
    assert_true(err == 0 && s3.in_buf_size == 5 && s3.init_cur_pos == 2);
    assert_string_equal(b3, "q");
    Gdef_val3 dv3 = { .dev.pets = { 8, pets } };
    ginq_def_val_data3(GWS_TYPE_PNG, 1, &err, &dv3);
    assert_true(err == 0 && dv3.dev.pets.num_ints == 3 && dv3.dev.echo_vol.z_max == 1);
    Gdef_choice3 dc3 = { .dev.pets = { 8, pets } };
    ginq_def_choice_data3(GWS_TYPE_PNG, 2, &err, &dc3);
    assert_true(err == 0 && dc3.max_choices == 9);
    Gdef_in3 dp3 = { .pets = { 8, pets } };
    ginq_def_pick_data3(GWS_TYPE_NULL, 1, &err, &dp3);
    assert_int_equal(err, 38);
    Gdef_string3 ds3 = { .dev.pets = { 8, pets } };
    ginq_def_string_data3(GWS_TYPE_PNG, 1, &err, &ds3);
    assert_true(err == 0 && ds3.buf_size == 80);
    Gdef_string ds = { .dev.pets = { 8, pets } };
    ginq_def_string_data(GWS_TYPE_PNG_LARGE, 1, &err, &ds);
    assert_float_equal(ds.dev.echo_area.x_max, 8192, 0);
    assert_int_equal(n_captured, errors);
    reset_gks();
}

/* The 2-D and 3-D forms of every device state and default-data inquiry answer the same:
 * the common part (mode, echo, pet, echo area = the volume's x and y, record) and the
 * class part, for devices initialised away from their defaults. */
static void assert_dev_agrees(const Gin_dev_st *d, Gop_mode m, Gecho_switch e, Gint pet,
                              const Glimit3 *v, const Gin_data *r)
{
    assert_true(d->op_mode == m && d->echo_switch == e && d->pet == pet);
    assert_true(d->echo_area.x_min == v->x_min && d->echo_area.x_max == v->x_max &&
                d->echo_area.y_min == v->y_min && d->echo_area.y_max == v->y_max);
    assert_true(d->in_data.num_ints == r->num_ints && d->in_data.ints == r->ints &&
                d->in_data.str_len == r->str_len);
}

#define AGREE(st2, st3) \
    assert_dev_agrees(&(st2).dev, (st3).op_mode, (st3).echo_switch, (st3).pet, &(st3).echo_vol, &(st3).in_data)
#define AGREE_DEF(d2, d3)                                                                  \
    do {                                                                                   \
        assert_int_equal((d2).pets.num_ints, (d3).pets.num_ints);                         \
        assert_true((d2).echo_area.x_max == (d3).echo_vol.x_max &&                         \
                    (d2).echo_area.y_max == (d3).echo_vol.y_max);                          \
        assert_true((d2).in_data.num_ints == 0 && (d3).in_data.num_ints == 0);            \
    } while (0)

static void test_inquiry_forms_agree(void **u)
{
    (void)u;
    open_with_script("");
    Gint ints[2] = { 4, 5 }, err2 = -1, err3 = -1;
    Gin_data rec = { 2, ints, 0, NULL, 3, "abc" };
    Glimit ea = { 10, 500, 20, 600 };
    Gloc l = { 0, { 0.25, 0.75 } };
    Gpoint sp[2] = { { 0.1, 0.2 }, { 0.3, 0.4 } };
    Gstroke sk = { 0, 2, sp };
    Gpick pk = { 3, 4 };
    ginit_loc(WS, 1, &l, 3, &ea, &rec);
    ginit_stroke(WS, 1, &sk, 2, &ea, 30, &rec);
    ginit_val(WS, 1, 2, 2, &ea, -1, 3, &rec);
    ginit_choice(WS, 1, GIN_STATUS_OK, 4, 2, &ea, &rec);
    ginit_pick(WS, 1, GIN_STATUS_OK, &pk, 2, &ea, &rec);
    ginit_string(WS, 1, "xyz", 1, &ea, 30, 2, &rec);
    gset_loc_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    gset_val_mode(WS, 1, GOP_SAMPLE, GSWITCH_NO_ECHO);
    assert_int_equal(n_captured, 0);

    Gloc_st l2;
    Gloc_st3 l3;
    ginq_loc_st(WS, 1, GINQ_SET, &err2, &l2);
    ginq_loc_st3(WS, 1, GINQ_SET, &err3, &l3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(l2, l3);
    assert_true(l2.dev.op_mode == GOP_EVENT && l2.dev.pet == 3 && l3.init_view_ind == 0);
    assert_true(l2.init_loc.position.x == l3.init_loc.position.x &&
                l2.init_loc.position.y == l3.init_loc.position.y && l3.init_loc.position.y == 0.75);
    Gpoint o2[4];
    Gpoint3 o3[4];
    Gstroke_st k2 = { .init_stroke = { 0, 4, o2 } };
    Gstroke_st3 k3 = { .init_stroke = { 0, 4, o3 } };
    ginq_stroke_st(WS, 1, GINQ_REALIZED, &err2, &k2);
    ginq_stroke_st3(WS, 1, GINQ_REALIZED, &err3, &k3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(k2, k3);
    assert_true(k2.in_buf_size == 30 && k3.in_buf_size == 30);
    assert_true(k2.init_stroke.num_points == 2 && k3.init_stroke.num_points == 2);
    assert_true(o2[1].y == o3[1].y && o3[1].y == (Gfloat)0.4);
    Gval_st v2;
    Gval_st3 v3;
    ginq_val_st(WS, 1, &err2, &v2);
    ginq_val_st3(WS, 1, &err3, &v3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(v2, v3);
    assert_true(v2.init_value == 2 && v3.init_value == 2 && v2.low_value == v3.low_value &&
                v3.low_value == -1 && v2.high_value == v3.high_value && v3.high_value == 3);
    Gchoice_st c2;
    Gchoice_st3 c3;
    ginq_choice_st(WS, 1, &err2, &c2);
    ginq_choice_st3(WS, 1, &err3, &c3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(c2, c3);
    assert_true(c2.init_status == GIN_STATUS_OK && c3.init_status == GIN_STATUS_OK &&
                c2.init_choice == 4 && c3.init_choice == 4);
    Gpick_st p2;
    Gpick_st3 p3;
    ginq_pick_st(WS, 1, GINQ_SET, &err2, &p2);
    ginq_pick_st3(WS, 1, GINQ_SET, &err3, &p3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(p2, p3);
    assert_true(p2.init_pick.seg_name == 3 && p3.init_pick.seg_name == 3 &&
                p2.init_pick.pick_id == 4 && p3.init_pick.pick_id == 4);
    char b2[3], b3[3];
    Gstring_st s2 = { .init_string = b2, .init_string_size = sizeof b2 };
    Gstring_st3 s3 = { .init_string = b3, .init_string_size = sizeof b3 };
    ginq_string_st(WS, 1, &err2, &s2);
    ginq_string_st3(WS, 1, &err3, &s3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE(s2, s3);
    assert_true(s2.in_buf_size == 30 && s3.in_buf_size == 30 && s2.init_cur_pos == 2 &&
                s3.init_cur_pos == 2);
    assert_string_equal(b2, "xy"); /* truncated to the buffer */
    assert_string_equal(b3, "xy");
    /* a type out of range: 2000 in both forms where the function has a type */
    ginq_pick_st(WS, 1, (Ginq_type)5, &err2, &p2);
    ginq_pick_st3(WS, 1, (Ginq_type)5, &err3, &p3);
    assert_true(err2 == 2000 && err3 == 2000);

    Gint pt2[2], pt3[2];
    Gdef_loc dl2 = { .dev.pets = { 2, pt2 } };
    Gdef_loc3 dl3 = { .pets = { 2, pt3 } };
    ginq_def_loc_data(GWS_TYPE_PNG, 1, &err2, &dl2);
    ginq_def_loc_data3(GWS_TYPE_PNG, 1, &err3, &dl3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(dl2.dev, dl3);
    assert_true(pt2[1] == 2 && pt3[1] == 2 && dl2.loc_pos.x == dl3.loc_pos.x);
    Gdef_stroke dk2 = { .dev.pets = { 2, pt2 } };
    Gdef_stroke3 dk3 = { .pets = { 2, pt3 } };
    ginq_def_stroke_data(GWS_TYPE_PNG, 1, &err2, &dk2);
    ginq_def_stroke_data3(GWS_TYPE_PNG, 1, &err3, &dk3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(dk2.dev, dk3);
    assert_true(dk2.buf_size == dk3.buf_size && dk2.max_buf_size == dk3.max_buf_size);
    Gdef_val dv2 = { .dev.pets = { 2, pt2 } };
    Gdef_val3 dv3 = { .dev.pets = { 2, pt3 } };
    ginq_def_val_data(GWS_TYPE_PNG, 1, &err2, &dv2);
    ginq_def_val_data3(GWS_TYPE_PNG, 1, &err3, &dv3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(dv2.dev, dv3.dev);
    assert_true(dv2.value == dv3.value && dv2.low_value == dv3.low_value &&
                dv2.high_value == dv3.high_value && dv3.high_value == 1);
    Gdef_choice dc2 = { .dev.pets = { 2, pt2 } };
    Gdef_choice3 dc3 = { .dev.pets = { 2, pt3 } };
    ginq_def_choice_data(GWS_TYPE_PNG, 1, &err2, &dc2);
    ginq_def_choice_data3(GWS_TYPE_PNG, 1, &err3, &dc3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(dc2.dev, dc3.dev);
    assert_true(dc2.max_choices == 9 && dc3.max_choices == 9);
    Gdef_in dp2 = { .pets = { 0, NULL } };
    Gdef_in3 dp3 = { .pets = { 0, NULL } };
    ginq_def_pick_data(GWS_TYPE_PNG, 1, &err2, &dp2);
    ginq_def_pick_data3(GWS_TYPE_PNG, 1, &err3, &dp3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(dp2, dp3);
    assert_true(dp2.pets.num_ints > 0);
    Gdef_string ds2 = { .dev.pets = { 2, pt2 } };
    Gdef_string3 ds3 = { .dev.pets = { 2, pt3 } };
    ginq_def_string_data(GWS_TYPE_PNG, 1, &err2, &ds2);
    ginq_def_string_data3(GWS_TYPE_PNG, 1, &err3, &ds3);
    assert_true(err2 == 0 && err3 == 0);
    AGREE_DEF(ds2.dev, ds3.dev);
    assert_true(ds2.buf_size == 80 && ds3.buf_size == 80 && ds2.max_buf_size == ds3.max_buf_size);
    assert_int_equal(n_captured, 0);
    reset_gks();
}
#undef AGREE
#undef AGREE_DEF

/* The environment variable attaches a script to the first input workstation; ESCAPE
 * with a file that cannot be read reports 182. */
static void test_env_and_escape(void **u)
{
    (void)u;
    write_script("input_env.txt", "choice 1 5\n");
    setenv("GKS_INPUT_SCRIPT", "input_env.txt", 1);
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(1, "input_env_a", GWS_TYPE_PNG);
    gopen_ws(2, "input_env_b", GWS_TYPE_PNG);
    unsetenv("GKS_INPUT_SCRIPT");
    Gin_status st;
    Gint c;
    greq_choice(2, 1, &st, &c);
    assert_int_equal(st, GIN_STATUS_NONE); /* ws 2 has no script */
    greq_choice(1, 1, &st, &c);
    assert_true(st == GIN_STATUS_OK && c == 5);
    Gint id = 2;
    Gescape_in_data in = { { 1, &id, 0, NULL, 12, "no/such/file" } };
    n_captured = 0;
    gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
    assert_int_equal(last_err(), 182);
    reset_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_class_mode_pet),
        cmocka_unit_test(test_break_and_exhausted),
        cmocka_unit_test(test_viewport_priority),
        cmocka_unit_test(test_view_priority3),
        cmocka_unit_test(test_pick_priority),
        cmocka_unit_test(test_queue_order_flush),
        cmocka_unit_test(test_queue_overflow),
        cmocka_unit_test(test_await_timeout),
        cmocka_unit_test(test_init_checks_and_inquiries),
        cmocka_unit_test(test_inquiry_forms_agree),
        cmocka_unit_test(test_env_and_escape),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
