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

/* The data record of this implementation, as the Fortran binding's GPREC packs it: "GKSR",
 * the counts IL, RL, SL, the IL integers, the RL reals and the SL string lengths, each as
 * decimal text ended by ',', then the strings' characters. The one reader of the format
 * (GUREC, and the CHOICE menu labels of gks_indev.c): the fields are read in order from p
 * (before end). */
typedef struct {
    const char *p, *end;
    long il, rl, sl; /* the counts, each 0..GKS_REC_MAX_COUNT */
} gks_rec_reader;
#define GKS_REC_MAX_COUNT 1000000
/* 0 when the len bytes at buf begin a packed record (its counts read), else -1. */
GKS_API int gks_rec_begin(gks_rec_reader *r, const char *buf, size_t len);
/* The next field as an integer (gks_rec_long) or a real (gks_rec_real): 0, or -1 when the
 * next text before end is no such field ended by ','. */
GKS_API int gks_rec_long(gks_rec_reader *r, long *v);
GKS_API int gks_rec_real(gks_rec_reader *r, double *v);
#endif
