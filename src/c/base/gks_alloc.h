/* SPDX-License-Identifier: MIT */
/*
 * gks_alloc.h -- the one allocation funnel of the library: overflow-checked sizes and,
 * in test builds, failure injection (fail the Nth allocation) to check that a failed
 * allocation reports error 300 and leaves the state lists unchanged.
 */
#ifndef GKS_ALLOC_H
#define GKS_ALLOC_H
#include "gks_private.h"
#include <stddef.h>

/* malloc(n * size) with overflow check; NULL on overflow or exhaustion (n*size == 0
 * allocates one byte so that NULL always means failure). */
void *gks_alloc_array(size_t n, size_t size);
/* calloc-like: zeroed. */
void *gks_calloc_array(size_t n, size_t size);
/* realloc(p, n * size) with overflow check; on failure p is untouched and NULL returned. */
void *gks_realloc_array(void *p, size_t n, size_t size);
/* The one growable-array step. arrp is the address of an array pointer (T **) whose array
 * has room for *cap elements of size: when need > *cap it is reallocated, the capacity
 * doubling from 16 until it holds need. 0 on success; 300 (storage overflow) on size
 * overflow or exhaustion, the array and *cap then untouched. */
int gks_grow(void *arrp, size_t *cap, size_t need, size_t size);
/* strdup through the funnel. */
char *gks_strdup(const char *s);
/* strndup through the funnel (copies at most n bytes, always terminates). */
char *gks_strndup(const char *s, size_t n);
void gks_free(void *p);
/* Makes the pages holding [p, p + bytes) present for writing in one call (Linux
 * madvise(MADV_POPULATE_WRITE); contents unchanged): a first touch of fresh memory costs one
 * page fault per 4 KiB, ~10 us each in the virtual machines measured, about three times the
 * populate's cost per page (docs/bench/scale.md). The range must lie in memory the caller
 * owns; its first and last pages are included whole (a page that holds a mapped byte is
 * mapped whole). 1 if done, 0 if not (bytes 0, another system, an older kernel). */
int gks_populate(const void *p, size_t bytes);

#ifdef GKS_FAULT_INJECTION
/* Test hooks, only in the test build of the modules (gks3d_test): make the Nth allocation
 * from now fail (0 = never); gks_alloc_count() counts the allocations made so far. */
void gks_alloc_fail_after(long n);
long gks_alloc_count(void);
/* Counts one allocation and says whether it is to fail (1) as gks_alloc_fail_after set:
 * the funnel's own check, also called by the tracer's funnel (src/rt/rt_alloc.c) and the
 * Fortran binding's (gks_f77_alloc) in their test builds. */
int gks_alloc_injected_failure(void);
#endif
#endif
