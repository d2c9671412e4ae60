/* SPDX-License-Identifier: MIT */
/*
 * gks_rec.c -- the reader of the GPREC data record (gks_rec.h).
 */
#include "gks_private.h"
#include "gks_rec.h"
#include <stdlib.h>
#include <string.h>

/* The next field's text (ended by ',' before end) into t[size], the cursor moved past the
 * ','; -1 when there is none or it does not fit. */
static int rec_field(gks_rec_reader *r, char *t, size_t size)
{
    size_t n = 0;
    while (r->p + n < r->end && r->p[n] != ',' && n < size - 1) {
        t[n] = r->p[n];
        n++;
    }
    if (n == 0 || r->p + n >= r->end || r->p[n] != ',')
        return -1;
    t[n] = '\0';
    r->p += n + 1;
    return 0;
}

GKS_API int gks_rec_long(gks_rec_reader *r, long *v)
{
    char t[32], *e;
    if (rec_field(r, t, sizeof t))
        return -1;
    *v = strtol(t, &e, 10);
    return *e ? -1 : 0;
}

GKS_API int gks_rec_real(gks_rec_reader *r, double *v)
{
    char t[40], *e;
    if (rec_field(r, t, sizeof t))
        return -1;
    *v = strtod(t, &e);
    return *e ? -1 : 0;
}

GKS_API int gks_rec_begin(gks_rec_reader *r, const char *buf, size_t len)
{
    *r = (gks_rec_reader){ buf, buf ? buf + len : NULL, 0, 0, 0 };
    if (!buf || len < 4 || memcmp(buf, "GKSR", 4) != 0)
        return -1;
    r->p += 4;
    long *n[3] = { &r->il, &r->rl, &r->sl };
    for (int i = 0; i < 3; i++)
        if (gks_rec_long(r, n[i]) || *n[i] < 0 || *n[i] > GKS_REC_MAX_COUNT)
            return -1;
    return 0;
}
