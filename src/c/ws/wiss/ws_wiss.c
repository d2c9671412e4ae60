/* SPDX-License-Identifier: MIT */
/*
 * ws_wiss.c -- Workstation Independent Segment Storage (type GWS_TYPE_WISS, category
 * WISS): a workstation that only stores segments (the core's segment store does the
 * storing; this driver draws nothing). ASSOCIATE SEGMENT WITH WORKSTATION, COPY SEGMENT TO
 * WORKSTATION and INSERT SEGMENT take their segments from it (src/c/core/api/gks_segment.c).
 */
#include "ws_driver.h"

static const Grgb wiss_colours[2] = { { 1, 1, 1 }, { 0, 0, 0 } };

static const gks_ws_desc wiss_desc = {
    .type = GWS_TYPE_WISS,
    .name = "wiss",
    .cat = GCAT_WISS,
    .cls = GCLASS_OTHER,
    .dc_units = GDC_OTHER,
    .dc_x = 1, .dc_y = 1,
    .raster_x = 1, .raster_y = 1,
    .colr_avail = GAVAIL_COLR,
    .n_colr = 2,
    .n_pred_colr = 2,
    .pred_colr = wiss_colours,
    .default_irg = GIRG_ALLOWED,
    .default_defer = GDEFER_ASAP,
    .hlhsr_modes = 1u << GHLHSR_NONE,
    .out = &gks_wdt_raster,
};

const gks_ws_driver gks_ws_wiss_driver = {
    .version = GKS_WS_DRIVER_VERSION,
    .desc = &wiss_desc,
};
