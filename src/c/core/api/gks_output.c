/* SPDX-License-Identifier: MIT */
/*
 * gks_output.c -- output primitives (ISO 7942 5.3 and their GKS-3D forms): POLYLINE (3),
 * POLYMARKER (3), TEXT (3), FILL AREA (3), FILL AREA SET (3), CELL ARRAY (3),
 * GENERALIZED DRAWING PRIMITIVE (3). The transformations they go through are set in
 * gks_transform.c.
 *
 * Each primitive: state check, argument checks (standard order), then the
 * workstation-independent stages: WC3 -> NDC3 by the current normalization
 * transformation, clipping at the viewport 3 when the clipping indicator is on (in the
 * core, gks_xform), then for each active workstation the attributes are resolved
 * (gks_attr.h) and the driver gets the primitive.
 * Non-finite coordinates never reach a driver: a polyline is broken at such a point, a
 * marker at such a point is dropped, an area or cell array containing one is not drawn
 * (GKS defines no error for them). Markers are clipped by their centres; TEXT becomes
 * polyline strokes (gks_text_layout.c) generated per workstation (the text bundle may differ)
 * and clipped like polylines. CELL ARRAY is the one primitive clipped by the driver
 * (prim.clip, prim.clip_box).
 */
#include "gks_alloc.h"
#include "gks_attr.h"
#include "gks_error.h"
#include "gks_export.h"
#include "gks_gdp.h"
#include "gks_mf_record.h"
#include "gks_output_data.h"
#include "gks_output_int.h"
#include "gks_output_rec.h"
#include "gks_seg_store.h"
#include "gks_segment.h"
#include "gks_state.h"
#include "gks_text_layout.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

/* ------------------------------------------------------------------ normalization */

/* The open segment, or NULL. */
static gks_segment *open_segment(void)
{
    const gks_state_list *sl = gks_ctx()->sl;
    return sl->open_seg ? gks_seg_find(sl->segs, sl->open_seg) : NULL;
}

/* A context mapping by m and clipping at box (when clip_on). 0 or -1 (degenerate). */
static int norm_from(norm_ctx *nc, const double m[3][4], const double box[6], int clip_on)
{
    memcpy(nc->m, m, sizeof nc->m);
    memcpy(nc->n, m, sizeof nc->n);
    memcpy(nc->pn, m, sizeof nc->pn);
    memcpy(nc->pat, m, sizeof nc->pat);
    memcpy(nc->box, box, sizeof nc->box);
    nc->clip_on = clip_on;
    nc->seg = NULL;
    gks_xform_clip_init(&nc->clip);
    if (clip_on && gks_xform_clip_add_box(&nc->clip, box, GKS_XFORM_CLIP_ALL))
        return -1;
    return 0;
}

/* The current state's context: WC3 -> NDC3 by the current normalization transformation,
 * then the open segment's transformation (if a segment is open), clipping at the current
 * viewport 3 when the clipping indicator is on. For a primitive INTERPRET ITEM performs
 * (ov, the argument of the gks_output_rec_* entries), the recorded normalization and
 * clipping volume replace the current ones, and NDC3 points enter through the identity.
 * 0, or 308 if the normalization cannot be represented (gks_xform_norm_tran3). */
/* The last current-state context and what it was made from (the current window and
 * viewport 3, clipping indicator, open segment and its transformation): a primitive drawn
 * under the same settings takes it as it is instead of making it again (a FILL AREA 3 per
 * triangle spent a fifth of its call on this). Compared by value, so no setting function
 * needs to know of it; not used while INTERPRET ITEM overrides the context. */
static struct {
    int valid;
    double w[6], v[6];
    int clip_on;
    const gks_segment *seg;
    double stran[3][4];
    norm_ctx nc;
} norm_cache;

static int norm_setup_xf(norm_ctx *nc, const gks_rec_xf *ov)
{
    static const double id[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
    const gks_state_list *sl = gks_ctx()->sl;
    double n[3][4], box[6], w[6];
    int clip_on;
    gks_segment *seg = open_segment();
    if (ov) {
        memcpy(n, ov->norm, sizeof n);
        memcpy(box, ov->box, sizeof box);
        clip_on = ov->clip_on;
    } else {
        gks_limit3_array(&sl->tran[sl->cur_tnr].win, w);
        gks_limit3_array(&sl->tran[sl->cur_tnr].vp, box);
        clip_on = sl->clip_ind == GIND_CLIP;
        if (norm_cache.valid && norm_cache.clip_on == clip_on && norm_cache.seg == seg &&
            memcmp(norm_cache.w, w, sizeof w) == 0 && memcmp(norm_cache.v, box, sizeof box) == 0 &&
            (!seg || memcmp(norm_cache.stran, seg->tran, sizeof norm_cache.stran) == 0)) {
            *nc = norm_cache.nc;
            return 0;
        }
        norm_cache.valid = 0;
        if (gks_xform_norm_tran3(w, box, n)) /* gks_cur_norm_matrix */
            return 308;
    }
    const double (*pm)[4] = ov && ov->ndc_pts ? id : (const double (*)[4])n;
    if (norm_from(nc, pm, box, clip_on))
        return 308;
    nc->seg = seg;
    memcpy(nc->n, n, sizeof nc->n);
    memcpy(nc->pat, n, sizeof nc->pat);
    if (seg) {
        gks_xform_mat34_multiply(seg->tran, pm, nc->m);
        gks_xform_mat34_multiply(seg->tran, n, nc->pat);
    }
    if (!ov) {
        memcpy(norm_cache.w, w, sizeof w);
        memcpy(norm_cache.v, box, sizeof box);
        norm_cache.clip_on = clip_on;
        norm_cache.seg = seg;
        if (seg)
            memcpy(norm_cache.stran, seg->tran, sizeof norm_cache.stran);
        norm_cache.nc = *nc;
        norm_cache.valid = 1;
    }
    return 0;
}

static int norm_setup(norm_ctx *nc)
{
    return norm_setup_xf(nc, NULL);
}

/* Metafile output (gks_mf_record.h): the primitive as the active MO workstations record
 * it. 0: an error was reported and the world changed; the caller returns at once. */
static GKS_MUST_CHECK int mf_out(int fctid, const norm_ctx *nc, gks_mf_prim p)
{
    if (!gks_mf_on())
        return 1;
    p.pn = (const double (*)[4])nc->pn;
    p.norm = (const double (*)[4])nc->n;
    p.box = nc->box;
    p.clip_on = nc->clip_on;
    return gks_mf_prim_write(fctid, &p);
}

/* ------------------------------------------------------------------ targets */

static void target_current(target *t, const norm_ctx *nc)
{
    const gks_segment *seg = nc->seg;
    memset(t, 0, sizeof *t);
    t->a = &gks_ctx()->sl->attrs;
    memcpy(t->pat_m, nc->pat, sizeof t->pat_m);
    t->done = seg && !seg->vis; /* an invisible open segment: stored, not drawn */
}

/* WC3 -> homogeneous NDC3; 1 if finite. */
static int to_ndc(const norm_ctx *nc, const double wc[3], double h[4])
{
    gks_xform_mat34_point(nc->m, wc, h);
    h[3] = 1.0;
    return isfinite(h[0]) && isfinite(h[1]) && isfinite(h[2]);
}

/* A point list in WC: 2-D (z = 0), 3-D, or double triples. */
typedef struct {
    const Gpoint *p2;
    const Gpoint3 *p3;
    const double (*d3)[3];
} pt_src;

static void src_get(const pt_src *s, size_t i, double o[3])
{
    if (s->p2) {
        o[0] = s->p2[i].x; o[1] = s->p2[i].y; o[2] = 0.0;
    } else if (s->p3) {
        o[0] = s->p3[i].x; o[1] = s->p3[i].y; o[2] = s->p3[i].z;
    } else {
        o[0] = s->d3[i][0]; o[1] = s->d3[i][1]; o[2] = s->d3[i][2];
    }
}

/* ------------------------------------------------------------------ growing piece lists */
typedef struct {
    Gpoint3 *pts;
    size_t n, cap;
    int *len;                  /* points of each piece */
    size_t np, capp;
} pieces;

static void pieces_free(pieces *b)
{
    gks_free(b->pts);
    gks_free(b->len);
    memset(b, 0, sizeof *b);
}

static int push_pt(pieces *b, const double h[4])
{
    if (gks_grow(&b->pts, &b->cap, b->n + 1, sizeof *b->pts))
        return 300;
    if (b->np == 0 || b->len[b->np - 1] == INT32_MAX)
        return 300;
    b->pts[b->n++] = (Gpoint3){ h[0], h[1], h[2] };
    b->len[b->np - 1]++;
    return 0;
}

static int new_piece(pieces *b)
{
    if (gks_grow(&b->len, &b->capp, b->np + 1, sizeof *b->len))
        return 300;
    b->len[b->np++] = 0;
    return 0;
}

/* Clip the segment a-b to the viewport box (clipping on) plane by plane, each
 * intersection computed from the segment already shortened by the previous planes and
 * the clipped coordinate set exactly on the plane, so a segment from -1e30 to 1e30 keeps
 * its visible part. The xform clipper (gks_xform_clip_*: the areas here, the
 * drivers' view clip) keeps it too, computing each crossing from the nearer end, but does
 * not put the clipped coordinate exactly on the plane; replacing this one by it may move
 * pixels of the reference pictures and is left open.
 * Returns 1 if a part survives; *moved_a / *moved_b say whether an end was moved. */
static int clip_segment(const norm_ctx *nc, double a[3], double b[3], int *moved_a,
                        int *moved_b)
{
    *moved_a = *moved_b = 0;
    if (!nc->clip_on)
        return 1;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            double lim = nc->box[2 * axis + side];
            double sg = side ? -1.0 : 1.0; /* inside: sg * (x - lim) >= 0 */
            double da = sg * (a[axis] - lim), db = sg * (b[axis] - lim);
            if (da < 0 && db < 0)
                return 0;
            if (da >= 0 && db >= 0)
                continue;
            double t = da / (da - db);
            double *moved = da < 0 ? a : b;
            const double *p = da < 0 ? a : b, *q = da < 0 ? b : a;
            double tt = da < 0 ? t : 1.0 - t; /* from p towards q */
            double r[3];
            for (int k = 0; k < 3; k++)
                r[k] = p[k] + tt * (q[k] - p[k]);
            r[axis] = lim;
            if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(r[2]))
                return 0; /* overflow near DBL_MAX: treated as not visible */
            memcpy(moved, r, sizeof r);
            if (da < 0)
                *moved_a = 1;
            else
                *moved_b = 1;
        }
    return 1;
}

/* Whether the point h lies in the clipping region (closed box). */
static int point_visible(const norm_ctx *nc, const double h[3])
{
    if (!nc->clip_on)
        return 1;
    for (int k = 0; k < 3; k++)
        if (!(h[k] >= nc->box[2 * k] && h[k] <= nc->box[2 * k + 1]))
            return 0;
    return 1;
}

/* Clip the polyline s[0..n-1] (WC3) into b: normalized, clipped pieces of >= 2 points.
 * A segment touching a non-finite point is dropped (the polyline is broken there).
 * Returns 0 or 300. */
static int clip_polyline(const norm_ctx *nc, const pt_src *s, size_t n, pieces *b)
{
    double prev[4] = { 0 }, cur[4], wc[3];
    int prev_ok = 0, open = 0;
    for (size_t i = 0; i < n; i++) {
        src_get(s, i, wc);
        int ok = to_ndc(nc, wc, cur);
        if (ok && prev_ok) {
            double a[4] = { prev[0], prev[1], prev[2], 1 }, e[4] = { cur[0], cur[1], cur[2], 1 };
            int ma, mb;
            int vis = clip_segment(nc, a, e, &ma, &mb);
            if (vis) {
                if (!(open && !ma)) {
                    if (new_piece(b) || push_pt(b, a))
                        return 300;
                }
                if (push_pt(b, e))
                    return 300;
            }
            open = vis && !mb;
        } else {
            open = 0;
        }
        if (ok)
            memcpy(prev, cur, sizeof prev);
        prev_ok = ok;
    }
    return 0;
}

/* ------------------------------------------------------------------ dispatch */
/* Attributes every primitive carries, independent of the workstation. */
static void prim_common(gks_prim *p, const gks_cur_attrs *a)
{
    p->view_ind = a->view_ind;
    p->area_props[0] = a->area_props[0];
    p->area_props[1] = a->area_props[1];
    p->refl_eq[0] = a->refl_eq[0];
    p->refl_eq[1] = a->refl_eq[1];
    p->light_mask = a->light_mask;
    p->shading[0] = a->int_shad[0];
    p->shading[1] = a->int_shad[1];
}

#ifdef GKS_FAULT_INJECTION
/* Test hook, only in the test build of the modules (gks3d_test): every primitive a
 * driver receives is first passed to hook (NULL = none). */
GKS_TEST_API void gks_test_set_prim_hook(gks_prim_hook hook, void *ctx)
{
    gks_ctx()->prim_hook = hook;
    gks_ctx()->prim_hook_ctx = ctx;
}
#endif

static int send(gks_ws *ws, const gks_prim *p)
{
#ifdef GKS_FAULT_INJECTION
    gks_context *c = gks_ctx();
    if (c->prim_hook)
        c->prim_hook(c->prim_hook_ctx, ws->id, p);
#endif
    if (!ws->drv->primitive)
        return 0;
    int err = ws->drv->primitive(ws, p);
    if (!err)
        ws->disp_empty = GDISP_NOT_EMPTY;
    return err;
}

/* The next workstation of the target, or NULL when there is none left. */
static gks_ws *next_ws(target *t)
{
    if (t->done)
        return NULL;
    if (t->only) {
        t->done = 1;
        return t->only;
    }
    gks_context *c = gks_ctx();
    while (t->k < c->sl->n_open) {
        gks_ws *ws = c->ws[t->k++];
        if (ws->state == GWS_ACTIVE)
            return ws;
    }
    t->done = 1;
    return NULL;
}

/* Send the pieces as polylines (attributes already in p) to ws. */
static int send_pieces(gks_ws *ws, gks_prim *p, const pieces *b)
{
    size_t off = 0;
    for (size_t k = 0; k < b->np; k++) {
        p->n_points = b->len[k];
        p->pts = b->pts + off;
        p->loop_counts = &p->n_points;
        off += (size_t)b->len[k];
        if (p->n_points < 2)
            continue;
        int err = send(ws, p);
        if (err)
            return err;
    }
    return 0;
}

/* ------------------------------------------------------------------ segment recording */
/* Stores a primitive into the open segment (if any): geometry mapped to NDC3 by the
 * normalization only (nc->n), unclipped, with the current attributes, normalization and
 * clipping volume. Returns 0, 300 or 301. */
static int record(const norm_ctx *nc, gks_seg_prim *sp, const pt_src *src, size_t n)
{
    gks_segment *seg = nc->seg;
    if (!seg)
        return 0;
    gks_seg_bound *bound = gks_alloc_array(1, sizeof *bound);
    Gpoint3 *pts = gks_alloc_array(n ? n : 1, sizeof *pts);
    int err = 0;
    if (!bound || !pts) {
        err = 300;
        goto done;
    }
    memset(bound, 0, sizeof *bound); /* padding: snapshots are compared bytewise */
    bound->attrs = gks_ctx()->sl->attrs;
    memcpy(bound->norm, nc->n, sizeof bound->norm);
    for (size_t i = 0; i < n; i++) {
        double wc[3], o[3];
        src_get(src, i, wc);
        if (sp->kind == GKS_SEG_TEXT) /* TEXT keeps WC3 (position, two vectors) */
            memcpy(o, wc, sizeof o);
        else
            gks_xform_mat34_point(nc->pn, wc, o);
        pts[i] = (Gpoint3){ o[0], o[1], o[2] };
    }
    sp->pts = pts;
    sp->n_points = (int)n;
    sp->bound = bound;
    sp->clip = nc->clip_on;
    memcpy(sp->clip_box, nc->box, sizeof sp->clip_box);
    err = gks_seg_append(seg, sp);
done:
    gks_free(bound);
    gks_free(pts);
    return err;
}

/* ------------------------------------------------------------------ POLYLINE */
static int emit_polyline(const norm_ctx *nc, const pt_src *s, size_t n, target *t)
{
    pieces b = { 0 };
    int err = clip_polyline(nc, s, n, &b);
    gks_ws *ws;
    while (!err && b.np > 0 && (ws = next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_POLYLINE, .n_loops = 1 };
        prim_common(&p, t->a);
        gks_attr_prim_line(ws, t->a, &p);
        err = send_pieces(ws, &p, &b);
    }
    pieces_free(&b);
    return err;
}

static void polyline_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3,
                         const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (n < 2 || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    norm_ctx nc;
    if (norm_setup_xf(&nc, xf))
        GKS_FAIL(308, fctid);
    pt_src s = { p2, p3, NULL };
    gks_seg_prim sp = { .kind = GKS_SEG_POLYLINE, .n_loops = 1 };
    if (!mf_out(fctid, &nc,
               (gks_mf_prim){ .item = GKSM_ITEM_POLYLINE3, .n = (size_t)n, .p2 = p2, .p3 = p3 }))
        return;
    int err = record(&nc, &sp, &s, (size_t)n);
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_polyline(&nc, &s, (size_t)n, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

GKS_API void gpolyline(const Gpoint_list *l)
{
    polyline_any(GFN_PL, l ? l->num_points : 0, l ? l->points : NULL, NULL, NULL);
}

GKS_API void gpolyline3(const Gpoint_list3 *l)
{
    polyline_any(GFN_PL3, l ? l->num_points : 0, NULL, l ? l->points : NULL, NULL);
}

void gks_output_rec_polyline3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    polyline_any(GFN_PL3, l->num_points, NULL, l->points, xf);
}

/* ------------------------------------------------------------------ POLYMARKER */
static int emit_polymarker(const norm_ctx *nc, const pt_src *s, size_t n, target *t)
{
    pieces b = { 0 };
    int err = new_piece(&b);
    for (size_t i = 0; i < n && !err; i++) {
        double wc[3], h[4];
        src_get(s, i, wc);
        if (!to_ndc(nc, wc, h) || !point_visible(nc, h))
            continue; /* centre not finite or outside the clipping region */
        err = push_pt(&b, h);
    }
    gks_ws *ws;
    while (!err && b.n > 0 && (ws = next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_POLYMARKER, .n_loops = 1, .n_points = (int)b.n,
                       .pts = b.pts };
        p.loop_counts = &p.n_points;
        prim_common(&p, t->a);
        gks_attr_prim_marker(ws, t->a, &p);
        err = send(ws, &p);
    }
    pieces_free(&b);
    return err;
}

static void polymarker_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3,
                           const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (n < 1 || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    norm_ctx nc;
    if (norm_setup_xf(&nc, xf))
        GKS_FAIL(308, fctid);
    pt_src s = { p2, p3, NULL };
    gks_seg_prim sp = { .kind = GKS_SEG_POLYMARKER, .n_loops = 1 };
    if (!mf_out(fctid, &nc,
               (gks_mf_prim){ .item = GKSM_ITEM_POLYMARKER3, .n = (size_t)n, .p2 = p2, .p3 = p3 }))
        return;
    int err = record(&nc, &sp, &s, (size_t)n);
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_polymarker(&nc, &s, (size_t)n, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

GKS_API void gpolymarker(const Gpoint_list *l)
{
    polymarker_any(GFN_PM, l ? l->num_points : 0, l ? l->points : NULL, NULL, NULL);
}

GKS_API void gpolymarker3(const Gpoint_list3 *l)
{
    polymarker_any(GFN_PM3, l ? l->num_points : 0, NULL, l ? l->points : NULL, NULL);
}

void gks_output_rec_polymarker3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    polymarker_any(GFN_PM3, l->num_points, NULL, l->points, xf);
}

/* ------------------------------------------------------------------ TEXT */
typedef struct {
    const norm_ctx *nc;
    pieces *b;
} stroke_ctx;

static int stroke_emit(void *ctx, size_t n, const double (*pts)[3])
{
    stroke_ctx *sc = ctx;
    pt_src s = { NULL, NULL, pts };
    return clip_polyline(sc->nc, &s, n, sc->b);
}

/* TEXT at pos with direction vectors d0, d1 (WC3; nc maps WC3 to the final NDC3). */
static int emit_text(const norm_ctx *nc, const double pos[3], const double d0[3],
                     const double d1[3], const char *str, target *t)
{
    gks_text_frame f;
    if (!isfinite(pos[0]) || !isfinite(pos[1]) || !isfinite(pos[2]) ||
        gks_text_frame3(pos, d0, d1, &f))
        return 0; /* nothing to draw */
    pieces b = { 0 };
    int err = 0;
    gks_ws *ws;
    while (!err && *str && (ws = next_ws(t))) {
        gks_text_attrs ta;
        gks_prim p = { .kind = GKS_PRIM_POLYLINE, .n_loops = 1 };
        prim_common(&p, t->a);
        gks_attr_text_layout(ws, t->a, &ta, &p.colour);
        p.attrs.linetype = 1;
        p.attrs.linewidth = 1.0;
        p.attrs.text = 1;
        p.attrs.hlhsr_id = t->a->hlhsr_id;
        p.attrs.pick_id = t->a->pick_id;
        if (ws->drv->text) { /* the driver draws the characters, or declines */
            gks_text_prim tp = { .str = str, .frame = &f, .attrs = &ta, .clip_on = nc->clip_on,
                                 .colour = p.colour, .hlhsr_id = p.attrs.hlhsr_id,
                                 .pick_id = p.attrs.pick_id, .view_ind = p.view_ind };
            memcpy(tp.m, nc->m, sizeof tp.m);
            memcpy(tp.clip_box, nc->box, sizeof tp.clip_box);
            int r = ws->drv->text(ws, &tp);
            if (r == 0)
                ws->disp_empty = GDISP_NOT_EMPTY;
            if (r != GKS_WS_TEXT_STROKE) {
                err = r == GKS_WS_TEXT_CLIPPED ? 0 : r;
                continue;
            }
        }
        b.n = b.np = 0;
        stroke_ctx sc = { nc, &b };
        err = gks_text_strokes(&f, &ta, str, stroke_emit, &sc);
        if (!err)
            err = send_pieces(ws, &p, &b);
    }
    pieces_free(&b);
    return err;
}

static void text_any(int fctid, const double pos[3], const double d0[3], const double d1[3],
                     const char *str, const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (!str || gks_text_check(str))
        GKS_FAIL(101, fctid);
    norm_ctx nc;
    if (norm_setup_xf(&nc, xf))
        GKS_FAIL(308, fctid);
    const double wc[3][3] = { { pos[0], pos[1], pos[2] }, { d0[0], d0[1], d0[2] },
                              { d1[0], d1[1], d1[2] } };
    pt_src s = { NULL, NULL, wc };
    size_t len = strlen(str);
    gks_seg_prim sp = { .kind = GKS_SEG_TEXT, .n_loops = 1, .str = str,
                        .str_len = len > INT32_MAX ? INT32_MAX : (int)len };
    if (!mf_out(fctid, &nc, (gks_mf_prim){ .item = GKSM_ITEM_TEXT3, .n = 3, .d3 = wc, .str = str }))
        return;
    int err = record(&nc, &sp, &s, 3);
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_text(&nc, pos, d0, d1, str, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

GKS_API void gtext(const Gpoint *pos, const char *str)
{
    const double p[3] = { pos ? pos->x : NAN, pos ? pos->y : NAN, 0 };
    text_any(GFN_TX, p, (const double[3]){ 1, 0, 0 }, (const double[3]){ 0, 1, 0 }, str, NULL);
}

static void text3_any(const Gpoint3 *pos, const Gvec3 dir[2], const char *str,
                      const gks_rec_xf *xf)
{
    const double p[3] = { pos ? pos->x : NAN, pos ? pos->y : NAN, pos ? pos->z : NAN };
    double d0[3] = { NAN, NAN, NAN }, d1[3] = { NAN, NAN, NAN };
    if (dir) {
        d0[0] = dir[0].delta_x; d0[1] = dir[0].delta_y; d0[2] = dir[0].delta_z;
        d1[0] = dir[1].delta_x; d1[1] = dir[1].delta_y; d1[2] = dir[1].delta_z;
    }
    text_any(GFN_TX3, p, d0, d1, str, xf);
}

GKS_API void gtext3(const Gpoint3 *pos, const Gvec3 dir[2], const char *str)
{
    text3_any(pos, dir, str, NULL);
}

void gks_output_rec_text3(const gks_rec_xf *xf, const Gpoint3 *pos, const Gvec3 dir[2],
                          const char *str)
{
    text3_any(pos, dir, str, xf);
}

/* ------------------------------------------------------------------ FILL AREA (SET) */
/* Send an area (nl loops, counts[k] points each, m points in all, NDC3) to the target's
 * workstations. is_set: FILL AREA SET (edges apply). Returns 0 or an error number. */
static int dispatch_area(int nl, const int *counts, int m, const Gpoint3 *pts, int is_set,
                         target *t)
{
    int err = 0;
    gks_ws *ws;
    while (!err && (ws = next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_FILL_AREA, .n_loops = nl, .loop_counts = counts,
                       .n_points = m, .pts = pts };
        Grgb *pat = NULL;
        prim_common(&p, t->a);
        err = gks_attr_prim_fill(ws, t->a, (const double (*)[4])t->pat_m, &p, &pat);
        if (!is_set)
            p.attrs.edge_flag = 0; /* GKS-3D edges belong to FILL AREA SET */
        if (!err)
            err = send(ws, &p);
        gks_free(pat);
    }
    return err;
}

/* The clipped path of an area: homogeneous copy, Sutherland-Hodgman per loop, loops with
 * fewer than 3 points dropped. Returns 0 or an error number. */
static int clip_area(const norm_ctx *nc, size_t nloops, const size_t *cnt, size_t n,
                     const Gpoint3 *pts, int is_set, target *t)
{
    double (*h)[4] = gks_alloc_array(n, sizeof *h);
    size_t *out_len = gks_alloc_array(nloops, sizeof *out_len);
    double (*out)[4] = NULL;
    Gpoint3 *cp = NULL;
    int *counts = NULL;
    int err = 0;
    if (!h || !out_len) {
        err = 300;
        goto done;
    }
    for (size_t i = 0; i < n; i++) {
        h[i][0] = pts[i].x; h[i][1] = pts[i].y; h[i][2] = pts[i].z; h[i][3] = 1.0;
    }
    size_t n_out = 0;
    int r = gks_xform_clip_polygon(&nc->clip, nloops, cnt, (const double (*)[4])h, NULL, 0,
                                   out_len, &n_out);
    if ((r != 0 && r != 300) || n_out < 3)
        goto done;
    out = gks_alloc_array(n_out, sizeof *out);
    cp = gks_alloc_array(n_out, sizeof *cp);
    counts = gks_alloc_array(nloops, sizeof *counts);
    if (!out || !cp || !counts) {
        err = 300;
        goto done;
    }
    if (gks_xform_clip_polygon(&nc->clip, nloops, cnt, (const double (*)[4])h, out, n_out,
                               out_len, &n_out))
        goto done;
    size_t m = 0, src_off = 0;
    int nl = 0;
    for (size_t k = 0; k < nloops; k++) {
        if (out_len[k] >= 3 && out_len[k] <= INT32_MAX) {
            for (size_t i = 0; i < out_len[k]; i++)
                cp[m + i] = (Gpoint3){ out[src_off + i][0], out[src_off + i][1],
                                       out[src_off + i][2] };
            m += out_len[k];
            counts[nl++] = (int)out_len[k];
        }
        src_off += out_len[k];
    }
    if (nl > 0 && m <= INT32_MAX)
        err = dispatch_area(nl, counts, (int)m, cp, is_set, t);
done:
    gks_free(h);
    gks_free(out_len);
    gks_free(out);
    gks_free(cp);
    gks_free(counts);
    return err;
}

/* An area: nloops loops (loop k: cnt[k] >= 3 points, n in all) taken from s one after the
 * other, mapped by nc. is_set: FILL AREA SET. An area inside the clipping region (the
 * common case) goes to the drivers without a clipping pass (24 bytes per vertex). */
#define AREA_SMALL 16 /* areas up to this many points and loops use stack buffers */

static int emit_area(const norm_ctx *nc, size_t nloops, const size_t *cnt, size_t n,
                     const pt_src *s, int is_set, target *t)
{
    Gpoint3 pts_small[AREA_SMALL];
    int counts_small[AREA_SMALL];
    Gpoint3 *pts = n <= AREA_SMALL ? pts_small : gks_alloc_array(n, sizeof *pts);
    int *counts = nloops <= AREA_SMALL ? counts_small : gks_alloc_array(nloops, sizeof *counts);
    int err = 0, inside = 1;
    if (!pts || !counts) {
        err = 300;
        goto done;
    }
    const double (*m)[4] = (const double (*)[4])nc->m;
    for (size_t i = 0; i < n; i++) {
        double wc[3], h[3];
        src_get(s, i, wc);
        for (int k = 0; k < 3; k++) /* to_ndc inline (the same operations) */
            h[k] = m[k][0] * wc[0] + m[k][1] * wc[1] + m[k][2] * wc[2] + m[k][3];
        if (!(isfinite(h[0]) && isfinite(h[1]) && isfinite(h[2])))
            goto done; /* a non-finite vertex: the area is not drawn */
        inside = inside && point_visible(nc, h);
        pts[i] = (Gpoint3){ h[0], h[1], h[2] };
    }
    for (size_t k = 0; k < nloops; k++)
        counts[k] = (int)cnt[k];
    if (inside)
        err = dispatch_area((int)nloops, counts, (int)n, pts, is_set, t);
    else
        err = clip_area(nc, nloops, cnt, n, pts, is_set, t);
done:
    if (pts != pts_small)
        gks_free(pts);
    if (counts != counts_small)
        gks_free(counts);
    return err;
}

/* Area after the argument checks (see emit_area). */
static void output_area(int fctid, size_t nloops, const size_t *cnt, const pt_src *s,
                        int is_set, const gks_rec_xf *xf)
{
    norm_ctx nc;
    if (norm_setup_xf(&nc, xf))
        GKS_FAIL(308, fctid);
    size_t n = 0;
    for (size_t k = 0; k < nloops; k++)
        n += cnt[k];
    if (n > INT32_MAX || nloops > INT32_MAX)
        GKS_FAIL(300, fctid);
    if (!mf_out(fctid, &nc,
               (gks_mf_prim){ .item = is_set ? GKSM_ITEM_FILL_AREA_SET3 : GKSM_ITEM_FILL_AREA3,
                              .n_loops = nloops, .cnt = cnt, .n = n, .p2 = s->p2, .p3 = s->p3,
                              .d3 = s->d3 }))
        return;
    int err = 0;
    if (nc.seg) { /* stored in the open segment */
        int icnt_small[AREA_SMALL];
        int *icnt = nloops <= AREA_SMALL ? icnt_small : gks_alloc_array(nloops, sizeof *icnt);
        if (!icnt)
            GKS_FAIL(300, fctid);
        for (size_t k = 0; k < nloops; k++)
            icnt[k] = (int)cnt[k];
        gks_seg_prim sp = { .kind = is_set ? GKS_SEG_FILL_AREA_SET : GKS_SEG_FILL_AREA,
                            .n_loops = (int)nloops, .loop_counts = icnt };
        err = record(&nc, &sp, s, n);
        if (icnt != icnt_small)
            gks_free(icnt);
    }
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_area(&nc, nloops, cnt, n, s, is_set, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

static void fill_area_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3,
                          const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (n < 3 || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    size_t cnt = (size_t)n;
    pt_src s = { p2, p3, NULL };
    output_area(fctid, 1, &cnt, &s, 0, xf);
}

GKS_API void gfill_area(const Gpoint_list *l)
{
    fill_area_any(GFN_FA, l ? l->num_points : 0, l ? l->points : NULL, NULL, NULL);
}

GKS_API void gfill_area3(const Gpoint_list3 *l)
{
    fill_area_any(GFN_FA3, l ? l->num_points : 0, NULL, l ? l->points : NULL, NULL);
}

void gks_output_rec_fill_area3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    fill_area_any(GFN_FA3, l->num_points, NULL, l->points, xf);
}

/* FILL AREA SET (3): the loops are copied into one WC3 array. */
static void fill_area_set_any(int fctid, const Gpoint_list_list *l2, const Gpoint_list_list3 *l3,
                              const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    int nl = l2 ? l2->num_point_lists : l3 ? l3->num_point_lists : 0;
    if (nl < 1 || (l2 && !l2->point_lists) || (l3 && !l3->point_lists))
        GKS_FAIL(100, fctid);
    size_t total = 0;
    for (int k = 0; k < nl; k++) {
        int c = l2 ? l2->point_lists[k].num_points : l3->point_lists[k].num_points;
        int has = l2 ? l2->point_lists[k].points != NULL : l3->point_lists[k].points != NULL;
        if (c < 3 || !has)
            GKS_FAIL(100, fctid);
        total += (size_t)c;
    }
    size_t *cnt = gks_alloc_array((size_t)nl, sizeof *cnt);
    double (*wc)[3] = gks_alloc_array(total, sizeof *wc);
    if (!cnt || !wc) {
        gks_free(cnt);
        gks_free(wc);
        GKS_FAIL(300, fctid);
    }
    size_t off = 0;
    for (int k = 0; k < nl; k++) {
        int c = l2 ? l2->point_lists[k].num_points : l3->point_lists[k].num_points;
        pt_src s = { l2 ? l2->point_lists[k].points : NULL,
                     l3 ? l3->point_lists[k].points : NULL, NULL };
        for (int i = 0; i < c; i++)
            src_get(&s, (size_t)i, wc[off + (size_t)i]);
        cnt[k] = (size_t)c;
        off += (size_t)c;
    }
    pt_src all = { NULL, NULL, (const double (*)[3])wc };
    output_area(fctid, (size_t)nl, cnt, &all, 1, xf);
    gks_free(cnt);
    gks_free(wc);
}

GKS_API void gfill_area_set(const Gpoint_list_list *l)
{
    fill_area_set_any(GFN_FAS, l, NULL, NULL);
}

GKS_API void gfill_area_set3(const Gpoint_list_list3 *l)
{
    fill_area_set_any(GFN_FAS3, NULL, l, NULL);
}

void gks_output_rec_fill_area_set3(const gks_rec_xf *xf, const Gpoint_list_list3 *l)
{
    fill_area_set_any(GFN_FAS3, NULL, l, xf);
}

/* ------------------------------------------------------------------ CELL ARRAY */
/* A cell array with corners pqr (mapped by nc) and colour indices colr (nx*ny). */
static int emit_cell_array(const norm_ctx *nc, const double pqr[3][3], int nx, int ny,
                           const Gint *colr, target *t)
{
    double h[3][4];
    for (int i = 0; i < 3; i++)
        if (!to_ndc(nc, pqr[i], h[i]))
            return 0; /* a non-finite corner: not drawn */
    size_t n = (size_t)nx * (size_t)ny;
    Grgb *rgb = gks_alloc_array(n, sizeof *rgb);
    if (!rgb)
        return 300;
    int err = 0;
    gks_ws *ws;
    while (!err && (ws = next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_CELL_ARRAY, .n_loops = 1,
                       .cell_p = { h[0][0], h[0][1], h[0][2] },
                       .cell_q = { h[1][0], h[1][1], h[1][2] },
                       .cell_r = { h[2][0], h[2][1], h[2][2] },
                       .cell_nx = nx, .cell_ny = ny, .cells = rgb, .clip = nc->clip_on };
        p.loop_counts = &p.n_points;
        memcpy(p.clip_box, nc->box, sizeof nc->box);
        prim_common(&p, t->a);
        p.attrs.hlhsr_id = t->a->hlhsr_id;
        p.attrs.pick_id = t->a->pick_id;
        for (size_t i = 0; i < n; i++)
            rgb[i] = gks_attr_colour(ws, colr[i]);
        err = send(ws, &p);
    }
    gks_free(rgb);
    return err;
}

static void cell_array_any(int fctid, const double pqr[3][3], const Gpat_rep *ca,
                           const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (!ca || !ca->colr_array || ca->dims.size_x < 1 || ca->dims.size_y < 1)
        GKS_FAIL(91, fctid);
    norm_ctx nc;
    if (norm_setup_xf(&nc, xf))
        GKS_FAIL(308, fctid);
    pt_src s = { NULL, NULL, pqr };
    gks_seg_prim sp = { .kind = GKS_SEG_CELL_ARRAY, .n_loops = 1, .cell_nx = ca->dims.size_x,
                        .cell_ny = ca->dims.size_y, .cell_colr = ca->colr_array };
    int err = 0;
    if (!mf_out(fctid, &nc,
               (gks_mf_prim){ .item = GKSM_ITEM_CELL_ARRAY3, .n = 3, .d3 = pqr,
                              .nx = ca->dims.size_x, .ny = ca->dims.size_y, .colr = ca->colr_array }))
        return;
    if (nc.seg) { /* the corners are stored as P, Q, R in NDC3 */
        double o[3][3];
        for (int i = 0; i < 3; i++)
            gks_xform_mat34_point(nc.pn, pqr[i], o[i]);
        sp.cell_p = (Gpoint3){ o[0][0], o[0][1], o[0][2] };
        sp.cell_q = (Gpoint3){ o[1][0], o[1][1], o[1][2] };
        sp.cell_r = (Gpoint3){ o[2][0], o[2][1], o[2][2] };
        err = record(&nc, &sp, &s, 0);
    }
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_cell_array(&nc, pqr, ca->dims.size_x, ca->dims.size_y, ca->colr_array, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

GKS_API void gcell_array(const Grect *r, const Gpat_rep *ca)
{
    double pqr[3][3] = { { NAN, NAN, 0 }, { NAN, NAN, 0 }, { NAN, NAN, 0 } };
    if (r) {
        pqr[0][0] = r->p.x; pqr[0][1] = r->p.y;
        pqr[1][0] = r->q.x; pqr[1][1] = r->q.y;
        pqr[2][0] = r->q.x; pqr[2][1] = r->p.y; /* R: end of P's row (x direction) */
    }
    cell_array_any(GFN_CA, (const double (*)[3])pqr, ca, NULL);
}

static void cell_array3_any(const Gparal *par, const Gpat_rep *ca, const gks_rec_xf *xf)
{
    double pqr[3][3] = { { NAN, NAN, NAN }, { NAN, NAN, NAN }, { NAN, NAN, NAN } };
    if (par) {
        const Gpoint3 *v[3] = { &par->p, &par->q, &par->r };
        for (int i = 0; i < 3; i++) {
            pqr[i][0] = v[i]->x; pqr[i][1] = v[i]->y; pqr[i][2] = v[i]->z;
        }
    }
    cell_array_any(GFN_CA3, (const double (*)[3])pqr, ca, xf);
}

GKS_API void gcell_array3(const Gparal *par, const Gpat_rep *ca)
{
    cell_array3_any(par, ca, NULL);
}

void gks_output_rec_cell_array3(const gks_rec_xf *xf, const Gparal *par, const Gpat_rep *ca)
{
    cell_array3_any(par, ca, xf);
}

/* ------------------------------------------------------------------ GDP (gks_gdp.c) */
/* A GDP's tessellation, in WC3, through the POLYLINE and FILL AREA paths (segments and
 * the metafile record what is drawn). The caller did the state and argument checks. */
void gks_output_polyline_d3(int fctid, size_t n, const double (*p)[3])
{
    norm_ctx nc;
    if (norm_setup(&nc))
        GKS_FAIL(308, fctid);
    pt_src s = { NULL, NULL, p };
    gks_seg_prim sp = { .kind = GKS_SEG_POLYLINE, .n_loops = 1 };
    if (!mf_out(fctid, &nc, (gks_mf_prim){ .item = GKSM_ITEM_POLYLINE3, .n = n, .d3 = p }))
        return;
    int err = record(&nc, &sp, &s, n);
    target t;
    target_current(&t, &nc);
    if (!err)
        err = emit_polyline(&nc, &s, n, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

void gks_output_area_d3(int fctid, size_t n, const double (*p)[3])
{
    pt_src s = { NULL, NULL, p };
    output_area(fctid, 1, &n, &s, 0, NULL);
}

/* ------------------------------------------------------------------ internal interface */
/* For the primitives with data (gks_output_data.c): gks_output_int.h. */
int gks_out_norm_setup(norm_ctx *nc, const gks_rec_xf *xf) { return norm_setup_xf(nc, xf); }
int gks_out_norm_from(norm_ctx *nc, const double m[3][4], const double box[6], int clip_on)
{
    return norm_from(nc, m, box, clip_on);
}
void gks_out_target_current(target *t, const norm_ctx *nc) { target_current(t, nc); }
gks_ws *gks_out_next_ws(target *t) { return next_ws(t); }
int gks_out_send(gks_ws *ws, const gks_prim *p) { return send(ws, p); }
void gks_out_prim_common(gks_prim *p, const gks_cur_attrs *a) { prim_common(p, a); }
/* For segment replay (gks_replay.c): the stages of each primitive kind, on NDC3 points. */
int gks_out_emit_polyline(const norm_ctx *nc, const Gpoint3 *pts, size_t n, target *t)
{
    pt_src s = { NULL, pts, NULL };
    return emit_polyline(nc, &s, n, t);
}
int gks_out_emit_polymarker(const norm_ctx *nc, const Gpoint3 *pts, size_t n, target *t)
{
    pt_src s = { NULL, pts, NULL };
    return emit_polymarker(nc, &s, n, t);
}
int gks_out_emit_text(const norm_ctx *nc, const double pos[3], const double d0[3],
                      const double d1[3], const char *str, target *t)
{
    return emit_text(nc, pos, d0, d1, str, t);
}
int gks_out_emit_area(const norm_ctx *nc, size_t nloops, const size_t *cnt, size_t n,
                      const Gpoint3 *pts, int is_set, target *t)
{
    pt_src s = { NULL, pts, NULL };
    return emit_area(nc, nloops, cnt, n, &s, is_set, t);
}
int gks_out_emit_cell_array(const norm_ctx *nc, const double pqr[3][3], int nx, int ny,
                            const Gint *colr, target *t)
{
    return emit_cell_array(nc, pqr, nx, ny, colr, t);
}
