/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_record.c -- metafile output: the recording hooks the core calls (gks_mf_record.h) and WRITE
 * ITEM TO GKSM. Each hook writes one item to every active MO workstation (or to the
 * addressed MO); a primitive is preceded by the items of the current attributes,
 * normalization and clipping volume that changed since the MO last wrote them.
 */
#include "gks_mf_record.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_context.h"
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

void gks_mf_recount(void)
{
    gks_context *c = gks_ctx();
    int n = 0;
    for (int i = 0; i < c->sl->n_open; i++)
        if (c->ws[i]->state == GWS_ACTIVE && c->ws[i]->drv->desc->cat == GCAT_MO)
            n++;
    c->sl->mf_n_mo_active = n;
}

char *gks_mf_file_name(const char *conn_id)
{
    size_t n = strlen(conn_id);
    int digits = n > 0;
    for (size_t i = 0; i < n; i++)
        digits &= conn_id[i] >= '0' && conn_id[i] <= '9';
    if (!digits)
        return gks_strdup(conn_id);
    char *s = gks_alloc_array(n + 9, 1);
    if (s)
        snprintf(s, n + 9, "gks%s.gksm", conn_id);
    return s;
}

int gks_mf_file(const gks_ws *ws, char **path)
{
    if (!ws->conn_id || !*ws->conn_id)
        return 21;
    *path = gks_mf_file_name(ws->conn_id);
    return *path ? 0 : 300;
}

static gks_mf_out *mo_of(gks_ws *ws)
{
    return ws && ws->drv->desc->cat == GCAT_MO ? ws->priv : NULL;
}

/* The active MO workstation at open-list position i that still writes (not lost), or NULL. */
static gks_mf_out *active_mo(const gks_context *c, int i)
{
    gks_mf_out *o = c->ws[i]->state == GWS_ACTIVE ? mo_of(c->ws[i]) : NULL;
    return o && !o->lost ? o : NULL;
}

/* The errors of one recorded item, one per MO workstation at most: every MO receives the
 * item whatever happened to the others, and the errors are reported after the loop. */
typedef struct {
    int n;
    int err[GKS_MAX_OPEN_WS];
} mf_errs;

/* Notes the outcome of an item on o: a write failure (303) marks o lost, so that its loss is
 * reported once and nothing more is written to the broken file; 300 and 161 are noted each
 * time (the item was not written, the file itself is intact). */
static void note(mf_errs *e, gks_mf_out *o, int err)
{
    if (!err)
        return;
    if (err == 303)
        o->lost = 1;
    if (e->n < GKS_MAX_OPEN_WS)
        e->err[e->n++] = err;
}

/* Reports the noted errors. Returns 1 if the world is unchanged (gks_error_report), 0 as
 * soon as the handler changed it (the remaining errors are then not reported). */
GKS_MUST_CHECK static int report(const mf_errs *e, int fctid)
{
    for (int i = 0; i < e->n; i++)
        if (!gks_error_report(e->err[i], fctid))
            return 0;
    return 1;
}

/* Writes the record under construction as item `item`; 0, 300 or 303. */
static int put(gks_mf_out *o, int item)
{
    if (o->rec.failed)
        return 300;
    int err = gksm_write_item(o->fp, item, &o->rec);
    gksm_rec_clear(&o->rec);
    return err == 0 ? 0 : err == 161 ? 161 : 303;
}

static int put_nums(gks_mf_out *o, int item, int n, const long *iv, int m, const double *rv)
{
    gksm_rec_clear(&o->rec);
    for (int i = 0; i < n; i++)
        gksm_rec_int(&o->rec, iv[i]);
    for (int i = 0; i < m; i++)
        gksm_rec_real(&o->rec, rv[i]);
    return put(o, item);
}

/* Builds o's record from fmt (gks_mf_record.h) and writes it. */
static int put_fmt(gks_mf_out *o, int item, const char *fmt, va_list ap)
{
    gksm_rec_clear(&o->rec);
    for (const char *f = fmt; *f; f++) {
        switch (*f) {
        case 'i':
            gksm_rec_int(&o->rec, va_arg(ap, int));
            break;
        case 'r':
            gksm_rec_real(&o->rec, va_arg(ap, double));
            break;
        case 'I': {
            int n = va_arg(ap, int);
            const int *v = va_arg(ap, const int *);
            for (int k = 0; k < n; k++)
                gksm_rec_int(&o->rec, v[k]);
            break;
        }
        case 'R': {
            int n = va_arg(ap, int);
            const double *v = va_arg(ap, const double *);
            for (int k = 0; k < n; k++)
                gksm_rec_real(&o->rec, v[k]);
            break;
        }
        default: { /* 's' */
            const char *str = va_arg(ap, const char *);
            gksm_rec_str(&o->rec, str ? str : "", str ? strlen(str) : 0);
            break;
        }
        }
    }
    return put(o, item);
}

int gks_mf_rec(int fctid, int item, const char *fmt, ...)
{
    gks_context *c = gks_ctx();
    mf_errs e = { 0 };
    for (int i = 0; i < c->sl->n_open; i++) {
        gks_mf_out *o = active_mo(c, i);
        if (!o)
            continue;
        va_list ap;
        va_start(ap, fmt);
        note(&e, o, put_fmt(o, item, fmt, ap));
        va_end(ap);
    }
    return report(&e, fctid);
}

int gks_mf_ws_rec(int fctid, int ws_id, int item, const char *fmt, ...)
{
    gks_mf_out *o = mo_of(gks_ws_lookup(ws_id));
    if (!o || o->lost)
        return 1;
    va_list ap;
    va_start(ap, fmt);
    mf_errs e = { 0 };
    note(&e, o, put_fmt(o, item, fmt, ap));
    va_end(ap);
    return report(&e, fctid);
}

int gks_mf_escape(int fctid, gks_ws *ws, int func_id, const Gescape_in_data *in)
{
    gks_mf_out *o = mo_of(ws);
    if (!o)
        return 0;
    if (o->lost)
        return 1;
    int ni = in->num_ints > 0 && in->ints ? in->num_ints : 0;
    int nr = in->num_floats > 0 && in->floats ? in->num_floats : 0;
    gksm_rec_clear(&o->rec);
    gksm_rec_int(&o->rec, func_id);
    gksm_rec_int(&o->rec, ni);
    for (int i = 0; i < ni; i++)
        gksm_rec_int(&o->rec, in->ints[i]);
    gksm_rec_int(&o->rec, nr);
    for (int i = 0; i < nr; i++)
        gksm_rec_real(&o->rec, in->floats[i]);
    gksm_rec_str(&o->rec, in->str ? in->str : "", in->str ? in->str_len : 0);
    mf_errs e = { 0 };
    note(&e, o, put(o, GKSM_ITEM_ESCAPE));
    if (report(&e, fctid)) {
    } /* the caller returns either way: the ESCAPE was for this MO */
    return 1;
}

/* ---------------------------------------------------------------- attribute sync */
/* The current primitive attributes recorded one item per entry: n ints or n reals. */
typedef struct {
    int item;
    size_t off;
    int n;
    char kind; /* 'i' int (or enum), 'r' double */
} attr_field;

#define F(item, field, n, kind) { GKSM_ITEM_##item, offsetof(gks_cur_attrs, field), n, kind }
static const attr_field attr_fields[] = {
    F(LINE_IND, line_ind, 1, 'i'),         F(LINETYPE, linetype, 1, 'i'),
    F(LINEWIDTH, linewidth, 1, 'r'),       F(LINE_COLR, line_colr_ind, 1, 'i'),
    F(MARKER_IND, marker_ind, 1, 'i'),     F(MARKER_TYPE, marker_type, 1, 'i'),
    F(MARKER_SIZE, marker_size, 1, 'r'),   F(MARKER_COLR, marker_colr_ind, 1, 'i'),
    F(TEXT_IND, text_ind, 1, 'i'),         F(TEXT_FONT_PREC, text_font_prec, 2, 'i'),
    F(CHAR_EXPAN, char_expan, 1, 'r'),     F(CHAR_SPACE, char_space, 1, 'r'),
    F(TEXT_COLR, text_colr_ind, 1, 'i'),   F(CHAR_HT, char_ht, 1, 'r'),
    F(CHAR_UP, char_up_vec, 2, 'r'),       F(TEXT_PATH, text_path, 1, 'i'),
    F(TEXT_ALIGN, text_align, 2, 'i'),     F(FILL_IND, fill_ind, 1, 'i'),
    F(INT_STYLE, fill_int_style, 1, 'i'),  F(STYLE_IND, fill_style_ind, 1, 'i'),
    F(FILL_COLR, fill_colr_ind, 1, 'i'),   F(PAT_SIZE, pat_size, 2, 'r'),
    F(PAT_REF_VECS, pat_ref_point, 9, 'r'), F(ASF, asf, GKS_N_ASF, 'i'),
    F(PICK_ID, pick_id, 1, 'i'),           F(EDGE_FLAG, edge_flag, 1, 'i'),
    F(EDGETYPE, edgetype, 1, 'i'),         F(EDGEWIDTH, edgewidth, 1, 'r'),
    F(EDGE_COLR, edge_colr_ind, 1, 'i'),   F(EDGE_IND, edge_ind, 1, 'i'),
    F(VIEW_IND, view_ind, 1, 'i'),         F(HLHSR_ID, hlhsr_id, 1, 'i'),
};
#undef F

/* The layouts the table relies on (ints and enums are int-sized, reals contiguous). */
_Static_assert(sizeof(Gtext_path) == sizeof(int) && sizeof(Gasf) == sizeof(int) &&
                   sizeof(Gtext_align) == 2 * sizeof(int) &&
                   sizeof(Gtext_font_prec) == 2 * sizeof(int),
               "enum fields must be int-sized");
_Static_assert(offsetof(gks_cur_attrs, pat_ref_vec) ==
                   offsetof(gks_cur_attrs, pat_ref_point) + 3 * sizeof(double),
               "pattern reference point and vectors must be contiguous");

static int field_item(gks_mf_out *o, const attr_field *f, const gks_cur_attrs *a)
{
    const char *base = (const char *)a + f->off;
    gksm_rec_clear(&o->rec);
    for (int k = 0; k < f->n; k++) {
        if (f->kind == 'i') {
            int v;
            memcpy(&v, base + (size_t)k * sizeof v, sizeof v);
            gksm_rec_int(&o->rec, v);
        } else {
            double v;
            memcpy(&v, base + (size_t)k * sizeof v, sizeof v);
            gksm_rec_real(&o->rec, v);
        }
    }
    return put(o, f->item);
}

static int props_item(gks_mf_out *o, int side, const Garea_props *p)
{
    const double r[9] = { p->ambient_coef, p->diffuse_coef, p->specular_coef,
                          p->specular_colr.red, p->specular_colr.green, p->specular_colr.blue,
                          p->specular_exp, p->transpar_coef, p->refr_index };
    return put_nums(o, GKSM_ITEM_AREA_PROPS, 1, (const long[]){ side }, 9, r);
}

static int light_state_item(gks_mf_out *o, uint64_t mask)
{
    long on[GKS_MAX_LIGHT_IND + 1];
    int n = 0;
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++)
        if (mask >> i & 1)
            on[1 + n++] = i + 1;
    on[0] = n;
    return put_nums(o, GKSM_ITEM_LIGHT_STATE, n + 1, on, 0, NULL);
}

/* Writes the entries of `a` that differ from what o last wrote (all when not synced). */
static int sync_attrs(gks_mf_out *o, const gks_cur_attrs *a)
{
    int all = !o->synced, err = 0;
    const gks_cur_attrs *l = &o->last;
    for (size_t i = 0; i < sizeof attr_fields / sizeof attr_fields[0] && !err; i++) {
        const attr_field *f = &attr_fields[i];
        size_t sz = (size_t)f->n * (f->kind == 'i' ? sizeof(int) : sizeof(double));
        if (all || memcmp((const char *)a + f->off, (const char *)l + f->off, sz) != 0)
            err = field_item(o, f, a);
    }
    for (int s = 0; s < 2 && !err; s++) {
        if (all || memcmp(&a->area_props[s], &l->area_props[s], sizeof a->area_props[s]))
            err = props_item(o, s, &a->area_props[s]);
        if (!err && (all || a->refl_eq[s] != l->refl_eq[s]))
            err = put_nums(o, GKSM_ITEM_REFL_EQ, 2, (const long[]){ s, a->refl_eq[s] }, 0, NULL);
        if (!err && (all || a->int_shad[s] != l->int_shad[s]))
            err = put_nums(o, GKSM_ITEM_INT_SHAD, 2, (const long[]){ s, a->int_shad[s] }, 0, NULL);
    }
    if (!err && (all || a->light_mask != l->light_mask))
        err = light_state_item(o, a->light_mask);
    return err;
}

static int sync_xform(gks_mf_out *o, const gks_mf_prim *p)
{
    int all = !o->synced, err = 0;
    if (all || memcmp(o->norm, p->norm, sizeof o->norm)) {
        double r[12];
        memcpy(r, p->norm, sizeof r);
        err = put_nums(o, GKSM_ITEM_NORM, 0, NULL, 12, r);
        memcpy(o->norm, p->norm, sizeof o->norm);
    }
    if (!err && (all || o->clip_on != p->clip_on || memcmp(o->box, p->box, sizeof o->box))) {
        err = put_nums(o, GKSM_ITEM_CLIP_VOL3, 1, (const long[]){ p->clip_on }, 6, p->box);
        memcpy(o->box, p->box, sizeof o->box);
        o->clip_on = p->clip_on;
    }
    return err;
}

/* ---------------------------------------------------------------- primitives */
static void src_point(const gks_mf_prim *p, size_t i, double o[3])
{
    if (p->p2) {
        o[0] = p->p2[i].x; o[1] = p->p2[i].y; o[2] = 0.0;
    } else if (p->p3) {
        o[0] = p->p3[i].x; o[1] = p->p3[i].y; o[2] = p->p3[i].z;
    } else {
        o[0] = p->d3[i][0]; o[1] = p->d3[i][1]; o[2] = p->d3[i][2];
    }
}

/* Point i mapped by pn; 1 if finite. */
static int ndc_point(const gks_mf_prim *p, size_t i, double o[3])
{
    double w[3];
    src_point(p, i, w);
    for (int r = 0; r < 3; r++)
        o[r] = p->pn[r][0] * w[0] + p->pn[r][1] * w[1] + p->pn[r][2] * w[2] + p->pn[r][3];
    return isfinite(o[0]) && isfinite(o[1]) && isfinite(o[2]);
}

static void rec_point(gksm_rec *r, const double v[3])
{
    for (int k = 0; k < 3; k++)
        gksm_rec_real(r, v[k]);
}

/* POLYLINE 3: one item per run of finite points (a non-finite point breaks the line, as
 * in the pipeline); POLYMARKER 3: the finite points. */
static int write_points(gks_mf_out *o, const gks_mf_prim *p)
{
    const int line = p->item == GKSM_ITEM_POLYLINE3;
    double v[3];
    size_t i = 0;
    while (i < p->n) {
        size_t s = i, e, k = 0;
        if (line) {
            while (s < p->n && !ndc_point(p, s, v))
                s++;
            for (e = s; e < p->n && ndc_point(p, e, v); e++)
                k++;
        } else {
            for (e = s; e < p->n; e++)
                k += (size_t)ndc_point(p, e, v);
        }
        i = e;
        if (k < (line ? 2u : 1u))
            continue;
        gksm_rec_clear(&o->rec);
        gksm_rec_int(&o->rec, (long)k);
        for (size_t j = s; j < e; j++)
            if (ndc_point(p, j, v))
                rec_point(&o->rec, v);
        int err = put(o, p->item);
        if (err)
            return err;
    }
    return 0;
}

static int write_area(gks_mf_out *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->rec);
    if (p->item == GKSM_ITEM_FILL_AREA_SET3) {
        gksm_rec_int(&o->rec, (long)p->n_loops);
        for (size_t k = 0; k < p->n_loops; k++)
            gksm_rec_int(&o->rec, (long)p->cnt[k]);
    } else {
        gksm_rec_int(&o->rec, (long)p->n);
    }
    for (size_t i = 0; i < p->n; i++) {
        double v[3];
        if (!ndc_point(p, i, v))
            return 0; /* not drawn: not recorded */
        rec_point(&o->rec, v);
    }
    return put(o, p->item);
}

static int write_text(gks_mf_out *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->rec);
    for (size_t i = 0; i < 3; i++) {
        double w[3];
        src_point(p, i, w);
        if (i == 0 && !(isfinite(w[0]) && isfinite(w[1]) && isfinite(w[2])))
            return 0; /* nothing drawn */
        rec_point(&o->rec, w);
    }
    gksm_rec_str(&o->rec, p->str, strlen(p->str));
    return put(o, p->item);
}

static int write_cells(gks_mf_out *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->rec);
    for (size_t i = 0; i < 3; i++) {
        double v[3];
        if (!ndc_point(p, i, v))
            return 0;
        rec_point(&o->rec, v);
    }
    gksm_rec_int(&o->rec, p->nx);
    gksm_rec_int(&o->rec, p->ny);
    size_t n = (size_t)p->nx * (size_t)p->ny;
    for (size_t i = 0; i < n; i++)
        gksm_rec_int(&o->rec, p->colr[i]);
    return put(o, p->item);
}

/* A primitive with data: its packed form (gks_area_data.h), integers then reals. */
static int write_data(gks_mf_out *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->rec);
    for (size_t i = 0; i < p->n_dints; i++)
        gksm_rec_int(&o->rec, p->dints[i]);
    for (size_t i = 0; i < p->n_dreals; i++)
        gksm_rec_real(&o->rec, p->dreals[i]);
    return put(o, p->item);
}

int gks_mf_prim_write(int fctid, const gks_mf_prim *p)
{
    gks_context *c = gks_ctx();
    mf_errs e = { 0 };
    for (int i = 0; i < c->sl->n_open; i++) {
        gks_mf_out *o = active_mo(c, i);
        if (!o)
            continue;
        int err = sync_attrs(o, &c->sl->attrs);
        if (!err)
            err = sync_xform(o, p);
        if (err) {
            o->synced = 0; /* what was written is unknown: write everything next time */
            note(&e, o, err);
            continue;
        }
        o->last = c->sl->attrs;
        o->synced = 1;
        switch (p->item) {
        case GKSM_ITEM_POLYLINE3:
        case GKSM_ITEM_POLYMARKER3:
            err = write_points(o, p);
            break;
        case GKSM_ITEM_FILL_AREA3:
        case GKSM_ITEM_FILL_AREA_SET3:
            err = write_area(o, p);
            break;
        case GKSM_ITEM_TEXT3:
            err = write_text(o, p);
            break;
        case GKSM_ITEM_FILL_AREA3_DATA:
        case GKSM_ITEM_FILL_AREA_SET3_DATA:
        case GKSM_ITEM_TRI_STRIP3_DATA:
        case GKSM_ITEM_QUAD_MESH3_DATA:
        case GKSM_ITEM_SOFAS3_DATA:
            err = write_data(o, p);
            break;
        default:
            err = write_cells(o, p);
            break;
        }
        note(&e, o, err);
    }
    return report(&e, fctid);
}

/* ---------------------------------------------------------------- WRITE ITEM TO GKSM */
GKS_API void gwrite_item(Gint ws_id, Gint type, Gint length, const Gitem_data *item_data)
{
    /* The record's characters (docs/METAFILE.md: records stay character-coded). */
    const char *data = item_data ? item_data->data.impl_dep.data : NULL;
    size_t have = item_data ? item_data->data.impl_dep.size : 0;
    if (gks_check_state(GFN_WITM))
        return;
    if (ws_id < 0)
        GKS_FAIL(20, GFN_WITM);
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        GKS_FAIL(25, GFN_WITM);
    if (ws->state != GWS_ACTIVE)
        GKS_FAIL(30, GFN_WITM);
    gks_mf_out *o = mo_of(ws);
    if (!o)
        GKS_FAIL(32, GFN_WITM);
    if (type < GKSM_ITEM_USER_MIN || type > 999)
        GKS_FAIL(160, GFN_WITM);
    if (length < 0 || (length > 0 && (!data || (size_t)length > have)))
        GKS_FAIL(161, GFN_WITM);
    if (o->lost)
        return; /* the loss was reported once */
    gksm_rec_clear(&o->rec);
    gksm_rec_raw(&o->rec, data, (size_t)length);
    mf_errs e = { 0 };
    note(&e, o, put(o, type));
    if (report(&e, GFN_WITM)) {
    } /* the last action: returning is right either way */
}
