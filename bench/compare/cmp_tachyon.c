/* SPDX-License-Identifier: MIT */
/*
 * cmp_tachyon -- SPD scenes, ours vs Tachyon, one thread, same run.
 *   cmp_tachyon TACHYON_EXE OUTDIR scene.nff...
 * Tachyon reads NFF itself, but its reader (nffparse.c of Tachyon 0.99) is not usable for
 * the SPD: every "l" becomes a VISIBLE sphere of radius 1 (gears: the eye sits inside one, the
 * frame is white), the view angle is ignored (zoom 1 = 90 degrees), concave polygons are
 * fanned. So the scene is exported to Tachyon's own scene format (OUTDIR/NAME.dat): camera
 * with zoom = 0.5/tan(angle/2) (Tachyon: image plane height 1/zoom at distance 1), lights of radius 0 with intensity 1/sqrt(n) as ours, textures
 * AMBIENT 0 DIFFUSE Kd SPECULAR Ks (mirror) PHONG PLASTIC Ks PHONG_SIZE Shine OPACITY 1-T,
 * polygons ear-clipped into triangles (pp patches into smooth STRI). Tachyon has no
 * refraction (transmission goes straight through), so on gears and mount it traces fewer
 * and cheaper rays than the SPD procedure asks.
 * Tachyon: "tachyon NAME.dat -numthreads 1 -res 513 513 -raydepth 5", 513x513 pixel-centre
 * eye rays; its self-reported preprocessing (grid build) and ray tracing times, wall clock.
 * Ours: the SPD procedure (512x512 pixels from 513x513 corner rays, depth 5, no cut-off,
 * exact Fresnel), 1 thread: rt_scene_commit + rt_render, wall clock.
 * Each measured REPS times (default 3; "-reps N" first, 1..100, for a busy machine),
 * interleaved (Tachyon, ours, Tachyon, ours, ...); best of REPS.
 */
#include "bench_scene.h"
#include "scene_io.h"

#include <math.h>
#include <stdio.h>
#include <sys/resource.h>
#include <stdlib.h>
#include <string.h>

enum { REPS_DEFAULT = 3, REPS_MAX = 100 };

/* ---------------------------------------------------------------- export */

/* Ear clipping of a simple (possibly concave) planar polygon given by 2D points q[2*i];
 * writes n-2 triangles as local vertex indices into tri; always produces n-2 triangles
 * (when no ear is found, e.g. for self-intersecting outlines, the first convex-or-not vertex
 * is clipped). */
static void ear_clip(const double *q, int n, int *V, int *tri)
{
    double area = 0.0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        area += q[2 * i] * q[2 * j + 1] - q[2 * j] * q[2 * i + 1];
    }
    for (int i = 0; i < n; i++)
        V[i] = area >= 0.0 ? i : n - 1 - i;
    int m = n, nt = 0, guard = 0;
    int i = 0;
    while (m > 3) {
        int a = V[(i + m - 1) % m], b = V[i % m], c = V[(i + 1) % m];
        double ax = q[2 * a], ay = q[2 * a + 1], bx = q[2 * b], by = q[2 * b + 1], cx = q[2 * c], cy = q[2 * c + 1];
        double cr = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        int ear = cr > 0.0 || guard > m;
        for (int k = 0; ear && guard <= m && k < m; k++) {
            int p = V[k];
            if (p == a || p == b || p == c)
                continue;
            double px = q[2 * p], py = q[2 * p + 1];
            if ((px == ax && py == ay) || (px == bx && py == by) || (px == cx && py == cy))
                continue;
            double d1 = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
            double d2 = (cx - bx) * (py - by) - (cy - by) * (px - bx);
            double d3 = (ax - cx) * (py - cy) - (ay - cy) * (px - cx);
            if (d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0)
                ear = 0;
        }
        if (!ear) {
            i = (i + 1) % m;
            guard++;
            continue;
        }
        tri[3 * nt] = a;
        tri[3 * nt + 1] = b;
        tri[3 * nt + 2] = c;
        nt++;
        for (int k = i % m; k + 1 < m; k++)
            V[k] = V[k + 1];
        m--;
        i = i % m;
        guard = 0;
    }
    tri[3 * nt] = V[0];
    tri[3 * nt + 1] = V[1];
    tri[3 * nt + 2] = V[2];
}

/* Tachyon's camera is left-handed: every point and direction is written mirrored in x, so
 * that its picture is not the mirror image of ours */
static void put_vec(FILE *f, const char *key, const double *v)
{
    fprintf(f, " %s %.9g %.9g %.9g", key, -v[0], v[1], v[2]);
}

/* writes the scene in Tachyon's format; 0 on success */
static int write_tachyon(const char *nff, const char *dat)
{
    scene_io_scene io;
    char err[512];
    if (scene_io_load(nff, SCENE_IO_AUTO, NULL, &io, err, sizeof err) != SCENE_IO_OK) {
        fprintf(stderr, "%s\n", err);
        return -1;
    }
    FILE *f = fopen(dat, "w");
    int maxn = 3;
    for (size_t p = 0; p < io.num_polygons; p++)
        maxn = io.poly_nverts[p] > maxn ? io.poly_nverts[p] : maxn;
    double *q = bs_alloc((size_t)maxn, 2 * sizeof(double));
    int *V = bs_alloc((size_t)maxn, sizeof(int)), *tri = bs_alloc((size_t)maxn, 3 * sizeof(int));
    if (!f || !q || !V || !tri || !io.view.present) {
        if (f)
            fclose(f);
        free(q);
        free(V);
        free(tri);
        scene_io_free(&io);
        return -1;
    }
    const scene_io_view *v = &io.view;
    double dir[3] = {v->at[0] - v->from[0], v->at[1] - v->from[1], v->at[2] - v->from[2]};
    fprintf(f, "BEGIN_SCENE\n RESOLUTION 513 513\nCAMERA\n ZOOM %.9g\n ASPECTRATIO 1.0\n ANTIALIASING 0\n"
               " RAYDEPTH 5\n",
            0.5 / tan(0.5 * v->angle * 3.14159265358979323846 / 180.0));
    put_vec(f, "CENTER", v->from);
    put_vec(f, "\n VIEWDIR", dir);
    put_vec(f, "\n UPDIR", v->up);
    fprintf(f, "\nEND_CAMERA\nBACKGROUND %.9g %.9g %.9g\n", io.background[0], io.background[1], io.background[2]);
    double in = io.num_lights ? 1.0 / sqrt((double)io.num_lights) : 1.0;
    for (size_t l = 0; l < io.num_lights; l++) {
        fprintf(f, "LIGHT");
        put_vec(f, "CENTER", io.lights[l].pos);
        fprintf(f, " RAD 0.0 COLOR %.9g %.9g %.9g\n", in * io.lights[l].color[0], in * io.lights[l].color[1],
                in * io.lights[l].color[2]);
    }
    for (size_t m = 0; m < io.num_materials; m++) {
        const scene_io_material *mt = &io.materials[m];
        double t = mt->t > 1.0 ? 1.0 : mt->t;
        fprintf(f, "TEXDEF t%zu AMBIENT 0 DIFFUSE %.9g SPECULAR %.9g OPACITY %.9g PHONG PLASTIC %.9g PHONG_SIZE %.9g "
                   "COLOR %.9g %.9g %.9g TEXFUNC 0\n",
                m, mt->kd, mt->ks, 1.0 - t, mt->ks, mt->shine > 0.0 ? mt->shine : 1.0, mt->color[0], mt->color[1],
                mt->color[2]);
    }
    for (size_t p = 0; p < io.num_polygons; p++) {
        int n = io.poly_nverts[p];
        const uint32_t *ix = io.poly_verts + io.poly_start[p];
        double nn[3] = {0, 0, 0};
        for (int k = 0; k < n; k++) { /* Newell normal */
            const double *a = io.vertices + 3 * (size_t)ix[k], *b = io.vertices + 3 * (size_t)ix[(k + 1) % n];
            nn[0] += (a[1] - b[1]) * (a[2] + b[2]);
            nn[1] += (a[2] - b[2]) * (a[0] + b[0]);
            nn[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
        int ax = fabs(nn[0]) > fabs(nn[1]) ? (fabs(nn[0]) > fabs(nn[2]) ? 0 : 2) : (fabs(nn[1]) > fabs(nn[2]) ? 1 : 2);
        int u = (ax + 1) % 3, w = (ax + 2) % 3;
        for (int k = 0; k < n; k++) {
            q[2 * k] = io.vertices[3 * (size_t)ix[k] + u];
            q[2 * k + 1] = io.vertices[3 * (size_t)ix[k] + w];
        }
        if (n == 3) {
            tri[0] = 0, tri[1] = 1, tri[2] = 2;
        } else {
            ear_clip(q, n, V, tri);
        }
        int smooth = io.normals != NULL;
        for (int k = 0; k < n - 2; k++) {
            fprintf(f, smooth ? "STRI" : "TRI");
            static const int order[3] = {0, 2, 1}; /* the mirror reverses the winding: undo */
            for (int c = 0; c < 3; c++) {
                char key[4] = {'V', (char)('0' + c), 0, 0};
                put_vec(f, key, io.vertices + 3 * (size_t)ix[tri[3 * k + order[c]]]);
            }
            for (int c = 0; smooth && c < 3; c++) {
                char key[4] = {'N', (char)('0' + c), 0, 0};
                const double *nv = io.normals + 3 * (size_t)ix[tri[3 * k + order[c]]];
                put_vec(f, key, nv[0] == 0.0 && nv[1] == 0.0 && nv[2] == 0.0 ? nn : nv);
            }
            fprintf(f, " t%u\n", (unsigned)io.poly_material[p]);
        }
    }
    fprintf(f, "END_SCENE\n");
    int rc = fclose(f);
    free(q);
    free(V);
    free(tri);
    scene_io_free(&io);
    return rc == 0 ? 0 : -1;
}

/* ---------------------------------------------------------------- runs */

typedef struct timing {
    double build, trace; /* wall seconds: grid build, tracing */
    double cpu;          /* CPU seconds of the whole job: parse + build + trace (+ Tachyon's image) */
} timing;

static double children_cpu(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_CHILDREN, &ru) != 0)
        return 0.0;
    return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
           1e-6 * (double)ru.ru_stime.tv_usec;
}

/* runs Tachyon once; 0 and its self-reported preprocessing and tracing seconds (wall) and
 * the CPU time of the process (from the children's rusage) on success */
static int run_tachyon(const char *exe, const char *scene, const char *out, timing *tm)
{
    if (strchr(exe, '\'') || strchr(scene, '\'') || strchr(out, '\''))
        return -1;
    char cmd[4096];
    int n = snprintf(cmd, sizeof cmd,
                     "exec '%s' '%s' -numthreads 1 -res 513 513 -raydepth 5 -format PPM -o '%s' 2>&1", exe,
                     scene, out);
    if (n < 0 || (size_t)n >= sizeof cmd)
        return -1;
    double c0 = children_cpu();
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    char line[1024];
    tm->build = tm->trace = -1.0;
    while (fgets(line, sizeof line, p)) {
        const char *q;
        if ((q = strstr(line, "Preprocessing Time:")))
            tm->build = atof(q + strlen("Preprocessing Time:"));
        else if ((q = strstr(line, "Ray Tracing Time:")))
            tm->trace = atof(q + strlen("Ray Tracing Time:"));
    }
    int st = pclose(p);
    tm->cpu = children_cpu() - c0;
    return st == 0 && tm->build >= 0.0 && tm->trace >= 0.0 ? 0 : -1;
}

static void write_ppm(const char *path, const float *rgb, int w, int h)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, "P6\n%d %d\n255\n", w, h);
    for (size_t k = 0; k < (size_t)w * h * 3; k++) {
        float x = rgb[k];
        fputc(x <= 0.0f ? 0 : x >= 1.0f ? 255 : (int)(x * 255.0f + 0.5f), f);
    }
    fclose(f);
}

/* ours once: commit and render (wall), load + commit + render (process CPU); 0 on success */
static int run_ours(const char *scene, const char *ppm, timing *tm, rt_stats *st)
{
    bs_scene s;
    char err[512];
    bs_options opt = {.size = 512};
    double c0 = bs_process_cpu();
    if (bs_load(scene, &opt, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        bs_free(&s);
        return -1;
    }
    rt_render_options o;
    bs_spd_options(&s, &o);
    float *rgb = bs_alloc((size_t)512 * 512, 3 * sizeof(float));
    if (!rgb) {
        bs_free(&s);
        return -1;
    }
    double t0 = bs_wall();
    int rc = rt_render(s.rt, &s.cam, &o, rgb, st);
    tm->trace = bs_wall() - t0;
    tm->cpu = bs_process_cpu() - c0;
    tm->build = s.commit_wall;
    if (rc == RT_OK && ppm)
        write_ppm(ppm, rgb, 512, 512);
    free(rgb);
    bs_free(&s);
    return rc == RT_OK ? 0 : -1;
}

static void keep_best(timing *best, const timing *t)
{
    best->build = fmin(best->build, t->build);
    best->trace = fmin(best->trace, t->trace);
    best->cpu = fmin(best->cpu, t->cpu);
}

int main(int argc, char **argv)
{
    int reps = REPS_DEFAULT;
    if (argc > 2 && strcmp(argv[1], "-reps") == 0) {
        reps = atoi(argv[2]);
        argc -= 2;
        argv += 2;
    }
    if (argc < 4 || reps < 1 || reps > REPS_MAX) {
        fprintf(stderr, "usage: cmp_tachyon [-reps N] TACHYON_EXE OUTDIR scene.nff...\n");
        return 2;
    }
    const char *exe = argv[1], *outdir = argv[2];
    printf("Tachyon vs ours: SPD scenes, 513x513 eye rays, depth 5, 1 thread; best of %d interleaved runs "
           "(each column its own minimum)\n", reps);
    printf("wall: grid build + trace (Tachyon: its 'Preprocessing' + 'Ray Tracing' times; ours: rt_scene_commit + "
           "rt_render); CPU: the whole job, parse + build + trace, process CPU time (robust to load)\n");
    printf("%-22s %7s %7s | %7s %7s | %6s | %7s %7s %6s | %s\n", "scene", "T.build", "T.trace", "o.build", "o.trace",
           "wall", "T.cpu", "o.cpu", "cpu", "ours rays");
    printf("%-22s %7s %7s | %7s %7s | %6s | %7s %7s %6s |\n", "", "wall s", "wall s", "wall s", "wall s", "o/T", "s",
           "s", "o/T");
    int fails = 0;
    for (int a = 3; a < argc; a++) {
        const char *scene = argv[a];
        const char *base = strrchr(scene, '/');
        base = base ? base + 1 : scene;
        char tout[2048], oout[2048], dat[2048];
        snprintf(tout, sizeof tout, "%s/tachyon_%s.ppm", outdir, base);
        snprintf(dat, sizeof dat, "%s/%s.dat", outdir, base);
        if (write_tachyon(scene, dat) != 0) {
            fprintf(stderr, "%s: cannot export to %s\n", scene, dat);
            fails++;
            continue;
        }
        snprintf(oout, sizeof oout, "%s/ours_%s.ppm", outdir, base);
        timing tb = {1e30, 1e30, 1e30}, ob = {1e30, 1e30, 1e30};
        double tf = 1e30, of = 1e30;
        rt_stats st;
        memset(&st, 0, sizeof st);
        int ok = 1;
        for (int r = 0; r < reps && ok; r++) {
            timing t, o;
            if (run_tachyon(exe, dat, tout, &t) != 0) {
                fprintf(stderr, "%s: tachyon failed\n", scene);
                ok = 0;
                break;
            }
            keep_best(&tb, &t);
            tf = fmin(tf, t.build + t.trace);
            if (run_ours(scene, r == 0 ? oout : NULL, &o, &st) != 0) {
                fprintf(stderr, "%s: ours failed\n", scene);
                ok = 0;
                break;
            }
            keep_best(&ob, &o);
            of = fmin(of, o.build + o.trace);
        }
        if (!ok) {
            fails++;
            continue;
        }
        printf("%-22s %7.3f %7.3f | %7.3f %7.3f | %6.2f | %7.3f %7.3f %6.2f | eye %llu shadow %llu refl %llu "
               "refr %llu\n",
               base, tb.build, tb.trace, ob.build, ob.trace, of / tf, tb.cpu, ob.cpu, ob.cpu / tb.cpu,
               (unsigned long long)st.eye_rays, (unsigned long long)st.shadow_rays,
               (unsigned long long)st.reflection_rays, (unsigned long long)st.refraction_rays);
        fflush(stdout);
    }
    printf("(o/T < 1: ours faster; the issue's goal is o/T <= 0.5 on every SPD polygon scene)\n");
    return fails ? 1 : 0;
}
