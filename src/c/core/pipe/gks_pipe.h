/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe.h -- the output pipeline as core/api and segment replay use it.
 *
 * The entries gks_pipe_<primitive> take a primitive after its entry point's state and
 * argument checks: normalization (gks_pipe_norm.h; the current one, or the recorded xf of
 * INTERPRET ITEM), the metafile record (the active MO workstations), the open segment's
 * record, clipping (gks_pipe_clip.h) and the dispatch to the workstations
 * (gks_pipe_dispatch.h). They return 0, a GKS error number for the caller to report for
 * fctid, or GKS_PIPE_REPORTED: the metafile writer reported an error and the error
 * handler changed the world, so the caller returns at once.
 *
 * The stages gks_pipe_emit_<primitive> are the clipping and dispatch of one primitive
 * already normalized (segment replay sends stored primitives through them).
 */
#ifndef GKS_PIPE_H
#define GKS_PIPE_H
#include "gks_private.h"
#include "gks.h"
#include "gks_area_data.h"
#include "gks_pipe_dispatch.h"
#include "gks_pipe_norm.h"
#include <stddef.h>

#define GKS_PIPE_REPORTED (-1)

struct gks_rec_xf;
/* POLYLINE (3) and POLYMARKER (3): n points of s. */
int gks_pipe_polyline(int fctid, const struct gks_rec_xf *xf, const gks_pipe_src *s, size_t n);
int gks_pipe_polymarker(int fctid, const struct gks_rec_xf *xf, const gks_pipe_src *s, size_t n);
/* TEXT (3) at pos with direction vectors d0, d1 (WC3); str checked by the caller. */
int gks_pipe_text(int fctid, const struct gks_rec_xf *xf, const double pos[3],
                  const double d0[3], const double d1[3], const char *str);
/* FILL AREA (3) (is_set 0) and FILL AREA SET (3) (is_set 1): nloops loops of cnt[k] >= 3
 * points taken from s one after the other. */
int gks_pipe_area(int fctid, const struct gks_rec_xf *xf, size_t nloops, const size_t *cnt,
                  const gks_pipe_src *s, int is_set);
/* CELL ARRAY (3): corners P, Q, R (WC3), nx * ny colour indices. */
int gks_pipe_cell_array(int fctid, const struct gks_rec_xf *xf, const double pqr[3][3],
                        int nx, int ny, const Gint *colr);
/* The arrays a gks_area_data points into when a caller builds one (the entry points from
 * a call's records, the pipeline its NDC3 copy), each NULL when not used; freed together
 * (gks_area_arrays_free). */
typedef struct gks_area_arrays {
    double (*pts)[3], (*vn)[3], (*vrgb)[3], (*fn)[3], (*frgb)[3];
    int *ints, *vci, *fci;
} gks_area_arrays;
void gks_area_arrays_free(gks_area_arrays *a);

/* A primitive with data (metafile item `item`, d checked by gks_area_data_check), in WC3
 * (xf NULL) or as recorded (gks_pipe_data.c). */
int gks_pipe_area_data(int fctid, int item, const gks_area_data *d, const struct gks_rec_xf *xf);

/* The stages after normalization, on NDC3 points before nc's segment transformation; TEXT
 * from its WC3 position and direction vectors. 0 or a GKS error number. */
int gks_pipe_emit_polyline(const gks_pipe_norm *nc, const Gpoint3 *pts, size_t n,
                           gks_pipe_target *t);
int gks_pipe_emit_polymarker(const gks_pipe_norm *nc, const Gpoint3 *pts, size_t n,
                             gks_pipe_target *t);
int gks_pipe_emit_text(const gks_pipe_norm *nc, const double pos[3], const double d0[3],
                       const double d1[3], const char *str, gks_pipe_target *t);
int gks_pipe_emit_area(const gks_pipe_norm *nc, size_t nloops, const size_t *cnt, size_t n,
                       const Gpoint3 *pts, int is_set, gks_pipe_target *t);
int gks_pipe_emit_cell_array(const gks_pipe_norm *nc, const double pqr[3][3], int nx, int ny,
                             const Gint *colr, gks_pipe_target *t);
/* A stored primitive with data (kind GKS_SEG_AREA_DATA) drawn through nc on t. */
int gks_pipe_data_emit_stored(const gks_pipe_norm *nc, const gks_seg_prim *sp,
                              gks_pipe_target *t);
/* INSERT SEGMENT: the stored sp (with data) mapped by M into the open segment, with the
 * clipping volume of cur. 0, 300 or 301. */
int gks_pipe_data_insert(gks_segment *open, const double M[3][4], const gks_pipe_norm *cur,
                         const gks_seg_prim *sp);
#endif
