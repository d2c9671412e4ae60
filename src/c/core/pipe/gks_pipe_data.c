/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_data.c -- the output pipeline of the PHIGS PLUS primitives with data
 * (gks_pipe.h: gks_pipe_area_data, gks_pipe_data_emit_stored, gks_pipe_data_insert).
 *
 * A primitive with data comes in one canonical form (gks_area_data): shared vertices
 * (points, optional normals and colours) and facets made of loops of vertex indices, each
 * facet with an optional colour and normal. Its points go through the normalization (and
 * segment) transformation, its normals through its inverse transpose, renormalised; each
 * facet is clipped at the viewport 3 (when clipping is on) with its vertex normals and
 * colours interpolated at new vertices; per workstation the colours are resolved (indices
 * through the colour table) and the facet is sent to the driver as one GKS_PRIM_FILL_AREA
 * with data (ws_driver.h) -- or the whole primitive at once as one indexed mesh to a driver
 * with the entry mesh, when no clipping plane cuts it (send_mesh). A facet with a non-finite point or normal is not drawn (as
 * FILL AREA 3 with a non-finite point).
 */
#include "gks_pipe.h"
#include "gks_alloc.h"
#include "gks_attr_resolve.h"
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include "gks_xform.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

/* ------------------------------------------------------------------ transformation */
/* The inverse transpose of m's linear part (normals), scaled by its largest element;
 * 0, or -1 when singular or not finite (src/c/xform). */
static int normal_matrix(const double m[3][4], double nm[3][3])
{
    double m4[4][4];
    gks_xform_mat34_to_mat4(m, m4);
    return gks_xform_normal_matrix(m4, nm);
}

/* The n normals of v mapped by nm and normalised into new arrays *o, with *ok[i] = 1 where
 * the result is a finite unit vector: 0, or 300 (the caller frees what was allocated). */
static int map_normals(const double nm[3][3], const double (*v)[3], size_t n, double (**o)[3],
                       unsigned char **ok)
{
    *o = gks_alloc_array(n, sizeof **o);
    *ok = gks_alloc_array(n, 1);
    if (!*o || !*ok)
        return 300;
    for (size_t i = 0; i < n; i++)
        (*ok)[i] = (unsigned char)gks_xform_normal(nm, v[i], (*o)[i]);
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

/* Scratch space of one facet for one workstation: its vertices as homogeneous NDC3 points
 * with their attributes (normal, colour: what clipping interpolates), the clipped loops,
 * and the arrays sent to the driver. */
enum { NATTR = 6 };
typedef struct {
    double (*h)[4], (*at)[NATTR];
    size_t cap;
    double (*ch)[4], (*cat)[NATTR];
    size_t ccap;
    size_t *lens;              /* loop lengths in, then out */
    size_t cap_lens;
    Gpoint3 *pts;
    Gvec3 *vn;
    Grgb *vc;
    int *counts;
    size_t cap_out, cap_counts;
} facet_buf;

static void facet_buf_free(facet_buf *b)
{
    gks_free(b->h);
    gks_free(b->at);
    gks_free(b->ch);
    gks_free(b->cat);
    gks_free(b->lens);
    gks_free(b->pts);
    gks_free(b->vn);
    gks_free(b->vc);
    gks_free(b->counts);
    memset(b, 0, sizeof *b);
}

/* Arrays of m vertices (c1, c2: element counts, grown together to one capacity *cap). */
static int grow_pair(void *p1, size_t s1, void *p2, size_t s2, size_t *cap, size_t m)
{
    size_t c1 = *cap, c2 = *cap;
    if (gks_grow(p1, &c1, m, s1) || gks_grow(p2, &c2, m, s2))
        return 300;
    if (c1 > *cap) /* both grew to the same capacity */
        *cap = c1;
    return 0;
}

/* Output arrays for m vertices and nl loops. */
static int out_reserve(facet_buf *b, size_t m, size_t nl)
{
    size_t c3 = b->cap_out;
    if (gks_grow(&b->vc, &c3, m, sizeof *b->vc) ||
        grow_pair(&b->pts, sizeof *b->pts, &b->vn, sizeof *b->vn, &b->cap_out, m))
        return 300;
    return gks_grow(&b->counts, &b->cap_counts, nl, sizeof *b->counts);
}

/* The facet's nl loops (b->lens, nv vertices in b->h, b->at) clipped at nc's region into
 * b->ch, b->cat, b->lens: 0 (*n_out vertices), 300, or -1 (not drawn: an overflow). */
static int clip_facet(const gks_pipe_norm *nc, size_t nl, facet_buf *b, size_t *n_out)
{
    for (int pass = 0; pass < 2; pass++) {
        double *cat = b->cat ? &b->cat[0][0] : NULL; /* none before the first growth */
        int r = gks_xform_clip_polygon_attr(&nc->clip, nl, b->lens, (const double (*)[4])b->h,
                                            &b->at[0][0], NATTR, b->ch, cat,
                                            b->ch ? b->ccap : 0, b->lens + nl, n_out);
        if (r != 300 || pass == 1)
            return r == 0 ? 0 : -1;
        if (grow_pair(&b->ch, sizeof *b->ch, &b->cat, sizeof *b->cat, &b->ccap, *n_out))
            return 300;
    }
    return -1;
}

/* Sends facet f (loops from loop0, indices from idx0) to ws. */
static int send_facet(gks_ws *ws, const gks_prim *tpl, const gks_pipe_norm *nc, const mapped *mp,
                      size_t f, size_t loop0, size_t idx0, facet_buf *b)
{
    const gks_area_data *d = mp->d;
    size_t nl = (size_t)d->facet_loops[f], nv = 0;
    for (size_t k = 0; k < nl; k++)
        nv += (size_t)d->loop_counts[loop0 + k];
    int use_n = mp->n != NULL, use_c = (d->vflag & GVERT_COORD_COLR) != 0, inside = 1;
    if (grow_pair(&b->h, sizeof *b->h, &b->at, sizeof *b->at, &b->cap, nv) ||
        gks_grow(&b->lens, &b->cap_lens, 2 * nl, sizeof *b->lens))
        return 300;
    for (size_t i = 0; i < nv; i++) {
        size_t j = (size_t)d->idx[idx0 + i];
        if (!mp->pok[j])
            return 0; /* a non-finite point: the facet is not drawn */
        double *h = b->h[i], *n = b->at[i], *c = b->at[i] + 3;
        memcpy(h, mp->p[j], 3 * sizeof *h);
        h[3] = 1.0;
        if (use_n && !mp->nok[j])
            use_n = 0; /* a degenerate normal: the facet has no vertex normals */
        if (use_n)
            memcpy(n, mp->n[j], 3 * sizeof *n);
        else
            n[0] = n[1] = n[2] = 0.0;
        if (use_c) {
            Grgb cv = colr_of(ws, d->ctype, d->vrgb, d->vci, j);
            c[0] = cv.red; c[1] = cv.green; c[2] = cv.blue;
        } else {
            c[0] = c[1] = c[2] = 0.0;
        }
        if (nc->clip_on)
            for (int k = 0; k < 3; k++)
                inside = inside && h[k] >= nc->box[2 * k] && h[k] <= nc->box[2 * k + 1];
    }
    /* The facet's loops, clipped when not inside (loops left with < 3 points dropped). */
    for (size_t k = 0; k < nl; k++)
        b->lens[k] = b->lens[nl + k] = (size_t)d->loop_counts[loop0 + k];
    const double (*vh)[4] = (const double (*)[4])b->h, (*va)[NATTR] = (const double (*)[NATTR])b->at;
    if (!inside) {
        size_t n_out;
        int err = clip_facet(nc, nl, b, &n_out);
        if (err)
            return err > 0 ? err : 0;
        if (n_out == 0)
            return 0; /* nothing of the facet is left (and no clip arrays were made) */
        vh = (const double (*)[4])b->ch;
        va = (const double (*)[NATTR])b->cat;
    }
    size_t m = 0, off = 0, nlo = 0;
    if (out_reserve(b, nv, nl))
        return 300;
    for (size_t k = 0; k < nl; k++) {
        size_t lc = b->lens[nl + k];
        const double (*lh)[4] = vh + off, (*la)[NATTR] = va + off;
        off += lc;
        if (!inside && lc < 3)
            continue;
        if (lc > INT32_MAX || out_reserve(b, m + lc, nl))
            return 300;
        for (size_t i = 0; i < lc; i++) {
            double n[3] = { la[i][0], la[i][1], la[i][2] }, c[3] = { la[i][3], la[i][4], la[i][5] };
            if (!inside) { /* interpolated: normals renormalised, colours clamped */
                double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                if (len > 0 && isfinite(len))
                    for (int j = 0; j < 3; j++)
                        n[j] /= len;
                else
                    n[0] = n[1] = n[2] = 0.0; /* opposite normals: none (below) */
                for (int j = 0; j < 3; j++)
                    c[j] = fmin(1.0, fmax(0.0, c[j]));
            }
            b->pts[m + i] = (Gpoint3){ lh[i][0], lh[i][1], lh[i][2] };
            b->vn[m + i] = (Gvec3){ n[0], n[1], n[2] };
            if (use_n && n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
                use_n = 0; /* interpolated between opposite normals */
            b->vc[m + i] = (Grgb){ c[0], c[1], c[2] };
        }
        b->counts[nlo++] = (int)lc;
        m += lc;
    }
    if (nlo == 0 || m > INT32_MAX)
        return 0;
    gks_prim p = *tpl; /* the workstation's resolved attributes */
    p.n_loops = (int)nlo;
    p.loop_counts = b->counts;
    p.n_points = (int)m;
    p.pts = b->pts;
    if (d->fflag & GFACET_COLR)
        p.colour = colr_of(ws, d->ctype, d->frgb, d->fci, f);
    if (mp->fn && mp->fnok[f]) {
        p.has_fnormal = 1;
        p.fnormal = (Gvec3){ mp->fn[f][0], mp->fn[f][1], mp->fn[f][2] };
    }
    p.vnormals = use_n ? b->vn : NULL;
    p.vcolours = use_c ? b->vc : NULL;
    return gks_pipe_send(ws, &p);
}

/* The colours of the n values of a list (rgb or indices ci, by ctype) for ws: rgb itself, or
 * the indices resolved into *own (gks_alloc'd; the caller frees it). NULL with *own NULL:
 * storage. */
static const double (*colours_of(const gks_ws *ws, int ctype, const double (*rgb)[3],
                                 const int *ci, size_t n, double (**own)[3]))[3]
{
    *own = NULL;
    if (ctype == GCOLR_RGB)
        return rgb;
    if (!(*own = gks_alloc_array(n ? n : 1, sizeof **own)))
        return NULL;
    for (size_t k = 0; k < n; k++) {
        Grgb c = colr_of(ws, ctype, rgb, ci, k);
        (*own)[k][0] = c.red; (*own)[k][1] = c.green; (*own)[k][2] = c.blue;
    }
    return (const double (*)[3])*own;
}

/* The whole primitive to ws's driver entry mesh (ws_driver.h, gks_mesh), when it needs no
 * clipping (clipping off, or every vertex inside the volume; the simplest correct rule: a
 * mesh a clipping plane cuts goes facet by facet as before) and every point is finite and
 * every normal maps to a unit vector, so that the facets send_facet would send are exactly
 * the mesh's. 0, an error number, or GKS_WS_MESH_FACETS: the caller sends the facets. */
static int send_mesh(gks_ws *ws, const gks_prim *tpl, const gks_pipe_norm *nc, const mapped *mp)
{
    const gks_area_data *d = mp->d;
    if (!ws->drv->mesh)
        return GKS_WS_MESH_FACETS;
    for (size_t i = 0; i < d->n_verts; i++) {
        if (!mp->pok[i] || (mp->n && !mp->nok[i]))
            return GKS_WS_MESH_FACETS;
        for (int k = 0; nc->clip_on && k < 3; k++)
            if (!(mp->p[i][k] >= nc->box[2 * k] && mp->p[i][k] <= nc->box[2 * k + 1]))
                return GKS_WS_MESH_FACETS;
    }
    for (size_t f = 0; mp->fn && f < d->n_facets; f++)
        if (!mp->fnok[f])
            return GKS_WS_MESH_FACETS;
    gks_mesh m = { .prim = *tpl, .n_verts = d->n_verts, .pts = (const double (*)[3])mp->p,
                   .vnormals = (const double (*)[3])mp->n, .n_facets = d->n_facets,
                   .n_loops = d->n_loops, .n_idx = d->n_idx, .facet_loops = d->facet_loops,
                   .loop_counts = d->loop_counts, .idx = d->idx,
                   .fnormals = (const double (*)[3])mp->fn };
    double (*vown)[3] = NULL, (*fown)[3] = NULL;
    int err = 0;
    if (d->vflag & GVERT_COORD_COLR) {
        m.vcolours = colours_of(ws, d->ctype, d->vrgb, d->vci, d->n_verts, &vown);
        err = m.vcolours ? 0 : 300;
    }
    if (!err && (d->fflag & GFACET_COLR)) {
        m.fcolours = colours_of(ws, d->ctype, d->frgb, d->fci, d->n_facets, &fown);
        err = m.fcolours ? 0 : 300;
    }
    if (!err)
        err = gks_pipe_send_mesh(ws, &m);
    gks_free(vown);
    gks_free(fown);
    return err;
}

/* Maps d's points by nc->m and its normals by the inverse transpose. */
static int map_data(const gks_pipe_norm *nc, const gks_area_data *d, int is_set, mapped *mp)
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
    if ((d->vflag & GVERT_COORD_NORM) && nm_ok && map_normals(nm, d->vnorm, nv, &mp->n, &mp->nok))
        return 300;
    if ((d->fflag & GFACET_NORM) && nm_ok && map_normals(nm, d->fnorm, nf, &mp->fn, &mp->fnok))
        return 300;
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

static int data_emit(const gks_pipe_norm *nc, const gks_area_data *d, int is_set,
                     gks_pipe_target *t)
{
    mapped mp;
    facet_buf b;
    memset(&b, 0, sizeof b);
    int err = map_data(nc, d, is_set, &mp);
    gks_ws *ws;
    while (!err && (ws = gks_pipe_next_ws(t))) {
        /* The attributes are resolved once per workstation, the facets share them. */
        gks_prim tpl = { .kind = GKS_PRIM_FILL_AREA, .n_loops = 1 };
        Grgb *pat = NULL;
        gks_pipe_prim_common(&tpl, t->a);
        err = gks_attr_prim_fill(ws, t->a, t->pat_m, &tpl, &pat);
        if (!is_set)
            tpl.attrs.edge_flag = 0; /* GKS-3D edges belong to the area sets */
        if (!err) {
            int m = send_mesh(ws, &tpl, nc, &mp);
            if (m != GKS_WS_MESH_FACETS) { /* drawn whole, or its error */
                err = m;
                gks_free(pat);
                continue;
            }
        }
        size_t loop0 = 0, idx0 = 0;
        for (size_t f = 0; f < d->n_facets && !err; f++) {
            err = send_facet(ws, &tpl, nc, &mp, f, loop0, idx0, &b);
            for (int k = 0; k < d->facet_loops[f]; k++)
                idx0 += (size_t)d->loop_counts[loop0 + (size_t)k];
            loop0 += (size_t)d->facet_loops[f];
        }
        gks_free(pat);
    }
    mapped_free(&mp);
    facet_buf_free(&b);
    return err;
}

/* ------------------------------------------------------------------ storage */
/* d mapped to NDC3 by pn for the segment store and the metafile (gks_area_data.h): points
 * by pn, normals by its inverse transpose, not normalised (so that an identity map, as
 * at INTERPRET ITEM, reproduces them exactly); a non-finite normal becomes 0 (dropped when
 * drawn, as the non-finite one would be), a facet with a non-finite point is left out
 * (it is not drawn). Owns its arrays; n_facets 0: nothing to keep. */
typedef struct {
    gks_area_data d;
    gks_area_arrays a;
} ndc_data;

void gks_area_arrays_free(gks_area_arrays *a)
{
    gks_free(a->pts);
    gks_free(a->vn);
    gks_free(a->vrgb);
    gks_free(a->fn);
    gks_free(a->frgb);
    gks_free(a->ints);
    gks_free(a->vci);
    gks_free(a->fci);
    memset(a, 0, sizeof *a);
}

static void map_raw_normal(const double nm[3][3], int ok, const double v[3], double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = ok ? nm[i][0] * v[0] + nm[i][1] * v[1] + nm[i][2] * v[2] : 0.0;
    if (!(isfinite(o[0]) && isfinite(o[1]) && isfinite(o[2])))
        o[0] = o[1] = o[2] = 0.0;
}

static int to_ndc_data(const double pn[3][4], const gks_area_data *d, ndc_data *o)
{
    memset(o, 0, sizeof *o);
    o->d = *d;
    size_t nv = d->n_verts, nf = d->n_facets;
    o->a.pts = gks_alloc_array(nv, sizeof *o->a.pts);
    o->a.ints = gks_alloc_array(nf + d->n_loops + d->n_idx + 1, sizeof *o->a.ints);
    if (!o->a.pts || !o->a.ints)
        return 300;
    unsigned char *bad = gks_alloc_array(nv, 1);
    if (!bad)
        return 300;
    for (size_t i = 0; i < nv; i++) {
        gks_xform_mat34_point(pn, d->pts[i], o->a.pts[i]);
        double *q = o->a.pts[i];
        bad[i] = !(isfinite(q[0]) && isfinite(q[1]) && isfinite(q[2]));
        if (bad[i])
            q[0] = q[1] = q[2] = 0.0; /* referenced by no facet kept */
    }
    double nm[3][3];
    int nm_ok = normal_matrix(pn, nm) == 0;
    if (d->vnorm) {
        if (!(o->a.vn = gks_alloc_array(nv, sizeof *o->a.vn))) {
            gks_free(bad);
            return 300;
        }
        for (size_t i = 0; i < nv; i++)
            map_raw_normal(nm, nm_ok, d->vnorm[i], o->a.vn[i]);
        o->d.vnorm = (const double (*)[3])o->a.vn;
    }
    int fcr = (d->fflag & GFACET_COLR) && d->ctype == GCOLR_RGB;
    int fci = (d->fflag & GFACET_COLR) && d->ctype == GCOLR_INDIRECT;
    if ((d->fnorm && !(o->a.fn = gks_alloc_array(nf, sizeof *o->a.fn))) ||
        (fcr && !(o->a.frgb = gks_alloc_array(nf, sizeof *o->a.frgb))) ||
        (fci && !(o->a.fci = gks_alloc_array(nf, sizeof *o->a.fci)))) {
        gks_free(bad);
        return 300;
    }
    /* The facets kept, compacted: loops per facet, counts, indices, facet data. */
    int *fl = o->a.ints, *lc = o->a.ints + nf, *ix = o->a.ints + nf + d->n_loops;
    size_t kf = 0, kl = 0, ki = 0, l0 = 0, i0 = 0;
    for (size_t f = 0; f < nf; f++) {
        size_t nl = (size_t)d->facet_loops[f], n = 0;
        for (size_t k = 0; k < nl; k++)
            n += (size_t)d->loop_counts[l0 + k];
        int keep = 1;
        for (size_t i = 0; i < n && keep; i++)
            keep = !bad[d->idx[i0 + i]];
        if (keep) {
            fl[kf] = (int)nl;
            memcpy(lc + kl, d->loop_counts + l0, nl * sizeof *lc);
            memcpy(ix + ki, d->idx + i0, n * sizeof *ix);
            if (o->a.fn)
                map_raw_normal(nm, nm_ok, d->fnorm[f], o->a.fn[kf]);
            if (fcr)
                memcpy(o->a.frgb[kf], d->frgb[f], sizeof o->a.frgb[kf]);
            if (fci)
                o->a.fci[kf] = d->fci[f];
            kf++;
            kl += nl;
            ki += n;
        }
        l0 += nl;
        i0 += n;
    }
    gks_free(bad);
    /* Compact the three index lists into one another's place (they shrank). */
    memmove(o->a.ints + kf, lc, kl * sizeof *lc);
    memmove(o->a.ints + kf + kl, ix, ki * sizeof *ix);
    o->d.pts = (const double (*)[3])o->a.pts;
    o->d.n_facets = kf;
    o->d.n_loops = kl;
    o->d.n_idx = ki;
    o->d.facet_loops = o->a.ints;
    o->d.loop_counts = o->a.ints + kf;
    o->d.idx = o->a.ints + kf + kl;
    o->d.fnorm = (const double (*)[3])o->a.fn;
    o->d.frgb = (const double (*)[3])o->a.frgb;
    o->d.fci = o->a.fci;
    return 0;
}

/* The packed form of d with the item number first (segment store). */
static int pack_store(int item, const gks_area_data *d, int **ints, size_t *ni,
                      Gpoint3 **tri, size_t *nt)
{
    size_t a, t;
    if (gks_area_data_sizes(d, &a, &t) || a >= INT32_MAX)
        return 300;
    *ints = gks_alloc_array(a + 1, sizeof **ints);
    double (*tt)[3] = gks_alloc_array(t ? t : 1, sizeof *tt);
    *tri = gks_alloc_array(t ? t : 1, sizeof **tri);
    if (!*ints || !tt || !*tri) {
        gks_free(tt);
        return 300;
    }
    (*ints)[0] = item;
    gks_area_data_pack(d, *ints + 1, tt);
    for (size_t i = 0; i < t; i++)
        (*tri)[i] = (Gpoint3){ tt[i][0], tt[i][1], tt[i][2] };
    gks_free(tt);
    *ni = a + 1;
    *nt = t;
    return 0;
}

/* Appends d (NDC3) to seg with the bound attributes and normalization, the clipping
 * volume (clip_on, box). 0, 300 or 301. */
static int store(gks_segment *seg, int item, const gks_area_data *d, const gks_seg_bound *b,
                 int clip_on, const double box[6])
{
    int *ints = NULL;
    Gpoint3 *tri = NULL;
    size_t ni = 0, nt = 0;
    int err = pack_store(item, d, &ints, &ni, &tri, &nt);
    if (!err) {
        gks_seg_prim sp = { .kind = GKS_SEG_AREA_DATA, .n_loops = 1, .n_points = (int)nt,
                            .pts = tri, .dints = ints, .n_dints = (int)ni, .bound = b,
                            .clip = clip_on };
        memcpy(sp.clip_box, box, sizeof sp.clip_box);
        err = gks_seg_append(seg, &sp);
    }
    gks_free(ints);
    gks_free(tri);
    return err;
}

/* The metafile item of d (NDC3): the packed form, integers then reals. */
static int mf_write(int fctid, int item, const gks_pipe_norm *nc, const gks_area_data *d)
{
    size_t a, t;
    if (gks_area_data_sizes(d, &a, &t))
        return gks_error_report(300, fctid);
    int *ints = gks_alloc_array(a, sizeof *ints);
    double (*tri)[3] = gks_alloc_array(t ? t : 1, sizeof *tri);
    if (!ints || !tri) {
        gks_free(ints);
        gks_free(tri);
        return gks_error_report(300, fctid);
    }
    gks_area_data_pack(d, ints, tri);
    gks_mf_prim p = { .item = item, .pn = (const double (*)[4])nc->pn,
                      .norm = (const double (*)[4])nc->n, .box = nc->box,
                      .clip_on = nc->clip_on, .dints = ints, .n_dints = a,
                      .dreals = &tri[0][0], .n_dreals = 3 * t };
    int ok = gks_mf_prim_write(fctid, &p);
    gks_free(ints);
    gks_free(tri);
    return ok;
}

static int item_is_set(int item) { return item != GKSM_ITEM_FILL_AREA3_DATA; }

/* Records d (metafile), stores it (open segment) and draws it. */
int gks_pipe_area_data(int fctid, int item, const gks_area_data *d, const gks_rec_xf *xf)
{
    gks_pipe_norm buf;
    const gks_pipe_norm *nc;
    if (gks_pipe_norm_get(&nc, &buf, xf))
        return 308;
    int err = 0;
    if (gks_mf_on() || nc->seg) {
        ndc_data o;
        err = to_ndc_data((const double (*)[4])nc->pn, d, &o);
        if (!err && o.d.n_facets > 0 && gks_mf_on() && !mf_write(fctid, item, nc, &o.d)) {
            gks_area_arrays_free(&o.a);
            return GKS_PIPE_REPORTED; /* the error handler changed the world */
        }
        if (!err && o.d.n_facets > 0 && nc->seg) {
            gks_seg_bound *b = gks_alloc_array(1, sizeof *b);
            if (!b) {
                err = 300;
            } else {
                memset(b, 0, sizeof *b); /* padding: snapshots are compared bytewise */
                b->attrs = gks_ctx()->sl->attrs;
                memcpy(b->norm, nc->n, sizeof b->norm);
                err = store(nc->seg, item, &o.d, b, nc->clip_on, nc->box);
                gks_free(b);
            }
        }
        gks_area_arrays_free(&o.a);
    }
    gks_pipe_target t;
    gks_pipe_target_current(&t, nc);
    if (!err)
        err = data_emit(nc, d, item_is_set(item), &t);
    return err;
}

/* Unpacks a stored primitive with data (its triples copied into *tri). 0, -1 or 300. */
static int unpack_stored(const gks_seg_prim *sp, gks_area_data *d, double (**tri)[3], int *item)
{
    size_t nt = sp->n_points > 0 ? (size_t)sp->n_points : 0;
    *tri = gks_alloc_array(nt ? nt : 1, sizeof **tri);
    if (!*tri)
        return 300;
    for (size_t i = 0; i < nt; i++) {
        (*tri)[i][0] = sp->pts[i].x; (*tri)[i][1] = sp->pts[i].y; (*tri)[i][2] = sp->pts[i].z;
    }
    if (sp->n_dints < 1)
        return -1;
    *item = sp->dints[0];
    return gks_area_data_unpack(sp->dints + 1, (size_t)sp->n_dints - 1,
                                (const double (*)[3]) * tri, nt, d);
}

int gks_pipe_data_emit_stored(const gks_pipe_norm *nc, const gks_seg_prim *sp,
                              gks_pipe_target *t)
{
    gks_area_data d;
    double (*tri)[3] = NULL;
    int item = 0;
    int r = unpack_stored(sp, &d, &tri, &item);
    int err = r == 300 ? 300 : 0;
    if (r == 0)
        err = data_emit(nc, &d, item_is_set(item), t);
    gks_free(tri);
    return err;
}

int gks_pipe_data_insert(gks_segment *open, const double M[3][4], const gks_pipe_norm *cur,
                         const gks_seg_prim *sp)
{
    gks_area_data d;
    double (*tri)[3] = NULL;
    int item = 0;
    int r = unpack_stored(sp, &d, &tri, &item);
    int err = r == 300 ? 300 : 0;
    if (r == 0) {
        ndc_data o;
        gks_seg_bound *b = gks_alloc_array(1, sizeof *b);
        err = b ? to_ndc_data(M, &d, &o) : 300;
        if (b && !err) {
            *b = *sp->bound;
            gks_xform_mat34_multiply(M, sp->bound->norm, b->norm);
            if (o.d.n_facets > 0)
                err = store(open, item, &o.d, b, cur->clip_on, cur->box);
        }
        if (b)
            gks_area_arrays_free(&o.a);
        gks_free(b);
    }
    gks_free(tri);
    return err;
}
