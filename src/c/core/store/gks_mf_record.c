/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_record.c -- metafile output: the recording hooks the core calls (gks_mf_record.h).
 * Each hook encodes one item, as the item table (gks_mf_items.def) describes it, and hands
 * it to every active MO workstation's driver (or to the addressed MO) through its
 * record_item entry; a primitive is preceded by the items of the current attributes,
 * normalization and clipping volume that changed since the MO last wrote them.
 */
#include "gks_mf_record.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_context.h"
#include <math.h>
#include <stddef.h>
#include <string.h>

/* The workstations the hooks look at: the open ones, then GKS3D_RECORD's recorder
 * (gks_record.h; gks_record_mirror in gks_context.h), which is in no list of the program's. */
static int n_targets(const gks_context *c)
{
    return c->sl->n_open + (c->rec_ws != NULL);
}
static gks_ws *target(const gks_context *c, int i)
{
    return i < c->sl->n_open ? c->ws[i] : c->rec_ws;
}

void gks_mf_recount(void)
{
    gks_context *c = gks_ctx();
    int n = 0;
    for (int i = 0; i < n_targets(c); i++)
        if (target(c, i)->state == GWS_ACTIVE && gks_mf_is_mo(target(c, i)))
            n++;
    c->sl->mf_n_mo_active = n;
}

/* The format of every item that has one, from the item table. */
static const char *const item_fmts[GKSM_ITEM_USER_MIN] = {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) [type] = GKSM_FMT_STR fmt,
#define GKSM_ALSO(key, name, kind, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
};

const char *gksm_item_fmt(int type)
{
    return type >= 0 && type < GKSM_ITEM_USER_MIN ? item_fmts[type] : NULL;
}

gks_mf_ws *gks_mf_ws_state(gks_ws *ws)
{
    if (!ws->mf) {
        gks_mf_ws *m = gks_calloc_array(1, sizeof *m);
        if (!m)
            return NULL;
        gksm_rec_init(&m->rec);
        ws->mf = m;
    }
    return ws->mf;
}

void gks_mf_ws_free(gks_ws *ws)
{
    if (ws->mf && gks_mf_is_mo(ws))
        gksm_rec_free(&((gks_mf_ws *)ws->mf)->rec);
    gks_free(ws->mf);
    ws->mf = NULL;
}

/* An MO workstation being written to: its driver takes the items, m is what the core
 * keeps for it. */
typedef struct {
    gks_ws *ws;
    gks_mf_ws *m;
} mo_t;

/* ws as an MO being written to; 300 if its state cannot be made, -1 if not an MO. */
static int mo_of(gks_ws *ws, mo_t *o)
{
    if (!gks_mf_is_mo(ws))
        return -1;
    o->ws = ws;
    o->m = gks_mf_ws_state(ws);
    return o->m ? 0 : 300;
}

/* The errors of one recorded item, one per MO workstation at most: every MO receives the
 * item whatever happened to the others, and the errors are reported after the loop. A
 * write failure (303) is the driver's to report once (it then writes and returns nothing
 * more); 300 and 161 are noted each time (the item was not written, the file is intact). */
typedef struct {
    int n;
    int err[GKS_MAX_OPEN_WS];
} mf_errs;

static void note(mf_errs *e, int err)
{
    if (err && e->n < GKS_MAX_OPEN_WS)
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

/* Hands the record under construction to the MO's driver as item `item`; 0, 161, 300 or 303. */
static int put(const mo_t *o, int item)
{
    gksm_rec *r = &o->m->rec;
    int err = r->failed ? 300 : o->ws->drv->record_item(o->ws, item, r->buf, r->len);
    gksm_rec_clear(r);
    return err == 0 || err == 161 || err == 300 ? err : 303;
}

static int put_nums(const mo_t *o, int item, int n, const long *iv, int m, const double *rv)
{
    gksm_rec *r = &o->m->rec;
    gksm_rec_clear(r);
    for (int i = 0; i < n; i++)
        gksm_rec_int(r, iv[i]);
    for (int i = 0; i < m; i++)
        gksm_rec_real(r, rv[i]);
    return put(o, item);
}

/* Builds o's record of item `item` from its format fmt (gks_mf_items.def), the value of
 * each group in a[], and writes it. */
static int put_args(const mo_t *o, int item, const char *fmt, const gksm_arg *a)
{
    gksm_rec *r = &o->m->rec;
    gksm_rec_clear(r);
    int n, arr;
    char k;
    for (const char *f = fmt; (f = gksm_fmt_next(f, &n, &k, &arr)); a++) {
        if (k == 'I') {
            for (long j = 0; j < a->i; j++)
                gksm_rec_int(r, a->iv[j]);
        } else if (k == 's') {
            gksm_rec_str(r, a->s ? a->s : "", a->s ? strlen(a->s) : 0);
        } else if (arr && k == 'i') {
            for (int j = 0; j < n; j++)
                gksm_rec_int(r, a->iv[j]);
        } else if (arr) {
            for (int j = 0; j < n; j++)
                gksm_rec_real(r, a->rv[j]);
        } else if (k == 'i') {
            gksm_rec_int(r, a->i);
        } else {
            gksm_rec_real(r, a->r);
        }
    }
    return put(o, item);
}

/* The item to ws if it is an MO: -1 if not, else 0 or its error (300 for its state). */
static int put_args_to(gks_ws *ws, int item, const char *fmt, const gksm_arg *a)
{
    mo_t o;
    int err = mo_of(ws, &o);
    return err ? err : put_args(&o, item, fmt, a);
}

/* A REC_ALL item to every active MO workstation; what report returned. */
static int rec_all(int fctid, int item, const char *fmt, const gksm_arg *a)
{
    gks_context *c = gks_ctx();
    mf_errs e = { 0 };
    for (int i = 0; i < n_targets(c); i++) {
        if (target(c, i)->state != GWS_ACTIVE)
            continue;
        int err = put_args_to(target(c, i), item, fmt, a);
        if (err >= 0)
            note(&e, err);
    }
    return report(&e, fctid);
}

/* A REC_WS item to the workstation ws_id if it is an MO, and to the recorder when it
 * mirrors that one; what report returned. */
static int rec_ws(int fctid, int ws_id, int item, const char *fmt, const gksm_arg *a)
{
    gks_ws *to[2] = { gks_ws_lookup(ws_id), gks_record_mirror(ws_id) };
    mf_errs e = { 0 };
    for (int k = 0; k < 2; k++) {
        int err = put_args_to(to[k], item, fmt, a);
        if (err < 0)
            continue;
        if (!err && k == 1 && item == GKSM_ITEM_CLEAR)
            gks_ctx()->rec_drawn = 0; /* the recorded frame ended */
        note(&e, err);
    }
    return report(&e, fctid);
}

/* The typed hooks of the REC_ALL and REC_WS rows (gks_mf_record.h): each packs its
 * arguments, one gksm_arg per group of its format (and one unused, so that no array is
 * empty), for rec_all or rec_ws. */
#define GKSM_HOOK_REC_ALL(name, key, fmt)                                                  \
    int gks_mf_rec_##key(int fctid GKSM_PARAMS fmt)                                        \
    {                                                                                      \
        const gksm_arg a[] = { GKSM_ARGS fmt { 0 } };                                      \
        return rec_all(fctid, GKSM_ITEM_##name, GKSM_FMT_STR fmt, a);                      \
    }
#define GKSM_HOOK_REC_WS(name, key, fmt)                                                   \
    int gks_mf_ws_rec_##key(int fctid, int ws_id GKSM_PARAMS fmt)                          \
    {                                                                                      \
        const gksm_arg a[] = { GKSM_ARGS fmt { 0 } };                                      \
        return rec_ws(fctid, ws_id, GKSM_ITEM_##name, GKSM_FMT_STR fmt, a);                \
    }
#define GKSM_HOOK_REC_OWN(name, key, fmt)
#define GKSM_HOOK_PRIM(name, key, fmt)
#define GKSM_HOOK_ATTR(name, key, fmt)
#define GKSM_HOOK_STATE(name, key, fmt)
#define GKSM_HOOK_READ(name, key, fmt)
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_HOOK_##kind(name, key, fmt)
#define GKSM_ALSO(key, name, kind, fmt) GKSM_HOOK_##kind(name, key, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO

int gks_mf_escape(int fctid, gks_ws *ws, int func_id, const Gescape_in_data *in)
{
    mo_t o;
    int err = mo_of(ws, &o);
    if (err < 0)
        return 0;
    if (!err) {
        int ni = in->num_ints > 0 && in->ints ? in->num_ints : 0;
        int nr = in->num_floats > 0 && in->floats ? in->num_floats : 0;
        gksm_rec *r = &o.m->rec;
        gksm_rec_clear(r);
        gksm_rec_int(r, func_id);
        gksm_rec_int(r, ni);
        for (int i = 0; i < ni; i++)
            gksm_rec_int(r, in->ints[i]);
        gksm_rec_int(r, nr);
        for (int i = 0; i < nr; i++)
            gksm_rec_real(r, in->floats[i]);
        gksm_rec_str(r, in->str ? in->str : "", in->str ? in->str_len : 0);
        err = put(&o, GKSM_ITEM_ESCAPE);
    }
    mf_errs e = { 0 };
    note(&e, err);
    if (report(&e, fctid)) {
    } /* the caller returns either way: the ESCAPE was for this MO */
    return 1;
}

int gks_mf_user_item(int fctid, gks_ws *ws, int type, const char *data, size_t len)
{
    mo_t o;
    int err = mo_of(ws, &o);
    if (err < 0)
        return 1;
    if (!err) {
        gksm_rec_clear(&o.m->rec);
        gksm_rec_raw(&o.m->rec, data, len);
        err = put(&o, type);
    }
    mf_errs e = { 0 };
    note(&e, err);
    return report(&e, fctid);
}

/* ---------------------------------------------------------------- attribute sync */
/* The current primitive attributes recorded one item per entry (the ATTR rows of the item
 * table, in their order): the n ints or n reals the item's format names, from a
 * gks_cur_attrs field on (PATTERN REFERENCE POINT AND VECTORS: the point and the two
 * vectors after it). */
typedef struct {
    int item;
    size_t off;
} attr_field;

#define GKSM_ATTR_ROW_ATTR(name, key) { GKSM_ITEM_##name, offsetof(gks_cur_attrs, key) },
#define GKSM_ATTR_ROW_REC_WS(name, key)
#define GKSM_ATTR_ROW_REC_ALL(name, key)
#define GKSM_ATTR_ROW_REC_OWN(name, key)
#define GKSM_ATTR_ROW_PRIM(name, key)
#define GKSM_ATTR_ROW_STATE(name, key)
#define GKSM_ATTR_ROW_READ(name, key)
static const attr_field attr_fields[] = {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_ATTR_ROW_##kind(name, key)
#define GKSM_ALSO(key, name, kind, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
};

/* The layouts the table relies on (ints and enums are int-sized, reals contiguous). */
_Static_assert(sizeof(Gtext_path) == sizeof(int) && sizeof(Gasf) == sizeof(int) &&
                   sizeof(Gtext_align) == 2 * sizeof(int) &&
                   sizeof(Gtext_font_prec) == 2 * sizeof(int) && GKS_N_ASF == 17,
               "enum fields must be int-sized");
_Static_assert(offsetof(gks_cur_attrs, pat_ref_vec) ==
                   offsetof(gks_cur_attrs, pat_ref_point) + 3 * sizeof(double),
               "pattern reference point and vectors must be contiguous");

/* The bytes of field f: n ints or n reals as its item's format says. */
static size_t field_size(const attr_field *f, int *n, char *k)
{
    int arr;
    *n = 0; /* an item without a format has no fields */
    *k = 'i';
    gksm_fmt_next(gksm_item_fmt(f->item), n, k, &arr);
    return (size_t)*n * (*k == 'i' ? sizeof(int) : sizeof(double));
}

static int field_item(const mo_t *o, const attr_field *f, const gks_cur_attrs *a)
{
    const char *base = (const char *)a + f->off;
    gksm_rec *r = &o->m->rec;
    int n;
    char k;
    gksm_rec_clear(r);
    field_size(f, &n, &k);
    for (int j = 0; j < n; j++) {
        if (k == 'i') {
            int v;
            memcpy(&v, base + (size_t)j * sizeof v, sizeof v);
            gksm_rec_int(r, v);
        } else {
            double v;
            memcpy(&v, base + (size_t)j * sizeof v, sizeof v);
            gksm_rec_real(r, v);
        }
    }
    return put(o, f->item);
}

static int props_item(const mo_t *o, int side, const Garea_props *p)
{
    const double r[9] = { p->ambient_coef, p->diffuse_coef, p->specular_coef,
                          p->specular_colr.red, p->specular_colr.green, p->specular_colr.blue,
                          p->specular_exp, p->transpar_coef, p->refr_index };
    return put_nums(o, GKSM_ITEM_AREA_PROPS, 1, (const long[]){ side }, 9, r);
}

static int light_state_item(const mo_t *o, uint64_t mask)
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
static int sync_attrs(const mo_t *o, const gks_cur_attrs *a)
{
    int all = !o->m->synced, err = 0;
    const gks_cur_attrs *l = &o->m->last;
    for (size_t i = 0; i < sizeof attr_fields / sizeof attr_fields[0] && !err; i++) {
        const attr_field *f = &attr_fields[i];
        int n;
        char k;
        size_t sz = field_size(f, &n, &k);
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

static int sync_xform(const mo_t *o, const gks_mf_prim *p)
{
    int all = !o->m->synced, err = 0;
    if (all || memcmp(o->m->norm, p->norm, sizeof o->m->norm)) {
        double r[12];
        memcpy(r, p->norm, sizeof r);
        err = put_nums(o, GKSM_ITEM_NORM, 0, NULL, 12, r);
        memcpy(o->m->norm, p->norm, sizeof o->m->norm);
    }
    if (!err && (all || o->m->clip_on != p->clip_on || memcmp(o->m->box, p->box, sizeof o->m->box))) {
        err = put_nums(o, GKSM_ITEM_CLIP_VOL3, 1, (const long[]){ p->clip_on }, 6, p->box);
        memcpy(o->m->box, p->box, sizeof o->m->box);
        o->m->clip_on = p->clip_on;
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
static int write_points(const mo_t *o, const gks_mf_prim *p)
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
        gksm_rec_clear(&o->m->rec);
        gksm_rec_int(&o->m->rec, (long)k);
        for (size_t j = s; j < e; j++)
            if (ndc_point(p, j, v))
                rec_point(&o->m->rec, v);
        int err = put(o, p->item);
        if (err)
            return err;
    }
    return 0;
}

static int write_area(const mo_t *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->m->rec);
    if (p->item == GKSM_ITEM_FILL_AREA_SET3) {
        gksm_rec_int(&o->m->rec, (long)p->n_loops);
        for (size_t k = 0; k < p->n_loops; k++)
            gksm_rec_int(&o->m->rec, (long)p->cnt[k]);
    } else {
        gksm_rec_int(&o->m->rec, (long)p->n);
    }
    for (size_t i = 0; i < p->n; i++) {
        double v[3];
        if (!ndc_point(p, i, v))
            return 0; /* not drawn: not recorded */
        rec_point(&o->m->rec, v);
    }
    return put(o, p->item);
}

static int write_text(const mo_t *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->m->rec);
    for (size_t i = 0; i < 3; i++) {
        double w[3];
        src_point(p, i, w);
        if (i == 0 && !(isfinite(w[0]) && isfinite(w[1]) && isfinite(w[2])))
            return 0; /* nothing drawn */
        rec_point(&o->m->rec, w);
    }
    gksm_rec_str(&o->m->rec, p->str, strlen(p->str));
    return put(o, p->item);
}

static int write_cells(const mo_t *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->m->rec);
    for (size_t i = 0; i < 3; i++) {
        double v[3];
        if (!ndc_point(p, i, v))
            return 0;
        rec_point(&o->m->rec, v);
    }
    gksm_rec_int(&o->m->rec, p->nx);
    gksm_rec_int(&o->m->rec, p->ny);
    size_t n = (size_t)p->nx * (size_t)p->ny;
    for (size_t i = 0; i < n; i++)
        gksm_rec_int(&o->m->rec, p->colr[i]);
    return put(o, p->item);
}

/* A primitive with data: its packed form (gks_area_data.h), integers then reals. */
static int write_data(const mo_t *o, const gks_mf_prim *p)
{
    gksm_rec_clear(&o->m->rec);
    for (size_t i = 0; i < p->n_dints; i++)
        gksm_rec_int(&o->m->rec, p->dints[i]);
    for (size_t i = 0; i < p->n_dreals; i++)
        gksm_rec_real(&o->m->rec, p->dreals[i]);
    return put(o, p->item);
}

int gks_mf_prim_write(int fctid, const gks_mf_prim *p)
{
    gks_context *c = gks_ctx();
    mf_errs e = { 0 };
    for (int i = 0; i < n_targets(c); i++) {
        mo_t mo;
        const mo_t *o = &mo;
        if (target(c, i)->state != GWS_ACTIVE)
            continue;
        int err = mo_of(target(c, i), &mo);
        if (!err && target(c, i) == c->rec_ws)
            c->rec_drawn = 1;
        if (err < 0)
            continue;
        if (err) {
            note(&e, err);
            continue;
        }
        err = sync_attrs(o, &c->sl->attrs);
        if (!err)
            err = sync_xform(o, p);
        if (err) {
            o->m->synced = 0; /* what was written is unknown: write everything next time */
            note(&e, err);
            continue;
        }
        o->m->last = c->sl->attrs;
        o->m->synced = 1;
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
        note(&e, err);
    }
    return report(&e, fctid);
}
