/* SPDX-License-Identifier: MIT */
/*
 * rt_render.c -- shading (PHIGS PLUS reflectance equations, shadows, mirror reflection,
 * refraction with Fresnel weighting) and the tiled multi-threaded frame loop.
 *
 * Secondary ray origins are offset from the hit point along the geometric normal, to the
 * side the ray leaves on, by eps = 1e-12 * (max|hit coordinate| + t) + 1e-9 * scene extent:
 * about 10^4 ulps of the hit point's magnitude, far above its rounding error, far below any
 * feature size. Planar primitives cannot be re-hit from that side, so the traversal does not
 * even test the primitive a secondary ray leaves (rt_rayx.skip; also not as the cached
 * shadow blocker): one triangle test less per shadow, reflection and refraction ray.
 *
 * Shadow rays: one per non-ambient light in the surface's light mask when the (ray-facing)
 * normal faces the light, the surface's reflectance equation uses diffuse/specular terms and
 * the spot cone reaches the point. A transparent surface on the way attenuates the light by
 * its transparency coefficient kt (no refraction of shadow rays); an opaque one blocks it.
 *
 * Transmitting surfaces (kt > 0): Fresnel reflectance F (exact dielectric or Schlick); the
 * reflected ray has weight ks*Cs + kt*F, the refracted ray kt*(1 - F); total internal reflection
 * gives F = 1. Index exactly 1: straight through, F = 0, the ray continues on its own line
 * (origin moved forward along d past the surface, not along the normal), so the picture
 * behind is unchanged. Local shading is not scaled by kt.
 *
 * Frame loop: tiles of 16x16 rays; a tile row's primary rays are made together from
 * per-column and per-row terms (rt_camera_rays_row: the same bits as rt_camera_ray). Corner
 * rays (SPD mode) are traced once each and kept in the picture itself (corner (x,y) at pixel
 * (x,y), the last row and column aside) and averaged in place at the end: no second
 * full-size buffer to page-fault in. Per worker: a mailbox and, per depth and light, the last
 * opaque shadow blocker, tested first (rt_isect_prim; an opaque hit answers as the traversal
 * would). Lights surely behind the surface are rejected before the square root. Eye rays
 * that no primitive's projection reaches (rt_cover: the convex hull of a triangle's, quad's or
 * cell array's projected vertices, a polygon's box) are background without being traced; the
 * others test just the primitives whose projections reach them (per-ray candidate lists, a
 * superset of what they can hit: the grid is not walked), unless the lists would exceed
 * RT_CAND_PER_RAY entries per ray or the raster RT_CAND_RAYS rays (then the mask alone);
 * the lists ascend in a lower bound of the ray's t at the primitive, and a ray stops where
 * that bound passes its best hit's tie window (rt_cover_keys, rt_trace_cands). Eye rays'
 * reflections off a large flat mirror test the list of a light buffer built from the eye's
 * mirror image (rt_job_mirrors, rt_mirror_nearest) instead of walking the grid.
 * All of this leaves the picture and the ray counts bit for bit as the direct evaluation.
 */

#define _DEFAULT_SOURCE 1 /* madvise */
#define GKS3D_RT_BUILDING 1
#include "rt_geom.h"
#include "rt_internal.h"
#include "rt_lbuf.h"
#include "rt_packet.h"
#include "rt_prim.h"
#include "rt_shade.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

#define RT_TILE 16
#define RT_MAX_DEPTH 64
_Static_assert(RT_TILE <= RT_CAM_ROW, "a tile row is one batch of camera rays");

void rt_render_options_default(rt_render_options *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->samples = 1;
    o->max_depth = 5;
    o->fresnel = RT_FRESNEL_EXACT;
    /* On the speed/error Pareto front (README, docs/speed_error.png): corner rays cost one
     * ray per pixel like a centre ray but filter 2x2; a cut-off of 0.01 saves up to 40 % of
     * the rays for 0.2 % more RMSE. Reference renders set cutoff 0 and samples. */
    o->corner_rays = 1;
    o->cutoff = 0.01;
    o->light_buffers = 1;
}

/* A planar mirror (rt_job_mirrors): a light buffer built from the mirror image of the eye,
   and the terms of its candidates' t bounds (rt_trace_mirror) */
#define RT_MIRRORS 2
typedef struct rt_mirror {
    rt_lbuf lb;   /* ok = 0: none */
    double zstep; /* depth per bucket of lb */
    double k0;    /* lb.zlo less the margins (2 lb.zeps) */
} rt_mirror;

typedef struct rt_job {
    const rt_scene *sc;
    const rt_camera *cam;
    rt_render_options o;
    double eps_box;     /* the scene extent's part of rt_eps: 1e-9 of its largest side */
    float *rgb;
    float *edge;        /* corner mode: corners (w, 0..h) then (0..w-1, h), RGB; the others are
                           kept in rgb itself (corner (x,y) at pixel (x,y)) until averaged */
    float *corner_next; /* after edge in its block: one row of corners per resolve part but the
                           last, the next part's first row as traced (rt_corner_part) */
    int corner_parts;   /* the rows corner_next has room for, + 1 */
    int gw, gh;         /* ray grid size (pixels or corners) */
    int m;              /* strata per axis */
    uint32_t *cand_off; /* one-ray modes, rays up to RT_CAND_RAYS: candidates of ray k (the
                           primitives whose projection, with a margin, reaches it; a superset
                           of those it can hit) are cand[cand_off[k] .. cand_off[k + 1] - 1];
                           NULL: none (then cover, if any) */
    uint32_t *cand;
    double *cand_key;   /* with cand: per primitive a lower bound of the t at which an eye ray
                           can hit it; every list is in ascending order of it (rt_cover_keys) */
    uint8_t *cover;     /* one-ray modes: per ray, 1 if a primitive's projection (with a
                           margin) reaches it; NULL: no culling */
    int packets;        /* one-ray modes without candidate lists: eye rays in 8 x 8 packets
                           (rt_packet.c; the same hits); 0 when GKS_RT_PACKETS=0 */
    rt_lbuf lbuf[RT_MAX_LIGHTS]; /* shadow-ray candidates per light (ok = 0: walk the grid) */
    rt_mirror mir[RT_MIRRORS];   /* planar mirrors' reflection-ray candidates (rt_job_mirrors) */
    uint8_t *mir_of;             /* NULL, or per primitive: 0, or k + 1 for a member of mir[k] */
    unsigned short *cover_out; /* NULL, or per pixel: its eye rays that hit (rt_render_cover) */
    uint8_t *corner_hit;       /* corner mode with cover_out: per corner ray, 1 if it hit */
    int tiles_x, ntiles;
    int stride;         /* the k-th tile taken is (k * stride) mod ntiles (rt_tile_order) */
    atomic_int next;
    atomic_int done;
    atomic_ullong rays;
    double t0, last_report;
    double t_tiles;     /* when the first tile started: the estimate's clock (set-up apart) */
    pthread_mutex_t lock;
    const rt_tile_hook *hook;  /* o.tiles; NULL: every tile here */
    atomic_int hook_failed;    /* a callback failed: threads stop, rt_render fails */
    rt_stats remote;           /* ray counters of the tiles stored by rt_frame_store */
} rt_job;

/* The frame handed to a tile hook (rt_frame_store). */
struct rt_frame {
    rt_job *job;
};

/* Tile payload: RT_PAYLOAD_COUNTERS uint64 ray counters, then RGB floats per ray of the tile,
   row-major (in corner mode the corner rays, before averaging), then, when rt_render_cover
   was asked for coverage, one uint16 per ray: its eye-ray hits (corner mode: 0/1 of the
   corner ray; else of the pixel's samples). */
#define RT_PAYLOAD_COUNTERS 8

/* Shadow-ray blocker cache, one per (depth, light) and thread: the opaque primitives that
 * blocked the latest shadow rays, most recent first. After a blocked ray the next one (the
 * neighbouring pixel's) tests them first: one that it hits gives the traversal's answer
 * (blocked) without walking. Gears, -s 513 -corner: with 4 entries 222k -> 117k blocked
 * walks for 485k more probes (1 entry: 450k hits, 4: 556k). After a lit ray nothing is
 * probed: its successor is most likely lit as well. */
#define RT_SCACHE 4
typedef struct rt_scache {
    long id[RT_SCACHE]; /* -1: none */
    int live;           /* the last shadow ray of this slot was blocked */
} rt_scache;

/* moves entry k (or, k == RT_SCACHE, a new blocker b) to the front */
static void rt_scache_front(rt_scache *c, int k, long b)
{
    if (k == RT_SCACHE)
        for (k = 0; k < RT_SCACHE - 1 && c->id[k] != b; k++)
            ;
    for (; k > 0; k--) /* (memmove of at most 3 entries: a libc call) */
        c->id[k] = c->id[k - 1];
    c->id[0] = b;
}

typedef struct rt_worker {
    rt_job *job;
    rt_ctx ctx;
    rt_scache *shadow_cache; /* [depth * nlights + light] */
    rt_stats st;
    int eye_hit;             /* the latest eye ray hit a primitive */
    int err;
    unsigned char *payload;  /* with a tile hook: one tile's payload */
    char pad[RT_LINE];       /* the next worker's record on other cache lines (RT_LINE) */
} rt_worker;

static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* clip [t0,t1] of a ray to the display volume (6 planes of cam) */
static int rt_clip_volume(const rt_camera *cam, const double o[3], const double d[3], double *t0,
                          double *t1)
{
    double eps = 1e-9 * cam->scale;
    for (int f = 0; f < 6; f++) {
        const double *pl = cam->plane[f];
        double num = dot3(pl, o) + pl[3] + eps;
        double den = dot3(pl, d);
        if (den == 0.0) {
            if (num < 0.0)
                return 0;
            continue;
        }
        double t = -num / den;
        if (den > 0.0) {
            if (t > *t0) *t0 = t;
        } else {
            if (t < *t1) *t1 = t;
        }
    }
    return *t0 <= *t1;
}

static double rt_fresnel(int mode, double cos_i, double cos_t, double n1, double n2)
{
    if (mode == RT_FRESNEL_NONE)
        return 0.0;
    if (mode == RT_FRESNEL_SCHLICK) {
        double r0 = (n1 - n2) / (n1 + n2);
        r0 *= r0;
        double c = n1 <= n2 ? cos_i : cos_t;
        double x = 1.0 - c;
        return r0 + (1.0 - r0) * x * x * x * x * x;
    }
    double rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    double rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

static inline double rt_absmax3(const double v[3])
{
    double a = fabs(v[0]), b = fabs(v[1]), c = fabs(v[2]);
    double m = a > b ? a : b;
    return m > c ? m : c;
}

/* the part of rt_eps that depends on the scene alone (rt_job.eps_box) */
static double rt_eps_box(const rt_scene *sc)
{
    const double e[3] = {sc->bbox[3] - sc->bbox[0], sc->bbox[4] - sc->bbox[1], sc->bbox[5] - sc->bbox[2]};
    return 1e-9 * rt_absmax3(e);
}

/* offset of secondary ray origins from the surface (see the file comment) */
static double rt_eps(const rt_job *job, const double p[3], double t)
{
    return 1e-12 * (rt_absmax3(p) + fabs(t)) + job->eps_box + 1e-300;
}

/* fmax(a, b) inline, the same value for every input as glibc's: b if a is NaN, a if b is
   NaN, b when they compare equal (fmax is a libm call at this build's flags) */
static inline double rt_fmax2(double a, double b)
{
    return (a > b || b != b) ? a : b;
}

/* fmin(a, b) and fmax(a, b) inline for the candidate lists' boxes and row bounds (libm calls
   at this build's flags, 1.7 M of them in SPD gears): glibc's value for every input (a NaN
   operand gives the other one, equal operands the second), in quiet compares as the calls */
static inline double rt_fmin_q(double a, double b)
{
    return isless(a, b) || isnan(b) ? a : b;
}

static inline double rt_fmax_q(double a, double b)
{
    return isgreater(a, b) || isnan(b) ? a : b;
}

/* the candidate primitives of an eye ray (rt_job.cand) */
typedef struct rt_cands {
    const uint32_t *ids;
    size_t n;
    const double *key; /* rt_job.cand_key */
} rt_cands;

static void rt_trace(rt_worker *w, const double o[3], const double d[3], double tmin, double tmax,
                     int depth, double weight, int secondary, long from, const rt_cands *cand,
                     double out[3]);
static void rt_trace_mirror(rt_worker *w, const rt_mirror *m, const double o[3],
                            const double d[3], int depth, double weight, long from, double out[3]);

static void rt_spawn(rt_worker *w, const double p[3], const double n[3], double side_eps,
                     const double d[3], int depth, double weight, int kind, long from,
                     double out[3])
{
    double o[3];
    for (int i = 0; i < 3; i++)
        o[i] = p[i] + side_eps * n[i];
    if (kind == 0)
        w->st.reflection_rays++;
    else
        w->st.refraction_rays++;
    rt_trace(w, o, d, 0.0, INFINITY, depth, weight, 1, from, NULL, out);
}

/* rt_spawn of the reflection ray of an eye ray off a member of mirror mir (not inline: in
   rt_secondary it costs the other secondary rays 0.2 % of SPD mount's instructions) */
static __attribute__((noinline)) void rt_spawn_mirror(rt_worker *w, const rt_mirror *mir,
                                                      const double p[3], const double n[3],
                                                      double side_eps, const double d[3],
                                                      double weight, long from, double out[3])
{
    double o[3];
    for (int i = 0; i < 3; i++)
        o[i] = p[i] + side_eps * n[i];
    w->st.reflection_rays++;
    rt_trace_mirror(w, mir, o, d, 2, weight, from, out);
}

/* the transmittance of the shadow ray from o toward light li over [t0, t1] (t0 < t1), in
   this order: the blocker cache (cache: w->shadow_cache's entry of the ray's depth and
   light), the light's buffer (lb, job->lbuf[li]: the candidates of the ray's cell whose
   projection its footprint does not surely miss, rt_lbuf_next), the grid walk; from is the
   primitive the ray leaves */
static double rt_shadow_T(rt_worker *w, rt_scache *cache, const rt_lbuf *lb, long from,
                          const double o[3], const double L[3], double t0, double t1)
{
    const rt_scene *sc = w->job->sc;
    double T = 0.0;
    rt_rayx r;
    rt_lbuf_q q;
    uint32_t k0 = 0; /* the first candidate of the buffer's list */
    int f = -2;      /* -2: the buffer not asked yet */
    if (!cache->live && lb->ok) {
        /* no blocker to probe: the buffer first, on the ray's origin, range and direction
           as rt_rayx_setup makes them (components below 1e-150 of the largest flushed
           to 0), so the same answer as after the set-up; no candidate left (none whose
           projection the footprint reaches and whose plane test passes) answers "lit"
           without the set-up */
        const double a0 = fabs(L[0]), a1 = fabs(L[1]), a2 = fabs(L[2]);
        const double a01 = a0 > a1 ? a0 : a1, tiny = 1e-150 * (a01 > a2 ? a01 : a2);
        memcpy(r.o, o, sizeof r.o);
        r.d[0] = a0 < tiny ? 0.0 : L[0];
        r.d[1] = a1 < tiny ? 0.0 : L[1];
        r.d[2] = a2 < tiny ? 0.0 : L[2];
        r.tmin = t0;
        r.tmax = t1;
        f = rt_lbuf_query_at(sc, lb, &r, (uint32_t)from, &q, &k0); /* rt_lbuf.h, inline */
    }
    if (f == 0 || (f > 0 && k0 == q.n)) {
        T = 1.0;
        w->st.shadow_lbuf++;
    } else if (!(f == -2 ? rt_rayx_setup(&r, o, L, t0, t1) : rt_rayx_setup_made(&r))) {
        T = 1.0; /* (f != -2: the query made r's o, d and range as rt_rayx_setup would) */
    } else {
        r.skip = (uint32_t)from;
        int k = RT_SCACHE;
        if (cache->live)
            for (k = 0; k < RT_SCACHE; k++) {
                double tb; /* rt_hits_prim's test, inline (cached ids are valid) */
                if (cache->id[k] >= 0 && cache->id[k] != from &&
                    rt_isect_prim(sc, &r, (size_t)cache->id[k], r.tmin, r.tmax, &tb))
                    break;
            }
        if (k < RT_SCACHE) {
            T = 0.0; /* same answer as the traversal: an opaque primitive blocks */
            rt_scache_front(cache, k, cache->id[k]);
        } else {
            /* the light buffer's candidates where it has them, else the walk */
            if (f == -2) {
                f = lb->ok ? rt_lbuf_query(sc, lb, &r, (uint32_t)from, &q, &k0) : -1;
            }
            w->st.shadow_lbuf += f >= 0;
            w->st.shadow_walks += f < 0;
            long blocker = -1;
            if (f < 0) {
                T = rt_trace_transmit(sc, &w->ctx, &r, 0);
                blocker = w->ctx.blocker;
            } else if (f > 0) {
                T = rt_lbuf_transmit(sc, lb, &q, &r, k0, &blocker);
            } else {
                T = 1.0;
            }
            cache->live = T == 0.0;
            if (T == 0.0 && blocker >= 0)
                rt_scache_front(cache, RT_SCACHE, blocker);
        }
    }
    return T;
}

/* P the hit point, N the shading normal (facing the ray); shadow rays start at Ps + eps Ng
   (Ng the geometric normal facing the ray; Ps = P except for smooth areas). What does not
   depend on the light (the shadow rays' origin, the diffuse colour times kd, the surface's
   fields) is taken once per hit. */
static void rt_shade_lights(rt_worker *w, const rt_surface *s, const double Od[3], const double P[3],
                            const double N[3], const double Ps[3], const double Ng[3],
                            const double d[3], double eps, int depth, long from, double out[3])
{
    const rt_job *job = w->job;
    const rt_scene *sc = job->sc;
    const int nl = sc->nlights, direct = s->refl_eq >= RT_REFL_DIFFUSE;
    const int spec_on = s->refl_eq == RT_REFL_SPECULAR && s->ks > 0.0;
    const int clip = job->o.clip_secondary;
    const uint64_t mask = s->light_mask;
    double o[3], kdO[3]; /* the shadow rays' origin; kd Od */
    for (int c = 0; c < 3; c++) {
        o[c] = Ps[c] + eps * Ng[c];
        kdO[c] = s->kd * Od[c];
    }
    rt_scache *cache = &w->shadow_cache[(size_t)depth * (size_t)nl];
    for (int li = 0; li < nl; li++) {
        if (!(mask >> li & 1u))
            continue;
        const rt_light *l = &sc->light[li];
        if (l->type == RT_LIGHT_AMBIENT) {
            for (int c = 0; c < 3; c++)
                out[c] += s->ka * Od[c] * l->color[c];
            continue;
        }
        if (!direct)
            continue;
        rt_light_term lt; /* rt_shade.h, shared with the classic modes */
        if (!rt_light_term_at(l, P, N, &lt))
            continue;
        const double *L = lt.L;
        const double dist = lt.dist;
        /* shadow ray */
        double t0 = 0.0, t1 = l->type == RT_LIGHT_DIRECTIONAL ? INFINITY : dist * (1.0 - 1e-12) - eps;
        w->st.shadow_rays++;
        double T = 0.0;
        if (clip && !rt_clip_volume(job->cam, o, L, &t0, &t1)) {
            T = 1.0;
        } else if (t1 <= t0) {
            T = 1.0;
        } else {
            T = rt_shadow_T(w, &cache[li], &job->lbuf[li], from, o, L, t0, t1);
        }
        if (T == 0.0)
            continue;
        /* attenuation and spot factor only for light that arrives */
        double f = T * rt_light_att(l, &lt) * rt_light_spot(l, &lt);
        double spec = 0.0;
        if (spec_on) {
            const double E[3] = {-d[0], -d[1], -d[2]};
            spec = rt_spec_term(N, &lt, E, s->ks, s->spec_exp);
        }
        for (int c = 0; c < 3; c++)
            out[c] += f * l->color[c] * (kdO[c] * lt.NL + spec * s->specular[c]);
    }
}

/* the margin by which adapted directions stay off the geometric plane: 1/100 of the
   viewer's cosine (the direction mirrored in the plane itself has the full cosine) */
static double rt_bend_margin(double cos_g)
{
    return 0.01 * cos_g;
}

/* refracted direction T kept below the plane of N (facing the viewer, cosine cos_g) */
static void rt_keep_below(double T[3], const double N[3], double cos_g)
{
    const double lo = rt_bend_margin(cos_g), q = -dot3(T, N);
    if (q >= lo)
        return;
    for (int c = 0; c < 3; c++)
        T[c] -= (lo - q) * N[c];
    double l = sqrt(dot3(T, T));
    for (int c = 0; c < 3; c++)
        T[c] /= l;
}

/* The shading normal of a smooth area's hit (docs/RAYTRACING.md, "Smooth areas"): Ns, the
   interpolated front normal, turned with the side hit; ROBUST: adapted so that the viewer's
   mirror direction R stays above the plane of N (the geometric normal facing the ray) by
   rt_bend_margin: R is lifted to that elevation and Ns becomes the half vector of the viewer
   and R (Keller et al. 2017); Ps, Hanika's shadow point, where it lies above the plane. NAIVE:
   Ns only turned, Ps = P. */
static void rt_smooth_normal(int mode, int side, const double P[3], const double N[3],
                             const double d[3], double Ns[3], double Ps[3])
{
    if (side)
        for (int c = 0; c < 3; c++)
            Ns[c] = -Ns[c];
    if (mode != RT_SMOOTH_ROBUST) {
        memcpy(Ps, P, 3 * sizeof *Ps);
        return;
    }
    double up = 0.0;
    for (int c = 0; c < 3; c++)
        up += (Ps[c] - P[c]) * N[c];
    if (!(up > 0.0))
        memcpy(Ps, P, 3 * sizeof *Ps);
    const double cos_g = -dot3(N, d), cv = -dot3(Ns, d);
    const double lo = rt_bend_margin(cos_g);
    double R[3];
    for (int c = 0; c < 3; c++)
        R[c] = d[c] + 2.0 * cv * Ns[c];
    const double q = dot3(R, N);
    if (q >= lo)
        return;
    for (int c = 0; c < 3; c++)
        R[c] += (lo - q) * N[c];
    double l = sqrt(dot3(R, R));
    double H[3];
    for (int c = 0; c < 3; c++)
        H[c] = R[c] / l - d[c];
    l = sqrt(dot3(H, H));
    if (!(l > 0.0) || !isfinite(l)) {
        memcpy(Ns, N, 3 * sizeof *Ns);
        return;
    }
    for (int c = 0; c < 3; c++)
        Ns[c] = H[c] / l;
}

/* a transmitting surface (kt > 0) hit from side (1: back) with cos_i = -Nsh.d: the Fresnel
   reflectance *F and, unless total internal reflection, the refracted direction T; returns 1
   when a refraction ray goes on (*straight: index 1, on the same line) */
static int rt_refract(const rt_job *job, const rt_surface *s, int side, int smooth, double cos_i,
                      const double d[3], const double Nsh[3], const double N[3], double T[3],
                      double *F, int *straight)
{
    double n1 = side ? s->refr_index : 1.0, n2 = side ? 1.0 : s->refr_index;
    if (n1 == n2) {
        *F = 0.0;
        memcpy(T, d, 3 * sizeof *T);
        *straight = cos_i > 1e-3;
        return 1;
    }
    double eta = n1 / n2;
    double sin2t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2t >= 1.0) {
        *F = 1.0; /* total internal reflection */
        return 0;
    }
    double cos_t = sqrt(1.0 - sin2t);
    *F = rt_fresnel(job->o.fresnel, cos_i, cos_t, n1, n2);
    for (int c = 0; c < 3; c++)
        T[c] = eta * d[c] + (eta * cos_i - cos_t) * Nsh[c];
    double l = sqrt(dot3(T, T));
    for (int c = 0; c < 3; c++)
        T[c] /= l;
    if (smooth && job->o.smooth == RT_SMOOTH_ROBUST)
        rt_keep_below(T, N, -dot3(N, d));
    return 1;
}

/* the reflection and refraction rays of a hit at P (below the depth limit), their colours
   added to out with their weights: reflected ks*Cs + kt*F, refracted kt*(1 - F) */
static void rt_secondary(rt_worker *w, const rt_surface *s, const double P[3], const double N[3],
                         const double Nsh[3], const double d[3], int side, int smooth, double eps,
                         int depth, double weight, long i, double out[3])
{
    const rt_job *job = w->job;
    double wr[3] = {0, 0, 0}, wt = 0.0;
    if (s->refl_eq == RT_REFL_SPECULAR)
        for (int c = 0; c < 3; c++)
            wr[c] = s->ks * s->specular[c];
    double cos_i = -dot3(Nsh, d);
    if (cos_i > 1.0)
        cos_i = 1.0;
    double T[3] = {0, 0, 0};
    int straight = 0;
    if (s->transparency > 0.0) {
        double F;
        const int refract = rt_refract(job, s, side, smooth, cos_i, d, Nsh, N, T, &F, &straight);
        for (int c = 0; c < 3; c++)
            wr[c] += s->transparency * F;
        wt = refract ? s->transparency * (1.0 - F) : 0.0;
    }
    double wrm = rt_fmax2(wr[0], rt_fmax2(wr[1], wr[2]));
    if (wrm > 0.0 && !(job->o.cutoff > 0.0 && weight * wrm < job->o.cutoff)) {
        double R[3], col[3];
        for (int c = 0; c < 3; c++)
            R[c] = d[c] + 2.0 * cos_i * Nsh[c];
        double l = sqrt(dot3(R, R));
        for (int c = 0; c < 3; c++)
            R[c] /= l;
        /* an eye ray's reflection off a flat mirror: the mirror's candidates */
        const rt_mirror *mir = job->mir_of && depth == 1 && !smooth && job->mir_of[i]
                                   ? &job->mir[job->mir_of[i] - 1] : NULL;
        if (mir)
            rt_spawn_mirror(w, mir, P, N, eps, R, weight * wrm, i, col);
        else
            rt_spawn(w, P, N, eps, R, depth + 1, weight * wrm, 0, i, col);
        for (int c = 0; c < 3; c++)
            out[c] += wr[c] * col[c];
    }
    if (wt > 0.0 && !(job->o.cutoff > 0.0 && weight * wt < job->o.cutoff)) {
        double col[3];
        if (straight) /* index 1: continue on the same line, just past the surface */
            rt_spawn(w, P, d, eps / cos_i, T, depth + 1, weight * wt, 1, i, col);
        else
            rt_spawn(w, P, N, -eps, T, depth + 1, weight * wt, 1, i, col);
        for (int c = 0; c < 3; c++)
            out[c] += wt * col[c];
    }
}

/* the colour of the ray (o, d) whose nearest hit is internal primitive i (< 0: none) at t
   (rt_trace, and the eye rays traced in packets) */
static void rt_shade_hit(rt_worker *w, const double o[3], const double d[3], int depth,
                         double weight, long i, double t, double out[3])
{
    const rt_job *job = w->job;
    const rt_scene *sc = job->sc;
    for (int c = 0; c < 3; c++)
        out[c] = job->o.background[c];
    if (depth == 1) {
        w->st.eye_hits += i >= 0;
        w->eye_hit = i >= 0;
    }
    if (i < 0)
        return;
    const rt_prim *p = rt_prim_rec(sc, (size_t)i); /* (a cell's data: its own record) */
    double P[3], N[3];
    for (int c = 0; c < 3; c++)
        P[c] = o[c] + t * d[c];
    double ng[3];
    rt_prim_ng(sc, (size_t)i, ng);
    double dn = dot3(ng, d);
    int side = dn > 0.0;
    for (int c = 0; c < 3; c++)
        N[c] = side ? -ng[c] : ng[c];
    const rt_surface *s = rt_prim_surf(sc, p, side);
    double Od[3];
    if (p->kind == RT_KIND_CELL)
        rt_cell_color(sc, &sc->cell[p->data], P, Od);
    else
        memcpy(Od, s->diffuse, sizeof Od);
    /* smooth areas: the shading normal Ns and the shadow rays' start Ps (rt_smooth.c) */
    double Ns[3], Ps[3], Oi[3];
    const int sm = sc->prim_vd || sc->ntri > sc->ntri_plain /* meshes */
                       ? rt_smooth_at(sc, (size_t)i, P, ng, Ns, Ps, Oi) : 0;
    const int smooth = (sm & 1) && job->o.smooth != RT_SMOOTH_FLAT;
    if (sm & 2)
        memcpy(Od, Oi, sizeof Od);
    if (smooth)
        rt_smooth_normal(job->o.smooth, side, P, N, d, Ns, Ps);
    const double *Nsh = smooth ? Ns : N, *Psh = smooth ? Ps : P;
    double eps = rt_eps(job, P, t);
    if (s->refl_eq == RT_REFL_NONE) {
        memcpy(out, Od, sizeof Od);
    } else {
        out[0] = out[1] = out[2] = 0.0;
        rt_shade_lights(w, s, Od, P, Nsh, Psh, N, d, eps, depth, i, out);
    }
    if (depth >= job->o.max_depth)
        return;
    rt_secondary(w, s, P, N, Nsh, d, side, smooth, eps, depth, weight, i, out);
}

/* The nearest hit among an eye ray's candidates: rt_trace_list's tests and choice
   (rt_nearest_update) in the list's order, which ascends in key, a lower bound of any hit's
   t (rt_cover_keys). rt_trace_list tests a candidate only up to best + 2 eb (beyond it a hit
   can neither win nor tie); once a key exceeds that, no later candidate can hit below it,
   nor can best + 2 eb grow again (only an update could raise it, and an update needs such a
   hit): the rest of the list is left out with the same answer. */
static long rt_trace_cands(const rt_scene *sc, const rt_rayx *r, const rt_cands *c,
                           double *tout)
{
    double best = INFINITY, eb = 0.0;
    long bi = -1;
    for (size_t k = 0; k < c->n; k++) {
        const uint32_t i = c->ids[k];
        const double lim = best + 2.0 * eb;
        if (c->key[i] > lim)
            break;
        double t;
        if (i != r->skip && rt_isect_prim(sc, r, i, r->tmin, lim < r->tmax ? lim : r->tmax, &t))
            rt_nearest_update(sc, r, i, t, &best, &bi, &eb);
    }
    *tout = best;
    return bi;
}

/* The nearest hit of ray r, a reflection of an eye ray off a member of mirror m, among m's
   candidates: the list of the buffer's cell where r's footprint lies (else, -1, the grid
   walk). The buffer is a light buffer (rt_lbuf.c) built from E', the mirror image of the
   eye: the ray's line passes (within dev) through E', so its points at the depths of the
   primitives project into the footprint, and the list is a superset of what it can hit (the
   primitives left out of the buffer lie on the mirror's plane or behind it, where the ray,
   eps above the plane and leaving it, never comes: see rt_job_mirrors). As rt_trace_cands,
   in the list's order, which ascends in the depth bucket b of each primitive's nearest
   vertex less zeps (depth: along ez from E'): the ray, of unit direction, gains at most its
   t in depth, so it reaches no point of such a primitive before t = zlo + b zstep - z (z its
   origin's depth), less zeps more for the rounding of z and of the hit's t (about 1e-15 of
   the coordinates, zeps 1e-7 of the depths); once that passes best + 2 eb, no later
   candidate can hit below it, and the rest of the list is left out with the same answer. */
static long rt_mirror_nearest(rt_worker *w, const rt_mirror *m, const rt_rayx *r, double *tout)
{
    const rt_scene *sc = w->job->sc;
    const uint32_t *ids = NULL;
    uint32_t n = 0;
    double z;
    const int f = rt_lbuf_find_z(&m->lb, r, &ids, &n, &z);
    if (f < 0)
        return rt_trace_nearest(sc, &w->ctx, r, tout);
    w->st.reflection_mirror++;
    double best = INFINITY, eb = 0.0;
    long bi = -1;
    const double k0 = m->k0 - z, zstep = m->zstep;
    const uint16_t *zb = m->lb.zb;
    for (uint32_t k = 0; k < n; k++) {
        const uint32_t i = ids[k];
        const double lim = best + 2.0 * eb;
        if (k0 + (double)zb[i] * zstep > lim)
            break;
        double t;
        if (i != r->skip && rt_isect_prim(sc, r, i, r->tmin, lim < r->tmax ? lim : r->tmax, &t))
            rt_nearest_update(sc, r, i, t, &best, &bi, &eb);
    }
    *tout = best;
    return bi;
}

/* rt_trace of a reflection ray (o, d) from primitive from, a member of mirror m, with
   rt_mirror_nearest instead of the walk */
static void rt_trace_mirror(rt_worker *w, const rt_mirror *m, const double o[3],
                            const double d[3], int depth, double weight, long from, double out[3])
{
    const rt_job *job = w->job;
    double tmin = 0.0, tmax = INFINITY;
    for (int c = 0; c < 3; c++)
        out[c] = job->o.background[c];
    if (job->o.clip_secondary && !rt_clip_volume(job->cam, o, d, &tmin, &tmax))
        return;
    rt_rayx r;
    if (!rt_rayx_setup(&r, o, d, tmin, tmax))
        return;
    r.skip = (uint32_t)from;
    double t;
    const long i = rt_mirror_nearest(w, m, &r, &t);
    rt_shade_hit(w, o, d, depth, weight, i, t, out);
}

/* from: the primitive a secondary ray leaves (never hit by it, rt_rayx.skip), -1 for eye rays;
   cand: an eye ray's candidates (tested instead of walking the grid), or NULL */
static void rt_trace(rt_worker *w, const double o[3], const double d[3], double tmin, double tmax,
                     int depth, double weight, int secondary, long from, const rt_cands *cand,
                     double out[3])
{
    const rt_job *job = w->job;
    const rt_scene *sc = job->sc;
    for (int c = 0; c < 3; c++)
        out[c] = job->o.background[c];
    if (secondary && job->o.clip_secondary && !rt_clip_volume(job->cam, o, d, &tmin, &tmax))
        return;
    rt_rayx r;
    if (!rt_rayx_setup(&r, o, d, tmin, tmax))
        return;
    if (from >= 0)
        r.skip = (uint32_t)from;
    double t;
    long i = !cand ? rt_trace_nearest(sc, &w->ctx, &r, &t)
             : cand->key ? rt_trace_cands(sc, &r, cand, &t)
                         : rt_trace_list(sc, &r, cand->ids, cand->n, &t);
    rt_shade_hit(w, o, d, depth, weight, i, t, out);
}

/* The picture is usually fresh from malloc (mmap): its first touch takes one page fault per
   4 KiB, ~10 us each in the virtual machine measured (512x512 RGB floats: 9 ms, more than
   tracing half of tetra). Populating the pages in one call costs a third of that. Part k of n
   of the pages (each tracing thread its share); contents are unchanged; whole pages inside the
   buffer only; errors (older kernels) ignored. */
static void rt_prefault(void *p, size_t bytes, int k, int n)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    long ps = sysconf(_SC_PAGESIZE);
    if (ps <= 0 || (ps & (ps - 1)) != 0)
        return;
    uintptr_t pg = (uintptr_t)ps;
    uintptr_t a = ((uintptr_t)p + pg - 1) & ~(pg - 1), e = ((uintptr_t)p + bytes) & ~(pg - 1);
    if (e <= a || e - a < 16 * pg)
        return;
    size_t lo, hi; /* part k's pages */
    rt_par_range((e - a) / pg, k, n, &lo, &hi);
    if (hi > lo)
        (void)madvise((void *)(a + lo * pg), (hi - lo) * pg, MADV_POPULATE_WRITE);
#else
    (void)p;
    (void)bytes;
    (void)k;
    (void)n;
#endif
}

static uint64_t rt_mix(uint64_t x)
{
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

static void rt_eye(rt_worker *w, double px, double py, double out[3])
{
    const rt_job *job = w->job;
    rt_ray ray;
    w->st.eye_rays++;
    w->eye_hit = 0;
    if (rt_camera_ray(job->cam, px, py, &ray) != RT_OK) {
        for (int c = 0; c < 3; c++)
            out[c] = job->o.background[c];
        return;
    }
    rt_trace(w, ray.org, ray.dir, ray.tmin, ray.tmax, 1, 1.0, 0, -1, NULL, out);
}

/* Eye ray culling for scenes lying in front of the eye plane: the ray through raster point
   (px, py) can only hit a primitive whose projection contains (px, py). A straight edge
   projects to a straight edge, so a triangle, convex quad or cell array projects to the
   convex polygon of its projected vertices; a general polygon is bounded by the box of its
   vertices. Each is taken enlarged by RT_COVER_MARGIN raster units (rays and projections err
   by ~1e-12 of the raster; the inversion is checked to 1/100 below), and every ray point
   inside gets the primitive in its candidate list (or is marked, rt_cover): rays without one
   are background, the others test their candidates only. Built once per frame, row intervals
   per primitive: O(vertices + rays covered). None (no culling) if a vertex is not in front of
   the eye plane, if there are more vertices than rays (the projections would cost more than
   they can save), or without memory. */
#define RT_COVER_MARGIN 0.25

/* where the rays a primitive's projection reaches go: a mask (mark), per-ray counts (count)
   or the primitive's index into each ray's candidate list (fill: next[k] is the slot after
   ray k's next free one, lists are filled from the back) */
enum { RT_COVER_MARK, RT_COVER_COUNT, RT_COVER_FILL };

typedef struct rt_cover_sink {
    int pass;
    uint8_t *mask;
    uint32_t *next;
    uint32_t *ids;
    uint32_t prim;
} rt_cover_sink;

/* the rays (x + off, y + off) of row y in [lo, hi] (raster units, clamped) */
static void rt_cover_span(rt_cover_sink *s, int gw, double off, int y, double lo, double hi)
{
    double a = ceil(lo - off), b = floor(hi - off);
    if (!(a <= b) || b < 0.0 || a > gw - 1)
        return;
    int x0 = a < 0.0 ? 0 : (int)a, x1 = b > gw - 1 ? gw - 1 : (int)b;
    const size_t k0 = (size_t)y * (size_t)gw + (size_t)x0, n = (size_t)(x1 - x0 + 1);
    if (s->pass == RT_COVER_MARK)
        memset(s->mask + k0, 1, n);
    else if (s->pass == RT_COVER_COUNT)
        for (size_t k = k0; k < k0 + n; k++)
            s->next[k]++;
    else
        for (size_t k = k0; k < k0 + n; k++)
            s->ids[--s->next[k]] = s->prim;
}

/* the rays inside the convex polygon q[0..n-1] (either orientation) enlarged by m: per row
   the interval where every edge's half-plane, moved out by m, holds (that intersection
   contains the m-neighbourhood of the polygon); a polygon of almost no area: its box. */
static void rt_cover_convex(rt_cover_sink *s, int gw, int gh, double off, const double (*q)[2],
                            int n, const double bb[4], double m)
{
    double area = 0.0, l2 = 0.0;
    for (int i = 0; i < n; i++) {
        const double *p0 = q[i], *p1 = q[(i + 1) % n];
        area += p0[0] * p1[1] - p1[0] * p0[1];
        l2 += (p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]);
    }
    const int box = !(fabs(area) > 1e-9 * l2);
    const double sg = area > 0.0 ? 1.0 : -1.0;
    /* edge i: sg * ((p1 - p0) x (p - p0)) >= -m |p1 - p0|, i.e. cx * px + a + b * py >= 0:
       per row a lower (cx > 0) or upper (cx < 0) bound on px, or all or nothing (cx == 0) */
    double ka[4], kb[4];
    int kind[4];
    for (int i = 0; i < n && !box; i++) {
        const double *p0 = q[i], *p1 = q[(i + 1) % n];
        const double ex = p1[0] - p0[0], ey = p1[1] - p0[1];
        const double cx = -sg * ey;
        const double a = sg * (ey * p0[0] - ex * p0[1]) + m * sqrt(ex * ex + ey * ey), b = sg * ex;
        kind[i] = cx > 0.0 ? 1 : (cx < 0.0 ? -1 : 0);
        ka[i] = kind[i] ? -a / cx : a;
        kb[i] = kind[i] ? -b / cx : b;
    }
    double y0 = ceil(bb[2] - m - off), y1 = floor(bb[3] + m - off);
    if (y0 < 0.0)
        y0 = 0.0;
    if (y1 > gh - 1)
        y1 = gh - 1;
    for (int y = (int)y0; y <= (int)y1 && y0 <= y1; y++) {
        const double py = y + off;
        double lo = bb[0] - m, hi = bb[1] + m;
        for (int i = 0; i < n && !box; i++) {
            const double v = ka[i] + kb[i] * py;
            if (kind[i] > 0)
                lo = rt_fmax_q(lo, v);
            else if (kind[i] < 0)
                hi = rt_fmin_q(hi, v);
            else if (v < 0.0)
                hi = -INFINITY;
        }
        rt_cover_span(s, gw, off, y, lo, hi);
    }
}

/* The culling of one-ray modes (rt_job.cover, rt_job.cand_off/cand), or nothing (the view
   mapping does not invert the rays well, a vertex is not in front of the eye plane, more
   vertices than rays, or no memory). */
typedef struct rt_cover_out {
    uint8_t *mask;
    uint32_t *off, *ids;
    double *key; /* with off and ids: rt_cover_keys' bounds (the lists in their order) */
} rt_cover_out;

/* Rays per frame up to which eye rays get candidate lists (4 bytes per ray), and at most
   RT_CAND_PER_RAY list entries per ray on average (else the mask alone). */
#define RT_CAND_RAYS (1u << 22)
#define RT_CAND_PER_RAY 16

/* one pass of primitives lo .. hi-1's projections into sink s; 0 if a vertex does not project */
static int rt_cover_pass(const rt_scene *sc, const rt_camera *cam, const double vm[4][4],
                         double ws, double off, int gw, int gh, rt_cover_sink *s, size_t lo,
                         size_t hi, const uint32_t *perm)
{
    for (size_t j = lo; j < hi; j++) {
        /* the fill pass goes backwards: each list ends up in the order of perm (NULL:
           ascending primitive order) */
        const size_t pj = s->pass == RT_COVER_FILL ? hi - 1 - (j - lo) : j;
        const size_t i = perm ? perm[pj] : pj;
        double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY}, q[4][2], x[3];
        const size_t nv = rt_prim_nverts(sc, i);
        for (size_t k = 0; k < nv; k++) {
            double pu, pv; /* finite */
            rt_prim_vertex(sc, i, k, x);
            if (!rt_camera_project(cam, vm, ws, x, &pu, &pv))
                return 0;
            if (k < 4) {
                q[k][0] = pu;
                q[k][1] = pv;
            }
            bb[0] = rt_fmin_q(bb[0], pu);
            bb[1] = rt_fmax_q(bb[1], pu);
            bb[2] = rt_fmin_q(bb[2], pv);
            bb[3] = rt_fmax_q(bb[3], pv);
        }
        const int kind = rt_prim_geo(sc, i).kind;
        const int convex = kind == RT_KIND_TRI || kind == RT_KIND_QUAD || kind == RT_KIND_CELL;
        s->prim = (uint32_t)i;
        rt_cover_convex(s, gw, gh, off, (const double(*)[2])q, convex ? (int)nv : 0, bb,
                        RT_COVER_MARGIN);
    }
    return 1;
}

/* The candidate lists' passes on the pool: part k of the count and fill passes takes the
   primitives of rt_par_range (k, n) with per-ray counters of its own (cnt[k]; cnt[0] becomes
   the lists' offsets). Between them the counters become each part's list ends: in every
   ray's list part k's entries follow those of the parts before it, so the lists are those of
   one pass over all primitives in order. The ends are set in n ranges of rays: the ranges'
   totals (tot), then their running sums, then the ends. */
typedef struct rt_cover_job {
    const rt_scene *sc;
    const rt_camera *cam;
    const double (*vm)[4];
    double ws, off;
    int gw, gh, pass, nt;
    size_t nrays;
    uint32_t *cnt[RT_PAR_MAX];
    uint32_t *ids;
    const uint32_t *perm; /* the primitives in the lists' order (NULL: ascending) */
    uint64_t tot[RT_PAR_MAX];
    int ok[RT_PAR_MAX];
} rt_cover_job;

static void rt_cover_part(void *arg, int k, int n)
{
    rt_cover_job *j = arg;
    size_t lo, hi;
    rt_par_range(j->sc->nprim, k, n, &lo, &hi);
    rt_cover_sink s = {j->pass, NULL, j->cnt[k], j->ids, 0};
    j->ok[k] = rt_cover_pass(j->sc, j->cam, j->vm, j->ws, j->off, j->gw, j->gh, &s, lo, hi, j->perm);
}

static void rt_cover_total_part(void *arg, int k, int n)
{
    rt_cover_job *j = arg;
    size_t lo, hi;
    rt_par_range(j->nrays, k, n, &lo, &hi);
    uint64_t t = 0;
    for (int p = 0; p < j->nt; p++)
        for (size_t r = lo; r < hi; r++)
            t += j->cnt[p][r];
    j->tot[k] = t;
}

/* after the running sums: tot[k] = entries of the rays before range k */
static void rt_cover_ends_part(void *arg, int k, int n)
{
    rt_cover_job *j = arg;
    size_t lo, hi;
    rt_par_range(j->nrays, k, n, &lo, &hi);
    uint64_t total = j->tot[k];
    for (size_t r = lo; r < hi; r++) {
        for (int p = 0; p < j->nt; p++)
            total += j->cnt[p][r];
        uint64_t e = total; /* part p's end: the list's end less the later parts' entries */
        for (int p = j->nt - 1; p >= 0; p--) {
            const uint32_t c = j->cnt[p][r];
            j->cnt[p][r] = (uint32_t)(e <= UINT32_MAX ? e : 0);
            e -= c;
        }
    }
}

/* Primitives per part of the candidate lists' passes at least: each part beyond the first
   costs a counter per ray. */
#define RT_COVER_PART_PRIMS 1024

/* Can the camera's rays be culled by projection? The ends of the rays through the raster's
   corners and centre must come back to their raster points within 1/100 of a raster unit
   (else a badly conditioned view mapping: no culling), and the primitives' vertices must not
   outnumber the rays (budget). */
static int rt_cover_usable(const rt_scene *sc, const rt_camera *cam, const double vm[4][4], double ws,
                           size_t budget)
{
    for (int k = 0; k < 5; k++) {
        double px = k == 4 ? 0.5 * cam->width : (k & 1) * cam->width;
        double py = k == 4 ? 0.5 * cam->height : (k >> 1) * cam->height;
        rt_ray r;
        if (rt_camera_ray(cam, px, py, &r) != RT_OK)
            return 0;
        for (int e = 0; e < 2; e++) {
            double q[3], u, v;
            for (int i = 0; i < 3; i++)
                q[i] = r.org[i] + (e ? r.tmax : 0.0) * r.dir[i];
            if (!rt_camera_project(cam, vm, ws, q, &u, &v) || !(fabs(u - px) <= 0.01) ||
                !(fabs(v - py) <= 0.01))
                return 0;
        }
    }
    for (size_t i = 0, nv = 0; i < sc->nprim; i++) {
        nv += rt_prim_nverts(sc, i);
        if (nv > budget)
            return 0;
    }
    return 1;
}

/* the passes of the candidate lists over j (its count arrays made): counts, their running
   sums (list ends), then the lists filled from the back, which leaves each ray's offset at
   its list's start. 1: lists made (j->ids, j->cnt[0]); 0: too many entries or no memory
   (the mask alone will do); -1: a pass failed */
static int rt_cover_lists_run(rt_cover_job *j, size_t budget)
{
    int ok = 1;
    j->pass = RT_COVER_COUNT;
    rt_par_run(j->nt, rt_cover_part, j);
    for (int p = 0; p < j->nt; p++)
        ok = ok && j->ok[p];
    if (!ok)
        return -1;
    rt_par_run(j->nt, rt_cover_total_part, j);
    uint64_t total = 0;
    for (int p = 0; p < j->nt; p++) {
        const uint64_t t = j->tot[p];
        j->tot[p] = total;
        total += t;
    }
    if (total > (uint64_t)RT_CAND_PER_RAY * budget)
        return 0;
    rt_par_run(j->nt, rt_cover_ends_part, j);
    j->cnt[0][budget] = (uint32_t)total;
    j->ids = rt_alloc_array(total ? (size_t)total : 1, sizeof(uint32_t));
    int filled = j->ids != NULL;
    if (filled) {
        j->pass = RT_COVER_FILL;
        rt_par_run(j->nt, rt_cover_part, j);
        for (int p = 0; p < j->nt; p++)
            filled = filled && j->ok[p];
    }
    if (filled)
        return 1;
    free(j->ids);
    return 0;
}

/* the candidate lists of the budget rays (out->off, out->ids): 1 made, 0 not (the mask alone
   will do), -1 no culling at all */
static int rt_cover_lists(const rt_scene *sc, const rt_camera *cam, const double vm[4][4], double ws,
                          double off, int gw, int gh, int threads, size_t budget,
                          const uint32_t *perm, rt_cover_out *out)
{
    rt_cover_job *j = rt_calloc_array(1, sizeof *j);
    if (!j)
        return -1;
    int nt = threads < 1 ? 1 : threads;
    if ((size_t)nt > sc->nprim / RT_COVER_PART_PRIMS + 1)
        nt = (int)(sc->nprim / RT_COVER_PART_PRIMS + 1);
    j->sc = sc;
    j->cam = cam;
    j->vm = vm;
    j->ws = ws;
    j->off = off;
    j->gw = gw;
    j->gh = gh;
    j->nrays = budget;
    j->perm = perm;
    while (j->nt < nt && (j->cnt[j->nt] = rt_calloc_array(budget + 1, sizeof(uint32_t))))
        j->nt++; /* fewer parts where memory runs short */
    const int r = j->nt > 0 ? rt_cover_lists_run(j, budget) : -1;
    if (r == 1) {
        out->off = j->cnt[0];
        out->ids = j->ids;
        for (int p = 1; p < j->nt; p++)
            free(j->cnt[p]);
        free(j);
        return 1;
    }
    for (int p = 0; p < j->nt; p++)
        free(j->cnt[p]);
    free(j);
    return r;
}

typedef struct rt_keyed {
    double key;
    uint32_t i;
} rt_keyed;

/* ascending key, ties by ascending index (keys are never NaN) */
static int rt_keyed_cmp(const void *pa, const void *pb)
{
    const rt_keyed *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return a->i < b->i ? -1 : (a->i > b->i);
}

/* Eye rays start on one plane (the front plane of the display volume, mapped to VRC3) and
 * have unit directions. With nu its unit normal (pointing along the rays) and c = nu . o for
 * its points o, a ray from o reaches a point x at t = |x - o| >= (x - o) . nu = x . nu - c;
 * every point of a primitive lies in the hull of its vertices, so no eye ray meets primitive
 * i before key[i] = min over its vertices v of v . nu - c, less a margin (1e-7 of the
 * coordinates' magnitude, against the rounding of the rays and of the hit tests: the
 * traversal's own premise, that a hit's t lies within the build's far smaller eps of the
 * primitive, see rt_build.c). *perm: the primitives in ascending key (ties: ascending
 * index). 1 on success; 0 (no keys, no error) when the ray origins do not lie on one plane
 * to 1e-9 of their magnitude or memory runs short. */
static int rt_cover_keys(const rt_scene *sc, const rt_camera *cam, double **key, uint32_t **perm)
{
    *key = NULL;
    *perm = NULL;
    rt_ray r[5];
    for (int k = 0; k < 5; k++) {
        const double px = k == 4 ? 0.5 * cam->width : (k & 1) * cam->width;
        const double py = k == 4 ? 0.5 * cam->height : (k >> 1) * cam->height;
        if (rt_camera_ray(cam, px, py, &r[k]) != RT_OK)
            return 0;
    }
    double a[3], b[3], nu[3];
    for (int c = 0; c < 3; c++) {
        a[c] = r[1].org[c] - r[0].org[c];
        b[c] = r[2].org[c] - r[0].org[c];
    }
    nu[0] = a[1] * b[2] - a[2] * b[1];
    nu[1] = a[2] * b[0] - a[0] * b[2];
    nu[2] = a[0] * b[1] - a[1] * b[0];
    const double ln = sqrt(dot3(nu, nu));
    if (!(ln > 0.0) || !isfinite(ln))
        return 0;
    const double sg = dot3(nu, r[4].dir) < 0.0 ? -1.0 : 1.0;
    for (int c = 0; c < 3; c++)
        nu[c] *= sg / ln;
    /* R: the magnitude of the coordinates involved */
    double R = 0.0;
    for (int c = 0; c < 6; c++)
        R = fmax(R, fabs(sc->bbox[c]));
    for (int k = 0; k < 5; k++)
        R = fmax(R, rt_absmax3(r[k].org));
    const double c0 = dot3(nu, r[0].org);
    for (int k = 0; k < 5; k++)
        if (!(fabs(dot3(nu, r[k].org) - c0) <= 1e-9 * R) || !(dot3(nu, r[k].dir) > 0.0))
            return 0; /* not one plane, or a ray running back along it */
    if (!(R > 0.0) || !isfinite(R))
        return 0;
    const double margin = 1e-7 * R;
    double *kk = rt_alloc_array(sc->nprim, sizeof *kk);
    uint32_t *pp = rt_alloc_array(sc->nprim, sizeof *pp);
    rt_keyed *tmp = rt_alloc_array(sc->nprim, sizeof *tmp);
    if (!kk || !pp || !tmp) {
        free(kk);
        free(pp);
        free(tmp);
        return 0;
    }
    for (size_t i = 0; i < sc->nprim; i++) {
        double m = INFINITY, x[3];
        const size_t nv = rt_prim_nverts(sc, i);
        for (size_t k = 0; k < nv; k++) {
            rt_prim_vertex(sc, i, k, x);
            m = fmin(m, dot3(nu, x));
        }
        const double d = m - c0;
        kk[i] = isfinite(d) ? d - margin - 1e-12 * fabs(d) : -INFINITY;
    }
    for (size_t i = 0; i < sc->nprim; i++)
        tmp[i] = (rt_keyed){kk[i], (uint32_t)i};
    qsort(tmp, sc->nprim, sizeof *tmp, rt_keyed_cmp);
    for (size_t i = 0; i < sc->nprim; i++)
        pp[i] = tmp[i].i;
    free(tmp);
    *key = kk;
    *perm = pp;
    return 1;
}

static rt_cover_out rt_cover(const rt_scene *sc, const rt_camera *cam, double off, int gw, int gh,
                             int threads)
{
    rt_cover_out none = {NULL, NULL, NULL, NULL}, out = none;
    if (sc->nprim == 0)
        return none;
    double vm[4][4], ws;
    if (!rt_camera_vmap(cam, vm, &ws))
        return none;
    size_t budget = (size_t)gw * (size_t)gh;
    if (!rt_cover_usable(sc, cam, (const double(*)[4])vm, ws, budget))
        return none;
    if (budget <= RT_CAND_RAYS && sc->nprim <= UINT32_MAX) {
        double *key;
        uint32_t *perm;
        rt_cover_keys(sc, cam, &key, &perm);
        const int r = rt_cover_lists(sc, cam, (const double(*)[4])vm, ws, off, gw, gh, threads,
                                     budget, perm, &out);
        free(perm);
        if (r > 0) {
            out.key = key;
            return out;
        }
        free(key);
        if (r < 0)
            return none;
        /* too many entries or no memory: the mask alone */
    }
    rt_cover_sink s = {RT_COVER_MARK, rt_calloc_array(budget, 1), NULL, NULL, 0};
    if (!s.mask)
        return none;
    if (!rt_cover_pass(sc, cam, vm, ws, off, gw, gh, &s, 0, sc->nprim, NULL)) {
        free(s.mask);
        return none;
    }
    out.mask = s.mask;
    return out;
}

/* where corner ray (x, y) is kept: in the picture itself at pixel (x, y), the last column and
   row of corners in job->edge (see rt_corner_rows) */
static float *rt_corner_at(const rt_job *job, int x, int y)
{
    const int W = job->cam->width, H = job->cam->height;
    if (x < W && y < H)
        return job->rgb + 3 * ((size_t)y * (size_t)W + (size_t)x);
    if (x == W)
        return job->edge + 3 * (size_t)y;
    return job->edge + 3 * ((size_t)H + 1 + (size_t)x);
}

/* eye ray (x, y)'s colour col into the picture (corner rays: where rt_corner_at keeps them)
   and its hit into the cover */
static void rt_eye_store(rt_worker *w, int x, int y, double col[3])
{
    rt_job *job = w->job;
    const size_t row = (size_t)y * (size_t)job->gw;
    float *dst;
    if (job->o.corner_rays) {
        dst = rt_corner_at(job, x, y);
    } else {
        dst = job->rgb + 3 * (row + (size_t)x);
        for (int c = 0; c < 3; c++)
            col[c] += 0.0; /* as the sum over samples below: -0 becomes +0 */
    }
    for (int c = 0; c < 3; c++)
        dst[c] = isfinite(col[c]) ? (float)col[c] : 0.0f;
    if (job->corner_hit)
        job->corner_hit[row + (size_t)x] = (uint8_t)w->eye_hit;
    else if (job->cover_out)
        job->cover_out[row + (size_t)x] = (unsigned short)w->eye_hit;
}

/* the nearest hits of the n rays pk (rt_packet_nearest, or one by one when they do not
   form a packet) into pi, pt */
static void rt_packet_eye(rt_worker *w, int n, const rt_ray *pk, long *pi, double *pt)
{
    const rt_scene *sc = w->job->sc;
    rt_rayx rx[RT_PACKET];
    rt_packet_stats ps = {0};
    if (rt_packet_nearest(sc, &w->ctx, (size_t)n, pk, pi, pt, rx, &ps))
        return;
    for (int j = 0; j < n; j++)
        pi[j] = rt_rayx_setup(&rx[j], pk[j].org, pk[j].dir, pk[j].tmin, pk[j].tmax)
                    ? rt_trace_nearest(sc, &w->ctx, &rx[j], &pt[j])
                    : -1;
}

/* The eye rays of a tile without candidate lists (one per corner or pixel centre, those the
   cover mask does not cull) traced in packets of 8 x 8 (the hits of rt_trace_nearest, bit for
   bit), then shaded in raster order as rt_tile_rows does: the same picture. */
#define RT_PK_SIDE 8
_Static_assert(RT_PK_SIDE * RT_PK_SIDE <= RT_PACKET, "a block is one packet");
static void rt_tile_packets(rt_worker *w, int x0, int x1, int y0, int y1)
{
    rt_job *job = w->job;
    const double off = job->o.corner_rays ? 0.0 : 0.5;
    double xt[RT_TILE][4], yt[4], col[3];
    rt_ray ray[RT_TILE][RT_TILE], pk[RT_PACKET];
    int ok[RT_TILE][RT_TILE];
    long hi[RT_TILE][RT_TILE], pi[RT_PACKET];
    double ht[RT_TILE][RT_TILE], pt[RT_PACKET];
    for (int x = x0; x < x1; x++)
        rt_camera_xterm(job->cam, x + off, xt[x - x0]);
    for (int y = y0; y < y1; y++) {
        rt_camera_yterm(job->cam, y + off, yt);
        rt_camera_rays_row(job->cam, (const double(*)[4])xt, x1 - x0, yt, ray[y - y0], ok[y - y0]);
        const uint8_t *cov = job->cover ? job->cover + (size_t)y * (size_t)job->gw : NULL;
        for (int x = x0; x < x1; x++)
            ok[y - y0][x - x0] &= !cov || cov[x];
    }
    for (int by = 0; by < y1 - y0; by += RT_PK_SIDE)
        for (int bx = 0; bx < x1 - x0; bx += RT_PK_SIDE) {
            int n = 0;
            for (int y = by; y < by + RT_PK_SIDE && y < y1 - y0; y++)
                for (int x = bx; x < bx + RT_PK_SIDE && x < x1 - x0; x++)
                    if (ok[y][x])
                        pk[n++] = ray[y][x];
            if (n)
                rt_packet_eye(w, n, pk, pi, pt);
            n = 0;
            for (int y = by; y < by + RT_PK_SIDE && y < y1 - y0; y++)
                for (int x = bx; x < bx + RT_PK_SIDE && x < x1 - x0; x++)
                    if (ok[y][x]) {
                        hi[y][x] = pi[n];
                        ht[y][x] = pt[n++];
                    }
        }
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            w->st.eye_rays++;
            w->eye_hit = 0;
            const rt_ray *r = &ray[y - y0][x - x0];
            if (ok[y - y0][x - x0])
                rt_shade_hit(w, r->org, r->dir, 1, 1.0, hi[y - y0][x - x0], ht[y - y0][x - x0], col);
            else
                memcpy(col, job->o.background, sizeof col);
            rt_eye_store(w, x, y, col);
        }
}

/* one ray per corner or pixel centre over [x0,x1) x [y0,y1): x terms once per column, y
   terms once per row */
static void rt_tile_rows(rt_worker *w, int x0, int x1, int y0, int y1)
{
    rt_job *job = w->job;
    if (job->packets && !job->cand_off) {
        rt_tile_packets(w, x0, x1, y0, y1);
        return;
    }
    const double off = job->o.corner_rays ? 0.0 : 0.5;
    double xt[RT_TILE][4], xs[RT_TILE][4], yt[4], col[3];
    rt_ray ray[RT_TILE];
    int ok[RT_TILE], slot[RT_TILE];
    for (int x = x0; x < x1; x++)
        rt_camera_xterm(job->cam, x + off, xt[x - x0]);
    for (int y = y0; y < y1; y++) {
        /* the rays of a tile row first (independent, their divisions overlap), only those
           not culled (slot -1: surely background) */
        int n = 0;
        const size_t row = (size_t)y * (size_t)job->gw;
        const uint32_t *co = job->cand_off ? job->cand_off + row : NULL;
        const uint8_t *cov = job->cover ? job->cover + row : NULL;
        for (int x = x0; x < x1; x++) {
            slot[x - x0] = -1;
            if (co ? co[x + 1] != co[x] : !cov || cov[x]) {
                memcpy(xs[n], xt[x - x0], sizeof xs[n]);
                slot[x - x0] = n++;
            }
        }
        rt_camera_yterm(job->cam, y + off, yt);
        rt_camera_rays_row(job->cam, (const double(*)[4])xs, n, yt, ray, ok);
        for (int x = x0; x < x1; x++) {
            const int k = slot[x - x0];
            w->st.eye_rays++;
            w->eye_hit = 0;
            if (k >= 0 && ok[k]) {
                const rt_cands cd = {co ? job->cand + co[x] : NULL, co ? co[x + 1] - co[x] : 0,
                                     job->cand_key};
                rt_trace(w, ray[k].org, ray[k].dir, ray[k].tmin, ray[k].tmax, 1, 1.0, 0, -1,
                         co ? &cd : NULL, col);
            } else
                memcpy(col, job->o.background, sizeof col);
            rt_eye_store(w, x, y, col);
        }
    }
}

/* m x m samples per pixel (jittered or at the sub-pixel centres), averaged */
static void rt_tile_samples(rt_worker *w, int x0, int x1, int y0, int y1)
{
    rt_job *job = w->job;
    const int m = job->m;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double acc[3] = {0, 0, 0}, col[3];
            int hits = 0;
            uint64_t seed = rt_mix(((uint64_t)(uint32_t)y << 32) | (uint32_t)x);
            for (int b = 0; b < m; b++)
                for (int a = 0; a < m; a++) {
                    double ja = 0.5, jb = 0.5;
                    if (job->o.jitter) {
                        uint64_t h = rt_mix(seed ^ (uint64_t)(b * m + a));
                        ja = (double)(h >> 11) * 0x1.0p-53;
                        jb = (double)(rt_mix(h) >> 11) * 0x1.0p-53;
                    }
                    rt_eye(w, x + (a + ja) / m, y + (b + jb) / m, col);
                    for (int c = 0; c < 3; c++)
                        acc[c] += col[c];
                    hits += w->eye_hit;
                }
            if (job->cover_out)
                job->cover_out[(size_t)y * (size_t)job->gw + (size_t)x] = (unsigned short)hits;
            float *dst = job->rgb + 3 * ((size_t)y * (size_t)job->gw + (size_t)x);
            for (int c = 0; c < 3; c++) {
                double v = acc[c] / (double)(m * m);
                dst[c] = isfinite(v) ? (float)v : 0.0f;
            }
        }
}

static void rt_tile(rt_worker *w, int tile)
{
    rt_job *job = w->job;
    int tx = tile % job->tiles_x, ty = tile / job->tiles_x;
    int x0 = tx * RT_TILE, y0 = ty * RT_TILE;
    int x1 = x0 + RT_TILE < job->gw ? x0 + RT_TILE : job->gw;
    int y1 = y0 + RT_TILE < job->gh ? y0 + RT_TILE : job->gh;
    if (job->o.corner_rays || (job->m == 1 && !job->o.jitter))
        rt_tile_rows(w, x0, x1, y0, y1);
    else
        rt_tile_samples(w, x0, x1, y0, y1);
}

/* Corner mode, after all rays: pixel (x, y) = mean of corners (x, y), (x+1, y), (x, y+1),
   (x+1, y+1), in place. Pixel (x, y) holds corner (x, y), which no later pixel needs (in
   row-major order); the corners read next are not yet overwritten. */
/* pixel value from its 4 corners k00 (also the destination), k10, k01, k11 */
static inline void rt_corner_mean(float *k00, const float *k10, const float *k01, const float *k11)
{
    for (size_t c = 0; c < 3; c++) {
        double v = 0.25 * ((double)k00[c] + k10[c] + k01[c] + k11[c]);
        k00[c] = isfinite(v) ? (float)v : 0.0f;
    }
}

/* corner rays' rows [y0, y1) averaged into pixels in place, left to right and top to bottom
   (corner x + 1 and the row below are read before they are replaced); below: the corners
   under row y1 - 1 as traced (the next row, or the edge row under the last) */
static void rt_corner_rows(const rt_job *job, size_t y0, size_t y1, const float *below)
{
    const size_t W = (size_t)job->cam->width;
    float *rgb = job->rgb;
    const float *edge = job->edge;
    for (size_t y = y0; y < y1; y++) {
        float *r0 = rgb + 3 * y * W;
        const float *r1 = y + 1 < y1 ? rgb + 3 * (y + 1) * W : below;
        for (size_t x = 0; x + 1 < W; x++)
            rt_corner_mean(r0 + 3 * x, r0 + 3 * (x + 1), r1 + 3 * x, r1 + 3 * (x + 1));
        rt_corner_mean(r0 + 3 * (W - 1), edge + 3 * y, r1 + 3 * (W - 1), edge + 3 * (y + 1));
    }
}

/* tile t's rectangle of the ray grid and payload size */
static size_t rt_tile_rect(const rt_job *job, int t, int *x0, int *x1, int *y0, int *y1)
{
    int tx = t % job->tiles_x, ty = t / job->tiles_x;
    *x0 = tx * RT_TILE;
    *y0 = ty * RT_TILE;
    *x1 = *x0 + RT_TILE < job->gw ? *x0 + RT_TILE : job->gw;
    *y1 = *y0 + RT_TILE < job->gh ? *y0 + RT_TILE : job->gh;
    return RT_PAYLOAD_COUNTERS * sizeof(uint64_t) +
           (size_t)(*x1 - *x0) * (size_t)(*y1 - *y0) *
               (3 * sizeof(float) + (job->cover_out ? sizeof(uint16_t) : 0));
}

/* ray (x, y)'s eye-ray hits as a payload keeps them (job->cover_out set) */
static uint16_t rt_cover_get(const rt_job *job, int x, int y)
{
    const size_t k = (size_t)y * (size_t)job->gw + (size_t)x;
    return job->corner_hit ? job->corner_hit[k] : job->cover_out[k];
}

static void rt_cover_set(const rt_job *job, int x, int y, uint16_t v)
{
    const size_t k = (size_t)y * (size_t)job->gw + (size_t)x;
    if (job->corner_hit)
        job->corner_hit[k] = v != 0;
    else
        job->cover_out[k] = v <= (uint16_t)(job->m * job->m) ? v : (uint16_t)(job->m * job->m);
}

/* where ray (x, y) of the grid is kept until the frame is resolved */
static float *rt_ray_slot(const rt_job *job, int x, int y)
{
    if (job->o.corner_rays)
        return rt_corner_at(job, x, y);
    return job->rgb + 3 * ((size_t)y * (size_t)job->gw + (size_t)x);
}

static void rt_counters(const rt_stats *s, uint64_t c[RT_PAYLOAD_COUNTERS])
{
    c[0] = s->eye_rays;
    c[1] = s->eye_hits;
    c[2] = s->shadow_rays;
    c[3] = s->reflection_rays;
    c[4] = s->refraction_rays;
    c[5] = s->shadow_lbuf;
    c[6] = s->shadow_walks;
    c[7] = s->reflection_mirror;
}

/* packs tile t traced by w (counters: the difference of w's stats to before) */
static size_t rt_tile_pack(rt_worker *w, int t, const rt_stats *before)
{
    int x0, x1, y0, y1;
    size_t bytes = rt_tile_rect(w->job, t, &x0, &x1, &y0, &y1);
    uint64_t a[RT_PAYLOAD_COUNTERS], b[RT_PAYLOAD_COUNTERS];
    rt_counters(&w->st, a);
    rt_counters(before, b);
    for (int k = 0; k < RT_PAYLOAD_COUNTERS; k++)
        a[k] -= b[k];
    memcpy(w->payload, a, sizeof a);
    unsigned char *p = w->payload + sizeof a;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++, p += 3 * sizeof(float))
            memcpy(p, rt_ray_slot(w->job, x, y), 3 * sizeof(float));
    for (int y = y0; w->job->cover_out && y < y1; y++)
        for (int x = x0; x < x1; x++, p += sizeof(uint16_t)) {
            const uint16_t v = rt_cover_get(w->job, x, y);
            memcpy(p, &v, sizeof v);
        }
    return bytes;
}

int rt_frame_tile_rgb(const rt_frame *f, int tile, const void *payload, size_t bytes,
                      int rect[4], float *rgb)
{
    if (!f || !f->job || !payload || !rect || !rgb || tile < 0 || tile >= f->job->ntiles)
        return RT_ERR_ARG;
    int x0, x1, y0, y1;
    if (bytes != rt_tile_rect(f->job, tile, &x0, &x1, &y0, &y1))
        return RT_ERR_ARG;
    rect[0] = x0, rect[1] = x1, rect[2] = y0, rect[3] = y1;
    memcpy(rgb, (const unsigned char *)payload + RT_PAYLOAD_COUNTERS * sizeof(uint64_t),
           (size_t)(x1 - x0) * (size_t)(y1 - y0) * 3 * sizeof(float));
    return RT_OK;
}

int rt_frame_store(rt_frame *f, int tile, const void *payload, size_t bytes)
{
    if (!f || !f->job || !payload || tile < 0 || tile >= f->job->ntiles)
        return RT_ERR_ARG;
    rt_job *job = f->job;
    int x0, x1, y0, y1;
    if (bytes != rt_tile_rect(job, tile, &x0, &x1, &y0, &y1))
        return RT_ERR_ARG;
    uint64_t c[RT_PAYLOAD_COUNTERS];
    memcpy(c, payload, sizeof c);
    const unsigned char *p = (const unsigned char *)payload + sizeof c;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++, p += 3 * sizeof(float)) {
            float v[3];
            memcpy(v, p, sizeof v);
            float *dst = rt_ray_slot(job, x, y);
            for (int k = 0; k < 3; k++)
                dst[k] = isfinite(v[k]) ? v[k] : 0.0f; /* never NaN/Inf in the picture */
        }
    for (int y = y0; job->cover_out && y < y1; y++)
        for (int x = x0; x < x1; x++, p += sizeof(uint16_t)) {
            uint16_t v;
            memcpy(&v, p, sizeof v);
            rt_cover_set(job, x, y, v);
        }
    rt_stats *r = &job->remote;
    r->eye_rays += c[0];
    r->eye_hits += c[1];
    r->shadow_rays += c[2];
    r->reflection_rays += c[3];
    r->refraction_rays += c[4];
    r->shadow_lbuf += c[5];
    r->shadow_walks += c[6];
    r->reflection_mirror += c[7];
    return RT_OK;
}

/* the hook's next tile for a worker, -1 when none (or after a failure) */
static int rt_hook_next(rt_job *job)
{
    if (atomic_load(&job->hook_failed))
        return -1;
    pthread_mutex_lock(&job->lock);
    int t = job->hook->next(job->hook->user);
    pthread_mutex_unlock(&job->lock);
    if (t < -1 || t >= job->ntiles) {
        atomic_store(&job->hook_failed, 1);
        return -1;
    }
    return t;
}

/* Progress of the set-up (o.progress): a phase's name when it starts, its time when it
   ends, one line each ("rt: set-up: light buffers ... 0.81 s"); the grid is built before
   rt_render (rt_scene_commit), so its line gives the time it took. */
static double rt_phase(const rt_job *job, const char *name, double t_begin)
{
    if (!job->o.progress)
        return 0.0;
    const double now = rt_now();
    if (name)
        fprintf(stderr, "rt: set-up: %s ...", name);
    else
        fprintf(stderr, " %.2f s\n", now - t_begin);
    fflush(stderr);
    return now;
}

static void rt_progress(rt_job *job, uint64_t rays)
{
    int done = atomic_fetch_add(&job->done, 1) + 1;
    atomic_fetch_add(&job->rays, (unsigned long long)rays);
    if (!job->o.progress && !job->o.progress_fn)
        return;
    pthread_mutex_lock(&job->lock);
    if (job->o.progress_fn)
        job->o.progress_fn(job->o.progress_user, done, job->ntiles);
    double now = rt_now();
    if (job->o.progress && done == job->ntiles) { /* the summary line */
        double el = now - job->t0;
        unsigned long long rays_all = atomic_load(&job->rays);
        fprintf(stderr, "rt: %d tiles done in %.2f s, %llu rays, %.2f Mrays/s\n", done, el,
                rays_all, el > 0.0 ? (double)rays_all / el * 1e-6 : 0.0);
    } else if (job->o.progress && now - job->last_report > 0.5) {
        job->last_report = now;
        double el = now - job->t0;
        /* the tiles are taken spread over the picture (rt_tile_stride), so the time per tile
           so far is a sample of the whole picture's, not of its top rows; the set-up (eye-ray
           lists, light buffers) before the first tile is not a tile's */
        double tl = now - job->t_tiles;
        double left = done > 0 ? tl * (job->ntiles - done) / done : 0.0;
        fprintf(stderr, "rt: tiles %d/%d, %.2f Mrays/s, %.1f s left\r", done, job->ntiles,
                el > 0.0 ? (double)atomic_load(&job->rays) / el * 1e-6 : 0.0, left);
    }
    pthread_mutex_unlock(&job->lock);
}

/* The order the tiles are taken in: k -> (k * stride) mod ntiles with stride coprime to
   ntiles near ntiles / golden ratio, so that any first part of the order is spread evenly
   over the picture (the progress estimate then sees a sample of the whole picture's cost,
   not the top rows'). The tiles a worker gets do not change the picture. */
static int rt_tile_stride(int ntiles)
{
    if (ntiles <= 2)
        return 1;
    int s = (int)((double)ntiles * 0.6180339887498949);
    for (;; s++) {
        int a = s, b = ntiles;
        while (b) {
            int r = a % b;
            a = b;
            b = r;
        }
        if (a == 1)
            return s;
    }
}

static void rt_work(rt_worker *w)
{
    rt_job *job = w->job;
    for (;;) {
        int t;
        if (job->hook) {
            t = rt_hook_next(job);
        } else {
            int k = atomic_fetch_add(&job->next, 1);
            t = k < job->ntiles ? (int)((int64_t)k * job->stride % job->ntiles) : k;
        }
        if (t < 0 || t >= job->ntiles)
            break;
        const rt_stats st0 = w->st;
        uint64_t before = w->st.eye_rays + w->st.shadow_rays + w->st.reflection_rays +
                          w->st.refraction_rays;
        rt_tile(w, t);
        if (job->hook) {
            size_t bytes = rt_tile_pack(w, t, &st0);
            pthread_mutex_lock(&job->lock);
            int rc = job->hook->done(job->hook->user, t, w->payload, bytes);
            pthread_mutex_unlock(&job->lock);
            if (rc < 0) {
                atomic_store(&job->hook_failed, 1);
                break;
            }
        }
        rt_progress(job, w->st.eye_rays + w->st.shadow_rays + w->st.reflection_rays +
                             w->st.refraction_rays - before);
    }
}

/* part k of the frame's rt_par_run: worker k takes tiles until none is left (the tiles a
   worker gets do not change the picture) */
static void rt_work_part(void *arg, int k, int n)
{
    rt_worker *w = (rt_worker *)arg + k;
    const rt_job *job = w->job;
    /* part k's share of the picture's pages made present first (rt_prefault): each thread
       its own, not the calling thread all of them before the tiles */
    rt_prefault(job->rgb, (size_t)job->cam->width * (size_t)job->cam->height * 3 * sizeof(float),
                k, n);
    rt_work(w);
}

/* light buffers (rt_lbuf.c) for the lights of the scene, when asked for and when they pay:
   projecting a primitive's box costs about as much as a shadow ray's grid walk saves, and
   each eye ray that hits asks at most one shadow ray per light, so the primitives must not
   outnumber the eye rays */
static int rt_job_lbufs(rt_job *job)
{
    const rt_scene *sc = job->sc;
    const double rays = (double)job->gw * (double)job->gh * (double)(job->m * job->m);
    if (!job->o.light_buffers || !sc->use_grid || sc->nprim == 0 || (double)sc->nprim > rays)
        return RT_OK;
    int rc = RT_OK;
    for (int li = 0; li < sc->nlights && rc == RT_OK; li++)
        rc = rt_lbuf_build(sc, &sc->light[li], rt_par_threads(job->o.threads), &job->lbuf[li]);
    return rc;
}

static void rt_job_lbufs_free(rt_job *job)
{
    for (int li = 0; li < RT_MAX_LIGHTS; li++)
        rt_lbuf_free(&job->lbuf[li]);
    for (int k = 0; k < RT_MIRRORS; k++)
        rt_lbuf_free(&job->mir[k].lb);
    free(job->mir_of);
    job->mir_of = NULL;
}
/* Planar mirrors. An eye ray's reflection off a flat primitive (geometric normal, no smooth
 * normal) lies on the line through the mirror image E' of the eye in the primitive's plane,
 * like a shadow ray on the line through its light: a light buffer built from E'
 * (rt_lbuf_build_omit) gives it a short list of candidates in depth order instead of the
 * grid walk (rt_trace_mirror). Mirrors: the planes of the flat primitives that reflect on
 * the eye's side (specular ks > 0 or transparent), grouped by plane: a member's unit normal
 * n (turned to the eye) within RT_MIRROR_NTOL of the group's in every component, each
 * vertex v within delta of n . v = c. Built for at most RT_MIRRORS groups that cover the
 * most raster area, when that area (an upper bound of their eye rays: it ignores what hides
 * them) is at least RT_MIRROR_MIN_RAYS and RT_MIRROR_PER_PRIM times the primitives' number
 * (a buffer's build costs about 1500 instructions per primitive, a reflection ray that takes
 * the list saves about 1000: docs/bench/rt_tuning.md). Left out of a buffer: the primitives
 * with every vertex at n . v - c <= delta (on the plane or behind it). A ray leaving a member
 * starts eps >= 1e-9 of the scene's extent E above the member's plane (rt_eps; the hit point
 * lies on it to the hit's error, about 1e-15 of the coordinates), and its direction R has
 * R . N = cos_i >= 0 for the member's normal N (to the rounding), so R . n >= -2e-12 and
 * within the scene box (t <= 1.8 E) it sinks by at most 4e-12 E: its points there stay
 * above the plane by nearly eps. delta is 1e-3 of that, and the rounding of the tests is
 * below 1e-3 of it when the coordinates' magnitude is at most RT_MIRROR_MAX_OFFSET times E
 * (else no mirrors): no primitive left out can be hit. The perspective camera only (the
 * eye: its projection reference point). */
#define RT_MIRROR_MIN_RAYS 4096.0
#define RT_MIRROR_PER_PRIM 4.0
#define RT_MIRROR_MAX_OFFSET 1000.0

typedef struct rt_mirror_key {
    double n[3], c; /* the plane, n turned to the eye */
    double area;    /* raster area of the primitive */
    uint32_t i;
} rt_mirror_key;

/* by the normal rounded to RT_MIRROR_NQ, then c, then primitive */
#define RT_MIRROR_NQ 0x1p40
static int rt_mirror_qn_cmp(const double na[3], const double nb[3])
{
    for (int c = 0; c < 3; c++) {
        const double qa = nearbyint(na[c] * RT_MIRROR_NQ), qb = nearbyint(nb[c] * RT_MIRROR_NQ);
        if (qa != qb)
            return qa < qb ? -1 : 1;
    }
    return 0;
}

static int rt_mirror_key_cmp(const void *pa, const void *pb)
{
    const rt_mirror_key *a = pa, *b = pb;
    const int q = rt_mirror_qn_cmp(a->n, b->n);
    if (q)
        return q;
    if (a->c != b->c)
        return a->c < b->c ? -1 : 1;
    return a->i < b->i ? -1 : (a->i > b->i);
}

/* 1 if unit normals a and b differ by at most RT_MIRROR_NTOL in every component */
#define RT_MIRROR_NTOL 1e-12
static int rt_mirror_same_n(const double a[3], const double b[3])
{
    return fabs(a[0] - b[0]) <= RT_MIRROR_NTOL && fabs(a[1] - b[1]) <= RT_MIRROR_NTOL &&
           fabs(a[2] - b[2]) <= RT_MIRROR_NTOL;
}

/* the raster area of primitive i's projection (clipped to the raster by its box); the whole
   raster when a vertex does not project */
static double rt_mirror_area(const rt_scene *sc, const rt_camera *cam, const double vm[4][4],
                             double ws, double gw, double gh, size_t i)
{
    const size_t nv = rt_prim_nverts(sc, i);
    double bb[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY}, a = 0.0, p0[2] = {0, 0}, pl[2];
    for (size_t k = 0; k < nv; k++) {
        double x[3], q[2];
        rt_prim_vertex(sc, i, k, x);
        if (!rt_camera_project(cam, vm, ws, x, &q[0], &q[1]))
            return gw * gh;
        if (k == 0)
            memcpy(p0, q, sizeof p0);
        else
            a += pl[0] * q[1] - q[0] * pl[1];
        memcpy(pl, q, sizeof pl);
        bb[0] = fmin(bb[0], q[0]);
        bb[1] = fmax(bb[1], q[0]);
        bb[2] = fmin(bb[2], q[1]);
        bb[3] = fmax(bb[3], q[1]);
    }
    if (nv == 0)
        return 0.0;
    a = 0.5 * fabs(a + pl[0] * p0[1] - p0[0] * pl[1]);
    const double bw = bb[1] - bb[0], bh = bb[3] - bb[2];
    const double cw = fmin(bb[1], gw) - fmax(bb[0], 0.0), ch = fmin(bb[3], gh) - fmax(bb[2], 0.0);
    if (!(cw > 0.0) || !(ch > 0.0))
        return 0.0;
    if (rt_prim_geo(sc, i).kind == RT_KIND_POLY || !(bw * bh > 0.0))
        return cw * ch; /* loops, or no area: the clipped box */
    return fmin(a, bw * bh) * (cw * ch) / (bw * bh);
}

/* 1 if surface s spawns reflection rays (specular ks Cs > 0, or transparent: Fresnel) */
static int rt_mirror_surf(const rt_surface *s)
{
    return (s->refl_eq == RT_REFL_SPECULAR && s->ks > 0.0 &&
            fmax(s->specular[0], fmax(s->specular[1], s->specular[2])) > 0.0) ||
           s->transparency > 0.0;
}

/* 1 if primitive i reflects on its side that faces point E; its plane (n turned to E, c) */
static int rt_mirror_plane(const rt_scene *sc, size_t i, const double E[3], double n[3],
                           double *c)
{
    const rt_prim *p = rt_prim_rec(sc, i);
    if (!rt_mirror_surf(rt_prim_surf(sc, p, 0)) && !rt_mirror_surf(rt_prim_surf(sc, p, 1)))
        return 0; /* (before the normal: most primitives are not mirrors) */
    double v[3];
    rt_prim_ng(sc, i, n);
    rt_prim_vertex(sc, i, 0, v);
    const double h = dot3(n, E) - dot3(n, v);
    if (h == 0.0 || !isfinite(h) || !rt_mirror_surf(rt_prim_surf(sc, p, h < 0.0)))
        return 0;
    for (int k = 0; k < 3; k++) /* (+ 0.0: -0 becomes +0, equal planes compare equal) */
        n[k] = (h < 0.0 ? -n[k] : n[k]) + 0.0;
    *c = dot3(n, v);
    return 1;
}

/* 1 if every vertex v of primitive i has n . v - c <= delta (and >= -delta with two) */
static int rt_mirror_below(const rt_scene *sc, size_t i, const double n[3], double c,
                           double delta, int two)
{
    const size_t nv = rt_prim_nverts(sc, i);
    for (size_t k = 0; k < nv; k++) {
        double v[3];
        rt_prim_vertex(sc, i, k, v);
        const double h = dot3(n, v) - c;
        if (!(h <= delta) || (two && !(h >= -delta)))
            return 0;
    }
    return 1;
}

/* mirror m of plane (n, c) for the members keys[a..b-1]: its buffer from the eye's image,
   the members marked in job->mir_of; RT_OK also when no buffer is made */
static int rt_mirror_build(rt_job *job, int m, const rt_mirror_key *keys, size_t a, size_t b,
                           double delta)
{
    const rt_scene *sc = job->sc;
    const double *n = keys[a].n, c = keys[a].c, *E = job->cam->prp;
    uint8_t *omit = rt_alloc_array(sc->nprim, 1);
    if (!omit)
        return RT_ERR_NOMEM;
    for (size_t i = 0; i < sc->nprim; i++)
        omit[i] = (uint8_t)rt_mirror_below(sc, i, n, c, delta, 0);
    rt_light l;
    memset(&l, 0, sizeof l);
    l.type = RT_LIGHT_POSITIONAL;
    const double h = dot3(n, E) - c;
    for (int k = 0; k < 3; k++)
        l.position[k] = E[k] - 2.0 * h * n[k];
    rt_mirror *mi = &job->mir[m];
    int rc = rt_lbuf_build_omit(sc, &l, omit, 0, rt_par_threads(job->o.threads), &mi->lb);
    free(omit);
    if (rc != RT_OK || !mi->lb.ok)
        return rc;
    mi->zstep = mi->lb.zscale > 0.0 ? 1.0 / mi->lb.zscale : 0.0;
    mi->k0 = mi->lb.zlo - 2.0 * mi->lb.zeps;
    for (size_t k = a; k < b; k++)
        job->mir_of[keys[k].i] = (uint8_t)(m + 1);
    return RT_OK;
}

/* the mirrors of the frame (see above); RT_OK also when there are none */
static int rt_job_mirrors(rt_job *job)
{
    const rt_scene *sc = job->sc;
    const rt_camera *cam = job->cam;
    const double rays = (double)job->gw * (double)job->gh * (double)(job->m * job->m);
    if (!job->o.light_buffers || !sc->use_grid || sc->nprim == 0 || sc->nprim > UINT32_MAX ||
        (double)sc->nprim > rays || job->o.max_depth < 2 || !cam->perspective)
        return RT_OK;
    double ext = 0.0, mag = 0.0;
    for (int k = 0; k < 3; k++) {
        ext = fmax(ext, sc->bbox[3 + k] - sc->bbox[k]);
        mag = fmax(mag, fmax(fabs(sc->bbox[k]), fabs(sc->bbox[3 + k])));
    }
    mag = fmax(mag, rt_absmax3(cam->prp));
    if (!(ext > 0.0) || !(mag <= RT_MIRROR_MAX_OFFSET * ext))
        return RT_OK;
    const double delta = 1e-3 * 1e-9 * ext; /* 1e-3 of rt_eps's least offset */
    double vm[4][4], ws;
    if (!rt_camera_vmap(cam, vm, &ws))
        return RT_OK;
    rt_mirror_key *keys = rt_alloc_array(sc->nprim, sizeof *keys);
    if (!keys)
        return RT_ERR_NOMEM;
    size_t nk = 0;
    for (size_t i = 0; i < sc->nprim; i++) {
        rt_mirror_key *k = &keys[nk];
        if ((sc->prim_vd && sc->prim_vd[i] != RT_NO_VD) || (i >= sc->ntri_plain && i < sc->ntri))
            continue; /* vertex data or a mesh's triangle: maybe smooth */
        if (!rt_mirror_plane(sc, i, cam->prp, k->n, &k->c))
            continue;
        k->i = (uint32_t)i;
        k->area = rt_mirror_area(sc, cam, (const double(*)[4])vm, ws, job->gw, job->gh, i);
        nk++;
    }
    qsort(keys, nk, sizeof *keys, rt_mirror_key_cmp);
    /* the groups: runs of equal rounded n whose c lie within delta of the run's first;
       members whose n is not the run's first's within RT_MIRROR_NTOL or with a vertex off
       its plane by more than delta are dropped (their area too) */
    size_t best[RT_MIRRORS][2] = {{0, 0}};
    double barea[RT_MIRRORS] = {0.0};
    for (size_t a = 0, b; a < nk; a = b) {
        double area = 0.0, n[3], c = keys[a].c;
        memcpy(n, keys[a].n, sizeof n);
        size_t w = a; /* the members kept move to keys[a..w-1] */
        for (b = a; b < nk && !rt_mirror_qn_cmp(keys[b].n, n) && keys[b].c - c <= delta; b++)
            if (rt_mirror_same_n(keys[b].n, n) && rt_mirror_below(sc, keys[b].i, n, c, delta, 1)) {
                area += keys[b].area;
                keys[w] = keys[b];
                keys[w++].c = c;
            }
        const double need = fmax(RT_MIRROR_MIN_RAYS, RT_MIRROR_PER_PRIM * (double)sc->nprim);
        if (!(area * (double)(job->m * job->m) >= need))
            continue;
        int slot = -1; /* the smallest kept group, replaced if this one is larger */
        for (int m = 0; m < RT_MIRRORS; m++)
            if (barea[m] < area && (slot < 0 || barea[m] < barea[slot]))
                slot = m;
        if (slot >= 0) {
            barea[slot] = area;
            best[slot][0] = a;
            best[slot][1] = w;
        }
    }
    int rc = RT_OK;
    if (barea[0] > 0.0 && !(job->mir_of = rt_calloc_array(sc->nprim, 1)))
        rc = RT_ERR_NOMEM;
    for (int m = 0; m < RT_MIRRORS && rc == RT_OK; m++)
        if (barea[m] > 0.0)
            rc = rt_mirror_build(job, m, keys, best[m][0], best[m][1], delta);
    free(keys);
    return rc;
}


/* frees what rt_render_cover allocated for the job and its nt workers w (w may be NULL) */
static void rt_job_release(rt_job *job, rt_worker *w, int nt)
{
    for (int k = 0; w && k < nt; k++) {
        rt_ctx_free(&w[k].ctx);
        free(w[k].shadow_cache);
        free(w[k].payload);
    }
    rt_job_lbufs_free(job);
    free(w);
    free(job->edge);
    free(job->corner_hit);
    free(job->cover);
    free(job->cand_off);
    free(job->cand);
    free(job->cand_key);
}

int rt_render(const rt_scene *sc, const rt_camera *cam, const rt_render_options *opts,
              float *rgb, rt_stats *stats)
{
    return rt_render_cover(sc, cam, opts, rgb, NULL, stats);
}

/* cover[y*W + x] = corner hits of corners (x,y), (x+1,y), (x,y+1), (x+1,y+1), rows [y0, y1) */
static void rt_corner_cover_rows(const rt_job *job, size_t y0, size_t y1)
{
    const size_t W = (size_t)job->cam->width, G = W + 1;
    const uint8_t *h = job->corner_hit;
    for (size_t y = y0; y < y1; y++)
        for (size_t x = 0; x < W; x++)
            job->cover_out[y * W + x] = (unsigned short)(h[y * G + x] + h[y * G + x + 1] +
                                                         h[(y + 1) * G + x] + h[(y + 1) * G + x + 1]);
}

/* part k of the corner rays' resolve (rt_par_run): rows [y0, y1) averaged, and their cover
   made from the corners' hit flags when asked for. Part k's last row reads the first row of
   part k + 1 as traced, which that part replaces: rt_job_trace saved it in job->corner_next
   (row k) before the parts ran, so every pixel is the mean of the same corners, in the same
   order, as in one pass. */
static void rt_corner_part(void *arg, int k, int n)
{
    const rt_job *job = arg;
    const size_t W = (size_t)job->cam->width, H = (size_t)job->cam->height;
    size_t y0, y1;
    rt_par_range(H, k, n, &y0, &y1);
    rt_corner_rows(job, y0, y1,
                   y1 == H ? job->edge + 3 * (H + 1) : job->corner_next + 3 * W * (size_t)k);
    if (job->corner_hit)
        rt_corner_cover_rows(job, y0, y1);
}

/* the options' and the camera's checks; *m = the samples' grid side (samples = m * m) */
static int rt_render_check(const rt_render_options *o, const rt_camera *cam, int *m)
{
    if (o->samples < 1 || o->samples > 4096 || o->max_depth < 1 || o->max_depth > RT_MAX_DEPTH ||
        !isfinite(o->cutoff) || o->cutoff < 0.0 || o->threads < 0 || o->fresnel < 0 ||
        o->fresnel > RT_FRESNEL_NONE)
        return RT_ERR_ARG;
    *m = 1;
    while (*m * *m < o->samples)
        (*m)++;
    if (*m * *m != o->samples)
        return RT_ERR_ARG;
    for (int c = 0; c < 3; c++)
        if (!isfinite(o->background[c]))
            return RT_ERR_ARG;
    if (cam->width < 1 || cam->height < 1 || cam->width > 65536 || cam->height > 65536)
        return RT_ERR_ARG;
    return RT_OK;
}

/* corner rays: the picture's edge row and column, and with a cover the corners' hit flags */
static int rt_job_corner_bufs(rt_job *job)
{
    /* the resolve's parts: as many as the frame's threads, one row each but the first */
    job->corner_parts = rt_par_threads(job->o.threads);
    if (job->corner_parts > job->cam->height)
        job->corner_parts = job->cam->height;
    const size_t ne = (size_t)job->gw + (size_t)job->gh - 1;
    const size_t nn = (size_t)(job->corner_parts - 1) * (size_t)job->cam->width;
    job->edge = rt_alloc_array(ne + nn, 3 * sizeof(float));
    job->corner_next = job->edge ? job->edge + 3 * ne : NULL;
    if (job->cover_out)
        job->corner_hit = rt_alloc_array((size_t)job->gw, (size_t)job->gh);
    if (!job->edge || (job->cover_out && !job->corner_hit)) {
        free(job->edge);
        free(job->corner_hit);
        return RT_ERR_NOMEM;
    }
    return RT_OK;
}

/* nt workers (w from rt_calloc_array): shadow caches cleared, mailboxes, and with a tile hook
   a payload buffer each (rt_job_release frees what was made, also after a failure) */
static int rt_workers_init(rt_job *job, rt_worker *w, int nt, size_t max_payload)
{
    const rt_scene *sc = job->sc;
    size_t ncache = (size_t)(job->o.max_depth + 1) * (size_t)(sc->nlights > 0 ? sc->nlights : 1);
    for (int k = 0; k < nt; k++) {
        w[k].job = job;
        w[k].shadow_cache = rt_alloc_array(ncache, sizeof(rt_scache));
        if (!w[k].shadow_cache || rt_ctx_init(&w[k].ctx, sc) != RT_OK)
            return RT_ERR_NOMEM;
        if (job->hook && !(w[k].payload = rt_alloc_array(1, max_payload)))
            return RT_ERR_NOMEM;
        for (size_t a = 0; a < ncache; a++) {
            for (int j = 0; j < RT_SCACHE; j++)
                w[k].shadow_cache[a].id[j] = -1;
            w[k].shadow_cache[a].live = 0;
        }
    }
    return RT_OK;
}

/* the frame's statistics: the workers' and remote tiles' ray counts, the scene's figures */
static void rt_job_stats(const rt_job *job, const rt_worker *w, int nt, rt_stats *out)
{
    const rt_scene *sc = job->sc;
    rt_stats st = job->remote;
    for (int k = 0; k < nt; k++)
        rt_stats_add(&st, &w[k].st); /* workers count rays only; the rest is set below */
    st.render_seconds = rt_now() - job->t0;
    st.grid_cells = sc->use_grid ? sc->grid.ncells + sc->grid.nsubcells : 0;
    st.grid_refs = sc->use_grid ? sc->grid.nrefs + sc->grid.nsrefs : 0;
    st.prims = sc->nprim;
    st.build_seconds = sc->build_seconds;
    st.memory_bytes = sc->memory_bytes;
    st.tri_bytes = sc->tri_bytes;
    st.grid_bytes = sc->grid_bytes;
    *out = st;
}

/* the tiles traced by nt workers on the pool's threads, the hook's begin and end around
   them (the frame lives from begin to end), corner rays averaged and the cover made when the
   frame is whole here. *traced: 0 when the hook's begin refused the frame (nothing traced) */
static int rt_job_trace(rt_job *job, rt_worker *w, int nt, size_t max_payload, int *traced)
{
    rt_frame frame = {job};
    *traced = 0;
    if (job->hook && job->hook->begin &&
        job->hook->begin(job->hook->user, &frame, job->ntiles, max_payload) < 0)
        return RT_ERR_HOOK;
    *traced = 1;
    int rc = RT_OK;
    pthread_mutex_init(&job->lock, NULL);
    rt_par_run(nt, rt_work_part, w); /* the pool's threads (rt_pool.c): tiles by a counter */
    int whole = 1; /* the frame is complete here */
    if (job->hook) {
        int e = job->hook->end ? job->hook->end(job->hook->user, &frame) : 1;
        if (e < 0 || atomic_load(&job->hook_failed))
            rc = RT_ERR_HOOK;
        whole = e > 0;
    }
    pthread_mutex_destroy(&job->lock);
    if (job->o.corner_rays && whole && rc == RT_OK) { /* corners to pixels (rt_corner_part) */
        const int parts = nt < job->corner_parts ? nt : job->corner_parts;
        const size_t W = (size_t)job->cam->width, H = (size_t)job->cam->height;
        for (int k = 0; k + 1 < parts; k++) {
            size_t y0, y1;
            rt_par_range(H, k, parts, &y0, &y1);
            memcpy(job->corner_next + 3 * W * (size_t)k, job->rgb + 3 * W * y1,
                   3 * W * sizeof(float));
        }
        rt_par_run(parts, rt_corner_part, job);
    }
    return rc;
}

int rt_render_cover(const rt_scene *sc, const rt_camera *cam, const rt_render_options *opts,
                    float *rgb, unsigned short *cover, rt_stats *stats)
{
    if (!sc || !cam || !rgb)
        return RT_ERR_ARG;
    if (!sc->committed)
        return RT_ERR_STATE;
    rt_job job;
    memset(&job, 0, sizeof job);
    if (opts)
        job.o = *opts;
    else
        rt_render_options_default(&job.o);
    const rt_render_options *o = &job.o;
    int m;
    if (rt_render_check(o, cam, &m) != RT_OK)
        return RT_ERR_ARG;
    job.t0 = rt_now(); /* render_seconds: with the eye-ray lists and light buffers built here */
    job.sc = sc;
    job.eps_box = rt_eps_box(sc);
    job.cam = cam;
    job.rgb = rgb;
    job.m = m;
    job.gw = cam->width + (o->corner_rays ? 1 : 0);
    job.gh = cam->height + (o->corner_rays ? 1 : 0);
    job.cover_out = cover;
    if (o->corner_rays && rt_job_corner_bufs(&job) != RT_OK)
        return RT_ERR_NOMEM;
    if (o->corner_rays || (m == 1 && !o->jitter)) { /* all NULL: no culling */
        const double tp = rt_phase(&job, "candidate lists", 0.0);
        const rt_cover_out cv = rt_cover(sc, cam, o->corner_rays ? 0.0 : 0.5, job.gw, job.gh,
                                         rt_par_threads(o->threads));
        job.cover = cv.mask;
        job.cand_off = cv.off;
        job.cand = cv.ids;
        job.cand_key = cv.key;
        const char *pe = getenv("GKS_RT_PACKETS"); /* "0": every eye ray alone (tests) */
        job.packets = !(pe && !strcmp(pe, "0"));
        rt_phase(&job, NULL, tp);
    }
    const double tl = rt_phase(&job, "light buffers", 0.0);
    int rc = rt_job_lbufs(&job);
    if (rc == RT_OK)
        rc = rt_job_mirrors(&job);
    rt_phase(&job, NULL, tl);
    job.tiles_x = (job.gw + RT_TILE - 1) / RT_TILE;
    job.ntiles = job.tiles_x * ((job.gh + RT_TILE - 1) / RT_TILE);
    job.stride = rt_tile_stride(job.ntiles);
    job.t_tiles = rt_now();
    atomic_init(&job.next, 0);
    atomic_init(&job.done, 0);
    atomic_init(&job.rays, 0);
    atomic_init(&job.hook_failed, 0);
    job.hook = o->tiles;
    if (job.hook && (!job.hook->next || !job.hook->done)) {
        job.hook = NULL;
        if (rc == RT_OK)
            rc = RT_ERR_ARG;
    }
    int tx0, tx1, ty0, ty1; /* tile 0 is a largest tile */
    const size_t max_payload = rt_tile_rect(&job, 0, &tx0, &tx1, &ty0, &ty1);
    int nt = rt_par_threads(o->threads);
    if (nt > job.ntiles)
        nt = job.ntiles;
    rt_worker *w = rt_calloc_array((size_t)nt, sizeof *w);
    if (!w)
        rc = RT_ERR_NOMEM;
    if (rc == RT_OK)
        rc = rt_workers_init(&job, w, nt, max_payload);
    int traced = 0;
    if (rc == RT_OK)
        rc = rt_job_trace(&job, w, nt, max_payload, &traced);
    if (traced && stats)
        rt_job_stats(&job, w, nt, stats);
    rt_job_release(&job, w, nt);
    return rc;
}
