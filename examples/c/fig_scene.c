/* SPDX-License-Identifier: MIT */
/*
 * fig_scene.c -- the paper's pictures (Fig. 2-5) through the C binding: scenes, workstation
 * set-up and the preview-then-render loop shared by fig2.c ... fig5.c. The Fortran 77
 * programs (examples/f77/figlib.f) make the same calls with the same single-precision
 * numbers in the same order, so both write byte-identical PNG files.
 *
 * A program previews its scene with each classic HLHSR mode (none, hidden line, z-buffer,
 * painter) on a workstation of a third of the size -- a low-resolution preview is just a
 * smaller workstation viewport -- and then draws the main picture (classic or ray traced).
 * A mode the workstation lacks (SET HLHSR MODE reports error 511) is skipped with a note.
 */
#define _POSIX_C_SOURCE 200809L
#include "fig_scene.h"
#include <gks.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef float real; /* the precision of the Fortran binding's REAL arguments */

enum { WS = 1, MAX_NAME = 300 };

/* The last error reported and the number of real errors (an example's own ERROR HANDLING;
 * C handlers get no user data). */
static Gint last_error;
static int n_errors;

static void error_handler(Gint err_num, Gint func_num, const char *err_file)
{
    last_error = err_num;
    if (err_num == 511 && func_num == GFN_SHRM)
        return; /* mode not available: the program skips that preview */
    n_errors++;
    gerr_hand(err_num, func_num, err_file);
}

static void fill3(int n, const real *x, const real *y, const real *z)
{
    Gpoint3 p[8];
    for (int i = 0; i < n; i++)
        p[i] = (Gpoint3){ x[i], y[i], z[i] };
    Gpoint_list3 l = { n, p };
    gfill_area3(&l);
}

/* Parallelogram p, p+u, p+u+v, p+v (front side: normal u x v). */
static void quad(real px, real py, real pz, real ux, real uy, real uz, real vx, real vy, real vz)
{
    real x[4] = { px, px + ux, (px + ux) + vx, px + vx };
    real y[4] = { py, py + uy, (py + uy) + vy, py + vy };
    real z[4] = { pz, pz + uz, (pz + uz) + vz, pz + vz };
    fill3(4, x, y, z);
}

/* SET AREA PROPERTIES and SET BACK AREA PROPERTIES to the same values. */
static void area_props(real amb, real dif, real spec, real spexp, real transp, real refr)
{
    Garea_props p = { amb, dif, spec, { 1.0f, 1.0f, 1.0f }, spexp, transp, refr };
    gset_area_props(&p);
    gset_back_area_props(&p);
}

/* The board: 8 x 8 squares of side 0.1 in the plane y = 0.1, colours 8 and 9. */
static void board(void)
{
    const real s = 0.1f;
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 8; k++) {
            gset_fill_colr_ind((i + k) % 2 ? 9 : 8);
            quad(0.1f + (real)i * s, 0.1f, 0.1f + (real)k * s, s, 0.0f, 0.0f, 0.0f, 0.0f, s);
        }
}

/* Fig. 2/3: board, a mirror standing at its back, a red tile floating above it and a glass
 * block (transparent, refraction index 1.5) on it; lit (Fig. 3) or flat (Fig. 2). */
static void scene_board(int lit)
{
    gset_refl_eq(lit ? GREFL_AMB_DIFF_SPEC : GREFL_NONE);
    gset_back_refl_eq(lit ? GREFL_AMB_DIFF_SPEC : GREFL_NONE);
    area_props(1.0f, 0.85f, 0.1f, 10.0f, 0.0f, 1.0f);
    board();
    area_props(0.2f, 0.2f, 0.8f, 50.0f, 0.0f, 1.0f);
    gset_fill_colr_ind(10);
    quad(0.2f, 0.1f, 0.15f, 0.6f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f);
    area_props(1.0f, 0.85f, 0.1f, 10.0f, 0.0f, 1.0f);
    gset_fill_colr_ind(2);
    quad(0.3f, 0.35f, 0.45f, 0.15f, 0.0f, 0.0f, 0.0f, 0.02f, 0.15f);
    /* the glass block [x0, x0+a] x [y0, y0+h] x [z0, z0+a], faces with outward normals */
    const real x0 = 0.55f, y0 = 0.102f, z0 = 0.5f, a = 0.2f, h = 0.12f;
    area_props(0.1f, 0.1f, 0.2f, 80.0f, 0.85f, 1.5f);
    gset_fill_colr_ind(11);
    quad(x0, y0, z0, a, 0.0f, 0.0f, 0.0f, 0.0f, a);                 /* bottom, -y */
    quad(x0, y0 + h, z0, 0.0f, 0.0f, a, a, 0.0f, 0.0f);             /* top, +y */
    quad(x0, y0, z0 + a, a, 0.0f, 0.0f, 0.0f, h, 0.0f);             /* front, +z */
    quad(x0, y0, z0, 0.0f, h, 0.0f, a, 0.0f, 0.0f);                 /* back, -z */
    quad(x0 + a, y0, z0, 0.0f, h, 0.0f, 0.0f, 0.0f, a);             /* right, +x */
    quad(x0, y0, z0, 0.0f, 0.0f, a, 0.0f, h, 0.0f);                 /* left, -x */
}

/* Fig. 4/5: board and a horizontal ventilator above it (hub and blades, colours 13, 12). */
static void scene_fan(void)
{
    gset_refl_eq(GREFL_AMB_DIFF);
    gset_back_refl_eq(GREFL_AMB_DIFF);
    area_props(1.0f, 0.85f, 0.0f, 1.0f, 0.0f, 1.0f);
    board();
    const real *c = FIG_FAN_C;
    real x[6], y[6], z[6];
    area_props(0.9f, 0.8f, 0.0f, 1.0f, 0.0f, 1.0f);
    gset_fill_colr_ind(12);
    for (int i = 0; i < FIG_FAN_N; i++) {
        for (int k = 0; k < 4; k++) {
            real r = k < 2 ? FIG_FAN_R0 : FIG_FAN_R1;
            x[k] = c[0] + r * FIG_FAN_DIR[i][k][0];
            y[k] = c[1];
            z[k] = c[2] + r * FIG_FAN_DIR[i][k][1];
        }
        fill3(4, x, y, z);
    }
    gset_fill_colr_ind(13);
    for (int k = 0; k < 6; k++) {
        x[k] = c[0] + FIG_FAN_R0 * FIG_HUB_DIR[k][0];
        y[k] = c[1] + 0.004f;
        z[k] = c[2] + FIG_FAN_R0 * FIG_HUB_DIR[k][1];
    }
    fill3(6, x, y, z);
}

static void colour(int i, real r, real g, real b)
{
    Gcolr_rep c = { { r, g, b } };
    gset_colr_rep(WS, i, &c);
}

static void round_matrix(Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = (real)m[i][j]; /* the Fortran binding returns REAL matrices */
}

/* View 1: the paper's camera above the front right of the board; clip limits per scene. */
static void view(const real *clip)
{
    Gint err = 0;
    Gview_rep3 v = { .clip_limit = { clip[0], clip[1], clip[2], clip[3], clip[4], clip[5] },
                     .xy_clip = GIND_CLIP, .back_clip = GIND_CLIP, .front_clip = GIND_CLIP };
    Gpoint3 vrp = { FIG_VRP[0], FIG_VRP[1], FIG_VRP[2] };
    Gvec3 vpn = { FIG_VPN[0], FIG_VPN[1], FIG_VPN[2] };
    Gvec3 vup = { FIG_VUP[0], FIG_VUP[1], FIG_VUP[2] };
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, v.ori_matrix);
    Gview_map3 map = { { FIG_WINDOW[0], FIG_WINDOW[1], FIG_WINDOW[2], FIG_WINDOW[3] },
                       { FIG_PRVP[0], FIG_PRVP[1], FIG_PRVP[2], FIG_PRVP[3], FIG_PRVP[4],
                         FIG_PRVP[5] },
                       GPROJ_PERSPECT, { FIG_PRP[0], FIG_PRP[1], FIG_PRP[2] },
                       FIG_VPD, FIG_BPD, FIG_FPD };
    geval_view_map_matrix3(&map, &err, v.map_matrix);
    round_matrix(v.ori_matrix);
    round_matrix(v.map_matrix);
    gset_view_rep3(WS, 1, &v);
}

static void light(int ind, int type, const real *colr, const real *pos)
{
    Glight_src_rep l = { type, { colr[0], colr[1], colr[2] }, { pos[0], pos[1], pos[2] },
                         { 0.0f, 0.0f, -1.0f }, { 1.0f, 0.0f }, 0.0f, 0.0f };
    gset_light_src_rep(WS, ind, &l);
}

static void escape_ints(int func, int n, Gint v1, Gint v2)
{
    Gint ints[3] = { WS, v1, v2 };
    Gescape_in_data in = { { n + 1, ints, 0, NULL, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

/* One picture: file base name, viewport size in pixels, HLHSR mode. 0 = written,
 * 1 = skipped (mode not available). */
static int picture(const char *base, int size, int mode, int scene, int clip_secondary)
{
    static const real white[3] = { 1.0f, 1.0f, 1.0f }, origin[3] = { 0.0f, 0.0f, 0.0f };
    gopen_ws(WS, "1", GWS_TYPE_PNG);
    Gescape_in_data in = { { 1, (Gint[]){ WS }, 0, NULL, strlen(base), base } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    last_error = 0;
    gset_hlhsr_mode(WS, mode);
    if (last_error == 511) {
        gclose_ws(WS);
        char path[MAX_NAME + 8];
        snprintf(path, sizeof path, "%s.png", base);
        remove(path); /* the background picture of the unused workstation */
        printf("HLHSR mode %d not available: %s skipped\n", mode, path);
        return 1;
    }
    gactivate_ws(WS);
    /* colour 0 first: the picture is cleared to it when the viewport sets its size */
    colour(0, 0.1f, 0.11f, 0.14f);
    colour(2, 0.85f, 0.15f, 0.1f);
    colour(8, 0.9f, 0.9f, 0.85f);
    colour(9, 0.15f, 0.2f, 0.45f);
    colour(10, 0.75f, 0.75f, 0.8f);
    colour(11, 0.8f, 0.95f, 0.9f);
    colour(12, 0.9f, 0.6f, 0.15f);
    colour(13, 0.3f, 0.3f, 0.3f);
    Glimit win = { 0.0f, 1.0f, 0.0f, 1.0f }, vp = { 0.0f, (real)size, 0.0f, (real)size };
    gset_ws_win(WS, &win);
    gset_ws_vp(WS, &vp);
    view(scene == FIG_SCENE_FAN ? FIG_CLIP_FAN : FIG_CLIP_BOARD);
    light(2, GLIGHT_AMBIENT, FIG_AMBIENT, origin);
    light(3, GLIGHT_POSITIONAL, white, scene == FIG_SCENE_FAN ? FIG_LAMP_FAN : FIG_LAMP_BOARD);
    if (mode == GHLHSR_RAYTRACE) {
        escape_ints(GESC_RT_SAMPLES, 2, 4, 0); /* 2 x 2 samples per pixel */
        escape_ints(GESC_RT_CLIP_SECONDARY, 1, clip_secondary, 0);
    }
    gset_view_ind(1);
    gset_fill_int_style(GSTYLE_SOLID);
    Gint on[2] = { 2, 3 };
    Gint_list act = { 2, on }, deact = { 0, NULL };
    gset_light_src_state(&act, &deact);
    if (scene == FIG_SCENE_FAN)
        scene_fan();
    else
        scene_board(scene == FIG_SCENE_BOARD);
    gdeactivate_ws(WS);
    gclose_ws(WS);
    return 0;
}

int fig_run(int argc, char **argv, const char *name, int scene, int main_mode,
            int clip_secondary)
{
    static const int modes[] = { GHLHSR_NONE, GHLHSR_HIDDEN_LINE, GHLHSR_ZBUFFER,
                                 GHLHSR_PAINTER };
    static const char *const mode_names[] = { "none", "hiddenline", "zbuffer", "painter" };
    int size = 480;
    const char *prefix = argc > 2 ? argv[2] : "";
    if (argc > 1) {
        char *end = NULL;
        long v = strtol(argv[1], &end, 10);
        if (*end || v < 24 || v > 2048) {
            fprintf(stderr, "usage: %s [SIZE (24..2048, default 480) [PREFIX]]\n", argv[0]);
            return 2;
        }
        size = (int)v;
    }
    if (strlen(prefix) > MAX_NAME - 40) {
        fprintf(stderr, "%s: PREFIX too long\n", argv[0]);
        return 2;
    }
    gset_err_hand(error_handler, NULL);
    gopen_gks(NULL, 0);
    char base[MAX_NAME];
    for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        snprintf(base, sizeof base, "%s%s_%s", prefix, name, mode_names[m]);
        picture(base, size / 3, modes[m], scene, 0);
    }
    snprintf(base, sizeof base, "%s%s", prefix, name);
    picture(base, size, main_mode, scene, clip_secondary);
    gclose_gks();
    return n_errors ? 1 : 0;
}
