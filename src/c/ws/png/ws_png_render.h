/* SPDX-License-Identifier: MIT */
/*
 * ws_png_render.h -- the classic renderers of the PNG workstation (internal): the view
 * pipeline of a primitive (NDC3 -> NPC3 -> clip -> DC, per view cached for the frame),
 * every primitive with its attributes, and the HLHSR modes none, hidden line, z-buffer
 * and painter on top of the raster module (src/c/raster).
 *
 * Nominal sizes (DC unit = one output pixel): linewidth 1, edgewidth 1, marker size
 * PNG_NOMINAL_MARKER_SIZE; a scale factor multiplies them (<= 0 or NaN counts as 1).
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
 *                bias = PNG_HL_BIAS + min((|dz/dx|+|dz/dy|)(0.75 + w/2), dz_area,
 *                PNG_HL_BIAS_MAX) in DC depth units (the workstation viewport's depth =
 *                1), dz/dx, dz/dy the area's depth gradient per pixel, w the line width in
 *                pixels, dz_area the depth extent of the (clipped) area, beyond which no
 *                bias is ever needed; other lines and markers get PNG_HL_BIAS.
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
 * Retained primitives (modes 1 and 3, hlhsr_id != 0) are kept for the frame in flat
 * arrays (records, DC points, counts, colours) that grow geometrically and are reused.
 * UPDATE composes them over a copy of the immediately drawn framebuffer, so repeated
 * updates of one frame draw each primitive once (the copy costs one more framebuffer
 * while the frame has retained primitives).
 */
#ifndef WS_PNG_RENDER_H
#define WS_PNG_RENDER_H
#include "raster.h"
#include "ws_driver.h"

#define PNG_NOMINAL_MARKER_SIZE 7.0
#define PNG_HL_BIAS 1e-4
#define PNG_HL_BIAS_MAX 0.25

typedef struct png_render png_render;

/* New renderer state, NULL if out of memory. */
png_render *ws_png_render_new(void);
/* Frees it (NULL allowed). */
void ws_png_render_free(png_render *r);
/* New frame: forgets retained primitives and the cached view pipelines. */
void ws_png_render_reset(png_render *r);
/* Number of primitives retained for drawing at UPDATE. */
size_t ws_png_render_retained(const png_render *r);
/* Draws a primitive into fb, or retains it (see above). Returns 0 or 300 (storage).
 * Primitives with non-finite coordinates or degenerate transformations draw nothing. */
int ws_png_render_prim(png_render *r, const gks_ws *ws, gks_raster_fb *fb, const gks_prim *prim);
/* The picture of the frame: fb itself when nothing is retained, else a framebuffer owned
 * by r holding fb with the retained primitives drawn over it by the HLHSR mode.
 * Returns 0 or 300 (*out = NULL). */
int ws_png_render_compose(png_render *r, const gks_ws *ws, gks_raster_fb *fb,
                          gks_raster_fb **out);
#endif
