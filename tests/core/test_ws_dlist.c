/* SPDX-License-Identifier: MIT */
/*
 * test_ws_dlist.c -- the render layer's display list (src/c/ws/render/ws_dlist.h): records
 * with their vertices, per-vertex data, counts and indices read back as written; equal
 * consecutive attributes stored once (by their bytes or by the caller's key); chunks that
 * never move once written, sealed to the sink in order; released chunks freed, those a
 * reader still keeps not (two readers on one list, each reading and counting its own
 * records); a record larger than a chunk in a chunk of its own; the last record taken
 * back; counts out of range refused; and every allocation of a workload failed in turn
 * (gks_alloc_fail_after): 300 and the list as before the failing call. And gks_populate,
 * with which a new chunk's pages are made present: contents kept, no fault left to take.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>
#include "gks_alloc.h"
#include "ws_dlist.h"

typedef struct attr {
    double colour[3];
    int style;
} attr;

/* Appends a polygon record of n vertices (one loop, vertex i at (base + i, 2 (base + i),
 * -i)) with attributes a; returns the result of ws_dlist_append. */
static int add_poly(ws_dlist *dl, int view, const attr *a, size_t n, double base)
{
    ws_dl_put p;
    const ws_dl_need need = { .n_vtx = n, .n_loops = 1 };
    int e = ws_dlist_append(dl, WS_DL_TRACER, 7, view, a, sizeof *a, &need, &p);
    if (e)
        return e;
    for (size_t i = 0; i < n; i++) {
        p.xyz[3 * i] = base + (double)i;
        p.xyz[3 * i + 1] = 2 * (base + (double)i);
        p.xyz[3 * i + 2] = -(double)i;
    }
    p.loops[0] = (int)n;
    return 0;
}

/* Checks record r of chunk c against add_poly(.., n, base). */
static void check_poly(const ws_dl_chunk *c, const ws_dl_rec *r, size_t n, double base)
{
    assert_int_equal(r->kind, 7);
    assert_int_equal(r->n_vtx, n);
    assert_int_equal(r->n_facets, 0);
    assert_int_equal(r->n_loops, 1);
    assert_int_equal(c->cnt[r->cnt], (int)n);
    assert_int_equal(r->n_idx, 0);
    for (size_t i = 0; i < n; i++) {
        const double *v = c->xyz + 3 * (r->vtx + i);
        assert_true(v[0] == base + (double)i && v[1] == 2 * (base + (double)i) &&
                    v[2] == -(double)i);
    }
}

static void test_empty(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    assert_non_null(dl);
    assert_null(ws_dlist_first(dl));
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 0);
    ws_dlist_seal(dl); /* nothing to seal */
    ws_dlist_unappend(dl); /* nothing to take back */
    assert_null(ws_dlist_first(dl));
    ws_dlist_free(dl);
    ws_dlist_free(NULL);
}

static void test_records_and_attributes(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    const attr a = { { 1, 0.5, 0 }, 2 }, b = { { 0, 0, 1 }, 2 };
    assert_int_equal(add_poly(dl, 3, &a, 4, 10), 0);
    assert_int_equal(add_poly(dl, 3, &a, 3, 20), 0);
    assert_int_equal(add_poly(dl, 5, &b, 5, 30), 0);
    assert_int_equal(add_poly(dl, 5, &a, 3, 40), 0);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 4);
    const ws_dl_chunk *c = ws_dlist_first(dl);
    assert_non_null(c);
    assert_null(c->next);
    assert_int_equal(c->n_rec, 4);
    check_poly(c, &c->rec[0], 4, 10);
    check_poly(c, &c->rec[1], 3, 20);
    check_poly(c, &c->rec[2], 5, 30);
    check_poly(c, &c->rec[3], 3, 40);
    assert_int_equal(c->rec[0].view, 3);
    assert_int_equal(c->rec[2].view, 5);
    /* equal consecutive attributes are stored once, a change is a new copy */
    assert_int_equal(c->rec[0].attr, c->rec[1].attr);
    assert_int_not_equal(c->rec[1].attr, c->rec[2].attr);
    assert_int_not_equal(c->rec[2].attr, c->rec[3].attr);
    assert_int_equal(c->rec[0].attr % 8, 0);
    assert_memory_equal(c->attr + c->rec[2].attr, &b, sizeof b);
    assert_memory_equal(c->attr + c->rec[3].attr, &a, sizeof a);
    assert_int_equal(c->n_attr, 3 * ((sizeof a + 7) / 8 * 8));
    assert_int_equal(c->rec[0].data_size, 0);
    /* own data does not break the sharing of attributes */
    ws_dl_put p;
    const ws_dl_need nd = { .n_vtx = 1, .data_size = 4 };
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 8, 5, &a, sizeof a, &nd, &p), 0);
    memcpy(p.data, "abc", 4);
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 8, 5, &a, sizeof a, &nd, &p), 0);
    memcpy(p.data, "xyz", 4);
    assert_int_equal(c->rec[4].attr, c->rec[5].attr);
    assert_int_not_equal(c->rec[4].data, c->rec[5].data);
    assert_string_equal((const char *)c->attr + c->rec[4].data, "abc");
    assert_string_equal((const char *)c->attr + c->rec[5].data, "xyz");
    /* a new frame */
    ws_dlist_reset(dl);
    assert_null(ws_dlist_first(dl));
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 0);
    assert_int_equal(ws_dlist_bytes(dl), 0);
    assert_int_equal(add_poly(dl, 0, &a, 3, 1), 0);
    check_poly(ws_dlist_first(dl), &ws_dlist_first(dl)->rec[0], 3, 1);
    ws_dlist_free(dl);
}

/* A mesh: shared vertices once, normals and colours per vertex, facets as index lists. */
static void test_mesh(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    const attr a = { { 1, 1, 1 }, 0 };
    ws_dl_put p;
    const ws_dl_need need = { .n_vtx = 4, .flags = WS_DL_NORMALS | WS_DL_COLOURS,
                              .n_facets = 2, .n_loops = 2, .n_idx = 6,
                              .data_size = sizeof(double) + 1 };
    assert_int_equal(add_poly(dl, 1, &a, 3, 0), 0); /* without data before it */
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 9, 1, &a, sizeof a, &need, &p), 0);
    assert_non_null(p.nrm);
    assert_non_null(p.rgb);
    assert_non_null(p.idx);
    for (int i = 0; i < 12; i++) {
        p.xyz[i] = i;
        p.nrm[i] = 100 + i;
        p.rgb[i] = 200 + i;
    }
    assert_non_null(p.data);
    const double key = 0.125;
    memcpy(p.data, &key, sizeof key);
    ((unsigned char *)p.data)[sizeof key] = 77;
    p.facets[0] = p.facets[1] = 1;
    p.loops[0] = p.loops[1] = 3;
    const uint32_t ix[6] = { 0, 1, 2, 0, 2, 3 };
    memcpy(p.idx, ix, sizeof ix);
    /* the first chunk had no room for normals, colours and indices: the mesh is in the
     * next one, which has (and the chunks after it will have) */
    const ws_dl_chunk *c0 = ws_dlist_first(dl), *c = c0->next;
    assert_non_null(c);
    assert_int_equal(c0->n_rec, 1);
    const ws_dl_rec *r = &c->rec[0];
    assert_int_equal(r->flags, WS_DL_NORMALS | WS_DL_COLOURS);
    assert_int_equal(r->n_idx, 6);
    assert_memory_equal(c->idx + r->idx, ix, sizeof ix);
    /* the record's own data, aligned, after its attributes */
    assert_int_equal(r->data_size, sizeof(double) + 1);
    assert_int_equal(r->data % 8, 0);
    assert_true(r->data >= r->attr + sizeof a);
    assert_memory_equal(c->attr + r->data, &key, sizeof key);
    assert_int_equal(c->attr[r->data + sizeof key], 77);
    assert_int_equal(c->cnt[r->cnt], 1);
    assert_int_equal(c->cnt[r->cnt + 2], 3);
    for (int i = 0; i < 12; i++) {
        assert_true(c->xyz[3 * (size_t)r->vtx + (size_t)i] == i);
        assert_true(c->nrm[3 * (size_t)r->vtx + (size_t)i] == 100 + i);
        assert_true(c->rgb[3 * (size_t)r->vtx + (size_t)i] == 200 + i);
    }
    check_poly(c0, &c0->rec[0], 3, 0); /* untouched */
    assert_true(c->cap[2] >= 8192 && c->cap[3] >= 8192 && c->cap[5] >= 16384);
    /* a record without normals, then one with: its normals at its vertices' index */
    assert_int_equal(add_poly(dl, 1, &a, 5, 0), 0);
    const ws_dl_need nn = { .n_vtx = 2, .flags = WS_DL_NORMALS, .n_loops = 1 };
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 9, 1, &a, sizeof a, &nn, &p), 0);
    const ws_dl_rec *r2 = &c->rec[c->n_rec - 1];
    assert_int_equal(r2->vtx, 4 + 5);
    assert_ptr_equal(p.nrm, c->nrm + 3 * (size_t)r2->vtx);
    assert_null(p.rgb);
    assert_int_equal(c->n_nrm, c->n_xyz);
    assert_int_equal(sizeof(ws_dl_rec), 48);
    ws_dlist_free(dl);
}

/* The sink's view: the chunks in order, each with its records at that time. */
typedef struct sink_log {
    const ws_dl_chunk *chunk[64];
    size_t n_rec[64];
    int n;
} sink_log;

static void sink(void *user, ws_dl_chunk *c)
{
    sink_log *l = user;
    assert_true(c->sealed);
    assert_true(l->n < 64);
    l->chunk[l->n] = c;
    l->n_rec[l->n++] = c->n_rec;
}

static void test_chunks_and_sink(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    sink_log log = { .n = 0 };
    ws_dlist_set_sink(dl, sink, &log);
    const attr a = { { 0.25, 0.5, 0.75 }, 1 };
    enum { N = 6000 };
    assert_int_equal(add_poly(dl, 0, &a, 5, 0), 0);
    const ws_dl_chunk *c0 = ws_dlist_first(dl);
    const double *xyz0 = c0->xyz;
    for (int k = 1; k < N; k++)
        assert_int_equal(add_poly(dl, 0, &a, 5, 10.0 * k), 0);
    /* a record larger than a chunk: a chunk of its own */
    assert_int_equal(add_poly(dl, 0, &a, 100000, -1), 0);
    assert_int_equal(add_poly(dl, 0, &a, 3, 5), 0);
    ws_dlist_seal(dl);
    ws_dlist_seal(dl); /* twice: once to the sink */
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), N + 2);
    assert_true(log.n >= 3);
    /* the sink saw every chunk, in order, complete; the first one never moved */
    assert_ptr_equal(log.chunk[0], c0);
    assert_ptr_equal(c0->xyz, xyz0);
    size_t k = 0;
    int i = 0;
    for (const ws_dl_chunk *c = ws_dlist_first(dl); c; c = c->next, i++) {
        assert_ptr_equal(log.chunk[i], c);
        assert_int_equal(log.n_rec[i], c->n_rec);
        assert_true(c->n_xyz <= c->cap[1]);
        for (size_t j = 0; j < c->n_rec; j++, k++) {
            if (k < N)
                check_poly(c, &c->rec[j], 5, 10.0 * (double)k);
            else if (k == N)
                check_poly(c, &c->rec[j], 100000, -1);
            else
                check_poly(c, &c->rec[j], 3, 5);
        }
    }
    assert_int_equal(i, log.n);
    assert_int_equal(k, N + 2);
    assert_true(ws_dlist_bytes(dl) >= (size_t)(N * 5 + 100003) * 3 * sizeof(double));
    /* a record after the seal starts a new chunk */
    assert_int_equal(add_poly(dl, 0, &a, 3, 7), 0);
    assert_int_equal(log.n, i);
    ws_dlist_free(dl);
}

/* A streaming reader releases each chunk it has read: the list frees the released chunks,
 * wherever they are, when it makes a new chunk or at ws_dlist_trim, never one still being
 * read. */
static void release_sink(void *user, ws_dl_chunk *c)
{
    sink_log *l = user;
    sink(user, c);
    if (l->n % 2) /* every other chunk is released at once, the others at the end */
        ws_dlist_release(c, WS_DL_TRACER);
}

/* A streaming reader that releases every chunk at once. */
static void release_all_sink(void *user, ws_dl_chunk *c)
{
    sink(user, c);
    ws_dlist_release(c, WS_DL_TRACER);
}

static void test_release(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    sink_log log = { .n = 0 };
    ws_dlist_set_sink(dl, release_sink, &log);
    const attr a = { { 0.5, 0.5, 0.5 }, 4 };
    for (int k = 0; k < 10000; k++)
        assert_int_equal(add_poly(dl, 1, &a, 4, k), 0);
    assert_true(log.n >= 4);
    /* the first and third chunks were released at once, the second is not: they are freed,
     * the second stays */
    assert_ptr_equal(ws_dlist_first(dl), log.chunk[1]);
    assert_ptr_equal(ws_dlist_first(dl)->next, log.chunk[3]);
    const size_t held = ws_dlist_bytes(dl);
    for (int i = 1; i < log.n; i += 2)
        ws_dlist_release((ws_dl_chunk *)log.chunk[i], WS_DL_TRACER);
    ws_dlist_trim(dl);
    assert_true(ws_dlist_bytes(dl) < held);
    ws_dlist_seal(dl);
    ws_dlist_release((ws_dl_chunk *)log.chunk[log.n - 1], WS_DL_TRACER);
    ws_dlist_trim(dl);
    assert_null(ws_dlist_first(dl));
    assert_int_equal(ws_dlist_bytes(dl), 0);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 10000);
    /* appending goes on in a new chunk */
    assert_int_equal(add_poly(dl, 1, &a, 3, 9), 0);
    check_poly(ws_dlist_first(dl), &ws_dlist_first(dl)->rec[0], 3, 9);
    ws_dlist_free(dl);
}

/* Appends a classic record (kind 3) of one vertex and n bytes of data. */
static int add_classic(ws_dlist *dl, size_t n)
{
    ws_dl_put p;
    const ws_dl_need need = { .n_vtx = 1, .data_size = n };
    int e = ws_dlist_append(dl, WS_DL_CLASSIC, 3, 0, NULL, 0, &need, &p);
    if (!e) {
        p.xyz[0] = p.xyz[1] = p.xyz[2] = 1.0;
        memset(p.data, 0x5a, n);
    }
    return e;
}

/* Two readers on one list: the tracer (streaming, releases what it read) and the classic
 * renderer (keeps its records to the frame's end). A chunk is freed once every reader of its
 * records released it: chunks with only the tracer's records go, a chunk with a classic
 * record in it stays (with the tracer's records in it, which the classic reader skips by
 * their reader), and each reader's count is its own. */
static void test_two_readers(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    sink_log log = { .n = 0 };
    ws_dlist_set_sink(dl, release_all_sink, &log);
    const attr a = { { 0.5, 0.25, 0.5 }, 2 };
    assert_int_equal(add_classic(dl, 24), 0); /* the first chunk: mixed */
    for (int k = 0; k < 6000; k++)
        assert_int_equal(add_poly(dl, 0, &a, 4, k), 0);
    assert_int_equal(add_classic(dl, 24), 0);
    ws_dlist_seal(dl);
    ws_dlist_trim(dl);
    assert_true(log.n >= 3);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 6000);
    assert_int_equal(ws_dlist_count(dl, WS_DL_CLASSIC), 2);
    assert_int_equal(ws_dlist_count(dl, WS_DL_CLASSIC | WS_DL_TRACER), 6002);
    /* the tracer released every chunk: the first and the last (classic records) stay */
    const ws_dl_chunk *c = ws_dlist_first(dl);
    assert_ptr_equal(c, log.chunk[0]);
    assert_ptr_equal(c->next, log.chunk[log.n - 1]);
    assert_null(c->next->next);
    assert_int_equal(c->readers, WS_DL_CLASSIC | WS_DL_TRACER);
    size_t classic = 0;
    for (; c; c = c->next)
        for (size_t j = 0; j < c->n_rec; j++)
            if (c->rec[j].reader == WS_DL_CLASSIC) {
                classic++;
                assert_int_equal(c->rec[j].kind, 3);
                assert_int_equal(c->attr[c->rec[j].data + 23], 0x5a);
            }
    assert_int_equal(classic, 2);
    /* the frame boundary frees the rest */
    ws_dlist_reset(dl);
    assert_null(ws_dlist_first(dl));
    assert_int_equal(ws_dlist_bytes(dl), 0);
    assert_int_equal(ws_dlist_count(dl, WS_DL_CLASSIC | WS_DL_TRACER), 0);
    ws_dlist_free(dl);
}

static void test_unappend_and_limits(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    const attr a = { { 0, 1, 0 }, 3 }, b = { { 1, 0, 0 }, 3 };
    assert_int_equal(add_poly(dl, 2, &a, 4, 1), 0);
    const ws_dl_chunk *c = ws_dlist_first(dl);
    const size_t nx = c->n_xyz, nc = c->n_cnt, na = c->n_attr;
    assert_int_equal(add_poly(dl, 2, &b, 6, 2), 0);
    ws_dlist_unappend(dl);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 1);
    assert_int_equal(c->n_rec, 1);
    assert_int_equal(c->n_xyz, nx);
    assert_int_equal(c->n_cnt, nc);
    assert_int_equal(c->n_attr, na); /* b's copy taken back as well */
    ws_dlist_unappend(dl);           /* only the last append */
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 1);
    assert_int_equal(add_poly(dl, 2, &a, 3, 3), 0);
    assert_int_equal(c->rec[1].attr, c->rec[0].attr);
    check_poly(c, &c->rec[0], 4, 1);
    check_poly(c, &c->rec[1], 3, 3);
    /* counts the records cannot hold */
    ws_dl_put p;
    const ws_dl_need neg = { .n_vtx = 3, .n_loops = -1 };
    const ws_dl_need over = { .n_vtx = 3, .n_facets = 1 << 30, .n_loops = 1 << 30 };
    const ws_dl_need wide = { .n_vtx = (size_t)UINT32_MAX + 2, .n_loops = 1, .n_idx = 3 };
    const ws_dl_need huge = { .n_vtx = SIZE_MAX / 8, .n_loops = 1 };
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 1, 0, &a, sizeof a, &neg, &p), 300);
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 1, 0, &a, sizeof a, &over, &p), 300);
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 1, 0, &a, sizeof a, &wide, &p), 300);
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 1, 0, &a, sizeof a, &huge, &p), 300);
    const ws_dl_need one = { .n_vtx = 3, .n_loops = 1 };
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 256, 0, &a, sizeof a, &one, &p), 300);
    assert_int_equal(ws_dlist_append(dl, WS_DL_TRACER, 1, -1, &a, sizeof a, &one, &p), 300);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 2);
    assert_null(c->next);
    ws_dlist_free(dl);
}

/* Appends a keyed polygon record (ws_dlist_append_keyed) of 3 vertices; a NULL: by the key
 * alone. Returns its result. */
static int add_keyed(ws_dlist *dl, unsigned reader, uint64_t key, const attr *a)
{
    ws_dl_put p;
    const ws_dl_need need = { .n_vtx = 3, .n_loops = 1 };
    int e = ws_dlist_append_keyed(dl, reader, 7, 0, key, a, sizeof(attr), &need, &p);
    if (!e) {
        memset(p.xyz, 0, 9 * sizeof *p.xyz);
        p.loops[0] = 3;
    }
    return e;
}

/* Keyed attributes: a record after the last one appended, of the same reader and non-zero
 * key, shares its attributes without them (attr NULL); any other case asks for them (-1,
 * the list unchanged) or compares their bytes as ws_dlist_append does. */
static void test_keyed(void **state)
{
    (void)state;
    ws_dlist *dl = ws_dlist_new();
    const attr a = { { 0.5, 0, 1 }, 4 }, b = { { 0, 1, 0 }, 4 };
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 5, NULL), -1); /* no record yet */
    assert_null(ws_dlist_first(dl));
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 5, &a), 0);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 5, NULL), 0);
    const ws_dl_chunk *c = ws_dlist_first(dl);
    assert_int_equal(c->n_rec, 2);
    assert_int_equal(c->rec[1].attr, c->rec[0].attr);
    assert_memory_equal(c->attr + c->rec[1].attr, &a, sizeof a);
    /* another key, key 0, another reader's record between: the attributes are asked for */
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 6, NULL), -1);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 0, NULL), -1);
    assert_int_equal(c->n_rec, 2);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 6, &b), 0);
    assert_int_not_equal(c->rec[2].attr, c->rec[1].attr);
    assert_memory_equal(c->attr + c->rec[2].attr, &b, sizeof b);
    assert_int_equal(add_keyed(dl, WS_DL_CLASSIC, 6, NULL), -1);
    assert_int_equal(add_classic(dl, 8), 0);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 6, NULL), -1);
    /* an equal key's bytes are not compared: the record after an unkeyed one compares them */
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 6, &b), 0);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, &b), 0);
    assert_int_equal(c->rec[5].attr, c->rec[4].attr);
    /* the last record taken back: the key before it again */
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 8, &a), 0);
    ws_dlist_unappend(dl);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 8, NULL), -1);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), 0);
    assert_int_equal(c->rec[6].attr, c->rec[5].attr);
    /* a record sharing them taken back: the fills as before, the key kept */
    const size_t nr = c->n_rec, nx = c->n_xyz, nc = c->n_cnt, na = c->n_attr;
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), 0);
    ws_dlist_unappend(dl);
    assert_true(c->n_rec == nr && c->n_xyz == nx && c->n_cnt == nc && c->n_attr == na);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 6);
    /* a new chunk copies them: asked for at the chunk's end, and after a seal */
    const size_t n = c->cap[0] - c->n_rec;
    for (size_t k = 0; k < n; k++)
        assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), 0);
    assert_null(c->next);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), -1);
    assert_null(c->next);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, &b), 0);
    assert_non_null(c->next);
    assert_memory_equal(c->next->attr + c->next->rec[0].attr, &b, sizeof b);
    ws_dlist_seal(dl);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), -1);
    assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), 6 + n + 1);
    /* a new frame forgets the key */
    ws_dlist_reset(dl);
    assert_int_equal(add_keyed(dl, WS_DL_TRACER, 7, NULL), -1);
    ws_dlist_free(dl);
}

/* A workload of 3000 records (some of them large, with data) and a seal; each failing
 * append must return 300 and leave the list as it was. Returns the failures seen. */
static int workload(ws_dlist *dl, sink_log *log)
{
    int fails = 0;
    for (int k = 0; k < 3000; k++) {
        const attr a = { { k % 3, 0, 0 }, k % 7 };
        const size_t before = ws_dlist_count(dl, WS_DL_TRACER);
        const int n0 = log->n;
        const size_t n = k % 500 == 0 ? 20000 : 3 + (size_t)k % 5;
        int e = add_poly(dl, k % 4, &a, n, k);
        if (e) {
            assert_int_equal(e, 300);
            assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), before);
            assert_int_equal(log->n, n0); /* nothing sealed by a failed append */
            fails++;
        }
    }
    ws_dlist_seal(dl);
    return fails;
}

/* Every allocation of the workload fails in turn. */
static void test_oom(void **state)
{
    (void)state;
    sink_log log = { .n = 0 };
    ws_dlist *dl = ws_dlist_new();
    ws_dlist_set_sink(dl, sink, &log);
    long a0 = gks_alloc_count();
    assert_int_equal(workload(dl, &log), 0);
    const long allocs = gks_alloc_count() - a0;
    const size_t recs = ws_dlist_count(dl, WS_DL_TRACER);
    assert_true(allocs >= 3);
    int total_fails = 0;
    for (long n = 1; n <= allocs; n++) {
        ws_dlist_reset(dl);
        log.n = 0;
        gks_alloc_fail_after(n);
        int f = workload(dl, &log);
        gks_alloc_fail_after(0);
        assert_int_equal(f, 1); /* exactly the nth allocation failed: one record lost */
        assert_int_equal(ws_dlist_count(dl, WS_DL_TRACER), recs - 1);
        size_t seen = 0;
        for (const ws_dl_chunk *c = ws_dlist_first(dl); c; c = c->next)
            seen += c->n_rec;
        assert_int_equal(seen, recs - 1);
        total_fails += f;
    }
    gks_alloc_fail_after(1);
    ws_dlist *none = ws_dlist_new();
    gks_alloc_fail_after(0);
    assert_null(none);
    print_message("ws_dlist: %ld allocations, each failed in turn (%d failures, 300 each)\n",
                  allocs, total_fails);
    ws_dlist_free(dl);
}

static long minor_faults(void)
{
    struct rusage u;
    return getrusage(RUSAGE_SELF, &u) == 0 ? u.ru_minflt : -1;
}

/* Minor page faults taken by writing every byte of a fresh mapping of the given pages, made
 * present first by gks_populate when populate is set (*done: what it returned). */
static long write_faults(size_t pages, int populate, int *done)
{
    const size_t bytes = pages * (size_t)sysconf(_SC_PAGESIZE);
    unsigned char *m = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    assert_true(m != MAP_FAILED);
    if (populate)
        *done = gks_populate(m + 1, bytes - 2); /* whole first and last pages included */
    const long f0 = minor_faults();
    memset(m, 0x5a, bytes);
    const long faults = minor_faults() - f0;
    munmap(m, bytes);
    return faults;
}

/* gks_populate: nothing for 0 bytes; a range not page-aligned keeps its contents; on fresh
 * pages that it made present (it returns 1 where the kernel has MADV_POPULATE_WRITE), writing
 * every byte takes no fault per page, where without it each page takes one. Compared with
 * the same writes to a mapping not populated, since a sanitizer's shadow memory adds faults
 * of its own to both. */
static void test_populate(void **state)
{
    (void)state;
    unsigned char buf[3 * 4096 + 100];
    for (size_t i = 0; i < sizeof buf; i++)
        buf[i] = (unsigned char)(i * 7u);
    assert_int_equal(gks_populate(buf, 0), 0);
    const int r = gks_populate(buf + 13, sizeof buf - 50);
    assert_true(r == 0 || r == 1);
    for (size_t i = 0; i < sizeof buf; i++)
        assert_int_equal(buf[i], (unsigned char)(i * 7u));

    enum { PAGES = 64 };
    int done = 0;
    const long plain = write_faults(PAGES, 0, &done);
    const long populated = write_faults(PAGES, 1, &done);
    print_message("gks_populate: %s; writing %d pages: %ld faults, %ld when populated\n",
                  done ? "done" : "not available here", PAGES, plain, populated);
    assert_true(plain >= PAGES); /* the pages themselves */
    if (done) /* a sanitizer's shadow of 64 pages is 8 pages: at most that many of its own */
        assert_true(populated <= plain - PAGES + PAGES / 4);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_empty),
        cmocka_unit_test(test_records_and_attributes),
        cmocka_unit_test(test_mesh),
        cmocka_unit_test(test_chunks_and_sink),
        cmocka_unit_test(test_release),
        cmocka_unit_test(test_two_readers),
        cmocka_unit_test(test_unappend_and_limits),
        cmocka_unit_test(test_keyed),
        cmocka_unit_test(test_oom),
        cmocka_unit_test(test_populate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
