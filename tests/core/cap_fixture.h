/* SPDX-License-Identifier: MIT */
/* cap_fixture.h -- the fixture shared by the primitive and attribute tests: GKS open with
 * one active null workstation (id 1), primitive capture on, default transformation (WC =
 * NDC unit square, clipping on); and exact error expectations. Include after cmocka.h,
 * prim_capture.h and core_util.h. */
#ifndef CAP_FIXTURE_H
#define CAP_FIXTURE_H

static int setup(void **state)
{
    (void)state;
    enter_state(GST_WSAC);
    cap_start();
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    cap_stop();
    reset_gks();
    return 0;
}

/* Exactly one error was reported: err in function fct; the capture is then emptied. */
static void expect_error(int err, int fct)
{
    if (n_captured != 1 || captured[0].err != err || captured[0].fct != fct)
        fail_msg("got %d errors, first %d (fct %d); want %d (fct %d)", n_captured,
                 n_captured ? captured[0].err : 0, n_captured ? captured[0].fct : -1, err, fct);
    n_captured = 0;
}

static void expect_no_error(void)
{
    if (n_captured)
        fail_msg("unexpected error %d (fct %d)", captured[0].err, captured[0].fct);
}
#endif
