/* SPDX-License-Identifier: MIT */
/*
 * test_rt_lbuf.c -- light buffers (rt_lbuf.c): shadow rays that test a per-light candidate
 * list instead of walking the grid must give the walk's answers. Each scene is rendered with
 * light buffers on and off (and on a brute-force scene, which never has any) and the
 * pictures compared: a candidate missing from a list lets light through where the walk
 * finds the blocker (checked: dropping the last candidate of every list changes 36 values by
 * up to 1.5e-3 here, 1266 by up to 3.5e-2 in gears); the
 * tolerance 1e-6 relative only absorbs the order in which transparencies are multiplied
 * (product of up to a few factors in [0,1], rounding ~1e-16). Every test also requires the
 * buffers to have answered the share stated of the shadow rays that needed a traversal (so
 * the comparison is not empty) and no non-finite pixel.
 * Scenes: all primitive kinds (tessellated floor, closed triangle sphere whose shadow edges
 * run along its mesh edges, transparent box of quads, concave polygon with a hole, cell
 * array, mirrors for shadow rays from secondary hits) under positional, spot and directional
 * lights and a light inside the scene box (no buffer: the walk), also translated by 1e6 and
 * with the light 1e4 away; secondary rays clipped to the display volume; a grazing light on
 * a finely tessellated sphere; the SPD gears (glass, 144-gons, five lights), whose quads and
 * polygons also check the parts of the hits' error bounds kept with their records
 * (check_hit_bounds).
 * Mirror buffers (rt_render.c, rt_job_mirrors: eye rays' reflections off a flat floor take
 * a list built from the eye's mirror image) are on with light buffers: the same comparison
 * covers them: they must have answered 30 % of the reflection rays on the level floor
 * (test_kinds_and_lights) and on a tilted one whose quads' normals differ in their last bits,
 * with a quad just under it (left out of the mirror's lists) and a post through it
 * (test_mirror). Checked: leaving out what lies within 3 units of the plane instead changes
 * 1153 values of the tilted floor's picture; stopping a list 0.3 early, 12 values of the
 * level floor's.
 * A shadow ray tests only the candidates of its cell whose projection (4 lines per primitive,
 * rt_lbuf_next) its footprint may meet (checked: a line test 1e-3 too eager changes 1800
 * values of test_kinds_and_lights' picture, 13695 of the gears').
 * The build's parts (test_build_parts): the buffers built with 2, 3 and 8 threads equal the
 * one-thread buffer array for array, and every list is in ascending (depth bucket, primitive)
 * order, the order the early stop of a shadow ray relies on.
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

#define GKS3D_RT_BUILDING 1
#include "gksrt.h"
#include "rt_internal.h"
#include "rt_check.h"
#include "rt_testutil.h"

enum { W = 96, H = 96 };

typedef struct lb_case {
    double off;          /* translation of everything */
    int lights;          /* 0: positional + spot + directional; 1: + one inside the box;
                            2: positional 1e4 away; 3: grazing directional (sphere scene) */
    int sphere_only;     /* 1: fine sphere on a floor */
    int tilted;          /* 1: the floor tilted (its quads' normals differ in their last bits),
                            a quad under it and a post through it (mirror buffers) */
} lb_case;

static int add_surface(rt_scene *sc, double r, double g, double b, double ks, double kt)
{
    rt_surface s;
    rt_surface_default(&s);
    s.refl_eq = RT_REFL_SPECULAR;
    s.ka = 0.1;
    s.kd = 0.7;
    s.ks = ks;
    s.spec_exp = 20;
    s.diffuse[0] = r;
    s.diffuse[1] = g;
    s.diffuse[2] = b;
    s.transparency = kt;
    s.refr_index = 1.0;
    int id = rt_scene_add_surface(sc, &s);
    assert_true(id >= 0);
    return id;
}

static void add_quad(rt_scene *sc, const double q[4][3], double off, int sf, int sb)
{
    double v[12];
    for (int k = 0; k < 4; k++)
        for (int j = 0; j < 3; j++)
            v[3 * k + j] = q[k][j] + off;
    int n = 4;
    assert_true(rt_scene_add_polygon(sc, 1, &n, v, sf, sb) >= 0);
}

static void build(rt_scene *sc, const lb_case *lc)
{
    const double o = lc->off;
    const int floor_s = add_surface(sc, 0.9, 0.8, 0.6, 0.3, 0.0);
    const int ball = add_surface(sc, 0.8, 0.2, 0.2, 0.5, 0.0);
    /* floor z = -2.5 over [-1.6,1.6]^2 in 8x8 quads sharing their edges (tilted: z = -2.5 +
       0.3 (y + 0.1 x), rising away from the eye) */
    const double tz = lc->tilted ? 0.3 : 0.0;
#define FZ(x, y) (-2.5 + tz * ((y) + 0.1 * (x)))
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++) {
            const double x0 = -1.6 + 0.4 * i, y0 = -1.6 + 0.4 * j, x1 = x0 + 0.4, y1 = y0 + 0.4;
            const double q[4][3] = {{x0, y0, FZ(x0, y0)}, {x1, y0, FZ(x1, y0)}, {x1, y1, FZ(x1, y1)},
                                    {x0, y1, FZ(x0, y1)}};
            add_quad(sc, q, o, floor_s, floor_s);
        }
    if (lc->tilted) {
        /* a red quad just under the floor (left out of the mirror's buffer) and a post
           standing through it (kept: reflections see its upper part) */
        const int red = add_surface(sc, 0.9, 0.1, 0.1, 0.0, 0.0);
        const double u[4][3] = {{-1.0, -1.0, FZ(-1.0, -1.0) - 1e-3}, {1.0, -1.0, FZ(1.0, -1.0) - 1e-3},
                                {1.0, 1.0, FZ(1.0, 1.0) - 1e-3}, {-1.0, 1.0, FZ(-1.0, 1.0) - 1e-3}};
        add_quad(sc, u, o, red, red);
        const double p[4][3] = {{0.9, -0.9, -3.0}, {1.3, -0.9, -3.0}, {1.3, -0.9, -1.2}, {0.9, -0.9, -1.2}};
        add_quad(sc, p, o, red, red);
    }
#undef FZ
    if (lc->sphere_only) {
        assert_int_equal(rtu_add_sphere(sc, (const double[3]){o, o, -1.9 + o}, 0.55, 48, 24, ball), 0);
    } else {
        assert_int_equal(rtu_add_sphere(sc, (const double[3]){-0.3 + o, -0.2 + o, -1.9 + o}, 0.4, 16, 8, ball), 0);
        /* transparent box (front kt 0.5, back 0.7) of quads */
        const int glass_f = add_surface(sc, 0.6, 0.9, 0.9, 0.2, 0.5);
        const int glass_b = add_surface(sc, 0.6, 0.9, 0.9, 0.2, 0.7);
        const double lo[3] = {0.3, 0.2, -2.4}, hi[3] = {0.9, 0.8, -1.6};
        for (int a = 0; a < 3; a++)
            for (int sgn = 0; sgn < 2; sgn++) {
                const int b = (a + 1) % 3, c = (a + 2) % 3;
                double q[4][3];
                for (int k = 0; k < 4; k++) {
                    q[k][a] = sgn ? hi[a] : lo[a];
                    const int kb = sgn ? (k == 1 || k == 2) : (k >= 2);
                    const int kc = sgn ? (k >= 2) : (k == 1 || k == 2);
                    q[k][b] = kb ? hi[b] : lo[b];
                    q[k][c] = kc ? hi[c] : lo[c];
                }
                add_quad(sc, q, o, glass_f, glass_b);
            }
        /* concave polygon with a hole, kt 0.6, tilted */
        const int veil = add_surface(sc, 0.3, 0.3, 0.9, 0.0, 0.6);
        const double poly[] = {-1.2, 0.3, -1.2, -0.4, 0.3, -1.0, -0.4, 1.2, -1.0, -0.8, 0.8, -1.1,
                               -1.2, 1.2, -1.3, /* hole */ -0.9, 0.6, -1.15, -0.7, 0.6, -1.1,
                               -0.7, 0.8, -1.12};
        double pv[24];
        for (int k = 0; k < 24; k++)
            pv[k] = poly[k] + o;
        const int counts[2] = {5, 3};
        assert_true(rt_scene_add_polygon(sc, 2, counts, pv, veil, veil) >= 0);
        /* opaque cell array, standing */
        const int cells = add_surface(sc, 1, 1, 1, 0.0, 0.0);
        const float rgb[6] = {1, 0, 0, 0, 1, 0};
        const double P[3] = {-1.0 + o, 0.9 + o, -2.5 + o}, R[3] = {-0.2 + o, 1.2 + o, -2.5 + o},
                     Q[3] = {-0.2 + o, 1.2 + o, -1.8 + o};
        assert_true(rt_scene_add_cell_array(sc, P, Q, R, 2, 1, rgb, cells, cells) >= 0);
    }
    rt_light l;
    memset(&l, 0, sizeof l);
    l.color[0] = l.color[1] = l.color[2] = 0.8;
    l.c1 = 1.0;
    l.type = RT_LIGHT_AMBIENT;
    assert_true(rt_scene_add_light(sc, &l) >= 0);
    if (lc->lights == 3) { /* grazing: 3 degrees above the floor */
        l.type = RT_LIGHT_DIRECTIONAL;
        l.direction[0] = -cos(3 * M_PI / 180);
        l.direction[1] = 0.1;
        l.direction[2] = -sin(3 * M_PI / 180);
        assert_true(rt_scene_add_light(sc, &l) >= 0);
        return;
    }
    l.type = RT_LIGHT_POSITIONAL;
    const double far = lc->lights == 2 ? 1e4 : 1.0;
    l.position[0] = 2.0 * far + o;
    l.position[1] = 1.5 * far + o;
    l.position[2] = 1.0 * far + o;
    assert_true(rt_scene_add_light(sc, &l) >= 0);
    if (lc->lights == 2)
        return;
    l.type = RT_LIGHT_SPOT;
    l.position[0] = -1.5 + o;
    l.position[1] = 2.0 + o;
    l.position[2] = 0.5 + o;
    l.direction[0] = 1.5;
    l.direction[1] = -2.0;
    l.direction[2] = -2.5;
    l.concentration = 2;
    l.spread = 1.0;
    assert_true(rt_scene_add_light(sc, &l) >= 0);
    l.type = RT_LIGHT_DIRECTIONAL;
    l.direction[0] = -0.3;
    l.direction[1] = -0.4;
    l.direction[2] = -1.0;
    assert_true(rt_scene_add_light(sc, &l) >= 0);
    if (lc->lights == 1) { /* inside the scene box, above the floor */
        l.type = RT_LIGHT_POSITIONAL;
        l.position[0] = 1.2 + o;
        l.position[1] = -1.2 + o;
        l.position[2] = -2.0 + o;
        assert_true(rt_scene_add_light(sc, &l) >= 0);
    }
}

static int camera(rt_camera *cam, double off)
{
    /* eye at (0, -0.6, 2.5) + off looking down -z through the window [-1,1]^2 at n = off */
    rtu_view v = {.win = {-1 + off, 1 + off, -1.2 + off, 0.8 + off}, .prp = {off, -0.6 + off, 2.5 + off},
                  .vpd = off, .fpd = 1.0 + off, .bpd = -4.0 + off, .vp = {0, 1, 0, 1, 0, 1},
                  .perspective = 1};
    double m[4][4];
    rtu_view_matrix(&v, m);
    return rt_camera_from_view(cam, m, v.vp, W, H);
}

/* renders the case with light buffers lb (brute: no grid); the picture in rgb */
static void render(const lb_case *lc, int lb, int brute, int clip, float *rgb, rt_stats *st)
{
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    build(sc, lc);
    rt_build_options bo = {.brute_force = brute, .brute_threshold = brute ? 0 : -1};
    assert_int_equal(rt_scene_commit(sc, &bo), RT_OK);
    rt_camera cam;
    assert_int_equal(camera(&cam, lc->off), RT_OK);
    rt_render_options o;
    rt_render_options_default(&o);
    o.threads = 2;
    o.cutoff = 0.0;
    o.light_buffers = lb;
    o.clip_secondary = clip;
    memset(st, 0, sizeof *st);
    rtc_traps_on();
    assert_int_equal(rt_render(sc, &cam, &o, rgb, st), RT_OK);
    rtc_traps_off();
    assert_int_equal(rtc_nonfinite(rgb, (size_t)W * H * 3), 0);
    rt_scene_free(sc);
}

/* pixels differing by more than 1e-6 relative */
static size_t differ(const float *a, const float *b, double *maxd)
{
    size_t bad = 0;
    *maxd = 0.0;
    for (size_t i = 0; i < (size_t)W * H * 3; i++) {
        const double d = rtc_reldiff(a[i], b[i]);
        *maxd = d > *maxd ? d : *maxd;
        bad += d > 1e-6;
        if (d > 1e-6 && getenv("LBDBG"))
            printf("  pixel %zu %zu ch %zu: %.9g vs %.9g\n", (i / 3) % W, (i / 3) / W, i % 3, a[i], b[i]);
    }
    return bad;
}

/* on == off == brute force; the buffers answered at least min_share of the shadow rays (and
   at most max_share), the mirror buffers at least mirror_share of the reflection rays (0:
   none) */
static void check_case_m(const lb_case *lc, int clip, double min_share, double max_share,
                         double mirror_share)
{
    float *on = malloc(sizeof(float) * W * H * 3), *off = malloc(sizeof(float) * W * H * 3),
          *bf = malloc(sizeof(float) * W * H * 3);
    assert_true(on && off && bf);
    rt_stats s_on, s_off, s_bf;
    render(lc, 1, 0, clip, on, &s_on);
    render(lc, 0, 0, clip, off, &s_off);
    render(lc, 1, 1, clip, bf, &s_bf);
    double d1, d2;
    const size_t n1 = differ(on, off, &d1), n2 = differ(on, bf, &d2);
    const double share = (double)s_on.shadow_lbuf / (double)(s_on.shadow_lbuf + s_on.shadow_walks + 1);
    const double mshare = (double)s_on.reflection_mirror / (double)(s_on.reflection_rays + 1);
    printf("off %g lights %d clip %d tilted %d: shadow rays %llu, from buffers %.3f; reflection "
           "rays %llu, from mirrors %.3f; differ from walk %zu (max %.2g), from brute force %zu "
           "(max %.2g)\n",
           lc->off, lc->lights, clip, lc->tilted, (unsigned long long)s_on.shadow_rays, share,
           (unsigned long long)s_on.reflection_rays, mshare, n1, d1, n2, d2);
    assert_int_equal(n1, 0);
    assert_int_equal(n2, 0);
    assert_int_equal(s_off.shadow_lbuf, 0);
    assert_true(s_off.shadow_walks > 1000);
    assert_int_equal(s_bf.shadow_lbuf, 0);
    assert_true(s_on.shadow_rays == s_off.shadow_rays && s_on.shadow_rays > 1000);
    assert_true(share >= min_share && share <= max_share);
    assert_int_equal(s_off.reflection_mirror, 0);
    assert_int_equal(s_bf.reflection_mirror, 0);
    assert_true(s_on.reflection_rays == s_off.reflection_rays && s_on.reflection_rays > 1000);
    if (mirror_share > 0.0)
        assert_true(mshare >= mirror_share);
    else if (mirror_share == 0.0)
        assert_int_equal(s_on.reflection_mirror, 0);
    free(on);
    free(off);
    free(bf);
}

static void check_case(const lb_case *lc, int clip, double min_share, double max_share)
{
    check_case_m(lc, clip, min_share, max_share, -1.0);
}

static void test_kinds_and_lights(void **state)
{
    (void)state;
    const lb_case c0 = {.off = 0.0, .lights = 0};
    check_case_m(&c0, 0, 0.99, 1.0, 0.3);
    check_case_m(&c0, 1, 0.99, 1.0, 0.3); /* secondary rays clipped to the display volume */
}

static void test_light_inside(void **state)
{
    (void)state;
    const lb_case c = {.off = 0.0, .lights = 1}; /* 4 lights, the inside one walks */
    check_case(&c, 0, 0.5, 0.9);
}

static void test_translated_and_far(void **state)
{
    (void)state;
    const lb_case c1 = {.off = 1e6, .lights = 0};
    check_case_m(&c1, 0, 0.99, 1.0, 0.0); /* coordinates 1e6 times the extent: no mirrors */
    const lb_case c2 = {.off = 0.0, .lights = 2};
    check_case(&c2, 0, 0.99, 1.0);
}

/* the mirror buffers (rt_render.c, rt_job_mirrors): a floor of coplanar quads whose normals
   differ in their last bits, a quad just under it, a post through it */
static void test_mirror(void **state)
{
    (void)state;
    const lb_case c = {.off = 0.0, .lights = 0, .tilted = 1};
    check_case_m(&c, 0, 0.99, 1.0, 0.3);
    check_case_m(&c, 1, 0.99, 1.0, 0.3);
}

static void test_grazing_sphere(void **state)
{
    (void)state;
    const lb_case c = {.off = 0.0, .lights = 3, .sphere_only = 1};
    check_case(&c, 0, 0.99, 1.0);
}

/* SPD gears at 128x128 (corner rays, depth 5): glass, 144-gons, five positional lights */
/* the hit error bounds' parts kept with the records (rt_quad.vmax, rt_poly.uvmax, read by
   rt_hit_err per hit): the largest magnitude of the quad's coordinates and of the polygon's
   2-D bounds, as rt_absmax would find it */
static void check_hit_bounds(const rt_scene *sc)
{
    for (size_t k = 0; k < sc->nquad; k++) {
        double m = 0.0;
        for (int j = 0; j < 12; j++)
            m = fmax(m, fabs(sc->quad[k].v[j / 3][j % 3]));
        assert_true(sc->quad[k].vmax == m);
    }
    for (size_t k = 0; k < sc->npoly; k++) {
        const rt_poly *p = &sc->poly[k];
        const double m = fmax(fmax(fabs(p->umin), fabs(p->umax)), fmax(fabs(p->vmin), fabs(p->vmax)));
        assert_true(p->uvmax == m);
    }
}

static void test_gears(void **state)
{
    (void)state;
    rtu_mesh m;
    if (rtu_load_nff(RT_DATA_DIR "/spd/gears.nff.gz", &m) != 0) {
        fprintf(stderr, "gears.nff not found under %s\n", RT_DATA_DIR);
        fail();
    }
    double vo[4][4], bb[6];
    rtu_lookat(m.from, m.at, m.up, vo);
    rtu_mesh_transform(&m, vo);
    rtu_mesh_bbox(&m, bb);
    rtu_view v;
    rtu_nff_view(&m, bb, &v);
    double vm[4][4];
    rtu_view_matrix(&v, vm);
    rt_camera cam;
    assert_int_equal(rt_camera_from_view(&cam, vm, v.vp, 128, 128), RT_OK);
    float *pic[2];
    rt_stats st[2];
    for (int k = 0; k < 2; k++) {
        rt_scene *sc = rt_scene_new();
        rt_surface s;
        rt_surface_default(&s);
        assert_int_equal(rtu_mesh_add(&m, sc, rt_scene_add_surface(sc, &s)), 0);
        assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
        assert_true(sc->nquad > 0 && sc->npoly > 0);
        check_hit_bounds(sc);
        rt_render_options o;
        rt_render_options_default(&o);
        o.cutoff = 0.0;
        o.threads = 2;
        o.light_buffers = 1 - k;
        pic[k] = malloc(sizeof(float) * 128 * 128 * 3);
        assert_non_null(pic[k]);
        assert_int_equal(rt_render(sc, &cam, &o, pic[k], &st[k]), RT_OK);
        rt_scene_free(sc);
    }
    size_t bad = 0;
    double maxd = 0.0;
    for (size_t i = 0; i < 128 * 128 * 3; i++) {
        const double d = rtc_reldiff(pic[0][i], pic[1][i]);
        maxd = d > maxd ? d : maxd;
        bad += d > 1e-6;
    }
    const double share = (double)st[0].shadow_lbuf / (double)(st[0].shadow_lbuf + st[0].shadow_walks + 1);
    printf("gears: shadow rays %llu, from buffers %.4f, differ %zu (max %.2g)\n",
           (unsigned long long)st[0].shadow_rays, share, bad, maxd);
    assert_int_equal(bad, 0);
    assert_true(share > 0.99);
    assert_int_equal(rtc_nonfinite(pic[0], 128 * 128 * 3), 0);
    free(pic[0]);
    free(pic[1]);
    rtu_mesh_free(&m);
}

/* every light's buffer with 1, 2, 3 and 8 threads: equal, lists in (bucket, id) order;
   returns the buffers compared */
static int check_parts(const rt_scene *sc)
{
    int built = 0;
    for (int li = 0; li < sc->nlights; li++) {
        rt_lbuf one;
        assert_int_equal(rt_lbuf_build(sc, &sc->light[li], 1, &one), RT_OK);
        if (!one.ok)
            continue;
        built++;
        const size_t nc = (size_t)one.nu * (size_t)one.nv;
        assert_int_equal(one.off[0], 0);
        for (size_t c = 0; c < nc; c++) {
            assert_true(one.off[c] <= one.off[c + 1]);
            for (uint32_t k = one.off[c] + 1; k < one.off[c + 1]; k++) {
                const uint32_t a = one.ids[k - 1], b = one.ids[k];
                assert_true(one.zb[a] < one.zb[b] || (one.zb[a] == one.zb[b] && a < b));
            }
        }
        const int threads[3] = {2, 3, 8};
        for (int t = 0; t < 3; t++) {
            rt_lbuf par;
            assert_int_equal(rt_lbuf_build(sc, &sc->light[li], threads[t], &par), RT_OK);
            assert_true(par.ok && par.nu == one.nu && par.nv == one.nv);
            assert_memory_equal(par.off, one.off, (nc + 1) * sizeof(uint32_t));
            assert_memory_equal(par.ids, one.ids, (size_t)one.off[nc] * sizeof(uint32_t));
            assert_memory_equal(par.zb, one.zb, sc->nprim * sizeof(uint16_t));
            rt_lbuf_free(&par);
        }
        rt_lbuf_free(&one);
    }
    return built;
}

static void test_build_parts(void **state)
{
    (void)state;
    /* the fine sphere on the floor (about 2300 primitives: 3 parts at 8 threads) */
    const lb_case c = {.off = 0.0, .lights = 0, .sphere_only = 1};
    rt_scene *sc = rt_scene_new();
    assert_non_null(sc);
    build(sc, &c);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    assert_true(sc->nprim > 2 * 1024);
    assert_true(check_parts(sc) >= 2);
    rt_scene_free(sc);
    /* the gears: 144-gons with holes among triangles, five lights */
    rtu_mesh m;
    assert_int_equal(rtu_load_nff(RT_DATA_DIR "/spd/gears.nff.gz", &m), 0);
    sc = rt_scene_new();
    assert_non_null(sc);
    rt_surface s;
    rt_surface_default(&s);
    assert_int_equal(rtu_mesh_add(&m, sc, rt_scene_add_surface(sc, &s)), 0);
    assert_int_equal(rt_scene_commit(sc, NULL), RT_OK);
    printf("parts: gears %zu primitives, %d buffers\n", sc->nprim, check_parts(sc));
    rt_scene_free(sc);
    rtu_mesh_free(&m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kinds_and_lights),
        cmocka_unit_test(test_light_inside),
        cmocka_unit_test(test_translated_and_far),
        cmocka_unit_test(test_mirror),
        cmocka_unit_test(test_grazing_sphere),
        cmocka_unit_test(test_gears),
        cmocka_unit_test(test_build_parts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
