/* SPDX-License-Identifier: MIT */
/*
 * ncar_cmp.c -- compares the frames of an NCAR Graphics example drawn by gks3d (PNG files)
 * with NCAR's own rendering of the same program (its NCGM translated by `ctrans -d sun`:
 * Sun raster images, one after another in one file).
 *
 *   ncar_cmp REF.ras OUT1.png [OUT2.png ...]
 *
 * Both pictures are reduced to CMP_N x CMP_N pixels by averaging square blocks (a box blur
 * of 8 pixels of both 1024x1024 pictures). What is compared is then
 * geometry and colour at 1/128 of the frame: the reduction removes what legitimately
 * differs, the stroke font's shapes (NCAR's Hershey-style fonts vs this library's, text
 * is about one block high), anti-aliasing and line widths of one or two pixels, and the
 * one-pixel rounding of NCAR's integer VDC. A frame passes when at most FRAC_MAX of its
 * blocks differ by more than DIFF_TOL (largest channel, 0..255): a missing or misplaced
 * curve, contour band, map outline or a wrong fill (hollow for solid, a colour index
 * off) changes far more blocks than that (docs/NCAR.md gives the figures).
 * NCAR_CMP_DUMP=DIR writes NCAR's frames as DIR/ncar-001.png, ... to look at, and each
 * pair side by side at a quarter of the size (NCAR left, gks3d right) as DIR/side-001.png
 * (docs/NCAR.md).
 * Exit 0 if the frame counts agree and every frame passes, 1 otherwise; one line per frame.
 */
#include "image_util.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMP_N 128
#define DIFF_TOL 48      /* largest channel difference of a block that counts as differing */
#define FRAC_MAX 0.02    /* share of differing blocks a frame may have */

static unsigned long be32(const unsigned char *p)
{
    return ((unsigned long)p[0] << 24) | ((unsigned long)p[1] << 16) |
           ((unsigned long)p[2] << 8) | p[3];
}

/* The next Sun raster image of f (8-bit with colour map or 24-bit, standard encoding, as
 * ctrans writes them) into im; 1 read, 0 end of file, -1 malformed. */
static int read_ras(FILE *f, img *im)
{
    unsigned char h[32];
    size_t got = fread(h, 1, sizeof h, f);
    if (got == 0)
        return 0;
    if (got != sizeof h || be32(h) != 0x59a66a95UL)
        return -1;
    unsigned long w = be32(h + 4), ht = be32(h + 8), depth = be32(h + 12);
    unsigned long type = be32(h + 20), maptype = be32(h + 24), maplen = be32(h + 28);
    if (w == 0 || ht == 0 || w > 16384 || ht > 16384 || (depth != 8 && depth != 24) ||
        type > 1 || maplen > 768 || (maptype == 1 && maplen % 3))
        return -1;
    unsigned char map[768];
    if (maplen && fread(map, 1, maplen, f) != maplen)
        return -1;
    size_t ncol = maptype == 1 ? maplen / 3 : 0;
    size_t bpp = depth / 8, row = (size_t)w * bpp;
    size_t pad = row + (row & 1); /* rows are padded to 16 bits */
    unsigned char *line = malloc(pad);
    im->w = (int)w;
    im->h = (int)ht;
    im->rgb = malloc((size_t)w * ht * 3);
    if (!line || !im->rgb) {
        free(line);
        free(im->rgb);
        return -1;
    }
    for (unsigned long y = 0; y < ht; y++) {
        if (fread(line, 1, pad, f) != pad) {
            free(line);
            free(im->rgb);
            im->rgb = NULL;
            return -1;
        }
        unsigned char *o = im->rgb + (size_t)y * w * 3;
        for (unsigned long x = 0; x < w; x++) {
            if (depth == 8) {
                unsigned char i = line[x];
                o[3 * x + 0] = i < ncol ? map[i] : i;
                o[3 * x + 1] = i < ncol ? map[ncol + i] : i;
                o[3 * x + 2] = i < ncol ? map[2 * ncol + i] : i;
            } else { /* Sun 24-bit: B, G, R */
                o[3 * x + 0] = line[3 * x + 2];
                o[3 * x + 1] = line[3 * x + 1];
                o[3 * x + 2] = line[3 * x + 0];
            }
        }
    }
    free(line);
    return 1;
}

/* ref and out (equal sizes, multiples of 4) side by side, each reduced 4:1 by block means. */
static int write_side(const char *path, const img *ref, const img *out)
{
    if (ref->w != out->w || ref->h != out->h || ref->w % 4 || ref->h % 4)
        return -1;
    img s = { ref->w / 2, ref->h / 4, NULL };
    s.rgb = malloc((size_t)s.w * (size_t)s.h * 3);
    if (!s.rgb)
        return -1;
    for (int k = 0; k < 2; k++) {
        const img *m = k ? out : ref;
        for (int j = 0; j < s.h; j++)
            for (int i = 0; i < m->w / 4; i++)
                for (int c = 0; c < 3; c++) {
                    int sum = 0;
                    for (int y = 0; y < 4; y++)
                        for (int x = 0; x < 4; x++)
                            sum += m->rgb[((size_t)(4 * j + y) * (size_t)m->w + (size_t)(4 * i + x)) * 3 + (size_t)c];
                    s.rgb[((size_t)j * (size_t)s.w + (size_t)(k * m->w / 4 + i)) * 3 + (size_t)c] =
                        (unsigned char)((sum + 8) / 16);
                }
    }
    int e = img_write(path, &s);
    free(s.rgb);
    return e;
}

/* The CMP_N x CMP_N block averages of im (its size a multiple of CMP_N). */
static int reduce(const img *im, float *out)
{
    if (im->w % CMP_N || im->h % CMP_N)
        return -1;
    int bx = im->w / CMP_N, by = im->h / CMP_N;
    for (int j = 0; j < CMP_N; j++)
        for (int i = 0; i < CMP_N; i++)
            for (int c = 0; c < 3; c++) {
                double s = 0;
                for (int y = 0; y < by; y++)
                    for (int x = 0; x < bx; x++)
                        s += im->rgb[((size_t)(j * by + y) * (size_t)im->w + (size_t)(i * bx + x)) * 3 + (size_t)c];
                out[(j * CMP_N + i) * 3 + c] = (float)(s / (bx * by));
            }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: ncar_cmp REF.ras OUT1.png [OUT2.png ...]\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    if (!f) {
        fprintf(stderr, "ncar_cmp: cannot read %s\n", argv[1]);
        return 1;
    }
    static float a[CMP_N * CMP_N * 3], b[CMP_N * CMP_N * 3];
    int nout = argc - 2, frame = 0, bad = 0, r;
    img ref = { 0, 0, NULL };
    while ((r = read_ras(f, &ref)) == 1) {
        frame++;
        if (frame > nout) {
            free(ref.rgb);
            continue;
        }
        const char *dump = getenv("NCAR_CMP_DUMP"); /* directory: NCAR's frames as PNG */
        if (dump && *dump) {
            char path[4096];
            snprintf(path, sizeof path, "%s/ncar-%03d.png", dump, frame);
            if (img_write(path, &ref))
                printf("frame %d: cannot write %s\n", frame, path);
        }
        img out = { 0, 0, NULL };
        int rd = img_read(argv[1 + frame], &out);
        if (!rd && dump && *dump) {
            char path[4096];
            snprintf(path, sizeof path, "%s/side-%03d.png", dump, frame);
            if (write_side(path, &ref, &out))
                printf("frame %d: cannot write %s\n", frame, path);
        }
        if (rd || reduce(&ref, a) || reduce(&out, b)) {
            printf("frame %d: cannot read or reduce %s\n", frame, argv[1 + frame]);
            bad = 1;
        } else {
            size_t over = 0;
            double sum = 0;
            for (int k = 0; k < CMP_N * CMP_N; k++) {
                float m = 0;
                for (int c = 0; c < 3; c++) {
                    float d = a[3 * k + c] - b[3 * k + c];
                    d = d < 0 ? -d : d;
                    m = d > m ? d : m;
                }
                sum += m;
                over += m > DIFF_TOL;
            }
            double frac = (double)over / (CMP_N * CMP_N);
            int ok = frac <= FRAC_MAX;
            printf("frame %d: %s blocks over %d: %.2f%% (limit %.0f%%), mean difference %.1f\n",
                   frame, ok ? "ok" : "DIFFERS", DIFF_TOL, 100 * frac, 100 * FRAC_MAX,
                   sum / (CMP_N * CMP_N));
            bad |= !ok;
        }
        img_free(&out);
        free(ref.rgb);
        ref.rgb = NULL;
    }
    fclose(f);
    if (r < 0) {
        printf("%s: malformed Sun raster after frame %d\n", argv[1], frame);
        return 1;
    }
    if (frame != nout) {
        printf("frame count: NCAR %d, gks3d %d\n", frame, nout);
        return 1;
    }
    return bad;
}
