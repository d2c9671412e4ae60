/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_record.h -- the GKS metafile workstations: recording at the API level (the core calls a
 * one-line hook from each function the metafile records; the hook writes an item to every
 * active MO workstation, or to the addressed workstation when it is an MO) and
 * interpretation of items (INTERPRET ITEM performs the recorded function). Item numbers
 * and data records: docs/METAFILE.md. The character codec is gks_mf_codec.h.
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

/* Item types (docs/METAFILE.md). RAL GKS's table for the GKS items; GKS-3D and lighting
 * items in numbers RAL leaves free below 100. */
enum {
    GKSM_ITEM_END = 0, GKSM_ITEM_CLEAR = 1, GKSM_ITEM_REDRAW = 2, GKSM_ITEM_UPDATE = 3,
    GKSM_ITEM_DEFER = 4, GKSM_ITEM_MESSAGE = 5, GKSM_ITEM_ESCAPE = 6,
    GKSM_ITEM_TEXT3 = 7, GKSM_ITEM_CELL_ARRAY3 = 8, GKSM_ITEM_FILL_AREA_SET3 = 9,
    GKSM_ITEM_POLYLINE = 11, GKSM_ITEM_POLYMARKER = 12, GKSM_ITEM_TEXT = 13,
    GKSM_ITEM_FILL_AREA = 14, GKSM_ITEM_CELL_ARRAY = 15, GKSM_ITEM_GDP = 16,
    GKSM_ITEM_POLYLINE3 = 17, GKSM_ITEM_POLYMARKER3 = 18, GKSM_ITEM_FILL_AREA3 = 19,
    GKSM_ITEM_LINE_IND = 21, GKSM_ITEM_LINETYPE = 22, GKSM_ITEM_LINEWIDTH = 23,
    GKSM_ITEM_LINE_COLR = 24, GKSM_ITEM_MARKER_IND = 25, GKSM_ITEM_MARKER_TYPE = 26,
    GKSM_ITEM_MARKER_SIZE = 27, GKSM_ITEM_MARKER_COLR = 28, GKSM_ITEM_TEXT_IND = 29,
    GKSM_ITEM_TEXT_FONT_PREC = 30, GKSM_ITEM_CHAR_EXPAN = 31, GKSM_ITEM_CHAR_SPACE = 32,
    GKSM_ITEM_TEXT_COLR = 33, GKSM_ITEM_CHAR_VECS = 34, GKSM_ITEM_TEXT_PATH = 35,
    GKSM_ITEM_TEXT_ALIGN = 36, GKSM_ITEM_FILL_IND = 37, GKSM_ITEM_INT_STYLE = 38,
    GKSM_ITEM_STYLE_IND = 39, GKSM_ITEM_FILL_COLR = 40, GKSM_ITEM_PAT_SIZE_NDC = 41,
    GKSM_ITEM_PAT_REF_NDC = 42, GKSM_ITEM_ASF = 43, GKSM_ITEM_PICK_ID = 44,
    GKSM_ITEM_PAT_REF_VECS = 45, GKSM_ITEM_EDGE_FLAG = 46, GKSM_ITEM_EDGETYPE = 47,
    GKSM_ITEM_EDGEWIDTH = 48, GKSM_ITEM_EDGE_COLR = 49, GKSM_ITEM_EDGE_IND = 50,
    GKSM_ITEM_LINE_REP = 51, GKSM_ITEM_MARKER_REP = 52, GKSM_ITEM_TEXT_REP = 53,
    GKSM_ITEM_FILL_REP = 54, GKSM_ITEM_PAT_REP = 55, GKSM_ITEM_COLR_REP = 56,
    GKSM_ITEM_EDGE_REP = 57, GKSM_ITEM_VIEW_REP3 = 58, GKSM_ITEM_CHAR_HT = 59,
    GKSM_ITEM_CHAR_UP = 60, GKSM_ITEM_CLIP_RECT = 61, GKSM_ITEM_NORM = 62,
    GKSM_ITEM_PAT_SIZE = 63, GKSM_ITEM_CLIP_VOL3 = 64, GKSM_ITEM_VIEW_IND = 65,
    GKSM_ITEM_HLHSR_ID = 66, GKSM_ITEM_HLHSR_MODE = 67, GKSM_ITEM_AREA_PROPS = 68,
    GKSM_ITEM_REFL_EQ = 69, GKSM_ITEM_LIGHT_STATE = 70, GKSM_ITEM_WS_WIN = 71,
    GKSM_ITEM_WS_VP = 72, GKSM_ITEM_WS_WIN3 = 73, GKSM_ITEM_WS_VP3 = 74,
    GKSM_ITEM_LIGHT_REP = 75,
    GKSM_ITEM_FILL_AREA3_DATA = 76, GKSM_ITEM_FILL_AREA_SET3_DATA = 77,
    GKSM_ITEM_TRI_STRIP3_DATA = 78, GKSM_ITEM_QUAD_MESH3_DATA = 79,
    GKSM_ITEM_SOFAS3_DATA = 80, GKSM_ITEM_INT_SHAD = 86,
    GKSM_ITEM_CREATE_SEG = 81, GKSM_ITEM_CLOSE_SEG = 82, GKSM_ITEM_RENAME_SEG = 83,
    GKSM_ITEM_DEL_SEG = 84, GKSM_ITEM_SEG_TRAN3 = 85, GKSM_ITEM_SEG_TRAN = 91,
    GKSM_ITEM_VIS = 92, GKSM_ITEM_HIGHL = 93, GKSM_ITEM_SEG_PRI = 94, GKSM_ITEM_DET = 95,
    GKSM_ITEM_USER_MIN = 101 /* user items: 101..999 */
};

/* INTERPRET ITEM's normalization for primitives (gks_output.c reads it from the context
 * while a recorded primitive is performed): points are NDC3 (ndc_pts = 1; TEXT: WC3 and
 * ndc_pts = 0), norm is the recorded WC3 -> NDC3 matrix for text geometry and pattern
 * boxes, box/clip_on the recorded clipping volume. */
typedef struct gks_norm_override {
    double norm[3][4];
    double box[6];
    int clip_on;
    int ndc_pts;
} gks_norm_override;

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

/* Output state of an MO workstation (ws->priv of ws_mo.c). */
typedef struct gks_mf_out {
    FILE *fp;
    int lost;                  /* a write failed (reported once): nothing more is written */
    gksm_rec rec;              /* reused data record */
    int synced;                /* `last`, norm, box, clip_on hold what was written */
    gks_cur_attrs last;
    double norm[3][4];
    double box[6];
    int clip_on;
} gks_mf_out;

/* Input state of an MI workstation (ws->priv of ws_mi.c): the reader and the
 * interpretation state of the items read from it (recorded normalization, clipping). */
typedef struct gks_mf_in {
    FILE *fp;
    int allow_escapes;         /* GESC_MI_ALLOW_ESCAPES: 1 performs every recorded ESCAPE */
    gksm_in in;
    gks_norm_override xf;
} gks_mf_in;

/* The metafile workstation drivers (ws_mo.c, ws_mi.c). */
extern const gks_ws_driver gks_ws_mo_driver;
extern const gks_ws_driver gks_ws_mi_driver;

/* The metafile's file name for a connection identifier: the identifier itself, or
 * "gks<digits>.gksm" when it is all digits (a Fortran integer CONID), as the PNG
 * workstation names "gks<digits>.png". NULL on storage overflow. Free with gks_free. */
char *gks_mf_file_name(const char *conn_id);
/* The drivers' file entry (ws_driver.h) of MO and MI: 21 for an empty identifier. */
int gks_mf_file(const gks_ws *ws, char **path);

/* Whether any MO workstation is active (the fast-path test). */
static inline int gks_mf_on(void)
{
    const gks_state_list *sl = gks_ctx()->sl;
    return sl && sl->mf_n_mo_active > 0;
}

/* ACTIVATE / DEACTIVATE WORKSTATION: recount the active MO workstations. */
void gks_mf_recount(void);

/* INTERPRET ITEM of a primitive with data (item GKSM_ITEM_*_DATA, d in NDC3, with the
 * MI's normalization override in effect): performed as the function that wrote it (its
 * state check, gks_area_data_check's errors). Defined by the output pipeline
 * (core/api/gks_output_data.c). */
#include "gks_area_data.h"
void gks_area_data_perform(int item, const gks_area_data *d);

/* ---- hooks: each writes one item (errors 300, 303 reported for fctid). Each returns
 * what gks_error_report returned (1 when nothing was reported): on 0 the caller returns at
 * once (gks_error.h). ---- */
/* A primitive, preceded by the attribute, normalization and clipping items that changed. */
GKS_MUST_CHECK int gks_mf_prim_write(int fctid, const gks_mf_prim *p);
/* An item of the active MO workstations, its data record described by fmt: 'i' an int
 * argument, 'r' a double, 'I' (int n, const int *v) n ints, 'R' (int n, const double *v)
 * n reals, 's' a string (const char *, written as count and characters). */
GKS_MUST_CHECK int gks_mf_rec(int fctid, int item, const char *fmt, ...);
/* The same for a workstation-addressed function: written only when ws_id is an open MO
 * (active or not; no fast path needed: these are not per-primitive calls). */
GKS_MUST_CHECK int gks_mf_ws_rec(int fctid, int ws_id, int item, const char *fmt, ...);

/* ESCAPE addressed to workstation ws: if ws is an MO, writes the ESCAPE item (function
 * identification, integers, reals, string) and returns 1; else returns 0. */
int gks_mf_escape(int fctid, gks_ws *ws, int func_id, const Gescape_in_data *in);

/* The one-line hook of a function recorded on every active MO (fast path: one test).
 * Returns from the calling void function when the error handler changed the world. */
#define GKS_MF(fct, item, ...)                                                             \
    do {                                                                                   \
        if (gks_mf_on() && !gks_mf_rec((fct), (item), __VA_ARGS__))                        \
            return;                                                                        \
    } while (0)
/* The same for a workstation-addressed function (gks_mf_ws_rec). */
#define GKS_MF_WS(fct, ws_id, item, ...)                                                   \
    do {                                                                                   \
        if (!gks_mf_ws_rec((fct), (ws_id), (item), __VA_ARGS__))                           \
            return;                                                                        \
    } while (0)
#endif
