/* SPDX-License-Identifier: MIT */
/*
 * gks_result_mem.c -- result memory (gks_result_mem.h): CREATE STORE and DELETE STORE of
 * the C binding, and the one allocation that inquiries and ESCAPE make in a Gstore.
 */
#include "gks_result_mem.h"
#include "gks_alloc.h"

struct gks_store_rec {
    void *data; /* what the last inquiry given this store put there (gks_alloc) */
};

GKS_API void gcreate_store(Gint *err_ind, Gstore *store)
{
    Gstore s = gks_calloc_array(1, sizeof *s);
    *err_ind = s ? 0 : 300;
    if (store)
        *store = s;
}

GKS_API void gdel_store(Gstore store)
{
    if (!store)
        return;
    gks_free(store->data);
    gks_free(store);
}

void *gks_result_alloc(Gstore store, size_t n, size_t size)
{
    if (!store)
        return NULL;
    gks_free(store->data);
    store->data = gks_calloc_array(n ? n : 1, size ? size : 1);
    return store->data;
}
