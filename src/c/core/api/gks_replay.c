/* SPDX-License-Identifier: MIT */
/*
 * gks_replay.c -- segment replay, the stage of the output pipeline that sends stored
 * primitives again: regeneration of a workstation (gks_ws_regenerate), a segment drawn
 * onto one workstation (ASSOCIATE, COPY SEGMENT TO WORKSTATION) and INSERT SEGMENT.
 * Each stored primitive goes through the same stages as a new one (core/pipe/gks_pipe.h,
 * gks_pipe_emit_*), with its segment's transformation and its bound attributes and
 * clipping volume. It calls the output pipeline and the segment store; neither calls it.
 */
#include "gks_replay.h"
#include "gks_alloc.h"
#include "gks_pipe.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <string.h>

/* A stored primitive (NDC3 geometry; TEXT in WC3 through its bound normalization) sent
 * to the target through the affine map S (NDC3 -> NDC3) and clipped at box when clip_on. */
static int emit_stored(gks_pipe_target *t, const double S[3][4], const double box[6],
                       int clip_on, const gks_seg_prim *sp)
{
    gks_pipe_norm nc;
    double sn[3][4];
    gks_xform_mat34_multiply(S, sp->bound->norm, sn); /* WC3 -> final NDC3 */
    if (gks_pipe_norm_from(&nc, sp->kind == GKS_SEG_TEXT ? (const double (*)[4])sn : S, box, clip_on))
        return 0;
    t->a = &sp->bound->attrs;
    memcpy(t->pat_m, sn, sizeof sn);
    size_t n = (size_t)sp->n_points;
    switch (sp->kind) {
    case GKS_SEG_POLYLINE:
        return gks_pipe_emit_polyline(&nc, sp->pts, n, t);
    case GKS_SEG_POLYMARKER:
        return gks_pipe_emit_polymarker(&nc, sp->pts, n, t);
    case GKS_SEG_TEXT: {
        if (n != 3 || sp->str_len < 1)
            return 0;
        char *str = gks_strndup(sp->str, (size_t)sp->str_len);
        if (!str)
            return 300;
        const double pos[3] = { sp->pts[0].x, sp->pts[0].y, sp->pts[0].z };
        const double d0[3] = { sp->pts[1].x, sp->pts[1].y, sp->pts[1].z };
        const double d1[3] = { sp->pts[2].x, sp->pts[2].y, sp->pts[2].z };
        int err = gks_pipe_emit_text(&nc, pos, d0, d1, str, t);
        gks_free(str);
        return err;
    }
    case GKS_SEG_FILL_AREA:
    case GKS_SEG_FILL_AREA_SET: {
        size_t nl = (size_t)sp->n_loops;
        size_t *cnt = gks_alloc_array(nl, sizeof *cnt);
        if (!cnt)
            return 300;
        if (sp->loop_counts)
            for (size_t k = 0; k < nl; k++)
                cnt[k] = (size_t)sp->loop_counts[k];
        else
            cnt[0] = n;
        int err = gks_pipe_emit_area(&nc, nl, cnt, n, sp->pts, sp->kind == GKS_SEG_FILL_AREA_SET, t);
        gks_free(cnt);
        return err;
    }
    case GKS_SEG_CELL_ARRAY: {
        const double pqr[3][3] = { { sp->cell_p.x, sp->cell_p.y, sp->cell_p.z },
                                   { sp->cell_q.x, sp->cell_q.y, sp->cell_q.z },
                                   { sp->cell_r.x, sp->cell_r.y, sp->cell_r.z } };
        return gks_pipe_emit_cell_array(&nc, pqr, sp->cell_nx, sp->cell_ny, sp->cell_colr, t);
    }
    case GKS_SEG_AREA_DATA:
        return gks_pipe_data_emit_stored(&nc, sp, t);
    }
    return 0;
}

int gks_replay_segment(gks_ws *ws, const gks_segment *seg)
{
    int err = 0;
    for (size_t k = 0; k < gks_seg_count(seg) && !err; k++) {
        gks_seg_prim sp;
        gks_seg_get(seg, k, &sp);
        gks_pipe_target t = { .only = ws };
        err = emit_stored(&t, (const double (*)[4])seg->tran, sp.clip_box, sp.clip, &sp);
    }
    return err;
}

int gks_replay_segments(gks_ws *ws)
{
    const gks_seg_store *st = gks_ctx()->sl->segs;
    if (st->n == 0)
        return 0;
    gks_segment **order = gks_alloc_array(st->n, sizeof *order);
    if (!order)
        return 300;
    size_t n = gks_seg_draw_order(st, ws->id, order);
    int err = 0;
    for (size_t i = 0; i < n && !err; i++)
        if (order[i]->vis)
            err = gks_replay_segment(ws, order[i]);
    gks_free(order);
    return err;
}

/* One stored primitive of an inserted segment, mapped by M (segment transformation, then
 * insert transformation), stored into the open segment as a new primitive with the current
 * clipping volume. */
static int insert_record(gks_segment *open, const double M[3][4], const gks_pipe_norm *cur,
                         const gks_seg_prim *sp)
{
    gks_seg_bound *bound = gks_alloc_array(1, sizeof *bound);
    size_t n = (size_t)sp->n_points;
    Gpoint3 *pts = gks_alloc_array(n ? n : 1, sizeof *pts);
    int err = 0;
    if (!bound || !pts) {
        err = 300;
        goto done;
    }
    *bound = *sp->bound;
    gks_xform_mat34_multiply(M, sp->bound->norm, bound->norm);
    for (size_t i = 0; i < n; i++) {
        double p[3] = { sp->pts[i].x, sp->pts[i].y, sp->pts[i].z }, o[3];
        if (sp->kind == GKS_SEG_TEXT)
            memcpy(o, p, sizeof o); /* WC3: the new normalization carries M */
        else
            gks_xform_mat34_point(M, p, o);
        pts[i] = (Gpoint3){ o[0], o[1], o[2] };
    }
    gks_seg_prim np = *sp;
    np.pts = pts;
    np.bound = bound;
    np.clip = cur->clip_on;
    memcpy(np.clip_box, cur->box, sizeof np.clip_box);
    const Gpoint3 *c[3] = { &sp->cell_p, &sp->cell_q, &sp->cell_r };
    Gpoint3 *d[3] = { &np.cell_p, &np.cell_q, &np.cell_r };
    for (int k = 0; k < 3; k++) {
        double p[3] = { c[k]->x, c[k]->y, c[k]->z }, o[3];
        gks_xform_mat34_point(M, p, o);
        *d[k] = (Gpoint3){ o[0], o[1], o[2] };
    }
    err = gks_seg_append(open, &np);
done:
    gks_free(bound);
    gks_free(pts);
    return err;
}

int gks_replay_insert(const gks_segment *seg, const double ins[3][4])
{
    gks_pipe_norm cur;
    if (gks_pipe_norm_setup(&cur, NULL))
        return 308;
    double M[3][4], total[3][4];
    gks_xform_mat34_multiply(ins, seg->tran, M); /* segment transformation first */
    gks_segment *open = cur.seg;
    if (open)
        gks_xform_mat34_multiply(open->tran, M, total);
    else
        memcpy(total, M, sizeof total);
    int err = 0;
    for (size_t k = 0; k < gks_seg_count(seg) && !err; k++) {
        gks_seg_prim sp;
        gks_seg_get(seg, k, &sp);
        if (open && sp.kind == GKS_SEG_AREA_DATA)
            err = gks_pipe_data_insert(open, (const double (*)[4])M, &cur, &sp);
        else if (open)
            err = insert_record(open, (const double (*)[4])M, &cur, &sp);
        gks_pipe_target t;
        gks_pipe_target_current(&t, &cur);
        if (!err)
            err = emit_stored(&t, (const double (*)[4])total, cur.box, cur.clip_on, &sp);
    }
    return err;
}

int gks_ws_regenerate(gks_ws *ws)
{
    /* The picture being replaced is discarded, not written: a regeneration is a new
     * version of the same frame (primitives outside segments are lost, as ISO 7942 says). */
    int err = gks_ws_new_frame(ws);
    if (!err)
        err = gks_replay_segments(ws);
    return err;
}
