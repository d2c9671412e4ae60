/* SPDX-License-Identifier: MIT */
/* rt_testutil.c -- see rt_testutil.h */
#include "rt_testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

/* The test data (tests/data) is stored gzip-compressed; gzopen also reads plain files.
 * The data is inflated into an anonymous temporary file so that the loaders below can use
 * stdio's scanning. NULL if the file cannot be read. */
static FILE *open_data(const char *path)
{
    gzFile gz = gzopen(path, "rb");
    if (!gz)
        return NULL;
    FILE *f = tmpfile();
    char buf[1 << 16];
    int n = 0;
    while (f && (n = gzread(gz, buf, sizeof buf)) > 0)
        if (fwrite(buf, 1, (size_t)n, f) != (size_t)n)
            n = -1;
    if (gzclose(gz) != Z_OK || n < 0) {
        if (f)
            fclose(f);
        return NULL;
    }
    if (f)
        rewind(f);
    return f;
}

void rtu_view_matrix(const rtu_view *v, double m[4][4])
{
    double umin = v->win[0], umax = v->win[1], vmin = v->win[2], vmax = v->win[3];
    double xmin = v->vp[0], xmax = v->vp[1], ymin = v->vp[2], ymax = v->vp[3];
    double zmin = v->vp[4], zmax = v->vp[5];
    double cu = 0.5 * (umin + umax), cv = 0.5 * (vmin + vmax);
    double Sx = (xmax - xmin) / (umax - umin), Sy = (ymax - ymin) / (vmax - vmin);
    double Dz = zmax - zmin, B = v->bpd, F = v->fpd, VPD = v->vpd;
    double pu = v->prp[0], pv = v->prp[1], pn = v->prp[2];
    memset(m, 0, 16 * sizeof(double));
    if (!v->perspective) {
        double hx = (pu - cu) / (VPD - pn), hy = (pv - cv) / (VPD - pn);
        m[0][0] = Sx; m[0][2] = Sx * hx; m[0][3] = xmin - Sx * (hx * VPD + umin);
        m[1][1] = Sy; m[1][2] = Sy * hy; m[1][3] = ymin - Sy * (hy * VPD + vmin);
        m[2][2] = Dz / (F - B); m[2][3] = zmin - B * Dz / (F - B);
        m[3][3] = 1.0;
        return;
    }
    /* x*w = a*(pn - n) + Sx*(pn - VPD)*(u - pu), a = xmin + Sx*(pu - umin), w = pn - n */
    double ax = xmin + Sx * (pu - umin), ay = ymin + Sy * (pv - vmin);
    m[0][0] = Sx * (pn - VPD); m[0][2] = -ax; m[0][3] = ax * pn - Sx * (pn - VPD) * pu;
    m[1][1] = Sy * (pn - VPD); m[1][2] = -ay; m[1][3] = ay * pn - Sy * (pn - VPD) * pv;
    double K = Dz / (1.0 / (pn - F) - 1.0 / (pn - B));
    m[2][2] = -zmin + K / (pn - B);
    m[2][3] = zmin * pn + K - K * pn / (pn - B);
    m[3][2] = -1.0;
    m[3][3] = pn;
}

void rtu_view_projector(const rtu_view *v, double x, double y, double front[3], double back[3])
{
    double umin = v->win[0], umax = v->win[1], vmin = v->win[2], vmax = v->win[3];
    double Sx = (v->vp[1] - v->vp[0]) / (umax - umin), Sy = (v->vp[3] - v->vp[2]) / (vmax - vmin);
    /* point on the view plane */
    double u1 = umin + (x - v->vp[0]) / Sx, v1 = vmin + (y - v->vp[2]) / Sy;
    double q[3] = {u1, v1, v->vpd};
    double d[3];
    if (v->perspective) {
        for (int i = 0; i < 3; i++)
            d[i] = q[i] - v->prp[i];
        double tf = (v->fpd - v->prp[2]) / d[2], tb = (v->bpd - v->prp[2]) / d[2];
        for (int i = 0; i < 3; i++) {
            front[i] = v->prp[i] + tf * d[i];
            back[i] = v->prp[i] + tb * d[i];
        }
        return;
    }
    double cu = 0.5 * (umin + umax), cv = 0.5 * (vmin + vmax);
    d[0] = cu - v->prp[0];
    d[1] = cv - v->prp[1];
    d[2] = v->vpd - v->prp[2];
    double tf = (v->fpd - v->vpd) / d[2], tb = (v->bpd - v->vpd) / d[2];
    for (int i = 0; i < 3; i++) {
        front[i] = q[i] + tf * d[i];
        back[i] = q[i] + tb * d[i];
    }
}

static void norm3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; i++)
        v[i] /= l;
}

void rtu_lookat(const double from[3], const double at[3], const double up[3], double m[4][4])
{
    double n[3] = {from[0] - at[0], from[1] - at[1], from[2] - at[2]}, u[3], v[3];
    norm3(n);
    u[0] = up[1] * n[2] - up[2] * n[1];
    u[1] = up[2] * n[0] - up[0] * n[2];
    u[2] = up[0] * n[1] - up[1] * n[0];
    norm3(u);
    v[0] = n[1] * u[2] - n[2] * u[1];
    v[1] = n[2] * u[0] - n[0] * u[2];
    v[2] = n[0] * u[1] - n[1] * u[0];
    memset(m, 0, 16 * sizeof(double));
    for (int i = 0; i < 3; i++) {
        m[0][i] = u[i];
        m[1][i] = v[i];
        m[2][i] = n[i];
    }
    for (int r = 0; r < 3; r++)
        m[r][3] = -(m[r][0] * from[0] + m[r][1] * from[1] + m[r][2] * from[2]);
    m[3][3] = 1.0;
}

void rtu_xform_point(const double m[4][4], const double p[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; i++)
        r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    memcpy(out, r, sizeof r);
}

static int grow(void **p, size_t *cap, size_t need, size_t es)
{
    if (need <= *cap)
        return 1;
    size_t nc = *cap ? *cap * 2 : 1024;
    while (nc < need)
        nc *= 2;
    void *q = realloc(*p, nc * es);
    if (!q)
        return 0;
    *p = q;
    *cap = nc;
    return 1;
}

typedef struct {
    size_t cxyz, ccounts, cidx, csurf, csurfs, clights;
} caps;

static int add_vertex(rtu_mesh *m, caps *c, const double p[3])
{
    if (!grow((void **)&m->xyz, &c->cxyz, 3 * (size_t)(m->nv + 1), sizeof(double)))
        return -1;
    memcpy(m->xyz + 3 * (size_t)m->nv, p, 3 * sizeof(double));
    return m->nv++;
}

static int add_poly(rtu_mesh *m, caps *c, int n, const int *ix, int surf)
{
    if (!grow((void **)&m->counts, &c->ccounts, (size_t)m->np + 1, sizeof(int)) ||
        !grow((void **)&m->surf, &c->csurf, (size_t)m->np + 1, sizeof(int)) ||
        !grow((void **)&m->idx, &c->cidx, m->nidx + (size_t)n, sizeof(int)))
        return -1;
    m->counts[m->np] = n;
    m->surf[m->np] = surf;
    memcpy(m->idx + m->nidx, ix, (size_t)n * sizeof(int));
    m->nidx += (size_t)n;
    m->np++;
    return 0;
}

int rtu_load_off(const char *path, rtu_mesh *m)
{
    memset(m, 0, sizeof *m);
    FILE *f = open_data(path);
    if (!f)
        return -1;
    char hdr[64];
    int nv, nf, ne;
    caps c = {0};
    if (fscanf(f, "%63s", hdr) != 1 || strcmp(hdr, "OFF") != 0 || fscanf(f, "%d %d %d", &nv, &nf, &ne) != 3) {
        fclose(f);
        return -1;
    }
    for (int i = 0; i < nv; i++) {
        double p[3];
        if (fscanf(f, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3 || add_vertex(m, &c, p) < 0)
            goto fail;
    }
    for (int i = 0; i < nf; i++) {
        int n, ix[64];
        if (fscanf(f, "%d", &n) != 1 || n < 1 || n > 64)
            goto fail;
        for (int k = 0; k < n; k++)
            if (fscanf(f, "%d", &ix[k]) != 1 || ix[k] < 0 || ix[k] >= nv)
                goto fail;
        int ch; /* skip optional colour on the line */
        while ((ch = fgetc(f)) != '\n' && ch != EOF) {
        }
        if (add_poly(m, &c, n, ix, 0) < 0)
            goto fail;
    }
    fclose(f);
    return 0;
fail:
    fclose(f);
    rtu_mesh_free(m);
    return -1;
}

int rtu_load_nff(const char *path, rtu_mesh *m)
{
    memset(m, 0, sizeof *m);
    FILE *f = open_data(path);
    if (!f)
        return -1;
    caps c = {0};
    char tok[64];
    int cur = -1;
    while (fscanf(f, "%63s", tok) == 1) {
        if (strcmp(tok, "v") == 0) {
            char w[32];
            if (fscanf(f, "%31s %lf %lf %lf", w, &m->from[0], &m->from[1], &m->from[2]) != 4 ||
                fscanf(f, "%31s %lf %lf %lf", w, &m->at[0], &m->at[1], &m->at[2]) != 4 ||
                fscanf(f, "%31s %lf %lf %lf", w, &m->up[0], &m->up[1], &m->up[2]) != 4 ||
                fscanf(f, "%31s %lf", w, &m->angle) != 2 || fscanf(f, "%31s %lf", w, &m->hither) != 2 ||
                fscanf(f, "%31s %d %d", w, &m->res[0], &m->res[1]) != 3)
                goto fail;
            m->has_view = 1;
        } else if (strcmp(tok, "b") == 0) {
            if (fscanf(f, "%lf %lf %lf", &m->bg[0], &m->bg[1], &m->bg[2]) != 3)
                goto fail;
        } else if (strcmp(tok, "l") == 0) {
            double p[3];
            if (fscanf(f, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3)
                goto fail;
            if (!grow((void **)&m->lights, &c.clights, (size_t)m->nlights + 1, sizeof *m->lights))
                goto fail;
            memcpy(m->lights[m->nlights++], p, sizeof p);
        } else if (strcmp(tok, "f") == 0) {
            double r, g, b, kd, ks, sh, t, ior;
            if (fscanf(f, "%lf %lf %lf %lf %lf %lf %lf %lf", &r, &g, &b, &kd, &ks, &sh, &t, &ior) != 8)
                goto fail;
            if (!grow((void **)&m->surfs, &c.csurfs, (size_t)m->nsurfs + 1, sizeof *m->surfs))
                goto fail;
            rt_surface *s = &m->surfs[m->nsurfs];
            rt_surface_default(s);
            s->refl_eq = RT_REFL_SPECULAR;
            s->ka = 0.0;
            s->kd = kd;
            s->ks = ks;
            s->diffuse[0] = r; s->diffuse[1] = g; s->diffuse[2] = b;
            s->spec_exp = sh;
            s->transparency = t > 1.0 ? 1.0 : t;
            s->refr_index = ior > 0.0 ? ior : 1.0;
            cur = m->nsurfs++;
        } else if (strcmp(tok, "p") == 0 || strcmp(tok, "pp") == 0) {
            int n, pp = tok[1] == 'p';
            if (fscanf(f, "%d", &n) != 1 || n < 1 || n > 100000)
                goto fail;
            int *ix = malloc((size_t)n * sizeof(int));
            if (!ix)
                goto fail;
            for (int k = 0; k < n; k++) {
                double p[3], nn[3];
                if (fscanf(f, "%lf %lf %lf", &p[0], &p[1], &p[2]) != 3 ||
                    (pp && fscanf(f, "%lf %lf %lf", &nn[0], &nn[1], &nn[2]) != 3) ||
                    (ix[k] = add_vertex(m, &c, p)) < 0) {
                    free(ix);
                    goto fail;
                }
            }
            int rc = add_poly(m, &c, n, ix, cur < 0 ? 0 : cur);
            free(ix);
            if (rc < 0)
                goto fail;
        } else {
            int ch; /* unsupported primitive (s, c) or comment: skip the line */
            while ((ch = fgetc(f)) != '\n' && ch != EOF) {
            }
        }
    }
    fclose(f);
    return 0;
fail:
    fclose(f);
    rtu_mesh_free(m);
    return -1;
}

void rtu_mesh_free(rtu_mesh *m)
{
    free(m->xyz);
    free(m->counts);
    free(m->idx);
    free(m->surf);
    free(m->surfs);
    free(m->lights);
    memset(m, 0, sizeof *m);
}

void rtu_mesh_transform(rtu_mesh *m, const double vo[4][4])
{
    for (int i = 0; i < m->nv; i++)
        rtu_xform_point(vo, m->xyz + 3 * i, m->xyz + 3 * i);
    for (int i = 0; i < m->nlights; i++)
        rtu_xform_point(vo, m->lights[i], m->lights[i]);
}

void rtu_mesh_bbox(const rtu_mesh *m, double bb[6])
{
    for (int i = 0; i < 3; i++) {
        bb[i] = INFINITY;
        bb[3 + i] = -INFINITY;
    }
    for (int k = 0; k < m->nv; k++)
        for (int i = 0; i < 3; i++) {
            bb[i] = fmin(bb[i], m->xyz[3 * k + i]);
            bb[3 + i] = fmax(bb[3 + i], m->xyz[3 * k + i]);
        }
}

int rtu_mesh_add(const rtu_mesh *m, rt_scene *sc, int default_surface)
{
    int base = -1;
    for (int i = 0; i < m->nsurfs; i++) {
        int id = rt_scene_add_surface(sc, &m->surfs[i]);
        if (id < 0)
            return -1;
        if (base < 0)
            base = id;
    }
    for (int i = 0; i < m->nlights; i++) {
        rt_light l;
        memset(&l, 0, sizeof l);
        l.type = RT_LIGHT_POSITIONAL;
        double in = 1.0 / sqrt((double)m->nlights);
        l.color[0] = l.color[1] = l.color[2] = in;
        memcpy(l.position, m->lights[i], sizeof l.position);
        l.c1 = 1.0;
        if (rt_scene_add_light(sc, &l) < 0)
            break; /* more than 64 lights: ignored */
    }
    size_t off = 0;
    double *buf = NULL;
    size_t cap = 0;
    for (int p = 0; p < m->np; p++) {
        int n = m->counts[p];
        if (!grow((void **)&buf, &cap, 3 * (size_t)n, sizeof(double))) {
            free(buf);
            return -1;
        }
        for (int k = 0; k < n; k++)
            memcpy(buf + 3 * k, m->xyz + 3 * (size_t)m->idx[off + (size_t)k], 3 * sizeof(double));
        off += (size_t)n;
        int s = m->nsurfs ? base + m->surf[p] : default_surface;
        if (rt_scene_add_polygon(sc, 1, &n, buf, s, s) < 0) {
            free(buf);
            return -1;
        }
    }
    free(buf);
    return 0;
}

void rtu_nff_view(const rtu_mesh *m, const double bb[6], rtu_view *v)
{
    memset(v, 0, sizeof *v);
    double h = tan(0.5 * m->angle * 3.14159265358979323846 / 180.0);
    double far = 0.0;
    for (int k = 0; k < 8; k++) {
        double p[3] = {bb[k & 1 ? 3 : 0], bb[k & 2 ? 4 : 1], bb[k & 4 ? 5 : 2]};
        far = fmax(far, sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
    v->perspective = 1;
    v->win[0] = -h; v->win[1] = h; v->win[2] = -h; v->win[3] = h;
    v->vpd = -1.0;
    v->fpd = -(m->hither > 0.0 ? m->hither : 1e-3 * far);
    v->bpd = -1.01 * far - 1.0;
    v->vp[1] = v->vp[3] = v->vp[5] = 1.0;
}

rt_scene *rtu_nff_scene(const char *path, double sky, int w, int h, rt_camera *cam)
{
    rtu_mesh mesh;
    if (rtu_load_nff(path, &mesh))
        return NULL;
    double vo[4][4], bb[6], m[4][4];
    rtu_lookat(mesh.from, mesh.at, mesh.up, vo);
    rtu_mesh_transform(&mesh, vo);
    rtu_mesh_bbox(&mesh, bb);
    rtu_view v;
    rtu_nff_view(&mesh, bb, &v);
    v.win[3] += sky * (v.win[3] - v.win[2]);
    rtu_view_matrix(&v, m);
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    if (!sc || rtu_mesh_add(&mesh, sc, rt_scene_add_surface(sc, &s)) != 0 ||
        rt_scene_commit(sc, NULL) != RT_OK || rt_camera_from_view(cam, m, v.vp, w, h) != RT_OK) {
        rt_scene_free(sc);
        sc = NULL;
    }
    rtu_mesh_free(&mesh);
    return sc;
}

/* ---- closed-mesh leak probe ---- */

double rtu_rand(uint64_t *state)
{
    *state = *state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)(*state >> 11) * 0x1.0p-53;
}

void rtu_rand_dir(uint64_t *state, double d[3])
{
    for (;;) {
        double l2 = 0.0;
        for (int i = 0; i < 3; i++) {
            d[i] = 2.0 * rtu_rand(state) - 1.0;
            l2 += d[i] * d[i];
        }
        if (l2 > 1e-4 && l2 <= 1.0) {
            double l = sqrt(l2);
            for (int i = 0; i < 3; i++)
                d[i] /= l;
            return;
        }
    }
}

static int rtu_certify_inside(const rt_scene *sc, const double q[3], uint64_t *rng, int *inner)
{
    int side = -1;
    for (int k = 0; k < 16; k++) {
        rt_ray r;
        rt_hit h;
        memcpy(r.org, q, sizeof r.org);
        rtu_rand_dir(rng, r.dir);
        r.tmin = 0.0;
        r.tmax = INFINITY;
        if (rt_intersect(sc, 1, &r, &h) != RT_OK || h.prim < 0)
            return 0;
        if (side >= 0 && h.side != side)
            return 0;
        side = h.side;
    }
    *inner = side;
    return 1;
}

int rtu_interior_point(const rtu_mesh *m, const rt_scene *sc, double p[3], int *inner_side)
{
    double bb[6];
    rtu_mesh_bbox(m, bb);
    double diag = sqrt((bb[3] - bb[0]) * (bb[3] - bb[0]) + (bb[4] - bb[1]) * (bb[4] - bb[1]) +
                       (bb[5] - bb[2]) * (bb[5] - bb[2]));
    uint64_t rng = 99;
    size_t off = 0;
    for (int f = 0; f < m->np; f++) {
        int nv = m->counts[f];
        const int *ix = m->idx + off;
        off += (size_t)nv;
        if (nv != 3 || f % 101 != 0)
            continue;
        const double *a = m->xyz + 3 * ix[0], *b = m->xyz + 3 * ix[1], *c = m->xyz + 3 * ix[2];
        double e1[3], e2[3], n[3], cen[3];
        for (int i = 0; i < 3; i++) {
            e1[i] = b[i] - a[i];
            e2[i] = c[i] - a[i];
            cen[i] = (a[i] + b[i] + c[i]) / 3.0;
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(l > 0.0))
            continue;
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            rt_ray r;
            rt_hit h;
            for (int i = 0; i < 3; i++) {
                r.dir[i] = sgn * n[i] / l;
                r.org[i] = cen[i] + 1e-5 * diag * r.dir[i];
            }
            r.tmin = 0.0;
            r.tmax = INFINITY;
            if (rt_intersect(sc, 1, &r, &h) != RT_OK || h.prim < 0)
                continue;
            double q[3];
            for (int i = 0; i < 3; i++)
                q[i] = r.org[i] + 0.5 * h.t * r.dir[i];
            if (rtu_certify_inside(sc, q, &rng, inner_side)) {
                memcpy(p, q, sizeof q);
                return 0;
            }
        }
    }
    return -1;
}

static int rtu_cmp_edge(const void *x, const void *y)
{
    const int *a = x, *b = y;
    if (a[0] != b[0])
        return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

int rtu_leak_rays(const rtu_mesh *m, const double p[3], size_t nrand, uint64_t seed,
                  rt_ray **rays, size_t *n, size_t *nvert, size_t *nedge)
{
    int *edges = malloc(2 * m->nidx * sizeof(int));
    if (!edges)
        return -1;
    size_t ne = 0, off = 0;
    for (int f = 0; f < m->np; f++) {
        int nv = m->counts[f];
        for (int k = 0; k < nv; k++) {
            int a = m->idx[off + (size_t)k], b = m->idx[off + (size_t)((k + 1) % nv)];
            edges[2 * ne] = a < b ? a : b;
            edges[2 * ne + 1] = a < b ? b : a;
            ne++;
        }
        off += (size_t)nv;
    }
    qsort(edges, ne, 2 * sizeof(int), rtu_cmp_edge);
    size_t nu = 0;
    for (size_t k = 0; k < ne; k++)
        if (nu == 0 || rtu_cmp_edge(edges + 2 * k, edges + 2 * (nu - 1)) != 0) {
            edges[2 * nu] = edges[2 * k];
            edges[2 * nu + 1] = edges[2 * k + 1];
            nu++;
        }
    size_t total = (size_t)m->nv + nu + nrand;
    rt_ray *r = malloc(total * sizeof *r);
    if (!r) {
        free(edges);
        return -1;
    }
    size_t k = 0;
    for (int v = 0; v < m->nv; v++, k++)
        for (int i = 0; i < 3; i++)
            r[k].dir[i] = m->xyz[3 * v + i] - p[i];
    for (size_t e = 0; e < nu; e++, k++)
        for (int i = 0; i < 3; i++)
            r[k].dir[i] = 0.5 * (m->xyz[3 * edges[2 * e] + i] + m->xyz[3 * edges[2 * e + 1] + i]) - p[i];
    uint64_t rng = seed;
    for (size_t j = 0; j < nrand; j++, k++)
        rtu_rand_dir(&rng, r[k].dir);
    for (size_t j = 0; j < total; j++) {
        memcpy(r[j].org, p, 3 * sizeof(double));
        r[j].tmin = 0.0;
        r[j].tmax = INFINITY;
    }
    free(edges);
    *rays = r;
    *n = total;
    *nvert = (size_t)m->nv;
    *nedge = nu;
    return 0;
}

void rtu_options_plain(rt_render_options *o)
{
    rt_render_options_default(o);
    o->corner_rays = 0;
    o->cutoff = 0.0;
}

rt_scene *rtu_scene_one_surface(int *surf)
{
    rt_scene *sc = rt_scene_new();
    if (!sc)
        return NULL;
    rt_surface s;
    rt_surface_default(&s);
    *surf = rt_scene_add_surface(sc, &s);
    if (*surf < 0) {
        rt_scene_free(sc);
        return NULL;
    }
    return sc;
}

int rtu_add_sphere(rt_scene *sc, const double c[3], double r, int nu, int nv, int s)
{
    return rtu_add_sphere_data(sc, c, r, nu, nv, s, 0);
}

int rtu_add_sphere_data(rt_scene *sc, const double c[3], double r, int nu, int nv, int s,
                        int normals)
{
    for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
            double p[4][3], q[4][3];
            for (int k = 0; k < 4; k++) {
                const int ii = i + (k == 1 || k == 2), jj = j + (k >= 2);
                const double pi = 3.14159265358979323846; /* M_PI is not ISO C */
                const double th = pi * jj / nv, ph = 2 * pi * (ii % nu) / nu;
                q[k][0] = sin(th) * cos(ph);
                q[k][1] = sin(th) * sin(ph);
                q[k][2] = cos(th);
                for (int a = 0; a < 3; a++)
                    p[k][a] = c[a] + r * q[k][a];
            }
            for (int t = 0; t < 2; t++) { /* (0, 1, 2) and (0, 2, 3), none at a pole */
                if ((t == 0 && j == 0) || (t == 1 && j == nv - 1))
                    continue;
                const int n = 3;
                const double v[9] = {p[0][0], p[0][1], p[0][2], p[1 + t][0], p[1 + t][1],
                                     p[1 + t][2], p[2 + t][0], p[2 + t][1], p[2 + t][2]};
                const double w[9] = {q[0][0], q[0][1], q[0][2], q[1 + t][0], q[1 + t][1],
                                     q[1 + t][2], q[2 + t][0], q[2 + t][1], q[2 + t][2]};
                const rt_vertex_data vd = {w, NULL};
                if (rt_scene_add_polygon_data(sc, 1, &n, v, normals ? &vd : NULL, s, s) < 0)
                    return -1;
            }
        }
    return 0;
}

int rtu_load_scene_vrc(const char *path, rtu_mesh *m, double bb[6])
{
    size_t n = strlen(path);
    int isoff = (n > 4 && !strcmp(path + n - 4, ".off")) || (n > 7 && !strcmp(path + n - 7, ".off.gz"));
    if ((isoff ? rtu_load_off(path, m) : rtu_load_nff(path, m)) != 0)
        return -1;
    rtu_mesh_bbox(m, bb);
    if (!m->has_view) {
        double c[3] = {0.5 * (bb[0] + bb[3]), 0.5 * (bb[1] + bb[4]), 0.5 * (bb[2] + bb[5])};
        double r = 0.5 * sqrt((bb[3] - bb[0]) * (bb[3] - bb[0]) + (bb[4] - bb[1]) * (bb[4] - bb[1]) +
                              (bb[5] - bb[2]) * (bb[5] - bb[2]));
        memcpy(m->at, c, sizeof c);
        memcpy(m->from, c, sizeof c);
        m->from[2] += 3.0 * r;
        m->up[1] = 1.0;
        m->angle = 40.0;
        m->hither = 0.01 * r;
    }
    double vo[4][4];
    rtu_lookat(m->from, m->at, m->up, vo);
    rtu_mesh_transform(m, vo);
    rtu_mesh_bbox(m, bb);
    return 0;
}

int rtu_same_hit(const rt_hit *a, const rt_hit *b)
{
    return a->prim == b->prim &&
           (a->prim < 0 || (a->side == b->side && memcmp(&a->t, &b->t, sizeof a->t) == 0 &&
                            memcmp(a->p, b->p, sizeof a->p) == 0 &&
                            memcmp(a->ng, b->ng, sizeof a->ng) == 0));
}
