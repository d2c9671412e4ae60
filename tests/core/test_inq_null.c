/* SPDX-License-Identifier: MIT */
/*
 * test_inq_null.c -- every inquiry function of the C binding (every ginq_* declared in
 * include/gks.h; the callers are generated from it by gen_inq_null.sh) called with each of
 * its pointer arguments NULL in turn, in every operating state: the error indicator is 2003
 * and nothing crashes (docs/ERRORS.md). With a NULL error indicator the call has nowhere to
 * answer and must return without effect; with every pointer valid (zeroed buffers, so the
 * lists inside output records have no storage) the call must not crash either.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"

typedef struct inq_case {
    const char *name;
    int (*call)(int nul); /* nul: pointer to pass NULL (0-based), -1 none, -2 the err_ind */
    int nptr;             /* pointer arguments other than the error indicator */
    int has_err;          /* 1 if the function has an error indicator */
} inq_case;

/* scratch output buffers, zeroed before every call; big enough for any output record */
static _Alignas(64) unsigned char bufs[8][1 << 16];
static Gstore store;

static void *scratch(int k)
{
    return bufs[k];
}

#include "test_inq_null_gen.c"

static void run_all(const char *state)
{
    int n = (int)(sizeof inq_cases / sizeof inq_cases[0]);
    for (int i = 0; i < n; i++) {
        const inq_case *c = &inq_cases[i];
        for (int nul = -2; nul < c->nptr; nul++) {
            if (nul == -2 && !c->has_err)
                continue;
            memset(bufs, 0, sizeof bufs);
            n_captured = 0;
            int err = c->call(nul);
            if (n_captured)
                fail_msg("%s (%s, NULL argument %d): called ERROR HANDLING (%d)", c->name,
                         state, nul, captured[0].err);
            if (nul >= 0 && c->has_err && err != 2003)
                fail_msg("%s (%s): NULL pointer argument %d gave error %d, want 2003",
                         c->name, state, nul, err);
        }
    }
}

static void test_every_inquiry_every_null(void **u)
{
    (void)u;
    reset_gks();
    run_all("GKCL");
    gopen_gks(NULL, 0);
    run_all("GKOP");
    unlink("inq_null.png");
    gopen_ws(1, "inq_null", GWS_TYPE_PNG);
    run_all("WSOP");
    gactivate_ws(1);
    gcreate_seg(1);
    run_all("SGOP");
    gclose_seg();
    run_all("WSAC");
    n_captured = 0;
    reset_gks();
    unlink("inq_null.png");
    /* the table covers every inquiry of the header: at least the 152 of 2026-12-01 */
    assert_true(sizeof inq_cases / sizeof inq_cases[0] >= 152);
}

int main(void)
{
    gcreate_store(&(Gint){ 0 }, &store);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_inquiry_every_null),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    gdel_store(store);
    return rc;
}
