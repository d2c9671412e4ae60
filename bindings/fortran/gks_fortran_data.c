/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_data.c -- FORTRAN 77 entry points of the PHIGS PLUS primitives with data and
 * the interior shading methods (docs/BINDING.md), thin wrappers over the C binding:
 *   GFA3D  FILL AREA 3 WITH DATA             GSISM  SET INTERIOR SHADING METHOD
 *   GFAS3D FILL AREA SET 3 WITH DATA         GSBISM SET BACK INTERIOR SHADING METHOD
 *   GTS3D  TRIANGLE STRIP 3 WITH DATA        GQISM  INQUIRE INTERIOR SHADING METHODS
 *   GQM3D  QUADRILATERAL MESH 3 WITH DATA
 *   GSFA3D SET OF FILL AREA SET 3 WITH DATA
 * Explicit arrays instead of data records, in one order for all: flags (FFLAG, VFLAG,
 * CTYPE), the counts, the facet data FCI(*) (colour indices), FCR(3,*) (RGB), FN(3,*)
 * (normals), then the vertices PX, PY, PZ, VCI(*), VCR(3,*), VN(3,*). Arrays the flags and
 * the colour type do not select are not read (any variable may be passed). Vertex
 * indices of GSFA3D are 1-based.
 */
#include "gks.h"
#include "gks_binding.h"
#include "FC.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define FAPI __attribute__((visibility("default")))
#define FNAME(lower, UPPER) FC_GLOBAL(lower, UPPER)

typedef int fint;
typedef float freal;

/* The C records of one call. */
typedef struct {
    Gfacet_vdata3 v;
    Gfacet_data3 *f;
} frec;

static void frec_free(frec *r)
{
    free(r->v.points);
    free(r->v.colrs);
    free(r->v.norms);
    free(r->f);
}

static void *alloc_n(size_t n, size_t size)
{
    if (n == 0)
        n = 1;
    return n > SIZE_MAX / size ? NULL : calloc(n, size);
}

static int flag_ok(fint f) { return f >= 0 && f <= 3; }

/* Vertex record of n vertices (n < 0 passes as 0: the core reports 100), facet records
 * of nf facets; 0, or -1 after reporting 300. Arrays are read by the flags only (and
 * only when the flags are valid: the core reports 2000 otherwise). */
static int take(fint fflag, fint vflag, fint ctype, fint n, fint nf, const fint *fci,
                const freal *fcr, const freal *fn, const freal *px, const freal *py,
                const freal *pz, const fint *vci, const freal *vcr, const freal *vn, frec *r,
                Gint fctid)
{
    memset(r, 0, sizeof *r);
    size_t nv = n > 0 ? (size_t)n : 0, nfc = nf > 0 ? (size_t)nf : 0;
    int ok = flag_ok(fflag) && flag_ok(vflag) && (ctype == GCOLR_INDIRECT || ctype == GCOLR_RGB);
    r->v.num_vertices = n > 0 ? n : 0;
    r->v.points = alloc_n(nv, sizeof *r->v.points);
    r->v.colrs = alloc_n(nv, sizeof *r->v.colrs);
    r->v.norms = alloc_n(nv, sizeof *r->v.norms);
    r->f = alloc_n(nfc, sizeof *r->f);
    if (!r->v.points || !r->v.colrs || !r->v.norms || !r->f) {
        frec_free(r);
        gks_binding_error(300, fctid);
        return -1;
    }
    for (size_t i = 0; i < nv; i++)
        r->v.points[i] = (Gpoint3){ px[i], py[i], pz[i] };
    if (ok && (vflag & GVERT_COORD_COLR))
        for (size_t i = 0; i < nv; i++) {
            if (ctype == GCOLR_RGB)
                r->v.colrs[i].rgb = (Grgb){ vcr[3 * i], vcr[3 * i + 1], vcr[3 * i + 2] };
            else
                r->v.colrs[i].ind = vci[i];
        }
    if (ok && (vflag & GVERT_COORD_NORM))
        for (size_t i = 0; i < nv; i++)
            r->v.norms[i] = (Gvec3){ vn[3 * i], vn[3 * i + 1], vn[3 * i + 2] };
    for (size_t f = 0; ok && f < nfc; f++) {
        if (fflag & GFACET_COLR) {
            if (ctype == GCOLR_RGB)
                r->f[f].colr.rgb = (Grgb){ fcr[3 * f], fcr[3 * f + 1], fcr[3 * f + 2] };
            else
                r->f[f].colr.ind = fci[f];
        }
        if (fflag & GFACET_NORM)
            r->f[f].norm = (Gvec3){ fn[3 * f], fn[3 * f + 1], fn[3 * f + 2] };
    }
    return 0;
}

/* GFA3D(FFLAG, VFLAG, CTYPE, N, FCI, FCR(3), FN(3), PX(N), PY(N), PZ(N), VCI(N),
 * VCR(3,N), VN(3,N)) */
FAPI void FNAME(gfa3d, GFA3D)(const fint *fflag, const fint *vflag, const fint *ctype,
                              const fint *n, const fint *fci, const freal *fcr, const freal *fn,
                              const freal *px, const freal *py, const freal *pz,
                              const fint *vci, const freal *vcr, const freal *vn)
{
    frec r;
    if (take(*fflag, *vflag, *ctype, *n, 1, fci, fcr, fn, px, py, pz, vci, vcr, vn, &r,
             GFN_FA3D))
        return;
    gfill_area3_data(*fflag, *vflag, *ctype, r.f, &r.v);
    frec_free(&r);
}

/* GFAS3D(FFLAG, VFLAG, CTYPE, NL, LCNT(NL), FCI, FCR(3), FN(3), PX, PY, PZ, VCI, VCR, VN):
 * loop k has LCNT(k) vertices, the loops one after the other in the vertex arrays. */
FAPI void FNAME(gfas3d, GFAS3D)(const fint *fflag, const fint *vflag, const fint *ctype,
                                const fint *nl, const fint *lcnt, const fint *fci,
                                const freal *fcr, const freal *fn, const freal *px,
                                const freal *py, const freal *pz, const fint *vci,
                                const freal *vcr, const freal *vn)
{
    size_t total = 0;
    int bad = *nl < 1;
    for (fint k = 0; !bad && k < *nl; k++) {
        if (lcnt[k] < 3)
            bad = 1;
        else
            total += (size_t)lcnt[k];
        if (total > INT32_MAX)
            bad = 1;
    }
    frec r;
    if (take(*fflag, *vflag, *ctype, bad ? 0 : (fint)total, 1, fci, fcr, fn, px, py, pz, vci,
             vcr, vn, &r, GFN_FAS3D))
        return;
    fint nsets = *nl > 0 ? *nl : 0;
    Gfacet_vdata3 *loops = alloc_n((size_t)nsets, sizeof *loops);
    if (!loops) {
        frec_free(&r);
        gks_binding_error(300, GFN_FAS3D);
        return;
    }
    if (bad) {
        /* A loop of fewer than 3 vertices (or none): the core reports 100. */
        for (fint k = 0; k < nsets; k++)
            loops[k] = (Gfacet_vdata3){ 0, r.v.points, NULL, NULL };
    } else {
        size_t off = 0;
        for (fint k = 0; k < nsets; k++) {
            loops[k] = (Gfacet_vdata3){ lcnt[k], r.v.points + off, r.v.colrs + off,
                                        r.v.norms + off };
            off += (size_t)lcnt[k];
        }
    }
    gfill_area_set3_data(*fflag, *vflag, *ctype, r.f, *nl, loops);
    free(loops);
    frec_free(&r);
}

/* GTS3D(FFLAG, VFLAG, CTYPE, N, FCI(N-2), FCR(3,N-2), FN(3,N-2), PX(N), PY(N), PZ(N),
 * VCI(N), VCR(3,N), VN(3,N)) */
FAPI void FNAME(gts3d, GTS3D)(const fint *fflag, const fint *vflag, const fint *ctype,
                              const fint *n, const fint *fci, const freal *fcr, const freal *fn,
                              const freal *px, const freal *py, const freal *pz,
                              const fint *vci, const freal *vcr, const freal *vn)
{
    frec r;
    if (take(*fflag, *vflag, *ctype, *n, *n - 2, fci, fcr, fn, px, py, pz, vci, vcr, vn, &r,
             GFN_TS3D))
        return;
    gtri_strip3_data(*fflag, *vflag, *ctype, r.f, &r.v);
    frec_free(&r);
}

/* GQM3D(FFLAG, VFLAG, CTYPE, M, N, FCI((M-1)*(N-1)), FCR(3,*), FN(3,*), PX(M,N), PY(M,N),
 * PZ(M,N), VCI(M,N), VCR(3,M,N), VN(3,M,N)): vertex (I,J) = PX(I,J), I fastest. */
FAPI void FNAME(gqm3d, GQM3D)(const fint *fflag, const fint *vflag, const fint *ctype,
                              const fint *m, const fint *n, const fint *fci, const freal *fcr,
                              const freal *fn, const freal *px, const freal *py,
                              const freal *pz, const fint *vci, const freal *vcr,
                              const freal *vn)
{
    int ok = *m >= 2 && *n >= 2 && (int64_t)*m * *n <= INT32_MAX / 4;
    fint nv = ok ? *m * *n : 0, nf = ok ? (*m - 1) * (*n - 1) : 0;
    frec r;
    if (take(*fflag, *vflag, *ctype, nv, nf, fci, fcr, fn, px, py, pz, vci, vcr, vn, &r,
             GFN_QM3D))
        return;
    Gint_size dim = { *m, *n };
    gquad_mesh3_data(*fflag, *vflag, *ctype, &dim, r.f, &r.v);
    frec_free(&r);
}

/* GSFA3D(FFLAG, VFLAG, CTYPE, NSETS, NLPS(NSETS), LCNT(*), IDX(*), FCI(NSETS),
 * FCR(3,NSETS), FN(3,NSETS), NV, PX(NV), PY(NV), PZ(NV), VCI(NV), VCR(3,NV), VN(3,NV)):
 * set k has NLPS(k) loops; the loops of all sets one after the other have LCNT(l)
 * vertices each, whose 1-based indices follow one after the other in IDX. */
FAPI void FNAME(gsfa3d, GSFA3D)(const fint *fflag, const fint *vflag, const fint *ctype,
                                const fint *nsets, const fint *nlps, const fint *lcnt,
                                const fint *idx, const fint *fci, const freal *fcr,
                                const freal *fn, const fint *nv, const freal *px,
                                const freal *py, const freal *pz, const fint *vci,
                                const freal *vcr, const freal *vn)
{
    fint ns = *nsets > 0 ? *nsets : 0;
    frec r;
    if (take(*fflag, *vflag, *ctype, *nv, ns, fci, fcr, fn, px, py, pz, vci, vcr, vn, &r,
             GFN_SFA3D))
        return;
    /* Count the loops and indices (a bad count: the core reports 100 on a 0 list). */
    size_t nl = 0, ni = 0;
    int bad = 0;
    for (fint k = 0; k < ns && !bad; k++) {
        if (nlps[k] < 1 || (size_t)nlps[k] > (size_t)INT32_MAX - nl)
            bad = 1;
        else
            nl += (size_t)nlps[k];
    }
    for (size_t l = 0; l < nl && !bad; l++) {
        if (lcnt[l] < 3 || (size_t)lcnt[l] > (size_t)INT32_MAX - ni)
            bad = 1;
        else
            ni += (size_t)lcnt[l];
    }
    Gint_list_list *sets = alloc_n((size_t)ns, sizeof *sets);
    Gint_list *lists = alloc_n(bad ? 1 : nl, sizeof *lists);
    Gint *ind = alloc_n(bad ? 1 : ni, sizeof *ind);
    if (!sets || !lists || !ind) {
        free(sets);
        free(lists);
        free(ind);
        frec_free(&r);
        gks_binding_error(300, GFN_SFA3D);
        return;
    }
    if (bad) {
        for (fint k = 0; k < ns; k++)
            sets[k] = (Gint_list_list){ 0, lists };
    } else {
        for (size_t i = 0; i < ni; i++)
            ind[i] = idx[i] - 1;
        size_t l0 = 0, i0 = 0;
        for (fint k = 0; k < ns; k++) {
            sets[k] = (Gint_list_list){ nlps[k], lists + l0 };
            for (fint l = 0; l < nlps[k]; l++, l0++) {
                lists[l0] = (Gint_list){ lcnt[l0], ind + i0 };
                i0 += (size_t)lcnt[l0];
            }
        }
    }
    gset_of_fill_area_set3_data(*fflag, *vflag, *ctype, *nsets, r.f, sets, &r.v);
    free(sets);
    free(lists);
    free(ind);
    frec_free(&r);
}

/* GSISM(METH) / GSBISM(METH): SET (BACK) INTERIOR SHADING METHOD, GSHNON, GSHCOL, GSHNOR. */
FAPI void FNAME(gsism, GSISM)(const fint *meth) { gset_int_shad_meth(*meth); }
FAPI void FNAME(gsbism, GSBISM)(const fint *meth) { gset_back_int_shad_meth(*meth); }

/* GQISM(ERRIND, METH, BMETH): INQUIRE INTERIOR SHADING METHODS (front and back). */
FAPI void FNAME(gqism, GQISM)(fint *errind, fint *meth, fint *bmeth)
{
    Gint f = 0, b = 0;
    ginq_int_shad_meth(errind, &f, &b);
    if (!*errind) {
        *meth = f;
        *bmeth = b;
    }
}
