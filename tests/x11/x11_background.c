/* SPDX-License-Identifier: MIT */
/*
 * x11_background.c -- the first frame right on the X11 workstation (issue 37 item 6):
 * colour 0 set after OPEN WORKSTATION and SET WORKSTATION VIEWPORT (which clears the
 * picture) and before the first output is the background of the first frame shown, in
 * every HLHSR mode. The window's pixel (5, 5) is read back with Xlib through a second
 * connection, polled for up to 5 s (the workstation's requests reach the server on its
 * own connection); exact colour: no anti-aliasing at the corner. Run under Xvfb by
 * test_x11_bg.sh. Prints "X11 BACKGROUND PASS" or FAIL lines.
 */
#include <gks.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

/* The top-level window named "gks3d" (one workstation is open at a time), or 0. */
static Window find_window(Display *dpy, Window w)
{
    char *name = NULL;
    if (XFetchName(dpy, w, &name) && name) {
        int hit = strncmp(name, "gks3d", 5) == 0;
        XFree(name);
        if (hit)
            return w;
    }
    Window root, parent, *kids = NULL, found = 0;
    unsigned n = 0;
    if (XQueryTree(dpy, w, &root, &parent, &kids, &n)) {
        for (unsigned i = 0; i < n && !found; i++)
            found = find_window(dpy, kids[i]);
        if (kids)
            XFree(kids);
    }
    return found;
}

static unsigned long corner_pixel(Display *dpy)
{
    Window w = find_window(dpy, DefaultRootWindow(dpy));
    if (!w)
        return 0x1000000UL; /* no window (yet) */
    XImage *im = XGetImage(dpy, w, 5, 5, 1, 1, AllPlanes, ZPixmap);
    if (!im)
        return 0x1000000UL;
    unsigned long p = XGetPixel(im, 0, 0) & 0xffffffUL;
    XDestroyImage(im);
    return p;
}

int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("FAIL: no display for the check\n");
        return 1;
    }
    int fails = 0;
    gopen_gks(NULL, 0);
    for (int mode = 0; mode <= 4; mode++) {
        gopen_ws(1, "", GWS_TYPE_X11);
        gset_ws_vp(1, &(Glimit){ 0, 800, 0, 800 }); /* clears the (empty) picture */
        gset_hlhsr_mode(1, mode);
        Gcolr_rep red = { .rgb = { 1, 0, 0 } };
        gset_colr_rep(1, 0, &red);
        gactivate_ws(1);
        Gpoint p[4] = { { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 }, { 0.4, 0.6 } };
        gset_fill_int_style(GSTYLE_SOLID);
        gset_fill_colr_ind(1);
        gfill_area(&(Gpoint_list){ 4, p });
        gupd_ws(1, GFLAG_PERFORM);
        unsigned long px = 0;
        for (int i = 0; i < 50 && (px = corner_pixel(dpy)) != 0xff0000UL; i++)
            nanosleep(&(struct timespec){ 0, 100000000L }, NULL);
        if (px != 0xff0000UL) {
            printf("FAIL: HLHSR mode %d: window pixel (5,5) is %06lx, want ff0000\n", mode, px);
            fails++;
        }
        gdeactivate_ws(1);
        gclose_ws(1);
    }
    gclose_gks();
    XCloseDisplay(dpy);
    printf(fails ? "X11 BACKGROUND FAIL\n" : "X11 BACKGROUND PASS\n");
    return fails != 0;
}
