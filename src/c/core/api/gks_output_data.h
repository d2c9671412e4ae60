/* SPDX-License-Identifier: MIT */
/*
 * gks_output_data.h -- the canonical form of the PHIGS PLUS primitives with data
 * (gks_output_data.c): vertices shared by facets, each facet a list of loops of vertex
 * indices. FILL AREA 3 WITH DATA is one facet of one loop, FILL AREA SET 3 WITH DATA one
 * facet of several loops, a triangle strip one triangle per facet, a quadrilateral mesh
 * one quadrilateral per facet, SET OF FILL AREA SET 3 WITH DATA as given. The segment
 * store and the metafile keep this form.
 */
#ifndef GKS_OUTPUT_DATA_H
#define GKS_OUTPUT_DATA_H
#include "gks_private.h"
#include "gks_output_int.h"
#include <stddef.h>

typedef struct {
    int fflag, vflag, ctype;   /* GFACET_*, GVERT_*, GCOLR_* */
    size_t n_verts, n_facets, n_loops, n_idx;
    const int *facet_loops;    /* n_facets: loops of each facet (>= 1) */
    const int *loop_counts;    /* n_loops: vertices of each loop (>= 3) */
    const int *idx;            /* n_idx: 0-based vertex index of each loop vertex */
    const double (*pts)[3];    /* n_verts points (WC3, or NDC3 when stored) */
    const double (*vnorm)[3];  /* n_verts normals when vflag has normals */
    const double (*vrgb)[3];   /* n_verts colours when vflag has colours, GCOLR_RGB */
    const int *vci;            /* ... GCOLR_INDIRECT */
    const double (*fnorm)[3];  /* n_facets normals when fflag has normals */
    const double (*frgb)[3];   /* n_facets colours when fflag has colours, GCOLR_RGB */
    const int *fci;            /* ... GCOLR_INDIRECT */
} gks_area_data;

/* Full consistency check (flags, counts, indices, colours, arrays present): 0, 92, 96,
 * 100, 904, 2000 or 2003. */
int gks_area_data_check(const gks_area_data *d);
/* Draws d mapped by nc on the target's workstations; is_set: edges apply. 0 or an error. */
int gks_area_data_emit(const norm_ctx *nc, const gks_area_data *d, int is_set, target *t);
#endif
