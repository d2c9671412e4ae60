/* SPDX-License-Identifier: MIT */
/*
 * surface.c -- C twin of examples/f77/surface.f (same calls, same single-precision numbers,
 * byte-identical PNG files): the surface z = f(x, y) of a damped ripple on a 32 x 32 grid,
 * each cell two FILL AREA 3 triangles coloured by height, ray traced above a mirror plane.
 * The data stay in the scientist's coordinates: SET WINDOW 3 / SET VIEWPORT 3 map them to
 * NDC3 and the view's up vector is the z axis. A z-buffer preview at a third of the size
 * comes first. Then the same surface drawn WITH DATA (FILL AREA 3 WITH DATA, interior shading
 * method normal interpolation): vertex colours by height and vertex normals from the analytic
 * gradient, so that it is shaded smooth. Usage: surface_c [SIZE [PREFIX [png|pdf|svg|ps|eps]]]
 * (24..2048, default 480; the vector types draw a side of SIZE x 0.2 mm); writes
 * PREFIXsurface_zbuffer.png, PREFIXsurface.png, PREFIXsurface_smooth_zbuffer.png and
 * PREFIXsurface_smooth.png.
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

static Gint ws_type = GWS_TYPE_PNG; /* or a vector type (third argument) */

/* The colour of height h: the colour map 16..31 (below) as a continuous function. */
static Grgb height_colour(real h)
{
    real t = (h + 0.8f) / 1.6f;
    t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
    Grgb c = { 0.15f + 0.8f * t, 0.3f + 0.5f * (1.0f - fabsf(2.0f * t - 1.0f)), 0.85f - 0.75f * t };
    return c;
}

/* One triangle WITH DATA: vertex colours by height, vertex normals (-fx, -fy, 1) from the
 * analytic gradient of f. */
static void fill3_data(const real *x, const real *y, const real *z, const real (*g)[2])
{
    Gpoint3 p[3];
    Gcoval c[3];
    Gvec3 n[3];
    for (int i = 0; i < 3; i++) {
        p[i] = (Gpoint3){ x[i], y[i], z[i] };
        c[i].rgb = height_colour(z[i]);
        n[i] = (Gvec3){ -g[i][0], -g[i][1], 1.0f };
    }
    Gfacet_vdata3 vd = { 3, p, c, n };
    gfill_area3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_RGB, NULL, &vd);
}

static void picture(const char *base, int size, int mode, const real *x, const real *y,
                    real z[N + 1][N + 1], real g[N + 1][N + 1][2])
{
    gopen_ws(WS, "1", ws_type);
    Gescape_in_data in = { { 1, (Gint[]){ WS }, 0, NULL, strlen(base), base } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    gset_hlhsr_mode(WS, mode);
    gactivate_ws(WS);
    /* vector types: a side of size x 0.2 mm (their nominal unit in the place of a pixel) */
    real side = ws_type == GWS_TYPE_PNG ? (real)size : (real)size * 0.0002f;
    Glimit win = { 0.0f, 1.0f, 0.0f, 1.0f }, vp = { 0.0f, side, 0.0f, side };
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
    /* the surface: two triangles per grid cell, colour by mean height (flat), or with
       vertex data (g given: colours by height and normals from the gradient, interpolated) */
    area_props(0.7f, 0.8f, 0.3f, 30.0f);
    if (g) {
        gset_int_shad_meth(GSHAD_NORM);
        gset_back_int_shad_meth(GSHAD_NORM);
    }
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            if (g) {
                real tx[3] = { x[i], x[i + 1], x[i + 1] }, ty[3] = { y[j], y[j], y[j + 1] },
                     tz[3] = { z[j][i], z[j][i + 1], z[j + 1][i + 1] };
                const real tg[3][2] = { { g[j][i][0], g[j][i][1] },
                                        { g[j][i + 1][0], g[j][i + 1][1] },
                                        { g[j + 1][i + 1][0], g[j + 1][i + 1][1] } };
                fill3_data(tx, ty, tz, tg);
                real ux[3] = { x[i], x[i + 1], x[i] }, uy[3] = { y[j], y[j + 1], y[j + 1] },
                     uz[3] = { z[j][i], z[j + 1][i + 1], z[j + 1][i] };
                const real ug[3][2] = { { g[j][i][0], g[j][i][1] },
                                        { g[j + 1][i + 1][0], g[j + 1][i + 1][1] },
                                        { g[j + 1][i][0], g[j + 1][i][1] } };
                fill3_data(ux, uy, uz, ug);
                continue;
            }
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
    static const char *const names[] = { "png", "pdf", "svg", "ps", "eps" };
    static const Gint types[] = { GWS_TYPE_PNG, GWS_TYPE_PDF, GWS_TYPE_SVG, GWS_TYPE_PS,
                                  GWS_TYPE_EPS };
    if (argc > 3) {
        ws_type = 0;
        for (int t = 0; t < 5; t++)
            if (strcmp(argv[3], names[t]) == 0)
                ws_type = types[t];
        if (!ws_type) {
            fprintf(stderr, "%s: unknown workstation type %s\n", argv[0], argv[3]);
            return 2;
        }
    }
    if (argc > 1) {
        char *end = NULL;
        long v = strtol(argv[1], &end, 10);
        if (*end || v < 24 || v > 2048) {
            fprintf(stderr, "usage: %s [SIZE (24..2048) [PREFIX [png|pdf|svg|ps|eps]]]\n",
                    argv[0]);
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
    static real g[N + 1][N + 1][2]; /* the gradient (df/dx, df/dy) */
    for (int j = 0; j <= N; j++)
        for (int i = 0; i <= N; i++) {
            real r2 = x[i] * x[i] + y[j] * y[j];
            real r = sqrtf(r2);
            z[j][i] = 0.8f * cosf(2.5f * r) * expf(-0.25f * r2);
            /* (df/dr) / r = 0.8 exp(-r^2/4) (-2.5 sin(2.5 r) / r - 0.5 cos(2.5 r)), with
               sin(2.5 r) / r -> 2.5 at r = 0; df/dx = x (df/dr) / r */
            real s = r > 0.0f ? -2.5f * sinf(2.5f * r) / r : -6.25f;
            real dr = 0.8f * expf(-0.25f * r2) * (s - 0.5f * cosf(2.5f * r));
            g[j][i][0] = dr * x[i];
            g[j][i][1] = dr * y[j];
        }
    char base[256];
    gopen_gks(NULL, 0);
    snprintf(base, sizeof base, "%ssurface_zbuffer", prefix);
    picture(base, size / 3, GHLHSR_ZBUFFER, x, y, z, NULL);
    snprintf(base, sizeof base, "%ssurface", prefix);
    picture(base, size, GHLHSR_RAYTRACE, x, y, z, NULL);
    snprintf(base, sizeof base, "%ssurface_smooth_zbuffer", prefix);
    picture(base, size / 3, GHLHSR_ZBUFFER, x, y, z, g);
    snprintf(base, sizeof base, "%ssurface_smooth", prefix);
    picture(base, size, GHLHSR_RAYTRACE, x, y, z, g);
    gclose_gks();
    return 0;
}
