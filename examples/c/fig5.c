/* SPDX-License-Identifier: MIT */
/*
 * fig5.c -- Fig. 5: as Fig. 4, with secondary rays clipped to the display volume
 * (ESCAPE GESC_RT_CLIP_SECONDARY): no shadow from the clipped part.
 * Usage: fig5_c [SIZE [PREFIX]] (fig_scene.h); writes PREFIXfig5.png and the previews
 * PREFIXfig5_{none,hiddenline,zbuffer,painter}.png. Fortran twin: examples/f77/fig5.f.
 */
#include "fig_scene.h"
#include <gks.h>

int main(int argc, char **argv)
{
    return fig_run(argc, argv, "fig5", FIG_SCENE_FAN, GHLHSR_RAYTRACE, 1);
}
