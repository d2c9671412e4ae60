/* SPDX-License-Identifier: MIT */
/*
 * ws_tran.c -- the workstation transformation of a workstation state list as a matrix
 * (ws_driver.h), for the drivers and the core alike.
 */
#include "ws_driver.h"
#include "gks_xform.h"

int gks_ws_tran_matrix(const gks_ws *ws, double m[4][4])
{
    double win[6], vp[6];
    gks_limit3_array(&ws->cur_win, win);
    gks_limit3_array(&ws->cur_vp, vp);
    return gks_xform_ws_tran3(win, vp, m);
}

int gks_ws_pixel_matrix(const gks_ws *ws, double s, double m[4][4])
{
    double win[6];
    gks_limit3_array(&ws->cur_win, win);
    const double vp[6] = { 0, (ws->cur_vp.x_max - ws->cur_vp.x_min) * s, 0,
                           (ws->cur_vp.y_max - ws->cur_vp.y_min) * s, 0, 1 };
    return gks_xform_ws_tran3(win, vp, m);
}
