/* SPDX-License-Identifier: MIT */
/*
 * gks_par.c -- MPI start and end for the library (gks_par.h). The state is per process by
 * nature (MPI is initialised once per process), so it lives in this file alone.
 */
#include "gks_par.h"
#ifdef GKS_HAVE_MPI
#include <mpi.h>
#endif

#include "gks_alloc.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int gks_par_frames_default(void)
{
    const char *v = getenv("GKS3D_MPI_FRAMES");
    return v && strcmp(v, "1") == 0;
}

char *gks_par_rank_path(const char *name)
{
    int r = gks_par_rank();
    if (r == 0)
        return gks_strdup(name);
    size_t n = strlen(name) + 16;
    char *p = gks_alloc_array(n, 1);
    if (p)
        snprintf(p, n, "%s.%d", name, r);
    return p;
}

#ifndef GKS_HAVE_MPI
int gks_par_rank(void) { return 0; }
int gks_par_size(void) { return 1; }
int gks_par_start(int *serialized)
{
    if (serialized)
        *serialized = 0;
    return 0;
}
void gks_par_lost(void) {}
#else
/* a launcher's environment variable as a non-negative number, -1 if absent or bad */
static int env_int(const char *a, const char *b)
{
    const char *v = getenv(a);
    if (!v)
        v = getenv(b);
    if (!v || !*v)
        return -1;
    char *end;
    long n = strtol(v, &end, 10);
    return *end || n < 0 || n > 1 << 24 ? -1 : (int)n;
}

static struct {
    int tried;     /* gks_par_start ran once */
    int ours;      /* we initialised MPI (and finalise it) */
    int lost;      /* a rank was lost: no MPI_Finalize */
    int serialized;
    int ok;        /* several ranks */
} par;

static void par_end(void)
{
    int fin = 0;
    MPI_Finalized(&fin);
    if (!fin && !par.lost)
        MPI_Finalize();
}

int gks_par_rank(void)
{
    int init = 0, fin = 0, r = 0;
    MPI_Initialized(&init);
    MPI_Finalized(&fin);
    if (init && !fin && MPI_Comm_rank(MPI_COMM_WORLD, &r) == MPI_SUCCESS)
        return r;
    r = env_int("OMPI_COMM_WORLD_RANK", "PMI_RANK");
    return r > 0 && gks_par_size() > 1 ? r : 0;
}

int gks_par_size(void)
{
    int init = 0, fin = 0, n = 1;
    MPI_Initialized(&init);
    MPI_Finalized(&fin);
    if (init && !fin && MPI_Comm_size(MPI_COMM_WORLD, &n) == MPI_SUCCESS)
        return n;
    n = env_int("OMPI_COMM_WORLD_SIZE", "PMI_SIZE");
    return n > 1 ? n : 1;
}

int gks_par_start(int *serialized)
{
    if (!par.tried) {
        par.tried = 1;
        int init = 0, fin = 0, level = MPI_THREAD_SINGLE;
        MPI_Initialized(&init);
        MPI_Finalized(&fin);
        if (fin)
            return 0;
        if (!init) {
            if (gks_par_size() < 2)
                return 0; /* not launched as several processes: no MPI at all */
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

void gks_par_lost(void) { par.lost = 1; }
#endif
