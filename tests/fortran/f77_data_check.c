/* SPDX-License-Identifier: MIT */
/*
 * f77_data_check -- runs f77_data (Fortran) and f77_data_twin (C), which draw the same
 * primitives with data, requires both PASS lines, then compares their outputs exactly:
 * the PNGs sample by sample (0 differing samples: the same calls must give the same
 * picture) and the metafiles item by item (the bytes after the 90-character header, which
 * holds the date).
 */
#include "raster.h"
#include "gks_alloc.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int run(const char *prog, const char *want)
{
    FILE *p = popen(prog, "r");
    if (!p)
        return 0;
    char line[512];
    int pass = 0;
    while (fgets(line, sizeof line, p)) {
        fputs(line, stdout);
        pass |= strstr(line, want) != NULL;
    }
    return pclose(p) == 0 && pass;
}

static char *slurp(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *b = malloc((size_t)*n + 1);
    if (b && fread(b, 1, (size_t)*n, f) != (size_t)*n) {
        free(b);
        b = NULL;
    }
    fclose(f);
    return b;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s F77_PROGRAM C_PROGRAM\n", argv[0]);
        return 2;
    }
    remove("gks21.png");
    remove("c21.png");
    if (!run(argv[1], "F77 DATA PASS") || !run(argv[2], "C DATA PASS")) {
        printf("FAIL: a program did not pass\n");
        return 1;
    }
    int w1, h1, w2, h2;
    unsigned char *a, *b;
    if (gks_raster_png_read_rgb8("gks21.png", &w1, &h1, &a) != GKS_RASTER_OK ||
        gks_raster_png_read_rgb8("c21.png", &w2, &h2, &b) != GKS_RASTER_OK || w1 != w2 ||
        h1 != h2) {
        printf("FAIL: PNGs missing or of different sizes\n");
        return 1;
    }
    size_t n = (size_t)w1 * (size_t)h1 * 3, diff = 0, ink = 0;
    for (size_t i = 0; i < n; i++) {
        diff += a[i] != b[i];
        ink += a[i] != 255;
    }
    gks_free(a);
    gks_free(b);
    printf("%zu differing samples, %zu samples drawn\n", diff, ink);
    long na = 0, nb = 0;
    char *ma = slurp("gks22.gksm", &na), *mb = slurp("c22.gksm", &nb);
    int mf_same = ma && mb && na == nb && na > 90 && memcmp(ma + 90, mb + 90, (size_t)na - 90) == 0;
    int items = 0;
    for (long i = 90; ma && i + 7 <= na; i++)
        if (memcmp(ma + i, "GKSM 7", 6) == 0 || memcmp(ma + i, "GKSM 8", 6) == 0)
            items++; /* items 76..89: the primitives with data among them */
    printf("metafiles %s (%ld and %ld bytes, %d items 7x/8x)\n", mf_same ? "equal" : "DIFFER",
           na, nb, items);
    free(ma);
    free(mb);
    if (diff || ink < 1000 || !mf_same || items < 5) {
        printf("FAIL\n");
        return 1;
    }
    return 0;
}
