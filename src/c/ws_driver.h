/*
 * ws_driver.h -- workstation drivers behind one small interface (cairo/netCDF style):
 * one static const table per workstation type, designated initialisers, NULL = not
 * supported (the core supplies the default). The core decides legality and resolves
 * attributes; a driver receives primitives in NDC3 with resolved colours and only draws.
 */
#ifndef WS_DRIVER_H
#define WS_DRIVER_H
#include "gks_private.h"
#include "gks.h"
#include "gks_context.h"

#define GKS_WS_DRIVER_VERSION 1

/* Workstation description table (ISO 7942 6.2): constant per workstation type. */
typedef struct gks_ws_desc {
    int type;
    const char *name;
    Gws_cat cat;
    Gws_class cls;
    Gdc_units dc_units;
    double dc_x, dc_y;            /* display space size in DC units */
    int raster_x, raster_y;       /* display space size in raster units */
    Gcolr_avail colr_avail;
    int n_colr;                   /* colour table size */
    int n_pred_colr;              /* predefined colour representations */
    const Grgb *pred_colr;
    Girg_mode default_irg;        /* default implicit regeneration mode */
    Gdefer_mode default_defer;
    unsigned hlhsr_modes;         /* mask of supported HLHSR modes (1 << mode) */
} gks_ws_desc;

/* A primitive as the core hands it to drivers: points in NDC3 after normalization and
 * clipping to the viewport (if on); attributes resolved to colours. */
typedef enum { GKS_PRIM_POLYLINE, GKS_PRIM_FILL_AREA } gks_prim_kind;

typedef struct gks_prim {
    gks_prim_kind kind;
    int n_loops;              /* fill area set: number of loops; 1 otherwise */
    const int *loop_counts;   /* points per loop */
    int n_points;
    const Gpoint3 *pts;       /* NDC3 */
    Grgb colour;
    int view_ind;             /* view index attribute: the ws's view representation */
    Garea_props area_props[2]; /* front, back area properties (lighting) */
    int refl_eq[2];           /* front, back reflectance equation, GREFL_* */
    uint64_t light_mask;      /* bit i-1: light source index i is active */
} gks_prim;

/* Workstation state list (ISO 7942 6.6): owned by the core, created at OPEN WORKSTATION. */
struct gks_ws {
    int id;
    char *conn_id;
    const gks_ws_driver *drv;
    Gws_st state;
    Gdefer_mode defer_mode;
    Girg_mode irg_mode;
    Gdisp_space_empty disp_empty;
    Gnew_frame_nec_upd new_frame;
    Gupd_st tran_upd_st;
    Glimit3 req_win, cur_win;     /* workstation window, NPC */
    Glimit3 req_vp, cur_vp;       /* workstation viewport, DC */
    Grgb *colr;                   /* colour table, desc->n_colr entries */
    Gview_rep3 views[GKS_MAX_VIEW_IND + 1]; /* view table; 0 fixed: identity, NPC cube */
    int hlhsr_mode;
    unsigned char *colr_defined;
    Glight_src_rep lights[GKS_MAX_LIGHT_IND];      /* light source table, index i at [i-1] */
    unsigned char light_defined[GKS_MAX_LIGHT_IND];
    void *priv;                   /* the driver's own data */
};

struct gks_ws_driver {
    int version;
    const gks_ws_desc *desc;
    /* Returns 0 or a GKS error number (26: cannot be opened, 300: storage). */
    int (*open)(gks_ws *ws);
    void (*close)(gks_ws *ws);
    /* Start a new frame (the display surface is cleared). */
    int (*clear)(gks_ws *ws);
    /* Make the picture current: e.g. write the frame's file. */
    int (*update)(gks_ws *ws);
    int (*primitive)(gks_ws *ws, const gks_prim *prim);
    int (*message)(gks_ws *ws, const char *msg);
    /* Returns 0, 180 (not supported by this ws) or 182 (bad data record). */
    int (*escape)(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out);
};

/* The compiled-in drivers. */
extern const gks_ws_driver gks_ws_null_driver;
extern const gks_ws_driver gks_ws_png_driver;
extern const gks_ws_driver gks_ws_png_large_driver;
#endif
