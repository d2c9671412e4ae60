/* SPDX-License-Identifier: MIT */
/*
 * gks_metafile.c -- the metafile input functions GET ITEM TYPE FROM GKSM, READ ITEM FROM
 * GKSM and INTERPRET ITEM, and WRITE ITEM TO GKSM. The items come from the MI workstation's
 * driver (item_reader: the file and its bytes) and go to the MO's (record_item, through
 * core/store/gks_mf_record.c). INTERPRET ITEM decodes a data record as its row of the item
 * table (core/store/gks_mf_items.def) says and performs the recorded function through the
 * public entry points, primitives through the pipeline's recorded-normalization entries
 * (gks_output_rec.h). A data record is untrusted: every field is checked against the
 * record's length, every count before anything is allocated from it (errors 165, 300).
 */
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_export.h"
#include "gks_mf_record.h"
#include "gks_output_rec.h"
#include "gks_state.h"
#include "ws_driver.h"
#include <limits.h>
#include <math.h>
#include <string.h>

/* ---------------------------------------------------------------- reading */
/* State check, then 20, 25, 34. The MI's reader, and in *ws_out its workstation. */
static gksm_in *mi_checked(int fct, Gint ws_id, int *allow)
{
    if (gks_check_state(fct))
        return NULL;
    if (ws_id < 0)
        GKS_FAIL_RET(20, fct, NULL);
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        GKS_FAIL_RET(25, fct, NULL);
    if (ws->drv->desc->cat != GCAT_MI || !ws->drv->item_reader)
        GKS_FAIL_RET(34, fct, NULL);
    return ws->drv->item_reader(ws, allow);
}

GKS_API void gget_item_type(Gint ws_id, Gint *type, Gint *length)
{
    int allow;
    gksm_in *m = mi_checked(GFN_GTITM, ws_id, &allow);
    if (!m)
        return;
    int t;
    size_t len;
    int err = gksm_in_peek(m, &t, &len);
    if (!err && len > INT_MAX)
        err = 163;
    if (err)
        GKS_FAIL(err, GFN_GTITM);
    if (type)
        *type = t;
    if (length)
        *length = (Gint)len;
}

GKS_API void gread_item(Gint ws_id, Gint max_length, Gitem_data *item_data)
{
    int allow;
    gksm_in *m = mi_checked(GFN_RDITM, ws_id, &allow);
    if (!m)
        return;
    char *data = item_data ? item_data->data.impl_dep.data : NULL;
    int type = 0;
    size_t length = 0;
    int perr = gksm_in_peek(m, &type, &length);
    if (!perr && length > INT_MAX)
        perr = 163;
    if (perr)
        GKS_FAIL(perr, GFN_RDITM);
    if (max_length < 0 || (max_length > 0 && !data))
        GKS_FAIL(166, GFN_RDITM);
    size_t got;
    int err = gksm_in_read(m, data, (size_t)max_length, &got);
    if (err)
        GKS_FAIL(err, GFN_RDITM);
    if (item_data) {
        item_data->type = type;
        item_data->length = (Gint)length;
        item_data->data.impl_dep.size = got;
    }
    gks_ctx()->sl->mf_last_mi = ws_id + 1;
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
    if (!gks_mf_is_mo(ws))
        GKS_FAIL(32, GFN_WITM);
    if (type < GKSM_ITEM_USER_MIN || type > 999)
        GKS_FAIL(160, GFN_WITM);
    if (length < 0 || (length > 0 && (!data || (size_t)length > have)))
        GKS_FAIL(161, GFN_WITM);
    if (gks_mf_user_item(GFN_WITM, ws, type, data, (size_t)length)) {
    } /* the last action: returning is right either way */
}

/* ---------------------------------------------------------------- decoding */
typedef struct {
    gksm_cur c;
    int err;
} dec;

static long d_long(dec *d)
{
    long v = 0;
    if (!d->err && gksm_get_int(&d->c, &v))
        d->err = 165;
    return d->err ? 0 : v;
}

static int d_int(dec *d)
{
    long v = d_long(d);
    if (v < INT_MIN || v > INT_MAX) {
        d->err = 165;
        return 0;
    }
    return (int)v;
}

static double d_real(dec *d)
{
    double v = 0;
    if (!d->err && gksm_get_real(&d->c, &v))
        d->err = 165;
    return d->err ? 0 : v;
}

static void d_reals(dec *d, double *v, int n)
{
    for (int i = 0; i < n; i++)
        v[i] = d_real(d);
}

/* Width of one field of kind 'i' or 'r' in this record's format. */
static size_t field_w(const dec *d, char kind)
{
    return kind == 'r' && d->c.ri == 1 ? (size_t)d->c.rw : (size_t)d->c.iw;
}

/* A count in [min, max] that must fit `per` fields of kind `kind` each in what is left of
 * the record (so nothing is allocated beyond the record's size); -1 (err 165) if not. */
static long d_count(dec *d, long min, long max, size_t per, char kind)
{
    long n = d_long(d);
    size_t w = field_w(d, kind) * per;
    if (d->err || n < min || n > max || (n > 0 && (size_t)n > gksm_cur_left(&d->c) / w)) {
        d->err = 165;
        return -1;
    }
    return n;
}

/* A string field as a terminated copy (NULL and err 165/300 on failure). */
static char *d_str(dec *d)
{
    const char *s;
    size_t n;
    if (d->err || gksm_get_str(&d->c, &s, &n)) {
        d->err = 165;
        return NULL;
    }
    char *t = gks_strndup(s, n);
    if (!t)
        d->err = 300;
    if (t && strlen(t) != n) { /* an embedded NUL: not a GKS string */
        gks_free(t);
        d->err = 165;
        return NULL;
    }
    return t;
}

/* A new array of n (at least 1) elements of `size` bytes, or NULL with err 300. */
static void *d_alloc(dec *d, size_t n, size_t size)
{
    void *p = gks_alloc_array(n ? n : 1, size);
    if (!p)
        d->err = 300;
    return p;
}

/* n points of `dim` reals each (z = 0 when dim is 2) into a new array. */
static Gpoint3 *d_points(dec *d, long n, int dim)
{
    Gpoint3 *p = d_alloc(d, (size_t)n, sizeof *p);
    if (!p)
        return NULL;
    for (long i = 0; i < n; i++) {
        p[i].x = d_real(d);
        p[i].y = d_real(d);
        p[i].z = dim == 3 ? d_real(d) : 0.0;
    }
    return p;
}

/* ---------------------------------------------------------------- interpretation */
/* The most integers and reals of an item decoded by its format (VIEW REPRESENTATION 3: 4
 * integers, 38 reals); a format beyond them is refused (165), never written past. */
#define FIELDS_MAX_INTS 8
#define FIELDS_MAX_REALS 48

typedef struct {
    dec d;
    gks_rec_xf *xf;        /* the MI's interpretation state (or a local default) */
    int allow_escapes;     /* the MI's GESC_MI_ALLOW_ESCAPES (0 without an MI) */
    int iv[FIELDS_MAX_INTS];
    double rv[FIELDS_MAX_REALS];
    char *str;             /* the string field, if the format has one */
} interp;

/* The interpretation state before any NORMALIZATION / CLIPPING item: identity, the NDC
 * unit cube, clipping on. */
static void xf_default(gks_rec_xf *xf)
{
    memset(xf, 0, sizeof *xf);
    for (int i = 0; i < 3; i++)
        xf->norm[i][i] = 1;
    const double box[6] = { 0, 1, 0, 1, 0, 1 };
    memcpy(xf->box, box, sizeof box);
    xf->clip_on = 1;
}

/* The interpretation state of the MI workstation mi (its gks_ws.mf, made at first use,
 * freed with the workstation by gks_mf_ws_free): the NORMALIZATION and CLIPPING VOLUME
 * items interpreted from it so far. NULL on storage overflow. */
static gks_rec_xf *mi_state(gks_ws *mi)
{
    if (!mi->mf) {
        gks_rec_xf *xf = gks_alloc_array(1, sizeof *xf);
        if (!xf)
            return NULL;
        xf_default(xf);
        mi->mf = xf;
    }
    return mi->mf;
}

/* The recorded normalization for a primitive: points in NDC3 (ndc 1) or WC3 (TEXT). */
static gks_rec_xf xf_for(const interp *ip, int ndc)
{
    gks_rec_xf x = *ip->xf;
    x.ndc_pts = ndc;
    return x;
}

/* The ids of the active workstations a workstation item applies to (not WISS). */
static int active_targets(int ids[GKS_MAX_ACTIVE_WS])
{
    gks_context *c = gks_ctx();
    int n = 0;
    for (int i = 0; i < c->sl->n_active; i++) {
        gks_ws *ws = gks_ws_lookup(c->sl->active_ws[i]);
        if (ws && ws->drv->desc->cat != GCAT_WISS)
            ids[n++] = ws->id;
    }
    return n;
}

/* A call per target workstation (WS its identifier); the loop stops when an error handler
 * changed the world (gks_error.h): the remaining ids may be stale, GKS may be closed. */
#define EACH_WS(...)                                                                       \
    do {                                                                                   \
        int ids_[GKS_MAX_ACTIVE_WS];                                                       \
        int n_ = active_targets(ids_);                                                     \
        unsigned long epoch_ = gks_world_epoch();                                          \
        for (int k_ = 0; k_ < n_ && gks_world_epoch() == epoch_; k_++) {                   \
            const Gint ws_ = ids_[k_];                                                     \
            __VA_ARGS__;                                                                   \
        }                                                                                  \
    } while (0)
#define WS ws_

/* Polyline/polymarker/fill area items: n then n points of dim reals, performed as the
 * 3-D primitive `item` (POLYLINE 3, POLYMARKER 3 or FILL AREA 3). */
static void x_points(interp *ip, int dim, int item)
{
    long min = item == GKSM_ITEM_POLYLINE3 ? 2 : item == GKSM_ITEM_POLYMARKER3 ? 1 : 3;
    long n = d_count(&ip->d, min, LONG_MAX, (size_t)dim, 'r');
    if (n < 0)
        return;
    Gpoint3 *p = d_points(&ip->d, n, dim);
    if (p && !ip->d.err && gksm_cur_left(&ip->d.c) == 0) {
        Gpoint_list3 l = { (Gint)n, p };
        gks_rec_xf x = xf_for(ip, 1);
        if (item == GKSM_ITEM_POLYLINE3)
            gks_output_rec_polyline3(&x, &l);
        else if (item == GKSM_ITEM_POLYMARKER3)
            gks_output_rec_polymarker3(&x, &l);
        else
            gks_output_rec_fill_area3(&x, &l);
    } else if (!ip->d.err) {
        ip->d.err = 165;
    }
    gks_free(p);
}

static void x_fill_area_set(interp *ip)
{
    dec *d = &ip->d;
    long nl = d_count(d, 1, LONG_MAX, 1, 'i');
    Gpoint_list3 *lists = nl < 0 ? NULL : d_alloc(d, (size_t)nl, sizeof *lists);
    if (!lists)
        return;
    long total = 0;
    for (long k = 0; k < nl && !d->err; k++) {
        long c = d_long(d);
        if (c < 3 || c > INT_MAX || total > LONG_MAX - c)
            d->err = 165;
        lists[k].num_points = (Gint)c;
        total += c;
    }
    Gpoint3 *p = NULL;
    if (!d->err && (size_t)total > gksm_cur_left(&d->c) / (3 * field_w(d, 'r')))
        d->err = 165;
    if (!d->err)
        p = d_points(d, total, 3);
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    if (!d->err) {
        long off = 0;
        for (long k = 0; k < nl; k++) {
            lists[k].points = p + off;
            off += lists[k].num_points;
        }
        Gpoint_list_list3 ll = { (Gint)nl, lists };
        gks_rec_xf x = xf_for(ip, 1);
        gks_output_rec_fill_area_set3(&x, &ll);
    }
    gks_free(p);
    gks_free(lists);
}

/* A primitive with data: its packed form (gks_area_data.h), the header's counts checked
 * against what is left of the record before anything is allocated. */
static void x_data(interp *ip, int type)
{
    dec *d = &ip->d;
    int hdr[GKS_AREA_DATA_HEADER];
    for (int k = 0; k < GKS_AREA_DATA_HEADER; k++)
        hdr[k] = d_int(d);
    size_t ni = 0, nt = 0;
    if (!d->err && gks_area_data_packed_sizes(hdr, &ni, &nt))
        d->err = 165;
    if (d->err)
        return;
    size_t more = ni - GKS_AREA_DATA_HEADER, left = gksm_cur_left(&d->c);
    size_t wi = field_w(d, 'i'), wr = field_w(d, 'r');
    if (more > left / wi || nt > (left - more * wi) / (3 * wr)) {
        d->err = 165;
        return;
    }
    int *ints = d_alloc(d, ni, sizeof *ints);
    double (*tri)[3] = d_alloc(d, nt, sizeof *tri);
    for (size_t k = 0; !d->err && k < ni; k++)
        ints[k] = k < GKS_AREA_DATA_HEADER ? hdr[k] : d_int(d);
    for (size_t i = 0; !d->err && i < nt; i++)
        d_reals(d, tri[i], 3);
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    gks_area_data a;
    if (!d->err && gks_area_data_unpack(ints, ni, (const double (*)[3])tri, nt, &a))
        d->err = 165;
    if (!d->err) {
        gks_rec_xf x = xf_for(ip, 1);
        gks_output_rec_data(&x, type, &a);
    }
    gks_free(ints);
    gks_free(tri);
}

static void x_text(interp *ip, int three)
{
    dec *d = &ip->d;
    double v[9] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
    if (three)
        d_reals(d, v, 9);
    else
        d_reals(d, v, 2);
    char *s = d_str(d);
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    if (!d->err) {
        Gpoint3 pos = { v[0], v[1], v[2] };
        Gvec3 dir[2] = { { v[3], v[4], v[5] }, { v[6], v[7], v[8] } };
        gks_rec_xf x = xf_for(ip, 0);
        gks_output_rec_text3(&x, &pos, dir, s);
    }
    gks_free(s);
}

/* The colour-index grid of a cell array or pattern: NX, NY, then NX*NY indices, which must
 * end the record. Returns the indices (the caller frees them), or NULL with d->err set
 * (165: bad counts, garbage or trailing data; 300: storage). */
static Gint *d_index_grid(dec *d, Gint *nx_out, Gint *ny_out)
{
    long nx = d_long(d), ny = d_long(d);
    if (!d->err && (nx < 1 || ny < 1 || nx > INT_MAX || ny > INT_MAX ||
                    (size_t)nx > gksm_cur_left(&d->c) / field_w(d, 'i') / (size_t)ny))
        d->err = 165;
    if (d->err)
        return NULL;
    size_t n = (size_t)nx * (size_t)ny;
    Gint *colr = d_alloc(d, n, sizeof *colr);
    if (!colr)
        return NULL;
    for (size_t i = 0; i < n; i++)
        colr[i] = d_int(d);
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    if (d->err) {
        gks_free(colr);
        return NULL;
    }
    *nx_out = (Gint)nx;
    *ny_out = (Gint)ny;
    return colr;
}

static void x_cell_array(interp *ip, int dim)
{
    dec *d = &ip->d;
    double v[9] = { 0 };
    for (int i = 0; i < 3; i++)
        d_reals(d, v + 3 * i, dim);
    Gint nx, ny;
    Gint *colr = d->err ? NULL : d_index_grid(d, &nx, &ny);
    if (!colr)
        return;
    Gparal par = { { v[0], v[1], v[2] }, { v[3], v[4], v[5] }, { v[6], v[7], v[8] } };
    Gpat_rep ca = { { nx, ny }, colr };
    gks_rec_xf x = xf_for(ip, 1);
    gks_output_rec_cell_array3(&x, &par, &ca);
    gks_free(colr);
}

static void x_pat_rep(interp *ip)
{
    dec *d = &ip->d;
    int ind = d_int(d);
    Gint nx, ny;
    Gint *colr = d->err ? NULL : d_index_grid(d, &nx, &ny);
    if (!colr)
        return;
    Gpat_rep rep = { { nx, ny }, colr };
    EACH_WS(gset_pat_rep(ws_, ind, &rep));
    gks_free(colr);
}

static void x_light_state(interp *ip)
{
    dec *d = &ip->d;
    long n = d_count(d, 0, GKS_MAX_LIGHT_IND, 1, 'i');
    if (n < 0)
        return;
    Gint on[GKS_MAX_LIGHT_IND], off[GKS_MAX_LIGHT_IND];
    unsigned char is_on[GKS_MAX_LIGHT_IND + 1] = { 0 };
    for (long i = 0; i < n && !d->err; i++) {
        on[i] = d_int(d);
        if (on[i] < 1 || on[i] > GKS_MAX_LIGHT_IND)
            d->err = 165;
        else
            is_on[on[i]] = 1;
    }
    if (d->err || gksm_cur_left(&d->c) != 0) {
        d->err = 165;
        return;
    }
    int m = 0;
    for (int i = 1; i <= GKS_MAX_LIGHT_IND; i++)
        if (!is_on[i])
            off[m++] = i;
    Gint_list a = { (Gint)n, on }, b = { m, off };
    gset_light_src_state(&a, &b);
}

/* Caps on what an untrusted metafile may ask of a ray-traced picture (docs/METAFILE.md). */
#define MI_CAP_RT_SAMPLES 16
#define MI_CAP_RT_MAX_DEPTH 16

/* Whether a recorded ESCAPE may be performed: everything when the application allowed it
 * (GESC_MI_ALLOW_ESCAPES); otherwise the picture settings only, the sample count and ray
 * depth capped in place. A metafile is untrusted input: it may not choose where the viewer
 * writes, how many threads it starts, or print to its standard error. 0 or 180. */
static int escape_policy(const interp *ip, int func, Gint *ints, long ni)
{
    if (ip->allow_escapes)
        return 0;
    switch (func) {
    case GESC_RT_SAMPLES:
        if (ni >= 2 && ints[1] > MI_CAP_RT_SAMPLES)
            ints[1] = MI_CAP_RT_SAMPLES;
        return 0;
    case GESC_RT_MAX_DEPTH:
        if (ni >= 2 && ints[1] > MI_CAP_RT_MAX_DEPTH)
            ints[1] = MI_CAP_RT_MAX_DEPTH;
        return 0;
    case GESC_RT_CLIP_SECONDARY:
    case GESC_RT_CUTOFF:
    case GESC_RT_SPD:
    case GESC_PNG_SUPERSAMPLE:
    case GESC_PNG_COMPRESSION:
    case GESC_VEC_LINE_JOIN:
    case GESC_VEC_LINE_CAP:
    case GESC_VEC_MITER_LIMIT:
    case GESC_VEC_LINE_SCALE:
    case GESC_VEC_PAGE:
        return 0;
    default: /* file names, threads, progress, statistics, and anything newer */
        return 180;
    }
}

/* ESCAPE: function identification, integers (the first, the workstation identifier, is
 * replaced by each active workstation's), reals, string. */
static void x_escape(interp *ip)
{
    dec *d = &ip->d;
    int func = d_int(d);
    long ni = d_count(d, 1, LONG_MAX, 1, 'i');
    Gint *ints = ni < 0 ? NULL : d_alloc(d, (size_t)ni, sizeof *ints);
    Gfloat *reals = NULL;
    if (!ints)
        return;
    for (long i = 0; i < ni; i++)
        ints[i] = d_int(d);
    long nr = d_count(d, 0, LONG_MAX, 1, 'r');
    if (nr >= 0)
        reals = d_alloc(d, (size_t)nr, sizeof *reals);
    for (long i = 0; reals && i < nr; i++)
        reals[i] = d_real(d);
    const char *s = NULL;
    size_t n = 0;
    if (!d->err && gksm_get_str(&d->c, &s, &n))
        d->err = 165;
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    if (!d->err)
        d->err = escape_policy(ip, func, ints, ni);
    if (!d->err) {
        Gescape_in_data in = { { (Gint)ni, ints, (Gint)nr, reals, n, s } };
        EACH_WS((ints[0] = ws_, gescape(func, &in, NULL, NULL)));
    }
    gks_free(ints);
    gks_free(reals);
}

/* Decodes a data record by its item's format into ip->iv, ip->rv, ip->str: complete and
 * nothing left over. 1 if it did. */
static int fields(interp *ip, const char *fmt)
{
    int ni = 0, nr = 0, n, arr;
    char k;
    while ((fmt = gksm_fmt_next(fmt, &n, &k, &arr)) && !ip->d.err) {
        if (k == 's') {
            if (ip->str)
                ip->d.err = 165; /* one string per format */
            else
                ip->str = d_str(&ip->d);
            continue;
        }
        if (k == 'i' ? n > FIELDS_MAX_INTS - ni : n > FIELDS_MAX_REALS - nr) {
            ip->d.err = 165; /* a format beyond the arrays: never written past them */
            return 0;
        }
        for (int j = 0; j < n; j++) {
            if (k == 'i')
                ip->iv[ni++] = d_int(&ip->d);
            else
                ip->rv[nr++] = d_real(&ip->d);
        }
    }
    if (!ip->d.err && gksm_cur_left(&ip->d.c) != 0)
        ip->d.err = 165;
    return ip->d.err == 0;
}

static Gasf asf_of(int v) { return (Gasf)v; }

static void x_asf(interp *ip)
{
    int f[GKS_N_ASF];
    int n = (int)(gksm_cur_left(&ip->d.c) / field_w(&ip->d, 'i'));
    if (n != 13 && n != GKS_N_ASF) {
        ip->d.err = 165;
        return;
    }
    for (int i = 0; i < n; i++)
        f[i] = d_int(&ip->d);
    if (ip->d.err || gksm_cur_left(&ip->d.c) != 0) {
        ip->d.err = 165;
        return;
    }
    for (int i = 0; i < n; i++)
        if (f[i] != GASF_BUNDLED && f[i] != GASF_INDIV) {
            ip->d.err = 165;
            return;
        }
    Gasfs3 a = { { asf_of(f[0]), asf_of(f[1]), asf_of(f[2]), asf_of(f[3]), asf_of(f[4]),
                   asf_of(f[5]), asf_of(f[6]), asf_of(f[7]), asf_of(f[8]), asf_of(f[9]),
                   asf_of(f[10]), asf_of(f[11]), asf_of(f[12]) },
                 GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV };
    if (n == 13) {
        gset_asfs(&a.asfs);
        return;
    }
    a.edge_flag = asf_of(f[13]);
    a.edgetype = asf_of(f[14]);
    a.edgewidth = asf_of(f[15]);
    a.edge_colr_ind = asf_of(f[16]);
    gset_asfs3(&a);
}

/* The items decoded by their format whose function needs more than an expression. */
static void x_pat_ref_vecs(interp *ip)
{
    const double *r = ip->rv;
    Gvec3 v[2] = { { r[3], r[4], r[5] }, { r[6], r[7], r[8] } };
    gset_pat_ref_point_vecs(&(Gpoint3){ r[0], r[1], r[2] }, v);
}

static void x_area_props(interp *ip)
{
    const double *r = ip->rv;
    Garea_props p = { r[0], r[1], r[2], { r[3], r[4], r[5] }, r[6], r[7], r[8] };
    if (ip->iv[0] == 0)
        gset_area_props(&p);
    else if (ip->iv[0] == 1)
        gset_back_area_props(&p);
    else
        ip->d.err = 165;
}

static void x_clip_vol3(interp *ip)
{
    if (ip->iv[0] != 0 && ip->iv[0] != 1) {
        ip->d.err = 165;
        return;
    }
    ip->xf->clip_on = ip->iv[0];
    memcpy(ip->xf->box, ip->rv, sizeof ip->xf->box);
}

/* RAL: the clipping rectangle (0,1,0,1 when off). */
static void x_clip_rect(interp *ip)
{
    const double b[6] = { ip->rv[0], ip->rv[1], ip->rv[2], ip->rv[3], 0, 1 };
    memcpy(ip->xf->box, b, sizeof b);
    ip->xf->clip_on = 1;
}

/* RAL: height and width vectors (NDC). */
static void x_char_vecs(interp *ip)
{
    gset_char_ht(hypot(ip->rv[0], ip->rv[1]));
    gset_char_up_vec(&(Gvec){ ip->rv[0], ip->rv[1] });
}

static void x_view_rep3(interp *ip, Gint ws)
{
    const double *r = ip->rv;
    Gview_rep3 v;
    memcpy(v.ori_matrix, r, sizeof v.ori_matrix);
    memcpy(v.map_matrix, r + 16, sizeof v.map_matrix);
    v.clip_limit = (Glimit3){ r[32], r[33], r[34], r[35], r[36], r[37] };
    v.xy_clip = (Gclip_ind)ip->iv[1];
    v.back_clip = (Gclip_ind)ip->iv[2];
    v.front_clip = (Gclip_ind)ip->iv[3];
    gset_view_rep3(ws, ip->iv[0], &v);
}

static void x_light_rep(interp *ip, Gint ws)
{
    const double *r = ip->rv;
    Glight_src_rep v = { ip->iv[1], { r[0], r[1], r[2] }, { r[3], r[4], r[5] },
                         { r[6], r[7], r[8] }, { r[9], r[10] }, r[11], r[12] };
    gset_light_src_rep(ws, ip->iv[0], &v);
}

static void x_seg_tran3(interp *ip)
{
    Gtran_matrix3 m;
    memcpy(m, ip->rv, sizeof m);
    gset_seg_tran3(ip->iv[0], (const Gfloat (*)[4])m);
}

static void x_seg_tran(interp *ip)
{
    Gtran_matrix m;
    memcpy(m, ip->rv, sizeof m);
    gset_seg_tran(ip->iv[0], (const Gfloat (*)[3])m);
}

/* GDP: no GDP exists here with no points (GDP identifier invalid: 102, or 100). */
static void x_gdp(interp *ip)
{
    int id = d_int(&ip->d);
    if (!ip->d.err)
        ggdp3(&(Gpoint_list3){ 0, NULL }, id, NULL);
}

/* ---------------------------------------------------------------- the item table */
/* One function per row of gks_mf_items.def: FIELDS rows decode by their format, then
 * perform (on every target workstation for REC_WS rows); OWN rows decode themselves. */
#define I(k) (ip->iv[k])
#define R(k) (ip->rv[k])
#define S (ip->str)
#define SIDE(front, back)                                                                  \
    (I(0) == 0 ? (void)(front) : I(0) == 1 ? (void)(back) : (void)(ip->d.err = 165))
#define GKSM_RUN_REC_WS(...) EACH_WS(__VA_ARGS__)
#define GKSM_RUN_REC_ALL(...) __VA_ARGS__
#define GKSM_RUN_REC_OWN(...) __VA_ARGS__
#define GKSM_RUN_PRIM(...) __VA_ARGS__
#define GKSM_RUN_ATTR(...) __VA_ARGS__
#define GKSM_RUN_STATE(...) __VA_ARGS__
#define GKSM_RUN_READ(...) __VA_ARGS__
#define GKSM_DO_FIELDS(kind, fmt, ...)                                                     \
    if (fields(ip, GKSM_FMT_STR fmt))                                                      \
        GKSM_RUN_##kind(__VA_ARGS__);
#define GKSM_DO_OWN(kind, fmt, ...) __VA_ARGS__;
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...)                                    \
    static void perform_##name(interp *ip)                                                 \
    {                                                                                      \
        (void)ip;                                                                          \
        GKSM_DO_##dec(kind, fmt, __VA_ARGS__)                                              \
    }
#define GKSM_ALSO(key, name, kind, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM

static void (*const performers[GKSM_ITEM_USER_MIN])(interp *) = {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) [type] = perform_##name,
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
};

GKS_API void ginterpret_item(Gint type, Gint length, const Gitem_data *item_data)
{
    if (gks_check_state(GFN_IITM))
        return;
    const char *data = item_data ? item_data->data.impl_dep.data : NULL;
    size_t have = item_data ? item_data->data.impl_dep.size : 0;
    if (length < 0 || (length > 0 && (!data || (size_t)length > have)))
        GKS_FAIL(161, GFN_IITM);
    if (type < 0)
        GKS_FAIL(164, GFN_IITM);
    if (type >= GKSM_ITEM_USER_MIN)
        GKS_FAIL(167, GFN_IITM);
    if (!performers[type])
        GKS_FAIL(164, GFN_IITM);
    /* The record's field format and the interpretation state: those of the MI the last
     * item was read from; this writer's format and a fresh state otherwise. */
    gks_state_list *sl = gks_ctx()->sl;
    gks_ws *mi = sl->mf_last_mi > 0 ? gks_ws_lookup(sl->mf_last_mi - 1) : NULL;
    int allow = 0;
    gksm_in *m = mi && mi->drv->desc->cat == GCAT_MI && mi->drv->item_reader
                     ? mi->drv->item_reader(mi, &allow)
                     : NULL;
    gks_rec_xf *st = m ? mi_state(mi) : NULL;
    if (m && !st)
        GKS_FAIL(300, GFN_IITM);
    gksm_in fmt = { .iw = 11, .rw = 24, .ri = 1, .zero = 0, .one = 1 };
    gks_rec_xf local;
    xf_default(&local);
    interp ip = { .xf = st ? st : &local, .allow_escapes = m ? allow : 0 };
    gksm_cur_init(&ip.d.c, m ? m : &fmt, data ? data : "", (size_t)length);
    performers[type](&ip);
    gks_free(ip.str);
    if (ip.d.err)
        GKS_FAIL(ip.d.err, GFN_IITM);
}
