/* SPDX-License-Identifier: MIT */
/*
 * rt_par.c -- fork-join parallel loops for the stages before the first ray (commit and grid
 * build). rt_par_run(n, fn, arg) calls fn(arg, k, n) for k = 0 .. n-1, part 0 on the calling
 * thread; a part whose thread cannot be started runs on the caller after its own, so the
 * result never depends on how many threads really ran (callers split work by k and n only).
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

int rt_par_threads(int requested)
{
    long n = requested;
    if (n <= 0)
        n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        n = 1;
    return n > RT_PAR_MAX ? RT_PAR_MAX : (int)n;
}

typedef struct rt_par_part {
    rt_par_fn fn;
    void *arg;
    int k, n;
} rt_par_part;

static void *rt_par_main(void *p)
{
    const rt_par_part *q = p;
    q->fn(q->arg, q->k, q->n);
    return NULL;
}

void rt_par_run(int n, rt_par_fn fn, void *arg)
{
    if (n > RT_PAR_MAX)
        n = RT_PAR_MAX;
    if (n <= 1) {
        fn(arg, 0, 1);
        return;
    }
    pthread_t th[RT_PAR_MAX];
    rt_par_part part[RT_PAR_MAX];
    int started[RT_PAR_MAX] = {0};
    for (int k = 1; k < n; k++) {
        part[k] = (rt_par_part){fn, arg, k, n};
        started[k] = pthread_create(&th[k], NULL, rt_par_main, &part[k]) == 0;
    }
    fn(arg, 0, n);
    for (int k = 1; k < n; k++) {
        if (started[k])
            pthread_join(th[k], NULL);
        else
            fn(arg, k, n);
    }
}
