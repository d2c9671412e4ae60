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

/* The binding's one allocation funnel: n * size bytes, overflow checked (at least one
 * byte, so NULL always means failure); NULL on failure. */
void *gks_f77_alloc(size_t n, size_t size);
/* Storage overflow inside the binding: error 300 for fctid through the core's error path
 * (gks_binding_error). */
void gks_f77_nomem(Gint fctid);

/* Blank-padded copy of a C string into a CHARACTER*(dlen); returns the copied length. */
fint gks_f77_fill_str(const char *src, char *dst, size_t dlen);

/* A C list inquiry (num_elems_appl_list, start_pos, err_ind, list, length). */
typedef void (*gks_f77_list_inq)(Gint, Gint, Gint *, Gint_list *, Gint *);

/* The Fortran list-inquiry convention: element N (1-based) into *elem, the list length
 * into *ol; N = 0 asks only for the length; N beyond the list reports 2002. */
void gks_f77_list_elem(gks_f77_list_inq f, fint n, fint *errind, fint *ol, fint *elem);

/* Fortran REAL arrays <-> C binding values. Matrices are column-major M(I,J) = m[i][j]:
 * 4x4 view matrices, 3x4 GKS-3D segment matrices; limits are XMIN,XMAX,YMIN,YMAX(,ZMIN,
 * ZMAX). */
static inline void gks_f77_get_m4(const freal *a, Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = a[i + 4 * j];
}
static inline void gks_f77_put_m4(const Gmatrix3 m, freal *a)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            a[i + 4 * j] = (freal)m[i][j];
}
static inline void gks_f77_get_m34(const freal *a, Gtran_matrix3 m)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = a[i + 3 * j];
}
static inline void gks_f77_put_m34(const Gtran_matrix3 m, freal *a)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            a[i + 3 * j] = (freal)m[i][j];
}
static inline void gks_f77_put_limit3(const Glimit3 *l, freal *a)
{
    a[0] = (freal)l->x_min; a[1] = (freal)l->x_max; a[2] = (freal)l->y_min;
    a[3] = (freal)l->y_max; a[4] = (freal)l->z_min; a[5] = (freal)l->z_max;
}
#endif
