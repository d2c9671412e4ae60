/* SPDX-License-Identifier: MIT */
/*
 * test_mesh_trace.c -- meshes kept whole for the tracer (issue 38, the driver entry mesh and
 * rt_scene_add_mesh): a smooth height field of non-planar quadrilaterals drawn as one
 * QUADRILATERAL MESH 3 WITH DATA and ray traced shows the same picture as the same surface
 * drawn as FILL AREA 3 WITH DATA triangles (each quadrilateral split at the diagonal the tracer
 * splits it at), without the rows of dotted dark pixels along mesh lines that the facet path
 * drew (one planar polygon per quadrilateral, each flattened onto its own plane: along a shared
 * edge one neighbour's plane lies above the other's, and a sample ray hitting the lower one
 * there had its shadow ray blocked by the neighbour). The mesh lines lie on pixel corners,
 * where the workstation's corner rays sample them. A TRIANGLE STRIP 3 WITH DATA gives exactly
 * the picture of its triangles drawn one by one (the same triangles and data, stored shared).
 * A mesh a clipping plane cuts goes facet by facet (the rule of the driver entry mesh); a PDF
 * workstation takes a mesh whole in ray-tracing mode as the PNG one does.
 *
 * Tolerance of the height field: a pixel counts as a dark outlier when the mesh's is darker
 * than the triangles' by more than 24 of 255 levels in a channel (a shadowed sample among the
 * pixel's corner rays darkens it by about 34 levels here: (kd N.L) / 4 of the surface colour);
 * none may be. Elsewhere the two pictures may differ where both triangles at a shared edge are
 * hit at the same distance (the mesh's triangles share one id, the facets' do not, so a tie
 * can go to the other triangle, whose interpolated data agree along the edge up to rounding):
 * by at most 2 levels, checked too.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "png_util.h"

/* SZ pixels; the mesh M x M vertices 8 pixels apart from pixel 8 (NPC 1/16) */
enum { SZ = 128, M = 15, STEP = 8 };

/* vertex (i, j): a bump and a ripple, exact unit normal */
static void vertex(int i, int j, Gpoint3 *p, Gvec3 *n)
{
    const double pi = 3.14159265358979323846;
    double x = (double)(STEP * (i + 1)) / SZ, y = (double)(STEP * (j + 1)) / SZ;
    double a = (x - 0.45) * (x - 0.45) + (y - 0.55) * (y - 0.55), e = exp(-a / 0.03);
    double z = 0.4 + 0.3 * e + 0.03 * sin(5 * pi * x) * sin(5 * pi * y);
    double zx = 0.3 * e * (-2 * (x - 0.45) / 0.03) + 0.03 * 5 * pi * cos(5 * pi * x) * sin(5 * pi * y);
    double zy = 0.3 * e * (-2 * (y - 0.55) / 0.03) + 0.03 * 5 * pi * sin(5 * pi * x) * cos(5 * pi * y);
    double l = sqrt(zx * zx + zy * zy + 1);
    *p = (Gpoint3){ x, y, z };
    *n = (Gvec3){ -zx / l, -zy / l, 1 / l };
}

enum { FIELD_MESH, FIELD_TRIS, STRIP_WHOLE, STRIP_TRIS };

static void draw(int what)
{
    static Gpoint3 p[M * M];
    static Gvec3 n[M * M];
    for (int j = 0; j < M; j++)
        for (int i = 0; i < M; i++)
            vertex(i, j, &p[j * M + i], &n[j * M + i]);
    if (what == FIELD_MESH) {
        Gint_size dim = { M, M };
        Gfacet_vdata3 vd = { M * M, p, NULL, n };
        gquad_mesh3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, &dim, NULL, &vd);
    } else if (what == FIELD_TRIS) {
        for (int j = 0; j + 1 < M; j++)
            for (int i = 0; i + 1 < M; i++) {
                const int k = j * M + i, c[2][3] = { { k, k + 1, k + M + 1 }, { k, k + M + 1, k + M } };
                for (int t = 0; t < 2; t++) {
                    Gpoint3 q[3] = { p[c[t][0]], p[c[t][1]], p[c[t][2]] };
                    Gvec3 m[3] = { n[c[t][0]], n[c[t][1]], n[c[t][2]] };
                    Gfacet_vdata3 vd = { 3, q, NULL, m };
                    gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
                }
            }
    } else { /* row 7 of the field and row 8 zigzagged as a strip: (i, 7), (i, 8), ... */
        Gpoint3 q[2 * M];
        Gvec3 m[2 * M];
        for (int i = 0; i < M; i++)
            for (int r = 0; r < 2; r++) {
                q[2 * i + r] = p[(7 + r) * M + i];
                m[2 * i + r] = n[(7 + r) * M + i];
            }
        if (what == STRIP_WHOLE) {
            Gfacet_vdata3 vd = { 2 * M, q, NULL, m };
            gtri_strip3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
        } else {
            for (int k = 0; k + 2 < 2 * M; k++) { /* odd k reversed, as the strip is */
                int a = k, b = k % 2 ? k + 2 : k + 1, c = k % 2 ? k + 1 : k + 2;
                Gpoint3 t[3] = { q[a], q[b], q[c] };
                Gvec3 tn[3] = { m[a], m[b], m[c] };
                Gfacet_vdata3 vd = { 3, t, NULL, tn };
                gfill_area3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, NULL, &vd);
            }
        }
    }
}

/* GESC_RT_THREADS of the next pictures (-1: not set, the default). */
static int rt_threads = -1;

/* The picture of `what` ray traced on a SZ x SZ PNG, in *img. */
static void picture(int what, image *img)
{
    const char *file = "t_mesh_trace.png";
    png_ws_open(file, SZ, GHLHSR_RAYTRACE, 0);
    if (rt_threads >= 0) {
        Gint ints[2] = { 1, rt_threads };
        Gescape_in_data in = { .num_ints = 2, .ints = ints };
        gescape(GESC_RT_THREADS, &in, NULL, NULL);
    }
    Gcolr_rep c = { { 0.9, 0.7, 0.4 } }, bg = { { 0.2, 0.3, 0.5 } };
    gset_colr_rep(1, 2, &c);
    gset_colr_rep(1, 3, &bg);
    gset_fill_int_style(GSTYLE_SOLID);
    Garea_props pr = { 0.2, 0.8, 0, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&pr);
    gset_back_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF);
    gset_back_refl_eq(GREFL_AMB_DIFF);
    gset_int_shad_meth(GSHAD_NORM);
    gset_back_int_shad_meth(GSHAD_NORM);
    Glight_src_rep amb = { GLIGHT_AMBIENT, { 1, 1, 1 }, { 0, 0, 0 }, { 0, 0, -1 },
                           { 1, 0 }, 0, 0 };
    Glight_src_rep dl = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 },
                          { 0.45, -0.55, -0.7 }, { 1, 0 }, 0, 0 };
    gset_light_src_rep(1, 2, &amb);
    gset_light_src_rep(1, 3, &dl);
    Gint on[2] = { 2, 3 };
    Gint_list act = { 2, on };
    gset_light_src_state(&act, NULL);
    gset_fill_colr_ind(3); /* a back wall the surface shadows */
    Gpoint3 w[4] = { { 0, 0, 0.02 }, { 1, 0, 0.02 }, { 1, 1, 0.02 }, { 0, 1, 0.02 } };
    Gpoint_list3 wl = { 4, w };
    gfill_area3(&wl);
    gset_fill_colr_ind(2);
    draw(what);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_true(read_png(file, img));
    assert_int_equal(img->w, SZ);
    remove(file);
}

/* Pixels where a is darker than b by more than 24 levels (dark outliers), and the largest
 * difference elsewhere in *rest. */
static int dark_outliers(const image *a, const image *b, int *rest)
{
    int n = 0;
    *rest = 0;
    for (size_t k = 0; k < (size_t)SZ * SZ; k++) {
        int dark = 0, d = 0;
        for (int q = 0; q < 3; q++) {
            int e = (int)b->rgb[3 * k + q] - (int)a->rgb[3 * k + q];
            dark |= e > 24;
            d = abs(e) > d ? abs(e) : d;
        }
        n += dark;
        if (!dark && d > *rest)
            *rest = d;
    }
    return n;
}

static void test_quad_mesh_no_dark_rows(void **u)
{
    (void)u;
    image mesh, tris;
    picture(FIELD_MESH, &mesh);
    picture(FIELD_TRIS, &tris);
    int rest;
    int n = dark_outliers(&mesh, &tris, &rest);
    print_message("quadrilateral mesh against its triangles: %d dark outliers, largest other "
                  "difference %d/255\n", n, rest);
    assert_int_equal(n, 0);
    assert_true(rest <= 2);
    free(mesh.rgb);
    free(tris.rgb);
}

static void test_strip_is_its_triangles(void **u)
{
    (void)u;
    image whole, tris;
    picture(STRIP_WHOLE, &whole);
    picture(STRIP_TRIS, &tris);
    assert_memory_equal(whole.rgb, tris.rgb, (size_t)SZ * SZ * 3);
    free(whole.rgb);
    free(tris.rgb);
}

/* Smooth FILL AREA 3 WITH DATA triangles (vertex normals, shading method NORMAL) are
 * recorded at the call with one thread and through the display list's worker with two
 * (ws_raytrace.c, queue_fill_area): the same picture, byte for byte. */
static void test_smooth_areas_threads(void **u)
{
    (void)u;
    image one, two;
    rt_threads = 1;
    picture(FIELD_TRIS, &one);
    rt_threads = 2;
    picture(FIELD_TRIS, &two);
    rt_threads = -1;
    assert_memory_equal(one.rgb, two.rgb, (size_t)SZ * SZ * 3);
    free(one.rgb);
    free(two.rgb);
}

/* The primitives the tracer kept in the last picture of workstation 1 (GESC_RT_STATS). */
static int traced_prims(void)
{
    Gint ws[1] = { 1 }, err;
    Gescape_in_data in = { .num_ints = 1, .ints = ws };
    Gstore store = NULL;
    Gescape_out_data *out = NULL;
    gcreate_store(&err, &store);
    gescape(GESC_RT_STATS, &in, &store, &out);
    assert_non_null(out);
    assert_true(out->num_ints >= 8);
    int n = out->ints[7];
    gdel_store(store);
    return n;
}

/* The clipping rule of the driver entry mesh: a 4 x 4 quadrilateral mesh inside the
 * clipping volume reaches the tracer whole (18 triangles); one a clipping plane cuts goes
 * facet by facet (9 quadrilaterals, those cut clipped: fewer than 18 primitives), as before. */
static void test_clip_rule(void **u)
{
    (void)u;
    for (int cut = 0; cut < 2; cut++) {
        gopen_gks(NULL, 0);
        gopen_ws(1, "t_mesh_clip.png", GWS_TYPE_PNG);
        gactivate_ws(1);
        gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
        Gpoint3 p[16];
        for (int k = 0; k < 16; k++)
            p[k] = (Gpoint3){ 0.2 + 0.2 * (k % 4), 0.2 + 0.2 * (k / 4), 0.5 + 0.05 * (k % 3) };
        if (cut) { /* window x [0, 0.7] onto the unit viewport 3: x > 0.7 is clipped */
            Glimit3 w = { 0, 0.7, 0, 1, 0, 1 };
            gset_win3(1, &w);
            gsel_norm_tran(1);
        }
        Gint_size dim = { 4, 4 };
        Gfacet_vdata3 vd = { 16, p, NULL, NULL };
        gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, &dim, NULL, &vd);
        gupd_ws(1, GFLAG_PERFORM);
        int n = traced_prims();
        print_message("quadrilateral mesh %s: %d primitives traced\n",
                      cut ? "cut by the clipping volume" : "inside", n);
        if (cut)
            assert_true(n > 0 && n < 18);
        else
            assert_int_equal(n, 18);
        gdeactivate_ws(1);
        gclose_ws(1);
        gclose_gks();
        remove("t_mesh_clip.png");
    }
}

#ifdef GKS_HAVE_CAIRO
/* The vector workstations take meshes whole too: the same 4 x 4 mesh on a PDF workstation in
 * ray-tracing mode reaches the tracer as 18 triangles (its facets would be 9 polygons). */
static void test_vector_ws_mesh(void **u)
{
    (void)u;
    gopen_gks(NULL, 0);
    gopen_ws(1, "t_mesh_vec.pdf", GWS_TYPE_PDF);
    gactivate_ws(1);
    gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
    Gpoint3 p[16];
    for (int k = 0; k < 16; k++)
        p[k] = (Gpoint3){ 0.2 + 0.2 * (k % 4), 0.2 + 0.2 * (k / 4), 0.5 + 0.05 * (k % 3) };
    Gint_size dim = { 4, 4 };
    Gfacet_vdata3 vd = { 16, p, NULL, NULL };
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, &dim, NULL, &vd);
    gupd_ws(1, GFLAG_PERFORM);
    assert_int_equal(traced_prims(), 18);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    remove("t_mesh_vec.pdf");
}
#endif

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quad_mesh_no_dark_rows),
        cmocka_unit_test(test_strip_is_its_triangles),
        cmocka_unit_test(test_smooth_areas_threads),
        cmocka_unit_test(test_clip_rule),
#ifdef GKS_HAVE_CAIRO
        cmocka_unit_test(test_vector_ws_mesh),
#endif
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
