/* SPDX-License-Identifier: MIT */
/*
 * ws_classic.h -- the classic renderers of the render layer (internal; the PNG, X11
 * and cairo workstations draw with them): the view pipeline of a primitive (NDC3 -> NPC3
 * -> clip -> DC, per view cached for the frame),
 * every primitive with its attributes, and the HLHSR modes none, hidden line, z-buffer
 * and painter on top of the raster module (src/c/raster).
 *
 * Nominal sizes (DC unit = one output pixel): linewidth 1, edgewidth 1, marker size
 * WS_CLASSIC_NOMINAL_MARKER_SIZE; a scale factor multiplies them (<= 0 or NaN counts as 1).
 * Marker type 1 (dot) is always the smallest dot (one pixel). Text strokes (attrs.text)
 * are drawn solid, 1 pixel wide, in the text colour.
 *
 * HLHSR modes (ws->hlhsr_mode):
 *  0 none        primitives drawn at once, in order, no depth test.
 *  1 hidden line areas become outlines in their colour (with the edge attributes where
 *                the edge flag is on) and hidden lines are removed: at UPDATE the
 *                frame's areas are written to the depth buffer only, then all edges,
 *                lines, markers, text and cell arrays are drawn depth-tested. An area's
 *                own edges pass the test with a slope-scaled bias (as glPolygonOffset):
 *                bias = WS_CLASSIC_HL_BIAS + min((|dz/dx|+|dz/dy|)(0.75 + w/2), dz_area,
 *                WS_CLASSIC_HL_BIAS_MAX) in DC depth units (the workstation viewport's depth =
 *                1), dz/dx, dz/dy the area's depth gradient per pixel, w the line width in
 *                pixels, dz_area the depth extent of the (clipped) area, beyond which no
 *                bias is ever needed; other lines and markers get WS_CLASSIC_HL_BIAS.
 *  2 z-buffer    primitives drawn at once with a depth test (nearer or equal wins);
 *                edges of areas with the slope-scaled bias above so they show on their
 *                own area.
 *  3 painter     the frame's primitives are retained and drawn at UPDATE sorted by depth,
 *                farthest first, without depth test. Sort key: the mean DC depth of the
 *                primitive's vertices after clipping (DC depth is affine in NPC z), ties in
 *                the order of arrival. Lines, markers and text are sorted with the areas.
 *  4 ray tracing fill areas go to ws_raytrace (not here); other primitives as mode 0.
 * HLHSR identifier (attrs.hlhsr_id): 0 = the primitive takes part in the workstation's
 * HLHSR mode; any other value = it is retained and drawn at UPDATE after everything
 * else, without depth test (on top), in order of arrival. (OpenPHIGS reads 0 as OFF:
 * this implementation keeps 0, the GKS default, as "takes part".)
 *
 * Retained primitives (modes 1 and 3, hlhsr_id != 0) are kept for the frame in the render
 * layer's display list (ws_dlist.h; the one list of the frame, which the tracer's areas go
 * through as well: these are its WS_DL_CLASSIC records): a record each, its DC points after clipping as the
 * vertices, its counts as the loops, its attributes (with pattern, cell and smooth-shading
 * floats) shared by equal consecutive records. UPDATE composes them over a copy of the
 * immediately drawn framebuffer, so repeated updates of one frame draw each primitive once
 * (the copy costs one more framebuffer while the frame has retained primitives).
 */
#ifndef WS_CLASSIC_H
#define WS_CLASSIC_H
#include "gks_xform.h"
#include "raster.h"
#include "ws_driver.h"
#include "ws_dlist.h"

#define WS_CLASSIC_NOMINAL_MARKER_SIZE 7.0
#define WS_CLASSIC_HL_BIAS 1e-4
#define WS_CLASSIC_HL_BIAS_MAX 0.25

typedef struct ws_classic ws_classic;

/* New renderer state, NULL if out of memory. Its retained primitives go to the display
 * list dl (the render layer's, shared with the tracer; it must outlive the renderer), or to a
 * list of its own (dl NULL: a renderer of its own, such as the cairo types' vector one). */
ws_classic *ws_classic_new(ws_dlist *dl);
/* Frees it (NULL allowed). */
void ws_classic_free(ws_classic *r);
/* New frame: forgets the cached view pipelines and the retained primitives -- those of a
 * list of its own; a shared list forgets them at its owner's ws_dlist_reset (ws_render_reset
 * does both). */
void ws_classic_reset(ws_classic *r);
/* Number of primitives retained for drawing at UPDATE. */
size_t ws_classic_retained(const ws_classic *r);
/* Draws a primitive into fb, or retains it (see above). Returns 0 or 300 (storage).
 * Primitives with non-finite coordinates or degenerate transformations draw nothing. */
int ws_classic_prim(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb, const gks_prim *prim);
/* The picture of the frame: fb itself when nothing is retained, else a framebuffer owned
 * by r holding fb with the retained primitives drawn over it by the HLHSR mode.
 * Returns 0 or 300 (*out = NULL). */
int ws_classic_compose(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb,
                          gks_raster_fb **out);
/* The same without the overlays (hlhsr_id != 0): a back end that draws them itself. */
int ws_classic_compose_base(ws_classic *r, const gks_ws *ws, gks_raster_fb *fb,
                               gks_raster_fb **out);

/* Output scale (default 1, 1: the PNG workstation): px_per_dc output pixels per DC unit
 * (the workstation viewport's size in pixels is its DC size times this) and px_per_unit
 * pixels per nominal unit (line and edge width 1, marker size 1; hatch spacing stays in
 * pixels). Invalid values are ignored. */
void ws_classic_set_scale(ws_classic *r, double px_per_dc, double px_per_unit);
/* As ws_classic_prim, but the primitive is retained whatever the HLHSR mode (for a back
 * end that draws the frame at UPDATE through ws_classic_walk). */
int ws_classic_keep(ws_classic *r, const gks_ws *ws, const gks_prim *prim);

/* A primitive the back end draws itself (a vector driver's TEXT), kept in the frame's
 * order: ws_classic_walk emits it as a WS_ITEM_MARK item with mark = id in its place
 * (painter: sorted by key, a mean DC depth; overlay: with the overlays; hidden line: with
 * the lines, not depth-tested, so a back end should keep only what needs no test).
 * Returns 0 or 300. */
int ws_classic_keep_mark(ws_classic *r, size_t id, double key, int overlay);
/* The view pipeline of view index vi on ws (cached for the frame): npc maps NDC3 to
 * homogeneous NPC3, clip is the region there (view clip limits by the indicators and the
 * workstation window; valid until the next call with other inputs), dc maps NPC3 to output
 * pixels (x right, y up) and DC depth. 0, or -1 if the pipeline is degenerate. */
int ws_classic_view(ws_classic *r, const gks_ws *ws, int vi, double npc[4][4],
                       double dc[4][4], const gks_xform_clip **clip);
/* Is homogeneous NPC point h inside clip region c (w >= wmin and every plane)? */
int ws_classic_clip_inside(const gks_xform_clip *c, const double h[4]);

/* An item of the frame for vector back ends: points in output pixels (DC x right, y up,
 * z depth), widths and sizes in pixels, unit = pixels per nominal unit.
 *  AREA    n_loops loops (counts[k] points) filled by the even-odd rule with style
 *          (GKS_RASTER_SOLID, _HATCH with hatch -1..-12, _PATTERN with nx x ny colours
 *          rgb_list and pat_geo = reference point, cell width vector, cell height vector);
 *  LINE    n_loops pieces, a negative count continues the previous piece (its first point
 *          is the previous piece's last); linetype 1..4, width;
 *  MARKERS n_loops chunks of centres; marker_type 1..5, marker_size (diameter), width;
 *  CELLS   cell array: parallelogram cell_o, cell_u (end of the first row), cell_v (end of
 *          the first column), nx x ny colours rgb_list row-major from cell_o, drawn inside
 *          the n_loops loops (the parallelogram clipped);
 *  MARK    a record of the back end's own (ws_classic_keep_mark), id in mark. */
typedef enum {
    WS_ITEM_AREA, WS_ITEM_LINE, WS_ITEM_MARKERS, WS_ITEM_CELLS, WS_ITEM_MARK
} ws_item_kind;
typedef struct ws_render_item {
    ws_item_kind kind;
    float rgb[3];
    int n_loops;
    const int *counts;
    const gks_raster_pt *pts;
    double unit;
    int style, hatch;
    int linetype;
    double width;
    int marker_type;
    double marker_size;
    int nx, ny;
    const float *rgb_list;
    double pat_geo[6];
    gks_raster_pt cell_o, cell_u, cell_v;
    size_t mark;
} ws_render_item;
typedef int (*ws_render_emit)(void *ctx, const ws_render_item *it);
/* The retained primitives of the frame as items to emit, in the order of HLHSR mode mode:
 * painter sorted as drawn; hidden line: the areas' depths rasterised into a width x height
 * depth buffer owned by r, then only the lines, outlines and markers in front of it
 * (visible runs split at sample spacing <= 1/2 pixel, the same bias as the raster);
 * others in order of arrival; overlays (hlhsr_id != 0) last. Returns 0, 300 or the first
 * non-zero result of emit. */
int ws_classic_walk(ws_classic *r, int mode, int width, int height, ws_render_emit emit,
                       void *ctx);
#endif
