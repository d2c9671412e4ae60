/* SPDX-License-Identifier: MIT */
/*
 * rt_testutil.h -- helpers for the gksrt tests and benchmark (not part of the library):
 * view mapping matrices from the formulas of BINDINGS.md 3.3, a view orientation matrix,
 * and tiny OFF / NFF loaders (plain or gzip-compressed files).
 */
#ifndef GKS3D_RT_TESTUTIL_H
#define GKS3D_RT_TESTUTIL_H

#include "gksrt.h"

#include <stddef.h>
#include <stdint.h>

/* View parameters (BINDINGS.md 3.3): window [umin,umax]x[vmin,vmax] in the plane n = vpd,
 * prp, back plane n = bpd, front n = fpd, viewport xmin,xmax,ymin,ymax,zmin,zmax (NPC). */
typedef struct rtu_view {
    double win[4];
    double prp[3];
    double vpd, bpd, fpd;
    double vp[6];
    int perspective;
} rtu_view;

/* Builds the view mapping matrix VRC3 -> NPC3 from the closed forms. */
void rtu_view_matrix(const rtu_view *v, double m[4][4]);
/* The projector through NPC (x, y) computed directly from the view parameters: point on the
 * front plane (n = fpd) and on the back plane (n = bpd). */
void rtu_view_projector(const rtu_view *v, double x, double y, double front[3], double back[3]);

/* rt_render_options_default with pixel-centre rays (corner_rays 0) and no cut-off: the
 * tests count rays per pixel and compare pixel values with closed forms. */
void rtu_options_plain(rt_render_options *o);

/* 1 if the two hits are equal bit for bit in every field rt_intersect writes (a miss: prim
 * < 0 on both) */
int rtu_same_hit(const rt_hit *a, const rt_hit *b);

/* View orientation (world -> VRC): origin at 'from', n axis towards 'from' - 'at'. */
void rtu_lookat(const double from[3], const double at[3], const double up[3], double m[4][4]);
void rtu_xform_point(const double m[4][4], const double p[3], double out[3]);

typedef struct rtu_mesh {
    double *xyz;          /* vertices (already in VRC3 after rtu_mesh_transform) */
    int nv;
    int *counts;          /* polygon vertex counts */
    int *idx;             /* vertex indices, all polygons */
    int *surf;            /* surface index per polygon (NFF), 0 for OFF */
    int np;
    size_t nidx;
    rt_surface *surfs;
    int nsurfs;
    double (*lights)[3];
    int nlights;
    double from[3], at[3], up[3], angle, hither;
    int res[2];
    double bg[3];
    int has_view;
} rtu_mesh;

int rtu_load_off(const char *path, rtu_mesh *m);  /* 0 on success */
int rtu_load_nff(const char *path, rtu_mesh *m);
void rtu_mesh_free(rtu_mesh *m);
void rtu_mesh_transform(rtu_mesh *m, const double vo[4][4]);
/* adds all polygons (and NFF surfaces / positional lights) to sc; returns 0 on success */
int rtu_mesh_add(const rtu_mesh *m, rt_scene *sc, int default_surface);
/* bounding box lo xyz hi xyz */
void rtu_mesh_bbox(const rtu_mesh *m, double bb[6]);
/* The benchmarks' scene: an OFF (.off, .off.gz) or NFF file, viewed from its own NFF view or,
 * when it has none, from 3 bounding radii along +z; transformed into VRC3. bb receives the box
 * in VRC3. 0 on success (m then owned by the caller), -1 when the file cannot be loaded. */
int rtu_load_scene_vrc(const char *path, rtu_mesh *m, double bb[6]);

/* perspective camera for an NFF view: scene must already be in VRC3 (eye at origin looking
 * down -n); fills the view so that the whole bbox lies between front and back planes. */
void rtu_nff_view(const rtu_mesh *m, const double bb_vrc[6], rtu_view *v);

/* An NFF file as a committed scene in VRC3 with one default surface, and in *cam the file's
 * view at w x h pixels, its window raised at the top by sky times its height (0: the file's
 * view; test_rt_progress's sky). NULL when the file cannot be loaded or the scene built. */
rt_scene *rtu_nff_scene(const char *path, double sky, int w, int h, rt_camera *cam);

/* A new scene with one surface, rt_surface_default's, whose index goes to *surf; NULL when
 * either cannot be made (the scenes of the build and packet tests) */
rt_scene *rtu_scene_one_surface(int *surf);

/* ---- closed-mesh leak probe (test_rt_hard, bench/rt/rt_leak) ---- */

/* deterministic uniform [0,1) (64-bit LCG) */
double rtu_rand(uint64_t *state);
/* uniform random unit vector */
void rtu_rand_dir(uint64_t *state, double d[3]);

/* A closed lat-long sphere of triangles (nu around, nv from pole to pole; the pole rows are
 * single triangles), both sides surface s: vertex (i, j) = c + r (sin th cos ph, sin th sin ph,
 * cos th), th = pi j / nv, ph = 2 pi i / nu. 0 on success. */
int rtu_add_sphere(rt_scene *sc, const double c[3], double r, int nu, int nv, int s);
/* the same, with normals != 0 the sphere's own (exact) normals at the vertices */
int rtu_add_sphere_data(rt_scene *sc, const double c[3], double r, int nu, int nv, int s,
                        int normals);

/* A point certified inside the closed mesh m (already added to the committed scene sc):
 * found behind a face along its normal, half-way to the next surface, and accepted when 16
 * random rays from it all hit the same side of the surface; that side (rt_hit.side seen
 * from inside) in *inner_side. 0 on success. A ray from inside that leaks through the
 * surface either misses or first hits the other side. */
int rtu_interior_point(const rtu_mesh *m, const rt_scene *sc, double p[3], int *inner_side);

/* Rays from p aimed exactly at every vertex, then at every edge midpoint (each undirected edge
 * once), then nrand random directions; aimed rays have dir = target - p (so the surface is at
 * t <= 1), random ones unit dir. *rays allocated (free()); counts returned. 0 on success. */
int rtu_leak_rays(const rtu_mesh *m, const double p[3], size_t nrand, uint64_t seed,
                  rt_ray **rays, size_t *n, size_t *nvert, size_t *nedge);

#endif
