/* SPDX-License-Identifier: MIT */
#include "gks_alloc.h"
#include "gks_export.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Failure injection state: the only mutable file-level state besides the context; it
 * exists for the tests (SQLite test_malloc style) and costs one branch per allocation. */
static long fail_countdown; /* 0 = off; k = the kth allocation from now fails */
static long alloc_count;

static int injected_failure(void)
{
    alloc_count++;
    if (fail_countdown <= 0)
        return 0;
    return --fail_countdown == 0;
}

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

GKS_TEST_API void gks_alloc_fail_after(long n)
{
    fail_countdown = n > 0 ? n : 0;
}

GKS_TEST_API long gks_alloc_count(void)
{
    return alloc_count;
}
