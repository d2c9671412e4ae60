/*
 * ws_raytrace.h -- HLHSR mode GHLHSR_RAYTRACE for raster workstations: FILL AREA
 * primitives are recorded in VRC3 and traced with gksrt when the frame is written.
 */
#ifndef WS_RAYTRACE_H
#define WS_RAYTRACE_H
#include "raster.h"
#include "ws_driver.h"

typedef struct ws_rt ws_rt;

/* New empty recording, NULL if out of memory. */
ws_rt *ws_rt_new(void);
/* Frees a recording (NULL allowed). */
void ws_rt_free(ws_rt *r);
/* Forgets all recorded primitives (new frame); keeps the options. */
void ws_rt_reset(ws_rt *r);
/* Number of recorded primitives. */
int ws_rt_count(const ws_rt *r);
/* Shadow/reflection/refraction rays limited to the display volume (1) or not (0). */
void ws_rt_set_clip_secondary(ws_rt *r, int on);
/* The ray-tracing ESCAPEs (GESC_RT_*, gks.h) of a workstation: 0, 180 (unknown id) or 182
 * (bad data record). */
int ws_rt_escape(ws_rt *r, int func_id, const Gescape_in_data *in, Gescape_out_data *out);
/* Records a FILL AREA (others are ignored): points transformed by the view orientation
 * matrix of prim->view_ind into VRC3. Returns 0 or 300 (storage). */
int ws_rt_record(ws_rt *r, const gks_ws *ws, const gks_prim *prim);
/* Traces the primitives of the view of the first recorded primitive into fb: only pixels
 * whose primary ray hits a primitive are written. wsm: NPC3 -> image pixels (x right,
 * y up, pixel (i,j) centre at (i+.5, j+.5)). Returns 0 or 300 (storage). */
int ws_rt_render(ws_rt *r, const gks_ws *ws, const double wsm[4][4], gks_raster_fb *fb);
#endif
