/* SPDX-License-Identifier: MIT */
/*
 * ws_wdt.c -- the output facilities and predefined bundles of the raster workstations.
 * The raster module draws linetypes 1..4, marker types 1..5, hatch styles -1..-12,
 * patterns and solid/hollow interiors; text is stroked in the core with the compiled-in
 * simplex font (font 1) and the faces derived from it (RAL GKS's numbers -101, -102,
 * -104 .. -107, src/c/raster/raster.h), so every precision of each is available.
 */
#include "ws_wdt.h"

static const int linetypes[] = { 1, 2, 3, 4 };
static const int markertypes[] = { 1, 2, 3, 4, 5 };
static const Gtext_font_prec font_precs[] = {
    { 1, GPREC_STRING },     { 1, GPREC_CHAR },       { 1, GPREC_STROKE },
    { -101, GPREC_STROKE },  { -102, GPREC_STROKE },  { -104, GPREC_STROKE },
    { -105, GPREC_STROKE },  { -106, GPREC_STROKE },  { -107, GPREC_STROKE },
};
static const int int_styles[] = { GSTYLE_HOLLOW, GSTYLE_SOLID, GSTYLE_PAT, GSTYLE_HATCH };
static const int hatch_styles[] = { -1, -2, -3, -4, -5, -6, -7, -8, -9, -10, -11, -12 };

/* Predefined bundles (index i at [i-1]). */
static const Gline_bundle pred_line[] = {
    { 1, 1.0, 1 }, { 2, 1.0, 1 }, { 3, 1.0, 1 }, { 4, 1.0, 1 }, { 1, 3.0, 1 },
};
static const Gmarker_bundle pred_marker[] = {
    { 1, 1.0, 1 }, { 2, 1.0, 1 }, { 3, 1.0, 1 }, { 4, 1.0, 1 }, { 5, 1.0, 1 },
};
/* Text bundle i has colour index i: programs written for colour devices (RAL's CONCOL,
 * COLREP) tell their lines of text apart by text index alone. */
static const Gtext_bundle pred_text[] = {
    { { 1, GPREC_STRING }, 1.0, 0.0, 1 },
    { { 1, GPREC_CHAR }, 1.0, 0.0, 2 },
    { { 1, GPREC_STROKE }, 1.0, 0.0, 3 },
    { { 1, GPREC_STROKE }, 0.8, 0.2, 4 },
    { { 1, GPREC_STROKE }, 1.5, 0.0, 5 },
};
static const Gfill_bundle pred_fill[] = {
    { GSTYLE_HOLLOW, 1, 1 }, { GSTYLE_SOLID, 1, 1 }, { GSTYLE_PAT, 1, 1 },
    { GSTYLE_HATCH, -1, 1 }, { GSTYLE_HATCH, -3, 1 },
};
static const Gedge_bundle pred_edge[] = {
    { GEDGE_ON, 1, 1.0, 1 }, { GEDGE_ON, 2, 1.0, 1 }, { GEDGE_ON, 1, 3.0, 1 },
};
/* Pattern 1: 2x2 checkerboard of colours 1 and 0; pattern 2: 4x4 diagonal stripe of
 * colour 2 on 0; pattern 3: 3x1 red, green, blue stripes. */
static const int pat1[] = { 1, 0, 0, 1 };
static const int pat2[] = { 2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 2, 0,  0, 0, 0, 2 };
static const int pat3[] = { 2, 3, 4 };
static const gks_wdt_pattern pred_pat[] = { { 2, 2, pat1 }, { 4, 4, pat2 }, { 3, 1, pat3 } };

#define N(a) ((int)(sizeof(a) / sizeof((a)[0])))

const Grgb gks_wdt_white_black[2] = { { 1, 1, 1 }, { 0, 0, 0 } };

const gks_wdt_output gks_wdt_raster = {
    .line = { N(linetypes), linetypes, .n_sizes = 0, .nom = 1, .min = 1, .max = 256 },
    .marker = { N(markertypes), markertypes, .n_sizes = 0, .nom = 7, .min = 1, .max = 1024 },
    .n_font_precs = N(font_precs), .font_precs = font_precs,
    .n_char_hts = 0, .min_char_ht = 0, .max_char_ht = 1e6,
    .n_char_expans = 0, .min_char_expan = 0, .max_char_expan = 1e6,
    .n_int_styles = N(int_styles), .int_styles = int_styles,
    .n_hatch_styles = N(hatch_styles), .hatch_styles = hatch_styles,
    .edge = { N(linetypes), linetypes, .n_sizes = 0, .nom = 1, .min = 1, .max = 256 },
    .n_pred_line = N(pred_line), .pred_line = pred_line,
    .n_pred_marker = N(pred_marker), .pred_marker = pred_marker,
    .n_pred_text = N(pred_text), .pred_text = pred_text,
    .n_pred_fill = N(pred_fill), .pred_fill = pred_fill,
    .n_pred_pat = N(pred_pat), .pred_pat = pred_pat,
    .n_pred_edge = N(pred_edge), .pred_edge = pred_edge,
    .max_bundles = GKS_WDT_MAX_BUNDLES,
};

int gks_wdt_has(const int *list, int n, int v)
{
    for (int i = 0; i < n; i++)
        if (list[i] == v)
            return 1;
    return 0;
}

int gks_wdt_has_font(const gks_wdt_output *t, int font, int prec)
{
    for (int i = 0; i < t->n_font_precs; i++)
        if (t->font_precs[i].font == font && (int)t->font_precs[i].prec >= prec)
            return 1;
    return 0;
}
