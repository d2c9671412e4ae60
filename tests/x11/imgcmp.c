/* SPDX-License-Identifier: MIT */
/*
 * imgcmp.c -- test helper: compares two PNG pictures of equal size.
 *   imgcmp same A B     exit 0 when they agree within the image tests' tolerance
 *                       (tests/images/test_images.c: a pixel differs when a channel differs
 *                       by more than 1 level; at most 1 in 1000 pixels may differ)
 *   imgcmp differ A B   exit 0 when they clearly differ: at least 5 % of the pixels by
 *                       more than 16 levels (a turned view, not noise)
 * Prints the count of pixels over the tolerance and the largest difference; exit 1 when
 * the test fails, 2 when a file cannot be read or the sizes differ.
 */
#include "image_util.h"
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 4)
        return 2;
    int same = strcmp(argv[1], "same") == 0;
    img a, b;
    if (img_read(argv[2], &a) || img_read(argv[3], &b))
        return 2;
    img_cmp r;
    if (img_compare(&a, &b, same ? 1 : 16, NULL, &r))
        return 2;
    size_t n = (size_t)a.w * (size_t)a.h;
    int ok = same ? r.n_over <= n / 1000 : r.n_over >= n / 20;
    printf("imgcmp %s: %zu of %zu pixels over %d levels, max difference %d: %s\n", argv[1],
           r.n_over, n, same ? 1 : 16, r.max_diff, ok ? "ok" : "FAIL");
    img_free(&a);
    img_free(&b);
    return ok ? 0 : 1;
}
