/* SPDX-License-Identifier: MIT */
/* test_ncarg_profile.c -- the NCAR Graphics profile (libgks3d_ncarg, docs/NCAR.md) through
 * the C and Fortran entries a program linked with it reaches: NCAR's initial state and
 * colour table, fill style 4, the workstation type mapping, escape -1388 (NGSRAT's
 * records through GESC), the PostScript escapes, GZW2NX and GZW2NY. NCAR Graphics itself
 * is not needed. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"
#include "FC.h"

typedef int fint;
typedef float freal;
void FC_GLOBAL(gesc, GESC)(const fint *fctid, const fint *lidr, const char *idr,
                           const fint *mlodr, fint *lodr, char *odr, size_t idr_len,
                           size_t odr_len);
void FC_GLOBAL(gzw2nx, GZW2NX)(const fint *n, const freal *p, freal *q);
void FC_GLOBAL(gzw2ny, GZW2NY)(const fint *n, const freal *p, freal *q);

/* GESC(fct, lidr, IDR, 4, 4, ODR) with CHARACTER*80 IDR(4), ODR(4), MLODR and LODR one
 * constant in read-only memory, as NGSRAT passes them (a write to LODR would fault). */
static const fint four = 4;
static void gesc80(fint fct, fint lidr, const char idr[][80], char odr[4][80])
{
    FC_GLOBAL(gesc, GESC)(&fct, &lidr, &idr[0][0], &four, (fint *)&four, &odr[0][0], 80, 80);
}

static void rec(char r[80], const char *s)
{
    memset(r, ' ', 80);
    memcpy(r, s, strlen(s));
}

static void test_initial_state(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    Gint e;
    Gfill_int_style fis;
    ginq_fill_int_style(&e, &fis);
    assert_int_equal(fis, GSTYLE_SOLID); /* NCAR's, not ISO's HOLLOW */
    gset_fill_int_style((Gfill_int_style)4); /* PLOTCHAR's solid text fill */
    ginq_fill_int_style(&e, &fis);
    assert_int_equal(fis, GSTYLE_SOLID);
    gset_fill_int_style(GSTYLE_HATCH);
    ginq_fill_int_style(&e, &fis);
    assert_int_equal(fis, GSTYLE_HATCH);
    gset_fill_int_style((Gfill_int_style)5); /* still not a style */
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 2000);
    /* NCAR's NCGM type 1: a PNG workstation of category OUTPUT, colours 0 black, 1 white */
    gopen_ws(1, "ncarprof", 1);
    assert_int_equal(n_captured, 1);
    Gcolr_rep c;
    ginq_colr_rep(1, 0, GINQ_SET, &e, &c);
    assert_int_equal(e, 0);
    assert_true(c.rgb.red == 0 && c.rgb.green == 0 && c.rgb.blue == 0);
    ginq_colr_rep(1, 1, GINQ_SET, &e, &c);
    assert_true(c.rgb.red == 1 && c.rgb.green == 1 && c.rgb.blue == 1);
    Gws_cat cat;
    ginq_ws_cat(1, &e, &cat);
    assert_int_equal(e, 0);
    assert_int_equal(cat, GCAT_OUT); /* so NCAR's FRAME does not request a string */
    ginq_ws_cat(20, &e, &cat); /* NCAR's colour PostScript: ours (cairo) or none */
#ifdef GKS_HAVE_CAIRO
    assert_int_equal(e, 0);
#else
    assert_int_equal(e, 23);
#endif
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(access("ncarprof.png", F_OK), 0);
    unlink("ncarprof.png");
    assert_int_equal(n_captured, 1);
    /* GKS3D_WS_TYPES overrides the profile's mapping */
    setenv("GKS3D_WS_TYPES", "1=99", 1);
    gopen_gks(NULL, 0);
    ginq_ws_cat(1, &e, &cat);
    assert_int_equal(cat, GCAT_OUT);
    gopen_ws(1, "ncarprof", 1);
    char conn[32];
    Gint type;
    ginq_ws_conn_type(1, (Gint)sizeof conn, &e, conn, &type);
    gclose_ws(1);
    gclose_gks();
    unsetenv("GKS3D_WS_TYPES");
    assert_int_equal(access("ncarprof.png", F_OK), -1); /* the null workstation */
    assert_int_equal(n_captured, 1);
}

static void test_escape_1388(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    char idr[4][80], odr[4][80];
    rec(idr[0], "    0"); /* save */
    gesc80(-1388, 1, (const char (*)[80])idr, odr);
    gset_linetype(2);
    gset_fill_colr_ind(5);
    gset_char_ht(0.25);
    rec(idr[0], "    2"); /* get */
    memset(odr, 'x', sizeof odr);
    gesc80(-1388, 1, (const char (*)[80])idr, odr);
    int v[14]; /* 7I10, 7I10 */
    char f[11] = { 0 };
    for (int i = 0; i < 14; i++) {
        memcpy(f, odr[i / 7] + 10 * (i % 7), 10);
        v[i] = atoi(f);
    }
    assert_int_equal(v[0], 1);  /* clipping on */
    assert_int_equal(v[1], 2);  /* linetype */
    assert_int_equal(v[11], GSTYLE_SOLID);
    assert_int_equal(v[13], 5); /* fill colour */
    assert_true(odr[0][75] == ' ' && odr[1][79] == ' '); /* blank-filled */
    char r5[17] = { 0 };
    memcpy(r5, odr[2] + 64, 16);
    assert_float_equal(atof(r5), 0.25, 1e-6); /* character height */
    rec(idr[0], "    1"); /* restore */
    gesc80(-1388, 1, (const char (*)[80])idr, odr);
    Gint e, lt, fc;
    ginq_linetype(&e, &lt);
    ginq_fill_colr_ind(&e, &fc);
    assert_int_equal(lt, 1);
    assert_int_equal(fc, 1);
    /* set: NGSRAT's IOPT 3 record, linetype 3, fill colour 7, height 0.5 */
    /* NGSRAT's IOPT 3 records (LIDR = 1, as NGSRAT passes it) */
    rec(idr[0], "    3         1         3         1         3         1         1         0");
    rec(idr[1], "         1         0         0         0         1         1         7");
    rec(idr[2], "   1.0000000E+00   1.0000000E+00   1.0000000E+00   0.0000000E+00   5.0000000E-01");
    rec(idr[3], "   0.0000000E+00   1.0000000E+00");
    gesc80(-1388, 1, (const char (*)[80])idr, odr);
    if (n_captured)
        print_message("error %d\n", captured[0].err);
    assert_int_equal(n_captured, 0);
    ginq_linetype(&e, &lt);
    ginq_fill_colr_ind(&e, &fc);
    assert_int_equal(lt, 3);
    assert_int_equal(fc, 7);
    Gfloat h;
    ginq_char_ht(&e, &h);
    assert_float_equal(h, 0.5, 1e-6);
    rec(idr[0], "   xx"); /* a malformed option */
    gesc80(-1388, 1, (const char (*)[80])idr, odr);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 182);
    gclose_gks();
}

#ifdef GKS_HAVE_CAIRO
/* The contents of file (at most cap - 1 bytes) in buf, NUL-terminated with NULs replaced */
static void slurp(const char *file, char *buf, size_t cap)
{
    FILE *f = fopen(file, "rb");
    size_t n = f ? fread(buf, 1, cap - 1, f) : 0;
    if (f)
        fclose(f);
    for (size_t i = 0; i < n; i++)
        if (!buf[i])
            buf[i] = ' ';
    buf[n] = '\0';
}
#endif

/* NCAR's PostScript/PDF escapes as NGSETI and NGSETR write them: onto a PDF workstation
 * the line style and page escapes of gks.h (the page as cairo writes it: the MediaBox);
 * for a workstation that is not a vector one, and one not open, no effect and no error. */
static void test_escape_ps_and_others(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    char idr[4][80], odr[4][80];
    rec(idr[0], "    1 1"); /* join, cap of workstation 1 (not open): no effect */
    gesc80(-1518, 1, (const char (*)[80])idr, odr);
    gesc80(-1519, 1, (const char (*)[80])idr, odr);
    rec(idr[0], "    1    4.000"); /* miter limit, nominal line width */
    gesc80(-1520, 1, (const char (*)[80])idr, odr);
    gesc80(-1516, 1, (const char (*)[80])idr, odr);
    assert_int_equal(n_captured, 0);
    /* LX LY UX UY (NGSETI): 4I9 in columns 2-10, 12-20, 22-30, 32-40; then PW, PH */
    rec(idr[0], "       100       200       300       400");
    gesc80(-1521, 1, (const char (*)[80])idr, odr);
    rec(idr[0], "  500");
    gesc80(-1529, 1, (const char (*)[80])idr, odr);
    rec(idr[0], "  600");
    gesc80(-1530, 1, (const char (*)[80])idr, odr);
    assert_int_equal(n_captured, 0);
#ifdef GKS_HAVE_CAIRO /* else NCAR's PDF type answers 23 */
    gopen_ws(4, "ncarpage.pdf", 11); /* NCAR's PDF type */
    gopen_ws(5, "ncarpage2", 1);     /* NCGM: PNG, not a vector workstation */
    rec(idr[0], "    4 0");          /* miter joins on the PDF, none on the PNG */
    gesc80(-1518, 1, (const char (*)[80])idr, odr);
    rec(idr[0], "    5 0");
    gesc80(-1518, 1, (const char (*)[80])idr, odr);
    rec(idr[0], "    4 7"); /* NCAR writes 0..2 */
    gesc80(-1519, 1, (const char (*)[80])idr, odr);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 182);
    n_captured = 0;
    gactivate_ws(4);
    Gpoint p[2] = { { 0.1f, 0.1f }, { 0.9f, 0.9f } };
    Gpoint_list l = { 2, p };
    gpolyline(&l);
    gdeactivate_ws(4);
    gclose_ws(4);
    gclose_ws(5);
    assert_int_equal(n_captured, 0);
    static char buf[1 << 16];
    slurp("ncarpage.pdf", buf, sizeof buf);
    assert_non_null(strstr(buf, "/MediaBox [ 0 0 500 600 ]"));
#endif
    gesc80(-1999, 1, (const char (*)[80])idr, odr); /* not NCAR's: as without the profile */
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 180);
    gclose_gks();
}

/* -1387 (NGMFTC) closes the workstation; -1389 (NGREOP, no attributes, two colours from
 * index 2) opens it again on the file named, with those colours. */
static void test_suspend_reopen(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    char idr[6][80], odr[4][80];
    gopen_ws(3, "ncarreop", 1);
    rec(idr[0], "    3");
    gesc80(-1387, 1, (const char (*)[80])idr, odr);
    Gint e, t;
    char conn[32];
    ginq_ws_conn_type(3, (Gint)sizeof conn, &e, conn, &t);
    assert_int_equal(e, 7); /* closed: no workstation open, GKS back in GKOP */
    rec(idr[0], "    3    2    1    0    2    2    0");
    rec(idr[1], "ncarreop");
    rec(idr[2], "");
    rec(idr[3], "");
    rec(idr[4], "");
    rec(idr[5], " 1.000 0.500 0.000 0.000 0.000 1.000");
    fint fct = -1389, lidr = 6, one = 1;
    FC_GLOBAL(gesc, GESC)(&fct, &lidr, &idr[0][0], &one, &one, &odr[0][0], 80, 80);
    assert_int_equal(n_captured, 0);
    ginq_ws_conn_type(3, (Gint)sizeof conn, &e, conn, &t);
    assert_int_equal(e, 0);
    assert_string_equal(conn, "ncarreop");
    Gcolr_rep c;
    ginq_colr_rep(3, 2, GINQ_SET, &e, &c);
    assert_true(c.rgb.red == 1 && fabs(c.rgb.green - 0.5) < 1e-6 && c.rgb.blue == 0);
    ginq_colr_rep(3, 3, GINQ_SET, &e, &c);
    assert_true(c.rgb.red == 0 && c.rgb.green == 0 && c.rgb.blue == 1);
    gclose_ws(3);
    gclose_gks();
    unlink("ncarreop.png");
    assert_int_equal(n_captured, 0);
}

static void test_w2n(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    Glimit w = { 10, 20, -1, 1 }, v = { 0.1, 0.6, 0.2, 0.4 };
    gset_win(1, &w);
    gset_vp(1, &v);
    gsel_norm_tran(1);
    fint n = 2;
    freal p[2] = { 10, 15 }, q[2];
    FC_GLOBAL(gzw2nx, GZW2NX)(&n, p, q);
    assert_float_equal(q[0], 0.1, 1e-6);
    assert_float_equal(q[1], 0.35, 1e-6);
    p[0] = -1;
    p[1] = 0;
    FC_GLOBAL(gzw2ny, GZW2NY)(&n, p, q);
    assert_float_equal(q[0], 0.2, 1e-6);
    assert_float_equal(q[1], 0.3, 1e-6);
    assert_int_equal(n_captured, 0);
    gclose_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_initial_state),
        cmocka_unit_test(test_escape_1388),
        cmocka_unit_test(test_escape_ps_and_others),
        cmocka_unit_test(test_suspend_reopen),
        cmocka_unit_test(test_w2n),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
