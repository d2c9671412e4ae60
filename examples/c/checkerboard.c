/* SPDX-License-Identifier: MIT */
/*
 * checkerboard.c -- the paper's first scene (Urban & Haberstroh, Fig. 2 and 3) through the
 * C binding: a checkerboard with a mirror standing on it and a red tile floating above it,
 * lit by an ambient and a positional light. The same scene goes to two PNG workstations:
 * workstation 1 previews it with the z-buffer (HLHSR mode 2, a small viewport = a cheap
 * preview), workstation 2 ray traces it (HLHSR mode 4): shadows and the mirror image appear
 * only there. Writes checkerboard_preview.png and checkerboard_rt.png.
 */
#include <gks.h>

enum { PREVIEW = 1, TRACED = 2 };

static void quad(double x0, double y0, double z0, double ux, double uy, double uz,
                 double vx, double vy, double vz)
{
    Gpoint3 p[4] = { { x0, y0, z0 },
                     { x0 + ux, y0 + uy, z0 + uz },
                     { x0 + ux + vx, y0 + uy + vy, z0 + uz + vz },
                     { x0 + vx, y0 + vy, z0 + vz } };
    Gpoint_list3 l = { 4, p };
    gfill_area3(&l);
}

static void setup_workstation(Gint ws, const char *file, double size, Gint hlhsr,
                              const Gview_rep3 *view)
{
    Glimit win = { 0, 1, 0, 1 }, vp = { 0, size, 0, size };
    Gcolr_rep light_square = { { 0.9, 0.9, 0.85 } }, dark_square = { { 0.15, 0.2, 0.45 } },
              mirror = { { 0.75, 0.75, 0.8 } };
    gopen_ws(ws, file, GWS_TYPE_PNG);
    gactivate_ws(ws);
    gset_ws_win(ws, &win);
    gset_ws_vp(ws, &vp);
    gset_hlhsr_mode(ws, hlhsr);
    gset_view_rep3(ws, 1, view);
    gset_colr_rep(ws, 8, &light_square);
    gset_colr_rep(ws, 9, &dark_square);
    gset_colr_rep(ws, 10, &mirror);
    /* light 2: ambient, light 3: positional, above and in front of the board (NDC3) */
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 0.25, 0.25, 0.25 }, { 0, 0, 0 }, { 0, 0, -1 },
                           { 1, 0 }, 0, 1 };
    Glight_src_rep lamp = { GLIGHT_POSITIONAL, { 1, 1, 1 }, { 0.2, 0.95, 0.85 }, { 0, 0, -1 },
                            { 1, 0 }, 0, 1 };
    gset_light_src_rep(ws, 2, &amb);
    gset_light_src_rep(ws, 3, &lamp);
}

int main(void)
{
    Gint err;
    Gview_rep3 view = { .clip_limit = { 0, 1, 0, 1, 0, 1 }, .xy_clip = GIND_CLIP,
                        .back_clip = GIND_CLIP, .front_clip = GIND_CLIP };
    /* look at the board's centre from the front, above, slightly from the right */
    Gpoint3 vrp = { 0.5, 0.3, 0.5 };
    Gvec3 vpn = { 0.35, 0.55, 1 }, vup = { 0, 1, 0 };
    Gview_map3 map = { { -0.55, 0.55, -0.55, 0.55 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PERSPECT,
                       { 0, 0, 2.5 }, 0, -1, 1 };

    gopen_gks(NULL, 0);
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, view.ori_matrix);
    geval_view_map_matrix3(&map, &err, view.map_matrix);
    setup_workstation(PREVIEW, "checkerboard_preview.png", 160, GHLHSR_ZBUFFER, &view);
    setup_workstation(TRACED, "checkerboard_rt.png", 480, GHLHSR_RAYTRACE, &view);

    gset_view_ind(1);
    Gint lights[2] = { 2, 3 };
    Gint_list on = { 2, lights };
    gset_light_src_state(&on, NULL);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    gset_back_refl_eq(GREFL_AMB_DIFF_SPEC);

    /* the board: 8 x 8 squares in the plane y = 0.1 */
    Garea_props matte = { 1, 0.85, 0.1, { 1, 1, 1 }, 10, 0, 1 };
    gset_area_props(&matte);
    gset_back_area_props(&matte);
    const double s = 0.8 / 8;
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 8; k++) {
            gset_fill_colr_ind((i + k) % 2 ? 9 : 8);
            quad(0.1 + i * s, 0.1, 0.1 + k * s, s, 0, 0, 0, 0, s);
        }

    /* a mirror standing at the back of the board */
    Garea_props mirror = { 0.2, 0.2, 0.8, { 1, 1, 1 }, 50, 0, 1 };
    gset_area_props(&mirror);
    gset_back_area_props(&mirror);
    gset_fill_colr_ind(10);
    quad(0.2, 0.1, 0.15, 0.6, 0, 0, 0, 0.5, 0);

    /* a red tile floating above the board: it casts a shadow */
    gset_area_props(&matte);
    gset_back_area_props(&matte);
    gset_fill_colr_ind(2);
    quad(0.45, 0.35, 0.45, 0.15, 0, 0, 0, 0.02, 0.15);

    gdeactivate_ws(PREVIEW);
    gdeactivate_ws(TRACED);
    gclose_ws(PREVIEW);
    gclose_ws(TRACED);
    gclose_gks();
    return 0;
}
