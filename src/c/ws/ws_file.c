/* SPDX-License-Identifier: MIT */
/*
 * ws_file.c -- file names of the file workstations (ws_file.h) and the ESCAPE that sets one
 * (gks_ws_file_rename, ws_driver.h); the entries the file workstations (PNG, cairo) share:
 * messages to standard error, the integer argument of their ESCAPEs.
 */
#include "ws_file.h"
#include "ws_driver.h"
#include "gks_alloc.h"
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void gks_ws_note(const gks_ws *ws, const char *fmt, ...)
{
    char text[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    if (ws && ws->host && ws->host->note)
        ws->host->note(text);
}

char *gks_ws_file_base(const char *conn, const char *ext)
{
    size_t n = conn ? strlen(conn) : 0, ne = strlen(ext);
    if (n == 0)
        return gks_strdup("gks");
    int digits = 1;
    for (size_t i = 0; i < n; i++)
        digits &= isdigit((unsigned char)conn[i]) != 0;
    if (digits) {
        char *s = gks_alloc_array(n + 4, 1);
        if (s)
            snprintf(s, n + 4, "gks%s", conn);
        return s;
    }
    if (n > ne && strcmp(conn + n - ne, ext) == 0)
        return gks_strndup(conn, n - ne);
    return gks_strdup(conn);
}

char *gks_ws_file_default_base(const gks_ws *ws, const char *ext)
{
    const char *conn = ws->conn_id ? ws->conn_id : "";
    char *b = gks_ws_file_base(conn, ext);
    int named = 0; /* the connection names a file: a second user of it gets error 21 */
    for (const char *c = conn; *c && !named; c++)
        named = !isdigit((unsigned char)*c);
    char *f = b && !named ? gks_ws_file_frame(b, 1, ext) : NULL;
    int taken = f && gks_ws_file_taken(ws, f);
    gks_free(f);
    if (!taken)
        return b;
    size_t n = strlen(b) + 24;
    char *s = gks_alloc_array(n, 1);
    if (s)
        snprintf(s, n, "%s-ws%d", b, ws->id);
    gks_free(b);
    return s;
}

char *gks_ws_file_frame(const char *base, int frame, const char *ext)
{
    size_t n = strlen(base) + strlen(ext) + 16;
    char *path = gks_alloc_array(n, 1);
    if (!path)
        return NULL;
    if (frame <= 1)
        snprintf(path, n, "%s%s", base, ext);
    else
        snprintf(path, n, "%s-%03d%s", base, frame, ext);
    return path;
}

int gks_ws_file_message(gks_ws *ws, const char *msg)
{
    fprintf(stderr, "gks3d: message for workstation %d: %s\n", ws->id, msg);
    return 0;
}

int gks_ws_escape_int(const Gescape_in_data *in, int lo, int hi, int *v)
{
    if (in->num_ints < 2 || !in->ints || in->ints[1] < lo || in->ints[1] > hi)
        return 182;
    *v = in->ints[1];
    return 0;
}

int gks_ws_file_claim_frame(gks_ws *ws, const char *base, int frame, const char *ext,
                            char **path)
{
    *path = gks_ws_file_frame(base, frame, ext);
    int e = *path ? gks_ws_file_claim(ws, *path) : 300; /* 21: another workstation's file */
    if (e) {
        gks_free(*path);
        *path = NULL;
    }
    return e;
}

int gks_ws_file_rename(gks_ws *ws, const char *name, size_t len, int frame, const char *ext,
                       char **base)
{
    char *b = gks_strndup(name, len), *f = NULL;
    int e = b ? gks_ws_file_claim_frame(ws, b, frame, ext, &f) : 300;
    gks_free(f);
    if (e) {
        gks_free(b);
        return e;
    }
    gks_free(*base);
    *base = b;
    return 0;
}
