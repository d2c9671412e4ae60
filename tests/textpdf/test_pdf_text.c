/* SPDX-License-Identifier: MIT */
/*
 * test_pdf_text.c -- text as text in vector output (issue 37 item 7). The same three texts
 * (left, centre and right aligned, in bands of the page) are written to a PDF in STRING and
 * CHAR precision (str.pdf) and in STROKE precision (stk.pdf). Checked with poppler-utils:
 *  - pdffonts: str.pdf embeds a TrueType font (fontconfig's, fonts-dejavu-core), stk.pdf
 *    none (the stroke font, a Type 3 font of outlines);
 *  - pdftotext finds every text of str.pdf and none of stk.pdf;
 *  - positions: both files rendered by pdftoppm at 144 dpi; per band the ink box of the
 *    real-font text and the word box pdftotext reports agree with the ink box of the stroke
 *    rendering (the extent the core computes) within 0.2 of the character height on the
 *    left and right (the real glyphs are centred in the stroke glyphs' cells, their side
 *    bearings differ), and the ink's top (cap line) and bottom within 0.15 of it (the caps
 *    are sized to the stroke font's cap height; the pen of the strokes adds half a unit).
 * Usage: test_pdf_text OUTDIR. Exit 0 pass, 1 fail, 77 skipped (no cairo, no fontconfig
 * build, or poppler-utils missing).
 */
#include <gks.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DPI 144.0
#define PAGE_M 0.15                      /* workstation viewport edge, metres */
#define PX_PER_WC (PAGE_M / 0.0254 * DPI) /* window [0,1] -> pixels of the rendering */
#define HT 0.05                          /* character height, WC */

static const char *const words[3] = { "Left123", "Centre", "Right" };
static const double ys[3] = { 0.8, 0.5, 0.2 };  /* baselines, WC */
static int fails;

static void write_pdf(const char *path, int stroke)
{
    static const Ghor_text_align al[3] = { GHOR_LEFT, GHOR_CTR, GHOR_RIGHT };
    static const double xs[3] = { 0.1, 0.5, 0.9 };
    gopen_ws(1, path, GWS_TYPE_PDF);
    gactivate_ws(1);
    gset_ws_vp(1, &(Glimit){ 0, PAGE_M, 0, PAGE_M });
    gset_char_ht(HT);
    for (int i = 0; i < 3; i++) {
        Gtext_prec p = stroke ? GPREC_STROKE : i == 1 ? GPREC_CHAR : GPREC_STRING;
        gset_text_font_prec(&(Gtext_font_prec){ 1, p });
        gset_text_align(&(Gtext_align){ al[i], GVERT_BASE });
        gtext(&(Gpoint){ xs[i], ys[i] }, words[i]);
    }
    gdeactivate_ws(1);
    gclose_ws(1);
}

/* stdout of cmd, at most n-1 bytes; 0 on failure */
static int run(const char *cmd, char *out, size_t n)
{
    FILE *f = popen(cmd, "r");
    if (!f)
        return 0;
    size_t k = fread(out, 1, n - 1, f);
    out[k] = '\0';
    return pclose(f) == 0;
}

typedef struct { int x0, y0, x1, y1; } box; /* ink, pixels, y down; x0 > x1: none */

/* The ink box (any channel below 128) in each band of the page rendered from pdf. */
static int ink_boxes(const char *pdf, const char *outdir, const char *tag, box b[3])
{
    char cmd[1024], png[600];
    snprintf(png, sizeof png, "%s/%s", outdir, tag);
    snprintf(cmd, sizeof cmd, "pdftoppm -png -r %d -singlefile '%s' '%s'", (int)DPI, pdf, png);
    if (system(cmd) != 0)
        return 0;
    strcat(png, ".png");
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, png))
        return 0;
    pi.format = PNG_FORMAT_GRAY;
    unsigned char *g = malloc(PNG_IMAGE_SIZE(pi));
    if (!g || !png_image_finish_read(&pi, NULL, g, 0, NULL)) {
        free(g);
        return 0;
    }
    int w = (int)pi.width, h = (int)pi.height;
    for (int i = 0; i < 3; i++)
        b[i] = (box){ w, h, -1, -1 };
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            if (g[(size_t)y * w + x] >= 128)
                continue;
            double wy = 1.0 - (y + 0.5) / h; /* WC y of the pixel */
            for (int i = 0; i < 3; i++)
                if (wy > ys[i] - 0.15 && wy < ys[i] + 0.15) {
                    box *q = &b[i];
                    if (x < q->x0) q->x0 = x;
                    if (x > q->x1) q->x1 = x;
                    if (y < q->y0) q->y0 = y;
                    if (y > q->y1) q->y1 = y;
                }
        }
    free(g);
    return 1;
}

static void near(const char *what, int i, double got, double want, double tol)
{
    int ok = got - want <= tol && want - got <= tol;
    printf("%s %-7s %-18s %8.1f px, stroke rendering %8.1f px (tolerance %.1f)\n",
           ok ? "ok  " : "FAIL", words[i], what, got, want, tol);
    fails += !ok;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    char str[512], stk[512], cmd[1200], out[16384];
    snprintf(str, sizeof str, "%s/str.pdf", argv[1]);
    snprintf(stk, sizeof stk, "%s/stk.pdf", argv[1]);
    if (system("command -v pdftotext >/dev/null && command -v pdffonts >/dev/null && "
               "command -v pdftoppm >/dev/null") != 0) {
        printf("skipped: poppler-utils not installed (scripts/setup.sh installs it)\n");
        return 77;
    }
    gopen_gks(NULL, 0);
    remove(str);
    remove(stk);
    write_pdf(str, 0);
    write_pdf(stk, 1);
    gclose_gks();

    snprintf(cmd, sizeof cmd, "pdffonts '%s'", str);
    if (!run(cmd, out, sizeof out) || !strstr(out, "TrueType")) {
        printf("FAIL: pdffonts lists no TrueType font in %s:\n%s\n", str, out);
        fails++;
    } else {
        printf("ok   pdffonts %s:\n%s", str, out);
    }
    snprintf(cmd, sizeof cmd, "pdffonts '%s'", stk);
    if (!run(cmd, out, sizeof out) || strstr(out, "TrueType")) {
        printf("FAIL: the STROKE precision file has a TrueType font:\n%s\n", out);
        fails++;
    }
    snprintf(cmd, sizeof cmd, "pdftotext '%s' -", stk);
    if (run(cmd, out, sizeof out))
        for (int i = 0; i < 3; i++)
            if (strstr(out, words[i])) {
                printf("FAIL: STROKE precision text \"%s\" found as text\n", words[i]);
                fails++;
            }

    box bs[3], bk[3];
    if (!ink_boxes(str, argv[1], "str", bs) || !ink_boxes(stk, argv[1], "stk", bk)) {
        printf("FAIL: pdftoppm could not render the files\n");
        return 1;
    }
    snprintf(cmd, sizeof cmd, "pdftotext -bbox '%s' -", str);
    if (!run(cmd, out, sizeof out)) {
        printf("FAIL: pdftotext -bbox %s\n", str);
        return 1;
    }
    const double hpx = HT * PX_PER_WC, k = DPI / 72.0; /* points -> pixels */
    for (int i = 0; i < 3; i++) {
        /* the word's box from pdftotext (points, y down) */
        char pat[64];
        snprintf(pat, sizeof pat, ">%s</word>", words[i]);
        char *hit = strstr(out, pat), *line = hit;
        double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        while (line && line > out && line[-1] != '\n')
            line--;
        if (!hit || sscanf(line, " <word xMin=\"%lf\" yMin=\"%lf\" xMax=\"%lf\" yMax=\"%lf\"", &x0,
                           &y0, &x1, &y1) != 4) {
            printf("FAIL: pdftotext does not find \"%s\"\n", words[i]);
            fails++;
            continue;
        }
        printf("ok   pdftotext finds \"%s\"\n", words[i]);
        if (bk[i].x0 > bk[i].x1 || bs[i].x0 > bs[i].x1) {
            printf("FAIL: no ink in band %d\n", i);
            fails++;
            continue;
        }
        near("left, pdftotext", i, x0 * k, bk[i].x0, 0.2 * hpx);
        near("right, pdftotext", i, x1 * k, bk[i].x1 + 1, 0.2 * hpx);
        near("left, ink", i, bs[i].x0, bk[i].x0, 0.2 * hpx);
        near("right, ink", i, bs[i].x1, bk[i].x1, 0.2 * hpx);
        near("top, ink", i, bs[i].y0, bk[i].y0, 0.15 * hpx);
        near("bottom, ink", i, bs[i].y1, bk[i].y1, 0.15 * hpx);
    }
    printf("%d failures (character height %.1f px)\n", fails, hpx);
    return fails ? 1 : 0;
}
