/* SPDX-License-Identifier: MIT */
/*
 * gks_output_data.c -- the PHIGS PLUS primitives with data added to GKS-3D (FILL AREA 3
 * WITH DATA, ...) and SET (BACK) INTERIOR SHADING METHOD with its inquiry.
 *
 * Each entry point checks its state and arguments and puts the primitive into one
 * canonical form (gks_area_data: shared vertices, facets made of loops of vertex
 * indices), which the output pipeline draws (core/pipe/gks_pipe_data.c).
 */
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_export.h"
#include "gks_mf_record.h"
#include "gks_output_rec.h"
#include "gks_pipe.h"
#include "gks_state.h"
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


/* INTERPRET ITEM (gks_metafile.c) of a primitive with data: d in NDC3, xf the recorded
 * normalization. */
void gks_output_rec_data(const gks_rec_xf *xf, int item, const gks_area_data *d)
{
    int fctid = item == GKSM_ITEM_FILL_AREA3_DATA       ? GFN_FA3D
                : item == GKSM_ITEM_FILL_AREA_SET3_DATA ? GFN_FAS3D
                : item == GKSM_ITEM_TRI_STRIP3_DATA     ? GFN_TS3D
                : item == GKSM_ITEM_QUAD_MESH3_DATA     ? GFN_QM3D
                                                        : GFN_SFA3D;
    if (gks_check_state(fctid))
        return;
    int err = gks_area_data_check(d);
    if (err)
        GKS_FAIL(err, fctid);
    err = gks_pipe_area_data(fctid, item, d, xf);
    if (err > 0)
        GKS_FAIL(err, fctid);
}

/* Checks the flags and vertex record of a call, copies its vertex data into w and d.
 * Returns 0 or an error number. */
static int take_vdata(Gint fflag, Gint vflag, Gint ctype, const Gfacet_vdata3 *v, size_t min_n,
                      gks_area_arrays *w, gks_area_data *d)
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
static int take_fdata(Gint fflag, Gint ctype, const Gfacet_data3 *fd, size_t nf, gks_area_arrays *w,
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

/* The index structure of a call, built into one int array (freed by the caller). */
typedef struct {
    int *ints;
    size_t n;
} ibuf;

/* d->facet_loops, loop_counts and idx for nf facets, nl loops and ni indices: 0 or 300. */
static int index_alloc(gks_area_data *d, size_t nf, size_t nl, size_t ni, ibuf *b)
{
    if (nf > INT32_MAX || nl > INT32_MAX || ni > INT32_MAX || nf + nl > SIZE_MAX - ni)
        return 300;
    b->ints = gks_alloc_array(nf + nl + ni, sizeof *b->ints);
    if (!b->ints)
        return 300;
    d->n_facets = nf;
    d->n_loops = nl;
    d->n_idx = ni;
    d->facet_loops = b->ints;
    d->loop_counts = b->ints + nf;
    d->idx = b->ints + nf + nl;
    return 0;
}

/* The writable views of index_alloc's arrays. */
#define FL(b) ((b)->ints)
#define LC(b, d) ((b)->ints + (d)->n_facets)
#define IX(b, d) ((b)->ints + (d)->n_facets + (d)->n_loops)

/* Checks (the flags and arrays, then the structure), draws and frees. */
static void finish(int fctid, int item, int err, gks_area_data *d, ibuf *b, gks_area_arrays *w)
{
    if (!err)
        err = gks_area_data_check(d);
    if (!err)
        err = gks_pipe_area_data(fctid, item, d, NULL);
    gks_free(b->ints);
    gks_area_arrays_free(w);
    if (err > 0)
        GKS_FAIL(err, fctid);
}

GKS_API void gfill_area3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_FA3D))
        return;
    gks_area_arrays w = { 0 };
    gks_area_data d = { 0 };
    ibuf b = { 0 };
    int err = take_vdata(fflag, vflag, colr_type, vdata, 3, &w, &d);
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, 1, &w, &d);
    if (!err)
        err = index_alloc(&d, 1, 1, d.n_verts, &b);
    if (!err) {
        FL(&b)[0] = 1;
        LC(&b, &d)[0] = (int)d.n_verts;
        for (size_t i = 0; i < d.n_verts; i++)
            IX(&b, &d)[i] = (int)i;
    }
    finish(GFN_FA3D, GKSM_ITEM_FILL_AREA3_DATA, err, &d, &b, &w);
}

GKS_API void gfill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type,
                                  const Gfacet_data3 *fdata, Gint num_sets,
                                  const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_FAS3D))
        return;
    gks_area_arrays w = { 0 };
    gks_area_data d = { 0 };
    ibuf b = { 0 };
    int err = 0;
    /* The loops are copied into one vertex record. */
    Gfacet_vdata3 all = { 0, NULL, NULL, NULL };
    if (fflag < GFACET_NONE || fflag > GFACET_COLR_NORM || vflag < GVERT_COORD ||
        vflag > GVERT_COORD_COLR_NORM || colr_type < GCOLR_INDIRECT || colr_type > GCOLR_RGB)
        err = 2000;
    else if (num_sets < 1 || !vdata)
        err = num_sets < 1 ? 100 : 2003;
    size_t total = 0;
    for (Gint k = 0; !err && k < num_sets; k++) {
        const Gfacet_vdata3 *v = &vdata[k];
        if (v->num_vertices < 3 || !v->points)
            err = 100;
        else if (((vflag & GVERT_COORD_COLR) && !v->colrs) ||
                 ((vflag & GVERT_COORD_NORM) && !v->norms))
            err = 2003;
        else if ((size_t)v->num_vertices > (size_t)INT32_MAX - total)
            err = 300;
        else
            total += (size_t)v->num_vertices;
    }
    if (!err) {
        all.num_vertices = (Gint)total;
        all.points = gks_alloc_array(total, sizeof *all.points);
        all.colrs = gks_alloc_array(total, sizeof *all.colrs);
        all.norms = gks_alloc_array(total, sizeof *all.norms);
        if (!all.points || !all.colrs || !all.norms)
            err = 300;
    }
    if (!err) {
        size_t off = 0;
        for (Gint k = 0; k < num_sets; k++) {
            const Gfacet_vdata3 *v = &vdata[k];
            size_t c = (size_t)v->num_vertices;
            memcpy(all.points + off, v->points, c * sizeof *v->points);
            if (vflag & GVERT_COORD_COLR)
                memcpy(all.colrs + off, v->colrs, c * sizeof *v->colrs);
            if (vflag & GVERT_COORD_NORM)
                memcpy(all.norms + off, v->norms, c * sizeof *v->norms);
            off += c;
        }
        err = take_vdata(fflag, vflag, colr_type, &all, 3, &w, &d);
    }
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, 1, &w, &d);
    if (!err)
        err = index_alloc(&d, 1, (size_t)num_sets, total, &b);
    if (!err) {
        FL(&b)[0] = num_sets;
        for (Gint k = 0; k < num_sets; k++)
            LC(&b, &d)[k] = vdata[k].num_vertices;
        for (size_t i = 0; i < total; i++)
            IX(&b, &d)[i] = (int)i;
    }
    gks_free(all.points);
    gks_free(all.colrs);
    gks_free(all.norms);
    finish(GFN_FAS3D, GKSM_ITEM_FILL_AREA_SET3_DATA, err, &d, &b, &w);
}

GKS_API void gtri_strip3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_TS3D))
        return;
    gks_area_arrays w = { 0 };
    gks_area_data d = { 0 };
    ibuf b = { 0 };
    int err = take_vdata(fflag, vflag, colr_type, vdata, 3, &w, &d);
    size_t nt = err ? 0 : d.n_verts - 2;
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, nt, &w, &d);
    if (!err && nt > SIZE_MAX / 4)
        err = 300;
    if (!err)
        err = index_alloc(&d, nt, nt, 3 * nt, &b);
    for (size_t i = 0; !err && i < nt; i++) {
        /* Triangle i is (i, i+1, i+2), every other one reversed (i+1, i, i+2): all
         * triangles of the strip keep the orientation of the first. */
        int *t = IX(&b, &d) + 3 * i;
        FL(&b)[i] = 1;
        LC(&b, &d)[i] = 3;
        t[0] = (int)(i % 2 ? i + 1 : i);
        t[1] = (int)(i % 2 ? i : i + 1);
        t[2] = (int)(i + 2);
    }
    finish(GFN_TS3D, GKSM_ITEM_TRI_STRIP3_DATA, err, &d, &b, &w);
}

GKS_API void gquad_mesh3_data(Gint fflag, Gint vflag, Gint colr_type, const Gint_size *dim,
                              const Gfacet_data3 *fdata, const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_QM3D))
        return;
    gks_area_arrays w = { 0 };
    gks_area_data d = { 0 };
    ibuf b = { 0 };
    int err = 0;
    if (fflag < GFACET_NONE || fflag > GFACET_COLR_NORM || vflag < GVERT_COORD ||
        vflag > GVERT_COORD_COLR_NORM || colr_type < GCOLR_INDIRECT || colr_type > GCOLR_RGB)
        err = 2000;
    else if (!dim || !vdata)
        err = 2003;
    else if (dim->size_x < 2 || dim->size_y < 2 ||
             (size_t)dim->size_x * (size_t)dim->size_y > (size_t)INT32_MAX / 4 ||
             vdata->num_vertices != dim->size_x * dim->size_y)
        err = 100;
    size_t mx = err ? 0 : (size_t)dim->size_x, my = err ? 0 : (size_t)dim->size_y;
    size_t nq = (mx - 1) * (my - 1);
    if (!err)
        err = take_vdata(fflag, vflag, colr_type, vdata, 4, &w, &d);
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, nq, &w, &d);
    if (!err)
        err = index_alloc(&d, nq, nq, 4 * nq, &b);
    for (size_t j = 0; !err && j + 1 < my; j++)
        for (size_t i = 0; i + 1 < mx; i++) {
            /* Quadrilateral (i, j): vertices (i,j), (i+1,j), (i+1,j+1), (i,j+1); vertex
             * (i, j) is vdata[j * size_x + i], facets in the same order. */
            size_t q = j * (mx - 1) + i;
            int *t = IX(&b, &d) + 4 * q;
            FL(&b)[q] = 1;
            LC(&b, &d)[q] = 4;
            t[0] = (int)(j * mx + i);
            t[1] = (int)(j * mx + i + 1);
            t[2] = (int)((j + 1) * mx + i + 1);
            t[3] = (int)((j + 1) * mx + i);
        }
    finish(GFN_QM3D, GKSM_ITEM_QUAD_MESH3_DATA, err, &d, &b, &w);
}

GKS_API void gset_of_fill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type, Gint num_sets,
                                         const Gfacet_data3 *fdata, const Gint_list_list *vlist,
                                         const Gfacet_vdata3 *vdata)
{
    if (gks_check_state(GFN_SFA3D))
        return;
    gks_area_arrays w = { 0 };
    gks_area_data d = { 0 };
    ibuf b = { 0 };
    int err = 0;
    if (fflag < GFACET_NONE || fflag > GFACET_COLR_NORM || vflag < GVERT_COORD ||
        vflag > GVERT_COORD_COLR_NORM || colr_type < GCOLR_INDIRECT || colr_type > GCOLR_RGB)
        err = 2000;
    else if (num_sets < 1)
        err = 100;
    else if (!vlist || !vdata)
        err = 2003;
    size_t nl = 0, ni = 0;
    for (Gint k = 0; !err && k < num_sets; k++) {
        const Gint_list_list *s = &vlist[k];
        if (s->num_lists < 1)
            err = 100;
        else if (!s->lists)
            err = 2003;
        for (Gint l = 0; !err && l < s->num_lists; l++) {
            if (s->lists[l].num_ints < 3)
                err = 100;
            else if (!s->lists[l].ints)
                err = 2003;
            else if ((size_t)s->lists[l].num_ints > (size_t)INT32_MAX - ni)
                err = 300;
            else
                ni += (size_t)s->lists[l].num_ints;
        }
        if (!err && nl >= (size_t)INT32_MAX - (size_t)s->num_lists)
            err = 300;
        nl += err ? 0 : (size_t)s->num_lists;
    }
    if (!err)
        err = take_vdata(fflag, vflag, colr_type, vdata, 3, &w, &d);
    if (!err)
        err = take_fdata(fflag, colr_type, fdata, (size_t)num_sets, &w, &d);
    if (!err)
        err = index_alloc(&d, (size_t)num_sets, nl, ni, &b);
    if (!err) {
        size_t l0 = 0, i0 = 0;
        for (Gint k = 0; k < num_sets; k++) {
            const Gint_list_list *s = &vlist[k];
            FL(&b)[k] = s->num_lists;
            for (Gint l = 0; l < s->num_lists; l++) {
                LC(&b, &d)[l0++] = s->lists[l].num_ints;
                memcpy(IX(&b, &d) + i0, s->lists[l].ints,
                       (size_t)s->lists[l].num_ints * sizeof(int));
                i0 += (size_t)s->lists[l].num_ints;
            }
        }
    }
    finish(GFN_SFA3D, GKSM_ITEM_SOFAS3_DATA, err, &d, &b, &w);
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
