/* SPDX-License-Identifier: MIT */
/*
 * gks_inq_std.c -- the remaining inquiry functions of ISO 7942 and ISO 8805 in their
 * ISO 8651-4 form: current attribute sets, pattern vectors, colour facilities and
 * indices, dynamic modification and default deferral entries of the description tables,
 * GKS-3D view and HLHSR facilities, GDP entries, pixel readback. (The C binding's Gstore
 * is gks_result_mem.c.) Like every inquiry they never call ERROR HANDLING: *err_ind
 * receives the error and nothing else is written on error.
 */
#include "gks_gdp.h"
#include "gks_legacy.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <string.h>

/* ------------------------------------------------------------- description tables */

GKS_API void ginq_colr_facs(Gint ws_type, Gint *err_ind, Gcolr_facs *colr_facs)
{
    GKS_INQ_ARGS(err_ind, colr_facs);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err_ind);
    if (d)
        *colr_facs = (Gcolr_facs){ d->n_colr, d->colr_avail, d->n_pred_colr };
}

GKS_API void ginq_pred_colr_rep(Gint ws_type, Gint ind, Gint *err_ind, Gcolr_rep *colr_rep)
{
    GKS_INQ_ARGS(err_ind, colr_rep);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err_ind);
    if (!d)
        return;
    if (ind < 0) {
        *err_ind = 93;
        return;
    }
    if (ind >= d->n_pred_colr) {
        *err_ind = 95;
        return;
    }
    colr_rep->rgb = d->pred_colr[ind];
}

/* Dynamic modification: a raster file workstation cannot change a written picture, so
 * every change of a displayed table entry needs an implicit regeneration (IRG), except
 * where nothing displayed depends on it. The PNG workstation draws with the bundle and
 * colour values current when a primitive is drawn; a changed entry changes only later
 * primitives, so a changed picture needs a regeneration: IRG throughout. */
GKS_API void ginq_dyn_mod_ws_attrs(Gint ws_type, Gint *err_ind, Gdyn_mod_ws_attrs *dyn_mod)
{
    GKS_INQ_ARGS(err_ind, dyn_mod);
    if (gks_inq_ws_type(ws_type, 1, err_ind))
        *dyn_mod = (Gdyn_mod_ws_attrs){ GDYN_IRG, GDYN_IRG, GDYN_IRG, GDYN_IRG,
                                        GDYN_IRG, GDYN_IRG, GDYN_IRG };
}

GKS_API void ginq_dyn_mod_ws_attrs3(Gint ws_type, Gint *err_ind, Gdyn_mod_ws_attrs3 *dyn_mod)
{
    GKS_INQ_ARGS(err_ind, dyn_mod);
    Gdyn_mod_ws_attrs a;
    ginq_dyn_mod_ws_attrs(ws_type, err_ind, &a);
    if (!*err_ind)
        *dyn_mod = (Gdyn_mod_ws_attrs3){ a, GDYN_IRG, GDYN_IRG, GDYN_IRG };
}

GKS_API void ginq_def_defer_sts(Gint ws_type, Gint *err_ind, Gdefer_mode *def_defer_mode,
                                Girg_mode *def_irg_mode)
{
    GKS_INQ_ARGS(err_ind, def_defer_mode, def_irg_mode);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err_ind);
    if (!d)
        return;
    *def_defer_mode = d->default_defer;
    *def_irg_mode = d->default_irg;
}

/* Segment changes (docs/BINDING.md, Segments): highlighting and detectability do not
 * change a PNG picture (IMM); a transformation, visibility or priority change and a
 * deletion need a regeneration; primitives added to an open segment are drawn at once. */
GKS_API void ginq_dyn_mod_seg_attrs(Gint ws_type, Gint *err_ind, Gdyn_mod_seg_attrs *dyn_mod)
{
    GKS_INQ_ARGS(err_ind, dyn_mod);
    if (gks_inq_ws_type(ws_type, 1, err_ind))
        *dyn_mod = (Gdyn_mod_seg_attrs){ .tran = GDYN_IRG, .appear = GDYN_IRG,
                                         .disappear = GDYN_IRG, .highl = GDYN_IMM,
                                         .pri = GDYN_IRG, .add_prim = GDYN_IMM,
                                         .del = GDYN_IRG };
}

GKS_API void ginq_disp_space_size3(Gint ws_type, Gint *err_ind, Gdisp_space_size3 *disp_size)
{
    GKS_INQ_ARGS(err_ind, disp_size);
    Gdisp_space_size s;
    ginq_disp_space_size(ws_type, err_ind, &s);
    if (*err_ind)
        return;
    /* DC z runs over [0, 1]; the raster has one depth unit. */
    *disp_size = (Gdisp_space_size3){ s.dc_units, { s.size_dc.size_x, s.size_dc.size_y, 1 },
                                      { s.size_raster.size_x, s.size_raster.size_y, 1 } };
}

GKS_API void ginq_max_ws_st_tables3(Gint ws_type, Gint *err_ind, Gmax_ws_st_tables3 *l)
{
    GKS_INQ_ARGS(err_ind, l);
    Gmax_ws_st_tables t;
    ginq_max_ws_st_tables(ws_type, err_ind, &t);
    if (*err_ind)
        return;
    *l = (Gmax_ws_st_tables3){ t.line_bundles, t.marker_bundles, t.text_bundles,
                               t.fill_bundles, t.pat_reps, t.colr_reps, t.edge_bundles,
                               GKS_MAX_VIEW_IND };
}

/* View 0 is the only predefined view (identity matrices, clip limits the NPC cube). */
GKS_API void ginq_view_facs(Gint ws_type, Gint *err_ind, Gint *num_pred_views)
{
    GKS_INQ_ARGS(err_ind, num_pred_views);
    if (gks_inq_ws_type(ws_type, 1, err_ind))
        *num_pred_views = 1;
}

GKS_API void ginq_pred_view_rep(Gint ws_type, Gint view_ind, Gint *err_ind, Gview_rep3 *rep)
{
    GKS_INQ_ARGS(err_ind, rep);
    if (!gks_inq_ws_type(ws_type, 1, err_ind))
        return;
    if (view_ind < 0) {
        *err_ind = 514;
        return;
    }
    if (view_ind > 0) {
        *err_ind = 2002;
        return;
    }
    memset(rep, 0, sizeof *rep);
    for (int i = 0; i < 4; i++)
        rep->ori_matrix[i][i] = rep->map_matrix[i][i] = 1;
    rep->clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    rep->xy_clip = rep->back_clip = rep->front_clip = GIND_CLIP;
}

/* HLHSR identifiers: every value is accepted and passed to the drivers, none selects a
 * method of its own: the list holds the default 0. Modes: those of the description
 * table (SET HLHSR MODE accepts them). */
GKS_API void ginq_hlhsr_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos,
                             Gint *err_ind, Gint_list *hlhsr_ids, Gint *length_ids,
                             Gint_list *hlhsr_modes, Gint *length_modes)
{
    GKS_INQ_ARGS(err_ind, hlhsr_ids, length_ids, hlhsr_modes, length_modes);
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err_ind);
    if (!d)
        return;
    int modes[32], n = 0;
    for (int m = 0; m < 32; m++)
        if (d->hlhsr_modes & (1u << m))
            modes[n++] = m;
    static const int ids[1] = { 0 };
    Gint e1 = gks_list_copy(ids, 1, num_elems_appl_list, start_pos, hlhsr_ids, length_ids);
    Gint e2 = gks_list_copy(modes, n, num_elems_appl_list, start_pos, hlhsr_modes, length_modes);
    *err_ind = e1 ? e1 : e2;
}

/* ------------------------------------------------------------ GKS state list values */
/* The pattern width (k = 0) or height (k = 1) vector: the pattern's width or height along
 * the direction of the k-th pattern reference vector, its x and y. */
static void pat_vec(Gint *err_ind, Gvec *v, int k)
{
    GKS_INQ_ARGS(err_ind, v);
    Gvec sz;
    Gpoint3 p;
    Gvec3 r[2];
    ginq_pat_size(err_ind, &sz.delta_x, &sz.delta_y);
    if (*err_ind)
        return;
    ginq_pat_ref_point_vecs(err_ind, &p, r);
    double l = sqrt(r[k].delta_x * r[k].delta_x + r[k].delta_y * r[k].delta_y +
                    r[k].delta_z * r[k].delta_z);
    double s = k ? sz.delta_y : sz.delta_x;
    *v = (Gvec){ s * r[k].delta_x / l, s * r[k].delta_y / l };
}

GKS_API void ginq_pat_width_vec(Gint *err_ind, Gvec *v)
{
    pat_vec(err_ind, v, 0);
}

GKS_API void ginq_pat_ht_vec(Gint *err_ind, Gvec *v)
{
    pat_vec(err_ind, v, 1);
}

GKS_API void ginq_cur_prim_attrs(Gint *err_ind, Gprim_attrs *p)
{
    GKS_INQ_ARGS(err_ind, p);
    *err_ind = gks_inq_state(GKS_S_OPEN);
    if (*err_ind)
        return;
    const gks_cur_attrs *a = &gks_ctx()->sl->attrs;
    Gint e;
    Gprim_attrs r = { .line_ind = a->line_ind, .marker_ind = a->marker_ind,
                      .text_ind = a->text_ind, .char_ht = a->char_ht,
                      .char_up_vec = a->char_up_vec, .text_path = a->text_path,
                      .text_align = a->text_align, .fill_ind = a->fill_ind,
                      .pat_ref_point = { a->pat_ref_point.x, a->pat_ref_point.y } };
    ginq_char_width(&e, &r.char_width);
    ginq_char_base_vec(&e, &r.char_base_vec);
    ginq_pat_width_vec(&e, &r.pat_width_vec);
    ginq_pat_ht_vec(&e, &r.pat_ht_vec);
    *p = r;
}

GKS_API void ginq_cur_prim_attrs3(Gint *err_ind, Gprim_attrs3 *p)
{
    GKS_INQ_ARGS(err_ind, p);
    Gprim_attrs b;
    ginq_cur_prim_attrs(err_ind, &b);
    if (*err_ind)
        return;
    const gks_cur_attrs *a = &gks_ctx()->sl->attrs;
    *p = (Gprim_attrs3){ b, a->pat_ref_point, { a->pat_ref_vec[0], a->pat_ref_vec[1] },
                         a->edge_ind, a->view_ind, a->hlhsr_id };
}

GKS_API void ginq_cur_indiv_attrs(Gint *err_ind, Gindiv_attrs *p)
{
    GKS_INQ_ARGS(err_ind, p);
    *err_ind = gks_inq_state(GKS_S_OPEN);
    if (*err_ind)
        return;
    const gks_cur_attrs *a = &gks_ctx()->sl->attrs;
    Gint e;
    Gindiv_attrs r = { .linetype = a->linetype, .linewidth = a->linewidth,
                       .line_colr_ind = a->line_colr_ind, .marker_type = a->marker_type,
                       .marker_size = a->marker_size, .marker_colr_ind = a->marker_colr_ind,
                       .text_font_prec = a->text_font_prec, .char_expan = a->char_expan,
                       .char_space = a->char_space, .text_colr_ind = a->text_colr_ind,
                       .fill_int_style = a->fill_int_style,
                       .fill_style_ind = a->fill_style_ind,
                       .fill_colr_ind = a->fill_colr_ind };
    ginq_asfs(&e, &r.asfs);
    *p = r;
}

GKS_API void ginq_cur_indiv_attrs3(Gint *err_ind, Gindiv_attrs3 *p)
{
    GKS_INQ_ARGS(err_ind, p);
    Gindiv_attrs b;
    ginq_cur_indiv_attrs(err_ind, &b);
    if (*err_ind)
        return;
    const gks_cur_attrs *a = &gks_ctx()->sl->attrs;
    Gindiv_attrs3 r = { .attrs = b, .edge_flag = a->edge_flag, .edgetype = a->edgetype,
                        .edgewidth = a->edgewidth, .edge_colr_ind = a->edge_colr_ind };
    Gint e;
    ginq_asfs3(&e, &r.asfs);
    *p = r;
}

GKS_API void ginq_seg_attrs(Gint seg_name, Gint *err_ind, Gseg_attrs *attrs)
{
    GKS_INQ_ARGS(err_ind, attrs);
    Gseg_attrs3 a;
    ginq_seg_attrs3(seg_name, err_ind, &a);
    if (*err_ind)
        return;
    attrs->seg_name = a.seg_name;
    for (int i = 0; i < 2; i++) { /* x/y rows; the z column is dropped */
        attrs->tran_matrix[i][0] = a.tran_matrix[i][0];
        attrs->tran_matrix[i][1] = a.tran_matrix[i][1];
        attrs->tran_matrix[i][2] = a.tran_matrix[i][3];
    }
    attrs->vis = a.vis;
    attrs->highl = a.highl;
    attrs->pri = a.pri;
    attrs->det = a.det;
}

/* --------------------------------------------------------------- workstation lists */
/* INQUIRE LIST OF COLOUR INDICES: 7, 20, 25, 33, 35, 36 (gks_inq_out_ws), then the
 * defined indices in ascending order under the list rule. */
GKS_API void ginq_list_colr_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                 Gint *err_ind, Gint_list *colr_inds, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, colr_inds, length_list);
    const gks_ws *ws = gks_inq_out_ws(ws_id, err_ind);
    if (ws)
        *err_ind = gks_list_flags(ws->colr_defined, 0, ws->drv->desc->n_colr - 1,
                                  num_elems_appl_list, start_pos, colr_inds, length_list);
}

/* ------------------------------------------------------------------------ GDPs */
GKS_API void ginq_list_avail_gdps3(Gint ws_type, Gint num_elems_appl_list, Gint start_pos,
                                   Gint *err_ind, Gint_list *gdps, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, gdps, length_list);
    ginq_list_avail_gdps(ws_type, num_elems_appl_list, start_pos, err_ind, gdps, length_list);
}

/* The attribute bundles of a GDP: 41 when ws_type cannot generate it. */
static void gdp_attrs(Gint ws_type, Gint gdp, Gint *err_ind, Gint *num_attr, Gattrs *attr,
                      int max)
{
    Gint len = 0, buf[64];
    Gint_list l = { 0, buf };
    ginq_list_avail_gdps(ws_type, 64, 0, err_ind, &l, &len);
    if (*err_ind)
        return;
    for (int i = 0; i < l.num_ints; i++)
        if (buf[i] == gdp) {
            Gattrs a[2];
            int k = gks_gdp_attrs(gdp, max == 5, a);
            for (int j = 0; j < k && j < max; j++)
                attr[j] = a[j];
            *num_attr = k;
            return;
        }
    *err_ind = 41;
}

GKS_API void ginq_gdp(Gint ws_type, Gint gdp, Gint *err_ind, Gint *num_attr, Gattrs attr[4])
{
    GKS_INQ_ARGS(err_ind, num_attr, attr);
    gdp_attrs(ws_type, gdp, err_ind, num_attr, attr, 4);
}

GKS_API void ginq_gdp3(Gint ws_type, Gint gdp, Gint *err_ind, Gint *num_attr, Gattrs attr[5])
{
    GKS_INQ_ARGS(err_ind, num_attr, attr);
    gdp_attrs(ws_type, gdp, err_ind, num_attr, attr, 5);
}

/* ------------------------------------------------------------------------ pixels */
/* The workstation of a pixel inquiry: 7, 20, 25, 39, 40. */
static gks_ws *pixel_ws(Gint ws_id, Gint *err)
{
    gks_ws *ws = gks_inq_ws(ws_id, err);
    if (!ws)
        return NULL;
    Gws_cat c = ws->drv->desc->cat;
    if (c != GCAT_OUT && c != GCAT_OUTIN) {
        *err = 39;
        return NULL;
    }
    if (!ws->drv->read_pixels) {
        *err = 40;
        return NULL;
    }
    return ws;
}

/* WC point -> image pixel of ws: the current normalization transformation, the current
 * view's orientation and mapping matrices, the workstation transformation (viewport
 * relative). 0 or 308. */
static int wc_to_pixel(const gks_ws *ws, const Gpoint *p, double *x, double *y)
{
    double n[3][4], m[4][4];
    if (gks_cur_norm_matrix(n))
        return 308;
    double h[4] = { n[0][0] * p->x + n[0][1] * p->y + n[0][3],
                    n[1][0] * p->x + n[1][1] * p->y + n[1][3],
                    n[2][0] * p->x + n[2][1] * p->y + n[2][3], 1 };
    const Gview_rep3 *v = &ws->views[gks_ctx()->sl->attrs.view_ind];
    double t[4], u[4];
    for (int i = 0; i < 4; i++)
        t[i] = v->ori_matrix[i][0] * h[0] + v->ori_matrix[i][1] * h[1] +
               v->ori_matrix[i][2] * h[2] + v->ori_matrix[i][3] * h[3];
    for (int i = 0; i < 4; i++)
        u[i] = v->map_matrix[i][0] * t[0] + v->map_matrix[i][1] * t[1] +
               v->map_matrix[i][2] * t[2] + v->map_matrix[i][3] * t[3];
    if (u[3] == 0 || !isfinite(u[3]))
        return 308;
    if (gks_ws_pixel_matrix(ws, 1.0, m))
        return 308;
    double q[3] = { u[0] / u[3], u[1] / u[3], u[2] / u[3] };
    *x = m[0][0] * q[0] + m[0][1] * q[1] + m[0][2] * q[2] + m[0][3];
    *y = m[1][0] * q[0] + m[1][1] * q[1] + m[1][2] * q[2] + m[1][3];
    return isfinite(*x) && isfinite(*y) ? 0 : 308;
}

/* Pixel column/row of an image coordinate, kept in int range (far points stay outside). */
static int pixel_index(double c)
{
    double f = floor(c);
    return f < -1e9 ? -1000000000 : f > 1e9 ? 1000000000 : (int)f;
}

/* Colour index of an 0xRRGGBB pixel: the lowest defined colour table entry whose 8-bit
 * realization it is, else -1. */
static Gint colour_index(const gks_ws *ws, int rgb)
{
    if (rgb < 0)
        return -1;
    for (int i = 0; i < ws->drv->desc->n_colr; i++) {
        if (!ws->colr_defined[i])
            continue;
        const Grgb *c = &ws->colr[i];
        int r = (int)lrint(c->red * 255), g = (int)lrint(c->green * 255),
            b = (int)lrint(c->blue * 255);
        if (((r << 16) | (g << 8) | b) == rgb)
            return i;
    }
    return -1;
}

GKS_API void ginq_pixel_array_dims(Gint ws_id, const Grect *rect, Gint *err_ind, Gint_size *dims)
{
    GKS_INQ_ARGS(err_ind, rect, dims);
    gks_ws *ws = pixel_ws(ws_id, err_ind);
    if (!ws)
        return;
    double px, py, qx, qy;
    if ((*err_ind = wc_to_pixel(ws, &rect->p, &px, &py)) ||
        (*err_ind = wc_to_pixel(ws, &rect->q, &qx, &qy)))
        return;
    /* Pixels whose centres lie in the rectangle (at least the one containing P). */
    double x0 = fmin(px, qx), x1 = fmax(px, qx), y0 = fmin(py, qy), y1 = fmax(py, qy);
    double nx = floor(x1 - 0.5) - ceil(x0 - 0.5) + 1, ny = floor(y1 - 0.5) - ceil(y0 - 0.5) + 1;
    dims->size_x = nx < 1 ? 1 : nx > 1e9 ? 1000000000 : (Gint)nx;
    dims->size_y = ny < 1 ? 1 : ny > 1e9 ? 1000000000 : (Gint)ny;
}

GKS_API void ginq_pixel_array(Gint ws_id, const Gpoint *pixel_loc, const Gint_size *dims,
                              Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                              Gpres_inval *pres_inval, Gint_list *pixel_array,
                              Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, pixel_loc, dims, pres_inval, pixel_array, length_list);
    gks_ws *ws = pixel_ws(ws_id, err_ind);
    if (!ws)
        return;
    if (dims->size_x < 1 || dims->size_y < 1) {
        *err_ind = 91;
        return;
    }
    double x, y;
    if ((*err_ind = wc_to_pixel(ws, pixel_loc, &x, &y)))
        return;
    long long total = (long long)dims->size_x * dims->size_y;
    if (start_pos < 0 || start_pos >= total) {
        *err_ind = 2002;
        return;
    }
    *length_list = total > 0x7fffffff ? 0x7fffffff : (Gint)total;
    /* Row by row from the top row (the one containing pixel_loc) downward. */
    int ix = pixel_index(x), iy = pixel_index(y), nx = dims->size_x;
    int *row = gks_alloc_array((size_t)nx, sizeof *row);
    if (!row) {
        *err_ind = 300;
        return;
    }
    Gpres_inval inval = GINVAL_ABSENT;
    int k = 0, cap = pixel_array && pixel_array->ints ? num_elems_appl_list : 0;
    long long first = start_pos, last = first + (cap > 0 ? cap : 0);
    if (last > total)
        last = total;
    for (long long e = first; e < last;) {
        int j = (int)(e / nx);
        if (ws->drv->read_pixels(ws, ix, iy - j, nx, 1, row)) {
            *err_ind = 300;
            break;
        }
        for (int i = (int)(e % nx); i < nx && e < last; i++, e++) {
            Gint c = colour_index(ws, row[i]);
            if (c < 0)
                inval = GINVAL_PRESENT;
            pixel_array->ints[k++] = c;
        }
    }
    gks_free(row);
    if (*err_ind)
        return;
    if (pixel_array)
        pixel_array->num_ints = k;
    *pres_inval = inval;
}

GKS_API void ginq_pixel(Gint ws_id, const Gpoint *pixel_loc, Gint *err_ind, Gint *colr_ind)
{
    GKS_INQ_ARGS(err_ind, pixel_loc, colr_ind);
    gks_ws *ws = pixel_ws(ws_id, err_ind);
    if (!ws)
        return;
    double x, y;
    if ((*err_ind = wc_to_pixel(ws, pixel_loc, &x, &y)))
        return;
    int rgb;
    if (ws->drv->read_pixels(ws, pixel_index(x), pixel_index(y), 1, 1, &rgb)) {
        *err_ind = 300;
        return;
    }
    *colr_ind = colour_index(ws, rgb);
}
