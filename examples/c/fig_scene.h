/* SPDX-License-Identifier: MIT */
/*
 * fig_scene.h -- the scenes of the paper's pictures (Urban & Haberstroh 1992, Fig. 2-5) for
 * the C example programs fig2.c ... fig5.c (examples/c/fig_scene.c) and the image tests
 * (tests/images). examples/f77/figlib.f holds the same numbers in the same call order: the
 * C and Fortran programs write byte-identical PNG files (tested).
 *
 * All numbers are single precision (float), exactly what the Fortran REAL arguments carry,
 * and every derived coordinate is computed in float in the same order as figlib.f.
 * Coordinates are NDC3 (normalization transformation 0): the board lies in the plane y = 0.1.
 */
#ifndef FIG_SCENE_H
#define FIG_SCENE_H

/* Scenes: the board scene lit (Fig. 3), the ventilator (Fig. 4/5), the board scene without
 * the lighting model, every area in its flat colour as plain GKS-3D draws it (Fig. 2). */
enum { FIG_SCENE_BOARD = 1, FIG_SCENE_FAN = 2, FIG_SCENE_FLAT = 3 };

/* View (both scenes): EVALUATE VIEW ORIENTATION MATRIX 3 and VIEW MAPPING MATRIX 3. */
static const float FIG_VRP[3] = { 0.5f, 0.3f, 0.5f };
static const float FIG_VPN[3] = { 0.35f, 0.55f, 1.0f };
static const float FIG_VUP[3] = { 0.0f, 1.0f, 0.0f };
static const float FIG_WINDOW[4] = { -0.55f, 0.55f, -0.55f, 0.55f }; /* umin umax vmin vmax */
static const float FIG_PRVP[6] = { 0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f };
static const float FIG_PRP[3] = { 0.0f, 0.0f, 2.5f };
static const float FIG_VPD = 0.0f, FIG_BPD = -1.0f, FIG_FPD = 1.0f;
/* View clip limits in NPC3: the whole unit cube for the board scene; for the fan scene
 * y <= 0.7 cuts off the far (upper in the picture) half of the ventilator. */
static const float FIG_CLIP_BOARD[6] = { 0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f };
static const float FIG_CLIP_FAN[6] = { 0.0f, 1.0f, 0.0f, 0.7f, 0.0f, 1.0f };

/* Lights: 2 ambient, 3 positional (NDC3). Fan scene: the lamp is nearly above the fan. */
static const float FIG_AMBIENT[3] = { 0.25f, 0.25f, 0.25f };
static const float FIG_LAMP_BOARD[3] = { 0.2f, 0.95f, 0.85f };
static const float FIG_LAMP_FAN[3] = { 0.4f, 1.3f, 0.65f };

/* The ventilator: horizontal, centre FIG_FAN_C, FIG_FAN_N blades at the angles whose
 * cosines and sines are tabulated (72 degree steps, starting at 10 degrees), each blade a
 * quadrilateral from radius FIG_FAN_R0 to FIG_FAN_R1, half width (in angle) given by the
 * second table. The hub is a hexagon of radius FIG_FAN_R0. */
enum { FIG_FAN_N = 5 };
static const float FIG_FAN_C[3] = { 0.5f, 0.55f, 0.5f };
static const float FIG_FAN_R0 = 0.06f, FIG_FAN_R1 = 0.34f;
/* Blade i: corner directions (cos, sin) at angle a_i - 12 deg, a_i + 12 deg (inner, radius
 * R0), a_i + 20 deg, a_i - 20 deg (outer, radius R1), a_i = 10 + 72 i degrees, rounded
 * to float. */
static const float FIG_FAN_DIR[FIG_FAN_N][4][2] = {
    { { 0.9993908f, -0.0348995f }, { 0.9271839f, 0.3746066f },
      { 0.8660254f, 0.5000000f }, { 0.9848078f, -0.1736482f } },
    { { 0.3420201f, 0.9396926f }, { -0.0697565f, 0.9975641f },
      { -0.2079117f, 0.9781476f }, { 0.4694716f, 0.8829476f } },
    { { -0.7880108f, 0.6156615f }, { -0.9702957f, 0.2419219f },
      { -0.9945219f, 0.1045285f }, { -0.6946584f, 0.7193398f } },
    { { -0.8290376f, -0.5591929f }, { -0.5299193f, -0.8480481f },
      { -0.4067366f, -0.9135455f }, { -0.8987940f, -0.4383711f } },
    { { 0.2756374f, -0.9612617f }, { 0.6427876f, -0.7660444f },
      { 0.7431448f, -0.6691306f }, { 0.1391731f, -0.9902681f } },
};
/* Hub hexagon directions (cos, sin of 0, 60, ..., 300 degrees). */
static const float FIG_HUB_DIR[6][2] = {
    { 1.0f, 0.0f }, { 0.5f, 0.8660254f }, { -0.5f, 0.8660254f },
    { -1.0f, 0.0f }, { -0.5f, -0.8660254f }, { 0.5f, -0.8660254f },
};

/* Runs one picture program: previews of the scene with the classic HLHSR modes 0-3 on a
 * workstation of a third of the size, then the main picture with HLHSR mode main_mode.
 * clip_secondary: ESCAPE GESC_RT_CLIP_SECONDARY on the main workstation. Arguments
 * (argv): [SIZE [PREFIX]], SIZE = main viewport in pixels (default 480, 24..2048),
 * PREFIX = prepended to the file names. Returns the process exit status: 0, 1 when GKS
 * reported an error (logged to standard error), 2 for bad arguments. */
int fig_run(int argc, char **argv, const char *name, int scene, int main_mode,
            int clip_secondary);

#endif
