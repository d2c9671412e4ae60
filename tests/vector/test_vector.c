/* SPDX-License-Identifier: MIT */
/*
 * test_vector.c -- the vector workstations (PDF, SVG, PS, EPS) opened by real readers.
 *
 *   test_vector run     CBIN FBIN OUT  runs fig2, surface and plot2d (C) with every type,
 *                                      fig2 and surface (Fortran) as PDF, SVG and EPS
 *   test_vector readers OUT            rasterises every vector file with its reader
 *                                      (PDF pdftoppm, SVG rsvg-convert, PS/EPS gs) and
 *                                      compares it with the PNG workstation's picture
 *   test_vector twins   OUT            C and Fortran files byte-identical, and plot2d
 *                                      written three times gives the same files
 *   test_vector text    OUT            ink of TEXT agrees with INQUIRE TEXT EXTENT
 *   test_vector resolution OUT         ESCAPE GESC_VEC_RESOLUTION (embedded image size)
 *
 * Pictures: SIZE pixels (fig2 and plot2d 360, previews 120; surface 180, ray traced at
 * 300 dpi on the vector types) on the PNG workstation, SIZE x 0.2 mm on the vector ones, whose
 * nominal unit (line width 1) is 0.2 mm; rasterised at 127 dpi (0.2 mm per pixel) both have
 * the same pixel grid, line widths, marker sizes, dashes and hatch spacing.
 *
 * Tolerance and its reason. The readers anti-alias every edge, the PNG workstation (no
 * ESCAPE -110) does not, so edge pixels differ by up to the full contrast while areas agree;
 * the readers also differ among themselves in how they draw lines one pixel wide
 * (ghostscript's fill adjustment widens them) and how they resample embedded images
 * (poppler's downsampling moves a raster by up to a pixel). Both pictures are therefore
 * compared after a 3 x 3 box blur (anti-aliasing moves coverage within a pixel, the blur
 * spreads either over the same block), at the best of the shifts by at most one pixel, and
 *   - the mean absolute channel difference is at most 8 levels of 255, and
 *   - at most 3 % of the pixels differ by more than 48 levels in some channel.
 * Measured (fig2 at 360 pixels, previews 120, surface 180, plot2d 360): mean 0.5 to 7.1,
 * over 48 at most 2.5 % (ghostscript, hidden line); another mode's picture is rejected by
 * far (mean 51, 39 %: the mismatch check below, so the comparison can fail). Hidden-line
 * visibility is sampled at the vector workstation's resolution (300 dpi), not the PNG's
 * 127 dpi, which moves the end of a hidden line by up to a pixel: within the same bounds.
 * Exit status 77 (CTest: skipped) when a reader is missing, with a message.
 */
#define _POSIX_C_SOURCE 200809L
#include "image_util.h"
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { PATH_LEN = 1200, SKIP = 77 };
#define MEAN_TOL 8.0
#define OVER_LEVEL 48
#define OVER_FRAC 0.03

typedef struct { const char *prog; int size; const char *files[6]; } program;

/* Programs and the files of one run (without extension). */
static const program programs[] = {
    { "fig2", 360, { "fig2", "fig2_none", "fig2_hiddenline", "fig2_zbuffer", "fig2_painter",
                     0 } },
    { "surface", 180, { "surface", "surface_zbuffer", 0 } }, /* ray traced: kept small */
    { "plot2d", 360, { "plot2d", 0 } },
};
static const char *const vec_types[] = { "pdf", "svg", "eps", "ps" };

static int sh(const char *cmd)
{
    int r = system(cmd);
    return r == 0 ? 0 : 1;
}

static int have(const char *tool)
{
    char cmd[256];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", tool);
    return sh(cmd) == 0;
}

static int run_all(const char *cbin, const char *fbin, const char *out)
{
    char cmd[3 * PATH_LEN];
    int fail = 0;
    for (size_t p = 0; p < sizeof programs / sizeof programs[0]; p++) {
        const char *types[] = { "png", "pdf", "svg", "eps", "ps" };
        for (int t = 0; t < 5; t++) {
            snprintf(cmd, sizeof cmd, "cd '%s' && '%s/%s_c' %d c_ %s", out, cbin,
                     programs[p].prog, programs[p].size, types[t]);
            if (sh(cmd)) {
                printf("FAIL: %s\n", cmd);
                fail = 1;
            }
        }
        if (strcmp(programs[p].prog, "plot2d") == 0) { /* reproducible: again twice */
            for (int t = 1; t < 5; t++)
                for (int again = 0; again < 2; again++) {
                    snprintf(cmd, sizeof cmd, "cd '%s' && '%s/%s_c' %d %s %s", out, cbin,
                             programs[p].prog, programs[p].size, again ? "e_" : "d_",
                             types[t]);
                    if (sh(cmd)) {
                        printf("FAIL: %s\n", cmd);
                        fail = 1;
                    }
                }
        }
        if (strcmp(programs[p].prog, "plot2d") == 0 || !fbin[0])
            continue;
        for (int t = 0; t < 3; t++) {
            snprintf(cmd, sizeof cmd, "cd '%s' && '%s/%s_f77' %d f_ %s", out, fbin,
                     programs[p].prog, programs[p].size, vec_types[t]);
            if (sh(cmd)) {
                printf("FAIL: %s\n", cmd);
                fail = 1;
            }
        }
    }
    return fail;
}

static int exists(const char *path)
{
    return access(path, R_OK) == 0;
}

/* The reader's rasterisation of file (0.2 mm per pixel) into png; 0 on success. */
static int rasterise(const char *type, const char *file, const char *png, int w, int h)
{
    char cmd[3 * PATH_LEN];
    if (strcmp(type, "pdf") == 0) {
        char stem[PATH_LEN];
        snprintf(stem, sizeof stem, "%.*s", (int)(strlen(png) - 4), png);
        snprintf(cmd, sizeof cmd, "pdftoppm -png -singlefile -scale-to-x %d -scale-to-y %d "
                                  "'%s' '%s'", w, h, file, stem);
    } else if (strcmp(type, "svg") == 0) {
        snprintf(cmd, sizeof cmd, "rsvg-convert -w %d -h %d -b white -o '%s' '%s'", w, h, png,
                 file);
    } else { /* gs: the page (PS) or the bounding box (EPS) at 127 dpi; cairo's EPS box is
              * the page rounded up to whole points, the page at its top-left corner */
        snprintf(cmd, sizeof cmd, "gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=png16m -r127 "
                                  "-dTextAlphaBits=4 -dGraphicsAlphaBits=4 %s "
                                  "-sOutputFile='%s' '%s'",
                 strcmp(type, "eps") == 0 ? "-dEPSCrop" : "", png, file);
    }
    return sh(cmd);
}

/* im cropped to w x h from its top-left corner (a reader that rounds the page up to whole
 * pixels adds the extra row and column at the bottom and right). */
static int crop(img *im, int w, int h)
{
    if (im->w < w || im->h < h)
        return -1;
    for (int j = 0; j < h; j++)
        memmove(im->rgb + (size_t)j * (size_t)w * 3, im->rgb + (size_t)j * (size_t)im->w * 3,
                (size_t)w * 3);
    im->w = w;
    im->h = h;
    return 0;
}

static double px(const img *im, int i, int j, int c)
{
    i = i < 0 ? 0 : i >= im->w ? im->w - 1 : i;
    j = j < 0 ? 0 : j >= im->h ? im->h - 1 : j;
    return im->rgb[3 * ((size_t)j * (size_t)im->w + (size_t)i) + (size_t)c];
}

/* Mean absolute channel difference and fraction of pixels over OVER_LEVEL, after a 3 x 3
 * box blur of both, b shifted by (dx, dy) pixels. */
static void blur_diff_at(const img *a, const img *b, int dx, int dy, double *mean, double *frac)
{
    double s = 0;
    size_t over = 0;
    for (int j = 0; j < a->h; j++)
        for (int i = 0; i < a->w; i++) {
            int o = 0;
            for (int c = 0; c < 3; c++) {
                double sa = 0, sb = 0;
                for (int dj = -1; dj <= 1; dj++)
                    for (int di = -1; di <= 1; di++) {
                        sa += px(a, i + di, j + dj, c);
                        sb += px(b, i + di + dx, j + dj + dy, c);
                    }
                double d = fabs(sa - sb) / 9.0;
                s += d;
                o |= d > OVER_LEVEL;
            }
            over += (size_t)o;
        }
    double n = (double)a->w * (double)a->h;
    *mean = s / (3.0 * n);
    *frac = (double)over / n;
}

/* The best of the shifts by at most one pixel (readers snap embedded images to their pixel
 * grid: poppler's image downsampling moves an embedded raster by up to a pixel). */
static void blur_diff(const img *a, const img *b, double *mean, double *frac)
{
    *mean = *frac = INFINITY;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            double m, f;
            blur_diff_at(a, b, dx, dy, &m, &f);
            if (m < *mean) {
                *mean = m;
                *frac = f;
            }
        }
}

/* One vector file against its PNG: 0 within tolerance, 1 not, -1 missing / unreadable. */
static int compare_one(const char *out, const char *name, const char *type, const char *png_name,
                       double *mean, double *frac)
{
    char ref_path[PATH_LEN], file[PATH_LEN], ras[PATH_LEN];
    snprintf(ref_path, sizeof ref_path, "%s/c_%s.png", out, png_name);
    snprintf(file, sizeof file, "%s/c_%s.%s", out, name, type);
    snprintf(ras, sizeof ras, "%s/r_%s.%s.png", out, name, type);
    img ref = { 0 }, got = { 0 };
    if (!exists(file) || img_read(ref_path, &ref)) {
        printf("FAIL: %s or %s missing\n", file, ref_path);
        return -1;
    }
    int r = -1;
    if (rasterise(type, file, ras, ref.w, ref.h) || img_read(ras, &got)) {
        printf("FAIL: the reader could not open %s\n", file);
    } else if ((got.w != ref.w || got.h != ref.h) && crop(&got, ref.w, ref.h)) {
        printf("FAIL: %s rasterised to %d x %d, want %d x %d\n", file, got.w, got.h, ref.w,
               ref.h);
    } else {
        blur_diff(&ref, &got, mean, frac);
        r = *mean <= MEAN_TOL && *frac <= OVER_FRAC ? 0 : 1;
    }
    img_free(&ref);
    img_free(&got);
    return r;
}

static int missing_readers(void)
{
    const char *tools[] = { "pdftoppm", "rsvg-convert", "gs" };
    int miss = 0;
    for (int i = 0; i < 3; i++)
        if (!have(tools[i])) {
            printf("skipped: %s not found (install poppler-utils, librsvg2-bin, ghostscript: "
                   "scripts/setup.sh)\n", tools[i]);
            miss = 1;
        }
    return miss;
}

static int readers(const char *out)
{
    if (missing_readers())
        return SKIP;
    int fail = 0;
    for (size_t p = 0; p < sizeof programs / sizeof programs[0]; p++)
        for (int k = 0; programs[p].files[k]; k++)
            for (int t = 0; t < 4; t++) {
                const char *f = programs[p].files[k];
                double mean = 0, frac = 0;
                int r = compare_one(out, f, vec_types[t], f, &mean, &frac);
                printf("%-20s %-4s mean |diff| %5.2f (<= %.0f), over %d: %5.2f %% (<= %.0f %%)"
                       "%s\n", f, vec_types[t], mean, MEAN_TOL, OVER_LEVEL, 100 * frac,
                       100 * OVER_FRAC, r ? "  FAIL" : "");
                fail |= r != 0;
            }
    /* the comparison can fail: another mode's picture is out of tolerance */
    double mean = 0, frac = 0;
    int r = compare_one(out, "fig2_hiddenline", "pdf", "fig2_zbuffer", &mean, &frac);
    printf("mismatch check: fig2_hiddenline.pdf against fig2_zbuffer.png: mean %.2f, "
           "over %.2f %% -> %s\n", mean, 100 * frac, r == 1 ? "rejected (good)" : "ACCEPTED");
    fail |= r != 1;
    return fail;
}

static int twins(const char *out)
{
    int fail = 0, n = 0;
    for (size_t p = 0; p < 2; p++)
        for (int k = 0; programs[p].files[k]; k++)
            for (int t = 0; t < 3; t++) {
                char a[PATH_LEN], b[PATH_LEN];
                snprintf(a, sizeof a, "%s/c_%s.%s", out, programs[p].files[k], vec_types[t]);
                snprintf(b, sizeof b, "%s/f_%s.%s", out, programs[p].files[k], vec_types[t]);
                int s = file_same(a, b);
                if (s != 1) {
                    printf("FAIL: %s and %s %s\n", a, b, s < 0 ? "unreadable" : "differ");
                    fail = 1;
                }
                n++;
            }
    printf("%d C/Fortran file pairs compared\n", n);
    /* the same program three times gives the same file (plot2d: a cell array, a pattern,
     * hatches and text; cairo's PostScript padding of images once made EPS and PS vary) */
    for (int t = 0; t < 4; t++)
        for (int again = 0; again < 2; again++) {
            char a[PATH_LEN], b[PATH_LEN];
            snprintf(a, sizeof a, "%s/c_plot2d.%s", out, vec_types[t]);
            snprintf(b, sizeof b, "%s/%s_plot2d.%s", out, again ? "e" : "d", vec_types[t]);
            int s = file_same(a, b);
            if (s != 1) {
                printf("FAIL: %s and %s %s (the same program)\n", a, b,
                       s < 0 ? "unreadable" : "differ");
                fail = 1;
            }
        }
    printf("plot2d written three times: %s\n", fail ? "files differ" : "identical files");
    return fail;
}

/* TEXT on a PDF workstation and on a PNG workstation of the same pixel grid: the ink
 * of each string lies inside its INQUIRE TEXT EXTENT parallelogram (to a pixel) and fills
 * most of it. */
static int text(const char *out)
{
    if (missing_readers())
        return SKIP;
    static const char *const strs[] = { "HELLO vector", "Ag|y_123", "W" };
    const Gint types[2] = { GWS_TYPE_PNG, GWS_TYPE_PDF };
    const char *ext[2] = { "png", "pdf" };
    int fail = 0;
    gopen_gks(NULL, 0);
    for (int s = 0; s < 3; s++)
        for (int t = 0; t < 2; t++) {
            char base[PATH_LEN / 2], file[PATH_LEN], ras[PATH_LEN];
            snprintf(base, sizeof base, "%.500s/text%d", out, s);
            snprintf(file, sizeof file, "%s.%s", base, ext[t]);
            gopen_ws(1, file, types[t]);
            gactivate_ws(1);
            float side = t ? 400 * 0.0002f : 400.0f;
            Glimit w = { 0, 1, 0, 1 }, v = { 0, side, 0, side };
            gset_ws_win(1, &w);
            gset_ws_vp(1, &v);
            gset_char_ht(0.06f + 0.03f * (float)s);
            Gpoint pos = { 0.1f, 0.4f };
            gtext(&pos, strs[s]);
            Gint err = -1;
            Gtext_extent ex;
            ginq_text_extent(1, &pos, strs[s], &err, &ex);
            gdeactivate_ws(1);
            gclose_ws(1);
            img im = { 0 };
            const char *rp = file;
            if (t) {
                snprintf(ras, sizeof ras, "%s.pdf.png", base);
                if (rasterise("pdf", file, ras, 400, 400)) {
                    printf("FAIL: pdftoppm could not open %s\n", file);
                    fail = 1;
                    continue;
                }
                rp = ras;
            }
            if (err || img_read(rp, &im)) {
                printf("FAIL: %s: extent error %d or picture unreadable\n", file, (int)err);
                fail = 1;
                continue;
            }
            /* extent box in pixels (NDC * 400, y down) */
            double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
            for (int k = 0; k < 4; k++) {
                x0 = fmin(x0, ex.paral[k].x * 400);
                x1 = fmax(x1, ex.paral[k].x * 400);
                y0 = fmin(y0, (1 - ex.paral[k].y) * 400);
                y1 = fmax(y1, (1 - ex.paral[k].y) * 400);
            }
            int ix0 = 400, ix1 = -1, iy0 = 400, iy1 = -1;
            for (int j = 0; j < im.h; j++)
                for (int i = 0; i < im.w; i++)
                    if (px(&im, i, j, 0) < 128) {
                        ix0 = i < ix0 ? i : ix0;
                        ix1 = i > ix1 ? i : ix1;
                        iy0 = j < iy0 ? j : iy0;
                        iy1 = j > iy1 ? j : iy1;
                    }
            int inside = ix0 >= x0 - 1.5 && ix1 + 1 <= x1 + 1.5 && iy0 >= y0 - 1.5 &&
                         iy1 + 1 <= y1 + 1.5;
            double fw = (ix1 + 1 - ix0) / (x1 - x0), fh = (iy1 + 1 - iy0) / (y1 - y0);
            int ok = ix1 >= 0 && inside && fw >= 0.85 && fh >= 0.6;
            printf("%-4s \"%s\": extent x %.1f..%.1f y %.1f..%.1f, ink x %d..%d y %d..%d "
                   "(width %.2f, height %.2f of the extent)%s\n", ext[t], strs[s], x0, x1, y0,
                   y1, ix0, ix1 + 1, iy0, iy1 + 1, fw, fh, ok ? "" : "  FAIL");
            fail |= !ok;
            img_free(&im);
        }
    gclose_gks();
    return fail;
}

static Gint last_err;
static void on_error(Gint err, Gint func, const char *file)
{
    (void)func;
    (void)file;
    last_err = err;
}

/* ESCAPE GESC_VEC_RESOLUTION: a z-buffer frame's embedded image has the requested
 * resolution at the page size (pdfimages -list), a bad value reports 182 and changes
 * nothing. */
static int resolution(const char *out)
{
    if (!have("pdfimages")) {
        printf("skipped: pdfimages not found (poppler-utils)\n");
        return SKIP;
    }
    int fail = 0;
    gset_err_hand(on_error, NULL);
    gopen_gks(NULL, 0);
    for (int k = 0; k < 3; k++) {
        char file[PATH_LEN], cmd[3 * PATH_LEN];
        snprintf(file, sizeof file, "%s/res%d.pdf", out, k);
        gopen_ws(1, file, GWS_TYPE_PDF);
        Glimit w = { 0, 1, 0, 1 }, v = { 0, 0.0508f, 0, 0.0254f }; /* 2 x 1 inch */
        gset_ws_win(1, &w);
        gset_ws_vp(1, &v);
        gset_hlhsr_mode(1, GHLHSR_ZBUFFER);
        last_err = 0;
        if (k > 0) {
            Gint ints[2] = { 1, 100 };
            Gescape_in_data in = { { 2, ints, 0, NULL, 0, NULL } };
            gescape(GESC_VEC_RESOLUTION, &in, NULL, NULL);
            if (k == 2) {
                ints[1] = 5;
                gescape(GESC_VEC_RESOLUTION, &in, NULL, NULL);
            }
        }
        int want_err = k == 2 ? 182 : 0, want = k == 0 ? 300 : 100;
        gactivate_ws(1);
        gset_fill_int_style(GSTYLE_SOLID);
        Gpoint p[3] = { { 0.1f, 0.1f }, { 0.9f, 0.2f }, { 0.5f, 0.45f } };
        Gpoint_list l = { 3, p };
        gfill_area(&l);
        gdeactivate_ws(1);
        gclose_ws(1);
        snprintf(cmd, sizeof cmd, "pdfimages -list '%s' | awk 'NR > 2 { print $4, $5 }'",
                 file);
        FILE *f = popen(cmd, "r");
        int iw = -1, ih = -1;
        if (!f || fscanf(f, "%d %d", &iw, &ih) != 2)
            iw = ih = -1;
        if (f)
            pclose(f);
        int ok = iw == 2 * want && ih == want && last_err == want_err;
        printf("resolution %s: image %d x %d (want %d x %d), error %d (want %d)%s\n",
               k == 0 ? "default" : k == 1 ? "100 dpi" : "100 dpi then 5 (bad)", iw, ih,
               2 * want, want, (int)last_err, want_err, ok ? "" : "  FAIL");
        fail |= !ok;
    }
    gclose_gks();
    return fail;
}

int main(int argc, char **argv)
{
    if (argc >= 5 && strcmp(argv[1], "run") == 0)
        return run_all(argv[2], argv[3], argv[4]);
    if (argc >= 3 && strcmp(argv[1], "readers") == 0)
        return readers(argv[2]);
    if (argc >= 3 && strcmp(argv[1], "twins") == 0)
        return twins(argv[2]);
    if (argc >= 3 && strcmp(argv[1], "text") == 0)
        return text(argv[2]);
    if (argc >= 3 && strcmp(argv[1], "resolution") == 0)
        return resolution(argv[2]);
    fprintf(stderr, "usage: test_vector run CBIN FBIN OUT | readers OUT | twins OUT | text OUT\n");
    return 2;
}
