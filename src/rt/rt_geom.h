/* SPDX-License-Identifier: MIT */
/*
 * rt_geom.h -- the normal of a triangle, inline: the scene checks every triangle added with
 * rt_tri_normal_sane (rt_scene.c, a hot path), rt_geom.c gives rt_tri_unit_normal at hits;
 * and the front normal of any committed primitive (rt_prim_ng).
 * Private to src/rt.
 */
#ifndef GKS3D_RT_GEOM_H
#define GKS3D_RT_GEOM_H
#include "rt_internal.h"
#include "rt_shade.h"

#include <math.h>
#include <string.h>

/* The unit normal of the triangle v0 v1 v2 (sane vertices): rt_points_frame and rt_poly_normal
   for 3 points, unrolled, the same operations in the same order (the same bits); 0 if it is
   degenerate. The add-time check of a triangle, and the fallback of rt_tri_unit_normal. */
static inline int rt_tri_normal_sane(const double *v0, const double *v1, const double *v2,
                                     double n[3])
{
    const double *v[3] = {v0, v1, v2};
    double pb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY}, c[3];
    rt_bbox_add(pb, v0);
    rt_bbox_add(pb, v1);
    rt_bbox_add(pb, v2);
    const double ext = fmax(pb[3] - pb[0], fmax(pb[4] - pb[1], pb[5] - pb[2]));
    if (!(ext > 0.0) || !isfinite(ext))
        return 0;
    for (int j = 0; j < 3; j++) {
        c[j] = 0.0;
        c[j] += (v0[j] - pb[j]) / 3.0;
        c[j] += (v1[j] - pb[j]) / 3.0;
        c[j] += (v2[j] - pb[j]) / 3.0;
        c[j] += pb[j];
    }
    n[0] = n[1] = n[2] = 0.0;
    for (int i = 0; i < 3; i++) {
        const double *a = v[i], *b = v[i == 2 ? 0 : i + 1];
        double ax = a[0] - c[0], ay = a[1] - c[1], az = a[2] - c[2];
        double bx = b[0] - c[0], by = b[1] - c[1], bz = b[2] - c[2];
        n[0] += (ay - by) * (az + bz);
        n[1] += (az - bz) * (ax + bx);
        n[2] += (ax - bx) * (ay + by);
    }
    const double tol = 1e-12 * ext * ext;
    const double m = rt_sh_absmax3(n);
    if (m != 0.0 && isfinite(m)) {
        const double x = n[0] / m, y = n[1] / m, z = n[2] / m;
        const double len = m * sqrt(x * x + y * y + z * z);
        if (len > tol && isfinite(len)) {
            for (int i = 0; i < 3; i++)
                n[i] /= len;
            return 1;
        }
    }
    static const int three = 3; /* nearly degenerate: the general fallback */
    double vv[9];
    for (int i = 0; i < 3; i++)
        memcpy(vv + 3 * i, v[i], 3 * sizeof(double));
    return rt_newell_normal(vv, 3, &three, 1, c, ext, n);
}

/* The front unit normal of a committed triangle v0 v1 v2 (one that rt_tri_normal_sane finds
   not degenerate) at its hits and in the grid's build: one cross product of two edges and one
   square root. It points the same way as rt_tri_normal_sane's (both are the Newell normal of
   v0 v1 v2) and differs from it by a few roundings (relative 1e-15). Where the cross product
   is ill-conditioned (the sine of the angle at v0 below 1e-11: a sliver, whose cross product
   loses digits), or its square leaves the range of normal doubles (coordinates beyond about
   1e75 or below 1e-75), rt_tri_normal_sane's scaled computation is taken instead. */
void rt_tri_unit_normal_slow(const double *v0, const double *v1, const double *v2, double n[3]);
static inline void rt_tri_unit_normal(const double *v0, const double *v1, const double *v2,
                                      double n[3])
{
    const double e1[3] = {v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2]};
    const double e2[3] = {v2[0] - v0[0], v2[1] - v0[1], v2[2] - v0[2]};
    const double c0 = e1[1] * e2[2] - e1[2] * e2[1], c1 = e1[2] * e2[0] - e1[0] * e2[2],
                 c2 = e1[0] * e2[1] - e1[1] * e2[0];
    const double l2 = c0 * c0 + c1 * c1 + c2 * c2;
    const double a2 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2];
    const double b2 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
    /* l2 = a2 b2 sin^2: sin > 1e-11, and all three squares normal and finite */
    if (l2 > 1e-22 * (a2 * b2) && l2 > 1e-290 && a2 * b2 < 1e290) {
        const double len = sqrt(l2);
        n[0] = c0 / len;
        n[1] = c1 / len;
        n[2] = c2 / len;
        return;
    }
    rt_tri_unit_normal_slow(v0, v1, v2, n);
}

/* the front unit normal of committed triangle primitive i (rt_geom.c) */
void rt_prim_ng_tri(const rt_scene *sc, size_t i, double ng[3]);
/* the front unit normal of committed primitive i: a triangle's computed (rt_prim_ng_tri), the
   stored one of a quad, polygon or cell array copied inline (no call: the shading of every
   hit asks for it) */
static inline void rt_prim_ng(const rt_scene *sc, size_t i, double ng[3])
{
    if (i < sc->ntri) {
        rt_prim_ng_tri(sc, i, ng);
        return;
    }
    const rt_prim *p = rt_prim_rest(sc, i);
    const double *n;
    switch (p->kind) {
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
#endif
