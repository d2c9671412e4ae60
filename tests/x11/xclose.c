/* SPDX-License-Identifier: MIT */
/*
 * xclose.c -- test helper: closes an X window as a window manager does (a WM_PROTOCOLS
 * client message with WM_DELETE_WINDOW, "wmdelete") or destroys it from another client
 * ("destroy"), so that test_x11_close.sh can close the X11 workstation's window under Xvfb,
 * which has no window manager. Usage: xclose wmdelete|destroy WINDOW_ID (exit 1 on error)
 */
#include <X11/Xlib.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 3)
        return 1;
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy)
        return 1;
    Window w = (Window)strtoul(argv[2], NULL, 0);
    if (strcmp(argv[1], "destroy") == 0) {
        XDestroyWindow(dpy, w);
    } else {
        XEvent e;
        memset(&e, 0, sizeof e);
        e.xclient.type = ClientMessage;
        e.xclient.window = w;
        e.xclient.message_type = XInternAtom(dpy, "WM_PROTOCOLS", False);
        e.xclient.format = 32;
        e.xclient.data.l[0] = (long)XInternAtom(dpy, "WM_DELETE_WINDOW", False);
        e.xclient.data.l[1] = CurrentTime;
        XSendEvent(dpy, w, False, NoEventMask, &e);
    }
    XCloseDisplay(dpy);
    return 0;
}
