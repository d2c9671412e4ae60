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
 * grow_probe touch: the first touch of fresh memory instead (256 MiB of a reserved range with
 * huge-page advice, as rt_big has it, written once) by one thread, then by two threads at
 * once, 256 MiB each, none of it freed before the end: GB/s per thread. On a VM whose host backs guest pages only when first
 * used this is far below the speed of writing memory already touched (also printed).
 */
#define _DEFAULT_SOURCE 1
#include <pthread.h>
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

#define TOUCH_BYTES ((size_t)256 << 20)

/* seconds to write TOUCH_BYTES of fresh memory (into *sec), and then again (rewrite) */
typedef struct touch_run {
    double sec, again;
    void *p; /* unmapped at the end: each run gets memory no run before it freed */
} touch_run;

static void *touch(void *arg)
{
    touch_run *r = arg;
    unsigned char *p = mmap(NULL, TOUCH_BYTES, PROT_READ | PROT_WRITE,
                            MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) {
        r->sec = r->again = -1.0;
        return NULL;
    }
    (void)madvise(p, TOUCH_BYTES, MADV_HUGEPAGE);
    double t0 = now();
    memset(p, 1, TOUCH_BYTES);
    double t1 = now();
    memset(p, 2, TOUCH_BYTES);
    __asm__ volatile("" : : "r"(p) : "memory");
    r->sec = t1 - t0;
    r->again = now() - t1;
    r->p = p;
    return NULL;
}

static int touch_probe(void)
{
    touch_run one = {0}, two[2] = {{0}};
    touch(&one);
    pthread_t th;
    if (pthread_create(&th, NULL, touch, &two[1]) != 0)
        return 1;
    touch(&two[0]);
    pthread_join(th, NULL);
    const void *maps[3] = {one.p, two[0].p, two[1].p};
    for (int k = 0; k < 3; k++)
        if (maps[k])
            munmap((void *)maps[k], TOUCH_BYTES);
    if (one.sec <= 0.0 || two[0].sec <= 0.0 || two[1].sec <= 0.0)
        return 1;
    const double gb = (double)TOUCH_BYTES / 1e9;
    printf("touch fresh memory: 1 thread %.2f GB/s, 2 threads at once %.2f and %.2f GB/s each; "
           "rewriting it %.1f GB/s\n",
           gb / one.sec, gb / two[0].sec, gb / two[1].sec, gb / one.again);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "touch") == 0)
        return touch_probe();
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
