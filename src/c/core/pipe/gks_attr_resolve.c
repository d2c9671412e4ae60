/* SPDX-License-Identifier: MIT */
/*
 * gks_attr_resolve.c -- the attribute stage of the output pipeline: the current
 * attributes resolved for one workstation (gks_attr_resolve.h).
 */
#include "gks_attr_resolve.h"
#include "gks_alloc.h"
#include "gks_pipe_dispatch.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <assert.h>
#include <math.h>
#include <string.h>

const gks_wdt_output *gks_attr_wdt(const gks_ws *ws)
{
    const gks_wdt_output *t = ws->drv->desc->out;
    return t ? t : &gks_wdt_raster;
}

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
    /* The precision asked for, when its font is available (else STROKE with font 1): the
     * strokes are the same in every precision, and a driver that draws text itself may
     * honour STRING and CHAR (the vector workstations write them in a real font); the
     * realized representation says STROKE, the precision every workstation can give. */
    const Gtext_bundle *b = &ws->text_rep[bundle_ind(ws->text_def, a->text_ind)];
    const Gtext_font_prec req = PICK(GKS_ASF_TEXT_FONT_PREC, a->text_font_prec, b->text_font_prec);
    out->prec = req.font == tb.text_font_prec.font ? req.prec : GPREC_STROKE;
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
        pattern_box(a, m, p); /* only a pattern has a box (ws_driver.h) */
    }
    p->attrs.edge_flag = e.flag == GEDGE_ON;
    p->attrs.edgetype = e.type;
    p->attrs.edgewidth = e.width;
    p->attrs.edge_colour = ws->colr[e.colr_ind];
    common(a, p);
    return 0;
}

gks_prim *gks_attr_area_make(const gks_ws *ws, const gks_cur_attrs *a, const double m[3][4],
                             int edges, gks_prim *buf, Grgb **pattern, int *err)
{
    gks_context *c = gks_ctx();
    gks_area_memo *e = &c->sl->area_memo[(unsigned)ws->id % GKS_MAX_OPEN_WS];
    /* The state list's block is written only through gks_attrs_w, which bumps attrs_gen:
     * the same generation is the same bytes. Other blocks (a segment's bound attributes)
     * and a changed generation are compared bytewise. */
    const uint64_t gen = a == &c->sl->attrs ? c->sl->attrs_gen : 0;
    *pattern = NULL;
    *err = 0;
    if (e->ws == ws && e->tables_gen == c->tables_gen &&
        ((gen && e->attrs_gen == gen) || memcmp(&e->a, a, sizeof *a) == 0)) {
        assert(memcmp(&e->a, a, sizeof *a) == 0); /* a write past gks_attrs_w */
        e->attrs_gen = gen;
        return gks_attr_area_kept(e, edges);
    }
    *buf = (gks_prim){ .kind = GKS_PRIM_FILL_AREA, .n_loops = 1 };
    gks_pipe_prim_common(buf, a);
    *err = gks_attr_prim_fill(ws, a, m, buf, pattern);
    const int flag = buf->attrs.edge_flag;
    if (!edges)
        buf->attrs.edge_flag = 0;
    if (*err || *pattern) {
        e->ws = NULL;
        return buf; /* attr_gen 0: not kept */
    }
    e->ws = ws;
    e->tables_gen = c->tables_gen;
    e->attrs_gen = gen;
    memcpy(&e->a, a, sizeof *a); /* with its padding: compared bytewise */
    e->edge_flag = flag;
    /* a new number for the set with edges (as resolved) and the next for it without */
    c->prim_attr_gen += 2;
    e->attr_gen = c->prim_attr_gen - 1;
    buf->attr_gen = e->attr_gen + (uint64_t)(flag && !edges);
    e->p = *buf;
    return &e->p;
}
