/* SPDX-License-Identifier: MIT */
/*
 * gks_priority.c -- input priority orderings: SET VIEWPORT INPUT PRIORITY (normalization
 * transformations, GKS state list) and SET VIEW TRANSFORMATION INPUT PRIORITY (view
 * indices, workstation state list), with their list inquiries. The orderings decide which
 * transformation maps a LOCATOR/STROKE position back (gks_indev.c reads them).
 */
#include "gks_error.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <string.h>

/* Moves item a directly above (higher) or below ref in list[0..n-1] (highest first). */
static void reorder(int *list, int n, int a, int ref, int higher)
{
    if (a == ref)
        return;
    int k = 0;
    for (int i = 0; i < n; i++) /* remove a */
        if (list[i] != a)
            list[k++] = list[i];
    int r = 0;
    while (r < k && list[r] != ref)
        r++;
    int at = higher ? r : r + 1;
    memmove(list + at + 1, list + at, (size_t)(k - at) * sizeof *list);
    list[at] = a;
}

GKS_API void gset_vp_in_pri(Gint tran_num, Gint ref_tran_num, Grel_pri rel_pri)
{
    if (gks_check_state(GFN_SVPIP))
        return;
    if (tran_num < 0 || tran_num > GKS_MAX_NORM_TRAN || ref_tran_num < 0 ||
        ref_tran_num > GKS_MAX_NORM_TRAN)
        GKS_FAIL(50, GFN_SVPIP);
    if (rel_pri != GPRI_HIGHER && rel_pri != GPRI_LOWER)
        GKS_FAIL(2000, GFN_SVPIP);
    reorder(gks_ctx()->sl->tran_pri, GKS_MAX_NORM_TRAN + 1, tran_num, ref_tran_num,
            rel_pri == GPRI_HIGHER);
}

GKS_API void ginq_list_norm_tran_nums(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                      Gint_list *list, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, list, length_list);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *err_ind = gks_list_copy(gks_ctx()->sl->tran_pri, GKS_MAX_NORM_TRAN + 1,
                                 num_elems_appl_list, start_pos, list, length_list);
}

GKS_API void gset_view_tran_in_pri(Gint ws_id, Gint view_ind, Gint ref_view_ind,
                                   Grel_pri rel_pri)
{
    if (gks_check_state(GFN_SVTIP))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SVTIP, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (view_ind < 0 || view_ind > GKS_MAX_VIEW_IND || ref_view_ind < 0 ||
        ref_view_ind > GKS_MAX_VIEW_IND)
        GKS_FAIL(515, GFN_SVTIP);
    if (rel_pri != GPRI_HIGHER && rel_pri != GPRI_LOWER)
        GKS_FAIL(2000, GFN_SVTIP);
    reorder(ws->view_pri, GKS_MAX_VIEW_IND + 1, view_ind, ref_view_ind, rel_pri == GPRI_HIGHER);
}

GKS_API void ginq_list_view_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                 Gint *err_ind, Gint_list *list, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, list, length_list);
    const gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (ws)
        *err_ind = gks_list_copy(ws->view_pri, GKS_MAX_VIEW_IND + 1, num_elems_appl_list,
                                 start_pos, list, length_list);
}
