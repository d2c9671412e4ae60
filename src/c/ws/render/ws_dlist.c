/* SPDX-License-Identifier: MIT */
/*
 * ws_dlist.c -- the retained display list of one frame (ws_dlist.h): chunks allocated in one
 * block each, with fixed capacities, filled in order and handed to the sink when sealed.
 */
#include "ws_dlist.h"
#include "gks_alloc.h"
#include <limits.h>
#include <string.h>

/* The arrays of a chunk, in the order of ws_dl_chunk.cap. */
enum { A_REC, A_XYZ, A_NRM, A_RGB, A_CNT, A_IDX, A_ATTR, N_ARR };

/* Element sizes of the arrays. */
static const size_t elem[N_ARR] = { sizeof(ws_dl_rec), 3 * sizeof(double), 3 * sizeof(double),
                                    3 * sizeof(double), sizeof(int), sizeof(uint32_t), 1 };

/* Capacities of a new chunk: records, vertices, normals, colours, counts, indices, attribute
 * and data bytes (about 64 bytes per record: a renderer's own data per record fits). About
 * 480 KiB, touched only as far as it is filled (a large block is mapped on first use). The
 * normals, colours and indices get room only once the frame has had a record with them. */
static const size_t def_cap[N_ARR] = { 2048, 8192, 8192, 8192, 4096, 16384, 131072 };

struct ws_dlist {
    ws_dl_chunk *first, *cur;
    size_t n_rec[WS_DL_N_READERS]; /* records of each reader (bit r: n_rec[r]) */
    size_t bytes;              /* allocated by the chunks */
    unsigned used_arr;         /* bit a: the frame had a record with array a */
    ws_dlist_sink sink;
    void *sink_user;
    /* the state before the last append (ws_dlist_unappend) */
    ws_dl_chunk *undo_chunk;
    size_t undo[N_ARR];
    int undo_reader;
    int undo_plain;            /* append_plain's: only n_rec, n_xyz, n_cnt changed */
    uint64_t undo_key;
    const ws_dl_chunk *undo_key_chunk;
    /* the key of the last record appended (ws_dlist_append_keyed; 0: none) and its chunk */
    uint64_t key;
    const ws_dl_chunk *key_chunk;
    /* released chunks kept for the next ones of the same size (at most N_SPARE, linked by
       next): their pages are already in memory, where a new block would be first-touched
       memory again (the tracer's worker releases a chunk every ~2000 areas) */
    ws_dl_chunk *spare;
    int n_spare;
};

enum { N_SPARE = 4 };

static size_t round8(size_t n) { return (n + 7) & ~(size_t)7; }

/* Where the fill of each array is in a chunk. */
static const size_t fill_off[N_ARR] = {
    offsetof(ws_dl_chunk, n_rec), offsetof(ws_dl_chunk, n_xyz), offsetof(ws_dl_chunk, n_nrm),
    offsetof(ws_dl_chunk, n_rgb), offsetof(ws_dl_chunk, n_cnt), offsetof(ws_dl_chunk, n_idx),
    offsetof(ws_dl_chunk, n_attr) };

/* Fill of array a of chunk c. */
static size_t *fill_of(ws_dl_chunk *c, int a)
{
    return (size_t *)(void *)((unsigned char *)c + fill_off[a]);
}

ws_dlist *ws_dlist_new(void)
{
    return gks_calloc_array(1, sizeof(ws_dlist));
}

/* Frees the chunks from c on (linked by next). */
static void free_chunks(ws_dl_chunk *c)
{
    for (ws_dl_chunk *n; c; c = n) {
        n = c->next;
        gks_free(c);
    }
}

void ws_dlist_reset(ws_dlist *dl)
{
    free_chunks(dl->first);
    free_chunks(dl->spare);
    dl->spare = NULL;
    dl->n_spare = 0;
    dl->first = dl->cur = dl->undo_chunk = NULL;
    dl->key = 0;
    dl->key_chunk = NULL;
    memset(dl->n_rec, 0, sizeof dl->n_rec);
    dl->bytes = 0;
    dl->used_arr = 0;
}

void ws_dlist_free(ws_dlist *dl)
{
    if (!dl)
        return;
    ws_dlist_reset(dl);
    gks_free(dl);
}

void ws_dlist_set_sink(ws_dlist *dl, ws_dlist_sink fn, void *user)
{
    dl->sink = fn;
    dl->sink_user = user;
}

void ws_dlist_seal(ws_dlist *dl)
{
    ws_dl_chunk *c = dl->cur;
    if (!c || c->sealed || !c->n_rec)
        return;
    c->sealed = 1;
    if (dl->sink)
        dl->sink(dl->sink_user, c);
}

/* A new chunk with room for at least want[] (and the defaults), linked after the current one,
 * which is sealed. 0 or 300 (nothing changed). */
static int chunk_new(ws_dlist *dl, const size_t want[N_ARR])
{
    size_t cap[N_ARR], off[N_ARR], total = round8(sizeof(ws_dl_chunk));
    for (int a = 0; a < N_ARR; a++) {
        const size_t d = a == A_NRM || a == A_RGB || a == A_IDX
                             ? ((dl->used_arr >> a) & 1u ? def_cap[a] : 0)
                             : def_cap[a];
        cap[a] = want[a] > d ? want[a] : d; /* <= UINT32_MAX (need_of), offsets fit */
        if ((a == A_NRM || a == A_RGB) && cap[a])
            cap[a] = cap[A_XYZ]; /* indexed as the vertices */
        if (cap[a] > UINT32_MAX || cap[a] > (SIZE_MAX - 8) / elem[a])
            return 300;
        off[a] = total;
        const size_t bytes = round8(cap[a] * elem[a]);
        if (bytes > SIZE_MAX - total)
            return 300;
        total += bytes;
    }
    unsigned char *b = NULL;
    if (dl->spare && dl->spare->bytes == total) { /* the same capacities: the same layout */
        b = (unsigned char *)(void *)dl->spare;
        dl->spare = dl->spare->next;
        dl->n_spare--;
    } else {
        b = gks_alloc_array(1, total);
        if (b) /* the records, vertices (normals, colours) and counts */
            (void)gks_populate(b, off[A_IDX]); /* written at once by the appender */
    }
    if (!b)
        return 300;
    ws_dl_chunk *c = (ws_dl_chunk *)(void *)b;
    memset(c, 0, sizeof *c);
    atomic_init(&c->done, 0u);
    memcpy(c->cap, cap, sizeof cap);
    c->rec = (ws_dl_rec *)(void *)(b + off[A_REC]);
    c->xyz = (double *)(void *)(b + off[A_XYZ]);
    c->nrm = (double *)(void *)(b + off[A_NRM]);
    c->rgb = (double *)(void *)(b + off[A_RGB]);
    c->cnt = (int *)(void *)(b + off[A_CNT]);
    c->idx = (uint32_t *)(void *)(b + off[A_IDX]);
    c->attr = b + off[A_ATTR];
    c->bytes = total;
    ws_dlist_seal(dl);
    if (dl->cur)
        dl->cur->next = c;
    else
        dl->first = c;
    dl->cur = c;
    dl->bytes += total;
    ws_dlist_trim(dl);
    return 0;
}

void ws_dlist_release(ws_dl_chunk *c, unsigned reader)
{
    atomic_fetch_or_explicit(&c->done, reader, memory_order_release);
}

/* Every reader of sealed chunk c has released it. */
static int chunk_done(ws_dl_chunk *c)
{
    return c->sealed &&
           (c->readers & ~atomic_load_explicit(&c->done, memory_order_acquire)) == 0;
}

void ws_dlist_trim(ws_dlist *dl)
{
    ws_dl_chunk *prev = NULL;
    for (ws_dl_chunk *c = dl->first, *n; c; c = n) {
        n = c->next;
        if (!chunk_done(c)) {
            prev = c;
            continue;
        }
        if (prev)
            prev->next = n;
        else
            dl->first = n;
        if (dl->cur == c)
            dl->cur = prev;
        if (dl->undo_chunk == c)
            dl->undo_chunk = NULL;
        dl->bytes -= c->bytes;
        if (dl->n_spare < N_SPARE) { /* kept for chunk_new; its fields are set again there */
            c->next = dl->spare;
            dl->spare = c;
            dl->n_spare++;
        } else {
            gks_free(c);
        }
    }
}

/* The index of reader bit reader in n_rec. */
static int reader_ix(unsigned reader) { return reader == WS_DL_TRACER; }

/* The room a record needs per array (want[A_ATTR] = attribute bytes); 0, or 300 for counts
 * the records cannot hold. */
static int need_of(const ws_dl_need *need, size_t attr_size, size_t want[N_ARR])
{
    if (need->n_facets < 0 || need->n_loops < 0 || need->n_facets > INT_MAX - need->n_loops ||
        attr_size > UINT32_MAX / 4 || need->data_size > UINT32_MAX / 4 ||
        need->n_vtx > UINT32_MAX || need->n_idx > UINT32_MAX ||
        (size_t)need->n_facets + (size_t)need->n_loops > UINT32_MAX)
        return 300;
    want[A_REC] = 1;
    want[A_XYZ] = need->n_vtx;
    want[A_NRM] = need->flags & WS_DL_NORMALS ? need->n_vtx : 0;
    want[A_RGB] = need->flags & WS_DL_COLOURS ? need->n_vtx : 0;
    want[A_CNT] = (size_t)need->n_facets + (size_t)need->n_loops;
    want[A_IDX] = need->n_idx;
    want[A_ATTR] = round8(attr_size) + round8(need->data_size);
    return 0;
}

/* The attributes of c's last record are reader's attributes of key and attr (attr_size
 * bytes): by the key (ws_dlist_append_keyed), else by their bytes (attr NULL: never). */
static int same_attr(const ws_dlist *dl, const ws_dl_chunk *c, unsigned reader, uint64_t key,
                     const void *attr, size_t attr_size)
{
    if (!c->n_rec)
        return 0;
    const ws_dl_rec *l = &c->rec[c->n_rec - 1];
    if (l->attr_size != attr_size)
        return 0;
    if (key && key == dl->key && c == dl->key_chunk && l->reader == reader)
        return 1; /* the last record appended, with these attributes */
    return attr && (attr_size == 0 || memcmp(c->attr + l->attr, attr, attr_size) == 0);
}

static int fits(ws_dl_chunk *c, const size_t want[N_ARR])
{
    if (c->sealed)
        return 0;
    for (int a = 0; a < N_ARR; a++)
        if (want[a] > c->cap[a] - *fill_of(c, a))
            return 0;
    /* normals and colours at the vertices' index */
    return (!want[A_NRM] || c->n_xyz + want[A_NRM] <= c->cap[A_NRM]) &&
           (!want[A_RGB] || c->n_xyz + want[A_RGB] <= c->cap[A_RGB]);
}

/* The state before an append, for ws_dlist_unappend. */
static void undo_note(ws_dlist *dl, ws_dl_chunk *c, unsigned reader)
{
    dl->undo_chunk = c;
    dl->undo[A_REC] = c->n_rec;
    dl->undo[A_XYZ] = c->n_xyz;
    dl->undo[A_NRM] = c->n_nrm;
    dl->undo[A_RGB] = c->n_rgb;
    dl->undo[A_CNT] = c->n_cnt;
    dl->undo[A_IDX] = c->n_idx;
    dl->undo[A_ATTR] = c->n_attr;
    dl->undo_reader = reader_ix(reader);
    dl->undo_plain = 0;
    dl->undo_key = dl->key;
    dl->undo_key_chunk = dl->key_chunk;
}

/* The common record, made as ws_dlist_append's general path makes it: one facet of loops
 * taking its vertices in order, with no normals, colours, indices or own data, and the
 * attributes of the previous record in the open current chunk, which has room for it (the
 * tracer's areas between attribute changes). Returns 0 (appended) or -1 (not this case:
 * nothing changed). */
static int append_plain(ws_dlist *dl, unsigned reader, int kind, int view, uint64_t key,
                        const void *attr, size_t attr_size, const ws_dl_need *need,
                        ws_dl_put *put)
{
    ws_dl_chunk *c = dl->cur;
    const size_t nv = need->n_vtx, nl = (size_t)need->n_loops;
    if (!c || c->sealed || need->flags || need->n_facets || need->n_idx || need->data_size ||
        need->n_loops < 0 || (unsigned)kind > UCHAR_MAX || (unsigned)view > UCHAR_MAX ||
        c->n_rec >= c->cap[A_REC] || nv > c->cap[A_XYZ] - c->n_xyz ||
        nl > c->cap[A_CNT] - c->n_cnt || !same_attr(dl, c, reader, key, attr, attr_size))
        return -1; /* n_vtx fits a chunk's 32-bit capacity, n_loops its counts; attr_size
                      is the last record's */
    /* undo_note for the three fills this record changes */
    dl->undo_chunk = c;
    dl->undo[A_REC] = c->n_rec;
    dl->undo[A_XYZ] = c->n_xyz;
    dl->undo[A_CNT] = c->n_cnt;
    dl->undo_reader = reader_ix(reader);
    dl->undo_plain = 1;
    dl->undo_key = dl->key;
    dl->undo_key_chunk = dl->key_chunk;
    c->readers |= reader;
    ws_dl_rec *r = &c->rec[c->n_rec++];
    *r = (ws_dl_rec){ .kind = (unsigned char)kind, .view = (unsigned char)view,
                      .reader = (unsigned char)reader, .n_loops = need->n_loops,
                      .attr = c->rec[c->n_rec - 2].attr, .attr_size = (uint32_t)attr_size,
                      .data = (uint32_t)c->n_attr, .vtx = (uint32_t)c->n_xyz,
                      .n_vtx = (uint32_t)nv, .cnt = (uint32_t)c->n_cnt,
                      .idx = (uint32_t)c->n_idx };
    c->n_xyz += nv;
    c->n_cnt += nl;
    *put = (ws_dl_put){ .rec = r, .xyz = nv ? c->xyz + 3 * (size_t)r->vtx : NULL,
                        .loops = nl ? c->cnt + r->cnt : NULL };
    dl->n_rec[dl->undo_reader]++;
    dl->key = key;
    dl->key_chunk = c;
    return 0;
}

/* ws_dlist_append_keyed for every record append_plain does not make. */
static int append_general(ws_dlist *dl, unsigned reader, int kind, int view, uint64_t key,
                          const void *attr, size_t attr_size, const ws_dl_need *need,
                          ws_dl_put *put)
{
    size_t want[N_ARR];
    if (kind < 0 || kind > UCHAR_MAX || view < 0 || view > UCHAR_MAX ||
        need_of(need, attr_size, want))
        return 300;
    ws_dl_chunk *c = dl->cur;
    int shared = c && !c->sealed && same_attr(dl, c, reader, key, attr, attr_size);
    const size_t data_bytes = round8(need->data_size);
    if (shared)
        want[A_ATTR] = data_bytes;
    const int fresh = !c || !fits(c, want);
    if (!attr && attr_size && (fresh || !shared))
        return -1; /* the attributes are copied: the caller gives them */
    for (int a = A_NRM; a <= A_IDX; a++) /* new chunks have room for these from now on */
        if (want[a] && a != A_CNT)
            dl->used_arr |= 1u << a;
    if (fresh) {
        want[A_ATTR] = round8(attr_size) + data_bytes;
        shared = 0;
        if (chunk_new(dl, want))
            return 300;
        c = dl->cur;
    }
    undo_note(dl, c, reader);
    c->readers |= reader;
    ws_dl_rec *r = &c->rec[c->n_rec++];
    *r = (ws_dl_rec){ .kind = (unsigned char)kind, .view = (unsigned char)view,
                      .reader = (unsigned char)reader,
                      .flags = (unsigned char)(need->flags & (WS_DL_NORMALS | WS_DL_COLOURS)),
                      .n_facets = need->n_facets,
                      .n_loops = need->n_loops, .attr_size = (uint32_t)attr_size,
                      .vtx = (uint32_t)c->n_xyz, .n_vtx = (uint32_t)need->n_vtx,
                      .cnt = (uint32_t)c->n_cnt, .idx = (uint32_t)c->n_idx,
                      .n_idx = (uint32_t)need->n_idx };
    r->attr = shared ? c->rec[c->n_rec - 2].attr : (uint32_t)c->n_attr;
    if (!shared && attr_size)
        memcpy(c->attr + c->n_attr, attr, attr_size);
    r->data = (uint32_t)(c->n_attr + want[A_ATTR] - data_bytes);
    r->data_size = (uint32_t)need->data_size;
    c->n_attr += want[A_ATTR];
    c->n_xyz += want[A_XYZ];
    if (want[A_NRM])
        c->n_nrm = c->n_xyz;
    if (want[A_RGB])
        c->n_rgb = c->n_xyz;
    c->n_cnt += want[A_CNT];
    c->n_idx += want[A_IDX];
    *put = (ws_dl_put){ .rec = r,
                        .xyz = want[A_XYZ] ? c->xyz + 3 * (size_t)r->vtx : NULL,
                        .nrm = want[A_NRM] ? c->nrm + 3 * (size_t)r->vtx : NULL,
                        .rgb = want[A_RGB] ? c->rgb + 3 * (size_t)r->vtx : NULL,
                        .facets = need->n_facets ? c->cnt + r->cnt : NULL,
                        .loops = need->n_loops ? c->cnt + r->cnt + need->n_facets : NULL,
                        .idx = want[A_IDX] ? c->idx + r->idx : NULL,
                        .data = need->data_size ? c->attr + r->data : NULL };
    dl->n_rec[dl->undo_reader]++;
    dl->key = key;
    dl->key_chunk = c;
    return 0;
}

int ws_dlist_append_keyed(ws_dlist *dl, unsigned reader, int kind, int view, uint64_t key,
                          const void *attr, size_t attr_size, const ws_dl_need *need,
                          ws_dl_put *put)
{
    if (append_plain(dl, reader, kind, view, key, attr, attr_size, need, put) == 0)
        return 0;
    return append_general(dl, reader, kind, view, key, attr, attr_size, need, put);
}

int ws_dlist_append(ws_dlist *dl, unsigned reader, int kind, int view, const void *attr,
                    size_t attr_size, const ws_dl_need *need, ws_dl_put *put)
{
    return ws_dlist_append_keyed(dl, reader, kind, view, 0, attr, attr_size, need, put);
}

void ws_dlist_unappend(ws_dlist *dl)
{
    ws_dl_chunk *c = dl->undo_chunk;
    if (!c || c != dl->cur || c->sealed)
        return;
    for (int a = 0; a < N_ARR; a++)
        if (!dl->undo_plain || a == A_REC || a == A_XYZ || a == A_CNT)
            *fill_of(c, a) = dl->undo[a];
    dl->key = dl->undo_key;
    dl->key_chunk = dl->undo_key_chunk;
    dl->undo_chunk = NULL;
    dl->n_rec[dl->undo_reader]--; /* c->readers keeps the bit: a reader of c reads nothing */
}

const ws_dl_chunk *ws_dlist_first(const ws_dlist *dl) { return dl->first; }

size_t ws_dlist_count(const ws_dlist *dl, unsigned mask)
{
    size_t n = 0;
    for (int i = 0; i < WS_DL_N_READERS; i++)
        if ((mask >> i) & 1u)
            n += dl->n_rec[i];
    return n;
}

size_t ws_dlist_bytes(const ws_dlist *dl) { return dl->bytes; }
