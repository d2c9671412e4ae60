/* SPDX-License-Identifier: MIT */
/*
 * rt_polygon.h -- point-in-polygon grids for big polygons (issue 20): a polygon with many
 * edges crossing its slabs (long edges, a self-winding polygon) gets a 2-D grid over its
 * projected box, Haines' grid method (Graphics Gems IV, "Point in Polygon Strategies"):
 * each cell lists the edges meeting it (a small margin around it) and stores the even-odd
 * parity of its lower right corner; a query point's parity is the corner's, corrected by
 * the cell's edges that cross the path from the point right to the cell's right side and
 * down that side to the corner. The corrections use the crossing rule of rt_isect_poly
 * (half-open in v, the product test in u) and count the path's crossings with ties broken
 * as that rule breaks them, so the answer is the rule's answer over all edges: the
 * pictures equal the slab method's, at a cost of the cell's edges instead of the slab's.
 * Private to src/rt.
 */
#ifndef GKS3D_RT_POLYGON_H
#define GKS3D_RT_POLYGON_H

#include <stddef.h>
#include <stdint.h>

typedef struct rt_pgrid {
    int gu, gv;            /* cells along u, v */
    double u0, v0;         /* grid origin (the polygon's box less a margin) */
    double inv_du, inv_dv; /* cells per unit */
    double *xs, *vs;       /* the gu + 1 column lines, gv + 1 row lines */
    uint8_t *corner;       /* gv x gu: parity at (xs[i + 1], vs[j]) of cell (i, j) */
    uint32_t *off;         /* gu * gv + 1: first entry of cell (i, j) = off[j * gu + i] */
    uint32_t *ids;         /* edge numbers */
    double *e;             /* edges (u0, v0, u1, v1), v0 <= v1 */
    size_t ne, nref;
} rt_pgrid;

/* Polygons with at least this many edges (and crowded slabs) get a grid. */
#define RT_PGRID_MIN_EDGES 1024

/* Builds g for the polygon whose nloops loops (counts) of 2-D vertices uv (u, v pairs,
 * consecutive) span [umin,umax] x [vmin,vmax]. Returns 0, or -1 on storage failure or when
 * the grid would not fit its memory budget (then g is empty and the slabs are used). */
int rt_pgrid_build(rt_pgrid *g, const double *uv, const uint32_t *counts, uint32_t nloops,
                   double umin, double umax, double vmin, double vmax);
void rt_pgrid_free(rt_pgrid *g);
/* bytes held by g */
size_t rt_pgrid_bytes(const rt_pgrid *g);

/* Even-odd parity (1 inside) of (pu, pv) by the crossing rule of rt_isect_poly. */
int rt_pgrid_parity(const rt_pgrid *g, double pu, double pv);

#endif
