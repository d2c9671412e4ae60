/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_codec.c -- GKS metafile codec (see gks_mf_codec.h for the format).
 */
#include "gks_mf_codec.h"
#include "gks_alloc.h"
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { W_H = 4, W_T = 3, W_L = 10, W_I = 11, W_R = 24 };
#define GKSM_MAX_LEN_FIELD 10
#define GKSM_MAX_INT_FIELD 20
#define GKSM_MAX_REAL_FIELD 40

/* ---------------------------------------------------------------- writing */

void gksm_rec_init(gksm_rec *r)
{
    r->buf = NULL;
    r->len = r->cap = 0;
    r->failed = 0;
}

void gksm_rec_free(gksm_rec *r)
{
    gks_free(r->buf);
    gksm_rec_init(r);
}

void gksm_rec_clear(gksm_rec *r)
{
    r->len = 0;
    r->failed = 0;
}

static char *rec_grow(gksm_rec *r, size_t extra)
{
    if (r->failed)
        return NULL;
    if (extra > SIZE_MAX - r->len - 1) {
        r->failed = 1;
        return NULL;
    }
    /* + the terminator snprintf writes */
    if (gks_grow(&r->buf, &r->cap, r->len + extra + 1, 1)) {
        r->failed = 1;
        return NULL;
    }
    return r->buf + r->len;
}

void gksm_rec_int(gksm_rec *r, long v)
{
    char *p = rec_grow(r, W_I);
    if (!p)
        return;
    if (v > 9999999999L)
        v = 9999999999L;
    if (v < -9999999999L)
        v = -9999999999L;
    snprintf(p, W_I + 1, "%*ld", W_I, v);
    r->len += W_I;
}

void gksm_rec_real(gksm_rec *r, double v)
{
    char *p = rec_grow(r, W_R);
    if (!p)
        return;
    if (!isfinite(v))
        v = 0.0;
    snprintf(p, W_R + 1, "%*.16e", W_R, v);
    r->len += W_R;
}

void gksm_rec_raw(gksm_rec *r, const char *s, size_t n)
{
    char *p = rec_grow(r, n);
    if (!p)
        return;
    if (n)
        memcpy(p, s, n);
    r->len += n;
}

void gksm_rec_str(gksm_rec *r, const char *s, size_t n)
{
    if (n > 999999999) {
        r->failed = 1;
        return;
    }
    gksm_rec_int(r, (long)n);
    gksm_rec_raw(r, s, n);
}

int gksm_write_header(FILE *fp, const char *name, const char *date)
{
    char today[16];
    if (!date) {
        time_t now = time(NULL);
        struct tm tm;
        if (!gmtime_r(&now, &tm))
            memset(&tm, 0, sizeof tm);
        snprintf(today, sizeof today, "%02d/%02d/%02d", tm.tm_year % 100, (tm.tm_mon + 1) % 100,
                 tm.tm_mday % 100);
        date = today;
    }
    int n = fprintf(fp, "GKSM%-40.40s%-8.8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", name ? name : "",
                    date, 1, W_H, W_T, W_L, W_I, W_R, 1, 1, 0, 1);
    return n == GKSM_HEADER_LEN ? 0 : -1;
}

int gksm_write_record(FILE *fp, int type, const char *rec, size_t len)
{
    if (type < 0 || type > 999 || len > 9999999999ULL)
        return 161;
    if (fprintf(fp, "GKSM%*d%*zu", W_T, type, W_L, len) != W_H + W_T + W_L)
        return -1;
    if (len && fwrite(rec, 1, len, fp) != len)
        return -1;
    return 0;
}

int gksm_write_item(FILE *fp, int type, const gksm_rec *r)
{
    if (r && r->failed)
        return -1;
    return gksm_write_record(fp, type, r ? r->buf : NULL, r ? r->len : 0);
}

/* ---------------------------------------------------------------- reading */

/* Parses a right-justified, blank-padded unsigned or signed integer field of exactly
 * w characters. Returns 0 or -1. */
static int parse_int_field(const char *s, int w, long long *v)
{
    int i = 0;
    while (i < w && s[i] == ' ')
        i++;
    if (i == w)
        return -1;
    int neg = 0;
    if (s[i] == '-' || s[i] == '+') {
        neg = s[i] == '-';
        i++;
    }
    if (i == w)
        return -1;
    long long x = 0;
    for (; i < w; i++) {
        if (!isdigit((unsigned char)s[i]))
            return -1;
        if (x > (LLONG_MAX - 9) / 10)
            return -1;
        x = 10 * x + (s[i] - '0');
    }
    *v = neg ? -x : x;
    return 0;
}

static int read_exact(gksm_in *m, char *buf, size_t n)
{
    if (m->left >= 0 && (unsigned long long)m->left < n)
        return -1;
    if (n && fread(buf, 1, n, m->fp) != n)
        return -1;
    if (m->left >= 0)
        m->left -= (long long)n;
    return 0;
}

static int skip_bytes(gksm_in *m, size_t n)
{
    char tmp[4096];
    while (n) {
        size_t k = n < sizeof tmp ? n : sizeof tmp;
        if (read_exact(m, tmp, k))
            return -1;
        n -= k;
    }
    return 0;
}

int gksm_in_open(gksm_in *m, FILE *fp)
{
    memset(m, 0, sizeof *m);
    m->fp = fp;
    m->left = -1;
    long pos = ftell(fp);
    if (pos >= 0 && fseek(fp, 0, SEEK_END) == 0) {
        long end = ftell(fp);
        if (end >= pos && fseek(fp, pos, SEEK_SET) == 0)
            m->left = end - pos;
        else
            return 163;
    } else {
        clearerr(fp);
    }
    char h[GKSM_HEADER_LEN];
    if (read_exact(m, h, sizeof h) || memcmp(h, "GKSM", 4) != 0)
        return 163;
    long long f[8];
    for (int k = 0; k < 8; k++)
        if (parse_int_field(h + 52 + 2 * k, 2, &f[k]))
            return 163;
    long long zero, one;
    if (parse_int_field(h + 68, 11, &zero) || parse_int_field(h + 79, 11, &one))
        return 163;
    /* f: V H T L I R F RI */
    if (f[1] < 0 || f[1] > 4 || f[2] < 1 || f[2] > 4 || f[3] < 1 || f[3] > GKSM_MAX_LEN_FIELD ||
        f[4] < 1 || f[4] > GKSM_MAX_INT_FIELD || f[5] < 1 || f[5] > GKSM_MAX_REAL_FIELD ||
        f[6] != 1 || (f[7] != 1 && f[7] != 2) || (f[7] == 2 && one == zero))
        return 163;
    m->h = (int)f[1];
    m->t = (int)f[2];
    m->l = (int)f[3];
    m->iw = (int)f[4];
    m->rw = (int)f[5];
    m->ri = (int)f[7];
    m->zero = (double)zero;
    m->one = (double)one;
    return 0;
}

int gksm_in_peek(gksm_in *m, int *type, size_t *len)
{
    if (!m->have_item) {
        char hdr[4 + 4 + GKSM_MAX_LEN_FIELD];
        size_t n = (size_t)(m->h + m->t + m->l);
        if (m->left == 0)
            return 162;
        if (m->left < 0) { /* unknown size: end of file is "no item left" */
            int ch = getc(m->fp);
            if (ch == EOF)
                return 162;
            ungetc(ch, m->fp);
        }
        if (read_exact(m, hdr, n) || memcmp(hdr, "GKSM", (size_t)m->h) != 0)
            return 163;
        long long t, l;
        if (parse_int_field(hdr + m->h, m->t, &t) || parse_int_field(hdr + m->h + m->t, m->l, &l) ||
            t < 0 || l < 0)
            return 163;
        if (m->left >= 0 && l > m->left)
            return 163; /* the data record cannot be there */
        m->type = (int)t;
        m->len = (size_t)l;
        m->have_item = 1;
    }
    *type = m->type;
    *len = m->len;
    return 0;
}

int gksm_in_read(gksm_in *m, char *buf, size_t cap, size_t *got)
{
    int type;
    size_t len;
    int err = gksm_in_peek(m, &type, &len);
    if (err)
        return err;
    size_t k = len < cap ? len : cap;
    m->have_item = 0;
    if (read_exact(m, buf, k) || skip_bytes(m, len - k))
        return 163;
    *got = k;
    return 0;
}

int gksm_in_skip(gksm_in *m)
{
    size_t got;
    return gksm_in_read(m, NULL, 0, &got);
}

void gksm_cur_init(gksm_cur *c, const gksm_in *m, const char *rec, size_t len)
{
    c->p = rec;
    c->n = len;
    c->iw = m->iw;
    c->rw = m->rw;
    c->ri = m->ri;
    c->zero = m->zero;
    c->one = m->one;
}

size_t gksm_cur_left(const gksm_cur *c)
{
    return c->n;
}

int gksm_get_int(gksm_cur *c, long *v)
{
    long long x;
    if (c->n < (size_t)c->iw || parse_int_field(c->p, c->iw, &x) || x < LONG_MIN || x > LONG_MAX)
        return 165;
    *v = (long)x;
    c->p += c->iw;
    c->n -= (size_t)c->iw;
    return 0;
}

int gksm_get_real(gksm_cur *c, double *v)
{
    if (c->ri == 2) { /* scaled integers in integer-width fields */
        long k;
        if (gksm_get_int(c, &k))
            return 165;
        *v = ((double)k - c->zero) / (c->one - c->zero);
        return 0;
    }
    char tmp[GKSM_MAX_REAL_FIELD + 1];
    if (c->n < (size_t)c->rw)
        return 165;
    memcpy(tmp, c->p, (size_t)c->rw);
    tmp[c->rw] = '\0';
    /* strtod accepts "nan", "inf" and hex floats: allow only a plain decimal number. */
    for (int i = 0; i < c->rw; i++)
        if (tmp[i] == '\0' || !strchr(" +-.0123456789eE", tmp[i]))
            return 165;
    char *end;
    errno = 0;
    double x = strtod(tmp, &end);
    if (end == tmp)
        return 165; /* no number at all */
    while (*end == ' ')
        end++;
    if (*end != '\0' || !isfinite(x))
        return 165;
    *v = x;
    c->p += c->rw;
    c->n -= (size_t)c->rw;
    return 0;
}

int gksm_get_str(gksm_cur *c, const char **s, size_t *n)
{
    gksm_cur save = *c;
    long k;
    if (gksm_get_int(c, &k))
        return 165;
    if (k < 0 || (unsigned long)k > c->n) {
        *c = save;
        return 165;
    }
    *s = c->p;
    *n = (size_t)k;
    c->p += k;
    c->n -= (size_t)k;
    return 0;
}
