/* SPDX-License-Identifier: MIT */
/*
 * xform_clip.c -- clipping in homogeneous coordinates, before the division by w:
 * lines and polylines plane by plane, polygons with several loops (and per-vertex
 * attributes) by re-entrant Sutherland–Hodgman. The region is an intersection of
 * half-spaces p·X >= 0 plus w >= wmin.
 */
#include "gks_xform.h"
#include "xform_internal.h"

#include <math.h>
#include <string.h>

/* The axis tag of plane p (see gks_xform_clip.axis). */
static unsigned char plane_axis(const double p[4])
{
    if (p[1] == 0.0 && p[2] == 0.0 && p[0] != 0.0)
        return 1;
    if (p[0] == 0.0 && p[2] == 0.0 && p[1] != 0.0)
        return 2;
    if (p[0] == 0.0 && p[1] == 0.0 && p[2] != 0.0)
        return 3;
    return 0;
}

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
    c->axis[c->n] = plane_axis(p);
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
        /* finite, not zero, room checked above: cannot fail; axis tag i / 2 + 1 */
        if ((flags & bit) && gks_xform_clip_add_plane(c, planes[i]))
            return GKS_E_ARITHMETIC;
    }
    return 0;
}

/* A region filled by hand must still be sane: plane count in range, finite coefficients,
 * axis tags in range. */
static int region_ok(const gks_xform_clip *c)
{
    if (c->n < 0 || c->n > GKS_XFORM_MAX_PLANES || !isfinite(c->wmin) || c->wmin < 0.0)
        return 0;
    for (int i = 0; i < c->n; i++)
        if (c->axis[i] > 3)
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
    const int a = c->axis[k];
    if (a) /* the other terms are 0: the same value (up to the sign of a zero) */
        return p[a - 1] * x[a - 1] + p[3] * x[3];
    return p[0] * x[0] + p[1] * x[1] + p[2] * x[2] + p[3] * x[3];
}

/* r = a + t(b − a) for n values, exact at t = 0 and t = 1. */
static void lerp_n(const double *a, const double *b, double t, double *r, size_t n)
{
    if (t <= 0.0) {
        memcpy(r, a, n * sizeof *r);
        return;
    }
    if (t >= 1.0) {
        memcpy(r, b, n * sizeof *r);
        return;
    }
    for (size_t i = 0; i < n; i++)
        r[i] = a[i] + t * (b[i] - a[i]);
}

/* The crossing of segment a -> b (n values: the point, then any attributes) with the
 * plane of a constraint worth da at a and db at b (opposite signs or one of them 0),
 * interpolated from the end nearer to the plane (|d| smaller): the step t*(far - near)
 * then has |t| <= 1/2, so a far end at 1e30 cannot wipe out the near end's coordinates
 * (from the far end, t rounds to 1 and the "crossing" would be the near vertex itself,
 * off the plane by up to its whole distance). */
static void cross_n(const double *a, const double *b, double da, double db, double *r,
                    size_t n)
{
    if (fabs(da) <= fabs(db))
        lerp_n(a, b, da / (da - db), r, n);
    else
        lerp_n(b, a, db / (db - da), r, n);
}

/* Put the crossing r exactly on the plane of constraint k where that plane is a face of a
 * box (one non-zero coefficient among x, y, z: x_i = lim·w) or the w >= wmin test, so
 * that the clipped coordinate is the limit itself (w = 1: -(-lim)·1/1 = lim exactly). */
static void snap(const gks_xform_clip *c, int k, double r[4])
{
    if (c->wmin > 0.0) {
        if (k == 0) {
            r[3] = c->wmin;
            return;
        }
        k--;
    }
    const int a = c->axis[k] - 1;
    if (a >= 0)
        r[a] = -c->p[k][3] * r[3] / c->p[k][a];
}

int gks_xform_clip_segment(const gks_xform_clip *c, double a[4], double b[4], int *moved_a,
                           int *moved_b)
{
    *moved_a = *moved_b = 0;
    if (c->n < 0 || c->n > GKS_XFORM_MAX_PLANES || !(c->wmin >= 0.0))
        return 0; /* not a region */
    const int k = n_constraints(c);
    for (int i = 0; i < k; i++) {
        const double da = constraint(c, i, a), db = constraint(c, i, b);
        if (da < 0.0 && db < 0.0)
            return 0;
        if (da >= 0.0 && db >= 0.0)
            continue;
        if (!isfinite(da) || !isfinite(db) || !isfinite(da - db))
            return 0; /* overflow near DBL_MAX (or NaN): treated as not visible */
        double r[4];
        cross_n(a, b, da, db, r, 4);
        snap(c, i, r);
        if (!xform_finite_n(r, 4))
            return 0;
        if (da < 0.0) {
            memcpy(a, r, sizeof r);
            *moved_a = 1;
        } else {
            memcpy(b, r, sizeof r);
            *moved_b = 1;
        }
    }
    return 1;
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
        double a[4], b[4];
        int ma, mb;
        memcpy(a, pts[i], sizeof a);
        memcpy(b, pts[i + 1], sizeof b);
        if (!gks_xform_clip_segment(c, a, b, &ma, &mb)) {
            open = 0;
            continue;
        }
        if (!(open && !ma)) {                 /* start a new piece at a */
            if (no < out_cap)
                memcpy(out[no], a, sizeof a);
            no++;
            if (np < piece_cap)
                piece_len[np] = 1;
            np++;
        }
        if (no < out_cap)                     /* extend the piece to b */
            memcpy(out[no], b, sizeof b);
        no++;
        if (np - 1 < piece_cap)
            piece_len[np - 1]++;
        open = !mb;
    }
    *n_out = no;
    *n_pieces = np;
    return (no > out_cap || np > piece_cap) ? GKS_E_STORAGE_OVERFLOW : 0;
}

/* ---- re-entrant Sutherland–Hodgman ---------------------------------------------------- */

/* A vertex while clipping: the point, then the attributes (interpolated like the point). */
#define SH_MAXV (4 + GKS_XFORM_CLIP_MAX_ATTR)

typedef struct {
    int have_first;
    double first[SH_MAXV], prev[SH_MAXV];
    double first_d, prev_d;
} sh_stage;

typedef struct {
    const gks_xform_clip *c;
    int k;                                   /* number of constraints */
    size_t nv;                               /* values per vertex: 4 + attributes */
    sh_stage st[GKS_XFORM_MAX_PLANES + 1];
    double (*out)[4];
    double *out_attr;
    size_t cap, count;
    int bad;                                 /* a non-finite point was produced */
} sh_ctx;

static void sh_sink(sh_ctx *x, const double *p)
{
    if (!xform_finite_n(p, 4)) {
        x->bad = 1;
    } else if (x->count < x->cap) {
        memcpy(x->out[x->count], p, 4 * sizeof p[0]);
        if (x->nv > 4)
            memcpy(x->out_attr + x->count * (x->nv - 4), p + 4, (x->nv - 4) * sizeof p[0]);
    }
    x->count++;
}

/* Strict crossing: one end strictly inside, the other strictly outside (a vertex lying on
 * the plane is itself the crossing point and is emitted as a vertex). */
static int sh_crosses(double a, double b)
{
    return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
}

static void sh_push(sh_ctx *x, int s, const double *p);

/* A vertex copy, of fixed size for points alone (the common case, inlined). */
static void sh_copy(double *d, const double *p, size_t nv)
{
    if (nv == 4)
        memcpy(d, p, 4 * sizeof *p);
    else
        memcpy(d, p, nv * sizeof *p);
}

/* The crossing is put exactly on a box face (snap), as the segment clipper does: else a
 * far vertex (x = 1e250) left it an ulp outside, and the clipped polygon's boundary along
 * the face was then clipped away again as a polyline (issue 40 J: a HOLLOW area lost its
 * edge on the clip boundary). */
static void sh_emit_crossing(sh_ctx *x, int s, const double *a, double da, const double *b,
                             double db)
{
    double q[SH_MAXV];
    cross_n(a, b, da, db, q, x->nv);
    snap(x->c, s, q);
    sh_push(x, s + 1, q);
}

static void sh_push(sh_ctx *x, int s, const double *p)
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
        sh_copy(g->first, p, x->nv);
        g->first_d = d;
    } else if (sh_crosses(g->prev_d, d)) {
        sh_emit_crossing(x, s, g->prev, g->prev_d, p, d);
    }
    if (d >= 0.0)
        sh_push(x, s + 1, p);
    sh_copy(g->prev, p, x->nv);
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

int gks_xform_clip_polygon_attr(const gks_xform_clip *c, size_t nloops, const size_t *loop_len,
                                const double (*pts)[4], const double *attr, size_t na,
                                double (*out)[4], double *out_attr, size_t out_cap,
                                size_t *out_len, size_t *n_out)
{
    *n_out = 0;
    if (nloops == 0)
        return GKS_E_NPOINTS_INVALID;
    size_t total = 0;
    for (size_t l = 0; l < nloops; l++) {
        out_len[l] = 0;
        if (loop_len[l] < 3 || loop_len[l] > ((size_t)-1) / SH_MAXV - total)
            return GKS_E_NPOINTS_INVALID;
        total += loop_len[l];
    }
    if (na > GKS_XFORM_CLIP_MAX_ATTR || (na > 0 && (!attr || (out && !out_attr))))
        return GKS_E_NPOINTS_INVALID;
    if (!region_ok(c) || !xform_finite_n(&pts[0][0], total * 4))
        return GKS_E_ARITHMETIC;

    sh_ctx x;
    memset(&x, 0, sizeof x);
    x.c = c;
    x.k = n_constraints(c);
    x.nv = 4 + na;
    x.out = out;
    x.out_attr = out_attr;
    x.cap = out ? out_cap : 0;
    size_t base = 0;
    for (size_t l = 0; l < nloops; l++) {
        const size_t before = x.count;
        for (size_t i = 0; i < loop_len[l]; i++) {
            double v[SH_MAXV];
            memcpy(v, pts[base + i], 4 * sizeof v[0]);
            if (na)
                memcpy(v + 4, attr + (base + i) * na, na * sizeof v[0]);
            sh_push(&x, 0, v);
        }
        sh_close(&x, 0);
        base += loop_len[l];
        out_len[l] = x.count - before;
        if (x.bad)
            return GKS_E_ARITHMETIC;
    }
    *n_out = x.count;
    return (x.count > x.cap) ? GKS_E_STORAGE_OVERFLOW : 0;
}

int gks_xform_clip_polygon(const gks_xform_clip *c, size_t nloops, const size_t *loop_len,
                           const double (*pts)[4], double (*out)[4], size_t out_cap,
                           size_t *out_len, size_t *n_out)
{
    return gks_xform_clip_polygon_attr(c, nloops, loop_len, pts, NULL, 0, out, NULL, out_cap,
                                       out_len, n_out);
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
