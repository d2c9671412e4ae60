/* SPDX-License-Identifier: MIT */
/*
 * gks_gdp.h -- the generalized drawing primitives of this implementation (gks_gdp.c):
 * RAL GKS's ARC, CHORD, PIE and CIRCLE (identifiers -1..-4) and an ELLIPSE (-5). Each is
 * tessellated in WC3 and drawn through the POLYLINE (ARC) or FILL AREA path (the others),
 * so workstations, segments, the metafile and the tracer see ordinary primitives.
 */
#ifndef GKS_GDP_H
#define GKS_GDP_H
#include "gks.h"
#include <stddef.h>

/* The GDP identifiers every output workstation type lists, in list order; count. */
int gks_gdp_list(const Gint **ids);

/* The attribute bundles GDP gdp uses (3-D: fill areas add the edge bundle) into attr
 * (room for 2); the count, 0 if gdp is not a GDP of this implementation. */
int gks_gdp_attrs(Gint gdp, int three_d, Gattrs attr[2]);

/* gks_output.c: a polyline / one fill area given in WC3, after the argument checks. */
void gks_output_polyline_d3(int fctid, size_t n, const double (*p)[3]);
void gks_output_area_d3(int fctid, size_t n, const double (*p)[3]);

#endif
