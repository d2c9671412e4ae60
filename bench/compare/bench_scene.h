/* SPDX-License-Identifier: MIT */
/*
 * bench_scene.h -- scene set-up shared by bench/compare and bench/speed_error (not part of
 * the library): reads an NFF / OFF / PLY file with scene_io, moves it into view reference
 * coordinates (VRC3: eye at the origin looking down -n), adds it to a gksrt scene with the
 * SPD conventions and recovers the rt_camera from a perspective view mapping matrix.
 *
 * SPD conventions (Haines' SPD readme): NFF "f r g b Kd Ks Shine T ior" becomes refl_eq
 * SPECULAR, ka = 0, kd = Kd, ks = Ks, Od = (r,g,b), Cs = white, se = Shine, kt = T,
 * index = ior (1 when <= 0); each of the n positional lights has intensity 1/sqrt(n).
 * Meshes (no view, no lights) get scene_io_frame_view's camera, one positional light above
 * and right of the eye plus an ambient light, and a white surface ka 0.1, kd 0.8 (ks 0).
 */
#ifndef GKS3D_BENCH_SCENE_H
#define GKS3D_BENCH_SCENE_H

#include "gksrt.h"

#include <stddef.h>
#include <stdint.h>

typedef struct bs_scene {
    rt_scene *rt;            /* committed scene */
    rt_camera cam;
    double background[3];
    double world_to_vrc[4][4];
    /* the scene view in world coordinates (for peers that read the original file) */
    double from[3], at[3], up[3], angle, hither, far_dist;
    /* light 0 in VRC3 and world coordinates (meshes: the added light) */
    double light_vrc[3], light_world[3];
    int nlights;
    /* triangles (after fan triangulation of polygons) for peers: VRC3 and world vertices */
    size_t nverts;
    double *verts_vrc;       /* 3 * nverts */
    double *verts_world;     /* 3 * nverts */
    size_t ntris;
    uint32_t *tris;          /* 3 * ntris vertex indices */
    int *tri_prim;           /* gksrt primitive id of each triangle */
    size_t npolys;           /* primitives added to gksrt */
    int all_triangles;       /* 1: every polygon was a triangle (tri k == prim k) */
    int indexed;             /* 1: added as one indexed mesh (bs_options.indexed): every
                                tri_prim is the mesh's id */
    double commit_seconds;   /* CPU time of rt_scene_commit (process) */
    double commit_wall;      /* wall time of rt_scene_commit */
} bs_scene;

typedef struct bs_options {
    int size;                /* raster size (square); <= 0: the NFF resolution, else 512 */
    const rt_build_options *build;  /* NULL: defaults */
    double mesh_ks;          /* meshes: ks (mirror weight) of the surface, 0 = matte */
    int indexed;             /* 1: a file whose polygons all have one material goes to gksrt
                                as one indexed mesh (rt_scene_add_mesh: the shared vertex
                                buffer and the fan triangles' indices, as Embree is given it);
                                0 (and other files): one rt_scene_add_polygon per polygon */
} bs_options;

/* Loads path, builds and commits the gksrt scene and the camera. Returns 0, or -1 with a
 * message in err. bs_free is safe after any return. */
int bs_load(const char *path, const bs_options *opt, bs_scene *s, char *err, size_t err_size);
void bs_free(bs_scene *s);

/* Perspective camera in VRC3: eye at the origin looking down -n, full field of view angle
 * degrees, front/back planes at distances near < far, w x h raster. Returns RT_OK or the
 * rt_camera_from_view error. */
int bs_camera(rt_camera *cam, double angle, double near, double far, int w, int h);

/* Render options of the SPD procedure: corner rays, depth 5, no cut-off, exact Fresnel,
 * the scene background, 1 thread. */
void bs_spd_options(const bs_scene *s, rt_render_options *o);

/* Checked allocation of n * size bytes (overflow and failure give NULL). */
void *bs_alloc(size_t n, size_t size);

/* Seconds: CPU time of the calling thread / of the process, monotonic wall clock. */
double bs_thread_cpu(void);
double bs_process_cpu(void);
double bs_wall(void);

#endif
