/* SPDX-License-Identifier: MIT */
/*
 * scene_io.h -- reader of scene files for the examples and benchmarks (target scene_io).
 *
 * Reads, into one neutral in-memory scene:
 *   - NFF, Eric Haines' Neutral File Format (the SPD scenes):
 *       v            view block: from x y z / at x y z / up x y z / angle deg / hither d /
 *                    resolution w h (the six lines in any order, all required)
 *       b r g b      background colour
 *       l x y z [r g b]   positional light (colour defaults to white)
 *       f r g b Kd Ks Shine T index   material of the following primitives
 *       p n          polygon, n vertex lines "x y z" follow (kept exactly as given)
 *       pp n         polygonal patch, n vertex lines "x y z nx ny nz" follow
 *       s x y z r    sphere            } no such primitives in GKS: tessellated into polygons
 *       c  + 2 lines "x y z radius" (base, apex): open cone } (options.tessellate > 0) or
 *                                                         skipped with one warning
 *       # ...        comment to the end of the line
 *   - OFF (ASCII): "OFF" header line (also COFF/NOFF/CNOFF; per-vertex extras ignored),
 *     "nv nf ne", nv vertex lines, nf face lines "n i0 .. in-1 [colour]".
 *   - PLY (ASCII 1.0): element "vertex" with scalar properties x, y, z (others skipped),
 *     element "face" with a list property "vertex_indices" (or "vertex_index"); other
 *     elements are skipped. Binary PLY is rejected with a message.
 * All formats are read line by line: each entity, vertex and face on its own line (as the
 * SPD generators and mesh tools write them), no extra fields (OFF vertex/face lines may carry
 * extras). Numbers must be finite; NFF colours and "f" values must be >= 0.
 * Any of them may be gzip-compressed (read through zlib; plain files are read as they are).
 * OFF and PLY polygons get material 0 (white, Kd 1); they have no view and no lights.
 *
 * Untrusted input: every malformed item gives an error return and a message
 * "file:line: what" (NaN/Inf/overflowing numbers, missing or extra fields, counts larger than
 * the rest of the file can hold, indices out of range, polygons with < 3 vertices, binary or
 * truncated files, more than UINT32_MAX vertices or INT_MAX polygons/vertices per polygon).
 * Allocation never follows a declared count further than the remaining input can justify.
 *
 * No GKS header is included: the scene can feed the GKS-3D binding (examples/c/nff_view.c)
 * or the ray tracer directly (bench/). Not thread-safe per scene; no global state.
 */
#ifndef GKS3D_SCENE_IO_H
#define GKS3D_SCENE_IO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Return codes. */
enum {
    SCENE_IO_OK = 0,
    SCENE_IO_ERR_ARG = -1,    /* NULL argument, unknown format */
    SCENE_IO_ERR_OPEN = -2,   /* file cannot be opened / read / decompressed */
    SCENE_IO_ERR_SYNTAX = -3, /* malformed content (message has file:line) */
    SCENE_IO_ERR_NOMEM = -4,  /* allocation failed or size overflow */
    SCENE_IO_ERR_LIMIT = -5   /* input larger than options.max_bytes or the index types hold */
};

typedef enum {
    SCENE_IO_AUTO = 0, /* by content: "OFF"/"COFF"/... first word -> OFF, "ply" -> PLY, else NFF */
    SCENE_IO_NFF = 1,
    SCENE_IO_OFF = 2,
    SCENE_IO_PLY = 3
} scene_io_format;

/* NFF "f": colour and the Whitted coefficients, exactly as in the file (all finite, >= 0;
 * NFF files use index 0 for opaque surfaces: keep it, the consumer decides). */
typedef struct scene_io_material {
    double color[3];   /* r g b */
    double kd;         /* diffuse coefficient */
    double ks;         /* specular coefficient = mirror reflection weight */
    double shine;      /* Phong exponent */
    double t;          /* transmittance (0 = opaque) */
    double ior;        /* index of refraction */
} scene_io_material;

/* NFF "l": positional light. */
typedef struct scene_io_light {
    double pos[3];
    double color[3];   /* (1,1,1) when the file gives none */
    int has_color;
} scene_io_light;

/* NFF "v" block. present = 0 when the file has none (OFF, PLY, NFF without v). */
typedef struct scene_io_view {
    int present;
    double from[3], at[3], up[3]; /* eye, look-at point, up vector (not parallel to at-from) */
    double angle;      /* full field of view in degrees, 0 < angle < 180 (NFF: horizontal
                          and vertical; the reader does not reinterpret it) */
    double hither;     /* distance of the near plane from the eye, > 0 */
    int res_x, res_y;  /* image resolution, 1..65536 each */
} scene_io_view;

/* The scene: flat arrays. Polygon i has poly_nverts[i] >= 3 vertices whose indices are
 * poly_verts[poly_start[i] .. poly_start[i] + poly_nverts[i] - 1] (poly_start has
 * num_polygons + 1 entries; poly_start[num_polygons] = number of indices), and material
 * poly_material[i] (< num_materials). NFF polygons get their own vertices (no sharing),
 * in file order; OFF/PLY faces share the file's vertices. */
typedef struct scene_io_scene {
    scene_io_format format;      /* format actually read */
    scene_io_view view;
    double background[3];        /* NFF "b"; (0,0,0) when absent */
    int has_background;

    size_t num_lights;
    scene_io_light *lights;
    size_t num_materials;        /* >= 1 once any polygon exists (a default material 0,
                                    white, Kd 1, is created for primitives before any "f") */
    scene_io_material *materials;

    size_t num_vertices;         /* <= UINT32_MAX */
    double *vertices;            /* 3 * num_vertices: x y z */
    double *normals;             /* NULL, or 3 * num_vertices: the "pp" vertex normals as
                                    given (not normalised); (0,0,0) for vertices without one */
    size_t num_polygons;         /* <= INT_MAX */
    int *poly_nverts;            /* num_polygons */
    size_t *poly_start;          /* num_polygons + 1 */
    uint32_t *poly_verts;        /* poly_start[num_polygons] vertex indices */
    uint32_t *poly_material;     /* num_polygons */

    size_t num_spheres, num_cones; /* NFF "s"/"c" seen (tessellated or skipped) */
    size_t num_patches;          /* NFF "pp" read */
} scene_io_scene;

/* Warning sink (NULL = warnings dropped; the counts in the scene still say what happened). */
typedef void (*scene_io_warn_fn)(void *ctx, const char *msg);

typedef struct scene_io_options {
    int tessellate;      /* > 0: "s" and "c" become polygons with this many segments around
                            (clamped to 3..1024): spheres in tessellate/2 bands, triangles at
                            the poles and planar quads between; open cones as quads (triangles
                            where a radius is 0); outward-facing (counter-clockwise seen from
                            outside) with exact vertex normals. 0: skipped, one warning per kind. */
    size_t max_bytes;    /* largest (decompressed) input accepted; 0 = 1 GiB */
    scene_io_warn_fn warn;
    void *warn_ctx;
} scene_io_options;

/* Fills o with the defaults: tessellate 0 (skip with warning), max_bytes 1 GiB, no sink. */
void scene_io_options_default(scene_io_options *o);

/* Reads the file at path (gzip or plain) in format fmt (SCENE_IO_AUTO: by content) into *s
 * (overwritten; freed on error, so scene_io_free is always safe afterwards). opt may be NULL
 * (defaults). On error, err (if not NULL) receives a NUL-terminated message of at most
 * err_size bytes, "path:line: what" for content errors. Returns SCENE_IO_OK or SCENE_IO_ERR_*. */
int scene_io_load(const char *path, scene_io_format fmt, const scene_io_options *opt,
                  scene_io_scene *s, char *err, size_t err_size);

/* Same from a memory buffer of len bytes (need not be NUL-terminated, not gzip); name is used
 * in messages (NULL: "<memory>"). */
int scene_io_parse(const char *data, size_t len, const char *name, scene_io_format fmt,
                   const scene_io_options *opt, scene_io_scene *s, char *err, size_t err_size);

/* Frees the arrays of *s and zeroes it (NULL allowed; a zeroed scene allowed). */
void scene_io_free(scene_io_scene *s);

/* Axis-aligned bounding box of the vertices used by polygons. Returns 1, or 0 when the scene
 * has no polygon (lo/hi then untouched). */
int scene_io_bounds(const scene_io_scene *s, double lo[3], double hi[3]);

/* Vertex normals computed from the faces (replacing s->normals): each polygon's Newell
 * normal added to its vertices, weighted by the polygon's area (angle_weighted 0) or, unit
 * length, by the polygon's angle at the vertex (angle_weighted 1: Thuermer and Wuethrich
 * 1998, independent of how a surface is cut into polygons), then normalised; (0,0,0) where
 * they cancel. Shared vertices (OFF, PLY) get smooth normals across their faces, creases
 * included. Returns SCENE_IO_OK, SCENE_IO_ERR_ARG (NULL), SCENE_IO_ERR_NOMEM. */
int scene_io_vertex_normals(scene_io_scene *s, int angle_weighted);

/* A default camera for scenes without a view (meshes): up = +y, looking at the bounding-box
 * centre from the direction (0.6, 0.5, 1) (front, above, right), at the distance at which
 * the bounding sphere just fills the angle-degree field of view; hither at 1/100 of that
 * distance. v->present is set to 1. Returns SCENE_IO_OK or SCENE_IO_ERR_ARG (empty scene,
 * res outside 1..65536, angle outside (0,180)). */
int scene_io_frame_view(const scene_io_scene *s, double angle, int res_x, int res_y,
                        scene_io_view *v);

/* "NFF", "OFF", "PLY" or "auto". */
const char *scene_io_format_name(scene_io_format fmt);

#ifdef __cplusplus
}
#endif
#endif /* GKS3D_SCENE_IO_H */
