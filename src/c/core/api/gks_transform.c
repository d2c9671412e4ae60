/* SPDX-License-Identifier: MIT */
/*
 * gks_transform.c -- the transformation functions (ISO 7942 5.5, ISO 8805): SET WINDOW (3),
 * SET VIEWPORT (3), SELECT NORMALIZATION TRANSFORMATION, SET CLIPPING INDICATOR,
 * SET WORKSTATION WINDOW (3), SET WORKSTATION VIEWPORT (3), and their inquiries
 * (INQUIRE CURRENT NORMALIZATION TRANSFORMATION NUMBER, INQUIRE NORMALIZATION
 * TRANSFORMATION (3), INQUIRE CLIPPING (3), INQUIRE WORKSTATION TRANSFORMATION (3)).
 * The transformations themselves are applied by the output pipeline (gks_output.c) and
 * the workstation drivers.
 */
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_replay.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>

/* --- Normalization transformations ------------------------------------------------ */
/* The checks are the xform module's (gks_xform_check_*), on a rectangle or box given as
 * the double[6] they take: x, y, z limits; a 2-D rectangle has z from 0 to 0 (the 2-D
 * checks read the first four). dim is 2 or 3, 0 for a NULL argument (error 51). */
typedef struct {
    double v[6];
    int dim;
} box;

static box box2(const Glimit *r)
{
    box b = { { 0 }, 0 };
    if (r)
        b = (box){ { r->x_min, r->x_max, r->y_min, r->y_max, 0.0, 0.0 }, 2 };
    return b;
}

static box box3(const Glimit3 *r)
{
    box b = { { 0 }, 0 };
    if (r) {
        gks_limit3_array(r, b.v);
        b.dim = 3;
    }
    return b;
}

/* Limits l from box b: x and y, and z when it is 3-D. */
static void put_limits(Glimit3 *l, const box *b)
{
    l->x_min = b->v[0], l->x_max = b->v[1], l->y_min = b->v[2], l->y_max = b->v[3];
    if (b->dim == 3)
        l->z_min = b->v[4], l->z_max = b->v[5];
}

/* SET WINDOW (3) / SET VIEWPORT (3) of transformation tran_num to box b: 50, then 51 (and
 * 52 for a viewport outside NDC space); a 2-D rectangle keeps z. */
static void set_norm_limits(int fct, Gint tran_num, box b, int viewport)
{
    if (gks_check_state(fct))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, fct);
    const double *v = b.v;
    int err = !b.dim     ? 51
              : viewport ? (b.dim == 3 ? gks_xform_check_viewport3(v) : gks_xform_check_viewport(v))
              : (b.dim == 3 ? gks_xform_check_window3(v) : gks_xform_check_window(v)) ? 51
                                                                                       : 0;
    if (err)
        GKS_FAIL(err, fct);
    gks_norm_tran *t = &gks_ctx()->sl->tran[tran_num];
    put_limits(viewport ? &t->vp : &t->win, &b);
}

GKS_API void gset_win(Gint tran_num, const Glimit *win)
{
    set_norm_limits(GFN_SWN, tran_num, box2(win), 0);
}

GKS_API void gset_vp(Gint tran_num, const Glimit *vp)
{
    set_norm_limits(GFN_SVP, tran_num, box2(vp), 1);
}

GKS_API void gset_win3(Gint tran_num, const Glimit3 *win)
{
    set_norm_limits(GFN_SW3, tran_num, box3(win), 0);
}

GKS_API void gset_vp3(Gint tran_num, const Glimit3 *vp)
{
    set_norm_limits(GFN_SV3, tran_num, box3(vp), 1);
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
/* The display space of ws, [0,dc_x] x [0,dc_y] x [0,1], as the xform checks take it. */
static void display_space(const gks_ws *ws, double ds[3])
{
    ds[0] = ws->drv->desc->dc_x, ds[1] = ws->drv->desc->dc_y, ds[2] = 1.0;
}

/* The requested workstation window or viewport changed: current at once or pending (see
 * above); a failed clear or regeneration is reported for fct. */
static void ws_tran_changed(gks_ws *ws, int fct)
{
    int err = 0;
    if (ws->disp_empty == GDISP_EMPTY) {
        ws->cur_win = ws->req_win;
        ws->cur_vp = ws->req_vp;
        err = ws->drv->clear ? ws->drv->clear(ws) : 0;
    } else {
        ws->tran_upd_st = GUPD_PEND;
        ws->new_frame = GNEW_YES;
        err = ws->irg_mode == GIRG_ALLOWED ? gks_ws_regenerate(ws) : 0;
    }
    if (err)
        GKS_FAIL(err, fct);
}

/* SET WORKSTATION WINDOW (3) / VIEWPORT (3): the workstation (7, 20, 25, 33, 36), then box
 * b (51; a window outside the NPC unit cube 53, a viewport outside the display space 54),
 * then the requested window or viewport set, recorded on a metafile output by the typed
 * hook mf, and made current or pending. */
static void set_ws_limits(int fct, int (*mf)(int, int, const double *), Gint ws_id, box b,
                          int viewport)
{
    if (gks_check_state(fct))
        return;
    gks_ws *ws = gks_ws_checked(fct, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    double ds[3];
    display_space(ws, ds);
    int err = !b.dim     ? 51
              : viewport ? gks_xform_check_ws_viewport3(b.v, ds)
                         : gks_xform_check_ws_window3(b.v);
    if (err)
        GKS_FAIL(err, fct);
    put_limits(viewport ? &ws->req_vp : &ws->req_win, &b);
    if (!mf(fct, ws_id, b.v))
        return;
    ws_tran_changed(ws, fct);
}

GKS_API void gset_ws_win(Gint ws_id, const Glimit *ws_win)
{
    set_ws_limits(GFN_SWKWN, gks_mf_ws_rec_SWKWN, ws_id, box2(ws_win), 0);
}

GKS_API void gset_ws_vp(Gint ws_id, const Glimit *ws_vp)
{
    set_ws_limits(GFN_SWKVP, gks_mf_ws_rec_SWKVP, ws_id, box2(ws_vp), 1);
}

GKS_API void gset_ws_win3(Gint ws_id, const Glimit3 *ws_win)
{
    set_ws_limits(GFN_SWKW3, gks_mf_ws_rec_SWKW3, ws_id, box3(ws_win), 0);
}

GKS_API void gset_ws_vp3(Gint ws_id, const Glimit3 *ws_vp)
{
    set_ws_limits(GFN_SWKV3, gks_mf_ws_rec_SWKV3, ws_id, box3(ws_vp), 1);
}

/* --- Inquiries --------------------------------------------------------------------- */
GKS_API void ginq_cur_norm_tran_num(Gint *err_ind, Gint *norm_tran_num)
{
    GKS_INQ_ARGS(err_ind, norm_tran_num);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *norm_tran_num = gks_ctx()->sl->cur_tnr;
}

GKS_API void ginq_norm_tran(Gint num, Gint *err_ind, Gtran *norm_tran)
{
    GKS_INQ_ARGS(err_ind, norm_tran);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    if (num < 0 || num > GKS_MAX_NORM_TRAN) {
        *err_ind = 50;
        return;
    }
    const gks_norm_tran *t = &gks_ctx()->sl->tran[num];
    norm_tran->win = (Glimit){ t->win.x_min, t->win.x_max, t->win.y_min, t->win.y_max };
    norm_tran->vp = (Glimit){ t->vp.x_min, t->vp.x_max, t->vp.y_min, t->vp.y_max };
}

GKS_API void ginq_clip(Gint *err_ind, Gclip *clip)
{
    GKS_INQ_ARGS(err_ind, clip);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_state_list *sl = gks_ctx()->sl;
    const Glimit3 *v = &sl->tran[sl->cur_tnr].vp;
    clip->clip_ind = sl->clip_ind;
    clip->clip_rect = (Glimit){ v->x_min, v->x_max, v->y_min, v->y_max };
}

GKS_API void ginq_ws_tran(Gint ws_id, Gint *err_ind, Gupd_st *ws_tran_upd_st,
                          Glimit *req_ws_win, Glimit *cur_ws_win,
                          Glimit *req_ws_vp, Glimit *cur_ws_vp)
{
    GKS_INQ_ARGS(err_ind, ws_tran_upd_st, req_ws_win, cur_ws_win, req_ws_vp, cur_ws_vp);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
#define XY(l) ((Glimit){ (l).x_min, (l).x_max, (l).y_min, (l).y_max })
    *ws_tran_upd_st = ws->tran_upd_st;
    *req_ws_win = XY(ws->req_win);
    *cur_ws_win = XY(ws->cur_win);
    *req_ws_vp = XY(ws->req_vp);
    *cur_ws_vp = XY(ws->cur_vp);
#undef XY
}

GKS_API void ginq_norm_tran3(Gint num, Gint *err_ind, Gtran3 *norm_tran)
{
    GKS_INQ_ARGS(err_ind, norm_tran);
    *err_ind = gks_inq_state(GKS_S_OPEN);
    if (*err_ind)
        return;
    if (num < 0 || num > GKS_MAX_NORM_TRAN) {
        *err_ind = 50;
        return;
    }
    const gks_norm_tran *t = &gks_ctx()->sl->tran[num];
    *norm_tran = (Gtran3){ t->win, t->vp };
}

GKS_API void ginq_clip3(Gint *err_ind, Gclip3 *clip)
{
    GKS_INQ_ARGS(err_ind, clip);
    *err_ind = gks_inq_state(GKS_S_OPEN);
    if (*err_ind)
        return;
    const gks_state_list *sl = gks_ctx()->sl;
    *clip = (Gclip3){ sl->clip_ind, sl->tran[sl->cur_tnr].vp };
}

GKS_API void ginq_ws_tran3(Gint ws_id, Gint *err_ind, Gupd_st *ws_tran_upd_st,
                           Glimit3 *req_ws_win, Glimit3 *cur_ws_win, Glimit3 *req_ws_vp,
                           Glimit3 *cur_ws_vp)
{
    GKS_INQ_ARGS(err_ind, ws_tran_upd_st, req_ws_win, cur_ws_win, req_ws_vp, cur_ws_vp);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    *ws_tran_upd_st = ws->tran_upd_st;
    *req_ws_win = ws->req_win;
    *cur_ws_win = ws->cur_win;
    *req_ws_vp = ws->req_vp;
    *cur_ws_vp = ws->cur_vp;
}
