/* SPDX-License-Identifier: MIT */
/*
 * ws_png.c -- the PNG workstation (types 100 and 101): category OUTPUT, raster, display
 * space 1024x1024 (type 100) or 8192x8192 (type 101) pixels; DC unit = one pixel.
 * The image of a frame is the current workstation viewport (its size in pixels).
 *
 * File naming (docs/WORKSTATIONS.md): the connection identifier gives a base name B:
 *   ""/NULL -> "gks";  all digits N (a Fortran CONID) -> "gksN"; either + "-wsW" (W =
 *   workstation identifier) when another open workstation writes its frame-1 file;
 *   "path.png" -> "path";  anything else is used as is. Frame 1 is written to B.png, frame k > 1 to B-k.png
 *   (k with at least three digits). ESCAPE GESC_SET_FILE_NAME replaces B.
 * A frame's file is written at UPDATE WORKSTATION, CLEAR WORKSTATION and CLOSE
 * WORKSTATION when it has new content; a workstation closed without any drawing still
 * writes one (background) picture. INQUIRE PIXEL (ARRAY) reads the picture the update
 * would write, ray-traced areas traced at the inquiry (seen_picture).
 *
 * Rendering and the HLHSR modes: ws_classic.h. Anti-aliasing: ESCAPE
 * GESC_PNG_SUPERSAMPLE (ints[1] = s in 1..4) renders the following frames with s x s
 * samples per pixel (box-filtered to the image when written); it applies at once if the
 * current frame is still empty, else from the next CLEAR WORKSTATION. Default 1 (none).
 * Compression: ESCAPE GESC_PNG_COMPRESSION (ints[1] = 0 fast, the default: zlib run-length
 * strategy with the SUB row filter; 1..9: zlib level with libpng's adaptive row filters,
 * 9 smallest) applies to every file written from then on.
 */
#include "raster.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include "ws_driver.h"
#include "ws_render.h"
#include "ws_file.h"
#include "ws_mpi.h"
#include "gks_par.h"
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>

/* Predefined colours: 0 background white, 1 foreground black, then the usual six. */
static const Grgb png_colours[8] = {
    { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 },
};

/* The workstation state a picture is made with besides the primitives: the window and
 * viewport, colour 0 (the tracer's background), the HLHSR mode, the view and light source
 * tables (the tracer's cameras and lights, the classic renderer's view pipelines). */
typedef struct seen_key {
    Glimit3 win, vp;
    Grgb bg;
    int hlhsr_mode;
    Gview_rep3 views[GKS_MAX_VIEW_IND + 1];
    Glight_src_rep lights[GKS_MAX_LIGHT_IND];
    unsigned char light_defined[GKS_MAX_LIGHT_IND];
} seen_key;

typedef struct png_ws {
    gks_raster_fb *fb;  /* primitives drawn at once */
    Glimit3 fb_vp;      /* the viewport fb was sized for (framebuffer()'s quick check) */
    char *base;
    int frame;          /* 1-based number of the current frame */
    int dirty;          /* content not yet written */
    int written_any;    /* some file has been written */
    int frame_written;  /* the current frame has a file */
    int ss;             /* supersampling factor of the next framebuffer (anti-aliasing) */
    int compression;    /* PNG compression: GKS_RASTER_PNG_FAST or a zlib level 1..9 */
    ws_render *r;       /* the classic renderer and the tracer's recording (ws_render.h) */
    int mpi_frames;     /* MPI run: whole frames to ranks (1) or tiles of each frame (0) */
    gks_raster_fb *seen; /* pixel readback: the picture as png_update would write it now */
    int seen_ok;        /* seen is current: no output, clear or ESCAPE since it was made */
    seen_key *key;      /* ... and the workstation state it was made with */
    unsigned char *rgb8; /* the written picture's 8-bit rows when resolved on the tracer's
                            pool (write_picture), kept for the next frames of its size */
    size_t rgb8_n;      /* its bytes */
} png_ws;

/* The base name B (file naming above). Several workstations opened without a connection
 * identifier (NCAR's c_test38 opens three) or on one Fortran unit number (fgke04) so get
 * files of their own (gks_ws_file_default_base). */
static char *png_base(const gks_ws *ws)
{
    return gks_ws_file_default_base(ws, ".png");
}

/* The file of frame 1 (later frames are B-k.png beside it). */
static int png_file(const gks_ws *ws, char **path)
{
    char *b = png_base(ws);
    *path = b ? gks_ws_file_frame(b, 1, ".png") : NULL;
    gks_free(b);
    return *path ? 0 : 300;
}

static int png_open(gks_ws *ws)
{
    png_ws *p = gks_calloc_array(1, sizeof *p);
    if (!p)
        return 300;
    p->base = png_base(ws);
    p->r = ws_render_new();
    p->key = gks_calloc_array(1, sizeof *p->key);
    if (!p->base || !p->r || !p->key) {
        gks_free(p->base);
        ws_render_free(p->r);
        gks_free(p->key);
        gks_free(p);
        return 300;
    }
    p->frame = 1;
    p->ss = 1;
    p->compression = GKS_RASTER_PNG_FAST;
    p->mpi_frames = gks_par_frames_default();
    ws->priv = p;
    return 0;
}

static void png_close(gks_ws *ws)
{
    png_ws *p = ws->priv;
    gks_raster_fb_free(p->fb);
    gks_raster_fb_free(p->seen);
    gks_free(p->key);
    gks_free(p->rgb8);
    ws_render_free(p->r);
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

/* The thread count of the frame's parallel parts (GESC_RT_THREADS: 0 the online CPUs). */
static int png_threads(const png_ws *p)
{
    rt_render_options o;
    ws_rt_options(p->r->rt, &o);
    return o.threads;
}

/* Sample rows [k*h/n, (k+1)*h/n) of a new framebuffer cleared to the background (part k of
 * n on the tracer's pool; each sample as gks_raster_fb_clear writes it). */
typedef struct clear_job {
    gks_raster_fb *fb;
    float bg[3];
} clear_job;

static void clear_part(void *arg, int k, int n)
{
    clear_job *j = arg;
    const int h = j->fb->h;
    gks_raster_fb_clear_rows(j->fb, j->bg, (int)((long)k * h / n), (int)((long)(k + 1) * h / n));
}

/* framebuffer() when the viewport is not the one fb was sized for (apart, so that the check
 * per primitive is a short inline test). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static gks_raster_fb *framebuffer_resize(gks_ws *ws)
{
    png_ws *p = ws->priv;
    const Glimit3 *vp = &ws->cur_vp;
    int w, h;
    image_size(ws, &w, &h);
    p->fb_vp = *vp;
    if (p->fb && p->fb->width == w && p->fb->height == h)
        return p->fb;
    gks_raster_fb_free(p->fb);
    p->fb = gks_raster_fb_alloc(w, h, p->ss);
    if (p->fb) { /* one pass, its first touch of the memory, in parts on the tracer's pool */
        clear_job j = { p->fb, { (float)ws->colr[0].red, (float)ws->colr[0].green,
                                 (float)ws->colr[0].blue } };
        rt_parallel_parts(png_threads(p), clear_part, &j);
    }
    return p->fb;
}

/* The framebuffer for the current viewport, created or re-created and cleared to
 * colour 0 when its size changed; NULL on storage overflow. */
static inline gks_raster_fb *framebuffer(gks_ws *ws)
{
    const png_ws *p = ws->priv;
    const Glimit3 *vp = &ws->cur_vp;
    if (p->fb && vp->x_min == p->fb_vp.x_min && vp->x_max == p->fb_vp.x_max &&
        vp->y_min == p->fb_vp.y_min && vp->y_max == p->fb_vp.y_max)
        return p->fb; /* the viewport it was sized for: no size to recompute per primitive */
    return framebuffer_resize(ws);
}

static int png_clear(gks_ws *ws)
{
    png_ws *p = ws->priv;
    p->seen_ok = 0;
    if (p->frame_written) {
        p->frame++;
        p->frame_written = 0;
    }
    p->dirty = 0;
    ws_render_reset(p->r);
    if (p->fb && p->fb->ss == p->ss) { /* same sampling: cleared in place if the size */
        gks_raster_fb *fb = p->fb;      /* is unchanged (framebuffer() checks it) */
        int w, h;
        image_size(ws, &w, &h);
        if (fb->width == w && fb->height == h) {
            float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green,
                            (float)ws->colr[0].blue };
            gks_raster_fb_clear(fb, bg);
            return 0;
        }
    }
    /* another size or sampling: the new framebuffer is made by the first output or
       update that needs it (framebuffer()), at the viewport of that time; a program that
       sets the workstation window and then the viewport (the usual order) so makes one
       framebuffer, not one of the default 1024 x 1024 pixels first */
    gks_raster_fb_free(p->fb);
    p->fb = NULL;
    return 0;
}

/* gks_ws_driver.background: the empty frame's picture cleared to the new colour 0; a
 * frame file already written of it is written again at the next update. */
static int png_background(gks_ws *ws)
{
    png_ws *p = ws->priv;
    p->seen_ok = 0;
    if (p->fb) {
        float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green,
                        (float)ws->colr[0].blue };
        gks_raster_fb_clear(p->fb, bg);
    }
    if (p->frame_written)
        p->dirty = 1;
    return 0;
}

static int ws_matrix(const gks_ws *ws, double m[4][4]);

/* The written picture's rows resolved to 8 bits (each as gks_raster_fb_resolve_row makes
 * it) by every part of a write on the tracer's pool while part 0 compresses them in order:
 * a row is claimed by whichever part takes next, and done[y] says it is complete. */
typedef struct write_job {
    const gks_raster_fb *pic;
    unsigned char *rgb8;
    atomic_uchar *done;
    atomic_int next; /* the next row to claim */
    const char *path;
    int compression;
    int rc;          /* part 0's GKS_RASTER_* code */
} write_job;

/* Claims the next row and resolves it; 0 when every row was claimed. */
static int resolve_next(write_job *j)
{
    const int y = atomic_fetch_add_explicit(&j->next, 1, memory_order_relaxed);
    if (y >= j->pic->height)
        return 0;
    gks_raster_fb_resolve_row(j->pic, y, j->rgb8 + 3 * (size_t)j->pic->width * (size_t)y);
    atomic_store_explicit(&j->done[y], 1, memory_order_release);
    return 1;
}

/* gks_raster_row_fn of part 0: row y once complete; meanwhile the waiting part resolves
 * rows itself (a claimed row that is not done is being resolved by a running part). */
static const unsigned char *ready_row(void *user, int y)
{
    write_job *j = user;
    while (!atomic_load_explicit(&j->done[y], memory_order_acquire))
        if (!resolve_next(j))
            sched_yield();
    return j->rgb8 + 3 * (size_t)j->pic->width * (size_t)y;
}

static void write_part(void *arg, int k, int n)
{
    (void)n;
    write_job *j = arg;
    if (k == 0)
        j->rc = gks_raster_png_write_rows(j->path, j->pic->width, j->pic->height, ready_row, j,
                                          j->compression);
    else
        while (resolve_next(j))
            ;
}

/* The picture into the file at path: with one thread (GESC_RT_THREADS 1) resolved row by
 * row as libpng takes them; with more, the other parts on the tracer's pool resolve rows
 * ahead into p->rgb8 while this thread compresses them (the same rows to the same PNG
 * writer: the same bytes), so that the frame's serial tail is the compression alone.
 * Without storage for the 8-bit copy it falls back to the rows one by one. A GKS_RASTER_*
 * code. */
static int write_picture(png_ws *p, const gks_raster_fb *pic, const char *path)
{
    const int threads = png_threads(p);
    const size_t need = 3 * (size_t)pic->width * (size_t)pic->height;
    if (threads != 1 && p->rgb8_n != need) {
        gks_free(p->rgb8);
        p->rgb8 = gks_alloc_array(need, 1);
        p->rgb8_n = p->rgb8 ? need : 0;
    }
    atomic_uchar *done = threads != 1 && p->rgb8
                         ? gks_alloc_array((size_t)pic->height, sizeof *done) : NULL;
    if (!done)
        return gks_raster_fb_write_png(pic, path, p->compression);
    write_job j = { .pic = pic, .rgb8 = p->rgb8, .done = done, .path = path,
                    .compression = p->compression, .rc = GKS_RASTER_E_IO };
    atomic_init(&j.next, 0);
    for (int y = 0; y < pic->height; y++)
        atomic_init(&done[y], 0);
    rt_parallel_parts(threads, write_part, &j);
    gks_free(done);
    return j.rc;
}

/* Writes the frame's file; recorded ray-tracing primitives are traced first. */
static int png_update(gks_ws *ws)
{
    png_ws *p = ws->priv;
    if (!p->dirty && p->written_any)
        return 0;
    p->seen_ok = 0; /* the trace below goes into the framebuffer itself */
    gks_raster_fb *fb = framebuffer(ws);
    if (!fb)
        return 300;
    /* MPI run (ws_mpi.h): this rank may trace a share of the frame, all of it, or none,
       and only one rank writes it */
    const int writes = ws_mpi_writes(p->mpi_frames, p->frame);
    const int shares = ws_mpi_shares_tiles(p->mpi_frames);
    ws_rt_set_share_tiles(p->r->rt, shares);
    int fault = 0;
    double wsm[4][4];
    if ((writes || shares) && ws_rt_count(p->r->rt) > 0 && ws_matrix(ws, wsm) == 0) {
        int e = ws_rt_render(p->r->rt, ws, (const double (*)[4])wsm, fb);
        if (e == 305)
            fault = e; /* a lost rank: rank 0's frame is complete all the same */
        else if (e)
            return e;
    }
    if (!writes) { /* another rank writes this frame */
        p->dirty = 0;
        p->written_any = 1;
        p->frame_written = 1;
        return fault;
    }
    gks_raster_fb *pic;
    if (ws_classic_compose(p->r->classic, ws, fb, &pic))
        return 300;
    char *path;
    /* a later frame's name, or one an ESCAPE set, may be another workstation's file */
    int c = gks_ws_file_claim_frame(ws, p->base, p->frame, ".png", &path);
    if (c)
        return c;
    errno = 0;
    int r = write_picture(p, pic, path);
    if (r == GKS_RASTER_E_IO)
        gks_ws_note(ws, "cannot write \"%s\": %s", path, errno ? strerror(errno) : "write failed");
    gks_free(path);
    if (r != GKS_RASTER_OK)
        return r == GKS_RASTER_E_NOMEM ? 300 : 303;
    p->dirty = 0;
    p->written_any = 1;
    p->frame_written = 1;
    return fault;
}

/* NPC3 -> image pixels and depth: workstation window -> viewport (DC), minus the
 * viewport origin; DC z in [0,1], larger = nearer. */
static int ws_matrix(const gks_ws *ws, double m[4][4])
{
    return gks_ws_pixel_matrix(ws, 1.0, m);
}

static int png_primitive(gks_ws *ws, const gks_prim *prim)
{
    png_ws *p = ws->priv;
    p->seen_ok = 0;
    gks_raster_fb *fb = framebuffer(ws);
    if (!fb)
        return 300;
    int e = ws_render_prim(p->r, ws, fb, prim); /* 300, or 308 (coordinate range) */
    if (!e)
        p->dirty = 1;
    return e;
}

/* A mesh kept whole: the tracer's (ray tracing), else the facets one by one (0 only when
 * recorded, so that the frame is dirty just as after its facets). */
static int png_mesh(gks_ws *ws, const gks_mesh *m)
{
    png_ws *p = ws->priv;
    int e = ws_render_mesh(p->r, ws, m);
    if (!e)
        p->dirty = 1;
    return e;
}

static int png_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    png_ws *p = ws->priv;
    p->seen_ok = 0; /* sampling or ray-tracing options may change the picture */
    if (func_id == GESC_PNG_SUPERSAMPLE) {
        int e = gks_ws_escape_int(in, 1, 4, &p->ss);
        if (e)
            return e;
        if (!p->dirty && !p->frame_written && ws_classic_retained(p->r->classic) == 0 &&
            ws_rt_count(p->r->rt) == 0) { /* nothing drawn yet: this frame already */
            gks_raster_fb_free(p->fb);
            p->fb = NULL;
            return framebuffer(ws) ? 0 : 300;
        }
        return 0;
    }
    if (func_id == GESC_PNG_COMPRESSION) {
        return gks_ws_escape_int(in, GKS_RASTER_PNG_FAST, GKS_RASTER_PNG_LEVEL_MAX,
                                 &p->compression);
    }
    return ws_rt_file_escape(p->r->rt, ws, func_id, in, out, p->frame, ".png", &p->base);
}

/* The key of the picture ws's state gives now (seen_key). */
static void seen_key_of(const gks_ws *ws, seen_key *k)
{
    memset(k, 0, sizeof *k);
    memcpy(&k->win, &ws->cur_win, sizeof k->win);
    memcpy(&k->vp, &ws->cur_vp, sizeof k->vp);
    memcpy(&k->bg, &ws->colr[0], sizeof k->bg);
    k->hlhsr_mode = ws->hlhsr_mode;
    memcpy(k->views, ws->views, sizeof k->views);
    memcpy(k->lights, ws->lights, sizeof k->lights);
    memcpy(k->light_defined, ws->light_defined, sizeof k->light_defined);
}

/* *dst (re-created if its size differs) becomes a copy of src; 0 or 300. */
static int fb_copy(gks_raster_fb **dst, const gks_raster_fb *src)
{
    gks_raster_fb *d = *dst;
    if (!d || d->width != src->width || d->height != src->height || d->ss != src->ss) {
        gks_raster_fb_free(d);
        d = *dst = gks_raster_fb_create(src->width, src->height, src->ss);
        if (!d)
            return 300;
    }
    size_t ns = (size_t)src->w * (size_t)src->h;
    memcpy(d->rgb, src->rgb, 3 * ns * sizeof *d->rgb);
    memcpy(d->z, src->z, ns * sizeof *d->z);
    return 0;
}

/* The picture png_update would write now, in p->seen: a copy of the framebuffer with the
 * recorded ray-tracing areas traced into it (here alone, never by the ranks of an MPI
 * run, which do not all inquire) and the retained primitives composed over it. The
 * framebuffer and the recording stay as they are, so the frame written later is the same
 * whether or not it was inquired. Kept for the next readback (INQUIRE PIXEL ARRAY reads
 * row by row) until output, CLEAR, UPDATE, an ESCAPE or a change of the state in
 * seen_key. 0 or 300 (storage; 305 of a lost MPI rank cannot occur alone). */
static int seen_picture(gks_ws *ws, const gks_raster_fb **out)
{
    png_ws *p = ws->priv;
    seen_key k;
    seen_key_of(ws, &k);
    if (p->seen_ok && memcmp(&k, p->key, sizeof k) == 0) {
        *out = p->seen;
        return 0;
    }
    p->seen_ok = 0;
    gks_raster_fb *fb = framebuffer(ws), *pic;
    if (!fb || fb_copy(&p->seen, fb))
        return 300;
    double wsm[4][4];
    if ((p->dirty || !p->written_any) && ws_rt_count(p->r->rt) > 0 &&
        ws_matrix(ws, wsm) == 0) { /* png_update traces then */
        ws_rt_set_share_tiles(p->r->rt, 0);
        if (ws_rt_render(p->r->rt, ws, (const double (*)[4])wsm, p->seen))
            return 300;
    }
    if (ws_classic_compose(p->r->classic, ws, p->seen, &pic))
        return 300;
    if (pic != p->seen && fb_copy(&p->seen, pic))
        return 300;
    memcpy(p->key, &k, sizeof k);
    p->seen_ok = 1;
    *out = p->seen;
    return 0;
}

/* Pixel readback: the picture as it would be written now (seen_picture), ray-traced
 * areas included. */
static int png_read_pixels(gks_ws *ws, int x0, int y0, int nx, int ny, int *rgb)
{
    const gks_raster_fb *pic;
    if (seen_picture(ws, &pic))
        return 300;
    unsigned char *row = gks_alloc_array((size_t)pic->width, 3);
    if (!row)
        return 300;
    for (int j = 0; j < ny; j++) {
        int y = y0 + j, have = y >= 0 && y < pic->height;
        if (have)
            gks_raster_fb_resolve_row(pic, pic->height - 1 - y, row);
        for (int i = 0; i < nx; i++) {
            int x = x0 + i;
            const unsigned char *c = row + 3 * (size_t)x;
            rgb[(size_t)j * (size_t)nx + (size_t)i] =
                have && x >= 0 && x < pic->width ? (c[0] << 16) | (c[1] << 8) | c[2] : -1;
        }
    }
    gks_free(row);
    return 0;
}

#define PNG_DESC(TYPE, NAME, SIZE, CAT, IN)                                          \
    {                                                                                \
        .type = TYPE, .name = NAME, .cat = CAT, .cls = GCLASS_RASTER,                  \
        .dc_units = GDC_OTHER, .dc_x = SIZE, .dc_y = SIZE, .raster_x = SIZE,         \
        .raster_y = SIZE, .colr_avail = GAVAIL_COLR, .n_colr = 256, .n_pred_colr = 8, \
        .pred_colr = png_colours, .default_irg = GIRG_SUPPR,                         \
        .default_defer = GDEFER_ASAP, .out = &gks_wdt_raster, .in = IN,               \
        .hlhsr_modes = (1u << GHLHSR_NONE) | (1u << GHLHSR_HIDDEN_LINE) |               \
                       (1u << GHLHSR_ZBUFFER) | (1u << GHLHSR_PAINTER) |                \
                       (1u << GHLHSR_RAYTRACE),                                         \
    }

/* 100 and 101 are OUTIN (input from scripts, docs/INPUT.md); 102 is the same picture
 * without input devices, category OUTPUT: what a program that asks the category to
 * decide whether to wait for the user (NCAR's FRAME, docs/NCAR.md) needs. */
static const gks_ws_desc png_desc =
    PNG_DESC(GWS_TYPE_PNG, "png", 1024, GCAT_OUTIN, &gks_in_desc_std);
static const gks_ws_desc png_large_desc =
    PNG_DESC(GWS_TYPE_PNG_LARGE, "png-large", 8192, GCAT_OUTIN, &gks_in_desc_std);
static const gks_ws_desc png_output_desc =
    PNG_DESC(GWS_TYPE_PNG_OUTPUT, "png-output", 1024, GCAT_OUT, NULL);

#define PNG_DRIVER(DESC)                                                           \
    {                                                                              \
        .desc = &DESC, .file = png_file,                                           \
        .open = png_open, .background = png_background,                            \
        .close = png_close, .clear = png_clear, .update = png_update,              \
        .primitive = png_primitive, .mesh = png_mesh, .message = gks_ws_file_message, .escape = png_escape,  \
        .read_pixels = png_read_pixels,                                            \
    }

const gks_ws_driver gks_ws_png_driver = PNG_DRIVER(png_desc);
const gks_ws_driver gks_ws_png_large_driver = PNG_DRIVER(png_large_desc);
const gks_ws_driver gks_ws_png_output_driver = PNG_DRIVER(png_output_desc);
