/* SPDX-License-Identifier: MIT */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE 1 /* madvise, MADV_POPULATE_WRITE */
#endif
#include "gks_alloc.h"
#include "gks_export.h"
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#ifdef GKS_FAULT_INJECTION
/* Failure injection state (SQLite test_malloc style), only in the test build of the
 * modules (gks3d_test, src/c/CMakeLists.txt); the installed libraries have none.
 * Atomic: the tracer's worker threads allocate through this funnel too. */
static atomic_long fail_countdown; /* 0 = off; k = the kth allocation from now fails */
static atomic_long alloc_count;

int gks_alloc_injected_failure(void)
{
    atomic_fetch_add_explicit(&alloc_count, 1, memory_order_relaxed);
    long c = atomic_load_explicit(&fail_countdown, memory_order_relaxed);
    while (c > 0) /* exactly one allocation takes the countdown from 1 to 0 */
        if (atomic_compare_exchange_weak_explicit(&fail_countdown, &c, c - 1,
                                                  memory_order_relaxed, memory_order_relaxed))
            return c == 1;
    return 0;
}
#define injected_failure gks_alloc_injected_failure
#else
static int injected_failure(void) { return 0; }
#endif

static int size_ok(size_t n, size_t size, size_t *bytes)
{
    if (size != 0 && n > SIZE_MAX / size)
        return 0;
    *bytes = n * size;
    if (*bytes == 0)
        *bytes = 1;
    return 1;
}

void *gks_alloc_array(size_t n, size_t size)
{
    size_t bytes;
    if (!size_ok(n, size, &bytes) || injected_failure())
        return NULL;
    return malloc(bytes);
}

void *gks_calloc_array(size_t n, size_t size)
{
    size_t bytes;
    if (!size_ok(n, size, &bytes) || injected_failure())
        return NULL;
    return calloc(1, bytes);
}

void *gks_realloc_array(void *p, size_t n, size_t size)
{
    size_t bytes;
    if (!size_ok(n, size, &bytes) || injected_failure())
        return NULL;
    return realloc(p, bytes);
}

int gks_grow(void *arrp, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    void *p; /* *arrp is a T *: copied as bytes, not read through a void ** */
    memcpy(&p, arrp, sizeof p);
    size_t c = *cap > 0 ? *cap : 16;
    while (c < need)
        c = c > SIZE_MAX / 2 ? need : 2 * c;
    void *q = gks_realloc_array(p, c, size);
    if (!q)
        return 300;
    memcpy(arrp, &q, sizeof q);
    *cap = c;
    return 0;
}

char *gks_strndup(const char *s, size_t n)
{
    size_t len = strnlen(s, n);
    char *d = gks_alloc_array(len + 1, 1);
    if (!d)
        return NULL;
    memcpy(d, s, len);
    d[len] = '\0';
    return d;
}

char *gks_strdup(const char *s)
{
    return gks_strndup(s, SIZE_MAX);
}

void gks_free(void *p)
{
    free(p);
}

int gks_populate(const void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const long ps = sysconf(_SC_PAGESIZE);
    if (bytes == 0 || ps <= 0 || (ps & (ps - 1)) != 0 || (uintptr_t)p > UINTPTR_MAX - bytes)
        return 0;
    const uintptr_t pg = (uintptr_t)ps;
    const uintptr_t a = (uintptr_t)p & ~(pg - 1);
    const uintptr_t last = ((uintptr_t)p + bytes - 1) & ~(pg - 1);
    return madvise((void *)a, last - a + pg, MADV_POPULATE_WRITE) == 0;
#else
    (void)p;
    (void)bytes;
    return 0;
#endif
}

#ifdef GKS_FAULT_INJECTION
GKS_TEST_API void gks_alloc_fail_after(long n)
{
    atomic_store(&fail_countdown, n > 0 ? n : 0);
}

GKS_TEST_API long gks_alloc_count(void)
{
    return atomic_load(&alloc_count);
}
#endif
