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

#endif
