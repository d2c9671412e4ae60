/* SPDX-License-Identifier: MIT */
/*
 * ws_mpi.h -- how the PNG workstation shares its work among the ranks of an MPI run
 * (docs/MPI.md). Two modes, chosen per workstation (ESCAPE GESC_RT_MPI_FRAMES, default from
 * GKS3D_MPI_FRAMES):
 *   tiles  (0): every rank traces tiles of every ray-traced frame; rank 0 gathers them and
 *               alone writes the files;
 *   frames (1): frame k (1-based) is traced and written whole by rank (k - 1) mod N; the
 *               other ranks neither trace nor write it.
 * In a single process (or without the MPI build) every frame is traced and written here.
 */
#ifndef WS_MPI_H
#define WS_MPI_H
#include "gks_private.h"

/* 1 if this process writes (and, in frames mode, traces) frame `frame`. */
int ws_mpi_writes(int frames_mode, int frame);
/* 1 if the ray-traced views of a frame are to be shared tile by tile (tiles mode, N > 1). */
int ws_mpi_shares_tiles(int frames_mode);

#ifdef GKS_HAVE_MPI
#include "rt_mpi.h"
/* The ranks' link, set up at the first use (starting MPI if needed); NULL in a single
 * process. *serialized: 1 if threads may call MPI one at a time. Timeout of the faults:
 * GKS3D_MPI_TIMEOUT seconds (default 60). */
rt_mpi_link *ws_mpi_link(int *serialized);
#endif
#endif
