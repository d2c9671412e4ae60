/* SPDX-License-Identifier: MIT */
/*
 * test_images.c -- image regression tests of the example programs (examples/c/fig*.c,
 * surface.c and their Fortran twins in examples/f77).
 *
 *   test_images run   CBIN FBIN REFDIR OUTDIR   runs every C and Fortran program at the test
 *                                               size (the CTest fixture of the others)
 *   test_images refs  CBIN FBIN REFDIR OUTDIR   each C program's pictures against
 *                                               REFDIR/<file>.ref.png
 *   test_images twins CBIN FBIN REFDIR OUTDIR   C and Fortran pictures byte-identical
 *   test_images fig45 CBIN FBIN REFDIR OUTDIR   the structural Fig. 4/5 check
 *
 * CBIN/FBIN: directories of the programs <name>_c and <name>_f77. Pictures are written to
 * OUTDIR (c_<file>.png, f_<file>.png), diff pictures to OUTDIR/<file>.diff.png.
 * Test size: 120 pixels (previews 40). With GKS_UPDATE_IMAGE_REFS=1 in the environment the
 * refs mode writes the references instead of comparing.
 *
 * Tolerance of the reference comparison: a pixel counts as different when a channel differs
 * by more than 1 level, and at most 1 in 1000 pixels may differ (1 in a 40 x 40 preview, 14
 * in the 120 x 120 picture).
 * The ray tracer is deterministic and independent of the thread count, so our own build
 * reproduces the references exactly (max difference 0, checked at generation); the
 * allowance absorbs last-bit differences of another compiler or libm, which can move a
 * polygon edge across a sample point and flip an edge pixel, not a changed picture.
 *
 * Fig. 4/5 (the paper's point): both show the ventilator whose far part is clipped away by
 * the view clip (NPC3 y > 0.7); Fig. 4 traces shadow rays against the whole scene, Fig. 5
 * only against the display volume. The fan scene is opaque with reflectance equation
 * ambient+diffuse, so shadow rays are its only secondary rays (no reflection or refraction
 * path to follow). From the scene geometry (fig_scene.h) and the camera the
 * tracer recovers (rt_camera_from_view), each sample ray of each pixel is cast here: its
 * visible point, then the segment to the lamp, whose hits on the fan are classified inside or
 * outside the display volume (mapped to NPC3). Then
 *   (a) the pictures differ only at pixels where some sample's shadow ray reaches the
 *       clipped part (dilated by one pixel for samples that graze an edge);
 *   (b) where every sample's shadow ray is blocked only by the clipped part (eroded by one
 *       pixel), Fig. 4 is darker than Fig. 5 in every pixel, by at least 30 % on average;
 *   (c) that region is not trivially small and the "may differ" region not the whole picture.
 */
#define _POSIX_C_SOURCE 200809L
#include "fig_scene.h"
#include "image_util.h"
#include <gks.h>
#include <gksrt.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

enum { TEST_SIZE = 120, MAX_FILES = 5, PATH_LEN = 1024 };

typedef struct {
    const char *name;
    int n_files;
    const char *files[MAX_FILES];
} example;

static const example EXAMPLES[] = {
    { "fig2", 5, { "fig2", "fig2_none", "fig2_hiddenline", "fig2_zbuffer", "fig2_painter" } },
    { "fig3", 5, { "fig3", "fig3_none", "fig3_hiddenline", "fig3_zbuffer", "fig3_painter" } },
    { "fig4", 5, { "fig4", "fig4_none", "fig4_hiddenline", "fig4_zbuffer", "fig4_painter" } },
    { "fig5", 5, { "fig5", "fig5_none", "fig5_hiddenline", "fig5_zbuffer", "fig5_painter" } },
    { "surface", 4, { "surface", "surface_zbuffer", "surface_smooth", "surface_smooth_zbuffer" } },
};
enum { N_EXAMPLES = sizeof EXAMPLES / sizeof EXAMPLES[0] };

typedef struct {
    const char *cbin, *fbin, *refdir, *outdir;
} config;
static config cfg;

/* Runs DIR/NAME SUFFIX with the test size and prefix OUTDIR/tag_; 0 on exit status 0. */
static int run_example(const char *dir, const char *name, const char *suffix, const char *tag)
{
    char prog[PATH_LEN], prefix[PATH_LEN], size[16];
    snprintf(prog, sizeof prog, "%s/%s%s", dir, name, suffix);
    snprintf(prefix, sizeof prefix, "%s/%s_", cfg.outdir, tag);
    snprintf(size, sizeof size, "%d", TEST_SIZE);
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        execl(prog, prog, size, prefix, (char *)NULL);
        _exit(127);
    }
    int st = 0;
    if (waitpid(pid, &st, 0) != pid)
        return -1;
    return WIFEXITED(st) && WEXITSTATUS(st) == 0 ? 0 : -1;
}

static void out_path(char *buf, size_t n, const char *tag, const char *file)
{
    snprintf(buf, n, "%s/%s_%s.png", cfg.outdir, tag, file);
}

/* ------------------------------------------------------------------ running */
static void test_run(void **state)
{
    const example *ex = *state;
    assert_int_equal(run_example(cfg.cbin, ex->name, "_c", "c"), 0);
    assert_int_equal(run_example(cfg.fbin, ex->name, "_f77", "f"), 0);
}

/* ------------------------------------------------------------------ references */
static void test_reference(void **state)
{
    const example *ex = *state;
    const char *update = getenv("GKS_UPDATE_IMAGE_REFS");
    for (int i = 0; i < ex->n_files; i++) {
        char out[PATH_LEN], ref[PATH_LEN], diff[PATH_LEN];
        out_path(out, sizeof out, "c", ex->files[i]);
        snprintf(ref, sizeof ref, "%s/%s.ref.png", cfg.refdir, ex->files[i]);
        snprintf(diff, sizeof diff, "%s/%s.diff.png", cfg.outdir, ex->files[i]);
        if (update && strcmp(update, "1") == 0) {
            assert_int_equal(file_copy(out, ref), 0);
            printf("reference written: %s\n", ref);
            continue;
        }
        img a, b;
        if (img_read(ref, &a))
            fail_msg("missing reference %s (GKS_UPDATE_IMAGE_REFS=1 writes it)", ref);
        assert_int_equal(img_read(out, &b), 0);
        img_cmp r;
        int sized = img_compare(&a, &b, 1, diff, &r);
        size_t allowed = (size_t)a.w * (size_t)a.h / 1000;
        printf("%s: %zu pixels over tolerance (allowed %zu), max difference %d\n",
               ex->files[i], r.n_over, allowed, r.max_diff);
        img_free(&a);
        img_free(&b);
        assert_int_equal(sized, 0);
        assert_true(r.n_over <= allowed);
    }
}

/* ------------------------------------------------------------------ C vs Fortran */
static void test_twins(void **state)
{
    const example *ex = *state;
    for (int i = 0; i < ex->n_files; i++) {
        char a[PATH_LEN], b[PATH_LEN];
        out_path(a, sizeof a, "c", ex->files[i]);
        out_path(b, sizeof b, "f", ex->files[i]);
        int same = file_same(a, b);
        printf("%s: C and Fortran pictures %s\n", ex->files[i],
               same == 1 ? "byte-identical" : "DIFFER");
        assert_int_equal(same, 1);
    }
}

/* ------------------------------------------------------------------ Fig. 4/5 geometry */
typedef struct {
    int n;
    double v[8][3]; /* VRC3 */
} poly;

static void xf_point(const Gmatrix3 m, const double p[3], double o[3])
{
    double w = m[3][0] * p[0] + m[3][1] * p[1] + m[3][2] * p[2] + m[3][3];
    if (w == 0 || !isfinite(w))
        w = 1;
    for (int i = 0; i < 3; i++)
        o[i] = (m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3]) / w;
}

static void sub(const double a[3], const double b[3], double o[3])
{
    for (int i = 0; i < 3; i++)
        o[i] = a[i] - b[i];
}

static double dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Ray o + t d against a convex polygon: t, or NAN when missed. */
static double hit_convex(const poly *p, const double o[3], const double d[3])
{
    double nrm[3] = { 0, 0, 0 };
    for (int i = 0; i < p->n; i++) { /* Newell */
        const double *a = p->v[i], *b = p->v[(i + 1) % p->n];
        nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
        nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
        nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    double den = dot(nrm, d);
    if (fabs(den) < 1e-300)
        return NAN;
    double w[3];
    sub(p->v[0], o, w);
    double t = dot(nrm, w) / den;
    double q[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    for (int i = 0; i < p->n; i++) {
        double e[3], r[3], c[3];
        sub(p->v[(i + 1) % p->n], p->v[i], e);
        sub(q, p->v[i], r);
        cross(e, r, c);
        if (dot(c, nrm) < 0)
            return NAN;
    }
    return t;
}

typedef struct {
    Gmatrix3 ori, map;
    double box[6]; /* display volume, NPC3 */
    poly board, fan[FIG_FAN_N + 1];
    double lamp[3];
} fan_scene;

static void round_matrix(Gmatrix3 m)
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[i][j] = (float)m[i][j];
}

/* The view of fig_scene.c (same float inputs, matrices rounded to float as there). */
static void scene_view(fan_scene *s)
{
    Gint err = 0;
    Gpoint3 vrp = { FIG_VRP[0], FIG_VRP[1], FIG_VRP[2] };
    Gvec3 vpn = { FIG_VPN[0], FIG_VPN[1], FIG_VPN[2] };
    Gvec3 vup = { FIG_VUP[0], FIG_VUP[1], FIG_VUP[2] };
    gopen_gks(NULL, 0);
    geval_view_ori_matrix3(&vrp, &vpn, &vup, GCOORD_NDC, &err, s->ori);
    assert_int_equal(err, 0);
    Gview_map3 m = { { FIG_WINDOW[0], FIG_WINDOW[1], FIG_WINDOW[2], FIG_WINDOW[3] },
                     { FIG_PRVP[0], FIG_PRVP[1], FIG_PRVP[2], FIG_PRVP[3], FIG_PRVP[4],
                       FIG_PRVP[5] },
                     GPROJ_PERSPECT, { FIG_PRP[0], FIG_PRP[1], FIG_PRP[2] },
                     FIG_VPD, FIG_BPD, FIG_FPD };
    geval_view_map_matrix3(&m, &err, s->map);
    assert_int_equal(err, 0);
    gclose_gks();
    round_matrix(s->ori);
    round_matrix(s->map);
}

/* The board and fan polygons of fig_scene.c in VRC3 (float arithmetic as there). */
static void scene_polys(fan_scene *s)
{
    static const double bx[4] = { 0.1, 0.9, 0.9, 0.1 }, bz[4] = { 0.1, 0.1, 0.9, 0.9 };
    s->board.n = 4;
    for (int k = 0; k < 4; k++)
        xf_point(s->ori, (const double[3]){ (float)bx[k], 0.1f, (float)bz[k] }, s->board.v[k]);
    const float *c = FIG_FAN_C;
    for (int i = 0; i < FIG_FAN_N; i++) {
        s->fan[i].n = 4;
        for (int k = 0; k < 4; k++) {
            float r = k < 2 ? FIG_FAN_R0 : FIG_FAN_R1;
            float x = c[0] + r * FIG_FAN_DIR[i][k][0], z = c[2] + r * FIG_FAN_DIR[i][k][1];
            xf_point(s->ori, (const double[3]){ x, c[1], z }, s->fan[i].v[k]);
        }
    }
    poly *hub = &s->fan[FIG_FAN_N];
    hub->n = 6;
    for (int k = 0; k < 6; k++) {
        float x = c[0] + FIG_FAN_R0 * FIG_HUB_DIR[k][0], y = c[1] + 0.004f,
              z = c[2] + FIG_FAN_R0 * FIG_HUB_DIR[k][1];
        xf_point(s->ori, (const double[3]){ x, y, z }, hub->v[k]);
    }
    xf_point(s->ori, (const double[3]){ FIG_LAMP_FAN[0], FIG_LAMP_FAN[1], FIG_LAMP_FAN[2] },
             s->lamp);
}

static int inside_box(const fan_scene *s, const double p[3])
{
    double npc[3];
    xf_point(s->map, p, npc);
    const double e = 1e-9;
    return npc[0] >= s->box[0] - e && npc[0] <= s->box[1] + e && npc[1] >= s->box[2] - e &&
           npc[1] <= s->box[3] + e && npc[2] >= s->box[4] - e && npc[2] <= s->box[5] + e;
}

enum { S_BG = 0, S_SAME = 1, S_AFFECTED = 2, S_DARKER = 4 };

/* Classifies one primary ray: S_BG (misses), S_SAME (shadow rays never reach the clipped
 * part), S_AFFECTED (some hit outside the display volume), plus S_DARKER when the point is on
 * the board and only the clipped part blocks the lamp. */
static int classify(const fan_scene *s, const rt_ray *ray)
{
    double best = INFINITY;
    int on_board = 0;
    double t = hit_convex(&s->board, ray->org, ray->dir);
    if (t >= ray->tmin && t <= ray->tmax) {
        best = t;
        on_board = 1;
    }
    for (int i = 0; i <= FIG_FAN_N; i++) {
        t = hit_convex(&s->fan[i], ray->org, ray->dir);
        if (t >= ray->tmin && t <= ray->tmax && t < best) {
            best = t;
            on_board = 0;
        }
    }
    if (!isfinite(best))
        return S_BG;
    double p[3], d[3];
    for (int k = 0; k < 3; k++)
        p[k] = ray->org[k] + best * ray->dir[k];
    sub(s->lamp, p, d);
    int hit_in = 0, hit_out = 0;
    for (int i = 0; i <= FIG_FAN_N; i++) {
        t = hit_convex(&s->fan[i], p, d);
        if (!(t > 1e-6 && t < 1 - 1e-6))
            continue;
        double h[3] = { p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2] };
        if (inside_box(s, h))
            hit_in = 1;
        else
            hit_out = 1;
    }
    if (!hit_out)
        return S_SAME;
    return S_AFFECTED | (on_board && !hit_in ? S_DARKER : 0);
}

static int lum(const img *im, int x, int y)
{
    const unsigned char *p = im->rgb + 3 * ((size_t)y * im->w + x);
    return p[0] + p[1] + p[2];
}

static void test_fig45(void **state)
{
    (void)state;
    char p4[PATH_LEN], p5[PATH_LEN];
    out_path(p4, sizeof p4, "c", "fig4");
    out_path(p5, sizeof p5, "c", "fig5");
    img f4, f5;
    assert_int_equal(img_read(p4, &f4), 0);
    assert_int_equal(img_read(p5, &f5), 0);
    const int S = TEST_SIZE;
    assert_int_equal(f4.w, S);
    assert_int_equal(f5.h, S);

    fan_scene *s = calloc(1, sizeof *s);
    assert_non_null(s);
    scene_view(s);
    scene_polys(s);
    /* Display volume and raster as the workstation computes them: clip limits ∩ the
     * workstation window [0,1]^3, viewport S x S pixels, rows rounded to whole pixels. */
    const double box[6] = { fmax(0, FIG_CLIP_FAN[0]), fmin(1, FIG_CLIP_FAN[1]),
                            fmax(0, FIG_CLIP_FAN[2]), fmin(1, FIG_CLIP_FAN[3]),
                            fmax(0, FIG_CLIP_FAN[4]), fmin(1, FIG_CLIP_FAN[5]) };
    int ix0 = (int)round(box[0] * S), ix1 = (int)round(box[1] * S);
    int iy0 = (int)round(box[2] * S), iy1 = (int)round(box[3] * S);
    double sx = (box[1] - box[0]) / ((box[1] - box[0]) * S),
           sy = (box[3] - box[2]) / ((box[3] - box[2]) * S);
    double nb[6] = { box[0] + (ix0 - box[0] * S) * sx, box[0] + (ix1 - box[0] * S) * sx,
                     box[2] + (iy0 - box[2] * S) * sy, box[2] + (iy1 - box[2] * S) * sy,
                     box[4], box[5] };
    memcpy(s->box, nb, sizeof nb);
    int w = ix1 - ix0, h = iy1 - iy0;
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, (const double (*)[4])s->map, nb, w, h), RT_OK);

    /* Per picture pixel: OR of the sample classes, and whether all samples are S_DARKER.
     * The main picture has 2 x 2 stratified samples per pixel (GESC_RT_SAMPLES 4). */
    size_t n = (size_t)S * S;
    unsigned char *any = calloc(n, 1), *all_dark = calloc(n, 1);
    unsigned char *may = calloc(n, 1), *pure = calloc(n, 1);
    assert_true(any && all_dark && may && pure);
    for (int row = 0; row < h; row++)
        for (int c = 0; c < w; c++) {
            int acc = 0, dark = 1;
            for (int k = 0; k < 4; k++) {
                rt_ray ray;
                assert_int_equal(rt_camera_ray(&cam, c + 0.25 + 0.5 * (k & 1),
                                               row + 0.25 + 0.5 * (k >> 1), &ray), RT_OK);
                int cl = classify(s, &ray);
                acc |= cl;
                dark &= (cl & S_DARKER) != 0;
            }
            /* rt rows are top-first within the raster; PNG row 0 is the picture's top */
            size_t q = (size_t)(S - iy1 + row) * S + (size_t)(ix0 + c);
            any[q] = (acc & S_AFFECTED) != 0;
            all_dark[q] = (unsigned char)dark;
        }
    size_t n_may = 0, n_pure = 0, n_diff = 0, bad = 0, not_darker = 0;
    double sum4 = 0, sum5 = 0;
    for (int y = 0; y < S; y++)
        for (int x = 0; x < S; x++) {
            int m = 0, p = 1;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    int xx = x + dx, yy = y + dy;
                    int ok = xx >= 0 && yy >= 0 && xx < S && yy < S;
                    m |= ok && any[(size_t)yy * S + xx];
                    p &= ok && all_dark[(size_t)yy * S + xx];
                }
            size_t q = (size_t)y * S + x;
            may[q] = (unsigned char)m;
            pure[q] = (unsigned char)p;
            n_may += m;
            n_pure += p;
            int differ = memcmp(f4.rgb + 3 * q, f5.rgb + 3 * q, 3) != 0;
            n_diff += differ;
            if (differ && !m) {
                if (bad < 5)
                    printf("pixel (%d, %d) differs outside the computed region\n", x, y);
                bad++;
            }
            if (p) {
                int l4 = lum(&f4, x, y), l5 = lum(&f5, x, y);
                not_darker += l4 >= l5;
                sum4 += l4;
                sum5 += l5;
            }
        }
    printf("fig4/fig5: %zu pixels differ; region reached by secondary rays: %zu pixels "
           "(dilated); shadowed only by the clipped part: %zu pixels (eroded), mean "
           "brightness %.1f vs %.1f\n", n_diff, n_may, n_pure, n_pure ? sum4 / n_pure : 0.0,
           n_pure ? sum5 / n_pure : 0.0);
    assert_int_equal(bad, 0);                 /* (a) */
    assert_true(n_diff > 0);
    assert_int_equal(not_darker, 0);          /* (b) */
    assert_true(sum4 <= 0.7 * sum5);
    assert_true(n_pure >= n / 50);            /* (c): at least 2 % of the picture */
    assert_true(n_may <= n / 2);
    free(any);
    free(all_dark);
    free(may);
    free(pure);
    free(s);
    img_free(&f4);
    img_free(&f5);
}

int main(int argc, char **argv)
{
    if (argc != 6) {
        fprintf(stderr, "usage: %s run|refs|twins|fig45 CBIN FBIN REFDIR OUTDIR\n", argv[0]);
        return 2;
    }
    cfg = (config){ argv[2], argv[3], argv[4], argv[5] };
    struct CMUnitTest runs[N_EXAMPLES], refs[N_EXAMPLES], twins[N_EXAMPLES];
    for (int i = 0; i < N_EXAMPLES; i++) {
        runs[i] = (struct CMUnitTest)cmocka_unit_test_prestate(test_run, (void *)&EXAMPLES[i]);
        runs[i].name = EXAMPLES[i].name;
        refs[i] = (struct CMUnitTest)cmocka_unit_test_prestate(test_reference,
                                                               (void *)&EXAMPLES[i]);
        refs[i].name = EXAMPLES[i].name;
        twins[i] = (struct CMUnitTest)cmocka_unit_test_prestate(test_twins,
                                                                (void *)&EXAMPLES[i]);
        twins[i].name = EXAMPLES[i].name;
    }
    const struct CMUnitTest fig45[] = { cmocka_unit_test(test_fig45) };
    if (strcmp(argv[1], "run") == 0)
        return _cmocka_run_group_tests("example programs", runs, N_EXAMPLES, NULL, NULL);
    if (strcmp(argv[1], "refs") == 0)
        return _cmocka_run_group_tests("image references", refs, N_EXAMPLES, NULL, NULL);
    if (strcmp(argv[1], "twins") == 0)
        return _cmocka_run_group_tests("C vs Fortran", twins, N_EXAMPLES, NULL, NULL);
    if (strcmp(argv[1], "fig45") == 0)
        return cmocka_run_group_tests(fig45, NULL, NULL);
    fprintf(stderr, "unknown mode %s\n", argv[1]);
    return 2;
}
