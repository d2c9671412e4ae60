/* SPDX-License-Identifier: MIT */
/*
 * gks_segment.c -- segment functions (ISO 7942 5.7, GKS-3D SET SEGMENT TRANSFORMATION 3)
 * and their inquiries. The content lives in the segment store (gks_seg_store.h); primitives
 * enter it from the output pipeline while a segment is open, and leave it again through
 * segment replay (gks_replay.c: regeneration, REDRAW ALL SEGMENTS ON WORKSTATION).
 *
 * Picture changes: this PNG-file implementation cannot modify a picture dynamically, so a
 * change that affects a workstation's picture (segment transformation, visibility,
 * priority, deletion) needs an implicit regeneration there: done at once when the
 * workstation's implicit regeneration mode is ALLOWED, else "new frame action necessary
 * at update" is set and UPDATE WORKSTATION (PERFORM) or REDRAW ALL SEGMENTS does it.
 * Highlighting and detectability do not change a PNG picture.
 */
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_seg_store.h"
#include "gks_segment.h"
#include "gks_replay.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <math.h>
#include <stddef.h>
#include <string.h>

static gks_seg_store *store(void)
{
    return gks_ctx()->sl->segs;
}

static int finite_n(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* The pictures of workstations ids[0..n-1] have changed. A failed regeneration is
 * reported for its workstation and the others still regenerate, unless the handler
 * changed the world: then 0 (the caller returns at once). */
static GKS_MUST_CHECK int pictures_changed(const int *ids, int n, int fctid)
{
    for (int i = 0; i < n; i++) {
        gks_ws *ws = gks_ws_lookup(ids[i]);
        if (!ws)
            continue;
        if (ws->irg_mode != GIRG_ALLOWED) {
            ws->new_frame = GNEW_YES;
            continue;
        }
        int err = gks_ws_regenerate(ws);
        if (err && !gks_error_report(err, fctid))
            return 0;
    }
    return 1;
}

/* The picture of every workstation holding segment s has changed (see above). */
static GKS_MUST_CHECK int picture_changed(const gks_segment *s, int fctid)
{
    int ids[GKS_MAX_OPEN_WS]; /* a copy: s may cease to exist during the loop */
    memcpy(ids, s->ws, (size_t)s->n_ws * sizeof ids[0]);
    return pictures_changed(ids, s->n_ws, fctid);
}

/* A picture change as the caller's last action: whatever the handler did, the caller
 * returns next (the GKS_MUST_CHECK of picture_changed is satisfied here, once). */
static void shown_change(const gks_segment *s, int fctid)
{
    if (!picture_changed(s, fctid)) {
    }
}

/* Segment `name` ceases to exist (pointers to it are stale: the world changes). */
static void seg_delete(int name)
{
    gks_seg_delete(store(), name);
    gks_world_changed();
}

/* Entry of a function on an existing segment: the state check, then 120, 122. */
static gks_segment *existing(int fctid, Gint name)
{
    if (gks_check_state(fctid))
        return NULL;
    if (name < 1)
        GKS_FAIL_RET(120, fctid, NULL);
    gks_segment *s = gks_seg_find(store(), name);
    if (!s)
        GKS_FAIL_RET(122, fctid, NULL);
    return s;
}

GKS_API void gcreate_seg(Gint seg_name)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_CRSG))
        return;
    if (seg_name < 1)
        GKS_FAIL(120, GFN_CRSG);
    if (gks_seg_find(store(), seg_name))
        GKS_FAIL(121, GFN_CRSG);
    gks_segment *s = gks_seg_create(store(), seg_name);
    if (!s)
        GKS_FAIL(301, GFN_CRSG);
    for (int i = 0; i < c->sl->n_active; i++)
        gks_seg_ws_add(s, c->sl->active_ws[i]); /* n_active <= GKS_MAX_OPEN_WS: cannot fail */
    c->sl->open_seg = seg_name;
    c->op_st = GST_SGOP;
    GKS_MF(CRSG, seg_name);
}

GKS_API void gclose_seg(void)
{
    gks_context *c = gks_ctx();
    if (gks_check_state(GFN_CLSG))
        return;
    c->sl->open_seg = 0;
    c->op_st = GST_WSAC;
    GKS_MF0(CLSG);
}

GKS_API void grename_seg(Gint old_seg_name, Gint new_seg_name)
{
    if (gks_check_state(GFN_RENSG))
        return;
    if (old_seg_name < 1 || new_seg_name < 1)
        GKS_FAIL(120, GFN_RENSG);
    gks_segment *s = gks_seg_find(store(), old_seg_name);
    if (gks_seg_find(store(), new_seg_name))
        GKS_FAIL(121, GFN_RENSG);
    if (!s)
        GKS_FAIL(122, GFN_RENSG);
    s->name = new_seg_name;
    GKS_MF(RENSG, old_seg_name, new_seg_name);
    gks_state_list *sl = gks_ctx()->sl;
    if (sl->open_seg == old_seg_name)
        sl->open_seg = new_seg_name;
}

GKS_API void gdel_seg(Gint seg_name)
{
    gks_segment *s = existing(GFN_DSG, seg_name);
    if (!s)
        return;
    if (gks_ctx()->sl->open_seg == seg_name)
        GKS_FAIL(125, GFN_DSG);
    GKS_MF(DSG, seg_name);
    /* ISO 7942: the segment is deleted, then the pictures are regenerated without it. */
    int vis = s->vis;
    int ids[GKS_MAX_OPEN_WS], n = s->n_ws;
    memcpy(ids, s->ws, (size_t)n * sizeof ids[0]);
    seg_delete(seg_name);
    if (vis && !pictures_changed(ids, n, GFN_DSG))
        return;
}

GKS_API void gdel_seg_ws(Gint ws_id, Gint seg_name)
{
    if (gks_check_state(GFN_DSGWK))
        return;
    gks_ws *ws = gks_ws_checked(GFN_DSGWK, ws_id, GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT);
    if (!ws)
        return;
    if (seg_name < 1)
        GKS_FAIL(120, GFN_DSGWK);
    gks_segment *s = gks_seg_find(store(), seg_name);
    if (!s || !gks_seg_on_ws(s, ws_id))
        GKS_FAIL(123, GFN_DSGWK);
    if (gks_ctx()->sl->open_seg == seg_name)
        GKS_FAIL(125, GFN_DSGWK);
    GKS_MF_WS(DSGWK, ws_id, seg_name);
    gks_seg_ws_remove(s, ws_id);
    int vis = s->vis;
    if (s->n_ws == 0) /* stored nowhere any more: the segment ceases to exist */
        seg_delete(seg_name);
    if (vis && !pictures_changed(&ws_id, 1, GFN_DSGWK))
        return;
}

/* ------------------------------------------------------------ segment attributes */
/* SET SEGMENT TRANSFORMATION (3): m the n elements (12: 3-D, 6: 2-D) of the matrix as given
 * and recorded. 2003 for a NULL matrix, 308 for a non-finite element (GKS has no error of
 * its own for it: 308, as for the other non-finite reals, docs/BINDING.md; stored it would
 * make the segment vanish). Stored as 3x4: the 2-D matrix acts on x and y and z passes
 * unchanged (ISO 8805: the 3-D one with identity z row and no z coupling). A visible
 * segment's pictures change. */
static void set_tran(int fctid, int (*mf)(int, int, const double *), Gint name, const double *m,
                     int n)
{
    gks_segment *s = existing(fctid, name);
    if (!s)
        return;
    if (!m)
        GKS_FAIL(2003, fctid);
    if (!finite_n(m, n))
        GKS_FAIL(308, fctid);
    if (n == 12)
        memcpy(s->tran, m, sizeof s->tran);
    else
        gks_xform_mat23_to_mat34((const double (*)[3])m, s->tran);
    if (gks_mf_on() && !mf(fctid, name, m))
        return;
    if (s->vis)
        shown_change(s, fctid);
}

GKS_API void gset_seg_tran3(Gint seg_name, const Gtran_matrix3 tran_matrix)
{
    set_tran(GFN_SSGT3, gks_mf_rec_SSGT3, seg_name, tran_matrix ? &tran_matrix[0][0] : NULL, 12);
}

GKS_API void gset_seg_tran(Gint seg_name, const Gtran_matrix tran_matrix)
{
    set_tran(GFN_SSGT, gks_mf_rec_SSGT, seg_name, tran_matrix ? &tran_matrix[0][0] : NULL, 6);
}

/* SET VISIBILITY, HIGHLIGHTING, DETECTABILITY and SEGMENT PRIORITY: the function, its
 * typed metafile hook, the error for a value it does not take, the values and where the
 * segment holds it. A switch (real 0) takes lo (off) or hi (on) and stores 1 for on in an int; the
 * priority (real 1) takes a real in [lo, hi] and stores it in a double. A change of the
 * stored value alters the segment's pictures always (visibility), while it is visible
 * (priority) or never (highlighting and detectability do not show in a PNG picture). */
enum { SHOWN_NEVER, SHOWN_IF_VISIBLE, SHOWN_ALWAYS };
typedef struct {
    int fctid;
    int (*mf_switch)(int fctid, int name, int v); /* the typed hook of a switch, */
    int (*mf_real)(int fctid, int name, double v); /* or of the priority */
    int err, real;
    double lo, hi;
    size_t field;
    int shown;
} seg_attr;

static const seg_attr VIS = { GFN_SVIS, gks_mf_rec_SVIS, NULL, 2000, 0, GSEG_INVIS, GSEG_VIS,
                              offsetof(gks_segment, vis), SHOWN_ALWAYS };
static const seg_attr HIGHL = { GFN_SHLIT, gks_mf_rec_SHLIT, NULL, 2000, 0, GSEG_NORM, GSEG_HIGHL,
                                offsetof(gks_segment, highl), SHOWN_NEVER };
static const seg_attr DET = { GFN_SDTEC, gks_mf_rec_SDTEC, NULL, 2000, 0, GSEG_UNDET, GSEG_DET,
                              offsetof(gks_segment, det), SHOWN_NEVER };
static const seg_attr PRI = { GFN_SSGP, NULL, gks_mf_rec_SSGP, 126, 1, 0.0, 1.0,
                              offsetof(gks_segment, pri), SHOWN_IF_VISIBLE };

static void set_attr(const seg_attr *k, Gint name, double v)
{
    gks_segment *s = existing(k->fctid, name);
    if (!s)
        return;
    if (k->real ? !(v >= k->lo && v <= k->hi) : v != k->lo && v != k->hi)
        GKS_FAIL(k->err, k->fctid);
    if (gks_mf_on() && !(k->real ? k->mf_real(k->fctid, name, v)
                                 : k->mf_switch(k->fctid, name, (int)v)))
        return;
    char *f = (char *)s + k->field;
    double now = k->real ? v : v == k->hi, was = k->real ? *(double *)f : *(int *)f;
    if (now == was)
        return;
    if (k->real)
        *(double *)f = now;
    else
        *(int *)f = (int)now;
    if (k->shown == SHOWN_ALWAYS || (k->shown == SHOWN_IF_VISIBLE && s->vis))
        shown_change(s, k->fctid);
}

GKS_API void gset_vis(Gint seg_name, Gseg_vis vis) { set_attr(&VIS, seg_name, vis); }
GKS_API void gset_highl(Gint seg_name, Gseg_highl highl) { set_attr(&HIGHL, seg_name, highl); }
GKS_API void gset_seg_pri(Gint seg_name, Gfloat pri) { set_attr(&PRI, seg_name, pri); }
GKS_API void gset_det(Gint seg_name, Gseg_det det) { set_attr(&DET, seg_name, det); }

/* The segment `name` of a WISS function: 120, 124 (not on the WISS, or no such segment). */
static gks_segment *on_wiss(int fctid, const gks_ws *wiss, Gint name)
{
    if (name < 1)
        GKS_FAIL_RET(120, fctid, NULL);
    gks_segment *s = gks_seg_find(store(), name);
    if (!s || !gks_seg_on_ws(s, wiss->id))
        GKS_FAIL_RET(124, fctid, NULL);
    return s;
}

/* The WISS, or NULL after reporting 27. */
static gks_ws *wiss_open(int fctid)
{
    gks_ws *w = gks_wiss();
    if (!w)
        GKS_FAIL_RET(27, fctid, NULL);
    return w;
}

/* Entry of ASSOCIATE SEGMENT WITH WORKSTATION and COPY SEGMENT TO WORKSTATION: the state
 * check, 20, 25, 27 (no WISS), the checks of gks_ws_checked (flags) on ws_id, then the
 * segment on the WISS (120, 124). The segment and *ws, or NULL after reporting. */
static gks_segment *wiss_to_ws(int fctid, Gint ws_id, Gint name, unsigned flags, gks_ws **ws)
{
    if (gks_check_state(fctid))
        return NULL;
    if (ws_id < 0)
        GKS_FAIL_RET(20, fctid, NULL);
    if (!gks_ws_lookup(ws_id))
        GKS_FAIL_RET(25, fctid, NULL);
    gks_ws *wiss = wiss_open(fctid);
    if (!wiss)
        return NULL;
    *ws = gks_ws_checked(fctid, ws_id, flags);
    return *ws ? on_wiss(fctid, wiss, name) : NULL;
}

GKS_API void gassoc_seg_ws(Gint ws_id, Gint seg_name)
{
    gks_ws *ws;
    gks_segment *s = wiss_to_ws(GFN_ASGWK, ws_id, seg_name, GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT, &ws);
    if (!s || gks_seg_on_ws(s, ws_id))
        return; /* already stored there: nothing to do */
    if (gks_seg_ws_add(s, ws_id))
        GKS_FAIL(301, GFN_ASGWK);
    int err = s->vis ? gks_replay_segment(ws, s) : 0;
    if (err)
        GKS_FAIL(err, GFN_ASGWK);
}

GKS_API void gcopy_seg_ws(Gint ws_id, Gint seg_name)
{
    gks_ws *ws;
    gks_segment *s = wiss_to_ws(GFN_CSGWK, ws_id, seg_name,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS, &ws);
    int err = s ? gks_replay_segment(ws, s) : 0;
    if (err)
        GKS_FAIL(err, GFN_CSGWK);
}

static void insert_any(int fctid, Gint seg_name, const double m[3][4])
{
    if (gks_check_state(fctid))
        return;
    gks_ws *wiss = wiss_open(fctid);
    if (!wiss)
        return;
    gks_segment *s = on_wiss(fctid, wiss, seg_name);
    if (!s)
        return;
    if (gks_ctx()->sl->open_seg == seg_name)
        GKS_FAIL(125, fctid);
    if (!m)
        GKS_FAIL(2003, fctid);
    if (!finite_n(&m[0][0], 12))
        GKS_FAIL(308, fctid);
    int err = gks_replay_insert(s, m);
    if (err)
        GKS_FAIL(err, fctid);
}

GKS_API void ginsert_seg(Gint seg_name, const Gtran_matrix tran_matrix)
{
    double m[3][4];
    if (tran_matrix)
        gks_xform_mat23_to_mat34(tran_matrix, m);
    insert_any(GFN_INSG, seg_name, tran_matrix ? (const double (*)[4])m : NULL);
}

GKS_API void ginsert_seg3(Gint seg_name, const Gtran_matrix3 tran_matrix)
{
    insert_any(GFN_INSG3, seg_name, (const double (*)[4])tran_matrix);
}

void gks_segment_ws_closed(int ws_id)
{
    gks_seg_store *st = store();
    for (size_t i = 0; i < st->n;) {
        gks_segment *s = st->seg[i];
        gks_seg_ws_remove(s, ws_id);
        if (s->n_ws == 0 && gks_ctx()->sl->open_seg != s->name)
            seg_delete(s->name); /* st->seg[i] is now the next one */
        else
            i++;
    }
}

/* ---------------------------------------------------------------- inquiries */

GKS_API void ginq_set_seg_names(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                Gint_list *seg_names, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, seg_names, length_list);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_seg_store *st = store();
    gks_list_out w = gks_list_begin(seg_names, num_elems_appl_list, start_pos);
    for (size_t i = 0; i < st->n; i++)
        gks_list_put(&w, st->seg[i]->name);
    *err_ind = gks_list_end(&w, length_list);
}

GKS_API void ginq_name_open_seg(Gint *err_ind, Gint *seg_name)
{
    GKS_INQ_ARGS(err_ind, seg_name);
    if (gks_inq_begin(err_ind, GKS_S_SGOP))
        return;
    *seg_name = gks_ctx()->sl->open_seg;
}

/* The segment of an inquiry: GKS open (7), then 120, 122; NULL with *err_ind set. */
static const gks_segment *inq_seg(Gint name, Gint *err_ind)
{
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return NULL;
    const gks_segment *s = name < 1 ? NULL : gks_seg_find(store(), name);
    if (!s)
        *err_ind = name < 1 ? 120 : 122;
    return s;
}

GKS_API void ginq_seg_attrs3(Gint seg_name, Gint *err_ind, Gseg_attrs3 *attrs)
{
    GKS_INQ_ARGS(err_ind, attrs);
    const gks_segment *s = inq_seg(seg_name, err_ind);
    if (!s)
        return;
    attrs->seg_name = s->name;
    memcpy(attrs->tran_matrix, s->tran, sizeof attrs->tran_matrix);
    attrs->vis = s->vis ? GSEG_VIS : GSEG_INVIS;
    attrs->highl = s->highl ? GSEG_HIGHL : GSEG_NORM;
    attrs->pri = s->pri;
    attrs->det = s->det ? GSEG_DET : GSEG_UNDET;
}

GKS_API void ginq_set_seg_names_ws(Gint ws_id, Gint num_elems_appl_list, Gint start_pos,
                                   Gint *err_ind, Gint_list *seg_names, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, seg_names, length_list);
    if (!gks_inq_ws(ws_id, err_ind))
        return;
    const gks_seg_store *st = store();
    gks_list_out w = gks_list_begin(seg_names, num_elems_appl_list, start_pos);
    for (size_t i = 0; i < st->n; i++)
        if (gks_seg_on_ws(st->seg[i], ws_id))
            gks_list_put(&w, st->seg[i]->name);
    *err_ind = gks_list_end(&w, length_list);
}

GKS_API void ginq_set_assoc_wss(Gint seg_name, Gint num_elems_appl_list, Gint start_pos,
                                Gint *err_ind, Gint_list *ws_ids, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, ws_ids, length_list);
    const gks_segment *s = inq_seg(seg_name, err_ind);
    if (s)
        *err_ind = gks_list_copy(s->ws, s->n_ws, num_elems_appl_list, start_pos, ws_ids,
                                 length_list);
}

GKS_API void ginq_num_seg_pris(Gint ws_type, Gint *err_ind, Gint *num_seg_pris)
{
    GKS_INQ_ARGS(err_ind, num_seg_pris);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    const gks_ws_driver *drv = gks_driver_for_type(ws_type);
    if (!drv) {
        *err_ind = 23;
        return;
    }
    if (drv->desc->cat == GCAT_MI) {
        *err_ind = 33;
        return;
    }
    /* Priorities are kept as given (doubles): 0 means "a continuous range". */
    *num_seg_pris = 0;
}
