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
#include "gks_segment.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>

/* --- Normalization transformations ------------------------------------------------ */
/* The checks are the xform module's (gks_xform_check_*); a NULL rectangle is 51. These
 * give a 2-D rectangle as the double[4] / double[6] boxes they take. */
static void rect4(const Glimit *r, double b[4])
{
    b[0] = r->x_min, b[1] = r->x_max, b[2] = r->y_min, b[3] = r->y_max;
}

/* A 2-D workstation window or viewport as a box with z from 0 to 0. */
static void rect6(const Glimit *r, double b[6])
{
    rect4(r, b);
    b[4] = b[5] = 0.0;
}

GKS_API void gset_win(Gint tran_num, const Glimit *win)
{
    if (gks_check_state(GFN_SWN))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SWN);
    double b[4];
    if (!win)
        GKS_FAIL(51, GFN_SWN);
    rect4(win, b);
    if (gks_xform_check_window(b))
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
    double b[4];
    if (!vp)
        GKS_FAIL(51, GFN_SVP);
    rect4(vp, b);
    int err = gks_xform_check_viewport(b); /* 51, then 52 */
    if (err)
        GKS_FAIL(err, GFN_SVP);
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

GKS_API void gset_win3(Gint tran_num, const Glimit3 *win)
{
    double b[6];
    if (gks_check_state(GFN_SW3))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SW3);
    if (!win)
        GKS_FAIL(51, GFN_SW3);
    gks_limit3_array(win, b);
    if (gks_xform_check_window3(b))
        GKS_FAIL(51, GFN_SW3);
    gks_ctx()->sl->tran[tran_num].win = *win;
}

GKS_API void gset_vp3(Gint tran_num, const Glimit3 *vp)
{
    double b[6];
    if (gks_check_state(GFN_SV3))
        return;
    if (tran_num < 1 || tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SV3);
    if (!vp)
        GKS_FAIL(51, GFN_SV3);
    gks_limit3_array(vp, b);
    int err = gks_xform_check_viewport3(b); /* 51, then 52 */
    if (err)
        GKS_FAIL(err, GFN_SV3);
    gks_ctx()->sl->tran[tran_num].vp = *vp;
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

static int ws_tran_changed(gks_ws *ws)
{
    if (ws->disp_empty == GDISP_EMPTY) {
        ws->cur_win = ws->req_win;
        ws->cur_vp = ws->req_vp;
        return ws->drv->clear ? ws->drv->clear(ws) : 0;
    }
    ws->tran_upd_st = GUPD_PEND;
    ws->new_frame = GNEW_YES;
    return ws->irg_mode == GIRG_ALLOWED ? gks_ws_regenerate(ws) : 0;
}

GKS_API void gset_ws_win(Gint ws_id, const Glimit *ws_win)
{
    if (gks_check_state(GFN_SWKWN))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKWN, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    double b[6];
    if (!ws_win)
        GKS_FAIL(51, GFN_SWKWN);
    rect6(ws_win, b);
    int e = gks_xform_check_ws_window3(b); /* 51, then 53 */
    if (e)
        GKS_FAIL(e, GFN_SWKWN);
    ws->req_win.x_min = ws_win->x_min; ws->req_win.x_max = ws_win->x_max;
    ws->req_win.y_min = ws_win->y_min; ws->req_win.y_max = ws_win->y_max;
    GKS_MF_WS(SWKWN, ws_id, &ws_win->x_min);
    int err = ws_tran_changed(ws);
    if (err)
        GKS_FAIL(err, GFN_SWKWN);
}

GKS_API void gset_ws_vp(Gint ws_id, const Glimit *ws_vp)
{
    if (gks_check_state(GFN_SWKVP))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKVP, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    double b[6];
    if (!ws_vp)
        GKS_FAIL(51, GFN_SWKVP);
    rect6(ws_vp, b);
    double ds[3];
    display_space(ws, ds);
    int e = gks_xform_check_ws_viewport3(b, ds); /* 51, then 54 */
    if (e)
        GKS_FAIL(e, GFN_SWKVP);
    ws->req_vp.x_min = ws_vp->x_min; ws->req_vp.x_max = ws_vp->x_max;
    ws->req_vp.y_min = ws_vp->y_min; ws->req_vp.y_max = ws_vp->y_max;
    GKS_MF_WS(SWKVP, ws_id, &ws_vp->x_min);
    int err = ws_tran_changed(ws);
    if (err)
        GKS_FAIL(err, GFN_SWKVP);
}

GKS_API void gset_ws_win3(Gint ws_id, const Glimit3 *ws_win)
{
    if (gks_check_state(GFN_SWKW3))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKW3, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    double b[6];
    if (!ws_win)
        GKS_FAIL(51, GFN_SWKW3);
    gks_limit3_array(ws_win, b);
    int e = gks_xform_check_ws_window3(b); /* 51, then 53 */
    if (e)
        GKS_FAIL(e, GFN_SWKW3);
    ws->req_win = *ws_win;
    GKS_MF_WS(SWKW3, ws_id, &ws_win->x_min);
    int err = ws_tran_changed(ws);
    if (err)
        GKS_FAIL(err, GFN_SWKW3);
}

GKS_API void gset_ws_vp3(Gint ws_id, const Glimit3 *ws_vp)
{
    if (gks_check_state(GFN_SWKV3))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SWKV3, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    double b[6];
    if (!ws_vp)
        GKS_FAIL(51, GFN_SWKV3);
    gks_limit3_array(ws_vp, b);
    double ds[3];
    display_space(ws, ds);
    int e = gks_xform_check_ws_viewport3(b, ds); /* 51, then 54 */
    if (e)
        GKS_FAIL(e, GFN_SWKV3);
    ws->req_vp = *ws_vp;
    GKS_MF_WS(SWKV3, ws_id, &ws_vp->x_min);
    int err = ws_tran_changed(ws);
    if (err)
        GKS_FAIL(err, GFN_SWKV3);
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
