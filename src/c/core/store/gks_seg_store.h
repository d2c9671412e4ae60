/* SPDX-License-Identifier: MIT */
/*
 * gks_seg_store.h -- segment storage (ISO 7942 4.7, 6.7): named segments holding their
 * primitives in NDC3, before segment transformation and clipping, with the attributes
 * and the clipping volume bound to each primitive, so that a segment can be redrawn
 * with another transformation. One store per GKS state list.
 *
 * Storage is flat: per segment one record array and pools of points, integers (loop counts,
 * cell colour indices), characters and attribute snapshots (a snapshot is shared by
 * consecutive primitives with equal attributes and normalization). Memory grows linearly with the content and is freed
 * when the segment is deleted. Segment lookup is linear in the number of segments.
 */
#ifndef GKS_SEG_H
#define GKS_SEG_H
#include "gks_private.h"
#include "gks_context.h"
#include <stddef.h>

/* What a stored primitive is: the output function that created it. */
typedef enum {
    GKS_SEG_POLYLINE, GKS_SEG_POLYMARKER, GKS_SEG_TEXT, GKS_SEG_FILL_AREA,
    GKS_SEG_FILL_AREA_SET, GKS_SEG_CELL_ARRAY,
    GKS_SEG_AREA_DATA            /* a primitive with data (gks_area_data.h) */
} gks_seg_kind;

/* The attributes bound to a primitive and the normalization transformation it was
 * created with (WC3 -> NDC3; TEXT geometry and pattern boxes are replayed through it). */
typedef struct gks_seg_bound {
    gks_cur_attrs attrs;
    double norm[3][4];
} gks_seg_bound;

/* A primitive as the core stores and replays it (colours still as indices). Geometry in
 * NDC3, not yet segment-transformed nor clipped; TEXT keeps its WC3 position and two
 * direction vectors (pts[0..2]) and its string, because its strokes depend on WC sizes. */
typedef struct gks_seg_prim {
    gks_seg_kind kind;
    int n_loops;                 /* fill area set loops; 1 otherwise */
    const int *loop_counts;
    int n_points;
    const Gpoint3 *pts;
    Gpoint3 cell_p, cell_q, cell_r;
    int cell_nx, cell_ny;
    const int *cell_colr;        /* colour indices, cell_nx * cell_ny */
    const char *str;             /* TEXT: the string (str_len bytes, not terminated) */
    int str_len;
    /* GKS_SEG_AREA_DATA: the item number, then the integers of gks_area_data_pack; pts
     * (n_points) are its triples (points, normals, colours). */
    const int *dints;
    int n_dints;
    const gks_seg_bound *bound;  /* attributes and normalization */
    int clip;                    /* 1: clip_box bound (viewport 3 with clipping on) */
    double clip_box[6];
} gks_seg_prim;

typedef struct gks_seg_rec gks_seg_rec;

typedef struct gks_segment {
    int name;
    double tran[3][4];           /* segment transformation 3, NDC3 -> NDC3 */
    int vis;                     /* 1 visible, 0 invisible */
    int highl;                   /* 1 highlighted, 0 normal */
    double pri;                  /* segment priority in [0, 1] */
    int det;                     /* 1 detectable, 0 undetectable */
    int ws[GKS_MAX_OPEN_WS];     /* workstations the segment is stored on */
    int n_ws;
    /* content */
    gks_seg_rec *rec;
    size_t n_rec, cap_rec;
    Gpoint3 *pts;
    size_t n_pts, cap_pts;
    int *ints;
    size_t n_ints, cap_ints;
    gks_seg_bound *bound;
    size_t n_bound, cap_bound;
    char *chars;
    size_t n_chars, cap_chars;
} gks_segment;

typedef struct gks_seg_store {
    gks_segment **seg;           /* in order of creation */
    size_t n, cap;
} gks_seg_store;

void gks_seg_store_init(gks_seg_store *st);
/* Deletes every segment. */
void gks_seg_store_free(gks_seg_store *st);

/* The segment called name, or NULL. */
gks_segment *gks_seg_find(const gks_seg_store *st, int name);
/* New empty segment with the standard's initial attributes (identity transformation,
 * visible, normal, priority 0, undetectable). Returns it, NULL on storage overflow. The
 * caller has checked that the name is valid and unused. */
gks_segment *gks_seg_create(gks_seg_store *st, int name);
/* Deletes segment `name` (no-op if absent). */
void gks_seg_delete(gks_seg_store *st, int name);

/* Appends a copy of a primitive. Returns 0 or 301 (segment storage overflow: the segment
 * is unchanged). */
int gks_seg_append(gks_segment *s, const gks_seg_prim *p);
/* Number of stored primitives; primitive i (pointers valid until the next append). */
size_t gks_seg_count(const gks_segment *s);
void gks_seg_get(const gks_segment *s, size_t i, gks_seg_prim *p);

/* Workstation association: add (no-op if present; 0 or 301), remove, test. */
int gks_seg_ws_add(gks_segment *s, int ws_id);
void gks_seg_ws_remove(gks_segment *s, int ws_id);
int gks_seg_on_ws(const gks_segment *s, int ws_id);

/* The segments stored on ws_id in drawing order: ascending priority, and for equal
 * priority in order of creation (later ones drawn over earlier ones). Fills out (capacity
 * st->n) and returns the count. */
size_t gks_seg_draw_order(const gks_seg_store *st, int ws_id, gks_segment **out);
#endif
