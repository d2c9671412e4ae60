/* SPDX-License-Identifier: MIT */
/*
 * test_nff_view.c -- end-to-end runs of the examples nff_view and mesh_view:
 *   test_nff_view NFF_VIEW MESH_VIEW TETRA_NFF WORKDIR
 * SPD tetra at 64x64 with --spd: the statistics lines parse, the counts follow from the
 * procedure (65x65 corner eye rays, a matte scene spawns no reflection or refraction rays,
 * at most one shadow ray per hit with one light), they do not depend on the thread count,
 * and the PNG shows the scene: background where rays miss, the red tetrahedron where they
 * hit. Malformed input gives exit status 2 and "file:line:" on stderr.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

static const char *nff_view, *mesh_view, *tetra, *workdir;

typedef struct { long long eye, hit, refl, refr, shadow; double t[4]; } stats;

/* Runs cmd (stderr to stdout); returns the exit status, output in out. */
static int run(const char *cmd, char *out, size_t size)
{
    char full[8192];
    int len = snprintf(full, sizeof full, "%s 2>&1", cmd);
    assert_true(len > 0 && (size_t)len < sizeof full); /* the command fits */
    FILE *p = popen(full, "r");
    assert_non_null(p);
    size_t n = fread(out, 1, size - 1, p);
    out[n] = '\0';
    int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static void parse_stats(const char *out, stats *s)
{
    int used = 0;
    int n = sscanf(out, "rays eye=%lld eye_hit=%lld reflect=%lld refract=%lld shadow=%lld\n%n",
                   &s->eye, &s->hit, &s->refl, &s->refr, &s->shadow, &used);
    if (n != 5) {
        print_error("unparsable output: %s\n", out);
        fail();
    }
    n = sscanf(out + used, "time draw=%lf build=%lf render=%lf frame=%lf", &s->t[0], &s->t[1],
               &s->t[2], &s->t[3]);
    assert_int_equal(n, 4);
    for (int k = 0; k < 4; k++)
        assert_true(isfinite(s->t[k]) && s->t[k] >= 0);
}

/* Reads an RGB PNG; caller frees. */
static unsigned char *read_png(const char *path, int *w, int *h)
{
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&im, path));
    im.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(im));
    assert_non_null(buf);
    assert_true(png_image_finish_read(&im, NULL, buf, 0, NULL));
    *w = (int)im.width;
    *h = (int)im.height;
    return buf;
}

static void test_tetra_spd(void **state)
{
    (void)state;
    char cmd[2048], out[4096], png[1024];
    snprintf(png, sizeof png, "%s/tetra_small.png", workdir);
    remove(png);
    snprintf(cmd, sizeof cmd, "'%s' --spd --threads 1 --size 64x64 '%s' '%s'", nff_view, tetra, png);
    assert_int_equal(run(cmd, out, sizeof out), 0);
    stats a, b;
    parse_stats(out, &a);
    assert_int_equal(a.eye, 65 * 65);         /* rays at the pixel corners */
    assert_true(a.hit > 0 && a.hit < a.eye);
    assert_int_equal(a.refl, 0);              /* tetra: Ks = 0, T = 0 */
    assert_int_equal(a.refr, 0);
    assert_true(a.shadow > 0 && a.shadow <= a.hit); /* one light: <= one shadow ray per hit */

    /* same statistics with two threads */
    snprintf(cmd, sizeof cmd, "'%s' --spd --threads 2 --size 64x64 '%s' '%s'", nff_view, tetra, png);
    assert_int_equal(run(cmd, out, sizeof out), 0);
    parse_stats(out, &b);
    assert_true(a.eye == b.eye && a.hit == b.hit && a.refl == b.refl && a.refr == b.refr &&
                a.shadow == b.shadow);

    /* the picture: NFF background (0.078 0.361 0.753) where rays miss, red-dominated
     * (material 1 0.2 0.2) where they hit. Tolerance: +-2 levels for the background
     * (8-bit rounding); the covered fraction may differ from the corner-hit fraction by
     * edge pixels only (< 0.1 at 64x64 for this outline). */
    int w, h;
    unsigned char *px = read_png(png, &w, &h);
    assert_int_equal(w, 64);
    assert_int_equal(h, 64);
    int bg = 0, red = 0, other = 0;
    for (int i = 0; i < w * h; i++) {
        const unsigned char *p = px + 3 * i;
        if (abs(p[0] - 20) <= 2 && abs(p[1] - 92) <= 2 && abs(p[2] - 192) <= 2)
            bg++;
        else if (p[0] >= p[1] && p[0] >= p[2])
            red++;
        else
            other++;
    }
    free(px);
    double covered = 1.0 - (double)bg / (w * h), frac = (double)a.hit / (double)a.eye;
    assert_true(bg > 0 && red > 0);
    assert_true(fabs(covered - frac) < 0.1);
    assert_true(other < red); /* blended edge pixels (many: the outline is a fractal) */
}

/* Camera mapping, exactly: the NFF angle spans the image edges, where the outermost SPD
 * corner rays go. A rectangle at 0.99 (1.01) of the window's half sizes, seen head-on,
 * is hit by all corner rays except (including) the border ones: (w-1)x(h-1) of (w+1)x(h+1)
 * rays (all of them). Non-square: square pixels, angle horizontal. One light at the eye:
 * one shadow ray per hit. */
static void test_camera_exact(void **state)
{
    (void)state;
    const int sizes[2][2] = { { 8, 8 }, { 16, 8 } };
    for (int k = 0; k < 2; k++)
        for (int out = 0; out < 2; out++) {
            int w = sizes[k][0], h = sizes[k][1];
            double hw = 10 * tan(20 * 3.14159265358979323846 / 180), hh = hw * h / w;
            double f = out ? 1.01 : 0.99;
            char path[1024], png[1100], cmd[4096], o[4096];
            snprintf(path, sizeof path, "%s/rect.nff", workdir);
            snprintf(png, sizeof png, "%s/rect.png", workdir);
            FILE *fp = fopen(path, "w");
            assert_non_null(fp);
            fprintf(fp, "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n"
                        "resolution %d %d\nb 0 0 0\nl 0 0 10\nf 1 1 1 1 0 1 0 0\n"
                        "p 4\n%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n%.17g %.17g 0\n",
                    w, h, -f * hw, -f * hh, f * hw, -f * hh, f * hw, f * hh, -f * hw, f * hh);
            fclose(fp);
            snprintf(cmd, sizeof cmd, "'%s' --spd --threads 1 '%s' '%s'", nff_view, path, png);
            assert_int_equal(run(cmd, o, sizeof o), 0);
            stats st;
            parse_stats(o, &st);
            assert_int_equal(st.eye, (w + 1) * (h + 1));
            assert_int_equal(st.hit, out ? (w + 1) * (h + 1) : (w - 1) * (h - 1));
            assert_int_equal(st.shadow, st.hit);
            assert_int_equal(st.refl, 0);
        }
}

static void test_malformed_exit(void **state)
{
    (void)state;
    char path[1024], cmd[2048], out[4096], want[1100];
    snprintf(path, sizeof path, "%s/bad.nff", workdir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("b 0 0 0\nf 1 1 1 1 0 1 0 0\np 3\n0 0 0\n1 nan 0\n0 1 0\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s/bad.png'", nff_view, path, workdir);
    assert_int_equal(run(cmd, out, sizeof out), 2);
    snprintf(want, sizeof want, "%s:5: ", path);
    assert_non_null(strstr(out, want));
    /* usage error */
    snprintf(cmd, sizeof cmd, "'%s' --threads x a b", nff_view);
    assert_int_equal(run(cmd, out, sizeof out), 1);
}

static void test_mesh_view(void **state)
{
    (void)state;
    char path[1024], png[1024], cmd[4096], out[4096];
    snprintf(path, sizeof path, "%s/cube.off", workdir);
    snprintf(png, sizeof png, "%s/cube.png", workdir);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
          "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n", f);
    fclose(f);
    snprintf(cmd, sizeof cmd, "'%s' --stats --ground --threads 1 --size 48x32 '%s' '%s'", mesh_view,
             path, png);
    assert_int_equal(run(cmd, out, sizeof out), 0);
    stats s;
    parse_stats(out, &s);
    assert_int_equal(s.eye, 49 * 33); /* the workstation's default: rays at pixel corners */
    assert_true(s.hit > 0 && s.hit <= s.eye);
    assert_true(s.shadow > 0);
    int w, h;
    unsigned char *px = read_png(png, &w, &h);
    assert_int_equal(w, 48);
    assert_int_equal(h, 32);
    int distinct = 0;
    for (int i = 1; i < w * h; i++)
        distinct += memcmp(px, px + 3 * i, 3) != 0;
    free(px);
    assert_true(distinct > w * h / 10); /* not blank */
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: test_nff_view NFF_VIEW MESH_VIEW TETRA_NFF WORKDIR\n");
        return 2;
    }
    nff_view = argv[1];
    mesh_view = argv[2];
    tetra = argv[3];
    workdir = argv[4];
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tetra_spd),
        cmocka_unit_test(test_camera_exact),
        cmocka_unit_test(test_malformed_exit),
        cmocka_unit_test(test_mesh_view),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
