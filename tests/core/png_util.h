/* SPDX-License-Identifier: MIT */
/* png_util.h -- the PNG workstation of the core tests: opened for a picture, and its PNG
 * read back for pixel checks. */
#ifndef PNG_UTIL_H
#define PNG_UTIL_H
#include <gks.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

typedef struct { int w, h; unsigned char *rgb; } image;

/* Read an 8-bit RGB image (row 0 = top); 1 on success. Free img->rgb. */
static inline int read_png(const char *path, image *img)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    img->w = img->h = 0;
    img->rgb = NULL;
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path))
        return 0;
    pi.format = PNG_FORMAT_RGB;
    img->w = (int)pi.width;
    img->h = (int)pi.height;
    img->rgb = malloc(PNG_IMAGE_SIZE(pi));
    if (!img->rgb || !png_image_finish_read(&pi, NULL, img->rgb, 0, NULL)) {
        free(img->rgb);
        img->rgb = NULL;
        return 0;
    }
    return 1;
}

/* GKS opened and workstation 1 open and active, writing file (removed first): an s x s
 * pixel PNG of the unit square in HLHSR mode `mode`; with one_ray (ray tracing) one ray
 * per pixel centre and no depth cut-off, so that a pixel is a plain sample of the scene. */
static inline void png_ws_open(const char *file, int s, int mode, int one_ray)
{
    unlink(file);
    gopen_gks(NULL, 0);
    gopen_ws(1, file, GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit win = { 0, 1, 0, 1 }, vp = { 0, (Gfloat)s, 0, (Gfloat)s };
    gset_ws_win(1, &win);
    gset_ws_vp(1, &vp);
    gset_hlhsr_mode(1, mode);
    if (one_ray && mode == GHLHSR_RAYTRACE) {
        Gint ints[2] = { 1, 1 };
        Gfloat zero[1] = { 0.0 };
        Gescape_in_data in = { .num_ints = 2, .ints = ints, .num_floats = 1, .floats = zero };
        gescape(GESC_RT_SAMPLES, &in, NULL, NULL);
        gescape(GESC_RT_CUTOFF, &in, NULL, NULL);
    }
}

/* Pixel (x, y) with y counted from the BOTTOM row (DC convention). */
static inline const unsigned char *px(const image *img, int x, int y)
{
    return img->rgb + 3 * ((size_t)(img->h - 1 - y) * img->w + x);
}
#endif
