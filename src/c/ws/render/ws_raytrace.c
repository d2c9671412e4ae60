/* SPDX-License-Identifier: MIT */
/*
 * ws_raytrace.c -- HLHSR mode GHLHSR_RAYTRACE (paper sections 3 and 5) for the drawing
 * workstations (render layer, ws_render.h). Area primitives (FILL AREA, FILL AREA SET, CELL
 * ARRAY) are not rasterized but recorded in VRC3 (the NDC3 points after the view orientation
 * matrix of their view); when the frame is written they are traced with gksrt, view by view in
 * ascending view index order: the camera comes from the view's mapping matrix, the display
 * volume is the view clip volume (where the indicators are on) intersected with the
 * workstation window, and the traced pixels are composed over the framebuffer by their sample
 * coverage. POLYLINEs, POLYMARKERs and TEXT are annotations, rasterized as in mode 0 and
 * ignored by the tracer (a traced surface covers them). Lights the tracer rejects (a spot
 * light of spread 0, a zero direction) are left out. Documentation: docs/RAYTRACING.md.
 */
#include "ws_raytrace.h"
#include "ws_vrc.h"
#include "gks_alloc.h"
#include "gks_xform.h"
#include "ws_mpi.h"
#include "ws_dlist.h"
#include <stdio.h>
#include <limits.h>
#include <stdatomic.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* The attributes a pair of tracer surfaces is made of (consecutive areas of one attribute
 * setting share one pair). */
typedef struct rt_attr {
    Grgb colour;             /* diffuse colour */
    Garea_props props[2];
    int refl_eq[2];
    uint64_t light_mask;     /* GKS numbering: bit i-1 = light index i */
} rt_attr;

/* The recording of one view: its tracer scene, filled as the primitives arrive (VRC3), and
 * the GKS light mask of each of its surfaces (mapped to the scene's lights when traced). */
typedef struct rt_view_rec {
    rt_scene *sc;
    rt_attr last;            /* attributes of the latest surfaces f, b (valid if f >= 0) */
    int f, b;
    uint64_t *smask;         /* per surface id */
    size_t nsmask, capsmask;
} rt_view_rec;

/* Record kinds of a FILL AREA (SET) in the display list (ws_dlist.h): its loops of 3 or more
 * points, with their VRC3 unit normals and colours where it is shaded smooth and has them;
 * attributes an rt_qattr. DL_POLY: the points in VRC3; DL_POLY_NDC: in NDC3, for the
 * recording worker to map with the record's orientation (rt_qattr.ori, affine), known at
 * the call to stay within the tracer's range there. */
enum { DL_POLY = 1, DL_POLY_NDC = 2 };

/* A queued area's attributes: the tracer's, and the first three rows of its view's
 * orientation matrix (a DL_POLY_NDC record's points go through them on the worker). */
typedef struct rt_qattr {
    rt_attr a;
    double ori[3][4];
} rt_qattr;

/* Where the recording worker's scene writes its next triangles (rt_scene_input_next: up to
 * two byte ranges of reserved storage), published by the worker after each chunk for the
 * application's thread, which makes those pages present while it would otherwise wait for a
 * full queue (prefault_step). A sequence lock: seq odd while the worker writes. */
typedef struct pf_window {
    atomic_uint seq;
    atomic_int n;
    _Atomic uintptr_t lo[2], hi[2];
} pf_window;

struct ws_rt {
    rt_view_rec view[GKS_MAX_VIEW_IND + 1];
    size_t count;            /* tracer primitives recorded (or queued) */
    /* asynchronous recording: the display list of the frame (the render layer's, which the
     * classic renderer reads as well, or the recording's own: own_dl), its sealed chunks
     * with areas go to the queue (NULL: off); the worker's side: the view record its areas go to (NULL: their
     * surfaces failed), the first error and the areas lost since the last ws_rt_sync */
    ws_dlist *dl;
    int own_dl;
    rt_serial *queue;
    int qtried;              /* rt_serial_new was asked (and said NULL: off) */
    rt_view_rec *wvr;
    atomic_int werr;
    size_t wlost;
    pf_window pf;            /* the worker's scene: where its next triangles go */
    double *wxyz;            /* the worker's VRC3 points of a DL_POLY_NDC record of more */
    size_t wcap;             /* than STACK_POINTS points (room for wcap points) */
    /* the application's side: the display list's key of the queued areas' rt_qattr for
     * the core's numbers kattr (gks_prim.attr_gen) and kviews (gks_ws.views_gen), and the
     * largest |coordinate| klim of a point that its orientation keeps in range (-1: none,
     * the points are mapped at the call); keys counts the keys given */
    uint64_t kattr, kviews, key, keys;
    double klim;
    uintptr_t pf_done[2];    /* the application's side: end of what it made present there */
    rt_render_options opts;  /* set by the ESCAPEs */
    rt_stats last;           /* of the last traced picture */
    int share_tiles;         /* the next frames' tiles are shared by the MPI ranks */
    ws_rt_tile_fn tile_fn;   /* preview of each traced tile, or NULL */
    void *tile_user;
};

void ws_rt_set_tile_fn(ws_rt *r, ws_rt_tile_fn fn, void *user)
{
    r->tile_fn = fn;
    r->tile_user = user;
}

/* The tile hook of a preview: every tile traced here, in order; each one's colours go to
 * tile_fn as framebuffer pixels (ray (x, y) of the grid shows as pixel (x, y), the extra
 * corner rays of the last column and row are left out). Callbacks run one at a time. */
typedef struct tile_preview {
    ws_rt *r;
    rt_frame *f;
    int next, ntiles, ix0, iy1, w, h;
    float ray[16 * 16 * 3], px[16 * 16 * 3];
} tile_preview;

static int preview_begin(void *user, rt_frame *f, int ntiles, size_t max_tile_bytes)
{
    (void)max_tile_bytes;
    ((tile_preview *)user)->f = f;
    ((tile_preview *)user)->ntiles = ntiles;
    return 0;
}

static int preview_next(void *user)
{
    tile_preview *t = user;
    return t->next < t->ntiles ? t->next++ : -1;
}

static int preview_done(void *user, int tile, const void *payload, size_t bytes)
{
    tile_preview *t = user;
    int rc[4];
    if (rt_frame_tile_rgb(t->f, tile, payload, bytes, rc, t->ray) != RT_OK)
        return 0; /* no preview of this tile; the frame is still right */
    int rw = rc[1] - rc[0], x1 = rc[1] < t->w ? rc[1] : t->w, y1 = rc[3] < t->h ? rc[3] : t->h;
    int w = x1 - rc[0], h = y1 - rc[2];
    if (w <= 0 || h <= 0)
        return 0;
    for (int y = rc[2]; y < y1; y++) /* grid rows top-first -> preview rows bottom-up */
        for (int x = rc[0]; x < x1; x++)
            for (int q = 0; q < 3; q++) {
                float v = t->ray[3 * ((size_t)(y - rc[2]) * rw + (x - rc[0])) + q];
                t->px[3 * ((size_t)(y1 - 1 - y) * w + (x - rc[0])) + q] =
                    v > 0 ? (v < 1 ? v : 1) : 0;
            }
    t->r->tile_fn(t->r->tile_user, t->ix0 + rc[0], t->iy1 - y1, w, h, t->px);
    return 0;
}

static int preview_end(void *user, rt_frame *f)
{
    (void)user, (void)f;
    return 1;
}

/* Areas of more points are recorded synchronously (as the queue's blocks of 256 KiB
 * did: their points would fill a chunk alone). */
#define QUEUE_MAX_POINTS ((size_t)10000)

/* Points transformed on the stack up to this many (larger areas use the heap). */
#define STACK_POINTS 32

ws_rt *ws_rt_new(ws_dlist *dl)
{
    ws_rt *r = gks_calloc_array(1, sizeof(ws_rt));
    if (!r)
        return NULL;
    r->own_dl = !dl;
    r->dl = dl ? dl : ws_dlist_new();
    if (!r->dl) {
        gks_free(r);
        return NULL;
    }
    rt_render_options_default(&r->opts);
    return r;
}

/* How far ahead of the worker its scene's storage is made present: the storage of its next
 * PF_TRIS triangles (9 MiB of vertices, 64 of the queue's chunks), in steps of PF_STEP (one
 * huge page of the arrays), never in the worker's current huge page or the one after it, so
 * that the two threads do not fault the same page at the same time (the records' 1.5 MiB
 * lie within that gap: the worker touches them itself). */
#define PF_TRIS ((size_t)1 << 17)
#define PF_STEP ((uintptr_t)2 << 20)

/* The worker's side: where sc writes its next PF_TRIS triangles (n 0: nowhere known). */
static void pf_publish(ws_rt *r, const rt_scene *sc)
{
    void *lo[2] = { NULL, NULL }, *hi[2] = { NULL, NULL };
    const int n = sc ? rt_scene_input_next(sc, PF_TRIS, lo, hi) : 0;
    const unsigned q = atomic_load_explicit(&r->pf.seq, memory_order_relaxed);
    atomic_store_explicit(&r->pf.seq, q + 1, memory_order_relaxed);
    /* release stores (no fences, which ThreadSanitizer does not model): a reader that sees
       any of them sees seq odd afterwards */
    for (int i = 0; i < 2; i++) {
        atomic_store_explicit(&r->pf.lo[i], (uintptr_t)lo[i], memory_order_release);
        atomic_store_explicit(&r->pf.hi[i], (uintptr_t)hi[i], memory_order_release);
    }
    atomic_store_explicit(&r->pf.n, n, memory_order_release);
    atomic_store_explicit(&r->pf.seq, q + 2, memory_order_release);
}

/* The application's side: the published ranges (their number), or 0 while the worker is
 * writing them (the caller then waits for the queue as before: nothing here spins). */
static int pf_read(ws_rt *r, uintptr_t lo[2], uintptr_t hi[2])
{
    const unsigned q = atomic_load_explicit(&r->pf.seq, memory_order_acquire);
    if (q & 1u)
        return 0;
    const int n = atomic_load_explicit(&r->pf.n, memory_order_acquire);
    for (int i = 0; i < 2; i++) {
        lo[i] = atomic_load_explicit(&r->pf.lo[i], memory_order_acquire);
        hi[i] = atomic_load_explicit(&r->pf.hi[i], memory_order_acquire);
    }
    return atomic_load_explicit(&r->pf.seq, memory_order_relaxed) == q ? n : 0;
}

/* While the queue is full, the application's thread makes the next pages of the worker's
 * scene present (up to PF_STEP per call), ahead of the worker: on this VM the first touch of
 * fresh memory is most of the worker's time in the calls (docs/bench/rt_tuning.md,
 * 2026-12-06), so the thread that would wait takes part of it. 1 if it did some, 0 if
 * nothing is left to do. */
static int prefault_step(ws_rt *r)
{
    uintptr_t lo[2], hi[2];
    const int n = pf_read(r, lo, hi);
    for (int i = 0; i < n; i++) {
        const uintptr_t end = hi[i];
        const uintptr_t from = (lo[i] & ~(PF_STEP - 1)) + 2 * PF_STEP;
        const uintptr_t d = r->pf_done[i] <= end ? r->pf_done[i] : 0; /* beyond: another scene's */
        uintptr_t a = d > from ? d : from;
        if (a >= end)
            continue;
        uintptr_t e = (a & ~(PF_STEP - 1)) + PF_STEP;
        e = e < end ? e : end;
        r->pf_done[i] = e;
        if (gks_populate((const void *)a, e - a))
            return 1;
    }
    return 0;
}

/* Waits until every queued area is in its scene (the scenes are then as if each area had
 * been recorded at its call). Returns the first error of the worker since the last sync
 * (300 or 308) or 0; its areas are not counted. */
static int ws_rt_sync(ws_rt *r)
{
    if (r->queue) {
        ws_dlist_seal(r->dl); /* the chunk being filled to the queue */
        rt_serial_drain(r->queue);
        pf_publish(r, NULL); /* no worker at work now; its scenes may change */
        r->pf_done[0] = r->pf_done[1] = 0;
        ws_dlist_trim(r->dl); /* every chunk is in the scenes: freed (unless the classic
                                 renderer has records in it) */
        r->count -= r->wlost;
        r->wlost = 0;
        r->wvr = NULL;
    }
    return atomic_exchange(&r->werr, 0);
}

/* Stops the asynchronous recording (after a sync); it starts again at the next area. */
static void queue_stop(ws_rt *r)
{
    atomic_store(&r->werr, ws_rt_sync(r)); /* a worker's error stays to be reported */
    rt_serial_free(r->queue);
    r->queue = NULL;
    r->qtried = 0;
    ws_dlist_set_sink(r->dl, NULL, NULL);
    if (r->own_dl)
        ws_dlist_reset(r->dl); /* the render layer's list: reset at the frame boundary */
}

void ws_rt_reset(ws_rt *r)
{
    queue_stop(r);
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++) {
        rt_view_rec *vr = &r->view[v];
        rt_scene_free(vr->sc);
        gks_free(vr->smask);
        memset(vr, 0, sizeof *vr);
    }
    r->count = 0;
    atomic_store(&r->werr, 0);
}

void ws_rt_free(ws_rt *r)
{
    if (!r)
        return;
    ws_rt_reset(r);
    if (r->own_dl)
        ws_dlist_free(r->dl);
    gks_free(r->wxyz);
    gks_free(r);
}

int ws_rt_count(const ws_rt *r) { return r->count > INT_MAX ? INT_MAX : (int)r->count; }

void ws_rt_options(const ws_rt *r, rt_render_options *o) { *o = r->opts; }

void ws_rt_set_share_tiles(ws_rt *r, int on) { r->share_tiles = on != 0; }

static int clamp_view(int v) { return v >= 0 && v <= GKS_MAX_VIEW_IND ? v : 0; }

/* The attributes of prim into *a, field by field (rt_attr has no padding: its bytes are
 * compared by the display list). */
_Static_assert(sizeof(rt_attr) ==
                   sizeof(Grgb) + 2 * sizeof(Garea_props) + 2 * sizeof(int) + sizeof(uint64_t),
               "rt_attr has padding");
static void attr_set(rt_attr *a, const gks_prim *prim)
{
    a->colour = prim->colour;
    a->props[0] = prim->area_props[0];
    a->props[1] = prim->area_props[1];
    a->refl_eq[0] = prim->refl_eq[0];
    a->refl_eq[1] = prim->refl_eq[1];
    a->light_mask = prim->light_mask;
}

/* The attributes of prim. */
static rt_attr attr_of(const gks_prim *prim)
{
    rt_attr a;
    attr_set(&a, prim);
    return a;
}

static int same_attr(const rt_attr *a, const rt_attr *b)
{
    return a->colour.red == b->colour.red && a->colour.green == b->colour.green &&
           a->colour.blue == b->colour.blue && a->refl_eq[0] == b->refl_eq[0] &&
           a->refl_eq[1] == b->refl_eq[1] && a->light_mask == b->light_mask &&
           memcmp(&a->props[0], &b->props[0], sizeof a->props) == 0;
}

/* Tracer surface of one side of attributes a (light mask set when traced). */
static void surface_of(const rt_attr *a, int side, rt_surface *s)
{
    const Garea_props *p = &a->props[side];
    rt_surface_default(s);
    s->refl_eq = a->refl_eq[side] - 1;
    if (s->refl_eq < RT_REFL_NONE || s->refl_eq > RT_REFL_SPECULAR)
        s->refl_eq = RT_REFL_NONE;
    s->ka = p->ambient_coef;
    s->kd = p->diffuse_coef;
    s->ks = p->specular_coef;
    s->diffuse[0] = a->colour.red;
    s->diffuse[1] = a->colour.green;
    s->diffuse[2] = a->colour.blue;
    s->specular[0] = p->specular_colr.red;
    s->specular[1] = p->specular_colr.green;
    s->specular[2] = p->specular_colr.blue;
    s->spec_exp = p->specular_exp;
    s->transparency = p->transpar_coef;
    s->refr_index = p->refr_index;
    s->light_mask = 0;
}

/* The GKS error for a tracer result: storage (RT_ERR_NOMEM, RT_ERR_LIMIT: an
 * implementation limit on items) is 300; data the tracer cannot use (RT_ERR_SINGULAR,
 * RT_ERR_ARG, RT_ERR_STATE) is 308, arithmetic error. */
static int gks_err_of_rt(int rc)
{
    if (rc >= 0)
        return 0;
    return rc == RT_ERR_NOMEM || rc == RT_ERR_LIMIT ? 300 : 308;
}

static int note_surface(rt_view_rec *vr, int id, uint64_t mask)
{
    if (gks_grow(&vr->smask, &vr->capsmask, (size_t)id + 1, sizeof *vr->smask))
        return 300;
    vr->smask[id] = mask;
    if ((size_t)id >= vr->nsmask)
        vr->nsmask = (size_t)id + 1;
    return 0;
}

/* The scene of view vi and the surfaces of attributes a in it (created when they differ from
 * the latest ones); *vrp NULL when the surfaces are not usable. Returns 0 or 300. */
static int view_surfaces(ws_rt *r, int vi, const rt_attr *a, rt_view_rec **vrp)
{
    rt_view_rec *vr = &r->view[vi];
    *vrp = NULL;
    if (!vr->sc) {
        vr->sc = rt_scene_new();
        if (!vr->sc)
            return 300;
        vr->f = vr->b = -1;
    }
    if (vr->f < 0 || !same_attr(&vr->last, a)) {
        rt_surface s;
        surface_of(a, 0, &s);
        int f = rt_scene_add_surface(vr->sc, &s);
        surface_of(a, 1, &s);
        int b = rt_scene_add_surface(vr->sc, &s);
        if (f < 0 || b < 0) /* values are checked at SET: only storage fails here */
            return gks_err_of_rt(f < 0 ? f : b);
        if (note_surface(vr, f, a->light_mask) || note_surface(vr, b, a->light_mask))
            return 300;
        vr->last = *a;
        vr->f = f;
        vr->b = b;
    }
    *vrp = vr;
    return 0;
}

static int display_volume(const gks_ws *ws, const Gview_rep3 *v, double b[6]);

/* The box (lo xyz, hi xyz) to which the polygons of view v beyond the tracer's coordinate
 * range are clipped: the display volume's VRC3 box enlarged 1000 times about its centre
 * (so reflections still see the polygon around it). 0 if that box is itself out of range
 * (a view mapping of enormous scale) or the view shows nothing. */
static int far_clip_box(const gks_ws *ws, const Gview_rep3 *v, double cb[6])
{
    double b[6], inv[4][4];
    if (!display_volume(ws, v, b) || gks_xform_invert(v->map_matrix, inv))
        return 0;
    double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (int k = 0; k < 8; k++) {
        const double c[3] = { b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)] };
        double q[3];
        if (!(gks_xform_point(inv, c, q) != 0.0))
            return 0;
        for (int j = 0; j < 3; j++) {
            lo[j] = fmin(lo[j], q[j]);
            hi[j] = fmax(hi[j], q[j]);
        }
    }
    double h = 0.0;
    for (int j = 0; j < 3; j++)
        h = fmax(h, 0.5 * (hi[j] - lo[j]));
    for (int j = 0; j < 3; j++) {
        double c = 0.5 * (lo[j] + hi[j]);
        cb[j] = c - 1000.0 * h;
        cb[3 + j] = c + 1000.0 * h;
        if (!(fabs(cb[j]) <= 0.25 * RT_COORD_MAX && fabs(cb[3 + j]) <= 0.25 * RT_COORD_MAX))
            return 0;
    }
    return h > 0.0;
}

/* Sutherland-Hodgman clip of the loops (counts, n_loops; points of st doubles, xyz first, then
 * vertex data interpolated alike) to box cb: the even-odd interior inside the box is kept
 * (the parts outside are replaced by paths on the box). Interpolation in long double, whose
 * range holds the difference of two doubles. Returns the new points (gks_alloc'ed) with
 * their counts in *out_counts (loops of fewer than 3 points left out) and *out_loops; NULL
 * + *out_loops 0 if nothing is left; NULL + 300. */
static double *clip_loops(const double *xyz, size_t st, const int *counts, int n_loops,
                          const double cb[6], int **out_counts, int *out_loops, int *err)
{
    double *res = NULL, *a = NULL, *b = NULL;
    int *rc = gks_alloc_array((size_t)n_loops, sizeof *rc);
    size_t nres = 0, capres = 0;
    int nl = 0;
    *err = 300;
    *out_loops = 0;
    if (!rc)
        return NULL;
    const double *src = xyz;
    for (int k = 0; k < n_loops; src += st * (size_t)counts[k], k++) {
        size_t m = (size_t)counts[k];
        gks_free(a);
        a = gks_alloc_array(m, st * sizeof *a);
        if (!a)
            goto fail;
        memcpy(a, src, m * st * sizeof *a);
        for (int f = 0; f < 6 && m >= 3; f++) {
            const int j = f % 3, upper = f >= 3;
            const double L = cb[f];
            b = gks_alloc_array(2 * m, st * sizeof *b); /* a half-space clip: <= 2m points */
            if (!b)
                goto fail;
            size_t o = 0;
            for (size_t i = 0; i < m; i++) {
                const double *p = a + st * i, *q = a + st * ((i + 1) % m);
                const int pin = upper ? p[j] <= L : p[j] >= L;
                const int qin = upper ? q[j] <= L : q[j] >= L;
                if (pin)
                    memcpy(b + st * o++, p, st * sizeof *b);
                if (pin != qin) {
                    long double t = ((long double)L - p[j]) / ((long double)q[j] - p[j]);
                    for (size_t c = 0; c < st; c++)
                        b[st * o + c] =
                            (double)(p[c] + t * ((long double)q[c] - (long double)p[c]));
                    b[st * o + j] = L;
                    o++;
                }
            }
            gks_free(a);
            a = b;
            b = NULL;
            m = o;
        }
        if (m < 3)
            continue;
        if (gks_grow(&res, &capres, nres + m, st * sizeof *res))
            goto fail;
        memcpy(res + st * nres, a, m * st * sizeof *a);
        nres += m;
        rc[nl++] = (int)m;
    }
    gks_free(a);
    *err = 0;
    if (nl == 0) {
        gks_free(rc);
        gks_free(res);
        return NULL;
    }
    *out_counts = rc;
    *out_loops = nl;
    return res;
fail:
    gks_free(a);
    gks_free(b);
    gks_free(res);
    gks_free(rc);
    return NULL;
}

/* A polygon (VRC3 points xyz, vertex data vd) beyond the tracer's coordinate range, clipped
 * to far_clip_box with its vertex data (normals renormalised) and recorded. 0, 300 or 308
 * (docs/RAYTRACING.md, "Coordinate range"). */
static int push_far_polygon(ws_rt *r, const gks_ws *ws, rt_view_rec *vr, const Gview_rep3 *v,
                            int n_loops, const int *counts, size_t n_pts, const double *xyz,
                            const rt_vertex_data *vd)
{
    double cb[6];
    if (!far_clip_box(ws, v, cb))
        return 308;
    const size_t st = 3 + (vd->normals ? 3 : 0) + (vd->colours ? 3 : 0);
    double *pk = gks_alloc_array(n_pts, st * sizeof *pk);
    if (!pk)
        return 300;
    for (size_t i = 0; i < n_pts; i++) {
        double *d = pk + st * i;
        memcpy(d, xyz + 3 * i, 3 * sizeof *d);
        if (vd->normals)
            memcpy(d + 3, vd->normals + 3 * i, 3 * sizeof *d);
        if (vd->colours)
            memcpy(d + st - 3, vd->colours + 3 * i, 3 * sizeof *d);
    }
    int *cc = NULL, nc = 0, err = 0;
    double *cp = clip_loops(pk, st, counts, n_loops, cb, &cc, &nc, &err);
    gks_free(pk);
    if (err || !cp)
        return err; /* 300, or nothing near the display volume: nothing to trace */
    size_t m = 0;
    for (int k = 0; k < nc; k++)
        m += (size_t)cc[k];
    double *cx = gks_alloc_array(m, 9 * sizeof *cx);
    int id = RT_ERR_NOMEM;
    if (cx) {
        double *cn = vd->normals ? cx + 3 * m : NULL, *ccol = vd->colours ? cx + 6 * m : NULL;
        for (size_t i = 0; i < m; i++) {
            const double *d = cp + st * i;
            memcpy(cx + 3 * i, d, 3 * sizeof *cx);
            if (cn) {
                const double l = sqrt(d[3] * d[3] + d[4] * d[4] + d[5] * d[5]);
                for (int k = 0; k < 3; k++)
                    cn[3 * i + k] = l > 0 && isfinite(l) ? d[3 + k] / l : 0.0;
            }
            if (ccol)
                memcpy(ccol + 3 * i, d + st - 3, 3 * sizeof *ccol);
        }
        const rt_vertex_data cvd = { cn, ccol };
        id = rt_scene_add_polygon_data(vr->sc, nc, cc, cx, &cvd, vr->f, vr->b);
    }
    gks_free(cx);
    gks_free(cp);
    gks_free(cc);
    if (id < 0)
        return gks_err_of_rt(id);
    r->count++;
    return 0;
}

/* The largest |v[i]| of n values (NaN ignored, as fmax does). */
static double max_abs(const double *v, size_t n)
{
    double big = 0.0;
    for (size_t i = 0; i < n; i++)
        if (fabs(v[i]) > big)
            big = fabs(v[i]);
    return big;
}

/* Records a polygon of n_loops loops (counts >= 3) with NDC3 points xyz (3 doubles each;
 * overwritten with their VRC3 images) in view vi; vn (NDC3 unit normals) and vc (colours),
 * 3 doubles per point each, or NULL; vn is overwritten with the VRC3 normals (the inverse
 * transpose of the view orientation, renormalised). */
static int push_polygon(ws_rt *r, const gks_ws *ws, const rt_attr *a, int vi, int n_loops,
                        const int *counts, size_t n_pts, double *xyz, double *vn,
                        const double *vc)
{
    rt_view_rec *vr;
    int e = view_surfaces(r, vi, a, &vr);
    if (e || !vr)
        return e;
    const Gview_rep3 *v = &ws->views[vi];
    ws_vrc_points(v->ori_matrix, xyz, n_pts, xyz);
    double nm[3][3];
    if (vn && gks_xform_normal_matrix(v->ori_matrix, nm))
        vn = NULL; /* a singular view orientation: no usable normals */
    for (size_t i = 0; vn && i < n_pts; i++) { /* a degenerate normal adds nothing */
        double *q = vn + 3 * i;
        gks_xform_normal(nm, q, q);
    }
    const rt_vertex_data vd = { vn, vc };
    /* Beyond the tracer's range (it would drop the polygon, the classic modes draw it):
     * clipped to a box around the display volume. Other polygons go in unchanged. */
    if (max_abs(xyz, 3 * n_pts) > RT_COORD_MAX)
        return push_far_polygon(r, ws, vr, v, n_loops, counts, n_pts, xyz, &vd);
    int id = rt_scene_add_polygon_data(vr->sc, n_loops, counts, xyz, &vd, vr->f, vr->b);
    if (id < 0)
        return gks_err_of_rt(id);
    r->count++;
    return 0;
}

/* Records a cell array P, Q, R (NDC3) of nx x ny colours, row j at cells[j*stride]. */
static int push_cells(ws_rt *r, const gks_ws *ws, const rt_attr *a, int vi, const double P[3],
                      const double Q[3], const double R[3], int nx, int ny, const Grgb *cells,
                      size_t stride)
{
    size_t nc = (size_t)nx * (size_t)ny;
    if (nc > (size_t)INT32_MAX / 3)
        return 300;
    rt_view_rec *vr;
    int e = view_surfaces(r, vi, a, &vr);
    if (e || !vr)
        return e;
    float *rgb = gks_alloc_array(nc, 3 * sizeof *rgb);
    if (!rgb)
        return 300;
    const Gview_rep3 *v = &ws->views[vi];
    double c[3][3];
    const double *in[3] = { P, Q, R };
    for (int k = 0; k < 3; k++)
        ws_vrc_point(v->ori_matrix, in[k][0], in[k][1], in[k][2], c[k]);
    /* a cell array beyond the tracer's coordinate range (its fourth corner P + Q - R
     * included) is not clipped: 308 instead of a silent omission (docs/RAYTRACING.md) */
    for (int k = 0; k < 3; k++)
        if (!(fabs(c[0][k]) <= 0.5 * RT_COORD_MAX && fabs(c[1][k]) <= 0.5 * RT_COORD_MAX &&
              fabs(c[2][k]) <= 0.5 * RT_COORD_MAX)) {
            gks_free(rgb);
            return 308;
        }
    float *d = rgb;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            const Grgb *s = &cells[(size_t)j * stride + (size_t)i];
            /* non-finite colours cannot come from the colour table; 0 keeps the tracer safe */
            d[0] = isfinite(s->red) ? (float)s->red : 0.0f;
            d[1] = isfinite(s->green) ? (float)s->green : 0.0f;
            d[2] = isfinite(s->blue) ? (float)s->blue : 0.0f;
            d += 3;
        }
    int id = rt_scene_add_cell_array(vr->sc, c[0], c[1], c[2], nx, ny, rgb, vr->f, vr->b);
    gks_free(rgb);
    if (id < 0)
        return gks_err_of_rt(id);
    r->count++;
    return 0;
}

/* 1 if prim's loops are a consistent FILL AREA (SET) record of 3 or more points (counts not
 * negative, summing to n_points), with *total its points; 0: nothing traceable. */
static int area_points(const gks_prim *prim, size_t *total)
{
    if (prim->n_points < 3 || prim->n_loops < 1 || !prim->loop_counts || !prim->pts)
        return 0;
    *total = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        if (prim->loop_counts[k] < 0)
            return 0;
        *total += (size_t)prim->loop_counts[k];
    }
    return *total == (size_t)prim->n_points;
}

/* prim's loops of 3 or more points (fewer enclose nothing, even-odd rule: left out) into
 * counts and their points into xyz, with their normals into vn and colours into vc where
 * those are not NULL (3 doubles per point each). Returns the loops kept, *np their points. */
static int gather_loops(const gks_prim *prim, int *counts, double *xyz, double *vn, double *vc,
                        size_t *np)
{
    int nl = 0;
    size_t src = 0;
    *np = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        if (m >= 3) {
            counts[nl++] = (int)m;
            for (size_t i = 0; i < m; i++, ++*np) {
                const Gpoint3 *p = &prim->pts[src + i];
                double *o = xyz + 3 * *np;
                o[0] = p->x, o[1] = p->y, o[2] = p->z;
                if (vn) {
                    const Gvec3 *q = &prim->vnormals[src + i];
                    o = vn + 3 * *np;
                    o[0] = q->delta_x, o[1] = q->delta_y, o[2] = q->delta_z;
                }
                if (vc) {
                    const Grgb *q = &prim->vcolours[src + i];
                    o = vc + 3 * *np;
                    o[0] = q->red, o[1] = q->green, o[2] = q->blue;
                }
            }
        }
        src += m;
    }
    return nl;
}

static int record_fill_area(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    size_t total;
    if (!area_points(prim, &total))
        return 0; /* inconsistent record: nothing traceable */
    /* Interior shading method COLOUR or NORMAL on either side: the vertex colours and
     * normals are interpolated and shaded per ray (the tracer's equivalent of both methods;
     * docs/RAYTRACING.md); NONE: the facet's colour and plane. */
    const int smooth = prim->shading[0] > GSHAD_NONE || prim->shading[1] > GSHAD_NONE;
    const int has_n = smooth && prim->vnormals, has_c = smooth && prim->vcolours;
    const int on_stack = total <= STACK_POINTS;
    double sxyz[3 * STACK_POINTS], sn[3 * STACK_POINTS], sc[3 * STACK_POINTS];
    int scounts[4];
    int *counts = (size_t)prim->n_loops <= sizeof scounts / sizeof scounts[0]
                      ? scounts
                      : gks_alloc_array((size_t)prim->n_loops, sizeof *counts);
    double *xyz = on_stack ? sxyz : gks_alloc_array(total, 3 * sizeof *xyz);
    double *vn = !has_n ? NULL : on_stack ? sn : gks_alloc_array(total, 3 * sizeof *vn);
    double *vc = !has_c ? NULL : on_stack ? sc : gks_alloc_array(total, 3 * sizeof *vc);
    int err = 300;
    if (counts && xyz && (vn || !has_n) && (vc || !has_c)) {
        size_t np;
        const int nl = gather_loops(prim, counts, xyz, vn, vc, &np);
        rt_attr a = attr_of(prim);
        err = nl ? push_polygon(r, ws, &a, clamp_view(prim->view_ind), nl, counts, np, xyz,
                                vn, vc)
                 : 0;
    }
    if (counts != scounts)
        gks_free(counts);
    if (!on_stack) {
        gks_free(xyz);
        gks_free(vn);
        gks_free(vc);
    }
    return err;
}

static int inside_box(const double p[3], const double b[6])
{
    return p[0] >= b[0] && p[0] <= b[1] && p[1] >= b[2] && p[1] <= b[3] && p[2] >= b[4] &&
           p[2] <= b[5];
}

/* Corner (i, j) of the cell grid: P + (i/nx)(R - P) + (j/ny)(Q - R). */
static void cell_corner(const double P[3], const double U[3], const double V[3], int nx, int ny,
                        int i, int j, double o[3])
{
    double a = (double)i / nx, b = (double)j / ny;
    for (int k = 0; k < 3; k++)
        o[k] = P[k] + a * U[k] + b * V[k];
}

/* Sutherland-Hodgman clip of a convex polygon (n <= 4 points, room for 10) by box b. */
static int clip_to_box(double (*p)[3], int n, const double b[6])
{
    double tmp[10][3];
    for (int f = 0; f < 6 && n > 0; f++) {
        int ax = f / 2, hi = f % 2;
        int m = 0;
        for (int i = 0; i < n; i++) {
            const double *a = p[i], *c = p[(i + 1) % n];
            double da = hi ? b[f] - a[ax] : a[ax] - b[f];
            double dc = hi ? b[f] - c[ax] : c[ax] - b[f];
            if (da >= 0)
                memcpy(tmp[m++], a, sizeof tmp[0]);
            if ((da >= 0) != (dc >= 0)) {
                double t = da / (da - dc);
                for (int k = 0; k < 3; k++)
                    tmp[m][k] = a[k] + t * (c[k] - a[k]);
                m++;
            }
        }
        n = m;
        memcpy(p, tmp, (size_t)n * sizeof tmp[0]);
    }
    return n;
}

/* A CELL ARRAY clipped by its NDC3 clip box: per row, the run of cells inside the box as a
 * one-row cell array, the cells crossing the boundary as clipped polygons of their colour. */
static int record_cells_clipped(ws_rt *r, const gks_ws *ws, const gks_prim *prim,
                                const double P[3], const double U[3], const double V[3])
{
    const double *b = prim->clip_box;
    int nx = prim->cell_nx, ny = prim->cell_ny;
    const rt_attr base = attr_of(prim);
    const int vi = clamp_view(prim->view_ind);
    for (int j = 0; j < ny; j++) {
        int run = -1;
        for (int i = 0; i <= nx; i++) {
            int inside = 0;
            double c[4][3];
            if (i < nx) {
                cell_corner(P, U, V, nx, ny, i, j, c[0]);
                cell_corner(P, U, V, nx, ny, i + 1, j, c[1]);
                cell_corner(P, U, V, nx, ny, i + 1, j + 1, c[2]);
                cell_corner(P, U, V, nx, ny, i, j + 1, c[3]);
                inside = inside_box(c[0], b) && inside_box(c[1], b) && inside_box(c[2], b) &&
                         inside_box(c[3], b);
            }
            if (inside && run < 0)
                run = i;
            if (!inside && run >= 0) { /* flush the run [run, i) */
                double p0[3], r0[3], q0[3];
                cell_corner(P, U, V, nx, ny, run, j, p0);
                cell_corner(P, U, V, nx, ny, i, j, r0);
                cell_corner(P, U, V, nx, ny, i, j + 1, q0);
                int e = push_cells(r, ws, &base, vi, p0, q0, r0, i - run, 1,
                                   prim->cells + (size_t)j * (size_t)nx + (size_t)run,
                                   (size_t)nx);
                if (e)
                    return e;
                run = -1;
            }
            if (inside || i == nx)
                continue;
            double poly[10][3];
            memcpy(poly, c, sizeof c);
            int n = clip_to_box(poly, 4, b);
            if (n < 3)
                continue;
            rt_attr a = base;
            a.colour = prim->cells[(size_t)j * (size_t)nx + (size_t)i];
            int e = push_polygon(r, ws, &a, vi, 1, &n, (size_t)n, &poly[0][0], NULL, NULL);
            if (e)
                return e;
        }
    }
    return 0;
}

static int record_cells(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    int nx = prim->cell_nx, ny = prim->cell_ny;
    if (nx < 1 || ny < 1 || !prim->cells)
        return 0;
    if ((size_t)nx > (size_t)INT32_MAX / 3 / (size_t)ny)
        return 300; /* more colours than the recording can index */
    double P[3] = { prim->cell_p.x, prim->cell_p.y, prim->cell_p.z };
    double Q[3] = { prim->cell_q.x, prim->cell_q.y, prim->cell_q.z };
    double R[3] = { prim->cell_r.x, prim->cell_r.y, prim->cell_r.z };
    for (int k = 0; k < 3; k++)
        if (!isfinite(P[k]) || !isfinite(Q[k]) || !isfinite(R[k]))
            return 0;
    double S[3], U[3], V[3];
    for (int k = 0; k < 3; k++) {
        S[k] = P[k] + Q[k] - R[k];
        U[k] = R[k] - P[k];
        V[k] = Q[k] - R[k];
    }
    const double *b = prim->clip_box;
    if (!prim->clip ||
        (inside_box(P, b) && inside_box(Q, b) && inside_box(R, b) && inside_box(S, b)))
    {
        const rt_attr a = attr_of(prim);
        return push_cells(r, ws, &a, clamp_view(prim->view_ind), P, Q, R, nx, ny, prim->cells,
                          (size_t)nx);
    }
    if (!(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
        return 0; /* empty or NaN clip box: nothing visible */
    return record_cells_clipped(r, ws, prim, P, U, V);
}

/* ---- asynchronous recording ---------------------------------------------------------- */

/* n points p (3 doubles each) through the affine orientation rows ori into o, as
 * queue_points computes them (the same operations in the same order: the same values bit
 * for bit): ws_vrc_point_affine, with rows 0 and 1 in the two lanes of SSE2 registers. */
static void vrc_points_affine(const double (*ori)[4], const double *p, size_t n, double *o)
{
#if defined(__SSE2__)
    const __m128d c0 = _mm_set_pd(ori[1][0], ori[0][0]), c1 = _mm_set_pd(ori[1][1], ori[0][1]);
    const __m128d c2 = _mm_set_pd(ori[1][2], ori[0][2]), c3 = _mm_set_pd(ori[1][3], ori[0][3]);
    const double r0 = ori[2][0], r1 = ori[2][1], r2 = ori[2][2], r3 = ori[2][3];
    for (size_t i = 0; i < 3 * n; i += 3) {
        const double x = p[i], y = p[i + 1], z = p[i + 2];
        const __m128d o01 = _mm_add_pd(
            _mm_add_pd(_mm_add_pd(_mm_mul_pd(c0, _mm_set1_pd(x)), _mm_mul_pd(c1, _mm_set1_pd(y))),
                       _mm_mul_pd(c2, _mm_set1_pd(z))),
            c3);
        _mm_storeu_pd(o + i, o01);
        o[i + 2] = r0 * x + r1 * y + r2 * z + r3;
    }
#else
    for (size_t i = 0; i < 3 * n; i += 3)
        ws_vrc_point_affine(ori, p[i], p[i + 1], p[i + 2], o + i);
#endif
}

/* The worker's side: the tracer's records of a sealed chunk of the display list into the
 * views' scenes (the classic renderer's records in it are skipped), then the chunk released. rt_serial runs the chunks one at a time in queue order, so
 * the scenes get the areas in call order, with the surfaces the synchronous path would have
 * made (view_surfaces makes new ones only when the attributes differ from the view's latest). */
static void rec_run(void *user, void *item)
{
    ws_rt *r = user;
    ws_dl_chunk *c = item;
    size_t attr = SIZE_MAX;
    int view = -1;
    rt_qattr qa;
    double sxyz[3 * STACK_POINTS];
    for (size_t k = 0; k < c->n_rec; k++) {
        const ws_dl_rec *h = &c->rec[k];
        if (h->reader != WS_DL_TRACER)
            continue;
        int e = 0;
        if (h->attr != attr || h->view != view) {
            memcpy(&qa, c->attr + h->attr, sizeof qa);
            attr = h->attr;
            view = h->view;
            e = view_surfaces(r, view, &qa.a, &r->wvr);
        }
        rt_view_rec *vr = r->wvr;
        const rt_vertex_data vd = {
            h->flags & WS_DL_NORMALS ? c->nrm + 3 * (size_t)h->vtx : NULL,
            h->flags & WS_DL_COLOURS ? c->rgb + 3 * (size_t)h->vtx : NULL };
        const double *xyz = c->xyz + 3 * (size_t)h->vtx;
        if (h->kind == DL_POLY_NDC && vr) { /* NDC3 points: into VRC3 here */
            double *o = sxyz;
            if (h->n_vtx > STACK_POINTS) {
                o = r->wcap >= h->n_vtx || !gks_grow(&r->wxyz, &r->wcap, h->n_vtx,
                                                     3 * sizeof *r->wxyz)
                        ? r->wxyz
                        : NULL;
                if (!o)
                    vr = NULL; /* no storage: lost as if the scene had none */
            }
            if (o)
                vrc_points_affine((const double (*)[4])qa.ori, xyz, h->n_vtx, o);
            xyz = o;
        }
        const int *cnt = c->cnt + h->cnt;
        int id = !vr ? RT_ERR_NOMEM
                 : h->flags ? rt_scene_add_polygon_data(vr->sc, h->n_loops, cnt, xyz, &vd,
                                                        vr->f, vr->b)
                            : rt_scene_add_polygon(vr->sc, h->n_loops, cnt, xyz, vr->f, vr->b);
        if (id < 0) {
            e = e ? e : gks_err_of_rt(id);
            r->wlost++;
        }
        int none = 0;
        if (e)
            atomic_compare_exchange_strong(&r->werr, &none, e);
    }
    pf_publish(r, r->wvr ? r->wvr->sc : NULL);
    ws_dlist_release(c, WS_DL_TRACER);
}

/* The display list's sink: a sealed chunk with areas to the worker (one with only the
 * classic renderer's records stays where it is). */
static void queue_chunk(void *user, ws_dl_chunk *c)
{
    ws_rt *r = user;
    if (!(c->readers & WS_DL_TRACER))
        return;
    while (rt_serial_full(r->queue) && prefault_step(r))
        ;
    rt_serial_push(r->queue, c);
}

/* The queue of the asynchronous recording, started at the first area (rt_serial_new once:
 * with one thread, or no storage for it, it stays NULL and areas are recorded at the call). */
static rt_serial *queue_of(ws_rt *r)
{
    if (!r->queue && !r->qtried) {
        r->qtried = 1;
        r->queue = rt_serial_new(r->opts.threads, rec_run, r);
        if (r->queue)
            ws_dlist_set_sink(r->dl, queue_chunk, r);
    }
    return r->queue;
}

/* Whether prim is a FILL AREA (SET) for the queue (a consistent record): 1 with *nl loops
 * of 3 or more points and their *np points (nl > 0), and in *data the vertex data smooth
 * shading uses (WS_DL_NORMALS, WS_DL_COLOURS: interior shading method COLOUR or NORMAL on
 * either side, as record_fill_area decides), else 0. */
static int queue_countable(const gks_prim *prim, int *nl, size_t *np, unsigned *data)
{
    const int smooth = prim->shading[0] > GSHAD_NONE || prim->shading[1] > GSHAD_NONE;
    *data = (smooth && prim->vnormals ? WS_DL_NORMALS : 0u) |
            (smooth && prim->vcolours ? WS_DL_COLOURS : 0u);
    if (prim->n_points < 3 || prim->n_loops < 1 || !prim->loop_counts || !prim->pts)
        return 0;
    size_t total = 0;
    *nl = 0;
    *np = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        int m = prim->loop_counts[k];
        if (m < 0)
            return 0;
        total += (size_t)m;
        if (m >= 3) {
            ++*nl;
            *np += (size_t)m;
        }
    }
    return total == (size_t)prim->n_points && *nl > 0;
}

#if defined(__SSE2__)
/* queue_points for an affine ori (ws_vrc_affine): rows 0 and 1 of ws_vrc_point_affine in
 * the two lanes of SSE2 registers, row 2 alone, each lane with the same operations in the
 * same order (no fused multiply-add: baseline x86-64), so the points are the same bit for
 * bit; the matrix is loaded once (the stores into xyz could alias it for the compiler).
 * _mm_max_pd(a, big) is a > big ? a : big per lane, as the scalar loop keeps its maximum
 * (a NaN leaves it). */
static int queue_points_affine(const gks_prim *prim, const double (*ori)[4], int *counts,
                               double *xyz)
{
    const __m128d c0 = _mm_set_pd(ori[1][0], ori[0][0]), c1 = _mm_set_pd(ori[1][1], ori[0][1]);
    const __m128d c2 = _mm_set_pd(ori[1][2], ori[0][2]), c3 = _mm_set_pd(ori[1][3], ori[0][3]);
    const double r0 = ori[2][0], r1 = ori[2][1], r2 = ori[2][2], r3 = ori[2][3];
    const __m128d sign = _mm_set1_pd(-0.0);
    __m128d big01 = _mm_setzero_pd();
    double big2 = 0.0;
    size_t src = 0, q = 0;
    int nl = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        if (m >= 3) {
            counts[nl++] = (int)m;
            for (size_t i = 0; i < m; i++, q += 3) {
                const Gpoint3 *p = &prim->pts[src + i];
                const double x = p->x, y = p->y, z = p->z;
                const __m128d o01 = _mm_add_pd(
                    _mm_add_pd(_mm_add_pd(_mm_mul_pd(c0, _mm_set1_pd(x)),
                                          _mm_mul_pd(c1, _mm_set1_pd(y))),
                               _mm_mul_pd(c2, _mm_set1_pd(z))),
                    c3);
                const double o2 = r0 * x + r1 * y + r2 * z + r3;
                _mm_storeu_pd(xyz + q, o01);
                xyz[q + 2] = o2;
                big01 = _mm_max_pd(_mm_andnot_pd(sign, o01), big01);
                const double a = fabs(o2);
                big2 = a > big2 ? a : big2;
            }
        }
        src += m;
    }
    double b[2];
    _mm_storeu_pd(b, big01);
    return b[0] > RT_COORD_MAX || b[1] > RT_COORD_MAX || big2 > RT_COORD_MAX;
}
#endif

/* prim's loops of 3 or more points into counts and their VRC3 points (view orientation ori,
 * as ws_vrc_points computes them) into xyz; returns whether their max_abs is above
 * RT_COORD_MAX. */
static int queue_points(const gks_prim *prim, const double (*ori)[4], int *counts, double *xyz)
{
    const int affine = ws_vrc_affine(ori);
#if defined(__SSE2__)
    if (affine) /* the common case in two lanes: see queue_points_affine */
        return queue_points_affine(prim, ori, counts, xyz);
#endif
    size_t src = 0, q = 0;
    double big = 0.0;
    int nl = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        if (m >= 3) {
            counts[nl++] = (int)m;
            for (size_t i = 0; i < m; i++, q += 3) { /* ws_vrc_points, one pass from the prim */
                const Gpoint3 *p = &prim->pts[src + i];
                double *o = xyz + q;
                if (affine)
                    ws_vrc_point_affine(ori, p->x, p->y, p->z, o);
                else
                    ws_vrc_point(ori, p->x, p->y, p->z, o);
                for (int j = 0; j < 3; j++) { /* a NaN leaves big as it is */
                    const double a = fabs(o[j]);
                    big = a > big ? a : big;
                }
            }
        }
        src += m;
    }
    return big > RT_COORD_MAX;
}

/* The vertex data of prim's loops of 3 or more points, as push_polygon has them: normals
 * (nrm, 3 doubles each, or NULL) by the normal matrix nm, colours (rgb, or NULL). */
static void queue_data(const gks_prim *prim, const double nm[3][3], double *nrm, double *rgb)
{
    size_t src = 0, q = 0;
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        for (size_t i = 0; m >= 3 && i < m; i++, q += 3) {
            if (nrm) {
                const Gvec3 *v = &prim->vnormals[src + i];
                const double d[3] = { v->delta_x, v->delta_y, v->delta_z };
                gks_xform_normal(nm, d, nrm + q);
            }
            if (rgb) {
                const Grgb *c = &prim->vcolours[src + i];
                rgb[q] = c->red, rgb[q + 1] = c->green, rgb[q + 2] = c->blue;
            }
        }
        src += m;
    }
}

/* The largest |coordinate| of a point that the affine orientation ori maps within
 * RT_COORD_MAX, rounding included: L with (row's |linear part| sum) L + |translation| <=
 * RT_COORD_MAX / 2 for every row, the factor 2 far above the rounding of the point's four
 * operations and of L itself; -1 (none) for an orientation that is not affine. */
static double ori_limit(const double (*ori)[4])
{
    if (!ws_vrc_affine(ori))
        return -1.0;
    double s = 0.0, t = 0.0;
    for (int i = 0; i < 3; i++) {
        s = fmax(s, fabs(ori[i][0]) + fabs(ori[i][1]) + fabs(ori[i][2]));
        t = fmax(t, fabs(ori[i][3]));
    }
    if (!(t <= 0.5 * RT_COORD_MAX))
        return -1.0;
    return s > 0.0 ? (0.5 * RT_COORD_MAX - t) / s : INFINITY;
}

/* prim's loops of 3 or more points into counts and their points as they are into xyz;
 * returns the largest |coordinate| among them (a NaN left out: the orientation makes all
 * three coordinates of such a point NaN, which the range check leaves out as well). */
static double queue_points_ndc(const gks_prim *prim, int *counts, double *xyz)
{
    size_t src = 0, q = 0;
    int nl = 0;
#if defined(__SSE2__)
    const __m128d sign = _mm_set1_pd(-0.0);
    __m128d big = _mm_setzero_pd(); /* _mm_max_pd(a, big): a > big ? a : big per lane */
#else
    double big = 0.0;
#endif
    for (int k = 0; k < prim->n_loops; k++) {
        size_t m = (size_t)prim->loop_counts[k];
        if (m >= 3) {
            counts[nl++] = (int)m;
            const double *p = &prim->pts[src].x;
            double *o = xyz + q;
            const size_t n = 3 * m;
            size_t i = 0;
#if defined(__SSE2__)
            for (; i + 4 <= n; i += 4) {
                const __m128d v0 = _mm_loadu_pd(p + i), v1 = _mm_loadu_pd(p + i + 2);
                _mm_storeu_pd(o + i, v0);
                _mm_storeu_pd(o + i + 2, v1);
                big = _mm_max_pd(_mm_andnot_pd(sign, v0), big);
                big = _mm_max_pd(_mm_andnot_pd(sign, v1), big);
            }
            for (; i < n; i++) { /* the upper lane 0 */
                const __m128d v = _mm_load_sd(p + i);
                _mm_store_sd(o + i, v);
                big = _mm_max_pd(_mm_andnot_pd(sign, v), big);
            }
#else
            for (; i < n; i++) {
                const double a = fabs(o[i] = p[i]);
                big = a > big ? a : big;
            }
#endif
            q += n;
        }
        src += m;
    }
#if defined(__SSE2__)
    double b[2];
    _mm_storeu_pd(b, big);
    return b[0] > b[1] ? b[0] : b[1];
#else
    return big;
#endif
}

/* The asynchronous path of a FILL AREA (SET): a record of the display list with its loops of
 * 3 or more points and their vertex data, made here on the caller's thread; a sealed chunk
 * goes to the queue. The points are mapped into VRC3 here when that is needed to know
 * whether they are in the tracer's range; else the worker maps them (DL_POLY_NDC). Returns
 * 1 (queued), 0 (not for this path: the caller records it synchronously, which also drops
 * what this path would drop) or 300. */
static int queue_fill_area(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    int nl;
    size_t np;
    unsigned data;
    if (!queue_of(r) || !queue_countable(prim, &nl, &np, &data))
        return 0;
    if (np > QUEUE_MAX_POINTS)
        return 0; /* a large area: synchronous */
    const int vi = clamp_view(prim->view_ind);
    const double (*ori)[4] = (const double (*)[4])ws->views[vi].ori_matrix;
    double nm[3][3];
    if ((data & WS_DL_NORMALS) && gks_xform_normal_matrix(ws->views[vi].ori_matrix, nm))
        data &= ~(unsigned)WS_DL_NORMALS; /* a singular view orientation: no usable normals */
    /* rt_qattr is made from the primitive's attributes and the view table alone: the
     * core's numbers for them (gks_prim.attr_gen, gks_ws.views_gen) give it a key, and the
     * record after one of the same key shares its attributes without making or comparing
     * them */
    uint64_t key = 0;
    if (prim->attr_gen && ws->views_gen) {
        if (prim->attr_gen != r->kattr || ws->views_gen != r->kviews) {
            r->kattr = prim->attr_gen;
            r->kviews = ws->views_gen;
            r->key = ++r->keys;
            r->klim = ori_limit(ori);
        }
        key = r->key;
    }
    /* points go as they are, for the worker, where the orientation surely keeps them in
     * range (checked when they are in the record: else mapped here, DL_POLY) */
    const int kind = key && r->klim >= 0.0 ? DL_POLY_NDC : DL_POLY;
    const ws_dl_need need = { .n_vtx = np, .flags = data, .n_loops = nl };
    ws_dl_put put;
    int e = key ? ws_dlist_append_keyed(r->dl, WS_DL_TRACER, kind, vi, key, NULL,
                                        sizeof(rt_qattr), &need, &put)
                : -1;
    if (e < 0) {
        rt_qattr a;
        attr_set(&a.a, prim);
        memcpy(a.ori, ori, sizeof a.ori);
        e = ws_dlist_append_keyed(r->dl, WS_DL_TRACER, kind, vi, key, &a, sizeof a, &need,
                                  &put);
    }
    if (e)
        return 300;
    if (kind != DL_POLY_NDC || !(queue_points_ndc(prim, put.loops, put.xyz) <= r->klim)) {
        put.rec->kind = DL_POLY;
        /* the VRC3 coordinates against the range, as the synchronous path checks their
         * max_abs */
        if (queue_points(prim, ori, put.loops, put.xyz)) {
            ws_dlist_unappend(r->dl);
            return 0; /* beyond the tracer's range: the synchronous path clips it */
        }
    }
    if (data)
        queue_data(prim, (const double (*)[3])nm, put.nrm, put.rgb);
    r->count++;
    return 1;
}

/* With two or more threads (GESC_RT_THREADS; 0: online CPUs) a FILL AREA (SET) goes to the
 * asynchronous recording (queue_fill_area): a record of the display list, whose sealed chunks
 * a worker of the tracer's thread pool adds to the views' scenes while the application goes
 * on. Everything else (cell arrays, meshes, areas beyond the coordinate range, areas of more
 * than QUEUE_MAX_POINTS points), UPDATE, the ESCAPEs
 * and the reset first wait for the queued areas (ws_rt_sync), so every scene holds the same
 * primitives in the same order as with one thread. The checks that decide an area's fate
 * are made here at the call; only a storage failure of the worker comes later: it is reported
 * (300) by the next area or frame of this workstation, that area not recorded. */
static int record_sync(ws_rt *r, const gks_ws *ws, const gks_prim *prim);

int ws_rt_record(ws_rt *r, const gks_ws *ws, const gks_prim *prim)
{
    if (prim->kind == GKS_PRIM_FILL_AREA) {
        if (atomic_load_explicit(&r->werr, memory_order_relaxed))
            return ws_rt_sync(r);
        int q = queue_fill_area(r, ws, prim);
        if (q)
            return q == 1 ? 0 : q;
    }
    return record_sync(r, ws, prim);
}

/* ws_rt_record's synchronous path (apart, so that the queued area's call has no frame of
 * its own). */
__attribute__((noinline)) static int record_sync(ws_rt *r, const gks_ws *ws,
                                                 const gks_prim *prim)
{
    int se = ws_rt_sync(r);
    if (se)
        return se;
    rt_view_rec *vr = &r->view[clamp_view(prim->view_ind)];
    const int n0 = rt_scene_count(vr->sc);
    const size_t count = r->count;
    int err = 0;
    if (prim->kind == GKS_PRIM_FILL_AREA)
        err = record_fill_area(r, ws, prim);
    else if (prim->kind == GKS_PRIM_CELL_ARRAY)
        err = record_cells(r, ws, prim);
    if (err && vr->sc) { /* as if the call never happened (a clipped cell array records
                            several primitives) */
        rt_scene_truncate(vr->sc, n0);
        r->count = count;
    }
    return err;
}

/* ---- meshes kept whole (the driver entry mesh, ws_driver.h) ------------------------- */

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* The triangles of mesh m's triangle and quadrilateral facets, counted (tri NULL) or written
 * to tri (3 vertex indices each): a triangle facet as it is, a quadrilateral as two triangles
 * split at the diagonal that separates its other two corners (in the plane of its diagonals'
 * cross product, VRC3 points xyz; 0-2 when both or neither do, as for a non-planar or a
 * bow-tie quad), so that a concave quad is covered exactly. The other facets (more loops or
 * vertices) go as polygons (mesh_polygons). */
static size_t mesh_triangles(const gks_mesh *m, const double *xyz, uint32_t *tri)
{
    size_t nt = 0, loop = 0, i0 = 0;
    for (size_t f = 0; f < m->n_facets; f++) {
        const int nl = m->facet_loops[f];
        const int nv = nl == 1 ? m->loop_counts[loop] : 0;
        const int *ix = m->idx + i0;
        for (int k = 0; k < nl; k++)
            i0 += (size_t)m->loop_counts[loop + (size_t)k];
        loop += (size_t)nl;
        if (nv != 3 && nv != 4)
            continue;
        if (!tri) {
            nt += nv == 4 ? 2 : 1;
            continue;
        }
        uint32_t *t = tri + 3 * nt;
        int c[4] = { ix[0], ix[1], ix[2], nv == 4 ? ix[3] : 0 };
        if (nv == 4) { /* the diagonal 1-3 when 0-2 does not separate corners 1 and 3 */
            const double *p[4];
            double d02[3], d13[3], n[3], e1[3], e3[3], a[3], b[3];
            for (int k = 0; k < 4; k++)
                p[k] = xyz + 3 * (size_t)c[k];
            for (int k = 0; k < 3; k++) {
                d02[k] = p[2][k] - p[0][k];
                d13[k] = p[3][k] - p[1][k];
                e1[k] = p[1][k] - p[0][k];
                e3[k] = p[3][k] - p[0][k];
            }
            cross3(d02, d13, n);
            cross3(d02, e1, a);
            cross3(d02, e3, b);
            const double s1 = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
            const double s3 = b[0] * n[0] + b[1] * n[1] + b[2] * n[2];
            if ((s1 > 0.0 && s3 > 0.0) || (s1 < 0.0 && s3 < 0.0)) {
                int c0 = c[0];
                c[0] = c[1]; c[1] = c[2]; c[2] = c[3]; c[3] = c0; /* rotated: split at 1-3 */
            }
        }
        for (int k = 0; k < 3; k++)
            t[k] = (uint32_t)c[k];
        nt++;
        if (nv == 4) {
            t[3] = (uint32_t)c[0];
            t[4] = (uint32_t)c[2];
            t[5] = (uint32_t)c[3];
            nt++;
        }
    }
    return nt;
}

/* The facets of m other than triangles and quadrilaterals, each recorded as the FILL AREA
 * (SET) it would arrive as (record_fill_area, with the mesh's attributes and data). 0, 300
 * or 308. */
static int mesh_polygons(ws_rt *r, const gks_ws *ws, const gks_mesh *m)
{
    size_t loop = 0, i0 = 0, cap = 0, capc = 0;
    Gpoint3 *pts = NULL;
    Gvec3 *vn = NULL;
    Grgb *vc = NULL;
    int *counts = NULL, err = 0;
    for (size_t f = 0; f < m->n_facets && !err; f++) {
        const int nl = m->facet_loops[f];
        size_t nv = 0;
        for (int k = 0; k < nl; k++)
            nv += (size_t)m->loop_counts[loop + (size_t)k];
        if (nl > 1 || (nv != 3 && nv != 4)) {
            size_t c1 = cap, c2 = cap;
            if (gks_grow(&pts, &c1, nv, sizeof *pts) || gks_grow(&vn, &c2, nv, sizeof *vn) ||
                gks_grow(&vc, &cap, nv, sizeof *vc) ||
                gks_grow(&counts, &capc, (size_t)nl, sizeof *counts) || nv > INT32_MAX) {
                err = 300;
                break;
            }
            for (size_t i = 0; i < nv; i++) {
                const size_t j = (size_t)m->idx[i0 + i];
                pts[i] = (Gpoint3){ m->pts[j][0], m->pts[j][1], m->pts[j][2] };
                if (m->vnormals)
                    vn[i] = (Gvec3){ m->vnormals[j][0], m->vnormals[j][1], m->vnormals[j][2] };
                if (m->vcolours)
                    vc[i] = (Grgb){ m->vcolours[j][0], m->vcolours[j][1], m->vcolours[j][2] };
            }
            memcpy(counts, m->loop_counts + loop, (size_t)nl * sizeof *counts);
            gks_prim p = m->prim;
            p.n_loops = nl;
            p.loop_counts = counts;
            p.n_points = (int)nv;
            p.pts = pts;
            p.vnormals = m->vnormals ? vn : NULL;
            p.vcolours = m->vcolours ? vc : NULL;
            err = record_fill_area(r, ws, &p);
        }
        loop += (size_t)nl;
        i0 += nv;
    }
    gks_free(pts);
    gks_free(vn);
    gks_free(vc);
    gks_free(counts);
    return err;
}

/* The vertices of a mesh into the tracer's arrays (rt_scene_mesh_begin), in parts: VRC3
 * points by the view orientation ori, their largest |coordinate| per part, normals by the
 * normal matrix nm (has_n) and colours (has_c). */
typedef struct mesh_job {
    const gks_mesh *m;
    const double (*ori)[4];
    double nm[3][3];
    int has_n, has_c;
    rt_mesh_fill f;
    double big[RT_PARTS_MAX];
} mesh_job;

static void mesh_vertices(void *arg, int k, int n)
{
    mesh_job *j = arg;
    const gks_mesh *m = j->m;
    const size_t lo = m->n_verts / (size_t)n * (size_t)k, hi =
        k == n - 1 ? m->n_verts : m->n_verts / (size_t)n * (size_t)(k + 1);
    ws_vrc_points(j->ori, &m->pts[0][0] + 3 * lo, hi - lo, j->f.xyz + 3 * lo);
    j->big[k] = max_abs(j->f.xyz + 3 * lo, 3 * (hi - lo));
    for (size_t i = lo; i < hi; i++) {
        if (j->has_n) { /* a degenerate normal adds nothing */
            double q[3];
            gks_xform_normal(j->nm, m->vnormals[i], q);
            rt_mesh_store_normal(j->f.normals + 3 * i, q);
        }
        if (j->has_c)
            rt_mesh_store_colour(j->f.colours + 3 * i, m->vcolours[i]);
    }
}

/* The mesh's triangles into view vi's scene as one indexed mesh, written straight into the
 * tracer's arrays (rt_scene_mesh_begin): VRC3 points, normals and colours where the interior
 * shading method interpolates them, as record_fill_area takes them; then its other facets.
 * GKS_WS_MESH_FACETS when a point is beyond the tracer's coordinate range (the facets are
 * then clipped one by one). 0, 300 or 308. */
static int record_mesh(ws_rt *r, const gks_ws *ws, const gks_mesh *m)
{
    const gks_prim *prim = &m->prim;
    const int smooth = prim->shading[0] > GSHAD_NONE || prim->shading[1] > GSHAD_NONE;
    const int vi = clamp_view(prim->view_ind);
    const Gview_rep3 *v = &ws->views[vi];
    const size_t nv = m->n_verts;
    for (size_t i = 0; i < m->n_idx; i++) /* the core checked them (gks_area_data_check) */
        if (m->idx[i] < 0 || (size_t)m->idx[i] >= nv)
            return 308;
    const size_t nt = mesh_triangles(m, NULL, NULL);
    mesh_job j = { .m = m, .ori = (const double (*)[4])v->ori_matrix };
    j.has_n = smooth && m->vnormals && !gks_xform_normal_matrix(v->ori_matrix, j.nm);
    j.has_c = smooth && m->vcolours;
    rt_attr a = attr_of(prim);
    rt_view_rec *vr;
    int err = view_surfaces(r, vi, &a, &vr);
    if (err || !vr)
        return err;
    if (nt) {
        int rc = rt_scene_mesh_begin(vr->sc, nv, j.has_n, j.has_c, nt, &j.f);
        if (rc < 0)
            return gks_err_of_rt(rc);
        /* the vertices on the frame's threads when there are many (each one alone: the
         * same values for any number of parts) */
        if (nv >= 65536)
            rt_parallel_parts(r->opts.threads, mesh_vertices, &j);
        else
            mesh_vertices(&j, 0, 1);
        for (int k = 1; k < RT_PARTS_MAX; k++)
            j.big[0] = fmax(j.big[0], j.big[k]); /* parts not run left 0 */
        if (j.big[0] > RT_COORD_MAX)
            return GKS_WS_MESH_FACETS; /* the reservation is dropped */
        mesh_triangles(m, j.f.xyz, j.f.idx);
        int id = rt_scene_mesh_end(vr->sc, vr->f, vr->b);
        if (id < 0)
            return gks_err_of_rt(id);
        r->count++;
    }
    return mesh_polygons(r, ws, m);
}

int ws_rt_record_mesh(ws_rt *r, const gks_ws *ws, const gks_mesh *m)
{
    /* A colour per facet: a surface pair per facet, as before; a single facet shares
     * nothing: recorded as the FILL AREA (SET) it is, as before. */
    if (m->fcolours || m->n_facets < 2)
        return GKS_WS_MESH_FACETS;
    int se = ws_rt_sync(r);
    if (se)
        return se;
    rt_view_rec *vr = &r->view[clamp_view(m->prim.view_ind)];
    const int n0 = rt_scene_count(vr->sc);
    const size_t count = r->count;
    int err = record_mesh(r, ws, m);
    if (err > 0 && vr->sc) { /* as if the call never happened */
        rt_scene_truncate(vr->sc, n0);
        r->count = count;
    }
    return err;
}

/* Makes view vi's scene ready to trace: the workstation's lights its surfaces use (in
 * ascending light index; those the tracer rejects left out), the surfaces' masks in the
 * scene's light numbering, and the commit; with cull (clipped secondary rays) primitives
 * entirely outside cull's display volume are left out. Returns 0 or 300. */
static int prepare_scene(ws_rt *r, const gks_ws *ws, int vi, const rt_camera *cull)
{
    rt_view_rec *vr = &r->view[vi];
    rt_scene *sc = vr->sc;
    const Gmatrix3 *ori = &ws->views[vi].ori_matrix;
    uint64_t used = 0;
    for (size_t k = 0; k < vr->nsmask; k++)
        used |= vr->smask[k];
    rt_scene_clear_lights(sc);
    int bit[GKS_MAX_LIGHT_IND];
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++) {
        bit[i] = -1;
        if (!((used >> i) & 1) || !ws->light_defined[i])
            continue;
        rt_light l;
        ws_vrc_light(&ws->lights[i], *ori, &l);
        int id = rt_scene_add_light(sc, &l);
        if (id == RT_ERR_NOMEM)
            return 300;
        bit[i] = id; /* < 0: rejected by the tracer, left out */
    }
    for (size_t k = 0; k < vr->nsmask; k++) {
        uint64_t mask = 0;
        for (int i = 0; i < GKS_MAX_LIGHT_IND; i++)
            if (((vr->smask[k] >> i) & 1) && bit[i] >= 0)
                mask |= (uint64_t)1 << bit[i];
        rt_scene_set_surface_lights(sc, (int)k, mask);
    }
    rt_build_options bo;
    memset(&bo, 0, sizeof bo);
    bo.brute_threshold = -1; /* defaults */
    bo.threads = r->opts.threads; /* the build on the frame's threads (GESC_RT_THREADS) */
    bo.progress = r->opts.progress; /* the grid: the first set-up phase (GESC_RT_PROGRESS) */
    if (cull) {
        bo.ncull = 6;
        memcpy(bo.cull, cull->plane, sizeof bo.cull);
        bo.cull_eps = 2e-9 * cull->scale;
    }
    return gks_err_of_rt(rt_scene_commit(sc, &bo));
}

/* Display volume of view v: clip limits where on, intersected with the ws window. */
static int display_volume(const gks_ws *ws, const Gview_rep3 *v, double b[6])
{
    gks_limit3_array(&ws->cur_win, b);
    if (v->xy_clip == GIND_CLIP) {
        b[0] = fmax(b[0], v->clip_limit.x_min);
        b[1] = fmin(b[1], v->clip_limit.x_max);
        b[2] = fmax(b[2], v->clip_limit.y_min);
        b[3] = fmin(b[3], v->clip_limit.y_max);
    }
    if (v->back_clip == GIND_CLIP)
        b[4] = fmax(b[4], v->clip_limit.z_min);
    if (v->front_clip == GIND_CLIP)
        b[5] = fmin(b[5], v->clip_limit.z_max);
    return b[0] < b[1] && b[2] < b[3] && b[4] < b[5];
}

/* The composition's passes over a view's pixels, in parts by rows on the tracer's pool
 * (rt_parallel_parts: part k of n takes rows [k*rows/n, (k+1)*rows/n)); each pixel is
 * computed as on one thread, so the picture does not depend on the number of parts. */
typedef struct compose_job {
    gks_raster_fb *fb;
    const float *rgb;         /* the traced pixels (compose_part) */
    unsigned short *cnt;      /* their coverage counts (cnt_part sets them to 1) */
    int per, ix0, ix1, iy0, iy1, w, h;
    const double *bg;
    atomic_int differs;       /* background_part: a sample differs from bg */
} compose_job;

static void part_rows(int rows, int k, int n, int *r0, int *r1)
{
    *r0 = (int)((long long)rows * k / n);
    *r1 = (int)((long long)rows * (k + 1) / n);
}

/* part k of n of all_background: its sample rows of the rectangle */
static void background_part(void *arg, int k, int n)
{
    compose_job *j = arg;
    const gks_raster_fb *fb = j->fb;
    const float b[3] = { (float)j->bg[0], (float)j->bg[1], (float)j->bg[2] };
    int y0, y1;
    part_rows((j->iy1 - j->iy0) * fb->ss, k, n, &y0, &y1);
    for (int y = j->iy0 * fb->ss + y0; y < j->iy0 * fb->ss + y1; y++) {
        if (atomic_load_explicit(&j->differs, memory_order_relaxed))
            return; /* another part found one: the answer is known */
        const float *d = fb->rgb + 3 * ((size_t)y * (size_t)fb->w + (size_t)(j->ix0 * fb->ss));
        for (int x = j->ix0 * fb->ss; x < j->ix1 * fb->ss; x++, d += 3)
            if (d[0] != b[0] || d[1] != b[1] || d[2] != b[2]) {
                atomic_store_explicit(&j->differs, 1, memory_order_relaxed);
                return;
            }
    }
}

/* 1 if every sample of fb's pixels [ix0,ix1) x [iy0,iy1) has colour bg (j's rectangle). */
static int all_background(compose_job *j, int threads)
{
    atomic_init(&j->differs, 0);
    rt_parallel_parts(threads, background_part, j);
    return !atomic_load(&j->differs);
}

/* part k of n of the coverage counts of a view without other content: every pixel 1 */
static void cnt_part(void *arg, int k, int n)
{
    compose_job *j = arg;
    int r0, r1;
    part_rows(j->h, k, n, &r0, &r1);
    for (size_t q = (size_t)r0 * (size_t)j->w; q < (size_t)r1 * (size_t)j->w; q++)
        j->cnt[q] = 1;
}

static float clampf(double v, double hi) { return !(v > 0) ? 0.0f : v > hi ? (float)hi : (float)v; }

/* The pixels of view vi: its display volume's rectangle of fb, rounded to whole pixels,
 * px = { ix0, ix1, iy0, iy1 }, and the camera through them. 0: nothing of the view is
 * visible (empty volume or rectangle, singular mapping). */
static int view_pixels(const gks_ws *ws, const Gview_rep3 *v, const double wsm[4][4],
                       const gks_raster_fb *fb, int px[4], rt_camera *cam)
{
    double box[6];
    if (!display_volume(ws, v, box))
        return 0;
    double lo[3], hi[3];
    gks_xform_point(wsm, (const double[3]){ box[0], box[2], box[4] }, lo);
    gks_xform_point(wsm, (const double[3]){ box[1], box[3], box[5] }, hi);
    if (!(hi[0] > lo[0]) || !(hi[1] > lo[1]))
        return 0;
    int ix0 = (int)fmax(0, fmin(fb->width, round(lo[0])));
    int ix1 = (int)fmax(0, fmin(fb->width, round(hi[0])));
    int iy0 = (int)fmax(0, fmin(fb->height, round(lo[1])));
    int iy1 = (int)fmax(0, fmin(fb->height, round(hi[1])));
    if (ix1 <= ix0 || iy1 <= iy0)
        return 0;
    double sx = (box[1] - box[0]) / (hi[0] - lo[0]), sy = (box[3] - box[2]) / (hi[1] - lo[1]);
    double nb[6] = { box[0] + (ix0 - lo[0]) * sx, box[0] + (ix1 - lo[0]) * sx,
                     box[2] + (iy0 - lo[1]) * sy, box[2] + (iy1 - lo[1]) * sy, box[4], box[5] };
    px[0] = ix0;
    px[1] = ix1;
    px[2] = iy0;
    px[3] = iy1;
    return rt_camera_from_view(cam, v->map_matrix, nb, ix1 - ix0, iy1 - iy0) == RT_OK;
}

/* Composes rows [row0, row1) of the traced w x h pixels (rgb, rows top-first; cnt[k] of per
 * sample rays hit) into fb's pixels [ix0, ix0 + w) x [iy1 - h, iy1) (compose_part). rt rows are top-first; framebuffer
 * rows bottom-up, ss x ss samples per pixel. The traced colour T = a*H + (1-a)*bg for
 * coverage a: the pixel becomes a*clamp(H) + (1-a)*F over the framebuffer's F (exact for
 * unjittered samples). */
static void compose_rows(gks_raster_fb *fb, const float *rgb, const unsigned short *cnt,
                         int per, int ix0, int iy1, int w, int row0, int row1,
                         const double bg[3])
{
    for (int row = row0; row < row1; row++) {
        int j = iy1 - 1 - row;
        for (int c = 0; c < w; c++) {
            size_t k = (size_t)row * w + c;
            if (!cnt[k])
                continue;
            double a = (double)cnt[k] / per;
            float ah[3];
            for (int q = 0; q < 3; q++)
                ah[q] = clampf(rgb[3 * k + q] - (1 - a) * bg[q], a);
            int i = ix0 + c;
            for (int sj = 0; sj < fb->ss; sj++)
                for (int si = 0; si < fb->ss; si++) {
                    float *d = fb->rgb + 3 * ((size_t)(j * fb->ss + sj) * fb->w +
                                              (size_t)(i * fb->ss + si));
                    for (int q = 0; q < 3; q++)
                        d[q] = cnt[k] == per ? ah[q] : clampf(ah[q] + (1 - a) * d[q], 1);
                }
        }
    }
}

/* part k of n of compose_traced: its rows of the traced pixels */
static void compose_part(void *arg, int k, int n)
{
    compose_job *j = arg;
    int r0, r1;
    part_rows(j->h, k, n, &r0, &r1);
    compose_rows(j->fb, j->rgb, j->cnt, j->per, j->ix0, j->iy1, j->w, r0, r1, j->bg);
}

/* Traces view vi into its display volume's pixels of fb; adds the ray statistics to *st and
 * sets *traced when the tracer ran. Returns 0 or 300. */
static int render_view(ws_rt *r, const gks_ws *ws, int vi, const double wsm[4][4],
                       gks_raster_fb *fb, rt_stats *st, int *traced, int *fault)
{
    int px[4];
    rt_camera cam;
    if (!view_pixels(ws, &ws->views[vi], wsm, fb, px, &cam))
        return 0;
    const int ix0 = px[0], ix1 = px[1], iy0 = px[2], iy1 = px[3];
    int w = ix1 - ix0, h = iy1 - iy0;

    rt_scene *sc = r->view[vi].sc;
    int err = prepare_scene(r, ws, vi, r->opts.clip_secondary ? &cam : NULL);
    if (err)
        return err;
    rt_render_options o;
    ws_rt_options(r, &o); /* what the ESCAPEs set */
    /* rays that leave the scene see the workstation's background (colour index 0) */
    const double bg[3] = { ws->colr[0].red, ws->colr[0].green, ws->colr[0].blue };
    memcpy(o.background, bg, sizeof bg);
    const char *env = getenv("GKS3D_RT_PROGRESS");
    if (env && strcmp(env, "1") == 0)
        o.progress = 1;
    int assemble = 1; /* this process composes the traced pixels (rank 0 when shared) */
    int serialized = 0, rank = 0;
    void *link = r->share_tiles ? ws_mpi_link(&serialized, &rank) : NULL;
    void *mj = NULL;
    if (link) {
        if (!serialized)
            o.threads = 1; /* MPI calls from the calling thread only */
        assemble = rank == 0;
    }
    size_t n = (size_t)w * (size_t)h;
    float *rgb = gks_alloc_array(n, 3 * sizeof(float));
    unsigned short *cnt = gks_alloc_array(n, sizeof *cnt);
    int per = 1;
    rt_stats s;
    if (!rgb || !cnt) {
        err = 300;
        goto done;
    }
    /* Over a rectangle that is still all background the traced colour is the answer
     * (T = a*H + (1-a)*bg): coverage is needed only over other content. */
    /* The same decision on every MPI rank (the annotations are the same): the tiles'
     * payloads, which carry the coverage when it is asked for, agree. */
    compose_job cj = { .fb = fb, .rgb = rgb, .cnt = cnt, .ix0 = ix0, .ix1 = ix1, .iy0 = iy0,
                       .iy1 = iy1, .w = w, .h = h, .bg = bg };
    const int need_cover = !all_background(&cj, o.threads);
    if (!need_cover) {
        rt_parallel_parts(o.threads, cnt_part, &cj);
    } else {
        per = o.corner_rays ? 4 : o.samples;
    }
    if (link) {
        long nt = o.threads > 0 ? o.threads : sysconf(_SC_NPROCESSORS_ONLN);
        o.tiles = ws_mpi_frame_start(link, nt > 0 && nt < 256 ? (int)nt : 1, &mj);
    }
    tile_preview *tp = NULL;
    rt_tile_hook th;
    if (r->tile_fn && !o.tiles && (tp = gks_calloc_array(1, sizeof *tp))) {
        *tp = (tile_preview){ .r = r, .ix0 = ix0, .iy1 = iy1, .w = w, .h = h };
        th = (rt_tile_hook){ tp, preview_begin, preview_next, preview_done, preview_end };
        o.tiles = &th;
    }
    int rr = need_cover ? rt_render_cover(sc, &cam, &o, rgb, cnt, &s)
                        : rt_render(sc, &cam, &o, rgb, &s);
    gks_free(tp);
    if (link && ws_mpi_frame_end(link, mj))
        *fault = 305; /* reported after the frame is written */
    if (link && rr == RT_ERR_HOOK) { /* rank 0 went silent (ws_mpi.h) */
        err = 305;
        goto done;
    }
    if (rr != RT_OK) {
        err = gks_err_of_rt(rr);
        goto done;
    }
    rt_stats_add(st, &s);
    *traced = 1;
    if (assemble) { /* else the other ranks' pixels are rank 0's to compose */
        cj.per = per;
        rt_parallel_parts(o.threads, compose_part, &cj);
    }
done:
    gks_free(rgb);
    gks_free(cnt);
    return err;
}

int ws_rt_render(ws_rt *r, const gks_ws *ws, const double wsm[4][4], gks_raster_fb *fb)
{
    int se = ws_rt_sync(r);
    if (se)
        return se;
    if (!r->count)
        return 0;
    rt_stats sum;
    memset(&sum, 0, sizeof sum);
    int traced = 0, fault = 0;
    for (int vi = 0; vi <= GKS_MAX_VIEW_IND; vi++) {
        if (rt_scene_count(r->view[vi].sc) == 0)
            continue;
        int err = render_view(r, ws, vi, wsm, fb, &sum, &traced, &fault);
        if (err)
            return err;
    }
    if (traced)
        r->last = sum;
    return fault;
}

/* ---- ESCAPEs ------------------------------------------------------------------------- */

/* The escapes that set one integer option: ints[1] in [lo, hi]. */
static const struct int_escape {
    int id, lo, hi;
    size_t off;
} int_escapes[] = {
    { GESC_RT_CLIP_SECONDARY, 0, 1, offsetof(rt_render_options, clip_secondary) },
    { GESC_RT_MAX_DEPTH, 1, 64, offsetof(rt_render_options, max_depth) },
    { GESC_RT_THREADS, 0, 256, offsetof(rt_render_options, threads) },
    { GESC_RT_PROGRESS, 0, 1, offsetof(rt_render_options, progress) },
    { GESC_RT_SPD, 0, 1, offsetof(rt_render_options, corner_rays) },
};

static Gint sat_int(uint64_t v) { return v > (uint64_t)INT_MAX ? INT_MAX : (Gint)v; }

static int escape_stats(const ws_rt *r, Gescape_out_data *out)
{
    if (!out || !out->ints || !out->floats || out->num_ints < 8 || out->num_floats < 2)
        return 182;
    const rt_stats *s = &r->last;
    const uint64_t v[8] = { s->eye_rays, s->eye_hits, s->reflection_rays, s->refraction_rays,
                            s->shadow_rays, s->grid_cells, s->grid_refs, s->prims };
    for (int k = 0; k < 8; k++)
        out->ints[k] = sat_int(v[k]);
    out->floats[0] = s->build_seconds;
    out->floats[1] = s->render_seconds;
    out->num_ints = 8;
    out->num_floats = 2;
    return 0;
}

static int escape_samples(ws_rt *r, const Gescape_in_data *in)
{
    int s = in->ints[1];
    int jitter = in->num_ints >= 3 ? in->ints[2] : 0;
    if (s < 1 || s > 256 || jitter < 0 || jitter > 1)
        return 182;
    int m = 1;
    while (m * m < s)
        m++;
    if (m * m != s)
        return 182;
    r->opts.samples = s;
    r->opts.jitter = jitter;
    r->opts.corner_rays = 0; /* stratified samples per pixel instead of the corner rays */
    return 0;
}

int ws_rt_escape(ws_rt *r, int func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    queue_stop(r); /* queued areas in; the queue follows the (new) thread count */
    if (func_id > GESC_RT_CLIP_SECONDARY || func_id < GESC_RT_SPD)
        return 180;
    if (func_id == GESC_RT_STATS)
        return escape_stats(r, out);
    if (!in)
        return 182;
    if (func_id == GESC_RT_CUTOFF) {
        if (in->num_floats < 1 || !in->floats)
            return 182;
        double c = in->floats[0];
        if (!(c >= 0 && c < 1))
            return 182;
        r->opts.cutoff = c;
        return 0;
    }
    if (in->num_ints < 2 || !in->ints)
        return 182;
    if (func_id == GESC_RT_SAMPLES)
        return escape_samples(r, in);
    for (size_t k = 0; k < sizeof int_escapes / sizeof int_escapes[0]; k++) {
        const struct int_escape *e = &int_escapes[k];
        if (e->id != func_id)
            continue;
        if (in->ints[1] < e->lo || in->ints[1] > e->hi)
            return 182;
        *(int *)((char *)&r->opts + e->off) = in->ints[1];
        return 0;
    }
    return 180;
}

int ws_rt_file_escape(ws_rt *r, gks_ws *ws, int func_id, const Gescape_in_data *in,
                      Gescape_out_data *out, int frame, const char *ext, char **base)
{
    if (func_id <= GESC_RT_CLIP_SECONDARY && func_id >= GESC_RT_SPD)
        return ws_rt_escape(r, func_id, in, out);
    if (func_id != GESC_SET_FILE_NAME)
        return 180;
    return gks_ws_file_rename(ws, in->str, in->str_len, frame, ext, base);
}
