/* SPDX-License-Identifier: MIT */
/*
 * gks_rec.h -- the one reader of this implementation's data record, as the Fortran
 * binding's GPREC packs it: "GKSR", the counts IL, RL, SL, the IL integers, the RL reals
 * and the SL string lengths, each as decimal text ended by ',', then the strings'
 * characters. Read by GUREC (bindings/fortran) and by the CHOICE menu labels (ws_input.c).
 * The Fortran binding includes it too, so it has no internal-header guard; its names are
 * exported like those of core/api/gks_binding.h.
 */
#ifndef GKS_REC_H
#define GKS_REC_H
#include "gks.h"
#include <stddef.h>

#define GKS_REC_MAX_COUNT 1000000

/* The fields are read in order from p (before end). */
typedef struct {
    const char *p, *end;
    long il, rl, sl; /* the counts, each 0..GKS_REC_MAX_COUNT */
} gks_rec_reader;

/* 0 when the len bytes at buf begin a packed record (its counts read), else -1. */
GKS_API int gks_rec_begin(gks_rec_reader *r, const char *buf, size_t len);
/* The next field as an integer (gks_rec_long) or a real (gks_rec_real): 0, or -1 when the
 * next text before end is no such field ended by ','. */
GKS_API int gks_rec_long(gks_rec_reader *r, long *v);
GKS_API int gks_rec_real(gks_rec_reader *r, double *v);
#endif
