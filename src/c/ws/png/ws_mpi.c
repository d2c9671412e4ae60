/* SPDX-License-Identifier: MIT */
/*
 * ws_mpi.c -- the PNG workstation's share of an MPI run (ws_mpi.h). The link lives as long as
 * the process (MPI itself is per process).
 */
#include "ws_mpi.h"
#include "gks_par.h"

#include <stdio.h>
#include <stdlib.h>

int ws_mpi_writes(int frames_mode, int frame)
{
    int n = gks_par_size(), r = gks_par_rank();
    if (n < 2)
        return 1;
    return frames_mode ? (frame - 1) % n == r : r == 0;
}

int ws_mpi_shares_tiles(int frames_mode)
{
#ifdef GKS_HAVE_MPI
    return !frames_mode && gks_par_size() > 1;
#else
    (void)frames_mode;
    return 0;
#endif
}

#ifdef GKS_HAVE_MPI
static rt_mpi_link link_;
static int link_state; /* 0 not tried, 1 up, -1 none */

rt_mpi_link *ws_mpi_link(int *serialized)
{
    int ser = 0;
    if (link_state == 0) {
        link_state = -1;
        if (gks_par_start(&ser)) {
            double timeout = 60.0;
            const char *t = getenv("GKS3D_MPI_TIMEOUT");
            if (t && *t) {
                char *end;
                double v = strtod(t, &end);
                if (!*end && v > 0 && v < 1e6)
                    timeout = v;
            }
            if (rt_mpi_link_init(&link_, MPI_COMM_WORLD, timeout) == 0)
                link_state = 1;
            else
                fprintf(stderr, "gks3d: MPI: cannot set up the ranks' link; tracing alone\n");
        }
    }
    gks_par_start(&ser);
    if (serialized)
        *serialized = ser;
    return link_state == 1 ? &link_ : NULL;
}
#endif
