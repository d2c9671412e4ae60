/* SPDX-License-Identifier: MIT */
/*
 * rt_mpi.c -- dynamic tile distribution of one frame over MPI ranks (rt_mpi.h, docs/MPI.md).
 *
 * Messages (on the link's communicator, tags RT_MPI_TAG ..+2), ints unless said:
 *   REQ   rank k -> 0   {seq, want}          k wants up to `want` more tiles of frame seq
 *   GRANT 0 -> rank k   {seq, first, count}  tiles first .. first+count-1; count 0: none left
 *   TILE  rank k -> 0   {seq, tile} + payload (bytes, rt_frame_store's)
 * Rank 0 serves messages whenever one of its threads asks for a tile or hands one in, and
 * while it waits for the last remote tiles. A rank asks again when its queue is down to its
 * thread count, so a grant is on its way while it traces; chunks shrink with the tiles left
 * (guided), so the last tiles spread over all ranks.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_mpi.h"
#include "rt_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { TAG_REQ = RT_MPI_TAG, TAG_GRANT = RT_MPI_TAG + 1, TAG_TILE = RT_MPI_TAG + 2 };
enum { T_FREE = 0, T_GRANTED = 1, T_HERE = 2, T_DONE = 3 };
#define HDR (2 * sizeof(int))
#define NSEND ((int)(sizeof ((rt_mpi_job *)0)->send_req / sizeof(MPI_Request)))
#define QCAP ((int)(sizeof ((rt_mpi_job *)0)->queue / sizeof(int)))

static void nap(rt_mpi_job *j)
{
    struct timespec ts = {0, 50000}; /* 50 us between polls: a waiting rank yields its core */
    double t0 = rt_now();
    nanosleep(&ts, NULL);
    j->wait_seconds += rt_now() - t0;
}

int rt_mpi_link_init(rt_mpi_link *l, MPI_Comm comm, double timeout)
{
    memset(l, 0, sizeof *l);
    l->comm = comm;
    MPI_Comm_rank(l->comm, &l->rank);
    MPI_Comm_size(l->comm, &l->size);
    l->timeout = timeout > 0 ? timeout : 60.0;
    if (l->size < 1 || l->size > RT_MPI_MAX_RANKS)
        goto fail;
    l->lost = rt_calloc_array((size_t)l->size, 1);
    l->early_seq = rt_calloc_array((size_t)l->size, sizeof(int));
    l->early_want = rt_calloc_array((size_t)l->size, sizeof(int));
    if (!l->lost || !l->early_seq || !l->early_want)
        goto fail;
    return 0;
fail:
    rt_mpi_link_free(l);
    return -1;
}

void rt_mpi_link_free(rt_mpi_link *l)
{
    free(l->lost);
    free(l->early_seq);
    free(l->early_want);
    memset(l, 0, sizeof *l);
    l->comm = MPI_COMM_NULL;
}

/* a fault in this frame: rank `lost` is not waited for again; the first message is kept */
__attribute__((format(printf, 3, 4))) static void fault(rt_mpi_job *j, int lost, const char *fmt,
                                                        ...)
{
    j->fault = 1;
    j->l->lost[lost] = 1;
    if (j->msg[0])
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(j->msg, sizeof j->msg, fmt, ap);
    va_end(ap);
}

/* ---- rank 0 ------------------------------------------------------------------------------ */

static int grant(rt_mpi_job *j, int k, int want)
{
    rt_mpi_link *l = j->l;
    int first = j->free_from, count = 0;
    if (!l->lost[k]) {
        while (first < j->ntiles && j->state[first] != T_FREE)
            first++;
        int left = 0;
        for (int t = first; t < j->ntiles; t++)
            left += j->state[t] == T_FREE;
        int chunk = left / (2 * l->size); /* guided */
        if (chunk > want)
            chunk = want;
        if (chunk < 1)
            chunk = 1;
        while (first + count < j->ntiles && count < chunk && j->state[first + count] == T_FREE) {
            j->state[first + count] = T_GRANTED;
            j->owner[first + count] = k;
            count++;
        }
        if (count == 0)
            first = 0;
        j->out[k] += count;
        j->joined[k] = 1;
    }
    if (count == 0) /* k asks no more in this frame: every REQ has had its GRANT */
        j->finished[k] = 1;
    int msg[3] = {(int)j->seq, first, count};
    return MPI_Send(msg, 3, MPI_INT, k, TAG_GRANT, l->comm) == MPI_SUCCESS ? 0 : -1;
}

static int serve_(rt_mpi_job *j);

/* handles every message waiting; 0 or -1 (MPI failure, bad tile) */
static int serve(rt_mpi_job *j)
{
    double t0 = rt_now();
    int rc = serve_(j);
    j->serve_seconds += rt_now() - t0;
    return rc;
}

static int serve_(rt_mpi_job *j)
{
    rt_mpi_link *l = j->l;
    for (;;) {
        int flag = 0;
        MPI_Status st;
        if (MPI_Iprobe(MPI_ANY_SOURCE, TAG_REQ, l->comm, &flag, &st) != MPI_SUCCESS)
            return -1;
        if (!flag && MPI_Iprobe(MPI_ANY_SOURCE, TAG_TILE, l->comm, &flag, &st) != MPI_SUCCESS)
            return -1;
        if (!flag)
            return 0;
        int k = st.MPI_SOURCE;
        if (st.MPI_TAG == TAG_REQ) {
            int m[2];
            if (MPI_Recv(m, 2, MPI_INT, k, TAG_REQ, l->comm, MPI_STATUS_IGNORE) != MPI_SUCCESS)
                return -1;
            j->heard[k] = rt_now();
            if ((unsigned)m[0] == j->seq) {
                if (grant(j, k, m[1]))
                    return -1;
            } else if ((unsigned)m[0] == j->seq + 1) { /* a rank already at the next frame */
                l->early_seq[k] = m[0];
                l->early_want[k] = m[1];
            } else { /* an old frame: nothing left there */
                int g[3] = {m[0], 0, 0};
                if (MPI_Send(g, 3, MPI_INT, k, TAG_GRANT, l->comm) != MPI_SUCCESS)
                    return -1;
            }
        } else if (st.MPI_TAG == TAG_TILE) {
            int n = 0;
            MPI_Get_count(&st, MPI_BYTE, &n);
            if (n < (int)HDR || (size_t)n > HDR + j->max_bytes) {
                MPI_Recv(NULL, 0, MPI_BYTE, k, TAG_TILE, l->comm, MPI_STATUS_IGNORE);
                return -1;
            }
            if (MPI_Recv(j->buf, n, MPI_BYTE, k, TAG_TILE, l->comm, MPI_STATUS_IGNORE) !=
                MPI_SUCCESS)
                return -1;
            j->heard[k] = rt_now();
            j->recv_bytes += n;
            int h[2];
            memcpy(h, j->buf, sizeof h);
            int t = h[1];
            /* a stale frame, or a tile given to another rank after k was found lost */
            if ((unsigned)h[0] != j->seq || t < 0 || t >= j->ntiles || j->state[t] != T_GRANTED ||
                j->owner[t] != k)
                continue;
            if (rt_frame_store(j->frame, t, j->buf + HDR, (size_t)n - HDR) != RT_OK)
                return -1;
            j->state[t] = T_DONE;
            j->out[k]--;
            j->complete++;
        }
    }
}

/* ranks owing tiles that have been silent too long: lost, their tiles free again */
static void check_silent(rt_mpi_job *j)
{
    double now = rt_now();
    for (int k = 1; k < j->l->size; k++)
        if (j->out[k] > 0 && now - j->heard[k] > j->l->timeout) {
            fault(j, k, "rank %d sent nothing for %.0f s while tracing tiles of frame %u: "
                  "found lost, its tiles traced on rank 0", k, j->l->timeout, j->seq);
            for (int t = 0; t < j->ntiles; t++)
                if (j->state[t] == T_GRANTED && j->owner[t] == k)
                    j->state[t] = T_FREE;
            j->free_from = 0;
            j->out[k] = 0;
        }
}

static int remote_out(const rt_mpi_job *j)
{
    int n = 0;
    for (int k = 1; k < j->l->size; k++)
        n += j->out[k];
    return n;
}

static int r0_begin(void *u, rt_frame *f, int ntiles, size_t max_bytes)
{
    rt_mpi_job *j = u;
    rt_mpi_link *l = j->l;
    size_t n = (size_t)l->size;
    j->frame = f;
    j->ntiles = ntiles;
    j->max_bytes = max_bytes;
    j->state = rt_calloc_array((size_t)ntiles, 1);
    j->owner = rt_calloc_array((size_t)ntiles, sizeof(int));
    j->out = rt_calloc_array(n, sizeof(int));
    j->heard = rt_calloc_array(n, sizeof(double));
    j->joined = rt_calloc_array(n, 1);
    j->finished = rt_calloc_array(n, 1);
    j->buf = rt_alloc_array(1, HDR + max_bytes);
    if (!j->state || !j->owner || !j->out || !j->heard || !j->joined || !j->finished || !j->buf)
        return RT_ERR_NOMEM;
    double now = rt_now();
    for (size_t k = 0; k < n; k++)
        j->heard[k] = now;
    j->joined[0] = 1;
    for (int k = 1; k < l->size; k++) /* requests that came before this frame started */
        if ((unsigned)l->early_seq[k] == j->seq) {
            l->early_seq[k] = 0;
            if (grant(j, k, l->early_want[k]))
                return RT_ERR_HOOK;
        }
    return serve(j) ? RT_ERR_HOOK : 0;
}

static int r0_next(void *u)
{
    rt_mpi_job *j = u;
    for (;;) {
        if (serve(j))
            return RT_ERR_HOOK;
        while (j->free_from < j->ntiles && j->state[j->free_from] != T_FREE)
            j->free_from++;
        if (j->free_from < j->ntiles) {
            j->state[j->free_from] = T_HERE;
            j->tiles_here++;
            return j->free_from++;
        }
        if (remote_out(j) == 0)
            return -1; /* the rest is in progress here */
        check_silent(j);
        nap(j);
    }
}

static int r0_done(void *u, int tile, const void *payload, size_t bytes)
{
    rt_mpi_job *j = u;
    (void)payload;
    (void)bytes;
    j->state[tile] = T_DONE;
    j->complete++;
    return serve(j) ? RT_ERR_HOOK : 0;
}

static int r0_end(void *u, rt_frame *f)
{
    rt_mpi_job *j = u;
    (void)f;
    if (j->complete != j->ntiles)
        return RT_ERR_HOOK; /* a thread stopped early (a failed callback) */
    /* every rank takes part in every frame and asks until it is told "no more", so no
       message is left over; one that does not within the timeout (its workstation did not
       open, it died before the frame) is lost: reported, never waited for again */
    for (int k = 1; k < j->l->size; k++) {
        while (!j->finished[k] && !j->l->lost[k]) {
            if (serve(j))
                return RT_ERR_HOOK;
            if (rt_now() - j->heard[k] > j->l->timeout)
                fault(j, k, "rank %d did not take part in frame %u within %.0f s: found lost "
                      "(could it not open its workstation?)", k, j->seq, j->l->timeout);
            else
                nap(j);
        }
    }
    return 1;
}

/* ---- other ranks ------------------------------------------------------------------------- */

static int ask(rt_mpi_job *j)
{
    int want = 2 * j->threads;
    if (want > QCAP - j->qn)
        want = QCAP - j->qn;
    int m[2] = {(int)j->seq, want};
    if (MPI_Send(m, 2, MPI_INT, 0, TAG_REQ, j->l->comm) != MPI_SUCCESS)
        return -1;
    j->asked = 1;
    return 0;
}

/* takes a grant if one is there (block: waits up to the timeout); 0 or -1 */
static int take_grant(rt_mpi_job *j, int block)
{
    double t0 = rt_now();
    for (;;) {
        int flag = 0;
        MPI_Status st;
        if (MPI_Iprobe(0, TAG_GRANT, j->l->comm, &flag, &st) != MPI_SUCCESS)
            return -1;
        if (flag) {
            int g[3];
            if (MPI_Recv(g, 3, MPI_INT, 0, TAG_GRANT, j->l->comm, MPI_STATUS_IGNORE) !=
                MPI_SUCCESS)
                return -1;
            if ((unsigned)g[0] != j->seq)
                continue; /* answer to an old frame's request */
            j->asked = 0;
            if (g[2] <= 0 || g[1] < 0 || g[2] > QCAP - j->qn || g[1] + g[2] > j->ntiles) {
                j->ended = 1;
                return g[2] <= 0 ? 0 : -1;
            }
            for (int t = 0; t < g[2]; t++)
                j->queue[(j->qh + j->qn++) % QCAP] = g[1] + t;
            return 0;
        }
        if (!block)
            return 0;
        if (rt_now() - t0 > j->l->timeout) {
            fault(j, 0, "rank 0 did not answer rank %d for %.0f s in frame %u", j->l->rank,
                  j->l->timeout, j->seq);
            return -1;
        }
        nap(j);
    }
}

static int rk_begin(void *u, rt_frame *f, int ntiles, size_t max_bytes)
{
    rt_mpi_job *j = u;
    j->frame = f;
    j->ntiles = ntiles;
    j->max_bytes = max_bytes;
    if (j->l->lost[0])
        return RT_ERR_HOOK; /* rank 0 is gone: nobody to trace for */
    return ask(j) ? RT_ERR_HOOK : 0;
}

static int rk_next(void *u)
{
    rt_mpi_job *j = u;
    if (j->asked && take_grant(j, 0))
        return RT_ERR_HOOK;
    while (j->qn == 0) {
        if (j->ended)
            return -1;
        if (!j->asked && ask(j))
            return RT_ERR_HOOK;
        if (take_grant(j, 1))
            return RT_ERR_HOOK;
    }
    int t = j->queue[j->qh];
    j->qh = (j->qh + 1) % QCAP;
    j->qn--;
    if (j->qn <= j->threads && !j->asked && !j->ended && ask(j))
        return RT_ERR_HOOK;
    j->tiles_here++;
    return t;
}

/* waits for send slot s to complete (up to the timeout); 0 or -1 */
static int send_wait(rt_mpi_job *j, int s)
{
    double t0 = rt_now();
    for (;;) {
        int flag = 0;
        if (MPI_Test(&j->send_req[s], &flag, MPI_STATUS_IGNORE) != MPI_SUCCESS)
            return -1;
        if (flag)
            return 0;
        if (rt_now() - t0 > j->l->timeout) {
            fault(j, 0, "rank 0 took no tile from rank %d for %.0f s in frame %u", j->l->rank,
                  j->l->timeout, j->seq);
            return -1;
        }
        nap(j);
    }
}

static int rk_done(void *u, int tile, const void *payload, size_t bytes)
{
    rt_mpi_job *j = u;
    int s = j->nsend % NSEND;
    if (j->nsend >= NSEND && send_wait(j, s))
        return RT_ERR_HOOK;
    if (!j->send_buf[s] && !(j->send_buf[s] = rt_alloc_array(1, HDR + j->max_bytes)))
        return RT_ERR_NOMEM;
    int h[2] = {(int)j->seq, tile};
    memcpy(j->send_buf[s], h, HDR);
    memcpy(j->send_buf[s] + HDR, payload, bytes);
    if (MPI_Isend(j->send_buf[s], (int)(HDR + bytes), MPI_BYTE, 0, TAG_TILE, j->l->comm,
                  &j->send_req[s]) != MPI_SUCCESS)
        return RT_ERR_HOOK;
    j->nsend++;
    j->sent_bytes += (long)(HDR + bytes);
    return 0;
}

static int rk_end(void *u, rt_frame *f)
{
    rt_mpi_job *j = u;
    (void)f;
    int n = j->nsend < NSEND ? j->nsend : NSEND;
    for (int s = 0; s < n; s++)
        if (send_wait(j, s))
            return RT_ERR_HOOK;
    j->nsend = 0;
    return 0;
}

/* ---- job --------------------------------------------------------------------------------- */

const rt_tile_hook *rt_mpi_job_start(rt_mpi_job *j, rt_mpi_link *l, int threads)
{
    memset(j, 0, sizeof *j);
    j->l = l;
    j->threads = threads > 0 ? threads : 1;
    if (j->threads > QCAP / 4)
        j->threads = QCAP / 4;
    j->seq = ++l->seq;
    for (int s = 0; s < NSEND; s++)
        j->send_req[s] = MPI_REQUEST_NULL;
    if (l->rank == 0)
        j->hook = (rt_tile_hook){j, r0_begin, r0_next, r0_done, r0_end};
    else
        j->hook = (rt_tile_hook){j, rk_begin, rk_next, rk_done, rk_end};
    return &j->hook;
}

int rt_mpi_job_finish(rt_mpi_job *j)
{
    for (int s = 0; s < NSEND; s++) {
        int flag = 1;
        if (j->send_req[s] != MPI_REQUEST_NULL)
            MPI_Test(&j->send_req[s], &flag, MPI_STATUS_IGNORE);
        if (flag)
            free(j->send_buf[s]);
        else /* after a fault only: the buffer must outlive the send, so it is left */
            MPI_Request_free(&j->send_req[s]);
    }
    free(j->state);
    free(j->owner);
    free(j->out);
    free(j->heard);
    free(j->joined);
    free(j->finished);
    free(j->buf);
    j->state = NULL;
    j->owner = NULL;
    j->out = NULL;
    j->heard = NULL;
    j->joined = NULL;
    j->finished = NULL;
    j->buf = NULL;
    return j->fault;
}
