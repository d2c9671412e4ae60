/* SPDX-License-Identifier: MIT */
/*
 * mpi_frames.c -- an animation for the MPI tests (tests/mpi/run_mpi_test.sh): NFRAMES
 * ray-traced frames of a lit square turning over a floor, written as anim.png,
 * anim-002.png, ... in the current directory; GKS errors are logged to the file errors.txt
 * (rank R > 0: errors.txt.R). With MPI_TEST_NO_WS=R the process of rank R
 * (OMPI_COMM_WORLD_RANK) does not open its workstation, as if it could not, and draws
 * nothing: the other ranks must report it and still finish.
 */
#include <gks.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NFRAMES 4

static void square(double cx, double cy, double z, double r, double a)
{
    Gpoint3 p[4];
    for (int k = 0; k < 4; k++) {
        double t = a + k * 1.5707963267948966;
        p[k] = (Gpoint3){ cx + r * cos(t), cy + r * sin(t), z };
    }
    Gpoint_list3 l = { 4, p };
    gfill_area3(&l);
}

int main(void)
{
    const char *skip = getenv("MPI_TEST_NO_WS"), *rank = getenv("OMPI_COMM_WORLD_RANK");
    int no_ws = skip && rank && strcmp(skip, rank) == 0;
    gopen_gks("errors.txt", 0);
    if (!no_ws) {
        gopen_ws(1, "anim", GWS_TYPE_PNG);
        gactivate_ws(1);
        Glimit ws_vp = { 0, 160, 0, 120 }, ws_win = { 0, 1, 0, 0.75 };
        gset_ws_win(1, &ws_win);
        gset_ws_vp(1, &ws_vp);
        gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
        for (int f = 0; f < NFRAMES; f++) {
            gset_fill_colr_ind(3);
            square(0.5, 0.375, 0.2, 0.5, 0.0); /* floor */
            gset_fill_colr_ind(2);
            square(0.5, 0.375, 0.5, 0.2, 0.3 * f);
            gset_fill_colr_ind(4);
            square(0.3 + 0.1 * f, 0.3, 0.6, 0.08, -0.2 * f);
            gupd_ws(1, GFLAG_PERFORM);
            gclear_ws(1, GFLAG_ALWAYS);
        }
        gdeactivate_ws(1);
        gclose_ws(1);
    }
    gclose_gks();
    return 0;
}
