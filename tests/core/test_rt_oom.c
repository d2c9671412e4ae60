/* SPDX-License-Identifier: MIT */
/*
 * test_rt_oom.c -- every allocation of a ray-traced frame fails in turn, the tracer's
 * (src/rt/rt_alloc.c) among them: the test build sends those through the library's
 * failure injection (gks_alloc_fail_after, src/c/base/gks_alloc.c). A ray-traced PNG
 * workstation (opened before the failures start) records a lit, shadowed height field of FILL AREA 3 quads, a triangle above
 * them, a small QUADRILATERAL MESH 3 WITH DATA (kept whole: the driver's mesh entry and the
 * tracer's indexed mesh) and a cell array and traces them at CLOSE WORKSTATION. For each n the nth allocation
 * fails: the only error reported is 300 (storage overflow), or none and the picture is
 * byte for byte the one without failures (a failure absorbed by a fallback); nothing
 * crashes, GKS can be closed, and (in the AddressSanitizer build) nothing leaks. Prints
 * the counts.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <cmocka.h>
#include "core_util.h"
#include "gks_alloc.h"

/* src/rt/rt_alloc.c, test build only: the tracer's allocations, and its injected failures */
long rt_alloc_count(void);
long rt_alloc_injected(void);

static const Glimit unit_win = { 0, 1, 0, 1 };
static const Glimit vp32 = { 0, 32, 0, 32 };

enum { GRID = 6 };

/* The bytes of a file (caller frees), NULL if it cannot be read. */
static unsigned char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    unsigned char *b = NULL;
    size_t n = 0, cap = 0, got;
    do {
        if (n == cap) {
            unsigned char *nb = realloc(b, cap = cap ? 2 * cap : 4096);
            if (!nb) {
                free(b);
                fclose(f);
                return NULL;
            }
            b = nb;
        }
        got = fread(b + n, 1, cap - n, f);
        n += got;
    } while (got > 0);
    fclose(f);
    *len = n;
    return b;
}

static double height(int i, int j)
{
    return 0.3 + 0.1 * sin(i * 0.9) * cos(j * 0.7);
}

/* The workstation of a frame, opened before failures are injected. */
static void open_frame(void)
{
    const char *file = "t_rt_oom.png";
    unlink(file);
    capture_reset();
    gopen_ws(1, file, GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_win(1, &unit_win);
    gset_ws_vp(1, &vp32);
    gset_hlhsr_mode(1, GHLHSR_RAYTRACE);
    Gint ints[2] = { 1, 2 }; /* two threads: the pool's allocations too */
    Gescape_in_data in = { .num_ints = 2, .ints = ints };
    gescape(GESC_RT_THREADS, &in, NULL, NULL);
}

/* The frame's output and its trace at CLOSE WORKSTATION; errors go to capture_handler. */
static void draw_frame(void)
{
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0.3, -0.5, -0.8 },
                         { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
    Gcolr_rep cr = { { 0.8, 0.6, 0.4 } };
    gset_colr_rep(1, 2, &cr);
    gset_fill_colr_ind(2);
    gset_fill_int_style(GSTYLE_SOLID);
    Garea_props pr = { 0, 1, 0, { 1, 1, 1 }, 1, 0, 1 };
    gset_area_props(&pr);
    gset_refl_eq(GREFL_AMB_DIFF);
    Gint on = 2;
    Gint_list a = { 1, &on };
    gset_light_src_state(&a, NULL);
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            double x0 = 0.1 + 0.8 * i / GRID, x1 = 0.1 + 0.8 * (i + 1) / GRID;
            double y0 = 0.1 + 0.8 * j / GRID, y1 = 0.1 + 0.8 * (j + 1) / GRID;
            Gpoint3 p[4] = { { x0, y0, height(i, j) }, { x1, y0, height(i + 1, j) },
                             { x1, y1, height(i + 1, j + 1) }, { x0, y1, height(i, j + 1) } };
            Gpoint_list3 q = { 4, p };
            gfill_area3(&q);
        }
    Gpoint3 blocker[3] = { { 0.3, 0.3, 0.7 }, { 0.6, 0.35, 0.7 }, { 0.4, 0.6, 0.7 } };
    Gpoint_list3 t = { 3, blocker };
    gfill_area3(&t);
    /* a smooth QUADRILATERAL MESH 3 WITH DATA, kept whole for the tracer (ws_rt_record_mesh,
     * rt_scene_mesh_begin): its allocations too */
    Gpoint3 mp[9];
    Gvec3 mn[9];
    for (int k = 0; k < 9; k++) {
        mp[k] = (Gpoint3){ 0.6 + 0.15 * (k % 3), 0.05 + 0.1 * (k / 3), 0.25 + 0.02 * (k % 2) };
        mn[k] = (Gvec3){ 0.1 * (k % 3) - 0.1, 0.05 * (k / 3), 1 };
    }
    gset_int_shad_meth(GSHAD_NORM);
    Gint_size dim = { 3, 3 };
    Gfacet_vdata3 vd = { 9, mp, NULL, mn };
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD_NORM, GCOLR_INDIRECT, &dim, NULL, &vd);
    Gint cells[4] = { 1, 2, 2, 1 };
    Gpat_rep cols = { { 2, 2 }, cells };
    Gparal par = { { 0.05, 0.05, 0.2 }, { 0.25, 0.25, 0.2 }, { 0.25, 0.05, 0.2 } };
    gcell_array3(&par, &cols);
    gdeactivate_ws(1);
    gclose_ws(1);
}

static void test_each_allocation_fails(void **u)
{
    (void)u;
    reset_gks();
    gopen_gks(NULL, 0);
    open_frame();
    long c0 = gks_alloc_count(), r0 = rt_alloc_count();
    draw_frame();
    long used = gks_alloc_count() - c0, rt_used = rt_alloc_count() - r0;
    gclose_gks();
    if (n_captured)
        fail_msg("the frame without failures: error %d in function %d", captured[0].err,
                 captured[0].fct);
    size_t ref_len;
    unsigned char *ref = slurp("t_rt_oom.png", &ref_len);
    assert_non_null(ref);
    assert_true(rt_used > 10);
    long reported = 0, rt_failed = 0, rt_reported = 0, absorbed = 0;
    for (long n = 1; n <= used + 1; n++) {
        reset_gks();
        gopen_gks(NULL, 0);
        open_frame();
        n_captured = 0;
        long rb = rt_alloc_injected();
        gks_alloc_fail_after(n);
        draw_frame();
        int in_tracer = rt_alloc_injected() > rb; /* the nth allocation was the tracer's */
        gks_alloc_fail_after(0);
        for (int k = 0; k < n_captured && k < MAX_CAPTURED; k++)
            if (captured[k].err != 300)
                fail_msg("allocation %ld failed: error %d in function %d, want 300", n,
                         captured[k].err, captured[k].fct);
        reported += n_captured > 0;
        gclose_gks();
        if (!n_captured) { /* absorbed: the same picture by another way */
            size_t len;
            unsigned char *pic = slurp("t_rt_oom.png", &len);
            if (!pic || len != ref_len || memcmp(pic, ref, len) != 0)
                fail_msg("allocation %ld failed, no error reported and another picture", n);
            free(pic);
            absorbed += n <= used; /* n = used + 1 fails nothing */
        }
        rt_failed += in_tracer;
        rt_reported += in_tracer && n_captured > 0;
    }
    reset_gks();
    free(ref);
    /* A few failures are absorbed by design and give the same picture: the recording
     * queue (rt_serial_new) falls back to recording at the call, the coverage pass
     * (rt_cover) to the tracer without candidate lists, the depth order of the eye rays'
     * candidate lists (three arrays) to the lists in primitive order, the second level's
     * reservation per build part to growing as it goes, the shrink of its 2-byte
     * offsets (rt_big_shrink) to keeping the larger block, and the PNG workstation's 8-bit
     * copy of the picture and its row flags (resolved on the pool, ws_png.c) to resolving
     * the rows one by one as before, and the block of a mesh's sort into spatial order
     * (rt_scene_mesh_end) to the given order. The counts say how many. */
    printf("RT_OOM: %ld allocations per frame (%ld of them the tracer's), each failed in turn: "
           "%ld reported 300, %ld absorbed with the same picture; of the %ld tracer "
           "allocations failed %ld reported 300; no other error\n",
           used, rt_used, reported, absorbed, rt_failed, rt_reported);
    assert_true(rt_failed >= rt_used);
    assert_int_equal(reported + absorbed, used);
    assert_true(absorbed <= 12);
    unlink("t_rt_oom.png");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_each_allocation_fails),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
