/* SPDX-License-Identifier: MIT */
/*
 * x11_close.c -- a window that closes is an event, not an exit (issue 40 G); run by
 * test_x11_close.sh under Xvfb, which closes the window while REQUEST LOCATOR waits: by
 * WM_DELETE_WINDOW (as a window manager does), by destroying it from another client, or by
 * killing the connection (xkill). A metafile workstation is open and active beside it.
 * Checked: the REQUEST ends with status NONE and no error; a polyline afterwards reports
 * 303 once (UPDATE WORKSTATION then has nothing more to report); a REQUEST again returns
 * NONE at once;
 * CLOSE WORKSTATION of both and CLOSE GKS report nothing; the metafile ends with its END
 * item (read back through an MI workstation). The process ends normally (main 78a5733:
 * Xlib called exit(1), or the REQUEST never ended).
 */
#include <gks.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int n_err, errs[16];

static void handler(Gint err, Gint fct, const char *file)
{
    (void)fct, (void)file;
    if (n_err < 16)
        errs[n_err] = err;
    n_err++;
}

static int fails;
#define CHECK(c)                                                                         \
    do {                                                                                 \
        if (!(c)) {                                                                      \
            printf("FAIL %s:%d: %s (errors %d, first %d)\n", __FILE__, __LINE__, #c,      \
                   n_err, n_err ? errs[0] : 0);                                          \
            fails++;                                                                     \
        }                                                                                \
    } while (0)

static void line(void)
{
    Gpoint p[2] = { { 0.1, 0.1 }, { 0.9, 0.9 } };
    gpolyline(&(Gpoint_list){ 2, p });
}

int main(void)
{
    gset_err_hand(handler, NULL);
    gopen_gks(NULL, 0);
    remove("x11_close.gksm");
    gopen_ws(2, "x11_close.gksm", GWS_TYPE_MO);
    gopen_ws(1, "", GWS_TYPE_X11);
    if (n_err) {
        printf("FAIL: open: error %d\n", errs[0]);
        return 1;
    }
    gactivate_ws(1);
    gactivate_ws(2);
    line();
    gupd_ws(1, GFLAG_PERFORM);
    printf("READY\n");
    fflush(stdout);
    Gin_status st = GIN_STATUS_OK;
    Gloc loc;
    greq_loc(1, 1, &st, &loc); /* the window is closed while it waits */
    printf("REQUEST status %d\n", (int)st);
    CHECK(st == GIN_STATUS_NONE);
    CHECK(n_err == 0);
    n_err = 0;
    line();
    CHECK(n_err == 1 && errs[0] == 303);
    n_err = 0;
    gupd_ws(1, GFLAG_PERFORM); /* nothing new to show: the loss was reported */
    CHECK(n_err == 0);
    n_err = 0;
    st = GIN_STATUS_OK;
    greq_loc(1, 1, &st, &loc);
    CHECK(st == GIN_STATUS_NONE && n_err == 0);
    gdeactivate_ws(1);
    gclose_ws(1);
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_gks();
    CHECK(n_err == 0);
    /* the metafile is whole: its items up to END */
    n_err = 0;
    gopen_gks(NULL, 0);
    gopen_ws(3, "x11_close.gksm", GWS_TYPE_MI);
    int end = 0, items = 0;
    while (n_err == 0 && items < 10000) {
        Gint type = -1, len = 0;
        gget_item_type(3, &type, &len);
        if (n_err || type == 0) {
            end = n_err == 0;
            break;
        }
        char *data = malloc((size_t)len + 1);
        if (!data)
            break;
        gread_item(3, len, &(Gitem_data){ .data.impl_dep = { (size_t)len, data } });
        free(data);
        items++;
    }
    CHECK(end && items > 0);
    gclose_ws(3);
    gclose_gks();
    printf("%s (%d items before END)\n", fails ? "X11 CLOSE FAIL" : "X11 CLOSE PASS", items);
    return fails != 0;
}
