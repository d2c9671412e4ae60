/* SPDX-License-Identifier: MIT */
/*
 * rt_internal.h -- private data of the gksrt ray tracer. Not for applications.
 */
#ifndef GKS3D_RT_INTERNAL_H
#define GKS3D_RT_INTERNAL_H

#ifndef GKS3D_RT_BUILDING
#error "rt_internal.h is private to src/rt"
#endif

#include "gksrt.h"
#include "rt_polygon.h"
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* ---- allocation funnel (rt_alloc.c) ---- */
void *rt_alloc_array(size_t n, size_t size);
/* rt_alloc_array's n elements starting on a cache line (RT_LINE bytes; free() frees them) */
void *rt_alloc_lines(size_t n, size_t size);
void *rt_calloc_array(size_t n, size_t size);
void *rt_realloc_array(void *p, size_t n, size_t size);
/* Grows *p (element size es) so that it holds at least need elements; *cap updated. */
int rt_grow(void **p, size_t *cap, size_t need, size_t es);
/* A growable array that never moves once it is large (beyond 4 MiB it lives in a reserved
   range of address space and grows in place: no copy, no fresh pages for a copy); for the
   arrays a scene's recording grows to hundreds of MB. Zero-initialised = empty. */
typedef struct rt_big {
    void *p;
    size_t cap;        /* elements of size es that p holds */
    size_t map_bytes;  /* its own mapping's size, 0: malloc'ed */
} rt_big;
/* room for at least need elements of size es (the same es every time): 1, or 0 (no storage;
   the array is unchanged) */
int rt_big_grow(rt_big *b, size_t need, size_t es);
/* gives back the storage beyond the first keep elements of size es (the data before stays in
   place; a malloc'ed array may move, as realloc moves it); b then holds keep elements of es */
void rt_big_shrink(rt_big *b, size_t keep, size_t es);
void rt_big_free(rt_big *b);

/* ---- the thread pool (rt_pool.c): fork-join loops ---- */
#define RT_PAR_MAX 64 /* threads at most */
/* bytes of a cache line: the padding after a per-thread record that its thread writes while
   the next record's thread writes that one (records side by side in an array), so the two
   threads do not take the same line from each other (false sharing) */
#define RT_LINE 64
typedef void (*rt_par_fn)(void *arg, int k, int n);
/* threads for a request as rt_build_options.threads takes it (0: online CPUs), 1 .. RT_PAR_MAX */
int rt_par_threads(int requested);
/* the threads the pool has now (its workers and the caller): the largest count a caller
   asked for so far, 1 before any; for work whose caller gives no count (rt_scene_mesh_end) */
int rt_par_pool_threads(void);
/* fn(arg, k, n) for k = 0 .. n-1 on up to n threads of the pool (k = 0 on the caller); returns
   when all are done. Parts must not depend on which thread runs them. */
void rt_par_run(int n, rt_par_fn fn, void *arg);
/* [*lo, *hi) of part k of n of 0 .. count-1 */
static inline void rt_par_range(size_t count, int k, int n, size_t *lo, size_t *hi)
{
    *lo = count / (size_t)n * (size_t)k + (count % (size_t)n < (size_t)k ? count % (size_t)n : (size_t)k);
    *hi = *lo + count / (size_t)n + ((size_t)k < count % (size_t)n);
}

/* the vertices of a polygon of nloops loops (loop_counts[k] > 0 each) in *nv: RT_OK,
   RT_ERR_ARG (a count <= 0), RT_ERR_LIMIT (too many) (rt_scene.c) */
int rt_loops_vertices(int nloops, const int *loop_counts, size_t *nv);

/* ---- primitives ---- */
enum { RT_KIND_TRI = 0, RT_KIND_POLY = 1, RT_KIND_CELL = 2, RT_KIND_QUAD = 3 };

typedef struct rt_tri {
    double v[3][3];
} rt_tri;

/* planar strictly convex 4-gon: watertight edge functions like the triangle, t from the plane */
typedef struct rt_quad {
    double v[4][3];
    double n[3];
    double vmax; /* the largest |v[k][j]| (rt_hit_err's bound, read per hit) */
} rt_quad;

/* doubles per entry of rt_scene's edges */
#define RT_EDGE_STRIDE 5

typedef struct rt_poly {
    double n[3], d;     /* plane n.x = d, unit n */
    int ku, kv;         /* projection axes (dominant axis dropped) */
    uint32_t uv0;       /* first 2-D vertex in scene uv array */
    uint32_t loop0;     /* first loop count in scene loops array */
    uint32_t nloops;
    double umin, umax, vmin, vmax; /* 2-D bounds (exact reject) */
    double uvmax;       /* the largest of |umin|, |umax|, |vmin|, |vmax| (rt_hit_err) */
    double inv_h;       /* slabs per unit v */
    double cu, cv, rin2;/* disk around (cu,cv) crossed by no edge (radius^2, < 0: none) ... */
    int cin;            /* ... in which every point has this even-odd parity */
    double rout2;       /* outside the disk around (cu,cv) of radius^2 rout2 (all vertices
                           inside, with a margin): even-odd parity 0 */
    uint32_t nslab;     /* horizontal slabs over [vmin,vmax]; edge lists per slab */
    size_t slab0;       /* first entry in scene slab_off (nslab + 1 entries) */
    uint32_t pgrid;     /* 1 + index in scene pgrid (a big polygon's grid, rt_polygon.h), 0 */
} rt_poly;

typedef struct rt_cell {
    double p[3], a[3], b[3]; /* corner P, column edge R-P, row edge Q-R */
    double n[3], d;          /* unit normal (a x b), plane */
    int ku, kv;
    double inv[2][2];        /* inverse of the projected [a b] */
    int nx, ny;
    size_t rgb0;             /* first float in scene cell colour array */
} rt_cell;

/* 12 bytes per primitive. The front normal is not stored: rt_prim_ng gives it (the plane
   normal of a quad, polygon or cell; a triangle's computed from its vertices at each use by
   rt_tri_unit_normal, the same bits every time). A triangle's data is its primitive index.
   Mesh triangles have no record stored: their mesh's (rt_cmesh) is theirs (rt_prim_at). */
#define RT_SPAIR_MAX ((uint32_t)1 << 29) /* distinct surface pairs at most (sp's bits) */
typedef struct rt_prim {
    int id;             /* user id */
    uint32_t data;      /* index into tris/quads/polys/cells */
    uint32_t kind : 2;  /* RT_KIND_* */
    uint32_t opaque : 1;/* both sides kt == 0 */
    uint32_t sp : 29;   /* (front, back) surfaces: the scene's spair[sp] */
} rt_prim;

/* raw input polygon / cell array kept until commit */
typedef struct rt_in_prim {
    int kind;           /* RT_KIND_POLY or RT_KIND_CELL */
    int id;             /* primitive id */
    int front, back;
    size_t xyz0;        /* first double (poly: all loops; cell: P,Q,R) */
    size_t loop0;       /* poly: first loop count */
    int nloops;
    int nx, ny;         /* cell */
    size_t rgb0;        /* cell: first float of colours in in_rgb */
} rt_in_prim;

/* per-vertex data of one smooth area (rt_scene_add_polygon_data), in id order */
typedef struct rt_vd {
    uint32_t id;        /* primitive id */
    uint32_t nv;        /* vertices (all loops) */
    uint32_t nloops;
    uint8_t has_n, has_c;
    size_t v0;          /* first vertex in vd_xyz (3 doubles), vd_n, vd_c (3 floats each) */
    size_t loop0;       /* first loop count in vd_loops */
} rt_vd;

#define RT_NO_VD UINT32_MAX

/* The grid's frame choice (rt_build.c) ranks the primitives by the largest face of their
   bounding box and tries the RT_FRAME_CAND largest: such a list, descending, the lower index
   first among equal areas (what one pass in index order keeps). */
#define RT_FRAME_CAND 8
typedef struct rt_fcands {
    double area[RT_FRAME_CAND];
    size_t cand[RT_FRAME_CAND];
    int nc;
} rt_fcands;
/* the area the frame choice ranks a primitive by: the largest face of its box, of extents
   (max - min of its points) ex, ey, ez */
static inline double rt_fcands_area(double ex, double ey, double ez)
{
    const double a = ey * ez, b = ex * ez, m = b > a ? b : a, c = ex * ey;
    return m > c ? m : c;
}
/* the primitive of index i and rt_fcands_area ar into l, ranked as the frame choice ranks it */
void rt_fcands_add(rt_fcands *l, double ar, size_t i);
/* 1 if rt_fcands_add(l, ar, ...) would change l (a cheap test before the call) */
static inline int rt_fcands_takes(const rt_fcands *l, double ar)
{
    return l->nc < RT_FRAME_CAND || l->area[RT_FRAME_CAND - 1] < ar;
}
/* the list from, its indices + off, into l, as if its primitives came after l's */
void rt_fcands_merge(rt_fcands *l, const rt_fcands *from, size_t off);

/* an indexed mesh (rt_scene_add_mesh): its triangles nt input triangles from t0 in the
   scene's mtri (offsets 3 v into mv_xyz, global: rt_scene.vmask), its vertices nv from v0
   (mv_xyz; mv_n and mv_c where has_n, has_c); every triangle has the mesh's id and surfaces */
typedef struct rt_mesh {
    uint32_t id;
    int front, back;
    uint8_t has_n, has_c;
    size_t t0, nt, v0, nv;
    double bb[6];       /* box of its triangles (degenerate ones were dropped when added) */
    rt_fcands cands;     /* its triangles' frame candidates (indices from its first) */
    size_t nused;        /* stored in spatial order: its vertices used by its triangles, the
                            first nused (rt_mesh_sort); 0: not known */
} rt_mesh;

/* the committed triangles of one mesh (rt_scene.cmesh): the primitives from the previous
   entry's end (the first: ntri_plain) up to end share the record rec (data aside: a
   triangle's is its index) */
typedef struct rt_cmesh {
    size_t end;
    rt_prim rec;
} rt_cmesh;

/* an axis-aligned box cut into n[0] x n[1] x n[2] equal cells */
typedef struct rt_box {
    double lo[3], hi[3], cw[3], inv_cw[3];
    int n[3];
} rt_box;

/* second level: a finer grid inside one crowded top-level cell. Two cache lines, the grid's
   array of them starting on a line (rt_alloc_lines): the top walk's clip to the box (a third
   of the rays miss it) reads the first line (lo, hi), a walk of it both; on malloc's 16-byte
   alignment a record spanned three lines unless the array happened to start on a line
   (docs/bench/rt_tuning.md) */
/* rt_grid.odist's byte of a top cell: an empty cell's cube edge (1 .. RT_CUBE_MAX), or for an
   occupied cell RT_CUBE_OCC with RT_CUBE_LIST (its own list is not empty) and RT_CUBE_SUB (it
   has a second-level grid) */
enum { RT_CUBE_MAX = 127, RT_CUBE_OCC = 128, RT_CUBE_LIST = 1, RT_CUBE_SUB = 2 };

typedef struct rt_subgrid {
    rt_box b;
    uint32_t first;    /* first of its cells among the grid's sub cells (soff, sleaf) */
    uint32_t ref0;     /* its first reference in srefs */
    uint32_t first16;  /* its first cell offset in the grid's soff16 (first + its index) */
    uint32_t loc0;     /* its first primitive in the grid's sloc (sref16's layout) */
} rt_subgrid;
_Static_assert(sizeof(rt_subgrid) == 2 * RT_LINE && offsetof(rt_subgrid, b.hi) + 24 <= RT_LINE,
               "rt_subgrid: two cache lines, the box's clip in the first");

/* linear index of cell c in box g (x fastest) */
static inline size_t rt_cell_index(const rt_box *g, const int c[3])
{
    return ((size_t)c[2] * (size_t)g->n[1] + (size_t)c[1]) * (size_t)g->n[0] + (size_t)c[0];
}

/* A float leaf (rt_leaf.c): the triangles of one cell list (top-level cell without a
   second level, or second-level cell) as float offsets from an anchor, in structure-of-arrays
   rows of L lanes: row j (vertex j / 3, axis j % 3) at lf + 9 * lane0 + j * L, the
   triangles' primitive indices at lid + lane0. Lanes n .. L-1 repeat lane 0. A float test
   of its lanes (rt_leaf_fn) only rules triangles out; the exact double test decides the rest
   (docs/RAYTRACING.md, "Float leaves"). */
typedef struct rt_leaf {
    double a[3];        /* anchor: the centre of its triangles' box */
    float r;            /* >= max |v - a| (max norm) over its vertices */
    uint32_t n;         /* triangles */
    uint32_t lane0;     /* first lane (a multiple of 4) */
    uint32_t L;         /* lanes (n rounded up to a multiple of 4) */
} rt_leaf;

/* the per-ray, per-leaf data of a float test (rt_leaf.c: rt_fray_leaf) */
typedef struct rt_fray {
    float q[3];         /* fl(anchor - origin) along kx, ky, kz */
    float sx, sy;       /* the ray's shear, rounded to float */
    float ka, kc, kb;   /* error bound of a lane's edge functions: P (ka + kc P) + kb */
    int rx, ry, rz;     /* rows of vertex 0's kx, ky, kz components */
} rt_fray;

/* Writes the lanes (0 .. n-1) of a leaf whose float edge functions do not rule out a hit of
   the exact test into cand, in increasing order; returns their number. */
typedef uint32_t (*rt_leaf_fn)(const float *rows, uint32_t L, uint32_t n, const rt_fray *f,
                               uint32_t *cand);

/* The occupied space's k-DOP (rt_grid.kd_lo, kd_hi): the coordinates of a point (x, y, z) of
   the grid frame along the 4 diagonals of a cell and the 6 diagonals of its faces, written
   for doubles and for GCC's vectors of them (rt_trace.c's four-ray set-up). */
#define RT_KDOP 10
#define RT_KDOP_PROJ(s, x, y, z)                                                           \
    do {                                                                                   \
        const __typeof__(x) kp_xy_ = (x) + (y), kp_xmy_ = (x) - (y);                      \
        (s)[0] = kp_xy_ + (z), (s)[1] = kp_xy_ - (z), (s)[2] = kp_xmy_ + (z),              \
        (s)[3] = kp_xmy_ - (z), (s)[4] = kp_xy_, (s)[5] = kp_xmy_, (s)[6] = (x) + (z),     \
        (s)[7] = (x) - (z), (s)[8] = (y) + (z), (s)[9] = (y) - (z);                        \
    } while (0)

typedef struct rt_grid {
    int rotated;       /* 0: grid axes = VRC3 axes; 1: grid frame p' = R (p - c) */
    int all_opaque;    /* every primitive opaque: transmittance rays stop at the first hit */
    double R[3][3], c[3];
    rt_box b;
    uint32_t *off;     /* ncells + 1 */
    uint32_t *refs;
    size_t ncells, nrefs;
    int32_t *sub;      /* per top cell: sub-grid index or -1; NULL if there are none */
    uint8_t *odist;    /* empty cubes: 8 arrays of ncells, one per octant o of directions
                          (bit a of o set: negative along axis a); cell c's entry in array o
                          is the edge m (in cells, 1 <= m <= RT_CUBE_MAX) of the largest cube
                          of cells without references or a sub-grid that has c as its corner
                          and extends from c in o's directions (cells beyond the box count as
                          empty); an occupied c has RT_CUBE_OCC and what it holds (RT_CUBE_LIST,
                          RT_CUBE_SUB), so the walk loads only the offsets or the sub-grid
                          index it needs */
    /* the k-DOP of the occupied cells: every point of every primitive p (in the grid frame)
       has kd_lo[j] <= s_j(p) <= kd_hi[j], s = RT_KDOP_PROJ(p), with a pad beyond the
       roundings of a ray's clip to it (rt_trace.c: rays that miss it skip the walk, and
       the walk of the others starts and ends at it) */
    double kd_lo[RT_KDOP], kd_hi[RT_KDOP];
    rt_subgrid *subs;
    size_t nsubs;
    /* second-level cell lists, in one of two layouts: soff16 != NULL (every sub-grid has
       at most 65535 references): a sub-grid's cells have their first references at
       srefs + ref0 + soff16[first16 + c], c = 0 .. its cells (the last: its end), 2 B per
       cell; else soff (absolute, sub cells + 1 entries). The references themselves in one
       of two layouts: srefs (4-byte primitive indices), or, on a widened top level's
       sub-grids (rt_build.c, rt_sub_local), sref16 != NULL (soff16 too, srefs NULL): a
       sub-grid's reference j is primitive sloc[loc0 + sref16[ref0 + j]], 2 B per reference
       and 4 B per primitive the sub-grid holds */
    uint32_t *soff;
    uint16_t *soff16;
    uint32_t *srefs;
    uint16_t *sref16;
    uint32_t *sloc;
    size_t nsubcells, nsrefs, nsloc;
    rt_big soff_m, srefs_m; /* the storage of soff (or soff16) and srefs */
    /* float leaves (rt_leaf.c; nearest-hit rays only): per top cell and per second-level
       cell 1 + its leaf's index, 0: the cell's list is tested in double (no list, fewer
       triangles than rt_build_options.leaf_min, or a primitive that is not a triangle).
       NULL: no leaves. */
    uint32_t *tleaf, *sleaf;
    rt_leaf *leaves; size_t nleaves;
    float *lf; uint32_t *lid; size_t nlanes;
    rt_leaf_fn leaf_fn, leaf_fn4; /* the kernels chosen for this CPU (rt_leaf_kernel) ... */
    const char *leaf_name;        /* ... and the name of leaf_fn */
    /* flat sub-grids (rt_build.c, rt_sub_planes; any-hit rays of mesh-only scenes, nearest-hit
       rays of one-mesh scenes through subplane_near): per
       sub-grid 1 + the index of its plane in splanes, 0: none; NULL: no sub-grid is flat */
    uint32_t *subplane;
    struct rt_subplane *splanes; size_t nsplanes;
    /* subplane where the nearest-hit walks skip flat sub-grids too, else NULL (a scene of
       one mesh: its hits are ordered by distance, then by the given order, so the answer
       does not depend on the order of the tests; docs/RAYTRACING.md, "Flat sub-grids") */
    const uint32_t *subplane_near;
} rt_grid;

/* The plane of a flat sub-grid: every vertex v of every triangle it references has
   lo <= n . v <= hi (as computed, rounded outwards). A segment o + t d, t in [tmin, tmax],
   whose ends p0, p1 both have n . p > hi + m or both n . p < lo - m, with the margin
   m = ka S + kb S^3 + 16 u S' (S >= |coordinate| of the scene's vertices and of o, S' >= S
   and those of p0 and p1, u = 2^-53), crosses none of its triangles for the watertight test
   (docs/RAYTRACING.md, "Flat sub-grids"). */
typedef struct rt_subplane {
    double n[3];
    double lo, hi;
    double ka, kb;
} rt_subplane;

/* A segment's values for the test of rt_subplane (rt_flat_beyond): its ends p0 = o + tmin d
   and p1 = o + tmax d as computed, S and S^3 over the scene's scale and the origin, rounded
   up, and the ends' term 16 u S' (0x1p-40 covers the roundings of the maxima and products).
   An infinite or NaN value makes a margin that skips nothing. One computation for the
   single-ray walks (rt_trace.c) and the packets' (rt_packet.c). */
typedef struct rt_flatseg {
    double p0[3], p1[3], S, S3, pe;
} rt_flatseg;

static inline void rt_flatseg_init(rt_flatseg *s, const double o[3], const double d[3],
                                   double tmin, double tmax, double scale)
{
    double S = scale, Sp;
    for (int k = 0; k < 3; k++)
        S = S > fabs(o[k]) ? S : fabs(o[k]);
    Sp = S;
    for (int k = 0; k < 3; k++) {
        s->p0[k] = o[k] + tmin * d[k];
        s->p1[k] = o[k] + tmax * d[k];
        const double e = fabs(s->p0[k]) > fabs(s->p1[k]) ? fabs(s->p0[k]) : fabs(s->p1[k]);
        Sp = Sp > e ? Sp : e;
    }
    s->S = S * (1.0 + 0x1p-40);
    s->S3 = s->S * s->S * s->S * (1.0 + 0x1p-40);
    s->pe = 16.0 * 0x1p-53 * Sp * (1.0 + 0x1p-40);
}

/* 1 when the segment of s lies beyond the slab of plane p by its margin on one side: it
   crosses none of the flat sub-grid's triangles */
static inline int rt_flat_beyond(const rt_subplane *p, const rt_flatseg *s)
{
    const double s0 = p->n[0] * s->p0[0] + p->n[1] * s->p0[1] + p->n[2] * s->p0[2];
    const double s1 = p->n[0] * s->p1[0] + p->n[1] * s->p1[1] + p->n[2] * s->p1[2];
    const double m = p->ka * s->S + p->kb * s->S3 + s->pe;
    const double hi = p->hi + m, lo = p->lo - m;
    return (s0 > hi && s1 > hi) | (s0 < lo && s1 < lo);
}

/* the first reference (in srefs) of cell c of sub-grid k, c = 0 .. its cells (the last: the
   end of its last cell), in either layout of the second level */
static inline uint32_t rt_sub_off(const rt_grid *g, size_t k, size_t c)
{
    const rt_subgrid *sg = &g->subs[k];
    return g->soff16 ? sg->ref0 + g->soff16[sg->first16 + c] : g->soff[sg->first + c];
}

struct rt_scene {
    /* input */
    rt_surface *surf; size_t nsurf, capsurf;
    int (*spair)[2]; size_t nspair, capspair; /* distinct (front, back) surface pairs, and ... */
    uint32_t *spair_hash; size_t spair_hcap;   /* ... their hash table: 1 + index, 0 empty */
    uint32_t spair_last;                       /* the pair found last (consecutive primitives
                                                  mostly share one) */
    rt_light light[RT_MAX_LIGHTS]; int nlights;
    rt_in_prim *in; size_t nin, capin;     /* polygons other than triangles, cell arrays */
    /* triangles (single-loop polygons of 3 vertices) as given, in id order: the committed
       triangles are these (tri == in_tri) unless commit culls (then a copy) */
    rt_big in_tri;                    /* rt_tri, nintri of them */
    size_t nintri;
    rt_big in_tri_prim;               /* rt_prim per triangle, as the commit makes it (made
                                         when the triangle is added; degenerate triangles
                                         are not kept); the committed records are these
                                         (prim == in_tri_prim.p) unless commit culls */
    double tri_bb[6];                 /* box of the input triangles; ... */
    int tri_bb_stale;                 /* ... 1: to be recomputed (after a truncation) */
    size_t nids;                      /* primitive ids handed out (all kinds) */
    double *in_xyz; size_t nxyz, capxyz;
    int *in_loops; size_t nloopsin, caploopsin;
    float *in_rgb; size_t nrgb, caprgb;
    rt_vd *vd; size_t nvd, capvd;     /* smooth areas' vertex data */
    double *vd_xyz; float *vd_n, *vd_c; size_t nvdv, capvdxyz, capvdn, capvdc;
    int *vd_loops; size_t nvdl, capvdl;
    /* indexed meshes, in id order: vertices (double xyz; float unit normals and colours, the
       arrays made when a mesh has them) and triangles (3 global vertex indices each) */
    rt_mesh *mesh; size_t nmesh, capmesh;
    rt_big mv_xyz, mv_n, mv_c; size_t nmv;
    rt_big mtri; size_t nmtri;
    /* The meshes' index words (mtri, ctri) hold each vertex as its element offset 3 v into
       mv_xyz (and mv_n, mv_c), so that a reader's address is the offset scaled by the element
       size, the multiply by 3 done once when the mesh is added. The meshes in spatial order
       (rt_scene_mesh_end): each mesh's index triples sorted, the offset in the low RT_VBITS
       bits of a word and 8 bits of the triangle's given position within its mesh above it
       (rt_ctri_given), for the tie rule's "given first". vmask: the offset bits of a word,
       RT_VMASK while the meshes are sorted, all ones once a mesh beyond the limits was added
       (every mesh in its given order from then on); vlimit: the vertices the scene's meshes
       may have in spatial order, RT_VMASK / 3 + 1 (set lower by a test) */
    uint32_t vmask;
    size_t vlimit;
    int mesh_open;                    /* rt_scene_mesh_begin's reservation at mesh[nmesh] */
    /* committed */
    int committed;
    uint32_t *prim_vd;                /* per committed prim: its rt_vd or RT_NO_VD; NULL
                                         when the scene has no vertex data */
    /* the records of the primitives that are not mesh triangles: those of primitives
       i < ntri_plain at prim[i], those of i >= ntri at prim[i - (ntri - ntri_plain)]
       (rt_prim_at, rt_prim_geo; nprim counts the mesh triangles too) */
    rt_prim *prim; size_t nprim;
    rt_cmesh *cmesh;                  /* per mesh (nmesh): its committed triangles' record */
    rt_tri *tri; size_t ntri;         /* prim index i < ntri: a triangle; i < ntri_plain:
                                         tri[i], else the mesh triangle ctri[i - ntri_plain] */
    int tri_owned;                    /* 1: tri is a culled copy, 0: tri == in_tri */
    size_t ntri_plain;
    uint32_t (*ctri)[3];              /* committed mesh triangles: vertex offsets (3 v into
                                         mv_xyz, the bits of vmask) and given positions
                                         (rt_ctri_given) */
    int ctri_owned;                   /* 1: a compacted copy, 0: ctri == mtri (all kept) */
    int prim_owned;                   /* 1: prim is allocated, 0: prim == in_tri_prim.p */
    rt_quad *quad; size_t nquad;      /* ntri <= i < ntri + nquad: quad[i - ntri] */
    rt_poly *poly; size_t npoly;
    rt_cell *cell; size_t ncell;
    double *uv; size_t nuv;           /* 2-D polygon vertices (pairs) */
    uint32_t *loops; size_t nloops;   /* loop vertex counts of committed polygons */
    size_t *slab_off; size_t nslab_off; /* per polygon slab: first edge in edges */
    double *edges; size_t nedges;     /* RT_EDGE_STRIDE doubles per edge per slab: u0, v0, v1
                                         (v0 < v1) and the differences u1 - u0, v1 - v0 as the
                                         crossing test computed them (rt_isect_poly) */
    rt_pgrid *pgrid;                  /* per polygon (npoly), for those with pgrid != 0 */
    int use_grid;
    rt_grid grid;
    double bbox[6];                   /* lo xyz, hi xyz of kept primitives */
    double scale;                     /* max |coordinate| of the scene box (epsilons) */
    double build_seconds;
    size_t memory_bytes;
    size_t tri_bytes, grid_bytes;     /* parts of memory_bytes (rt_stats) */
};

/* the vertex-offset bits (3 v) of a mesh triangle's index word while the meshes are in
   spatial order (rt_scene.vmask): 5,592,406 vertices in the scene; the 8 bits above hold a
   third of the triangle's given position, 2^24 triangles a mesh */
#define RT_VBITS 24
/* the vertices a scene's meshes may have: every offset 3 v fits in an index word */
#define RT_MAX_MESH_VERTS (UINT32_MAX / 3)
#define RT_VMASK (((uint32_t)1 << RT_VBITS) - 1)
/* a mesh triangle's given position within its mesh, from its index triple ix (meshes in
   spatial order: rt_scene.vmask == RT_VMASK) */
static inline uint32_t rt_ctri_given(const uint32_t ix[3])
{
    return ix[0] >> RT_VBITS | (ix[1] >> RT_VBITS) << 8 | (ix[2] >> RT_VBITS) << 16;
}
/* the given position's bits that word k (0, 1, 2) of a triple holds */
static inline uint32_t rt_ctri_given_bits(uint32_t given, int k)
{
    return (given >> (8 * k) & 0xffu) << RT_VBITS;
}

/* The three vertices of committed triangle primitive i (0 <= i < ntri; a triangle
   primitive's data is its index i): every reader of committed triangle vertices goes through
   this, rt_tri_copy, rt_tri_vert and rt_tri_prefetch, so the vertices' storage is known in
   one place. A plain triangle (i < ntri_plain) holds its 72 bytes itself; a mesh triangle
   holds indices into the shared vertex array, so that triangles sharing an edge use the same
   doubles. */
static inline void rt_tri_verts(const rt_scene *sc, size_t i, const double *v[3])
{
    if (i < sc->ntri_plain) {
        v[0] = sc->tri[i].v[0];
        v[1] = sc->tri[i].v[1];
        v[2] = sc->tri[i].v[2];
        return;
    }
    const uint32_t *ix = sc->ctri[i - sc->ntri_plain], vm = sc->vmask;
    const double *X = sc->mv_xyz.p;
    v[0] = X + (ix[0] & vm);
    v[1] = X + (ix[1] & vm);
    v[2] = X + (ix[2] & vm);
}
/* The nine coordinates of committed triangle primitive i into out (rt_tri_verts' vertices):
   a plain triangle's 72 bytes in one copy, a mesh triangle's three gathered, no loop. */
static inline void rt_tri_copy(const rt_scene *sc, size_t i, double out[9])
{
    if (i < sc->ntri_plain) {
        memcpy(out, sc->tri[i].v, 9 * sizeof(double));
        return;
    }
    const uint32_t *ix = sc->ctri[i - sc->ntri_plain], vm = sc->vmask;
    const double *X = sc->mv_xyz.p;
    memcpy(out, X + (ix[0] & vm), 3 * sizeof(double));
    memcpy(out + 3, X + (ix[1] & vm), 3 * sizeof(double));
    memcpy(out + 6, X + (ix[2] & vm), 3 * sizeof(double));
}
/* Vertex k (0, 1, 2) of committed triangle primitive t (rt_tri_verts). */
static inline const double *rt_tri_vert(const rt_scene *sc, size_t t, int k)
{
    if (t < sc->ntri_plain)
        return sc->tri[t].v[k];
    return (const double *)sc->mv_xyz.p + (sc->ctri[t - sc->ntri_plain][k] & sc->vmask);
}
/* starts loading the vertices of committed triangle t (both cache lines of a plain one's 72
   bytes; a mesh triangle's indices) */
static inline void rt_tri_prefetch(const rt_scene *sc, size_t t)
{
    if (t >= sc->ntri_plain) {
        __builtin_prefetch(sc->ctri[t - sc->ntri_plain]);
        return;
    }
    const char *p = (const char *)&sc->tri[t];
    __builtin_prefetch(p);
    __builtin_prefetch(p + sizeof(rt_tri) - 1);
}

/* the stored record of committed primitive i >= ntri (not a triangle) */
static inline const rt_prim *rt_prim_rest(const rt_scene *sc, size_t i)
{
    return &sc->prim[i - (sc->ntri - sc->ntri_plain)];
}
/* the mesh of committed mesh triangle i (ntri_plain <= i < ntri): its index in sc->mesh and
   sc->cmesh, found by the meshes' ends (one mesh: no search) */
static inline size_t rt_cmesh_of(const rt_scene *sc, size_t i)
{
    size_t lo = 0, hi = sc->nmesh - 1; /* the last mesh ends at ntri */
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (sc->cmesh[mid].end <= i)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}
/* the record of committed mesh triangle i: its mesh's */
static inline const rt_prim *rt_cmesh_rec(const rt_scene *sc, size_t i)
{
    return &sc->cmesh[rt_cmesh_of(sc, i)].rec;
}
/* the stored record of committed primitive i, or a mesh triangle's mesh's (its data is not
   the triangle's: rt_prim_at) */
static inline const rt_prim *rt_prim_rec(const rt_scene *sc, size_t i)
{
    const size_t nmc = sc->ntri - sc->ntri_plain;
    if (i - sc->ntri_plain < nmc)
        return rt_cmesh_rec(sc, i);
    return &sc->prim[i < sc->ntri_plain ? i : i - nmc];
}
/* the record of committed primitive i (a mesh triangle's made from its mesh's) */
static inline rt_prim rt_prim_at(const rt_scene *sc, size_t i)
{
    rt_prim p = *rt_prim_rec(sc, i);
    if (i < sc->ntri)
        p.data = (uint32_t)i;
    return p;
}
/* the kind and data of committed primitive i, what its geometry needs (rt_prim_at's, the
   other fields not set for a triangle: no mesh search) */
static inline rt_prim rt_prim_geo(const rt_scene *sc, size_t i)
{
    if (i < sc->ntri)
        return (rt_prim){.kind = RT_KIND_TRI, .data = (uint32_t)i};
    return *rt_prim_rest(sc, i);
}
/* the user id and the opacity of committed primitive i */
static inline int rt_prim_id(const rt_scene *sc, size_t i) { return rt_prim_rec(sc, i)->id; }
static inline int rt_prim_opaque(const rt_scene *sc, size_t i)
{
    return rt_prim_rec(sc, i)->opaque;
}

/* grows the box bb (lo xyz, hi xyz) by the point p */
static inline void rt_bbox_add(double bb[6], const double p[3])
{
    for (int i = 0; i < 3; i++) {
        if (p[i] < bb[i]) bb[i] = p[i];
        if (p[i] > bb[3 + i]) bb[3 + i] = p[i];
    }
}
/* the surface of side (0 front, 1 back) of primitive p */
static inline const rt_surface *rt_prim_surf(const rt_scene *sc, const rt_prim *p, int side)
{
    return &sc->surf[sc->spair[p->sp][side]];
}

/* ---- traversal (rt_grid.c) ---- */

/* per-ray precomputed data */
typedef struct rt_rayx {
    double o[3], d[3];
    double tmin, tmax;
    int kx, ky, kz;
    double sx, sy, sz;
    uint32_t skip;      /* primitive never hit: the planar one a secondary ray leaves (its origin
                           is moved off the plane, its direction points away); RT_NO_SKIP */
} rt_rayx;

#define RT_NO_SKIP UINT32_MAX

/* Nearest-hit choice between the best hit so far (*best, *bi, its error bound *eb; *bi < 0:
   none) and a hit of primitive i at t (rt_geom.c): hits whose distances are equal within
   their error bound go to the primitive drawn later (docs/RAYTRACING.md, "Coplanar
   surfaces"). A hit beyond *best + 2 * *eb never wins (the caller's search bound). */
void rt_nearest_update(const rt_scene *sc, const rt_rayx *r, uint32_t i, double t, double *best,
                       long *bi, double *eb);

/* The part of a hit's error bound (rt_nearest_update) that depends on triangle primitive i
   alone, computed once for the rays of a packet that hit it: its cross product scaled by the
   largest component (x, y, z), that vector's length nrm, and the largest vertex coordinate
   magnitude vmax; ok = 0 for a degenerate cross product (the general bound is taken). */
typedef struct rt_tri_err {
    double x, y, z, nrm, vmax;
    int ok;
} rt_tri_err;
void rt_tri_err_init(const rt_scene *sc, uint32_t i, rt_tri_err *q);
/* rt_nearest_update for triangle primitive i with q from rt_tri_err_init: the same choice and
   values, bit for bit */
void rt_nearest_update_tri(const rt_scene *sc, const rt_rayx *r, uint32_t i, double t,
                           const rt_tri_err *q, double *best, long *bi, double *eb);

/* a ray in the grid frame (traversal only; primitive tests use the rt_rayx) */
typedef struct rt_gray {
    double o[3], d[3], invd[3];
} rt_gray;

/* point / direction into the grid frame */
void rt_grid_point(const rt_grid *g, const double p[3], double out[3]);
void rt_grid_dir(const rt_grid *g, const double v[3], double out[3]);

/* per-thread traversal context: mailbox */
#define RT_HBOX 256 /* entries of the small mailbox (power of 2) */

typedef struct rt_ctx {
    uint32_t *mbox;     /* exact mailbox, nprim entries (NULL in the batch API's contexts:
                           nearest-hit and any-hit rays only) */
    uint64_t *hbox;     /* small direct-mapped mailbox: (stamp << 32 | prim) at prim % RT_HBOX */
    uint32_t stamp;
    size_t nprim;
    long blocker;       /* set by rt_trace_transmit when blocked by an opaque primitive */
    int beside;         /* the last nearest-hit packet had no ray in the grid box
                           (rt_packet.c: the next one tries rt_pk_beside) */
} rt_ctx;

int rt_ctx_init(rt_ctx *c, const rt_scene *sc);
void rt_ctx_free(rt_ctx *c);
/* the checks of a batch call (sc, and rays and out when n > 0: RT_ERR_ARG; sc committed:
   RT_ERR_STATE) and its context: the small mailbox only (RT_ERR_NOMEM) */
int rt_batch_begin(const rt_scene *sc, size_t n, const rt_ray *rays, const void *out, rt_ctx *c);

/* 0 if the ray is unusable (non-finite, zero direction, NaN range). r->skip = RT_NO_SKIP. */
int rt_rayx_setup(rt_rayx *r, const double o[3], const double d[3], double tmin, double tmax);
/* rt_rayx_setup for r whose o, d, tmin and tmax are already what rt_rayx_setup would make
   of them (d's components below 1e-150 of the largest flushed to 0): its checks and shear */
int rt_rayx_setup_made(rt_rayx *r);

/* nearest hit: returns internal prim index or -1; *t set. side of hit in *side. */
long rt_trace_nearest(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, double *t);
/* nearest hit among the primitives ids[0..n-1] only (a superset of those the ray can hit:
   then the same answer as rt_trace_nearest), as rt_trace_nearest returns it */
long rt_trace_list(const rt_scene *sc, const rt_rayx *r, const uint32_t *ids, size_t n,
                   double *t);
/* transmittance along the ray: product of kt of the surfaces hit; 0 = blocked.
 * any_hit = 1: 0 on the first hit regardless of transparency. */
double rt_trace_transmit(const rt_scene *sc, rt_ctx *c, const rt_rayx *r, int any_hit);
/* the same over the primitives ids[0..n-1] only, a superset of those the ray can hit, in
   order of zb[id] and up to the first zb[id] > zbo (a light buffer's list, rt_lbuf_find) */
double rt_trace_transmit_list(const rt_scene *sc, rt_ctx *c, const rt_rayx *r,
                              const uint32_t *ids, uint32_t n, const uint16_t *zb, uint32_t zbo);
/* rt_occluded's answers for rays[0..n-1] in context c (a batch context: its small mailbox) */
void rt_occluded_rays(const rt_scene *sc, rt_ctx *c, size_t n, const rt_ray *rays,
                      unsigned char *occluded);
/* 1 if the ray hits internal primitive i within its range */
int rt_hits_prim(const rt_scene *sc, const rt_rayx *r, long i);

/* float leaves (rt_leaf.c), built after the grid: RT_OK or RT_ERR_NOMEM; and their bytes */
int rt_leaves_build(const rt_scene *sc, rt_grid *g, int leaf_min);
/* the smallest leaf rt_leaves_build(.., leaf_min) takes: leaf_min, or GKS_RT_LEAF_MIN's when
   it is 0; no leaves when it is not above 0 */
int rt_leaves_min(int leaf_min);
size_t rt_leaves_bytes(const rt_grid *g);
void rt_leaves_free(rt_grid *g);
/* The widest SIMD level this CPU runs and GKS_RT_SIMD (scalar, sse, avx2) allows: 0 scalar,
 * 1 SSE2, 2 AVX2, 3 AVX-512 (F, VL and DQ); the float leaves, the packet path and the batch
 * set-up choose their kernels by it (a kernel a level lacks is the next narrower one's). */
int rt_simd_level(void);
/* the kernel of the float test for this CPU, or the one GKS_RT_SIMD forces ("scalar", "sse",
   "avx2": no wider than the CPU has), and its name; *fn4 the one for leaves of 4 lanes */
rt_leaf_fn rt_leaf_kernel(const char **name, rt_leaf_fn *fn4);

/* the float test's range: S (rt_leaf.c) within [RT_FS_MIN, RT_FS_MAX] keeps the bound's
   terms normal floats and P^2 (at most 4 S^2) finite */
#define RT_FS_MIN 1e-12
#define RT_FS_MAX 1e15
/* the float test's data for ray r and leaf lf: 1, or 0 when the leaf's and the ray's scale S
   leaves the bound's range (then every lane is a candidate). The bound: rt_leaf.c. */
static inline int rt_fray_leaf(const rt_rayx *r, const rt_leaf *lf, rt_fray *f)
{
    const double qx = lf->a[r->kx] - r->o[r->kx], qy = lf->a[r->ky] - r->o[r->ky],
                 qz = lf->a[r->kz] - r->o[r->kz];
    const double ax = fabs(qx), ay = fabs(qy), az = fabs(qz);
    const double Q = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
    const double S = (Q + (double)lf->r) * (1.0 + 0x1p-20);
    if (!(S >= RT_FS_MIN && S <= RT_FS_MAX))
        return 0;
    const double u = 0x1p-24, e1 = 8.5 * u * S;
    f->q[0] = (float)qx;
    f->q[1] = (float)qy;
    f->q[2] = (float)qz;
    f->sx = (float)r->sx;
    f->sy = (float)r->sy;
    f->ka = (float)(1.01 * 4.0 * e1);
    f->kc = (float)(1.01 * 4.0001 * u);
    f->kb = (float)(1.01 * 2.0 * e1 * e1 + 1e-36);
    f->rx = r->kx;
    f->ry = r->ky;
    f->rz = r->kz;
    return 1;
}

/* grid build (rt_grid.c) */
int rt_grid_build(rt_scene *sc, const rt_build_options *o);
void rt_grid_free(rt_grid *g);
/* for tests (rt_build.c): the cells whose triangle/box test the build's margin filters left
   to the exact test (a process total), and the filters switched on (1, the default) or off (0:
   every cell through the exact test; the grid is the same either way) */
uint64_t rt_build_exact_cells(void);
void rt_build_set_filter(int on);
/* the most cells per axis of the triangle ranges that the build's filters take at once */
enum { RT_BUILD_SPAN = 32 };
/* for tests (rt_build.c): the build's edge filter (rt_edge_filter) and the slab path's masks
   (rt_slab_masks) in their plain C forms (form 0: what targets without SSE2 run) or as the
   build runs them (form 1: SSE2 where compiled), so that a test compares the two bit for bit.
   rt_build_edge_filter: cv the terms of the cell on P, cw those of the cell on Q (rt_axis_cell
   there); 1 separates, 0 keeps, -1 undecided. rt_build_slab_masks: cvT[i][np] must be
   defined; sepm, undm written for the rows not in outq (bits np and above arbitrary). */
int rt_build_edge_filter(int form, const double ro[3], const double ri[3], const double cv[3],
                         const double cw[3]);
void rt_build_slab_masks(int form, const double (*cvT)[RT_BUILD_SPAN + 1], int np,
                         const double (*cw)[3], int nq, uint32_t outq, const double ro[3],
                         const double ri[3], uint32_t *sepm, uint32_t *undm);
/* the k-th smallest (from 0) of the n values r, the value r[k] has once r is sorted (r may be
   reordered; rt_build.c, the top level's median extent) */
double rt_kth_smallest(double *r, size_t n, size_t k);
/* for tests (rt_build.c): the smallest chunk of the second level's dynamic parts, in
   references (0: the default), and the chunks part 0 takes at most (0: no limit); the grid is
   the same whatever the chunks are. The chunks taken from the back (a process total). */
void rt_build_set_chunks(size_t min_refs, int front_max);
uint64_t rt_build_back_chunks(void);
/* the vertices of committed primitive i: their number, and vertex k as traced (polygon
   vertices projected onto the polygon's plane; the 4 corners of a cell array) */
size_t rt_prim_nverts(const rt_scene *sc, size_t i);
void rt_prim_vertex(const rt_scene *sc, size_t i, size_t k, double out[3]);

/* ---- light buffers (rt_lbuf.c) ---- */
typedef struct rt_lbuf {
    int ok;                   /* 0: none (the light's shadow rays walk the grid) */
    int ortho;                /* directional light: projection along ez */
    double L[3];              /* light position (ortho: scene box centre) */
    double ex[3], ey[3], ez[3];
    double exy[3][2];         /* (ex[k], ey[k]): u and v in two lanes (rt_lbuf_find_at) */
    double u0, v0, su, sv;    /* cell of plane point (u, v): ((u - u0) su, (v - v0) sv) */
    int nu, nv;
    double slack, kdev, zeps; /* query margin: slack + 2 kdev * (light's distance from ray) */
    double zlo, zscale;       /* depth bucket of z: (z - zlo) * zscale, clamped */
    uint32_t *off, *ids;      /* cell lists (nu * nv + 1 offsets), in order of zb */
    uint16_t *zb;             /* per primitive: bucket of its nearest depth (less zeps) */
    float *edge;              /* per primitive 4 lines (a, b, c) on the plane, (a, b) unit:
                                 a u + b v + c >= 0 holds on its projection (rt_lbuf_query) */
    double emargin;           /* the lines' margin: the build's and their float rounding */
} rt_lbuf;

/* A shadow ray's place in a light buffer (rt_lbuf_query): its cell's list ids[0..n-1], the
   depth bucket zb of its origin, its footprint's centre (u, v) and the bound -thr below
   which a primitive's line at (u, v) shows that the ray surely misses it (float: the lines'
   arithmetic) */
typedef struct rt_lbuf_q {
    const uint32_t *ids;
    uint32_t n, zb;
    float u, v, thr;
} rt_lbuf_q;

/* builds the buffer of light l; lb->ok = 0 (RT_OK) when the light gets none; RT_ERR_NOMEM */
int rt_lbuf_build(const rt_scene *sc, const rt_light *l, int threads, rt_lbuf *lb);
/* the same without the primitives i with omit[i] != 0 in its lists (omit NULL: none), with
   the lines for rt_lbuf_next when lines != 0 (edge NULL otherwise: rt_lbuf_find(_z) only) */
int rt_lbuf_build_omit(const rt_scene *sc, const rt_light *l, const uint8_t *omit, int lines,
                       int threads, rt_lbuf *lb);
void rt_lbuf_free(rt_lbuf *lb);
/* the candidates of a shadow ray toward lb's light: 1 with the list ids[0..n-1] and the
   bucket zb of the ray origin's depth (entries of a later bucket lie beyond the origin: they
   cannot be hit), 0 if no primitive can be hit, -1 if the ray must walk the grid */
int rt_lbuf_find(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n,
                 uint32_t *zb);
/* rt_lbuf_find with the footprint kept in *q (q->ids, n, zb as rt_lbuf_find's); when it
   returns 1, *k0 the first candidate from position 0 on that rt_lbuf_next finds and whose
   plane test does not reject r (a quad's or polygon's, rt_prim_plane_t, with the values of
   its exact test: r's o, d, tmin and tmax as rt_rayx_setup makes them), q->n when there is
   none (rt_lbuf.h: the same inline, rt_lbuf_query_at) */
int rt_lbuf_query(const rt_scene *sc, const rt_lbuf *lb, const rt_rayx *r, uint32_t skip,
                  rt_lbuf_q *q, uint32_t *k0);
/* the position of the next candidate of q's list from position k on, up to its bucket zb, but
   skip, that the ray can hit (whose projection q's footprint does not surely miss); q->n
   when there is none */
uint32_t rt_lbuf_next(const rt_lbuf *lb, const rt_lbuf_q *q, uint32_t skip, uint32_t k);
/* the transmittance of shadow ray r over the candidates of q that rt_lbuf_next finds from
   position k on (the ones it can hit, in list order), as rt_trace_transmit_list gives it
   over the whole list: the product of the transparencies of the sides hit, 0 at the first
   opaque primitive hit (*blocker: it; -1 otherwise) */
double rt_lbuf_transmit(const rt_scene *sc, const rt_lbuf *lb, const rt_lbuf_q *q,
                        const rt_rayx *r, uint32_t k, long *blocker);
/* the same with *z the depth of the ray's origin (along ez from L) instead of its bucket */
int rt_lbuf_find_z(const rt_lbuf *lb, const rt_rayx *r, const uint32_t **ids, uint32_t *n,
                   double *z);

/* ---- smooth areas (rt_smooth.c) ---- */
/* Interpolation at point P of committed primitive i (front normal ng): 0 if i has no vertex
 * data. Otherwise bit 1: n (unit, front side) is the interpolated normal, ps Hanika's
 * shadow point (= P where it would lie below the plane); bit 2: rgb the interpolated colour. */
int rt_smooth_at(const rt_scene *sc, size_t i, const double P[3], const double ng[3],
                 double n[3], double ps[3], double rgb[3]);

/* cell array colour at point p (on the plane) */
void rt_cell_color(const rt_scene *sc, const rt_cell *c, const double p[3], double rgb[3]);

double rt_now(void);

/* ---- primary rays by raster row and column (rt_camera.c) ---- */

/* rt_camera_ray(cam, px, py) == rt_camera_rays_row of rt_camera_xterm(px) and
 * rt_camera_yterm(py), bit for bit: the x terms can be computed once per raster column, the y
 * terms once per row. px, py must be finite. */
void rt_camera_xterm(const rt_camera *cam, double px, double xt[4]);
void rt_camera_yterm(const rt_camera *cam, double py, double yt[4]);
/* The rays of the n <= RT_CAM_ROW raster points (xt[i], yt) (unusable where ok[i] == 0),
 * computed together (vector divisions). */
#define RT_CAM_ROW 16
void rt_camera_rays_row(const rt_camera *cam, const double (*xt)[4], int n, const double yt[4],
                        rt_ray *ray, int *ok);
/* The view mapping (inverse of cam->minv) and the sign of w in front of the eye plane; 0 if
 * not usable. */
int rt_camera_vmap(const rt_camera *cam, double vm[4][4], double *wsign);
/* Raster position (as rt_camera_ray takes it) of the VRC3 point p: 1, or 0 if p is not in
 * front of the eye plane by a margin (its projection would not bound the rays through it). */
int rt_camera_project(const rt_camera *cam, const double vm[4][4], double wsign, const double p[3],
                      double *px, double *py);

#endif
