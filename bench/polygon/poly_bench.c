/* SPDX-License-Identifier: MIT */
/*
 * poly_bench.c -- one big self-intersecting FILL AREA 3 through the whole GKS call path
 * (issue 20): the same polygon drawn by a 256 x 256 PNG workstation in HLHSR mode 0 (no
 * HLHSR), 2 (z-buffer) and 4 (ray tracing, one thread, corner rays as by default), CPU
 * seconds of FILL AREA 3 + UPDATE WORKSTATION (the tracer's grid build and tracing happen
 * at UPDATE) and the ratio ray-traced / z-buffer. Shapes, N vertices around (0.5, 0.5):
 *   star    vertex i at angle 2 pi (i k mod N) / N, k = N/2 - 1 made prime to N: every
 *           edge nearly a diameter, the polygon winds k times around the centre
 *   spiral  T = sqrt(N) turns inwards (radius 0.45 -> 0.225) and one edge back out across
 *           all of them: winding numbers 0..T
 *   random  vertices uniform in the square [0.05, 0.95]^2 (random chords)
 * Usage: poly_bench [-s SIZE] [-t THREADS] [shape:N ...]  (default star:1000000
 * spiral:1000000). The pictures: poly_<shape>_m<mode>.png in the working directory.
 */
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* CPU seconds of the process (the machines are shared; the tracer runs one thread) */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static long gcd(long a, long b)
{
    while (b) {
        long t = a % b;
        a = b;
        b = t;
    }
    return a;
}

static Gpoint3 *make(const char *shape, long n)
{
    Gpoint3 *p = malloc((size_t)n * sizeof *p);
    if (!p)
        return NULL;
    const double tau = 6.283185307179586;
    if (strcmp(shape, "star") == 0) {
        long k = n / 2 - 1;
        while (k > 1 && gcd(k, n) != 1)
            k--;
        for (long i = 0; i < n; i++) {
            double a = tau * (double)((i * k) % n) / (double)n;
            p[i] = (Gpoint3){ 0.5 + 0.45 * cos(a), 0.5 + 0.45 * sin(a), 0.5 };
        }
    } else if (strcmp(shape, "spiral") == 0) {
        double turns = floor(sqrt((double)n));
        for (long i = 0; i < n; i++) {
            double s = (double)i / (double)n, a = tau * turns * s, r = 0.45 * (1.0 - 0.5 * s);
            p[i] = (Gpoint3){ 0.5 + r * cos(a), 0.5 + r * sin(a), 0.5 };
        }
    } else if (strcmp(shape, "random") == 0) {
        unsigned long long x = 88172645463325252ull;
        for (long i = 0; i < n; i++) {
            double c[2];
            for (int j = 0; j < 2; j++) {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                c[j] = 0.05 + 0.9 * (double)(x >> 11) / 9007199254740992.0;
            }
            p[i] = (Gpoint3){ c[0], c[1], 0.5 };
        }
    } else {
        free(p);
        return NULL;
    }
    return p;
}

static double run(const Gpoint3 *p, long n, int mode, int size, int threads, const char *file)
{
    unlink(file);
    gopen_ws(1, file, GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_win(1, &(Glimit){ 0, 1, 0, 1 });
    gset_ws_vp(1, &(Glimit){ 0, size, 0, size });
    gset_hlhsr_mode(1, mode);
    Gint ints[2] = { 1, threads };
    gescape(GESC_RT_THREADS, &(Gescape_in_data){ .num_ints = 2, .ints = ints }, NULL, NULL);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(4);
    gupd_ws(1, GFLAG_PERFORM); /* the empty frame: buffers allocated */
    gclear_ws(1, GFLAG_ALWAYS);
    double t0 = now();
    gfill_area3(&(Gpoint_list3){ (Gint)n, (Gpoint3 *)p });
    gupd_ws(1, GFLAG_PERFORM);
    double t = now() - t0;
    gdeactivate_ws(1);
    gclose_ws(1);
    return t;
}

int main(int argc, char **argv)
{
    int size = 256, threads = 1, a = 1;
    for (; a < argc && argv[a][0] == '-'; a += 2) {
        if (a + 1 >= argc)
            return 2;
        if (strcmp(argv[a], "-s") == 0)
            size = atoi(argv[a + 1]);
        else if (strcmp(argv[a], "-t") == 0)
            threads = atoi(argv[a + 1]);
        else
            return 2;
    }
    const char *defaults[] = { "star:1000000", "spiral:1000000" };
    int nrows = a < argc ? argc - a : 2;
    gopen_gks(NULL, 0);
    printf("%-8s %8s %10s %10s %10s %8s   (%d x %d pixels, tracer threads %d)\n", "shape", "N",
           "mode0 s", "zbuf s", "traced s", "rt/zbuf", size, size, threads);
    for (int r = 0; r < nrows; r++) {
        const char *row = a < argc ? argv[a + r] : defaults[r];
        char shape[32];
        long n = 0;
        if (sscanf(row, "%31[a-z]:%ld", shape, &n) != 2 || n < 3) {
            fprintf(stderr, "poly_bench: bad row %s\n", row);
            return 2;
        }
        Gpoint3 *p = make(shape, n);
        if (!p) {
            fprintf(stderr, "poly_bench: unknown shape %s\n", shape);
            return 2;
        }
        double t[3];
        const int modes[3] = { GHLHSR_NONE, GHLHSR_ZBUFFER, GHLHSR_RAYTRACE };
        for (int m = 0; m < 3; m++) {
            char file[64];
            snprintf(file, sizeof file, "poly_%s_m%d", shape, modes[m]);
            t[m] = run(p, n, modes[m], size, threads, file);
        }
        printf("%-8s %8ld %10.3f %10.3f %10.3f %8.2f\n", shape, n, t[0], t[1], t[2],
               t[2] / t[1]);
        fflush(stdout);
        free(p);
    }
    gclose_gks();
    return 0;
}
