/* SPDX-License-Identifier: MIT */
/*
 * raster.h -- the raster module of the PNG workstation (internal, not installed).
 *
 * Draws primitives that the workstation driver has already transformed to device
 * coordinates (DC), clipped and given resolved attributes (RGB colours in [0,1]).
 * It knows nothing about GKS state.
 *
 * Conventions
 *  - DC: pixel units of the OUTPUT image, double precision; x right, y UP, y = 0 at the
 *    bottom edge; pixel (i, j) covers [i, i+1) x [j, j+1), its centre is (i+.5, j+.5).
 *    z in [0, 1], LARGER z = NEARER the viewer.
 *  - Coverage: a pixel (sub-pixel when supersampling) is covered iff its centre is inside
 *    the area by the even-odd rule. A centre exactly on an edge belongs to the area on its
 *    right (crossings x <= centre count), a centre exactly on a horizontal edge to the area
 *    above it (half-open [ymin, ymax) rule). Two areas sharing an edge therefore never both
 *    cover or both miss a pixel (triangles, polygons and cell arrays use the same rule).
 *  - Depth (zmode): NONE draws colour only; TEST draws colour where z + zbias >= zbuf
 *    and then sets zbuf = max(zbuf, z) (so later primitives win ties, as in painter
 *    order); ONLY does the same test and depth write but no colour (hidden-line pass).
 *  - Anti-aliasing: a framebuffer created with ss = 2..4 stores ss*width x ss*height
 *    samples; all coordinates, widths, sizes and hatch spacings stay in output pixels;
 *    output (resolve / PNG) is the box-filtered mean of each ss x ss block.
 *  - Errors: functions return GKS_RASTER_OK (0) or a gks_raster_status; hostile input
 *    (NaN/Inf, negative counts, NULL) is rejected before anything is drawn.
 *  - Allocation goes through the library funnel gks_alloc_array / gks_free (gks_alloc.h).
 */
#ifndef GKS_RASTER_H
#define GKS_RASTER_H
#include "gks_private.h"
#include <stddef.h>

typedef enum gks_raster_status {
    GKS_RASTER_OK = 0,
    GKS_RASTER_E_ARG = 1,    /* invalid argument: NULL, count, NaN/Inf, unknown type */
    GKS_RASTER_E_NOMEM = 2,  /* allocation failed or size overflow */
    GKS_RASTER_E_IO = 3,     /* file cannot be opened, written or read */
    GKS_RASTER_E_FORMAT = 4  /* file is not a PNG the reader understands */
} gks_raster_status;

typedef enum gks_raster_zmode {
    GKS_RASTER_Z_NONE = 0,   /* no depth test, colour only (painter / HLHSR none) */
    GKS_RASTER_Z_TEST = 1,   /* depth test and write, colour */
    GKS_RASTER_Z_ONLY = 2    /* depth test and write, no colour (hidden-line pass) */
} gks_raster_zmode;

/* A DC point; same layout as Gpoint3. */
typedef struct gks_raster_pt { double x, y, z; } gks_raster_pt;

/* Framebuffer. Colour is float RGB: supersampling averages and the tracer's float output
 * need more than 8 bits until the final PNG, and 12 B/pixel is cheap at workstation
 * sizes. Rows are stored bottom-up (row 0 = DC y in [0,1)), w*h samples. */
typedef struct gks_raster_fb {
    int width, height;  /* output image size in pixels */
    int ss;             /* supersampling factor 1..4 */
    int w, h;           /* sample grid size: ss*width, ss*height */
    float *rgb;         /* 3*w*h floats, sample (i, j) at rgb[3*((size_t)j*w + i)] */
    float *z;           /* w*h floats, cleared to -INFINITY (farthest) */
} gks_raster_fb;

/* Create a width x height framebuffer (1 <= width, height <= 65536, ss 1..4), cleared to
 * black and farthest depth. NULL on bad arguments or when memory is exhausted. */
gks_raster_fb *gks_raster_fb_create(int width, int height, int ss);
/* The same framebuffer with its samples not yet written (for a caller that clears it
 * itself, e.g. in parts by gks_raster_fb_clear_rows: the clear is then its first touch). */
gks_raster_fb *gks_raster_fb_alloc(int width, int height, int ss);
/* Free a framebuffer (NULL is ignored). */
void gks_raster_fb_free(gks_raster_fb *fb);
/* Clear colour to rgb (components clamped to [0,1]; NULL = black) and depth to farthest. */
void gks_raster_fb_clear(gks_raster_fb *fb, const float rgb[3]);
/* The same for the sample rows [y0, y1) only (0 <= y0 <= y1 <= h; others are ignored), so
 * that parts of the rows can be cleared on several threads with the same result. */
void gks_raster_fb_clear_rows(gks_raster_fb *fb, const float rgb[3], int y0, int y1);
/* Box-filter one image row (0 = top) to 8-bit RGB: 3*width bytes to out. E_ARG on NULL or
 * a bad row. */
int gks_raster_fb_resolve_row(const gks_raster_fb *fb, int row, unsigned char *out);

/* --- Areas ---------------------------------------------------------------------- */
typedef enum gks_raster_style {
    GKS_RASTER_SOLID = 0,
    GKS_RASTER_HATCH = 1,
    GKS_RASTER_PATTERN = 2
} gks_raster_style;

/* Hatch styles (value of gks_raster_fill.hatch; GKS negative hatch indices): lines one
 * output pixel wide every GKS_RASTER_HATCH_SPACING output pixels (-1..-6), or every
 * GKS_RASTER_HATCH_SPACING/2 pixels (-7..-12, same order). Pixels between hatch lines
 * are left untouched (colour and depth). */
#define GKS_RASTER_HATCH_SPACING 8
enum {
    GKS_RASTER_HATCH_HORIZONTAL = -1,
    GKS_RASTER_HATCH_VERTICAL = -2,
    GKS_RASTER_HATCH_UP45 = -3,        /* +45 degrees: rising to the right */
    GKS_RASTER_HATCH_DOWN45 = -4,      /* -45 degrees */
    GKS_RASTER_HATCH_CROSS = -5,       /* horizontal + vertical */
    GKS_RASTER_HATCH_DIAGCROSS = -6,   /* +45 + -45 */
    GKS_RASTER_HATCH_LAST = -12
};

/* Interior of an area (HOLLOW is the caller's: it strokes the boundary). Pattern: pat_rgb holds pat_nx*pat_ny RGB triples, cell (i, j) at
 * pat_rgb[3*(j*pat_nx + i)]; cell (0, 0) has its corner at pat_ref and spans pat_u
 * (i direction) and pat_v (j direction), all in DC; tiled, nearest neighbour. */
typedef struct gks_raster_fill {
    gks_raster_style style;
    float rgb[3];              /* SOLID and HATCH colour */
    int hatch;                 /* HATCH: -1 .. -12 */
    int pat_nx, pat_ny;        /* PATTERN */
    const float *pat_rgb;
    double pat_ref[2], pat_u[2], pat_v[2];
    gks_raster_zmode zmode;
    float zbias;               /* >= 0, added to z in the depth test only */
} gks_raster_fill;

/* FILL AREA 3 / FILL AREA SET 3: fill n_loops closed loops (counts[k] points each,
 * stored one after another in pts) by the even-odd rule. Depth is taken from the plane
 * through the vertices' centroid with the Newell normal (best-fit plane for slightly
 * non-planar polygons), clamped to the vertices' z range. Loops with fewer than 3
 * points add nothing. E_ARG: NULL, n_loops < 1, a count < 0, a non-finite coordinate,
 * a bad fill; E_NOMEM. */
int gks_raster_fill_area(gks_raster_fb *fb, int n_loops, const int *counts,
                         const gks_raster_pt *pts, const gks_raster_fill *fill);

/* Fast path: n triangles (pts[3k..3k+2]), same coverage and depth rule as
 * gks_raster_fill_area (depth from the triangle's plane; SSE2/AVX2 depth test).
 * rgb: NULL to use fill->rgb, else one RGB triple per triangle (replaces fill->rgb).
 * E_ARG (nothing drawn) on NULL, a bad fill or any non-finite coordinate; no E_NOMEM. */
int gks_raster_triangles(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                         const float *rgb, const gks_raster_fill *fill);

/* Smooth areas (interior shading methods COLOUR and NORMAL): per-vertex attributes, n
 * floats per point (3 <= n <= GKS_RASTER_VATTR_MAX), interpolated perspective-correct (with
 * the vertices' 1/w, w their homogeneous clip coordinate: attribute/w and 1/w are linear in
 * the screen). A sample's colour is shade(user, attributes) when shade is set, else the first
 * three attributes; clamped to [0,1]. */
#define GKS_RASTER_VATTR_MAX 12
typedef void (*gks_raster_shade_fn)(void *user, const float *attr, float rgb[3]);
typedef struct gks_raster_vattr {
    int n;
    const float *v;            /* n per point */
    const double *invw;        /* 1/w per point, > 0 */
    gks_raster_shade_fn shade; /* NULL: attributes 0..2 are the colour */
    void *user;
} gks_raster_vattr;

/* One CONVEX loop of n points (fan from point 0), coverage and depth as
 * gks_raster_fill_area's triangles; fill supplies zmode and zbias and must be SOLID.
 * E_ARG on NULL, n < 3, a bad attribute description, non-finite points or 1/w <= 0. */
int gks_raster_fill_smooth(gks_raster_fb *fb, int n, const gks_raster_pt *pts,
                           const gks_raster_vattr *va, const gks_raster_fill *fill);

/* CELL ARRAY 3 (after projection): the parallelogram with corner o, i-direction edge
 * o->pu and j-direction edge o->pv is divided into nx x ny cells; cell (i, j) has
 * colour rgb[3*(j*nx + i)] and covers o + [i/nx,(i+1)/nx](pu-o) + [j/ny,(j+1)/ny](pv-o).
 * Each covered pixel takes the colour of the cell containing its centre; the depth
 * plane is that of o, pu, pv. fill supplies zmode and zbias only (NULL = no depth).
 * E_ARG on NULL, nx or ny < 1, non-finite corner; a degenerate parallelogram draws
 * nothing; never E_NOMEM. (GKS-3D's P, Q, R map to o, pu, pv by the caller.) */
int gks_raster_cell_array(gks_raster_fb *fb, const gks_raster_pt *o,
                          const gks_raster_pt *pu, const gks_raster_pt *pv,
                          int nx, int ny, const float *rgb, const gks_raster_fill *fill);

/* CELL ARRAY 3 restricted to an area: as gks_raster_cell_array (same o, pu, pv, cells,
 * depth plane and zmode), but only the samples inside the even-odd interior of the
 * n_loops loops (counts[k] points each, DC, e.g. the parallelogram clipped by the caller)
 * and inside the parallelogram (up to 1e-9 of its size) are drawn. E_ARG as both
 * functions; E_NOMEM. */
int gks_raster_cell_array_clipped(gks_raster_fb *fb, const gks_raster_pt *o,
                                  const gks_raster_pt *pu, const gks_raster_pt *pv, int nx,
                                  int ny, const float *rgb, const gks_raster_fill *fill,
                                  int n_loops, const int *counts, const gks_raster_pt *pts);

/* --- Lines and markers -------------------------------------------------------------- */
/* Linetypes (GKS 1..4). Pattern lengths in output pixels times max(1, width):
 * dashed 8 on 4 off; dotted 2 on 4 off; dash-dotted 8 on 3 off 2 on 3 off. The pattern
 * continues across vertices (arc length along the whole polyline). */
enum { GKS_RASTER_LT_SOLID = 1, GKS_RASTER_LT_DASHED = 2, GKS_RASTER_LT_DOTTED = 3,
       GKS_RASTER_LT_DASHDOT = 4 };

typedef struct gks_raster_line {
    float rgb[3];
    double width;              /* output pixels; values below 1 draw as 1 */
    int type;                  /* linetype 1..4 (ignored by markers: always solid) */
    gks_raster_zmode zmode;    /* NONE or TEST (ONLY is treated as TEST without colour) */
    float zbias;               /* >= 0; hidden-line mode: lets edges at a surface's own
                                  depth show; e.g. 1e-3 */
} gks_raster_line;

/* POLYLINE 3: n >= 2 points, z interpolated along each segment. Width 1 without
 * supersampling takes a Bresenham fast path (from the pixel holding one end point to the
 * pixel holding the other, 8-connected). Wider lines (and all lines when ss > 1) are
 * quads of the given width (same coverage rule as areas) with butt ends and round joins
 * where the line turns. E_ARG: NULL, n < 2, non-finite coordinate, type outside 1..4,
 * width NaN or >= 1e6, bad zmode/zbias; E_NOMEM never. */
int gks_raster_polyline(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                        const gks_raster_line *attr);

/* Continuation state of a polyline drawn in several calls (gks_raster_polyline_cont):
 * zero-initialise before the first call. */
typedef struct gks_raster_stroke {
    int cont;            /* 0: the next call starts a new polyline */
    double phase;        /* linetype pattern position at the last point drawn */
    gks_raster_pt prev;  /* the point before the last point drawn (for the join) */
} gks_raster_stroke;

/* POLYLINE 3 in pieces: as gks_raster_polyline, but when st->cont is set pts[0] must be
 * the last point of the previous call and the polyline continues there: linetype phase
 * carried on, the join at pts[0] drawn, the thin path's shared pixel not plotted twice.
 * The picture equals that of one gks_raster_polyline call over all points. Updates *st.
 * E_ARG as gks_raster_polyline or st NULL. */
int gks_raster_polyline_cont(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                             const gks_raster_line *attr, gks_raster_stroke *st);

/* POLYMARKER 3: n >= 1 markers of GKS type 1 dot (one output pixel), 2 plus, 3 asterisk,
 * 4 circle, 5 diagonal cross, centred at each point, size = nominal diameter in output
 * pixels, stroked solid with attr's colour, width, zmode and zbias. E_ARG as polyline,
 * or type outside 1..5, size not finite or < 0. */
int gks_raster_markers(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts, int type,
                       double size, const gks_raster_line *attr);

/* --- PNG ---------------------------------------------------------------------------- */
/* PNG compression: GKS_RASTER_PNG_FAST (0) is zlib's run-length strategy with the SUB row
 * filter -- 3 to 5 times faster to encode than libpng's defaults, files 0.9 to 2 times as
 * large (measured in docs/WORKSTATIONS.md); 1..9 are zlib levels with libpng's adaptive
 * row filters (6 = libpng's default, 9 = smallest). */
enum { GKS_RASTER_PNG_FAST = 0, GKS_RASTER_PNG_LEVEL_MAX = 9 };

/* Write the resolved framebuffer as 8-bit RGB PNG (row 0 of the file = top of the image),
 * resolving one row at a time. E_IO if the file cannot be written, E_NOMEM, E_ARG (also
 * for a compression outside 0..9). Never aborts. */
int gks_raster_fb_write_png(const gks_raster_fb *fb, const char *path, int compression);
/* Write w x h 8-bit RGB pixels (rgb8 row 0 = top) as PNG, compression as above. */
int gks_raster_png_write_rgb8(const char *path, int w, int h, const unsigned char *rgb8,
                              int compression);
/* The same with the rows taken one at a time, in order from y = 0 (top), from row(user, y):
 * 3*w bytes, read before the next call (the same file as gks_raster_png_write_rgb8 of those
 * rows). For a caller that makes the rows while earlier ones are compressed. */
typedef const unsigned char *(*gks_raster_row_fn)(void *user, int y);
int gks_raster_png_write_rows(const char *path, int w, int h, gks_raster_row_fn row,
                              void *user, int compression);
/* Read any PNG as 8-bit RGB (alpha dropped, palette/grey expanded, 16-bit stripped):
 * *rgb8 (row 0 = top, free with gks_free), *w, *h. E_IO, E_FORMAT, E_NOMEM, E_ARG. */
int gks_raster_png_read_rgb8(const char *path, int *w, int *h, unsigned char **rgb8);

#endif
