/* SPDX-License-Identifier: MIT */
/* png_util.h -- reading a workstation's PNG back for pixel checks in the core tests. */
#ifndef PNG_UTIL_H
#define PNG_UTIL_H
#include <png.h>
#include <stdlib.h>
#include <string.h>

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

/* Pixel (x, y) with y counted from the BOTTOM row (DC convention). */
static inline const unsigned char *px(const image *img, int x, int y)
{
    return img->rgb + 3 * ((size_t)(img->h - 1 - y) * img->w + x);
}
#endif
