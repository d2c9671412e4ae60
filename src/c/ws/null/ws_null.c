/* SPDX-License-Identifier: MIT */
/*
 * ws_null.c -- the null workstation (type 99): category OUTPUT, accepts everything and
 * draws nothing; for batch runs and tests that need an open, active workstation.
 */
#include "ws_driver.h"

GKS_WS_DRIVER_NODRAW(gks_ws_null_driver, GWS_TYPE_NULL, "null", GCAT_OUT, GCLASS_RASTER, 1024, 256);
