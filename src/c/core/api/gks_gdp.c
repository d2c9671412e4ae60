/* SPDX-License-Identifier: MIT */
/*
 * gks_gdp.c -- GENERALIZED DRAWING PRIMITIVE (3) (ISO 7942 5.3, ISO 8805). The GDPs are
 * those of RAL GKS, defined by points on the curve as its programs use them (RAL's gdpex
 * draws a pie chart with -3), plus an ellipse:
 *   -1 ARC     3 points P1, P2, P3 on a circle: the arc from P1 through P2 to P3
 *              (polyline attributes);
 *   -2 CHORD   the same arc closed by the chord P3-P1 (fill area attributes);
 *   -3 PIE     the sector of that arc: centre, P1 ... P3 (fill area attributes);
 *   -4 CIRCLE  3 points on the circle, or 2: the centre and a point on the circle (the
 *              circle then lies in the plane z = const of the centre);
 *   -5 ELLIPSE 3 points: the centre and the ends of two conjugate semi-diameters.
 * The data record is not used. Collinear or coincident points (no circle) draw the given
 * points as a polyline (ARC) or fill area: degenerate, never an error or a crash. The
 * curve is tessellated in WC3 with at most 1 degree per chord (chord height below
 * 4e-5 of the radius: 0.02 pixel for a radius of half the 1024-pixel display).
 */
#include "gks_gdp.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_state.h"
#include <math.h>
#include <string.h>

#define GDP_PI 3.14159265358979323846
#define GDP_STEP (2.0 * GDP_PI / 360.0) /* largest angle per chord */

static const Gint gdp_ids[] = { GGDP_ARC, GGDP_CHORD, GGDP_PIE, GGDP_CIRCLE, GGDP_ELLIPSE };

int gks_gdp_list(const Gint **ids)
{
    *ids = gdp_ids;
    return (int)(sizeof gdp_ids / sizeof gdp_ids[0]);
}

int gks_gdp_attrs(Gint gdp, int three_d, Gattrs attr[2])
{
    if (gdp == GGDP_ARC) {
        attr[0] = GATTR_LINE;
        return 1;
    }
    if (gdp > GGDP_CHORD || gdp < GGDP_ELLIPSE)
        return 0;
    attr[0] = GATTR_FILL;
    attr[1] = GATTR_EDGE;
    return three_d ? 2 : 1;
}

static void sub3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[0] - b[0]; o[1] = a[1] - b[1]; o[2] = a[2] - b[2];
}
static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* An ellipse c + u cos t + v sin t for t in [0, sweep]: the centre c, the axes u, v. */
typedef struct { double c[3], u[3], v[3], sweep; } conic;

/* The circle through p[0..2]: centre, u = p0 - c, v = n x u (n the triangle's normal),
 * sweep = the angle from p0 counter-clockwise about n to p2 (p1 lies between). 0 if the
 * points are collinear, coincident or not finite. */
static int circle3(const double p[3][3], conic *k)
{
    double a[3], b[3], n[3], t1[3], t2[3], d[3];
    sub3(p[1], p[0], a);
    sub3(p[2], p[0], b);
    cross3(a, b, n);
    double nn = dot3(n, n), aa = dot3(a, a), bb = dot3(b, b);
    if (!(nn > 1e-24 * aa * bb) || !isfinite(nn))
        return 0;
    /* c - p0 = (|a|^2 (b x n) + |b|^2 (n x a)) / (2 |n|^2) */
    cross3(b, n, t1);
    cross3(n, a, t2);
    for (int i = 0; i < 3; i++)
        d[i] = (aa * t1[i] + bb * t2[i]) / (2.0 * nn);
    double ln = sqrt(nn);
    for (int i = 0; i < 3; i++) {
        k->c[i] = p[0][i] + d[i];
        k->u[i] = -d[i];
        n[i] /= ln;
    }
    cross3(n, k->u, k->v);
    double r2 = dot3(k->u, k->u), e[3];
    sub3(p[2], k->c, e);
    double ang = atan2(dot3(e, k->v) / r2, dot3(e, k->u) / r2);
    k->sweep = ang > 0 ? ang : ang + 2.0 * GDP_PI;
    return isfinite(k->sweep) && r2 > 0;
}

/* Points of k: 1 + ceil(sweep / GDP_STEP) of them (the last = the first for a full
 * turn, dropped then); with_centre prepends c. NULL when out of memory. */
static double (*tessellate(const conic *k, int full, int with_centre, size_t *n))[3]
{
    size_t segs = (size_t)ceil(k->sweep / GDP_STEP);
    if (segs < 2)
        segs = 2;
    size_t m = segs + (full ? 0 : 1) + (with_centre ? 1 : 0);
    double (*q)[3] = gks_alloc_array(m, sizeof *q);
    if (!q)
        return NULL;
    size_t j = 0;
    if (with_centre)
        memcpy(q[j++], k->c, sizeof q[0]);
    size_t last = full ? segs - 1 : segs;
    for (size_t i = 0; i <= last; i++) {
        double t = k->sweep * (double)i / (double)segs, ct = cos(t), st = sin(t);
        for (int a = 0; a < 3; a++)
            q[j][a] = k->c[a] + k->u[a] * ct + k->v[a] * st;
        j++;
    }
    *n = j;
    return q;
}

static void gdp_any(int fctid, int n, const Gpoint *p2, const Gpoint3 *p3, Gint id)
{
    if (gks_check_state(fctid))
        return;
    if (n < 0 || (n > 0 && !p2 && !p3))
        GKS_FAIL(100, fctid);
    Gattrs at[2];
    if (!gks_gdp_attrs(id, 0, at))
        GKS_FAIL(102, fctid);
    int ok_n = n == 3 || (id == GGDP_CIRCLE && n == 2);
    if (!ok_n)
        GKS_FAIL(100, fctid);
    double p[3][3];
    for (int i = 0; i < n; i++) {
        p[i][0] = p2 ? p2[i].x : p3[i].x;
        p[i][1] = p2 ? p2[i].y : p3[i].y;
        p[i][2] = p2 ? 0.0 : p3[i].z;
    }
    conic k;
    int full = id == GGDP_CIRCLE || id == GGDP_ELLIPSE, ok;
    if (id == GGDP_ELLIPSE) {
        memcpy(k.c, p[0], sizeof k.c);
        sub3(p[1], p[0], k.u);
        sub3(p[2], p[0], k.v);
        double x[3];
        cross3(k.u, k.v, x);
        k.sweep = 2.0 * GDP_PI;
        ok = dot3(x, x) > 0 && isfinite(dot3(x, x));
    } else if (n == 2) { /* CIRCLE: centre, point on the circle; plane z = const */
        memcpy(k.c, p[0], sizeof k.c);
        sub3(p[1], p[0], k.u);
        k.u[2] = 0.0;
        k.v[0] = -k.u[1]; k.v[1] = k.u[0]; k.v[2] = 0.0;
        k.sweep = 2.0 * GDP_PI;
        double r2 = dot3(k.u, k.u);
        ok = r2 > 0 && isfinite(r2);
        p[2][0] = p[0][0]; p[2][1] = p[0][1]; p[2][2] = p[0][2];
    } else {
        ok = circle3((const double (*)[3])p, &k);
        if (full)
            k.sweep = 2.0 * GDP_PI;
    }
    if (!ok) { /* no curve: the given points as they are */
        if (id == GGDP_ARC)
            gks_output_polyline_d3(fctid, 3, (const double (*)[3])p);
        else
            gks_output_area_d3(fctid, 3, (const double (*)[3])p);
        return;
    }
    size_t m = 0;
    double (*q)[3] = tessellate(&k, full, id == GGDP_PIE, &m);
    if (!q)
        GKS_FAIL(300, fctid);
    if (id == GGDP_ARC)
        gks_output_polyline_d3(fctid, m, (const double (*)[3])q);
    else
        gks_output_area_d3(fctid, m, (const double (*)[3])q);
    gks_free(q);
}

GKS_API void ggdp(const Gpoint_list *l, Gint gdp_id, const Ggdp_data *data)
{
    (void)data; /* no GDP of this implementation takes data */
    gdp_any(GFN_GDP, l ? l->num_points : -1, l ? l->points : NULL, NULL, gdp_id);
}

GKS_API void ggdp3(const Gpoint_list3 *l, Gint gdp_id, const Ggdp_data *data)
{
    (void)data;
    gdp_any(GFN_GDP3, l ? l->num_points : -1, NULL, l ? l->points : NULL, gdp_id);
}
