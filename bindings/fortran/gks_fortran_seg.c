/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_seg.c -- Fortran 77 entry points of the segment functions and their
 * inquiries (ISO 8651-1 names; GSSGT3 and GQSGA3 take the GKS-3D 3x4 matrix). Matrices are
 * Fortran arrays M(2,3) / M(3,4): element (i,j) is row i, column j.
 */
#include "gks_fortran.h"
#include <string.h>

static void from_f23(const freal *a, Gtran_matrix m)
{
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            m[i][j] = a[i + 2 * j];
}

static void from_f34(const freal *a, Gtran_matrix3 m)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = a[i + 3 * j];
}

FAPI void FNAME(gcrsg, GCRSG)(const fint *sgna) { gcreate_seg(*sgna); }
FAPI void FNAME(gclsg, GCLSG)(void) { gclose_seg(); }
FAPI void FNAME(grensg, GRENSG)(const fint *old, const fint *new_name)
{
    grename_seg(*old, *new_name);
}
FAPI void FNAME(gdsg, GDSG)(const fint *sgna) { gdel_seg(*sgna); }
FAPI void FNAME(gdsgwk, GDSGWK)(const fint *wkid, const fint *sgna) { gdel_seg_ws(*wkid, *sgna); }

FAPI void FNAME(gssgt, GSSGT)(const fint *sgna, const freal *m)
{
    Gtran_matrix t;
    from_f23(m, t);
    gset_seg_tran(*sgna, (const Gfloat (*)[3])t);
}

FAPI void FNAME(gssgt3, GSSGT3)(const fint *sgna, const freal *m)
{
    Gtran_matrix3 t;
    from_f34(m, t);
    gset_seg_tran3(*sgna, (const Gfloat (*)[4])t);
}

FAPI void FNAME(gsvis, GSVIS)(const fint *sgna, const fint *vis) { gset_vis(*sgna, (Gseg_vis)*vis); }
FAPI void FNAME(gshlit, GSHLIT)(const fint *sgna, const fint *hil)
{
    gset_highl(*sgna, (Gseg_highl)*hil);
}
FAPI void FNAME(gssgp, GSSGP)(const fint *sgna, const freal *prior) { gset_seg_pri(*sgna, *prior); }
FAPI void FNAME(gsdtec, GSDTEC)(const fint *sgna, const fint *det) { gset_det(*sgna, (Gseg_det)*det); }

/* GQSGUS(N, ERRIND, OL, SGNA): set of segment names in use. */
FAPI void FNAME(gqsgus, GQSGUS)(const fint *n, fint *errind, fint *ol, fint *sgna)
{
    gks_f77_list_elem(ginq_set_seg_names, *n, errind, ol, sgna);
}

/* GQOPSG(ERRIND, SGNA): name of the open segment. */
FAPI void FNAME(gqopsg, GQOPSG)(fint *errind, fint *sgna)
{
    Gint e, name = 0;
    ginq_name_open_seg(&e, &name);
    *errind = e;
    if (!e)
        *sgna = name;
}

static void seg_attrs(fint sgna, fint *errind, Gseg_attrs3 *a)
{
    Gint e;
    memset(a, 0, sizeof *a);
    ginq_seg_attrs3(sgna, &e, a);
    *errind = e;
}

/* GQSGA(SGNA, ERRIND, SEGTM(2,3), VIS, HIL, SGPR, DET). */
FAPI void FNAME(gqsga, GQSGA)(const fint *sgna, fint *errind, freal *segtm, fint *vis,
                              fint *hil, freal *sgpr, fint *det)
{
    Gseg_attrs3 a;
    seg_attrs(*sgna, errind, &a);
    if (*errind)
        return;
    const int col[3] = { 0, 1, 3 }; /* x, y and translation columns of the 3x4 matrix */
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 3; j++)
            segtm[i + 2 * j] = (freal)a.tran_matrix[i][col[j]];
    *vis = a.vis;
    *hil = a.highl;
    *sgpr = (freal)a.pri;
    *det = a.det;
}

/* GQSGA3(SGNA, ERRIND, SEGTM(3,4), VIS, HIL, SGPR, DET). */
FAPI void FNAME(gqsga3, GQSGA3)(const fint *sgna, fint *errind, freal *segtm, fint *vis,
                                fint *hil, freal *sgpr, fint *det)
{
    Gseg_attrs3 a;
    seg_attrs(*sgna, errind, &a);
    if (*errind)
        return;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            segtm[i + 3 * j] = (freal)a.tran_matrix[i][j];
    *vis = a.vis;
    *hil = a.highl;
    *sgpr = (freal)a.pri;
    *det = a.det;
}

/* The Fortran list convention (see gks_f77_list_elem) over a list inquiry that also takes
 * a workstation or segment identifier. */
static void list_elem_of(void (*f)(Gint, Gint, Gint, Gint *, Gint_list *, Gint *), fint id,
                         fint n, fint *errind, fint *ol, fint *elem)
{
    Gint v = 0, len = 0, e = 0;
    Gint_list l = { 0, &v };
    f(id, n > 0 ? 1 : 0, n > 0 ? n - 1 : (n == 0 ? 0 : -1), &e, &l, &len);
    *errind = e;
    *ol = len;
    if (*errind == 0 && n > len)
        *errind = 2002;
    if (*errind == 0 && n > 0)
        *elem = v;
}

/* GQSGWK(WKID, N, ERRIND, OL, SGNA): set of segment names on a workstation. */
FAPI void FNAME(gqsgwk, GQSGWK)(const fint *wkid, const fint *n, fint *errind, fint *ol,
                                fint *sgna)
{
    list_elem_of(ginq_set_seg_names_ws, *wkid, *n, errind, ol, sgna);
}

/* GQASWK(SGNA, N, ERRIND, OL, WKID): set of workstations a segment is stored on. */
FAPI void FNAME(gqaswk, GQASWK)(const fint *sgna, const fint *n, fint *errind, fint *ol,
                                fint *wkid)
{
    list_elem_of(ginq_set_assoc_wss, *sgna, *n, errind, ol, wkid);
}

/* GQSGP(WTYPE, ERRIND, NSG): number of segment priorities supported (0 = continuous). */
FAPI void FNAME(gqsgp, GQSGP)(const fint *wtype, fint *errind, fint *nsg)
{
    Gint e, k = 0;
    ginq_num_seg_pris(*wtype, &e, &k);
    *errind = e;
    if (!e)
        *nsg = k;
}

FAPI void FNAME(gasgwk, GASGWK)(const fint *wkid, const fint *sgna) { gassoc_seg_ws(*wkid, *sgna); }
FAPI void FNAME(gcsgwk, GCSGWK)(const fint *wkid, const fint *sgna) { gcopy_seg_ws(*wkid, *sgna); }

/* GINSG(SGNA, M(2,3)) */
FAPI void FNAME(ginsg, GINSG)(const fint *sgna, const freal *m)
{
    Gtran_matrix t;
    from_f23(m, t);
    ginsert_seg(*sgna, (const Gfloat (*)[3])t);
}

/* GINSG3(SGNA, M(3,4)) */
FAPI void FNAME(ginsg3, GINSG3)(const fint *sgna, const freal *m)
{
    Gtran_matrix3 t;
    from_f34(m, t);
    ginsert_seg3(*sgna, (const Gfloat (*)[4])t);
}
