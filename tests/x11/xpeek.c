/* SPDX-License-Identifier: MIT */
/*
 * xpeek.c -- test helper: prints the colour (rrggbb, hex) of pixel (x, y) of an X window,
 * so that test_x11.sh can check what the X11 workstation drew (prompt line, menu, picture).
 * Usage: xpeek WINDOW_ID X Y ...   (one line per position; exit 1 on error)
 */
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc < 4 || argc % 2)
        return 1;
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy)
        return 1;
    Window w = (Window)strtoul(argv[1], NULL, 0);
    for (int i = 2; i + 1 < argc; i += 2) {
        XImage *im = XGetImage(dpy, w, atoi(argv[i]), atoi(argv[i + 1]), 1, 1, AllPlanes,
                               ZPixmap);
        if (!im)
            return 1;
        printf("%06lx\n", XGetPixel(im, 0, 0) & 0xffffffUL);
        XDestroyImage(im);
    }
    XCloseDisplay(dpy);
    return 0;
}
