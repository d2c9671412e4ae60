/*
 * ws_png.c -- the PNG workstation (types 100 and 101): category OUTPUT, raster, display
 * space 1024x1024 (type 100) or 8192x8192 (type 101) pixels; DC unit = one pixel.
 * The image of a frame is the current workstation viewport (its size in pixels).
 *
 * File naming (docs/WORKSTATIONS.md): the connection identifier gives a base name B:
 *   ""/NULL -> "gks";  all digits N (a Fortran CONID) -> "gksN";  "path.png" -> "path";
 *   anything else is used as is. Frame 1 is written to B.png, frame k > 1 to B-k.png
 *   (k with at least three digits). ESCAPE GESC_SET_FILE_NAME replaces B.
 * A frame's file is written at UPDATE WORKSTATION, CLEAR WORKSTATION and CLOSE
 * WORKSTATION when it has new content; a workstation closed without any drawing still
 * writes one (background) picture.
 */
#include "raster.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include "ws_driver.h"
#include "ws_raytrace.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Predefined colours: 0 background white, 1 foreground black, then the usual six. */
static const Grgb png_colours[8] = {
    { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 },
};

typedef struct png_ws {
    gks_raster_fb *fb;
    char *base;
    int frame;          /* 1-based number of the current frame */
    int dirty;          /* content not yet written */
    int written_any;    /* some file has been written */
    int frame_written;  /* the current frame has a file */
    ws_rt *rt;          /* FILL AREAs recorded in HLHSR mode GHLHSR_RAYTRACE */
} png_ws;

static char *base_from_conn(const char *conn)
{
    size_t n = strlen(conn);
    if (n == 0)
        return gks_strdup("gks");
    int digits = 1;
    for (size_t i = 0; i < n; i++)
        digits &= isdigit((unsigned char)conn[i]) != 0;
    if (digits) {
        char *s = gks_alloc_array(n + 4, 1);
        if (s)
            snprintf(s, n + 4, "gks%s", conn);
        return s;
    }
    if (n > 4 && strcmp(conn + n - 4, ".png") == 0)
        return gks_strndup(conn, n - 4);
    return gks_strdup(conn);
}

static int png_open(gks_ws *ws)
{
    png_ws *p = gks_calloc_array(1, sizeof *p);
    if (!p)
        return 300;
    p->base = base_from_conn(ws->conn_id);
    p->rt = ws_rt_new();
    if (!p->base || !p->rt) {
        gks_free(p->base);
        ws_rt_free(p->rt);
        gks_free(p);
        return 300;
    }
    p->frame = 1;
    ws->priv = p;
    return 0;
}

static void png_close(gks_ws *ws)
{
    png_ws *p = ws->priv;
    gks_raster_fb_free(p->fb);
    ws_rt_free(p->rt);
    gks_free(p->base);
    gks_free(p);
    ws->priv = NULL;
}

static void image_size(const gks_ws *ws, int *w, int *h)
{
    *w = (int)ceil(ws->cur_vp.x_max - ws->cur_vp.x_min - 1e-9);
    *h = (int)ceil(ws->cur_vp.y_max - ws->cur_vp.y_min - 1e-9);
    if (*w < 1) *w = 1;
    if (*h < 1) *h = 1;
}

/* The framebuffer for the current viewport, created or re-created and cleared to
 * colour 0 when its size changed; NULL on storage overflow. */
static gks_raster_fb *framebuffer(gks_ws *ws)
{
    png_ws *p = ws->priv;
    int w, h;
    image_size(ws, &w, &h);
    if (p->fb && p->fb->width == w && p->fb->height == h)
        return p->fb;
    gks_raster_fb_free(p->fb);
    p->fb = gks_raster_fb_create(w, h, 1);
    if (p->fb) {
        float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green, (float)ws->colr[0].blue };
        gks_raster_fb_clear(p->fb, bg);
    }
    return p->fb;
}

static int png_clear(gks_ws *ws)
{
    png_ws *p = ws->priv;
    if (p->frame_written) {
        p->frame++;
        p->frame_written = 0;
    }
    p->dirty = 0;
    ws_rt_reset(p->rt);
    gks_raster_fb_free(p->fb);
    p->fb = NULL;
    return framebuffer(ws) ? 0 : 300;
}

static int ws_matrix(const gks_ws *ws, double m[4][4]);

/* Writes the frame's file; recorded ray-tracing primitives are traced first. */
static int png_update(gks_ws *ws)
{
    png_ws *p = ws->priv;
    if (!p->dirty && p->written_any)
        return 0;
    gks_raster_fb *fb = framebuffer(ws);
    if (!fb)
        return 300;
    double wsm[4][4];
    if (ws_rt_count(p->rt) > 0 && ws_matrix(ws, wsm) == 0) {
        int e = ws_rt_render(p->rt, ws, (const double (*)[4])wsm, fb);
        if (e)
            return e;
    }
    size_t n = strlen(p->base) + 32;
    char *path = gks_alloc_array(n, 1);
    if (!path)
        return 300;
    if (p->frame == 1)
        snprintf(path, n, "%s.png", p->base);
    else
        snprintf(path, n, "%s-%03d.png", p->base, p->frame);
    int r = gks_raster_fb_write_png(fb, path);
    gks_free(path);
    if (r != GKS_RASTER_OK)
        return r == GKS_RASTER_E_NOMEM ? 300 : 303;
    p->dirty = 0;
    p->written_any = 1;
    p->frame_written = 1;
    return 0;
}

/* NPC3 -> image pixels and depth: workstation window -> viewport (DC), minus the
 * viewport origin; DC z in [0,1], larger = nearer. */
static int ws_matrix(const gks_ws *ws, double m[4][4])
{
    double win[6];
    gks_limit3_array(&ws->cur_win, win);
    const double vp[6] = { 0, ws->cur_vp.x_max - ws->cur_vp.x_min, 0,
                           ws->cur_vp.y_max - ws->cur_vp.y_min, 0, 1 };
    return gks_xform_ws_tran3(win, vp, m);
}

/* The view pipeline of a primitive: NDC3 -> NPC3 (homogeneous) by the view
 * representation of its view index (an index not in the table uses view 0), and the
 * clip region in homogeneous NPC3: the view clip limits where the indicators are on,
 * intersected with the workstation window (clipping there is mandatory). */
static int view_setup(const gks_ws *ws, int view_ind, double npc[4][4], gks_xform_clip *clip)
{
    const Gview_rep3 *v = &ws->views[view_ind >= 0 && view_ind <= GKS_MAX_VIEW_IND ? view_ind : 0];
    gks_xform_multiply(v->map_matrix, v->ori_matrix, npc);
    double lim[6], win[6];
    gks_limit3_array(&v->clip_limit, lim);
    gks_limit3_array(&ws->cur_win, win);
    unsigned flags = (v->xy_clip == GIND_CLIP ? GKS_XFORM_CLIP_XY : 0) |
                     (v->back_clip == GIND_CLIP ? GKS_XFORM_CLIP_BACK : 0) |
                     (v->front_clip == GIND_CLIP ? GKS_XFORM_CLIP_FRONT : 0);
    gks_xform_clip_init(clip);
    if (flags && gks_xform_clip_add_box(clip, lim, flags))
        return 1;
    return gks_xform_clip_add_box(clip, win, GKS_XFORM_CLIP_ALL);
}

static int png_primitive(gks_ws *ws, const gks_prim *prim)
{
    png_ws *p = ws->priv;
    gks_raster_fb *fb = framebuffer(ws);
    if (!fb)
        return 300;
    if (ws->hlhsr_mode == GHLHSR_RAYTRACE && prim->kind == GKS_PRIM_FILL_AREA) {
        if (ws_rt_record(p->rt, ws, prim))
            return 300;
        p->dirty = 1;
        return 0;
    }
    double m[4][4], npc[4][4];
    gks_xform_clip clip;
    if (ws_matrix(ws, m) || view_setup(ws, prim->view_ind, npc, &clip))
        return 0; /* degenerate transformation: nothing visible */

    size_t n = (size_t)prim->n_points;
    size_t cap = prim->kind == GKS_PRIM_POLYLINE ? 2 * n : 4 * n + 16;
    double (*h)[4] = gks_alloc_array(n, sizeof *h);
    double (*out)[4] = gks_alloc_array(cap, sizeof *out);
    size_t *len = gks_alloc_array(n + (size_t)prim->n_loops, sizeof *len);
    size_t *loops = gks_alloc_array((size_t)prim->n_loops, sizeof *loops);
    int *counts = gks_alloc_array((size_t)prim->n_loops, sizeof *counts);
    gks_raster_pt *pts = gks_alloc_array(cap, sizeof *pts);
    int err = 0;
    if (!h || !out || !len || !loops || !counts || !pts) {
        err = 300;
        goto done;
    }
    for (size_t i = 0; i < n; i++)
        gks_xform_apply(npc, (const double[4]){ prim->pts[i].x, prim->pts[i].y, prim->pts[i].z, 1 },
                        h[i]);
    size_t n_out = 0, n_pieces = 0;
    int r;
    if (prim->kind == GKS_PRIM_POLYLINE) {
        r = gks_xform_clip_polyline(&clip, n, (const double (*)[4])h, out, cap, len, n,
                                    &n_out, &n_pieces);
    } else {
        for (int k = 0; k < prim->n_loops; k++)
            loops[k] = (size_t)prim->loop_counts[k];
        r = gks_xform_clip_polygon(&clip, (size_t)prim->n_loops, loops,
                                   (const double (*)[4])h, out, cap, len, &n_out);
        if (r == 300 && n_out > cap) { /* more vertices than estimated: grow, retry */
            double (*o2)[4] = gks_realloc_array(out, n_out, sizeof *out);
            gks_raster_pt *p2 = o2 ? gks_realloc_array(pts, n_out, sizeof *pts) : NULL;
            if (o2)
                out = o2;
            if (p2)
                pts = p2;
            if (o2 && p2) {
                cap = n_out;
                r = gks_xform_clip_polygon(&clip, (size_t)prim->n_loops, loops,
                                           (const double (*)[4])h, out, cap, len, &n_out);
            }
        }
        n_pieces = (size_t)prim->n_loops;
    }
    if (r == 300)
        err = 300;
    if (r)
        goto done;
    for (size_t i = 0; i < n_out; i++) {
        double c[3], q[3];
        if (gks_xform_divide(out[i], c))
            goto done; /* cannot happen after clipping with wmin > 0 */
        gks_xform_point(m, c, q);
        pts[i] = (gks_raster_pt){ q[0], q[1], q[2] };
    }
    gks_raster_zmode zmode = ws->hlhsr_mode == GHLHSR_ZBUFFER ? GKS_RASTER_Z_TEST : GKS_RASTER_Z_NONE;
    const float rgb[3] = { (float)prim->colour.red, (float)prim->colour.green,
                           (float)prim->colour.blue };
    if (prim->kind == GKS_PRIM_POLYLINE) {
        gks_raster_line la = { .rgb = { rgb[0], rgb[1], rgb[2] }, .width = 1, .type = 1,
                               .zmode = zmode };
        size_t off = 0;
        for (size_t k = 0; k < n_pieces; k++) {
            gks_raster_polyline(fb, len[k], pts + off, &la);
            off += len[k];
        }
    } else {
        int nl = 0;
        for (size_t k = 0; k < n_pieces; k++)
            counts[nl++] = (int)len[k];
        gks_raster_fill fa = { .style = GKS_RASTER_SOLID, .rgb = { rgb[0], rgb[1], rgb[2] },
                               .zmode = zmode };
        if (n_out >= 3)
            gks_raster_fill_area(fb, nl, counts, pts, &fa);
    }
    p->dirty = 1;
done:
    gks_free(h);
    gks_free(out);
    gks_free(len);
    gks_free(loops);
    gks_free(counts);
    gks_free(pts);
    return err;
}

static int png_message(gks_ws *ws, const char *msg)
{
    /* A file workstation has no operator display: messages go to standard error. */
    fprintf(stderr, "gks3d: message for workstation %d: %s\n", ws->id, msg);
    return 0;
}

static int png_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    png_ws *p = ws->priv;
    if (func_id <= GESC_RT_CLIP_SECONDARY) /* the ray-tracing controls */
        return ws_rt_escape(p->rt, func_id, in, out);
    if (func_id != GESC_SET_FILE_NAME)
        return 180;
    char *b = gks_strndup(in->str, in->str_len);
    if (!b)
        return 300;
    gks_free(p->base);
    p->base = b;
    return 0;
}

#define PNG_DESC(TYPE, NAME, SIZE)                                                   \
    {                                                                                \
        .type = TYPE, .name = NAME, .cat = GCAT_OUT, .cls = GCLASS_RASTER,           \
        .dc_units = GDC_OTHER, .dc_x = SIZE, .dc_y = SIZE, .raster_x = SIZE,         \
        .raster_y = SIZE, .colr_avail = GAVAIL_COLR, .n_colr = 256, .n_pred_colr = 8, \
        .pred_colr = png_colours, .default_irg = GIRG_SUPPR,                         \
        .default_defer = GDEFER_ASAP,                                                \
        .hlhsr_modes = (1u << GHLHSR_NONE) | (1u << GHLHSR_ZBUFFER) | (1u << GHLHSR_RAYTRACE),\
    }

static const gks_ws_desc png_desc = PNG_DESC(GWS_TYPE_PNG, "png", 1024);
static const gks_ws_desc png_large_desc = PNG_DESC(GWS_TYPE_PNG_LARGE, "png-large", 8192);

#define PNG_DRIVER(DESC)                                                           \
    {                                                                              \
        .version = GKS_WS_DRIVER_VERSION, .desc = &DESC, .open = png_open,         \
        .close = png_close, .clear = png_clear, .update = png_update,              \
        .primitive = png_primitive, .message = png_message, .escape = png_escape,  \
    }

const gks_ws_driver gks_ws_png_driver = PNG_DRIVER(png_desc);
const gks_ws_driver gks_ws_png_large_driver = PNG_DRIVER(png_large_desc);
