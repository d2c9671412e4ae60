/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_input.c -- FORTRAN 77 binding of the input functions (ISO 8651-1 names and
 * argument lists, as in RAL GKS libraries/gks/base, e.g. gqsts.f): GINLC GINSK GINVL
 * GINCH GINPK GINST, GSLCM GSSKM GSVLM GSCHM GSPKM GSSTM, GRQLC GRQSK GRQVL GRQCH GRQPK
 * GRQST, GSMLC GSMSK GSMVL GSMCH GSMPK GSMST, GWAIT GFLUSH, GGTLC GGTSK GGTVL GGTCH
 * GGTPK GGTST, GQLCS GQSKS GQVLS GQCHS GQPKS GQSTS, GQDLC GQDSK GQDVL GQDCH GQDPK GQDST,
 * GQLI, GQIQOV, GQSIM; GPREC, GUREC; the 3-D forms GINLC3 ... GQDST3; the subset string
 * forms GINSTS GRQSTS GSMSTS GGTSTS GQSTSS (argument lists: docs/INPUT.md).
 *
 * Thin wrappers over gks_input.c (which makes the standard's checks and reports the
 * errors; the input model: docs/INPUT.md). Enumerations pass unchanged
 * (GNONE/GOK/GNCHOI, GREQU/GSAMPL/GEVENT, GNECHO/GECHO, GNCLAS..GSTRIN have the C values).
 * Data records DATREC(LDR) are CHARACTER arrays passed to C as their LDR * LEN(DATREC(1))
 * characters; inquiries return the record's characters the same way. Output strings are
 * blank-padded; output arrays get at most their declared size (N).
 */
#include "gks_binding.h"
#include "gks_rec.h"
#include "gks_fortran.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static Glimit echo_area(const freal *xmin, const freal *xmax, const freal *ymin,
                        const freal *ymax)
{
    return (Glimit){ *xmin, *xmax, *ymin, *ymax };
}

/* The characters of DATREC(LDR) as a data record (none for LDR <= 0). */
static Gin_data record_in(fint ldr, const char *datrec, size_t elem_len)
{
    return (Gin_data){ 0, NULL, 0, NULL, ldr > 0 ? (size_t)ldr * elem_len : 0, datrec };
}

/* A record's characters into DATREC(MLDR), blank-padded; *ldr = elements used.
 * Returns 0 or 2001 (DATREC too small). */
static fint record_out(const Gin_data *r, fint mldr, fint *ldr, char *datrec, size_t elem_len)
{
    size_t cap = mldr > 0 ? (size_t)mldr * elem_len : 0;
    size_t n = r->str ? r->str_len : 0;
    if (cap)
        memset(datrec, ' ', cap);
    *ldr = elem_len ? (fint)((n + elem_len - 1) / elem_len) : 0;
    if (n > cap)
        return 2001;
    if (n)
        memcpy(datrec, r->str, n);
    return 0;
}

/* A C string buffer for a CHARACTER*(len) output ("" on entry); NULL: 300 reported. */
static char *str_buffer(size_t len, Gint fctid)
{
    char *b = len < SIZE_MAX ? gks_f77_alloc(len + 1, 1) : NULL;
    if (!b)
        gks_f77_nomem(fctid);
    else
        b[0] = '\0';
    return b;
}

/* A buffer for a string the core returns (REQUEST, SAMPLE, GET STRING): the C functions
 * write the whole input string, up to the device's buffer size, which may exceed
 * LEN(STR) (str_len); fill_fstr then truncates. 1024 = the largest string buffer of any
 * device (GKS_IN_STRING_MAX, docs/INPUT.md). */
#define STRING_RESULT_MAX 1024

static char *result_buffer(size_t str_len, Gint fctid)
{
    return str_buffer(str_len > STRING_RESULT_MAX ? str_len : STRING_RESULT_MAX, fctid);
}

/* The stroke state inquiries ask the core with room for the largest initial stroke
 * (GKS_IN_STROKE_MAX points) so that NP is the stroke's size and ERRIND 2001 tells that
 * N is too small (the C functions fill at most the capacity given). */
#define STROKE_INQ_MAX 1024

/* Points buffer of capacity n (none for n <= 0). Returns -1 when out of memory, with 300
 * reported for fctid unless fctid < 0 (inquiries report through ERRIND). */
static int stroke_buffer(Gstroke *s, fint n, Gint fctid)
{
    *s = (Gstroke){ 0, n > 0 ? n : 0, NULL };
    if (n <= 0)
        return 0;
    if (!(s->points = gks_f77_alloc((size_t)n, sizeof *s->points))) {
        if (fctid >= 0)
            gks_f77_nomem(fctid);
        return -1;
    }
    return 0;
}

/* A stroke into Fortran arrays of size n: *np points, at most n copied. */
static void stroke_out(const Gstroke *s, fint n, fint *tnr, fint *np, freal *px, freal *py)
{
    *tnr = s->norm_tran_num;
    *np = s->num_points;
    for (fint i = 0; i < s->num_points && i < n && s->points; i++) {
        px[i] = (freal)s->points[i].x;
        py[i] = (freal)s->points[i].y;
    }
}

/* ---- INITIALISE ---- */

/* GINLC(WKID, LCDNR, TNR, PX, PY, PET, XMIN, XMAX, YMIN, YMAX, LDR, DATREC) */
FAPI void FNAME(ginlc, GINLC)(const fint *wkid, const fint *lcdnr, const fint *tnr,
                              const freal *px, const freal *py, const fint *pet,
                              const freal *xmin, const freal *xmax, const freal *ymin,
                              const freal *ymax, const fint *ldr, const char *datrec,
                              size_t datrec_len)
{
    Gloc l = { *tnr, { *px, *py } };
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_loc(*wkid, *lcdnr, &l, *pet, &e, &d);
}

/* GINSK(WKID, SKDNR, TNR, N, PXA, PYA, PET, XMIN, XMAX, YMIN, YMAX, BUFLEN, LDR, DATREC) */
FAPI void FNAME(ginsk, GINSK)(const fint *wkid, const fint *skdnr, const fint *tnr,
                              const fint *n, const freal *pxa, const freal *pya,
                              const fint *pet, const freal *xmin, const freal *xmax,
                              const freal *ymin, const freal *ymax, const fint *buflen,
                              const fint *ldr, const char *datrec, size_t datrec_len)
{
    Gstroke s;
    if (stroke_buffer(&s, *n, GFN_INSK))
        return;
    s.norm_tran_num = *tnr;
    s.num_points = *n;
    for (fint i = 0; i < *n; i++)
        s.points[i] = (Gpoint){ pxa[i], pya[i] };
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_stroke(*wkid, *skdnr, &s, *pet, &e, *buflen, &d);
    free(s.points);
}

/* GINVL(WKID, VLDNR, IVAL, PET, XMIN, XMAX, YMIN, YMAX, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(ginvl, GINVL)(const fint *wkid, const fint *vldnr, const freal *ival,
                              const fint *pet, const freal *xmin, const freal *xmax,
                              const freal *ymin, const freal *ymax, const freal *loval,
                              const freal *hival, const fint *ldr, const char *datrec,
                              size_t datrec_len)
{
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_val(*wkid, *vldnr, *ival, *pet, &e, *loval, *hival, &d);
}

/* GINCH(WKID, CHDNR, ISTAT, ICHNR, PET, XMIN, XMAX, YMIN, YMAX, LDR, DATREC) */
FAPI void FNAME(ginch, GINCH)(const fint *wkid, const fint *chdnr, const fint *istat,
                              const fint *ichnr, const fint *pet, const freal *xmin,
                              const freal *xmax, const freal *ymin, const freal *ymax,
                              const fint *ldr, const char *datrec, size_t datrec_len)
{
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_choice(*wkid, *chdnr, (Gin_status)*istat, *ichnr, *pet, &e, &d);
}

/* GINPK(WKID, PCDNR, ISTAT, ISGNA, IPCID, PET, XMIN, XMAX, YMIN, YMAX, LDR, DATREC) */
FAPI void FNAME(ginpk, GINPK)(const fint *wkid, const fint *pcdnr, const fint *istat,
                              const fint *isgna, const fint *ipcid, const fint *pet,
                              const freal *xmin, const freal *xmax, const freal *ymin,
                              const freal *ymax, const fint *ldr, const char *datrec,
                              size_t datrec_len)
{
    Gpick p = { *isgna, *ipcid };
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_pick(*wkid, *pcdnr, (Gin_status)*istat, &p, *pet, &e, &d);
}

/* GINST(WKID, STDNR, LSTR, ISTR, PET, XMIN, XMAX, YMIN, YMAX, BUFLEN, INIPOS, LDR, DATREC):
 * the initial string is the first LSTR characters of ISTR (at most LEN(ISTR)). */
FAPI void FNAME(ginst, GINST)(const fint *wkid, const fint *stdnr, const fint *lstr,
                              const char *istr, const fint *pet, const freal *xmin,
                              const freal *xmax, const freal *ymin, const freal *ymax,
                              const fint *buflen, const fint *inipos, const fint *ldr,
                              const char *datrec, size_t istr_len, size_t datrec_len)
{
    size_t n = *lstr > 0 ? (size_t)*lstr : 0;
    if (n > istr_len)
        n = istr_len;
    char *s = str_buffer(n, GFN_INST);
    if (!s)
        return;
    memcpy(s, istr, n);
    s[n] = '\0';
    Glimit e = echo_area(xmin, xmax, ymin, ymax);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_string(*wkid, *stdnr, s, *pet, &e, *buflen, *inipos, &d);
    free(s);
}

/* ---- SET MODE: G<S..M>(WKID, DNR, MODE, ESW) ---- */

#define F77_SET_MODE(lower, UPPER, cfn)                                                  \
    FAPI void FNAME(lower, UPPER)(const fint *wkid, const fint *dnr, const fint *mode,  \
                                  const fint *esw)                                      \
    {                                                                                   \
        cfn(*wkid, *dnr, (Gop_mode)*mode, (Gecho_switch)*esw);                          \
    }
F77_SET_MODE(gslcm, GSLCM, gset_loc_mode)
F77_SET_MODE(gsskm, GSSKM, gset_stroke_mode)
F77_SET_MODE(gsvlm, GSVLM, gset_val_mode)
F77_SET_MODE(gschm, GSCHM, gset_choice_mode)
F77_SET_MODE(gspkm, GSPKM, gset_pick_mode)
F77_SET_MODE(gsstm, GSSTM, gset_string_mode)
#undef F77_SET_MODE

/* ---- REQUEST ---- */

/* GRQLC(WKID, LCDNR, STAT, TNR, PX, PY) */
FAPI void FNAME(grqlc, GRQLC)(const fint *wkid, const fint *lcdnr, fint *stat, fint *tnr,
                              freal *px, freal *py)
{
    Gin_status s;
    Gloc l;
    greq_loc(*wkid, *lcdnr, &s, &l);
    *stat = s;
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
}

/* GRQSK(WKID, SKDNR, N, STAT, TNR, NP, PXA, PYA) */
FAPI void FNAME(grqsk, GRQSK)(const fint *wkid, const fint *skdnr, const fint *n, fint *stat,
                              fint *tnr, fint *np, freal *pxa, freal *pya)
{
    Gstroke k;
    Gin_status s = GIN_STATUS_NONE;
    *stat = GIN_STATUS_NONE;
    *tnr = *np = 0;
    if (stroke_buffer(&k, *n, GFN_RQSK))
        return;
    greq_stroke(*wkid, *skdnr, &s, &k);
    *stat = s;
    stroke_out(&k, *n, tnr, np, pxa, pya);
    free(k.points);
}

/* GRQVL(WKID, VLDNR, STAT, VAL) */
FAPI void FNAME(grqvl, GRQVL)(const fint *wkid, const fint *vldnr, fint *stat, freal *val)
{
    Gin_status s;
    Gfloat v;
    greq_val(*wkid, *vldnr, &s, &v);
    *stat = s;
    *val = (freal)v;
}

/* GRQCH(WKID, CHDNR, STAT, CHNR) */
FAPI void FNAME(grqch, GRQCH)(const fint *wkid, const fint *chdnr, fint *stat, fint *chnr)
{
    Gin_status s;
    Gint c;
    greq_choice(*wkid, *chdnr, &s, &c);
    *stat = s;
    *chnr = c;
}

/* GRQPK(WKID, PCDNR, STAT, SGNA, PCID) */
FAPI void FNAME(grqpk, GRQPK)(const fint *wkid, const fint *pcdnr, fint *stat, fint *sgna,
                              fint *pcid)
{
    Gin_status s;
    Gpick p;
    greq_pick(*wkid, *pcdnr, &s, &p);
    *stat = s;
    *sgna = p.seg_name;
    *pcid = p.pick_id;
}

/* GRQST(WKID, STDNR, STAT, LOSTR, STR) */
FAPI void FNAME(grqst, GRQST)(const fint *wkid, const fint *stdnr, fint *stat, fint *lostr,
                              char *str, size_t str_len)
{
    Gin_status s = GIN_STATUS_NONE;
    char *b = result_buffer(str_len, GFN_RQST);
    if (b)
        greq_string(*wkid, *stdnr, &s, b);
    *stat = s;
    *lostr = gks_f77_fill_str(b ? b : "", str, str_len);
    free(b);
}

/* ---- SAMPLE ---- */

/* GSMLC(WKID, LCDNR, TNR, PX, PY) */
FAPI void FNAME(gsmlc, GSMLC)(const fint *wkid, const fint *lcdnr, fint *tnr, freal *px,
                              freal *py)
{
    Gloc l;
    gsample_loc(*wkid, *lcdnr, &l);
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
}

/* GSMSK(WKID, SKDNR, N, TNR, NP, PXA, PYA) */
FAPI void FNAME(gsmsk, GSMSK)(const fint *wkid, const fint *skdnr, const fint *n, fint *tnr,
                              fint *np, freal *pxa, freal *pya)
{
    Gstroke k;
    *tnr = *np = 0;
    if (stroke_buffer(&k, *n, GFN_SMSK))
        return;
    gsample_stroke(*wkid, *skdnr, &k);
    stroke_out(&k, *n, tnr, np, pxa, pya);
    free(k.points);
}

/* GSMVL(WKID, VLDNR, VAL) */
FAPI void FNAME(gsmvl, GSMVL)(const fint *wkid, const fint *vldnr, freal *val)
{
    Gfloat v;
    gsample_val(*wkid, *vldnr, &v);
    *val = (freal)v;
}

/* GSMCH(WKID, CHDNR, STAT, CHNR) */
FAPI void FNAME(gsmch, GSMCH)(const fint *wkid, const fint *chdnr, fint *stat, fint *chnr)
{
    Gin_status s;
    Gint c;
    gsample_choice(*wkid, *chdnr, &s, &c);
    *stat = s;
    *chnr = c;
}

/* GSMPK(WKID, PCDNR, STAT, SGNA, PCID) */
FAPI void FNAME(gsmpk, GSMPK)(const fint *wkid, const fint *pcdnr, fint *stat, fint *sgna,
                              fint *pcid)
{
    Gin_status s;
    Gpick p;
    gsample_pick(*wkid, *pcdnr, &s, &p);
    *stat = s;
    *sgna = p.seg_name;
    *pcid = p.pick_id;
}

/* GSMST(WKID, STDNR, LOSTR, STR) */
FAPI void FNAME(gsmst, GSMST)(const fint *wkid, const fint *stdnr, fint *lostr, char *str,
                              size_t str_len)
{
    char *b = result_buffer(str_len, GFN_SMST);
    if (b)
        gsample_string(*wkid, *stdnr, b);
    *lostr = gks_f77_fill_str(b ? b : "", str, str_len);
    free(b);
}

/* ---- event input ---- */

/* GWAIT(TOUT, WKID, ICL, IDNR) */
FAPI void FNAME(gwait, GWAIT)(const freal *tout, fint *wkid, fint *icl, fint *idnr)
{
    Gint w, n;
    Gin_class c;
    gawait_event(*tout, &w, &c, &n);
    *wkid = w;
    *icl = c;
    *idnr = n;
}

/* GFLUSH(WKID, ICL, IDNR) */
FAPI void FNAME(gflush, GFLUSH)(const fint *wkid, const fint *icl, const fint *idnr)
{
    gflush_events(*wkid, (Gin_class)*icl, *idnr);
}

/* GGTLC(TNR, PX, PY) */
FAPI void FNAME(ggtlc, GGTLC)(fint *tnr, freal *px, freal *py)
{
    Gloc l;
    gget_loc(&l);
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
}

/* GGTSK(N, TNR, NP, PXA, PYA) */
FAPI void FNAME(ggtsk, GGTSK)(const fint *n, fint *tnr, fint *np, freal *pxa, freal *pya)
{
    Gstroke k;
    *tnr = *np = 0;
    if (stroke_buffer(&k, *n, GFN_GTSK))
        return;
    gget_stroke(&k);
    stroke_out(&k, *n, tnr, np, pxa, pya);
    free(k.points);
}

/* GGTVL(VAL) */
FAPI void FNAME(ggtvl, GGTVL)(freal *val)
{
    Gfloat v;
    gget_val(&v);
    *val = (freal)v;
}

/* GGTCH(STAT, CHNR) */
FAPI void FNAME(ggtch, GGTCH)(fint *stat, fint *chnr)
{
    Gin_status s;
    Gint c;
    gget_choice(&s, &c);
    *stat = s;
    *chnr = c;
}

/* GGTPK(STAT, SGNA, PCID) */
FAPI void FNAME(ggtpk, GGTPK)(fint *stat, fint *sgna, fint *pcid)
{
    Gin_status s;
    Gpick p;
    gget_pick(&s, &p);
    *stat = s;
    *sgna = p.seg_name;
    *pcid = p.pick_id;
}

/* GGTST(LOSTR, STR) */
FAPI void FNAME(ggtst, GGTST)(fint *lostr, char *str, size_t str_len)
{
    char *b = result_buffer(str_len, GFN_GTST);
    if (b)
        gget_string(b);
    *lostr = gks_f77_fill_str(b ? b : "", str, str_len);
    free(b);
}

/* ---- inquiries: ERRIND first; the other outputs only when ERRIND = 0 ---- */

/* The outputs common to the device state inquiries; returns ERRIND (0 or 2001). */
static fint dev_out(const Gin_dev_st *d, fint mldr, fint *mode, fint *esw, fint *pet,
                    freal *earea, fint *ldr, char *datrec, size_t datrec_len)
{
    *mode = d->op_mode;
    *esw = d->echo_switch;
    *pet = d->pet;
    earea[0] = (freal)d->echo_area.x_min;
    earea[1] = (freal)d->echo_area.x_max;
    earea[2] = (freal)d->echo_area.y_min;
    earea[3] = (freal)d->echo_area.y_max;
    return record_out(&d->in_data, mldr, ldr, datrec, datrec_len);
}

/* GQLCS(WKID, LCDNR, TYPE, MLDR, ERRIND, MODE, ESW, TNR, PX, PY, PET, EAREA, LDR, DATREC) */
FAPI void FNAME(gqlcs, GQLCS)(const fint *wkid, const fint *lcdnr, const fint *type,
                              const fint *mldr, fint *errind, fint *mode, fint *esw,
                              fint *tnr, freal *px, freal *py, fint *pet, freal *earea,
                              fint *ldr, char *datrec, size_t datrec_len)
{
    Gloc_st s = { 0 };
    ginq_loc_st(*wkid, *lcdnr, (Ginq_type)*type, errind, &s);
    if (*errind)
        return;
    *tnr = s.init_loc.norm_tran_num;
    *px = (freal)s.init_loc.position.x;
    *py = (freal)s.init_loc.position.y;
    *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
}

/* GQSKS(WKID, SKDNR, TYPE, N, MLDR, ERRIND, MODE, ESW, TNR, NP, PXA, PYA, PET, EAREA,
 *       BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqsks, GQSKS)(const fint *wkid, const fint *skdnr, const fint *type,
                              const fint *n, const fint *mldr, fint *errind, fint *mode,
                              fint *esw, fint *tnr, fint *np, freal *pxa, freal *pya,
                              fint *pet, freal *earea, fint *buflen, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gstroke_st s = { 0 };
    if (stroke_buffer(&s.init_stroke, *n > STROKE_INQ_MAX ? *n : STROKE_INQ_MAX, -1)) {
        *errind = 300;
        return;
    }
    ginq_stroke_st(*wkid, *skdnr, (Ginq_type)*type, errind, &s);
    if (!*errind) {
        stroke_out(&s.init_stroke, *n, tnr, np, pxa, pya);
        *buflen = s.in_buf_size;
        *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
        if (!*errind && *np > *n)
            *errind = 2001;
    }
    free(s.init_stroke.points);
}

/* GQVLS(WKID, VLDNR, MLDR, ERRIND, MODE, ESW, IVAL, PET, EAREA, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(gqvls, GQVLS)(const fint *wkid, const fint *vldnr, const fint *mldr,
                              fint *errind, fint *mode, fint *esw, freal *ival, fint *pet,
                              freal *earea, freal *loval, freal *hival, fint *ldr,
                              char *datrec, size_t datrec_len)
{
    Gval_st s = { 0 };
    ginq_val_st(*wkid, *vldnr, errind, &s);
    if (*errind)
        return;
    *ival = (freal)s.init_value;
    *loval = (freal)s.low_value;
    *hival = (freal)s.high_value;
    *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
}

/* GQCHS(WKID, CHDNR, MLDR, ERRIND, MODE, ESW, ISTAT, ICHNR, PET, EAREA, LDR, DATREC) */
FAPI void FNAME(gqchs, GQCHS)(const fint *wkid, const fint *chdnr, const fint *mldr,
                              fint *errind, fint *mode, fint *esw, fint *istat, fint *ichnr,
                              fint *pet, freal *earea, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gchoice_st s = { 0 };
    ginq_choice_st(*wkid, *chdnr, errind, &s);
    if (*errind)
        return;
    *istat = s.init_status;
    *ichnr = s.init_choice;
    *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
}

/* GQPKS(WKID, PCDNR, TYPE, MLDR, ERRIND, MODE, ESW, ISTAT, ISGNA, IPCID, PET, EAREA, LDR,
 *       DATREC) */
FAPI void FNAME(gqpks, GQPKS)(const fint *wkid, const fint *pcdnr, const fint *type,
                              const fint *mldr, fint *errind, fint *mode, fint *esw,
                              fint *istat, fint *isgna, fint *ipcid, fint *pet, freal *earea,
                              fint *ldr, char *datrec, size_t datrec_len)
{
    Gpick_st s = { 0 };
    ginq_pick_st(*wkid, *pcdnr, (Ginq_type)*type, errind, &s);
    if (*errind)
        return;
    *istat = s.init_status;
    *isgna = s.init_pick.seg_name;
    *ipcid = s.init_pick.pick_id;
    *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
}

/* GQSTS(WKID, STDNR, MLDR, ERRIND, MODE, ESW, LOSTR, ISTR, PET, EAREA, BUFLEN, INIPOS, LDR,
 *       DATREC) -- RAL's argument list (MLDR third; docs/BINDING.md) */
FAPI void FNAME(gqsts, GQSTS)(const fint *wkid, const fint *stdnr, const fint *mldr,
                              fint *errind, fint *mode, fint *esw, fint *lostr, char *istr,
                              fint *pet, freal *earea, fint *buflen, fint *inipos, fint *ldr,
                              char *datrec, size_t istr_len, size_t datrec_len)
{
    Gstring_st s = { 0 };
    s.init_string = istr_len < SIZE_MAX ? gks_f77_alloc(istr_len + 1, 1) : NULL;
    if (!s.init_string) {
        *errind = 300;
        return;
    }
    s.init_string[0] = '\0';
    s.init_string_size = istr_len + 1;
    ginq_string_st(*wkid, *stdnr, errind, &s);
    if (!*errind) {
        *lostr = gks_f77_fill_str(s.init_string, istr, istr_len);
        *buflen = s.in_buf_size;
        *inipos = s.init_cur_pos;
        *errind = dev_out(&s.dev, *mldr, mode, esw, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.init_string);
}

/* The outputs common to the default-data inquiries: element N of the prompt/echo types
 * (N = 0: only their number OL). Returns ERRIND (0, 2001, 2002 or 300). */
static fint def_out(const Gdef_in *d, fint n, fint mldr, fint *ol, fint *pet, freal *earea,
                    fint *ldr, char *datrec, size_t datrec_len)
{
    *ol = d->pets.num_ints;
    if (n < 0 || n > d->pets.num_ints)
        return 2002;
    if (n > 0)
        *pet = d->pets.ints[n - 1];
    earea[0] = (freal)d->echo_area.x_min;
    earea[1] = (freal)d->echo_area.x_max;
    earea[2] = (freal)d->echo_area.y_min;
    earea[3] = (freal)d->echo_area.y_max;
    return record_out(&d->in_data, mldr, ldr, datrec, datrec_len);
}

/* Room for the first n prompt/echo types (n <= 0: none). Returns -1 when out of memory. */
static int pets_buffer(Gdef_in *d, fint n)
{
    d->pets = (Gint_list){ n > 0 ? n : 0, NULL };
    if (n > 0 && !(d->pets.ints = gks_f77_alloc((size_t)n, sizeof(Gint))))
        return -1;
    return 0;
}

/* GQDLC(WTYPE, LCDNR, N, MLDR, ERRIND, DPX, DPY, OL, PET, EAREA, LDR, DATREC) */
FAPI void FNAME(gqdlc, GQDLC)(const fint *wtype, const fint *lcdnr, const fint *n,
                              const fint *mldr, fint *errind, freal *dpx, freal *dpy,
                              fint *ol, fint *pet, freal *earea, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gdef_loc s = { 0 };
    if (pets_buffer(&s.dev, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_loc_data(*wtype, *lcdnr, errind, &s);
    if (!*errind) {
        *dpx = (freal)s.loc_pos.x;
        *dpy = (freal)s.loc_pos.y;
        *errind = def_out(&s.dev, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDSK(WTYPE, SKDNR, N, MLDR, ERRIND, DBUFSK, OL, PET, EAREA, BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqdsk, GQDSK)(const fint *wtype, const fint *skdnr, const fint *n,
                              const fint *mldr, fint *errind, fint *dbufsk, fint *ol,
                              fint *pet, freal *earea, fint *buflen, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gdef_stroke s = { 0 };
    if (pets_buffer(&s.dev, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_stroke_data(*wtype, *skdnr, errind, &s);
    if (!*errind) {
        *dbufsk = s.max_buf_size;
        *buflen = s.buf_size;
        *errind = def_out(&s.dev, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDVL(WTYPE, VLDNR, N, MLDR, ERRIND, DVAL, OL, PET, EAREA, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(gqdvl, GQDVL)(const fint *wtype, const fint *vldnr, const fint *n,
                              const fint *mldr, fint *errind, freal *dval, fint *ol,
                              fint *pet, freal *earea, freal *loval, freal *hival, fint *ldr,
                              char *datrec, size_t datrec_len)
{
    Gdef_val s = { 0 };
    if (pets_buffer(&s.dev, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_val_data(*wtype, *vldnr, errind, &s);
    if (!*errind) {
        *dval = (freal)s.value;
        *loval = (freal)s.low_value;
        *hival = (freal)s.high_value;
        *errind = def_out(&s.dev, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDCH(WTYPE, CHDNR, N, MLDR, ERRIND, MALT, OL, PET, EAREA, LDR, DATREC) */
FAPI void FNAME(gqdch, GQDCH)(const fint *wtype, const fint *chdnr, const fint *n,
                              const fint *mldr, fint *errind, fint *malt, fint *ol,
                              fint *pet, freal *earea, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gdef_choice s = { 0 };
    if (pets_buffer(&s.dev, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_choice_data(*wtype, *chdnr, errind, &s);
    if (!*errind) {
        *malt = s.max_choices;
        *errind = def_out(&s.dev, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDPK(WTYPE, PCDNR, N, MLDR, ERRIND, OL, PET, EAREA, LDR, DATREC) */
FAPI void FNAME(gqdpk, GQDPK)(const fint *wtype, const fint *pcdnr, const fint *n,
                              const fint *mldr, fint *errind, fint *ol, fint *pet,
                              freal *earea, fint *ldr, char *datrec, size_t datrec_len)
{
    Gdef_in s = { 0 };
    if (pets_buffer(&s, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_pick_data(*wtype, *pcdnr, errind, &s);
    if (!*errind)
        *errind = def_out(&s, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    free(s.pets.ints);
}

/* GQDST(WTYPE, STDNR, N, MLDR, ERRIND, MBUFF, OL, PET, EAREA, BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqdst, GQDST)(const fint *wtype, const fint *stdnr, const fint *n,
                              const fint *mldr, fint *errind, fint *mbuff, fint *ol,
                              fint *pet, freal *earea, fint *buflen, fint *ldr, char *datrec,
                              size_t datrec_len)
{
    Gdef_string s = { 0 };
    if (pets_buffer(&s.dev, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_string_data(*wtype, *stdnr, errind, &s);
    if (!*errind) {
        *mbuff = s.max_buf_size;
        *buflen = s.buf_size;
        *errind = def_out(&s.dev, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQLI(WTYPE, ERRIND, NLCD, NSKD, NVLD, NCHD, NPCD, NSTD) */
FAPI void FNAME(gqli, GQLI)(const fint *wtype, fint *errind, fint *nlcd, fint *nskd,
                            fint *nvld, fint *nchd, fint *npcd, fint *nstd)
{
    Gnum_in n = { 0 };
    ginq_num_avail_in(*wtype, errind, &n);
    if (*errind)
        return;
    *nlcd = n.loc;
    *nskd = n.stroke;
    *nvld = n.val;
    *nchd = n.choice;
    *npcd = n.pick;
    *nstd = n.string;
}

/* GQIQOV(ERRIND, WKID, ICL, IDNR) */
FAPI void FNAME(gqiqov, GQIQOV)(fint *errind, fint *wkid, fint *icl, fint *idnr)
{
    Gint w = 0, n = 0;
    Gin_class c = GIN_NONE;
    ginq_in_overf(errind, &w, &c, &n);
    if (*errind)
        return;
    *wkid = w;
    *icl = c;
    *idnr = n;
}

/* GQSIM(ERRIND, FLAG) */
FAPI void FNAME(gqsim, GQSIM)(fint *errind, fint *flag)
{
    Gsimult_events f = GSIMULT_NO_MORE;
    ginq_more_simult_events(errind, &f);
    if (!*errind)
        *flag = f;
}

/* ---- GPREC / GUREC: the data record format of this implementation ----
 *
 * A packed record is a character stream laid over DATREC(1..LDR), element after element
 * (LEN(DATREC(1)) characters each), blank-padded at the end: "GKSR", the counts IL, RL,
 * SL, the IL integers, the RL reals (9 significant digits: a REAL round-trips) and the SL
 * string lengths, each as decimal text ended by ',', then the strings' characters. The
 * magic lets GUREC tell a packed record from other text (2003); decimal text keeps it
 * printable and small (gksdemo packs 32 integers into 4 elements of 80).
 *
 * Two forms of legacy call are accepted (docs/INPUT.md "Data records from Fortran"):
 * - STR as one string holding the SL strings one after the other (xgks's GPREC and its
 *   gksdemo.f: MENU = 'CONTINUERETURN', LSTR = 8, 6) instead of the standard's array
 *   STR(SL): taken when SL > 1, the lengths add up to at most LEN(STR) and STR(1) is not
 *   blank after its first LSTR(1) characters (an array element is blank-padded there);
 * - a CHARACTER actual argument for LSTR when SL = 0 (gksdemo: GPREC(0,IA,0,EMPTRP,0,
 *   DUMMYA,CHAR,...) with CHARACTER*1 CHAR): it shifts the hidden lengths, so the one
 *   received for DATREC is that of STR. With SL = 0 a DATREC length below
 *   REC_ELEM_MIN (shorter than the record's magic: no DATREC is declared so) is taken for
 *   that call and the standard's CHARACTER*80 is used. Every other length is DATREC's
 *   declared one and GPREC never writes past MLDR elements of it (issue 40 F). */

#define REC_MAGIC "GKSR"
#define REC_ELEM_STD 80 /* ISO 8651-1: DATREC is CHARACTER*80 */
#define REC_ELEM_MIN 4  /* strlen(REC_MAGIC): a shorter hidden length is the shifted call's */

typedef struct { char *buf; size_t n, cap; } rec_stream;

static int rec_put(rec_stream *s, const char *text, size_t n)
{
    if (s->n + n > s->cap)
        return -1;
    memcpy(s->buf + s->n, text, n);
    s->n += n;
    return 0;
}

static int rec_int(rec_stream *s, long v)
{
    char t[24];
    int k = snprintf(t, sizeof t, "%ld,", v);
    return rec_put(s, t, (size_t)k);
}

/* Whether STR holds the SL strings one after another (see above); lengths checked. */
static int str_concatenated(fint sl, const fint *lstr, const char *str, size_t str_len)
{
    size_t sum = 0;
    if (sl < 2)
        return 0;
    for (fint i = 0; i < sl; i++)
        sum += (size_t)lstr[i];
    if (sum > str_len)
        return 0;
    for (size_t k = (size_t)lstr[0]; k < sum; k++)
        if (str[k] != ' ')
            return 1;
    return 0;
}

/* GPREC(IL, IA, RL, RA, SL, LSTR, STR, MLDR, ERRIND, LDR, DATREC): STR(SL) strings of
 * LEN(STR) characters, the first LSTR(i) of each used. ERRIND 2001 if the record does
 * not fit into MLDR elements, 2003 for negative counts or lengths beyond LEN(STR). */
FAPI void FNAME(gprec, GPREC)(const fint *il, const fint *ia, const fint *rl, const freal *ra,
                              const fint *sl, const fint *lstr, const char *str,
                              const fint *mldr, fint *errind, fint *ldr, char *datrec,
                              size_t str_len, size_t datrec_len)
{
    *ldr = 0;
    if (*il < 0 || *rl < 0 || *sl < 0) {
        *errind = 2003;
        return;
    }
    for (fint i = 0; i < *sl; i++)
        if (lstr[i] < 0 || (size_t)lstr[i] > str_len) {
            *errind = 2003;
            return;
        }
    size_t elem = (*sl == 0 && datrec_len < REC_ELEM_MIN) ? REC_ELEM_STD : datrec_len;
    rec_stream s = { datrec, 0, *mldr > 0 ? (size_t)*mldr * elem : 0 };
    int bad = rec_put(&s, REC_MAGIC, 4) || rec_int(&s, *il) || rec_int(&s, *rl) ||
              rec_int(&s, *sl);
    for (fint i = 0; !bad && i < *il; i++)
        bad = rec_int(&s, ia[i]);
    for (fint i = 0; !bad && i < *rl; i++) {
        char t[32];
        int k = snprintf(t, sizeof t, "%.9g,", (double)ra[i]);
        bad = rec_put(&s, t, (size_t)k);
    }
    for (fint i = 0; !bad && i < *sl; i++)
        bad = rec_int(&s, lstr[i]);
    int concat = !bad && str_concatenated(*sl, lstr, str, str_len);
    size_t at = 0;
    for (fint i = 0; !bad && i < *sl; i++) {
        const char *from = concat ? str + at : str + (size_t)i * str_len;
        bad = rec_put(&s, from, (size_t)lstr[i]);
        at += (size_t)lstr[i];
    }
    if (bad) {
        *errind = 2001;
        return;
    }
    size_t used = elem ? (s.n + elem - 1) / elem : 0;
    memset(datrec + s.n, ' ', used * elem - s.n);
    *ldr = (fint)used;
    *errind = 0;
}

/* GUREC(LDR, DATREC, IIL, IRL, ISL, ERRIND, IL, IA, RL, RA, SL, LSTR, STR): IIL, IRL, ISL
 * are the sizes of IA, RA, STR/LSTR; IL, RL, SL the counts in the record (at most the
 * sizes are stored: ERRIND 2001 if any count exceeds its size, a string its LEN).
 * ERRIND 2003 if DATREC is no record packed by GPREC. */
FAPI void FNAME(gurec, GUREC)(const fint *ldr, const char *datrec, const fint *iil,
                              const fint *irl, const fint *isl, fint *errind, fint *il,
                              fint *ia, fint *rl, freal *ra, fint *sl, fint *lstr, char *str,
                              size_t datrec_len, size_t str_len)
{
    gks_rec_reader r;
    *il = *rl = *sl = 0;
    if (gks_rec_begin(&r, datrec, *ldr > 0 ? (size_t)*ldr * datrec_len : 0)) {
        *errind = 2003;
        return;
    }
    long n[3] = { r.il, r.rl, r.sl };
    fint e = 0;
    for (long i = 0; i < n[0]; i++) {
        long v;
        if (gks_rec_long(&r, &v)) {
            *errind = 2003;
            return;
        }
        if (i < *iil)
            ia[i] = (fint)v;
    }
    for (long i = 0; i < n[1]; i++) {
        double v;
        if (gks_rec_real(&r, &v)) {
            *errind = 2003;
            return;
        }
        if (i < *irl)
            ra[i] = (freal)v;
    }
    /* The SL lengths, then the characters: any number of strings GPREC packed (the
     * lengths are read twice, once to find where the characters begin). */
    gks_rec_reader lr = r;
    size_t total = 0;
    for (long i = 0; i < n[2]; i++) {
        long len;
        if (gks_rec_long(&r, &len) || len < 0 || (size_t)len > (size_t)(r.end - r.p) ||
            (total += (size_t)len) > (size_t)(r.end - r.p)) {
            *errind = 2003;
            return;
        }
    }
    if (total > (size_t)(r.end - r.p)) {
        *errind = 2003;
        return;
    }
    for (long i = 0; i < n[2]; i++) {
        long len;
        gks_rec_long(&lr, &len); /* read and checked above */
        if (i < *isl) {
            size_t k = (size_t)len < str_len ? (size_t)len : str_len;
            memcpy(str + (size_t)i * str_len, r.p, k);
            memset(str + (size_t)i * str_len + k, ' ', str_len - k);
            lstr[i] = (fint)k;
            if ((size_t)len > str_len)
                e = 2001;
        }
        r.p += len;
    }
    if (n[0] > *iil || n[1] > *irl || n[2] > *isl)
        e = 2001;
    *il = (fint)n[0];
    *rl = (fint)n[1];
    *sl = (fint)n[2];
    *errind = e;
}

/* ---- GKS-3D input (ISO 8806-1 style names; argument lists in bindings/fortran/README.md)
 * EVOL(6) = XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX of the echo volume (DC3). ---- */

static Glimit3 evol_in(const freal *v)
{
    return (Glimit3){ v[0], v[1], v[2], v[3], v[4], v[5] };
}

static void evol_out(const Glimit3 *l, freal *v)
{
    v[0] = (freal)l->x_min; v[1] = (freal)l->x_max; v[2] = (freal)l->y_min;
    v[3] = (freal)l->y_max; v[4] = (freal)l->z_min; v[5] = (freal)l->z_max;
}

/* GINLC3(WKID, LCDNR, VIEWI, TNR, PX, PY, PZ, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(ginlc3, GINLC3)(const fint *wkid, const fint *lcdnr, const fint *viewi,
                                const fint *tnr, const freal *px, const freal *py,
                                const freal *pz, const fint *pet, const freal *evol,
                                const fint *ldr, const char *datrec, size_t datrec_len)
{
    Gloc3 l = { *tnr, { *px, *py, *pz } };
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_loc3(*wkid, *lcdnr, *viewi, &l, *pet, &e, &d);
}

/* GINSK3(WKID, SKDNR, VIEWI, TNR, N, PXA, PYA, PZA, PET, EVOL, BUFLEN, LDR, DATREC) */
FAPI void FNAME(ginsk3, GINSK3)(const fint *wkid, const fint *skdnr, const fint *viewi,
                                const fint *tnr, const fint *n, const freal *pxa,
                                const freal *pya, const freal *pza, const fint *pet,
                                const freal *evol, const fint *buflen, const fint *ldr,
                                const char *datrec, size_t datrec_len)
{
    Gpoint3 *p = *n > 0 ? gks_f77_alloc((size_t)*n, sizeof *p) : NULL;
    if (*n > 0 && !p) {
        gks_f77_nomem(GFN_INSK3);
        return;
    }
    for (fint i = 0; i < *n; i++)
        p[i] = (Gpoint3){ pxa[i], pya[i], pza[i] };
    Gstroke3 s = { *tnr, *n, p };
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_stroke3(*wkid, *skdnr, *viewi, &s, *pet, &e, *buflen, &d);
    free(p);
}

/* GINVL3(WKID, VLDNR, IVAL, PET, EVOL, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(ginvl3, GINVL3)(const fint *wkid, const fint *vldnr, const freal *ival,
                                const fint *pet, const freal *evol, const freal *loval,
                                const freal *hival, const fint *ldr, const char *datrec,
                                size_t datrec_len)
{
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_val3(*wkid, *vldnr, *ival, *pet, &e, *loval, *hival, &d);
}

/* GINCH3(WKID, CHDNR, ISTAT, ICHNR, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(ginch3, GINCH3)(const fint *wkid, const fint *chdnr, const fint *istat,
                                const fint *ichnr, const fint *pet, const freal *evol,
                                const fint *ldr, const char *datrec, size_t datrec_len)
{
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_choice3(*wkid, *chdnr, (Gin_status)*istat, *ichnr, *pet, &e, &d);
}

/* GINPK3(WKID, PCDNR, ISTAT, ISGNA, IPCID, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(ginpk3, GINPK3)(const fint *wkid, const fint *pcdnr, const fint *istat,
                                const fint *isgna, const fint *ipcid, const fint *pet,
                                const freal *evol, const fint *ldr, const char *datrec,
                                size_t datrec_len)
{
    Gpick p = { *isgna, *ipcid };
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_pick3(*wkid, *pcdnr, (Gin_status)*istat, &p, *pet, &e, &d);
}

/* GINST3(WKID, STDNR, LSTR, ISTR, PET, EVOL, BUFLEN, INIPOS, LDR, DATREC) */
FAPI void FNAME(ginst3, GINST3)(const fint *wkid, const fint *stdnr, const fint *lstr,
                                const char *istr, const fint *pet, const freal *evol,
                                const fint *buflen, const fint *inipos, const fint *ldr,
                                const char *datrec, size_t istr_len, size_t datrec_len)
{
    size_t n = *lstr > 0 ? (size_t)*lstr : 0;
    if (n > istr_len)
        n = istr_len;
    char *s = str_buffer(n, GFN_INST3);
    if (!s)
        return;
    memcpy(s, istr, n);
    s[n] = '\0';
    Glimit3 e = evol_in(evol);
    Gin_data d = record_in(*ldr, datrec, datrec_len);
    ginit_string3(*wkid, *stdnr, s, *pet, &e, *buflen, *inipos, &d);
    free(s);
}

/* GRQLC3(WKID, LCDNR, STAT, VIEWI, TNR, PX, PY, PZ) */
FAPI void FNAME(grqlc3, GRQLC3)(const fint *wkid, const fint *lcdnr, fint *stat, fint *viewi,
                                fint *tnr, freal *px, freal *py, freal *pz)
{
    Gin_status st;
    Gloc3 l;
    greq_loc3(*wkid, *lcdnr, &st, viewi, &l);
    *stat = st;
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
    *pz = (freal)l.position.z;
}

/* A stroke 3 into Fortran arrays of size n. */
static void stroke3_out(const Gstroke3 *s, fint n, fint *tnr, fint *np, freal *px, freal *py,
                        freal *pz)
{
    *tnr = s->norm_tran_num;
    *np = s->num_points;
    for (fint i = 0; i < s->num_points && i < n && s->points; i++) {
        px[i] = (freal)s->points[i].x;
        py[i] = (freal)s->points[i].y;
        pz[i] = (freal)s->points[i].z;
    }
}

/* GRQSK3(WKID, SKDNR, N, STAT, VIEWI, TNR, NP, PXA, PYA, PZA) */
FAPI void FNAME(grqsk3, GRQSK3)(const fint *wkid, const fint *skdnr, const fint *n, fint *stat,
                                fint *viewi, fint *tnr, fint *np, freal *pxa, freal *pya,
                                freal *pza)
{
    Gpoint3 *p = *n > 0 ? gks_f77_alloc((size_t)*n, sizeof *p) : NULL;
    if (*n > 0 && !p) {
        gks_f77_nomem(GFN_RQSK3);
        return;
    }
    Gstroke3 s = { 0, *n > 0 ? *n : 0, p };
    Gin_status st;
    greq_stroke3(*wkid, *skdnr, &st, viewi, &s);
    *stat = st;
    stroke3_out(&s, *n, tnr, np, pxa, pya, pza);
    free(p);
}

/* GSMLC3(WKID, LCDNR, VIEWI, TNR, PX, PY, PZ) */
FAPI void FNAME(gsmlc3, GSMLC3)(const fint *wkid, const fint *lcdnr, fint *viewi, fint *tnr,
                                freal *px, freal *py, freal *pz)
{
    Gloc3 l;
    gsample_loc3(*wkid, *lcdnr, viewi, &l);
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
    *pz = (freal)l.position.z;
}

/* GSMSK3(WKID, SKDNR, N, VIEWI, TNR, NP, PXA, PYA, PZA) */
FAPI void FNAME(gsmsk3, GSMSK3)(const fint *wkid, const fint *skdnr, const fint *n,
                                fint *viewi, fint *tnr, fint *np, freal *pxa, freal *pya,
                                freal *pza)
{
    Gpoint3 *p = *n > 0 ? gks_f77_alloc((size_t)*n, sizeof *p) : NULL;
    if (*n > 0 && !p) {
        gks_f77_nomem(GFN_SMSK3);
        return;
    }
    Gstroke3 s = { 0, *n > 0 ? *n : 0, p };
    gsample_stroke3(*wkid, *skdnr, viewi, &s);
    stroke3_out(&s, *n, tnr, np, pxa, pya, pza);
    free(p);
}

/* GGTLC3(VIEWI, TNR, PX, PY, PZ) */
FAPI void FNAME(ggtlc3, GGTLC3)(fint *viewi, fint *tnr, freal *px, freal *py, freal *pz)
{
    Gloc3 l;
    gget_loc3(viewi, &l);
    *tnr = l.norm_tran_num;
    *px = (freal)l.position.x;
    *py = (freal)l.position.y;
    *pz = (freal)l.position.z;
}

/* GGTSK3(N, VIEWI, TNR, NP, PXA, PYA, PZA) */
FAPI void FNAME(ggtsk3, GGTSK3)(const fint *n, fint *viewi, fint *tnr, fint *np, freal *pxa,
                                freal *pya, freal *pza)
{
    Gpoint3 *p = *n > 0 ? gks_f77_alloc((size_t)*n, sizeof *p) : NULL;
    if (*n > 0 && !p) {
        gks_f77_nomem(GFN_GTSK3);
        return;
    }
    Gstroke3 s = { 0, *n > 0 ? *n : 0, p };
    gget_stroke3(viewi, &s);
    stroke3_out(&s, *n, tnr, np, pxa, pya, pza);
    free(p);
}

/* GQLCS3(WKID, LCDNR, TYPE, MLDR, ERRIND, MODE, ESW, VIEWI, TNR, PX, PY, PZ, PET, EVOL,
 * LDR, DATREC) */
FAPI void FNAME(gqlcs3, GQLCS3)(const fint *wkid, const fint *lcdnr, const fint *type,
                                const fint *mldr, fint *errind, fint *mode, fint *esw,
                                fint *viewi, fint *tnr, freal *px, freal *py, freal *pz,
                                fint *pet, freal *evol, fint *ldr, char *datrec,
                                size_t datrec_len)
{
    Gloc_st3 s = { 0 };
    ginq_loc_st3(*wkid, *lcdnr, (Ginq_type)*type, errind, &s);
    if (*errind)
        return;
    *mode = s.op_mode;
    *esw = s.echo_switch;
    *pet = s.pet;
    *viewi = s.init_view_ind;
    *tnr = s.init_loc.norm_tran_num;
    *px = (freal)s.init_loc.position.x;
    *py = (freal)s.init_loc.position.y;
    *pz = (freal)s.init_loc.position.z;
    evol_out(&s.echo_vol, evol);
    *errind = record_out(&s.in_data, *mldr, ldr, datrec, datrec_len);
}

/* GQDLC3(WTYPE, LCDNR, N, MLDR, ERRIND, DPX, DPY, DPZ, OL, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(gqdlc3, GQDLC3)(const fint *wtype, const fint *lcdnr, const fint *n,
                                const fint *mldr, fint *errind, freal *dpx, freal *dpy,
                                freal *dpz, fint *ol, fint *pet, freal *evol, fint *ldr,
                                char *datrec, size_t datrec_len)
{
    Gdef_in d2 = { 0 };
    if (pets_buffer(&d2, *n)) {
        *errind = 300;
        return;
    }
    Gdef_loc3 s = { .pets = d2.pets };
    ginq_def_loc_data3(*wtype, *lcdnr, errind, &s);
    if (!*errind) {
        *dpx = (freal)s.loc_pos.x;
        *dpy = (freal)s.loc_pos.y;
        *dpz = (freal)s.loc_pos.z;
        evol_out(&s.echo_vol, evol);
        freal earea[4];
        d2 = (Gdef_in){ s.pets, { 0, 0, 0, 0 }, s.in_data };
        *errind = def_out(&d2, *n, *mldr, ol, pet, earea, ldr, datrec, datrec_len);
    }
    free(s.pets.ints);
}

/* GQSKS3(WKID, SKDNR, TYPE, N, MLDR, ERRIND, MODE, ESW, VIEWI, TNR, NP, PXA, PYA, PZA, PET,
 *        EVOL, BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqsks3, GQSKS3)(const fint *wkid, const fint *skdnr, const fint *type,
                                const fint *n, const fint *mldr, fint *errind, fint *mode,
                                fint *esw, fint *viewi, fint *tnr, fint *np, freal *pxa,
                                freal *pya, freal *pza, fint *pet, freal *evol, fint *buflen,
                                fint *ldr, char *datrec, size_t datrec_len)
{
    Gstroke_st3 s = { 0 };
    s.init_stroke.num_points = *n > STROKE_INQ_MAX ? *n : STROKE_INQ_MAX;
    if (!(s.init_stroke.points =
              gks_f77_alloc((size_t)s.init_stroke.num_points, sizeof(Gpoint3)))) {
        *errind = 300;
        return;
    }
    ginq_stroke_st3(*wkid, *skdnr, (Ginq_type)*type, errind, &s);
    if (!*errind) {
        *mode = s.op_mode;
        *esw = s.echo_switch;
        *pet = s.pet;
        *viewi = s.init_view_ind;
        *buflen = s.in_buf_size;
        stroke3_out(&s.init_stroke, *n, tnr, np, pxa, pya, pza);
        evol_out(&s.echo_vol, evol);
        *errind = record_out(&s.in_data, *mldr, ldr, datrec, datrec_len);
        if (!*errind && *np > *n)
            *errind = 2001;
    }
    free(s.init_stroke.points);
}

/* The outputs common to the 3-D device state inquiries; returns ERRIND (0 or 2001). */
#define DEV3_OUT(s)                                                                      \
    (*mode = (s).op_mode, *esw = (s).echo_switch, *pet = (s).pet,                        \
     evol_out(&(s).echo_vol, evol), record_out(&(s).in_data, *mldr, ldr, datrec, datrec_len))

/* GQVLS3(WKID, VLDNR, MLDR, ERRIND, MODE, ESW, IVAL, PET, EVOL, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(gqvls3, GQVLS3)(const fint *wkid, const fint *vldnr, const fint *mldr,
                                fint *errind, fint *mode, fint *esw, freal *ival, fint *pet,
                                freal *evol, freal *loval, freal *hival, fint *ldr,
                                char *datrec, size_t datrec_len)
{
    Gval_st3 s = { 0 };
    ginq_val_st3(*wkid, *vldnr, errind, &s);
    if (*errind)
        return;
    *ival = (freal)s.init_value;
    *loval = (freal)s.low_value;
    *hival = (freal)s.high_value;
    *errind = DEV3_OUT(s);
}

/* GQCHS3(WKID, CHDNR, MLDR, ERRIND, MODE, ESW, ISTAT, ICHNR, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(gqchs3, GQCHS3)(const fint *wkid, const fint *chdnr, const fint *mldr,
                                fint *errind, fint *mode, fint *esw, fint *istat, fint *ichnr,
                                fint *pet, freal *evol, fint *ldr, char *datrec,
                                size_t datrec_len)
{
    Gchoice_st3 s = { 0 };
    ginq_choice_st3(*wkid, *chdnr, errind, &s);
    if (*errind)
        return;
    *istat = s.init_status;
    *ichnr = s.init_choice;
    *errind = DEV3_OUT(s);
}

/* GQPKS3(WKID, PCDNR, TYPE, MLDR, ERRIND, MODE, ESW, ISTAT, ISGNA, IPCID, PET, EVOL, LDR,
 *        DATREC) */
FAPI void FNAME(gqpks3, GQPKS3)(const fint *wkid, const fint *pcdnr, const fint *type,
                                const fint *mldr, fint *errind, fint *mode, fint *esw,
                                fint *istat, fint *isgna, fint *ipcid, fint *pet, freal *evol,
                                fint *ldr, char *datrec, size_t datrec_len)
{
    Gpick_st3 s = { 0 };
    ginq_pick_st3(*wkid, *pcdnr, (Ginq_type)*type, errind, &s);
    if (*errind)
        return;
    *istat = s.init_status;
    *isgna = s.init_pick.seg_name;
    *ipcid = s.init_pick.pick_id;
    *errind = DEV3_OUT(s);
}

/* GQSTS3(WKID, STDNR, MLDR, ERRIND, MODE, ESW, LOSTR, ISTR, PET, EVOL, BUFLEN, INIPOS, LDR,
 *        DATREC) -- as GQSTS */
FAPI void FNAME(gqsts3, GQSTS3)(const fint *wkid, const fint *stdnr, const fint *mldr,
                                fint *errind, fint *mode, fint *esw, fint *lostr, char *istr,
                                fint *pet, freal *evol, fint *buflen, fint *inipos,
                                fint *ldr, char *datrec, size_t istr_len, size_t datrec_len)
{
    Gstring_st3 s = { 0 };
    s.init_string = istr_len < SIZE_MAX ? gks_f77_alloc(istr_len + 1, 1) : NULL;
    if (!s.init_string) {
        *errind = 300;
        return;
    }
    s.init_string[0] = '\0';
    s.init_string_size = istr_len + 1;
    ginq_string_st3(*wkid, *stdnr, errind, &s);
    if (!*errind) {
        *lostr = gks_f77_fill_str(s.init_string, istr, istr_len);
        *buflen = s.in_buf_size;
        *inipos = s.init_cur_pos;
        *errind = DEV3_OUT(s);
    }
    free(s.init_string);
}
#undef DEV3_OUT

/* The outputs common to the 3-D default-data inquiries (as def_out, echo volume). */
static fint def3_out(const Gint_list *pets, const Glimit3 *vol, const Gin_data *rec, fint n,
                     fint mldr, fint *ol, fint *pet, freal *evol, fint *ldr, char *datrec,
                     size_t datrec_len)
{
    freal earea[4];
    Gdef_in d = { *pets, { 0, 0, 0, 0 }, *rec };
    fint e = def_out(&d, n, mldr, ol, pet, earea, ldr, datrec, datrec_len);
    if (e != 2002)
        evol_out(vol, evol);
    return e;
}

/* Room for the first n prompt/echo types of a 3-D default-data inquiry; -1: no memory. */
static int pets3_buffer(Gint_list *pets, fint n)
{
    Gdef_in d;
    int r = pets_buffer(&d, n);
    *pets = d.pets;
    return r;
}

/* GQDSK3(WTYPE, SKDNR, N, MLDR, ERRIND, DBUFSK, OL, PET, EVOL, BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqdsk3, GQDSK3)(const fint *wtype, const fint *skdnr, const fint *n,
                                const fint *mldr, fint *errind, fint *dbufsk, fint *ol,
                                fint *pet, freal *evol, fint *buflen, fint *ldr, char *datrec,
                                size_t datrec_len)
{
    Gdef_stroke3 s = { 0 };
    if (pets3_buffer(&s.pets, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_stroke_data3(*wtype, *skdnr, errind, &s);
    if (!*errind) {
        *dbufsk = s.max_buf_size;
        *buflen = s.buf_size;
        *errind = def3_out(&s.pets, &s.echo_vol, &s.in_data, *n, *mldr, ol, pet, evol, ldr,
                           datrec, datrec_len);
    }
    free(s.pets.ints);
}

/* GQDVL3(WTYPE, VLDNR, N, MLDR, ERRIND, DVAL, OL, PET, EVOL, LOVAL, HIVAL, LDR, DATREC) */
FAPI void FNAME(gqdvl3, GQDVL3)(const fint *wtype, const fint *vldnr, const fint *n,
                                const fint *mldr, fint *errind, freal *dval, fint *ol,
                                fint *pet, freal *evol, freal *loval, freal *hival, fint *ldr,
                                char *datrec, size_t datrec_len)
{
    Gdef_val3 s = { 0 };
    if (pets3_buffer(&s.dev.pets, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_val_data3(*wtype, *vldnr, errind, &s);
    if (!*errind) {
        *dval = (freal)s.value;
        *loval = (freal)s.low_value;
        *hival = (freal)s.high_value;
        *errind = def3_out(&s.dev.pets, &s.dev.echo_vol, &s.dev.in_data, *n, *mldr, ol, pet,
                           evol, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDCH3(WTYPE, CHDNR, N, MLDR, ERRIND, MALT, OL, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(gqdch3, GQDCH3)(const fint *wtype, const fint *chdnr, const fint *n,
                                const fint *mldr, fint *errind, fint *malt, fint *ol,
                                fint *pet, freal *evol, fint *ldr, char *datrec,
                                size_t datrec_len)
{
    Gdef_choice3 s = { 0 };
    if (pets3_buffer(&s.dev.pets, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_choice_data3(*wtype, *chdnr, errind, &s);
    if (!*errind) {
        *malt = s.max_choices;
        *errind = def3_out(&s.dev.pets, &s.dev.echo_vol, &s.dev.in_data, *n, *mldr, ol, pet,
                           evol, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* GQDPK3(WTYPE, PCDNR, N, MLDR, ERRIND, OL, PET, EVOL, LDR, DATREC) */
FAPI void FNAME(gqdpk3, GQDPK3)(const fint *wtype, const fint *pcdnr, const fint *n,
                                const fint *mldr, fint *errind, fint *ol, fint *pet,
                                freal *evol, fint *ldr, char *datrec, size_t datrec_len)
{
    Gdef_in3 s = { 0 };
    if (pets3_buffer(&s.pets, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_pick_data3(*wtype, *pcdnr, errind, &s);
    if (!*errind)
        *errind = def3_out(&s.pets, &s.echo_vol, &s.in_data, *n, *mldr, ol, pet, evol, ldr,
                           datrec, datrec_len);
    free(s.pets.ints);
}

/* GQDST3(WTYPE, STDNR, N, MLDR, ERRIND, MBUFF, OL, PET, EVOL, BUFLEN, LDR, DATREC) */
FAPI void FNAME(gqdst3, GQDST3)(const fint *wtype, const fint *stdnr, const fint *n,
                                const fint *mldr, fint *errind, fint *mbuff, fint *ol,
                                fint *pet, freal *evol, fint *buflen, fint *ldr, char *datrec,
                                size_t datrec_len)
{
    Gdef_string3 s = { 0 };
    if (pets3_buffer(&s.dev.pets, *n)) {
        *errind = 300;
        return;
    }
    ginq_def_string_data3(*wtype, *stdnr, errind, &s);
    if (!*errind) {
        *mbuff = s.max_buf_size;
        *buflen = s.buf_size;
        *errind = def3_out(&s.dev.pets, &s.dev.echo_vol, &s.dev.in_data, *n, *mldr, ol, pet,
                           evol, ldr, datrec, datrec_len);
    }
    free(s.dev.pets.ints);
}

/* ---- The FORTRAN 77 subset forms of the string functions (ISO 8651-1 3.4: for
 * compilers without CHARACTER*(*), STR declared CHARACTER*80 by the program). Their
 * argument lists are those of the full forms, which already carry the lengths
 * explicitly (LSTR in, LOSTR out); the characters' count is taken from the CHARACTER
 * passed, as there. ---- */

/* GINSTS(WKID, STDNR, LSTR, ISTR, PET, XMIN, XMAX, YMIN, YMAX, BUFLEN, INIPOS, LDR, DATREC) */
FAPI void FNAME(ginsts, GINSTS)(const fint *wkid, const fint *stdnr, const fint *lstr,
                                const char *istr, const fint *pet, const freal *xmin,
                                const freal *xmax, const freal *ymin, const freal *ymax,
                                const fint *buflen, const fint *inipos, const fint *ldr,
                                const char *datrec, size_t istr_len, size_t datrec_len)
{
    FNAME(ginst, GINST)(wkid, stdnr, lstr, istr, pet, xmin, xmax, ymin, ymax, buflen, inipos,
                        ldr, datrec, istr_len, datrec_len);
}

/* GRQSTS(WKID, STDNR, STAT, LOSTR, STR) */
FAPI void FNAME(grqsts, GRQSTS)(const fint *wkid, const fint *stdnr, fint *stat, fint *lostr,
                                char *str, size_t str_len)
{
    FNAME(grqst, GRQST)(wkid, stdnr, stat, lostr, str, str_len);
}

/* GSMSTS(WKID, STDNR, LOSTR, STR) */
FAPI void FNAME(gsmsts, GSMSTS)(const fint *wkid, const fint *stdnr, fint *lostr, char *str,
                                size_t str_len)
{
    FNAME(gsmst, GSMST)(wkid, stdnr, lostr, str, str_len);
}

/* GGTSTS(LOSTR, STR) */
FAPI void FNAME(ggtsts, GGTSTS)(fint *lostr, char *str, size_t str_len)
{
    FNAME(ggtst, GGTST)(lostr, str, str_len);
}

/* GQSTSS(WKID, STDNR, MLDR, ERRIND, MODE, ESW, LOSTR, ISTR, PET, EAREA, BUFLEN, INIPOS, LDR,
 *        DATREC) */
FAPI void FNAME(gqstss, GQSTSS)(const fint *wkid, const fint *stdnr, const fint *mldr,
                                fint *errind, fint *mode, fint *esw, fint *lostr, char *istr,
                                fint *pet, freal *earea, fint *buflen, fint *inipos,
                                fint *ldr, char *datrec, size_t istr_len, size_t datrec_len)
{
    FNAME(gqsts, GQSTS)(wkid, stdnr, mldr, errind, mode, esw, lostr, istr, pet, earea, buflen,
                        inipos, ldr, datrec, istr_len, datrec_len);
}
