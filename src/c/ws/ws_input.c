/* SPDX-License-Identifier: MIT */
/*
 * ws_input.c -- the input facilities the workstation types share and the CHOICE menu
 * labels of a data record (ws_input.h).
 */
#include "ws_input.h"
#include "gks_rec.h"
#include <stdlib.h>
#include <string.h>

const gks_in_desc gks_in_desc_std = {
    .n_dev = { 2, 2, 2, 2, 2, 2 },
    .max_pet = { 6, 4, 3, 3, 3, 1 },
    .max_choices = 9,
};

int gks_in_menu_labels(const Gin_data *r, const char **lab, int *len, int max)
{
    const char *p = r->str, *end = r->str ? r->str + r->str_len : NULL;
    int k = 0;
    if (!p || r->str_len == 0 || max <= 0)
        return 0;
    if (r->str_len >= 4 && memcmp(p, "GKSR", 4) == 0) {
        gks_rec_reader rd;
        if (gks_rec_begin(&rd, p, r->str_len))
            return 0;
        long lens[64], ns = rd.sl > 64 ? 64 : rd.sl;
        for (long i = 0; i < rd.il + rd.rl; i++) /* integers, reals: skipped */
            while (rd.p < rd.end && *rd.p++ != ',')
                ;
        for (long i = 0; i < ns; i++)
            if (gks_rec_long(&rd, &lens[i]) || lens[i] < 0)
                return 0;
        for (long i = 0; i < ns && rd.end - rd.p >= lens[i]; i++) {
            if (k < max) {
                lab[k] = rd.p;
                len[k++] = (int)lens[i];
            }
            rd.p += lens[i];
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
