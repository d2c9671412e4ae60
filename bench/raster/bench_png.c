/* SPDX-License-Identifier: MIT */
/*
 * bench_png.c -- PNG encoding cost of the PNG workstation's compression settings
 * (ESCAPE GESC_PNG_COMPRESSION): each input PNG is decoded once, then written with the
 * fast default (zlib run-length strategy, SUB row filter) and with zlib levels 1, 6
 * (libpng's default) and 9 with adaptive row filters; prints CPU milliseconds (best of
 * 3) and file size, and the ratios against level 6.
 *   Usage: bench_png OUT_DIR FILE.png...
 */
#include "raster.h"
#include "gks_alloc.h"
#include <stdio.h>
#include <sys/stat.h>
#include <time.h>

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static const struct { const char *name; int compression; } settings[] = {
    { "fast", GKS_RASTER_PNG_FAST }, { "zlib1", 1 }, { "zlib6", 6 }, { "zlib9", 9 },
};
enum { NSET = sizeof settings / sizeof settings[0], LEVEL6 = 2 };

static int bench_file(const char *out, const char *path)
{
    int w, h;
    unsigned char *rgb8 = NULL;
    if (gks_raster_png_read_rgb8(path, &w, &h, &rgb8) != GKS_RASTER_OK) {
        fprintf(stderr, "bench_png: cannot read %s\n", path);
        return 1;
    }
    double ms[NSET];
    long bytes[NSET];
    for (int k = 0; k < NSET; k++) {
        ms[k] = 1e30;
        for (int rep = 0; rep < 3; rep++) {
            double t0 = cpu_now();
            if (gks_raster_png_write_rgb8(out, w, h, rgb8, settings[k].compression)) {
                fprintf(stderr, "bench_png: cannot write %s\n", out);
                gks_free(rgb8);
                return 1;
            }
            double dt = 1e3 * (cpu_now() - t0);
            ms[k] = dt < ms[k] ? dt : ms[k];
        }
        struct stat st;
        bytes[k] = stat(out, &st) == 0 ? (long)st.st_size : -1;
    }
    const char *base = path;
    for (const char *c = path; *c; c++)
        if (*c == '/')
            base = c + 1;
    printf("%-24s %5dx%-5d", base, w, h);
    for (int k = 0; k < NSET; k++)
        printf(" | %7.2f ms %9ld B", ms[k], bytes[k]);
    printf(" | fast/zlib6 time %.2f size %.2f\n", ms[0] / ms[LEVEL6],
           (double)bytes[0] / (double)bytes[LEVEL6]);
    gks_free(rgb8);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: bench_png OUT_DIR FILE.png...\n");
        return 2;
    }
    char out[4096];
    snprintf(out, sizeof out, "%s/bench_png_out.png", argv[1]);
    printf("%-24s %11s", "image", "size");
    for (int k = 0; k < NSET; k++)
        printf(" | %-22s", settings[k].name);
    printf(" |\n");
    int rc = 0;
    for (int i = 2; i < argc; i++)
        rc |= bench_file(out, argv[i]);
    remove(out);
    return rc;
}
