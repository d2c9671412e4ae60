/* SPDX-License-Identifier: MIT */
/*
 * rt_mpi_bench.c -- the tracer's frame shared by MPI ranks (src/rt/rt_mpi.h), measured for the
 * cost model of docs/MPI.md. Run under mpirun (it calls MPI itself, as a program that uses
 * MPI would):
 *
 *   mpirun -n N rt_mpi_bench SCENE [-s SIZE] [-t THREADS] [-reps R] [-depth D] [-sphere NU]
 *
 * Every rank loads SCENE (NFF/OFF) and builds the grid (replicated, timed), then traces
 * R frames (SPD corner rays, no cut-off) with the tile hook; rank 0 prints one line of
 * figures, each the best of the R frames where it is a time:
 *   build     scene build on each rank, CPU s (max over ranks; replicated work)
 *   setup     rt_render's per-frame work before the first tile (eye-ray lists, light
 *             buffers; replicated on every rank), CPU s of the calling thread
 *   wall      rank 0's rt_render time for the whole frame
 *   tile CPU  thread CPU time of all tiles (sum over ranks; robust against other load),
 *             per tile mean and max, and per rank (its share: the load balance)
 *   imbalance max over ranks of (tile CPU / threads) divided by its mean
 *   gather    bytes received by rank 0 and its time serving (receiving, storing, granting)
 *   identical the distributed picture equals rank 0's one-process picture bit for bit
 * and the load average (/proc/loadavg) when the line was printed.
 */
#include "gksrt.h"
#include "rt_mpi.h"
#include "rt_testutil.h"

#include <math.h>
#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double thread_cpu(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* wraps rt_mpi's hook: thread CPU time of each tile, time to the first tile */
typedef struct wrap {
    const rt_tile_hook *in;
    double t_call, t_begin; /* rt_render called / begin reached (calling thread's CPU) */
    double cpu_sum, cpu_max;
    long tiles;
} wrap;
static _Thread_local double tile_t0;

static int w_begin(void *u, rt_frame *f, int n, size_t b)
{
    wrap *w = u;
    w->t_begin = thread_cpu();
    return w->in->begin(w->in->user, f, n, b);
}
static int w_next(void *u)
{
    wrap *w = u;
    int t = w->in->next(w->in->user);
    tile_t0 = thread_cpu();
    return t;
}
static int w_done(void *u, int tile, const void *p, size_t b)
{
    wrap *w = u;
    double c = thread_cpu() - tile_t0;
    w->cpu_sum += c;
    if (c > w->cpu_max)
        w->cpu_max = c;
    w->tiles++;
    return w->in->done(w->in->user, tile, p, b);
}
static int w_end(void *u, rt_frame *f)
{
    wrap *w = u;
    return w->in->end(w->in->user, f);
}

static double load1(void)
{
    double l = -1;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1;
        fclose(f);
    }
    return l;
}

int main(int argc, char **argv)
{
    int level = 0, rank = 0, size = 1;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &level);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (argc < 2) {
        if (rank == 0)
            fprintf(stderr, "usage: rt_mpi_bench SCENE [-s SIZE] [-t THREADS] [-reps R] [-depth D] [-sphere NU]\n");
        MPI_Finalize();
        return 1;
    }
    const char *path = argv[1];
    int sz = 513, threads = 1, reps = 3, depth = 5, sphere = 0;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "-s") && i + 1 < argc) sz = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-t") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-depth") && i + 1 < argc) depth = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-sphere") && i + 1 < argc) sphere = atoi(argv[++i]);
    }
    if (level < MPI_THREAD_SERIALIZED)
        threads = 1;
    rtu_mesh m;
    double bb[6];
    if (rtu_load_scene_vrc(path, &m, bb) != 0) {
        fprintf(stderr, "cannot load %s\n", path);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    double tb0 = thread_cpu();
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    s.ka = 0.1;
    s.kd = 0.8;
    int sid = rt_scene_add_surface(sc, &s);
    if (!m.nlights) {
        rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {-0.3, -0.5, -1}};
        rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
        rt_scene_add_light(sc, &l);
        rt_scene_add_light(sc, &a);
    }
    /* -sphere NU: a lat-long sphere of about NU * NU triangles in front of the scene (build
       time at large triangle counts) */
    const double sc_c[3] = {0.5 * (bb[0] + bb[3]), 0.5 * (bb[1] + bb[4]), bb[5]};
    if (sphere > 2 && rtu_add_sphere(sc, sc_c, 0.1 * (bb[3] - bb[0]), sphere, sphere / 2, sid)) {
        fprintf(stderr, "sphere failed\n");
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    if (rtu_mesh_add(&m, sc, sid) != 0 || rt_scene_commit(sc, NULL) != RT_OK) {
        fprintf(stderr, "scene build failed\n");
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    double tbuild = thread_cpu() - tb0, tbuild_max = 0;
    MPI_Reduce(&tbuild, &tbuild_max, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    rtu_view v;
    rtu_nff_view(&m, bb, &v);
    double vm[4][4];
    rtu_view_matrix(&v, vm);
    rt_camera cam;
    if (rt_camera_from_view(&cam, vm, v.vp, sz, sz) != RT_OK)
        MPI_Abort(MPI_COMM_WORLD, 1);
    rt_render_options ro;
    rt_render_options_default(&ro);
    ro.threads = threads;
    ro.cutoff = 0.0;
    ro.max_depth = depth;
    memcpy(ro.background, m.bg, sizeof ro.background);
    size_t npx = (size_t)sz * sz * 3;
    float *rgb = malloc(npx * sizeof(float)), *ref = malloc(npx * sizeof(float));
    rt_mpi_link link;
    if (rt_mpi_link_init(&link, MPI_COMM_WORLD, 120.0))
        MPI_Abort(MPI_COMM_WORLD, 1);
    double best_wall = 1e30, best_setup = 1e30, best_serve = 0, cpu_sum = 0, cpu_max = 0;
    long recv = 0, tiles = 0, ntiles = 0;
    double share_best[2] = {0, 0}; /* this rank's tile CPU in the best frame, tiles */
    for (int r = 0; r < reps; r++) {
        rt_mpi_job j;
        wrap w = {.in = rt_mpi_job_start(&j, &link, threads)};
        rt_tile_hook h = {&w, w_begin, w_next, w_done, w_end};
        ro.tiles = &h;
        MPI_Barrier(MPI_COMM_WORLD);
        double w0 = wall();
        w.t_call = thread_cpu();
        int rc = rt_render(sc, &cam, &ro, rgb, NULL);
        double tw = wall() - w0;
        if (rc != RT_OK || rt_mpi_job_finish(&j)) {
            fprintf(stderr, "rank %d: frame failed (%d): %s\n", rank, rc, j.msg);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        if (tw < best_wall) { /* every figure from rank 0's best frame */
            best_wall = tw;
            best_setup = w.t_begin - w.t_call;
            best_serve = j.serve_seconds;
            recv = j.recv_bytes;
            ntiles = j.ntiles;
            share_best[0] = w.cpu_sum;
            share_best[1] = (double)w.tiles;
            cpu_sum = w.cpu_sum;
            cpu_max = w.cpu_max;
            tiles = w.tiles;
        }
    }
    /* a frame's figures per rank come from that rank's own best frame: the frames differ
       little, and a common frame would need one more round of messages per frame */
    double *shares = rank == 0 ? malloc(2 * (size_t)size * sizeof(double)) : NULL;
    MPI_Gather(share_best, 2, MPI_DOUBLE, shares, 2, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    (void)cpu_sum;
    (void)tiles;
    double setup_max = 0;
    MPI_Reduce(&best_setup, &setup_max, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    double cmax = 0;
    MPI_Reduce(&cpu_max, &cmax, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    if (rank == 0) {
        rt_render_options one = ro;
        one.tiles = NULL;
        double t0 = wall();
        rt_stats pr;
        rt_render(sc, &cam, &one, ref, &pr);
        double tone = wall() - t0;
        int same = memcmp(ref, rgb, npx * sizeof(float)) == 0;
        double total = 0, busy_max = 0;
        long tl = 0;
        for (int k = 0; k < size; k++) {
            total += shares[2 * k];
            tl += (long)shares[2 * k + 1];
            if (shares[2 * k] > busy_max)
                busy_max = shares[2 * k];
        }
        double mean = total / size;
        printf("%s %dx%d N=%d T=%d: prims %llu, build %.3f s, setup %.4f s, wall %.3f s (alone on rank 0, "
               "no hook: %.3f s), tiles %ld (%ld counted), tile CPU %.3f s (mean %.2f ms, max "
               "%.2f ms), per rank",
               path, sz, sz, size, threads, (unsigned long long)pr.prims, tbuild_max, setup_max, best_wall, tone, ntiles, tl,
               total, 1e3 * total / (tl ? tl : 1), 1e3 * cmax);
        for (int k = 0; k < size; k++)
            printf(" %.3f/%ld", shares[2 * k], (long)shares[2 * k + 1]);
        printf(", imbalance %.3f, gather %ld bytes, serve %.4f s, scene memory %.1f MB, "
               "identical %s, load %.2f\n", mean > 0 ? busy_max / mean : 0.0, recv, best_serve,
               pr.memory_bytes / 1e6, same ? "yes" : "NO", load1());
        free(shares);
    }
    rt_mpi_link_free(&link);
    free(rgb);
    free(ref);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
    MPI_Finalize();
    return 0;
}
