/* SPDX-License-Identifier: MIT */
/*
 * raster_line.c -- polylines (thin Bresenham fast path; wide lines as quads with round
 * joins), GKS linetypes continued across vertices, and polymarkers.
 */
#include "raster.h"
#include <math.h>

#define PI 3.14159265358979323846
#define SQRT1_2 0.70710678118654752440

/* On/off lengths (first is on) in units of max(1, width) output pixels. */
typedef struct dash { int n; double len[4]; } dash;
static const dash dash_tab[5] = {
    {0, {0}},
    {0, {0}},                /* 1 solid */
    {2, {8, 4}},             /* 2 dashed */
    {2, {2, 4}},             /* 3 dotted */
    {4, {8, 3, 2, 3}},       /* 4 dash-dotted */
};

typedef struct line_ctx {
    gks_raster_fb *fb;
    const gks_raster_line *attr;
    float rgb[3];
    double w;                 /* width, output pixels, >= 1 */
    int n_dash;               /* 0 = solid */
    double dash[4], period;   /* scaled by w */
    double phase;             /* pattern position at the current vertex, [0, period) */
} line_ctx;

static float clamp01(float v)
{
    if (!(v > 0.0f))
        return 0.0f;
    return v < 1.0f ? v : 1.0f;
}

/* Is the pattern on at phase ph; *left = distance to the next change. */
static int dash_on(const line_ctx *c, double ph, double *left)
{
    if (c->n_dash == 0) {
        *left = INFINITY;
        return 1;
    }
    ph = fmod(ph, c->period);
    if (!(ph >= 0.0))
        ph = 0.0;
    for (int k = 0; k < c->n_dash; k++) {
        if (ph < c->dash[k]) {
            *left = c->dash[k] - ph;
            return k % 2 == 0;
        }
        ph -= c->dash[k];
    }
    *left = c->dash[0]; /* rounding at the very end of the period */
    return 1;
}

static double phase_add(const line_ctx *c, double ph, double d)
{
    if (c->n_dash == 0)
        return 0.0;
    double r = fmod(ph + d, c->period);
    return isfinite(r) && r >= 0.0 ? r : 0.0;
}

/* Point of segment a-b on the boundary k of box {xmin, xmax, ymin, ymax}: that
 * coordinate exact, the other from the slope (so a huge segment clipped to the image
 * keeps its position), clamped into the box. */
static void boundary_point(const double a[2], const double b[2], const double box[4], int k,
                           double c[2])
{
    int ax = k / 2, o = 1 - ax;
    double slope = (0.5 * b[o] - 0.5 * a[o]) / (0.5 * b[ax] - 0.5 * a[ax]);
    c[ax] = box[k];
    c[o] = a[o] + (c[ax] - a[ax]) * slope;
    if (!(c[o] >= box[2 * o]))
        c[o] = box[2 * o];
    if (c[o] > box[2 * o + 1])
        c[o] = box[2 * o + 1];
}

/* Liang-Barsky clip of a + t(b - a) to box {xmin, xmax, ymin, ymax}; differences are
 * halved so that nothing overflows for any finite input. Gives the clipped end points
 * c0, c1 and their parameters t0, t1; 0 if nothing is left. */
static int clip_seg(const double a[2], const double b[2], const double box[4], double c0[2],
                    double c1[2], double *t0, double *t1)
{
    if (a[0] >= box[0] && a[0] <= box[1] && a[1] >= box[2] && a[1] <= box[3] &&
        b[0] >= box[0] && b[0] <= box[1] && b[1] >= box[2] && b[1] <= box[3]) {
        c0[0] = a[0]; c0[1] = a[1]; c1[0] = b[0]; c1[1] = b[1]; /* trivially inside */
        *t0 = 0.0;
        *t1 = 1.0;
        return 1;
    }
    double h[2] = {0.5 * b[0] - 0.5 * a[0], 0.5 * b[1] - 0.5 * a[1]};
    double lo = 0.0, hi = 1.0;
    int klo = -1, khi = -1;
    for (int k = 0; k < 4; k++) {
        int ax = k / 2;
        double p = k % 2 == 0 ? -h[ax] : h[ax];
        double q = k % 2 == 0 ? 0.5 * a[ax] - 0.5 * box[k] : 0.5 * box[k] - 0.5 * a[ax];
        if (p == 0.0) {
            if (q < 0.0)
                return 0;
            continue;
        }
        double r = q / p;
        if (p < 0.0) {
            if (r > lo) {
                lo = r;
                klo = k;
            }
        } else if (r < hi) {
            hi = r;
            khi = k;
        }
        if (lo > hi)
            return 0;
    }
    *t0 = lo;
    *t1 = hi;
    if (klo < 0) {
        c0[0] = a[0];
        c0[1] = a[1];
    } else {
        boundary_point(a, b, box, klo, c0);
    }
    if (khi < 0) {
        c1[0] = b[0];
        c1[1] = b[1];
    } else {
        boundary_point(a, b, box, khi, c1);
    }
    return 1;
}

static double lerp(double a, double b, double t)
{
    return (1.0 - t) * a + t * b;
}

/* Length of (dx, dy): sqrt when the squares cannot overflow (fast path), else hypot. */
static double length2(double dx, double dy)
{
    double ax = fabs(dx), ay = fabs(dy);
    if (ax < 1e150 && ay < 1e150)
        return sqrt(dx * dx + dy * dy);
    return hypot(dx, dy);
}

static void plot(const line_ctx *c, int x, int y, double z)
{
    gks_raster_fb *fb = c->fb;
    if (x < 0 || y < 0 || x >= fb->w || y >= fb->h)
        return;
    size_t i = (size_t)y * (size_t)fb->w + (size_t)x;
    gks_raster_zmode zm = c->attr->zmode;
    if (zm != GKS_RASTER_Z_NONE) {
        float zf = (float)z;
        if (!(zf + c->attr->zbias >= fb->z[i]))
            return;
        if (zf > fb->z[i])
            fb->z[i] = zf;
        if (zm == GKS_RASTER_Z_ONLY)
            return;
    }
    fb->rgb[3 * i] = c->rgb[0];
    fb->rgb[3 * i + 1] = c->rgb[1];
    fb->rgb[3 * i + 2] = c->rgb[2];
}

/* Pixel column (row) of a coordinate on an axis of n pixels. The display surface is
 * closed: a point on its right (top) boundary, v = n up to rounding, belongs to the last
 * pixel, so lines at NDC x = 1 or y = 1 are drawn like those at 0. */
static int edge_pixel(double v, int n)
{
    int i = (int)floor(v);
    return i == n && v <= n + 1e-9 * n ? n - 1 : i;
}

/* 1-pixel segment (ss == 1): Bresenham between the pixels holding the clipped end points. */
static void thin_segment(line_ctx *c, const gks_raster_pt *pa, const gks_raster_pt *pb,
                         int skip_first)
{
    double a[2] = {pa->x, pa->y}, b[2] = {pb->x, pb->y};
    double len = 2.0 * length2(0.5 * b[0] - 0.5 * a[0], 0.5 * b[1] - 0.5 * a[1]);
    double box[4] = {-1.0, c->fb->w + 1.0, -1.0, c->fb->h + 1.0}, t0, t1, p0[2], p1[2];
    double ph0 = c->phase;
    c->phase = phase_add(c, c->phase, len);
    if (!clip_seg(a, b, box, p0, p1, &t0, &t1))
        return;
    if (t0 > 0.0)
        skip_first = 0;
    double x0 = p0[0], y0 = p0[1], x1 = p1[0], y1 = p1[1];
    double za = lerp(pa->z, pb->z, t0), zb = lerp(pa->z, pb->z, t1);
    double cl = length2(x1 - x0, y1 - y0);
    double phs = phase_add(c, ph0, t0 * len);
    int ix = edge_pixel(x0, c->fb->w), iy = edge_pixel(y0, c->fb->h);
    int ex = edge_pixel(x1, c->fb->w), ey = edge_pixel(y1, c->fb->h);
    int dx = ex > ix ? ex - ix : ix - ex, dy = ey > iy ? ey - iy : iy - ey;
    int sx = ex > ix ? 1 : -1, sy = ey > iy ? 1 : -1;
    int n = dx > dy ? dx : dy, err = dx - dy;
    int simple = c->n_dash == 0 && c->attr->zmode == GKS_RASTER_Z_NONE;
    for (int k = 0; k <= n; k++) {
        if (!(k == 0 && skip_first)) {
            double t = n ? (double)k / n : 0.0, left;
            if (simple || dash_on(c, phs + t * cl, &left))
                plot(c, ix, iy, za + (zb - za) * t);
        }
        int e2 = 2 * err;
        if (e2 > -dy) {
            err -= dy;
            ix += sx;
        }
        if (e2 < dx) {
            err += dx;
            iy += sy;
        }
    }
}

static int fill_tris(line_ctx *c, const gks_raster_pt *t, size_t n)
{
    gks_raster_fill f = {.style = GKS_RASTER_SOLID, .zmode = c->attr->zmode,
                         .zbias = c->attr->zbias};
    f.rgb[0] = c->rgb[0]; f.rgb[1] = c->rgb[1]; f.rgb[2] = c->rgb[2];
    return gks_raster_triangles(c->fb, n, t, NULL, &f);
}

/* Quad of width w around p -> q. */
static int quad(line_ctx *c, const gks_raster_pt *p, const gks_raster_pt *q, double ux,
                double uy)
{
    double nx = -uy * 0.5 * c->w, ny = ux * 0.5 * c->w;
    gks_raster_pt t[6] = {
        {p->x + nx, p->y + ny, p->z}, {q->x + nx, q->y + ny, q->z}, {q->x - nx, q->y - ny, q->z},
        {p->x + nx, p->y + ny, p->z}, {q->x - nx, q->y - ny, q->z}, {p->x - nx, p->y - ny, p->z},
    };
    return fill_tris(c, t, 2);
}

/* Round join: a disc of diameter w as a triangle fan (8..48 sides by width). */
static int disc(line_ctx *c, const gks_raster_pt *p)
{
    enum { NMAX = 48 };
    gks_raster_pt t[3 * NMAX];
    int n = (int)(3.0 * c->w);
    n = n < 8 ? 8 : n > NMAX ? NMAX : n;
    double r = 0.5 * c->w;
    for (int k = 0; k < n; k++) {
        double a0 = 2.0 * PI * k / n, a1 = 2.0 * PI * (k + 1) / n;
        t[3 * k] = *p;
        t[3 * k + 1] = (gks_raster_pt){p->x + r * cos(a0), p->y + r * sin(a0), p->z};
        t[3 * k + 2] = (gks_raster_pt){p->x + r * cos(a1), p->y + r * sin(a1), p->z};
    }
    return fill_tris(c, t, (size_t)n);
}

/* Does the polyline turn at b (a -> b -> c) enough for the quads to leave a gap? */
static int turns(const gks_raster_pt *a, const gks_raster_pt *b, const gks_raster_pt *c,
                 double w)
{
    double ux = 0.5 * b->x - 0.5 * a->x, uy = 0.5 * b->y - 0.5 * a->y;
    double vx = 0.5 * c->x - 0.5 * b->x, vy = 0.5 * c->y - 0.5 * b->y;
    double lu = length2(ux, uy), lv = length2(vx, vy);
    if (!(lu > 0.0) || !(lv > 0.0))
        return 1;
    ux /= lu; uy /= lu; vx /= lv; vy /= lv;
    double cross = ux * vy - uy * vx, dot = ux * vx + uy * vy;
    return dot < 0.0 || fabs(cross) * w > 0.05;
}

static int wide_segment(line_ctx *c, const gks_raster_pt *pa, const gks_raster_pt *pb)
{
    double a[2] = {pa->x, pa->y}, b[2] = {pb->x, pb->y}, m = c->w + 2.0;
    double len = 2.0 * length2(0.5 * b[0] - 0.5 * a[0], 0.5 * b[1] - 0.5 * a[1]);
    double box[4] = {-m, c->fb->width + m, -m, c->fb->height + m}, t0, t1, p0[2], p1[2];
    double ph0 = c->phase;
    c->phase = phase_add(c, c->phase, len);
    if (!clip_seg(a, b, box, p0, p1, &t0, &t1))
        return GKS_RASTER_OK;
    gks_raster_pt p = {p0[0], p0[1], lerp(pa->z, pb->z, t0)};
    gks_raster_pt q = {p1[0], p1[1], lerp(pa->z, pb->z, t1)};
    double cl = length2(q.x - p.x, q.y - p.y);
    if (!(cl > 0.0))
        return GKS_RASTER_OK;
    double ux = (q.x - p.x) / cl, uy = (q.y - p.y) / cl;
    double ph = phase_add(c, ph0, t0 * len), pos = 0.0;
    for (int guard = 0; pos < cl && guard < 1000000; guard++) {
        double left;
        int on = dash_on(c, ph + pos, &left);
        double end = pos + left < cl ? pos + left : cl;
        if (on) {
            double s0 = pos / cl, s1 = end / cl;
            gks_raster_pt u = {lerp(p.x, q.x, s0), lerp(p.y, q.y, s0), lerp(p.z, q.z, s0)};
            gks_raster_pt v = {lerp(p.x, q.x, s1), lerp(p.y, q.y, s1), lerp(p.z, q.z, s1)};
            int rc = quad(c, &u, &v, ux, uy);
            if (rc != GKS_RASTER_OK)
                return rc;
        }
        if (!(end > pos))
            break;
        pos = end;
    }
    return GKS_RASTER_OK;
}

static int line_check(const gks_raster_fb *fb, const gks_raster_line *attr)
{
    return fb && attr && !isnan(attr->width) && attr->width < 1e6 &&
           (int)attr->zmode >= 0 && (int)attr->zmode <= 2 && isfinite(attr->zbias) &&
           attr->zbias >= 0.0f;
}

static int pts_finite(const gks_raster_pt *pts, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y) || !isfinite(pts[i].z))
            return 0;
    return 1;
}

static void ctx_init(line_ctx *c, gks_raster_fb *fb, const gks_raster_line *attr, int type)
{
    *c = (line_ctx){.fb = fb, .attr = attr};
    for (int k = 0; k < 3; k++)
        c->rgb[k] = clamp01(attr->rgb[k]);
    c->w = attr->width > 1.0 ? attr->width : 1.0;
    c->n_dash = dash_tab[type].n;
    for (int k = 0; k < c->n_dash; k++) {
        c->dash[k] = dash_tab[type].len[k] * c->w;
        c->period += c->dash[k];
    }
}

/* Round join at v (a -> v -> b), if the pattern is on there and v is near the image. */
static int join(line_ctx *c, const gks_raster_pt *a, const gks_raster_pt *v,
                const gks_raster_pt *b)
{
    double left, m = c->w;
    if (v->x < -m || v->y < -m || v->x > c->fb->width + m || v->y > c->fb->height + m)
        return GKS_RASTER_OK;
    if (dash_on(c, c->phase, &left) && turns(a, v, b, c->w))
        return disc(c, v);
    return GKS_RASTER_OK;
}

/* prev: the point before pts[0] when continuing a polyline (NULL: a new polyline). */
static int polyline_draw(line_ctx *c, size_t n, const gks_raster_pt *pts,
                         const gks_raster_pt *prev)
{
    if (c->fb->ss == 1 && c->w <= 1.0) {
        for (size_t i = 0; i + 1 < n; i++)
            thin_segment(c, &pts[i], &pts[i + 1], i > 0 || prev);
        return GKS_RASTER_OK;
    }
    if (prev && n >= 2) {
        int rc = join(c, prev, &pts[0], &pts[1]);
        if (rc != GKS_RASTER_OK)
            return rc;
    }
    for (size_t i = 0; i + 1 < n; i++) {
        int rc = wide_segment(c, &pts[i], &pts[i + 1]);
        if (rc != GKS_RASTER_OK)
            return rc;
        if (i + 2 >= n)
            break;
        rc = join(c, &pts[i], &pts[i + 1], &pts[i + 2]);
        if (rc != GKS_RASTER_OK)
            return rc;
    }
    return GKS_RASTER_OK;
}

int gks_raster_polyline(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                        const gks_raster_line *attr)
{
    if (!line_check(fb, attr) || !pts || n < 2 || attr->type < 1 || attr->type > 4)
        return GKS_RASTER_E_ARG;
    if (!pts_finite(pts, n))
        return GKS_RASTER_E_ARG;
    line_ctx c;
    ctx_init(&c, fb, attr, attr->type);
    return polyline_draw(&c, n, pts, NULL);
}

int gks_raster_polyline_cont(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                             const gks_raster_line *attr, gks_raster_stroke *st)
{
    if (!st || !line_check(fb, attr) || !pts || n < 2 || attr->type < 1 || attr->type > 4)
        return GKS_RASTER_E_ARG;
    if (!pts_finite(pts, n))
        return GKS_RASTER_E_ARG;
    line_ctx c;
    ctx_init(&c, fb, attr, attr->type);
    if (st->cont && isfinite(st->phase) && st->phase >= 0.0)
        c.phase = c.n_dash ? fmod(st->phase, c.period) : 0.0;
    int rc = polyline_draw(&c, n, pts, st->cont && pts_finite(&st->prev, 1) ? &st->prev : NULL);
    st->phase = c.phase;
    st->prev = pts[n - 2];
    st->cont = 1;
    return rc;
}

static int marker_one(line_ctx *c, int type, const gks_raster_pt *p, double size)
{
    double r = 0.5 * size, d = r * SQRT1_2;
    if (type == 1) {
        gks_raster_fb *fb = c->fb;
        double fx = floor(p->x), fy = floor(p->y);
        if (fx < 0 || fy < 0 || fx >= fb->width || fy >= fb->height)
            return GKS_RASTER_OK;
        for (int j = 0; j < fb->ss; j++)
            for (int i = 0; i < fb->ss; i++)
                plot(c, (int)fx * fb->ss + i, (int)fy * fb->ss + j, p->z);
        return GKS_RASTER_OK;
    }
    if (type == 4) {
        enum { N = 48 };
        gks_raster_pt ring[N + 1];
        int nseg = size < 8 ? 12 : size < 24 ? 24 : N;
        for (int k = 0; k <= nseg; k++) {
            double a = 2.0 * PI * k / nseg;
            ring[k] = (gks_raster_pt){p->x + r * cos(a), p->y + r * sin(a), p->z};
        }
        c->phase = 0.0;
        return polyline_draw(c, (size_t)nseg + 1, ring, NULL);
    }
    gks_raster_pt s[4][2] = {
        {{p->x - r, p->y, p->z}, {p->x + r, p->y, p->z}},
        {{p->x, p->y - r, p->z}, {p->x, p->y + r, p->z}},
        {{p->x - d, p->y - d, p->z}, {p->x + d, p->y + d, p->z}},
        {{p->x - d, p->y + d, p->z}, {p->x + d, p->y - d, p->z}},
    };
    int first = type == 5 ? 2 : 0, last = type == 2 ? 2 : 4;
    for (int k = first; k < last; k++) {
        c->phase = 0.0;
        int rc = polyline_draw(c, 2, s[k], NULL);
        if (rc != GKS_RASTER_OK)
            return rc;
    }
    return GKS_RASTER_OK;
}

int gks_raster_markers(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts, int type,
                       double size, const gks_raster_line *attr)
{
    if (!line_check(fb, attr) || !pts || n < 1 || type < 1 || type > 5 ||
        !isfinite(size) || size < 0.0 || size > 1e6)
        return GKS_RASTER_E_ARG;
    if (!pts_finite(pts, n))
        return GKS_RASTER_E_ARG;
    line_ctx c;
    ctx_init(&c, fb, attr, GKS_RASTER_LT_SOLID);
    for (size_t i = 0; i < n; i++) {
        int rc = marker_one(&c, type, &pts[i], size);
        if (rc != GKS_RASTER_OK)
            return rc;
    }
    return GKS_RASTER_OK;
}
