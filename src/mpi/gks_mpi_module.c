/* SPDX-License-Identifier: MIT */
/*
 * gks_mpi_module.c -- libgks3d-mpi.so, the MPI module of libgks3d (gks_mpi_module.h,
 * docs/MPI.md): MPI start and end, and the tile distribution of src/rt/rt_mpi.c behind the
 * table of gks_mpi_module.h. Loaded by libgks3d (gks_par.c) only under an MPI launcher; the
 * state is per process by nature (MPI is initialised once per process). Everything but
 * the entry point is hidden (-fvisibility=hidden).
 */
#include "gks_mpi_module.h"
#include "rt_mpi.h"

#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static struct {
    int tried;     /* start ran once */
    int ours;      /* we initialised MPI (and finalise it) */
    int lost;      /* a rank was lost: no MPI_Finalize */
    int serialized;
    int ok;        /* several ranks */
} par;

static gks_mpi_store_fn host_store; /* libgks3d's rt_frame_store */

/* rt_mpi.c stores the tiles it receives with rt_frame_store, which lives in libgks3d
 * (hidden there): this module's own definition forwards to libgks3d's. */
int rt_frame_store(rt_frame *f, int tile, const void *payload, size_t bytes)
{
    return host_store ? host_store(f, tile, payload, bytes) : -1;
}

static int up(void)
{
    int init = 0, fin = 0;
    MPI_Initialized(&init);
    MPI_Finalized(&fin);
    return init && !fin;
}

static void par_end(void)
{
    int fin = 0;
    MPI_Finalized(&fin);
    if (!fin && !par.lost)
        MPI_Finalize();
}

static int mod_rank(void)
{
    int r = 0;
    return up() && MPI_Comm_rank(MPI_COMM_WORLD, &r) == MPI_SUCCESS ? r : -1;
}

static int mod_size(void)
{
    int n = 1;
    return up() && MPI_Comm_size(MPI_COMM_WORLD, &n) == MPI_SUCCESS ? n : -1;
}

static int mod_start(int *serialized)
{
    if (!par.tried) {
        par.tried = 1;
        int init = 0, fin = 0, level = MPI_THREAD_SINGLE;
        MPI_Initialized(&init);
        MPI_Finalized(&fin);
        if (fin)
            return 0;
        if (!init) {
            if (MPI_Init_thread(NULL, NULL, MPI_THREAD_SERIALIZED, &level) != MPI_SUCCESS)
                return 0;
            par.ours = 1;
            atexit(par_end);
        }
        MPI_Query_thread(&level);
        par.serialized = level >= MPI_THREAD_SERIALIZED;
        int n = 1;
        MPI_Comm_size(MPI_COMM_WORLD, &n);
        par.ok = n > 1;
    }
    if (serialized)
        *serialized = par.serialized;
    return par.ok;
}

static void mod_lost(void) { par.lost = 1; }

static rt_mpi_link link_;
static int link_state; /* 0 not tried, 1 up, -1 none */

static void *mod_link(double timeout, gks_mpi_store_fn store)
{
    if (link_state == 0) {
        link_state = -1;
        host_store = store;
        if (store && mod_start(NULL) && rt_mpi_link_init(&link_, MPI_COMM_WORLD, timeout) == 0)
            link_state = 1;
    }
    return link_state == 1 ? &link_ : NULL;
}

static int mod_link_rank(const void *l) { return ((const rt_mpi_link *)l)->rank; }

static const struct rt_tile_hook *mod_job_start(void *l, int threads, void **job)
{
    rt_mpi_job *j = calloc(1, sizeof *j);
    const rt_tile_hook *h = j ? rt_mpi_job_start(j, l, threads) : NULL;
    if (!h) {
        free(j);
        j = NULL;
    }
    *job = j;
    return h;
}

static int mod_job_finish(void *job, gks_mpi_stats *st, char *msg, size_t msg_size)
{
    rt_mpi_job *j = job;
    if (!j)
        return 0;
    if (st)
        *st = (gks_mpi_stats){ j->seq, j->tiles_here, j->ntiles, j->sent_bytes, j->recv_bytes };
    int fault = rt_mpi_job_finish(j);
    if (fault && msg && msg_size)
        snprintf(msg, msg_size, "%s", j->msg);
    free(j);
    return fault;
}

static const gks_mpi_module table = {
    GKS_MPI_MODULE_ABI, mod_start, mod_rank, mod_size, mod_lost,
    mod_link, mod_link_rank, mod_job_start, mod_job_finish,
};

/* The module's one exported name (GKS_MPI_MODULE_ENTRY). */
__attribute__((visibility("default"))) const gks_mpi_module *gks3d_mpi_module(void);
const gks_mpi_module *gks3d_mpi_module(void) { return &table; }
