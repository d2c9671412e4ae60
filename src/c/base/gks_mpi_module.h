/* SPDX-License-Identifier: MIT */
/*
 * gks_mpi_module.h -- the interface between libgks3d and its MPI module libgks3d-mpi.so
 * (src/mpi, docs/MPI.md). libgks3d does not link libmpi: the module does, and libgks3d
 * loads it (dlopen, gks_par.c) only when the program was started by an MPI launcher as one
 * of several processes. No MPI type crosses this interface, so libgks3d compiles without
 * mpi.h. The module exports one function, GKS_MPI_MODULE_ENTRY, which returns its table;
 * libgks3d refuses a table whose abi differs from GKS_MPI_MODULE_ABI (a module of another
 * release). The tracer's types are only passed through (pointers).
 */
#ifndef GKS_MPI_MODULE_H
#define GKS_MPI_MODULE_H
#include <stddef.h>

#define GKS_MPI_MODULE_ABI 1
#define GKS_MPI_MODULE_ENTRY "gks3d_mpi_module"
#define GKS_MPI_MODULE_NAME "libgks3d-mpi.so"

struct rt_frame;     /* src/rt/gksrt.h */
struct rt_tile_hook; /* src/rt/gksrt.h */

/* What a frame moved, for GKS3D_MPI_REPORT=1. */
typedef struct gks_mpi_stats {
    unsigned seq;         /* the frame's sequence number (all ranks count alike) */
    long tiles_here;      /* tiles traced on this rank */
    int ntiles;           /* tiles of the frame */
    long sent_bytes, recv_bytes;
} gks_mpi_stats;

/* The tracer's rt_frame_store (the module stores the tiles it receives with it; it lives
 * in libgks3d, whose internal names the module cannot see). */
typedef int (*gks_mpi_store_fn)(struct rt_frame *f, int tile, const void *payload, size_t bytes);

typedef struct gks_mpi_module {
    int abi; /* GKS_MPI_MODULE_ABI */
    /* Starts MPI if the program has not (MPI_Init_thread, MPI_THREAD_SERIALIZED, finalised
     * at exit unless a rank was lost); 1 if MPI_COMM_WORLD has several ranks. *serialized
     * (may be NULL): 1 if threads may call MPI one at a time. Repeated calls are cheap. */
    int (*start)(int *serialized);
    /* Rank and size of MPI_COMM_WORLD while MPI is up; -1 before start or after the end. */
    int (*rank)(void);
    int (*size)(void);
    /* A rank was lost: skip MPI_Finalize at exit (it would wait for the lost rank). */
    void (*lost)(void);
    /* The ranks' link over MPI_COMM_WORLD (once per process; MPI started); NULL: none.
     * timeout: seconds of silence before a rank counts as lost. */
    void *(*link)(double timeout, gks_mpi_store_fn store);
    int (*link_rank)(const void *link);
    /* One frame: *job receives the frame's state; returns the hook for
     * rt_render_options.tiles, NULL if out of memory (then *job is NULL). */
    const struct rt_tile_hook *(*job_start)(void *link, int threads, void **job);
    /* After rt_render: fills *st (may be NULL), frees the job; returns 1 and a one-line
     * message in msg if a rank was lost or timed out in this frame, else 0. */
    int (*job_finish)(void *job, gks_mpi_stats *st, char *msg, size_t msg_size);
} gks_mpi_module;

typedef const gks_mpi_module *(*gks_mpi_module_entry)(void);
#endif
