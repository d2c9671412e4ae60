/* SPDX-License-Identifier: MIT */
/*
 * gks_output_data.c -- the PHIGS PLUS primitives with data added to GKS-3D (FILL AREA 3
 * WITH DATA, ...) and SET (BACK) INTERIOR SHADING METHOD with its inquiry.
 *
 * Every primitive with data is first put into one canonical form (gks_area_data): shared
 * vertices (points, optional normals and colours) and facets made of loops of vertex
 * indices, each facet with an optional colour and normal. Then one pipeline: points
 * through the normalization (and segment) transformation, normals through its inverse
 * transpose, renormalised; each facet clipped at the viewport 3 (when clipping is on) with
 * its vertex normals and colours interpolated at new vertices; per workstation the colours
 * resolved (indices through the colour table) and the facet sent to the driver as one
 * GKS_PRIM_FILL_AREA with data (ws_driver.h). A facet with a non-finite point or normal is
 * not drawn (as FILL AREA 3 with a non-finite point).
 */
#include "gks_alloc.h"
#include "gks_attr.h"
#include "gks_error.h"
#include "gks_export.h"
#include "gks_output_data.h"
#include "gks_output_int.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

/* ------------------------------------------------------------------ checks */
static int unit_ok(double v) { return isfinite(v) && v >= 0 && v <= 1; }

static int rgb_ok(const Grgb *c) { return unit_ok(c->red) && unit_ok(c->green) && unit_ok(c->blue); }

/* Checks the colours of n values of colour type ctype: 0, 92 or 96. */
static int colrs_ok(int ctype, const Gcoval *c, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        if (ctype == GCOLR_INDIRECT && c[i].ind < 0)
            return 92;
        if (ctype == GCOLR_RGB && !rgb_ok(&c[i].rgb))
            return 96;
    }
    return 0;
}

int gks_area_data_check(const gks_area_data *d)
{
    if (d->fflag < GFACET_NONE || d->fflag > GFACET_COLR_NORM || d->vflag < GVERT_COORD ||
        d->vflag > GVERT_COORD_COLR_NORM || d->ctype < GCOLR_INDIRECT || d->ctype > GCOLR_RGB)
        return 2000;
    if (d->n_facets < 1 || d->n_verts < 3 || d->n_verts > INT32_MAX || d->n_facets > INT32_MAX ||
        d->n_loops > INT32_MAX || d->n_idx > INT32_MAX)
        return 100;
    if (!d->pts || !d->facet_loops || !d->loop_counts || !d->idx)
        return 2003;
    int vc = d->vflag & GVERT_COORD_COLR, vn = d->vflag & GVERT_COORD_NORM;
    int fc = d->fflag & GFACET_COLR, fn = d->fflag & GFACET_NORM;
    if ((vc && (d->ctype == GCOLR_RGB ? !d->vrgb : !d->vci)) || (vn && !d->vnorm) ||
        (fc && (d->ctype == GCOLR_RGB ? !d->frgb : !d->fci)) || (fn && !d->fnorm))
        return 2003;
    size_t loops = 0, nidx = 0;
    for (size_t f = 0; f < d->n_facets; f++) {
        if (d->facet_loops[f] < 1 || (size_t)d->facet_loops[f] > d->n_loops - loops)
            return 100;
        for (int k = 0; k < d->facet_loops[f]; k++) {
            int c = d->loop_counts[loops + (size_t)k];
            if (c < 3 || (size_t)c > d->n_idx - nidx)
                return 100;
            nidx += (size_t)c;
        }
        loops += (size_t)d->facet_loops[f];
    }
    if (loops != d->n_loops || nidx != d->n_idx)
        return 100;
    for (size_t i = 0; i < d->n_idx; i++)
        if (d->idx[i] < 0 || (size_t)d->idx[i] >= d->n_verts)
            return 904;
    for (size_t i = 0; i < d->n_verts; i++) {
        if (vc && d->ctype == GCOLR_INDIRECT && d->vci[i] < 0)
            return 92;
        if (vc && d->ctype == GCOLR_RGB &&
            !rgb_ok(&(Grgb){ d->vrgb[i][0], d->vrgb[i][1], d->vrgb[i][2] }))
            return 96;
    }
    for (size_t f = 0; f < d->n_facets; f++) {
        if (fc && d->ctype == GCOLR_INDIRECT && d->fci[f] < 0)
            return 92;
        if (fc && d->ctype == GCOLR_RGB &&
            !rgb_ok(&(Grgb){ d->frgb[f][0], d->frgb[f][1], d->frgb[f][2] }))
            return 96;
    }
    return 0;
}

/* ------------------------------------------------------------------ transformation */
/* The inverse transpose of m's linear part (normals), scaled by its largest element;
 * 0, or -1 when singular or not finite. */
static int normal_matrix(const double m[3][4], double nm[3][3])
{
    double c[3][3]; /* cofactors: inverse transpose = cofactor matrix / det */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    double det = m[0][0] * c[0][0] + m[0][1] * c[0][1] + m[0][2] * c[0][2];
    if (!isfinite(det) || det == 0.0)
        return -1;
    double s = det > 0 ? 1.0 : -1.0; /* the sign keeps orientation: n maps like p x q */
    double mx = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            mx = fmax(mx, fabs(c[i][j]));
    if (!(mx > 0.0) || !isfinite(mx))
        return -1;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            nm[i][j] = s * c[i][j] / mx;
    return 0;
}

/* nm * v normalised into o; 1 if the result is a finite unit vector. */
static int map_normal(const double nm[3][3], const double v[3], double o[3])
{
    double r[3], len = 0.0;
    for (int i = 0; i < 3; i++) {
        r[i] = nm[i][0] * v[0] + nm[i][1] * v[1] + nm[i][2] * v[2];
        if (!isfinite(r[i]))
            return 0;
    }
    double mx = fmax(fabs(r[0]), fmax(fabs(r[1]), fabs(r[2])));
    if (!(mx > 0.0))
        return 0;
    for (int i = 0; i < 3; i++) {
        r[i] /= mx; /* no overflow in the squares */
        len += r[i] * r[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++)
        o[i] = r[i] / len;
    return 1;
}

/* ------------------------------------------------------------------ clipping */
/* A vertex while clipping: point, normal, colour. */
typedef struct { double p[3], n[3], c[3]; } cvert;

typedef struct {
    cvert *v;
    size_t n, cap;
} cbuf;

static int cbuf_push(cbuf *b, const cvert *v)
{
    if (b->n == b->cap) {
        size_t cap = b->cap ? 2 * b->cap : 64;
        cvert *a = gks_realloc_array(b->v, cap, sizeof *a);
        if (!a)
            return 300;
        b->v = a;
        b->cap = cap;
    }
    b->v[b->n++] = *v;
    return 0;
}

/* One Sutherland-Hodgman pass of the loop in[0..n-1] against axis/side of box into out;
 * normals and colours interpolated linearly at new vertices (normals renormalised). */
static int clip_pass(const cvert *in, size_t n, int axis, int side, const double box[6],
                     cbuf *out)
{
    double lim = box[2 * axis + side], sg = side ? -1.0 : 1.0;
    out->n = 0;
    for (size_t i = 0; i < n; i++) {
        const cvert *a = &in[i], *b = &in[(i + 1) % n];
        double da = sg * (a->p[axis] - lim), db = sg * (b->p[axis] - lim);
        int err = 0;
        if (da >= 0)
            err = cbuf_push(out, a);
        if (!err && ((da >= 0) != (db >= 0))) {
            double t = da / (da - db);
            cvert r;
            for (int k = 0; k < 3; k++) {
                r.p[k] = a->p[k] + t * (b->p[k] - a->p[k]);
                r.n[k] = a->n[k] + t * (b->n[k] - a->n[k]);
                r.c[k] = a->c[k] + t * (b->c[k] - a->c[k]);
            }
            r.p[axis] = lim;
            double len = sqrt(r.n[0] * r.n[0] + r.n[1] * r.n[1] + r.n[2] * r.n[2]);
            if (len > 0 && isfinite(len))
                for (int k = 0; k < 3; k++)
                    r.n[k] /= len;
            else
                r.n[0] = r.n[1] = r.n[2] = 0.0; /* opposite normals: none (see send) */
            for (int k = 0; k < 3; k++)
                r.c[k] = fmin(1.0, fmax(0.0, r.c[k]));
            err = cbuf_push(out, &r);
        }
        if (err)
            return err;
    }
    return 0;
}

/* Clips the loop v[0..n-1] at box; the result in *res (res->n < 3: nothing left). */
static int clip_loop(const cvert *v, size_t n, const double box[6], cbuf *res, cbuf *tmp)
{
    res->n = 0;
    for (size_t i = 0; i < n; i++)
        if (cbuf_push(res, &v[i]))
            return 300;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            int err = clip_pass(res->v, res->n, axis, side, box, tmp);
            if (err)
                return err;
            cbuf t = *res;
            *res = *tmp;
            *tmp = t;
            if (res->n < 3) {
                res->n = 0;
                return 0;
            }
        }
    return 0;
}

/* ------------------------------------------------------------------ emission */
/* The primitive's vertices in final NDC3, valid flags per vertex. */
typedef struct {
    const gks_area_data *d;
    double (*p)[3];            /* points */
    double (*n)[3];            /* vertex normals (unit) or NULL */
    double (*fn)[3];           /* facet normals (unit) or NULL */
    unsigned char *pok, *nok, *fnok;
    int is_set;
} mapped;

/* The colour of colour value k of a list for ws. */
static Grgb colr_of(const gks_ws *ws, int ctype, const double (*rgb)[3], const int *ci, size_t k)
{
    if (ctype == GCOLR_RGB)
        return (Grgb){ rgb[k][0], rgb[k][1], rgb[k][2] };
    return gks_attr_colour(ws, ci[k]);
}

/* Scratch space of one facet for one workstation. */
typedef struct {
    cvert *v;                  /* the facet's vertices, loop after loop */
    size_t cap;
    cbuf res, tmp;
    Gpoint3 *pts;
    Gvec3 *vn;
    Grgb *vc;
    int *counts;
    size_t cap_out, cap_counts;
} facet_buf;

static void facet_buf_free(facet_buf *b)
{
    gks_free(b->v);
    gks_free(b->res.v);
    gks_free(b->tmp.v);
    gks_free(b->pts);
    gks_free(b->vn);
    gks_free(b->vc);
    gks_free(b->counts);
    memset(b, 0, sizeof *b);
}

static int grow(void **a, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *n = gks_realloc_array(*a, c, size);
    if (!n)
        return 300;
    *a = n;
    *cap = c;
    return 0;
}

/* Output arrays for m vertices and nl loops. */
static int out_reserve(facet_buf *b, size_t m, size_t nl)
{
    size_t c1 = b->cap_out, c2 = b->cap_out, c3 = b->cap_out;
    if (grow((void **)&b->pts, &c1, m, sizeof *b->pts) ||
        grow((void **)&b->vn, &c2, m, sizeof *b->vn) ||
        grow((void **)&b->vc, &c3, m, sizeof *b->vc))
        return 300;
    if (c1 > b->cap_out) /* all three grew to the same capacity */
        b->cap_out = c1;
    return grow((void **)&b->counts, &b->cap_counts, nl, sizeof *b->counts);
}

/* Sends facet f (loops from loop0, indices from idx0) to ws. */
static int send_facet(gks_ws *ws, target *t, const norm_ctx *nc, const mapped *mp, size_t f,
                      size_t loop0, size_t idx0, facet_buf *b)
{
    const gks_area_data *d = mp->d;
    size_t nl = (size_t)d->facet_loops[f], nv = 0;
    for (size_t k = 0; k < nl; k++)
        nv += (size_t)d->loop_counts[loop0 + k];
    int use_n = mp->n != NULL, use_c = (d->vflag & GVERT_COORD_COLR) != 0, inside = 1;
    if (grow((void **)&b->v, &b->cap, nv, sizeof *b->v))
        return 300;
    for (size_t i = 0; i < nv; i++) {
        size_t j = (size_t)d->idx[idx0 + i];
        if (!mp->pok[j])
            return 0; /* a non-finite point: the facet is not drawn */
        cvert *v = &b->v[i];
        memcpy(v->p, mp->p[j], sizeof v->p);
        if (use_n && !mp->nok[j])
            use_n = 0; /* a degenerate normal: the facet has no vertex normals */
        if (use_n)
            memcpy(v->n, mp->n[j], sizeof v->n);
        else
            v->n[0] = v->n[1] = v->n[2] = 0.0;
        if (use_c) {
            Grgb c = colr_of(ws, d->ctype, d->vrgb, d->vci, j);
            v->c[0] = c.red; v->c[1] = c.green; v->c[2] = c.blue;
        } else {
            v->c[0] = v->c[1] = v->c[2] = 0.0;
        }
        if (nc->clip_on)
            for (int k = 0; k < 3; k++)
                inside = inside && v->p[k] >= nc->box[2 * k] && v->p[k] <= nc->box[2 * k + 1];
    }
    /* The facet's loops, clipped when not inside. */
    size_t m = 0, off = 0, nlo = 0;
    if (out_reserve(b, nv, nl))
        return 300;
    for (size_t k = 0; k < nl; k++) {
        size_t c = (size_t)d->loop_counts[loop0 + k];
        const cvert *lv = b->v + off;
        size_t lc = c;
        off += c;
        if (!inside) {
            int err = clip_loop(lv, c, nc->box, &b->res, &b->tmp);
            if (err)
                return err;
            lv = b->res.v;
            lc = b->res.n;
            if (lc < 3)
                continue;
        }
        if (lc > INT32_MAX || out_reserve(b, m + lc, nl))
            return 300;
        for (size_t i = 0; i < lc; i++) {
            const cvert *v = &lv[i];
            b->pts[m + i] = (Gpoint3){ v->p[0], v->p[1], v->p[2] };
            b->vn[m + i] = (Gvec3){ v->n[0], v->n[1], v->n[2] };
            if (use_n && v->n[0] == 0.0 && v->n[1] == 0.0 && v->n[2] == 0.0)
                use_n = 0; /* interpolated between opposite normals */
            b->vc[m + i] = (Grgb){ v->c[0], v->c[1], v->c[2] };
        }
        b->counts[nlo++] = (int)lc;
        m += lc;
    }
    if (nlo == 0 || m > INT32_MAX)
        return 0;
    gks_prim p = { .kind = GKS_PRIM_FILL_AREA, .n_loops = (int)nlo, .loop_counts = b->counts,
                   .n_points = (int)m, .pts = b->pts };
    Grgb *pat = NULL;
    gks_out_prim_common(&p, t->a);
    int err = gks_attr_prim_fill(ws, t->a, (const double (*)[4])t->pat_m, &p, &pat);
    if (!mp->is_set)
        p.attrs.edge_flag = 0; /* GKS-3D edges belong to the area sets */
    if (d->fflag & GFACET_COLR)
        p.colour = colr_of(ws, d->ctype, d->frgb, d->fci, f);
    if (mp->fn && mp->fnok[f]) {
        p.has_fnormal = 1;
        p.fnormal = (Gvec3){ mp->fn[f][0], mp->fn[f][1], mp->fn[f][2] };
    }
    p.vnormals = use_n ? b->vn : NULL;
    p.vcolours = use_c ? b->vc : NULL;
    if (!err)
        err = gks_out_send(ws, &p);
    gks_free(pat);
    return err;
}

/* Maps d's points by nc->m and its normals by the inverse transpose. */
static int map_data(const norm_ctx *nc, const gks_area_data *d, int is_set, mapped *mp)
{
    memset(mp, 0, sizeof *mp);
    mp->d = d;
    mp->is_set = is_set;
    size_t nv = d->n_verts, nf = d->n_facets;
    mp->p = gks_alloc_array(nv, sizeof *mp->p);
    mp->pok = gks_alloc_array(nv, 1);
    if (!mp->p || !mp->pok)
        return 300;
    for (size_t i = 0; i < nv; i++) {
        gks_xform_mat34_point(nc->m, d->pts[i], mp->p[i]);
        mp->pok[i] = isfinite(mp->p[i][0]) && isfinite(mp->p[i][1]) && isfinite(mp->p[i][2]);
    }
    double nm[3][3];
    int nm_ok = normal_matrix(nc->m, nm) == 0;
    if ((d->vflag & GVERT_COORD_NORM) && nm_ok) {
        mp->n = gks_alloc_array(nv, sizeof *mp->n);
        mp->nok = gks_alloc_array(nv, 1);
        if (!mp->n || !mp->nok)
            return 300;
        for (size_t i = 0; i < nv; i++)
            mp->nok[i] = (unsigned char)map_normal(nm, d->vnorm[i], mp->n[i]);
    }
    if ((d->fflag & GFACET_NORM) && nm_ok) {
        mp->fn = gks_alloc_array(nf, sizeof *mp->fn);
        mp->fnok = gks_alloc_array(nf, 1);
        if (!mp->fn || !mp->fnok)
            return 300;
        for (size_t f = 0; f < nf; f++)
            mp->fnok[f] = (unsigned char)map_normal(nm, d->fnorm[f], mp->fn[f]);
    }
    return 0;
}

static void mapped_free(mapped *mp)
{
    gks_free(mp->p);
    gks_free(mp->n);
    gks_free(mp->fn);
    gks_free(mp->pok);
    gks_free(mp->nok);
    gks_free(mp->fnok);
}

int gks_area_data_emit(const norm_ctx *nc, const gks_area_data *d, int is_set, target *t)
{
    mapped mp;
    facet_buf b;
    memset(&b, 0, sizeof b);
    int err = map_data(nc, d, is_set, &mp);
    gks_ws *ws;
    while (!err && (ws = gks_out_next_ws(t))) {
        size_t loop0 = 0, idx0 = 0;
        for (size_t f = 0; f < d->n_facets && !err; f++) {
            err = send_facet(ws, t, nc, &mp, f, loop0, idx0, &b);
            for (int k = 0; k < d->facet_loops[f]; k++)
                idx0 += (size_t)d->loop_counts[loop0 + (size_t)k];
            loop0 += (size_t)d->facet_loops[f];
        }
    }
    mapped_free(&mp);
    facet_buf_free(&b);
    return err;
}

/* ------------------------------------------------------------------ output */
/* Checks d, then draws it (and, in later steps of this file's history, stores it). */
static void output_data(int fctid, const gks_area_data *d, int is_set)
{
    norm_ctx nc;
    if (gks_out_norm_setup(&nc))
        GKS_FAIL(308, fctid);
    target t;
    gks_out_target_current(&t, &nc);
    int err = gks_area_data_emit(&nc, d, is_set, &t);
    if (err)
        GKS_FAIL(err, fctid);
}

/* The vertex arrays of v as double triples (points, normals, colours). */
typedef struct {
    double (*pts)[3], (*vn)[3], (*vrgb)[3], (*fn)[3], (*frgb)[3];
    int *vci, *fci;
} wc_arrays;

static void wc_free(wc_arrays *w)
{
    gks_free(w->pts);
    gks_free(w->vn);
    gks_free(w->vrgb);
    gks_free(w->fn);
    gks_free(w->frgb);
    gks_free(w->vci);
    gks_free(w->fci);
}

/* Checks the flags and vertex record of a call, copies its vertex data into w and d.
 * Returns 0 or an error number. */
static int take_vdata(Gint fflag, Gint vflag, Gint ctype, const Gfacet_vdata3 *v, size_t min_n,
                      wc_arrays *w, gks_area_data *d)
{
    if (fflag < GFACET_NONE || fflag > GFACET_COLR_NORM || vflag < GVERT_COORD ||
        vflag > GVERT_COORD_COLR_NORM || ctype < GCOLR_INDIRECT || ctype > GCOLR_RGB)
        return 2000;
    if (!v)
        return 2003;
    if (v->num_vertices < 0 || (size_t)v->num_vertices < min_n || !v->points)
        return 100;
    size_t n = (size_t)v->num_vertices;
    if (((vflag & GVERT_COORD_COLR) && !v->colrs) || ((vflag & GVERT_COORD_NORM) && !v->norms))
        return 2003;
    if (vflag & GVERT_COORD_COLR) {
        int e = colrs_ok(ctype, v->colrs, n);
        if (e)
            return e;
    }
    d->fflag = fflag;
    d->vflag = vflag;
    d->ctype = ctype;
    d->n_verts = n;
    w->pts = gks_alloc_array(n, sizeof *w->pts);
    if (!w->pts)
        return 300;
    for (size_t i = 0; i < n; i++) {
        w->pts[i][0] = v->points[i].x; w->pts[i][1] = v->points[i].y; w->pts[i][2] = v->points[i].z;
    }
    d->pts = (const double (*)[3])w->pts;
    if (vflag & GVERT_COORD_NORM) {
        if (!(w->vn = gks_alloc_array(n, sizeof *w->vn)))
            return 300;
        for (size_t i = 0; i < n; i++) {
            w->vn[i][0] = v->norms[i].delta_x; w->vn[i][1] = v->norms[i].delta_y;
            w->vn[i][2] = v->norms[i].delta_z;
        }
        d->vnorm = (const double (*)[3])w->vn;
    }
    if ((vflag & GVERT_COORD_COLR) && ctype == GCOLR_RGB) {
        if (!(w->vrgb = gks_alloc_array(n, sizeof *w->vrgb)))
            return 300;
        for (size_t i = 0; i < n; i++) {
            w->vrgb[i][0] = v->colrs[i].rgb.red; w->vrgb[i][1] = v->colrs[i].rgb.green;
            w->vrgb[i][2] = v->colrs[i].rgb.blue;
        }
        d->vrgb = (const double (*)[3])w->vrgb;
    } else if (vflag & GVERT_COORD_COLR) {
        if (!(w->vci = gks_alloc_array(n, sizeof *w->vci)))
            return 300;
        for (size_t i = 0; i < n; i++)
            w->vci[i] = v->colrs[i].ind;
        d->vci = w->vci;
    }
    return 0;
}

/* Checks and copies nf facet records (fdata NULL allowed when fflag is GFACET_NONE). */
static int take_fdata(Gint fflag, Gint ctype, const Gfacet_data3 *fd, size_t nf, wc_arrays *w,
                      gks_area_data *d)
{
    if (fflag == GFACET_NONE)
        return 0;
    if (!fd)
        return 2003;
    for (size_t f = 0; f < nf; f++)
        if (fflag & GFACET_COLR) {
            int e = colrs_ok(ctype, &fd[f].colr, 1);
            if (e)
                return e;
        }
    if (fflag & GFACET_NORM) {
        if (!(w->fn = gks_alloc_array(nf, sizeof *w->fn)))
            return 300;
        for (size_t f = 0; f < nf; f++) {
            w->fn[f][0] = fd[f].norm.delta_x; w->fn[f][1] = fd[f].norm.delta_y;
            w->fn[f][2] = fd[f].norm.delta_z;
        }
        d->fnorm = (const double (*)[3])w->fn;
    }
    if ((fflag & GFACET_COLR) && ctype == GCOLR_RGB) {
        if (!(w->frgb = gks_alloc_array(nf, sizeof *w->frgb)))
            return 300;
        for (size_t f = 0; f < nf; f++) {
            w->frgb[f][0] = fd[f].colr.rgb.red; w->frgb[f][1] = fd[f].colr.rgb.green;
            w->frgb[f][2] = fd[f].colr.rgb.blue;
        }
        d->frgb = (const double (*)[3])w->frgb;
    } else if (fflag & GFACET_COLR) {
        if (!(w->fci = gks_alloc_array(nf, sizeof *w->fci)))
            return 300;
        for (size_t f = 0; f < nf; f++)
            w->fci[f] = fd[f].colr.ind;
        d->fci = w->fci;
    }
    return 0;
}

GKS_API void gfill_area3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_FA3D))
        return;
    wc_arrays w;
    memset(&w, 0, sizeof w);
    gks_area_data d;
    memset(&d, 0, sizeof d);
    int err = take_vdata(fflag, vflag, colr_type, vdata, 3, &w, &d);
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, 1, &w, &d);
    int *ints = NULL;
    if (!err) {
        size_t n = d.n_verts;
        ints = gks_alloc_array(n + 2, sizeof *ints);
        if (!ints || n > INT32_MAX)
            err = 300;
    }
    if (!err) {
        ints[0] = 1;                  /* one loop */
        ints[1] = (int)d.n_verts;     /* of all vertices */
        for (size_t i = 0; i < d.n_verts; i++)
            ints[2 + i] = (int)i;
        d.n_facets = 1;
        d.n_loops = 1;
        d.n_idx = d.n_verts;
        d.facet_loops = ints;
        d.loop_counts = ints + 1;
        d.idx = ints + 2;
        output_data(GFN_FA3D, &d, 0);
    }
    gks_free(ints);
    wc_free(&w);
    if (err)
        GKS_FAIL(err, GFN_FA3D);
}

/* ------------------------------------------------------------------ shading methods */
static void set_shad(int fct, int side, Gint method)
{
    if (gks_check_state(fct))
        return;
    if (method < GSHAD_NONE || method > GSHAD_NORM)
        GKS_FAIL(523, fct);
    gks_ctx()->sl->attrs.int_shad[side] = method;
}

GKS_API void gset_int_shad_meth(Gint method) { set_shad(GFN_SISM, 0, method); }
GKS_API void gset_back_int_shad_meth(Gint method) { set_shad(GFN_SBISM, 1, method); }

GKS_API void ginq_int_shad_meth(Gint *err_ind, Gint *front, Gint *back)
{
    GKS_INQ_ARGS(err_ind, front, back);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    if (front)
        *front = gks_ctx()->sl->attrs.int_shad[0];
    if (back)
        *back = gks_ctx()->sl->attrs.int_shad[1];
}
