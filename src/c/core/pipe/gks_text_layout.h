/* SPDX-License-Identifier: MIT */
/*
 * gks_text_layout.h -- TEXT (3) layout: turns a string into polyline strokes of the compiled-in
 * stroke font (src/c/font) in WC3, honouring character height, expansion factor,
 * spacing, up vector, text path and alignment, in the text plane of TEXT 3 (the x/y
 * plane for 2-D TEXT). No GKS state: the caller passes resolved attributes.
 */
#ifndef GKS_TEXT_H
#define GKS_TEXT_H
#include "gks_private.h"
#include "gks.h"
#include <stddef.h>

/* Resolved text attributes (after the aspect source flags and the workstation). */
typedef struct gks_text_attrs {
    int font;                  /* a stroke font of src/c/font (gks_font_has); any
                                  other number lays out as font 1 */
    Gtext_prec prec;           /* text precision asked for (the layout is the same in all) */
    double char_expan, char_space, char_ht;
    double up[2];              /* character up vector in text-plane coordinates */
    Gtext_path path;
    Gtext_align align;
} gks_text_attrs;

/* The text plane in WC3: origin = the text position; ex, ey orthonormal, ex along the
 * first text direction vector (for 2-D TEXT: (1,0,0), (0,1,0)). */
typedef struct gks_text_frame {
    double org[3], ex[3], ey[3];
} gks_text_frame;

/* Called for each stroke: n >= 2 points in WC3. A non-zero return stops the layout and
 * is returned by gks_text_strokes. */
typedef int (*gks_text_emit)(void *ctx, size_t n, const double (*pts)[3]);

/* 101 if s holds a character outside the font's ISO 646 printable range 32..126, else 0. */
int gks_text_check(const char *s);

/* Build the text plane of TEXT 3 from the position and the two text direction vectors.
 * Returns 0, or -1 if a vector is zero, not finite, or the two are parallel. */
int gks_text_frame3(const double pos[3], const double d0[3], const double d1[3],
                    gks_text_frame *f);

/* Emit the strokes of s (checked with gks_text_check). Returns 0 or the callback's value.
 * Nothing is emitted if the attributes are degenerate (zero up vector, height <= 0). */
int gks_text_strokes(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                     gks_text_emit emit, void *ctx);

/* Called for each character of a string laid out as gks_text_strokes lays it out: ch, the
 * WC3 point of the glyph's font-unit origin (0, 0), and the WC3 vectors of one font unit
 * along the glyph's x (base direction, times the expansion factor) and y (up). The stroke
 * point (gx, gy) is org + gx * ux + gy * uy (gks_text_strokes computes the same point in
 * another order, so equal to rounding). A non-zero return stops the layout. */
typedef int (*gks_text_place_fn)(void *ctx, int ch, const double org[3], const double ux[3],
                                 const double uy[3]);

/* Call place for each character of s (checked with gks_text_check); 0 or place's value.
 * Nothing is called if the attributes are degenerate (as gks_text_strokes). */
int gks_text_place(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                   gks_text_place_fn place, void *ctx);

/* Text extent rectangle (corners lower-left, lower-right, upper-right, upper-left in the
 * text's own base/up frame) and concatenation point, in WC3. */
void gks_text_extent(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                     double corners[4][3], double concat[3]);
#endif
