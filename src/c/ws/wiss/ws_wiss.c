/* SPDX-License-Identifier: MIT */
/*
 * ws_wiss.c -- Workstation Independent Segment Storage (type GWS_TYPE_WISS, category
 * WISS): a workstation that only stores segments (the core's segment store does the
 * storing; this driver draws nothing). ASSOCIATE SEGMENT WITH WORKSTATION, COPY SEGMENT TO
 * WORKSTATION and INSERT SEGMENT take their segments from it (src/c/core/api/gks_segment.c).
 */
#include "ws_driver.h"

static const gks_ws_desc wiss_desc = {
    GKS_WS_DESC_NODRAW(GWS_TYPE_WISS, "wiss", GCAT_WISS, GCLASS_OTHER, 1),
    .n_colr = 2,
    .n_pred_colr = 2,
    .pred_colr = gks_wdt_white_black,
    .hlhsr_modes = 1u << GHLHSR_NONE,
};

const gks_ws_driver gks_ws_wiss_driver = {
    .version = GKS_WS_DRIVER_VERSION,
    .desc = &wiss_desc,
};
