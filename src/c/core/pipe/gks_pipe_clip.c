/* SPDX-License-Identifier: MIT */
/* gks_pipe_clip.c -- the clipping stage (gks_pipe_clip.h). */
#include "gks_pipe_clip.h"
#include "gks_alloc.h"
#include <stdint.h>
#include <string.h>

void gks_pipe_pieces_free(gks_pipe_pieces *b)
{
    gks_free(b->pts);
    gks_free(b->len);
    memset(b, 0, sizeof *b);
}

int gks_pipe_piece_push(gks_pipe_pieces *b, const double h[4])
{
    if (gks_grow(&b->pts, &b->cap, b->n + 1, sizeof *b->pts))
        return 300;
    if (b->np == 0 || b->len[b->np - 1] == INT32_MAX)
        return 300;
    b->pts[b->n++] = (Gpoint3){ h[0], h[1], h[2] };
    b->len[b->np - 1]++;
    return 0;
}

int gks_pipe_piece_new(gks_pipe_pieces *b)
{
    if (gks_grow(&b->len, &b->capp, b->np + 1, sizeof *b->len))
        return 300;
    b->len[b->np++] = 0;
    return 0;
}

int gks_pipe_clip_polyline(const gks_pipe_norm *nc, const gks_pipe_src *s, size_t n,
                           gks_pipe_pieces *b)
{
    double prev[4] = { 0 }, cur[4], wc[3];
    int prev_ok = 0, prev_in = 0, open = 0;
    for (size_t i = 0; i < n; i++) {
        gks_pipe_src_get(s, i, wc);
        int ok = gks_pipe_to_ndc(nc, wc, cur);
        int in = ok && gks_pipe_visible(nc, cur); /* both ends in: nothing to clip */
        if (ok && prev_ok) {
            double a[4] = { prev[0], prev[1], prev[2], 1 }, e[4] = { cur[0], cur[1], cur[2], 1 };
            int ma = 0, mb = 0; /* plane by plane at the viewport 3 (gks_xform.h) */
            int vis = (in && prev_in) || gks_xform_clip_segment(&nc->clip, a, e, &ma, &mb);
            if (vis) {
                if (!(open && !ma)) {
                    if (gks_pipe_piece_new(b) || gks_pipe_piece_push(b, a))
                        return 300;
                }
                if (gks_pipe_piece_push(b, e))
                    return 300;
            }
            open = vis && !mb;
        } else {
            open = 0;
        }
        if (ok)
            memcpy(prev, cur, sizeof prev);
        prev_ok = ok;
        prev_in = in;
    }
    return 0;
}

void gks_pipe_loops_free(gks_pipe_loops *a)
{
    gks_free(a->pts);
    gks_free(a->counts);
    memset(a, 0, sizeof *a);
}

int gks_pipe_clip_area(const gks_pipe_norm *nc, size_t nloops, const size_t *cnt, size_t n,
                       const Gpoint3 *pts, gks_pipe_loops *res)
{
    double (*h)[4] = gks_alloc_array(n, sizeof *h);
    size_t *out_len = gks_alloc_array(nloops, sizeof *out_len);
    double (*out)[4] = NULL;
    Gpoint3 *cp = NULL;
    int *counts = NULL;
    int err = 0;
    memset(res, 0, sizeof *res);
    if (!h || !out_len) {
        err = 300;
        goto done;
    }
    for (size_t i = 0; i < n; i++) {
        h[i][0] = pts[i].x; h[i][1] = pts[i].y; h[i][2] = pts[i].z; h[i][3] = 1.0;
    }
    size_t n_out = 0;
    int r = gks_xform_clip_polygon(&nc->clip, nloops, cnt, (const double (*)[4])h, NULL, 0,
                                   out_len, &n_out);
    if ((r != 0 && r != 300) || n_out < 3)
        goto done;
    out = gks_alloc_array(n_out, sizeof *out);
    cp = gks_alloc_array(n_out, sizeof *cp);
    counts = gks_alloc_array(nloops, sizeof *counts);
    if (!out || !cp || !counts) {
        err = 300;
        goto done;
    }
    if (gks_xform_clip_polygon(&nc->clip, nloops, cnt, (const double (*)[4])h, out, n_out,
                               out_len, &n_out))
        goto done;
    size_t m = 0, src_off = 0;
    int nl = 0;
    for (size_t k = 0; k < nloops; k++) {
        if (out_len[k] >= 3 && out_len[k] <= INT32_MAX) {
            for (size_t i = 0; i < out_len[k]; i++)
                cp[m + i] = (Gpoint3){ out[src_off + i][0], out[src_off + i][1],
                                       out[src_off + i][2] };
            m += out_len[k];
            counts[nl++] = (int)out_len[k];
        }
        src_off += out_len[k];
    }
    if (nl > 0 && m <= INT32_MAX) {
        res->pts = cp;
        res->counts = counts;
        res->nl = nl;
        res->m = (int)m;
        cp = NULL;
        counts = NULL;
    }
done:
    gks_free(h);
    gks_free(out_len);
    gks_free(out);
    gks_free(cp);
    gks_free(counts);
    return err;
}
