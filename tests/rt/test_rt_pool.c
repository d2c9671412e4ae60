/* SPDX-License-Identifier: MIT */
/*
 * test_rt_pool.c -- the tracer's thread pool (src/rt/rt_pool.c): every part of a fork-join
 * loop runs exactly once, also nested in a part and from several threads at once; an ordered
 * queue runs its items one at a time in push order, its effects visible after the drain, and
 * is refused for one thread (the caller then works alone).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

typedef struct parts {
    atomic_int ran[RT_PAR_MAX];
    atomic_int bad;
    int nested;
} parts;

static void count_part(void *arg, int k, int n)
{
    parts *p = arg;
    if (k < 0 || k >= n || n > RT_PAR_MAX)
        atomic_fetch_add(&p->bad, 1);
    else
        atomic_fetch_add(&p->ran[k], 1);
    if (p->nested) { /* a loop inside a part: runs to completion too */
        parts q;
        memset(&q, 0, sizeof q);
        rt_par_run(3, count_part, &q);
        for (int j = 0; j < 3; j++)
            if (atomic_load(&q.ran[j]) != 1)
                atomic_fetch_add(&p->bad, 1);
    }
}

static void check_run(int n, int nested)
{
    parts p;
    memset(&p, 0, sizeof p);
    p.nested = nested;
    rt_par_run(n, count_part, &p);
    int m = n < 1 ? 1 : n;
    for (int k = 0; k < RT_PAR_MAX; k++)
        assert_int_equal(atomic_load(&p.ran[k]), k < m ? 1 : 0);
    assert_int_equal(atomic_load(&p.bad), 0);
}

static void test_par_run(void **u)
{
    (void)u;
    for (int n = 0; n <= 9; n++)
        check_run(n, 0);
    check_run(RT_PAR_MAX, 0);
    check_run(4, 1);
    assert_int_equal(rt_par_threads(1), 1);
    assert_int_equal(rt_par_threads(5), 5);
    assert_true(rt_par_threads(0) >= 1);
    assert_int_equal(rt_par_threads(100000), RT_PAR_MAX);
}

static void *caller(void *arg)
{
    (void)arg;
    for (int i = 0; i < 50; i++)
        check_run(1 + i % 5, i % 7 == 0);
    return NULL;
}

/* loops from several threads at once share the pool: each gets all its parts */
static void test_par_concurrent(void **u)
{
    (void)u;
    pthread_t th[4];
    for (int i = 0; i < 4; i++)
        assert_int_equal(pthread_create(&th[i], NULL, caller, NULL), 0);
    for (int i = 0; i < 4; i++)
        pthread_join(th[i], NULL);
}

typedef struct seq {
    int *got;
    int n;
    atomic_int inside, overlap;
} seq;

static void take(void *user, void *item)
{
    seq *s = user;
    if (atomic_fetch_add(&s->inside, 1) != 0)
        atomic_fetch_add(&s->overlap, 1);
    s->got[s->n++] = *(int *)item;
    free(item);
    atomic_fetch_sub(&s->inside, 1);
}

static void test_serial(void **u)
{
    (void)u;
    seq s = { 0 };
    assert_null(rt_serial_new(1, take, &s)); /* one thread: no queue */
    assert_null(rt_serial_new(2, NULL, &s));
    const int N = 5000;
    s.got = calloc((size_t)N, sizeof *s.got);
    assert_non_null(s.got);
    rt_serial *q = rt_serial_new(2, take, &s);
    assert_non_null(q);
    for (int round = 0; round < 3; round++) {
        for (int i = 0; i < N / 3; i++) {
            int *v = malloc(sizeof *v);
            assert_non_null(v);
            *v = round * (N / 3) + i;
            rt_serial_push(q, v);
        }
        rt_serial_drain(q); /* everything pushed so far has run, in order */
        assert_int_equal(s.n, (round + 1) * (N / 3));
        for (int i = 0; i < s.n; i++)
            assert_int_equal(s.got[i], i);
    }
    assert_int_equal(atomic_load(&s.overlap), 0);
    rt_serial_free(q);
    rt_serial_free(NULL);
    rt_serial_drain(NULL);
    free(s.got);
}

/* an item that runs until the test opens its gate */
typedef struct gate {
    atomic_int started, open;
} gate;

static void hold(void *user, void *item)
{
    gate *g = user;
    if (item) {
        atomic_store(&g->started, 1);
        while (!atomic_load(&g->open))
            sched_yield();
    }
}

/* rt_serial_full says 1 exactly when a push would wait: 32 items queued while one runs */
static void test_serial_full(void **u)
{
    (void)u;
    gate g = { 0 };
    rt_serial *q = rt_serial_new(2, hold, &g);
    assert_non_null(q);
    assert_int_equal(rt_serial_full(q), 0);
    rt_serial_push(q, &g); /* runs on the worker and holds it */
    while (!atomic_load(&g.started))
        sched_yield();
    for (int i = 0; i < 32; i++) {
        assert_int_equal(rt_serial_full(q), 0);
        rt_serial_push(q, NULL);
    }
    assert_int_equal(rt_serial_full(q), 1);
    atomic_store(&g.open, 1);
    rt_serial_drain(q);
    assert_int_equal(rt_serial_full(q), 0);
    rt_serial_free(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_par_run),
        cmocka_unit_test(test_par_concurrent),
        cmocka_unit_test(test_serial),
        cmocka_unit_test(test_serial_full),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
