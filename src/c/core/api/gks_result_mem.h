/* SPDX-License-Identifier: MIT */
/*
 * gks_result_mem.h -- result memory: the memory behind the C binding's Gstore (ISO 8651-4
 * 3.9). Inquiries and ESCAPE whose results have a size only GKS knows put them into a
 * Gstore the application created (gcreate_store); each use frees what it held before.
 * (Not to be confused with core/store/, the segment store and the metafile recording.)
 */
#ifndef GKS_RESULT_MEM_H
#define GKS_RESULT_MEM_H
#include "gks_private.h"
#include "gks.h"
#include <stddef.h>

/* Replace the Gstore's contents by n zeroed elements of size bytes; NULL if store is NULL
 * or memory is exhausted (the store is then empty). */
void *gks_result_alloc(Gstore store, size_t n, size_t size);
#endif
