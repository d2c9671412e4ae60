/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_codec.h -- the GKS metafile (GKSM, ISO 7942 Annex E) codec, character-coded as RAL GKS
 * writes it: a 90-character file header, then items "header + data record". No GKS state:
 * the metafile workstations (output and input) build on this.
 *
 * File header: "GKSM" N(40 name) D(8 yy/mm/dd) V(2) H(2) T(2) L(2) I(2) R(2) F(2) RI(2)
 *   ZERO(11) ONE(11). H = length of the "GKSM" prefix repeated in each item header (0..4),
 *   T = length of the item type field, L = length of the data-length field, I/R = widths of
 *   integer/real fields in data records, F = 1 (formatted characters), RI = 1 (reals as
 *   reals; 2 = scaled integers, read only).
 * This writer uses H=4, T=3, L=10, I=11, R=24 (reals with 17 significant digits, so every
 *   double round-trips exactly); the reader accepts any H 0..4, T 1..4, L 1..10, I 1..20,
 *   R 1..40 (RAL: 1, 3, 7, 4, 9).
 * Item header: the prefix ("GKSM" truncated to H), the item type (T digits) and the length
 *   of the data record in characters (L digits), all right-justified, blank-padded.
 * Data record: integers in I-wide fields, reals in R-wide fields, strings as an integer
 *   count followed by the raw characters.
 *
 * The reader treats its input as untrusted: every length is checked against the header's
 * limits and the bytes left in the file; nothing is allocated from a declared count. Errors
 * use the standard's numbers: 162 no item left, 163 item invalid (bad header or item
 * header, truncated data), 165 data record invalid for the item type.
 * Users: the MO driver (writing), the MI driver (the file and its items), the core's item
 * encoder and decoder (data records): so it lives with the drivers (ws/mf) and sees no
 * GKS state.
 */
#ifndef GKSM_H
#define GKSM_H
#include "gks_private.h"
#include <stddef.h>
#include <stdio.h>

#define GKSM_HEADER_LEN 90
#define GKSM_MAX_ITEM_TYPE 9999

/* ---- writing ---- */

/* A data record under construction (grows; NULL-safe to free when zeroed). */
typedef struct gksm_rec {
    char *buf;
    size_t len, cap;
    int failed;       /* an allocation failed: the record is unusable */
} gksm_rec;

void gksm_rec_init(gksm_rec *r);
void gksm_rec_free(gksm_rec *r);
void gksm_rec_clear(gksm_rec *r);
void gksm_rec_int(gksm_rec *r, long v);
/* Non-finite values are written as 0 (GKS never passes them to a workstation). */
void gksm_rec_real(gksm_rec *r, double v);
/* Integer count then the raw characters. */
void gksm_rec_str(gksm_rec *r, const char *s, size_t n);
/* Raw characters (a user item's data record as given). */
void gksm_rec_raw(gksm_rec *r, const char *s, size_t n);

/* Writes the file header; name is truncated/padded to 40 characters, date "yy/mm/dd"
 * (NULL: today's date). Returns 0 or -1 (write error). */
int gksm_write_header(FILE *fp, const char *name, const char *date);
/* Writes one item. Returns 0, -1 (write error or failed record) or 161 (type out of range
 * or record too long for the length field). */
int gksm_write_item(FILE *fp, int type, const gksm_rec *r);
/* The same for a record of len characters at rec. */
int gksm_write_record(FILE *fp, int type, const char *rec, size_t len);

/* ---- reading ---- */

typedef struct gksm_in {
    FILE *fp;
    long long left;          /* bytes left after the current position, -1 if unknown */
    int h, t, l, iw, rw, ri; /* header field widths and real format */
    double zero, one;        /* scaled-integer reals: value = (k - zero) / (one - zero) */
    int have_item;           /* an item header has been read and its data not yet */
    int type;
    size_t len;              /* data record length of the current item */
} gksm_in;

/* Reads and checks the file header. Returns 0 or 163. */
int gksm_in_open(gksm_in *m, FILE *fp);
/* The type and data length of the next item (reads its header once; repeated calls return
 * the same item until its data is read or skipped). Returns 0, 162 (end of file) or 163. */
int gksm_in_peek(gksm_in *m, int *type, size_t *len);
/* Reads the current item's data record into buf (cap bytes): if cap < len, the first cap
 * characters are stored and the rest skipped. *got = characters stored. Returns 0, 162 or
 * 163 (file ends inside the record). */
int gksm_in_read(gksm_in *m, char *buf, size_t cap, size_t *got);
/* Skips the current item. Returns 0, 162 or 163. */
int gksm_in_skip(gksm_in *m);

/* A cursor over a data record, for decoding its fields. */
typedef struct gksm_cur {
    const char *p;
    size_t n;
    int iw, rw, ri;
    double zero, one;
} gksm_cur;

void gksm_cur_init(gksm_cur *c, const gksm_in *m, const char *rec, size_t len);
/* Each returns 0 or 165 (field missing or not a number / out of range). */
int gksm_get_int(gksm_cur *c, long *v);
int gksm_get_real(gksm_cur *c, double *v);
/* A string: count then characters; *s points into the record (not terminated). */
int gksm_get_str(gksm_cur *c, const char **s, size_t *n);
/* Characters left undecoded. */
size_t gksm_cur_left(const gksm_cur *c);
#endif
