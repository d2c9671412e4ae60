/* SPDX-License-Identifier: MIT */
/*
 * rt_smooth.c -- smooth areas: per-vertex normals and colours (rt_scene_add_polygon_data) and
 * their interpolation at a hit. Triangles: barycentric coordinates. Other polygons: mean value
 * coordinates (Hormann and Floater 2006, "Mean value coordinates for arbitrary planar
 * polygons"; every loop of a set contributes its edges), which reduce to linear interpolation
 * along each edge, so two areas that share an edge and its vertex data agree along it.
 * Coordinates are taken in the projection of the plane that drops its dominant axis.
 * The shadow point is Hanika's (2021): the hit point projected onto the tangent plane of each
 * vertex (its position and normal), those points interpolated with the same weights.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int fin(const double *v, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

int rt_scene_add_polygon_data(rt_scene *sc, int nloops, const int *loop_counts, const double *xyz,
                              const rt_vertex_data *vd, int front_surface, int back_surface)
{
    const int has_n = vd && vd->normals, has_c = vd && vd->colours;
    if (!sc || nloops <= 0 || !loop_counts || !xyz)
        return RT_ERR_ARG;
    size_t nv;
    const int lrc = rt_loops_vertices(nloops, loop_counts, &nv);
    if (lrc != RT_OK)
        return lrc;
    if ((has_n && !fin(vd->normals, 3 * nv)) || (has_c && !fin(vd->colours, 3 * nv)))
        return RT_ERR_ARG;
    int id = rt_scene_add_polygon(sc, nloops, loop_counts, xyz, front_surface, back_surface);
    if (id < 0 || (!has_n && !has_c))
        return id;
    size_t need = sc->nvdv + nv;
    if (!rt_grow((void **)&sc->vd, &sc->capvd, sc->nvd + 1, sizeof *sc->vd) ||
        !rt_grow((void **)&sc->vd_xyz, &sc->capvdxyz, 3 * need, sizeof(double)) ||
        !rt_grow((void **)&sc->vd_n, &sc->capvdn, 3 * need, sizeof(float)) ||
        !rt_grow((void **)&sc->vd_c, &sc->capvdc, 3 * need, sizeof(float)) ||
        !rt_grow((void **)&sc->vd_loops, &sc->capvdl, sc->nvdl + (size_t)nloops, sizeof(int))) {
        rt_scene_truncate(sc, id);
        return RT_ERR_NOMEM;
    }
    rt_vd *r = &sc->vd[sc->nvd++];
    r->id = (uint32_t)id;
    r->nv = (uint32_t)nv;
    r->nloops = (uint32_t)nloops;
    r->has_n = (uint8_t)has_n;
    r->has_c = (uint8_t)has_c;
    r->v0 = sc->nvdv;
    r->loop0 = sc->nvdl;
    memcpy(sc->vd_xyz + 3 * sc->nvdv, xyz, 3 * nv * sizeof(double));
    float *n = sc->vd_n + 3 * sc->nvdv, *c = sc->vd_c + 3 * sc->nvdv;
    for (size_t i = 0; i < nv; i++) {
        double l = 0.0;
        if (has_n) {
            const double *q = vd->normals + 3 * i;
            double m = fmax(fabs(q[0]), fmax(fabs(q[1]), fabs(q[2])));
            if (m > 0.0) {
                double a = q[0] / m, b = q[1] / m, e = q[2] / m;
                l = m * sqrt(a * a + b * b + e * e);
            }
        }
        for (int k = 0; k < 3; k++) {
            n[3 * i + k] = l > 0.0 ? (float)(vd->normals[3 * i + k] / l) : 0.0f;
            double cc = has_c ? vd->colours[3 * i + k] : 0.0;
            c[3 * i + k] = (float)(cc < 0.0 ? 0.0 : cc > 1.0 ? 1.0 : cc);
        }
    }
    memcpy(sc->vd_loops + sc->nvdl, loop_counts, (size_t)nloops * sizeof(int));
    sc->nvdv = need;
    sc->nvdl += (size_t)nloops;
    return id;
}

/* weighted sums of the vertex data */
typedef struct rt_acc {
    double w, n[3], c[3], ps[3];
} rt_acc;

/* vertex x of normal n and colour c (NULL: none) with weight w */
static inline void rt_acc_vert(rt_acc *a, const double *x, const float *n, const float *c,
                               double w, const double P[3])
{
    a->w += w;
    if (n) {
        const double h = (P[0] - x[0]) * n[0] + (P[1] - x[1]) * n[1] + (P[2] - x[2]) * n[2];
        for (int k = 0; k < 3; k++) {
            a->n[k] += w * n[k];
            a->ps[k] += w * (P[k] - h * n[k]);
        }
    }
    if (c)
        for (int k = 0; k < 3; k++)
            a->c[k] += w * c[k];
}

static inline void rt_acc_add(rt_acc *a, const rt_scene *sc, const rt_vd *r, size_t j, double w,
                              const double P[3])
{
    rt_acc_vert(a, sc->vd_xyz + 3 * (r->v0 + j), r->has_n ? sc->vd_n + 3 * (r->v0 + j) : NULL,
                r->has_c ? sc->vd_c + 3 * (r->v0 + j) : NULL, w, P);
}

/* the normal, shadow point and colour of the sums a (rt_smooth_at's result) */
static int rt_smooth_end(const rt_acc *a, int has_n, int has_c, const double ng[3], double n[3],
                         double ps[3], double rgb[3]);

/* rt_smooth_at of mesh triangle primitive i: the barycentric weights of a lone triangle
   (below), over the shared vertex data */
static int rt_smooth_mesh(const rt_scene *sc, size_t i, const double P[3], const double ng[3],
                          double n[3], double ps[3], double rgb[3])
{
    const rt_mesh *m = &sc->mesh[rt_cmesh_of(sc, i)];
    if (!m->has_n && !m->has_c)
        return 0;
    const double ax = fabs(ng[0]), ay = fabs(ng[1]), az = fabs(ng[2]);
    const int kd = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    const int ku = (kd + 1) % 3, kv = (kd + 2) % 3;
    const uint32_t *cx = sc->ctri[i - sc->ntri_plain];
    const uint32_t ix[3] = {cx[0] & sc->vmask, cx[1] & sc->vmask, cx[2] & sc->vmask};
    const double *X = sc->mv_xyz.p;
    const float *N = sc->mv_n.p, *C = sc->mv_c.p;
    double s[3][2];
    for (int j = 0; j < 3; j++) {
        s[j][0] = X[ix[j] + ku] - P[ku];
        s[j][1] = X[ix[j] + kv] - P[kv];
    }
    rt_acc a;
    memset(&a, 0, sizeof a);
    for (int j = 0; j < 3; j++) {
        const double *p = s[(j + 1) % 3], *q = s[(j + 2) % 3];
        const size_t e = ix[j]; /* the vertex's element offset, 3 v */
        rt_acc_vert(&a, X + e, m->has_n ? N + e : NULL, m->has_c ? C + e : NULL,
                    p[0] * q[1] - p[1] * q[0], P);
    }
    return rt_smooth_end(&a, m->has_n, m->has_c, ng, n, ps, rgb);
}

int rt_smooth_at(const rt_scene *sc, size_t i, const double P[3], const double ng[3],
                 double n[3], double ps[3], double rgb[3])
{
    if (i >= sc->ntri_plain && i < sc->ntri)
        return rt_smooth_mesh(sc, i, P, ng, n, ps, rgb);
    if (!sc->prim_vd || sc->prim_vd[i] == RT_NO_VD)
        return 0;
    const rt_vd *r = &sc->vd[sc->prim_vd[i]];
    const double ax = fabs(ng[0]), ay = fabs(ng[1]), az = fabs(ng[2]);
    const int kd = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    const int ku = (kd + 1) % 3, kv = (kd + 2) % 3;
    const double *X = sc->vd_xyz + 3 * r->v0;
    rt_acc a;
    memset(&a, 0, sizeof a);
    if (r->nv == 3) {
        double s[3][2];
        for (int j = 0; j < 3; j++) {
            s[j][0] = X[3 * j + ku] - P[ku];
            s[j][1] = X[3 * j + kv] - P[kv];
        }
        for (int j = 0; j < 3; j++) {
            const double *p = s[(j + 1) % 3], *q = s[(j + 2) % 3];
            rt_acc_add(&a, sc, r, (size_t)j, p[0] * q[1] - p[1] * q[0], P);
        }
    } else {
        /* mean value coordinates: vertex i gets (tan(a_{i-1}/2) + tan(a_i/2)) / r_i, a_i the
           signed angle at P from vertex i to i + 1, tan(a/2) = det / (r_i r_{i+1} + dot);
           on a vertex or an edge: that vertex, or linear along that edge */
        const int *counts = sc->vd_loops + r->loop0;
        size_t base = 0;
        int special = 0;
        for (uint32_t l = 0; l < r->nloops && !special; l++) {
            const size_t m = (size_t)counts[l];
            for (size_t e = 0; e < m; e++) {
                const size_t j0 = base + e, j1 = base + (e + 1) % m;
                const double s0[2] = {X[3 * j0 + ku] - P[ku], X[3 * j0 + kv] - P[kv]};
                const double s1[2] = {X[3 * j1 + ku] - P[ku], X[3 * j1 + kv] - P[kv]};
                const double r0 = hypot(s0[0], s0[1]), r1 = hypot(s1[0], s1[1]);
                if (r0 == 0.0 || r1 == 0.0) {
                    memset(&a, 0, sizeof a);
                    rt_acc_add(&a, sc, r, r0 == 0.0 ? j0 : j1, 1.0, P);
                    special = 1;
                    break;
                }
                const double det = s0[0] * s1[1] - s0[1] * s1[0];
                const double den = r0 * r1 + (s0[0] * s1[0] + s0[1] * s1[1]);
                if (!(den > 1e-14 * r0 * r1)) { /* on the edge (angle pi) */
                    memset(&a, 0, sizeof a);
                    rt_acc_add(&a, sc, r, j0, r1, P);
                    rt_acc_add(&a, sc, r, j1, r0, P);
                    special = 1;
                    break;
                }
                const double t = det / den;
                rt_acc_add(&a, sc, r, j0, t / r0, P);
                rt_acc_add(&a, sc, r, j1, t / r1, P);
            }
            base += m;
        }
    }
    return rt_smooth_end(&a, r->has_n, r->has_c, ng, n, ps, rgb);
}

static int rt_smooth_end(const rt_acc *ap, int has_n, int has_c, const double ng[3], double n[3],
                         double ps[3], double rgb[3])
{
    const rt_acc a = *ap;
    if (!(fabs(a.w) > 0.0) || !isfinite(a.w))
        return 0;
    int got = 0;
    if (has_c) {
        for (int k = 0; k < 3; k++) {
            double c = a.c[k] / a.w;
            rgb[k] = c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0;
        }
        got |= 2;
    }
    if (has_n) {
        double v[3] = {a.n[0] / a.w, a.n[1] / a.w, a.n[2] / a.w};
        double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (l > 1e-6 && isfinite(l)) {
            double sg = v[0] * ng[0] + v[1] * ng[1] + v[2] * ng[2] < 0.0 ? -1.0 : 1.0;
            for (int k = 0; k < 3; k++) {
                n[k] = sg * v[k] / l;
                ps[k] = a.ps[k] / a.w;
            }
            if (fin(ps, 3))
                got |= 1;
        }
    }
    return got;
}
