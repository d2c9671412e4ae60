/* SPDX-License-Identifier: MIT */
/*
 * gks.h -- C binding of the gks3d library: GKS-3D (ISO 8805) in the style of the
 * ISO 8651-4 GKS C binding.
 *
 * Names follow ISO 8651-4 (gopen_gks, gopen_ws, gpolyline, ginq_op_st, ...). Where the
 * GKS-3D C binding (ISO/IEC 8806-4) text was not available, GKS-3D functions follow the
 * same naming rules (a trailing "3" for 3-D variants: gfill_area3, gset_win3, ...); see
 * docs/BINDING.md for every such choice.
 *
 * Gfloat is double: the whole pipeline is computed in double precision.
 */
#ifndef GKS3D_GKS_H
#define GKS3D_GKS_H

#include <stddef.h>

#include "gks3d_version.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(GKS3D_BUILDING)
#define GKS_API __attribute__((visibility("default")))
#else
#define GKS_API
#endif

/* ESCAPE of a metafile input workstation (docs/METAFILE.md, "Untrusted input"): ints[0] the MI
 * workstation, ints[1] 1: INTERPRET ITEM of items read from it performs every recorded
 * ESCAPE as recorded; 0 (the default): only the picture settings listed there, with the
 * ray-tracing sample count and depth capped; file names, threads, progress output and the
 * other identifiers are refused (error 180). */
enum { GESC_MI_ALLOW_ESCAPES = -140 };

/* ---------------------------------------------------------------------------------
 * Basic types
 * --------------------------------------------------------------------------------- */
typedef int Gint;
typedef double Gfloat;
typedef double Gdouble;

typedef struct { size_t size; void *data; } Gdata;

/* ---------------------------------------------------------------------------------
 * Enumerations (values as the ISO Fortran binding's GKS_PAR constants)
 * --------------------------------------------------------------------------------- */
typedef enum { GASF_BUNDLED, GASF_INDIV } Gasf;
typedef enum { GIND_NO_CLIP, GIND_CLIP } Gclip_ind;
typedef enum { GAVAIL_MONOCHR, GAVAIL_COLR } Gcolr_avail;
typedef enum { GFLAG_COND, GFLAG_ALWAYS } Gctrl_flag;
typedef enum { GCOORD_WC, GCOORD_NDC } Gcoord_switch;
typedef enum { GDC_METRES, GDC_OTHER } Gdc_units;
typedef enum { GDEFER_ASAP, GDEFER_BNIG, GDEFER_BNIL, GDEFER_ASTI } Gdefer_mode;
typedef enum { GDISP_NOT_EMPTY, GDISP_EMPTY } Gdisp_space_empty;
typedef enum { GIRG_SUPPR, GIRG_ALLOWED } Girg_mode;
typedef enum {
    GLEVEL_0A, GLEVEL_0B, GLEVEL_0C, GLEVEL_1A, GLEVEL_1B,
    GLEVEL_1C, GLEVEL_2A, GLEVEL_2B, GLEVEL_2C
} Glevel;
typedef enum { GNEW_NO, GNEW_YES } Gnew_frame_nec_upd;
typedef enum { GST_GKCL, GST_GKOP, GST_WSOP, GST_WSAC, GST_SGOP } Gop_st;
typedef enum { GFLAG_POSTPONE, GFLAG_PERFORM } Gupd_regen_flag;
typedef enum { GUPD_NOT_PEND, GUPD_PEND } Gupd_st;
typedef enum { GCAT_OUT, GCAT_IN, GCAT_OUTIN, GCAT_WISS, GCAT_MO, GCAT_MI } Gws_cat;
typedef enum { GCLASS_VEC, GCLASS_RASTER, GCLASS_OTHER } Gws_class;
typedef enum { GWS_INACTIVE, GWS_ACTIVE } Gws_st;
typedef enum { GINQ_SET, GINQ_REALIZED } Ginq_type;
typedef enum { GSTYLE_HOLLOW, GSTYLE_SOLID, GSTYLE_PAT, GSTYLE_HATCH } Gfill_int_style;

/* ---------------------------------------------------------------------------------
 * Structures
 * --------------------------------------------------------------------------------- */
typedef struct { Gfloat x, y; } Gpoint;
typedef struct { Gfloat x, y, z; } Gpoint3;
typedef struct { Gfloat delta_x, delta_y; } Gvec;
typedef struct { Gfloat delta_x, delta_y, delta_z; } Gvec3;
typedef struct { Gfloat x_min, x_max, y_min, y_max; } Glimit;
typedef struct { Gfloat x_min, x_max, y_min, y_max, z_min, z_max; } Glimit3;
typedef struct { Gint num_points; Gpoint *points; } Gpoint_list;
typedef struct { Gint num_points; Gpoint3 *points; } Gpoint_list3;
typedef struct { Gint num_ints; Gint *ints; } Gint_list;
typedef struct { Gfloat red, green, blue; } Grgb;
typedef union { Grgb rgb; } Gcolr_rep;
typedef struct { Gfloat size_x, size_y; } Gfloat_size;
typedef struct { Gint size_x, size_y; } Gint_size;
typedef struct { Glimit win; Glimit vp; } Gtran;
typedef struct { Gclip_ind clip_ind; Glimit clip_rect; } Gclip;

/* Maximum numbers of workstations (INQUIRE WORKSTATION MAXIMUM NUMBERS). */
typedef struct { Gint simult_open, simult_active, assoc_seg; } Gws_max_nums;

/* Display space size (INQUIRE DISPLAY SPACE SIZE). */
typedef struct {
    Gdc_units dc_units;
    Gfloat_size size_dc;
    Gint_size size_raster;
} Gdisp_space_size;

/* ESCAPE data records (ISO 8651-4: a union with one member per escape; escape_r1 ... for
 * registered, escape_u1 ... for implementation-specific escapes). Every escape of this
 * library takes the same record, the anonymous first member: an integer array, a real
 * array and a string; the Gdata members exist for source compatibility and are never
 * read. Output records live in the application's Gstore (gescape). */
typedef union {
    struct {
        Gint num_ints;   const Gint *ints;
        Gint num_floats; const Gfloat *floats;
        size_t str_len;  const char *str;
    };
    Gdata escape_r1;
    Gdata escape_u1;
} Gescape_in_data;
typedef union {
    struct {
        Gint num_ints;   Gint *ints;      /* capacity in, count out (driver side) */
        Gint num_floats; Gfloat *floats;  /* capacity in, count out (driver side) */
    };
    Gdata escape_r1;
    Gdata escape_u1;
} Gescape_out_data;
/* Storage for results whose size only GKS knows (ISO 8651-4 3.9): gcreate_store,
 * gdel_store; each call a store is passed to frees what it held before. */
typedef struct gks_store_rec *Gstore;

/* ERROR HANDLING procedure type: (error number, function identification, error file). */
typedef void (*Gerr_handler)(Gint err_num, Gint func_num, const char *err_file);

/* ---------------------------------------------------------------------------------
 * Workstation types of this implementation (INQUIRE LIST OF AVAILABLE WORKSTATION TYPES)
 * --------------------------------------------------------------------------------- */
enum {
    GWS_TYPE_MO = 2,          /* category MO: GKS metafile output; connection id = file name */
    GWS_TYPE_WISS = 3,        /* category WISS: workstation independent segment storage */
    GWS_TYPE_MI = 4,          /* category MI: GKS metafile input; connection id = file name */
    GWS_TYPE_NULL = 99,       /* category OUTPUT: accepts everything, draws nothing */
    GWS_TYPE_PNG = 100,       /* category OUTIN, raster, 1024x1024 pixel display space;
                                 input from scripts (docs/INPUT.md) */
    GWS_TYPE_PNG_LARGE = 101, /* category OUTIN, raster, 8192x8192 pixel display space */
    GWS_TYPE_PNG_OUTPUT = 102, /* category OUTPUT (no input devices), otherwise as 100 */
    /* Vector workstations (built with cairo only, else OPEN WORKSTATION reports 23): category
     * OUTPUT, display space A4 portrait in metres (DC = metres), page = ws viewport. */
    GWS_TYPE_PDF = 110,       /* PDF file, one page per frame */
    GWS_TYPE_SVG = 111,       /* SVG file per frame (named like the PNG frames) */
    GWS_TYPE_PS = 112,        /* PostScript file, one page per frame */
    GWS_TYPE_EPS = 113,       /* EPS file per frame */
    GWS_TYPE_X11 = 210        /* category OUTIN, interactive X11 window, 800x800 pixels;
                                 only in builds with GKS_WITH_X11 (else error 23) */
};

/* Function identifications passed to ERROR HANDLING: the standard's numbers (0..108, the
 * RAL GKSE_PAR list); GKS-3D and this library's additions are numbered from 109 on.
 * The full list is in docs/BINDING.md. */
enum {
#define GKS_FN(id, sym, name, states, mf) GFN_##sym = id,
#include "gks_functions.def"
#undef GKS_FN
    GFN_COUNT_DUMMY_
};

/* The version of the library loaded at run time, GKS3D_VERSION_ENCODE(major, minor, patch),
 * to compare with GKS3D_VERSION of the headers compiled against (gks3d_version.h). Not an
 * ISO function: callable in every operating state, reports no error; each pointer may be
 * NULL. */
GKS_API int gks3d_version(int *major, int *minor, int *patch);

/* ---------------------------------------------------------------------------------
 * Control functions
 * --------------------------------------------------------------------------------- */
/* OPEN GKS. err_file: path of the error file (NULL or "" = standard error). Errors: 1, 200. */
GKS_API void gopen_gks(const char *err_file, size_t mem_unit);
/* CLOSE GKS. Errors: 2. */
GKS_API void gclose_gks(void);
/* OPEN WORKSTATION. conn_id: see docs (PNG file naming). Errors: 8, 20, 21, 22, 23, 24, 26, 28, 42. */
GKS_API void gopen_ws(Gint ws_id, const char *conn_id, Gint ws_type);
/* CLOSE WORKSTATION. Errors: 7, 20, 25, 29, 147. */
GKS_API void gclose_ws(Gint ws_id);
/* ACTIVATE WORKSTATION. Errors: 6, 20, 25, 29, 33, 35, 43. */
GKS_API void gactivate_ws(Gint ws_id);
/* DEACTIVATE WORKSTATION. Errors: 3, 20, 30, 33, 35. */
GKS_API void gdeactivate_ws(Gint ws_id);
/* CLEAR WORKSTATION. Errors: 6, 20, 25, 33, 35. */
GKS_API void gclear_ws(Gint ws_id, Gctrl_flag ctrl_flag);
/* REDRAW ALL SEGMENTS ON WORKSTATION. Errors: 7, 20, 25, 33, 35, 36. */
GKS_API void gredraw_all_seg_ws(Gint ws_id);
/* UPDATE WORKSTATION. Errors: 7, 20, 25, 33, 35, 36. */
GKS_API void gupd_ws(Gint ws_id, Gupd_regen_flag upd_regen_flag);
/* SET DEFERRAL STATE. Errors: 7, 20, 25, 33, 35, 36. */
GKS_API void gset_defer_st(Gint ws_id, Gdefer_mode defer_mode, Girg_mode irg_mode);
/* MESSAGE. Errors: 7, 20, 25, 36. */
GKS_API void gmessage(Gint ws_id, const char *msg);
/* ESCAPE (ISO 8651-4): func_id one of the GESC_* identifiers below. An escape that
 * returns data (GESC_RT_STATS) puts it into *store_data (created by gcreate_store) and
 * sets *out_data to it; for the others store_data and out_data may be NULL (*out_data is
 * set to NULL). Errors: 8, 180, 181, 182, 300. */
GKS_API void gescape(Gint func_id, const Gescape_in_data *in_data, Gstore *store_data,
                     Gescape_out_data **out_data);
/* EMERGENCY CLOSE GKS: callable in any state, never reports an error. */
GKS_API void gemergency_close_gks(void);

/* GKS metafile (GKSM) functions; format and item types in docs/METAFILE.md.
 * Item data record (ISO 8651-4 Gitem_data). This implementation keeps every record in
 * the metafile's own character form: data.impl_dep holds its characters (size = number
 * of characters, data = the characters, no terminating NUL needed); the decoded members
 * of the standard's union are not used. */
typedef struct {
    Gint type;                         /* item type */
    Gint length;                       /* item data record length */
    union {
        Gctrl_flag clear_ws;
        Gupd_regen_flag upd_ws;
        struct { Gdefer_mode defer_mode; Girg_mode irg_mode; } defer_st;
        Gdata gdp_unsupp;
        Gdata impl_dep;                /* this implementation: the record's characters */
    } data;
} Gitem_data;
/* WRITE ITEM TO GKSM: a user item (type 101..999) of `length` characters
 * (item_data->data.impl_dep) on the active MO workstation ws_id. Errors: 5, 20, 25, 30,
 * 32, 160 (type not > 100), 161 (length < 0 or more than impl_dep.size). */
GKS_API void gwrite_item(Gint ws_id, Gint type, Gint length, const Gitem_data *item_data);
/* GET ITEM TYPE FROM GKSM: type and data record length of the MI's current item.
 * Errors: 7, 20, 25, 34, 162 (no item left), 163 (item invalid). */
GKS_API void gget_item_type(Gint ws_id, Gint *type, Gint *length);
/* READ ITEM FROM GKSM: item_data->data.impl_dep.data is the caller's buffer; it receives
 * the first min(max_length, length) characters of the current item's record
 * (impl_dep.size = that count; type and length set) and the next item becomes current.
 * Errors: 7, 20, 25, 34, 162, 163, 166 (max_length < 0, or > 0 with no buffer). */
GKS_API void gread_item(Gint ws_id, Gint max_length, Gitem_data *item_data);
/* INTERPRET ITEM: performs the recorded function (primitives in NDC3 with the recorded
 * normalization and clipping volume; workstation items on every active workstation),
 * decoding the record (item_data->data.impl_dep, `length` characters) in the field
 * format of the MI the last item was read from. Errors: 7, 161 (length < 0 or more than
 * impl_dep.size), 164 (not a GKS item type), 165 (record invalid for the type), 167 (user
 * item), and those of the function performed. */
GKS_API void ginterpret_item(Gint type, Gint length, const Gitem_data *item_data);

/* ESCAPE function identifiers of this implementation (negative = implementation specific,
 * as the standard reserves). Data records: ints[0] = workstation identifier, then as listed. */
enum {
    GESC_SET_FILE_NAME = -101,   /* ints[0] ws id; str = base file name for the next frames */
    GESC_RT_CLIP_SECONDARY = -102, /* ints[0] ws id, ints[1] 0/1: ray-traced shadow, reflection
                                    and refraction rays see only the display volume (1) or
                                    the whole scene (0, default). PNG workstations only. */
    /* Ray-tracing controls of a PNG workstation (HLHSR mode GHLHSR_RAYTRACE); they take effect
     * at the next picture written. */
    GESC_RT_SAMPLES = -103,      /* ints[1] samples per pixel (perfect square 1..256),
                                    ints[2] 0/1 jitter within strata */
    GESC_RT_MAX_DEPTH = -104,    /* ints[1] maximum ray depth 1..64 (eye ray = 1) */
    GESC_RT_CUTOFF = -105,       /* floats[0] adaptive depth cut-off weight in [0,1), 0 = off */
    GESC_RT_THREADS = -106,      /* ints[1] thread count, 0 = all online CPUs */
    GESC_RT_PROGRESS = -107,     /* ints[1] 0/1: progress report on stderr */
    GESC_RT_STATS = -108,        /* out (ints): [0] eye rays, [1] eye rays that hit, [2] reflection,
                                    [3] refraction, [4] shadow rays, [5] grid cells, [6] grid
                                    references, [7] primitives (each saturating at INT_MAX);
                                    out (floats): [0] build seconds, [1] render seconds, of the
                                    last traced picture. Capacity 8 ints / 2 floats (less: 182). */
    GESC_RT_SPD = -109,          /* ints[1] 0/1: SPD procedure (rays at pixel corners) */
    GESC_PNG_SUPERSAMPLE = -110, /* ints[1] 1..4: anti-aliasing of a PNG workstation by s x s
                                    samples per pixel (box filter); applies at once while the
                                    frame is empty, else from the next CLEAR WORKSTATION */
    GESC_PNG_COMPRESSION = -111, /* ints[1] 0: fast PNG encoding (default; zlib run-length,
                                    SUB filter), 1..9: zlib level with adaptive filters
                                    (9 smallest files); for every file written from then on */
    GESC_VEC_RESOLUTION = -112,  /* ints[1] 10..2400 dots per inch (default 300) of what a
                                    vector workstation rasterises (z-buffer and ray-traced
                                    pictures, hidden-line visibility); at once while the frame
                                    is empty, else from the next frame */
    /* Line style and page placement of the vector workstations (PDF, SVG, PS, EPS), for
     * the pages and files written from then on (a frame is drawn when it is written: the
     * whole frame). Other workstations: 180. */
    GESC_VEC_LINE_JOIN = -113,   /* ints[1] 0 miter, 1 round (default), 2 bevel */
    GESC_VEC_LINE_CAP = -114,    /* ints[1] 0 butt (default), 1 round, 2 projecting square */
    GESC_VEC_MITER_LIMIT = -115, /* floats[0] 1..1000: the miter joins' limit (ratio of the
                                    miter length to the line width; default 10) */
    GESC_VEC_LINE_SCALE = -116,  /* floats[0] 0.01..100: factor on every line width (the
                                    nominal line width; default 1) */
    GESC_VEC_PAGE = -117,        /* ints[1..4] llx, lly, urx, ury: the picture fitted
                                    (aspect kept, centred) into this rectangle of a page, in
                                    points (1/72 inch) from the page's lower left corner,
                                    -72000..72000; ints[5..6] (optional) page width and
                                    height 1..72000 (default: as given before, else 612 x
                                    792, US letter); all four 0: the default, the page is
                                    the workstation viewport */
    /* Scripted input (docs/INPUT.md): ints[0] ws id of an INPUT/OUTIN workstation; str =
     * name of a file of raw device events (device coordinates) that its logical input
     * devices replay from now on, replacing any script (182: unreadable file). */
    GESC_INPUT_SCRIPT = -130,
    /* NCAR GKS's two escapes, accepted as they are so that NCAR's programs run unchanged
     * (docs/COMPAT.md). Their record is NCAR's: the Gdata member escape_r1 (data, size),
     * or from GESC the record IDR(1). */
    GESC_NCAR_FILE_NAME = -1391, /* escape_r1: the file name (left justified, blank filled;
                                    trailing blanks dropped) of the next workstation opened
                                    that writes a file: it replaces that workstation's
                                    connection identifier */
    GESC_NCAR_PAUSE = -1396      /* escape_r1: the workstation identifier as a decimal
                                    number (NCAR: 5 characters): NCAR pauses its X window;
                                    here UPDATE WORKSTATION (PERFORM) of that workstation */
};

/* ---------------------------------------------------------------------------------
 * Error handling
 * --------------------------------------------------------------------------------- */
/* ERROR HANDLING: the default handler; it calls gerr_log. */
GKS_API void gerr_hand(Gint err_num, Gint func_num, const char *err_file);
/* ERROR LOGGING: writes number, function name and message to the error file. */
GKS_API void gerr_log(Gint err_num, Gint func_num, const char *err_file);
/* SET ERROR HANDLER (ISO 8651-4): installs new_hand (NULL = the default gerr_hand). */
GKS_API void gset_err_hand(Gerr_handler new_hand, Gerr_handler *old_hand);
/* The standard message text of an error number ("" if unknown); never NULL. */
GKS_API const char *gks_error_message(Gint err_num);
/* The ISO name of a function identification ("" if unknown); never NULL. */
GKS_API const char *gks_function_name(Gint func_num);
/* What went wrong in the error being handled, in words, beyond the standard's message:
 * for an error about a file its name and the system's reason (`cannot open "out/x.png":
 * No such file or directory`), for a missing X display which one; "" when the error has
 * none. Valid while ERROR HANDLING runs (an application's handler may read it) and until
 * the next error is reported; ERROR LOGGING writes it after the message. Never NULL. */
GKS_API const char *gks_error_detail(void);

/* ---------------------------------------------------------------------------------
 * Output primitives and attributes (2-D subset; the 3-D pipeline extends these)
 * --------------------------------------------------------------------------------- */
/* POLYLINE. Errors: 5, 100. */
GKS_API void gpolyline(const Gpoint_list *point_list);
/* FILL AREA. Errors: 5, 100. */
GKS_API void gfill_area(const Gpoint_list *point_list);
/* SET POLYLINE COLOUR INDEX. Errors: 8, 92. */
GKS_API void gset_line_colr_ind(Gint colr_ind);
/* SET FILL AREA COLOUR INDEX. Errors: 8, 92. */
GKS_API void gset_fill_colr_ind(Gint colr_ind);
/* SET COLOUR REPRESENTATION. Errors: 7, 20, 25, 33, 35, 36, 93, 96. */
GKS_API void gset_colr_rep(Gint ws_id, Gint colr_ind, const Gcolr_rep *colr_rep);
/* SET WINDOW. Errors: 8, 50, 51. */
GKS_API void gset_win(Gint tran_num, const Glimit *win);
/* SET VIEWPORT. Errors: 8, 50, 51, 52. */
GKS_API void gset_vp(Gint tran_num, const Glimit *vp);
/* SELECT NORMALIZATION TRANSFORMATION. Errors: 8, 50. */
GKS_API void gsel_norm_tran(Gint tran_num);
/* SET CLIPPING INDICATOR. Errors: 8. */
GKS_API void gset_clip_ind(Gclip_ind clip_ind);
/* SET WORKSTATION WINDOW. Errors: 7, 20, 25, 33, 36, 51, 53. */
GKS_API void gset_ws_win(Gint ws_id, const Glimit *ws_win);
/* SET WORKSTATION VIEWPORT. Errors: 7, 20, 25, 33, 36, 51, 54. */
GKS_API void gset_ws_vp(Gint ws_id, const Glimit *ws_vp);

/* ---------------------------------------------------------------------------------
 * Output primitives, attributes, bundles and their inquiries (ISO 7942 5.3-5.4 and the
 * GKS-3D additions). Errors listed per function, in the order they are checked.
 * --------------------------------------------------------------------------------- */
typedef enum { GPREC_STRING, GPREC_CHAR, GPREC_STROKE } Gtext_prec;
typedef enum { GPATH_RIGHT, GPATH_LEFT, GPATH_UP, GPATH_DOWN } Gtext_path;
typedef enum { GHOR_NORM, GHOR_LEFT, GHOR_CTR, GHOR_RIGHT } Ghor_text_align;
typedef enum { GVERT_NORM, GVERT_TOP, GVERT_CAP, GVERT_HALF, GVERT_BASE, GVERT_BOTTOM } Gvert_text_align;
typedef enum { GEDGE_OFF, GEDGE_ON } Gedge_flag;

/* Line types (also edge types), marker types and hatch styles are Gint in the standard, so
 * the ISO C binding (ISO/IEC 8651-4) names them as macros; the values are the Fortran
 * binding's GLSOLI ... (linetypes) and GPOINT ... (marker types). Hatch styles are
 * workstation dependent: these are the twelve of every drawing workstation here (ws_wdt.c,
 * docs/WORKSTATIONS.md), lines in DC spaced 8 pixels (7..12: 4 pixels) on the raster. */
#define GLINE_SOLID 1           /* ISO linetype 1, Fortran GLSOLI */
#define GLINE_DASH 2            /* ISO linetype 2, GLDASH */
#define GLINE_DOT 3             /* ISO linetype 3, GLDOT */
#define GLINE_DASH_DOT 4        /* ISO linetype 4, GLDASD */
#define GMARKER_DOT 1           /* ISO marker type 1 (.), Fortran GPOINT */
#define GMARKER_PLUS 2          /* ISO marker type 2 (+), GPLUS */
#define GMARKER_ASTERISK 3      /* ISO marker type 3 (*), GAST */
#define GMARKER_CIRCLE 4        /* ISO marker type 4 (o), GOMARK */
#define GMARKER_CROSS 5         /* ISO marker type 5 (x), GXMARK */
#define GHATCH_HOR (-1)         /* horizontal lines */
#define GHATCH_VERT (-2)        /* vertical lines */
#define GHATCH_DIAG_45 (-3)     /* rising diagonals, 45 degrees */
#define GHATCH_DIAG_135 (-4)    /* falling diagonals, 135 degrees */
#define GHATCH_CROSS (-5)       /* horizontal and vertical lines */
#define GHATCH_DIAG_CROSS (-6)  /* both diagonals */
#define GHATCH_HOR_DENSE (-7)   /* as -1 .. -6 with half the spacing */
#define GHATCH_VERT_DENSE (-8)
#define GHATCH_DIAG_45_DENSE (-9)
#define GHATCH_DIAG_135_DENSE (-10)
#define GHATCH_CROSS_DENSE (-11)
#define GHATCH_DIAG_CROSS_DENSE (-12)
typedef struct { Gint font; Gtext_prec prec; } Gtext_font_prec;
typedef struct { Ghor_text_align hor; Gvert_text_align vert; } Gtext_align;
typedef struct { Gint num_point_lists; Gpoint_list *point_lists; } Gpoint_list_list;
typedef struct { Gint num_point_lists; Gpoint_list3 *point_lists; } Gpoint_list_list3;
typedef struct { Gpoint p, q; } Grect;
/* CELL ARRAY 3 parallelogram: P = corner of cell (0,0), Q = the opposite corner, R = the
 * corner at the end of P's first row (cells of a row run from P towards R). */
typedef struct { Gpoint3 p, q, r; } Gparal;
/* Colour index array / pattern: dims.size_x columns, dims.size_y rows, element (i, j) =
 * colr_array[j * dims.size_x + i], row 0 at P (cell array) or at the reference point. */
typedef struct { Gint_size dims; Gint *colr_array; } Gpat_rep;
/* GDP data record (no GDP is supported by this implementation). */
typedef struct {
    Gint num_ints;   const Gint *ints;
    Gint num_floats; const Gfloat *floats;
    size_t str_len;  const char *str;
} Ggdp_data;
/* Aspect source flags: the 13 of GKS in the standard's order, then (Gasfs3) the four
 * GKS-3D edge flags. Default: all GASF_INDIV. */
typedef struct {
    Gasf linetype, linewidth, line_colr_ind;
    Gasf marker_type, marker_size, marker_colr_ind;
    Gasf text_font_prec, char_expan, char_space, text_colr_ind;
    Gasf fill_int_style, fill_style_ind, fill_colr_ind;
} Gasfs;
typedef struct {
    Gasfs asfs;
    Gasf edge_flag, edgetype, edgewidth, edge_colr_ind;
} Gasfs3;
/* Bundles (SET ... REPRESENTATION, INQUIRE ... REPRESENTATION). */
typedef struct { Gint type; Gfloat width; Gint colr_ind; } Gline_bundle;
typedef struct { Gint type; Gfloat size; Gint colr_ind; } Gmarker_bundle;
typedef struct {
    Gtext_font_prec text_font_prec; Gfloat char_expan; Gfloat char_space; Gint colr_ind;
} Gtext_bundle;
typedef struct { Gfill_int_style int_style; Gint style_ind; Gint colr_ind; } Gfill_bundle;
typedef struct { Gedge_flag flag; Gint type; Gfloat width; Gint colr_ind; } Gedge_bundle;
/* Workstation facilities (INQUIRE ... FACILITIES). Lists are filled like the other list
 * inquiries: the caller gives the capacity in num_elems_appl_list and the 0-based start
 * position; *length_list receives the implementation's length. A width/size count of 0
 * means continuous between min and max (nominal = the size of scale factor 1). */
typedef struct {
    Gint_list types; Gint num_widths; Gfloat nom_width, min_width, max_width; Gint num_pred_inds;
} Gline_facs;
typedef struct {
    Gint_list types; Gint num_sizes; Gfloat nom_size, min_size, max_size; Gint num_pred_inds;
} Gmarker_facs;
typedef struct {
    Gint num_font_precs; Gtext_font_prec *font_precs; /* count out (capacity: num_elems_appl_list) */
    Gint num_char_hts; Gfloat min_char_ht, max_char_ht;
    Gint num_char_expans; Gfloat min_char_expan, max_char_expan;
    Gint num_pred_inds;
} Gtext_facs;
typedef struct {
    Gint num_int_styles;
    Gfill_int_style int_style[4];  /* the available interior styles */
    Gint_list hatch_styles;        /* capacity: hatch_length; count out */
    Gint num_pred_inds;
} Gfill_facs;
typedef struct {
    Gint_list types; Gint num_widths; Gfloat nom_width, min_width, max_width; Gint num_pred_inds;
} Gedge_facs;
/* Maximum lengths of the workstation state tables (bundle indices run 1..length). */
typedef struct {
    Gint line_bundles, marker_bundles, text_bundles, fill_bundles, pat_reps, colr_reps,
         edge_bundles;
} Gmax_ws_st_tables;
/* Text extent (INQUIRE TEXT EXTENT): concatenation point and the extent parallelogram
 * (corners in the order lower-left, lower-right, upper-right, upper-left of the text
 * extent rectangle, in the text's own frame), WC. */
typedef struct { Gpoint concat_point; Gpoint paral[4]; } Gtext_extent;
typedef struct { Gpoint3 concat_point; Gpoint3 paral[4]; } Gtext_extent3;

/* POLYMARKER / POLYMARKER 3. Markers whose centre is outside the clipping region (or not
 * finite) are not drawn. Errors: 5, 100 (fewer than 1 point). */
GKS_API void gpolymarker(const Gpoint_list *point_list);
GKS_API void gpolymarker3(const Gpoint_list3 *point_list);
/* TEXT: string of ISO 646 printable characters (32..126) at pos (WC). STRING and CHAR
 * precision are drawn as STROKE (allowed: a higher precision). Errors: 5, 101. */
GKS_API void gtext(const Gpoint *pos, const char *str);
/* TEXT 3: text plane through pos spanned by dir[0] (the text's local x axis) and dir[1];
 * character up vector, height etc. act within that plane. Parallel or zero direction
 * vectors draw nothing (no error is defined). Errors: 5, 101. */
GKS_API void gtext3(const Gpoint3 *pos, const Gvec3 dir[2], const char *str);
/* FILL AREA SET / FILL AREA SET 3: even-odd interior of all loops (holes), edges drawn
 * with the edge attributes when the edge flag is on. Errors: 5, 100 (no loop, or a loop
 * with fewer than 3 points). */
GKS_API void gfill_area_set(const Gpoint_list_list *point_list_list);
GKS_API void gfill_area_set3(const Gpoint_list_list3 *point_list_list);
/* CELL ARRAY: rectangle with corners P (cell (0,0)) and Q; CELL ARRAY 3: parallelogram
 * P, Q, R. Errors: 5, 91 (a dimension < 1 or no array). */
GKS_API void gcell_array(const Grect *rect, const Gpat_rep *colr_array);
GKS_API void gcell_array3(const Gparal *paral, const Gpat_rep *colr_array);
/* GENERALIZED DRAWING PRIMITIVE (3): RAL GKS's GDPs (points on the curve) and an ellipse;
 * every output workstation type lists them (docs/BINDING.md, "GDPs"). The data record is
 * not used (may be NULL). Errors: 5, 100 (negative count, no points, or a count the GDP
 * does not take), 102 (not a GDP of this implementation). */
enum {
    GGDP_ARC = -1,    /* P1, P2, P3 on a circle: the arc P1 -> P2 -> P3 (polyline) */
    GGDP_CHORD = -2,  /* that arc closed by the chord P3 P1 (fill area) */
    GGDP_PIE = -3,    /* the sector: centre, P1 ... P3 (fill area) */
    GGDP_CIRCLE = -4, /* 3 points on the circle, or centre and one point (fill area) */
    GGDP_ELLIPSE = -5 /* centre, ends of two conjugate semi-diameters (fill area) */
};
GKS_API void ggdp(const Gpoint_list *point_list, Gint gdp_id, const Ggdp_data *gdp_data);
GKS_API void ggdp3(const Gpoint_list3 *point_list, Gint gdp_id, const Ggdp_data *gdp_data);

/* Primitive attributes (the GKS state list). All in states GKOP, WSOP, WSAC, SGOP
 * (error 8). Non-finite reals without an error of their own report 308. */
GKS_API void gset_line_ind(Gint line_ind);                 /* 60: index < 1 */
GKS_API void gset_linetype(Gint linetype);                  /* 63: linetype 0 */
GKS_API void gset_linewidth(Gfloat linewidth);              /* 65: < 0 or NaN */
GKS_API void gset_marker_ind(Gint marker_ind);              /* 66 */
GKS_API void gset_marker_type(Gint marker_type);            /* 69: type 0 */
GKS_API void gset_marker_size(Gfloat marker_size);          /* 71: < 0 or NaN */
GKS_API void gset_marker_colr_ind(Gint colr_ind);           /* 92 */
GKS_API void gset_text_ind(Gint text_ind);                  /* 72 */
GKS_API void gset_text_font_prec(const Gtext_font_prec *font_prec); /* 75: font 0; 2000 */
GKS_API void gset_char_expan(Gfloat char_expan);            /* 77: <= 0 */
GKS_API void gset_char_space(Gfloat char_space);            /* 308 */
GKS_API void gset_text_colr_ind(Gint colr_ind);             /* 92 */
GKS_API void gset_char_ht(Gfloat char_ht);                  /* 78: <= 0 */
GKS_API void gset_char_up_vec(const Gvec *char_up_vec);     /* 79: length zero */
GKS_API void gset_text_path(Gtext_path text_path);          /* 2000 */
GKS_API void gset_text_align(const Gtext_align *text_align); /* 2000 */
GKS_API void gset_fill_ind(Gint fill_ind);                  /* 80 */
GKS_API void gset_fill_int_style(Gfill_int_style style);    /* 2000 */
GKS_API void gset_fill_style_ind(Gint style_ind);           /* 84: index 0 */
GKS_API void gset_pat_size(Gdouble x_size, Gdouble y_size); /* 87: width or height <= 0 */
/* SET PATTERN REFERENCE POINT: also resets the pattern reference vectors to (1,0,0),
 * (0,1,0) and z to 0 (the GKS-3D meaning of the 2-D function). Errors: 8, 308. */
GKS_API void gset_pat_ref_point(const Gpoint *ref_point);
/* SET PATTERN REFERENCE POINT AND VECTORS (GKS-3D): the pattern box lies in the plane
 * of vecs[0] (width direction) and vecs[1] (height direction). Errors: 8, 308, 2000
 * (a vector zero or the two parallel). */
GKS_API void gset_pat_ref_point_vecs(const Gpoint3 *ref_point, const Gvec3 vecs[2]);
GKS_API void gset_asfs(const Gasfs *asfs);                  /* 2000 */
GKS_API void gset_asfs3(const Gasfs3 *asfs);                /* 2000 */
GKS_API void gset_pick_id(Gint pick_id);                    /* 97: < 0 */
/* SET HLHSR IDENTIFIER (GKS-3D primitive attribute; any value, passed to drivers). */
GKS_API void gset_hlhsr_id(Gint hlhsr_id);
/* GKS-3D edge attributes of FILL AREA SET (3). Edge index < 1 is error 500 (PHIGS 100 + 400);
 * the edgetype and edgewidth checks reuse the linetype/linewidth numbers 63, 64, 65. */
GKS_API void gset_edge_flag(Gedge_flag edge_flag);          /* 2000 */
GKS_API void gset_edgetype(Gint edgetype);                  /* 63 */
GKS_API void gset_edgewidth(Gfloat edgewidth);              /* 65 */
GKS_API void gset_edge_colr_ind(Gint colr_ind);             /* 92 */
GKS_API void gset_edge_ind(Gint edge_ind);                  /* 500 */

/* Representations (workstation bundle tables, indices 1..20; patterns 1..20). All:
 * 7, 20, 25, 33, 35, 36, then as listed, colour index 93 last. */
GKS_API void gset_line_rep(Gint ws_id, Gint line_ind, const Gline_bundle *rep);     /* 60, 63, 64, 65, 93 */
GKS_API void gset_marker_rep(Gint ws_id, Gint marker_ind, const Gmarker_bundle *rep); /* 66, 69, 70, 71, 93 */
GKS_API void gset_text_rep(Gint ws_id, Gint text_ind, const Gtext_bundle *rep);     /* 72, 75, 76, 77, 93 */
GKS_API void gset_fill_rep(Gint ws_id, Gint fill_ind, const Gfill_bundle *rep);     /* 80, 83, 84, 85, 86, 93 */
GKS_API void gset_pat_rep(Gint ws_id, Gint pat_ind, const Gpat_rep *rep);           /* 85, 90, 91, 93 */
GKS_API void gset_edge_rep(Gint ws_id, Gint edge_ind, const Gedge_bundle *rep);     /* 500, 63, 64, 65, 93 */

/* Inquiries of the current primitive attributes (error 8). */
GKS_API void ginq_line_ind(Gint *err_ind, Gint *line_ind);
GKS_API void ginq_linetype(Gint *err_ind, Gint *linetype);
GKS_API void ginq_linewidth(Gint *err_ind, Gfloat *linewidth);
GKS_API void ginq_marker_ind(Gint *err_ind, Gint *marker_ind);
GKS_API void ginq_marker_type(Gint *err_ind, Gint *marker_type);
GKS_API void ginq_marker_size(Gint *err_ind, Gfloat *marker_size);
GKS_API void ginq_marker_colr_ind(Gint *err_ind, Gint *colr_ind);
GKS_API void ginq_text_ind(Gint *err_ind, Gint *text_ind);
GKS_API void ginq_text_font_prec(Gint *err_ind, Gtext_font_prec *font_prec);
GKS_API void ginq_char_expan(Gint *err_ind, Gfloat *char_expan);
GKS_API void ginq_char_space(Gint *err_ind, Gfloat *char_space);
GKS_API void ginq_text_colr_ind(Gint *err_ind, Gint *colr_ind);
GKS_API void ginq_char_ht(Gint *err_ind, Gfloat *char_ht);
GKS_API void ginq_char_up_vec(Gint *err_ind, Gvec *char_up_vec);
/* Character width (height x expansion factor 1 of the font: the standard's CHARACTER
 * WIDTH = height) and the base vector (up vector turned clockwise by 90 degrees, unit). */
GKS_API void ginq_char_width(Gint *err_ind, Gfloat *char_width);
GKS_API void ginq_char_base_vec(Gint *err_ind, Gvec *char_base_vec);
GKS_API void ginq_text_path(Gint *err_ind, Gtext_path *text_path);
GKS_API void ginq_text_align(Gint *err_ind, Gtext_align *text_align);
GKS_API void ginq_fill_ind(Gint *err_ind, Gint *fill_ind);
GKS_API void ginq_fill_int_style(Gint *err_ind, Gfill_int_style *fill_int_style);
GKS_API void ginq_fill_style_ind(Gint *err_ind, Gint *fill_style_ind);
GKS_API void ginq_pat_size(Gint *err_ind, Gdouble *x_size, Gdouble *y_size);
GKS_API void ginq_pat_ref_point(Gint *err_ind, Gpoint *ref_point);
GKS_API void ginq_pat_ref_point_vecs(Gint *err_ind, Gpoint3 *ref_point, Gvec3 vecs[2]);
GKS_API void ginq_asfs(Gint *err_ind, Gasfs *asfs);
GKS_API void ginq_asfs3(Gint *err_ind, Gasfs3 *asfs);
GKS_API void ginq_pick_id(Gint *err_ind, Gint *pick_id);
GKS_API void ginq_hlhsr_id(Gint *err_ind, Gint *hlhsr_id);
GKS_API void ginq_edge_flag(Gint *err_ind, Gedge_flag *edge_flag);
GKS_API void ginq_edgetype(Gint *err_ind, Gint *edgetype);
GKS_API void ginq_edgewidth(Gint *err_ind, Gfloat *edgewidth);
GKS_API void ginq_edge_colr_ind(Gint *err_ind, Gint *colr_ind);
GKS_API void ginq_edge_ind(Gint *err_ind, Gint *edge_ind);

/* Workstation state list inquiries: 7, 20, 25, 33/35/36 as the set function, then:
 * index invalid (60/66/72/80/85/500), 2000 (type not GINQ_SET/GINQ_REALIZED),
 * not defined (61/67/73/81/88/501). GINQ_REALIZED returns the values the workstation
 * uses (unsupported types replaced, widths and sizes clamped to the workstation's range,
 * undefined colour indices replaced by 1). */
GKS_API void ginq_line_rep(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, Gline_bundle *rep);
GKS_API void ginq_marker_rep(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, Gmarker_bundle *rep);
GKS_API void ginq_text_rep(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, Gtext_bundle *rep);
GKS_API void ginq_fill_rep(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, Gfill_bundle *rep);
GKS_API void ginq_edge_rep(Gint ws_id, Gint ind, Ginq_type type, Gint *err_ind, Gedge_bundle *rep);
/* Pattern (ISO 8651-4): *pat_rep points into *store (gcreate_store), which holds the
 * representation and its colour array until the store is used again or deleted. */
GKS_API void ginq_pat_rep(Gint ws_id, Gint ind, Ginq_type type, Gstore *store, Gint *err_ind, Gpat_rep **pat_rep);
/* Lists of defined indices, ascending (INQUIRE LIST OF ... INDICES). */
GKS_API void ginq_list_line_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
GKS_API void ginq_list_marker_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
GKS_API void ginq_list_text_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
GKS_API void ginq_list_fill_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
GKS_API void ginq_list_pat_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
GKS_API void ginq_list_edge_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *inds, Gint *length_list);
/* INQUIRE TEXT EXTENT (3): with the workstation's resolved text attributes, in WC.
 * Errors: 7, 20, 25, 39 (not OUTPUT/OUTIN), 101 (invalid character), 308 (position not
 * finite), 2000 (TEXT 3 direction vectors zero or parallel). */
GKS_API void ginq_text_extent(Gint ws_id, const Gpoint *pos, const char *str, Gint *err_ind, Gtext_extent *extent);
GKS_API void ginq_text_extent3(Gint ws_id, const Gpoint3 *pos, const Gvec3 dir[2], const char *str, Gint *err_ind, Gtext_extent3 *extent);

/* Workstation description table inquiries: 8, 22, 23, 39 (not OUTPUT/OUTIN), then for
 * the predefined ones: index invalid (60/66/72/80/85/500), not predefined
 * (62/68/74/82/89/502). */
GKS_API void ginq_line_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gline_facs *facs, Gint *length_list);
GKS_API void ginq_marker_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gmarker_facs *facs, Gint *length_list);
GKS_API void ginq_text_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gtext_facs *facs, Gint *length_list);
/* Fill area facilities (ISO 8651-4): all interior styles; the hatch styles from
 * hatch_start_pos (capacity hatch_length); *act_hatch_length = their number. */
GKS_API void ginq_fill_facs(Gint ws_type, Gint hatch_length, Gint hatch_start_pos, Gint *err_ind, Gfill_facs *facs, Gint *act_hatch_length);
GKS_API void ginq_pat_facs(Gint ws_type, Gint *err_ind, Gint *num_pred_inds);
GKS_API void ginq_edge_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gedge_facs *facs, Gint *length_list);
GKS_API void ginq_pred_line_rep(Gint ws_type, Gint ind, Gint *err_ind, Gline_bundle *rep);
GKS_API void ginq_pred_marker_rep(Gint ws_type, Gint ind, Gint *err_ind, Gmarker_bundle *rep);
GKS_API void ginq_pred_text_rep(Gint ws_type, Gint ind, Gint *err_ind, Gtext_bundle *rep);
GKS_API void ginq_pred_fill_rep(Gint ws_type, Gint ind, Gint *err_ind, Gfill_bundle *rep);
GKS_API void ginq_pred_edge_rep(Gint ws_type, Gint ind, Gint *err_ind, Gedge_bundle *rep);
/* Predefined pattern: as ginq_pat_rep (Gstore). */
GKS_API void ginq_pred_pat_rep(Gint ws_type, Gint ind, Gstore *store, Gint *err_ind, Gpat_rep **pat_rep);
GKS_API void ginq_max_ws_st_tables(Gint ws_type, Gint *err_ind, Gmax_ws_st_tables *lengths);
/* INQUIRE LIST OF AVAILABLE GENERALIZED DRAWING PRIMITIVES: always empty here. */
GKS_API void ginq_list_avail_gdps(Gint ws_type, Gint num_elems_appl_list, Gint start_pos, Gint *err_ind, Gint_list *gdps, Gint *length_list);

/* ---------------------------------------------------------------------------------
 * Utility functions (matrices act on column vectors: x' = m[0][0]x + m[0][1]y + m[0][2])
 * --------------------------------------------------------------------------------- */
typedef Gfloat Gtran_matrix[2][3];   /* 2-D segment/insert transformation */
typedef Gfloat Gtran_matrix3[3][4];  /* GKS-3D segment/insert transformation */
typedef Gfloat Gmatrix3[4][4];       /* view orientation / mapping matrix, m[row][col] */
typedef enum { GPROJ_PARAL, GPROJ_PERSPECT } Gproj_type;
/* View mapping parameters (EVALUATE VIEW MAPPING MATRIX 3), all in VRC3 except proj_vp. */
typedef struct {
    Glimit win;              /* view window on the view plane (u, v) */
    Glimit3 proj_vp;         /* projection viewport, NPC3 */
    Gproj_type proj_type;
    Gpoint3 proj_ref_point;  /* PRP (u, v, n) */
    Gfloat view_plane, back_plane, front_plane; /* distances along n */
} Gview_map3;

/* EVALUATE TRANSFORMATION MATRIX: scale and rotate about the fixed point, then shift.
 * With GCOORD_WC the fixed point and the shift are first mapped to NDC by the current
 * normalization transformation (the shift by its scale part). Errors: 8, 308. */
GKS_API void geval_tran_matrix(const Gpoint *fixed, const Gvec *shift, Gdouble angle,
                               const Gvec *scale, Gcoord_switch sw, Gtran_matrix m);
/* ACCUMULATE TRANSFORMATION MATRIX: result = (new transformation) after m_in. Errors: 8, 308. */
GKS_API void gaccum_tran_matrix(const Gtran_matrix m_in, const Gpoint *fixed, const Gvec *shift,
                                Gdouble angle, const Gvec *scale, Gcoord_switch sw,
                                Gtran_matrix m_out);
/* EVALUATE TRANSFORMATION MATRIX 3: scale, rotate about x, then y, then z (radians) about
 * the fixed point, then shift. Errors: 8, 308. */
GKS_API void geval_tran_matrix3(const Gpoint3 *fixed, const Gvec3 *shift, Gdouble x_ang,
                                Gdouble y_ang, Gdouble z_ang, const Gvec3 *scale,
                                Gcoord_switch sw, Gtran_matrix3 m);
/* ACCUMULATE TRANSFORMATION MATRIX 3. Errors: 8, 308. */
GKS_API void gaccum_tran_matrix3(const Gtran_matrix3 m_in, const Gpoint3 *fixed,
                                 const Gvec3 *shift, Gdouble x_ang, Gdouble y_ang,
                                 Gdouble z_ang, const Gvec3 *scale, Gcoord_switch sw,
                                 Gtran_matrix3 m_out);
/* EVALUATE VIEW ORIENTATION MATRIX 3 (VRP, VPN, VUP as in PHIGS PEVOM3; the Fortran GEVVWM
 * takes VUP before VPN). With GCOORD_WC the VRP is mapped to NDC3 by the current
 * normalization transformation and VPN, VUP by its scale part. Errors: 8, 559, 560, 561, 308. */
GKS_API void geval_view_ori_matrix3(const Gpoint3 *vrp, const Gvec3 *vpn, const Gvec3 *vup,
                                    Gcoord_switch sw, Gint *err_ind, Gmatrix3 m);
/* EVALUATE VIEW MAPPING MATRIX 3. Errors: 8, 2000, 551, 552, 308, 558, 562, 563, 564, 555. */
GKS_API void geval_view_map_matrix3(const Gview_map3 *map, Gint *err_ind, Gmatrix3 m);

/* ---------------------------------------------------------------------------------
 * GKS-3D output and viewing
 * --------------------------------------------------------------------------------- */
/* View representation (SET VIEW REPRESENTATION 3): orientation NDC3 -> VRC3, mapping
 * VRC3 -> NPC3, view clip limits in NPC3 and the xy/back/front clip indicators. */
typedef struct {
    Gmatrix3 ori_matrix;
    Gmatrix3 map_matrix;
    Glimit3 clip_limit;
    Gclip_ind xy_clip, back_clip, front_clip;
} Gview_rep3;

/* HLHSR modes (SET HLHSR MODE, per workstation). */
enum {
    GHLHSR_NONE = 0,        /* areas drawn in order */
    GHLHSR_HIDDEN_LINE = 1, /* areas become outlines, hidden lines removed */
    GHLHSR_ZBUFFER = 2,     /* z-buffer */
    GHLHSR_PAINTER = 3,     /* areas depth sorted (mean DC depth), drawn far to near */
    GHLHSR_RAYTRACE = 4     /* ray tracing of FILL AREAs with lighting (PNG workstations) */
};
#define GKS_MAX_VIEW_IND 20 /* view table entries 0..20; 0 is fixed */

/* POLYLINE 3. Errors: 5, 100. */
GKS_API void gpolyline3(const Gpoint_list3 *point_list);
/* FILL AREA 3. Errors: 5, 100. */
GKS_API void gfill_area3(const Gpoint_list3 *point_list);
/* SET VIEW INDEX (a primitive attribute). Errors: 8, 514. */
GKS_API void gset_view_ind(Gint view_ind);
/* SET VIEW REPRESENTATION 3. Errors: 7, 20, 25, 33, 35, 36, 515, 553, 554, 308. */
GKS_API void gset_view_rep3(Gint ws_id, Gint view_ind, const Gview_rep3 *rep);
/* SET HLHSR MODE. Errors: 7, 20, 25, 33, 35, 36, 511. */
GKS_API void gset_hlhsr_mode(Gint ws_id, Gint mode);
/* SET WINDOW 3 / SET VIEWPORT 3. Errors: 8, 50, 51 (x/y min >= max, z min > max), 52. */
GKS_API void gset_win3(Gint tran_num, const Glimit3 *win);
GKS_API void gset_vp3(Gint tran_num, const Glimit3 *vp);
GKS_API void ginq_view_ind(Gint *err_ind, Gint *view_ind);
GKS_API void ginq_view_rep3(Gint ws_id, Gint view_ind, Gint *err_ind, Gview_rep3 *rep);
GKS_API void ginq_hlhsr_mode(Gint ws_id, Gint *err_ind, Gint *mode);

/* ---------------------------------------------------------------------------------
 * Lighting (PHIGS PLUS semantics added to GKS-3D). Used by HLHSR mode GHLHSR_RAYTRACE.
 * --------------------------------------------------------------------------------- */
/* Area properties (a primitive attribute, front and back). Coefficients in [0,1];
 * transpar_coef: 0 = opaque, 1 = fully transmitting; specular_exp >= 0; refr_index > 0.
 * Defaults: ambient 1, diffuse 1, specular 0, specular colour white, exponent 1,
 * transparency 0, refraction index 1. */
typedef struct {
    Gfloat ambient_coef, diffuse_coef, specular_coef;
    Grgb specular_colr;
    Gfloat specular_exp, transpar_coef, refr_index;
} Garea_props;
/* Reflectance equations (PHIGS PLUS values). Default GREFL_NONE: the area has its flat
 * colour, so an unlit default picture equals the classic one. */
enum { GREFL_NONE = 1, GREFL_AMBIENT = 2, GREFL_AMB_DIFF = 3, GREFL_AMB_DIFF_SPEC = 4 };
/* Light source types (PHIGS PLUS values). */
enum { GLIGHT_AMBIENT = 1, GLIGHT_DIRECTIONAL = 2, GLIGHT_POSITIONAL = 3, GLIGHT_SPOT = 4 };
#define GKS_MAX_LIGHT_IND 64 /* light source table entries 1..64 */
/* Light source representation. pos and dir are in NDC3, like the primitives after
 * normalization: the ray tracer transforms them by the view orientation matrix into VRC3.
 * dir is the direction the light travels. atten: positional/spot attenuation
 * 1/(atten[0] + atten[1]*d). conc_exp: spot concentration exponent; spread_angle: spot half
 * angle in radians, [0, pi]. colr in [0,1]. */
typedef struct {
    Gint type;
    Grgb colr;
    Gpoint3 pos;
    Gvec3 dir;
    Gfloat atten[2];
    Gfloat conc_exp;
    Gfloat spread_angle;
} Glight_src_rep;

/* SET (BACK) AREA PROPERTIES. Errors: 8, 96 (specular colour outside [0,1]), 2000 (NULL,
 * NaN, a coefficient or the transparency outside [0,1], exponent < 0, refraction index <= 0). */
GKS_API void gset_area_props(const Garea_props *props);
GKS_API void gset_back_area_props(const Garea_props *props);
/* SET (BACK) REFLECTANCE EQUATION: GREFL_*. Errors: 8, 524 (not 1..4). */
GKS_API void gset_refl_eq(Gint refl_eq);
GKS_API void gset_back_refl_eq(Gint refl_eq);
/* SET LIGHT SOURCE REPRESENTATION (workstation table, index 1..64; index 1 is predefined
 * as a white ambient light). Errors: 7, 20, 25, 33, 35, 36, 529 (index < 1 or > 64),
 * 531 (type not 1..4), 532 (spot spread angle outside [0,pi]), 96 (colour outside [0,1]),
 * 2000 (NULL, NaN/Inf, negative attenuation or concentration). */
GKS_API void gset_light_src_rep(Gint ws_id, Gint light_ind, const Glight_src_rep *rep);
/* SET LIGHT SOURCE STATE (a primitive attribute: the set of active light indices).
 * Activations are applied, then deactivations. Errors: 8, 533 (an entry < 1; entries > 64
 * are also 533 in this implementation), 535 (an index in both lists). NULL = empty list. */
GKS_API void gset_light_src_state(const Gint_list *activate, const Gint_list *deactivate);
GKS_API void ginq_area_props(Gint *err_ind, Garea_props *front, Garea_props *back);
GKS_API void ginq_refl_eq(Gint *err_ind, Gint *front, Gint *back);
/* Errors in *err_ind: workstation errors, 529, 2002 (index not defined). */
GKS_API void ginq_light_src_rep(Gint ws_id, Gint light_ind, Gint *err_ind, Glight_src_rep *rep);
/* Active light indices in ascending order (list convention of the other list inquiries). */
GKS_API void ginq_light_src_state(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                  Gint_list *active, Gint *length_list);

/* ---------------------------------------------------------------------------------
 * Primitives with data and interior shading methods (PHIGS PLUS, ISO 9592-4, added to
 * GKS-3D; docs/BINDING.md). Each facet may carry a colour and a normal, each vertex a
 * colour and a normal, chosen by the facet and vertex flags (PHIGS PLUS values). Colours
 * are of one colour type per call: GCOLR_INDIRECT (an index into the workstation's colour
 * table, resolved per workstation like every GKS colour index) or GCOLR_RGB (direct, each
 * component in [0,1]). Points and normals are in WC3; normals transform with the inverse
 * transpose of the normalization (and segment) transformation and are renormalised. A
 * facet colour replaces the fill area colour; vertex colours are interpolated under
 * GSHAD_COLR, vertex normals under GSHAD_NORM (SET INTERIOR SHADING METHOD). Arrays the
 * flags do not select are not read (may be NULL).
 * --------------------------------------------------------------------------------- */
enum { GFACET_NONE = 0, GFACET_COLR = 1, GFACET_NORM = 2, GFACET_COLR_NORM = 3 };
enum { GVERT_COORD = 0, GVERT_COORD_COLR = 1, GVERT_COORD_NORM = 2, GVERT_COORD_COLR_NORM = 3 };
enum { GCOLR_INDIRECT = 0, GCOLR_RGB = 1 };
/* Interior shading methods: none (flat), colour interpolation (Gouraud), normal
 * interpolation (Phong). PHIGS PLUS numbers its normal interpolation 4 (3 is DOT
 * PRODUCT, not offered here); this extension numbers the three methods 1..3. */
enum { GSHAD_NONE = 1, GSHAD_COLR = 2, GSHAD_NORM = 3 };

/* A colour value of a data record (PHIGS PLUS Pcoval): ind for GCOLR_INDIRECT, rgb for
 * GCOLR_RGB. */
typedef union { Gint ind; Grgb rgb; } Gcoval;
/* Facet data (PHIGS PLUS Pfacet_data3 as a struct): colr read when the facet flag has
 * colour, norm when it has a normal. */
typedef struct { Gcoval colr; Gvec3 norm; } Gfacet_data3;
/* Vertex data (PHIGS PLUS Pfacet_vdata_list3 as parallel arrays): num_vertices points;
 * colrs and norms (num_vertices each) read when the vertex flag selects them. */
typedef struct {
    Gint num_vertices;
    Gpoint3 *points;
    Gcoval *colrs;
    Gvec3 *norms;
} Gfacet_vdata3;
/* A list of index lists: the loops (fill area set) of one set of SET OF FILL AREA SET 3
 * WITH DATA, each loop a list of 0-based vertex indices. */
typedef struct { Gint num_lists; Gint_list *lists; } Gint_list_list;

/* Errors of the primitives with data (after the state error 5): 100 (fewer than 3
 * vertices in a loop, no loop, quadrilateral mesh dimensions < 2, or a NULL points
 * array), 2000 (facet flag, vertex flag or colour type out of range), 2003 (a NULL
 * record or an array the flags select is NULL), 92 (a colour index < 0), 96 (an RGB
 * component outside [0,1] or not finite), 904 (a vertex index out of range; PHIGS 504).
 * A facet with a non-finite point is not drawn (as FILL AREA 3); a zero or non-finite
 * normal is dropped (the facet is drawn without vertex normals, or facet normal). */
/* FILL AREA 3 WITH DATA: one facet, fdata (may be NULL when fflag = GFACET_NONE). */
GKS_API void gfill_area3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata);
/* FILL AREA SET 3 WITH DATA: one facet of num_sets loops, vdata[k] the k-th loop (PHIGS
 * PLUS's edge data flag and edge data are not taken: edges follow the edge attributes, as
 * for FILL AREA SET 3). */
GKS_API void gfill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type,
                                  const Gfacet_data3 *fdata, Gint num_sets,
                                  const Gfacet_vdata3 *vdata);
/* TRIANGLE STRIP 3 WITH DATA: n = vdata->num_vertices >= 3 vertices, n - 2 triangles
 * (i, i+1, i+2), odd i reversed so that all keep the first one's orientation; fdata has
 * n - 2 records. */
GKS_API void gtri_strip3_data(Gint fflag, Gint vflag, Gint colr_type, const Gfacet_data3 *fdata,
                              const Gfacet_vdata3 *vdata);
/* QUADRILATERAL MESH 3 WITH DATA: dim->size_x * dim->size_y vertices (each >= 2; vertex
 * (i, j) at vdata->points[j * size_x + i], num_vertices must equal the product, else 100),
 * (size_x - 1) * (size_y - 1) quadrilaterals (i,j), (i+1,j), (i+1,j+1), (i,j+1) with their
 * fdata records in the same order. */
GKS_API void gquad_mesh3_data(Gint fflag, Gint vflag, Gint colr_type, const Gint_size *dim,
                              const Gfacet_data3 *fdata, const Gfacet_vdata3 *vdata);
/* SET OF FILL AREA SET 3 WITH DATA: num_sets facets sharing the vertices of vdata; set k
 * is vlist[k], its loops lists of 0-based vertex indices (904 when out of range); fdata
 * has num_sets records. */
GKS_API void gset_of_fill_area_set3_data(Gint fflag, Gint vflag, Gint colr_type, Gint num_sets,
                                         const Gfacet_data3 *fdata, const Gint_list_list *vlist,
                                         const Gfacet_vdata3 *vdata);
/* SET (BACK) INTERIOR SHADING METHOD: GSHAD_*. Errors: 8, 523 (not 1..3; PHIGS 123). */
GKS_API void gset_int_shad_meth(Gint method);
GKS_API void gset_back_int_shad_meth(Gint method);
/* INQUIRE INTERIOR SHADING METHODS: the current front and back methods. Errors: 8. */
GKS_API void ginq_int_shad_meth(Gint *err_ind, Gint *front, Gint *back);

/* ---------------------------------------------------------------------------------
 * Inquiry functions: never call the error handler; *err_ind receives the error number
 * (0 = none). List inquiries fill list->ints (capacity num_elems_appl_list) from the
 * 0-based start_pos and return the implementation's list length.
 * --------------------------------------------------------------------------------- */
GKS_API void ginq_op_st(Gop_st *op_st);
GKS_API void ginq_level_gks(Gint *err_ind, Glevel *level);
GKS_API void ginq_list_avail_ws_types(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                      Gint_list *ws_types, Gint *length_list);
GKS_API void ginq_ws_max_nums(Gint *err_ind, Gws_max_nums *ws_max_num);
GKS_API void ginq_max_norm_tran_num(Gint *err_ind, Gint *max_norm_tran_num);
GKS_API void ginq_set_open_wss(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                               Gint_list *open_ws, Gint *length_list);
GKS_API void ginq_set_active_wss(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                 Gint_list *active_ws, Gint *length_list);
/* INQUIRE WORKSTATION CONNECTION AND TYPE (ISO 8651-4): conn_id receives at most
 * string_length bytes, NUL-terminated (truncated if needed). */
GKS_API void ginq_ws_conn_type(Gint ws_id, Gint string_length, Gint *err_ind, char *conn_id,
                               Gint *ws_type);
GKS_API void ginq_ws_st(Gint ws_id, Gint *err_ind, Gws_st *ws_st);
GKS_API void ginq_ws_defer_upd_sts(Gint ws_id, Gint *err_ind, Gdefer_mode *defer_mode,
                                   Girg_mode *irg_mode, Gdisp_space_empty *disp_empty,
                                   Gnew_frame_nec_upd *new_frame);
GKS_API void ginq_ws_cat(Gint ws_type, Gint *err_ind, Gws_cat *cat);
GKS_API void ginq_ws_class(Gint ws_type, Gint *err_ind, Gws_class *ws_class);
GKS_API void ginq_disp_space_size(Gint ws_type, Gint *err_ind, Gdisp_space_size *disp_size);
GKS_API void ginq_cur_norm_tran_num(Gint *err_ind, Gint *norm_tran_num);
GKS_API void ginq_norm_tran(Gint num, Gint *err_ind, Gtran *norm_tran);
GKS_API void ginq_clip(Gint *err_ind, Gclip *clip);
GKS_API void ginq_line_colr_ind(Gint *err_ind, Gint *colr_ind);
GKS_API void ginq_fill_colr_ind(Gint *err_ind, Gint *colr_ind);
GKS_API void ginq_colr_rep(Gint ws_id, Gint colr_ind, Ginq_type type, Gint *err_ind,
                           Gcolr_rep *colr_rep);
GKS_API void ginq_ws_tran(Gint ws_id, Gint *err_ind, Gupd_st *ws_tran_upd_st,
                          Glimit *req_ws_win, Glimit *cur_ws_win,
                          Glimit *req_ws_vp, Glimit *cur_ws_vp);
/* INQUIRE ERROR STATE (ISO 8651-4 has no such name; this follows its rules): whether
 * GKS is currently inside ERROR HANDLING, and the last error number reported. */
GKS_API void ginq_err_st(Gint *in_error_handling, Gint *last_err_num);

/* ---------------------------------------------------------------------------------
 * Segments (ISO 7942 5.7; SET SEGMENT TRANSFORMATION 3 of ISO 8805). Segment names are
 * positive integers (120 otherwise). A segment is stored on the workstations active when
 * it is created; its primitives are kept in NDC3 with their attributes and clipping
 * volume, and redrawn through the segment transformation on regeneration.
 * --------------------------------------------------------------------------------- */
typedef enum { GSEG_INVIS, GSEG_VIS } Gseg_vis;
typedef enum { GSEG_NORM, GSEG_HIGHL } Gseg_highl;
typedef enum { GSEG_UNDET, GSEG_DET } Gseg_det;
typedef struct {
    Gint seg_name;
    Gtran_matrix3 tran_matrix;  /* NDC3 -> NDC3; a 2-D matrix is stored as x/y rows */
    Gseg_vis vis;
    Gseg_highl highl;
    Gfloat pri;                 /* [0, 1] */
    Gseg_det det;
} Gseg_attrs3;

/* CREATE SEGMENT. Errors: 3, 120, 121, 301. */
GKS_API void gcreate_seg(Gint seg_name);
/* CLOSE SEGMENT. Errors: 4. */
GKS_API void gclose_seg(void);
/* RENAME SEGMENT. Errors: 7, 120, 121, 122. */
GKS_API void grename_seg(Gint old_seg_name, Gint new_seg_name);
/* DELETE SEGMENT. Errors: 7, 120, 122, 125. */
GKS_API void gdel_seg(Gint seg_name);
/* DELETE SEGMENT FROM WORKSTATION. Errors: 7, 20, 25, 33, 35, 120, 123, 125. */
GKS_API void gdel_seg_ws(Gint ws_id, Gint seg_name);
/* SET SEGMENT TRANSFORMATION (2-D matrix: x/y rows, z unchanged). Errors: 7, 120, 122. */
GKS_API void gset_seg_tran(Gint seg_name, const Gtran_matrix tran_matrix);
/* SET SEGMENT TRANSFORMATION 3. Errors: 7, 120, 122. */
GKS_API void gset_seg_tran3(Gint seg_name, const Gtran_matrix3 tran_matrix);
/* SET VISIBILITY. Errors: 7, 120, 122, 2000. */
GKS_API void gset_vis(Gint seg_name, Gseg_vis vis);
/* SET HIGHLIGHTING. Errors: 7, 120, 122, 2000. */
GKS_API void gset_highl(Gint seg_name, Gseg_highl highl);
/* SET SEGMENT PRIORITY. Errors: 7, 120, 122, 126. */
GKS_API void gset_seg_pri(Gint seg_name, Gfloat pri);
/* SET DETECTABILITY. Errors: 7, 120, 122, 2000. */
GKS_API void gset_det(Gint seg_name, Gseg_det det);
/* ASSOCIATE SEGMENT WITH WORKSTATION (the segment must be on the WISS). Errors: 6, 20, 25,
 * 27, 33, 35, 120, 124, 301. */
GKS_API void gassoc_seg_ws(Gint ws_id, Gint seg_name);
/* COPY SEGMENT TO WORKSTATION: the segment's primitives, through its transformation and
 * clipping volumes, drawn on ws (not stored there). Errors: 6, 20, 25, 27, 33, 35, 36, 120,
 * 124. */
GKS_API void gcopy_seg_ws(Gint ws_id, Gint seg_name);
/* INSERT SEGMENT (3): the segment's primitives, mapped by its segment transformation and
 * then tran_matrix, become new output primitives with their bound attributes and the
 * current clipping volume. Errors: 5, 27, 120, 124, 125. */
GKS_API void ginsert_seg(Gint seg_name, const Gtran_matrix tran_matrix);
GKS_API void ginsert_seg3(Gint seg_name, const Gtran_matrix3 tran_matrix);
/* ---- input priorities (ISO 7942 SET VIEWPORT INPUT PRIORITY, ISO 8805 SET VIEW
 * TRANSFORMATION INPUT PRIORITY): the orderings by which LOCATOR/STROKE positions are
 * transformed back (see "Input" below). */
typedef enum { GPRI_HIGHER, GPRI_LOWER } Grel_pri;
/* SET VIEWPORT INPUT PRIORITY: tran_num directly above/below ref_tran_num. Errors: 8, 50,
 * 2000. */
GKS_API void gset_vp_in_pri(Gint tran_num, Gint ref_tran_num, Grel_pri rel_pri);
/* INQUIRE LIST OF NORMALIZATION TRANSFORMATION NUMBERS (in priority order). */
GKS_API void ginq_list_norm_tran_nums(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                      Gint_list *list, Gint *length_list);
/* SET VIEW TRANSFORMATION INPUT PRIORITY. Errors: 7, 20, 25, 33, 35, 36, 515, 2000. */
GKS_API void gset_view_tran_in_pri(Gint ws_id, Gint view_ind, Gint ref_view_ind,
                                   Grel_pri rel_pri);
/* INQUIRE LIST OF VIEW INDICES (in priority order). */
GKS_API void ginq_list_view_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                 Gint *err_ind, Gint_list *list, Gint *length_list);
/* SET WORKSTATION WINDOW 3 (NPC3) / VIEWPORT 3 (DC3, z in [0,1]). Errors: 7, 20, 25, 33,
 * 36, 51, 53 (window) / 54 (viewport). */
GKS_API void gset_ws_win3(Gint ws_id, const Glimit3 *ws_win);
GKS_API void gset_ws_vp3(Gint ws_id, const Glimit3 *ws_vp);
/* INQUIRE WORKSTATION TRANSFORMATION 3. */
GKS_API void ginq_ws_tran3(Gint ws_id, Gint *err_ind, Gupd_st *ws_tran_upd_st,
                           Glimit3 *req_ws_win, Glimit3 *cur_ws_win, Glimit3 *req_ws_vp,
                           Glimit3 *cur_ws_vp);

/* Segment inquiries (list convention of the other list inquiries). */
GKS_API void ginq_set_seg_names(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                Gint_list *seg_names, Gint *length_list);
GKS_API void ginq_name_open_seg(Gint *err_ind, Gint *seg_name);
GKS_API void ginq_seg_attrs3(Gint seg_name, Gint *err_ind, Gseg_attrs3 *attrs);
GKS_API void ginq_set_seg_names_ws(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                   Gint *err_ind, Gint_list *seg_names, Gint *length_list);
GKS_API void ginq_set_assoc_wss(Gint seg_name, Gint num_elems_appl_list, Gint start_pos,
                                Gint *err_ind, Gint_list *ws_ids, Gint *length_list);
/* Number of segment priorities supported: 0 = continuous. */
GKS_API void ginq_num_seg_pris(Gint ws_type, Gint *err_ind, Gint *num_seg_pris);

/* ---------------------------------------------------------------------------------
 * Further inquiries of ISO 7942 / ISO 8805 (src/c/core/api/gks_inq_std.c): current
 * attribute sets, colour facilities, dynamic modification, pixels, GKS-3D description
 * table entries. Types and argument lists as ISO 8651-4 (NCAR's published header);
 * the GKS-3D forms append their entries (docs/BINDING.md).
 * --------------------------------------------------------------------------------- */
/* CREATE STORE: *store receives a new, empty store. Errors (in *err_ind): 300. */
GKS_API void gcreate_store(Gint *err_ind, Gstore *store);
/* DELETE STORE: frees the store and what it holds (NULL is ignored). */
GKS_API void gdel_store(Gstore store);

typedef enum { GATTR_LINE, GATTR_MARKER, GATTR_TEXT, GATTR_FILL, GATTR_EDGE } Gattrs;
typedef enum { GINVAL_ABSENT, GINVAL_PRESENT } Gpres_inval;
typedef enum { GDYN_IRG, GDYN_IMM } Gdyn_mod;
typedef struct { Gint num_colrs; Gcolr_avail colr_avail; Gint num_pred_inds; } Gcolr_facs;
/* Current primitive attributes (INQUIRE CURRENT PRIMITIVE ATTRIBUTE VALUES). */
typedef struct {
    Gint line_ind, marker_ind, text_ind;
    Gdouble char_ht;
    Gvec char_up_vec;
    Gdouble char_width;
    Gvec char_base_vec;
    Gtext_path text_path;
    Gtext_align text_align;
    Gint fill_ind;
    Gvec pat_width_vec, pat_ht_vec;
    Gpoint pat_ref_point;
} Gprim_attrs;
/* GKS-3D: the 2-D set, then the pattern reference point and vectors in 3-D, edge index,
 * view index and HLHSR identifier. */
typedef struct {
    Gprim_attrs attrs;
    Gpoint3 pat_ref_point;
    Gvec3 pat_ref_vecs[2];
    Gint edge_ind, view_ind, hlhsr_id;
} Gprim_attrs3;
/* Current individual attributes (INQUIRE CURRENT INDIVIDUAL ATTRIBUTE VALUES). */
typedef struct {
    Gint linetype;
    Gdouble linewidth;
    Gint line_colr_ind;
    Gint marker_type;
    Gdouble marker_size;
    Gint marker_colr_ind;
    Gtext_font_prec text_font_prec;
    Gdouble char_expan, char_space;
    Gint text_colr_ind;
    Gfill_int_style fill_int_style;
    Gint fill_style_ind, fill_colr_ind;
    Gasfs asfs;
} Gindiv_attrs;
typedef struct {
    Gindiv_attrs attrs;
    Gedge_flag edge_flag;
    Gint edgetype;
    Gdouble edgewidth;
    Gint edge_colr_ind;
    Gasfs3 asfs;
} Gindiv_attrs3;
/* Dynamic modification accepted for workstation attributes / segment attributes. */
typedef struct {
    Gdyn_mod line_bundle, marker_bundle, text_bundle, fill_bundle, pat_rep, colr_rep, ws_tran;
} Gdyn_mod_ws_attrs;
typedef struct {
    Gdyn_mod_ws_attrs attrs;
    Gdyn_mod edge_bundle, view_rep, hlhsr_mode;
} Gdyn_mod_ws_attrs3;
typedef struct {
    Gdyn_mod tran, appear, disappear, highl, pri, add_prim, del;
} Gdyn_mod_seg_attrs;
/* 2-D segment attributes (INQUIRE SEGMENT ATTRIBUTES); the 3-D form is Gseg_attrs3. */
typedef struct {
    Gint seg_name;
    Gtran_matrix tran_matrix;
    Gseg_vis vis;
    Gseg_highl highl;
    Gfloat pri;
    Gseg_det det;
} Gseg_attrs;
typedef struct { Glimit3 win; Glimit3 vp; } Gtran3;
typedef struct { Gclip_ind clip_ind; Glimit3 clip_vol; } Gclip3;
typedef struct { Gfloat size_x, size_y, size_z; } Gfloat_size3;
typedef struct { Gint size_x, size_y, size_z; } Gint_size3;
typedef struct { Gdc_units dc_units; Gfloat_size3 size_dc; Gint_size3 size_raster; } Gdisp_space_size3;
typedef struct {
    Gint line_bundles, marker_bundles, text_bundles, fill_bundles, pat_reps, colr_reps,
         edge_bundles, view_reps;
} Gmax_ws_st_tables3;

/* Current attribute sets: error 8. */
GKS_API void ginq_cur_prim_attrs(Gint *err_ind, Gprim_attrs *attrs);
GKS_API void ginq_cur_prim_attrs3(Gint *err_ind, Gprim_attrs3 *attrs);
GKS_API void ginq_cur_indiv_attrs(Gint *err_ind, Gindiv_attrs *attrs);
GKS_API void ginq_cur_indiv_attrs3(Gint *err_ind, Gindiv_attrs3 *attrs);
/* Pattern width and height vectors: the pattern size along the reference vectors'
 * directions, x/y components (WC). Error 8. */
GKS_API void ginq_pat_width_vec(Gint *err_ind, Gvec *pat_width_vec);
GKS_API void ginq_pat_ht_vec(Gint *err_ind, Gvec *pat_ht_vec);
/* INQUIRE NORMALIZATION TRANSFORMATION 3 (8, 50) and CLIPPING 3 (8). */
GKS_API void ginq_norm_tran3(Gint num, Gint *err_ind, Gtran3 *norm_tran);
GKS_API void ginq_clip3(Gint *err_ind, Gclip3 *clip);
/* 2-D segment attributes: the x/y rows of the segment's 3-D matrix. Errors 7, 120, 122. */
GKS_API void ginq_seg_attrs(Gint seg_name, Gint *err_ind, Gseg_attrs *attrs);
/* INQUIRE LIST OF COLOUR INDICES (defined entries, ascending). Errors 7, 20, 25, 33, 35, 36. */
GKS_API void ginq_list_colr_inds(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                 Gint *err_ind, Gint_list *colr_inds, Gint *length_list);
/* Description table: 8, 22, 23, then 39 (not OUTPUT/OUTIN) for output entries; the
 * predefined colour representation adds 93 (index < 0) and 95 (not predefined). */
GKS_API void ginq_colr_facs(Gint ws_type, Gint *err_ind, Gcolr_facs *colr_facs);
GKS_API void ginq_pred_colr_rep(Gint ws_type, Gint ind, Gint *err_ind, Gcolr_rep *colr_rep);
GKS_API void ginq_dyn_mod_ws_attrs(Gint ws_type, Gint *err_ind, Gdyn_mod_ws_attrs *dyn_mod);
GKS_API void ginq_dyn_mod_ws_attrs3(Gint ws_type, Gint *err_ind, Gdyn_mod_ws_attrs3 *dyn_mod);
GKS_API void ginq_def_defer_sts(Gint ws_type, Gint *err_ind, Gdefer_mode *def_defer_mode,
                                Girg_mode *def_irg_mode);
GKS_API void ginq_dyn_mod_seg_attrs(Gint ws_type, Gint *err_ind, Gdyn_mod_seg_attrs *dyn_mod);
GKS_API void ginq_disp_space_size3(Gint ws_type, Gint *err_ind, Gdisp_space_size3 *disp_size);
GKS_API void ginq_max_ws_st_tables3(Gint ws_type, Gint *err_ind, Gmax_ws_st_tables3 *lengths);
/* GKS-3D view and HLHSR facilities: number of predefined views, a predefined view
 * representation (view index < 0: 514; not predefined: 2002), HLHSR identifiers and
 * modes (list convention; both lists share capacity and start position). */
GKS_API void ginq_view_facs(Gint ws_type, Gint *err_ind, Gint *num_pred_views);
GKS_API void ginq_pred_view_rep(Gint ws_type, Gint view_ind, Gint *err_ind, Gview_rep3 *rep);
GKS_API void ginq_hlhsr_facs(Gint ws_type, Gint num_elems_appl_list, Gint start_pos,
                             Gint *err_ind, Gint_list *hlhsr_ids, Gint *length_ids,
                             Gint_list *hlhsr_modes, Gint *length_modes);
/* GDPs: INQUIRE GENERALIZED DRAWING PRIMITIVE (3): the attribute bundles a GDP uses
 * (41: the type cannot generate the GDP). */
GKS_API void ginq_list_avail_gdps3(Gint ws_type, Gint num_elems_appl_list, Gint start_pos,
                                   Gint *err_ind, Gint_list *gdps, Gint *length_list);
GKS_API void ginq_gdp(Gint ws_type, Gint gdp, Gint *err_ind, Gint *num_attr, Gattrs attr[4]);
GKS_API void ginq_gdp3(Gint ws_type, Gint gdp, Gint *err_ind, Gint *num_attr, Gattrs attr[5]);
/* Pixel inquiries (raster workstations that keep a frame buffer: PNG). Points are WC of
 * the current normalization transformation, mapped through it and the workstation
 * transformation to a pixel of the current frame as drawn so far. A pixel whose colour
 * is no entry of the colour table (anti-aliased edges, lit ray-traced areas), or that
 * lies outside the display surface, is the invalid colour index -1.
 * Errors: 7, 20, 25, 39 (not OUTPUT/OUTIN), 40 (no pixel readback). */
GKS_API void ginq_pixel_array_dims(Gint ws_id, const Grect *rect, Gint *err_ind, Gint_size *dims);
/* Pixel array from pixel_loc (the top-left corner) dims->size_x columns by size_y rows,
 * row-major from the top row, into pixel_array (list convention over the whole array:
 * capacity num_elems_appl_list, 0-based start_pos; *length_list = columns * rows). */
GKS_API void ginq_pixel_array(Gint ws_id, const Gpoint *pixel_loc, const Gint_size *dims,
                              Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                              Gpres_inval *pres_inval, Gint_list *pixel_array,
                              Gint *length_list);
GKS_API void ginq_pixel(Gint ws_id, const Gpoint *pixel_loc, Gint *err_ind, Gint *colr_ind);

/* ---------------------------------------------------------------------------------
 * Input (ISO 7942 5.9, ISO 8805 LOCATOR 3 / STROKE 3; names after ISO 8651-4, see
 * docs/INPUT.md). Input level c: REQUEST, SAMPLE and EVENT mode. The PNG workstations
 * (category OUTIN) have 2 devices of every class, fed by input scripts (ESCAPE
 * GESC_INPUT_SCRIPT or the environment variable GKS_INPUT_SCRIPT; events in device
 * coordinates); an interactive workstation (X11) adds its mouse and keyboard. A REQUEST
 * with no event that can come (script exhausted, no interactive device) returns status
 * GIN_STATUS_NONE at once. Locator and stroke positions go back through the view
 * transformation of highest view transformation input priority whose clip limits hold
 * them, then through the normalization transformation of highest viewport input priority
 * whose viewport holds them. PICK returns the visible, detectable segment of highest
 * priority with a primitive within 0.01 NPC of the position, and that primitive's pick
 * identifier. The input queue holds GKS_IN_QUEUE_CAPACITY events; when it is full
 * further events are lost until it has been emptied, and the next AWAIT EVENT reports
 * 147 once. Output arguments are set to "no input" before any check (status
 * GIN_STATUS_NONE, transformation 0, position (0,0), empty stroke, empty string).
 * Errors are listed per function in the order they are checked.
 * --------------------------------------------------------------------------------- */
#define GKS_IN_QUEUE_CAPACITY 128
typedef enum { GOP_REQ, GOP_SAMPLE, GOP_EVENT } Gop_mode;
typedef enum { GSWITCH_NO_ECHO, GSWITCH_ECHO } Gecho_switch;
/* Values of the Fortran GNONE, GOK, GNPICK/GNCHOI (NCAR's C header lists OK first). */
typedef enum { GIN_STATUS_NONE, GIN_STATUS_OK, GIN_STATUS_NO_IN } Gin_status;
typedef enum {
    GIN_NONE, GIN_LOC, GIN_STROKE, GIN_VAL, GIN_CHOICE, GIN_PICK, GIN_STRING
} Gin_class;
typedef enum { GSIMULT_NO_MORE, GSIMULT_MORE } Gsimult_events;
/* A locator value: normalization transformation and position in its WC. */
typedef struct { Gint norm_tran_num; Gpoint position; } Gloc;
/* A stroke value. As an output, num_points is the capacity of points on entry and the
 * number of points on return. */
typedef struct { Gint norm_tran_num; Gint num_points; Gpoint *points; } Gstroke;
typedef struct { Gint seg_name; Gint pick_id; } Gpick;
/* Prompt/echo-type data record (the Fortran binding passes its packed CHARACTER*80
 * records as str). Never interpreted by this implementation. */
typedef struct {
    Gint num_ints;   const Gint *ints;
    Gint num_floats; const Gfloat *floats;
    size_t str_len;  const char *str;
} Gin_data;
/* Numbers of logical input devices per class (INQUIRE NUMBER OF AVAILABLE ...). */
typedef struct { Gint loc, stroke, val, choice, pick, string; } Gnum_in;
/* Device state common to all classes (INQUIRE ... DEVICE STATE). */
typedef struct {
    Gop_mode op_mode;
    Gecho_switch echo_switch;
    Gint pet;
    Glimit echo_area;
    Gin_data in_data;
} Gin_dev_st;
typedef struct { Gin_dev_st dev; Gloc init_loc; } Gloc_st;
typedef struct { Gin_dev_st dev; Gstroke init_stroke; Gint in_buf_size; } Gstroke_st;
typedef struct { Gin_dev_st dev; Gfloat init_value, low_value, high_value; } Gval_st;
typedef struct { Gin_dev_st dev; Gin_status init_status; Gint init_choice; } Gchoice_st;
typedef struct { Gin_dev_st dev; Gin_status init_status; Gpick init_pick; } Gpick_st;
/* init_string: capacity init_string_size bytes (NUL-terminated on return). */
typedef struct {
    Gin_dev_st dev;
    char *init_string; size_t init_string_size;
    Gint in_buf_size, init_cur_pos;
} Gstring_st;
/* Default device data (INQUIRE DEFAULT ... DEVICE DATA): the prompt/echo types
 * (pets.ints: capacity pets.num_ints on entry, count on return), echo area, record. */
typedef struct { Gint_list pets; Glimit echo_area; Gin_data in_data; } Gdef_in;
typedef struct { Gdef_in dev; Gpoint loc_pos; } Gdef_loc;
typedef struct { Gdef_in dev; Gint max_buf_size, buf_size; } Gdef_stroke;
typedef struct { Gdef_in dev; Gfloat value, low_value, high_value; } Gdef_val;
typedef struct { Gdef_in dev; Gint max_choices; } Gdef_choice;
typedef struct { Gdef_in dev; Gint max_buf_size, buf_size; } Gdef_string;
/* GKS-3D: a locator 3 value (WC3 position), a stroke 3 (as Gstroke), their device states
 * (echo volume in DC3, view index of the initial value) and default data. */
typedef struct { Gint norm_tran_num; Gpoint3 position; } Gloc3;
typedef struct { Gint norm_tran_num; Gint num_points; Gpoint3 *points; } Gstroke3;
typedef struct {
    Gop_mode op_mode; Gecho_switch echo_switch; Gint pet; Glimit3 echo_vol; Gin_data in_data;
    Gint init_view_ind; Gloc3 init_loc;
} Gloc_st3;
typedef struct {
    Gop_mode op_mode; Gecho_switch echo_switch; Gint pet; Glimit3 echo_vol; Gin_data in_data;
    Gint init_view_ind; Gstroke3 init_stroke; Gint in_buf_size;
} Gstroke_st3;
typedef struct { Gint_list pets; Glimit3 echo_vol; Gin_data in_data; Gpoint3 loc_pos; } Gdef_loc3;
/* The other classes' 3-D device states and default data: as the 2-D ones with an echo
 * volume (DC3) instead of the echo area. */
#define GKS_IN_DEV_ST3_ \
    Gop_mode op_mode; Gecho_switch echo_switch; Gint pet; Glimit3 echo_vol; Gin_data in_data
typedef struct { GKS_IN_DEV_ST3_; Gfloat init_value, low_value, high_value; } Gval_st3;
typedef struct { GKS_IN_DEV_ST3_; Gin_status init_status; Gint init_choice; } Gchoice_st3;
typedef struct { GKS_IN_DEV_ST3_; Gin_status init_status; Gpick init_pick; } Gpick_st3;
typedef struct {
    GKS_IN_DEV_ST3_;
    char *init_string; size_t init_string_size;
    Gint in_buf_size, init_cur_pos;
} Gstring_st3;
#undef GKS_IN_DEV_ST3_
typedef struct { Gint_list pets; Glimit3 echo_vol; Gin_data in_data; } Gdef_in3;
typedef struct { Gdef_in3 dev; Gfloat value, low_value, high_value; } Gdef_val3;
typedef struct { Gdef_in3 dev; Gint max_choices; } Gdef_choice3;
typedef struct { Gdef_in3 dev; Gint max_buf_size, buf_size; } Gdef_string3;
typedef struct {
    Gint_list pets; Glimit3 echo_vol; Gin_data in_data; Gint max_buf_size, buf_size;
} Gdef_stroke3;

/* INITIALISE LOCATOR / STROKE / VALUATOR / CHOICE / PICK / STRING (3). The valuator range
 * and the stroke/string buffer sizes are explicit arguments (as NCAR's ginit_string), not
 * members of the data record; the record is stored and returned, not interpreted. Echo
 * areas are in DC (2-D: the echo volume's z is [0,1]). Errors: 7, 20, 25, 38, 140, 144
 * (pet), 51, 145 (echo area), 146 (record; buffer size outside 1..max; valuator low >=
 * high), 2000 (initial status), 152 (initial value: locator/stroke point outside NDC by
 * its transformation, invalid transformation or view index, value outside the range,
 * choice outside 1..max, pick segment < 1, string cursor outside 1..length+1), 153, 154. */
GKS_API void ginit_loc(Gint ws_id, Gint loc_num, const Gloc *init_loc, Gint pet,
                       const Glimit *echo_area, const Gin_data *loc_data);
GKS_API void ginit_stroke(Gint ws_id, Gint stroke_num, const Gstroke *init_stroke, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size,
                          const Gin_data *stroke_data);
GKS_API void ginit_val(Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                       const Glimit *echo_area, Gfloat low_value, Gfloat high_value,
                       const Gin_data *val_data);
GKS_API void ginit_choice(Gint ws_id, Gint choice_num, Gin_status init_status,
                          Gint init_choice, Gint pet, const Glimit *echo_area,
                          const Gin_data *choice_data);
GKS_API void ginit_pick(Gint ws_id, Gint pick_num, Gin_status init_status,
                        const Gpick *init_pick, Gint pet, const Glimit *echo_area,
                        const Gin_data *pick_data);
GKS_API void ginit_string(Gint ws_id, Gint string_num, const char *init_string, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size, Gint init_cur_pos,
                          const Gin_data *string_data);
GKS_API void ginit_loc3(Gint ws_id, Gint loc_num, Gint init_view_ind, const Gloc3 *init_loc,
                        Gint pet, const Glimit3 *echo_vol, const Gin_data *loc_data);
GKS_API void ginit_stroke3(Gint ws_id, Gint stroke_num, Gint init_view_ind,
                           const Gstroke3 *init_stroke, Gint pet, const Glimit3 *echo_vol,
                           Gint in_buf_size, const Gin_data *stroke_data);
GKS_API void ginit_val3(Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                        const Glimit3 *echo_vol, Gfloat low_value, Gfloat high_value,
                        const Gin_data *val_data);
GKS_API void ginit_choice3(Gint ws_id, Gint choice_num, Gin_status init_status,
                           Gint init_choice, Gint pet, const Glimit3 *echo_vol,
                           const Gin_data *choice_data);
GKS_API void ginit_pick3(Gint ws_id, Gint pick_num, Gin_status init_status,
                         const Gpick *init_pick, Gint pet, const Glimit3 *echo_vol,
                         const Gin_data *pick_data);
GKS_API void ginit_string3(Gint ws_id, Gint string_num, const char *init_string, Gint pet,
                           const Glimit3 *echo_vol, Gint in_buf_size, Gint init_cur_pos,
                           const Gin_data *string_data);
/* SET LOCATOR / ... / STRING MODE: SAMPLE and EVENT start from the initial value.
 * Errors: 7, 20, 25, 38, 140, 2000. */
GKS_API void gset_loc_mode(Gint ws_id, Gint loc_num, Gop_mode op_mode, Gecho_switch echo_switch);
GKS_API void gset_stroke_mode(Gint ws_id, Gint stroke_num, Gop_mode op_mode,
                              Gecho_switch echo_switch);
GKS_API void gset_val_mode(Gint ws_id, Gint val_num, Gop_mode op_mode, Gecho_switch echo_switch);
GKS_API void gset_choice_mode(Gint ws_id, Gint choice_num, Gop_mode op_mode,
                              Gecho_switch echo_switch);
GKS_API void gset_pick_mode(Gint ws_id, Gint pick_num, Gop_mode op_mode,
                            Gecho_switch echo_switch);
GKS_API void gset_string_mode(Gint ws_id, Gint string_num, Gop_mode op_mode,
                              Gecho_switch echo_switch);
/* REQUEST LOCATOR / ... / STRING (3): waits for the device's trigger; status OK, NONE
 * (break, or no event can come) or NO_IN (no choice / nothing picked). Stroke: num_points
 * is the capacity of points on entry, the count returned on return. string: a buffer of
 * the device's buffer size + 1 bytes. Errors: 7, 20, 25, 38, 140, 141. */
GKS_API void greq_loc(Gint ws_id, Gint loc_num, Gin_status *in_status, Gloc *loc);
GKS_API void greq_stroke(Gint ws_id, Gint stroke_num, Gin_status *in_status, Gstroke *stroke);
GKS_API void greq_val(Gint ws_id, Gint val_num, Gin_status *in_status, Gfloat *value);
GKS_API void greq_choice(Gint ws_id, Gint choice_num, Gin_status *in_status, Gint *choice);
GKS_API void greq_pick(Gint ws_id, Gint pick_num, Gin_status *in_status, Gpick *pick);
GKS_API void greq_string(Gint ws_id, Gint string_num, Gin_status *in_status, char *string);
GKS_API void greq_loc3(Gint ws_id, Gint loc_num, Gin_status *in_status, Gint *view_ind,
                       Gloc3 *loc);
GKS_API void greq_stroke3(Gint ws_id, Gint stroke_num, Gin_status *in_status, Gint *view_ind,
                          Gstroke3 *stroke);
/* SAMPLE LOCATOR / ... / STRING (3): the current measure, after the operator actions that
 * are pending (one script line for a device in SAMPLE or EVENT mode).
 * Errors: 7, 20, 25, 38, 140, 142. */
GKS_API void gsample_loc(Gint ws_id, Gint loc_num, Gloc *loc);
GKS_API void gsample_stroke(Gint ws_id, Gint stroke_num, Gstroke *stroke);
GKS_API void gsample_val(Gint ws_id, Gint val_num, Gfloat *value);
GKS_API void gsample_choice(Gint ws_id, Gint choice_num, Gin_status *in_status, Gint *choice);
GKS_API void gsample_pick(Gint ws_id, Gint pick_num, Gin_status *in_status, Gpick *pick);
GKS_API void gsample_string(Gint ws_id, Gint string_num, char *string);
GKS_API void gsample_loc3(Gint ws_id, Gint loc_num, Gint *view_ind, Gloc3 *loc);
GKS_API void gsample_stroke3(Gint ws_id, Gint stroke_num, Gint *view_ind, Gstroke3 *stroke);
/* AWAIT EVENT: the oldest queued event becomes the current event report; if the queue is
 * empty, waits up to timeout seconds for one (*in_class GIN_NONE if none came).
 * Errors: 7, 151 (timeout negative, NaN or infinite), 147 (the queue overflowed). */
GKS_API void gawait_event(Gfloat timeout, Gint *ws_id, Gin_class *in_class, Gint *in_num);
/* FLUSH DEVICE EVENTS. Errors: 7, 20, 25, 38, 2000 (class not LOC..STRING), 140. */
GKS_API void gflush_events(Gint ws_id, Gin_class in_class, Gint in_num);
/* GET LOCATOR / ... / STRING (3): the value of the current event report.
 * Errors: 7, 150. */
GKS_API void gget_loc(Gloc *loc);
GKS_API void gget_stroke(Gstroke *stroke);
GKS_API void gget_val(Gfloat *value);
GKS_API void gget_choice(Gin_status *in_status, Gint *choice);
GKS_API void gget_pick(Gin_status *in_status, Gpick *pick);
GKS_API void gget_string(char *string);
GKS_API void gget_loc3(Gint *view_ind, Gloc3 *loc);
GKS_API void gget_stroke3(Gint *view_ind, Gstroke3 *stroke);
/* Input inquiries: *err_ind as the other inquiries, nothing else written on error.
 * Device states: 7, 20, 25, 38, 140, 2000 (type); in_data points into the state list
 * (valid until the device is initialised again). Default data: 8, 22, 23, 38, 140. */
GKS_API void ginq_loc_st3(Gint ws_id, Gint loc_num, Ginq_type type, Gint *err_ind,
                          Gloc_st3 *st);
GKS_API void ginq_stroke_st3(Gint ws_id, Gint stroke_num, Ginq_type type, Gint *err_ind,
                             Gstroke_st3 *st);
GKS_API void ginq_def_loc_data3(Gint ws_type, Gint loc_num, Gint *err_ind, Gdef_loc3 *def);
GKS_API void ginq_def_stroke_data3(Gint ws_type, Gint stroke_num, Gint *err_ind,
                                   Gdef_stroke3 *def);
GKS_API void ginq_val_st3(Gint ws_id, Gint val_num, Gint *err_ind, Gval_st3 *st);
GKS_API void ginq_choice_st3(Gint ws_id, Gint choice_num, Gint *err_ind, Gchoice_st3 *st);
GKS_API void ginq_pick_st3(Gint ws_id, Gint pick_num, Ginq_type type, Gint *err_ind,
                           Gpick_st3 *st);
GKS_API void ginq_string_st3(Gint ws_id, Gint string_num, Gint *err_ind, Gstring_st3 *st);
GKS_API void ginq_def_val_data3(Gint ws_type, Gint val_num, Gint *err_ind, Gdef_val3 *def);
GKS_API void ginq_def_choice_data3(Gint ws_type, Gint choice_num, Gint *err_ind,
                                   Gdef_choice3 *def);
GKS_API void ginq_def_pick_data3(Gint ws_type, Gint pick_num, Gint *err_ind, Gdef_in3 *def);
GKS_API void ginq_def_string_data3(Gint ws_type, Gint string_num, Gint *err_ind,
                                   Gdef_string3 *def);
GKS_API void ginq_loc_st(Gint ws_id, Gint loc_num, Ginq_type type, Gint *err_ind, Gloc_st *st);
GKS_API void ginq_stroke_st(Gint ws_id, Gint stroke_num, Ginq_type type, Gint *err_ind,
                            Gstroke_st *st);
GKS_API void ginq_val_st(Gint ws_id, Gint val_num, Gint *err_ind, Gval_st *st);
GKS_API void ginq_choice_st(Gint ws_id, Gint choice_num, Gint *err_ind, Gchoice_st *st);
GKS_API void ginq_pick_st(Gint ws_id, Gint pick_num, Ginq_type type, Gint *err_ind,
                          Gpick_st *st);
GKS_API void ginq_string_st(Gint ws_id, Gint string_num, Gint *err_ind, Gstring_st *st);
GKS_API void ginq_def_loc_data(Gint ws_type, Gint loc_num, Gint *err_ind, Gdef_loc *def);
GKS_API void ginq_def_stroke_data(Gint ws_type, Gint stroke_num, Gint *err_ind,
                                  Gdef_stroke *def);
GKS_API void ginq_def_val_data(Gint ws_type, Gint val_num, Gint *err_ind, Gdef_val *def);
GKS_API void ginq_def_choice_data(Gint ws_type, Gint choice_num, Gint *err_ind,
                                  Gdef_choice *def);
GKS_API void ginq_def_pick_data(Gint ws_type, Gint pick_num, Gint *err_ind, Gdef_in *def);
GKS_API void ginq_def_string_data(Gint ws_type, Gint string_num, Gint *err_ind,
                                  Gdef_string *def);
/* INQUIRE NUMBER OF AVAILABLE LOGICAL INPUT DEVICES. Errors: 8, 22, 23, 38. */
GKS_API void ginq_num_avail_in(Gint ws_type, Gint *err_ind, Gnum_in *num_in);
/* INQUIRE INPUT QUEUE OVERFLOW: the device whose event was lost first; clears the
 * condition. Errors: 7, 148 (no overflow since GKS was opened or the last inquiry), 149
 * (it overflowed, but that workstation has been closed). */
GKS_API void ginq_in_overf(Gint *err_ind, Gint *ws_id, Gin_class *in_class, Gint *in_num);
/* INQUIRE MORE SIMULTANEOUS EVENTS: GSIMULT_NO_MORE (every trigger belongs to one
 * device). Errors: 7. */
GKS_API void ginq_more_simult_events(Gint *err_ind, Gsimult_events *simult_events);

#ifdef __cplusplus
}
#endif
#endif /* GKS3D_GKS_H */
