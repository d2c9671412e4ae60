/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_inq.c -- FORTRAN 77 forms of the inquiries and utilities that complete the
 * ISO 8651-1 list (colour facilities, pixels, dynamic modification, default deferral)
 * and their GKS-3D counterparts (3-D normalization, clipping, display space, table
 * lengths, views, HLHSR, GDPs), plus GEVTM3 / GACTM3. Each converts arguments and calls
 * the C binding; errors arrive in ERRIND as the C inquiries report them.
 */
#include "gks_fortran.h"
#include <stdlib.h>
#include <string.h>

/* GQCF(WTYPE, ERRIND, NCOLI, COLA, NPCI): INQUIRE COLOUR FACILITIES. */
FAPI void FNAME(gqcf, GQCF)(const fint *wtype, fint *errind, fint *ncoli, fint *cola, fint *npci)
{
    Gcolr_facs f;
    ginq_colr_facs(*wtype, errind, &f);
    if (*errind)
        return;
    *ncoli = f.num_colrs;
    *cola = (fint)f.colr_avail;
    *npci = f.num_pred_inds;
}

/* GQPCR(WTYPE, PCI, ERRIND, RED, GREEN, BLUE): INQUIRE PREDEFINED COLOUR REPRESENTATION. */
FAPI void FNAME(gqpcr, GQPCR)(const fint *wtype, const fint *pci, fint *errind, freal *red,
                              freal *green, freal *blue)
{
    Gcolr_rep c;
    ginq_pred_colr_rep(*wtype, *pci, errind, &c);
    if (*errind)
        return;
    *red = (freal)c.rgb.red;
    *green = (freal)c.rgb.green;
    *blue = (freal)c.rgb.blue;
}

/* GQECI(WKID, N, ERRIND, OL, COLIND): the N-th defined colour index (N = 0: count only). */
FAPI void FNAME(gqeci, GQECI)(const fint *wkid, const fint *n, fint *errind, fint *ol,
                              fint *colind)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    ginq_list_colr_inds(*wkid, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : (*n == 0 ? 0 : -1), errind,
                        &l, &len);
    if (*errind == 0 || *errind == 2002)
        *ol = len;
    if (*errind == 0 && *n > 0)
        *colind = v;
}

/* GQPX(WKID, PX, PY, ERRIND, COLI): INQUIRE PIXEL (-1 = invalid colour index). */
FAPI void FNAME(gqpx, GQPX)(const fint *wkid, const freal *px, const freal *py, fint *errind,
                            fint *coli)
{
    Gpoint p = { *px, *py };
    Gint c = -1;
    ginq_pixel(*wkid, &p, errind, &c);
    if (!*errind)
        *coli = c;
}

/* GQPXAD(WKID, PX, PY, QX, QY, ERRIND, N, M): INQUIRE PIXEL ARRAY DIMENSIONS. */
FAPI void FNAME(gqpxad, GQPXAD)(const fint *wkid, const freal *px, const freal *py,
                                const freal *qx, const freal *qy, fint *errind, fint *n,
                                fint *m)
{
    Grect r = { { *px, *py }, { *qx, *qy } };
    Gint_size d;
    ginq_pixel_array_dims(*wkid, &r, errind, &d);
    if (*errind)
        return;
    *n = d.size_x;
    *m = d.size_y;
}

/* GQPXA(WKID, PX, PY, DIMX, DIMY, NCS, NRS, DX, DY, ERRIND, INVVAL, COLIA(DIMX,DIMY)):
 * INQUIRE PIXEL ARRAY: DX columns by DY rows from the pixel at (PX, PY) (its top-left
 * corner) into COLIA from column NCS, row NRS (row NRS = the top row). 2001 if they do
 * not fit, 91 if DX or DY < 1. */
FAPI void FNAME(gqpxa, GQPXA)(const fint *wkid, const freal *px, const freal *py,
                              const fint *dimx, const fint *dimy, const fint *ncs,
                              const fint *nrs, const fint *dx, const fint *dy, fint *errind,
                              fint *invval, fint *colia)
{
    Gpoint p = { *px, *py };
    Gint_size d = { *dx, *dy };
    Gint e = 0, len = 0;
    Gpres_inval inv = GINVAL_ABSENT;
    Gint_list l = { 0, NULL };
    /* State and workstation checks first, with an empty request. */
    ginq_pixel_array(*wkid, &p, &d, 0, 0, &e, &inv, &l, &len);
    if (!e && (*ncs < 1 || *nrs < 1 || *ncs - 1 + *dx > *dimx || *nrs - 1 + *dy > *dimy))
        e = 2001;
    if (e) {
        *errind = e;
        return;
    }
    /* An inquiry reports storage overflow in ERRIND only (never through ERROR HANDLING). */
    size_t n = (size_t)*dx * (size_t)*dy;
    Gint *buf = gks_f77_alloc(n, sizeof *buf);
    if (!buf) {
        *errind = 300;
        return;
    }
    l.ints = buf;
    ginq_pixel_array(*wkid, &p, &d, (Gint)n, 0, &e, &inv, &l, &len);
    if (!e) {
        for (fint j = 0; j < *dy; j++)
            for (fint i = 0; i < *dx; i++)
                colia[(size_t)(*ncs - 1 + i) + (size_t)(*nrs - 1 + j) * (size_t)*dimx] =
                    buf[(size_t)j * (size_t)*dx + (size_t)i];
        *invval = (fint)inv;
    }
    free(buf);
    *errind = e;
}

/* GQDWKA(WTYPE, ERRIND, PLBUN, PMBUN, TXBUN, FABUN, PAREP, COLREP, WKTR): dynamic
 * modification of workstation attributes, GIRG = 0 / GIMM = 1. */
FAPI void FNAME(gqdwka, GQDWKA)(const fint *wtype, fint *errind, fint *plbun, fint *pmbun,
                                fint *txbun, fint *fabun, fint *parep, fint *colrep,
                                fint *wktr)
{
    Gdyn_mod_ws_attrs a;
    ginq_dyn_mod_ws_attrs(*wtype, errind, &a);
    if (*errind)
        return;
    *plbun = a.line_bundle; *pmbun = a.marker_bundle; *txbun = a.text_bundle;
    *fabun = a.fill_bundle; *parep = a.pat_rep; *colrep = a.colr_rep; *wktr = a.ws_tran;
}

/* GQDWK3(WTYPE, ERRIND, PLBUN, PMBUN, TXBUN, FABUN, PAREP, COLREP, WKTR, EDBUN, VWREP,
 * HRM): the GKS-3D form, edge bundle, view representation and HLHSR mode appended. */
FAPI void FNAME(gqdwk3, GQDWK3)(const fint *wtype, fint *errind, fint *plbun, fint *pmbun,
                                fint *txbun, fint *fabun, fint *parep, fint *colrep,
                                fint *wktr, fint *edbun, fint *vwrep, fint *hrm)
{
    Gdyn_mod_ws_attrs3 a;
    ginq_dyn_mod_ws_attrs3(*wtype, errind, &a);
    if (*errind)
        return;
    *plbun = a.attrs.line_bundle; *pmbun = a.attrs.marker_bundle; *txbun = a.attrs.text_bundle;
    *fabun = a.attrs.fill_bundle; *parep = a.attrs.pat_rep; *colrep = a.attrs.colr_rep;
    *wktr = a.attrs.ws_tran; *edbun = a.edge_bundle; *vwrep = a.view_rep; *hrm = a.hlhsr_mode;
}

/* GQDDS(WTYPE, ERRIND, DEFMOD, REGMOD): default deferral state values. */
FAPI void FNAME(gqdds, GQDDS)(const fint *wtype, fint *errind, fint *defmod, fint *regmod)
{
    Gdefer_mode d;
    Girg_mode r;
    ginq_def_defer_sts(*wtype, errind, &d, &r);
    if (*errind)
        return;
    *defmod = (fint)d;
    *regmod = (fint)r;
}

/* GQDSGA(WTYPE, ERRIND, SGTR, VONOFF, VOFFON, HIGH, SGPR, ADD, SGDEL): dynamic
 * modification of segment attributes. */
FAPI void FNAME(gqdsga, GQDSGA)(const fint *wtype, fint *errind, fint *sgtr, fint *vonoff,
                                fint *voffon, fint *high, fint *sgpr, fint *add, fint *sgdel)
{
    Gdyn_mod_seg_attrs a;
    ginq_dyn_mod_seg_attrs(*wtype, errind, &a);
    if (*errind)
        return;
    *sgtr = a.tran; *vonoff = a.disappear; *voffon = a.appear; *high = a.highl;
    *sgpr = a.pri; *add = a.add_prim; *sgdel = a.del;
}

/* GEVTM3(X0,Y0,Z0, DX,DY,DZ, PHIX,PHIY,PHIZ, FX,FY,FZ, SW, MOUT(3,4)). */
FAPI void FNAME(gevtm3, GEVTM3)(const freal *x0, const freal *y0, const freal *z0,
                                const freal *dx, const freal *dy, const freal *dz,
                                const freal *phix, const freal *phiy, const freal *phiz,
                                const freal *fx, const freal *fy, const freal *fz,
                                const fint *sw, freal *mout)
{
    Gpoint3 f = { *x0, *y0, *z0 };
    Gvec3 s = { *dx, *dy, *dz }, sc = { *fx, *fy, *fz };
    Gtran_matrix3 m;
    gks_f77_get_m34(mout, m); /* unchanged on error */
    geval_tran_matrix3(&f, &s, *phix, *phiy, *phiz, &sc, (Gcoord_switch)*sw, m);
    gks_f77_put_m34((const Gfloat (*)[4])m, mout);
}

/* GACTM3(MINP(3,4), X0,Y0,Z0, DX,DY,DZ, PHIX,PHIY,PHIZ, FX,FY,FZ, SW, MOUT(3,4)). */
FAPI void FNAME(gactm3, GACTM3)(const freal *minp, const freal *x0, const freal *y0,
                                const freal *z0, const freal *dx, const freal *dy,
                                const freal *dz, const freal *phix, const freal *phiy,
                                const freal *phiz, const freal *fx, const freal *fy,
                                const freal *fz, const fint *sw, freal *mout)
{
    Gtran_matrix3 in, m;
    gks_f77_get_m34(minp, in);
    gks_f77_get_m34(mout, m);
    Gpoint3 f = { *x0, *y0, *z0 };
    Gvec3 s = { *dx, *dy, *dz }, sc = { *fx, *fy, *fz };
    gaccum_tran_matrix3((const Gfloat (*)[4])in, &f, &s, *phix, *phiy, *phiz, &sc,
                        (Gcoord_switch)*sw, m);
    gks_f77_put_m34((const Gfloat (*)[4])m, mout);
}

/* GQVWI(ERRIND, VWI): current view index. */
FAPI void FNAME(gqvwi, GQVWI)(fint *errind, fint *vwi)
{
    Gint v = 0;
    ginq_view_ind(errind, &v);
    if (!*errind)
        *vwi = v;
}

/* GQVWR(WKID, VWI, TYPE, ERRIND, VWUPD, VWM(4,4), PRM(4,4), VCLP(6), CLW, CLB, CLF): view
 * representation (PHIGS PQVWR order; the update state is always GNPEND: a view
 * representation is current at once; TYPE GSET and GREALI return the same values). */
FAPI void FNAME(gqvwr, GQVWR)(const fint *wkid, const fint *vwi, const fint *type,
                              fint *errind, fint *vwupd, freal *vwm, freal *prm, freal *vclp,
                              fint *clw, fint *clb, fint *clf)
{
    Gview_rep3 r;
    ginq_view_rep3(*wkid, *vwi, errind, &r);
    if (!*errind && *type != GINQ_SET && *type != GINQ_REALIZED)
        *errind = 2000;
    if (*errind)
        return;
    *vwupd = GUPD_NOT_PEND;
    gks_f77_put_m4((const Gfloat (*)[4])r.ori_matrix, vwm);
    gks_f77_put_m4((const Gfloat (*)[4])r.map_matrix, prm);
    gks_f77_put_limit3(&r.clip_limit, vclp);
    *clw = r.xy_clip; *clb = r.back_clip; *clf = r.front_clip;
}

/* GQPVWR(WTYPE, PVWI, ERRIND, VWM(4,4), PRM(4,4), VCLP(6), CLW, CLB, CLF). */
FAPI void FNAME(gqpvwr, GQPVWR)(const fint *wtype, const fint *pvwi, fint *errind, freal *vwm,
                                freal *prm, freal *vclp, fint *clw, fint *clb, fint *clf)
{
    Gview_rep3 r;
    ginq_pred_view_rep(*wtype, *pvwi, errind, &r);
    if (*errind)
        return;
    gks_f77_put_m4((const Gfloat (*)[4])r.ori_matrix, vwm);
    gks_f77_put_m4((const Gfloat (*)[4])r.map_matrix, prm);
    gks_f77_put_limit3(&r.clip_limit, vclp);
    *clw = r.xy_clip; *clb = r.back_clip; *clf = r.front_clip;
}

/* GQVWF(WTYPE, ERRIND, NPVW): number of predefined view indices. */
FAPI void FNAME(gqvwf, GQVWF)(const fint *wtype, fint *errind, fint *npvw)
{
    Gint n = 0;
    ginq_view_facs(*wtype, errind, &n);
    if (!*errind)
        *npvw = n;
}

/* GQHRM(WKID, ERRIND, HRMUPD, CHRM, RHRM): HLHSR mode (PHIGS PQHRM order; a mode is
 * current at once: update state GNPEND, requested = current). */
FAPI void FNAME(gqhrm, GQHRM)(const fint *wkid, fint *errind, fint *hrmupd, fint *chrm,
                              fint *rhrm)
{
    Gint m = 0;
    ginq_hlhsr_mode(*wkid, errind, &m);
    if (*errind)
        return;
    *hrmupd = GUPD_NOT_PEND;
    *chrm = *rhrm = m;
}

/* GQHRF(WTYPE, NI, NM, ERRIND, NHRID, HRID, NHRM, HRM): the NI-th HLHSR identifier and
 * the NM-th HLHSR mode (0: counts only), list convention of GQFAF. */
FAPI void FNAME(gqhrf, GQHRF)(const fint *wtype, const fint *ni, const fint *nm, fint *errind,
                              fint *nhrid, fint *hrid, fint *nhrm, fint *hrm)
{
    Gint ids[32], modes[32], lid = 0, lm = 0;
    Gint_list li = { 0, ids }, lmo = { 0, modes };
    ginq_hlhsr_facs(*wtype, 32, 0, errind, &li, &lid, &lmo, &lm);
    if (*errind)
        return;
    *nhrid = lid;
    *nhrm = lm;
    if (*ni < 0 || *ni > li.num_ints || *nm < 0 || *nm > lmo.num_ints) {
        *errind = 2002;
        return;
    }
    if (*ni > 0)
        *hrid = ids[*ni - 1];
    if (*nm > 0)
        *hrm = modes[*nm - 1];
}

/* GQNT3(NTNR, ERRIND, WINDOW(6), VIEWPT(6)): normalization transformation 3. */
FAPI void FNAME(gqnt3, GQNT3)(const fint *ntnr, fint *errind, freal *window, freal *viewpt)
{
    Gtran3 t;
    ginq_norm_tran3(*ntnr, errind, &t);
    if (*errind)
        return;
    gks_f77_put_limit3(&t.win, window);
    gks_f77_put_limit3(&t.vp, viewpt);
}

/* GQCLP3(ERRIND, CLSW, CLRECT(6)): clipping indicator and clipping volume. */
FAPI void FNAME(gqclp3, GQCLP3)(fint *errind, fint *clsw, freal *clrect)
{
    Gclip3 c;
    ginq_clip3(errind, &c);
    if (*errind)
        return;
    *clsw = (fint)c.clip_ind;
    gks_f77_put_limit3(&c.clip_vol, clrect);
}

/* GQDSP3(WTYPE, ERRIND, DCUNIT, RX, RY, RZ, LX, LY, LZ): display space size 3. */
FAPI void FNAME(gqdsp3, GQDSP3)(const fint *wtype, fint *errind, fint *dcunit, freal *rx,
                                freal *ry, freal *rz, fint *lx, fint *ly, fint *lz)
{
    Gdisp_space_size3 d;
    ginq_disp_space_size3(*wtype, errind, &d);
    if (*errind)
        return;
    *dcunit = (fint)d.dc_units;
    *rx = (freal)d.size_dc.size_x; *ry = (freal)d.size_dc.size_y; *rz = (freal)d.size_dc.size_z;
    *lx = d.size_raster.size_x; *ly = d.size_raster.size_y; *lz = d.size_raster.size_z;
}

/* GQLWK3(WTYPE, ERRIND, MPLBTE, MPMBTE, MTXBTE, MFABTE, MPAI, MCOLI, MEDBTE, MVWTE):
 * GQLWK's table lengths, then the edge bundle and view tables. */
FAPI void FNAME(gqlwk3, GQLWK3)(const fint *wtype, fint *errind, fint *mpl, fint *mpm,
                                fint *mtx, fint *mfa, fint *mpa, fint *mcoli, fint *med,
                                fint *mvw)
{
    Gmax_ws_st_tables3 t;
    ginq_max_ws_st_tables3(*wtype, errind, &t);
    if (*errind)
        return;
    *mpl = t.line_bundles; *mpm = t.marker_bundles; *mtx = t.text_bundles;
    *mfa = t.fill_bundles; *mpa = t.pat_reps; *mcoli = t.colr_reps;
    *med = t.edge_bundles; *mvw = t.view_reps;
}

/* GQEGD3(WTYPE, N, ERRIND, NGDP, GDPL): the N-th available GDP 3 (N = 0: count only). */
FAPI void FNAME(gqegd3, GQEGD3)(const fint *wtype, const fint *n, fint *errind, fint *ngdp,
                                fint *gdpl)
{
    Gint v = 0, len = 0;
    Gint_list l = { 0, &v };
    ginq_list_avail_gdps3(*wtype, *n > 0 ? 1 : 0, *n > 0 ? *n - 1 : (*n == 0 ? 0 : -1),
                          errind, &l, &len);
    if (*errind == 0 || *errind == 2002)
        *ngdp = len;
    if (*errind == 0 && *n > 0)
        *gdpl = v;
}

/* GQGDP3(WTYPE, GDP, ERRIND, NBND, BNDL(5)): bundles used by a GDP 3 (GPLATT = 0 ...
 * GFAATT = 3, edge = 4). */
FAPI void FNAME(gqgdp3, GQGDP3)(const fint *wtype, const fint *gdp, fint *errind, fint *nbnd,
                                fint *bndl)
{
    Gint n = 0;
    Gattrs a[5];
    ginq_gdp3(*wtype, *gdp, errind, &n, a);
    if (*errind)
        return;
    *nbnd = n;
    for (Gint i = 0; i < n; i++)
        bndl[i] = (fint)a[i];
}
