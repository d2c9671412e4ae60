/* SPDX-License-Identifier: MIT */
/*
 * bench_gks.c -- the output pipeline through the whole GKS call path (issue 3,
 * Performance): a PNG workstation of 1024 x 1024 pixels in HLHSR mode z-buffer, one
 * thread, drawing
 *   tri16 N   N random FILL AREA 3 triangles, vertices uniform in a 16 x 16 px box
 *   tri128 N  the same in a 128 x 128 px box
 *   walk M    one POLYLINE 3 of M points, a random walk with steps in [-2, 2) px
 * for N = 10^4, 10^5, 10^6 and M = 10^7, and the same workload (same numbers) drawn by
 * Mesa's llvmpipe through OSMesa (when built with it: LP_NUM_THREADS=0, one thread,
 * client vertex arrays, depth test GL_GREATER as GKS's "larger z is nearer").
 * Both sides first draw an empty frame (buffers allocated and touched), then the timed
 * frame. Timed, in CPU seconds of the process (wall seconds in brackets; the machines
 * are shared): GKS: CLEAR WORKSTATION + the primitives + UPDATE WORKSTATION, which
 * box-filters to 8 bits and writes the PNG file with the workstation's default (fast)
 * encoder settings (more than OSMesa's read-back; "upd" is that part alone); OSMesa:
 * glClear + draw + glFinish + glReadPixels, and apart from that the time to write the
 * read-back as a PNG file with the same encoder settings (zlib run-length strategy, SUB
 * filter): "GKS/(llvmpipe+PNG)" compares like with like, two programs that each leave
 * the picture in a PNG file. Each run is a child process: its peak resident memory (getrusage
 * ru_maxrss of the child) includes the generated input (24 B per GKS point).
 * Usage: bench_gks [-g] [-m K] [rows...]  with rows tri16:N, tri128:N, walk:M or "all" (the
 * default); -g: GKS only (no llvmpipe run), e.g. for profiling; -m K: HLHSR mode K
 * (default 2, z-buffer; 1 hidden line and 3 painter retain the frame's primitives).
 * The pictures go to the working directory (bench_gks.png: the empty frame,
 * bench_gks-002.png: the timed one).
 */
#include <gks.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef HAVE_OSMESA
#include <GL/osmesa.h>
#include <png.h>
#include <setjmp.h>
#include <zlib.h>
#include <GL/gl.h>
#endif

enum { SIZE = 1024 };
static double wall_sec; /* wall time of the last run (child) */
static double upd_sec;  /* GKS: CPU seconds of UPDATE WORKSTATION (resolve + PNG file);
                          OSMesa: CPU seconds to write its read-back as a PNG file */
static int hlhsr_mode = GHLHSR_ZBUFFER;

typedef struct { uint64_t s; } rng;
static double urand(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (double)((r->s * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}

/* CPU time of the process: the machines this runs on are shared, and both sides are
 * single-threaded, so CPU seconds compare them fairly (wall time is printed too). */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The workload in pixels: 3n triangle vertices (x, y in [0,1024], z in [0,1]) and n
 * colours, or n walk points. */
typedef struct { int walk; size_t n; double box; double *xyz; float *rgb; } work;

static int work_make(work *w)
{
    rng r = { 0x9E3779B97F4A7C15ull };
    size_t nv = w->walk ? w->n : 3 * w->n;
    w->xyz = malloc(nv * 3 * sizeof *w->xyz);
    w->rgb = w->walk ? NULL : malloc(w->n * 3 * sizeof *w->rgb);
    if (!w->xyz || (!w->walk && !w->rgb))
        return 1;
    if (w->walk) {
        double x = 512, y = 512;
        for (size_t i = 0; i < w->n; i++) {
            x += (urand(&r) - 0.5) * 4;
            y += (urand(&r) - 0.5) * 4;
            if (x < 0 || x > SIZE)
                x = 512;
            if (y < 0 || y > SIZE)
                y = 512;
            w->xyz[3 * i] = x;
            w->xyz[3 * i + 1] = y;
            w->xyz[3 * i + 2] = 0.5;
        }
        return 0;
    }
    for (size_t t = 0; t < w->n; t++) {
        double cx = urand(&r) * SIZE, cy = urand(&r) * SIZE;
        for (int k = 0; k < 3; k++) {
            double *p = w->xyz + 9 * t + 3 * k;
            p[0] = cx + (urand(&r) - 0.5) * w->box;
            p[1] = cy + (urand(&r) - 0.5) * w->box;
            p[2] = urand(&r);
        }
        for (int k = 0; k < 3; k++)
            w->rgb[3 * t + k] = (float)urand(&r);
    }
    return 0;
}

/* GKS: colours through the colour table (254 random entries, index per triangle). */
static double run_gks(work *w)
{
    gopen_gks(NULL, 0);
    gopen_ws(1, "bench_gks", GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_hlhsr_mode(1, hlhsr_mode);
    gset_fill_int_style(GSTYLE_SOLID);
    rng r = { 12345 };
    for (int i = 2; i < 256; i++) {
        Gcolr_rep c = { .rgb = { urand(&r), urand(&r), urand(&r) } };
        gset_colr_rep(1, i, &c);
    }
    size_t nv = w->walk ? w->n : 3 * w->n;
    Gpoint3 *p = malloc(nv * sizeof *p);
    if (!p)
        return -1;
    for (size_t i = 0; i < nv; i++) /* NDC = WC (transformation 0) */
        p[i] = (Gpoint3){ w->xyz[3 * i] / SIZE, w->xyz[3 * i + 1] / SIZE, w->xyz[3 * i + 2] };
    free(w->xyz);
    w->xyz = NULL;
    gclear_ws(1, GFLAG_ALWAYS); /* warm-up: the framebuffer exists (as for OSMesa) */
    double t0 = now(), w0 = wall();
    gclear_ws(1, GFLAG_ALWAYS);
    if (w->walk) {
        Gpoint_list3 l = { (Gint)w->n, p };
        gset_line_colr_ind(1);
        gpolyline3(&l);
    } else {
        for (size_t t = 0; t < w->n; t++) {
            Gpoint_list3 l = { 3, p + 3 * t };
            gset_fill_colr_ind((Gint)(2 + t % 254));
            gfill_area3(&l);
        }
    }
    double tu = now();
    gupd_ws(1, GFLAG_PERFORM);
    double dt = now() - t0;
    upd_sec = now() - tu;
    wall_sec = wall() - w0;
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    free(p);
    return dt;
}

#ifdef HAVE_OSMESA
/* rb: SIZE x SIZE RGBA, GL rows bottom-up; written top row first, alpha dropped. */
static int write_png_like_gks(const char *path, const unsigned char *rb)
{
    FILE *fp = fopen(path, "wb");
    if (!fp)
        return -1;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : NULL);
        fclose(fp);
        return -1;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, SIZE, SIZE, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_strategy(png, Z_RLE);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    png_set_filler(png, 0, PNG_FILLER_AFTER);
    for (int y = SIZE - 1; y >= 0; y--)
        png_write_row(png, rb + (size_t)y * SIZE * 4);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(fp) == 0 ? 0 : -1;
}

static double run_osmesa(work *w)
{
    setenv("LP_NUM_THREADS", "0", 1);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf = malloc((size_t)SIZE * SIZE * 4);
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, SIZE, SIZE))
        return -1;
    size_t nv = w->walk ? w->n : 3 * w->n;
    float *v = malloc(nv * 3 * sizeof *v);
    float *c = w->walk ? NULL : malloc(nv * 3 * sizeof *c);
    unsigned char *rb = malloc((size_t)SIZE * SIZE * 4);
    if (!v || (!w->walk && !c) || !rb)
        return -1;
    for (size_t i = 0; i < nv; i++) {
        v[3 * i] = (float)w->xyz[3 * i];
        v[3 * i + 1] = (float)w->xyz[3 * i + 1];
        v[3 * i + 2] = (float)w->xyz[3 * i + 2];
        if (c)
            memcpy(c + 3 * i, w->rgb + 3 * (i / 3), 3 * sizeof *c);
    }
    free(w->xyz);
    w->xyz = NULL;
    glViewport(0, 0, SIZE, SIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, SIZE, 0, SIZE, 0, -1); /* z in [0,1] -> depth [0,1], larger nearer */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v);
    if (c) {
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(3, GL_FLOAT, 0, c);
    }
    glClearColor(1, 1, 1, 1);
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT); /* warm-up: buffers touched */
    glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    glFinish();
    double t0 = now(), w0 = wall();
    if (w->walk) {
        glDisable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glColor3f(0, 0, 0);
        glDrawArrays(GL_LINE_STRIP, 0, (GLsizei)nv);
    } else {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDrawArrays(GL_TRIANGLES, 0, (GLsizei)nv);
    }
    glFinish();
    glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    double dt = now() - t0;
    wall_sec = wall() - w0;
    /* Like for like with GKS's UPDATE: the read-back written as an 8-bit RGB PNG file
     * with the PNG workstation's default encoder settings (zlib run-length strategy, SUB
     * row filter; docs/WORKSTATIONS.md). Timed apart. */
    double tp = now();
    if (write_png_like_gks("bench_osmesa.png", rb) != 0)
        return -1;
    upd_sec = now() - tp;
    OSMesaDestroyContext(ctx);
    free(v);
    free(c);
    free(rb);
    free(buf);
    return dt;
}
#endif

/* Runs one implementation in a child; *sec and *maxrss_kb from the child. */
static int child_run(work w, int osmesa, double *sec, double *wsec, double *usec,
                     long *maxrss_kb)
{
    int fd[2];
    if (pipe(fd))
        return 1;
    pid_t pid = fork();
    if (pid < 0)
        return 1;
    if (pid == 0) {
        close(fd[0]);
        double dt = -1;
        if (work_make(&w) == 0) {
#ifdef HAVE_OSMESA
            dt = osmesa ? run_osmesa(&w) : run_gks(&w);
#else
            (void)osmesa;
            dt = run_gks(&w);
#endif
        }
        double msg[3] = { dt, wall_sec, upd_sec };
        if (write(fd[1], msg, sizeof msg) != (ssize_t)sizeof msg)
            _exit(2);
        _exit(0);
    }
    close(fd[1]);
    double msg[3] = { -1, -1, 0 };
    ssize_t got = read(fd[0], msg, sizeof msg);
    close(fd[0]);
    double dt = msg[0];
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) < 0 || got != (ssize_t)sizeof msg || dt < 0)
        return 1;
    *sec = dt;
    *wsec = msg[1];
    *usec = msg[2];
    *maxrss_kb = ru.ru_maxrss;
    return 0;
}

static int gks_only;

static int row(const char *name, int walk, double box, size_t n)
{
    work w = { .walk = walk, .n = n, .box = box };
    double tg, to = 0, wg, wo = 0, ug, uo = 0;
    (void)uo; /* used only with the OSMesa comparison */
    long mg, mo = 0;
    if (child_run(w, 0, &tg, &wg, &ug, &mg)) {
        printf("%-7s %9zu  GKS failed\n", name, n);
        return 1;
    }
    printf("%-6s %8zu  GKS %7.3f s (%7.3f) upd %5.3f %7.1f ns/prim %6.1f MiB", name, n, tg,
           wg, ug, 1e9 * tg / n, mg / 1024.0);
#ifdef HAVE_OSMESA
    if (gks_only)
        ;
    else if (child_run(w, 1, &to, &wo, &uo, &mo) == 0)
        printf(" | llvmpipe %7.3f s (%7.3f) %6.1f MiB | GKS/llvmpipe %.2f"
               " | llvmpipe+PNG %7.3f s | GKS/(llvmpipe+PNG) %.2f", to, wo, mo / 1024.0,
               tg / to, to + uo, tg / (to + uo));
    else
        printf(" | llvmpipe failed");
#else
    (void)to;
    (void)wo;
    (void)uo;
    (void)mo;
    (void)uo;
#endif
    printf("\n");
    fflush(stdout);
    return 0;
}

int main(int argc, char **argv)
{
    int rc = 0;
    setvbuf(stdout, NULL, _IOLBF, 0);
#ifndef HAVE_OSMESA
    printf("(built without OSMesa: no llvmpipe comparison)\n");
#endif
    for (;;) {
        if (argc > 1 && strcmp(argv[1], "-g") == 0) {
            gks_only = 1;
            argv++;
            argc--;
        } else if (argc > 2 && strcmp(argv[1], "-m") == 0) {
            hlhsr_mode = atoi(argv[2]);
            argv += 2;
            argc -= 2;
        } else {
            break;
        }
    }
    if (argc < 2 || strcmp(argv[1], "all") == 0) {
        const size_t ns[3] = { 10000, 100000, 1000000 };
        for (int k = 0; k < 3; k++)
            rc |= row("tri16", 0, 16, ns[k]);
        for (int k = 0; k < 3; k++)
            rc |= row("tri128", 0, 128, ns[k]);
        rc |= row("walk", 1, 0, 10000000);
        return rc;
    }
    for (int i = 1; i < argc; i++) {
        char name[16];
        unsigned long long n;
        if (sscanf(argv[i], "%15[a-z0-9]:%llu", name, &n) != 2 || n == 0) {
            fprintf(stderr, "bad row %s (tri16:N, tri128:N, walk:M)\n", argv[i]);
            return 2;
        }
        if (strcmp(name, "walk") == 0)
            rc |= row("walk", 1, 0, (size_t)n);
        else if (strcmp(name, "tri16") == 0 || strcmp(name, "tri128") == 0)
            rc |= row(name, 0, strcmp(name, "tri16") == 0 ? 16 : 128, (size_t)n);
    }
    return rc;
}
