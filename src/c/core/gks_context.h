/* SPDX-License-Identifier: MIT */
/*
 * gks_context.h -- the root object holding the standard's tables: the GKS description
 * table (const), the GKS state list (exists while GKS is open), the error state list and
 * the workstation state lists of the open workstations. Other file-level mutable state of
 * the core: the allocation fault-injection counter (base/gks_alloc.c), the normalization
 * cache `norm_cache` (pipe/gks_pipe_norm.c: the last current-state context, compared by
 * value, never a second source of truth) and the legacy settings `legacy`
 * (gks_legacy.c: GKS3D_WS_TYPES, GKS3D_ASF and NCAR's next file name, read at OPEN GKS).
 */
#ifndef GKS_CONTEXT_H
#define GKS_CONTEXT_H
#include "gks_private.h"
#include "gks.h"
#include "ws_driver.h" /* gks_ws, gks_ws_driver, gks_limit3_array */
#include <stdint.h>
#include <stdio.h>

#define GKS_MAX_OPEN_WS 16
#define GKS_MAX_ACTIVE_WS 16
#define GKS_MAX_NORM_TRAN 31 /* transformations 0..31; 0 is the unity transformation */
#define GKS_ERROR_DETAIL_MAX 512 /* bytes of an error detail (gks_error_note), NUL included */

/* GKS description table (ISO 7942 6.3), constant. */
typedef struct gks_desc_table {
    Glevel level;
    int n_ws_types;
    const gks_ws_driver *const *ws_types; /* the compiled-in driver list */
    Gws_max_nums max_nums;
    int max_norm_tran;
} gks_desc_table;

/* Aspect source flags, in the standard's order (GKS 13, then the GKS-3D edge four). */
enum {
    GKS_ASF_LINETYPE, GKS_ASF_LINEWIDTH, GKS_ASF_LINE_COLR,
    GKS_ASF_MARKER_TYPE, GKS_ASF_MARKER_SIZE, GKS_ASF_MARKER_COLR,
    GKS_ASF_TEXT_FONT_PREC, GKS_ASF_CHAR_EXPAN, GKS_ASF_CHAR_SPACE, GKS_ASF_TEXT_COLR,
    GKS_ASF_FILL_INT_STYLE, GKS_ASF_FILL_STYLE_IND, GKS_ASF_FILL_COLR,
    GKS_ASF_EDGE_FLAG, GKS_ASF_EDGETYPE, GKS_ASF_EDGEWIDTH, GKS_ASF_EDGE_COLR,
    GKS_N_ASF
};

/* Primitive attributes currently selected (the GKS state list's "current" entries),
 * named after the standard's entries. Defaults: gks_attr_init. */
typedef struct gks_cur_attrs {
    int line_ind, linetype;
    double linewidth;
    int line_colr_ind;
    int marker_ind, marker_type;
    double marker_size;
    int marker_colr_ind;
    int text_ind;
    Gtext_font_prec text_font_prec;
    double char_expan, char_space;
    int text_colr_ind;
    double char_ht;
    Gvec char_up_vec;
    Gtext_path text_path;
    Gtext_align text_align;
    int fill_ind;
    Gfill_int_style fill_int_style;
    int fill_style_ind;
    Gvec pat_size;               /* width, height */
    Gpoint3 pat_ref_point;
    Gvec3 pat_ref_vec[2];        /* width and height directions (GKS-3D) */
    int edge_ind;
    Gedge_flag edge_flag;
    int edgetype;
    double edgewidth;
    int edge_colr_ind;
    Gasf asf[GKS_N_ASF];
    int pick_id;
    int hlhsr_id;
    int fill_colr_ind;
    int view_ind;
    Garea_props area_props[2];  /* front, back (SET (BACK) AREA PROPERTIES) */
    int refl_eq[2];             /* front, back reflectance equation, GREFL_* */
    uint64_t light_mask;        /* bit i-1: light source index i is active */
    int int_shad[2];            /* front, back interior shading method, GSHAD_* */
} gks_cur_attrs;

/* A FILL AREA primitive as resolved for one workstation (gks_attr_area_prim): kept with
 * what it was made from, the attributes a (compared bytewise unless attrs_gen says the
 * state list's block is unchanged) and the generation of the workstation tables, so that
 * a run of areas with the same attributes resolves them once. Patterns are not kept
 * (their colours are allocated per primitive). */
typedef struct gks_area_memo {
    const gks_ws *ws;           /* NULL: empty */
    uint64_t tables_gen;        /* gks_context.tables_gen when made */
    uint64_t attrs_gen;         /* gks_state_list.attrs_gen when made from it, else 0 */
    gks_cur_attrs a;
    gks_prim p;                 /* the primitive sent, geometry set by each caller */
    int edge_flag;              /* p.attrs.edge_flag as resolved */
    uint64_t attr_gen;          /* p.attr_gen for a FILL AREA SET (+ 1: the same without
                                   edges, for a FILL AREA whose edge flag is cleared) */
} gks_area_memo;

typedef struct gks_norm_tran {
    Glimit3 win;
    Glimit3 vp;
} gks_norm_tran;

/* GKS state list (ISO 7942 6.4), allocated at OPEN GKS and freed at CLOSE GKS. */
typedef struct gks_state_list {
    int open_ws[GKS_MAX_OPEN_WS];   /* set of open workstations, in order of opening */
    int n_open;
    int active_ws[GKS_MAX_ACTIVE_WS];
    int n_active;
    /* The current attributes: read here, written only through gks_attrs_w (const so that
     * a write past it does not compile), which counts every write in attrs_gen. */
    const gks_cur_attrs attrs;
    uint64_t attrs_gen;         /* from 1; bumped by every gks_attrs_w */
    int cur_tnr;
    gks_norm_tran tran[GKS_MAX_NORM_TRAN + 1];
    int tran_pri[GKS_MAX_NORM_TRAN + 1]; /* viewport input priority, highest first */
    Gclip_ind clip_ind;
    char *err_file; /* error file as given at OPEN GKS (NULL = standard error) */
    struct gks_seg_store *segs; /* segment storage (gks_seg_store.h) */
    int open_seg;               /* name of the open segment, 0 = none */
    int mf_n_mo_active;         /* active MO workstations (gks_mf_record.c: the MO fast path) */
    int mf_last_mi;             /* 1 + id of the MI the last GKSM item was read from; 0 none */
    struct gks_in_queue *inq;   /* input queue and current event report (gks_indev.h) */
    gks_area_memo area_memo[GKS_MAX_OPEN_WS]; /* by workstation identifier modulo the size */
} gks_state_list;

/* Error state list (ISO 7942 6.5) plus the installed ERROR HANDLING procedure. Survives
 * CLOSE GKS: the handler is installed by the application, possibly before OPEN GKS. */
typedef struct gks_error_state {
    int in_handler;        /* error state: ON while ERROR HANDLING runs */
    int last_error;
    FILE *fp;              /* error file opened at OPEN GKS, NULL = standard error */
    Gerr_handler handler;  /* NULL = gerr_hand */
    unsigned long epoch;   /* world epoch (gks_error.h): changes when the world does */
    /* What went wrong, in words, for the next report (gks_error_note: a file and the
     * system's reason, a missing display); moved to `detail` by gks_error_report, where
     * ERROR LOGGING and gks_error_detail() read it while the handler runs. */
    char note[GKS_ERROR_DETAIL_MAX];
    char detail[GKS_ERROR_DETAIL_MAX];
} gks_error_state;

/* Test hook: called with every primitive just before a driver receives it. */
struct gks_prim;
typedef void (*gks_prim_hook)(void *ctx, int ws_id, const struct gks_prim *prim);

typedef struct gks_context {
    Gop_st op_st;
    gks_prim_hook prim_hook;       /* NULL except in tests (gks_test_set_prim_hook) */
    void *prim_hook_ctx;
    const gks_desc_table *desc;
    gks_state_list *sl;            /* NULL while GKS is closed */
    gks_error_state err;
    gks_ws *ws[GKS_MAX_OPEN_WS];   /* workstation state lists, parallel to sl->open_ws */
    gks_ws *rec_ws;                /* GKS3D_RECORD's hidden MO (gks_record.h), or NULL */
    int rec_mirror;                /* the workstation it mirrors, -1: none */
    int rec_drawn;                 /* a primitive recorded since its last CLEAR item */
    uint64_t tables_gen;           /* changes with every change of a workstation's bundle,
                                      pattern or colour table and at OPEN and CLOSE
                                      WORKSTATION (gks_ws_tables_changed) */
    uint64_t prim_attr_gen;        /* the last gks_prim.attr_gen given (gks_area_memo:
                                      2 per resolved set of attributes), never reset */
    uint64_t views_gen;            /* the last gks_ws.views_gen given, never reset */
} gks_context;

/* The current normalization transformation WC3 -> NDC3 as a 3x4 matrix.
 * Returns 0 or 308 (degenerate or non-finite window/viewport). GKS must be open. */
int gks_cur_norm_matrix(double m[3][4]);

/* The standard's initial values of the current primitive attributes (gks_attr.c). */
void gks_attr_init(gks_cur_attrs *a);

/* The context of this process (the C binding is procedural; GKS is single-threaded). */
extern gks_context gks_the_context; /* only through gks_ctx */
static inline gks_context *gks_ctx(void)
{
    return &gks_the_context;
}

/* GKS3D_RECORD's recorder (gks_record.h): its identifier, never a program's (they are
 * >= 0); and the recorder when a function addressed to ws_id is to be recorded on it too
 * (ws_id the mirrored workstation, or GKS_REC_WS_ID), else NULL. Here, beside the fields
 * it reads, so that the metafile hooks (store/gks_mf_record.c) and the recorder
 * (gks_record.c, which calls them) do not call each other. */
#define GKS_REC_WS_ID (-1)
static inline gks_ws *gks_record_mirror(int ws_id)
{
    const gks_context *c = gks_ctx();
    if (!c->rec_ws)
        return NULL;
    return ws_id == GKS_REC_WS_ID || (ws_id >= 0 && ws_id == c->rec_mirror) ? c->rec_ws : NULL;
}

/* A workstation's bundle, pattern or colour table changed, or a workstation was created or
 * destroyed: what the pipeline resolved from the tables is made again. */
static inline void gks_ws_tables_changed(void)
{
    gks_ctx()->tables_gen++;
}

/* A state list's current attributes for writing: counts the write (attrs_gen), so that
 * what the pipeline resolved from them is made again. */
static inline gks_cur_attrs *gks_attrs_w_of(gks_state_list *sl)
{
    sl->attrs_gen++;
    return (gks_cur_attrs *)&sl->attrs; /* the state list is allocated, never const */
}
/* The same for the state list of open GKS. */
static inline gks_cur_attrs *gks_attrs_w(void)
{
    return gks_attrs_w_of(gks_ctx()->sl);
}

/* Workstation state list of open workstation ws_id, or NULL. */
gks_ws *gks_ws_lookup(int ws_id);

/* Driver of workstation type ws_type as the application gave it (GKS3D_WS_TYPES applied,
 * gks_legacy.h), or NULL if the type does not exist. */
const gks_ws_driver *gks_driver_for_type(int ws_type);

/* The open WISS workstation, or NULL. */
gks_ws *gks_wiss(void);

#endif
