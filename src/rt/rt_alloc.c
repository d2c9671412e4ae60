/* SPDX-License-Identifier: MIT */
/*
 * rt_alloc.c -- the allocation funnel of gksrt: every size multiplication overflow-checked.
 */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE 1 /* madvise, MADV_HUGEPAGE */
#endif
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

/* Large arrays (vertices, references, cell offsets of big meshes: tens of MB read at random
   by the traversal) are asked to live on transparent huge pages where the system does so
   only on request (THP "madvise" mode): far fewer TLB misses. Advice only; failure ignored.
   Only the pages inside the block are advised, which leaves the block's own mapping split:
   realloc's mremap then fails and glibc copies the block. That is kept on purpose: huge pages
   that mremap moved read far slower at random afterwards (docs/bench/scale.md, grow_probe);
   arrays that grow large while the scene is recorded use rt_big below, which never moves. */
#define RT_HUGE_MIN ((size_t)4 << 20)

static void rt_huge(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (!p || bytes < RT_HUGE_MIN)
        return;
    const uintptr_t pg = 4096;
    uintptr_t a = ((uintptr_t)p + pg - 1) & ~(pg - 1), e = ((uintptr_t)p + bytes) & ~(pg - 1);
    if (e > a)
        (void)madvise((void *)a, e - a, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

#ifdef GKS_FAULT_INJECTION
/* The test build of the library (gksrt_test in gks3d_test, src/c/CMakeLists.txt) sends
 * every allocation of the tracer through the failure injection of the library's funnel
 * (src/c/base/gks_alloc.c): gks_alloc_fail_after(n) fails the nth allocation of either.
 * Declared here, not included: gksrt includes no GKS header. */
int gks_alloc_injected_failure(void);
static atomic_long rt_allocs;   /* the tracer's share of gks_alloc_count() */
static atomic_long rt_injected; /* the tracer's allocations made to fail */
static int rt_injected_failure(void)
{
    atomic_fetch_add_explicit(&rt_allocs, 1, memory_order_relaxed);
    if (!gks_alloc_injected_failure())
        return 0;
    atomic_fetch_add_explicit(&rt_injected, 1, memory_order_relaxed);
    return 1;
}
#define RT_INJECTED_FAILURE() rt_injected_failure()

/* Test hooks (test_rt_oom): the tracer's allocations so far, and how many of them failed
 * by injection. */
long rt_alloc_count(void)
{
    return atomic_load(&rt_allocs);
}

long rt_alloc_injected(void)
{
    return atomic_load(&rt_injected);
}
#else
#define RT_INJECTED_FAILURE() 0
#endif

static int rt_mul_ok(size_t n, size_t size, size_t *out)
{
    if (size != 0 && n > SIZE_MAX / size)
        return 0;
    *out = n * size;
    return 1;
}

void *rt_alloc_array(size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes) || RT_INJECTED_FAILURE())
        return NULL;
    void *p = malloc(bytes ? bytes : 1);
    rt_huge(p, bytes);
    return p;
}

void *rt_alloc_lines(size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes) || bytes > SIZE_MAX - RT_LINE || RT_INJECTED_FAILURE())
        return NULL;
    /* C11's aligned_alloc takes a size that is a multiple of the alignment */
    const size_t lines = bytes ? (bytes - 1) / RT_LINE + 1 : 1;
    return aligned_alloc(RT_LINE, lines * RT_LINE);
}

void *rt_calloc_array(size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes) || RT_INJECTED_FAILURE())
        return NULL;
    if (bytes == 0)
        return calloc(1, 1);
    void *p = calloc(n, size);
    rt_huge(p, bytes);
    return p;
}

void *rt_realloc_array(void *p, size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes) || RT_INJECTED_FAILURE())
        return NULL;
    void *q = realloc(p, bytes ? bytes : 1);
    rt_huge(q, bytes);
    return q;
}

int rt_grow(void **p, size_t *cap, size_t need, size_t es)
{
    if (need <= *cap)
        return 1;
    size_t nc = *cap ? *cap : 16;
    while (nc < need) {
        if (nc > SIZE_MAX / 2)
            return 0;
        nc *= 2;
    }
    void *q = rt_realloc_array(*p, nc, es);
    if (!q)
        return 0;
    *p = q;
    *cap = nc;
    return 1;
}

double rt_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* ---- arrays that do not move once large ---- */

/* Address space reserved for a large rt_big at once (pages are given only when touched):
   64 GiB, 9*10^8 triangles of 72 B. Where the system refuses it (strict overcommit, an
   address-space limit) the array stays on malloc. */
#define RT_BIG_RESERVE ((size_t)1 << 36)

#if defined(__linux__) && defined(MAP_NORESERVE) && defined(MAP_ANONYMOUS)
#define RT_BIG_MAP 1
#endif

int rt_big_grow(rt_big *b, size_t need, size_t es)
{
    size_t bytes;
    if (need <= b->cap)
        return 1;
    if (!rt_mul_ok(need, es, &bytes) || es == 0)
        return 0;
#ifdef RT_BIG_MAP
    if (bytes > RT_HUGE_MIN) {
        if (RT_INJECTED_FAILURE())
            return 0;
        size_t res = bytes > RT_BIG_RESERVE / 2 ? 2 * bytes : RT_BIG_RESERVE;
        if (bytes <= SIZE_MAX / 2 && !b->map_bytes) { /* only one move: malloc -> mapping */
            void *q = mmap(NULL, res, PROT_READ | PROT_WRITE,
                           MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
            if (q != MAP_FAILED) {
#ifdef MADV_HUGEPAGE
                (void)madvise(q, res, MADV_HUGEPAGE);
#endif
                if (b->p && b->cap)
                    memcpy(q, b->p, b->cap * es);
                free(b->p);
                b->p = q;
                b->map_bytes = res;
                b->cap = res / es;
                return 1;
            }
        }
        if (b->map_bytes) /* the reservation is full: a larger one is not tried */
            return 0;
    }
#endif
    return rt_grow(&b->p, &b->cap, need, es);
}

void rt_big_shrink(rt_big *b, size_t keep, size_t es)
{
    size_t bytes;
    if (!b->p || !rt_mul_ok(keep, es, &bytes) || bytes == 0)
        return;
#ifdef RT_BIG_MAP
    if (b->map_bytes) { /* the whole pages after the kept bytes go back to the system */
        const long ps = sysconf(_SC_PAGESIZE);
        const size_t pg = ps > 0 ? (size_t)ps : 4096;
        const size_t at = (bytes + pg - 1) / pg * pg;
        if (at < b->map_bytes && munmap((char *)b->p + at, b->map_bytes - at) == 0)
            b->map_bytes = at;
        b->cap = keep;
        return;
    }
#endif
    void *q = realloc(b->p, bytes);
    if (q) {
        b->p = q;
        b->cap = keep;
    }
}

void rt_big_free(rt_big *b)
{
#ifdef RT_BIG_MAP
    if (b->map_bytes)
        (void)munmap(b->p, b->map_bytes);
    else
#endif
        free(b->p);
    b->p = NULL;
    b->cap = 0;
    b->map_bytes = 0;
}
