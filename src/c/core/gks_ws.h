/* SPDX-License-Identifier: MIT */
/*
 * gks_ws.h -- workstation state lists: creation/destruction and the common argument
 * checks of workstation functions (errors 20, 25, 31..39 in the standard's order).
 */
#ifndef GKS_WS_H
#define GKS_WS_H
#include "gks_private.h"
#include "ws_driver.h"
#include "gks_context.h"
#include "gks_indev.h" /* the input part of the state list, ws->in */

/* Category restrictions a function places on its workstation argument. */
enum {
    GKS_WSC_NOT_MO = 1 << 0,    /* 31 */
    GKS_WSC_NOT_MI = 1 << 1,    /* 33 */
    GKS_WSC_NOT_INPUT = 1 << 2, /* 35 */
    GKS_WSC_NOT_WISS = 1 << 3   /* 36 */
};

/* Checks (after the state check): 20 invalid id, 25 not open, then the category errors
 * selected by `cat_flags`. Reports the error for `fctid` and returns NULL on failure. */
gks_ws *gks_ws_checked(int fctid, int ws_id, unsigned cat_flags);

/* For inquiries of a workstation state list: the open workstation ws_id, or NULL with
 * *err set to 7 (state), 20 (invalid id) or 25 (not open); NULL when err is NULL. Never
 * calls the handler. */
gks_ws *gks_inq_ws(Gint ws_id, Gint *err);
/* gks_inq_ws for the inquiries of an output workstation's tables: also 33 (MI), 35 (INPUT),
 * 36 (WISS). */
gks_ws *gks_inq_out_ws(Gint ws_id, Gint *err);
/* For inquiries of a workstation description table: the table of ws_type, or NULL with
 * *err set to 8 (state), 22 (invalid type), 23 (type does not exist) and, with out = 1,
 * 39 (not of category OUTPUT or OUTIN). */
const gks_ws_desc *gks_inq_ws_type(Gint ws_type, int out, Gint *err);

/* Create the state list of a workstation being opened (colour table, transformation,
 * deferral from the description table). NULL on storage overflow. */
gks_ws *gks_ws_create(int ws_id, const char *conn_id, const gks_ws_driver *drv);
void gks_ws_destroy(gks_ws *ws);
/* ws's view table changed (or is new): a new gks_ws.views_gen. */
static inline void gks_ws_views_changed(gks_ws *ws)
{
    ws->views_gen = ++gks_ctx()->views_gen;
}
/* The services gks_ws_create gives every workstation (ws->host). */
extern const gks_ws_host gks_ws_core_host;

/* OPEN WORKSTATION's file check, before the driver opens anything: the driver's file
 * (drv->file) must be a regular file or not exist yet in a writable directory (MI: an
 * existing readable regular file): else 26 (a directory, FIFO or device is refused, so
 * nothing blocks). Its canonical path (symbolic links resolved) goes to ws->file; if
 * another open workstation has the same file, 21. Returns 0, 21, 26 or 300. */
int gks_ws_file_check(gks_ws *ws);

/* Apply a pending workstation transformation and clear the surface (a new frame). */
int gks_ws_new_frame(gks_ws *ws);
#endif
