/* SPDX-License-Identifier: MIT */
/*
 * x11_input.c -- the X11 workstation (GWS_TYPE_X11). "nodisplay": with no display OPEN
 * WORKSTATION reports 26 and the workstation is not open. "interactive" (run by
 * test_x11.sh under Xvfb, driven by xdotool): a detectable square in segment 1 is shown,
 * then REQUEST LOCATOR, PICK (its echo highlights the square under the pointer, checked
 * by the script's pixel reads), CHOICE and STRING take the mouse clicks and keys the script
 * sends; the values are checked against the positions clicked. Then the echoes: a CHOICE
 * menu (prompt/echo type 3) clicked, the VALUATOR slider clicked, a STROKE dragged, and a
 * ray-traced picture whose pixels the script reads (xpeek).
 */
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int last_err, n_err;

static void handler(Gint err, Gint fct, const char *file)
{
    (void)fct, (void)file;
    last_err = err;
    n_err++;
}

static int fails;
#define CHECK(c)                                                                         \
    do {                                                                                 \
        if (!(c)) {                                                                      \
            fprintf(stderr, "FAIL %s:%d: %s\n", __FILE__, __LINE__, #c);                 \
            fails++;                                                                     \
        }                                                                                \
    } while (0)

int main(int argc, char **argv)
{
    gset_err_hand(handler, NULL);
    gopen_gks(NULL, 0);
    if (argc > 1 && strcmp(argv[1], "nodisplay") == 0) {
        unsetenv("DISPLAY");
        gopen_ws(1, "", GWS_TYPE_X11);
        CHECK(n_err == 1 && last_err == 26);
        Gint err;
        Gws_st st;
        ginq_ws_st(1, &err, &st);
        CHECK(err == 7); /* still GKOP: no workstation open */
        Gop_st op;
        ginq_op_st(&op);
        CHECK(op == GST_GKOP);
        gclose_gks();
        printf(fails ? "X11 NODISPLAY FAIL\n" : "X11 NODISPLAY PASS\n");
        return fails != 0;
    }
    gopen_ws(1, "", GWS_TYPE_X11);
    CHECK(n_err == 0);
    if (n_err) {
        printf("X11 INTERACTIVE FAIL (open: %d)\n", last_err);
        return 1;
    }
    gactivate_ws(1);
    Gpoint sq[4] = { { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 }, { 0.4, 0.6 } };
    Gpoint_list pl = { 4, sq };
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gcreate_seg(1);
    gset_pick_id(9);
    gfill_area(&pl);
    gclose_seg();
    gset_det(1, GSEG_DET);
    gupd_ws(1, GFLAG_PERFORM);
    printf("READY\n");
    fflush(stdout);
    Gin_status s;
    Gloc l;
    greq_loc(1, 1, &s, &l); /* click at window (200, 600): DC (200.5, 199.5) */
    printf("locator %d %d %.4f %.4f\n", s, l.norm_tran_num, l.position.x, l.position.y);
    CHECK(s == GIN_STATUS_OK && fabs(l.position.x - 200.5 / 800) < 1e-6 &&
          fabs(l.position.y - 199.5 / 800) < 1e-6);
    Gpick p;
    greq_pick(1, 1, &s, &p); /* click at the square's centre */
    printf("pick %d %d %d\n", s, p.seg_name, p.pick_id);
    CHECK(s == GIN_STATUS_OK && p.seg_name == 1 && p.pick_id == 9);
    Gint c;
    greq_choice(1, 1, &s, &c); /* key 3 */
    printf("choice %d %d\n", s, c);
    CHECK(s == GIN_STATUS_OK && c == 3);
    char str[81];
    greq_string(1, 1, &s, str); /* "gks" Return */
    printf("string %d '%s'\n", s, str);
    CHECK(s == GIN_STATUS_OK && strcmp(str, "gks") == 0);
    greq_loc(1, 1, &s, &l); /* Escape: break */
    printf("break %d\n", s);
    CHECK(s == GIN_STATUS_NONE);

    /* CHOICE prompt/echo type 3: a menu of the record's labels at the echo area's top
     * right (window x 716..780, items 20 high from y 99); the script clicks item 2. */
    Gin_data menu = { 0, NULL, 0, NULL, 17, "alpha\0beta\0gamma" };
    Glimit ea = { 400, 780, 100, 700 };
    ginit_choice(1, 1, GIN_STATUS_OK, 1, 3, &ea, &menu);
    printf("MENU\n");
    fflush(stdout);
    greq_choice(1, 1, &s, &c);
    printf("menu %d %d\n", s, c);
    CHECK(s == GIN_STATUS_OK && c == 2);
    /* VALUATOR: the slider (track x 390..690 at y 311); a click at 3/4, then Return. */
    Glimit ev = { 100, 700, 100, 500 };
    ginit_val(1, 1, 0.5, 1, &ev, 0, 10, NULL);
    Gfloat v;
    greq_val(1, 1, &s, &v);
    printf("valuator %d %.3f\n", s, v);
    CHECK(s == GIN_STATUS_OK && fabs(v - 7.5) < 0.05);
    /* STROKE by a drag: press at window (100, 700), move, release at (300, 600). */
    Gpoint pts[64];
    Gstroke sk = { 0, 64, pts };
    greq_stroke(1, 1, &s, &sk);
    printf("stroke %d %d\n", s, sk.num_points);
    CHECK(s == GIN_STATUS_OK && sk.num_points >= 3 &&
          fabs(pts[0].x - 100.5 / 800) < 1e-6 && fabs(pts[0].y - 99.5 / 800) < 1e-6 &&
          fabs(pts[sk.num_points - 1].x - 300.5 / 800) < 1e-6);
    /* Ray tracing in the window: the square again, traced tile by tile; then the script
     * looks at the window's pixels and ends with a key (CHOICE). */
    gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
    gclear_ws(1, GFLAG_ALWAYS);
    gset_fill_colr_ind(3);
    gfill_area(&pl);
    gupd_ws(1, GFLAG_PERFORM);
    printf("TRACED\n");
    fflush(stdout);
    greq_choice(1, 1, &s, &c);
    CHECK(s == GIN_STATUS_OK);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    CHECK(n_err == 0);
    printf(fails ? "X11 INTERACTIVE FAIL\n" : "X11 INTERACTIVE PASS\n");
    return fails != 0;
}
