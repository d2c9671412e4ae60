/*
 * gks_output.c -- output primitives (2-D subset: POLYLINE, FILL AREA), their colour
 * attributes and the normalization transformation: WC -> NDC, clipping at the viewport
 * when the clipping indicator is on (in the core, in homogeneous form, by gks_xform),
 * then dispatch to every active workstation with the colour resolved per workstation.
 */
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <string.h>

static Grgb resolve_colour(const gks_ws *ws, int ind)
{
    int n = ws->drv->desc->n_colr;
    /* ISO 7942: a colour index not present in the table is drawn with index 1. */
    if (ind < 0 || ind >= n || !ws->colr_defined[ind])
        ind = 1 < n ? 1 : 0;
    return ws->colr[ind];
}

static int dispatch(gks_prim *p, int colr_ind)
{
    gks_context *c = gks_ctx();
    const gks_cur_attrs *a = &c->sl->attrs;
    p->area_props[0] = a->area_props[0];
    p->area_props[1] = a->area_props[1];
    p->refl_eq[0] = a->refl_eq[0];
    p->refl_eq[1] = a->refl_eq[1];
    p->light_mask = a->light_mask;
    for (int i = 0; i < c->sl->n_open; i++) {
        gks_ws *ws = c->ws[i];
        if (ws->state != GWS_ACTIVE || !ws->drv->primitive)
            continue;
        p->colour = resolve_colour(ws, colr_ind);
        int err = ws->drv->primitive(ws, p);
        if (err)
            return err;
        ws->disp_empty = GDISP_NOT_EMPTY;
    }
    return 0;
}

/* WC3 -> NDC3 by the current normalization transformation, homogeneous (w = 1).
 * Returns 0 if a coordinate is not finite (the primitive is then not drawn: GKS has no
 * error for it), 1 otherwise. */
static int normalize(const double (*in)[3], size_t n, double (*out)[4])
{
    double m[3][4];
    if (gks_cur_norm_matrix(m))
        return 0;
    for (size_t i = 0; i < n; i++) {
        gks_xform_mat34_point(m, in[i], out[i]);
        out[i][3] = 1.0;
        if (!isfinite(out[i][0]) || !isfinite(out[i][1]) || !isfinite(out[i][2]))
            return 0;
    }
    return 1;
}

/* The clip region in NDC3: the current viewport 3 if clipping is on, else none (the
 * workstation clips at its window in any case). */
static void clip_region(gks_xform_clip *clip)
{
    const gks_state_list *sl = gks_ctx()->sl;
    gks_xform_clip_init(clip);
    if (sl->clip_ind == GIND_CLIP) {
        double box[6];
        gks_limit3_array(&sl->tran[sl->cur_tnr].vp, box);
        gks_xform_clip_add_box(clip, box, GKS_XFORM_CLIP_ALL);
    }
}

static void to_points(double (*h)[4], size_t n, Gpoint3 *pts)
{
    for (size_t i = 0; i < n; i++)
        pts[i] = (Gpoint3){ h[i][0], h[i][1], h[i][2] };
}

/* POLYLINE (3) after the argument checks: wc holds n >= 2 points. */
static void output_polyline(int fctid, size_t n, const double (*wc)[3])
{
    double (*h)[4] = gks_alloc_array(n, sizeof *h);
    double (*out)[4] = gks_alloc_array(2 * (n - 1), sizeof *out);
    size_t *len = gks_alloc_array(n - 1, sizeof *len);
    Gpoint3 *pts = gks_alloc_array(2 * (n - 1), sizeof *pts);
    int err = 0;
    if (!h || !out || !len || !pts) {
        err = 300;
    } else if (normalize(wc, n, h)) {
        gks_xform_clip clip;
        size_t n_out, n_pieces;
        clip_region(&clip);
        if (gks_xform_clip_polyline(&clip, n, (const double (*)[4])h, out, 2 * (n - 1),
                                    len, n - 1, &n_out, &n_pieces) == 0) {
            to_points(out, n_out, pts);
            size_t off = 0;
            for (size_t k = 0; k < n_pieces && !err; k++) {
                gks_prim p = { .kind = GKS_PRIM_POLYLINE, .n_loops = 1,
                               .n_points = (int)len[k], .pts = pts + off,
                               .view_ind = gks_ctx()->sl->attrs.view_ind };
                p.loop_counts = &p.n_points;
                err = dispatch(&p, gks_ctx()->sl->attrs.line_colr_ind);
                off += len[k];
            }
        }
    }
    gks_free(h);
    gks_free(out);
    gks_free(len);
    gks_free(pts);
    if (err)
        gks_error_report(err, fctid);
}

/* FILL AREA (3) after the argument checks: wc holds n >= 3 points. */
static void output_fill_area(int fctid, size_t n, const double (*wc)[3])
{
    double (*h)[4] = gks_alloc_array(n, sizeof *h);
    double (*out)[4] = NULL;
    Gpoint3 *pts = NULL;
    int err = 0;
    if (!h) {
        err = 300;
    } else if (normalize(wc, n, h)) {
        gks_xform_clip clip;
        size_t out_len, n_out = 0;
        clip_region(&clip);
        /* Counting call, then the real one. */
        int r = gks_xform_clip_polygon(&clip, 1, &n, (const double (*)[4])h, NULL, 0,
                                       &out_len, &n_out);
        if ((r == 0 || r == 300) && n_out >= 3) {
            out = gks_alloc_array(n_out, sizeof *out);
            pts = gks_alloc_array(n_out, sizeof *pts);
            if (!out || !pts)
                err = 300;
            else if (gks_xform_clip_polygon(&clip, 1, &n, (const double (*)[4])h, out, n_out,
                                            &out_len, &n_out) == 0 && out_len >= 3) {
                to_points(out, n_out, pts);
                int cnt = (int)out_len;
                gks_prim p = { .kind = GKS_PRIM_FILL_AREA, .n_loops = 1, .loop_counts = &cnt,
                               .n_points = cnt, .pts = pts,
                               .view_ind = gks_ctx()->sl->attrs.view_ind };
                err = dispatch(&p, gks_ctx()->sl->attrs.fill_colr_ind);
            }
        }
    }
    gks_free(h);
    gks_free(out);
    gks_free(pts);
    if (err)
        gks_error_report(err, fctid);
}

/* Copy a 2-D or 3-D point list into WC3 (z = 0 for 2-D), NULL on storage overflow. */
static double (*wc_points(const Gpoint *p2, const Gpoint3 *p3, size_t n))[3]
{
    double (*wc)[3] = gks_alloc_array(n, sizeof *wc);
    for (size_t i = 0; wc && i < n; i++) {
        wc[i][0] = p2 ? p2[i].x : p3[i].x;
        wc[i][1] = p2 ? p2[i].y : p3[i].y;
        wc[i][2] = p2 ? 0.0 : p3[i].z;
    }
    return wc;
}

static void polyline_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3)
{
    if (gks_check_state(fctid))
        return;
    if (n < 2 || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    double (*wc)[3] = wc_points(p2, p3, (size_t)n);
    if (!wc)
        GKS_FAIL(300, fctid);
    output_polyline(fctid, (size_t)n, (const double (*)[3])wc);
    gks_free(wc);
}

static void fill_area_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3)
{
    if (gks_check_state(fctid))
        return;
    if (n < 3 || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    double (*wc)[3] = wc_points(p2, p3, (size_t)n);
    if (!wc)
        GKS_FAIL(300, fctid);
    output_fill_area(fctid, (size_t)n, (const double (*)[3])wc);
    gks_free(wc);
}

GKS_API void gpolyline(const Gpoint_list *l)
{
    polyline_any(GFN_PL, l ? l->num_points : 0, l ? l->points : NULL, NULL);
}

GKS_API void gpolyline3(const Gpoint_list3 *l)
{
    polyline_any(GFN_PL3, l ? l->num_points : 0, NULL, l ? l->points : NULL);
}

GKS_API void gfill_area(const Gpoint_list *l)
{
    fill_area_any(GFN_FA, l ? l->num_points : 0, l ? l->points : NULL, NULL);
}

GKS_API void gfill_area3(const Gpoint_list3 *l)
{
    fill_area_any(GFN_FA3, l ? l->num_points : 0, NULL, l ? l->points : NULL);
}

GKS_API void gset_line_colr_ind(Gint colr_ind)
{
    if (gks_check_state(GFN_SPLCI))
        return;
    if (colr_ind < 0)
        GKS_FAIL(92, GFN_SPLCI);
    gks_ctx()->sl->attrs.line_colr_ind = colr_ind;
}

GKS_API void gset_fill_colr_ind(Gint colr_ind)
{
    if (gks_check_state(GFN_SFACI))
        return;
    if (colr_ind < 0)
        GKS_FAIL(92, GFN_SFACI);
    gks_ctx()->sl->attrs.fill_colr_ind = colr_ind;
}

GKS_API void gset_colr_rep(Gint ws_id, Gint colr_ind, const Gcolr_rep *colr_rep)
{
    if (gks_check_state(GFN_SCR))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SCR, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (colr_ind < 0 || colr_ind >= ws->drv->desc->n_colr)
        GKS_FAIL(93, GFN_SCR);
    if (!colr_rep)
        GKS_FAIL(96, GFN_SCR);
    const Grgb *c = &colr_rep->rgb;
    if (!(c->red >= 0 && c->red <= 1 && c->green >= 0 && c->green <= 1 && c->blue >= 0 &&
          c->blue <= 1))
        GKS_FAIL(96, GFN_SCR);
    ws->colr[colr_ind] = *c;
    ws->colr_defined[colr_ind] = 1;
}

/* --- Normalization transformations ------------------------------------------------ */
static int rect_valid(const Glimit *r)
{
    return r && isfinite(r->x_min) && isfinite(r->x_max) && isfinite(r->y_min) &&
           isfinite(r->y_max) && r->x_min < r->x_max && r->y_min < r->y_max;
}

GKS_API void gset_win(Gint tran_num, const Glimit *win)
{
    if (gks_check_state(GFN_SWN))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SWN);
    if (!rect_valid(win))
        GKS_FAIL(51, GFN_SWN);
    Glimit3 *w = &gks_ctx()->sl->tran[tran_num].win;
    w->x_min = win->x_min; w->x_max = win->x_max;
    w->y_min = win->y_min; w->y_max = win->y_max;
}

GKS_API void gset_vp(Gint tran_num, const Glimit *vp)
{
    if (gks_check_state(GFN_SVP))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SVP);
    if (!rect_valid(vp))
        GKS_FAIL(51, GFN_SVP);
    if (vp->x_min < 0 || vp->x_max > 1 || vp->y_min < 0 || vp->y_max > 1)
        GKS_FAIL(52, GFN_SVP);
    Glimit3 *v = &gks_ctx()->sl->tran[tran_num].vp;
    v->x_min = vp->x_min; v->x_max = vp->x_max;
    v->y_min = vp->y_min; v->y_max = vp->y_max;
}

GKS_API void gsel_norm_tran(Gint tran_num)
{
    if (gks_check_state(GFN_SELNT))
        return;
    if (tran_num < 0 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SELNT);
    gks_ctx()->sl->cur_tnr = tran_num;
}

GKS_API void gset_clip_ind(Gclip_ind clip_ind)
{
    if (gks_check_state(GFN_SCLIP))
        return;
    if (clip_ind != GIND_CLIP && clip_ind != GIND_NO_CLIP)
        GKS_FAIL(2000, GFN_SCLIP);
    gks_ctx()->sl->clip_ind = clip_ind;
}

/* --- Workstation transformation ------------------------------------------------------ */
/* Requested values become current at once when the display surface is empty, else at
 * the next regeneration (UPDATE with PERFORM, CLEAR, or at once if implicit
 * regeneration is allowed). */
static int ws_tran_changed(gks_ws *ws)
{
    if (ws->disp_empty == GDISP_EMPTY) {
        ws->cur_win = ws->req_win;
        ws->cur_vp = ws->req_vp;
        return ws->drv->clear ? ws->drv->clear(ws) : 0;
    }
    ws->tran_upd_st = GUPD_PEND;
    ws->new_frame = GNEW_YES;
    return ws->irg_mode == GIRG_ALLOWED ? gks_ws_new_frame(ws) : 0;
}

GKS_API void gset_ws_win(Gint ws_id, const Glimit *ws_win)
{
    if (gks_check_state(GFN_SWKWN))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKWN, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (!rect_valid(ws_win))
        GKS_FAIL(51, GFN_SWKWN);
    if (ws_win->x_min < 0 || ws_win->x_max > 1 || ws_win->y_min < 0 || ws_win->y_max > 1)
        GKS_FAIL(53, GFN_SWKWN);
    ws->req_win.x_min = ws_win->x_min; ws->req_win.x_max = ws_win->x_max;
    ws->req_win.y_min = ws_win->y_min; ws->req_win.y_max = ws_win->y_max;
    int err = ws_tran_changed(ws);
    if (err)
        gks_error_report(err, GFN_SWKWN);
}

GKS_API void gset_ws_vp(Gint ws_id, const Glimit *ws_vp)
{
    if (gks_check_state(GFN_SWKVP))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKVP, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (!rect_valid(ws_vp))
        GKS_FAIL(51, GFN_SWKVP);
    const gks_ws_desc *d = ws->drv->desc;
    if (ws_vp->x_min < 0 || ws_vp->x_max > d->dc_x || ws_vp->y_min < 0 || ws_vp->y_max > d->dc_y)
        GKS_FAIL(54, GFN_SWKVP);
    ws->req_vp.x_min = ws_vp->x_min; ws->req_vp.x_max = ws_vp->x_max;
    ws->req_vp.y_min = ws_vp->y_min; ws->req_vp.y_max = ws_vp->y_max;
    int err = ws_tran_changed(ws);
    if (err)
        gks_error_report(err, GFN_SWKVP);
}
