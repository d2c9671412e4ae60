/* SPDX-License-Identifier: MIT */
/* core_util.h -- shared helpers of the core tests: a capturing error handler, driving
 * GKS into an operating state, and a snapshot of the state lists. */
#ifndef CORE_UTIL_H
#define CORE_UTIL_H
#include <gks.h>
#include <string.h>

#define MAX_CAPTURED 64
typedef struct { int err, fct; } captured_error;
static captured_error captured[MAX_CAPTURED];
static int n_captured;

static inline void capture_handler(Gint err, Gint fct, const char *file)
{
    (void)file;
    if (n_captured < MAX_CAPTURED)
        captured[n_captured] = (captured_error){ err, fct };
    n_captured++;
}

static inline void capture_reset(void)
{
    n_captured = 0;
    gset_err_hand(capture_handler, NULL);
}

/* Close everything, whatever the state. */
static inline void reset_gks(void)
{
    gemergency_close_gks();
    capture_reset();
}

/* Drive GKS from GKCL into `st` (GKCL, GKOP, WSOP, WSAC, SGOP) with workstation 1 = null
 * and, in SGOP, segment 1 open. */
static inline void enter_state(Gop_st st)
{
    reset_gks();
    if (st >= GST_GKOP)
        gopen_gks(NULL, 0);
    if (st >= GST_WSOP)
        gopen_ws(1, NULL, GWS_TYPE_NULL);
    if (st >= GST_WSAC)
        gactivate_ws(1);
    if (st >= GST_SGOP)
        gcreate_seg(1);
    n_captured = 0;
}

/* What "no other effect" is compared on. */
typedef struct {
    Gop_st op;
    Gint n_open, n_active, open[4], active[4];
    Gint tnr, line_ci, fill_ci;
    Gtran tran1;
    Gint open_seg, n_segs, segs[4];
    Gseg_attrs3 seg1;
} snapshot;

static inline void take_snapshot(snapshot *s)
{
    Gint err, len;
    memset(s, 0, sizeof *s);
    ginq_op_st(&s->op);
    Gint_list l = { 0, s->open };
    ginq_set_open_wss(4, 0, &err, &l, &s->n_open);
    l.ints = s->active;
    ginq_set_active_wss(4, 0, &err, &l, &s->n_active);
    ginq_cur_norm_tran_num(&err, &s->tnr);
    ginq_line_colr_ind(&err, &s->line_ci);
    ginq_fill_colr_ind(&err, &s->fill_ci);
    ginq_norm_tran(1, &err, &s->tran1);
    ginq_name_open_seg(&err, &s->open_seg);
    l.ints = s->segs;
    ginq_set_seg_names(4, 0, &err, &l, &s->n_segs);
    ginq_seg_attrs3(1, &err, &s->seg1);
    (void)len;
}
#endif
