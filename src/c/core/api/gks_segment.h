/* SPDX-License-Identifier: MIT */
/*
 * gks_segment.h -- the segment functions' link to the rest of the core: workstation
 * closing and clearing. The store itself is gks_seg_store.h, the replay of stored
 * segments gks_replay.h.
 */
#ifndef GKS_SEGMENT_H
#define GKS_SEGMENT_H
#include "gks_private.h"
#include "gks_context.h"
#include "gks_seg_store.h"

/* CLOSE WORKSTATION / CLEAR WORKSTATION: the segments stored on ws_id are removed from
 * it; a segment stored on no workstation any more is deleted (the open one excepted). */
void gks_segment_ws_closed(int ws_id);
#endif
