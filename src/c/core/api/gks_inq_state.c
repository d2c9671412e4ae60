/* SPDX-License-Identifier: MIT */
/*
 * gks_inq_state.c -- inquiry functions. They never call ERROR HANDLING: the error
 * indicator receives the error number (state errors as the function's class requires:
 * 8 for the GKS state list, 7 for workstation state lists, 0 for description tables that
 * are available in every state except GKCL (8)), and nothing else is written on error.
 */
#include "gks_legacy.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <string.h>

gks_ws *gks_inq_ws(Gint ws_id, Gint *err)
{
    if (gks_inq_begin(err, GKS_S_WSOPEN))
        return NULL;
    if (ws_id < 0) {
        *err = 20;
        return NULL;
    }
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        *err = 25;
    return ws;
}

gks_ws *gks_inq_out_ws(Gint ws_id, Gint *err)
{
    gks_ws *ws = gks_inq_ws(ws_id, err);
    if (!ws)
        return NULL;
    Gws_cat c = ws->drv->desc->cat;
    *err = c == GCAT_MI ? 33 : c == GCAT_IN ? 35 : c == GCAT_WISS ? 36 : 0;
    return *err ? NULL : ws;
}

const gks_ws_desc *gks_inq_ws_type(Gint ws_type, int out, Gint *err)
{
    *err = gks_inq_state(GKS_S_OPEN);
    if (*err)
        return NULL;
    if (gks_ws_type_map(ws_type) <= 0) {
        *err = 22;
        return NULL;
    }
    const gks_ws_driver *d = gks_driver_for_type(ws_type);
    if (!d) {
        *err = 23;
        return NULL;
    }
    if (out && d->desc->cat != GCAT_OUT && d->desc->cat != GCAT_OUTIN) {
        *err = 39;
        return NULL;
    }
    return d->desc;
}

GKS_API void ginq_op_st(Gop_st *op_st)
{
    if (!gks_thread_mine()) { /* no error indicator: reported through the handler */
        gks_thread_refused(-1);
        return;
    }
    if (op_st)
        *op_st = gks_ctx()->op_st;
}

GKS_API void ginq_level_gks(Gint *err_ind, Glevel *level)
{
    GKS_INQ_ARGS(err_ind, level);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *level = gks_ctx()->desc->level;
}

GKS_API void ginq_list_avail_ws_types(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                      Gint_list *ws_types, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, ws_types, length_list);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_desc_table *d = gks_ctx()->desc;
    int types[16];
    int n = d->n_ws_types < 16 ? d->n_ws_types : 16;
    for (int i = 0; i < n; i++)
        types[i] = d->ws_types[i]->desc->type;
    *err_ind = gks_list_copy(types, n, num_elems_appl_list, start_pos, ws_types, length_list);
}

GKS_API void ginq_ws_max_nums(Gint *err_ind, Gws_max_nums *ws_max_num)
{
    GKS_INQ_ARGS(err_ind, ws_max_num);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *ws_max_num = gks_ctx()->desc->max_nums;
}

GKS_API void ginq_max_norm_tran_num(Gint *err_ind, Gint *max_norm_tran_num)
{
    GKS_INQ_ARGS(err_ind, max_norm_tran_num);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *max_norm_tran_num = gks_ctx()->desc->max_norm_tran;
}

/* INQUIRE SET OF OPEN / ACTIVE WORKSTATIONS: 8, then the list rule over the identifiers. */
static void ws_set(int active, Gint cap, Gint start, Gint *err_ind, Gint_list *out,
                   Gint *length_list)
{
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_state_list *sl = gks_ctx()->sl;
    *err_ind = active ? gks_list_copy(sl->active_ws, sl->n_active, cap, start, out, length_list)
                      : gks_list_copy(sl->open_ws, sl->n_open, cap, start, out, length_list);
}

GKS_API void ginq_set_open_wss(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                               Gint_list *open_ws, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, open_ws, length_list);
    ws_set(0, num_elems_appl_list, start_pos, err_ind, open_ws, length_list);
}

GKS_API void ginq_set_active_wss(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                 Gint_list *active_ws, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, active_ws, length_list);
    ws_set(1, num_elems_appl_list, start_pos, err_ind, active_ws, length_list);
}

GKS_API void ginq_ws_conn_type(Gint ws_id, Gint string_length, Gint *err_ind, char *conn_id,
                               Gint *ws_type)
{
    GKS_INQ_ARGS(err_ind, conn_id, ws_type);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    size_t len = strlen(ws->conn_id);
    if (conn_id && string_length > 0) {
        size_t k = len < (size_t)string_length - 1 ? len : (size_t)string_length - 1;
        memcpy(conn_id, ws->conn_id, k);
        conn_id[k] = '\0';
    }
    if (ws_type)
        *ws_type = ws->drv->desc->type;
}

GKS_API void ginq_ws_st(Gint ws_id, Gint *err_ind, Gws_st *ws_st)
{
    GKS_INQ_ARGS(err_ind, ws_st);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (ws)
        *ws_st = ws->state;
}

GKS_API void ginq_ws_defer_upd_sts(Gint ws_id, Gint *err_ind, Gdefer_mode *defer_mode,
                                   Girg_mode *irg_mode, Gdisp_space_empty *disp_empty,
                                   Gnew_frame_nec_upd *new_frame)
{
    GKS_INQ_ARGS(err_ind, defer_mode, irg_mode, disp_empty, new_frame);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    *defer_mode = ws->defer_mode;
    *irg_mode = ws->irg_mode;
    *disp_empty = ws->disp_empty;
    *new_frame = ws->new_frame;
}

GKS_API void ginq_ws_cat(Gint ws_type, Gint *err_ind, Gws_cat *cat)
{
    GKS_INQ_ARGS(err_ind, cat);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 0, err_ind);
    if (d)
        *cat = d->cat;
}

GKS_API void ginq_ws_class(Gint ws_type, Gint *err_ind, Gws_class *ws_class)
{
    GKS_INQ_ARGS(err_ind, ws_class);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err_ind);
    if (d)
        *ws_class = d->cls;
}

GKS_API void ginq_disp_space_size(Gint ws_type, Gint *err_ind, Gdisp_space_size *disp_size)
{
    GKS_INQ_ARGS(err_ind, disp_size);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 0, err_ind);
    if (!d)
        return;
    if (d->cat != GCAT_OUT && d->cat != GCAT_OUTIN) {
        *err_ind = 31;
        return;
    }
    disp_size->dc_units = d->dc_units;
    disp_size->size_dc = (Gfloat_size){ d->dc_x, d->dc_y };
    disp_size->size_raster = (Gint_size){ d->raster_x, d->raster_y };
}

GKS_API void ginq_colr_rep(Gint ws_id, Gint colr_ind, Ginq_type type, Gint *err_ind,
                           Gcolr_rep *colr_rep)
{
    GKS_INQ_ARGS(err_ind, colr_rep);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    if (ws->drv->desc->cat == GCAT_MI) { *err_ind = 33; return; }
    if (colr_ind < 0) { *err_ind = 93; return; }
    if (type != GINQ_SET && type != GINQ_REALIZED) { *err_ind = 2000; return; }
    if (colr_ind >= ws->drv->desc->n_colr || !ws->colr_defined[colr_ind]) {
        *err_ind = 94;
        return;
    }
    Grgb c = ws->colr[colr_ind];
    if (type == GINQ_REALIZED) { /* 8 bits per component in the PNG */
        c.red = (int)(c.red * 255 + 0.5) / 255.0;
        c.green = (int)(c.green * 255 + 0.5) / 255.0;
        c.blue = (int)(c.blue * 255 + 0.5) / 255.0;
    }
    colr_rep->rgb = c;
}

