/* SPDX-License-Identifier: MIT */
/*
 * tess_error -- "model only what a scene needs", measured (issue 19): tessellation level x
 * interior shading against the error of the picture.
 *   tess_error [-s SIZE] [-ref N] [-reps R] [-csv FILE] [-o DIR]
 * Two surfaces, each as N x N quads (two triangles each) for N = 8, 16, ..., 256, traced flat
 * (geometric normals) and interpolated (exact vertex normals, RT_SMOOTH_ROBUST):
 *   sphere   the unit sphere as N x N lat-long quads (N around, N from pole to pole),
 *            compared with the exact sphere evaluated ray by ray (ray/sphere intersection,
 *            the same reflectance equation; alone, a convex sphere neither shadows nor
 *            reflects itself);
 *   surface  the surface example's function z = 0.8 cos(2.5 r) exp(-r^2/4) over [-2,2]^2
 *            (examples/c/surface.c), normals from its analytic gradient, compared with the
 *            same function at REF x REF quads (default 1024), interpolated;
 * both ambient 0.3 + one light, diffuse 0.8 + specular 0.3 (exponent 30), black background,
 * SIZE x SIZE pixels (default 256) with rt_render_options_default (corner rays; their mirror
 * rays see only the background or the surface itself), one thread. Time: process CPU of
 * commit (grid build) + rt_render, best of R (default 3). Error: RMSE over all pixels and
 * channels of the clamped linear RGB, PSNR, largest channel error, and the RMSE over the
 * pixels both pictures cover fully (the shading away from the outline). Prints a table and the
 * coarsest interpolated mesh whose RMSE is below the finest flat one's; -csv appends rows in
 * the columns of speed_error's CSV (scene "sphere-tess"/"surface-tess", label "8f"/"8i",
 * ssim empty); -o writes DIR/<scene>_<N><f|i>.ppm and DIR/<scene>_ref.ppm.
 */
#include "gksrt.h"
#include "rt_testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double clamp01(double v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

static const double PI = 3.14159265358979323846;

/* the scene's surface, light and camera */
typedef struct scene_def {
    const char *name;
    int sphere;
    double vo[4][4];        /* world -> VRC3 */
    rtu_view view;
    rt_surface su;
    rt_light light[2];
} scene_def;

/* z and gradient of the surface example's function */
static double surf_f(double x, double y, double g[2])
{
    double r2 = x * x + y * y, r = sqrt(r2);
    double s = r > 0.0 ? -2.5 * sin(2.5 * r) / r : -6.25;
    double dr = 0.8 * exp(-0.25 * r2) * (s - 0.5 * cos(2.5 * r));
    g[0] = dr * x;
    g[1] = dr * y;
    return 0.8 * cos(2.5 * r) * exp(-0.25 * r2);
}

/* point (u, v) in [0,1]^2 of the surface: position and unit normal in world coordinates */
static void surf_point(const scene_def *d, double u, double v, double p[3], double n[3])
{
    if (d->sphere) {
        double th = PI * v, ph = 2 * PI * u;
        n[0] = sin(th) * cos(ph);
        n[1] = sin(th) * sin(ph);
        n[2] = cos(th);
        memcpy(p, n, 3 * sizeof *p);
        return;
    }
    double g[2];
    p[0] = -2 + 4 * u;
    p[1] = -2 + 4 * v;
    p[2] = surf_f(p[0], p[1], g);
    double l = sqrt(g[0] * g[0] + g[1] * g[1] + 1);
    n[0] = -g[0] / l;
    n[1] = -g[1] / l;
    n[2] = 1 / l;
}

static void to_vrc(const double m[4][4], const double p[3], double o[3], int dir)
{
    for (int i = 0; i < 3; i++)
        o[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + (dir ? 0 : m[i][3]);
}

/* the N x N mesh in VRC3, vertex normals when normals != 0 */
static rt_scene *build(const scene_def *d, int N, int normals)
{
    rt_scene *sc = rt_scene_new();
    if (!sc)
        return NULL;
    int s = rt_scene_add_surface(sc, &d->su);
    if (s < 0 || rt_scene_add_light(sc, &d->light[0]) < 0 ||
        rt_scene_add_light(sc, &d->light[1]) < 0) {
        rt_scene_free(sc);
        return NULL;
    }
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double P[4][3], Q[4][3];
            for (int k = 0; k < 4; k++) {
                double p[3], n[3];
                int ii = i + (k == 1 || k == 2), jj = j + (k >= 2);
                surf_point(d, (double)(d->sphere ? ii % N : ii) / N, (double)jj / N, p, n);
                to_vrc(d->vo, p, P[k], 0);
                to_vrc(d->vo, n, Q[k], 1);
            }
            for (int t = 0; t < 2; t++) {
                if (d->sphere && ((t == 0 && j == 0) || (t == 1 && j == N - 1)))
                    continue; /* none at a pole */
                const int a = 0, b = 1 + t, c = 2 + t, three = 3;
                double v[9], n[9];
                for (int k = 0; k < 3; k++) {
                    v[k] = P[a][k], v[3 + k] = P[b][k], v[6 + k] = P[c][k];
                    n[k] = Q[a][k], n[3 + k] = Q[b][k], n[6 + k] = Q[c][k];
                }
                const rt_vertex_data vd = {n, NULL};
                if (rt_scene_add_polygon_data(sc, 1, &three, v, normals ? &vd : NULL, s, s) < 0) {
                    rt_scene_free(sc);
                    return NULL;
                }
            }
        }
    return sc;
}

/* the exact sphere along one ray (VRC3; the sphere's centre is the VRC3 image of 0) */
static int exact_sphere(const scene_def *d, const rt_ray *r, double out[3])
{
    double c[3], o[3];
    const double zero[3] = {0, 0, 0};
    to_vrc(d->vo, zero, c, 0);
    for (int k = 0; k < 3; k++)
        o[k] = r->org[k] - c[k];
    double b = o[0] * r->dir[0] + o[1] * r->dir[1] + o[2] * r->dir[2];
    double cc = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - 1.0;
    out[0] = out[1] = out[2] = 0.0;
    if (b * b - cc < 0.0)
        return 0;
    double t = -b - sqrt(b * b - cc);
    if (t < r->tmin || t > r->tmax)
        return 0;
    double N[3], P[3];
    for (int k = 0; k < 3; k++) {
        N[k] = o[k] + t * r->dir[k];
        P[k] = c[k] + N[k];
    }
    const rt_surface *s = &d->su;
    const rt_light *l = &d->light[1];
    double L[3];
    for (int k = 0; k < 3; k++)
        L[k] = l->position[k] - P[k];
    double dl = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    for (int k = 0; k < 3; k++)
        L[k] /= dl;
    double nl = N[0] * L[0] + N[1] * L[1] + N[2] * L[2], sp = 0.0;
    if (nl > 0.0) {
        double R[3];
        for (int k = 0; k < 3; k++)
            R[k] = 2.0 * nl * N[k] - L[k];
        double re = -(R[0] * r->dir[0] + R[1] * r->dir[1] + R[2] * r->dir[2]);
        if (re > 0.0)
            sp = s->ks * pow(re, s->spec_exp);
    }
    double att = 1.0 / (l->c1 + l->c2 * dl);
    for (int k = 0; k < 3; k++)
        out[k] = s->ka * s->diffuse[k] * d->light[0].color[k] +
                 (nl > 0.0 ? att * l->color[k] * (s->kd * s->diffuse[k] * nl + sp * s->specular[k])
                           : 0.0);
    return 1;
}

/* the exact sphere with the renderer's corner rays: each pixel the mean of its 4 corners */
static void exact_image(const scene_def *d, const rt_camera *cam, float *rgb,
                        unsigned short *cover)
{
    const int w = cam->width, h = cam->height;
    double *cr = calloc((size_t)(w + 1) * (h + 1) * 3, sizeof *cr);
    unsigned char *hit = calloc((size_t)(w + 1) * (h + 1), 1);
    if (!cr || !hit)
        exit(1);
    for (int y = 0; y <= h; y++)
        for (int x = 0; x <= w; x++) {
            rt_ray r;
            const size_t c = (size_t)y * (w + 1) + x;
            if (rt_camera_ray(cam, x, y, &r) == RT_OK)
                hit[c] = (unsigned char)exact_sphere(d, &r, cr + 3 * c);
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            for (int k = 0; k < 3; k++) {
                const size_t a = (size_t)y * (w + 1) + x, b = a + (size_t)(w + 1);
                cover[(size_t)y * w + x] = (unsigned short)(hit[a] + hit[a + 1] + hit[b] + hit[b + 1]);
                rgb[3 * ((size_t)y * w + x) + k] =
                    (float)(0.25 * (cr[3 * a + k] + cr[3 * (a + 1) + k] + cr[3 * b + k] +
                                    cr[3 * (b + 1) + k]));
            }
    free(cr);
    free(hit);
}

static void write_ppm(const char *path, const float *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (size_t i = 0; i < 3 * (size_t)w * h; i++)
        fputc((int)lrint(255.0 * clamp01(rgb[i])), f);
    fclose(f);
}

/* time (commit + render, best of reps) and picture of the N x N mesh */
static double run(const scene_def *d, const rt_camera *cam, int N, int normals, int reps,
                  float *rgb, unsigned short *cover, rt_stats *st)
{
    double best = INFINITY;
    for (int r = 0; r < reps; r++) {
        rt_scene *sc = build(d, N, normals);
        if (!sc) {
            fprintf(stderr, "tess_error: out of memory at %d x %d\n", N, N);
            exit(1);
        }
        rt_render_options o;
        rt_render_options_default(&o);
        o.threads = 1;
        double t0 = cpu_now();
        if (rt_scene_commit(sc, NULL) != RT_OK || rt_render_cover(sc, cam, &o, rgb, cover, st) != RT_OK) {
            fprintf(stderr, "tess_error: render failed\n");
            exit(1);
        }
        best = fmin(best, cpu_now() - t0);
        rt_scene_free(sc);
    }
    return best;
}

/* RMSE and largest error over all n pixels, and the RMSE over the pixels that both pictures
   cover fully (all 4 corner rays hit: away from the outline) */
static void errors(const float *a, const float *ref, const unsigned short *ca,
                   const unsigned short *cr, size_t n, double *rmse, double *mx, double *inner)
{
    double se = 0.0, si = 0.0;
    size_t ni = 0;
    *mx = 0.0;
    for (size_t p = 0; p < n; p++)
        for (int k = 0; k < 3; k++) {
            double e = clamp01(a[3 * p + k]) - clamp01(ref[3 * p + k]);
            se += e * e;
            *mx = fmax(*mx, fabs(e));
            if (ca[p] == 4 && cr[p] == 4) {
                si += e * e;
                ni++;
            }
        }
    *rmse = sqrt(se / (double)(3 * n));
    *inner = sqrt(si / (double)(ni ? ni : 1));
}

int main(int argc, char **argv)
{
    int size = 256, refn = 1024, reps = 3;
    const char *csv = NULL, *dir = NULL;
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "-s") && a + 1 < argc)
            size = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-ref") && a + 1 < argc)
            refn = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-reps") && a + 1 < argc)
            reps = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-csv") && a + 1 < argc)
            csv = argv[++a];
        else if (!strcmp(argv[a], "-o") && a + 1 < argc)
            dir = argv[++a];
        else {
            fprintf(stderr, "usage: %s [-s SIZE] [-ref N] [-reps R] [-csv FILE] [-o DIR]\n",
                    argv[0]);
            return 2;
        }
    }
    if (size < 16 || size > 4096 || refn < 256 || refn > 4096 || reps < 1)
        return 2;
    FILE *out = NULL;
    if (csv && !(out = fopen(csv, "a"))) {
        fprintf(stderr, "tess_error: cannot append to %s\n", csv);
        return 1;
    }
    const size_t np = 3 * (size_t)size * size;
    float *ref = malloc(np * sizeof *ref), *img = malloc(np * sizeof *img);
    unsigned short *cref = malloc(np / 3 * sizeof *cref), *cimg = malloc(np / 3 * sizeof *cimg);
    if (!ref || !img || !cref || !cimg)
        return 1;
    for (int which = 0; which < 2; which++) {
        scene_def d;
        memset(&d, 0, sizeof d);
        d.sphere = which == 0;
        d.name = d.sphere ? "sphere-tess" : "surface-tess";
        /* camera: the sphere seen from (2, -2.5, 1.5) * 1.6, the surface as in the example
           (direction (1, -1.4, 1.1), z up) */
        const double from_s[3] = {3.2, -4.0, 2.4}, from_f[3] = {4.0, -5.6, 4.4};
        const double at[3] = {0, 0, d.sphere ? 0.0 : -0.2}, up[3] = {0, 0, 1};
        rtu_lookat(d.sphere ? from_s : from_f, at, up, d.vo);
        rtu_mesh m;
        memset(&m, 0, sizeof m);
        m.angle = d.sphere ? 32.0 : 44.0;
        m.hither = 0.1;
        double bb[6] = {-12, -12, -12, 12, 12, 12};
        rtu_nff_view(&m, bb, &d.view);
        rt_surface_default(&d.su);
        d.su.refl_eq = RT_REFL_SPECULAR;
        d.su.ka = 0.7;
        d.su.kd = 0.8;
        d.su.ks = 0.3;
        d.su.spec_exp = 30.0;
        d.su.diffuse[0] = 0.55, d.su.diffuse[1] = 0.7, d.su.diffuse[2] = 0.85;
        d.light[0] = (rt_light){.type = RT_LIGHT_AMBIENT, .color = {0.3, 0.3, 0.3}};
        const double lw[3] = {1.5, 0.5, 7.0};
        d.light[1] = (rt_light){.type = RT_LIGHT_POSITIONAL, .color = {1, 1, 1}, .c1 = 1.0};
        to_vrc(d.vo, lw, d.light[1].position, 0);
        double vm[4][4];
        rtu_view_matrix(&d.view, vm);
        rt_camera cam;
        if (rt_camera_from_view(&cam, vm, d.view.vp, size, size) != RT_OK)
            return 1;
        rt_stats st;
        double tref = 0.0;
        if (d.sphere)
            exact_image(&d, &cam, ref, cref);
        else
            tref = run(&d, &cam, refn, 1, 1, ref, cref, &st);
        char path[1024];
        if (dir) {
            snprintf(path, sizeof path, "%s/%s_ref.ppm", dir, d.name);
            write_ppm(path, ref, size, size);
        }
        if (d.sphere)
            printf("# %s: %d x %d pixels, reference the exact sphere (corner rays)\n", d.name,
                   size, size);
        else
            printf("# %s: %d x %d pixels, reference %d x %d quads interpolated (%.2f s)\n",
                   d.name, size, size, refn, refn, tref);
        printf("%-6s %-13s %10s %10s %9s %9s %11s %10s\n", "quads", "shading", "time_s", "rmse",
               "psnr_db", "max_err", "rmse_inside", "triangles");
        double flat_finest = INFINITY, flat_finest_in = INFINITY;
        int coarsest = 0, coarsest_in = 0;
        double cr_rmse = 0.0, cr_time = 0.0, ff_time = 0.0;
        for (int shade = 0; shade < 2; shade++)
            for (int N = 8; N <= 256; N *= 2) {
                double t = run(&d, &cam, N, shade, reps, img, cimg, &st), rmse, mx, inner;
                errors(img, ref, cimg, cref, np / 3, &rmse, &mx, &inner);
                double psnr = rmse > 0.0 ? 20.0 * log10(1.0 / rmse) : INFINITY;
                printf("%3dx%-3d %-13s %10.4f %10.3e %9.2f %9.4f %11.3e %10llu\n", N, N,
                       shade ? "interpolated" : "flat", t, rmse, psnr, mx, inner,
                       (unsigned long long)st.prims);
                if (!shade && N == 256) {
                    flat_finest = rmse;
                    flat_finest_in = inner;
                    ff_time = t;
                }
                if (shade && !coarsest_in && inner < flat_finest_in)
                    coarsest_in = N;
                if (shade && !coarsest && rmse < flat_finest) {
                    coarsest = N;
                    cr_rmse = rmse;
                    cr_time = t;
                }
                if (dir) {
                    snprintf(path, sizeof path, "%s/%s_%d%c.ppm", dir, d.name, N, shade ? 'i' : 'f');
                    write_ppm(path, img, size, size);
                }
                if (out)
                    fprintf(out,
                            "%s,\"%dx%d quads %s\",1,0,5,0.01,exact,0.25,1,%.6f,%llu,%llu,%.6e,%.4f,"
                            ",%.6f,0,0,0,%d%c,0\n",
                            d.name, N, N, shade ? "interpolated" : "flat", t,
                            (unsigned long long)st.eye_rays,
                            (unsigned long long)(st.eye_rays + st.shadow_rays +
                                                 st.reflection_rays + st.refraction_rays),
                            rmse, psnr, mx, N, shade ? 'i' : 'f');
            }
        if (coarsest)
            printf("# %s: the coarsest interpolated mesh beating the finest flat one (256x256, "
                   "RMSE %.3e, %.4f s): %dx%d, RMSE %.3e, %.4f s\n",
                   d.name, flat_finest, ff_time, coarsest, coarsest, cr_rmse, cr_time);
        else
            printf("# %s: no interpolated mesh beats the finest flat one\n", d.name);
        if (coarsest_in)
            printf("# %s: inside the outline (rmse_inside %.3e for 256x256 flat): %dx%d\n",
                   d.name, flat_finest_in, coarsest_in, coarsest_in);
    }
    if (out)
        fclose(out);
    free(ref);
    free(img);
    free(cref);
    free(cimg);
    return 0;
}
