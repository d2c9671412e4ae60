/* SPDX-License-Identifier: MIT */
/*
 * test_rt_buildfilter.c -- the margin filters of the grid build (rt_build.c: rt_tri_cells,
 * rt_tri_slab, rt_tri_row; docs/RAYTRACING.md, "The build's margin filter") keep the grid
 * that the exact triangle/box tests make, where the filters cannot decide as well as where
 * they can: the grid hash of each scene with the filters on equals the hash with them off
 * (rt_build_set_filter(0): every cell through the exact test rt_tri_box, the whole row range
 * of rt_tri_row's triangles without its face, inside and plane tests), on 1 and 2 build
 * threads, and the filters did hand cells to the exact test (rt_build_exact_cells) on the
 * scenes built for that.
 * Scenes in [0, 8]^3 (two tiny anchor triangles fix the scene box, so that the build's eps =
 * 1e-9 (scale + extent) = 1.6e-8 and the eps-enlarged cell boxes of an 8^3 grid over that box
 * are known here exactly, computed as the build computes them):
 *  - "touch": triangles with an edge whose projection along one axis passes through a corner
 *    of a cell's enlarged box (the edge test's separation exactly 0 in exact arithmetic), or
 *    1, 4 and 64 ulps and 1e-14 .. 1e-10 beside it, on both sides, for the three axes, the
 *    four corners of a cell face and several cells; the third vertex on the far side of the
 *    edge (the edge axis decides) or on the near side; the edge as the build's edge 0, 1 and
 *    2 (the filter's lanes);
 *  - "slab": the same edges on triangles inside one cell on the third axis, whose cells the
 *    build decides in the projection along that axis (rt_tri_slab);
 *  - "row": triangles inside one cell on two axes and spanning cells on the third
 *    (rt_tri_row), their end on it at the values where the row's face test and its eps
 *    margin flip (computed as the build computes them), in the margin band and on the face;
 *    on the other two axes 2 eps inside a cell and at the scene box's faces;
 *  - "band": the edges of "touch" and "slab" at B / 8 beside the corner (B the filter's outer
 *    margin, computed here as the build computes it), where the filter's m lies in the middle
 *    of its undecided band on the side where rt_tri_box decides against the wrong bound (the
 *    outer one for a keep, the inner one for a separation): a filter deciding the band by
 *    either bound changes the grid; each triangle sends at least one cell to the exact test;
 *    and the triangles of "row" in the middle of the row's margin band (eps / 2 inside a
 *    face), each sending a cell to the exact test;
 *  - "lattice": random triangles with vertices on the enlarged boxes' faces (q - eps, q + eps)
 *    and on q and q + 1/2: faces, edges and corners touched exactly everywhere;
 *  - "lattice" again with the second level (crowded cells get sub-grids, whose cell boxes the
 *    build takes from a table).
 * And the plain C forms of the edge filter and of the slab path's masks (what targets without
 * SSE2 build; rt_build_edge_filter, rt_build_slab_masks) give the SSE2 forms' answers bit for
 * bit, and the definition's on hand-made cases: every combination of the edges' m against
 * their bounds (below, at, above ri and ro, NaN, the filter off), cells in both lanes of an
 * SSE2 pair, then random cells and bounds of any magnitude, ties and NaN included.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"
#include "rt_testutil.h"

enum { N = 8 }; /* grid cells per axis over [0, 8]^3: cell width 1 */

static const double EPS = 1e-9 * (8.0 + 8.0); /* the build's eps for this scene box */

/* the enlarged box of cell q on an axis as rt_build.c computes it (grid lo 0, cw 1, hi 8) */
static double cell_lo(int q)
{
    return (q == 0 ? 0.0 : 0.0 + q * 1.0) - EPS;
}

static double cell_hi(int q)
{
    return (q == N - 1 ? 8.0 : 0.0 + (q + 1) * 1.0) + EPS;
}

typedef struct tris {
    double *v; /* 9 per triangle */
    size_t n, cap;
} tris;

static void add_tri(tris *t, const double v[9])
{
    if (t->n == t->cap) {
        t->cap = t->cap ? 2 * t->cap : 256;
        t->v = realloc(t->v, t->cap * 9 * sizeof(double));
        assert_non_null(t->v);
    }
    memcpy(t->v + 9 * t->n++, v, 9 * sizeof(double));
}

/* a triangle given in (u, p, q) coordinates, where p and q are the two axes of the projection
   and u the third: axis a of the triangle's points gets (u, p, q)[(a - ax + 3) % 3]; its
   vertex k is upq[(k + rot) % 3] (rot 0, 1, 2: the edge upq[0] -> upq[1] is the build's edge
   0, 1, 2, the edges e0 = V1 - V0, e1 = V2 - V1, e2 = V0 - V2 of rt_tri_box) */
static void rot_tri(int ax, int rot, const double upq[3][3], double v[9])
{
    for (int k = 0; k < 3; k++)
        for (int a = 0; a < 3; a++)
            v[3 * k + a] = upq[(k + rot) % 3][(a - ax + 3) % 3];
}

static void add_rot(tris *t, int ax, int rot, const double upq[3][3])
{
    double v[9];
    rot_tri(ax, rot, upq, v);
    add_tri(t, v);
}

/* the filter's outer margin B for triangle v as the build computes it (rt_tri_cells,
   docs/RAYTRACING.md, "The bound"): 64 u emax (L_x + L_y + L_z) + 2^-1000, emax the largest
   |edge component|, L_a the largest of |e0_a|, |e2_a| and, over the cells of the triangle's
   range on a (those its box widened by eps meets), |bc - V0_a| and h; D (the differences of
   the cells' h, ulps here) is left out */
static double filter_B(const double v[9])
{
    double emax = 0.0, sum = 0.0;
    for (int a = 0; a < 3; a++) {
        const double e0 = v[3 + a] - v[a], e1 = v[6 + a] - v[3 + a], e2 = v[a] - v[6 + a];
        emax = fmax(emax, fmax(fabs(e0), fmax(fabs(e1), fabs(e2))));
        const double lo = fmin(v[a], fmin(v[3 + a], v[6 + a])) - EPS;
        const double hi = fmax(v[a], fmax(v[3 + a], v[6 + a])) + EPS;
        double L = fmax(fabs(e0), fabs(e2));
        for (int q = (int)fmax(0.0, floor(lo)); q <= (int)fmin(N - 1, floor(hi)); q++) {
            const double bc = 0.5 * (cell_lo(q) + cell_hi(q));
            L = fmax(L, fmax(fabs(bc - v[a]), 0.5 * (cell_hi(q) - cell_lo(q))));
        }
        sum += L;
    }
    return 64.0 * (DBL_EPSILON / 2) * emax * sum + 0x1p-1000;
}

/* the triangle of "touch" (touch_edges): the edge through the corner (P, Q) shifted by d
   along (sp, sq), the third vertex on the side w */
static void touch_tri(double upq[3][3], const double u[3], double P, double Q, double sp,
                      double sq, double w, double d)
{
    const double p0 = P + d * sp, q0 = Q + d * sq;
    const double r[3][3] = {
        {u[0], p0 - 1.0 * sp, q0 + 1.0 * sq},
        {u[1], p0 + 1.0 * sp, q0 - 1.0 * sq},
        {u[2], p0 + w * 0.75 * sp, q0 + w * 0.75 * sq},
    };
    memcpy(upq, r, sizeof r);
}
/* the edges of "touch" (see the head comment), the triangles' vertices at u[0], u[1], u[2]
   on the third axis, each triangle with the edge as edge 0, 1 and 2 of the build. fixed: the
   fixed offsets (0, 1e-14 .. 1e-10, 1, 4, 64 ulps); band: the offset B / 8 (filter_B) on
   both sides, which moves the filter's m by B / 2 (the edge's normal in the projection is
   (e_Q, -e_P) = 2 (sp, sq) up to sign, the shift (d sp, d sq): 4 d): the middle of the band
   between the exact threshold and ro (the edge outside: rt_tri_box separates, by far more
   than its rounding, where |m| <= ro) or ri (inside: rt_tri_box keeps where |m| > ri), so
   that the filter must leave the cell to rt_tri_box */
static void touch_edges(tris *t, const double u[3], int fixed, int band)
{
    const double offs[] = {0.0, 1e-14, 1e-13, 1e-12, 1e-10};
    const int ulps[] = {1, 4, 64};
    for (int ax = 0; ax < 3; ax++)
        for (int qp = 2; qp <= 5; qp += 3)
            for (int qq = 2; qq <= 5; qq += 3)
                for (int corner = 0; corner < 4; corner++) {
                    /* the corner (P, Q) of cell (qp, qq) in the projection; the cell lies on
                       the side sp, sq of it (+1: towards larger coordinates) */
                    const double P = corner & 1 ? cell_hi(qp) : cell_lo(qp);
                    const double Q = corner & 2 ? cell_hi(qq) : cell_lo(qq);
                    const double sp = corner & 1 ? -1.0 : 1.0, sq = corner & 2 ? -1.0 : 1.0;
                    /* an edge through (P, Q) along (sp, -sq) keeps the cell on one side (the
                       side of (sp, sq)); shifted by d along (sp, sq) */
                    for (int side = -1; side <= 1; side += 2)
                        for (int far = 0; far < 2; far++)
                            for (int rot = 0; rot < 3; rot++) {
                                /* the third vertex: away from the cell (far) or towards it */
                                const double w = far ? -1.0 : 1.0;
                                double ds[5 + 3 + 1];
                                int nd = 0;
                                if (fixed) {
                                    for (size_t k = 0; k < sizeof offs / sizeof *offs; k++)
                                        ds[nd++] = side * offs[k];
                                    for (size_t k = 0; k < sizeof ulps / sizeof *ulps; k++)
                                        ds[nd++] = side * ulps[k] * (nextafter(P, INFINITY) - P);
                                }
                                if (band) {
                                    double upq0[3][3], v[9];
                                    touch_tri(upq0, u, P, Q, sp, sq, w, 0.0);
                                    rot_tri(ax, rot, upq0, v);
                                    ds[nd++] = side * filter_B(v) / 8.0;
                                }
                                for (int k = 0; k < nd; k++) {
                                    double upq[3][3];
                                    touch_tri(upq, u, P, Q, sp, sq, w, ds[k]);
                                    add_rot(t, ax, rot, upq);
                                }
                            }
                }
}

/* "touch": see the head comment */
static void touch_scene(tris *t)
{
    touch_edges(t, (const double[3]){2.5, 5.5, 4.0}, 1, 1);
    /* planes through a cell corner, and a vertex on a cell face, exactly */
    for (int q = 2; q <= 4; q++) {
        const double X = cell_hi(q), Y = cell_hi(q + 1), Z = cell_lo(q);
        const double v1[9] = {X + 1.0, Y, Z - 1.0, X, Y + 1.0, Z - 1.0, X, Y, Z};
        add_tri(t, v1);
        const double v2[9] = {X + 0.5, Y - 0.5, Z, X - 0.5, Y, Z + 0.5, X, Y + 0.5, Z - 0.5};
        add_tri(t, v2);
        const double v3[9] = {cell_lo(q), 3.25, 4.5, cell_lo(q) - 0.75, 4.75, 3.5,
                              cell_lo(q) - 0.5, 3.5, 5.25};
        add_tri(t, v3);
    }
}

/* "slab": the edges of "touch" on triangles that lie inside one cell on the third axis (the
   build's rt_tri_slab: its cells decided in the projection along that axis), in the middle of
   the cell and as close to its faces as the cell range of one cell allows (2 eps inside,
   where the enlarged box is 3 eps away), tilted both ways */
static void slab_scene(tris *t)
{
    touch_edges(t, (const double[3]){4.25, 4.75, 4.5}, 1, 1);
    touch_edges(t, (const double[3]){4.0 + 2.0 * EPS, 5.0 - 2.0 * EPS, 4.5}, 1, 1);
    touch_edges(t, (const double[3]){5.0 - 2.0 * EPS, 4.0 + 2.0 * EPS, 5.0 - 2.0 * EPS}, 1, 1);
    touch_edges(t, (const double[3]){4.5, 4.5, 4.5}, 1, 1);
}

/* "band": the edges of "touch" and "slab" at the offsets B / 8 only (touch_edges: the filter's
   m in the middle of its undecided band), general: the triangles of "touch" (several cells on
   every axis, rt_tri_cells' filter), or those of "slab" (rt_tri_slab's) */
static void band_scene(tris *t, int general)
{
    if (general) {
        touch_edges(t, (const double[3]){2.5, 5.5, 4.0}, 0, 1);
        return;
    }
    touch_edges(t, (const double[3]){4.25, 4.75, 4.5}, 0, 1);
    touch_edges(t, (const double[3]){4.0 + 2.0 * EPS, 5.0 - 2.0 * EPS, 4.5}, 0, 1);
    touch_edges(t, (const double[3]){5.0 - 2.0 * EPS, 4.0 + 2.0 * EPS, 5.0 - 2.0 * EPS}, 0, 1);
}

/* the cell box of q on an axis as the build computes it from cell_lo and cell_hi (rt_axis_box) */
static void cell_box(int q, double *bc, double *h)
{
    *bc = 0.5 * (cell_lo(q) + cell_hi(q));
    *h = 0.5 * (cell_hi(q) - cell_lo(q));
}

/* the smallest double y with y - bc >= t as the build computes it (a comparison of
   rt_tri_row), found by stepping ulps from x (x near it) */
static double first_ge(double x, double bc, double t)
{
    for (int k = 0; k < 64 && x - bc >= t; k++)
        x = nextafter(x, -INFINITY);
    for (int k = 0; k < 64 && !(x - bc >= t); k++)
        x = nextafter(x, INFINITY);
    assert_true(x - bc >= t && !(nextafter(x, -INFINITY) - bc >= t));
    return x;
}

/* "row": triangles inside one cell on two axes (p, q; rt_tri_row), spanning cells on the
   third (u), whose end on u lies at the face of cell k's enlarged box, on both sides of the
   values where rt_tri_row's comparisons flip, computed as the build computes them (mn = bb -
   bc against h: the face test; against h - eps: the margin), the middle of the margin band
   (eps / 2 inside the face: the cell to rt_tri_box), and the face itself; the triangle below
   the face (its top vertex at the lower face of k) or above (its bottom vertex at the upper
   face of k - 1), touching with a vertex or with an edge in the face; on p and q in the
   middle of cell 4, 2 eps from its faces (as close as a one-cell range allows), and at the
   scene box's faces (the first and last cells: the inside test at its bound). band: only the
   margin band's middle (each triangle sends a cell to rt_tri_box). */
static void row_scene(tris *t, int band)
{
    static const struct {
        double lo, hi;
    } pq[] = {{4.0 + 2.0 * EPS, 5.0 - 2.0 * EPS}, {0.0, 1.0 - 2.0 * EPS}, {7.0 + 2.0 * EPS, 8.0}};
    for (int ax = 0; ax < 3; ax++)
        for (size_t r = 0; r < sizeof pq / sizeof *pq; r++)
            for (int k = 2; k <= 7; k++)
                for (int below = k == 7; below < 2; below++) {
                    /* the face: the lower one of cell k (the triangle below it, its top mx
                       = U - bc against -h and eps - h) or the upper one of cell k - 1 (the
                       triangle above, its bottom mn = U - bc against h and h - eps) */
                    const int cell = below ? k : k - 1;
                    double bc, h;
                    cell_box(cell, &bc, &h);
                    const double F = below ? cell_lo(cell) : cell_hi(cell);
                    const double in = below ? INFINITY : -INFINITY; /* into the cell */
                    double U[8];
                    int nu = 0;
                    if (!band) {
                        /* the face test's flip (kept: mx >= -h, mn <= h, i.e. not mn >=
                           the double above h): the last value kept and the first not */
                        const double hu = nextafter(h, INFINITY);
                        const double keep = below ? first_ge(F, bc, -h)
                                                  : nextafter(first_ge(F, bc, hu), -INFINITY);
                        U[nu++] = keep;
                        U[nu++] = nextafter(keep, -in);
                        U[nu++] = nextafter(keep, in);
                        U[nu++] = F;
                        /* the margin's flip (mx >= eps - h, mn <= h - eps): the last value
                           without the margin and the first with it */
                        const double mu = nextafter(h - EPS, INFINITY);
                        const double m = below ? first_ge(F + EPS, bc, EPS - h)
                                               : nextafter(first_ge(F - EPS, bc, mu), -INFINITY);
                        U[nu++] = m;
                        U[nu++] = nextafter(m, -in);
                    }
                    U[nu++] = below ? F + EPS / 2 : F - EPS / 2;
                    const double s = below ? -1.0 : 1.0; /* from U to the rest of the triangle */
                    const double p0 = pq[r].lo, p1 = pq[r].hi, pm = 0.5 * (p0 + p1);
                    for (int j = 0; j < nu; j++) {
                        const double u = U[j];
                        /* a vertex at U, the plane tilted; an edge at U */
                        const double t1[3][3] = {{u, pm, 0.75 * p0 + 0.25 * p1},
                                                 {u + s * 1.25, p0, p1},
                                                 {u + s * 0.75, p1, p0}};
                        const double t2[3][3] = {{u, p0, p0}, {u, p1, p1}, {u + s * 1.25, pm, p0}};
                        add_rot(t, ax, 0, t1);
                        add_rot(t, ax, 0, t2);
                    }
                }
}

/* "lattice": n random triangles near the centre, vertices on q - eps, q + eps, q, q + 1/2 */
static void lattice_scene(tris *t, int n, uint64_t seed)
{
    uint64_t st = seed;
    for (int k = 0; k < n; k++) {
        double v[9];
        const int base[3] = {2 + (int)(4 * rtu_rand(&st)), 2 + (int)(4 * rtu_rand(&st)),
                             2 + (int)(4 * rtu_rand(&st))};
        for (int j = 0; j < 9; j++) {
            const int q = base[j % 3] + (int)(3 * rtu_rand(&st)) - 1;
            const int kind = (int)(4 * rtu_rand(&st));
            v[j] = kind == 0 ? cell_lo(q) : kind == 1 ? cell_hi(q - 1) : kind == 2 ? q : q + 0.5;
        }
        add_tri(t, v);
    }
}

static rt_scene *make_scene(const tris *t)
{
    int surf;
    rt_scene *sc = rtu_scene_one_surface(&surf);
    assert_non_null(sc);
    const int three = 3;
    /* the anchors: the scene box is [0, 8]^3 */
    const double a0[9] = {0, 0, 0, 0.01, 0, 0, 0, 0.01, 0};
    const double a1[9] = {8, 8, 8, 7.99, 8, 8, 8, 7.99, 8};
    assert_true(rt_scene_add_polygon(sc, 1, &three, a0, surf, surf) >= 0);
    assert_true(rt_scene_add_polygon(sc, 1, &three, a1, surf, surf) >= 0);
    for (size_t k = 0; k < t->n; k++)
        assert_true(rt_scene_add_polygon(sc, 1, &three, t->v + 9 * k, surf, surf) >= 0);
    return sc;
}

/* commits t with the filter on and off on 1 and 2 threads; the hashes agree; returns the
   cells the filter left to the exact test (1 thread) */
static uint64_t check(const tris *t, int subgrids, const char *name)
{
    rt_scene *sc = make_scene(t);
    uint64_t hash = 0, exact = 0;
    for (int threads = 1; threads <= 2; threads++)
        for (int on = 1; on >= 0; on--) {
            rt_build_options o = {.brute_threshold = 0, .threads = threads,
                                  .grid_res = {N, N, N}, .grid_box = {0, 0, 0, 8, 8, 8},
                                  .no_subgrids = !subgrids, .sub_min = subgrids ? 4 : 0};
            rt_build_set_filter(on);
            const uint64_t e0 = rt_build_exact_cells();
            const int rc = rt_scene_commit(sc, &o);
            const uint64_t e1 = rt_build_exact_cells();
            rt_build_set_filter(1);
            assert_int_equal(rc, RT_OK);
            assert_true(sc->use_grid);
            /* the box this test computed the cells of */
            assert_true(sc->scale == 8.0);
            for (int a = 0; a < 3; a++) {
                assert_true(sc->bbox[a] == 0.0 && sc->bbox[3 + a] == 8.0);
                assert_true(sc->grid.b.lo[a] == 0.0 && sc->grid.b.hi[a] == 8.0);
                assert_true(sc->grid.b.cw[a] == 1.0 && sc->grid.b.n[a] == N);
            }
            rt_grid_info gi;
            assert_int_equal(rt_scene_grid_info(sc, &gi), RT_OK);
            if (threads == 1 && on)
                exact = e1 - e0;
            printf("%s, %d thread(s), filter %s: %zu triangles, grid %016llx, %llu refs, "
                   "%llu sub refs, %llu cells to the exact test\n", name, threads,
                   on ? "on" : "off", t->n, (unsigned long long)gi.hash,
                   (unsigned long long)gi.refs, (unsigned long long)gi.subrefs,
                   (unsigned long long)(e1 - e0));
            if (hash == 0)
                hash = gi.hash;
            else if (gi.hash != hash)
                fail_msg("%s: grid %016llx with the filter %s on %d thread(s), %016llx before",
                         name, (unsigned long long)gi.hash, on ? "on" : "off", threads,
                         (unsigned long long)hash);
            if (subgrids)
                assert_true(gi.subgrids > 0);
        }
    rt_scene_free(sc);
    return exact;
}

static void test_touch(void **state)
{
    (void)state;
    tris t = {0};
    touch_scene(&t);
    const uint64_t exact = check(&t, 0, "touch");
    assert_true(exact > 0); /* the filter met separations within its bound */
    free(t.v);
}

static void test_slab(void **state)
{
    (void)state;
    tris t = {0};
    slab_scene(&t);
    const uint64_t exact = check(&t, 0, "slab");
    assert_true(exact > 0);
    free(t.v);
}

static void test_row(void **state)
{
    (void)state;
    tris t = {0};
    row_scene(&t, 0);
    (void)check(&t, 0, "row");
    free(t.v);
}

/* every triangle of "band" puts a cell in the filter's band, every one of "row" with band
   set a cell in rt_tri_row's margin band: at least one cell per triangle to the exact test */
static void test_band(void **state)
{
    (void)state;
    static const char *const names[] = {"band, general", "band, slab", "band, row"};
    for (int kind = 0; kind < 3; kind++) {
        tris t = {0};
        if (kind < 2)
            band_scene(&t, kind == 0);
        else
            row_scene(&t, 1);
        const uint64_t exact = check(&t, 0, names[kind]);
        assert_true(exact >= t.n);
        free(t.v);
    }
}

static void test_lattice(void **state)
{
    (void)state;
    tris t = {0};
    lattice_scene(&t, 3000, 99);
    const uint64_t exact = check(&t, 0, "lattice");
    assert_true(exact > 0);
    free(t.v);
}

static void test_lattice_sub(void **state)
{
    (void)state;
    tris t = {0};
    lattice_scene(&t, 3000, 7);
    (void)check(&t, 1, "lattice, second level");
    free(t.v);
}

/* ---- the filters' plain C forms against the SSE2 forms (rt_build_edge_filter,
   rt_build_slab_masks: form 0 is what targets without SSE2 run, form 1 what this one runs) */

/* a double of any kind: small (most), of any exponent, subnormal, +-0, +-inf, NaN */
static double any_double(uint64_t *st)
{
    const double r = rtu_rand(st) - 0.5;
    switch ((int)(16 * rtu_rand(st))) {
    case 0:
        return 0.0;
    case 1:
        return -0.0;
    case 2:
        return INFINITY;
    case 3:
        return -INFINITY;
    case 4:
        return NAN;
    case 5:
        return DBL_MIN * r; /* subnormal */
    case 6:
        return ldexp(r, (int)(2100 * rtu_rand(st)) - 1074); /* up to overflow */
    default:
        return 8.0 * r;
    }
}

/* the bounds (ri, ro) of an edge whose filter value is m = |cw - cv| as the build computes
   it: around m (ties, one ulp either way), random, or as the filter off makes them (ro
   infinite, ri -inf or NaN); ri <= ro or NaN, as the build's are */
static void any_bounds(uint64_t *st, double m, double *ri, double *ro)
{
    double a = any_double(st), b = any_double(st);
    switch ((int)(8 * rtu_rand(st))) {
    case 0:
        a = m;
        break;
    case 1:
        b = m;
        break;
    case 2:
        a = nextafter(m, INFINITY);
        break;
    case 3:
        b = nextafter(m, -INFINITY);
        break;
    case 4:
        a = -INFINITY;
        b = INFINITY;
        break;
    case 5:
        a = NAN;
        b = INFINITY;
        break;
    default:
        break;
    }
    *ri = a > b ? b : a; /* NaN stays where it is */
    *ro = a > b ? a : b;
}

/* the filter's answer by its definition: 1 if an edge's m > ro, else -1 if one's m is not
   <= ri, else 0 */
static int edge_def(const double ro[3], const double ri[3], const double cv[3],
                    const double cw[3])
{
    int sep = 0, und = 0;
    for (int i = 0; i < 3; i++) {
        const double m = fabs(cw[i] - cv[i]);
        sep |= m > ro[i];
        und |= !(m <= ri[i]);
    }
    return sep ? 1 : -und;
}

/* one edge of a hand-made case: m = |cw - cv| (cw, cv given) placed by state against its
   bounds: below ri, at ri, between, at ro, above ro, m NaN, ri NaN, the filter off (ro inf,
   ri -inf), ri = ro = m */
enum { EDGE_STATES = 9 };
static void edge_state(int state, double *cv, double *cw, double *ri, double *ro)
{
    if (state == 5)
        *cw = NAN;
    const double m = fabs(*cw - *cv);
    switch (state) {
    case 0:
        *ri = nextafter(m, INFINITY);
        *ro = *ri + 1.0;
        break;
    case 1:
        *ri = m;
        *ro = m + 1.0;
        break;
    case 2:
        *ri = nextafter(m, -INFINITY);
        *ro = nextafter(m, INFINITY);
        break;
    case 3:
        *ri = nextafter(m, -INFINITY);
        *ro = m;
        break;
    case 4:
        *ro = nextafter(m, -INFINITY);
        *ri = *ro - 1.0;
        break;
    case 5:
        *ri = 1.0;
        *ro = 2.0;
        break;
    case 6:
        *ri = NAN;
        *ro = nextafter(m, INFINITY);
        break;
    case 7:
        *ri = -INFINITY;
        *ro = INFINITY;
        break;
    default:
        *ri = *ro = m;
        break;
    }
}

/* rt_edge_filter's two forms give the same answer as each other and, on the hand-made cases,
   as the definition: every combination of the three edges' states (the edges in the two SSE2
   lanes and alone) at several magnitudes, then random cells and bounds */
static void test_forms_edge(void **state)
{
    (void)state;
    uint64_t st = 12345;
    long n = 0;
    static const double mags[] = {1.0, 0x1p-1060, 0x1p1000, 3.0e-5};
    for (size_t g = 0; g < sizeof mags / sizeof *mags; g++)
        for (int c = 0; c < EDGE_STATES * EDGE_STATES * EDGE_STATES; c++) {
            double cv[3], cw[3], ri[3], ro[3];
            for (int i = 0, k = c; i < 3; i++, k /= EDGE_STATES) {
                cv[i] = mags[g] * (rtu_rand(&st) - 0.5);
                cw[i] = mags[g] * (rtu_rand(&st) - 0.5);
                edge_state(k % EDGE_STATES, &cv[i], &cw[i], &ri[i], &ro[i]);
            }
            const int d = edge_def(ro, ri, cv, cw);
            const int r0 = rt_build_edge_filter(0, ro, ri, cv, cw);
            const int r1 = rt_build_edge_filter(1, ro, ri, cv, cw);
            if (r0 != d || r1 != d)
                fail_msg("edge filter, states %d (magnitude %g): plain C %d, as built %d, "
                         "defined %d", c, mags[g], r0, r1, d);
            n++;
        }
    for (int k = 0; k < 200000; k++) {
        double cv[3], cw[3], ri[3], ro[3];
        for (int i = 0; i < 3; i++) {
            cv[i] = any_double(&st);
            cw[i] = rtu_rand(&st) < 0.5 ? cv[i] + any_double(&st) : any_double(&st);
            any_bounds(&st, fabs(cw[i] - cv[i]), &ri[i], &ro[i]);
        }
        const int r0 = rt_build_edge_filter(0, ro, ri, cv, cw);
        const int r1 = rt_build_edge_filter(1, ro, ri, cv, cw);
        if (r0 != r1)
            fail_msg("edge filter, random case %d: plain C %d, as built %d (cv %a %a %a, cw "
                     "%a %a %a, ri %a %a %a, ro %a %a %a)", k, r0, r1, cv[0], cv[1], cv[2],
                     cw[0], cw[1], cw[2], ri[0], ri[1], ri[2], ro[0], ro[1], ro[2]);
        n++;
    }
    printf("edge filter: %ld cases, the two forms equal\n", n);
}

/* rt_slab_masks' forms for one range: the same masks below np for every row not in outq,
   and with want (the definition's masks) when given; rows in outq left alone */
static void slab_compare(const double (*cvT)[RT_BUILD_SPAN + 1], int np, const double (*cw)[3],
                         int nq, uint32_t outq, const double ro[3], const double ri[3],
                         const uint32_t *wsep, const uint32_t *wund, const char *what, int k)
{
    uint32_t s0[RT_BUILD_SPAN], u0[RT_BUILD_SPAN], s1[RT_BUILD_SPAN], u1[RT_BUILD_SPAN];
    for (int q = 0; q < RT_BUILD_SPAN; q++)
        s0[q] = u0[q] = s1[q] = u1[q] = 0xdeadbeefu;
    rt_build_slab_masks(0, cvT, np, cw, nq, outq, ro, ri, s0, u0);
    rt_build_slab_masks(1, cvT, np, cw, nq, outq, ro, ri, s1, u1);
    const uint32_t all = np == 32 ? ~(uint32_t)0 : ((uint32_t)1 << np) - 1;
    for (int q = 0; q < RT_BUILD_SPAN; q++) {
        if (q >= nq || (outq >> q & 1)) { /* not written */
            if (s0[q] != 0xdeadbeefu || u0[q] != 0xdeadbeefu || s1[q] != 0xdeadbeefu ||
                u1[q] != 0xdeadbeefu)
                fail_msg("slab masks, %s %d: row %d (out) written", what, k, q);
            continue;
        }
        if ((s0[q] & all) != (s1[q] & all) || (u0[q] & all) != (u1[q] & all))
            fail_msg("slab masks, %s %d, row %d of %d, %d cells: plain C %08x %08x, as built "
                     "%08x %08x", what, k, q, nq, np, s0[q] & all, u0[q] & all, s1[q] & all,
                     u1[q] & all);
        if (wsep && ((s0[q] & all) != wsep[q] || (u0[q] & all) != wund[q]))
            fail_msg("slab masks, %s %d, row %d: %08x %08x, defined %08x %08x", what, k, q,
                     s0[q] & all, u0[q] & all, wsep[q], wund[q]);
    }
}

/* rt_slab_masks' two forms give the same masks, and on the hand-made ranges those of the
   definition: every row length 1 .. 32 with the cells' m below ri, at ri, between, at ro,
   above ro or NaN on each edge in turn (the SSE2 lanes' pairs, the odd last cell); then
   random ranges, with m tied to a bound in some cells */
static void test_forms_slab(void **state)
{
    (void)state;
    uint64_t st = 777;
    double cvT[3][RT_BUILD_SPAN + 1], cw[RT_BUILD_SPAN][3], ro[3], ri[3];
    uint32_t ws[RT_BUILD_SPAN], wu[RT_BUILD_SPAN];
    /* hand-made: ri 1, ro 2; cell p has m(p) = 0.5, 1, 1.5, 2, 3 or NaN (state (p + p / 6)
       mod 6, all exact) on edge (p / 6) mod 3 in row 0 (cw 4, cvT 4 - m), 0.25 on the
       others: each state on each edge in both lanes of a pair; row 1 has cw -4 (m 8 - m(p):
       separates), row 2 is out, rows 3 .. have cw 4 + (q mod 4) / 2 (m + 0.5 ...) */
    static const double ms[] = {0.5, 1.0, 1.5, 2.0, 3.0, NAN};
    for (int np = 1; np <= RT_BUILD_SPAN; np++)
        for (int nq = 1; nq <= 8; nq++) {
            const uint32_t outq = nq > 2 ? 4u : 0u;
            for (int i = 0; i < 3; i++) {
                ri[i] = 1.0;
                ro[i] = 2.0;
                cvT[i][np] = rtu_rand(&st); /* the lane after the last cell */
                for (int p = 0; p < np; p++)
                    cvT[i][p] = 4.0 - (i == (p / 6) % 3 ? ms[(p + p / 6) % 6] : 0.25);
            }
            for (int q = 0; q < nq; q++) {
                ws[q] = wu[q] = 0;
                for (int i = 0; i < 3; i++)
                    cw[q][i] = q == 1 ? -4.0 : 4.0 + 0.5 * (q % 4);
            }
            for (int q = 0; q < nq; q++)
                for (int p = 0; p < np; p++) {
                    int sep = 0, und = 0;
                    for (int i = 0; i < 3; i++) {
                        const double m = fabs(cw[q][i] - cvT[i][p]);
                        sep |= m > ro[i];
                        und |= !(m <= ri[i]);
                    }
                    ws[q] |= (uint32_t)sep << p;
                    wu[q] |= (uint32_t)und << p;
                }
            slab_compare(cvT, np, cw, nq, outq, ro, ri, ws, wu, "hand-made", np);
        }
    for (int k = 0; k < 20000; k++) {
        const int np = 1 + (int)(RT_BUILD_SPAN * rtu_rand(&st));
        const int nq = 1 + (int)(RT_BUILD_SPAN * rtu_rand(&st));
        const uint32_t outq = rtu_rand(&st) < 0.5 ? 0u : (uint32_t)(st >> 32);
        for (int i = 0; i < 3; i++)
            for (int p = 0; p <= np; p++)
                cvT[i][p] = any_double(&st);
        for (int q = 0; q < nq; q++)
            for (int i = 0; i < 3; i++)
                cw[q][i] = rtu_rand(&st) < 0.5 ? cvT[i][0] + any_double(&st) : any_double(&st);
        for (int i = 0; i < 3; i++) {
            const int p = (int)(np * rtu_rand(&st)), q = (int)(nq * rtu_rand(&st));
            any_bounds(&st, fabs(cw[q][i] - cvT[i][p]), &ri[i], &ro[i]);
        }
        slab_compare(cvT, np, cw, nq, outq, ro, ri, NULL, NULL, "random", k);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_touch),
        cmocka_unit_test(test_slab),
        cmocka_unit_test(test_row),
        cmocka_unit_test(test_band),
        cmocka_unit_test(test_lattice),
        cmocka_unit_test(test_lattice_sub),
        cmocka_unit_test(test_forms_edge),
        cmocka_unit_test(test_forms_slab),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
