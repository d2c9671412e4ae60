/*
 * rt_alloc.c -- the allocation funnel of gksrt: every size multiplication overflow-checked.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

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
    if (!rt_mul_ok(n, size, &bytes))
        return NULL;
    return malloc(bytes ? bytes : 1);
}

void *rt_calloc_array(size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes))
        return NULL;
    if (bytes == 0)
        return calloc(1, 1);
    return calloc(n, size);
}

void *rt_realloc_array(void *p, size_t n, size_t size)
{
    size_t bytes;
    if (!rt_mul_ok(n, size, &bytes))
        return NULL;
    return realloc(p, bytes ? bytes : 1);
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
