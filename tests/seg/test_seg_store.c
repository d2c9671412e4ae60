/* SPDX-License-Identifier: MIT */
/*
 * test_seg_store.c -- segment storage: what is appended comes back bit-identical, the
 * drawing order follows priority then creation, memory grows linearly with content, and a
 * failed allocation (301) leaves the segment unchanged.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <malloc.h>
#include <string.h>
#include <cmocka.h>
#include "gks_alloc.h"
#include "gks_seg_store.h"

static gks_seg_prim make_area(const Gpoint3 *pts, int n, const int *loops, int nl,
                              const gks_seg_bound *a)
{
    return (gks_seg_prim){ .kind = GKS_SEG_FILL_AREA_SET, .n_loops = nl, .loop_counts = loops,
                           .n_points = n, .pts = pts, .bound = a, .clip = 1,
                           .clip_box = { 0.1, 0.9, 0.2, 0.8, 0, 1 } };
}

static void test_round_trip(void **u)
{
    (void)u;
    gks_seg_store st;
    gks_seg_store_init(&st);
    gks_segment *s = gks_seg_create(&st, 7);
    assert_non_null(s);
    assert_ptr_equal(gks_seg_find(&st, 7), s);
    assert_null(gks_seg_find(&st, 8));
    assert_true(s->vis == 1 && s->highl == 0 && s->det == 0 && s->pri == 0.0);
    assert_true(s->tran[0][0] == 1 && s->tran[1][1] == 1 && s->tran[2][2] == 1 && s->tran[0][3] == 0);

    gks_seg_bound a1, a2;
    memset(&a1, 0, sizeof a1);
    a1.attrs.fill_colr_ind = 3;
    a1.norm[0][0] = a1.norm[1][1] = a1.norm[2][2] = 1;
    a2 = a1;
    a2.attrs.fill_colr_ind = 4;
    Gpoint3 sq[8] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
                      { .25, .25, .5 }, { .75, .25, .5 }, { .75, .75, .5 }, { .25, .75, .5 } };
    int loops[2] = { 4, 4 };
    gks_seg_prim p1 = make_area(sq, 8, loops, 2, &a1);
    gks_seg_prim p2 = make_area(sq, 4, loops, 1, &a1); /* same attributes: shared snapshot */
    int colr[6] = { 1, 2, 3, 4, 5, 6 };
    gks_seg_prim p3 = { .kind = GKS_SEG_CELL_ARRAY, .n_points = 0, .cell_p = { 0, 0, 0 },
                        .cell_q = { 1, 1, 0 }, .cell_r = { 1, 0, 0 }, .cell_nx = 3,
                        .cell_ny = 2, .cell_colr = colr, .bound = &a2 };
    gks_seg_prim p4 = { .kind = GKS_SEG_TEXT, .n_loops = 1, .n_points = 3, .pts = sq,
                        .str = "abc", .str_len = 3, .bound = &a2 };
    assert_int_equal(gks_seg_append(s, &p1), 0);
    assert_int_equal(gks_seg_append(s, &p2), 0);
    assert_int_equal(gks_seg_append(s, &p3), 0);
    assert_int_equal(gks_seg_append(s, &p4), 0);
    assert_int_equal(s->n_bound, 2);
    assert_int_equal(gks_seg_count(s), 4);

    gks_seg_prim q;
    gks_seg_get(s, 0, &q);
    assert_int_equal(q.kind, GKS_SEG_FILL_AREA_SET);
    assert_int_equal(q.n_loops, 2);
    assert_int_equal(q.loop_counts[0], 4);
    assert_int_equal(q.loop_counts[1], 4);
    assert_int_equal(q.n_points, 8);
    assert_memory_equal(q.pts, sq, sizeof sq);
    assert_int_equal(q.bound->attrs.fill_colr_ind, 3);
    assert_true(q.bound->norm[1][1] == 1);
    assert_int_equal(q.clip, 1);
    assert_true(q.clip_box[1] == 0.9 && q.clip_box[3] == 0.8);
    gks_seg_get(s, 1, &q);
    assert_int_equal(q.n_loops, 1);
    assert_int_equal(q.n_points, 4);
    gks_seg_get(s, 2, &q);
    assert_int_equal(q.kind, GKS_SEG_CELL_ARRAY);
    assert_int_equal(q.cell_nx, 3);
    assert_int_equal(q.cell_ny, 2);
    assert_memory_equal(q.cell_colr, colr, sizeof colr);
    assert_true(q.cell_r.x == 1 && q.cell_q.y == 1);
    assert_int_equal(q.bound->attrs.fill_colr_ind, 4);
    gks_seg_get(s, 3, &q);
    assert_int_equal(q.kind, GKS_SEG_TEXT);
    assert_int_equal(q.str_len, 3);
    assert_memory_equal(q.str, "abc", 3);
    assert_int_equal(q.n_points, 3);
    assert_null(q.loop_counts);

    gks_seg_delete(&st, 7);
    assert_null(gks_seg_find(&st, 7));
    gks_seg_store_free(&st);
}

static void test_draw_order(void **u)
{
    (void)u;
    gks_seg_store st;
    gks_seg_store_init(&st);
    const double pri[5] = { 0.5, 0.1, 0.5, 0.0, 1.0 };
    for (int i = 0; i < 5; i++) {
        gks_segment *s = gks_seg_create(&st, 10 + i);
        s->pri = pri[i];
        assert_int_equal(gks_seg_ws_add(s, 1), 0);
        assert_int_equal(gks_seg_ws_add(s, 1), 0); /* idempotent */
        if (i != 2)
            assert_int_equal(gks_seg_ws_add(s, 2), 0);
    }
    gks_segment *out[5];
    size_t n = gks_seg_draw_order(&st, 1, out);
    assert_int_equal(n, 5);
    const int want1[5] = { 13, 11, 10, 12, 14 };
    for (size_t i = 0; i < n; i++)
        assert_int_equal(out[i]->name, want1[i]);
    n = gks_seg_draw_order(&st, 2, out);
    assert_int_equal(n, 4);
    assert_int_equal(out[2]->name, 10);
    gks_seg_ws_remove(gks_seg_find(&st, 13), 1);
    assert_false(gks_seg_on_ws(gks_seg_find(&st, 13), 1));
    assert_true(gks_seg_on_ws(gks_seg_find(&st, 13), 2));
    assert_int_equal(gks_seg_draw_order(&st, 1, out), 4);
    assert_int_equal(gks_seg_draw_order(&st, 3, out), 0);
    gks_seg_delete(&st, 11);
    gks_seg_delete(&st, 999); /* absent: no-op */
    assert_int_equal(st.n, 4);
    gks_seg_store_free(&st);
}

/* Bytes the C library's heap holds (glibc: small chunks plus mmapped ones); 0 when it
 * cannot tell, e.g. under AddressSanitizer, which replaces malloc. */
static size_t heap_bytes(void)
{
    struct mallinfo2 mi = mallinfo2();
    return mi.uordblks + mi.hblkhd;
}

/* Bytes per stored point stay bounded as content grows (linear growth, doubling slack). */
static void test_linear_memory(void **u)
{
    (void)u;
    gks_seg_store st;
    gks_seg_store_init(&st);
    gks_segment *s = gks_seg_create(&st, 1);
    gks_seg_bound a;
    memset(&a, 0, sizeof a);
    Gpoint3 tri[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    int one = 3;
    gks_seg_prim p = make_area(tri, 3, &one, 1, &a);
    size_t per_prim_max = 0, base = heap_bytes();
    for (int k = 1; k <= 100000; k++) {
        assert_int_equal(gks_seg_append(s, &p), 0);
        if (k == 1000 || k == 10000 || k == 100000) {
            size_t now = heap_bytes(), per = now > base ? (now - base) / (size_t)k : 0;
            if (per > per_prim_max)
                per_prim_max = per;
        }
    }
    assert_int_equal(s->n_bound, 1);
    gks_seg_store_free(&st);
    if (per_prim_max == 0)
        skip(); /* no growth seen: this heap is not measurable (AddressSanitizer's) */
    /* record + 3 points + 1 loop count, at most doubled by the growth slack */
    size_t exact = sizeof(Gpoint3) * 3 + sizeof(int) + 2 * sizeof(size_t) * 4 + 100;
    assert_true(per_prim_max <= 2 * exact + 64);
}

/* An allocation failure leaves the segment exactly as it was. */
static void test_overflow(void **u)
{
    (void)u;
    gks_seg_store st;
    gks_seg_store_init(&st);
    gks_segment *s = gks_seg_create(&st, 1);
    gks_seg_bound a;
    memset(&a, 0, sizeof a);
    Gpoint3 tri[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    int one = 3;
    gks_seg_prim p = make_area(tri, 3, &one, 1, &a);
    assert_int_equal(gks_seg_append(s, &p), 0);
    int n_failed = 0;
    for (long k = 1; k <= 4; k++) {
        gks_seg_bound b = a;
        b.attrs.fill_colr_ind = (int)k; /* a new snapshot is needed each time */
        p.bound = &b;
        /* force growth of every pool: make the k-th allocation fail */
        for (int fill = 0; fill < 2000; fill++) {
            if (s->n_rec == s->cap_rec || s->n_pts + 3 > s->cap_pts)
                break;
            assert_int_equal(gks_seg_append(s, &p), 0);
        }
        size_t n_rec = s->n_rec, n_pts = s->n_pts, n_attrs = s->n_bound;
        gks_alloc_fail_after(k);
        int e = gks_seg_append(s, &p);
        gks_alloc_fail_after(0);
        if (e) {
            n_failed++;
            assert_int_equal(e, 301);
            assert_int_equal(s->n_rec, n_rec);
            assert_int_equal(s->n_pts, n_pts);
            assert_int_equal(s->n_bound, n_attrs);
        }
    }
    assert_true(n_failed >= 1);
    assert_null(gks_seg_find(&st, 2));
    gks_alloc_fail_after(1);
    assert_null(gks_seg_create(&st, 2));
    gks_alloc_fail_after(0);
    gks_seg_store_free(&st);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip), cmocka_unit_test(test_draw_order),
        cmocka_unit_test(test_linear_memory), cmocka_unit_test(test_overflow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
