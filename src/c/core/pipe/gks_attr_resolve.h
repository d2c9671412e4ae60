/* SPDX-License-Identifier: MIT */
/*
 * gks_attr_resolve.h -- the attribute stage of the output pipeline: attribute resolution
 * for one workstation (ISO 7942 4.4.4-4.4.8). Each aspect comes from the current
 * individual value or, by its aspect source flag, from the workstation's bundle of the
 * current index (index 1 if that index is not defined); then the workstation realizes it
 * (unsupported linetype -> 1, marker type -> 3, font -> 1, interior style -> HOLLOW,
 * hatch style -> its first one, pattern index -> 1; widths and sizes clamped to the
 * workstation's range; undefined colour index -> 1).
 */
#ifndef GKS_ATTR_RESOLVE_H
#define GKS_ATTR_RESOLVE_H
#include "gks_private.h"
#include "gks_context.h"
#include "gks_text_layout.h"
#include <assert.h>
#include <string.h>

/* The workstation's output description table (never NULL). */
const gks_wdt_output *gks_attr_wdt(const gks_ws *ws);

/* The colour of index ind on ws (undefined index -> 1). */
Grgb gks_attr_colour(const gks_ws *ws, int ind);
/* The realized colour index (undefined -> 1). */
int gks_attr_colr_ind(const gks_ws *ws, int ind);

/* Realized bundles (INQUIRE ... REPRESENTATION with GINQ_REALIZED, and dispatch). */
void gks_attr_realize_line(const gks_ws *ws, const Gline_bundle *in, Gline_bundle *out);
void gks_attr_realize_marker(const gks_ws *ws, const Gmarker_bundle *in, Gmarker_bundle *out);
void gks_attr_realize_text(const gks_ws *ws, const Gtext_bundle *in, Gtext_bundle *out);
void gks_attr_realize_fill(const gks_ws *ws, const Gfill_bundle *in, Gfill_bundle *out);
void gks_attr_realize_edge(const gks_ws *ws, const Gedge_bundle *in, Gedge_bundle *out);

/* The effective (ASF-selected, realized) bundles of the current attributes on ws. */
void gks_attr_line(const gks_ws *ws, const gks_cur_attrs *a, Gline_bundle *out);
void gks_attr_marker(const gks_ws *ws, const gks_cur_attrs *a, Gmarker_bundle *out);
void gks_attr_text(const gks_ws *ws, const gks_cur_attrs *a, Gtext_bundle *out);
void gks_attr_fill(const gks_ws *ws, const gks_cur_attrs *a, Gfill_bundle *out);
void gks_attr_edge(const gks_ws *ws, const gks_cur_attrs *a, Gedge_bundle *out);

/* Resolved text layout attributes for ws (bundle part from gks_attr_text). */
void gks_attr_text_layout(const gks_ws *ws, const gks_cur_attrs *a, gks_text_attrs *out,
                          Grgb *colour);

/* Fill a primitive's colour and attributes for ws for an area primitive: interior,
 * pattern (*pattern receives an allocated colour array the caller frees with gks_free,
 * NULL when not a pattern), edges. m maps WC3 to the primitive's final NDC3 (the
 * normalization, then the segment transformation): the pattern reference point and box
 * vectors go through it. Returns 0 or 300. */
int gks_attr_prim_fill(const gks_ws *ws, const gks_cur_attrs *a, const double m[3][4],
                       gks_prim *p, Grgb **pattern);
/* The primitive of an area for ws: zero but for kind GKS_PRIM_FILL_AREA, n_loops 1, the
 * attributes of gks_pipe_prim_common and gks_attr_prim_fill (the same values, *pattern
 * likewise, *err 0 or 300), attrs.edge_flag cleared unless edges (FILL AREA SET),
 * resolved once while the current attributes a and the workstation tables stay the same:
 * the primitive kept in the state list (gks_area_memo), with its attr_gen (a new number
 * whenever it is made again; one for the set with edges, the next for the same cleared),
 * or buf when it is not kept (a pattern, an error; attr_gen 0). The caller sets the
 * geometry, nothing else, and sends it before the next call. gks_attr_area_prim is the
 * common case inline (the state list's attributes unwritten since the primitive was kept),
 * gks_attr_area_make every case. */
gks_prim *gks_attr_area_make(const gks_ws *ws, const gks_cur_attrs *a, const double m[3][4],
                             int edges, gks_prim *buf, Grgb **pattern, int *err);

/* The primitive kept in e, for an area with edges or not (gks_attr_area_prim). */
static inline gks_prim *gks_attr_area_kept(gks_area_memo *e, int edges)
{
    const int cleared = e->edge_flag && !edges;
    e->p.attrs.edge_flag = e->edge_flag && edges;
    e->p.attr_gen = e->attr_gen + (uint64_t)cleared;
    return &e->p;
}

static inline gks_prim *gks_attr_area_prim(const gks_ws *ws, const gks_cur_attrs *a,
                                           const double m[3][4], int edges, gks_prim *buf,
                                           Grgb **pattern, int *err)
{
    const gks_context *c = gks_ctx();
    gks_area_memo *e = &c->sl->area_memo[(unsigned)ws->id % GKS_MAX_OPEN_WS];
    if (e->ws == ws && e->tables_gen == c->tables_gen && a == &c->sl->attrs &&
        e->attrs_gen == c->sl->attrs_gen) {
        assert(memcmp(&e->a, a, sizeof *a) == 0); /* a write past gks_attrs_w */
        *pattern = NULL;
        *err = 0;
        return gks_attr_area_kept(e, edges);
    }
    return gks_attr_area_make(ws, a, m, edges, buf, pattern, err);
}
void gks_attr_prim_line(const gks_ws *ws, const gks_cur_attrs *a, gks_prim *p);
void gks_attr_prim_marker(const gks_ws *ws, const gks_cur_attrs *a, gks_prim *p);
#endif
