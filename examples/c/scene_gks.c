/* SPDX-License-Identifier: MIT */
/*
 * scene_gks.c -- scene_io scenes drawn through the GKS-3D C binding; see scene_gks.h.
 */
#define _POSIX_C_SOURCE 200809L
#include "scene_gks.h"

#include <gks.h>

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { WS = 1, VIEW = 1, FIRST_COLR = 8, MAX_COLR = 256, FIRST_LIGHT = 2 };

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int fail(char *err, size_t size, const char *fmt, ...)
{
    if (err && size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, size, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static double clamp01(double v, int *clamped)
{
    if (v >= 0 && v <= 1)
        return v;
    *clamped = 1;
    return v > 1 ? 1 : 0;
}

/* Colour indices: one per distinct colour, FIRST_COLR.. MAX_COLR-1; beyond, the nearest. */
typedef struct {
    Grgb colr[MAX_COLR];
    int n;
    int overflow;
} palette;

static int palette_index(palette *p, const double rgb[3], int *clamped)
{
    Grgb c = { clamp01(rgb[0], clamped), clamp01(rgb[1], clamped), clamp01(rgb[2], clamped) };
    int best = -1;
    double bd = INFINITY;
    for (int i = 0; i < p->n; i++) {
        double dr = p->colr[i].red - c.red, dg = p->colr[i].green - c.green,
               db = p->colr[i].blue - c.blue, d = dr * dr + dg * dg + db * db;
        if (d < bd) {
            bd = d;
            best = i;
        }
    }
    if (best >= 0 && bd == 0)
        return FIRST_COLR + best;
    if (p->n < MAX_COLR - FIRST_COLR) {
        p->colr[p->n] = c;
        return FIRST_COLR + p->n++;
    }
    p->overflow = 1;
    return FIRST_COLR + best;
}

/* View orientation and mapping of view; far = distance of the back plane. */
static int make_view(const scene_io_view *v, double far, double ax, double ay, Gview_rep3 *rep,
                     char *err, size_t es)
{
    Gint e1 = 0, e2 = 0;
    Gpoint3 vrp = { v->from[0], v->from[1], v->from[2] };
    Gvec3 vpn = { v->from[0] - v->at[0], v->from[1] - v->at[1], v->from[2] - v->at[2] };
    Gvec3 vup = { v->up[0], v->up[1], v->up[2] };
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &e1, rep->ori_matrix);
    /* half width of the window on the view plane n = -hither; square pixels */
    double hw = v->hither * tan(0.5 * v->angle * 3.14159265358979323846 / 180);
    double hh = hw * ay / ax;
    Gview_map3 map = { { -hw, hw, -hh, hh }, { 0, ax, 0, ay, 0, 1 }, GPROJ_PERSPECT,
                       { 0, 0, 0 }, -v->hither, -far, -v->hither };
    geval_view_map_matrix3(&map, &e2, rep->map_matrix);
    if (e1 || e2)
        return fail(err, es, "the view gives GKS error %d (%s)", e1 ? e1 : e2,
                    gks_error_message(e1 ? e1 : e2));
    rep->clip_limit = map.proj_vp;
    rep->xy_clip = rep->back_clip = rep->front_clip = GIND_CLIP;
    return 0;
}

/* Distance from the eye to the farthest polygon vertex of all scenes (>= 2 hither). */
static double far_distance(const scene_io_scene *const *sc, int n, const scene_io_view *v)
{
    double far = 0;
    for (int k = 0; k < n; k++) {
        double lo[3], hi[3];
        if (!scene_io_bounds(sc[k], lo, hi))
            continue;
        for (int c = 0; c < 8; c++) {
            double p[3] = { c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2] };
            double d = sqrt((p[0] - v->from[0]) * (p[0] - v->from[0]) +
                            (p[1] - v->from[1]) * (p[1] - v->from[1]) +
                            (p[2] - v->from[2]) * (p[2] - v->from[2]));
            far = d > far ? d : far;
        }
    }
    far *= 1.01;
    return far > 2 * v->hither ? far : 2 * v->hither;
}

static void escape_int(Gint func, Gint a, Gint b, int nb)
{
    Gint ints[3] = { WS, a, b };
    Gescape_in_data in = { .num_ints = nb ? 3 : 2, .ints = ints };
    gescape(func, &in, NULL, NULL);
}

static int setup_lights(const scene_io_light *lights, size_t n, double ambient, int *clamped,
                        char *err, size_t es)
{
    if (n > (size_t)(GKS_MAX_LIGHT_IND - FIRST_LIGHT + 1))
        return fail(err, es, "%zu lights: at most %d supported", n,
                    GKS_MAX_LIGHT_IND - FIRST_LIGHT + 1);
    Gint on[GKS_MAX_LIGHT_IND];
    int non = 0;
    if (ambient > 0) {
        double a = clamp01(ambient, clamped);
        Glight_src_rep amb = { GLIGHT_AMBIENT, { a, a, a }, { 0, 0, 0 }, { 0, 0, -1 },
                               { 1, 0 }, 0, 1 };
        gset_light_src_rep(WS, 1, &amb);
        on[non++] = 1;
    }
    for (size_t i = 0; i < n; i++) {
        const scene_io_light *l = &lights[i];
        Glight_src_rep rep = { GLIGHT_POSITIONAL,
                               { clamp01(l->color[0], clamped), clamp01(l->color[1], clamped),
                                 clamp01(l->color[2], clamped) },
                               { l->pos[0], l->pos[1], l->pos[2] }, { 0, 0, -1 }, { 1, 0 }, 0, 1 };
        gset_light_src_rep(WS, FIRST_LIGHT + (Gint)i, &rep);
        on[non++] = FIRST_LIGHT + (Gint)i;
    }
    Gint off_1[1] = { 1 };
    Gint_list act = { non, on }, deact = { 1, off_1 };
    gset_light_src_state(&act, ambient > 0 ? NULL : &deact);
    return 0;
}

static void set_material(const scene_io_material *m, Gint colr_ind, int *clamped)
{
    double kd = clamp01(m->kd, clamped);
    Garea_props ap = { kd, kd, clamp01(m->ks, clamped), { 1, 1, 1 }, m->shine,
                       clamp01(m->t, clamped), m->ior > 0 ? m->ior : 1 };
    gset_area_props(&ap);
    gset_back_area_props(&ap);
    gset_fill_colr_ind(colr_ind);
}

/* FILL AREA 3 for every polygon of s; pts has room for the largest polygon. The colour
 * representations must be set before: attributes are bound when a primitive is created. */
static void draw_scene(const scene_io_scene *s, Gpoint3 *pts, Gvec3 *nrm, palette *pal,
                       int *clamped)
{
    uint32_t cur = UINT32_MAX;
    if (nrm) {
        gset_int_shad_meth(GSHAD_NORM);
        gset_back_int_shad_meth(GSHAD_NORM);
    }
    for (size_t i = 0; i < s->num_polygons; i++) {
        uint32_t m = s->poly_material[i];
        if (m != cur && m < s->num_materials) {
            set_material(&s->materials[m], palette_index(pal, s->materials[m].color, clamped),
                         clamped);
            cur = m;
        }
        const uint32_t *idx = s->poly_verts + s->poly_start[i];
        int nv = s->poly_nverts[i];
        for (int k = 0; k < nv; k++) {
            const double *v = s->vertices + 3 * (size_t)idx[k];
            pts[k] = (Gpoint3){ v[0], v[1], v[2] };
        }
        int with = 0; /* every vertex has a non-zero normal */
        for (int k = 0; nrm && k < nv; k++) {
            const double *q = s->normals + 3 * (size_t)idx[k];
            nrm[k] = (Gvec3){ q[0], q[1], q[2] };
            with = k == 0 ? 1 : with;
            if (q[0] == 0 && q[1] == 0 && q[2] == 0)
                with = -1;
        }
        if (with > 0) {
            Gfacet_vdata3 vd = { nv, pts, NULL, nrm };
            gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
            continue;
        }
        Gpoint_list3 l = { nv, pts };
        gfill_area3(&l);
    }
}

static int resolution_ok(const scene_io_view *v, Gint *type, char *err, size_t es)
{
    int m = v->res_x > v->res_y ? v->res_x : v->res_y;
    if (v->res_x < 1 || v->res_y < 1 || m > 8192)
        return fail(err, es, "resolution %dx%d: the PNG workstations hold at most 8192x8192",
                    v->res_x, v->res_y);
    *type = m <= 1024 ? GWS_TYPE_PNG : GWS_TYPE_PNG_LARGE;
    return 0;
}

int scene_gks_render(const scene_io_scene *const *scenes, int n, const scene_io_view *view,
                     const scene_io_light *lights, size_t num_lights, const double bg[3],
                     const char *png_path, const scene_gks_options *opt,
                     scene_gks_result *res, char *err, size_t err_size)
{
    if (!scenes || n < 1 || !view || !view->present || !png_path || !opt || !res)
        return fail(err, err_size, "missing scene, view or output");
    memset(res, 0, sizeof *res);
    Gint type = GWS_TYPE_PNG;
    if (resolution_ok(view, &type, err, err_size))
        return -1;
    size_t maxv = 0, npoly = 0;
    for (int k = 0; k < n; k++) {
        npoly += scenes[k]->num_polygons;
        for (size_t i = 0; i < scenes[k]->num_polygons; i++)
            if ((size_t)scenes[k]->poly_nverts[i] > maxv)
                maxv = (size_t)scenes[k]->poly_nverts[i];
    }
    if (npoly == 0)
        return fail(err, err_size, "the scene has no polygons");
    Gpoint3 *pts = maxv <= SIZE_MAX / sizeof *pts ? malloc(maxv * sizeof *pts) : NULL;
    Gvec3 *nrm = opt->smooth && maxv <= SIZE_MAX / sizeof *nrm ? malloc(maxv * sizeof *nrm) : NULL;
    if (!pts || (opt->smooth && !nrm)) {
        free(pts);
        free(nrm);
        return fail(err, err_size, "out of memory");
    }

    double t0 = now_s();
    double ax = 1, ay = 1;
    if (view->res_x >= view->res_y)
        ay = (double)view->res_y / view->res_x;
    else
        ax = (double)view->res_x / view->res_y;
    Gview_rep3 rep;
    int clamped = 0, rc = 0;
    gopen_gks(NULL, 0);
    if (make_view(view, far_distance(scenes, n, view), ax, ay, &rep, err, err_size)) {
        gclose_gks();
        free(pts);
        free(nrm);
        return -1;
    }
    gopen_ws(WS, png_path, type);
    gactivate_ws(WS);
    Glimit win = { 0, ax, 0, ay }, vp = { 0, view->res_x, 0, view->res_y };
    gset_ws_win(WS, &win);
    gset_ws_vp(WS, &vp);
    gset_hlhsr_mode(WS, opt->zbuffer ? GHLHSR_ZBUFFER : GHLHSR_RAYTRACE);
    if (opt->zbuffer) /* the tracer fills every area; the z-buffer by the interior style */
        gset_fill_int_style(GSTYLE_SOLID);
    gset_view_rep3(WS, VIEW, &rep);
    gset_view_ind(VIEW);
    gset_clip_ind(GIND_NO_CLIP);
    Gcolr_rep back = { { clamp01(bg[0], &clamped), clamp01(bg[1], &clamped),
                         clamp01(bg[2], &clamped) } };
    gset_colr_rep(WS, 0, &back);
    rc = setup_lights(lights, num_lights, opt->ambient, &clamped, err, err_size);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    gset_back_refl_eq(GREFL_AMB_DIFF_SPEC);

    /* ray-tracing controls (ESCAPEs of the PNG workstation) */
    if (opt->spd) {
        escape_int(GESC_RT_SPD, 1, 0, 0);
        Gint ints[1] = { WS };
        Gfloat zero[1] = { 0 };
        Gescape_in_data in = { .num_ints = 1, .ints = ints, .num_floats = 1, .floats = zero };
        gescape(GESC_RT_CUTOFF, &in, NULL, NULL);
    }
    if (opt->depth > 0 || opt->spd)
        escape_int(GESC_RT_MAX_DEPTH, opt->depth > 0 ? opt->depth : 5, 0, 0);
    if (opt->samples > 0)
        escape_int(GESC_RT_SAMPLES, opt->samples, 0, 1);
    if (opt->threads >= 0)
        escape_int(GESC_RT_THREADS, opt->threads, 0, 0);

    /* the colour table first (materials used by polygons), then the primitives */
    palette pal = { .n = 0 };
    for (int k = 0; k < n; k++)
        for (size_t i = 0; i < scenes[k]->num_materials; i++)
            palette_index(&pal, scenes[k]->materials[i].color, &clamped);
    for (int i = 0; i < pal.n; i++) {
        Gcolr_rep c = { pal.colr[i] };
        gset_colr_rep(WS, FIRST_COLR + i, &c);
    }
    /* the display surface takes the background colour when it is cleared: REDRAW ALL
     * SEGMENTS clears it without starting a new frame file (CLEAR WORKSTATION would
     * write the empty frame 1 first) */
    gredraw_all_seg_ws(WS);
    for (int k = 0; k < n && !rc; k++)
        draw_scene(scenes[k], pts, scenes[k]->normals ? nrm : NULL, &pal, &clamped);
    double t1 = now_s();
    gupd_ws(WS, GFLAG_PERFORM);
    double t2 = now_s();
    res->draw_s = t1 - t0;
    res->frame_s = t2 - t1;

    Gint ints[1] = { WS };
    Gescape_in_data in = { .num_ints = 1, .ints = ints };
    Gstore store = NULL;
    Gescape_out_data *out = NULL;
    Gint in_h, before, after, serr;
    gcreate_store(&serr, &store);
    ginq_err_st(&in_h, &before);
    gescape(GESC_RT_STATS, &in, &store, &out);
    ginq_err_st(&in_h, &after);
    if (out && out->num_ints == 8 && out->num_floats == 2) {
        res->have_stats = 1;
        for (int k = 0; k < 8; k++)
            res->stats[k] = out->ints[k];
        res->build_s = out->floats[0];
        res->render_s = out->floats[1];
    }
    gdel_store(store);
    gdeactivate_ws(WS);
    gclose_ws(WS);
    Gint last = 0;
    ginq_err_st(&in_h, &last);
    gclose_gks();
    free(pts);
    free(nrm);
    if (!opt->quiet && clamped)
        fprintf(stderr, "warning: colours or coefficients outside [0,1] were clamped\n");
    if (!opt->quiet && pal.overflow)
        fprintf(stderr, "warning: more than %d distinct colours: nearest ones used\n",
                MAX_COLR - FIRST_COLR);
    if (rc)
        return rc;
    /* errors before the statistics inquiry, or while closing, are fatal; a statistics
     * ESCAPE the workstation does not support only leaves have_stats at 0 */
    if (before || last != after) {
        Gint e = before ? before : last;
        return fail(err, err_size, "GKS reported error %d (%s)", e, gks_error_message(e));
    }
    return 0;
}

void scene_gks_print_stats(const scene_gks_result *r)
{
    printf("rays eye=%lld eye_hit=%lld reflect=%lld refract=%lld shadow=%lld\n", r->stats[0],
           r->stats[1], r->stats[2], r->stats[3], r->stats[4]);
    printf("time draw=%.3f build=%.3f render=%.3f frame=%.3f\n", r->draw_s, r->build_s,
           r->render_s, r->frame_s);
    fflush(stdout);
}

void scene_gks_warn_stderr(void *ctx, const char *msg)
{
    (void)ctx;
    fprintf(stderr, "%s\n", msg);
}

int scene_gks_int_arg(const char *s, long lo, long hi, int *v)
{
    char *e;
    long x = strtol(s, &e, 10);
    if (!*s || *e || x < lo || x > hi)
        return -1;
    *v = (int)x;
    return 0;
}

int scene_gks_real_arg(const char *s, double lo, double hi, double *v)
{
    char *e;
    double x = strtod(s, &e);
    if (!*s || *e || !(x >= lo && x <= hi))
        return -1;
    *v = x;
    return 0;
}

int scene_gks_size_arg(const char *s, int *w, int *h)
{
    int a, b;
    char tail;
    if (sscanf(s, "%dx%d%c", &a, &b, &tail) != 2 || a < 1 || b < 1 || a > 8192 || b > 8192)
        return -1;
    *w = a;
    *h = b;
    return 0;
}

int scene_gks_perfect_square(int n)
{
    int m = 1;
    while (m * m < n)
        m++;
    return m * m == n;
}
