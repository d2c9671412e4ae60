/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_clip.h -- the clipping stage of the output pipeline: polylines into pieces
 * (the polyline strokes of TEXT too), areas by the region of gks_xform_clip, both in NDC3
 * at the clipping volume of a gks_pipe_norm.
 */
#ifndef GKS_PIPE_CLIP_H
#define GKS_PIPE_CLIP_H
#include "gks_private.h"
#include "gks_pipe_norm.h"
#include <stddef.h>

/* Clipped polyline pieces, the points of piece k at pts + sum(len[0..k-1]). */
typedef struct gks_pipe_pieces {
    Gpoint3 *pts;
    size_t n, cap;
    int *len;                  /* points of each piece */
    size_t np, capp;
} gks_pipe_pieces;

void gks_pipe_pieces_free(gks_pipe_pieces *b);
/* A new piece, or one more point h (NDC3) on the last one: 0 or 300. */
int gks_pipe_piece_new(gks_pipe_pieces *b);
int gks_pipe_piece_push(gks_pipe_pieces *b, const double h[4]);

/* The polyline s[0..n-1] mapped by nc and clipped at its volume, appended to b as pieces
 * of >= 2 points. A segment touching a non-finite point is dropped (the polyline is
 * broken there). 0 or 300. */
int gks_pipe_clip_polyline(const gks_pipe_norm *nc, const gks_pipe_src *s, size_t n,
                           gks_pipe_pieces *b);

/* A clipped area: nl loops of counts[k] >= 3 points, m points in all (NDC3). */
typedef struct gks_pipe_loops {
    Gpoint3 *pts;
    int *counts;
    int nl, m;
} gks_pipe_loops;

/* The area (nloops loops, cnt[k] points each, n in all, NDC3) clipped by nc's region
 * (Sutherland-Hodgman per loop, loops with fewer than 3 points dropped) into *out, which
 * the caller frees (gks_pipe_loops_free); out->nl 0: nothing left. 0 or 300. */
int gks_pipe_clip_area(const gks_pipe_norm *nc, size_t nloops, const size_t *cnt, size_t n,
                       const Gpoint3 *pts, gks_pipe_loops *out);
void gks_pipe_loops_free(gks_pipe_loops *a);
#endif
