/* SPDX-License-Identifier: MIT */
/*
 * gks_inq_attr.c -- inquiries of the output attributes: current primitive attributes
 * (GKS state list), workstation bundle tables (SET and REALIZED values), the output
 * facilities and predefined bundles of workstation description tables, and INQUIRE TEXT
 * EXTENT (3). They never call ERROR HANDLING; nothing but *err_ind is written on error.
 */
#include "gks_legacy.h"
#include "gks_attr_resolve.h"
#include "gks_error.h"
#include "gks_gdp.h"
#include "gks_result_mem.h"
#include "gks_state.h"
#include "gks_text_layout.h"
#include "gks_ws.h"
#include <math.h>
#include <string.h>

/* ------------------------------------------------------------------ current values */
/* Body of a current-attribute inquiry: error 8 unless GKS is open. */
#define INQ_CUR(OUT, EXPR)                                                            \
    do {                                                                              \
        GKS_INQ_ARGS(err_ind, OUT);                                                   \
        *err_ind = gks_inq_state(GKS_S_OPEN);                                         \
        if (!*err_ind) {                                                              \
            const gks_cur_attrs *a = &gks_ctx()->sl->attrs;                           \
            *(OUT) = (EXPR);                                                          \
        }                                                                             \
    } while (0)

GKS_API void ginq_line_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->line_ind); }
GKS_API void ginq_linetype(Gint *err_ind, Gint *v) { INQ_CUR(v, a->linetype); }
GKS_API void ginq_linewidth(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->linewidth); }
GKS_API void ginq_line_colr_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->line_colr_ind); }
GKS_API void ginq_marker_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->marker_ind); }
GKS_API void ginq_marker_type(Gint *err_ind, Gint *v) { INQ_CUR(v, a->marker_type); }
GKS_API void ginq_marker_size(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->marker_size); }
GKS_API void ginq_marker_colr_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->marker_colr_ind); }
GKS_API void ginq_text_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->text_ind); }
GKS_API void ginq_text_font_prec(Gint *err_ind, Gtext_font_prec *v) { INQ_CUR(v, a->text_font_prec); }
GKS_API void ginq_char_expan(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->char_expan); }
GKS_API void ginq_char_space(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->char_space); }
GKS_API void ginq_text_colr_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->text_colr_ind); }
GKS_API void ginq_char_ht(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->char_ht); }
GKS_API void ginq_char_up_vec(Gint *err_ind, Gvec *v) { INQ_CUR(v, a->char_up_vec); }
GKS_API void ginq_char_width(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->char_ht); }
GKS_API void ginq_text_path(Gint *err_ind, Gtext_path *v) { INQ_CUR(v, a->text_path); }
GKS_API void ginq_text_align(Gint *err_ind, Gtext_align *v) { INQ_CUR(v, a->text_align); }
GKS_API void ginq_fill_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->fill_ind); }
GKS_API void ginq_fill_int_style(Gint *err_ind, Gfill_int_style *v) { INQ_CUR(v, a->fill_int_style); }
GKS_API void ginq_fill_style_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->fill_style_ind); }
GKS_API void ginq_fill_colr_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->fill_colr_ind); }
GKS_API void ginq_pat_size(Gint *err_ind, Gdouble *x_size, Gdouble *y_size)
{
    GKS_INQ_ARGS(err_ind, x_size, y_size);
    Gvec v;
    INQ_CUR(&v, a->pat_size);
    if (*err_ind)
        return;
    *x_size = v.delta_x;
    *y_size = v.delta_y;
}
GKS_API void ginq_pick_id(Gint *err_ind, Gint *v) { INQ_CUR(v, a->pick_id); }
GKS_API void ginq_hlhsr_id(Gint *err_ind, Gint *v) { INQ_CUR(v, a->hlhsr_id); }
GKS_API void ginq_edge_flag(Gint *err_ind, Gedge_flag *v) { INQ_CUR(v, a->edge_flag); }
GKS_API void ginq_edgetype(Gint *err_ind, Gint *v) { INQ_CUR(v, a->edgetype); }
GKS_API void ginq_edgewidth(Gint *err_ind, Gfloat *v) { INQ_CUR(v, a->edgewidth); }
GKS_API void ginq_edge_colr_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->edge_colr_ind); }
GKS_API void ginq_edge_ind(Gint *err_ind, Gint *v) { INQ_CUR(v, a->edge_ind); }

GKS_API void ginq_char_base_vec(Gint *err_ind, Gvec *v)
{
    GKS_INQ_ARGS(err_ind, v);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const Gvec *u = &gks_ctx()->sl->attrs.char_up_vec;
    double l = hypot(u->delta_x, u->delta_y);
    *v = (Gvec){ u->delta_y / l, -u->delta_x / l };
}

GKS_API void ginq_pat_ref_point(Gint *err_ind, Gpoint *v)
{
    GKS_INQ_ARGS(err_ind, v);
    if (!gks_inq_begin(err_ind, GKS_S_OPEN))
        *v = (Gpoint){ gks_ctx()->sl->attrs.pat_ref_point.x, gks_ctx()->sl->attrs.pat_ref_point.y };
}

GKS_API void ginq_pat_ref_point_vecs(Gint *err_ind, Gpoint3 *p, Gvec3 vecs[2])
{
    GKS_INQ_ARGS(err_ind, p, vecs);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_cur_attrs *a = &gks_ctx()->sl->attrs;
    *p = a->pat_ref_point;
    vecs[0] = a->pat_ref_vec[0];
    vecs[1] = a->pat_ref_vec[1];
}

GKS_API void ginq_asfs3(Gint *err_ind, Gasfs3 *s)
{
    GKS_INQ_ARGS(err_ind, s);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const Gasf *f = gks_ctx()->sl->attrs.asf;
    s->asfs = (Gasfs){ f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8], f[9], f[10],
                       f[11], f[12] };
    s->edge_flag = f[GKS_ASF_EDGE_FLAG];
    s->edgetype = f[GKS_ASF_EDGETYPE];
    s->edgewidth = f[GKS_ASF_EDGEWIDTH];
    s->edge_colr_ind = f[GKS_ASF_EDGE_COLR];
}

GKS_API void ginq_asfs(Gint *err_ind, Gasfs *s)
{
    GKS_INQ_ARGS(err_ind, s);
    Gasfs3 s3;
    ginq_asfs3(err_ind, &s3);
    if (!*err_ind)
        *s = s3.asfs;
}

/* ------------------------------------------------------------------ bundle tables */
/* The open output workstation of a representation inquiry (7, 20, 25, then 33, 35, 36
 * as SET ... REPRESENTATION); the index range (err_ind_bad) and the type (2000). */
static gks_ws *rep_ws(Gint ws_id, Gint ind, Ginq_type type, int err_bad_ind, Gint *err)
{
    gks_ws *ws = gks_inq_out_ws(ws_id, err);
    if (!ws)
        return NULL;
    if (!*err && (ind < 1 || ind > gks_attr_wdt(ws)->max_bundles || ind > GKS_WDT_MAX_BUNDLES))
        *err = err_bad_ind;
    if (!*err && type != GINQ_SET && type != GINQ_REALIZED)
        *err = 2000;
    return *err ? NULL : ws;
}

/* The representation inquiries: rep_ws's checks, then the undefined index (err_undef),
 * then the SET value or the REALIZED one (gks_attr_realize_*). */
#define REP_INQ(NAME, BUNDLE, KIND, ERR_BAD, ERR_UNDEF)                                  \
    GKS_API void NAME(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, BUNDLE *rep) \
    {                                                                                    \
        GKS_INQ_ARGS(err_ind, rep);                                                      \
        gks_ws *ws = rep_ws(ws_id, ind, type, ERR_BAD, err_ind);                         \
        if (!ws)                                                                         \
            return;                                                                      \
        if (!ws->KIND##_def[ind])                                                        \
            *err_ind = ERR_UNDEF;                                                        \
        else if (type == GINQ_REALIZED)                                                  \
            gks_attr_realize_##KIND(ws, &ws->KIND##_rep[ind], rep);                      \
        else                                                                             \
            *rep = ws->KIND##_rep[ind];                                                  \
    }
REP_INQ(ginq_line_rep, Gline_bundle, line, 60, 61)
REP_INQ(ginq_marker_rep, Gmarker_bundle, marker, 66, 67)
REP_INQ(ginq_text_rep, Gtext_bundle, text, 72, 73)
REP_INQ(ginq_fill_rep, Gfill_bundle, fill, 80, 81)
REP_INQ(ginq_edge_rep, Gedge_bundle, edge, 500, 501)
#undef REP_INQ

/* Copy a pattern (nx x ny indices) into rep (capacity cap): 2001 if too small. realize:
 * replace undefined colour indices of ws by 1 (ws may be NULL for predefined ones). */
/* A pattern into the application's store (ISO 8651-4): the Gpat_rep and its colour array
 * in one block; *out points at it. 2003 without a store, 300 when memory is exhausted. */
static int put_pattern(const gks_ws *ws, int nx, int ny, const int *colr, Gstore *store,
                       Gpat_rep **out)
{
    if (!store || !*store || !out)
        return 2003;
    size_t n = (size_t)nx * (size_t)ny;
    Gpat_rep *rep = gks_result_alloc(*store, 1, sizeof *rep + n * sizeof(Gint));
    if (!rep)
        return 300;
    rep->dims = (Gint_size){ nx, ny };
    rep->colr_array = (Gint *)(rep + 1);
    for (size_t i = 0; i < n; i++)
        rep->colr_array[i] = ws ? gks_attr_colr_ind(ws, colr[i]) : colr[i];
    *out = rep;
    return 0;
}

GKS_API void ginq_pat_rep(Gint ws_id, Gint ind, Ginq_type type, Gstore *store, Gint *err_ind,
                          Gpat_rep **rep)
{
    GKS_INQ_ARGS(err_ind, store, rep);
    gks_ws *ws = rep_ws(ws_id, ind, type, 85, err_ind);
    if (!ws)
        return;
    if (!ws->pat_def[ind]) {
        *err_ind = 88;
        return;
    }
    *err_ind = put_pattern(type == GINQ_REALIZED ? ws : NULL, ws->pat_rep[ind].nx,
                           ws->pat_rep[ind].ny, ws->pat_rep[ind].colr, store, rep);
}

/* List of defined indices of a bundle table. */
static void list_inds(Gint ws_id, const unsigned char *(*def)(const gks_ws *), Gint cap,
                      Gint start, Gint *err_ind, Gint_list *out, Gint *len)
{
    gks_ws *ws = gks_inq_out_ws(ws_id, err_ind);
    if (!ws)
        return;
    *err_ind = gks_list_flags(def(ws), 1, GKS_WDT_MAX_BUNDLES, cap, start, out, len);
}

static const unsigned char *def_line(const gks_ws *ws) { return ws->line_def; }
static const unsigned char *def_marker(const gks_ws *ws) { return ws->marker_def; }
static const unsigned char *def_text(const gks_ws *ws) { return ws->text_def; }
static const unsigned char *def_fill(const gks_ws *ws) { return ws->fill_def; }
static const unsigned char *def_pat(const gks_ws *ws) { return ws->pat_def; }
static const unsigned char *def_edge(const gks_ws *ws) { return ws->edge_def; }

#define LIST_INQ(NAME, DEF)                                                              \
    GKS_API void NAME(Gint ws_id, Gint cap, Gint start, Gint *err_ind, Gint_list *inds, \
                      Gint *length_list)                                                 \
    {                                                                                    \
        GKS_INQ_ARGS(err_ind, inds, length_list);                                        \
        list_inds(ws_id, DEF, cap, start, err_ind, inds, length_list);                   \
    }
LIST_INQ(ginq_list_line_inds, def_line)
LIST_INQ(ginq_list_marker_inds, def_marker)
LIST_INQ(ginq_list_text_inds, def_text)
LIST_INQ(ginq_list_fill_inds, def_fill)
LIST_INQ(ginq_list_pat_inds, def_pat)
LIST_INQ(ginq_list_edge_inds, def_edge)

/* ------------------------------------------------------------------ text extent */
static void text_extent_any(Gint ws_id, const double pos[3], const double d0[3],
                            const double d1[3], const char *str, Gint *err_ind,
                            double corners[4][3], double concat[3])
{
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    Gws_cat cat = ws->drv->desc->cat;
    if (cat != GCAT_OUT && cat != GCAT_OUTIN) {
        *err_ind = 39;
        return;
    }
    if (!str || gks_text_check(str)) {
        *err_ind = 101;
        return;
    }
    if (!isfinite(pos[0]) || !isfinite(pos[1]) || !isfinite(pos[2])) {
        *err_ind = 308; /* non-finite text position */
        return;
    }
    gks_text_frame f;
    if (gks_text_frame3(pos, d0, d1, &f)) {
        *err_ind = 2000; /* degenerate text direction vectors (TEXT 3) */
        return;
    }
    gks_text_attrs ta;
    gks_attr_text_layout(ws, &gks_ctx()->sl->attrs, &ta, NULL);
    gks_text_extent(&f, &ta, str, corners, concat);
}

GKS_API void ginq_text_extent(Gint ws_id, const Gpoint *pos, const char *str, Gint *err_ind,
                              Gtext_extent *extent)
{
    GKS_INQ_ARGS(err_ind, pos, str, extent);
    double c[4][3], cc[3];
    const double p[3] = { pos ? pos->x : 0, pos ? pos->y : 0, 0 };
    text_extent_any(ws_id, p, (const double[3]){ 1, 0, 0 }, (const double[3]){ 0, 1, 0 },
                    str, err_ind, c, cc);
    if (*err_ind)
        return;
    extent->concat_point = (Gpoint){ cc[0], cc[1] };
    for (int i = 0; i < 4; i++)
        extent->paral[i] = (Gpoint){ c[i][0], c[i][1] };
}

GKS_API void ginq_text_extent3(Gint ws_id, const Gpoint3 *pos, const Gvec3 dir[2],
                               const char *str, Gint *err_ind, Gtext_extent3 *extent)
{
    GKS_INQ_ARGS(err_ind, pos, dir, str, extent);
    double c[4][3], cc[3];
    const double p[3] = { pos ? pos->x : NAN, pos ? pos->y : NAN, pos ? pos->z : NAN };
    double d0[3] = { 1, 0, 0 }, d1[3] = { 0, 1, 0 };
    if (dir) {
        d0[0] = dir[0].delta_x; d0[1] = dir[0].delta_y; d0[2] = dir[0].delta_z;
        d1[0] = dir[1].delta_x; d1[1] = dir[1].delta_y; d1[2] = dir[1].delta_z;
    }
    text_extent_any(ws_id, p, d0, d1, str, err_ind, c, cc);
    if (*err_ind)
        return;
    extent->concat_point = (Gpoint3){ cc[0], cc[1], cc[2] };
    for (int i = 0; i < 4; i++)
        extent->paral[i] = (Gpoint3){ c[i][0], c[i][1], c[i][2] };
}

/* ------------------------------------------------------------------ description tables */
/* The output description table of a workstation type: 8, 22, 23, 39. */
static const gks_wdt_output *inq_out_type(Gint ws_type, Gint *err)
{
    const gks_ws_desc *d = gks_inq_ws_type(ws_type, 1, err);
    if (!d)
        return NULL;
    return d->out ? d->out : &gks_wdt_raster;
}

/* The polyline, polymarker and edge facilities have one form: the types under the list
 * rule, the number of widths or sizes (0: continuous), their nominal, minimum and maximum,
 * and the number of predefined bundles; written into the members the caller names. */
typedef struct {
    Gint_list *types;
    Gint *num;
    Gfloat *nom, *min, *max;
    Gint *num_pred;
} size_facs_out;

enum { FACS_LINE, FACS_MARKER, FACS_EDGE };

static void size_facs(Gint ws_type, int which, Gint cap, Gint start, Gint *err_ind,
                      Gint *length_list, size_facs_out o)
{
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (!t)
        return;
    const gks_wdt_sizes *z = which == FACS_LINE ? &t->line
                             : which == FACS_MARKER ? &t->marker
                                                    : &t->edge;
    *err_ind = gks_list_copy(z->types, z->n_types, cap, start, o.types, length_list);
    if (*err_ind)
        return;
    *o.num = z->n_sizes;
    *o.nom = z->nom;
    *o.min = z->min;
    *o.max = z->max;
    *o.num_pred = which == FACS_LINE     ? t->n_pred_line
                  : which == FACS_MARKER ? t->n_pred_marker
                                         : t->n_pred_edge;
}

#define SIZE_FACS(name, T, which, num_, nom_, min_, max_)                                \
    GKS_API void name(Gint ws_type, Gint cap, Gint start, Gint *err_ind, T *f,           \
                      Gint *length_list)                                                 \
    {                                                                                    \
        GKS_INQ_ARGS(err_ind, f, length_list);                                           \
        size_facs(ws_type, which, cap, start, err_ind, length_list,                      \
                  (size_facs_out){ &f->types, &f->num_, &f->nom_, &f->min_, &f->max_,    \
                                   &f->num_pred_inds });                                 \
    }
SIZE_FACS(ginq_line_facs, Gline_facs, FACS_LINE, num_widths, nom_width, min_width, max_width)
SIZE_FACS(ginq_marker_facs, Gmarker_facs, FACS_MARKER, num_sizes, nom_size, min_size, max_size)
SIZE_FACS(ginq_edge_facs, Gedge_facs, FACS_EDGE, num_widths, nom_width, min_width, max_width)
#undef SIZE_FACS

GKS_API void ginq_text_facs(Gint ws_type, Gint cap, Gint start, Gint *err_ind,
                            Gtext_facs *f, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, f, length_list);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (!t)
        return;
    gks_list_out w = { .num = &f->num_font_precs, .cap = f->font_precs ? cap : 0, .start = start };
    for (int i = 0; i < t->n_font_precs; i++) {
        int k = gks_list_slot(&w);
        if (k >= 0)
            f->font_precs[k] = t->font_precs[i];
    }
    if ((*err_ind = gks_list_end(&w, length_list)))
        return;
    f->num_char_hts = t->n_char_hts;
    f->min_char_ht = t->min_char_ht;
    f->max_char_ht = t->max_char_ht;
    f->num_char_expans = t->n_char_expans;
    f->min_char_expan = t->min_char_expan;
    f->max_char_expan = t->max_char_expan;
    f->num_pred_inds = t->n_pred_text;
}

GKS_API void ginq_fill_facs(Gint ws_type, Gint hatch_length, Gint hatch_start_pos,
                            Gint *err_ind, Gfill_facs *f, Gint *act_hatch_length)
{
    GKS_INQ_ARGS(err_ind, f, act_hatch_length);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (!t)
        return;
    *err_ind = gks_list_copy(t->hatch_styles, t->n_hatch_styles, hatch_length, hatch_start_pos,
                         &f->hatch_styles, act_hatch_length);
    if (*err_ind)
        return;
    int n = t->n_int_styles < 4 ? t->n_int_styles : 4;
    f->num_int_styles = n;
    for (int i = 0; i < n; i++)
        f->int_style[i] = (Gfill_int_style)t->int_styles[i];
    f->num_pred_inds = t->n_pred_fill;
}

GKS_API void ginq_pat_facs(Gint ws_type, Gint *err_ind, Gint *num_pred_inds)
{
    GKS_INQ_ARGS(err_ind, num_pred_inds);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (t)
        *num_pred_inds = t->n_pred_pat;
}

/* Predefined bundle i of a table with n entries: errors bad_ind (index < 1) and
 * not_pred (index > n). */
static int pred_index(Gint ind, int n, int bad_ind, int not_pred)
{
    if (ind < 1)
        return bad_ind;
    return ind > n ? not_pred : 0;
}

#define PRED_INQ(NAME, TYPE, N, TABLE, BAD, NOTPRED)                                     \
    GKS_API void NAME(Gint ws_type, Gint ind, Gint *err_ind, TYPE *rep)                  \
    {                                                                                    \
        GKS_INQ_ARGS(err_ind, rep);                                                      \
        const gks_wdt_output *t = inq_out_type(ws_type, err_ind);                        \
        if (!t)                                                                          \
            return;                                                                      \
        *err_ind = pred_index(ind, t->N, BAD, NOTPRED);                                  \
        if (!*err_ind)                                                                   \
            *rep = t->TABLE[ind - 1];                                                    \
    }
PRED_INQ(ginq_pred_line_rep, Gline_bundle, n_pred_line, pred_line, 60, 62)
PRED_INQ(ginq_pred_marker_rep, Gmarker_bundle, n_pred_marker, pred_marker, 66, 68)
PRED_INQ(ginq_pred_text_rep, Gtext_bundle, n_pred_text, pred_text, 72, 74)
PRED_INQ(ginq_pred_fill_rep, Gfill_bundle, n_pred_fill, pred_fill, 80, 82)
PRED_INQ(ginq_pred_edge_rep, Gedge_bundle, n_pred_edge, pred_edge, 500, 502)

GKS_API void ginq_pred_pat_rep(Gint ws_type, Gint ind, Gstore *store, Gint *err_ind,
                               Gpat_rep **rep)
{
    GKS_INQ_ARGS(err_ind, store, rep);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (!t)
        return;
    *err_ind = pred_index(ind, t->n_pred_pat, 85, 89);
    if (!*err_ind)
        *err_ind = put_pattern(NULL, t->pred_pat[ind - 1].nx, t->pred_pat[ind - 1].ny,
                               t->pred_pat[ind - 1].colr, store, rep);
}

GKS_API void ginq_max_ws_st_tables(Gint ws_type, Gint *err_ind, Gmax_ws_st_tables *l)
{
    GKS_INQ_ARGS(err_ind, l);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    if (!t)
        return;
    int m = t->max_bundles < GKS_WDT_MAX_BUNDLES ? t->max_bundles : GKS_WDT_MAX_BUNDLES;
    const gks_ws_driver *d = gks_driver_for_type(ws_type);
    *l = (Gmax_ws_st_tables){ m, m, m, m, m, d->desc->n_colr, m };
}

GKS_API void ginq_list_avail_gdps(Gint ws_type, Gint cap, Gint start, Gint *err_ind,
                                  Gint_list *gdps, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, gdps, length_list);
    const gks_wdt_output *t = inq_out_type(ws_type, err_ind);
    const Gint *ids = NULL;
    int n = gks_gdp_list(&ids); /* every output workstation draws the core's GDPs */
    if (t)
        *err_ind = gks_list_copy(ids, n, cap, start, gdps, length_list);
}
