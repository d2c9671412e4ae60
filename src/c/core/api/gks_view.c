/* SPDX-License-Identifier: MIT */
/*
 * gks_view.c -- GKS-3D viewing and HLHSR functions: SET VIEW INDEX, SET VIEW
 * REPRESENTATION 3, SET HLHSR MODE, and their inquiries (SET WINDOW 3 and SET VIEWPORT 3
 * are in gks_transform.c).
 */
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>



GKS_API void gset_view_ind(Gint view_ind)
{
    if (gks_check_state(GFN_SVWI))
        return;
    if (view_ind < 0)
        GKS_FAIL(514, GFN_SVWI);
    gks_attrs_w()->view_ind = view_ind;
}

static int matrix_finite(const Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            if (!isfinite(m[i][j]))
                return 0;
    return 1;
}

GKS_API void gset_view_rep3(Gint ws_id, Gint view_ind, const Gview_rep3 *rep)
{
    if (gks_check_state(GFN_SVWR))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SVWR, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (view_ind < 1 || view_ind > GKS_MAX_VIEW_IND)
        GKS_FAIL(515, GFN_SVWR);
    double b[6];
    if (!rep)
        GKS_FAIL(553, GFN_SVWR);
    gks_limit3_array(&rep->clip_limit, b);
    int err = gks_xform_check_view_clip_limits(b); /* 553, then 554 */
    if (err)
        GKS_FAIL(err, GFN_SVWR);
    if (!matrix_finite(rep->ori_matrix) || !matrix_finite(rep->map_matrix))
        GKS_FAIL(308, GFN_SVWR);
    if ((unsigned)rep->xy_clip > GIND_CLIP || (unsigned)rep->back_clip > GIND_CLIP ||
        (unsigned)rep->front_clip > GIND_CLIP)
        GKS_FAIL(2000, GFN_SVWR);
    ws->views[view_ind] = *rep;
    gks_ws_views_changed(ws);
    GKS_MF_WS(SVWR, ws_id, view_ind, &rep->ori_matrix[0][0], &rep->map_matrix[0][0],
              &rep->clip_limit.x_min, rep->xy_clip, rep->back_clip, rep->front_clip);
}

GKS_API void gset_hlhsr_mode(Gint ws_id, Gint mode)
{
    if (gks_check_state(GFN_SHRM))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SHRM, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (mode < 0 || mode > 31 || !(ws->drv->desc->hlhsr_modes & (1u << mode)))
        GKS_FAIL(511, GFN_SHRM);
    ws->hlhsr_mode = mode;
    GKS_MF_WS(SHRM, ws_id, mode);
}

GKS_API void ginq_view_ind(Gint *err_ind, Gint *view_ind)
{
    GKS_INQ_ARGS(err_ind, view_ind);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *view_ind = gks_ctx()->sl->attrs.view_ind;
}

GKS_API void ginq_view_rep3(Gint ws_id, Gint view_ind, Gint *err_ind, Gview_rep3 *rep)
{
    GKS_INQ_ARGS(err_ind, rep);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    if (view_ind < 0 || view_ind > GKS_MAX_VIEW_IND) {
        *err_ind = view_ind < 0 ? 514 : 515;
        return;
    }
    *rep = ws->views[view_ind];
}

GKS_API void ginq_hlhsr_mode(Gint ws_id, Gint *err_ind, Gint *mode)
{
    GKS_INQ_ARGS(err_ind, mode);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    *mode = ws->hlhsr_mode;
}
