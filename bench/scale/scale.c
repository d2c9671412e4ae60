/* SPDX-License-Identifier: MIT */
/*
 * scale.c -- a large scene from the GKS API to a ray-traced picture (issue 21): a lat-long
 * sphere of about N triangles, one FILL AREA 3 per triangle, in front of a back wall (two
 * triangles) it shadows, one directional and one ambient light, diffuse reflectance, drawn on
 * a 1024 x 1024 PNG workstation in HLHSR mode ray tracing with the workstation's defaults
 * (corner rays, depth 5), then UPDATE WORKSTATION writes the picture.
 *
 * Usage: scale N [-t THREADS] [-m MODE] [-s SURFACE] [-o FILE.png]
 *   N        triangles of the sphere (>= 8); vertices of the height field (-s mesh, tris)
 *   -t       ESCAPE GESC_RT_THREADS (0 = all online CPUs, the default)
 *   -m       HLHSR mode (4 ray tracing, the default; 2 z-buffer for comparison)
 *   -s       sphere (the default); mesh: a height field of about N vertices (a square grid,
 *            two bumps) as one QUADRILATERAL MESH 3 WITH DATA with exact vertex normals and
 *            interior shading method NORMAL; tris: the same surface as FILL AREA 3 triangles
 *            (each grid cell split at its diagonal (i,j)-(i+1,j+1), as the tracer splits the
 *            mesh's quadrilaterals), flat; both in front of the shadowed back wall
 *   -o       picture file (default scale.png in the working directory)
 * Prints one line of key=value figures: surface, n (triangles drawn; the mesh: its
 * quadrilaterals' triangles), verts (-s mesh, tris: the height field's vertices), calls (wall s of the GKS calls,
 * OPEN WORKSTATION to the last FILL AREA 3), update (wall s of UPDATE WORKSTATION: transfer,
 * build, render, composition and the PNG file), build and render (the tracer's own seconds,
 * ESCAPE GESC_RT_STATS), total (wall s of both), cpu (process CPU s), rss (peak resident MiB,
 * getrusage), B/tri (peak resident bytes per triangle), us/call (calls / n); calls_cpu and
 * update_cpu: process CPU s of the two phases (all threads), cpu_us/call: calls_cpu / n,
 * app_us/call: CPU s of the application's thread in the calls / n (with 2 or more threads
 * the recording runs on a pool worker beside it; under load the better estimate of an idle
 * machine's us/call than the wall figure); upd_app_cpu: CPU s of the application's thread in
 * UPDATE WORKSTATION (the rest of update_cpu ran on the pool's workers); calls_flt, upd_flt:
 * the process's minor page faults (first touches of memory) in the two phases, app_flt and
 * upd_app_flt those of the application's thread (Linux: RUSAGE_THREAD; else -1); app_waits,
 * upd_app_waits: how often the application's thread slept in the two phases (voluntary
 * context switches: the recording's queue full, a pool's parts not done; else -1);
 * calls_usr, calls_sys, upd_usr, upd_sys: the process's user and system CPU s in the two
 * phases, app_usr, app_sys, upd_app_usr, upd_app_sys those of the application's thread
 * (system CPU here is mostly first touches of memory; -1 where unknown).
 * bench/scale/run.sh runs the series and prints the goals.
 */
#if defined(__linux__) && !defined(_GNU_SOURCE)
#define _GNU_SOURCE 1 /* RUSAGE_THREAD */
#endif
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

/* Minor page faults of the process (thread 0) or of the calling thread (thread 1; -1 where
 * the system has no per-thread figure); *waits: the calling thread's voluntary context
 * switches (it slept: waited for the recording's queue or a pool's parts), -1 unknown. */
static long faults(int thread, long *waits)
{
    *waits = -1;
    struct rusage u;
#ifdef RUSAGE_THREAD
    if (getrusage(thread ? RUSAGE_THREAD : RUSAGE_SELF, &u) != 0)
        return -1;
    if (thread)
        *waits = u.ru_nvcsw;
#else
    if (thread || getrusage(RUSAGE_SELF, &u) != 0)
        return -1;
#endif
    return u.ru_minflt;
}

/* User and system CPU s of the process (thread 0) or of the calling thread (thread 1; both
 * -1 where the system has no per-thread figure): system CPU is mostly the kernel's page
 * faults here, so the split says whether a phase's CPU went to first touches of memory. */
static void usr_sys(int thread, double *usr, double *sys)
{
    struct rusage u;
    *usr = *sys = -1;
#ifdef RUSAGE_THREAD
    if (getrusage(thread ? RUSAGE_THREAD : RUSAGE_SELF, &u) != 0)
        return;
#else
    if (thread || getrusage(RUSAGE_SELF, &u) != 0)
        return;
#endif
    *usr = (double)u.ru_utime.tv_sec + 1e-6 * (double)u.ru_utime.tv_usec;
    *sys = (double)u.ru_stime.tv_sec + 1e-6 * (double)u.ru_stime.tv_usec;
}

/* b - a, or -1 if either is unknown */
static double fdiff(double a, double b) { return a < 0 || b < 0 ? -1 : b - a; }

/* b - a, or -1 if either is unknown */
static long diff(long a, long b) { return a < 0 || b < 0 ? -1 : b - a; }

static void escape_int(int id, int ws, int v)
{
    Gint ints[2] = { ws, v };
    Gescape_in_data in = { .num_ints = 2, .ints = ints };
    gescape(id, &in, NULL, NULL);
}

/* The height field over the unit square, z in [0.2, 0.8] (two bumps and a ripple): point and
 * unit normal of vertex (i, j) of an m x m grid. */
static void height(long i, long j, long m, Gpoint3 *p, Gvec3 *nv)
{
    const double pi = 3.14159265358979323846;
    double x = 0.1 + 0.8 * (double)i / (double)(m - 1), y = 0.1 + 0.8 * (double)j / (double)(m - 1);
    double a = (x - 0.35) * (x - 0.35) + (y - 0.6) * (y - 0.6);
    double b = (x - 0.65) * (x - 0.65) + (y - 0.35) * (y - 0.35);
    double ea = exp(-a / 0.02), eb = exp(-b / 0.03);
    double z = 0.35 + 0.25 * ea + 0.2 * eb + 0.02 * sin(6 * pi * x) * sin(6 * pi * y);
    double zx = 0.25 * ea * (-2 * (x - 0.35) / 0.02) + 0.2 * eb * (-2 * (x - 0.65) / 0.03) +
                0.02 * 6 * pi * cos(6 * pi * x) * sin(6 * pi * y);
    double zy = 0.25 * ea * (-2 * (y - 0.6) / 0.02) + 0.2 * eb * (-2 * (y - 0.35) / 0.03) +
                0.02 * 6 * pi * sin(6 * pi * x) * cos(6 * pi * y);
    double l = sqrt(zx * zx + zy * zy + 1);
    *p = (Gpoint3){ x, y, z };
    *nv = (Gvec3){ -zx / l, -zy / l, 1 / l };
}

/* The height field of about n vertices (-s mesh: one QUADRILATERAL MESH 3 WITH DATA; -s
 * tris: FILL AREA 3 triangles); the triangles drawn. */
static long height_field(long n, int mesh)
{
    long m = (long)floor(sqrt((double)n));
    if (m < 2)
        m = 2;
    Gpoint3 *p = malloc((size_t)m * (size_t)m * sizeof *p);
    Gvec3 *nv = malloc((size_t)m * (size_t)m * sizeof *nv);
    if (!p || !nv)
        exit(1);
    for (long j = 0; j < m; j++)
        for (long i = 0; i < m; i++)
            height(i, j, m, &p[j * m + i], &nv[j * m + i]);
    if (mesh) {
        gset_int_shad_meth(GSHAD_NORM);
        gset_back_int_shad_meth(GSHAD_NORM);
        Gint_size dim = { (Gint)m, (Gint)m };
        Gfacet_vdata3 vd = { (Gint)(m * m), p, NULL, nv };
        gquad_mesh3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, &dim, NULL, &vd);
    } else {
        Gpoint3 t[3];
        Gpoint_list3 l = { 3, t };
        for (long j = 0; j + 1 < m; j++)
            for (long i = 0; i + 1 < m; i++) {
                const Gpoint3 *q = &p[j * m + i];
                t[0] = q[0]; t[1] = q[1]; t[2] = q[m + 1];
                gfill_area3(&l);
                t[1] = q[m + 1]; t[2] = q[m];
                gfill_area3(&l);
            }
    }
    free(p);
    free(nv);
    return 2 * (m - 1) * (m - 1);
}

int main(int argc, char **argv)
{
    long n = 0, verts = 0;
    int threads = 0, mode = GHLHSR_RAYTRACE;
    const char *out = "scale.png", *surface = "sphere";
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-t") == 0 && i + 1 < argc)
            threads = atoi(argv[++i]);
        else if (strcmp(argv[i], "-m") == 0 && i + 1 < argc)
            mode = atoi(argv[++i]);
        else if (strcmp(argv[i], "-s") == 0 && i + 1 < argc)
            surface = argv[++i];
        else if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            out = argv[++i];
        else
            n = strtol(argv[i], NULL, 10);
    }
    const int field = strcmp(surface, "mesh") == 0 || strcmp(surface, "tris") == 0;
    if (n < 8 || (!field && strcmp(surface, "sphere") != 0)) {
        fprintf(stderr, "usage: scale N [-t THREADS] [-m MODE] [-s sphere|mesh|tris] "
                        "[-o FILE.png]\n");
        return 2;
    }
    /* 2 nu (nv - 1) triangles (the pole rows have one per quad), nu ~ 2 nv */
    long nv = (long)floor(sqrt((double)n / 4.0)) + 1, nu = n / (2 * (nv - 1));
    if (nu < 3)
        nu = 3;
    if (field) /* no sphere */
        nv = 0, nu = 3;
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

    long v0, v1, v2;
    double pu[3], ps[3], tu[3], ts[3]; /* process and thread user / system CPU at 3 points */
    const long f0 = faults(0, &v0), g0 = faults(1, &v0);
    usr_sys(0, &pu[0], &ps[0]);
    usr_sys(1, &tu[0], &ts[0]);
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
    if (field) {
        drawn += height_field(n, surface[0] == 'm');
        verts = (long)floor(sqrt((double)n));
        verts = verts < 2 ? 4 : verts * verts;
    }
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
    const long f1 = faults(0, &v1), g1 = faults(1, &v1);
    usr_sys(0, &pu[1], &ps[1]);
    usr_sys(1, &tu[1], &ts[1]);
    gupd_ws(1, GFLAG_PERFORM);
    double w2 = wall(), c2 = cpu(), a2 = clock_s(CLOCK_THREAD_CPUTIME_ID);
    const long f2 = faults(0, &v2), g2 = faults(1, &v2);
    usr_sys(0, &pu[2], &ps[2]);
    usr_sys(1, &tu[2], &ts[2]);
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
    printf("surface=%s verts=%ld ", surface, verts);
    printf("n=%ld calls=%.3f update=%.3f build=%.3f render=%.3f total=%.3f close=%.3f "
           "cpu=%.2f rss=%.1f B/tri=%.0f us/call=%.3f calls_cpu=%.3f update_cpu=%.3f "
           "cpu_us/call=%.3f app_us/call=%.3f upd_app_cpu=%.3f calls_flt=%ld app_flt=%ld "
           "upd_flt=%ld upd_app_flt=%ld app_waits=%ld upd_app_waits=%ld ",
           drawn, w1 - w0, w2 - w1, fl[0], fl[1], w2 - w0, w3 - w2, cpu(), rss / 1048576.0,
           rss / (double)drawn, 1e6 * (w1 - w0) / (double)drawn, c1 - c0, c2 - c1,
           1e6 * (c1 - c0) / (double)drawn, 1e6 * (a1 - a0) / (double)drawn, a2 - a1,
           diff(f0, f1), diff(g0, g1), diff(f1, f2), diff(g1, g2), diff(v0, v1), diff(v1, v2));
    printf("calls_usr=%.3f calls_sys=%.3f app_usr=%.3f app_sys=%.3f upd_usr=%.3f upd_sys=%.3f "
           "upd_app_usr=%.3f upd_app_sys=%.3f\n",
           fdiff(pu[0], pu[1]), fdiff(ps[0], ps[1]), fdiff(tu[0], tu[1]), fdiff(ts[0], ts[1]),
           fdiff(pu[1], pu[2]), fdiff(ps[1], ps[2]), fdiff(tu[1], tu[2]), fdiff(ts[1], ts[2]));
    return 0;
}
