/* SPDX-License-Identifier: MIT */
/*
 * gks_fortran_mf.c -- FORTRAN 77 binding of the GKS metafile functions (ISO 8651-1):
 * GWITM, GGTITM, GRDITM, GIITM. The item data record is DATREC, an array of LDR (MLDR)
 * CHARACTER elements holding the record's characters one after the other (ISO 8651-1
 * declares CHARACTER*80 DATREC(LDR)); its capacity is LDR times the element length.
 */
#include "gks_fortran.h"
#include <string.h>

/* The record capacity of DATREC(LDR) (0 for a negative LDR). */
static size_t capacity(fint ldr, size_t elem_len)
{
    return ldr > 0 ? (size_t)ldr * elem_len : 0;
}

/* A length that does not fit in DATREC reaches the core as an invalid length (161). */
static Gint fitting(fint len, fint ldr, size_t elem_len)
{
    return len >= 0 && (size_t)len > capacity(ldr, elem_len) ? -1 : len;
}

/* DATREC's characters as a Gitem_data record (the core keeps records character-coded). */
static Gitem_data item_of(const char *rec, size_t n)
{
    Gitem_data d = { .data.impl_dep = { n, (void *)rec } };
    return d;
}

/* GWITM(WKID, TYPE, IDRL, LDR, DATREC) */
FAPI void FNAME(gwitm, GWITM)(const fint *wkid, const fint *type, const fint *idrl,
                              const fint *ldr, const char *datrec, size_t datrec_len)
{
    Gitem_data d = item_of(datrec, capacity(*ldr, datrec_len));
    gwrite_item(*wkid, *type, fitting(*idrl, *ldr, datrec_len), &d);
}

/* GGTITM(WKID, TYPE, IDRL) */
FAPI void FNAME(ggtitm, GGTITM)(const fint *wkid, fint *type, fint *idrl)
{
    Gint t = 0, l = 0;
    gget_item_type(*wkid, &t, &l);
    *type = t;
    *idrl = l;
}

/* GRDITM(WKID, MIDRL, MLDR, DATREC): at most MIDRL characters (and no more than DATREC
 * holds); the rest of DATREC is blank. */
FAPI void FNAME(grditm, GRDITM)(const fint *wkid, const fint *midrl, const fint *mldr,
                                char *datrec, size_t datrec_len)
{
    size_t cap = capacity(*mldr, datrec_len);
    if (cap)
        memset(datrec, ' ', cap);
    Gint max = *midrl;
    if (max > 0 && (size_t)max > cap)
        max = (Gint)cap;
    Gitem_data d = item_of(cap ? datrec : NULL, cap);
    gread_item(*wkid, max, &d);
}

/* GIITM(TYPE, IDRL, LDR, DATREC) */
FAPI void FNAME(giitm, GIITM)(const fint *type, const fint *idrl, const fint *ldr,
                              const char *datrec, size_t datrec_len)
{
    Gitem_data d = item_of(datrec, capacity(*ldr, datrec_len));
    ginterpret_item(*type, fitting(*idrl, *ldr, datrec_len), &d);
}
