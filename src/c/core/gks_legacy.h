/* SPDX-License-Identifier: MIT */
/*
 * gks_legacy.h -- the configuration switches for unchanged legacy programs (README,
 * "Legacy programs"): GKS3D_WS_TYPES maps foreign workstation type numbers to ours,
 * GKS3D_ASF sets the initial aspect source flags. Both are read at OPEN GKS.
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

#endif
