/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_norm.c -- the normalization stage (gks_pipe_norm.h). The current state's
 * context is kept with what it was made from and reused while those settings stay the
 * same (a FILL AREA 3 per triangle would otherwise make it on every call).
 */
#include "gks_pipe_norm.h"
#include "gks_context.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include <stdint.h>
#include <string.h>

/* Whether n doubles are the same bit for bit (as memcmp, inline: it runs per primitive). */
static int same_bits(const double *a, const double *b, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        uint64_t x, y;
        memcpy(&x, &a[i], sizeof x);
        memcpy(&y, &b[i], sizeof y);
        if (x != y)
            return 0;
    }
    return 1;
}

/* Whether the normalization transformations a and b (window and viewport 3, 12 doubles)
 * are the same bit for bit: every pair compared, no early exit (a reduction the compiler
 * makes in vector registers; it runs per primitive). */
static int same_tran(const gks_norm_tran *a, const gks_norm_tran *b)
{
    enum { N = sizeof(gks_norm_tran) / sizeof(uint64_t) };
    _Static_assert(sizeof(gks_norm_tran) == 12 * sizeof(double), "no padding in gks_norm_tran");
    const unsigned char *pa = (const unsigned char *)a, *pb = (const unsigned char *)b;
    uint64_t d = 0;
    for (size_t i = 0; i < N; i++) {
        uint64_t x, y;
        memcpy(&x, pa + i * sizeof x, sizeof x);
        memcpy(&y, pb + i * sizeof y, sizeof y);
        d |= x ^ y;
    }
    return d == 0;
}

/* The open segment, or NULL. */
static gks_segment *open_segment(void)
{
    const gks_state_list *sl = gks_ctx()->sl;
    return sl->open_seg ? gks_seg_find(sl->segs, sl->open_seg) : NULL;
}

void gks_pipe_norm_facts(gks_pipe_norm *nc)
{
    const double (*m)[4] = (const double (*)[4])nc->m;
    const double *b = nc->box;
    nc->axis_aligned = m[0][1] == 0 && m[0][2] == 0 && m[1][0] == 0 && m[1][2] == 0 &&
                       m[2][0] == 0 && m[2][1] == 0;
    /* the sum is finite only if each limit is (an overflow only means the points' own
     * checks are made) */
    nc->box_finite = nc->clip_on && isfinite(((b[0] + b[1]) + (b[2] + b[3])) + (b[4] + b[5]));
}

int gks_pipe_norm_from(gks_pipe_norm *nc, const double m[3][4], const double box[6], int clip_on)
{
    memcpy(nc->m, m, sizeof nc->m);
    memcpy(nc->n, m, sizeof nc->n);
    memcpy(nc->pn, m, sizeof nc->pn);
    memcpy(nc->pat, m, sizeof nc->pat);
    memcpy(nc->box, box, sizeof nc->box);
    nc->clip_on = clip_on;
    nc->seg = NULL;
    gks_pipe_norm_facts(nc);
    gks_xform_clip_init(&nc->clip);
    nc->clip.wmin = 0.0; /* NDC3 points have w = 1: no eye plane to keep off */
    if (clip_on && gks_xform_clip_add_box(&nc->clip, box, GKS_XFORM_CLIP_ALL))
        return -1;
    return 0;
}

/* The last current-state context and what it was made from (the current window and
 * viewport 3, clipping indicator, open segment and its transformation), compared by
 * value, so no setting function needs to know of it; not used for a recorded
 * normalization (INTERPRET ITEM). */
static struct {
    int valid;
    gks_norm_tran tr; /* the current window and viewport 3, as the state list holds them */
    int clip_on;
    const gks_segment *seg;
    double stran[3][4];
    gks_pipe_norm nc;
} norm_cache;

/* Whether the cache holds the current state's context (seg: the open segment). */
static int cache_current(const gks_state_list *sl, const gks_segment *seg)
{
    const gks_norm_tran *tr = &sl->tran[sl->cur_tnr];
    return norm_cache.valid && norm_cache.clip_on == (sl->clip_ind == GIND_CLIP) &&
           norm_cache.seg == seg && same_tran(&norm_cache.tr, tr) &&
           (!seg || same_bits(&norm_cache.stran[0][0], &seg->tran[0][0], 12));
}

/* WC3 -> NDC3 by the current normalization transformation, then the open segment's
 * transformation (if a segment is open), clipping at the current viewport 3 when the
 * clipping indicator is on. For a recorded normalization (ov), its matrix and clipping
 * volume replace the current ones, and NDC3 points enter through the identity. Made here
 * when the cache does not hold it (gks_pipe_norm_get, which runs per primitive, checks). */
#if defined(__GNUC__)
__attribute__((noinline)) /* apart: the cache's hit, per primitive, stays a short leaf */
#endif
static int norm_make(const gks_pipe_norm **ncp, gks_pipe_norm *nc, const gks_rec_xf *ov)
{
    static const double id[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
    const gks_state_list *sl = gks_ctx()->sl;
    double n[3][4], box[6], w[6];
    int clip_on;
    gks_segment *seg = open_segment();
    if (ov) {
        memcpy(n, ov->norm, sizeof n);
        memcpy(box, ov->box, sizeof box);
        clip_on = ov->clip_on;
    } else {
        const gks_norm_tran *tr = &sl->tran[sl->cur_tnr];
        clip_on = sl->clip_ind == GIND_CLIP;
        gks_limit3_array(&tr->win, w);
        gks_limit3_array(&tr->vp, box);
        norm_cache.valid = 0;
        if (gks_xform_norm_tran3(w, box, n)) /* gks_cur_norm_matrix */
            return 308;
    }
    const double (*pm)[4] = ov && ov->ndc_pts ? id : (const double (*)[4])n;
    if (gks_pipe_norm_from(nc, pm, box, clip_on))
        return 308;
    nc->seg = seg;
    memcpy(nc->n, n, sizeof nc->n);
    memcpy(nc->pat, n, sizeof nc->pat);
    if (seg) {
        gks_xform_mat34_multiply(seg->tran, pm, nc->m);
        gks_xform_mat34_multiply(seg->tran, n, nc->pat);
        gks_pipe_norm_facts(nc);
    }
    if (!ov) {
        norm_cache.tr = sl->tran[sl->cur_tnr];
        norm_cache.clip_on = clip_on;
        norm_cache.seg = seg;
        if (seg)
            memcpy(norm_cache.stran, seg->tran, sizeof norm_cache.stran);
        norm_cache.nc = *nc;
        norm_cache.valid = 1;
    }
    *ncp = nc;
    return 0;
}

int gks_pipe_norm_get(const gks_pipe_norm **ncp, gks_pipe_norm *nc, const gks_rec_xf *ov)
{
    if (!ov && cache_current(gks_ctx()->sl, open_segment())) {
        *ncp = &norm_cache.nc;
        return 0;
    }
    return norm_make(ncp, nc, ov);
}

int gks_pipe_norm_setup(gks_pipe_norm *nc, const gks_rec_xf *xf)
{
    const gks_pipe_norm *p;
    int err = gks_pipe_norm_get(&p, nc, xf);
    if (!err && p != nc)
        *nc = *p;
    return err;
}
