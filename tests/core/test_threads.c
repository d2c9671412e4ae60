/* SPDX-License-Identifier: MIT */
/*
 * test_threads.c -- the thread rule (docs/ARCHITECTURE.md "Threads", issue 40): GKS
 * belongs to the thread that opened it until CLOSE GKS; a call from another thread is
 * refused with error 950 (through ERROR HANDLING, or in an inquiry's error indicator) and
 * changes nothing. Three parts, each with two threads:
 *  - the owner draws 300 frames of polylines on a PNG workstation while a second thread
 *    calls output, attribute, control, segment, input and inquiry functions 300 times
 *    each: every call is refused, the owner's state is as the owner left it, the owner
 *    sees no error;
 *  - after CLOSE GKS a second thread opens GKS, draws and closes it: no error;
 *  - two threads call OPEN GKS at the same moment, 50 times: exactly one opens it.
 * Built and run under ThreadSanitizer too (docs/ARCHITECTURE.md gives the command): no
 * data race is reported.
 */
#include <gks.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { E_THREAD = 950, N = 300 };

static atomic_int n_refused, n_other, last_other;
static _Thread_local int my_errors; /* errors reported in the calling thread */

static void handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    my_errors++;
    if (err == E_THREAD) {
        atomic_fetch_add(&n_refused, 1);
    } else {
        atomic_fetch_add(&n_other, 1);
        atomic_store(&last_other, err);
    }
}

static int failures;
#define CHECK(c)                                                                         \
    do {                                                                                 \
        if (!(c)) {                                                                      \
            printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #c);                          \
            failures++;                                                                  \
        }                                                                                \
    } while (0)

static atomic_int stop;

/* The second thread: every kind of call, each refused. */
static void *intruder(void *arg)
{
    int *inq_bad = arg;
    Gpoint p[2] = { { 0, 0 }, { 1, 1 } };
    for (int i = 0; i < N; i++) {
        gpolyline(&(Gpoint_list){ 2, p });
        gset_line_colr_ind(7);
        gset_win(1, &(Glimit){ 0, 2, 0, 2 });
        gopen_ws(5, "threads_intruder.png", GWS_TYPE_PNG);
        gupd_ws(1, GFLAG_PERFORM);
        gcreate_seg(9);
        gset_loc_mode(1, 1, GOP_EVENT, GSWITCH_ECHO);
        gclose_ws(1);
        gclose_gks();
        gopen_gks(NULL, 0);
        gemergency_close_gks();
        gset_err_hand(NULL, NULL);
        Gop_st op = (Gop_st)-1;
        ginq_op_st(&op);
        if (op != (Gop_st)-1)
            (*inq_bad)++;
        Gint err = 0, ci = -1, n = -1, id;
        ginq_line_colr_ind(&err, &ci);
        *inq_bad += err != E_THREAD || ci != -1;
        err = 0;
        Gint_list l = { 1, &id };
        ginq_set_open_wss(1, 0, &err, &l, &n);
        *inq_bad += err != E_THREAD || n != -1;
        Gtran t;
        err = 0;
        ginq_norm_tran(1, &err, &t);
        *inq_bad += err != E_THREAD;
        Gint in_h = -1, last = -1;
        ginq_err_st(&in_h, &last);
        *inq_bad += in_h != -1 || last != -1;
    }
    atomic_store(&stop, 1);
    return NULL;
}

/* calls per iteration of intruder() that report 950 through the handler */
enum { HANDLER_CALLS = 13 };

static void part_refused(void)
{
    gset_err_hand(handler, NULL);
    gopen_gks(NULL, 0);
    unlink("threads_owner.png");
    gopen_ws(1, "threads_owner.png", GWS_TYPE_PNG);
    gset_ws_vp(1, &(Glimit){ 0, 64, 0, 64 });
    gactivate_ws(1);
    gset_line_colr_ind(2);
    int inq_bad = 0;
    pthread_t t;
    CHECK(pthread_create(&t, NULL, intruder, &inq_bad) == 0);
    int frames = 0;
    for (; frames < N || !atomic_load(&stop); frames++) {
        for (int k = 0; k < 20; k++) {
            Gpoint p[3] = { { 0.05 * k, 0.1 }, { 0.5, 0.9 }, { 0.9, 0.05 * k } };
            gpolyline(&(Gpoint_list){ 3, p });
        }
        Gint err, ci;
        ginq_line_colr_ind(&err, &ci);
        CHECK(err == 0 && ci == 2);
        gclear_ws(1, GFLAG_ALWAYS);
    }
    pthread_join(t, NULL);
    CHECK(my_errors == 0);
    CHECK(atomic_load(&n_other) == 0);
    CHECK(inq_bad == 0);
    CHECK(atomic_load(&n_refused) == N * HANDLER_CALLS);
    Gop_st op;
    ginq_op_st(&op);
    CHECK(op == GST_WSAC);
    Gint err, n, ids[4];
    Gint_list l = { 4, ids };
    ginq_set_open_wss(4, 0, &err, &l, &n);
    CHECK(err == 0 && n == 1 && ids[0] == 1);
    Gtran tr;
    ginq_norm_tran(1, &err, &tr);
    CHECK(err == 0 && tr.win.x_max == 1);
    Gint seg;
    ginq_name_open_seg(&err, &seg);
    CHECK(err == 4); /* no segment open */
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    CHECK(my_errors == 0);
    printf("refused: %d calls from the second thread while the owner drew %d frames\n",
           atomic_load(&n_refused), frames);
}

/* After CLOSE GKS any thread may open GKS. */
static void *second_owner(void *arg)
{
    (void)arg;
    gopen_gks(NULL, 0);
    gopen_ws(2, "threads_second.png", GWS_TYPE_PNG);
    gset_ws_vp(2, &(Glimit){ 0, 32, 0, 32 });
    gactivate_ws(2);
    Gpoint p[2] = { { 0, 0 }, { 1, 1 } };
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_gks();
    return (void *)(long)my_errors;
}

static void part_handover(void)
{
    pthread_t t;
    void *r = (void *)1;
    CHECK(pthread_create(&t, NULL, second_owner, NULL) == 0);
    pthread_join(t, &r);
    CHECK(r == NULL);
    Gop_st op;
    ginq_op_st(&op); /* back to this thread: GKS is closed, nobody owns it */
    CHECK(op == GST_GKCL);
    unlink("threads_second.png");
}

static pthread_barrier_t go;
static atomic_int n_opened;

static void *racer(void *arg)
{
    (void)arg;
    pthread_barrier_wait(&go);
    int before = my_errors;
    gopen_gks(NULL, 0);
    int opened = my_errors == before;
    pthread_barrier_wait(&go); /* both have tried */
    if (opened) {
        atomic_fetch_add(&n_opened, 1);
        gclose_gks();
    }
    return NULL;
}

static void part_race(void)
{
    for (int i = 0; i < 50; i++) {
        atomic_store(&n_opened, 0);
        pthread_barrier_init(&go, NULL, 2);
        pthread_t a, b;
        CHECK(pthread_create(&a, NULL, racer, NULL) == 0);
        CHECK(pthread_create(&b, NULL, racer, NULL) == 0);
        pthread_join(a, NULL);
        pthread_join(b, NULL);
        pthread_barrier_destroy(&go);
        CHECK(atomic_load(&n_opened) == 1);
    }
}

int main(void)
{
    part_refused();
    part_handover();
    part_race();
    unlink("threads_owner.png");
    printf(failures ? "THREADS FAIL %d\n" : "THREADS PASS\n", failures);
    return failures != 0;
}
