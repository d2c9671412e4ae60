/* SPDX-License-Identifier: MIT */
/*
 * cmp_embree -- ours (rt_intersect / rt_occluded) vs Embree 3 (rtcIntersect1 / rtcOccluded1,
 * and its rtcIntersect16 packets on the primary rays), one thread, the same rays, same run.
 *   cmp_embree rays RES mesh.off...   primary, shadow and incoherent Mrays/s, ratios, hit
 *                                     agreement; build time and memory of each mesh
 *   cmp_embree build                  build time and memory per primitive, 10^4 .. 10^6 triangles
 *   cmp_embree ours RES SET mesh.off  ours only, one pass over one ray set (SET: primary, shadow,
 *                                     inside, misses; the rays below), for profilers: e.g.
 *                                     valgrind --tool=callgrind --toggle-collect=ours_pass
 *
 * Rays: RES x RES pixel-centre primary rays of the framing camera (rt_camera_ray, in VRC3),
 * the same rays rounded to float for Embree. Shadow rays: from every primary hit of ours
 * whose surface faces the light, origin moved off the surface along the normal by
 * 1e-6 x (distance to the light), towards the light, segment up to the light (t in
 * [0, 1 - 1e-6], dir = light - origin). Embree: RTC_SCENE_FLAG_NONE, build quality medium
 * (its defaults), device "threads=1". Times: CPU time of the calling thread, best of 5
 * interleaved runs (ours, Embree, ours, ...).
 * Incoherent rays, nearest hit (rtcIntersect1), deterministic random numbers:
 * - inside: from every primary hit of ours, origin moved 1e-6 x (hit distance) to the far side
 *   of the surface (into a closed mesh), direction uniform on the hemisphere away from the
 *   surface (into the mesh), t in [0, inf);
 * - in-box misses: origin uniform on the sphere of twice the mesh box's half diagonal around
 *   its centre, aimed at a point uniform in the box (the ray enters the box), t in [0, inf);
 *   of these candidates the first min(RES^2, IBOX_RAYS) that ours misses are kept (the set is
 *   defined by ours; Embree's hits on it are reported as disagreement).
 * Mesh build: rt_scene_commit of the loaded scene again (default options, 1 thread) and
 * rtcCommitScene, process CPU time, best of 5; memory as in the build series.
 * Agreement: both miss, or both hit the same triangle with |t_ours - t_embree| <= TOL_T *
 * (t_ours + |org| / |dir|) (TOL_T = 1e-5: Embree's float ray/triangle test and float ray
 * origin; distances within a few float ulps of the scene scale; the primary rays start at
 * the eye, the origin of VRC3). Shadow: same occluded flag.
 */
#include "bench_scene.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { REPS = 5, MAX_EXAMPLES = 5, IBOX_RAYS = 1 << 18 };
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

/* xorshift64*: deterministic random numbers in [0,1) */
static double rnd(uint64_t *st)
{
    *st ^= *st >> 12;
    *st ^= *st << 25;
    *st ^= *st >> 27;
    return (double)((*st * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

/* a direction uniform on the unit sphere */
static void rnd_dir(uint64_t *st, double d[3])
{
    const double z = 2.0 * rnd(st) - 1.0, a = 6.283185307179586 * rnd(st), r = sqrt(fmax(0.0, 1.0 - z * z));
    d[0] = r * cos(a);
    d[1] = r * sin(a);
    d[2] = z;
}

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

/* incoherent rays from inside the mesh: from ours' primary hits, just behind the surface,
   random directions (see the top of the file); returns their number */
static size_t make_inside_rays(const rt_ray *prim, const rt_hit *hits, size_t n, rt_ray *out)
{
    uint64_t st = 0x2545F4914F6CDD1DULL;
    size_t m = 0;
    for (size_t k = 0; k < n; k++) {
        const rt_hit *h = &hits[k];
        if (h->prim < 0)
            continue;
        double sg = h->side ? -1.0 : 1.0, len = 0.0; /* sg * ng: the side the ray came from */
        for (int i = 0; i < 3; i++)
            len += (h->p[i] - prim[k].org[i]) * (h->p[i] - prim[k].org[i]);
        const double eps = 1e-6 * sqrt(len);
        rt_ray *r = &out[m++];
        for (int i = 0; i < 3; i++)
            r->org[i] = h->p[i] - sg * eps * h->ng[i];
        rnd_dir(&st, r->dir);
        double dn = 0.0;
        for (int i = 0; i < 3; i++)
            dn += sg * h->ng[i] * r->dir[i];
        for (int i = 0; dn > 0.0 && i < 3; i++) /* into the mesh, away from the surface */
            r->dir[i] = -r->dir[i];
        r->tmin = 0.0;
        r->tmax = INFINITY;
    }
    return m;
}

/* up to want rays that enter the mesh box and miss the mesh (ours' answer), from at most
   64 * want candidates (see the top of the file); returns their number */
static size_t make_ibox_rays(const bs_scene *s, size_t want, rt_ray *out, rt_ray *cand, rt_hit *tmp)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, c[3], R = 0.0;
    for (size_t v = 0; v < s->nverts; v++)
        for (int i = 0; i < 3; i++) {
            lo[i] = fmin(lo[i], s->verts_vrc[3 * v + i]);
            hi[i] = fmax(hi[i], s->verts_vrc[3 * v + i]);
        }
    for (int i = 0; i < 3; i++) {
        c[i] = 0.5 * (lo[i] + hi[i]);
        R += 0.25 * (hi[i] - lo[i]) * (hi[i] - lo[i]);
    }
    R = sqrt(R);
    uint64_t st = 0x9E3779B97F4A7C15ULL;
    size_t m = 0;
    for (int batch = 0; batch < 64 && m < want; batch++) {
        for (size_t k = 0; k < want; k++) {
            double u[3];
            rnd_dir(&st, u);
            rt_ray *r = &cand[k];
            for (int i = 0; i < 3; i++) {
                r->org[i] = c[i] + 2.0 * R * u[i];
                r->dir[i] = lo[i] + (hi[i] - lo[i]) * rnd(&st) - r->org[i];
            }
            r->tmin = 0.0;
            r->tmax = INFINITY;
        }
        rt_intersect(s->rt, want, cand, tmp);
        for (size_t k = 0; k < want && m < want; k++)
            if (tmp[k].prim < 0)
                out[m++] = cand[k];
    }
    return m;
}

static double time_ours(const rt_scene *sc, const rt_ray *rays, size_t n, rt_hit *hits)
{
    double t0 = bs_thread_cpu();
    rt_intersect(sc, n, rays, hits);
    return bs_thread_cpu() - t0;
}

/* hit agreement of ours and Embree on n rays (res > 0: primary rays of a res x res raster,
   examples name the pixel) */
typedef struct agreement {
    size_t nhit, both_miss, same, tie, hitmiss, other;
    double maxrel;
    int nex;
    char ex[MAX_EXAMPLES][200];
} agreement;

static void agree(const rt_ray *rays, const rt_hit *hits, const em_res *er, size_t n, int res, agreement *a)
{
    memset(a, 0, sizeof *a);
    for (size_t k = 0; k < n; k++) {
        int po = hits[k].prim, pe = er->prim[k];
        a->nhit += po >= 0;
        if (po < 0 && pe < 0) {
            a->both_miss++;
            continue;
        }
        /* relative to t plus the origin's distance in units of dir (Embree's float origin) */
        const double *o = rays[k].org, *d = rays[k].dir;
        const double ot = sqrt((o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        double rel = po >= 0 && pe >= 0 ? fabs(hits[k].t - er->t[k]) / (hits[k].t + ot) : INFINITY;
        const char *kind;
        if (po == pe && rel <= TOL_T) {
            a->same++;
            a->maxrel = fmax(a->maxrel, rel);
            continue;
        } else if (po >= 0 && pe >= 0 && rel <= TOL_T) {
            a->tie++;
            kind = "other triangle, same t (shared edge/vertex)";
        } else if (po < 0 || pe < 0) {
            a->hitmiss++;
            kind = "hit vs miss";
        } else {
            a->other++;
            kind = "different t";
        }
        if (a->nex >= MAX_EXAMPLES)
            continue;
        char where[64] = "";
        if (res > 0)
            snprintf(where, sizeof where, " (pixel %zu,%zu)", k % (size_t)res, k / (size_t)res);
        snprintf(a->ex[a->nex++], sizeof a->ex[0], "ray %zu%s: ours prim %d t %.9g, Embree prim %d t %.9g: %s", k,
                 where, po, po >= 0 ? hits[k].t : -1.0, pe, pe >= 0 ? (double)er->t[k] : -1.0, kind);
    }
}

/* the statistics of a committed scene (memory_bytes, grid_cells, grid_refs) from a 2x2 render */
static int ours_stats(rt_scene *sc, rt_stats *rs)
{
    rt_camera cam;
    float px[3 * 4];
    rt_render_options o;
    memset(rs, 0, sizeof *rs);
    rt_render_options_default(&o);
    o.threads = 1;
    if (bs_camera(&cam, 30.0, 1.0, 4.0, 2, 2) != RT_OK || rt_render(sc, &cam, &o, px, rs) != RT_OK)
        return -1;
    return 0;
}

static int cmd_rays(int res, int nfiles, char **files)
{
    em_mem mem;
    atomic_init(&mem.bytes, 0);
    atomic_init(&mem.peak, 0);
    RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
    if (!dev) {
        fprintf(stderr, "rtcNewDevice failed\n");
        return 1;
    }
    rtcSetDeviceMemoryMonitorFunction(dev, em_monitor, &mem);
    printf("Embree %d.%d.%d vs ours: %dx%d primary rays + shadow rays to one point light, 1 thread, "
           "CPU seconds of the tracing thread, best of %d interleaved runs\n",
           RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, res, res, REPS);
    printf("E.pk16: Embree's rtcIntersect16 packets (4x4 pixel blocks) on the same primary rays\n");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s | %7s %8s %8s %6s | %s\n", "mesh", "tris", "o.prim", "E.prim",
           "o/E", "E.pk16", "o/E16", "shadow", "o.shad", "E.shad", "o/E", "agreement (primary; shadow)");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s | %7s %8s %8s %6s |\n", "", "", "Mrays/s", "Mrays/s", "", "Mrays/s",
           "", "rays", "Mrays/s", "Mrays/s", "");
    int fails = 0;
    char(*inc_rows)[640] = bs_alloc((size_t)nfiles, sizeof *inc_rows);
    char(*bld_rows)[200] = bs_alloc((size_t)nfiles, sizeof *bld_rows);
    if (!inc_rows || !bld_rows) {
        fprintf(stderr, "out of memory\n");
        free(inc_rows);
        free(bld_rows);
        rtcReleaseDevice(dev);
        return 1;
    }
    for (int f = 0; f < nfiles; f++) {
        inc_rows[f][0] = bld_rows[f][0] = '\0';
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
        size_t n = (size_t)res * res, nbox = n < IBOX_RAYS ? n : IBOX_RAYS;
        rt_ray *rays = bs_alloc(n, sizeof *rays);
        rt_ray *srays = bs_alloc(n, sizeof *srays);
        rt_ray *irays = bs_alloc(n, sizeof *irays);
        rt_ray *brays = bs_alloc(nbox, sizeof *brays);
        rt_ray *cand = bs_alloc(nbox, sizeof *cand);
        rt_hit *hits = bs_alloc(n, sizeof *hits);
        rt_hit *ihits = bs_alloc(n, sizeof *ihits);
        unsigned char *occ = bs_alloc(n, 1);
        em_res er = {bs_alloc(n, sizeof(int)), bs_alloc(n, sizeof(float)), bs_alloc(n, 1)};
        long long mem0 = atomic_load(&mem.bytes);
        RTCScene esc = em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris);
        if (!rays || !srays || !irays || !brays || !cand || !hits || !ihits || !occ || !er.prim || !er.t ||
            !er.occ || !esc) {
            fprintf(stderr, "%s: out of memory\n", base);
            fails++;
            goto next;
        }
        rtcCommitScene(esc);
        const long long emem = atomic_load(&mem.bytes) - mem0;
        for (int y = 0; y < res; y++)
            for (int x = 0; x < res; x++)
                rt_camera_ray(&s.cam, x + 0.5, y + 0.5, &rays[(size_t)y * res + x]);
        double op = 1e30, ep = 1e30, os = 1e30, es = 1e30, e16 = 1e30;
        size_t ns = 0, hit16 = 0;
        for (int r = 0; r < REPS; r++) {
            op = fmin(op, time_ours(s.rt, rays, n, hits));
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
        agreement ag;
        agree(rays, hits, &er, n, res, &ag);
        size_t socc = 0, sdis = 0;
        for (size_t k = 0; k < ns; k++) {
            socc += occ[k];
            sdis += occ[k] != er.occ[k];
        }
        size_t dis = ag.tie + ag.hitmiss + ag.other;
        size_t ehit = 0;
        for (size_t k = 0; k < n; k++)
            ehit += er.prim[k] >= 0;
        printf("%-24s %7zu | %8.2f %8.2f %6.2f | %8.2f %6.2f | %7zu %8.2f %8.2f %6.2f | %zu/%zu rays differ; %zu/%zu\n",
               base, s.ntris, n / op * 1e-6, n / ep * 1e-6, ep / op, n / e16 * 1e-6, e16 / op, ns,
               ns ? ns / os * 1e-6 : 0.0, ns ? ns / es * 1e-6 : 0.0, ns ? es / os : 0.0, dis, n, sdis, ns);
        printf("    packets: %zu hits (rtcIntersect1: %zu)\n", hit16, ehit);
        printf("    primary: %zu hits (ours), %zu both miss, %zu same triangle (max rel. t diff %.2e, tol %.0e); "
               "differ: %zu edge/vertex ties, %zu hit/miss, %zu other; shadow: %zu occluded (ours), %zu differ\n",
               ag.nhit, ag.both_miss, ag.same, ag.maxrel, TOL_T, ag.tie, ag.hitmiss, ag.other, socc, sdis);
        for (int e = 0; e < ag.nex; e++)
            printf("    e.g. %s\n", ag.ex[e]);
        fflush(stdout);

        /* incoherent rays: from inside the mesh, and in-box misses */
        const size_t ni = make_inside_rays(rays, hits, n, irays);
        const size_t nm = make_ibox_rays(&s, nbox, brays, cand, ihits);
        double oi = 1e30, ei = 1e30, om = 1e30, em = 1e30;
        for (int r = 0; r < REPS; r++) {
            if (ni) {
                oi = fmin(oi, time_ours(s.rt, irays, ni, ihits));
                ei = fmin(ei, time_embree_primary(esc, &s, irays, ni, &er));
            }
            if (nm) {
                om = fmin(om, time_ours(s.rt, brays, nm, hits));
                em = fmin(em, time_embree_primary(esc, &s, brays, nm, &er));
            }
        }
        /* er holds Embree's answers on the in-box misses (hits: ours) */
        agreement am, ai;
        agree(brays, hits, &er, nm, 0, &am);
        if (ni)
            time_embree_primary(esc, &s, irays, ni, &er);
        agree(irays, ihits, &er, ni, 0, &ai);
        int len = snprintf(inc_rows[f], sizeof inc_rows[0],
                           "%-24s %7zu | %7zu %8.2f %8.2f %6.2f | %7zu %8.2f %8.2f %6.2f | inside %zu/%zu differ "
                           "(%zu hits); misses %zu/%zu differ\n",
                           base, s.ntris, ni, ni ? ni / oi * 1e-6 : 0.0, ni ? ni / ei * 1e-6 : 0.0, ni ? ei / oi : 0.0,
                           nm, nm ? nm / om * 1e-6 : 0.0, nm ? nm / em * 1e-6 : 0.0, nm ? em / om : 0.0,
                           ai.tie + ai.hitmiss + ai.other, ni, ai.nhit, am.tie + am.hitmiss + am.other, nm);
        for (int e = 0; e < ai.nex && e < 2 && len > 0 && (size_t)len < sizeof inc_rows[0]; e++)
            len += snprintf(inc_rows[f] + len, sizeof inc_rows[0] - (size_t)len, "    inside e.g. %s\n", ai.ex[e]);
        for (int e = 0; e < am.nex && e < 2 && len > 0 && (size_t)len < sizeof inc_rows[0]; e++)
            len += snprintf(inc_rows[f] + len, sizeof inc_rows[0] - (size_t)len, "    misses e.g. %s\n", am.ex[e]);

        /* build time and memory of this mesh */
        const rt_build_options one = {.brute_threshold = -1, .threads = 1};
        double ob = 1e30, eb = 1e30;
        rt_stats rs;
        for (int r = 0; r < REPS; r++) {
            double t0 = bs_process_cpu();
            int rc = rt_scene_commit(s.rt, &one);
            ob = fmin(ob, bs_process_cpu() - t0);
            RTCScene es2 = em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris);
            if (rc != RT_OK || !es2) {
                fails++;
                if (es2)
                    rtcReleaseScene(es2);
                break;
            }
            t0 = bs_process_cpu();
            rtcCommitScene(es2);
            eb = fmin(eb, bs_process_cpu() - t0);
            rtcReleaseScene(es2);
        }
        if (ours_stats(s.rt, &rs) != 0)
            fails++;
        const double omem = (double)rs.memory_bytes;
        snprintf(bld_rows[f], sizeof bld_rows[0],
                 "%-24s %7zu | %8.4f %8.4f %6.2f | %8.1f %8.1f %6.2f | %8.1f %8.1f %8.1f\n", base, s.ntris, ob,
                 eb, ob / eb, omem / s.ntris, (double)emem / s.ntris, omem / (double)emem,
                 (double)rs.tri_bytes / s.ntris, (double)rs.grid_bytes / s.ntris,
                 (omem - (double)rs.tri_bytes - (double)rs.grid_bytes) / s.ntris);
    next:
        if (esc)
            rtcReleaseScene(esc);
        free(rays);
        free(srays);
        free(irays);
        free(brays);
        free(cand);
        free(hits);
        free(ihits);
        free(occ);
        free(er.prim);
        free(er.t);
        free(er.occ);
        bs_free(&s);
    }
    printf("(o/E = ours Mrays/s / Embree Mrays/s; issue 21's goals: primary o/E >= 1.0 against "
           "rtcIntersect1 on every mesh, shadow o/E >= 0.7; o/E16 against the packets reported, aim >= 0.5)\n");
    printf("\nEmbree %d.%d.%d vs ours, incoherent rays (nearest hit, rtcIntersect1), the same rays, 1 thread, CPU "
           "seconds of the tracing thread, best of %d interleaved runs\n",
           RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH, REPS);
    printf("inside: from every primary hit, just behind the surface (inside a closed mesh), uniform random "
           "directions into the mesh; misses: rays from a sphere around the mesh box aimed into the box that miss the mesh\n");
    printf("%-24s %7s | %7s %8s %8s %6s | %7s %8s %8s %6s | %s\n", "mesh", "tris", "inside", "o.ins", "E.ins", "o/E",
           "misses", "o.miss", "E.miss", "o/E", "agreement");
    printf("%-24s %7s | %7s %8s %8s %6s | %7s %8s %8s %6s |\n", "", "", "rays", "Mrays/s", "Mrays/s", "", "rays",
           "Mrays/s", "Mrays/s", "");
    for (int f = 0; f < nfiles; f++)
        fputs(inc_rows[f], stdout);
    printf("(issue 21's goals: inside o/E >= 0.7, in-box misses o/E >= 0.8)\n");
    printf("\nMesh build time and memory: rt_scene_commit (default options, 1 thread) vs rtcCommitScene, process CPU "
           "seconds, best of %d; memory as in the random-triangle series below\n",
           REPS);
    printf("o.B/tri in parts (rt_stats): tri = the triangle records (rt_prim and the double vertices rt_tri), "
           "grid = both grid levels, rest = the other scene arrays\n");
    printf("%-24s %7s | %8s %8s %6s | %8s %8s %6s | %8s %8s %8s\n", "mesh", "tris", "o.build", "E.build", "o/E",
           "o.B/tri", "E.B/tri", "o/E", "tri", "grid", "rest");
    printf("%-24s %7s | %8s %8s %6s | %8s %8s %6s | %8s %8s %8s\n", "", "", "s", "s", "", "", "", "", "B/tri",
           "B/tri", "B/tri");
    for (int f = 0; f < nfiles; f++)
        fputs(bld_rows[f], stdout);
    printf("(issue 21's goals: build o/E <= 1.5, mem o/E <= 1.0)\n");
    free(inc_rows);
    free(bld_rows);
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

/* ---------------------------------------------------------------- build scaling */

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
            rt_grid_info g2, g1;
            if (rc == RT_OK)
                rc = rt_scene_grid_info(sc, &g2);
            double t0 = bs_process_cpu();
            if (rc == RT_OK)
                rc = rt_scene_commit(sc, &b1);
            ob = fmin(ob, bs_process_cpu() - t0);
            if (rc == RT_OK)
                rc = rt_scene_grid_info(sc, &g1);
            if (rc == RT_OK && g1.hash != g2.hash) { /* the grid must not depend on the threads */
                printf("%9zu   grid hash %016llx with 1 thread, %016llx with 2\n", n,
                       (unsigned long long)g1.hash, (unsigned long long)g2.hash);
                rc = RT_ERR_STATE;
            }
            if (rc != RT_OK || ours_stats(sc, &rs) != 0)
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

/* the one traced pass of cmd_ours (a function of its own: callgrind --toggle-collect=ours_pass) */
__attribute__((noinline)) static void ours_pass(const rt_scene *sc, int shadow, size_t m, const rt_ray *rays,
                                                rt_hit *hits, unsigned char *occ)
{
    if (shadow)
        rt_occluded(sc, m, rays, occ);
    else
        rt_intersect(sc, m, rays, hits);
}

/* ours only on one ray set, traced once after the rays are made (for callgrind/perf) */
static int cmd_ours(int res, const char *set, const char *file)
{
    bs_scene s;
    char err[512];
    bs_options opt = {.size = res};
    if (bs_load(file, &opt, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        bs_free(&s);
        return 1;
    }
    size_t n = (size_t)res * res, nbox = n < IBOX_RAYS ? n : IBOX_RAYS, m = 0;
    rt_ray *rays = bs_alloc(n, sizeof *rays), *set_rays = bs_alloc(n, sizeof *set_rays);
    rt_ray *cand = bs_alloc(nbox, sizeof *cand);
    rt_hit *hits = bs_alloc(n, sizeof *hits), *tmp = bs_alloc(n, sizeof *tmp);
    unsigned char *occ = bs_alloc(n, 1);
    int rc = 1;
    if (!rays || !set_rays || !cand || !hits || !tmp || !occ) {
        fprintf(stderr, "out of memory\n");
        goto done;
    }
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++)
            rt_camera_ray(&s.cam, x + 0.5, y + 0.5, &rays[(size_t)y * res + x]);
    if (strcmp(set, "primary") != 0)
        rt_intersect(s.rt, n, rays, hits);
    if (!strcmp(set, "primary")) {
        memcpy(set_rays, rays, n * sizeof *rays);
        m = n;
    } else if (!strcmp(set, "shadow")) {
        m = make_shadow_rays(&s, hits, n, set_rays);
    } else if (!strcmp(set, "inside")) {
        m = make_inside_rays(rays, hits, n, set_rays);
    } else if (!strcmp(set, "misses")) {
        m = make_ibox_rays(&s, nbox, set_rays, cand, tmp);
    } else {
        fprintf(stderr, "unknown ray set %s (primary, shadow, inside, misses)\n", set);
        goto done;
    }
    double t0 = bs_thread_cpu();
    ours_pass(s.rt, !strcmp(set, "shadow"), m, set_rays, hits, occ);
    double t = bs_thread_cpu() - t0;
    /* FNV-1a over the answers (primitive and t bits, or the occluded flags): equal sums, the
       same hits bit for bit */
    uint64_t h = 1469598103934665603ULL;
    for (size_t k = 0; k < m; k++) {
        uint64_t v = (uint64_t)occ[k];
        if (strcmp(set, "shadow") != 0) {
            memcpy(&v, &hits[k].t, sizeof v);
            v ^= (uint64_t)(uint32_t)hits[k].prim << 1;
        }
        for (int b = 0; b < 8; b++)
            h = (h ^ ((v >> (8 * b)) & 0xFF)) * 1099511628211ULL;
    }
    printf("%s %s: %zu rays, %.3f s CPU, %.2f Mrays/s (one pass), answers %016llx\n", file, set, m, t,
           t > 0 ? m / t * 1e-6 : 0.0, (unsigned long long)h);
    rc = 0;
done:
    free(rays);
    free(set_rays);
    free(cand);
    free(hits);
    free(tmp);
    free(occ);
    bs_free(&s);
    return rc;
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
    if (argc == 5 && !strcmp(argv[1], "ours")) {
        int res = atoi(argv[2]);
        if (res < 1 || res > 8192) {
            fprintf(stderr, "bad resolution\n");
            return 2;
        }
        return cmd_ours(res, argv[3], argv[4]);
    }
    fprintf(stderr, "usage: cmp_embree rays RES mesh.off... | cmp_embree build | cmp_embree ours RES SET mesh.off\n");
    return 2;
}
