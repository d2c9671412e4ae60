/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_output.c -- FORTRAN 77 binding of the output primitives, primitive
 * attributes, representations and their inquiries (ISO 8651-1 names; GKS-3D names from
 * CERN's GKSGRAL-3D primer where it gives them, [I] names documented in
 * bindings/fortran/README.md otherwise). Thin wrappers: convert arguments (REAL -> double,
 * Fortran arrays -> C lists, 1-based list positions -> 0-based), call the C binding,
 * convert outputs. CHARACTER arguments take a size_t hidden length after all explicit
 * arguments; text keeps its trailing blanks. Conventions as gks_fortran.c.
 */
#include "gks_binding.h"
#include "gks_fortran.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ helpers */
/* NUL-terminated copy of the first len characters of a text string; NULL: reported 300.
 * Not trimmed: a CHARACTER text has its full declared length in ISO 8651-1, so the
 * trailing blanks of 'HOURS ' are drawn and measured (TEXT, INQUIRE TEXT EXTENT). File
 * names and connection identifiers are trimmed elsewhere (gks_fortran.c). */
static char *fstr(const char *s, size_t len, Gint fctid)
{
    char *p = len < SIZE_MAX ? gks_f77_alloc(len + 1, 1) : NULL;
    if (!p) {
        gks_f77_nomem(fctid);
        return NULL;
    }
    memcpy(p, s, len);
    p[len] = '\0';
    return p;
}

/* Point arrays (z = NULL: 2-D). n <= 0 gives an empty list (the core reports 100).
 * Returns 0 or -1 (300 reported). */
static int points2(fint n, const freal *px, const freal *py, Gpoint_list *l, Gint fctid)
{
    l->num_points = n;
    l->points = NULL;
    if (n <= 0)
        return 0;
    if (!(l->points = gks_f77_alloc((size_t)n, sizeof *l->points))) {
        gks_f77_nomem(fctid);
        return -1;
    }
    for (fint i = 0; i < n; i++)
        l->points[i] = (Gpoint){ px[i], py[i] };
    return 0;
}

static int points3(fint n, const freal *px, const freal *py, const freal *pz, Gpoint_list3 *l,
                   Gint fctid)
{
    l->num_points = n;
    l->points = NULL;
    if (n <= 0)
        return 0;
    if (!(l->points = gks_f77_alloc((size_t)n, sizeof *l->points))) {
        gks_f77_nomem(fctid);
        return -1;
    }
    for (fint i = 0; i < n; i++)
        l->points[i] = (Gpoint3){ px[i], py[i], pz[i] };
    return 0;
}

/* Sub-array of a Fortran INTEGER COLIA(DIMX, DIMY): DX columns from ISC, DY rows from ISR,
 * row-major as Gpat_rep. An inconsistent request gives dims 0 x 0 (the core reports 91).
 * Returns 0 or -1 (300 reported); free rep->colr_array. */
static int sub_array(fint dimx, fint dimy, fint isc, fint isr, fint dx, fint dy,
                     const fint *colia, Gpat_rep *rep, Gint fctid)
{
    rep->dims = (Gint_size){ 0, 0 };
    rep->colr_array = NULL;
    if (dx < 1 || dy < 1 || isc < 1 || isr < 1 || dimx < 1 || dimy < 1 ||
        isc - 1 > dimx - dx || isr - 1 > dimy - dy)
        return 0;
    rep->colr_array = gks_f77_alloc((size_t)dx * (size_t)dy, sizeof(Gint));
    if (!rep->colr_array) {
        gks_f77_nomem(fctid);
        return -1;
    }
    for (fint j = 0; j < dy; j++)
        for (fint i = 0; i < dx; i++)
            rep->colr_array[(size_t)j * (size_t)dx + (size_t)i] =
                colia[(size_t)(isc - 1 + i) + (size_t)(isr - 1 + j) * (size_t)dimx];
    rep->dims = (Gint_size){ dx, dy };
    return 0;
}

/* Three Fortran arrays X(2), Y(2), Z(2) as two vectors (X(k), Y(k), Z(k)). */
static void two_vecs(const freal *x, const freal *y, const freal *z, Gvec3 v[2])
{
    for (int k = 0; k < 2; k++)
        v[k] = (Gvec3){ x[k], y[k], z[k] };
}

/* ------------------------------------------------------------------ primitives */
/* GPM(N, PX, PY) / GPM3(N, PX, PY, PZ) */
FAPI void FNAME(gpm, GPM)(const fint *n, const freal *px, const freal *py)
{
    Gpoint_list l;
    if (points2(*n, px, py, &l, GFN_PM))
        return;
    gpolymarker(&l);
    free(l.points);
}

FAPI void FNAME(gpm3, GPM3)(const fint *n, const freal *px, const freal *py, const freal *pz)
{
    Gpoint_list3 l;
    if (points3(*n, px, py, pz, &l, GFN_PM3))
        return;
    gpolymarker3(&l);
    free(l.points);
}

/* TEXT's string: an embedded CHAR(0) would end the C string and silently shorten the
 * text, so it becomes DEL (127), a code the core rejects with 101 in the standard's
 * order of checks (issue 20: GTX('AB'//CHAR(0)//'CD') is 101, not "AB"). */
static char *text_str(const char *s, size_t len, Gint fctid)
{
    char *t = fstr(s, len, fctid);
    for (size_t i = 0; t && i < len; i++)
        if (t[i] == '\0')
            t[i] = 127;
    return t;
}

static void text_n(freal px, freal py, const char *s, size_t len)
{
    char *t = text_str(s, len, GFN_TX);
    if (!t)
        return;
    Gpoint p = { px, py };
    gtext(&p, t);
    free(t);
}

/* GTX(PX, PY, CHARS); subset GTXS(PX, PY, LSTR, CHARS) */
FAPI void FNAME(gtx, GTX)(const freal *px, const freal *py, const char *chars, size_t len)
{
    text_n(*px, *py, chars, len);
}

FAPI void FNAME(gtxs, GTXS)(const freal *px, const freal *py, const fint *lstr,
                            const char *chars, size_t len)
{
    size_t n = *lstr < 0 ? 0 : (size_t)*lstr;
    text_n(*px, *py, chars, n < len ? n : len);
}

/* GTX3(PX, PY, PZ, TDX(2), TDY(2), TDZ(2), STR): text direction vectors k = 1, 2 are
 * (TDX(k), TDY(k), TDZ(k)). */
FAPI void FNAME(gtx3, GTX3)(const freal *px, const freal *py, const freal *pz, const freal *tdx,
                            const freal *tdy, const freal *tdz, const char *str, size_t len)
{
    char *t = text_str(str, len, GFN_TX3);
    if (!t)
        return;
    Gpoint3 p = { *px, *py, *pz };
    Gvec3 d[2];
    two_vecs(tdx, tdy, tdz, d);
    gtext3(&p, d, t);
    free(t);
}

/* FILL AREA SET: PTR(k) = index of the last point of sub-area k (1-based, ascending).
 * Inconsistent pointers make the sub-area empty (the core reports 100). */
static void fill_set(fint nptr, const fint *ptr, const freal *px, const freal *py,
                     const freal *pz, Gint fctid)
{
    if (nptr < 1) {
        if (pz)
            gfill_area_set3(&(Gpoint_list_list3){ 0, NULL });
        else
            gfill_area_set(&(Gpoint_list_list){ 0, NULL });
        return;
    }
    Gpoint_list *l2 = pz ? NULL : gks_f77_alloc((size_t)nptr, sizeof *l2);
    Gpoint_list3 *l3 = pz ? gks_f77_alloc((size_t)nptr, sizeof *l3) : NULL;
    fint total = nptr > 0 && ptr[nptr - 1] > 0 ? ptr[nptr - 1] : 0;
    Gpoint *p2 = pz ? NULL : gks_f77_alloc((size_t)total, sizeof *p2);
    Gpoint3 *p3 = pz ? gks_f77_alloc((size_t)total, sizeof *p3) : NULL;
    if ((pz && (!l3 || !p3)) || (!pz && (!l2 || !p2))) {
        free(l2); free(l3); free(p2); free(p3);
        gks_f77_nomem(fctid);
        return;
    }
    for (fint i = 0; i < total; i++) {
        if (pz)
            p3[i] = (Gpoint3){ px[i], py[i], pz[i] };
        else
            p2[i] = (Gpoint){ px[i], py[i] };
    }
    fint start = 0;
    for (fint k = 0; k < nptr; k++) {
        fint end = ptr[k];
        fint cnt = end > start && end <= total ? end - start : 0;
        if (pz)
            l3[k] = (Gpoint_list3){ cnt, p3 + start };
        else
            l2[k] = (Gpoint_list){ cnt, p2 + start };
        if (cnt > 0)
            start = end;
    }
    if (pz)
        gfill_area_set3(&(Gpoint_list_list3){ nptr, l3 });
    else
        gfill_area_set(&(Gpoint_list_list){ nptr, l2 });
    free(l2); free(l3); free(p2); free(p3);
}

/* GFAS(NPTR, PTR, PX, PY) / GFAS3(NPTR, PTR, PX, PY, PZ) */
FAPI void FNAME(gfas, GFAS)(const fint *nptr, const fint *ptr, const freal *px, const freal *py)
{
    fill_set(*nptr, ptr, px, py, NULL, GFN_FAS);
}

FAPI void FNAME(gfas3, GFAS3)(const fint *nptr, const fint *ptr, const freal *px,
                              const freal *py, const freal *pz)
{
    fill_set(*nptr, ptr, px, py, pz, GFN_FAS3);
}

/* GCA(PX, PY, QX, QY, DIMX, DIMY, ISC, ISR, DX, DY, COLIA(DIMX, DIMY)) */
FAPI void FNAME(gca, GCA)(const freal *px, const freal *py, const freal *qx, const freal *qy,
                          const fint *dimx, const fint *dimy, const fint *isc, const fint *isr,
                          const fint *dx, const fint *dy, const fint *colia)
{
    Gpat_rep a;
    if (sub_array(*dimx, *dimy, *isc, *isr, *dx, *dy, colia, &a, GFN_CA))
        return;
    Grect r = { { *px, *py }, { *qx, *qy } };
    gcell_array(&r, &a);
    free(a.colr_array);
}

/* GCA3(PX,PY,PZ, QX,QY,QZ, RX,RY,RZ, DIMX, DIMY, ISC, ISR, DX, DY, COLIA) [I]: P = cell
 * (1,1) corner, Q = opposite corner, R = end of P's first row. */
FAPI void FNAME(gca3, GCA3)(const freal *px, const freal *py, const freal *pz, const freal *qx,
                            const freal *qy, const freal *qz, const freal *rx, const freal *ry,
                            const freal *rz, const fint *dimx, const fint *dimy,
                            const fint *isc, const fint *isr, const fint *dx, const fint *dy,
                            const fint *colia)
{
    Gpat_rep a;
    if (sub_array(*dimx, *dimy, *isc, *isr, *dx, *dy, colia, &a, GFN_CA3))
        return;
    Gparal r = { { *px, *py, *pz }, { *qx, *qy, *qz }, { *rx, *ry, *rz } };
    gcell_array3(&r, &a);
    free(a.colr_array);
}

/* GGDP(N, PX, PY, PRIMID, LDR, DATREC) / GGDP3(N, PX, PY, PZ, PRIMID, LDR, DATREC):
 * the GDPs of this implementation (GARC ... GELLIP in GKS3D_PAR) take no data, so the
 * data record is not decoded. */
FAPI void FNAME(ggdp, GGDP)(const fint *n, const freal *px, const freal *py, const fint *primid,
                            const fint *ldr, const char *datrec, size_t len)
{
    (void)ldr; (void)datrec; (void)len;
    Gpoint_list l;
    if (points2(*n > 0 ? *n : 0, px, py, &l, GFN_GDP))
        return;
    l.num_points = *n;
    ggdp(&l, *primid, NULL);
    free(l.points);
}

FAPI void FNAME(ggdp3, GGDP3)(const fint *n, const freal *px, const freal *py, const freal *pz,
                              const fint *primid, const fint *ldr, const char *datrec,
                              size_t len)
{
    (void)ldr; (void)datrec; (void)len;
    Gpoint_list3 l;
    if (points3(*n > 0 ? *n : 0, px, py, pz, &l, GFN_GDP3))
        return;
    l.num_points = *n;
    ggdp3(&l, *primid, NULL);
    free(l.points);
}

/* ------------------------------------------------------------------ attributes */
#define SET_I(lower, UPPER, CALL) \
    FAPI void FNAME(lower, UPPER)(const fint *v) { CALL(*v); }
#define SET_R(lower, UPPER, CALL) \
    FAPI void FNAME(lower, UPPER)(const freal *v) { CALL(*v); }
SET_I(gspli, GSPLI, gset_line_ind)
SET_I(gsln, GSLN, gset_linetype)
SET_R(gslwsc, GSLWSC, gset_linewidth)
SET_I(gspmi, GSPMI, gset_marker_ind)
SET_I(gsmk, GSMK, gset_marker_type)
SET_R(gsmksc, GSMKSC, gset_marker_size)
SET_I(gspmci, GSPMCI, gset_marker_colr_ind)
SET_I(gstxi, GSTXI, gset_text_ind)
SET_R(gschxp, GSCHXP, gset_char_expan)
SET_R(gschsp, GSCHSP, gset_char_space)
SET_I(gstxci, GSTXCI, gset_text_colr_ind)
SET_R(gschh, GSCHH, gset_char_ht)
SET_I(gsfai, GSFAI, gset_fill_ind)
SET_I(gsfasi, GSFASI, gset_fill_style_ind)
SET_I(gspkid, GSPKID, gset_pick_id)
SET_I(gshrid, GSHRID, gset_hlhsr_id)
SET_I(gsedt, GSEDT, gset_edgetype)
SET_R(gsewsc, GSEWSC, gset_edgewidth)
SET_I(gsedci, GSEDCI, gset_edge_colr_ind)
SET_I(gsedi, GSEDI, gset_edge_ind)

FAPI void FNAME(gstxp, GSTXP)(const fint *v) { gset_text_path((Gtext_path)*v); }
FAPI void FNAME(gsfais, GSFAIS)(const fint *v) { gset_fill_int_style((Gfill_int_style)*v); }
FAPI void FNAME(gsedfg, GSEDFG)(const fint *v) { gset_edge_flag((Gedge_flag)*v); }

FAPI void FNAME(gstxfp, GSTXFP)(const fint *font, const fint *prec)
{
    Gtext_font_prec fp = { *font, (Gtext_prec)*prec };
    gset_text_font_prec(&fp);
}

FAPI void FNAME(gschup, GSCHUP)(const freal *x, const freal *y)
{
    Gvec v = { *x, *y };
    gset_char_up_vec(&v);
}

FAPI void FNAME(gstxal, GSTXAL)(const fint *h, const fint *v)
{
    Gtext_align a = { (Ghor_text_align)*h, (Gvert_text_align)*v };
    gset_text_align(&a);
}

FAPI void FNAME(gspa, GSPA)(const freal *szx, const freal *szy)
{
    gset_pat_size(*szx, *szy);
}

FAPI void FNAME(gsparf, GSPARF)(const freal *x, const freal *y)
{
    Gpoint p = { *x, *y };
    gset_pat_ref_point(&p);
}

/* GSPRPV(RFX, RFY, RFZ, VX(2), VY(2), VZ(2)) [I]: SET PATTERN REFERENCE POINT AND VECTORS;
 * vector k = (VX(k), VY(k), VZ(k)). */
FAPI void FNAME(gsprpv, GSPRPV)(const freal *x, const freal *y, const freal *z, const freal *vx,
                                const freal *vy, const freal *vz)
{
    Gpoint3 p = { *x, *y, *z };
    Gvec3 v[2];
    two_vecs(vx, vy, vz, v);
    gset_pat_ref_point_vecs(&p, v);
}

static Gasfs asfs_from(const fint *f)
{
    Gasfs a = { (Gasf)f[0], (Gasf)f[1], (Gasf)f[2], (Gasf)f[3], (Gasf)f[4], (Gasf)f[5],
                (Gasf)f[6], (Gasf)f[7], (Gasf)f[8], (Gasf)f[9], (Gasf)f[10], (Gasf)f[11],
                (Gasf)f[12] };
    return a;
}

/* GSASF(LASF(13)) / GASF3(LASF(17)): 14..17 = edge flag, edgetype, edgewidth, edge colour. */
FAPI void FNAME(gsasf, GSASF)(const fint *lasf)
{
    Gasfs a = asfs_from(lasf);
    gset_asfs(&a);
}

FAPI void FNAME(gasf3, GASF3)(const fint *lasf)
{
    Gasfs3 a = { asfs_from(lasf), (Gasf)lasf[13], (Gasf)lasf[14], (Gasf)lasf[15],
                 (Gasf)lasf[16] };
    gset_asfs3(&a);
}

/* ------------------------------------------------------------------ representations */
FAPI void FNAME(gsplr, GSPLR)(const fint *wkid, const fint *pli, const fint *ltype,
                              const freal *lwidth, const fint *coli)
{
    Gline_bundle b = { *ltype, *lwidth, *coli };
    gset_line_rep(*wkid, *pli, &b);
}

FAPI void FNAME(gspmr, GSPMR)(const fint *wkid, const fint *pmi, const fint *mtype,
                              const freal *mszsf, const fint *coli)
{
    Gmarker_bundle b = { *mtype, *mszsf, *coli };
    gset_marker_rep(*wkid, *pmi, &b);
}

FAPI void FNAME(gstxr, GSTXR)(const fint *wkid, const fint *txi, const fint *font,
                              const fint *prec, const freal *chxp, const freal *chsp,
                              const fint *coli)
{
    Gtext_bundle b = { { *font, (Gtext_prec)*prec }, *chxp, *chsp, *coli };
    gset_text_rep(*wkid, *txi, &b);
}

FAPI void FNAME(gsfar, GSFAR)(const fint *wkid, const fint *fai, const fint *ints,
                              const fint *styli, const fint *coli)
{
    Gfill_bundle b = { (Gfill_int_style)*ints, *styli, *coli };
    gset_fill_rep(*wkid, *fai, &b);
}

/* GSPAR(WKID, PAI, DIMX, DIMY, ISC, ISR, DX, DY, COLIA(DIMX, DIMY)) */
FAPI void FNAME(gspar, GSPAR)(const fint *wkid, const fint *pai, const fint *dimx,
                              const fint *dimy, const fint *isc, const fint *isr,
                              const fint *dx, const fint *dy, const fint *colia)
{
    Gpat_rep a;
    if (sub_array(*dimx, *dimy, *isc, *isr, *dx, *dy, colia, &a, GFN_SPAR))
        return;
    gset_pat_rep(*wkid, *pai, &a);
    free(a.colr_array);
}

/* GSEDR(WKID, EDI, EDFLAG, EDTYPE, EDWSF, EDCI) */
FAPI void FNAME(gsedr, GSEDR)(const fint *wkid, const fint *edi, const fint *flag,
                              const fint *type, const freal *width, const fint *coli)
{
    Gedge_bundle b = { (Gedge_flag)*flag, *type, *width, *coli };
    gset_edge_rep(*wkid, *edi, &b);
}

/* ------------------------------------------------------------------ current values */
#define INQ_I(lower, UPPER, CALL) \
    FAPI void FNAME(lower, UPPER)(fint *errind, fint *v) { CALL(errind, v); }
#define INQ_R(lower, UPPER, CALL)                                \
    FAPI void FNAME(lower, UPPER)(fint *errind, freal *v)        \
    {                                                            \
        Gfloat d = 0;                                            \
        CALL(errind, &d);                                        \
        if (!*errind)                                            \
            *v = (freal)d;                                       \
    }
#define INQ_E(lower, UPPER, CALL, TYPE)                          \
    FAPI void FNAME(lower, UPPER)(fint *errind, fint *v)         \
    {                                                            \
        TYPE d;                                                  \
        CALL(errind, &d);                                        \
        if (!*errind)                                            \
            *v = (fint)d;                                        \
    }
INQ_I(gqpli, GQPLI, ginq_line_ind)
INQ_I(gqln, GQLN, ginq_linetype)
INQ_R(gqlwsc, GQLWSC, ginq_linewidth)
INQ_I(gqpmi, GQPMI, ginq_marker_ind)
INQ_I(gqmk, GQMK, ginq_marker_type)
INQ_R(gqmksc, GQMKSC, ginq_marker_size)
INQ_I(gqpmci, GQPMCI, ginq_marker_colr_ind)
INQ_I(gqtxi, GQTXI, ginq_text_ind)
INQ_R(gqchxp, GQCHXP, ginq_char_expan)
INQ_R(gqchsp, GQCHSP, ginq_char_space)
INQ_I(gqtxci, GQTXCI, ginq_text_colr_ind)
INQ_R(gqchh, GQCHH, ginq_char_ht)
INQ_R(gqchw, GQCHW, ginq_char_width)
INQ_E(gqtxp, GQTXP, ginq_text_path, Gtext_path)
INQ_I(gqfai, GQFAI, ginq_fill_ind)
INQ_E(gqfais, GQFAIS, ginq_fill_int_style, Gfill_int_style)
INQ_I(gqfasi, GQFASI, ginq_fill_style_ind)
INQ_I(gqpkid, GQPKID, ginq_pick_id)
INQ_I(gqhrid, GQHRID, ginq_hlhsr_id)
INQ_E(gqedfg, GQEDFG, ginq_edge_flag, Gedge_flag)
INQ_I(gqedt, GQEDT, ginq_edgetype)
INQ_R(gqewsc, GQEWSC, ginq_edgewidth)
INQ_I(gqedci, GQEDCI, ginq_edge_colr_ind)
INQ_I(gqedi, GQEDI, ginq_edge_ind)

FAPI void FNAME(gqtxfp, GQTXFP)(fint *errind, fint *font, fint *prec)
{
    Gtext_font_prec fp;
    ginq_text_font_prec(errind, &fp);
    if (*errind)
        return;
    *font = fp.font;
    *prec = (fint)fp.prec;
}

static void put_vec(void (*f)(Gint *, Gvec *), fint *errind, freal *x, freal *y)
{
    Gvec v;
    f(errind, &v);
    if (*errind)
        return;
    *x = (freal)v.delta_x;
    *y = (freal)v.delta_y;
}

FAPI void FNAME(gqchup, GQCHUP)(fint *errind, freal *x, freal *y) { put_vec(ginq_char_up_vec, errind, x, y); }
FAPI void FNAME(gqchb, GQCHB)(fint *errind, freal *x, freal *y) { put_vec(ginq_char_base_vec, errind, x, y); }

FAPI void FNAME(gqtxal, GQTXAL)(fint *errind, fint *h, fint *v)
{
    Gtext_align a;
    ginq_text_align(errind, &a);
    if (*errind)
        return;
    *h = (fint)a.hor;
    *v = (fint)a.vert;
}

/* GQPA(ERRIND, PWX, PWY, PHX, PHY): the pattern width and height vectors (pattern size
 * along the first two coordinates of the pattern reference vectors). */
FAPI void FNAME(gqpa, GQPA)(fint *errind, freal *pwx, freal *pwy, freal *phx, freal *phy)
{
    Gvec w, h;
    ginq_pat_width_vec(errind, &w);
    if (*errind)
        return;
    ginq_pat_ht_vec(errind, &h);
    *pwx = (freal)w.delta_x;
    *pwy = (freal)w.delta_y;
    *phx = (freal)h.delta_x;
    *phy = (freal)h.delta_y;
}

FAPI void FNAME(gqparf, GQPARF)(fint *errind, freal *x, freal *y)
{
    Gpoint p;
    ginq_pat_ref_point(errind, &p);
    if (*errind)
        return;
    *x = (freal)p.x;
    *y = (freal)p.y;
}

/* GQPRPV(ERRIND, RFX, RFY, RFZ, VX(2), VY(2), VZ(2)) [I] */
FAPI void FNAME(gqprpv, GQPRPV)(fint *errind, freal *x, freal *y, freal *z, freal *vx,
                                freal *vy, freal *vz)
{
    Gpoint3 p;
    Gvec3 v[2];
    ginq_pat_ref_point_vecs(errind, &p, v);
    if (*errind)
        return;
    *x = (freal)p.x; *y = (freal)p.y; *z = (freal)p.z;
    for (int k = 0; k < 2; k++) {
        vx[k] = (freal)v[k].delta_x;
        vy[k] = (freal)v[k].delta_y;
        vz[k] = (freal)v[k].delta_z;
    }
}

/* GQASF(ERRIND, LASF(13)) / GQASF3(ERRIND, LASF(17)) [I] */
static void asfs_out(fint *errind, fint *lasf, int n)
{
    Gasfs3 a;
    ginq_asfs3(errind, &a);
    if (*errind)
        return;
    const Gasf *f13 = &a.asfs.linetype;
    for (int i = 0; i < 13; i++)
        lasf[i] = (fint)f13[i];
    if (n == 17) {
        lasf[13] = (fint)a.edge_flag;
        lasf[14] = (fint)a.edgetype;
        lasf[15] = (fint)a.edgewidth;
        lasf[16] = (fint)a.edge_colr_ind;
    }
}

FAPI void FNAME(gqasf, GQASF)(fint *errind, fint *lasf) { asfs_out(errind, lasf, 13); }
FAPI void FNAME(gqasf3, GQASF3)(fint *errind, fint *lasf) { asfs_out(errind, lasf, 17); }

/* ------------------------------------------------------------------ ws representations */
FAPI void FNAME(gqplr, GQPLR)(const fint *wkid, const fint *pli, const fint *type, fint *errind,
                              fint *ltype, freal *lwidth, fint *coli)
{
    Gline_bundle b;
    ginq_line_rep(*wkid, *pli, (Ginq_type)*type, errind, &b);
    if (*errind)
        return;
    *ltype = b.type;
    *lwidth = (freal)b.width;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqpmr, GQPMR)(const fint *wkid, const fint *pmi, const fint *type, fint *errind,
                              fint *mtype, freal *mszsf, fint *coli)
{
    Gmarker_bundle b;
    ginq_marker_rep(*wkid, *pmi, (Ginq_type)*type, errind, &b);
    if (*errind)
        return;
    *mtype = b.type;
    *mszsf = (freal)b.size;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqtxr, GQTXR)(const fint *wkid, const fint *txi, const fint *type, fint *errind,
                              fint *font, fint *prec, freal *chxp, freal *chsp, fint *coli)
{
    Gtext_bundle b;
    ginq_text_rep(*wkid, *txi, (Ginq_type)*type, errind, &b);
    if (*errind)
        return;
    *font = b.text_font_prec.font;
    *prec = (fint)b.text_font_prec.prec;
    *chxp = (freal)b.char_expan;
    *chsp = (freal)b.char_space;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqfar, GQFAR)(const fint *wkid, const fint *fai, const fint *type, fint *errind,
                              fint *ints, fint *styli, fint *coli)
{
    Gfill_bundle b;
    ginq_fill_rep(*wkid, *fai, (Ginq_type)*type, errind, &b);
    if (*errind)
        return;
    *ints = (fint)b.int_style;
    *styli = b.style_ind;
    *coli = b.colr_ind;
}

/* GQEDR(WKID, EDI, TYPE, ERRIND, EDFLAG, EDTYPE, EDWSF, EDCI) [I] */
FAPI void FNAME(gqedr, GQEDR)(const fint *wkid, const fint *edi, const fint *type, fint *errind,
                              fint *flag, fint *etype, freal *ewsf, fint *coli)
{
    Gedge_bundle b;
    ginq_edge_rep(*wkid, *edi, (Ginq_type)*type, errind, &b);
    if (*errind)
        return;
    *flag = (fint)b.flag;
    *etype = b.type;
    *ewsf = (freal)b.width;
    *coli = b.colr_ind;
}

/* A pattern into PARRAY(NMX, MMX): N columns, M rows; 2001 if it does not fit. */
static void pattern_out(const Gpat_rep *r, fint nmx, fint mmx, fint *errind, fint *n, fint *m,
                        fint *parray)
{
    *n = r->dims.size_x;
    *m = r->dims.size_y;
    if (*n > nmx || *m > mmx) {
        *errind = 2001;
        return;
    }
    for (fint j = 0; j < *m; j++)
        for (fint i = 0; i < *n; i++)
            parray[(size_t)i + (size_t)j * (size_t)nmx] = r->colr_array[(size_t)j * (size_t)*n + (size_t)i];
}

/* GQPAR(WKID, PAI, TYPE, NMX, MMX, ERRIND, N, M, PARRAY(NMX, MMX)) */
FAPI void FNAME(gqpar, GQPAR)(const fint *wkid, const fint *pai, const fint *type,
                              const fint *nmx, const fint *mmx, fint *errind, fint *n, fint *m,
                              fint *parray)
{
    Gstore st = NULL;
    Gpat_rep *r = NULL;
    gcreate_store(errind, &st);
    if (*errind)
        return;
    ginq_pat_rep(*wkid, *pai, (Ginq_type)*type, &st, errind, &r);
    if (!*errind)
        pattern_out(r, *nmx, *mmx, errind, n, m, parray);
    gdel_store(st);
}

/* List of defined indices: N = element wanted (1-based), N = 0 only the count. */
typedef void (*inds_inq)(Gint, Gint, Gint, Gint *, Gint_list *, Gint *);
static void inds_elem(inds_inq f, fint wkid, fint n, fint *errind, fint *ol, fint *elem)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    f(wkid, n > 0 ? 1 : 0, n > 0 ? n - 1 : (n == 0 ? 0 : -1), errind, &l, &len);
    *ol = len;
    if (*errind == 0 && n > len)
        *errind = 2002;
    if (*errind == 0 && n > 0)
        *elem = v;
}

#define INDS(lower, UPPER, CALL)                                                      \
    FAPI void FNAME(lower, UPPER)(const fint *wkid, const fint *n, fint *errind,     \
                                  fint *ol, fint *ind)                               \
    {                                                                                 \
        inds_elem(CALL, *wkid, *n, errind, ol, ind);                                  \
    }
INDS(gqepli, GQEPLI, ginq_list_line_inds)
INDS(gqepmi, GQEPMI, ginq_list_marker_inds)
INDS(gqetxi, GQETXI, ginq_list_text_inds)
INDS(gqefai, GQEFAI, ginq_list_fill_inds)
INDS(gqepai, GQEPAI, ginq_list_pat_inds)
INDS(gqeedi, GQEEDI, ginq_list_edge_inds)

/* ------------------------------------------------------------------ text extent */
static void extent_n(fint wkid, freal px, freal py, const char *s, size_t len, fint *errind,
                     freal *cpx, freal *cpy, freal *tx, freal *ty)
{
    char *t = text_str(s, len, GFN_TX);
    if (!t) {
        *errind = 300;
        return;
    }
    Gpoint p = { px, py };
    Gtext_extent e;
    ginq_text_extent(wkid, &p, t, errind, &e);
    free(t);
    if (*errind)
        return;
    *cpx = (freal)e.concat_point.x;
    *cpy = (freal)e.concat_point.y;
    for (int i = 0; i < 4; i++) {
        tx[i] = (freal)e.paral[i].x;
        ty[i] = (freal)e.paral[i].y;
    }
}

/* GQTXX(WKID, PX, PY, STR, ERRIND, CPX, CPY, TXEXPX(4), TXEXPY(4)); subset GQTXXS with
 * LSTR before STR. */
FAPI void FNAME(gqtxx, GQTXX)(const fint *wkid, const freal *px, const freal *py,
                              const char *str, fint *errind, freal *cpx, freal *cpy,
                              freal *tx, freal *ty, size_t len)
{
    extent_n(*wkid, *px, *py, str, len, errind, cpx, cpy, tx, ty);
}

FAPI void FNAME(gqtxxs, GQTXXS)(const fint *wkid, const freal *px, const freal *py,
                                const fint *lstr, const char *str, fint *errind, freal *cpx,
                                freal *cpy, freal *tx, freal *ty, size_t len)
{
    size_t n = *lstr < 0 ? 0 : (size_t)*lstr;
    extent_n(*wkid, *px, *py, str, n < len ? n : len, errind, cpx, cpy, tx, ty);
}

/* GQTXX3(WKID, PX, PY, PZ, TDX(2), TDY(2), TDZ(2), STR, ERRIND, CPX, CPY, CPZ, TXEXPX(4),
 * TXEXPY(4), TXEXPZ(4)) [I] */
FAPI void FNAME(gqtxx3, GQTXX3)(const fint *wkid, const freal *px, const freal *py,
                                const freal *pz, const freal *tdx, const freal *tdy,
                                const freal *tdz, const char *str, fint *errind, freal *cpx,
                                freal *cpy, freal *cpz, freal *tx, freal *ty, freal *tz,
                                size_t len)
{
    char *t = text_str(str, len, GFN_TX3);
    if (!t) {
        *errind = 300;
        return;
    }
    Gpoint3 p = { *px, *py, *pz };
    Gvec3 d[2];
    two_vecs(tdx, tdy, tdz, d);
    Gtext_extent3 e;
    ginq_text_extent3(*wkid, &p, d, t, errind, &e);
    free(t);
    if (*errind)
        return;
    *cpx = (freal)e.concat_point.x;
    *cpy = (freal)e.concat_point.y;
    *cpz = (freal)e.concat_point.z;
    for (int i = 0; i < 4; i++) {
        tx[i] = (freal)e.paral[i].x;
        ty[i] = (freal)e.paral[i].y;
        tz[i] = (freal)e.paral[i].z;
    }
}

/* ------------------------------------------------------------------ description tables */
/* Element n (1-based; 0 = counts only) of a facilities list: the count in *ol, the element
 * in *elem; 2002 if n is outside. */
static void facs_elem(int err, const Gint_list *l, Gint len, fint n, fint *errind, fint *ol,
                      fint *elem)
{
    *errind = err;
    if (err)
        return;
    *ol = len;
    if (n < 0 || n > len)
        *errind = 2002;
    else if (n > 0 && l->num_ints > 0)
        *elem = l->ints[0];
}

/* GQPLF(WTYPE, N, ERRIND, NLT, LT, NLW, NOMLW, RLWMIN, RLWMAX, NPPLI) */
FAPI void FNAME(gqplf, GQPLF)(const fint *wtype, const fint *n, fint *errind, fint *nlt,
                              fint *lt, fint *nlw, freal *nomlw, freal *rlwmin, freal *rlwmax,
                              fint *nppli)
{
    Gint v = 0, len = 0;
    Gline_facs f = { .types = { 0, &v } };
    ginq_line_facs(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : 0, errind, &f, &len);
    if (*errind == 2002) /* element out of range: still report the counts */
        ginq_line_facs(*wtype, 0, 0, errind, &f, &len);
    if (*errind)
        return;
    facs_elem(0, &f.types, len, *n, errind, nlt, lt);
    *nlw = f.num_widths;
    *nomlw = (freal)f.nom_width;
    *rlwmin = (freal)f.min_width;
    *rlwmax = (freal)f.max_width;
    *nppli = f.num_pred_inds;
}

/* GQPMF(WTYPE, N, ERRIND, NMT, MT, NMS, NOMMS, RMSMIN, RMSMAX, NPPMI) */
FAPI void FNAME(gqpmf, GQPMF)(const fint *wtype, const fint *n, fint *errind, fint *nmt,
                              fint *mt, fint *nms, freal *nomms, freal *rmsmin, freal *rmsmax,
                              fint *nppmi)
{
    Gint v = 0, len = 0;
    Gmarker_facs f = { .types = { 0, &v } };
    ginq_marker_facs(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : 0, errind, &f, &len);
    if (*errind == 2002)
        ginq_marker_facs(*wtype, 0, 0, errind, &f, &len);
    if (*errind)
        return;
    facs_elem(0, &f.types, len, *n, errind, nmt, mt);
    *nms = f.num_sizes;
    *nomms = (freal)f.nom_size;
    *rmsmin = (freal)f.min_size;
    *rmsmax = (freal)f.max_size;
    *nppmi = f.num_pred_inds;
}

/* GQTXF(WTYPE, N, ERRIND, NFPP, FONT, PREC, NCHH, MINCHH, MAXCHH, NCHX, MINCHX, MAXCHX,
 * NPTXI) */
FAPI void FNAME(gqtxf, GQTXF)(const fint *wtype, const fint *n, fint *errind, fint *nfpp,
                              fint *font, fint *prec, fint *nchh, freal *minchh, freal *maxchh,
                              fint *nchx, freal *minchx, freal *maxchx, fint *nptxi)
{
    Gtext_font_prec fp = { 0, GPREC_STRING };
    Gint len = 0;
    Gtext_facs f = { .num_font_precs = 0, .font_precs = &fp };
    ginq_text_facs(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : 0, errind, &f, &len);
    if (*errind == 2002)
        ginq_text_facs(*wtype, 0, 0, errind, &f, &len);
    if (*errind)
        return;
    *nfpp = len;
    if (*n < 0 || *n > len) {
        *errind = 2002;
    } else if (*n > 0) {
        *font = fp.font;
        *prec = (fint)fp.prec;
    }
    *nchh = f.num_char_hts;
    *minchh = (freal)f.min_char_ht;
    *maxchh = (freal)f.max_char_ht;
    *nchx = f.num_char_expans;
    *minchx = (freal)f.min_char_expan;
    *maxchx = (freal)f.max_char_expan;
    *nptxi = f.num_pred_inds;
}

/* GQFAF(WTYPE, NI, NH, ERRIND, NIS, IS, NHS, HS, NPFAI): element NI of the interior styles,
 * element NH of the hatch styles. */
FAPI void FNAME(gqfaf, GQFAF)(const fint *wtype, const fint *ni, const fint *nh, fint *errind,
                              fint *nis, fint *is, fint *nhs, fint *hs, fint *npfai)
{
    Gint vh[64], lh = 0;
    Gfill_facs f = { .hatch_styles = { 0, vh } };
    ginq_fill_facs(*wtype, 64, 0, errind, &f, &lh);
    if (*errind)
        return;
    *nis = f.num_int_styles;
    *nhs = lh;
    *npfai = f.num_pred_inds;
    if (*ni < 0 || *ni > f.num_int_styles || *nh < 0 || *nh > f.hatch_styles.num_ints) {
        *errind = 2002;
        return;
    }
    if (*ni > 0)
        *is = (fint)f.int_style[*ni - 1];
    if (*nh > 0)
        *hs = vh[*nh - 1];
}

FAPI void FNAME(gqpaf, GQPAF)(const fint *wtype, fint *errind, fint *nppai)
{
    ginq_pat_facs(*wtype, errind, nppai);
}

/* GQEDF(WTYPE, N, ERRIND, NET, ET, NEW, NOMEW, REWMIN, REWMAX, NPEDI) [I] */
FAPI void FNAME(gqedf, GQEDF)(const fint *wtype, const fint *n, fint *errind, fint *net,
                              fint *et, fint *new_, freal *nomew, freal *rewmin, freal *rewmax,
                              fint *npedi)
{
    Gint v = 0, len = 0;
    Gedge_facs f = { .types = { 0, &v } };
    ginq_edge_facs(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : 0, errind, &f, &len);
    if (*errind == 2002)
        ginq_edge_facs(*wtype, 0, 0, errind, &f, &len);
    if (*errind)
        return;
    facs_elem(0, &f.types, len, *n, errind, net, et);
    *new_ = f.num_widths;
    *nomew = (freal)f.nom_width;
    *rewmin = (freal)f.min_width;
    *rewmax = (freal)f.max_width;
    *npedi = f.num_pred_inds;
}

FAPI void FNAME(gqpplr, GQPPLR)(const fint *wtype, const fint *pli, fint *errind, fint *ltype,
                                freal *lwidth, fint *coli)
{
    Gline_bundle b;
    ginq_pred_line_rep(*wtype, *pli, errind, &b);
    if (*errind)
        return;
    *ltype = b.type;
    *lwidth = (freal)b.width;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqppmr, GQPPMR)(const fint *wtype, const fint *pmi, fint *errind, fint *mtype,
                                freal *mszsf, fint *coli)
{
    Gmarker_bundle b;
    ginq_pred_marker_rep(*wtype, *pmi, errind, &b);
    if (*errind)
        return;
    *mtype = b.type;
    *mszsf = (freal)b.size;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqptxr, GQPTXR)(const fint *wtype, const fint *txi, fint *errind, fint *font,
                                fint *prec, freal *chxp, freal *chsp, fint *coli)
{
    Gtext_bundle b;
    ginq_pred_text_rep(*wtype, *txi, errind, &b);
    if (*errind)
        return;
    *font = b.text_font_prec.font;
    *prec = (fint)b.text_font_prec.prec;
    *chxp = (freal)b.char_expan;
    *chsp = (freal)b.char_space;
    *coli = b.colr_ind;
}

FAPI void FNAME(gqpfar, GQPFAR)(const fint *wtype, const fint *fai, fint *errind, fint *ints,
                                fint *styli, fint *coli)
{
    Gfill_bundle b;
    ginq_pred_fill_rep(*wtype, *fai, errind, &b);
    if (*errind)
        return;
    *ints = (fint)b.int_style;
    *styli = b.style_ind;
    *coli = b.colr_ind;
}

/* GQPEDR(WTYPE, EDI, ERRIND, EDFLAG, EDTYPE, EDWSF, EDCI) [I] */
FAPI void FNAME(gqpedr, GQPEDR)(const fint *wtype, const fint *edi, fint *errind, fint *flag,
                                fint *etype, freal *ewsf, fint *coli)
{
    Gedge_bundle b;
    ginq_pred_edge_rep(*wtype, *edi, errind, &b);
    if (*errind)
        return;
    *flag = (fint)b.flag;
    *etype = b.type;
    *ewsf = (freal)b.width;
    *coli = b.colr_ind;
}

/* GQPPAR(WTYPE, PPAI, NMX, MMX, ERRIND, N, M, PARRAY(NMX, MMX)) */
FAPI void FNAME(gqppar, GQPPAR)(const fint *wtype, const fint *pai, const fint *nmx,
                                const fint *mmx, fint *errind, fint *n, fint *m, fint *parray)
{
    Gstore st = NULL;
    Gpat_rep *r = NULL;
    gcreate_store(errind, &st);
    if (*errind)
        return;
    ginq_pred_pat_rep(*wtype, *pai, &st, errind, &r);
    if (!*errind)
        pattern_out(r, *nmx, *mmx, errind, n, m, parray);
    gdel_store(st);
}

/* GQLWK(WTYPE, ERRIND, MPLBTE, MPMBTE, MTXBTE, MFABTE, MPAI, MCOLI) */
FAPI void FNAME(gqlwk, GQLWK)(const fint *wtype, fint *errind, fint *mpl, fint *mpm, fint *mtx,
                              fint *mfa, fint *mpa, fint *mcoli)
{
    Gmax_ws_st_tables t;
    ginq_max_ws_st_tables(*wtype, errind, &t);
    if (*errind)
        return;
    *mpl = t.line_bundles;
    *mpm = t.marker_bundles;
    *mtx = t.text_bundles;
    *mfa = t.fill_bundles;
    *mpa = t.pat_reps;
    *mcoli = t.colr_reps;
}

/* GQEGDP(WTYPE, N, ERRIND, NGDP, GDPL): the N-th available GDP (N = 0: count only). */
FAPI void FNAME(gqegdp, GQEGDP)(const fint *wtype, const fint *n, fint *errind, fint *ngdp,
                                fint *gdpl)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    ginq_list_avail_gdps(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : (*n == 0 ? 0 : -1),
                         errind, &l, &len);
    if (*errind == 0 || *errind == 2002)
        *ngdp = len;
    if (*errind == 0 && *n > 0)
        *gdpl = v;
}

/* GQGDP(WTYPE, GDP, ERRIND, NBND, BNDL(4)): the bundles a GDP uses (GPLATT = 0 ...
 * GFAATT = 3); ERRIND 41 for a GDP the type cannot generate. */
FAPI void FNAME(gqgdp, GQGDP)(const fint *wtype, const fint *gdp, fint *errind, fint *nbnd,
                              fint *bndl)
{
    Gint n = 0;
    Gattrs a[4];
    ginq_gdp(*wtype, *gdp, errind, &n, a);
    if (*errind)
        return;
    *nbnd = n;
    for (Gint i = 0; i < n; i++)
        bndl[i] = (fint)a[i];
}
