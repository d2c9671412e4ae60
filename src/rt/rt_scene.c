/* SPDX-License-Identifier: MIT */
/*
 * rt_scene.c -- scene building: surfaces, lights, polygons, cell arrays, commit
 * (degenerate primitives dropped, planes and projections precomputed, grid built).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_geom.h"
#include "rt_shade.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fin3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* geometry coordinates beyond RT_COORD_MAX (gksrt.h) are dropped at commit */
static int sane3(const double v[3])
{
    return fin3(v) && fabs(v[0]) <= RT_COORD_MAX && fabs(v[1]) <= RT_COORD_MAX &&
           fabs(v[2]) <= RT_COORD_MAX;
}

void rt_surface_default(rt_surface *s)
{
    if (!s)
        return;
    memset(s, 0, sizeof *s);
    s->refl_eq = RT_REFL_DIFFUSE;
    s->ka = s->kd = 1.0;
    for (int i = 0; i < 3; i++)
        s->diffuse[i] = s->specular[i] = 1.0;
    s->spec_exp = 1.0;
    s->refr_index = 1.0;
    s->light_mask = ~(uint64_t)0;
}

/* the input triangles and their primitive records */
static rt_tri *in_tris(const rt_scene *sc) { return sc->in_tri.p; }
static rt_prim *in_tri_prims(const rt_scene *sc) { return sc->in_tri_prim.p; }

int rt_scene_input_next(const rt_scene *sc, size_t n, void *lo[2], void *hi[2])
{
    const rt_big *b[2] = { &sc->in_tri, &sc->in_tri_prim };
    const size_t es[2] = { sizeof(rt_tri), sizeof(rt_prim) };
    int k = 0;
    for (int i = 0; i < 2; i++) {
        if (!b[i]->map_bytes || sc->nintri > b[i]->cap) /* on malloc: it may move */
            continue;
        const size_t room = b[i]->cap - sc->nintri, m = n < room ? n : room;
        lo[k] = (char *)b[i]->p + sc->nintri * es[i];
        hi[k] = (char *)lo[k] + m * es[i];
        k++;
    }
    return k;
}

static int rt_tri_prim(rt_scene *sc, const double *v, int id, int front, int back,
                       rt_prim *pr);
static void rt_tri_bbox(const rt_scene *sc, size_t lo, size_t hi, double bb[6]);

rt_scene *rt_scene_new(void)
{
    rt_scene *sc = rt_calloc_array(1, sizeof *sc);
    if (sc)
        rt_tri_bbox(sc, 0, 0, sc->tri_bb);
    return sc;
}

static void rt_scene_uncommit(rt_scene *sc)
{
    for (size_t k = 0; sc->pgrid && k < sc->npoly; k++)
        rt_pgrid_free(&sc->pgrid[k]);
    free(sc->pgrid); sc->pgrid = NULL;
    if (sc->prim_owned)
        free(sc->prim);
    sc->prim = NULL; sc->nprim = 0; sc->prim_owned = 0;
    free(sc->cmesh); sc->cmesh = NULL;
    if (sc->tri_owned)
        free(sc->tri);
    sc->tri = NULL; sc->ntri = 0; sc->tri_owned = 0;
    if (sc->ctri_owned)
        free(sc->ctri);
    sc->ctri = NULL; sc->ntri_plain = 0; sc->ctri_owned = 0;
    free(sc->quad); sc->quad = NULL; sc->nquad = 0;
    free(sc->poly); sc->poly = NULL; sc->npoly = 0;
    free(sc->cell); sc->cell = NULL; sc->ncell = 0;
    free(sc->uv); sc->uv = NULL; sc->nuv = 0;
    free(sc->loops); sc->loops = NULL; sc->nloops = 0;
    free(sc->slab_off); sc->slab_off = NULL; sc->nslab_off = 0;
    free(sc->edges); sc->edges = NULL; sc->nedges = 0;
    rt_grid_free(&sc->grid);
    free(sc->prim_vd); sc->prim_vd = NULL;
    sc->use_grid = 0;
    sc->committed = 0;
}

void rt_scene_free(rt_scene *sc)
{
    if (!sc)
        return;
    rt_scene_uncommit(sc);
    free(sc->surf);
    free(sc->spair);
    free(sc->spair_hash);
    free(sc->in);
    rt_big_free(&sc->in_tri);
    rt_big_free(&sc->in_tri_prim);
    free(sc->in_xyz);
    free(sc->in_loops);
    free(sc->in_rgb);
    free(sc->vd);
    free(sc->vd_xyz);
    free(sc->vd_n);
    free(sc->vd_c);
    free(sc->vd_loops);
    free(sc->mesh);
    rt_big_free(&sc->mv_xyz);
    rt_big_free(&sc->mv_n);
    rt_big_free(&sc->mv_c);
    rt_big_free(&sc->mtri);
    free(sc);
}

int rt_scene_add_surface(rt_scene *sc, const rt_surface *s)
{
    if (!sc || !s)
        return RT_ERR_ARG;
    if (s->refl_eq < RT_REFL_NONE || s->refl_eq > RT_REFL_SPECULAR)
        return RT_ERR_ARG;
    const double k[] = {s->ka, s->kd, s->ks, s->spec_exp, s->diffuse[0], s->diffuse[1],
                        s->diffuse[2], s->specular[0], s->specular[1], s->specular[2]};
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++)
        if (!isfinite(k[i]) || k[i] < 0.0)
            return RT_ERR_ARG;
    if (!isfinite(s->transparency) || s->transparency < 0.0 || s->transparency > 1.0)
        return RT_ERR_ARG;
    if (!isfinite(s->refr_index) || s->refr_index <= 0.0)
        return RT_ERR_ARG;
    if (sc->nsurf >= INT_MAX)
        return RT_ERR_LIMIT;
    if (!rt_grow((void **)&sc->surf, &sc->capsurf, sc->nsurf + 1, sizeof *sc->surf))
        return RT_ERR_NOMEM;
    sc->surf[sc->nsurf] = *s;
    sc->committed = 0;
    return (int)sc->nsurf++;
}

/* 1 if the light l's values are usable for its type (rt_scene_add_light's RT_ERR_ARG) */
static int rt_light_ok(const rt_light *l)
{
    if (l->type < RT_LIGHT_AMBIENT || l->type > RT_LIGHT_SPOT)
        return 0;
    for (int i = 0; i < 3; i++)
        if (!isfinite(l->color[i]) || l->color[i] < 0.0)
            return 0;
    const int dir = l->type == RT_LIGHT_DIRECTIONAL || l->type == RT_LIGHT_SPOT;
    const int pos = l->type == RT_LIGHT_POSITIONAL || l->type == RT_LIGHT_SPOT;
    if (dir && (!fin3(l->direction) ||
                !(fabs(l->direction[0]) + fabs(l->direction[1]) + fabs(l->direction[2]) > 0.0)))
        return 0;
    if (pos && (!fin3(l->position) || !isfinite(l->c1) || !isfinite(l->c2) || l->c1 < 0.0 ||
                l->c2 < 0.0 || !(l->c1 + l->c2 > 0.0)))
        return 0;
    if (l->type == RT_LIGHT_SPOT &&
        (!isfinite(l->concentration) || l->concentration < 0.0 || !isfinite(l->spread) ||
         l->spread <= 0.0 || l->spread > 3.14159265358979323846 + 1e-12))
        return 0;
    return 1;
}

/* the finite non-zero direction v as a unit vector into o */
static void rt_unit_direction(const double v[3], double o[3])
{
    double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(n > 0.0) || !isfinite(n)) { /* tiny or huge components: scale first */
        double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
        double t[3] = {v[0] / m, v[1] / m, v[2] / m};
        n = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (int i = 0; i < 3; i++)
            o[i] = t[i] / n;
    } else {
        for (int i = 0; i < 3; i++)
            o[i] = v[i] / n;
    }
}

int rt_scene_add_light(rt_scene *sc, const rt_light *l)
{
    if (!sc || !l || !rt_light_ok(l))
        return RT_ERR_ARG;
    if (sc->nlights >= RT_MAX_LIGHTS)
        return RT_ERR_LIMIT;
    rt_light *d = &sc->light[sc->nlights];
    *d = *l;
    if (l->type == RT_LIGHT_DIRECTIONAL || l->type == RT_LIGHT_SPOT)
        rt_unit_direction(l->direction, d->direction);
    return sc->nlights++;
}

void rt_scene_clear_lights(rt_scene *sc)
{
    if (sc)
        sc->nlights = 0;
}

int rt_scene_set_surface_lights(rt_scene *sc, int surf, uint64_t mask)
{
    if (!sc || surf < 0 || (size_t)surf >= sc->nsurf)
        return RT_ERR_ARG;
    sc->surf[surf].light_mask = mask;
    return RT_OK;
}

int rt_scene_count(const rt_scene *sc)
{
    return sc ? (int)sc->nids : 0;
}

int rt_scene_truncate(rt_scene *sc, int n)
{
    if (!sc || n < 0 || (size_t)n > sc->nids)
        return RT_ERR_ARG;
    rt_scene_uncommit(sc);
    while (sc->nintri > 0 && in_tri_prims(sc)[sc->nintri - 1].id >= n) {
        sc->nintri--;
        sc->tri_bb_stale = 1;
    }
    while (sc->nin > 0 && sc->in[sc->nin - 1].id >= n) {
        const rt_in_prim *p = &sc->in[--sc->nin];
        sc->nxyz = p->xyz0;
        if (p->kind == RT_KIND_CELL)
            sc->nrgb = p->rgb0;
        else
            sc->nloopsin = p->loop0;
    }
    sc->mesh_open = 0;
    while (sc->nmesh > 0 && sc->mesh[sc->nmesh - 1].id >= (uint32_t)n) {
        const rt_mesh *m = &sc->mesh[--sc->nmesh];
        sc->nmv = m->v0;
        sc->nmtri = m->t0;
    }
    while (sc->nvd > 0 && sc->vd[sc->nvd - 1].id >= (uint32_t)n) {
        const rt_vd *r = &sc->vd[--sc->nvd];
        sc->nvdv = r->v0;
        sc->nvdl = r->loop0;
    }
    sc->nids = (size_t)n;
    return RT_OK;
}

static int rt_surface_ok(const rt_scene *sc, int s)
{
    return s >= 0 && (size_t)s < sc->nsurf;
}

int rt_loops_vertices(int nloops, const int *loop_counts, size_t *nv)
{
    *nv = 0;
    for (int k = 0; k < nloops; k++) {
        if (loop_counts[k] <= 0)
            return RT_ERR_ARG;
        *nv += (size_t)loop_counts[k];
        if (*nv > (size_t)UINT32_MAX / 4)
            return RT_ERR_LIMIT;
    }
    return RT_OK;
}

int rt_scene_add_polygon(rt_scene *sc, int nloops, const int *loop_counts, const double *xyz,
                         int front_surface, int back_surface)
{
    if (!sc || nloops <= 0 || !loop_counts || !xyz)
        return RT_ERR_ARG;
    if (!rt_surface_ok(sc, front_surface) || !rt_surface_ok(sc, back_surface))
        return RT_ERR_ARG;
    size_t nv;
    const int lrc = rt_loops_vertices(nloops, loop_counts, &nv);
    if (lrc != RT_OK)
        return lrc;
    if (sc->nids >= INT_MAX || sc->nxyz + 3 * nv > (size_t)UINT32_MAX * 2)
        return RT_ERR_LIMIT;
    if (nloops == 1 && nv == 3) {
        /* a triangle: kept as the committed scene will trace it, with its primitive record
           as the commit makes it; a degenerate one (never traced) only takes its id */
        rt_prim pr;
        const int trc = rt_tri_prim(sc, xyz, (int)sc->nids, front_surface, back_surface, &pr);
        if (trc < 0) /* rt_prim_init's error (storage for the surface pair) */
            return trc;
        if (trc) {
            if (!rt_big_grow(&sc->in_tri, sc->nintri + 1, sizeof(rt_tri)) ||
                !rt_big_grow(&sc->in_tri_prim, sc->nintri + 1, sizeof(rt_prim)))
                return RT_ERR_NOMEM;
            pr.data = (uint32_t)sc->nintri;
            memcpy(in_tris(sc)[sc->nintri].v, xyz, sizeof(rt_tri));
            in_tri_prims(sc)[sc->nintri++] = pr;
            for (int i = 0; i < 3; i++)
                rt_bbox_add(sc->tri_bb, xyz + 3 * i);
        }
        sc->committed = 0;
        return (int)sc->nids++;
    }
    if (!rt_grow((void **)&sc->in, &sc->capin, sc->nin + 1, sizeof *sc->in) ||
        !rt_grow((void **)&sc->in_xyz, &sc->capxyz, sc->nxyz + 3 * nv, sizeof(double)) ||
        !rt_grow((void **)&sc->in_loops, &sc->caploopsin, sc->nloopsin + (size_t)nloops,
                 sizeof(int)))
        return RT_ERR_NOMEM;
    rt_in_prim *p = &sc->in[sc->nin];
    p->kind = RT_KIND_POLY;
    p->id = (int)sc->nids;
    p->front = front_surface;
    p->back = back_surface;
    p->xyz0 = sc->nxyz;
    p->loop0 = sc->nloopsin;
    p->nloops = nloops;
    p->nx = p->ny = 0;
    p->rgb0 = 0;
    memcpy(sc->in_xyz + sc->nxyz, xyz, 3 * nv * sizeof(double));
    memcpy(sc->in_loops + sc->nloopsin, loop_counts, (size_t)nloops * sizeof(int));
    sc->nxyz += 3 * nv;
    sc->nloopsin += (size_t)nloops;
    sc->committed = 0;
    sc->nin++;
    return (int)sc->nids++;
}

_Static_assert(RT_PARTS_MAX == RT_PAR_MAX, "gksrt.h's RT_PARTS_MAX is the pool's RT_PAR_MAX");

void rt_parallel_parts(int threads, void (*fn)(void *arg, int k, int n), void *arg)
{
    rt_par_run(rt_par_threads(threads), fn, arg);
}

void rt_mesh_store_normal(float o[3], const double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2]))), l = 0.0;
    if (m > 0.0) {
        double a = v[0] / m, b = v[1] / m, e = v[2] / m;
        l = m * sqrt(a * a + b * b + e * e);
    }
    for (int k = 0; k < 3; k++) /* as rt_scene_add_polygon_data stores them */
        o[k] = l > 0.0 ? (float)(v[k] / l) : 0.0f;
}

void rt_mesh_store_colour(float o[3], const double c[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = (float)(c[k] < 0.0 ? 0.0 : c[k] > 1.0 ? 1.0 : c[k]);
}

int rt_scene_mesh_begin(rt_scene *sc, size_t nverts, int has_n, int has_c, size_t ntris,
                        rt_mesh_fill *f)
{
    if (!sc || !f)
        return RT_ERR_ARG;
    memset(f, 0, sizeof *f);
    if (sc->nids >= INT_MAX || nverts > (size_t)RT_MAX_MESH_VERTS - sc->nmv ||
        ntris > ((size_t)1 << 31) - sc->nmtri)
        return RT_ERR_LIMIT;
    const size_t nv = sc->nmv + nverts, nt = sc->nmtri + ntris;
    if (!rt_grow((void **)&sc->mesh, &sc->capmesh, sc->nmesh + 1, sizeof *sc->mesh) ||
        !rt_big_grow(&sc->mv_xyz, nv ? nv : 1, 3 * sizeof(double)) ||
        (has_n && !rt_big_grow(&sc->mv_n, nv ? nv : 1, 3 * sizeof(float))) ||
        (has_c && !rt_big_grow(&sc->mv_c, nv ? nv : 1, 3 * sizeof(float))) ||
        !rt_big_grow(&sc->mtri, nt ? nt : 1, 3 * sizeof(uint32_t)))
        return RT_ERR_NOMEM;
    /* the reservation, for rt_scene_mesh_end (a later add or begin replaces it) */
    sc->mesh[sc->nmesh] = (rt_mesh){ .has_n = has_n != 0, .has_c = has_c != 0,
                                     .t0 = sc->nmtri, .nt = ntris, .v0 = sc->nmv, .nv = nverts };
    sc->mesh_open = 1;
    f->xyz = (double *)sc->mv_xyz.p + 3 * sc->nmv;
    f->normals = has_n ? (float *)sc->mv_n.p + 3 * sc->nmv : NULL;
    f->colours = has_c ? (float *)sc->mv_c.p + 3 * sc->nmv : NULL;
    f->idx = (uint32_t *)sc->mtri.p + 3 * sc->nmtri;
    return RT_OK;
}

/* The per-triangle work of an added mesh m, in parts of consecutive triangles (and of its
   vertices) on the pool: every index below m->nv (else bad) and made global (+ v0); a triangle
   with a vertex that is not sane or that rt_tri_prim would find degenerate is dropped (never
   traced), the kept ones moved to the front of the part's range in order; the box of the kept
   ones and their frame candidates (rt_fcands: ranked as the grid's frame choice ranks them);
   the normals and colours finite (else bad); with sum, each kept triangle's vertex sum (the
   centre's coordinates times 3, which rt_mesh_sort's order is made of) at its kept place, so
   that the sort does not gather the vertices in the given order a second time. What the
   commit did for every mesh triangle at every commit (the check and the box here, the ranking
   in the frame choice's pass), done once here, where the caller (the workstation's recording)
   may overlap it with the application's calls. The same kept triangles, box and candidates
   for any number of parts. */
typedef struct rt_mesh_add_part {
    double bb[6];
    size_t kept;
    int bad;
    rt_fcands cands;           /* the kept ones' frame candidates (indices from the part's) */
} rt_mesh_add_part;

typedef struct rt_mesh_add_job {
    const rt_mesh *m;
    uint32_t *ix;             /* the mesh's index triples, the kept ones written there */
    const uint32_t *six;      /* ... as given, read from here (the caller's, or ix) */
    const double (*X)[3];     /* the mesh's vertices (its own indices): the scene's copy, or
                                 the caller's array that rt_scene_add_mesh adds */
    const float *n, *c;       /* the mesh's normals, colours (NULL: none) */
    double (*sum)[3];         /* per triangle: its vertex sum (NULL: not wanted) */
    _Alignas(RT_LINE) rt_mesh_add_part part[RT_PAR_MAX];
} rt_mesh_add_job;

static inline int rt_tri_surely_sane_ext(const double *v0, const double *v1, const double *v2,
                                         double ext);

/* *l, *h := the least and the greatest of a, b, c, the first of equal values kept */
static inline void rt_minmax3(double a, double b, double c, double *l, double *h)
{
    const double l1 = b < a ? b : a, h1 = b > a ? b : a;
    *l = c < l1 ? c : l1;
    *h = c > h1 ? c : h1;
}

static void rt_mesh_add_run(void *arg, int k, int n)
{
    rt_mesh_add_job *j = arg;
    const rt_mesh *m = j->m;
    rt_mesh_add_part *o = &j->part[k];
    size_t lo, hi, w;
    rt_par_range(3 * m->nv, k, n, &lo, &hi);
    const float *nf = j->n, *cf = j->c; /* no pass over the vertices without either */
    if (nf || cf)
        for (size_t i = lo; i < hi; i++)
            if ((nf && !isfinite(nf[i])) || (cf && !isfinite(cf[i])))
                o->bad = 1;
    double bb0 = INFINITY, bb1 = INFINITY, bb2 = INFINITY;
    double bb3 = -INFINITY, bb4 = -INFINITY, bb5 = -INFINITY;
    rt_par_range(m->nt, k, n, &lo, &hi);
    w = lo;
    for (size_t t = lo; t < hi && !o->bad; t++) {
        const uint32_t *q = j->six + 3 * t;
        if (q[0] >= m->nv || q[1] >= m->nv || q[2] >= m->nv) {
            o->bad = 1;
            break;
        }
        const uint32_t a = q[0] + (uint32_t)m->v0, b = q[1] + (uint32_t)m->v0,
                       c = q[2] + (uint32_t)m->v0;
        const double *A = j->X[q[0]], *B = j->X[q[1]], *C = j->X[q[2]];
        /* the triangle's box, the first of equal values kept (-0 or +0, as rt_bbox_add
           growing a box by A, B, C in turn keeps them), its extent for rt_tri_surely_sane's
           test (hi - lo is the same value whichever zero is kept), and the vertex sum; axis
           by axis written out (gcc keeps 3-element loops and their arrays in memory) */
        double l0, h0, l1, h1, l2, h2;
        rt_minmax3(A[0], B[0], C[0], &l0, &h0);
        rt_minmax3(A[1], B[1], C[1], &l1, &h1);
        rt_minmax3(A[2], B[2], C[2], &l2, &h2);
        const double s0 = A[0] + B[0] + C[0], s1 = A[1] + B[1] + C[1], s2 = A[2] + B[2] + C[2];
        /* sane3 of A, B and C: a finite sum of the sums has finite addends, and then the box
           bounds every coordinate's size (one test, not nine of each kind); a sum that
           overflows takes sane3 itself */
        const int fin = isfinite(s0 + s1 + s2);
        if (fin ? !((l0 >= -RT_COORD_MAX) & (l1 >= -RT_COORD_MAX) & (l2 >= -RT_COORD_MAX) &
                    (h0 <= RT_COORD_MAX) & (h1 <= RT_COORD_MAX) & (h2 <= RT_COORD_MAX))
                : !(sane3(A) && sane3(B) && sane3(C)))
            continue;
        double ext = h0 - l0 > 0.0 ? h0 - l0 : 0.0;
        ext = h1 - l1 > ext ? h1 - l1 : ext;
        ext = h2 - l2 > ext ? h2 - l2 : ext;
        double nrm[3];
        if (!(rt_tri_surely_sane_ext(A, B, C, ext) || rt_tri_normal_sane(A, B, C, nrm)))
            continue;
        bb0 = l0 < bb0 ? l0 : bb0;
        bb1 = l1 < bb1 ? l1 : bb1;
        bb2 = l2 < bb2 ? l2 : bb2;
        bb3 = h0 > bb3 ? h0 : bb3;
        bb4 = h1 > bb4 ? h1 : bb4;
        bb5 = h2 > bb5 ? h2 : bb5;
        if (j->sum) {
            j->sum[w][0] = s0;
            j->sum[w][1] = s1;
            j->sum[w][2] = s2;
        }
        /* the frame candidates' rank from the box made here (rt_pts_bbox's values); a call
           only for a triangle that enters the list */
        const double ar = rt_fcands_area(h0 - l0, h1 - l1, h2 - l2);
        if (rt_fcands_takes(&o->cands, ar))
            rt_fcands_add(&o->cands, ar, w - lo);
        uint32_t *d = j->ix + 3 * w++;
        d[0] = a;
        d[1] = b;
        d[2] = c;
    }
    const double bb[6] = {bb0, bb1, bb2, bb3, bb4, bb5};
    memcpy(o->bb, bb, sizeof bb);
    o->kept = w - lo;
}

/* rt_mesh_add_run on the pool's threads (parts of at least 16384 triangles) over the mesh's
   vertices and index triples (src, srcix: the caller's, not yet copied; NULL: the scene's);
   the kept triangles closed up in the scene's triples, in order (and their vertex sums into
   sum, NULL: none); the box into m. RT_OK or RT_ERR_ARG (nothing added). */
static int rt_mesh_add_check(rt_scene *sc, rt_mesh *m, double (*sum)[3], const double *src,
                             const uint32_t *srcix)
{
    rt_mesh_add_job job, *j = &job; /* 13 KiB: no allocation that could fail */
    memset(j, 0, sizeof *j);
    j->m = m;
    j->ix = (uint32_t *)sc->mtri.p + 3 * m->t0;
    j->six = srcix ? srcix : j->ix;
    j->X = (const double (*)[3])(src ? src : (const double *)sc->mv_xyz.p + 3 * m->v0);
    j->n = m->has_n ? (const float *)sc->mv_n.p + 3 * m->v0 : NULL;
    j->c = m->has_c ? (const float *)sc->mv_c.p + 3 * m->v0 : NULL;
    j->sum = sum;
    int np = rt_par_pool_threads();
    if ((size_t)np > m->nt / 16384 + 1)
        np = (int)(m->nt / 16384 + 1);
    rt_par_run(np, rt_mesh_add_run, j);
    size_t w = 0;
    int bad = 0;
    m->cands.nc = 0;
    for (int i = 0; i < 3; i++) {
        m->bb[i] = INFINITY;
        m->bb[3 + i] = -INFINITY;
    }
    for (int k = 0; k < np; k++) {
        const rt_mesh_add_part *o = &j->part[k];
        size_t lo, hi;
        rt_par_range(m->nt, k, np, &lo, &hi);
        bad |= o->bad;
        rt_fcands_merge(&m->cands, &o->cands, w);
        if (w < lo && o->kept) {
            memmove(j->ix + 3 * w, j->ix + 3 * lo, 3 * o->kept * sizeof(uint32_t));
            if (sum)
                memmove(sum + w, sum + lo, o->kept * sizeof *sum);
        }
        w += o->kept;
        for (int i = 0; i < 3; i++) {
            m->bb[i] = fmin(m->bb[i], o->bb[i]);
            m->bb[3 + i] = fmax(m->bb[3 + i], o->bb[3 + i]);
        }
    }
    if (bad)
        return RT_ERR_ARG;
    m->nt = w;
    return RT_OK;
}

/* The Morton code of point p's cell in a box cut into 1024 cells an axis (lo: its low corner,
   sc: 1024 / its widths, 0 for an empty width): 30 bits, x in bit 0, y in bit 1, z in bit 2
   of each triple; a coordinate outside the box is clamped to its first or last cell */
static uint32_t rt_morton30(const double lo[3], const double sc[3], const double p[3])
{
    uint32_t c = 0;
    for (int k = 0; k < 3; k++) {
        const double f = (p[k] - lo[k]) * sc[k];
        uint32_t q = f > 0.0 ? (f < 1023.0 ? (uint32_t)f : 1023u) : 0u;
        q = (q | q << 16) & 0x030000ffu; /* the 10 bits spread 3 apart */
        q = (q | q << 8) & 0x0300f00fu;
        q = (q | q << 4) & 0x030c30c3u;
        q = (q | q << 2) & 0x09249249u;
        c |= q << k;
    }
    return c;
}

/* LSD radix sort of a[0 .. n-1] by their 30-bit codes in bits 32-61, with b of the same size;
   returns the sorted keys (a or b). Four passes of 8 bits (stable: equal codes keep their
   order), every pass's counts from one read of the keys, a pass whose digit is the same for
   every key skipped: 256 lists written at once fit the first-level cache where 1024 did not
   (three passes of 10 bits missed it about twice a key and pass). */
static uint64_t *rt_sort_codes(uint64_t *a, uint64_t *b, size_t n)
{
    uint32_t cnt[4][256];
    memset(cnt, 0, sizeof cnt);
    for (size_t v = 0; v < n; v++) {
        const uint32_t c = (uint32_t)(a[v] >> 32);
        cnt[0][c & 0xff]++;
        cnt[1][c >> 8 & 0xff]++;
        cnt[2][c >> 16 & 0xff]++;
        cnt[3][c >> 24]++;
    }
    uint64_t *from = a, *to = b;
    for (int q = 0; q < 4; q++) {
        uint32_t *k = cnt[q], run = 0;
        if (n && k[(uint32_t)(a[0] >> (32 + 8 * q)) & 0xff] == n)
            continue; /* one digit for all: the order stays */
        for (int d = 0; d < 256; d++) {
            const uint32_t x = k[d];
            k[d] = run;
            run += x;
        }
        const int sh = 32 + 8 * q;
        for (size_t v = 0; v < n; v++)
            to[k[from[v] >> sh & 0xff]++] = from[v];
        uint64_t *x = from;
        from = to;
        to = x;
    }
    return from;
}

/* the place of key x in the sorted keys s[0 .. n-1] (x is one of them) */
static size_t rt_sorted_place(const uint64_t *s, size_t n, uint64_t x)
{
    size_t lo = 0, hi = n; /* s[lo] <= x < s[hi] */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (s[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Added mesh m in spatial order: its triangles sorted by the Morton code of their centres in
   its box (ties: the given order), each triple's vertices written as offsets 3 v with the
   given position above them (rt_ctri_given), the frame candidates' indices renumbered to
   match; its vertices renumbered in the order of their first use by the sorted triangles
   (unused ones last, in the given order), with the same coordinates, normals and colours,
   each triangle's vertices in their given roles. key: 2 nt words, to: nv, tmp: 24 nt bytes
   and 24 nv without src, 12 nv with normals or colours; tmp holds the triangles' vertex
   sums on entry (rt_mesh_add_check). src: the vertices in the given
   order when the scene's copy is not yet made (rt_scene_add_mesh: they are placed from the
   caller's array, no copy first), or NULL. */
static void rt_mesh_sort(rt_scene *sc, rt_mesh *m, uint64_t *key, uint32_t *to, void *tmp,
                         const double *src)
{
    const size_t nt = m->nt, nv = m->nv;
    const uint32_t v0 = (uint32_t)m->v0;
    uint32_t (*T)[3] = (uint32_t (*)[3])sc->mtri.p + m->t0;
    double (*X)[3] = (double (*)[3])sc->mv_xyz.p + m->v0;
    const double (*sum)[3] = tmp;
    double lo[3], sk[3];
    for (int k = 0; k < 3; k++) { /* centres as sums of three: the box taken three times */
        const double w = 3.0 * (m->bb[3 + k] - m->bb[k]);
        lo[k] = 3.0 * m->bb[k];
        sk[k] = w > 0.0 ? 1024.0 / w : 0.0;
    }
    for (size_t t = 0; t < nt; t++)
        key[t] = (uint64_t)rt_morton30(lo, sk, sum[t]) << 32 | t;
    uint64_t cand[RT_FRAME_CAND]; /* the candidates' keys, found again once sorted */
    for (int q = 0; q < m->cands.nc; q++)
        cand[q] = key[m->cands.cand[q]];
    const uint64_t *s = rt_sort_codes(key, key + nt, nt);
    for (int q = 0; q < m->cands.nc; q++)
        m->cands.cand[q] = rt_sorted_place(s, nt, cand[q]);
    /* the triples in the new order (the given ones copied to tmp), vertices numbered at
       their first use */
    uint32_t (*G)[3] = tmp;
    memcpy(G, T, nt * sizeof *T);
    for (size_t v = 0; v < nv; v++)
        to[v] = UINT32_MAX;
    uint32_t next = 0;
    for (size_t t = 0; t < nt; t++) {
        const uint32_t o = (uint32_t)s[t];
        for (int k = 0; k < 3; k++) { /* a new number without a branch (taken at random) */
            const uint32_t v = G[o][k] - v0, u = to[v], fresh = u == UINT32_MAX;
            const uint32_t x = fresh ? next : u;
            to[v] = x;
            next += fresh;
            T[t][k] = 3 * (v0 + x) | rt_ctri_given_bits(o, k);
        }
    }
    m->nused = next;
    for (size_t v = 0; v < nv; v++)
        if (to[v] == UINT32_MAX)
            to[v] = next++;
    if (!src) {
        memcpy(tmp, X, nv * 3 * sizeof(double));
        src = tmp;
    }
    for (size_t v = 0; v < nv; v++)
        memcpy(X[to[v]], src + 3 * v, 3 * sizeof(double));
    rt_big *fl[2] = {m->has_n ? &sc->mv_n : NULL, m->has_c ? &sc->mv_c : NULL};
    for (int k = 0; k < 2; k++) {
        if (!fl[k])
            continue;
        float (*F)[3] = (float (*)[3])fl[k]->p + m->v0;
        memcpy(tmp, F, nv * 3 * sizeof(float));
        for (size_t v = 0; v < nv; v++)
            memcpy(F[to[v]], (const float *)tmp + 3 * v, 3 * sizeof(float));
    }
}

/* The given order back for every mesh of the scene, the triangles moved in place along the
   cycles of their permutation (no memory needed), the frame candidates renumbered back; the
   scene's meshes keep the given order from now on (a mesh beyond the limits was added). */
static void rt_meshes_given_order(rt_scene *sc)
{
    for (size_t mi = 0; mi < sc->nmesh && sc->vmask != UINT32_MAX; mi++) {
        rt_mesh *m = &sc->mesh[mi];
        uint32_t (*T)[3] = (uint32_t (*)[3])sc->mtri.p + m->t0;
        for (int q = 0; q < m->cands.nc; q++)
            m->cands.cand[q] = rt_ctri_given(T[m->cands.cand[q]]);
        for (size_t t = 0; t < m->nt; t++) {
            for (uint32_t g = rt_ctri_given(T[t]); g != t; g = rt_ctri_given(T[t])) {
                uint32_t x[3];
                memcpy(x, T[g], sizeof x);
                memcpy(T[g], T[t], sizeof x);
                memcpy(T[t], x, sizeof x);
            }
        }
        for (size_t t = 0; t < m->nt; t++)
            for (int k = 0; k < 3; k++)
                T[t][k] &= RT_VMASK;
    }
    sc->vmask = UINT32_MAX;
}

/* added mesh m's index words (vertex indices, global) as the vertices' offsets 3 v, the
   position of each triangle above them (rt_ctri_given) when given */
static void rt_mesh_offsets(rt_scene *sc, rt_mesh *m, int given)
{
    uint32_t (*T)[3] = (uint32_t (*)[3])sc->mtri.p + m->t0;
    for (size_t t = 0; t < m->nt; t++)
        for (int k = 0; k < 3; k++)
            T[t][k] = 3 * T[t][k] | (given ? rt_ctri_given_bits((uint32_t)t, k) : 0u);
}

/* Added mesh m (its indices global and checked) stored in spatial order: its vertices in the
   order of their first use, its triangles in the Morton order of their centres (rt_mesh_sort),
   while the scene's vertices' offsets fit in RT_VBITS bits and the mesh's triangles in 24;
   else the given order for every mesh from now on. The triangles of a cell list are near
   each other in space, so their index triples and vertices then share cache lines (a ray's
   chain reference -> index triple -> three vertices misses less). The same coordinates, the
   same triangles with their vertices in their given roles, the tie rule on the given
   positions: every answer stays bit for bit; no byte more at rest. key, tmp, to: the parts
   of rt_mesh_end's block, tmp with the triangles' vertex sums (rt_mesh_add_check), or NULL:
   without it the given order is kept with the positions written (nothing else changes).
   Either way the index words end as offsets (rt_scene.vmask). */
static void rt_mesh_order(rt_scene *sc, rt_mesh *m, uint64_t *key, void *tmp, uint32_t *to,
                          const double *src)
{
    if (sc->nmesh == 0) { /* a scene without meshes starts over */
        sc->vmask = RT_VMASK;
        sc->vlimit = (size_t)RT_VMASK / 3 + 1;
    }
    if (sc->vmask != UINT32_MAX &&
        (sc->nmv + m->nv > sc->vlimit || m->nt > ((size_t)1 << 24)))
        rt_meshes_given_order(sc);
    if (sc->vmask != UINT32_MAX && key) {
        rt_mesh_sort(sc, m, key, to, tmp, src);
        return;
    }
    if (src) /* the given order: the vertices as given */
        memcpy((double *)sc->mv_xyz.p + 3 * m->v0, src, m->nv * 3 * sizeof(double));
    /* with the positions written unless the given order holds from now on */
    rt_mesh_offsets(sc, m, sc->vmask != UINT32_MAX);
}

/* rt_scene_mesh_end with the vertices of the open mesh in src (its nv, 3 doubles each) and
   its index triples in srcix (nt) when they are not yet in the scene's arrays
   (rt_scene_add_mesh: the check reads them there, writes the kept triples into the scene's,
   and the spatial order places the vertices from there, no copy of them first), or NULL */
static int rt_mesh_end(rt_scene *sc, int front_surface, int back_surface, const double *src,
                       const uint32_t *srcix)
{
    if (!sc || !sc->mesh_open)
        return RT_ERR_STATE;
    sc->mesh_open = 0;
    rt_mesh *m = &sc->mesh[sc->nmesh];
    if (!rt_surface_ok(sc, front_surface) || !rt_surface_ok(sc, back_surface))
        return RT_ERR_ARG;
    /* rt_mesh_order's memory, taken before the check so that the check leaves the vertex
       sums there: one block of 8-byte words, each part as large as its own use (none when
       the scene keeps the given order): the sort's keys and their second buffer (2 nt
       words); tmp, the largest of its uses in turn: the sums (24 bytes a triangle), the
       given triples (12), the vertices when they are the scene's copy (24 a vertex: src
       NULL), the normals or colours (12 a vertex); then the new numbers (4 a vertex).
       Parts sized by the larger of the two counts left most of the block unused for
       triangles of their own vertices, a heap peak that the next scene faults in again
       (docs/bench/rt_tuning.md, "Random triangles at N = 30000"). The counts are below
       2^31 and RT_MAX_MESH_VERTS (rt_scene_mesh_begin): the sizes cannot overflow. */
    const size_t nt = m->nt, nv = m->nv;
    const size_t vbytes = src ? (m->has_n || m->has_c ? 12 * nv : 0) : 24 * nv;
    const size_t ntmp = ((24 * nt > vbytes ? 24 * nt : vbytes) + 7) / 8;
    uint64_t *key = sc->nmesh == 0 || sc->vmask != UINT32_MAX
                        ? rt_alloc_array(2 * nt + ntmp + (4 * nv + 7) / 8 + 1, sizeof(uint64_t))
                        : NULL;
    uint64_t *tmp = key ? key + 2 * nt : NULL;
    const int rc = rt_mesh_add_check(sc, m, (double (*)[3])tmp, src, srcix);
    if (rc == RT_OK)
        rt_mesh_order(sc, m, key, tmp, key ? (uint32_t *)(tmp + ntmp) : NULL, src);
    free(key);
    if (rc != RT_OK)
        return rc;
    m->id = (uint32_t)sc->nids;
    m->front = front_surface;
    m->back = back_surface;
    sc->nmesh++;
    sc->nmv += m->nv;
    sc->nmtri += m->nt;
    sc->committed = 0;
    return (int)sc->nids++;
}

int rt_scene_mesh_end(rt_scene *sc, int front_surface, int back_surface)
{
    return rt_mesh_end(sc, front_surface, back_surface, NULL, NULL);
}

int rt_scene_add_mesh(rt_scene *sc, size_t nverts, const double *xyz, const double *normals,
                      const double *colours, size_t ntris, const uint32_t *idx,
                      int front_surface, int back_surface)
{
    if (!sc || (nverts && !xyz) || (ntris && !idx))
        return RT_ERR_ARG;
    for (size_t i = 0; i < 3 * nverts; i++)
        if ((normals && !isfinite(normals[i])) || (colours && !isfinite(colours[i])))
            return RT_ERR_ARG;
    rt_mesh_fill f;
    const int rc = rt_scene_mesh_begin(sc, nverts, normals != NULL, colours != NULL, ntris, &f);
    if (rc != RT_OK)
        return rc;
    for (size_t i = 0; i < nverts; i++) {
        if (normals)
            rt_mesh_store_normal(f.normals + 3 * i, normals + 3 * i);
        if (colours)
            rt_mesh_store_colour(f.colours + 3 * i, colours + 3 * i);
    }
    return rt_mesh_end(sc, front_surface, back_surface, nverts ? xyz : NULL,
                       ntris ? idx : NULL);
}

int rt_scene_add_cell_array(rt_scene *sc, const double P[3], const double Q[3], const double R[3],
                            int nx, int ny, const float *rgb, int front_surface, int back_surface)
{
    if (!sc || !P || !Q || !R || !rgb || nx <= 0 || ny <= 0)
        return RT_ERR_ARG;
    if (!rt_surface_ok(sc, front_surface) || !rt_surface_ok(sc, back_surface))
        return RT_ERR_ARG;
    size_t ncol = (size_t)nx * (size_t)ny;
    if (ncol > ((size_t)1 << 31) / 3)
        return RT_ERR_LIMIT;
    for (size_t i = 0; i < 3 * ncol; i++)
        if (!isfinite(rgb[i]))
            return RT_ERR_ARG;
    if (sc->nids >= INT_MAX)
        return RT_ERR_LIMIT;
    if (!rt_grow((void **)&sc->in, &sc->capin, sc->nin + 1, sizeof *sc->in) ||
        !rt_grow((void **)&sc->in_xyz, &sc->capxyz, sc->nxyz + 9, sizeof(double)) ||
        !rt_grow((void **)&sc->in_rgb, &sc->caprgb, sc->nrgb + 3 * ncol, sizeof(float)))
        return RT_ERR_NOMEM;
    rt_in_prim *p = &sc->in[sc->nin];
    p->kind = RT_KIND_CELL;
    p->id = (int)sc->nids;
    p->front = front_surface;
    p->back = back_surface;
    p->xyz0 = sc->nxyz;
    p->loop0 = 0;
    p->nloops = 0;
    p->nx = nx;
    p->ny = ny;
    p->rgb0 = sc->nrgb;
    memcpy(sc->in_xyz + sc->nxyz, P, 3 * sizeof(double));
    memcpy(sc->in_xyz + sc->nxyz + 3, Q, 3 * sizeof(double));
    memcpy(sc->in_xyz + sc->nxyz + 6, R, 3 * sizeof(double));
    memcpy(sc->in_rgb + sc->nrgb, rgb, 3 * ncol * sizeof(float));
    sc->nxyz += 9;
    sc->nrgb += 3 * ncol;
    sc->committed = 0;
    sc->nin++;
    return (int)sc->nids++;
}

/* ---- commit ---- */

static int rt_dominant_axis(const double n[3])
{
    double ax = fabs(n[0]), ay = fabs(n[1]), az = fabs(n[2]);
    if (ax >= ay && ax >= az)
        return 0;
    return ay >= az ? 1 : 2;
}

static double rt_len3(const double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (m == 0.0 || !isfinite(m))
        return m;
    double a = v[0] / m, b = v[1] / m, c = v[2] / m;
    return m * sqrt(a * a + b * b + c * c);
}

static void rt_cross(const double a[3], const double b[3], double r[3])
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

/* plane normal of a polygon (all loops): the shared Newell normal (rt_shade.h) */
static int rt_poly_normal(const double *v, size_t nv, const int *counts, int nloops,
                          const double c[3], double ext, double n[3])
{
    return rt_newell_normal(v, nv, counts, nloops, c, ext, n);
}

/* planar (within 1e-12 of the size) and strictly convex 4-gon */
static int rt_quad_convex(const double *v, const double n[3], const double c[3], double ext)
{
    for (int i = 0; i < 4; i++) {
        double d = n[0] * (v[3 * i] - c[0]) + n[1] * (v[3 * i + 1] - c[1]) + n[2] * (v[3 * i + 2] - c[2]);
        if (!(fabs(d) <= 1e-12 * ext))
            return 0;
    }
    for (int i = 0; i < 4; i++) {
        const double *a = v + 3 * i, *b = v + 3 * ((i + 1) & 3), *e = v + 3 * ((i + 2) & 3);
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double w[3] = {e[0] - b[0], e[1] - b[1], e[2] - b[2]};
        double x[3];
        rt_cross(u, w, x);
        if (!(x[0] * n[0] + x[1] * n[1] + x[2] * n[2] > 1e-9 * ext * ext))
            return 0;
    }
    return 1;
}

/* 1 if every one of the nv points v (and, for a cell array P, Q, R, its fourth corner
   P + Q - R) lies outside one of the cull planes of o by more than its margin */
static int rt_culled(const rt_build_options *o, const double *v, size_t nv, int cell)
{
    double s[3];
    size_t n = cell ? 4 : nv;
    for (int f = 0; f < o->ncull; f++) {
        const double *pl = o->cull[f];
        int out = 1;
        for (size_t i = 0; i < n && out; i++) {
            const double *q = v + 3 * i;
            if (cell && i == 3) {
                for (int k = 0; k < 3; k++)
                    s[k] = v[k] + v[3 + k] - v[6 + k];
                q = s;
            }
            out = pl[0] * q[0] + pl[1] * q[1] + pl[2] * q[2] + pl[3] < -o->cull_eps;
        }
        if (out)
            return 1;
    }
    return 0;
}

/* bounding box pb and centroid c (relative to the box corner: robust for large offsets) of
   the nv points v; 0 if a point is not sane or the extent *ext is zero or not finite */
static int rt_points_frame(const double *v, size_t nv, double pb[6], double c[3], double *ext)
{
    for (int j = 0; j < 3; j++) {
        pb[j] = INFINITY;
        pb[3 + j] = -INFINITY;
        c[j] = 0.0;
    }
    for (size_t i = 0; i < nv; i++) {
        if (!sane3(v + 3 * i))
            return 0;
        rt_bbox_add(pb, v + 3 * i);
    }
    *ext = fmax(pb[3] - pb[0], fmax(pb[4] - pb[1], pb[5] - pb[2]));
    if (!(*ext > 0.0) || !isfinite(*ext))
        return 0;
    for (size_t i = 0; i < nv; i++)
        for (int j = 0; j < 3; j++)
            c[j] += (v[3 * i + j] - pb[j]) / (double)nv;
    for (int j = 0; j < 3; j++)
        c[j] += pb[j];
    return 1;
}

static uint32_t rt_spair_slot(int front, int back, size_t hcap)
{
    uint64_t h = ((uint64_t)(uint32_t)front << 32 | (uint32_t)back) * 0x9E3779B97F4A7C15u;
    return (uint32_t)(h >> 32) & (uint32_t)(hcap - 1);
}

/* the index of the surface pair (front, back) in sc->spair, added if new: RT_OK, RT_ERR_NOMEM,
   RT_ERR_LIMIT (RT_SPAIR_MAX pairs) */
static int rt_spair_find(rt_scene *sc, int front, int back, uint32_t *sp)
{
    const uint32_t last = sc->spair_last;
    if (last < sc->nspair && sc->spair[last][0] == front && sc->spair[last][1] == back) {
        *sp = last;
        return RT_OK;
    }
    if (sc->spair_hcap) {
        for (uint32_t h = rt_spair_slot(front, back, sc->spair_hcap);; h = (h + 1) & (uint32_t)(sc->spair_hcap - 1)) {
            const uint32_t e = sc->spair_hash[h];
            if (!e)
                break;
            if (sc->spair[e - 1][0] == front && sc->spair[e - 1][1] == back) {
                *sp = sc->spair_last = e - 1;
                return RT_OK;
            }
        }
    }
    if (sc->nspair >= RT_SPAIR_MAX)
        return RT_ERR_LIMIT;
    if (!rt_grow((void **)&sc->spair, &sc->capspair, sc->nspair + 1, sizeof *sc->spair))
        return RT_ERR_NOMEM;
    if (2 * (sc->nspair + 1) > sc->spair_hcap) { /* load <= 1/2: rehash into twice the room */
        const size_t hcap = sc->spair_hcap ? 2 * sc->spair_hcap : 64;
        uint32_t *hash = rt_calloc_array(hcap, sizeof *hash);
        if (!hash)
            return RT_ERR_NOMEM;
        for (size_t k = 0; k < sc->nspair; k++) {
            uint32_t h = rt_spair_slot(sc->spair[k][0], sc->spair[k][1], hcap);
            while (hash[h])
                h = (h + 1) & (uint32_t)(hcap - 1);
            hash[h] = (uint32_t)k + 1;
        }
        free(sc->spair_hash);
        sc->spair_hash = hash;
        sc->spair_hcap = hcap;
    }
    uint32_t h = rt_spair_slot(front, back, sc->spair_hcap);
    while (sc->spair_hash[h])
        h = (h + 1) & (uint32_t)(sc->spair_hcap - 1);
    sc->spair[sc->nspair][0] = front;
    sc->spair[sc->nspair][1] = back;
    sc->spair_hash[h] = (uint32_t)sc->nspair + 1;
    *sp = sc->spair_last = (uint32_t)sc->nspair++;
    return RT_OK;
}

/* id and surfaces of a primitive record: RT_OK, or rt_spair_find's error */
static int rt_prim_init(rt_scene *sc, rt_prim *pr, int id, int front, int back)
{
    uint32_t sp;
    const int rc = rt_spair_find(sc, front, back, &sp);
    if (rc != RT_OK)
        return rc;
    pr->id = id;
    pr->sp = sp;
    pr->opaque = sc->surf[front].transparency == 0.0 && sc->surf[back].transparency == 0.0;
    return RT_OK;
}

/* 1 if rt_tri_normal_sane surely finds the triangle v0 v1 v2 (sane vertices) not degenerate:
   twice its area, the cross product of two edges, is at least 10 times its tolerance
   (1e-12 ext^2, ext the largest extent); both computations round by ~1e-15 ext^2, so its
   Newell normal's length then passes the tolerance. 0: not sure (ask rt_tri_normal_sane).
   The add-time check of a triangle (which keeps no normal) without its 15 divisions. */
/* rt_tri_surely_sane's test once the triangle's extent ext (its box's largest side) is known */
static inline int rt_tri_surely_sane_ext(const double *v0, const double *v1, const double *v2,
                                         double ext)
{
    if (!(ext > 0.0) || !(ext < 1e100))
        return 0;
    const double e10 = v1[0] - v0[0], e11 = v1[1] - v0[1], e12 = v1[2] - v0[2];
    const double e20 = v2[0] - v0[0], e21 = v2[1] - v0[1], e22 = v2[2] - v0[2];
    const double c0 = e11 * e22 - e12 * e21, c1 = e12 * e20 - e10 * e22,
                 c2 = e10 * e21 - e11 * e20;
    const double t = 1e-11 * ext * ext;
    return c0 * c0 + c1 * c1 + c2 * c2 > t * t;
}

static inline int rt_tri_surely_sane(const double *v0, const double *v1, const double *v2)
{
    double ext = 0.0;
    for (int j = 0; j < 3; j++) {
        const double a = v0[j] < v1[j] ? v0[j] : v1[j], b = v0[j] < v1[j] ? v1[j] : v0[j];
        const double lo = a < v2[j] ? a : v2[j], hi = b > v2[j] ? b : v2[j];
        ext = hi - lo > ext ? hi - lo : ext;
    }
    return rt_tri_surely_sane_ext(v0, v1, v2, ext);
}

/* The primitive record of the triangle v (9 doubles) of id and surfaces front, back, as the
   commit traces it (data set by the caller): 1, 0 if it is degenerate (never traced), or the
   error of rt_prim_init (an RT_ERR_*, negative). */
static int rt_tri_prim(rt_scene *sc, const double *v, int id, int front, int back,
                       rt_prim *pr)
{
    double nrm[3];
    if (!sane3(v) || !sane3(v + 3) || !sane3(v + 6))
        return 0;
    if (!rt_tri_surely_sane(v, v + 3, v + 6) && !rt_tri_normal_sane(v, v + 3, v + 6, nrm))
        return 0;
    memset(pr, 0, sizeof *pr);
    const int rc = rt_prim_init(sc, pr, id, front, back);
    if (rc != RT_OK)
        return rc;
    pr->kind = RT_KIND_TRI;
    return 1;
}

/* box of the input triangles lo .. hi-1 */
static void rt_tri_bbox(const rt_scene *sc, size_t lo, size_t hi, double bb[6])
{
    for (int i = 0; i < 3; i++) {
        bb[i] = INFINITY;
        bb[3 + i] = -INFINITY;
    }
    for (size_t k = lo; k < hi; k++)
        for (int i = 0; i < 3; i++)
            rt_bbox_add(bb, in_tris(sc)[k].v[i]);
}

/* Triangles first, in id order. Their records were made when they were added (degenerate ones
   were not kept), so without culling the committed triangles and records are the input's.
   With culling (o->ncull) the kept ones are copied, in nt parts of consecutive triangles
   (threads): each part writes the records of its triangles at their input places (id
   RT_CULLED: culled); a serial pass closes the gaps, so the result is the same for any nt. */
#define RT_CULLED (-1)

typedef struct rt_tri_job {
    rt_scene *sc;
    const rt_build_options *o;
    double bb[RT_PAR_MAX][6];
    size_t kept[RT_PAR_MAX];
} rt_tri_job;

static void rt_commit_tri_part(void *arg, int part, int nparts)
{
    rt_tri_job *j = arg;
    rt_scene *sc = j->sc;
    const rt_build_options *o = j->o;
    double *bb = j->bb[part];
    size_t lo, hi, kept = 0;
    rt_par_range(sc->nintri, part, nparts, &lo, &hi);
    for (int i = 0; i < 3; i++) {
        bb[i] = INFINITY;
        bb[3 + i] = -INFINITY;
    }
    for (size_t k = lo; k < hi; k++) {
        const double *v = &in_tris(sc)[k].v[0][0];
        rt_prim *pr = &sc->prim[k];
        if (rt_culled(o, v, 3, 0)) {
            pr->id = RT_CULLED;
            continue;
        }
        sc->tri[k] = in_tris(sc)[k];
        *pr = in_tri_prims(sc)[k];
        for (int i = 0; i < 3; i++)
            rt_bbox_add(bb, v + 3 * i);
        kept++;
    }
    j->kept[part] = kept;
}

/* the box of the input triangles, part of rt_tri_bbox's parallel recomputation */
static void rt_tri_bbox_part(void *arg, int part, int nparts)
{
    rt_tri_job *j = arg;
    size_t lo, hi;
    rt_par_range(j->sc->nintri, part, nparts, &lo, &hi);
    rt_tri_bbox(j->sc, lo, hi, j->bb[part]);
}

static int rt_commit_tris(rt_scene *sc, const rt_build_options *o, double bb[6])
{
    const int cull = o && o->ncull > 0;
    sc->tri = in_tris(sc);
    sc->ntri = sc->nprim = sc->nintri;
    if (!cull && !sc->tri_bb_stale) {
        memcpy(bb, sc->tri_bb, sizeof sc->tri_bb);
        return RT_OK;
    }
    if (cull) {
        sc->tri = rt_alloc_array(sc->nintri, sizeof *sc->tri);
        if (!sc->tri)
            return RT_ERR_NOMEM;
        sc->tri_owned = 1;
    }
    int nt = rt_par_threads(o ? o->threads : 0);
    if ((size_t)nt > sc->nintri / 16384 + 1)
        nt = (int)(sc->nintri / 16384 + 1);
    rt_tri_job *j = rt_alloc_array(1, sizeof *j);
    if (!j)
        return RT_ERR_NOMEM;
    j->sc = sc;
    j->o = o;
    rt_par_run(nt, cull ? rt_commit_tri_part : rt_tri_bbox_part, j);
    size_t kept = 0;
    for (int k = 0; k < nt; k++) {
        kept += cull ? j->kept[k] : 0;
        for (int i = 0; i < 3; i++) {
            if (j->bb[k][i] < bb[i])
                bb[i] = j->bb[k][i];
            if (j->bb[k][3 + i] > bb[3 + i])
                bb[3 + i] = j->bb[k][3 + i];
        }
    }
    free(j);
    if (!cull) { /* the input's box, recomputed after a truncation */
        memcpy(sc->tri_bb, bb, sizeof sc->tri_bb);
        sc->tri_bb_stale = 0;
        return RT_OK;
    }
    size_t w = 0; /* close the gaps, in order */
    for (size_t k = 0; k < sc->nintri; k++) {
        if (sc->prim[k].id == RT_CULLED)
            continue;
        sc->prim[w] = sc->prim[k];
        sc->prim[w].data = (uint32_t)w;
        sc->tri[w] = sc->tri[k];
        w++;
    }
    sc->ntri = sc->nprim = kept;
    return RT_OK;
}

/* The meshes' triangles after the plain ones (ntri_plain), in id order. They have no records
   of their own: a mesh's committed triangles share its record (rt_scene.cmesh). Degenerate
   ones were dropped when the mesh was added (rt_scene_mesh_end), which also made each mesh's
   box: without culling the commit only makes the meshes' records and ctri is the input's
   index triples. With culling the culled ones are left out and the box is of the kept ones:
   the kept index triples are a compacted copy (ctri_owned). In nt parts of consecutive
   triangles (threads): each part marks its culled triangles; a serial pass closes the gaps,
   so the result is the same for any nt. */
typedef struct rt_mesh_job {
    rt_scene *sc;
    const rt_build_options *o;
    uint8_t *cut;             /* per input mesh triangle: 1 culled */
    double bb[RT_PAR_MAX][6];
    size_t kept[RT_PAR_MAX];
} rt_mesh_job;

static void rt_commit_mesh_part(void *arg, int part, int nparts)
{
    rt_mesh_job *j = arg;
    rt_scene *sc = j->sc;
    const uint32_t (*in)[3] = (const uint32_t (*)[3])sc->mtri.p;
    const double *X = sc->mv_xyz.p;
    const uint32_t vm = sc->vmask;
    double *bb = j->bb[part];
    size_t lo, hi, kept = 0;
    rt_par_range(sc->nmtri, part, nparts, &lo, &hi);
    for (int i = 0; i < 3; i++) {
        bb[i] = INFINITY;
        bb[3 + i] = -INFINITY;
    }
    for (size_t t = lo; t < hi; t++) {
        const double *a = X + (in[t][0] & vm), *b = X + (in[t][1] & vm), *c = X + (in[t][2] & vm);
        double v[9];
        memcpy(v, a, sizeof v / 3);
        memcpy(v + 3, b, sizeof v / 3);
        memcpy(v + 6, c, sizeof v / 3);
        j->cut[t] = (uint8_t)rt_culled(j->o, v, 3, 0);
        if (j->cut[t])
            continue;
        rt_bbox_add(bb, a);
        rt_bbox_add(bb, b);
        rt_bbox_add(bb, c);
        kept++;
    }
    j->kept[part] = kept;
}

static int rt_commit_mesh(rt_scene *sc, const rt_build_options *o, double bb[6])
{
    sc->ntri_plain = sc->ntri;
    if (sc->nmtri == 0)
        return RT_OK;
    const int cull = o && o->ncull > 0;
    sc->cmesh = rt_calloc_array(sc->nmesh, sizeof *sc->cmesh);
    if (!sc->cmesh)
        return RT_ERR_NOMEM;
    for (size_t mi = 0; mi < sc->nmesh; mi++) {
        const rt_mesh *m = &sc->mesh[mi];
        const int rc = rt_prim_init(sc, &sc->cmesh[mi].rec, (int)m->id, m->front, m->back);
        if (rc != RT_OK)
            return rc;
        sc->cmesh[mi].rec.kind = RT_KIND_TRI;
        sc->cmesh[mi].end = sc->ntri_plain + m->t0 + m->nt;
    }
    uint32_t (*in)[3] = sc->mtri.p;
    sc->ctri = in;
    sc->ctri_owned = 0;
    if (!cull) {
        for (size_t mi = 0; mi < sc->nmesh; mi++) /* the boxes made when added */
            for (int i = 0; i < 3; i++) {
                bb[i] = fmin(bb[i], sc->mesh[mi].bb[i]);
                bb[3 + i] = fmax(bb[3 + i], sc->mesh[mi].bb[3 + i]);
            }
        sc->nprim += sc->nmtri;
        sc->ntri = sc->ntri_plain + sc->nmtri;
        return RT_OK;
    }
    rt_mesh_job *j = rt_alloc_array(1, sizeof *j);
    uint8_t *cut = rt_alloc_array(sc->nmtri, 1);
    if (!j || !cut) {
        free(j);
        free(cut);
        return RT_ERR_NOMEM;
    }
    j->sc = sc;
    j->o = o;
    j->cut = cut;
    int nt = rt_par_threads(o->threads);
    if ((size_t)nt > sc->nmtri / 16384 + 1)
        nt = (int)(sc->nmtri / 16384 + 1);
    rt_par_run(nt, rt_commit_mesh_part, j);
    size_t kept = 0;
    for (int k = 0; k < nt; k++) {
        kept += j->kept[k];
        for (int i = 0; i < 3; i++) {
            bb[i] = fmin(bb[i], j->bb[k][i]);
            bb[3 + i] = fmax(bb[3 + i], j->bb[k][3 + i]);
        }
    }
    free(j);
    if (kept < sc->nmtri) { /* close the gaps, in order, in a copy of the index triples */
        sc->ctri = rt_alloc_array(kept ? kept : 1, sizeof *sc->ctri);
        if (!sc->ctri) {
            free(cut);
            return RT_ERR_NOMEM;
        }
        sc->ctri_owned = 1;
        size_t w = 0, mi = 0;
        for (size_t t = 0; t < sc->nmtri; t++) {
            for (; t >= sc->mesh[mi].t0 + sc->mesh[mi].nt; mi++) /* meshes before t's */
                sc->cmesh[mi].end = sc->ntri_plain + w;
            if (!cut[t])
                memcpy(sc->ctri[w++], in[t], sizeof *sc->ctri);
        }
        for (; mi < sc->nmesh; mi++)
            sc->cmesh[mi].end = sc->ntri_plain + w;
    }
    free(cut);
    sc->nprim += kept;
    sc->ntri = sc->ntri_plain + kept;
    return RT_OK;
}

/* The committed arrays of every kind for the input (prim: the plain triangles' records grown
   in place unless culling makes a copy; mesh triangles have none). RT_OK or RT_ERR_NOMEM. */
static int rt_commit_alloc(rt_scene *sc, const rt_build_options *o)
{
    const size_t n = sc->nin;
    if (o && o->ncull > 0) {
        sc->prim = rt_alloc_array(sc->nintri + n + 1, sizeof *sc->prim);
        sc->prim_owned = 1;
    } else if (rt_big_grow(&sc->in_tri_prim, sc->nintri + n + 1, sizeof(rt_prim))) {
        sc->prim = in_tri_prims(sc); /* the other kinds' records follow the triangles' */
    }
    sc->quad = rt_alloc_array(n, sizeof *sc->quad);
    sc->poly = rt_alloc_array(n, sizeof *sc->poly);
    sc->cell = rt_alloc_array(n, sizeof *sc->cell);
    sc->uv = rt_alloc_array(sc->nxyz / 3 * 2, sizeof(double));
    sc->loops = rt_alloc_array(sc->nloopsin, sizeof(uint32_t));
    if (!sc->prim || !sc->quad || !sc->poly || !sc->cell || !sc->uv || !sc->loops)
        return RT_ERR_NOMEM;
    return RT_OK;
}

/* The cell array in (P, Q, R at v) as the next committed cell, its record *pr completed and
   its corners added to bb: 1, or 0 if it is degenerate (not kept). */
static int rt_commit_cell(rt_scene *sc, const rt_in_prim *in, const double *v, rt_prim *pr,
                          double bb[6])
{
    const double *P = v, *Q = v + 3, *R = v + 6;
    rt_cell *ce = &sc->cell[sc->ncell];
    double nn[3];
    for (int j = 0; j < 3; j++) {
        ce->p[j] = P[j];
        ce->a[j] = R[j] - P[j];
        ce->b[j] = Q[j] - R[j];
    }
    rt_cross(ce->a, ce->b, nn);
    double l = rt_len3(nn);
    if (!(l > 1e-12 * rt_len3(ce->a) * rt_len3(ce->b)) || !isfinite(l))
        return 0;
    for (int j = 0; j < 3; j++)
        ce->n[j] = nn[j] / l;
    ce->d = ce->n[0] * P[0] + ce->n[1] * P[1] + ce->n[2] * P[2];
    int k = rt_dominant_axis(ce->n);
    ce->ku = (k + 1) % 3;
    ce->kv = (k + 2) % 3;
    double m00 = ce->a[ce->ku], m01 = ce->b[ce->ku], m10 = ce->a[ce->kv], m11 = ce->b[ce->kv];
    double det = m00 * m11 - m01 * m10;
    if (!(fabs(det) > 0.0) || !isfinite(1.0 / det))
        return 0;
    ce->inv[0][0] = m11 / det;
    ce->inv[0][1] = -m01 / det;
    ce->inv[1][0] = -m10 / det;
    ce->inv[1][1] = m00 / det;
    ce->nx = in->nx;
    ce->ny = in->ny;
    ce->rgb0 = in->rgb0;
    pr->kind = RT_KIND_CELL;
    pr->data = (uint32_t)sc->ncell++;
    double S[3];
    for (int j = 0; j < 3; j++)
        S[j] = P[j] + Q[j] - R[j];
    rt_bbox_add(bb, P); rt_bbox_add(bb, Q); rt_bbox_add(bb, R); rt_bbox_add(bb, S);
    return 1;
}

/* The polygon in (nv vertices v, centroid c, extent ext) as the next committed planar convex
   quad or polygon, its record *pr completed and the traced vertices added to bb: 1, or 0 if
   it has no plane (not kept). */
static int rt_commit_poly(rt_scene *sc, const rt_in_prim *in, const double *v, size_t nv,
                          const double c[3], double ext, rt_prim *pr, double bb[6])
{
    const int *counts = sc->in_loops + in->loop0;
    double nrm[3];
    if (!rt_poly_normal(v, nv, counts, in->nloops, c, ext, nrm))
        return 0;
    if (in->nloops == 1 && nv == 4 && rt_quad_convex(v, nrm, c, ext)) {
        rt_quad *q = &sc->quad[sc->nquad];
        memcpy(q->v, v, 12 * sizeof(double));
        memcpy(q->n, nrm, sizeof q->n);
        q->vmax = 0.0; /* a maximum of magnitudes: exact in any order */
        for (int i = 0; i < 12; i++)
            q->vmax = fabs(v[i]) > q->vmax ? fabs(v[i]) : q->vmax;
        pr->kind = RT_KIND_QUAD;
        pr->data = (uint32_t)sc->nquad++;
        for (int i = 0; i < 4; i++)
            rt_bbox_add(bb, v + 3 * i);
        return 1;
    }
    rt_poly *po = &sc->poly[sc->npoly];
    memcpy(po->n, nrm, sizeof po->n);
    po->d = nrm[0] * c[0] + nrm[1] * c[1] + nrm[2] * c[2];
    int k = rt_dominant_axis(nrm);
    po->ku = (k + 1) % 3;
    po->kv = (k + 2) % 3;
    po->uv0 = (uint32_t)sc->nuv;
    po->loop0 = (uint32_t)sc->nloops;
    po->nloops = (uint32_t)in->nloops;
    for (int q = 0; q < in->nloops; q++)
        sc->loops[sc->nloops++] = (uint32_t)counts[q];
    for (size_t i = 0; i < nv; i++) {
        double pu = v[3 * i + po->ku], pv = v[3 * i + po->kv];
        sc->uv[2 * sc->nuv] = pu;
        sc->uv[2 * sc->nuv + 1] = pv;
        sc->nuv++;
        /* vertex projected onto the plane along axis k: the surface actually traced */
        double pp[3];
        pp[po->ku] = pu;
        pp[po->kv] = pv;
        pp[k] = (po->d - nrm[po->ku] * pu - nrm[po->kv] * pv) / nrm[k];
        if (fin3(pp))
            rt_bbox_add(bb, pp);
    }
    pr->kind = RT_KIND_POLY;
    pr->data = (uint32_t)sc->npoly++;
    return 1;
}

/* Stable partition of the stored records from first on (to the last, of primitive nprim -
   1): quads, then the rest, so that the prim index alone selects the fast paths (i < ntri: a
   triangle; i < ntri + nquad: quad[i - ntri]). RT_OK or RT_ERR_NOMEM. */
static int rt_quads_first(rt_scene *sc, size_t first)
{
    const size_t last = sc->nprim - (sc->ntri - sc->ntri_plain), nrest = last - first;
    rt_prim *tmp = rt_alloc_array(nrest, sizeof *tmp);
    if (!tmp)
        return RT_ERR_NOMEM;
    size_t qa = 0, qb = sc->nquad;
    for (size_t i = first; i < last; i++) {
        if (sc->prim[i].kind == RT_KIND_QUAD)
            tmp[qa++] = sc->prim[i];
        else
            tmp[qb++] = sc->prim[i];
    }
    if (nrest)
        memcpy(sc->prim + first, tmp, nrest * sizeof *tmp);
    free(tmp);
    return RT_OK;
}

static int rt_commit_prims(rt_scene *sc, const rt_build_options *o)
{
    const int cull = o && o->ncull > 0;
    int rc = rt_commit_alloc(sc, o);
    if (rc != RT_OK)
        return rc;
    double bb[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    rc = rt_commit_tris(sc, o, bb);
    if (rc == RT_OK)
        rc = rt_commit_mesh(sc, o, bb);
    if (rc != RT_OK)
        return rc;
    const size_t nmc = sc->ntri - sc->ntri_plain, first = sc->nprim - nmc; /* the other
                                                      kinds' records from here */
    for (size_t id = 0; id < sc->nin; id++) {
        const rt_in_prim *in = &sc->in[id];
        const double *v = sc->in_xyz + in->xyz0;
        size_t nv = 0;
        if (in->kind == RT_KIND_CELL)
            nv = 3;
        else
            for (int k = 0; k < in->nloops; k++)
                nv += (size_t)sc->in_loops[in->loop0 + (size_t)k];
        if (cull && rt_culled(o, v, nv, in->kind == RT_KIND_CELL))
            continue;
        double pb[6], c[3], ext;
        if (!rt_points_frame(v, nv, pb, c, &ext))
            continue;
        rt_prim *pr = &sc->prim[sc->nprim - nmc];
        memset(pr, 0, sizeof *pr);
        rc = rt_prim_init(sc, pr, in->id, in->front, in->back);
        if (rc != RT_OK)
            return rc;
        if (in->kind == RT_KIND_CELL ? rt_commit_cell(sc, in, v, pr, bb)
                                     : rt_commit_poly(sc, in, v, nv, c, ext, pr, bb))
            sc->nprim++;
    }
    rc = rt_quads_first(sc, first);
    if (rc != RT_OK)
        return rc;
    if (sc->nprim == 0)
        for (int i = 0; i < 6; i++)
            bb[i] = 0.0;
    memcpy(sc->bbox, bb, sizeof bb);
    double s = 0.0;
    for (int i = 0; i < 6; i++)
        s = fmax(s, fabs(bb[i]));
    sc->scale = s;
    return RT_OK;
}

static uint32_t rt_slab_of(const rt_poly *p, double v)
{
    double f = (v - p->vmin) * p->inv_h;
    if (!(f > 0.0))
        return 0;
    if (f >= (double)(p->nslab - 1))
        return p->nslab - 1;
    return (uint32_t)f;
}

/* number of (slab, edge) entries of polygon p with its current slab count */
static size_t rt_slab_entries(const rt_scene *sc, const rt_poly *p)
{
    const double *lu = sc->uv + 2 * (size_t)p->uv0;
    size_t n = 0;
    for (uint32_t l = 0; l < p->nloops; l++) {
        uint32_t m = sc->loops[p->loop0 + l];
        const double *q = lu + 2 * (size_t)(m - 1);
        for (uint32_t i = 0; i < m; i++) {
            const double *a = lu + 2 * (size_t)i;
            if (a[1] != q[1])
                n += 1 + rt_slab_of(p, fmax(a[1], q[1])) - rt_slab_of(p, fmin(a[1], q[1]));
            q = a;
        }
        lu += 2 * (size_t)m;
    }
    return n;
}

/* Edge-free disk of polygon p around the centre of its 2-D box: radius = distance to the
 * nearest edge less a relative margin far above rounding; the even-odd parity of its centre
 * (crossing rule of rt_isect_poly over all edges) holds in the whole disk. */
static void rt_poly_disk(const rt_scene *sc, rt_poly *p)
{
    const double cu = 0.5 * (p->umin + p->umax), cv = 0.5 * (p->vmin + p->vmax);
    const double *lu = sc->uv + 2 * (size_t)p->uv0;
    double dmin2 = INFINITY, dmax2 = 0.0;
    int in = 0;
    for (uint32_t l = 0; l < p->nloops; l++) {
        uint32_t m = sc->loops[p->loop0 + l];
        const double *q = lu + 2 * (size_t)(m - 1);
        for (uint32_t i = 0; i < m; i++) {
            const double *a = lu + 2 * (size_t)i;
            const double *lo = q[1] < a[1] ? q : a, *hi = q[1] < a[1] ? a : q;
            if (lo[1] != hi[1] && lo[1] <= cv && cv < hi[1] &&
                (cv - lo[1]) * (hi[0] - lo[0]) > (cu - lo[0]) * (hi[1] - lo[1]))
                in ^= 1;
            double ex = a[0] - q[0], ey = a[1] - q[1], l2 = ex * ex + ey * ey;
            double s = l2 > 0.0 ? ((cu - q[0]) * ex + (cv - q[1]) * ey) / l2 : 0.0;
            s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
            double dx = q[0] + s * ex - cu, dy = q[1] + s * ey - cv;
            double d2 = dx * dx + dy * dy;
            if (d2 < dmin2)
                dmin2 = d2;
            const double au = a[0] - cu, av = a[1] - cv;
            dmax2 = fmax(dmax2, au * au + av * av);
            q = a;
        }
        lu += 2 * (size_t)m;
    }
    double size = fmax(p->umax - p->umin, p->vmax - p->vmin);
    double margin = 1e-9 * (size + fabs(cu) + fabs(cv));
    double r = sqrt(dmin2) - margin;
    p->cu = cu;
    p->cv = cv;
    p->cin = in;
    p->rin2 = r > margin && isfinite(r) ? r * r * (1.0 - 1e-9) : -1.0;
    /* the polygon lies in the disk through its farthest vertex; a point beyond it by the same
       relative margin is far from every edge, so the crossing rule counts it outside */
    const double ro = sqrt(dmax2) + margin;
    p->rout2 = isfinite(ro) ? ro * ro * (1.0 + 1e-9) : INFINITY;
}

/* Per polygon: 2-D bounds and horizontal slabs, each listing the edges whose v range meets
 * it (same slab function for edges and query points, so the even-odd count is unchanged). */
/* Polygon k's 2-D bounds, edge-free disk and slab count (its grid instead, a big polygon whose
   slabs stay crowded): *ns slabs and *entries (slab, edge) entries. RT_OK or RT_ERR_NOMEM. */
static int rt_poly_plan(rt_scene *sc, size_t k, size_t *ns_out, size_t *entries_out)
{
    rt_poly *p = &sc->poly[k];
    const double *uv = sc->uv + 2 * (size_t)p->uv0;
    size_t nv = 0;
    for (uint32_t l = 0; l < p->nloops; l++)
        nv += sc->loops[p->loop0 + l];
    p->umin = p->vmin = INFINITY;
    p->umax = p->vmax = -INFINITY;
    for (size_t i = 0; i < nv; i++) {
        p->umin = fmin(p->umin, uv[2 * i]);
        p->umax = fmax(p->umax, uv[2 * i]);
        p->vmin = fmin(p->vmin, uv[2 * i + 1]);
        p->vmax = fmax(p->vmax, uv[2 * i + 1]);
    }
    const double ub[4] = {p->umin, p->umax, p->vmin, p->vmax};
    p->uvmax = 0.0; /* a maximum of magnitudes: exact in any order */
    for (int i = 0; i < 4; i++)
        p->uvmax = fabs(ub[i]) > p->uvmax ? fabs(ub[i]) : p->uvmax;
    rt_poly_disk(sc, p);
    /* one slab per vertex above 8: fewer edges per slab in the crossing loop (SPD gears'
       144-gons; measured in docs/bench/rt_tuning.md) */
    size_t ns = nv <= 8 ? 1 : nv;
    if (ns > 1024)
        ns = 1024;
    double h = p->vmax - p->vmin;
    if (!(h > 0.0) || !isfinite((double)ns / h))
        ns = 1;
    size_t entries;
    /* long edges repeat in many slabs: keep the lists within 8 entries per edge */
    for (;;) {
        p->nslab = (uint32_t)ns;
        p->inv_h = ns > 1 ? (double)ns / h : 0.0;
        entries = rt_slab_entries(sc, p);
        if (ns == 1 || entries <= 8 * nv + 64)
            break;
        ns /= 2;
    }
    /* a big polygon whose slabs stay crowded (long edges, many turns): its grid */
    p->pgrid = 0;
    if (nv >= RT_PGRID_MIN_EDGES && entries > 64 * ns) {
        if (!sc->pgrid)
            sc->pgrid = rt_calloc_array(sc->npoly, sizeof *sc->pgrid);
        if (!sc->pgrid)
            return RT_ERR_NOMEM;
        if (rt_pgrid_build(&sc->pgrid[k], sc->uv + 2 * (size_t)p->uv0,
                           sc->loops + p->loop0, p->nloops, p->umin, p->umax, p->vmin,
                           p->vmax) == 0) {
            p->pgrid = (uint32_t)k + 1;
            ns = 1;
            p->nslab = 1;
            p->inv_h = 0.0;
            entries = 0;
        }
    }
    *ns_out = ns;
    *entries_out = entries;
    return RT_OK;
}

/* Polygon p's edges into its slabs' lists (none for a polygon with a grid): a counting pass
   (slab_off from *base on), then the edges stored upwards at cursor (one per slab). */
static void rt_poly_fill(rt_scene *sc, const rt_poly *p, size_t *base, size_t *cursor)
{
    size_t *so = sc->slab_off + p->slab0;
    for (uint32_t s = 0; s <= p->nslab; s++)
        so[s] = 0;
    for (int pass = 0; pass < 2; pass++) {
        const double *lu = sc->uv + 2 * (size_t)p->uv0;
        for (uint32_t l = 0; l < (p->pgrid ? 0 : p->nloops); l++) {
            uint32_t m = sc->loops[p->loop0 + l];
            const double *q = lu + 2 * (size_t)(m - 1);
            for (uint32_t i = 0; i < m; i++) {
                const double *a = lu + 2 * (size_t)i;
                if (a[1] != q[1]) { /* horizontal edges never cross */
                    uint32_t s0 = rt_slab_of(p, fmin(a[1], q[1]));
                    uint32_t s1 = rt_slab_of(p, fmax(a[1], q[1]));
                    for (uint32_t s = s0; s <= s1; s++) {
                        if (pass == 0) {
                            so[s + 1]++;
                        } else {
                            /* stored upwards: (u0, v0, v1, u1 - u0, v1 - v0) with v0 < v1,
                               the differences the crossing test of rt_isect_poly takes */
                            const double *lo = q[1] < a[1] ? q : a, *hi = q[1] < a[1] ? a : q;
                            double *e = sc->edges + RT_EDGE_STRIDE * cursor[s]++;
                            e[0] = lo[0]; e[1] = lo[1]; e[2] = hi[1];
                            e[3] = hi[0] - lo[0]; e[4] = hi[1] - lo[1];
                        }
                    }
                }
                q = a;
            }
            lu += 2 * (size_t)m;
        }
        if (pass == 0) {
            so[0] = *base;
            for (uint32_t s = 0; s < p->nslab; s++) {
                so[s + 1] += so[s];
                cursor[s] = so[s];
            }
            *base = so[p->nslab];
        }
    }
}

static int rt_poly_slabs(rt_scene *sc)
{
    size_t nslab_tot = 0, nedge_tot = 0;
    for (size_t k = 0; k < sc->npoly; k++) {
        size_t ns, entries;
        if (rt_poly_plan(sc, k, &ns, &entries) != RT_OK)
            return RT_ERR_NOMEM;
        sc->poly[k].slab0 = nslab_tot;
        nslab_tot += ns + 1;
        nedge_tot += entries;
    }
    sc->slab_off = rt_alloc_array(nslab_tot, sizeof(size_t));
    sc->edges = rt_alloc_array(nedge_tot, RT_EDGE_STRIDE * sizeof(double));
    if (!sc->slab_off || !sc->edges)
        return RT_ERR_NOMEM;
    size_t cursor[1024];
    size_t base = 0;
    for (size_t k = 0; k < sc->npoly; k++)
        rt_poly_fill(sc, &sc->poly[k], &base, cursor);
    sc->nslab_off = nslab_tot;
    sc->nedges = nedge_tot;
    return RT_OK;
}

/* Per committed primitive the index of its vertex data record (sc->prim_vd; RT_NO_VD: none;
   rt_smooth.c adds the records); RT_ERR_NOMEM. */
static int rt_vd_commit(rt_scene *sc)
{
    free(sc->prim_vd);
    sc->prim_vd = NULL;
    if (sc->nvd == 0 || sc->nprim == 0)
        return RT_OK;
    sc->prim_vd = rt_alloc_array(sc->nprim, sizeof *sc->prim_vd);
    if (!sc->prim_vd)
        return RT_ERR_NOMEM;
    for (size_t i = 0; i < sc->nprim; i++) {
        uint32_t id = (uint32_t)rt_prim_id(sc, i);
        size_t lo = 0, hi = sc->nvd; /* records are in ascending id order */
        while (lo < hi) {
            size_t mid = lo + (hi - lo) / 2;
            if (sc->vd[mid].id < id)
                lo = mid + 1;
            else
                hi = mid;
        }
        sc->prim_vd[i] = lo < sc->nvd && sc->vd[lo].id == id ? (uint32_t)lo : RT_NO_VD;
    }
    return RT_OK;
}

int rt_scene_commit(rt_scene *sc, const rt_build_options *opts)
{
    if (!sc)
        return RT_ERR_ARG;
    double t0 = rt_now();
    const int progress = opts && opts->progress;
    if (progress) { /* the name when the phase starts, its time when it ends */
        fprintf(stderr, "rt: set-up: grid of %zu primitives ...", sc->nids);
        fflush(stderr);
    }
    rt_scene_uncommit(sc);
    int rc = rt_commit_prims(sc, opts);
    if (rc == RT_OK)
        rc = rt_poly_slabs(sc);
    if (rc == RT_OK)
        rc = rt_grid_build(sc, opts);
    if (rc == RT_OK)
        rc = rt_vd_commit(sc);
    if (rc != RT_OK) {
        if (progress)
            fprintf(stderr, " failed\n");
        rt_scene_uncommit(sc);
        return rc;
    }
    const size_t nmt = sc->ntri - sc->ntri_plain, mvb = 3 * sizeof(double) +
        (sc->mv_n.p ? 3 * sizeof(float) : 0) + (sc->mv_c.p ? 3 * sizeof(float) : 0);
    /* the records: the plain triangles' and, per mesh, one for its triangles */
    const size_t cmesh_bytes = nmt ? sc->nmesh * sizeof *sc->cmesh : 0;
    sc->tri_bytes = sc->ntri_plain * (sizeof *sc->prim + sizeof *sc->tri) + cmesh_bytes +
                    nmt * 3 * sizeof(uint32_t) + sc->nmv * mvb;
    /* the second level's cell offsets: 2 B per cell and one per sub-grid, or 4 B per cell
       and one (rt_internal.h) */
    const rt_grid *gr = &sc->grid;
    const size_t soff_bytes = gr->soff16 ? (gr->nsubcells + gr->nsubs) * sizeof(uint16_t)
                              : gr->soff ? (gr->nsubcells + 1) * sizeof(uint32_t)
                                         : 0;
    const size_t srefs_bytes = gr->sref16 ? gr->nsrefs * sizeof(uint16_t) +
                                                gr->nsloc * sizeof(uint32_t)
                                          : gr->nsrefs * sizeof(uint32_t);
    sc->grid_bytes = sc->use_grid ? (sc->grid.ncells + 1 + sc->grid.nrefs) *
                                            sizeof(uint32_t) + srefs_bytes + soff_bytes +
                                        sc->grid.nsubs * sizeof(rt_subgrid) +
                                        (sc->grid.sub ? sc->grid.ncells * sizeof(int32_t) : 0) +
                                        (sc->grid.odist ? 8 * sc->grid.ncells * sizeof(uint8_t) : 0) +
                                        rt_leaves_bytes(&sc->grid) +
                                        (sc->grid.subplane ? sc->grid.nsubs * sizeof(uint32_t) +
                                                                 sc->grid.nsplanes * sizeof(rt_subplane)
                                                           : 0)
                                  : 0;
    sc->memory_bytes = sizeof *sc + (sc->nprim - nmt) * sizeof *sc->prim + cmesh_bytes +
                       sc->ntri_plain * sizeof *sc->tri + nmt * 3 * sizeof(uint32_t) +
                       sc->nmv * mvb +
                       sc->nquad * sizeof *sc->quad +
                       sc->npoly * sizeof *sc->poly + sc->ncell * sizeof *sc->cell +
                       sc->nuv * 2 * sizeof(double) + sc->nloops * sizeof(uint32_t) +
                       sc->nslab_off * sizeof(size_t) + sc->nedges * RT_EDGE_STRIDE * sizeof(double) +
                       sc->nrgb * sizeof(float) + sc->nspair * sizeof *sc->spair +
                       sc->spair_hcap * sizeof *sc->spair_hash +
                       (sc->prim_vd ? sc->nprim * sizeof(uint32_t) + sc->nvd * sizeof *sc->vd +
                                          sc->nvdv * (3 * sizeof(double) + 6 * sizeof(float))
                                    : 0) +
                       sc->grid_bytes;
    for (size_t k = 0; sc->pgrid && k < sc->npoly; k++)
        sc->memory_bytes += rt_pgrid_bytes(&sc->pgrid[k]);
    sc->build_seconds = rt_now() - t0;
    sc->committed = 1;
    if (progress)
        fprintf(stderr, " %.2f s\n", sc->build_seconds);
    return RT_OK;
}

void rt_cell_color(const rt_scene *sc, const rt_cell *c, const double p[3], double rgb[3])
{
    double qu = p[c->ku] - c->p[c->ku], qv = p[c->kv] - c->p[c->kv];
    double s = c->inv[0][0] * qu + c->inv[0][1] * qv;
    double t = c->inv[1][0] * qu + c->inv[1][1] * qv;
    double fs = s * c->nx, ft = t * c->ny;
    int i = fs >= 0.0 ? (fs < c->nx ? (int)fs : c->nx - 1) : 0;
    int j = ft >= 0.0 ? (ft < c->ny ? (int)ft : c->ny - 1) : 0;
    const float *col = sc->in_rgb + c->rgb0 + 3 * ((size_t)j * (size_t)c->nx + (size_t)i);
    for (int k = 0; k < 3; k++)
        rgb[k] = col[k];
}
