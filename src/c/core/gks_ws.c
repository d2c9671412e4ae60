/* SPDX-License-Identifier: MIT */
#define _XOPEN_SOURCE 700 /* realpath */
#include "gks_ws.h"
#include "gks_mf_record.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "ws_file.h"
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

gks_ws *gks_ws_checked(int fctid, int ws_id, unsigned cat_flags)
{
    if (ws_id < 0)
        GKS_FAIL_RET(20, fctid, NULL);
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        GKS_FAIL_RET(25, fctid, NULL);
    Gws_cat cat = ws->drv->desc->cat;
    int err = 0;
    if ((cat_flags & GKS_WSC_NOT_MO) && cat == GCAT_MO)
        err = 31;
    else if ((cat_flags & GKS_WSC_NOT_MI) && cat == GCAT_MI)
        err = 33;
    else if ((cat_flags & GKS_WSC_NOT_INPUT) && cat == GCAT_IN)
        err = 35;
    else if ((cat_flags & GKS_WSC_NOT_WISS) && cat == GCAT_WISS)
        err = 36;
    if (err)
        GKS_FAIL_RET(err, fctid, NULL);
    return ws;
}

/* The bundle tables from the description table's predefined bundles. 300 on storage
 * overflow (the caller destroys the half-made state list). */
static int init_bundles(gks_ws *ws, const gks_wdt_output *t)
{
    int max = t->max_bundles < GKS_WDT_MAX_BUNDLES ? t->max_bundles : GKS_WDT_MAX_BUNDLES;
    for (int i = 1; i <= max; i++) {
        if (i <= t->n_pred_line) {
            ws->line_rep[i] = t->pred_line[i - 1];
            ws->line_def[i] = 1;
        }
        if (i <= t->n_pred_marker) {
            ws->marker_rep[i] = t->pred_marker[i - 1];
            ws->marker_def[i] = 1;
        }
        if (i <= t->n_pred_text) {
            ws->text_rep[i] = t->pred_text[i - 1];
            ws->text_def[i] = 1;
        }
        if (i <= t->n_pred_fill) {
            ws->fill_rep[i] = t->pred_fill[i - 1];
            ws->fill_def[i] = 1;
        }
        if (i <= t->n_pred_edge) {
            ws->edge_rep[i] = t->pred_edge[i - 1];
            ws->edge_def[i] = 1;
        }
        if (i <= t->n_pred_pat) {
            const gks_wdt_pattern *p = &t->pred_pat[i - 1];
            size_t n = (size_t)p->nx * (size_t)p->ny;
            ws->pat_rep[i].colr = gks_alloc_array(n, sizeof(int));
            if (!ws->pat_rep[i].colr)
                return 300;
            memcpy(ws->pat_rep[i].colr, p->colr, n * sizeof(int));
            ws->pat_rep[i].nx = p->nx;
            ws->pat_rep[i].ny = p->ny;
            ws->pat_def[i] = 1;
        }
    }
    return 0;
}

static int file_claim(gks_ws *ws, const char *path);
static int file_taken(const gks_ws *ws, const char *path);
/* gks_ws_host.note: the driver's words for its next error report */
static void note(const char *text)
{
    gks_error_note("%s", text);
}

const gks_ws_host gks_ws_core_host = { .file_claim = file_claim, .file_taken = file_taken,
                                       .note = note };

gks_ws *gks_ws_create(int ws_id, const char *conn_id, const gks_ws_driver *drv)
{
    const gks_ws_desc *d = drv->desc;
    gks_ws *ws = gks_calloc_array(1, sizeof *ws);
    if (!ws)
        return NULL;
    gks_ws_tables_changed(); /* a new ws may reuse a closed one's address */
    ws->id = ws_id;
    ws->drv = drv;
    ws->host = &gks_ws_core_host;
    ws->conn_id = gks_strdup(conn_id ? conn_id : "");
    int n = d->n_colr > 0 ? d->n_colr : 1;
    ws->colr = gks_calloc_array((size_t)n, sizeof *ws->colr);
    ws->colr_defined = gks_calloc_array((size_t)n, 1);
    if (!ws->conn_id || !ws->colr || !ws->colr_defined) {
        gks_ws_destroy(ws);
        return NULL;
    }
    for (int i = 0; i < d->n_pred_colr && i < n; i++) {
        ws->colr[i] = d->pred_colr[i];
        ws->colr_defined[i] = 1;
    }
    ws->state = GWS_INACTIVE;
    ws->defer_mode = d->default_defer;
    ws->irg_mode = d->default_irg;
    ws->disp_empty = GDISP_EMPTY;
    ws->new_frame = GNEW_NO;
    ws->tran_upd_st = GUPD_NOT_PEND;
    ws->req_win = ws->cur_win = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    ws->req_vp = ws->cur_vp = (Glimit3){ 0, d->dc_x, 0, d->dc_y, 0, 1 };
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++) {
        Gview_rep3 *r = &ws->views[v];
        for (int i = 0; i < 4; i++)
            r->ori_matrix[i][i] = r->map_matrix[i][i] = 1;
        r->clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
        r->xy_clip = r->back_clip = r->front_clip = GIND_CLIP;
    }
    gks_ws_views_changed(ws);
    ws->hlhsr_mode = GHLHSR_NONE;
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++)
        ws->view_pri[v] = v;
    /* Light source 1 is predefined: white ambient light. */
    ws->lights[0] = (Glight_src_rep){ .type = GLIGHT_AMBIENT, .colr = { 1, 1, 1 },
                                      .dir = { 0, 0, -1 }, .atten = { 1, 0 },
                                      .spread_angle = 3.14159265358979323846 };
    ws->light_defined[0] = 1;
    if (init_bundles(ws, d->out ? d->out : &gks_wdt_raster) || gks_in_ws_open(ws, d->in)) {
        gks_ws_destroy(ws);
        return NULL;
    }
    return ws;
}

/* realpath() into the funnel; NULL with *err = 26 (no such path; noted with the
 * system's reason) or 300. */
static char *canonical(const char *path, int *err)
{
    char *r = realpath(path, NULL);
    if (!r) {
        *err = errno == ENOMEM ? 300 : 26;
        if (*err == 26)
            gks_error_note("cannot open \"%s\": %s", path, strerror(errno));
        return NULL;
    }
    char *c = gks_strdup(r);
    free(r);
    *err = c ? 0 : 300;
    return c;
}

/* The canonical path of `path`, which must be usable: an existing regular file (readable,
 * or writable when `write`), or, when writing, a name not yet taken in a writable
 * directory. NULL with *err = 26 or 300; a 26 is noted for the error report with the file
 * and the system's reason (`cannot open "out/x.png": No such file or directory`). */
static char *usable_file(const char *path, int write, int *err)
{
    struct stat st;
    if (stat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode)) {
            gks_error_note("cannot open \"%s\": %s", path,
                           S_ISDIR(st.st_mode) ? strerror(EISDIR) : "not a regular file");
            *err = 26;
            return NULL;
        }
        if (access(path, write ? W_OK : R_OK) != 0) {
            gks_error_note("cannot open \"%s\" for %s: %s", path, write ? "writing" : "reading",
                           strerror(errno));
            *err = 26;
            return NULL;
        }
        return canonical(path, err);
    }
    if (errno != ENOENT || !write) {
        gks_error_note("cannot open \"%s\": %s", path, strerror(errno));
        *err = 26;
        return NULL;
    }
    const char *slash = strrchr(path, '/');
    char *dir = slash ? gks_strndup(path, slash == path ? 1 : (size_t)(slash - path))
                      : gks_strdup(".");
    if (!dir) {
        *err = 300;
        return NULL;
    }
    char *cdir = NULL;
    /* the file does not exist yet: its folder must, and must be writable */
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode) || access(dir, W_OK | X_OK) != 0) {
        int e = errno;
        if (stat(dir, &st) == 0 && !S_ISDIR(st.st_mode))
            e = ENOTDIR;
        gks_error_note("cannot open \"%s\": %s", path, strerror(e));
        *err = 26;
    } else
        cdir = canonical(dir, err);
    gks_free(dir);
    if (!cdir)
        return NULL;
    const char *base = slash ? slash + 1 : path;
    size_t n = strlen(cdir) + strlen(base) + 2;
    char *c = gks_alloc_array(n, 1);
    if (c)
        snprintf(c, n, "%s%s%s", cdir, strcmp(cdir, "/") ? "/" : "", base);
    gks_free(cdir);
    *err = c ? 0 : 300;
    return c;
}

/* 1 if an open workstation other than self writes or reads the file canon (its file at
 * OPEN or one it claimed later). */
static int file_in_use(const gks_ws *self, const char *canon)
{
    const gks_context *c = gks_ctx();
    for (int i = 0; c->sl && i < c->sl->n_open; i++) {
        const gks_ws *o = c->ws[i];
        if (o == self)
            continue;
        if (o->file && strcmp(o->file, canon) == 0)
            return 1;
        for (int k = 0; k < o->n_files; k++)
            if (strcmp(o->files[k], canon) == 0)
                return 1;
    }
    return 0;
}

int gks_ws_file_check(gks_ws *ws)
{
    if (!ws->drv->file)
        return 0;
    char *path = NULL;
    int err = ws->drv->file(ws, &path);
    if (err)
        return err;
    if (!*path) {
        gks_free(path);
        return 21;
    }
    char *canon = usable_file(path, ws->drv->desc->cat != GCAT_MI, &err);
    gks_free(path);
    if (!canon)
        return err;
    if (file_in_use(ws, canon)) {
        gks_error_note("\"%s\" is written or read by another open workstation", canon);
        gks_free(canon);
        return 21; /* the connection (its file) is in use by another workstation */
    }
    ws->file = canon;
    return 0;
}

/* gks_ws_host.file_taken */
static int file_taken(const gks_ws *ws, const char *path)
{
    int err;
    char *canon = usable_file(path, 1, &err);
    int taken = canon && file_in_use(ws, canon);
    gks_free(canon);
    return taken;
}

/* gks_ws_host.file_claim */
static int file_claim(gks_ws *ws, const char *path)
{
    int err;
    char *canon = usable_file(path, 1, &err);
    if (!canon)
        return err;
    int own = ws->file && strcmp(ws->file, canon) == 0;
    for (int k = 0; !own && k < ws->n_files; k++)
        own = strcmp(ws->files[k], canon) == 0;
    if (own) {
        gks_free(canon);
        return 0;
    }
    if (file_in_use(ws, canon)) {
        gks_free(canon);
        return 21;
    }
    if (ws->n_files == INT_MAX ||
        gks_grow(&ws->files, &ws->cap_files, (size_t)ws->n_files + 1, sizeof *ws->files)) {
        gks_free(canon);
        return 300;
    }
    ws->files[ws->n_files++] = canon;
    return 0;
}

void gks_ws_destroy(gks_ws *ws)
{
    if (!ws)
        return;
    gks_ws_tables_changed();
    gks_in_ws_close(ws);
    gks_mf_ws_free(ws);
    gks_free(ws->conn_id);
    gks_free(ws->file);
    for (int k = 0; k < ws->n_files; k++)
        gks_free(ws->files[k]);
    gks_free(ws->files);
    gks_free(ws->colr);
    gks_free(ws->colr_defined);
    for (int i = 0; i <= GKS_WDT_MAX_BUNDLES; i++)
        gks_free(ws->pat_rep[i].colr);
    gks_free(ws);
}

int gks_ws_new_frame(gks_ws *ws)
{
    ws->cur_win = ws->req_win;
    ws->cur_vp = ws->req_vp;
    ws->tran_upd_st = GUPD_NOT_PEND;
    ws->new_frame = GNEW_NO;
    ws->disp_empty = GDISP_EMPTY;
    return ws->drv->clear ? ws->drv->clear(ws) : 0;
}
