/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_ws3.c -- Fortran 77 entry points of the input priority functions and the
 * workstation transformation 3: GSVPIP(TNR, RTNR, RELPRI), GQENTN(N, ERRIND, OL, SNTRAN),
 * GSVTIP(WKID, VWI, RVWI, RELPRI) and GQEVWI(WKID, N, ERRIND, OL, VWI) (our names for the
 * GKS-3D view priority), GSWKW3(WKID, WKWN(6)), GSWKV3(WKID, WKVP(6)) and
 * GQWKT3(WKID, ERRIND, TUS, RWINDO(6), CWINDO(6), RVIEWP(6), CVIEWP(6)); limits as
 * xmin, xmax, ymin, ymax, zmin, zmax.
 */
#include "gks_fortran.h"

FAPI void FNAME(gsvpip, GSVPIP)(const fint *tnr, const fint *rtnr, const fint *relpri)
{
    gset_vp_in_pri(*tnr, *rtnr, (Grel_pri)*relpri);
}

FAPI void FNAME(gqentn, GQENTN)(const fint *n, fint *errind, fint *ol, fint *sntran)
{
    gks_f77_list_elem(ginq_list_norm_tran_nums, *n, errind, ol, sntran);
}

FAPI void FNAME(gsvtip, GSVTIP)(const fint *wkid, const fint *vwi, const fint *rvwi,
                                const fint *relpri)
{
    gset_view_tran_in_pri(*wkid, *vwi, *rvwi, (Grel_pri)*relpri);
}

FAPI void FNAME(gqevwi, GQEVWI)(const fint *wkid, const fint *n, fint *errind, fint *ol,
                                fint *vwi)
{
    Gint v = 0, len = 0, e = 0;
    Gint_list l = { 0, &v };
    ginq_list_view_inds(*wkid, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : (*n == 0 ? 0 : -1), &e, &l,
                        &len);
    *errind = e;
    *ol = len;
    if (e == 0 && *n > len)
        *errind = 2002;
    if (*errind == 0 && *n > 0)
        *vwi = v;
}

static Glimit3 limit3(const freal *a)
{
    return (Glimit3){ a[0], a[1], a[2], a[3], a[4], a[5] };
}

static void put3(const Glimit3 *l, freal *a)
{
    a[0] = (freal)l->x_min; a[1] = (freal)l->x_max; a[2] = (freal)l->y_min;
    a[3] = (freal)l->y_max; a[4] = (freal)l->z_min; a[5] = (freal)l->z_max;
}

FAPI void FNAME(gswkw3, GSWKW3)(const fint *wkid, const freal *wkwn)
{
    Glimit3 l = limit3(wkwn);
    gset_ws_win3(*wkid, &l);
}

FAPI void FNAME(gswkv3, GSWKV3)(const fint *wkid, const freal *wkvp)
{
    Glimit3 l = limit3(wkvp);
    gset_ws_vp3(*wkid, &l);
}

FAPI void FNAME(gqwkt3, GQWKT3)(const fint *wkid, fint *errind, fint *tus, freal *rwindo,
                                freal *cwindo, freal *rviewp, freal *cviewp)
{
    Gint e = 0;
    Gupd_st st = GUPD_NOT_PEND;
    Glimit3 rw, cw, rv, cv;
    ginq_ws_tran3(*wkid, &e, &st, &rw, &cw, &rv, &cv);
    *errind = e;
    if (e)
        return;
    *tus = (fint)st;
    put3(&rw, rwindo);
    put3(&cw, cwindo);
    put3(&rv, rviewp);
    put3(&cv, cviewp);
}
