/* SPDX-License-Identifier: MIT */
/*
 * ws_x11.c -- the interactive X11 workstation (type GWS_TYPE_X11, category OUTIN, raster,
 * display space 800 x 800 pixels, DC unit = one pixel, y up). Output goes through the
 * render layer (ws_render.h: the classic HLHSR modes and ray tracing, routed there) into a
 * framebuffer that UPDATE WORKSTATION (and every input wait) shows in the window: the
 * window is the render layer's output sink. Ray-traced views appear tile by tile as they
 * are traced; an Expose event redraws from the shown picture.
 *
 * Connection identifier: an X display name ("" or a Fortran unit number: $DISPLAY).
 * No display: OPEN WORKSTATION reports 26 and nothing else happens. The window is opened
 * only by OPEN WORKSTATION of this type.
 *
 * Physical input devices (the core maps them to logical devices; docs/INPUT.md):
 *   mouse button 1 press   LOCATOR and PICK trigger at the pointer position;
 *   button 1 drag          LOCATOR in SAMPLE or EVENT mode: a trigger at every position
 *                          the pointer reaches (how gks3d-render's window turns the view);
 *                          STROKE: a press adds a point, dragging adds points along the
 *                          way and its release ends the stroke; button 3 ends it too
 *   keys 1..9              CHOICE number; 0: no choice; with a menu: a click on an item
 *   keys + / -, slider     VALUATOR up / down a tenth of its range or a click on the
 *                          slider; Return triggers (SAMPLE/EVENT: every change)
 *   typed text + Return    STRING
 *   Escape                 break of the device a REQUEST waits for
 * Which logical device an action goes to: the one a REQUEST waits for, else the first
 * device in SAMPLE or EVENT mode of a class the action serves.
 * Prompt and echo (devices with echo on), drawn over the picture: a prompt line at the top
 * (device, keys, the text typed, the last MESSAGE); CHOICE type 3: a menu of the record's
 * labels (gks_in_menu_labels; numbers when there are none); VALUATOR: a slider; STROKE: the
 * points so far and a rubber band to the pointer; LOCATOR type 4 / 5: a rubber line /
 * rectangle from the initial position; PICK: the aperture square at the pointer and the
 * segment a trigger there would pick, outlined in the highlight colour; the pointer is a
 * crosshair.
 *
 * A window that closes is an event, not an exit (issue 40 G). The window asks the window
 * manager for WM_DELETE_WINDOW, so closing it sends a message instead of killing the
 * connection; Xlib's error handlers are the workstation's, so a protocol error (a window
 * destroyed by another client) or a lost connection (the server gone, xkill) never calls
 * exit inside the library. From then on the window is gone: a pending REQUEST ends with
 * status NONE (the input entry reports no source), and output, UPDATE, CLEAR and MESSAGE
 * report 303; CLOSE WORKSTATION frees what is left without touching a lost connection.
 */
#include "gks_alloc.h"
#include "gks_xform.h"
#include "raster.h"
#include "ws_driver.h"
#include "ws_render.h"
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/cursorfont.h>
#include <X11/keysym.h>
#include <ctype.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define X11_SIZE 800

static const Grgb x11_colours[8] = {
    { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 },
};

/* Geometry of the overlay (window pixels). */
#define BAR_H 18      /* prompt line */
#define ITEM_H 20     /* menu item */
#define SLIDER_W 300
#define MAX_ITEMS 32
#define APERTURE 8    /* half side of the pick aperture square (0.01 NPC of 800) */
#define HIGHLIGHT 0x00c0ff /* pick echo: the segment under the pointer */

typedef struct x11_ws {
    const gks_ws *ws;         /* the workstation (pick echo asks the core about it) */
    struct x11_ws *next;      /* the open X11 workstations (x11_list) */
    Display *dpy;
    Atom wm_delete;           /* WM_DELETE_WINDOW */
    volatile int gone;        /* the window is closed or destroyed: nothing is shown */
    volatile int lost;        /* the connection is lost: no Xlib call on dpy any more */
    Window win;
    GC gc;
    XFontStruct *font;
    gks_in_active act;        /* the devices taking input during the current input call */
    int have_act;
    char msg[128];            /* last MESSAGE */
    int mx, my, in_win;       /* pointer (window pixels) */
    int dragging;             /* stroke: button 1 held since a press */
    int menu_x, menu_y, menu_w, menu_n; /* the menu drawn (items top-down) */
    int slider_x, slider_y;   /* the slider track's left end, middle */
    XImage *img;              /* the picture shown (window size, 32-bit TrueColor) */
    int w, h;
    gks_raster_fb *fb;
    ws_render *r; /* the classic renderer and the tracer's recording */
    int dirty;
    double pts[GKS_IN_STROKE_MAX][3]; /* stroke being entered / the last raw event */
    int npts;
    char text[GKS_IN_STRING_MAX + 1];
    int ntext;
    double val;
    int have_val;
} x11_ws;

/* ---- Xlib's error handlers (process-wide): the open X11 workstations ---- */

static x11_ws *x11_list;             /* open workstations (changed by OPEN/CLOSE only) */
static XErrorHandler prev_error;     /* the handlers before the first X11 workstation */
static XIOErrorHandler prev_io_error;

static x11_ws *x11_of(Display *dpy)
{
    for (x11_ws *x = x11_list; x; x = x->next)
        if (x->dpy == dpy)
            return x;
    return NULL;
}

/* A protocol error (Xlib's default prints it and calls exit): on a workstation's display
 * it is noted, and a window that no longer exists is gone. Other displays: the handler
 * the program had. */
static int x11_error(Display *dpy, XErrorEvent *e)
{
    x11_ws *x = x11_of(dpy);
    if (!x)
        return prev_error ? prev_error(dpy, e) : 0;
    if ((e->error_code == BadWindow || e->error_code == BadDrawable) && e->resourceid == x->win)
        x->gone = 1;
    return 0;
}

/* The connection is lost: Xlib calls this, then the display's exit handler (x11_io_exit),
 * which returns instead of calling exit; Xlib then leaves the display alone. */
static int x11_io_error(Display *dpy)
{
    if (!x11_of(dpy) && prev_io_error)
        return prev_io_error(dpy);
    return 0;
}

static void x11_io_exit(Display *dpy, void *user)
{
    (void)dpy;
    x11_ws *x = user;
    x->lost = 1;
    x->gone = 1;
}

static void x11_register(x11_ws *x)
{
    if (!x11_list) {
        prev_error = XSetErrorHandler(x11_error);
        prev_io_error = XSetIOErrorHandler(x11_io_error);
    }
    x->next = x11_list;
    x11_list = x;
    XSetIOErrorExitHandler(x->dpy, x11_io_exit, x);
}

static void x11_unregister(x11_ws *x)
{
    for (x11_ws **p = &x11_list; *p; p = &(*p)->next)
        if (*p == x) {
            *p = x->next;
            break;
        }
    if (!x11_list) { /* the program's handlers again (Xlib's defaults if it had none) */
        XSetErrorHandler(prev_error);
        XSetIOErrorHandler(prev_io_error);
    }
}

static int x11_ws_matrix(const gks_ws *ws, double m[4][4])
{
    return gks_ws_pixel_matrix(ws, 1.0, m);
}

static gks_raster_fb *x11_fb(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    int w = (int)ceil(ws->cur_vp.x_max - ws->cur_vp.x_min - 1e-9);
    int h = (int)ceil(ws->cur_vp.y_max - ws->cur_vp.y_min - 1e-9);
    w = w < 1 ? 1 : w;
    h = h < 1 ? 1 : h;
    if (x->fb && x->fb->width == w && x->fb->height == h)
        return x->fb;
    gks_raster_fb_free(x->fb);
    if ((x->fb = gks_raster_fb_create(w, h, 1))) {
        float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green,
                        (float)ws->colr[0].blue };
        gks_raster_fb_clear(x->fb, bg);
    }
    return x->fb;
}

static void overlay(x11_ws *x);

static void x11_blit(x11_ws *x)
{
    if (x->gone)
        return;
    if (x->img)
        XPutImage(x->dpy, x->win, x->gc, x->img, 0, 0, 0, 0, (unsigned)x->w, (unsigned)x->h);
    overlay(x);
    XFlush(x->dpy);
}

/* Window pixel of a DC position. */
static int wx_of(double dc_x) { return (int)floor(dc_x); }
static int wy_of(const x11_ws *x, double dc_y) { return x->h - 1 - (int)floor(dc_y); }

static void text_at(x11_ws *x, int px, int py, const char *t, int n)
{
    XDrawString(x->dpy, x->win, x->gc, px, py, t, n);
}

static int text_w(const x11_ws *x, const char *t, int n)
{
    return x->font ? XTextWidth(x->font, t, n) : 6 * n;
}

/* The echo area's top-right corner in window pixels (whole window if it is empty). */
static void echo_corner(const x11_ws *x, const gks_in_active_dev *d, int *rx, int *ty)
{
    int r = wx_of(d->echo_vol.x_max), t = wy_of(x, d->echo_vol.y_max);
    *rx = r > x->w - 4 || r < 40 ? x->w - 4 : r;
    *ty = t < BAR_H + 4 ? BAR_H + 4 : t;
}

/* Pick echo (gks_in_outline_fn): a primitive of the segment under the pointer drawn over
 * the picture in the highlight colour, 3 pixels wide: lines, area loops, a square at each
 * marker or text position. */
/* A window coordinate for Xlib's 16-bit points (far outside the window: clamped). */
static short xcoord(double v)
{
    v = floor(v);
    return (short)(v < -8192 ? -8192 : v > 8192 ? 8192 : isfinite(v) ? v : 0);
}

static void outline_prim(void *user, gks_in_outline_kind kind, int n, const double (*dc)[3])
{
    x11_ws *x = user;
    XPoint *pt = n > 0 ? gks_alloc_array((size_t)n + 1, sizeof *pt) : NULL;
    if (!pt)
        return;
    for (int i = 0; i < n; i++)
        pt[i] = (XPoint){ xcoord(dc[i][0]), xcoord(x->h - 1 - floor(dc[i][1])) };
    if (kind == GKS_IN_OUTLINE_POINTS) {
        for (int i = 0; i < n; i++)
            XDrawRectangle(x->dpy, x->win, x->gc, pt[i].x - 4, pt[i].y - 4, 8, 8);
    } else {
        int k = n;
        if (kind == GKS_IN_OUTLINE_AREA && n > 2)
            pt[k++] = pt[0]; /* close the loop */
        if (k > 1)
            XDrawLines(x->dpy, x->win, x->gc, pt, k, CoordModeOrigin);
    }
    gks_free(pt);
}

/* PICK prompt/echo: the segment a trigger at the pointer would pick, highlighted (types 1
 * and 3: the whole segment; type 2: its primitives with the picked pick identifier). */
static void pick_echo(x11_ws *x, const gks_in_active_dev *d)
{
    double dc[3] = { x->mx + 0.5, x->h - x->my - 0.5, 0 };
    Gpick p;
    if (!x->act.pick_at || !x->act.pick_at(x->ws, dc, &p))
        return;
    XSetForeground(x->dpy, x->gc, HIGHLIGHT);
    XSetLineAttributes(x->dpy, x->gc, 3, LineSolid, CapRound, JoinRound);
    x->act.seg_outline(x->ws, p.seg_name, d->pet == 2 ? p.pick_id : -1, outline_prim, x);
    XSetLineAttributes(x->dpy, x->gc, 0, LineSolid, CapButt, JoinMiter);
}

static const char *const class_names[] = { "", "LOCATOR", "STROKE", "VALUATOR", "CHOICE",
                                           "PICK", "STRING" };

/* The prompt line: the device a REQUEST waits for and how to answer it, or the device
 * taking input, and the last MESSAGE. */
static void prompt_line(x11_ws *x)
{
    const gks_in_active *a = &x->act;
    char t[256];
    int n = 0;
    if (x->have_act && a->request >= 0) {
        const gks_in_active_dev *d = &a->dev[a->request];
        static const char *const how[] = { "", "click", "click points, drag; button 3 ends",
                                           "+/- or slider, Return", "keys 1-9 or menu",
                                           "click a segment", "type, Return" };
        n = snprintf(t, sizeof t, "REQUEST %s %d: %s; Esc breaks", class_names[d->cls],
                     d->num, how[d->cls]);
        if (d->cls == GIN_STRING && n < (int)sizeof t)
            n += snprintf(t + n, sizeof t - (size_t)n, "  > %.*s_", x->ntext, x->text);
        if (d->cls == GIN_VAL && n < (int)sizeof t)
            n += snprintf(t + n, sizeof t - (size_t)n, "  = %g", x->have_val ? x->val : d->val);
    } else if (x->have_act && a->n > 0) {
        n = snprintf(t, sizeof t, "%s %d taking input", class_names[a->dev[0].cls],
                     a->dev[0].num);
    }
    if (x->msg[0] && n < (int)sizeof t)
        n += snprintf(t + n, sizeof t - (size_t)n, "%s%s", n ? "   | " : "", x->msg);
    if (n > (int)sizeof t - 1)
        n = (int)sizeof t - 1;
    XSetForeground(x->dpy, x->gc, 0xffffcc);
    XFillRectangle(x->dpy, x->win, x->gc, 0, 0, (unsigned)x->w, BAR_H);
    XSetForeground(x->dpy, x->gc, 0x000000);
    text_at(x, 4, BAR_H - 5, t, n);
}

/* The CHOICE menu (echo type 3): its items (the data record's labels, else numbers) at the
 * echo area's top right, the one under the pointer highlighted; where presses land. */
static void choice_menu(x11_ws *x, const gks_in_active_dev *d)
{
    const char *lab[MAX_ITEMS];
    int len[MAX_ITEMS];
    int k = gks_in_menu_labels(&d->rec, lab, len, MAX_ITEMS);
    char num[MAX_ITEMS][4];
    if (k == 0)
        for (; k < d->max_choice && k < MAX_ITEMS; k++) {
            len[k] = snprintf(num[k], sizeof num[k], "%d", k + 1);
            lab[k] = num[k];
        }
    int wmax = 0;
    for (int j = 0; j < k; j++)
        if (text_w(x, lab[j], len[j]) > wmax)
            wmax = text_w(x, lab[j], len[j]);
    int rx, ty;
    echo_corner(x, d, &rx, &ty);
    x->menu_w = wmax + 34;
    x->menu_x = rx - x->menu_w;
    x->menu_y = ty;
    x->menu_n = k;
    XSetForeground(x->dpy, x->gc, 0xf0f0f0);
    XFillRectangle(x->dpy, x->win, x->gc, x->menu_x, ty, (unsigned)x->menu_w,
                   (unsigned)(k * ITEM_H));
    for (int j = 0; j < k; j++) {
        int iy = ty + j * ITEM_H;
        int hot = x->in_win && x->mx >= x->menu_x && x->mx < rx && x->my >= iy &&
                  x->my < iy + ITEM_H;
        XSetForeground(x->dpy, x->gc, hot ? 0x3060c0 : 0xf0f0f0);
        XFillRectangle(x->dpy, x->win, x->gc, x->menu_x + 1, iy + 1, (unsigned)x->menu_w - 2,
                       ITEM_H - 2);
        XSetForeground(x->dpy, x->gc, hot ? 0xffffff : 0x000000);
        char nb[8];
        int nn = snprintf(nb, sizeof nb, "%d", j + 1);
        text_at(x, x->menu_x + 6, iy + ITEM_H - 6, nb, nn);
        text_at(x, x->menu_x + 28, iy + ITEM_H - 6, lab[j], len[j]);
    }
    XSetForeground(x->dpy, x->gc, 0x000000);
    XDrawRectangle(x->dpy, x->win, x->gc, x->menu_x, ty, (unsigned)x->menu_w,
                   (unsigned)(k * ITEM_H));
}

/* The VALUATOR slider at the echo area's top right: the value's knob, value and range. */
static void valuator_slider(x11_ws *x, const gks_in_active_dev *d)
{
    int rx, ty;
    echo_corner(x, d, &rx, &ty);
    x->slider_x = rx - SLIDER_W - 10;
    x->slider_y = ty + 12;
    double v = x->have_val ? x->val : d->val;
    double f = d->high > d->low ? (v - d->low) / (d->high - d->low) : 0;
    int kx = x->slider_x + (int)lround(f * SLIDER_W);
    XSetForeground(x->dpy, x->gc, 0xf0f0f0);
    XFillRectangle(x->dpy, x->win, x->gc, x->slider_x - 8, ty, SLIDER_W + 16, 40);
    XSetForeground(x->dpy, x->gc, 0x000000);
    XDrawRectangle(x->dpy, x->win, x->gc, x->slider_x - 8, ty, SLIDER_W + 16, 40);
    XDrawLine(x->dpy, x->win, x->gc, x->slider_x, x->slider_y, x->slider_x + SLIDER_W,
              x->slider_y);
    XSetForeground(x->dpy, x->gc, 0x3060c0);
    XFillRectangle(x->dpy, x->win, x->gc, kx - 4, x->slider_y - 8, 9, 17);
    XSetForeground(x->dpy, x->gc, 0x000000);
    char vt[64];
    int vn = snprintf(vt, sizeof vt, "%g  [%g, %g]", v, d->low, d->high);
    text_at(x, x->slider_x, ty + 36, vt, vn);
}

/* The STROKE's points so far, joined, and a rubber band from the last to the pointer. */
static void stroke_echo(x11_ws *x)
{
    XSetForeground(x->dpy, x->gc, 0xd00000);
    for (int j = 0; j < x->npts; j++) {
        int px = wx_of(x->pts[j][0]), py = wy_of(x, x->pts[j][1]);
        XDrawRectangle(x->dpy, x->win, x->gc, px - 2, py - 2, 4, 4);
        if (j > 0)
            XDrawLine(x->dpy, x->win, x->gc, wx_of(x->pts[j - 1][0]),
                      wy_of(x, x->pts[j - 1][1]), px, py);
    }
    if (x->in_win)
        XDrawLine(x->dpy, x->win, x->gc, wx_of(x->pts[x->npts - 1][0]),
                  wy_of(x, x->pts[x->npts - 1][1]), x->mx, x->my);
}

/* The LOCATOR's rubber line (echo type 4) or rectangle (5) from its initial position. */
static void locator_band(x11_ws *x, const gks_in_active_dev *d)
{
    int ix = wx_of(d->init_dc[0]), iy = wy_of(x, d->init_dc[1]);
    XSetForeground(x->dpy, x->gc, 0xd00000);
    if (d->pet == 4)
        XDrawLine(x->dpy, x->win, x->gc, ix, iy, x->mx, x->my);
    else
        XDrawRectangle(x->dpy, x->win, x->gc, ix < x->mx ? ix : x->mx, iy < x->my ? iy : x->my,
                       (unsigned)abs(x->mx - ix), (unsigned)abs(x->my - iy));
}

/* Prompt line, menu, slider, rubber bands and aperture of the devices taking input. */
static void overlay(x11_ws *x)
{
    x->menu_n = 0;
    x->slider_x = -1;
    if (!x->have_act && !x->msg[0])
        return;
    prompt_line(x);
    const gks_in_active *a = &x->act;
    for (int i = 0; x->have_act && i < a->n; i++) {
        const gks_in_active_dev *d = &a->dev[i];
        if (!d->echo)
            continue;
        if (d->cls == GIN_CHOICE && d->pet == 3 && !x->menu_n) {
            choice_menu(x, d);
        } else if (d->cls == GIN_VAL && x->slider_x < 0) {
            valuator_slider(x, d);
        } else if (d->cls == GIN_STROKE && (x->npts > 0)) {
            stroke_echo(x);
        } else if (d->cls == GIN_LOC && (d->pet == 4 || d->pet == 5) && x->in_win) {
            locator_band(x, d);
        } else if (d->cls == GIN_PICK && x->in_win) {
            pick_echo(x, d);
            XSetForeground(x->dpy, x->gc, 0xd00000);
            XDrawRectangle(x->dpy, x->win, x->gc, x->mx - APERTURE, x->my - APERTURE,
                           2 * APERTURE, 2 * APERTURE);
        }
    }
}

/* Copies picture pic into the window image (viewport origin at the window's lower left)
 * and shows it. Rows of pic are top-down. Returns 0 or 300. */
static int x11_show(gks_ws *ws, const gks_raster_fb *pic)
{
    x11_ws *x = ws->priv;
    unsigned char *row = gks_alloc_array((size_t)pic->width, 3);
    if (!row)
        return 300;
    int ox = (int)ws->cur_vp.x_min, oy = (int)ws->cur_vp.y_min;
    for (int j = 0; j < pic->height; j++) {
        gks_raster_fb_resolve_row(pic, j, row);
        int wy = x->h - 1 - (oy + pic->height - 1 - j);
        if (wy < 0 || wy >= x->h)
            continue;
        for (int i = 0; i < pic->width; i++) {
            int wx = ox + i;
            if (wx < 0 || wx >= x->w)
                continue;
            const unsigned char *c = row + 3 * (size_t)i;
            XPutPixel(x->img, wx, wy, ((unsigned long)c[0] << 16) | ((unsigned long)c[1] << 8) | c[2]);
        }
    }
    gks_free(row);
    x11_blit(x);
    return x->gone ? 303 : 0; /* closed or lost while it was shown */
}

static int x11_open(gks_ws *ws)
{
    const char *name = ws->conn_id;
    int digits = 1;
    for (const char *c = name; *c; c++)
        digits &= isdigit((unsigned char)*c) != 0;
    XInitThreads(); /* the tracer's threads show tiles (one at a time, under its lock) */
    Display *dpy = XOpenDisplay(digits ? NULL : name);
    if (!dpy) {
        const char *env = getenv("DISPLAY");
        if (!digits)
            gks_ws_note(ws, "cannot open X display \"%s\"", name);
        else if (!env || !*env)
            gks_ws_note(ws, "no X display: DISPLAY is not set (give a display name as the "
                            "connection identifier, or run under an X server)");
        else
            gks_ws_note(ws, "cannot open X display \"%s\" (DISPLAY)", env);
        return 26;
    }
    int scr = DefaultScreen(dpy);
    Visual *vis = DefaultVisual(dpy, scr);
    if (DefaultDepth(dpy, scr) < 24 || vis->class != TrueColor) {
        gks_ws_note(ws, "X display \"%s\" has no 24-bit TrueColor visual", DisplayString(dpy));
        XCloseDisplay(dpy);
        return 26;
    }
    x11_ws *x = gks_calloc_array(1, sizeof *x);
    if (!x) {
        XCloseDisplay(dpy);
        return 300;
    }
    x->ws = ws;
    x->dpy = dpy;
    x->w = x->h = X11_SIZE;
    x->r = ws_render_new();
    char *data = gks_calloc_array((size_t)x->w * (size_t)x->h, 4);
    if (!x->r || !data) {
        ws_render_free(x->r);
        gks_free(data);
        gks_free(x);
        XCloseDisplay(dpy);
        return 300;
    }
    x->win = XCreateSimpleWindow(dpy, RootWindow(dpy, scr), 0, 0, (unsigned)x->w,
                                 (unsigned)x->h, 0, BlackPixel(dpy, scr), WhitePixel(dpy, scr));
    XStoreName(dpy, x->win, "gks3d");
    x->wm_delete = XInternAtom(dpy, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(dpy, x->win, &x->wm_delete, 1);
    x11_register(x);
    XSelectInput(dpy, x->win, ExposureMask | ButtonPressMask | ButtonReleaseMask |
                                  PointerMotionMask | EnterWindowMask | LeaveWindowMask |
                                  KeyPressMask | StructureNotifyMask);
    XDefineCursor(dpy, x->win, XCreateFontCursor(dpy, XC_crosshair));
    x->gc = XCreateGC(dpy, x->win, 0, NULL);
    if ((x->font = XLoadQueryFont(dpy, "fixed")))
        XSetFont(dpy, x->gc, x->font->fid);
    x->img = XCreateImage(dpy, vis, (unsigned)DefaultDepth(dpy, scr), ZPixmap, 0, data,
                          (unsigned)x->w, (unsigned)x->h, 32, 0);
    for (int j = 0; j < x->h; j++)
        for (int i = 0; i < x->w; i++)
            XPutPixel(x->img, i, j, 0xffffff);
    XMapWindow(dpy, x->win);
    XEvent e;
    do /* wait until mapped, so the first picture shows */
        XNextEvent(dpy, &e);
    while (e.type != MapNotify && !x->gone);
    ws->priv = x;
    return 0;
}

static void x11_close(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    if (!x)
        return;
    XDestroyImage(x->img); /* frees its data (no request to the server) */
    /* The font and GC structures are the client's: freed in every case (on a lost
     * connection Xlib marked the display broken and only buffers the requests). */
    if (x->font)
        XFreeFont(x->dpy, x->font);
    XFreeGC(x->dpy, x->gc);
    if (!x->gone)
        XDestroyWindow(x->dpy, x->win);
    if (!x->lost)
        XSync(x->dpy, False); /* errors of the requests above while the handlers are ours */
    /* A lost connection: Xlib marked the display broken, so XCloseDisplay only frees it
     * and closes the socket. Any error on the way still reaches this workstation's
     * handlers (unregistered after). */
    XCloseDisplay(x->dpy);
    x11_unregister(x);
    gks_raster_fb_free(x->fb);
    ws_render_free(x->r);
    gks_free(x);
    ws->priv = NULL;
}

static int x11_clear(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    if (x->gone)
        return 303;
    ws_render_reset(x->r);
    gks_raster_fb_free(x->fb);
    x->fb = NULL;
    x->dirty = 1;
    return x11_fb(ws) ? 0 : 300;
}

/* gks_ws_driver.background: the empty frame's picture cleared to the new colour 0, shown
 * at the next update. */
static int x11_background(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    if (x->fb) {
        float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green,
                        (float)ws->colr[0].blue };
        gks_raster_fb_clear(x->fb, bg);
    }
    x->dirty = 1;
    return 0;
}

/* A traced tile shown at once (ws_rt_tile_fn): the window shows the picture forming. */
static void x11_tile(void *user, int i0, int j0, int w, int h, const float *rgb)
{
    gks_ws *ws = user;
    x11_ws *x = ws->priv;
    int ox = (int)ws->cur_vp.x_min, oy = (int)ws->cur_vp.y_min;
    int wx0 = ox + i0, wy0 = x->h - (oy + j0 + h);
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            int wx = wx0 + i, wy = x->h - 1 - (oy + j0 + j);
            if (wx < 0 || wx >= x->w || wy < 0 || wy >= x->h)
                continue;
            const float *c = rgb + 3 * ((size_t)j * w + i);
            XPutPixel(x->img, wx, wy,
                      ((unsigned long)lround(c[0] * 255) << 16) |
                          ((unsigned long)lround(c[1] * 255) << 8) |
                          (unsigned long)lround(c[2] * 255));
        }
    if (wx0 < x->w && wy0 < x->h && wx0 + w > 0 && wy0 + h > 0) {
        XPutImage(x->dpy, x->win, x->gc, x->img, wx0 < 0 ? 0 : wx0, wy0 < 0 ? 0 : wy0,
                  wx0 < 0 ? 0 : wx0, wy0 < 0 ? 0 : wy0, (unsigned)w, (unsigned)h);
        XFlush(x->dpy);
    }
}

/* Shows the frame: ray-traced areas traced first, retained primitives composed. */
static int x11_update(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    if (x->gone) /* the window is closed: what was drawn since it was shown is lost */
        return x->dirty ? (x->dirty = 0, 303) : 0;
    gks_raster_fb *fb = x11_fb(ws), *pic;
    if (!fb)
        return 300;
    double m[4][4];
    if (ws_rt_count(x->r->rt) > 0 && x11_ws_matrix(ws, m) == 0) {
        ws_rt_set_tile_fn(x->r->rt, x11_tile, ws);
        int e = ws_rt_render(x->r->rt, ws, (const double (*)[4])m, fb);
        if (e)
            return e;
        ws_rt_reset(x->r->rt); /* traced into fb: not again at the next update */
    }
    if (ws_classic_compose(x->r->classic, ws, fb, &pic))
        return 300;
    x->dirty = 0;
    return x11_show(ws, pic);
}

static int x11_primitive(gks_ws *ws, const gks_prim *prim)
{
    x11_ws *x = ws->priv;
    if (x->gone)
        return 303;
    gks_raster_fb *fb = x11_fb(ws);
    if (!fb)
        return 300;
    x->dirty = 1;
    return ws_render_prim(x->r, ws, fb, prim);
}

/* A mesh the render layer traces, recorded whole (ws_render_mesh); else its facets. */
static int x11_mesh(gks_ws *ws, const gks_mesh *m)
{
    x11_ws *x = ws->priv;
    if (x->gone)
        return 303;
    if (ws_render_route(ws, &m->prim) != WS_ROUTE_TRACE)
        return GKS_WS_MESH_FACETS;
    if (!x11_fb(ws))
        return 300;
    int e = ws_render_mesh(x->r, ws, m);
    if (!e)
        x->dirty = 1;
    return e;
}

static int x11_message(gks_ws *ws, const char *msg)
{
    x11_ws *x = ws->priv;
    if (x->gone)
        return 303;
    snprintf(x->msg, sizeof x->msg, "%s", msg);
    XStoreName(x->dpy, x->win, msg);
    x11_blit(x);
    return 0;
}

static int x11_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    x11_ws *x = ws->priv;
    if (func_id <= GESC_RT_CLIP_SECONDARY && func_id >= GESC_RT_SPD)
        return ws_rt_escape(x->r->rt, func_id, in, out);
    return 180;
}

/* The device a physical action of kind cls goes to (-1 none): the REQUEST's if it is of
 * an accepted class, else the first SAMPLE/EVENT device of one. */
static int target(const gks_in_active *a, unsigned classes)
{
    if (a->request >= 0 && (classes & (1u << a->dev[a->request].cls)))
        return a->request;
    for (int i = 0; i < a->n; i++)
        if (a->dev[i].mode != GOP_REQ && (classes & (1u << a->dev[i].cls)))
            return i;
    return -1;
}

static void prompt(x11_ws *x, const gks_in_active *a)
{
    char t[96];
    if (x->gone)
        return;
    if (a->request >= 0)
        snprintf(t, sizeof t, "gks3d: REQUEST %s %d", class_names[a->dev[a->request].cls],
                 a->dev[a->request].num);
    else
        snprintf(t, sizeof t, "gks3d");
    XStoreName(x->dpy, x->win, t);
}

/* The stroke being entered as a raw event of device k; 1. */
static int stroke_event(x11_ws *x, const gks_in_active *a, int k, gks_in_raw *ev)
{
    *ev = (gks_in_raw){ .cls = GIN_STROKE, .num = a->dev[k].num, .n = x->npts,
                        .pts = (const double (*)[3])x->pts };
    x->npts = 0;
    x->dragging = 0;
    return 1;
}

/* The valuator value at window x position px on the slider of device d. */
static double slider_value(const x11_ws *x, const gks_in_active_dev *d, int px)
{
    double f = (double)(px - x->slider_x) / SLIDER_W;
    f = f < 0 ? 0 : f > 1 ? 1 : f;
    return d->low + f * (d->high - d->low);
}

static int on_slider(const x11_ws *x, int px, int py)
{
    return x->slider_x >= 0 && px >= x->slider_x - 8 && px <= x->slider_x + SLIDER_W + 8 &&
           py >= x->slider_y - 12 && py <= x->slider_y + 28;
}

/* A window event (closed, destroyed, exposed, entered, left); 1 if e was one. */
static int window_event(x11_ws *x, const XEvent *e)
{
    if (e->type == ClientMessage && e->xclient.window == x->win &&
        (Atom)e->xclient.data.l[0] == x->wm_delete) { /* closed by the window manager */
        XDestroyWindow(x->dpy, x->win);
        XFlush(x->dpy);
        x->gone = 1;
        return 1;
    }
    if (e->type == DestroyNotify && e->xdestroywindow.window == x->win) {
        x->gone = 1; /* destroyed by another client */
        return 1;
    }
    if (e->type == Expose) {
        if (e->xexpose.count == 0)
            x11_blit(x);
        return 1;
    }
    if (e->type == EnterNotify || e->type == LeaveNotify) {
        x->in_win = e->type == EnterNotify;
        x11_blit(x);
        return 1;
    }
    return 0;
}

/* A LOCATOR raw event of device k at window pixel (px, py); 1. */
static int locator_event(x11_ws *x, const gks_in_active *a, int k, int px, int py,
                         gks_in_raw *ev)
{
    double dc[3] = { px + 0.5, x->h - py - 0.5, 0 };
    *ev = (gks_in_raw){ .cls = a->dev[k].cls, .num = a->dev[k].num, .n = 1 };
    memcpy(x->pts[0], dc, sizeof dc);
    ev->pts = (const double (*)[3])x->pts;
    return 1;
}

/* The pointer moved: stroke points and the slider follow a drag; a drag with button 1
 * triggers a LOCATOR in SAMPLE or EVENT mode at every position (a program turning a view
 * follows the pointer: gks3d-render's window); else the echo follows the pointer. */
static int motion(x11_ws *x, const gks_in_active *a, XEvent *e, gks_in_raw *ev)
{
    /* the latest of the motions queued right behind this one, not past a press or release:
     * a drag queued whole (a loaded machine, xdotool) would else report its end before its
     * press, and a program turning a view would turn it backwards */
    while (XEventsQueued(x->dpy, QueuedAlready) > 0) {
        XEvent nx;
        XPeekEvent(x->dpy, &nx);
        if (nx.type != MotionNotify || nx.xmotion.window != x->win)
            break;
        XNextEvent(x->dpy, e);
    }
    x->mx = e->xmotion.x;
    x->my = e->xmotion.y;
    x->in_win = 1;
    int ks = target(a, 1u << GIN_STROKE), kv = target(a, 1u << GIN_VAL);
    int kl = target(a, 1u << GIN_LOC);
    if (x->dragging && ks >= 0 && x->npts > 0 && x->npts < GKS_IN_STROKE_MAX) {
        double dc[3] = { x->mx + 0.5, x->h - x->my - 0.5, 0 };
        double dx = dc[0] - x->pts[x->npts - 1][0], dy = dc[1] - x->pts[x->npts - 1][1];
        if (dx * dx + dy * dy >= 36) /* a point every 6 pixels of the drag */
            memcpy(x->pts[x->npts++], dc, sizeof dc);
    }
    if (kv >= 0 && (e->xmotion.state & Button1Mask) && on_slider(x, x->mx, x->my)) {
        x->val = slider_value(x, &a->dev[kv], x->mx);
        x->have_val = 1;
    }
    if (kl >= 0 && a->dev[kl].mode != GOP_REQ && (e->xmotion.state & Button1Mask))
        return locator_event(x, a, kl, x->mx, x->my, ev);
    x11_blit(x); /* rubber bands, aperture, menu highlight follow the pointer */
    return 0;
}

/* A button press: a menu item, the slider, a stroke point or its end, a LOCATOR or PICK
 * trigger. */
static int press(x11_ws *x, const gks_in_active *a, const XEvent *e, gks_in_raw *ev)
{
    int px = e->xbutton.x, py = e->xbutton.y;
    int kc = target(a, 1u << GIN_CHOICE), kv = target(a, 1u << GIN_VAL);
    if (e->xbutton.button == Button1 && kc >= 0 && x->menu_n > 0 && px >= x->menu_x &&
        px < x->menu_x + x->menu_w && py >= x->menu_y && py < x->menu_y + x->menu_n * ITEM_H) {
        *ev = (gks_in_raw){ .cls = GIN_CHOICE, .num = a->dev[kc].num,
                            .choice = (py - x->menu_y) / ITEM_H + 1 };
        return 1;
    }
    if (e->xbutton.button == Button1 && kv >= 0 && on_slider(x, px, py)) {
        x->val = slider_value(x, &a->dev[kv], px);
        x->have_val = 1;
        x11_blit(x);
        if (a->dev[kv].mode == GOP_REQ)
            return 0; /* Return triggers */
        *ev = (gks_in_raw){ .cls = GIN_VAL, .num = a->dev[kv].num, .val = x->val };
        x->have_val = 0; /* the next input starts from the device's value */
        return 1;
    }
    int k = target(a, (1u << GIN_LOC) | (1u << GIN_PICK) | (1u << GIN_STROKE));
    if (k < 0)
        return 0;
    if (a->dev[k].cls == GIN_STROKE) {
        if (e->xbutton.button == Button1 && x->npts < GKS_IN_STROKE_MAX) {
            double dc[3] = { px + 0.5, x->h - py - 0.5, 0 };
            memcpy(x->pts[x->npts++], dc, sizeof dc);
            x->dragging = 1;
            x11_blit(x);
            return 0;
        }
        if (x->npts == 0)
            return 0;
        return stroke_event(x, a, k, ev);
    }
    return locator_event(x, a, k, px, py, ev);
}

/* A key typed for a STRING device (the REQUEST's or the first in SAMPLE/EVENT): the text
 * grows, or Return ends it (1). */
static int string_key(x11_ws *x, const gks_in_active *a, int ks, KeySym sym,
                      const char *buf, int n, gks_in_raw *ev)
{
    if (sym == XK_Return || sym == XK_KP_Enter) {
        x->text[x->ntext] = '\0';
        x->ntext = 0;
        *ev = (gks_in_raw){ .cls = GIN_STRING, .num = a->dev[ks].num, .str = x->text };
        return 1;
    }
    if (sym == XK_BackSpace && x->ntext > 0)
        x->ntext--;
    else if (n == 1 && isprint((unsigned char)buf[0]) && x->ntext < a->dev[ks].str_buf)
        x->text[x->ntext++] = buf[0];
    x11_blit(x); /* the prompt line shows the text typed */
    return 0;
}

/* A key for a VALUATOR: + / - step a tenth of the range, Return triggers (1). */
static int valuator_key(x11_ws *x, const gks_in_active_dev *d, KeySym sym, const char *buf,
                        int n, gks_in_raw *ev)
{
    if (!x->have_val) {
        x->val = d->val;
        x->have_val = 1;
    }
    double step = (d->high - d->low) / 10;
    if (n == 1 && (buf[0] == '+' || buf[0] == '-')) {
        x->val += buf[0] == '+' ? step : -step;
        x->val = x->val < d->low ? d->low : x->val > d->high ? d->high : x->val;
        x11_blit(x);
        if (d->mode == GOP_REQ)
            return 0;
    } else if (sym != XK_Return) {
        return 0;
    }
    *ev = (gks_in_raw){ .cls = GIN_VAL, .num = d->num, .val = x->val };
    x->have_val = 0;
    return 1;
}

/* A key press: break (Escape), STRING text, a CHOICE digit, VALUATOR steps. */
static int key(x11_ws *x, const gks_in_active *a, XEvent *e, gks_in_raw *ev)
{
    char buf[8];
    KeySym sym;
    int n = XLookupString(&e->xkey, buf, sizeof buf, &sym, NULL);
    if (sym == XK_Escape && a->request >= 0) {
        *ev = (gks_in_raw){ .cls = a->dev[a->request].cls, .num = a->dev[a->request].num,
                            .brk = 1 };
        x->npts = 0;
        x->dragging = 0;
        return 1;
    }
    int ks = target(a, 1u << GIN_STRING), kc = target(a, 1u << GIN_CHOICE),
        kv = target(a, 1u << GIN_VAL);
    if (ks >= 0 && (a->request < 0 || a->request == ks))
        return string_key(x, a, ks, sym, buf, n, ev);
    if (kc >= 0 && n == 1 && buf[0] >= '0' && buf[0] <= '9') {
        *ev = (gks_in_raw){ .cls = GIN_CHOICE, .num = a->dev[kc].num, .choice = buf[0] - '0' };
        return 1;
    }
    if (kv >= 0)
        return valuator_key(x, &a->dev[kv], sym, buf, n, ev);
    return 0;
}

/* One X event -> a raw event (1), or nothing (0). */
static int translate(gks_ws *ws, const gks_in_active *a, XEvent *e, gks_in_raw *ev)
{
    x11_ws *x = ws->priv;
    if (window_event(x, e))
        return 0;
    if (e->type == MotionNotify)
        return motion(x, a, e, ev);
    if (e->type == ButtonRelease) {
        int ks = target(a, 1u << GIN_STROKE);
        if (e->xbutton.button == Button1 && x->dragging && ks >= 0 && x->npts > 1)
            return stroke_event(x, a, ks, ev); /* the end of a drag */
        x->dragging = 0;
        return 0;
    }
    if (e->type == ButtonPress)
        return press(x, a, e, ev);
    if (e->type == KeyPress)
        return key(x, a, e, ev);
    return 0;
}


static int x11_input(gks_ws *ws, const gks_in_active *act, double timeout, gks_in_raw *ev)
{
    x11_ws *x = ws->priv;
    if (x->gone)
        return -1; /* no device left: a REQUEST ends with status NONE */
    x->act = *act;
    x->have_act = 1;
    if (x->dirty) {
        if (x11_update(ws))
            return -1;
    } else {
        x11_blit(x);
    }
    prompt(x, act);
    int ms = timeout > 0 ? (int)ceil(timeout * 1000) : 0;
    for (;;) {
        while (XPending(x->dpy)) {
            XEvent e;
            XNextEvent(x->dpy, &e);
            if (translate(ws, act, &e, ev)) {
                x->have_act = 0;
                if (act->request >= 0)
                    x11_blit(x); /* the REQUEST's prompt and echo go */
                return 1;
            }
            if (x->gone)
                return -1;
        }
        if (x->gone)
            return -1;
        struct pollfd p = { ConnectionNumber(x->dpy), POLLIN, 0 };
        if (ms <= 0 || poll(&p, 1, ms) <= 0)
            return 0;
        if (p.revents & (POLLERR | POLLHUP)) {
            XPending(x->dpy); /* Xlib reads the end: the lost connection (x11_io_exit) */
            x->gone = 1;
            return -1;
        }
        ms = 0; /* one wait per call: the core loops */
        if (!XPending(x->dpy))
            return 0;
    }
}

static const gks_ws_desc x11_desc = {
    .type = GWS_TYPE_X11, .name = "x11", .cat = GCAT_OUTIN, .cls = GCLASS_RASTER,
    .dc_units = GDC_OTHER, .dc_x = X11_SIZE, .dc_y = X11_SIZE, .raster_x = X11_SIZE,
    .raster_y = X11_SIZE, .colr_avail = GAVAIL_COLR, .n_colr = 256, .n_pred_colr = 8,
    .pred_colr = x11_colours, .default_irg = GIRG_SUPPR, .default_defer = GDEFER_ASAP,
    .out = &gks_wdt_raster, .in = &gks_in_desc_std,
    .hlhsr_modes = (1u << GHLHSR_NONE) | (1u << GHLHSR_HIDDEN_LINE) | (1u << GHLHSR_ZBUFFER) |
                   (1u << GHLHSR_PAINTER) | (1u << GHLHSR_RAYTRACE),
};

const gks_ws_driver gks_ws_x11_driver = {
    .desc = &x11_desc, .open = x11_open, .close = x11_close,
    .clear = x11_clear, .background = x11_background, .update = x11_update, .primitive = x11_primitive,
    .mesh = x11_mesh, .message = x11_message, .escape = x11_escape, .input = x11_input,
};
