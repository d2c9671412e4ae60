/* SPDX-License-Identifier: MIT */
/*
 * ws_shade.c -- flat shading of planar areas (ws_shade.h): the ray tracer's local shading
 * (src/rt/rt_shade.h, the Newell normal and the per-light terms both use) without shadow
 * rays, at the vertex centroid:
 *   I = sum(ambient) ka*Od*La + sum(other) att*spot*[kd*Od*Lc*max(0,N.L) + ks*Cs*Lc*max(0,R.E)^se]
 * (specular term for AMB_DIFF_SPEC only), N the facet normal turned towards the eye, E the unit
 * vector towards the eye, att = 1/(c1 + c2*d), spot = cos^concentration inside the spread.
 * Lights are validated as gksrt validates them (a light the tracer rejects is left out here too).
 */
#include "ws_shade.h"
#include "ws_vrc.h"
#include "rt_shade.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include <math.h>
#include <string.h>

#define SHADE_PI 3.14159265358979323846

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static int unit3(double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0) || !isfinite(m))
        return 0;
    double t[3] = { v[0] / m, v[1] / m, v[2] / m };
    double l = sqrt(dot3(t, t));
    for (int i = 0; i < 3; i++)
        v[i] = t[i] / l;
    return 1;
}

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* Newell normal (all loops) about the centroid c, or for self-cancelling outlines the largest
 * fan cross product: the tracer's front side (rt_newell_normal, shared). 0 if degenerate. */
static int facet_normal(const double (*v)[3], size_t nv, const int *counts, int nloops,
                        const double c[3], double n[3])
{
    double ext = 0;
    for (size_t i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            ext = fmax(ext, fabs(v[i][k] - c[k]));
    return rt_newell_normal(&v[0][0], nv, counts, nloops, c, ext, n);
}

/* A light of the table in VRC3, validated as gksrt does; 0 if the tracer would reject it. */
typedef rt_light vlight;

static int light_vrc(const Glight_src_rep *g, const Gmatrix3 ori, vlight *l)
{
    ws_vrc_light(g, ori, l);
    if (l->type < GLIGHT_AMBIENT || l->type > GLIGHT_SPOT || !finite3(l->color) ||
        l->color[0] < 0 || l->color[1] < 0 || l->color[2] < 0)
        return 0;
    if ((l->type == GLIGHT_DIRECTIONAL || l->type == GLIGHT_SPOT) &&
        (!finite3(l->direction) || !unit3(l->direction)))
        return 0;
    if ((l->type == GLIGHT_POSITIONAL || l->type == GLIGHT_SPOT) &&
        (!finite3(l->position) || !isfinite(l->c1) || !isfinite(l->c2) || l->c1 < 0 ||
         l->c2 < 0 || !(l->c1 + l->c2 > 0)))
        return 0;
    if (l->type == GLIGHT_SPOT &&
        (!isfinite(l->concentration) || l->concentration < 0 || !isfinite(l->spread) ||
         l->spread <= 0 || l->spread > SHADE_PI + 1e-12))
        return 0;
    return 1;
}

/* Adds light l's contribution at point P with normal N (facing the eye E) to sh: the tracer's
 * per-light terms (rt_shade.h) without the shadow ray. */
static void add_light(ws_shade *sh, const vlight *l, int eq, const Garea_props *pr,
                      const double P[3], const double N[3], const double E[3])
{
    if (l->type == GLIGHT_AMBIENT) {
        for (int c = 0; c < 3; c++)
            sh->mul[c] += pr->ambient_coef * l->color[c];
        return;
    }
    if (eq < GREFL_AMB_DIFF)
        return;
    rt_light_term t;
    if (!rt_light_term_at(l, P, N, &t))
        return;
    double f = rt_light_att(l, &t);
    f *= rt_light_spot(l, &t);
    double spec = 0;
    if (eq == GREFL_AMB_DIFF_SPEC && pr->specular_coef > 0)
        spec = rt_spec_term(N, &t, E, pr->specular_coef, pr->specular_exp);
    const double cs[3] = { pr->specular_colr.red, pr->specular_colr.green, pr->specular_colr.blue };
    for (int c = 0; c < 3; c++) {
        sh->mul[c] += f * l->color[c] * pr->diffuse_coef * t.NL;
        sh->add[c] += f * l->color[c] * spec * cs[c];
    }
}

static void identity(ws_shade *sh)
{
    for (int c = 0; c < 3; c++) {
        sh->mul[c] = 1;
        sh->add[c] = 0;
    }
    sh->side = 0;
}

/* The area's vertices in VRC3 into v (room for cap; a cell array needs 4), its loops. */
static int area_vertices(const gks_prim *prim, const Gmatrix3 ori, double (*v)[3], size_t cap,
                         size_t *nv, int *nloops, const int **counts)
{
    static const int four = 4;
    if (prim->kind == GKS_PRIM_CELL_ARRAY) {
        const Gpoint3 *p = &prim->cell_p, *q = &prim->cell_q, *r = &prim->cell_r;
        const Gpoint3 c[4] = { *p, *r, *q, { p->x + q->x - r->x, p->y + q->y - r->y,
                                             p->z + q->z - r->z } };
        for (int i = 0; i < 4; i++)
            ws_vrc_point(ori, c[i].x, c[i].y, c[i].z, v[i]);
        *nv = 4;
        *nloops = 1;
        *counts = &four;
        return 1;
    }
    if (prim->kind != GKS_PRIM_FILL_AREA || prim->n_points < 3 || prim->n_loops < 1 ||
        !prim->pts || !prim->loop_counts || (size_t)prim->n_points > cap)
        return 0;
    size_t total = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        if (prim->loop_counts[k] < 1)
            return 0;
        total += (size_t)prim->loop_counts[k];
    }
    if (total != (size_t)prim->n_points)
        return 0;
    for (int i = 0; i < prim->n_points; i++)
        ws_vrc_point(ori, prim->pts[i].x, prim->pts[i].y, prim->pts[i].z, v[i]);
    *nv = (size_t)prim->n_points;
    *nloops = prim->n_loops;
    *counts = prim->loop_counts;
    return 1;
}

int ws_shade_area(const gks_ws *ws, const gks_prim *prim, ws_shade *sh)
{
    identity(sh);
    if (prim->refl_eq[0] == GREFL_NONE && prim->refl_eq[1] == GREFL_NONE)
        return 0; /* the common unlit case: nothing to compute */
    int vi = prim->view_ind >= 0 && prim->view_ind <= GKS_MAX_VIEW_IND ? prim->view_ind : 0;
    const Gview_rep3 *view = &ws->views[vi];
    /* Vertices in VRC3: a fixed buffer covers typical areas, larger ones are allocated. */
    enum { CAP = 256 };
    double buf[CAP][3];
    double (*v)[3] = buf;
    size_t nv = 0;
    int nloops = 0;
    const int *counts = NULL;
    double (*heap)[3] = NULL;
    if (prim->kind == GKS_PRIM_FILL_AREA && prim->n_points > CAP) {
        heap = gks_alloc_array((size_t)prim->n_points, sizeof *heap);
        if (!heap)
            return 1;
        v = heap;
    }
    size_t cap = heap ? (size_t)prim->n_points : CAP;
    int ok = area_vertices(prim, view->ori_matrix, v, cap, &nv, &nloops, &counts);
    double c[3] = { 0, 0, 0 }, n[3];
    if (ok) {
        for (size_t i = 0; i < nv; i++)
            for (int k = 0; k < 3; k++)
                c[k] += v[i][k] / (double)nv;
        ok = finite3(c) && facet_normal((const double (*)[3])v, nv, counts, nloops, c, n);
    }
    gks_free(heap);
    if (!ok)
        return 1;
    double eye[3], E[3];
    int persp = 0;
    if (gks_xform_view_camera(view->map_matrix, eye, &persp))
        return 1;
    for (int k = 0; k < 3; k++)
        E[k] = persp ? eye[k] - c[k] : eye[k];
    if (!unit3(E))
        return 1;
    int side = dot3(n, E) < 0;
    if (side)
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    int eq = prim->refl_eq[side];
    sh->side = side;
    if (eq <= GREFL_NONE || eq > GREFL_AMB_DIFF_SPEC)
        return 0;
    const Garea_props *pr = &prim->area_props[side];
    for (int c2 = 0; c2 < 3; c2++)
        sh->mul[c2] = 0;
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++) {
        if (!((prim->light_mask >> i) & 1) || !ws->light_defined[i])
            continue;
        vlight l;
        if (light_vrc(&ws->lights[i], view->ori_matrix, &l))
            add_light(sh, &l, eq, pr, c, n, E);
    }
    return 0;
}

static double clamp01(double v) { return !(v > 0) ? 0 : v > 1 ? 1 : v; }

Grgb ws_shade_apply(const ws_shade *sh, const Grgb *od)
{
    return (Grgb){ clamp01(sh->mul[0] * od->red + sh->add[0]),
                   clamp01(sh->mul[1] * od->green + sh->add[1]),
                   clamp01(sh->mul[2] * od->blue + sh->add[2]) };
}

static const Gview_rep3 *view_of(const gks_ws *ws, const gks_prim *prim)
{
    int vi = prim->view_ind >= 0 && prim->view_ind <= GKS_MAX_VIEW_IND ? prim->view_ind : 0;
    return &ws->views[vi];
}

void ws_shade_vrc_point(const gks_ws *ws, const gks_prim *prim, const Gpoint3 *p, double o[3])
{
    ws_vrc_point(view_of(ws, prim)->ori_matrix, p->x, p->y, p->z, o);
}

int ws_shade_vrc_normal(const gks_ws *ws, const gks_prim *prim, const Gvec3 *n, double o[3])
{
    double nm[3][3];
    const double v[3] = { n->delta_x, n->delta_y, n->delta_z };
    o[0] = o[1] = o[2] = 0;
    return !gks_xform_normal_matrix(view_of(ws, prim)->ori_matrix, nm) &&
           gks_xform_normal(nm, v, o);
}

int ws_shade_ctx_init(const gks_ws *ws, const gks_prim *prim, ws_shade_ctx *c)
{
    memset(c, 0, sizeof *c);
    const Gview_rep3 *view = view_of(ws, prim);
    if (gks_xform_view_camera(view->map_matrix, c->eye, &c->persp))
        return 1;
    if (!c->persp && !unit3(c->eye))
        return 1;
    for (int s = 0; s < 2; s++) {
        c->eq[s] = prim->refl_eq[s];
        c->pr[s] = prim->area_props[s];
    }
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++) {
        if (!((prim->light_mask >> i) & 1) || !ws->light_defined[i])
            continue;
        if (light_vrc(&ws->lights[i], view->ori_matrix, &c->l[c->nl]))
            c->nl++;
    }
    return 0;
}

void ws_shade_point(const ws_shade_ctx *c, const double P[3], const double N[3],
                    const double od[3], float out[3])
{
    double E[3], n[3] = { N[0], N[1], N[2] };
    for (int k = 0; k < 3; k++)
        E[k] = c->persp ? c->eye[k] - P[k] : c->eye[k];
    int side = 0;
    if (unit3(E) && dot3(n, E) < 0) {
        side = 1;
        for (int k = 0; k < 3; k++)
            n[k] = -n[k];
    }
    const int eq = c->eq[side];
    if (eq <= GREFL_NONE || eq > GREFL_AMB_DIFF_SPEC) {
        for (int k = 0; k < 3; k++)
            out[k] = (float)clamp01(od[k]);
        return;
    }
    ws_shade sh;
    for (int k = 0; k < 3; k++)
        sh.mul[k] = sh.add[k] = 0;
    for (int i = 0; i < c->nl; i++)
        add_light(&sh, &c->l[i], eq, &c->pr[side], P, n, E);
    for (int k = 0; k < 3; k++)
        out[k] = (float)clamp01(sh.mul[k] * od[k] + sh.add[k]);
}
