/* SPDX-License-Identifier: MIT */
/*
 * test_f77_oom.c -- the FORTRAN 77 binding's allocations (gks_f77_alloc) fail in turn.
 * Linked with the test build of the wrappers (gks3d_fortran_test) and of the library
 * (gks3d_test), where gks_f77_alloc goes through the library's failure injection
 * (gks_alloc_fail_after). For each wrapper below, called from C as a Fortran program calls
 * it: the allocations of one call are counted, then each fails in turn. A failed
 * allocation of the binding must give error 300 -- through GERHND (defined here, in place
 * of the library's) for a function, in ERRIND for an inquiry -- and no other error; a
 * failed allocation of the library behind it may only give 300 as well. Nothing crashes,
 * and in the AddressSanitizer build nothing leaks. Prints the counts.
 *
 * The wrappers reach 20 of the binding's 23 call sites of gks_f77_alloc: str_dup_n (GMSG),
 * make_points (GPL), make_points3 (GPL3), GESC's file name, fstr (GTX), points2 (GPM),
 * points3 (GPM3), sub_array (GCA), fill_set's four (GFAS, GFAS3), str_buffer (GINST),
 * stroke_buffer (GINSK), GQSTS, pets_buffer (GQDLC), GINSK3, GQSKS3, GQSTS3, GQPXA. Not
 * reached: GRQSK3, GSMSK3 and GGTSK3 (REQUEST, SAMPLE and GET need operator input).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "gks_fortran.h"
#include "gks_alloc.h"

long gks_f77_alloc_injected(void); /* gks_fortran.c, test build only */

enum { WK = 1 };
static int n_err, err_other;
static fint last_err, last_fct;

/* The program's own ERROR HANDLING subroutine (replaces gerhnd.f). */
void FNAME(gerhnd, GERHND)(const fint *errnr, const fint *fctid, const fint *errfil)
{
    (void)errfil;
    n_err++;
    last_err = *errnr;
    last_fct = *fctid;
    if (*errnr != 300)
        err_other = *errnr;
}

/* The wrappers, as a Fortran program calls them (hidden CHARACTER lengths last). */
void FNAME(gopks, GOPKS)(const fint *, const fint *);
void FNAME(gclks, GCLKS)(void);
void FNAME(gopwk, GOPWK)(const fint *, const fint *, const fint *);
void FNAME(gswkvp, GSWKVP)(const fint *, const freal *, const freal *, const freal *, const freal *);
void FNAME(gacwk, GACWK)(const fint *);
void FNAME(gdawk, GDAWK)(const fint *);
void FNAME(gclwk, GCLWK)(const fint *);
void FNAME(gmsg, GMSG)(const fint *, const char *, size_t);
void FNAME(gesc, GESC)(const fint *, const fint *, const char *, const fint *, fint *, char *,
                       size_t, size_t);
void FNAME(gpl, GPL)(const fint *, const freal *, const freal *);
void FNAME(gpl3, GPL3)(const fint *, const freal *, const freal *, const freal *);
void FNAME(gpm, GPM)(const fint *, const freal *, const freal *);
void FNAME(gpm3, GPM3)(const fint *, const freal *, const freal *, const freal *);
void FNAME(gtx, GTX)(const freal *, const freal *, const char *, size_t);
void FNAME(gfas, GFAS)(const fint *, const fint *, const freal *, const freal *);
void FNAME(gfas3, GFAS3)(const fint *, const fint *, const freal *, const freal *,
                         const freal *);
void FNAME(gca, GCA)(const freal *, const freal *, const freal *, const freal *, const fint *,
                     const fint *, const fint *, const fint *, const fint *, const fint *,
                     const fint *);
void FNAME(ginsk, GINSK)(const fint *, const fint *, const fint *, const fint *, const freal *,
                         const freal *, const fint *, const freal *, const freal *,
                         const freal *, const freal *, const fint *, const fint *,
                         const char *, size_t);
void FNAME(ginst, GINST)(const fint *, const fint *, const fint *, const char *, const fint *,
                         const freal *, const freal *, const freal *, const freal *,
                         const fint *, const fint *, const fint *, const char *, size_t,
                         size_t);
void FNAME(ginsk3, GINSK3)(const fint *, const fint *, const fint *, const fint *, const fint *,
                           const freal *, const freal *, const freal *, const fint *,
                           const freal *, const fint *, const fint *, const char *, size_t);
void FNAME(gqsts, GQSTS)(const fint *, const fint *, const fint *, fint *, fint *, fint *,
                         fint *, char *, fint *, freal *, fint *, fint *, fint *, char *,
                         size_t, size_t);
void FNAME(gqsts3, GQSTS3)(const fint *, const fint *, const fint *, fint *, fint *, fint *,
                           fint *, char *, fint *, freal *, fint *, fint *, fint *, char *,
                           size_t, size_t);
void FNAME(gqsks3, GQSKS3)(const fint *, const fint *, const fint *, const fint *, const fint *,
                           fint *, fint *, fint *, fint *, fint *, fint *, freal *, freal *,
                           freal *, fint *, freal *, fint *, fint *, char *, size_t);
void FNAME(gqdlc, GQDLC)(const fint *, const fint *, const fint *, const fint *, fint *,
                         freal *, freal *, fint *, fint *, freal *, fint *, char *, size_t);
void FNAME(gqpxa, GQPXA)(const fint *, const freal *, const freal *, const fint *,
                         const fint *, const fint *, const fint *, const fint *, const fint *,
                         fint *, fint *, fint *);

static const fint one = 1, two = 2, three = 3, four = 4, zero = 0, wk = WK;
static const freal xs[4] = { 0.1f, 0.9f, 0.9f, 0.1f }, ys[4] = { 0.1f, 0.1f, 0.9f, 0.9f },
                   zs[4] = { 0.5f, 0.5f, 0.5f, 0.5f };
static const freal sx[6] = { 0.1f, 0.4f, 0.1f, 0.6f, 0.9f, 0.9f },
                   sy[6] = { 0.1f, 0.1f, 0.4f, 0.6f, 0.6f, 0.9f };
static const fint sptr[2] = { 3, 6 }; /* two triangles: points 1-3 and 4-6 */
static char blank80[80];

/* Each case calls one wrapper; returns the ERRIND of an inquiry, else 0. */
static fint c_gmsg(void) { FNAME(gmsg, GMSG)(&wk, "HELLO", 5); return 0; }
static fint c_gesc(void)
{
    char idr[2][80];
    memset(idr, ' ', sizeof idr);
    memcpy(idr[0], "         1", 10);
    memcpy(idr[1], "t_f77_oom", 9);
    const fint fct = GESC_SET_FILE_NAME;
    fint lodr = 0;
    char odr[80];
    FNAME(gesc, GESC)(&fct, &two, &idr[0][0], &one, &lodr, odr, 80, 80);
    return 0;
}
static fint c_gpl(void) { FNAME(gpl, GPL)(&four, xs, ys); return 0; }
static fint c_gpl3(void) { FNAME(gpl3, GPL3)(&four, xs, ys, zs); return 0; }
static fint c_gpm(void) { FNAME(gpm, GPM)(&four, xs, ys); return 0; }
static fint c_gpm3(void) { FNAME(gpm3, GPM3)(&four, xs, ys, zs); return 0; }
static fint c_gtx(void)
{
    const freal x = 0.2f, y = 0.5f;
    FNAME(gtx, GTX)(&x, &y, "TEXT", 4);
    return 0;
}
static fint c_gfas(void)
{
    FNAME(gfas, GFAS)(&two, sptr, sx, sy);
    return 0;
}
static fint c_gfas3(void)
{
    const freal sz[6] = { 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f };
    FNAME(gfas3, GFAS3)(&two, sptr, sx, sy, sz);
    return 0;
}
static fint c_gca(void)
{
    const freal px = 0.1f, py = 0.1f, qx = 0.4f, qy = 0.4f;
    const fint colia[4] = { 1, 2, 3, 4 };
    FNAME(gca, GCA)(&px, &py, &qx, &qy, &two, &two, &one, &one, &two, &two, colia);
    return 0;
}
static fint c_ginsk(void)
{
    const freal x0 = 0, x1 = 1024, y0 = 0, y1 = 1024;
    const fint tnr = 0, buf = 64;
    FNAME(ginsk, GINSK)(&wk, &one, &tnr, &two, xs, ys, &one, &x0, &x1, &y0, &y1, &buf, &zero,
                        blank80, 80);
    return 0;
}
static fint c_ginst(void)
{
    const freal x0 = 0, x1 = 1024, y0 = 0, y1 = 1024;
    const fint buf = 64;
    FNAME(ginst, GINST)(&wk, &one, &three, "ABC", &one, &x0, &x1, &y0, &y1, &buf, &one, &zero,
                        blank80, 3, 80);
    return 0;
}
static fint c_ginsk3(void)
{
    const freal evol[6] = { 0, 1024, 0, 1024, 0, 1 };
    const fint buf = 64;
    FNAME(ginsk3, GINSK3)(&wk, &one, &zero, &zero, &two, xs, ys, zs, &one, evol, &buf, &zero,
                          blank80, 80);
    return 0;
}
static fint c_gqsts(void)
{
    fint e = -1, mode, esw, lostr, pet, buf, inipos, ldr;
    freal earea[4];
    char istr[80], datrec[80];
    FNAME(gqsts, GQSTS)(&wk, &one, &one, &e, &mode, &esw, &lostr, istr, &pet, earea, &buf,
                        &inipos, &ldr, datrec, 80, 80);
    return e;
}
static fint c_gqsts3(void)
{
    fint e = -1, mode, esw, lostr, pet, buf, inipos, ldr;
    freal evol[6];
    char istr[80], datrec[80];
    FNAME(gqsts3, GQSTS3)(&wk, &one, &one, &e, &mode, &esw, &lostr, istr, &pet, evol, &buf,
                          &inipos, &ldr, datrec, 80, 80);
    return e;
}
static fint c_gqsks3(void)
{
    fint e = -1, mode, esw, viewi, tnr, np, pet, buf, ldr;
    freal px[8], py[8], pz[8], evol[6];
    char datrec[80];
    FNAME(gqsks3, GQSKS3)(&wk, &one, &zero, &two, &one, &e, &mode, &esw, &viewi, &tnr, &np, px,
                          py, pz, &pet, evol, &buf, &ldr, datrec, 80);
    return e;
}
static fint c_gqdlc(void)
{
    fint e = -1, ol, pet, ldr;
    freal dpx, dpy, earea[4];
    char datrec[80];
    const fint wtype = GWS_TYPE_PNG;
    FNAME(gqdlc, GQDLC)(&wtype, &one, &one, &one, &e, &dpx, &dpy, &ol, &pet, earea, &ldr,
                        datrec, 80);
    return e;
}
static fint c_gqpxa(void)
{
    fint e = -1, inv, colia[4];
    const freal px = 0.5f, py = 0.5f;
    FNAME(gqpxa, GQPXA)(&wk, &px, &py, &two, &two, &one, &one, &two, &two, &e, &inv, colia);
    return e;
}

static const struct {
    const char *name;
    fint (*call)(void);
} cases[] = {
    { "GMSG", c_gmsg },     { "GESC", c_gesc },     { "GPL", c_gpl },
    { "GPL3", c_gpl3 },     { "GPM", c_gpm },       { "GPM3", c_gpm3 },
    { "GTX", c_gtx },       { "GFAS", c_gfas },     { "GFAS3", c_gfas3 },
    { "GCA", c_gca },       { "GINSK", c_ginsk },   { "GINST", c_ginst },
    { "GINSK3", c_ginsk3 }, { "GQSTS", c_gqsts },   { "GQSTS3", c_gqsts3 },
    { "GQSKS3", c_gqsks3 }, { "GQDLC", c_gqdlc },   { "GQPXA", c_gqpxa },
};

/* GKS open, a PNG workstation (OUTIN: it has input devices) active. */
static void start(void)
{
    const fint errfil = 0, bufa = 0, conid = 77, wtype = GWS_TYPE_PNG;
    FNAME(gopks, GOPKS)(&errfil, &bufa);
    FNAME(gopwk, GOPWK)(&wk, &conid, &wtype);
    FNAME(gacwk, GACWK)(&wk);
    /* a 63 x 63-pixel picture: every run writes it at CLOSE WORKSTATION (at the default
       1024 x 1024 pixels most of the test's time went there) */
    const freal x0 = 0.0f, x1 = 63.0f;
    FNAME(gswkvp, GSWKVP)(&wk, &x0, &x1, &x0, &x1);
}

static void stop(void)
{
    FNAME(gdawk, GDAWK)(&wk);
    FNAME(gclwk, GCLWK)(&wk);
    FNAME(gclks, GCLKS)();
}

int main(void)
{
    int bad = 0;
    long total = 0, f77_total = 0, reported = 0;
    memset(blank80, ' ', sizeof blank80);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        start();
        n_err = 0;
        err_other = 0;
        long a0 = gks_alloc_count();
        fint e = cases[c].call();
        long used = gks_alloc_count() - a0;
        if (n_err || e) {
            printf("FAIL %s without failures: error %d (ERRIND %d)\n", cases[c].name,
                   (int)last_err, (int)e);
            bad++;
        }
        stop();
        long f77_here = 0;
        for (long n = 1; n <= used; n++) {
            start();
            n_err = 0;
            err_other = 0;
            long i0 = gks_f77_alloc_injected();
            gks_alloc_fail_after(n);
            e = cases[c].call();
            gks_alloc_fail_after(0);
            int in_f77 = gks_f77_alloc_injected() > i0;
            f77_here += in_f77;
            int got300 = (n_err > 0 && !err_other) || e == 300;
            if (err_other || (e != 0 && e != 300) || (in_f77 && !got300)) {
                printf("FAIL %s allocation %ld (%s): %d errors, last %d in %d, ERRIND %d\n",
                       cases[c].name, n, in_f77 ? "binding" : "library", n_err,
                       (int)last_err, (int)last_fct, (int)e);
                bad++;
            }
            reported += got300;
            stop();
        }
        if (f77_here < 1) {
            printf("FAIL %s: no allocation of the binding\n", cases[c].name);
            bad++;
        }
        total += used;
        f77_total += f77_here;
    }
    unlink("77");
    unlink("t_f77_oom");
    printf("F77_OOM: %zu wrappers, %ld allocations failed in turn (%ld of them the binding's, "
           "each reported 300), %ld reported 300 in all\n",
           sizeof cases / sizeof cases[0], total, f77_total, reported);
    printf(bad ? "F77_OOM FAIL\n" : "F77_OOM PASS\n");
    return bad != 0;
}
