/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_file.c -- the file name of a metafile workstation (gks_mf_file.h).
 */
#include "gks_mf_file.h"
#include "gks_alloc.h"
#include <stdio.h>
#include <string.h>

char *gks_mf_file_name(const char *conn_id)
{
    size_t n = strlen(conn_id);
    int digits = n > 0;
    for (size_t i = 0; i < n; i++)
        digits &= conn_id[i] >= '0' && conn_id[i] <= '9';
    if (!digits)
        return gks_strdup(conn_id);
    char *s = gks_alloc_array(n + 9, 1);
    if (s)
        snprintf(s, n + 9, "gks%s.gksm", conn_id);
    return s;
}

int gks_mf_file_path(const char *conn_id, char **path)
{
    if (!conn_id || !*conn_id)
        return 21;
    *path = gks_mf_file_name(conn_id);
    return *path ? 0 : 300;
}
