/* SPDX-License-Identifier: MIT */
/*
 * test_render.c -- GKS3D_RECORD and gks3d-render (README "Legacy programs", docs/man/man1/
 * gks3d-render.1), run as a user runs them:
 *
 *   test_render DIR RENDER FIG3 PLOT2D vector|novector
 *   (DIR made empty and the test run in it; the programs' paths; novector: built without cairo, the
 *   PDF and SVG part 2 is left out)
 *
 * 1. fig3_c recorded through GKS3D_RECORD writes the same five pictures as unrecorded
 *    (byte for byte), and the recording re-rendered to PNG gives those five pictures byte
 *    for byte: the renderer interprets what the program did through the same pipeline.
 *    Frame 3 (the z-buffer preview, 80 pixels) re-rendered in the ray-tracing mode at 240
 *    pixels with 4 samples is byte-identical to the program's own ray-traced fig3.png.
 * 2. Frame 3 as PDF (pdftoppm) and SVG (rsvg-convert) at 240 pixels (48 mm) against the
 *    z-buffer PNG of the same size; plot2d_c (the RAL-style 2-D plot) recorded and
 *    re-rendered as PDF and SVG against the program's own PNG. Tolerance: the vector tests'
 *    (tests/vector/test_vector.c, and why): after a 3 x 3 box blur, at the best shift by at
 *    most a pixel, mean absolute channel difference <= 8 of 255 and at most 3 % of the
 *    pixels over 48 levels. The other HLHSR mode's picture (hidden line) must fail it, so
 *    the comparison can fail.
 * 3. Missing file, a file that is not a metafile, a truncated recording: exit status 2, the
 *    reader's error number and name on standard error, no output file. A metafile whose
 *    ESCAPE sets a file name: the escape refused (error 180 named), exit status 4, no file
 *    of that name, the picture written. Usage errors: 1; --help: 0.
 *    With --progress the set-up's phases (grid, candidate lists, light buffers) are
 *    reported a line each before the tiles.
 * 4. --name PATTERN (frame N's file; a bad pattern is a usage error writing nothing),
 *    --view 0,0 (the picture unchanged) and 30,10 (changed), --x11 without a display
 *    (status 3, a clear message). The window itself: tests/x11/test_render_x11.sh.
 * Exit status 77 (CTest: skipped) when pdftoppm or rsvg-convert is missing.
 */
#define _POSIX_C_SOURCE 200809L
#include "image_util.h"
#include <gks.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define MEAN_TOL 8.0
#define OVER_LEVEL 48
#define OVER_FRAC 0.03

static const char *render, *fig3, *plot2d;
static int failures;

#define CHECK(cond, ...)                                                                   \
    do {                                                                                   \
        if (!(cond)) {                                                                     \
            printf("FAIL: " __VA_ARGS__);                                                  \
            printf("\n");                                                                  \
            failures++;                                                                    \
        }                                                                                  \
    } while (0)

/* The exit status of sh -c cmd (-1: not run or killed). */
static int sh(const char *cmd)
{
    int st = system(cmd);
    return st != -1 && WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int shf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int shf(const char *fmt, ...)
{
    char cmd[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(cmd, sizeof cmd, fmt, ap);
    va_end(ap);
    return sh(cmd);
}

static int same_file(const char *a, const char *b)
{
    return shf("cmp -s '%s' '%s'", a, b) == 0;
}

static int exists(const char *p)
{
    return access(p, F_OK) == 0;
}

static double px(const img *im, int i, int j, int c)
{
    i = i < 0 ? 0 : i >= im->w ? im->w - 1 : i;
    j = j < 0 ? 0 : j >= im->h ? im->h - 1 : j;
    return im->rgb[3 * ((size_t)j * (size_t)im->w + (size_t)i) + (size_t)c];
}

/* The vector tests' measure: after a 3 x 3 box blur, the best shift by at most a pixel. */
static void blur_diff(const img *a, const img *b, double *mean, double *frac)
{
    *mean = *frac = INFINITY;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
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
            double n = (double)a->w * (double)a->h, m = s / (3.0 * n);
            if (m < *mean) {
                *mean = m;
                *frac = (double)over / n;
            }
        }
}

/* ras (a reader's rasterisation, cropped to ref's size from the top left) against ref:
 * 1 within tolerance. */
static int close_to(const char *ref_path, const char *ras_path, double *mean, double *frac)
{
    img a = { 0 }, b = { 0 };
    int ok = 0;
    *mean = *frac = INFINITY;
    if (!img_read(ref_path, &a) && !img_read(ras_path, &b) && b.w >= a.w && b.h >= a.h) {
        img c = { a.w, a.h, malloc((size_t)a.w * (size_t)a.h * 3) };
        if (c.rgb) {
            for (int j = 0; j < a.h; j++)
                memcpy(c.rgb + (size_t)j * (size_t)a.w * 3,
                       b.rgb + (size_t)j * (size_t)b.w * 3, (size_t)a.w * 3);
            blur_diff(&a, &c, mean, frac);
            ok = *mean <= MEAN_TOL && *frac <= OVER_FRAC;
            img_free(&c);
        }
    }
    img_free(&a);
    img_free(&b);
    return ok;
}

/* A vector file rasterised by its reader to w x h pixels (0.2 mm a pixel): 0 on success. */
static int rasterise(const char *file, const char *png, int w, int h)
{
    if (strstr(file, ".pdf")) {
        char stem[256];
        snprintf(stem, sizeof stem, "%.*s", (int)(strlen(png) - 4), png);
        return shf("pdftoppm -png -singlefile -scale-to-x %d -scale-to-y %d '%s' '%s'", w, h,
                   file, stem);
    }
    return shf("rsvg-convert -w %d -h %d -b white -o '%s' '%s'", w, h, png, file);
}

static void compare_vector(const char *file, const char *ref, int w, int h, int want_ok)
{
    char ras[256];
    snprintf(ras, sizeof ras, "ras_%s.png", file);
    double mean, frac;
    CHECK(rasterise(file, ras, w, h) == 0, "the reader could not open %s", file);
    int ok = close_to(ref, ras, &mean, &frac);
    printf("%s against %s: mean %.2f, over %d: %.2f %% -> %s\n", file, ref, mean, OVER_LEVEL,
           100 * frac, ok ? "within" : "outside");
    CHECK(ok == want_ok, "%s against %s: %s tolerance", file, ref,
          want_ok ? "outside" : "unexpectedly within");
}

static void test_fig3(void)
{
    static const char *const pics[5] = { "fig3_none.png", "fig3_hiddenline.png",
                                         "fig3_zbuffer.png", "fig3_painter.png", "fig3.png" };
    static const char *const frames[5] = { "re.png", "re-002.png", "re-003.png", "re-004.png",
                                           "re-005.png" };
    CHECK(shf("mkdir -p plain rec && cd plain && '%s' 240 > /dev/null", fig3) == 0,
          "fig3_c did not run");
    CHECK(shf("cd rec && GKS3D_RECORD=fig3.gksm '%s' 240 > /dev/null", fig3) == 0,
          "fig3_c did not run recorded");
    for (int i = 0; i < 5; i++) {
        char a[64], b[64];
        snprintf(a, sizeof a, "plain/%s", pics[i]);
        snprintf(b, sizeof b, "rec/%s", pics[i]);
        CHECK(same_file(a, b), "%s recorded differs from %s unrecorded", b, a);
    }
    CHECK(shf("cd rec && '%s' fig3.gksm -o re.png 2> re.log", render) == 0,
          "gks3d-render fig3.gksm -o re.png failed");
    CHECK(shf("grep -q '5 of 5 frames written' rec/re.log") == 0, "no summary line");
    for (int i = 0; i < 5; i++) {
        char a[64], b[64];
        snprintf(a, sizeof a, "rec/%s", frames[i]);
        snprintf(b, sizeof b, "rec/%s", pics[i]);
        CHECK(same_file(a, b), "re-rendered %s differs from the program's %s", a, b);
    }
    CHECK(shf("cd rec && '%s' fig3.gksm -o rt.png --frames 3 --mode raytrace --size 240 "
              "--samples 4 --quiet", render) == 0, "ray-traced re-render failed");
    CHECK(same_file("rec/rt.png", "rec/fig3.png"),
          "frame 3 ray traced differs from the program's fig3.png");
    CHECK(!exists("rec/rt-002.png"), "--frames 3 wrote more than one frame");
    /* --progress: the set-up's phases (grid, candidate lists, light buffers) a line each,
       then the tiles and the summary (src/rt/rt_render.c) */
    CHECK(shf("cd rec && '%s' fig3.gksm -o pr.png --frames 3 --mode raytrace --size 120 "
              "--samples 1 --progress --quiet 2> pr.log", render) == 0, "--progress failed");
    CHECK(shf("grep -q '^rt: set-up: grid of [0-9]* primitives \\.\\.\\. [0-9.]* s$' rec/pr.log"
              " && grep -q '^rt: set-up: candidate lists \\.\\.\\. [0-9.]* s$' rec/pr.log"
              " && grep -q '^rt: set-up: light buffers \\.\\.\\. [0-9.]* s$' rec/pr.log"
              " && grep -q 'rt: [0-9]* tiles done in' rec/pr.log") == 0,
          "--progress: the set-up phases or the summary not reported (rec/pr.log)");
    /* the summary line: frames, time, and the rays of the ray-traced frame */
    CHECK(shf("cd rec && '%s' fig3.gksm -o sum.png --frames 3 --mode raytrace --size 120 "
              "--samples 1 2> sum.log && grep -q '^gks3d-render: 1 of 5 frames written to "
              "sum.png in [0-9.]* s; [1-9][0-9]* rays traced in [0-9.]* s, [0-9.]* Mrays/s$' "
              "sum.log", render) == 0,
          "the summary line lacks the frames, time or rays (rec/sum.log)");
}

static void test_vector_out(void)
{
    CHECK(shf("cd rec && '%s' fig3.gksm -o z.png --frames 3 --size 240 --quiet && "
              "'%s' fig3.gksm -o z.pdf --frames 3 --size 240 --quiet && "
              "'%s' fig3.gksm -o z.svg --frames 3 --size 240 --quiet && "
              "'%s' fig3.gksm -o hl.png --frames 2 --size 240 --quiet",
              render, render, render, render) == 0, "vector re-render of fig3 failed");
    if (chdir("rec") == 0) {
        compare_vector("z.pdf", "z.png", 240, 240, 1);
        compare_vector("z.svg", "z.png", 240, 240, 1);
        compare_vector("z.pdf", "hl.png", 240, 240, 0); /* another mode: must fail */
        CHECK(chdir("..") == 0, "chdir");
    }
    CHECK(shf("mkdir -p p2 && cd p2 && GKS3D_RECORD=plot.gksm '%s' 360 > /dev/null && "
              "'%s' plot.gksm -o plot.pdf --quiet && '%s' plot.gksm -o plot.svg --quiet",
              plot2d, render, render) == 0, "plot2d_c recorded and re-rendered failed");
    if (chdir("p2") == 0) {
        compare_vector("plot.pdf", "plot2d.png", 360, 360, 1);
        compare_vector("plot.svg", "plot2d.png", 360, 360, 1);
        CHECK(chdir("..") == 0, "chdir");
    }
}

/* A metafile whose ESCAPE names a file (written by the library's own MO workstation). */
static void write_hostile(const char *path)
{
    gopen_gks(NULL, 0);
    gopen_ws(1, path, GWS_TYPE_MO);
    gactivate_ws(1);
    Gescape_in_data in = { { 1, (Gint[]){ 1 }, 0, NULL, 6, "pwned1" } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    Gpoint p[2] = { { 0.1f, 0.1f }, { 0.9f, 0.9f } };
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
}

static void test_bad_input(void)
{
    CHECK(shf("mkdir -p bad && cd bad && '%s' nosuch.gksm -o a.png 2> a.log; test $? = 2",
              render) == 0, "missing file: exit status not 2");
    CHECK(shf("grep -q 'GKS error 26' bad/a.log") == 0, "missing file: no error 26 named");
    CHECK(shf("cd bad && echo 'not a metafile' > t.gksm && '%s' t.gksm -o b.png 2> b.log; "
              "test $? = 2", render) == 0, "text file: exit status not 2");
    CHECK(shf("cd bad && head -c 20000 ../rec/fig3.gksm > cut.gksm && "
              "'%s' cut.gksm -o c.png 2> c.log; test $? = 2", render) == 0,
          "truncated file: exit status not 2");
    CHECK(shf("grep -q 'truncated' bad/c.log && grep -q 'GKS error 163' bad/c.log") == 0,
          "truncated file (inside an item): no clear message");
    CHECK(shf("cd bad && head -c $(grep -abo 'GKSM  0' ../rec/fig3.gksm | cut -d: -f1) "
              "../rec/fig3.gksm > end.gksm && '%s' end.gksm -o d.png 2> d.log; test $? = 2",
              render) == 0, "file without END: exit status not 2");
    CHECK(shf("grep -q 'truncated' bad/d.log && grep -q 'GKS error 162' bad/d.log") == 0,
          "file without END: no clear message");
    CHECK(!exists("bad/a.png") && !exists("bad/b.png") && !exists("bad/c.png") &&
              !exists("bad/d.png"),
          "an output file was written for a bad input");
    write_hostile("bad/hostile.gksm");
    CHECK(shf("cd bad && '%s' hostile.gksm -o h.png 2> h.log; test $? = 4", render) == 0,
          "hostile file: exit status not 4");
    CHECK(shf("grep -q 'GKS error 180' bad/h.log") == 0, "hostile file: refusal not named");
    CHECK(exists("bad/h.png") && !exists("bad/pwned1.png"),
          "hostile file: the escape chose a file name");
    CHECK(shf("'%s' > /dev/null 2>&1; test $? = 1", render) == 0, "no arguments: not 1");
    CHECK(shf("'%s' x.gksm -o x.gif > /dev/null 2>&1; test $? = 1", render) == 0,
          "unknown type: not 1");
    CHECK(shf("'%s' --help | grep -q 'usage: gks3d-render'", render) == 0, "--help");
}

/* --name: frame N's file from the pattern and N alone; patterns with another conversion,
 * and PDF/PS (pages, not files), are usage errors that write nothing. --view 0,0 changes
 * nothing. --x11 without a display: a clear message, status 3. */
static void test_name_view(void)
{
    CHECK(shf("mkdir -p nm && cd nm && '%s' ../rec/fig3.gksm --name 'f%%%%-%%03d.png' "
              "--frames 2,4-5 --quiet", render) == 0, "--name failed");
    CHECK(same_file("nm/f%-002.png", "rec/re-002.png") &&
              same_file("nm/f%-004.png", "rec/re-004.png") &&
              same_file("nm/f%-005.png", "rec/re-005.png"),
          "--name: frames 2, 4, 5 not written to f%%-002.png, f%%-004.png, f%%-005.png");
    CHECK(shf("cd nm && test $(ls | wc -l) = 3") == 0, "--name: other files written");
    static const char *const bad[] = { "x-%s.png", "x.png", "x-%d-%d.png", "x-%n.png",
                                       "x-%10d.png", "x-%d.pdf" };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        CHECK(shf("cd nm && '%s' ../rec/fig3.gksm --name '%s' > /dev/null 2>&1; "
                  "test $? = 1 && test $(ls | wc -l) = 3", render, bad[i]) == 0,
              "--name '%s': not a usage error, or a file written", bad[i]);
    CHECK(shf("cd nm && '%s' ../rec/fig3.gksm -o v.png --frames 3 --view 0,0 --quiet",
              render) == 0 && same_file("nm/v.png", "rec/re-003.png"),
          "--view 0,0 changed the picture");
    CHECK(shf("cd nm && '%s' ../rec/fig3.gksm -o t.png --frames 3 --view 30,10 --quiet",
              render) == 0 && !same_file("nm/t.png", "rec/re-003.png"),
          "--view 30,10 did not turn the picture");
    CHECK(shf("cd nm && DISPLAY= '%s' ../rec/fig3.gksm --x11 2> x.log; test $? = 3",
              render) == 0, "--x11 without a display: exit status not 3");
    CHECK(shf("grep -qE 'no X display|built without X11' nm/x.log") == 0,
          "--x11 without a display: no clear message");
}

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: test_render DIR RENDER FIG3 PLOT2D vector|novector\n");
        return 2;
    }
    render = argv[2];
    fig3 = argv[3];
    plot2d = argv[4];
    int vector = strcmp(argv[5], "vector") == 0;
    if (shf("rm -rf '%s' && mkdir -p '%s'", argv[1], argv[1]) || chdir(argv[1])) {
        printf("FAIL: cannot make %s\n", argv[1]);
        return 1;
    }
    if (vector &&
        sh("command -v pdftoppm > /dev/null && command -v rsvg-convert > /dev/null") != 0) {
        printf("SKIP: pdftoppm (poppler-utils) or rsvg-convert (librsvg2-bin) missing\n");
        return 77;
    }
    test_fig3();
    if (vector)
        test_vector_out();
    else
        printf("built without cairo: PDF and SVG not tested\n");
    test_bad_input();
    test_name_view();
    printf("%s (%d failures)\n", failures ? "FAILED" : "passed", failures);
    return failures ? 1 : 0;
}
