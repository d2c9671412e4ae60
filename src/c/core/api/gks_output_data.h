/* SPDX-License-Identifier: MIT */
/*
 * gks_output_data.h -- the pipeline of the primitives with data (gks_output_data.c) as the
 * rest of the output pipeline uses it: drawing a stored one, inserting one into the open
 * segment.
 */
#ifndef GKS_OUTPUT_DATA_H
#define GKS_OUTPUT_DATA_H
#include "gks_private.h"
#include "gks_area_data.h"
#include "gks_output_int.h"

/* Draws d mapped by nc on the target's workstations; is_set: edges apply. 0 or an error. */
int gks_area_data_emit(const norm_ctx *nc, const gks_area_data *d, int is_set, target *t);
/* A stored primitive with data (kind GKS_SEG_AREA_DATA) drawn through nc (the segment
 * transformation and the clipping volume) on t. 0 or an error. */
int gks_area_data_emit_stored(const norm_ctx *nc, const gks_seg_prim *sp, target *t);
/* INSERT SEGMENT: the stored sp mapped by M into the open segment, with the clipping
 * volume of cur. 0, 300 or 301. */
int gks_area_data_insert(gks_segment *open, const double M[3][4], const norm_ctx *cur,
                         const gks_seg_prim *sp);
#endif
