/* SPDX-License-Identifier: MIT */
/*
 * gks_output_int.h -- the output pipeline's stages shared by gks_output.c (the ISO
 * primitives) and gks_output_data.c (the PHIGS PLUS primitives with data): the
 * normalization/clipping context of a primitive, its target workstations and the send to
 * a driver (with the test hook). Internal to core/api.
 */
#ifndef GKS_OUTPUT_INT_H
#define GKS_OUTPUT_INT_H
#include "gks_private.h"
#include "gks_seg_store.h"
#include "gks_xform.h"
#include "gks_context.h"

typedef struct {
    double m[3][4];            /* source -> NDC3 after the segment transformation */
    double n[3][4];            /* WC3 -> NDC3 (normalization only; what segments store) */
    double pn[3][4];           /* source -> NDC3 before the segment transformation: n, or
                                  the identity for INTERPRET ITEM's NDC3 points */
    double pat[3][4];          /* WC3 -> final NDC3 for pattern boxes */
    gks_xform_clip clip;       /* in NDC3 (w = 1) */
    int clip_on;
    double box[6];             /* the clipping volume: the viewport 3 when created */
    gks_segment *seg;          /* the open segment (current state only), else NULL */
} norm_ctx;

/* Where a primitive goes: the active workstations with the current attributes, or one
 * workstation with a segment's stored binding (regeneration). */
typedef struct {
    const gks_cur_attrs *a;
    double pat_m[3][4];        /* WC3 -> final NDC3, for pattern boxes */
    gks_ws *only;              /* regeneration target; NULL: the active workstations */
    int k, done;
} target;

/* The current state's context (0 or 308), or one mapping by m clipped at box (0, -1). */
struct gks_rec_xf; /* gks_mf_record.h: NULL = the current normalization */
int gks_out_norm_setup(norm_ctx *nc, const struct gks_rec_xf *xf);
int gks_out_norm_from(norm_ctx *nc, const double m[3][4], const double box[6], int clip_on);
/* The active workstations with the current attributes (none if the open segment is
 * invisible). */
void gks_out_target_current(target *t, const norm_ctx *nc);
gks_ws *gks_out_next_ws(target *t);
/* The attributes every primitive carries (view index, lighting, shading methods). */
void gks_out_prim_common(gks_prim *p, const gks_cur_attrs *a);
/* Hands p to ws's driver (after the test hook). 0 or the driver's error. */
int gks_out_send(gks_ws *ws, const gks_prim *p);
#endif
