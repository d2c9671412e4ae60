/* SPDX-License-Identifier: MIT */
/*
 * gks_area_data.h -- the canonical form of the PHIGS PLUS primitives with data: vertices
 * shared by facets, each facet a list of loops of vertex indices, with optional vertex
 * and facet colours and normals. FILL AREA 3 WITH DATA is one facet of one loop, FILL
 * AREA SET 3 WITH DATA one facet of several loops, a triangle strip one triangle per
 * facet, a quadrilateral mesh one quadrilateral per facet, SET OF FILL AREA SET 3 WITH
 * DATA as given. The pipeline (core/api/gks_output_data.c) draws this form; the segment
 * store and the metafile keep it packed (gks_area_data_pack): integers and real triples.
 */
#ifndef GKS_AREA_DATA_H
#define GKS_AREA_DATA_H
#include "gks_private.h"
#include "gks.h"
#include <stddef.h>

typedef struct {
    int fflag, vflag, ctype;   /* GFACET_*, GVERT_*, GCOLR_* */
    size_t n_verts, n_facets, n_loops, n_idx;
    const int *facet_loops;    /* n_facets: loops of each facet (>= 1) */
    const int *loop_counts;    /* n_loops: vertices of each loop (>= 3) */
    const int *idx;            /* n_idx: 0-based vertex index of each loop vertex */
    const double (*pts)[3];    /* n_verts points (WC3, or NDC3 when stored/recorded) */
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

/* The packed form: integers fflag, vflag, ctype, n_verts, n_facets, n_loops, n_idx, then
 * facet_loops, loop_counts, idx, vci (indirect vertex colours), fci (indirect facet
 * colours); triples pts, vnorm, vrgb, fnorm, frgb (those present). Sizes: 0, or 300 if
 * they overflow an int. */
#define GKS_AREA_DATA_HEADER 7
int gks_area_data_sizes(const gks_area_data *d, size_t *n_ints, size_t *n_triples);
void gks_area_data_pack(const gks_area_data *d, int *ints, double (*tri)[3]);
/* Sizes from a packed header (GKS_AREA_DATA_HEADER ints): 0, or -1 if the header is
 * invalid (flags out of range, negative counts, sizes overflowing an int). */
int gks_area_data_packed_sizes(const int *hdr, size_t *n_ints, size_t *n_triples);
/* A view of a packed form (d points into ints and tri): 0 when n_ints and n_tri are
 * exactly the sizes the header gives, else -1. The content is not checked (see
 * gks_area_data_check). */
int gks_area_data_unpack(const int *ints, size_t n_ints, const double (*tri)[3], size_t n_tri,
                         gks_area_data *d);
#endif
