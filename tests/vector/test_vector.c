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
 *   test_vector linestyle OUT          ESCAPEs GESC_VEC_LINE_JOIN ... GESC_VEC_PAGE as poppler
 *                                      draws them
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

/* ---- ESCAPEs GESC_VEC_LINE_JOIN, _CAP, _MITER_LIMIT, _LINE_SCALE, _PAGE ---- */
typedef struct { int join, cap, page; double miter, scale; } line_case;

/* One PDF page, 2 x 2 inches: a V of width 30 nominal units (6 mm) with its apex at
 * (0.5, 0.8), and a horizontal segment from x 0.3 to 0.7 at y 0.15; the escapes of c
 * (join/cap -1 and miter/scale 0 = not given; page: the picture into the rectangle
 * 72 72 216 216 points of a letter page), and the bad values, which must each report 182
 * and change nothing. Returns the error count of the bad values that were not 182. */
static int line_page(const char *file, const line_case *c)
{
    gopen_ws(1, file, GWS_TYPE_PDF);
    Glimit w = { 0, 1, 0, 1 }, v = { 0, 0.0508f, 0, 0.0508f };
    gset_ws_win(1, &w);
    gset_ws_vp(1, &v);
    Gint ints[7] = { 1 };
    Gfloat x = 0;
    Gescape_in_data in = { { 2, ints, 1, &x, 0, NULL } };
    int bad = 0;
    struct { int id, ni; Gint i1; double x; } wrong[] = {
        { GESC_VEC_LINE_JOIN, 2, 3, 0 }, { GESC_VEC_LINE_CAP, 2, -1, 0 },
        { GESC_VEC_MITER_LIMIT, 2, 0, 0.5 }, { GESC_VEC_LINE_SCALE, 2, 0, 0 },
        { GESC_VEC_PAGE, 3, 10, 0 }, { GESC_VEC_PAGE, 5, 300, 0 },
    };
    for (size_t k = 0; k < sizeof wrong / sizeof wrong[0]; k++) {
        last_err = 0;
        in.num_ints = wrong[k].ni;
        ints[1] = wrong[k].i1; /* PAGE: llx 300 > urx 0 */
        ints[2] = ints[3] = ints[4] = 0;
        x = (Gfloat)wrong[k].x;
        gescape(wrong[k].id, &in, NULL, NULL);
        bad += last_err != 182;
    }
    in.num_ints = 2;
    if (c->join >= 0) {
        ints[1] = c->join;
        gescape(GESC_VEC_LINE_JOIN, &in, NULL, NULL);
    }
    if (c->cap >= 0) {
        ints[1] = c->cap;
        gescape(GESC_VEC_LINE_CAP, &in, NULL, NULL);
    }
    if (c->miter > 0) {
        x = (Gfloat)c->miter;
        gescape(GESC_VEC_MITER_LIMIT, &in, NULL, NULL);
    }
    if (c->scale > 0) {
        x = (Gfloat)c->scale;
        gescape(GESC_VEC_LINE_SCALE, &in, NULL, NULL);
    }
    if (c->page) {
        Gint pg[5] = { 1, 72, 72, 216, 216 };
        Gescape_in_data pin = { { 5, pg, 0, NULL, 0, NULL } };
        gescape(GESC_VEC_PAGE, &pin, NULL, NULL);
    }
    gactivate_ws(1);
    gset_linewidth(30);
    Gpoint vee[3] = { { 0.3f, 0.4f }, { 0.5f, 0.8f }, { 0.7f, 0.4f } };
    Gpoint seg[2] = { { 0.3f, 0.15f }, { 0.7f, 0.15f } };
    Gpoint_list l1 = { 3, vee }, l2 = { 2, seg };
    gpolyline(&l1);
    gpolyline(&l2);
    gdeactivate_ws(1);
    gclose_ws(1);
    return bad;
}

/* Dark pixels of the picture (288 x 288 pixels for 2 inches) above the apex row (y 0.8:
 * what the join adds), left of x 0.3 on the segment's rows (what the cap adds), and in all. */
typedef struct { long above, left, all; } line_count;
static int count_dark(const char *png, line_count *n)
{
    img im = { 0 };
    if (img_read(png, &im))
        return -1;
    *n = (line_count){ 0, 0, 0 };
    for (int j = 0; j < im.h; j++)
        for (int i = 0; i < im.w; i++) {
            if (px(&im, i, j, 0) >= 128)
                continue;
            double xn = (i + 0.5) / im.w, yn = 1.0 - (j + 0.5) / im.h;
            n->all++;
            n->above += yn > 0.8;
            n->left += xn < 0.3 && yn < 0.3;
        }
    img_free(&im);
    return 0;
}

/* The line style escapes as poppler draws them: the join above the apex of a V whose
 * half angle is 26.6 degrees (its miter reaches 1.12 line widths above the apex, a round
 * join 0.5, a bevel 0.22), so miter > round > bevel, and a miter limit of 2 (below
 * 1 / sin 26.6 = 2.24) gives the bevel exactly; the cap beyond the end of a segment:
 * none for butt, half a width for square, less for round; a line scale of 2 draws about
 * twice the ink (1.6 .. 2.4: the joins and caps do not scale linearly); the page: a
 * letter page (pdfinfo) with every dark pixel inside the rectangle. */
static int line_style(const char *out)
{
    if (!have("pdftoppm") || !have("pdfinfo")) {
        printf("skipped: pdftoppm or pdfinfo not found (poppler-utils)\n");
        return SKIP;
    }
    static const struct { const char *name; line_case c; } cases[] = {
        { "default", { -1, -1, 0, 0, 0 } },  { "miter", { 0, -1, 0, 0, 0 } },
        { "bevel", { 2, -1, 0, 0, 0 } },     { "miter2", { 0, -1, 0, 2.0, 0 } },
        { "capround", { -1, 1, 0, 0, 0 } },  { "capsquare", { -1, 2, 0, 0, 0 } },
        { "scale2", { -1, -1, 0, 0, 2.0 } }, { "page", { -1, -1, 1, 0, 0 } },
    };
    enum { N = sizeof cases / sizeof cases[0] };
    line_count n[N];
    int fail = 0;
    gset_err_hand(on_error, NULL);
    gopen_gks(NULL, 0);
    for (int k = 0; k < N; k++) {
        char file[PATH_LEN], png[PATH_LEN + 8], stem[PATH_LEN], cmd[3 * PATH_LEN];
        snprintf(file, sizeof file, "%s/line_%s.pdf", out, cases[k].name);
        snprintf(stem, sizeof stem, "%s/line_%s", out, cases[k].name);
        snprintf(png, sizeof png, "%s.png", stem);
        int bad = line_page(file, &cases[k].c);
        if (cases[k].c.page)
            snprintf(cmd, sizeof cmd, "pdftoppm -png -singlefile -r 72 '%s' '%s'", file, stem);
        else
            snprintf(cmd, sizeof cmd, "pdftoppm -png -singlefile -r 144 '%s' '%s'", file, stem);
        if (bad || sh(cmd) || count_dark(png, &n[k])) {
            printf("FAIL %s: %d bad values not reported as 182, or no picture\n",
                   cases[k].name, bad);
            fail = 1;
            n[k] = (line_count){ -1, -1, -1 };
        }
        printf("%-9s above apex %5ld, left of segment %4ld, all %6ld\n", cases[k].name,
               n[k].above, n[k].left, n[k].all);
    }
    /* 0 default (round join, butt cap) 1 miter 2 bevel 3 miter limit 2 4 round cap
     * 5 square cap 6 scale 2 7 page */
    struct { const char *what; int ok; } checks[] = {
        { "miter > round > bevel > 0", n[1].above > n[0].above && n[0].above > n[2].above &&
                                           n[2].above > 0 },
        { "miter limit 2 = bevel", n[3].above == n[2].above && n[3].all == n[2].all },
        { "butt cap: nothing left of the end", n[0].left == 0 },
        { "square cap > round cap > 0", n[5].left > n[4].left && n[4].left > 0 },
        { "scale 2: 1.6 .. 2.4 times the ink", n[6].all > 1.6 * n[0].all &&
                                                   n[6].all < 2.4 * n[0].all },
    };
    for (size_t k = 0; k < sizeof checks / sizeof checks[0]; k++) {
        printf("%s: %s\n", checks[k].what, checks[k].ok ? "ok" : "FAIL");
        fail |= !checks[k].ok;
    }
    /* the page: 612 x 792 points, the picture inside 72..216 (x), 792-216..792-72 (rows) */
    char file[PATH_LEN], cmd[3 * PATH_LEN];
    snprintf(file, sizeof file, "%s/line_page.pdf", out);
    snprintf(cmd, sizeof cmd, "pdfinfo '%s' | grep -q 'Page size: *612 x 792 pts'", file);
    int page_ok = sh(cmd) == 0;
    img im = { 0 };
    snprintf(file, sizeof file, "%s/line_page.png", out);
    long inside = 0, outside = 0;
    if (img_read(file, &im) == 0) {
        for (int j = 0; j < im.h; j++)
            for (int i = 0; i < im.w; i++)
                if (px(&im, i, j, 0) < 128) {
                    int in_rect = i >= 72 && i < 216 && j >= 792 - 216 && j < 792 - 72;
                    inside += in_rect;
                    outside += !in_rect;
                }
        page_ok &= im.w == 612 && im.h == 792;
        img_free(&im);
    }
    page_ok &= inside > 0 && outside == 0;
    printf("page: letter %s, dark pixels inside the rectangle %ld, outside %ld: %s\n",
           page_ok ? "yes" : "no", inside, outside, page_ok ? "ok" : "FAIL");
    fail |= !page_ok;
    /* not a vector workstation: 180 */
    gopen_ws(2, NULL, GWS_TYPE_NULL);
    Gint ints[2] = { 2, 0 };
    Gescape_in_data in = { { 2, ints, 0, NULL, 0, NULL } };
    last_err = 0;
    gescape(GESC_VEC_LINE_JOIN, &in, NULL, NULL);
    printf("null workstation: error %d (want 180)\n", (int)last_err);
    fail |= last_err != 180;
    gclose_ws(2);
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
    if (argc >= 3 && strcmp(argv[1], "linestyle") == 0)
        return line_style(argv[2]);
    fprintf(stderr, "usage: test_vector run CBIN FBIN OUT | readers OUT | twins OUT | text OUT | "
                    "resolution OUT | linestyle OUT\n");
    return 2;
}
