/* SPDX-License-Identifier: MIT */
/*
 * ws_render.h -- the render layer's one entry for a drawing workstation (internal): the
 * classic renderer (ws_classic.h) and the ray-tracing recording (ws_raytrace.h) of one
 * workstation, and the routing between them by the workstation's HLHSR mode, written here
 * once. The drivers are output sinks: PNG writes the pixels to a file, X11 shows them in a
 * window, the cairo types put vectors (and the raster part as an image) into a document.
 */
#ifndef WS_RENDER_H
#define WS_RENDER_H
#include "ws_classic.h"
#include "ws_raytrace.h"

/* Where a primitive is drawn. */
typedef enum {
    WS_ROUTE_CLASSIC, /* the classic renderer of the HLHSR mode (ws_classic) */
    WS_ROUTE_TRACE    /* recorded for the tracer, traced at the update (ws_raytrace) */
} ws_route;

/* The route of prim on ws: an area (FILL AREA, FILL AREA SET, CELL ARRAY) in HLHSR mode
 * GHLHSR_RAYTRACE goes to the tracer, everything else to the classic renderer. */
ws_route ws_render_route(const gks_ws *ws, const gks_prim *prim);

/* One workstation's renderers; the drivers use the two parts directly for what is theirs
 * (composing, pixel readback, the ray-tracing ESCAPEs, the traced tiles shown at once). */
typedef struct ws_render {
    ws_dlist *dl;           /* the frame's one display list (ws_dlist.h), which both read:
                               the classic renderer's retained records, the tracer's areas */
    ws_classic *classic;    /* retained and immediate primitives of the classic modes */
    ws_rt *rt;              /* areas recorded in HLHSR mode GHLHSR_RAYTRACE */
} ws_render;

/* Both renderers on one display list, empty; NULL if out of memory. */
ws_render *ws_render_new(void);
/* Frees both and the list (NULL allowed). */
void ws_render_free(ws_render *r);
/* A new frame: forgets the recorded and the retained primitives of both (each reader's
 * state, then the display list: the frame boundary). A driver that traced the frame into its
 * framebuffer calls ws_rt_reset alone, which keeps the list's classic records. */
void ws_render_reset(ws_render *r);
/* Draws prim by its route (ws_render_route): recorded for the tracer, or drawn into fb by
 * the classic renderer. Returns 0 or the error of the renderer (300 storage, 308 coordinate
 * range of the tracer). */
int ws_render_prim(ws_render *r, gks_ws *ws, gks_raster_fb *fb, const gks_prim *prim);
/* A mesh kept whole (the driver entry mesh): recorded for the tracer in HLHSR mode
 * GHLHSR_RAYTRACE (ws_rt_record_mesh); GKS_WS_MESH_FACETS in the classic modes (they draw
 * the facets one by one, as without the entry). */
int ws_render_mesh(ws_render *r, gks_ws *ws, const gks_mesh *m);
#endif
