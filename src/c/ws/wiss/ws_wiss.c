/* SPDX-License-Identifier: MIT */
/*
 * ws_wiss.c -- Workstation Independent Segment Storage (type GWS_TYPE_WISS, category
 * WISS): a workstation that only stores segments (the core's segment store does the
 * storing; this driver draws nothing). ASSOCIATE SEGMENT WITH WORKSTATION, COPY SEGMENT TO
 * WORKSTATION and INSERT SEGMENT take their segments from it (src/c/core/api/gks_segment.c).
 */
#include "ws_driver.h"

GKS_WS_DRIVER_NODRAW(gks_ws_wiss_driver, GWS_TYPE_WISS, "wiss", GCAT_WISS, GCLASS_OTHER, 1, 2);
