/* SPDX-License-Identifier: MIT */
/*
 * x11_input.c -- the X11 workstation (GWS_TYPE_X11). "nodisplay": with no display OPEN
 * WORKSTATION reports 26 and the workstation is not open. "interactive" (run by
 * test_x11.sh under Xvfb, driven by xdotool): a detectable square in segment 1 is shown,
 * then REQUEST LOCATOR, PICK, CHOICE and STRING take the mouse clicks and keys the script
 * sends; the values are checked against the positions clicked.
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
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    CHECK(n_err == 0);
    printf(fails ? "X11 INTERACTIVE FAIL\n" : "X11 INTERACTIVE PASS\n");
    return fails != 0;
}
