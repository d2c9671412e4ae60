/* SPDX-License-Identifier: MIT */
/*
 * fig2.c -- Fig. 2: the checkerboard scene drawn the conventional GKS way: HLHSR mode
 * z-buffer, no lighting model (reflectance equation NONE: flat colours).
 * Usage: fig2_c [SIZE [PREFIX]] (fig_scene.h); writes PREFIXfig2.png and the previews
 * PREFIXfig2_{none,hiddenline,zbuffer,painter}.png. Fortran twin: examples/f77/fig2.f.
 */
#include "fig_scene.h"
#include <gks.h>

int main(int argc, char **argv)
{
    return fig_run(argc, argv, "fig2", FIG_SCENE_FLAT, GHLHSR_ZBUFFER, 0);
}
