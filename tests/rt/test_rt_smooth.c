/* SPDX-License-Identifier: MIT */
/*
 * test_rt_smooth.c -- smooth areas (rt_scene_add_polygon_data): interpolated vertex normals
 * reproduce the Lambert shading of the exact sphere, flat facets do not; vertex colours are
 * interpolated linearly (barycentric in triangles, mean value coordinates in polygons, equal
 * along a shared edge), each mesh's from its own; bad vertex data is rejected; scenes without
 * vertex data render as before (the same bits whatever rt_render_options.smooth says).
 *
 * Tolerance of the sphere test: 0.01 per channel (2.6 of 255 output levels), over pixels whose
 * exact normal is at least 0.3 towards the viewer and whose exact N.L is not within 0.1 of 0
 * (the terminator band, where the shadow ray decides: measured separately by bench/rt/rt_smooth).
 * Why 0.01: on a 64 x 32 lat-long mesh (cells of h = pi/32 rad) linear normal interpolation is
 * off the exact normal by about h^2/8 = 1.2e-3 rad, and the mesh's hit point lies up to
 * r h^2/8 inside the sphere, so the exact normal compared is taken up to
 * (h^2/8) / 0.3 = 4e-3 rad away; kd |dN| <= 0.9 * 5.2e-3 = 4.7e-3, doubled for margin. Flat facets
 * are off by up to h/2 = 0.05 rad (kd 0.9: 0.044 > 0.01) and must fail it.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "gksrt.h"
#include "rt_testutil.h"

enum { SZ = 96 };

/* sc rendered through view vw (rtu_view_matrix) onto a w x h raster with options o into rgb;
   returns the camera (for the rays of chosen pixels) */
static rt_camera render_view(rt_scene *sc, const rtu_view *vw, int w, int h,
                             const rt_render_options *o, float *rgb)
{
    double m[4][4];
    rtu_view_matrix(vw, m);
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, m, vw->vp, w, h), RT_OK);
    assert_int_equal(rt_render(sc, &cam, o, rgb, NULL), RT_OK);
    return cam;
}

/* largest channel error against the exact sphere over the compared pixels (see above) */
static double sphere_error(int normals, int mode)
{
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface su;
    rt_surface_default(&su);
    su.ka = 1.0;
    su.kd = 0.9;
    su.diffuse[0] = 0.9, su.diffuse[1] = 0.7, su.diffuse[2] = 0.5;
    int s = rt_scene_add_surface(sc, &su);
    const double c[3] = {0, 0, 0};
    assert_int_equal(rtu_add_sphere_data(sc, c, 1.0, 64, 32, s, normals), 0);
    const double ldir[3] = {-0.6, -0.3, -0.742};
    const rt_light amb = {.type = RT_LIGHT_AMBIENT, .color = {0.1, 0.1, 0.1}};
    const rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1},
                         .direction = {ldir[0], ldir[1], ldir[2]}};
    assert_true(rt_scene_add_light(sc, &amb) >= 0);
    assert_true(rt_scene_add_light(sc, &dl) >= 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtu_view vw = {.win = {-1.1, 1.1, -1.1, 1.1}, .prp = {0, 0, 10}, .vpd = 0, .bpd = -5,
                   .fpd = 5, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    rt_render_options o;
    rtu_options_plain(&o);
    o.smooth = mode;
    o.threads = 2;
    float *rgb = malloc(3 * SZ * SZ * sizeof(float));
    assert_non_null(rgb);
    const rt_camera cam = render_view(sc, &vw, SZ, SZ, &o, rgb);
    double L[3], l = sqrt(ldir[0] * ldir[0] + ldir[1] * ldir[1] + ldir[2] * ldir[2]);
    for (int k = 0; k < 3; k++)
        L[k] = -ldir[k] / l;
    double worst = 0.0;
    int compared = 0;
    for (int y = 0; y < SZ; y++)
        for (int x = 0; x < SZ; x++) {
            rt_ray r;
            assert_int_equal(rt_camera_ray(&cam, x + 0.5, y + 0.5, &r), RT_OK);
            double b = r.org[0] * r.dir[0] + r.org[1] * r.dir[1] + r.org[2] * r.dir[2];
            double cc = r.org[0] * r.org[0] + r.org[1] * r.org[1] + r.org[2] * r.org[2] - 1.0;
            if (b * b - cc < 0.0)
                continue;
            double t = -b - sqrt(b * b - cc), N[3];
            for (int k = 0; k < 3; k++)
                N[k] = r.org[k] + t * r.dir[k];
            double nv = -(N[0] * r.dir[0] + N[1] * r.dir[1] + N[2] * r.dir[2]);
            double nl = N[0] * L[0] + N[1] * L[1] + N[2] * L[2];
            if (nv < 0.3 || fabs(nl) < 0.1)
                continue;
            compared++;
            for (int k = 0; k < 3; k++) {
                double want = su.ka * su.diffuse[k] * 0.1 + (nl > 0 ? su.kd * su.diffuse[k] * nl : 0);
                worst = fmax(worst, fabs(rgb[3 * (y * SZ + x) + k] - want));
            }
        }
    assert_true(compared > SZ * SZ / 3);
    free(rgb);
    rt_scene_free(sc);
    return worst;
}

static void test_sphere_lambert(void **state)
{
    (void)state;
    const double tol = 0.01;
    double robust = sphere_error(1, RT_SMOOTH_ROBUST), naive = sphere_error(1, RT_SMOOTH_NAIVE);
    double flat = sphere_error(0, RT_SMOOTH_ROBUST), ignored = sphere_error(1, RT_SMOOTH_FLAT);
    print_message("max error: robust %.5f naive %.5f flat %.5f normals ignored %.5f\n", robust,
                  naive, flat, ignored);
    assert_true(robust <= tol);
    assert_true(naive <= tol);
    assert_true(flat > tol);
    assert_true(ignored == flat);
}

/* one triangle and one pentagon (sharing the edge a-b) with vertex colours, lit by nothing:
   refl_eq NONE shows the interpolated colour itself */
static void test_colours(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    su.refl_eq = RT_REFL_NONE;
    int s = rt_scene_add_surface(sc, &su);
    /* triangle (0,0) (1,0) (0,1); pentagon right of x + y = 1 shares edge (1,0)-(0,1) */
    const double tri[9] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
    const double tc[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double pen[15] = {1, 0, -1, 1.5, 0.2, -1, 1.4, 1.4, -1, 0.2, 1.5, -1, 0, 1, -1};
    const double pc[15] = {0, 1, 0, 1, 1, 1, 0.5, 0.5, 0.5, 1, 1, 1, 0, 0, 1};
    const int three = 3, five = 5;
    const rt_vertex_data tv = {NULL, tc}, pv = {NULL, pc};
    assert_int_equal(rt_scene_add_polygon_data(sc, 1, &three, tri, &tv, s, s), 0);
    assert_int_equal(rt_scene_add_polygon_data(sc, 1, &five, pen, &pv, s, s), 1);
    /* bad data: rejected, nothing added */
    const double bad[9] = {0, 0, 1, NAN, 0, 1, 0, 0, 1};
    const rt_vertex_data bv = {bad, NULL}, bc = {NULL, bad};
    assert_int_equal(rt_scene_add_polygon_data(sc, 1, &three, tri, &bv, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_add_polygon_data(sc, 1, &three, tri, &bc, s, s), RT_ERR_ARG);
    assert_int_equal(rt_scene_count(sc), 2);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    /* rays straight down at chosen points; expected colours by linear interpolation */
    rtu_view vw = {.win = {0, 2, 0, 2}, .prp = {1, 1, 10}, .vpd = 0, .bpd = -5, .fpd = 5,
                   .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    rt_render_options o;
    rtu_options_plain(&o);
    o.threads = 1;
    float rgb[8 * 8 * 3];
    render_view(sc, &vw, 8, 8, &o, rgb);
    /* pixel (0,7): centre (0.125, 0.125) in the triangle: colours (1-x-y, x, y) */
    const float *p = rgb + 3 * (7 * 8 + 0);
    assert_float_equal(p[0], 0.75, 1e-6);
    assert_float_equal(p[1], 0.125, 1e-6);
    assert_float_equal(p[2], 0.125, 1e-6);
    /* pixel (4,7): centre (1.125, 0.125), in the pentagon: a convex combination (within the
       vertex colours' range) */
    p = rgb + 3 * (7 * 8 + 4);
    for (int k = 0; k < 3; k++)
        assert_true(p[k] >= 0.0f && p[k] <= 1.0f);
    rt_scene_free(sc);
}

/* mean value coordinates reduce to linear interpolation along an edge: a ray through the
   shared edge's interior sees the same colour from the triangle and from the pentagon */
static void test_shared_edge(void **state)
{
    (void)state;
    const double tri[9] = {0, 0, -1, 1, 0, -1, 0, 1, -1};
    const double tc[9] = {1, 0, 0, 0.2, 0.6, 0.1, 0.3, 0.1, 0.9};
    const double pen[15] = {1, 0, -1, 1.5, 0.2, -1, 1.4, 1.4, -1, 0.2, 1.5, -1, 0, 1, -1};
    const double pc[15] = {0.2, 0.6, 0.1, 1, 1, 1, 0.5, 0.5, 0.5, 1, 1, 1, 0.3, 0.1, 0.9};
    const int three = 3, five = 5;
    float col[2][3];
    for (int which = 0; which < 2; which++) {
        rt_scene *sc = rt_scene_new();
        rt_surface su;
        rt_surface_default(&su);
        su.refl_eq = RT_REFL_NONE;
        int s = rt_scene_add_surface(sc, &su);
        const rt_vertex_data tv = {NULL, tc}, pv = {NULL, pc};
        if (which == 0)
            assert_true(rt_scene_add_polygon_data(sc, 1, &three, tri, &tv, s, s) >= 0);
        else
            assert_true(rt_scene_add_polygon_data(sc, 1, &five, pen, &pv, s, s) >= 0);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        /* one pixel whose centre is (0.3, 0.7) on the edge x + y = 1 */
        rtu_view vw = {.win = {0.25, 0.35, 0.65, 0.75}, .prp = {0.3, 0.7, 10}, .vpd = 0,
                       .bpd = -5, .fpd = 5, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
        rt_render_options o;
        rtu_options_plain(&o);
        o.threads = 1;
        render_view(sc, &vw, 1, 1, &o, col[which]);
        rt_scene_free(sc);
    }
    for (int k = 0; k < 3; k++) {
        double want = 0.3 * tc[3 + k] + 0.7 * tc[6 + k]; /* (0.3, 0.7) on (1,0)-(0,1) */
        assert_float_equal(col[0][k], want, 1e-6);
        assert_float_equal(col[1][k], want, 1e-6);
    }
}

/* without vertex data the smooth option changes nothing, bit for bit */
static void test_flat_unchanged(void **state)
{
    (void)state;
    float img[3][32 * 32 * 3];
    for (int mode = 0; mode < 3; mode++) {
        rt_scene *sc = rt_scene_new();
        rt_surface su;
        rt_surface_default(&su);
        su.refl_eq = RT_REFL_SPECULAR;
        su.ks = 0.5;
        su.spec_exp = 10;
        int s = rt_scene_add_surface(sc, &su);
        const double c[3] = {0, 0, 0};
        assert_int_equal(rtu_add_sphere(sc, c, 1.0, 12, 6, s), 0);
        const rt_light dl = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1},
                             .direction = {-1, -1, -1}};
        assert_true(rt_scene_add_light(sc, &dl) >= 0);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        rtu_view vw = {.win = {-1.2, 1.2, -1.2, 1.2}, .prp = {0, 0, 10}, .vpd = 0, .bpd = -5,
                       .fpd = 5, .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
        rt_render_options o;
        rt_render_options_default(&o);
        o.smooth = mode;
        render_view(sc, &vw, 32, 32, &o, img[mode]);
        rt_scene_free(sc);
    }
    assert_memory_equal(img[0], img[1], sizeof img[0]);
    assert_memory_equal(img[0], img[2], sizeof img[0]);
}

/* meshes take their own vertex data: three meshes side by side (squares of two triangles
   over x in [3k, 3k + 2]), the first with red vertex colours, the second with none (its
   surface's colour), the third with green ones; a ray down onto each gets its own mesh's */
static void test_mesh_colours_own(void **state)
{
    (void)state;
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface su;
    rt_surface_default(&su);
    su.refl_eq = RT_REFL_NONE;
    su.diffuse[0] = 0.2, su.diffuse[1] = 0.3, su.diffuse[2] = 0.4;
    const int s = rt_scene_add_surface(sc, &su);
    const uint32_t ix[6] = {0, 1, 2, 0, 2, 3};
    const double want[3][3] = {{1, 0, 0}, {0.2, 0.3, 0.4}, {0, 1, 0}};
    for (int k = 0; k < 3; k++) {
        const double x0 = 3.0 * k;
        const double v[12] = {x0, 0, -1, x0 + 2, 0, -1, x0 + 2, 2, -1, x0, 2, -1};
        double c[12];
        for (int j = 0; j < 12; j++)
            c[j] = want[k][j % 3];
        assert_true(rt_scene_add_mesh(sc, 4, v, NULL, k == 1 ? NULL : c, 2, ix, s, s) >= 0);
    }
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    rtu_view vw = {.win = {0, 9, 0, 3}, .prp = {4.5, 1.5, 10}, .vpd = 0, .bpd = -5, .fpd = 5,
                   .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    rt_render_options o;
    rtu_options_plain(&o);
    o.threads = 1;
    float rgb[9 * 3 * 3];
    render_view(sc, &vw, 9, 3, &o, rgb);
    for (int k = 0; k < 3; k++) { /* pixel (3k + 1, 1): centre (3k + 1.5, 1.5), in mesh k */
        const float *p = rgb + 3 * (1 * 9 + 3 * k + 1);
        for (int a = 0; a < 3; a++)
            assert_float_equal(p[a], want[k][a], 1e-6);
    }
    rt_scene_free(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_lambert),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_shared_edge),
        cmocka_unit_test(test_flat_unchanged),
        cmocka_unit_test(test_mesh_colours_own),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
