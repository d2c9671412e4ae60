/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran.h -- what the Fortran 77 binding's C files share: the name mangling, the
 * Fortran scalar types and the list-inquiry helper.
 */
#ifndef GKS_FORTRAN_H
#define GKS_FORTRAN_H
#include "gks.h"
#include "FC.h"

#define FAPI __attribute__((visibility("default")))
#define FNAME(lower, UPPER) FC_GLOBAL(lower, UPPER)

typedef int fint;
typedef float freal;

/* A C list inquiry (num_elems_appl_list, start_pos, err_ind, list, length). */
typedef void (*gks_f77_list_inq)(Gint, Gint, Gint *, Gint_list *, Gint *);

/* The Fortran list-inquiry convention: element N (1-based) into *elem, the list length
 * into *ol; N = 0 asks only for the length; N beyond the list reports 2002. */
void gks_f77_list_elem(gks_f77_list_inq f, fint n, fint *errind, fint *ol, fint *elem);
#endif
