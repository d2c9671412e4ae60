/* SPDX-License-Identifier: MIT */
/*
 * ws_mpi.c -- the PNG workstation's share of an MPI run (ws_mpi.h), through the MPI module
 * (gks_mpi_module.h). The link lives as long as the process (MPI itself is per process).
 */
#include "ws_mpi.h"
#include "gks_par.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int ws_mpi_writes(int frames_mode, int frame)
{
    int n = gks_par_size(), r = gks_par_rank();
    if (n < 2)
        return 1;
    return frames_mode ? (frame - 1) % n == r : r == 0;
}

int ws_mpi_shares_tiles(int frames_mode)
{
    return !frames_mode && gks_par_module() && gks_par_size() > 1;
}

void *ws_mpi_link(int *serialized, int *rank)
{
    static int reported;
    const gks_mpi_module *m = gks_par_module();
    int ser = 0;
    void *l = NULL;
    if (m && m->start(&ser)) {
        double timeout = 60.0;
        const char *t = getenv("GKS3D_MPI_TIMEOUT");
        if (t && *t) {
            char *end;
            double v = strtod(t, &end);
            if (!*end && v > 0 && v < 1e6)
                timeout = v;
        }
        l = m->link(timeout, rt_frame_store);
        if (!l && !reported) {
            reported = 1;
            fprintf(stderr, "gks3d: MPI: cannot set up the ranks' link; tracing alone\n");
        }
    }
    if (serialized)
        *serialized = ser;
    if (rank)
        *rank = l ? m->link_rank(l) : 0;
    return l;
}

const rt_tile_hook *ws_mpi_frame_start(void *link, int threads, void **job)
{
    *job = NULL;
    const gks_mpi_module *m = gks_par_module();
    return m && link ? m->job_start(link, threads, job) : NULL;
}

int ws_mpi_frame_end(void *link, void *job)
{
    const gks_mpi_module *m = gks_par_module();
    if (!m || !link || !job)
        return 0;
    gks_mpi_stats st;
    char msg[256] = "";
    int fault = m->job_finish(job, &st, msg, sizeof msg);
    int rank = m->link_rank(link), size = gks_par_size();
    const char *rep = getenv("GKS3D_MPI_REPORT");
    if (rep && strcmp(rep, "1") == 0)
        fprintf(stderr, "gks3d: MPI rank %d of %d: frame %u: %ld of %d tiles traced here, "
                "%ld bytes sent, %ld received\n", rank, size, st.seq, st.tiles_here,
                st.ntiles, st.sent_bytes, st.recv_bytes);
    if (fault) {
        /* a lost rank: on rank 0 the picture is still complete (its tiles were traced
           here); the caller reports the error after the frame is written */
        fprintf(stderr, "gks3d: MPI rank %d: %s\n", rank, msg);
        gks_par_lost();
    }
    return fault;
}
