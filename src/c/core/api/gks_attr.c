/* SPDX-License-Identifier: MIT */
/*
 * gks_attr.c -- primitive attributes (ISO 7942 5.4; GKS-3D edge, pattern and HLHSR
 * attributes): the individual setters, the aspect source flags, the workstation
 * representations (SET ... REPRESENTATION, SET COLOUR REPRESENTATION) and the resolution of attributes for one
 * workstation at dispatch (gks_attr.h).
 */
#include "gks_attr.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <string.h>

void gks_attr_init(gks_cur_attrs *a)
{
    a->int_shad[0] = a->int_shad[1] = GSHAD_NONE;
    a->line_ind = a->marker_ind = a->text_ind = a->fill_ind = a->edge_ind = 1;
    a->linetype = 1;
    a->linewidth = 1.0;
    a->line_colr_ind = 1;
    a->marker_type = 3;
    a->marker_size = 1.0;
    a->marker_colr_ind = 1;
    a->text_font_prec = (Gtext_font_prec){ 1, GPREC_STRING };
    a->char_expan = 1.0;
    a->char_space = 0.0;
    a->text_colr_ind = 1;
    a->char_ht = 0.01;
    a->char_up_vec = (Gvec){ 0, 1 };
    a->text_path = GPATH_RIGHT;
    a->text_align = (Gtext_align){ GHOR_NORM, GVERT_NORM };
    a->fill_int_style = GSTYLE_HOLLOW;
    a->fill_style_ind = 1;
    a->fill_colr_ind = 1;
    a->pat_size = (Gvec){ 1, 1 };
    a->pat_ref_point = (Gpoint3){ 0, 0, 0 };
    a->pat_ref_vec[0] = (Gvec3){ 1, 0, 0 };
    a->pat_ref_vec[1] = (Gvec3){ 0, 1, 0 };
    a->edge_flag = GEDGE_OFF;
    a->edgetype = 1;
    a->edgewidth = 1.0;
    a->edge_colr_ind = 1;
    for (int i = 0; i < GKS_N_ASF; i++)
        a->asf[i] = GASF_INDIV;
    a->pick_id = 0;
    a->hlhsr_id = 0;
}

/* ---------------------------------------------------------------- individual setters */
#define ATTRS() (&gks_ctx()->sl->attrs)

/* Body of an integer setter: state check, `bad` -> error `err`, then assignment. */
#define SET_INT(FN, FIELD, BAD, ERR)                                                 \
    do {                                                                             \
        if (gks_check_state(FN))                                                     \
            return;                                                                  \
        if (BAD)                                                                     \
            GKS_FAIL(ERR, FN);                                                       \
        ATTRS()->FIELD = v;                                                          \
    } while (0)

GKS_API void gset_line_ind(Gint v) { SET_INT(GFN_SPLI, line_ind, v < 1, 60); }
GKS_API void gset_linetype(Gint v) { SET_INT(GFN_SLN, linetype, v == 0, 63); }
GKS_API void gset_linewidth(Gfloat v) { SET_INT(GFN_SLWSC, linewidth, !(v >= 0) || !isfinite(v), 65); }
GKS_API void gset_line_colr_ind(Gint v) { SET_INT(GFN_SPLCI, line_colr_ind, v < 0, 92); }
GKS_API void gset_fill_colr_ind(Gint v) { SET_INT(GFN_SFACI, fill_colr_ind, v < 0, 92); }
GKS_API void gset_marker_ind(Gint v) { SET_INT(GFN_SPMI, marker_ind, v < 1, 66); }
GKS_API void gset_marker_type(Gint v) { SET_INT(GFN_SMK, marker_type, v == 0, 69); }
GKS_API void gset_marker_size(Gfloat v) { SET_INT(GFN_SMKSC, marker_size, !(v >= 0) || !isfinite(v), 71); }
GKS_API void gset_marker_colr_ind(Gint v) { SET_INT(GFN_SPMCI, marker_colr_ind, v < 0, 92); }
GKS_API void gset_text_ind(Gint v) { SET_INT(GFN_STXI, text_ind, v < 1, 72); }
GKS_API void gset_char_expan(Gfloat v) { SET_INT(GFN_SCHXP, char_expan, !(v > 0) || !isfinite(v), 77); }
GKS_API void gset_char_space(Gfloat v) { SET_INT(GFN_SCHSP, char_space, !isfinite(v), 308); }
GKS_API void gset_text_colr_ind(Gint v) { SET_INT(GFN_STXCI, text_colr_ind, v < 0, 92); }
GKS_API void gset_char_ht(Gfloat v) { SET_INT(GFN_SCHH, char_ht, !(v > 0) || !isfinite(v), 78); }
GKS_API void gset_text_path(Gtext_path v) { SET_INT(GFN_STXP, text_path, (unsigned)v > GPATH_DOWN, 2000); }
GKS_API void gset_fill_ind(Gint v) { SET_INT(GFN_SFAI, fill_ind, v < 1, 80); }
GKS_API void gset_fill_int_style(Gfill_int_style v) { SET_INT(GFN_SFAIS, fill_int_style, (unsigned)v > GSTYLE_HATCH, 2000); }
GKS_API void gset_fill_style_ind(Gint v) { SET_INT(GFN_SFASI, fill_style_ind, v == 0, 84); }
GKS_API void gset_pick_id(Gint v) { SET_INT(GFN_SPKID, pick_id, v < 0, 97); }
GKS_API void gset_hlhsr_id(Gint v) { SET_INT(GFN_SHRID, hlhsr_id, 0, 0); }
GKS_API void gset_edge_flag(Gedge_flag v) { SET_INT(GFN_SEDFG, edge_flag, (unsigned)v > GEDGE_ON, 2000); }
GKS_API void gset_edgetype(Gint v) { SET_INT(GFN_SEDT, edgetype, v == 0, 63); }
GKS_API void gset_edgewidth(Gfloat v) { SET_INT(GFN_SEWSC, edgewidth, !(v >= 0) || !isfinite(v), 65); }
GKS_API void gset_edge_colr_ind(Gint v) { SET_INT(GFN_SEDCI, edge_colr_ind, v < 0, 92); }
GKS_API void gset_edge_ind(Gint v) { SET_INT(GFN_SEDI, edge_ind, v < 1, 500); }

GKS_API void gset_text_font_prec(const Gtext_font_prec *fp)
{
    if (gks_check_state(GFN_STXFP))
        return;
    if (!fp || fp->font == 0)
        GKS_FAIL(75, GFN_STXFP);
    if ((unsigned)fp->prec > GPREC_STROKE)
        GKS_FAIL(2000, GFN_STXFP);
    ATTRS()->text_font_prec = *fp;
}

GKS_API void gset_char_up_vec(const Gvec *up)
{
    if (gks_check_state(GFN_SCHUP))
        return;
    if (!up || !isfinite(up->delta_x) || !isfinite(up->delta_y) ||
        !(hypot(up->delta_x, up->delta_y) > 0))
        GKS_FAIL(79, GFN_SCHUP);
    ATTRS()->char_up_vec = *up;
}

GKS_API void gset_text_align(const Gtext_align *al)
{
    if (gks_check_state(GFN_STXAL))
        return;
    if (!al || (unsigned)al->hor > GHOR_RIGHT || (unsigned)al->vert > GVERT_BOTTOM)
        GKS_FAIL(2000, GFN_STXAL);
    ATTRS()->text_align = *al;
}

GKS_API void gset_pat_size(Gdouble x_size, Gdouble y_size)
{
    if (gks_check_state(GFN_SPA))
        return;
    if (!(x_size > 0) || !(y_size > 0) || !isfinite(x_size) || !isfinite(y_size))
        GKS_FAIL(87, GFN_SPA);
    ATTRS()->pat_size = (Gvec){ x_size, y_size };
}

GKS_API void gset_pat_ref_point(const Gpoint *p)
{
    if (gks_check_state(GFN_SPARF))
        return;
    if (!p || !isfinite(p->x) || !isfinite(p->y))
        GKS_FAIL(308, GFN_SPARF);
    gks_cur_attrs *a = ATTRS();
    a->pat_ref_point = (Gpoint3){ p->x, p->y, 0 };
    a->pat_ref_vec[0] = (Gvec3){ 1, 0, 0 };
    a->pat_ref_vec[1] = (Gvec3){ 0, 1, 0 };
}

GKS_API void gset_pat_ref_point_vecs(const Gpoint3 *p, const Gvec3 vecs[2])
{
    if (gks_check_state(GFN_SPRPV))
        return;
    if (!p || !vecs || !isfinite(p->x) || !isfinite(p->y) || !isfinite(p->z))
        GKS_FAIL(308, GFN_SPRPV);
    double d0[3] = { vecs[0].delta_x, vecs[0].delta_y, vecs[0].delta_z };
    double d1[3] = { vecs[1].delta_x, vecs[1].delta_y, vecs[1].delta_z };
    gks_text_frame f;
    if (gks_text_frame3((const double[3]){ 0, 0, 0 }, d0, d1, &f))
        GKS_FAIL(2000, GFN_SPRPV); /* zero, non-finite or parallel vectors */
    gks_cur_attrs *a = ATTRS();
    a->pat_ref_point = *p;
    a->pat_ref_vec[0] = vecs[0];
    a->pat_ref_vec[1] = vecs[1];
}

static int asf_valid(const Gasf *f, int n)
{
    for (int i = 0; i < n; i++)
        if ((unsigned)f[i] > GASF_INDIV)
            return 0;
    return 1;
}

static void asfs_to_array(const Gasfs *s, Gasf *f)
{
    const Gasf v[13] = { s->linetype, s->linewidth, s->line_colr_ind, s->marker_type,
                         s->marker_size, s->marker_colr_ind, s->text_font_prec,
                         s->char_expan, s->char_space, s->text_colr_ind,
                         s->fill_int_style, s->fill_style_ind, s->fill_colr_ind };
    memcpy(f, v, sizeof v);
}

GKS_API void gset_asfs(const Gasfs *asfs)
{
    if (gks_check_state(GFN_SASF))
        return;
    Gasf f[13];
    if (!asfs)
        GKS_FAIL(2000, GFN_SASF);
    asfs_to_array(asfs, f);
    if (!asf_valid(f, 13))
        GKS_FAIL(2000, GFN_SASF);
    memcpy(ATTRS()->asf, f, sizeof f);
}

GKS_API void gset_asfs3(const Gasfs3 *asfs)
{
    if (gks_check_state(GFN_ASF3))
        return;
    Gasf f[GKS_N_ASF];
    if (!asfs)
        GKS_FAIL(2000, GFN_ASF3);
    asfs_to_array(&asfs->asfs, f);
    f[GKS_ASF_EDGE_FLAG] = asfs->edge_flag;
    f[GKS_ASF_EDGETYPE] = asfs->edgetype;
    f[GKS_ASF_EDGEWIDTH] = asfs->edgewidth;
    f[GKS_ASF_EDGE_COLR] = asfs->edge_colr_ind;
    if (!asf_valid(f, GKS_N_ASF))
        GKS_FAIL(2000, GFN_ASF3);
    memcpy(ATTRS()->asf, f, sizeof f);
}

/* ---------------------------------------------------------------- representations */
const gks_wdt_output *gks_attr_wdt(const gks_ws *ws)
{
    const gks_wdt_output *t = ws->drv->desc->out;
    return t ? t : &gks_wdt_raster;
}

/* Common checks of SET ... REPRESENTATION: state, workstation (20, 25, 33, 35, 36). */
static gks_ws *rep_ws(int fct, Gint ws_id)
{
    if (gks_check_state(fct))
        return NULL;
    return gks_ws_checked(fct, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
}

static int bad_index(const gks_ws *ws, int ind)
{
    int max = gks_attr_wdt(ws)->max_bundles;
    return ind < 1 || ind > max || ind > GKS_WDT_MAX_BUNDLES;
}

GKS_API void gset_line_rep(Gint ws_id, Gint ind, const Gline_bundle *rep)
{
    gks_ws *ws = rep_ws(GFN_SPLR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(60, GFN_SPLR);
    if (!rep || rep->type == 0)
        GKS_FAIL(63, GFN_SPLR);
    if (!gks_wdt_has(t->line.types, t->line.n_types, rep->type))
        GKS_FAIL(64, GFN_SPLR);
    if (!(rep->width >= 0) || !isfinite(rep->width))
        GKS_FAIL(65, GFN_SPLR);
    if (rep->colr_ind < 0)
        GKS_FAIL(93, GFN_SPLR);
    ws->line_rep[ind] = *rep;
    ws->line_def[ind] = 1;
    GKS_MF_WS(SPLR, ws_id, ind, rep->type, rep->width, rep->colr_ind);
}

GKS_API void gset_marker_rep(Gint ws_id, Gint ind, const Gmarker_bundle *rep)
{
    gks_ws *ws = rep_ws(GFN_SPMR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(66, GFN_SPMR);
    if (!rep || rep->type == 0)
        GKS_FAIL(69, GFN_SPMR);
    if (!gks_wdt_has(t->marker.types, t->marker.n_types, rep->type))
        GKS_FAIL(70, GFN_SPMR);
    if (!(rep->size >= 0) || !isfinite(rep->size))
        GKS_FAIL(71, GFN_SPMR);
    if (rep->colr_ind < 0)
        GKS_FAIL(93, GFN_SPMR);
    ws->marker_rep[ind] = *rep;
    ws->marker_def[ind] = 1;
    GKS_MF_WS(SPMR, ws_id, ind, rep->type, rep->size, rep->colr_ind);
}

GKS_API void gset_text_rep(Gint ws_id, Gint ind, const Gtext_bundle *rep)
{
    gks_ws *ws = rep_ws(GFN_STXR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(72, GFN_STXR);
    if (!rep || rep->text_font_prec.font == 0)
        GKS_FAIL(75, GFN_STXR);
    if ((unsigned)rep->text_font_prec.prec > GPREC_STROKE ||
        !gks_wdt_has_font(t, rep->text_font_prec.font, (int)rep->text_font_prec.prec))
        GKS_FAIL(76, GFN_STXR);
    if (!(rep->char_expan > 0) || !isfinite(rep->char_expan))
        GKS_FAIL(77, GFN_STXR);
    if (!isfinite(rep->char_space))
        GKS_FAIL(308, GFN_STXR);
    if (rep->colr_ind < 0)
        GKS_FAIL(93, GFN_STXR);
    ws->text_rep[ind] = *rep;
    ws->text_def[ind] = 1;
    GKS_MF_WS(STXR, ws_id, ind, rep->text_font_prec.font, rep->text_font_prec.prec,
              rep->char_expan, rep->char_space, rep->colr_ind);
}

GKS_API void gset_fill_rep(Gint ws_id, Gint ind, const Gfill_bundle *rep)
{
    gks_ws *ws = rep_ws(GFN_SFAR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(80, GFN_SFAR);
    if (!rep || !gks_wdt_has(t->int_styles, t->n_int_styles, (int)rep->int_style))
        GKS_FAIL(83, GFN_SFAR);
    int pat_or_hatch = rep->int_style == GSTYLE_PAT || rep->int_style == GSTYLE_HATCH;
    if (pat_or_hatch && rep->style_ind == 0)
        GKS_FAIL(84, GFN_SFAR);
    if (rep->int_style == GSTYLE_PAT && rep->style_ind < 0)
        GKS_FAIL(85, GFN_SFAR);
    if (rep->int_style == GSTYLE_HATCH &&
        !gks_wdt_has(t->hatch_styles, t->n_hatch_styles, rep->style_ind))
        GKS_FAIL(86, GFN_SFAR);
    if (rep->colr_ind < 0)
        GKS_FAIL(93, GFN_SFAR);
    ws->fill_rep[ind] = *rep;
    ws->fill_def[ind] = 1;
    GKS_MF_WS(SFAR, ws_id, ind, rep->int_style, rep->style_ind, rep->colr_ind);
}

GKS_API void gset_pat_rep(Gint ws_id, Gint ind, const Gpat_rep *rep)
{
    gks_ws *ws = rep_ws(GFN_SPAR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(85, GFN_SPAR);
    if (!gks_wdt_has(t->int_styles, t->n_int_styles, GSTYLE_PAT))
        GKS_FAIL(90, GFN_SPAR);
    if (!rep || !rep->colr_array || rep->dims.size_x < 1 || rep->dims.size_y < 1)
        GKS_FAIL(91, GFN_SPAR);
    size_t n = (size_t)rep->dims.size_x * (size_t)rep->dims.size_y;
    for (size_t i = 0; i < n; i++)
        if (rep->colr_array[i] < 0)
            GKS_FAIL(93, GFN_SPAR);
    int *c = gks_alloc_array(n, sizeof *c);
    if (!c)
        GKS_FAIL(300, GFN_SPAR);
    memcpy(c, rep->colr_array, n * sizeof *c);
    gks_free(ws->pat_rep[ind].colr);
    ws->pat_rep[ind].colr = c;
    ws->pat_rep[ind].nx = rep->dims.size_x;
    ws->pat_rep[ind].ny = rep->dims.size_y;
    ws->pat_def[ind] = 1;
    GKS_MF_WS(SPAR, ws_id, ind, rep->dims.size_x, rep->dims.size_y, (int)n, rep->colr_array);
}

GKS_API void gset_edge_rep(Gint ws_id, Gint ind, const Gedge_bundle *rep)
{
    gks_ws *ws = rep_ws(GFN_SEDR, ws_id);
    if (!ws)
        return;
    const gks_wdt_output *t = gks_attr_wdt(ws);
    if (bad_index(ws, ind))
        GKS_FAIL(500, GFN_SEDR);
    if (!rep || (unsigned)rep->flag > GEDGE_ON)
        GKS_FAIL(2000, GFN_SEDR);
    if (rep->type == 0)
        GKS_FAIL(63, GFN_SEDR);
    if (!gks_wdt_has(t->edge.types, t->edge.n_types, rep->type))
        GKS_FAIL(64, GFN_SEDR);
    if (!(rep->width >= 0) || !isfinite(rep->width))
        GKS_FAIL(65, GFN_SEDR);
    if (rep->colr_ind < 0)
        GKS_FAIL(93, GFN_SEDR);
    ws->edge_rep[ind] = *rep;
    ws->edge_def[ind] = 1;
    GKS_MF_WS(SEDR, ws_id, ind, rep->flag, rep->type, rep->width, rep->colr_ind);
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
    GKS_MF_WS(SCR, ws_id, colr_ind, c->red, c->green, c->blue);
}

/* ---------------------------------------------------------------- resolution */
int gks_attr_colr_ind(const gks_ws *ws, int ind)
{
    int n = ws->drv->desc->n_colr;
    /* ISO 7942: a colour index not present in the table is drawn with index 1. */
    if (ind < 0 || ind >= n || !ws->colr_defined[ind])
        ind = 1 < n ? 1 : 0;
    return ind;
}

Grgb gks_attr_colour(const gks_ws *ws, int ind)
{
    return ws->colr[gks_attr_colr_ind(ws, ind)];
}

/* A scale factor realized: nominal * s clamped to [min, max], back to a factor. */
static double clamp_scale(double s, const gks_wdt_sizes *z)
{
    if (!(z->nom > 0))
        return s;
    double w = s * z->nom;
    if (!(w >= z->min))
        w = z->min;
    if (w > z->max)
        w = z->max;
    return w / z->nom;
}

void gks_attr_realize_line(const gks_ws *ws, const Gline_bundle *in, Gline_bundle *out)
{
    const gks_wdt_output *t = gks_attr_wdt(ws);
    out->type = gks_wdt_has(t->line.types, t->line.n_types, in->type) ? in->type : 1;
    out->width = clamp_scale(in->width, &t->line);
    out->colr_ind = gks_attr_colr_ind(ws, in->colr_ind);
}

void gks_attr_realize_marker(const gks_ws *ws, const Gmarker_bundle *in, Gmarker_bundle *out)
{
    const gks_wdt_output *t = gks_attr_wdt(ws);
    out->type = gks_wdt_has(t->marker.types, t->marker.n_types, in->type) ? in->type : 3;
    out->size = clamp_scale(in->size, &t->marker);
    out->colr_ind = gks_attr_colr_ind(ws, in->colr_ind);
}

void gks_attr_realize_text(const gks_ws *ws, const Gtext_bundle *in, Gtext_bundle *out)
{
    const gks_wdt_output *t = gks_attr_wdt(ws);
    *out = *in;
    if (!gks_wdt_has_font(t, in->text_font_prec.font, (int)in->text_font_prec.prec))
        out->text_font_prec.font = 1;
    /* STRING and CHAR precision are drawn as STROKE (a higher precision is allowed). */
    out->text_font_prec.prec = GPREC_STROKE;
    if (out->char_expan < t->min_char_expan)
        out->char_expan = t->min_char_expan;
    if (out->char_expan > t->max_char_expan)
        out->char_expan = t->max_char_expan;
    out->colr_ind = gks_attr_colr_ind(ws, in->colr_ind);
}

void gks_attr_realize_fill(const gks_ws *ws, const Gfill_bundle *in, Gfill_bundle *out)
{
    const gks_wdt_output *t = gks_attr_wdt(ws);
    *out = *in;
    if (!gks_wdt_has(t->int_styles, t->n_int_styles, (int)in->int_style))
        out->int_style = GSTYLE_HOLLOW;
    if (out->int_style == GSTYLE_HATCH &&
        !gks_wdt_has(t->hatch_styles, t->n_hatch_styles, out->style_ind))
        out->style_ind = t->n_hatch_styles > 0 ? t->hatch_styles[0] : -1;
    if (out->int_style == GSTYLE_PAT &&
        (out->style_ind < 1 || out->style_ind > GKS_WDT_MAX_BUNDLES ||
         !ws->pat_def[out->style_ind]))
        out->style_ind = 1;
    if (out->int_style == GSTYLE_PAT && !ws->pat_def[1])
        out->int_style = GSTYLE_SOLID;
    out->colr_ind = gks_attr_colr_ind(ws, in->colr_ind);
}

void gks_attr_realize_edge(const gks_ws *ws, const Gedge_bundle *in, Gedge_bundle *out)
{
    const gks_wdt_output *t = gks_attr_wdt(ws);
    out->flag = in->flag == GEDGE_ON ? GEDGE_ON : GEDGE_OFF;
    out->type = gks_wdt_has(t->edge.types, t->edge.n_types, in->type) ? in->type : 1;
    out->width = clamp_scale(in->width, &t->edge);
    out->colr_ind = gks_attr_colr_ind(ws, in->colr_ind);
}

/* The bundle index to use: ind if defined on ws, else 1 (ISO 7942 4.4.4). */
static int bundle_ind(const unsigned char *def, int ind)
{
    return ind >= 1 && ind <= GKS_WDT_MAX_BUNDLES && def[ind] ? ind : 1;
}

#define PICK(ASF, INDIV, BUNDLED) (a->asf[ASF] == GASF_INDIV ? (INDIV) : (BUNDLED))

void gks_attr_line(const gks_ws *ws, const gks_cur_attrs *a, Gline_bundle *out)
{
    const Gline_bundle *b = &ws->line_rep[bundle_ind(ws->line_def, a->line_ind)];
    Gline_bundle s = { PICK(GKS_ASF_LINETYPE, a->linetype, b->type),
                       PICK(GKS_ASF_LINEWIDTH, a->linewidth, b->width),
                       PICK(GKS_ASF_LINE_COLR, a->line_colr_ind, b->colr_ind) };
    gks_attr_realize_line(ws, &s, out);
}

void gks_attr_marker(const gks_ws *ws, const gks_cur_attrs *a, Gmarker_bundle *out)
{
    const Gmarker_bundle *b = &ws->marker_rep[bundle_ind(ws->marker_def, a->marker_ind)];
    Gmarker_bundle s = { PICK(GKS_ASF_MARKER_TYPE, a->marker_type, b->type),
                         PICK(GKS_ASF_MARKER_SIZE, a->marker_size, b->size),
                         PICK(GKS_ASF_MARKER_COLR, a->marker_colr_ind, b->colr_ind) };
    gks_attr_realize_marker(ws, &s, out);
}

void gks_attr_text(const gks_ws *ws, const gks_cur_attrs *a, Gtext_bundle *out)
{
    const Gtext_bundle *b = &ws->text_rep[bundle_ind(ws->text_def, a->text_ind)];
    Gtext_bundle s = { PICK(GKS_ASF_TEXT_FONT_PREC, a->text_font_prec, b->text_font_prec),
                       PICK(GKS_ASF_CHAR_EXPAN, a->char_expan, b->char_expan),
                       PICK(GKS_ASF_CHAR_SPACE, a->char_space, b->char_space),
                       PICK(GKS_ASF_TEXT_COLR, a->text_colr_ind, b->colr_ind) };
    gks_attr_realize_text(ws, &s, out);
}

void gks_attr_fill(const gks_ws *ws, const gks_cur_attrs *a, Gfill_bundle *out)
{
    const Gfill_bundle *b = &ws->fill_rep[bundle_ind(ws->fill_def, a->fill_ind)];
    Gfill_bundle s = { PICK(GKS_ASF_FILL_INT_STYLE, a->fill_int_style, b->int_style),
                       PICK(GKS_ASF_FILL_STYLE_IND, a->fill_style_ind, b->style_ind),
                       PICK(GKS_ASF_FILL_COLR, a->fill_colr_ind, b->colr_ind) };
    gks_attr_realize_fill(ws, &s, out);
}

void gks_attr_edge(const gks_ws *ws, const gks_cur_attrs *a, Gedge_bundle *out)
{
    const Gedge_bundle *b = &ws->edge_rep[bundle_ind(ws->edge_def, a->edge_ind)];
    Gedge_bundle s = { PICK(GKS_ASF_EDGE_FLAG, a->edge_flag, b->flag),
                       PICK(GKS_ASF_EDGETYPE, a->edgetype, b->type),
                       PICK(GKS_ASF_EDGEWIDTH, a->edgewidth, b->width),
                       PICK(GKS_ASF_EDGE_COLR, a->edge_colr_ind, b->colr_ind) };
    gks_attr_realize_edge(ws, &s, out);
}

void gks_attr_text_layout(const gks_ws *ws, const gks_cur_attrs *a, gks_text_attrs *out,
                          Grgb *colour)
{
    Gtext_bundle tb;
    gks_attr_text(ws, a, &tb);
    out->font = tb.text_font_prec.font;
    out->prec = tb.text_font_prec.prec;
    out->char_expan = tb.char_expan;
    out->char_space = tb.char_space;
    out->char_ht = a->char_ht;
    out->up[0] = a->char_up_vec.delta_x;
    out->up[1] = a->char_up_vec.delta_y;
    out->path = a->text_path;
    out->align = a->text_align;
    if (colour)
        *colour = ws->colr[tb.colr_ind];
}

static void common(const gks_cur_attrs *a, gks_prim *p)
{
    p->attrs.hlhsr_id = a->hlhsr_id;
    p->attrs.pick_id = a->pick_id;
}

void gks_attr_prim_line(const gks_ws *ws, const gks_cur_attrs *a, gks_prim *p)
{
    Gline_bundle b;
    gks_attr_line(ws, a, &b);
    p->attrs.linetype = b.type;
    p->attrs.linewidth = b.width;
    p->colour = ws->colr[b.colr_ind];
    common(a, p);
}

void gks_attr_prim_marker(const gks_ws *ws, const gks_cur_attrs *a, gks_prim *p)
{
    Gmarker_bundle b;
    gks_attr_marker(ws, a, &b);
    p->attrs.marker_type = b.type;
    p->attrs.marker_size = b.size;
    p->colour = ws->colr[b.colr_ind];
    common(a, p);
}

static double vlen3(const Gvec3 *v)
{
    return sqrt(v->delta_x * v->delta_x + v->delta_y * v->delta_y + v->delta_z * v->delta_z);
}

/* Pattern reference point and box vectors WC3 -> NDC3 by the current normalization. */
static void pattern_box(const gks_cur_attrs *a, const double m[3][4], gks_prim *p)
{
    const double r[3] = { a->pat_ref_point.x, a->pat_ref_point.y, a->pat_ref_point.z };
    double o[3];
    gks_xform_mat34_point(m, r, o);
    p->attrs.pat_ref = (Gpoint3){ o[0], o[1], o[2] };
    const double size[2] = { a->pat_size.delta_x, a->pat_size.delta_y };
    Gvec3 *dst[2] = { &p->attrs.pat_width, &p->attrs.pat_height };
    for (int k = 0; k < 2; k++) {
        const Gvec3 *v = &a->pat_ref_vec[k];
        double l = vlen3(v), s = l > 0 ? size[k] / l : 0;
        double d[3] = { v->delta_x * s, v->delta_y * s, v->delta_z * s }, t[3];
        for (int i = 0; i < 3; i++)
            t[i] = m[i][0] * d[0] + m[i][1] * d[1] + m[i][2] * d[2];
        *dst[k] = (Gvec3){ t[0], t[1], t[2] };
    }
}

int gks_attr_prim_fill(const gks_ws *ws, const gks_cur_attrs *a, const double m[3][4],
                       gks_prim *p, Grgb **pattern)
{
    Gfill_bundle f;
    Gedge_bundle e;
    gks_attr_fill(ws, a, &f);
    gks_attr_edge(ws, a, &e);
    *pattern = NULL;
    p->attrs.int_style = f.int_style;
    p->attrs.style_ind = f.style_ind;
    p->colour = ws->colr[f.colr_ind];
    p->attrs.pattern = NULL;
    p->attrs.pat_nx = p->attrs.pat_ny = 0;
    if (f.int_style == GSTYLE_PAT) {
        const int nx = ws->pat_rep[f.style_ind].nx, ny = ws->pat_rep[f.style_ind].ny;
        Grgb *c = gks_alloc_array((size_t)nx * (size_t)ny, sizeof *c);
        if (!c)
            return 300;
        for (size_t i = 0; i < (size_t)nx * (size_t)ny; i++)
            c[i] = gks_attr_colour(ws, ws->pat_rep[f.style_ind].colr[i]);
        p->attrs.pattern = c;
        p->attrs.pat_nx = nx;
        p->attrs.pat_ny = ny;
        *pattern = c;
    }
    pattern_box(a, m, p);
    p->attrs.edge_flag = e.flag == GEDGE_ON;
    p->attrs.edgetype = e.type;
    p->attrs.edgewidth = e.width;
    p->attrs.edge_colour = ws->colr[e.colr_ind];
    common(a, p);
    return 0;
}
