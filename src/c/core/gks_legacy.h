/* SPDX-License-Identifier: MIT */
/*
 * gks_legacy.h -- the configuration switches for unchanged legacy programs (README,
 * "Legacy programs"): GKS3D_WS_TYPES maps foreign workstation type numbers to ours,
 * GKS3D_ASF sets the initial aspect source flags. Both are read at OPEN GKS.
 * Also NCAR GKS's escapes -1391 (file name of the next workstation) and -1396 (pause).
 */
#ifndef GKS_LEGACY_H
#define GKS_LEGACY_H
#include "gks.h"

/* Read GKS3D_WS_TYPES and GKS3D_ASF (OPEN GKS). A malformed value is ignored as a whole
 * and reported once on stderr; the previous OPEN GKS's settings are dropped. */
void gks_legacy_load(void);

/* The workstation type ws_type names after GKS3D_WS_TYPES (one step; unmapped numbers
 * unchanged). */
int gks_ws_type_map(int ws_type);

/* The initial value of every aspect source flag (GKS3D_ASF; default INDIVIDUAL). */
Gasf gks_legacy_asf(void);

/* ESCAPE GESC_NCAR_FILE_NAME / GESC_NCAR_PAUSE (gks.h) with NCAR's record in
 * in->escape_r1: 0, or the error to report (182: record empty, absent or, for the
 * pause, not a number; 300). The name is kept until the next OPEN WORKSTATION of a file
 * workstation (or OPEN GKS). For the pause, *pause_ws_id = the workstation identifier
 * the record names (the caller looks it up, 182 if it is not open, and updates it), else
 * -1. */
int gks_legacy_escape(Gint func_id, const Gescape_in_data *in, int *pause_ws_id);

/* At OPEN WORKSTATION: the name a GESC_NCAR_FILE_NAME escape left, for a workstation that
 * writes a file (writes_file != 0), else NULL. The caller owns (gks_free) the string,
 * and the name is then used up. */
char *gks_legacy_take_file_name(int writes_file);

/* The registered profile (gks_binding.h gks_set_profile), or NULL: ISO GKS. */
struct gks_profile;
const struct gks_profile *gks_legacy_profile(void);

#endif
