/* SPDX-License-Identifier: MIT */
/*
 * f77_view3_check -- runs f77_view3 (the GKS-3D slice through the Fortran binding), requires
 * its "F77 VIEW3 PASS" line, then checks gks3.png pixel by pixel (exact: z-buffered flat
 * fills sample pixel centres, and the squares cross between two pixel columns):
 * blue where B is nearer (x < 8), red where A is (x >= 8).
 */
#include "raster.h"
#include "gks_alloc.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s PROGRAM\n", argv[0]);
        return 2;
    }
    FILE *p = popen(argv[1], "r");
    if (!p)
        return 1;
    char line[512];
    int pass = 0;
    while (fgets(line, sizeof line, p)) {
        fputs(line, stdout);
        pass |= strstr(line, "F77 VIEW3 PASS") != NULL;
    }
    if (pclose(p) != 0 || !pass) {
        printf("FAIL: program did not pass\n");
        return 1;
    }
    int w, h;
    unsigned char *rgb;
    if (gks_raster_png_read_rgb8("gks3.png", &w, &h, &rgb) != GKS_RASTER_OK || w != 16 || h != 8) {
        printf("FAIL: gks3.png missing or not 16x8\n");
        return 1;
    }
    int bad = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const unsigned char *c = rgb + 3 * (y * w + x);
            int want_r = x >= 8 ? 255 : 0, want_b = x >= 8 ? 0 : 255;
            if (c[0] != want_r || c[1] != 0 || c[2] != want_b)
                bad++;
        }
    gks_free(rgb);
    printf("%d wrong pixels\n", bad);
    return bad != 0;
}
