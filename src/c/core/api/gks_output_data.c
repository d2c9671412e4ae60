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

/* One call's canonical form under construction: the data, the arrays copied for it, its
 * index ints (one allocation: fl, lc, ix are the writable views of d's facet_loops,
 * loop_counts and idx), and the first error met (each step below does nothing once err
 * is set). */
typedef struct {
    int fctid, item, err;
    gks_area_data d;
    gks_area_arrays w;
    int *ints, *fl, *lc, *ix;
} job;

/* The start of every entry: 1 when the state check failed (reported, nothing to do);
 * else 0, with the flags checked (2000) and kept in the job's data. */
static int begin(job *j, int fctid, int item, Gint fflag, Gint vflag, Gint ctype)
{
    *j = (job){ .fctid = fctid, .item = item };
    if (gks_check_state(fctid))
        return 1;
    if (fflag < GFACET_NONE || fflag > GFACET_COLR_NORM || vflag < GVERT_COORD ||
        vflag > GVERT_COORD_COLR_NORM || ctype < GCOLR_INDIRECT || ctype > GCOLR_RGB)
        j->err = 2000;
    j->d.fflag = fflag;
    j->d.vflag = vflag;
    j->d.ctype = ctype;
    return 0;
}

/* Checks the vertex record of a call (at least min_n vertices) and copies its data. */
static void take_vdata(job *j, const Gfacet_vdata3 *v, size_t min_n)
{
    gks_area_data *d = &j->d;
    gks_area_arrays *w = &j->w;
    Gint vflag = d->vflag, ctype = d->ctype;
    if (j->err)
        return;
    if (!v) {
        j->err = 2003;
        return;
    }
    if (v->num_vertices < 0 || (size_t)v->num_vertices < min_n || !v->points) {
        j->err = 100;
        return;
    }
    size_t n = (size_t)v->num_vertices;
    if (((vflag & GVERT_COORD_COLR) && !v->colrs) || ((vflag & GVERT_COORD_NORM) && !v->norms)) {
        j->err = 2003;
        return;
    }
    if ((vflag & GVERT_COORD_COLR) && (j->err = colrs_ok(ctype, v->colrs, n)))
        return;
    d->n_verts = n;
    j->err = 300;
    w->pts = gks_alloc_array(n, sizeof *w->pts);
    if (!w->pts)
        return;
    for (size_t i = 0; i < n; i++) {
        w->pts[i][0] = v->points[i].x; w->pts[i][1] = v->points[i].y; w->pts[i][2] = v->points[i].z;
    }
    d->pts = (const double (*)[3])w->pts;
    if (vflag & GVERT_COORD_NORM) {
        if (!(w->vn = gks_alloc_array(n, sizeof *w->vn)))
            return;
        for (size_t i = 0; i < n; i++) {
            w->vn[i][0] = v->norms[i].delta_x; w->vn[i][1] = v->norms[i].delta_y;
            w->vn[i][2] = v->norms[i].delta_z;
        }
        d->vnorm = (const double (*)[3])w->vn;
    }
    if ((vflag & GVERT_COORD_COLR) && ctype == GCOLR_RGB) {
        if (!(w->vrgb = gks_alloc_array(n, sizeof *w->vrgb)))
            return;
        for (size_t i = 0; i < n; i++) {
            w->vrgb[i][0] = v->colrs[i].rgb.red; w->vrgb[i][1] = v->colrs[i].rgb.green;
            w->vrgb[i][2] = v->colrs[i].rgb.blue;
        }
        d->vrgb = (const double (*)[3])w->vrgb;
    } else if (vflag & GVERT_COORD_COLR) {
        if (!(w->vci = gks_alloc_array(n, sizeof *w->vci)))
            return;
        for (size_t i = 0; i < n; i++)
            w->vci[i] = v->colrs[i].ind;
        d->vci = w->vci;
    }
    j->err = 0;
}

/* Checks and copies nf facet records (fd NULL allowed when fflag is GFACET_NONE). */
static void take_fdata(job *j, const Gfacet_data3 *fd, size_t nf)
{
    gks_area_data *d = &j->d;
    gks_area_arrays *w = &j->w;
    Gint fflag = d->fflag, ctype = d->ctype;
    if (j->err || fflag == GFACET_NONE)
        return;
    if (!fd) {
        j->err = 2003;
        return;
    }
    for (size_t f = 0; f < nf; f++)
        if ((fflag & GFACET_COLR) && (j->err = colrs_ok(ctype, &fd[f].colr, 1)))
            return;
    j->err = 300;
    if (fflag & GFACET_NORM) {
        if (!(w->fn = gks_alloc_array(nf, sizeof *w->fn)))
            return;
        for (size_t f = 0; f < nf; f++) {
            w->fn[f][0] = fd[f].norm.delta_x; w->fn[f][1] = fd[f].norm.delta_y;
            w->fn[f][2] = fd[f].norm.delta_z;
        }
        d->fnorm = (const double (*)[3])w->fn;
    }
    if ((fflag & GFACET_COLR) && ctype == GCOLR_RGB) {
        if (!(w->frgb = gks_alloc_array(nf, sizeof *w->frgb)))
            return;
        for (size_t f = 0; f < nf; f++) {
            w->frgb[f][0] = fd[f].colr.rgb.red; w->frgb[f][1] = fd[f].colr.rgb.green;
            w->frgb[f][2] = fd[f].colr.rgb.blue;
        }
        d->frgb = (const double (*)[3])w->frgb;
    } else if (fflag & GFACET_COLR) {
        if (!(w->fci = gks_alloc_array(nf, sizeof *w->fci)))
            return;
        for (size_t f = 0; f < nf; f++)
            w->fci[f] = fd[f].colr.ind;
        d->fci = w->fci;
    }
    j->err = 0;
}

/* The facets of the call: its nf facet records are checked and copied, then its index
 * structure is allocated in one int array, facet_loops, loop_counts and idx for nf
 * facets, nl loops and ni indices (300 when they do not fit). */
static void facets(job *j, const Gfacet_data3 *fd, size_t nf, size_t nl, size_t ni)
{
    gks_area_data *d = &j->d;
    take_fdata(j, fd, nf);
    if (j->err)
        return;
    if (nf > INT32_MAX || nl > INT32_MAX || ni > INT32_MAX || nf + nl > SIZE_MAX - ni ||
        !(j->ints = gks_alloc_array(nf + nl + ni, sizeof *j->ints))) {
        j->err = 300;
        return;
    }
    d->n_facets = nf;
    d->n_loops = nl;
    d->n_idx = ni;
    d->facet_loops = j->fl = j->ints;
    d->loop_counts = j->lc = j->ints + nf;
    d->idx = j->ix = j->ints + nf + nl;
}

/* Checks (the flags and arrays, then the structure), draws, reports and frees. */
static void finish(job *j)
{
    int err = j->err;
    if (!err)
        err = gks_area_data_check(&j->d);
    if (!err)
        err = gks_pipe_area_data(j->fctid, j->item, &j->d, NULL);
    gks_free(j->ints);
    gks_area_arrays_free(&j->w);
    if (err > 0)
        GKS_FAIL(err, j->fctid);
}

/* One facet of num_sets loops, vdata[k] the k-th, in the order given: FILL AREA SET 3 WITH
 * DATA, and FILL AREA 3 WITH DATA as its one-loop case. Several loops are first copied
 * into one vertex record. */
static void loops_facet(job *j, Gint num_sets, const Gfacet_vdata3 *vdata, const Gfacet_data3 *fd)
{
    Gint vflag = j->d.vflag;
    Gfacet_vdata3 all = { 0, NULL, NULL, NULL };
    if (!j->err && (num_sets < 1 || !vdata))
        j->err = num_sets < 1 ? 100 : 2003;
    size_t total = 0;
    for (Gint k = 0; !j->err && num_sets > 1 && k < num_sets; k++) {
        const Gfacet_vdata3 *v = &vdata[k];
        if (v->num_vertices < 3 || !v->points)
            j->err = 100;
        else if (((vflag & GVERT_COORD_COLR) && !v->colrs) ||
                 ((vflag & GVERT_COORD_NORM) && !v->norms))
            j->err = 2003;
        else if ((size_t)v->num_vertices > (size_t)INT32_MAX - total)
            j->err = 300;
        else
            total += (size_t)v->num_vertices;
    }
    if (!j->err && num_sets > 1) {
        all.num_vertices = (Gint)total;
        all.points = gks_alloc_array(total, sizeof *all.points);
        all.colrs = gks_alloc_array(total, sizeof *all.colrs);
        all.norms = gks_alloc_array(total, sizeof *all.norms);
        if (!all.points || !all.colrs || !all.norms)
            j->err = 300;
    }
    if (!j->err && num_sets > 1) {
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
    }
    take_vdata(j, num_sets > 1 ? &all : vdata, 3);
    gks_free(all.points);
    gks_free(all.colrs);
    gks_free(all.norms);
    facets(j, fd, 1, (size_t)num_sets, j->d.n_verts);
    if (!j->err) {
        j->fl[0] = num_sets;
        for (Gint k = 0; k < num_sets; k++)
            j->lc[k] = vdata[k].num_vertices;
        for (size_t i = 0; i < j->d.n_verts; i++)
            j->ix[i] = (int)i;
    }
    finish(j);
}

GKS_API void gfill_area3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata)
{
    job j;
    if (!begin(&j, GFN_FA3D, GKSM_ITEM_FILL_AREA3_DATA, fflag, vflag, colr_type))
        loops_facet(&j, 1, vdata, fdata);
}

GKS_API void gfill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type,
                                  const Gfacet_data3 *fdata, Gint num_sets,
                                  const Gfacet_vdata3 *vdata)
{
    job j;
    if (!begin(&j, GFN_FAS3D, GKSM_ITEM_FILL_AREA_SET3_DATA, fflag, vflag, colr_type))
        loops_facet(&j, num_sets, vdata, fdata);
}

GKS_API void gtri_strip3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata)
{
    job j;
    if (begin(&j, GFN_TS3D, GKSM_ITEM_TRI_STRIP3_DATA, fflag, vflag, colr_type))
        return;
    take_vdata(&j, vdata, 3);
    size_t nt = j.err ? 0 : j.d.n_verts - 2;
    if (!j.err && nt > SIZE_MAX / 4)
        j.err = 300;
    facets(&j, fdata, nt, nt, 3 * nt);
    for (size_t i = 0; !j.err && i < nt; i++) {
        /* Triangle i is (i, i+1, i+2), every other one reversed (i+1, i, i+2): all
         * triangles of the strip keep the orientation of the first. */
        int *t = j.ix + 3 * i;
        j.fl[i] = 1;
        j.lc[i] = 3;
        t[0] = (int)(i % 2 ? i + 1 : i);
        t[1] = (int)(i % 2 ? i : i + 1);
        t[2] = (int)(i + 2);
    }
    finish(&j);
}

GKS_API void gquad_mesh3_data(Gint fflag, Gint vflag, Gint colr_type, const Gint_size *dim,
                              const Gfacet_data3 *fdata, const Gfacet_vdata3 *vdata)
{
    job j;
    if (begin(&j, GFN_QM3D, GKSM_ITEM_QUAD_MESH3_DATA, fflag, vflag, colr_type))
        return;
    if (!j.err && (!dim || !vdata))
        j.err = 2003;
    else if (!j.err && (dim->size_x < 2 || dim->size_y < 2 ||
                        (size_t)dim->size_x * (size_t)dim->size_y > (size_t)INT32_MAX / 4 ||
                        vdata->num_vertices != dim->size_x * dim->size_y))
        j.err = 100;
    size_t mx = j.err ? 0 : (size_t)dim->size_x, my = j.err ? 0 : (size_t)dim->size_y;
    size_t nq = (mx - 1) * (my - 1);
    take_vdata(&j, vdata, 4);
    facets(&j, fdata, nq, nq, 4 * nq);
    for (size_t y = 0; !j.err && y + 1 < my; y++)
        for (size_t i = 0; i + 1 < mx; i++) {
            /* Quadrilateral (i, y): vertices (i,y), (i+1,y), (i+1,y+1), (i,y+1); vertex
             * (i, y) is vdata[y * size_x + i], facets in the same order. */
            size_t q = y * (mx - 1) + i;
            int *t = j.ix + 4 * q;
            j.fl[q] = 1;
            j.lc[q] = 4;
            t[0] = (int)(y * mx + i);
            t[1] = (int)(y * mx + i + 1);
            t[2] = (int)((y + 1) * mx + i + 1);
            t[3] = (int)((y + 1) * mx + i);
        }
    finish(&j);
}

GKS_API void gset_of_fill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type, Gint num_sets,
                                         const Gfacet_data3 *fdata, const Gint_list_list *vlist,
                                         const Gfacet_vdata3 *vdata)
{
    job j;
    if (begin(&j, GFN_SFA3D, GKSM_ITEM_SOFAS3_DATA, fflag, vflag, colr_type))
        return;
    if (!j.err && num_sets < 1)
        j.err = 100;
    else if (!j.err && (!vlist || !vdata))
        j.err = 2003;
    size_t nl = 0, ni = 0;
    for (Gint k = 0; !j.err && k < num_sets; k++) {
        const Gint_list_list *s = &vlist[k];
        if (s->num_lists < 1)
            j.err = 100;
        else if (!s->lists)
            j.err = 2003;
        for (Gint l = 0; !j.err && l < s->num_lists; l++) {
            if (s->lists[l].num_ints < 3)
                j.err = 100;
            else if (!s->lists[l].ints)
                j.err = 2003;
            else if ((size_t)s->lists[l].num_ints > (size_t)INT32_MAX - ni)
                j.err = 300;
            else
                ni += (size_t)s->lists[l].num_ints;
        }
        if (!j.err && nl >= (size_t)INT32_MAX - (size_t)s->num_lists)
            j.err = 300;
        nl += j.err ? 0 : (size_t)s->num_lists;
    }
    take_vdata(&j, vdata, 3);
    facets(&j, fdata, (size_t)num_sets, nl, ni);
    if (!j.err) {
        size_t l0 = 0, i0 = 0;
        for (Gint k = 0; k < num_sets; k++) {
            const Gint_list_list *s = &vlist[k];
            j.fl[k] = s->num_lists;
            for (Gint l = 0; l < s->num_lists; l++) {
                j.lc[l0++] = s->lists[l].num_ints;
                memcpy(j.ix + i0, s->lists[l].ints,
                       (size_t)s->lists[l].num_ints * sizeof(int));
                i0 += (size_t)s->lists[l].num_ints;
            }
        }
    }
    finish(&j);
}

/* ------------------------------------------------------------------ shading methods */
static void set_shad(int fct, int side, Gint method)
{
    if (gks_check_state(fct))
        return;
    if (method < GSHAD_NONE || method > GSHAD_NORM)
        GKS_FAIL(523, fct);
    gks_attrs_w()->int_shad[side] = method;
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
