/* SPDX-License-Identifier: MIT */
/*
 * fig4.c -- Fig. 4: the ventilator above the board, its far half cut off by the view clip
 * in NPC3, ray traced with secondary rays NOT clipped: the clipped part still casts its shadow.
 * Usage: fig4_c [SIZE [PREFIX]] (fig_scene.h); writes PREFIXfig4.png and the previews
 * PREFIXfig4_{none,hiddenline,zbuffer,painter}.png. Fortran twin: examples/f77/fig4.f.
 */
#include "fig_scene.h"
#include <gks.h>

int main(int argc, char **argv)
{
    return fig_run(argc, argv, "fig4", FIG_SCENE_FAN, GHLHSR_RAYTRACE, 0);
}
