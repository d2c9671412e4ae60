/* SPDX-License-Identifier: MIT */
/*
 * frame.c -- NCAR's FRAME for NCAR programs run unchanged on gks3d (docs/COMPAT.md): C
 * c_frame and the Fortran FRAME (external name frame_, gfortran's and g77's convention).
 * Not part of the library: link it before -lgks3d (examples/ncar/CMakeLists.txt builds
 * it as gks3d_ncar).
 */
#include "ncarg/ncargC.h"

void c_frame(void)
{
    Gint ids[64], n = 0, err;
    Gint_list active = { 64, ids };
    ginq_set_active_wss(64, 0, &err, &active, &n);
    if (err)
        return;
    for (Gint i = 0; i < active.num_ints; i++) {
        char conn[8];
        Gint type;
        Gws_cat cat;
        ginq_ws_conn_type(ids[i], (Gint)sizeof conn, &err, conn, &type);
        if (err)
            continue;
        ginq_ws_cat(type, &err, &cat);
        if (err || (cat != GCAT_OUT && cat != GCAT_OUTIN && cat != GCAT_MO))
            continue;
        gupd_ws(ids[i], GFLAG_PERFORM);
        gclear_ws(ids[i], GFLAG_ALWAYS);
    }
}

/* CALL FRAME from Fortran. */
void frame_(void);
void frame_(void)
{
    c_frame();
}
