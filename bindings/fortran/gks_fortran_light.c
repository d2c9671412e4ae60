/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_light.c -- FORTRAN 77 entry points of the lighting functions (PHIGS PLUS
 * semantics added to GKS-3D, paper section 5) and their inquiries, as thin wrappers over
 * the C binding (gks.h). Names: G + the GKSE_PAR function name where it fits 6 characters
 * (GSAPR = ESAPR, GSBAPR, GSRFEQ, GSLSR, GSLSS); SET BACK REFLECTANCE EQUATION is GSBRFQ
 * (its identification in GKSE_PAR is ESBRFEQ). Inquiries GQ + the same stem. Arguments
 * are explicit REAL/INTEGER values and arrays, not PHIGS data records (documented in
 * bindings/fortran/README.md and docs/BINDING.md).
 *
 * Also the integer ESCAPEs of the ray-tracing workstation for GESC (gks_f77_escape_ints).
 */
#include "gks.h"
#include "FC.h"
#include <stddef.h>
#include <stdint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define FAPI __attribute__((visibility("default")))
#define FNAME(lower, UPPER) FC_GLOBAL(lower, UPPER)

typedef int fint;
typedef float freal;

/* Area properties from the Fortran argument list; SPCOL(3) = specular colour R, G, B. */
static Garea_props make_props(const freal *ambc, const freal *difc, const freal *specc,
                              const freal *spcol, const freal *spexp, const freal *transc,
                              const freal *refri)
{
    Garea_props p = { *ambc, *difc, *specc, { spcol[0], spcol[1], spcol[2] },
                      *spexp, *transc, *refri };
    return p;
}

static void put_props(const Garea_props *p, freal *ambc, freal *difc, freal *specc,
                      freal *spcol, freal *spexp, freal *transc, freal *refri)
{
    *ambc = (freal)p->ambient_coef;
    *difc = (freal)p->diffuse_coef;
    *specc = (freal)p->specular_coef;
    spcol[0] = (freal)p->specular_colr.red;
    spcol[1] = (freal)p->specular_colr.green;
    spcol[2] = (freal)p->specular_colr.blue;
    *spexp = (freal)p->specular_exp;
    *transc = (freal)p->transpar_coef;
    *refri = (freal)p->refr_index;
}

/* GSAPR(AMBC, DIFC, SPECC, SPCOL(3), SPEXP, TRANSC, REFRI): SET AREA PROPERTIES. */
FAPI void FNAME(gsapr, GSAPR)(const freal *ambc, const freal *difc, const freal *specc,
                              const freal *spcol, const freal *spexp, const freal *transc,
                              const freal *refri)
{
    Garea_props p = make_props(ambc, difc, specc, spcol, spexp, transc, refri);
    gset_area_props(&p);
}

/* GSBAPR(same arguments): SET BACK AREA PROPERTIES. */
FAPI void FNAME(gsbapr, GSBAPR)(const freal *ambc, const freal *difc, const freal *specc,
                                const freal *spcol, const freal *spexp, const freal *transc,
                                const freal *refri)
{
    Garea_props p = make_props(ambc, difc, specc, spcol, spexp, transc, refri);
    gset_back_area_props(&p);
}

/* GSRFEQ(RFEQ) / GSBRFQ(RFEQ): SET (BACK) REFLECTANCE EQUATION, RFEQ = GRNONE..GRAMDS. */
FAPI void FNAME(gsrfeq, GSRFEQ)(const fint *rfeq) { gset_refl_eq(*rfeq); }
FAPI void FNAME(gsbrfq, GSBRFQ)(const fint *rfeq) { gset_back_refl_eq(*rfeq); }

/* GSLSR(WKID, LSI, LSTYPE, COLR(3), POS(3), DIR(3), ATTEN(2), CONCEX, SPREAD):
 * SET LIGHT SOURCE REPRESENTATION; POS and DIR in NDC3, SPREAD in radians. */
FAPI void FNAME(gslsr, GSLSR)(const fint *wkid, const fint *lsi, const fint *lstype,
                              const freal *colr, const freal *pos, const freal *dir,
                              const freal *atten, const freal *concex, const freal *spread)
{
    Glight_src_rep r = { *lstype, { colr[0], colr[1], colr[2] }, { pos[0], pos[1], pos[2] },
                         { dir[0], dir[1], dir[2] }, { atten[0], atten[1] }, *concex,
                         *spread };
    gset_light_src_rep(*wkid, *lsi, &r);
}

/* GSLSS(NACT, ACT, NDEACT, DEACT): SET LIGHT SOURCE STATE (count before each list, the
 * DEC/OpenPHIGS order). NACT or NDEACT <= 0: empty list (the array is not read). */
FAPI void FNAME(gslss, GSLSS)(const fint *nact, const fint *act, const fint *ndeact,
                              const fint *deact)
{
    /* Gint is int: the Fortran arrays are passed as they are; the core does not write. */
    Gint_list on = { *nact > 0 ? *nact : 0, *nact > 0 ? (Gint *)(uintptr_t)act : NULL };
    Gint_list off = { *ndeact > 0 ? *ndeact : 0, *ndeact > 0 ? (Gint *)(uintptr_t)deact : NULL };
    gset_light_src_state(&on, &off);
}

/* GQAPR(ERRIND, AMBC, DIFC, SPECC, SPCOL(3), SPEXP, TRANSC, REFRI) / GQBAPR(...):
 * INQUIRE (BACK) AREA PROPERTIES (current values of the GKS state list). */
FAPI void FNAME(gqapr, GQAPR)(fint *errind, freal *ambc, freal *difc, freal *specc,
                              freal *spcol, freal *spexp, freal *transc, freal *refri)
{
    Garea_props f, unused; /* both outputs are required (a NULL one is 2003) */
    memset(&f, 0, sizeof f);
    ginq_area_props(errind, &f, &unused);
    if (!*errind)
        put_props(&f, ambc, difc, specc, spcol, spexp, transc, refri);
}

FAPI void FNAME(gqbapr, GQBAPR)(fint *errind, freal *ambc, freal *difc, freal *specc,
                                freal *spcol, freal *spexp, freal *transc, freal *refri)
{
    Garea_props b, unused; /* both outputs are required (a NULL one is 2003) */
    memset(&b, 0, sizeof b);
    ginq_area_props(errind, &unused, &b);
    if (!*errind)
        put_props(&b, ambc, difc, specc, spcol, spexp, transc, refri);
}

/* GQRFEQ(ERRIND, RFEQ, BRFEQ): INQUIRE REFLECTANCE EQUATIONS (front and back). */
FAPI void FNAME(gqrfeq, GQRFEQ)(fint *errind, fint *rfeq, fint *brfeq)
{
    Gint f = 0, b = 0;
    ginq_refl_eq(errind, &f, &b);
    if (*errind)
        return;
    *rfeq = f;
    *brfeq = b;
}

/* GQLSR(WKID, LSI, ERRIND, LSTYPE, COLR(3), POS(3), DIR(3), ATTEN(2), CONCEX, SPREAD):
 * INQUIRE LIGHT SOURCE REPRESENTATION. ERRIND 529 (index outside 1..64), 2002 (index not
 * defined) or a workstation error; outputs unchanged on error. */
FAPI void FNAME(gqlsr, GQLSR)(const fint *wkid, const fint *lsi, fint *errind, fint *lstype,
                              freal *colr, freal *pos, freal *dir, freal *atten, freal *concex,
                              freal *spread)
{
    Glight_src_rep r;
    memset(&r, 0, sizeof r);
    ginq_light_src_rep(*wkid, *lsi, errind, &r);
    if (*errind)
        return;
    *lstype = r.type;
    const double c[3] = { r.colr.red, r.colr.green, r.colr.blue },
                 p[3] = { r.pos.x, r.pos.y, r.pos.z },
                 d[3] = { r.dir.delta_x, r.dir.delta_y, r.dir.delta_z };
    for (int i = 0; i < 3; i++) {
        colr[i] = (freal)c[i];
        pos[i] = (freal)p[i];
        dir[i] = (freal)d[i];
    }
    atten[0] = (freal)r.atten[0];
    atten[1] = (freal)r.atten[1];
    *concex = (freal)r.conc_exp;
    *spread = (freal)r.spread_angle;
}

/* GQLSS(N, ERRIND, OL, LSI): INQUIRE LIGHT SOURCE STATE, the GKS list-inquiry form: OL =
 * number of active light indices, LSI = the N-th (ascending, 1-based); N = 0 returns only
 * OL; N < 0 or N > OL gives ERRIND 2002 (OL still returned). */
FAPI void FNAME(gqlss, GQLSS)(const fint *n, fint *errind, fint *ol, fint *lsi)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    fint k = *n;
    ginq_light_src_state(k > 0 ? 1 : 0, k > 0 ? k - 1 : (k == 0 ? 0 : -1), errind, &l, &len);
    *ol = len;
    if (*errind == 0 && k > len)
        *errind = 2002; /* the C binding accepts start 0 of an empty list */
    if (*errind == 0 && k > 0)
        *lsi = v;
}

/* ---------------------------------------------------------------- GESC integer records */
/* One I10 field (columns 10*i+1 .. 10*i+10) of the record rec (length len): blanks, an
 * optional sign, digits, blanks. 0 = ok, -1 = not an integer. */
static int i10_field(const char *rec, size_t len, int i, Gint *out)
{
    size_t a = (size_t)i * 10;
    if (a >= len)
        return -1;
    size_t e = len - a < 10 ? len : a + 10;
    while (a < e && rec[a] == ' ')
        a++;
    int neg = a < e && rec[a] == '-';
    if (a < e && (rec[a] == '-' || rec[a] == '+'))
        a++;
    long v = 0;
    int digits = 0;
    for (; a < e && rec[a] >= '0' && rec[a] <= '9'; a++, digits++)
        v = v * 10 + (rec[a] - '0'); /* at most 10 digits: no overflow of long (64 bit) */
    while (a < e && rec[a] == ' ')
        a++;
    if (!digits || a != e || v > 2147483647L)
        return -1;
    *out = (Gint)(neg ? -v : v);
    return 0;
}

/* One E20 field (columns 11..30) of the record rec (length len): a real number written by
 * any Fortran real edit descriptor, blank filled. 0 = ok, -1 = not a finite real. */
static int e20_field(const char *rec, size_t len, Gfloat *out)
{
    char buf[21];
    if (len < 30)
        return -1;
    memcpy(buf, rec + 10, 20);
    buf[20] = '\0';
    for (int i = 0; i < 20; i++)
        if (buf[i] == 'D' || buf[i] == 'd')
            buf[i] = 'E'; /* Fortran's double precision exponent */
    char *end = NULL;
    double v = strtod(buf, &end);
    while (end && *end == ' ')
        end++;
    if (end == buf || !end || *end || !isfinite(v) || fabs(v) > 3.0e38)
        return -1;
    *out = (Gfloat)v;
    return 0;
}

/* The real ESCAPEs of the vector workstations from GESC (GESC_VEC_MITER_LIMIT,
 * GESC_VEC_LINE_SCALE): IDR(1) columns 1-10 the workstation identifier (I10), 11-30 the
 * value (E20). Returns 1 when fctid is one of them (the escape has then been called, a
 * malformed record reaching the core as empty data: error 182), 0 otherwise. */
int gks_f77_escape_real(fint fctid, fint lidr, const char *idr, size_t idr_len)
{
    if (fctid != GESC_VEC_MITER_LIMIT && fctid != GESC_VEC_LINE_SCALE)
        return 0;
    Gint ws = 0;
    Gfloat x = 0;
    int ok = lidr >= 1 && !i10_field(idr, idr_len, 0, &ws) && !e20_field(idr, idr_len, &x);
    Gescape_in_data in = { { 1, &ws, ok, &x, 0, NULL } };
    gescape(fctid, &in, NULL, NULL);
    return 1;
}

/* The integer ESCAPEs of the PNG and ray-tracing workstations from GESC: IDR(1) holds I10 fields,
 * columns 1-10 the workstation identifier, 11-20 and 21-30 the values (GESC_RT_*, GESC_PNG_*). Returns
 * 1 when fctid is one of them (the escape has then been called, malformed records reaching
 * the core as empty data: error 182), 0 otherwise. Called by GESC in gks_fortran.c. */
int gks_f77_escape_ints(fint fctid, fint lidr, const char *idr, size_t idr_len)
{
    int nvals;
    switch (fctid) {
    case GESC_RT_CLIP_SECONDARY:
    case GESC_RT_MAX_DEPTH:
    case GESC_RT_THREADS:
    case GESC_RT_PROGRESS:
    case GESC_RT_SPD:
    case GESC_PNG_SUPERSAMPLE:
    case GESC_PNG_COMPRESSION:
    case GESC_VEC_RESOLUTION:
    case GESC_VEC_LINE_JOIN:
    case GESC_VEC_LINE_CAP:
        nvals = 1;
        break;
    case GESC_RT_SAMPLES:
        nvals = 2;
        break;
    case GESC_VEC_PAGE: /* four values, or six when columns 51-70 hold two more */
        nvals = idr_len >= 70 && idr[69] != ' ' ? 6 : 4;
        break;
    default:
        return 0;
    }
    Gint ints[7] = { 0 };
    Gescape_in_data in = { { 0, ints, 0, NULL, 0, NULL } };
    int ok = lidr >= 1 && idr_len >= 20;
    for (int i = 0; ok && i <= nvals; i++)
        ok = !i10_field(idr, idr_len, i, &ints[i]);
    if (ok)
        in.num_ints = nvals + 1;
    gescape(fctid, &in, NULL, NULL);
    return 1;
}
