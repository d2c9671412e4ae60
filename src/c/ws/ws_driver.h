/* SPDX-License-Identifier: MIT */
/*
 * ws_driver.h -- workstation drivers behind one small interface (cairo/netCDF style):
 * one static const table per workstation type, designated initialisers, NULL = not
 * supported (the core supplies the default). The core decides legality and resolves
 * attributes; a driver receives primitives in NDC3 with resolved colours and only draws.
 * This header and ws_input.h are all a driver knows of the core: it includes no header of
 * src/c/core, and what it may ask of the core goes through gks_ws.host and
 * gks_in_active (the CMake modules of the drivers do not see src/c/core).
 */
#ifndef WS_DRIVER_H
#define WS_DRIVER_H
#include "gks_private.h"
#include "gks.h"
#include "ws_wdt.h"
#include "ws_input.h"
#include <stddef.h>
#include <stdint.h>

typedef struct gks_ws gks_ws;
typedef struct gks_ws_driver gks_ws_driver;

/* A GKS 3-D limit as the six numbers xmin, xmax, ymin, ymax, zmin, zmax. */
static inline void gks_limit3_array(const Glimit3 *l, double b[6])
{
    b[0] = l->x_min; b[1] = l->x_max; b[2] = l->y_min;
    b[3] = l->y_max; b[4] = l->z_min; b[5] = l->z_max;
}

/* What the core does for a driver on request (set at OPEN WORKSTATION, gks_ws.c).
 * file_claim: a file workstation is about to create or replace the file `path` (a frame
 * after the first, a name an ESCAPE set; frame 1 of the name opened may be passed too).
 * 0 if no other open workstation writes or reads that file (canonical paths compared, as
 * at OPEN); its path is then ws's for as long as ws is open. 21 if another one uses it
 * (nothing is written), 26 if it is not a regular file or cannot be created, 300. */
typedef struct gks_ws_host {
    int (*file_claim)(gks_ws *ws, const char *path);
    /* 1 if another open workstation writes (or wrote, in this opening) the file path. */
    int (*file_taken)(const gks_ws *ws, const char *path);
    /* Words for the error the driver is about to return (the file and the system's
     * reason, the display that is missing): the core's report shows them after the
     * standard message (gks_error_detail). Use gks_ws_note below. */
    void (*note)(const char *text);
} gks_ws_host;

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
    /* Output facilities and predefined bundles (ws_wdt.h); NULL = gks_wdt_raster. */
    const struct gks_wdt_output *out;
    /* Logical input devices (category INPUT/OUTIN), NULL = none (gks_indev.h). */
    const struct gks_in_desc *in;
} gks_ws_desc;

/* The description-table members that the workstations which draw nothing (null, WISS, MO,
 * MI) share: a square display space of dc DC units (and raster units), DC units OTHER,
 * colour available, implicit regeneration allowed, deferral ASAP, the raster output
 * table. Each table adds its colour table, predefined colours (gks_wdt_white_black) and
 * HLHSR modes. */
#define GKS_WS_DESC_NODRAW(type_, name_, cat_, cls_, dc_)                                  \
    .type = (type_), .name = (name_), .cat = (cat_), .cls = (cls_), .dc_units = GDC_OTHER,  \
    .dc_x = (dc_), .dc_y = (dc_), .raster_x = (dc_), .raster_y = (dc_),                    \
    .colr_avail = GAVAIL_COLR, .default_irg = GIRG_ALLOWED, .default_defer = GDEFER_ASAP,  \
    .out = &gks_wdt_raster

/* The driver of a workstation that draws nothing and has no entries of its own (null,
 * WISS): the description table of GKS_WS_DESC_NODRAW with n_colr_ colours, the predefined
 * gks_wdt_white_black and HLHSR mode NONE alone, and the driver table drv_ naming it. */
#define GKS_WS_DRIVER_NODRAW(drv_, type_, name_, cat_, cls_, dc_, n_colr_)                 \
    static const gks_ws_desc drv_##_desc = {                                               \
        GKS_WS_DESC_NODRAW(type_, name_, cat_, cls_, dc_),                                 \
        .n_colr = (n_colr_),                                                               \
        .n_pred_colr = 2,                                                                  \
        .pred_colr = gks_wdt_white_black,                                                  \
        .hlhsr_modes = 1u << GHLHSR_NONE,                                                  \
    };                                                                                     \
    const gks_ws_driver drv_ = { .desc = &drv_##_desc }

/* A primitive as the core hands it to drivers: points in NDC3 after normalization,
 * segment transformation and clipping to the viewport (if on); attributes resolved for this
 * workstation (individual or bundled by the aspect source flags, colour indices turned into
 * colours, unsupported values replaced as the standard says). TEXT reaches drivers as
 * GKS_PRIM_POLYLINE strokes (text = 1) unless the driver's text entry takes it; FILL AREA
 * SET as GKS_PRIM_FILL_AREA with n_loops >= 1 and the edge attributes; markers as their
 * clip-surviving centres. */
typedef enum {
    GKS_PRIM_POLYLINE, GKS_PRIM_FILL_AREA, GKS_PRIM_POLYMARKER, GKS_PRIM_CELL_ARRAY
} gks_prim_kind;

typedef struct gks_prim_attrs {
    int linetype;              /* 1 solid, 2 dashed, 3 dotted, 4 dash-dotted */
    double linewidth;          /* linewidth scale factor (1 = nominal width) */
    int marker_type;           /* 1 dot, 2 plus, 3 asterisk, 4 circle, 5 diagonal cross */
    double marker_size;        /* marker size scale factor (1 = nominal size) */
    Gfill_int_style int_style; /* fill area interior style */
    int style_ind;             /* hatch style (negative, ISO) or pattern index */
    int pat_nx, pat_ny;        /* pattern: cell counts and colours (row-major, row 0 at the */
    const Grgb *pattern;       /* reference point), NULL unless int_style == GSTYLE_PAT */
    Gpoint3 pat_ref;           /* pattern reference point and the pattern box's width and */
    Gvec3 pat_width, pat_height; /* height vectors, all in NDC3 (0 unless pattern is set) */
    int edge_flag;             /* FILL AREA SET edges: 0 off, 1 on */
    int edgetype;              /* as linetype */
    double edgewidth;          /* edgewidth scale factor */
    Grgb edge_colour;
    int hlhsr_id;              /* HLHSR identifier attribute */
    int pick_id;               /* pick identifier attribute */
    int text;                  /* 1: a polyline stroke of TEXT (annotation) */
} gks_prim_attrs;

typedef struct gks_prim {
    gks_prim_kind kind;
    int n_loops;              /* fill area set: number of loops; 1 otherwise */
    const int *loop_counts;   /* points per loop */
    int n_points;
    const Gpoint3 *pts;       /* NDC3 */
    Grgb colour;              /* line, marker, text or fill colour */
    gks_prim_attrs attrs;
    /* CELL ARRAY (3): the parallelogram P (cell (0,0) corner), Q (opposite corner), R (the
     * corner at the end of P's first row) in NDC3, nx*ny colours row-major from P; the clip
     * box (NDC3 xmin,xmax,ymin,ymax,zmin,zmax) applies when clip = 1 (cells are clipped per
     * sample, the only primitive not clipped in the core). */
    Gpoint3 cell_p, cell_q, cell_r;
    int cell_nx, cell_ny;
    const Grgb *cells;
    int clip;
    double clip_box[6];
    int view_ind;             /* view index attribute: the ws's view representation */
    Garea_props area_props[2]; /* front, back area properties (lighting) */
    int refl_eq[2];           /* front, back reflectance equation, GREFL_* */
    uint64_t light_mask;      /* bit i-1: light source index i is active */
    /* FILL AREA primitives with data (FILL AREA (SET) 3 WITH DATA; triangle strips,
     * quadrilateral meshes and sets of fill area sets arrive as one FILL AREA per facet
     * unless the driver's entry mesh takes them whole, gks_mesh below):
     * per-vertex unit normals in NDC3 (inverse transpose of the point transformation,
     * renormalised) and colours resolved for this workstation, n_points each in the
     * order of pts (all loops), NULL = none; the facet normal (unit, NDC3) when
     * has_fnormal; clipping interpolated both at new vertices. A facet colour is already
     * in colour. All zero/NULL for the other primitives. */
    const Gvec3 *vnormals;
    const Grgb *vcolours;
    int has_fnormal;
    Gvec3 fnormal;
    int shading[2];           /* front, back interior shading method, GSHAD_* (1..3) */
    /* A number for the attributes: every field above but the geometry (n_loops,
     * loop_counts, n_points, pts) and the data (vnormals, vcolours, has_fnormal, fnormal).
     * Two primitives with the same non-zero attr_gen have the same attributes, so a
     * driver that keeps what it made of the last one's may reuse it without looking at
     * them; 0: no such promise (compare them). The core never gives a number to two
     * different sets of attributes in a process. */
    uint64_t attr_gen;
} gks_prim;

/* TEXT (3) as text, for a driver that draws the characters itself (the optional entry
 * `text` of gks_ws_driver). The layout types are gks_text_layout.h's (core/pipe): attrs
 * are resolved for this workstation (font and precision, height, up vector, path,
 * alignment, expansion factor, spacing), frame is the text plane in source coordinates
 * (WC3), m maps them to NDC3 (normalization, then the segment transformation), and the
 * clipping volume box (NDC3) applies when clip_on; the strokes the core would send are
 * those of gks_text_strokes(frame, attrs, str) through m, clipped at box. */
typedef struct gks_text_prim {
    const char *str;                     /* printable ISO 646, not empty */
    const struct gks_text_frame *frame;
    const struct gks_text_attrs *attrs;
    double m[3][4];
    int clip_on;
    double clip_box[6];
    Grgb colour;                         /* text colour */
    int hlhsr_id, pick_id, view_ind;
} gks_text_prim;

/* A primitive with data as one indexed mesh, for a driver that keeps a mesh whole (the
 * optional entry `mesh` of gks_ws_driver): TRIANGLE STRIP 3, QUADRILATERAL MESH 3, SET OF
 * FILL AREA SET 3 and FILL AREA (SET) 3 WITH DATA, with its shared vertices. n_verts points
 * in NDC3 (normalization and segment transformation applied), the per-vertex unit normals
 * (inverse transpose, renormalised) and colours (resolved for this workstation) where the
 * primitive has them, NULL otherwise; n_facets facets, facet f of facet_loops[f] loops, the
 * loops' vertex counts in loop_counts and their vertex indices (0 <= idx < n_verts) in idx,
 * all facets' loops in order; per-facet colours (resolved) and unit normals or NULL. prim
 * carries the attributes exactly as the facets would (kind GKS_PRIM_FILL_AREA, resolved
 * colour, area properties, shading, view, lights; pts, vnormals etc. unset). The core calls
 * the entry only for a mesh that needs no clipping (clipping off, or every vertex inside the
 * clipping volume), whose points are all finite and whose normals all map to unit vectors:
 * the facets it would send are then exactly the mesh's facets with these data. */
typedef struct gks_mesh {
    gks_prim prim;
    size_t n_verts;
    const double (*pts)[3];
    const double (*vnormals)[3];
    const double (*vcolours)[3];
    size_t n_facets, n_loops, n_idx;
    const int *facet_loops, *loop_counts, *idx;
    const double (*fcolours)[3];
    const double (*fnormals)[3];
} gks_mesh;

/* Result of the driver entry mesh besides 0 (drawn) and GKS error numbers: not drawn, the
 * core sends the facets one GKS_PRIM_FILL_AREA each to primitive (as without the entry). */
enum { GKS_WS_MESH_FACETS = -1 };

/* Results of the driver entry text besides 0 (drawn) and GKS error numbers. */
enum {
    GKS_WS_TEXT_STROKE = -1,  /* not drawn: the core sends the strokes (the default) */
    GKS_WS_TEXT_CLIPPED = -2  /* nothing visible: clipped away or degenerate */
};

/* Workstation state list (ISO 7942 6.6): owned by the core, created at OPEN WORKSTATION. */
struct gks_ws {
    int id;
    char *conn_id;
    char *file;                   /* canonical path of the file it writes/reads, or NULL */
    char **files;                 /* canonical paths of the other files it wrote or will */
    int n_files;                  /* write (later frames, ESCAPE file names): gks_ws_file_claim */
    size_t cap_files;
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
    /* A number for the view table: a new one whenever an entry is set (SET VIEW
     * REPRESENTATION 3) and at OPEN WORKSTATION, never given to two tables in a process,
     * so a driver that keeps what it made of the table (such as a copy of an orientation
     * matrix) may reuse it while the number stays; 0: no such promise. */
    uint64_t views_gen;
    int hlhsr_mode;
    int view_pri[GKS_MAX_VIEW_IND + 1]; /* view transformation input priority, highest first */
    unsigned char *colr_defined;
    Glight_src_rep lights[GKS_MAX_LIGHT_IND];      /* light source table, index i at [i-1] */
    unsigned char light_defined[GKS_MAX_LIGHT_IND];
    void *priv;                   /* the driver's own data */
    void *mf;                     /* the core's metafile state of an MO or MI (gks_mf_record.h) */
    const gks_ws_host *host;      /* the core's services (above) */
    struct gks_in_ws *in;         /* input device state lists (core's), NULL = no input */
    /* Bundle tables (ISO 7942 6.6), index i at [i], 1..GKS_WDT_MAX_BUNDLES; *_def[i] != 0
     * when entry i is defined. Initialised from the description table's predefined
     * bundles at OPEN WORKSTATION. Pattern colour arrays are owned (gks_alloc). */
    Gline_bundle line_rep[GKS_WDT_MAX_BUNDLES + 1];
    Gmarker_bundle marker_rep[GKS_WDT_MAX_BUNDLES + 1];
    Gtext_bundle text_rep[GKS_WDT_MAX_BUNDLES + 1];
    Gfill_bundle fill_rep[GKS_WDT_MAX_BUNDLES + 1];
    Gedge_bundle edge_rep[GKS_WDT_MAX_BUNDLES + 1];
    struct { int nx, ny; int *colr; } pat_rep[GKS_WDT_MAX_BUNDLES + 1];
    unsigned char line_def[GKS_WDT_MAX_BUNDLES + 1], marker_def[GKS_WDT_MAX_BUNDLES + 1],
        text_def[GKS_WDT_MAX_BUNDLES + 1], fill_def[GKS_WDT_MAX_BUNDLES + 1],
        edge_def[GKS_WDT_MAX_BUNDLES + 1], pat_def[GKS_WDT_MAX_BUNDLES + 1];
};

struct gksm_in; /* ws/mf/gks_mf_codec.h */
struct gks_ws_driver {
    const gks_ws_desc *desc;
    /* File workstations: the name of the file the workstation will write (MI: read) for
     * its connection identifier, in *path (gks_alloc'd); 0, 21 or 300. OPEN WORKSTATION
     * checks it before open (gks_ws_file_check): 26 if it cannot be created (read), 21
     * if another open workstation uses the same file. NULL: no file. */
    int (*file)(const gks_ws *ws, char **path);
    /* Returns 0 or a GKS error number (26: cannot be opened, 300: storage). */
    int (*open)(gks_ws *ws);
    void (*close)(gks_ws *ws);
    /* CLOSE WORKSTATION, after update and before close: write what ends the output (a
     * metafile's END item) and close the file, checking every result. Returns 0 or 303
     * (a loss not reported before). NULL: nothing to finish. EMERGENCY CLOSE GKS does not
     * call it: close must then end what it can without reporting. */
    int (*finish)(gks_ws *ws);
    /* Start a new frame (the display surface is cleared). */
    int (*clear)(gks_ws *ws);
    /* Colour 0 changed while the display surface is empty (no output since the frame
     * began): the frame's background becomes the new colour 0 (ws->colr[0]), the frame
     * stays the same (same file, same page; a picture already written of it is written
     * again at the next update). Returns 0 or 300. NULL: the driver reads colour 0 only
     * when it writes the frame. */
    int (*background)(gks_ws *ws);
    /* Make the picture current: e.g. write the frame's file. */
    int (*update)(gks_ws *ws);
    int (*primitive)(gks_ws *ws, const gks_prim *prim);
    /* TEXT (3) unstroked (gks_text_prim): 0, GKS_WS_TEXT_STROKE, GKS_WS_TEXT_CLIPPED or an
     * error number. NULL: every TEXT reaches primitive as its strokes. */
    int (*text)(gks_ws *ws, const gks_text_prim *t);
    /* A mesh with data as one indexed primitive (gks_mesh): 0, GKS_WS_MESH_FACETS or an
     * error number. NULL: every mesh reaches primitive as one FILL AREA per facet. */
    int (*mesh)(gks_ws *ws, const gks_mesh *m);
    int (*message)(gks_ws *ws, const char *msg);
    /* Returns 0, 180 (not supported by this ws) or 182 (bad data record). */
    int (*escape)(gks_ws *ws, int func_id, const Gescape_in_data *in, Gescape_out_data *out);
    /* Pixel readback (INQUIRE PIXEL ...): the picture as it would be written now, nx x ny
     * pixels from image pixel (x0, y0) (DC relative to the viewport origin, y up), row by
     * row upward, each 0xRRGGBB (8 bits per component) or -1 outside the image. Returns 0
     * or 300. NULL: the type has no pixel store readback (error 40). */
    int (*read_pixels)(gks_ws *ws, int x0, int y0, int nx, int ny, int *rgb);
    /* Interactive input devices: waits at most timeout seconds (0: poll) for a raw event
     * of the physical devices, given the logical devices taking input now (to map the
     * mouse and keys to them and to draw prompts and echoes). Returns 1 with *ev filled
     * (valid until the next call), 0 if none came, -1 if no event can ever come (e.g.
     * the window is gone). NULL: the type's devices are fed by input scripts only. */
    int (*input)(gks_ws *ws, const gks_in_active *act, double timeout, gks_in_raw *ev);
    /* Metafile output (MO): writes one item, its type and data record (the fields as the
     * core encodes them, ws/mf/gks_mf_codec.h). Returns 0, 161 (type or length beyond the
     * format) or 303: a write failed, and from then on the driver writes nothing more and
     * returns 0 (a loss is reported once). NULL: the type records no metafile. */
    int (*record_item)(gks_ws *ws, int type, const char *rec, size_t len);
    /* Metafile input (MI): the reader of its file (the items, their field format), for GET
     * ITEM TYPE, READ ITEM and INTERPRET ITEM in the core, and in *allow_escapes whether
     * ESCAPE GESC_MI_ALLOW_ESCAPES allowed every recorded escape. NULL: not a metafile input. */
    struct gksm_in *(*item_reader)(gks_ws *ws, int *allow_escapes);
};

/* The drivers of the list ws_drivers.def (those of an optional dependency are defined
 * only when it is built, and listed only then). */
#define GKS_WS_DRIVER(folder, table, when) extern const gks_ws_driver table;
#include "ws_drivers.def"
#undef GKS_WS_DRIVER
/* gks_ws_host.file_claim of ws's core. */
static inline int gks_ws_file_claim(gks_ws *ws, const char *path)
{
    return ws->host->file_claim(ws, path);
}
/* gks_ws_host.note of ws's core, printf-formatted (ws_file.c). */
void gks_ws_note(const gks_ws *ws, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* gks_ws_host.file_taken of ws's core. */
static inline int gks_ws_file_taken(const gks_ws *ws, const char *path)
{
    return ws->host->file_taken(ws, path);
}
/* The base name of ws's files (ws_file.h) for extension ext; a connection identifier
 * that names no file (""/NULL, or all digits: a Fortran unit) whose frame-1 file another
 * open workstation writes gets B-wsW instead (W = ws's identifier), so that several
 * workstations on one such connection write files of their own. gks_alloc'ed, NULL on
 * storage overflow (ws_file.c). */
char *gks_ws_file_default_base(const gks_ws *ws, const char *ext);
/* The file of frame `frame` of base (extension ext) claimed as above: 0 with *path
 * (gks_alloc'd), else 300 or the claim's 21, 26 with *path NULL (ws_file.c). */
int gks_ws_file_claim_frame(gks_ws *ws, const char *base, int frame, const char *ext,
                            char **path);
/* ESCAPE "set file name": the base name name[0..len) replaces *base (gks_alloc'd) when the
 * file of its frame `frame` (extension ext) can be claimed as above; 0, 21, 26 or 300, and
 * *base unchanged on error (ws_file.c). */
int gks_ws_file_rename(gks_ws *ws, const char *name, size_t len, int frame, const char *ext,
                       char **base);
/* The message entry of the file workstations, which have no operator display: the message
 * goes to standard error (ws_file.c). Returns 0. */
int gks_ws_file_message(gks_ws *ws, const char *msg);
/* The integer argument of a workstation's ESCAPE, ints[1] of the input data record (ints[0]
 * is the function identifier), into *v: 0 when it is there and in [lo, hi], else 182
 * (ws_file.c). */
int gks_ws_escape_int(const Gescape_in_data *in, int lo, int hi, int *v);
/* The workstation transformation of ws (current window -> current viewport, NPC3 -> DC3)
 * as a 4x4 matrix (ws_tran.c); gks_ws_pixel_matrix maps onto the picture's pixels
 * instead: the viewport moved to the origin and scaled by s pixels per DC unit, z onto
 * [0,1]. 0, or gks_xform_ws_tran3's error (51, 308). */
int gks_ws_tran_matrix(const gks_ws *ws, double m[4][4]);
int gks_ws_pixel_matrix(const gks_ws *ws, double s, double m[4][4]);
#endif
