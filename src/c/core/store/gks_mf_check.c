/* SPDX-License-Identifier: MIT */
/*
 * gks_mf_check.c -- the metafile column of include/gks_functions.def against the item
 * table (gks_mf_items.def), checked by the compiler; this file has no code. A function
 * whose column is MF_ITEM(NAME) must be the key of item NAME's row (or of a GKSM_ALSO of
 * it); MF_STATE and MF_PRIM must name an attribute or state row and a primitive row; and
 * the function of every row a hook writes must name that row in its column. What the
 * compiler cannot see (that the function calls its hook, that every attribute row is
 * claimed) is checked by tests/core/check_mf_items.sh.
 */
#include "gks_mf_items.h"

/* The kind of each item. */
enum {
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_KIND_##name = GKSM_##kind,
#define GKSM_ALSO(key, name, kind, fmt)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
    GKSM_KIND_NONE_ = -1
};

/* A column as "check, item": MF_ITEM(CLEAR) -> MF_ITEM_, CLEAR. */
#define MF_NO MF_NONE_, _
#define MF_PRIMS MF_NONE_, _
#define MF_USER MF_NONE_, _
#define MF_ITEM(name) MF_ITEM_, name
#define MF_STATE(name) MF_STATE_, name
#define MF_PRIM(name) MF_PRIM_, name
#define MF_APPLY(sym, ...) MF_APPLY_(sym, __VA_ARGS__)
#define MF_APPLY_(sym, check, name) check(sym, name)

/* Whether a function's column agrees with the table. */
#define MF_NONE_(sym, name) 1
#define MF_ITEM_(sym, name) ((int)GKSM_FN_##sym == (int)GKSM_ITEM_##name)
#define MF_STATE_(sym, name) ((int)GKSM_KIND_##name == GKSM_ATTR || (int)GKSM_KIND_##name == GKSM_STATE)
#define MF_PRIM_(sym, name) ((int)GKSM_KIND_##name == GKSM_PRIM)
#define GKS_FN(id, sym, name, states, mf)                                                  \
    _Static_assert(MF_APPLY(sym, mf), #sym ": its metafile column names an item of "       \
                                          "another function or kind (gks_functions.def)");
#include "gks_functions.def"
#undef GKS_FN
#undef MF_NONE_
#undef MF_ITEM_
#undef MF_STATE_
#undef MF_PRIM_

/* The item a function's column says its hook writes (MF_ITEM), else -1. */
#define MF_NONE_(sym, name) -1
#define MF_ITEM_(sym, name) GKSM_ITEM_##name
#define MF_STATE_(sym, name) -1
#define MF_PRIM_(sym, name) -1
enum {
#define GKS_FN(id, sym, name, states, mf) GKS_MF_COLUMN_##sym = MF_APPLY(sym, mf),
#include "gks_functions.def"
#undef GKS_FN
    GKS_MF_COLUMN_NONE_ = -1
};

/* Every row a hook writes is its function's column. */
#define GKSM_ROW_REC(name, key)                                                            \
    _Static_assert((int)GKS_MF_COLUMN_##key == (int)GKSM_ITEM_##name,                                \
                   #key " writes item " #name ", which its metafile column does not name");
#define GKSM_ROW_REC_WS GKSM_ROW_REC
#define GKSM_ROW_REC_ALL GKSM_ROW_REC
#define GKSM_ROW_REC_OWN GKSM_ROW_REC
#define GKSM_ROW_PRIM(name, key)
#define GKSM_ROW_ATTR(name, key)
#define GKSM_ROW_STATE(name, key)
#define GKSM_ROW_READ(name, key)
#define GKSM_ITEM(type, name, kind, key, fmt, dec, ...) GKSM_ROW_##kind(name, key)
#define GKSM_ALSO(key, name, kind, fmt) GKSM_ROW_##kind(name, key)
#include "gks_mf_items.def"
#undef GKSM_ITEM
#undef GKSM_ALSO
