/* SPDX-License-Identifier: MIT */
/*
 * cmp_povray -- one mesh scene, ours vs POV-Ray 3.7, one thread, same run.
 *   cmp_povray POVRAY_EXE OUTDIR mesh.off [SIZE]
 * The mesh is exported as a POV-Ray mesh2 (world coordinates) with the same camera
 * (scene_io_frame_view: 40 degrees, square), one point light (no attenuation) and a white
 * finish { ambient 0.1 diffuse 0.8 } (= our ka 0.1, kd 0.8, ambient light 1). Both render
 * SIZE x SIZE (default 512) pixels, one ray per pixel centre, shadows, no anti-aliasing.
 * POV-Ray: +WT1 -D -A, the CPU seconds of its own Parse + Bounding and Trace statistics.
 * Ours: reading the OFF file, the scene, rt_scene_commit (as POV-Ray's parse reads its file)
 * + rt_render (1 thread, defaults), process CPU seconds. Best of 3
 * interleaved runs.
 */
#include "bench_scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { REPS = 3 };

static int write_pov(const bs_scene *s, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "// exported by bench/compare/cmp_povray (right-handed data: right -x)\n");
    fprintf(f, "global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 }\n");
    fprintf(f, "background { color rgb 0 }\n");
    fprintf(f, "camera { perspective location <%.17g,%.17g,%.17g> sky <%.17g,%.17g,%.17g>\n", s->from[0],
            s->from[1], s->from[2], s->up[0], s->up[1], s->up[2]);
    fprintf(f, "  up y right -x angle %.17g look_at <%.17g,%.17g,%.17g> }\n", s->angle, s->at[0], s->at[1],
            s->at[2]);
    fprintf(f, "light_source { <%.17g,%.17g,%.17g> color rgb 1 }\n", s->light_world[0], s->light_world[1],
            s->light_world[2]);
    fprintf(f, "mesh2 {\n  vertex_vectors { %zu", s->nverts);
    for (size_t i = 0; i < s->nverts; i++)
        fprintf(f, ",\n<%.9g,%.9g,%.9g>", s->verts_world[3 * i], s->verts_world[3 * i + 1],
                s->verts_world[3 * i + 2]);
    fprintf(f, " }\n  face_indices { %zu", s->ntris);
    for (size_t t = 0; t < s->ntris; t++)
        fprintf(f, ",\n<%u,%u,%u>", s->tris[3 * t], s->tris[3 * t + 1], s->tris[3 * t + 2]);
    fprintf(f, " }\n  pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.8 }\n}\n");
    return fclose(f) == 0 ? 0 : -1;
}

/* seconds in "( 1.234 seconds)" after key */
static double pov_seconds(const char *line, const char *key)
{
    const char *q = strstr(line, key);
    if (!q)
        return -1.0;
    q = strchr(q, '(');
    return q ? atof(q + 1) : -1.0;
}

/* POV-Ray once: CPU seconds of parse + bounding and of tracing, from its statistics (each
 * "... Time:" line is followed by "using N thread(s) with X CPU-seconds total") */
static int run_pov(const char *exe, const char *pov, const char *png, int size, double *parse, double *trace)
{
    if (strchr(exe, '\'') || strchr(pov, '\'') || strchr(png, '\''))
        return -1;
    char cmd[4096];
    int n = snprintf(cmd, sizeof cmd, "exec '%s' '+I%s' '+O%s' +W%d +H%d +WT1 -D -A +FN -V 2>&1", exe, pov, png, size,
                     size);
    if (n < 0 || (size_t)n >= sizeof cmd)
        return -1;
    FILE *p = popen(cmd, "r");
    if (!p)
        return -1;
    char line[1024];
    double cpu[3] = {-1.0, -1.0, -1.0};
    int cur = -1;
    while (fgets(line, sizeof line, p)) {
        const char *q;
        if (pov_seconds(line, "Parse Time:") >= 0.0)
            cur = 0;
        else if (pov_seconds(line, "Bounding Time:") >= 0.0)
            cur = 1;
        else if (pov_seconds(line, "Trace Time:") >= 0.0)
            cur = 2;
        else if (cur >= 0 && (q = strstr(line, " with ")) && strstr(line, "CPU-seconds")) {
            cpu[cur] = atof(q + strlen(" with "));
            cur = -1;
        }
    }
    int st = pclose(p);
    *parse = cpu[0] + cpu[1];
    *trace = cpu[2];
    return st == 0 && cpu[0] >= 0.0 && cpu[1] >= 0.0 && cpu[2] >= 0.0 ? 0 : -1;
}

int main(int argc, char **argv)
{
    if (argc < 4) {
        fprintf(stderr, "usage: cmp_povray POVRAY_EXE OUTDIR mesh.off [SIZE]\n");
        return 2;
    }
    const char *exe = argv[1], *outdir = argv[2], *mesh = argv[3];
    int size = argc > 4 ? atoi(argv[4]) : 512;
    if (size < 16 || size > 8192)
        return 2;
    const char *base = strrchr(mesh, '/');
    base = base ? base + 1 : mesh;
    char pov[2048], png[2048];
    snprintf(pov, sizeof pov, "%s/%s.pov", outdir, base);
    snprintf(png, sizeof png, "%s/povray_%s.png", outdir, base);
    bs_options opt = {.size = size};
    bs_scene s;
    char err[512];
    if (bs_load(mesh, &opt, &s, err, sizeof err) != 0 || write_pov(&s, pov) != 0) {
        fprintf(stderr, "%s: %s\n", mesh, err);
        bs_free(&s);
        return 1;
    }
    size_t ntris = s.ntris;
    bs_free(&s);
    double pp = 1e30, pt = 1e30, pf = 1e30, ob = 1e30, orr = 1e30, of = 1e30;
    float *rgb = bs_alloc((size_t)size * size, 3 * sizeof(float));
    if (!rgb)
        return 1;
    for (int r = 0; r < REPS; r++) {
        double a, b;
        if (run_pov(exe, pov, png, size, &a, &b) != 0) {
            fprintf(stderr, "povray failed on %s\n", pov);
            free(rgb);
            return 1;
        }
        pp = a < pp ? a : pp;
        pt = b < pt ? b : pt;
        pf = a + b < pf ? a + b : pf;
        const double tl = bs_process_cpu(); /* reading the OFF file counts, as POV-Ray's parse */
        if (bs_load(mesh, &opt, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            bs_free(&s);
            free(rgb);
            return 1;
        }
        const double tload = bs_process_cpu() - tl;
        rt_render_options o;
        rt_render_options_default(&o);
        o.threads = 1;
        o.corner_rays = 0; /* as POV-Ray here: one ray per pixel centre, no cut-off */
        o.cutoff = 0.0;
        double t0 = bs_process_cpu();
        int rc = rt_render(s.rt, &s.cam, &o, rgb, NULL);
        double tr = bs_process_cpu() - t0;
        double tb = tload; /* read + scene + commit */
        bs_free(&s);
        if (rc == RT_OK && r == 0) {
            char ppm[2048];
            snprintf(ppm, sizeof ppm, "%s/ours_%s.ppm", outdir, base);
            FILE *f = fopen(ppm, "wb");
            if (f) {
                fprintf(f, "P6\n%d %d\n255\n", size, size);
                for (size_t k = 0; k < (size_t)size * size * 3; k++)
                    fputc(rgb[k] <= 0.0f ? 0 : rgb[k] >= 1.0f ? 255 : (int)(rgb[k] * 255.0f + 0.5f), f);
                fclose(f);
            }
        }
        if (rc != RT_OK) {
            free(rgb);
            return 1;
        }
        ob = tb < ob ? tb : ob;
        orr = tr < orr ? tr : orr;
        of = tb + tr < of ? tb + tr : of;
    }
    free(rgb);
    printf("POV-Ray 3.7 vs ours: %s as mesh2 (%zu triangles), %dx%d, 1 ray per pixel + shadow rays to 1 light, "
           "1 thread (+WT1); CPU seconds, best of %d interleaved runs\n",
           base, ntris, size, size, REPS);
    printf("%-18s %9s %9s %9s | %9s %9s %9s | %7s %7s\n", "mesh", "P.parse", "P.trace", "P.frame", "o.read",
           "o.trace", "o.frame", "frame", "trace");
    printf("%-18s %9s %9s %9s | %9s %9s %9s | %7s %7s\n", "", "+bound s", "s", "s", "+build s", "s", "s", "o/P",
           "o/P");
    printf("%-18s %9.3f %9.3f %9.3f | %9.3f %9.3f %9.3f | %7.3f %7.3f\n", base, pp, pt, pf, ob, orr, of, of / pf,
           orr / pt);
    printf("(both count reading their file: POV-Ray's 'parse' reads the mesh2 text, ours' read+build reads "
           "the OFF file, builds the scene and commits it on 1 thread)\n");
    return 0;
}
