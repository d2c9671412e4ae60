/* SPDX-License-Identifier: MIT */
/* hello.c -- the smallest GKS program: a filled triangle and a polyline frame on a PNG
 * workstation. Writes hello_c.png in the current directory. */
#include <gks.h>

int main(void)
{
    Gpoint tri[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
    Gpoint box[5] = { { 0.05, 0.05 }, { 0.95, 0.05 }, { 0.95, 0.95 }, { 0.05, 0.95 }, { 0.05, 0.05 } };
    Gpoint_list tri_list = { 3, tri }, box_list = { 5, box };
    Glimit ws_vp = { 0, 200, 0, 100 }, ws_win = { 0, 1, 0, 0.5 };
    Glimit win = { 0, 1, 0, 1 }, vp = { 0, 1, 0, 0.5 };

    gopen_gks(NULL, 0);
    gopen_ws(1, "hello_c.png", GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_win(1, &ws_win);
    gset_ws_vp(1, &ws_vp);
    gset_win(1, &win);
    gset_vp(1, &vp);
    gsel_norm_tran(1);
    gset_fill_colr_ind(2);   /* red */
    gfill_area(&tri_list);
    gset_line_colr_ind(4);   /* blue */
    gpolyline(&box_list);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    return 0;
}
