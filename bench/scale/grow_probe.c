/* SPDX-License-Identifier: MIT */
/*
 * grow_probe.c -- how a large array should grow on this machine (the recording of bench/scale
 * grows its triangle arrays to hundreds of MB). Grows a 512 MiB array three ways and reads it
 * at random twice afterwards:
 *   copy:    realloc doubling with huge-page advice on the inner pages (the block's mapping is
 *            split, mremap fails, glibc copies into fresh memory: what rt_grow does);
 *   mremap:  the same with advice on whole pages (one mapping: realloc moves it by mremap);
 *   reserve: a reserved range (MAP_NORESERVE, huge-page advice) that grows in place (rt_big).
 * Prints the seconds of the growth and of each random pass. Linux only.
 */
#define _DEFAULT_SOURCE 1
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void advise(void *p, size_t n, int whole)
{
    const uintptr_t pg = 4096;
    uintptr_t a = whole ? (uintptr_t)p & ~(pg - 1) : ((uintptr_t)p + pg - 1) & ~(pg - 1);
    uintptr_t e = whole ? ((uintptr_t)p + n + pg - 1) & ~(pg - 1) : ((uintptr_t)p + n) & ~(pg - 1);
    if (e > a)
        (void)madvise((void *)a, e - a, MADV_HUGEPAGE);
}

static double random_pass(const unsigned char *p, size_t n)
{
    double t = now();
    volatile unsigned s = 0;
    for (size_t i = 0; i < n; i += 1152)
        s += p[(i * 2654435761u) % n];
    (void)s;
    return now() - t;
}

int main(void)
{
    const size_t n = (size_t)512 << 20;
    for (int way = 0; way < 3; way++) {
        unsigned char *p;
        double t0 = now();
        if (way < 2) {
            size_t cap = (size_t)1 << 20;
            p = malloc(cap);
            if (!p)
                return 1;
            memset(p, 1, cap);
            while (cap < n) {
                unsigned char *q = realloc(p, 2 * cap);
                if (!q)
                    return 1;
                p = q;
                advise(p, 2 * cap, way == 1);
                memset(p + cap, 1, cap);
                cap *= 2;
            }
        } else {
            p = mmap(NULL, (size_t)1 << 36, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
            if (p == MAP_FAILED)
                return 1;
            (void)madvise(p, (size_t)1 << 36, MADV_HUGEPAGE);
            memset(p, 1, n);
        }
        double t1 = now(), r1 = random_pass(p, n), r2 = random_pass(p, n);
        printf("%-8s grow %.3f s, random read %.3f s, again %.3f s\n",
               way == 0 ? "copy" : way == 1 ? "mremap" : "reserve", t1 - t0, r1, r2);
        if (way < 2)
            free(p);
        else
            munmap(p, (size_t)1 << 36);
    }
    return 0;
}
