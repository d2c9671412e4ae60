/* SPDX-License-Identifier: MIT */
/*
 * ws_mo.c -- the GKS metafile output workstation (type GWS_TYPE_MO, category MO). The
 * connection identifier is the file name; OPEN WORKSTATION writes the file header, CLOSE
 * WORKSTATION the END item. The core encodes the items (core/store/gks_mf_record.c) and
 * hands them to record_item; the driver has no drawing entries. It owns the file: a
 * failed write marks it lost (reported once), and nothing more is written to it.
 */
#include "gks_alloc.h"
#include "gks_mf_codec.h"
#include "gks_mf_file.h"
#include "ws_driver.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>

/* The MO's file. */
typedef struct {
    FILE *fp;
    int lost; /* a write failed (reported once): nothing more is written */
} mo_out;

static const gks_ws_desc mo_desc = {
    GKS_WS_DESC_NODRAW(GWS_TYPE_MO, "gksm-out", GCAT_MO, GCLASS_OTHER, 1024),
    .n_colr = 256,
    .n_pred_colr = 2,
    .pred_colr = gks_wdt_white_black,
    /* every mode is recorded (the interpreting workstation decides what it supports) */
    .hlhsr_modes = 1u << GHLHSR_NONE | 1u << GHLHSR_HIDDEN_LINE | 1u << GHLHSR_ZBUFFER |
                   1u << GHLHSR_PAINTER | 1u << GHLHSR_RAYTRACE,
};

static int mo_file(const gks_ws *ws, char **path)
{
    return gks_mf_file_path(ws->conn_id, path);
}

static int mo_open(gks_ws *ws)
{
    if (!ws->conn_id || !*ws->conn_id)
        return 21;
    mo_out *o = gks_calloc_array(1, sizeof *o);
    if (!o)
        return 300;
    char *path = gks_mf_file_name(ws->conn_id);
    o->fp = path ? fopen(path, "wb") : NULL;
    if (!o->fp && path)
        gks_ws_note(ws, "cannot open \"%s\": %s", path, strerror(errno));
    if (o->fp && gksm_write_header(o->fp, "gks3d GKS-3D metafile", NULL)) {
        gks_ws_note(ws, "cannot write \"%s\": %s", path, errno ? strerror(errno) : "write failed");
        fclose(o->fp);
        o->fp = NULL;
    }
    gks_free(path);
    if (!o->fp) {
        gks_free(o);
        return 26;
    }
    ws->priv = o;
    return 0;
}

/* Writes the END item and closes the file. 0, or 303 when a write or fclose failed. */
static int mo_end(mo_out *o)
{
    int err = 0;
    if (!o->lost)
        err = gksm_write_record(o->fp, 0 /* END */, NULL, 0) != 0;
    err |= fclose(o->fp) != 0;
    o->fp = NULL;
    return err ? 303 : 0;
}

/* CLOSE WORKSTATION: the END item and the file's close are checked; a loss is reported
 * once per workstation (not again when an earlier item already reported it). */
static int mo_finish(gks_ws *ws)
{
    mo_out *o = ws->priv;
    if (!o || !o->fp)
        return 0;
    int was_lost = o->lost;
    int err = mo_end(o);
    return err && !was_lost ? err : 0;
}

/* Frees the workstation; after EMERGENCY CLOSE GKS (no finish) ends the file unchecked. */
static void mo_close(gks_ws *ws)
{
    mo_out *o = ws->priv;
    if (!o)
        return;
    if (o->fp)
        (void)mo_end(o);
    gks_free(o);
    ws->priv = NULL;
}

/* UPDATE WORKSTATION (and CLOSE, before finish): the items so far reach the file. A failure
 * is reported once: it marks the workstation lost. */
static int mo_update(gks_ws *ws)
{
    mo_out *o = ws->priv;
    if (o->lost)
        return 0;
    if (fflush(o->fp) == 0 && !ferror(o->fp))
        return 0;
    o->lost = 1;
    return 303;
}

/* One item from the core: 0, 161, or 303 for the first failed write (then 0: lost). */
static int mo_record_item(gks_ws *ws, int type, const char *rec, size_t len)
{
    mo_out *o = ws->priv;
    if (o->lost)
        return 0;
    int err = gksm_write_record(o->fp, type, rec, len);
    if (err == 161)
        return 161;
    if (err) {
        o->lost = 1;
        return 303;
    }
    return 0;
}

const gks_ws_driver gks_ws_mo_driver = {
    .desc = &mo_desc,
    .file = mo_file,
    .open = mo_open,
    .close = mo_close,
    .finish = mo_finish,
    .update = mo_update,
    .record_item = mo_record_item,
};
