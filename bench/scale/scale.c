/* SPDX-License-Identifier: MIT */
/*
 * scale.c -- a large scene from the GKS API to a ray-traced picture (issue 21): a lat-long
 * sphere of about N triangles, one FILL AREA 3 per triangle, in front of a back wall (two
 * triangles) it shadows, one directional and one ambient light, diffuse reflectance, drawn on
 * a 1024 x 1024 PNG workstation in HLHSR mode ray tracing with the workstation's defaults
 * (corner rays, depth 5), then UPDATE WORKSTATION writes the picture.
 *
 * Usage: scale N [-t THREADS] [-m MODE] [-o FILE.png]
 *   N        triangles of the sphere (>= 8)
 *   -t       ESCAPE GESC_RT_THREADS (0 = all online CPUs, the default)
 *   -m       HLHSR mode (4 ray tracing, the default; 2 z-buffer for comparison)
 *   -o       picture file (default scale.png in the working directory)
 * Prints one line of key=value figures: n (triangles drawn), calls (wall s of the GKS calls,
 * OPEN WORKSTATION to the last FILL AREA 3), update (wall s of UPDATE WORKSTATION: transfer,
 * build, render, composition and the PNG file), build and render (the tracer's own seconds,
 * ESCAPE GESC_RT_STATS), total (wall s of both), cpu (process CPU s), rss (peak resident MiB,
 * getrusage), B/tri (peak resident bytes per triangle), us/call (calls / n); calls_cpu and
 * update_cpu: process CPU s of the two phases (all threads), cpu_us/call: calls_cpu / n,
 * app_us/call: CPU s of the application's thread in the calls / n (with 2 or more threads
 * the recording runs on a pool worker beside it; under load the better estimate of an idle
 * machine's us/call than the wall figure).
 * bench/scale/run.sh runs the series and prints the goals.
 */
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double clock_s(clockid_t c)
{
    struct timespec t;
    clock_gettime(c, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double cpu(void) { return clock_s(CLOCK_PROCESS_CPUTIME_ID); }

static void escape_int(int id, int ws, int v)
{
    Gint ints[2] = { ws, v };
    Gescape_in_data in = { .num_ints = 2, .ints = ints };
    gescape(id, &in, NULL, NULL);
}

int main(int argc, char **argv)
{
    long n = 0;
    int threads = 0, mode = GHLHSR_RAYTRACE;
    const char *out = "scale.png";
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-t") == 0 && i + 1 < argc)
            threads = atoi(argv[++i]);
        else if (strcmp(argv[i], "-m") == 0 && i + 1 < argc)
            mode = atoi(argv[++i]);
        else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            out = argv[++i];
        else
            n = strtol(argv[i], NULL, 10);
    }
    if (n < 8) {
        fprintf(stderr, "usage: scale N [-t THREADS] [-m MODE] [-o FILE.png]\n");
        return 2;
    }
    /* 2 nu (nv - 1) triangles (the pole rows have one per quad), nu ~ 2 nv */
    long nv = (long)floor(sqrt((double)n / 4.0)) + 1, nu = n / (2 * (nv - 1));
    if (nu < 3)
        nu = 3;
    Gpoint3 *g = malloc((size_t)nu * (size_t)(nv + 1) * sizeof *g);
    if (!g)
        return 1;
    const double pi = 3.14159265358979323846, r = 0.35;
    for (long j = 0; j <= nv; j++)
        for (long i = 0; i < nu; i++) {
            double th = pi * (double)j / (double)nv, ph = 2 * pi * (double)i / (double)nu;
            g[j * nu + i] = (Gpoint3){ 0.5 + r * sin(th) * cos(ph), 0.5 + r * cos(th),
                                       0.55 + r * sin(th) * sin(ph) };
        }

    double w0 = wall(), c0 = cpu(), a0 = clock_s(CLOCK_THREAD_CPUTIME_ID);
    gopen_gks(NULL, 0);
    gopen_ws(1, out, GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_hlhsr_mode(1, mode);
    escape_int(GESC_RT_THREADS, 1, threads);
    Gcolr_rep c = { { 0.9, 0.7, 0.4 } };
    gset_colr_rep(1, 2, &c);
    Gcolr_rep cw = { { 0.6, 0.7, 0.9 } };
    gset_colr_rep(1, 3, &cw);
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 0.2, 0.2, 0.2 }, { 0, 0, 0 }, { 0, 0, -1 },
                           { 1, 0 }, 0, 1 };
    Glight_src_rep dir = { GLIGHT_DIRECTIONAL, { 0.9, 0.9, 0.9 }, { 0, 0, 0 },
                           { 0.45, -0.55, -0.7 }, { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &amb);
    gset_light_src_rep(1, 3, &dir);
    Gint on[2] = { 2, 3 };
    Gint_list act = { 2, on };
    gset_light_src_state(&act, NULL);
    Garea_props pr = { 1, 1, 0, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&pr);
    gset_back_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF);
    gset_back_refl_eq(GREFL_AMB_DIFF);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(3);
    Gpoint3 wallp[4] = { { 0, 0, 0.02 }, { 1, 0, 0.02 }, { 1, 1, 0.02 }, { 0, 1, 0.02 } };
    Gpoint3 t[3];
    Gpoint_list3 l = { 3, t };
    long drawn = 0;
    for (int k = 0; k < 2; k++) {
        t[0] = wallp[0];
        t[1] = wallp[1 + k];
        t[2] = wallp[2 + k];
        gfill_area3(&l);
        drawn++;
    }
    gset_fill_colr_ind(2);
    for (long j = 0; j < nv; j++)
        for (long i = 0; i < nu; i++) {
            const Gpoint3 *p00 = &g[j * nu + i], *p10 = &g[j * nu + (i + 1) % nu];
            const Gpoint3 *p01 = &g[(j + 1) * nu + i], *p11 = &g[(j + 1) * nu + (i + 1) % nu];
            if (j > 0) { /* none at a pole */
                t[0] = *p00;
                t[1] = *p10;
                t[2] = *p11;
                gfill_area3(&l);
                drawn++;
            }
            if (j < nv - 1) {
                t[0] = *p00;
                t[1] = *p11;
                t[2] = *p01;
                gfill_area3(&l);
                drawn++;
            }
        }
    free(g);
    double w1 = wall(), c1 = cpu(), a1 = clock_s(CLOCK_THREAD_CPUTIME_ID);
    gupd_ws(1, GFLAG_PERFORM);
    double w2 = wall(), c2 = cpu();
    Gfloat fl[2] = { 0 };
    Gint inw[1] = { 1 }, serr;
    Gescape_in_data sin_ = { .num_ints = 1, .ints = inw };
    Gstore store = NULL;
    Gescape_out_data *sout = NULL;
    gcreate_store(&serr, &store);
    gescape(GESC_RT_STATS, &sin_, &store, &sout);
    if (sout && sout->num_floats >= 2) {
        fl[0] = sout->floats[0];
        fl[1] = sout->floats[1];
    }
    gdel_store(store);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    double w3 = wall();
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    double rss = (double)ru.ru_maxrss * 1024.0;
    printf("n=%ld calls=%.3f update=%.3f build=%.3f render=%.3f total=%.3f close=%.3f "
           "cpu=%.2f rss=%.1f B/tri=%.0f us/call=%.3f calls_cpu=%.3f update_cpu=%.3f "
           "cpu_us/call=%.3f app_us/call=%.3f\n",
           drawn, w1 - w0, w2 - w1, fl[0], fl[1], w2 - w0, w3 - w2, cpu(), rss / 1048576.0,
           rss / (double)drawn, 1e6 * (w1 - w0) / (double)drawn, c1 - c0, c2 - c1,
           1e6 * (c1 - c0) / (double)drawn, 1e6 * (a1 - a0) / (double)drawn);
    return 0;
}
