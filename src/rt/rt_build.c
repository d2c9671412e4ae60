/* SPDX-License-Identifier: MIT */
/*
 * rt_build.c -- construction of the uniform grid in flat CSR arrays (cell offsets +
 * reference array, no per-cell allocation) with a second level in crowded cells.
 * The grid may be laid out in a rotated frame (p' = R (p - c), chosen from the largest
 * primitives when it shrinks the grid box: scenes seen obliquely in VRC3); rays are rotated
 * for the traversal only, primitive tests stay in VRC3, so results do not depend on it.
 * A primitive goes into every cell its surface overlaps: SAT for triangles (Akenine-Moeller),
 * Sutherland-Hodgman clipping of each loop for quads, polygons and cell arrays, against the
 * cell box enlarged by eps = 1e-9 * (scene magnitude + extent), far above the rounding of the
 * rotation and of hit points near cell faces. Resolution rule and its measurements: gksrt.h
 * (RT_GRID_FACTOR_DEFAULT). The top level also stores, per cell and octant of directions, the
 * largest empty cube starting there (empty-space jumps of the traversal), and the grid a
 * k-DOP of the occupied space (the rays' walks start and end at it).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"
#include "rt_internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* min / max without libm calls (fmin/fmax are not inlined without -ffast-math); the build
   only sees finite values; a NaN in the second operand returns the first, as fmin/fmax do */
static inline double rt_dmin(double a, double b)
{
    return b < a ? b : a;
}

static inline double rt_dmax(double a, double b)
{
    return b > a ? b : a;
}

/* ---- overlap tests for the build ---- */

/* triangle / box SAT (Akenine-Moeller); box given by centre and half sizes; e: the edges
   v1-v0, v2-v1, v0-v2, n = e0 x e1 (per triangle). Cheapest axes first: box faces, the
   triangle's plane, then the 9 edge x box-axis products written out (the zero components
   of those axes dropped). Rounding (~1e-16 relative) is far below the enlargement of the
   cell box by eps (1e-9 relative), so the test stays conservative. */
static inline int rt_sep(double p0, double p1, double p2, double rad)
{
    double mn = rt_dmin(p0, rt_dmin(p1, p2)), mx = rt_dmax(p0, rt_dmax(p1, p2));
    return mn > rad || mx < -rad;
}

static int rt_tri_box(const rt_tri *t, const double e[3][3], const double n[3], const double bc[3],
                      const double h[3])
{
    double v[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            v[i][j] = t->v[i][j] - bc[j];
    for (int j = 0; j < 3; j++) /* box face normals */
        if (rt_sep(v[0][j], v[1][j], v[2][j], h[j]))
            return 0;
    double pd = n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2];
    if (fabs(pd) > h[0] * fabs(n[0]) + h[1] * fabs(n[1]) + h[2] * fabs(n[2]))
        return 0;
    for (int i = 0; i < 3; i++) {
        const double ex = e[i][0], ey = e[i][1], ez = e[i][2];
        const double ax = fabs(ex), ay = fabs(ey), az = fabs(ez);
        if (rt_sep(ey * v[0][2] - ez * v[0][1], ey * v[1][2] - ez * v[1][1],
                   ey * v[2][2] - ez * v[2][1], h[1] * az + h[2] * ay))
            return 0;
        if (rt_sep(ez * v[0][0] - ex * v[0][2], ez * v[1][0] - ex * v[1][2],
                   ez * v[2][0] - ex * v[2][2], h[0] * az + h[2] * ax))
            return 0;
        if (rt_sep(ex * v[0][1] - ey * v[0][0], ex * v[1][1] - ey * v[1][0],
                   ex * v[2][1] - ey * v[2][0], h[0] * ay + h[1] * ax))
            return 0;
    }
    return 1;
}

typedef struct rt_clipbuf {
    double *a, *b;
    size_t cap; /* doubles in each of a and b */
} rt_clipbuf;

static int rt_clipbuf_reserve(rt_clipbuf *cb, size_t need)
{
    if (need <= cb->cap)
        return 1;
    size_t nc = need * 2;
    double *na = rt_realloc_array(cb->a, nc, sizeof(double));
    if (!na)
        return 0;
    cb->a = na;
    double *nb = rt_realloc_array(cb->b, nc, sizeof(double));
    if (!nb)
        return 0;
    cb->b = nb;
    cb->cap = nc;
    return 1;
}

/* Sutherland-Hodgman clip of a planar loop against box [lo,hi]; 1 if anything remains */
static int rt_loop_box(rt_clipbuf *cb, const double *pts, size_t n, const double lo[3],
                       const double hi[3], int *err)
{
    for (size_t i = 0; i < n; i++) { /* quick accept: a vertex inside */
        const double *p = pts + 3 * i;
        if (p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
            p[2] <= hi[2])
            return 1;
    }
    if (!rt_clipbuf_reserve(cb, 3 * (n + 2))) {
        *err = 1;
        return 0;
    }
    memcpy(cb->a, pts, 3 * n * sizeof(double));
    size_t cur = n;
    for (int pl = 0; pl < 6 && cur > 0; pl++) {
        int ax = pl >> 1, upper = pl & 1;
        double lim = upper ? hi[ax] : lo[ax];
        if (!rt_clipbuf_reserve(cb, 3 * (2 * cur + 2))) { /* each edge emits <= 2 points */
            *err = 1;
            return 0;
        }
        size_t out = 0;
        const double *q = cb->a + 3 * (cur - 1);
        double dq = upper ? lim - q[ax] : q[ax] - lim;
        for (size_t i = 0; i < cur; i++) {
            const double *p = cb->a + 3 * i;
            double dp = upper ? lim - p[ax] : p[ax] - lim;
            if ((dp >= 0.0) != (dq >= 0.0)) {
                double s = dq / (dq - dp);
                for (int j = 0; j < 3; j++)
                    cb->b[3 * out + j] = q[j] + s * (p[j] - q[j]);
                cb->b[3 * out + ax] = lim;
                out++;
            }
            if (dp >= 0.0) {
                memcpy(cb->b + 3 * out, p, 3 * sizeof(double));
                out++;
            }
            q = p;
            dq = dp;
        }
        double *t = cb->a;
        cb->a = cb->b;
        cb->b = t;
        cur = out;
    }
    return cur > 0;
}

static int rt_plane_box(const double n[3], double d, const double bc[3], const double h[3])
{
    double s = n[0] * bc[0] + n[1] * bc[1] + n[2] * bc[2] - d;
    double r = h[0] * fabs(n[0]) + h[1] * fabs(n[1]) + h[2] * fabs(n[2]);
    return fabs(s) <= r * (1.0 + 1e-12);
}

typedef struct rt_pair {
    uint32_t cell, prim;
} rt_pair;

/* the eps-enlarged cell boxes of a grid of at most RT_TAB cells per axis (a sub-grid) by
   axis: centre and half size of cell q on axis a, the values rt_axis_box computes */
enum { RT_TAB = 32 };
typedef struct rt_cell_tab {
    const rt_box *box; /* the grid they belong to */
    double bc[3][RT_TAB], h[3][RT_TAB];
} rt_cell_tab;

/* one thread's build scratch: its (cell, primitive) pairs in primitive order */
typedef struct rt_build {
    const rt_cell_tab *tab; /* the cell boxes of the grid being filled, or NULL (rt_sub_cells) */
    rt_pair *pairs;
    size_t npairs, cap;
    rt_clipbuf cb;
    double *pts;
    size_t cappts;
    double *tpts;      /* the second level: the grid-frame vertices of the triangles of the
                          top cell at hand (9 doubles per reference; rt_sub_cells) ... */
    size_t captpts;
    const double **tv; /* ... or on a widened top level, per reference, where its 9
                          coordinates are: in tpts or in the scene's arrays (rt_sub_classify) */
    size_t captv;
    const double *gv;  /* the meshes' vertices in the rotated grid frame (rt_mesh_gframe), or
                          NULL (not rotated, or no mesh) */
    char pad[RT_LINE]; /* the next part's scratch on other cache lines (RT_LINE) */
} rt_build;

static void rt_build_free(rt_build *b)
{
    free(b->cb.a);
    free(b->cb.b);
    free(b->pts);
    free(b->tpts);
    free(b->tv);
    free(b->pairs);
    memset(b, 0, sizeof *b);
}

static int rt_build_push(rt_build *b, size_t cell, size_t prim)
{
    if (b->npairs == b->cap &&
        !rt_grow((void **)&b->pairs, &b->cap, b->npairs + 1, sizeof *b->pairs))
        return 0;
    b->pairs[b->npairs].cell = (uint32_t)cell;
    b->pairs[b->npairs].prim = (uint32_t)prim;
    b->npairs++;
    return 1;
}

/* Number of vertices of primitive i as rt_prim_vertex gives them */
size_t rt_prim_nverts(const rt_scene *sc, size_t i)
{
    if (i < sc->ntri)
        return 3;
    const rt_prim *p = rt_prim_rest(sc, i);
    if (p->kind == RT_KIND_QUAD || p->kind == RT_KIND_CELL)
        return 4;
    const rt_poly *po = &sc->poly[p->data];
    size_t nv = 0;
    for (uint32_t l = 0; l < po->nloops; l++)
        nv += sc->loops[po->loop0 + l];
    return nv;
}

/* Vertex k of primitive i, as traced: triangle and quad vertices; polygon vertices projected
   onto the polygon's plane (as rt_scene_commit does; the traced region lies in their convex
   hull); the 4 corners of a cell array. */
void rt_prim_vertex(const rt_scene *sc, size_t i, size_t k, double out[3])
{
    if (i < sc->ntri) {
        memcpy(out, rt_tri_vert(sc, i, (int)k), 3 * sizeof(double));
        return;
    }
    const rt_prim *p = rt_prim_rest(sc, i);
    if (p->kind == RT_KIND_QUAD) {
        memcpy(out, sc->quad[p->data].v[k], 3 * sizeof(double));
    } else if (p->kind == RT_KIND_CELL) {
        const rt_cell *c = &sc->cell[p->data];
        for (int j = 0; j < 3; j++)
            out[j] = c->p[j] + (k == 1 || k == 2 ? c->a[j] : 0.0) + (k >= 2 ? c->b[j] : 0.0);
    } else {
        const rt_poly *po = &sc->poly[p->data];
        const double *uv = sc->uv + 2 * ((size_t)po->uv0 + k);
        int ax = 3 - po->ku - po->kv;
        out[po->ku] = uv[0];
        out[po->kv] = uv[1];
        out[ax] = (po->d - po->n[po->ku] * uv[0] - po->n[po->kv] * uv[1]) / po->n[ax];
    }
}

/* 3-D points of the triangle / polygon / cell outline(s) of primitive i lying on the traced
   plane (VRC3), rt_prim_vertex's, into the build's scratch */
static size_t rt_prim_points(const rt_scene *sc, rt_build *b, size_t i, int *err)
{
    if (i < sc->ntri && b->cappts >= 9) { /* the common case, without calls */
        rt_tri_copy(sc, i, b->pts);
        return 3;
    }
    const size_t nv = rt_prim_nverts(sc, i);
    if (!rt_grow((void **)&b->pts, &b->cappts, 3 * nv, sizeof(double))) {
        *err = 1;
        return 0;
    }
    for (size_t k = 0; k < nv; k++)
        rt_prim_vertex(sc, i, k, b->pts + 3 * k);
    return nv;
}

/* rt_prim_points' points taken into the grid frame (rt_grid_point): a mesh triangle's from
   b->gv when the grid is rotated, the same values rotated once per vertex */
static inline size_t rt_prim_gpoints(const rt_scene *sc, rt_build *b, size_t i, int *err)
{
    if (b->gv && i < sc->ntri && i >= sc->ntri_plain && b->cappts >= 9) {
        const uint32_t *ix = sc->ctri[i - sc->ntri_plain];
        for (int k = 0; k < 3; k++)
            memcpy(b->pts + 3 * k, b->gv + (ix[k] & sc->vmask), 3 * sizeof(double));
        return 3;
    }
    const size_t npts = rt_prim_points(sc, b, i, err);
    for (size_t k = 0; k < npts && sc->grid.rotated; k++)
        rt_grid_point(&sc->grid, b->pts + 3 * k, b->pts + 3 * k);
    return npts;
}

static inline void rt_pts_bbox(const double *pts, size_t npts, double bb[6])
{
    if (npts == 3) { /* triangles: the loop below unrolled (same values) */
        for (int i = 0; i < 3; i++) {
            bb[i] = rt_dmin(rt_dmin(pts[i], pts[3 + i]), pts[6 + i]);
            bb[3 + i] = rt_dmax(rt_dmax(pts[i], pts[3 + i]), pts[6 + i]);
        }
        return;
    }
    for (int i = 0; i < 3; i++) {
        bb[i] = INFINITY;
        bb[3 + i] = -INFINITY;
    }
    for (size_t v = 0; v < npts; v++)
        for (int i = 0; i < 3; i++) {
            bb[i] = rt_dmin(bb[i], pts[3 * v + i]);
            bb[3 + i] = rt_dmax(bb[3 + i], pts[3 * v + i]);
        }
}

/* the cell of coordinate x on axis a of g, clamped to the grid (NaN: 0); in SSE2 with
   maxsd / minsd instead of branches, which the build's boxes take at random (gcc makes
   branches of the plain C: 0.5 M mispredicted of 5.8 M in a commit of 10^5 random
   triangles) */
static inline int rt_cell_of(const rt_box *g, double x, int a)
{
    const double f = (x - g->lo[a]) * g->inv_cw[a];
#if defined(__SSE2__)
    /* maxsd gives its second operand 0 when f is NaN, minsd the first when not above */
    const __m128d c = _mm_max_sd(_mm_set_sd(f), _mm_setzero_pd());
    return _mm_cvttsd_si32(_mm_min_sd(c, _mm_set_sd((double)(g->n[a] - 1))));
#else
    if (!(f > 0.0))
        return 0;
    if (f >= (double)(g->n[a] - 1))
        return g->n[a] - 1;
    return (int)f;
#endif
}

/* cells ~= target, as cubic as the box allows; dims thinner than 1/1000 of the largest get 1 */
static void rt_box_resolution(rt_box *g, double target, int maxn)
{
    double ext[3], mx = 0.0;
    for (int a = 0; a < 3; a++) {
        ext[a] = g->hi[a] - g->lo[a];
        mx = rt_dmax(mx, ext[a]);
    }
    double vol = 1.0;
    int k = 0;
    for (int a = 0; a < 3; a++)
        if (ext[a] > 1e-3 * mx) {
            vol *= ext[a] / mx;
            k++;
        }
    if (target < 1.0)
        target = 1.0;
    double s = pow(target / vol, 1.0 / (double)k) / mx;
    double total = 1.0;
    for (int a = 0; a < 3; a++) {
        double n = ext[a] > 1e-3 * mx ? floor(ext[a] * s + 0.5) : 1.0;
        g->n[a] = n < 1.0 ? 1 : (n > (double)maxn ? maxn : (int)n);
        total *= g->n[a];
    }
    while (total > (double)(1 << 25)) {
        total = 1.0;
        for (int a = 0; a < 3; a++) {
            g->n[a] = g->n[a] > 1 ? (g->n[a] * 3) / 4 : 1;
            total *= g->n[a];
        }
    }
}

static void rt_box_finish(rt_box *g)
{
    for (int a = 0; a < 3; a++) {
        g->cw[a] = (g->hi[a] - g->lo[a]) / g->n[a];
        g->inv_cw[a] = g->n[a] / (g->hi[a] - g->lo[a]);
    }
}

void rt_grid_free(rt_grid *g)
{
    free(g->off);
    free(g->refs);
    free(g->sub);
    free(g->odist);
    free(g->subs);
    rt_big_free(&g->soff_m);
    rt_big_free(&g->srefs_m);
    free(g->sref16);
    free(g->sloc);
    rt_leaves_free(g); /* soff16 lives in soff_m */
    free(g->subplane);
    free(g->splanes);
    memset(g, 0, sizeof *g);
}

/* cell box of cell c of g, enlarged by eps */
static void rt_cell_box(const rt_box *g, const int c[3], double eps, double lo[3], double hi[3])
{
    for (int a = 0; a < 3; a++) {
        lo[a] = (c[a] == 0 ? g->lo[a] : g->lo[a] + c[a] * g->cw[a]) - eps;
        hi[a] = (c[a] == g->n[a] - 1 ? g->hi[a] : g->lo[a] + (c[a] + 1) * g->cw[a]) + eps;
    }
}

void rt_grid_point(const rt_grid *g, const double p[3], double out[3])
{
    if (!g->rotated) {
        memcpy(out, p, 3 * sizeof(double));
        return;
    }
    double q[3] = {p[0] - g->c[0], p[1] - g->c[1], p[2] - g->c[2]};
    for (int a = 0; a < 3; a++)
        out[a] = g->R[a][0] * q[0] + g->R[a][1] * q[1] + g->R[a][2] * q[2];
}

void rt_grid_dir(const rt_grid *g, const double v[3], double out[3])
{
    if (!g->rotated) {
        memcpy(out, v, 3 * sizeof(double));
        return;
    }
    double q[3] = {v[0], v[1], v[2]};
    for (int a = 0; a < 3; a++)
        out[a] = g->R[a][0] * q[0] + g->R[a][1] * q[1] + g->R[a][2] * q[2];
}

/* plane n.x = d of primitive p (VRC3); 0 for triangles (SAT instead) */
static void rt_prim_plane(const rt_scene *sc, const rt_prim *p, double n[3], double *d)
{
    n[0] = n[1] = n[2] = 0.0;
    *d = 0.0;
    if (p->kind == RT_KIND_QUAD) {
        const rt_quad *q = &sc->quad[p->data];
        memcpy(n, q->n, 3 * sizeof(double));
        *d = n[0] * q->v[0][0] + n[1] * q->v[0][1] + n[2] * q->v[0][2];
    } else if (p->kind == RT_KIND_POLY) {
        memcpy(n, sc->poly[p->data].n, 3 * sizeof(double));
        *d = sc->poly[p->data].d;
    } else if (p->kind == RT_KIND_CELL) {
        memcpy(n, sc->cell[p->data].n, 3 * sizeof(double));
        *d = sc->cell[p->data].d;
    }
}

/* Triangle t (edges e, normal n as rt_tri_box takes them) against the cells c0 .. c1 of g
 * (at most RT_SPAN per axis), pushing (base + cell, prim) for each cell it overlaps: the same
 * decisions as rt_tri_box cell by cell, bit for bit (a cell is taken when no test separates,
 * whatever the order of the tests). The face and plane tests are rt_tri_box's own, with their
 * per-axis terms computed once per axis and cell row (the face test from the triangle's box:
 * the same values, see rt_axis_cells). The 9 edge axes a = e_i x X_g go
 * through a margin filter (docs/RAYTRACING.md, "The build's margin filter"): with V0 the
 * triangle's first vertex, a.(V_k - bc) = a.(V_k - V0) - a.(bc - V0); the first term takes
 * two values per axis up to rounding (0 and s, a component of a cross product of the edges,
 * per triangle), the second is a difference of two products that depend on one axis's cell
 * each (per axis and cell row). Where the filter's value lies farther from the test's
 * threshold than the error bound of both computations, it decides (separates / keeps); a
 * cell left undecided by it gets rt_tri_box. Group g (the axes e_i x X_g) depends on the
 * cells of the other two axes only: its result is kept for the cells sharing them
 * (X group: per row of the x loop; Y group: per x within a z slab; Z group: per (x, y) over
 * all z). 0: no memory. */
enum { RT_SPAN = RT_BUILD_SPAN };

typedef struct rt_axis_cell {
    double bc, h;  /* the eps-enlarged cell box on this axis: centre, half size */
    double cv[3];  /* [i]: e[i][b1] * (bc - V0[a]) + s_gi / 2, g = b2 (the group in which this
                      axis is P, see rt_edge_filter) */
    double cw[3];  /* [i]: e[i][b2] * (bc - V0[a]), for the group g = b1 (this axis is Q) */
    double nv, nh; /* n[a] * v[0], h * |n[a]| */
    int sep;       /* the box face of this axis separates */
} rt_axis_cell;

/* The filter of group g with P = g + 1, Q = g + 2 (mod 3), p and q the cells on P and Q:
   for each edge i, m = q->cw[i] - p->cv[i] approximates a.(bc - V0) - s / 2; |m| > ro[i]:
   the axis separates (rt_tri_box would find so); |m| <= ri[i]: it does not; between (or
   NaN): undecided. Returns 1 when an axis of the group separates, 0 when none does, -1
   when undecided. The plain C form, which targets without SSE2 use; compiled everywhere, so
   that a test compares it with the SSE2 form (rt_build_edge_filter): the same answers
   where ri[i] <= ro[i] or either is NaN, as the build makes them (with ri > ro, |m| in
   between separates in SSE2 only). */
static inline int rt_edge_filter_c(const double ro[3], const double ri[3],
                                   const rt_axis_cell *p, const rt_axis_cell *q)
{
    int r = 0;
    for (int i = 0; i < 3; i++) {
        const double m = fabs(q->cw[i] - p->cv[i]);
        if (!(m <= ri[i])) {
            if (m > ro[i])
                return 1;
            r = -1;
        }
    }
    return r;
}

/* rt_edge_filter_c's answers, in SSE2 where compiled */
static inline int rt_edge_filter(const double ro[3], const double ri[3], const rt_axis_cell *p,
                                 const rt_axis_cell *q)
{
#if defined(__SSE2__)
    /* edges 0 and 1 in SSE2 lanes (the same operations: the same m), edge 2 alone, the
       answers combined without a branch per edge */
    const __m128d m01 = _mm_andnot_pd(_mm_set1_pd(-0.0),
                                      _mm_sub_pd(_mm_loadu_pd(q->cw), _mm_loadu_pd(p->cv)));
    const double m2 = fabs(q->cw[2] - p->cv[2]);
    const int sep = _mm_movemask_pd(_mm_cmpgt_pd(m01, _mm_loadu_pd(ro))) | (m2 > ro[2]);
    const int und = _mm_movemask_pd(_mm_cmpnle_pd(m01, _mm_loadu_pd(ri))) | !(m2 <= ri[2]);
    return sep ? 1 : -(und != 0);
#else
    return rt_edge_filter_c(ro, ri, p, q);
#endif
}


/* centre bc and half size h of the eps-enlarged cell q of g on axis a (rt_cell_box's box) */
static inline void rt_axis_box(const rt_box *g, int a, int q, double eps, double *bc, double *h)
{
    const double lo = (q == 0 ? g->lo[a] : g->lo[a] + q * g->cw[a]) - eps;
    const double hi = (q == g->n[a] - 1 ? g->hi[a] : g->lo[a] + (q + 1) * g->cw[a]) + eps;
    *bc = 0.5 * (lo + hi);
    *h = 0.5 * (hi - lo);
}

/* rt_axis_box's values, from tab when it is not NULL (then tab->box is g) */
static inline void rt_tab_box(const rt_cell_tab *tab, const rt_box *g, int a, int q, double eps,
                              double *bc, double *h)
{
    if (tab) {
        *bc = tab->bc[a][q];
        *h = tab->h[a][q];
    } else {
        rt_axis_box(g, a, q, eps, bc, h);
    }
}

/* tab := the cell boxes of g (at most RT_TAB cells per axis), as rt_axis_box gives them */
static void rt_tab_fill(rt_cell_tab *tab, const rt_box *g, double eps)
{
    tab->box = g;
    for (int a = 0; a < 3; a++)
        for (int q = 0; q < g->n[a]; q++)
            rt_axis_box(g, a, q, eps, &tab->bc[a][q], &tab->h[a][q]);
}

/* cells whose triangle/box test the build's filters (the margin filter of rt_tri_cells, the
   margins of rt_tri_row and rt_tri_slab) left to rt_tri_box (process total, for tests), and
   the filters' switch (1: on; 0, for tests comparing both: every cell of rt_tri_row's range
   through rt_tri_box, every cell of the other paths that no box face separates through the
   edge tests of rt_tri_box's operands) */
static uint64_t rt_exact_cells;
static int rt_filter_on = 1;

/* Triangle t whose cells span one axis a only (c0 == c1 on the others), as rt_tri_cells
 * decides, with fewer tests. When the whole triangle lies in the cell's box shrunk by eps on
 * the two other axes, a cell of the row whose face test on a keeps it with that margin too
 * (the triangle's range on a meets [-h + eps, h - eps]) holds a point of the triangle at
 * least eps inside its box on every axis (the triangle is connected); then every axis of the
 * SAT keeps the cell with a margin of eps times the axis' 1-norm in exact arithmetic, while
 * the computed tests err by ~1e-15 of the scene's scale times that norm (eps is 1e-9 of it):
 * the 9 edge tests keep it, and the face and plane tests are computed as rt_tri_cells
 * computes them (the same operands). A cell without the margin gets rt_tri_box's tests (the
 * same decision as rt_tri_cells', bit for bit; with the triangle inside the box on the other
 * two axes, rt_tri_box's edge tests cannot separate a cell that the face tests keep, by
 * monotone rounding, so it decides as the face and plane tests: docs/RAYTRACING.md, "One
 * cell on two axes"). With the filters off (rt_build_set_filter), every cell of the row
 * goes through rt_tri_box, without the face test, the inside test or the margins: the
 * reference that tests compare the row's decisions with.
 * Returns 1, 0 (no memory), or -1 when the triangle is not inside on the other two axes
 * (nothing pushed). */
static int rt_tri_row(const rt_tri *t, const double e[3][3], const double n[3], const double bb[6],
                      const rt_box *g, const int c0[3], const int c1[3], double eps, rt_build *b,
                      size_t base, size_t prim, int a)
{
    const rt_cell_tab *tab = b->tab && b->tab->box == g ? b->tab : NULL;
    double nv[3], nh[3], bc[3], h[3];
    int c[3] = {c0[0], c0[1], c0[2]};
    if (!__atomic_load_n(&rt_filter_on, __ATOMIC_RELAXED)) {
        for (int s = 0; s < 3; s++)
            if (s != a)
                rt_tab_box(tab, g, s, c0[s], eps, &bc[s], &h[s]);
        for (c[a] = c0[a]; c[a] <= c1[a]; c[a]++) {
            rt_tab_box(tab, g, a, c[a], eps, &bc[a], &h[a]);
            if (rt_tri_box(t, e, n, bc, h) && !rt_build_push(b, base + rt_cell_index(g, c), prim))
                return 0;
        }
        __atomic_fetch_add(&rt_exact_cells, (uint64_t)(c1[a] - c0[a] + 1), __ATOMIC_RELAXED);
        return 1;
    }
    for (int s = 0; s < 3; s++) {
        if (s == a)
            continue;
        rt_tab_box(tab, g, s, c0[s], eps, &bc[s], &h[s]);
        /* min_k (V_k - bc) is (min_k V_k) - bc, bit for bit (rounding is monotonic) */
        if (!(bb[s] - bc[s] >= eps - h[s] && bb[3 + s] - bc[s] <= h[s] - eps))
            return -1;
        nv[s] = n[s] * (t->v[0][s] - bc[s]);
        nh[s] = h[s] * fabs(n[s]);
    }
    uint64_t nexact = 0;
    for (c[a] = c0[a]; c[a] <= c1[a]; c[a]++) {
        rt_tab_box(tab, g, a, c[a], eps, &bc[a], &h[a]);
        const double mn = bb[a] - bc[a], mx = bb[3 + a] - bc[a];
        if (mn > h[a] || mx < -h[a]) /* the face test (rt_sep) */
            continue;
        if (!(mn <= h[a] - eps && mx >= eps - h[a])) {
            nexact++;
            if (rt_tri_box(t, e, n, bc, h) && !rt_build_push(b, base + rt_cell_index(g, c), prim))
                return 0;
            continue;
        }
        nv[a] = n[a] * (t->v[0][a] - bc[a]);
        nh[a] = h[a] * fabs(n[a]);
        const double pd = nv[0] + nv[1] + nv[2];
        if (fabs(pd) > nh[0] + nh[1] + nh[2])
            continue;
        if (!rt_build_push(b, base + rt_cell_index(g, c), prim))
            return 0;
    }
    if (nexact)
        __atomic_fetch_add(&rt_exact_cells, nexact, __ATOMIC_RELAXED);
    return 1;
}

uint64_t rt_build_exact_cells(void)
{
    return __atomic_load_n(&rt_exact_cells, __ATOMIC_RELAXED);
}

void rt_build_set_filter(int on)
{
    __atomic_store_n(&rt_filter_on, on != 0, __ATOMIC_RELAXED);
}

/* half the filter's s of group g (P, Q) for the three edges (rt_tri_cells) */
#define RT_HALF_S(hg, P, Q)                                                                    \
    do {                                                                                       \
        (hg)[0] = 0.5 * (e[0][Q] * e[2][P] - e[0][P] * e[2][Q]);                               \
        (hg)[1] = 0.5 * (e[1][P] * e[0][Q] - e[1][Q] * e[0][P]);                               \
        (hg)[2] = (hg)[0];                                                                     \
    } while (0)

/* rt_edge_filter's bounds of group gi (P, Q) for the three edges (rt_tri_cells); in SSE2
   edges 0 and 1 side by side (the same operations in the same order, so the same values),
   edge 2 alone: gcc leaves the plain loop scalar */
#if defined(__SSE2__)
#define RT_BOUNDS(gi, P, Q)                                                                    \
    do {                                                                                       \
        const __m128d hs01 = _mm_andnot_pd(_mm_set1_pd(-0.0), _mm_loadu_pd(hs[gi]));           \
        const __m128d rho = _mm_add_pd(_mm_mul_pd(_mm_set1_pd(hmax[P]), _mm_loadu_pd(ae[Q])),  \
                                       _mm_mul_pd(_mm_set1_pd(hmax[Q]), _mm_loadu_pd(ae[P]))); \
        const __m128d wr = _mm_add_pd(hs01, rho);                                             \
        _mm_storeu_pd(ro[gi], _mm_add_pd(wr, _mm_set1_pd(B)));                                 \
        _mm_storeu_pd(ri[gi], _mm_sub_pd(wr, _mm_set1_pd(Bi)));                                \
        const double wr2 = fabs(hs[gi][2]) + (hmax[P] * ae[Q][2] + hmax[Q] * ae[P][2]);        \
        ro[gi][2] = wr2 + B;                                                                   \
        ri[gi][2] = wr2 - Bi;                                                                  \
    } while (0)
#else
#define RT_BOUNDS(gi, P, Q)                                                                    \
    do {                                                                                       \
        for (int i = 0; i < 3; i++) {                                                          \
            const double wr = fabs(hs[gi][i]) + (hmax[P] * ae[Q][i] + hmax[Q] * ae[P][i]);     \
            ro[gi][i] = wr + B;                                                                \
            ri[gi][i] = wr - Bi;                                                               \
        }                                                                                      \
    } while (0)
#endif

/* the per-axis terms of rt_tri_cells for the cells c0[a] .. c1[a] of axis a (a constant where
   it is inlined): the cell box, the face test, the plane's terms, the filter's products; L,
   hmin, hmax as rt_tri_cells describes them */
static inline __attribute__((always_inline)) void
rt_axis_cells(const rt_tri *t, const double e[3][3], const double n[3], const double bb[6],
              const rt_box *g,
              const int c0[3], const int c1[3], double eps, const double hs[3][3],
              const double ae[3][3], int a, const rt_cell_tab *tab, rt_axis_cell *ac,
              double *L, double *hmin, double *hmax)
{
    const int b1 = a == 2 ? 0 : a + 1, b2 = a == 0 ? 2 : a - 1;
    const double o = t->v[0][a], na = n[a], ana = fabs(n[a]);
    const double f0 = e[0][b1], f1 = e[1][b1], f2 = e[2][b1];
    const double g0 = e[0][b2], g1 = e[1][b2], g2 = e[2][b2];
    const double m0 = hs[b2][0], m1 = hs[b2][1], m2 = hs[b2][2];
    double l = rt_dmax(ae[a][0], ae[a][2]), hn = HUGE_VAL, hx = 0.0;
#define RT_AXIS_CELL(q)                                                                        \
    do {                                                                                       \
        rt_axis_cell *x = &ac[(q) - c0[a]];                                                    \
        double bc, h;                                                                          \
        rt_tab_box(tab, g, a, (q), eps, &bc, &h);                                              \
        x->bc = bc;                                                                            \
        x->h = h;                                                                              \
        x->sep = (bb[a] - bc > h) | (bb[3 + a] - bc < -h); /* both: no branch */               \
        x->nv = na * (t->v[0][a] - bc);                                                        \
        x->nh = h * ana;                                                                       \
        const double d = bc - o;                                                               \
        x->cv[0] = f0 * d + m0;                                                                \
        x->cv[1] = f1 * d + m1;                                                                \
        x->cv[2] = f2 * d + m2;                                                                \
        x->cw[0] = g0 * d;                                                                     \
        x->cw[1] = g1 * d;                                                                     \
        x->cw[2] = g2 * d;                                                                     \
        l = rt_dmax(l, rt_dmax(fabs(d), h));                                                   \
        hn = rt_dmin(hn, h);                                                                   \
        hx = rt_dmax(hx, h);                                                                   \
    } while (0)
    /* rt_sep of V_k - bc: min_k (V_k - bc) is (min_k V_k) - bc, bit for bit (rounding is
       monotonic), the same for max. The first two cells written out (most ranges have one
       or two cells per axis): fewer loop tests */
    RT_AXIS_CELL(c0[a]);
    if (c1[a] > c0[a]) {
        RT_AXIS_CELL(c0[a] + 1);
        for (int q = c0[a] + 2; q <= c1[a]; q++)
            RT_AXIS_CELL(q);
    }
#undef RT_AXIS_CELL
    *L = l;
    *hmin = hn;
    *hmax = hx;
}

/* rt_tri_slab's filter of group a for the cells of a range, row by row: for row kq of Q (not
   in outq) and cell kp of P, edge i: m = |cw[kq][i] - cvT[i][kp]| (rt_edge_filter's m);
   bit kp of sepm[kq] set when m > ro[i] for an edge, of undm[kq] when !(m <= ri[i]) for one
   (NaN included); bits at np and above are arbitrary (0 here). The plain C form, one cell at
   a time, which targets without SSE2 use; compiled everywhere, so that a test compares it
   with the SSE2 form (rt_build_slab_masks): the same bits below np, for any inputs. */
static void rt_slab_masks_c(const double cvT[3][RT_SPAN + 1], int np, const double cw[][3],
                            int nq, uint32_t outq, const double ro[3], const double ri[3],
                            uint32_t *sepm, uint32_t *undm)
{
    for (int kq = 0; kq < nq; kq++) {
        if (outq >> kq & 1)
            continue;
        const double *w = cw[kq];
        uint32_t sm = 0, um = 0;
        for (int kp = 0; kp < np; kp++) {
            int sep = 0, und = 0;
            for (int i = 0; i < 3; i++) {
                const double m = fabs(w[i] - cvT[i][kp]);
                sep |= m > ro[i];
                und |= !(m <= ri[i]);
            }
            sm |= (uint32_t)sep << kp;
            um |= (uint32_t)und << kp;
        }
        sepm[kq] = sm;
        undm[kq] = um;
    }
}

/* rt_slab_masks_c's masks; in SSE2 the cells of a row side by side in lanes, two at a time
   (cvT[i][np] defined; bit np then arbitrary), without a branch per cell. inline: gcc then
   inlines it into rt_tri_slab as when that was its one caller (without it, the second
   caller, rt_build_slab_masks, kept it out of line and changed rt_tri_slab's code) */
static inline void
rt_slab_masks(const double cvT[3][RT_SPAN + 1], int np, const double cw[][3], int nq,
              uint32_t outq, const double ro[3], const double ri[3], uint32_t *sepm,
              uint32_t *undm)
{
#if !defined(__SSE2__)
    rt_slab_masks_c(cvT, np, cw, nq, outq, ro, ri, sepm, undm);
#else
    for (int kq = 0; kq < nq; kq++) {
        if (outq >> kq & 1)
            continue;
        const double *w = cw[kq];
        uint32_t sm = 0, um = 0;
        const __m128d sign = _mm_set1_pd(-0.0);
        for (int kp = 0; kp < np; kp += 2) {
            __m128d s = _mm_setzero_pd(), u = _mm_setzero_pd();
            for (int i = 0; i < 3; i++) {
                const __m128d m = _mm_andnot_pd(sign, _mm_sub_pd(_mm_set1_pd(w[i]),
                                                                 _mm_loadu_pd(&cvT[i][kp])));
                s = _mm_or_pd(s, _mm_cmpgt_pd(m, _mm_set1_pd(ro[i])));
                u = _mm_or_pd(u, _mm_cmpnle_pd(m, _mm_set1_pd(ri[i])));
            }
            sm |= (uint32_t)_mm_movemask_pd(s) << kp;
            um |= (uint32_t)_mm_movemask_pd(u) << kp;
        }
        sepm[kq] = sm;
        undm[kq] = um;
    }
#endif
}

int rt_build_edge_filter(int form, const double ro[3], const double ri[3], const double cv[3],
                         const double cw[3])
{
    rt_axis_cell p, q;
    memset(&p, 0, sizeof p);
    memset(&q, 0, sizeof q);
    memcpy(p.cv, cv, sizeof p.cv);
    memcpy(q.cw, cw, sizeof q.cw);
    return form ? rt_edge_filter(ro, ri, &p, &q) : rt_edge_filter_c(ro, ri, &p, &q);
}

void rt_build_slab_masks(int form, const double (*cvT)[RT_BUILD_SPAN + 1], int np,
                         const double (*cw)[3], int nq, uint32_t outq, const double ro[3],
                         const double ri[3], uint32_t *sepm, uint32_t *undm)
{
    if (form)
        rt_slab_masks(cvT, np, cw, nq, outq, ro, ri, sepm, undm);
    else
        rt_slab_masks_c(cvT, np, cw, nq, outq, ro, ri, sepm, undm);
}

/* Triangle t whose cells span two axes with one cell on the third, a (c0[a] == c1[a]), as
 * rt_tri_cells decides, with fewer tests. When the whole triangle lies in that cell's box
 * shrunk by eps on a, the triangle meets a cell of the range exactly when its projection
 * along a meets the cell's rectangle, and the projection's separating axes are the faces of
 * the two other axes, P and Q, and the three axes e_i x X_a of the filter's group a. A cell
 * whose face tests keep it with a margin of eps and whose group-a filter keeps it with a
 * margin of eps (|e_i| on P and Q): the projection meets the rectangle shrunk by eps, so a
 * point of the triangle lies at least eps inside the cell's box on every axis, and every
 * axis of rt_tri_box keeps it (rt_tri_row's argument); no plane test and no other group is
 * needed. A face test or the filter that separates decides as in rt_tri_cells; the cells
 * left between (a margin under eps, or undecided by the filter) get rt_tri_box. Returns 1, 0
 * (no memory), or -1 when the triangle is not inside on a (nothing pushed). */
static int rt_tri_slab(const rt_tri *t, const double e[3][3], const double n[3],
                       const double bb[6], const rt_box *g, const int c0[3], const int c1[3],
                       double eps, rt_build *b, size_t base, size_t prim, int a)
{
    const rt_cell_tab *tab = b->tab && b->tab->box == g ? b->tab : NULL;
    double bca, ha;
    rt_tab_box(tab, g, a, c0[a], eps, &bca, &ha);
    if (!(bb[a] - bca >= eps - ha && bb[3 + a] - bca <= ha - eps))
        return -1;
    const int P = a == 2 ? 0 : a + 1, Q = a == 0 ? 2 : a - 1; /* group a's P and Q */
    double hs[3]; /* rt_tri_cells' hs[a] */
    RT_HALF_S(hs, P, Q);
    double emax = 0.0;
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            emax = rt_dmax(emax, fabs(e[i][k]));
    /* the cells of P (cv: P's terms of group a) and of Q (cw), as rt_axis_cells makes them;
       out: the face test separates, in: it keeps with the margin; L, hmin, hmax as there */
    double cvT[3][RT_SPAN + 1], cw[RT_SPAN][3], bcp[RT_SPAN], hp[RT_SPAN], bcq[RT_SPAN], hq[RT_SPAN];
    uint32_t outp = 0, inp = 0, outq = 0, inq = 0;
    double L[3], hmin[2], hmax[2];
#define RT_SLAB_AXIS(X, O, BCS, HS, OUT, IN, S, TERMS)                                        \
    do {                                                                                       \
        const double o = t->v[0][X], f0 = e[0][O], f1 = e[1][O], f2 = e[2][O];                 \
        double l = rt_dmax(fabs(e[0][X]), fabs(e[2][X])), hn = HUGE_VAL, hx = 0.0;             \
        for (int q = c0[X]; q <= c1[X]; q++) {                                                 \
            const int k = q - c0[X];                                                           \
            double bc, h;                                                                      \
            rt_tab_box(tab, g, X, q, eps, &bc, &h);                                            \
            BCS[k] = bc;                                                                       \
            HS[k] = h;                                                                         \
            const double mn = bb[X] - bc, mx = bb[3 + X] - bc;                                 \
            OUT |= (uint32_t)((mn > h) | (mx < -h)) << k;                                      \
            IN |= (uint32_t)((mn <= h - eps) & (mx >= eps - h)) << k;                          \
            const double d = bc - o;                                                           \
            TERMS;                                                                             \
            l = rt_dmax(l, rt_dmax(fabs(d), h));                                               \
            hn = rt_dmin(hn, h);                                                               \
            hx = rt_dmax(hx, h);                                                               \
        }                                                                                      \
        L[S] = l;                                                                              \
        hmin[S] = hn;                                                                          \
        hmax[S] = hx;                                                                          \
    } while (0)
    RT_SLAB_AXIS(P, Q, bcp, hp, outp, inp, 0,
                 (cvT[0][k] = f0 * d + hs[0], cvT[1][k] = f1 * d + hs[1], cvT[2][k] = f2 * d + hs[2]));
    RT_SLAB_AXIS(Q, P, bcq, hq, outq, inq, 1,
                 (cw[k][0] = f0 * d, cw[k][1] = f1 * d, cw[k][2] = f2 * d));
#undef RT_SLAB_AXIS
    /* the lane after the last cell defined (rt_slab_masks reads cells in pairs) */
    for (int i = 0; i < 3; i++)
        cvT[i][c1[P] - c0[P] + 1] = 0.0;
    L[2] = rt_dmax(rt_dmax(fabs(e[0][a]), fabs(e[2][a])), rt_dmax(fabs(bca - t->v[0][a]), ha));
    /* rt_tri_cells' bounds of group a (B, Dh over the range's cells; a has one cell), the
       inner one less eps (|e_i| on P and Q): the shrunk rectangle's half extent on the axis */
    const double B = __atomic_load_n(&rt_filter_on, __ATOMIC_RELAXED)
                         ? 64.0 * (DBL_EPSILON / 2) * emax * (L[0] + L[1] + L[2]) + 0x1p-1000
                         : HUGE_VAL;
    const double Bi = B + emax * ((hmax[0] - hmin[0]) + (hmax[1] - hmin[1]));
    double ro[3], ri[3];
    for (int i = 0; i < 3; i++) {
        const double aP = fabs(e[i][P]), aQ = fabs(e[i][Q]);
        const double wr = fabs(hs[i]) + (hmax[0] * aQ + hmax[1] * aP);
        ro[i] = wr + B;
        ri[i] = wr - Bi - eps * (aP + aQ);
    }
    /* the filter's answers for every cell of the range, row by row (rt_slab_masks): bit kp of
       sepm[kq], an edge separates; of undm[kq], one is not kept by the inner bound */
    const int np = c1[P] - c0[P] + 1, nq = c1[Q] - c0[Q] + 1;
    uint32_t sepm[RT_SPAN], undm[RT_SPAN];
    rt_slab_masks(cvT, np, cw, nq, outq, ro, ri, sepm, undm);
    const uint32_t all = np == 32 ? ~(uint32_t)0 : ((uint32_t)1 << np) - 1;
    uint64_t nexact = 0;
    int c[3];
    c[a] = c0[a];
    for (int kq = 0; kq < nq; kq++) {
        if (outq >> kq & 1)
            continue;
        /* the cells to take, and among them those rt_tri_box decides: bit sets walked in
           order (the same pushes, in the same order, as a test per cell) */
        uint32_t take = all & ~outp & ~sepm[kq];
        const uint32_t exact = undm[kq] | (inq >> kq & 1 ? ~inp : ~(uint32_t)0);
        c[Q] = c0[Q] + kq;
        while (take) {
            const int kp = __builtin_ctz(take);
            take &= take - 1;
            c[P] = c0[P] + kp;
            if (exact >> kp & 1) {
                double bc[3], h[3];
                bc[a] = bca;
                h[a] = ha;
                bc[P] = bcp[kp];
                h[P] = hp[kp];
                bc[Q] = bcq[kq];
                h[Q] = hq[kq];
                nexact++;
                if (!rt_tri_box(t, e, n, bc, h))
                    continue;
            }
            if (!rt_build_push(b, base + rt_cell_index(g, c), prim))
                return 0;
        }
    }
    if (nexact)
        __atomic_fetch_add(&rt_exact_cells, nexact, __ATOMIC_RELAXED);
    return 1;
}

/* always inlined into rt_insert, its one caller: gcc stopped inlining it when the top
   level's loop changed (bunny commit 280 -> 298 M instructions) */
static inline __attribute__((always_inline)) int
rt_tri_cells(const rt_tri *t, const double e[3][3], const double n[3], const double bb[6],
             const rt_box *g, const int c0[3], const int c1[3], double eps, rt_build *b,
             size_t base, size_t prim)
{
    const int spans = (c0[0] != c1[0]) + (c0[1] != c1[1]) + (c0[2] != c1[2]);
    if (spans == 1) {
        const int a = c0[0] != c1[0] ? 0 : c0[1] != c1[1] ? 1 : 2;
        const int r = rt_tri_row(t, e, n, bb, g, c0, c1, eps, b, base, prim, a);
        if (r >= 0)
            return r;
    }
    for (int a = 0; a < 3 && spans < 3; a++) { /* a row not inside on both: on one of them? */
        const int r = c0[a] == c1[a] ? rt_tri_slab(t, e, n, bb, g, c0, c1, eps, b, base, prim, a)
                                     : -1;
        if (r >= 0)
            return r;
    }
    /* hs[gi][i] = s / 2, s = a.(V_j - V0), a = e_i x X_gi: j = 2 for edge 0 (d = V2 - V0 =
       -e[2] as computed), j = 1 for edges 1 and 2 (d = V1 - V0 = e[0]); a.w = e_i[P] w_Q -
       e_i[Q] w_P, P = gi + 1, Q = gi + 2. Edge 2's value is edge 0's (the same products). */
    double hs[3][3];
    RT_HALF_S(hs[0], 1, 2);
    RT_HALF_S(hs[1], 2, 0);
    RT_HALF_S(hs[2], 0, 1);
    /* ae[a][i]: |e_i| on axis a (the three edges side by side for RT_BOUNDS), emax the
       largest; L[a]: at least |V_k - V0|, |bc - V0| and h on axis a over the
       cells of the range (|V1 - V0| = |e[0]|, |V2 - V0| = |e[2]|) */
    double ae[3][3], emax = 0.0;
    for (int i = 0; i < 3; i++)
        for (int a = 0; a < 3; a++) {
            ae[a][i] = fabs(e[i][a]);
            emax = rt_dmax(emax, ae[a][i]);
        }
    double L[3], hmin[3], hmax[3];
    rt_axis_cell ac[3][RT_SPAN];
    const rt_cell_tab *tab = b->tab && b->tab->box == g ? b->tab : NULL;
    rt_axis_cells(t, e, n, bb, g, c0, c1, eps, hs, ae, 0, tab, ac[0], &L[0], &hmin[0], &hmax[0]);
    rt_axis_cells(t, e, n, bb, g, c0, c1, eps, hs, ae, 1, tab, ac[1], &L[1], &hmin[1], &hmax[1]);
    rt_axis_cells(t, e, n, bb, g, c0, c1, eps, hs, ae, 2, tab, ac[2], &L[2], &hmin[2], &hmax[2]);
    /* the bounds of rt_edge_filter: ro = |s|/2 + rho_max + B, ri = |s|/2 + rho_max - B - Dh,
       rho_max = h_P |e_Q| + h_Q |e_P| with the largest h of the range's cells on P and Q,
       B = 64 u emax (L_x + L_y + L_z) + 2^-1000 (at least 64 u G, G = |e_P| L_Q + |e_Q| L_P),
       Dh = emax * sum (hmax - hmin) >= rho_max - rho_min: above the errors of the filter's and
       rt_tri_box's computations together (docs/RAYTRACING.md, "The build's margin filter");
       the filter off: B infinite, every cell undecided */
    const double B = __atomic_load_n(&rt_filter_on, __ATOMIC_RELAXED)
                         ? 64.0 * (DBL_EPSILON / 2) * emax * (L[0] + L[1] + L[2]) + 0x1p-1000
                         : HUGE_VAL;
    const double Bi = B + emax * ((hmax[0] - hmin[0]) + (hmax[1] - hmin[1]) + (hmax[2] - hmin[2]));
    double ro[3][3], ri[3][3];
    RT_BOUNDS(0, 1, 2);
    RT_BOUNDS(1, 2, 0);
    RT_BOUNDS(2, 0, 1);
    /* memo of the Y group per x (this z slab) and of the Z group per (x, y), as bit masks
       over x (RT_SPAN <= 32): bit ix of *k set when the group of that x is known, of *v when
       it separates (no memset of byte arrays per slab and triangle); a group that the filter
       leaves undecided is not kept (rare: every cell sharing it asks again). The Z memo's
       first 8 rows cleared at once (a fixed size: stores, no loop; a test of the first slab
       per row instead was a branch taken at random) */
    uint32_t gzk[RT_SPAN], gzv[RT_SPAN];
    if (c1[1] - c0[1] < 8) {
        for (int i = 0; i < 8; i++) /* a fixed count: unrolled stores */
            gzk[i] = gzv[i] = 0;
    } else {
        memset(gzk, 0, sizeof gzk);
        memset(gzv, 0, sizeof gzv);
    }
    uint64_t nexact = 0;
    int c[3];
    for (c[2] = c0[2]; c[2] <= c1[2]; c[2]++) {
        rt_axis_cell *z = &ac[2][c[2] - c0[2]];
        if (z->sep)
            continue;
        uint32_t gyk = 0, gyv = 0;
        for (c[1] = c0[1]; c[1] <= c1[1]; c[1]++) {
            const int iy = c[1] - c0[1];
            rt_axis_cell *y = &ac[1][iy];
            if (y->sep)
                continue;
            int gx = 2; /* the X group of this (y, z); 2: not yet known */
            uint32_t zk = gzk[iy], zv = gzv[iy];
            for (c[0] = c0[0]; c[0] <= c1[0]; c[0]++) {
                const int ix = c[0] - c0[0];
                const uint32_t bit = (uint32_t)1 << ix;
                rt_axis_cell *x = &ac[0][ix];
                if (x->sep)
                    continue;
                const double pd = x->nv + y->nv + z->nv;
                if (fabs(pd) > x->nh + y->nh + z->nh)
                    continue;
                if (gx == 2)
                    gx = rt_edge_filter(ro[0], ri[0], y, z);
                if (gx > 0)
                    break; /* the same for every x of this row */
                int und = gx < 0;
                if (!(zk & bit)) {
                    const int r = rt_edge_filter(ro[2], ri[2], x, y);
                    if (r >= 0)
                        zk |= bit;
                    if (r > 0)
                        zv |= bit;
                    und |= r < 0;
                }
                if (zv & bit)
                    continue;
                if (!(gyk & bit)) {
                    const int r = rt_edge_filter(ro[1], ri[1], z, x);
                    if (r >= 0)
                        gyk |= bit;
                    if (r > 0)
                        gyv |= bit;
                    und |= r < 0;
                }
                if (gyv & bit)
                    continue;
                if (und) {
                    const double bc[3] = {x->bc, y->bc, z->bc}, h[3] = {x->h, y->h, z->h};
                    nexact++;
                    if (!rt_tri_box(t, e, n, bc, h))
                        continue;
                }
                if (!rt_build_push(b, base + rt_cell_index(g, c), prim))
                    return 0;
            }
            gzk[iy] = zk;
            gzv[iy] = zv;
        }
    }
    if (nexact)
        __atomic_fetch_add(&rt_exact_cells, nexact, __ATOMIC_RELAXED);
    return 1;
}

/* a primitive's geometry in the grid frame, for the cell tests of rt_insert */
typedef struct rt_ins {
    const rt_prim *p;
    rt_tri tri;                 /* a triangle: its vertices (grid frame), edges and normal */
    double te[3][3], tn[3];
    double n[3], d;             /* the plane (d: other kinds only) */
} rt_ins;

static void rt_ins_init(const rt_scene *sc, const double *pts, const rt_prim *p, rt_ins *q)
{
    const rt_grid *gr = &sc->grid;
    q->p = p;
    if (p->kind != RT_KIND_TRI) { /* a triangle's plane is not used: SAT instead */
        double n0[3], d0;
        rt_prim_plane(sc, p, n0, &d0);
        rt_grid_dir(gr, n0, q->n);
        q->d = gr->rotated ? d0 - (n0[0] * gr->c[0] + n0[1] * gr->c[1] + n0[2] * gr->c[2]) : d0;
        return;
    }
    memcpy(q->tri.v, pts, sizeof q->tri.v);
    /* the edges from pts, not from the copy just stored: a load of the copy spanning two of
       the copy's stores cannot be forwarded from them and waits for the stores */
    for (int j = 0; j < 3; j++) {
        q->te[0][j] = pts[3 + j] - pts[j];
        q->te[1][j] = pts[6 + j] - pts[3 + j];
        q->te[2][j] = pts[j] - pts[6 + j];
    }
    q->tn[0] = q->te[0][1] * q->te[1][2] - q->te[0][2] * q->te[1][1];
    q->tn[1] = q->te[0][2] * q->te[1][0] - q->te[0][0] * q->te[1][2];
    q->tn[2] = q->te[0][0] * q->te[1][1] - q->te[0][1] * q->te[1][0];
}

/* 1 if the surface of q overlaps the box lo..hi (centre bc, half sizes h) */
static int rt_ins_overlaps(const rt_scene *sc, rt_build *b, const rt_ins *q, const double lo[3],
                           const double hi[3], const double bc[3], const double h[3], int *err)
{
    const rt_prim *p = q->p;
    if (p->kind == RT_KIND_TRI)
        return rt_tri_box(&q->tri, q->te, q->tn, bc, h);
    if (!rt_plane_box(q->n, q->d, bc, h))
        return 0;
    if (p->kind != RT_KIND_POLY)
        return rt_loop_box(&b->cb, b->pts, 4, lo, hi, err);
    const rt_poly *po = &sc->poly[p->data];
    size_t at = 0;
    int hit = 0;
    for (uint32_t l = 0; l < po->nloops && !hit && !*err; l++) {
        size_t m = sc->loops[po->loop0 + l];
        hit = rt_loop_box(&b->cb, b->pts + 3 * at, m, lo, hi, err);
        at += m;
    }
    return hit;
}

/* the eps-enlarged cell boxes of cells c0 .. c1 by axis (rt_cell_box's values), for ranges
   shorter than RT_SPAN on every axis */
typedef struct rt_axis_boxes {
    double lo[3][RT_SPAN], hi[3][RT_SPAN], bc[3][RT_SPAN], h[3][RT_SPAN];
} rt_axis_boxes;

static void rt_axis_boxes_init(const rt_box *g, const int c0[3], const int c1[3], double eps,
                               rt_axis_boxes *ab)
{
    for (int a = 0; a < 3; a++)
        for (int q = c0[a]; q <= c1[a]; q++) {
            const double lo = (q == 0 ? g->lo[a] : g->lo[a] + q * g->cw[a]) - eps;
            const double hi = (q == g->n[a] - 1 ? g->hi[a] : g->lo[a] + (q + 1) * g->cw[a]) + eps;
            ab->lo[a][q - c0[a]] = lo;
            ab->hi[a][q - c0[a]] = hi;
            ab->bc[a][q - c0[a]] = 0.5 * (lo + hi);
            ab->h[a][q - c0[a]] = 0.5 * (hi - lo);
        }
}

/* the box of cell c (ab: by axis, from c0; NULL: rt_cell_box) with its centre and half sizes */
static void rt_ins_cell_box(const rt_box *g, const rt_axis_boxes *ab, const int c0[3],
                            const int c[3], double eps, double lo[3], double hi[3], double bc[3],
                            double h[3])
{
    if (ab) {
        for (int a = 0; a < 3; a++) {
            const int q = c[a] - c0[a];
            lo[a] = ab->lo[a][q];
            hi[a] = ab->hi[a][q];
            bc[a] = ab->bc[a][q];
            h[a] = ab->h[a][q];
        }
        return;
    }
    rt_cell_box(g, c, eps, lo, hi);
    for (int a = 0; a < 3; a++) {
        bc[a] = 0.5 * (lo[a] + hi[a]);
        h[a] = 0.5 * (hi[a] - lo[a]);
    }
}

/* adds (base + cell, i) for every cell of box g whose eps-enlarged box the surface of
   primitive i overlaps; geometry is taken into the grid frame of sc first (tv: a triangle's
   three vertices already in the grid frame, as rt_prim_gbox made them; NULL: from the scene) */
static void rt_insert(const rt_scene *sc, rt_build *b, size_t i, const rt_box *g, size_t base,
                      double eps, const double *tv, int *err)
{
    /* a triangle's kind from a constant record (its other fields are not read here): a
       record made on the stack for every insertion was stored in parts and loaded whole,
       a load that waits for the stores */
    static const rt_prim tri_geo = {.kind = RT_KIND_TRI};
    rt_prim pr; /* (q's below: its lifetime) */
    const rt_prim *p = &tri_geo;
    if (i >= sc->ntri) {
        pr = rt_prim_geo(sc, i);
        p = &pr;
    }
    size_t npts = 3;
    const double *pts = tv; /* a triangle's 9 coordinates (tv), or b->pts */
    if (!tv) {
        npts = rt_prim_gpoints(sc, b, i, err);
        if (*err)
            return;
        pts = b->pts;
    }
    double bb[6];
    rt_pts_bbox(pts, npts, bb);
    int c0[3], c1[3];
    for (int a = 0; a < 3; a++) {
        if (bb[a] - eps > g->hi[a] || bb[3 + a] + eps < g->lo[a])
            return;
        c0[a] = rt_cell_of(g, bb[a] - eps, a);
        c1[a] = rt_cell_of(g, bb[3 + a] + eps, a);
    }
    const int single = c0[0] == c1[0] && c0[1] == c1[1] && c0[2] == c1[2];
    if (single) { /* its enlarged box lies in one cell: it overlaps that cell, no test needed */
        if (!rt_build_push(b, base + rt_cell_index(g, c0), i))
            *err = 1;
        return;
    }
    rt_ins q;
    rt_ins_init(sc, pts, p, &q);
    const int by_axis = c1[0] - c0[0] < RT_SPAN && c1[1] - c0[1] < RT_SPAN &&
                        c1[2] - c0[2] < RT_SPAN;
    if (p->kind == RT_KIND_TRI && by_axis) {
        if (!rt_tri_cells(&q.tri, q.te, q.tn, bb, g, c0, c1, eps, b, base, i))
            *err = 1;
        return;
    }
    rt_axis_boxes ab;
    if (by_axis)
        rt_axis_boxes_init(g, c0, c1, eps, &ab);
    int c[3];
    for (c[2] = c0[2]; c[2] <= c1[2] && !*err; c[2]++)
        for (c[1] = c0[1]; c[1] <= c1[1] && !*err; c[1]++)
            for (c[0] = c0[0]; c[0] <= c1[0] && !*err; c[0]++) {
                double lo[3], hi[3], bc[3], h[3];
                rt_ins_cell_box(g, by_axis ? &ab : NULL, c0, c, eps, lo, hi, bc, h);
                if (rt_ins_overlaps(sc, b, &q, lo, hi, bc, h, err) &&
                    !rt_build_push(b, base + rt_cell_index(g, c), i))
                    *err = 1;
            }
}

/* pairs -> CSR (stable: primitive order kept within a cell) */
static int rt_csr(const rt_build *b, size_t ncells, uint32_t **offp, uint32_t **refsp)
{
    uint32_t *off = rt_calloc_array(ncells + 1, sizeof(uint32_t));
    uint32_t *refs = rt_alloc_array(b->npairs, sizeof(uint32_t));
    if (!off || !refs) {
        free(off);
        free(refs);
        return RT_ERR_NOMEM;
    }
    for (size_t k = 0; k < b->npairs; k++)
        off[b->pairs[k].cell + 1]++;
    for (size_t k = 0; k < ncells; k++)
        off[k + 1] += off[k];
    for (size_t k = 0; k < b->npairs; k++)
        refs[off[b->pairs[k].cell]++] = b->pairs[k].prim;
    for (size_t k = ncells; k > 0; k--)
        off[k] = off[k - 1];
    off[0] = 0;
    *offp = off;
    *refsp = refs;
    return RT_OK;
}

/* The top level in chunks of consecutive primitives taken dynamically by the parts (a shared
 * counter: a faster core takes more of them), each chunk with its own pairs and its own count
 * of them per cell; the counts give each chunk's place in every cell's list (after the chunks
 * before it), so the chunks scatter their references in parallel into the arrays one part
 * would give. RT_TOP_CHUNKS chunks per part while their counts take at most 8 bytes per
 * primitive, fewer (down to one per part) where cells are many. */
#define RT_TOP_CHUNKS 16

typedef struct rt_top_chunk {
    rt_pair *pairs;
    size_t npairs, cap;
    uint32_t *cnt; /* per cell: its pairs there, then its first place in the cell's list */
    int err;
} rt_top_chunk;

typedef struct rt_top_job {
    const rt_scene *sc;
    rt_build *b; /* per part */
    rt_top_chunk *chunk;
    size_t nchunks;
    size_t next; /* atomic: the next chunk to take (insertion), then to scatter */
    double eps;
    uint32_t *refs;
    const rt_cell_tab *tab; /* the top grid's cell boxes (at most RT_TAB cells per axis), or NULL */
} rt_top_job;

static void rt_top_insert(void *arg, int k, int n)
{
    (void)n;
    rt_top_job *j = arg;
    const rt_grid *g = &j->sc->grid;
    rt_build *b = &j->b[k];
    b->tab = j->tab;
    size_t q;
    while ((q = __atomic_fetch_add(&j->next, 1, __ATOMIC_RELAXED)) < j->nchunks) {
        rt_top_chunk *ch = &j->chunk[q];
        size_t lo, hi;
        rt_par_range(j->sc->nprim, (int)q, (int)j->nchunks, &lo, &hi);
        /* the part's scratch collects the chunk's pairs, which the chunk then keeps */
        b->pairs = NULL;
        b->npairs = b->cap = 0;
        int err = 0;
        for (size_t i = lo; i < hi && !err; i++)
            rt_insert(j->sc, b, i, &g->b, 0, j->eps, NULL, &err);
        ch->pairs = b->pairs;
        ch->npairs = b->npairs;
        ch->cap = b->cap;
        b->pairs = NULL;
        b->npairs = b->cap = 0;
        if (!err && j->nchunks > 1) {
            ch->cnt = rt_calloc_array(g->ncells, sizeof(uint32_t));
            if (!ch->cnt)
                err = 1;
            for (size_t p = 0; p < ch->npairs && !err; p++)
                ch->cnt[ch->pairs[p].cell]++;
        }
        ch->err = err;
    }
    b->tab = NULL;
}

static void rt_top_scatter(void *arg, int k, int n)
{
    (void)k;
    (void)n;
    rt_top_job *j = arg;
    size_t q;
    while ((q = __atomic_fetch_add(&j->next, 1, __ATOMIC_RELAXED)) < j->nchunks) {
        const rt_top_chunk *ch = &j->chunk[q];
        uint32_t *at = ch->cnt;
        for (size_t p = 0; p < ch->npairs; p++)
            j->refs[at[ch->pairs[p].cell]++] = ch->pairs[p].prim;
    }
}

static int rt_top_level(rt_scene *sc, rt_build *bs, int nt, double eps)
{
    rt_grid *g = &sc->grid;
    /* per-chunk counts cost 4 B per cell and chunk: at most 8 B per primitive (with the
       default resolution rule, cells are a fraction of the primitives) */
    size_t nchunks = 1;
    if (nt > 1 && sc->nprim >= 2 * (size_t)nt) {
        nchunks = (size_t)RT_TOP_CHUNKS * (size_t)nt;
        while (nchunks > (size_t)nt && (double)nchunks * (double)g->ncells >
                                             2.0 * (double)sc->nprim + 65536.0)
            nchunks /= 2;
        if ((double)nchunks * (double)g->ncells > 2.0 * (double)sc->nprim + 65536.0 ||
            nchunks > sc->nprim)
            nchunks = 1;
    }
    if (nchunks == 1)
        nt = 1;
    rt_top_job job;
    memset(&job, 0, sizeof job);
    job.sc = sc;
    job.b = bs;
    job.eps = eps;
    job.nchunks = nchunks;
    /* the cell boxes from a table, as in the second level's grids, where it fits: a load
       each instead of rt_axis_box's products and end tests */
    rt_cell_tab tab;
    if (g->b.n[0] <= RT_TAB && g->b.n[1] <= RT_TAB && g->b.n[2] <= RT_TAB) {
        rt_tab_fill(&tab, &g->b, eps);
        job.tab = &tab;
    }
    job.chunk = rt_calloc_array(nchunks, sizeof(rt_top_chunk));
    if (!job.chunk)
        return RT_ERR_NOMEM;
    rt_par_run(nt, rt_top_insert, &job);
    int rc = RT_OK;
    size_t total = 0;
    for (size_t q = 0; q < nchunks; q++) {
        if (job.chunk[q].err)
            rc = RT_ERR_NOMEM;
        total += job.chunk[q].npairs;
    }
    if (rc == RT_OK && total > UINT32_MAX - 1)
        rc = RT_ERR_LIMIT;
    if (rc == RT_OK && nchunks == 1) {
        g->nrefs = total;
        rt_build one = {.pairs = job.chunk[0].pairs, .npairs = job.chunk[0].npairs};
        rc = rt_csr(&one, g->ncells, &g->off, &g->refs);
    } else if (rc == RT_OK) {
        g->off = rt_alloc_array(g->ncells + 1, sizeof(uint32_t));
        g->refs = job.refs = rt_alloc_array(total, sizeof(uint32_t));
        if (!g->off || !g->refs)
            rc = RT_ERR_NOMEM;
        uint32_t run = 0;
        for (size_t c = 0; c < g->ncells && rc == RT_OK; c++) {
            g->off[c] = run;
            for (size_t q = 0; q < nchunks; q++) {
                const uint32_t m = job.chunk[q].cnt[c];
                job.chunk[q].cnt[c] = run;
                run += m;
            }
        }
        if (rc == RT_OK) {
            g->off[g->ncells] = run;
            g->nrefs = total;
            job.next = 0;
            rt_par_run(nt, rt_top_scatter, &job);
        }
    }
    for (size_t q = 0; q < nchunks; q++) { /* the second level needs one grid's pairs at a time */
        free(job.chunk[q].cnt);
        free(job.chunk[q].pairs);
    }
    free(job.chunk);
    return rc;
}

/* Second level (measured: docs/bench/rt_tuning.md). A top cell holding more than RT_SUB_MIN references is
 * split into "large" primitives (their part inside the cell spans at least half the cell in
 * two axes: floors, walls crossing the cell) that stay in the top cell's list, and the rest,
 * which get their own grid of about RT_SUB_FACTOR cells per reference (at most 32 per axis)
 * over the box of their parts inside the cell. So a small dense object standing on a huge
 * floor (teapot in a stadium) is resolved by a grid around the object, not around the cell.
 * Traversal tests a cell's list first, then walks its second-level grid. */
#define RT_SUB_MIN 8
#define RT_SUB_FACTOR 3.0
#define RT_SUB_FACTOR_LARGE 4.0 /* beyond RT_GRID_KNEE primitives (gksrt.h) */
/* Flat sub-grids (beyond RT_GRID_KNEE primitives, default sub_factor): a sub-grid whose
 * resolution gives one axis 1 cell (a nearly planar patch in the cell, as on the fandisk's
 * faces lying near grid planes) gets RT_SUB_FLAT1 times the cells, one with 2 cells on its
 * thinnest axis RT_SUB_FLAT2 times. Spread over two axes, sub_factor cells per reference make
 * cells much smaller than the triangles (fandisk: 2.7 cells per longest edge against the
 * bunny's 1.8, 1.9 references per cell in its 138 one-cell-thick sub-grids, 5.9 cells per
 * triangle in a sub-grid against 4.3): fandisk 91.6 -> 87.2 B/tri for 0.4-0.6 % more
 * single-ray instructions and 0.9-1.5 % fewer for packets (docs/bench/rt_tuning.md,
 * 2026-12-06). */
#define RT_SUB_FLAT1 0.5
#define RT_SUB_FLAT2 0.7

/* bounding box of primitive i in the grid frame (its points in the frame left in b->pts) */
static void rt_prim_gbox(const rt_scene *sc, rt_build *b, size_t i, double bb[6], int *err)
{
    size_t npts = rt_prim_gpoints(sc, b, i, err);
    rt_pts_bbox(b->pts, npts, bb);
}

/* The second level in chunks of consecutive top cells taken dynamically (the VM's vCPUs, and
 * any machine's cores under other load, run at unequal speeds, which a static split cannot
 * follow). Part 0 (the caller) takes chunks from the front of the top cells, the other parts
 * from the back; each take is a share of the references left (1/(2n) of them, at least
 * RT_SUB_CHUNK_MIN references), so the chunks shrink towards the meeting point and the parts
 * end together. Part k makes the grids of its chunks into its own arrays, cells and
 * references counted from its own first ones; chunk records say where. The chunks are then
 * laid out one after the other in cell order, which gives the arrays one part would give
 * whatever the chunks were: part 0's chunks are the front, so its arrays become the grid's
 * (rt_big: grown in place) and the others' chunks are copied behind them (rt_sub_place).
 * Each grid's (cell, primitive) pairs are sorted into the part's cell offsets and references
 * as soon as the grid is made (the pair scratch holds one grid's pairs only). */
#define RT_SUB_CHUNKS 512       /* chunk records at most at each end (then the rest at once) */
#define RT_SUB_CHUNK_MIN 4096.0 /* references: the smallest chunk while more are left */
#define RT_SUB_CELL_BITS 26     /* the take state's fields: top cells < 2^26 (2^25 at most) */

typedef struct rt_sub_part {
    rt_subgrid *subs;    /* its grids (first: counted from its first sub cell) */
    size_t capsubs;
    size_t nsubs, total; /* grids, their cells */
    rt_big off, refs;    /* uint32: per sub cell its first reference (counted from the part's
                            first), the references; total and nref of them */
    size_t nref;
    rt_big loc;          /* uint32, with rt_sub_job.local: its grids' tables of primitives
                            (rt_sub_csr), nloc entries */
    size_t nloc;
    int err;             /* 1: no memory, 2: too many cells */
    char pad[RT_LINE];   /* the next part on other cache lines (RT_LINE) */
} rt_sub_part;

typedef struct rt_sub_chunk {
    size_t c0, c1;               /* top cells [c0, c1) */
    int part;                    /* the part whose arrays hold its grids */
    uint32_t loc_l;              /* its first table entry there (rt_sub_job.local) */
    size_t sub_l, cell_l, ref_l; /* its first grid, sub cell and reference there */
    size_t nsubs, ncell, nref;
    size_t sub0, cell0, ref0;    /* its first grid, sub cell and reference in the grid's */
    uint32_t nloc, loc0;         /* its table entries, the first in the grid's (fewer than
                                    references, so 32 bits: the records stay small) */
} rt_sub_chunk;

typedef struct rt_sub_job {
    rt_scene *sc;
    rt_build *b;         /* per part */
    rt_sub_part *part;
    uint8_t *keep;       /* per top reference: stays in the top cell's list */
    double eps, sub_factor;
    double flat[2];      /* factors of sub_factor for 1 and 2 cells on the thinnest axis */
    int sub_min;
    int nparts;
    int local;           /* references as indices into each grid's table (rt_sub_csr) */
    double chunk_min;    /* references */
    uint64_t state;      /* atomic: cells [lo, hi) left, lo | hi << 26 | back chunks << 52 */
    rt_sub_chunk *front; /* part 0's chunks in cell order, nfront of them */
    size_t nfront;
    rt_sub_chunk *back;  /* the others', in the order taken (cell order reversed) */
    size_t nback;        /* after the run */
    size_t front_max;    /* part 0's chunks at most (0: no limit; rt_build_set_chunks) */
} rt_sub_job;

/* where triangle i's 9 grid-frame coordinates lie in order in the scene's arrays (a plain
   triangle's own in an unrotated grid; a mesh triangle's consecutive vertices, in the arrays
   of the grid's frame), or NULL */
static inline const double *rt_tri_in_frame(const rt_scene *sc, const rt_build *b, size_t i)
{
    if (i < sc->ntri_plain)
        return sc->grid.rotated ? NULL : sc->tri[i].v[0];
    if (sc->grid.rotated && !b->gv)
        return NULL;
    const uint32_t *ix = sc->ctri[i - sc->ntri_plain], vm = sc->vmask, v0 = ix[0] & vm;
    if ((ix[1] & vm) != v0 + 3 || (ix[2] & vm) != v0 + 6)
        return NULL;
    return (b->gv ? b->gv : (const double *)sc->mv_xyz.p) + v0;
}

/* The references of top cell ci (eps-enlarged box lo .. hi): keep[r] = 1 for the large ones
 * (their part in the cell spans at least half of it in two axes; they stay in the cell's
 * list), sb grown by the parts of the others, whose number is returned; where the triangles'
 * grid-frame vertices are into b->tv (per reference, in list order) for their insertion into
 * the sub-grid (the values rt_insert would compute again: one gather and rotation per
 * reference less): gathered into b->tpts, or with in_place (a widened top level: large
 * triangles, as in a soup of unshared ones) in the scene's arrays where they hold the 9
 * coordinates in order (a plain triangle in an unrotated grid; a mesh triangle whose vertices
 * are consecutive, in the arrays of the grid's frame): the gather's stores and loads less
 * (random triangles: 6-7 % fewer first-level misses in the build); not on the meshes, whose
 * shared vertices are consecutive now and then: the test and its mispredicts cost their
 * commits about 1 % (docs/bench/rt_tuning.md, 2026-12-06). */
static inline __attribute__((always_inline)) uint32_t
rt_sub_classify(const rt_scene *sc, rt_build *b, size_t ci, const double lo[3], const double hi[3],
                double eps, int in_place, uint8_t *keep, double sb[6], int *err)
{
    const rt_grid *g = &sc->grid;
    uint32_t nsmall = 0;
    const size_t n = g->off[ci + 1] - g->off[ci];
    if (!rt_grow((void **)&b->tpts, &b->captpts, 9 * n, sizeof(double)) ||
        (in_place && !rt_grow((void **)&b->tv, &b->captv, n ? n : 1, sizeof *b->tv))) {
        *err = 1;
        return 0;
    }
    for (uint32_t r = g->off[ci]; r < g->off[ci + 1] && !*err; r++) {
        double bb[6];
        const size_t i = g->refs[r];
        if (i < sc->ntri) { /* rt_prim_gpoints' values, made in place */
            double *tp = b->tpts + 9 * (size_t)(r - g->off[ci]);
            const double *tv = in_place ? rt_tri_in_frame(sc, b, i) : NULL;
            if (!tv && b->gv && i >= sc->ntri_plain) {
                const uint32_t *ix = sc->ctri[i - sc->ntri_plain], vm = sc->vmask;
                memcpy(tp, b->gv + (ix[0] & vm), 3 * sizeof(double));
                memcpy(tp + 3, b->gv + (ix[1] & vm), 3 * sizeof(double));
                memcpy(tp + 6, b->gv + (ix[2] & vm), 3 * sizeof(double));
            } else if (!tv) {
                rt_tri_copy(sc, i, tp);
                for (int k = 0; k < 3 && g->rotated; k++)
                    rt_grid_point(g, tp + 3 * k, tp + 3 * k);
            }
            if (!tv)
                tv = tp;
            if (in_place)
                b->tv[r - g->off[ci]] = tv;
            rt_pts_bbox(tv, 3, bb);
        } else {
            rt_prim_gbox(sc, b, g->refs[r], bb, err);
        }
        int span = 0;
        for (int a = 0; a < 3; a++) {
            bb[a] = rt_dmax(bb[a] - eps, lo[a]);
            bb[3 + a] = rt_dmin(bb[3 + a] + eps, hi[a]);
            span += bb[3 + a] - bb[a] >= 0.5 * (hi[a] - lo[a]);
        }
        keep[r] = span >= 2;
        if (keep[r])
            continue;
        nsmall++;
        for (int a = 0; a < 3; a++) {
            sb[a] = rt_dmin(sb[a], bb[a]);
            sb[3 + a] = rt_dmax(sb[3 + a], bb[3 + a]);
        }
    }
    return nsmall;
}

/* the next chunk of part k into *ch (cells, and for the back its record's index in *slot):
   1, or 0 when no cells are left */
static int rt_sub_take(rt_sub_job *j, int k, size_t *c0, size_t *c1, size_t *slot)
{
    const uint32_t *off = j->sc->grid.off;
    const uint64_t mask = ((uint64_t)1 << RT_SUB_CELL_BITS) - 1;
    uint64_t s = __atomic_load_n(&j->state, __ATOMIC_ACQUIRE);
    for (;;) {
        const size_t lo = (size_t)(s & mask), hi = (size_t)(s >> RT_SUB_CELL_BITS & mask);
        const size_t nb = (size_t)(s >> (2 * RT_SUB_CELL_BITS));
        if (lo >= hi)
            return 0;
        double want = (double)(off[hi] - off[lo]) / (2.0 * j->nparts);
        if (want < j->chunk_min)
            want = j->chunk_min;
        size_t a = lo, e = hi, l, h;
        uint64_t ns;
        if (k == 0 && j->nparts > 1 && j->front_max && j->nfront >= j->front_max)
            return 0;
        if (k == 0) { /* the first e > lo with off[e] - off[lo] >= want */
            if (j->nparts > 1 && j->nfront < RT_SUB_CHUNKS - 1) {
                for (l = lo + 1, h = hi; l < h;) {
                    const size_t m = l + (h - l) / 2;
                    if ((double)(off[m] - off[lo]) < want)
                        l = m + 1;
                    else
                        h = m;
                }
                e = l;
            }
            ns = (uint64_t)e | (uint64_t)hi << RT_SUB_CELL_BITS |
                 (uint64_t)nb << (2 * RT_SUB_CELL_BITS);
        } else { /* the last a < hi with off[hi] - off[a] >= want */
            if (nb < RT_SUB_CHUNKS - 1) {
                for (l = lo, h = hi - 1; l < h;) {
                    const size_t m = h - (h - l) / 2;
                    if ((double)(off[hi] - off[m]) < want)
                        h = m - 1;
                    else
                        l = m;
                }
                a = l;
            }
            ns = (uint64_t)lo | (uint64_t)a << RT_SUB_CELL_BITS |
                 (uint64_t)(nb + 1) << (2 * RT_SUB_CELL_BITS);
        }
        if (__atomic_compare_exchange_n(&j->state, &s, ns, 0, __ATOMIC_ACQ_REL,
                                        __ATOMIC_ACQUIRE)) {
            *c0 = a;
            *c1 = e;
            *slot = k == 0 ? j->nfront++ : nb;
            return 1;
        }
    }
}

/* the resolution of sub-grid box sb for nsmall references: sub_factor cells per reference,
   fewer when it comes out flat (RT_SUB_FLAT1, RT_SUB_FLAT2) */
static void rt_sub_resolution(rt_box *sb, const rt_sub_job *j, uint32_t nsmall)
{
    rt_box_resolution(sb, j->sub_factor * nsmall, RT_TAB); /* RT_TAB: rt_cell_tab */
    int thin = sb->n[0] < sb->n[1] ? sb->n[0] : sb->n[1];
    thin = thin < sb->n[2] ? thin : sb->n[2];
    if (thin <= 2 && j->flat[thin - 1] != 1.0)
        rt_box_resolution(sb, j->flat[thin - 1] * j->sub_factor * nsmall, RT_TAB);
}

/* The pairs of the sub-grid just filled (nc cells from the part's cell total) into the part's
 * CSR arrays, stable (reference order kept within a cell): its entries of off serve as
 * counts, then as cursors. With loc (rt_sub_job.local) the grid's table of primitives as well:
 * the primitives that got a pair, in the order of their insertion, into loc, and as
 * references their indices there. One insertion's pairs are consecutive and two consecutive
 * insertions are of different primitives (a top cell lists each once), so a pair's index is
 * the number of changes of primitive before it, counted without a branch; returns the
 * table's length (0 without loc). */
static uint32_t rt_sub_csr(rt_sub_part *pt, const rt_build *b, size_t total, size_t nc,
                           uint32_t *loc)
{
    uint32_t *off = (uint32_t *)pt->off.p + total, *refs = pt->refs.p;
    memset(off, 0, nc * sizeof *off);
    for (size_t q = 0; q < b->npairs; q++)
        off[b->pairs[q].cell]++;
    uint32_t run = (uint32_t)pt->nref;
    for (size_t c = 0; c < nc; c++) {
        const uint32_t m = off[c];
        off[c] = run;
        run += m;
    }
    uint32_t l = 0;
    if (loc && b->npairs) {
        uint32_t prev = b->pairs[0].prim;
        for (size_t q = 0; q < b->npairs; q++) {
            const uint32_t i = b->pairs[q].prim;
            l += i != prev;
            prev = i;
            loc[l] = i;
            refs[off[b->pairs[q].cell]++] = l;
        }
        l++;
    } else {
        for (size_t q = 0; q < b->npairs; q++)
            refs[off[b->pairs[q].cell]++] = b->pairs[q].prim;
    }
    for (size_t c = nc; c > 1; c--) /* off[c - 1] is now the start of c */
        off[c - 1] = off[c - 2];
    off[0] = (uint32_t)pt->nref;
    pt->nref = run;
    return l;
}

/* the grids of the crowded cells of chunk ch into part k's arrays */
static int rt_sub_chunk_run(rt_sub_job *j, int k, rt_sub_chunk *ch, rt_cell_tab *tab)
{
    rt_sub_part *pt = &j->part[k];
    rt_build *b = &j->b[k];
    rt_scene *sc = j->sc;
    rt_grid *g = &sc->grid;
    const double eps = j->eps;
    const uint32_t sub_min = (uint32_t)j->sub_min;
    uint8_t *keep = j->keep;
    ch->part = k;
    ch->sub_l = pt->nsubs;
    ch->cell_l = pt->total;
    ch->ref_l = pt->nref;
    ch->loc_l = (uint32_t)pt->nloc;
    /* room for the chunk's grids, cells and references at once, so that they grow without
       copies (realloc): about sub_factor cells per reference of a crowded cell, and twice as
       many references as cells (1.07-1.42 times on the meshes, 2.0-2.1 on random triangles,
       which grew by a copy of the whole array with room for as many as cells: 0.26 M of 41 M
       instructions at 10^4); a larger chunk grows on from there, a failed reservation is
       only a lost head start; the unused room is not counted at rest and, beyond a few
       pages, never touched */
    size_t ns = 0, crowded = 0;
    for (size_t ci = ch->c0; ci < ch->c1; ci++) {
        const uint32_t cnt = g->off[ci + 1] - g->off[ci];
        ns += cnt > sub_min;
        crowded += cnt > sub_min ? cnt : 0;
    }
    if (!rt_grow((void **)&pt->subs, &pt->capsubs, pt->nsubs + ns + 1, sizeof(rt_subgrid)))
        return 1;
    const size_t want = (size_t)(j->sub_factor * (double)crowded) + 1;
    (void)(rt_big_grow(&pt->off, pt->total + want, sizeof(uint32_t)) &&
           rt_big_grow(&pt->refs, pt->nref + 2 * want, sizeof(uint32_t)));
    size_t total = pt->total;
    int err = 0;
    const size_t n0 = (size_t)g->b.n[0], n01 = n0 * (size_t)g->b.n[1];
    for (size_t ci = ch->c0; ci < ch->c1 && !err; ci++) {
        uint32_t cnt = g->off[ci + 1] - g->off[ci];
        g->sub[ci] = -1;
        if (cnt <= sub_min)
            continue;
        const int c[3] = {(int)(ci % n0), (int)(ci % n01 / n0), (int)(ci / n01)};
        double lo[3], hi[3], sb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
        /* the enlarged cell box: the top-level walk places a ray in this cell when
           it is within rounding of it (a point on a cell plane computed as 2e-16
           beyond 0 is in the cell by its index), and a ray with a direction
           component exactly 0 is then clipped to the sub box exactly: clipped to the
           cell box itself, the second-level grid was skipped for it */
        rt_cell_box(&g->b, c, eps, lo, hi);
        /* one copy of the classification for each (in_place a constant) */
        const uint32_t nsmall = j->local ? rt_sub_classify(sc, b, ci, lo, hi, eps, 1, keep, sb, &err)
                                         : rt_sub_classify(sc, b, ci, lo, hi, eps, 0, keep, sb, &err);
        if (nsmall <= sub_min || err) {
            for (uint32_t r = g->off[ci]; r < g->off[ci + 1]; r++)
                keep[r] = 1;
            continue;
        }
        rt_subgrid *sg = &pt->subs[pt->nsubs];
        g->sub[ci] = (int32_t)pt->nsubs++;
        for (int a = 0; a < 3; a++) { /* sub box: the small parts, at least eps thick */
            double mid = 0.5 * (sb[a] + sb[3 + a]);
            sg->b.lo[a] = rt_dmax(lo[a], rt_dmin(sb[a], mid - eps));
            sg->b.hi[a] = rt_dmin(hi[a], rt_dmax(sb[3 + a], mid + eps));
        }
        rt_sub_resolution(&sg->b, j, nsmall);
        rt_box_finish(&sg->b);
        size_t nc = (size_t)sg->b.n[0] * sg->b.n[1] * sg->b.n[2];
        if (total + nc > UINT32_MAX - 1) {
            err = 2;
            break;
        }
        sg->first = (uint32_t)total;
        b->npairs = 0;
        rt_tab_fill(tab, &sg->b, eps);
        b->tab = tab;
        for (uint32_t r = g->off[ci]; r < g->off[ci + 1] && !err; r++)
            if (!keep[r]) {
                const int tri = g->refs[r] < sc->ntri;
                const double *tv = !tri      ? NULL
                                   : j->local ? b->tv[r - g->off[ci]]
                                              : b->tpts + 9 * (size_t)(r - g->off[ci]);
                rt_insert(sc, b, g->refs[r], &sg->b, 0, eps, tv, &err);
            }
        b->tab = NULL;
        if (!err && pt->nref + b->npairs > UINT32_MAX - 1)
            err = 2;
        if (!err && (!rt_big_grow(&pt->off, total + nc, sizeof(uint32_t)) ||
                     !rt_big_grow(&pt->refs, pt->nref + b->npairs, sizeof(uint32_t)) ||
                     (j->local && !rt_big_grow(&pt->loc, pt->nloc + nsmall, sizeof(uint32_t)))))
            err = 1;
        if (err)
            break;
        sg->loc0 = (uint32_t)pt->nloc; /* counted from the part's first entry */
        pt->nloc += rt_sub_csr(pt, b, total, nc, j->local ? (uint32_t *)pt->loc.p + pt->nloc : NULL);
        total += nc;
    }
    pt->total = total;
    ch->nsubs = pt->nsubs - ch->sub_l;
    ch->ncell = pt->total - ch->cell_l;
    ch->nref = pt->nref - ch->ref_l;
    ch->nloc = (uint32_t)(pt->nloc - ch->loc_l);
    return err;
}

static void rt_sub_cells(void *arg, int k, int n)
{
    (void)n;
    rt_sub_job *j = arg;
    rt_sub_part *pt = &j->part[k];
    j->b[k].npairs = 0;
    rt_cell_tab tab; /* the cell boxes of the sub-grid being filled (rt_tri_cells) */
    size_t c0, c1, slot;
    while (!pt->err && rt_sub_take(j, k, &c0, &c1, &slot)) {
        rt_sub_chunk *ch = k == 0 ? &j->front[slot] : &j->back[slot];
        ch->c0 = c0;
        ch->c1 = c1;
        pt->err = rt_sub_chunk_run(j, k, ch, &tab);
    }
    if (pt->err) /* the others stop at their next take */
        __atomic_store_n(&j->state, 0, __ATOMIC_RELEASE);
}

/* [*a, *e): the part of [lo, hi) that lies in [from, from + len); 1 if it is not empty */
static inline int rt_span_cut(size_t lo, size_t hi, size_t from, size_t len, size_t *a, size_t *e)
{
    *a = lo > from ? lo : from;
    *e = hi < from + len ? hi : from + len;
    return *a < *e;
}

/* The grid's arrays are part 0's grown to the whole (rt_big: in place); the chunks of the
 * other parts (the back chunks) are copied behind part 0's, cell offsets shifted from their
 * part's references to the grid's. Thread k of n copies the k-th n-th of the cells after part
 * 0's and of the references after part 0's. */
static void rt_sub_place(void *arg, int k, int n)
{
    rt_sub_job *j = arg;
    rt_grid *g = &j->sc->grid;
    const rt_sub_part *part = j->part;
    uint32_t *soff = g->soff_m.p, *srefs = g->srefs_m.p;
    size_t lo, hi, a, e;
    rt_par_range(g->nsubcells - part[0].total, k, n, &lo, &hi);
    for (size_t q = 0; q < j->nback; q++) {
        const rt_sub_chunk *ch = &j->back[q];
        if (!rt_span_cut(lo + part[0].total, hi + part[0].total, ch->cell0, ch->ncell, &a, &e))
            continue;
        const uint32_t *off = (const uint32_t *)part[ch->part].off.p + ch->cell_l;
        const uint32_t shift = (uint32_t)ch->ref0 - (uint32_t)ch->ref_l; /* mod 2^32 */
        for (size_t c = a; c < e; c++)
            soff[c] = off[c - ch->cell0] + shift;
    }
    rt_par_range(g->nsrefs - part[0].nref, k, n, &lo, &hi);
    for (size_t q = 0; q < j->nback; q++) {
        const rt_sub_chunk *ch = &j->back[q];
        if (rt_span_cut(lo + part[0].nref, hi + part[0].nref, ch->ref0, ch->nref, &a, &e))
            memcpy(srefs + a,
                   (const uint32_t *)part[ch->part].refs.p + ch->ref_l + (a - ch->ref0),
                   (e - a) * sizeof(uint32_t));
    }
}

/* the chunks' places in the grid's arrays (front chunks, then back chunks in cell order: the
   reverse of their taking), their sub-grids into g->subs (first cells shifted) and their top
   cells' grid indices shifted; the totals into *nsubs, *total, *nref */
static void rt_sub_merge(rt_sub_job *j, size_t *nsubs, size_t *total, size_t *nref, size_t *nloc)
{
    size_t s = 0, c = 0, r = 0, l = 0;
    for (size_t q = 0; q < j->nfront + j->nback; q++) {
        rt_sub_chunk *ch = q < j->nfront ? &j->front[q] : &j->back[j->nback - 1 - (q - j->nfront)];
        ch->sub0 = s;
        ch->cell0 = c;
        ch->ref0 = r;
        ch->loc0 = (uint32_t)l;
        s += ch->nsubs;
        c += ch->ncell;
        r += ch->nref;
        l += ch->nloc;
    }
    *nsubs = s;
    *total = c;
    *nref = r;
    *nloc = l;
}

static void rt_sub_merge_subs(rt_grid *g, const rt_sub_job *j)
{
    for (size_t q = 0; q < j->nfront + j->nback; q++) {
        const rt_sub_chunk *ch = q < j->nfront ? &j->front[q] : &j->back[q - j->nfront];
        const rt_subgrid *from = j->part[ch->part].subs + ch->sub_l;
        const uint32_t shift = (uint32_t)ch->cell0 - (uint32_t)ch->cell_l; /* mod 2^32 */
        const uint32_t lshift = (uint32_t)ch->loc0 - (uint32_t)ch->loc_l;
        for (size_t i = 0; i < ch->nsubs; i++) {
            g->subs[ch->sub0 + i] = from[i];
            g->subs[ch->sub0 + i].first += shift;
            g->subs[ch->sub0 + i].loc0 += lshift;
        }
        if (g->sloc && ch->nloc)
            memcpy(g->sloc + ch->loc0, (const uint32_t *)j->part[ch->part].loc.p + ch->loc_l,
                   ch->nloc * sizeof(uint32_t));
        if (ch->sub0 == ch->sub_l)
            continue;
        for (size_t ci = ch->c0; ci < ch->c1; ci++)
            if (g->sub[ci] >= 0)
                g->sub[ci] = (int32_t)((size_t)g->sub[ci] - ch->sub_l + ch->sub0);
    }
}

/* top lists: only the references kept (keep[k] != 0), compacted in place */
static void rt_top_compact(rt_grid *g, const uint8_t *keep)
{
    uint32_t w = 0;
    for (size_t ci = 0; ci < g->ncells; ci++) {
        uint32_t k0 = g->off[ci], k1 = g->off[ci + 1];
        g->off[ci] = w;
        for (uint32_t k = k0; k < k1; k++)
            if (keep[k])
                g->refs[w++] = g->refs[k];
    }
    g->off[g->ncells] = w;
    g->nrefs = w;
}

/* Every sub-grid's first reference (ref0); then, when no sub-grid has more than 65535
 * references, the second level's 2-byte layout (rt_grid.soff16): each sub-grid's cell offsets
 * relative to its ref0, its cells + 1 of them (the last its end), written over the 4-byte
 * offsets, whose storage is then cut to the 2-byte array's size: 2 B per sub cell instead of
 * 4, the same lists, no second array. With a larger sub-grid the 4-byte layout stays (the walk
 * reads either). */
static void rt_sub_narrow(rt_grid *g)
{
    int narrow = g->nsubcells + g->nsubs <= UINT32_MAX; /* first16 fits in 32 bits */
    for (size_t k = 0; k < g->nsubs; k++) {
        rt_subgrid *sg = &g->subs[k];
        const size_t nc = (size_t)sg->b.n[0] * (size_t)sg->b.n[1] * (size_t)sg->b.n[2];
        sg->ref0 = g->soff[sg->first];
        sg->first16 = sg->first + (uint32_t)k;
        narrow &= g->soff[sg->first + nc] - sg->ref0 <= UINT16_MAX;
    }
    if (!narrow || !g->nsubs)
        return;
    /* in place, in the 4-byte array's storage, in order: 2-byte entry first16 + c of
       sub-grid k lies at byte 2 (first + k + c), 4-byte entry first + c at 4 (first + c);
       k <= first (every sub-grid has a cell), so no 2-byte entry reaches a 4-byte one not
       yet read (the bytes are copied with memcpy: two types in one array) */
    unsigned char *m = g->soff_m.p;
    for (size_t k = 0; k < g->nsubs; k++) {
        const rt_subgrid *sg = &g->subs[k];
        const size_t nc = (size_t)sg->b.n[0] * (size_t)sg->b.n[1] * (size_t)sg->b.n[2];
        /* the sub-grid's fields in locals: the byte stores may alias them */
        const uint32_t ref0 = sg->ref0;
        const unsigned char *from = m + 4 * (size_t)sg->first;
        unsigned char *to = m + 2 * (size_t)sg->first16;
        for (size_t c = 0; c <= nc; c++) {
            uint32_t v;
            memcpy(&v, from + 4 * c, sizeof v);
            const uint16_t r = (uint16_t)(v - ref0);
            memcpy(to + 2 * c, &r, sizeof r);
        }
    }
    rt_big_shrink(&g->soff_m, g->nsubcells + g->nsubs, sizeof(uint16_t));
    g->soff16 = g->soff_m.p;
    g->soff = NULL;
}

/* A widened top level's sub-grids (rt_top_coarsen) hold triangles that span several of
 * their cells: about 7 references per triangle from 1.2 sub-grids each on random triangles,
 * so a sub-grid names the same few primitives again and again. Their references become
 * 2-byte indices into a table of the primitives each sub-grid holds (rt_grid.sref16, sloc:
 * 2 B per reference and 4 B per primitive and sub-grid, instead of 4 B per reference;
 * random triangles 27-31 -> 19-21 B a triangle), the same lists in the same order; the
 * walks read a cell's list through the table. The build makes the tables and the indices
 * (rt_sub_csr, rt_sub_job.local: srefs holds the indices, sloc the tables); here they are
 * narrowed to 2 bytes when the second level has the 2-byte offsets' layout (at most 65535
 * references a sub-grid, so as many primitives), else, or without the memory for them,
 * made primitive indices again (srefs, sloc freed). With leaves (float leaves may be made:
 * they read srefs) both are kept until rt_sub_local_end. The meshes' sub-grids (about 4
 * references per insertion) keep srefs: their rays would pay the table's load per
 * reference (docs/bench/rt_tuning.md, 2026-12-06). */
static void rt_sub_local(rt_grid *g, int leaves)
{
    if (!g->sloc)
        return;
    uint32_t *refs = g->srefs;
    uint16_t *r16 = g->soff16 && g->nsubs && g->nsrefs
                        ? rt_alloc_array(g->nsrefs, sizeof(uint16_t)) : NULL;
    for (size_t j = 0; r16 && j < g->nsrefs; j++)
        r16[j] = (uint16_t)refs[j];
    for (size_t k = 0; (!r16 || leaves) && k < g->nsubs; k++) {
        const rt_subgrid *sg = &g->subs[k];
        const size_t nc = (size_t)sg->b.n[0] * (size_t)sg->b.n[1] * (size_t)sg->b.n[2];
        const uint32_t *loc = g->sloc + sg->loc0;
        for (uint32_t j = sg->ref0, e = rt_sub_off(g, k, nc); j < e; j++)
            refs[j] = loc[refs[j]];
    }
    if (!r16) {
        free(g->sloc);
        g->sloc = NULL;
        g->nsloc = 0;
        return;
    }
    g->sref16 = r16;
    if (!leaves) {
        rt_big_free(&g->srefs_m);
        g->srefs = NULL;
    }
}

/* after the float leaves: the layout that rt_sub_local left both of, the one the walks read
   (srefs with leaves, else sref16 and sloc) */
static void rt_sub_local_end(rt_grid *g)
{
    if (!g->sref16 || !g->srefs)
        return;
    if (g->tleaf) {
        free(g->sref16);
        free(g->sloc);
        g->sref16 = NULL;
        g->sloc = NULL;
        g->nsloc = 0;
    } else {
        rt_big_free(&g->srefs_m);
        g->srefs = NULL;
    }
}

/* for tests: the smallest chunk of the second level's dynamic parts in references (0: the
   default, RT_SUB_CHUNK_MIN) and the front chunks that part 0 takes at most (0: no limit), so
   that a test makes many chunks and chunks of the back on any machine (the grid stays the
   same); the back chunks made (a process total) */
static size_t rt_chunk_min = 0;
static int rt_front_max = 0;
static uint64_t rt_back_chunks = 0;

void rt_build_set_chunks(size_t min_refs, int front_max)
{
    __atomic_store_n(&rt_chunk_min, min_refs, __ATOMIC_RELAXED);
    __atomic_store_n(&rt_front_max, front_max, __ATOMIC_RELAXED);
}

uint64_t rt_build_back_chunks(void)
{
    return __atomic_load_n(&rt_back_chunks, __ATOMIC_RELAXED);
}

static int rt_build_subgrids(rt_scene *sc, rt_build *bs, int nt, double eps, double sub_factor,
                             const double flat[2], int sub_min, int local)
{
    rt_grid *g = &sc->grid;
    size_t nsub = 0;
    for (size_t ci = 0; ci < g->ncells; ci++)
        nsub += g->off[ci + 1] - g->off[ci] > (uint32_t)sub_min;
    if (nsub == 0)
        return RT_OK;
    if ((size_t)nt > g->ncells)
        nt = 1;
    if (g->ncells >> RT_SUB_CELL_BITS)
        return RT_ERR_LIMIT; /* not with the resolution rule's 2^25 cells at most */
    g->sub = rt_alloc_array(g->ncells, sizeof(int32_t));
    uint8_t *keep = rt_alloc_array(g->nrefs, 1);
    rt_sub_chunk *chunks = rt_calloc_array(2 * RT_SUB_CHUNKS, sizeof(rt_sub_chunk));
    rt_sub_part part[RT_PAR_MAX];
    memset(part, 0, sizeof part);
    if (!g->sub || !keep || !chunks) {
        free(keep);
        free(chunks);
        return RT_ERR_NOMEM;
    }
    memset(keep, 1, g->nrefs);
    const size_t cmin = __atomic_load_n(&rt_chunk_min, __ATOMIC_RELAXED);
    rt_sub_job job = {.sc = sc, .b = bs, .part = part, .keep = keep, .eps = eps,
                      .sub_factor = sub_factor, .flat = {flat[0], flat[1]},
                      .sub_min = sub_min, .nparts = nt, .local = local,
                      .chunk_min = cmin ? (double)cmin : RT_SUB_CHUNK_MIN,
                      .state = (uint64_t)g->ncells << RT_SUB_CELL_BITS,
                      .front = chunks, .back = chunks + RT_SUB_CHUNKS,
                      .front_max = (size_t)__atomic_load_n(&rt_front_max, __ATOMIC_RELAXED)};
    rt_par_run(nt, rt_sub_cells, &job);
    job.nback = (size_t)(job.state >> (2 * RT_SUB_CELL_BITS));
    __atomic_fetch_add(&rt_back_chunks, job.nback, __ATOMIC_RELAXED);
    int err = 0;
    for (int k = 0; k < nt; k++)
        if (part[k].err && !err)
            err = part[k].err;
    size_t nsubs = 0, total = 0, nref = 0, nloc = 0;
    if (!err)
        rt_sub_merge(&job, &nsubs, &total, &nref, &nloc);
    if (!err && (total > UINT32_MAX - 1 || nref > UINT32_MAX - 1))
        err = 2;
    if (!err) {
        g->subs = rt_alloc_lines(nsubs ? nsubs : 1, sizeof(rt_subgrid));
        if (!g->subs || !rt_big_grow(&part[0].off, total + 1, sizeof(uint32_t)) ||
            !rt_big_grow(&part[0].refs, nref ? nref : 1, sizeof(uint32_t)))
            err = 1;
        if (!err && local && !(g->sloc = rt_alloc_array(nloc ? nloc : 1, sizeof(uint32_t))))
            err = 1;
        g->nsloc = nloc;
    }
    if (!err) {
        g->soff_m = part[0].off;
        g->srefs_m = part[0].refs;
        memset(&part[0].off, 0, sizeof part[0].off);
        memset(&part[0].refs, 0, sizeof part[0].refs);
        g->soff = g->soff_m.p;
        g->srefs = g->srefs_m.p;
        g->nsubcells = total;
        g->nsrefs = nref;
        rt_sub_merge_subs(g, &job);
        g->nsubs = nsubs;
        g->soff[total] = (uint32_t)nref;
        if (job.nback)
            rt_par_run(nt, rt_sub_place, &job);
        rt_sub_narrow(g);
    }
    for (int k = 0; k < nt; k++) {
        free(part[k].subs);
        rt_big_free(&part[k].off);
        rt_big_free(&part[k].refs);
        rt_big_free(&part[k].loc);
    }
    free(chunks);
    if (!err)
        rt_top_compact(g, keep);
    free(keep);
    if (err)
        return err == 2 ? RT_ERR_LIMIT : RT_ERR_NOMEM;
    return RT_OK;
}

/* Empty cubes of the top level (rt_grid.odist), per octant o: m(c) = 0 for an occupied cell,
 * else 1 + the least m of the 7 neighbours c + s (s a non-empty sum of o's unit steps), a
 * neighbour beyond the box counting as 255: the largest-square recurrence in 3-D, one sweep
 * from o's far corner back (the neighbours are done first). A ray whose steps lie in octant o
 * is inside that cube from where it enters c until it leaves one of the cube's far faces, so
 * the traversal jumps there (rt_trace.c). Then the stored bytes: m capped at RT_CUBE_MAX (a
 * smaller cube is empty as well), an occupied cell's 0 replaced by RT_CUBE_OCC and what the
 * cell holds. Octants are independent: one per pool part. */
typedef struct rt_cubes_job {
    rt_grid *g;
    const uint8_t *occ; /* per top cell: 0 when empty, else its stored byte (RT_CUBE_OCC ...) */
} rt_cubes_job;

static void rt_empty_cubes_part(void *arg, int k, int n)
{
    const rt_cubes_job *j = arg;
    rt_grid *g = j->g;
    const uint8_t *occ = j->occ;
    const int n0 = g->b.n[0], n1 = g->b.n[1], n2 = g->b.n[2];
    const ptrdiff_t s1 = n0, s2 = (ptrdiff_t)n0 * n1;
    /* the row of a neighbour beyond the box (a grid has at most 1024 cells per axis:
       rt_grid_options, rt_box_resolution) */
    uint8_t none[1024];
    memset(none, 255, sizeof none);
    for (int o = k; o < 8; o += n) {
        uint8_t *m = g->odist + (size_t)o * g->ncells;
        /* sweep against o's directions: x from the end for a positive x step, and so on */
        const int dx = o & 1 ? 1 : -1, dy = o & 2 ? 1 : -1, dz = o & 4 ? 1 : -1;
        const int x0 = dx > 0 ? 0 : n0 - 1;
        for (int z = dz > 0 ? 0 : n2 - 1; z >= 0 && z < n2; z += dz) {
            const int iz = (unsigned)(z - dz) < (unsigned)n2; /* neighbour in z inside */
            for (int y = dy > 0 ? 0 : n1 - 1; y >= 0 && y < n1; y += dy) {
                const int iy = (unsigned)(y - dy) < (unsigned)n1;
                uint8_t *row = m + (size_t)z * (size_t)s2 + (size_t)y * (size_t)s1;
                const uint8_t *oc = occ + (row - m);
                /* the rows of the neighbours behind in y, in z and in both (none beyond) */
                const uint8_t *ry = iy ? row - dy * s1 : none, *rz = iz ? row - dz * s2 : none;
                const uint8_t *ryz = iy && iz ? row - dy * s1 - dz * s2 : none;
                /* p: the cell behind in x; a, b, c: ry, rz, ryz there (255 before the row) */
                unsigned p = 255, a = 255, b = 255, c = 255;
                for (int i = 0, x = x0; i < n0; i++, x += dx) {
                    const unsigned vy = ry[x], vz = rz[x], vyz = ryz[x];
                    unsigned v = p < vy ? p : vy;
                    v = vz < v ? vz : v;
                    v = vyz < v ? vyz : v;
                    v = a < v ? a : v;
                    v = b < v ? b : v;
                    v = c < v ? c : v;
                    /* 0 when occupied, else v + 1 up to 255: no branch (taken at random) */
                    v = (v + (v < 255)) & (0u - (oc[x] == 0));
                    row[x] = (uint8_t)v;
                    p = v;
                    a = vy;
                    b = vz;
                    c = vyz;
                }
            }
        }
        for (size_t ci = 0; ci < g->ncells; ci++) { /* an occupied cell's m is 0 */
            const unsigned v = m[ci];
            m[ci] = (uint8_t)(occ[ci] | (v > RT_CUBE_MAX ? RT_CUBE_MAX : v));
        }
    }
}

static int rt_empty_cubes(rt_grid *g, int nt)
{
    if (g->ncells > SIZE_MAX / 8)
        return RT_ERR_LIMIT;
    uint8_t *occ = rt_alloc_array(g->ncells, 1);
    g->odist = occ ? rt_alloc_array(g->ncells, 8) : NULL;
    if (!g->odist) {
        free(occ);
        return RT_ERR_NOMEM;
    }
    for (size_t ci = 0; ci < g->ncells; ci++) {
        const int list = g->off[ci + 1] != g->off[ci], sub = g->sub && g->sub[ci] >= 0;
        occ[ci] = (uint8_t)(list || sub ? RT_CUBE_OCC | (list ? RT_CUBE_LIST : 0) |
                                              (sub ? RT_CUBE_SUB : 0)
                                        : 0);
    }
    rt_cubes_job j = {.g = g, .occ = occ};
    rt_par_run(nt < 8 ? nt : 8, rt_empty_cubes_part, &j);
    free(occ);
    return RT_OK;
}

/* the extremes of box [lo, hi]'s corners along the k-DOP's directions into kd_lo, kd_hi */
static void rt_kdop_add(rt_grid *g, const double lo[3], const double hi[3])
{
    for (int q = 0; q < 8; q++) {
        double s[RT_KDOP];
        RT_KDOP_PROJ(s, q & 1 ? hi[0] : lo[0], q & 2 ? hi[1] : lo[1], q & 4 ? hi[2] : lo[2]);
        for (int j = 0; j < RT_KDOP; j++) {
            g->kd_lo[j] = rt_dmin(g->kd_lo[j], s[j]);
            g->kd_hi[j] = rt_dmax(g->kd_hi[j], s[j]);
        }
    }
}

/* the extremes of the mesh vertices along the k-DOP's directions (in the grid frame) into
   kd_lo, kd_hi: with SSE2 the projections in pairs (s0 s1, s2 s3, s4 s5, s6 s7, s8 s9 of
   RT_KDOP_PROJ: x + (y, -y), then (x + y) + (z, -z) and so on; a + (-b) is a - b exactly) */
static void rt_kdop_mesh(const rt_scene *sc, rt_grid *g)
{
    const double *X = sc->mv_xyz.p;
#if defined(__SSE2__)
    __m128d lo[5], hi[5];
    for (int k = 0; k < 5; k++) {
        lo[k] = _mm_set1_pd(INFINITY);
        hi[k] = _mm_set1_pd(-INFINITY);
    }
    for (size_t v = 0; v < sc->nmv; v++) {
        double p[3];
        rt_grid_point(g, X + 3 * v, p);
        const __m128d x = _mm_set1_pd(p[0]), y = _mm_set1_pd(p[1]);
        const __m128d ny = _mm_set_pd(-p[1], p[1]), nz = _mm_set_pd(-p[2], p[2]);
        const __m128d xy = _mm_add_pd(x, ny);
        const __m128d q[5] = {_mm_add_pd(_mm_unpacklo_pd(xy, xy), nz),
                              _mm_add_pd(_mm_unpackhi_pd(xy, xy), nz), xy, _mm_add_pd(x, nz),
                              _mm_add_pd(y, nz)};
        for (int k = 0; k < 5; k++) {
            lo[k] = _mm_min_pd(lo[k], q[k]);
            hi[k] = _mm_max_pd(hi[k], q[k]);
        }
    }
    for (int k = 0; k < 5; k++) {
        _mm_storeu_pd(g->kd_lo + 2 * k, lo[k]);
        _mm_storeu_pd(g->kd_hi + 2 * k, hi[k]);
    }
#else
    for (int j = 0; j < RT_KDOP; j++) {
        g->kd_lo[j] = INFINITY;
        g->kd_hi[j] = -INFINITY;
    }
    for (size_t v = 0; v < sc->nmv; v++) {
        double p[3], s[RT_KDOP];
        rt_grid_point(g, X + 3 * v, p);
        RT_KDOP_PROJ(s, p[0], p[1], p[2]);
        for (int j = 0; j < RT_KDOP; j++) {
            g->kd_lo[j] = rt_dmin(g->kd_lo[j], s[j]);
            g->kd_hi[j] = rt_dmax(g->kd_hi[j], s[j]);
        }
    }
#endif
}

/* the extremes of the corners of the top cells with a list (their boxes enlarged by eps, as
   the lists were made) and of the second-level grids' boxes (each holds its primitives'
   parts in its cell) into kd_lo, kd_hi; without an occupied cell the grid box's own */
static void rt_kdop_cells(rt_grid *g, double eps)
{
    const rt_box *b = &g->b;
    for (int j = 0; j < RT_KDOP; j++) {
        g->kd_lo[j] = INFINITY;
        g->kd_hi[j] = -INFINITY;
    }
    const size_t n0 = (size_t)b->n[0], n01 = n0 * (size_t)b->n[1];
    int any = 0;
    for (size_t ci = 0; ci < g->ncells; ci++) {
        if (g->off[ci + 1] != g->off[ci]) {
            const int c[3] = {(int)(ci % n0), (int)(ci % n01 / n0), (int)(ci / n01)};
            double lo[3], hi[3];
            rt_cell_box(b, c, eps, lo, hi);
            rt_kdop_add(g, lo, hi);
            any = 1;
        } else if (g->sub && g->sub[ci] >= 0) {
            const rt_box *sb = &g->subs[g->sub[ci]].b;
            rt_kdop_add(g, sb->lo, sb->hi);
            any = 1;
        }
    }
    if (!any)
        rt_kdop_add(g, b->lo, b->hi);
}

/* The k-DOP of the occupied space (rt_grid.kd_lo, kd_hi). When every primitive is a mesh
 * triangle: the extremes of the mesh vertices (exact; vertices of culled triangles only
 * widen it). Otherwise those of the occupied cells' boxes, whose corners lie up to a cell
 * beyond the surface along the diagonals (on the meshes they turn away about half as many
 * in-box misses as the vertices do: docs/bench/rt_tuning.md). Padded by four times the
 * grid box's pad: the clip of a ray to the slabs rounds as its clip to the grid box does
 * (rt_trace.c), in sums of up to three coordinates. */
static void rt_occupied_kdop(const rt_scene *sc, rt_grid *g, double eps)
{
    if (sc->ntri_plain == 0 && sc->ntri == sc->nprim && sc->nmv > 0)
        rt_kdop_mesh(sc, g);
    else
        rt_kdop_cells(g, eps);
    const rt_box *b = &g->b;
    double mx = 0.0;
    for (int a = 0; a < 3; a++)
        mx = rt_dmax(mx, b->hi[a] - b->lo[a]);
    const double pad = 4.0 * (1e-6 * mx + 1e-12 * sc->scale);
    for (int j = 0; j < RT_KDOP; j++) {
        g->kd_lo[j] -= pad;
        g->kd_hi[j] += pad;
    }
}

/* Grid frame. A scene seen obliquely (a floor at 30 degrees to the view direction, as in the
 * SPD scenes traced in VRC3) has a VRC3-aligned bounding box that is mostly empty: rays then
 * step through many empty cells. But the volume alone overrates a rotation (empty cells cost
 * little with the empty-space jumps), and in VRC3 the eye rays run close to the -z axis, which
 * a rotation takes off the grid axes. Two estimates per frame, as ratios to the VRC3 axes:
 * - eye rays E: they cross about V^(2/3) N^(1/3) (|d_x| + |d_y| + |d_z|) cells in all (V the
 *   box volume, N cells, d the view direction VRC3 z in the grid frame: 1 in VRC3 axes, up to
 *   sqrt(3) rotated);
 * - secondary rays S: the mean |n_x| + |n_y| + |n_z| of the primitive normals (1 when every
 *   surface lies in grid planes, 1.5 on average for random ones): rays leaving a surface that
 *   lies near a grid plane are out of the cells holding it sooner.
 * Candidate frames: for each of the RT_FRAME_CAND largest primitives (by the area of their
 * bounding box) the frame (longest edge, normal x edge, normal). A candidate qualifies when
 * E < 0.7 (RT_FRAME_EYE), or when S < 0.9 and E < 1.5 (RT_FRAME_SEC, RT_FRAME_EYE_MAX); of
 * those the smallest E * S is taken (axes thinner than 1/1000 of the largest counted at that
 * size; at most RT_FRAME_SAMPLE primitives evaluated).
 * Measurements: docs/bench/rt_tuning.md. */
#define RT_FRAME_EYE 0.7
#define RT_FRAME_SEC 0.9
#define RT_FRAME_EYE_MAX 1.5
#define RT_FRAME_SAMPLE 50000
#define RT_FRAME_PRE 64 /* the subset of the sample for a candidate's first estimate */
#define RT_FRAME_PRE_V 16 /* ... when the sample's points are the vertex array in place: every
                             16th vertex or sparser, no more points than the triangles' subset
                             has (in the order of first use, spread over the meshes; read in
                             order, no triangle's index triple and vertices gathered) */

static double rt_box_volume(const double bb[6])
{
    double e[3], mx = 0.0;
    for (int a = 0; a < 3; a++) {
        e[a] = bb[3 + a] - bb[a];
        mx = rt_dmax(mx, e[a]);
    }
    if (!(mx > 0.0))
        return 0.0;
    return rt_dmax(e[0], 1e-3 * mx) * rt_dmax(e[1], 1e-3 * mx) * rt_dmax(e[2], 1e-3 * mx);
}

/* Widens bb (min xyz, max xyz) by the n points pts, each rotated into the grid's frame. */
static void rt_box_add_points(const rt_grid *g, const double *pts, size_t n, double bb[6])
{
    for (size_t q = 0; q < n; q++) {
        double p[3];
        rt_grid_point(g, pts + 3 * q, p);
        for (int a = 0; a < 3; a++) {
            bb[a] = rt_dmin(bb[a], p[a]);
            bb[3 + a] = rt_dmax(bb[3 + a], p[a]);
        }
    }
}

/* The frame's passes over all primitives (the candidates, the boxes) run in nt parts of
 * consecutive primitives on the pool, each with its own scratch (b[k]); their results are
 * merged in part order into what one pass gives: the boxes are minima and maxima, the
 * candidates the largest areas with the lower index first among equal ones. */
typedef struct rt_frame_job {
    const rt_scene *sc;
    rt_build *b;       /* per part */
    size_t stride;     /* rt_frame_box: every stride-th primitive */
    const double *fp;  /* ... or these nfp points (rt_frame_points), when not NULL, */
    size_t nfp;
    size_t pstride;    /* every pstride-th of them */
    size_t skip_lo, skip_hi; /* rt_frame_cand_part: primitives left out */
    int err[RT_PAR_MAX];
    double bb[RT_PAR_MAX][6];
    size_t cand[RT_PAR_MAX][RT_FRAME_CAND];
    double area[RT_PAR_MAX][RT_FRAME_CAND];
    int nc[RT_PAR_MAX];
} rt_frame_job;

static void rt_frame_box_part(void *arg, int k, int n)
{
    rt_frame_job *j = arg;
    const rt_scene *sc = j->sc;
    rt_build *b = &j->b[k];
    double bb[6]; /* here, not in j: the parts' boxes share cache lines there */
    size_t lo, hi;
    int err = 0;
    for (int a = 0; a < 3; a++) {
        bb[a] = INFINITY;
        bb[3 + a] = -INFINITY;
    }
    if (j->fp && j->pstride > 1) {
        rt_par_range((j->nfp + j->pstride - 1) / j->pstride, k, n, &lo, &hi);
        for (size_t m = lo; m < hi; m++)
            rt_box_add_points(&sc->grid, j->fp + 3 * m * j->pstride, 1, bb);
        memcpy(j->bb[k], bb, sizeof bb);
        j->err[k] = 0;
        return;
    }
    if (j->fp) {
        rt_par_range(j->nfp, k, n, &lo, &hi);
        rt_box_add_points(&sc->grid, j->fp + 3 * lo, hi - lo, bb);
        memcpy(j->bb[k], bb, sizeof bb);
        j->err[k] = 0;
        return;
    }
    rt_par_range((sc->nprim + j->stride - 1) / j->stride, k, n, &lo, &hi);
    for (size_t m = lo; m < hi && !err; m++) {
        size_t npts = rt_prim_points(sc, b, m * j->stride, &err);
        rt_box_add_points(&sc->grid, b->pts, npts, bb);
    }
    memcpy(j->bb[k], bb, sizeof bb);
    j->err[k] = err;
}

/* box of all primitive points (every stride-th primitive; or every pstride-th of the nfp
   points fp when fp is not NULL) in the current grid frame, in nt parts (b: nt scratches) */
static int rt_frame_box_of(const rt_scene *sc, rt_build *b, int nt, size_t stride,
                           const double *fp, size_t nfp, size_t pstride, double bb[6])
{
    rt_frame_job *j = rt_calloc_array(1, sizeof *j);
    if (!j)
        return RT_ERR_NOMEM;
    j->sc = sc;
    j->b = b;
    j->stride = stride;
    j->fp = fp;
    j->nfp = nfp;
    j->pstride = pstride;
    const size_t items = fp ? nfp / pstride / 3 : sc->nprim / stride;
    if ((size_t)nt > items / 4096 + 1)
        nt = (int)(items / 4096 + 1);
    rt_par_run(nt, rt_frame_box_part, j);
    int err = 0;
    for (int a = 0; a < 3; a++) {
        bb[a] = INFINITY;
        bb[3 + a] = -INFINITY;
    }
    for (int k = 0; k < nt; k++) {
        err |= j->err[k];
        for (int a = 0; a < 3; a++) {
            bb[a] = rt_dmin(bb[a], j->bb[k][a]);
            bb[3 + a] = rt_dmax(bb[3 + a], j->bb[k][3 + a]);
        }
    }
    free(j);
    return err ? RT_ERR_NOMEM : RT_OK;
}

static int rt_frame_box(const rt_scene *sc, rt_build *b, int nt, size_t stride, double bb[6])
{
    return rt_frame_box_of(sc, b, nt, stride, NULL, 0, 1, bb);
}

/* The number of mesh vertices the primitives use when every primitive is a mesh triangle and
 * they use exactly the first ones of the scene's vertex array (each mesh's vertices in the
 * order of their first use, rt_mesh_sort, every mesh but the last using all of its own); else
 * 0. Then the points of all primitives are those vertices. */
static size_t rt_mesh_used_prefix(const rt_scene *sc)
{
    if (sc->nmesh == 0 || sc->ntri_plain != 0 || sc->ntri != sc->nmtri || sc->nprim != sc->nmtri)
        return 0;
    for (size_t mi = 0; mi + 1 < sc->nmesh; mi++)
        if (sc->mesh[mi].nused != sc->mesh[mi].nv)
            return 0;
    const rt_mesh *m = &sc->mesh[sc->nmesh - 1];
    return m->nused ? m->v0 + m->nused : 0;
}

/* The points whose box rt_frame_box takes (every stride-th primitive's), into *fp (*nfp of
 * them, 3 doubles each), a shared mesh vertex once: a box does not depend on repeats or the
 * order of its points, so rt_frame_box_of over them gives the same box, and a frame's pass
 * then rotates each vertex of a closed mesh once instead of about six times (each in about
 * six triangles) and gathers no index triples. With stride 1 and rt_mesh_used_prefix's
 * vertices, *fp is the scene's vertex array itself (no copy); else a copy, also in *own for
 * the caller to free (NULL: nothing to free). 0, or 1 when out of memory. */
static int rt_frame_points(const rt_scene *sc, rt_build *b, size_t stride, const double **fp,
                           size_t *nfp, double **own)
{
    *own = NULL;
    const size_t nu = stride == 1 ? rt_mesh_used_prefix(sc) : 0;
    if (nu) {
        *fp = sc->mv_xyz.p;
        *nfp = nu;
        return 0;
    }
    const size_t ns = (sc->nprim + stride - 1) / stride;
    uint8_t *seen = sc->nmv ? rt_calloc_array(sc->nmv, 1) : NULL;
    double *p = NULL;
    size_t cap = 0, n = 0;
    int err = sc->nmv && !seen;
    const double *X = sc->mv_xyz.p;
    for (size_t m = 0; m < ns && !err; m++) {
        const size_t i = m * stride;
        if (i < sc->ntri && i >= sc->ntri_plain) {
            if (3 * (n + 3) > cap && !rt_grow((void **)&p, &cap, 3 * (n + 3), sizeof(double))) {
                err = 1;
                break;
            }
            const uint32_t *ix = sc->ctri[i - sc->ntri_plain];
            for (int k = 0; k < 3; k++) {
                const uint32_t e = ix[k] & sc->vmask, v = e / 3; /* offset, vertex */
                if (seen[v])
                    continue;
                seen[v] = 1;
                memcpy(p + 3 * n++, X + e, 3 * sizeof(double));
            }
            continue;
        }
        const size_t np = rt_prim_points(sc, b, i, &err);
        if (err || !rt_grow((void **)&p, &cap, 3 * (n + np), sizeof(double))) {
            err = 1;
            break;
        }
        memcpy(p + 3 * n, b->pts, 3 * np * sizeof(double));
        n += np;
    }
    free(seen);
    if (err) {
        free(p);
        return 1;
    }
    *fp = *own = p;
    *nfp = n;
    return 0;
}

/* S of nk candidate frames at once: S[k] = the mean |n_x| + |n_y| + |n_z| of the m unit
   normals (nx, ny, nz: m each) taken into frame R[k] (rt_grid_dir's products and sums, each
   frame's sum over the normals in their order: the values one pass per frame gives), 0 if
   there are none. One pass over the normals for every frame (the normals are read once, not
   once per frame: they do not fit the D1 cache); in SSE2 two normals side by side, their
   terms added to a frame's sum one after the other. */
static void rt_frame_normals(const double *nx, const double *ny, const double *nz, size_t m,
                             const double (*R)[3][3], int nk, double *S)
{
    double sum[RT_FRAME_CAND] = {0};
    size_t i = 0;
#if defined(__SSE2__)
    /* blocks of normals that stay in the D1 cache, each taken by every frame in turn (the
       frame's entries in registers), two normals side by side and their terms added to the
       frame's sum one after the other */
    const __m128d sg = _mm_set1_pd(-0.0);
    for (size_t i0 = 0; i0 + 2 <= m; i0 = i) {
        const size_t i1 = m - i0 > 512 ? i0 + 512 : m - (m - i0) % 2;
        for (int k = 0; k < nk; k++) {
            const __m128d r0 = _mm_set1_pd(R[k][0][0]), r1 = _mm_set1_pd(R[k][0][1]),
                          r2 = _mm_set1_pd(R[k][0][2]), r3 = _mm_set1_pd(R[k][1][0]),
                          r4 = _mm_set1_pd(R[k][1][1]), r5 = _mm_set1_pd(R[k][1][2]),
                          r6 = _mm_set1_pd(R[k][2][0]), r7 = _mm_set1_pd(R[k][2][1]),
                          r8 = _mm_set1_pd(R[k][2][2]);
            double s = sum[k];
            for (i = i0; i < i1; i += 2) {
                const __m128d x = _mm_loadu_pd(nx + i), y = _mm_loadu_pd(ny + i),
                              z = _mm_loadu_pd(nz + i);
                const __m128d q0 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r0, x), _mm_mul_pd(r1, y)),
                                              _mm_mul_pd(r2, z));
                const __m128d q1 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r3, x), _mm_mul_pd(r4, y)),
                                              _mm_mul_pd(r5, z));
                const __m128d q2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(r6, x), _mm_mul_pd(r7, y)),
                                              _mm_mul_pd(r8, z));
                const __m128d a = _mm_add_pd(_mm_add_pd(_mm_andnot_pd(sg, q0),
                                                        _mm_andnot_pd(sg, q1)),
                                             _mm_andnot_pd(sg, q2));
                s = (s + _mm_cvtsd_f64(a)) + _mm_cvtsd_f64(_mm_unpackhi_pd(a, a));
            }
            sum[k] = s;
        }
        i = i1;
    }
#endif
    for (; i < m; i++)
        for (int k = 0; k < nk; k++) {
            double q[3];
            for (int a = 0; a < 3; a++)
                q[a] = R[k][a][0] * nx[i] + R[k][a][1] * ny[i] + R[k][a][2] * nz[i];
            sum[k] += fabs(q[0]) + fabs(q[1]) + fabs(q[2]);
        }
    for (int k = 0; k < nk; k++)
        S[k] = m ? sum[k] / (double)m : 0.0;
}

/* frame of primitive i: rows (edge, normal x edge, normal); 0 if degenerate */
static int rt_prim_frame(const rt_scene *sc, rt_build *b, size_t i, double R[3][3], int *err)
{
    size_t npts = rt_prim_points(sc, b, i, err);
    double n[3];
    rt_prim_ng(sc, i, n);
    double best = 0.0, u[3] = {0, 0, 0};
    for (size_t k = 0; k < npts; k++) {
        const double *a = b->pts + 3 * k, *q = b->pts + 3 * ((k + 1) % npts);
        double e[3] = {q[0] - a[0], q[1] - a[1], q[2] - a[2]};
        double en = e[0] * n[0] + e[1] * n[1] + e[2] * n[2];
        for (int j = 0; j < 3; j++)
            e[j] -= en * n[j];
        double l = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        if (l > best) {
            best = l;
            for (int j = 0; j < 3; j++)
                u[j] = e[j] / l;
        }
    }
    if (!(best > 0.0) || !isfinite(best))
        return 0;
    double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    double lv = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(lv > 0.5))
        return 0;
    for (int j = 0; j < 3; j++) {
        R[0][j] = u[j];
        R[1][j] = v[j] / lv;
        R[2][j] = n[j];
    }
    return 1;
}

/* area ar of primitive i into the descending list area/cand of *nc (at most RT_FRAME_CAND)
   entries; an equal area stays behind the ones already there */
static void rt_cand_add(double *area, size_t *cand, int *nc, double ar, size_t i)
{
    int k = *nc < RT_FRAME_CAND ? (*nc)++ : RT_FRAME_CAND;
    while (k > 0 && area[k - 1] < ar) { /* insertion into a descending list */
        if (k < RT_FRAME_CAND) {
            area[k] = area[k - 1];
            cand[k] = cand[k - 1];
        }
        k--;
    }
    if (k < RT_FRAME_CAND) {
        area[k] = ar;
        cand[k] = i;
    }
}

/* the area the frame choice ranks a primitive by: the largest face of the box of its points */
static inline double rt_pts_area(const double *pts, size_t npts)
{
    double bb[6];
    rt_pts_bbox(pts, npts, bb);
    return rt_fcands_area(bb[3] - bb[0], bb[4] - bb[1], bb[5] - bb[2]);
}

void rt_fcands_add(rt_fcands *l, double ar, size_t i)
{
    rt_cand_add(l->area, l->cand, &l->nc, ar, i);
}

void rt_fcands_merge(rt_fcands *l, const rt_fcands *from, size_t off)
{
    for (int q = 0; q < from->nc; q++)
        rt_cand_add(l->area, l->cand, &l->nc, from->area[q], from->cand[q] + off);
}

/* part k's candidates: the primitives of the largest bounding-box areas, the primitives
   skip_lo .. skip_hi-1 (the meshes' triangles, ranked when they were added) left out */
static void rt_frame_cand_part(void *arg, int k, int n)
{
    rt_frame_job *j = arg;
    const rt_scene *sc = j->sc;
    rt_build *b = &j->b[k];
    const size_t skip = j->skip_hi - j->skip_lo;
    size_t lo, hi;
    rt_par_range(sc->nprim - skip, k, n, &lo, &hi);
    int err = 0, nc = 0;
    double area[RT_FRAME_CAND]; /* here, not in j: the parts' lists share cache lines there */
    size_t cand[RT_FRAME_CAND];
    /* the part's primitives below skip_lo, then those from skip_hi on */
    const size_t a0 = lo, a1 = hi < j->skip_lo ? hi : j->skip_lo;
    const size_t b0 = (lo > j->skip_lo ? lo : j->skip_lo) + skip, b1 = hi + skip;
    for (size_t i = a0; i < a1 && !err; i++) {
        size_t npts = rt_prim_points(sc, b, i, &err);
        rt_cand_add(area, cand, &nc, rt_pts_area(b->pts, npts), i);
    }
    for (size_t i = b0; i < b1 && !err; i++) {
        size_t npts = rt_prim_points(sc, b, i, &err);
        rt_cand_add(area, cand, &nc, rt_pts_area(b->pts, npts), i);
    }
    memcpy(j->area[k], area, (size_t)nc * sizeof *area);
    memcpy(j->cand[k], cand, (size_t)nc * sizeof *cand);
    j->nc[k] = nc;
    j->err[k] = err;
}

/* The meshes' triangles are left out of the candidates' pass (j->skip_lo .. skip_hi) when
   each of them is committed at ntri_plain + its index in the meshes (none culled): their lists
   were made when they were added. */
static void rt_frame_skip(const rt_scene *sc, rt_frame_job *j)
{
    j->skip_lo = j->skip_hi = sc->nprim;
    if (sc->nmesh > 0 && sc->ntri - sc->ntri_plain == sc->nmtri) {
        j->skip_lo = sc->ntri_plain;
        j->skip_hi = sc->ntri;
    }
}

/* The candidates of all primitives into l: the parts' lists (nt) in order, those below
   skip_lo first, then the meshes' lists, then the parts' from skip_hi on: the list one pass
   in index order makes. 1 if a part failed (no memory). */
static int rt_frame_cands(const rt_scene *sc, const rt_frame_job *j, int nt, rt_fcands *l)
{
    int err = 0;
    l->nc = 0;
    for (int pass = 0; pass < 2; pass++) {
        for (int k = 0; k < nt; k++) {
            err |= j->err[k];
            for (int q = 0; q < j->nc[k]; q++)
                if ((j->cand[k][q] < j->skip_lo) == (pass == 0))
                    rt_cand_add(l->area, l->cand, &l->nc, j->area[k][q], j->cand[k][q]);
        }
        for (size_t mi = 0; pass == 0 && j->skip_lo < j->skip_hi && mi < sc->nmesh; mi++)
            rt_fcands_merge(l, &sc->mesh[mi].cands, sc->ntri_plain + sc->mesh[mi].t0);
    }
    return err;
}

/* the unit normals of every stride-th primitive (ns of them) into *sn (3 ns: the x, the y,
   then the z components), and s0 = their mean |n_x| + |n_y| + |n_z| in the unrotated frame
   (the sum in the normals' order) */
static int rt_frame_sample_ng(const rt_scene *sc, size_t stride, size_t ns, double **sn,
                              double *s0)
{
    double *n = rt_alloc_array(ns ? 3 * ns : 1, sizeof *n), sum = 0.0;
    if (!n)
        return RT_ERR_NOMEM;
    size_t k = 0;
#if defined(__SSE2__)
    /* two triangles side by side: rt_tri_unit_normal's operations in its order (sqrt and
       division correctly rounded in lanes as in scalars), so the same normals; a pair with a
       lane outside its common path (or not two triangles) goes through rt_prim_ng */
    for (; k + 2 <= ns; k += 2) {
        const rt_prim p0 = rt_prim_geo(sc, k * stride), p1 = rt_prim_geo(sc, (k + 1) * stride);
        int done = 0;
        if (p0.kind == RT_KIND_TRI && p1.kind == RT_KIND_TRI) {
            const double *a[3], *c[3];
            rt_tri_verts(sc, p0.data, a);
            rt_tri_verts(sc, p1.data, c);
            __m128d v0[3], e1[3], e2[3];
            for (int j = 0; j < 3; j++) {
                v0[j] = _mm_set_pd(c[0][j], a[0][j]);
                e1[j] = _mm_sub_pd(_mm_set_pd(c[1][j], a[1][j]), v0[j]);
                e2[j] = _mm_sub_pd(_mm_set_pd(c[2][j], a[2][j]), v0[j]);
            }
            const __m128d c0 = _mm_sub_pd(_mm_mul_pd(e1[1], e2[2]), _mm_mul_pd(e1[2], e2[1]));
            const __m128d c1 = _mm_sub_pd(_mm_mul_pd(e1[2], e2[0]), _mm_mul_pd(e1[0], e2[2]));
            const __m128d c2 = _mm_sub_pd(_mm_mul_pd(e1[0], e2[1]), _mm_mul_pd(e1[1], e2[0]));
            const __m128d l2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(c0, c0), _mm_mul_pd(c1, c1)),
                                          _mm_mul_pd(c2, c2));
            const __m128d a2 = _mm_add_pd(
                _mm_add_pd(_mm_mul_pd(e1[0], e1[0]), _mm_mul_pd(e1[1], e1[1])),
                _mm_mul_pd(e1[2], e1[2]));
            const __m128d b2 = _mm_add_pd(
                _mm_add_pd(_mm_mul_pd(e2[0], e2[0]), _mm_mul_pd(e2[1], e2[1])),
                _mm_mul_pd(e2[2], e2[2]));
            const __m128d ab = _mm_mul_pd(a2, b2);
            const __m128d ok =
                _mm_and_pd(_mm_and_pd(_mm_cmpgt_pd(l2, _mm_mul_pd(_mm_set1_pd(1e-22), ab)),
                                      _mm_cmpgt_pd(l2, _mm_set1_pd(1e-290))),
                           _mm_cmplt_pd(ab, _mm_set1_pd(1e290)));
            if (_mm_movemask_pd(ok) == 3) {
                const __m128d len = _mm_sqrt_pd(l2);
                _mm_storeu_pd(n + k, _mm_div_pd(c0, len));
                _mm_storeu_pd(n + ns + k, _mm_div_pd(c1, len));
                _mm_storeu_pd(n + 2 * ns + k, _mm_div_pd(c2, len));
                done = 1;
            }
        }
        for (size_t q = k; q < k + 2; q++) {
            if (!done) {
                double g[3];
                rt_prim_ng(sc, q * stride, g);
                n[q] = g[0];
                n[ns + q] = g[1];
                n[2 * ns + q] = g[2];
            }
            sum += fabs(n[q]) + fabs(n[ns + q]) + fabs(n[2 * ns + q]);
        }
    }
#endif
    for (; k < ns; k++) {
        double q[3];
        rt_prim_ng(sc, k * stride, q);
        n[k] = q[0];
        n[ns + k] = q[1];
        n[2 * ns + k] = q[2];
        sum += fabs(q[0]) + fabs(q[1]) + fabs(q[2]);
    }
    *s0 = ns ? sum / (double)ns : 0.0;
    *sn = n;
    return RT_OK;
}

/* rt_frame_box of every primitive (stride 1), through rt_frame_points when meshes share
   vertices */
static int rt_frame_box_all(const rt_scene *sc, rt_build *b, int nt, double bb[6])
{
    if (sc->ntri == sc->ntri_plain)
        return rt_frame_box(sc, b, nt, 1, bb);
    const double *fp = NULL;
    double *own;
    size_t nfp = 0;
    if (rt_frame_points(sc, b, 1, &fp, &nfp, &own))
        return RT_ERR_NOMEM;
    const int rc = rt_frame_box_of(sc, b, nt, 1, fp, nfp, 1, bb);
    free(own);
    return rc;
}

/* The union of the meshes' boxes (each its kept triangles' box, rt_mesh_add_check) into bb:
 * in the unrotated frame the box of the points rt_frame_points gives in place (the used
 * vertices of meshes that hold every primitive are exactly their kept triangles' vertices), up
 * to the sign of a zero bound, which no extent and so no volume sees; no pass over them. */
static void rt_meshes_box(const rt_scene *sc, double bb[6])
{
    for (int a = 0; a < 3; a++) {
        bb[a] = INFINITY;
        bb[3 + a] = -INFINITY;
    }
    for (size_t mi = 0; mi < sc->nmesh; mi++)
        for (int a = 0; a < 3; a++) {
            bb[a] = rt_dmin(bb[a], sc->mesh[mi].bb[a]);
            bb[3 + a] = rt_dmax(bb[3 + a], sc->mesh[mi].bb[3 + a]);
        }
}

/* the frame of the grid (b: nt scratches, one per part); when the frame is rotated and the
   sample was every primitive (stride 1), fb = the box of all primitive points in it (what
   rt_frame_box with stride 1 gives; the pass that judged the frame made it) and *have_fb = 1 */
static int rt_choose_frame(rt_scene *sc, rt_build *b, int nt, double fb[6], int *have_fb)
{
    rt_grid *g = &sc->grid;
    g->rotated = 0;
    size_t cand[RT_FRAME_CAND];
    double area[RT_FRAME_CAND];
    int nc = 0, err = 0;
    rt_frame_job *j = rt_calloc_array(1, sizeof *j);
    if (!j)
        return RT_ERR_NOMEM;
    j->sc = sc;
    j->b = b;
    rt_frame_skip(sc, j);
    rt_par_run(nt, rt_frame_cand_part, j);
    rt_fcands l;
    err = rt_frame_cands(sc, j, nt, &l);
    nc = l.nc;
    memcpy(area, l.area, sizeof area);
    memcpy(cand, l.cand, sizeof cand);
    free(j);
    if (err)
        return RT_ERR_NOMEM;
    size_t stride = sc->nprim / RT_FRAME_SAMPLE + 1;
    *have_fb = 0;
    /* the sample's normals, once for all candidates (a triangle's is recomputed), and s0 in
       the unrotated frame: made when a candidate passes its bound (rt_frame_sample_ng) */
    const size_t ns = (sc->nprim + stride - 1) / stride;
    double *sn = NULL, s0 = 0.0;
    /* the sample's points for the full passes (rt_frame_points): at once when meshes share
       vertices, else when a candidate first needs a full pass */
    const double *fp = NULL;
    double *fp_own = NULL, bb[6];
    size_t nfp = 0;
    int rc = sc->ntri > sc->ntri_plain && rt_frame_points(sc, b, stride, &fp, &nfp, &fp_own)
                 ? RT_ERR_NOMEM
                 : RT_OK;
    if (rc == RT_OK && fp && !fp_own)
        rt_meshes_box(sc, bb);
    else if (rc == RT_OK)
        rc = rt_frame_box_of(sc, b, nt, stride, fp, nfp, 1, bb);
    const double vol0 = rc == RT_OK ? rt_box_volume(bb) : 0.0;
    double best = INFINITY, bestR[3][3];
    int found = 0;
    for (int a = 0; a < 3; a++)
        g->c[a] = 0.5 * (sc->bbox[a] + sc->bbox[3 + a]);
    /* first each candidate's lower bound of E from a subset of the sample (every
       RT_FRAME_PRE-th of it, or every RT_FRAME_PRE_V-th of its points when they are the
       vertex array in place: the same point values, so a box inside the sample's and a volume
       no larger; the factor covers cbrt's rounding): a candidate it rules out needs neither
       S nor the full pass. The nl others are kept in order with their frames, bounds and
       view terms, their S then taken in one pass over the sample's normals. */
    double Rk[RT_FRAME_CAND][3][3], El[RT_FRAME_CAND], dzk[RT_FRAME_CAND], S[RT_FRAME_CAND];
    int nl = 0;
    size_t vstride = RT_FRAME_PRE * nfp / (3 * sc->nprim + 1);
    vstride = vstride > RT_FRAME_PRE_V ? vstride : RT_FRAME_PRE_V;
    for (int k = 0; k < nc && rc == RT_OK && vol0 > 0.0; k++) {
        if (!rt_prim_frame(sc, b, cand[k], g->R, &err))
            continue;
        g->rotated = 1;
        /* the view direction (VRC3 z) in the candidate frame: column 2 of R */
        const double dz = fabs(g->R[0][2]) + fabs(g->R[1][2]) + fabs(g->R[2][2]);
        rc = fp && !fp_own ? rt_frame_box_of(sc, b, nt, 1, fp, nfp, vstride, bb)
                           : rt_frame_box(sc, b, nt, stride * RT_FRAME_PRE, bb);
        g->rotated = 0;
        const double rl = rt_box_volume(bb) / vol0;
        const double e = cbrt(rl * rl) * dz * (1.0 - 1e-9);
        if (rc != RT_OK || e >= RT_FRAME_EYE_MAX)
            continue;
        memcpy(Rk[nl], g->R, sizeof Rk[nl]);
        El[nl] = e;
        dzk[nl++] = dz;
    }
    if (rc == RT_OK && nl > 0)
        rc = rt_frame_sample_ng(sc, stride, ns, &sn, &s0);
    if (rc == RT_OK && nl > 0 && s0 > 0.0) { /* no S: no candidate is taken */
        rt_frame_normals(sn, sn + ns, sn + 2 * ns, ns, (const double(*)[3][3])Rk, nl, S);
        for (int k = 0; k < nl; k++)
            S[k] /= s0;
    } else {
        nl = 0;
    }
    for (int k = 0; k < nl && rc == RT_OK; k++) {
        if ((El[k] >= RT_FRAME_EYE && S[k] >= RT_FRAME_SEC) || El[k] * S[k] >= best)
            continue;
        if (!fp && rt_frame_points(sc, b, stride, &fp, &nfp, &fp_own))
            rc = RT_ERR_NOMEM;
        memcpy(g->R, Rk[k], sizeof g->R);
        g->rotated = 1;
        if (rc == RT_OK)
            rc = rt_frame_box_of(sc, b, nt, stride, fp, nfp, 1, bb);
        g->rotated = 0;
        const double r = rt_box_volume(bb) / vol0;
        const double E = cbrt(r * r) * dzk[k];
        const int ok = E < RT_FRAME_EYE || (S[k] < RT_FRAME_SEC && E < RT_FRAME_EYE_MAX);
        if (ok && E * S[k] < best) {
            best = E * S[k];
            memcpy(bestR, g->R, sizeof bestR);
            memcpy(fb, bb, 6 * sizeof(double));
            found = 1;
        }
    }
    free(sn);
    free(fp_own);
    if (err)
        rc = RT_ERR_NOMEM;
    if (rc == RT_OK && found) {
        memcpy(g->R, bestR, sizeof bestR);
        g->rotated = 1;
        *have_fb = stride == 1;
    }
    return rc;
}

#define RT_GRID_KNEE 10000.0

/* Second level or one fine level. The second level resolves local crowding (a dense object on
 * a wide floor: teapot in a stadium); when nearly every occupied top cell is crowded, the
 * occupancy is uniform over the occupied part and one level of RT_UNIFORM_FACTOR cells per
 * primitive walks faster (one DDA, no second-level entries). Decided on the top-level counts,
 * for the default options up to RT_GRID_KNEE primitives (measurements: docs/bench/rt_tuning.md). */
#define RT_UNIFORM_SHARE 0.75
#define RT_UNIFORM_FACTOR 8.0

/* share of the occupied top cells with more than sub_min references */
static double rt_crowded_share(const rt_grid *g, uint32_t sub_min)
{
    size_t occ = 0, crowded = 0;
    for (size_t ci = 0; ci < g->ncells; ci++) {
        const uint32_t n = g->off[ci + 1] - g->off[ci];
        occ += n > 0;
        crowded += n > sub_min;
    }
    return occ ? (double)crowded / (double)occ : 0.0;
}

/* top-level cells for n primitives: factor * n; with the default factor, beyond
   RT_GRID_KNEE primitives only as n^(2/3) (see gksrt.h: the second level resolves the
   surfaces, the top level mainly skips empty space) */
static double rt_top_cells(const rt_build_options *o, double factor, double n)
{
    int dflt = !(o && isfinite(o->grid_factor) && o->grid_factor > 0.0);
    if (!dflt || n <= RT_GRID_KNEE)
        return factor * n;
    return factor * RT_GRID_KNEE * sqrt(n / RT_GRID_KNEE);
}

/* the build options as rt_grid_build applies them (defaults filled in) */
typedef struct rt_grid_opts {
    double factor;      /* top-level cells per primitive */
    int explicit_res;   /* 1: grid_res (and grid_box) as given */
    int sub_min;        /* references above which a top cell gets a second level */
    double sub_factor;  /* second-level cells per reference */
    double sub_flat[2]; /* its factors for flat sub-grids (RT_SUB_FLAT1, RT_SUB_FLAT2) */
    int no_subgrids;
    int all_default;    /* no resolution option given: the uniform alternative may replace
                           the two levels */
    int coarse;         /* the top level widened for large primitives (rt_top_coarsen) */
} rt_grid_opts;

static int rt_opt_pos(double x)
{
    return isfinite(x) && x > 0.0;
}

static void rt_grid_options(const rt_build_options *o, size_t nprim, rt_grid_opts *go)
{
    const int given = o != NULL;
    go->factor = given && rt_opt_pos(o->grid_factor) ? o->grid_factor : RT_GRID_FACTOR_DEFAULT;
    go->explicit_res = given && o->grid_res[0] > 0 && o->grid_res[1] > 0 && o->grid_res[2] > 0 &&
                       o->grid_res[0] <= 1024 && o->grid_res[1] <= 1024 && o->grid_res[2] <= 1024;
    go->sub_min = given && o->sub_min > 0 ? o->sub_min : RT_SUB_MIN;
    go->sub_factor = given && rt_opt_pos(o->sub_factor) ? o->sub_factor
                     : (double)nprim > RT_GRID_KNEE ? RT_SUB_FACTOR_LARGE
                                                    : RT_SUB_FACTOR;
    const int flat = !(given && rt_opt_pos(o->sub_factor)) && (double)nprim > RT_GRID_KNEE;
    go->sub_flat[0] = flat ? RT_SUB_FLAT1 : 1.0;
    go->sub_flat[1] = flat ? RT_SUB_FLAT2 : 1.0;
    go->no_subgrids = given && o->no_subgrids;
    go->all_default = !go->explicit_res &&
                      !(given && (rt_opt_pos(o->grid_factor) || o->no_subgrids ||
                                  o->sub_min > 0 || rt_opt_pos(o->sub_factor)));
    go->coarse = 0;
}

/* The top level for primitives that are large against its cells. Beyond RT_GRID_KNEE
 * primitives the top level mainly skips empty space and the second level resolves the
 * primitives; when a typical primitive's box spans more than RT_TOP_EXT_LARGE of a top cell
 * per axis (a volume of random triangles: a median of 0.28-0.49 at 3*10^4-10^6; the test
 * meshes, surfaces: 0.12-0.17), each is inserted into several top cells and so into several
 * sub-grids (2.2 per triangle at 10^5), each copy at the cost of its exact cell tests, and
 * the sub-grids split the space where no empty space is left to skip. Then the top cells
 * are widened to RT_TOP_EXT_TARGET times that median: fewer, larger sub-grids (measured:
 * docs/bench/rt_tuning.md, 2026-12-06). The median of a sample of at most
 * RT_TOP_EXT_SAMPLE primitives (every nprim / RT_TOP_EXT_SAMPLE + 1-th), each one's box
 * extent over the cell width averaged over the axes: a few huge primitives (a floor under a
 * small object) do not move it.
 * At or below RT_GRID_KNEE primitives (0.25 top cells per primitive) the trigger is
 * RT_TOP_EXT_LARGE_SMALL: random triangles' medians there are 0.55-0.60 (3,000-10,000), the
 * SPD scenes' 0.20-0.26 (teapot 0.203, mount-tessellated 0.218, gears 0.224, tetra 0.258), so
 * they keep their grids. A widened top level is all crowded, so it always gets the second
 * level (not the uniform alternative of RT_UNIFORM_SHARE), with RT_SUB_FACTOR_COARSE cells
 * per reference at any size: its triangles span several sub cells each, and fewer cells cut
 * the references and exact tests per triangle more than they cost its rays (2026-12-06: 3
 * instead of 4; 2.5 with the 2-byte references of rt_sub_local, whose tables then cost the
 * commit a pass, made in the build's CSR pass since: random triangles 3.8 -> 3.1 sub cells
 * and 7.7 -> 7.2 references a triangle at 10^6, build instructions as with 3 and no table,
 * rays 1-3 % more than with 3). */
#define RT_TOP_EXT_SAMPLE 1024
#define RT_TOP_EXT_LARGE 0.25
#define RT_TOP_EXT_LARGE_SMALL 0.4
#define RT_TOP_EXT_TARGET 0.1
#define RT_SUB_FACTOR_COARSE 2.5

static int rt_cmp_double(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The k-th smallest (from 0) of the n values r, r[k] once r is sorted (r may be reordered).
 * Values that are all non-negative (+0 to infinity) order as their bit patterns do, so it is
 * found digit by digit, 8 bits at a time from the top: each pass counts the digits of the
 * values that have the digits found so far, without a branch per value (a sort's comparisons
 * are taken at random: about 6,000 mispredicted of 1024 values); else qsort. */
double rt_kth_smallest(double *r, size_t n, size_t k)
{
    int plain = 1;
    for (size_t i = 0; i < n; i++)
        plain &= r[i] >= 0.0 && !signbit(r[i]);
    if (!plain) {
        qsort(r, n, sizeof *r, rt_cmp_double);
        return r[k];
    }
    uint64_t want = 0, mask = 0;
    for (int sh = 56; sh >= 0; sh -= 8) {
        uint32_t cnt[256];
        memset(cnt, 0, sizeof cnt);
        for (size_t i = 0; i < n; i++) {
            uint64_t x;
            memcpy(&x, &r[i], sizeof x);
            cnt[x >> sh & 0xff] += (x & mask) == want;
        }
        uint32_t d = 0;
        while (k >= cnt[d])
            k -= cnt[d++];
        want |= (uint64_t)d << sh;
        mask |= (uint64_t)0xff << sh;
    }
    double v;
    memcpy(&v, &want, sizeof v);
    return v;
}

/* the top level g widened for large primitives (above); *coarse = 1 when it was */
static int rt_top_coarsen(const rt_scene *sc, rt_build *b, rt_box *g, int *coarse)
{
    const double large =
        (double)sc->nprim > RT_GRID_KNEE ? RT_TOP_EXT_LARGE : RT_TOP_EXT_LARGE_SMALL;
    double r[RT_TOP_EXT_SAMPLE];
    const size_t stride = sc->nprim / RT_TOP_EXT_SAMPLE + 1;
    size_t m = 0, nlarge = 0;
    int err = 0;
    for (size_t i = 0; i < sc->nprim && !err; i += stride) {
        double bb[6];
        rt_prim_gbox(sc, b, i, bb, &err);
        r[m] = ((bb[3] - bb[0]) * g->inv_cw[0] + (bb[4] - bb[1]) * g->inv_cw[1] +
                (bb[5] - bb[2]) * g->inv_cw[2]) / 3.0;
        nlarge += r[m++] > large;
    }
    if (err)
        return RT_ERR_NOMEM;
    /* the median r[m / 2] of the sorted sample is above the trigger exactly when
       m - m / 2 values are: counted, so that most scenes need no sort */
    if (nlarge < m - m / 2)
        return RT_OK;
    const double med = rt_kth_smallest(r, m, m / 2);
    const double k = RT_TOP_EXT_TARGET / med;
    rt_box_resolution(g, (double)g->n[0] * g->n[1] * g->n[2] * k * k * k, 512);
    *coarse = 1;
    return RT_OK;
}

/* the grid's frame and box (rotated or not, padded, an explicit box where it holds the
   scene) and its top-level resolution */
static int rt_grid_frame_box(rt_scene *sc, rt_build *bs, int nt, const rt_build_options *o,
                             rt_grid_opts *go, double *mx)
{
    rt_grid *g = &sc->grid;
    double fb[6];
    memcpy(fb, sc->bbox, sizeof fb);
    int rc = RT_OK;
    g->rotated = 0;
    if (!go->explicit_res && !(o && o->grid_frame == 1)) {
        double rb[6];
        int have = 0;
        rc = rt_choose_frame(sc, bs, nt, rb, &have);
        if (rc == RT_OK && g->rotated && have)
            memcpy(fb, rb, sizeof fb);
        else if (rc == RT_OK && g->rotated)
            rc = rt_frame_box_all(sc, bs, nt, fb);
    }
    *mx = 0.0;
    for (int a = 0; a < 3; a++)
        *mx = rt_dmax(*mx, fb[3 + a] - fb[a]);
    double pad = 1e-6 * *mx + 1e-12 * sc->scale;
    for (int a = 0; a < 3; a++) {
        g->b.lo[a] = fb[a] - pad;
        g->b.hi[a] = fb[3 + a] + pad;
    }
    if (go->explicit_res) {
        for (int a = 0; a < 3; a++) {
            if (isfinite(o->grid_box[a]) && isfinite(o->grid_box[3 + a]) &&
                o->grid_box[a] < o->grid_box[3 + a]) {
                if (o->grid_box[a] <= sc->bbox[a])
                    g->b.lo[a] = o->grid_box[a];
                if (o->grid_box[3 + a] >= sc->bbox[3 + a])
                    g->b.hi[a] = o->grid_box[3 + a];
            }
            g->b.n[a] = o->grid_res[a];
        }
    } else {
        rt_box_resolution(&g->b, rt_top_cells(o, go->factor, (double)sc->nprim), 512);
        rt_box_finish(&g->b);
        if (rc == RT_OK && go->all_default)
            rc = rt_top_coarsen(sc, bs, &g->b, &go->coarse);
        if (go->coarse)
            go->sub_factor = RT_SUB_FACTOR_COARSE;
    }
    rt_box_finish(&g->b);
    g->ncells = (size_t)g->b.n[0] * (size_t)g->b.n[1] * (size_t)g->b.n[2];
    return rc;
}

/* the top level and the second level (or the one uniform level instead) */
static int rt_grid_levels(rt_scene *sc, rt_build *bs, int nt, const rt_grid_opts *go,
                          double eps)
{
    rt_grid *g = &sc->grid;
    int rc = rt_top_level(sc, bs, nt, eps);
    int no_subgrids = go->no_subgrids;
    if (rc == RT_OK && go->all_default && !go->coarse && (double)sc->nprim <= RT_GRID_KNEE &&
        rt_crowded_share(g, (uint32_t)go->sub_min) >= RT_UNIFORM_SHARE) {
        /* occupancy nearly uniform: one fine level instead (see RT_UNIFORM_SHARE) */
        free(g->off);
        free(g->refs);
        g->off = g->refs = NULL;
        rt_box_resolution(&g->b, RT_UNIFORM_FACTOR * (double)sc->nprim, 512);
        rt_box_finish(&g->b);
        g->ncells = (size_t)g->b.n[0] * (size_t)g->b.n[1] * (size_t)g->b.n[2];
        rc = rt_top_level(sc, bs, nt, eps);
        no_subgrids = 1;
    }
    if (rc == RT_OK && !no_subgrids)
        rc = rt_build_subgrids(sc, bs, nt, eps, go->sub_factor, go->sub_flat, go->sub_min,
                               go->coarse);
    return rc;
}

typedef struct rt_gframe_job {
    const rt_scene *sc;
    double *gv;
} rt_gframe_job;

static void rt_gframe_part(void *arg, int k, int n)
{
    const rt_gframe_job *j = arg;
    const double *X = j->sc->mv_xyz.p;
    size_t lo, hi;
    rt_par_range(j->sc->nmv, k, n, &lo, &hi);
    for (size_t v = lo; v < hi; v++)
        rt_grid_point(&j->sc->grid, X + 3 * v, j->gv + 3 * v);
}

/* The meshes' vertices in the rotated grid frame, into *gv (NULL when the grid is not rotated
 * or there is no mesh triangle), in nt parts: each vertex rotated once, where the insertions
 * of the top level and of the second level's cells rotated it again for every triangle and
 * crowded cell holding it (rt_prim_gpoints; the fandisk's 15843 vertices were rotated about
 * 15 times each). RT_OK or RT_ERR_NOMEM. */
static int rt_mesh_gframe(const rt_scene *sc, int nt, double **gv)
{
    *gv = NULL;
    if (!sc->grid.rotated || sc->ntri == sc->ntri_plain || !sc->nmv)
        return RT_OK;
    rt_gframe_job j = {.sc = sc, .gv = rt_alloc_array(sc->nmv, 3 * sizeof(double))};
    if (!j.gv)
        return RT_ERR_NOMEM;
    if ((size_t)nt > sc->nmv / 4096 + 1)
        nt = (int)(sc->nmv / 4096 + 1);
    rt_par_run(nt, rt_gframe_part, &j);
    *gv = j.gv;
    return RT_OK;
}

/* primitive j of sub-grid k's reference r (either layout) */
static inline uint32_t rt_sub_ref(const rt_grid *g, const rt_subgrid *sg, uint32_t r)
{
    return g->sref16 ? g->sloc[sg->loc0 + g->sref16[r]] : g->srefs[r];
}

/* Sub-grid k's plane (rt_subplane) if its triangles lie within RT_FLAT_TOL of the scene's
   scale of one plane: 1, else 0, -1 when out of memory. *seen: per triangle the last
   sub-grid (1 + k) that looked at it, so that a triangle in several of the sub-grid's cells
   is looked at once (allocated at the first use; a flat fandisk sub-grid references each
   triangle about 6 times, so a test per reference mispredicted at first references). The
   margin's constants (RT_FLAT_K1 the bound of the watertight test's distance from its
   plane, in u S^3): docs/RAYTRACING.md, "Flat sub-grids". */
#define RT_FLAT_TOL 0x1p-30
#define RT_FLAT_K1 16384.0
#define RT_FLAT_CHUNK 64u
/* min and max as one instruction each (no libm call; a NaN coordinate makes the
   triangle's |N| NaN, and then the sub-grid keeps no plane) */
#define RT_FMIN(a, b) ((a) < (b) ? (a) : (b))
#define RT_FMAX(a, b) ((a) > (b) ? (a) : (b))
static int rt_sub_plane(const rt_scene *sc, const rt_grid *g, size_t k, uint32_t **seen,
                        rt_subplane *pl)
{
    const rt_subgrid *sg = &g->subs[k];
    const size_t nc = (size_t)sg->b.n[0] * sg->b.n[1] * sg->b.n[2];
    const uint32_t a = rt_sub_off(g, k, 0), b = rt_sub_off(g, k, nc), mark = (uint32_t)k + 1;
    const double u = 0x1p-53, S = sc->scale, tol = RT_FLAT_TOL * S;
    if (a == b || !(S > 0.0) || !(S < 1e100))
        return 0;
    /* the unit normal of the first triangle */
    const uint32_t j0 = rt_sub_ref(g, sg, a);
    const double *v0 = rt_tri_vert(sc, j0, 0), *v1 = rt_tri_vert(sc, j0, 1),
                 *v2 = rt_tri_vert(sc, j0, 2);
    double n[3];
    n[0] = (v1[1] - v0[1]) * (v2[2] - v0[2]) - (v1[2] - v0[2]) * (v2[1] - v0[1]);
    n[1] = (v1[2] - v0[2]) * (v2[0] - v0[0]) - (v1[0] - v0[0]) * (v2[2] - v0[2]);
    n[2] = (v1[0] - v0[0]) * (v2[1] - v0[1]) - (v1[1] - v0[1]) * (v2[0] - v0[0]);
    const double ln = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(ln > 0.0))
        return 0;
    for (int i = 0; i < 3; i++)
        n[i] /= ln;
    /* the slab over the first few references' vertices first: most sub-grids of curved
       surfaces are left here, before the per-triangle marks (seen) are touched */
    double lo = INFINITY, hi = -INFINITY;
    for (uint32_t r = a; r < b && r < a + 16; r++) {
        const uint32_t j = rt_sub_ref(g, sg, r);
        if (j >= sc->ntri)
            return 0;
        for (int q = 0; q < 3; q++) {
            const double *v = rt_tri_vert(sc, j, q);
            const double d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
            lo = RT_FMIN(lo, d);
            hi = RT_FMAX(hi, d);
        }
        if (!(hi - lo <= tol))
            return 0;
    }
    if (!*seen && !(*seen = rt_calloc_array(sc->ntri, sizeof **seen)))
        return -1;
    /* per distinct triangle, in chunks of RT_FLAT_CHUNK references (those of a chunk not
       seen before gathered without a branch per reference; a curved sub-grid is left in
       its first chunks): the slab of n . v over its vertices (left as soon as it is thicker
       than tol), and from its edges e1, e2 and cross product N (max norms; |N| taken less
       the cross product's rounding, 48 u |e1| |e2|) the largest (|e1| + |e2|) / |N| and the
       least such |N| (1 / that is the largest 1 / |N|: a correctly rounded division is
       monotonic). A scene of mesh triangles only: every reference is a mesh triangle. */
    uint32_t *const mk = *seen, ds[RT_FLAT_CHUNK];
    double qmax = 0.0, lmin = INFINITY;
    for (uint32_t r0 = a; r0 < b; r0 += RT_FLAT_CHUNK) {
        const uint32_t r1 = b - r0 < RT_FLAT_CHUNK ? b : r0 + RT_FLAT_CHUNK;
        uint32_t nd = 0;
        for (uint32_t r = r0; r < r1; r++) {
            const uint32_t j = rt_sub_ref(g, sg, r);
            ds[nd] = j;
            nd += mk[j] != mark;
            mk[j] = mark;
        }
        for (uint32_t t = 0; t < nd; t++) {
            const double *w[3];
            rt_tri_verts(sc, ds[t], w);
            const double *w0 = w[0], *w1 = w[1], *w2 = w[2];
            const double d0 = n[0] * w0[0] + n[1] * w0[1] + n[2] * w0[2],
                         d1 = n[0] * w1[0] + n[1] * w1[1] + n[2] * w1[2],
                         d2 = n[0] * w2[0] + n[1] * w2[1] + n[2] * w2[2];
            lo = RT_FMIN(lo, RT_FMIN(d0, RT_FMIN(d1, d2)));
            hi = RT_FMAX(hi, RT_FMAX(d0, RT_FMAX(d1, d2)));
            if (!(hi - lo <= tol))
                return 0;
            double e1[3], e2[3], N[3];
            for (int i = 0; i < 3; i++) {
                e1[i] = w1[i] - w0[i];
                e2[i] = w2[i] - w0[i];
            }
            N[0] = e1[1] * e2[2] - e1[2] * e2[1];
            N[1] = e1[2] * e2[0] - e1[0] * e2[2];
            N[2] = e1[0] * e2[1] - e1[1] * e2[0];
            const double m1 = RT_FMAX(fabs(e1[0]), RT_FMAX(fabs(e1[1]), fabs(e1[2]))),
                         m2 = RT_FMAX(fabs(e2[0]), RT_FMAX(fabs(e2[1]), fabs(e2[2])));
            const double low = RT_FMAX(fabs(N[0]), RT_FMAX(fabs(N[1]), fabs(N[2]))) -
                               48.0 * u * m1 * m2;
            if (!(low > 0.0))
                return 0;
            qmax = RT_FMAX(qmax, 1.7320508075688772 * (m1 + m2) / low);
            lmin = RT_FMIN(lmin, low);
        }
    }
    const double rmax = 1.0 / lmin;
    /* |n| <= 1 + 4 u; n . v rounds by at most 3.01 u |n|_1 S <= 6 u S; the exact n . e of
       an edge is then at most (hi - lo) + 12 u S, and sin(n, N) <= |n . e1| |e2| +
       |n . e2| |e1| over |N| */
    pl->n[0] = n[0];
    pl->n[1] = n[1];
    pl->n[2] = n[2];
    pl->lo = lo - 8.0 * u * S;
    pl->hi = hi + 8.0 * u * S;
    pl->ka = 4.0 * 1.7320508075688772 * (hi - lo + 12.0 * u * S) * qmax * 1.001;
    pl->kb = RT_FLAT_K1 * u * rmax * 1.001;
    return isfinite(pl->ka) && isfinite(pl->kb) && isfinite(pl->lo) && isfinite(pl->hi);
}

/* rt_grid.subplane and splanes, for the sub-grids of a scene of mesh triangles only */
static int rt_sub_planes(const rt_scene *sc, rt_grid *g)
{
    if (sc->ntri_plain != 0 || sc->ntri != sc->nprim || !g->nsubs || g->nsubs >= UINT32_MAX)
        return RT_OK;
    uint32_t *of = rt_calloc_array(g->nsubs, sizeof *of), *seen = NULL;
    rt_subplane *pl = NULL;
    size_t np = 0, cap = 0;
    int rc = of ? RT_OK : RT_ERR_NOMEM;
    for (size_t k = 0; k < g->nsubs && rc == RT_OK; k++) {
        rt_subplane p;
        const int f = rt_sub_plane(sc, g, k, &seen, &p);
        if (f < 0)
            rc = RT_ERR_NOMEM;
        if (f <= 0)
            continue;
        if (!rt_grow((void **)&pl, &cap, np + 1, sizeof *pl)) {
            rc = RT_ERR_NOMEM;
            break;
        }
        pl[np++] = p;
        of[k] = (uint32_t)np;
    }
    free(seen);
    if (rc != RT_OK || !np) {
        free(of);
        free(pl);
        return rc;
    }
    g->subplane = of;
    g->splanes = pl;
    g->nsplanes = np;
    g->subplane_near = sc->nmesh == 1 ? of : NULL;
    return RT_OK;
}

int rt_grid_build(rt_scene *sc, const rt_build_options *o)
{
    int thr = o && o->brute_threshold >= 0 ? o->brute_threshold : RT_BRUTE_THRESHOLD_DEFAULT;
    sc->use_grid = 0;
    if ((o && o->brute_force) || sc->nprim == 0 || sc->nprim < (size_t)thr)
        return RT_OK;
    if (sc->nprim > UINT32_MAX - 1)
        return RT_ERR_LIMIT;
    rt_grid *g = &sc->grid;
    rt_grid_opts go;
    rt_grid_options(o, sc->nprim, &go);
    /* threads: at most one per 4096 primitives (the scene is the same for any number) */
    int nt = rt_par_threads(o ? o->threads : 0);
    if ((size_t)nt > sc->nprim / 4096 + 1)
        nt = (int)(sc->nprim / 4096 + 1);
    rt_build bs[RT_PAR_MAX];
    memset(bs, 0, sizeof bs);
    double mx;
    int rc = rt_grid_frame_box(sc, bs, nt, o, &go, &mx);
    const double eps = 1e-9 * (sc->scale + mx);
    double *gv = NULL;
    if (rc == RT_OK)
        rc = rt_mesh_gframe(sc, nt, &gv);
    for (int k = 0; k < nt; k++)
        bs[k].gv = gv;
    if (rc == RT_OK)
        rc = rt_grid_levels(sc, bs, nt, &go, eps);
    free(gv);
    for (int k = 0; k < nt; k++)
        bs[k].gv = NULL;
    if (rc == RT_OK)
        rc = rt_empty_cubes(g, nt);
    if (rc == RT_OK)
        rt_occupied_kdop(sc, g, eps);
    if (rc == RT_OK)
        rt_sub_local(g, rt_leaves_min(o ? o->leaf_min : 0) > 0);
    if (rc == RT_OK)
        rc = rt_leaves_build(sc, g, o ? o->leaf_min : 0);
    if (rc == RT_OK)
        rt_sub_local_end(g);
    if (rc == RT_OK)
        rc = rt_sub_planes(sc, g);
    for (int k = 0; k < nt; k++)
        rt_build_free(&bs[k]);
    if (rc != RT_OK) {
        rt_grid_free(g);
        return rc;
    }
    g->all_opaque = 1; /* the stored records, then those of the meshes that kept triangles */
    for (size_t i = 0; i < sc->nprim - (sc->ntri - sc->ntri_plain); i++)
        g->all_opaque &= sc->prim[i].opaque != 0;
    for (size_t m = 0, end = sc->ntri_plain; m < sc->nmesh && sc->ntri > sc->ntri_plain; m++) {
        g->all_opaque &= sc->cmesh[m].end == end || sc->cmesh[m].rec.opaque != 0;
        end = sc->cmesh[m].end;
    }
    sc->use_grid = 1;
    return RT_OK;
}

/* FNV-1a (64 bit) over n bytes, continuing from h */
static uint64_t rt_fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t k = 0; k < n; k++)
        h = (h ^ c[k]) * 0x100000001b3ULL;
    return h;
}

static uint64_t rt_fnv_box(uint64_t h, const rt_box *b)
{
    h = rt_fnv(h, b->lo, sizeof b->lo);
    h = rt_fnv(h, b->hi, sizeof b->hi);
    return rt_fnv(h, b->n, sizeof b->n);
}

/* the committed grid's hash (rt_grid_info.hash): field by field, no padding bytes */
static uint64_t rt_grid_hash(const rt_grid *g)
{
    uint64_t h = 0xcbf29ce484222325ULL;
    h = rt_fnv(h, &g->rotated, sizeof g->rotated);
    if (g->rotated) {
        h = rt_fnv(h, g->R, sizeof g->R);
        h = rt_fnv(h, g->c, sizeof g->c);
    }
    h = rt_fnv_box(h, &g->b);
    h = rt_fnv(h, g->off, (g->ncells + 1) * sizeof *g->off);
    h = rt_fnv(h, g->refs, g->nrefs * sizeof *g->refs);
    h = rt_fnv(h, g->odist, 8 * g->ncells);
    const int has_sub = g->sub != NULL;
    h = rt_fnv(h, &has_sub, sizeof has_sub);
    if (!has_sub)
        return h;
    h = rt_fnv(h, g->sub, g->ncells * sizeof *g->sub);
    for (size_t k = 0; k < g->nsubs; k++) {
        h = rt_fnv_box(h, &g->subs[k].b);
        h = rt_fnv(h, &g->subs[k].first, sizeof g->subs[k].first);
    }
    /* the absolute offsets whichever the layout (the hash of the 4-byte array) */
    for (size_t k = 0; k < g->nsubs; k++) {
        const rt_box *b = &g->subs[k].b;
        const size_t nc = (size_t)b->n[0] * (size_t)b->n[1] * (size_t)b->n[2];
        for (size_t c = 0; c < nc; c++) {
            const uint32_t o = rt_sub_off(g, k, c);
            h = rt_fnv(h, &o, sizeof o);
        }
    }
    const uint32_t end = (uint32_t)g->nsrefs;
    h = rt_fnv(h, &end, sizeof end);
    if (g->srefs)
        return rt_fnv(h, g->srefs, g->nsrefs * sizeof *g->srefs);
    /* the primitive indices whichever the layout (the sub-grids' references in order) */
    for (size_t k = 0; k < g->nsubs; k++) {
        const rt_subgrid *sg = &g->subs[k];
        const size_t nc = (size_t)sg->b.n[0] * (size_t)sg->b.n[1] * (size_t)sg->b.n[2];
        for (uint32_t j = sg->ref0; j < sg->ref0 + g->soff16[sg->first16 + nc]; j++)
            h = rt_fnv(h, &g->sloc[sg->loc0 + g->sref16[j]], sizeof(uint32_t));
    }
    return h;
}

int rt_scene_grid_info(const rt_scene *sc, rt_grid_info *gi)
{
    if (!sc || !gi)
        return RT_ERR_ARG;
    if (!sc->committed)
        return RT_ERR_STATE;
    memset(gi, 0, sizeof *gi);
    gi->simd = "none";
    gi->prims = sc->nprim;
    if (!sc->use_grid)
        return RT_OK;
    const rt_grid *g = &sc->grid;
    for (int a = 0; a < 3; a++)
        gi->res[a] = g->b.n[a];
    gi->rotated = g->rotated;
    gi->cells = g->ncells;
    gi->refs = g->nrefs;
    gi->subgrids = g->nsubs;
    gi->flat_subgrids = g->nsplanes;
    gi->subcells = g->nsubcells;
    gi->subrefs = g->nsrefs;
    double filled = 0.0;
    for (size_t ci = 0; ci < g->ncells; ci++) {
        uint32_t n = g->off[ci + 1] - g->off[ci];
        gi->empty_cells += n == 0 && !(g->sub && g->sub[ci] >= 0);
        if (n > gi->max_leaf_refs)
            gi->max_leaf_refs = n;
        if (g->sub && g->sub[ci] >= 0) {
            const size_t si = (size_t)g->sub[ci];
            const rt_subgrid *sg = &g->subs[si];
            size_t ns = (size_t)sg->b.n[0] * sg->b.n[1] * sg->b.n[2];
            for (size_t k = 0; k < ns; k++) {
                uint32_t m = rt_sub_off(g, si, k + 1) - rt_sub_off(g, si, k);
                if (m > gi->max_leaf_refs)
                    gi->max_leaf_refs = m;
                filled += m > 0 ? 1.0 / (double)(ns * g->ncells) : 0.0;
            }
        } else {
            filled += n > 0 ? 1.0 / (double)g->ncells : 0.0;
        }
    }
    gi->volume_fill = filled;
    gi->hash = rt_grid_hash(g);
    gi->float_leaves = g->nleaves;
    gi->float_lanes = g->nlanes;
    gi->simd = g->leaf_name;
    return RT_OK;
}
