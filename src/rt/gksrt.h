/* SPDX-License-Identifier: MIT */
/*
 * gksrt.h -- the grid ray tracer of the gks3d library (target gksrt; internal, not installed).
 *
 * Works in view reference coordinates (VRC3), as in Urban & Haberstroh, "Ray Tracing and
 * Graphics Standards" (1992): the caller transforms its area primitives into VRC3, the camera
 * is recovered from the INVERSE of the view mapping matrix (VRC3 -> NPC3), xy-clipping is done
 * by the choice of primary rays, z-clipping by limiting each primary ray to the segment between
 * the front (NPC z = zmax) and back (NPC z = zmin) planes of the display volume.
 * Includes no GKS header.
 *
 * Phases (Embree-like): rt_scene_new -> rt_scene_add_* -> rt_scene_commit -> rt_render /
 * rt_intersect / rt_occluded. Adding after a commit un-commits the scene (commit again).
 * A committed scene is read-only: any number of threads may trace it at the same time.
 *
 * Matrices are double m[4][4], m[row][col], acting on homogeneous COLUMN vectors (x,y,z,w).
 *
 * All functions returning int return RT_OK (0) or a negative RT_ERR_* code, or a
 * non-negative id where stated. Bad input (NaN/Inf, zero or huge counts) never crashes.
 */
#ifndef GKS3D_GKSRT_H
#define GKS3D_GKSRT_H

/* The tracer is internal to gks3d: this header is not installed and the library exports
 * none of its symbols (built with hidden visibility; RT_API marks the interface between the
 * tracer and the rest of the library only). It is not a public API because its option and
 * statistics structs are still changing and carry no size or version field; a public
 * tracer API would be a new, versioned one (docs/RAYTRACING.md). */
#define RT_API

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RT_OK = 0,
    RT_ERR_ARG = -1,      /* invalid argument (NULL, count <= 0, bad id, NaN where not allowed) */
    RT_ERR_NOMEM = -2,    /* allocation failed or size overflow */
    RT_ERR_STATE = -3,    /* scene not committed */
    RT_ERR_SINGULAR = -4, /* view mapping matrix singular / non-finite / display volume unusable */
    RT_ERR_LIMIT = -5,    /* implementation limit (more than RT_MAX_LIGHTS lights, > INT_MAX items) */
    RT_ERR_HOOK = -6      /* a tile hook callback failed (rt_render_options.tiles) */
};

#define RT_MAX_LIGHTS 64

typedef struct rt_scene rt_scene;

/* ---- Surfaces (PHIGS PLUS area properties + refraction index) ---------------------------- */

/* Reflectance equation. PHIGS PLUS numbers these 1..4 (NONE..SPECULAR): pass PHIGS value - 1. */
enum {
    RT_REFL_NONE = 0,     /* flat: colour = diffuse colour Od, no lights */
    RT_REFL_AMBIENT = 1,  /* ka*Od*La */
    RT_REFL_DIFFUSE = 2,  /* + kd*Od*Lc*max(0,N.L) */
    RT_REFL_SPECULAR = 3  /* + ks*Cs*Lc*max(0,R.E)^se, and mirror reflection weighted by ks*Cs */
};

typedef struct rt_surface {
    int refl_eq;           /* RT_REFL_* */
    double ka, kd, ks;     /* ambient, diffuse, specular coefficients (>= 0) */
    double diffuse[3];     /* Od, RGB in [0,1] (replaced by the cell colour on cell arrays) */
    double specular[3];    /* Cs, specular colour */
    double spec_exp;       /* se >= 0 */
    double transparency;   /* kt in [0,1]: weight of the transmitted ray; 0 = opaque */
    double refr_index;     /* > 0. A ray hitting the FRONT side enters a medium of this index
                              (from 1); hitting the BACK side it leaves a medium of the BACK
                              surface's index into 1. Exactly 1: no bending, no Fresnel loss,
                              the ray continues on its own line (picture behind unchanged).
                              Nested media: give an interface the relative index
                              n_inside / n_outside (tested: water 1.33 around glass 1.5). */
    uint64_t light_mask;   /* bit i set: light i (order of rt_scene_add_light) illuminates */
} rt_surface;

/* Fills s with: RT_REFL_DIFFUSE, ka = kd = 1, ks = 0, white, se = 1, kt = 0, index 1,
 * all lights on. */
RT_API void rt_surface_default(rt_surface *s);

/* Adds a surface; returns its id (>= 0) or RT_ERR_ARG (NaN, negative coefficients,
 * kt outside [0,1], index <= 0, refl_eq outside 0..3), RT_ERR_NOMEM. */
RT_API int rt_scene_add_surface(rt_scene *sc, const rt_surface *s);

/* ---- Lights (PHIGS PLUS light source representation), VRC3 ------------------------------ */

/* PHIGS PLUS light source types (same numbers). */
enum { RT_LIGHT_AMBIENT = 1, RT_LIGHT_DIRECTIONAL = 2, RT_LIGHT_POSITIONAL = 3, RT_LIGHT_SPOT = 4 };

typedef struct rt_light {
    int type;              /* RT_LIGHT_* */
    double color[3];       /* Lc (La for ambient), >= 0 */
    double position[3];    /* positional, spot */
    double direction[3];   /* directional, spot: the direction the light TRAVELS (non-zero) */
    double c1, c2;         /* positional, spot: att = 1/(c1 + c2*d); c1, c2 >= 0, c1 + c2 > 0 */
    double concentration;  /* spot: factor = cos(angle to axis)^concentration, >= 0 */
    double spread;         /* spot: half angle in radians, (0, pi]; no light beyond it */
} rt_light;

/* Adds a light; returns its index 0..RT_MAX_LIGHTS-1 (the bit in rt_surface.light_mask),
 * RT_ERR_ARG for bad values, RT_ERR_LIMIT beyond RT_MAX_LIGHTS. */
RT_API int rt_scene_add_light(rt_scene *sc, const rt_light *l);

/* ---- Scene ------------------------------------------------------------------------------- */

/* Forgets the scene's lights (surfaces keep their masks). Lights are used by rt_render only:
 * adding or clearing them does not un-commit the scene. */
RT_API void rt_scene_clear_lights(rt_scene *sc);
/* Replaces the light mask of surface surf (does not un-commit). RT_ERR_ARG for a bad id. */
RT_API int rt_scene_set_surface_lights(rt_scene *sc, int surf, uint64_t mask);
/* Number of primitive ids handed out so far (also those a commit drops). */
RT_API int rt_scene_count(const rt_scene *sc);
/* Removes the primitives of id >= n (0 <= n <= rt_scene_count), e.g. to undo a partly
 * recorded item; un-commits. RT_ERR_ARG for a bad n. */
RT_API int rt_scene_truncate(rt_scene *sc, int n);

/* New empty scene, NULL if out of memory. */
RT_API rt_scene *rt_scene_new(void);
/* Frees a scene (NULL allowed). */
RT_API void rt_scene_free(rt_scene *sc);

/* Coordinate range: a primitive with a vertex coordinate of magnitude above RT_COORD_MAX is
 * dropped at commit (products of such coordinates would overflow in the intersection
 * tests). The GKS workstation clips larger polygons before they get here. */
#define RT_COORD_MAX 1e100

/* GKS FILL AREA (nloops = 1) / FILL AREA SET (nloops > 1) in VRC3: loop k has loop_counts[k]
 * vertices, xyz holds all vertices of all loops consecutively (x,y,z each). Interior by the
 * even-odd rule over all loops; concave, self-intersecting, repeated or collinear vertices and
 * slight non-planarity allowed (plane: Newell normal through the vertex centroid; vertices are
 * projected onto it). The FRONT side is the one the Newell normal points to (counter-clockwise
 * loop seen from the front). Single-loop triangles use a watertight ray/triangle test.
 * Degenerate polygons (zero area, NaN/Inf) are accepted here and dropped at commit.
 * Returns the primitive id (>= 0; polygons and cell arrays share one numbering) or
 * RT_ERR_ARG (nloops/counts <= 0, bad surface id), RT_ERR_NOMEM, RT_ERR_LIMIT. */
RT_API int rt_scene_add_polygon(rt_scene *sc, int nloops, const int *loop_counts, const double *xyz,
                         int front_surface, int back_surface);

/* Per-vertex data of a smooth area (PHIGS PLUS primitives WITH DATA), for
 * rt_scene_add_polygon_data. Either pointer may be NULL. */
typedef struct rt_vertex_data {
    const double *normals;  /* 3 per vertex, VRC3, pointing to the side the vertex normal data
                               calls outside (normalised here; a zero normal adds nothing) */
    const double *colours;  /* 3 per vertex, RGB in [0,1]: replaces the surface's diffuse colour */
} rt_vertex_data;

/* rt_scene_add_polygon with per-vertex normals and/or colours (vd NULL or both pointers NULL:
 * exactly rt_scene_add_polygon). At a hit, the data are interpolated: triangles by barycentric
 * coordinates, other polygons (every loop of a set) by mean value coordinates (Hormann and
 * Floater 2006) in the plane, which are linear along every edge, so that neighbouring areas
 * sharing an edge's vertex data agree along it. The interpolated normal shades, reflects and
 * refracts (rt_render_options.smooth); the geometric plane still decides which side is hit and
 * where secondary rays start. If the interpolated normal points to the other side of the plane
 * than the front (vertex normals against the loop's winding), it is turned around.
 * RT_ERR_ARG also for non-finite normals or colours. */
RT_API int rt_scene_add_polygon_data(rt_scene *sc, int nloops, const int *loop_counts,
                                     const double *xyz, const rt_vertex_data *vd,
                                     int front_surface, int back_surface);
/* Where the next n triangles added to sc would be written in its input arrays (vertices, then
 * records): up to 2 byte ranges [lo[i], hi[i]) of storage it has already reserved, so that
 * another thread can make those pages present ahead of the writer (madvise
 * MADV_POPULATE_WRITE, which never changes their contents). Returns the number of ranges: 0
 * while the arrays are small (on malloc, where they may still move). Reads sc only. */
RT_API int rt_scene_input_next(const rt_scene *sc, size_t n, void *lo[2], void *hi[2]);

/* An indexed triangle mesh in VRC3 (a GKS mesh primitive WITH DATA kept whole: triangle
 * strips, quadrilateral meshes split into triangles, sets of fill area sets' triangles):
 * nverts vertices xyz (3 doubles each), optional per-vertex normals and colours as
 * rt_scene_add_polygon_data takes them (3 doubles per vertex, NULL: none; normalised and
 * stored as floats, colours clamped), ntris triangles idx[3t .. 3t+2] (indices < nverts).
 * The vertices are stored once (24 bytes, and 12 for normals and for colours where given)
 * and each triangle as three 4-byte indices, so that triangles sharing an edge trace exactly
 * the same doubles (watertight). Each triangle is traced and shaded exactly as the same
 * triangle given alone to rt_scene_add_polygon_data (front side: counter-clockwise seen from
 * the front; data interpolated barycentrically); degenerate triangles are dropped when the
 * mesh is added. All triangles carry the one id returned (hits report it). Returns the id or
 * RT_ERR_ARG (a NULL array with counts > 0, an index >= nverts, non-finite normals or
 * colours, a bad surface id), RT_ERR_NOMEM, RT_ERR_LIMIT (more than (2^32 - 1) / 3
 * vertices or 2^31 triangles in the scene's meshes). */
RT_API int rt_scene_add_mesh(rt_scene *sc, size_t nverts, const double *xyz,
                             const double *normals, const double *colours, size_t ntris,
                             const uint32_t *idx, int front_surface, int back_surface);

/* rt_scene_add_mesh in two steps, for a caller that fills the tracer's own arrays instead of
 * handing over copies (a large mesh then needs no second vertex buffer): rt_scene_mesh_begin
 * reserves nverts vertices and ntris triangles and points f at their arrays: xyz (3 doubles
 * per vertex), normals and colours (3 floats per vertex, when has_n, has_c; else NULL) to be
 * filled with rt_mesh_store_normal and rt_mesh_store_colour (as rt_scene_add_mesh stores
 * them), idx (3 per triangle, indices 0 .. nverts-1). rt_scene_mesh_end checks them (as
 * rt_scene_add_mesh) and adds the mesh: its id, or an RT_ERR_* with nothing added (also when
 * the caller gives up: the reservation ends with the next begin, add or truncation; the
 * arrays are valid until then). begin: RT_OK, RT_ERR_ARG, RT_ERR_NOMEM, RT_ERR_LIMIT; end:
 * RT_ERR_STATE without a reservation. */
typedef struct rt_mesh_fill {
    double *xyz;
    float *normals, *colours;
    uint32_t *idx;
} rt_mesh_fill;
RT_API int rt_scene_mesh_begin(rt_scene *sc, size_t nverts, int has_n, int has_c, size_t ntris,
                               rt_mesh_fill *f);
RT_API int rt_scene_mesh_end(rt_scene *sc, int front_surface, int back_surface);
/* fn(arg, k, n) for the parts k = 0 .. n-1 on up to n threads of the tracer's pool (n as
 * rt_build_options.threads takes a request: 0 = the online CPUs; 1 .. RT_PARTS_MAX), the part
 * k = 0 on the caller; returns when all are done. For a caller that prepares a large mesh's
 * data (rt_scene_mesh_begin's arrays) in parallel; parts must not depend on their thread. */
#define RT_PARTS_MAX 64
RT_API void rt_parallel_parts(int threads, void (*fn)(void *arg, int k, int n), void *arg);
/* a vertex normal v normalised into o (0 when zero), a colour c clamped to [0, 1] into o */
RT_API void rt_mesh_store_normal(float o[3], const double v[3]);
RT_API void rt_mesh_store_colour(float o[3], const double c[3]);

/* GKS CELL ARRAY 3 in VRC3: parallelogram with corners P, R, Q and P + Q - R (P and Q
 * diagonally opposite, R a third corner). Columns i = 0..nx-1 run from P towards R, rows
 * j = 0..ny-1 from R towards Q; cell (i,j) colour is rgb[3*(j*nx + i) + 0..2] (nearest
 * neighbour), replacing the surface's diffuse colour. rgb values must be finite (copied).
 * Front side: the normal (R-P) x (Q-R). Returns the primitive id or an RT_ERR_* code. */
RT_API int rt_scene_add_cell_array(rt_scene *sc, const double P[3], const double Q[3], const double R[3],
                            int nx, int ny, const float *rgb, int front_surface, int back_surface);

typedef struct rt_build_options {
    double grid_factor;   /* grid cells per primitive; <= 0: default RT_GRID_FACTOR_DEFAULT
                             (sublinear beyond 10^4 primitives, see below) */
    int brute_force;      /* 1: no grid (tests) */
    int brute_threshold;  /* no grid below this many primitives; < 0: default */
    int grid_res[3];      /* tests/tuning: > 0 in all three: this many cells per axis (<= 1024) */
    double grid_box[6];   /* tests/tuning: with grid_res, grid box lo xyz, hi xyz (united with
                             the scene box, which it must contain to be used exactly) */
    int no_subgrids;      /* 1: no second grid level */
    int sub_min;          /* second level for top cells with more references; <= 0: default */
    double sub_factor;    /* second-level cells per reference; <= 0: default */
    int grid_frame;       /* 0: automatic: the grid is laid out in a rotated frame (axes from
                             one of the largest primitives) when that is estimated to save
                             eye rays (along VRC3 -z) or secondary rays enough traversal
                             (docs/RAYTRACING.md; scenes seen obliquely);
                             1: always VRC3 axes. grid_res forces VRC3 axes. Results do not
                             depend on the frame (grid == brute force bit for bit). */
    int ncull;            /* 0..6: primitives whose every vertex lies outside one of the planes
                             cull[k] (a*x+b*y+c*z+d >= 0 inside) by more than cull_eps are left
                             out of the committed scene (the input keeps them), e.g. the
                             camera's clipping planes when secondary rays are clipped */
    double cull[6][4];
    double cull_eps;
    int threads;          /* threads of the commit and grid build: 0 = online CPUs; the
                             committed scene is identical for any count */
    int progress;         /* 1: report the build on standard error, as GESC_RT_PROGRESS's
                             set-up phases ("rt: set-up: grid of N primitives ... T s") */
    int leaf_min;         /* float leaves (docs/RAYTRACING.md) for cell lists of at least this
                             many triangles; 0: default (none, unless the environment's
                             GKS_RT_LEAF_MIN gives a count); < 0: none. Hits never depend
                             on it. */
} rt_build_options;

/* No float leaves by default: from 4 triangles they save 6 % of the instructions of primary
   rays on the bunny (797 instead of 845 per ray) but triple the scene's memory (29 instead of
   10 MB) and made incoherent rays from inside it about 20 % slower (cache misses, under
   load); from 8, +45 % memory (14.6 MB) for 1 % fewer instructions, times within noise. */

/* Grid resolution rule: top level cells ~= factor * primitives (default 0.25; with the default
 * factor and more than 10^4 primitives: 0.25 * 10^4 * sqrt(primitives / 10^4), i.e. factor
 * 0.079 at 10^5 and 0.025 at 10^6), as cubic as the grid box allows (axes thinner than 1/1000
 * of the largest get 1 cell), at most 512 per axis and 2^25 cells. With all grid options at
 * their defaults, when the median primitive's box spans more than 1/4 of a top cell per axis
 * beyond 10^4 primitives, or more than 0.4 up to 10^4 (a volume of large random triangles,
 * not a surface mesh), top cells 10 times the median extent, always with a second level of
 * ~3 cells per reference. A top cell with more than
 * 8 references keeps its large primitives (spanning half the cell in two axes) in its own
 * list and puts the rest into a second-level grid of ~3 cells per reference (default
 * sub_factor; 4 beyond 10^4 primitives, there 0.5 and 0.7 times that in sub-grids with 1 or 2
 * cells on their thinnest axis; at most 32 per axis) over the box of those parts.
 * Up to 10^4 primitives and with all grid options at their defaults, when at least 3/4 of
 * the occupied top cells hold more than 8 references (surfaces filling their cells evenly)
 * and the top level was not widened, one level of 8 cells per primitive replaces the two.
 * Below 4 primitives: no grid. An explicit grid_factor or sub_factor is always used as
 * given (linearly). The measurements behind these numbers: docs/bench/rt_tuning.md. */
#define RT_GRID_FACTOR_DEFAULT 0.25
#define RT_BRUTE_THRESHOLD_DEFAULT 4

/* Drops degenerate primitives, builds the uniform grid (CSR arrays). opts may be NULL
 * (defaults). Returns RT_OK, RT_ERR_NOMEM. */
RT_API int rt_scene_commit(rt_scene *sc, const rt_build_options *opts);

/* Statistics of the committed grid (for reports and tests). */
typedef struct rt_grid_info {
    int res[3];              /* top-level cells per axis; 0 0 0: brute force (no grid) */
    int rotated;             /* 1: grid laid out in a rotated frame (rt_build_options.grid_frame) */
    uint64_t prims;          /* primitives kept at commit */
    uint64_t cells, refs;    /* top level: cells, primitive references */
    uint64_t empty_cells;    /* top-level cells without references and without a second level */
    uint64_t subgrids, subcells, subrefs; /* second level */
    uint64_t max_leaf_refs;  /* most references in one cell that is traversed as a leaf */
    double volume_fill;      /* fraction of the grid box in non-empty leaf cells */
    uint64_t hash;           /* FNV-1a over the committed grid (frame, boxes, cell offsets and
                                references of both levels, empty cubes): equal
                                hashes, the same grid; 0 without a grid */
    uint64_t float_leaves, float_lanes; /* cell lists also kept as float leaves, their lanes */
    uint64_t flat_subgrids;  /* sub-grids whose triangles lie in one plane (rt_occluded skips
                                them where the ray's segment stays on one side) */
    const char *simd;        /* their test's kernel: "avx2", "sse", "scalar" ("none": no grid;
                                a static string) */
} rt_grid_info;

/* Fills gi for a committed scene. RT_ERR_ARG (NULL), RT_ERR_STATE (not committed). */
RT_API int rt_scene_grid_info(const rt_scene *sc, rt_grid_info *gi);

/* ---- Rays --------------------------------------------------------------------------------- */

typedef struct rt_ray {
    double org[3], dir[3];  /* dir need not be unit; non-finite or zero: always a miss */
    double tmin, tmax;      /* hits with tmin <= t <= tmax (in units of dir); tmax may be +inf */
} rt_ray;

typedef struct rt_hit {
    double t;        /* ray parameter of the nearest hit */
    int prim;        /* primitive id, -1 = miss */
    int side;        /* 0: front side hit, 1: back side */
    double p[3];     /* hit point org + t*dir */
    double ng[3];    /* unit geometric normal of the front side */
} rt_hit;

/* Nearest hit for n rays (ties in t within the intersection's error bound: the larger primitive
 * id, the area drawn later; within a mesh the nearer, at equal t the triangle given first).
 * RT_ERR_STATE if not committed, RT_ERR_NOMEM. Grid and brute force give bit-identical
 * results. */
RT_API int rt_intersect(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits);
/* occluded[k] = 1 if ray k hits anything in [tmin,tmax], else 0 (transparency ignored). */
RT_API int rt_occluded(const rt_scene *sc, size_t n, const rt_ray *rays, unsigned char *occluded);

/* The coherent path: rt_intersect and rt_occluded for rays in packets of RT_PACKET
 * consecutive rays (the last packet may be shorter), each packet traced together through the
 * grid (coherent grid traversal: its triangles loaded once per packet, tested for several rays
 * at a time). Give it 8 x 8 blocks of neighbouring primary rays (row by row within a block),
 * or shadow rays of neighbouring points toward one point light, in the same order. The
 * answers are those of rt_intersect / rt_occluded bit for bit, for any rays: a packet whose
 * rays do not share the dominant axis and the signs of their directions, or whose footprint
 * in the grid grows too large (diverging rays), and any scene without a grid, takes the
 * single-ray path; so does a ray whose nearest hit could depend on the order of the tests
 * (docs/RAYTRACING.md, "Packets"). Return values as rt_intersect / rt_occluded. */
#define RT_PACKET 64
RT_API int rt_intersect_packet(const rt_scene *sc, size_t n, const rt_ray *rays, rt_hit *hits);
RT_API int rt_occluded_packet(const rt_scene *sc, size_t n, const rt_ray *rays,
                              unsigned char *occluded);

/* ---- Camera (paper section 3) ------------------------------------------------------------ */

typedef struct rt_camera {
    int width, height;       /* raster size in pixels */
    int perspective;         /* 1: perspective (prp valid), 0: parallel (dop valid) */
    double prp[3];           /* projection reference point in VRC3 */
    double dop[3];           /* unit direction of projection (towards the back plane) */
    double minv[4][4];       /* inverse view mapping matrix NPC3 -> VRC3 */
    double box[6];           /* display volume in NPC3: xmin,xmax,ymin,ymax,zmin,zmax */
    double corner[8][3];     /* its corners in VRC3; index bit0: x max, bit1: y max, bit2: z max */
    double plane[6][4];      /* clipping planes in VRC3: a*x+b*y+c*z+d >= 0 inside (unit a,b,c);
                                order: x min, x max, y min, y max, back (z min), front (z max) */
    double origin[3];        /* VRC3 point of NPC (xmin, ymax, zmax): top-left raster corner */
    double du[3], dv[3];     /* raster steps on the front plane: one pixel right / one pixel down
                                (exact when the front plane maps affinely, as for all view
                                mapping matrices; rays themselves always use minv) */
    double scale;            /* size of the display volume in VRC3 (for epsilons) */
} rt_camera;

/* Recovers the camera from the view mapping matrix vmap (VRC3 -> NPC3) and the display volume
 * npc_box (xmin,xmax,ymin,ymax,zmin,zmax; = view clip volume ∩ workstation window):
 * inverts vmap, maps the 8 corners back to VRC3, P = vmap^-1 (0,0,1,0)^T gives the PRP (w != 0)
 * or direction of projection (w == 0), derives the 6 clipping planes and the raster on the
 * front plane. RT_ERR_SINGULAR if vmap is singular or non-finite or the volume has a corner at
 * or behind infinity; RT_ERR_ARG for a bad box (min >= max in x or y, zmin >= zmax, NaN) or
 * size (< 1 or > 65536). */
RT_API int rt_camera_from_view(rt_camera *cam, const double vmap[4][4], const double npc_box[6],
                        int width, int height);

/* Primary ray through raster position (px, py): px in [0,width] from the left edge, py in
 * [0,height] from the TOP edge (pixel (i,r) centre = (i+0.5, r+0.5)). org on the front plane,
 * unit dir, tmin = 0, tmax = distance to the back plane. Returns RT_OK or RT_ERR_ARG. */
RT_API int rt_camera_ray(const rt_camera *cam, double px, double py, rt_ray *ray);

/* ---- Rendering --------------------------------------------------------------------------- */

enum { RT_FRESNEL_EXACT = 0, RT_FRESNEL_SCHLICK = 1, RT_FRESNEL_NONE = 2 };

/* How interpolated vertex normals are used (docs/RAYTRACING.md, "Smooth areas"):
 * ROBUST: shadow rays start from Hanika's point (2021, "Hacking the shadow terminator": the
 *   hit point moved onto the interpolated tangent planes of the vertices, where that lies
 *   above the plane), and the shading normal is adapted so that the mirror direction of the
 *   viewer stays above the geometric surface (Keller et al. 2017, Iray), refracted directions
 *   are kept below it;
 * NAIVE: the interpolated normal as it is, shadow rays from the hit point (for comparison);
 * FLAT: vertex normals ignored (geometric normal), vertex colours still interpolated. */
enum { RT_SMOOTH_ROBUST = 0, RT_SMOOTH_NAIVE = 1, RT_SMOOTH_FLAT = 2 };

typedef struct rt_stats {
    uint64_t eye_rays, eye_hits, shadow_rays, reflection_rays, refraction_rays;
    uint64_t shadow_lbuf;             /* shadow rays answered from a light buffer's list */
    uint64_t shadow_walks;            /* shadow rays that walked the grid (the others: answered
                                         by the blocker cache, or trivially lit) */
    uint64_t reflection_mirror;       /* reflection rays (of eye rays off a flat mirror)
                                         answered from a mirror's list, not the grid walk */
    uint64_t grid_cells, grid_refs;   /* 0 when brute force */
    uint64_t prims;                   /* primitives kept at commit */
    double build_seconds;             /* commit time */
    double render_seconds;
    size_t memory_bytes;              /* scene + grid */
    size_t tri_bytes;                 /* of memory_bytes: the triangles' records (rt_prim and
                                         the vertices, rt_tri; a mesh's: one rt_prim for the
                                         mesh, the index triples and its shared vertex data) */
    size_t grid_bytes;                /* of memory_bytes: both grid levels */
} rt_stats;

/* *a += *b, field by field (the one sum of statistics: threads, tiles, views). */
static inline void rt_stats_add(rt_stats *a, const rt_stats *b)
{
    a->eye_rays += b->eye_rays;
    a->eye_hits += b->eye_hits;
    a->shadow_rays += b->shadow_rays;
    a->reflection_rays += b->reflection_rays;
    a->refraction_rays += b->refraction_rays;
    a->shadow_lbuf += b->shadow_lbuf;
    a->shadow_walks += b->shadow_walks;
    a->reflection_mirror += b->reflection_mirror;
    a->grid_cells += b->grid_cells;
    a->grid_refs += b->grid_refs;
    a->prims += b->prims;
    a->build_seconds += b->build_seconds;
    a->render_seconds += b->render_seconds;
    a->memory_bytes += b->memory_bytes;
    a->tri_bytes += b->tri_bytes;
    a->grid_bytes += b->grid_bytes;
}

typedef void (*rt_progress_fn)(void *user, int tiles_done, int tiles_total);

/* Tile distribution (docs/MPI.md): the frame's ray grid ((w+1) x (h+1) corner rays, else
 * w x h pixels) is cut into 16 x 16 tiles numbered row-major 0..ntiles-1, the same on every
 * process rendering the same view. A hook decides which tiles this process traces and hands
 * the traced ones on; tiles traced elsewhere come back through rt_frame_store. A tile's
 * payload (opaque bytes: its rays' results before the final resolve, and its ray counters)
 * depends only on scene, camera, options and tile index, so the picture is bit-identical
 * for any split. next and done are called one thread at a time (under rt_render's lock);
 * with threads == 1 every callback runs on the thread that called rt_render; begin and end
 * always do. A callback returning an error stops all threads; rt_render returns
 * RT_ERR_HOOK. */
typedef struct rt_frame rt_frame;
typedef struct rt_tile_hook {
    void *user;
    /* once before any tile: 0 or < 0 (error) */
    int (*begin)(void *user, rt_frame *f, int ntiles, size_t max_tile_bytes);
    /* next tile to trace here (>= 0); -1: none left for this process; < -1: error */
    int (*next)(void *user);
    /* a tile traced here and its payload: 0 or < 0 (error) */
    int (*done)(void *user, int tile, const void *payload, size_t bytes);
    /* after every local thread stopped: 1 the frame is complete here (resolved into rgb,
       stats over all tiles); 0 not assembled here (rgb unspecified, stats of the tiles
       traced here); < 0 error */
    int (*end)(void *user, rt_frame *f);
} rt_tile_hook;

/* Stores the payload of a tile traced elsewhere into f as if traced here (its ray counters
 * count in the frame's stats). Only from inside the hook's callbacks. RT_ERR_ARG for a bad
 * tile, size or payload. */
RT_API int rt_frame_store(rt_frame *f, int tile, const void *payload, size_t bytes);
/* A tile's colours for a preview while the frame forms (e.g. from rt_tile_hook.done): its
 * rectangle of the ray grid, rect = x0, x1, y0, y1 (rows from the top; in corner-ray mode
 * the (w+1) x (h+1) corner rays), and 3 floats per ray, row-major, into rgb (room for
 * 16 x 16 rays): the values before corner averaging and coverage. RT_ERR_ARG for a bad tile
 * or size. */
RT_API int rt_frame_tile_rgb(const rt_frame *f, int tile, const void *payload, size_t bytes,
                             int rect[4], float *rgb);

typedef struct rt_render_options {
    int samples;            /* per pixel: 1, 4, 9, 16, ... (perfect square, stratified) */
    int jitter;             /* 1: jitter within strata, deterministic per pixel and sample */
    int max_depth;          /* eye ray = depth 1; rays at depth max_depth spawn nothing (1..64) */
    double cutoff;          /* adaptive depth: no secondary ray whose weight (max over RGB of the
                               product of coefficients along the path) is below this; 0 = off */
    int threads;            /* 0: number of online CPUs (at most 64, the thread pool's limit);
                               picture identical for any count */
    int fresnel;            /* RT_FRESNEL_* for transmitting surfaces */
    int clip_secondary;     /* 1: shadow/reflection/refraction rays see only the display volume */
    int corner_rays;        /* 1: (w+1)x(h+1) rays at pixel corners, pixel = mean of its 4
                               corners (the SPD procedure's rays; samples and jitter ignored);
                               0: samples stratified rays per pixel */
    int light_buffers;      /* 1: shadow rays test the candidates of a per-light buffer instead of
                               walking the grid where it pays (same answers; rt_lbuf.c) */
    double background[3];
    int progress;           /* 1: report tiles done, Mrays/s and time left on stderr */
    rt_progress_fn progress_fn;  /* optional, called by one thread at a time; may be NULL */
    void *progress_user;
    const rt_tile_hook *tiles;   /* NULL: every tile traced here (default) */
    int smooth;             /* RT_SMOOTH_* for areas with vertex normals */
} rt_render_options;

/* Defaults (on the speed/error Pareto front of bench/speed_error): corner rays (samples 1, no
 * jitter, used when corner_rays is set to 0), depth 5, cut-off 0.01, threads 0, exact Fresnel,
 * clip_secondary 0, light buffers, black background, no progress, RT_SMOOTH_ROBUST. */
RT_API void rt_render_options_default(rt_render_options *o);

/* Shading of a hit (front or back surface by the side hit; the normal is turned to face the ray):
 *   refl_eq NONE: I = Od. Otherwise I = sum over ambient lights ka*Od*La + sum over other lights
 *   att*spot*T*[kd*Od*Lc*max(0,N.L) + ks*Cs*Lc*max(0,R.E)^se] (specular term only for
 *   SPECULAR), att = 1/(c1 + c2*d) (1 for directional), spot = cos^concentration inside the
 *   spread, T = shadow transmittance.
 * Shadow rays: one per non-ambient light in the light mask when N.L > 0 (and the spot cone
 *   reaches the point and refl_eq >= DIFFUSE); every surface crossed multiplies T by its
 *   transparency coefficient (no bending); an opaque one blocks.
 * Secondary rays (depth < max_depth): reflection with weight ks*Cs (refl_eq SPECULAR) plus, on
 *   transmitting surfaces (kt > 0), kt*F (Fresnel reflectance, 1 on total internal
 *   reflection); refraction (Snell) with weight kt*(1 - F). Local shading is not scaled by kt.
 *   Counting as the SPD procedure asks: every spawned reflection ray (also at transmitting
 *   surfaces and on TIR) is a reflection ray.
 * Self-intersection: secondary ray origins are moved off the surface along the normal, to the
 *   side they leave on, by 1e-12*(max|hit coordinate| + t) + 1e-9*(scene extent), i.e. ~10^4
 *   ulps of the hit point: far above its rounding error (tested at offsets up to 1e6).
 * Renders cam's raster into rgb (width*height*3 floats, row 0 = top, linear RGB, not clamped).
 * opts NULL: defaults; stats may be NULL. RT_ERR_STATE if the scene is not committed,
 * RT_ERR_ARG for bad options, RT_ERR_NOMEM. Never writes NaN/Inf. */
RT_API int rt_render(const rt_scene *sc, const rt_camera *cam, const rt_render_options *opts,
              float *rgb, rt_stats *stats);
/* rt_render, and with cover not NULL the coverage of each pixel (width*height counts, row 0 =
 * top): how many of its rays hit a primitive as eye rays, out of 4 with corner rays (its 4
 * corners), else out of opts->samples (its samples as traced, jittered or not). */
RT_API int rt_render_cover(const rt_scene *sc, const rt_camera *cam, const rt_render_options *opts,
                           float *rgb, unsigned short *cover, rt_stats *stats);

/* Ordered background work on the tracer's thread pool (rt_pool.c): items pushed to an
 * rt_serial are passed to fn(user, item) one at a time, in push order, on a pool worker while
 * the pushing thread goes on (the GKS workstation records areas into its scene this way).
 * At most 32 items wait: a push beyond that runs the oldest on the pusher, or waits while the
 * worker runs one. fn must not block
 * on the pusher. rt_serial_new returns NULL when threads (0: online CPUs) is below 2 or on
 * storage failure: the caller then does the work itself. rt_serial_drain returns when every
 * pushed item has run (its effects are then visible to the caller); rt_serial_free drains
 * and frees (NULL allowed). */
typedef struct rt_serial rt_serial;
typedef void (*rt_serial_fn)(void *user, void *item);
RT_API rt_serial *rt_serial_new(int threads, rt_serial_fn fn, void *user);
RT_API void rt_serial_push(rt_serial *s, void *item);
/* 1 if a push now would wait: 32 items wait and the oldest is being run (the pusher may do
 * other useful work first), else 0. */
RT_API int rt_serial_full(rt_serial *s);
RT_API void rt_serial_drain(rt_serial *s);
RT_API void rt_serial_free(rt_serial *s);

#ifdef __cplusplus
}
#endif
#endif
