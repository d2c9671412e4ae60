/* SPDX-License-Identifier: MIT */
/*
 * xgrab.c -- test helper: writes the picture of an X window (X, Y, W, H of it) as an
 * 8-bit RGB PNG, so a test can compare what a window shows with a file
 * (test_render_x11.sh: gks3d-render's window against an offline render).
 * Usage: xgrab WINDOW_ID X Y W H OUT.png   (exit 1 on error)
 */
#include "image_util.h"
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 7)
        return 1;
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy)
        return 1;
    Window win = (Window)strtoul(argv[1], NULL, 0);
    int x = atoi(argv[2]), y = atoi(argv[3]), w = atoi(argv[4]), h = atoi(argv[5]);
    if (w < 1 || h < 1)
        return 1;
    XImage *im = XGetImage(dpy, win, x, y, (unsigned)w, (unsigned)h, AllPlanes, ZPixmap);
    if (!im) {
        fprintf(stderr, "xgrab: no image of window 0x%lx\n", (unsigned long)win);
        return 1;
    }
    img out = { w, h, malloc((size_t)w * (size_t)h * 3) };
    if (!out.rgb)
        return 1;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            unsigned long p = XGetPixel(im, i, j);
            unsigned char *o = out.rgb + 3 * ((size_t)j * (size_t)w + (size_t)i);
            o[0] = (unsigned char)(p >> 16);
            o[1] = (unsigned char)(p >> 8);
            o[2] = (unsigned char)p;
        }
    XDestroyImage(im);
    XCloseDisplay(dpy);
    int rc = img_write(argv[6], &out);
    free(out.rgb);
    return rc ? 1 : 0;
}
