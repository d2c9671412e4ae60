/* SPDX-License-Identifier: MIT */
/*
 * xform_clip.c -- clipping in homogeneous coordinates, before the division by w:
 * Liang–Barsky for lines and polylines, re-entrant Sutherland–Hodgman for polygons with
 * several loops. The region is an intersection of half-spaces p·X >= 0 plus w >= wmin.
 */
#include "gks_xform.h"
#include "xform_internal.h"

#include <math.h>
#include <string.h>

void gks_xform_clip_init(gks_xform_clip *c)
{
    memset(c, 0, sizeof *c);
    c->n = 0;
    c->wmin = GKS_XFORM_WMIN_DEFAULT;
}

int gks_xform_clip_add_plane(gks_xform_clip *c, const double p[4])
{
    if (!xform_finite_n(p, 4) || (p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0 && p[3] == 0.0))
        return GKS_E_ARITHMETIC;
    if (c->n < 0 || c->n >= GKS_XFORM_MAX_PLANES)
        return GKS_E_STORAGE_OVERFLOW;
    memcpy(c->p[c->n], p, sizeof c->p[0]);
    c->n++;
    return 0;
}

int gks_xform_clip_add_box(gks_xform_clip *c, const double box[6], unsigned flags)
{
    if (!xform_finite_n(box, 6) || !(box[0] < box[1]) || !(box[2] < box[3])
        || !(box[4] <= box[5]))
        return GKS_E_RECT_INVALID;
    int need = ((flags & GKS_XFORM_CLIP_XY) ? 4 : 0) + ((flags & GKS_XFORM_CLIP_BACK) ? 1 : 0)
               + ((flags & GKS_XFORM_CLIP_FRONT) ? 1 : 0);
    if (c->n < 0 || c->n + need > GKS_XFORM_MAX_PLANES)
        return GKS_E_STORAGE_OVERFLOW;
    const double planes[6][4] = {
        { 1, 0, 0, -box[0] }, { -1, 0, 0, box[1] },   /* x >= xmin, x <= xmax */
        { 0, 1, 0, -box[2] }, { 0, -1, 0, box[3] },   /* y >= ymin, y <= ymax */
        { 0, 0, 1, -box[4] },                         /* back:  z >= zmin */
        { 0, 0, -1, box[5] },                         /* front: z <= zmax */
    };
    for (int i = 0; i < 6; i++) {
        unsigned bit = (i < 4) ? GKS_XFORM_CLIP_XY
                               : (i == 4) ? GKS_XFORM_CLIP_BACK : GKS_XFORM_CLIP_FRONT;
        if (flags & bit)
            memcpy(c->p[c->n++], planes[i], sizeof planes[i]);
    }
    return 0;
}

int gks_xform_clip_add_box_mapped(gks_xform_clip *c, const double box[6], unsigned flags,
                                  const double b_to_a[4][4])
{
    gks_xform_clip t;
    gks_xform_clip_init(&t);
    int err = gks_xform_clip_add_box(&t, box, flags);
    if (err)
        return err;
    if (!xform_finite_n(&b_to_a[0][0], 16))
        return GKS_E_ARITHMETIC;
    if (c->n < 0 || c->n + t.n > GKS_XFORM_MAX_PLANES)
        return GKS_E_STORAGE_OVERFLOW;
    double q[GKS_XFORM_MAX_PLANES][4];
    for (int i = 0; i < t.n; i++) {
        gks_xform_plane_pullback(t.p[i], b_to_a, q[i]);
        double mx = 0.0;
        for (int j = 0; j < 4; j++)
            mx = fmax(mx, fabs(q[i][j]));
        if (!(mx > 0.0) || !isfinite(mx))
            return GKS_E_ARITHMETIC;
        for (int j = 0; j < 4; j++)
            q[i][j] /= mx;
    }
    memcpy(c->p[c->n], q, (size_t)t.n * sizeof q[0]);
    c->n += t.n;
    return 0;
}

/* A region filled by hand must still be sane: plane count in range, finite coefficients. */
static int region_ok(const gks_xform_clip *c)
{
    if (c->n < 0 || c->n > GKS_XFORM_MAX_PLANES || !isfinite(c->wmin) || c->wmin < 0.0)
        return 0;
    return xform_finite_n(&c->p[0][0], (size_t)c->n * 4);
}

/* Number of constraints: the w >= wmin test (index 0, if enabled) and the planes. */
static int n_constraints(const gks_xform_clip *c)
{
    return c->n + (c->wmin > 0.0 ? 1 : 0);
}

/* Signed value of constraint k at X (>= 0 inside); affine along a segment. */
static double constraint(const gks_xform_clip *c, int k, const double x[4])
{
    if (c->wmin > 0.0) {
        if (k == 0)
            return x[3] - c->wmin;
        k--;
    }
    const double *p = c->p[k];
    return p[0] * x[0] + p[1] * x[1] + p[2] * x[2] + p[3] * x[3];
}

/* r = a + t(b − a), exact at t = 0 and t = 1. */
static void lerp4(const double a[4], const double b[4], double t, double r[4])
{
    if (t <= 0.0) {
        memcpy(r, a, 4 * sizeof *r);
        return;
    }
    if (t >= 1.0) {
        memcpy(r, b, 4 * sizeof *r);
        return;
    }
    for (int i = 0; i < 4; i++)
        r[i] = a[i] + t * (b[i] - a[i]);
}

/* The crossing of segment a -> b with the plane of a constraint worth da at a and db at b
 * (opposite signs or one of them 0), interpolated from the end nearer to the plane (|d|
 * smaller): the step t*(far - near) then has |t| <= 1/2, so a far end at 1e30 cannot wipe
 * out the near end's coordinates (from the far end, t rounds to 1 and the "crossing" would
 * be the near vertex itself, off the plane by up to its whole distance). */
static void cross4(const double a[4], const double b[4], double da, double db, double r[4])
{
    if (fabs(da) <= fabs(db))
        lerp4(a, b, da / (da - db), r);
    else
        lerp4(b, a, db / (db - da), r);
}

/* A point on a segment p0 -> p1 as its parameter t from p0 and u = 1 - t from p1, each
 * computed directly (d0/(d0-d1) and d1/(d1-d0)), so that a point near either end keeps its
 * precision when the other end is far away (t = 1 - 6e-31 is 1 in double, u is not 0);
 * d: the constraint values at p0 and p1 that define the point (crossings only). */
typedef struct seg_par {
    double t, u;
    double d[2];
} seg_par;

/* a before b along the segment: compared where the parameters are accurate */
static int seg_before(const seg_par *a, const seg_par *b)
{
    if (a->t <= 0.5 || b->t <= 0.5)
        return a->t < b->t;
    return a->u > b->u;
}

/* Liang–Barsky on a validated region: the visible part runs from *lo to *hi (0 = p0 and
 * 1 = p1 when that end is not clipped). Returns 0 / 308; *vis as documented. */
static int clip_seg(const gks_xform_clip *c, const double p0[4], const double p1[4],
                    seg_par *lo, seg_par *hi, int *vis)
{
    *lo = (seg_par){ 0.0, 1.0, { 0.0, 0.0 } };
    *hi = (seg_par){ 1.0, 0.0, { 0.0, 0.0 } };
    const int k = n_constraints(c);
    *vis = 0;
    for (int i = 0; i < k; i++) {
        const double d0 = constraint(c, i, p0), d1 = constraint(c, i, p1);
        if (!isfinite(d0) || !isfinite(d1) || !isfinite(d0 - d1))
            return GKS_E_ARITHMETIC;
        if (d0 < 0.0 && d1 < 0.0)
            return 0;
        if (d0 < 0.0 || d1 < 0.0) { /* crossing: d0 - d1 != 0 */
            const seg_par x = { d0 / (d0 - d1), d1 / (d1 - d0), { d0, d1 } };
            if (d0 < 0.0 && seg_before(lo, &x))
                *lo = x;
            else if (d1 < 0.0 && seg_before(&x, hi))
                *hi = x;
        }
        if (!seg_before(lo, hi))
            return 0;
    }
    *vis = 1;
    return 0;
}

/* The point x: an unclipped end exactly, otherwise the crossing (cross4). */
static void seg_point(const double p0[4], const double p1[4], const seg_par *x, double q[4])
{
    if (x->t <= 0.0)
        memcpy(q, p0, 4 * sizeof *q);
    else if (x->u <= 0.0)
        memcpy(q, p1, 4 * sizeof *q);
    else
        cross4(p0, p1, x->d[0], x->d[1], q);
}

int gks_xform_clip_line(const gks_xform_clip *c, const double p0[4], const double p1[4],
                        double *t0, double *t1, int *visible)
{
    if (!region_ok(c) || !xform_finite_n(p0, 4) || !xform_finite_n(p1, 4))
        return GKS_E_ARITHMETIC;
    seg_par lo, hi;
    int err = clip_seg(c, p0, p1, &lo, &hi, visible);
    if (!err && *visible) {
        *t0 = lo.t;
        *t1 = hi.t;
    }
    return err;
}

int gks_xform_clip_polyline(const gks_xform_clip *c, size_t n, const double (*pts)[4],
                            double (*out)[4], size_t out_cap,
                            size_t *piece_len, size_t piece_cap,
                            size_t *n_out, size_t *n_pieces)
{
    *n_out = 0;
    *n_pieces = 0;
    if (n < 2 || n > ((size_t)-1) / 4)
        return GKS_E_NPOINTS_INVALID;
    if (!region_ok(c) || !xform_finite_n(&pts[0][0], n * 4))
        return GKS_E_ARITHMETIC;
    if (!out)
        out_cap = 0;
    if (!piece_len)
        piece_cap = 0;

    size_t no = 0, np = 0;
    int open = 0;   /* the last piece ends at pts[i] exactly (segment end not clipped) */
    for (size_t i = 0; i + 1 < n; i++) {
        double q[4];
        seg_par lo, hi;
        int vis;
        int err = clip_seg(c, pts[i], pts[i + 1], &lo, &hi, &vis);
        if (err)
            return err;
        if (!vis) {
            open = 0;
            continue;
        }
        if (!(open && lo.t == 0.0)) {         /* start a new piece at p(lo) */
            seg_point(pts[i], pts[i + 1], &lo, q);
            if (!xform_finite_n(q, 4))
                return GKS_E_ARITHMETIC;
            if (no < out_cap)
                memcpy(out[no], q, sizeof q);
            no++;
            if (np < piece_cap)
                piece_len[np] = 1;
            np++;
        }
        seg_point(pts[i], pts[i + 1], &hi, q); /* extend the piece to p(hi) */
        if (!xform_finite_n(q, 4))
            return GKS_E_ARITHMETIC;
        if (no < out_cap)
            memcpy(out[no], q, sizeof q);
        no++;
        if (np - 1 < piece_cap)
            piece_len[np - 1]++;
        open = (hi.u == 0.0);
    }
    *n_out = no;
    *n_pieces = np;
    return (no > out_cap || np > piece_cap) ? GKS_E_STORAGE_OVERFLOW : 0;
}

/* ---- re-entrant Sutherland–Hodgman ---------------------------------------------------- */

typedef struct {
    int have_first;
    double first[4], prev[4];
    double first_d, prev_d;
} sh_stage;

typedef struct {
    const gks_xform_clip *c;
    int k;                                   /* number of constraints */
    sh_stage st[GKS_XFORM_MAX_PLANES + 1];
    double (*out)[4];
    size_t cap, count;
    int bad;                                 /* a non-finite point was produced */
} sh_ctx;

static void sh_sink(sh_ctx *x, const double p[4])
{
    if (!xform_finite_n(p, 4))
        x->bad = 1;
    else if (x->count < x->cap)
        memcpy(x->out[x->count], p, 4 * sizeof p[0]);
    x->count++;
}

/* Strict crossing: one end strictly inside, the other strictly outside (a vertex lying on
 * the plane is itself the crossing point and is emitted as a vertex). */
static int sh_crosses(double a, double b)
{
    return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
}

static void sh_push(sh_ctx *x, int s, const double p[4]);

static void sh_emit_crossing(sh_ctx *x, int s, const double a[4], double da,
                             const double b[4], double db)
{
    double q[4];
    cross4(a, b, da, db, q);
    sh_push(x, s + 1, q);
}

static void sh_push(sh_ctx *x, int s, const double p[4])
{
    if (s == x->k) {
        sh_sink(x, p);
        return;
    }
    sh_stage *g = &x->st[s];
    const double d = constraint(x->c, s, p);
    if (!isfinite(d)) {
        x->bad = 1;
        return;
    }
    if (!g->have_first) {
        g->have_first = 1;
        memcpy(g->first, p, sizeof g->first);
        g->first_d = d;
    } else if (sh_crosses(g->prev_d, d)) {
        sh_emit_crossing(x, s, g->prev, g->prev_d, p, d);
    }
    if (d >= 0.0)
        sh_push(x, s + 1, p);
    memcpy(g->prev, p, sizeof g->prev);
    g->prev_d = d;
}

/* Close the loop at stage s (edge prev → first), then the following stages. */
static void sh_close(sh_ctx *x, int s)
{
    for (; s < x->k; s++) {
        sh_stage *g = &x->st[s];
        if (g->have_first && sh_crosses(g->prev_d, g->first_d))
            sh_emit_crossing(x, s, g->prev, g->prev_d, g->first, g->first_d);
        g->have_first = 0;
    }
}

int gks_xform_clip_polygon(const gks_xform_clip *c, size_t nloops, const size_t *loop_len,
                           const double (*pts)[4], double (*out)[4], size_t out_cap,
                           size_t *out_len, size_t *n_out)
{
    *n_out = 0;
    if (nloops == 0)
        return GKS_E_NPOINTS_INVALID;
    size_t total = 0;
    for (size_t l = 0; l < nloops; l++) {
        out_len[l] = 0;
        if (loop_len[l] < 3 || loop_len[l] > ((size_t)-1) / 4 - total)
            return GKS_E_NPOINTS_INVALID;
        total += loop_len[l];
    }
    if (!region_ok(c) || !xform_finite_n(&pts[0][0], total * 4))
        return GKS_E_ARITHMETIC;

    sh_ctx x;
    memset(&x, 0, sizeof x);
    x.c = c;
    x.k = n_constraints(c);
    x.out = out;
    x.cap = out ? out_cap : 0;
    size_t base = 0;
    for (size_t l = 0; l < nloops; l++) {
        const size_t before = x.count;
        for (size_t i = 0; i < loop_len[l]; i++)
            sh_push(&x, 0, pts[base + i]);
        sh_close(&x, 0);
        base += loop_len[l];
        out_len[l] = x.count - before;
        if (x.bad)
            return GKS_E_ARITHMETIC;
    }
    *n_out = x.count;
    return (x.count > x.cap) ? GKS_E_STORAGE_OVERFLOW : 0;
}

int gks_xform_divide(const double in[4], double out[3])
{
    if (!xform_finite_n(in, 4) || !(in[3] > 0.0))
        return GKS_E_ARITHMETIC;
    double r[3] = { in[0] / in[3], in[1] / in[3], in[2] / in[3] };
    if (!xform_finite_n(r, 3))
        return GKS_E_ARITHMETIC;
    memcpy(out, r, sizeof r);
    return 0;
}
