/* SPDX-License-Identifier: MIT */
/*
 * ws_null.c -- the null workstation (type 99): category OUTPUT, accepts everything and
 * draws nothing; for batch runs and tests that need an open, active workstation.
 */
#include "ws_driver.h"

static const Grgb null_colours[2] = { { 1, 1, 1 }, { 0, 0, 0 } };

static const gks_ws_desc null_desc = {
    .type = GWS_TYPE_NULL,
    .name = "null",
    .cat = GCAT_OUT,
    .cls = GCLASS_RASTER,
    .dc_units = GDC_OTHER,
    .dc_x = 1024, .dc_y = 1024,
    .raster_x = 1024, .raster_y = 1024,
    .colr_avail = GAVAIL_COLR,
    .n_colr = 256,
    .n_pred_colr = 2,
    .pred_colr = null_colours,
    .default_irg = GIRG_ALLOWED,
    .default_defer = GDEFER_ASAP,
    .hlhsr_modes = 1u << GHLHSR_NONE,
    .out = &gks_wdt_raster,
};

const gks_ws_driver gks_ws_null_driver = {
    .version = GKS_WS_DRIVER_VERSION,
    .desc = &null_desc,
};
