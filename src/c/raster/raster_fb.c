/* SPDX-License-Identifier: MIT */
/*
 * raster_fb.c -- framebuffer: creation, clearing and the box-filter resolve to 8 bits.
 */
#include "raster.h"
#include "gks_alloc.h"
#include <math.h>
#include <stdint.h>

gks_raster_fb *gks_raster_fb_create(int width, int height, int ss)
{
    gks_raster_fb *fb = gks_raster_fb_alloc(width, height, ss);
    gks_raster_fb_clear(fb, NULL);
    return fb;
}

gks_raster_fb *gks_raster_fb_alloc(int width, int height, int ss)
{
    if (width < 1 || height < 1 || width > 65536 || height > 65536 || ss < 1 || ss > 4)
        return NULL;
    gks_raster_fb *fb = gks_calloc_array(1, sizeof *fb);
    if (!fb)
        return NULL;
    fb->width = width;
    fb->height = height;
    fb->ss = ss;
    fb->w = width * ss;
    fb->h = height * ss;
    size_t n = (size_t)fb->w; /* w*h checked by the funnel: n, then n*3 */
    if ((size_t)fb->h > SIZE_MAX / n) {
        gks_free(fb);
        return NULL;
    }
    n *= (size_t)fb->h;
    fb->z = gks_alloc_array(n, sizeof *fb->z);
    fb->rgb = n <= SIZE_MAX / 3 ? gks_alloc_array(n * 3, sizeof *fb->rgb) : NULL;
    if (!fb->z || !fb->rgb) {
        gks_raster_fb_free(fb);
        return NULL;
    }
    return fb;
}

void gks_raster_fb_free(gks_raster_fb *fb)
{
    if (!fb)
        return;
    gks_free(fb->rgb);
    gks_free(fb->z);
    gks_free(fb);
}

static float clamp01(float v)
{
    if (!(v > 0.0f)) /* also NaN */
        return 0.0f;
    return v < 1.0f ? v : 1.0f;
}

void gks_raster_fb_clear(gks_raster_fb *fb, const float rgb[3])
{
    if (fb)
        gks_raster_fb_clear_rows(fb, rgb, 0, fb->h);
}

void gks_raster_fb_clear_rows(gks_raster_fb *fb, const float rgb[3], int y0, int y1)
{
    if (!fb || y0 < 0 || y1 > fb->h || y0 >= y1)
        return;
    float c[3] = {0.0f, 0.0f, 0.0f};
    if (rgb)
        for (int k = 0; k < 3; k++)
            c[k] = clamp01(rgb[k]);
    size_t n = (size_t)fb->w * (size_t)y1;
    for (size_t i = (size_t)fb->w * (size_t)y0; i < n; i++) {
        fb->rgb[3 * i] = c[0];
        fb->rgb[3 * i + 1] = c[1];
        fb->rgb[3 * i + 2] = c[2];
        fb->z[i] = -INFINITY;
    }
}

/* One channel value in [0,1] (NaN -> 0) to 0..255, rounded to nearest (ties to even, as
 * lrintf in the default rounding mode; the sum is exact in float for ss <= 4). */
static unsigned char to_byte(float v)
{
    return (unsigned char)lrintf(v * 255.0f);
}

int gks_raster_fb_resolve_row(const gks_raster_fb *fb, int row, unsigned char *out)
{
    if (!fb || !out || row < 0 || row >= fb->height)
        return GKS_RASTER_E_ARG;
    int ss = fb->ss;
    int y = fb->height - 1 - row; /* framebuffer rows run bottom-up */
    if (ss == 1) {
        const float *p = fb->rgb + 3 * (size_t)y * (size_t)fb->w;
        size_t n = 3 * (size_t)fb->width;
        for (size_t i = 0; i < n; i++)
            out[i] = to_byte(clamp01(p[i]));
        return GKS_RASTER_OK;
    }
    float scale = 255.0f / (float)(ss * ss);
    for (int x = 0; x < fb->width; x++) {
        float acc[3] = {0.0f, 0.0f, 0.0f};
        for (int sy = 0; sy < ss; sy++) {
            const float *p = fb->rgb + 3 * ((size_t)(y * ss + sy) * (size_t)fb->w +
                                            (size_t)x * (size_t)ss);
            for (int sx = 0; sx < ss; sx++)
                for (int k = 0; k < 3; k++)
                    acc[k] += clamp01(p[3 * sx + k]);
        }
        for (int k = 0; k < 3; k++)
            out[3 * x + k] = (unsigned char)lrintf(acc[k] * scale);
    }
    return GKS_RASTER_OK;
}
