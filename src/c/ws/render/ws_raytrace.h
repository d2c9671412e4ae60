/* SPDX-License-Identifier: MIT */
/*
 * ws_raytrace.h -- HLHSR mode GHLHSR_RAYTRACE for raster workstations: FILL AREA, FILL AREA
 * SET and CELL ARRAY primitives are recorded in VRC3 and traced with gksrt when the frame is
 * written. The ray-tracing ESCAPEs (GESC_RT_*, gks.h) set the render options. Behaviour and
 * limits: docs/RAYTRACING.md.
 */
#ifndef WS_RAYTRACE_H
#define WS_RAYTRACE_H
#include "raster.h"
#include "ws_driver.h"
#include "gksrt.h"
#include "ws_dlist.h"

typedef struct ws_rt ws_rt;

/* New empty recording with default options, NULL if out of memory. Its areas go through
 * the display list dl (the render layer's, shared with the classic renderer; it must outlive
 * the recording), or a list of its own (dl NULL). */
ws_rt *ws_rt_new(ws_dlist *dl);
/* Frees a recording (NULL allowed). */
void ws_rt_free(ws_rt *r);
/* Forgets all recorded primitives (new frame); keeps the options and the last statistics.
 * A shared display list keeps its records (ws_dlist_reset at the frame boundary, by its
 * owner): the classic renderer's retained primitives stay. */
void ws_rt_reset(ws_rt *r);
/* Number of recorded tracer primitives (a clipped CELL ARRAY may record several). */
int ws_rt_count(const ws_rt *r);
/* The tiles of the next frames are shared by the ranks of an MPI run (on) or traced here
 * alone (off, the default); ws_mpi.h. Without the MPI module: no effect. */
void ws_rt_set_share_tiles(ws_rt *r, int on);
/* Called after each traced tile with its pixels, so that a window can show the picture as
 * it forms (not with tiles shared by MPI ranks): framebuffer pixels [i0, i0 + w) x
 * [j0, j0 + h) (j bottom-up as in the framebuffer), rgb w x h colours clamped to [0, 1],
 * rows bottom-up. A preview: the traced colours before coverage; the frame written into
 * the framebuffer afterwards is the picture. NULL fn: none (the default). */
typedef void (*ws_rt_tile_fn)(void *user, int i0, int j0, int w, int h, const float *rgb);
void ws_rt_set_tile_fn(ws_rt *r, ws_rt_tile_fn fn, void *user);
/* The render options the next picture uses (ESCAPE settings; the environment variable
 * GKS3D_RT_PROGRESS=1 is applied at render time, not here). */
void ws_rt_options(const ws_rt *r, rt_render_options *o);
/* The ray-tracing ESCAPEs GESC_RT_CLIP_SECONDARY .. GESC_RT_SPD of a workstation (records
 * as documented in gks.h, ints[0] = ws id already checked by the core). Returns 0, 180
 * (identifier not a ray-tracing escape) or 182 (bad data record: nothing changed). */
int ws_rt_escape(ws_rt *r, int func_id, const Gescape_in_data *in, Gescape_out_data *out);
/* The ESCAPEs a file workstation with ray tracing takes after its own: the ray-tracing ones
 * (ws_rt_escape on r) and GESC_SET_FILE_NAME (gks_ws_file_rename of *base, the file of frame
 * `frame` with extension ext); 180 for any other identifier. */
int ws_rt_file_escape(ws_rt *r, gks_ws *ws, int func_id, const Gescape_in_data *in,
                      Gescape_out_data *out, int frame, const char *ext, char **base);
/* Records an area primitive (FILL AREA / FILL AREA SET: GKS_PRIM_FILL_AREA with n_loops >=
 * 1; CELL ARRAY: GKS_PRIM_CELL_ARRAY; other kinds are ignored): points transformed by the
 * view orientation matrix of prim->view_ind into VRC3. A CELL ARRAY with clip = 1 that is not
 * inside its clip box is recorded exactly clipped: per row, the run of cells inside as a
 * one-row cell array and the cells crossing the box boundary as clipped polygons.
 * Returns 0 or 300 (storage; the recording is unchanged). */
int ws_rt_record(ws_rt *r, const gks_ws *ws, const gks_prim *prim);
/* Records a mesh kept whole (the driver entry mesh, gks_mesh): its triangles and
 * quadrilaterals (split into two triangles) as one indexed tracer mesh (rt_scene_add_mesh:
 * shared vertices stored once), its other facets as ws_rt_record records a FILL AREA (SET).
 * Returns 0, 300, 308, or GKS_WS_MESH_FACETS (not recorded: a single facet, a colour per
 * facet, or a vertex beyond the tracer's coordinate range; the core then sends the facets). */
int ws_rt_record_mesh(ws_rt *r, const gks_ws *ws, const gks_mesh *m);
/* Traces the recorded primitives into fb, one view after the other in ascending view index
 * order, each view's primitives with that view's camera into the pixels of its display volume
 * (view clip volume where on, intersected with the workstation window). A pixel is composed
 * over fb by the fraction of its sample rays that hit a primitive (0: fb unchanged). wsm:
 * NPC3 -> image pixels (x right, y up, pixel (i,j) centre at (i+.5, j+.5)). Returns 0 or
 * 300 (storage). Shared tiles (MPI): on ranks other than 0 fb is left as it is; 305 when a
 * rank was lost -- on rank 0 the frame is complete all the same (the lost rank's tiles are
 * traced here), elsewhere nothing was composed. */
int ws_rt_render(ws_rt *r, const gks_ws *ws, const double wsm[4][4], gks_raster_fb *fb);
#endif
