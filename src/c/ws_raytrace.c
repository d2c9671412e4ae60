/*
 * ws_raytrace.c -- HLHSR mode GHLHSR_RAYTRACE (paper sections 3 and 5) for the PNG
 * workstation. FILL AREAs are not rasterized but recorded in VRC3 (the NDC3 points after
 * the view orientation matrix of their view); when the frame is written they are traced
 * with gksrt: the camera comes from the view mapping matrix, the display volume is the view
 * clip volume (where the indicators are on) intersected with the workstation window.
 * Limitations (documented in docs): only primitives of ONE view are traced per frame, the
 * view of the first recorded primitive; POLYLINEs are annotations, rasterized as in mode 0
 * and ignored by the tracer (a traced surface overwrites them); lights the tracer rejects
 * (e.g. a spot light of spread 0, a zero direction) are left out.
 */
#include "ws_raytrace.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include "gksrt.h"
#include <math.h>
#include <string.h>

typedef struct rt_rec {
    int n_loops, loop_off;   /* loop counts at loops[loop_off..] */
    int n_points, pt_off;    /* xyz at xyz[3*pt_off..] */
    Grgb colour;
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
    double *xyz;             /* 3 per point */
    size_t n_pts, cap_pts;
    int clip_secondary;
};

ws_rt *ws_rt_new(void) { return gks_calloc_array(1, sizeof(ws_rt)); }

void ws_rt_free(ws_rt *r)
{
    if (!r)
        return;
    gks_free(r->recs);
    gks_free(r->loops);
    gks_free(r->xyz);
    gks_free(r);
}

void ws_rt_reset(ws_rt *r) { r->n_recs = r->n_loops = r->n_pts = 0; }

int ws_rt_count(const ws_rt *r) { return (int)r->n_recs; }

void ws_rt_set_clip_secondary(ws_rt *r, int on) { r->clip_secondary = on != 0; }

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

int ws_rt_record(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    if (prim->kind != GKS_PRIM_FILL_AREA || prim->n_points < 3 || prim->n_loops < 1)
        return 0;
    if (reserve((void **)&r->recs, r->n_recs, 1, &r->cap_recs, sizeof *r->recs) ||
        reserve((void **)&r->loops, r->n_loops, (size_t)prim->n_loops, &r->cap_loops,
                sizeof *r->loops) ||
        reserve((void **)&r->xyz, 3 * r->n_pts, 3 * (size_t)prim->n_points, &r->cap_pts,
                sizeof *r->xyz))
        return 300;
    int vi = clamp_view(prim->view_ind);
    const Gview_rep3 *v = &ws->views[vi];
    rt_rec *rec = &r->recs[r->n_recs];
    *rec = (rt_rec){ .n_loops = prim->n_loops, .loop_off = (int)r->n_loops,
                     .n_points = prim->n_points, .pt_off = (int)r->n_pts,
                     .colour = prim->colour, .refl_eq = { prim->refl_eq[0], prim->refl_eq[1] },
                     .light_mask = prim->light_mask, .view_ind = vi };
    rec->props[0] = prim->area_props[0];
    rec->props[1] = prim->area_props[1];
    memcpy(r->loops + r->n_loops, prim->loop_counts, (size_t)prim->n_loops * sizeof(int));
    for (int i = 0; i < prim->n_points; i++)
        xf_point(v->ori_matrix, prim->pts[i].x, prim->pts[i].y, prim->pts[i].z,
                 r->xyz + 3 * (r->n_pts + (size_t)i));
    r->n_recs++;
    r->n_loops += (size_t)prim->n_loops;
    r->n_pts += (size_t)prim->n_points;
    return 0;
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

/* Builds the scene of view vi. Returns 0, 300; *out NULL when nothing is traceable. */
static int build_scene(const ws_rt *r, const gks_ws *ws, int vi, rt_scene **out)
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
    for (size_t k = 0; k < r->n_recs; k++) {
        const rt_rec *rec = &r->recs[k];
        if (rec->view_ind != vi)
            continue;
        uint64_t mask = 0;
        for (int i = 0; i < GKS_MAX_LIGHT_IND; i++)
            if (((rec->light_mask >> i) & 1) && bit[i] >= 0)
                mask |= (uint64_t)1 << bit[i];
        rt_surface s;
        surface_of(rec, 0, mask, &s);
        int f = rt_scene_add_surface(sc, &s);
        surface_of(rec, 1, mask, &s);
        int b = rt_scene_add_surface(sc, &s);
        if (f == RT_ERR_NOMEM || b == RT_ERR_NOMEM) {
            rt_scene_free(sc);
            return 300;
        }
        if (f < 0 || b < 0)
            continue; /* cannot happen: values checked at SET */
        int id = rt_scene_add_polygon(sc, rec->n_loops, r->loops + rec->loop_off,
                                      r->xyz + 3 * (size_t)rec->pt_off, f, b);
        if (id == RT_ERR_NOMEM) {
            rt_scene_free(sc);
            return 300;
        }
    }
    if (rt_scene_commit(sc, NULL) != RT_OK) {
        rt_scene_free(sc);
        return 300;
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

static float clamp01(float v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

int ws_rt_render(ws_rt *r, const gks_ws *ws, const double wsm[4][4], gks_raster_fb *fb)
{
    if (!r->n_recs)
        return 0;
    int vi = r->recs[0].view_ind;
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
    double fx0 = fmax(0, fmin(fb->width, round(lo[0]))), fx1 = fmax(0, fmin(fb->width, round(hi[0])));
    double fy0 = fmax(0, fmin(fb->height, round(lo[1]))), fy1 = fmax(0, fmin(fb->height, round(hi[1])));
    int ix0 = (int)fx0, ix1 = (int)fx1, iy0 = (int)fy0, iy1 = (int)fy1;
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
    int err = build_scene(r, ws, vi, &sc);
    if (err || !sc)
        return err;
    size_t n = (size_t)w * (size_t)h;
    float *rgb = gks_alloc_array(n, 3 * sizeof(float));
    rt_ray *rays = gks_alloc_array(n, sizeof *rays);
    rt_hit *hits = gks_alloc_array(n, sizeof *hits);
    if (!rgb || !rays || !hits) {
        err = 300;
        goto done;
    }
    /* Coverage: the primary rays rt_render shoots (pixel centres, no jitter). */
    for (int row = 0; row < h; row++)
        for (int c = 0; c < w; c++)
            if (rt_camera_ray(&cam, c + 0.5, row + 0.5, &rays[(size_t)row * w + c]) != RT_OK)
                rays[(size_t)row * w + c] = (rt_ray){ .tmin = 1, .tmax = 0 };
    rt_render_options o;
    rt_render_options_default(&o);
    o.clip_secondary = r->clip_secondary;
    /* rays that leave the scene see the workstation's background (colour index 0) */
    o.background[0] = ws->colr[0].red;
    o.background[1] = ws->colr[0].green;
    o.background[2] = ws->colr[0].blue;
    int rr = rt_intersect(sc, n, rays, hits);
    if (rr == RT_OK)
        rr = rt_render(sc, &cam, &o, rgb, NULL);
    if (rr != RT_OK) {
        err = rr == RT_ERR_NOMEM ? 300 : 0;
        goto done;
    }
    /* rt rows are top-first; framebuffer rows bottom-up, ss x ss samples per pixel. */
    for (int row = 0; row < h; row++) {
        int j = iy1 - 1 - row;
        for (int c = 0; c < w; c++) {
            size_t k = (size_t)row * w + c;
            if (hits[k].prim < 0)
                continue;
            int i = ix0 + c;
            for (int sj = 0; sj < fb->ss; sj++)
                for (int si = 0; si < fb->ss; si++) {
                    float *d = fb->rgb + 3 * ((size_t)(j * fb->ss + sj) * fb->w +
                                              (size_t)(i * fb->ss + si));
                    for (int q = 0; q < 3; q++)
                        d[q] = clamp01(rgb[3 * k + q]);
                }
        }
    }
done:
    gks_free(rgb);
    gks_free(rays);
    gks_free(hits);
    rt_scene_free(sc);
    return err;
}

int ws_rt_escape(ws_rt *r, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    (void)out;
    if (func_id != GESC_RT_CLIP_SECONDARY)
        return 180;
    if (!in || in->num_ints < 2 || (unsigned)in->ints[1] > 1)
        return 182;
    ws_rt_set_clip_secondary(r, in->ints[1]);
    return 0;
}
