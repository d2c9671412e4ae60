/* SPDX-License-Identifier: MIT */
/*
 * ws_mi.c -- the GKS metafile input workstation (type GWS_TYPE_MI, category MI) and the
 * metafile input functions GET ITEM TYPE FROM GKSM, READ ITEM FROM GKSM and INTERPRET
 * ITEM. The file is untrusted: the header is checked at OPEN WORKSTATION, every length
 * against the bytes left (gks_mf_codec.c), and every count in a data record against the record's
 * length before anything is allocated from it.
 */
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include "ws_driver.h"
#include <limits.h>
#include <math.h>
#include <string.h>

static const gks_ws_desc mi_desc = {
    .type = GWS_TYPE_MI,
    .name = "gksm-in",
    .cat = GCAT_MI,
    .cls = GCLASS_OTHER,
    .dc_units = GDC_OTHER,
    .dc_x = 1, .dc_y = 1,
    .raster_x = 1, .raster_y = 1,
    .colr_avail = GAVAIL_COLR,
    .n_colr = 1,
    .default_irg = GIRG_ALLOWED,
    .default_defer = GDEFER_ASAP,
    .hlhsr_modes = 1u << GHLHSR_NONE,
    .out = &gks_wdt_raster,
};

/* The interpretation state before any NORMALIZATION / CLIPPING item: identity, clipping
 * at the NDC unit cube. */
static void xf_default(gks_norm_override *xf)
{
    memset(xf, 0, sizeof *xf);
    for (int i = 0; i < 3; i++)
        xf->norm[i][i] = 1;
    const double box[6] = { 0, 1, 0, 1, 0, 1 };
    memcpy(xf->box, box, sizeof box);
    xf->clip_on = 1;
}

static int mi_open(gks_ws *ws)
{
    if (!ws->conn_id || !*ws->conn_id)
        return 21;
    gks_mf_in *m = gks_calloc_array(1, sizeof *m);
    if (!m)
        return 300;
    char *path = gks_mf_file_name(ws->conn_id);
    m->fp = path ? fopen(path, "rb") : NULL;
    gks_free(path);
    if (!m->fp) {
        gks_free(m);
        return 26;
    }
    if (gksm_in_open(&m->in, m->fp)) { /* not a GKSM file this reader accepts */
        fclose(m->fp);
        gks_free(m);
        return 26;
    }
    xf_default(&m->xf);
    ws->priv = m;
    return 0;
}

static void mi_close(gks_ws *ws)
{
    gks_mf_in *m = ws->priv;
    if (!m)
        return;
    fclose(m->fp);
    gks_free(m);
    ws->priv = NULL;
}

/* GESC_MI_ALLOW_ESCAPES: ints[1] 0/1. */
static int mi_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    (void)out;
    gks_mf_in *m = ws->priv;
    if (func_id != GESC_MI_ALLOW_ESCAPES)
        return 180;
    if (in->num_ints < 2 || (in->ints[1] != 0 && in->ints[1] != 1))
        return 182;
    m->allow_escapes = in->ints[1];
    return 0;
}

const gks_ws_driver gks_ws_mi_driver = {
    .version = GKS_WS_DRIVER_VERSION,
    .desc = &mi_desc,
    .file = gks_mf_file,
    .open = mi_open,
    .close = mi_close,
    .escape = mi_escape,
};

/* ---------------------------------------------------------------- reading */
/* State check, then 20, 25, 34. */
static gks_mf_in *mi_checked(int fct, Gint ws_id)
{
    if (gks_check_state(fct))
        return NULL;
    if (ws_id < 0)
        GKS_FAIL_RET(20, fct, NULL);
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        GKS_FAIL_RET(25, fct, NULL);
    if (ws->drv->desc->cat != GCAT_MI)
        GKS_FAIL_RET(34, fct, NULL);
    return ws->priv;
}

GKS_API void gget_item_type(Gint ws_id, Gint *type, Gint *length)
{
    gks_mf_in *m = mi_checked(GFN_GTITM, ws_id);
    if (!m)
        return;
    int t;
    size_t len;
    int err = gksm_in_peek(&m->in, &t, &len);
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
    gks_mf_in *m = mi_checked(GFN_RDITM, ws_id);
    if (!m)
        return;
    char *data = item_data ? item_data->data.impl_dep.data : NULL;
    int type = 0;
    size_t length = 0;
    int perr = gksm_in_peek(&m->in, &type, &length);
    if (!perr && length > INT_MAX)
        perr = 163;
    if (perr)
        GKS_FAIL(perr, GFN_RDITM);
    if (max_length < 0 || (max_length > 0 && !data))
        GKS_FAIL(166, GFN_RDITM);
    size_t got;
    int err = gksm_in_read(&m->in, data, (size_t)max_length, &got);
    if (err)
        GKS_FAIL(err, GFN_RDITM);
    if (item_data) {
        item_data->type = type;
        item_data->length = (Gint)length;
        item_data->data.impl_dep.size = got;
    }
    gks_ctx()->sl->mf_last_mi = ws_id + 1;
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

/* A count that must fit `per` fields of kind `kind` each in what is left of the record
 * (so nothing is allocated beyond the record's size); -1 (err 165) if not. */
static long d_count(dec *d, long min, size_t per, char kind)
{
    long n = d_long(d);
    size_t w = field_w(d, kind) * per;
    if (d->err || n < min || (n > 0 && (size_t)n > gksm_cur_left(&d->c) / w)) {
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

/* n points of `dim` reals each (z = 0 when dim is 2) into a new array. */
static Gpoint3 *d_points(dec *d, long n, int dim)
{
    Gpoint3 *p = gks_alloc_array((size_t)(n > 0 ? n : 1), sizeof *p);
    if (!p) {
        d->err = 300;
        return NULL;
    }
    for (long i = 0; i < n; i++) {
        p[i].x = d_real(d);
        p[i].y = d_real(d);
        p[i].z = dim == 3 ? d_real(d) : 0.0;
    }
    return p;
}

/* ---------------------------------------------------------------- interpretation */
typedef struct {
    dec d;
    gks_norm_override *xf; /* the MI's interpretation state (or a local default) */
    int allow_escapes;     /* the MI's GESC_MI_ALLOW_ESCAPES (0 without an MI) */
} interp;

/* Runs a primitive function with the recorded normalization and clipping volume. */
#define WITH_XF(ip, ndc, call)                                                             \
    do {                                                                                   \
        gks_norm_override ov_ = *(ip)->xf;                                                 \
        ov_.ndc_pts = (ndc);                                                               \
        gks_ctx()->norm_override = &ov_;                                                   \
        call;                                                                              \
        gks_ctx()->norm_override = NULL;                                                   \
    } while (0)

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

/* A call per target workstation; the loop stops when an error handler changed the world
 * (gks_error.h): the remaining ids may be stale, GKS may be closed. */
#define EACH_WS(call)                                                                      \
    do {                                                                                   \
        int ids_[GKS_MAX_ACTIVE_WS];                                                       \
        int n_ = active_targets(ids_);                                                     \
        unsigned long epoch_ = gks_world_epoch();                                          \
        for (int k_ = 0; k_ < n_ && gks_world_epoch() == epoch_; k_++) {                   \
            const Gint ws_ = ids_[k_];                                                     \
            call;                                                                          \
        }                                                                                  \
    } while (0)

/* Polyline/polymarker/fill area items: n then n points of dim reals. */
static void i_points(interp *ip, int dim, void (*fn)(const Gpoint_list3 *), long min)
{
    long n = d_count(&ip->d, min, (size_t)dim, 'r');
    if (n < 0)
        return;
    Gpoint3 *p = d_points(&ip->d, n, dim);
    if (p && !ip->d.err && gksm_cur_left(&ip->d.c) == 0) {
        Gpoint_list3 l = { (Gint)n, p };
        WITH_XF(ip, 1, fn(&l));
    } else if (!ip->d.err) {
        ip->d.err = 165;
    }
    gks_free(p);
}

static void i_fill_area_set(interp *ip)
{
    dec *d = &ip->d;
    long nl = d_count(d, 1, 1, 'i');
    if (nl < 0)
        return;
    Gpoint_list3 *lists = gks_calloc_array((size_t)nl, sizeof *lists);
    if (!lists) {
        d->err = 300;
        return;
    }
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
        WITH_XF(ip, 1, gfill_area_set3(&ll));
    }
    gks_free(p);
    gks_free(lists);
}

/* A primitive with data: its packed form (gks_area_data.h), the header's counts checked
 * against what is left of the record before anything is allocated. */
static void i_data(interp *ip, int type)
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
    int *ints = gks_alloc_array(ni, sizeof *ints);
    double (*tri)[3] = gks_alloc_array(nt ? nt : 1, sizeof *tri);
    if (!ints || !tri)
        d->err = 300;
    for (size_t k = 0; !d->err && k < ni; k++)
        ints[k] = k < GKS_AREA_DATA_HEADER ? hdr[k] : d_int(d);
    for (size_t i = 0; !d->err && i < nt; i++)
        d_reals(d, tri[i], 3);
    if (!d->err && gksm_cur_left(&d->c) != 0)
        d->err = 165;
    gks_area_data a;
    if (!d->err && gks_area_data_unpack(ints, ni, (const double (*)[3])tri, nt, &a))
        d->err = 165;
    if (!d->err)
        WITH_XF(ip, 1, gks_area_data_perform(type, &a));
    gks_free(ints);
    gks_free(tri);
}

static void i_text(interp *ip, int three)
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
        WITH_XF(ip, 0, gtext3(&pos, dir, s));
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
    Gint *colr = gks_alloc_array(n, sizeof *colr);
    if (!colr) {
        d->err = 300;
        return NULL;
    }
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

static void i_cell_array(interp *ip, int dim)
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
    WITH_XF(ip, 1, gcell_array3(&par, &ca));
    gks_free(colr);
}

static void i_pat_rep(interp *ip)
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

static void i_light_state(interp *ip)
{
    dec *d = &ip->d;
    long n = d_count(d, 0, 1, 'i');
    if (n < 0)
        return;
    if (n > GKS_MAX_LIGHT_IND) {
        d->err = 165;
        return;
    }
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

static void i_message(interp *ip)
{
    char *s = d_str(&ip->d);
    if (!ip->d.err && gksm_cur_left(&ip->d.c) != 0)
        ip->d.err = 165;
    if (!ip->d.err)
        EACH_WS(gmessage(ws_, s));
    gks_free(s);
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
        return 0;
    default: /* file names, threads, progress, statistics, and anything newer */
        return 180;
    }
}

/* ESCAPE: function identification, integers (the first, the workstation identifier, is
 * replaced by each active workstation's), reals, string. */
static void i_escape(interp *ip)
{
    dec *d = &ip->d;
    int func = d_int(d);
    long ni = d_count(d, 1, 1, 'i');
    Gint *ints = NULL;
    Gfloat *reals = NULL;
    if (ni < 0)
        return;
    ints = gks_alloc_array((size_t)ni, sizeof *ints);
    if (!ints) {
        d->err = 300;
        return;
    }
    for (long i = 0; i < ni; i++)
        ints[i] = d_int(d);
    long nr = d_count(d, 0, 1, 'r');
    if (nr >= 0) {
        reals = gks_alloc_array((size_t)(nr > 0 ? nr : 1), sizeof *reals);
        if (!reals)
            d->err = 300;
    }
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

/* Items whose data record is a fixed list of fields: decoded into iv/rv by `fmt` (i, r),
 * complete and nothing left over, then performed. */
#define FIXED_MAX_INTS 8   /* the most integers of a fixed item (VIEW REPRESENTATION 3: 4) */
#define FIXED_MAX_REALS 48 /* the most reals (VIEW REPRESENTATION 3: 38) */
static int fixed(interp *ip, const char *fmt, int iv[FIXED_MAX_INTS], double rv[FIXED_MAX_REALS])
{
    int ni = 0, nr = 0;
    for (const char *f = fmt; *f; f++) {
        if (*f == 'i' ? ni == FIXED_MAX_INTS : nr == FIXED_MAX_REALS) {
            ip->d.err = 165; /* a format beyond the arrays: never written past them */
            return 0;
        }
        if (*f == 'i')
            iv[ni++] = d_int(&ip->d);
        else
            rv[nr++] = d_real(&ip->d);
    }
    if (!ip->d.err && gksm_cur_left(&ip->d.c) != 0)
        ip->d.err = 165;
    return ip->d.err == 0;
}

static Gasf asf_of(int v) { return (Gasf)v; }

static void i_asf(interp *ip)
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

/* Performs item `type`; returns 0, 164 (no such GKS item) or the decoding error. */
static int perform(interp *ip, int type)
{
    int iv[FIXED_MAX_INTS] = { 0 };
    double rv[FIXED_MAX_REALS] = { 0 };
    switch (type) {
    case GKSM_ITEM_END:
        break;
    case GKSM_ITEM_ESCAPE:
        i_escape(ip);
        break;
    case GKSM_ITEM_CLEAR:
        if (fixed(ip, "i", iv, rv))
            EACH_WS(gclear_ws(ws_, (Gctrl_flag)iv[0]));
        break;
    case GKSM_ITEM_REDRAW:
        if (fixed(ip, "", iv, rv))
            EACH_WS(gredraw_all_seg_ws(ws_));
        break;
    case GKSM_ITEM_UPDATE:
        if (fixed(ip, "i", iv, rv))
            EACH_WS(gupd_ws(ws_, (Gupd_regen_flag)iv[0]));
        break;
    case GKSM_ITEM_DEFER:
        if (fixed(ip, "ii", iv, rv))
            EACH_WS(gset_defer_st(ws_, (Gdefer_mode)iv[0], (Girg_mode)iv[1]));
        break;
    case GKSM_ITEM_MESSAGE:
        i_message(ip);
        break;
    case GKSM_ITEM_TEXT3:
        i_text(ip, 1);
        break;
    case GKSM_ITEM_TEXT:
        i_text(ip, 0);
        break;
    case GKSM_ITEM_CELL_ARRAY3:
        i_cell_array(ip, 3);
        break;
    case GKSM_ITEM_CELL_ARRAY:
        i_cell_array(ip, 2);
        break;
    case GKSM_ITEM_FILL_AREA_SET3:
        i_fill_area_set(ip);
        break;
    case GKSM_ITEM_FILL_AREA3_DATA:
    case GKSM_ITEM_FILL_AREA_SET3_DATA:
    case GKSM_ITEM_TRI_STRIP3_DATA:
    case GKSM_ITEM_QUAD_MESH3_DATA:
    case GKSM_ITEM_SOFAS3_DATA:
        i_data(ip, type);
        break;
    case GKSM_ITEM_INT_SHAD:
        if (fixed(ip, "ii", iv, rv)) {
            if (iv[0] == 0)
                gset_int_shad_meth(iv[1]);
            else if (iv[0] == 1)
                gset_back_int_shad_meth(iv[1]);
            else
                return 165;
        }
        break;
    case GKSM_ITEM_POLYLINE:
        i_points(ip, 2, gpolyline3, 2);
        break;
    case GKSM_ITEM_POLYMARKER:
        i_points(ip, 2, gpolymarker3, 1);
        break;
    case GKSM_ITEM_FILL_AREA:
        i_points(ip, 2, gfill_area3, 3);
        break;
    case GKSM_ITEM_POLYLINE3:
        i_points(ip, 3, gpolyline3, 2);
        break;
    case GKSM_ITEM_POLYMARKER3:
        i_points(ip, 3, gpolymarker3, 1);
        break;
    case GKSM_ITEM_FILL_AREA3:
        i_points(ip, 3, gfill_area3, 3);
        break;
    case GKSM_ITEM_GDP: /* no GDP exists here: GDP identifier invalid (102) */
        iv[0] = d_int(&ip->d);
        if (!ip->d.err) {
            Gpoint_list3 none = { 0, NULL };
            WITH_XF(ip, 1, ggdp3(&none, iv[0], NULL));
        }
        break;
    case GKSM_ITEM_LINE_IND: if (fixed(ip, "i", iv, rv)) gset_line_ind(iv[0]); break;
    case GKSM_ITEM_LINETYPE: if (fixed(ip, "i", iv, rv)) gset_linetype(iv[0]); break;
    case GKSM_ITEM_LINEWIDTH: if (fixed(ip, "r", iv, rv)) gset_linewidth(rv[0]); break;
    case GKSM_ITEM_LINE_COLR: if (fixed(ip, "i", iv, rv)) gset_line_colr_ind(iv[0]); break;
    case GKSM_ITEM_MARKER_IND: if (fixed(ip, "i", iv, rv)) gset_marker_ind(iv[0]); break;
    case GKSM_ITEM_MARKER_TYPE: if (fixed(ip, "i", iv, rv)) gset_marker_type(iv[0]); break;
    case GKSM_ITEM_MARKER_SIZE: if (fixed(ip, "r", iv, rv)) gset_marker_size(rv[0]); break;
    case GKSM_ITEM_MARKER_COLR: if (fixed(ip, "i", iv, rv)) gset_marker_colr_ind(iv[0]); break;
    case GKSM_ITEM_TEXT_IND: if (fixed(ip, "i", iv, rv)) gset_text_ind(iv[0]); break;
    case GKSM_ITEM_TEXT_FONT_PREC:
        if (fixed(ip, "ii", iv, rv))
            gset_text_font_prec(&(Gtext_font_prec){ iv[0], (Gtext_prec)iv[1] });
        break;
    case GKSM_ITEM_CHAR_EXPAN: if (fixed(ip, "r", iv, rv)) gset_char_expan(rv[0]); break;
    case GKSM_ITEM_CHAR_SPACE: if (fixed(ip, "r", iv, rv)) gset_char_space(rv[0]); break;
    case GKSM_ITEM_TEXT_COLR: if (fixed(ip, "i", iv, rv)) gset_text_colr_ind(iv[0]); break;
    case GKSM_ITEM_CHAR_VECS: /* RAL: height and width vectors (NDC) */
        if (fixed(ip, "rrrr", iv, rv)) {
            gset_char_ht(hypot(rv[0], rv[1]));
            gset_char_up_vec(&(Gvec){ rv[0], rv[1] });
        }
        break;
    case GKSM_ITEM_TEXT_PATH: if (fixed(ip, "i", iv, rv)) gset_text_path((Gtext_path)iv[0]); break;
    case GKSM_ITEM_TEXT_ALIGN:
        if (fixed(ip, "ii", iv, rv))
            gset_text_align(&(Gtext_align){ (Ghor_text_align)iv[0], (Gvert_text_align)iv[1] });
        break;
    case GKSM_ITEM_FILL_IND: if (fixed(ip, "i", iv, rv)) gset_fill_ind(iv[0]); break;
    case GKSM_ITEM_INT_STYLE:
        if (fixed(ip, "i", iv, rv))
            gset_fill_int_style((Gfill_int_style)iv[0]);
        break;
    case GKSM_ITEM_STYLE_IND: if (fixed(ip, "i", iv, rv)) gset_fill_style_ind(iv[0]); break;
    case GKSM_ITEM_FILL_COLR: if (fixed(ip, "i", iv, rv)) gset_fill_colr_ind(iv[0]); break;
    case GKSM_ITEM_PAT_SIZE_NDC: /* RAL: width and height vectors */
        if (fixed(ip, "rrrr", iv, rv))
            gset_pat_size(hypot(rv[0], rv[1]), hypot(rv[2], rv[3]));
        break;
    case GKSM_ITEM_PAT_REF_NDC:
        if (fixed(ip, "rr", iv, rv))
            gset_pat_ref_point(&(Gpoint){ rv[0], rv[1] });
        break;
    case GKSM_ITEM_ASF:
        i_asf(ip);
        break;
    case GKSM_ITEM_PICK_ID: if (fixed(ip, "i", iv, rv)) gset_pick_id(iv[0]); break;
    case GKSM_ITEM_PAT_REF_VECS:
        if (fixed(ip, "rrrrrrrrr", iv, rv)) {
            Gvec3 v[2] = { { rv[3], rv[4], rv[5] }, { rv[6], rv[7], rv[8] } };
            gset_pat_ref_point_vecs(&(Gpoint3){ rv[0], rv[1], rv[2] }, v);
        }
        break;
    case GKSM_ITEM_EDGE_FLAG: if (fixed(ip, "i", iv, rv)) gset_edge_flag((Gedge_flag)iv[0]); break;
    case GKSM_ITEM_EDGETYPE: if (fixed(ip, "i", iv, rv)) gset_edgetype(iv[0]); break;
    case GKSM_ITEM_EDGEWIDTH: if (fixed(ip, "r", iv, rv)) gset_edgewidth(rv[0]); break;
    case GKSM_ITEM_EDGE_COLR: if (fixed(ip, "i", iv, rv)) gset_edge_colr_ind(iv[0]); break;
    case GKSM_ITEM_EDGE_IND: if (fixed(ip, "i", iv, rv)) gset_edge_ind(iv[0]); break;
    case GKSM_ITEM_LINE_REP:
        if (fixed(ip, "iiri", iv, rv))
            EACH_WS(gset_line_rep(ws_, iv[0], &(Gline_bundle){ iv[1], rv[0], iv[2] }));
        break;
    case GKSM_ITEM_MARKER_REP:
        if (fixed(ip, "iiri", iv, rv))
            EACH_WS(gset_marker_rep(ws_, iv[0], &(Gmarker_bundle){ iv[1], rv[0], iv[2] }));
        break;
    case GKSM_ITEM_TEXT_REP:
        if (fixed(ip, "iiirri", iv, rv)) {
            Gtext_bundle b = { { iv[1], (Gtext_prec)iv[2] }, rv[0], rv[1], iv[3] };
            EACH_WS(gset_text_rep(ws_, iv[0], &b));
        }
        break;
    case GKSM_ITEM_FILL_REP:
        if (fixed(ip, "iiii", iv, rv)) {
            Gfill_bundle b = { (Gfill_int_style)iv[1], iv[2], iv[3] };
            EACH_WS(gset_fill_rep(ws_, iv[0], &b));
        }
        break;
    case GKSM_ITEM_PAT_REP:
        i_pat_rep(ip);
        break;
    case GKSM_ITEM_COLR_REP:
        if (fixed(ip, "irrr", iv, rv)) {
            Gcolr_rep c = { { rv[0], rv[1], rv[2] } };
            EACH_WS(gset_colr_rep(ws_, iv[0], &c));
        }
        break;
    case GKSM_ITEM_EDGE_REP:
        if (fixed(ip, "iiiri", iv, rv)) {
            Gedge_bundle b = { (Gedge_flag)iv[1], iv[2], rv[0], iv[3] };
            EACH_WS(gset_edge_rep(ws_, iv[0], &b));
        }
        break;
    case GKSM_ITEM_VIEW_REP3: {
        char fmt[43]; /* index, 16 + 16 + 6 reals, three clipping indicators */
        fmt[0] = 'i';
        memset(fmt + 1, 'r', 38);
        memcpy(fmt + 39, "iii", 4);
        if (fixed(ip, fmt, iv, rv)) {
            Gview_rep3 r;
            memcpy(r.ori_matrix, rv, sizeof r.ori_matrix);
            memcpy(r.map_matrix, rv + 16, sizeof r.map_matrix);
            r.clip_limit = (Glimit3){ rv[32], rv[33], rv[34], rv[35], rv[36], rv[37] };
            r.xy_clip = (Gclip_ind)iv[1];
            r.back_clip = (Gclip_ind)iv[2];
            r.front_clip = (Gclip_ind)iv[3];
            EACH_WS(gset_view_rep3(ws_, iv[0], &r));
        }
        break;
    }
    case GKSM_ITEM_CHAR_HT: if (fixed(ip, "r", iv, rv)) gset_char_ht(rv[0]); break;
    case GKSM_ITEM_CHAR_UP:
        if (fixed(ip, "rr", iv, rv))
            gset_char_up_vec(&(Gvec){ rv[0], rv[1] });
        break;
    case GKSM_ITEM_CLIP_RECT: /* RAL: the clipping rectangle (0,1,0,1 when off) */
        if (fixed(ip, "rrrr", iv, rv)) {
            const double b[6] = { rv[0], rv[1], rv[2], rv[3], 0, 1 };
            memcpy(ip->xf->box, b, sizeof b);
            ip->xf->clip_on = 1;
        }
        break;
    case GKSM_ITEM_NORM:
        if (fixed(ip, "rrrrrrrrrrrr", iv, rv))
            memcpy(ip->xf->norm, rv, sizeof ip->xf->norm);
        break;
    case GKSM_ITEM_PAT_SIZE:
        if (fixed(ip, "rr", iv, rv))
            gset_pat_size(rv[0], rv[1]);
        break;
    case GKSM_ITEM_CLIP_VOL3:
        if (fixed(ip, "irrrrrr", iv, rv)) {
            if (iv[0] != 0 && iv[0] != 1)
                return 165;
            ip->xf->clip_on = iv[0];
            memcpy(ip->xf->box, rv, sizeof ip->xf->box);
        }
        break;
    case GKSM_ITEM_VIEW_IND: if (fixed(ip, "i", iv, rv)) gset_view_ind(iv[0]); break;
    case GKSM_ITEM_HLHSR_ID: if (fixed(ip, "i", iv, rv)) gset_hlhsr_id(iv[0]); break;
    case GKSM_ITEM_HLHSR_MODE:
        if (fixed(ip, "i", iv, rv))
            EACH_WS(gset_hlhsr_mode(ws_, iv[0]));
        break;
    case GKSM_ITEM_AREA_PROPS:
        if (fixed(ip, "irrrrrrrrr", iv, rv)) {
            Garea_props p = { rv[0], rv[1], rv[2], { rv[3], rv[4], rv[5] }, rv[6], rv[7], rv[8] };
            if (iv[0] == 0)
                gset_area_props(&p);
            else if (iv[0] == 1)
                gset_back_area_props(&p);
            else
                return 165;
        }
        break;
    case GKSM_ITEM_REFL_EQ:
        if (fixed(ip, "ii", iv, rv)) {
            if (iv[0] == 0)
                gset_refl_eq(iv[1]);
            else if (iv[0] == 1)
                gset_back_refl_eq(iv[1]);
            else
                return 165;
        }
        break;
    case GKSM_ITEM_LIGHT_STATE:
        i_light_state(ip);
        break;
    case GKSM_ITEM_WS_WIN:
        if (fixed(ip, "rrrr", iv, rv))
            EACH_WS(gset_ws_win(ws_, &(Glimit){ rv[0], rv[1], rv[2], rv[3] }));
        break;
    case GKSM_ITEM_WS_VP:
        if (fixed(ip, "rrrr", iv, rv))
            EACH_WS(gset_ws_vp(ws_, &(Glimit){ rv[0], rv[1], rv[2], rv[3] }));
        break;
    case GKSM_ITEM_WS_WIN3:
        if (fixed(ip, "rrrrrr", iv, rv))
            EACH_WS(gset_ws_win3(ws_, &(Glimit3){ rv[0], rv[1], rv[2], rv[3], rv[4], rv[5] }));
        break;
    case GKSM_ITEM_WS_VP3:
        if (fixed(ip, "rrrrrr", iv, rv))
            EACH_WS(gset_ws_vp3(ws_, &(Glimit3){ rv[0], rv[1], rv[2], rv[3], rv[4], rv[5] }));
        break;
    case GKSM_ITEM_LIGHT_REP:
        if (fixed(ip, "iirrrrrrrrrrrrr", iv, rv)) {
            Glight_src_rep r = { iv[1], { rv[0], rv[1], rv[2] }, { rv[3], rv[4], rv[5] },
                                 { rv[6], rv[7], rv[8] }, { rv[9], rv[10] }, rv[11], rv[12] };
            EACH_WS(gset_light_src_rep(ws_, iv[0], &r));
        }
        break;
    case GKSM_ITEM_CREATE_SEG: if (fixed(ip, "i", iv, rv)) gcreate_seg(iv[0]); break;
    case GKSM_ITEM_CLOSE_SEG: if (fixed(ip, "", iv, rv)) gclose_seg(); break;
    case GKSM_ITEM_RENAME_SEG: if (fixed(ip, "ii", iv, rv)) grename_seg(iv[0], iv[1]); break;
    case GKSM_ITEM_DEL_SEG: if (fixed(ip, "i", iv, rv)) gdel_seg(iv[0]); break;
    case GKSM_ITEM_SEG_TRAN3:
        if (fixed(ip, "irrrrrrrrrrrr", iv, rv)) {
            Gtran_matrix3 m;
            memcpy(m, rv, sizeof m);
            gset_seg_tran3(iv[0], (const Gfloat (*)[4])m);
        }
        break;
    case GKSM_ITEM_SEG_TRAN:
        if (fixed(ip, "irrrrrr", iv, rv)) {
            Gtran_matrix m;
            memcpy(m, rv, sizeof m);
            gset_seg_tran(iv[0], (const Gfloat (*)[3])m);
        }
        break;
    case GKSM_ITEM_VIS: if (fixed(ip, "ii", iv, rv)) gset_vis(iv[0], (Gseg_vis)iv[1]); break;
    case GKSM_ITEM_HIGHL:
        if (fixed(ip, "ii", iv, rv))
            gset_highl(iv[0], (Gseg_highl)iv[1]);
        break;
    case GKSM_ITEM_SEG_PRI: if (fixed(ip, "ir", iv, rv)) gset_seg_pri(iv[0], rv[0]); break;
    case GKSM_ITEM_DET: if (fixed(ip, "ii", iv, rv)) gset_det(iv[0], (Gseg_det)iv[1]); break;
    default:
        return 164;
    }
    return ip->d.err;
}

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
    /* The record's field format and the interpretation state: those of the MI the last
     * item was read from; this writer's format and a fresh state otherwise. */
    gks_state_list *sl = gks_ctx()->sl;
    gks_ws *mi = sl->mf_last_mi > 0 ? gks_ws_lookup(sl->mf_last_mi - 1) : NULL;
    gks_mf_in *m = mi && mi->drv->desc->cat == GCAT_MI ? mi->priv : NULL;
    gksm_in fmt = { .iw = 11, .rw = 24, .ri = 1, .zero = 0, .one = 1 };
    gks_norm_override local;
    xf_default(&local);
    interp ip = { .xf = m ? &m->xf : &local, .allow_escapes = m ? m->allow_escapes : 0 };
    gksm_cur_init(&ip.d.c, m ? &m->in : &fmt, data ? data : "", (size_t)length);
    int err = perform(&ip, type);
    if (err)
        GKS_FAIL(err, GFN_IITM);
}
