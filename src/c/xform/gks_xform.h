/* SPDX-License-Identifier: MIT */
/*
 * gks_xform.h -- pure transformation and clipping math of the GKS-3D pipeline (internal).
 *
 * No GKS state, no I/O, no allocation: functions on doubles that return an error number
 * (0 = OK) where the standard defines errors. On error, the functions that produce a
 * matrix or a clip region leave it unchanged; the polyline/polygon clippers may have
 * written part of their output buffers (their counts are then 0 or the space needed).
 *
 * Conventions (BINDINGS.md §3.1):
 *  - 4x4 matrices are double m[4][4], m[row][col], acting on homogeneous COLUMN vectors
 *    (x,y,z,w) and pre-multiplying: p' = M p. A point is (x/w, y/w, z/w).
 *  - 2-D GKS matrices are 2x3:  x' = m[0][0]x + m[0][1]y + m[0][2],  y' = m[1][0]x + ...
 *  - GKS-3D segment / insert matrices are 3x4: x' = m[0][0]x + m[0][1]y + m[0][2]z + m[0][3].
 *  - Composition "A then B" is B·A; the product functions document their order.
 *  - NPC "front" is the larger z. VRC is right-handed (U, V, N); N points towards the viewer.
 *  - Boxes (3-D windows, viewports, clip limits) are double[6] = xmin,xmax,ymin,ymax,zmin,zmax;
 *    rectangles are double[4] = xmin,xmax,ymin,ymax (the Fortran array order).
 *
 * Non-finite input: every function checks its inputs. A NaN or infinity in an argument that
 * has a validity error of its own (window, viewport, VPN, VUP, clip box) reports that error
 * (in its place in the documented order); a NaN/Inf in any other argument (VRP, PRP, view
 * plane / back / front distances, fixed point, shift, angles, scale factors, matrices, points)
 * reports GKS_E_ARITHMETIC (308), checked after the validity errors that precede it. A
 * computed result that is not finite (overflow, e.g. a window 1e-320 wide) also reports 308.
 * No function that returns an error number ever outputs a NaN or an infinity. The void
 * utilities (multiply, apply, point, direction, conversions, compose, pull-back) do plain
 * arithmetic: they expect finite input and propagate whatever they are given.
 */
#ifndef GKS_XFORM_H
#define GKS_XFORM_H
#include "gks_private.h"
#include <stddef.h>

/* ---- Error numbers -------------------------------------------------------------------
 * GKS (ISO 7942) numbers where they apply. GKS-3D's own numbers are not available: for
 * conditions borrowed from PHIGS this project uses the rule
 *        our number = PHIGS number + 400
 * (e.g. 561 = PHIGS 161 "view up and view plane normal are parallel"). */
#define GKS_E_RECT_INVALID            51   /* rectangle / box definition invalid */
#define GKS_E_VIEWPORT_NOT_IN_NDC     52   /* viewport not within NDC unit square / cube */
#define GKS_E_WS_WINDOW_NOT_IN_NDC    53   /* ws window not within NDC (NPC) unit square/cube */
#define GKS_E_WS_VIEWPORT_NOT_IN_DS   54   /* ws viewport not within display space */
#define GKS_E_NPOINTS_INVALID         100  /* number of points invalid */
#define GKS_E_STORAGE_OVERFLOW        300  /* caller-supplied output space too small */
#define GKS_E_ARITHMETIC              308  /* non-finite input or result, singular matrix */
#define GKS_E_ENUM_RANGE              2000 /* enumeration out of range (projection type) */
#define GKS_E_VIEW_WINDOW_INVALID     551  /* PHIGS 151: UMIN>=UMAX or VMIN>=VMAX */
#define GKS_E_PROJ_VIEWPORT_INVALID   552  /* PHIGS 152: XMIN>=XMAX, YMIN>=YMAX or ZMIN>ZMAX */
#define GKS_E_CLIP_LIMITS_INVALID     553  /* PHIGS 153 */
#define GKS_E_CLIP_LIMITS_NOT_IN_NPC  554  /* PHIGS 154 */
#define GKS_E_PROJ_VIEWPORT_NOT_IN_NPC 555 /* PHIGS 155 */
#define GKS_E_FRONT_BACK_EQUAL        558  /* PHIGS 158: F == B while ZMIN != ZMAX */
#define GKS_E_VPN_ZERO                559  /* PHIGS 159: view plane normal length zero */
#define GKS_E_VUP_ZERO                560  /* PHIGS 160: view up vector length zero */
#define GKS_E_VIEW_UP_PARALLEL        561  /* PHIGS 161: VUP parallel to VPN */
#define GKS_E_PRP_BETWEEN_PLANES      562  /* PHIGS 162: PRP between front and back planes */
#define GKS_E_PRP_ON_VIEW_PLANE       563  /* PHIGS 163: PRP on the view plane */
#define GKS_E_BACK_IN_FRONT           564  /* PHIGS 164: back plane in front of front plane */

/* Projection types (GKS-3D / PHIGS PARALLEL = 0, PERSPECTIVE = 1). */
enum { GKS_XFORM_PARALLEL = 0, GKS_XFORM_PERSPECTIVE = 1 };

/* ---- 4x4 utilities (xform_matrix.c) -------------------------------------------------- */

/* m = I. */
void gks_xform_identity(double m[4][4]);

/* r = a·b (apply b first, then a). r may alias a or b. */
void gks_xform_multiply(const double a[4][4], const double b[4][4], double r[4][4]);

/* inv = m⁻¹ by Gauss-Jordan with partial pivoting on the row- and column-equilibrated
 * matrix (scaling by powers of two, exact). Returns 0, or 308 if m has a non-finite entry,
 * is (numerically) singular (pivot < 64·DBL_EPSILON after equilibration) or the inverse
 * overflows. inv may alias m. */
int gks_xform_invert(const double m[4][4], double inv[4][4]);

/* out = m·in for a homogeneous 4-vector. out may alias in. */
void gks_xform_apply(const double m[4][4], const double in[4], double out[4]);

/* Transform the point p = (x,y,z,1); out = xyz / w if w != 0 (the undivided xyz if w == 0).
 * Returns w, so the caller can reject w <= 0 (behind the eye) before using out. */
double gks_xform_point(const double m[4][4], const double p[3], double out[3]);


/* Normals through the upper-left 3x3 block A of m: nm = sign(det A) cof(A) / max|cof(A)|, the
 * inverse transpose up to a positive factor (normals are renormalised after it). -1 when A
 * is singular or not finite, else 0. */
int gks_xform_normal_matrix(const double m[4][4], double nm[3][3]);
/* nm v normalised into out (which may be v); 0 (out zero) if that is not a finite non-zero
 * vector, else 1. */
int gks_xform_normal(const double nm[3][3], const double v[3], double out[3]);

/* ---- Conversions and composition (xform_matrix.c) ------------------------------------ */

/* 3x4 segment/insert matrix → 4x4 (last row 0 0 0 1). */
void gks_xform_mat34_to_mat4(const double m[3][4], double r[4][4]);

/* 2-D 2x3 segment matrix → 3x4 (z passes unchanged: rows [a b 0 c], [d e 0 f], [0 0 1 0]). */
void gks_xform_mat23_to_mat34(const double m[2][3], double r[3][4]);

/* out = m·(p,1) for a 3x4 affine matrix. out may alias p. */
void gks_xform_mat34_point(const double m[3][4], const double p[3], double out[3]);




/* r = a∘b for affine 3x4 matrices (apply b first, then a). r may alias a or b. */
void gks_xform_mat34_multiply(const double a[3][4], const double b[3][4], double r[3][4]);

/* r = a∘b for affine 2x3 matrices (apply b first, then a). r may alias a or b. */
void gks_xform_mat23_multiply(const double a[2][3], const double b[2][3], double r[2][3]);


/* Plane pull-back: for a plane p (inside where p·X >= 0, X homogeneous in space B) and a
 * matrix m: A → B, out is the same plane in space A (out_j = Σ_i p_i m[i][j]). */
void gks_xform_plane_pullback(const double p[4], const double m[4][4], double out[4]);

/* ---- Windows, viewports, normalization and workstation transformations --------------- */

/* 2-D window (SET WINDOW): 51 unless xmin < xmax and ymin < ymax (all finite). */
int gks_xform_check_window(const double win[4]);

/* 2-D viewport (SET VIEWPORT): 51 as above, then 52 unless within [0,1]². */
int gks_xform_check_viewport(const double vp[4]);

/* 3-D window (SET WINDOW 3): 51 unless xmin < xmax, ymin < ymax, zmin <= zmax (finite).
 * A zero z-extent is allowed (PHIGS rule): every z then maps to the viewport's zmin. */
int gks_xform_check_window3(const double win[6]);

/* 3-D viewport (SET VIEWPORT 3): 51 as for the window (zmin == zmax allowed), then 52
 * unless within the NDC unit cube [0,1]³. */
int gks_xform_check_viewport3(const double vp[6]);

/* View clipping limits (SET VIEW REPRESENTATION 3, NPC): 553 (PHIGS 153) unless
 * xmin < xmax, ymin < ymax, zmin <= zmax (finite), then 554 (PHIGS 154) unless within the
 * NPC unit cube. */
int gks_xform_check_view_clip_limits(const double lim[6]);

/* Normalization transformation 3: window 3 (WC) → viewport 3 (NDC) as a 3x4 matrix,
 * x' = vxmin + (x − wxmin)(vxmax − vxmin)/(wxmax − wxmin), likewise y, z (z' = vzmin if the
 * window's z-extent is zero). Errors: 51 (window), 51 (viewport), 52 (viewport), 308. */
int gks_xform_norm_tran3(const double win[6], const double vp[6], double m[3][4]);

/* Workstation window 3 (SET WORKSTATION WINDOW 3, in NPC): 51 (x/y min >= max or
 * zmin > zmax), then 53 unless within the unit cube. */
int gks_xform_check_ws_window3(const double win[6]);

/* Workstation viewport 3 (SET WORKSTATION VIEWPORT 3, in DC): 51 as above, then 54 unless
 * within the display space [0,dsmax[0]]×[0,dsmax[1]]×[0,dsmax[2]]. */
int gks_xform_check_ws_viewport3(const double vp[6], const double dsmax[3]);

/* Workstation transformation 3 (NPC → DC) as a 4x4 affine matrix. In x and y the window is
 * mapped with one scale s = min(Vx/Wx, Vy/Wy) onto the largest part of the viewport with the
 * window's aspect ratio, placed at the viewport's lower-left corner (as GKS's workstation transformation);
 * z is mapped linearly wzmin → vzmin, wzmax → vzmax (all z → vzmin if wzmin == wzmax).
 * Errors: 51 (window), 51 (viewport), 308. Containment (53/54) is the checks' job. */
int gks_xform_ws_tran3(const double win[6], const double vp[6], double m[4][4]);

/* ---- Viewing (xform_view.c) ----------------------------------------------------------- */

/* EVALUATE VIEW ORIENTATION MATRIX 3 (BINDINGS §3.2): n = N/|N|, u = (U×N)/|U×N|,
 * v = n×u; rows u, v, n with translation −u·R, −v·R, −n·R. vrp, vpn, vup are in the
 * space the orientation acts on (NDC3 in GKS-3D; a WC-given VRP is mapped by the caller).
 * Errors in order: 559 (|VPN| = 0 or VPN not finite), 560 (|VUP| = 0 or not finite),
 * 561 (VUP ∥ VPN: |û×n̂| <= 16·DBL_EPSILON), 308 (VRP not finite). */
int gks_xform_eval_view_orientation3(const double vrp[3], const double vpn[3],
                                     const double vup[3], double m[4][4]);


/* View mapping parameters (the PHIGS/GKS-3D view mapping, all in VRC). */
typedef struct {
    double window[4];   /* view window umin, umax, vmin, vmax (in the plane n = vpd) */
    double viewport[6]; /* projection viewport xmin,xmax,ymin,ymax,zmin,zmax (NPC) */
    int proj_type;      /* GKS_XFORM_PARALLEL or GKS_XFORM_PERSPECTIVE */
    double prp[3];      /* projection reference point (u, v, n) */
    double vpd;         /* view plane distance (n of the view plane) */
    double bpd;         /* back plane distance */
    double fpd;         /* front plane distance (must be >= bpd) */
} gks_xform_view_map3;

/* EVALUATE VIEW MAPPING MATRIX 3 (BINDINGS §3.3). Parallel (oblique allowed): projectors
 * parallel to PRP → window centre. Perspective: projectors through the PRP; the last row is
 * [0, 0, −s, s·pn] with s = 1/(pn − B), so w = 1 on the back plane and w > 0 for every
 * point on the back plane's side of the PRP (the viewing side), w < 0 behind the eye. Window faces map to viewport x/y faces, B → zmin, F → zmax (z hyperbolic in n
 * for perspective; z = zmin everywhere if F == B and zmin == zmax).
 * Errors, in OpenPHIGS's order: 2000 (projection type not 0/1), 551 (window), 552 (viewport
 * x/y min >= max or zmin > zmax), 308 (PRP, VPD, BPD or FPD not finite), 558 (F == B while
 * zmin != zmax), 562 (perspective and B <= pn <= F: strictly between as in PHIGS, plus our
 * guards pn == B (s infinite) and pn == F (front plane through the eye)), 563 (pn == VPD,
 * both types), 564 (F < B), 555 (viewport not within [0,1]³), 308 (result not finite).
 * Equalities are exact (OpenPHIGS uses |x| < 1e-30). */
int gks_xform_eval_view_mapping3(const gks_xform_view_map3 *map, double m[4][4]);


/* Camera recovery (BINDINGS §3.3) for a mapping matrix M (VRC → NPC) or a product M·Mo
 * (space → NPC): P with M·P = (0,0,c,0), i.e. P ∝ M⁻¹(0,0,1,0) when M is invertible, found
 * as the null vector of M's x, y and w rows, so a flat projection viewport (zmin == zmax,
 * M singular) works too. If P_w != 0 the projection is perspective (*perspective = 1) and
 * eye = P_xyz / P_w is the PRP; else parallel (*perspective = 0) and eye is the unit
 * direction of projection, oriented from the scene towards the viewer (towards NPC +z; for
 * a flat viewport, where z carries no direction, the orientation is arbitrary). |P_w| is
 * judged relative to |P_xyz| (<= 1e-12 → parallel). Errors: 308 (non-finite M, or x, y, w
 * rows dependent). */
int gks_xform_view_camera(const double m[4][4], double eye[3], int *perspective);

/* ---- Modelling / segment transformations (xform_tran.c) ------------------------------- */

/* EVALUATE TRANSFORMATION MATRIX 3: result = T(shift) · T(fixed) · Rz · Ry · Rx · S · T(−fixed)
 * i.e. scale about the fixed point, then rotate about it (about x first, then y, then z;
 * angles in radians, positive = counter-clockwise looking down the axis towards the
 * origin), then shift. The coordinate switch (WC/NDC) is the caller's: fixed point and shift
 * are passed already in NDC. Errors: 308 (non-finite argument or result). */
int gks_xform_eval_tran3(const double fixed[3], const double shift[3], const double angles[3],
                         const double scale[3], double m[3][4]);

/* EVALUATE TRANSFORMATION MATRIX (2-D): scale about the fixed point, rotate by angle
 * (radians, counter-clockwise) about it, then shift. Errors: 308. */
int gks_xform_eval_tran(const double fixed[2], const double shift[2], double angle,
                        const double scale[2], double m[2][3]);

/* ACCUMULATE TRANSFORMATION MATRIX 3: out = new ∘ in, i.e. the input transformation is
 * applied first, then the one gks_xform_eval_tran3 builds from the other arguments.
 * out may alias in. Errors: 308 (non-finite input matrix, argument or result). */
int gks_xform_accum_tran3(const double in[3][4], const double fixed[3], const double shift[3],
                          const double angles[3], const double scale[3], double out[3][4]);

/* ACCUMULATE TRANSFORMATION MATRIX (2-D): out = new ∘ in. Errors: 308. */
int gks_xform_accum_tran(const double in[2][3], const double fixed[2], const double shift[2],
                         double angle, const double scale[2], double out[2][3]);

/* ---- Clipping in homogeneous coordinates (xform_clip.c) -------------------------------- */

#define GKS_XFORM_MAX_PLANES 12

/* A convex clip region: the points X = (x,y,z,w) with p[i]·X >= 0 for every i < n and
 * w >= wmin. wmin > 0 keeps points off (and behind) the eye plane of a perspective
 * projection so that the division by w is safe; 0 disables that test. */
typedef struct {
    int n;                                   /* planes in use, 0..GKS_XFORM_MAX_PLANES */
    double p[GKS_XFORM_MAX_PLANES][4];       /* a, b, c, d: a·x + b·y + c·z + d·w >= 0 */
    double wmin;
    /* per plane, set by the add functions: i + 1 if only coefficient i of x, y, z (and d)
     * is non-zero (a face of a box: evaluated and snapped on that axis alone), else 0 */
    unsigned char axis[GKS_XFORM_MAX_PLANES];
} gks_xform_clip;

/* Default wmin set by gks_xform_clip_init: w is 1 on the back plane for matrices from
 * gks_xform_eval_view_mapping3, so this removes only points within ~1e-9 of the PRP's plane
 * (relative to the PRP–back plane distance); parallel projections have w = 1. */
#define GKS_XFORM_WMIN_DEFAULT 1e-9

/* Clip-box flags: which faces of a box are clipping planes (the view clip indicators). */
enum {
    GKS_XFORM_CLIP_XY = 1,     /* x and y faces (4 planes) */
    GKS_XFORM_CLIP_BACK = 2,   /* z >= zmin (back: smaller z) */
    GKS_XFORM_CLIP_FRONT = 4,  /* z <= zmax (front: larger z) */
    GKS_XFORM_CLIP_ALL = 7
};

/* Empty region (no planes), wmin = GKS_XFORM_WMIN_DEFAULT. */
void gks_xform_clip_init(gks_xform_clip *c);

/* Append one plane. Errors: 308 (non-finite or all-zero coefficients), 300 (region full). */
int gks_xform_clip_add_plane(gks_xform_clip *c, const double p[4]);

/* Append the faces of an axis-aligned box (xmin,xmax,ymin,ymax,zmin,zmax, in the space
 * after the division) selected by flags: x − xmin·w >= 0, xmax·w − x >= 0, etc. Used for
 * the view clip limits (flags from the clip indicators) and the workstation window (ALL);
 * appending both gives their intersection. Errors: 51 (x/y min >= max or zmin > zmax,
 * or not finite), 300 (region full); on error c is unchanged. */
int gks_xform_clip_add_box(gks_xform_clip *c, const double box[6], unsigned flags);

/* Clip the segment a→b in place, plane by plane (the region's constraints in order): each
 * crossing is computed from the segment the previous planes have shortened, interpolated
 * from its end nearer to the plane, and put exactly on the plane when that is a face of a
 * box (gks_xform_clip_add_box) or the w test; so a segment from x = -1e30 to 1e30 keeps
 * its visible part. Returns 1 if a part survives (a segment touching the region in one
 * point keeps that point), 0 if not or if a crossing overflows; *moved_a / *moved_b say
 * which end was moved. For a region built by the functions above and finite a, b (what
 * gks_xform_clip_polyline checks once for all its segments). */
int gks_xform_clip_segment(const gks_xform_clip *c, double a[4], double b[4], int *moved_a,
                           int *moved_b);

/* Clip a polyline of n homogeneous points (gks_xform_clip_segment per segment). The
 * visible pieces are written one after the other to out (points, 4 doubles each), piece k
 * having piece_len[k] >= 2 points; consecutive segments that join inside the region continue the
 * same piece. Space needed: at most 2(n − 1) points and n − 1 pieces; *n_out and *n_pieces
 * are always set to the numbers needed, so out = NULL / piece_len = NULL with zero
 * capacities (NULL counts as capacity 0) is a counting call. Errors: 100 (n < 2),
 * 308 (non-finite input; a segment whose crossing overflows is dropped),
 * 300 (out_cap or piece_cap too small; nothing beyond the capacities is written). */
int gks_xform_clip_polyline(const gks_xform_clip *c, size_t n, const double (*pts)[4],
                            double (*out)[4], size_t out_cap,
                            size_t *piece_len, size_t piece_cap,
                            size_t *n_out, size_t *n_pieces);

/* Clip a polygon of nloops loops (loop k has loop_len[k] points, stored one loop after the
 * other in pts) with re-entrant Sutherland–Hodgman, each loop separately, against every
 * plane. Output: loop k's clipped loop has out_len[k] points (0 if it vanishes, a caller
 * should drop loops with < 3 points), stored one after the other in out. Winding numbers
 * inside the region are preserved loop by loop, so the even-odd interior of the result is
 * the even-odd interior of the input intersected with the region. The clipped loops can
 * contain degenerate edges running along the region's boundary (a loop leaving and
 * re-entering the region is closed by chords on the boundary planes, which may overlap as
 * back-and-forth edges of zero area): fill is unaffected, but edge drawing should skip
 * edges lying in a clip plane if the boundary must not be drawn.
 * *n_out is set to the total needed (on success and on 300; 0 on other errors);
 * out = NULL (or out_cap = 0) is a counting call.
 * out_len has nloops entries (required). Errors: 100 (a loop with < 3 points or nloops = 0),
 * 308 (non-finite input or result), 300 (out_cap too small). */
int gks_xform_clip_polygon(const gks_xform_clip *c, size_t nloops, const size_t *loop_len,
                           const double (*pts)[4], double (*out)[4], size_t out_cap,
                           size_t *out_len, size_t *n_out);

/* The same with na <= GKS_XFORM_CLIP_MAX_ATTR attributes per vertex (attr: na doubles per
 * point, e.g. a normal and a colour), interpolated at new vertices with the point's
 * parameter; out_attr receives na doubles per output point (required when out is given
 * and na > 0). The caller renormalises or clamps what needs it. Errors as
 * gks_xform_clip_polygon, and 100 for na too large or attr missing. */
#define GKS_XFORM_CLIP_MAX_ATTR 8
int gks_xform_clip_polygon_attr(const gks_xform_clip *c, size_t nloops, const size_t *loop_len,
                                const double (*pts)[4], const double *attr, size_t na,
                                double (*out)[4], double *out_attr, size_t out_cap,
                                size_t *out_len, size_t *n_out);

/* Divide a homogeneous point: out = xyz/w. Errors: 308 if w <= 0 or the result is not
 * finite (after clipping with wmin > 0 this cannot happen). */
int gks_xform_divide(const double in[4], double out[3]);

#endif
