/* SPDX-License-Identifier: MIT */
/*
 * ws_wdt.h -- the output part of workstation description tables (ISO 7942 6.2): lists
 * of supported linetypes, marker types, text fonts and precisions, interior and hatch
 * styles, edgetypes, the ranges of widths and sizes, and the predefined bundles and
 * patterns. One const table serves the raster workstations (PNG, null); a
 * gks_ws_desc points at it through its `out` field.
 */
#ifndef GKS_WDT_H
#define GKS_WDT_H
#include "gks_private.h"
#include "gks.h"

#define GKS_WDT_MAX_BUNDLES 20 /* bundle and pattern tables hold indices 1..20 */

/* A pattern definition: nx * ny colour indices, row-major from the reference corner. */
typedef struct gks_wdt_pattern {
    int nx, ny;
    const int *colr;
} gks_wdt_pattern;

/* The facilities of polyline, polymarker and edge: the types, and the widths or sizes
 * (count, 0: continuous; nominal, minimum, maximum in DC units, pixels). */
typedef struct gks_wdt_sizes {
    int n_types;
    const int *types;
    int n_sizes;
    double nom, min, max;
} gks_wdt_sizes;

typedef struct gks_wdt_output {
    gks_wdt_sizes line, marker;
    int n_font_precs;
    const Gtext_font_prec *font_precs;
    int n_char_hts;                        /* 0: continuous */
    double min_char_ht, max_char_ht;       /* DC units */
    int n_char_expans;
    double min_char_expan, max_char_expan;
    int n_int_styles;
    const int *int_styles;
    int n_hatch_styles;
    const int *hatch_styles;
    gks_wdt_sizes edge;
    int n_pred_line;
    const Gline_bundle *pred_line;         /* index i at [i-1] */
    int n_pred_marker;
    const Gmarker_bundle *pred_marker;
    int n_pred_text;
    const Gtext_bundle *pred_text;
    int n_pred_fill;
    const Gfill_bundle *pred_fill;
    int n_pred_pat;
    const gks_wdt_pattern *pred_pat;
    int n_pred_edge;
    const Gedge_bundle *pred_edge;
    int max_bundles;                       /* table lengths (<= GKS_WDT_MAX_BUNDLES) */
} gks_wdt_output;

/* The raster workstations' table (PNG types and the null workstation). */
extern const gks_wdt_output gks_wdt_raster;
/* Predefined colours 0 white and 1 black (the workstations that draw nothing). */
extern const Grgb gks_wdt_white_black[2];

/* Whether v is in list[0..n-1]. */
int gks_wdt_has(const int *list, int n, int v);
/* Whether font/precision is supported (exact pair, or font with a higher precision). */
int gks_wdt_has_font(const gks_wdt_output *t, int font, int prec);
#endif
