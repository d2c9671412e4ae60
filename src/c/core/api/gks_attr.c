/* SPDX-License-Identifier: MIT */
/*
 * gks_attr.c -- primitive attributes (ISO 7942 5.4; GKS-3D edge, pattern and HLHSR
 * attributes): the individual setters, the aspect source flags, the workstation
 * representations (SET ... REPRESENTATION, SET COLOUR REPRESENTATION). Their
 * resolution for one workstation at dispatch is core/pipe/gks_attr_resolve.c.
 */
#include "gks_binding.h"
#include "gks_legacy.h"
#include "gks_attr_resolve.h"
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
#define ATTRS() gks_attrs_w()

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
GKS_API void gset_fill_int_style(Gfill_int_style v)
{
    const gks_profile *prof = gks_legacy_profile(); /* a foreign GKS's styles */
    if (prof && prof->fill_int_style)
        v = (Gfill_int_style)prof->fill_int_style((Gint)v);
    SET_INT(GFN_SFAIS, fill_int_style, (unsigned)v > GSTYLE_HATCH, 2000);
}
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
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
    gks_ws_tables_changed();
    GKS_MF_WS(SCR, ws_id, colr_ind, c->red, c->green, c->blue);
    /* Colour 0 set before the first output of a frame is that frame's background (a
     * driver may have cleared its picture already, e.g. when the workstation viewport
     * was set); after output it takes effect at the next clear, like the standard's
     * deferred dynamic change of the background. */
    if (colr_ind == 0 && ws->disp_empty == GDISP_EMPTY && ws->drv->background) {
        int err = ws->drv->background(ws);
        if (err)
            GKS_FAIL(err, GFN_SCR);
    }
}
