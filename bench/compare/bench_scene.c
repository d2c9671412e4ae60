/* SPDX-License-Identifier: MIT */
/* bench_scene.c -- see bench_scene.h */
#include "bench_scene.h"
#include "scene_io.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const double bs_pi = 3.14159265358979323846;

void *bs_alloc(size_t n, size_t size)
{
    if (n == 0 || size == 0 || n > SIZE_MAX / size)
        return NULL;
    return malloc(n * size);
}

static double bs_clock(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bs_thread_cpu(void) { return bs_clock(CLOCK_THREAD_CPUTIME_ID); }
double bs_process_cpu(void) { return bs_clock(CLOCK_PROCESS_CPUTIME_ID); }
double bs_wall(void) { return bs_clock(CLOCK_MONOTONIC); }

static int bs_fail(char *err, size_t n, const char *fmt, ...)
{
    if (err && n) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

static int bs_normalize(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (!(l > 0.0) || !isfinite(l))
        return 0;
    for (int i = 0; i < 3; i++)
        v[i] /= l;
    return 1;
}

/* world -> VRC3: origin at the eye, n axis from 'at' towards the eye, v axis along 'up' */
static int bs_lookat(const double from[3], const double at[3], const double up[3], double m[4][4])
{
    double n[3] = {from[0] - at[0], from[1] - at[1], from[2] - at[2]}, u[3], v[3];
    if (!bs_normalize(n))
        return 0;
    u[0] = up[1] * n[2] - up[2] * n[1];
    u[1] = up[2] * n[0] - up[0] * n[2];
    u[2] = up[0] * n[1] - up[1] * n[0];
    if (!bs_normalize(u))
        return 0;
    v[0] = n[1] * u[2] - n[2] * u[1];
    v[1] = n[2] * u[0] - n[0] * u[2];
    v[2] = n[0] * u[1] - n[1] * u[0];
    memset(m, 0, 16 * sizeof(double));
    for (int i = 0; i < 3; i++) {
        m[0][i] = u[i];
        m[1][i] = v[i];
        m[2][i] = n[i];
    }
    for (int r = 0; r < 3; r++)
        m[r][3] = -(m[r][0] * from[0] + m[r][1] * from[1] + m[r][2] * from[2]);
    m[3][3] = 1.0;
    return 1;
}

static void bs_xform(const double m[4][4], const double p[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    memcpy(out, r, sizeof r);
}

/* inverse of a rigid world -> VRC matrix */
static void bs_vrc_to_world(const double m[4][4], const double p[3], double out[3])
{
    double q[3] = {p[0] - m[0][3], p[1] - m[1][3], p[2] - m[2][3]};
    for (int i = 0; i < 3; i++)
        out[i] = m[0][i] * q[0] + m[1][i] * q[1] + m[2][i] * q[2];
}

/* Perspective view mapping VRC3 -> NPC3 [0,1]^3 for an eye at the origin looking down -n,
 * full field of view 'angle' degrees on both axes, front plane at distance near (NPC z = 1),
 * back plane at far (NPC z = 0). With w = -z: x' = w/2 + x/(2h), z' = a*w + b,
 * z_npc = a + b/d (d = -z) = 1 at d = near and 0 at d = far. */
static void bs_view_matrix(double angle, double near, double far, double m[4][4])
{
    double h = tan(0.5 * angle * bs_pi / 180.0);
    double b = 1.0 / (1.0 / near - 1.0 / far), a = -b / far;
    memset(m, 0, 16 * sizeof(double));
    m[0][0] = 0.5 / h;
    m[0][2] = -0.5;
    m[1][1] = 0.5 / h;
    m[1][2] = -0.5;
    m[2][2] = -a;
    m[2][3] = b;
    m[3][2] = -1.0;
}

static int bs_add_materials(const scene_io_scene *io, bs_scene *s, int *base, const bs_options *opt)
{
    for (size_t i = 0; i < io->num_materials; i++) {
        const scene_io_material *mt = &io->materials[i];
        rt_surface su;
        rt_surface_default(&su);
        if (io->format == SCENE_IO_NFF) {
            su.refl_eq = RT_REFL_SPECULAR;
            su.ka = 0.0;
            su.kd = mt->kd;
            su.ks = mt->ks;
            memcpy(su.diffuse, mt->color, sizeof su.diffuse);
            su.specular[0] = su.specular[1] = su.specular[2] = 1.0;
            su.spec_exp = mt->shine;
            su.transparency = mt->t > 1.0 ? 1.0 : mt->t;
            su.refr_index = mt->ior > 0.0 ? mt->ior : 1.0;
        } else {
            su.refl_eq = opt->mesh_ks > 0.0 ? RT_REFL_SPECULAR : RT_REFL_DIFFUSE;
            su.ka = 0.1;
            su.kd = 0.8;
            su.ks = opt->mesh_ks;
            su.spec_exp = 20.0;
        }
        int id = rt_scene_add_surface(s->rt, &su);
        if (id < 0)
            return -1;
        if (i == 0)
            *base = id;
    }
    return 0;
}

static int bs_add_lights(const scene_io_scene *io, bs_scene *s, double dist)
{
    if (io->num_lights == 0) {
        /* meshes: one positional light up and right of the eye, plus ambient */
        double lv[3] = {0.5 * dist, 0.8 * dist, 0.0};
        memcpy(s->light_vrc, lv, sizeof lv);
        bs_vrc_to_world(s->world_to_vrc, lv, s->light_world);
        rt_light l = {.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .c1 = 1.0};
        memcpy(l.position, lv, sizeof lv);
        rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
        if (rt_scene_add_light(s->rt, &l) < 0 || rt_scene_add_light(s->rt, &a) < 0)
            return -1;
        s->nlights = 1;
        return 0;
    }
    double in = 1.0 / sqrt((double)io->num_lights);
    for (size_t i = 0; i < io->num_lights && i < RT_MAX_LIGHTS; i++) {
        rt_light l = {.type = RT_LIGHT_POSITIONAL, .c1 = 1.0};
        for (int k = 0; k < 3; k++)
            l.color[k] = in * io->lights[i].color[k];
        bs_xform(s->world_to_vrc, io->lights[i].pos, l.position);
        if (i == 0) {
            memcpy(s->light_vrc, l.position, sizeof l.position);
            memcpy(s->light_world, io->lights[i].pos, sizeof s->light_world);
        }
        if (rt_scene_add_light(s->rt, &l) < 0)
            return -1;
        s->nlights++;
    }
    return 0;
}

/* fan triangles of all polygons for the peers (s->tris; tri_prim set by the caller) */
static int bs_fan_triangles(const scene_io_scene *io, bs_scene *s)
{
    size_t ntri = 0;
    for (size_t p = 0; p < io->num_polygons; p++)
        ntri += (size_t)io->poly_nverts[p] - 2;
    s->ntris = ntri;
    s->tris = bs_alloc(ntri, 3 * sizeof(uint32_t));
    s->tri_prim = bs_alloc(ntri, sizeof(int));
    if (!s->tris || !s->tri_prim)
        return -1;
    size_t t = 0;
    s->all_triangles = 1;
    for (size_t p = 0; p < io->num_polygons; p++) {
        const int n = io->poly_nverts[p];
        const uint32_t *ix = io->poly_verts + io->poly_start[p];
        if (n != 3)
            s->all_triangles = 0;
        for (int k = 1; k + 1 < n; k++, t++) {
            s->tris[3 * t] = ix[0];
            s->tris[3 * t + 1] = ix[k];
            s->tris[3 * t + 2] = ix[k + 1];
        }
    }
    return 0;
}

/* all polygons share one material: 1 */
static int bs_one_material(const scene_io_scene *io)
{
    for (size_t p = 1; p < io->num_polygons; p++)
        if (io->poly_material[p] != io->poly_material[0])
            return 0;
    return io->num_polygons > 0;
}

/* the fan triangles into gksrt as one indexed mesh of all vertices (bs_options.indexed) */
static int bs_add_mesh(const scene_io_scene *io, bs_scene *s, int base)
{
    if (bs_fan_triangles(io, s) != 0)
        return -1;
    const int mat = base + (int)io->poly_material[0];
    const int id = rt_scene_add_mesh(s->rt, s->nverts, s->verts_vrc, NULL, NULL, s->ntris, s->tris, mat, mat);
    if (id < 0)
        return -1;
    for (size_t t = 0; t < s->ntris; t++)
        s->tri_prim[t] = id;
    s->npolys = 1;
    s->indexed = 1;
    return 0;
}

/* polygons into gksrt (VRC3) and fan triangles for the peers */
static int bs_add_polygons(const scene_io_scene *io, bs_scene *s, int base, int indexed)
{
    if (indexed && bs_one_material(io))
        return bs_add_mesh(io, s, base);
    size_t maxn = 3;
    for (size_t p = 0; p < io->num_polygons; p++)
        if ((size_t)io->poly_nverts[p] > maxn)
            maxn = (size_t)io->poly_nverts[p];
    double *buf = bs_alloc(maxn, 3 * sizeof(double));
    if (!buf || bs_fan_triangles(io, s) != 0) {
        free(buf);
        return -1;
    }
    size_t t = 0;
    for (size_t p = 0; p < io->num_polygons; p++) {
        int n = io->poly_nverts[p];
        const uint32_t *ix = io->poly_verts + io->poly_start[p];
        for (int k = 0; k < n; k++)
            memcpy(buf + 3 * k, s->verts_vrc + 3 * (size_t)ix[k], 3 * sizeof(double));
        int mat = (int)io->poly_material[p];
        int id = rt_scene_add_polygon(s->rt, 1, &n, buf, base + mat, base + mat);
        if (id < 0) {
            free(buf);
            return -1;
        }
        for (int k = 1; k + 1 < n; k++, t++)
            s->tri_prim[t] = id;
    }
    s->npolys = io->num_polygons;
    free(buf);
    return 0;
}

int bs_load(const char *path, const bs_options *opt, bs_scene *s, char *err, size_t err_size)
{
    if (!s)
        return bs_fail(err, err_size, "no scene");
    memset(s, 0, sizeof *s);
    if (!path || !opt)
        return bs_fail(err, err_size, "no path or options");
    scene_io_scene io;
    char msg[512];
    int rc = scene_io_load(path, SCENE_IO_AUTO, NULL, &io, msg, sizeof msg);
    if (rc != SCENE_IO_OK)
        return bs_fail(err, err_size, "%s", msg);
    int size = opt->size;
    scene_io_view v = io.view;
    if (!v.present && scene_io_frame_view(&io, 40.0, size > 0 ? size : 512, size > 0 ? size : 512, &v) != SCENE_IO_OK) {
        scene_io_free(&io);
        return bs_fail(err, err_size, "%s: cannot frame a view", path);
    }
    if (size <= 0)
        size = v.res_x;
    memcpy(s->from, v.from, sizeof s->from);
    memcpy(s->at, v.at, sizeof s->at);
    memcpy(s->up, v.up, sizeof s->up);
    s->angle = v.angle;
    s->hither = v.hither;
    memcpy(s->background, io.background, sizeof s->background);
    if (!bs_lookat(v.from, v.at, v.up, s->world_to_vrc)) {
        scene_io_free(&io);
        return bs_fail(err, err_size, "%s: degenerate view", path);
    }
    s->nverts = io.num_vertices;
    s->verts_vrc = bs_alloc(io.num_vertices, 3 * sizeof(double));
    s->verts_world = bs_alloc(io.num_vertices, 3 * sizeof(double));
    s->rt = rt_scene_new();
    if (!s->verts_vrc || !s->verts_world || !s->rt) {
        scene_io_free(&io);
        return bs_fail(err, err_size, "out of memory");
    }
    memcpy(s->verts_world, io.vertices, io.num_vertices * 3 * sizeof(double));
    double far = 0.0;
    for (size_t i = 0; i < io.num_vertices; i++) {
        double *q = s->verts_vrc + 3 * i;
        bs_xform(s->world_to_vrc, io.vertices + 3 * i, q);
        far = fmax(far, sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
    }
    double dist = sqrt((v.at[0] - v.from[0]) * (v.at[0] - v.from[0]) + (v.at[1] - v.from[1]) * (v.at[1] - v.from[1]) +
                       (v.at[2] - v.from[2]) * (v.at[2] - v.from[2]));
    s->far_dist = 1.01 * far + 1e-6 * dist;
    int base = 0;
    if (bs_add_materials(&io, s, &base, opt) != 0 || bs_add_lights(&io, s, dist) != 0 ||
        bs_add_polygons(&io, s, base, opt->indexed) != 0) {
        scene_io_free(&io);
        return bs_fail(err, err_size, "%s: cannot build the gksrt scene", path);
    }
    scene_io_free(&io);
    double t0 = bs_process_cpu(), w0 = bs_wall();
    const rt_build_options one = {.brute_threshold = -1, .threads = 1}; /* the defaults, 1 thread */
    rc = rt_scene_commit(s->rt, opt->build ? opt->build : &one);
    s->commit_seconds = bs_process_cpu() - t0;
    s->commit_wall = bs_wall() - w0;
    if (rc != RT_OK)
        return bs_fail(err, err_size, "%s: commit failed (%d)", path, rc);
    double near = v.hither > 0.0 ? v.hither : 1e-3 * dist;
    if (!(near < s->far_dist))
        return bs_fail(err, err_size, "%s: scene lies in front of the near plane", path);
    rc = bs_camera(&s->cam, v.angle, near, s->far_dist, size, size);
    if (rc != RT_OK)
        return bs_fail(err, err_size, "%s: camera failed (%d)", path, rc);
    return 0;
}

void bs_free(bs_scene *s)
{
    rt_scene_free(s->rt);
    free(s->verts_vrc);
    free(s->verts_world);
    free(s->tris);
    free(s->tri_prim);
    memset(s, 0, sizeof *s);
}

int bs_camera(rt_camera *cam, double angle, double near, double far, int w, int h)
{
    double vm[4][4], box[6] = {0, 1, 0, 1, 0, 1};
    if (!(near > 0.0 && near < far))
        return RT_ERR_ARG;
    bs_view_matrix(angle, near, far, vm);
    return rt_camera_from_view(cam, vm, box, w, h);
}

void bs_spd_options(const bs_scene *s, rt_render_options *o)
{
    rt_render_options_default(o);
    o->corner_rays = 1;
    o->max_depth = 5;
    o->cutoff = 0.0;
    o->fresnel = RT_FRESNEL_EXACT;
    o->threads = 1;
    memcpy(o->background, s->background, sizeof o->background);
}
