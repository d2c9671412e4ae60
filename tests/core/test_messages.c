/* SPDX-License-Identifier: MIT */
/* test_messages.c -- messages a user can act on (issue 37 item 5): an error about a file
 * names the file and the system's reason, in the error file and through
 * gks_error_detail() while the handler runs; a missing X display says so; no message text
 * carries an internal note. The handler's arguments are the standard's, unchanged. */
#include <gks.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

static Gint got_err, got_fn;
static char got_file[256], got_detail[600];
static void catch_err(Gint err, Gint fn, const char *f)
{
    got_err = err;
    got_fn = fn;
    snprintf(got_file, sizeof got_file, "%s", f ? f : "");
    snprintf(got_detail, sizeof got_detail, "%s", gks_error_detail());
    gerr_log(err, fn, f); /* the default logging, into the error file */
}

static char *slurp(const char *path)
{
    static char buf[8192];
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    if (f)
        fclose(f);
    buf[n] = '\0';
    return buf;
}

static void open_with_log(const char *log)
{
    gemergency_close_gks();
    remove(log);
    gset_err_hand(catch_err, NULL);
    gopen_gks(log, 0);
    got_err = 0;
    got_detail[0] = '\0';
}

/* The function identification of OPEN WORKSTATION (RAL GKSE_PAR: EOPWK = 2). */
#define FN_OPWK 2

static void test_missing_folder_named_with_reason(void **state)
{
    (void)state;
    open_with_log("messages_1.log");
    gopen_ws(1, "no_such_folder/x.png", GWS_TYPE_PNG);
    assert_int_equal(got_err, 26);
    assert_int_equal(got_fn, FN_OPWK);
    assert_string_equal(got_file, "messages_1.log");
    assert_string_equal(got_detail,
                        "cannot open \"no_such_folder/x.png\": No such file or directory");
    gclose_gks();
    const char *log = slurp("messages_1.log");
    assert_non_null(strstr(log, "GKS ERROR 26 in OPEN WORKSTATION: Specified workstation cannot "
                                "be opened: cannot open \"no_such_folder/x.png\": No such file "
                                "or directory\n"));
}

static void test_detail_belongs_to_its_error(void **state)
{
    (void)state;
    open_with_log("messages_2.log");
    gopen_ws(1, "no_such_folder/y.gksm", GWS_TYPE_MO);
    assert_int_equal(got_err, 26);
    assert_string_equal(got_detail,
                        "cannot open \"no_such_folder/y.gksm\": No such file or directory");
    gopen_ws(-1, "z.png", GWS_TYPE_PNG); /* error 20: nothing about a file */
    assert_int_equal(got_err, 20);
    assert_string_equal(got_detail, "");
    gclose_gks();
    const char *log = slurp("messages_2.log");
    assert_non_null(strstr(log, "GKS ERROR 20 in OPEN WORKSTATION: Specified workstation "
                                "identifier is invalid\n"));
    /* outside a handler ERROR LOGGING writes no detail */
    assert_null(strstr(log, "identifier is invalid:"));
}

static void test_unreadable_metafile_and_folder_as_file(void **state)
{
    (void)state;
    open_with_log("messages_3.log");
    gopen_ws(1, "no_such_input.gksm", GWS_TYPE_MI);
    assert_int_equal(got_err, 26);
    assert_string_equal(got_detail, "cannot open \"no_such_input.gksm\": No such file or directory");
    gopen_ws(1, ".", GWS_TYPE_MI); /* a folder */
    assert_int_equal(got_err, 26);
    assert_string_equal(got_detail, "cannot open \".\": Is a directory");
    FILE *f = fopen("not_a_metafile.gksm", "w");
    assert_non_null(f);
    fputs("hello\n", f);
    fclose(f);
    gopen_ws(1, "not_a_metafile.gksm", GWS_TYPE_MI);
    assert_int_equal(got_err, 26);
    assert_non_null(strstr(got_detail, "\"not_a_metafile.gksm\" is not a GKS metafile"));
    gclose_gks();
}

static void test_error_file_itself(void **state)
{
    (void)state;
    gemergency_close_gks();
    gset_err_hand(catch_err, NULL);
    got_detail[0] = '\0';
    gopen_gks("no_such_folder/errors.log", 0);
    assert_int_equal(got_err, 200);
    assert_string_equal(got_detail, "cannot open error file \"no_such_folder/errors.log\": "
                                    "No such file or directory");
}

static void test_missing_display_says_so(void **state)
{
    (void)state;
    open_with_log("messages_4.log");
    unsetenv("DISPLAY");
    gopen_ws(1, "", GWS_TYPE_X11);
    if (got_err == 23) { /* a build without X11 */
        gclose_gks();
        skip();
    }
    assert_int_equal(got_err, 26);
    assert_non_null(strstr(got_detail, "no X display: DISPLAY is not set"));
    gopen_ws(1, ":99999", GWS_TYPE_X11); /* no such display: no server listens */
    assert_int_equal(got_err, 26);
    assert_string_equal(got_detail, "cannot open X display \":99999\"");
    gclose_gks();
}

static void test_no_internal_notes_in_messages(void **state)
{
    (void)state;
    int n = 0;
    for (Gint e = 1; e <= 3000; e++) {
        const char *m = gks_error_message(e);
        if (!*m)
            continue;
        n++;
        if (strstr(m, "PHIGS") || strstr(m, "docs/") || strstr(m, "issue "))
            fail_msg("message of error %d carries an internal note: %s", (int)e, m);
    }
    assert_true(n > 100);
    assert_string_equal(gks_error_message(511), "HLHSR mode is not available on this workstation");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_missing_folder_named_with_reason),
        cmocka_unit_test(test_detail_belongs_to_its_error),
        cmocka_unit_test(test_unreadable_metafile_and_folder_as_file),
        cmocka_unit_test(test_error_file_itself),
        cmocka_unit_test(test_missing_display_says_so),
        cmocka_unit_test(test_no_internal_notes_in_messages),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
