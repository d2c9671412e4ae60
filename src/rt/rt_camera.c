/* SPDX-License-Identifier: MIT */
/*
 * rt_camera.c -- camera recovery from the view mapping matrix (Urban & Haberstroh, section 3):
 * the display volume's corners are mapped through the INVERSE view mapping matrix into VRC3;
 * P = M^-1 (0,0,1,0)^T is the projection reference point (w != 0) or the direction of
 * projection (w == 0); the 6 faces give the clipping planes; the raster lies on the front
 * plane (NPC z = zmax). Each primary ray is the VRC3 image of an NPC projector
 * x = const, y = const, cut to the segment between the front and back planes: this is exact
 * for any invertible matrix, parallel, oblique or perspective.
 */
#define GKS3D_RT_BUILDING 1
#include "rt_internal.h"

#include <math.h>
#include <string.h>

/* Gauss-Jordan with partial pivoting; 0 if singular, non-finite or badly conditioned */
static int rt_invert4(const double m[4][4], double inv[4][4])
{
    double a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            if (!isfinite(m[i][j]))
                return 0;
            a[i][j] = m[i][j];
            a[i][4 + j] = i == j ? 1.0 : 0.0;
        }
    double mx = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            mx = fmax(mx, fabs(m[i][j]));
    if (!(mx > 0.0))
        return 0;
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[p][c]))
                p = r;
        if (!(fabs(a[p][c]) > 1e-14 * mx))
            return 0;
        if (p != c)
            for (int j = 0; j < 8; j++) {
                double t = a[p][j];
                a[p][j] = a[c][j];
                a[c][j] = t;
            }
        double piv = a[c][c];
        for (int j = 0; j < 8; j++)
            a[c][j] /= piv;
        for (int r = 0; r < 4; r++) {
            if (r == c || a[r][c] == 0.0)
                continue;
            double f = a[r][c];
            for (int j = 0; j < 8; j++)
                a[r][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            inv[i][j] = a[i][4 + j];
            if (!isfinite(inv[i][j]))
                return 0;
        }
    /* residual check: M * inv = I */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0.0, sa = 0.0;
            for (int k = 0; k < 4; k++) {
                s += m[i][k] * inv[k][j];
                sa += fabs(m[i][k] * inv[k][j]);
            }
            if (!(fabs(s - (i == j ? 1.0 : 0.0)) <= 1e-9 * (1.0 + sa)))
                return 0;
        }
    return 1;
}

static void rt_mul4(const double m[4][4], const double v[4], double r[4])
{
    for (int i = 0; i < 4; i++)
        r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] + m[i][3] * v[3];
}

/* NPC point -> VRC3; 0 if at or beyond infinity */
static int rt_unmap(const rt_camera *cam, double x, double y, double z, double out[3])
{
    double v[4] = {x, y, z, 1.0}, h[4];
    rt_mul4(cam->minv, v, h);
    if (!(fabs(h[3]) > 0.0))
        return 0;
    for (int i = 0; i < 3; i++)
        out[i] = h[i] / h[3];
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

static void rt_norm3(double v[3])
{
    double m = fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
    if (!(m > 0.0))
        return;
    double a = v[0] / m, b = v[1] / m, c = v[2] / m;
    double l = sqrt(a * a + b * b + c * c);
    v[0] = a / l;
    v[1] = b / l;
    v[2] = c / l;
}

/* the 8 corners of the NPC box through c->minv: w of all 8 must be non-zero with one sign
   (w is affine in NPC, so the whole volume is then finite) */
static int rt_cam_corners(rt_camera *c, const double npc_box[6])
{
    double wsign = 0.0;
    for (int k = 0; k < 8; k++) {
        double v[4] = {npc_box[k & 1 ? 1 : 0], npc_box[k & 2 ? 3 : 2], npc_box[k & 4 ? 5 : 4], 1.0};
        double h[4];
        rt_mul4(c->minv, v, h);
        double hm = fmax(fabs(h[0]), fmax(fabs(h[1]), fabs(h[2])));
        if (!(fabs(h[3]) > 1e-12 * hm))
            return RT_ERR_SINGULAR;
        if (wsign == 0.0)
            wsign = h[3] > 0.0 ? 1.0 : -1.0;
        else if ((h[3] > 0.0 ? 1.0 : -1.0) != wsign)
            return RT_ERR_SINGULAR;
        for (int i = 0; i < 3; i++)
            c->corner[k][i] = h[i] / h[3];
        if (!isfinite(c->corner[k][0]) || !isfinite(c->corner[k][1]) || !isfinite(c->corner[k][2]))
            return RT_ERR_SINGULAR;
    }
    return RT_OK;
}

/* projection reference point or direction of projection, and the size of the volume;
   cen = the volume's centre */
static void rt_cam_projection(rt_camera *c, double cen[3])
{
    double P[4] = {c->minv[0][2], c->minv[1][2], c->minv[2][2], c->minv[3][2]};
    double pm = fmax(fabs(P[0]), fmax(fabs(P[1]), fabs(P[2])));
    double axis[3]; /* front -> back through the volume centre */
    double cf[3] = {0, 0, 0}, cbk[3] = {0, 0, 0};
    cen[0] = cen[1] = cen[2] = 0.0;
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++) {
            if (k & 4)
                cf[i] += 0.25 * c->corner[k][i];
            else
                cbk[i] += 0.25 * c->corner[k][i];
            cen[i] += 0.125 * c->corner[k][i];
        }
    for (int i = 0; i < 3; i++)
        axis[i] = cbk[i] - cf[i];
    if (fabs(P[3]) > 1e-12 * pm) {
        c->perspective = 1;
        for (int i = 0; i < 3; i++)
            c->prp[i] = P[i] / P[3];
        for (int i = 0; i < 3; i++)
            c->dop[i] = axis[i];
    } else {
        c->perspective = 0;
        for (int i = 0; i < 3; i++)
            c->dop[i] = P[i];
        if (c->dop[0] * axis[0] + c->dop[1] * axis[1] + c->dop[2] * axis[2] < 0.0)
            for (int i = 0; i < 3; i++)
                c->dop[i] = -c->dop[i];
    }
    rt_norm3(c->dop);
    double s = 0.0;
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++)
            s = fmax(s, fabs(c->corner[k][i] - cen[i]));
    c->scale = s;
}

/* clipping planes: faces by corner index bits; inside contains the centre cen */
static int rt_cam_planes(rt_camera *c, const double cen[3])
{
    static const int face[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                   {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    const double s = c->scale;
    for (int f = 0; f < 6; f++) {
        double n[3] = {0, 0, 0}, q[3] = {0, 0, 0};
        for (int e = 0; e < 4; e++) {
            const double *a = c->corner[face[f][e]], *b = c->corner[face[f][(e + 1) & 3]];
            double ax = a[0] - cen[0], ay = a[1] - cen[1], az = a[2] - cen[2];
            double bx = b[0] - cen[0], by = b[1] - cen[1], bz = b[2] - cen[2];
            n[0] += (ay - by) * (az + bz);
            n[1] += (az - bz) * (ax + bx);
            n[2] += (ax - bx) * (ay + by);
            for (int i = 0; i < 3; i++)
                q[i] += 0.25 * a[i];
        }
        double l = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2])));
        if (!(l > 1e-14 * s * s))
            return RT_ERR_SINGULAR;
        rt_norm3(n);
        double d = -(n[0] * q[0] + n[1] * q[1] + n[2] * q[2]);
        if (n[0] * cen[0] + n[1] * cen[1] + n[2] * cen[2] + d < 0.0) {
            for (int i = 0; i < 3; i++)
                n[i] = -n[i];
            d = -d;
        }
        for (int i = 0; i < 3; i++)
            c->plane[f][i] = n[i];
        c->plane[f][3] = d;
    }
    return RT_OK;
}

int rt_camera_from_view(rt_camera *cam, const double vmap[4][4], const double npc_box[6],
                        int width, int height)
{
    if (!cam || !vmap || !npc_box)
        return RT_ERR_ARG;
    if (width < 1 || height < 1 || width > 65536 || height > 65536)
        return RT_ERR_ARG;
    for (int i = 0; i < 6; i++)
        if (!isfinite(npc_box[i]))
            return RT_ERR_ARG;
    if (!(npc_box[0] < npc_box[1]) || !(npc_box[2] < npc_box[3]) || !(npc_box[4] < npc_box[5]))
        return RT_ERR_ARG;
    rt_camera c;
    memset(&c, 0, sizeof c);
    c.width = width;
    c.height = height;
    memcpy(c.box, npc_box, sizeof c.box);
    if (!rt_invert4(vmap, c.minv))
        return RT_ERR_SINGULAR;
    double cen[3];
    if (rt_cam_corners(&c, npc_box) != RT_OK)
        return RT_ERR_SINGULAR;
    rt_cam_projection(&c, cen);
    if (rt_cam_planes(&c, cen) != RT_OK)
        return RT_ERR_SINGULAR;
    /* raster on the front plane */
    double dx = (npc_box[1] - npc_box[0]) / width, dy = (npc_box[3] - npc_box[2]) / height;
    double o[3], a[3], b[3];
    if (!rt_unmap(&c, npc_box[0], npc_box[3], npc_box[5], o) ||
        !rt_unmap(&c, npc_box[0] + dx, npc_box[3], npc_box[5], a) ||
        !rt_unmap(&c, npc_box[0], npc_box[3] - dy, npc_box[5], b))
        return RT_ERR_SINGULAR;
    for (int i = 0; i < 3; i++) {
        c.origin[i] = o[i];
        c.du[i] = a[i] - o[i];
        c.dv[i] = b[i] - o[i];
    }
    *cam = c;
    return RT_OK;
}

/* Terms of a primary ray. The NPC point (x, y, z, 1) maps to h[k] = ((m[k][0]*x + m[k][1]*y) +
 * m[k][2]*z) + m[k][3] (the order of rt_unmap), so the products with x and with y can be
 * computed once per raster column and once per raster row: the rays stay bit for bit the ones
 * of the direct evaluation. */
void rt_camera_xterm(const rt_camera *cam, double px, double xt[4])
{
    double x = cam->box[0] + px * (cam->box[1] - cam->box[0]) / cam->width;
    for (int k = 0; k < 4; k++)
        xt[k] = cam->minv[k][0] * x;
}

void rt_camera_yterm(const rt_camera *cam, double py, double yt[4])
{
    double y = cam->box[3] - py * (cam->box[3] - cam->box[2]) / cam->height;
    for (int k = 0; k < 4; k++)
        yt[k] = cam->minv[k][1] * y;
}

/* The primary rays of n <= RT_CAM_ROW raster points of one row, from their terms: the front
 * and back points (x, y, zf) and (x, y, zb) through minv, divided; the ray from the front one
 * towards the back one, unit direction, tmax their distance. Written lane by lane for the
 * compiler's vector divisions; one ray (rt_camera_ray) takes the same path, so the same bits. */
void rt_camera_rays_row(const rt_camera *cam, const double (*xt)[4], int n, const double yt[4],
                        rt_ray *ray, int *ok)
{
    double f[3][RT_CAM_ROW], b[3][RT_CAM_ROW], hf3[RT_CAM_ROW], hb3[RT_CAM_ROW];
    double d[3][RT_CAM_ROW], m[RT_CAM_ROW], l[RT_CAM_ROW];
    if (n > RT_CAM_ROW)
        n = RT_CAM_ROW;
    const double zf = cam->box[5], zb = cam->box[4];
    for (int k = 0; k < 4; k++) {
        const double cf = cam->minv[k][2] * zf, cb = cam->minv[k][2] * zb, c3 = cam->minv[k][3];
        double *of = k < 3 ? f[k] : hf3, *ob = k < 3 ? b[k] : hb3;
        for (int i = 0; i < n; i++) {
            double xy = xt[i][k] + yt[k];
            of[i] = (xy + cf) + c3;
            ob[i] = (xy + cb) + c3;
        }
    }
    for (int i = 0; i < n; i++)
        ok[i] = fabs(hf3[i]) > 0.0 && fabs(hb3[i]) > 0.0;
    for (int i = 0; i < n; i++) {
        double wf = ok[i] ? hf3[i] : 1.0, wb = ok[i] ? hb3[i] : 1.0;
        for (int c = 0; c < 3; c++) {
            f[c][i] /= wf;
            b[c][i] /= wb;
        }
    }
    /* unusable rays get harmless values (no inf - inf, no 0 / 0: the tests trap them) */
    for (int i = 0; i < n; i++) {
        int fin = ok[i];
        for (int c = 0; c < 3; c++)
            fin &= isfinite(f[c][i]) && isfinite(b[c][i]);
        for (int c = 0; c < 3; c++) {
            if (!fin)
                f[c][i] = b[c][i] = 0.0;
            d[c][i] = b[c][i] - f[c][i];
        }
        double a0 = fabs(d[0][i]), a1 = fabs(d[1][i]), a2 = fabs(d[2][i]);
        double mm = a1 > a2 ? a1 : a2;
        mm = a0 > mm ? a0 : mm;
        ok[i] = fin && mm > 0.0 && isfinite(mm);
        if (!ok[i]) {
            d[0][i] = 1.0;
            d[1][i] = d[2][i] = 0.0;
            mm = 1.0;
        }
        m[i] = mm;
    }
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < n; i++)
            d[c][i] /= m[i];
    for (int i = 0; i < n; i++)
        l[i] = sqrt(d[0][i] * d[0][i] + d[1][i] * d[1][i] + d[2][i] * d[2][i]);
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < n; i++)
            d[c][i] /= l[i];
    for (int i = 0; i < n; i++) {
        for (int c = 0; c < 3; c++) {
            ray[i].org[c] = f[c][i];
            ray[i].dir[c] = d[c][i];
        }
        ray[i].tmin = 0.0;
        ray[i].tmax = m[i] * l[i];
    }
}

int rt_camera_vmap(const rt_camera *cam, double vm[4][4], double *wsign)
{
    if (!rt_invert4(cam->minv, vm))
        return 0;
    /* w of the display volume's centre: points in front of the eye plane share its sign */
    double c[4] = {0, 0, 0, 1}, h[4];
    for (int k = 0; k < 8; k++)
        for (int i = 0; i < 3; i++)
            c[i] += 0.125 * cam->corner[k][i];
    rt_mul4(vm, c, h);
    double hm = fmax(fabs(h[0]), fmax(fabs(h[1]), fabs(h[2])));
    if (!(fabs(h[3]) > 1e-9 * hm) || !isfinite(h[3]))
        return 0;
    *wsign = h[3] > 0.0 ? 1.0 : -1.0;
    return 1;
}

int rt_camera_project(const rt_camera *cam, const double vm[4][4], double wsign, const double p[3],
                      double *px, double *py)
{
    double v[4] = {p[0], p[1], p[2], 1.0}, h[4];
    rt_mul4(vm, v, h);
    double hm = fmax(fabs(h[0]), fmax(fabs(h[1]), fabs(h[2])));
    if (!(h[3] * wsign > 1e-9 * hm) || !isfinite(h[3]) || !isfinite(hm))
        return 0;
    double x = h[0] / h[3], y = h[1] / h[3];
    *px = (x - cam->box[0]) * cam->width / (cam->box[1] - cam->box[0]);
    *py = (cam->box[3] - y) * cam->height / (cam->box[3] - cam->box[2]);
    return isfinite(*px) && isfinite(*py);
}

int rt_camera_ray(const rt_camera *cam, double px, double py, rt_ray *ray)
{
    if (!cam || !ray || !isfinite(px) || !isfinite(py) || cam->width < 1 || cam->height < 1)
        return RT_ERR_ARG;
    double xt[4], yt[4];
    rt_camera_xterm(cam, px, xt);
    rt_camera_yterm(cam, py, yt);
    int ok;
    rt_camera_rays_row(cam, (const double(*)[4])xt, 1, yt, ray, &ok);
    return ok ? RT_OK : RT_ERR_ARG;
}
