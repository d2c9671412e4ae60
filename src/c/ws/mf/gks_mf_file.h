/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_file.h -- the file of a metafile workstation (MO, MI): its name for a connection
 * identifier. The file format itself is gks_mf_codec.h.
 */
#ifndef GKS_MF_FILE_H
#define GKS_MF_FILE_H
#include "gks_private.h"

/* The metafile's file name for a connection identifier: the identifier itself, or
 * "gks<digits>.gksm" when it is all digits (a Fortran integer CONID), as the PNG
 * workstation names "gks<digits>.png". NULL on storage overflow. Free with gks_free. */
char *gks_mf_file_name(const char *conn_id);
/* The drivers' file entry (ws_driver.h) of MO and MI for connection identifier conn_id:
 * 0 with the name in *path, 21 for an empty identifier, 300. */
int gks_mf_file_path(const char *conn_id, char **path);
#endif
