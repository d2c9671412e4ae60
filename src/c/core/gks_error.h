/* SPDX-License-Identifier: MIT */
/*
 * gks_error.h -- the one error path: every function that detects an error calls
 * gks_error_report(), which sets the error state, calls the current ERROR HANDLING
 * procedure (gerr_hand or the application's) and returns. Never exits.
 */
#ifndef GKS_ERROR_H
#define GKS_ERROR_H
#include "gks_private.h"
#include "gks.h"

/* Report error `err_num` detected in function `fctid`. */
void gks_error_report(int err_num, int fctid);

/* Entry-point guard: if the operating state does not allow `fctid`, report the state
 * error and return it; else return 0. Usage:  if (gks_check_state(GFN_PL)) return; */
int gks_check_state(int fctid);

/* For inquiries: the state error number for a function allowed in `mask`, or 0. */
int gks_inq_state(unsigned mask);

/* Shorthand for the entry points: report and return from a void function. */
#define GKS_FAIL(err, fct) do { gks_error_report((err), (fct)); return; } while (0)
#endif
