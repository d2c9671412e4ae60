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

/* Clip the segment a-b to the viewport box (clipping on) plane by plane, each
 * intersection computed from the segment already shortened by the previous planes and
 * the clipped coordinate set exactly on the plane, so a segment from -1e30 to 1e30 keeps
 * its visible part. The xform clipper (gks_xform_clip_*: the areas here, the
 * drivers' view clip) keeps it too, computing each crossing from the nearer end, but does
 * not put the clipped coordinate exactly on the plane; replacing this one by it may move
 * pixels of the reference pictures and is left open.
 * Returns 1 if a part survives; *moved_a / *moved_b say whether an end was moved. */
static int clip_segment(const gks_pipe_norm *nc, double a[3], double b[3], int *moved_a,
                        int *moved_b)
{
    *moved_a = *moved_b = 0;
    if (!nc->clip_on)
        return 1;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            double lim = nc->box[2 * axis + side];
            double sg = side ? -1.0 : 1.0; /* inside: sg * (x - lim) >= 0 */
            double da = sg * (a[axis] - lim), db = sg * (b[axis] - lim);
            if (da < 0 && db < 0)
                return 0;
            if (da >= 0 && db >= 0)
                continue;
            double t = da / (da - db);
            double *moved = da < 0 ? a : b;
            const double *p = da < 0 ? a : b, *q = da < 0 ? b : a;
            double tt = da < 0 ? t : 1.0 - t; /* from p towards q */
            double r[3];
            for (int k = 0; k < 3; k++)
                r[k] = p[k] + tt * (q[k] - p[k]);
            r[axis] = lim;
            if (!isfinite(r[0]) || !isfinite(r[1]) || !isfinite(r[2]))
                return 0; /* overflow near DBL_MAX: treated as not visible */
            memcpy(moved, r, sizeof r);
            if (da < 0)
                *moved_a = 1;
            else
                *moved_b = 1;
        }
    return 1;
}

int gks_pipe_clip_polyline(const gks_pipe_norm *nc, const gks_pipe_src *s, size_t n,
                           gks_pipe_pieces *b)
{
    double prev[4] = { 0 }, cur[4], wc[3];
    int prev_ok = 0, open = 0;
    for (size_t i = 0; i < n; i++) {
        gks_pipe_src_get(s, i, wc);
        int ok = gks_pipe_to_ndc(nc, wc, cur);
        if (ok && prev_ok) {
            double a[4] = { prev[0], prev[1], prev[2], 1 }, e[4] = { cur[0], cur[1], cur[2], 1 };
            int ma, mb;
            int vis = clip_segment(nc, a, e, &ma, &mb);
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
