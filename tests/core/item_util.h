/* SPDX-License-Identifier: MIT */
/* item_util.h -- Gitem_data records for the metafile tests: this implementation keeps a
 * record's characters in data.impl_dep (include/gks.h). */
#ifndef ITEM_UTIL_H
#define ITEM_UTIL_H
#include <gks.h>
#include <string.h>
/* A record of n characters at s (s may be NULL). */
#define ITEMN(s, n) (&(Gitem_data){ .data.impl_dep = { (size_t)(n), (void *)(s) } })
/* A record holding the characters of the NUL-terminated s. */
#define ITEM(s) ITEMN((s), strlen(s))
/* A read buffer: the array b. */
#define RBUF(b) ITEMN((b), sizeof(b))
#endif
