/* SPDX-License-Identifier: MIT */
/*
 * f77_data_twin.c -- the C twin of f77_data.f: the same primitives with data, the same
 * values (exact binary fractions, so REAL and double agree), through the C binding onto
 * c21.png and c22.gksm. f77_data_check compares the two programs' outputs.
 */
#include <gks.h>
#include <stdio.h>

int main(void)
{
    static Gpoint3 a[3] = { { 0.125, 0.125, 0.5 }, { 0.5, 0.125, 0.5 }, { 0.25, 0.375, 0.625 } };
    static Gcoval acr[3] = { { .rgb = { 1, 0, 0 } }, { .rgb = { 0, 1, 0 } }, { .rgb = { 0, 0, 1 } } };
    static Gvec3 avn[3] = { { 0, 0, 1 }, { 0.25, 0, 1 }, { 0, 0.25, 1 } };
    static Gpoint3 b[7] = { { 0.5, 0.5, 0.25 }, { 0.875, 0.5, 0.25 }, { 0.875, 0.875, 0.25 },
                            { 0.5, 0.875, 0.25 }, { 0.625, 0.5625, 0.25 },
                            { 0.75, 0.5625, 0.25 }, { 0.6875, 0.75, 0.25 } };
    static Gcoval bci[7] = { { .ind = 2 }, { .ind = 3 }, { .ind = 1 }, { .ind = 2 },
                             { .ind = 3 }, { .ind = 3 }, { .ind = 2 } };
    static Gpoint3 s[6] = { { 0.0625, 0.5, 0.25 }, { 0.125, 0.875, 0.25 }, { 0.1875, 0.5, 0.375 },
                            { 0.25, 0.875, 0.375 }, { 0.3125, 0.5, 0.5 }, { 0.375, 0.875, 0.5 } };
    static Gfacet_data3 sf[4] = { { .colr = { .rgb = { 1, 1, 0 } }, .norm = { 0, 0, 1 } },
                                  { .colr = { .rgb = { 0, 1, 1 } }, .norm = { 0, 1, 1 } },
                                  { .colr = { .rgb = { 1, 0, 1 } }, .norm = { 1, 0, 1 } },
                                  { .colr = { .rgb = { 0.5, 0.5, 0.5 } }, .norm = { 0, 0, -1 } } };
    static Gpoint3 q[6] = { { 0.5, 0.0625, 0.5 }, { 0.625, 0.0625, 0.5 }, { 0.75, 0.0625, 0.5 },
                            { 0.5, 0.25, 0.75 }, { 0.625, 0.25, 0.75 }, { 0.75, 0.25, 0.75 } };
    static Gvec3 qvn[6] = { { 0, 0, 1 }, { 0.25, 0, 1 }, { 0.5, 0, 1 },
                            { 0, 0.25, 1 }, { 0.25, 0.25, 1 }, { 0.5, 0.25, 1 } };
    static Gcoval qci[6] = { { .ind = 1 }, { .ind = 2 }, { .ind = 3 },
                             { .ind = 2 }, { .ind = 3 }, { .ind = 1 } };
    static Gpoint3 o[5] = { { 0.8125, 0.0625, 0.75 }, { 0.9375, 0.0625, 0.75 },
                            { 0.9375, 0.375, 0.75 }, { 0.8125, 0.375, 0.75 },
                            { 0.875, 0.25, 0.875 } };
    static Gfacet_data3 of[2] = { { .norm = { 0, -1, 1 } }, { .norm = { 1, 1, 1 } } };
    static Gcoval ocr[5] = { { .rgb = { 1, 0.5, 0 } }, { .rgb = { 0, 0.5, 1 } },
                             { .rgb = { 1, 1, 1 } }, { .rgb = { 0.25, 0.25, 0.25 } },
                             { .rgb = { 0, 1, 0 } } };
    static Gint i0[3] = { 0, 1, 4 }, i1[3] = { 1, 2, 4 }, i2[4] = { 2, 3, 0, 4 };
    Gint_list l0[1] = { { 3, i0 } }, l1[2] = { { 3, i1 }, { 4, i2 } };
    Gint_list_list sets[2] = { { 1, l0 }, { 2, l1 } };
    gopen_gks(NULL, 0);
    gopen_ws(1, "c21.png", GWS_TYPE_PNG);
    gopen_ws(2, "c22.gksm", GWS_TYPE_MO);
    gactivate_ws(1);
    gactivate_ws(2);
    for (Gint k = 1; k <= 2; k++) {
        gset_hlhsr_mode(k, GHLHSR_ZBUFFER);
        gset_colr_rep(k, 2, &(Gcolr_rep){ { 0.75, 0.25, 0.125 } });
        gset_colr_rep(k, 3, &(Gcolr_rep){ { 0.125, 0.5, 0.875 } });
    }
    gset_fill_int_style(GSTYLE_SOLID);
    gset_int_shad_meth(GSHAD_COLR);
    gset_back_int_shad_meth(GSHAD_NORM);
    Gint err = -1, m1 = 0, m2 = 0;
    ginq_int_shad_meth(&err, &m1, &m2);
    Gfacet_data3 af = { .norm = { 0, 0, 1 } };
    gfill_area3_data(GFACET_NORM, GVERT_COORD_COLR_NORM, GCOLR_RGB, &af,
                     &(Gfacet_vdata3){ 3, a, acr, avn });
    gset_edge_flag(GEDGE_ON);
    Gfacet_vdata3 loops[2] = { { 4, b, bci, NULL }, { 3, b + 4, bci + 4, NULL } };
    gfill_area_set3_data(GFACET_COLR, GVERT_COORD_COLR, GCOLR_INDIRECT,
                         &(Gfacet_data3){ .colr = { .ind = 3 } }, 2, loops);
    gset_edge_flag(GEDGE_OFF);
    gtri_strip3_data(GFACET_COLR_NORM, GVERT_COORD, GCOLR_RGB, sf,
                     &(Gfacet_vdata3){ 6, s, NULL, NULL });
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_INDIRECT, &(Gint_size){ 3, 2 },
                     NULL, &(Gfacet_vdata3){ 6, q, qci, qvn });
    gset_of_fill_area_set3_data(GFACET_NORM, GVERT_COORD_COLR, GCOLR_RGB, 2, of, sets,
                                &(Gfacet_vdata3){ 5, o, ocr, NULL });
    gdeactivate_ws(2);
    gdeactivate_ws(1);
    gclose_ws(2);
    gclose_ws(1);
    gclose_gks();
    int ok = err == 0 && m1 == GSHAD_COLR && m2 == GSHAD_NORM;
    puts(ok ? "C DATA PASS" : "C DATA FAIL");
    return !ok;
}
