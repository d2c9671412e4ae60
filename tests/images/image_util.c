/* SPDX-License-Identifier: MIT */
/* image_util.c -- see image_util.h. */
#include "image_util.h"
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int img_read(const char *path, img *im)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    memset(im, 0, sizeof *im);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path))
        return -1;
    pi.format = PNG_FORMAT_RGB;
    if (pi.width == 0 || pi.height == 0 || pi.width > 65536 || pi.height > 65536) {
        png_image_free(&pi);
        return -1;
    }
    im->w = (int)pi.width;
    im->h = (int)pi.height;
    im->rgb = malloc(PNG_IMAGE_SIZE(pi));
    if (!im->rgb || !png_image_finish_read(&pi, NULL, im->rgb, 0, NULL)) {
        png_image_free(&pi);
        img_free(im);
        return -1;
    }
    return 0;
}

int img_write(const char *path, const img *im)
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = (png_uint_32)im->w;
    pi.height = (png_uint_32)im->h;
    pi.format = PNG_FORMAT_RGB;
    return png_image_write_to_file(&pi, path, 0, im->rgb, 0, NULL) ? 0 : -1;
}

void img_free(img *im)
{
    free(im->rgb);
    im->rgb = NULL;
    im->w = im->h = 0;
}

int img_compare(const img *ref, const img *out, int tol, const char *diff_path, img_cmp *res)
{
    res->n_over = 0;
    res->max_diff = 0;
    if (ref->w != out->w || ref->h != out->h)
        return -1;
    size_t n = (size_t)ref->w * (size_t)ref->h;
    unsigned char *d = diff_path ? malloc(3 * n) : NULL;
    for (size_t i = 0; i < n; i++) {
        int m = 0;
        for (int c = 0; c < 3; c++) {
            int v = abs((int)ref->rgb[3 * i + c] - (int)out->rgb[3 * i + c]);
            m = v > m ? v : m;
        }
        res->max_diff = m > res->max_diff ? m : res->max_diff;
        res->n_over += m > tol;
        if (!d)
            continue;
        unsigned char grey = (unsigned char)((ref->rgb[3 * i] + ref->rgb[3 * i + 1] +
                                              ref->rgb[3 * i + 2]) / 9);
        unsigned char *p = d + 3 * i;
        p[0] = p[1] = p[2] = grey;
        if (m > tol) {
            p[0] = (unsigned char)(m < 64 ? 128 + 2 * m : 255);
            p[1] = p[2] = 0;
        } else if (m > 0) {
            p[0] = p[1] = 200;
            p[2] = 0;
        }
    }
    if (d && res->n_over > 0) {
        img di = { ref->w, ref->h, d };
        if (img_write(diff_path, &di))
            fprintf(stderr, "cannot write %s\n", diff_path);
        else
            fprintf(stderr, "diff picture: %s\n", diff_path);
    }
    free(d);
    return 0;
}

/* Whole file into memory (at most 64 MiB); NULL on failure. */
static unsigned char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    unsigned char *b = malloc(cap);
    while (b) {
        n += fread(b + n, 1, cap - n, f);
        if (n < cap || cap >= ((size_t)64 << 20))
            break;
        unsigned char *nb = realloc(b, cap * 2);
        if (!nb) {
            free(b);
            b = NULL;
            break;
        }
        b = nb;
        cap *= 2;
    }
    if (b && ferror(f)) {
        free(b);
        b = NULL;
    }
    fclose(f);
    *len = n;
    return b;
}

int file_same(const char *a, const char *b)
{
    size_t la = 0, lb = 0;
    unsigned char *pa = slurp(a, &la), *pb = slurp(b, &lb);
    int r = !pa || !pb ? -1 : la == lb && memcmp(pa, pb, la) == 0;
    free(pa);
    free(pb);
    return r;
}

int file_copy(const char *a, const char *b)
{
    size_t n = 0;
    unsigned char *p = slurp(a, &n);
    if (!p)
        return -1;
    FILE *f = fopen(b, "wb");
    int r = f && fwrite(p, 1, n, f) == n ? 0 : -1;
    if (f && fclose(f))
        r = -1;
    free(p);
    return r;
}
