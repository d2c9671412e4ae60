/* SPDX-License-Identifier: MIT */
/*
 * gks_pipe_norm.h -- the normalization stage of the output pipeline: the context a
 * primitive is drawn with (WC3 -> NDC3 by the current normalization transformation, then
 * the open segment's transformation, the clipping volume), made from the GKS state list,
 * from a recorded normalization (INTERPRET ITEM) or from a stored segment's mapping
 * (replay); and the point sources the primitives come in.
 */
#ifndef GKS_PIPE_NORM_H
#define GKS_PIPE_NORM_H
#include "gks_private.h"
#include "gks.h"
#include "gks_seg_store.h"
#include "gks_xform.h"
#include <math.h>
#include <stddef.h>

typedef struct gks_pipe_norm {
    double m[3][4];            /* source -> NDC3 after the segment transformation */
    double n[3][4];            /* WC3 -> NDC3 (normalization only; what segments store) */
    double pn[3][4];           /* source -> NDC3 before the segment transformation: n, or
                                  the identity for INTERPRET ITEM's NDC3 points */
    double pat[3][4];          /* WC3 -> final NDC3 for pattern boxes */
    gks_xform_clip clip;       /* in NDC3 (w = 1) */
    int clip_on;
    double box[6];             /* the clipping volume: the viewport 3 when created */
    gks_segment *seg;          /* the open segment (current state only), else NULL */
    /* facts of m and the clipping volume that areas use (gks_pipe_norm_facts, made again
       wherever m, box or clip_on change): m maps each coordinate by its own row alone (a
       scale and a shift per axis, no rotation or shear); clipping is on with a finite box */
    int axis_aligned, box_finite;
} gks_pipe_norm;

/* The recorded normalization a primitive performed by INTERPRET ITEM enters the pipeline
 * with (the argument of the gks_output_rec_* entries, gks_output_rec.h; the
 * interpreter, core/api/gks_metafile.c, keeps it per MI): points are NDC3
 * (ndc_pts = 1; TEXT: WC3 and ndc_pts = 0), norm is the recorded WC3 -> NDC3 matrix for
 * text geometry and pattern boxes, box/clip_on the recorded clipping volume. */
typedef struct gks_rec_xf {
    double norm[3][4];
    double box[6];
    int clip_on;
    int ndc_pts;
} gks_rec_xf;

/* Sets nc's axis_aligned and box_finite from its m, box and clip_on. */
void gks_pipe_norm_facts(gks_pipe_norm *nc);

/* xf NULL below: the current normalization. */
/* The context of the current state, or of the recorded normalization xf: 0, or 308 if
 * the normalization cannot be represented (gks_xform_norm_tran3). */
int gks_pipe_norm_setup(gks_pipe_norm *nc, const struct gks_rec_xf *xf);
/* The same without a copy: *ncp is the context the pipeline keeps for the current state
 * (valid until the next primitive's setup) or buf, made there. 0 or 308. */
int gks_pipe_norm_get(const gks_pipe_norm **ncp, gks_pipe_norm *buf,
                      const struct gks_rec_xf *xf);
/* A context mapping by m and clipping at box (when clip_on): 0, or -1 (degenerate box). */
int gks_pipe_norm_from(gks_pipe_norm *nc, const double m[3][4], const double box[6],
                       int clip_on);

/* A point list: 2-D (z = 0), 3-D, or double triples (exactly one is set). */
typedef struct gks_pipe_src {
    const Gpoint *p2;
    const Gpoint3 *p3;
    const double (*d3)[3];
} gks_pipe_src;

static inline void gks_pipe_src_get(const gks_pipe_src *s, size_t i, double o[3])
{
    if (s->p2) {
        o[0] = s->p2[i].x; o[1] = s->p2[i].y; o[2] = 0.0;
    } else if (s->p3) {
        o[0] = s->p3[i].x; o[1] = s->p3[i].y; o[2] = s->p3[i].z;
    } else {
        o[0] = s->d3[i][0]; o[1] = s->d3[i][1]; o[2] = s->d3[i][2];
    }
}

/* A source point -> homogeneous NDC3 (h[3] = 1); 1 if finite. */
static inline int gks_pipe_to_ndc(const gks_pipe_norm *nc, const double wc[3], double h[4])
{
    gks_xform_mat34_point(nc->m, wc, h);
    h[3] = 1.0;
    return isfinite(h[0]) && isfinite(h[1]) && isfinite(h[2]);
}

/* Whether the NDC3 point h lies in the clipping volume (closed box; always when off). */
static inline int gks_pipe_visible(const gks_pipe_norm *nc, const double h[3])
{
    if (!nc->clip_on)
        return 1;
    for (int k = 0; k < 3; k++)
        if (!(h[k] >= nc->box[2 * k] && h[k] <= nc->box[2 * k + 1]))
            return 0;
    return 1;
}
#endif
