/* SPDX-License-Identifier: MIT */
/*
 * raster_fill.c -- scan conversion of areas: even-odd polygons with holes, the triangle
 * fast path and cell arrays, with depth from the polygon's plane and solid, hatch,
 * pattern or cell colours.
 *
 * Coverage: a sample (i, r) with centre (i+.5, r+.5) is inside iff an odd number of
 * edges cross the row at an x <= i+.5, an edge spanning rows r with ymin <= r+.5 < ymax.
 * The crossing of an edge is always computed from its lower end point, so every
 * primitive sharing that edge gets the identical value (watertight, no double cover).
 */
#include "raster.h"
#include "gks_alloc.h"
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(GKS_RASTER_NO_AVX2)
#include <immintrin.h>
#define RASTER_AVX2 1 /* an AVX2 variant of the depth-tested span, chosen at run time */
#endif

enum { PAINT_SOLID, PAINT_HATCH, PAINT_PATTERN, PAINT_CELL, PAINT_SMOOTH };

typedef struct paint {
    gks_raster_fb *fb;
    int kind;
    gks_raster_zmode zmode;
    float zbias;
    float rgb[3];
    /* depth plane in sample coordinates: z = z0 + gx*(x - px) + gy*(y - py) */
    double px, py, z0, gx, gy, zmin, zmax;
    int hatch_kind, spacing;      /* hatch: 1..6, spacing in output pixels */
    double ox, oy, m[4];          /* pattern / cell: sample -> cell coordinates */
    int nx, ny;
    const float *cells;
    int avx2;                     /* CPU has AVX2: use span_solid_z_avx2 */
    int bounded;                  /* cell: skip samples outside the parallelogram */
    /* smooth: the current triangle's vertices (sample coordinates), 1/w and attributes */
    double sv[3][2], sdet, sw[3];
    const float *sa[3];
    const gks_raster_vattr *va;
} paint;

typedef struct edge {
    double x0, y0, dxdy;          /* lower end point and inverse slope */
    int r0, r1;                   /* rows r0 <= r < r1 whose centre the edge spans */
} edge;

static float clamp01(float v)
{
    if (!(v > 0.0f))
        return 0.0f;
    return v < 1.0f ? v : 1.0f;
}

/* First row whose centre is >= y, clamped to [0, h]. */
static int row_ceil(double y, int h)
{
    double v = ceil(y - 0.5);
    if (!(v > 0.0))
        return 0;
    return v < (double)h ? (int)v : h;
}

/* Build the edge a-b; 0 if it spans no row centre of the sample grid. */
static int edge_make(edge *e, double ax, double ay, double bx, double by, int h)
{
    e->r0 = e->r1 = 0;
    if (ay == by)
        return 0;
    if (ay > by) {
        double t = ax; ax = bx; bx = t;
        t = ay; ay = by; by = t;
    }
    e->r0 = row_ceil(ay, h);
    e->r1 = row_ceil(by, h);
    if (e->r0 >= e->r1)
        return 0;
    e->x0 = ax;
    e->y0 = ay;
    e->dxdy = (bx - ax) / (by - ay);
    if (!isfinite(e->dxdy)) /* overflow of an almost horizontal edge */
        e->dxdy = 0.0;
    return 1;
}

/* Crossing of row centre yc, clamped to [-1, w+1] (monotone, so order is kept). */
static double edge_x(const edge *e, double yc, int w)
{
    double x = e->x0 + (yc - e->y0) * e->dxdy;
    if (!(x > -1.0))
        return -1.0;
    return x < (double)w + 1.0 ? x : (double)w + 1.0;
}

/* First sample column whose centre is >= x (x already clamped). */
static int col_ceil(double x)
{
    double v = x - 0.5;
    int i = (int)v; /* |v| <= w + 1.5: in range; truncation, then up for positive fractions */
    return i < v ? i + 1 : i;
}

static double plane_z(const paint *p, double x, double y)
{
    double z = p->z0 + p->gx * (x - p->px) + p->gy * (y - p->py);
    if (!(z >= p->zmin)) /* NaN too */
        return p->zmin;
    return z <= p->zmax ? z : p->zmax;
}

/* Colour of sample (i, r) for non-solid paints; 0 = leave the sample untouched. */
static int paint_colour(const paint *p, int i, int r, float c[3])
{
    if (p->kind == PAINT_HATCH) {
        int hx = i / p->fb->ss, hy = r / p->fb->ss, s = p->spacing;
        int hor = hy % s == 0, ver = hx % s == 0;
        int up = (hx - hy) % s == 0, down = (hx + hy) % s == 0;
        int on = 0;
        switch (p->hatch_kind) {
        case 1: on = hor; break;
        case 2: on = ver; break;
        case 3: on = up; break;
        case 4: on = down; break;
        case 5: on = hor || ver; break;
        default: on = up || down; break;
        }
        if (!on)
            return 0;
        c[0] = p->rgb[0]; c[1] = p->rgb[1]; c[2] = p->rgb[2];
        return 1;
    }
    if (p->kind == PAINT_SMOOTH) {
        /* screen-space barycentric coordinates, then perspective-correct ones: attributes
           over w and 1/w are linear in the screen */
        const double x = i + 0.5, y = r + 0.5;
        double b[3], sum = 0.0;
        for (int k = 0; k < 3; k++) {
            const double *u = p->sv[(k + 1) % 3], *v = p->sv[(k + 2) % 3];
            b[k] = ((u[0] - x) * (v[1] - y) - (u[1] - y) * (v[0] - x)) / p->sdet * p->sw[k];
            sum += b[k];
        }
        if (!(fabs(sum) > 0.0))
            return 0;
        float at[GKS_RASTER_VATTR_MAX];
        const int n = p->va->n;
        for (int j = 0; j < n; j++)
            at[j] = (float)((b[0] * p->sa[0][j] + b[1] * p->sa[1][j] + b[2] * p->sa[2][j]) / sum);
        if (p->va->shade)
            p->va->shade(p->va->user, at, c);
        else {
            c[0] = at[0]; c[1] = at[1]; c[2] = at[2];
        }
        c[0] = clamp01(c[0]); c[1] = clamp01(c[1]); c[2] = clamp01(c[2]);
        return 1;
    }
    double x = i + 0.5 - p->ox, y = r + 0.5 - p->oy;
    double a = p->m[0] * x + p->m[1] * y, b = p->m[2] * x + p->m[3] * y;
    int ci, cj;
    if (p->kind == PAINT_PATTERN) {
        double fa = fmod(floor(a), (double)p->nx), fb = fmod(floor(b), (double)p->ny);
        if (fa < 0.0)
            fa += p->nx;
        if (fb < 0.0)
            fb += p->ny;
        /* NaN from an overflowing (huge) pattern coordinate falls back to cell 0 */
        ci = fa >= 0.0 && fa < p->nx ? (int)fa : 0;
        cj = fb >= 0.0 && fb < p->ny ? (int)fb : 0;
    } else {
        /* restricted to an area: samples beyond the parallelogram (by more than rounding)
         * are not part of the cell array */
        if (p->bounded && !(a > -1e-9 && a < 1.0 + 1e-9 && b > -1e-9 && b < 1.0 + 1e-9))
            return 0;
        a *= p->nx;
        b *= p->ny;
        ci = !(a >= 0.0) ? 0 : a >= p->nx ? p->nx - 1 : (int)a;
        cj = !(b >= 0.0) ? 0 : b >= p->ny ? p->ny - 1 : (int)b;
    }
    const float *s = p->cells + 3 * ((size_t)cj * (size_t)p->nx + (size_t)ci);
    c[0] = clamp01(s[0]); c[1] = clamp01(s[1]); c[2] = clamp01(s[2]);
    return 1;
}

/* Samples k..n-1 of a solid span with depth test, one at a time: z = zs + k*dz, the
 * formula of the vector loops, so that their tails give the same bits. */
static void span_solid_z_rest(float *zb, float *cb, int k, int n, float zs, float dz,
                              float bias, const float c[3], int colour)
{
    for (; k < n; k++) {
        float z = zs + (float)k * dz;
        if (!(z + bias >= zb[k]))
            continue;
        if (z > zb[k])
            zb[k] = z;
        if (colour) {
            float *d = cb + 3 * k;
            d[0] = c[0]; d[1] = c[1]; d[2] = c[2];
        }
    }
}

/* Solid colour with depth test: 4 samples at a time (SSE2), mostly rejected early. */
static void span_solid_z(float *zb, float *cb, int n, float zs, float dz, float bias,
                         const float c[3], int colour)
{
    int k = 0;
#if defined(__SSE2__)
    __m128 vzs = _mm_set1_ps(zs), vdz = _mm_set1_ps(dz), vb = _mm_set1_ps(bias);
    __m128 vk = _mm_set_ps(3.0f, 2.0f, 1.0f, 0.0f), four = _mm_set1_ps(4.0f);
    for (; k + 4 <= n; k += 4) {
        __m128 vz = _mm_add_ps(vzs, _mm_mul_ps(vk, vdz));
        vk = _mm_add_ps(vk, four);
        __m128 old = _mm_loadu_ps(zb + k);
        int m = _mm_movemask_ps(_mm_cmpge_ps(_mm_add_ps(vz, vb), old));
        if (!m)
            continue;
        _mm_storeu_ps(zb + k, _mm_max_ps(vz, old)); /* failing lanes keep old */
        if (!colour)
            continue;
        for (int l = 0; l < 4; l++) {
            if (!(m >> l & 1))
                continue;
            float *d = cb + 3 * (k + l);
            d[0] = c[0]; d[1] = c[1]; d[2] = c[2];
        }
    }
#endif
    span_solid_z_rest(zb, cb, k, n, zs, dz, bias, c, colour);
}

#ifdef RASTER_AVX2
/* span_solid_z, 8 samples at a time. */
__attribute__((target("avx2"))) static void span_solid_z_avx2(float *zb, float *cb, int n,
                                                               float zs, float dz, float bias,
                                                               const float c[3], int colour)
{
    __m256 vzs = _mm256_set1_ps(zs), vdz = _mm256_set1_ps(dz), vb = _mm256_set1_ps(bias);
    __m256 vk = _mm256_set_ps(7, 6, 5, 4, 3, 2, 1, 0), eight = _mm256_set1_ps(8.0f);
    int k = 0;
    for (; k + 8 <= n; k += 8) {
        __m256 vz = _mm256_add_ps(vzs, _mm256_mul_ps(vk, vdz));
        vk = _mm256_add_ps(vk, eight);
        __m256 old = _mm256_loadu_ps(zb + k);
        int m = _mm256_movemask_ps(_mm256_cmp_ps(_mm256_add_ps(vz, vb), old, _CMP_GE_OQ));
        if (!m)
            continue;
        _mm256_storeu_ps(zb + k, _mm256_max_ps(vz, old));
        if (!colour)
            continue;
        for (int l = 0; l < 8; l++) {
            if (!(m >> l & 1))
                continue;
            float *d = cb + 3 * (k + l);
            d[0] = c[0]; d[1] = c[1]; d[2] = c[2];
        }
    }
    span_solid_z_rest(zb, cb, k, n, zs, dz, bias, c, colour);
}
#endif

/* Fill samples i0 <= i < i1 of row r. */
static void span(const paint *p, int r, int i0, int i1)
{
    gks_raster_fb *fb = p->fb;
    if (i0 < 0)
        i0 = 0;
    if (i1 > fb->w)
        i1 = fb->w;
    if (i0 >= i1)
        return;
    size_t base = (size_t)r * (size_t)fb->w + (size_t)i0;
    float *zb = fb->z + base, *cb = fb->rgb + 3 * base;
    int n = i1 - i0;
    float zs = 0.0f, dz = 0.0f;
    if (p->zmode != GKS_RASTER_Z_NONE) {
        /* z at the first and last centre; if both lie in the vertices' z range the
         * step is the plane's gradient, else clamp both ends and interpolate */
        double za = p->z0 + p->gx * (i0 + 0.5 - p->px) + p->gy * (r + 0.5 - p->py);
        double ze = za + p->gx * (n - 1);
        if (za >= p->zmin && za <= p->zmax && ze >= p->zmin && ze <= p->zmax) {
            zs = (float)za;
            dz = (float)p->gx;
        } else {
            za = plane_z(p, i0 + 0.5, r + 0.5);
            ze = plane_z(p, i1 - 0.5, r + 0.5);
            zs = (float)za;
            dz = n > 1 ? (float)((ze - za) / (n - 1)) : 0.0f;
        }
    }
    if (p->kind == PAINT_SOLID) {
        if (p->zmode != GKS_RASTER_Z_NONE) {
            int colour = p->zmode == GKS_RASTER_Z_TEST;
#if defined(__GNUC__)
            /* the depth test is bound by z-buffer misses: fetch the next rows' lines */
            if (r + 2 < fb->h)
                for (int k = 0; k < n; k += 16) {
                    __builtin_prefetch(zb + 2 * (size_t)fb->w + k);
                    __builtin_prefetch(zb + (size_t)fb->w + k);
                }
#endif
#ifdef RASTER_AVX2
            if (p->avx2) {
                span_solid_z_avx2(zb, cb, n, zs, dz, p->zbias, p->rgb, colour);
                return;
            }
#endif
            span_solid_z(zb, cb, n, zs, dz, p->zbias, p->rgb, colour);
            return;
        }
        for (int k = 0; k < n; k++) {
            cb[3 * k] = p->rgb[0]; cb[3 * k + 1] = p->rgb[1]; cb[3 * k + 2] = p->rgb[2];
        }
        return;
    }
    for (int k = 0; k < n; k++) {
        float z = zs + (float)k * dz, c[3];
        if (p->zmode != GKS_RASTER_Z_NONE && !(z + p->zbias >= zb[k]))
            continue;
        if (!paint_colour(p, i0 + k, r, c))
            continue;
        if (p->zmode != GKS_RASTER_Z_NONE && z > zb[k])
            zb[k] = z;
        if (p->zmode != GKS_RASTER_Z_ONLY) {
            cb[3 * k] = c[0]; cb[3 * k + 1] = c[1]; cb[3 * k + 2] = c[2];
        }
    }
}

/* Plane through (x,y,z) with normal n (sample coordinates); flat if n is unusable. */
static void plane_set(paint *p, double x, double y, double z, double nx, double ny, double nz,
                      double zmin, double zmax)
{
    p->px = x;
    p->py = y;
    p->z0 = z;
    p->zmin = zmin;
    p->zmax = zmax;
    p->gx = p->gy = 0.0;
    double len = fabs(nx) + fabs(ny) + fabs(nz);
    if (!isfinite(len) || !(fabs(nz) > 1e-12 * len))
        return;
    double gx = -nx / nz, gy = -ny / nz;
    if (isfinite(gx) && isfinite(gy)) {
        p->gx = gx;
        p->gy = gy;
    }
}

/* One triangle, vertices in sample coordinates (x, y) with z. */
static void tri_draw(paint *p, const double v[3][3], int set_plane)
{
    int ia = 0, ib = 1, ic = 2, t;
    if (v[ib][1] < v[ia][1]) { t = ia; ia = ib; ib = t; }
    if (v[ic][1] < v[ib][1]) { t = ib; ib = ic; ic = t; }
    if (v[ib][1] < v[ia][1]) { t = ia; ia = ib; ib = t; }
    const double *a = v[ia], *b = v[ib], *c = v[ic];
    int w = p->fb->w, h = p->fb->h;
    edge el, e1, e2;
    if (!edge_make(&el, a[0], a[1], c[0], c[1], h))
        return;
    int ok1 = edge_make(&e1, a[0], a[1], b[0], b[1], h);
    edge_make(&e2, b[0], b[1], c[0], c[1], h);
    if (set_plane && p->zmode != GKS_RASTER_Z_NONE) {
        double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
        double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
        double zmin = fmin(a[2], fmin(b[2], c[2])), zmax = fmax(a[2], fmax(b[2], c[2]));
        plane_set(p, a[0], a[1], a[2], uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx,
                  zmin, zmax);
    }
    for (int r = el.r0; r < el.r1; r++) {
        double yc = r + 0.5;
        const edge *es = ok1 && r < e1.r1 ? &e1 : &e2;
        double xl = edge_x(&el, yc, w), xr = edge_x(es, yc, w);
        if (xl > xr) {
            double s = xl; xl = xr; xr = s;
        }
        span(p, r, col_ceil(xl), col_ceil(xr));
    }
}

static int fill_check(const gks_raster_fill *f)
{
    if ((int)f->zmode < 0 || (int)f->zmode > 2 || !isfinite(f->zbias) || f->zbias < 0.0f)
        return 0;
    switch (f->style) {
    case GKS_RASTER_SOLID:
        return 1;
    case GKS_RASTER_HATCH:
        return f->hatch <= -1 && f->hatch >= GKS_RASTER_HATCH_LAST;
    case GKS_RASTER_PATTERN:
        return f->pat_nx >= 1 && f->pat_ny >= 1 && f->pat_rgb;
    }
    return 0;
}

/* Inverse of the 2x2 basis (u | v) into m; 0 if singular or not finite. */
static int basis_inverse(double ux, double uy, double vx, double vy, double m[4])
{
    double det = ux * vy - uy * vx;
    if (!isfinite(det) || det == 0.0)
        return 0;
    m[0] = vy / det; m[1] = -vx / det;
    m[2] = -uy / det; m[3] = ux / det;
    for (int k = 0; k < 4; k++)
        if (!isfinite(m[k]))
            return 0;
    return 1;
}

static int paint_init(paint *p, gks_raster_fb *fb, const gks_raster_fill *f)
{
    *p = (paint){.fb = fb, .kind = PAINT_SOLID};
#ifdef RASTER_AVX2
    p->avx2 = __builtin_cpu_supports("avx2");
#endif
    if (!f)
        return GKS_RASTER_OK;
    if (!fill_check(f))
        return GKS_RASTER_E_ARG;
    p->zmode = f->zmode;
    p->zbias = f->zbias;
    for (int k = 0; k < 3; k++)
        p->rgb[k] = clamp01(f->rgb[k]);
    if (f->style == GKS_RASTER_HATCH) {
        int k = -f->hatch; /* 1..12 */
        p->kind = PAINT_HATCH;
        p->hatch_kind = (k - 1) % 6 + 1;
        p->spacing = k <= 6 ? GKS_RASTER_HATCH_SPACING : GKS_RASTER_HATCH_SPACING / 2;
    } else if (f->style == GKS_RASTER_PATTERN) {
        double s = fb->ss;
        p->kind = PAINT_PATTERN;
        p->nx = f->pat_nx;
        p->ny = f->pat_ny;
        p->cells = f->pat_rgb;
        p->ox = f->pat_ref[0] * s;
        p->oy = f->pat_ref[1] * s;
        if (!isfinite(p->ox) || !isfinite(p->oy) ||
            !basis_inverse(f->pat_u[0] * s, f->pat_u[1] * s, f->pat_v[0] * s, f->pat_v[1] * s,
                           p->m))
            return GKS_RASTER_E_ARG;
    }
    return GKS_RASTER_OK;
}

static int pts_finite(const gks_raster_pt *pts, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (!isfinite(pts[i].x) || !isfinite(pts[i].y) || !isfinite(pts[i].z))
            return 0;
    return 1;
}

static void tri_load(double v[3][3], const gks_raster_pt *t, double s)
{
    for (int k = 0; k < 3; k++) {
        v[k][0] = t[k].x * s;
        v[k][1] = t[k].y * s;
        v[k][2] = t[k].z;
    }
}

int gks_raster_triangles(gks_raster_fb *fb, size_t n, const gks_raster_pt *pts,
                         const float *rgb, const gks_raster_fill *fill)
{
    if (!fb || !fill || (n && !pts) || n > SIZE_MAX / 3)
        return GKS_RASTER_E_ARG;
    paint p;
    int rc = paint_init(&p, fb, fill);
    if (rc != GKS_RASTER_OK)
        return rc;
    if (!pts_finite(pts, 3 * n))
        return GKS_RASTER_E_ARG;
    double v[3][3];
    for (size_t t = 0; t < n; t++) {
        if (rgb)
            for (int k = 0; k < 3; k++)
                p.rgb[k] = clamp01(rgb[3 * t + k]);
        tri_load(v, pts + 3 * t, fb->ss);
        tri_draw(&p, v, 1);
    }
    return GKS_RASTER_OK;
}

int gks_raster_fill_smooth(gks_raster_fb *fb, int n, const gks_raster_pt *pts,
                           const gks_raster_vattr *va, const gks_raster_fill *fill)
{
    if (!fb || !fill || !pts || !va || !va->v || !va->invw || n < 3 || va->n < 3 ||
        va->n > GKS_RASTER_VATTR_MAX || fill->style != GKS_RASTER_SOLID)
        return GKS_RASTER_E_ARG;
    paint p;
    int rc = paint_init(&p, fb, fill);
    if (rc != GKS_RASTER_OK)
        return rc;
    if (!pts_finite(pts, (size_t)n))
        return GKS_RASTER_E_ARG;
    for (int k = 0; k < n; k++)
        if (!isfinite(va->invw[k]) || !(va->invw[k] > 0.0))
            return GKS_RASTER_E_ARG;
    p.kind = PAINT_SMOOTH;
    p.va = va;
    const double s = fb->ss;
    for (int t = 1; t + 1 < n; t++) { /* fan from vertex 0 (a convex loop) */
        const int id[3] = {0, t, t + 1};
        double v[3][3];
        for (int k = 0; k < 3; k++) {
            v[k][0] = p.sv[k][0] = pts[id[k]].x * s;
            v[k][1] = p.sv[k][1] = pts[id[k]].y * s;
            v[k][2] = pts[id[k]].z;
            p.sw[k] = va->invw[id[k]];
            p.sa[k] = va->v + (size_t)va->n * (size_t)id[k];
        }
        p.sdet = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]);
        if (!(fabs(p.sdet) > 0.0) || !isfinite(p.sdet))
            continue;
        tri_draw(&p, v, 1);
    }
    return GKS_RASTER_OK;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void sort_doubles(double *x, size_t n)
{
    if (n > 24) {
        qsort(x, n, sizeof *x, cmp_double);
        return;
    }
    for (size_t i = 1; i < n; i++) {
        double t = x[i];
        size_t j = i;
        for (; j > 0 && x[j - 1] > t; j--)
            x[j] = x[j - 1];
        x[j] = t;
    }
}

/* Best-fit plane: centroid and Newell normal, each loop's normal turned to agree with
 * the largest loop's (holes may run either way round). */
static void polygon_plane(paint *p, int n_loops, const int *counts, const gks_raster_pt *pts,
                          size_t total)
{
    double s = p->fb->ss, cx = 0, cy = 0, cz = 0, zmin = INFINITY, zmax = -INFINITY;
    for (size_t i = 0; i < total; i++) {
        cx += pts[i].x; cy += pts[i].y; cz += pts[i].z;
        zmin = fmin(zmin, pts[i].z);
        zmax = fmax(zmax, pts[i].z);
    }
    cx = cx / total * s; cy = cy / total * s; cz /= total;
    if (!isfinite(cx) || !isfinite(cy) || !isfinite(cz)) {
        cx = pts[0].x * s; cy = pts[0].y * s; cz = pts[0].z;
    }
    double ref[3] = {0, 0, 0}, sum[3] = {0, 0, 0}, best = -1.0;
    for (int pass = 0; pass < 2; pass++) {
        const gks_raster_pt *q = pts;
        for (int l = 0; l < n_loops; q += counts[l], l++) {
            double n[3] = {0, 0, 0};
            int m = counts[l];
            for (int i = 0; i < m; i++) {
                const gks_raster_pt *a = q + i, *b = q + (i + 1 == m ? 0 : i + 1);
                double ax = a->x * s - cx, ay = a->y * s - cy, az = a->z - cz;
                double bx = b->x * s - cx, by = b->y * s - cy, bz = b->z - cz;
                n[0] += (ay - by) * (az + bz);
                n[1] += (az - bz) * (ax + bx);
                n[2] += (ax - bx) * (ay + by);
            }
            double len = fabs(n[0]) + fabs(n[1]) + fabs(n[2]);
            if (pass == 0 && len > best) {
                best = len;
                ref[0] = n[0]; ref[1] = n[1]; ref[2] = n[2];
            }
            if (pass == 1) {
                double sg = n[0] * ref[0] + n[1] * ref[1] + n[2] * ref[2] < 0 ? -1.0 : 1.0;
                for (int k = 0; k < 3; k++)
                    sum[k] += sg * n[k];
            }
        }
    }
    plane_set(p, cx, cy, cz, sum[0], sum[1], sum[2], zmin, zmax);
}

/* Even-odd scan conversion of the loops with paint p (plane already set). */
static int polygon_draw(paint *p, int n_loops, const int *counts, const gks_raster_pt *pts)
{
    gks_raster_fb *fb = p->fb;
    double s = fb->ss;
    size_t ne = 0;
    edge e;
    const gks_raster_pt *q = pts;
    for (int l = 0; l < n_loops; q += counts[l], l++)
        for (int i = 0; i < counts[l]; i++) {
            const gks_raster_pt *a = q + i, *b = q + (i + 1 == counts[l] ? 0 : i + 1);
            ne += (size_t)edge_make(&e, a->x * s, a->y * s, b->x * s, b->y * s, fb->h);
        }
    if (ne < 2)
        return GKS_RASTER_OK;
    edge *edges = gks_alloc_array(ne, sizeof *edges);
    size_t *order = gks_alloc_array(ne, sizeof *order);
    size_t *active = gks_alloc_array(ne, sizeof *active);
    double *xs = gks_alloc_array(ne, sizeof *xs);
    size_t *start = gks_calloc_array((size_t)fb->h + 1, sizeof *start);
    int rc = GKS_RASTER_E_NOMEM;
    if (!edges || !order || !active || !xs || !start)
        goto done;
    rc = GKS_RASTER_OK;
    size_t k = 0;
    int rmin = fb->h, rmax = 0;
    q = pts;
    for (int l = 0; l < n_loops; q += counts[l], l++)
        for (int i = 0; i < counts[l]; i++) {
            const gks_raster_pt *a = q + i, *b = q + (i + 1 == counts[l] ? 0 : i + 1);
            if (!edge_make(&e, a->x * s, a->y * s, b->x * s, b->y * s, fb->h))
                continue;
            edges[k] = e;
            start[edges[k].r0 + 1]++;
            if (edges[k].r0 < rmin)
                rmin = edges[k].r0;
            if (edges[k].r1 > rmax)
                rmax = edges[k].r1;
            k++;
        }
    for (int r = 0; r < fb->h; r++) /* bucket sort by first row */
        start[r + 1] += start[r];
    for (size_t i = 0; i < ne; i++)
        order[start[edges[i].r0]++] = i;
    /* start[r] is now the end of bucket r, i.e. the beginning of bucket r+1 */
    size_t na = 0, next = rmin > 0 ? start[rmin - 1] : 0;
    for (int r = rmin; r < rmax; r++) {
        for (; next < start[r]; next++)
            active[na++] = order[next];
        double yc = r + 0.5;
        size_t keep = 0;
        for (size_t a = 0; a < na; a++) {
            const edge *ea = &edges[active[a]];
            if (ea->r1 <= r)
                continue;
            xs[keep] = edge_x(ea, yc, fb->w);
            active[keep++] = active[a];
        }
        na = keep;
        sort_doubles(xs, na);
        for (size_t j = 0; j + 1 < na; j += 2)
            span(p, r, col_ceil(xs[j]), col_ceil(xs[j + 1]));
    }
done:
    gks_free(edges);
    gks_free(order);
    gks_free(active);
    gks_free(xs);
    gks_free(start);
    return rc;
}

/* All four turns of the quad strictly the same way (then it is simple and convex: a
 * four-vertex loop cannot wind twice). Computed in sample coordinates as drawn. */
static int quad_convex(const gks_raster_pt *q, double s)
{
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        const gks_raster_pt *a = &q[k], *b = &q[(k + 1) % 4], *c = &q[(k + 2) % 4];
        double cr = (b->x * s - a->x * s) * (c->y * s - b->y * s) -
                    (b->y * s - a->y * s) * (c->x * s - b->x * s);
        pos += cr > 0.0;
        neg += cr < 0.0;
    }
    return pos == 4 || neg == 4;
}

/* The loops' point total into *total: 0 when n_loops < 1, a count is negative or there are
 * points but no pts. */
static int loops_total(int n_loops, const int *counts, const gks_raster_pt *pts, size_t *total)
{
    *total = 0;
    if (n_loops < 1 || !counts)
        return 0;
    for (int l = 0; l < n_loops; l++) {
        if (counts[l] < 0)
            return 0;
        *total += (size_t)counts[l];
    }
    return !*total || pts;
}

int gks_raster_fill_area(gks_raster_fb *fb, int n_loops, const int *counts,
                         const gks_raster_pt *pts, const gks_raster_fill *fill)
{
    size_t total;
    if (!fb || !fill || !loops_total(n_loops, counts, pts, &total))
        return GKS_RASTER_E_ARG;
    paint p;
    int rc = paint_init(&p, fb, fill);
    if (rc != GKS_RASTER_OK)
        return rc;
    if (!pts_finite(pts, total))
        return GKS_RASTER_E_ARG;
    if (total < 3)
        return GKS_RASTER_OK;
    if (n_loops == 1 && counts[0] == 3) {
        double v[3][3];
        tri_load(v, pts, fb->ss);
        tri_draw(&p, v, 1);
        return GKS_RASTER_OK;
    }
    if (p.zmode != GKS_RASTER_Z_NONE)
        polygon_plane(&p, n_loops, counts, pts, total);
    if (n_loops == 1 && counts[0] == 4 && quad_convex(pts, fb->ss)) {
        /* strictly convex quad: two triangles cover exactly its even-odd interior
         * (the shared diagonal is watertight), without allocation */
        double v[4][3];
        for (int k = 0; k < 4; k++) {
            v[k][0] = pts[k].x * fb->ss;
            v[k][1] = pts[k].y * fb->ss;
            v[k][2] = pts[k].z;
        }
        double t1[3][3] = {{v[0][0], v[0][1], v[0][2]}, {v[1][0], v[1][1], v[1][2]},
                           {v[2][0], v[2][1], v[2][2]}};
        double t2[3][3] = {{v[0][0], v[0][1], v[0][2]}, {v[2][0], v[2][1], v[2][2]},
                           {v[3][0], v[3][1], v[3][2]}};
        tri_draw(&p, t1, 0);
        tri_draw(&p, t2, 0);
        return GKS_RASTER_OK;
    }
    return polygon_draw(&p, n_loops, counts, pts);
}

/* Cell array paint and plane of the parallelogram; 0 when it is degenerate. */
static int cell_setup(paint *p, const gks_raster_pt *o, const gks_raster_pt *pu,
                      const gks_raster_pt *pv, int nx, int ny, const float *rgb, double *zw,
                      double uv[4])
{
    double s = p->fb->ss;
    p->kind = PAINT_CELL;
    p->nx = nx;
    p->ny = ny;
    p->cells = rgb;
    p->ox = o->x * s;
    p->oy = o->y * s;
    double ux = (pu->x - o->x) * s, uy = (pu->y - o->y) * s;
    double vx = (pv->x - o->x) * s, vy = (pv->y - o->y) * s;
    uv[0] = ux, uv[1] = uy, uv[2] = vx, uv[3] = vy;
    if (!basis_inverse(ux, uy, vx, vy, p->m))
        return 0;
    double uz = pu->z - o->z, vz = pv->z - o->z;
    *zw = o->z + uz + vz;
    plane_set(p, p->ox, p->oy, o->z, uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx,
              fmin(fmin(o->z, pu->z), fmin(pv->z, *zw)),
              fmax(fmax(o->z, pu->z), fmax(pv->z, *zw)));
    return 1;
}

/* A cell array paints solid cells: of fill only the z mode and bias count. */
static int cell_paint_init(paint *p, gks_raster_fb *fb, const gks_raster_fill *fill)
{
    gks_raster_fill f = {.style = GKS_RASTER_SOLID};
    if (fill) {
        f.zmode = fill->zmode;
        f.zbias = fill->zbias;
    }
    return paint_init(p, fb, &f);
}

int gks_raster_cell_array_clipped(gks_raster_fb *fb, const gks_raster_pt *o,
                                  const gks_raster_pt *pu, const gks_raster_pt *pv, int nx,
                                  int ny, const float *rgb, const gks_raster_fill *fill,
                                  int n_loops, const int *counts, const gks_raster_pt *pts)
{
    size_t total;
    if (!fb || !o || !pu || !pv || !rgb || nx < 1 || ny < 1 ||
        !loops_total(n_loops, counts, pts, &total))
        return GKS_RASTER_E_ARG;
    paint p;
    int rc = cell_paint_init(&p, fb, fill);
    if (rc != GKS_RASTER_OK)
        return rc;
    if (!pts_finite(o, 1) || !pts_finite(pu, 1) || !pts_finite(pv, 1) ||
        !pts_finite(pts, total))
        return GKS_RASTER_E_ARG;
    double zw, uv[4];
    if (total < 3 || !cell_setup(&p, o, pu, pv, nx, ny, rgb, &zw, uv))
        return GKS_RASTER_OK;
    p.bounded = 1;
    return polygon_draw(&p, n_loops, counts, pts);
}

int gks_raster_cell_array(gks_raster_fb *fb, const gks_raster_pt *o,
                          const gks_raster_pt *pu, const gks_raster_pt *pv,
                          int nx, int ny, const float *rgb, const gks_raster_fill *fill)
{
    if (!fb || !o || !pu || !pv || !rgb || nx < 1 || ny < 1)
        return GKS_RASTER_E_ARG;
    paint p;
    int rc = cell_paint_init(&p, fb, fill);
    if (rc != GKS_RASTER_OK)
        return rc;
    if (!pts_finite(o, 1) || !pts_finite(pu, 1) || !pts_finite(pv, 1))
        return GKS_RASTER_E_ARG;
    double zw, uv[4];
    if (!cell_setup(&p, o, pu, pv, nx, ny, rgb, &zw, uv))
        return GKS_RASTER_OK; /* degenerate: covers no sample centre */
    double ux = uv[0], uy = uv[1], vx = uv[2], vy = uv[3];
    double t1[3][3] = {{p.ox, p.oy, o->z}, {p.ox + ux, p.oy + uy, pu->z},
                       {p.ox + ux + vx, p.oy + uy + vy, zw}};
    double t2[3][3] = {{p.ox, p.oy, o->z}, {p.ox + ux + vx, p.oy + uy + vy, zw},
                       {p.ox + vx, p.oy + vy, pv->z}};
    tri_draw(&p, t1, 0);
    tri_draw(&p, t2, 0);
    return GKS_RASTER_OK;
}
