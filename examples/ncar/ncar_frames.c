/* SPDX-License-Identifier: MIT */
/*
 * ncar_frames.c -- a program in the style of NCAR's C examples (NCAR's headers, "stdout"
 * as error file, NULL connection identifier, c_frame between pictures), built with the
 * shim: two pictures on the PNG workstation give gks.png and gks-002.png.
 * Prints NCAR SHIM OK.
 */
#include <ncarg/gks.h>
#include <ncarg/ncargC.h>
#include <unistd.h>

int main(void)
{
    remove("gks.png");
    remove("gks-002.png");
    gopen_gks("stdout", 0);
    gopen_ws(1, NULL, GWS_TYPE_PNG);
    gactivate_ws(1);
    Gpoint p[2] = { { 0.1, 0.1 }, { 0.9, 0.9 } };
    Gpoint_list line = { 2, p };
    gpolyline(&line);
    c_frame();
    p[0].y = 0.9;
    p[1].y = 0.1;
    gpolyline(&line);
    c_frame();
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    int ok = access("gks.png", F_OK) == 0 && access("gks-002.png", F_OK) == 0 &&
             access("gks-003.png", F_OK) != 0;
    printf(ok ? "NCAR SHIM OK\n" : "NCAR SHIM FAILED\n");
    return ok ? 0 : 1;
}
