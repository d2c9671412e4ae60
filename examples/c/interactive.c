/* SPDX-License-Identifier: MIT */
/*
 * interactive.c -- the small interactive example: the Fig. 3 scene in a window (X11
 * workstation) in z-buffer preview. Click with mouse button 1 (LOCATOR 1 in EVENT mode)
 * to turn the camera: the horizontal position sets the azimuth, the vertical one the
 * elevation. Keys (CHOICE 1 in EVENT mode): 1 ray trace the current view in the same
 * window, 2 back to the z-buffer preview, 0 quit. The scene is one segment, redrawn with
 * the new view by REDRAW ALL SEGMENTS ON WORKSTATION.
 * Usage: interactive_c [SCRIPT]  -- SCRIPT: an input script (docs/INPUT.md) replayed
 * instead of the mouse and keys, e.g. for a batch run on the PNG workstation: then
 * "interactive_c script.txt png" writes interactive-NNN.png frames.
 */
#include "fig_scene.h"
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static void vpn_from(double az, double el, float vpn[3])
{
    vpn[0] = (float)(cos(el) * sin(az));
    vpn[1] = (float)sin(el);
    vpn[2] = (float)(cos(el) * cos(az));
}

int main(int argc, char **argv)
{
    int png = argc > 2 && strcmp(argv[2], "png") == 0;
    gopen_gks(NULL, 0);
    gopen_ws(1, png ? "interactive" : "", png ? GWS_TYPE_PNG : GWS_TYPE_X11);
    Gint err;
    Gws_st st;
    ginq_ws_st(1, &err, &st);
    if (err) {
        fprintf(stderr, "interactive: cannot open the workstation (no display?)\n");
        gclose_gks();
        return 1;
    }
    if (argc > 1) {
        Gint id = 1;
        Gescape_in_data in = { { 1, &id, 0, NULL, strlen(argv[1]), argv[1] } };
        gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
    }
    gactivate_ws(1);
    Glimit win = { 0, 1, 0, 1 }, vp = { 0, 800, 0, 800 };
    gset_ws_win(1, &win);
    gset_ws_vp(1, &vp);
    /* The paper's camera: VPN (0.35, 0.55, 1). */
    double az = atan2(0.35, 1.0), el = atan2(0.55, sqrt(0.35 * 0.35 + 1.0));
    float vpn[3];
    vpn_from(az, el, vpn);
    gset_hlhsr_mode(1, GHLHSR_ZBUFFER);
    fig_scene_setup(FIG_SCENE_BOARD, vpn);
    Gint ints[3] = { 1, 4, 0 };
    Gescape_in_data samples = { { 3, ints, 0, NULL, 0, NULL } };
    gescape(GESC_RT_SAMPLES, &samples, NULL, NULL); /* 2 x 2 samples per pixel when tracing */
    gcreate_seg(1);
    fig_scene_draw(FIG_SCENE_BOARD);
    gclose_seg();
    gredraw_all_seg_ws(1); /* on the background colour the setup chose */
    gupd_ws(1, GFLAG_PERFORM);
    gset_loc_mode(1, 1, GOP_EVENT, GSWITCH_ECHO);
    gset_choice_mode(1, 1, GOP_EVENT, GSWITCH_ECHO);
    gmessage(1, "click: turn the camera; 1 ray trace, 2 z-buffer, 0 quit");
    for (int done = 0; !done;) {
        Gint ws, num;
        Gin_class cls;
        gawait_event(png ? 0 : 60, &ws, &cls, &num);
        if (cls == GIN_NONE) {
            done = png; /* batch: the script is over */
            continue;
        }
        if (cls == GIN_LOC) {
            Gloc l;
            gget_loc(&l);
            /* NDC of the click: x -> azimuth in [-pi, pi], y -> elevation in [5, 85] deg */
            az = (l.position.x - 0.5) * 2 * M_PI;
            el = (5 + 80 * l.position.y) * M_PI / 180;
            vpn_from(az, el, vpn);
            fig_scene_view(FIG_SCENE_BOARD, vpn);
            printf("view: azimuth %.1f elevation %.1f deg\n", az * 180 / M_PI, el * 180 / M_PI);
        } else if (cls == GIN_CHOICE) {
            Gin_status s;
            Gint c;
            gget_choice(&s, &c);
            if (s != GIN_STATUS_OK || c == 0 || c == 9) {
                done = 1;
                continue;
            }
            gset_hlhsr_mode(1, c == 1 ? GHLHSR_RAYTRACE : GHLHSR_ZBUFFER);
            printf("HLHSR mode %s\n", c == 1 ? "ray tracing" : "z-buffer");
        }
        fflush(stdout);
        if (png) { /* batch: one file per step */
            static int frame = 0;
            char name[32];
            snprintf(name, sizeof name, "interactive-%03d", ++frame);
            Gint id = 1;
            Gescape_in_data fn = { { 1, &id, 0, NULL, strlen(name), name } };
            gescape(GESC_SET_FILE_NAME, &fn, NULL, NULL);
        }
        gredraw_all_seg_ws(1); /* the segment with the new view or HLHSR mode */
        gupd_ws(1, GFLAG_PERFORM);
    }
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    return 0;
}
