/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_items.h -- what the item table (gks_mf_items.def) generates: the item numbers
 * GKSM_ITEM_<NAME>, for each recording function GKSM_FN_<SYM> (its item), and the
 * format reader shared by the encoder and the decoder.
 */
#ifndef GKS_MF_ITEMS_H
#define GKS_MF_ITEMS_H
#include "gks_private.h"
#include "gks.h"

/* The kinds of item (gks_mf_items.def). */
enum { GKSM_REC_WS, GKSM_REC_ALL, GKSM_REC_OWN, GKSM_PRIM, GKSM_ATTR, GKSM_STATE, GKSM_READ };

enum {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_ITEM_##name = type,
#define GKSM_ALSO(key, name, kind, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
    GKSM_ITEM_USER_MIN = 101 /* user items: 101..999 */
};

/* GKSM_FN_<SYM>: the item a recording function writes (a hook of a function without a
 * row does not compile). */
#define GKSM_KEY_REC_WS(name, key) GKSM_FN_##key = GKSM_ITEM_##name,
#define GKSM_KEY_REC_ALL(name, key) GKSM_FN_##key = GKSM_ITEM_##name,
#define GKSM_KEY_REC_OWN(name, key) GKSM_FN_##key = GKSM_ITEM_##name,
#define GKSM_KEY_PRIM(name, key)
#define GKSM_KEY_ATTR(name, key)
#define GKSM_KEY_STATE(name, key)
#define GKSM_KEY_READ(name, key)
enum {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_KEY_##kind(name, key)
#define GKSM_ALSO(key, name, kind, fmt) GKSM_KEY_##kind(name, key)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
    GKSM_FN_NONE_ = -1
};

/* ---- the format column (gks_mf_items.def) as tokens: (i, 16r, r) ----
 * GKSM_EACH(M, groups...) expands M(group, position) for each of at most 8 groups (an
 * empty list is one empty group, which every M below maps to nothing). */
#define GKSM_CAT_(a, b) a##b
#define GKSM_CAT(a, b) GKSM_CAT_(a, b)
#define GKSM_NARGS(...) GKSM_NARGS_(__VA_ARGS__, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define GKSM_NARGS_(a1, a2, a3, a4, a5, a6, a7, a8, n, ...) n
#define GKSM_EACH(M, ...) GKSM_CAT(GKSM_EACH_, GKSM_NARGS(__VA_ARGS__))(M, __VA_ARGS__)
#define GKSM_EACH_1(M, a) M(a, 0)
#define GKSM_EACH_2(M, a, b) M(a, 0) M(b, 1)
#define GKSM_EACH_3(M, a, b, c) GKSM_EACH_2(M, a, b) M(c, 2)
#define GKSM_EACH_4(M, a, b, c, d) GKSM_EACH_3(M, a, b, c) M(d, 3)
#define GKSM_EACH_5(M, a, b, c, d, e) GKSM_EACH_4(M, a, b, c, d) M(e, 4)
#define GKSM_EACH_6(M, a, b, c, d, e, f) GKSM_EACH_5(M, a, b, c, d, e) M(f, 5)
#define GKSM_EACH_7(M, a, b, c, d, e, f, g) GKSM_EACH_6(M, a, b, c, d, e, f) M(g, 6)
#define GKSM_EACH_8(M, a, b, c, d, e, f, g, h) GKSM_EACH_7(M, a, b, c, d, e, f, g) M(h, 7)

/* The format string of a token list: GKSM_FMT_STR (i, 16r) is "i16r". A group not listed
 * here (a new count) fails to compile: add its three lines (string, parameter, argument). */
#define GKSM_FMT_STR(...) "" GKSM_EACH(GKSM_S, __VA_ARGS__)
#define GKSM_S(t, k) GKSM_S_##t
#define GKSM_S_
#define GKSM_S_any "*"
#define GKSM_S_i "i"
#define GKSM_S_r "r"
#define GKSM_S_s "s"
#define GKSM_S_I "I"
#define GKSM_S_2i "2i"
#define GKSM_S_17i "17i"
#define GKSM_S_2r "2r"
#define GKSM_S_3r "3r"
#define GKSM_S_4r "4r"
#define GKSM_S_6r "6r"
#define GKSM_S_9r "9r"
#define GKSM_S_12r "12r"
#define GKSM_S_16r "16r"

/* A typed hook's parameters after its fixed ones: GKSM_PARAMS (i, 16r) is
 * ", int a0, const double *a1" (I: ", int a<k>n, const int *a<k>"). */
#define GKSM_PARAMS(...) GKSM_EACH(GKSM_P, __VA_ARGS__)
#define GKSM_P(t, k) GKSM_P_##t(k)
#define GKSM_P_(k)
#define GKSM_P_i(k) , int a##k
#define GKSM_P_r(k) , double a##k
#define GKSM_P_s(k) , const char *a##k
#define GKSM_P_I(k) , int a##k##n, const int *a##k
#define GKSM_P_2i(k) , const int *a##k
#define GKSM_P_17i(k) , const int *a##k
#define GKSM_P_2r(k) , const double *a##k
#define GKSM_P_3r(k) , const double *a##k
#define GKSM_P_4r(k) , const double *a##k
#define GKSM_P_6r(k) , const double *a##k
#define GKSM_P_9r(k) , const double *a##k
#define GKSM_P_12r(k) , const double *a##k
#define GKSM_P_16r(k) , const double *a##k

/* One group's value as the encoder reads it (gks_mf_record.c): i or r a number, a count
 * and ints (I), N values (iv or rv), a string. */
typedef struct gksm_arg {
    long i;
    double r;
    const int *iv;
    const double *rv;
    const char *s;
} gksm_arg;

/* The hook's parameters as gksm_arg initialisers: GKSM_ARGS (i, 16r) is
 * "{ .i = a0 }, { .rv = a1 },". */
#define GKSM_ARGS(...) GKSM_EACH(GKSM_A, __VA_ARGS__)
#define GKSM_A(t, k) GKSM_A_##t(k)
#define GKSM_A_(k)
#define GKSM_A_i(k) { .i = a##k },
#define GKSM_A_r(k) { .r = a##k },
#define GKSM_A_s(k) { .s = a##k },
#define GKSM_A_I(k) { .i = a##k##n, .iv = a##k },
#define GKSM_A_2i(k) { .iv = a##k },
#define GKSM_A_17i(k) { .iv = a##k },
#define GKSM_A_2r(k) { .rv = a##k },
#define GKSM_A_3r(k) { .rv = a##k },
#define GKSM_A_4r(k) { .rv = a##k },
#define GKSM_A_6r(k) { .rv = a##k },
#define GKSM_A_9r(k) { .rv = a##k },
#define GKSM_A_12r(k) { .rv = a##k },
#define GKSM_A_16r(k) { .rv = a##k },

/* An item's data record format (gks_mf_items.def), NULL for a type without a row. */
const char *gksm_item_fmt(int type);

/* One group of an item format: n fields of kind k ('i', 'r', 's' or 'I'); arr = 1 when a
 * count was given (the values come from one array). Returns the format after the group,
 * or NULL at its end. */
static inline const char *gksm_fmt_next(const char *f, int *n, char *k, int *arr)
{
    if (!f || !*f)
        return NULL;
    int c = 0;
    *arr = 0;
    while (*f >= '0' && *f <= '9') {
        c = 10 * c + (*f++ - '0');
        *arr = 1;
    }
    *n = *arr ? c : 1;
    *k = *f ? *f++ : 'i';
    return f;
}
#endif
