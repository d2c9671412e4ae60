/* SPDX-License-Identifier: MIT */
/*
 * ncarg/gks.h -- lets programs written for NCAR Graphics' ISO C binding compile unchanged
 * against gks3d (docs/COMPAT.md "NCAR programs"): NCAR's header is the ISO C binding, so
 * this one is gks3d's, plus the C headers NCAR's includes for its programs.
 */
#ifndef GKS3D_NCARG_GKS_H
#define GKS3D_NCARG_GKS_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gks.h>
#endif
