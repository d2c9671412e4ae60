/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L /* stat */
/*
 * gks_fortran.c -- the FORTRAN 77 binding (ISO 8651-1 names) as thin C wrappers over the
 * C binding (gks.h). Each entry point dereferences its arguments, converts REAL to double
 * and 1-based list positions to 0-based, takes each CHARACTER argument as a pointer plus
 * a size_t hidden length after all explicit arguments (gfortran >= 8, ifx, flang), strips
 * trailing blanks from input text and blank-pads output text.
 *
 * ERROR HANDLING: fortran_err_trampoline is installed as the core's handler when the
 * library is loaded (constructor) and again by GOPKS. It calls the Fortran-callable
 * GERHND(ERRNR, FCTID, ERRFIL), ERRFIL being the unit given to GOPKS (0 before GOPKS).
 * The library's GERHND (gerhnd.f, its own object file) calls GERLOG (gerlog.f); a
 * program that defines its own SUBROUTINE GERHND replaces it at link time (static
 * archive: the member is never pulled in; shared library: ELF symbol interposition).
 */
#include "gks.h"
#include "gks_binding.h"
#include "gks_fortran.h"
#include "FC.h"
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>


/* The Fortran ERROR HANDLING subroutine (gerhnd.f or the application's own). */
extern void FNAME(gerhnd, GERHND)(const fint *errnr, const fint *fctid, const fint *errfil);

/* Parse a whole decimal integer (surrounding blanks allowed); 0 = ok. */
static int parse_int(const char *s, size_t len, long *out)
{
    while (len > 0 && s[len - 1] == ' ')
        len--;
    while (len > 0 && *s == ' ') {
        s++;
        len--;
    }
    if (len == 0 || len > 20)
        return -1;
    char buf[24];
    memcpy(buf, s, len);
    buf[len] = '\0';
    char *end = NULL;
    errno = 0;
    long v = strtol(buf, &end, 10);
    if (errno || *end != '\0' || v < INT32_MIN || v > INT32_MAX)
        return -1;
    *out = v;
    return 0;
}

/* The core's handler: err_file is the decimal text of the Fortran unit (NULL before OPEN
 * GKS: unit 0). When GKS was opened from C with a file name, the C default handles it. */
static void fortran_err_trampoline(Gint err_num, Gint func_num, const char *err_file)
{
    long unit = 0;
    if (err_file && parse_int(err_file, strlen(err_file), &unit)) {
        gerr_hand(err_num, func_num, err_file);
        return;
    }
    fint e = err_num, f = func_num, u = (fint)unit;
    FNAME(gerhnd, GERHND)(&e, &f, &u);
}

static void install_handler(void)
{
    gset_err_hand(fortran_err_trampoline, NULL);
}

/* Errors raised before GOPKS (e.g. GOPWK in state GKCL) also reach GERHND. */
__attribute__((constructor)) static void gks_fortran_init(void)
{
    install_handler();
}

void gks_f77_nomem(Gint fctid)
{
    gks_binding_error(300, fctid);
}

#ifdef GKS_FAULT_INJECTION
/* The test build of the binding (gks3d_fortran_test, bindings/fortran/CMakeLists.txt)
 * sends every allocation through the failure injection of the library's funnel
 * (gks_alloc_fail_after, src/c/base/gks_alloc.c); the installed libraries have none. */
#include "gks_alloc.h"
static long f77_injected; /* the binding's allocations made to fail (test_f77_oom) */
long gks_f77_alloc_injected(void) { return f77_injected; }
#endif

void *gks_f77_alloc(size_t n, size_t size)
{
#ifdef GKS_FAULT_INJECTION
    if (gks_alloc_injected_failure()) {
        f77_injected++;
        return NULL;
    }
#endif
    if (size != 0 && n > SIZE_MAX / size)
        return NULL;
    return malloc(n * size > 0 ? n * size : 1);
}

/* Length without trailing blanks. */
static size_t trimmed(const char *s, size_t len)
{
    while (len > 0 && s[len - 1] == ' ')
        len--;
    return len;
}

/* NUL-terminated copy of the first len bytes (caller frees); NULL when out of memory. */
static char *str_dup_n(const char *s, size_t len)
{
    if (len == SIZE_MAX)
        return NULL;
    char *p = gks_f77_alloc(len + 1, 1);
    if (!p)
        return NULL;
    if (len)
        memcpy(p, s, len);
    p[len] = '\0';
    return p;
}

fint gks_f77_fill_str(const char *src, char *dst, size_t dlen)
{
    size_t n = 0;
    while (n < dlen && src[n])
        n++;
    memcpy(dst, src, n);
    memset(dst + n, ' ', dlen - n);
    return (fint)n;
}

/* Point list from Fortran REAL arrays (NULL points when n <= 0: the core reports 100). */
static int make_points(fint n, const freal *px, const freal *py, Gpoint_list *pl, Gint fctid)
{
    pl->num_points = n;
    pl->points = NULL;
    if (n <= 0)
        return 0;
    if (!(pl->points = gks_f77_alloc((size_t)n, sizeof(Gpoint)))) {
        gks_f77_nomem(fctid);
        return -1;
    }
    for (fint i = 0; i < n; i++) {
        pl->points[i].x = px[i];
        pl->points[i].y = py[i];
    }
    return 0;
}

static Glimit make_limit(const freal *x0, const freal *x1, const freal *y0, const freal *y1)
{
    Glimit l = { *x0, *x1, *y0, *y1 };
    return l;
}

static void put_limit(const Glimit *l, freal *a)
{
    a[0] = (freal)l->x_min;
    a[1] = (freal)l->x_max;
    a[2] = (freal)l->y_min;
    a[3] = (freal)l->y_max;
}

/* ------------------------------------------------------------------ control */
/* GOPKS(ERRFIL, BUFA): OPEN GKS; ERRFIL is a Fortran unit, BUFA < 0 = default. */
FAPI void FNAME(gopks, GOPKS)(const fint *errfil, const fint *bufa)
{
    install_handler();
    gks_open_gks_unit(*errfil, *bufa < 0 ? 0 : (size_t)*bufa);
}

FAPI void FNAME(gclks, GCLKS)(void) { gclose_gks(); }
FAPI void FNAME(geclks, GECLKS)(void) { gemergency_close_gks(); }

/* The Fortran side's INQUIRE of a unit's file name (gkunam.f). */
extern void FNAME(gkunam, GKUNAM)(const fint *unit, char *name, fint *nlen, size_t name_len);

#define UNIT_NAME_MAX 4096

/* The regular file the program OPENed unit u on, into name (UNIT_NAME_MAX + 2 bytes);
 * 0 = none (unit not open or unnamed, a preconnected stream, a device, a name too long). */
static int unit_file(fint u, char *name)
{
    fint n = 0;
    FNAME(gkunam, GKUNAM)(&u, name, &n, UNIT_NAME_MAX + 1);
    if (n <= 0 || n > UNIT_NAME_MAX) /* n = UNIT_NAME_MAX + 1: the name did not fit */
        return 0;
    name[n] = '\0';
    if (!strcmp(name, "stdin") || !strcmp(name, "stdout") || !strcmp(name, "stderr"))
        return 0; /* gfortran's names of the preconnected units 5, 6, 0 */
    struct stat st;
    return stat(name, &st) == 0 && S_ISREG(st.st_mode);
}

/* Workstations opened on a unit's file, so that GQWKC answers the unit: slot = (wkid,
 * unit, file name); valid while that workstation's connection identifier is the name. */
static struct {
    fint wkid, unit;
    char *name;
} unit_ws[16];

static void unit_remember(fint wkid, fint unit, const char *name)
{
    int k = -1;
    for (int i = 0; i < 16; i++)
        if (unit_ws[i].name && unit_ws[i].wkid == wkid)
            k = i;
    for (int i = 0; k < 0 && i < 16; i++)
        if (!unit_ws[i].name)
            k = i;
    if (k < 0)
        k = 0; /* more than 16 remembered: the oldest slot goes */
    free(unit_ws[k].name);
    unit_ws[k].name = str_dup_n(name, strlen(name));
    unit_ws[k].wkid = wkid;
    unit_ws[k].unit = unit;
}

/* The unit GOPWK took workstation wkid's connection identifier conn from, or -1. */
static fint unit_recall(fint wkid, const char *conn)
{
    for (int i = 0; i < 16; i++)
        if (unit_ws[i].name && unit_ws[i].wkid == wkid && !strcmp(unit_ws[i].name, conn))
            return unit_ws[i].unit;
    return -1;
}

/* GOPWK(WKID, CONID, WTYPE): CONID is a Fortran unit. When the program OPENed that unit
 * on a regular file, the workstation uses that file (RAL's metafile programs); otherwise
 * CONID is passed as its decimal text (MO/MI: gksN.gksm). The unit itself is left alone. */
FAPI void FNAME(gopwk, GOPWK)(const fint *wkid, const fint *conid, const fint *wtype)
{
    char conn[16];
    char name[UNIT_NAME_MAX + 2];
    snprintf(conn, sizeof conn, "%d", *conid);
    int named = unit_file(*conid, name);
    gopen_ws(*wkid, named ? name : conn, *wtype);
    if (named)
        unit_remember(*wkid, *conid, name);
}

FAPI void FNAME(gclwk, GCLWK)(const fint *wkid) { gclose_ws(*wkid); }
FAPI void FNAME(gacwk, GACWK)(const fint *wkid) { gactivate_ws(*wkid); }
FAPI void FNAME(gdawk, GDAWK)(const fint *wkid) { gdeactivate_ws(*wkid); }
FAPI void FNAME(grsgwk, GRSGWK)(const fint *wkid) { gredraw_all_seg_ws(*wkid); }

FAPI void FNAME(gclrwk, GCLRWK)(const fint *wkid, const fint *cofl)
{
    gclear_ws(*wkid, (Gctrl_flag)*cofl);
}

FAPI void FNAME(guwk, GUWK)(const fint *wkid, const fint *regfl)
{
    gupd_ws(*wkid, (Gupd_regen_flag)*regfl);
}

FAPI void FNAME(gsds, GSDS)(const fint *wkid, const fint *defmod, const fint *regmod)
{
    gset_defer_st(*wkid, (Gdefer_mode)*defmod, (Girg_mode)*regmod);
}

static void message_n(fint wkid, const char *mess, size_t len)
{
    char *s = str_dup_n(mess, trimmed(mess, len));
    if (!s) {
        gks_f77_nomem(GFN_MSG);
        return;
    }
    gmessage(wkid, s);
    free(s);
}

/* GMSG(WKID, MESS) */
FAPI void FNAME(gmsg, GMSG)(const fint *wkid, const char *mess, size_t mess_len)
{
    message_n(*wkid, mess, mess_len);
}

/* GMSGS(WKID, LSTR, MESS): FORTRAN 77 subset form, LSTR characters of MESS. */
FAPI void FNAME(gmsgs, GMSGS)(const fint *wkid, const fint *lstr, const char *mess,
                              size_t mess_len)
{
    size_t n = *lstr < 0 ? 0 : (size_t)*lstr;
    message_n(*wkid, mess, n < mess_len ? n : mess_len);
}

/* GESC(FCTID, LIDR, IDR, MLODR, LODR, ODR). NCAR's -1391 (file name of the next
 * workstation) and -1396 (pause): IDR(1) is NCAR's record (gks.h GESC_NCAR_*).
 * Escapes -101 (set file name) and -130 (input script, docs/INPUT.md): IDR(1) holds the workstation identifier in columns 1-10 (I10),
 * IDR(2..LIDR) the file name, each record blank-trimmed and concatenated. Malformed records reach the core as empty data (182).
 * Any other escape: IDR(1..max(LIDR, MLODR)) is escape_r1 (a profile's, gks_binding.h, such as NCAR's
 * -1388); only an escape that returns data writes ODR, and LODR is never written, so a
 * program may pass constants there (as NCAR's fgke03 and NGSRAT do). */
int gks_f77_escape_ints(fint fctid, fint lidr, const char *idr, size_t idr_len); /* _light.c */
int gks_f77_escape_real(fint fctid, fint lidr, const char *idr, size_t idr_len);

/* ESCAPE -108 (GESRST, GESC_RT_STATS): IDR(1) columns 1-10 (I10) the workstation; ODR(1)
 * receives the eight counts as 8I10 (eye rays, eye rays that hit, reflection, refraction,
 * shadow rays, grid cells, grid references, primitives), ODR(2) the build and render
 * seconds as 2E20.8, each record blank-filled and cut at LEN(ODR); only MLODR records are
 * written, and LODR receives their number (0 when the escape failed: its error is reported
 * as in C). */
static void escape_stats(fint lidr, const char *idr, size_t idr_len, const fint *mlodr,
                         fint *lodr, char *odr, size_t odr_len)
{
    long ws = 0;
    Gint wsid = 0;
    Gescape_in_data in = { { 0, NULL, 0, NULL, 0, NULL } };
    if (lidr >= 1 && idr_len > 0 && !parse_int(idr, idr_len < 10 ? idr_len : 10, &ws)) {
        wsid = (Gint)ws;
        in.num_ints = 1;
        in.ints = &wsid;
    }
    Gstore store = NULL;
    Gint serr = 0;
    Gescape_out_data *out = NULL;
    gcreate_store(&serr, &store);
    gescape(GESC_RT_STATS, &in, serr ? NULL : &store, &out);
    fint n = 0;
    if (out && out->num_ints >= 8 && out->num_floats >= 2 && odr && odr_len > 0 && mlodr) {
        char rec[2][96];
        snprintf(rec[0], sizeof rec[0], "%10d%10d%10d%10d%10d%10d%10d%10d", (int)out->ints[0],
                 (int)out->ints[1], (int)out->ints[2], (int)out->ints[3], (int)out->ints[4],
                 (int)out->ints[5], (int)out->ints[6], (int)out->ints[7]);
        snprintf(rec[1], sizeof rec[1], "%20.8E%20.8E", (double)out->floats[0],
                 (double)out->floats[1]);
        for (; n < 2 && n < *mlodr; n++) {
            size_t k = strlen(rec[n]);
            memset(odr + (size_t)n * odr_len, ' ', odr_len);
            memcpy(odr + (size_t)n * odr_len, rec[n], k < odr_len ? k : odr_len);
        }
    }
    if (lodr)
        *lodr = n;
    if (store)
        gdel_store(store);
}

FAPI void FNAME(gesc, GESC)(const fint *fctid, const fint *lidr, const char *idr,
                            const fint *mlodr, fint *lodr, char *odr, size_t idr_len,
                            size_t odr_len)
{
    if (*fctid == GESC_RT_STATS) {
        escape_stats(*lidr, idr, idr_len, mlodr, lodr, odr, odr_len);
        return;
    }
    if (gks_f77_escape_ints(*fctid, *lidr, idr, idr_len) ||
        gks_f77_escape_real(*fctid, *lidr, idr, idr_len))
        return; /* integer and real records of gks3d's escapes (gks_fortran_light.c) */
    Gescape_in_data in = { { 0, NULL, 0, NULL, 0, NULL } };
    fint nrec = *lidr;
    long ws = 0;
    Gint wsid = 0;
    char *name = NULL;
    if ((*fctid == GESC_SET_FILE_NAME || *fctid == GESC_INPUT_SCRIPT) && nrec >= 2 &&
        idr_len > 0 && !parse_int(idr, idr_len < 10 ? idr_len : 10, &ws)) {
        wsid = (Gint)ws;
        size_t total = 0;
        size_t nr = (size_t)(nrec - 1);
        size_t cap = nr < SIZE_MAX / idr_len ? nr * idr_len : SIZE_MAX;
        if (cap == SIZE_MAX || !(name = gks_f77_alloc(cap + 1, 1))) {
            gks_f77_nomem(GFN_ESC);
            return;
        }
        for (fint r = 1; r < nrec; r++) {
            const char *rec = idr + (size_t)r * idr_len;
            size_t n = trimmed(rec, idr_len);
            memcpy(name + total, rec, n);
            total += n;
        }
        name[total] = '\0';
        in.num_ints = 1;
        in.ints = &wsid;
        in.str = name;
        in.str_len = total;
    }
    if ((*fctid == GESC_NCAR_FILE_NAME || *fctid == GESC_NCAR_PAUSE) && nrec >= 1) {
        in.escape_r1.size = idr_len; /* NCAR's record: IDR(1), blank filled */
        in.escape_r1.data = (void *)idr;
        gescape(*fctid, &in, NULL, NULL);
    } else if (!name) {
        /* Any other escape (a profile's, gks_binding.h): IDR(1..N) as one record of
         * N*LEN(IDR) characters in escape_r1, N = max(LIDR, MLODR): NCAR's NGSRAT passes
         * LIDR = 1 with IDR(4) and ODR(4), MLODR = 4, and NCAR's GESC reads IDR(2..4)
         * (the handler reads only what its escape defines); what it returns fills
         * ODR(1..MLODR) record by record (blank-filled). LODR is not written: NCAR's
         * NGSRAT passes one constant as MLODR and LODR (a write would fault), and NCAR's
         * GESC never sets it. */
        if (mlodr && *mlodr > nrec)
            nrec = *mlodr;
        if (nrec >= 1 && idr_len > 0 && (size_t)nrec <= SIZE_MAX / idr_len) {
            in.escape_r1.size = (size_t)nrec * idr_len;
            in.escape_r1.data = (void *)idr;
        }
        Gstore store = NULL;
        Gint serr = 0;
        Gescape_out_data *out = NULL;
        if (mlodr && *mlodr > 0 && odr && odr_len > 0)
            gcreate_store(&serr, &store);
        gescape(*fctid, &in, serr ? NULL : &store, &out);
        if (out && out->escape_r1.data) {
            const char *o = out->escape_r1.data;
            size_t n = out->escape_r1.size;
            for (size_t r = 0; r < (size_t)*mlodr && r * odr_len < n; r++) {
                size_t k = n - r * odr_len < odr_len ? n - r * odr_len : odr_len;
                memset(odr + r * odr_len, ' ', odr_len);
                memcpy(odr + r * odr_len, o + r * odr_len, k);
            }
        }
        if (store)
            gdel_store(store);
    } else
        gescape(*fctid, &in, NULL, NULL);
    free(name);
}

/* ------------------------------------------------------------------ output and attributes */
FAPI void FNAME(gpl, GPL)(const fint *n, const freal *px, const freal *py)
{
    Gpoint_list pl;
    if (make_points(*n, px, py, &pl, GFN_PL))
        return;
    gpolyline(&pl);
    free(pl.points);
}

FAPI void FNAME(gfa, GFA)(const fint *n, const freal *px, const freal *py)
{
    Gpoint_list pl;
    if (make_points(*n, px, py, &pl, GFN_FA))
        return;
    gfill_area(&pl);
    free(pl.points);
}

FAPI void FNAME(gsplci, GSPLCI)(const fint *coli) { gset_line_colr_ind(*coli); }
FAPI void FNAME(gsfaci, GSFACI)(const fint *coli) { gset_fill_colr_ind(*coli); }

FAPI void FNAME(gscr, GSCR)(const fint *wkid, const fint *ci, const freal *cr, const freal *cg,
                            const freal *cb)
{
    Gcolr_rep r;
    r.rgb.red = *cr;
    r.rgb.green = *cg;
    r.rgb.blue = *cb;
    gset_colr_rep(*wkid, *ci, &r);
}

/* ------------------------------------------------------------------ transformations */
FAPI void FNAME(gswn, GSWN)(const fint *tnr, const freal *x0, const freal *x1, const freal *y0,
                            const freal *y1)
{
    Glimit l = make_limit(x0, x1, y0, y1);
    gset_win(*tnr, &l);
}

FAPI void FNAME(gsvp, GSVP)(const fint *tnr, const freal *x0, const freal *x1, const freal *y0,
                            const freal *y1)
{
    Glimit l = make_limit(x0, x1, y0, y1);
    gset_vp(*tnr, &l);
}

FAPI void FNAME(gselnt, GSELNT)(const fint *tnr) { gsel_norm_tran(*tnr); }
FAPI void FNAME(gsclip, GSCLIP)(const fint *clsw) { gset_clip_ind((Gclip_ind)*clsw); }

FAPI void FNAME(gswkwn, GSWKWN)(const fint *wkid, const freal *x0, const freal *x1,
                                const freal *y0, const freal *y1)
{
    Glimit l = make_limit(x0, x1, y0, y1);
    gset_ws_win(*wkid, &l);
}

FAPI void FNAME(gswkvp, GSWKVP)(const fint *wkid, const freal *x0, const freal *x1,
                                const freal *y0, const freal *y1)
{
    Glimit l = make_limit(x0, x1, y0, y1);
    gset_ws_vp(*wkid, &l);
}

/* ------------------------------------------------------------------ inquiries */

/* Fortran list inquiry: N = element wanted (1-based), N = 0 only the count. */
void gks_f77_list_elem(gks_f77_list_inq f, fint n, fint *errind, fint *ol, fint *elem)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    f(n > 0 ? 1 : 0, n > 0 ? n - 1 : (n == 0 ? 0 : -1), errind, &l, &len);
    *ol = len;
    if (*errind == 0 && n > len)
        *errind = 2002; /* the C binding accepts start 0 of an empty list */
    if (*errind == 0 && n > 0)
        *elem = v;
}

FAPI void FNAME(gqops, GQOPS)(fint *opsta)
{
    Gop_st s = GST_GKCL;
    ginq_op_st(&s);
    *opsta = (fint)s;
}

/* GKSVER(MAJOR, MINOR, IPATCH): the version of the library loaded at run time (gks3d_version
 * of the C binding; not a function of the standard, so callable in any GKS state). */
FAPI void FNAME(gksver, GKSVER)(fint *major, fint *minor, fint *patch)
{
    int ma = 0, mi = 0, pa = 0;
    gks3d_version(&ma, &mi, &pa);
    *major = (fint)ma;
    *minor = (fint)mi;
    *patch = (fint)pa;
}

FAPI void FNAME(gqlvks, GQLVKS)(fint *errind, fint *level)
{
    Glevel l = GLEVEL_0A;
    ginq_level_gks(errind, &l);
    *level = (fint)l;
}

FAPI void FNAME(gqewk, GQEWK)(const fint *n, fint *errind, fint *number, fint *wktyp)
{
    gks_f77_list_elem(ginq_list_avail_ws_types, *n, errind, number, wktyp);
}

FAPI void FNAME(gqopwk, GQOPWK)(const fint *n, fint *errind, fint *ol, fint *wkid)
{
    gks_f77_list_elem(ginq_set_open_wss, *n, errind, ol, wkid);
}

FAPI void FNAME(gqacwk, GQACWK)(const fint *n, fint *errind, fint *ol, fint *wkid)
{
    gks_f77_list_elem(ginq_set_active_wss, *n, errind, ol, wkid);
}

FAPI void FNAME(gqwkm, GQWKM)(fint *errind, fint *mxopwk, fint *mxacwk, fint *mxwkas)
{
    Gws_max_nums m = { 0, 0, 0 };
    ginq_ws_max_nums(errind, &m);
    *mxopwk = m.simult_open;
    *mxacwk = m.simult_active;
    *mxwkas = m.assoc_seg;
}

FAPI void FNAME(gqmntn, GQMNTN)(fint *errind, fint *maxtnr)
{
    ginq_max_norm_tran_num(errind, maxtnr);
}

/* GQWKC(WKID, ERRIND, CONID, WTYPE): CONID = the connection identifier read as an
 * integer; -1 when it is not one (a workstation opened from C with a file name). */
FAPI void FNAME(gqwkc, GQWKC)(const fint *wkid, fint *errind, fint *conid, fint *wtype)
{
    char conn[UNIT_NAME_MAX + 2] = "";
    Gint t = 0;
    long v = -1;
    ginq_ws_conn_type(*wkid, (Gint)sizeof conn, errind, conn, &t);
    if (*errind)
        return;
    if (strlen(conn) >= sizeof conn - 1 || parse_int(conn, strlen(conn), &v))
        v = unit_recall(*wkid, conn); /* a file name: the unit GOPWK found it on, or -1 */
    *conid = (fint)v;
    *wtype = t;
}

FAPI void FNAME(gqwks, GQWKS)(const fint *wkid, fint *errind, fint *state)
{
    Gws_st s = GWS_INACTIVE;
    ginq_ws_st(*wkid, errind, &s);
    *state = (fint)s;
}

FAPI void FNAME(gqwkca, GQWKCA)(const fint *wtype, fint *errind, fint *wkcat)
{
    Gws_cat c = GCAT_OUT;
    ginq_ws_cat(*wtype, errind, &c);
    *wkcat = (fint)c;
}

FAPI void FNAME(gqwkcl, GQWKCL)(const fint *wtype, fint *errind, fint *vrtype)
{
    Gws_class c = GCLASS_VEC;
    ginq_ws_class(*wtype, errind, &c);
    *vrtype = (fint)c;
}

FAPI void FNAME(gqdsp, GQDSP)(const fint *wtype, fint *errind, fint *dcunit, freal *rxp,
                              freal *ryp, fint *lx, fint *ly)
{
    Gdisp_space_size d;
    memset(&d, 0, sizeof d);
    ginq_disp_space_size(*wtype, errind, &d);
    *dcunit = (fint)d.dc_units;
    *rxp = (freal)d.size_dc.size_x;
    *ryp = (freal)d.size_dc.size_y;
    *lx = d.size_raster.size_x;
    *ly = d.size_raster.size_y;
}

FAPI void FNAME(gqwkdu, GQWKDU)(const fint *wkid, fint *errind, fint *defmod, fint *regmod,
                                fint *dempty, fint *nframe)
{
    Gdefer_mode dm = GDEFER_ASAP;
    Girg_mode im = GIRG_SUPPR;
    Gdisp_space_empty de = GDISP_EMPTY;
    Gnew_frame_nec_upd nf = GNEW_NO;
    ginq_ws_defer_upd_sts(*wkid, errind, &dm, &im, &de, &nf);
    *defmod = (fint)dm;
    *regmod = (fint)im;
    *dempty = (fint)de;
    *nframe = (fint)nf;
}

FAPI void FNAME(gqcntn, GQCNTN)(fint *errind, fint *ctnr)
{
    ginq_cur_norm_tran_num(errind, ctnr);
}

/* GQNT(NTNR, ERRIND, WINDOW(4), VIEWPT(4)): XMIN, XMAX, YMIN, YMAX. */
FAPI void FNAME(gqnt, GQNT)(const fint *ntnr, fint *errind, freal *window, freal *viewpt)
{
    Gtran t;
    memset(&t, 0, sizeof t);
    ginq_norm_tran(*ntnr, errind, &t);
    put_limit(&t.win, window);
    put_limit(&t.vp, viewpt);
}

FAPI void FNAME(gqclip, GQCLIP)(fint *errind, fint *clsw, freal *clrect)
{
    Gclip c;
    memset(&c, 0, sizeof c);
    ginq_clip(errind, &c);
    *clsw = (fint)c.clip_ind;
    put_limit(&c.clip_rect, clrect);
}

FAPI void FNAME(gqplci, GQPLCI)(fint *errind, fint *coli) { ginq_line_colr_ind(errind, coli); }
FAPI void FNAME(gqfaci, GQFACI)(fint *errind, fint *coli) { ginq_fill_colr_ind(errind, coli); }

FAPI void FNAME(gqcr, GQCR)(const fint *wkid, const fint *coli, const fint *type, fint *errind,
                            freal *red, freal *green, freal *blue)
{
    Gcolr_rep r;
    memset(&r, 0, sizeof r);
    ginq_colr_rep(*wkid, *coli, (Ginq_type)*type, errind, &r);
    *red = (freal)r.rgb.red;
    *green = (freal)r.rgb.green;
    *blue = (freal)r.rgb.blue;
}

FAPI void FNAME(gqwkt, GQWKT)(const fint *wkid, fint *errind, fint *tus, freal *rwindo,
                              freal *cwindo, freal *rviewp, freal *cviewp)
{
    Gupd_st u = GUPD_NOT_PEND;
    Glimit rw, cw, rv, cv;
    memset(&rw, 0, sizeof rw);
    cw = rv = cv = rw;
    ginq_ws_tran(*wkid, errind, &u, &rw, &cw, &rv, &cv);
    *tus = (fint)u;
    put_limit(&rw, rwindo);
    put_limit(&cw, cwindo);
    put_limit(&rv, rviewp);
    put_limit(&cv, cviewp);
}

/* ------------------------------------------------------------------ helpers for GERLOG */
/* GKFNAM(FCTID, NAME, LNAME): the ISO name of a function identification, blank-padded;
 * LNAME = its length (0 if unknown). Not part of ISO 8651-1. */
FAPI void FNAME(gkfnam, GKFNAM)(const fint *fctid, char *name, fint *lname, size_t name_len)
{
    *lname = gks_f77_fill_str(gks_function_name(*fctid), name, name_len);
}

/* GKEMSG(ERRNR, MSG, LMSG): the standard message of an error number, blank-padded; while
 * ERROR HANDLING runs for ERRNR, followed by ": " and the detail (gks_error_detail: the
 * file and the system's reason, the missing display). */
FAPI void FNAME(gkemsg, GKEMSG)(const fint *errnr, char *msg, fint *lmsg, size_t msg_len)
{
    Gint in_handler = 0, last = 0;
    ginq_err_st(&in_handler, &last);
    const char *m = gks_error_message(*errnr), *d = gks_error_detail();
    if (!in_handler || last != *errnr || !*d) {
        *lmsg = gks_f77_fill_str(m, msg, msg_len);
        return;
    }
    char buf[1024];
    snprintf(buf, sizeof buf, "%s: %s", m, d);
    *lmsg = gks_f77_fill_str(buf, msg, msg_len);
}

/* ------------------------------------------------- GKS-3D output and viewing */
/* Names and argument lists as CERN's GKSGRAL-3D primer documents them (BINDINGS.md
 * §1.5); where it is silent, the documented [I] names. REAL(4,4) matrices: element (i,j)
 * is row i, column j of the matrix acting on column vectors, stored column-major. */

static int make_points3(fint n, const freal *px, const freal *py, const freal *pz,
                        Gpoint_list3 *pl, Gint fctid)
{
    pl->num_points = n;
    pl->points = NULL;
    if (n <= 0)
        return 0;
    if (!(pl->points = gks_f77_alloc((size_t)n, sizeof(Gpoint3)))) {
        gks_f77_nomem(fctid);
        return -1;
    }
    for (fint i = 0; i < n; i++)
        pl->points[i] = (Gpoint3){ px[i], py[i], pz[i] };
    return 0;
}

static void from_fmatrix4(const freal *a, Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = a[i + 4 * j];
}

static void to_fmatrix4(const Gmatrix3 m, freal *a)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            a[i + 4 * j] = (freal)m[i][j];
}

static Glimit3 make_limit3(const freal *a)
{
    Glimit3 l = { a[0], a[1], a[2], a[3], a[4], a[5] };
    return l;
}

/* GPL3(N, PXA, PYA, PZA) / GFA3(N, PXA, PYA, PZA) */
FAPI void FNAME(gpl3, GPL3)(const fint *n, const freal *px, const freal *py, const freal *pz)
{
    Gpoint_list3 pl;
    if (make_points3(*n, px, py, pz, &pl, GFN_PL3))
        return;
    gpolyline3(&pl);
    free(pl.points);
}

FAPI void FNAME(gfa3, GFA3)(const fint *n, const freal *px, const freal *py, const freal *pz)
{
    Gpoint_list3 pl;
    if (make_points3(*n, px, py, pz, &pl, GFN_FA3))
        return;
    gfill_area3(&pl);
    free(pl.points);
}

/* GSW3(TNR, WN(6)) / GSV3(TNR, VP(6)): XMIN, XMAX, YMIN, YMAX, ZMIN, ZMAX. */
FAPI void FNAME(gsw3, GSW3)(const fint *tnr, const freal *wn)
{
    Glimit3 l = make_limit3(wn);
    gset_win3(*tnr, &l);
}

FAPI void FNAME(gsv3, GSV3)(const fint *tnr, const freal *vp)
{
    Glimit3 l = make_limit3(vp);
    gset_vp3(*tnr, &l);
}

FAPI void FNAME(gsvwi, GSVWI)(const fint *vwi) { gset_view_ind(*vwi); }
FAPI void FNAME(gshrm, GSHRM)(const fint *wkid, const fint *hrm) { gset_hlhsr_mode(*wkid, *hrm); }

/* GSVWR(WKID, VWI, VWM(4,4), PRM(4,4), VCLP(6), CLW, CLB, CLF): SET VIEW REPRESENTATION 3
 * with the orientation matrix, the mapping matrix, the NPC3 clip limits and the xy, back
 * and front clip indicators (GNCLIP/GCLIP). */
FAPI void FNAME(gsvwr, GSVWR)(const fint *wkid, const fint *vwi, const freal *vwm,
                              const freal *prm, const freal *vclp, const fint *clw,
                              const fint *clb, const fint *clf)
{
    Gview_rep3 r;
    from_fmatrix4(vwm, r.ori_matrix);
    from_fmatrix4(prm, r.map_matrix);
    r.clip_limit = make_limit3(vclp);
    r.xy_clip = (Gclip_ind)*clw;
    r.back_clip = (Gclip_ind)*clb;
    r.front_clip = (Gclip_ind)*clf;
    gset_view_rep3(*wkid, *vwi, &r);
}

/* GEVVWM(VRPX,VRPY,VRPZ, VUPX,VUPY,VUPZ, VPNX,VPNY,VPNZ, CSW, ERR, VWM(4,4)):
 * EVALUATE VIEW ORIENTATION MATRIX 3. Note the order: VUP BEFORE VPN (GKSGRAL-3D), unlike
 * PHIGS PEVOM3 and the C binding. */
FAPI void FNAME(gevvwm, GEVVWM)(const freal *vrpx, const freal *vrpy, const freal *vrpz,
                                const freal *vupx, const freal *vupy, const freal *vupz,
                                const freal *vpnx, const freal *vpny, const freal *vpnz,
                                const fint *csw, fint *err, freal *vwm)
{
    Gpoint3 vrp = { *vrpx, *vrpy, *vrpz };
    Gvec3 vup = { *vupx, *vupy, *vupz }, vpn = { *vpnx, *vpny, *vpnz };
    Gmatrix3 m;
    Gint e = 0;
    geval_view_ori_matrix3(&vrp, &vpn, &vup, (Gcoord_switch)*csw, &e, m);
    *err = e;
    if (!e)
        to_fmatrix4((const Gfloat (*)[4])m, vwm);
}

/* GEVPJM(UMIN,UMAX,VMIN,VMAX, PRVP(6), PROTYP, PRPU,PRPV,PRPN, VPD, BPD, FPD, ERR, PRM(4,4)):
 * EVALUATE VIEW MAPPING MATRIX 3; PROTYP GPARL = 0 / GPERS = 1. */
FAPI void FNAME(gevpjm, GEVPJM)(const freal *umin, const freal *umax, const freal *vmin,
                                const freal *vmax, const freal *prvp, const fint *protyp,
                                const freal *prpu, const freal *prpv, const freal *prpn,
                                const freal *vpd, const freal *bpd, const freal *fpd,
                                fint *err, freal *prm)
{
    Gview_map3 v = { { *umin, *umax, *vmin, *vmax }, make_limit3(prvp), (Gproj_type)*protyp,
                     { *prpu, *prpv, *prpn }, *vpd, *bpd, *fpd };
    Gmatrix3 m;
    Gint e = 0;
    geval_view_map_matrix3(&v, &e, m);
    *err = e;
    if (!e)
        to_fmatrix4((const Gfloat (*)[4])m, prm);
}

/* 2-D segment matrices REAL M(2,3), column-major (BINDINGS.md §1.1). */
static void from_fmatrix23(const freal *a, Gtran_matrix m)
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            m[i][j] = a[i + 2 * j];
}

static void to_fmatrix23(const Gtran_matrix m, freal *a)
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            a[i + 2 * j] = (freal)m[i][j];
}

/* GEVTM(X0,Y0,DX,DY,PHI,SX,SY,SW,MOUT(2,3)) */
FAPI void FNAME(gevtm, GEVTM)(const freal *x0, const freal *y0, const freal *dx,
                              const freal *dy, const freal *phi, const freal *sx,
                              const freal *sy, const fint *sw, freal *mout)
{
    Gpoint f = { *x0, *y0 };
    Gvec s = { *dx, *dy }, sc = { *sx, *sy };
    Gtran_matrix m;
    from_fmatrix23(mout, m); /* on error the core leaves m, so MOUT stays unchanged */
    geval_tran_matrix(&f, &s, *phi, &sc, (Gcoord_switch)*sw, m);
    to_fmatrix23((const Gfloat (*)[3])m, mout);
}

/* GACTM(MINP(2,3),X0,Y0,DX,DY,PHI,SX,SY,SW,MOUT(2,3)) */
FAPI void FNAME(gactm, GACTM)(const freal *minp, const freal *x0, const freal *y0,
                              const freal *dx, const freal *dy, const freal *phi,
                              const freal *sx, const freal *sy, const fint *sw, freal *mout)
{
    Gtran_matrix in, m;
    from_fmatrix23(minp, in);
    from_fmatrix23(mout, m); /* unchanged on error */
    Gpoint f = { *x0, *y0 };
    Gvec s = { *dx, *dy }, sc = { *sx, *sy };
    gaccum_tran_matrix((const Gfloat (*)[3])in, &f, &s, *phi, &sc, (Gcoord_switch)*sw, m);
    to_fmatrix23((const Gfloat (*)[3])m, mout);
}
