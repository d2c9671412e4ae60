/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_record.h -- the metafile as a back-end: recording at the API level (the core calls a
 * one-line hook from each function the metafile records; the hook encodes the function's
 * item of gks_mf_items.def and hands it to every active MO workstation, or to the addressed
 * workstation when it is an MO, through the driver entry record_item), and the core's state
 * of the MO workstations. Interpretation (and the MI's state): core/api/gks_metafile.c. Item numbers and
 * data records: docs/METAFILE.md; the character codec: ws/mf/gks_mf_codec.h.
 *
 * Current primitive attributes, the normalization and the clipping volume are written
 * lazily: before each primitive, an MO writes the items of those entries that differ from
 * what it last wrote (all of them before its first primitive), so a metafile is complete
 * whatever was set before the MO was activated. Every hook returns at once when no MO is
 * active (one test of a counter in the state list).
 */
#ifndef GKS_MF_H
#define GKS_MF_H
#include "gks_private.h"
#include "gks_context.h"
#include "gks_error.h"
#include "gks_mf_codec.h"
#include "gks_mf_items.h"
#include "ws_driver.h"

/* A primitive as recorded (gks_output.c fills it after its argument checks). pn maps the
 * source points to NDC3 (before any segment transformation); norm/box/clip_on are the
 * normalization and clipping volume in effect. Points: one of p2, p3, d3. */
typedef struct gks_mf_prim {
    int item;                  /* GKSM_ITEM_POLYLINE3, _POLYMARKER3, _FILL_AREA3,
                                  _FILL_AREA_SET3, _TEXT3, _CELL_ARRAY3 */
    const double (*pn)[4];
    const double (*norm)[4];
    const double *box;
    int clip_on;
    size_t n_loops;            /* FILL AREA SET: loops and their point counts */
    const size_t *cnt;
    size_t n;
    const Gpoint *p2;
    const Gpoint3 *p3;
    const double (*d3)[3];
    const char *str;           /* TEXT 3: points = position, two direction vectors (WC3) */
    int nx, ny;                /* CELL ARRAY 3: points = P, Q, R; nx*ny colour indices */
    const Gint *colr;
    const int *dints;          /* primitives with data: the packed form (gks_area_data.h) */
    size_t n_dints;
    const double *dreals;
    size_t n_dreals;
} gks_mf_prim;

/* The core's recording state of an MO workstation (gks_ws.mf): what it last wrote (the
 * lazy attribute sync) and its reused data record. (An MI's gks_ws.mf is the interpreter's
 * state of the items read from it: core/api/gks_metafile.c.) */
typedef struct gks_mf_ws {
    gksm_rec rec;
    int synced;                /* `last`, norm, box, clip_on hold what was written */
    gks_cur_attrs last;
    double norm[3][4];
    double box[6];
    int clip_on;
} gks_mf_ws;

/* The MO ws's recording state, made at first use; NULL on storage overflow. */
gks_mf_ws *gks_mf_ws_state(gks_ws *ws);
/* Frees ws->mf (from gks_ws_destroy): an MO's recording state, or the one block an MI's
 * interpreter keeps there. */
void gks_mf_ws_free(gks_ws *ws);

/* Whether any MO workstation is active (the fast-path test). */
static inline int gks_mf_on(void)
{
    const gks_state_list *sl = gks_ctx()->sl;
    return sl && sl->mf_n_mo_active > 0;
}

/* ACTIVATE / DEACTIVATE WORKSTATION: recount the active MO workstations. */
void gks_mf_recount(void);

/* ---- hooks: each writes one item (errors 300, 303 reported for fctid). Each returns
 * what gks_error_report returned (1 when nothing was reported): on 0 the caller returns at
 * once (gks_error.h). ---- */
/* A primitive, preceded by the attribute, normalization and clipping items that changed. */
GKS_MUST_CHECK int gks_mf_prim_write(int fctid, const gks_mf_prim *p);
/* The typed hooks, one per REC_ALL and REC_WS row of gks_mf_items.def, generated from the
 * row's format (an argument of the wrong kind does not compile): gks_mf_rec_<KEY>(fctid,
 * values...) writes the item of function KEY on every active MO; gks_mf_ws_rec_<KEY>(fctid,
 * ws_id, values...) writes it when ws_id is an open MO (active or not; no fast path needed:
 * these are not per-primitive calls), and on the GKS3D_RECORD recorder when it mirrors
 * ws_id. The values follow the groups of the format: i an int, r a double, Ni / Nr one
 * pointer to N ints / doubles, I an int count and a pointer to the ints, s a string. */
#define GKSM_DECL_REC_ALL(name, key, fmt)                                                  \
    GKS_MUST_CHECK int gks_mf_rec_##key(int fctid GKSM_PARAMS fmt);
#define GKSM_DECL_REC_WS(name, key, fmt)                                                   \
    GKS_MUST_CHECK int gks_mf_ws_rec_##key(int fctid, int ws_id GKSM_PARAMS fmt);
#define GKSM_DECL_REC_OWN(name, key, fmt)
#define GKSM_DECL_PRIM(name, key, fmt)
#define GKSM_DECL_ATTR(name, key, fmt)
#define GKSM_DECL_STATE(name, key, fmt)
#define GKSM_DECL_READ(name, key, fmt)
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_DECL_##kind(name, key, fmt)
#define GKSM_ALSO(key, name, kind, fmt) GKSM_DECL_##kind(name, key, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO

/* ESCAPE addressed to workstation ws: if ws is an MO, writes the ESCAPE item (function
 * identification, integers, reals, string) and returns 1; else returns 0. */
int gks_mf_escape(int fctid, gks_ws *ws, int func_id, const Gescape_in_data *in);
/* WRITE ITEM TO GKSM after its checks: the user item to the MO ws. 1, or what
 * gks_error_report returned. */
int gks_mf_user_item(int fctid, gks_ws *ws, int type, const char *data, size_t len);
/* Whether ws is a metafile output (its driver takes items). */
static inline int gks_mf_is_mo(const gks_ws *ws)
{
    return ws && ws->drv->record_item != NULL;
}

/* The one-line hook of function SYM (GFN_SYM), recorded on every active MO as its item of
 * gks_mf_items.def (fast path: one test), the arguments as the item's format says. Returns
 * from the calling void function when the error handler changed the world. GKS_MF0: an
 * item without data. */
#define GKS_MF(sym, ...)                                                                   \
    do {                                                                                   \
        if (gks_mf_on() && !gks_mf_rec_##sym(GFN_##sym, __VA_ARGS__))                      \
            return;                                                                        \
    } while (0)
#define GKS_MF0(sym)                                                                       \
    do {                                                                                   \
        if (gks_mf_on() && !gks_mf_rec_##sym(GFN_##sym))                                   \
            return;                                                                        \
    } while (0)
/* The same for a workstation-addressed function (gks_mf_ws_rec_<KEY>). */
#define GKS_MF_WS(sym, ws_id, ...)                                                         \
    do {                                                                                   \
        if (!gks_mf_ws_rec_##sym(GFN_##sym, (ws_id), __VA_ARGS__))                         \
            return;                                                                        \
    } while (0)
#define GKS_MF_WS0(sym, ws_id)                                                             \
    do {                                                                                   \
        if (!gks_mf_ws_rec_##sym(GFN_##sym, (ws_id)))                                      \
            return;                                                                        \
    } while (0)
#endif
