/* SPDX-License-Identifier: MIT */
/*
 * gks_area_data.c -- checks and packing of the canonical form of the primitives with data
 * (gks_area_data.h).
 */
#include "gks_area_data.h"
#include <math.h>
#include <stdint.h>
#include <string.h>

static int unit_ok(double v) { return isfinite(v) && v >= 0 && v <= 1; }

static int rgb_ok(const Grgb *c) { return unit_ok(c->red) && unit_ok(c->green) && unit_ok(c->blue); }

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


/* What the flags select. */
typedef struct { int vc_i, vc_r, vn, fc_i, fc_r, fn; } sel;

static sel selected(int fflag, int vflag, int ctype)
{
    int rgb = ctype == GCOLR_RGB;
    return (sel){ (vflag & GVERT_COORD_COLR) && !rgb, (vflag & GVERT_COORD_COLR) && rgb,
                  (vflag & GVERT_COORD_NORM) != 0,    (fflag & GFACET_COLR) && !rgb,
                  (fflag & GFACET_COLR) && rgb,       (fflag & GFACET_NORM) != 0 };
}

/* Sizes for the counts; 0 or -1 (beyond INT32_MAX). */
static int sizes_of(sel s, size_t nv, size_t nf, size_t nl, size_t ni, size_t *n_ints,
                    size_t *n_tri)
{
    const size_t lim = INT32_MAX;
    if (nv > lim || nf > lim || nl > lim || ni > lim)
        return -1;
    size_t a = GKS_AREA_DATA_HEADER + nf + nl + ni + (s.vc_i ? nv : 0) + (s.fc_i ? nf : 0);
    size_t t = nv * (1 + (size_t)s.vn + (size_t)s.vc_r) + nf * ((size_t)s.fn + (size_t)s.fc_r);
    if (a > lim || t > lim / 3)
        return -1;
    *n_ints = a;
    *n_tri = t;
    return 0;
}

int gks_area_data_sizes(const gks_area_data *d, size_t *n_ints, size_t *n_triples)
{
    sel s = selected(d->fflag, d->vflag, d->ctype);
    return sizes_of(s, d->n_verts, d->n_facets, d->n_loops, d->n_idx, n_ints, n_triples) ? 300
                                                                                          : 0;
}

void gks_area_data_pack(const gks_area_data *d, int *ints, double (*tri)[3])
{
    sel s = selected(d->fflag, d->vflag, d->ctype);
    size_t nv = d->n_verts, nf = d->n_facets;
    int *p = ints;
    *p++ = d->fflag; *p++ = d->vflag; *p++ = d->ctype;
    *p++ = (int)nv; *p++ = (int)nf; *p++ = (int)d->n_loops; *p++ = (int)d->n_idx;
    memcpy(p, d->facet_loops, nf * sizeof *p); p += nf;
    memcpy(p, d->loop_counts, d->n_loops * sizeof *p); p += d->n_loops;
    memcpy(p, d->idx, d->n_idx * sizeof *p); p += d->n_idx;
    if (s.vc_i) { memcpy(p, d->vci, nv * sizeof *p); p += nv; }
    if (s.fc_i) { memcpy(p, d->fci, nf * sizeof *p); p += nf; }
    double (*t)[3] = tri;
    memcpy(t, d->pts, nv * sizeof *t); t += nv;
    if (s.vn) { memcpy(t, d->vnorm, nv * sizeof *t); t += nv; }
    if (s.vc_r) { memcpy(t, d->vrgb, nv * sizeof *t); t += nv; }
    if (s.fn) { memcpy(t, d->fnorm, nf * sizeof *t); t += nf; }
    if (s.fc_r) { memcpy(t, d->frgb, nf * sizeof *t); t += nf; }
}

int gks_area_data_packed_sizes(const int *h, size_t *n_ints, size_t *n_triples)
{
    if (h[0] < GFACET_NONE || h[0] > GFACET_COLR_NORM || h[1] < GVERT_COORD ||
        h[1] > GVERT_COORD_COLR_NORM || h[2] < GCOLR_INDIRECT || h[2] > GCOLR_RGB ||
        h[3] < 0 || h[4] < 0 || h[5] < 0 || h[6] < 0)
        return -1;
    return sizes_of(selected(h[0], h[1], h[2]), (size_t)h[3], (size_t)h[4], (size_t)h[5],
                    (size_t)h[6], n_ints, n_triples);
}

int gks_area_data_unpack(const int *ints, size_t n_ints, const double (*tri)[3], size_t n_tri,
                         gks_area_data *d)
{
    size_t ni, nt;
    if (n_ints < GKS_AREA_DATA_HEADER || gks_area_data_packed_sizes(ints, &ni, &nt) ||
        ni != n_ints || nt != n_tri)
        return -1;
    memset(d, 0, sizeof *d);
    sel s = selected(ints[0], ints[1], ints[2]);
    d->fflag = ints[0]; d->vflag = ints[1]; d->ctype = ints[2];
    size_t nv = (size_t)ints[3], nf = (size_t)ints[4];
    d->n_verts = nv; d->n_facets = nf; d->n_loops = (size_t)ints[5]; d->n_idx = (size_t)ints[6];
    const int *p = ints + GKS_AREA_DATA_HEADER;
    d->facet_loops = p; p += nf;
    d->loop_counts = p; p += d->n_loops;
    d->idx = p; p += d->n_idx;
    if (s.vc_i) { d->vci = p; p += nv; }
    if (s.fc_i) { d->fci = p; p += nf; }
    const double (*t)[3] = tri;
    d->pts = t; t += nv;
    if (s.vn) { d->vnorm = t; t += nv; }
    if (s.vc_r) { d->vrgb = t; t += nv; }
    if (s.fn) { d->fnorm = t; t += nf; }
    if (s.fc_r) { d->frgb = t; t += nf; }
    return 0;
}
