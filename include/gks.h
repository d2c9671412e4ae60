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

#ifdef __cplusplus
extern "C" {
#endif

#if defined(GKS3D_BUILDING)
#define GKS_API __attribute__((visibility("default")))
#else
#define GKS_API
#endif

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

/* ESCAPE data records: an integer array, a real array and a string. */
typedef struct {
    Gint num_ints;   const Gint *ints;
    Gint num_floats; const Gfloat *floats;
    size_t str_len;  const char *str;
} Gescape_in_data;
typedef struct {
    Gint num_ints;   Gint *ints;      /* capacity in, count out */
    Gint num_floats; Gfloat *floats;  /* capacity in, count out */
} Gescape_out_data;

/* ERROR HANDLING procedure type: (error number, function identification, error file). */
typedef void (*Gerr_handler)(Gint err_num, Gint func_num, const char *err_file);

/* ---------------------------------------------------------------------------------
 * Workstation types of this implementation (INQUIRE LIST OF AVAILABLE WORKSTATION TYPES)
 * --------------------------------------------------------------------------------- */
enum {
    GWS_TYPE_NULL = 99,       /* category OUTPUT: accepts everything, draws nothing */
    GWS_TYPE_PNG = 100,       /* category OUTPUT, raster, 1024x1024 pixel display space */
    GWS_TYPE_PNG_LARGE = 101  /* category OUTPUT, raster, 8192x8192 pixel display space */
};

/* Function identifications passed to ERROR HANDLING: the standard's numbers (0..108, the
 * RAL GKSE_PAR list); GKS-3D and this library's additions are numbered from 109 on.
 * The full list is in docs/BINDING.md. */
enum {
#define GKS_FN(id, sym, name, states) GFN_##sym = id,
#include "gks_functions.def"
#undef GKS_FN
    GFN_COUNT_DUMMY_
};

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
/* ESCAPE. func_id: one of the GESC_* identifiers below. Errors: 8, 180, 181, 182. */
GKS_API void gescape(Gint func_id, const Gescape_in_data *in, Gescape_out_data *out);
/* EMERGENCY CLOSE GKS: callable in any state, never reports an error. */
GKS_API void gemergency_close_gks(void);

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
    GESC_RT_SPD = -109           /* ints[1] 0/1: SPD procedure (rays at pixel corners) */
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
    GHLHSR_HIDDEN_LINE = 1, /* areas become outlines, hidden lines removed (not yet: 511) */
    GHLHSR_ZBUFFER = 2,     /* z-buffer */
    GHLHSR_PAINTER = 3,     /* depth sorted (not yet: 511) */
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
/* INQUIRE WORKSTATION CONNECTION AND TYPE: conn_id receives at most conn_size bytes
 * (NUL-terminated, truncated if needed); *conn_len the full length. */
GKS_API void ginq_ws_conn_type(Gint ws_id, size_t conn_size, Gint *err_ind, char *conn_id,
                               size_t *conn_len, Gint *ws_type);
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

#ifdef __cplusplus
}
#endif
#endif /* GKS3D_GKS_H */
