/* SPDX-License-Identifier: MIT */
/*
 * rt_pool.c -- the tracer's one thread pool. Worker threads are started on first use and
 * kept for the life of the process, grown to the largest thread count a caller asked for
 * (rt_build_options.threads, rt_render_options.threads, rt_serial_new; 0 = online CPUs).
 * They run queued parts: the parts of fork-join loops (rt_pool_run: the commit, the grid
 * build, the render's tiles) and the items of ordered queues (rt_serial: the workstation's
 * recording while the application draws).
 *
 * A caller waiting for its parts runs its own parts that no worker has taken yet, so nothing
 * waits for a busy worker: concurrent and nested calls cannot deadlock, and a part whose
 * worker could not be started runs on the caller. Callers split work by (k, n) only, so
 * results never depend on how many threads really ran.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

/* ---- the pool ---- */

typedef struct rt_pool_group rt_pool_group;

/* one queued part: fn(arg, k, n), counted in its group */
typedef struct rt_pool_task {
    rt_par_fn fn;
    void *arg;
    int k, n;
    rt_pool_group *g;
    struct rt_pool_task *next;
} rt_pool_task;

/* the parts a caller waits for: pending counts those not finished */
struct rt_pool_group {
    int pending;
};

static struct {
    pthread_mutex_t lock;
    pthread_cond_t work; /* a task was queued */
    pthread_cond_t done; /* a group's pending reached 0 */
    rt_pool_task *head, *tail;
    int workers;         /* threads started */
} pool = { PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, PTHREAD_COND_INITIALIZER,
           NULL, NULL, 0 };

int rt_par_threads(int requested)
{
    long n = requested;
    if (n <= 0)
        n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        n = 1;
    return n > RT_PAR_MAX ? RT_PAR_MAX : (int)n;
}

int rt_par_pool_threads(void)
{
    pthread_mutex_lock(&pool.lock);
    const int n = pool.workers + 1;
    pthread_mutex_unlock(&pool.lock);
    return n;
}

/* runs t (lock held on entry and exit) */
static void rt_pool_exec(rt_pool_task *t)
{
    pthread_mutex_unlock(&pool.lock);
    t->fn(t->arg, t->k, t->n);
    pthread_mutex_lock(&pool.lock);
    if (--t->g->pending == 0)
        pthread_cond_broadcast(&pool.done);
}

static rt_pool_task *rt_pool_pop(void)
{
    rt_pool_task *t = pool.head;
    if (t) {
        pool.head = t->next;
        if (!pool.head)
            pool.tail = NULL;
    }
    return t;
}

static void *rt_pool_main(void *unused)
{
    (void)unused;
    pthread_mutex_lock(&pool.lock);
    for (;;) {
        rt_pool_task *t = rt_pool_pop();
        if (t)
            rt_pool_exec(t);
        else
            pthread_cond_wait(&pool.work, &pool.lock);
    }
    return NULL;
}

/* at least want - 1 workers (the caller is the other thread), as far as they start; lock held */
static void rt_pool_grow(int want)
{
    while (pool.workers < want - 1) {
        pthread_t th;
        pthread_attr_t at;
        if (pthread_attr_init(&at) != 0)
            return;
        pthread_attr_setdetachstate(&at, PTHREAD_CREATE_DETACHED);
        int ok = pthread_create(&th, &at, rt_pool_main, NULL) == 0;
        pthread_attr_destroy(&at);
        if (!ok)
            return; /* fewer threads: the callers run the parts */
        pool.workers++;
    }
}

/* queues t (lock held) */
static void rt_pool_push(rt_pool_task *t)
{
    t->next = NULL;
    if (pool.tail)
        pool.tail->next = t;
    else
        pool.head = t;
    pool.tail = t;
    t->g->pending++;
    pthread_cond_signal(&pool.work);
}

/* waits until g has no part left, running its queued parts here (lock held) */
static void rt_pool_wait(rt_pool_group *g)
{
    while (g->pending > 0) {
        rt_pool_task **pp = &pool.head, *prev = NULL;
        while (*pp && (*pp)->g != g) {
            prev = *pp;
            pp = &(*pp)->next;
        }
        rt_pool_task *t = *pp;
        if (t) { /* not taken yet: run it here */
            *pp = t->next;
            if (pool.tail == t)
                pool.tail = prev;
            rt_pool_exec(t);
        } else {
            pthread_cond_wait(&pool.done, &pool.lock);
        }
    }
}

void rt_par_run(int n, rt_par_fn fn, void *arg)
{
    if (n > RT_PAR_MAX)
        n = RT_PAR_MAX;
    if (n <= 1) {
        fn(arg, 0, 1);
        return;
    }
    rt_pool_task task[RT_PAR_MAX];
    rt_pool_group g = { 0 };
    pthread_mutex_lock(&pool.lock);
    rt_pool_grow(n);
    for (int k = 1; k < n; k++) {
        task[k] = (rt_pool_task){ fn, arg, k, n, &g, NULL };
        rt_pool_push(&task[k]);
    }
    pthread_mutex_unlock(&pool.lock);
    fn(arg, 0, n);
    pthread_mutex_lock(&pool.lock);
    rt_pool_wait(&g);
    pthread_mutex_unlock(&pool.lock);
}

/* ---- ordered queues ---- */

/* Items queued at most: then the caller runs the oldest or waits. The workstation's recording
 * queues display-list chunks of 2048 areas (about 0.3 ms of the application's calls each);
 * its worker's cost per chunk is bursty (a chunk whose triangles start a fresh 2 MiB page
 * of the scene's arrays takes 0.3-6 ms against 0.1 ms), so a short queue makes the
 * application wait during a burst and the worker idle after it. 32 chunks (about 8 MB of
 * the list) absorb a burst: see docs/bench/scale.md, 2026-12-05 21:20 UTC. */
#define RT_SERIAL_CAP 32

struct rt_serial {
    rt_serial_fn fn;
    void *user;
    void *item[RT_SERIAL_CAP];
    int head, count;
    int running;         /* an item is being run (items run one at a time, in order) */
    int scheduled;       /* a drain task is queued or running in the pool */
    pthread_cond_t idle; /* running went to 0 */
    rt_pool_task task;
    rt_pool_group g;
};

rt_serial *rt_serial_new(int threads, rt_serial_fn fn, void *user)
{
    if (!fn || rt_par_threads(threads) < 2)
        return NULL;
    rt_serial *s = rt_calloc_array(1, sizeof *s);
    if (!s)
        return NULL;
    if (pthread_cond_init(&s->idle, NULL) != 0) {
        free(s);
        return NULL;
    }
    s->fn = fn;
    s->user = user;
    pthread_mutex_lock(&pool.lock);
    rt_pool_grow(rt_par_threads(threads));
    pthread_mutex_unlock(&pool.lock);
    return s;
}

/* runs the oldest item (lock held, s->running 0, s->count > 0) */
static void rt_serial_one(rt_serial *s)
{
    void *it = s->item[s->head];
    s->head = (s->head + 1) % RT_SERIAL_CAP;
    s->count--;
    s->running = 1;
    pthread_mutex_unlock(&pool.lock);
    s->fn(s->user, it);
    pthread_mutex_lock(&pool.lock);
    s->running = 0;
    pthread_cond_broadcast(&s->idle);
}

/* the pool's part of a queue: its items until none is left */
static void rt_serial_task(void *arg, int k, int n)
{
    (void)k, (void)n;
    rt_serial *s = arg;
    pthread_mutex_lock(&pool.lock);
    while (s->count > 0 && !s->running)
        rt_serial_one(s);
    s->scheduled = 0;
    pthread_mutex_unlock(&pool.lock);
}

void rt_serial_push(rt_serial *s, void *item)
{
    pthread_mutex_lock(&pool.lock);
    while (s->count == RT_SERIAL_CAP) { /* full: the oldest runs here or is running */
        if (!s->running)
            rt_serial_one(s);
        else
            pthread_cond_wait(&s->idle, &pool.lock);
    }
    s->item[(s->head + s->count) % RT_SERIAL_CAP] = item;
    s->count++;
    if (!s->scheduled && !s->running) {
        s->scheduled = 1;
        s->task = (rt_pool_task){ rt_serial_task, s, 0, 1, &s->g, NULL };
        rt_pool_push(&s->task);
    }
    pthread_mutex_unlock(&pool.lock);
}

int rt_serial_full(rt_serial *s)
{
    pthread_mutex_lock(&pool.lock);
    const int full = s->count == RT_SERIAL_CAP && s->running;
    pthread_mutex_unlock(&pool.lock);
    return full;
}

void rt_serial_drain(rt_serial *s)
{
    if (!s)
        return;
    pthread_mutex_lock(&pool.lock);
    while (s->count > 0 || s->running) {
        if (!s->running)
            rt_serial_one(s);
        else
            pthread_cond_wait(&s->idle, &pool.lock);
    }
    rt_pool_wait(&s->g); /* the drain task, if queued, finds nothing left */
    pthread_mutex_unlock(&pool.lock);
}

void rt_serial_free(rt_serial *s)
{
    if (!s)
        return;
    rt_serial_drain(s);
    pthread_cond_destroy(&s->idle);
    free(s);
}
