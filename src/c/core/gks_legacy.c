/* SPDX-License-Identifier: MIT */
/*
 * gks_legacy.c -- GKS3D_WS_TYPES and GKS3D_ASF (gks_legacy.h). The variables are parsed
 * once per OPEN GKS into this module's table; all or nothing, so a typo never maps half a
 * program's types. NCAR's escapes -1391 and -1396 (gks_legacy_escape). The registered
 * profile (gks_set_profile): the hooks a foreign GKS's library supplies.
 */
#include "gks_legacy.h"
#include "gks_alloc.h"
#include "gks_binding.h"
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define MAP_MAX 64 /* entries of GKS3D_WS_TYPES */

static struct {
    int n;
    int from[MAP_MAX], to[MAP_MAX];
    Gasf asf;
    char *next_file; /* GESC_NCAR_FILE_NAME: the next file workstation's name */
    const gks_profile *profile; /* gks_set_profile; NULL: none */
} legacy = { 0, { 0 }, { 0 }, GASF_INDIV, NULL, NULL };

GKS_API void gks_set_profile(const gks_profile *p)
{
    legacy.profile = p;
}

const gks_profile *gks_legacy_profile(void)
{
    return legacy.profile;
}

/* One decimal integer at *s (leading blanks allowed), advancing *s; 0 = ok. */
static int parse_num(const char **s, int *out)
{
    while (**s == ' ' || **s == '\t')
        (*s)++;
    if (!((**s >= '0' && **s <= '9') || **s == '-' || **s == '+'))
        return -1;
    char *end = NULL;
    errno = 0;
    long v = strtol(*s, &end, 10);
    if (errno || end == *s || v < INT_MIN || v > INT_MAX)
        return -1;
    *s = end;
    while (**s == ' ' || **s == '\t')
        (*s)++;
    *out = (int)v;
    return 0;
}

/* "F=T[,F=T...]" into the table; -1 (table untouched) if malformed, too long, or a
 * target is not a positive type number. A later entry for the same F replaces one. */
static int parse_map(const char *s)
{
    int n = 0, from[MAP_MAX], to[MAP_MAX];
    for (;;) {
        int f, t;
        if (parse_num(&s, &f) || *s++ != '=' || parse_num(&s, &t) || t <= 0)
            return -1;
        int k = 0;
        while (k < n && from[k] != f)
            k++;
        if (k == n) {
            if (n == MAP_MAX)
                return -1;
            n++;
        }
        from[k] = f;
        to[k] = t;
        if (*s == '\0')
            break;
        if (*s++ != ',')
            return -1;
    }
    legacy.n = n;
    memcpy(legacy.from, from, (size_t)n * sizeof from[0]);
    memcpy(legacy.to, to, (size_t)n * sizeof to[0]);
    return 0;
}

void gks_legacy_load(void)
{
    gks_free(legacy.next_file);
    legacy.next_file = NULL;
    legacy.n = 0;
    legacy.asf = GASF_INDIV;
    const char *m = getenv("GKS3D_WS_TYPES");
    if (m && *m && parse_map(m))
        fprintf(stderr, "gks3d: GKS3D_WS_TYPES=\"%.200s\" ignored: expected "
                        "FOREIGN=OURS[,FOREIGN=OURS...] (at most %d, OURS > 0)\n",
                m, MAP_MAX);
    const char *a = getenv("GKS3D_ASF");
    if (a && *a) {
        if (strcasecmp(a, "BUNDLED") == 0)
            legacy.asf = GASF_BUNDLED;
        else if (strcasecmp(a, "INDIVIDUAL") != 0)
            fprintf(stderr, "gks3d: GKS3D_ASF=\"%.200s\" ignored: expected BUNDLED or "
                            "INDIVIDUAL\n", a);
    }
}

int gks_ws_type_map(int ws_type)
{
    for (int i = 0; i < legacy.n; i++)
        if (legacy.from[i] == ws_type)
            return legacy.to[i];
    if (legacy.profile && legacy.profile->ws_type) /* the profile's default mapping */
        return legacy.profile->ws_type(ws_type);
    return ws_type;
}

Gasf gks_legacy_asf(void)
{
    return legacy.asf;
}

/* NCAR's record: escape_r1.size characters at escape_r1.data, to the first NUL, trailing
 * blanks dropped; NULL if empty or absent (or on storage overflow: *nomem set). */
static char *ncar_record(const Gescape_in_data *in, int *nomem)
{
    *nomem = 0;
    if (!in || !in->escape_r1.data)
        return NULL;
    const char *d = in->escape_r1.data;
    size_t n = strnlen(d, in->escape_r1.size);
    while (n > 0 && (d[n - 1] == ' ' || d[n - 1] == '\t'))
        n--;
    size_t lead = 0;
    while (lead < n && (d[lead] == ' ' || d[lead] == '\t'))
        lead++;
    if (lead == n)
        return NULL;
    char *s = gks_strndup(d + lead, n - lead);
    *nomem = s == NULL;
    return s;
}

int gks_legacy_escape(Gint func_id, const Gescape_in_data *in, int *pause_ws_id)
{
    *pause_ws_id = -1;
    int nomem;
    char *rec = ncar_record(in, &nomem);
    if (!rec)
        return nomem ? 300 : 182;
    if (func_id == GESC_NCAR_FILE_NAME) {
        gks_free(legacy.next_file);
        legacy.next_file = rec;
        return 0;
    }
    int id;
    const char *p = rec;
    const int ok = parse_num(&p, &id) == 0 && *p == '\0';
    gks_free(rec);
    if (!ok)
        return 182;
    *pause_ws_id = id;
    return 0;
}

char *gks_legacy_take_file_name(int writes_file)
{
    if (!writes_file || !legacy.next_file)
        return NULL;
    char *s = legacy.next_file;
    legacy.next_file = NULL;
    return s;
}
