/* SPDX-License-Identifier: MIT */
/*
 * rt_geom.c -- the front normal of a committed primitive (rt_prim_ng), at its hits and in
 * the grid's build (rt_trace.c, rt_render.c, rt_build.c). A leaf below the scene and the
 * grid, so that neither calls the other back.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"

#include <math.h>
#include <string.h>

void rt_prim_ng(const rt_scene *sc, size_t i, double ng[3])
{
    const rt_prim *p = &sc->prim[i];
    const double *n;
    switch (p->kind) {
    case RT_KIND_TRI:
        (void)rt_tri_normal_sane(rt_tri_vert(sc, p->data, 0), rt_tri_vert(sc, p->data, 1),
                                 rt_tri_vert(sc, p->data, 2), ng);
        return;
    case RT_KIND_QUAD:
        n = sc->quad[p->data].n;
        break;
    case RT_KIND_POLY:
        n = sc->poly[p->data].n;
        break;
    default:
        n = sc->cell[p->data].n;
        break;
    }
    memcpy(ng, n, 3 * sizeof(double));
}
