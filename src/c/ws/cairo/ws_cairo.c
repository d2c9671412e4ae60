/* SPDX-License-Identifier: MIT */
/*
 * ws_cairo.c -- the vector workstations through cairo: PDF (type 110, one page per frame,
 * multi-page), SVG (111, one file per frame), PostScript (112, one page per frame) and EPS
 * (113, one file per frame). Category OUTPUT, class vector; display space A4 portrait
 * (0.210 x 0.297 m), DC unit = metre; the page of a frame is the current workstation
 * viewport. Behaviour: docs/WORKSTATIONS.md.
 *
 * The frame goes through the render layer's view pipeline and renderers (ws_render.h,
 * ws_classic.h) at a resolution of GESC_VEC_RESOLUTION dots per inch (default 300),
 * so that every transformation, clip and HLHSR decision is the PNG workstation's:
 *  - HLHSR none and painter: every primitive retained and written as vectors in the
 *    mode's order (ws_classic_walk): lines with their types and widths, markers, text
 *    as its stroke-font polylines, fill areas (solid, hatch, pattern), cell arrays as
 *    images sampled nearest-neighbour;
 *  - hidden line: the visible runs of the lines and outlines as vector lines (visibility
 *    sampled against the areas' depth buffer at the resolution above);
 *  - z-buffer and ray tracing: the raster picture at the resolution above embedded as an
 *    image (nearest-neighbour), with the overlays (HLHSR identifier != 0) and, in ray
 *    tracing, the annotations the tracer ignores (lines, markers, text) drawn over it as
 *    vectors.
 * Nominal sizes: one nominal unit is VEC_UNIT_M (0.2 mm), the role of one pixel on the
 * PNG workstation: line width 1, marker size 7, dashes 8 on 4 off and hatch spacing 8 such
 * units.
 *
 * Files (ws_file.h): PDF B.pdf and PS B.ps hold all frames as pages; SVG and EPS write
 * frame k to B.svg / B-k.svg (like the PNG frames). A frame is drawn at UPDATE WORKSTATION
 * (and CLEAR and CLOSE WORKSTATION, which update first) when it has new content; SVG/EPS
 * files are (re)written then; a PDF/PS page is kept until the frame ends (CLEAR WORKSTATION
 * or the next frame's first output) and the document is complete at CLOSE WORKSTATION.
 * The creation date in PDF and PS files is fixed (VEC_DATE_*) so that equal programs give
 * equal files.
 */
#include "gks_alloc.h"
#include "gks_font.h"
#include "gks_text_layout.h"
#include "gks_xform.h"
#include "raster.h"
#include "ws_driver.h"
#include "ws_render.h"
#include "ws_file.h"
#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>
#include <cairo.h>
#ifdef GKS_HAVE_FONTCONFIG
#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>
#endif
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define VEC_UNIT_M 0.0002   /* nominal unit: 0.2 mm */
#define VEC_INCH_M 0.0254
#define VEC_PI 3.14159265358979323846
#define VEC_DEFAULT_DPI 300
#define VEC_DATE_PDF "1970-01-01T00:00:00Z"
#define VEC_DATE_PS "Thu Jan  1 00:00:00 1970"
#define VEC_DPI_MIN 10      /* GESC_VEC_RESOLUTION range */
#define VEC_DPI_MAX 2400
#define VEC_EM 32.0         /* stroke-font units per em of the user fonts */
#define VEC_MAX_FACES 64    /* user font faces (font, expansion factor) per workstation */
#define VEC_CLIP_MAX 32     /* points of a text's clip polygon */
/* The largest em of a text drawn as glyphs of a user font, in points (a 1.4 m em: no page
 * shows more than a piece of one character). A larger text is drawn by its strokes:
 * cairo's glyph rendering passes pixman rectangles it rejects ("Invalid rectangle passed")
 * from about 12,000 pt on (issue 40, character heights of 1e5 and more). */
#define VEC_TEXT_MAX_EM_PT 4096.0

typedef enum { VEC_PDF, VEC_SVG, VEC_PS, VEC_EPS } vec_format;

static const char *const vec_ext[] = { ".pdf", ".svg", ".ps", ".eps" };

/* Predefined colours as on the PNG workstation: 0 background white, 1 black, ... */
static const Grgb vec_colours[8] = {
    { 1, 1, 1 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 }, { 1, 0, 1 },
};

typedef struct vec_buf { unsigned char *p; size_t n, cap; int fail; } vec_buf;

/* What a frame's page needs beyond the retained records, taken at UPDATE (the
 * workstation's viewport, colours and mode may change before the frame ends). */
typedef struct vec_snap {
    double w_pt, h_pt;     /* size of the picture in points: the workstation viewport */
    double page_w, page_h; /* size of the page in points (the picture's, or GESC_VEC_PAGE's) */
    cairo_matrix_t place;  /* the picture's points (y down) -> the page's: the identity, or
                              GESC_VEC_PAGE's fit into its rectangle */
    double reg[4];         /* the part of the picture placed (points, y up): x0 y0 x1 y1 */
    int placed;            /* GESC_VEC_PAGE applies */
    int rw, rh;            /* raster size (pixels at the resolution) */
    double pw, ph;         /* page size in those pixels */
    float bg[3];           /* colour 0 */
    int mode;              /* HLHSR mode */
    cairo_surface_t *img;  /* the raster part (z-buffer, ray tracing) or NULL */
} vec_snap;

/* TEXT as text (vec_text): a cairo user font per stroke font and expansion factor draws
 * each glyph once per size and direction (PDF and PS: a Type 3 font, SVG: a <symbol>),
 * as the outline of its strokes with the pen of the stroked text; a text is its glyph
 * positions, the font's direction and size in raster pixels, and a clip polygon. */
typedef struct vec_face {
    int font;
    double expan;
    cairo_font_face_t *face;
} vec_face;

/* STRING and CHAR precision text in a real font (GKS_HAVE_FONTCONFIG): the font
 * fontconfig gives for VEC_TEXT_FAMILY (Debian: fonts-dejavu-core), written as text (PDF:
 * an embedded TrueType subset with its Unicode map, so readers find and select the text).
 * Sized so that its cap height is the stroke font's (21 units), each character centred in
 * the cell the core laid out for the stroke glyph: positions, extents and alignment stay
 * the core's. Opened at the first such text; state -1 = not available (no fontconfig, no
 * font, a printable character without a glyph): the stroke font is used. */
#define VEC_TEXT_FAMILY "DejaVu Sans"
typedef struct vec_real_font {
    int state;                 /* 0 not tried, 1 open, -1 not available */
    cairo_font_face_t *face;
    unsigned long index[95];   /* glyph index of characters 32..126 */
    double advance[95];        /* their advances in em */
    double em_units;           /* stroke-font units per em */
} vec_real_font;

typedef struct vec_text {
    int face;              /* user font face, or -1: the real font (vec_real_font) */
    double expan;          /* the real font's horizontal scale: expansion factor, narrowed
                              so that every glyph fits its stroke glyph's cell */
    double bx[2], by[2];   /* raster pixels per font unit along the glyph's x (without the
                              expansion factor) and y (up) */
    float rgb[3];
    size_t g0, ng;         /* glyphs (x, y in raster pixels) */
    size_t c0, nc;         /* clip polygon (raster pixels), nc = 0: none */
} vec_text;

/* How lines are stroked (ESCAPEs GESC_VEC_LINE_*): cairo's join and cap, the miter limit,
 * and a factor on every line width. */
typedef struct vec_line_style {
    cairo_line_join_t join;
    cairo_line_cap_t cap;
    double miter, scale;
} vec_line_style;

typedef struct vec_ws {
    vec_format fmt;
    char *base;
    int frame;             /* 1-based number of the current frame */
    int dirty;             /* content not yet drawn into the frame's page */
    int frame_written;     /* the current frame has been drawn (file or pending page) */
    int written_any;
    int dpi, next_dpi;     /* resolution of rasterised parts; next_dpi from the next frame */
    vec_line_style line;   /* GESC_VEC_LINE_JOIN, _CAP, _MITER_LIMIT, _LINE_SCALE */
    int page_set;          /* GESC_VEC_PAGE given: page[] = llx, lly, urx, ury, w, h (pt) */
    double page[6];
    ws_classic *vec;       /* retained primitives written as vectors */
    ws_render *r;          /* z-buffer primitives drawn at once into fb (r->classic),
                              areas recorded for ray tracing (r->rt) */
    gks_raster_fb *fb;     /* raster picture of z-buffer / ray tracing */
    int raster_used;       /* fb or rt hold part of the frame */
    vec_snap snap;         /* the frame as of its last UPDATE */
    cairo_surface_t *doc;  /* PDF/PS: the document */
    vec_buf ps;            /* PS: the document's bytes (creation date fixed at CLOSE) */
    int pages;
    int io_error;
    vec_face faces[VEC_MAX_FACES];
    int n_faces;
    vec_real_font real;
    vec_text *texts;       /* the frame's texts, ws_classic_keep_mark ids */
    size_t n_texts, cap_texts;
    cairo_glyph_t *glyphs;
    size_t n_glyphs, cap_glyphs;
    double (*clip)[2];
    size_t n_clip, cap_clip;
} vec_ws;

static double px_per_m(const vec_ws *v)
{
    return v->dpi / VEC_INCH_M;
}

/* Raster size of the current viewport at the resolution (at least 1 x 1). */
static void raster_size(const gks_ws *ws, const vec_ws *v, int *w, int *h)
{
    double s = px_per_m(v);
    double fw = ceil((ws->cur_vp.x_max - ws->cur_vp.x_min) * s - 1e-9);
    double fh = ceil((ws->cur_vp.y_max - ws->cur_vp.y_min) * s - 1e-9);
    *w = fw >= 1 && fw <= 65536 ? (int)fw : fw > 65536 ? 65536 : 1;
    *h = fh >= 1 && fh <= 65536 ? (int)fh : fh > 65536 ? 65536 : 1;
}

static void apply_dpi(vec_ws *v)
{
    v->dpi = v->next_dpi;
    double ppm = px_per_m(v);
    ws_classic_set_scale(v->vec, ppm, VEC_UNIT_M * ppm);
    ws_classic_set_scale(v->r->classic, ppm, VEC_UNIT_M * ppm);
}

static int vec_open_fmt(gks_ws *ws, vec_format fmt)
{
    vec_ws *v = gks_calloc_array(1, sizeof *v);
    if (!v)
        return 300;
    v->fmt = fmt;
    v->base = gks_ws_file_default_base(ws, vec_ext[fmt]);
    v->vec = ws_classic_new(NULL); /* its own list: the vector items */
    v->r = ws_render_new();
    if (!v->base || !v->vec || !v->r) {
        gks_free(v->base);
        ws_classic_free(v->vec);
        ws_render_free(v->r);
        gks_free(v);
        return 300;
    }
    v->frame = 1;
    v->next_dpi = VEC_DEFAULT_DPI;
    v->line = (vec_line_style){ CAIRO_LINE_JOIN_ROUND, CAIRO_LINE_CAP_BUTT, 10.0, 1.0 };
    apply_dpi(v);
    ws->priv = v;
    return 0;
}

static int pdf_open(gks_ws *ws) { return vec_open_fmt(ws, VEC_PDF); }
static int svg_open(gks_ws *ws) { return vec_open_fmt(ws, VEC_SVG); }
static int ps_open(gks_ws *ws) { return vec_open_fmt(ws, VEC_PS); }
static int eps_open(gks_ws *ws) { return vec_open_fmt(ws, VEC_EPS); }

/* --- memory stream of the PS document ------------------------------------------------- */
static cairo_status_t buf_write(void *closure, const unsigned char *data, unsigned int len)
{
    vec_buf *b = closure;
    if (b->fail)
        return CAIRO_STATUS_WRITE_ERROR;
    if (len > SIZE_MAX - b->n || gks_grow(&b->p, &b->cap, b->n + len, 1)) {
        b->fail = 1; /* b->p kept and freed by its owner */
        return CAIRO_STATUS_NO_MEMORY;
    }
    memcpy(b->p + b->n, data, len);
    b->n += len;
    return CAIRO_STATUS_SUCCESS;
}

/* Writes the PS bytes to path with the creation date line replaced by VEC_DATE_PS.
 * Returns 0, 300 or 303. */
static int buf_save_ps(vec_buf *b, const char *path)
{
    if (b->fail)
        return 300;
    static const char key[] = "%%CreationDate: ";
    const unsigned char *p = b->p, *end = b->p + b->n, *line = NULL;
    for (const unsigned char *q = p; q && q + sizeof key - 1 <= end;) {
        if (memcmp(q, key, sizeof key - 1) == 0) {
            line = q;
            break;
        }
        const unsigned char *nl = memchr(q, '\n', (size_t)(end - q));
        q = nl ? nl + 1 : NULL;
        if (q && q - p > 4096) /* the date is in the header */
            break;
    }
    FILE *f = fopen(path, "wb");
    if (!f)
        return 303;
    int ok = 1;
    if (line) {
        const unsigned char *nl = memchr(line, '\n', (size_t)(end - line));
        const unsigned char *rest = nl ? nl + 1 : end;
        ok = fwrite(p, 1, (size_t)(line - p), f) == (size_t)(line - p) &&
             fprintf(f, "%s%s\n", key, VEC_DATE_PS) > 0 &&
             fwrite(rest, 1, (size_t)(end - rest), f) == (size_t)(end - rest);
    } else {
        ok = fwrite(p, 1, b->n, f) == b->n;
    }
    ok &= fclose(f) == 0;
    return ok ? 0 : 303;
}

/* --- drawing items ---------------------------------------------------------------------- */
/* The raster pixels (x right, y up) -> the page's device space (points, y down) of the
 * line and marker paths (vec_draw). */
typedef struct vec_xf { double k, h; } vec_xf;

/* The loops of an item as path: in user space (t NULL), or in device space through t; a
 * loop of negative count continues the previous one (its first point is that one's last). */
static void path_loops(cairo_t *cr, const ws_render_item *it, const vec_xf *t, int closed)
{
    const gks_raster_pt *p = it->pts;
    for (int k = 0; k < it->n_loops; k++) {
        int c = it->counts[k];
        int cont = c < 0;
        if (cont)
            c = -c;
        for (int i = 0; i < c; i++) {
            if (i == 0 && cont)
                continue; /* the previous piece's last point */
            double x = p[i].x, y = p[i].y;
            if (t) {
                x = t->k * p[i].x;
                y = t->h - t->k * p[i].y;
            }
            if (i == 0)
                cairo_move_to(cr, x, y);
            else
                cairo_line_to(cr, x, y);
        }
        if (closed && c > 0)
            cairo_close_path(cr);
        p += c;
    }
}

/* Dashes of the raster module (raster.h) in nominal units times max(1, width). */
/* k: user space units per raster pixel (1 in pixel space, the page's points per pixel in
 * device space, see vec_draw). */
static void set_line(cairo_t *cr, const ws_render_item *it, int type, double width, double k,
                     const vec_line_style *ls)
{
    double w = width > it->unit ? width : it->unit;
    cairo_set_line_width(cr, w * k * ls->scale);
    cairo_set_line_join(cr, ls->join);
    cairo_set_line_cap(cr, ls->cap);
    cairo_set_miter_limit(cr, ls->miter);
    double s = k * it->unit * (w / it->unit > 1.0 ? w / it->unit : 1.0);
    double d[4];
    int n = 0;
    if (type == 2) {
        d[0] = 8 * s; d[1] = 4 * s; n = 2;
    } else if (type == 3) {
        d[0] = 2 * s; d[1] = 4 * s; n = 2;
    } else if (type == 4) {
        d[0] = 8 * s; d[1] = 3 * s; d[2] = 2 * s; d[3] = 3 * s; n = 4;
    }
    cairo_set_dash(cr, d, n, 0.0);
}

static cairo_surface_t *image_of(const float *rgb, int nx, int ny)
{
    cairo_surface_t *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, nx, ny);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        return s;
    cairo_surface_flush(s);
    unsigned char *d = cairo_image_surface_get_data(s);
    int stride = cairo_image_surface_get_stride(s);
    for (int j = 0; j < ny; j++) {
        uint32_t *row = (uint32_t *)(void *)(d + (size_t)j * (size_t)stride);
        for (int i = 0; i < nx; i++) {
            const float *c = rgb + 3 * ((size_t)j * (size_t)nx + (size_t)i);
            uint32_t q[3];
            for (int k = 0; k < 3; k++) {
                float x = c[k] >= 0.0f ? (c[k] <= 1.0f ? c[k] : 1.0f) : 0.0f;
                q[k] = (uint32_t)(x * 255.0f + 0.5f);
            }
            row[i] = 0xff000000u | q[0] << 16 | q[1] << 8 | q[2];
        }
    }
    cairo_surface_mark_dirty(s);
    return s;
}

/* An image (pattern cells, cell array) with the matrix from its pixel space to user space;
 * painted into the current path's even-odd interior. */
static void paint_image(cairo_t *cr, const float *rgb, int nx, int ny, const cairo_matrix_t *m,
                        cairo_extend_t extend)
{
    cairo_matrix_t inv = *m;
    if (cairo_matrix_invert(&inv) != CAIRO_STATUS_SUCCESS) {
        cairo_new_path(cr);
        return;
    }
    cairo_surface_t *img = image_of(rgb, nx, ny);
    cairo_pattern_t *pat = cairo_pattern_create_for_surface(img);
    cairo_pattern_set_matrix(pat, &inv);
    cairo_pattern_set_filter(pat, CAIRO_FILTER_NEAREST);
    cairo_pattern_set_extend(pat, extend);
    cairo_set_source(cr, pat);
    cairo_fill(cr);
    cairo_pattern_destroy(pat);
    cairo_surface_destroy(img);
}

/* Hatch lines of the raster module: the pixel rows / columns / diagonals k * spacing in
 * nominal units, one unit wide, through the units' centres, inside the current path. */
static void hatch(cairo_t *cr, const ws_render_item *it)
{
    int k = -it->hatch, kind = (k - 1) % 6 + 1;
    double u = it->unit, s = (k <= 6 ? GKS_RASTER_HATCH_SPACING : GKS_RASTER_HATCH_SPACING / 2);
    double x0, y0, x1, y1;
    cairo_save(cr);
    cairo_clip(cr);
    cairo_clip_extents(cr, &x0, &y0, &x1, &y1);
    x0 /= u; y0 /= u; x1 /= u; y1 /= u;
    cairo_scale(cr, u, u); /* nominal units from here */
    int hor = kind == 1 || kind == 5, ver = kind == 2 || kind == 5;
    int up = kind == 3 || kind == 6, down = kind == 4 || kind == 6;
    if (hor)
        for (double y = floor(y0 / s) * s; y <= y1; y += s) {
            cairo_move_to(cr, x0 - 1, y + 0.5);
            cairo_line_to(cr, x1 + 1, y + 0.5);
        }
    if (ver)
        for (double x = floor(x0 / s) * s; x <= x1; x += s) {
            cairo_move_to(cr, x + 0.5, y0 - 1);
            cairo_line_to(cr, x + 0.5, y1 + 1);
        }
    cairo_set_line_width(cr, 1.0);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    cairo_stroke(cr);
    /* diagonals x - y = c (up) and x + y = c + 1 (down), c a multiple of s; the raster's
     * staircase is 1 unit wide horizontally, 1/sqrt(2) across */
    double h = y1 - y0 + 2;
    if (up)
        for (double c = floor((x0 - y1 - 1) / s) * s; c <= x1 - y0 + 1; c += s) {
            cairo_move_to(cr, c + y0 - 1, y0 - 1);
            cairo_line_to(cr, c + y0 - 1 + h, y0 - 1 + h);
        }
    if (down)
        for (double c = floor((x0 + y0 - 2) / s) * s; c <= x1 + y1 + 1; c += s) {
            cairo_move_to(cr, c + 1 - (y0 - 1), y0 - 1);
            cairo_line_to(cr, c + 1 - (y0 - 1) - h, y0 - 1 + h);
        }
    cairo_set_line_width(cr, sqrt(0.5));
    cairo_stroke(cr);
    cairo_restore(cr);
}

/* The markers of an item as path in device space (type 1, the dot: filled discs; the
 * others: strokes). */
static void markers(cairo_t *cr, const ws_render_item *it, const vec_xf *t)
{
    const gks_raster_pt *p = it->pts;
    double k = t->k, h = t->h;
    double r = 0.5 * it->marker_size * k, d = r * sqrt(0.5), dot = 0.5 * it->unit * k;
    for (int j = 0; j < it->n_loops; j++)
        for (int i = 0; i < it->counts[j]; i++, p++) {
            double x = k * p->x, y = h - k * p->y;
            if (it->marker_type == 1) { /* the smallest dot: one nominal unit */
                cairo_new_sub_path(cr);
                cairo_arc(cr, x, y, dot, 0, 2 * VEC_PI);
                continue;
            }
            if (it->marker_type == 4) {
                cairo_new_sub_path(cr);
                cairo_arc(cr, x, y, r, 0, 2 * VEC_PI);
                continue;
            }
            if (it->marker_type == 2 || it->marker_type == 3) {
                cairo_move_to(cr, x - r, y);
                cairo_line_to(cr, x + r, y);
                cairo_move_to(cr, x, y - r);
                cairo_line_to(cr, x, y + r);
            }
            if (it->marker_type == 3 || it->marker_type == 5) {
                cairo_move_to(cr, x - d, y - d);
                cairo_line_to(cr, x + d, y + d);
                cairo_move_to(cr, x - d, y + d);
                cairo_line_to(cr, x + d, y - d);
            }
        }
}

/* --- TEXT as text: the user fonts -------------------------------------------------------- */
/* The pen of the stroked text: one nominal unit (the PNG workstation's 1-pixel text
 * strokes), in points. */
#define VEC_PEN_PT (VEC_UNIT_M * 72.0 / VEC_INCH_M)

static const cairo_user_data_key_t vec_face_key;

/* The glyph of ch in stroke font font (gks_font.h: unknown numbers draw as font 1). */
static void glyph_of(int font, int ch, gks_glyph *g)
{
    gks_font_get_glyph(font, ch, g);
}

/* A segment of a stroke as a quadrilateral, counter-clockwise (x right, y up) like
 * cairo_arc, so that with the winding rule the pieces of a glyph add up. */
static void pen_quad(cairo_t *cr, double x0, double y0, double x1, double y1, double hw)
{
    double dx = x1 - x0, dy = y1 - y0, l = hypot(dx, dy);
    if (!(l > 0))
        return;
    double nx = -dy / l * hw, ny = dx / l * hw;
    cairo_move_to(cr, x0 - nx, y0 - ny);
    cairo_line_to(cr, x1 - nx, y1 - ny);
    cairo_line_to(cr, x1 + nx, y1 + ny);
    cairo_line_to(cr, x0 + nx, y0 + ny);
    cairo_close_path(cr);
}

/* The glyph in em units (glyph space, y down): its strokes filled as the stroked text
 * draws them (vec_item: solid, butt caps, round joins) with the pen, whose width in em
 * follows from the scaled font's matrix to the page (points). */
static cairo_status_t glyph_render(cairo_scaled_font_t *sf, unsigned long glyph, cairo_t *cr,
                                   cairo_text_extents_t *ext)
{
    const vec_face *f = cairo_font_face_get_user_data(cairo_scaled_font_get_font_face(sf),
                                                      &vec_face_key);
    if (!f || glyph < 32 || glyph > 126)
        return CAIRO_STATUS_USER_FONT_ERROR;
    gks_glyph g;
    glyph_of(f->font, (int)glyph, &g);
    cairo_matrix_t fm, ctm;
    cairo_scaled_font_get_font_matrix(sf, &fm);
    cairo_scaled_font_get_ctm(sf, &ctm);
    cairo_matrix_multiply(&fm, &fm, &ctm);
    double s = sqrt(fabs(fm.xx * fm.yy - fm.xy * fm.yx)); /* points per em */
    if (!(s > 0) || !isfinite(s))
        return CAIRO_STATUS_USER_FONT_ERROR;
    double hw = 0.5 * VEC_PEN_PT / s, ex = f->expan / VEC_EM, ey = -1.0 / VEC_EM;
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    int off = 0;
    for (int k = 0; k < g.n_strokes && k < GKS_GLYPH_MAX_STROKES; k++) {
        int len = g.stroke_len[k];
        if (len < 0 || off + len > g.n_points || off + len > GKS_GLYPH_MAX_POINTS)
            break;
        const double *p = g.xy + 2 * off;
        for (int j = 0; j + 1 < len && len >= 2; j++)
            pen_quad(cr, p[2 * j] * ex, p[2 * j + 1] * ey, p[2 * j + 2] * ex,
                     p[2 * j + 3] * ey, hw);
        for (int j = 1; j + 1 < len; j++) { /* round joins */
            cairo_new_sub_path(cr);
            cairo_arc(cr, p[2 * j] * ex, p[2 * j + 1] * ey, hw, 0, 2 * VEC_PI);
        }
        off += len;
    }
    cairo_fill(cr);
    ext->x_advance = g.advance * ex;
    ext->y_advance = 0;
    return cairo_status(cr);
}

/* The face of (font, expan), made at first use; -1 when the table is full. */
static int face_index(vec_ws *v, int font, double expan)
{
    for (int i = 0; i < v->n_faces; i++)
        if (v->faces[i].font == font && v->faces[i].expan == expan)
            return i;
    if (v->n_faces == VEC_MAX_FACES)
        return -1;
    vec_face *d = gks_alloc_array(1, sizeof *d);
    cairo_font_face_t *f = cairo_user_font_face_create();
    if (!d || cairo_font_face_status(f) != CAIRO_STATUS_SUCCESS) {
        gks_free(d);
        cairo_font_face_destroy(f);
        return -1;
    }
    *d = (vec_face){ font, expan, NULL };
    cairo_user_font_face_set_render_glyph_func(f, glyph_render);
    if (cairo_font_face_set_user_data(f, &vec_face_key, d, gks_free) != CAIRO_STATUS_SUCCESS) {
        gks_free(d);
        cairo_font_face_destroy(f);
        return -1;
    }
    v->faces[v->n_faces] = (vec_face){ font, expan, f };
    return v->n_faces++;
}

/* The real font (vec_real_font), opened at first use; 0 when available. */
static int real_font(vec_ws *v)
{
    vec_real_font *r = &v->real;
    if (r->state)
        return r->state > 0 ? 0 : -1;
    r->state = -1;
#ifdef GKS_HAVE_FONTCONFIG
    /* A configuration of our own, destroyed after the match: fontconfig's default one
     * (FcConfigGetCurrent) is never freed and would stay with the process (LeakSanitizer
     * reports it); the face made from the matched pattern needs no configuration. */
    FcConfig *cfg = FcInitLoadConfigAndFonts();
    FcPattern *pat = cfg ? FcNameParse((const FcChar8 *)VEC_TEXT_FAMILY) : NULL;
    if (!pat) {
        if (cfg)
            FcConfigDestroy(cfg);
        return -1;
    }
    FcConfigSubstitute(cfg, pat, FcMatchPattern);
    FcDefaultSubstitute(pat);
    FcResult res;
    FcPattern *match = FcFontMatch(cfg, pat, &res);
    FcPatternDestroy(pat);
    FcConfigDestroy(cfg);
    FcChar8 *file = NULL; /* a font file: the outline font cairo embeds */
    if (!match || FcPatternGetString(match, FC_FILE, 0, &file) != FcResultMatch || !file) {
        if (match)
            FcPatternDestroy(match);
        return -1;
    }
    cairo_font_face_t *f = cairo_ft_font_face_create_for_pattern(match);
    FcPatternDestroy(match); /* the face holds its own reference */
    cairo_matrix_t em, id;
    cairo_matrix_init_identity(&em);
    cairo_matrix_init_identity(&id);
    cairo_font_options_t *o = cairo_font_options_create();
    cairo_font_options_set_hint_metrics(o, CAIRO_HINT_METRICS_OFF); /* outline metrics */
    cairo_font_options_set_hint_style(o, CAIRO_HINT_STYLE_NONE);
    cairo_scaled_font_t *sf = cairo_scaled_font_create(f, &em, &id, o);
    cairo_font_options_destroy(o);
    int ok = cairo_scaled_font_status(sf) == CAIRO_STATUS_SUCCESS;
    double cap = 0;
    for (int c = 32; c <= 126 && ok; c++) {
        char s[2] = { (char)c, 0 };
        cairo_glyph_t *g = NULL;
        int n = 0;
        if (cairo_scaled_font_text_to_glyphs(sf, 0, 0, s, 1, &g, &n, NULL, NULL, NULL) !=
                CAIRO_STATUS_SUCCESS || n != 1 || (g[0].index == 0 && c != ' ')) {
            ok = 0; /* a character without a glyph: the font does not serve */
        } else {
            cairo_text_extents_t e;
            cairo_scaled_font_glyph_extents(sf, g, 1, &e);
            r->index[c - 32] = g[0].index;
            r->advance[c - 32] = e.x_advance;
            if (c == 'H')
                cap = -e.y_bearing;
        }
        cairo_glyph_free(g);
    }
    cairo_scaled_font_destroy(sf);
    gks_font_metrics fm;
    gks_font_get_metrics(1, &fm);
    if (!ok || !(cap > 0.3 && cap < 1.5)) {
        cairo_font_face_destroy(f);
        return -1;
    }
    r->face = f;
    r->em_units = fm.cap / cap;
    r->state = 1;
    return 0;
#else
    (void)v;
    return -1;
#endif
}

/* The drawing of a page. Consecutive line items, and consecutive marker items, with equal
 * attributes are drawn as one path with one stroke (dots: one fill): text arrives as one
 * item per stroke of the font and hidden-line output as one item per visible run, and an
 * operation per item costs cairo a graphics state and the file an operator each (SVG a
 * <path> element with its whole style), which made 10^5-primitive plots slow
 * (docs/bench/vector.md). The colours are opaque, so one operation on the union paints
 * what the operations one after another paint; the dash pattern restarts at every
 * subpath, as it did at every item. Areas are not merged: their even-odd interiors would
 * cancel where two overlap.
 * Lines and markers are drawn in the page's device space (identity matrix, coordinates
 * transformed here): in a scaled and flipped user space cairo transforms every point to
 * device space and back, and PDF wraps every stroke in a matrix of its own. Areas, cell
 * arrays and hatches are drawn in raster pixels (the matrix pix). */
typedef struct vec_draw {
    cairo_t *cr;
    cairo_matrix_t place;  /* the picture's points -> the page's (vec_snap) */
    cairo_matrix_t pix;    /* raster pixels, y up -> device space */
    vec_xf xf;             /* the same for the line and marker paths */
    int device;            /* the current matrix is the identity (else pix) */
    int open;              /* a path is pending for the attributes below */
    ws_item_kind kind;     /* WS_ITEM_LINE or WS_ITEM_MARKERS */
    float rgb[3];
    int linetype, marker_type;
    double width, unit;
    const vec_ws *v;       /* the texts (WS_ITEM_MARK) */
    cairo_glyph_t *tmp;    /* a text's glyphs in device space */
    size_t cap_tmp;
    char *utf8;            /* its characters (real font) */
    size_t cap_utf8;
    cairo_text_cluster_t *clusters; /* one character, one glyph */
    size_t cap_clusters;
} vec_draw;

static void vec_flush(vec_draw *d)
{
    if (!d->open)
        return;
    if (d->kind == WS_ITEM_MARKERS && d->marker_type == 1) {
        cairo_set_fill_rule(d->cr, CAIRO_FILL_RULE_WINDING); /* discs may overlap */
        cairo_fill(d->cr);
    } else {
        cairo_stroke(d->cr);
    }
    d->open = 0;
}

/* Starts the pending path for it, unless the open one has its attributes. */
static void vec_group(vec_draw *d, const ws_render_item *it, int linetype, int marker_type)
{
    if (d->open && d->kind == it->kind && d->linetype == linetype &&
        d->marker_type == marker_type && d->width == it->width && d->unit == it->unit &&
        memcmp(d->rgb, it->rgb, sizeof d->rgb) == 0)
        return;
    vec_flush(d);
    if (!d->device) {
        cairo_set_matrix(d->cr, &d->place);
        d->device = 1;
    }
    cairo_set_source_rgb(d->cr, it->rgb[0], it->rgb[1], it->rgb[2]);
    set_line(d->cr, it, linetype, it->width, d->xf.k, &d->v->line);
    d->open = 1;
    d->kind = it->kind;
    memcpy(d->rgb, it->rgb, sizeof d->rgb);
    d->linetype = linetype;
    d->marker_type = marker_type;
    d->width = it->width;
    d->unit = it->unit;
}

/* Text i of the frame (vec_text) in device space: its glyphs with the font matrix from
 * em to the page, inside its clip polygon. */
static int text_draw(vec_draw *d, size_t i)
{
    const vec_ws *v = d->v;
    if (i >= v->n_texts)
        return 0;
    const vec_text *t = &v->texts[i];
    cairo_t *cr = d->cr;
    double k = d->xf.k, h = d->xf.h, s = VEC_EM * k;
    if (!d->device) {
        cairo_set_matrix(cr, &d->place);
        d->device = 1;
    }
    if (t->nc) {
        cairo_save(cr);
        for (size_t j = 0; j < t->nc; j++) {
            const double *p = v->clip[t->c0 + j];
            if (j == 0)
                cairo_move_to(cr, k * p[0], h - k * p[1]);
            else
                cairo_line_to(cr, k * p[0], h - k * p[1]);
        }
        cairo_close_path(cr);
        cairo_clip(cr);
    }
    cairo_matrix_t fm;
    const int real = t->face < 0;
    if (real) { /* em -> page: em_units font units, the expansion factor along x */
        double sr = v->real.em_units * k, e = t->expan;
        cairo_matrix_init(&fm, sr * e * t->bx[0], -sr * e * t->bx[1], -sr * t->by[0],
                          sr * t->by[1], 0, 0);
        cairo_set_font_face(cr, v->real.face);
    } else {
        cairo_matrix_init(&fm, s * t->bx[0], -s * t->bx[1], -s * t->by[0], s * t->by[1], 0, 0);
        cairo_set_font_face(cr, v->faces[t->face].face);
    }
    cairo_set_font_matrix(cr, &fm);
    cairo_set_source_rgb(cr, t->rgb[0], t->rgb[1], t->rgb[2]);
    if (gks_grow(&d->tmp, &d->cap_tmp, t->ng, sizeof *d->tmp) ||
        gks_grow(&d->utf8, &d->cap_utf8, t->ng + 1, 1) ||
        gks_grow(&d->clusters, &d->cap_clusters, t->ng, sizeof *d->clusters))
        return 300;
    const cairo_glyph_t *g = v->glyphs + t->g0;
    for (size_t j = 0; j < t->ng; j++) { /* pixels -> device */
        unsigned long ch = g[j].index; /* the character (32..126) */
        d->tmp[j] = (cairo_glyph_t){ real ? v->real.index[ch - 32] : ch, k * g[j].x,
                                     h - k * g[j].y };
        d->utf8[j] = (char)ch;
        d->clusters[j] = (cairo_text_cluster_t){ 1, 1 };
    }
    d->utf8[t->ng] = '\0';
    if (real) /* the text with its glyphs: readers map the glyphs back to the characters */
        cairo_show_text_glyphs(cr, d->utf8, (int)t->ng, d->tmp, (int)t->ng, d->clusters,
                               (int)t->ng, 0);
    else
        cairo_show_glyphs(cr, d->tmp, (int)t->ng);
    if (t->nc)
        cairo_restore(cr);
    return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : 300;
}

static int vec_item(void *ctx, const ws_render_item *it)
{
    vec_draw *d = ctx;
    cairo_t *cr = d->cr;
    switch (it->kind) {
    case WS_ITEM_LINE:
        vec_group(d, it, it->linetype, 0);
        path_loops(cr, it, &d->xf, 0);
        return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : 300;
    case WS_ITEM_MARKERS:
        vec_group(d, it, 1, it->marker_type);
        markers(cr, it, &d->xf);
        return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : 300;
    default:
        break;
    }
    vec_flush(d);
    if (it->kind == WS_ITEM_MARK)
        return text_draw(d, it->mark);
    if (d->device) {
        cairo_set_matrix(cr, &d->pix);
        d->device = 0;
    }
    switch (it->kind) {
    case WS_ITEM_AREA:
        cairo_set_source_rgb(cr, it->rgb[0], it->rgb[1], it->rgb[2]);
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
        path_loops(cr, it, NULL, 1);
        if (it->style == GKS_RASTER_HATCH) {
            hatch(cr, it);
        } else if (it->style == GKS_RASTER_PATTERN) {
            const double *g = it->pat_geo; /* reference point, cell width, cell height */
            cairo_matrix_t m;
            cairo_matrix_init(&m, g[2], g[3], g[4], g[5], g[0], g[1]);
            paint_image(cr, it->rgb_list, it->nx, it->ny, &m, CAIRO_EXTEND_REPEAT);
        } else {
            cairo_fill(cr);
        }
        break;
    case WS_ITEM_CELLS: {
        cairo_set_source_rgb(cr, it->rgb[0], it->rgb[1], it->rgb[2]);
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
        path_loops(cr, it, NULL, 1);
        const gks_raster_pt *o = &it->cell_o, *u = &it->cell_u, *w = &it->cell_v;
        cairo_matrix_t m;
        cairo_matrix_init(&m, (u->x - o->x) / it->nx, (u->y - o->y) / it->nx,
                          (w->x - o->x) / it->ny, (w->y - o->y) / it->ny, o->x, o->y);
        /* PAD keeps the edge cells' colour up to the clipped boundary; cairo 1.16's
         * PostScript surface pads such an image by an amount that varies from run to run
         * (plot2d.eps: 2 different files in 8 runs of one binary), so PS and EPS take
         * the image unpadded (the loops lie inside it: only edge anti-aliasing differs) */
        paint_image(cr, it->rgb_list, it->nx, it->ny, &m,
                    d->v->fmt == VEC_PS || d->v->fmt == VEC_EPS ? CAIRO_EXTEND_NONE
                                                                : CAIRO_EXTEND_PAD);
        break;
    }
    default:
        break;
    }
    return cairo_status(cr) == CAIRO_STATUS_SUCCESS ? 0 : 300;
}

/* The raster part of the frame (z-buffer, ray tracing) as an image; NULL + 300 on
 * storage overflow. */
static int raster_image(gks_ws *ws, vec_ws *v, cairo_surface_t **out)
{
    *out = NULL;
    double wsm[4][4];
    /* NPC3 -> raster pixels and depth: the ray tracer's wsm, as ws_png.c's */
    if (ws_rt_count(v->r->rt) > 0 && gks_ws_pixel_matrix(ws, px_per_m(v), wsm) == 0) {
        int e = ws_rt_render(v->r->rt, ws, (const double (*)[4])wsm, v->fb);
        if (e)
            return e;
        ws_rt_reset(v->r->rt); /* traced into fb once: later updates keep the picture */
    }
    gks_raster_fb *pic;
    if (ws_classic_compose_base(v->r->classic, ws, v->fb, &pic))
        return 300;
    cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_RGB24, pic->width,
                                                      pic->height);
    unsigned char *row8 = gks_alloc_array((size_t)pic->width, 3);
    if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS || !row8) {
        cairo_surface_destroy(img);
        gks_free(row8);
        return 300;
    }
    cairo_surface_flush(img);
    unsigned char *d = cairo_image_surface_get_data(img);
    int stride = cairo_image_surface_get_stride(img);
    for (int j = 0; j < pic->height; j++) {
        gks_raster_fb_resolve_row(pic, j, row8);
        uint32_t *row = (uint32_t *)(void *)(d + (size_t)j * (size_t)stride);
        for (int i = 0; i < pic->width; i++)
            row[i] = 0xff000000u | (uint32_t)row8[3 * i] << 16 |
                     (uint32_t)row8[3 * i + 1] << 8 | row8[3 * i + 2];
    }
    gks_free(row8);
    cairo_surface_mark_dirty(img);
    *out = img;
    return 0;
}

/* The page of the snapshot s: the picture itself, or (GESC_VEC_PAGE) a page of its own
 * size with the picture fitted into the rectangle, its aspect kept, centred. The picture
 * placed is what the workstation window maps to (the viewport's part the workstation
 * transformation fills, s->reg), clipped to it. */
static void page_place(const gks_ws *ws, const vec_ws *v, vec_snap *s)
{
    cairo_matrix_init_identity(&s->place);
    s->page_w = s->w_pt;
    s->page_h = s->h_pt;
    s->reg[0] = s->reg[1] = 0;
    s->reg[2] = s->w_pt;
    s->reg[3] = s->h_pt;
    s->placed = v->page_set;
    if (!v->page_set)
        return;
    double m[4][4];
    if (gks_ws_pixel_matrix(ws, 72.0 / VEC_INCH_M, m) == 0) {
        const Glimit3 *w = &ws->cur_win;
        double x0 = m[0][0] * w->x_min + m[0][3], x1 = m[0][0] * w->x_max + m[0][3];
        double y0 = m[1][1] * w->y_min + m[1][3], y1 = m[1][1] * w->y_max + m[1][3];
        if (x1 - x0 > 1e-9 && y1 - y0 > 1e-9) {
            s->reg[0] = x0;
            s->reg[1] = y0;
            s->reg[2] = x1;
            s->reg[3] = y1;
        }
    }
    const double *p = v->page; /* llx, lly, urx, ury, page width, height (points, y up) */
    double rw = p[2] - p[0], rh = p[3] - p[1];
    double gw = s->reg[2] - s->reg[0], gh = s->reg[3] - s->reg[1];
    double f = rw / gw < rh / gh ? rw / gw : rh / gh;
    s->page_w = p[4];
    s->page_h = p[5];
    /* picture points (y down from its top) -> page points (y down from the page's top) */
    cairo_matrix_init(&s->place, f, 0, 0, f, p[0] + 0.5 * (rw - f * gw) - f * s->reg[0],
                      p[5] - p[1] - 0.5 * (rh - f * gh) - f * (s->h_pt - s->reg[1]));
}

/* The frame's snapshot at UPDATE. */
static int snap_take(gks_ws *ws, vec_ws *v)
{
    vec_snap *s = &v->snap;
    cairo_surface_t *img = NULL;
    if (v->raster_used && v->fb) {
        int e = raster_image(ws, v, &img);
        if (e)
            return e;
    }
    if (s->img)
        cairo_surface_destroy(s->img);
    s->img = img;
    double k = 72.0 / VEC_INCH_M, vw = ws->cur_vp.x_max - ws->cur_vp.x_min,
           vh = ws->cur_vp.y_max - ws->cur_vp.y_min;
    s->w_pt = vw * k >= 1.0 ? vw * k : 1.0;
    s->h_pt = vh * k >= 1.0 ? vh * k : 1.0;
    s->pw = s->w_pt * v->dpi / 72.0;
    s->ph = s->h_pt * v->dpi / 72.0;
    page_place(ws, v, s);
    raster_size(ws, v, &s->rw, &s->rh);
    s->bg[0] = (float)ws->colr[0].red;
    s->bg[1] = (float)ws->colr[0].green;
    s->bg[2] = (float)ws->colr[0].blue;
    s->mode = ws->hlhsr_mode;
    return 0;
}

/* The frame onto a page (snapshot and retained records); cr: a fresh context of a page of
 * the snapshot's size. User space: raster pixels, y up. */
static int draw_frame(vec_ws *v, cairo_t *cr)
{
    const vec_snap *s = &v->snap;
    double k = 72.0 / v->dpi;
    cairo_set_matrix(cr, &s->place);
    if (s->placed) { /* only what the workstation window maps to */
        cairo_rectangle(cr, s->reg[0], s->h_pt - s->reg[3], s->reg[2] - s->reg[0],
                        s->reg[3] - s->reg[1]);
        cairo_clip(cr);
    }
    cairo_translate(cr, 0, s->h_pt);
    cairo_scale(cr, k, -k);
    cairo_set_source_rgb(cr, s->bg[0], s->bg[1], s->bg[2]);
    cairo_rectangle(cr, 0, 0, s->pw, s->ph);
    cairo_fill(cr);
    if (s->img) {
        /* user (pixels, y up) -> image (row 0 at the top), fitted to the page exactly
         * (its last row and column reach beyond the page by less than a pixel: scaled by at
         * most half a pixel over the page, so readers that snap images to their pixel grid
         * keep it in place) */
        int iw = cairo_image_surface_get_width(s->img);
        int ih = cairo_image_surface_get_height(s->img);
        cairo_pattern_t *pat = cairo_pattern_create_for_surface(s->img);
        cairo_matrix_t m;
        cairo_matrix_init(&m, iw / s->pw, 0, 0, -ih / s->ph, 0, ih);
        cairo_pattern_set_matrix(pat, &m);
        cairo_pattern_set_filter(pat, CAIRO_FILTER_NEAREST);
        cairo_set_source(cr, pat);
        cairo_rectangle(cr, 0, 0, s->pw, s->ph);
        cairo_fill(cr);
        cairo_pattern_destroy(pat);
    }
    vec_draw d = { .cr = cr, .place = s->place, .xf = { k, s->h_pt }, .v = v };
    cairo_get_matrix(cr, &d.pix);
    cairo_font_options_t *fo = cairo_font_options_create(); /* glyphs where they are put */
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    int e = ws_classic_walk(v->vec, s->mode, s->rw, s->rh, vec_item, &d);
    vec_flush(&d);
    if (!e)
        e = ws_classic_walk(v->r->classic, s->mode, s->rw, s->rh, vec_item, &d); /* overlays */
    vec_flush(&d);
    gks_free(d.tmp);
    gks_free(d.utf8);
    gks_free(d.clusters);
    if (!e && cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        e = 300;
    return e;
}

/* The PDF / PS document, created at its first page. */
static int doc_open(vec_ws *v, double w, double h)
{
    if (v->doc)
        return 0;
    if (v->fmt == VEC_PDF) {
        char *path = gks_ws_file_frame(v->base, 1, vec_ext[v->fmt]);
        if (!path)
            return 300;
        v->doc = cairo_pdf_surface_create(path, w, h);
        gks_free(path);
        cairo_pdf_surface_set_metadata(v->doc, CAIRO_PDF_METADATA_CREATOR, "gks3d");
        cairo_pdf_surface_set_metadata(v->doc, CAIRO_PDF_METADATA_CREATE_DATE, VEC_DATE_PDF);
    } else {
        v->doc = cairo_ps_surface_create_for_stream(buf_write, &v->ps, w, h);
    }
    if (cairo_surface_status(v->doc) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(v->doc);
        v->doc = NULL;
        return 303;
    }
    return 0;
}

/* PDF / PS: the frame, as of its last UPDATE, as the document's next page. */
static int page_emit(vec_ws *v)
{
    const vec_snap *s = &v->snap;
    int e = doc_open(v, s->page_w, s->page_h);
    if (e)
        return e;
    if (v->fmt == VEC_PDF)
        cairo_pdf_surface_set_size(v->doc, s->page_w, s->page_h);
    else
        cairo_ps_surface_set_size(v->doc, s->page_w, s->page_h);
    cairo_t *cr = cairo_create(v->doc);
    e = draw_frame(v, cr);
    cairo_show_page(cr);
    if (!e && cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        e = 303;
    cairo_destroy(cr);
    v->pages++;
    return e;
}

/* SVG / EPS: the frame's file. */
static int file_write(gks_ws *ws, vec_ws *v)
{
    double w = v->snap.page_w, h = v->snap.page_h;
    char *path;
    /* a later frame's name may be another workstation's file: 21, nothing written */
    int c = gks_ws_file_claim_frame(ws, v->base, v->frame, vec_ext[v->fmt], &path);
    if (c)
        return c;
    errno = 0; /* the reason of a failed write below, if the system gives one */
    cairo_surface_t *s;
    vec_buf b = { 0 };
    if (v->fmt == VEC_SVG) {
        s = cairo_svg_surface_create(path, w, h);
        cairo_svg_surface_restrict_to_version(s, CAIRO_SVG_VERSION_1_1);
    } else {
        s = cairo_ps_surface_create_for_stream(buf_write, &b, w, h);
        cairo_ps_surface_set_eps(s, 1);
    }
    int e = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS ? 0 : 303;
    if (!e) {
        cairo_t *cr = cairo_create(s);
        e = draw_frame(v, cr);
        cairo_show_page(cr);
        cairo_destroy(cr);
        cairo_surface_finish(s);
        if (!e && cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
            e = 303;
    }
    cairo_surface_destroy(s);
    if (!e && v->fmt == VEC_EPS)
        e = buf_save_ps(&b, path);
    if (e == 303)
        gks_ws_note(ws, "cannot write \"%s\": %s", path, errno ? strerror(errno) : "write failed");
    gks_free(b.p);
    gks_free(path);
    return e;
}

static int vec_update(gks_ws *ws)
{
    vec_ws *v = ws->priv;
    if (!v->dirty && v->written_any)
        return 0;
    int e = snap_take(ws, v);
    if (!e && (v->fmt == VEC_SVG || v->fmt == VEC_EPS))
        e = file_write(ws, v);
    if (e)
        return e;
    v->dirty = 0;
    v->written_any = 1;
    v->frame_written = 1;
    return 0;
}

/* The raster framebuffer of z-buffer / ray tracing for the current viewport. */
static gks_raster_fb *framebuffer(gks_ws *ws, vec_ws *v)
{
    int w, h;
    raster_size(ws, v, &w, &h);
    if (v->fb && v->fb->width == w && v->fb->height == h)
        return v->fb;
    gks_raster_fb_free(v->fb);
    v->fb = gks_raster_fb_create(w, h, 1);
    if (v->fb) {
        float bg[3] = { (float)ws->colr[0].red, (float)ws->colr[0].green,
                        (float)ws->colr[0].blue };
        gks_raster_fb_clear(v->fb, bg);
    }
    return v->fb;
}

static int vec_clear(gks_ws *ws)
{
    vec_ws *v = ws->priv;
    int e = 0;
    if (v->frame_written) {
        if (v->fmt == VEC_PDF || v->fmt == VEC_PS)
            e = page_emit(v);
        v->frame++;
        v->frame_written = 0;
    }
    v->dirty = 0;
    v->raster_used = 0;
    ws_render_reset(v->r);
    ws_classic_reset(v->vec);
    v->n_texts = v->n_glyphs = v->n_clip = 0;
    if (v->next_dpi != v->dpi)
        apply_dpi(v);
    gks_raster_fb_free(v->fb);
    v->fb = NULL;
    return e;
}

/* Ends the PDF or PS document: its last page, cairo's finish (the PDF's trailer written
 * and its file closed) and the PS file written from memory. 0, 300 or 303. Once only: the
 * document is gone afterwards. */
static int vec_end_document(vec_ws *v)
{
    int e = 0;
    if (v->frame_written && (v->fmt == VEC_PDF || v->fmt == VEC_PS))
        e = page_emit(v);
    v->frame_written = 0;
    if (v->doc) {
        cairo_surface_finish(v->doc);
        if (cairo_surface_status(v->doc) != CAIRO_STATUS_SUCCESS)
            e = 303;
        cairo_surface_destroy(v->doc);
        v->doc = NULL;
        if (!e && v->fmt == VEC_PS) {
            char *path = gks_ws_file_frame(v->base, 1, vec_ext[v->fmt]);
            e = path ? buf_save_ps(&v->ps, path) : 300;
            gks_free(path);
        }
    }
    return e;
}

/* .finish of CLOSE WORKSTATION: the document's writes are reported (issue 40 H: a full
 * disk cut the PDF and lost the PS with only a line on standard error). A failure of
 * storage is a failed write too: the document is lost either way. */
static int vec_finish(gks_ws *ws)
{
    vec_ws *v = ws->priv;
    errno = 0; /* the reason of a failed write, if the system gives one */
    int e = vec_end_document(v);
    if (e) {
        char *path = gks_ws_file_frame(v->base, 1, vec_ext[v->fmt]);
        const char *name = path ? path : v->base;
        if (e == 300)
            gks_ws_note(ws, "no storage left to write \"%s\"", name);
        else
            gks_ws_note(ws, "cannot write \"%s\": %s", name,
                        errno ? strerror(errno) : "write failed");
        gks_free(path);
    }
    return e ? 303 : 0;
}

static void vec_close(gks_ws *ws)
{
    vec_ws *v = ws->priv;
    /* EMERGENCY CLOSE GKS (no finish): end what can be ended; no error path is left */
    int e = vec_end_document(v);
    if (e)
        fprintf(stderr, "gks3d: workstation %d: error %d writing %s%s\n", ws->id, e, v->base,
                vec_ext[v->fmt]);
    gks_free(v->ps.p);
    if (v->snap.img)
        cairo_surface_destroy(v->snap.img);
    gks_raster_fb_free(v->fb);
    ws_render_free(v->r);
    ws_classic_free(v->vec);
    for (int i = 0; i < v->n_faces; i++)
        cairo_font_face_destroy(v->faces[i].face);
    if (v->real.face)
        cairo_font_face_destroy(v->real.face);
    gks_free(v->texts);
    gks_free(v->glyphs);
    gks_free(v->clip);
    gks_free(v->base);
    gks_free(v);
    ws->priv = NULL;
}

static int vec_primitive(gks_ws *ws, const gks_prim *prim)
{
    vec_ws *v = ws->priv;
    /* The document's own choice: what the render layer traces (ws_render_route) and the
     * z-buffer's primitives go into the raster picture fb; everything else is kept and
     * written as vectors. */
    int raster = ws_render_route(ws, prim) == WS_ROUTE_TRACE ||
                 (ws->hlhsr_mode == GHLHSR_ZBUFFER && prim->attrs.hlhsr_id == 0);
    int e;
    if (raster) {
        gks_raster_fb *fb = framebuffer(ws, v);
        if (!fb)
            return 300;
        e = ws_render_prim(v->r, ws, fb, prim);
        v->raster_used |= !e;
    } else {
        e = ws_classic_keep(v->vec, ws, prim);
    }
    if (!e)
        v->dirty = 1;
    return e;
}

/* A mesh the render layer traces, recorded whole (ws_render_mesh) for the raster picture;
 * any other mesh as its facets (GKS_WS_MESH_FACETS: vec_primitive). */
static int vec_mesh(gks_ws *ws, const gks_mesh *m)
{
    vec_ws *v = ws->priv;
    if (ws_render_route(ws, &m->prim) != WS_ROUTE_TRACE)
        return GKS_WS_MESH_FACETS;
    if (!framebuffer(ws, v))
        return 300;
    int e = ws_render_mesh(v->r, ws, m);
    if (!e) {
        v->raster_used = 1;
        v->dirty = 1;
    }
    return e;
}

/* floats[0] in [lo, hi] into *x: 0, or 182 */
static int escape_real(const Gescape_in_data *in, double lo, double hi, double *x)
{
    if (in->num_floats < 1 || !in->floats || !(in->floats[0] >= lo && in->floats[0] <= hi))
        return 182;
    *x = in->floats[0];
    return 0;
}

/* GESC_VEC_LINE_JOIN ... GESC_VEC_PAGE (gks.h): 0, or 182 with nothing changed. */
static int vec_style_escape(vec_ws *v, int func_id, const Gescape_in_data *in)
{
    static const cairo_line_join_t joins[3] = { CAIRO_LINE_JOIN_MITER, CAIRO_LINE_JOIN_ROUND,
                                                CAIRO_LINE_JOIN_BEVEL };
    static const cairo_line_cap_t caps[3] = { CAIRO_LINE_CAP_BUTT, CAIRO_LINE_CAP_ROUND,
                                              CAIRO_LINE_CAP_SQUARE };
    int i = 0, e;
    switch (func_id) {
    case GESC_VEC_LINE_JOIN:
        if (!(e = gks_ws_escape_int(in, 0, 2, &i)))
            v->line.join = joins[i];
        return e;
    case GESC_VEC_LINE_CAP:
        if (!(e = gks_ws_escape_int(in, 0, 2, &i)))
            v->line.cap = caps[i];
        return e;
    case GESC_VEC_MITER_LIMIT:
        return escape_real(in, 1.0, 1000.0, &v->line.miter);
    case GESC_VEC_LINE_SCALE:
        return escape_real(in, 0.01, 100.0, &v->line.scale);
    default:
        break;
    }
    /* GESC_VEC_PAGE */
    if (in->num_ints != 5 && in->num_ints != 7)
        return 182;
    const Gint *a = in->ints + 1;
    if (!a[0] && !a[1] && !a[2] && !a[3]) {
        v->page_set = 0;
        return 0;
    }
    double p[6] = { 0, 0, 0, 0, 612, 792 }; /* the page size: the one given before, or letter */
    if (v->page_set) {
        p[4] = v->page[4];
        p[5] = v->page[5];
    }
    for (int k = 0; k < in->num_ints - 1; k++) {
        if (a[k] < (k < 4 ? -72000 : 1) || a[k] > 72000)
            return 182;
        p[k] = a[k];
    }
    if (p[2] <= p[0] || p[3] <= p[1])
        return 182;
    memcpy(v->page, p, sizeof p);
    v->page_set = 1;
    return 0;
}

static int vec_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    vec_ws *v = ws->priv;
    if (func_id == GESC_VEC_RESOLUTION) {
        int e = gks_ws_escape_int(in, VEC_DPI_MIN, VEC_DPI_MAX, &v->next_dpi);
        if (e)
            return e;
        if (!v->dirty && !v->frame_written && !v->raster_used &&
            ws_classic_retained(v->vec) == 0 && ws_classic_retained(v->r->classic) == 0) {
            apply_dpi(v); /* nothing drawn yet: this frame already */
            gks_raster_fb_free(v->fb);
            v->fb = NULL;
        }
        return 0;
    }
    if (func_id <= GESC_VEC_LINE_JOIN && func_id >= GESC_VEC_PAGE)
        return vec_style_escape(v, func_id, in);
    /* PDF and PS hold all frames in frame 1's file, SVG and EPS one file per frame */
    int fr = v->fmt == VEC_PDF || v->fmt == VEC_PS ? 1 : v->frame;
    return ws_rt_file_escape(v->r->rt, ws, func_id, in, out, fr, vec_ext[v->fmt], &v->base);
}

/* --- TEXT as text: the driver entry ------------------------------------------------------ */
/* The text's way to raster pixels: source (WC3) -> NDC3 (m) -> homogeneous NPC3 (npc) ->
 * pixels and depth (dc). */
typedef struct text_chain {
    const double (*m)[4];
    double npc[4][4], dc[4][4];
} text_chain;

static void chain_h(const text_chain *c, const double wc[3], double h[4])
{
    double n[3];
    gks_xform_mat34_point(c->m, wc, n);
    gks_xform_apply((const double (*)[4])c->npc, (const double[4]){ n[0], n[1], n[2], 1 }, h);
}

/* A homogeneous NPC3 point to pixels and depth; 0 if not finite. */
static int chain_px(const text_chain *c, const double h[4], double px[3])
{
    double q[3];
    if (gks_xform_divide(h, q))
        return 0;
    gks_xform_point((const double (*)[4])c->dc, q, px);
    return isfinite(px[0]) && isfinite(px[1]) && isfinite(px[2]);
}

/* A vector in pixels per font unit, rounded to 2^-24 pixel so that texts of one size and
 * direction share one scaled font (one Type 3 font) whatever the rounding of their
 * positions' transformation. */
static double quantum(double x)
{
    return ldexp(nearbyint(ldexp(x, 24)), -24);
}

typedef struct place_ctx {
    vec_ws *v;
    const text_chain *c;
    int first;
    double bx[2], by[2];   /* pixels per font unit along ux and uy */
    int fail;
} place_ctx;

static int place_glyph(void *ctx, int ch, const double org[3], const double ux[3],
                       const double uy[3])
{
    place_ctx *p = ctx;
    vec_ws *v = p->v;
    double h[4], px[3];
    chain_h(p->c, org, h);
    if (!chain_px(p->c, h, px))
        return 1;
    if (p->first) { /* the glyph axes: the plane reaches the page affinely (vec_text) */
        double a[3], b[3], qa[3], qb[3];
        for (int i = 0; i < 3; i++) {
            a[i] = org[i] + ux[i];
            b[i] = org[i] + uy[i];
        }
        chain_h(p->c, a, h);
        int ok = chain_px(p->c, h, qa);
        chain_h(p->c, b, h);
        if (!ok || !chain_px(p->c, h, qb))
            return 1;
        for (int i = 0; i < 2; i++) {
            p->bx[i] = qa[i] - px[i];
            p->by[i] = qb[i] - px[i];
        }
        p->first = 0;
    }
    if (gks_grow(&v->glyphs, &v->cap_glyphs, v->n_glyphs + 1, sizeof *v->glyphs)) {
        p->fail = 300;
        return 1;
    }
    v->glyphs[v->n_glyphs++] = (cairo_glyph_t){ (unsigned long)ch, px[0], px[1] };
    return 0;
}

/* The clip polygon of a text: its extent rectangle widened by a body height on every side
 * (no ink lies beyond), clipped by the clipping volume (clip_on) and the view's region, in
 * pixels at v->clip + v->n_clip; *n = 0 and 0 when nothing is clipped off (no polygon
 * needed), GKS_WS_TEXT_CLIPPED when nothing is left, 300. */
static int text_clip(vec_ws *v, const gks_text_prim *t, const text_chain *c,
                     const gks_xform_clip *view, size_t *n)
{
    double cr[4][3], cc[3], r[4][4], u1[3], u2[3];
    gks_text_extent(t->frame, t->attrs, t->str, cr, cc);
    double l1 = 0, l2 = 0;
    for (int i = 0; i < 3; i++) {
        u1[i] = cr[1][i] - cr[0][i];
        u2[i] = cr[3][i] - cr[0][i];
        l1 += u1[i] * u1[i];
        l2 += u2[i] * u2[i];
    }
    l1 = sqrt(l1);
    l2 = sqrt(l2);
    if (!(l1 > 0) || !(l2 > 0))
        return GKS_WS_TEXT_CLIPPED;
    static const int sg[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
    gks_xform_clip box;
    gks_xform_clip_init(&box);
    if (t->clip_on && gks_xform_clip_add_box(&box, t->clip_box, GKS_XFORM_CLIP_ALL))
        return GKS_WS_TEXT_CLIPPED;
    int all_in = 1;
    for (int k = 0; k < 4; k++) {
        double wc[3], h[4];
        for (int i = 0; i < 3; i++)
            wc[i] = cr[k][i] + l2 * (sg[k][0] * u1[i] / l1 + sg[k][1] * u2[i] / l2);
        gks_xform_mat34_point(c->m, wc, r[k]);
        r[k][3] = 1;
        gks_xform_apply((const double (*)[4])c->npc, r[k], h);
        all_in &= ws_classic_clip_inside(&box, r[k]) &&
                  ws_classic_clip_inside(view, h);
    }
    *n = 0;
    if (all_in)
        return 0;
    double a[VEC_CLIP_MAX][4], b[VEC_CLIP_MAX][4];
    size_t len = 4, m = 4;
    memcpy(a, r, sizeof r);
    if (box.n > 0) {
        if (gks_xform_clip_polygon(&box, 1, &len, (const double (*)[4])a, b, VEC_CLIP_MAX,
                                   &m, &m) || m < 3)
            return GKS_WS_TEXT_CLIPPED;
        memcpy(a, b, m * sizeof a[0]);
    }
    for (size_t i = 0; i < m; i++) {
        double h[4];
        gks_xform_apply((const double (*)[4])c->npc, a[i], h);
        memcpy(a[i], h, sizeof h);
    }
    len = m;
    if (gks_xform_clip_polygon(view, 1, &len, (const double (*)[4])a, b, VEC_CLIP_MAX, &m,
                               &m) || m < 3)
        return GKS_WS_TEXT_CLIPPED;
    if (gks_grow(&v->clip, &v->cap_clip, v->n_clip + m, sizeof *v->clip))
        return 300;
    for (size_t i = 0; i < m; i++) {
        double px[3];
        if (!chain_px(c, b[i], px))
            return GKS_WS_TEXT_CLIPPED;
        v->clip[v->n_clip + i][0] = px[0];
        v->clip[v->n_clip + i][1] = px[1];
    }
    *n = m;
    return 0;
}

/* Whether the text plane reaches the page affinely (its origin and axis points at the
 * same w): 0, or GKS_WS_TEXT_STROKE (perspective across the plane, or not finite). */
static int text_plane_affine(const text_chain *c, const gks_text_frame *f)
{
    double pts[3][3], h[3][4], px[3][3];
    for (int i = 0; i < 3; i++) {
        pts[0][i] = f->org[i];
        pts[1][i] = f->org[i] + f->ex[i];
        pts[2][i] = f->org[i] + f->ey[i];
    }
    for (int k = 0; k < 3; k++) {
        chain_h(c, pts[k], h[k]);
        if (!chain_px(c, h[k], px[k]))
            return GKS_WS_TEXT_STROKE;
    }
    if (fabs(h[1][3] - h[0][3]) > 1e-12 * fabs(h[0][3]) ||
        fabs(h[2][3] - h[0][3]) > 1e-12 * fabs(h[0][3]))
        return GKS_WS_TEXT_STROKE;
    return 0;
}

/* The glyph axes bx, by (pixels per font unit) of the placed text pc, expansion factor
 * e: 0 when they are a similarity (the pen stays round) of a size cairo draws cleanly,
 * else GKS_WS_TEXT_STROKE. */
static int text_axes(const vec_ws *v, const place_ctx *pc, double e, double bx[2],
                     double by[2])
{
    bx[0] = quantum(pc->bx[0] / e);
    bx[1] = quantum(pc->bx[1] / e);
    by[0] = quantum(pc->by[0]);
    by[1] = quantum(pc->by[1]);
    double lx = hypot(bx[0], bx[1]), ly = hypot(by[0], by[1]);
    if (!(ly > 0) || !isfinite(ly) || fabs(lx - ly) > 1e-6 * ly ||
        fabs(bx[0] * by[0] + bx[1] * by[1]) > 1e-6 * ly * ly)
        return GKS_WS_TEXT_STROKE;
    if (!(VEC_EM * ly * 72.0 / v->dpi <= VEC_TEXT_MAX_EM_PT)) /* huge: by its strokes */
        return GKS_WS_TEXT_STROKE;
    return 0;
}

/* STRING and CHAR precision in the real font: each glyph g0 ... of the text centred in
 * the stroke glyph's cell (its advance, times the expansion factor e, along bx); a text
 * with a glyph wider than its cell (W, m) is narrowed as a whole until every glyph fits,
 * so the ink stays inside the extent the core computes. Returns that narrowing (<= 1). */
static double real_font_fit(vec_ws *v, const gks_text_attrs *a, size_t g0, double e,
                            const double bx[2])
{
    double sx = 1.0;
    for (size_t j = g0; j < v->n_glyphs; j++) {
        int ch = (int)v->glyphs[j].index;
        gks_glyph gl;
        glyph_of(a->font, ch, &gl);
        double ra = v->real.advance[ch - 32] * v->real.em_units;
        if (ra > gl.advance && ra > 0)
            sx = fmin(sx, gl.advance / ra);
    }
    for (size_t j = g0; j < v->n_glyphs; j++) {
        int ch = (int)v->glyphs[j].index;
        gks_glyph gl;
        glyph_of(a->font, ch, &gl);
        double ra = v->real.advance[ch - 32] * v->real.em_units * sx;
        double shift = 0.5 * (gl.advance - ra) * e;
        v->glyphs[j].x += shift * bx[0];
        v->glyphs[j].y += shift * bx[1];
    }
    return sx;
}

/* The painter key of a text: the depth of the middle of its extent (0 if not finite). */
static double text_depth(const text_chain *c, const gks_text_prim *t)
{
    double cr[4][3], cc[3], mid[3], hm[4], pm[3];
    gks_text_extent(t->frame, t->attrs, t->str, cr, cc);
    for (int i = 0; i < 3; i++)
        mid[i] = 0.5 * (cr[0][i] + cr[2][i]);
    chain_h(c, mid, hm);
    return chain_px(c, hm, pm) ? pm[2] : 0;
}

/* TEXT drawn as glyphs of the user font where that is the stroked text: HLHSR modes none,
 * painter and ray tracing, and overlays (hlhsr_id != 0) in every mode; hidden line and
 * z-buffer test the strokes against the depths (GKS_WS_TEXT_STROKE). The text plane must
 * reach the page by a similarity (rotation, reflection, uniform scale: the pen stays
 * round) after the expansion factor, which holds for 2-D text and for text planes parallel
 * to the view plane; other planes get the strokes. Every precision (STRING, CHAR,
 * STROKE) is drawn at STROKE precision, which the standard allows for any request: the
 * glyphs are clipped exactly, by the clipping volume and the view's region. The painter
 * key is the depth of the middle of the text extent. */
static int vec_text_prim(gks_ws *ws, const gks_text_prim *t)
{
    vec_ws *v = ws->priv;
    int mode = ws->hlhsr_mode;
    if (t->hlhsr_id == 0 && (mode == GHLHSR_HIDDEN_LINE || mode == GHLHSR_ZBUFFER))
        return GKS_WS_TEXT_STROKE;
    text_chain c = { .m = t->m };
    const gks_xform_clip *view;
    if (ws_classic_view(v->vec, ws, t->view_ind, c.npc, c.dc, &view) ||
        text_plane_affine(&c, t->frame))
        return GKS_WS_TEXT_STROKE;
    const gks_text_attrs *a = t->attrs;
    double e = a->char_expan, bx[2], by[2];
    size_t g0 = v->n_glyphs, c0 = v->n_clip, nc = 0;
    place_ctx pc = { .v = v, .c = &c, .first = 1 };
    int r = gks_text_place(t->frame, a, t->str, place_glyph, &pc);
    if (r || pc.first || !(e > 0)) {
        v->n_glyphs = g0;
        return pc.fail ? pc.fail : r ? GKS_WS_TEXT_STROKE : GKS_WS_TEXT_CLIPPED;
    }
    if (text_axes(v, &pc, e, bx, by)) {
        v->n_glyphs = g0;
        return GKS_WS_TEXT_STROKE;
    }
    const int use_real = a->prec != GPREC_STROKE && real_font(v) == 0;
    double sx = use_real ? real_font_fit(v, a, g0, e, bx) : 1.0;
    r = text_clip(v, t, &c, view, &nc);
    int fi = r || use_real ? -1 : face_index(v, a->font, e);
    if (!r && fi < 0 && !use_real)
        r = GKS_WS_TEXT_STROKE; /* more faces than the table holds */
    if (!r && gks_grow(&v->texts, &v->cap_texts, v->n_texts + 1, sizeof *v->texts))
        r = 300;
    double depth = !r && mode == GHLHSR_PAINTER ? text_depth(&c, t) : 0;
    if (!r)
        r = ws_classic_keep_mark(v->vec, v->n_texts, depth, t->hlhsr_id != 0);
    if (r) {
        v->n_glyphs = g0;
        v->n_clip = c0;
        return r;
    }
    vec_text *x = &v->texts[v->n_texts++];
    *x = (vec_text){ .face = fi, .expan = e * sx, .bx = { bx[0], bx[1] }, .by = { by[0], by[1] },
                     .rgb = { (float)t->colour.red, (float)t->colour.green,
                              (float)t->colour.blue },
                     .g0 = g0, .ng = v->n_glyphs - g0, .c0 = c0, .nc = nc };
    v->n_clip += nc;
    v->dirty = 1;
    return 0;
}

#define VEC_HLHSR                                                                      \
    ((1u << GHLHSR_NONE) | (1u << GHLHSR_HIDDEN_LINE) | (1u << GHLHSR_ZBUFFER) |       \
     (1u << GHLHSR_PAINTER) | (1u << GHLHSR_RAYTRACE))

#define VEC_DESC(TYPE, NAME)                                                           \
    {                                                                                  \
        .type = TYPE, .name = NAME, .cat = GCAT_OUT, .cls = GCLASS_VEC,                \
        .dc_units = GDC_METRES, .dc_x = 0.210, .dc_y = 0.297,                          \
        .raster_x = 2480, .raster_y = 3508, /* at the default 300 dpi */               \
        .colr_avail = GAVAIL_COLR, .n_colr = 256, .n_pred_colr = 8,                    \
        .pred_colr = vec_colours, .default_irg = GIRG_SUPPR,                           \
        .default_defer = GDEFER_ASAP, .out = &gks_wdt_raster, .hlhsr_modes = VEC_HLHSR, \
    }

static const gks_ws_desc pdf_desc = VEC_DESC(GWS_TYPE_PDF, "pdf");
static const gks_ws_desc svg_desc = VEC_DESC(GWS_TYPE_SVG, "svg");
static const gks_ws_desc ps_desc = VEC_DESC(GWS_TYPE_PS, "ps");
static const gks_ws_desc eps_desc = VEC_DESC(GWS_TYPE_EPS, "eps");

/* The file of frame 1 (OPEN WORKSTATION's check that no other workstation uses it: 21). */
static int vec_file_fmt(const gks_ws *ws, vec_format fmt, char **path)
{
    char *b = gks_ws_file_default_base(ws, vec_ext[fmt]);
    *path = b ? gks_ws_file_frame(b, 1, vec_ext[fmt]) : NULL;
    gks_free(b);
    return *path ? 0 : 300;
}
static int pdf_file(const gks_ws *ws, char **p) { return vec_file_fmt(ws, VEC_PDF, p); }
static int svg_file(const gks_ws *ws, char **p) { return vec_file_fmt(ws, VEC_SVG, p); }
static int ps_file(const gks_ws *ws, char **p) { return vec_file_fmt(ws, VEC_PS, p); }
static int eps_file(const gks_ws *ws, char **p) { return vec_file_fmt(ws, VEC_EPS, p); }

#define VEC_DRIVER(DESC, OPEN, FILE)                                                   \
    {                                                                                  \
        .desc = &DESC, .open = OPEN, .file = FILE,                                     \
        .close = vec_close, .finish = vec_finish, .clear = vec_clear,                  \
        .update = vec_update,                                                          \
        .primitive = vec_primitive, .mesh = vec_mesh, .text = vec_text_prim,           \
        .message = gks_ws_file_message,                                                \
        .escape = vec_escape,                                                          \
    }

const gks_ws_driver gks_ws_pdf_driver = VEC_DRIVER(pdf_desc, pdf_open, pdf_file);
const gks_ws_driver gks_ws_svg_driver = VEC_DRIVER(svg_desc, svg_open, svg_file);
const gks_ws_driver gks_ws_ps_driver = VEC_DRIVER(ps_desc, ps_open, ps_file);
const gks_ws_driver gks_ws_eps_driver = VEC_DRIVER(eps_desc, eps_open, eps_file);
