/* SPDX-License-Identifier: MIT */
/*
 * ws_vrc.h -- the view orientation transform NDC3 -> VRC3 of the PNG workstation, the one
 * place for it: the ray-tracing mode (ws_raytrace.c) records points and lights in VRC3, and
 * the flat and smooth shading of the classic modes (ws_shade.c) evaluates the same lighting
 * there. Inline, because the tracer's recording calls it per vertex.
 */
#ifndef WS_VRC_H
#define WS_VRC_H
#include "ws_driver.h"
#include "gksrt.h"
#include <math.h>
#include <string.h>

/* Whether m's last row is (0, 0, 0, 1) (the usual view orientation): then ws_vrc_point's w is
 * 1 for every point (0 times a finite coordinate is 0; a non-finite one gives NaN, which it
 * also takes as 1), and ws_vrc_point_affine gives the same values without the divisions. */
static inline int ws_vrc_affine(const Gmatrix3 m)
{
    return m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1;
}

/* The point (x, y, z) through m when ws_vrc_affine(m). */
static inline void ws_vrc_point_affine(const Gmatrix3 m, double x, double y, double z,
                                       double o[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = m[k][0] * x + m[k][1] * y + m[k][2] * z + m[k][3];
}

/* The point (x, y, z) through m, divided by w (w taken as 1 when it is 0 or not finite). */
static inline void ws_vrc_point(const Gmatrix3 m, double x, double y, double z, double o[3])
{
    double w = m[3][0] * x + m[3][1] * y + m[3][2] * z + m[3][3];
    if (w == 0 || !isfinite(w))
        w = 1;
    for (int i = 0; i < 3; i++)
        o[i] = (m[i][0] * x + m[i][1] * y + m[i][2] * z + m[i][3]) / w;
}

/* ws_vrc_point of n points p (3 doubles each) into o (may be p). */
static inline void ws_vrc_points(const Gmatrix3 m, const double *p, size_t n, double *o)
{
    const int affine = ws_vrc_affine(m);
    for (size_t i = 0; i < n; i++) {
        if (affine)
            ws_vrc_point_affine(m, p[3 * i], p[3 * i + 1], p[3 * i + 2], o + 3 * i);
        else
            ws_vrc_point(m, p[3 * i], p[3 * i + 1], p[3 * i + 2], o + 3 * i);
    }
}

/* The direction (x, y, z) through m's linear part. */
static inline void ws_vrc_dir(const Gmatrix3 m, double x, double y, double z, double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = m[i][0] * x + m[i][1] * y + m[i][2] * z;
}

/* Light g of the light source table as the tracer takes it, in VRC3 of view orientation ori
 * (not validated: rt_scene_add_light rejects what it cannot use). */
static inline void ws_vrc_light(const Glight_src_rep *g, const Gmatrix3 ori, rt_light *l)
{
    memset(l, 0, sizeof *l);
    l->type = g->type;
    l->color[0] = g->colr.red;
    l->color[1] = g->colr.green;
    l->color[2] = g->colr.blue;
    ws_vrc_point(ori, g->pos.x, g->pos.y, g->pos.z, l->position);
    ws_vrc_dir(ori, g->dir.delta_x, g->dir.delta_y, g->dir.delta_z, l->direction);
    l->c1 = g->atten[0];
    l->c2 = g->atten[1];
    l->concentration = g->conc_exp;
    l->spread = g->spread_angle;
}
#endif
