/* SPDX-License-Identifier: MIT */
/*
 * fig3.c -- Fig. 3: the same scene ray traced: positional light, shadows, mirror, glass block.
 * Usage: fig3_c [SIZE [PREFIX]] (fig_scene.h); writes PREFIXfig3.png and the previews
 * PREFIXfig3_{none,hiddenline,zbuffer,painter}.png. Fortran twin: examples/f77/fig3.f.
 */
#include "fig_scene.h"
#include <gks.h>

int main(int argc, char **argv)
{
    return fig_run(argc, argv, "fig3", FIG_SCENE_BOARD, GHLHSR_RAYTRACE, 0);
}
