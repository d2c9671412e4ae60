/* SPDX-License-Identifier: MIT */
/*
 * speed_error -- speed against error of the gksrt render settings (issue 7).
 *   speed_error [-s SIZE] [-ref-spp N] [-ref-depth D] [-ref-threads T] [-reps R] [-csv FILE]
 *               [-ref-cache DIR] NAME=SCENE[:ks]...
 * For each scene (NFF with its own view, or a mesh framed by scene_io_frame_view; ":ks"
 * after a mesh path gives its surface that mirror weight), renders a reference image
 * (SIZE x SIZE, double precision as always, exact Fresnel, no adaptive cut-off,
 * REF_SPP = 16x16 stratified samples per pixel, depth REF_DEPTH = 8: deeper than the default 5;
 * beyond 8 the ray trees of the transparent gear stacks grow about 2x per level and the
 * reference would take hours) and then every setting
 * of the table below, one thread, timing rt_render (process CPU seconds, best of R = 5 rounds,
 * each round rendering every setting once), and
 * compares it with the reference:
 *   RMSE     over all pixels and channels of the linear RGB clamped to [0,1]
 *   PSNR     20 log10(1 / RMSE) dB (peak 1)
 *   SSIM     mean SSIM of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (clamped RGB):
 *            Wang, Bovik, Sheikh, Simoncelli, "Image quality assessment: from error
 *            visibility to structural similarity", IEEE TIP 13(4), 2004, eq. (13):
 *            SSIM = (2 mx my + C1)(2 sxy + C2) / ((mx^2 + my^2 + C1)(sx^2 + sy^2 + C2)),
 *            local statistics under an 11x11 Gaussian window, sigma 1.5 (normalised,
 *            truncated at the image border), C1 = (0.01 L)^2, C2 = (0.03 L)^2, L = 1
 *   max err  largest absolute channel difference (clamped)
 *   nonfin   number of pixels with a NaN or Inf channel in the raw output (must be 0)
 * The tracer has no float mode (all geometry and shading is double), so "float vs double"
 * has no row. Pareto front per scene on (time, RMSE): a setting is dominated when another
 * is no slower and no less accurate and better in one of them by more than the noise
 * margin (time: 5 % or twice the difference between two timings of the defaults, whichever
 * is larger; RMSE 1 %); the rest form the front. For the defaults it also lists the settings
 * that are faster by more than the margin with an RMSE within 1 % (equal within noise).
 * -ref-cache DIR keeps the reference images (delete DIR to render them again).
 * Writes the CSV (one row per scene and setting) and prints a table per scene.
 */
#include "bench_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct setting {
    const char *name;
    const char *label;    /* short name for the plot */
    int samples, jitter, max_depth, fresnel, corner;
    double cutoff;
    double grid_factor;   /* 0: default */
    int is_default;       /* 1: rt_render_options_default; 2: the same again, to show the timing
                             noise (left out of the front and of the dominance checks) */
} setting;

/* Rows other than the two defaults rows set samples, jitter, depth, Fresnel, cut-off and
 * corner rays explicitly: 1, 0, 5, exact, 0, 0 (one ray per pixel centre, no cut-off: the
 * library's defaults until this sweep put corner rays + cut-off 0.01 on the front) except
 * for the parameters their names give. Grid rows rebuild the scene with
 * that rt_build_options.grid_factor (the defaults use RT_GRID_FACTOR_DEFAULT). */
static const setting settings[] = {
    {"defaults (rt_render_options_default)", "default", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 1},
    {"defaults again (timing noise)", "default again", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 2},
    {"4 spp stratified", "4s", 4, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"16 spp stratified", "16s", 16, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"1 spp jittered", "1j", 1, 1, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"4 spp jittered", "4j", 4, 1, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"16 spp jittered", "16j", 16, 1, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"corner rays (SPD mode)", "corner", 1, 0, 5, RT_FRESNEL_EXACT, 1, 0.0, 0.0, 0},
    {"depth 1", "d1", 1, 0, 1, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"depth 2", "d2", 1, 0, 2, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"depth 3", "d3", 1, 0, 3, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"depth 4", "d4", 1, 0, 4, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"depth 8", "d8", 1, 0, 8, RT_FRESNEL_EXACT, 0, 0.0, 0.0, 0},
    {"cut-off 0.001", "c.001", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.001, 0.0, 0},
    {"cut-off 0.01", "c.01", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.01, 0.0, 0},
    {"cut-off 0.03", "c.03", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.03, 0.0, 0},
    {"cut-off 0.1", "c.1", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.1, 0.0, 0},
    {"cut-off 0.3", "c.3", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.3, 0.0, 0},
    {"Schlick Fresnel", "schlick", 1, 0, 5, RT_FRESNEL_SCHLICK, 0, 0.0, 0.0, 0},
    {"grid factor 0.125", "g.125", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.125, 0},
    {"grid factor 0.25", "g.25", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.25, 0},
    {"grid factor 0.5", "g.5", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 0.5, 0},
    {"grid factor 1", "g1", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 1.0, 0},
    {"grid factor 2", "g2", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 2.0, 0},
    {"grid factor 4", "g4", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 4.0, 0},
    {"grid factor 8", "g8", 1, 0, 5, RT_FRESNEL_EXACT, 0, 0.0, 8.0, 0},
    {"4 spp stratified + cut-off 0.01", "4s+c.01", 4, 0, 5, RT_FRESNEL_EXACT, 0, 0.01, 0.0, 0},
    {"4 spp stratified + Schlick + cut-off 0.01", "4s+schlick+c.01", 4, 0, 5, RT_FRESNEL_SCHLICK, 0, 0.01, 0.0, 0},
    {"16 spp stratified + cut-off 0.01", "16s+c.01", 16, 0, 5, RT_FRESNEL_EXACT, 0, 0.01, 0.0, 0},
    {"corner rays + cut-off 0.001", "corner+c.001", 1, 0, 5, RT_FRESNEL_EXACT, 1, 0.001, 0.0, 0},
    {"corner rays + cut-off 0.01", "corner+c.01", 1, 0, 5, RT_FRESNEL_EXACT, 1, 0.01, 0.0, 0},
};
enum { NSET = sizeof settings / sizeof settings[0] };

typedef struct result {
    double time, rmse, psnr, ssim, maxerr;
    size_t nonfinite;
    uint64_t eye_rays, rays;
    int front;            /* on the front with the noise margins */
    int strict;           /* on the exact Pareto front (no margins: the plotted line) */
} result;

static float clamp01(float x)
{
    return x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f; /* NaN -> 0 */
}

/* separable normalised Gaussian blur (11 taps, sigma 1.5, truncated at the border) */
static void blur(const double *in, double *tmp, double *out, int w, int h)
{
    double g[11], s = 0.0;
    for (int k = 0; k < 11; k++) {
        g[k] = exp(-(double)((k - 5) * (k - 5)) / (2.0 * 1.5 * 1.5));
        s += g[k];
    }
    for (int k = 0; k < 11; k++)
        g[k] /= s;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double a = 0.0, ws = 0.0;
            for (int k = 0; k < 11; k++) {
                int xx = x + k - 5;
                if (xx < 0 || xx >= w)
                    continue;
                a += g[k] * in[(size_t)y * w + xx];
                ws += g[k];
            }
            tmp[(size_t)y * w + x] = a / ws;
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double a = 0.0, ws = 0.0;
            for (int k = 0; k < 11; k++) {
                int yy = y + k - 5;
                if (yy < 0 || yy >= h)
                    continue;
                a += g[k] * tmp[(size_t)yy * w + x];
                ws += g[k];
            }
            out[(size_t)y * w + x] = a / ws;
        }
}

/* mean SSIM of the luminance of two clamped images; -2 on allocation failure */
static double ssim(const float *a, const float *b, int w, int h)
{
    size_t n = (size_t)w * h;
    double *buf = bs_alloc(n, 8 * sizeof(double));
    if (!buf)
        return -2.0;
    double *x = buf, *y = buf + n, *xx = buf + 2 * n, *yy = buf + 3 * n, *xy = buf + 4 * n, *tmp = buf + 5 * n;
    double *mx = buf + 6 * n, *my = buf + 7 * n;
    for (size_t i = 0; i < n; i++) {
        x[i] = 0.2126 * clamp01(a[3 * i]) + 0.7152 * clamp01(a[3 * i + 1]) + 0.0722 * clamp01(a[3 * i + 2]);
        y[i] = 0.2126 * clamp01(b[3 * i]) + 0.7152 * clamp01(b[3 * i + 1]) + 0.0722 * clamp01(b[3 * i + 2]);
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    blur(x, tmp, mx, w, h);
    blur(y, tmp, my, w, h);
    blur(xx, tmp, x, w, h); /* x, y now hold E[x^2], E[y^2] */
    blur(yy, tmp, y, w, h);
    blur(xy, tmp, xx, w, h); /* xx now holds E[xy] */
    const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        double sx = x[i] - mx[i] * mx[i], sy = y[i] - my[i] * my[i], sxy = xx[i] - mx[i] * my[i];
        sum += (2.0 * mx[i] * my[i] + C1) * (2.0 * sxy + C2) /
               ((mx[i] * mx[i] + my[i] * my[i] + C1) * (sx + sy + C2));
    }
    free(buf);
    return sum / (double)n;
}

static void compare(const float *img, const float *ref, int w, int h, result *r)
{
    size_t n = (size_t)w * h;
    double se = 0.0, mx = 0.0;
    r->nonfinite = 0;
    for (size_t i = 0; i < n; i++) {
        int bad = 0;
        for (int c = 0; c < 3; c++) {
            bad |= !isfinite(img[3 * i + c]);
            double d = (double)clamp01(img[3 * i + c]) - (double)clamp01(ref[3 * i + c]);
            se += d * d;
            mx = fmax(mx, fabs(d));
        }
        r->nonfinite += (size_t)bad;
    }
    r->rmse = sqrt(se / (3.0 * (double)n));
    r->psnr = r->rmse > 0.0 ? 20.0 * log10(1.0 / r->rmse) : INFINITY;
    r->maxerr = mx;
    r->ssim = ssim(img, ref, w, h);
}

/* the defaults rows take rt_render_options_default as it is (only threads and background
 * set), so that they follow the library when its defaults change */
static void options_of(const setting *s, const bs_scene *sc, rt_render_options *o)
{
    rt_render_options_default(o);
    o->threads = 1;
    memcpy(o->background, sc->background, sizeof o->background);
    if (s->is_default)
        return;
    o->samples = s->samples;
    o->jitter = s->jitter;
    o->max_depth = s->max_depth;
    o->fresnel = s->fresnel;
    o->cutoff = s->cutoff;
    o->corner_rays = s->corner;
}

static int load(const char *path, double ks, int size, double grid_factor, bs_scene *s)
{
    rt_build_options bo = {.grid_factor = grid_factor, .brute_threshold = -1};
    bs_options opt = {.size = size, .build = &bo, .mesh_ks = ks};
    char err[512];
    if (bs_load(path, &opt, s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        bs_free(s);
        return -1;
    }
    return 0;
}

/* relative time margin: 5 %, or twice the difference between the two timings of the
 * defaults when that is larger (the measured noise of this run) */
static double time_margin(const result *r, int n)
{
    double m = 0.05;
    for (int k = 1; k < n; k++)
        if (settings[k].is_default == 2) {
            double a = r[0].time, b = r[k].time;
            m = fmax(m, 2.0 * fabs(a - b) / fmin(a, b));
        }
    return m;
}

/* Pareto front on (time, rmse) with noise margins */
static void pareto(result *r, int n)
{
    double tm = time_margin(r, n);
    for (int i = 0; i < n; i++) {
        r[i].front = settings[i].is_default != 2;
        for (int j = 0; j < n && r[i].front; j++) {
            if (j == i || settings[j].is_default == 2)
                continue;
            int no_worse = r[j].time <= r[i].time && r[j].rmse <= r[i].rmse;
            int better = r[j].time < (1.0 - tm) * r[i].time || r[j].rmse < 0.99 * r[i].rmse;
            if (no_worse && better)
                r[i].front = 0;
        }
        r[i].strict = settings[i].is_default != 2;
        for (int j = 0; j < n && r[i].strict; j++)
            if (j != i && settings[j].is_default != 2 && r[j].time <= r[i].time && r[j].rmse <= r[i].rmse &&
                (r[j].time < r[i].time || r[j].rmse < r[i].rmse))
                r[i].strict = 0;
    }
}

/* Reference cache: DIR/NAME_SIZE_SPP_DEPTH_KS.ref holds a text header line and the raw
 * floats; used when the header matches (delete the directory to force new references). The
 * header names the sampling: files written before 2026-11-25 04:00 UTC lack it and are
 * rendered again (references rendered then from the library's defaults had corner rays and
 * the cut-off once those became the defaults). */
#define REF_HEADER "speed_error reference (stratified, no cut-off) %d %s\n"
static int ref_cache_path(char *buf, size_t n, const char *dir, const char *name, int size, int spp, int depth,
                          double ks)
{
    int k = snprintf(buf, n, "%s/%s_%d_%d_%d_%g.ref", dir, name, size, spp, depth, ks);
    return k > 0 && (size_t)k < n ? 0 : -1;
}

static int ref_cache_read(const char *path, const char *scene, int size, float *ref)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    char want[4400], line[4400];
    snprintf(want, sizeof want, REF_HEADER, size, scene);
    size_t n = (size_t)size * size * 3;
    int ok = fgets(line, sizeof line, f) && !strcmp(line, want) && fread(ref, sizeof(float), n, f) == n;
    fclose(f);
    return ok ? 0 : -1;
}

static void ref_cache_write(const char *path, const char *scene, int size, const float *ref)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, REF_HEADER, size, scene);
    fwrite(ref, sizeof(float), (size_t)size * size * 3, f);
    fclose(f);
}

static int run_scene(const char *name, const char *path, double ks, int size, int ref_spp, int ref_depth,
                     int ref_threads, int reps, const char *cache, FILE *csv)
{
    bs_scene s;
    if (load(path, ks, size, 0.0, &s) != 0)
        return -1;
    size_t npx = (size_t)size * size;
    float *ref = bs_alloc(npx, 3 * sizeof(float)), *img = bs_alloc(npx, 3 * sizeof(float));
    result *res = calloc(NSET, sizeof *res);
    if (!ref || !img || !res) {
        free(ref);
        free(img);
        free(res);
        bs_free(&s);
        return -1;
    }
    /* the reference sets everything it depends on: the library's defaults (corner rays,
       cut-off) are among the settings it judges */
    rt_render_options o;
    options_of(&settings[0], &s, &o);
    o.samples = ref_spp;
    o.jitter = 0;
    o.corner_rays = 0;
    o.cutoff = 0.0;
    o.fresnel = RT_FRESNEL_EXACT;
    o.max_depth = ref_depth;
    o.threads = ref_threads;
    rt_stats st;
    memset(&st, 0, sizeof st);
    char cpath[4096] = "";
    if (cache && ref_cache_path(cpath, sizeof cpath, cache, name, size, ref_spp, ref_depth, ks) != 0)
        cache = NULL; /* path too long: no cache */
    double w0 = bs_wall();
    int rc = RT_OK, cached = cache && ref_cache_read(cpath, path, size, ref) == 0;
    if (!cached) {
        rc = rt_render(s.rt, &s.cam, &o, ref, &st);
        if (rc == RT_OK && cache)
            ref_cache_write(cpath, path, size, ref);
    }
    double tref = bs_wall() - w0;
    if (rc != RT_OK) {
        fprintf(stderr, "%s: reference render failed (%d)\n", name, rc);
        free(ref);
        free(img);
        free(res);
        bs_free(&s);
        return -1;
    }
    printf("\n%s (%s): %zu polygons, %dx%d; reference %d spp stratified, depth %d, exact Fresnel, no cut-off: ",
           name, path, s.npolys, size, size, ref_spp, ref_depth);
    if (cached)
        printf("read from %s\n", cpath);
    else
        printf("%.1f s wall on %d threads\n", tref, ref_threads);
    /* scenes with other grid factors, loaded up front so that the repetitions can be
     * interleaved: round r renders every setting once, so a burst of load on the shared
     * machine hits different settings in different rounds; each keeps its fastest round */
    bs_scene *grid = calloc(NSET, sizeof *grid);
    int ok = grid != NULL;
    for (int k = 0; ok && k < NSET; k++)
        if (settings[k].grid_factor > 0.0 && load(path, ks, size, settings[k].grid_factor, &grid[k]) != 0)
            ok = 0;
    for (int k = 0; k < NSET; k++)
        res[k].time = INFINITY;
    for (int r = 0; ok && r < reps; r++)
        for (int k = 0; k < NSET && ok; k++) {
            const setting *se = &settings[k];
            const bs_scene *sc = se->grid_factor > 0.0 ? &grid[k] : &s;
            options_of(se, sc, &o);
            double t0 = bs_process_cpu();
            rc = rt_render(sc->rt, &sc->cam, &o, img, &st);
            res[k].time = fmin(res[k].time, bs_process_cpu() - t0);
            if (rc != RT_OK) {
                fprintf(stderr, "%s: %s failed (%d)\n", name, se->name, rc);
                ok = 0;
            } else if (r == 0) { /* the picture is the same in every round */
                res[k].eye_rays = st.eye_rays;
                res[k].rays = st.eye_rays + st.shadow_rays + st.reflection_rays + st.refraction_rays;
                compare(img, ref, size, size, &res[k]);
            }
        }
    for (int k = 0; grid && k < NSET; k++)
        if (grid[k].rt)
            bs_free(&grid[k]);
    free(grid);
    if (!ok) {
        free(ref);
        free(img);
        free(res);
        bs_free(&s);
        return -1;
    }
    pareto(res, NSET);
    printf("%-46s %8s %10s %9s %8s %7s %8s %6s %s\n", "setting", "time s", "rays", "RMSE", "PSNR dB", "SSIM",
           "max err", "nonfin", "front");
    for (int k = 0; k < NSET; k++) {
        const result *r = &res[k];
        const setting *se = &settings[k];
        printf("%-46s %8.3f %10llu %9.2e %8.2f %7.4f %8.4f %6zu %s\n", se->name, r->time,
               (unsigned long long)r->rays, r->rmse, r->psnr, r->ssim, r->maxerr, r->nonfinite,
               r->front ? "*" : "");
        rt_render_options ro;
        options_of(se, &s, &ro);
        fprintf(csv, "%s,\"%s\",%d,%d,%d,%g,%s,%g,%d,%.6f,%llu,%llu,%.6e,%.4f,%.6f,%.6f,%zu,%d,%d,%s,%d\n", name,
                se->name, ro.samples, ro.jitter, ro.max_depth, ro.cutoff,
                ro.fresnel == RT_FRESNEL_SCHLICK ? "schlick" : ro.fresnel == RT_FRESNEL_NONE ? "none" : "exact",
                se->grid_factor > 0.0 ? se->grid_factor : RT_GRID_FACTOR_DEFAULT, ro.corner_rays, r->time,
                (unsigned long long)r->eye_rays, (unsigned long long)r->rays, r->rmse, r->psnr, r->ssim,
                r->maxerr, r->nonfinite, r->front, se->is_default, se->label, r->strict);
    }
    printf("front (*): ");
    for (int k = 0, first = 1; k < NSET; k++)
        if (res[k].front) {
            printf("%s%s", first ? "" : "; ", settings[k].name);
            first = 0;
        }
    printf("\ndefaults on the front: %s\n", res[0].front ? "YES" : "NO");
    double tm = time_margin(res, NSET);
    printf("time margin (noise): %.0f %%\n", 100.0 * tm);
    for (int j = 1; j < NSET; j++) {
        const result *d = &res[0], *r = &res[j];
        if (settings[j].is_default == 2)
            continue;
        if (r->time <= d->time && r->rmse <= d->rmse && (r->time < (1.0 - tm) * d->time || r->rmse < 0.99 * d->rmse))
            printf("  defaults dominated by: %s (%.3f s, RMSE %.3e vs %.3f s, %.3e)\n", settings[j].name, r->time,
                   r->rmse, d->time, d->rmse);
        else if (r->time < (1.0 - tm) * d->time && r->rmse <= 1.01 * d->rmse)
            printf("  as accurate within 1 %% and faster: %s (%.3f s, RMSE %.3e vs %.3f s, %.3e)\n",
                   settings[j].name, r->time, r->rmse, d->time, d->rmse);
    }
    fflush(stdout);
    free(ref);
    free(img);
    free(res);
    bs_free(&s);
    return 0;
}

int main(int argc, char **argv)
{
    int size = 256, ref_spp = 256, ref_depth = 8, ref_threads = 2, reps = 5;
    const char *csvpath = "speed_error.csv", *cache = NULL;
    int a = 1;
    for (; a < argc && argv[a][0] == '-'; a++) {
        if (a + 1 >= argc)
            break;
        if (!strcmp(argv[a], "-s")) size = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-ref-spp")) ref_spp = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-ref-depth")) ref_depth = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-ref-threads")) ref_threads = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-reps")) reps = atoi(argv[++a]);
        else if (!strcmp(argv[a], "-csv")) csvpath = argv[++a];
        else if (!strcmp(argv[a], "-ref-cache")) cache = argv[++a];
        else break;
    }
    if (a >= argc || size < 8 || size > 4096 || ref_spp < 1 || ref_depth < 1 || ref_depth > 64 || ref_threads < 0 ||
        reps < 1) {
        fprintf(stderr, "usage: speed_error [-s SIZE] [-ref-spp N] [-ref-depth D] [-ref-threads T] [-reps R] "
                        "[-csv FILE] [-ref-cache DIR] NAME=SCENE[:ks]...\n");
        return 2;
    }
    FILE *csv = fopen(csvpath, "w");
    if (!csv) {
        perror(csvpath);
        return 1;
    }
    fprintf(csv, "scene,setting,samples,jitter,max_depth,cutoff,fresnel,grid_factor,corner_rays,time_s,eye_rays,"
                 "total_rays,rmse,psnr_db,ssim,max_err,nonfinite,pareto,is_default,label,strict_pareto\n");
    printf("speed vs error, %dx%d, 1 thread, process CPU seconds of rt_render, best of %d interleaved rounds; "
           "errors vs the reference "
           "on linear RGB clamped to [0,1]\n",
           size, size, reps);
    int fails = 0;
    for (; a < argc; a++) {
        char spec[4096];
        snprintf(spec, sizeof spec, "%s", argv[a]);
        char *eq = strchr(spec, '=');
        if (!eq) {
            fprintf(stderr, "bad scene spec %s (NAME=PATH[:ks])\n", argv[a]);
            fails++;
            continue;
        }
        *eq = 0;
        char *path = eq + 1, *colon = strrchr(path, ':');
        double ks = 0.0;
        if (colon) {
            *colon = 0;
            ks = atof(colon + 1);
        }
        if (run_scene(spec, path, ks, size, ref_spp, ref_depth, ref_threads, reps, cache, csv) != 0)
            fails++;
    }
    fclose(csv);
    return fails ? 1 : 0;
}
