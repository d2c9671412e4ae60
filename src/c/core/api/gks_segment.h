/* SPDX-License-Identifier: MIT */
/*
 * gks_segment.h -- the segment functions' links to the rest of the core: workstation
 * closing/clearing and regeneration. The store itself is gks_seg_store.h.
 */
#ifndef GKS_SEGMENT_H
#define GKS_SEGMENT_H
#include "gks_private.h"
#include "gks_context.h"
#include "gks_seg_store.h"

/* CLOSE WORKSTATION / CLEAR WORKSTATION: the segments stored on ws_id are removed from
 * it; a segment stored on no workstation any more is deleted (the open one excepted). */
void gks_segment_ws_closed(int ws_id);

/* Regeneration of ws: a pending workstation transformation applied, the display surface
 * cleared (the picture being replaced is not written) and every visible segment stored
 * on ws redrawn in priority order. Returns 0 or a GKS error number. */
int gks_ws_regenerate(gks_ws *ws);

/* Redraws the visible segments stored on ws (priority order, each through its segment
 * transformation and its primitives' clipping volumes) onto the current frame. Defined by
 * the output pipeline (gks_output.c). Returns 0 or a GKS error number. */
int gks_output_redraw_segments(gks_ws *ws);
/* Draws segment seg's primitives (through its transformation and their clipping volumes)
 * onto ws's current frame, whatever its visibility (COPY SEGMENT TO WORKSTATION,
 * ASSOCIATE). Returns 0 or a GKS error number. */
int gks_output_draw_segment(gks_ws *ws, const gks_segment *seg);

/* INSERT SEGMENT: seg's primitives, mapped by its segment transformation and then by ins,
 * enter the output stream as new primitives: stored into the open segment (if any) with
 * the current clipping volume, and drawn on the active workstations. Returns 0 or a GKS
 * error number. */
int gks_output_insert_segment(const gks_segment *seg, const double ins[3][4]);
#endif
