/* SPDX-License-Identifier: MIT */
/*
 * ws_input.c -- the input facilities the workstation types share and the CHOICE menu
 * labels of a data record (ws_input.h).
 */
#include "ws_input.h"
#include <stdlib.h>
#include <string.h>

const gks_in_desc gks_in_desc_std = {
    .n_dev = { 2, 2, 2, 2, 2, 2 },
    .max_pet = { 6, 4, 3, 3, 3, 1 },
    .max_choices = 9,
};

/* One decimal ended by ',' at *p (before end), as GPREC writes them; -1 if none. */
static int rec_long(const char **p, const char *end, long *v)
{
    char t[24];
    size_t n = 0;
    while (*p + n < end && (*p)[n] != ',' && n < sizeof t - 1) {
        t[n] = (*p)[n];
        n++;
    }
    if (n == 0 || *p + n >= end || (*p)[n] != ',')
        return -1;
    t[n] = '\0';
    char *e;
    *v = strtol(t, &e, 10);
    *p += n + 1;
    return *e ? -1 : 0;
}

int gks_in_menu_labels(const Gin_data *r, const char **lab, int *len, int max)
{
    const char *p = r->str, *end = r->str ? r->str + r->str_len : NULL;
    int k = 0;
    if (!p || r->str_len == 0 || max <= 0)
        return 0;
    if (r->str_len >= 4 && memcmp(p, "GKSR", 4) == 0) {
        long n[3], lens[64];
        p += 4;
        for (int i = 0; i < 3; i++)
            if (rec_long(&p, end, &n[i]) || n[i] < 0 || n[i] > 100000)
                return 0;
        for (long i = 0; i < n[0] + n[1]; i++) /* integers, reals: skipped */
            while (p < end && *p++ != ',')
                ;
        if (n[2] > 64)
            n[2] = 64;
        for (long i = 0; i < n[2]; i++)
            if (rec_long(&p, end, &lens[i]) || lens[i] < 0)
                return 0;
        for (long i = 0; i < n[2] && end - p >= lens[i]; i++) {
            if (k < max) {
                lab[k] = p;
                len[k++] = (int)lens[i];
            }
            p += lens[i];
        }
        return k;
    }
    while (p < end && k < max) {
        const char *q = p;
        while (q < end && *q != '\0' && *q != '\n')
            q++;
        if (q > p) {
            lab[k] = p;
            len[k++] = (int)(q - p);
        }
        p = q + 1;
    }
    return k;
}
