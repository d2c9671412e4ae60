/* SPDX-License-Identifier: MIT */
/*
 * test_rt_camera.c -- camera recovery from view mapping matrices (paper section 3):
 * parallel, perspective and oblique matrices built from the closed forms of BINDINGS.md 3.3;
 * primary rays must equal the projectors computed directly from the view parameters within
 * 1e-9 relative; PRP / DOP recovery; clipping planes; raster; error cases.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "gksrt.h"
#include "rt_check.h"
#include "rt_testutil.h"

#define TOL 1e-9

static void check_rays(const rtu_view *v, int w, int h)
{
    double m[4][4];
    rtu_view_matrix(v, m);
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, m, v->vp, w, h), RT_OK);
    assert_int_equal(cam.perspective, v->perspective);
    double cu = 0.5 * (v->win[0] + v->win[1]), cv = 0.5 * (v->win[2] + v->win[3]);
    if (v->perspective) {
        for (int i = 0; i < 3; i++)
            assert_true(rtc_reldiff(cam.prp[i], v->prp[i]) < TOL);
    } else {
        double d[3] = {cu - v->prp[0], cv - v->prp[1], v->vpd - v->prp[2]};
        double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int i = 0; i < 3; i++)
            assert_true(fabs(cam.dop[i] - d[i] / l) < TOL);
    }
    double maxerr = 0.0;
    for (int r = 0; r <= 2 * h; r++)
        for (int c = 0; c <= 2 * w; c++) {
            double px = 0.5 * c, py = 0.5 * r; /* pixel corners and centres */
            rt_ray ray;
            assert_int_equal(rt_camera_ray(&cam, px, py, &ray), RT_OK);
            double x = v->vp[0] + px * (v->vp[1] - v->vp[0]) / w;
            double y = v->vp[3] - py * (v->vp[3] - v->vp[2]) / h;
            double f[3], b[3];
            rtu_view_projector(v, x, y, f, b);
            double d[3] = {b[0] - f[0], b[1] - f[1], b[2] - f[2]};
            double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            double scale = fmax(1.0, fmax(fabs(f[0]), fmax(fabs(f[1]), fabs(f[2]))));
            for (int i = 0; i < 3; i++) {
                maxerr = fmax(maxerr, fabs(ray.org[i] - f[i]) / scale);
                maxerr = fmax(maxerr, fabs(ray.dir[i] - d[i] / l));
            }
            maxerr = fmax(maxerr, rtc_reldiff(ray.tmax, l));
            assert_true(ray.tmin == 0.0);
        }
    assert_true(maxerr < TOL);
    /* clipping planes: 8 corners on their 3 planes, centre strictly inside */
    double cen[3] = {0, 0, 0};
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++)
            cen[i] += cam.corner[k][i] / 8;
    for (int f = 0; f < 6; f++) {
        const double *p = cam.plane[f];
        assert_true(p[0] * cen[0] + p[1] * cen[1] + p[2] * cen[2] + p[3] > 0.0);
        for (int k = 0; k < 8; k++) {
            int on = ((f >> 1) == 0 && ((k & 1) == (f & 1))) || ((f >> 1) == 1 && (((k >> 1) & 1) == (f & 1))) ||
                     ((f >> 1) == 2 && (((k >> 2) & 1) == (f & 1)));
            double s = p[0] * cam.corner[k][0] + p[1] * cam.corner[k][1] + p[2] * cam.corner[k][2] + p[3];
            if (on)
                assert_true(fabs(s) <= 1e-9 * cam.scale);
            else
                assert_true(s > 0.0);
        }
    }
    /* raster on the front plane: origin + i*du + r*dv = ray origin at pixel corner (i, r) */
    for (int r = 0; r <= h; r++)
        for (int c = 0; c <= w; c++) {
            rt_ray ray;
            rt_camera_ray(&cam, c, r, &ray);
            for (int i = 0; i < 3; i++) {
                double q = cam.origin[i] + c * cam.du[i] + r * cam.dv[i];
                assert_true(fabs(q - ray.org[i]) <= 1e-9 * fmax(1.0, cam.scale));
            }
        }
}

static void test_parallel(void **state)
{
    (void)state;
    rtc_traps_on();
    rtu_view v = {.win = {-1, 2, -0.5, 1.5}, .prp = {0.5, 0.5, 10}, .vpd = 0, .bpd = -3, .fpd = 1,
                  .vp = {0.1, 0.9, 0.2, 0.8, 0.1, 0.95}, .perspective = 0};
    check_rays(&v, 7, 5);
    rtc_traps_off();
}

static void test_oblique(void **state)
{
    (void)state;
    rtc_traps_on();
    rtu_view v = {.win = {-1, 2, -0.5, 1.5}, .prp = {3, -2, 5}, .vpd = 0.5, .bpd = -3, .fpd = 1,
                  .vp = {0, 1, 0, 1, 0, 1}, .perspective = 0};
    check_rays(&v, 6, 9);
    rtu_view pvt = {.win = {-462.27, -80.95, -4891.85, -94.78}, .prp = {-15.044, 1.318, 34.873},
                    .vpd = -1.213, .bpd = -3.311, .fpd = 15.332, .vp = {0.2, 0.7, 0.1, 0.9, 0.3, 0.6}};
    check_rays(&pvt, 5, 4);
    rtc_traps_off();
}

static void test_perspective(void **state)
{
    (void)state;
    rtc_traps_on();
    rtu_view v = {.win = {-1.5, 0.5, -1, 1}, .prp = {0.2, -0.1, 2}, .vpd = -1, .bpd = -4, .fpd = 0.5,
                  .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    check_rays(&v, 8, 6);
    rtu_view pvt = {.win = {-462.27, -80.95, -4891.85, -94.78}, .prp = {-15.044, 1.318, 34.873},
                    .vpd = -1.213, .bpd = -3.311, .fpd = 15.332, .vp = {0.2, 0.7, 0.1, 0.9, 0.3, 0.6},
                    .perspective = 1};
    check_rays(&pvt, 5, 4);
    rtc_traps_off();
}

/* a display volume smaller than the projection viewport (workstation window / view clip):
   rays still lie on the projectors, start on NPC z = box zmax and end on z = box zmin */
static void test_subbox(void **state)
{
    (void)state;
    rtc_traps_on();
    rtu_view v = {.win = {-1.5, 0.5, -1, 1}, .prp = {0.2, -0.1, 2}, .vpd = -1, .bpd = -4, .fpd = 0.5,
                  .vp = {0, 1, 0, 1, 0, 1}, .perspective = 1};
    double m[4][4], box[6] = {0.25, 0.75, 0.1, 0.6, 0.2, 0.7};
    rtu_view_matrix(&v, m);
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, m, box, 4, 4), RT_OK);
    for (int k = 0; k < 5; k++) {
        rt_ray ray;
        assert_int_equal(rt_camera_ray(&cam, k, 4 - k, &ray), RT_OK);
        double x = box[0] + k * (box[1] - box[0]) / 4, y = box[3] - (4 - k) * (box[3] - box[2]) / 4;
        for (int e = 0; e < 2; e++) {
            double p[4] = {ray.org[0], ray.org[1], ray.org[2], 1.0};
            if (e)
                for (int i = 0; i < 3; i++)
                    p[i] += ray.tmax * ray.dir[i];
            double q[4];
            for (int i = 0; i < 4; i++)
                q[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] * p[3];
            assert_true(fabs(q[0] / q[3] - x) < TOL);
            assert_true(fabs(q[1] / q[3] - y) < TOL);
            assert_true(fabs(q[2] / q[3] - (e ? box[4] : box[5])) < TOL);
        }
    }
    rtc_traps_off();
}

static void test_errors(void **state)
{
    (void)state;
    rt_camera cam;
    double box[6] = {0, 1, 0, 1, 0, 1};
    double z[4][4] = {{0}};
    assert_int_equal(rt_camera_from_view(&cam, z, box, 4, 4), RT_ERR_SINGULAR);
    double sing[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {1, 1, 0, 0}, {0, 0, 0, 1}};
    assert_int_equal(rt_camera_from_view(&cam, sing, box, 4, 4), RT_ERR_SINGULAR);
    double id[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_int_equal(rt_camera_from_view(&cam, id, box, 4, 4), RT_OK);
    assert_int_equal(cam.perspective, 0);
    id[1][2] = NAN;
    assert_int_equal(rt_camera_from_view(&cam, id, box, 4, 4), RT_ERR_SINGULAR);
    id[1][2] = INFINITY;
    assert_int_equal(rt_camera_from_view(&cam, id, box, 4, 4), RT_ERR_SINGULAR);
    id[1][2] = 0.0;
    /* w changes sign inside the volume: a corner at infinity */
    double pw[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, -0.5}};
    assert_int_equal(rt_camera_from_view(&cam, pw, box, 4, 4), RT_ERR_SINGULAR);
    double bad[6] = {0, 1, 0, 1, 0.5, 0.5};
    assert_int_equal(rt_camera_from_view(&cam, id, bad, 4, 4), RT_ERR_ARG);
    double bad2[6] = {0, 1, 1, 0, 0, 1};
    assert_int_equal(rt_camera_from_view(&cam, id, bad2, 4, 4), RT_ERR_ARG);
    double bad3[6] = {0, NAN, 0, 1, 0, 1};
    assert_int_equal(rt_camera_from_view(&cam, id, bad3, 4, 4), RT_ERR_ARG);
    assert_int_equal(rt_camera_from_view(&cam, id, box, 0, 4), RT_ERR_ARG);
    assert_int_equal(rt_camera_from_view(&cam, id, box, 4, 1 << 20), RT_ERR_ARG);
    assert_int_equal(rt_camera_from_view(NULL, id, box, 4, 4), RT_ERR_ARG);
    assert_int_equal(rt_camera_from_view(&cam, id, box, 4, 4), RT_OK);
    rt_ray ray;
    assert_int_equal(rt_camera_ray(&cam, NAN, 0, &ray), RT_ERR_ARG);
    assert_int_equal(rt_camera_ray(&cam, 0, INFINITY, &ray), RT_ERR_ARG);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_parallel),   cmocka_unit_test(test_oblique),
        cmocka_unit_test(test_perspective), cmocka_unit_test(test_subbox),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
