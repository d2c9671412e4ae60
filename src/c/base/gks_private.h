/* SPDX-License-Identifier: MIT */
/*
 * gks_private.h -- guard for the library's internal headers: they are not part of the
 * installed interface and refuse to be included by applications.
 */
#ifndef GKS_PRIVATE_H
#define GKS_PRIVATE_H
#ifndef GKS3D_BUILDING
#error "internal gks3d header: applications include <gks.h> only"
#endif
#endif
