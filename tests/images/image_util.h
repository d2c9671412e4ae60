/* SPDX-License-Identifier: MIT */
/* image_util.h -- PNG reading/writing, comparison with a tolerance and diff pictures for the
 * image regression tests (tests/images). */
#ifndef IMAGE_UTIL_H
#define IMAGE_UTIL_H
#include <stddef.h>

typedef struct {
    int w, h;
    unsigned char *rgb; /* 8-bit RGB, row 0 = top */
} img;

/* Reads path as 8-bit RGB; 0 on success, -1 (missing, unreadable, out of memory). */
int img_read(const char *path, img *im);
/* Writes im as an 8-bit RGB PNG; 0 on success. */
int img_write(const char *path, const img *im);
void img_free(img *im);

/* Comparison result: pixels whose largest channel difference exceeds tol, and the largest
 * difference of any channel. */
typedef struct {
    size_t n_over;
    int max_diff;
} img_cmp;

/* Compares two pictures of equal size (-1 if the sizes differ). When diff_path is not NULL
 * and some pixel exceeds tol, writes a diff picture there: the reference dimmed to a third,
 * pixels over tol in red (brightness = difference), pixels within tol but not equal in
 * yellow. */
int img_compare(const img *ref, const img *out, int tol, const char *diff_path, img_cmp *res);

/* 1 if the two files have identical bytes, 0 if not, -1 if one cannot be read. */
int file_same(const char *a, const char *b);
/* Copies file a to b; 0 on success. */
int file_copy(const char *a, const char *b);
#endif
