/* SPDX-License-Identifier: MIT */
/*
 * surface.c -- C twin of examples/f77/surface.f (same calls, same single-precision numbers,
 * byte-identical PNG files): the surface z = f(x, y) of a damped ripple on a 32 x 32 grid,
 * each cell two FILL AREA 3 triangles coloured by height, ray traced above a mirror plane.
 * The data stay in the scientist's coordinates: SET WINDOW 3 / SET VIEWPORT 3 map them to
 * NDC3 and the view's up vector is the z axis. A z-buffer preview at a third of the size
 * comes first. Usage: surface_c [SIZE [PREFIX]] (24..2048, default 480); writes
 * PREFIXsurface_zbuffer.png and PREFIXsurface.png.
 */
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef float real; /* the precision of the Fortran binding's REAL arguments */

enum { N = 32, NC = 16, WS = 1 };

static void fill3(int n, const real *x, const real *y, const real *z)
{
    Gpoint3 p[4];
    for (int i = 0; i < n; i++)
        p[i] = (Gpoint3){ x[i], y[i], z[i] };
    Gpoint_list3 l = { n, p };
    gfill_area3(&l);
}

static void round_matrix(Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = (real)m[i][j]; /* the Fortran binding returns REAL matrices */
}

static void escape_ints(int func, int n, const Gint *ints)
{
    Gescape_in_data in = { { n, ints, 0, NULL, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

static void area_props(real amb, real dif, real spec, real spexp)
{
    Garea_props p = { amb, dif, spec, { 1.0f, 1.0f, 1.0f }, spexp, 0.0f, 1.0f };
    gset_area_props(&p);
    gset_back_area_props(&p);
}

static void picture(const char *base, int size, int mode, const real *x, const real *y,
                    real z[N + 1][N + 1])
{
    gopen_ws(WS, "1", GWS_TYPE_PNG);
    Gescape_in_data in = { { 1, (Gint[]){ WS }, 0, NULL, strlen(base), base } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    gset_hlhsr_mode(WS, mode);
    gactivate_ws(WS);
    Glimit win = { 0.0f, 1.0f, 0.0f, 1.0f }, vp = { 0.0f, (real)size, 0.0f, (real)size };
    gset_ws_win(WS, &win);
    gset_ws_vp(WS, &vp);
    /* the scientist's coordinates -> NDC3 (uniform scale 0.2) */
    Glimit3 wn = { -2.5f, 2.5f, -2.5f, 2.5f, -1.5f, 1.5f }, vp3 = { 0.0f, 1.0f, 0.0f, 1.0f,
                                                                   0.2f, 0.8f };
    gset_win3(1, &wn);
    gset_vp3(1, &vp3);
    gsel_norm_tran(1);
    /* camera: z up */
    Gint err = 0;
    Gview_rep3 v = { .clip_limit = { 0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f }, .xy_clip = GIND_CLIP,
                     .back_clip = GIND_CLIP, .front_clip = GIND_CLIP };
    Gpoint3 vrp = { 0.5f, 0.5f, 0.45f };
    Gvec3 vpn = { 1.0f, -1.4f, 1.1f }, vup = { 0.0f, 0.0f, 1.0f };
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, v.ori_matrix);
    Gview_map3 map = { { -0.62f, 0.62f, -0.62f, 0.62f }, { 0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f },
                       GPROJ_PERSPECT, { 0.0f, 0.0f, 2.5f }, 0.0f, -1.0f, 1.0f };
    geval_view_map_matrix3(&map, &err, v.map_matrix);
    round_matrix(v.ori_matrix);
    round_matrix(v.map_matrix);
    gset_view_rep3(WS, 1, &v);
    gset_view_ind(1);
    /* colour map 16..31 from blue (low) to red (high); 14 the mirror */
    for (int c = 0; c < NC; c++) {
        real t = (real)c / (real)(NC - 1);
        Gcolr_rep r = { { 0.15f + 0.8f * t, 0.3f + 0.5f * (1.0f - fabsf(2.0f * t - 1.0f)),
                          0.85f - 0.75f * t } };
        gset_colr_rep(WS, 16 + c, &r);
    }
    Gcolr_rep mirror = { { 0.6f, 0.65f, 0.7f } };
    gset_colr_rep(WS, 14, &mirror);
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 0.3f, 0.3f, 0.3f }, { 0.0f, 0.0f, 0.0f },
                           { 0.0f, 0.0f, -1.0f }, { 1.0f, 0.0f }, 0.0f, 0.0f };
    Glight_src_rep lamp = { GLIGHT_POSITIONAL, { 1.0f, 1.0f, 1.0f }, { 0.3f, 0.1f, 1.4f },
                            { 0.0f, 0.0f, -1.0f }, { 1.0f, 0.0f }, 0.0f, 0.0f };
    gset_light_src_rep(WS, 2, &amb);
    gset_light_src_rep(WS, 3, &lamp);
    if (mode == GHLHSR_RAYTRACE)
        escape_ints(GESC_RT_SAMPLES, 3, (const Gint[]){ WS, 4, 0 });
    gset_fill_int_style(GSTYLE_SOLID);
    Gint on[2] = { 2, 3 };
    Gint_list act = { 2, on }, deact = { 0, NULL };
    gset_light_src_state(&act, &deact);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    gset_back_refl_eq(GREFL_AMB_DIFF_SPEC);
    /* the mirror plane below the surface */
    area_props(0.1f, 0.2f, 0.8f, 100.0f);
    gset_fill_colr_ind(14);
    real px[4] = { -2.5f, 2.5f, 2.5f, -2.5f }, py[4] = { -2.5f, -2.5f, 2.5f, 2.5f },
         pz[4] = { -1.2f, -1.2f, -1.2f, -1.2f };
    fill3(4, px, py, pz);
    /* the surface: two triangles per grid cell, colour by mean height */
    area_props(0.7f, 0.8f, 0.3f, 30.0f);
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            real zm = 0.25f * (((z[j][i] + z[j][i + 1]) + z[j + 1][i + 1]) + z[j + 1][i]);
            int c = (int)((zm + 0.8f) / 1.6f * (real)NC);
            gset_fill_colr_ind(16 + (c < 0 ? 0 : c > NC - 1 ? NC - 1 : c));
            real tx[3] = { x[i], x[i + 1], x[i + 1] }, ty[3] = { y[j], y[j], y[j + 1] },
                 tz[3] = { z[j][i], z[j][i + 1], z[j + 1][i + 1] };
            fill3(3, tx, ty, tz);
            real ux[3] = { x[i], x[i + 1], x[i] }, uy[3] = { y[j], y[j + 1], y[j + 1] },
                 uz[3] = { z[j][i], z[j + 1][i + 1], z[j + 1][i] };
            fill3(3, ux, uy, uz);
        }
    gdeactivate_ws(WS);
    gclose_ws(WS);
}

int main(int argc, char **argv)
{
    int size = 480;
    const char *prefix = argc > 2 ? argv[2] : "";
    if (argc > 1) {
        char *end = NULL;
        long v = strtol(argv[1], &end, 10);
        if (*end || v < 24 || v > 2048) {
            fprintf(stderr, "usage: %s [SIZE (24..2048) [PREFIX]]\n", argv[0]);
            return 2;
        }
        size = (int)v;
    }
    if (strlen(prefix) > 200)
        return 2;
    /* the data: x, y in [-2, 2]; z[j][i] = f(x[i], y[j]) */
    real x[N + 1], y[N + 1], z[N + 1][N + 1];
    for (int i = 0; i <= N; i++) {
        x[i] = -2.0f + 4.0f * (real)i / (real)N;
        y[i] = x[i];
    }
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            real r2 = x[i] * x[i] + y[j] * y[j];
            z[j][i] = 0.8f * cosf(2.5f * sqrtf(r2)) * expf(-0.25f * r2);
        }
    char base[256];
    gopen_gks(NULL, 0);
    snprintf(base, sizeof base, "%ssurface_zbuffer", prefix);
    picture(base, size / 3, GHLHSR_ZBUFFER, x, y, z);
    snprintf(base, sizeof base, "%ssurface", prefix);
    picture(base, size, GHLHSR_RAYTRACE, x, y, z);
    gclose_gks();
    return 0;
}
