/* SPDX-License-Identifier: MIT */
/*
 * gks_record.h -- GKS3D_RECORD=FILE.gksm (README, "Recording"): OPEN GKS opens a metafile
 * output workstation of its own, the recorder, outside the set of open workstations (no
 * inquiry, no workstation identifier, no limit of the program's sees it). It is active
 * while any output workstation of the program (category OUTPUT or OUTIN) is active, so it
 * receives every item an active MO receives; the functions addressed to one workstation of
 * the program, the mirrored one (the first output workstation open), are recorded on it
 * too (representations, view, HLHSR mode, workstation transformation, CLEAR, UPDATE and
 * the picture escapes), and when the mirrored workstation closes after drawing, a CLEAR
 * WORKSTATION item ends its frame. CLOSE GKS closes the file (a program that exits without
 * CLOSE GKS: at exit, atexit(3)).
 */
#ifndef GKS_RECORD_H
#define GKS_RECORD_H
#include "gks_context.h"


/* OPEN GKS: open the recorder if GKS3D_RECORD names a file (a failure: one line on stderr,
 * GKS opens without it). */
void gks_record_open(void);
/* CLOSE GKS / EMERGENCY CLOSE GKS: the recorder's END item and file closed (a failed
 * write: one line on stderr). While recording, a failed write of an item is reported to
 * the function that wrote it like any MO's (303). */
void gks_record_close(void);
/* After OPEN, CLOSE, ACTIVATE and DEACTIVATE WORKSTATION of the program (closing: ws_id
 * the workstation just closed, else -1): the recorder's state and the mirrored one. */
void gks_record_sync(int closed_ws_id);
/* ESCAPE func_id (done by the driver of ws_id): recorded on the recorder too when ws_id is
 * the mirrored workstation and the escape sets the picture (samples, depth, cut-off,
 * secondary rays, SPD, anti-aliasing, PNG compression, vector resolution), never file
 * names, threads or progress. */
void gks_record_escape(int ws_id, int func_id, const Gescape_in_data *in);
#endif
