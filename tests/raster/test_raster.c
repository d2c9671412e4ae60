/* SPDX-License-Identifier: MIT */
/*
 * test_raster.c -- raster module: exact coverage against an independent even-odd
 * point-in-polygon test, watertight shared edges, holes, depth buffer, linetypes,
 * markers, cell array mapping, supersampling, PNG round trip, stroke font, hostile input.
 * All comparisons are exact (pixel counts / per-pixel equality) unless stated.
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
#include "raster.h"
#include "gks_alloc.h"

/* The whole picture through gks_raster_fb_resolve_row: width x height 8-bit RGB, row 0 =
 * top (the test's own; the library resolves row by row). */
static int fb_resolve(const gks_raster_fb *fb, unsigned char *rgb8)
{
    if (!fb || !rgb8)
        return GKS_RASTER_E_ARG;
    for (int row = 0; row < fb->height; row++)
        gks_raster_fb_resolve_row(fb, row, rgb8 + (size_t)row * (size_t)fb->width * 3);
    return GKS_RASTER_OK;
}

#ifndef TEST_OUT_DIR
#define TEST_OUT_DIR "."
#endif

static const float WHITE[3] = {1, 1, 1}, RED[3] = {1, 0, 0}, GREEN[3] = {0, 1, 0};

static uint64_t rng_state = 88172645463325252ull;
static double urand(void) /* xorshift64*, [0,1) */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

static gks_raster_fill solid(const float c[3], gks_raster_zmode zm)
{
    gks_raster_fill f = {.style = GKS_RASTER_SOLID, .zmode = zm};
    memcpy(f.rgb, c, sizeof f.rgb);
    return f;
}

static const float *px(const gks_raster_fb *fb, int i, int j)
{
    return fb->rgb + 3 * ((size_t)j * fb->w + i);
}

static int lit(const gks_raster_fb *fb, int i, int j)
{
    const float *p = px(fb, i, j);
    return p[0] != 0.0f || p[1] != 0.0f || p[2] != 0.0f;
}

static size_t count_lit(const gks_raster_fb *fb)
{
    size_t n = 0;
    for (int j = 0; j < fb->h; j++)
        for (int i = 0; i < fb->w; i++)
            n += (size_t)lit(fb, i, j);
    return n;
}

/* Independent reference: even-odd count of edges crossed left of (or at) the centre,
 * an edge counting for rows with ymin <= yc < ymax. */
static int ref_inside(int n_loops, const int *counts, const gks_raster_pt *p, double xc, double yc)
{
    int odd = 0;
    for (int l = 0; l < n_loops; p += counts[l], l++)
        for (int i = 0; i < counts[l]; i++) {
            gks_raster_pt a = p[i], b = p[(i + 1) % counts[l]];
            if (a.y == b.y)
                continue;
            if (a.y > b.y) {
                gks_raster_pt t = a; a = b; b = t;
            }
            if (!(a.y <= yc && yc < b.y))
                continue;
            double x = a.x + (yc - a.y) * ((b.x - a.x) / (b.y - a.y));
            if (x <= xc)
                odd ^= 1;
        }
    return odd;
}

static void test_fb_create(void **state)
{
    (void)state;
    assert_null(gks_raster_fb_create(0, 10, 1));
    assert_null(gks_raster_fb_create(10, -1, 1));
    assert_null(gks_raster_fb_create(10, 10, 5));
    assert_null(gks_raster_fb_create(10, 10, 0));
    assert_null(gks_raster_fb_create(70000, 10, 1));
    gks_raster_fb *fb = gks_raster_fb_create(7, 5, 2);
    assert_non_null(fb);
    assert_int_equal(fb->w, 14);
    assert_int_equal(fb->h, 10);
    float c[3] = {0.25f, 2.0f, NAN};
    gks_raster_fb_clear(fb, c);
    assert_true(px(fb, 13, 9)[0] == 0.25f && px(fb, 13, 9)[1] == 1.0f && px(fb, 0, 0)[2] == 0.0f);
    assert_true(isinf(fb->z[0]) && fb->z[0] < 0);
    gks_raster_fb_free(fb);
    gks_raster_fb_free(NULL);
    /* allocation failure: NULL, nothing leaks (checked by ASan) */
    gks_alloc_fail_after(2);
    assert_null(gks_raster_fb_create(8, 8, 1));
    gks_alloc_fail_after(0);
}

static void random_coverage(int ss)
{
    enum { W = 48, H = 40 };
    gks_raster_fb *fb = gks_raster_fb_create(W, H, ss);
    assert_non_null(fb);
    for (int iter = 0; iter < 300; iter++) {
        gks_raster_pt p[24];
        int counts[3], n_loops = 1 + (int)(urand() * 3), total = 0;
        for (int l = 0; l < n_loops; l++) {
            counts[l] = 3 + (int)(urand() * 6);
            for (int i = 0; i < counts[l]; i++) {
                p[total + i].x = -10 + urand() * (W + 20);
                p[total + i].y = -10 + urand() * (H + 20);
                if (iter % 5 == 0) { /* vertices on the half-pixel grid: ties at centres */
                    p[total + i].x = floor(p[total + i].x * ss) / ss + 0.5 / ss;
                    p[total + i].y = floor(p[total + i].y * ss) / ss + 0.5 / ss;
                }
                p[total + i].z = 0.5;
            }
            total += counts[l];
        }
        gks_raster_fb_clear(fb, NULL);
        gks_raster_fill f = solid(WHITE, iter % 2 ? GKS_RASTER_Z_TEST : GKS_RASTER_Z_NONE);
        assert_int_equal(gks_raster_fill_area(fb, n_loops, counts, p, &f), GKS_RASTER_OK);
        /* reference in sample coordinates */
        gks_raster_pt q[24];
        for (int i = 0; i < total; i++)
            q[i] = (gks_raster_pt){p[i].x * ss, p[i].y * ss, 0.5};
        for (int j = 0; j < fb->h; j++)
            for (int i = 0; i < fb->w; i++)
                if (lit(fb, i, j) != ref_inside(n_loops, counts, q, i + 0.5, j + 0.5))
                {
                    for (int k = 0; k < total; k++)
                        print_message("%.17g %.17g\n", q[k].x, q[k].y);
                    print_message("ss %d zm %d loops %d counts %d %d %d\n", ss, (int)f.zmode, n_loops, counts[0], counts[1], counts[2]);
                    fail_msg("iter %d: sample %d,%d differs (lit %d)", iter, i, j, lit(fb, i, j));
                }
    }
    gks_raster_fb_free(fb);
}

static void test_coverage_random(void **state)
{
    (void)state;
    random_coverage(1);
    random_coverage(3);
    /* convex quads (drawn as two triangles internally) and their mirror images */
    gks_raster_fb *fb = gks_raster_fb_create(40, 40, 1);
    for (int iter = 0; iter < 200; iter++) {
        double a[4];
        for (int k = 0; k < 4; k++)
            a[k] = urand() * 6.283185307179586;
        for (int i = 1; i < 4; i++) /* sort the angles: a convex quad on an ellipse */
            for (int j = i; j > 0 && a[j - 1] > a[j]; j--) {
                double t = a[j]; a[j] = a[j - 1]; a[j - 1] = t;
            }
        gks_raster_pt q[4];
        for (int k = 0; k < 4; k++) {
            int kk = iter % 2 ? 3 - k : k;
            q[kk] = (gks_raster_pt){20 + 25 * cos(a[k]), 20 + 15 * sin(a[k]), 0};
            if (iter % 3 == 0) {
                q[kk].x = floor(q[kk].x) + 0.5;
                q[kk].y = floor(q[kk].y) + 0.5;
            }
        }
        int four = 4;
        gks_raster_fb_clear(fb, NULL);
        gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
        assert_int_equal(gks_raster_fill_area(fb, 1, &four, q, &f), 0);
        for (int j = 0; j < 40; j++)
            for (int i = 0; i < 40; i++)
                assert_int_equal(lit(fb, i, j), ref_inside(1, &four, q, i + .5, j + .5));
    }
    gks_raster_fb_free(fb);
}

/* Triangles sharing edges: each pixel covered exactly once (also at grid ties). */
static void test_shared_edges(void **state)
{
    (void)state;
    enum { W = 64, H = 64 };
    gks_raster_fb *fb = gks_raster_fb_create(W, H, 1);
    int cover[W * H];
    for (int iter = 0; iter < 40; iter++) {
        /* a fan around a centre, rim points on a circle, sometimes on pixel centres */
        int n = 3 + iter % 9;
        double cx = 32 + (urand() - 0.5) * 4, cy = 32 + (urand() - 0.5) * 4, a0 = urand();
        if (iter % 2) {
            cx = floor(cx) + 0.5;
            cy = floor(cy) + 0.5;
        }
        gks_raster_pt rim[12];
        for (int k = 0; k < n; k++) {
            double a = 2 * 3.14159265358979 * (k + a0) / n;
            rim[k] = (gks_raster_pt){cx + 28 * cos(a), cy + 28 * sin(a), 0};
            if (iter % 2) {
                rim[k].x = floor(rim[k].x) + 0.5;
                rim[k].y = floor(rim[k].y) + 0.5;
            }
        }
        memset(cover, 0, sizeof cover);
        for (int k = 0; k < n; k++) {
            gks_raster_pt t[3] = {{cx, cy, 0}, rim[k], rim[(k + 1) % n]};
            gks_raster_fb_clear(fb, NULL);
            gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
            assert_int_equal(gks_raster_triangles(fb, 1, t, NULL, &f), GKS_RASTER_OK);
            for (int j = 0; j < H; j++)
                for (int i = 0; i < W; i++)
                    cover[j * W + i] += lit(fb, i, j);
        }
        int one = 1;
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++) {
                int in = ref_inside(1, &n, rim, i + 0.5, j + 0.5);
                assert_int_equal(cover[j * W + i], in);
                one &= cover[j * W + i] <= 1;
            }
        assert_true(one);
        if (n < 4)
            continue;
        /* the same fan as two general polygons (centre, rim[0..h]) and (centre,
         * rim[h..n-1], rim[0]): they share two edges; again exactly once */
        int h = n / 2, na = h + 2, nb = n - h + 2;
        gks_raster_pt pa[16], pb[16];
        pa[0] = pb[0] = (gks_raster_pt){cx, cy, 0};
        for (int k = 0; k <= h; k++)
            pa[1 + k] = rim[k];
        for (int k = h; k <= n; k++)
            pb[1 + k - h] = rim[k % n];
        memset(cover, 0, sizeof cover);
        for (int k = 0; k < 2; k++) {
            gks_raster_fb_clear(fb, NULL);
            gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
            assert_int_equal(gks_raster_fill_area(fb, 1, k ? &nb : &na, k ? pb : pa, &f), 0);
            for (int j = 0; j < H; j++)
                for (int i = 0; i < W; i++)
                    cover[j * W + i] += lit(fb, i, j);
        }
        for (int j = 0; j < H; j++)
            for (int i = 0; i < W; i++)
                assert_int_equal(cover[j * W + i], ref_inside(1, &n, rim, i + 0.5, j + 0.5));
    }
    gks_raster_fb_free(fb);
}

static void test_holes(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    gks_raster_pt p[8] = {{10, 10, 0}, {50, 10, 0}, {50, 50, 0}, {10, 50, 0},
                          {20, 20, 0}, {40, 20, 0}, {40, 40, 0}, {20, 40, 0}};
    int counts[2] = {4, 4};
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
    for (int rev = 0; rev < 2; rev++) {
        if (rev) { /* hole the other way round */
            gks_raster_pt t = p[5]; p[5] = p[7]; p[7] = t;
        }
        gks_raster_fb_clear(fb, NULL);
        assert_int_equal(gks_raster_fill_area(fb, 2, counts, p, &f), GKS_RASTER_OK);
        assert_int_equal(count_lit(fb), 40 * 40 - 20 * 20);
        assert_true(lit(fb, 10, 10) && lit(fb, 49, 49) && lit(fb, 19, 30));
        assert_false(lit(fb, 20, 20) || lit(fb, 39, 39) || lit(fb, 9, 30) || lit(fb, 50, 30));
    }
    /* self-intersecting bow tie and a repeated/collinear vertex */
    gks_raster_pt b[6] = {{0, 0, 0}, {32, 32, 0}, {32, 32, 0}, {64, 64, 0}, {64, 0, 0}, {0, 64, 0}};
    int nb = 6;
    gks_raster_fb_clear(fb, NULL);
    assert_int_equal(gks_raster_fill_area(fb, 1, &nb, b, &f), GKS_RASTER_OK);
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++)
            assert_int_equal(lit(fb, i, j), ref_inside(1, &nb, b, i + .5, j + .5));
    gks_raster_fb_free(fb);
}

/* Two interpenetrating squares: z = x/64 (red) and z = 1 - x/64 (green): the nearer
 * (larger z) wins, the intersection is the line x = 32. */
static void test_zbuffer(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(64, 16, 1);
    gks_raster_pt a[4] = {{0, 0, 0}, {64, 0, 1}, {64, 16, 1}, {0, 16, 0}};
    gks_raster_pt b[4] = {{0, 0, 1}, {64, 0, 0}, {64, 16, 0}, {0, 16, 1}};
    int four = 4;
    for (int order = 0; order < 4; order++) {
        gks_raster_fb_clear(fb, NULL);
        gks_raster_fill fr = solid(RED, GKS_RASTER_Z_TEST), fg = solid(GREEN, GKS_RASTER_Z_TEST);
        if (order < 2) { /* general polygon path */
            assert_int_equal(gks_raster_fill_area(fb, 1, &four, order ? b : a, order ? &fg : &fr), 0);
            assert_int_equal(gks_raster_fill_area(fb, 1, &four, order ? a : b, order ? &fr : &fg), 0);
        } else { /* triangle path */
            gks_raster_pt ta[6] = {a[0], a[1], a[2], a[0], a[2], a[3]};
            gks_raster_pt tb[6] = {b[0], b[1], b[2], b[0], b[2], b[3]};
            assert_int_equal(gks_raster_triangles(fb, 2, order == 2 ? ta : tb, NULL,
                                                  order == 2 ? &fr : &fg), 0);
            assert_int_equal(gks_raster_triangles(fb, 2, order == 2 ? tb : ta, NULL,
                                                  order == 2 ? &fg : &fr), 0);
        }
        for (int j = 0; j < 16; j++)
            for (int i = 0; i < 64; i++) {
                const float *c = px(fb, i, j);
                if (i < 32)
                    assert_true(c[1] == 1.0f && c[0] == 0.0f);
                else
                    assert_true(c[0] == 1.0f && c[1] == 0.0f);
                /* depth: max of the two planes at the centre (float precision) */
                double x = i + 0.5, z = fmax(x / 64, 1 - x / 64);
                assert_true(fabs(fb->z[j * 64 + i] - z) < 1e-5);
            }
    }
    /* depth only: colour untouched, depth written; painter: last wins */
    gks_raster_fb_clear(fb, NULL);
    gks_raster_fill fz = solid(RED, GKS_RASTER_Z_ONLY);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, a, &fz), 0);
    assert_int_equal(count_lit(fb), 0);
    assert_true(fabs(fb->z[63] - 63.5 / 64) < 1e-5);
    gks_raster_fill fg = solid(GREEN, GKS_RASTER_Z_TEST);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, b, &fg), 0);
    assert_int_equal(count_lit(fb), 32 * 16);
    gks_raster_fill fn = solid(RED, GKS_RASTER_Z_NONE);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, a, &fn), 0);
    assert_true(px(fb, 5, 5)[0] == 1.0f && px(fb, 5, 5)[1] == 0.0f);
    gks_raster_fb_free(fb);
}

/* Slightly non-planar quad: depth stays within the vertices' range, close to the plane. */
static void test_nonplanar(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(32, 32, 1);
    gks_raster_pt q[5] = {{0, 0, 0.2}, {32, 0, 0.2}, {32, 32, 0.6}, {16, 40, 0.7}, {0, 32, 0.601}};
    int n = 5;
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_TEST);
    assert_int_equal(gks_raster_fill_area(fb, 1, &n, q, &f), 0);
    for (int j = 0; j < 32; j++)
        for (int i = 0; i < 32; i++) {
            double z = fb->z[j * 32 + i];
            assert_true(z >= 0.2 - 1e-6 && z <= 0.7 + 1e-6);
            assert_true(fabs(z - (0.2 + 0.4 * (j + 0.5) / 32)) < 0.01);
        }
    gks_raster_fb_free(fb);
}

static void test_styles(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    gks_raster_pt sq[4] = {{0, 0, 0}, {64, 0, 0}, {64, 64, 0}, {0, 64, 0}};
    int four = 4;
    for (int h = -1; h >= -12; h--) {
        gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
        f.style = GKS_RASTER_HATCH;
        f.hatch = h;
        gks_raster_fb_clear(fb, NULL);
        assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &f), 0);
        int s = h >= -6 ? 8 : 4, k = (-h - 1) % 6 + 1;
        for (int j = 0; j < 64; j++)
            for (int i = 0; i < 64; i++) {
                int hor = j % s == 0, ver = i % s == 0;
                int up = (i - j) % s == 0, dn = (i + j) % s == 0;
                int want = k == 1 ? hor : k == 2 ? ver : k == 3 ? up : k == 4 ? dn
                           : k == 5 ? hor || ver : up || dn;
                assert_int_equal(lit(fb, i, j), want);
            }
    }
    gks_raster_fill bad = solid(WHITE, GKS_RASTER_Z_NONE);
    bad.style = GKS_RASTER_HATCH;
    bad.hatch = 3;
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &bad), GKS_RASTER_E_ARG);
    /* pattern: 3x2 cells of 4x5 pixels from reference (2, 1) */
    float pat[18];
    for (int c = 0; c < 6; c++) {
        pat[3 * c] = (c + 1) / 8.0f;
        pat[3 * c + 1] = 0.5f;
        pat[3 * c + 2] = 0.25f;
    }
    gks_raster_fill f = {.style = GKS_RASTER_PATTERN, .pat_nx = 3, .pat_ny = 2, .pat_rgb = pat,
                         .pat_ref = {2, 1}, .pat_u = {4, 0}, .pat_v = {0, 5}};
    gks_raster_fb_clear(fb, NULL);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &f), 0);
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            int ci = (int)floor((i + 0.5 - 2) / 4), cj = (int)floor((j + 0.5 - 1) / 5);
            ci = ((ci % 3) + 3) % 3;
            cj = ((cj % 2) + 2) % 2;
            assert_true(px(fb, i, j)[0] == pat[3 * (cj * 3 + ci)]);
        }
    f.pat_v[1] = 1e-307; /* cells so thin that cell coordinates overflow to inf */
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &f), 0);
    assert_true(px(fb, 40, 40)[0] == pat[0]);
    f.pat_v[0] = 8; f.pat_v[1] = 0; /* singular basis */
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &f), GKS_RASTER_E_ARG);
    gks_raster_fb_free(fb);
}

static gks_raster_line line_attr(int type, double width)
{
    gks_raster_line a = {.rgb = {1, 1, 1}, .width = width, .type = type};
    return a;
}

/* Horizontal 1-pixel line along row 10: pixel k lit iff the pattern is on at arc k. */
static void test_linetypes(void **state)
{
    (void)state;
    static const double pat[5][4] = {{0}, {0}, {8, 4}, {2, 4}, {8, 3, 2, 3}};
    static const int np[5] = {0, 0, 2, 2, 4};
    gks_raster_fb *fb = gks_raster_fb_create(80, 20, 1);
    for (int type = 1; type <= 4; type++)
        for (int split = 0; split < 2; split++) {
            gks_raster_pt p[3] = {{0.5, 10.5, 0}, {33.5, 10.5, 0}, {70.5, 10.5, 0}};
            gks_raster_line a = line_attr(type, 1);
            gks_raster_fb_clear(fb, NULL);
            if (split) /* the pattern continues across the vertex */
                assert_int_equal(gks_raster_polyline(fb, 3, p, &a), 0);
            else
                assert_int_equal(gks_raster_polyline(fb, 2, (gks_raster_pt[]){p[0], p[2]}, &a), 0);
            for (int i = 0; i < 80; i++) {
                int want = i <= 70;
                if (want && np[type]) {
                    double per = 0, ph;
                    for (int k = 0; k < np[type]; k++)
                        per += pat[type][k];
                    ph = fmod(i, per);
                    int on = 1;
                    for (int k = 0; k < np[type]; k++) {
                        if (ph < pat[type][k])
                            break;
                        ph -= pat[type][k];
                        on = !on;
                    }
                    want = on;
                }
                assert_int_equal(lit(fb, i, 10), want);
            }
        }
    /* wide solid line: a 40 x 5 rectangle exactly */
    gks_raster_line a = line_attr(1, 5);
    gks_raster_pt w[2] = {{10, 20, 0}, {50, 20, 0}};
    gks_raster_fb *fb2 = gks_raster_fb_create(64, 40, 1);
    assert_int_equal(gks_raster_polyline(fb2, 2, w, &a), 0);
    assert_int_equal(count_lit(fb2), 200);
    assert_true(lit(fb2, 10, 17) && lit(fb2, 49, 21) && !lit(fb2, 10, 22) && !lit(fb2, 9, 20));
    /* wide dashed: dashes 8w = 16 on, 8 off for w = 2 along x from 0 */
    gks_raster_fb_clear(fb2, NULL);
    a = line_attr(2, 2);
    gks_raster_pt d[2] = {{0, 20, 0}, {64, 20, 0}};
    assert_int_equal(gks_raster_polyline(fb2, 2, d, &a), 0);
    for (int i = 0; i < 64; i++)
        assert_int_equal(lit(fb2, i, 20), fmod(i + 0.5, 24) < 16);
    /* wide polyline with a join: no hole at the corner */
    gks_raster_fb_clear(fb2, NULL);
    a = line_attr(1, 6);
    gks_raster_pt c[3] = {{10, 10, 0}, {40, 10, 0}, {40, 35, 0}};
    assert_int_equal(gks_raster_polyline(fb2, 3, c, &a), 0);
    assert_true(lit(fb2, 42, 8) && lit(fb2, 40, 10) && lit(fb2, 25, 12) && lit(fb2, 38, 30));
    gks_raster_fb_free(fb2);
    gks_raster_fb_free(fb);
}

/* Hidden-line use: depth-only surface, then its edges with a bias are visible; a line
 * behind the surface is not. */
static void test_line_depth(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(32, 32, 1);
    gks_raster_pt sq[4] = {{4, 4, 0.5}, {28, 4, 0.5}, {28, 28, 0.5}, {4, 28, 0.5}};
    int four = 4;
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_ONLY);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, sq, &f), 0);
    gks_raster_line a = line_attr(1, 1);
    a.zmode = GKS_RASTER_Z_TEST;
    a.zbias = 1e-3f;
    gks_raster_pt edge[2] = {{4.5, 4.5, 0.5}, {27.5, 4.5, 0.5}};
    assert_int_equal(gks_raster_polyline(fb, 2, edge, &a), 0);
    assert_int_equal(count_lit(fb), 24);
    gks_raster_pt behind[2] = {{4.5, 16.5, 0.3}, {27.5, 16.5, 0.3}};
    assert_int_equal(gks_raster_polyline(fb, 2, behind, &a), 0);
    assert_int_equal(count_lit(fb), 24);
    gks_raster_pt front[2] = {{0.5, 20.5, 0.6}, {31.5, 20.5, 0.6}};
    assert_int_equal(gks_raster_polyline(fb, 2, front, &a), 0);
    assert_int_equal(count_lit(fb), 24 + 32);
    a.zbias = 0.0f; /* without bias a line slightly behind is hidden */
    gks_raster_pt e2[2] = {{4.5, 8.5, 0.4999}, {27.5, 8.5, 0.4999}};
    assert_int_equal(gks_raster_polyline(fb, 2, e2, &a), 0);
    assert_int_equal(count_lit(fb), 24 + 32);
    gks_raster_fb_free(fb);
}

static void test_markers(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    gks_raster_line a = line_attr(1, 1);
    gks_raster_pt c = {20.5, 20.5, 0};
    int want[6] = {0, 1, 17, 29, 0, 13};
    for (int t = 1; t <= 5; t++) {
        gks_raster_fb_clear(fb, NULL);
        assert_int_equal(gks_raster_markers(fb, 1, &c, t, 8, &a), 0);
        size_t n = count_lit(fb);
        if (want[t])
            assert_int_equal(n, want[t]);
        for (int j = 0; j < 64; j++)
            for (int i = 0; i < 64; i++) {
                if (!lit(fb, i, j))
                    continue;
                int dx = i - 20, dy = j - 20;
                if (t == 2)
                    assert_true((dx == 0 && abs(dy) <= 4) || (dy == 0 && abs(dx) <= 4));
                if (t == 5)
                    assert_true(abs(dx) == abs(dy) && abs(dx) <= 3);
                if (t == 3)
                    assert_true(abs(dx) == abs(dy) || dx == 0 || dy == 0);
                if (t == 4)
                    assert_true(fabs(hypot(dx, dy) - 4.0) < 1.3);
            }
        if (t == 4)
            assert_true(n >= 16 && lit(fb, 24, 20) && lit(fb, 16, 20) && lit(fb, 20, 24));
        if (t == 3)
            assert_true(lit(fb, 16, 20) && lit(fb, 23, 23));
    }
    assert_int_equal(gks_raster_markers(fb, 1, &c, 6, 8, &a), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_markers(fb, 1, &c, 2, NAN, &a), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_markers(fb, 0, &c, 2, 5, &a), GKS_RASTER_E_ARG);
    gks_raster_fb_free(fb);
}

static void test_cell_array(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    float cells[4 * 2 * 3];
    for (int c = 0; c < 8; c++) {
        cells[3 * c] = (c + 1) / 8.0f;
        cells[3 * c + 1] = 1.0f;
        cells[3 * c + 2] = 0.0f;
    }
    gks_raster_pt o = {8, 8, 0}, pu = {48, 8, 0}, pv = {8, 40, 0};
    assert_int_equal(gks_raster_cell_array(fb, &o, &pu, &pv, 4, 2, cells, NULL), 0);
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            int in = i >= 8 && i < 48 && j >= 8 && j < 40;
            assert_int_equal(lit(fb, i, j), in);
            if (in) {
                int ci = (i - 8) / 10, cj = (j - 8) / 16;
                assert_true(px(fb, i, j)[0] == cells[3 * (cj * 4 + ci)]);
            }
        }
    /* rotated and sheared, against the reference mapping */
    gks_raster_fb_clear(fb, NULL);
    gks_raster_pt o2 = {30, 2, 0.5}, u2 = {60, 30, 0.5}, v2 = {5, 40, 0.5};
    gks_raster_fill zf = solid(WHITE, GKS_RASTER_Z_TEST);
    assert_int_equal(gks_raster_cell_array(fb, &o2, &u2, &v2, 4, 2, cells, &zf), 0);
    double ux = 30, uy = 28, vx = -25, vy = 38, det = ux * vy - uy * vx;
    gks_raster_pt quad[4] = {o2, u2, {35, 68, 0}, v2};
    int four = 4, n_in = 0;
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            int in = ref_inside(1, &four, quad, i + .5, j + .5);
            assert_int_equal(lit(fb, i, j), in);
            if (!in)
                continue;
            n_in++;
            double x = i + 0.5 - 30, y = j + 0.5 - 2;
            double a = (vy * x - vx * y) / det, b = (-uy * x + ux * y) / det;
            /* a centre within 1e-9 of a cell boundary may go to either cell */
            int ok = 0;
            for (int di = -1; di <= 1; di++)
                for (int dj = -1; dj <= 1; dj++) {
                    int ci = (int)floor(a * 4 + di * 1e-9), cj = (int)floor(b * 2 + dj * 1e-9);
                    ci = ci < 0 ? 0 : ci > 3 ? 3 : ci;
                    cj = cj < 0 ? 0 : cj > 1 ? 1 : cj;
                    ok |= px(fb, i, j)[0] == cells[3 * (cj * 4 + ci)];
                }
            assert_true(ok);
            assert_true(fabs(fb->z[j * 64 + i] - 0.5) < 1e-6);
        }
    assert_true(n_in > 1000);
    assert_int_equal(gks_raster_cell_array(fb, &o, &pu, &pv, 0, 2, cells, NULL), GKS_RASTER_E_ARG);
    gks_raster_fb_free(fb);
}

/* Supersampling: a rectangle 1.5 pixels wide -> columns 255, 128 (8 of 16 samples), 0. */
static void test_supersampling(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(4, 4, 4);
    gks_raster_pt r[4] = {{0, 0, 0}, {1.5, 0, 0}, {1.5, 4, 0}, {0, 4, 0}};
    int four = 4;
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, r, &f), 0);
    unsigned char out[48];
    assert_int_equal(fb_resolve(fb, out), 0);
    for (int y = 0; y < 4; y++) {
        assert_int_equal(out[3 * (y * 4)], 255);
        assert_int_equal(out[3 * (y * 4 + 1)], 128);
        assert_int_equal(out[3 * (y * 4 + 2)], 0);
    }
    gks_raster_fb_free(fb);
}

/* Supersampled 1-pixel line (ss = 2 takes the quad path): a horizontal line at y = 10.5
 * from x = 0.5 to 20.5 covers pixels 1..19 fully and pixels 0 and 20 half (2 of 4
 * samples -> 128); nothing above or below. */
static void test_supersampled_line(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(24, 20, 2);
    gks_raster_line a = line_attr(1, 1);
    gks_raster_pt p[2] = {{0.5, 10.5, 0}, {20.5, 10.5, 0}};
    assert_int_equal(gks_raster_polyline(fb, 2, p, &a), 0);
    unsigned char out[24 * 20 * 3];
    assert_int_equal(fb_resolve(fb, out), 0);
    for (int y = 0; y < 20; y++)
        for (int x = 0; x < 24; x++) {
            int v = out[3 * ((19 - y) * 24 + x)]; /* resolve: row 0 = top */
            int want = y != 10 ? 0 : (x >= 1 && x <= 19) ? 255 : (x == 0 || x == 20) ? 128 : 0;
            assert_int_equal(v, want);
        }
    gks_raster_fb_free(fb);
}

/* Hatch and pattern go through the per-sample path: depth test there too. */
static void test_hatch_depth(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(32, 32, 1);
    gks_raster_pt near[4] = {{0, 0, 0.8}, {16, 0, 0.8}, {16, 32, 0.8}, {0, 32, 0.8}};
    gks_raster_pt far[4] = {{0, 0, 0.2}, {32, 0, 0.2}, {32, 32, 0.2}, {0, 32, 0.2}};
    int four = 4;
    gks_raster_fill fz = solid(GREEN, GKS_RASTER_Z_ONLY);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, near, &fz), 0);
    gks_raster_fill h = solid(WHITE, GKS_RASTER_Z_TEST);
    h.style = GKS_RASTER_HATCH;
    h.hatch = GKS_RASTER_HATCH_VERTICAL;
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, far, &h), 0);
    for (int j = 0; j < 32; j++)
        for (int i = 0; i < 32; i++) {
            assert_int_equal(lit(fb, i, j), i >= 16 && i % 8 == 0);
            float z = fb->z[j * 32 + i];
            if (i < 16)
                assert_true(z == 0.8f);
            else if (i % 8 == 0)
                assert_true(z == 0.2f);
            else
                assert_true(isinf(z)); /* gaps between hatch lines stay untouched */
        }
    gks_raster_fb_free(fb);
}

static void test_png(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(37, 21, 1);
    for (int j = 0; j < 21; j++)
        for (int i = 0; i < 37; i++) {
            float *p = fb->rgb + 3 * (j * 37 + i);
            p[0] = i / 36.0f; p[1] = j / 20.0f; p[2] = 0.5f;
        }
    float *tl = fb->rgb + 3 * (20 * 37); /* DC top-left pixel: row 0 of the file */
    tl[0] = 1; tl[1] = 0; tl[2] = 0;
    const char *path = TEST_OUT_DIR "/raster_roundtrip.png";
    unsigned char ref[37 * 21 * 3], *rd = NULL;
    int w = 0, h = 0;
    assert_int_equal(fb_resolve(fb, ref), 0);
    /* every compression setting (fast, zlib 1..9) is lossless */
    for (int c = GKS_RASTER_PNG_FAST; c <= GKS_RASTER_PNG_LEVEL_MAX; c++) {
        assert_int_equal(gks_raster_fb_write_png(fb, path, c), 0);
        assert_int_equal(gks_raster_png_read_rgb8(path, &w, &h, &rd), 0);
        assert_int_equal(w, 37);
        assert_int_equal(h, 21);
        assert_memory_equal(rd, ref, sizeof ref);
        assert_true(rd[0] == 255 && rd[1] == 0 && rd[2] == 0);
        assert_int_equal(rd[3 * (20 * 37 + 36) + 1], 0); /* bottom row: green = 0 */
        gks_free(rd);
        rd = NULL;
    }
    unsigned char row[37 * 3];
    assert_int_equal(gks_raster_fb_resolve_row(fb, 20, row), 0);
    assert_memory_equal(row, ref + 20 * 37 * 3, sizeof row);
    assert_int_equal(gks_raster_fb_resolve_row(fb, 21, row), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fb_resolve_row(fb, -1, row), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fb_write_png(fb, path, -1), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fb_write_png(fb, path, 10), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_png_write_rgb8(path, 37, 21, ref, 10), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fb_write_png(fb, "/nonexistent-dir/x/y.png", 0), GKS_RASTER_E_IO);
    assert_int_equal(gks_raster_png_read_rgb8("/nonexistent-dir/y.png", &w, &h, &rd), GKS_RASTER_E_IO);
    assert_null(rd);
    const char *junk = TEST_OUT_DIR "/raster_junk.png";
    FILE *fp = fopen(junk, "wb");
    assert_non_null(fp);
    fputs("not a png file at all", fp);
    fclose(fp);
    assert_int_equal(gks_raster_png_read_rgb8(junk, &w, &h, &rd), GKS_RASTER_E_FORMAT);
    /* truncated PNG */
    FILE *in = fopen(path, "rb");
    unsigned char buf[200];
    size_t got = fread(buf, 1, sizeof buf, in);
    fclose(in);
    fp = fopen(junk, "wb");
    fwrite(buf, 1, got / 2, fp);
    fclose(fp);
    assert_int_equal(gks_raster_png_read_rgb8(junk, &w, &h, &rd), GKS_RASTER_E_FORMAT);
    assert_null(rd);
    assert_int_equal(gks_raster_png_write_rgb8(NULL, 1, 1, ref, 0), GKS_RASTER_E_ARG);
    gks_raster_fb_free(fb);
}

static void test_hostile(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(32, 32, 1);
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_TEST);
    gks_raster_pt p[4] = {{0, 0, 0}, {30, 0, 0}, {30, 30, 0}, {0, 30, 0}};
    int four = 4, zero = 0, neg = -3;
    for (int k = 0; k < 3; k++) {
        gks_raster_pt q[4];
        memcpy(q, p, sizeof q);
        double bad = k == 0 ? NAN : k == 1 ? INFINITY : -INFINITY;
        q[2].x = bad;
        assert_int_equal(gks_raster_fill_area(fb, 1, &four, q, &f), GKS_RASTER_E_ARG);
        q[2].x = 30;
        q[1].z = bad;
        assert_int_equal(gks_raster_triangles(fb, 1, q, NULL, &f), GKS_RASTER_E_ARG);
        gks_raster_line a = line_attr(2, 3);
        assert_int_equal(gks_raster_polyline(fb, 4, q, &a), GKS_RASTER_E_ARG);
        assert_int_equal(gks_raster_markers(fb, 4, q, 3, 5, &a), GKS_RASTER_E_ARG);
    }
    assert_int_equal(count_lit(fb), 0);
    assert_int_equal(gks_raster_fill_area(fb, 1, &zero, NULL, &f), GKS_RASTER_OK);
    assert_int_equal(gks_raster_fill_area(fb, 0, &four, p, &f), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fill_area(fb, 1, &neg, p, &f), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fill_area(NULL, 1, &four, p, &f), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, p, NULL), GKS_RASTER_E_ARG);
    gks_raster_line a = line_attr(1, 1);
    assert_int_equal(gks_raster_polyline(fb, 1, p, &a), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_polyline(fb, 0, NULL, &a), GKS_RASTER_E_ARG);
    a.type = 7;
    assert_int_equal(gks_raster_polyline(fb, 2, p, &a), GKS_RASTER_E_ARG);
    a = line_attr(1, NAN);
    assert_int_equal(gks_raster_polyline(fb, 2, p, &a), GKS_RASTER_E_ARG);
    assert_int_equal(count_lit(fb), 0);
    /* huge coordinates: a triangle with vertices at 1e30 covers the whole image */
    gks_raster_pt big[3] = {{-1e30, -1e30, 0.5}, {1e30, -1e30, 0.5}, {0, 1e30, 0.5}};
    assert_int_equal(gks_raster_triangles(fb, 1, big, NULL, &f), 0);
    assert_int_equal(count_lit(fb), 32 * 32);
    for (int i = 0; i < 32 * 32; i++)
        assert_true(fb->z[i] == 0.5f);
    gks_raster_pt big4[4] = {{-1e30, 16, 0}, {1e30, 16, 1}, {1e30, 1e30, 1}, {-1e300, 1e300, 0}};
    gks_raster_fb_clear(fb, NULL);
    assert_int_equal(gks_raster_fill_area(fb, 1, &four, big4, &f), 0);
    assert_int_equal(count_lit(fb), 32 * 16);
    for (int i = 0; i < 32 * 32; i++)
        assert_false(isnan(fb->z[i]));
    /* huge lines, thin and wide dashed: a horizontal line through the image */
    gks_raster_pt hl[2] = {{-1e30, 5.5, 0}, {1e30, 5.5, 0}};
    gks_raster_fb_clear(fb, NULL);
    a = line_attr(1, 1);
    assert_int_equal(gks_raster_polyline(fb, 2, hl, &a), 0);
    assert_int_equal(count_lit(fb), 32);
    a = line_attr(2, 3);
    gks_raster_pt hl2[3] = {{-1.7e308, 5.5, 0}, {1.7e308, 5.5, 0}, {1.7e308, -1.7e308, 0}};
    assert_int_equal(gks_raster_polyline(fb, 3, hl2, &a), 0);
    assert_int_equal(gks_raster_markers(fb, 1, hl2, 4, 1e5, &a), 0);
    for (int i = 0; i < 32 * 32 * 3; i++)
        assert_false(isnan(fb->rgb[i]));
    gks_raster_fb_free(fb);
}

/* 10^7 vertices on a circle (radius 20): same pixels as the exact circle test. */
static void test_many_vertices(void **state)
{
    (void)state;
    enum { N = 10000000 };
    gks_raster_pt *p = malloc(N * sizeof *p);
    assert_non_null(p);
    for (int k = 0; k < N; k++) {
        double a = 6.283185307179586 * k / N;
        p[k] = (gks_raster_pt){32 + 20 * cos(a), 32 + 20 * sin(a), 0.25 + 0.5 * (k % 2)};
    }
    gks_raster_fb *fb = gks_raster_fb_create(64, 64, 1);
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_TEST);
    int n = N;
    assert_int_equal(gks_raster_fill_area(fb, 1, &n, p, &f), 0);
    int diff = 0;
    for (int j = 0; j < 64; j++)
        for (int i = 0; i < 64; i++) {
            double r = hypot(i + .5 - 32, j + .5 - 32);
            int want = r < 20;
            if (fabs(r - 20) > 1e-3)
                diff += lit(fb, i, j) != want;
            assert_false(isnan(fb->z[j * 64 + i]));
        }
    assert_int_equal(diff, 0);
    free(p);
    gks_raster_fb_free(fb);
}

static void test_alloc_failure(void **state)
{
    (void)state;
    gks_raster_fb *fb = gks_raster_fb_create(32, 32, 1);
    gks_raster_pt p[5] = {{0, 0, 0}, {30, 0, 0}, {30, 30, 0}, {15, 20, 0}, {0, 30, 0}};
    int five = 5;
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
    for (int k = 1; k <= 5; k++) {
        gks_alloc_fail_after(k);
        assert_int_equal(gks_raster_fill_area(fb, 1, &five, p, &f), GKS_RASTER_E_NOMEM);
        assert_int_equal(count_lit(fb), 0);
    }
    gks_alloc_fail_after(6);
    assert_int_equal(gks_raster_fill_area(fb, 1, &five, p, &f), GKS_RASTER_OK);
    gks_alloc_fail_after(0);
    assert_true(count_lit(fb) > 500);
    gks_raster_fb_free(fb);
}

/* gks_raster_polyline_cont: a polyline drawn in pieces sharing their end points gives
 * exactly the picture of one gks_raster_polyline call (dash phase and joins carried),
 * thin and wide, with and without supersampling. */
static void test_polyline_cont(void **state)
{
    (void)state;
    enum { N = 61 };
    gks_raster_pt p[N];
    for (int i = 0; i < N; i++)
        p[i] = (gks_raster_pt){4 + i * 1.9, 40 + 25 * sin(i * 0.37), 0.5};
    for (int ss = 1; ss <= 2; ss++)
        for (double w = 1; w <= 5; w += 4) {
            gks_raster_fb *a = gks_raster_fb_create(128, 80, ss);
            gks_raster_fb *b = gks_raster_fb_create(128, 80, ss);
            assert_non_null(a);
            assert_non_null(b);
            gks_raster_line la = line_attr(GKS_RASTER_LT_DASHDOT, w);
            assert_int_equal(gks_raster_polyline(a, N, p, &la), GKS_RASTER_OK);
            gks_raster_stroke st = {0};
            const int cut[4] = {0, 17, 40, N - 1};
            for (int k = 0; k < 3; k++)
                assert_int_equal(gks_raster_polyline_cont(b, (size_t)(cut[k + 1] - cut[k] + 1),
                                                          p + cut[k], &la, &st),
                                 GKS_RASTER_OK);
            size_t n = (size_t)a->w * a->h * 3, diff = 0;
            for (size_t i = 0; i < n; i++)
                diff += a->rgb[i] != b->rgb[i];
            assert_int_equal(diff, 0);
            assert_true(count_lit(a) > 100);
            assert_int_equal(gks_raster_polyline_cont(b, 2, p, &la, NULL), GKS_RASTER_E_ARG);
            gks_raster_fb_free(a);
            gks_raster_fb_free(b);
        }
}

/* gks_raster_cell_array_clipped: only samples inside the given loops take cell colours,
 * and those equal the unclipped cell array's. */
static void test_cell_array_clipped(void **state)
{
    (void)state;
    const float cells[3 * 6] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 0, 1};
    gks_raster_pt o = {8, 8, 0.5}, pu = {56, 8, 0.5}, pv = {8, 40, 0.5};
    gks_raster_fb *a = gks_raster_fb_create(64, 48, 1);
    gks_raster_fb *b = gks_raster_fb_create(64, 48, 1);
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(gks_raster_cell_array(a, &o, &pu, &pv, 3, 2, cells, NULL), GKS_RASTER_OK);
    /* a triangle cutting the parallelogram */
    const gks_raster_pt tri[3] = {{0, 0, 0.5}, {64, 20, 0.5}, {20, 48, 0.5}};
    const int cnt = 3;
    assert_int_equal(gks_raster_cell_array_clipped(b, &o, &pu, &pv, 3, 2, cells, NULL, 1, &cnt,
                                                   tri),
                     GKS_RASTER_OK);
    size_t in = 0;
    for (int j = 0; j < b->h; j++)
        for (int i = 0; i < b->w; i++) {
            int inside = ref_inside(1, &cnt, tri, i + 0.5, j + 0.5);
            if (inside && lit(a, i, j)) {
                in++;
                assert_memory_equal(px(a, i, j), px(b, i, j), 3 * sizeof(float));
            } else {
                assert_false(lit(b, i, j));
            }
        }
    assert_true(in > 500);
    assert_int_equal(gks_raster_cell_array_clipped(b, &o, &pu, &pv, 3, 2, cells, NULL, 0, &cnt,
                                                   tri),
                     GKS_RASTER_E_ARG);
    gks_raster_fb_free(a);
    gks_raster_fb_free(b);
}

/* gks_raster_fill_smooth: a quad on the tilted plane Z = 2 + X/2 (X, Y in [-1,1]) seen
 * through the projection s = 8 + 12 (X, Y)/Z with 1/w = 1/Z; attributes linear in X and Y
 * (colour ((X+1)/2, (Y+1)/2, 1/2)). Perspective-correct interpolation reproduces them exactly
 * at every sample, whichever fan triangle it falls in: tolerance 2e-6 (float attributes and
 * colour); interpolating linearly in the screen would be off by more than 0.02 here. The
 * samples covered are exactly those gks_raster_fill_area covers. */
static void test_smooth_perspective(void **state)
{
    (void)state;
    const double X[4] = {-1, 1, 1, -1}, Y[4] = {-1, -1, 1, 1};
    gks_raster_pt q[4];
    double invw[4];
    float at[12];
    for (int k = 0; k < 4; k++) {
        double Z = 2 + 0.5 * X[k];
        q[k] = (gks_raster_pt){8 + 12 * X[k] / Z, 8 + 12 * Y[k] / Z, 0.5};
        invw[k] = 1 / Z;
        at[3 * k] = (float)((X[k] + 1) / 2);
        at[3 * k + 1] = (float)((Y[k] + 1) / 2);
        at[3 * k + 2] = 0.5f;
    }
    gks_raster_fb *a = gks_raster_fb_create(16, 16, 1), *b = gks_raster_fb_create(16, 16, 1);
    assert_non_null(a);
    assert_non_null(b);
    const float black[3] = {0, 0, 0};
    gks_raster_fb_clear(a, black);
    gks_raster_fb_clear(b, black);
    gks_raster_vattr va = {.n = 3, .v = at, .invw = invw};
    gks_raster_fill f = solid(WHITE, GKS_RASTER_Z_NONE);
    assert_int_equal(gks_raster_fill_smooth(a, 4, q, &va, &f), GKS_RASTER_OK);
    const int four = 4;
    assert_int_equal(gks_raster_fill_area(b, 1, &four, q, &f), GKS_RASTER_OK);
    double worst = 0, affine = 0;
    int n = 0;
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++) {
            assert_int_equal(lit(a, i, j), lit(b, i, j));
            if (!lit(b, i, j))
                continue;
            double u = (i + 0.5 - 8) / 12, v = (j + 0.5 - 8) / 12;
            double Z = 2 / (1 - 0.5 * u), Xp = u * Z, Yp = v * Z;
            const float *c = px(a, i, j);
            worst = fmax(worst, fabs(c[0] - (Xp + 1) / 2));
            worst = fmax(worst, fabs(c[1] - (Yp + 1) / 2));
            worst = fmax(worst, fabs(c[2] - 0.5));
            /* screen-linear along x: from the left edge (X = -1) to the right (X = 1) */
            double xl = 8 + 12 * -1 / 1.5, xr = 8 + 12 * 1 / 2.5;
            affine = fmax(affine, fabs((i + 0.5 - xl) / (xr - xl) - (Xp + 1) / 2));
            n++;
        }
    assert_true(n > 50);
    assert_true(worst <= 2e-6);
    assert_true(affine > 0.02);
    /* bad arguments draw nothing */
    const double bad[4] = {1, 0, 1, 1};
    gks_raster_vattr vb = {.n = 3, .v = at, .invw = bad};
    assert_int_equal(gks_raster_fill_smooth(a, 4, q, &vb, &f), GKS_RASTER_E_ARG);
    assert_int_equal(gks_raster_fill_smooth(a, 2, q, &va, &f), GKS_RASTER_E_ARG);
    gks_raster_fb_free(a);
    gks_raster_fb_free(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_smooth_perspective),
        cmocka_unit_test(test_fb_create),      cmocka_unit_test(test_coverage_random),
        cmocka_unit_test(test_shared_edges),   cmocka_unit_test(test_holes),
        cmocka_unit_test(test_zbuffer),        cmocka_unit_test(test_nonplanar),
        cmocka_unit_test(test_styles),         cmocka_unit_test(test_linetypes),
        cmocka_unit_test(test_line_depth),     cmocka_unit_test(test_markers),
        cmocka_unit_test(test_cell_array),     cmocka_unit_test(test_supersampling),
        cmocka_unit_test(test_png),
        cmocka_unit_test(test_hostile),        cmocka_unit_test(test_many_vertices),
        cmocka_unit_test(test_alloc_failure),  cmocka_unit_test(test_supersampled_line),
        cmocka_unit_test(test_hatch_depth),    cmocka_unit_test(test_polyline_cont),
        cmocka_unit_test(test_cell_array_clipped),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
