/* SPDX-License-Identifier: MIT */
/*
 * cmp_embree -- ours (rt_intersect / rt_occluded) vs Embree 3 (rtcIntersect1 / rtcOccluded1,
 * and its rtcIntersect16 packets on the primary rays), one thread, the same rays, same run;
 * ours' coherent path (rt_intersect_packet / rt_occluded_packet, 8x8 pixel blocks) beside.
 *   cmp_embree rays RES mesh.off...   primary, shadow and incoherent Mrays/s, ratios, hit
 *                                     agreement; build time and memory of each mesh
 *   cmp_embree build                  build time and memory per primitive, 10^4 .. 10^6 triangles
 *   cmp_embree ours RES SET mesh.off  ours only, one pass over one ray set (SET: primary, shadow,
 *                                     inside, misses; the rays below; packets, shadowpk: the
 *                                     primary and shadow rays in 8x8 pixel blocks through the
 *                                     packet path), for profilers: e.g.
 *                                     valgrind --tool=callgrind --toggle-collect=ours_pass
 *   cmp_embree embree RES SET mesh.off  Embree only on the same rays (the single-ray sets, the
 *                                     rays made by ours as above): rtcIntersect1 / rtcOccluded1,
 *                                     --toggle-collect=embree_pass
 *   cmp_embree commit SRC KIND [T]   one rt_scene_commit on T threads (default 1) of SRC: N
 *                                     random triangles (as in build) or a mesh file, KIND tri
 *                                     (separate triangles) or mesh (one indexed mesh); prints
 *                                     its CPU time and the grid's hash (the same hash, the same
 *                                     grid), for profilers: --toggle-collect=commit_pass;
 *                                     KIND embree: Embree's rtcCommitScene of N random
 *                                     triangles as build gives them (embree_commit_pass)
 *   cmp_embree judge RES mesh.off...  the disagreements on the primary, inside, misses and
 *                                     shadow rays, judged in exact rational arithmetic (GMP) on
 *                                     the inputs each tracer was given; ours also on Embree's
 *                                     float inputs
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
 * Meshes: both tracers are given the same kind of geometry, an indexed triangle mesh (ours:
 * rt_scene_add_mesh of the file's vertex buffer and its (fan) triangles' index triples, double
 * vertices; Embree: the same buffers in float). Ours then reports one id for the whole mesh,
 * so on the meshes "same" means the same mesh at the same t (a hit on the neighbour of
 * Embree's triangle across a shared edge counts as the same); the judge below loads the
 * triangles separately (one id each) to name the triangle.
 * Mesh build: from the caller's arrays to a committed scene, each tracer given the same
 * vertex and index arrays: ours rt_scene_add_mesh (its copy and spatial order) + rt_scene_commit
 * (default options, 1 thread), Embree its float buffers + rtcCommitScene; process CPU time,
 * best of 5; memory as in the build series.
 * Agreement: both miss, or both hit the same triangle with |t_ours - t_embree| <= TOL_T *
 * (t_ours + |org| / |dir|) (TOL_T = 1e-5: Embree's float ray/triangle test and float ray
 * origin; distances within a few float ulps of the scene scale; the primary rays start at
 * the eye, the origin of VRC3). Shadow: same occluded flag.
 */
#include "bench_scene.h"

#include <embree3/rtcore.h>
#include <gmp.h>
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

/* the pixel index of the k-th ray of a res x res raster in the order of ours' packets:
   8x8 blocks (RT_PACKET rays) row by row, rays row by row within a block; blocks cut at the
   raster's edge, so that with res not a multiple of 8 later packets straddle blocks */
enum { PK_SIDE = 8 };
static void block_order(int res, size_t *perm)
{
    size_t k = 0;
    for (int by = 0; by < res; by += PK_SIDE)
        for (int bx = 0; bx < res; bx += PK_SIDE)
            for (int j = 0; j < PK_SIDE * PK_SIDE; j++) {
                const int x = bx + j % PK_SIDE, y = by + j / PK_SIDE;
                if (x < res && y < res)
                    perm[k++] = (size_t)y * (size_t)res + (size_t)x;
            }
}

/* ours' packet path on the primary rays (rt_intersect_packet, 8x8 pixel blocks), timed as
   Embree's packets are: the rays gathered from the raster-order array into packet order one
   strip of blocks (PK_SIDE rows) at a time, into buffers that stay in the cache as Embree's
   16-ray packet on the stack does, traced, and the hits counted; blk and bh are scratch of at
   least PK_SIDE * res rays. (Gathering the whole frame first and scattering the hits back
   after it, as this did before, timed 384 bytes of memory traffic a ray that Embree's loop
   does not have: 20-25 % of ours' packet time at 1024^2.) */
static double time_ours_packets(const rt_scene *sc, const rt_ray *rays, int res, const size_t *perm,
                                rt_ray *blk, rt_hit *bh, size_t *nhit)
{
    const size_t n = (size_t)res * (size_t)res, strip = (size_t)PK_SIDE * (size_t)res;
    size_t hits = 0;
    double t0 = bs_thread_cpu();
    for (size_t k0 = 0; k0 < n; k0 += strip) {
        const size_t m = n - k0 < strip ? n - k0 : strip;
        for (size_t k = 0; k < m; k++)
            blk[k] = rays[perm[k0 + k]];
        rt_intersect_packet(sc, m, blk, bh);
        for (size_t k = 0; k < m; k++)
            hits += bh[k].prim >= 0;
    }
    double t = bs_thread_cpu() - t0;
    *nhit = hits;
    return t;
}

/* the packet path's answers for the whole frame, untimed: blk the rays and bh the hits in
   packet order, hits the same in raster order */
static void ours_packets_answers(const rt_scene *sc, const rt_ray *rays, size_t n, const size_t *perm,
                                 rt_ray *blk, rt_hit *bh, rt_hit *hits)
{
    for (size_t k = 0; k < n; k++)
        blk[k] = rays[perm[k]];
    rt_intersect_packet(sc, n, blk, bh);
    for (size_t k = 0; k < n; k++)
        hits[perm[k]] = bh[k];
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

/* ours given a mesh as Embree is given it: nv vertices v and nt index triples ix, one
   indexed mesh. Timed, as Embree's em_scene + rtcCommitScene, from the caller's arrays to a
   committed scene: rt_scene_add_mesh (the copy, and the spatial order the tracer stores a
   mesh in) and the commit on 1 thread, process CPU seconds in *secs; the statistics in *rs.
   0, or -1 on failure. */
__attribute__((noinline)) static int build_ours_mesh(const double *v, size_t nv, const uint32_t *ix, size_t nt, double *secs, rt_stats *rs)
{
    rt_scene *sc = rt_scene_new();
    rt_surface su;
    rt_surface_default(&su);
    const int sid = sc ? rt_scene_add_surface(sc, &su) : -1;
    const rt_build_options b1 = {.brute_threshold = -1, .threads = 1};
    const double t0 = bs_process_cpu();
    int rc = sid >= 0 ? rt_scene_add_mesh(sc, nv, v, NULL, NULL, nt, ix, sid, sid) : RT_ERR_NOMEM;
    if (rc >= 0)
        rc = rt_scene_commit(sc, &b1);
    *secs = bs_process_cpu() - t0;
    if (rc == RT_OK && ours_stats(sc, rs) != 0)
        rc = RT_ERR_STATE;
    rt_scene_free(sc);
    return rc == RT_OK ? 0 : -1;
}

/* Embree's side of build_ours_mesh: em_scene (the float buffers) and rtcCommitScene, process
   CPU seconds; the scene released. 0, or -1 on failure. */
__attribute__((noinline)) static int build_embree_mesh(RTCDevice dev, const double *v, size_t nv, const uint32_t *ix, size_t nt, double *secs)
{
    const double t0 = bs_process_cpu();
    RTCScene es = em_scene(dev, v, nv, ix, nt);
    if (!es)
        return -1;
    rtcCommitScene(es);
    *secs = bs_process_cpu() - t0;
    rtcReleaseScene(es);
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
    printf("E.pk16: Embree's rtcIntersect16 packets (4x4 pixel blocks) on the same primary rays; o/E16: ours' "
           "single-ray path against them; o.pk, pk/E16: ours' packet path (rt_intersect_packet, 8x8 pixel "
           "blocks, gathered a strip of 8 rows per call as Embree gathers a packet per call, hits counted) against "
           "them; o.shpk, pk/E: ours' rt_occluded_packet on the shadow rays in block order against "
           "rtcOccluded1\n");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s %8s %6s | %7s %8s %8s %6s %8s %6s | %s\n", "mesh", "tris", "o.prim",
           "E.prim", "o/E", "E.pk16", "o/E16", "o.pk", "pk/E16", "shadow", "o.shad", "E.shad", "o/E", "o.shpk",
           "pk/E", "agreement (primary; shadow)");
    printf("%-24s %7s | %8s %8s %6s | %8s %6s %8s %6s | %7s %8s %8s %6s %8s %6s |\n", "", "", "Mrays/s", "Mrays/s",
           "", "Mrays/s", "", "Mrays/s", "", "rays", "Mrays/s", "Mrays/s", "", "Mrays/s", "");
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
        bs_options opt = {.size = res, .indexed = 1};
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
        size_t *perm = bs_alloc(n, sizeof *perm);
        rt_ray *blk = bs_alloc(n, sizeof *blk);
        rt_hit *bh = bs_alloc(n, sizeof *bh), *phits = bs_alloc(n, sizeof *phits);
        unsigned char *pocc = bs_alloc(n, 1);
        em_res er = {bs_alloc(n, sizeof(int)), bs_alloc(n, sizeof(float)), bs_alloc(n, 1)};
        long long mem0 = atomic_load(&mem.bytes);
        RTCScene esc = em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris);
        if (!rays || !srays || !irays || !brays || !cand || !hits || !ihits || !occ || !er.prim || !er.t ||
            !er.occ || !esc || !perm || !blk || !bh || !phits || !pocc) {
            fprintf(stderr, "%s: out of memory\n", base);
            fails++;
            goto next;
        }
        rtcCommitScene(esc);
        const long long emem = atomic_load(&mem.bytes) - mem0;
        for (int y = 0; y < res; y++)
            for (int x = 0; x < res; x++)
                rt_camera_ray(&s.cam, x + 0.5, y + 0.5, &rays[(size_t)y * res + x]);
        double op = 1e30, ep = 1e30, os = 1e30, es = 1e30, e16 = 1e30, o16 = 1e30, osp = 1e30;
        size_t ns = 0, hit16 = 0, hitpk = 0;
        block_order(res, perm);
        for (int r = 0; r < REPS; r++) {
            op = fmin(op, time_ours(s.rt, rays, n, hits));
            ep = fmin(ep, time_embree_primary(esc, &s, rays, n, &er));
            e16 = fmin(e16, time_embree_packets(esc, rays, res, &hit16));
            o16 = fmin(o16, time_ours_packets(s.rt, rays, res, perm, blk, bh, &hitpk));
        }
        ours_packets_answers(s.rt, rays, n, perm, blk, bh, phits);
        /* the packet path's answers against the single-ray path's, bit for bit */
        size_t pkdiff = 0;
        for (size_t k = 0; k < n; k++)
            pkdiff += phits[k].prim != hits[k].prim ||
                      (hits[k].prim >= 0 && memcmp(&phits[k].t, &hits[k].t, sizeof hits[k].t) != 0);
        ns = make_shadow_rays(&s, hits, n, srays);
        /* the same shadow rays in block order (from the hits in block order), for the packets */
        const size_t nsb = make_shadow_rays(&s, bh, n, blk);
        for (int r = 0; r < REPS && ns; r++) {
            double t0 = bs_thread_cpu();
            rt_occluded(s.rt, ns, srays, occ);
            os = fmin(os, bs_thread_cpu() - t0);
            es = fmin(es, time_embree_shadow(esc, srays, ns, &er));
            t0 = bs_thread_cpu();
            rt_occluded_packet(s.rt, nsb, blk, pocc);
            osp = fmin(osp, bs_thread_cpu() - t0);
        }
        size_t spkdiff = 0;
        if (nsb) { /* against rt_occluded on the same block-order rays (after the timing) */
            unsigned char *o1 = bs_alloc(nsb, 1);
            if (o1 && rt_occluded(s.rt, nsb, blk, o1) == RT_OK)
                for (size_t k = 0; k < nsb; k++)
                    spkdiff += o1[k] != pocc[k];
            else
                spkdiff = nsb;
            free(o1);
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
        printf("%-24s %7zu | %8.2f %8.2f %6.2f | %8.2f %6.2f %8.2f %6.2f | %7zu %8.2f %8.2f %6.2f %8.2f %6.2f | "
               "%zu/%zu rays differ; %zu/%zu\n",
               base, s.ntris, n / op * 1e-6, n / ep * 1e-6, ep / op, n / e16 * 1e-6, e16 / op, n / o16 * 1e-6,
               e16 / o16, ns, ns ? ns / os * 1e-6 : 0.0, ns ? ns / es * 1e-6 : 0.0, ns ? es / os : 0.0,
               nsb ? nsb / osp * 1e-6 : 0.0, nsb ? es / osp : 0.0, dis, n, sdis, ns);
        printf("    packets: %zu hits (rtcIntersect1: %zu; ours' packets %zu); ours' packet path: %zu/%zu primary "
               "rays differ from its single-ray path (primitive or t bits), %zu/%zu shadow rays\n",
               hit16, ehit, hitpk, pkdiff, n, spkdiff, nsb);
        fails += pkdiff != 0 || spkdiff != 0 || hitpk != ag.nhit;
        printf("    primary: %zu hits (ours), %zu both miss, %zu same %s (max rel. t diff %.2e, tol %.0e); "
               "differ: %zu edge/vertex ties, %zu hit/miss, %zu other; shadow: %zu occluded (ours), %zu differ\n",
               ag.nhit, ag.both_miss, ag.same, s.indexed ? "mesh and t" : "triangle", ag.maxrel, TOL_T, ag.tie,
               ag.hitmiss, ag.other, socc, sdis);
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

        /* build time and memory of this mesh, from the arrays to a committed scene */
        double ob = 1e30, eb = 1e30;
        rt_stats rs;
        memset(&rs, 0, sizeof rs);
        for (int r = 0; r < REPS; r++) {
            double o1, e1;
            if (build_ours_mesh(s.verts_vrc, s.nverts, s.tris, s.ntris, &o1, &rs) != 0 ||
                build_embree_mesh(dev, s.verts_vrc, s.nverts, s.tris, s.ntris, &e1) != 0) {
                fails++;
                break;
            }
            ob = fmin(ob, o1);
            eb = fmin(eb, e1);
        }
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
        free(perm);
        free(blk);
        free(bh);
        free(phits);
        free(pocc);
        free(er.prim);
        free(er.t);
        free(er.occ);
        bs_free(&s);
    }
    printf("(o/E = ours Mrays/s / Embree Mrays/s; issue 39's goals on every mesh: primary o/E >= 1.0 against "
           "rtcIntersect1, ours' packets pk/E16 >= 0.5 against rtcIntersect16, shadow rays >= 0.8 against "
           "rtcOccluded1)\n");
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
    printf("(issue 39's goals: inside o/E >= 0.7, in-box misses o/E >= 0.8)\n");
    printf("\nMesh build time and memory, from the vertex and index arrays to a committed scene: rt_scene_add_mesh + "
           "rt_scene_commit (default options, 1 thread) vs Embree's float buffers + rtcCommitScene, process CPU "
           "seconds, best of %d; memory as in the random-triangle series below\n",
           REPS);
    printf("o.B/tri in parts (rt_stats): tri = the triangle records (rt_prim, and the mesh's double vertex buffer and index triples), "
           "grid = both grid levels, rest = the other scene arrays\n");
    printf("%-24s %7s | %8s %8s %6s | %8s %8s %6s | %8s %8s %8s\n", "mesh", "tris", "o.build", "E.build", "o/E",
           "o.B/tri", "E.B/tri", "o/E", "tri", "grid", "rest");
    printf("%-24s %7s | %8s %8s %6s | %8s %8s %6s | %8s %8s %8s\n", "", "", "s", "s", "", "", "", "", "B/tri",
           "B/tri", "B/tri");
    for (int f = 0; f < nfiles; f++)
        fputs(bld_rows[f], stdout);
    printf("(issue 39's goals: build o/E <= 1.2, mem o/E <= 1.0)\n");
    free(inc_rows);
    free(bld_rows);
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

/* ---------------------------------------------------------------- exact judge */

/* A ray with exact inputs: the doubles ours traces, or the floats Embree traces (converted to
   double exactly). Hits of the closed triangle a b c in [tmin, tmax] are decided in rational
   arithmetic (GMP mpq: every double is a dyadic rational, so nothing is rounded): the line
   o + t d crosses the closed triangle when the signed volumes [d, a-o, b-o], [d, b-o, c-o],
   [d, c-o, a-o] are all >= 0 or all <= 0 and not all 0 (a ray in the triangle's plane counts
   as a miss, as in both tracers); t = n.(a-o) / n.d with n = (b-a) x (c-a). */
typedef struct xray {
    double o[3], d[3], tmin, tmax;
} xray;

typedef struct xjudge {
    mpq_t A[3], B[3], C[3], D[3], tmp, tmp2, v[3], n[3], e1[3], e2[3], num, den, t, best;
} xjudge;

static void xj_init(xjudge *x)
{
    mpq_t *all[] = {x->A, x->B, x->C, x->D, x->v, x->n, x->e1, x->e2};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        for (int i = 0; i < 3; i++)
            mpq_init(all[k][i]);
    mpq_inits(x->tmp, x->tmp2, x->num, x->den, x->t, x->best, NULL);
}

static void xj_clear(xjudge *x)
{
    mpq_t *all[] = {x->A, x->B, x->C, x->D, x->v, x->n, x->e1, x->e2};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        for (int i = 0; i < 3; i++)
            mpq_clear(all[k][i]);
    mpq_clears(x->tmp, x->tmp2, x->num, x->den, x->t, x->best, NULL);
}

/* out = a x b */
static void xj_cross(xjudge *x, mpq_t out[3], mpq_t a[3], mpq_t b[3])
{
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3, k = (i + 2) % 3;
        mpq_mul(x->tmp, a[j], b[k]);
        mpq_mul(x->tmp2, a[k], b[j]);
        mpq_sub(out[i], x->tmp, x->tmp2);
    }
}

/* out = a . b */
static void xj_dot(xjudge *x, mpq_t out, mpq_t a[3], mpq_t b[3])
{
    mpq_set_ui(out, 0, 1);
    for (int i = 0; i < 3; i++) {
        mpq_mul(x->tmp, a[i], b[i]);
        mpq_add(out, out, x->tmp);
    }
}

/* sign of [D, P, Q] = D . (P x Q) */
static int xj_vol(xjudge *x, mpq_t P[3], mpq_t Q[3])
{
    xj_cross(x, x->v, P, Q);
    xj_dot(x, x->num, x->D, x->v);
    return mpq_sgn(x->num);
}

/* 1 and x->t = the exact distance when r hits the closed triangle a b c in [tmin, tmax] */
static int xj_hit(xjudge *x, const xray *r, const double *a, const double *b, const double *c)
{
    for (int i = 0; i < 3; i++) {
        mpq_set_d(x->tmp, r->o[i]);
        mpq_set_d(x->A[i], a[i]);
        mpq_sub(x->A[i], x->A[i], x->tmp);
        mpq_set_d(x->B[i], b[i]);
        mpq_sub(x->B[i], x->B[i], x->tmp);
        mpq_set_d(x->C[i], c[i]);
        mpq_sub(x->C[i], x->C[i], x->tmp);
        mpq_set_d(x->D[i], r->d[i]);
    }
    const int s0 = xj_vol(x, x->A, x->B), s1 = xj_vol(x, x->B, x->C), s2 = xj_vol(x, x->C, x->A);
    if ((s0 < 0 || s1 < 0 || s2 < 0) && (s0 > 0 || s1 > 0 || s2 > 0))
        return 0;
    if (s0 == 0 && s1 == 0 && s2 == 0)
        return 0;
    for (int i = 0; i < 3; i++) {
        mpq_sub(x->e1[i], x->B[i], x->A[i]);
        mpq_sub(x->e2[i], x->C[i], x->A[i]);
    }
    xj_cross(x, x->n, x->e1, x->e2);
    xj_dot(x, x->den, x->n, x->D);
    if (mpq_sgn(x->den) == 0)
        return 0;
    xj_dot(x, x->num, x->n, x->A);
    mpq_div(x->t, x->num, x->den);
    mpq_set_d(x->tmp, r->tmin);
    if (mpq_cmp(x->t, x->tmp) < 0)
        return 0;
    if (isfinite(r->tmax)) {
        mpq_set_d(x->tmp, r->tmax);
        if (mpq_cmp(x->t, x->tmp) > 0)
            return 0;
    }
    return 1;
}

/* a mesh as one tracer was given it: vertices (double, or float values as double) and the
   triangles' boxes for the filter */
typedef struct xmesh {
    const double *v;
    const uint32_t *tri;
    size_t ntri;
    double *box; /* 6 per triangle: lo xyz, hi xyz, enlarged by a relative 1e-6 */
} xmesh;

static int xmesh_init(xmesh *m, const double *v, const uint32_t *tri, size_t ntri)
{
    m->v = v;
    m->tri = tri;
    m->ntri = ntri;
    m->box = bs_alloc(ntri, 6 * sizeof(double));
    if (!m->box)
        return -1;
    for (size_t j = 0; j < ntri; j++) {
        double *b = m->box + 6 * j;
        for (int i = 0; i < 3; i++) {
            b[i] = INFINITY;
            b[3 + i] = -INFINITY;
        }
        double mag = 0.0;
        for (int k = 0; k < 3; k++)
            for (int i = 0; i < 3; i++) {
                double c = v[3 * tri[3 * j + k] + i];
                b[i] = fmin(b[i], c);
                b[3 + i] = fmax(b[3 + i], c);
                mag = fmax(mag, fabs(c));
            }
        for (int i = 0; i < 3; i++) {
            b[i] -= 1e-6 * mag;
            b[3 + i] += 1e-6 * mag;
        }
    }
    return 0;
}

/* can the ray meet box b? (the slab test in double on a box enlarged far beyond its
   rounding errors, 1e-6 relative: never rejects a triangle the ray hits; a filter only) */
static int x_box(const xray *r, const double *b)
{
    double t0 = -INFINITY, t1 = INFINITY;
    for (int i = 0; i < 3; i++) {
        if (r->d[i] == 0.0) {
            if (r->o[i] < b[i] || r->o[i] > b[3 + i])
                return 0;
            continue;
        }
        double ta = (b[i] - r->o[i]) / r->d[i], tb = (b[3 + i] - r->o[i]) / r->d[i];
        if (ta > tb) {
            double s = ta;
            ta = tb;
            tb = s;
        }
        ta -= 1e-9 * fabs(ta) + 1e-300;
        tb += 1e-9 * fabs(tb) + 1e-300;
        t0 = fmax(t0, ta);
        t1 = fmin(t1, tb);
    }
    return t0 <= t1 && t1 >= r->tmin - 1e-9 * fabs(r->tmin) - 1e-300 &&
           t0 <= r->tmax + 1e-9 * fabs(r->tmax) + 1e-300;
}

/* The exact nearest hit of r on m: returns the number of triangles at the nearest exact
   distance (0: the ray misses), their indices in near[] (at most XNEAR kept: a vertex of
   higher valence hit exactly is judged on the first XNEAR) */
enum { XNEAR = 32 };
static int x_nearest(xjudge *x, const xmesh *m, const xray *r, size_t near[XNEAR])
{
    int nn = 0;
    for (size_t j = 0; j < m->ntri; j++) {
        if (!x_box(r, m->box + 6 * j))
            continue;
        const uint32_t *t = m->tri + 3 * j;
        if (!xj_hit(x, r, m->v + 3 * t[0], m->v + 3 * t[1], m->v + 3 * t[2]))
            continue;
        int c = nn ? mpq_cmp(x->t, x->best) : -1;
        if (c < 0) {
            mpq_set(x->best, x->t);
            nn = 0;
        }
        if (c <= 0) {
            if (nn < XNEAR)
                near[nn] = j;
            nn++;
        }
    }
    return nn;
}

/* is a tracer's answer (a triangle index, -1 for a miss) the exact one? */
static int x_right(int nn, const size_t near[XNEAR], long tri)
{
    if (nn == 0)
        return tri < 0;
    for (int k = 0; k < nn && k < XNEAR; k++)
        if ((long)near[k] == tri)
            return 1;
    return 0;
}

static void x_ray_double(const rt_ray *r, xray *x)
{
    for (int i = 0; i < 3; i++) {
        x->o[i] = r->org[i];
        x->d[i] = r->dir[i];
    }
    x->tmin = r->tmin;
    x->tmax = r->tmax;
}

/* the ray as em_rayhit gives it to Embree */
static void x_ray_float(const rt_ray *r, xray *x)
{
    for (int i = 0; i < 3; i++) {
        x->o[i] = (float)r->org[i];
        x->d[i] = (float)r->dir[i];
    }
    x->tmin = (float)r->tmin;
    x->tmax = isinf(r->tmax) ? INFINITY : (float)r->tmax;
}

/* disagreement classes of the judge */
enum { XC_OHIT_EMISS, XC_OMISS_EHIT, XC_OTHER_TRI, XC_N };
static const char *const xc_name[XC_N] = {"ours hit, Embree miss", "ours miss, Embree hit",
                                          "both hit, other triangle"};

typedef struct xtally {
    size_t n, ours_d, emb_f, emb_d, both_f, oursf_f; /* see cmd_judge's legend */
} xtally;

/* is a tracer's answer (a gksrt primitive id, -1 for a miss) the exact one? (a polygon is a
   fan of several triangles: one of them among the nearest) */
static int x_prim_right(const bs_scene *s, int nn, const size_t near[XNEAR], int prim)
{
    if (prim < 0)
        return nn == 0;
    for (int k = 0; k < nn && k < XNEAR; k++)
        if (s->tri_prim[near[k]] == prim)
            return 1;
    return 0;
}

/* judges the rays on which ours (double inputs: hits) and Embree (float inputs: eprim as
   gksrt ids) disagree on the triangle hit or on hit vs miss; fhits: ours on the float inputs
   (primitive k = triangle k) */
static void x_judge_set(const bs_scene *s, const xmesh *md, const xmesh *mf, const rt_ray *rays, const rt_hit *hits, const int *eprim, const rt_hit *fhits,
                        size_t n, xtally tl[XC_N], size_t *fdis, size_t *fdis_oursf, size_t *fdis_emb,
                        size_t *nself, size_t *self_ok)
{
    xjudge x;
    xj_init(&x);
    memset(tl, 0, XC_N * sizeof *tl);
    *fdis = *fdis_oursf = *fdis_emb = *nself = *self_ok = 0;
    for (size_t k = 0; k < n; k++) {
        const int po = hits[k].prim, pe = eprim[k];
        const long tf = fhits[k].prim;
        xray rd, rf;
        size_t nd[XNEAR], nf[XNEAR];
        int nnd = -1, nnf = -1;
        /* ours on the float inputs against Embree on the same inputs */
        if ((tf < 0) != (pe < 0) || (tf >= 0 && s->tri_prim[tf] != pe)) {
            x_ray_float(&rays[k], &rf);
            nnf = x_nearest(&x, mf, &rf, nf);
            (*fdis)++;
            *fdis_oursf += x_right(nnf, nf, tf);
            *fdis_emb += x_prim_right(s, nnf, nf, pe);
        }
        if (po == pe) {
            /* the judge's self-check: every 1009th ray on which both agree, exactly */
            if (k % 1009 == 0) {
                x_ray_double(&rays[k], &rd);
                nnd = x_nearest(&x, md, &rd, nd);
                (*nself)++;
                *self_ok += x_prim_right(s, nnd, nd, po);
            }
            continue;
        }
        int c = po >= 0 && pe < 0 ? XC_OHIT_EMISS : po < 0 ? XC_OMISS_EHIT : XC_OTHER_TRI;
        x_ray_double(&rays[k], &rd);
        nnd = x_nearest(&x, md, &rd, nd);
        if (nnf < 0) {
            x_ray_float(&rays[k], &rf);
            nnf = x_nearest(&x, mf, &rf, nf);
        }
        xtally *t = &tl[c];
        t->n++;
        const int od = x_prim_right(s, nnd, nd, po), ef = x_prim_right(s, nnf, nf, pe);
        t->ours_d += od;
        t->emb_f += ef;
        t->emb_d += x_prim_right(s, nnd, nd, pe);
        t->both_f += od && ef;
        t->oursf_f += x_right(nnf, nf, tf);
    }
    xj_clear(&x);
}

static void x_print(const char *set, const xtally tl[XC_N], size_t fdis, size_t fo, size_t fe, size_t nself,
                    size_t self_ok)
{
    for (int c = 0; c < XC_N; c++)
        if (tl[c].n)
            printf("  %-8s %-26s %6zu | %8zu %8zu %8zu %8zu | %8zu\n", set, xc_name[c], tl[c].n, tl[c].ours_d,
                   tl[c].emb_f, tl[c].emb_d, tl[c].both_f, tl[c].oursf_f);
    printf("  %-8s %-26s %6zu |     (same inputs: ours-f right %zu, Embree right %zu)\n", set,
           "ours-f vs Embree differ", fdis, fo, fe);
    printf("  %-8s %-26s %6zu |     (the exact answer is both tracers' on %zu)\n", set, "self-check, agreeing rays",
           nself, self_ok);
}

/* shadow rays (occluded or not): ours (occ, double inputs) against Embree (eocc, float
   inputs) and ours on the float inputs (focc), judged by the exact existence of a hit in
   [tmin, tmax]; printed as the nearest-hit classes are */
static void x_judge_shadow(const xmesh *md, const xmesh *mf, const rt_ray *rays, const unsigned char *occ,
                           const unsigned char *eocc, const unsigned char *focc, size_t n)
{
    xjudge x;
    xj_init(&x);
    size_t nd[XNEAR], nf[XNEAR];
    size_t cls[2] = {0, 0}, ours[2] = {0, 0}, ef[2] = {0, 0}, ed[2] = {0, 0}, both[2] = {0, 0};
    size_t fo[2] = {0, 0}, fdis = 0, f_ok = 0, e_ok = 0, nself = 0, self_ok = 0;
    for (size_t k = 0; k < n; k++) {
        xray rd, rf;
        int xf = -1;
        if (focc[k] != eocc[k]) {
            x_ray_float(&rays[k], &rf);
            xf = x_nearest(&x, mf, &rf, nf) > 0;
            fdis++;
            f_ok += focc[k] == xf;
            e_ok += eocc[k] == xf;
        }
        if (occ[k] == eocc[k]) {
            if (k % 1009 == 0) {
                x_ray_double(&rays[k], &rd);
                nself++;
                self_ok += (x_nearest(&x, md, &rd, nd) > 0) == occ[k];
            }
            continue;
        }
        const int c = occ[k] ? 0 : 1; /* 0: ours blocked, Embree lit; 1: the reverse */
        x_ray_double(&rays[k], &rd);
        const int xd = x_nearest(&x, md, &rd, nd) > 0;
        if (xf < 0) {
            x_ray_float(&rays[k], &rf);
            xf = x_nearest(&x, mf, &rf, nf) > 0;
        }
        cls[c]++;
        ours[c] += occ[k] == xd;
        ef[c] += eocc[k] == xf;
        ed[c] += eocc[k] == xd;
        both[c] += occ[k] == xd && eocc[k] == xf;
        fo[c] += focc[k] == xf;
    }
    static const char *const name[2] = {"ours blocked, Embree lit", "ours lit, Embree blocked"};
    for (int c = 0; c < 2; c++)
        if (cls[c])
            printf("  %-8s %-26s %6zu | %8zu %8zu %8zu %8zu | %8zu\n", "shadow", name[c], cls[c], ours[c], ef[c],
                   ed[c], both[c], fo[c]);
    printf("  %-8s %-26s %6zu |     (same inputs: ours-f right %zu, Embree right %zu)\n", "shadow",
           "ours-f vs Embree differ", fdis, f_ok, e_ok);
    printf("  %-8s %-26s %6zu |     (the exact answer is both tracers' on %zu)\n", "shadow",
           "self-check, agreeing rays", nself, self_ok);
    xj_clear(&x);
}

/* cmp_embree judge RES mesh.off...: the disagreements of the rays command, judged exactly */
static int cmd_judge(int res, int nfiles, char **files)
{
    RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
    if (!dev)
        return 1;
    printf("Disagreements of ours and Embree %d.%d.%d on the nearest hit, judged in exact rational arithmetic "
           "(GMP) on the inputs each was given\n", RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
    printf("  ours: double vertices and rays; Embree: the same rounded to float. ours-f: ours given Embree's "
           "float inputs (the same geometry and rays)\n");
    printf("  columns: rays in the class | ours right (double inputs), Embree right on its float inputs, Embree "
           "right on the double inputs, both right on their own inputs | ours-f right (float inputs)\n");
    printf("  'right' = the tracer's triangle is among the exactly nearest (shared edges and vertices: all "
           "of them), or it misses and the ray hits nothing exactly\n");
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
        size_t n = (size_t)res * res, nbox = n < IBOX_RAYS ? n : IBOX_RAYS;
        rt_ray *rays = bs_alloc(n, sizeof *rays), *irays = bs_alloc(n, sizeof *irays);
        rt_ray *brays = bs_alloc(nbox, sizeof *brays), *cand = bs_alloc(nbox, sizeof *cand);
        rt_ray *frays = bs_alloc(n, sizeof *frays), *srays = bs_alloc(n, sizeof *srays);
        unsigned char *occ = bs_alloc(n, 1), *focc = bs_alloc(n, 1);
        rt_hit *hits = bs_alloc(n, sizeof *hits), *ihits = bs_alloc(n, sizeof *ihits);
        rt_hit *bhits = bs_alloc(nbox, sizeof *bhits), *fhits = bs_alloc(n, sizeof *fhits);
        double *vf = bs_alloc(s.nverts, 3 * sizeof(double)), *tv = bs_alloc(9, sizeof(double));
        em_res er = {bs_alloc(n, sizeof(int)), bs_alloc(n, sizeof(float)), bs_alloc(n, 1)};
        RTCScene esc = em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris);
        rt_scene *fsc = rt_scene_new();
        xmesh md = {0}, mf = {0};
        if (!rays || !irays || !brays || !cand || !frays || !srays || !occ || !focc || !hits || !ihits || !bhits || !fhits || !vf || !tv ||
            !er.prim || !er.t || !er.occ || !esc || !fsc) {
            fprintf(stderr, "%s: out of memory\n", base);
            fails++;
            goto next;
        }
        rtcCommitScene(esc);
        for (size_t i = 0; i < 3 * s.nverts; i++)
            vf[i] = (float)s.verts_vrc[i];
        /* ours on Embree's inputs: the float-rounded triangles, one polygon each (id = index) */
        rt_surface su;
        rt_surface_default(&su);
        int sid = rt_scene_add_surface(fsc, &su), three = 3;
        for (size_t j = 0; j < s.ntris && sid >= 0; j++) {
            for (int k = 0; k < 3; k++)
                memcpy(tv + 3 * k, vf + 3 * s.tris[3 * j + k], 3 * sizeof(double));
            if (rt_scene_add_polygon(fsc, 1, &three, tv, sid, sid) != (int)j)
                sid = -1;
        }
        if (sid < 0 || rt_scene_commit(fsc, NULL) != RT_OK || xmesh_init(&md, s.verts_vrc, s.tris, s.ntris) ||
            xmesh_init(&mf, vf, s.tris, s.ntris)) {
            fprintf(stderr, "%s: the float-input scene or the judge's boxes failed\n", base);
            fails++;
            goto next;
        }
        for (int y = 0; y < res; y++)
            for (int xx = 0; xx < res; xx++)
                rt_camera_ray(&s.cam, xx + 0.5, y + 0.5, &rays[(size_t)y * res + xx]);
        time_ours(s.rt, rays, n, hits);
        const size_t ni = make_inside_rays(rays, hits, n, irays);
        const size_t nm = make_ibox_rays(&s, nbox, brays, cand, bhits);
        printf("%s (%zu triangles; %zu primary, %zu inside, %zu in-box miss rays)\n", base, s.ntris, n, ni, nm);
        printf("  %-8s %-26s %6s | %8s %8s %8s %8s | %8s\n", "set", "class", "rays", "ours", "E(f)", "E(d)",
               "both", "ours-f");
        struct {
            const char *name;
            const rt_ray *r;
            rt_hit *h;
            size_t n;
        } sets[3] = {{"primary", rays, hits, n}, {"inside", irays, ihits, ni}, {"misses", brays, bhits, nm}};
        for (int q = 0; q < 3; q++) {
            if (!sets[q].n)
                continue;
            time_ours(s.rt, sets[q].r, sets[q].n, sets[q].h);
            time_embree_primary(esc, &s, sets[q].r, sets[q].n, &er);
            for (size_t k = 0; k < sets[q].n; k++) {
                rt_ray *fr = &frays[k];
                *fr = sets[q].r[k];
                for (int i = 0; i < 3; i++) {
                    fr->org[i] = (float)fr->org[i];
                    fr->dir[i] = (float)fr->dir[i];
                }
                fr->tmin = (float)fr->tmin;
                fr->tmax = isinf(fr->tmax) ? INFINITY : (float)fr->tmax;
            }
            time_ours(fsc, frays, sets[q].n, fhits);
            xtally tl[XC_N];
            size_t fdis, fo, fe, nself, self_ok;
            x_judge_set(&s, &md, &mf, sets[q].r, sets[q].h, er.prim, fhits, sets[q].n, tl, &fdis,
                        &fo, &fe, &nself, &self_ok);
            x_print(sets[q].name, tl, fdis, fo, fe, nself, self_ok);
            fflush(stdout);
        }
        /* shadow rays from ours' primary hits (hits: the primary set's, traced above) */
        const size_t ns = make_shadow_rays(&s, hits, n, srays);
        if (ns) {
            rt_occluded(s.rt, ns, srays, occ);
            time_embree_shadow(esc, srays, ns, &er);
            for (size_t k = 0; k < ns; k++) {
                frays[k] = srays[k];
                for (int i = 0; i < 3; i++) {
                    frays[k].org[i] = (float)frays[k].org[i];
                    frays[k].dir[i] = (float)frays[k].dir[i];
                }
                frays[k].tmin = (float)frays[k].tmin;
                frays[k].tmax = isinf(frays[k].tmax) ? INFINITY : (float)frays[k].tmax;
            }
            rt_occluded(fsc, ns, frays, focc);
            printf("  (%zu shadow rays to the light from ours' primary hits)\n", ns);
            x_judge_shadow(&md, &mf, srays, occ, er.occ, focc, ns);
            fflush(stdout);
        }
    next:
        if (esc)
            rtcReleaseScene(esc);
        rt_scene_free(fsc);
        free(md.box);
        free(mf.box);
        free(rays);
        free(irays);
        free(brays);
        free(cand);
        free(frays);
        free(srays);
        free(occ);
        free(focc);
        free(hits);
        free(ihits);
        free(bhits);
        free(fhits);
        free(vf);
        free(tv);
        free(er.prim);
        free(er.t);
        free(er.occ);
        bs_free(&s);
    }
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

/* ---------------------------------------------------------------- build scaling */

/* N random triangles (cmd_build's, see there): 9n vertex doubles, 3n indices (vertex 3t + k) */
static int random_tris(size_t n, double **vp, uint32_t **ixp)
{
    double *v = bs_alloc(n, 9 * sizeof(double));
    uint32_t *ix = bs_alloc(n, 3 * sizeof(uint32_t));
    *vp = v;
    *ixp = ix;
    if (!v || !ix)
        return -1;
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
    return 0;
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
    printf("m.*: ours given the triangles as Embree is: one indexed mesh of the 3N vertices (none shared) and N "
           "index triples, timed from the arrays to a committed scene (rt_scene_add_mesh + commit on 1 thread); "
           "m/E build against Embree's em_scene (float buffers) + rtcCommitScene\n");
    printf("%9s | %8s %9s %8s %8s %8s %9s %8s | %8s %8s | %8s %9s %8s | %6s %6s | %6s %6s\n", "tris", "o.build",
           "o.us/tri", "o.B/tri", "cells", "refs", "o.Mtri/s", "o.2t", "m.build", "m.B/tri", "E.build", "E.us/tri",
           "E.B/tri", "build", "mem", "build", "mem");
    printf("%9s | %8s %9s %8s %8s %8s %9s %8s | %8s %8s | %8s %9s %8s | %6s %6s | %6s %6s\n", "", "s", "", "",
           "/tri", "/tri", "", "wall s", "s", "", "s", "", "", "o/E", "o/E", "m/E", "m/E");
    static const size_t counts[] = {10000, 30000, 100000, 300000, 1000000};
    int fails = 0;
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        size_t n = counts[c];
        double *v;
        uint32_t *ix;
        if (random_tris(n, &v, &ix) != 0) {
            free(v);
            free(ix);
            fails++;
            continue;
        }
        double ob = 1e30, eb = 1e30, ebm = 1e30, ob2 = 1e30, mb = 1e30;
        rt_stats rs, ms;
        memset(&rs, 0, sizeof rs);
        memset(&ms, 0, sizeof ms);
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
            double m1 = 1e30;
            if (build_ours_mesh(v, 3 * n, ix, n, &m1, &ms) != 0)
                fails++;
            mb = fmin(mb, m1);

            long long before = atomic_load(&mem.bytes);
            const double ta = bs_process_cpu();
            RTCScene es = em_scene(dev, v, 3 * n, ix, n);
            if (!es) {
                fails++;
                continue;
            }
            t0 = bs_process_cpu();
            rtcCommitScene(es);
            const double t1 = bs_process_cpu();
            eb = fmin(eb, t1 - t0);
            ebm = fmin(ebm, t1 - ta);
            emem = atomic_load(&mem.bytes) - before;
            rtcReleaseScene(es);
        }
        printf("%9zu | %8.4f %9.3f %8.1f %8.2f %8.2f %9.2f %8.4f | %8.4f %8.1f | %8.4f %9.3f %8.1f | %6.2f %6.2f | "
               "%6.2f %6.2f\n",
               n, ob, ob / n * 1e6, (double)rs.memory_bytes / n, (double)rs.grid_cells / n, (double)rs.grid_refs / n,
               n / ob * 1e-6, ob2, mb, (double)ms.memory_bytes / n, eb, eb / n * 1e6, (double)emem / n, ob / eb,
               (double)rs.memory_bytes / (double)emem, mb / ebm, (double)ms.memory_bytes / (double)emem);
        fflush(stdout);
        free(v);
        free(ix);
    }
    printf("(us/tri and B/tri flat as N grows = linear build time and memory; issue 39's goals: build <= 1.2, "
           "mem <= 1.0, ours given the triangles as Embree is: m/E)\n");
    rtcReleaseDevice(dev);
    return fails ? 1 : 0;
}

/* the one commit of cmd_commit (a function of its own: callgrind --toggle-collect=commit_pass) */
__attribute__((noinline)) static int commit_pass(rt_scene *sc, int threads)
{
    const rt_build_options o = {.brute_threshold = -1, .threads = threads};
    return rt_scene_commit(sc, &o);
}

/* Embree's counterpart of commit_pass: rtcCommitScene of the em_scene made before it (callgrind
   --toggle-collect=embree_commit_pass) */
__attribute__((noinline)) static void embree_commit_pass(RTCScene es)
{
    rtcCommitScene(es);
}

/* cmd_commit's "embree" kind: N random triangles as cmd_build gives them to Embree (one mesh
   of 3N unshared float vertices), one rtcCommitScene on a 1-thread device; prints its process
   CPU seconds and Embree's memory per triangle (the device's memory monitor) */
static int cmd_commit_embree(size_t n)
{
    em_mem mem;
    atomic_init(&mem.bytes, 0);
    atomic_init(&mem.peak, 0);
    double *v = NULL;
    uint32_t *ix = NULL;
    RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
    RTCScene es = NULL;
    if (dev) {
        rtcSetDeviceMemoryMonitorFunction(dev, em_monitor, &mem);
        if (random_tris(n, &v, &ix) == 0)
            es = em_scene(dev, v, 3 * n, ix, n);
    }
    free(v);
    free(ix);
    if (!es) {
        fprintf(stderr, "cannot make the scene\n");
        if (dev)
            rtcReleaseDevice(dev);
        return 1;
    }
    const long long before = atomic_load(&mem.bytes);
    const double t0 = bs_process_cpu();
    embree_commit_pass(es);
    const double t = bs_process_cpu() - t0;
    const long long emem = atomic_load(&mem.bytes);
    printf("%zu embree, 1 thread: commit %.4f s CPU; %.1f B/tri (%.1f before the commit)\n", n, t,
           (double)emem / (double)n, (double)before / (double)n);
    rtcReleaseScene(es);
    rtcReleaseDevice(dev);
    return 0;
}

/* one commit for profilers and for checking that a change of the build keeps the grid: SRC a
   number N (cmd_build's N random triangles) or a mesh file (as cmd_rays loads it); kind "tri"
   (separate triangles, rt_scene_add_polygon) or "mesh" (one indexed mesh); prints the commit's
   process CPU seconds, the grid's hash (rt_grid_info.hash: equal, the same grid) and size */
static int cmd_commit(const char *src, const char *kind, int threads)
{
    const int mesh = !strcmp(kind, "mesh");
    if (!strcmp(kind, "embree")) {
        char *e;
        const unsigned long long ne = strtoull(src, &e, 10);
        if (*e != '\0' || ne == 0 || ne > 100000000ULL) {
            fprintf(stderr, "embree: N random triangles only\n");
            return 1;
        }
        return cmd_commit_embree((size_t)ne);
    }
    rt_scene *sc = NULL;
    bs_scene s;
    memset(&s, 0, sizeof s);
    char *end;
    const unsigned long long nr = strtoull(src, &end, 10);
    if (*end == '\0' && nr > 0 && nr <= 100000000ULL) {
        double *v = NULL;
        uint32_t *ix = NULL;
        sc = rt_scene_new();
        rt_surface su;
        rt_surface_default(&su);
        int sid = sc && random_tris((size_t)nr, &v, &ix) == 0 ? rt_scene_add_surface(sc, &su) : -1;
        const int three = 3;
        if (mesh && sid >= 0 && rt_scene_add_mesh(sc, 3 * (size_t)nr, v, NULL, NULL, (size_t)nr, ix, sid, sid) < 0)
            sid = -1;
        for (size_t t = 0; !mesh && t < (size_t)nr && sid >= 0; t++)
            if (rt_scene_add_polygon(sc, 1, &three, v + 9 * t, sid, sid) < 0)
                sid = -1;
        free(v);
        free(ix);
        if (sid < 0) {
            fprintf(stderr, "cannot make the scene\n");
            rt_scene_free(sc);
            return 1;
        }
    } else {
        char err[512];
        bs_options opt = {.size = 16, .indexed = mesh};
        if (bs_load(src, &opt, &s, err, sizeof err) != 0) {
            fprintf(stderr, "%s\n", err);
            bs_free(&s);
            return 1;
        }
        sc = s.rt;
    }
    const double t0 = bs_process_cpu(), w0 = bs_wall();
    int rc = commit_pass(sc, threads);
    const double t = bs_process_cpu() - t0, w = bs_wall() - w0;
    rt_grid_info gi;
    rt_stats rs;
    if (rc == RT_OK)
        rc = rt_scene_grid_info(sc, &gi);
    if (rc == RT_OK && ours_stats(sc, &rs) != 0)
        rc = RT_ERR_STATE;
    if (rc == RT_OK)
        printf("%s %s, %d thread(s): commit %.4f s CPU, %.4f s wall; grid %016llx: %llu cells %llu refs, "
               "%llu sub-grids %llu cells %llu refs; %.1f B/prim\n",
               src, mesh ? "mesh" : "tri", threads, t, w, (unsigned long long)gi.hash, (unsigned long long)gi.cells,
               (unsigned long long)gi.refs, (unsigned long long)gi.subgrids, (unsigned long long)gi.subcells,
               (unsigned long long)gi.subrefs, (double)rs.memory_bytes / (double)gi.prims);
    else
        fprintf(stderr, "commit failed (%d)\n", rc);
    if (s.rt)
        bs_free(&s);
    else
        rt_scene_free(sc);
    return rc == RT_OK ? 0 : 1;
}

/* the one traced pass of cmd_ours (a function of its own: callgrind --toggle-collect=ours_pass) */
__attribute__((noinline)) static void ours_pass(const rt_scene *sc, int shadow, int packets, size_t m,
                                                const rt_ray *rays, rt_hit *hits, unsigned char *occ)
{
    if (shadow && packets)
        rt_occluded_packet(sc, m, rays, occ);
    else if (shadow)
        rt_occluded(sc, m, rays, occ);
    else if (packets)
        rt_intersect_packet(sc, m, rays, hits);
    else
        rt_intersect(sc, m, rays, hits);
}

/* the packet sets of cmd_ours: the primary rays in 4x4 block order (packets), or the shadow
   rays made from the primary hits in block order (shadowpk); src[j] the pixel of ray j */
static size_t ours_block_set(const bs_scene *s, int res, int shadow, const rt_ray *rays, const rt_hit *hits,
                             rt_ray *out, size_t *src)
{
    const size_t n = (size_t)res * (size_t)res;
    size_t *perm = bs_alloc(n, sizeof *perm), m = 0;
    if (!perm)
        return 0;
    block_order(res, perm);
    for (size_t k = 0; k < n; k++) {
        if (!shadow)
            out[m] = rays[perm[k]];
        else if (make_shadow_rays(s, &hits[perm[k]], 1, &out[m]) == 0)
            continue;
        src[m++] = perm[k];
    }
    free(perm);
    return m;
}

/* the one traced pass of cmd_ours' Embree run (callgrind --toggle-collect=embree_pass):
   rtcIntersect1 or rtcOccluded1 per ray, as the rays command times them */
__attribute__((noinline)) static double embree_pass(RTCScene esc, const bs_scene *s, int shadow, size_t m,
                                                    const rt_ray *rays, em_res *er)
{
    return shadow ? time_embree_shadow(esc, rays, m, er) : time_embree_primary(esc, s, rays, m, er);
}

/* ours only (embree = 0) or Embree only (1: the single-ray sets) on one ray set, traced once
   after the rays are made (for callgrind/perf); the rays are made by ours either way */
static int cmd_ours(int res, const char *set, const char *file, int embree)
{
    bs_scene s;
    char err[512];
    bs_options opt = {.size = res, .indexed = 1};
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
    size_t *src = bs_alloc(n, sizeof *src);
    int rc = 1;
    if (!rays || !set_rays || !cand || !hits || !tmp || !occ || !src) {
        fprintf(stderr, "out of memory\n");
        goto done;
    }
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++)
            rt_camera_ray(&s.cam, x + 0.5, y + 0.5, &rays[(size_t)y * res + x]);
    if (strcmp(set, "primary") != 0 && strcmp(set, "packets") != 0)
        rt_intersect(s.rt, n, rays, hits);
    const int shadow = !strcmp(set, "shadow") || !strcmp(set, "shadowpk");
    const int packets = !strcmp(set, "packets") || !strcmp(set, "shadowpk");
    if (!strcmp(set, "primary")) {
        memcpy(set_rays, rays, n * sizeof *rays);
        m = n;
    } else if (!strcmp(set, "shadow")) {
        m = make_shadow_rays(&s, hits, n, set_rays);
    } else if (!strcmp(set, "inside")) {
        m = make_inside_rays(rays, hits, n, set_rays);
    } else if (!strcmp(set, "misses")) {
        m = make_ibox_rays(&s, nbox, set_rays, cand, tmp);
    } else if (packets) {
        m = ours_block_set(&s, res, shadow, rays, hits, set_rays, src);
    } else {
        fprintf(stderr, "unknown ray set %s (primary, shadow, inside, misses, packets, shadowpk)\n", set);
        goto done;
    }
    if (embree) {
        if (packets) {
            fprintf(stderr, "embree: single-ray sets only (primary, shadow, inside, misses)\n");
            goto done;
        }
        RTCDevice dev = rtcNewDevice("threads=1,set_affinity=0");
        RTCScene esc = dev ? em_scene(dev, s.verts_vrc, s.nverts, s.tris, s.ntris) : NULL;
        em_res er = {bs_alloc(m ? m : 1, sizeof(int)), bs_alloc(m ? m : 1, sizeof(float)), occ};
        size_t nh = 0;
        if (esc && er.prim && er.t) {
            memset(er.prim, 0, (m ? m : 1) * sizeof(int)); /* pages written before the pass, as ours' */
            memset(er.t, 0, (m ? m : 1) * sizeof(float));
            memset(occ, 0, n);
            rtcCommitScene(esc);
            const double te = embree_pass(esc, &s, shadow, m, set_rays, &er);
            for (size_t k = 0; k < m; k++)
                nh += shadow ? occ[k] : er.prim[k] >= 0;
            printf("%s %s: %zu rays, Embree %.3f s CPU, %.2f Mrays/s (one pass), %zu %s\n", file, set, m, te,
                   te > 0 ? m / te * 1e-6 : 0.0, nh, shadow ? "occluded" : "hits");
            rc = 0;
        } else
            fprintf(stderr, "Embree scene failed\n");
        free(er.prim);
        free(er.t);
        if (esc)
            rtcReleaseScene(esc);
        if (dev)
            rtcReleaseDevice(dev);
        goto done;
    }
    /* the answers' pages written once before the timed pass: otherwise the first write's page
       faults (64 MB of hits at 1024^2, costly in a VM) are timed as tracing */
    memset(hits, 0, n * sizeof *hits);
    memset(occ, 0, n);
    double t0 = bs_thread_cpu();
    ours_pass(s.rt, shadow, packets, m, set_rays, hits, occ);
    double t = bs_thread_cpu() - t0;
    if (packets) { /* the answers back in pixel order: the hash of primary / shadow */
        if (!shadow) {
            for (size_t k = 0; k < m; k++)
                tmp[src[k]] = hits[k];
            memcpy(hits, tmp, m * sizeof *hits);
        } else {
            unsigned char *px = calloc(n, 1);
            if (!px) {
                fprintf(stderr, "out of memory\n");
                goto done;
            }
            for (size_t k = 0; k < m; k++)
                px[src[k]] = (unsigned char)(1 + occ[k]);
            size_t j = 0;
            for (size_t k = 0; k < n; k++)
                if (px[k])
                    occ[j++] = (unsigned char)(px[k] - 1);
            free(px);
        }
    }
    /* FNV-1a over the answers (primitive and t bits, or the occluded flags): equal sums, the
       same hits bit for bit */
    uint64_t h = 1469598103934665603ULL;
    for (size_t k = 0; k < m; k++) {
        uint64_t v = (uint64_t)occ[k];
        if (!shadow) {
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
    free(src);
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
    if ((argc == 4 || argc == 5) && !strcmp(argv[1], "commit"))
        return cmd_commit(argv[2], argv[3], argc == 5 ? atoi(argv[4]) : 1);
    if (argc == 5 && (!strcmp(argv[1], "ours") || !strcmp(argv[1], "embree"))) {
        int res = atoi(argv[2]);
        if (res < 1 || res > 8192) {
            fprintf(stderr, "bad resolution\n");
            return 2;
        }
        return cmd_ours(res, argv[3], argv[4], !strcmp(argv[1], "embree"));
    }
    if (argc >= 4 && !strcmp(argv[1], "judge")) {
        int res = atoi(argv[2]);
        if (res < 1 || res > 8192) {
            fprintf(stderr, "bad resolution\n");
            return 2;
        }
        return cmd_judge(res, argc - 3, argv + 3);
    }
    fprintf(stderr, "usage: cmp_embree rays RES mesh.off... | cmp_embree build | cmp_embree ours|embree RES SET mesh.off"
                    " | cmp_embree judge RES mesh.off... | cmp_embree commit N|mesh.off tri|mesh [THREADS] | cmp_embree commit N embree\n");
    return 2;
}
