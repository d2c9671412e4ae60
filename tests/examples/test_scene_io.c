/* SPDX-License-Identifier: MIT */
/*
 * test_scene_io.c -- unit tests of the NFF/OFF/PLY reader (examples/c/scene_io.c):
 * every keyword with known values, and a table of malformed inputs, each with the error
 * code and the "name:line: message" it must produce.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "scene_io.h"

static int parse(const char *text, scene_io_format fmt, const scene_io_options *o,
                 scene_io_scene *s, char *err, size_t es)
{
    return scene_io_parse(text, strlen(text), "t", fmt, o, s, err, es);
}

static void count_warn(void *ctx, const char *msg)
{
    (void)msg;
    ++*(int *)ctx;
}

static void assert_vec(const double *v, double x, double y, double z)
{
    assert_true(v[0] == x && v[1] == y && v[2] == z);
}

/* ---- NFF keywords -------------------------------------------------------------------- */

static const char nff_all[] =
    "# comment line\n"
    "v\n"
    "from 1 2 3\n"
    "at 0 0 0.5\n"
    "up 0 0 1   # trailing comment\n"
    "angle 45\n"
    "hither 0.25\n"
    "resolution 320 200\n"
    "\n"
    "b 0.1 0.2 0.3\n"
    "l 4 5 6\n"
    "l -1 -2 -3 0.5 0.25 1\n"
    "f 1 0.5 0.25 0.7 0.3 20 0.4 1.5\n"
    "p 3\n"
    "0 0 0\n"
    "1 0 0\n"
    "0 1 0\n"
    "pp 3\n"
    "0 0 1 0 0 1\n"
    "1 0 1 0 0 2\n"
    "0 1 1 0.5 0 1\n"
    "f 0 1 0 1 0 1 0 0\n"
    "p 4\n"
    "0 0 2\n2 0 2\n1 1 2\n2 2 2\n";

static void test_nff_keywords(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    assert_int_equal(parse(nff_all, SCENE_IO_AUTO, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.format, SCENE_IO_NFF);
    assert_true(s.view.present);
    assert_vec(s.view.from, 1, 2, 3);
    assert_vec(s.view.at, 0, 0, 0.5);
    assert_vec(s.view.up, 0, 0, 1);
    assert_true(s.view.angle == 45 && s.view.hither == 0.25);
    assert_int_equal(s.view.res_x, 320);
    assert_int_equal(s.view.res_y, 200);
    assert_true(s.has_background);
    assert_vec(s.background, 0.1, 0.2, 0.3);
    assert_int_equal(s.num_lights, 2);
    assert_vec(s.lights[0].pos, 4, 5, 6);
    assert_vec(s.lights[0].color, 1, 1, 1);
    assert_int_equal(s.lights[0].has_color, 0);
    assert_vec(s.lights[1].color, 0.5, 0.25, 1);
    assert_int_equal(s.lights[1].has_color, 1);
    assert_int_equal(s.num_materials, 2);
    const scene_io_material *m = &s.materials[0];
    assert_vec(m->color, 1, 0.5, 0.25);
    assert_true(m->kd == 0.7 && m->ks == 0.3 && m->shine == 20 && m->t == 0.4 && m->ior == 1.5);
    assert_int_equal(s.num_polygons, 3);
    assert_int_equal(s.num_vertices, 10);
    assert_int_equal(s.num_patches, 1);
    assert_int_equal(s.poly_nverts[0], 3);
    assert_int_equal(s.poly_nverts[2], 4);
    assert_int_equal(s.poly_start[0], 0);
    assert_int_equal(s.poly_start[1], 3);
    assert_int_equal(s.poly_start[3], 10);
    assert_int_equal(s.poly_material[0], 0);
    assert_int_equal(s.poly_material[1], 0);
    assert_int_equal(s.poly_material[2], 1);
    for (uint32_t i = 0; i < 10; i++)
        assert_int_equal(s.poly_verts[i], i); /* NFF: own vertices in file order */
    assert_vec(s.vertices + 3 * 4, 1, 0, 1);
    assert_vec(s.vertices + 3 * 9, 2, 2, 2);
    /* normals: zero for "p" vertices, as given for "pp" */
    assert_non_null(s.normals);
    assert_vec(s.normals + 3 * 0, 0, 0, 0);
    assert_vec(s.normals + 3 * 4, 0, 0, 2);
    assert_vec(s.normals + 3 * 5, 0.5, 0, 1);
    assert_vec(s.normals + 3 * 9, 0, 0, 0);
    double lo[3], hi[3];
    assert_int_equal(scene_io_bounds(&s, lo, hi), 1);
    assert_vec(lo, 0, 0, 0);
    assert_vec(hi, 2, 2, 2);
    scene_io_free(&s);
    assert_null(s.vertices);
    scene_io_free(&s); /* twice is fine */
}

static void test_nff_default_material_crlf(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    const char *t = "p 3\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n";
    assert_int_equal(parse(t, SCENE_IO_NFF, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.num_materials, 1);
    assert_vec(s.materials[0].color, 1, 1, 1);
    assert_true(s.materials[0].kd == 1 && s.materials[0].ks == 0 && s.materials[0].ior == 1);
    assert_null(s.normals);
    assert_false(s.view.present);
    assert_false(s.has_background);
    scene_io_free(&s);
}

static void test_nff_spheres_skipped(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    int warnings = 0;
    scene_io_options o;
    scene_io_options_default(&o);
    o.warn = count_warn;
    o.warn_ctx = &warnings;
    const char *t = "s 0 0 0 1\ns 1 1 1 0.5\nc\n0 0 0 1\n0 0 1 0\nc\n0 0 0 1\n0 0 1 1\n";
    assert_int_equal(parse(t, SCENE_IO_NFF, &o, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.num_spheres, 2);
    assert_int_equal(s.num_cones, 2);
    assert_int_equal(s.num_polygons, 0);
    assert_int_equal(warnings, 2); /* once per kind */
    assert_int_equal(scene_io_bounds(&s, (double[3]){ 0 }, (double[3]){ 0 }), 0);
    scene_io_free(&s);
}

static void test_nff_sphere_tessellated(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    scene_io_options o;
    scene_io_options_default(&o);
    o.tessellate = 8;
    assert_int_equal(parse("s 1 2 3 2\n", SCENE_IO_NFF, &o, &s, err, sizeof err), SCENE_IO_OK);
    /* 8 around, 4 bands: 2 x 8 pole triangles + 2 x 8 quads */
    assert_int_equal(s.num_polygons, 32);
    int tri = 0;
    for (size_t i = 0; i < s.num_polygons; i++)
        tri += s.poly_nverts[i] == 3;
    assert_int_equal(tri, 16);
    for (size_t i = 0; i < s.num_vertices; i++) {
        const double *v = s.vertices + 3 * i, *n = s.normals + 3 * i;
        double d = sqrt((v[0] - 1) * (v[0] - 1) + (v[1] - 2) * (v[1] - 2) + (v[2] - 3) * (v[2] - 3));
        assert_true(fabs(d - 2) < 1e-12);
        assert_true(fabs(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) < 1e-12);
    }
    /* outward orientation: Newell normal of each polygon points away from the centre */
    for (size_t i = 0; i < s.num_polygons; i++) {
        double nw[3] = { 0, 0, 0 }, c[3] = { 0, 0, 0 };
        int k = s.poly_nverts[i];
        for (int j = 0; j < k; j++) {
            const double *a = s.vertices + 3 * s.poly_verts[s.poly_start[i] + j];
            const double *b = s.vertices + 3 * s.poly_verts[s.poly_start[i] + (j + 1) % k];
            nw[0] += (a[1] - b[1]) * (a[2] + b[2]);
            nw[1] += (a[2] - b[2]) * (a[0] + b[0]);
            nw[2] += (a[0] - b[0]) * (a[1] + b[1]);
            for (int q = 0; q < 3; q++)
                c[q] += a[q] / k;
        }
        assert_true(nw[0] * (c[0] - 1) + nw[1] * (c[1] - 2) + nw[2] * (c[2] - 3) > 0);
    }
    scene_io_free(&s);
}

static void test_nff_cone_tessellated(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    scene_io_options o;
    scene_io_options_default(&o);
    o.tessellate = 6;
    assert_int_equal(parse("c\n0 0 0 1\n0 0 2 0\nc\n0 0 0 1\n0 0 2 0.5\n", SCENE_IO_NFF, &o, &s,
                           err, sizeof err),
                     SCENE_IO_OK);
    assert_int_equal(s.num_polygons, 12);
    for (int i = 0; i < 6; i++) {
        assert_int_equal(s.poly_nverts[i], 3);     /* apex radius 0: triangles */
        assert_int_equal(s.poly_nverts[6 + i], 4); /* frustum: quads */
    }
    for (size_t i = 0; i < s.num_vertices; i++) {
        const double *v = s.vertices + 3 * i;
        double r = sqrt(v[0] * v[0] + v[1] * v[1]);
        assert_true(fabs(r - (v[2] == 0 ? 1 : i < 18 ? 0 : 0.5)) < 1e-12);
    }
    scene_io_free(&s);
}

/* ---- OFF and PLY --------------------------------------------------------------------- */

static const char off_cube[] =
    "OFF\n"
    "# a unit cube\n"
    "8 6 12\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "0 0 1\n1 0 1 0.5 0.5 0.5\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5 255 0 0\n4 0 4 7 3\n";

static void test_off_cube(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    assert_int_equal(parse(off_cube, SCENE_IO_AUTO, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.format, SCENE_IO_OFF);
    assert_int_equal(s.num_vertices, 8);
    assert_int_equal(s.num_polygons, 6);
    assert_int_equal(s.poly_start[6], 24);
    assert_int_equal(s.poly_verts[4 * 4 + 3], 5);
    assert_vec(s.vertices + 3 * 5, 1, 0, 1);
    assert_int_equal(s.num_materials, 1);
    assert_false(s.view.present);
    assert_int_equal(s.num_lights, 0);
    scene_io_free(&s);
    /* counts on the header line */
    const char *t = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    assert_int_equal(parse(t, SCENE_IO_AUTO, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.num_polygons, 1);
    scene_io_free(&s);
}

/* Numbers: the reader's fast path (at most 15 significant digits, exponent within +-22) and
 * strtod must give the same bits for every token; random decimal tokens of every shape (signs,
 * leading/trailing points, leading zeros, 1-20 digits, exponents -40..40) as OFF vertices. */
static void test_numbers_exact(void **state)
{
    (void)state;
    enum { NV = 30000, TOK = 48 };
    char *text = malloc((size_t)NV * 3 * TOK + 64);
    char (*tok)[TOK] = malloc((size_t)NV * 3 * sizeof *tok);
    assert_non_null(text);
    assert_non_null(tok);
    uint64_t x = 88172645463325252ull;
    size_t len = (size_t)sprintf(text, "OFF\n%d 1 0\n", NV);
    for (int k = 0; k < 3 * NV; k++) {
        char *t = tok[k];
        size_t n = 0;
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        const int nd = 1 + (int)(x % 20), point = (int)((x >> 8) % (size_t)(nd + 2)) - 1;
        if (x >> 20 & 1)
            t[n++] = (x >> 21 & 1) ? '-' : '+';
        for (int d = 0; d < nd; d++) {
            if (d == point)
                t[n++] = '.';
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            t[n++] = (char)('0' + (d < 2 && (x & 3) == 0 ? 0 : (int)(x % 10)));
        }
        if (point == nd)
            t[n++] = '.';
        if (x >> 30 & 1)
            n += (size_t)sprintf(t + n, "%c%d", (x >> 31 & 1) ? 'e' : 'E', (int)(x >> 32 & 63) % 81 - 40);
        t[n] = '\0';
        len += (size_t)sprintf(text + len, "%s%c", t, k % 3 == 2 ? '\n' : ' ');
    }
    len += (size_t)sprintf(text + len, "3 0 1 2\n");
    scene_io_scene s;
    char err[256];
    assert_int_equal(scene_io_parse(text, len, "t", SCENE_IO_OFF, NULL, &s, err, sizeof err),
                     SCENE_IO_OK);
    assert_int_equal(s.num_vertices, NV);
    size_t bad = 0;
    for (int k = 0; k < 3 * NV; k++) {
        const double ref = strtod(tok[k], NULL);
        if (memcmp(&ref, &s.vertices[k], sizeof ref) != 0 && bad++ < 5)
            printf("token '%s': %.17g, strtod %.17g\n", tok[k], s.vertices[k], ref);
    }
    assert_int_equal(bad, 0);
    scene_io_free(&s);
    free(text);
    free(tok);
}

static const char ply_tet[] =
    "ply\n"
    "format ascii 1.0\n"
    "comment a tetrahedron\n"
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\nproperty float nx\n"
    "element face 4\n"
    "property list uchar int vertex_indices\n"
    "element edge 1\n"
    "property int vertex1\nproperty int vertex2\n"
    "end_header\n"
    "0 0 0 9\n1 0 0 9\n0 1 0 9\n0 0 1.5 9\n"
    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
    "0 1\n";

static void test_ply_tetra(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    assert_int_equal(parse(ply_tet, SCENE_IO_AUTO, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(s.format, SCENE_IO_PLY);
    assert_int_equal(s.num_vertices, 4);
    assert_int_equal(s.num_polygons, 4);
    assert_vec(s.vertices + 9, 0, 0, 1.5);
    assert_int_equal(s.poly_verts[3 * 3 + 2], 3);
    scene_io_free(&s);
}

/* ---- files: plain, gzip, limits ------------------------------------------------------ */

static void write_file(const char *path, const char *data, size_t len, int gz)
{
    if (gz) {
        gzFile f = gzopen(path, "wb");
        assert_non_null(f);
        assert_int_equal(gzwrite(f, data, (unsigned)len), (int)len);
        assert_int_equal(gzclose(f), Z_OK);
    } else {
        FILE *f = fopen(path, "wb");
        assert_non_null(f);
        assert_int_equal(fwrite(data, 1, len, f), len);
        fclose(f);
    }
}

static void test_files(void **state)
{
    (void)state;
    char dir[] = "/tmp/scene_io_XXXXXX", p1[64], p2[64], p3[64];
    assert_non_null(mkdtemp(dir));
    snprintf(p1, sizeof p1, "%s/cube.off", dir);
    snprintf(p2, sizeof p2, "%s/cube.off.gz", dir);
    snprintf(p3, sizeof p3, "%s/cut.off.gz", dir);
    write_file(p1, off_cube, strlen(off_cube), 0);
    write_file(p2, off_cube, strlen(off_cube), 1);
    scene_io_scene a, b;
    char err[256];
    assert_int_equal(scene_io_load(p1, SCENE_IO_AUTO, NULL, &a, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(scene_io_load(p2, SCENE_IO_AUTO, NULL, &b, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(a.num_polygons, b.num_polygons);
    assert_memory_equal(a.vertices, b.vertices, 24 * sizeof(double));
    scene_io_free(&a);
    scene_io_free(&b);
    /* truncated gzip stream */
    FILE *f = fopen(p2, "rb");
    char buf[4096];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    write_file(p3, buf, n / 2, 0);
    assert_int_equal(scene_io_load(p3, SCENE_IO_AUTO, NULL, &a, err, sizeof err), SCENE_IO_ERR_OPEN);
    assert_non_null(strstr(err, "truncated"));
    /* size limit */
    scene_io_options o;
    scene_io_options_default(&o);
    o.max_bytes = 100;
    assert_int_equal(scene_io_load(p1, SCENE_IO_AUTO, &o, &a, err, sizeof err), SCENE_IO_ERR_LIMIT);
    assert_int_equal(scene_io_load(p2, SCENE_IO_AUTO, &o, &a, err, sizeof err), SCENE_IO_ERR_LIMIT);
    /* missing file */
    assert_int_equal(scene_io_load("/nonexistent/x.nff", SCENE_IO_AUTO, NULL, &a, err, sizeof err),
                     SCENE_IO_ERR_OPEN);
    assert_non_null(strstr(err, "/nonexistent/x.nff"));
    assert_int_equal(scene_io_load(NULL, SCENE_IO_AUTO, NULL, &a, err, sizeof err), SCENE_IO_ERR_ARG);
    unlink(p1);
    unlink(p2);
    unlink(p3);
    rmdir(dir);
}

static void test_frame_view(void **state)
{
    (void)state;
    scene_io_scene s;
    char err[256];
    scene_io_view v;
    assert_int_equal(parse(off_cube, SCENE_IO_AUTO, NULL, &s, err, sizeof err), SCENE_IO_OK);
    assert_int_equal(scene_io_frame_view(&s, 60, 200, 100, &v), SCENE_IO_OK);
    assert_true(v.present);
    assert_vec(v.at, 0.5, 0.5, 0.5);
    assert_vec(v.up, 0, 1, 0);
    /* bounding radius sqrt(3)/2, half angle 30 degrees: distance sqrt(3) */
    double d = sqrt((v.from[0] - 0.5) * (v.from[0] - 0.5) + (v.from[1] - 0.5) * (v.from[1] - 0.5) +
                    (v.from[2] - 0.5) * (v.from[2] - 0.5));
    assert_true(fabs(d - sqrt(3.0)) < 1e-12);
    assert_true(fabs(v.hither - d / 100) < 1e-15);
    assert_int_equal(v.res_x, 200);
    assert_int_equal(scene_io_frame_view(&s, 180, 200, 100, &v), SCENE_IO_ERR_ARG);
    assert_int_equal(scene_io_frame_view(&s, 60, 0, 100, &v), SCENE_IO_ERR_ARG);
    scene_io_free(&s);
    assert_int_equal(scene_io_frame_view(&s, 60, 10, 10, &v), SCENE_IO_ERR_ARG); /* empty */
}

/* ---- malformed input: error code and "t:line: message" ------------------------------- */

typedef struct {
    const char *text;
    size_t len;             /* 0: strlen */
    scene_io_format fmt;
    int code;
    const char *where;      /* expected message prefix, e.g. "t:3: " */
    const char *what;       /* expected substring of the message */
} bad_case;

#define V_OK "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\n"
#define PLY_HEAD "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" \
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n" \
                 "end_header\n"

static const bad_case bad_cases[] = {
    /* NFF numbers */
    { "f 1 1 1 1 0 1 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "needs 8 numbers, got 7" },
    { "f 1 1 nan 1 0 1 0 1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "non-finite" },
    { "b 0 0 0\nf 1 1 inf 1 0 1 0 1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "non-finite" },
    { "\n\nb 0 1e999 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:3: ", "non-finite" },
    { "b 0 0 -1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "negative" },
    { "b 0 0 0x\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "bad number" },
    { "b 0 0 1\0 2\n", 10, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "bad number" },
    { "b 0 0 11111111111111111111111111111111111111111111111111111111111111111111\n", 0,
      SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "too long" },
    { "b 0 0 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "unexpected '0'" },
    /* NFF polygons */
    { "p 3\n0 0 0\n1 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ",
      "'p' declares 3 vertices but the file has only 13 bytes left" },
    { "p 3\n0.000000 0 0\n1.000000 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:",
      "unexpected end of file: 'p' of line 1 has 2 of 3 vertices" },
    { "p 3\n0 0 0\n1 0 0\n# only a comment follows\n\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX,
      "t:", "has 2 of 3 vertices" },
    { "p 1000000000\n0 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "declares 1000000000" },
    { "p 99999999999999999999999\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "too large" },
    { "p -3\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "non-negative integer" },
    { "p 3.0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "non-negative integer" },
    { "p\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "missing" },
    { "p 2\n0 0 0\n1 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "at least 3" },
    { "p 3\n0 0 0\n1 0\n0 1 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:3: ", "needs 3 numbers, got 2" },
    { "p 3\n0 0 0 7\n1 0 0\n0 1 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "unexpected '7'" },
    { "p 3\n0 0 0\n1 0 NaN\n0 1 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:3: ", "non-finite" },
    { "pp 3\n0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n0.0000 1.0000 0.0000\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "needs 6 numbers, got 3" },
    { "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 -inf\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:4: ", "non-finite" },
    /* NFF keywords, lights, spheres, cones */
    { "x 1 2\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "unknown NFF keyword 'x'" },
    { "\x01\x02\xff\xfe garbage\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "unknown NFF keyword '\x3f\x3f\x3f\x3f'" },
    { "l 1 2\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "needs 3 numbers, got 2" },
    { "l 1 2 3 1 1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "colour (r g b) needs 3 numbers, got 2" },
    { "l 1 2 3 1 1 -1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "negative" },
    { "s 0 0 0 -1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "radius" },
    { "s 0 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "needs 4 numbers, got 3" },
    { "c\n0 0 0 1\n0 0 0 1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:", "degenerate cone" },
    { "c\n0 0 0 1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:", "end of file in a cone" },
    { "f 1 1 1 1 0 1 0 -1\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "negative" },
    /* NFF view block */
    { "v\nfrom 0 0 0\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 8 8\n", 0, SCENE_IO_NFF,
      SCENE_IO_ERR_SYNTAX, "t:", "coincide" },
    { "v\nfrom 0 0 5\nat 0 0 0\nup 0 0 2\nangle 40\nhither 1\nresolution 8 8\n", 0, SCENE_IO_NFF,
      SCENE_IO_ERR_SYNTAX, "t:", "parallel" },
    { "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\n", 0, SCENE_IO_NFF,
      SCENE_IO_ERR_SYNTAX, "t:", "end of file in the 'v' block" },
    { "v\nfrom 0 0 5\nfrom 0 0 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:3: ", "twice" },
    { "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 180\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX,
      "t:5: ", "angle 180" },
    { "v\nhither 0\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "hither 0 not positive" },
    { "v\nresolution 0 8\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "resolution" },
    { "v\nresolution 8.5 8\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "integers" },
    /* issue 20: beyond int, converted only after the range test (clang's float-cast-overflow
       sanitizer of the fuzz/UBSan builds flagged the cast before it) */
    { "v\nresolution 1e30 -3e12\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "1..65536" },
    { "v\nyon 8\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:2: ", "expected from/at/up" },
    { "v extra\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "unexpected 'extra'" },
    { V_OK "v\nfrom 1 1 1e400\n", 0, SCENE_IO_NFF, SCENE_IO_ERR_SYNTAX, "t:9: ", "non-finite" },
    /* OFF */
    { "OFF\n3 1 0\n0.0000000 0.0000000 0.0000000\n1.0000000 0.0000000 0.0000000\n", 0,
      SCENE_IO_OFF, SCENE_IO_ERR_SYNTAX, "t:", "2 of 3 vertices" },
    { "OFF\n1000000000 1000000000 0\n0 0 0\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:2: ",
      "exceed" },
    { "OFF\n99999999999 1 0\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:2: ", "too large" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:6: ", "vertex index 7 out of range" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:6: ", "non-negative integer" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:6: ", "at least 3" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:6: ", "2 of 3 vertex indices" },
    { "OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:4: ", "non-finite" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\njunk\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:7: ", "unexpected 'junk'" },
    { "OFF\n3 x 0\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:2: ", "face count" },
    { "OFF\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:", "missing vertex/face counts" },
    { "p 3\n", 0, SCENE_IO_OFF, SCENE_IO_ERR_SYNTAX, "t:1: ", "not an OFF file" },
    { "4OFF\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:1: ", "not supported" },
    /* PLY */
    { "ply\nformat binary_little_endian 1.0\nend_header\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX,
      "t:2: ", "binary PLY not supported" },
    { "ply\nformat ascii 1.0\nelement vertex 3\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:",
      "end of file in the PLY header" },
    { "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
      0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:", "lacks x, y or z" },
    { "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:",
      "exceeds" },
    { "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n", 0, SCENE_IO_AUTO,
      SCENE_IO_ERR_SYNTAX, "t:4: ", "unknown property type 'quad'" },
    { PLY_HEAD "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:13: ",
      "vertex index 3 out of range" },
    { PLY_HEAD "0 0 0\n1 0\n0 1 0\n3 0 1 2\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:11: ",
      "2 of 3 properties" },
    { PLY_HEAD "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:11: ",
      "non-finite" },
    { PLY_HEAD "0 0 0\n1 0 0\n0 1 0\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:9: ",
      "element 'face' count 1 exceeds what the remaining 19 bytes can hold" },
    { PLY_HEAD "0.0000 0.0000 0.0000\n1.0000 0.0000 0.0000\n0.0000 1.0000 0.0000\n", 0,
      SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:13: ", "unexpected end of file: 0 of 1 'face'" },
    { PLY_HEAD "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 5\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:13: ",
      "unexpected '5'" },
    { "ply\nformat ascii 1.0\nproperty float x\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:3: ",
      "before any 'element'" },
    { "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "3 0 1 2\n", 0, SCENE_IO_AUTO, SCENE_IO_ERR_SYNTAX, "t:", "no 'vertex' element" },
};

static void test_malformed(void **state)
{
    (void)state;
    for (size_t i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++) {
        const bad_case *c = &bad_cases[i];
        scene_io_scene s;
        char err[256];
        size_t len = c->len ? c->len : strlen(c->text);
        int rc = scene_io_parse(c->text, len, "t", c->fmt, NULL, &s, err, sizeof err);
        if (rc != c->code || strncmp(err, c->where, strlen(c->where)) != 0 ||
            !strstr(err, c->what)) {
            print_error("case %zu: rc %d, message \"%s\"; expected %d, \"%s...%s\"\n", i, rc, err,
                        c->code, c->where, c->what);
            fail();
        }
        /* the scene is empty after an error */
        assert_null(s.vertices);
        assert_int_equal(s.num_polygons, 0);
        /* a short message buffer truncates, never overflows */
        char small[8];
        memset(small, 'x', sizeof small);
        scene_io_parse(c->text, len, "t", c->fmt, NULL, &s, small, 5);
        assert_int_equal(small[5], 'x');
        assert_true(strlen(small) <= 4);
    }
}

static void check_scene(const scene_io_scene *s);

/* Every prefix of valid files: an error or a valid scene, never a crash (run under ASan). */
static void test_prefixes(void **state)
{
    (void)state;
    const char *texts[] = { nff_all, off_cube, ply_tet };
    for (int k = 0; k < 3; k++) {
        size_t n = strlen(texts[k]);
        for (size_t len = 0; len <= n; len++) {
            scene_io_scene s;
            char err[256];
            char *copy = malloc(len ? len : 1);
            memcpy(copy, texts[k], len); /* exact size: ASan catches over-reads */
            int rc = scene_io_parse(copy, len, "t", k ? SCENE_IO_AUTO : SCENE_IO_NFF, NULL, &s,
                                    err, sizeof err);
            if (rc == SCENE_IO_OK) {
                check_scene(&s);
            } else {
                assert_int_equal(rc, SCENE_IO_ERR_SYNTAX);
                assert_true(strncmp(err, "t:", 2) == 0);
            }
            scene_io_free(&s);
            free(copy);
        }
    }
}

/* Structural invariants of a scene the reader accepted. */
static void check_scene(const scene_io_scene *s)
{
    if (s->num_polygons == 0)
        return;
    assert_int_equal(s->poly_start[0], 0);
    for (size_t i = 0; i < s->num_polygons; i++) {
        assert_true(s->poly_nverts[i] >= 3);
        assert_int_equal(s->poly_start[i + 1] - s->poly_start[i], (size_t)s->poly_nverts[i]);
        assert_true(s->poly_material[i] < s->num_materials);
    }
    for (size_t k = 0; k < s->poly_start[s->num_polygons]; k++)
        assert_true(s->poly_verts[k] < s->num_vertices);
    for (size_t k = 0; k < 3 * s->num_vertices; k++)
        assert_true(isfinite(s->vertices[k]));
}

/* Deterministic mutations of valid files (bytes replaced, inserted digits, deleted
 * ranges): every result is a valid scene or a "t:<line>: " syntax error. */
static void test_mutations(void **state)
{
    (void)state;
    const char *texts[] = { nff_all, off_cube, ply_tet };
    static const char alphabet[] = "0123456789 \n-+.eEnaifp#x\0\xff";
    uint32_t seed = 12345;
    int accepted = 0, rejected = 0;
    for (int k = 0; k < 3; k++) {
        size_t n = strlen(texts[k]);
        for (int trial = 0; trial < 1500; trial++) {
            char *buf = malloc(n + 8);
            memcpy(buf, texts[k], n);
            size_t len = n;
            for (int m = 0; m < 1 + trial % 3; m++) {
                seed = seed * 1664525u + 1013904223u;
                size_t at = (seed >> 8) % len;
                char c = alphabet[(seed >> 3) % (sizeof alphabet - 1)];
                switch ((seed >> 28) % 3) {
                case 0: buf[at] = c; break;
                case 1:
                    memmove(buf + at + 1, buf + at, len - at);
                    buf[at] = c;
                    len++;
                    break;
                default: {
                    size_t d = 1 + (seed >> 20) % 8;
                    d = d > len - at ? len - at : d;
                    memmove(buf + at, buf + at + d, len - at - d);
                    len -= d;
                    break;
                }
                }
                if (len == 0)
                    break;
            }
            char *exact = malloc(len ? len : 1); /* exact size: ASan catches over-reads */
            memcpy(exact, buf, len);
            free(buf);
            scene_io_scene s;
            char err[256];
            scene_io_options o;
            scene_io_options_default(&o);
            o.tessellate = 4;
            int rc = scene_io_parse(exact, len, "t", SCENE_IO_AUTO, &o, &s, err, sizeof err);
            if (rc == SCENE_IO_OK) {
                check_scene(&s);
                accepted++;
            } else {
                assert_int_equal(rc, SCENE_IO_ERR_SYNTAX);
                assert_true(strncmp(err, "t:", 2) == 0 && err[2] >= '1' && err[2] <= '9');
                rejected++;
            }
            scene_io_free(&s);
            free(exact);
        }
    }
    print_message("mutations: %d accepted, %d rejected\n", accepted, rejected);
    assert_true(accepted > 100 && rejected > 100); /* both paths exercised */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nff_keywords),
        cmocka_unit_test(test_nff_default_material_crlf),
        cmocka_unit_test(test_nff_spheres_skipped),
        cmocka_unit_test(test_nff_sphere_tessellated),
        cmocka_unit_test(test_nff_cone_tessellated),
        cmocka_unit_test(test_off_cube),
        cmocka_unit_test(test_numbers_exact),
        cmocka_unit_test(test_ply_tetra),
        cmocka_unit_test(test_files),
        cmocka_unit_test(test_frame_view),
        cmocka_unit_test(test_malformed),
        cmocka_unit_test(test_prefixes),
        cmocka_unit_test(test_mutations),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
