/* SPDX-License-Identifier: MIT */
/*
 * gks_record.c -- the recorder of GKS3D_RECORD (gks_record.h). It is an ordinary MO
 * workstation state list kept in the context beside the program's workstations
 * (gks_context.rec_ws), so the metafile hooks (core/store/gks_mf_record.c) write to it and
 * nothing else of GKS sees it: not the set of open or active workstations, not the
 * workstation identifiers, not OPEN WORKSTATION's limits, not segments or input.
 */
#include "gks_record.h"
#include "gks_mf_record.h"
#include "gks_par.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <stdio.h>
#include <stdlib.h>

#define REC_WS_ID GKS_REC_WS_ID

/* Whether ws is one of the program's picture workstations (category OUTPUT or OUTIN). */
static int is_output(const gks_ws *ws)
{
    Gws_cat cat = ws->drv->desc->cat;
    return cat == GCAT_OUT || cat == GCAT_OUTIN;
}

/* A program that ends without CLOSE GKS (a legacy program's STOP, or PAUSE answered with
 * end of file) still leaves a complete metafile: END item written and file closed at exit.
 * Only the recorder is touched (the program's workstations are the program's). */
static void record_at_exit(void)
{
    if (gks_ctx()->rec_ws)
        gks_record_close();
}

void gks_record_open(void)
{
    static int at_exit;
    gks_context *c = gks_ctx();
    c->rec_ws = NULL;
    c->rec_mirror = -1;
    c->rec_drawn = 0;
    const char *path = getenv("GKS3D_RECORD");
    if (!path || !*path)
        return;
    if (gks_par_rank() > 0) /* under mpirun the picture is rank 0's: one file */
        return;
    const gks_ws_driver *drv = gks_driver_for_type(GWS_TYPE_MO);
    gks_ws *ws = drv ? gks_ws_create(REC_WS_ID, path, drv) : NULL;
    int err = ws ? gks_ws_file_check(ws) : 300;
    if (!err && drv->open)
        err = drv->open(ws);
    if (err) {
        fprintf(stderr, "gks3d: GKS3D_RECORD=\"%.200s\": not recorded (GKS error %d)\n",
                path, err);
        if (ws)
            gks_ws_destroy(ws);
        return;
    }
    c->rec_ws = ws;
    if (!at_exit)
        at_exit = atexit(record_at_exit) == 0;
}

void gks_record_close(void)
{
    gks_context *c = gks_ctx();
    gks_ws *ws = c->rec_ws;
    if (!ws)
        return;
    c->rec_ws = NULL;
    ws->state = GWS_INACTIVE;
    int err = ws->drv->finish ? ws->drv->finish(ws) : 0;
    if (ws->drv->close)
        ws->drv->close(ws);
    if (err)
        fprintf(stderr, "gks3d: GKS3D_RECORD: the metafile \"%.200s\" is incomplete "
                        "(GKS error %d)\n", ws->conn_id, err);
    gks_ws_destroy(ws);
    if (c->sl)
        gks_mf_recount();
}

/* The CLEAR WORKSTATION item that ends the recorded frame of the mirrored workstation. */
static void end_frame(gks_ws *rec)
{
    gks_context *c = gks_ctx();
    if (!c->rec_drawn)
        return;
    if (gks_mf_ws_rec_CLRWK(GFN_CLWK, REC_WS_ID, (int)GFLAG_ALWAYS)) {
    } /* reported to CLOSE WORKSTATION like any write error; nothing else to undo */
    (void)rec;
}

void gks_record_sync(int closed_ws_id)
{
    gks_context *c = gks_ctx();
    gks_ws *rec = c->rec_ws;
    if (!rec || !c->sl)
        return;
    if (closed_ws_id >= 0 && closed_ws_id == c->rec_mirror) {
        end_frame(rec);
        c->rec_mirror = -1;
    }
    int active = 0;
    for (int i = 0; i < c->sl->n_open; i++) {
        gks_ws *ws = c->ws[i];
        if (!is_output(ws))
            continue;
        if (c->rec_mirror < 0)
            c->rec_mirror = ws->id;
        active |= ws->state == GWS_ACTIVE;
    }
    rec->state = active ? GWS_ACTIVE : GWS_INACTIVE;
    gks_mf_recount();
}

void gks_record_escape(int ws_id, int func_id, const Gescape_in_data *in)
{
    gks_ws *rec = gks_record_mirror(ws_id);
    if (!rec || ws_id == REC_WS_ID)
        return;
    switch (func_id) {
    case GESC_RT_CLIP_SECONDARY:
    case GESC_RT_SAMPLES:
    case GESC_RT_MAX_DEPTH:
    case GESC_RT_CUTOFF:
    case GESC_RT_SPD:
    case GESC_PNG_SUPERSAMPLE:
    case GESC_PNG_COMPRESSION:
    case GESC_VEC_RESOLUTION:
    case GESC_VEC_LINE_JOIN:
    case GESC_VEC_LINE_CAP:
    case GESC_VEC_MITER_LIMIT:
    case GESC_VEC_LINE_SCALE:
    case GESC_VEC_PAGE:
        (void)gks_mf_escape(GFN_ESC, rec, func_id, in); /* a failed write is reported */
        break;
    default: /* file names, threads, progress, statistics: not the picture's */
        break;
    }
}
