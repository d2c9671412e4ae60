/* SPDX-License-Identifier: MIT */
/*
 * f77_png_check.c -- runs examples/f77/hello (hello_f77) in the current directory and checks
 * gks1.png: 1024x1024 (PNG workstation display space, default workstation viewport), a red
 * triangle interior, a blue 1-pixel outline at NDC 0.05/0.95, white elsewhere.
 * Tolerance: interior and background pixels must be exact (solid fill, no antialiasing in
 * the rasterizer); line pixels are searched within +-2 pixels of the exact position,
 * since NDC 0.05 * 1024 = 51.2 lands between pixel centres.
 * Usage: f77_png_check PROGRAM
 */
#define _POSIX_C_SOURCE 200809L
#include "raster.h"
#include <stdio.h>
#include <stdlib.h>

static const unsigned char *px(const unsigned char *rgb, int w, int x, int y)
{
    return rgb + 3 * ((size_t)y * (size_t)w + (size_t)x);
}

static int is(const unsigned char *p, int r, int g, int b)
{
    return p[0] == r && p[1] == g && p[2] == b;
}

/* Pixel (column, row) of an NDC point in a w x h image (row 0 at the top). */
static void ndc_px(double x, double y, int w, int h, int *cx, int *cy)
{
    *cx = (int)(x * w);
    *cy = (int)((1.0 - y) * h);
}

static int check(const unsigned char *rgb, int w, int h, double x, double y, int r, int g,
                 int b, int radius, const char *what)
{
    int cx, cy;
    ndc_px(x, y, w, h, &cx, &cy);
    for (int dy = -radius; dy <= radius; dy++)
        for (int dx = -radius; dx <= radius; dx++) {
            int X = cx + dx, Y = cy + dy;
            if (X >= 0 && Y >= 0 && X < w && Y < h && is(px(rgb, w, X, Y), r, g, b))
                return 0;
        }
    const unsigned char *p = px(rgb, w, cx, cy);
    printf("%s at (%d,%d): got %d %d %d want %d %d %d\n", what, cx, cy, p[0], p[1], p[2], r,
           g, b);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s PROGRAM\n", argv[0]);
        return 2;
    }
    remove("gks1.png");
    if (system(argv[1]) != 0) {
        printf("program failed\n");
        return 1;
    }
    int w = 0, h = 0;
    unsigned char *rgb = NULL;
    if (gks_raster_png_read_rgb8("gks1.png", &w, &h, &rgb) != 0 || !rgb) {
        printf("cannot read gks1.png\n");
        return 1;
    }
    int f = 0;
    if (w != 1024 || h != 1024) {
        printf("size %dx%d, want 1024x1024\n", w, h);
        free(rgb);
        return 1;
    }
    f += check(rgb, w, h, 0.5, 0.3667, 255, 0, 0, 0, "triangle centroid");
    f += check(rgb, w, h, 0.2, 0.15, 255, 0, 0, 0, "triangle near left corner");
    f += check(rgb, w, h, 0.8, 0.15, 255, 0, 0, 0, "triangle near right corner");
    f += check(rgb, w, h, 0.5, 0.85, 255, 0, 0, 0, "triangle near apex");
    f += check(rgb, w, h, 0.2, 0.8, 255, 255, 255, 0, "background inside outline");
    f += check(rgb, w, h, 0.02, 0.5, 255, 255, 255, 0, "background outside outline");
    f += check(rgb, w, h, 0.5, 0.07, 255, 255, 255, 0, "background below triangle");
    f += check(rgb, w, h, 0.05, 0.5, 0, 0, 255, 2, "left outline");
    f += check(rgb, w, h, 0.95, 0.5, 0, 0, 255, 2, "right outline");
    f += check(rgb, w, h, 0.5, 0.95, 0, 0, 255, 2, "top outline");
    f += check(rgb, w, h, 0.5, 0.05, 0, 0, 255, 2, "bottom outline");
    free(rgb);
    printf("%d failures\n", f);
    return f ? 1 : 0;
}
