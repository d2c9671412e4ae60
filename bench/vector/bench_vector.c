/* SPDX-License-Identifier: MIT */
/*
 * bench_vector.c -- writes a 2-D plot of N primitives (default 10^5: polylines of 4 points,
 * polymarkers of 1 point, fill areas of 3 points and TEXTs of 4 characters, a quarter of
 * each, colours cycling) with HLHSR mode none on a PDF, SVG, PS and EPS workstation, and,
 * for comparison, the PNG workstation at the same pixel grid (0.2 mm per pixel; run first).
 * Prints per type the wall and CPU seconds from OPEN to CLOSE WORKSTATION, the CPU time
 * as a multiple of PNG's and the file size. Figures: docs/bench/vector.md.
 * Usage: bench_vector [DIR [N]] (files DIR/bench_vector.<type>, default DIR = .).
 * Not a test: the goal (10^5 primitives in under 2 s) is read from its output.
 */
#include <gks.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <time.h>

static double now(clockid_t c)
{
    struct timespec t;
    clock_gettime(c, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* A deterministic pseudo-random number in [0, 1). */
static float rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (float)(*s >> 8) / 16777216.0f;
}

static void plot(long n)
{
    unsigned s = 12345;
    for (long i = 0; i < n; i++) {
        float x = 0.05f + 0.9f * rnd(&s), y = 0.05f + 0.9f * rnd(&s);
        int c = 1 + (int)(i % 7);
        switch (i % 4) {
        case 0: {
            Gpoint p[4];
            for (int k = 0; k < 4; k++)
                p[k] = (Gpoint){ x + 0.01f * (float)k, y + 0.01f * rnd(&s) };
            Gpoint_list l = { 4, p };
            gset_line_colr_ind(c);
            gpolyline(&l);
            break;
        }
        case 1: {
            Gpoint p = { x, y };
            Gpoint_list l = { 1, &p };
            gset_marker_colr_ind(c);
            gpolymarker(&l);
            break;
        }
        case 2: {
            Gpoint p[3] = { { x, y }, { x + 0.01f, y }, { x, y + 0.01f } };
            Gpoint_list l = { 3, p };
            gset_fill_colr_ind(c);
            gfill_area(&l);
            break;
        }
        default: {
            Gpoint p = { x, y };
            gset_text_colr_ind(c);
            gtext(&p, "GKS3");
            break;
        }
        }
    }
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    long n = argc > 2 ? strtol(argv[2], NULL, 10) : 100000;
    if (n < 1 || n > 100000000)
        return 2;
    static const struct { const char *ext; Gint type; } types[] = {
        { "png", GWS_TYPE_PNG }, { "pdf", GWS_TYPE_PDF }, { "svg", GWS_TYPE_SVG },
        { "ps", GWS_TYPE_PS }, { "eps", GWS_TYPE_EPS },
    };
    double png_cpu = 0; /* the peer of the same run: the CPU ratio to PNG is printed */
    gopen_gks(NULL, 0);
    gset_char_ht(0.004f);
    gset_marker_type(3);
    gset_fill_int_style(GSTYLE_SOLID);
    printf("bench_vector: %ld primitives, 0.2 m page (PNG: 1000 pixels), HLHSR mode none\n", n);
    for (int t = 0; t < 5; t++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/bench_vector.%s", dir, types[t].ext);
        double w0 = now(CLOCK_MONOTONIC), c0 = now(CLOCK_PROCESS_CPUTIME_ID);
        gopen_ws(1, path, types[t].type);
        float side = types[t].type == GWS_TYPE_PNG ? 1000.0f : 0.2f;
        Glimit win = { 0, 1, 0, 1 }, vp = { 0, side, 0, side };
        gset_ws_win(1, &win);
        gset_ws_vp(1, &vp);
        gactivate_ws(1);
        plot(n);
        gdeactivate_ws(1);
        gclose_ws(1);
        double w1 = now(CLOCK_MONOTONIC), c1 = now(CLOCK_PROCESS_CPUTIME_ID);
        struct stat st;
        long long size = stat(path, &st) == 0 ? (long long)st.st_size : -1;
        if (t == 0)
            png_cpu = c1 - c0;
        printf("%-4s wall %6.3f s  cpu %6.3f s (%5.1f x PNG)  file %9lld bytes (%.1f MB)\n",
               types[t].ext, w1 - w0, c1 - c0, png_cpu > 0 ? (c1 - c0) / png_cpu : 0.0, size,
               (double)size / 1e6);
    }
    gclose_gks();
    return 0;
}
