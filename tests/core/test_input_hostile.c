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

/* A: a 1000-point stroke on one line (about 9 KB) comes back whole, its last point right,
 * and a 2000-character string line is one line (its tail is not parsed as a line: the
 * CHOICE after it is the next value). */
static void test_long_lines(void **u)
{
    (void)u;
    size_t cap = 64 * 1024, at = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    at += (size_t)snprintf(text + at, cap - at, "stroke 1");
    for (int i = 0; i < 1000; i++)
        at += (size_t)snprintf(text + at, cap - at, " %d.0 %d.0", i + 1, i == 999 ? 900 : 100);
    at += (size_t)snprintf(text + at, cap - at, "\nstring 1 ");
    for (int i = 0; i < 2000; i++) /* the tail at 1087 reads "choice 1 7" on main */
        text[at++] = i >= 1078 && i < 1088 ? "choice 1 7"[i - 1078] : 'x';
    at += (size_t)snprintf(text + at, cap - at, "\nchoice 1 3\n");
    open_with_script(text);
    free(text);
    Gpoint p0 = { 0.5, 0.5 };
    Gstroke init = { 0, 1, &p0 };
    ginit_stroke(WS, 1, &init, 1, &earea, 1024, NULL);
    ginit_string(WS, 1, "", 1, &earea, 1024, 1, NULL);
    assert_int_equal(n_captured, 0);
    static Gpoint pts[1024];
    Gstroke s = { 0, 1024, pts };
    Gin_status st;
    greq_stroke(WS, 1, &st, &s);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(s.num_points, 1000);
    assert_float_equal(pts[999].x, 1000.0 / 1024, 1e-9);
    assert_float_equal(pts[999].y, 900.0 / 1024, 1e-9);
    static char str[1025];
    greq_string(WS, 1, &st, str);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(strlen(str), 1024); /* truncated to the buffer, as documented */
    Gint choice = 0;
    greq_choice(WS, 1, &st, &choice);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(choice, 3);
    assert_int_equal(n_captured, 0);
    close_all();
}

/* C: devices and FIFOs are refused at once (182), by ESCAPE and by GKS_INPUT_SCRIPT; a
 * REQUEST then returns NONE at once. alarm(): a hang ends the test as a failure. */
static void test_devices_refused(void **u)
{
    (void)u;
    alarm(20);
    open_with_script("");
    const char *dev[] = { "/dev/zero", "/dev/urandom", "/dev/null", "input_hostile.fifo", "." };
    unlink("input_hostile.fifo");
    assert_int_equal(mkfifo("input_hostile.fifo", 0600), 0);
    for (size_t i = 0; i < sizeof dev / sizeof dev[0]; i++) {
        n_captured = 0;
        attach(WS, dev[i]);
        if (n_captured != 1 || captured[0].err != 182)
            fail_msg("%s: %d errors (first %d), want 182", dev[i], n_captured,
                     n_captured ? captured[0].err : 0);
    }
    n_captured = 0;
    Gint choice;
    Gin_status st;
    greq_choice(WS, 1, &st, &choice); /* the script of "" stays: exhausted, NONE */
    assert_int_equal(st, GIN_STATUS_NONE);
    close_all();
    for (int k = 0; k < 2; k++) {
        setenv("GKS_INPUT_SCRIPT", k ? "/dev/zero" : "input_hostile.fifo", 1);
        reset_gks();
        gopen_gks(NULL, 0);
        gopen_ws(WS, "input_hostile_out", GWS_TYPE_PNG);
        unsetenv("GKS_INPUT_SCRIPT");
        gactivate_ws(WS);
        greq_choice(WS, 1, &st, &choice);
        assert_int_equal(st, GIN_STATUS_NONE);
        assert_int_equal(n_captured, 0);
        close_all();
    }
    unlink("input_hostile.fifo");
    alarm(0);
}

/* D: AWAIT EVENT with a timeout of 1e300 s in a child process sleeps: after 0.6 s it has
 * used less than 0.2 s of processor time (main: a busy loop, about 0.6 s). */
static void test_await_huge_timeout(void **u)
{
    (void)u;
    fflush(NULL);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        gopen_gks(NULL, 0);
        gopen_ws(WS, "input_hostile_out", GWS_TYPE_PNG);
        Gint ws, num;
        Gin_class cls;
        gawait_event(1e300, &ws, &cls, &num);
        _exit(3);
    }
    struct timespec t = { 0, 600000000 };
    nanosleep(&t, NULL);
    kill(pid, SIGKILL);
    int status;
    struct rusage ru;
    assert_int_equal(wait4(pid, &status, 0, &ru), pid);
    assert_true(WIFSIGNALED(status)); /* still waiting */
    double cpu = (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec +
                 (double)ru.ru_stime.tv_sec + 1e-6 * (double)ru.ru_stime.tv_usec;
    if (cpu >= 0.2)
        fail_msg("AWAIT EVENT(1e300) used %.3f s of processor time in 0.6 s", cpu);
    /* and an event still ends it at once */
    open_with_script("choice 1 2\n");
    gset_choice_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    Gint ws, num;
    Gin_class cls;
    gawait_event(1e300, &ws, &cls, &num);
    assert_int_equal(cls, GIN_CHOICE);
    assert_int_equal(n_captured, 0);
    close_all();
}

/* E: a line for device 5 (the workstation has 2) is skipped in EVENT and SAMPLE mode:
 * both valid events after it arrive. */
static void test_line_for_missing_device(void **u)
{
    (void)u;
    open_with_script("choice 5 2\nchoice 1 3\nvaluator 9 1\nchoice 1 4\n");
    gset_choice_mode(WS, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    int got = 0;
    for (int k = 0; k < 3; k++) {
        Gint ws, num, choice = 0;
        Gin_class cls;
        Gin_status st;
        gawait_event(0, &ws, &cls, &num);
        if (cls == GIN_NONE)
            break;
        gget_choice(&st, &choice);
        assert_int_equal(choice, 3 + got);
        got++;
    }
    assert_int_equal(got, 2);
    assert_int_equal(n_captured, 0);
    close_all();
    open_with_script("choice 5 2\nchoice 1 3\n");
    gset_choice_mode(WS, 1, GOP_SAMPLE, GSWITCH_NO_ECHO);
    Gint choice = 0;
    Gin_status st;
    gsample_choice(WS, 1, &st, &choice);
    assert_int_equal(st, GIN_STATUS_OK);
    assert_int_equal(choice, 3);
    close_all();
}

/* No storage while a stroke line is read or measured: REQUEST reports 300 and the line
 * stays, so the next REQUEST returns that stroke (main: the line was dropped as invalid
 * and the REQUEST went on to the next line). Every allocation of the REQUEST is failed
 * in turn. */
static void test_no_storage_keeps_line(void **u)
{
    (void)u;
    int saw300 = 0;
    for (long k = 1; k < 40; k++) {
        open_with_script("stroke 1 10 10 20 20 30 30 40 40 50 50\nlocator 1 512 512\n");
        static Gpoint pts[64];
        Gstroke s = { 0, 64, pts };
        Gin_status st;
        gks_alloc_fail_after(k);
        greq_stroke(WS, 1, &st, &s);
        gks_alloc_fail_after(0);
        if (n_captured) {
            assert_int_equal(captured[0].err, 300);
            assert_int_equal(st, GIN_STATUS_NONE);
            saw300++;
            n_captured = 0;
            s.num_points = 64;
            greq_stroke(WS, 1, &st, &s);
        }
        assert_int_equal(n_captured, 0);
        assert_int_equal(st, GIN_STATUS_OK);
        assert_int_equal(s.num_points, 5);
        assert_float_equal(pts[4].x, 50.0 / 1024, 1e-9);
        close_all();
    }
    assert_true(saw300 > 0);
}

/* ESCAPE -130 for a workstation that is not open: 25 (main: 182). */
static void test_escape_ws_not_open(void **u)
{
    (void)u;
    open_with_script("");
    attach(7, "input_hostile.txt");
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 25);
    close_all();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_get_string_after_shrink),
        cmocka_unit_test(test_long_lines),
        cmocka_unit_test(test_devices_refused),
        cmocka_unit_test(test_await_huge_timeout),
        cmocka_unit_test(test_line_for_missing_device),
        cmocka_unit_test(test_no_storage_keeps_line),
        cmocka_unit_test(test_escape_ws_not_open),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
