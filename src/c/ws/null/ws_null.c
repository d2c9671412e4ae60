/* SPDX-License-Identifier: MIT */
/*
 * ws_null.c -- the null workstation (type 99): category OUTPUT, accepts everything and
 * draws nothing; for batch runs and tests that need an open, active workstation.
 */
#include "ws_driver.h"

static const gks_ws_desc null_desc = {
    GKS_WS_DESC_NODRAW(GWS_TYPE_NULL, "null", GCAT_OUT, GCLASS_RASTER, 1024),
    .n_colr = 256,
    .n_pred_colr = 2,
    .pred_colr = gks_wdt_white_black,
    .hlhsr_modes = 1u << GHLHSR_NONE,
};

const gks_ws_driver gks_ws_null_driver = {
    .version = GKS_WS_DRIVER_VERSION,
    .desc = &null_desc,
};
