/* SPDX-License-Identifier: MIT */
/*
 * gks_binding.h -- entry points the Fortran binding needs beyond the ISO C names.
 * Exported (default visibility) but not part of the installed C interface.
 */
#ifndef GKS_BINDING_H
#define GKS_BINDING_H
#include "gks.h"

/* OPEN GKS for the Fortran binding: the error file is a Fortran unit number; no file
 * is opened by C (the Fortran GERLOG writes to the unit). The unit is passed to ERROR
 * HANDLING as its decimal text. */
GKS_API void gks_open_gks_unit(int err_unit, size_t mem_unit);

/* An error the binding itself detects (300: storage overflow while converting
 * arguments), reported through the core's one error path (gks_error_report): the error
 * state is set and the handler called like for any other error. */
GKS_API void gks_binding_error(int err_num, int fctid);

/* A profile: what a foreign GKS's programs expect beyond ISO GKS, supplied by a library
 * of its own (NCAR Graphics: bindings/ncarg, libgks3d_ncarg, docs/NCAR.md) that
 * registers it from a constructor. The core knows no profile; without one it is ISO GKS.
 * Every member may be NULL. The hooks run inside the entry point that calls them and may
 * call the public API (the state is then consistent). */
typedef struct gks_profile {
    /* After OPEN GKS has set the ISO initial state (the profile's initial attributes). */
    void (*opened_gks)(void);
    /* After OPEN WORKSTATION succeeded (its initial tables, e.g. a colour table). */
    void (*opened_ws)(Gint ws_id);
    /* A foreign workstation type to this library's, when GKS3D_WS_TYPES does not map it;
     * ws_type itself if the profile has no mapping. */
    Gint (*ws_type)(Gint ws_type);
    /* SET FILL AREA INTERIOR STYLE: a foreign style to an ISO one (unchanged if none). */
    Gint (*fill_int_style)(Gint style);
    /* ESCAPE: -1 if func_id is not the profile's (the core then goes on as without a
     * profile), else 0 or the error number to report. out (NULL if the caller gave no
     * store) has escape_r1 = a blank-filled buffer of GKS_PROFILE_ESC_OUT bytes (its
     * size); the profile sets the size to what it returns (0: nothing). */
    int (*escape)(Gint func_id, const Gescape_in_data *in, Gescape_out_data *out);
} gks_profile;

#define GKS_PROFILE_ESC_OUT 640 /* bytes of a profile escape's output (8 records of 80) */

/* Registers the profile (NULL: none); the last call wins. Takes effect at the next OPEN
 * GKS for opened_gks, at once for the others. */
GKS_API void gks_set_profile(const gks_profile *p);

#endif
