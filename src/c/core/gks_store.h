/* SPDX-License-Identifier: MIT */
/*
 * gks_store.h -- the C binding's Gstore (ISO 8651-4 3.9): inquiries and ESCAPE whose
 * results have a size only GKS knows put them into a store the application created;
 * each use frees what the store held before.
 */
#ifndef GKS_STORE_H
#define GKS_STORE_H
#include "gks_private.h"
#include "gks.h"
#include <stddef.h>

/* Replace the store's contents by n zeroed elements of size bytes; NULL if store is NULL
 * or memory is exhausted (the store is then empty). */
void *gks_store_alloc(Gstore store, size_t n, size_t size);
#endif
