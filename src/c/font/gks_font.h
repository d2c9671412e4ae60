/* SPDX-License-Identifier: MIT */
/*
 * gks_font.h -- the stroke fonts of TEXT (internal, not installed): a module of its own,
 * below the output pipeline's text layout (core/pipe) and the drivers that draw glyphs
 * themselves (ws/cairo). No GKS state; it sees base alone.
 *
 * A simplex sans stroke font for printable ASCII 32..126, compiled in. Font units: base
 * line 0, cap height 21, descender -7; glyph x from 0 to its advance width.
 * Faces derived from it by rule (no further glyph data), under the font numbers RAL GKS
 * gave its Roman software fonts (Starlink SUN/83, "Fonts"):
 *      1, -101  simplex sans (the table itself)
 *   -102        bold sans: every stroke drawn three times, 0, 0.5 and 1 unit to the
 *               right; advances and the widest advance grow by 1
 *   -104        seriffed: a serif 4 units wide (clipped to the body) at each free end of
 *               a steep stroke on the base line, x-height (14), cap line or descender
 *   -105        seriffed italic: -104 sheared, x += 0.2 * y
 *   -106        seriffed bold: -104 drawn as -102
 *   -107        seriffed bold italic
 * All faces share the vertical metrics below.
 */
#ifndef GKS_FONT_H
#define GKS_FONT_H
#include "gks_private.h"

enum { GKS_FONT_OK = 0, GKS_FONT_E_ARG = 1 };

#define GKS_GLYPH_MAX_POINTS 400
#define GKS_GLYPH_MAX_STROKES 64

typedef struct gks_font_metrics {
    double top;      /* 25: above accents / parentheses */
    double cap;      /* 21 */
    double half;     /* 10.5: half of the cap height */
    double base;     /* 0 */
    double bottom;   /* -7: descender */
    double max_advance;
} gks_font_metrics;

typedef struct gks_glyph {
    double advance;                        /* advance width, font units */
    int n_strokes;                         /* polylines */
    int n_points;
    int stroke_len[GKS_GLYPH_MAX_STROKES]; /* points of each polyline, in order */
    double xy[2 * GKS_GLYPH_MAX_POINTS];   /* x0,y0,x1,y1,... font units */
} gks_glyph;

/* 1 if font is one of the faces above, else 0. */
int gks_font_has(int font);
/* Metrics of font (font 1's for a font not in the list); nothing on NULL. */
void gks_font_get_metrics(int font, gks_font_metrics *m);
/* Strokes and advance of character ch in font. Characters outside 32..126 return E_ARG
 * and the glyph of '?' (so text layout can still proceed); a font not in the list returns
 * E_ARG and the glyph of font 1; E_ARG with nothing filled on NULL. */
int gks_font_get_glyph(int font, int ch, gks_glyph *g);
#endif
