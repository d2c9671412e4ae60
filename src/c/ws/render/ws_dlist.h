/* SPDX-License-Identifier: MIT */
/*
 * ws_dlist.h -- the retained display list of one frame (render layer, internal): what a
 * renderer keeps of the frame's primitives until UPDATE, in one indexed form that both the
 * classic renderer and the ray-tracing adapter read.
 *
 * A record is one primitive: its kind and view index (the reader's), its attributes (bytes
 * the reader defines, copied into the list; consecutive records with equal attributes share
 * one copy), its own data (bytes the reader defines that differ from record to record, such
 * as a colour after shading or a depth sort key), its vertices (3 doubles each, in the coordinates its renderer needs), optional
 * per-vertex normals and colours (3 doubles each, one per vertex), counts (the facets' loop
 * numbers, then the loops' vertex numbers) and indices into the record's own vertices. A
 * FILL AREA SET is one facet whose loops take the vertices in order (no indices); a mesh
 * keeps its shared vertices once and its facets as index lists.
 *
 * One list per frame serves every reader of the workstation's render layer (ws_render owns
 * it): each record names its reader (WS_DL_CLASSIC: the classic renderer, which keeps its
 * records until the frame ends; WS_DL_TRACER: the tracer's recording worker, which streams
 * them into its scenes), and a reader reads only its own records.
 *
 * The list is append-only for the frame and stored in chunks. A chunk is allocated once with
 * its capacities and never reallocated, so that a reader (a worker thread) can read a sealed
 * chunk while the caller appends to the next one. A chunk is sealed when the next record does
 * not fit or at ws_dlist_seal; each sealed chunk goes to the sink (ws_dlist_set_sink), in
 * order. A chunk stays in the list until ws_dlist_reset (the frame boundary) unless every
 * reader with records in it (ws_dl_chunk.readers) has released it (ws_dlist_release: a
 * streaming reader such as the tracer's worker, which keeps what it read in its own scene);
 * the list then takes it out, wherever it is in the list, and frees it or keeps it (up to 4,
 * freed at ws_dlist_reset) for the next chunk of the same size, whose pages are then already
 * in memory. A reader that keeps its records to the
 * end of the frame (the classic renderer) never releases, so a chunk with any of its records
 * stays. A record larger than a chunk gets a chunk of its own, sized to fit. Data flows one
 * way: renderer's recording -> list -> reader. A reader's own reset (ws_rt_reset,
 * ws_classic_reset) forgets only that reader's state, not the list.
 *
 * Threads: one thread appends, seals, trims and resets; a sink may hand a sealed chunk to
 * another thread, which then only reads it and releases it. ws_dlist_reset and ws_dlist_free
 * free the chunks: the caller first makes sure no reader is still at work (e.g.
 * rt_serial_drain).
 */
#ifndef WS_DLIST_H
#define WS_DLIST_H
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

/* Per-vertex data a record carries (flags of ws_dl_rec and ws_dl_need). */
enum { WS_DL_NORMALS = 1u, WS_DL_COLOURS = 2u };

/* The readers of the list, one bit each (ws_dl_rec.reader, ws_dl_chunk.readers). */
enum { WS_DL_CLASSIC = 1u, WS_DL_TRACER = 2u, WS_DL_N_READERS = 2 };

/* One primitive (48 bytes). Offsets are into the arrays of its chunk; a chunk holds at most
 * UINT32_MAX entries of each array, so they are 32-bit. A record's normals and colours (if
 * its flags say so) are at its vertices' index: nrm[3 * vtx ...], rgb[3 * vtx ...]. */
typedef struct ws_dl_rec {
    unsigned char kind;    /* the reader's record kind (0 .. 255) */
    unsigned char reader;  /* whose record it is: WS_DL_CLASSIC or WS_DL_TRACER */
    unsigned char flags;   /* WS_DL_NORMALS, WS_DL_COLOURS */
    unsigned char view;    /* view index (0 .. 255) */
    int n_facets;          /* cnt[cnt .. cnt + n_facets): loops per facet (0: one facet) */
    int n_loops;           /* then n_loops counts: vertices per loop */
    uint32_t attr, attr_size; /* attributes: attr_size bytes at attr (8-byte aligned) */
    uint32_t data, data_size; /* the record's own bytes at data (8-byte aligned) */
    uint32_t vtx, n_vtx;   /* vertices xyz[3 * vtx ...] (normals, colours alike) */
    uint32_t cnt;          /* first count */
    uint32_t idx, n_idx;   /* indices (0 .. n_vtx - 1) into the record's vertices; n_idx
                              0: the loops take the vertices in order */
} ws_dl_rec;

/* A chunk: read-only for readers. */
typedef struct ws_dl_chunk {
    struct ws_dl_chunk *next; /* the next chunk (set when it is made; a reader of a sealed
                                 chunk on another thread does not follow it) */
    int sealed;
    unsigned readers;         /* the readers of its records (set before it is sealed) */
    atomic_uint done;         /* the readers that released it (ws_dlist_release) */
    size_t bytes;             /* allocated for it */
    ws_dl_rec *rec;
    size_t n_rec;
    double *xyz, *nrm, *rgb;  /* 3 doubles per entry; nrm, rgb indexed as xyz (room for them
                                 only once the frame has had a record with them) */
    size_t n_xyz, n_nrm, n_rgb; /* n_nrm, n_rgb: the end of the last record with them */
    int *cnt;
    size_t n_cnt;
    uint32_t *idx;
    size_t n_idx;
    unsigned char *attr;      /* attribute and data bytes */
    size_t n_attr;
    size_t cap[7];            /* capacities (the list's) */
} ws_dl_chunk;

typedef struct ws_dlist ws_dlist;

/* What a record needs: vertices (normals, colours by flags), facets, loops, indices, bytes
 * of its own data. */
typedef struct ws_dl_need {
    size_t n_vtx;
    unsigned flags;
    int n_facets, n_loops;
    size_t n_idx;
    size_t data_size;
} ws_dl_need;

/* Where the caller writes a new record's data (NULL where the need is 0). */
typedef struct ws_dl_put {
    ws_dl_rec *rec;
    double *xyz, *nrm, *rgb;
    int *facets, *loops;      /* n_facets loop numbers, n_loops vertex numbers */
    uint32_t *idx;
    void *data;               /* data_size bytes */
} ws_dl_put;

/* Called with each sealed chunk, in order (on the appending thread). */
typedef void (*ws_dlist_sink)(void *user, ws_dl_chunk *c);

/* An empty list, NULL if out of memory. */
ws_dlist *ws_dlist_new(void);
/* Frees it and its chunks (NULL allowed). */
void ws_dlist_free(ws_dlist *dl);
/* A new frame (the frame boundary, for every reader at once): frees the chunks (no reader
 * may be at work). The sink stays. */
void ws_dlist_reset(ws_dlist *dl);
/* The sink of sealed chunks (NULL: none, the default). */
void ws_dlist_set_sink(ws_dlist *dl, ws_dlist_sink fn, void *user);
/* Appends a record of reader (one of WS_DL_CLASSIC, WS_DL_TRACER), kind and view (0 .. 255
 * each) with attributes attr (attr_size bytes, copied unless
 * equal to the previous record's in the chunk) and room for need; *put says where its data
 * goes (the caller fills it before the next call on dl). Returns 0, or 300 (storage, or a
 * count beyond the list's range, such as more than UINT32_MAX vertices: the list
 * unchanged). */
int ws_dlist_append(ws_dlist *dl, unsigned reader, int kind, int view, const void *attr, size_t attr_size,
                    const ws_dl_need *need, ws_dl_put *put);
/* ws_dlist_append with a key for the attributes (0: none). A non-zero key that equals the
 * key of the last record appended, when that record is reader's, of attr_size bytes of
 * attributes and in the open current chunk, shares that record's attributes without
 * comparing them: the caller promises that one reader never gives one non-zero key to two
 * different attribute contents (such as gks_prim.attr_gen for attributes made from the
 * primitive's alone). attr may be NULL: then the record is appended only when it shares
 * them that way; otherwise -1 (nothing changed: call again with attr). Returns 0, 300 or
 * -1. */
int ws_dlist_append_keyed(ws_dlist *dl, unsigned reader, int kind, int view, uint64_t key,
                          const void *attr, size_t attr_size, const ws_dl_need *need,
                          ws_dl_put *put);
/* Takes back the record just appended (before any other call on dl). */
void ws_dlist_unappend(ws_dlist *dl);
/* Seals the chunk being filled (to the sink) if it has records. */
void ws_dlist_seal(ws_dlist *dl);
/* Reader (a WS_DL_* bit) is done with sealed chunk c (any thread; c is not touched
 * afterwards): once every reader of its records is, the list frees it when it makes its
 * next chunk or at ws_dlist_trim. */
void ws_dlist_release(ws_dl_chunk *c, unsigned reader);
/* Frees the sealed chunks every reader of which has released them, now (the appending
 * thread; it looks at every chunk of the list). */
void ws_dlist_trim(ws_dlist *dl);
/* The first chunk of the frame that is not freed (NULL if none); the others by next. */
const ws_dl_chunk *ws_dlist_first(const ws_dlist *dl);
/* Records of the readers in mask (WS_DL_* bits) appended since the reset (those of freed
 * chunks included). */
size_t ws_dlist_count(const ws_dlist *dl, unsigned mask);
/* Bytes of the chunks held now (allocated), for measurements. */
size_t ws_dlist_bytes(const ws_dlist *dl);
#endif
