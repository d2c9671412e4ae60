/* SPDX-License-Identifier: MIT */
/*
 * gks_par.h -- the processes of a run under mpirun (docs/MPI.md). libgks3d does not link
 * libmpi. When the program was started by a launcher with more than one process, the MPI
 * module libgks3d-mpi.so (gks_mpi_module.h) is loaded and initialises MPI unless the program
 * has (then MPI_Init_thread with MPI_THREAD_SERIALIZED, finalised at exit unless a rank was
 * lost); a program's own MPI is used as it is and never finalised here. In a single process
 * rank 0 of 1 and nothing of MPI is loaded. Under a launcher without the module (not built,
 * not installed) one line on stderr says why; rank and size then come from the launcher's
 * environment, so rank 0 alone traces and writes the pictures.
 */
#ifndef GKS_PAR_H
#define GKS_PAR_H
#include "gks_private.h"
#include "gks_mpi_module.h"

/* This process's rank and the number of processes. Before MPI is started (and without the
 * module) they come from the launcher's environment (OMPI_COMM_WORLD_RANK / _SIZE,
 * PMI_RANK / PMI_SIZE, MV2_COMM_WORLD_RANK / _SIZE); outside a launcher 0 and 1. */
int gks_par_rank(void);
int gks_par_size(void);
/* Default of the animation mode (whole frames to ranks): GKS3D_MPI_FRAMES=1. */
int gks_par_frames_default(void);

/* The MPI module, loaded at the first call if the launcher's environment asks for it (see
 * above); NULL in a single process or when it cannot be loaded. */
const gks_mpi_module *gks_par_module(void);
/* Starts MPI if needed (see above; called by OPEN GKS, so every rank initialises MPI before
 * anything can fail on one rank alone); 1 if this process is one of several ranks of
 * MPI_COMM_WORLD, else 0 (always 0 without the module). *serialized (may be NULL): 1 if
 * several threads may make MPI calls one at a time (otherwise trace with one thread). */
int gks_par_start(int *serialized);
/* A rank was lost: MPI_Finalize would wait for it, so it is skipped at exit (mpirun then
 * reports that this process ended without MPI_Finalize, and ends the run). */
void gks_par_lost(void);
/* path for this rank's copy of a file written by every rank: name itself on rank 0 (and in
 * a single process), name.R on rank R; NULL if out of memory (free with gks_free). */
char *gks_par_rank_path(const char *name);
#endif
