/* SPDX-License-Identifier: MIT */
/*
 * gks_control.c -- control functions (ISO 7942 5.2): OPEN/CLOSE GKS, OPEN/CLOSE/ACTIVATE/
 * DEACTIVATE/CLEAR/UPDATE WORKSTATION, REDRAW ALL SEGMENTS ON WORKSTATION, SET DEFERRAL
 * STATE, MESSAGE, ESCAPE, EMERGENCY CLOSE GKS. Each entry point: state check, argument
 * checks in the standard's order (error -> report, no other effect), then the work.
 */
#include "gks_legacy.h"
#include "gks_record.h"
#include "gks_alloc.h"
#include "gks_binding.h"
#include "gks_error.h"
#include "gks_result_mem.h"
#include "gks_mf_record.h"
#include "gks_par.h"
#include "gks_seg_store.h"
#include "gks_segment.h"
#include "gks_replay.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <stdio.h>
#include <errno.h>
#include <string.h>

#define MAX_CONN_LEN 4096

static void init_state_list(gks_state_list *sl)
{
    gks_cur_attrs *a = gks_attrs_w_of(sl);
    gks_attr_init(a);
    a->line_colr_ind = 1;
    a->fill_colr_ind = 1;
    for (int k = 0; k < 2; k++) {
        a->area_props[k] = (Garea_props){ 1, 1, 0, { 1, 1, 1 }, 1, 0, 1 };
        a->refl_eq[k] = GREFL_NONE;
    }
    a->light_mask = 0;
    for (int i = 0; i < GKS_N_ASF; i++)
        a->asf[i] = gks_legacy_asf(); /* GKS3D_ASF (legacy programs) */
    for (int i = 0; i <= GKS_MAX_NORM_TRAN; i++) {
        sl->tran_pri[i] = i; /* 0 highest, then ascending numbers (ISO 7942 6.4) */
        sl->tran[i].win = (Glimit3){ 0, 1, 0, 1, 0, 1 };
        sl->tran[i].vp = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    }
    sl->cur_tnr = 0;
    sl->clip_ind = GIND_CLIP;
}

/* Shared by gopen_gks and gks_open_gks_unit. err_name: what ERROR HANDLING receives;
 * open_file: whether C opens err_name as the error file. Its state check claims GKS for
 * the calling thread (open_gks gives it up again when GKS stays closed). */
static void open_gks_claimed(const char *err_name, int open_file)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_OPKS))
        return;
    gks_par_start(NULL); /* MPI build under mpirun: MPI up on every rank (docs/MPI.md) */
    FILE *fp = NULL;
    /* "stdout" and "stderr" name the streams (NCAR's C programs pass "stdout"), not files
     * of that name; stderr is the default error file anyway. */
    if (open_file && err_name && strcmp(err_name, "stdout") == 0)
        fp = stdout;
    else if (open_file && err_name && *err_name && strcmp(err_name, "stderr") != 0) {
        char *path = NULL; /* MPI rank R > 0: err_name.R */
        if (gks_par_rank() > 0 && !(path = gks_par_rank_path(err_name)))
            GKS_FAIL(300, GFN_OPKS);
        fp = fopen(path ? path : err_name, "a");
        if (!fp) /* reported on standard error: the error file is what failed */
            gks_error_note("cannot open error file \"%s\": %s", path ? path : err_name,
                           strerror(errno));
        gks_free(path);
        if (!fp)
            GKS_FAIL(200, GFN_OPKS);
    }
    gks_state_list *sl = gks_calloc_array(1, sizeof *sl);
    gks_seg_store *segs = gks_calloc_array(1, sizeof *segs);
    char *name = (err_name && *err_name) ? gks_strdup(err_name) : NULL;
    if (!sl || !segs || (err_name && *err_name && !name)) {
        gks_free(sl);
        gks_free(segs);
        gks_free(name);
        if (fp && fp != stdout)
            fclose(fp);
        GKS_FAIL(300, GFN_OPKS);
    }
    gks_legacy_load(); /* GKS3D_WS_TYPES, GKS3D_ASF */
    init_state_list(sl);
    gks_seg_store_init(segs);
    sl->segs = segs;
    sl->err_file = name;
    c->sl = sl;
    c->err.fp = fp;
    c->op_st = GST_GKOP;
    gks_record_open(); /* GKS3D_RECORD */
    const gks_profile *prof = gks_legacy_profile(); /* a foreign GKS's initial state */
    if (prof && prof->opened_gks)
        prof->opened_gks();
}

static void open_gks(const char *err_name, int open_file)
{
    open_gks_claimed(err_name, open_file);
    /* ownership first: a refused call must not read the owner's state */
    if (gks_thread_mine() && gks_ctx()->op_st == GST_GKCL)
        gks_thread_release();
}

GKS_API void gopen_gks(const char *err_file, size_t mem_unit)
{
    (void)mem_unit; /* memory is allocated on demand */
    open_gks(err_file, 1);
}

GKS_API void gks_open_gks_unit(int err_unit, size_t mem_unit)
{
    char name[24];
    (void)mem_unit;
    snprintf(name, sizeof name, "%d", err_unit);
    open_gks(name, 0);
}

static void close_gks(gks_context *c)
{
    gks_record_close(); /* GKS3D_RECORD's file complete */
    gks_world_changed(); /* every state list is gone */
    if (c->err.fp && c->err.fp != stdout)
        fclose(c->err.fp);
    c->err.fp = NULL;
    gks_free(c->sl->err_file);
    gks_in_reset();
    gks_seg_store_free(c->sl->segs);
    gks_free(c->sl->segs);
    gks_free(c->sl);
    c->sl = NULL;
    c->op_st = GST_GKCL;
    gks_thread_release(); /* any thread may open GKS now */
}

GKS_API void gclose_gks(void)
{
    if (gks_check_state(GFN_CLKS))
        return;
    close_gks(gks_ctx());
}

GKS_API void gopen_ws(Gint ws_id, const char *conn_id, Gint ws_type)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_OPWK))
        return;
    if (ws_id < 0)
        GKS_FAIL(20, GFN_OPWK);
    if (gks_ws_lookup(ws_id))
        GKS_FAIL(24, GFN_OPWK);
    if (conn_id && strnlen(conn_id, MAX_CONN_LEN + 1) > MAX_CONN_LEN)
        GKS_FAIL(21, GFN_OPWK);
    if (gks_ws_type_map(ws_type) <= 0)
        GKS_FAIL(22, GFN_OPWK);
    const gks_ws_driver *drv = gks_driver_for_type(ws_type);
    if (!drv)
        GKS_FAIL(23, GFN_OPWK);
    if (c->sl->n_open >= c->desc->max_nums.simult_open)
        GKS_FAIL(42, GFN_OPWK);
    if (drv->desc->cat == GCAT_WISS && gks_wiss())
        GKS_FAIL(28, GFN_OPWK);
    /* NCAR's ESCAPE -1391 names the next file workstation (gks_legacy.h). */
    char *ncar_name = gks_legacy_take_file_name(drv->file != NULL);
    gks_ws *ws = gks_ws_create(ws_id, ncar_name ? ncar_name : conn_id, drv);
    gks_free(ncar_name);
    if (!ws)
        GKS_FAIL(300, GFN_OPWK);
    int err = gks_ws_file_check(ws);
    if (!err && drv->open)
        err = drv->open(ws);
    if (err) {
        gks_ws_destroy(ws);
        GKS_FAIL(err, GFN_OPWK);
    }
    c->ws[c->sl->n_open] = ws;
    c->sl->open_ws[c->sl->n_open++] = ws_id;
    if (c->op_st == GST_GKOP)
        c->op_st = GST_WSOP;
    gks_record_sync(-1);
    const gks_profile *prof = gks_legacy_profile(); /* a foreign GKS's tables */
    if (prof && prof->opened_ws)
        prof->opened_ws(ws_id);
}

GKS_API void gclose_ws(Gint ws_id)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_CLWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_CLWK, ws_id, 0);
    if (!ws)
        return;
    if (ws->state == GWS_ACTIVE)
        GKS_FAIL(29, GFN_CLWK);
    int err = ws->drv->update ? ws->drv->update(ws) : 0;
    int ferr = ws->drv->finish ? ws->drv->finish(ws) : 0;
    if (!err)
        err = ferr;
    if (ws->drv->close)
        ws->drv->close(ws);
    gks_segment_ws_closed(ws_id);
    gks_state_list *sl = c->sl;
    for (int i = 0; i < sl->n_open; i++) {
        if (sl->open_ws[i] != ws_id)
            continue;
        memmove(&sl->open_ws[i], &sl->open_ws[i + 1], (size_t)(sl->n_open - i - 1) * sizeof sl->open_ws[0]);
        memmove(&c->ws[i], &c->ws[i + 1], (size_t)(sl->n_open - i - 1) * sizeof c->ws[0]);
        sl->n_open--;
        c->ws[sl->n_open] = NULL;
        break;
    }
    gks_ws_destroy(ws);
    gks_world_changed();
    if (sl->n_open == 0)
        c->op_st = GST_GKOP;
    gks_record_sync(ws_id); /* the recorded frame of ws_id ends */
    if (err) /* the workstation is closed; the failed final write is still reported */
        GKS_FAIL(err, GFN_CLWK);
}

GKS_API void gactivate_ws(Gint ws_id)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_ACWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_ACWK, ws_id, 0);
    if (!ws)
        return;
    if (ws->state == GWS_ACTIVE)
        GKS_FAIL(29, GFN_ACWK);
    if (ws->drv->desc->cat == GCAT_MI)
        GKS_FAIL(33, GFN_ACWK);
    if (ws->drv->desc->cat == GCAT_IN)
        GKS_FAIL(35, GFN_ACWK);
    if (c->sl->n_active >= c->desc->max_nums.simult_active)
        GKS_FAIL(43, GFN_ACWK);
    ws->state = GWS_ACTIVE;
    c->sl->active_ws[c->sl->n_active++] = ws_id;
    c->op_st = GST_WSAC;
    gks_mf_recount();
    gks_record_sync(-1);
}

GKS_API void gdeactivate_ws(Gint ws_id)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_DAWK))
        return;
    if (ws_id < 0)
        GKS_FAIL(20, GFN_DAWK);
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws || ws->state != GWS_ACTIVE)
        GKS_FAIL(30, GFN_DAWK);
    ws->state = GWS_INACTIVE;
    gks_state_list *sl = c->sl;
    for (int i = 0; i < sl->n_active; i++) {
        if (sl->active_ws[i] != ws_id)
            continue;
        memmove(&sl->active_ws[i], &sl->active_ws[i + 1], (size_t)(sl->n_active - i - 1) * sizeof sl->active_ws[0]);
        sl->n_active--;
        break;
    }
    if (sl->n_active == 0)
        c->op_st = GST_WSOP;
    gks_mf_recount();
    gks_record_sync(-1);
}

GKS_API void gclear_ws(Gint ws_id, Gctrl_flag ctrl_flag)
{
    if (gks_check_state(GFN_CLRWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_CLRWK, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT);
    if (!ws)
        return;
    if (ctrl_flag != GFLAG_COND && ctrl_flag != GFLAG_ALWAYS)
        GKS_FAIL(2000, GFN_CLRWK);
    GKS_MF_WS(CLRWK, ws_id, ctrl_flag);
    if (ctrl_flag == GFLAG_COND && ws->disp_empty == GDISP_EMPTY &&
        ws->tran_upd_st == GUPD_NOT_PEND)
        return;
    /* ISO 7942 CLEAR WORKSTATION: the picture is finished, the surface cleared, and the
     * segments stored on the workstation are deleted from it (and deleted where stored
     * nowhere else). */
    int err = ws->drv->update ? ws->drv->update(ws) : 0;
    gks_segment_ws_closed(ws_id);
    if (!err)
        err = gks_ws_new_frame(ws);
    if (err)
        GKS_FAIL(err, GFN_CLRWK);
}

GKS_API void gredraw_all_seg_ws(Gint ws_id)
{
    if (gks_check_state(GFN_RSGWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_RSGWK, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    GKS_MF_WS0(RSGWK, ws_id);
    /* ISO 7942: apply a pending workstation transformation, clear the surface, redraw
     * all visible segments stored on the workstation. */
    int err = gks_ws_regenerate(ws);
    if (err)
        GKS_FAIL(err, GFN_RSGWK);
}

GKS_API void gupd_ws(Gint ws_id, Gupd_regen_flag upd_regen_flag)
{
    if (gks_check_state(GFN_UWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_UWK, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (upd_regen_flag != GFLAG_POSTPONE && upd_regen_flag != GFLAG_PERFORM)
        GKS_FAIL(2000, GFN_UWK);
    GKS_MF_WS(UWK, ws_id, upd_regen_flag);
    int err = 0;
    if (upd_regen_flag == GFLAG_PERFORM && ws->new_frame == GNEW_YES)
        err = gks_ws_regenerate(ws);
    if (!err && ws->drv->update)
        err = ws->drv->update(ws);
    if (err)
        GKS_FAIL(err, GFN_UWK);
}

GKS_API void gset_defer_st(Gint ws_id, Gdefer_mode defer_mode, Girg_mode irg_mode)
{
    if (gks_check_state(GFN_SDS))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SDS, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if ((unsigned)defer_mode > GDEFER_ASTI || (unsigned)irg_mode > GIRG_ALLOWED)
        GKS_FAIL(2000, GFN_SDS);
    ws->defer_mode = defer_mode;
    ws->irg_mode = irg_mode;
    GKS_MF_WS(SDS, ws_id, defer_mode, irg_mode);
    if (irg_mode == GIRG_ALLOWED && ws->new_frame == GNEW_YES) {
        int err = gks_ws_regenerate(ws);
        if (err)
            GKS_FAIL(err, GFN_SDS);
    }
}

GKS_API void gmessage(Gint ws_id, const char *msg)
{
    if (gks_check_state(GFN_MSG))
        return;
    gks_ws *ws = gks_ws_checked(GFN_MSG, ws_id, GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    GKS_MF_WS(MSG, ws_id, msg);
    int err = ws->drv->message ? ws->drv->message(ws, msg ? msg : "") : 0;
    if (err)
        GKS_FAIL(err, GFN_MSG);
}

/* The escapes that return data (their output record is placed in the caller's store). */
static int escape_has_output(Gint func_id) { return func_id == GESC_RT_STATS; }

#define GKS_ESC_OUT_CAP 64 /* integers and reals an escape may return */

GKS_API void gescape(Gint func_id, const Gescape_in_data *in, Gstore *store_data,
                     Gescape_out_data **out_data)
{
    if (out_data)
        *out_data = NULL;
    if (gks_check_state(GFN_ESC))
        return;
    if (func_id == GESC_INPUT_SCRIPT) { /* the core's: input devices are the core's */
        /* 182 without a workstation identifier, 25 when it names no open workstation */
        int has_id = in && in->num_ints >= 1 && in->ints;
        gks_ws *iws = has_id ? gks_ws_lookup(in->ints[0]) : NULL;
        int e = iws ? gks_in_script_attach(iws, in->str, in->str ? in->str_len : 0)
                    : has_id ? 25 : 182;
        if (e)
            GKS_FAIL(e, GFN_ESC);
        return;
    }
    if (func_id == GESC_NCAR_FILE_NAME || func_id == GESC_NCAR_PAUSE) { /* gks_legacy.h */
        int pid;
        int e = gks_legacy_escape(func_id, in, &pid);
        gks_ws *pws = !e && pid >= 0 ? gks_ws_lookup(pid) : NULL;
        if (!e && func_id == GESC_NCAR_PAUSE && !pws)
            e = 182; /* the record names no open workstation */
        if (!e && pws) /* NCAR's pause: UPDATE WORKSTATION (PERFORM), nobody to wait for */
            e = pws->new_frame == GNEW_YES ? gks_ws_regenerate(pws) : 0;
        if (!e && pws && pws->drv->update)
            e = pws->drv->update(pws);
        if (e)
            GKS_FAIL(e, GFN_ESC);
        return;
    }
    const gks_profile *prof = gks_legacy_profile(); /* a foreign GKS's escapes */
    if (prof && prof->escape) {
        Gescape_out_data *pout = NULL;
        if (store_data && *store_data) {
            pout = gks_result_alloc(*store_data, 1, sizeof *pout + GKS_PROFILE_ESC_OUT);
            if (!pout)
                GKS_FAIL(300, GFN_ESC);
            memset(pout, 0, sizeof *pout);
            pout->escape_r1.data = pout + 1;
            pout->escape_r1.size = GKS_PROFILE_ESC_OUT;
            memset(pout->escape_r1.data, ' ', GKS_PROFILE_ESC_OUT);
        }
        int e = prof->escape(func_id, in, pout);
        if (e > 0)
            GKS_FAIL(e, GFN_ESC);
        if (e == 0) {
            if (out_data)
                *out_data = pout;
            return;
        }
    }
    /* Identifiers this implementation knows: the driver checks the rest of the record. */
    if ((func_id > GESC_SET_FILE_NAME || func_id < GESC_VEC_PAGE) &&
        func_id != GESC_MI_ALLOW_ESCAPES)
        GKS_FAIL(180, GFN_ESC);
    if (!in || in->num_ints < 1 || !in->ints)
        GKS_FAIL(182, GFN_ESC);
    if (func_id == GESC_SET_FILE_NAME && (!in->str || in->str_len == 0))
        GKS_FAIL(182, GFN_ESC);
    gks_ws *ws = gks_ws_lookup(in->ints[0]);
    if (!ws)
        GKS_FAIL(182, GFN_ESC);
    if (gks_mf_escape(GFN_ESC, ws, func_id, in))
        return; /* addressed to an MO workstation: recorded (or its failure reported) */
    Gescape_out_data *out = NULL;
    if (escape_has_output(func_id) && store_data && *store_data) {
        /* One block in the store: the record, then its integer and real arrays. */
        size_t n = sizeof *out + GKS_ESC_OUT_CAP * (sizeof(Gint) + sizeof(Gfloat));
        out = gks_result_alloc(*store_data, 1, n);
        if (!out)
            GKS_FAIL(300, GFN_ESC);
        out->num_ints = GKS_ESC_OUT_CAP;
        out->ints = (Gint *)(out + 1);
        out->num_floats = GKS_ESC_OUT_CAP;
        out->floats = (Gfloat *)(out->ints + GKS_ESC_OUT_CAP);
    }
    int err = ws->drv->escape ? ws->drv->escape(ws, func_id, in, out) : 180;
    if (err)
        GKS_FAIL(err, GFN_ESC);
    gks_record_escape(ws->id, func_id, in); /* GKS3D_RECORD: the picture's settings */
    if (out_data)
        *out_data = out;
}

GKS_API void gemergency_close_gks(void)
{
    if (!gks_thread_mine()) { /* another thread's GKS: not this thread's to close */
        gks_thread_refused(-1);
        return;
    }
    gks_context *c = gks_ctx();
    if (c->op_st == GST_GKCL)
        return;
    gks_state_list *sl = c->sl;
    while (sl->n_open > 0) {
        gks_ws *ws = c->ws[--sl->n_open];
        if (ws->drv->update)
            ws->drv->update(ws);
        if (ws->drv->close)
            ws->drv->close(ws);
        gks_ws_destroy(ws);
        c->ws[sl->n_open] = NULL;
    }
    sl->n_active = 0;
    close_gks(c);
}
