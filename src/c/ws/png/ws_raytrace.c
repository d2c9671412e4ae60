/* SPDX-License-Identifier: MIT */
/*
 * ws_raytrace.c -- HLHSR mode GHLHSR_RAYTRACE (paper sections 3 and 5) for the PNG
 * workstation. Area primitives (FILL AREA, FILL AREA SET, CELL ARRAY) are not rasterized but
 * recorded in VRC3 (the NDC3 points after the view orientation matrix of their view); when
 * the frame is written they are traced with gksrt, view by view in ascending view index
 * order: the camera comes from the view's mapping matrix, the display volume is the view clip
 * volume (where the indicators are on) intersected with the workstation window, and the
 * traced pixels are composed over the framebuffer by their sample coverage.
 * POLYLINEs, POLYMARKERs and TEXT are annotations, rasterized as in mode 0 and ignored by the
 * tracer (a traced surface covers them). Lights the tracer rejects (a spot light of spread 0,
 * a zero direction) are left out. Documentation: docs/RAYTRACING.md.
 */
#include "ws_raytrace.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include "ws_mpi.h"
#ifdef GKS_HAVE_MPI
#include "gks_par.h"
#include <stdio.h>
#endif
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { REC_POLYGON, REC_CELLS };

typedef struct rt_rec {
    int kind;                /* REC_* */
    int n_loops, loop_off;   /* polygon: loop counts at loops[loop_off..] */
    int n_points, pt_off;    /* xyz at xyz[3*pt_off..]; cells: P, Q, R */
    int nx, ny;              /* cells: colours at rgb[3*rgb_off..] */
    size_t rgb_off;
    Grgb colour;             /* polygon diffuse colour */
    Garea_props props[2];
    int refl_eq[2];
    uint64_t light_mask;
    int view_ind;
} rt_rec;

struct ws_rt {
    rt_rec *recs;
    size_t n_recs, cap_recs;
    int *loops;
    size_t n_loops, cap_loops;
    double *xyz;             /* 3 per point, VRC3 */
    size_t n_pts, cap_pts;   /* counted in doubles */
    float *rgb;              /* cell colours */
    size_t n_rgb, cap_rgb;   /* counted in floats */
    rt_render_options opts;  /* set by the ESCAPEs */
    rt_stats last;           /* of the last traced picture */
    int share_tiles;         /* the next frames' tiles are shared by the MPI ranks */
};

/* Sample rays per coverage batch (bounds the temporary memory of ws_rt_render). */
#define COVER_BATCH 16384

ws_rt *ws_rt_new(void)
{
    ws_rt *r = gks_calloc_array(1, sizeof(ws_rt));
    if (r)
        rt_render_options_default(&r->opts);
    return r;
}

void ws_rt_free(ws_rt *r)
{
    if (!r)
        return;
    gks_free(r->recs);
    gks_free(r->loops);
    gks_free(r->xyz);
    gks_free(r->rgb);
    gks_free(r);
}

void ws_rt_reset(ws_rt *r) { r->n_recs = r->n_loops = r->n_pts = r->n_rgb = 0; }

int ws_rt_count(const ws_rt *r) { return (int)r->n_recs; }

void ws_rt_set_clip_secondary(ws_rt *r, int on) { r->opts.clip_secondary = on != 0; }

void ws_rt_options(const ws_rt *r, rt_render_options *o) { *o = r->opts; }

void ws_rt_set_share_tiles(ws_rt *r, int on) { r->share_tiles = on != 0; }

void ws_rt_last_stats(const ws_rt *r, rt_stats *st) { *st = r->last; }

/* Makes room for need more elements of size sz in *arr (count n, capacity *cap). */
static int reserve(void **arr, size_t n, size_t need, size_t *cap, size_t sz)
{
    if (need > ((size_t)INT32_MAX) - n)
        return 300;
    if (n + need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 16;
    while (c < n + need)
        c *= 2;
    void *p = gks_realloc_array(*arr, c, sz);
    if (!p)
        return 300;
    *arr = p;
    *cap = c;
    return 0;
}

static int clamp_view(int v) { return v >= 0 && v <= GKS_MAX_VIEW_IND ? v : 0; }

/* Affine (homogeneous, divided when w != 1) point and linear direction through m. */
static void xf_point(const Gmatrix3 m, double x, double y, double z, double o[3])
{
    double w = m[3][0] * x + m[3][1] * y + m[3][2] * z + m[3][3];
    if (w == 0 || !isfinite(w))
        w = 1;
    for (int i = 0; i < 3; i++)
        o[i] = (m[i][0] * x + m[i][1] * y + m[i][2] * z + m[i][3]) / w;
}

static void xf_dir(const Gmatrix3 m, double x, double y, double z, double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = m[i][0] * x + m[i][1] * y + m[i][2] * z;
}

/* The attributes every record of prim shares. */
static rt_rec rec_base(const gks_prim *prim, int kind)
{
    rt_rec rec = { .kind = kind, .colour = prim->colour,
                   .refl_eq = { prim->refl_eq[0], prim->refl_eq[1] },
                   .light_mask = prim->light_mask, .view_ind = clamp_view(prim->view_ind) };
    rec.props[0] = prim->area_props[0];
    rec.props[1] = prim->area_props[1];
    return rec;
}

/* Appends a polygon of n_loops loops (counts >= 3) with NDC3 points xyz (3 doubles each). */
static int push_polygon(ws_rt *r, const gks_ws *ws, rt_rec rec, int n_loops, const int *counts,
                        size_t n_pts, const double *xyz)
{
    if (reserve((void **)&r->recs, r->n_recs, 1, &r->cap_recs, sizeof *r->recs) ||
        reserve((void **)&r->loops, r->n_loops, (size_t)n_loops, &r->cap_loops,
                sizeof *r->loops) ||
        reserve((void **)&r->xyz, r->n_pts, 3 * n_pts, &r->cap_pts, sizeof *r->xyz))
        return 300;
    const Gview_rep3 *v = &ws->views[rec.view_ind];
    rec.kind = REC_POLYGON;
    rec.n_loops = n_loops;
    rec.loop_off = (int)r->n_loops;
    rec.n_points = (int)n_pts;
    rec.pt_off = (int)(r->n_pts / 3);
    memcpy(r->loops + r->n_loops, counts, (size_t)n_loops * sizeof(int));
    for (size_t i = 0; i < n_pts; i++)
        xf_point(v->ori_matrix, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2],
                 r->xyz + r->n_pts + 3 * i);
    r->recs[r->n_recs++] = rec;
    r->n_loops += (size_t)n_loops;
    r->n_pts += 3 * n_pts;
    return 0;
}

/* Appends a cell array P, Q, R (NDC3) of nx x ny colours, row j at cells[j*stride]. */
static int push_cells(ws_rt *r, const gks_ws *ws, rt_rec rec, const double P[3],
                      const double Q[3], const double R[3], int nx, int ny, const Grgb *cells,
                      size_t stride)
{
    size_t nc = (size_t)nx * (size_t)ny;
    if (nc > (size_t)INT32_MAX / 3)
        return 300;
    if (reserve((void **)&r->recs, r->n_recs, 1, &r->cap_recs, sizeof *r->recs) ||
        reserve((void **)&r->xyz, r->n_pts, 9, &r->cap_pts, sizeof *r->xyz) ||
        reserve((void **)&r->rgb, r->n_rgb, 3 * nc, &r->cap_rgb, sizeof *r->rgb))
        return 300;
    const Gview_rep3 *v = &ws->views[rec.view_ind];
    rec.kind = REC_CELLS;
    rec.n_points = 3;
    rec.pt_off = (int)(r->n_pts / 3);
    rec.nx = nx;
    rec.ny = ny;
    rec.rgb_off = r->n_rgb / 3;
    const double *c[3] = { P, Q, R };
    for (int k = 0; k < 3; k++)
        xf_point(v->ori_matrix, c[k][0], c[k][1], c[k][2], r->xyz + r->n_pts + 3 * (size_t)k);
    float *d = r->rgb + r->n_rgb;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const Grgb *s = &cells[(size_t)j * stride + (size_t)i];
            /* non-finite colours cannot come from the colour table; 0 keeps the tracer safe */
            d[0] = isfinite(s->red) ? (float)s->red : 0.0f;
            d[1] = isfinite(s->green) ? (float)s->green : 0.0f;
            d[2] = isfinite(s->blue) ? (float)s->blue : 0.0f;
            d += 3;
        }
    r->recs[r->n_recs++] = rec;
    r->n_pts += 9;
    r->n_rgb += 3 * nc;
    return 0;
}

static int record_fill_area(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    if (prim->n_points < 3 || prim->n_loops < 1 || !prim->loop_counts || !prim->pts)
        return 0;
    size_t total = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        if (prim->loop_counts[k] < 0)
            return 0;
        total += (size_t)prim->loop_counts[k];
    }
    if (total != (size_t)prim->n_points)
        return 0; /* inconsistent record: nothing traceable */
    int *counts = gks_alloc_array((size_t)prim->n_loops, sizeof *counts);
    double *xyz = gks_alloc_array((size_t)prim->n_points, 3 * sizeof *xyz);
    if (!counts || !xyz) {
        gks_free(counts);
        gks_free(xyz);
        return 300;
    }
    /* Loops of fewer than 3 points enclose nothing (even-odd rule): left out. */
    int nl = 0;
    size_t np = 0, src = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        if (m >= 3) {
            counts[nl++] = (int)m;
            for (size_t i = 0; i < m; i++) {
                const Gpoint3 *p = &prim->pts[src + i];
                xyz[3 * np] = p->x;
                xyz[3 * np + 1] = p->y;
                xyz[3 * np + 2] = p->z;
                np++;
            }
        }
        src += m;
    }
    int err = nl ? push_polygon(r, ws, rec_base(prim, REC_POLYGON), nl, counts, np, xyz) : 0;
    gks_free(counts);
    gks_free(xyz);
    return err;
}

static int inside_box(const double p[3], const double b[6])
{
    return p[0] >= b[0] && p[0] <= b[1] && p[1] >= b[2] && p[1] <= b[3] && p[2] >= b[4] &&
           p[2] <= b[5];
}

/* Corner (i, j) of the cell grid: P + (i/nx)(R - P) + (j/ny)(Q - R). */
static void cell_corner(const double P[3], const double U[3], const double V[3], int nx, int ny,
                        int i, int j, double o[3])
{
    double a = (double)i / nx, b = (double)j / ny;
    for (int k = 0; k < 3; k++)
        o[k] = P[k] + a * U[k] + b * V[k];
}

/* Sutherland-Hodgman clip of a convex polygon (n <= 4 points, room for 10) by box b. */
static int clip_to_box(double (*p)[3], int n, const double b[6])
{
    double tmp[10][3];
    for (int f = 0; f < 6 && n > 0; f++) {
        int ax = f / 2, hi = f % 2;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const double *a = p[i], *c = p[(i + 1) % n];
            double da = hi ? b[f] - a[ax] : a[ax] - b[f];
            double dc = hi ? b[f] - c[ax] : c[ax] - b[f];
            if (da >= 0)
                memcpy(tmp[m++], a, sizeof tmp[0]);
            if ((da >= 0) != (dc >= 0)) {
                double t = da / (da - dc);
                for (int k = 0; k < 3; k++)
                    tmp[m][k] = a[k] + t * (c[k] - a[k]);
                m++;
            }
        }
        n = m;
        memcpy(p, tmp, (size_t)n * sizeof tmp[0]);
    }
    return n;
}

/* A CELL ARRAY clipped by its NDC3 clip box: per row, the run of cells inside the box as a
 * one-row cell array, the cells crossing the boundary as clipped polygons of their colour. */
static int record_cells_clipped(ws_rt *r, const gks_ws *ws, const gks_prim *prim,
                                const double P[3], const double U[3], const double V[3])
{
    const double *b = prim->clip_box;
    int nx = prim->cell_nx, ny = prim->cell_ny;
    rt_rec base = rec_base(prim, REC_CELLS);
    for (int j = 0; j < ny; j++) {
        int run = -1;
        for (int i = 0; i <= nx; i++) {
            int inside = 0;
            double c[4][3];
            if (i < nx) {
                cell_corner(P, U, V, nx, ny, i, j, c[0]);
                cell_corner(P, U, V, nx, ny, i + 1, j, c[1]);
                cell_corner(P, U, V, nx, ny, i + 1, j + 1, c[2]);
                cell_corner(P, U, V, nx, ny, i, j + 1, c[3]);
                inside = inside_box(c[0], b) && inside_box(c[1], b) && inside_box(c[2], b) &&
                         inside_box(c[3], b);
            }
            if (inside && run < 0)
                run = i;
            if (!inside && run >= 0) { /* flush the run [run, i) */
                double p0[3], r0[3], q0[3];
                cell_corner(P, U, V, nx, ny, run, j, p0);
                cell_corner(P, U, V, nx, ny, i, j, r0);
                cell_corner(P, U, V, nx, ny, i, j + 1, q0);
                int e = push_cells(r, ws, base, p0, q0, r0, i - run, 1,
                                   prim->cells + (size_t)j * (size_t)nx + (size_t)run,
                                   (size_t)nx);
                if (e)
                    return e;
                run = -1;
            }
            if (inside || i == nx)
                continue;
            double poly[10][3];
            memcpy(poly, c, sizeof c);
            int n = clip_to_box(poly, 4, b);
            if (n < 3)
                continue;
            rt_rec rec = base;
            rec.colour = prim->cells[(size_t)j * (size_t)nx + (size_t)i];
            int e = push_polygon(r, ws, rec, 1, &n, (size_t)n, &poly[0][0]);
            if (e)
                return e;
        }
    }
    return 0;
}

static int record_cells(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    int nx = prim->cell_nx, ny = prim->cell_ny;
    if (nx < 1 || ny < 1 || !prim->cells)
        return 0;
    if ((size_t)nx > (size_t)INT32_MAX / 3 / (size_t)ny)
        return 300; /* more colours than the recording can index */
    double P[3] = { prim->cell_p.x, prim->cell_p.y, prim->cell_p.z };
    double Q[3] = { prim->cell_q.x, prim->cell_q.y, prim->cell_q.z };
    double R[3] = { prim->cell_r.x, prim->cell_r.y, prim->cell_r.z };
    for (int k = 0; k < 3; k++)
        if (!isfinite(P[k]) || !isfinite(Q[k]) || !isfinite(R[k]))
            return 0;
    double S[3], U[3], V[3];
    for (int k = 0; k < 3; k++) {
        S[k] = P[k] + Q[k] - R[k];
        U[k] = R[k] - P[k];
        V[k] = Q[k] - R[k];
    }
    const double *b = prim->clip_box;
    if (!prim->clip ||
        (inside_box(P, b) && inside_box(Q, b) && inside_box(R, b) && inside_box(S, b)))
        return push_cells(r, ws, rec_base(prim, REC_CELLS), P, Q, R, nx, ny, prim->cells,
                          (size_t)nx);
    if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
        return 0; /* empty or NaN clip box: nothing visible */
    return record_cells_clipped(r, ws, prim, P, U, V);
}

int ws_rt_record(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    size_t n_recs = r->n_recs, n_loops = r->n_loops, n_pts = r->n_pts, n_rgb = r->n_rgb;
    int err = 0;
    if (prim->kind == GKS_PRIM_FILL_AREA)
        err = record_fill_area(r, ws, prim);
    else if (prim->kind == GKS_PRIM_CELL_ARRAY)
        err = record_cells(r, ws, prim);
    if (err) { /* as if the call never happened */
        r->n_recs = n_recs;
        r->n_loops = n_loops;
        r->n_pts = n_pts;
        r->n_rgb = n_rgb;
    }
    return err;
}

static void surface_of(const rt_rec *rec, int side, uint64_t mask, rt_surface *s)
{
    const Garea_props *p = &rec->props[side];
    rt_surface_default(s);
    s->refl_eq = rec->refl_eq[side] - 1;
    if (s->refl_eq < RT_REFL_NONE || s->refl_eq > RT_REFL_SPECULAR)
        s->refl_eq = RT_REFL_NONE;
    s->ka = p->ambient_coef;
    s->kd = p->diffuse_coef;
    s->ks = p->specular_coef;
    s->diffuse[0] = rec->colour.red;
    s->diffuse[1] = rec->colour.green;
    s->diffuse[2] = rec->colour.blue;
    s->specular[0] = p->specular_colr.red;
    s->specular[1] = p->specular_colr.green;
    s->specular[2] = p->specular_colr.blue;
    s->spec_exp = p->specular_exp;
    s->transparency = p->transpar_coef;
    s->refr_index = p->refr_index;
    s->light_mask = mask;
}

static void light_of(const Glight_src_rep *g, const Gmatrix3 ori, rt_light *l)
{
    memset(l, 0, sizeof *l);
    l->type = g->type;
    l->color[0] = g->colr.red;
    l->color[1] = g->colr.green;
    l->color[2] = g->colr.blue;
    xf_point(ori, g->pos.x, g->pos.y, g->pos.z, l->position);
    xf_dir(ori, g->dir.delta_x, g->dir.delta_y, g->dir.delta_z, l->direction);
    l->c1 = g->atten[0];
    l->c2 = g->atten[1];
    l->concentration = g->conc_exp;
    l->spread = g->spread_angle;
}

/* The surfaces of the previous record, reused while records share their attributes
 * (consecutive areas of one attribute setting: one surface pair, not one per area). */
typedef struct surf_cache {
    const rt_rec *rec;
    uint64_t mask;
    int f, b;
} surf_cache;

static int same_surfaces(const rt_rec *a, const rt_rec *b)
{
    return a->colour.red == b->colour.red && a->colour.green == b->colour.green &&
           a->colour.blue == b->colour.blue && a->refl_eq[0] == b->refl_eq[0] &&
           a->refl_eq[1] == b->refl_eq[1] &&
           memcmp(&a->props[0], &b->props[0], sizeof a->props) == 0;
}

/* The GKS error for a tracer result: storage (RT_ERR_NOMEM, RT_ERR_LIMIT: an
 * implementation limit on items) is 300; data the tracer cannot use (RT_ERR_SINGULAR,
 * RT_ERR_ARG, RT_ERR_STATE) is 308, arithmetic error. */
static int gks_err_of_rt(int rc)
{
    if (rc >= 0)
        return 0;
    return rc == RT_ERR_NOMEM || rc == RT_ERR_LIMIT ? 300 : 308;
}

/* Adds record rec (of view vi, lights mask in the scene's numbering) to sc. Returns 0 or 300. */
static int add_rec(rt_scene *sc, const ws_rt *r, const rt_rec *rec, uint64_t mask,
                   surf_cache *cache)
{
    int f = cache->f, b = cache->b;
    if (!cache->rec || cache->mask != mask || !same_surfaces(cache->rec, rec)) {
        rt_surface s;
        surface_of(rec, 0, mask, &s);
        f = rt_scene_add_surface(sc, &s);
        surface_of(rec, 1, mask, &s);
        b = rt_scene_add_surface(sc, &s);
        if (f < 0 || b < 0) /* values are checked at SET: only storage fails here */
            return gks_err_of_rt(f < 0 ? f : b);
        *cache = (surf_cache){ rec, mask, f, b };
    }
    const double *xyz = r->xyz + 3 * (size_t)rec->pt_off;
    int id = rec->kind == REC_CELLS
                 ? rt_scene_add_cell_array(sc, xyz, xyz + 3, xyz + 6, rec->nx, rec->ny,
                                           r->rgb + 3 * rec->rgb_off, f, b)
                 : rt_scene_add_polygon(sc, rec->n_loops, r->loops + rec->loop_off, xyz, f, b);
    return gks_err_of_rt(id);
}

/* 1 if every vertex of rec lies outside one clipping plane of cam (beyond the tracer's
 * clip tolerance): with clipped secondary rays no ray can reach it. */
static int outside_volume(const ws_rt *r, const rt_rec *rec, const rt_camera *cam)
{
    const double *xyz = r->xyz + 3 * (size_t)rec->pt_off;
    double s[3];
    int n = rec->kind == REC_CELLS ? 4 : rec->n_points;
    double eps = 2e-9 * cam->scale;
    for (int f = 0; f < 6; f++) {
        const double *pl = cam->plane[f];
        int out = 1;
        for (int i = 0; i < n && out; i++) {
            const double *v = xyz + 3 * (size_t)i;
            if (i == 3 && rec->kind == REC_CELLS) { /* the fourth corner P + Q - R */
                for (int k = 0; k < 3; k++)
                    s[k] = xyz[k] + xyz[3 + k] - xyz[6 + k];
                v = s;
            }
            out = pl[0] * v[0] + pl[1] * v[1] + pl[2] * v[2] + pl[3] < -eps;
        }
        if (out)
            return 1;
    }
    return 0;
}

/* Builds the scene of view vi; with cull (clipped secondary rays) primitives entirely
 * outside cam's display volume are left out. Returns 0, 300; *out NULL when nothing is
 * traceable. */
static int build_scene(const ws_rt *r, const gks_ws *ws, int vi, const rt_camera *cull,
                       rt_scene **out)
{
    *out = NULL;
    rt_scene *sc = rt_scene_new();
    if (!sc)
        return 300;
    const Gmatrix3 *ori = &ws->views[vi].ori_matrix;
    uint64_t used = 0;
    for (size_t k = 0; k < r->n_recs; k++)
        if (r->recs[k].view_ind == vi)
            used |= r->recs[k].light_mask;
    int bit[GKS_MAX_LIGHT_IND];
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++) {
        bit[i] = -1;
        if (!((used >> i) & 1) || !ws->light_defined[i])
            continue;
        rt_light l;
        light_of(&ws->lights[i], *ori, &l);
        int id = rt_scene_add_light(sc, &l);
        if (id == RT_ERR_NOMEM) {
            rt_scene_free(sc);
            return 300;
        }
        bit[i] = id; /* < 0: rejected by the tracer, left out */
    }
    surf_cache cache = { NULL, 0, -1, -1 };
    for (size_t k = 0; k < r->n_recs; k++) {
        const rt_rec *rec = &r->recs[k];
        if (rec->view_ind != vi || (cull && outside_volume(r, rec, cull)))
            continue;
        uint64_t mask = 0;
        for (int i = 0; i < GKS_MAX_LIGHT_IND; i++)
            if (((rec->light_mask >> i) & 1) && bit[i] >= 0)
                mask |= (uint64_t)1 << bit[i];
        int err = add_rec(sc, r, rec, mask, &cache);
        if (err) {
            rt_scene_free(sc);
            return err;
        }
    }
    int rc = rt_scene_commit(sc, NULL);
    if (rc != RT_OK) {
        rt_scene_free(sc);
        return gks_err_of_rt(rc);
    }
    *out = sc;
    return 0;
}

/* Display volume of view v: clip limits where on, intersected with the ws window. */
static int display_volume(const gks_ws *ws, const Gview_rep3 *v, double b[6])
{
    gks_limit3_array(&ws->cur_win, b);
    if (v->xy_clip == GIND_CLIP) {
        b[0] = fmax(b[0], v->clip_limit.x_min);
        b[1] = fmin(b[1], v->clip_limit.x_max);
        b[2] = fmax(b[2], v->clip_limit.y_min);
        b[3] = fmin(b[3], v->clip_limit.y_max);
    }
    if (v->back_clip == GIND_CLIP)
        b[4] = fmax(b[4], v->clip_limit.z_min);
    if (v->front_clip == GIND_CLIP)
        b[5] = fmin(b[5], v->clip_limit.z_max);
    return b[0] < b[1] && b[2] < b[3] && b[4] < b[5];
}

/* Coverage of the eye rays: sample k of the raster (pixel-major strata centres, or corner
 * k of the (w+1) x (h+1) corner grid in SPD mode) hit a primitive. */
typedef struct cover_job {
    const rt_scene *sc;
    const rt_camera *cam;
    int m, corners;
    size_t k0, k1;          /* this thread's samples [k0, k1) */
    unsigned short *cnt;    /* strata: hits per pixel (ranges start on pixel boundaries) */
    unsigned char *corner;  /* SPD: hit flag per corner */
    int err;
} cover_job;

static void *cover_run(void *arg)
{
    cover_job *j = arg;
    const rt_camera *cam = j->cam;
    size_t w = (size_t)cam->width, gw = w + 1, mm = (size_t)j->m * (size_t)j->m;
    rt_ray *rays = gks_alloc_array(COVER_BATCH, sizeof *rays);
    rt_hit *hits = gks_alloc_array(COVER_BATCH, sizeof *hits);
    if (!rays || !hits)
        j->err = 300;
    for (size_t k0 = j->k0; k0 < j->k1 && !j->err; k0 += COVER_BATCH) {
        size_t nb = j->k1 - k0 < COVER_BATCH ? j->k1 - k0 : COVER_BATCH;
        for (size_t q = 0; q < nb; q++) {
            size_t k = k0 + q;
            double px, py;
            if (j->corners) {
                px = (double)(k % gw);
                py = (double)(k / gw);
            } else {
                size_t pix = k / mm, s = k % mm;
                int a = (int)(s % (size_t)j->m), b = (int)(s / (size_t)j->m);
                /* the same expression as rt_render's sample positions */
                px = (int)(pix % w) + (a + 0.5) / j->m;
                py = (int)(pix / w) + (b + 0.5) / j->m;
            }
            if (rt_camera_ray(cam, px, py, &rays[q]) != RT_OK)
                rays[q] = (rt_ray){ .tmin = 1, .tmax = 0 };
        }
        int rc = rt_intersect(j->sc, nb, rays, hits);
        if (rc != RT_OK) {
            j->err = gks_err_of_rt(rc);
            break;
        }
        for (size_t q = 0; q < nb; q++) {
            if (j->corners)
                j->corner[k0 + q] = hits[q].prim >= 0;
            else if (hits[q].prim >= 0)
                j->cnt[(k0 + q) / mm]++;
        }
    }
    gks_free(rays);
    gks_free(hits);
    return NULL;
}

/* Coverage of each pixel of cam's raster: cnt[row*w + c] = number of its sample rays (the
 * strata centres rt_render uses without jitter, or its 4 corner rays in SPD mode) that hit a
 * primitive; *per = samples per pixel. Traced by up to o->threads threads (0: online CPUs),
 * each on whole pixel rows. Returns 0 or 300. */
static int coverage(const rt_scene *sc, const rt_camera *cam, const rt_render_options *o,
                    unsigned short *cnt, int *per)
{
    int w = cam->width, h = cam->height;
    int m = 1;
    while (m * m < o->samples)
        m++;
    int corners = o->corner_rays != 0;
    size_t mm = (size_t)m * (size_t)m;
    size_t gw = corners ? (size_t)w + 1 : (size_t)w, gh = corners ? (size_t)h + 1 : (size_t)h;
    size_t row = gw * (corners ? 1 : mm); /* samples per row of rays */
    *per = corners ? 4 : (int)mm;
    memset(cnt, 0, (size_t)w * (size_t)h * sizeof *cnt);
    unsigned char *corner = corners ? gks_alloc_array(gw, gh) : NULL;
    if (corners && !corner)
        return 300;
    long nt = o->threads > 0 ? o->threads : sysconf(_SC_NPROCESSORS_ONLN);
    if (nt < 1)
        nt = 1;
    if (nt > 64)
        nt = 64;
    if ((size_t)nt > gh)
        nt = (long)gh;
    cover_job jobs[64];
    pthread_t th[64];
    int started[64] = { 0 };
    for (long t = 0; t < nt; t++) {
        jobs[t] = (cover_job){ .sc = sc, .cam = cam, .m = m, .corners = corners,
                               .k0 = gh * (size_t)t / (size_t)nt * row,
                               .k1 = gh * (size_t)(t + 1) / (size_t)nt * row, .cnt = cnt,
                               .corner = corner };
        if (t > 0)
            started[t] = pthread_create(&th[t], NULL, cover_run, &jobs[t]) == 0;
    }
    cover_run(&jobs[0]);
    int err = jobs[0].err;
    for (long t = 1; t < nt; t++) {
        if (started[t])
            pthread_join(th[t], NULL);
        else
            cover_run(&jobs[t]); /* no thread: same result on this one */
        err = err ? err : jobs[t].err;
    }
    for (size_t y = 0; corners && !err && y < (size_t)h; y++)
        for (size_t x = 0; x < (size_t)w; x++)
            cnt[y * (size_t)w + x] = (unsigned short)(corner[y * gw + x] + corner[y * gw + x + 1] +
                                                      corner[(y + 1) * gw + x] +
                                                      corner[(y + 1) * gw + x + 1]);
    gks_free(corner);
    return err;
}

/* 1 if every sample of fb's pixels [ix0,ix1) x [iy0,iy1) has colour bg. */
static int all_background(const gks_raster_fb *fb, int ix0, int ix1, int iy0, int iy1,
                          const double bg[3])
{
    const float b[3] = { (float)bg[0], (float)bg[1], (float)bg[2] };
    for (int y = iy0 * fb->ss; y < iy1 * fb->ss; y++) {
        const float *d = fb->rgb + 3 * ((size_t)y * (size_t)fb->w + (size_t)(ix0 * fb->ss));
        for (int x = ix0 * fb->ss; x < ix1 * fb->ss; x++, d += 3)
            if (d[0] != b[0] || d[1] != b[1] || d[2] != b[2])
                return 0;
    }
    return 1;
}

static float clampf(double v, double hi) { return !(v > 0) ? 0.0f : v > hi ? (float)hi : (float)v; }

static void stats_add(rt_stats *a, const rt_stats *b)
{
    a->eye_rays += b->eye_rays;
    a->eye_hits += b->eye_hits;
    a->shadow_rays += b->shadow_rays;
    a->reflection_rays += b->reflection_rays;
    a->refraction_rays += b->refraction_rays;
    a->grid_cells += b->grid_cells;
    a->grid_refs += b->grid_refs;
    a->prims += b->prims;
    a->build_seconds += b->build_seconds;
    a->render_seconds += b->render_seconds;
    a->memory_bytes += b->memory_bytes;
}

/* Traces view vi into its display volume's pixels of fb; adds the ray statistics to *st and
 * sets *traced when the tracer ran. Returns 0 or 300. */
static int render_view(const ws_rt *r, const gks_ws *ws, int vi, const double wsm[4][4],
                       gks_raster_fb *fb, rt_stats *st, int *traced, int *fault)
{
#ifndef GKS_HAVE_MPI
    (void)fault; /* only a lost MPI rank is a fault */
#endif
    const Gview_rep3 *v = &ws->views[vi];
    double box[6];
    if (!display_volume(ws, v, box))
        return 0;
    /* Pixel rectangle covered by the display volume, rounded to whole pixels. */
    double lo[3], hi[3];
    gks_xform_point(wsm, (const double[3]){ box[0], box[2], box[4] }, lo);
    gks_xform_point(wsm, (const double[3]){ box[1], box[3], box[5] }, hi);
    if (!(hi[0] > lo[0]) || !(hi[1] > lo[1]))
        return 0;
    int ix0 = (int)fmax(0, fmin(fb->width, round(lo[0])));
    int ix1 = (int)fmax(0, fmin(fb->width, round(hi[0])));
    int iy0 = (int)fmax(0, fmin(fb->height, round(lo[1])));
    int iy1 = (int)fmax(0, fmin(fb->height, round(hi[1])));
    if (ix1 <= ix0 || iy1 <= iy0)
        return 0;
    double sx = (box[1] - box[0]) / (hi[0] - lo[0]), sy = (box[3] - box[2]) / (hi[1] - lo[1]);
    double nb[6] = { box[0] + (ix0 - lo[0]) * sx, box[0] + (ix1 - lo[0]) * sx,
                     box[2] + (iy0 - lo[1]) * sy, box[2] + (iy1 - lo[1]) * sy, box[4], box[5] };
    int w = ix1 - ix0, h = iy1 - iy0;
    rt_camera cam;
    if (rt_camera_from_view(&cam, v->map_matrix, nb, w, h) != RT_OK)
        return 0; /* singular mapping: nothing visible */

    rt_scene *sc;
    int err = build_scene(r, ws, vi, r->opts.clip_secondary ? &cam : NULL, &sc);
    if (err || !sc)
        return err;
    rt_render_options o = r->opts;
    /* rays that leave the scene see the workstation's background (colour index 0) */
    const double bg[3] = { ws->colr[0].red, ws->colr[0].green, ws->colr[0].blue };
    memcpy(o.background, bg, sizeof bg);
    const char *env = getenv("GKS3D_RT_PROGRESS");
    if (env && strcmp(env, "1") == 0)
        o.progress = 1;
    int assemble = 1; /* this process composes the traced pixels (rank 0 when shared) */
#ifdef GKS_HAVE_MPI
    int serialized = 0;
    rt_mpi_link *link = r->share_tiles ? ws_mpi_link(&serialized) : NULL;
    rt_mpi_job mj;
    if (link) {
        if (!serialized)
            o.threads = 1; /* MPI calls from the calling thread only */
        assemble = link->rank == 0;
    }
#endif
    size_t n = (size_t)w * (size_t)h;
    float *rgb = gks_alloc_array(n, 3 * sizeof(float));
    unsigned short *cnt = gks_alloc_array(n, sizeof *cnt);
    int per = 1;
    rt_stats s;
    if (!rgb || !cnt) {
        err = 300;
        goto done;
    }
    /* Over a rectangle that is still all background the traced colour is the answer
     * (T = a*H + (1-a)*bg): coverage is needed only over other content. */
    if (!assemble || all_background(fb, ix0, ix1, iy0, iy1, bg)) {
        per = 1;
        for (size_t k = 0; k < n; k++)
            cnt[k] = 1;
    } else {
        err = coverage(sc, &cam, &o, cnt, &per);
        if (err)
            goto done;
    }
#ifdef GKS_HAVE_MPI
    if (link) {
        long nt = o.threads > 0 ? o.threads : sysconf(_SC_NPROCESSORS_ONLN);
        o.tiles = rt_mpi_job_start(&mj, link, nt > 0 && nt < 256 ? (int)nt : 1);
    }
#endif
    int rr = rt_render(sc, &cam, &o, rgb, &s);
#ifdef GKS_HAVE_MPI
    if (link) {
        const char *rep = getenv("GKS3D_MPI_REPORT");
        if (rep && strcmp(rep, "1") == 0)
            fprintf(stderr, "gks3d: MPI rank %d of %d: frame %u: %ld of %d tiles traced here, "
                    "%ld bytes sent, %ld received\n", link->rank, link->size, mj.seq,
                    mj.tiles_here, mj.ntiles, mj.sent_bytes, mj.recv_bytes);
    }
    if (link && rt_mpi_job_finish(&mj)) {
        /* a lost rank: on rank 0 the picture is still complete (its tiles were traced
           here); the error is reported after the frame is written */
        fprintf(stderr, "gks3d: MPI rank %d: %s\n", link->rank, mj.msg);
        gks_par_lost();
        *fault = 305;
    }
    if (rr == RT_ERR_HOOK) {
        err = 305;
        goto done;
    }
#endif
    if (rr != RT_OK) {
        err = gks_err_of_rt(rr);
        goto done;
    }
    stats_add(st, &s);
    *traced = 1;
    if (!assemble)
        goto done; /* the other ranks' pixels are rank 0's to compose */
    /* rt rows are top-first; framebuffer rows bottom-up, ss x ss samples per pixel. The
     * traced colour T = a*H + (1-a)*bg for coverage a: the pixel becomes a*clamp(H) + (1-a)*F
     * over the framebuffer's F (exact for unjittered samples). */
    for (int row = 0; row < h; row++) {
        int j = iy1 - 1 - row;
        for (int c = 0; c < w; c++) {
            size_t k = (size_t)row * w + c;
            if (!cnt[k])
                continue;
            double a = (double)cnt[k] / per;
            float ah[3];
            for (int q = 0; q < 3; q++)
                ah[q] = clampf(rgb[3 * k + q] - (1 - a) * bg[q], a);
            int i = ix0 + c;
            for (int sj = 0; sj < fb->ss; sj++)
                for (int si = 0; si < fb->ss; si++) {
                    float *d = fb->rgb + 3 * ((size_t)(j * fb->ss + sj) * fb->w +
                                              (size_t)(i * fb->ss + si));
                    for (int q = 0; q < 3; q++)
                        d[q] = cnt[k] == per ? ah[q] : clampf(ah[q] + (1 - a) * d[q], 1);
                }
        }
    }
done:
    gks_free(rgb);
    gks_free(cnt);
    rt_scene_free(sc);
    return err;
}

int ws_rt_render(ws_rt *r, const gks_ws *ws, const double wsm[4][4], gks_raster_fb *fb)
{
    if (!r->n_recs)
        return 0;
    unsigned char used[GKS_MAX_VIEW_IND + 1] = { 0 };
    for (size_t k = 0; k < r->n_recs; k++)
        used[r->recs[k].view_ind] = 1;
    rt_stats sum;
    memset(&sum, 0, sizeof sum);
    int traced = 0, fault = 0;
    for (int vi = 0; vi <= GKS_MAX_VIEW_IND; vi++) {
        if (!used[vi])
            continue;
        int err = render_view(r, ws, vi, wsm, fb, &sum, &traced, &fault);
        if (err)
            return err;
    }
    if (traced)
        r->last = sum;
    return fault;
}

/* ---- ESCAPEs ------------------------------------------------------------------------- */

/* The escapes that set one integer option: ints[1] in [lo, hi]. */
static const struct int_escape {
    int id, lo, hi;
    size_t off;
} int_escapes[] = {
    { GESC_RT_CLIP_SECONDARY, 0, 1, offsetof(rt_render_options, clip_secondary) },
    { GESC_RT_MAX_DEPTH, 1, 64, offsetof(rt_render_options, max_depth) },
    { GESC_RT_THREADS, 0, 256, offsetof(rt_render_options, threads) },
    { GESC_RT_PROGRESS, 0, 1, offsetof(rt_render_options, progress) },
    { GESC_RT_SPD, 0, 1, offsetof(rt_render_options, corner_rays) },
};

static Gint sat_int(uint64_t v) { return v > (uint64_t)INT_MAX ? INT_MAX : (Gint)v; }

static int escape_stats(const ws_rt *r, Gescape_out_data *out)
{
    if (!out || !out->ints || !out->floats || out->num_ints < 8 || out->num_floats < 2)
        return 182;
    const rt_stats *s = &r->last;
    const uint64_t v[8] = { s->eye_rays, s->eye_hits, s->reflection_rays, s->refraction_rays,
                            s->shadow_rays, s->grid_cells, s->grid_refs, s->prims };
    for (int k = 0; k < 8; k++)
        out->ints[k] = sat_int(v[k]);
    out->floats[0] = s->build_seconds;
    out->floats[1] = s->render_seconds;
    out->num_ints = 8;
    out->num_floats = 2;
    return 0;
}

static int escape_samples(ws_rt *r, const Gescape_in_data *in)
{
    int s = in->ints[1];
    int jitter = in->num_ints >= 3 ? in->ints[2] : 0;
    if (s < 1 || s > 256 || jitter < 0 || jitter > 1)
        return 182;
    int m = 1;
    while (m * m < s)
        m++;
    if (m * m != s)
        return 182;
    r->opts.samples = s;
    r->opts.jitter = jitter;
    r->opts.corner_rays = 0; /* stratified samples per pixel instead of the corner rays */
    return 0;
}

int ws_rt_escape(ws_rt *r, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    if (func_id > GESC_RT_CLIP_SECONDARY || func_id < GESC_RT_SPD)
        return 180;
    if (func_id == GESC_RT_STATS)
        return escape_stats(r, out);
    if (!in)
        return 182;
    if (func_id == GESC_RT_CUTOFF) {
        if (in->num_floats < 1 || !in->floats)
            return 182;
        double c = in->floats[0];
        if (!(c >= 0 && c < 1))
            return 182;
        r->opts.cutoff = c;
        return 0;
    }
    if (in->num_ints < 2 || !in->ints)
        return 182;
    if (func_id == GESC_RT_SAMPLES)
        return escape_samples(r, in);
    for (size_t k = 0; k < sizeof int_escapes / sizeof int_escapes[0]; k++) {
        const struct int_escape *e = &int_escapes[k];
        if (e->id != func_id)
            continue;
        if (in->ints[1] < e->lo || in->ints[1] > e->hi)
            return 182;
        *(int *)((char *)&r->opts + e->off) = in->ints[1];
        return 0;
    }
    return 180;
}
