/* SPDX-License-Identifier: MIT */
/*
 * ws_shade.h -- flat (per-facet) shading of planar areas for the classic HLHSR modes, with
 * the PHIGS PLUS reflectance equations, area properties and light sources (issue 5: "so a
 * previewed picture and the ray-traced one agree in local lighting"). The formulas are the ray
 * tracer's local shading (src/rt/gksrt.h, comment above rt_render) without shadows and
 * without secondary rays, evaluated once per area at the vertex centroid, in VRC3 like the
 * tracer: points, lights and the eye go through the view orientation matrix of the area's view.
 */
#ifndef WS_SHADE_H
#define WS_SHADE_H
#include "ws_driver.h"
#include "gksrt.h"

/* Flat shading of one area as an affine map of its diffuse colour Od:
 * colour = clamp(mul * Od + add, 0, 1) per component. mul/add do not depend on Od, so one
 * evaluation serves all cells of a CELL ARRAY. */
typedef struct ws_shade {
    double mul[3], add[3];
    int side;                /* 0: the front side faces the eye, 1: the back side */
} ws_shade;

/* Evaluates the flat shading of area primitive prim (GKS_PRIM_FILL_AREA with n_loops >= 1,
 * points in NDC3; or GKS_PRIM_CELL_ARRAY, its parallelogram P, R, Q) on workstation ws: the
 * facet normal (Newell, the tracer's front side) and vertex centroid in VRC3 of prim's view,
 * the eye (projection reference point or direction, from the view mapping matrix), the front or
 * back area properties and reflectance equation by the side the eye sees, and the lights of
 * ws's light source table active in prim->light_mask. Reflectance equation NONE (or an area
 * that is degenerate, or a view whose eye cannot be found): mul = 1, add = 0, i.e. the flat
 * colour. Returns 0, or 1 for the degenerate cases (sh is then the identity). */
int ws_shade_area(const gks_ws *ws, const gks_prim *prim, ws_shade *sh);

/* The shaded colour of diffuse colour od: clamp(mul*od + add) into [0,1] (NaN -> 0). */
Grgb ws_shade_apply(const ws_shade *sh, const Grgb *od);

/* Shading at points of a smooth area (interior shading methods COLOUR and NORMAL): the same
 * equations at point P with normal N, both in VRC3 of the area's view. */
typedef struct ws_shade_ctx {
    int persp;
    double eye[3];           /* VRC3 eye point (persp) or unit direction towards the eye */
    int eq[2];
    Garea_props pr[2];
    int nl;
    rt_light l[GKS_MAX_LIGHT_IND];   /* VRC3 */
} ws_shade_ctx;

/* The context of prim on ws; 1 if its view has no usable eye (then flat colours). */
int ws_shade_ctx_init(const gks_ws *ws, const gks_prim *prim, ws_shade_ctx *c);
/* The colour at P with unit front normal N (turned to the eye's side, which selects the
 * front or back properties) of diffuse colour od, clamped to [0,1]. */
void ws_shade_point(const ws_shade_ctx *c, const double P[3], const double N[3],
                    const double od[3], float out[3]);
/* The view orientation of prim's view: NDC3 point -> VRC3, and NDC3 normal -> VRC3 (by the
 * cofactor matrix, renormalised; 0 for a degenerate normal). */
void ws_shade_vrc_point(const gks_ws *ws, const gks_prim *prim, const Gpoint3 *p, double o[3]);
int ws_shade_vrc_normal(const gks_ws *ws, const gks_prim *prim, const Gvec3 *n, double o[3]);
#endif
