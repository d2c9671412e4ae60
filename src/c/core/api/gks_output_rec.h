/* SPDX-License-Identifier: MIT */
/*
 * gks_output_rec.h -- the output pipeline's entries for INTERPRET ITEM (gks_metafile.c): a
 * recorded primitive performed with the recorded normalization and clipping volume `xf`
 * (gks_pipe_norm.h) instead of the current ones, as the public function that wrote it
 * (its state check, argument checks and errors, reported for that function).
 */
#ifndef GKS_OUTPUT_REC_H
#define GKS_OUTPUT_REC_H
#include "gks_private.h"
#include "gks.h"
#include "gks_area_data.h"
#include "gks_pipe_norm.h"

void gks_output_rec_polyline3(const gks_rec_xf *xf, const Gpoint_list3 *l);
void gks_output_rec_polymarker3(const gks_rec_xf *xf, const Gpoint_list3 *l);
void gks_output_rec_fill_area3(const gks_rec_xf *xf, const Gpoint_list3 *l);
void gks_output_rec_fill_area_set3(const gks_rec_xf *xf, const Gpoint_list_list3 *l);
void gks_output_rec_text3(const gks_rec_xf *xf, const Gpoint3 *pos, const Gvec3 dir[2],
                          const char *str);
void gks_output_rec_cell_array3(const gks_rec_xf *xf, const Gparal *par, const Gpat_rep *ca);
/* A primitive with data (item GKSM_ITEM_*_DATA, d in NDC3): gks_output_data.c. */
void gks_output_rec_data(const gks_rec_xf *xf, int item, const gks_area_data *d);
#endif
