/* SPDX-License-Identifier: MIT */
/*
 * test_rt_tiles.c -- the tile-distribution hook of rt_render (rt_render_options.tiles,
 * rt_frame_store): a frame split between two "processes" (two rt_render calls, one tracing
 * some tiles and handing their payloads on, the other tracing the rest and storing the
 * first one's payloads) is bit-identical to the frame traced in one call, with the same ray
 * counts, for corner rays and jittered samples and any thread counts; failing callbacks
 * stop the render with RT_ERR_HOOK (end still called); bad stores are refused.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "gksrt.h"
#include "rt_testutil.h"

#define W 70
#define H 50
#define MAXT 64

/* one simulated process: the tiles it traces (mine[t]), payloads it hands on */
typedef struct proc {
    int ntiles, next;
    size_t max_bytes;
    const unsigned char *mine;
    unsigned char *payload[MAXT]; /* handed on by done */
    size_t bytes[MAXT];
    struct proc *from;            /* its payloads are stored in begin (assembler) */
    int assemble;                 /* end's answer */
    int fail_next, fail_done;     /* inject: next returns -5 / done returns -1 at this call */
    int calls, ends, traced;
} proc;

static int p_begin(void *u, rt_frame *f, int ntiles, size_t max_bytes)
{
    proc *p = u;
    assert_true(ntiles <= MAXT);
    p->ntiles = ntiles;
    p->max_bytes = max_bytes;
    p->next = 0;
    if (p->from)
        for (int t = 0; t < ntiles; t++)
            if (p->from->payload[t])
                assert_int_equal(rt_frame_store(f, t, p->from->payload[t], p->from->bytes[t]),
                                 RT_OK);
    return 0;
}

static int p_next(void *u)
{
    proc *p = u;
    if (++p->calls == p->fail_next)
        return -5;
    while (p->next < p->ntiles && !p->mine[p->next])
        p->next++;
    return p->next < p->ntiles ? p->next++ : -1;
}

static int p_done(void *u, int tile, const void *payload, size_t bytes)
{
    proc *p = u;
    assert_true(tile >= 0 && tile < p->ntiles && p->mine[tile]);
    assert_true(bytes <= p->max_bytes && !p->payload[tile]);
    p->traced++;
    if (p->traced == p->fail_done)
        return -1;
    p->payload[tile] = malloc(bytes);
    memcpy(p->payload[tile], payload, bytes);
    p->bytes[tile] = bytes;
    return 0;
}

static int p_end(void *u, rt_frame *f)
{
    proc *p = u;
    (void)f;
    p->ends++;
    return p->assemble;
}

static void proc_free(proc *p)
{
    for (int t = 0; t < MAXT; t++)
        free(p->payload[t]);
}

static rt_scene *mount(rt_camera *cam)
{
    rt_scene *sc = rtu_nff_scene(RT_DATA_DIR "/spd/mount-tessellated.nff.gz", 0, W, H, cam);
    assert_non_null(sc);
    return sc;
}

static rt_tile_hook hook_of(proc *p)
{
    return (rt_tile_hook){ .user = p, .begin = p_begin, .next = p_next, .done = p_done,
                           .end = p_end };
}

/* splits the frame by split(t) (1: process A) and checks it against one call */
static void check_split(const rt_scene *sc, const rt_camera *cam, rt_render_options o,
                        int (*split)(int), int ta, int tb)
{
    enum { N = W * H * 3 };
    float *ref = malloc(N * sizeof(float)), *a = malloc(N * sizeof(float)),
          *b = malloc(N * sizeof(float));
    rt_stats sr, sa, sb;
    o.threads = 2;
    assert_int_equal(rt_render(sc, cam, &o, ref, &sr), RT_OK);
    unsigned char ma[MAXT], mb[MAXT];
    for (int t = 0; t < MAXT; t++) {
        ma[t] = (unsigned char)split(t);
        mb[t] = !ma[t];
    }
    proc pa = { .mine = ma, .assemble = 0 }, pb = { .mine = mb, .from = &pa, .assemble = 1 };
    rt_tile_hook ha = hook_of(&pa), hb = hook_of(&pb);
    o.tiles = &ha;
    o.threads = ta;
    assert_int_equal(rt_render(sc, cam, &o, a, &sa), RT_OK);
    o.tiles = &hb;
    o.threads = tb;
    assert_int_equal(rt_render(sc, cam, &o, b, &sb), RT_OK);
    assert_true(pa.traced > 0 && pb.traced > 0);
    assert_int_equal(pa.traced + pb.traced, pa.ntiles);
    assert_int_equal(pa.ends, 1);
    assert_int_equal(pb.ends, 1);
    assert_memory_equal(ref, b, N * sizeof(float));
    /* the assembler's counters are those of all tiles; A's those of its own */
    assert_int_equal(sb.eye_rays, sr.eye_rays);
    assert_int_equal(sb.eye_hits, sr.eye_hits);
    assert_int_equal(sb.shadow_rays, sr.shadow_rays);
    assert_int_equal(sb.reflection_rays, sr.reflection_rays);
    assert_int_equal(sb.refraction_rays, sr.refraction_rays);
    assert_true(sa.eye_rays > 0 && sa.eye_rays < sr.eye_rays);
    proc_free(&pa);
    proc_free(&pb);
    free(ref);
    free(a);
    free(b);
}

static int odd(int t) { return t & 1; }
static int low(int t) { return t < 7; }

static void test_split_identical(void **state)
{
    (void)state;
    rt_camera cam;
    rt_scene *sc = mount(&cam);
    rt_render_options o;
    rt_render_options_default(&o); /* corner rays: tiles of the (W+1) x (H+1) ray grid */
    check_split(sc, &cam, o, odd, 3, 1);
    check_split(sc, &cam, o, low, 1, 2);
    o.corner_rays = 0;
    o.samples = 4;
    o.jitter = 1;
    check_split(sc, &cam, o, odd, 2, 3);
    o.samples = 1;
    o.jitter = 0; /* one ray per pixel centre: the culled path */
    check_split(sc, &cam, o, low, 1, 1);
    rt_scene_free(sc);
}

static void test_hook_failures(void **state)
{
    (void)state;
    rt_camera cam;
    rt_scene *sc = mount(&cam);
    rt_render_options o;
    rt_render_options_default(&o);
    float *rgb = malloc(W * H * 3 * sizeof(float));
    unsigned char m[MAXT];
    memset(m, 1, sizeof m);
    for (int threads = 1; threads <= 3; threads += 2) {
        o.threads = threads;
        proc p = { .mine = m, .assemble = 1, .fail_next = 3 };
        rt_tile_hook h = hook_of(&p);
        o.tiles = &h;
        assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_ERR_HOOK);
        assert_int_equal(p.ends, 1);
        proc_free(&p);
        proc q = { .mine = m, .assemble = 1, .fail_done = 2 };
        h = hook_of(&q);
        assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_ERR_HOOK);
        assert_int_equal(q.ends, 1);
        proc_free(&q);
        proc e = { .mine = m, .assemble = -1 }; /* end fails */
        h = hook_of(&e);
        assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_ERR_HOOK);
        proc_free(&e);
    }
    /* a hook without next or done is refused */
    rt_tile_hook bad = { .next = p_next };
    o.tiles = &bad;
    assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_ERR_ARG);
    rt_scene_free(sc);
    free(rgb);
}

/* stores with a wrong size or tile are refused and change nothing */
static proc *store_src;
static int bad_begin(void *u, rt_frame *f, int ntiles, size_t max_bytes)
{
    ((proc *)u)->max_bytes = max_bytes;
    const unsigned char *pl = store_src->payload[0];
    size_t n = store_src->bytes[0];
    assert_int_equal(n, max_bytes);
    assert_int_equal(rt_frame_store(f, 0, pl, n - 4), RT_ERR_ARG);
    assert_int_equal(rt_frame_store(f, 0, pl, n + 4), RT_ERR_ARG);
    assert_int_equal(rt_frame_store(f, -1, pl, n), RT_ERR_ARG);
    assert_int_equal(rt_frame_store(f, ntiles, pl, n), RT_ERR_ARG);
    assert_int_equal(rt_frame_store(f, 0, NULL, n), RT_ERR_ARG);
    assert_int_equal(rt_frame_store(NULL, 0, pl, n), RT_ERR_ARG);
    /* the last tile is smaller (70 + 1 corners: 7 columns; 51 rows: 3 rows) */
    assert_int_equal(rt_frame_store(f, ntiles - 1, pl, n), RT_ERR_ARG);
    return 0;
}

static void test_store_checks(void **state)
{
    (void)state;
    rt_camera cam;
    rt_scene *sc = mount(&cam);
    rt_render_options o;
    rt_render_options_default(&o);
    float *rgb = malloc(W * H * 3 * sizeof(float));
    unsigned char m[MAXT];
    memset(m, 1, sizeof m);
    proc p = { .mine = m, .assemble = 1 };
    rt_tile_hook h = hook_of(&p);
    o.tiles = &h;
    assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_OK);
    assert_int_equal(p.ntiles, 5 * 4);
    store_src = &p;
    rt_tile_hook hb = { .begin = bad_begin, .next = p_next, .done = p_done, .end = p_end };
    proc q = { .mine = m, .assemble = 1 };
    hb.user = &q;
    q.ntiles = p.ntiles;
    o.tiles = &hb;
    assert_int_equal(rt_render(sc, &cam, &o, rgb, NULL), RT_OK);
    proc_free(&p);
    proc_free(&q);
    rt_scene_free(sc);
    free(rgb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_split_identical),
        cmocka_unit_test(test_hook_failures),
        cmocka_unit_test(test_store_checks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
