/* SPDX-License-Identifier: MIT */
/*
 * test_first_frame.c -- the first frame right (issue 37 item 6): SET COLOUR REPRESENTATION
 * of index 0 after OPEN WORKSTATION and before the first output is the background of that
 * first frame, on every drawing file workstation type (PNG; PDF, SVG, PS, EPS when built
 * with cairo) and in every HLHSR mode 0-4, whatever came before it:
 *   "open"   colour 0 set right after OPEN WORKSTATION;
 *   "vp"     after SET WORKSTATION VIEWPORT (which clears the empty picture);
 *   "vp+upd" after SET WORKSTATION VIEWPORT and an UPDATE that already wrote the empty
 *            frame (the same frame is written again, to the same file).
 * A square is drawn in the middle; pixel (5, 5) from the top left of the frame's picture
 * must be red. PNG files are read directly; vector files are rendered by pdftoppm (PDF),
 * rsvg-convert (SVG) and gs (PS, EPS), which scripts/setup.sh installs. Tolerance: 3 of
 * 255 per channel, because the z-buffer and ray-traced modes embed the frame as an image
 * that the readers pass through their colour conversion (pdftoppm gives 254 for 255);
 * white, the wrong answer, is 255 away in green and blue.
 * Usage: test_first_frame OUTDIR. Exit 0 all pass, 1 any fail, 77 a renderer missing
 * (the types it renders are then skipped, the others still checked).
 */
#include <gks.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *outdir;
static int fails, skipped;

/* pixel (x, y) from the top left of an 8-bit PNG as RGB; 0 when unreadable */
static int png_pixel(const char *path, int x, int y, int rgb[3])
{
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path))
        return 0;
    pi.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(pi));
    png_color white = { 255, 255, 255 }; /* a transparent SVG background reads as white */
    int ok = buf && png_image_finish_read(&pi, &white, buf, 0, NULL) &&
             x < (int)pi.width && y < (int)pi.height;
    if (ok)
        for (int k = 0; k < 3; k++)
            rgb[k] = buf[3 * ((size_t)y * pi.width + (size_t)x) + (size_t)k];
    free(buf);
    png_image_free(&pi);
    return ok;
}

static int have(const char *tool)
{
    char cmd[256];
    snprintf(cmd, sizeof cmd, "command -v %s >/dev/null 2>&1", tool);
    return system(cmd) == 0;
}

typedef struct {
    int type;
    const char *ext, *tool;
    double vp; /* workstation viewport edge: 64 pixels, or 3 cm */
} wstype;

static const wstype types[] = {
    { GWS_TYPE_PNG, "png", NULL, 64 },
    { GWS_TYPE_PDF, "pdf", "pdftoppm", 0.03 },
    { GWS_TYPE_SVG, "svg", "rsvg-convert", 0.03 },
    { GWS_TYPE_PS, "ps", "gs", 0.03 },
    { GWS_TYPE_EPS, "eps", "gs", 0.03 },
};
static const char *const cases[] = { "open", "vp", "vp+upd" };

/* The frame's picture as a PNG: the file itself or its rendering; 1 on success (0 also
 * when a path does not fit the buffers: the test then fails rather than run a cut name). */
static int render(const wstype *t, const char *file, char *png, size_t n)
{
    char cmd[2048];
    int k;
    if (!t->tool)
        return snprintf(png, n, "%s", file) < (int)n;
    if (snprintf(png, n, "%s.render.png", file) >= (int)n)
        return 0;
    if (t->type == GWS_TYPE_PDF) {
        char prefix[700];
        if (snprintf(prefix, sizeof prefix, "%s.render", file) >= (int)sizeof prefix)
            return 0;
        k = snprintf(cmd, sizeof cmd, "pdftoppm -png -r 72 -singlefile '%s' '%s'", file, prefix);
    } else if (t->type == GWS_TYPE_SVG) {
        k = snprintf(cmd, sizeof cmd, "rsvg-convert -o '%s' '%s'", png, file);
    } else {
        k = snprintf(cmd, sizeof cmd, "gs -q -dSAFER -dBATCH -dNOPAUSE -sDEVICE=png16m -r72 %s "
                     "-dFirstPage=1 -dLastPage=1 -sOutputFile='%s' '%s'",
                     t->type == GWS_TYPE_EPS ? "-dEPSCrop" : "", png, file);
    }
    return k < (int)sizeof cmd && system(cmd) == 0;
}

static void one(const wstype *t, int mode, int c)
{
    char base[512], file[600], png[700];
    snprintf(base, sizeof base, "%s/%s_mode%d_%s", outdir, t->ext, mode,
             c == 0 ? "open" : c == 1 ? "vp" : "vpupd");
    snprintf(file, sizeof file, "%s.%s", base, t->ext);
    remove(file);
    gopen_ws(1, base, t->type);
    if (c >= 1)
        gset_ws_vp(1, &(Glimit){ 0, t->vp, 0, t->vp });
    gset_hlhsr_mode(1, mode);
    if (c == 2)
        gupd_ws(1, GFLAG_PERFORM);
    Gcolr_rep red = { .rgb = { 1, 0, 0 } };
    gset_colr_rep(1, 0, &red);
    if (c == 0)
        gset_ws_vp(1, &(Glimit){ 0, t->vp, 0, t->vp });
    gactivate_ws(1);
    Gpoint p[4] = { { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.6, 0.6 }, { 0.4, 0.6 } };
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(1);
    gfill_area(&(Gpoint_list){ 4, p });
    gdeactivate_ws(1);
    gclose_ws(1);
    int rgb[3] = { -1, -1, -1 };
    if (!render(t, file, png, sizeof png) || !png_pixel(png, 5, 5, rgb)) {
        printf("FAIL %s mode %d %s: no picture (%s)\n", t->ext, mode, cases[c], png);
        fails++;
        return;
    }
    int ok = rgb[0] >= 252 && rgb[1] <= 3 && rgb[2] <= 3;
    printf("%s %s HLHSR mode %d, colour 0 set %s: pixel (5,5) = %d %d %d\n",
           ok ? "ok  " : "FAIL", t->ext, mode, cases[c], rgb[0], rgb[1], rgb[2]);
    fails += !ok;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    outdir = argv[1];
    gopen_gks(NULL, 0);
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++) {
        const wstype *t = &types[i];
        Gint err = -1;
        Gws_cat cat;
        ginq_ws_cat(t->type, &err, &cat);
        if (err) {
            printf("skipped: %s, not built (GKS_WITH_CAIRO)\n", t->ext);
            continue;
        }
        if (t->tool && !have(t->tool)) {
            printf("skipped: %s, %s not installed (scripts/setup.sh installs it)\n", t->ext,
                   t->tool);
            skipped++;
            continue;
        }
        for (int mode = 0; mode <= 4; mode++)
            for (int c = 0; c < 3; c++)
                one(t, mode, c);
    }
    gclose_gks();
    printf("%d failures\n", fails);
    return fails ? 1 : skipped ? 77 : 0;
}
