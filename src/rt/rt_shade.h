/* SPDX-License-Identifier: MIT */
/*
 * rt_shade.h -- local shading shared by the tracer (rt_render.c) and the classic HLHSR modes
 * (src/c/ws/render/ws_shade.c), so that a preview and the traced picture agree where there are
 * no shadows or global effects: the Newell normal of a polygon and the per-light terms of the
 * PHIGS PLUS reflectance equations (gksrt.h, comment above rt_render). Includes no GKS header.
 */
#ifndef GKS3D_RT_SHADE_H
#define GKS3D_RT_SHADE_H

#include "gksrt.h"

#include <math.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Unit plane normal n of a polygon (all loops; v: nv points, 3 doubles each, loop k of
 * counts[k] points): Newell's normal about the point c, or for self-cancelling outlines (a
 * bow tie) the largest fan cross product (v_i - v_0) x (v_i+1 - v_0). 0 if degenerate: the
 * length does not exceed 1e-12 ext^2 (ext: the polygon's size) or is not finite. This is
 * the FRONT side of a gksrt polygon. */
RT_API int rt_newell_normal(const double *v, size_t nv, const int *counts, int nloops,
                            const double c[3], double ext, double n[3]);

/* A non-ambient light seen from point P with unit normal N. */
typedef struct rt_light_term {
    double L[3];   /* unit vector towards the light */
    double dist;   /* distance to it (+inf for a directional light) */
    double NL;     /* N.L */
    double ca;     /* spot light: cosine of the angle to its axis */
} rt_light_term;

static inline double rt_sh_dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double rt_sh_absmax3(const double v[3])
{
    double a = fabs(v[0]), b = fabs(v[1]), c = fabs(v[2]);
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* The terms of light l (validated, unit direction: as rt_scene_add_light keeps it) at P, N.
 * Returns 1 when the light reaches the side N faces (N.L > 0, inside a spot light's cone),
 * else 0 (t then partly set). Lights surely behind are rejected before the square root.
 * Inline, as the helpers below: evaluated per hit and light. */
static inline int rt_light_term_at(const rt_light *l, const double P[3], const double N[3],
                                   rt_light_term *t)
{
    double *L = t->L;
    t->dist = INFINITY;
    t->ca = 0.0;
    if (l->type == RT_LIGHT_DIRECTIONAL) {
        for (int c = 0; c < 3; c++)
            L[c] = -l->direction[c];
    } else {
        for (int c = 0; c < 3; c++)
            L[c] = l->position[c] - P[c];
        /* light surely behind the surface, found before the square root and divisions:
           N.L computed below is then < 0 as well (both dot products have relative errors
           ~1e-16 of S = sum |N_c L_c|, far below the margin 1e-12 S; S > 1e-250 |L| keeps
           the terms N_c L_c / dist out of the subnormal range where errors are absolute) */
        double nl = rt_sh_dot3(N, L);
        double S = fabs(N[0] * L[0]) + fabs(N[1] * L[1]) + fabs(N[2] * L[2]);
        if (nl < -1e-12 * S && S > 1e-250 * rt_sh_absmax3(L))
            return 0;
        t->dist = sqrt(rt_sh_dot3(L, L));
        if (!(t->dist > 0.0) || !isfinite(t->dist))
            return 0;
        for (int c = 0; c < 3; c++)
            L[c] /= t->dist;
    }
    t->NL = rt_sh_dot3(N, L);
    if (!(t->NL > 0.0))
        return 0;
    if (l->type == RT_LIGHT_SPOT) {
        t->ca = -rt_sh_dot3(L, l->direction);
        if (t->ca < cos(l->spread) || !(t->ca > 0.0))
            return 0;
    }
    return 1;
}

/* attenuation 1/(c1 + c2 dist) of a positional or spot light, 1 for a directional one */
static inline double rt_light_att(const rt_light *l, const rt_light_term *t)
{
    return l->type == RT_LIGHT_DIRECTIONAL ? 1.0 : 1.0 / (l->c1 + l->c2 * t->dist);
}

/* spot factor ca^concentration of a spot light, 1 for the others */
static inline double rt_light_spot(const rt_light *l, const rt_light_term *t)
{
    return l->type == RT_LIGHT_SPOT ? pow(t->ca, l->concentration) : 1.0;
}

/* specular term ks max(0, R.E)^se, R = 2 (N.L) N - L the mirrored light, E the unit vector
 * towards the eye */
static inline double rt_spec_term(const double N[3], const rt_light_term *t, const double E[3],
                                  double ks, double se)
{
    double R[3];
    for (int c = 0; c < 3; c++)
        R[c] = 2.0 * t->NL * N[c] - t->L[c];
    double RE = rt_sh_dot3(R, E);
    return RE > 0.0 ? ks * pow(RE, se) : 0.0;
}

#ifdef __cplusplus
}
#endif
#endif
