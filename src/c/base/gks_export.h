/* SPDX-License-Identifier: MIT */
/*
 * gks_export.h -- symbol visibility. The library builds with -fvisibility=hidden; the
 * public API is marked GKS_API in gks.h; hooks used only by the tests are GKS_TEST_API
 * and exist only in the test build of the modules (GKS_FAULT_INJECTION, gks3d_test).
 */
#ifndef GKS_EXPORT_H
#define GKS_EXPORT_H
#include "gks_private.h"
#define GKS_TEST_API __attribute__((visibility("default")))
#endif
