/* SPDX-License-Identifier: MIT */
/*
 * rt_mpi.h -- the tiles of one rt_render frame shared by the ranks of an MPI communicator
 * (MPI build only; docs/MPI.md). Every rank renders the same scene with the same camera and
 * options and passes rt_mpi_hook's hook in rt_render_options.tiles:
 *   rank 0 hands out tiles on demand (guided chunks, so a slow glass tile does not hold up a
 *   fast rank), traces tiles itself, stores the other ranks' tiles and alone has the whole
 *   frame when rt_render returns; the other ranks trace what they are given, send it and
 *   return a frame that is not assembled (their rgb is unspecified).
 * The picture is the one-process picture bit for bit (tile payloads do not depend on who
 * traced them; the frame is resolved once, on rank 0).
 * Faults never hang: a rank that sends nothing for `timeout` seconds while it owes tiles, or
 * that does not take part in a frame at all, is declared lost (rank 0 traces its tiles, the
 * picture is still complete) and the job reports the fault (rt_mpi_job_fault); a rank
 * waiting that long for rank 0 fails its rt_render with RT_ERR_HOOK.
 * Needs MPI_THREAD_SERIALIZED for more than one thread per rank (the hook's callbacks are
 * serialised by rt_render); below that, use threads = 1.
 */
#ifndef GKS3D_RT_MPI_H
#define GKS3D_RT_MPI_H
#include "gksrt.h"
#include <mpi.h>

#define RT_MPI_MAX_RANKS 4096
/* Tags of the link's messages (RT_MPI_TAG .. RT_MPI_TAG + 2), within the guaranteed
 * MPI_TAG_UB of 32767: a program that shares the communicator must not receive them. */
#define RT_MPI_TAG 32101

/* What lives from frame to frame: the communicator (used as given, not duplicated: a
 * duplicate is a collective call that would hang if one rank never makes it), the frame sequence number (all ranks count the same frames), the ranks
 * found lost, and a request that arrived for a frame rank 0 has not started yet. */
typedef struct rt_mpi_link {
    MPI_Comm comm;
    int rank, size;
    double timeout;          /* seconds without a message before a rank counts as lost */
    unsigned seq;
    unsigned char *lost;     /* [size] */
    int *early_seq, *early_want; /* [size], rank 0: a REQ for frame seq + 1 */
} rt_mpi_link;

/* Sets up l over comm (no MPI call but its rank and size). Returns 0, or -1 (size beyond
 * RT_MPI_MAX_RANKS, no memory). */
int rt_mpi_link_init(rt_mpi_link *l, MPI_Comm comm, double timeout);
void rt_mpi_link_free(rt_mpi_link *l);

/* One frame (one rt_render call). Fields are private to rt_mpi.c. */
typedef struct rt_mpi_job {
    rt_mpi_link *l;
    rt_tile_hook hook;
    int threads;             /* this rank's tracing threads (the chunk it asks for) */
    rt_frame *frame;
    int ntiles;
    size_t max_bytes;
    unsigned seq;
    /* rank 0 */
    unsigned char *state;    /* per tile: 0 free, 1 granted to a rank, 2 traced here, 3 done */
    int *owner;              /* rank a granted tile went to */
    int *out;                /* per rank: tiles granted and not yet back */
    double *heard;           /* per rank: time of its last message */
    unsigned char *joined;   /* per rank: took part in this frame */
    unsigned char *finished; /* per rank: was told that no tile is left */
    int free_from, complete;
    unsigned char *buf;      /* one incoming tile message */
    /* other ranks */
    int queue[64], qh, qn;
    int asked, ended;
    MPI_Request send_req[32];
    unsigned char *send_buf[32];
    int nsend;
    /* both */
    int fault;               /* a rank was lost or timed out in this frame */
    char msg[256];           /* what happened (one line) */
    long sent_bytes, recv_bytes, tiles_here;
    double serve_seconds;    /* rank 0: receiving and storing tiles, answering requests */
    double wait_seconds;     /* waiting (rank 0: for the last remote tiles or ranks; other
                                ranks: for a grant, for their sends) */
} rt_mpi_job;

/* Prepares j for one frame on link l and returns the hook for rt_render_options.tiles
 * (NULL: no memory). threads: this rank's tracing threads. */
const rt_tile_hook *rt_mpi_job_start(rt_mpi_job *j, rt_mpi_link *l, int threads);
/* After rt_render: frees j; returns 1 and the message in j->msg if a fault happened. */
int rt_mpi_job_finish(rt_mpi_job *j);
#endif
