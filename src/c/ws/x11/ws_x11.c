/* SPDX-License-Identifier: MIT */
/*
 * ws_x11.c -- the interactive X11 workstation (type GWS_TYPE_X11, category OUTIN, raster,
 * display space 800 x 800 pixels, DC unit = one pixel, y up). Output goes through the
 * PNG workstation's renderers (ws_png_render.h for the classic HLHSR modes, ws_raytrace.h
 * for ray tracing) into a framebuffer that UPDATE WORKSTATION (and every input wait)
 * shows in the window; an Expose event redraws from the shown picture.
 *
 * Connection identifier: an X display name ("" or a Fortran unit number: $DISPLAY).
 * No display: OPEN WORKSTATION reports 26 and nothing else happens. The window is opened
 * only by OPEN WORKSTATION of this type.
 *
 * Physical input devices (the core maps them to logical devices; docs/INPUT.md):
 *   mouse button 1 press   LOCATOR and PICK trigger at the pointer position;
 *                          STROKE: press adds a point, button 3 ends the stroke
 *   keys 1..9              CHOICE number; 0: no choice
 *   keys + / -             VALUATOR up / down a tenth of its range, Return triggers
 *   typed text + Return    STRING
 *   Escape                 break of the device a REQUEST waits for
 * Which logical device a press goes to: the one a REQUEST waits for, else the first
 * device in SAMPLE or EVENT mode of a class the action serves. Prompt and echo: the
 * window title names the device taking input; locator echo is the pointer (crosshair
 * cursor).
 */
#include "gks_alloc.h"
#include "gks_xform.h"
#include "raster.h"
#include "ws_driver.h"
#include "ws_png_render.h"
#include "ws_raytrace.h"
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/cursorfont.h>
#include <X11/keysym.h>
#include <ctype.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>

#define X11_SIZE 800

static const Grgb x11_colours[8] = {
    { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 },
};

typedef struct x11_ws {
    Display *dpy;
    Window win;
    GC gc;
    XImage *img;              /* the picture shown (window size, 32-bit TrueColor) */
    int w, h;
    gks_raster_fb *fb;
    png_render *render;
    ws_rt *rt;
    int dirty;
    double pts[GKS_IN_STROKE_MAX][3]; /* stroke being entered / the last raw event */
    int npts;
    char text[GKS_IN_STRING_MAX + 1];
    int ntext;
    double val;
    int have_val;
} x11_ws;

static int x11_ws_matrix(const gks_ws *ws, double m[4][4])
{
    double win[6];
    gks_limit3_array(&ws->cur_win, win);
    const double vp[6] = { 0, ws->cur_vp.x_max - ws->cur_vp.x_min, 0,
                           ws->cur_vp.y_max - ws->cur_vp.y_min, 0, 1 };
    return gks_xform_ws_tran3(win, vp, m);
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

static void x11_blit(x11_ws *x)
{
    if (x->img)
        XPutImage(x->dpy, x->win, x->gc, x->img, 0, 0, 0, 0, (unsigned)x->w, (unsigned)x->h);
    XFlush(x->dpy);
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
    return 0;
}

static int x11_open(gks_ws *ws)
{
    const char *name = ws->conn_id;
    int digits = 1;
    for (const char *c = name; *c; c++)
        digits &= isdigit((unsigned char)*c) != 0;
    Display *dpy = XOpenDisplay(digits ? NULL : name);
    if (!dpy)
        return 26;
    int scr = DefaultScreen(dpy);
    Visual *vis = DefaultVisual(dpy, scr);
    if (DefaultDepth(dpy, scr) < 24 || vis->class != TrueColor) {
        XCloseDisplay(dpy);
        return 26;
    }
    x11_ws *x = gks_calloc_array(1, sizeof *x);
    if (!x) {
        XCloseDisplay(dpy);
        return 300;
    }
    x->dpy = dpy;
    x->w = x->h = X11_SIZE;
    x->render = ws_png_render_new();
    x->rt = ws_rt_new();
    char *data = gks_calloc_array((size_t)x->w * (size_t)x->h, 4);
    if (!x->render || !x->rt || !data) {
        ws_png_render_free(x->render);
        ws_rt_free(x->rt);
        gks_free(data);
        gks_free(x);
        XCloseDisplay(dpy);
        return 300;
    }
    x->win = XCreateSimpleWindow(dpy, RootWindow(dpy, scr), 0, 0, (unsigned)x->w,
                                 (unsigned)x->h, 0, BlackPixel(dpy, scr), WhitePixel(dpy, scr));
    XStoreName(dpy, x->win, "gks3d");
    XSelectInput(dpy, x->win, ExposureMask | ButtonPressMask | KeyPressMask | StructureNotifyMask);
    XDefineCursor(dpy, x->win, XCreateFontCursor(dpy, XC_crosshair));
    x->gc = XCreateGC(dpy, x->win, 0, NULL);
    x->img = XCreateImage(dpy, vis, (unsigned)DefaultDepth(dpy, scr), ZPixmap, 0, data,
                          (unsigned)x->w, (unsigned)x->h, 32, 0);
    for (int j = 0; j < x->h; j++)
        for (int i = 0; i < x->w; i++)
            XPutPixel(x->img, i, j, 0xffffff);
    XMapWindow(dpy, x->win);
    XEvent e;
    do /* wait until mapped, so the first picture shows */
        XNextEvent(dpy, &e);
    while (e.type != MapNotify);
    ws->priv = x;
    return 0;
}

static void x11_close(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    if (!x)
        return;
    XDestroyImage(x->img); /* frees its data */
    XFreeGC(x->dpy, x->gc);
    XDestroyWindow(x->dpy, x->win);
    XCloseDisplay(x->dpy);
    gks_raster_fb_free(x->fb);
    ws_png_render_free(x->render);
    ws_rt_free(x->rt);
    gks_free(x);
    ws->priv = NULL;
}

static int x11_clear(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    ws_rt_reset(x->rt);
    ws_png_render_reset(x->render);
    gks_raster_fb_free(x->fb);
    x->fb = NULL;
    x->dirty = 1;
    return x11_fb(ws) ? 0 : 300;
}

/* Shows the frame: ray-traced areas traced first, retained primitives composed. */
static int x11_update(gks_ws *ws)
{
    x11_ws *x = ws->priv;
    gks_raster_fb *fb = x11_fb(ws), *pic;
    if (!fb)
        return 300;
    double m[4][4];
    if (ws_rt_count(x->rt) > 0 && x11_ws_matrix(ws, m) == 0) {
        int e = ws_rt_render(x->rt, ws, (const double (*)[4])m, fb);
        if (e)
            return e;
        ws_rt_reset(x->rt); /* traced into fb: not again at the next update */
    }
    if (ws_png_render_compose(x->render, ws, fb, &pic))
        return 300;
    x->dirty = 0;
    return x11_show(ws, pic);
}

static int x11_primitive(gks_ws *ws, const gks_prim *prim)
{
    x11_ws *x = ws->priv;
    gks_raster_fb *fb = x11_fb(ws);
    if (!fb)
        return 300;
    x->dirty = 1;
    if (ws->hlhsr_mode == GHLHSR_RAYTRACE &&
        (prim->kind == GKS_PRIM_FILL_AREA || prim->kind == GKS_PRIM_CELL_ARRAY))
        return ws_rt_record(x->rt, ws, prim) ? 300 : 0;
    return ws_png_render_prim(x->render, ws, fb, prim);
}

static int x11_message(gks_ws *ws, const char *msg)
{
    x11_ws *x = ws->priv;
    XStoreName(x->dpy, x->win, msg);
    XFlush(x->dpy);
    return 0;
}

static int x11_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    x11_ws *x = ws->priv;
    if (func_id <= GESC_RT_CLIP_SECONDARY && func_id >= GESC_RT_SPD)
        return ws_rt_escape(x->rt, func_id, in, out);
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
    static const char *const names[] = { "", "LOCATOR", "STROKE", "VALUATOR", "CHOICE",
                                         "PICK", "STRING" };
    char t[96];
    if (a->request >= 0)
        snprintf(t, sizeof t, "gks3d: REQUEST %s %d", names[a->dev[a->request].cls],
                 a->dev[a->request].num);
    else
        snprintf(t, sizeof t, "gks3d");
    XStoreName(x->dpy, x->win, t);
}

/* One X event -> a raw event (1), or nothing (0). */
static int translate(gks_ws *ws, const gks_in_active *a, XEvent *e, gks_in_raw *ev)
{
    x11_ws *x = ws->priv;
    if (e->type == Expose) {
        x11_blit(x);
        return 0;
    }
    if (e->type == ButtonPress) {
        double dc[3] = { e->xbutton.x + 0.5, x->h - e->xbutton.y - 0.5, 0 };
        int k = target(a, (1u << GIN_LOC) | (1u << GIN_PICK) | (1u << GIN_STROKE));
        if (k < 0)
            return 0;
        *ev = (gks_in_raw){ .cls = a->dev[k].cls, .num = a->dev[k].num };
        if (ev->cls == GIN_STROKE) {
            if (e->xbutton.button == Button1 && x->npts < GKS_IN_STROKE_MAX) {
                memcpy(x->pts[x->npts++], dc, sizeof dc);
                return 0;
            }
            if (x->npts == 0)
                return 0;
            ev->n = x->npts;
            x->npts = 0;
        } else {
            memcpy(x->pts[0], dc, sizeof dc);
            ev->n = 1;
        }
        ev->pts = (const double (*)[3])x->pts;
        return 1;
    }
    if (e->type != KeyPress)
        return 0;
    char buf[8];
    KeySym sym;
    int n = XLookupString(&e->xkey, buf, sizeof buf, &sym, NULL);
    if (sym == XK_Escape && a->request >= 0) {
        *ev = (gks_in_raw){ .cls = a->dev[a->request].cls, .num = a->dev[a->request].num,
                            .brk = 1 };
        return 1;
    }
    int ks = target(a, 1u << GIN_STRING), kc = target(a, 1u << GIN_CHOICE),
        kv = target(a, 1u << GIN_VAL);
    if (ks >= 0 && (a->request < 0 || a->request == ks)) {
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
        return 0;
    }
    if (kc >= 0 && n == 1 && buf[0] >= '0' && buf[0] <= '9') {
        *ev = (gks_in_raw){ .cls = GIN_CHOICE, .num = a->dev[kc].num, .choice = buf[0] - '0' };
        return 1;
    }
    if (kv >= 0) {
        const gks_in_active_dev *d = &a->dev[kv];
        if (!x->have_val) {
            x->val = d->val;
            x->have_val = 1;
        }
        double step = (d->high - d->low) / 10;
        if (n == 1 && (buf[0] == '+' || buf[0] == '-')) {
            x->val += buf[0] == '+' ? step : -step;
            x->val = x->val < d->low ? d->low : x->val > d->high ? d->high : x->val;
            if (d->mode == GOP_REQ)
                return 0;
        } else if (sym != XK_Return) {
            return 0;
        }
        *ev = (gks_in_raw){ .cls = GIN_VAL, .num = d->num, .val = x->val };
        return 1;
    }
    return 0;
}

static int x11_input(gks_ws *ws, const gks_in_active *act, double timeout, gks_in_raw *ev)
{
    x11_ws *x = ws->priv;
    if (x->dirty && x11_update(ws))
        return -1;
    prompt(x, act);
    int ms = timeout > 0 ? (int)ceil(timeout * 1000) : 0;
    for (;;) {
        while (XPending(x->dpy)) {
            XEvent e;
            XNextEvent(x->dpy, &e);
            if (translate(ws, act, &e, ev))
                return 1;
        }
        struct pollfd p = { ConnectionNumber(x->dpy), POLLIN, 0 };
        if (ms <= 0 || poll(&p, 1, ms) <= 0)
            return 0;
        if (p.revents & (POLLERR | POLLHUP))
            return -1;
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
    .version = GKS_WS_DRIVER_VERSION, .desc = &x11_desc, .open = x11_open, .close = x11_close,
    .clear = x11_clear, .update = x11_update, .primitive = x11_primitive,
    .message = x11_message, .escape = x11_escape, .input = x11_input,
};
