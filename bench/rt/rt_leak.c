/* SPDX-License-Identifier: MIT */
/*
 * rt_leak -- closed-mesh leak probe at full size (issue "Numerical stability: hard cases",
 * item 1) and, with -primary, primary-ray speed; both side by side with Embree 3 when built
 * with it (RT_WITH_EMBREE: libembree-dev found by CMake).
 *   rt_leak [-n NRANDOM] [-primary] [-s SIZE] MESH.off ...
 * Leak probe: from a certified interior point, rays aimed exactly at every vertex and every
 * edge midpoint plus NRANDOM (default 10^6) random directions. A leak is a miss or a first hit
 * on the outer side (away from the aimed target). Printed per mesh for gksrt and for Embree in
 * its default and its robust mode (RTC_SCENE_FLAG_ROBUST; single precision), and for gksrt's
 * packet path (rt_intersect_packet on the same rays sorted by direction), with the rays whose
 * hit differs from rt_intersect's.
 * -primary: SIZE x SIZE (512) camera rays as bench/rt/rt_bench -primary, one thread; Mrays/s of
 * gksrt (rt_intersect) and Embree (rtcIntersect1), hit agreement (same triangle, or both miss).
 */
#include "gksrt.h"
#include "rt_testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef RT_WITH_EMBREE
#include <embree3/rtcore.h>
#endif

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef struct leak_count {
    size_t miss, outer;
} leak_count;

static void count_leaks(const rt_hit *h, size_t n, size_t naimed, int inner, leak_count *c)
{
    memset(c, 0, sizeof *c);
    for (size_t k = 0; k < n; k++) {
        int aimed = k < naimed;
        c->miss += h[k].prim < 0;
        c->outer += h[k].prim >= 0 && h[k].side != inner && !(aimed && fabs(h[k].t - 1.0) <= 1e-6);
    }
}

/* the order of the rays for the packet path: by octant of the direction, then by a Morton
   code of its position on the cube face of its dominant axis (neighbouring directions form
   packets) */
typedef struct dir_key {
    uint64_t key;
    size_t k;
} dir_key;

static int cmp_key(const void *a, const void *b)
{
    const dir_key *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key;
}

static uint64_t spread16(uint64_t v)
{
    uint64_t r = 0;
    for (int b = 0; b < 16; b++)
        r |= ((v >> b) & 1u) << (2 * b);
    return r;
}

static dir_key *direction_order(const rt_ray *rays, size_t n)
{
    dir_key *o = malloc(n * sizeof *o);
    if (!o)
        return NULL;
    for (size_t k = 0; k < n; k++) {
        const double *d = rays[k].dir;
        const double ax = fabs(d[0]), ay = fabs(d[1]), az = fabs(d[2]);
        const int kz = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
        const double m = fabs(d[kz]) > 0.0 ? fabs(d[kz]) : 1.0;
        const double u = d[(kz + 1) % 3] / m, v = d[(kz + 2) % 3] / m; /* in [-1, 1] */
        const uint64_t qu = (uint64_t)((u + 1.0) * 32767.0), qv = (uint64_t)((v + 1.0) * 32767.0);
        const uint64_t oct = (uint64_t)(d[0] < 0) | (uint64_t)(d[1] < 0) << 1 | (uint64_t)(d[2] < 0) << 2;
        o[k].key = (oct << 36 | (uint64_t)kz << 32) | (spread16(qu) | spread16(qv) << 1);
        o[k].k = k;
    }
    qsort(o, n, sizeof *o, cmp_key);
    return o;
}

/* the leak rays again through the packet path (rt_intersect_packet), sorted by direction:
   its leaks, and the rays whose hit differs from rt_intersect's (h) in primitive or t bits */
static void packet_leaks(const rt_scene *sc, const rt_ray *rays, const rt_hit *h, size_t n,
                         size_t naimed, int inner)
{
    dir_key *o = direction_order(rays, n);
    rt_ray *r2 = malloc(n * sizeof *r2);
    rt_hit *h2 = malloc(n * sizeof *h2), *h3 = malloc(n * sizeof *h3);
    if (!o || !r2 || !h2 || !h3) {
        printf("  gksrt packets: out of memory\n");
        goto done;
    }
    for (size_t j = 0; j < n; j++)
        r2[j] = rays[o[j].k];
    double t0 = cpu_now();
    rt_intersect_packet(sc, n, r2, h2);
    const double tt = cpu_now() - t0;
    size_t differ = 0;
    for (size_t j = 0; j < n; j++) {
        const rt_hit *a = &h[o[j].k], *b = &h2[j];
        h3[o[j].k] = *b;
        differ += a->prim != b->prim || (a->prim >= 0 && memcmp(&a->t, &b->t, sizeof a->t) != 0);
    }
    leak_count c;
    count_leaks(h3, n, naimed, inner, &c);
    printf("  gksrt packets (by direction) : %zu misses, %zu outer-side first hits, %zu rays differ "
           "from rt_intersect  (%.2f Mrays/s)\n", c.miss, c.outer, differ, (double)n / tt * 1e-6);
done:
    free(o);
    free(r2);
    free(h2);
    free(h3);
}

#ifdef RT_WITH_EMBREE
static RTCScene embree_scene(RTCDevice dev, const rtu_mesh *m, int robust)
{
    RTCScene s = rtcNewScene(dev);
    if (robust)
        rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), (size_t)m->nv);
    unsigned *ix = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                           3 * sizeof(unsigned), (size_t)m->np);
    for (int i = 0; i < 3 * m->nv; i++)
        v[i] = (float)m->xyz[i];
    for (size_t i = 0; i < 3 * (size_t)m->np; i++)
        ix[i] = (unsigned)m->idx[i];
    rtcCommitGeometry(g);
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    return s;
}

/* Embree hits in rt_hit form (prim = triangle index, side from Embree's geometric normal Ng,
   which points to the front of a counter-clockwise triangle: side 1 when Ng . dir > 0) */
static double embree_trace(RTCScene s, const rt_ray *rays, size_t n, rt_hit *h)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    double t0 = cpu_now();
    for (size_t k = 0; k < n; k++) {
        struct RTCRayHit rh;
        memset(&rh, 0, sizeof rh);
        rh.ray.org_x = (float)rays[k].org[0];
        rh.ray.org_y = (float)rays[k].org[1];
        rh.ray.org_z = (float)rays[k].org[2];
        rh.ray.dir_x = (float)rays[k].dir[0];
        rh.ray.dir_y = (float)rays[k].dir[1];
        rh.ray.dir_z = (float)rays[k].dir[2];
        rh.ray.tnear = (float)rays[k].tmin;
        rh.ray.tfar = isinf(rays[k].tmax) ? INFINITY : (float)rays[k].tmax;
        rh.ray.mask = 0xFFFFFFFFu;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(s, &ctx, &rh);
        h[k].prim = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : (int)rh.hit.primID;
        h[k].t = rh.ray.tfar;
        double dn = rh.hit.Ng_x * rays[k].dir[0] + rh.hit.Ng_y * rays[k].dir[1] + rh.hit.Ng_z * rays[k].dir[2];
        h[k].side = dn > 0.0;
    }
    return cpu_now() - t0;
}
#endif

static int leak(const char *path, size_t nrand)
{
    rtu_mesh m;
    if (rtu_load_off(path, &m) != 0) {
        fprintf(stderr, "cannot load %s\n", path);
        return 1;
    }
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    int s = rt_scene_add_surface(sc, &su);
    double t0 = cpu_now();
    if (rtu_mesh_add(&m, sc, s) != 0 || rt_scene_commit(sc, NULL) != RT_OK)
        return 1;
    double tb = cpu_now() - t0;
    double p[3];
    int inner;
    if (rtu_interior_point(&m, sc, p, &inner) != 0) {
        fprintf(stderr, "%s: no interior point found\n", path);
        return 1;
    }
    rt_ray *rays;
    size_t n, nv, ne;
    if (rtu_leak_rays(&m, p, nrand, 7, &rays, &n, &nv, &ne) != 0)
        return 1;
    rt_hit *h = malloc(n * sizeof *h);
    if (!h)
        return 1;
    t0 = cpu_now();
    rt_intersect(sc, n, rays, h);
    double tt = cpu_now() - t0;
    leak_count c;
    count_leaks(h, n, nv + ne, inner, &c);
    printf("%s: %d triangles; rays: %zu at vertices, %zu at edge midpoints, %zu random\n", path, m.np,
           nv, ne, nrand);
    printf("  gksrt (double, watertight)   : %zu misses, %zu outer-side first hits  "
           "(build %.3f s, %.2f Mrays/s)\n", c.miss, c.outer, tb, (double)n / tt * 1e-6);
    packet_leaks(sc, rays, h, n, nv + ne, inner);
#ifdef RT_WITH_EMBREE
    RTCDevice dev = rtcNewDevice("threads=1");
    for (int robust = 0; robust < 2; robust++) {
        t0 = cpu_now();
        RTCScene es = embree_scene(dev, &m, robust);
        tb = cpu_now() - t0;
        tt = embree_trace(es, rays, n, h);
        count_leaks(h, n, nv + ne, inner, &c);
        printf("  Embree 3 %-20s: %zu misses, %zu outer-side first hits  (build %.3f s, %.2f Mrays/s)\n",
               robust ? "(robust, float)" : "(default, float)", c.miss, c.outer, tb, (double)n / tt * 1e-6);
        rtcReleaseScene(es);
    }
    rtcReleaseDevice(dev);
#else
    printf("  Embree 3: not built in (install libembree-dev and reconfigure)\n");
#endif
    free(h);
    free(rays);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
    return 0;
}

static int primary(const char *path, int size)
{
    rtu_mesh m;
    if (rtu_load_off(path, &m) != 0) {
        fprintf(stderr, "cannot load %s\n", path);
        return 1;
    }
    double bb[6];
    rtu_mesh_bbox(&m, bb); /* camera as in rt_bench: from +z of the box centre */
    double c[3] = {0.5 * (bb[0] + bb[3]), 0.5 * (bb[1] + bb[4]), 0.5 * (bb[2] + bb[5])};
    double r = 0.5 * sqrt((bb[3] - bb[0]) * (bb[3] - bb[0]) + (bb[4] - bb[1]) * (bb[4] - bb[1]) +
                          (bb[5] - bb[2]) * (bb[5] - bb[2]));
    memcpy(m.at, c, sizeof c);
    memcpy(m.from, c, sizeof c);
    m.from[2] += 3.0 * r;
    m.up[0] = m.up[2] = 0.0;
    m.up[1] = 1.0;
    m.angle = 40.0;
    m.hither = 0.01 * r;
    double vo[4][4];
    rtu_lookat(m.from, m.at, m.up, vo);
    rtu_mesh_transform(&m, vo);
    rtu_mesh_bbox(&m, bb);
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    int s = rt_scene_add_surface(sc, &su);
    if (rtu_mesh_add(&m, sc, s) != 0 || rt_scene_commit(sc, NULL) != RT_OK)
        return 1;
    rtu_view v;
    rtu_nff_view(&m, bb, &v);
    double vm[4][4];
    rtu_view_matrix(&v, vm);
    rt_camera cam;
    if (rt_camera_from_view(&cam, vm, v.vp, size, size) != RT_OK)
        return 1;
    size_t n = (size_t)size * (size_t)size;
    rt_ray *rays = malloc(n * sizeof *rays);
    rt_hit *h = malloc(n * sizeof *h);
    if (!rays || !h)
        return 1;
    for (int y = 0; y < size; y++)
        for (int x = 0; x < size; x++)
            rt_camera_ray(&cam, x + 0.5, y + 0.5, &rays[(size_t)y * (size_t)size + (size_t)x]);
    double best = INFINITY;
    for (int rep = 0; rep < 5; rep++) {
        double t0 = cpu_now();
        rt_intersect(sc, n, rays, h);
        double t = cpu_now() - t0;
        best = t < best ? t : best;
    }
    size_t nh = 0;
    for (size_t k = 0; k < n; k++)
        nh += h[k].prim >= 0;
    printf("%s: %d triangles, %zu primary rays (%zu hit): gksrt %.2f Mrays/s", path, m.np, n, nh,
           (double)n / best * 1e-6);
#ifdef RT_WITH_EMBREE
    RTCDevice dev = rtcNewDevice("threads=1");
    RTCScene es = embree_scene(dev, &m, 0);
    rt_hit *he = malloc(n * sizeof *he);
    if (!he)
        return 1;
    double beste = INFINITY;
    for (int rep = 0; rep < 5; rep++) {
        double t = embree_trace(es, rays, n, he);
        beste = t < beste ? t : beste;
    }
    size_t agree = 0;
    for (size_t k = 0; k < n; k++)
        agree += h[k].prim == he[k].prim;
    printf(", Embree %.2f Mrays/s, ours/Embree %.2f; same triangle on %.4f %% of the rays\n",
           (double)n / beste * 1e-6, beste / best, 100.0 * (double)agree / (double)n);
    free(he);
    rtcReleaseScene(es);
    rtcReleaseDevice(dev);
#else
    printf("\n");
#endif
    free(rays);
    free(h);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
    return 0;
}

int main(int argc, char **argv)
{
    size_t nrand = 1000000;
    int prim = 0, size = 512, rc = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "-n") && i + 1 < argc)
            nrand = (size_t)strtoull(argv[++i], NULL, 10);
        else if (!strcmp(argv[i], "-s") && i + 1 < argc)
            size = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-primary"))
            prim = 1;
        else
            rc |= prim ? primary(argv[i], size > 0 ? size : 512) : leak(argv[i], nrand);
    }
    if (argc < 2)
        fprintf(stderr, "usage: rt_leak [-n NRANDOM] [-primary] [-s SIZE] MESH.off ...\n");
    return argc < 2 ? 2 : rc;
}
