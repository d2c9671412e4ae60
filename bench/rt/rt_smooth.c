/* SPDX-License-Identifier: MIT */
/*
 * rt_smooth -- interpolated vertex normals on a coarse sphere against the analytic sphere
 * (issue 19): the same lat-long mesh traced flat (geometric normals), with the naive use of
 * the interpolated normals (RT_SMOOTH_NAIVE: shadow rays from the hit point, the normal as
 * interpolated) and with the robust one (RT_SMOOTH_ROBUST: Hanika's shadow point, normal
 * adapted so that reflections stay above the surface), and the exact sphere evaluated pixel by
 * pixel (ray/sphere intersection, the same reflectance equation, no secondary rays: a convex
 * sphere alone neither shadows nor reflects itself).
 *   rt_smooth [-s SIZE] [-nu NU] [-nv NV] [-spec] [-reps R] [-o PREFIX] [-only flat|naive|robust]
 * Unit sphere, orthographic view along -z, an ambient light 0.1 and a directional light from
 * the upper right behind the viewer's side, so that the terminator crosses the picture.
 * -spec adds a specular term (ks 0.6, exponent 20) and with it mirror reflection rays.
 * Prints per mode: RMSE and largest channel error over the pixels every mode and the sphere
 * cover (clamped linear RGB), the RMSE in the terminator band (analytic N.L in [0, 0.25]),
 * and the CPU time of rt_render (one thread, best of R). -o writes PREFIX{flat,naive,robust,
 * exact}.ppm. -only renders that mode alone, once, and prints nothing (for instruction counts:
 * valgrind --tool=callgrind rt_smooth -only robust).
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

static void write_ppm(const char *path, const float *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (int i = 0; i < 3 * w * h; i++)
        fputc((int)lrint(255.0 * clamp01(rgb[i])), f);
    fclose(f);
}

int main(int argc, char **argv)
{
    int size = 256, nu = 16, nv = 8, spec = 0, reps = 3;
    const char *prefix = NULL;
    int only = -1;
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "-only") && a + 1 < argc) {
            a++;
            only = !strcmp(argv[a], "flat") ? 0 : !strcmp(argv[a], "naive") ? 1
                                                : !strcmp(argv[a], "robust") ? 2 : -2;
            if (only == -2)
                return 2;
            continue;
        }
        if (!strcmp(argv[a], "-s") && a + 1 < argc)
            size = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-nu") && a + 1 < argc)
            nu = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-nv") && a + 1 < argc)
            nv = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-reps") && a + 1 < argc)
            reps = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-spec"))
            spec = 1;
        else if (!strcmp(argv[a], "-o") && a + 1 < argc)
            prefix = argv[++a];
        else {
            fprintf(stderr, "usage: %s [-s SIZE] [-nu NU] [-nv NV] [-spec] [-reps R] [-o PREFIX]\n",
                    argv[0]);
            return 2;
        }
    }
    if (size < 8 || size > 4096 || nu < 3 || nv < 2 || nu > 4096 || nv > 4096 || reps < 1)
        return 2;
    rt_surface su;
    rt_surface_default(&su);
    su.ka = 1.0;
    su.kd = 0.9;
    su.diffuse[0] = 0.9, su.diffuse[1] = 0.75, su.diffuse[2] = 0.5;
    if (spec) {
        su.refl_eq = RT_REFL_SPECULAR;
        su.ks = 0.6;
        su.spec_exp = 20.0;
    }
    const double ldir[3] = {-0.75, -0.35, 0.3}; /* travels towards -x, -y, +z: lit from +x, +y,
                                                   slightly from behind */
    const rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.1, 0.1, 0.1}};
    const rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1},
                         .direction = {ldir[0], ldir[1], ldir[2]}};
    rt_scene *sc[2];
    for (int k = 0; k < 2; k++) {
        sc[k] = rt_scene_new();
        int s = rt_scene_add_surface(sc[k], &su);
        const double c[3] = {0, 0, 0};
        if (!sc[k] || s < 0 || rtu_add_sphere_data(sc[k], c, 1.0, nu, nv, s, k) != 0 ||
            rt_scene_add_light(sc[k], &amb) < 0 || rt_scene_add_light(sc[k], &dl) < 0 ||
            rt_scene_commit(sc[k], NULL) != RT_OK) {
            fprintf(stderr, "rt_smooth: scene failed\n");
            return 1;
        }
    }
    rtu_view vw = {.win = {-1.2, 1.2, -1.2, 1.2}, .prp = {0, 0, 10}, .vpd = 0, .bpd = -5,
                   .fpd = 5, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    double m[4][4];
    rtu_view_matrix(&vw, m);
    rt_camera cam;
    if (rt_camera_from_view(&cam, m, vw.vp, size, size) != RT_OK)
        return 1;
    const size_t np = (size_t)size * size;
    float *img[4];
    unsigned short *cov[3];
    for (int k = 0; k < 4; k++)
        img[k] = calloc(3 * np, sizeof(float));
    for (int k = 0; k < 3; k++)
        cov[k] = calloc(np, sizeof(unsigned short));
    unsigned char *exact_hit = calloc(np, 1);
    double *exact_nl = calloc(np, sizeof(double));
    if (!img[0] || !img[1] || !img[2] || !img[3] || !cov[0] || !cov[1] || !cov[2] || !exact_hit ||
        !exact_nl)
        return 1;
    static const char *const names[3] = {"flat", "naive", "robust"};
    static const int modes[3] = {RT_SMOOTH_FLAT, RT_SMOOTH_NAIVE, RT_SMOOTH_ROBUST};
    double secs[3];
    for (int k = 0; k < 3; k++) {
        if (only >= 0 && k != only)
            continue;
        rt_render_options o;
        rtu_options_plain(&o);
        o.threads = 1;
        o.smooth = modes[k];
        secs[k] = INFINITY;
        for (int r = 0; r < reps; r++) {
            double t0 = cpu_now();
            if (rt_render_cover(sc[k == 0 ? 0 : 1], &cam, &o, img[k], cov[k], NULL) != RT_OK)
                return 1;
            secs[k] = fmin(secs[k], cpu_now() - t0);
        }
    }
    if (only >= 0)
        return 0;
    /* the exact sphere */
    double L[3] = {-ldir[0], -ldir[1], -ldir[2]};
    double ll = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    for (int c = 0; c < 3; c++)
        L[c] /= ll;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++) {
            rt_ray ray;
            if (rt_camera_ray(&cam, x + 0.5, y + 0.5, &ray) != RT_OK)
                continue;
            const double *o = ray.org, *d = ray.dir;
            double b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
            double cc = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - 1.0;
            double disc = b * b - cc;
            if (disc < 0.0)
                continue;
            double t = -b - sqrt(disc);
            double N[3];
            for (int c = 0; c < 3; c++)
                N[c] = o[c] + t * d[c];
            double nl = N[0] * L[0] + N[1] * L[1] + N[2] * L[2];
            const size_t p = (size_t)y * size + x;
            exact_hit[p] = 1;
            exact_nl[p] = nl;
            double sp = 0.0;
            if (spec && nl > 0.0) {
                double R[3];
                for (int c = 0; c < 3; c++)
                    R[c] = 2.0 * nl * N[c] - L[c];
                double re = -(R[0] * d[0] + R[1] * d[1] + R[2] * d[2]);
                if (re > 0.0)
                    sp = su.ks * pow(re, su.spec_exp);
            }
            for (int c = 0; c < 3; c++)
                img[3][3 * p + c] = (float)(su.ka * su.diffuse[c] * amb.color[c] +
                                            (nl > 0.0 ? su.kd * su.diffuse[c] * nl + sp : 0.0));
        }
    printf("# rt_smooth: unit sphere, %d x %d lat-long quads (%d triangles), %d x %d pixels, %s\n",
           nu, nv, 2 * nu * (nv - 1), size, size, spec ? "diffuse + specular + mirror rays"
                                                        : "Lambert (ambient + diffuse)");
    printf("%-7s %10s %10s %14s %10s\n", "mode", "rmse", "max_err", "rmse_terminator", "cpu_s");
    for (int k = 0; k < 3; k++) {
        double se = 0.0, st = 0.0, mx = 0.0;
        size_t n = 0, nt = 0;
        for (size_t p = 0; p < np; p++) {
            if (!exact_hit[p] || cov[0][p] == 0 || cov[1][p] == 0 || cov[2][p] == 0)
                continue;
            const int band = exact_nl[p] >= 0.0 && exact_nl[p] <= 0.25;
            for (int c = 0; c < 3; c++) {
                double e = clamp01(img[k][3 * p + c]) - clamp01(img[3][3 * p + c]);
                se += e * e;
                mx = fmax(mx, fabs(e));
                n++;
                if (band) {
                    st += e * e;
                    nt++;
                }
            }
        }
        printf("%-7s %10.5f %10.5f %14.5f %10.4f\n", names[k], sqrt(se / (double)(n ? n : 1)), mx,
               sqrt(st / (double)(nt ? nt : 1)), secs[k]);
    }
    if (prefix) {
        static const char *const files[4] = {"flat", "naive", "robust", "exact"};
        for (int k = 0; k < 4; k++) {
            char path[1024];
            snprintf(path, sizeof path, "%s%s.ppm", prefix, files[k]);
            write_ppm(path, img[k], size, size);
        }
    }
    for (int k = 0; k < 4; k++)
        free(img[k]);
    for (int k = 0; k < 3; k++)
        free(cov[k]);
    free(exact_hit);
    free(exact_nl);
    rt_scene_free(sc[0]);
    rt_scene_free(sc[1]);
    return 0;
}
