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
#define GKSM_ALSO(key, name, kind)
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
#define GKSM_ALSO(key, name, kind) GKSM_KEY_##kind(name, key)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
    GKSM_FN_NONE_ = -1
};

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
