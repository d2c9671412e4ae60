/* SPDX-License-Identifier: MIT */
/*
 * ncarg/ncargC.h -- the one routine of NCAR's utility libraries that NCAR's plain GKS
 * examples call: c_frame (Fortran FRAME), the end of a picture. frame.c implements it.
 */
#ifndef GKS3D_NCARG_NCARGC_H
#define GKS3D_NCARG_NCARGC_H
#include "ncarg/gks.h"

/* NCAR's FRAME: UPDATE WORKSTATION (PERFORM) then CLEAR WORKSTATION (ALWAYS) on every
 * active workstation of category OUTPUT, OUTIN or MO. */
void c_frame(void);
#endif
