/* SPDX-License-Identifier: MIT */
/*
 * ws_mpi.h -- how the render layer shares a file workstation's ray tracing (the PNG
 * workstation's frames and files) among the ranks of an MPI run (docs/MPI.md). Two modes,
 * chosen per workstation (ESCAPE GESC_RT_MPI_FRAMES, default from GKS3D_MPI_FRAMES):
 *   tiles  (0): every rank traces tiles of every ray-traced frame; rank 0 gathers them and
 *               alone writes the files;
 *   frames (1): frame k (1-based) is traced and written whole by rank (k - 1) mod N; the
 *               other ranks neither trace nor write it.
 * In a single process every frame is traced and written here. The tiles travel through the
 * MPI module (gks_mpi_module.h), loaded only under an MPI launcher; without it rank 0 traces
 * and writes alone (tiles mode; frames mode needs no messages).
 */
#ifndef WS_MPI_H
#define WS_MPI_H
#include "gks_private.h"
#include "gks_mpi_module.h"
#include "gksrt.h"

/* 1 if this process writes (and, in frames mode, traces) frame `frame`. */
int ws_mpi_writes(int frames_mode, int frame);
/* 1 if the ray-traced views of a frame are to be shared tile by tile (tiles mode, N > 1,
 * the MPI module loaded). */
int ws_mpi_shares_tiles(int frames_mode);

/* The ranks' link, set up at the first use (starting MPI if needed); NULL in a single
 * process or without the module. *serialized: 1 if threads may call MPI one at a time;
 * *rank: this rank. Timeout of the faults: GKS3D_MPI_TIMEOUT seconds (default 60). */
void *ws_mpi_link(int *serialized, int *rank);

/* One shared frame: the hook for rt_render_options.tiles (NULL: out of memory, trace
 * alone); *job is what ws_mpi_frame_end needs. */
const rt_tile_hook *ws_mpi_frame_start(void *link, int threads, void **job);
/* After rt_render: prints the frame's report when GKS3D_MPI_REPORT=1; returns 1 and
 * prints the message if a rank was lost (gks_par_lost is then called), else 0. */
int ws_mpi_frame_end(void *link, void *job);
#endif
