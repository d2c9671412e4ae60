/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_prim.c -- the output pipeline of each ISO primitive (gks_pipe.h): normalization,
 * the metafile and segment records, clipping and dispatch.
 *
 * Non-finite coordinates never reach a driver: a polyline is broken at such a point, a
 * marker at such a point is dropped, an area or cell array containing one is not drawn
 * (GKS defines no error for them). Markers are clipped by their centres; TEXT becomes
 * polyline strokes (gks_text_layout.c) generated per workstation (the text bundle may
 * differ) and clipped like polylines, unless the driver draws the text itself. CELL ARRAY
 * is the one primitive clipped by the driver (prim.clip, prim.clip_box).
 */
#include "gks_pipe.h"
#include "gks_alloc.h"
#include "gks_attr_resolve.h"
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_pipe_clip.h"
#include "gks_state.h"
#include "gks_text_layout.h"
#include <stdint.h>
#include <string.h>

/* ------------------------------------------------------------------ records */
/* Metafile output (gks_mf_record.h), called when gks_mf_on(): the primitive as the active
 * MO workstations record it. 0: an error was reported and the world changed; the caller
 * returns at once. */
static GKS_MUST_CHECK int mf_out(int fctid, const gks_pipe_norm *nc, gks_mf_prim p)
{
    p.pn = (const double (*)[4])nc->pn;
    p.norm = (const double (*)[4])nc->n;
    p.box = nc->box;
    p.clip_on = nc->clip_on;
    return gks_mf_prim_write(fctid, &p);
}

/* Stores a primitive into the open segment (if any): geometry mapped to NDC3 by the
 * normalization only (nc->pn), unclipped, with the current attributes, normalization and
 * clipping volume. Returns 0, 300 or 301. */
static int record(const gks_pipe_norm *nc, gks_seg_prim *sp, const gks_pipe_src *src, size_t n)
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
        gks_pipe_src_get(src, i, wc);
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

/* Send the pieces as polylines (attributes already in p) to ws. */
static int send_pieces(gks_ws *ws, gks_prim *p, const gks_pipe_pieces *b)
{
    size_t off = 0;
    for (size_t k = 0; k < b->np; k++) {
        p->n_points = b->len[k];
        p->pts = b->pts + off;
        p->loop_counts = &p->n_points;
        off += (size_t)b->len[k];
        if (p->n_points < 2)
            continue;
        int err = gks_pipe_send(ws, p);
        if (err)
            return err;
    }
    return 0;
}

/* ------------------------------------------------------------------ POLYLINE */
static int emit_polyline(const gks_pipe_norm *nc, const gks_pipe_src *s, size_t n,
                         gks_pipe_target *t)
{
    gks_pipe_pieces b = { 0 };
    int err = gks_pipe_clip_polyline(nc, s, n, &b);
    gks_ws *ws;
    while (!err && b.np > 0 && (ws = gks_pipe_next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_POLYLINE, .n_loops = 1 };
        gks_pipe_prim_common(&p, t->a);
        gks_attr_prim_line(ws, t->a, &p);
        err = send_pieces(ws, &p, &b);
    }
    gks_pipe_pieces_free(&b);
    return err;
}

/* ------------------------------------------------------------------ POLYMARKER */
static int emit_polymarker(const gks_pipe_norm *nc, const gks_pipe_src *s, size_t n,
                           gks_pipe_target *t)
{
    gks_pipe_pieces b = { 0 };
    int err = gks_pipe_piece_new(&b);
    for (size_t i = 0; i < n && !err; i++) {
        double wc[3], h[4];
        gks_pipe_src_get(s, i, wc);
        if (!gks_pipe_to_ndc(nc, wc, h) || !gks_pipe_visible(nc, h))
            continue; /* centre not finite or outside the clipping region */
        err = gks_pipe_piece_push(&b, h);
    }
    gks_ws *ws;
    while (!err && b.n > 0 && (ws = gks_pipe_next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_POLYMARKER, .n_loops = 1, .n_points = (int)b.n,
                       .pts = b.pts };
        p.loop_counts = &p.n_points;
        gks_pipe_prim_common(&p, t->a);
        gks_attr_prim_marker(ws, t->a, &p);
        err = gks_pipe_send(ws, &p);
    }
    gks_pipe_pieces_free(&b);
    return err;
}

/* POLYLINE (markers 0) and POLYMARKER (markers 1) after the entry point's checks. */
static int points_prim(int fctid, const gks_rec_xf *xf, const gks_pipe_src *s, size_t n,
                       int markers)
{
    gks_pipe_norm buf;
    const gks_pipe_norm *nc;
    if (gks_pipe_norm_get(&nc, &buf, xf))
        return 308;
    gks_seg_prim sp = { .kind = markers ? GKS_SEG_POLYMARKER : GKS_SEG_POLYLINE, .n_loops = 1 };
    if (gks_mf_on() &&
        !mf_out(fctid, nc,
                (gks_mf_prim){ .item = markers ? GKSM_ITEM_POLYMARKER3 : GKSM_ITEM_POLYLINE3,
                               .n = n, .p2 = s->p2, .p3 = s->p3, .d3 = s->d3 }))
        return GKS_PIPE_REPORTED;
    int err = record(nc, &sp, s, n);
    gks_pipe_target t;
    gks_pipe_target_current(&t, nc);
    if (!err)
        err = markers ? emit_polymarker(nc, s, n, &t) : emit_polyline(nc, s, n, &t);
    return err;
}

int gks_pipe_polyline(int fctid, const gks_rec_xf *xf, const gks_pipe_src *s, size_t n)
{
    return points_prim(fctid, xf, s, n, 0);
}

int gks_pipe_polymarker(int fctid, const gks_rec_xf *xf, const gks_pipe_src *s, size_t n)
{
    return points_prim(fctid, xf, s, n, 1);
}

/* ------------------------------------------------------------------ TEXT */
typedef struct {
    const gks_pipe_norm *nc;
    gks_pipe_pieces *b;
} stroke_ctx;

static int stroke_emit(void *ctx, size_t n, const double (*pts)[3])
{
    stroke_ctx *sc = ctx;
    gks_pipe_src s = { NULL, NULL, pts };
    return gks_pipe_clip_polyline(sc->nc, &s, n, sc->b);
}

int gks_pipe_emit_text(const gks_pipe_norm *nc, const double pos[3], const double d0[3],
                       const double d1[3], const char *str, gks_pipe_target *t)
{
    gks_text_frame f;
    if (!isfinite(pos[0]) || !isfinite(pos[1]) || !isfinite(pos[2]) ||
        gks_text_frame3(pos, d0, d1, &f))
        return 0; /* nothing to draw */
    gks_pipe_pieces b = { 0 };
    int err = 0;
    gks_ws *ws;
    while (!err && *str && (ws = gks_pipe_next_ws(t))) {
        gks_text_attrs ta;
        gks_prim p = { .kind = GKS_PRIM_POLYLINE, .n_loops = 1 };
        gks_pipe_prim_common(&p, t->a);
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
    gks_pipe_pieces_free(&b);
    return err;
}

int gks_pipe_text(int fctid, const gks_rec_xf *xf, const double pos[3], const double d0[3],
                  const double d1[3], const char *str)
{
    gks_pipe_norm buf;
    const gks_pipe_norm *nc;
    if (gks_pipe_norm_get(&nc, &buf, xf))
        return 308;
    const double wc[3][3] = { { pos[0], pos[1], pos[2] }, { d0[0], d0[1], d0[2] },
                              { d1[0], d1[1], d1[2] } };
    gks_pipe_src s = { NULL, NULL, wc };
    size_t len = strlen(str);
    gks_seg_prim sp = { .kind = GKS_SEG_TEXT, .n_loops = 1, .str = str,
                        .str_len = len > INT32_MAX ? INT32_MAX : (int)len };
    if (gks_mf_on() &&
        !mf_out(fctid, nc, (gks_mf_prim){ .item = GKSM_ITEM_TEXT3, .n = 3, .d3 = wc, .str = str }))
        return GKS_PIPE_REPORTED;
    int err = record(nc, &sp, &s, 3);
    gks_pipe_target t;
    gks_pipe_target_current(&t, nc);
    if (!err)
        err = gks_pipe_emit_text(nc, pos, d0, d1, str, &t);
    return err;
}

/* ------------------------------------------------------------------ FILL AREA (SET) */
/* Send an area (nl loops, counts[k] points each, m points in all, NDC3) to the target's
 * workstations. is_set: FILL AREA SET (edges apply). Returns 0 or an error number. Inline
 * (as emit_area in gks_pipe_area): the calls of an area are the application's thread's
 * work per FILL AREA, each with its frame. */
__attribute__((always_inline)) static inline int dispatch_area(int nl, const int *counts, int m,
                                                               const Gpoint3 *pts, int is_set,
                                                               gks_pipe_target *t)
{
    int err = 0;
    gks_ws *ws;
    while (!err && (ws = gks_pipe_next_ws(t))) {
        gks_prim buf, *p;
        Grgb *pat;
        /* GKS-3D edges belong to FILL AREA SET */
        p = gks_attr_area_prim(ws, t->a, t->pat_m, is_set, &buf, &pat, &err);
        p->n_loops = nl;
        p->loop_counts = counts;
        p->n_points = m;
        p->pts = pts;
        if (!err)
            err = gks_pipe_send(ws, p);
        if (pat)
            gks_free(pat);
    }
    return err;
}

/* nc->axis_aligned (gks_pipe_norm_facts): m maps each coordinate by its own row alone, a
 * scale and a shift per axis (the normalization, with no segment transformation or one
 * without rotation and shear). Then emit_area maps a point by m[k][k] * c + m[k][3] per
 * axis, which equals the full row: with the other coordinates finite their products with
 * the zero entries are zeros, which change a non-zero sum by nothing (a zero sum, whose sign
 * they may change, is made again by the full row); a non-finite coordinate makes its own
 * axis non-finite, so the area is dropped as in the full mapping, and an overflow is the
 * same sum's. */

#define AREA_SMALL 16 /* areas up to this many points and loops use stack buffers */

/* An area: nloops loops (loop k: cnt[k] >= 3 points, n in all) taken from s one after the
 * other, mapped by nc. is_set: FILL AREA SET. An area inside the clipping region (the
 * common case) goes to the drivers without a clipping pass (24 bytes per vertex). */
__attribute__((always_inline)) static inline int emit_area(const gks_pipe_norm *nc, size_t nloops,
                                                           const size_t *cnt, size_t n,
                                                           const gks_pipe_src *s, int is_set,
                                                           gks_pipe_target *t)
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
    if (s->p3 && nc->axis_aligned) {
        /* m and the box in locals: the stores into pts could alias nc for the compiler */
        const double a0 = m[0][0], a1 = m[1][1], a2 = m[2][2];
        const double t0 = m[0][3], t1 = m[1][3], t2 = m[2][3];
        const int clip_on = nc->clip_on;
        double b[6];
        memcpy(b, nc->box, sizeof b);
        /* a point in a finite box is finite: then its own check is not needed */
        const int box_finite = nc->box_finite;
        const Gpoint3 *q = s->p3;
        for (size_t i = 0; i < n; i++) {
            const double x = q[i].x, y = q[i].y, z = q[i].z;
            double h0 = a0 * x + t0, h1 = a1 * y + t1, h2 = a2 * z + t2;
            if (h0 == 0) /* the sign of a zero: as the full row makes it */
                h0 = m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3];
            if (h1 == 0)
                h1 = m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3];
            if (h2 == 0)
                h2 = m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3];
            const int in = !clip_on || (h0 >= b[0] && h0 <= b[1] && h1 >= b[2] && h1 <= b[3] &&
                                        h2 >= b[4] && h2 <= b[5]);
            if (!(in && box_finite) && !(isfinite(h0) && isfinite(h1) && isfinite(h2)))
                goto done; /* a non-finite vertex: the area is not drawn */
            inside = inside && in;
            pts[i] = (Gpoint3){ h0, h1, h2 };
        }
        goto mapped;
    }
    for (size_t i = 0; i < n; i++) {
        double wc[3], h[3];
        gks_pipe_src_get(s, i, wc);
        for (int k = 0; k < 3; k++) /* gks_pipe_to_ndc inline (the same operations) */
            h[k] = m[k][0] * wc[0] + m[k][1] * wc[1] + m[k][2] * wc[2] + m[k][3];
        if (!(isfinite(h[0]) && isfinite(h[1]) && isfinite(h[2])))
            goto done; /* a non-finite vertex: the area is not drawn */
        inside = inside && gks_pipe_visible(nc, h);
        pts[i] = (Gpoint3){ h[0], h[1], h[2] };
    }
mapped:
    for (size_t k = 0; k < nloops; k++)
        counts[k] = (int)cnt[k];
    if (inside) {
        err = dispatch_area((int)nloops, counts, (int)n, pts, is_set, t);
    } else {
        gks_pipe_loops a;
        err = gks_pipe_clip_area(nc, nloops, cnt, n, pts, &a);
        if (!err && a.nl > 0)
            err = dispatch_area(a.nl, a.counts, a.m, a.pts, is_set, t);
        gks_pipe_loops_free(&a);
    }
done:
    if (pts != pts_small)
        gks_free(pts);
    if (counts != counts_small)
        gks_free(counts);
    return err;
}

int gks_pipe_area(int fctid, const gks_rec_xf *xf, size_t nloops, const size_t *cnt,
                  const gks_pipe_src *s, int is_set)
{
    gks_pipe_norm buf;
    const gks_pipe_norm *nc;
    if (gks_pipe_norm_get(&nc, &buf, xf))
        return 308;
    size_t n = 0;
    for (size_t k = 0; k < nloops; k++)
        n += cnt[k];
    if (n > INT32_MAX || nloops > INT32_MAX)
        return 300;
    if (gks_mf_on() &&
        !mf_out(fctid, nc,
                (gks_mf_prim){ .item = is_set ? GKSM_ITEM_FILL_AREA_SET3 : GKSM_ITEM_FILL_AREA3,
                               .n_loops = nloops, .cnt = cnt, .n = n, .p2 = s->p2, .p3 = s->p3,
                               .d3 = s->d3 }))
        return GKS_PIPE_REPORTED;
    int err = 0;
    if (nc->seg) { /* stored in the open segment */
        int icnt_small[AREA_SMALL];
        int *icnt = nloops <= AREA_SMALL ? icnt_small : gks_alloc_array(nloops, sizeof *icnt);
        if (!icnt)
            return 300;
        for (size_t k = 0; k < nloops; k++)
            icnt[k] = (int)cnt[k];
        gks_seg_prim sp = { .kind = is_set ? GKS_SEG_FILL_AREA_SET : GKS_SEG_FILL_AREA,
                            .n_loops = (int)nloops, .loop_counts = icnt };
        err = record(nc, &sp, s, n);
        if (icnt != icnt_small)
            gks_free(icnt);
    }
    gks_pipe_target t;
    gks_pipe_target_current(&t, nc);
    if (!err)
        err = emit_area(nc, nloops, cnt, n, s, is_set, &t);
    return err;
}

/* ------------------------------------------------------------------ CELL ARRAY */
int gks_pipe_emit_cell_array(const gks_pipe_norm *nc, const double pqr[3][3], int nx, int ny,
                             const Gint *colr, gks_pipe_target *t)
{
    double h[3][4];
    for (int i = 0; i < 3; i++)
        if (!gks_pipe_to_ndc(nc, pqr[i], h[i]))
            return 0; /* a non-finite corner: not drawn */
    size_t n = (size_t)nx * (size_t)ny;
    Grgb *rgb = gks_alloc_array(n, sizeof *rgb);
    if (!rgb)
        return 300;
    int err = 0;
    gks_ws *ws;
    while (!err && (ws = gks_pipe_next_ws(t))) {
        gks_prim p = { .kind = GKS_PRIM_CELL_ARRAY, .n_loops = 1,
                       .cell_p = { h[0][0], h[0][1], h[0][2] },
                       .cell_q = { h[1][0], h[1][1], h[1][2] },
                       .cell_r = { h[2][0], h[2][1], h[2][2] },
                       .cell_nx = nx, .cell_ny = ny, .cells = rgb, .clip = nc->clip_on };
        p.loop_counts = &p.n_points;
        memcpy(p.clip_box, nc->box, sizeof nc->box);
        gks_pipe_prim_common(&p, t->a);
        p.attrs.hlhsr_id = t->a->hlhsr_id;
        p.attrs.pick_id = t->a->pick_id;
        for (size_t i = 0; i < n; i++)
            rgb[i] = gks_attr_colour(ws, colr[i]);
        err = gks_pipe_send(ws, &p);
    }
    gks_free(rgb);
    return err;
}

int gks_pipe_cell_array(int fctid, const gks_rec_xf *xf, const double pqr[3][3], int nx,
                        int ny, const Gint *colr)
{
    gks_pipe_norm buf;
    const gks_pipe_norm *nc;
    if (gks_pipe_norm_get(&nc, &buf, xf))
        return 308;
    gks_pipe_src s = { NULL, NULL, pqr };
    gks_seg_prim sp = { .kind = GKS_SEG_CELL_ARRAY, .n_loops = 1, .cell_nx = nx,
                        .cell_ny = ny, .cell_colr = colr };
    int err = 0;
    if (gks_mf_on() &&
        !mf_out(fctid, nc,
                (gks_mf_prim){ .item = GKSM_ITEM_CELL_ARRAY3, .n = 3, .d3 = pqr, .nx = nx,
                               .ny = ny, .colr = colr }))
        return GKS_PIPE_REPORTED;
    if (nc->seg) { /* the corners are stored as P, Q, R in NDC3 */
        double o[3][3];
        for (int i = 0; i < 3; i++)
            gks_xform_mat34_point(nc->pn, pqr[i], o[i]);
        sp.cell_p = (Gpoint3){ o[0][0], o[0][1], o[0][2] };
        sp.cell_q = (Gpoint3){ o[1][0], o[1][1], o[1][2] };
        sp.cell_r = (Gpoint3){ o[2][0], o[2][1], o[2][2] };
        err = record(nc, &sp, &s, 0);
    }
    gks_pipe_target t;
    gks_pipe_target_current(&t, nc);
    if (!err)
        err = gks_pipe_emit_cell_array(nc, pqr, nx, ny, colr, &t);
    return err;
}

/* ------------------------------------------------------------------ replay's entries */
int gks_pipe_emit_polyline(const gks_pipe_norm *nc, const Gpoint3 *pts, size_t n,
                           gks_pipe_target *t)
{
    gks_pipe_src s = { NULL, pts, NULL };
    return emit_polyline(nc, &s, n, t);
}

int gks_pipe_emit_polymarker(const gks_pipe_norm *nc, const Gpoint3 *pts, size_t n,
                             gks_pipe_target *t)
{
    gks_pipe_src s = { NULL, pts, NULL };
    return emit_polymarker(nc, &s, n, t);
}

int gks_pipe_emit_area(const gks_pipe_norm *nc, size_t nloops, const size_t *cnt, size_t n,
                       const Gpoint3 *pts, int is_set, gks_pipe_target *t)
{
    gks_pipe_src s = { NULL, pts, NULL };
    return emit_area(nc, nloops, cnt, n, &s, is_set, t);
}
