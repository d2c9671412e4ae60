/* SPDX-License-Identifier: MIT */
/*
 * ws_mi.c -- the GKS metafile input workstation (type GWS_TYPE_MI, category MI): the file
 * and its items as bytes. GET ITEM TYPE FROM GKSM, READ ITEM FROM GKSM and INTERPRET ITEM
 * are the core's (core/api/gks_metafile.c), which reads the items through item_reader. The
 * file is untrusted: the header is checked at OPEN WORKSTATION and every length against
 * the bytes left (gks_mf_codec.c).
 */
#include "gks_alloc.h"
#include "gks_mf_codec.h"
#include "gks_mf_file.h"
#include "ws_driver.h"
#include <errno.h>
#include <stdio.h>
#include <string.h>

/* The MI's file and its reader. */
typedef struct {
    FILE *fp;
    int allow_escapes; /* GESC_MI_ALLOW_ESCAPES: 1 performs every recorded ESCAPE */
    gksm_in in;
} mi_in;

static const gks_ws_desc mi_desc = {
    GKS_WS_DESC_NODRAW(GWS_TYPE_MI, "gksm-in", GCAT_MI, GCLASS_OTHER, 1),
    .n_colr = 1,
    .hlhsr_modes = 1u << GHLHSR_NONE,
};

static int mi_file(const gks_ws *ws, char **path)
{
    return gks_mf_file_path(ws->conn_id, path);
}

static int mi_open(gks_ws *ws)
{
    if (!ws->conn_id || !*ws->conn_id)
        return 21;
    mi_in *m = gks_calloc_array(1, sizeof *m);
    if (!m)
        return 300;
    char *path = gks_mf_file_name(ws->conn_id);
    m->fp = path ? fopen(path, "rb") : NULL;
    if (!m->fp && path)
        gks_ws_note(ws, "cannot open \"%s\": %s", path, strerror(errno));
    if (m->fp && gksm_in_open(&m->in, m->fp)) { /* not a GKSM file this reader accepts */
        gks_ws_note(ws, "\"%s\" is not a GKS metafile this library reads (docs/METAFILE.md)",
                    path);
        fclose(m->fp);
        m->fp = NULL;
    }
    gks_free(path);
    if (!m->fp) {
        gks_free(m);
        return 26;
    }
    ws->priv = m;
    return 0;
}

static void mi_close(gks_ws *ws)
{
    mi_in *m = ws->priv;
    if (!m)
        return;
    fclose(m->fp);
    gks_free(m);
    ws->priv = NULL;
}

/* GESC_MI_ALLOW_ESCAPES: ints[1] 0/1. */
static int mi_escape(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    (void)out;
    mi_in *m = ws->priv;
    if (func_id != GESC_MI_ALLOW_ESCAPES)
        return 180;
    if (in->num_ints < 2 || (in->ints[1] != 0 && in->ints[1] != 1))
        return 182;
    m->allow_escapes = in->ints[1];
    return 0;
}

static struct gksm_in *mi_item_reader(gks_ws *ws, int *allow_escapes)
{
    mi_in *m = ws->priv;
    *allow_escapes = m->allow_escapes;
    return &m->in;
}

const gks_ws_driver gks_ws_mi_driver = {
    .desc = &mi_desc,
    .file = mi_file,
    .open = mi_open,
    .close = mi_close,
    .escape = mi_escape,
    .item_reader = mi_item_reader,
};
