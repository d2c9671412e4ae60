/* SPDX-License-Identifier: MIT */
/*
 * cmp_embree -- ours (rt_intersect / rt_occluded) vs Embree 3 (rtcIntersect1 / rtcOccluded1,
 * and its rtcIntersect16 packets on the primary rays), one thread, the same rays, same run.
 *   cmp_embree rays RES mesh.off...   primary and shadow Mrays/s, ratios, hit agreement
 *   cmp_embree build                  build time and memory per primitive, 10^4 .. 10^6 triangles
 *
 * Rays: RES x RES pixel-centre primary rays of the framing camera (rt_camera_ray, in VRC3),
 * the same rays rounded to float for Embree. Shadow rays: from every primary hit of ours
 * whose surface faces the light, origin moved off the surface along the normal by
 * 1e-6 x (distance to the light), towards the light, segment up to the light (t in
 * [0, 1 - 1e-6], dir = light - origin). Embree: RTC_SCENE_FLAG_NONE, build quality medium
 * (its defaults), device "threads=1". Times: CPU time of the calling thread, best of 5
 * interleaved runs (ours, Embree, ours, ...).
 * Agreement: both miss, or both hit the same triangle with |t_ours - t_embree| <= TOL_T *
 * t_ours (TOL_T = 1e-5: Embree's float ray/triangle test; distances within a few float ulps
 * of the scene scale). Shadow: same occluded flag.
 */
#include "bench_scene.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { REPS = 5, MAX_EXAMPLES = 5 };
static const double TOL_T = 1e-5;

/* ---------------------------------------------------------------- Embree scene */

typedef struct em_mem {
    atomic_llong bytes, peak;
} em_mem;

static bool em_monitor(void *user, ssize_t bytes, bool post)
{
    (void)post;
    em_mem *m = user;
    long long b = atomic_fetch_add(&m->bytes, (long long)bytes) + (long long)bytes;
    long long p = atomic_load(&m->peak);
    while (b > p && !atomic_compare_exchange_weak(&m->peak, &p, b)) {
    }
    return true;
}

/* Embree triangle scene of float copies of verts (VRC3); NULL on failure */
static RTCScene em_scene(RTCDevice dev, const double *verts, size_t nv, const uint32_t *tris, size_t nt)
{
    RTCScene sc = rtcNewScene(dev);
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *vb = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv);
    unsigned *ib = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt);
    if (!sc || !g || !vb || !ib) {
        if (g)
            rtcReleaseGeometry(g);
        if (sc)
            rtcReleaseScene(sc);
        return NULL;
    }
    for (size_t i = 0; i < 3 * nv; i++)
        vb[i] = (float)verts[i];
    for (size_t i = 0; i < 3 * nt; i++)
        ib[i] = tris[i];
    rtcCommitGeometry(g);
    rtcAttachGeometry(sc, g);
    rtcReleaseGeometry(g);
    return sc;
}

static void em_rayhit(const rt_ray *r, struct RTCRayHit *rh)
{
    memset(rh, 0, sizeof *rh);
    rh->ray.org_x = (float)r->org[0];
    rh->ray.org_y = (float)r->org[1];
    rh->ray.org_z = (float)r->org[2];
    rh->ray.dir_x = (float)r->dir[0];
    rh->ray.dir_y = (float)r->dir[1];
    rh->ray.dir_z = (float)r->dir[2];
    rh->ray.tnear = (float)r->tmin;
    rh->ray.tfar = isinf(r->tmax) ? INFINITY : (float)r->tmax;
    rh->ray.mask = 0xFFFFFFFFu;
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.primID = RTC_INVALID_GEOMETRY_ID;
}

/* ---------------------------------------------------------------- rays */

typedef struct em_res {
    int *prim;       /* gksrt primitive id (via tri_prim) or -1 */
    float *t;
    unsigned char *occ;
} em_res;

static double time_embree_primary(RTCScene sc, const bs_scene *s, const rt_ray *rays, size_t n, em_res *res)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    double t0 = bs_thread_cpu();
    for (size_t k = 0; k < n; k++) {
        struct RTCRayHit rh;
        em_rayhit(&rays[k], &rh);
        rtcIntersect1(sc, &ctx, &rh);
        res->prim[k] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : s->tri_prim[rh.hit.primID];
        res->t[k] = rh.ray.tfar;
    }
    return bs_thread_cpu() - t0;
}

static double time_embree_shadow(RTCScene sc, const rt_ray *rays, size_t n, em_res *res)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    double t0 = bs_thread_cpu();
    for (size_t k = 0; k < n; k++) {
        struct RTCRayHit rh;
        em_rayhit(&rays[k], &rh);
        rtcOccluded1(sc, &ctx, &rh.ray);
        res->occ[k] = rh.ray.tfar == -INFINITY;
    }
    return bs_thread_cpu() - t0;
}

/* Embree's 16-wide packet path (rtcIntersect16, coherent context) on the same primary rays,
 * in 4x4 pixel blocks (lanes past the raster's edge invalid), packet set-up included as the
 * single-ray loop includes its own; hits counted for the agreement with rtcIntersect1. */
static double time_embree_packets(RTCScene sc, const rt_ray *rays, int res, size_t *nhit)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    size_t hits = 0;
    double t0 = bs_thread_cpu();
    for (int by = 0; by < res; by += 4)
        for (int bx = 0; bx < res; bx += 4) {
            RTC_ALIGN(64) struct RTCRayHit16 rh;
            RTC_ALIGN(64) int valid[16];
            for (int j = 0; j < 16; j++) {
                const int x = bx + j % 4, y = by + j / 4, in = x < res && y < res;
                const rt_ray *r = &rays[in ? (size_t)y * (size_t)res + (size_t)x : 0];
                valid[j] = in ? -1 : 0;
                rh.ray.org_x[j] = (float)r->org[0];
                rh.ray.org_y[j] = (float)r->org[1];
                rh.ray.org_z[j] = (float)r->org[2];
                rh.ray.dir_x[j] = (float)r->dir[0];
                rh.ray.dir_y[j] = (float)r->dir[1];
                rh.ray.dir_z[j] = (float)r->dir[2];
                rh.ray.tnear[j] = (float)r->tmin;
                rh.ray.tfar[j] = isinf(r->tmax) ? INFINITY : (float)r->tmax;
                rh.ray.time[j] = 0.0f;
                rh.ray.mask[j] = 0xFFFFFFFFu;
                rh.ray.id[j] = (unsigned)j;
                rh.ray.flags[j] = 0;
                rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.primID[j] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][j] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect16(valid, sc, &ctx, &rh);
            for (int j = 0; j < 16; j++)
                hits += valid[j] && rh.hit.geomID[j] != RTC_INVALID_GEOMETRY_ID;
        }
    double t = bs_thread_cpu() - t0;
    *nhit = hits;
    return t;
}

/* shadow rays from ours' primary hits facing the light; returns their number */
static size_t make_shadow_rays(const bs_scene *s, const rt_hit *hits, size_t n, rt_ray *out)
{
    size_t m = 0;
    for (size_t k = 0; k < n; k++) {
        const rt_hit *h = &hits[k];
        if (h->prim < 0)
            continue;
        double sg = h->side ? -1.0 : 1.0, d[3], dn = 0.0, len = 0.0;
        for (int i = 0; i < 3; i++) {
            d[i] = s->light_vrc[i] - h->p[i];
            dn += sg * h->ng[i] * d[i];
            len += d[i] * d[i];
        }
        if (!(dn > 0.0))
            continue; /* back to the light: no shadow ray, as in the renderer */
        double eps = 1e-6 * sqrt(len);
        rt_ray *r = &out[m++];
        for (int i = 0; i < 3; i++) {
            r->org[i] = h->p[i] + sg * eps * h->ng[i];
            r->dir[i] = s->light_vrc[i] - r->org[i];
        }
        r->tmin = 0.0;
        r->tmax = 1.0 - 1e-6;
    }
    return m;
}

static int cmd_rays(int res, int nfiles, char **files)
{
    RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
    if (!dev) {
        fprintf(stderr, "rtcNewDevice failed\n");
        return 1;
    }
    printf("Embree %d.%d.%d vs ours: %dx%d primary rays + shadow rays to one point light, 1 thread, "
           "CPU seconds of the tracing thread, best of %d interleaved runs\n",
           RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, res, res, REPS);
    printf("E.pk16: Embree's rtcIntersect16 packets (4x4 pixel blocks) on the same primary rays\n");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s | %7s %8s %8s %6s | %s\n", "mesh", "tris", "o.prim", "E.prim",
           "o/E", "E.pk16", "o/E16", "shadow", "o.shad", "E.shad", "o/E", "agreement (primary; shadow)");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s | %7s %8s %8s %6s |\n", "", "", "Mrays/s", "Mrays/s", "", "Mrays/s",
           "", "rays", "Mrays/s", "Mrays/s", "");
    int fails = 0;
    for (int f = 0; f < nfiles; f++) {
        const char *base = strrchr(files[f], '/');
        base = base ? base + 1 : files[f];
        bs_scene s;
        char err[512];
        bs_options opt = {.size = res};
        if (bs_load(files[f], &opt, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            bs_free(&s);
            fails++;
            continue;
        }
        size_t n = (size_t)res * res;
        rt_ray *rays = bs_alloc(n, sizeof *rays);
        rt_ray *srays = bs_alloc(n, sizeof *srays);
        rt_hit *hits = bs_alloc(n, sizeof *hits);
        unsigned char *occ = bs_alloc(n, 1);
        em_res er = {bs_alloc(n, sizeof(int)), bs_alloc(n, sizeof(float)), bs_alloc(n, 1)};
        RTCScene esc = em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris);
        if (!rays || !srays || !hits || !occ || !er.prim || !er.t || !er.occ || !esc) {
            fprintf(stderr, "%s: out of memory\n", base);
            fails++;
            goto next;
        }
        rtcCommitScene(esc);
        for (int y = 0; y < res; y++)
            for (int x = 0; x < res; x++)
                rt_camera_ray(&s.cam, x + 0.5, y + 0.5, &rays[(size_t)y * res + x]);
        double op = 1e30, ep = 1e30, os = 1e30, es = 1e30, e16 = 1e30;
        size_t ns = 0, hit16 = 0;
        for (int r = 0; r < REPS; r++) {
            double t0 = bs_thread_cpu();
            rt_intersect(s.rt, n, rays, hits);
            op = fmin(op, bs_thread_cpu() - t0);
            ep = fmin(ep, time_embree_primary(esc, &s, rays, n, &er));
            e16 = fmin(e16, time_embree_packets(esc, rays, res, &hit16));
        }
        ns = make_shadow_rays(&s, hits, n, srays);
        for (int r = 0; r < REPS && ns; r++) {
            double t0 = bs_thread_cpu();
            rt_occluded(s.rt, ns, srays, occ);
            os = fmin(os, bs_thread_cpu() - t0);
            es = fmin(es, time_embree_shadow(esc, srays, ns, &er));
        }
        /* agreement */
        size_t both_miss = 0, same = 0, tie = 0, hitmiss = 0, other = 0, nhit = 0;
        double maxrel = 0.0;
        int nex = 0;
        char ex[MAX_EXAMPLES][200];
        for (size_t k = 0; k < n; k++) {
            int po = hits[k].prim, pe = er.prim[k];
            nhit += po >= 0;
            if (po < 0 && pe < 0) {
                both_miss++;
                continue;
            }
            double rel = po >= 0 && pe >= 0 ? fabs(hits[k].t - er.t[k]) / hits[k].t : INFINITY;
            const char *kind;
            if (po == pe && rel <= TOL_T) {
                same++;
                maxrel = fmax(maxrel, rel);
                continue;
            } else if (po >= 0 && pe >= 0 && rel <= TOL_T) {
                tie++;
                kind = "other triangle, same t (shared edge/vertex)";
            } else if (po < 0 || pe < 0) {
                hitmiss++;
                kind = "hit vs miss";
            } else {
                other++;
                kind = "different t";
            }
            if (nex < MAX_EXAMPLES)
                snprintf(ex[nex++], sizeof ex[0], "ray %zu (pixel %zu,%zu): ours prim %d t %.9g, Embree prim %d t %.9g: %s",
                         k, k % (size_t)res, k / (size_t)res, po, po >= 0 ? hits[k].t : -1.0, pe,
                         pe >= 0 ? (double)er.t[k] : -1.0, kind);
        }
        size_t socc = 0, sdis = 0;
        for (size_t k = 0; k < ns; k++) {
            socc += occ[k];
            sdis += occ[k] != er.occ[k];
        }
        size_t dis = tie + hitmiss + other;
        size_t ehit = 0;
        for (size_t k = 0; k < n; k++)
            ehit += er.prim[k] >= 0;
        printf("%-24s %7zu | %8.2f %8.2f %6.2f | %8.2f %6.2f | %7zu %8.2f %8.2f %6.2f | %zu/%zu rays differ; %zu/%zu\n",
               base, s.ntris, n / op * 1e-6, n / ep * 1e-6, ep / op, n / e16 * 1e-6, e16 / op, ns,
               ns ? ns / os * 1e-6 : 0.0, ns ? ns / es * 1e-6 : 0.0, ns ? es / os : 0.0, dis, n, sdis, ns);
        printf("    packets: %zu hits (rtcIntersect1: %zu)\n", hit16, ehit);
        printf("    primary: %zu hits (ours), %zu both miss, %zu same triangle (max rel. t diff %.2e, tol %.0e); "
               "differ: %zu edge/vertex ties, %zu hit/miss, %zu other; shadow: %zu occluded (ours), %zu differ\n",
               nhit, both_miss, same, maxrel, TOL_T, tie, hitmiss, other, socc, sdis);
        for (int e = 0; e < nex; e++)
            printf("    e.g. %s\n", ex[e]);
        fflush(stdout);
    next:
        if (esc)
            rtcReleaseScene(esc);
        free(rays);
        free(srays);
        free(hits);
        free(occ);
        free(er.prim);
        free(er.t);
        free(er.occ);
        bs_free(&s);
    }
    printf("(o/E = ours Mrays/s / Embree Mrays/s; issue 21's goals: primary o/E >= 1.0 against "
           "rtcIntersect1 on every mesh, shadow o/E >= 0.7; o/E16 against the packets reported, aim >= 0.5)\n");
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

/* ---------------------------------------------------------------- build scaling */

/* xorshift64*: deterministic random numbers in [0,1) */
static double rnd(uint64_t *st)
{
    *st ^= *st >> 12;
    *st ^= *st << 25;
    *st ^= *st >> 27;
    return (double)((*st * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

static int cmd_build(void)
{
    em_mem mem;
    atomic_init(&mem.bytes, 0);
    atomic_init(&mem.peak, 0);
    RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
    if (!dev)
        return 1;
    rtcSetDeviceMemoryMonitorFunction(dev, em_monitor, &mem);
    printf("Build time and memory vs primitive count: random triangles (centres uniform in a unit cube "
           "at z in [-3,-2], vertices within a cube of side 2*N^(-1/3) around the centre), 1 thread, "
           "process CPU seconds, best of %d\n", REPS);
    printf("ours: rt_scene_commit (grid, default options, 1 thread) with memory = rt_stats.memory_bytes (scene + "
           "grid, double vertices); Embree: rtcCommitScene, memory = device memory monitor after commit "
           "(BVH + float vertex/index buffers)\n");
    printf("o.2t: the same commit on 2 threads (rt_build_options.threads), wall seconds (load-sensitive)\n");
    printf("%9s | %8s %9s %8s %8s %8s %9s %8s | %8s %9s %8s | %6s %6s\n", "tris", "o.build", "o.us/tri",
           "o.B/tri", "cells", "refs", "o.Mtri/s", "o.2t", "E.build", "E.us/tri", "E.B/tri", "build", "mem");
    printf("%9s | %8s %9s %8s %8s %8s %9s %8s | %8s %9s %8s | %6s %6s\n", "", "s", "", "", "/tri", "/tri", "",
           "wall s", "s", "", "", "o/E", "o/E");
    static const size_t counts[] = {10000, 30000, 100000, 300000, 1000000};
    int fails = 0;
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        size_t n = counts[c];
        double *v = bs_alloc(n, 9 * sizeof(double));
        uint32_t *ix = bs_alloc(n, 3 * sizeof(uint32_t));
        if (!v || !ix) {
            free(v);
            free(ix);
            fails++;
            continue;
        }
        uint64_t st = 0x9E3779B97F4A7C15ULL ^ n;
        double side = 2.0 * pow((double)n, -1.0 / 3.0);
        for (size_t t = 0; t < n; t++) {
            double cc[3] = {rnd(&st) - 0.5, rnd(&st) - 0.5, rnd(&st) - 3.0};
            for (int k = 0; k < 3; k++) {
                for (int i = 0; i < 3; i++)
                    v[9 * t + 3 * k + i] = cc[i] + side * (rnd(&st) - 0.5);
                ix[3 * t + k] = (uint32_t)(3 * t + (size_t)k);
            }
        }
        double ob = 1e30, eb = 1e30, ob2 = 1e30;
        rt_stats rs;
        memset(&rs, 0, sizeof rs);
        long long emem = 0;
        for (int r = 0; r < REPS; r++) {
            rt_scene *sc = rt_scene_new();
            rt_surface su;
            rt_surface_default(&su);
            int sid = sc ? rt_scene_add_surface(sc, &su) : -1;
            int three = 3;
            for (size_t t = 0; t < n && sid >= 0; t++)
                if (rt_scene_add_polygon(sc, 1, &three, v + 9 * t, sid, sid) < 0)
                    sid = -1;
            const rt_build_options b1 = {.brute_threshold = -1, .threads = 1},
                                   b2 = {.brute_threshold = -1, .threads = 2};
            double w0 = bs_wall();
            int rc = sid >= 0 ? rt_scene_commit(sc, &b2) : RT_ERR_NOMEM; /* the same scene */
            ob2 = fmin(ob2, bs_wall() - w0);
            double t0 = bs_process_cpu();
            if (rc == RT_OK)
                rc = rt_scene_commit(sc, &b1);
            ob = fmin(ob, bs_process_cpu() - t0);
            rt_camera cam;
            float px[3 * 4];
            rt_render_options o;
            rt_render_options_default(&o);
            o.threads = 1;
            if (rc != RT_OK || bs_camera(&cam, 30.0, 1.0, 4.0, 2, 2) != RT_OK ||
                rt_render(sc, &cam, &o, px, &rs) != RT_OK)
                fails++;
            rt_scene_free(sc);

            long long before = atomic_load(&mem.bytes);
            RTCScene es = em_scene(dev, v, 3 * n, ix, n);
            if (!es) {
                fails++;
                continue;
            }
            t0 = bs_process_cpu();
            rtcCommitScene(es);
            eb = fmin(eb, bs_process_cpu() - t0);
            emem = atomic_load(&mem.bytes) - before;
            rtcReleaseScene(es);
        }
        printf("%9zu | %8.4f %9.3f %8.1f %8.2f %8.2f %9.2f %8.4f | %8.4f %9.3f %8.1f | %6.2f %6.2f\n", n, ob,
               ob / n * 1e6, (double)rs.memory_bytes / n, (double)rs.grid_cells / n, (double)rs.grid_refs / n,
               n / ob * 1e-6, ob2, eb, eb / n * 1e6, (double)emem / n, ob / eb,
               (double)rs.memory_bytes / (double)emem);
        fflush(stdout);
        free(v);
        free(ix);
    }
    printf("(us/tri and B/tri flat as N grows = linear build time and memory; issue 21's goals: build o/E <= 1.5, "
           "mem o/E <= 1.0)\n");
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

int main(int argc, char **argv)
{
    if (argc >= 4 && !strcmp(argv[1], "rays")) {
        int res = atoi(argv[2]);
        if (res < 1 || res > 8192) {
            fprintf(stderr, "bad resolution\n");
            return 2;
        }
        return cmd_rays(res, argc - 3, argv + 3);
    }
    if (argc == 2 && !strcmp(argv[1], "build"))
        return cmd_build();
    fprintf(stderr, "usage: cmp_embree rays RES mesh.off... | cmp_embree build\n");
    return 2;
}
