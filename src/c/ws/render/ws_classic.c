/* SPDX-License-Identifier: MIT */
/*
 * ws_classic.c -- the classic renderer of every drawing workstation (PNG, X11, the cairo
 * types): primitives through the view pipeline into the raster module, and the classic
 * HLHSR modes (see ws_classic.h).
 *
 * Every primitive is built as one record in scratch arrays: its DC points after clipping
 * (fill loops, then edge pieces), counts, colour and attributes (with their floats:
 * pattern, cell colours, per-vertex attributes of smooth areas). A primitive drawn at once
 * is drawn from the scratch and dropped; a retained one is copied into the frame's display
 * list (ws_dlist.h: DC points as its vertices, counts as its loops, attributes and floats as
 * its attributes, shared by equal consecutive records, the rec as its own data), from which
 * UPDATE draws it. So there is one path from gks_prim to pixels, and the retained data is
 * the list's. Long polylines and marker lists are processed in chunks of CHUNK points so
 * that drawing at once needs O(CHUNK) memory whatever the point count.
 */
#include "ws_classic.h"
#include "ws_dlist.h"
#include "ws_shade.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { CHUNK = 4096 };
enum { REC_AREA, REC_LINE, REC_MARKER, REC_CELL, REC_MARK }; /* MARK: ws_classic_keep_mark */
enum { STYLE_HOLLOW = -1, STYLE_SMOOTH = -2 }; /* SMOOTH: per-vertex attributes (fl, nx floats
                                                  per point, the last 1/w; ny: shading context
                                                  or -1) */

/* Attributes of a record (shared by consecutive records with equal values). */
typedef struct rattr {
    int linetype;          /* line; area: boundary of HOLLOW */
    double width;          /* line width / marker stroke width, pixels */
    int marker_type;
    double marker_size;    /* pixels */
    int style;             /* area: STYLE_HOLLOW or a gks_raster_style */
    int hatch;
    int edge;              /* area: edge flag */
    int edgetype;
    double edgewidth;
    float edge_rgb[3];
    size_t fl;             /* first float of the pattern / cells in the float list */
    int nx, ny;
    double geo[6];         /* pattern reference point, cell width, cell height vector (DC) */
} rattr;

/* One primitive of the frame. Points from pt: area: fill loops, then edge pieces; cell:
 * o, pu, pv, then the clipped loops; line: pieces; marker: chunks of centres. Counts
 * from cnt: n_fill loops / pieces / chunks, then n_edge edge pieces. A negative piece
 * count marks a piece continuing the previous one (a chunk boundary inside a piece).
 * pt, cnt, attr index the scratch arrays while it is built (MARK: attr is the id). */
typedef struct rec {
    unsigned char kind, overlay;
    unsigned char outlined;  /* area: the boundary pieces were built (n_edge of them) */
    float rgb[3];
    float zbias;           /* edges of this area (slope-scaled) or lines */
    double key;            /* painter sort key: mean DC depth */
    size_t pt, cnt, attr;
    int n_fill, n_edge;
} rec;

/* A record's own data in the display list (32 bytes): what differs from record to record
 * and the list's record does not hold. Its kind is the list record's, n_edge its loops but
 * n_fill; a MARK has its id after it (a size_t). */
typedef struct srec {
    double key;
    float rgb[3];
    float zbias;
    int n_fill;
    unsigned char overlay, outlined;
} srec;

/* A record with its data, in the scratch arrays or in the display list. */
typedef struct rref {
    rec rc;
    const rattr *a;          /* NULL for MARK */
    const gks_raster_pt *pts;
    const int *cnt;
    const float *fl;         /* a->fl counts from here */
} rref;

/* A position in the display list's chunks (compose, walk): chunk number and record. */
typedef struct cursor {
    size_t chunk, k;
} cursor;

/* The view pipeline of one view index, valid while the inputs it was made from (view
 * representation, workstation window and viewport) are unchanged. */
typedef struct view_cache {
    int valid, ok;
    Gview_rep3 rep;
    Glimit3 win, vp;
    double npc[4][4];      /* NDC3 -> homogeneous NPC3 */
    double dc[4][4];       /* NPC3 -> DC (pixels of the image, depth in [0,1]) */
    gks_xform_clip clip;   /* view clip limits (by the indicators) and workstation window */
} view_cache;

struct ws_classic {
    ws_dlist *dl;          /* the display list of the frame: its WS_DL_CLASSIC records are
                              the retained primitives */
    int own_dl;            /* dl is this renderer's own (else the render layer's) */
    const ws_dl_chunk **chunks; /* compose, walk: the list's chunks, in order */
    size_t n_chunks, cap_chunks;
    /* scratch of the record being built */
    rattr *attrs;
    size_t n_attr, cap_attr;
    gks_raster_pt *pts;
    size_t n_pt, cap_pt;
    int *cnts;
    size_t n_cnt, cap_cnt;
    float *fl;
    size_t n_fl, cap_fl;
    /* scratch of the clipping stage */
    double (*h)[4], (*out)[4];
    size_t cap_h, cap_out;
    size_t *len, *loops;
    size_t cap_len, cap_loops;
    size_t *order;         /* painter: sorted record indices */
    double *keys;
    size_t cap_order;
    gks_raster_fb *composed;
    int fail;              /* result of the last GROW */
    double px_per_dc;      /* output pixels per DC unit (1 for the PNG workstation) */
    double px_per_unit;    /* output pixels per nominal unit (line width 1, marker size 1) */
    int keep;              /* the primitive being built is retained whatever the mode */
    gks_raster_fb *depth;  /* ws_classic_walk: depth buffer of hidden-line mode */
    gks_raster_pt *vis;    /* ws_classic_walk: visible runs of a piece */
    size_t cap_vis;
    view_cache views[GKS_MAX_VIEW_IND + 1];
    ws_shade_ctx *ctx;     /* shading contexts of smooth areas with normal interpolation */
    size_t n_ctx, cap_ctx;
};

/* --- growable arrays ------------------------------------------------------------------ */
/* gks_grow on r->arr, its error kept in r->fail. */
#define GROW(r, arr, cap, need) \
    ((r)->fail = gks_grow(&(r)->arr, &(r)->cap, (need), sizeof *(r)->arr))

ws_classic *ws_classic_new(ws_dlist *dl)
{
    ws_classic *r = gks_calloc_array(1, sizeof(ws_classic));
    if (r)
        r->own_dl = !dl;
    if (r && !(r->dl = dl ? dl : ws_dlist_new())) {
        ws_classic_free(r); /* frees what there is */
        r = NULL;
    }
    if (r)
        r->px_per_dc = r->px_per_unit = 1.0;
    return r;
}

void ws_classic_set_scale(ws_classic *r, double px_per_dc, double px_per_unit)
{
    if (!(px_per_dc > 0.0) || !isfinite(px_per_dc) || !(px_per_unit > 0.0) ||
        !isfinite(px_per_unit))
        return;
    if (px_per_dc != r->px_per_dc)
        for (int v = 0; v <= GKS_MAX_VIEW_IND; v++)
            r->views[v].valid = 0;
    r->px_per_dc = px_per_dc;
    r->px_per_unit = px_per_unit;
}

void ws_classic_free(ws_classic *r)
{
    if (!r)
        return;
    if (r->own_dl)
        ws_dlist_free(r->dl);
    gks_free(r->chunks);
    gks_free(r->attrs);
    gks_free(r->pts);
    gks_free(r->cnts);
    gks_free(r->fl);
    gks_free(r->h);
    gks_free(r->out);
    gks_free(r->len);
    gks_free(r->loops);
    gks_free(r->order);
    gks_free(r->keys);
    gks_raster_fb_free(r->composed);
    gks_raster_fb_free(r->depth);
    gks_free(r->vis);
    gks_free(r->ctx);
    gks_free(r);
}

void ws_classic_reset(ws_classic *r)
{
    if (r->own_dl)
        ws_dlist_reset(r->dl);
    r->n_attr = r->n_pt = r->n_cnt = r->n_fl = r->n_ctx = 0;
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++)
        r->views[v].valid = 0;
}

size_t ws_classic_retained(const ws_classic *r)
{
    return ws_dlist_count(r->dl, WS_DL_CLASSIC);
}

/* --- view pipeline ---------------------------------------------------------------------- */
/* The cached pipeline of view index vi (an index outside the table uses view 0). */
static const view_cache *view_get(ws_classic *r, const gks_ws *ws, int vi)
{
    if (vi < 0 || vi > GKS_MAX_VIEW_IND)
        vi = 0;
    view_cache *c = &r->views[vi];
    const Gview_rep3 *v = &ws->views[vi];
    if (c->valid && memcmp(&c->rep, v, sizeof *v) == 0 &&
        memcmp(&c->win, &ws->cur_win, sizeof c->win) == 0 &&
        memcmp(&c->vp, &ws->cur_vp, sizeof c->vp) == 0)
        return c;
    c->valid = 1;
    c->ok = 0;
    c->rep = *v;
    c->win = ws->cur_win;
    c->vp = ws->cur_vp;
    double win[6], lim[6];
    gks_limit3_array(&ws->cur_win, win);
    if (gks_ws_pixel_matrix(ws, r->px_per_dc, c->dc))
        return c;
    gks_xform_multiply(v->map_matrix, v->ori_matrix, c->npc);
    gks_limit3_array(&v->clip_limit, lim);
    unsigned flags = (v->xy_clip == GIND_CLIP ? GKS_XFORM_CLIP_XY : 0) |
                     (v->back_clip == GIND_CLIP ? GKS_XFORM_CLIP_BACK : 0) |
                     (v->front_clip == GIND_CLIP ? GKS_XFORM_CLIP_FRONT : 0);
    gks_xform_clip_init(&c->clip);
    if (flags && gks_xform_clip_add_box(&c->clip, lim, flags))
        return c;
    if (gks_xform_clip_add_box(&c->clip, win, GKS_XFORM_CLIP_ALL))
        return c;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(c->npc[i][j]))
                return c;
    c->ok = 1;
    return c;
}

static void to_h(const view_cache *v, const Gpoint3 *p, double h[4])
{
    gks_xform_apply(v->npc, (const double[4]){ p->x, p->y, p->z, 1 }, h);
}

/* A clipped homogeneous NPC point to DC; 0 if it cannot be divided. */
static int to_dc(const view_cache *v, const double h[4], gks_raster_pt *q)
{
    double c[3], d[3];
    if (gks_xform_divide(h, c))
        return 0;
    gks_xform_point(v->dc, c, d);
    *q = (gks_raster_pt){ d[0], d[1], d[2] };
    return isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]);
}

static int inside(const gks_xform_clip *c, const double h[4])
{
    return ws_classic_clip_inside(c, h);
}

int ws_classic_clip_inside(const gks_xform_clip *c, const double h[4])
{
    if (!(h[3] >= c->wmin))
        return 0;
    for (int i = 0; i < c->n; i++)
        if (!(c->p[i][0] * h[0] + c->p[i][1] * h[1] + c->p[i][2] * h[2] + c->p[i][3] * h[3] >=
              0.0))
            return 0;
    return 1;
}

static int all_inside(const gks_xform_clip *c, const double (*h)[4], size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!inside(c, h[i]))
            return 0;
    return 1;
}

/* An NDC3 point through the whole pipeline without clipping (pattern geometry). */
static int ndc_to_dc(const view_cache *v, const Gpoint3 *p, double q[3])
{
    double h[4];
    to_h(v, p, h);
    if (!(h[3] > 0.0))
        return 0;
    double c[3] = { h[0] / h[3], h[1] / h[3], h[2] / h[3] };
    gks_xform_point(v->dc, c, q);
    return isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]);
}

/* --- building records ------------------------------------------------------------------- */
typedef struct build {
    ws_classic *r;
    const view_cache *v;
    gks_raster_fb *fb;        /* non-NULL: draw each chunk at once, then drop it */
    const gks_ws *ws;
    int vi;                   /* the primitive's view index */
    gks_raster_stroke st;     /* stroke state across chunks drawn at once */
} build;

static int draw_rec(ws_classic *r, gks_raster_fb *fb, const rref *x, int zmode_kind,
                    gks_raster_stroke *st);

/* Record rc in the scratch arrays, resolved. */
static rref scratch_ref(const ws_classic *r, const rec *rc)
{
    return (rref){ .rc = *rc, .a = &r->attrs[rc->attr], .pts = r->pts + rc->pt,
                   .cnt = r->cnts + rc->cnt, .fl = r->fl };
}

/* Appends an attribute entry unless equal to the last one; sets *idx. */
static int attr_push(ws_classic *r, const rattr *a, size_t *idx)
{
    if (r->n_attr && memcmp(&r->attrs[r->n_attr - 1], a, sizeof *a) == 0) {
        *idx = r->n_attr - 1;
        return 0;
    }
    if (GROW(r, attrs, cap_attr, r->n_attr + 1))
        return 300;
    r->attrs[r->n_attr] = *a;
    *idx = r->n_attr++;
    return 0;
}

static int count_push(ws_classic *r, int c)
{
    if (GROW(r, cnts, cap_cnt, r->n_cnt + 1))
        return 300;
    r->cnts[r->n_cnt++] = c;
    return 0;
}

/* Mode of drawing a record at once (see draw_rec). */
enum { DRAW_PLAIN, DRAW_ZTEST, DRAW_HL_AREAS, DRAW_HL_LINES };

static int immediate_mode(const gks_ws *ws)
{
    return ws->hlhsr_mode == GHLHSR_ZBUFFER ? DRAW_ZTEST : DRAW_PLAIN;
}

/* The m chunk points r->h that are inside the clip region, in DC, as one run of marker
 * centres of *rc (none if none is inside). 0 or 300. */
static int chunk_markers(ws_classic *r, const view_cache *v, size_t m, rec *rc)
{
    if (GROW(r, pts, cap_pt, r->n_pt + m))
        return 300;
    size_t k = 0;
    for (size_t i = 0; i < m; i++)
        if (inside(&v->clip, r->h[i]) && to_dc(v, r->h[i], &r->pts[r->n_pt + k]))
            k++;
    if (!k)
        return 0;
    r->n_pt += k;
    if (count_push(r, (int)k))
        return 300;
    rc->n_fill++;
    return 0;
}

/* The polyline of the m chunk points r->h clipped, its pieces of at least 2 points in DC
 * appended to *rc; the first one continues the previous chunk's last piece (count
 * negated) when *cont and the chunk starts inside. *cont becomes whether the chunk ends
 * inside. 0 or 300. */
static int chunk_polyline(ws_classic *r, const view_cache *v, size_t m, int *cont, rec *rc)
{
    size_t n_out = 0, n_pieces = 0;
    int e = 0;
    if (all_inside(&v->clip, (const double (*)[4])r->h, m)) { /* trivial accept */
        memcpy(r->out, r->h, m * sizeof *r->out);
        r->len[0] = n_out = m;
        n_pieces = 1;
    } else {
        e = gks_xform_clip_polyline(&v->clip, m, (const double (*)[4])r->h, r->out,
                                    r->cap_out, r->len, r->cap_len, &n_out, &n_pieces);
    }
    if (e == 300)
        return 300;
    if (e)
        n_pieces = 0; /* non-finite: nothing of this chunk */
    if (GROW(r, pts, cap_pt, r->n_pt + n_out))
        return 300;
    size_t off = 0;
    for (size_t k = 0; k < n_pieces; k++) {
        size_t c = 0;
        for (size_t i = 0; i < r->len[k]; i++)
            if (to_dc(v, r->out[off + i], &r->pts[r->n_pt + c]))
                c++;
        off += r->len[k];
        if (c < 2)
            continue;
        r->n_pt += c;
        int first_cont = k == 0 && *cont && inside(&v->clip, r->h[0]);
        if (count_push(r, first_cont ? -(int)c : (int)c))
            return 300;
        rc->n_fill++;
    }
    *cont = e == 0 && inside(&v->clip, r->h[m - 1]);
    return 0;
}

/* Immediate output (b->fb): the pieces of *rc from point pt0 and count cnt0 on, drawn at
 * once and dropped. 0 or the error of draw_rec. */
static int chunk_draw(build *b, rec *rc, size_t pt0, size_t cnt0)
{
    ws_classic *r = b->r;
    rec t = *rc;
    t.pt = pt0;
    t.cnt = cnt0;
    t.n_fill = (int)(r->n_cnt - cnt0);
    const rref x = scratch_ref(r, &t);
    int de = draw_rec(r, b->fb, &x, immediate_mode(b->ws), &b->st);
    r->n_pt = pt0;
    r->n_cnt = cnt0;
    rc->n_fill = 0;
    return de;
}

/* Polyline pieces (or marker centres) of points p[0..n-1] (closed: back to p[0]) clipped
 * and in DC, appended to the list as counts of *rc, in chunks of CHUNK points (a polyline's
 * chunks overlap by one point). With b->fb, each chunk is drawn and dropped. */
static int add_pieces(build *b, const Gpoint3 *p, size_t n, int closed, rec *rc)
{
    ws_classic *r = b->r;
    const view_cache *v = b->v;
    int markers = rc->kind == REC_MARKER;
    size_t total = markers ? n : closed ? n + 1 : n; /* points walked, p[i % n] */
    const size_t overlap = markers ? 0 : 1;
    if (GROW(r, h, cap_h, CHUNK + 1) || GROW(r, out, cap_out, 2 * CHUNK + 2) ||
        GROW(r, len, cap_len, CHUNK + 1))
        return 300;
    int cont = 0; /* the previous chunk's last point was inside: its piece continues */
    for (size_t s = 0; s + overlap < total;) {
        size_t m = total - s;
        if (m > CHUNK + overlap)
            m = CHUNK + overlap;
        for (size_t i = 0; i < m; i++)
            to_h(v, &p[(s + i) % n], r->h[i]);
        size_t pt0 = r->n_pt, cnt0 = r->n_cnt;
        int e = markers ? chunk_markers(r, v, m, rc) : chunk_polyline(r, v, m, &cont, rc);
        if (e)
            return e;
        s += m - overlap;
        if (b->fb && r->n_cnt > cnt0 && (e = chunk_draw(b, rc, pt0, cnt0)))
            return e;
    }
    return 0;
}

/* The one place where the colour of an area is decided: flat shading (ws_shade.c) of the
 * resolved fill colour by the area's properties, reflectance equation and active lights,
 * with the formulas of the tracer's local shading (so a preview and the traced picture
 * agree where there are no shadows or global effects). */
static void area_colour(const gks_ws *ws, const gks_prim *prim, const view_cache *v,
                        float rgb[3])
{
    (void)v;
    ws_shade sh;
    ws_shade_area(ws, prim, &sh);
    Grgb c = ws_shade_apply(&sh, &prim->colour);
    rgb[0] = (float)c.red;
    rgb[1] = (float)c.green;
    rgb[2] = (float)c.blue;
}

static double scale_or_one(double s)
{
    return isfinite(s) && s > 0.0 ? (s < 1e4 ? s : 1e4) : 1.0;
}

static int type_or_solid(int t)
{
    return t >= 1 && t <= 4 ? t : GKS_RASTER_LT_SOLID;
}

/* Slope-scaled depth bias of the edges of the fill loops (DC): see ws_classic.h. */
static float edge_bias(const gks_raster_pt *p, const int *cnt, int n_loops, double w)
{
    double n[3] = { 0, 0, 0 }, zmin = INFINITY, zmax = -INFINITY;
    const gks_raster_pt *q = p;
    for (int l = 0; l < n_loops; q += cnt[l], l++)
        for (int i = 0; i < cnt[l]; i++) {
            const gks_raster_pt *a = q + i, *c = q + (i + 1 == cnt[l] ? 0 : i + 1);
            n[0] += (a->y - c->y) * (a->z + c->z);
            n[1] += (a->z - c->z) * (a->x + c->x);
            n[2] += (a->x - c->x) * (a->y + c->y);
            zmin = fmin(zmin, a->z);
            zmax = fmax(zmax, a->z);
        }
    double slope = (fabs(n[0]) + fabs(n[1])) / fabs(n[2]);
    double b = slope * (0.75 + 0.5 * w), range = zmax - zmin;
    if (!(b < range)) /* NaN (edge-on) too: the area's depth never differs by more */
        b = range;
    if (!(b < WS_CLASSIC_HL_BIAS_MAX))
        b = WS_CLASSIC_HL_BIAS_MAX;
    return (float)(WS_CLASSIC_HL_BIAS + b);
}

static void mean_key(const ws_classic *r, rec *rc, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += r->pts[rc->pt + i].z;
    rc->key = n ? s / (double)n : 0.0;
}

/* Pattern of an area into the float list and a->geo; 0 if unusable (solid instead). */
static int pattern_set(ws_classic *r, const view_cache *v, const gks_prim_attrs *pa, rattr *a)
{
    if (!pa->pattern || pa->pat_nx < 1 || pa->pat_ny < 1 ||
        (size_t)pa->pat_nx > SIZE_MAX / 3 / (size_t)pa->pat_ny)
        return 0;
    Gpoint3 ref = pa->pat_ref;
    Gpoint3 pw = { ref.x + pa->pat_width.delta_x, ref.y + pa->pat_width.delta_y,
                   ref.z + pa->pat_width.delta_z };
    Gpoint3 ph = { ref.x + pa->pat_height.delta_x, ref.y + pa->pat_height.delta_y,
                   ref.z + pa->pat_height.delta_z };
    double q0[3], q1[3], q2[3];
    if (!ndc_to_dc(v, &ref, q0) || !ndc_to_dc(v, &pw, q1) || !ndc_to_dc(v, &ph, q2))
        return 0;
    double g[6] = { q0[0], q0[1], (q1[0] - q0[0]) / pa->pat_nx, (q1[1] - q0[1]) / pa->pat_nx,
                    (q2[0] - q0[0]) / pa->pat_ny, (q2[1] - q0[1]) / pa->pat_ny };
    double det = g[2] * g[5] - g[3] * g[4];
    if (!isfinite(det) || fabs(det) < 1e-6)
        return 0;
    size_t nc = (size_t)pa->pat_nx * (size_t)pa->pat_ny;
    if (GROW(r, fl, cap_fl, r->n_fl + 3 * nc))
        return -1;
    for (size_t i = 0; i < nc; i++) {
        r->fl[r->n_fl + 3 * i] = (float)pa->pattern[i].red;
        r->fl[r->n_fl + 3 * i + 1] = (float)pa->pattern[i].green;
        r->fl[r->n_fl + 3 * i + 2] = (float)pa->pattern[i].blue;
    }
    a->fl = r->n_fl;
    r->n_fl += 3 * nc;
    a->nx = pa->pat_nx;
    a->ny = pa->pat_ny;
    memcpy(a->geo, g, sizeof g);
    return 1;
}

/* Fill loops of an area (or a cell array's parallelogram) clipped and in DC, appended as
 * rc's fill loops. ndc: the loops' points, n_loops loops of lc[k] points. */
static int add_loops(build *b, const Gpoint3 *ndc, int n_loops, const int *lc,
                     const gks_xform_clip *clip, rec *rc)
{
    ws_classic *r = b->r;
    size_t n = 0;
    for (int k = 0; k < n_loops; k++) {
        if (lc[k] < 0)
            return 0;
        n += (size_t)lc[k];
    }
    if (GROW(r, h, cap_h, n) || GROW(r, loops, cap_loops, (size_t)n_loops) ||
        GROW(r, len, cap_len, (size_t)n_loops))
        return 300;
    for (size_t i = 0; i < n; i++)
        to_h(b->v, &ndc[i], r->h[i]);
    for (int k = 0; k < n_loops; k++)
        r->loops[k] = (size_t)lc[k];
    if (all_inside(clip, r->h, n)) { /* trivial accept: no clipping */
        if (GROW(r, pts, cap_pt, r->n_pt + n))
            return 300;
        size_t off = 0;
        for (int k = 0; k < n_loops; off += (size_t)lc[k], k++) {
            int c = 0;
            for (int i = 0; i < lc[k]; i++)
                if (to_dc(b->v, r->h[off + (size_t)i], &r->pts[r->n_pt + (size_t)c]))
                    c++;
            if (c < 3)
                continue;
            r->n_pt += (size_t)c;
            if (count_push(r, c))
                return 300;
            rc->n_fill++;
        }
        return 0;
    }
    size_t need = 4 * n + 16;
    for (int attempt = 0; attempt < 3; attempt++) {
        if (GROW(r, out, cap_out, need))
            return 300;
        size_t n_out = 0;
        int e = gks_xform_clip_polygon(clip, (size_t)n_loops, r->loops,
                                       (const double (*)[4])r->h, r->out, r->cap_out, r->len,
                                       &n_out);
        if (e == 300 && n_out > r->cap_out) {
            need = n_out;
            continue;
        }
        if (e)
            return e == 300 ? 300 : 0; /* non-finite or degenerate: nothing */
        if (GROW(r, pts, cap_pt, r->n_pt + n_out))
            return 300;
        size_t off = 0;
        for (int k = 0; k < n_loops; k++) {
            size_t c = 0;
            for (size_t i = 0; i < r->len[k]; i++)
                if (to_dc(b->v, r->out[off + i], &r->pts[r->n_pt + c]))
                    c++;
            off += r->len[k];
            if (c < 3 || c > INT32_MAX)
                continue;
            r->n_pt += c;
            if (count_push(r, (int)c))
                return 300;
            rc->n_fill++;
        }
        return 0;
    }
    return 300;
}

/* rc's own data (srec) to dst. */
static void srec_put(void *dst, const rec *rc)
{
    const srec d = { .key = rc->key, .rgb = { rc->rgb[0], rc->rgb[1], rc->rgb[2] },
                     .zbias = rc->zbias, .n_fill = rc->n_fill, .overlay = rc->overlay,
                     .outlined = rc->outlined };
    memcpy(dst, &d, sizeof d);
}

/* The finished record rc (scratch from pt0, cnt0, fl0) into the display list: its DC
 * points as vertices, its counts as loops, its attributes with their floats (a->fl counted
 * from the first of them) as attributes, rc as its own data. 0 or 300. */
static int rec_retain(build *b, const rec *rc, size_t pt0, size_t cnt0, size_t fl0)
{
    ws_classic *r = b->r;
    const size_t n_fl = r->n_fl - fl0, asz = sizeof(rattr) + n_fl * sizeof(float);
    const size_t n_cnt = r->n_cnt - cnt0;
    if (n_fl > SIZE_MAX / sizeof(float) - sizeof(rattr) || n_cnt > INT32_MAX)
        return 300;
    rattr a = r->attrs[rc->attr];
    a.fl = a.fl >= fl0 ? a.fl - fl0 : 0;
    /* attributes and floats as one block (the list compares and copies it whole); without
     * floats a itself */
    unsigned char sblk[sizeof(rattr) + 64 * sizeof(float)];
    unsigned char *blk = !n_fl ? (unsigned char *)&a
                         : asz <= sizeof sblk ? sblk : gks_alloc_array(1, asz);
    if (!blk)
        return 300;
    if (n_fl) {
        memcpy(blk, &a, sizeof a);
        memcpy(blk + sizeof a, r->fl + fl0, n_fl * sizeof(float));
    }
    const ws_dl_need need = { .n_vtx = r->n_pt - pt0, .n_loops = (int)n_cnt,
                              .data_size = sizeof(srec) };
    ws_dl_put put;
    const int vi = b->vi >= 0 && b->vi <= GKS_MAX_VIEW_IND ? b->vi : 0; /* as view_get */
    int e = ws_dlist_append(r->dl, WS_DL_CLASSIC, rc->kind, vi, blk, asz, &need, &put);
    if (blk != sblk && blk != (unsigned char *)&a)
        gks_free(blk);
    if (e)
        return e;
    srec_put(put.data, rc);
    if (need.n_vtx)
        memcpy(put.xyz, r->pts + pt0, need.n_vtx * sizeof *r->pts);
    if (n_cnt)
        memcpy(put.loops, r->cnts + cnt0, n_cnt * sizeof *r->cnts);
    return 0;
}

/* The finished record: retained into the display list, or drawn at once; the scratch
 * dropped either way. */
static int rec_finish(build *b, rec *rc, size_t pt0, size_t cnt0, size_t attr0, size_t fl0,
                      int retain)
{
    ws_classic *r = b->r;
    int e = 0;
    if (rc->n_fill + rc->n_edge == 0) {
        /* nothing visible */
    } else if (retain) {
        e = rec_retain(b, rc, pt0, cnt0, fl0);
    } else {
        gks_raster_stroke st = { 0 };
        const rref x = scratch_ref(r, rc);
        e = draw_rec(r, b->fb, &x, immediate_mode(b->ws), &st);
    }
    r->n_pt = pt0;
    r->n_cnt = cnt0;
    r->n_attr = attr0;
    r->n_fl = fl0;
    return e;
}

/* 1 if the n points (DC) form a strictly convex loop (either orientation) */
static int dc_convex(const gks_raster_pt *q, int n)
{
    int sg = 0;
    for (int i = 0; i < n; i++) {
        const gks_raster_pt *a = &q[i], *c = &q[(i + 1) % n], *d = &q[(i + 2) % n];
        double x = (c->x - a->x) * (d->y - c->y) - (c->y - a->y) * (d->x - c->x);
        int t = x > 0 ? 1 : x < 0 ? -1 : 0;
        if (t == 0 || (sg && t != sg))
            return 0;
        sg = t;
    }
    return 1;
}

static int ctx_equal(const ws_shade_ctx *a, const ws_shade_ctx *b)
{
    return a->persp == b->persp && a->nl == b->nl && !memcmp(a->eye, b->eye, sizeof a->eye) &&
           !memcmp(a->eq, b->eq, sizeof a->eq) && !memcmp(a->pr, b->pr, sizeof a->pr) &&
           !memcmp(a->l, b->l, (size_t)a->nl * sizeof a->l[0]);
}

/* Normal interpolation, per sample: attributes Od, N, P (VRC3) of a smooth area. */
static void phong_sample(void *user, const float *at, float rgb[3])
{
    double od[3] = { at[0], at[1], at[2] }, N[3] = { at[3], at[4], at[5] },
           P[3] = { at[6], at[7], at[8] };
    double l = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
    if (!(l > 0) || !isfinite(l)) {
        rgb[0] = (float)od[0], rgb[1] = (float)od[1], rgb[2] = (float)od[2];
        return;
    }
    for (int k = 0; k < 3; k++)
        N[k] /= l;
    ws_shade_point(user, P, N, od, rgb);
}

/* One clip stage of a smooth loop (Sutherland-Hodgman): vertices of m doubles, the
 * homogeneous point first and then the attributes, all carried with the same parameter t
 * (linear in clip space, so the perspective divide after clipping stays correct). k: the
 * constraint (0 is w >= wmin when wmin > 0). Returns the output count, -1 past cap. */
static int smooth_clip_stage(const gks_xform_clip *c, int k, const double *in, int n, int m,
                             double *out, int cap)
{
    int o = 0;
    for (int i = 0; i < n; i++) {
        const double *p = in + (size_t)((i + n - 1) % n) * (size_t)m, *q = in + (size_t)i * (size_t)m;
        double dp, dq;
        if (c->wmin > 0.0 && k == 0) {
            dp = p[3] - c->wmin, dq = q[3] - c->wmin;
        } else {
            const double *pl = c->p[c->wmin > 0.0 ? k - 1 : k];
            dp = pl[0] * p[0] + pl[1] * p[1] + pl[2] * p[2] + pl[3] * p[3];
            dq = pl[0] * q[0] + pl[1] * q[1] + pl[2] * q[2] + pl[3] * q[3];
        }
        if (!isfinite(dp) || !isfinite(dq))
            return -1;
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) { /* from the nearer end, as cross4 */
            if (o >= cap)
                return -1;
            const double *a0 = fabs(dp) <= fabs(dq) ? p : q, *a1 = a0 == p ? q : p;
            const double t = a0 == p ? dp / (dp - dq) : dq / (dq - dp);
            for (int j = 0; j < m; j++)
                out[(size_t)o * (size_t)m + (size_t)j] = a0[j] + t * (a1[j] - a0[j]);
            o++;
        }
        if (dq >= 0) {
            if (o >= cap)
                return -1;
            memcpy(out + (size_t)o * (size_t)m, q, (size_t)m * sizeof *q);
            o++;
        }
    }
    return o;
}

/* 1 if the n DC points turn one way only (collinear and repeated points from clipping
 * allowed), i.e. fan-fillable as a convex loop. */
static int dc_convex_loose(const gks_raster_pt *q, int n)
{
    int sg = 0;
    for (int i = 0; i < n; i++) {
        const gks_raster_pt *a = &q[i], *c = &q[(i + 1) % n], *d = &q[(i + 2) % n];
        double x = (c->x - a->x) * (d->y - c->y) - (c->y - a->y) * (d->x - c->x);
        int t = x > 0 ? 1 : x < 0 ? -1 : 0;
        if (sg && t && t != sg)
            return 0;
        if (t)
            sg = t;
    }
    return sg != 0;
}

/* 1 if prim cannot be drawn smooth (smooth_setup): no interior shading method COLOUR or
 * NORMAL, no vertex normals or colours, not one loop of at least 3 points, not solid, or
 * hidden-line mode. */
static int smooth_refused(const build *b, const gks_prim *prim, const rattr *a, int meth)
{
    const int n = prim->n_points;
    return meth <= GSHAD_NONE || (!prim->vnormals && !prim->vcolours) || prim->n_loops != 1 ||
           n < 3 || prim->loop_counts[0] != n || a->style != GKS_RASTER_SOLID ||
           b->ws->hlhsr_mode == GHLHSR_HIDDEN_LINE;
}

/* An unclipped loop's n points r->h in DC into q: 1 if one is not representable (w = 0)
 * or the loop is not convex. */
static int smooth_whole_dc(const build *b, int n, gks_raster_pt *q)
{
    const double (*h)[4] = (const double (*)[4])b->r->h;
    for (int i = 0; i < n; i++)
        if (!to_dc(b->v, h[i], &q[i]) || !(fabs(h[i][3]) > 0))
            return 1;
    return !dc_convex(q, n);
}

/* The per-vertex attributes of prim's n vertices into f (per floats each, the last one
 * 1/|w|): phong: Od, N (zero without a normal) and P in VRC; else the colour shaded at the
 * vertex with its normal (lit) or the facet's flat shading. */
static void smooth_vertex_attrs(const build *b, const gks_prim *prim, int phong, int lit,
                                const ws_shade_ctx *ctx, const ws_shade *flat, float *f,
                                int per)
{
    const int nat = per - 1;
    for (int i = 0; i < prim->n_points; i++, f += per) {
        const Grgb *c = prim->vcolours ? &prim->vcolours[i] : &prim->colour;
        double od[3] = { c->red, c->green, c->blue }, P[3], N[3];
        ws_shade_vrc_point(b->ws, prim, &prim->pts[i], P);
        const int hasn = prim->vnormals && ws_shade_vrc_normal(b->ws, prim, &prim->vnormals[i], N);
        if (phong) {
            for (int k = 0; k < 3; k++) {
                f[k] = (float)od[k];
                f[3 + k] = hasn ? (float)N[k] : 0.0f;
                f[6 + k] = (float)P[k];
            }
        } else if (hasn && lit) {
            ws_shade_point(ctx, P, N, od, f);
        } else {
            Grgb g = ws_shade_apply(flat, c);
            f[0] = (float)g.red, f[1] = (float)g.green, f[2] = (float)g.blue;
        }
        f[nat] = (float)(1.0 / fabs(b->r->h[i][3]));
    }
}

/* The loop of n points (r->h, their attributes at r->fl + r->n_fl, per floats each) cut by
 * every constraint of the clip region with its attributes, then added to rc (points,
 * count) with the attributes of the clipped loop at r->fl + r->n_fl; *cnt its points.
 * 0, 1 (nothing left, or not convex: drawn flat instead) or 300. */
static int smooth_clip(build *b, rec *rc, int n, int per, int *cnt)
{
    ws_classic *r = b->r;
    const int nat = per - 1, m = 4 + nat;
    const int ks = b->v->clip.n + (b->v->clip.wmin > 0.0 ? 1 : 0);
    const int cap = n + ks + 1; /* a convex loop gains at most one point per plane */
    double *va = gks_alloc_array((size_t)cap * 2, (size_t)m * sizeof *va);
    if (!va)
        return 300;
    double *in = va, *out = va + (size_t)cap * (size_t)m;
    for (int i = 0; i < n; i++) {
        memcpy(in + (size_t)i * (size_t)m, r->h[i], 4 * sizeof *in);
        for (int j = 0; j < nat; j++)
            in[(size_t)i * (size_t)m + 4 + (size_t)j] = r->fl[r->n_fl + (size_t)i * (size_t)per + (size_t)j];
    }
    int c = n;
    for (int k = 0; k < ks && c >= 3; k++) {
        c = smooth_clip_stage(&b->v->clip, k, in, c, m, out, cap);
        double *t = in;
        in = out, out = t;
    }
    int ok = c >= 3 && !GROW(r, pts, cap_pt, r->n_pt + (size_t)c) &&
             !GROW(r, fl, cap_fl, r->n_fl + (size_t)per * (size_t)c);
    gks_raster_pt *q = r->pts + r->n_pt;
    for (int i = 0; ok && i < c; i++)
        ok = in[(size_t)i * (size_t)m + 3] > 0 && to_dc(b->v, in + (size_t)i * (size_t)m, &q[i]);
    ok = ok && dc_convex_loose(q, c);
    for (int i = 0; ok && i < c; i++) {
        float *g = r->fl + r->n_fl + (size_t)i * (size_t)per;
        for (int j = 0; j < nat; j++)
            g[j] = (float)in[(size_t)i * (size_t)m + 4 + (size_t)j];
        g[nat] = (float)(1.0 / in[(size_t)i * (size_t)m + 3]);
    }
    gks_free(va);
    if (!ok || count_push(r, c))
        return ok ? 300 : 1;
    r->n_pt += (size_t)c;
    rc->n_fill++;
    *cnt = c;
    return 0;
}

/* a->ny: the index of the shading context of a lit NORMAL area (ctx appended to r->ctx
 * unless it equals the last one), -1 otherwise (the vertex colours interpolated). 0 or 300. */
static int smooth_ctx(ws_classic *r, rattr *a, int phong, int lit, const ws_shade_ctx *ctx)
{
    a->ny = -1;
    if (!phong || !lit)
        return 0;
    if (!r->n_ctx || !ctx_equal(&r->ctx[r->n_ctx - 1], ctx)) {
        if (GROW(r, ctx, cap_ctx, r->n_ctx + 1))
            return 300;
        r->ctx[r->n_ctx++] = *ctx;
    }
    a->ny = (int)(r->n_ctx - 1);
    return 0;
}

/* An area with vertex data and interior shading method COLOUR or NORMAL (on either side),
 * solid, of one convex loop: its per-vertex attributes into the float list and a->style =
 * STYLE_SMOOTH; a loop crossing the clip region is clipped here with its attributes.
 * COLOUR (or no vertex normals): the colours shaded at the vertices (with their normals,
 * else the facet's), interpolated; NORMAL with normals: Od, N and P interpolated and shaded
 * per sample. 0: set up (add_loops adds the points), 2: set up with the clipped loop added
 * to rc, 1: drawn flat instead, 300. */
static int smooth_setup(build *b, const gks_prim *prim, rattr *a, rec *rc)
{
    ws_classic *r = b->r;
    const int meth = prim->shading[0] > prim->shading[1] ? prim->shading[0] : prim->shading[1];
    const int n = prim->n_points;
    if (smooth_refused(b, prim, a, meth))
        return 1;
    if (GROW(r, h, cap_h, (size_t)n) || GROW(r, pts, cap_pt, r->n_pt + (size_t)n))
        return 300;
    for (int i = 0; i < n; i++)
        to_h(b->v, &prim->pts[i], r->h[i]);
    const int whole = all_inside(&b->v->clip, r->h, (size_t)n);
    /* scratch: add_loops writes the same points */
    if (whole && smooth_whole_dc(b, n, r->pts + r->n_pt))
        return 1;
    const int phong = meth == GSHAD_NORM && prim->vnormals;
    const int per = (phong ? 9 : 3) + 1;
    ws_shade_ctx ctx;
    const int lit = !ws_shade_ctx_init(b->ws, prim, &ctx);
    ws_shade flat;
    ws_shade_area(b->ws, prim, &flat);
    if (GROW(r, fl, cap_fl, r->n_fl + (size_t)per * (size_t)n))
        return 300;
    smooth_vertex_attrs(b, prim, phong, lit, &ctx, &flat, r->fl + r->n_fl, per);
    int cnt = n;
    if (!whole) { /* clipped: the loop and its attributes cut by every constraint */
        int e = smooth_clip(b, rc, n, per, &cnt);
        if (e)
            return e;
    }
    a->style = STYLE_SMOOTH;
    a->fl = r->n_fl;
    a->nx = per;
    r->n_fl += (size_t)per * (size_t)cnt;
    if (smooth_ctx(r, a, phong, lit, &ctx))
        return 300;
    return whole ? 0 : 2;
}

static int build_area(build *b, const gks_prim *prim, int retain)
{
    ws_classic *r = b->r;
    const gks_prim_attrs *pa = &prim->attrs;
    size_t pt0 = r->n_pt, cnt0 = r->n_cnt, attr0 = r->n_attr, fl0 = r->n_fl;
    rec rc = { .kind = REC_AREA, .overlay = pa->hlhsr_id != 0, .pt = pt0, .cnt = cnt0 };
    area_colour(b->ws, prim, b->v, rc.rgb);
    rattr a;
    memset(&a, 0, sizeof a);
    a.linetype = GKS_RASTER_LT_SOLID;
    a.width = r->px_per_unit;
    if (pa->int_style == GSTYLE_SOLID) {
        a.style = GKS_RASTER_SOLID;
    } else if (pa->int_style == GSTYLE_HATCH) {
        a.style = GKS_RASTER_HATCH;
        a.hatch = pa->style_ind <= -1 && pa->style_ind >= GKS_RASTER_HATCH_LAST ? pa->style_ind
                                                                                : -1;
    } else if (pa->int_style == GSTYLE_PAT) {
        int ok = pattern_set(r, b->v, pa, &a);
        if (ok < 0)
            return 300;
        a.style = ok ? GKS_RASTER_PATTERN : GKS_RASTER_SOLID;
    } else {
        a.style = STYLE_HOLLOW;
    }
    if (pa->edge_flag) {
        a.edge = 1;
        a.edgetype = type_or_solid(pa->edgetype);
        a.edgewidth = scale_or_one(pa->edgewidth) * r->px_per_unit;
        a.edge_rgb[0] = (float)pa->edge_colour.red;
        a.edge_rgb[1] = (float)pa->edge_colour.green;
        a.edge_rgb[2] = (float)pa->edge_colour.blue;
    }
    int se = 1;
    if (prim->vnormals || prim->vcolours) {
        se = smooth_setup(b, prim, &a, &rc);
        if (se == 300)
            return 300;
    }
    int e = attr_push(r, &a, &rc.attr);
    if (!e && prim->n_points >= 3 && se != 2)
        e = add_loops(b, prim->pts, prim->n_loops, prim->loop_counts, &b->v->clip, &rc);
    if (e)
        return e;
    size_t n_fill_pts = r->n_pt - pt0;
    double w = a.edge ? a.edgewidth : r->px_per_unit;
    rc.zbias = rc.n_fill ? edge_bias(r->pts + pt0, r->cnts + cnt0, rc.n_fill, w)
                         : (float)WS_CLASSIC_HL_BIAS;
    /* the boundary: HOLLOW, the edge flag, and the outlines of hidden-line mode */
    if (a.style == STYLE_HOLLOW || a.edge || b->ws->hlhsr_mode == GHLHSR_HIDDEN_LINE) {
        int fill_loops = rc.n_fill;
        rc.n_fill = 0;
        size_t off = 0;
        build eb = *b;
        eb.fb = NULL;
        rec er = rc;
        er.kind = REC_LINE;
        for (int k = 0; k < prim->n_loops && !e; k++) {
            int c = prim->loop_counts[k];
            if (c >= 2)
                e = add_pieces(&eb, prim->pts + off, (size_t)c, 1, &er);
            off += (size_t)(c > 0 ? c : 0);
        }
        rc.n_fill = fill_loops;
        rc.n_edge = er.n_fill;
        rc.outlined = 1;
        if (e)
            return e;
    }
    mean_key(r, &rc, n_fill_pts ? n_fill_pts : r->n_pt - pt0);
    return rec_finish(b, &rc, pt0, cnt0, attr0, fl0, retain);
}

static int build_cell(build *b, const gks_prim *prim, int retain)
{
    ws_classic *r = b->r;
    if (prim->cell_nx < 1 || prim->cell_ny < 1 || !prim->cells ||
        (size_t)prim->cell_nx > SIZE_MAX / 3 / (size_t)prim->cell_ny)
        return 0;
    size_t pt0 = r->n_pt, cnt0 = r->n_cnt, attr0 = r->n_attr, fl0 = r->n_fl;
    rec rc = { .kind = REC_CELL, .overlay = prim->attrs.hlhsr_id != 0, .pt = pt0,
               .cnt = cnt0 };
    /* the corners o = P, pu = R (end of the first row), pv = P + Q - R, in DC */
    const Gpoint3 *P = &prim->cell_p, *Q = &prim->cell_q, *R = &prim->cell_r;
    Gpoint3 V = { P->x + Q->x - R->x, P->y + Q->y - R->y, P->z + Q->z - R->z };
    Gpoint3 par[4] = { *P, *R, *Q, V };
    double c0[3], c1[3], c2[3];
    if (!ndc_to_dc(b->v, P, c0) || !ndc_to_dc(b->v, R, c1) || !ndc_to_dc(b->v, Q, c2))
        return 0;
    /* the clip box of CELL ARRAY (NDC3): the parallelogram is clipped in NDC3 first
     * (a convex 4-gon cut by 6 planes keeps at most 10 vertices) */
    Gpoint3 clipped[16];
    const Gpoint3 *loop = par;
    int nl = 4;
    if (prim->clip) {
        gks_xform_clip nc;
        gks_xform_clip_init(&nc);
        if (gks_xform_clip_add_box(&nc, prim->clip_box, GKS_XFORM_CLIP_ALL))
            return 0;
        double hin[4][4], hout[16][4];
        for (int i = 0; i < 4; i++) {
            hin[i][0] = par[i].x; hin[i][1] = par[i].y; hin[i][2] = par[i].z; hin[i][3] = 1;
        }
        size_t l4 = 4, olen = 0, nout = 0;
        if (gks_xform_clip_polygon(&nc, 1, &l4, (const double (*)[4])hin, hout, 16, &olen,
                                   &nout) || olen < 3)
            return 0;
        for (size_t i = 0; i < olen; i++)
            clipped[i] = (Gpoint3){ hout[i][0], hout[i][1], hout[i][2] };
        loop = clipped;
        nl = (int)olen;
    }
    if (GROW(r, pts, cap_pt, r->n_pt + 3))
        return 300;
    r->pts[r->n_pt++] = (gks_raster_pt){ c0[0], c0[1], c0[2] };
    r->pts[r->n_pt++] = (gks_raster_pt){ c1[0], c1[1], c1[2] };
    r->pts[r->n_pt++] = (gks_raster_pt){ c0[0] + c2[0] - c1[0], c0[1] + c2[1] - c1[1],
                                         c0[2] + c2[2] - c1[2] };
    size_t nc = (size_t)prim->cell_nx * (size_t)prim->cell_ny;
    rattr a;
    memset(&a, 0, sizeof a);
    a.nx = prim->cell_nx;
    a.ny = prim->cell_ny;
    a.fl = r->n_fl;
    if (GROW(r, fl, cap_fl, r->n_fl + 3 * nc))
        return 300;
    ws_shade sh;
    ws_shade_area(b->ws, prim, &sh);
    for (size_t i = 0; i < nc; i++) {
        Grgb c = ws_shade_apply(&sh, &prim->cells[i]);
        r->fl[r->n_fl + 3 * i] = (float)c.red;
        r->fl[r->n_fl + 3 * i + 1] = (float)c.green;
        r->fl[r->n_fl + 3 * i + 2] = (float)c.blue;
    }
    r->n_fl += 3 * nc;
    int e = attr_push(r, &a, &rc.attr);
    if (!e)
        e = add_loops(b, loop, 1, &nl, &b->v->clip, &rc);
    if (e)
        return e;
    mean_key(r, &rc, r->n_pt - pt0);
    return rec_finish(b, &rc, pt0, cnt0, attr0, fl0, retain);
}

static int build_line(build *b, const gks_prim *prim, int retain)
{
    ws_classic *r = b->r;
    const gks_prim_attrs *pa = &prim->attrs;
    size_t pt0 = r->n_pt, cnt0 = r->n_cnt, attr0 = r->n_attr, fl0 = r->n_fl;
    int marker = prim->kind == GKS_PRIM_POLYMARKER;
    rec rc = { .kind = marker ? REC_MARKER : REC_LINE, .overlay = pa->hlhsr_id != 0,
               .pt = pt0, .cnt = cnt0, .zbias = (float)WS_CLASSIC_HL_BIAS };
    rc.rgb[0] = (float)prim->colour.red;
    rc.rgb[1] = (float)prim->colour.green;
    rc.rgb[2] = (float)prim->colour.blue;
    rattr a;
    memset(&a, 0, sizeof a);
    a.linetype = pa->text ? GKS_RASTER_LT_SOLID : type_or_solid(pa->linetype);
    a.width = (pa->text || marker ? 1.0 : scale_or_one(pa->linewidth)) * r->px_per_unit;
    a.marker_type = pa->marker_type >= 1 && pa->marker_type <= 5 ? pa->marker_type : 3;
    a.marker_size =
        WS_CLASSIC_NOMINAL_MARKER_SIZE * scale_or_one(pa->marker_size) * r->px_per_unit;
    int e = attr_push(r, &a, &rc.attr);
    if (e)
        return e;
    build lb = *b;
    lb.fb = retain ? NULL : b->fb;
    if (prim->n_points >= (marker ? 1 : 2))
        e = add_pieces(&lb, prim->pts, (size_t)prim->n_points, 0, &rc);
    if (e)
        return e;
    if (!retain) { /* drawn chunk by chunk */
        r->n_attr = attr0;
        return 0;
    }
    mean_key(r, &rc, r->n_pt - pt0);
    return rec_finish(b, &rc, pt0, cnt0, attr0, fl0, 1);
}

int ws_classic_prim(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb, const gks_prim *prim)
{
    if (!r || !ws || (!fb && !r->keep) || !prim || prim->n_points < 0 || prim->n_loops < 0 ||
        (prim->n_points > 0 && !prim->pts))
        return 0;
    if (prim->kind == GKS_PRIM_FILL_AREA) {
        if (!prim->loop_counts || prim->n_loops < 1)
            return 0;
        long long s = 0;
        for (int k = 0; k < prim->n_loops; k++)
            s += prim->loop_counts[k] > 0 ? prim->loop_counts[k] : 0;
        if (s != prim->n_points)
            return 0; /* inconsistent counts: nothing, never a read beyond pts */
    }
    const view_cache *v = view_get(r, ws, prim->view_ind);
    if (!v->ok)
        return 0; /* degenerate transformation: nothing visible */
    int mode = ws->hlhsr_mode;
    int retain = r->keep || prim->attrs.hlhsr_id != 0 || mode == GHLHSR_HIDDEN_LINE ||
                 mode == GHLHSR_PAINTER;
    build b = { .r = r, .v = v, .fb = fb, .ws = ws, .vi = prim->view_ind };
    size_t n_pt = r->n_pt, n_cnt = r->n_cnt, n_attr = r->n_attr, n_fl = r->n_fl;
    int e = 0;
    switch (prim->kind) {
    case GKS_PRIM_FILL_AREA:
        e = build_area(&b, prim, retain);
        break;
    case GKS_PRIM_CELL_ARRAY:
        e = build_cell(&b, prim, retain);
        break;
    case GKS_PRIM_POLYLINE:
    case GKS_PRIM_POLYMARKER:
        e = build_line(&b, prim, retain);
        break;
    }
    if (e) { /* storage overflow: the list as before the primitive */
        r->n_pt = n_pt;
        r->n_cnt = n_cnt;
        r->n_attr = n_attr;
        r->n_fl = n_fl;
    }
    return e;
}

/* --- drawing records --------------------------------------------------------------------- */
/* The first storage failure of the raster calls of a record (e keeps the first). */
static int nomem(int e, int raster_rc)
{
    return e ? e : raster_rc == GKS_RASTER_E_NOMEM ? 300 : 0;
}

/* e, or v when e is 0 (the first of two GKS error numbers). */
static int first_err(int e, int v)
{
    return e ? e : v;
}

/* Pieces of a line record, counts cnt[0..n-1] from pts (negative = continues). 0 or 300. */
static int draw_pieces(gks_raster_fb *fb, const gks_raster_pt *pts, const int *cnt, int n,
                       const gks_raster_line *la, gks_raster_stroke *st)
{
    size_t off = 0;
    int e = 0;
    for (int k = 0; k < n; k++) {
        int c = cnt[k] < 0 ? -cnt[k] : cnt[k];
        if (cnt[k] >= 0)
            *st = (gks_raster_stroke){ 0 };
        e = nomem(e, gks_raster_polyline_cont(fb, (size_t)c, pts + off, la, st));
        off += (size_t)c;
    }
    return e;
}

/* A marker record's n runs of markers. */
static int draw_markers(gks_raster_fb *fb, const gks_raster_pt *pts, const int *cnt, int n,
                        const rattr *a, const gks_raster_line *la)
{
    size_t off = 0;
    int e = 0;
    for (int k = 0; k < n; k++) {
        e = nomem(e, gks_raster_markers(fb, (size_t)cnt[k], pts + off, a->marker_type,
                                        a->marker_size, la));
        off += (size_t)cnt[k];
    }
    return e;
}

/* A smooth area's one loop of n points (STYLE_SMOOTH: per-vertex attributes at r->fl +
 * a->fl, a->nx floats each, the last 1/w; a->ny the shading context of a per-sample shaded
 * one, or -1). 0 or 300. */
static int draw_smooth(ws_classic *r, gks_raster_fb *fb, const rattr *a, const float *fl,
                       const gks_raster_pt *pts, int n, gks_raster_zmode zm)
{
    const int per = a->nx, nat = per - 1;
    double iw[64], *invw = n <= 64 ? iw : gks_alloc_array((size_t)n, sizeof *invw);
    float *at = gks_alloc_array((size_t)n * (size_t)nat, sizeof *at);
    if (!invw || !at) {
        if (invw != iw)
            gks_free(invw);
        gks_free(at);
        return 300;
    }
    const float *src = fl + a->fl;
    for (int i = 0; i < n; i++) {
        memcpy(at + (size_t)i * (size_t)nat, src + (size_t)i * (size_t)per,
               (size_t)nat * sizeof *at);
        invw[i] = src[(size_t)i * (size_t)per + (size_t)nat];
    }
    gks_raster_vattr va = { .n = nat, .v = at, .invw = invw,
                            .shade = a->ny >= 0 ? phong_sample : NULL,
                            .user = a->ny >= 0 ? &r->ctx[a->ny] : NULL };
    gks_raster_fill f = { .style = GKS_RASTER_SOLID, .zmode = zm };
    int e = nomem(0, gks_raster_fill_smooth(fb, n, pts, &va, &f));
    if (invw != iw)
        gks_free(invw);
    gks_free(at);
    return e;
}

/* An area record's interior in its style (HOLLOW and SMOOTH as SOLID; everything SOLID in
 * DRAW_HL_AREAS). */
static int draw_fill(gks_raster_fb *fb, const rref *x, int how, gks_raster_zmode zm)
{
    const rec *rc = &x->rc;
    const rattr *a = x->a;
    gks_raster_fill f = { .style = a->style == STYLE_HOLLOW || a->style == STYLE_SMOOTH
                                       ? GKS_RASTER_SOLID
                                       : (gks_raster_style)a->style,
                          .rgb = { rc->rgb[0], rc->rgb[1], rc->rgb[2] },
                          .hatch = a->hatch, .zmode = zm };
    if (how == DRAW_HL_AREAS)
        f.style = GKS_RASTER_SOLID;
    if (f.style == GKS_RASTER_PATTERN) {
        f.pat_nx = a->nx;
        f.pat_ny = a->ny;
        f.pat_rgb = x->fl + a->fl;
        memcpy(f.pat_ref, a->geo, 2 * sizeof(double));
        memcpy(f.pat_u, a->geo + 2, 2 * sizeof(double));
        memcpy(f.pat_v, a->geo + 4, 2 * sizeof(double));
    }
    return nomem(0, gks_raster_fill_area(fb, rc->n_fill, x->cnt, x->pts, &f));
}

/* An area record's lines after its interior: in DRAW_HL_LINES a record retained before the
 * mode became hidden line has its clipped loops drawn as outlines; else its edges (edge
 * attributes when the edge flag is on, the boundary of HOLLOW or hidden-line outlines in
 * the line attributes la). The edge pieces follow the n_fill_pts points of the loops. */
static int draw_area_lines(gks_raster_fb *fb, const rec *rc, const rattr *a,
                           const gks_raster_pt *pts, const int *cnt, size_t n_fill_pts,
                           int outline, gks_raster_zmode zm, gks_raster_line *la)
{
    int e = 0;
    if (!rc->outlined && outline) { /* retained before the mode became hidden line: */
        const gks_raster_pt *q = pts;    /* the clipped loops as outlines */
        la->zbias = rc->zbias;
        for (int k = 0; k < rc->n_fill; q += cnt[k], k++) {
            gks_raster_stroke ls = { 0 };
            gks_raster_pt close[2] = { q[cnt[k] - 1], q[0] };
            e = nomem(e, gks_raster_polyline_cont(fb, (size_t)cnt[k], q, la, &ls));
            e = nomem(e, gks_raster_polyline_cont(fb, 2, close, la, &ls));
        }
        return e;
    }
    if (rc->n_edge == 0)
        return 0;
    la->zbias = zm == GKS_RASTER_Z_NONE ? 0.0f : rc->zbias;
    if (a->edge) {
        la->rgb[0] = a->edge_rgb[0];
        la->rgb[1] = a->edge_rgb[1];
        la->rgb[2] = a->edge_rgb[2];
        la->type = a->edgetype;
        la->width = a->edgewidth;
    } else if (a->style != STYLE_HOLLOW && !outline) {
        return 0; /* outlines were built for another mode */
    }
    gks_raster_stroke es = { 0 };
    return draw_pieces(fb, pts + n_fill_pts, cnt + rc->n_fill, rc->n_edge, la, &es);
}

/* Draws a record. how: DRAW_PLAIN (no depth), DRAW_ZTEST (depth test; edges of areas
 * with the slope bias), DRAW_HL_AREAS (areas into the depth buffer only, nothing else),
 * DRAW_HL_LINES (everything but area interiors, depth-tested; areas as outlines). */
static int draw_rec(ws_classic *r, gks_raster_fb *fb, const rref *x, int how,
                    gks_raster_stroke *st)
{
    const rec *rc = &x->rc;
    if (rc->kind == REC_MARK) /* the back end draws it */
        return 0;
    const rattr *a = x->a;
    const gks_raster_pt *pts = x->pts;
    const int *cnt = x->cnt;
    gks_raster_zmode zm = how == DRAW_PLAIN ? GKS_RASTER_Z_NONE
                          : how == DRAW_HL_AREAS ? GKS_RASTER_Z_ONLY : GKS_RASTER_Z_TEST;
    gks_raster_line la = { .rgb = { rc->rgb[0], rc->rgb[1], rc->rgb[2] }, .width = a->width,
                           .type = a->linetype, .zmode = zm,
                           .zbias = how == DRAW_HL_LINES ? rc->zbias : 0.0f };
    if (how == DRAW_HL_AREAS && rc->kind != REC_AREA) /* areas only */
        return 0;
    if (rc->kind == REC_LINE)
        return draw_pieces(fb, pts, cnt, rc->n_fill, &la, st);
    if (rc->kind == REC_MARKER)
        return draw_markers(fb, pts, cnt, rc->n_fill, a, &la);
    if (rc->kind == REC_CELL) {
        gks_raster_fill f = { .zmode = zm };
        return nomem(0, gks_raster_cell_array_clipped(fb, &pts[0], &pts[1], &pts[2], a->nx,
                                                      a->ny, x->fl + a->fl, &f, rc->n_fill,
                                                      cnt, pts + 3));
    }
    /* area: interior, then boundary (HOLLOW) and edges */
    size_t n_fill_pts = 0;
    for (int k = 0; k < rc->n_fill; k++)
        n_fill_pts += (size_t)cnt[k];
    int outline = how == DRAW_HL_LINES, e = 0;
    if (rc->n_fill == 1 && !outline && a->style == STYLE_SMOOTH && how != DRAW_HL_AREAS &&
        cnt[0] >= 3)
        e = draw_smooth(r, fb, a, x->fl, pts, cnt[0], zm);
    else if (rc->n_fill && !outline && (a->style != STYLE_HOLLOW || how == DRAW_HL_AREAS))
        e = draw_fill(fb, x, how, zm);
    if (how == DRAW_HL_AREAS)
        return e;
    return first_err(e, draw_area_lines(fb, rc, a, pts, cnt, n_fill_pts, outline, zm, &la));
}

/* A painter sort entry: key, then the record's position (chunk << 32 | record: arrival
 * order; a chunk holds at most UINT32_MAX records). */
typedef struct key_idx { double key; uint64_t idx; } key_idx;

static int cmp_key(const void *pa, const void *pb)
{
    const key_idx *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->idx > b->idx) - (a->idx < b->idx);
}

/* The display list's chunks into r->chunks, in order. 0 or 300. */
static int chunks_build(ws_classic *r)
{
    size_t n = 0;
    for (const ws_dl_chunk *c = ws_dlist_first(r->dl); c; c = c->next)
        n++;
    if (GROW(r, chunks, cap_chunks, n))
        return 300;
    n = 0;
    for (const ws_dl_chunk *c = ws_dlist_first(r->dl); c; c = c->next)
        r->chunks[n++] = c;
    r->n_chunks = n;
    return 0;
}

/* Record d of chunk c with its data. */
static rref ref_of(const ws_dl_chunk *c, const ws_dl_rec *d)
{
    srec s;
    memcpy(&s, c->attr + d->data, sizeof s);
    rref x;
    x.rc = (rec){ .kind = (unsigned char)d->kind, .overlay = s.overlay,
                  .outlined = s.outlined, .rgb = { s.rgb[0], s.rgb[1], s.rgb[2] },
                  .zbias = s.zbias, .key = s.key, .n_fill = s.n_fill,
                  .n_edge = d->n_loops - s.n_fill };
    if (d->kind == REC_MARK)
        memcpy(&x.rc.attr, c->attr + d->data + sizeof s, sizeof x.rc.attr);
    x.a = d->attr_size ? (const rattr *)(const void *)(c->attr + d->attr) : NULL;
    x.fl = (const float *)(const void *)(c->attr + d->attr + sizeof(rattr));
    x.pts = (const gks_raster_pt *)(const void *)(c->xyz + 3 * (size_t)d->vtx);
    x.cnt = c->cnt + d->cnt + d->n_facets;
    return x;
}

/* The classic record after *it (the tracer's records are not this renderer's) into *x, *it
 * past it; 0 at the end. A cursor starts at { 0, 0 } (after chunks_build). */
static int rec_next(const ws_classic *r, cursor *it, rref *x)
{
    for (; it->chunk < r->n_chunks; it->chunk++, it->k = 0) {
        const ws_dl_chunk *c = r->chunks[it->chunk];
        while (it->k < c->n_rec) {
            const ws_dl_rec *d = &c->rec[it->k++];
            if (d->reader == WS_DL_CLASSIC) {
                *x = ref_of(c, d);
                return 1;
            }
        }
    }
    return 0;
}

/* Painter's order of the classic records of r->chunks that are not overlays: by key (mean
 * DC depth, farthest first), ties in the order of arrival. Returns the sorted entries (caller
 * frees) and their number in *m, or NULL (300). */
static key_idx *painter_order(const ws_classic *r, size_t *m)
{
    key_idx *ki = gks_alloc_array(ws_dlist_count(r->dl, WS_DL_CLASSIC), sizeof *ki);
    if (!ki)
        return NULL;
    size_t n = 0;
    for (size_t ci = 0; ci < r->n_chunks; ci++) {
        const ws_dl_chunk *c = r->chunks[ci];
        for (size_t k = 0; k < c->n_rec; k++) {
            const ws_dl_rec *d = &c->rec[k];
            srec s;
            if (d->reader != WS_DL_CLASSIC)
                continue;
            memcpy(&s, c->attr + d->data, sizeof s);
            if (!s.overlay)
                ki[n++] = (key_idx){ isfinite(s.key) ? s.key : 0.0,
                                     (uint64_t)ci << 32 | (uint64_t)k };
        }
    }
    qsort(ki, n, sizeof *ki, cmp_key);
    *m = n;
    return ki;
}

/* The record of painter entry k with its data. */
static rref ref_key(const ws_classic *r, const key_idx *k)
{
    const ws_dl_chunk *c = r->chunks[k->idx >> 32];
    return ref_of(c, &c->rec[k->idx & UINT32_MAX]);
}

static int compose(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb, gks_raster_fb **out,
                   int overlays);

int ws_classic_compose(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb,
                          gks_raster_fb **out)
{
    return compose(r, ws, fb, out, 1);
}

int ws_classic_compose_base(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb,
                               gks_raster_fb **out)
{
    return compose(r, ws, fb, out, 0);
}

static int compose(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb, gks_raster_fb **out,
                   int overlays)
{
    *out = fb;
    if (ws_dlist_count(r->dl, WS_DL_CLASSIC) == 0)
        return 0;
    if (chunks_build(r)) {
        *out = NULL;
        return 300;
    }
    gks_raster_fb *c = r->composed;
    if (!c || c->width != fb->width || c->height != fb->height || c->ss != fb->ss) {
        gks_raster_fb_free(c);
        c = r->composed = gks_raster_fb_create(fb->width, fb->height, fb->ss);
        if (!c) {
            *out = NULL;
            return 300;
        }
    }
    size_t ns = (size_t)fb->w * (size_t)fb->h;
    memcpy(c->rgb, fb->rgb, 3 * ns * sizeof *c->rgb);
    memcpy(c->z, fb->z, ns * sizeof *c->z);
    int mode = ws->hlhsr_mode, e = 0; /* the first storage failure: the picture lacks it */
    rref x;
    if (mode == GHLHSR_PAINTER) {
        size_t n;
        key_idx *ki = painter_order(r, &n);
        if (!ki) {
            *out = NULL;
            return 300;
        }
        for (size_t i = 0; i < n; i++) {
            gks_raster_stroke st = { 0 };
            const rref x = ref_key(r, &ki[i]);
            e = first_err(e, draw_rec(r, c, &x, DRAW_PLAIN, &st));
        }
        gks_free(ki);
    } else if (mode == GHLHSR_HIDDEN_LINE) {
        for (int pass = 0; pass < 2; pass++)
            for (cursor it = { 0, 0 }; rec_next(r, &it, &x);) {
                gks_raster_stroke st = { 0 };
                if (!x.rc.overlay)
                    e = first_err(e, draw_rec(r, c, &x, pass ? DRAW_HL_LINES : DRAW_HL_AREAS,
                                              &st));
            }
    } else { /* retained under another mode, the mode changed within the frame */
        for (cursor it = { 0, 0 }; rec_next(r, &it, &x);) {
            gks_raster_stroke st = { 0 };
            if (!x.rc.overlay)
                e = first_err(e, draw_rec(r, c, &x, immediate_mode(ws), &st));
        }
    }
    for (cursor it = { 0, 0 }; overlays && rec_next(r, &it, &x);) {
        gks_raster_stroke st = { 0 };
        if (x.rc.overlay)
            e = first_err(e, draw_rec(r, c, &x, DRAW_PLAIN, &st));
    }
    *out = c;
    return e;
}

int ws_classic_keep(ws_classic *r, const gks_ws *ws, const gks_prim *prim)
{
    if (!r)
        return 0;
    r->keep = 1;
    int e = ws_classic_prim(r, ws, NULL, prim);
    r->keep = 0;
    return e;
}

int ws_classic_keep_mark(ws_classic *r, size_t id, double key, int overlay)
{
    const rec rc = { .kind = REC_MARK, .overlay = overlay != 0, .key = key, .attr = id };
    const ws_dl_need need = { .data_size = sizeof(srec) + sizeof id };
    ws_dl_put put;
    if (ws_dlist_append(r->dl, WS_DL_CLASSIC, REC_MARK, 0, NULL, 0, &need, &put))
        return 300;
    srec_put(put.data, &rc);
    memcpy((unsigned char *)put.data + sizeof(srec), &id, sizeof id);
    return 0;
}

int ws_classic_view(ws_classic *r, const gks_ws *ws, int vi, double npc[4][4],
                       double dc[4][4], const gks_xform_clip **clip)
{
    const view_cache *v = view_get(r, ws, vi);
    if (!v->ok)
        return -1;
    memcpy(npc, v->npc, sizeof v->npc);
    memcpy(dc, v->dc, sizeof v->dc);
    *clip = &v->clip;
    return 0;
}

/* --- the frame's records for vector back ends (ws_classic_walk) ----------------------- */
typedef struct walk {
    ws_classic *r;
    ws_render_emit emit;
    void *ctx;
    const gks_raster_fb *depth; /* hidden-line mode: visibility of lines, else NULL */
} walk;

/* Is DC point (x, y, z) in front of the depth buffer (the raster's Z_TEST rule)? Outside
 * the buffer nothing hides it. */
static int visible(const gks_raster_fb *d, double x, double y, double z, float bias)
{
    double fx = floor(x), fy = floor(y);
    if (!(fx >= 0.0 && fy >= 0.0 && fx < d->w && fy < d->h))
        return 1;
    return z + bias >= d->z[(size_t)fy * (size_t)d->w + (size_t)fx];
}

static int emit_run(walk *w, ws_render_item *it, size_t n)
{
    if (n < 2)
        return 0;
    int c = (int)n;
    it->n_loops = 1;
    it->counts = &c;
    it->pts = w->r->vis;
    return w->emit(w->ctx, it);
}

/* A polyline piece pts[0..n-1] (closed: back to pts[0]) as its visible runs: every segment
 * is sampled at most half a pixel apart against the depth buffer; a run starts or ends
 * where the samples change. */
static int emit_visible(walk *w, ws_render_item *it, const gks_raster_pt *pts, size_t n,
                        int closed, float bias)
{
    ws_classic *r = w->r;
    size_t run = 0; /* points of the open run in r->vis */
    size_t nseg = closed ? n : n - 1;
    for (size_t s = 0; s < nseg; s++) {
        const gks_raster_pt *a = &pts[s], *b = &pts[(s + 1) % n];
        double len = hypot(b->x - a->x, b->y - a->y);
        double steps = ceil(2.0 * len);
        size_t k_n = steps >= 1.0 && steps < 1e7 ? (size_t)steps : 1;
        for (size_t k = 0; k < k_n; k++) {
            double t = (k + 0.5) / (double)k_n;
            int v = visible(w->depth, a->x + t * (b->x - a->x), a->y + t * (b->y - a->y),
                            a->z + t * (b->z - a->z), bias);
            if (v == (run > 0))
                continue;
            double t0 = (double)k / (double)k_n;
            gks_raster_pt q = { a->x + t0 * (b->x - a->x), a->y + t0 * (b->y - a->y),
                                a->z + t0 * (b->z - a->z) };
            if (GROW(r, vis, cap_vis, run + 1))
                return 300;
            r->vis[run++] = q;
            if (!v) {
                int e = emit_run(w, it, run);
                run = 0;
                if (e)
                    return e;
            }
        }
        if (run) {
            if (GROW(r, vis, cap_vis, run + 1))
                return 300;
            r->vis[run++] = *b;
        }
    }
    return emit_run(w, it, run);
}

/* Line pieces cnt[0..n-1] from pts (negative count: continues the previous piece) as one
 * item, or with a depth buffer as their visible runs. */
static int emit_pieces(walk *w, ws_render_item *it, const gks_raster_pt *pts, const int *cnt,
                       int n, float bias)
{
    if (n <= 0)
        return 0;
    if (!w->depth) {
        it->n_loops = n;
        it->counts = cnt;
        it->pts = pts;
        return w->emit(w->ctx, it);
    }
    size_t off = 0;
    for (int k = 0; k < n; k++) {
        size_t c = (size_t)(cnt[k] < 0 ? -cnt[k] : cnt[k]);
        int e = emit_visible(w, it, pts + off, c, 0, bias);
        if (e)
            return e;
        off += c;
    }
    return 0;
}

static void line_item(ws_render_item *it, const ws_classic *r, const float rgb[3], int type,
                      double width)
{
    memset(it, 0, sizeof *it);
    it->kind = WS_ITEM_LINE;
    memcpy(it->rgb, rgb, sizeof it->rgb);
    it->linetype = type;
    it->width = width;
    it->unit = r->px_per_unit;
}

/* One record as items, in the order and with the choices of draw_rec; hl: the lines pass
 * of hidden-line mode (w->depth set). */
static int emit_rec(walk *w, const rref *x, int hl)
{
    ws_classic *r = w->r;
    const rec *rc = &x->rc;
    const rattr *a = x->a;
    const gks_raster_pt *pts = x->pts;
    const int *cnt = x->cnt;
    const gks_raster_fb *depth = w->depth;
    if (!hl)
        w->depth = NULL;
    ws_render_item it;
    int e = 0;
    if (rc->kind == REC_MARK) {
        memset(&it, 0, sizeof it);
        it.kind = WS_ITEM_MARK;
        it.mark = rc->attr;
        e = w->emit(w->ctx, &it);
        w->depth = depth;
        return e;
    }
    line_item(&it, r, rc->rgb, a->linetype, a->width);
    if (rc->kind == REC_LINE) {
        e = emit_pieces(w, &it, pts, cnt, rc->n_fill, rc->zbias);
    } else if (rc->kind == REC_MARKER) {
        it.kind = WS_ITEM_MARKERS;
        it.marker_type = a->marker_type;
        it.marker_size = a->marker_size;
        size_t off = 0;
        for (int k = 0; k < rc->n_fill && !e; off += (size_t)cnt[k], k++) {
            const gks_raster_pt *p = pts + off;
            size_t m = (size_t)cnt[k];
            if (w->depth) { /* a marker is visible when its centre is */
                if (GROW(r, vis, cap_vis, m)) {
                    e = 300;
                    break;
                }
                size_t j = 0;
                for (size_t i = 0; i < m; i++)
                    if (visible(w->depth, p[i].x, p[i].y, p[i].z, (float)WS_CLASSIC_HL_BIAS))
                        r->vis[j++] = p[i];
                p = r->vis;
                m = j;
            }
            if (m == 0)
                continue;
            int c = (int)m;
            it.n_loops = 1;
            it.counts = &c;
            it.pts = p;
            e = w->emit(w->ctx, &it);
        }
    } else if (rc->kind == REC_CELL) {
        memset(&it, 0, sizeof it);
        it.kind = WS_ITEM_CELLS;
        it.unit = r->px_per_unit;
        it.cell_o = pts[0];
        it.cell_u = pts[1];
        it.cell_v = pts[2];
        it.nx = a->nx;
        it.ny = a->ny;
        it.rgb_list = x->fl + a->fl;
        it.n_loops = rc->n_fill;
        it.counts = cnt;
        it.pts = pts + 3;
        e = w->emit(w->ctx, &it);
    } else {
        size_t n_fill_pts = 0;
        for (int k = 0; k < rc->n_fill; k++)
            n_fill_pts += (size_t)cnt[k];
        if (rc->n_fill && !hl && a->style != STYLE_HOLLOW) {
            memset(&it, 0, sizeof it);
            it.kind = WS_ITEM_AREA;
            memcpy(it.rgb, rc->rgb, sizeof it.rgb);
            it.unit = r->px_per_unit;
            it.style = a->style;
            it.hatch = a->hatch;
            if (a->style == GKS_RASTER_PATTERN) {
                it.nx = a->nx;
                it.ny = a->ny;
                it.rgb_list = x->fl + a->fl;
                memcpy(it.pat_geo, a->geo, sizeof it.pat_geo);
            }
            it.n_loops = rc->n_fill;
            it.counts = cnt;
            it.pts = pts;
            e = w->emit(w->ctx, &it);
        }
        line_item(&it, r, rc->rgb, a->linetype, a->width);
        if (e) {
        } else if (!rc->outlined && hl) { /* retained before the mode became hidden line */
            const gks_raster_pt *q = pts;
            for (int k = 0; k < rc->n_fill && !e; q += cnt[k], k++)
                e = emit_visible(w, &it, q, (size_t)cnt[k], 1, rc->zbias);
        } else if (rc->n_edge > 0 && (a->edge || a->style == STYLE_HOLLOW || hl)) {
            if (a->edge) {
                memcpy(it.rgb, a->edge_rgb, sizeof it.rgb);
                it.linetype = a->edgetype;
                it.width = a->edgewidth;
            }
            e = emit_pieces(w, &it, pts + n_fill_pts, cnt + rc->n_fill, rc->n_edge, rc->zbias);
        }
    }
    w->depth = depth;
    return e;
}

int ws_classic_walk(ws_classic *r, int mode, int width, int height, ws_render_emit emit,
                       void *ctx)
{
    if (ws_dlist_count(r->dl, WS_DL_CLASSIC) == 0)
        return 0;
    if (chunks_build(r))
        return 300;
    walk w = { .r = r, .emit = emit, .ctx = ctx };
    int e = 0;
    rref x;
    if (mode == GHLHSR_PAINTER) {
        size_t n;
        key_idx *ki = painter_order(r, &n);
        if (!ki)
            return 300;
        for (size_t i = 0; i < n && !e; i++) {
            x = ref_key(r, &ki[i]);
            e = emit_rec(&w, &x, 0);
        }
        gks_free(ki);
    } else if (mode == GHLHSR_HIDDEN_LINE) {
        gks_raster_fb *d = r->depth;
        if (!d || d->width != width || d->height != height) {
            gks_raster_fb_free(d);
            d = r->depth = gks_raster_fb_create(width, height, 1);
            if (!d)
                return 300;
        }
        gks_raster_fb_clear(d, NULL);
        for (cursor it = { 0, 0 }; rec_next(r, &it, &x);) {
            gks_raster_stroke st = { 0 };
            if (!x.rc.overlay)
                draw_rec(r, d, &x, DRAW_HL_AREAS, &st);
        }
        w.depth = d;
        for (cursor it = { 0, 0 }; !e && rec_next(r, &it, &x);)
            if (!x.rc.overlay)
                e = emit_rec(&w, &x, 1);
        w.depth = NULL;
    } else {
        for (cursor it = { 0, 0 }; !e && rec_next(r, &it, &x);)
            if (!x.rc.overlay)
                e = emit_rec(&w, &x, 0);
    }
    for (cursor it = { 0, 0 }; !e && rec_next(r, &it, &x);)
        if (x.rc.overlay)
            e = emit_rec(&w, &x, 0);
    return e;
}
