/* SPDX-License-Identifier: MIT */
/* test_legacy_env.c -- the legacy-program switches read at OPEN GKS: GKS3D_WS_TYPES maps
 * foreign workstation types (OPEN WORKSTATION and the inquiries that take a type), a
 * malformed value is ignored as a whole; GKS3D_ASF sets the initial aspect source flags. */
#define _POSIX_C_SOURCE 200809L /* setenv */
#include <gks.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static Gint last_err;
static void catch_err(Gint err, Gint fn, const char *f)
{
    (void)fn;
    (void)f;
    last_err = err;
}

static void open_with(const char *types, const char *asf)
{
    gemergency_close_gks();
    if (types)
        setenv("GKS3D_WS_TYPES", types, 1);
    else
        unsetenv("GKS3D_WS_TYPES");
    if (asf)
        setenv("GKS3D_ASF", asf, 1);
    else
        unsetenv("GKS3D_ASF");
    gset_err_hand(catch_err, NULL);
    gopen_gks(NULL, 0);
    last_err = 0;
}

/* The category of type t through the inquiry, or -err. */
static int cat_of(Gint t)
{
    Gint e = -1;
    Gws_cat c = GCAT_OUT;
    ginq_ws_cat(t, &e, &c);
    return e ? -e : (int)c;
}

static void test_map(void **state)
{
    (void)state;
    open_with(" 1=100, 41 = 100,106=100,50=2,10=4,0=99", NULL);
    assert_int_equal(cat_of(41), GCAT_OUTIN);
    assert_int_equal(cat_of(50), GCAT_MO);
    assert_int_equal(cat_of(10), GCAT_MI);
    assert_int_equal(cat_of(0), GCAT_OUT); /* 0 would be error 22 unmapped */
    assert_int_equal(cat_of(100), GCAT_OUTIN); /* our own numbers still work */
    assert_int_equal(cat_of(7), -23);
    Gdisp_space_size d;
    Gint e = -1;
    ginq_disp_space_size(106, &e, &d);
    assert_int_equal(e, 0);
    assert_int_equal(d.size_raster.size_x, 1024);
    gopen_ws(1, "legacy_env_out", 41);
    assert_int_equal(last_err, 0);
    Gint t = 0;
    char conn[64];
    ginq_ws_conn_type(1, sizeof conn, &e, conn, &t);
    assert_int_equal(e, 0);
    assert_int_equal(t, GWS_TYPE_PNG); /* the type the workstation really is */
    gopen_ws(2, "", 0);
    assert_int_equal(last_err, 0);
    gclose_ws(2);
    gclose_ws(1);
    /* A foreign number that is also ours: the map wins (RAL's 4 is not our MI). */
    open_with("4=99", NULL);
    assert_int_equal(cat_of(4), GCAT_OUT);
    /* Each OPEN GKS reads the variable again: without it, 41 is unknown. */
    open_with(NULL, NULL);
    assert_int_equal(cat_of(41), -23);
    gopen_ws(1, "legacy_env_out", 41);
    assert_int_equal(last_err, 23);
    assert_int_equal(cat_of(0), -22);
    gclose_gks();
}

static void test_malformed(void **state)
{
    (void)state;
    static const char *bad[] = {
        "41", "41=", "=100", "41=100,", ",41=100", "41=100,,1=100", "41=x", "x=100",
        "41=0", "41=-100", "41=100;1=100", "99999999999=100", "41=99999999999",
        "41=100 1=100", "41==100", "41=100=2",
        "1=1,2=1,3=1,4=1,5=1,6=1,7=1,8=1,9=1,10=1,11=1,12=1,13=1,14=1,15=1,16=1,17=1,"
        "18=1,19=1,20=1,21=1,22=1,23=1,24=1,25=1,26=1,27=1,28=1,29=1,30=1,31=1,32=1,"
        "33=1,34=1,35=1,36=1,37=1,38=1,39=1,40=1,41=1,42=1,43=1,44=1,45=1,46=1,47=1,"
        "48=1,49=1,50=1,51=1,52=1,53=1,54=1,55=1,56=1,57=1,58=1,59=1,60=1,61=1,62=1,"
        "63=1,64=1,65=100",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        open_with(bad[i], NULL);
        assert_int_equal(cat_of(41), -23); /* nothing mapped, nothing half-mapped */
        assert_int_equal(cat_of(1), -23);
        assert_int_equal(cat_of(100), GCAT_OUTIN);
    }
    /* 64 entries are the limit, and a repeated number takes the later target. */
    open_with("41=2,41=100", NULL);
    assert_int_equal(cat_of(41), GCAT_OUTIN);
    open_with("", NULL); /* empty: no map, no complaint */
    assert_int_equal(cat_of(41), -23);
    gclose_gks();
}

static void check_asfs(Gasf want)
{
    Gasfs3 a;
    Gint e = -1;
    ginq_asfs3(&e, &a);
    assert_int_equal(e, 0);
    const Gasf *f = &a.asfs.linetype;
    for (int i = 0; i < 13; i++)
        assert_int_equal(f[i], want);
    assert_int_equal(a.edge_flag, want);
    assert_int_equal(a.edgetype, want);
    assert_int_equal(a.edgewidth, want);
    assert_int_equal(a.edge_colr_ind, want);
}

static void test_asf(void **state)
{
    (void)state;
    open_with(NULL, NULL);
    check_asfs(GASF_INDIV); /* the standard's initial value */
    open_with(NULL, "BUNDLED");
    check_asfs(GASF_BUNDLED);
    open_with(NULL, "bundled");
    check_asfs(GASF_BUNDLED);
    open_with(NULL, "INDIVIDUAL");
    check_asfs(GASF_INDIV);
    open_with(NULL, "BUNDLE");
    check_asfs(GASF_INDIV); /* malformed: the default */
    open_with(NULL, "");
    check_asfs(GASF_INDIV);
    /* SET ASPECT SOURCE FLAGS still overrides the initial values. */
    open_with(NULL, "BUNDLED");
    Gasfs3 a;
    Gint e;
    ginq_asfs3(&e, &a);
    a.asfs.fill_colr_ind = GASF_INDIV;
    gset_asfs3(&a);
    ginq_asfs3(&e, &a);
    assert_int_equal(a.asfs.fill_colr_ind, GASF_INDIV);
    assert_int_equal(a.asfs.fill_int_style, GASF_BUNDLED);
    gclose_gks();
}

/* NCAR's escapes with NCAR's record (escape_r1), as c_fgke03 and c_test12 pass it. */
static void ncar_escape(Gint id, const char *rec)
{
    Gescape_in_data in;
    char buf[80];
    strncpy(buf, rec, sizeof buf);
    in.escape_r1.data = buf;
    in.escape_r1.size = strlen(rec);
    gescape(id, &in, NULL, NULL);
}

static void test_ncar_escapes(void **state)
{
    (void)state;
    open_with(NULL, NULL);
    unlink("t_meta01.png");
    unlink("t_meta02.png");
    unlink("gks.png");
    ncar_escape(GESC_NCAR_FILE_NAME, "t_meta01   "); /* blank filled, as NCAR's */
    assert_int_equal(last_err, 0);
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gactivate_ws(1);
    ncar_escape(GESC_NCAR_PAUSE, "    1");
    assert_int_equal(last_err, 0);
    ncar_escape(GESC_NCAR_PAUSE, "    2"); /* not open */
    assert_int_equal(last_err, 182);
    last_err = 0;
    ncar_escape(GESC_NCAR_PAUSE, "1x");
    assert_int_equal(last_err, 182);
    last_err = 0;
    ncar_escape(GESC_NCAR_FILE_NAME, "   ");
    assert_int_equal(last_err, 182);
    last_err = 0;
    gdeactivate_ws(1);
    gclose_ws(1);
    assert_int_equal(access("t_meta01.png", F_OK), 0);
    ncar_escape(GESC_NCAR_FILE_NAME, "t_meta02");
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gclose_ws(1);
    /* the name is used up: the next workstation gets its own default again */
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gclose_ws(1);
    assert_int_equal(last_err, 0);
    assert_int_equal(access("t_meta02.png", F_OK), 0);
    assert_int_equal(access("gks.png", F_OK), 0);
    /* a name left at CLOSE GKS is dropped at the next OPEN GKS */
    ncar_escape(GESC_NCAR_FILE_NAME, "t_meta03");
    gclose_gks();
    open_with(NULL, NULL);
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gclose_ws(1);
    assert_int_equal(access("t_meta03.png", F_OK), -1);
    gclose_gks();
    unlink("t_meta01.png");
    unlink("t_meta02.png");
    unlink("gks.png");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_map),
        cmocka_unit_test(test_malformed),
        cmocka_unit_test(test_asf),
        cmocka_unit_test(test_ncar_escapes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
