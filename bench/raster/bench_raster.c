/* SPDX-License-Identifier: MIT */
/*
 * bench_raster.c -- timings of the raster module at 1024 x 1024, single thread:
 *   tri16   10^6 random z-buffered triangles, vertices within a 16 px box
 *   tri128  10^6 random z-buffered triangles, vertices within a 128 px box
 *   eq16    10^6 random z-buffered equilateral triangles of side 16 px (111 px area)
 *   eq128   the same with side 128 px (7094 px area, the demanding reading of "128 px")
 *   walk    one 10^7-point random-walk polyline, 1 px, solid
 * Reference figures (Mesa llvmpipe, single thread): tri16 1.18 s, tri128 10.3 s,
 * walk 1.88 s. Usage: bench_raster [tri16|tri128|eq16|eq128|walk|all] [count] [out.png]
 * (the raster module alone, wall time; bench_gks runs the same rows through the whole GKS
 * call path with peak memory and the OSMesa comparison in the same run).
 */
#include "raster.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static uint64_t rng = 0x9E3779B97F4A7C15ull;
static double urand(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return (double)((rng * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int bench_tris(gks_raster_fb *fb, size_t n, double size, int equilateral,
                      const char *png)
{
    gks_raster_pt *p = malloc(3 * n * sizeof *p);
    float *c = malloc(3 * n * sizeof *c);
    if (!p || !c)
        return 1;
    for (size_t t = 0; t < n; t++) {
        double cx = urand() * 1024, cy = urand() * 1024, a = urand() * 6.283185307179586;
        for (int k = 0; k < 3; k++) {
            double r = size / 1.7320508075688772, ak = a + k * 2.0943951023931957;
            p[3 * t + k] = equilateral
                ? (gks_raster_pt){cx + r * cos(ak), cy + r * sin(ak), urand()}
                : (gks_raster_pt){cx + (urand() - 0.5) * size, cy + (urand() - 0.5) * size,
                                  urand()};
        }
        for (int k = 0; k < 3; k++)
            c[3 * t + k] = (float)urand();
    }
    gks_raster_fb_clear(fb, NULL);
    gks_raster_fill f = {.style = GKS_RASTER_SOLID, .zmode = GKS_RASTER_Z_TEST};
    double t0 = now();
    int rc = gks_raster_triangles(fb, n, p, c, &f);
    double dt = now() - t0;
    printf("%s%-4g %zu triangles: %.3f s (%.1f ns/triangle) rc %d\n",
           equilateral ? "eq" : "tri", size, n, dt, 1e9 * dt / n, rc);
    if (png)
        gks_raster_fb_write_png(fb, png, GKS_RASTER_PNG_FAST);
    free(p);
    free(c);
    return rc;
}

static int bench_walk(gks_raster_fb *fb, size_t n, const char *png)
{
    gks_raster_pt *p = malloc(n * sizeof *p);
    if (!p)
        return 1;
    double x = 512, y = 512;
    for (size_t i = 0; i < n; i++) {
        x += (urand() - 0.5) * 4;
        y += (urand() - 0.5) * 4;
        if (x < 0 || x > 1024)
            x = 512;
        if (y < 0 || y > 1024)
            y = 512;
        p[i] = (gks_raster_pt){x, y, 0.5};
    }
    gks_raster_fb_clear(fb, NULL);
    gks_raster_line a = {.rgb = {1, 1, 1}, .width = 1, .type = 1};
    double t0 = now();
    int rc = gks_raster_polyline(fb, n, p, &a);
    double dt = now() - t0;
    printf("walk    %zu points: %.3f s (%.1f ns/segment) rc %d\n", n, dt, 1e9 * dt / n, rc);
    if (png)
        gks_raster_fb_write_png(fb, png, GKS_RASTER_PNG_FAST);
    free(p);
    return rc;
}

int main(int argc, char **argv)
{
    const char *what = argc > 1 ? argv[1] : "all";
    size_t n = argc > 2 ? strtoull(argv[2], NULL, 10) : 0;
    const char *png = argc > 3 ? argv[3] : NULL;
    gks_raster_fb *fb = gks_raster_fb_create(1024, 1024, 1);
    if (!fb)
        return 1;
    int all = strcmp(what, "all") == 0, rc = 0;
    if (all || strcmp(what, "tri16") == 0)
        rc |= bench_tris(fb, n ? n : 1000000, 16, 0, png);
    if (all || strcmp(what, "tri128") == 0)
        rc |= bench_tris(fb, n ? n : 1000000, 128, 0, png);
    if (all || strcmp(what, "eq16") == 0)
        rc |= bench_tris(fb, n ? n : 1000000, 16, 1, png);
    if (all || strcmp(what, "eq128") == 0)
        rc |= bench_tris(fb, n ? n : 1000000, 128, 1, png);
    if (all || strcmp(what, "walk") == 0)
        rc |= bench_walk(fb, n ? n : 10000000, png);
    gks_raster_fb_free(fb);
    return rc != 0;
}
