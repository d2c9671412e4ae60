/* SPDX-License-Identifier: MIT */
/*
 * gks_seg_store.c -- segment storage (see gks_seg_store.h).
 */
#include "gks_seg_store.h"
#include "gks_alloc.h"
#include <stdint.h>
#include <string.h>

struct gks_seg_rec {
    gks_seg_kind kind;
    int n_loops, n_points, cell_nx, cell_ny, clip, str_len, n_dints;
    size_t pts_off, loops_off, cells_off, bound_ind, str_off, dints_off;
    Gpoint3 cell_p, cell_q, cell_r;
    double clip_box[6];
};

void gks_seg_store_init(gks_seg_store *st)
{
    st->seg = NULL;
    st->n = st->cap = 0;
}

static void seg_free(gks_segment *s)
{
    if (!s)
        return;
    gks_free(s->rec);
    gks_free(s->pts);
    gks_free(s->ints);
    gks_free(s->bound);
    gks_free(s->chars);
    gks_free(s);
}

void gks_seg_store_free(gks_seg_store *st)
{
    for (size_t i = 0; i < st->n; i++)
        seg_free(st->seg[i]);
    gks_free(st->seg);
    gks_seg_store_init(st);
}

gks_segment *gks_seg_find(const gks_seg_store *st, int name)
{
    for (size_t i = 0; i < st->n; i++)
        if (st->seg[i]->name == name)
            return st->seg[i];
    return NULL;
}

gks_segment *gks_seg_create(gks_seg_store *st, int name)
{
    if (gks_grow(&st->seg, &st->cap, st->n + 1, sizeof *st->seg))
        return NULL;
    gks_segment *s = gks_calloc_array(1, sizeof *s);
    if (!s)
        return NULL;
    s->name = name;
    for (int i = 0; i < 3; i++)
        s->tran[i][i] = 1.0;
    s->vis = 1;
    st->seg[st->n++] = s;
    return s;
}

void gks_seg_delete(gks_seg_store *st, int name)
{
    for (size_t i = 0; i < st->n; i++) {
        if (st->seg[i]->name != name)
            continue;
        seg_free(st->seg[i]);
        memmove(st->seg + i, st->seg + i + 1, (st->n - i - 1) * sizeof *st->seg);
        st->n--;
        return;
    }
}

/* Makes room for `extra` more elements of `size` in *a (count *n, capacity *cap). */
static int reserve(void *a, size_t *n, size_t *cap, size_t extra, size_t size)
{
    if (extra > SIZE_MAX / 2 - *n)
        return 301;
    return gks_grow(a, cap, *n + extra, size) ? 301 : 0;
}

int gks_seg_append(gks_segment *s, const gks_seg_prim *p)
{
    size_t n_pts = p->n_points > 0 ? (size_t)p->n_points : 0;
    size_t n_loops = p->kind == GKS_SEG_FILL_AREA_SET && p->n_loops > 0 ? (size_t)p->n_loops : 0;
    size_t n_cells = 0, n_chars = p->kind == GKS_SEG_TEXT && p->str_len > 0 ? (size_t)p->str_len : 0;
    size_t n_dints = p->kind == GKS_SEG_AREA_DATA && p->n_dints > 0 ? (size_t)p->n_dints : 0;
    if (p->kind == GKS_SEG_CELL_ARRAY && p->cell_nx > 0 && p->cell_ny > 0) {
        if ((size_t)p->cell_nx > SIZE_MAX / (size_t)p->cell_ny)
            return 301;
        n_cells = (size_t)p->cell_nx * (size_t)p->cell_ny;
    }
    int share = s->n_bound > 0 &&
                memcmp(&s->bound[s->n_bound - 1], p->bound, sizeof *p->bound) == 0;
    /* Reserve everything first: on failure nothing has changed. */
    if (reserve(&s->rec, &s->n_rec, &s->cap_rec, 1, sizeof *s->rec) ||
        reserve(&s->pts, &s->n_pts, &s->cap_pts, n_pts, sizeof *s->pts) ||
        n_cells > SIZE_MAX / 2 - n_loops || n_dints > SIZE_MAX / 2 - n_loops - n_cells ||
        reserve(&s->ints, &s->n_ints, &s->cap_ints, n_loops + n_cells + n_dints,
                sizeof *s->ints) ||
        reserve(&s->chars, &s->n_chars, &s->cap_chars, n_chars, 1) ||
        (!share && reserve(&s->bound, &s->n_bound, &s->cap_bound, 1, sizeof *s->bound)))
        return 301;
    gks_seg_rec *r = &s->rec[s->n_rec++];
    *r = (gks_seg_rec){ .kind = p->kind, .n_loops = (int)n_loops, .n_points = (int)n_pts,
                        .clip = p->clip, .pts_off = s->n_pts, .loops_off = s->n_ints,
                        .cells_off = s->n_ints + n_loops, .str_off = s->n_chars,
                        .str_len = (int)n_chars, .n_dints = (int)n_dints,
                        .dints_off = s->n_ints + n_loops + n_cells,
                        .cell_p = p->cell_p, .cell_q = p->cell_q,
                        .cell_r = p->cell_r };
    if (n_cells) {
        r->cell_nx = p->cell_nx;
        r->cell_ny = p->cell_ny;
    }
    memcpy(r->clip_box, p->clip_box, sizeof r->clip_box);
    if (n_pts)
        memcpy(s->pts + s->n_pts, p->pts, n_pts * sizeof *p->pts);
    s->n_pts += n_pts;
    if (n_loops)
        memcpy(s->ints + s->n_ints, p->loop_counts, n_loops * sizeof *s->ints);
    if (n_cells)
        memcpy(s->ints + s->n_ints + n_loops, p->cell_colr, n_cells * sizeof *s->ints);
    if (n_dints)
        memcpy(s->ints + s->n_ints + n_loops + n_cells, p->dints, n_dints * sizeof *s->ints);
    s->n_ints += n_loops + n_cells + n_dints;
    if (n_chars)
        memcpy(s->chars + s->n_chars, p->str, n_chars);
    s->n_chars += n_chars;
    if (!share)
        s->bound[s->n_bound++] = *p->bound;
    r->bound_ind = s->n_bound - 1;
    return 0;
}

size_t gks_seg_count(const gks_segment *s)
{
    return s->n_rec;
}

void gks_seg_get(const gks_segment *s, size_t i, gks_seg_prim *p)
{
    const gks_seg_rec *r = &s->rec[i];
    *p = (gks_seg_prim){ .kind = r->kind, .n_loops = r->n_loops ? r->n_loops : 1,
                         .loop_counts = r->n_loops ? s->ints + r->loops_off : NULL,
                         .n_points = r->n_points,
                         .pts = s->pts ? s->pts + r->pts_off : NULL, /* no NULL + 0 */
                         .cell_p = r->cell_p, .cell_q = r->cell_q, .cell_r = r->cell_r,
                         .cell_nx = r->cell_nx, .cell_ny = r->cell_ny,
                         .cell_colr = r->cell_nx ? s->ints + r->cells_off : NULL,
                         .str = r->str_len ? s->chars + r->str_off : NULL,
                         .str_len = r->str_len, .bound = &s->bound[r->bound_ind],
                         .dints = r->n_dints ? s->ints + r->dints_off : NULL,
                         .n_dints = r->n_dints,
                         .clip = r->clip };
    memcpy(p->clip_box, r->clip_box, sizeof p->clip_box);
}

int gks_seg_ws_add(gks_segment *s, int ws_id)
{
    if (gks_seg_on_ws(s, ws_id))
        return 0;
    if (s->n_ws >= GKS_MAX_OPEN_WS)
        return 301;
    s->ws[s->n_ws++] = ws_id;
    return 0;
}

void gks_seg_ws_remove(gks_segment *s, int ws_id)
{
    for (int i = 0; i < s->n_ws; i++) {
        if (s->ws[i] == ws_id) {
            memmove(s->ws + i, s->ws + i + 1, (size_t)(s->n_ws - i - 1) * sizeof *s->ws);
            s->n_ws--;
            return;
        }
    }
}

int gks_seg_on_ws(const gks_segment *s, int ws_id)
{
    for (int i = 0; i < s->n_ws; i++)
        if (s->ws[i] == ws_id)
            return 1;
    return 0;
}

size_t gks_seg_draw_order(const gks_seg_store *st, int ws_id, gks_segment **out)
{
    size_t n = 0;
    for (size_t i = 0; i < st->n; i++) {
        gks_segment *s = st->seg[i];
        if (!gks_seg_on_ws(s, ws_id))
            continue;
        /* insertion sort, stable: creation order kept among equal priorities */
        size_t k = n++;
        while (k > 0 && out[k - 1]->pri > s->pri) {
            out[k] = out[k - 1];
            k--;
        }
        out[k] = s;
    }
    return n;
}
