/* SPDX-License-Identifier: MIT */
/*
 * scene_io.c -- NFF, OFF and PLY (ASCII, optionally gzip'd) readers; see scene_io.h.
 *
 * The whole input is held in memory (at most options.max_bytes) and parsed line by line:
 * every record sits on its own line, as the format descriptions and the SPD generators have
 * it. Declared counts are checked against the bytes left before anything is reserved for
 * them; otherwise arrays grow with what was actually read.
 */
#include "scene_io.h"

#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

#define SIO_DEFAULT_MAX_BYTES ((size_t)1 << 30)
#define SIO_MAX_TESS 1024
#define SIO_PI 3.14159265358979323846

typedef struct { const char *s; size_t n; } sio_tok;

typedef struct {
    const char *p, *end;     /* cursor and end of input */
    const char *name;        /* for messages */
    size_t line;             /* line of the cursor (1-based) */
    char *err;
    size_t err_size;
    const scene_io_options *opt;
    scene_io_scene *s;
    size_t cap_vert, cap_norm, cap_nverts, cap_pmat, cap_pstart, cap_idx, cap_mat, cap_light;
    size_t cur_mat;          /* SIZE_MAX: no "f" yet */
    int warned_sphere, warned_cone;
} sio_reader;

/* ---- messages and allocation ----------------------------------------------------------- */

static int sio_fail(sio_reader *r, int code, const char *fmt, ...)
{
    if (!r->err || r->err_size == 0)
        return code;
    int n = snprintf(r->err, r->err_size, "%s:%zu: ", r->name, r->line);
    if (n < 0 || (size_t)n >= r->err_size)
        return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->err + n, r->err_size - (size_t)n, fmt, ap);
    va_end(ap);
    return code;
}

static void sio_warn(sio_reader *r, const char *fmt, ...)
{
    if (!r->opt->warn)
        return;
    char buf[256];
    int n = snprintf(buf, sizeof buf, "%s:%zu: warning: ", r->name, r->line);
    if (n < 0 || (size_t)n >= sizeof buf)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf + n, sizeof buf - (size_t)n, fmt, ap);
    va_end(ap);
    r->opt->warn(r->opt->warn_ctx, buf);
}

/* Printable, shortened copy of a token for messages. */
static const char *sio_show(const sio_tok *t, char buf[32])
{
    size_t n = t->n < 24 ? t->n : 24, k = 0;
    for (size_t i = 0; i < n; i++)
        buf[k++] = isprint((unsigned char)t->s[i]) ? t->s[i] : '?';
    if (t->n > n) {
        buf[k++] = '.'; buf[k++] = '.'; buf[k++] = '.';
    }
    buf[k] = '\0';
    return buf;
}

/* Grows *p (capacity *cap elements of es bytes) to hold need elements; overflow checked. */
static int sio_grow(void **p, size_t *cap, size_t need, size_t es)
{
    if (need <= *cap)
        return 0;
    size_t nc = *cap ? *cap : 16;
    while (nc < need) {
        if (nc > SIZE_MAX / 2)
            return -1;
        nc *= 2;
    }
    if (es == 0 || nc > SIZE_MAX / es)
        return -1;
    void *q = realloc(*p, nc * es);
    if (!q)
        return -1;
    *p = q;
    *cap = nc;
    return 0;
}

/* ---- lexing: tokens within a line ------------------------------------------------------ */

/* Skips blank and comment-only lines; 0 at end of input, else 1 with the cursor on a token. */
static int sio_begin_line(sio_reader *r)
{
    while (r->p < r->end) {
        char c = *r->p;
        if (c == '\n') {
            r->line++;
            r->p++;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            r->p++;
        } else if (c == '#') {
            while (r->p < r->end && *r->p != '\n')
                r->p++;
        } else {
            return 1;
        }
    }
    return 0;
}

/* Next token on the current line; 0 at the end of the line (newline not consumed). */
static int sio_tok_next(sio_reader *r, sio_tok *t)
{
    while (r->p < r->end && (*r->p == ' ' || *r->p == '\t' || *r->p == '\r' || *r->p == '\f' ||
                             *r->p == '\v'))
        r->p++;
    if (r->p < r->end && *r->p == '#')
        while (r->p < r->end && *r->p != '\n')
            r->p++;
    if (r->p >= r->end || *r->p == '\n')
        return 0;
    t->s = r->p;
    while (r->p < r->end && !isspace((unsigned char)*r->p) && *r->p != '#')
        r->p++;
    t->n = (size_t)(r->p - t->s);
    return 1;
}

/* Ends the current line (strict: another token on it is an error). The cursor stays on
 * the newline, so checks of the record that follow still report its line number; the next
 * sio_begin_line moves on. */
static int sio_end_line(sio_reader *r, int strict, const char *what)
{
    sio_tok t;
    if (strict && sio_tok_next(r, &t)) {
        char b[32];
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected '%s' after %s", sio_show(&t, b), what);
    }
    while (r->p < r->end && *r->p != '\n')
        r->p++;
    return SCENE_IO_OK;
}

static int sio_tok_is(const sio_tok *t, const char *word)
{
    size_t n = strlen(word);
    return t->n == n && memcmp(t->s, word, n) == 0;
}

static size_t sio_remaining(const sio_reader *r)
{
    return (size_t)(r->end - r->p);
}

/* ---- numbers --------------------------------------------------------------------------- */

/* Decimal token [+-]digits[.digits][e[+-]digits] with at most 15 significant digits and a
 * decimal exponent within +-22: the digits are an exact integer below 2^53 and the power of
 * ten is exact, so one IEEE multiplication or division rounds the value correctly, as strtod
 * does (Clinger's fast path). 0 if the token is not of that form (strtod decides then). */
static int sio_fast_num(const char *s, size_t n, double *v)
{
    static const double p10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                   1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                   1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    size_t i = 0;
    int neg = 0;
    if (i < n && (s[i] == '+' || s[i] == '-'))
        neg = s[i++] == '-';
    uint64_t m = 0;
    int sig = 0, digits = 0, scale = 0; /* value = m * 10^(scale + exponent) */
    for (int frac = 0; i < n; i++) {
        if (s[i] == '.' && !frac) {
            frac = 1;
            continue;
        }
        if (s[i] < '0' || s[i] > '9')
            break;
        digits++;
        if (m == 0 && s[i] == '0') { /* leading zeros: not significant */
            scale -= frac;
            continue;
        }
        if (++sig > 15)
            return 0;
        m = 10 * m + (uint64_t)(s[i] - '0');
        scale -= frac;
    }
    if (digits == 0)
        return 0;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        int eneg = 0, e = 0, ed = 0;
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-'))
            eneg = s[i++] == '-';
        for (; i < n && s[i] >= '0' && s[i] <= '9'; i++, ed++)
            if ((e = 10 * e + (s[i] - '0')) > 1000)
                return 0;
        if (ed == 0)
            return 0;
        scale += eneg ? -e : e;
    }
    if (i != n || scale < -22 || scale > 22)
        return 0;
    double x = (double)m;
    x = scale < 0 ? x / p10[-scale] : x * p10[scale];
    *v = neg ? -x : x;
    return 1;
}

static int sio_num(sio_reader *r, const sio_tok *t, const char *what, double *v)
{
    if (sio_fast_num(t->s, t->n, v))
        return SCENE_IO_OK;
    char buf[64], b[32];
    if (t->n >= sizeof buf)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "number too long for %s: '%s'", what, sio_show(t, b));
    memcpy(buf, t->s, t->n);
    buf[t->n] = '\0';
    char *e;
    double x = strtod(buf, &e);
    if (e != buf + t->n || t->n == 0)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "bad number for %s: '%s'", what, sio_show(t, b));
    if (!isfinite(x))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "non-finite number for %s: '%s'", what,
                        sio_show(t, b));
    *v = x;
    return SCENE_IO_OK;
}

/* Reads n numbers from the current line into v. */
static int sio_nums(sio_reader *r, int n, const char *what, double *v)
{
    for (int i = 0; i < n; i++) {
        sio_tok t;
        if (!sio_tok_next(r, &t))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s needs %d numbers, got %d", what, n, i);
        int rc = sio_num(r, &t, what, &v[i]);
        if (rc)
            return rc;
    }
    return SCENE_IO_OK;
}

/* Unsigned decimal integer <= max. */
static int sio_count(sio_reader *r, const sio_tok *t, const char *what, unsigned long long max,
                     unsigned long long *v)
{
    char b[32];
    size_t i = (t->n > 0 && t->s[0] == '+') ? 1 : 0;
    if (i == t->n)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "bad count for %s: '%s'", what, sio_show(t, b));
    unsigned long long x = 0;
    for (; i < t->n; i++) {
        if (t->s[i] < '0' || t->s[i] > '9')
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "bad %s: '%s' (expected a non-negative integer)",
                            what, sio_show(t, b));
        unsigned d = (unsigned)(t->s[i] - '0');
        if (x > (max - d) / 10)
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s too large: '%s' (at most %llu)", what,
                            sio_show(t, b), max);
        x = x * 10 + d;
    }
    *v = x;
    return SCENE_IO_OK;
}

static int sio_count_next(sio_reader *r, const char *what, unsigned long long max,
                          unsigned long long *v)
{
    sio_tok t;
    if (!sio_tok_next(r, &t))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "missing %s", what);
    return sio_count(r, &t, what, max, v);
}

static int sio_nonneg(sio_reader *r, const double *v, int n, const char *what)
{
    for (int i = 0; i < n; i++)
        if (v[i] < 0)
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "negative value %g in %s", v[i], what);
    return SCENE_IO_OK;
}

/* ---- scene building -------------------------------------------------------------------- */

static int sio_nomem(sio_reader *r)
{
    return sio_fail(r, SCENE_IO_ERR_NOMEM, "out of memory");
}

/* Appends a vertex (normal may be NULL); its index in *idx. */
static int sio_add_vertex(sio_reader *r, const double xyz[3], const double *normal, uint32_t *idx)
{
    scene_io_scene *s = r->s;
    if (s->num_vertices >= (size_t)UINT32_MAX)
        return sio_fail(r, SCENE_IO_ERR_LIMIT, "more than %lu vertices", (unsigned long)UINT32_MAX);
    if (sio_grow((void **)&s->vertices, &r->cap_vert, s->num_vertices + 1, 3 * sizeof(double)))
        return sio_nomem(r);
    if (normal && !s->normals) {
        /* first vertex normal: earlier vertices get (0,0,0) */
        s->normals = calloc(r->cap_vert, 3 * sizeof(double));
        if (!s->normals)
            return sio_nomem(r);
        r->cap_norm = r->cap_vert;
    }
    if (s->normals &&
        sio_grow((void **)&s->normals, &r->cap_norm, s->num_vertices + 1, 3 * sizeof(double)))
        return sio_nomem(r);
    size_t i = s->num_vertices;
    memcpy(s->vertices + 3 * i, xyz, 3 * sizeof(double));
    if (s->normals) {
        if (normal)
            memcpy(s->normals + 3 * i, normal, 3 * sizeof(double));
        else
            memset(s->normals + 3 * i, 0, 3 * sizeof(double));
    }
    s->num_vertices++;
    *idx = (uint32_t)i;
    return SCENE_IO_OK;
}

/* The material for the next primitive: the current one, or a default white one. */
static int sio_material(sio_reader *r, uint32_t *m)
{
    scene_io_scene *s = r->s;
    if (r->cur_mat == SIZE_MAX) {
        if (sio_grow((void **)&s->materials, &r->cap_mat, s->num_materials + 1,
                     sizeof *s->materials))
            return sio_nomem(r);
        s->materials[s->num_materials] =
            (scene_io_material){ { 1, 1, 1 }, 1, 0, 1, 0, 1 };
        r->cur_mat = s->num_materials++;
    }
    *m = (uint32_t)r->cur_mat;
    return SCENE_IO_OK;
}

/* Appends a polygon of n vertex indices with the current material. */
static int sio_add_polygon(sio_reader *r, size_t n, const uint32_t *idx)
{
    scene_io_scene *s = r->s;
    if (s->num_polygons >= (size_t)INT_MAX)
        return sio_fail(r, SCENE_IO_ERR_LIMIT, "more than %d polygons", INT_MAX);
    if (n > (size_t)INT_MAX)
        return sio_fail(r, SCENE_IO_ERR_LIMIT, "polygon with more than %d vertices", INT_MAX);
    uint32_t m = 0;
    int rc = sio_material(r, &m);
    if (rc)
        return rc;
    size_t start = s->poly_start ? s->poly_start[s->num_polygons] : 0;
    if (start > SIZE_MAX - n)
        return sio_nomem(r);
    if (sio_grow((void **)&s->poly_nverts, &r->cap_nverts, s->num_polygons + 1, sizeof(int)) ||
        sio_grow((void **)&s->poly_material, &r->cap_pmat, s->num_polygons + 1, sizeof(uint32_t)) ||
        sio_grow((void **)&s->poly_start, &r->cap_pstart, s->num_polygons + 2, sizeof(size_t)) ||
        sio_grow((void **)&s->poly_verts, &r->cap_idx, start + n, sizeof(uint32_t)))
        return sio_nomem(r);
    memcpy(s->poly_verts + start, idx, n * sizeof(uint32_t));
    s->poly_start[s->num_polygons] = start;
    s->poly_start[s->num_polygons + 1] = start + n;
    s->poly_nverts[s->num_polygons] = (int)n;
    s->poly_material[s->num_polygons] = m;
    s->num_polygons++;
    return SCENE_IO_OK;
}

/* A polygon given by coordinates (and optional normals), vertices appended. */
static int sio_add_polygon_xyz(sio_reader *r, int n, const double *xyz, const double *nrm)
{
    uint32_t idx[4];
    if (n > 4)
        return sio_fail(r, SCENE_IO_ERR_ARG, "internal: polygon too large");
    for (int i = 0; i < n; i++) {
        int rc = sio_add_vertex(r, xyz + 3 * i, nrm ? nrm + 3 * i : NULL, &idx[i]);
        if (rc)
            return rc;
    }
    return sio_add_polygon(r, (size_t)n, idx);
}

/* ---- NFF ------------------------------------------------------------------------------- */

static double sio_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sio_cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static int sio_nff_view(sio_reader *r)
{
    static const char *const keys[6] = { "from", "at", "up", "angle", "hither", "resolution" };
    scene_io_view v = { 0 };
    int seen[6] = { 0 };
    int rc = sio_end_line(r, 1, "'v'");
    if (rc)
        return rc;
    for (int k = 0; k < 6; k++) {
        if (!sio_begin_line(r))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file in the 'v' block");
        sio_tok t;
        sio_tok_next(r, &t);
        int which = -1;
        for (int j = 0; j < 6; j++)
            if (sio_tok_is(&t, keys[j]))
                which = j;
        char b[32];
        if (which < 0)
            return sio_fail(r, SCENE_IO_ERR_SYNTAX,
                            "expected from/at/up/angle/hither/resolution in the 'v' block, got '%s'",
                            sio_show(&t, b));
        if (seen[which])
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'%s' given twice in the 'v' block", keys[which]);
        seen[which] = 1;
        double a[3];
        switch (which) {
        case 0: rc = sio_nums(r, 3, "from", v.from); break;
        case 1: rc = sio_nums(r, 3, "at", v.at); break;
        case 2: rc = sio_nums(r, 3, "up", v.up); break;
        case 3:
            rc = sio_nums(r, 1, "angle", &v.angle);
            if (!rc && !(v.angle > 0 && v.angle < 180))
                rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "angle %g outside (0, 180) degrees", v.angle);
            break;
        case 4:
            rc = sio_nums(r, 1, "hither", &v.hither);
            if (!rc && !(v.hither > 0))
                rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "hither %g not positive", v.hither);
            break;
        default:
            rc = sio_nums(r, 2, "resolution", a);
            if (!rc && !(a[0] >= 1 && a[0] <= 65536 && a[1] >= 1 && a[1] <= 65536 &&
                         a[0] == floor(a[0]) && a[1] == floor(a[1])))
                rc = sio_fail(r, SCENE_IO_ERR_SYNTAX,
                              "resolution %g %g: need two integers in 1..65536", a[0], a[1]);
            if (!rc) { /* converted only once in range (an out-of-range cast is UB) */
                v.res_x = (int)a[0];
                v.res_y = (int)a[1];
            }
            break;
        }
        if (!rc)
            rc = sio_end_line(r, 1, keys[which]);
        if (rc)
            return rc;
    }
    double d[3] = { v.at[0] - v.from[0], v.at[1] - v.from[1], v.at[2] - v.from[2] }, c[3];
    sio_cross(d, v.up, c);
    double dd = sio_dot(d, d), uu = sio_dot(v.up, v.up);
    if (!(dd > 0) || !isfinite(dd))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "view: 'from' and 'at' coincide");
    if (!(uu > 0) || !isfinite(uu) || !(sio_dot(c, c) > 1e-24 * dd * uu))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "view: 'up' is zero or parallel to the view direction");
    v.present = 1;
    r->s->view = v;
    return SCENE_IO_OK;
}

/* p / pp: n vertex lines of 3 (p) or 6 (pp) numbers. */
static int sio_nff_polygon(sio_reader *r, int patch)
{
    const char *what = patch ? "'pp'" : "'p'";
    unsigned long long n;
    int rc = sio_count_next(r, patch ? "patch vertex count" : "polygon vertex count",
                            (unsigned long long)INT_MAX, &n);
    size_t start_line = r->line;
    if (rc)
        return rc;
    if (n < 3)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s with %llu vertices (at least 3 needed)", what, n);
    /* each vertex line needs at least "0 0 0\n" (6 bytes) or 12 bytes for a patch */
    size_t per = patch ? 12 : 6;
    if (n > (sio_remaining(r) + 1) / per)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX,
                        "%s declares %llu vertices but the file has only %zu bytes left", what, n,
                        sio_remaining(r));
    rc = sio_end_line(r, 1, what);
    if (rc)
        return rc;
    uint32_t stackbuf[64], *idx = stackbuf;
    if (n > 64) {
        idx = malloc((size_t)n * sizeof *idx);
        if (!idx)
            return sio_nomem(r);
    }
    for (size_t i = 0; i < n && !rc; i++) {
        if (!sio_begin_line(r)) {
            rc = sio_fail(r, SCENE_IO_ERR_SYNTAX,
                          "unexpected end of file: %s of line %zu has %zu of %llu vertices", what,
                          start_line, i, n);
            break;
        }
        double v[6];
        rc = sio_nums(r, patch ? 6 : 3, patch ? "patch vertex (x y z nx ny nz)" : "vertex (x y z)", v);
        if (!rc)
            rc = sio_end_line(r, 1, "vertex");
        if (!rc)
            rc = sio_add_vertex(r, v, patch ? v + 3 : NULL, &idx[i]);
    }
    if (!rc)
        rc = sio_add_polygon(r, (size_t)n, idx);
    if (!rc && patch)
        r->s->num_patches++;
    if (idx != stackbuf)
        free(idx);
    return rc;
}

/* Unit vectors u, w perpendicular to axis a (|a| > 0) and to each other. */
static void sio_basis(const double a[3], double u[3], double w[3])
{
    double t[3] = { 1, 0, 0 };
    if (fabs(a[0]) > fabs(a[1]) && fabs(a[0]) > fabs(a[2])) {
        t[0] = 0;
        t[1] = 1;
    }
    sio_cross(a, t, u);
    double l = sqrt(sio_dot(u, u));
    for (int i = 0; i < 3; i++)
        u[i] /= l;
    sio_cross(a, u, w);
    l = sqrt(sio_dot(w, w));
    for (int i = 0; i < 3; i++)
        w[i] /= l;
}

static int sio_tess_count(const sio_reader *r)
{
    int n = r->opt->tessellate;
    if (n > SIO_MAX_TESS)
        n = SIO_MAX_TESS;
    return n < 3 ? 3 : n;
}

/* Sphere as a UV mesh: triangles at the poles, planar quads between; counter-clockwise seen
 * from outside; vertex normals exact. */
static int sio_sphere(sio_reader *r, const double c[3], double rad)
{
    int nu = sio_tess_count(r), nv = nu / 2 < 2 ? 2 : nu / 2;
    for (int j = 0; j < nv; j++) {
        double t0 = SIO_PI * j / nv, t1 = SIO_PI * (j + 1) / nv;
        for (int i = 0; i < nu; i++) {
            double p0 = 2 * SIO_PI * i / nu, p1 = 2 * SIO_PI * (i + 1) / nu;
            double ang[4][2] = { { t0, p0 }, { t1, p0 }, { t1, p1 }, { t0, p1 } };
            double xyz[12], nrm[12];
            int k = 0;
            for (int q = 0; q < 4; q++) {
                if ((j == 0 && q == 3) || (j == nv - 1 && q == 2))
                    continue; /* pole: drop the repeated vertex */
                double th = ang[q][0], ph = ang[q][1];
                double n[3] = { sin(th) * cos(ph), sin(th) * sin(ph), cos(th) };
                for (int a = 0; a < 3; a++) {
                    nrm[3 * k + a] = n[a];
                    xyz[3 * k + a] = c[a] + rad * n[a];
                }
                k++;
            }
            int rc = sio_add_polygon_xyz(r, k, xyz, nrm);
            if (rc)
                return rc;
        }
    }
    return SCENE_IO_OK;
}

/* Open cone (frustum) from base (radius rb) to apex (radius ra), no caps. */
static int sio_cone(sio_reader *r, const double b[4], const double a[4])
{
    double ax[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] }, u[3], w[3];
    double len = sqrt(sio_dot(ax, ax));
    sio_basis(ax, u, w);
    int n = sio_tess_count(r);
    /* slant normal: radial component len, axial component (rb - ra) */
    double nr = len, na = b[3] - a[3], nl = sqrt(nr * nr + na * na);
    for (int i = 0; i < n; i++) {
        double p[2] = { 2 * SIO_PI * i / n, 2 * SIO_PI * (i + 1) / n };
        double xyz[12], nrm[12];
        int k = 0;
        /* order: base p0, base p1, apex p1, apex p0 (counter-clockwise from outside) */
        const int ring[4] = { 0, 0, 1, 1 }, side[4] = { 0, 1, 1, 0 };
        for (int q = 0; q < 4; q++) {
            const double *e = ring[q] ? a : b;
            if (e[3] == 0 && q == (ring[q] ? 3 : 1))
                continue; /* zero radius: one vertex */
            double cs = cos(p[side[q]]), sn = sin(p[side[q]]);
            for (int m = 0; m < 3; m++) {
                double radial = cs * u[m] + sn * w[m];
                xyz[3 * k + m] = e[m] + e[3] * radial;
                nrm[3 * k + m] = (nr * radial + na * ax[m] / len) / nl;
            }
            k++;
        }
        int rc = sio_add_polygon_xyz(r, k, xyz, nrm);
        if (rc)
            return rc;
    }
    return SCENE_IO_OK;
}

static int sio_nff_sphere(sio_reader *r)
{
    double v[4];
    int rc = sio_nums(r, 4, "'s' (x y z radius)", v);
    if (!rc)
        rc = sio_end_line(r, 1, "'s'");
    if (rc)
        return rc;
    if (!(v[3] > 0))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "sphere radius %g not positive", v[3]);
    r->s->num_spheres++;
    if (r->opt->tessellate > 0)
        return sio_sphere(r, v, v[3]);
    if (!r->warned_sphere)
        sio_warn(r, "spheres ('s') skipped: GKS has no sphere primitive (tessellation is off)");
    r->warned_sphere = 1;
    return SCENE_IO_OK;
}

static int sio_nff_cone(sio_reader *r)
{
    double e[2][4];
    int rc = sio_end_line(r, 1, "'c'");
    for (int k = 0; k < 2 && !rc; k++) {
        if (!sio_begin_line(r))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file in a cone ('c')");
        rc = sio_nums(r, 4, k ? "cone apex (x y z radius)" : "cone base (x y z radius)", e[k]);
        if (!rc)
            rc = sio_end_line(r, 1, "cone end");
    }
    if (rc)
        return rc;
    double ax[3] = { e[1][0] - e[0][0], e[1][1] - e[0][1], e[1][2] - e[0][2] };
    double l2 = sio_dot(ax, ax);
    if (e[0][3] < 0 || e[1][3] < 0 || !(e[0][3] + e[1][3] > 0) || !(l2 > 0) || !isfinite(l2))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX,
                        "degenerate cone (negative or zero radii, or base = apex)");
    r->s->num_cones++;
    if (r->opt->tessellate > 0)
        return sio_cone(r, e[0], e[1]);
    if (!r->warned_cone)
        sio_warn(r, "cones ('c') skipped: GKS has no cone primitive (tessellation is off)");
    r->warned_cone = 1;
    return SCENE_IO_OK;
}

static int sio_parse_nff(sio_reader *r)
{
    scene_io_scene *s = r->s;
    while (sio_begin_line(r)) {
        sio_tok t;
        sio_tok_next(r, &t);
        int rc;
        if (sio_tok_is(&t, "v")) {
            rc = sio_nff_view(r);
        } else if (sio_tok_is(&t, "b")) {
            rc = sio_nums(r, 3, "'b' (r g b)", s->background);
            if (!rc)
                rc = sio_nonneg(r, s->background, 3, "'b'");
            if (!rc)
                rc = sio_end_line(r, 1, "'b'");
            s->has_background = 1;
        } else if (sio_tok_is(&t, "l")) {
            scene_io_light l = { { 0, 0, 0 }, { 1, 1, 1 }, 0 };
            rc = sio_nums(r, 3, "'l' (x y z [r g b])", l.pos);
            sio_tok c;
            const char *save = r->p;
            if (!rc && sio_tok_next(r, &c)) {
                r->p = save;
                rc = sio_nums(r, 3, "'l' colour (r g b)", l.color);
                if (!rc)
                    rc = sio_nonneg(r, l.color, 3, "'l' colour");
                l.has_color = 1;
            }
            if (!rc)
                rc = sio_end_line(r, 1, "'l'");
            if (!rc && sio_grow((void **)&s->lights, &r->cap_light, s->num_lights + 1, sizeof l))
                rc = sio_nomem(r);
            if (!rc)
                s->lights[s->num_lights++] = l;
        } else if (sio_tok_is(&t, "f")) {
            double f[8];
            rc = sio_nums(r, 8, "'f' (r g b Kd Ks Shine T index)", f);
            if (!rc)
                rc = sio_nonneg(r, f, 8, "'f'");
            if (!rc)
                rc = sio_end_line(r, 1, "'f'");
            if (!rc && s->num_materials >= (size_t)UINT32_MAX)
                rc = sio_fail(r, SCENE_IO_ERR_LIMIT, "too many materials");
            if (!rc && sio_grow((void **)&s->materials, &r->cap_mat, s->num_materials + 1,
                                sizeof *s->materials))
                rc = sio_nomem(r);
            if (!rc) {
                s->materials[s->num_materials] =
                    (scene_io_material){ { f[0], f[1], f[2] }, f[3], f[4], f[5], f[6], f[7] };
                r->cur_mat = s->num_materials++;
            }
        } else if (sio_tok_is(&t, "p")) {
            rc = sio_nff_polygon(r, 0);
        } else if (sio_tok_is(&t, "pp")) {
            rc = sio_nff_polygon(r, 1);
        } else if (sio_tok_is(&t, "s")) {
            rc = sio_nff_sphere(r);
        } else if (sio_tok_is(&t, "c")) {
            rc = sio_nff_cone(r);
        } else {
            char b[32];
            rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "unknown NFF keyword '%s'", sio_show(&t, b));
        }
        if (rc)
            return rc;
    }
    return SCENE_IO_OK;
}

/* ---- OFF ------------------------------------------------------------------------------- */

/* Reserves nv vertices (already checked against the input size). */
static int sio_reserve_vertices(sio_reader *r, size_t nv)
{
    if (nv == 0)
        return SCENE_IO_OK;
    if (sio_grow((void **)&r->s->vertices, &r->cap_vert, nv, 3 * sizeof(double)))
        return sio_nomem(r);
    return SCENE_IO_OK;
}

/* One face: count then indices (< nv) on the current line; extras ignored if !strict. */
static int sio_face(sio_reader *r, size_t nv, size_t base, uint32_t **buf, size_t *cap,
                    int strict, const char *what)
{
    unsigned long long n;
    int rc = sio_count_next(r, "face vertex count", (unsigned long long)INT_MAX, &n);
    if (rc)
        return rc;
    if (n < 3)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s with %llu vertices (at least 3 needed)", what, n);
    if (n > (sio_remaining(r) + 1) / 2)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s declares %llu vertices, more than the line holds",
                        what, n);
    if (sio_grow((void **)buf, cap, (size_t)n, sizeof **buf))
        return sio_nomem(r);
    for (size_t i = 0; i < n; i++) {
        sio_tok t;
        unsigned long long k;
        if (!sio_tok_next(r, &t))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "%s has %zu of %llu vertex indices", what, i, n);
        rc = sio_count(r, &t, "vertex index", (unsigned long long)UINT32_MAX, &k);
        if (rc)
            return rc;
        if (k >= nv)
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "vertex index %llu out of range (%zu vertices)",
                            k, nv);
        (*buf)[i] = (uint32_t)(base + k);
    }
    rc = sio_end_line(r, strict, what);
    if (!rc)
        rc = sio_add_polygon(r, (size_t)n, *buf);
    return rc;
}

static int sio_parse_off(sio_reader *r)
{
    sio_tok t;
    if (!sio_begin_line(r))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "empty file");
    sio_tok_next(r, &t);
    if (!(t.n >= 3 && t.n <= 8 && memcmp(t.s + t.n - 3, "OFF", 3) == 0))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "not an OFF file (first word must be OFF)");
    if (t.n > 3 && (memchr(t.s, 'n', t.n - 3) || memchr(t.s, '4', t.n - 3)))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "OFF variant '%.*s' not supported", (int)t.n, t.s);
    const char *save = r->p;
    if (!sio_tok_next(r, &t)) { /* counts on the next line */
        int rc = sio_end_line(r, 1, "OFF");
        if (rc)
            return rc;
        if (!sio_begin_line(r))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file: missing vertex/face counts");
    } else {
        r->p = save;
    }
    unsigned long long nv, nf, ne;
    int rc = sio_count_next(r, "vertex count", (unsigned long long)UINT32_MAX, &nv);
    if (!rc)
        rc = sio_count_next(r, "face count", (unsigned long long)INT_MAX, &nf);
    if (!rc && sio_tok_next(r, &t))
        rc = sio_count(r, &t, "edge count", ULLONG_MAX, &ne);
    if (rc)
        return rc;
    /* a vertex line needs >= 6 bytes ("0 0 0\n"), a face line >= 8 ("3 0 1 2\n") */
    size_t left = sio_remaining(r) + 1;
    if (nv > left / 6 || nf > left / 8 || nv * 6 + nf * 8 > left)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX,
                        "counts %llu vertices, %llu faces exceed what the remaining %zu bytes can hold",
                        nv, nf, left - 1);
    rc = sio_end_line(r, 1, "the counts");
    if (rc)
        return rc;
    rc = sio_reserve_vertices(r, (size_t)nv);
    for (size_t i = 0; i < nv && !rc; i++) {
        if (!sio_begin_line(r))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file: %zu of %llu vertices",
                            i, nv);
        double v[3];
        uint32_t idx;
        rc = sio_nums(r, 3, "OFF vertex (x y z)", v);
        if (!rc)
            rc = sio_end_line(r, 0, "vertex");
        if (!rc)
            rc = sio_add_vertex(r, v, NULL, &idx);
    }
    uint32_t *buf = NULL;
    size_t cap = 0;
    for (size_t i = 0; i < nf && !rc; i++) {
        if (!sio_begin_line(r)) {
            rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file: %zu of %llu faces", i, nf);
            break;
        }
        rc = sio_face(r, (size_t)nv, 0, &buf, &cap, 0, "OFF face");
    }
    free(buf);
    if (!rc && sio_begin_line(r)) {
        sio_tok_next(r, &t);
        char b[32];
        rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected '%s' after the last face", sio_show(&t, b));
    }
    return rc;
}

/* ---- PLY ------------------------------------------------------------------------------- */

#define SIO_PLY_MAX_ELEM 16
#define SIO_PLY_MAX_PROP 64

typedef struct {
    char name[32];
    unsigned long long count;
    int nprop;
    int is_list[SIO_PLY_MAX_PROP];
    int role[SIO_PLY_MAX_PROP]; /* 0 other, 1 x, 2 y, 3 z, 4 face indices */
} sio_ply_elem;

static int sio_ply_type(const sio_tok *t)
{
    static const char *const types[] = { "char", "uchar", "short", "ushort", "int", "uint",
                                         "float", "double", "int8", "uint8", "int16", "uint16",
                                         "int32", "uint32", "float32", "float64" };
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (sio_tok_is(t, types[i]))
            return 1;
    return 0;
}

static int sio_ply_header(sio_reader *r, sio_ply_elem *el, int *nel)
{
    sio_tok t;
    char b[32];
    if (!sio_begin_line(r) || (sio_tok_next(r, &t), !sio_tok_is(&t, "ply")))
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "not a PLY file (first line must be 'ply')");
    int rc = sio_end_line(r, 1, "ply"), have_format = 0;
    while (!rc) {
        if (!sio_begin_line(r))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file in the PLY header");
        sio_tok_next(r, &t);
        if (sio_tok_is(&t, "end_header")) {
            if (!have_format)
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY header without 'format'");
            return sio_end_line(r, 1, "end_header");
        } else if (sio_tok_is(&t, "comment") || sio_tok_is(&t, "obj_info")) {
            rc = sio_end_line(r, 0, "comment");
        } else if (sio_tok_is(&t, "format")) {
            sio_tok f, v;
            if (!sio_tok_next(r, &f) || !sio_tok_next(r, &v))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "incomplete 'format' line");
            if (sio_tok_is(&f, "binary_little_endian") || sio_tok_is(&f, "binary_big_endian"))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "binary PLY not supported (ASCII only)");
            if (!sio_tok_is(&f, "ascii") || !sio_tok_is(&v, "1.0"))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unsupported PLY format '%s'",
                                sio_show(&f, b));
            have_format = 1;
            rc = sio_end_line(r, 1, "format");
        } else if (sio_tok_is(&t, "element")) {
            if (*nel >= SIO_PLY_MAX_ELEM)
                return sio_fail(r, SCENE_IO_ERR_LIMIT, "more than %d PLY elements", SIO_PLY_MAX_ELEM);
            sio_ply_elem *e = &el[*nel];
            memset(e, 0, sizeof *e);
            sio_tok nm;
            if (!sio_tok_next(r, &nm))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'element' without a name");
            snprintf(e->name, sizeof e->name, "%.*s", (int)(nm.n < 31 ? nm.n : 31), nm.s);
            rc = sio_count_next(r, "element count", (unsigned long long)INT_MAX, &e->count);
            if (!rc)
                rc = sio_end_line(r, 1, "element");
            (*nel)++;
        } else if (sio_tok_is(&t, "property")) {
            if (*nel == 0)
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'property' before any 'element'");
            sio_ply_elem *e = &el[*nel - 1];
            if (e->nprop >= SIO_PLY_MAX_PROP)
                return sio_fail(r, SCENE_IO_ERR_LIMIT, "more than %d properties", SIO_PLY_MAX_PROP);
            sio_tok ty, nm;
            if (!sio_tok_next(r, &ty))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'property' without a type");
            int list = sio_tok_is(&ty, "list");
            if (list) {
                sio_tok ct, it;
                if (!sio_tok_next(r, &ct) || !sio_tok_next(r, &it) || !sio_ply_type(&ct) ||
                    !sio_ply_type(&it))
                    return sio_fail(r, SCENE_IO_ERR_SYNTAX, "bad list property types");
            } else if (!sio_ply_type(&ty)) {
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unknown property type '%s'", sio_show(&ty, b));
            }
            if (!sio_tok_next(r, &nm))
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'property' without a name");
            int role = 0;
            if (strcmp(e->name, "vertex") == 0 && !list) {
                if (sio_tok_is(&nm, "x")) role = 1;
                if (sio_tok_is(&nm, "y")) role = 2;
                if (sio_tok_is(&nm, "z")) role = 3;
            }
            if (strcmp(e->name, "face") == 0 && list &&
                (sio_tok_is(&nm, "vertex_indices") || sio_tok_is(&nm, "vertex_index")))
                role = 4;
            e->is_list[e->nprop] = list;
            e->role[e->nprop] = role;
            e->nprop++;
            rc = sio_end_line(r, 1, "property");
        } else {
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "unknown PLY header keyword '%s'",
                            sio_show(&t, b));
        }
    }
    return rc;
}

/* One element line: all properties read and checked; vertex coordinates / face polygon kept. */
static int sio_ply_line(sio_reader *r, const sio_ply_elem *e, size_t nv, uint32_t **buf,
                        size_t *cap)
{
    double xyz[3] = { 0, 0, 0 };
    int have = 0, rc = SCENE_IO_OK;
    for (int p = 0; p < e->nprop && !rc; p++) {
        sio_tok t;
        if (e->role[p] == 4) {
            /* the face list: reuse the OFF face reader without ending the line */
            unsigned long long n;
            rc = sio_count_next(r, "face vertex count", (unsigned long long)INT_MAX, &n);
            if (rc)
                break;
            if (n < 3)
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY face with %llu vertices (at least 3 needed)", n);
            if (n > (sio_remaining(r) + 1) / 2)
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY face declares %llu vertices, more than the file holds", n);
            if (sio_grow((void **)buf, cap, (size_t)n, sizeof **buf))
                return sio_nomem(r);
            for (size_t i = 0; i < n && !rc; i++) {
                unsigned long long k;
                if (!sio_tok_next(r, &t))
                    return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY face has %zu of %llu vertex indices", i, n);
                rc = sio_count(r, &t, "vertex index", (unsigned long long)UINT32_MAX, &k);
                if (!rc && k >= nv)
                    rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "vertex index %llu out of range (%zu vertices)", k, nv);
                if (!rc)
                    (*buf)[i] = (uint32_t)k;
            }
            have = (int)n;
            continue;
        }
        if (e->is_list[p]) {
            unsigned long long n;
            rc = sio_count_next(r, "list length", (unsigned long long)INT_MAX, &n);
            for (size_t i = 0; i < n && !rc; i++) {
                double d;
                if (!sio_tok_next(r, &t))
                    return sio_fail(r, SCENE_IO_ERR_SYNTAX, "list has %zu of %llu entries", i, n);
                rc = sio_num(r, &t, "list entry", &d);
            }
            continue;
        }
        double d;
        if (!sio_tok_next(r, &t))
            return sio_fail(r, SCENE_IO_ERR_SYNTAX, "'%s' line has %d of %d properties", e->name, p,
                            e->nprop);
        rc = sio_num(r, &t, "property", &d);
        if (!rc && e->role[p] >= 1 && e->role[p] <= 3)
            xyz[e->role[p] - 1] = d;
    }
    if (!rc)
        rc = sio_end_line(r, 1, e->name);
    if (rc)
        return rc;
    if (strcmp(e->name, "vertex") == 0) {
        uint32_t idx;
        return sio_add_vertex(r, xyz, NULL, &idx);
    }
    if (have)
        return sio_add_polygon(r, (size_t)have, *buf);
    return SCENE_IO_OK;
}

static int sio_parse_ply(sio_reader *r)
{
    sio_ply_elem el[SIO_PLY_MAX_ELEM];
    int nel = 0;
    int rc = sio_ply_header(r, el, &nel);
    if (rc)
        return rc;
    size_t nv = 0, left = sio_remaining(r) + 1, need = 0;
    int have_xyz = 0;
    for (int i = 0; i < nel; i++) {
        /* each property takes >= 2 bytes ("0 "); a face list >= 8 ("3 0 1 2 ") */
        size_t per = 0;
        for (int p = 0; p < el[i].nprop; p++)
            per += el[i].role[p] == 4 ? 8 : 2;
        if (per == 0)
            per = 1;
        if (el[i].count > left / per || need > left - el[i].count * per)
            return sio_fail(r, SCENE_IO_ERR_SYNTAX,
                            "element '%s' count %llu exceeds what the remaining %zu bytes can hold",
                            el[i].name, el[i].count, left - 1);
        need += el[i].count * per;
        if (strcmp(el[i].name, "vertex") == 0) {
            int m = 0;
            for (int p = 0; p < el[i].nprop; p++)
                m |= el[i].role[p] >= 1 && el[i].role[p] <= 3 ? 1 << el[i].role[p] : 0;
            if (m != 14)
                return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY vertex element lacks x, y or z");
            nv = (size_t)el[i].count;
            have_xyz = 1;
        }
    }
    if (!have_xyz)
        return sio_fail(r, SCENE_IO_ERR_SYNTAX, "PLY file has no 'vertex' element");
    rc = sio_reserve_vertices(r, nv);
    uint32_t *buf = NULL;
    size_t cap = 0;
    for (int i = 0; i < nel && !rc; i++)
        for (size_t k = 0; k < el[i].count && !rc; k++) {
            if (!sio_begin_line(r)) {
                rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected end of file: %zu of %llu '%s' elements",
                              k, el[i].count, el[i].name);
                break;
            }
            rc = sio_ply_line(r, &el[i], nv, &buf, &cap);
        }
    free(buf);
    if (!rc && sio_begin_line(r)) {
        sio_tok t;
        char b[32];
        sio_tok_next(r, &t);
        rc = sio_fail(r, SCENE_IO_ERR_SYNTAX, "unexpected '%s' after the last element", sio_show(&t, b));
    }
    return rc;
}

/* ---- public ---------------------------------------------------------------------------- */

void scene_io_options_default(scene_io_options *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->max_bytes = SIO_DEFAULT_MAX_BYTES;
}

void scene_io_free(scene_io_scene *s)
{
    if (!s)
        return;
    free(s->lights);
    free(s->materials);
    free(s->vertices);
    free(s->normals);
    free(s->poly_nverts);
    free(s->poly_start);
    free(s->poly_verts);
    free(s->poly_material);
    memset(s, 0, sizeof *s);
}

const char *scene_io_format_name(scene_io_format fmt)
{
    switch (fmt) {
    case SCENE_IO_NFF: return "NFF";
    case SCENE_IO_OFF: return "OFF";
    case SCENE_IO_PLY: return "PLY";
    default: return "auto";
    }
}

static scene_io_format sio_sniff(const char *data, size_t len)
{
    sio_reader r = { .p = data, .end = data + len, .line = 1 };
    sio_tok t;
    if (!sio_begin_line(&r) || !sio_tok_next(&r, &t))
        return SCENE_IO_NFF;
    if (sio_tok_is(&t, "ply"))
        return SCENE_IO_PLY;
    if (t.n >= 3 && t.n <= 8 && memcmp(t.s + t.n - 3, "OFF", 3) == 0)
        return SCENE_IO_OFF;
    return SCENE_IO_NFF;
}

int scene_io_parse(const char *data, size_t len, const char *name, scene_io_format fmt,
                   const scene_io_options *opt, scene_io_scene *s, char *err, size_t err_size)
{
    scene_io_options defaults;
    scene_io_options_default(&defaults);
    if (!opt)
        opt = &defaults;
    if (err && err_size)
        err[0] = '\0';
    if (!s)
        return SCENE_IO_ERR_ARG;
    memset(s, 0, sizeof *s);
    sio_reader r = { .p = data, .end = data + len, .name = name ? name : "<memory>", .line = 1,
                     .err = err, .err_size = err_size, .opt = opt, .s = s, .cur_mat = SIZE_MAX };
    if (!data && len)
        return sio_fail(&r, SCENE_IO_ERR_ARG, "no data");
    if (!data)
        r.p = r.end = "";
    size_t max = opt->max_bytes ? opt->max_bytes : SIO_DEFAULT_MAX_BYTES;
    if (len > max)
        return sio_fail(&r, SCENE_IO_ERR_LIMIT, "input of %zu bytes exceeds the limit of %zu", len, max);
    if (fmt == SCENE_IO_AUTO)
        fmt = sio_sniff(r.p, len);
    int rc;
    switch (fmt) {
    case SCENE_IO_NFF: rc = sio_parse_nff(&r); break;
    case SCENE_IO_OFF: rc = sio_parse_off(&r); break;
    case SCENE_IO_PLY: rc = sio_parse_ply(&r); break;
    default: rc = sio_fail(&r, SCENE_IO_ERR_ARG, "unknown format %d", (int)fmt); break;
    }
    if (rc) {
        scene_io_free(s);
        return rc;
    }
    s->format = fmt;
    return SCENE_IO_OK;
}

int scene_io_load(const char *path, scene_io_format fmt, const scene_io_options *opt,
                  scene_io_scene *s, char *err, size_t err_size)
{
    if (err && err_size)
        err[0] = '\0';
    if (!s)
        return SCENE_IO_ERR_ARG;
    memset(s, 0, sizeof *s);
    if (!path) {
        if (err && err_size)
            snprintf(err, err_size, "no file name");
        return SCENE_IO_ERR_ARG;
    }
    size_t max = opt && opt->max_bytes ? opt->max_bytes : SIO_DEFAULT_MAX_BYTES;
    gzFile f = gzopen(path, "rb");
    if (!f) {
        if (err && err_size)
            snprintf(err, err_size, "%s: cannot open", path);
        return SCENE_IO_ERR_OPEN;
    }
    gzbuffer(f, 1 << 17);
    char *buf = NULL;
    size_t len = 0, cap = 0, first = (size_t)1 << 20;
    struct stat st; /* a plain file is read into one buffer of its size (no copy on growth) */
    if (stat(path, &st) == 0 && st.st_size > 0 && (uintmax_t)st.st_size < (uintmax_t)max)
        first = (size_t)st.st_size + 1;
    int rc = SCENE_IO_OK;
    for (;;) {
        if (len == cap && sio_grow((void **)&buf, &cap, cap ? cap + 1 : first, 1)) {
            rc = SCENE_IO_ERR_NOMEM;
            if (err && err_size)
                snprintf(err, err_size, "%s: out of memory", path);
            break;
        }
        size_t want = cap - len;
        if (want > (size_t)1 << 30)
            want = (size_t)1 << 30;
        int n = gzread(f, buf + len, (unsigned)want);
        if (n < 0) {
            int zerr;
            const char *m = gzerror(f, &zerr);
            rc = SCENE_IO_ERR_OPEN;
            if (err && err_size)
                snprintf(err, err_size, "%s: read error: %s", path, m ? m : "?");
            break;
        }
        if (n == 0)
            break;
        len += (size_t)n;
        if (len > max) {
            rc = SCENE_IO_ERR_LIMIT;
            if (err && err_size)
                snprintf(err, err_size, "%s: larger than the limit of %zu bytes", path, max);
            break;
        }
    }
    int zc = gzclose(f);
    if (!rc && zc != Z_OK) {
        rc = SCENE_IO_ERR_OPEN;
        if (err && err_size)
            snprintf(err, err_size, "%s: %s", path,
                     zc == Z_BUF_ERROR ? "truncated gzip data" : "read error");
    }
    if (!rc)
        rc = scene_io_parse(buf, len, path, fmt, opt, s, err, err_size);
    free(buf);
    return rc;
}

int scene_io_bounds(const scene_io_scene *s, double lo[3], double hi[3])
{
    if (!s || s->num_polygons == 0 || !s->poly_start)
        return 0;
    double l[3] = { INFINITY, INFINITY, INFINITY }, h[3] = { -INFINITY, -INFINITY, -INFINITY };
    size_t ni = s->poly_start[s->num_polygons];
    for (size_t i = 0; i < ni; i++) {
        const double *v = s->vertices + 3 * (size_t)s->poly_verts[i];
        for (int a = 0; a < 3; a++) {
            l[a] = v[a] < l[a] ? v[a] : l[a];
            h[a] = v[a] > h[a] ? v[a] : h[a];
        }
    }
    memcpy(lo, l, sizeof l);
    memcpy(hi, h, sizeof h);
    return 1;
}

int scene_io_vertex_normals(scene_io_scene *s, int angle_weighted)
{
    if (!s || (s->num_polygons && (!s->poly_start || !s->poly_nverts || !s->poly_verts)))
        return SCENE_IO_ERR_ARG;
    if (s->num_vertices > SIZE_MAX / (3 * sizeof(double)))
        return SCENE_IO_ERR_NOMEM;
    double *n = calloc(s->num_vertices ? s->num_vertices : 1, 3 * sizeof(double));
    if (!n)
        return SCENE_IO_ERR_NOMEM;
    for (size_t p = 0; p < s->num_polygons; p++) {
        const uint32_t *ix = s->poly_verts + s->poly_start[p];
        const size_t m = (size_t)s->poly_nverts[p];
        double f[3] = { 0, 0, 0 };
        for (size_t i = 0; i < m; i++) { /* Newell: 2 x area x unit normal */
            const double *a = s->vertices + 3 * (size_t)ix[i];
            const double *b = s->vertices + 3 * (size_t)ix[(i + 1) % m];
            f[0] += (a[1] - b[1]) * (a[2] + b[2]);
            f[1] += (a[2] - b[2]) * (a[0] + b[0]);
            f[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
        double fl = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!(fl > 0) || !isfinite(fl))
            continue;
        for (size_t i = 0; i < m; i++) {
            double w = 1;
            if (angle_weighted) {
                const double *a = s->vertices + 3 * (size_t)ix[(i + m - 1) % m];
                const double *v = s->vertices + 3 * (size_t)ix[i];
                const double *b = s->vertices + 3 * (size_t)ix[(i + 1) % m];
                double u[3], t[3], uu = 0, tt = 0, ut = 0;
                for (int k = 0; k < 3; k++) {
                    u[k] = a[k] - v[k];
                    t[k] = b[k] - v[k];
                    uu += u[k] * u[k];
                    tt += t[k] * t[k];
                    ut += u[k] * t[k];
                }
                double c = uu > 0 && tt > 0 ? ut / sqrt(uu * tt) : 1;
                w = acos(c < -1 ? -1 : c > 1 ? 1 : c) / fl;
            }
            double *q = n + 3 * (size_t)ix[i];
            for (int k = 0; k < 3; k++)
                q[k] += w * f[k];
        }
    }
    for (size_t i = 0; i < s->num_vertices; i++) {
        double *q = n + 3 * i, l = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        for (int k = 0; k < 3; k++)
            q[k] = l > 0 && isfinite(l) ? q[k] / l : 0;
    }
    free(s->normals);
    s->normals = n;
    return SCENE_IO_OK;
}

int scene_io_frame_view(const scene_io_scene *s, double angle, int res_x, int res_y,
                        scene_io_view *v)
{
    double lo[3], hi[3];
    if (!v || !(angle > 0 && angle < 180) || res_x < 1 || res_x > 65536 || res_y < 1 ||
        res_y > 65536 || !scene_io_bounds(s, lo, hi))
        return SCENE_IO_ERR_ARG;
    double c[3], rad = 0, dir[3] = { 0.6, 0.5, 1 };
    for (int a = 0; a < 3; a++) {
        c[a] = 0.5 * (lo[a] + hi[a]);
        rad += 0.25 * (hi[a] - lo[a]) * (hi[a] - lo[a]);
    }
    rad = sqrt(rad);
    if (!(rad > 0) || !isfinite(rad))
        rad = 1;
    double dl = sqrt(sio_dot(dir, dir));
    double dist = rad / sin(0.5 * angle * SIO_PI / 180);
    memset(v, 0, sizeof *v);
    for (int a = 0; a < 3; a++) {
        v->at[a] = c[a];
        v->from[a] = c[a] + dist * dir[a] / dl;
    }
    v->up[1] = 1;
    v->angle = angle;
    v->hither = dist / 100;
    v->res_x = res_x;
    v->res_y = res_y;
    v->present = 1;
    return SCENE_IO_OK;
}
