/* SPDX-License-Identifier: MIT */
/*
 * ws_file.h -- file names of the file workstations (PNG, PDF, SVG, PS, EPS): the base name
 * from the connection identifier and the name of a frame's file (docs/WORKSTATIONS.md):
 *   ""/NULL -> "gks";  all digits N (a Fortran CONID) -> "gksN";  "path.EXT" -> "path";
 *   anything else is used as is. Frame 1 is B.EXT, frame k > 1 B-k.EXT (k >= 3 digits).
 */
#ifndef WS_FILE_H
#define WS_FILE_H

/* The base name for connection identifier conn and extension ext (".png"); gks_alloc'ed,
 * NULL on storage overflow. */
char *gks_ws_file_base(const char *conn, const char *ext);
/* The file of frame (>= 1) of base: gks_alloc'ed, NULL on storage overflow. */
char *gks_ws_file_frame(const char *base, int frame, const char *ext);
#endif
