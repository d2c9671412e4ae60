/* SPDX-License-Identifier: MIT */
/* gks_version.c -- gks3d_version(): the version this library was built as (see gks.h). */
#include "gks.h"

GKS_API int gks3d_version(int *major, int *minor, int *patch)
{
    if (major)
        *major = GKS3D_VERSION_MAJOR;
    if (minor)
        *minor = GKS3D_VERSION_MINOR;
    if (patch)
        *patch = GKS3D_VERSION_PATCH;
    return GKS3D_VERSION;
}
