/* SPDX-License-Identifier: MIT */
/*
 * gks_input.c -- the input functions of ISO 7942 5.9 and ISO 8805 (INITIALISE, SET MODE,
 * REQUEST, SAMPLE, AWAIT EVENT, FLUSH DEVICE EVENTS, GET, their 3-D forms for LOCATOR and
 * STROKE) and the input inquiries. Guard clauses in the standard's order, then the device
 * logic of gks_indev.c.
 *
 * Checks of every function that names a device: 7 (state), 20 (invalid ws id), 25 (not
 * open), 38 (neither INPUT nor OUTIN; also MO, MI, WISS), 140 (no such device). Then:
 * INITIALISE 144 (prompt/echo type), 51 (echo area invalid), 145 (echo area outside the
 * display space), 146 (data record: negative counts), 152 (initial value), 153/154
 * (initial stroke/string longer than the buffer; buffer size outside 1..max: 146);
 * SET MODE 2000 (mode or echo switch out of range); REQUEST 141 (not in REQUEST mode);
 * SAMPLE 142 (not in SAMPLE mode); AWAIT EVENT 151 (timeout negative or not finite), 147
 * (the queue overflowed); GET 150 (no value of the class in the current event report).
 * Output arguments are set to "no input" before any check (REQUEST: status NONE), so a
 * caller never reads stale values.
 */
#include "gks_legacy.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_indev.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <math.h>
#include <string.h>

/* Reports an error as the caller's last action (the caller returns right after). */
static void report(int e, int fctid)
{
    GKS_FAIL(e, fctid);
}

static const Gloc no_loc = { 0, { 0, 0 } };
static const Gpick no_pick = { 0, 0 };

/* The device checks after the category check: 2000 for a class outside LOC..STRING
 * (FLUSH DEVICE EVENTS), 140 for a device number the type does not have. */
static int device_number_error(const gks_ws_desc *d, Gin_class cls, Gint dev)
{
    if (d->cat != GCAT_IN && d->cat != GCAT_OUTIN)
        return 38;
    if (cls < GIN_LOC || cls > GIN_STRING)
        return 2000;
    if (dev < 1 || dev > gks_in_num_devices(d->in, cls))
        return 140;
    return 0;
}

/* Workstation and device of the functions that name an open workstation. */
static int device_error(Gint ws_id, Gin_class cls, Gint dev, gks_ws **out)
{
    if (ws_id < 0)
        return 20;
    gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        return 25;
    *out = ws;
    return device_number_error(ws->drv->desc, cls, dev);
}

/* Workstation type and device of the default-data inquiries: 22, 23, 38, 140. */
static int type_device_error(Gint ws_type, Gin_class cls, Gint dev, const gks_ws_desc **out)
{
    if (gks_ws_type_map(ws_type) <= 0)
        return 22;
    const gks_ws_driver *d = gks_driver_for_type(ws_type);
    if (!d)
        return 23;
    *out = d->desc;
    return device_number_error(d->desc, cls, dev);
}

/* Entry of every function that names a device: the state check (7), then the device
 * checks; the device, or NULL with the first error reported for fctid. */
static gks_indev *input_entry(int fctid, Gint ws_id, Gin_class cls, Gint num, gks_ws **ws)
{
    if (gks_check_state(fctid))
        return NULL;
    gks_ws *w = NULL;
    int e = device_error(ws_id, cls, num, &w);
    if (e) {
        report(e, fctid);
        return NULL;
    }
    *ws = w;
    return gks_in_dev(w, cls, num);
}

static void set_err(Gint *err_ind, Gint e)
{
    if (err_ind)
        *err_ind = e;
}

/* ---- INITIALISE ---- */

static int rec_error(const Gin_data *r)
{
    return r && (r->num_ints < 0 || r->num_floats < 0 || (r->num_ints > 0 && !r->ints) ||
                 (r->num_floats > 0 && !r->floats) || (r->str_len > 0 && !r->str))
               ? 146
               : 0;
}

/* Echo volume checks (51 invalid, 145 outside the display space) of a DC3 volume. */
static int echo_error(const gks_ws *ws, const Glimit3 *e)
{
    const gks_ws_desc *d = ws->drv->desc;
    if (!e || !(e->x_min < e->x_max) || !(e->y_min < e->y_max) || !(e->z_min <= e->z_max))
        return 51;
    if (e->x_min < 0 || e->x_max > d->dc_x || e->y_min < 0 || e->y_max > d->dc_y ||
        e->z_min < 0 || e->z_max > 1)
        return 145;
    return 0;
}

/* An invalid echo volume (51) for a NULL argument. */
static const Glimit3 bad_vol = { 1, 0, 1, 0, 0, 0 };

static Glimit3 echo_vol2(const Glimit *e)
{
    return e ? (Glimit3){ e->x_min, e->x_max, e->y_min, e->y_max, 0, 1 }
             : (Glimit3){ 1, 0, 1, 0, 0, 0 };
}

/* Is WC3 point p, under transformation tnr, inside NDC space (the unit cube)? */
static int in_ndc(int tnr, const Gpoint3 *p)
{
    if (tnr < 0 || tnr > GKS_MAX_NORM_TRAN)
        return 0;
    const gks_norm_tran *t = &gks_ctx()->sl->tran[tnr];
    const Gfloat w[6] = { t->win.x_min, t->win.x_max, t->win.y_min, t->win.y_max,
                          t->win.z_min, t->win.z_max };
    const Gfloat v[6] = { t->vp.x_min, t->vp.x_max, t->vp.y_min, t->vp.y_max,
                          t->vp.z_min, t->vp.z_max };
    const Gfloat q[3] = { p->x, p->y, p->z };
    for (int i = 0; i < 3; i++) {
        double dw = w[2 * i + 1] - w[2 * i];
        double n = dw != 0 ? v[2 * i] + (q[i] - w[2 * i]) * (v[2 * i + 1] - v[2 * i]) / dw
                           : v[2 * i];
        if (!isfinite(n) || n < -1e-9 || n > 1 + 1e-9)
            return 0;
    }
    return 1;
}

/* The common part of INITIALISE: pet (144), echo volume (51, 145), record (146). */
static int init_common(const gks_ws *ws, Gin_class cls, Gint pet, const Glimit3 *ev,
                       const Gin_data *rec)
{
    if (pet < 1 || pet > ws->in->desc->max_pet[cls - GIN_LOC])
        return 144;
    int e = echo_error(ws, ev);
    return e ? e : rec_error(rec);
}

/* Stores the new state; 0 or 300 (the device unchanged). */
static int init_store(gks_indev *d, Gint pet, const Glimit3 *ev, const Gin_data *rec,
                      const gks_in_val *init)
{
    Gin_data r = { 0 };
    gks_in_val v = { 0 };
    if (gks_in_rec_copy(&r, rec) || gks_in_val_copy(&v, init)) {
        gks_in_rec_free(&r);
        return 300;
    }
    gks_in_rec_free(&d->rec);
    gks_in_val_free(&d->init);
    d->rec = r;
    d->init = v;
    d->pet = pet;
    d->echo_vol = *ev;
    return 0;
}

static void do_init_loc(int fct, Gint ws_id, Gint num, Gint view_ind, Gint tnr, Gpoint3 pos,
                     Gint pet, const Glimit3 *ev, const Gin_data *rec)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_LOC, num, &ws);
    if (!d)
        return;
    int e = init_common(ws, GIN_LOC, pet, ev, rec);
    if (!e && (view_ind < 0 || view_ind > GKS_MAX_VIEW_IND || !in_ndc(tnr, &pos)))
        e = 152;
    if (e)
        GKS_FAIL(e, fct);
    gks_in_val v = { .status = GIN_STATUS_OK, .tnr = tnr, .view_ind = view_ind, .pos = pos };
    if (init_store(d, pet, ev, rec, &v))
        GKS_FAIL(300, fct);
}

GKS_API void ginit_loc(Gint ws_id, Gint loc_num, const Gloc *init_loc, Gint pet,
                       const Glimit *echo_area, const Gin_data *loc_data)
{
    Glimit3 ev = echo_vol2(echo_area);
    Gloc l = init_loc ? *init_loc : (Gloc){ -1, { 0, 0 } };
    do_init_loc(GFN_INLC, ws_id, loc_num, 0, l.norm_tran_num,
             (Gpoint3){ l.position.x, l.position.y, 0 }, pet, &ev, loc_data);
}

GKS_API void ginit_loc3(Gint ws_id, Gint loc_num, Gint init_view_ind, const Gloc3 *init_loc,
                        Gint pet, const Glimit3 *echo_vol, const Gin_data *loc_data)
{
    Gloc3 l = init_loc ? *init_loc : (Gloc3){ -1, { 0, 0, 0 } };
    do_init_loc(GFN_INLC3, ws_id, loc_num, init_view_ind, l.norm_tran_num, l.position, pet,
             echo_vol, loc_data);
}

static void do_init_stroke(int fct, Gint ws_id, Gint num, Gint view_ind, Gint tnr, Gint n,
                        const Gpoint3 *pts, const Gpoint *pts2, Gint pet, const Glimit3 *ev,
                        Gint buf, const Gin_data *rec)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_STROKE, num, &ws);
    if (!d)
        return;
    int e = init_common(ws, GIN_STROKE, pet, ev, rec);
    if (!e && (buf < 1 || buf > GKS_IN_STROKE_MAX))
        e = 146;
    if (!e && (n < 0 || (n > 0 && !pts && !pts2) || view_ind < 0 ||
               view_ind > GKS_MAX_VIEW_IND || tnr < 0 || tnr > GKS_MAX_NORM_TRAN))
        e = 152;
    gks_in_val v = { .status = GIN_STATUS_OK, .tnr = tnr, .view_ind = view_ind };
    if (!e && n > 0 && !(v.pts = gks_alloc_array((size_t)n, sizeof *v.pts)))
        e = 300;
    for (Gint i = 0; !e && i < n; i++) {
        v.pts[i] = pts ? pts[i] : (Gpoint3){ pts2[i].x, pts2[i].y, 0 };
        if (!in_ndc(tnr, &v.pts[i]))
            e = 152;
    }
    if (!e && n > buf)
        e = 153;
    v.n = n;
    if (!e && init_store(d, pet, ev, rec, &v))
        e = 300;
    if (!e)
        d->buf_size = buf;
    gks_in_val_free(&v);
    if (e)
        report(e, fct);
}

GKS_API void ginit_stroke(Gint ws_id, Gint stroke_num, const Gstroke *init_stroke, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size,
                          const Gin_data *stroke_data)
{
    Glimit3 ev = echo_vol2(echo_area);
    Gstroke s = init_stroke ? *init_stroke : (Gstroke){ -1, 0, NULL };
    do_init_stroke(GFN_INSK, ws_id, stroke_num, 0, s.norm_tran_num, s.num_points, NULL,
                s.points, pet, &ev, in_buf_size, stroke_data);
}

GKS_API void ginit_stroke3(Gint ws_id, Gint stroke_num, Gint init_view_ind,
                           const Gstroke3 *init_stroke, Gint pet, const Glimit3 *echo_vol,
                           Gint in_buf_size, const Gin_data *stroke_data)
{
    Gstroke3 s = init_stroke ? *init_stroke : (Gstroke3){ -1, 0, NULL };
    do_init_stroke(GFN_INSK3, ws_id, stroke_num, init_view_ind, s.norm_tran_num, s.num_points,
                s.points, NULL, pet, echo_vol, in_buf_size, stroke_data);
}

static void do_init_val(int fct, Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                        const Glimit3 *evp, Gfloat low_value, Gfloat high_value,
                        const Gin_data *val_data)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_VAL, val_num, &ws);
    if (!d)
        return;
    Glimit3 ev = evp ? *evp : echo_vol2(NULL);
    int e = init_common(ws, GIN_VAL, pet, &ev, val_data);
    if (!e && !(low_value < high_value))
        e = 146;
    if (!e && !(init_value >= low_value && init_value <= high_value))
        e = 152;
    if (e)
        GKS_FAIL(e, fct);
    gks_in_val v = { .status = GIN_STATUS_OK, .val = init_value };
    if (init_store(d, pet, &ev, val_data, &v))
        GKS_FAIL(300, fct);
    d->low = low_value;
    d->high = high_value;
}

GKS_API void ginit_val(Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                       const Glimit *echo_area, Gfloat low_value, Gfloat high_value,
                       const Gin_data *val_data)
{
    Glimit3 ev = echo_vol2(echo_area);
    do_init_val(GFN_INVL, ws_id, val_num, init_value, pet, &ev, low_value, high_value,
                val_data);
}

GKS_API void ginit_val3(Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                        const Glimit3 *echo_vol, Gfloat low_value, Gfloat high_value,
                        const Gin_data *val_data)
{
    do_init_val(GFN_INVL3, ws_id, val_num, init_value, pet, echo_vol ? echo_vol : &bad_vol,
                low_value, high_value, val_data);
}

static void do_init_choice(int fct, Gint ws_id, Gint choice_num, Gin_status init_status,
                           Gint init_choice, Gint pet, Glimit3 ev, const Gin_data *choice_data)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_CHOICE, choice_num, &ws);
    if (!d)
        return;
    int e = init_common(ws, GIN_CHOICE, pet, &ev, choice_data);
    if (!e && (unsigned)init_status > GIN_STATUS_NO_IN)
        e = 2000;
    if (!e && init_status == GIN_STATUS_OK &&
        (init_choice < 1 || init_choice > ws->in->desc->max_choices))
        e = 152;
    if (e)
        GKS_FAIL(e, fct);
    gks_in_val v = { .status = init_status, .choice = init_choice };
    if (init_store(d, pet, &ev, choice_data, &v))
        GKS_FAIL(300, fct);
}

GKS_API void ginit_choice(Gint ws_id, Gint choice_num, Gin_status init_status,
                          Gint init_choice, Gint pet, const Glimit *echo_area,
                          const Gin_data *choice_data)
{
    do_init_choice(GFN_INCH, ws_id, choice_num, init_status, init_choice, pet,
                   echo_vol2(echo_area), choice_data);
}

GKS_API void ginit_choice3(Gint ws_id, Gint choice_num, Gin_status init_status,
                           Gint init_choice, Gint pet, const Glimit3 *echo_vol,
                           const Gin_data *choice_data)
{
    do_init_choice(GFN_INCH3, ws_id, choice_num, init_status, init_choice, pet,
                   echo_vol ? *echo_vol : bad_vol, choice_data);
}

static void do_init_pick(int fct, Gint ws_id, Gint pick_num, Gin_status init_status,
                         const Gpick *init_pick, Gint pet, Glimit3 ev, const Gin_data *pick_data)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_PICK, pick_num, &ws);
    if (!d)
        return;
    int e = init_common(ws, GIN_PICK, pet, &ev, pick_data);
    if (!e && (unsigned)init_status > GIN_STATUS_NO_IN)
        e = 2000;
    if (!e && init_status == GIN_STATUS_OK && (!init_pick || init_pick->seg_name < 1))
        e = 152;
    if (e)
        GKS_FAIL(e, fct);
    gks_in_val v = { .status = init_status, .pick = init_pick ? *init_pick : no_pick };
    if (init_store(d, pet, &ev, pick_data, &v))
        GKS_FAIL(300, fct);
}

GKS_API void ginit_pick(Gint ws_id, Gint pick_num, Gin_status init_status,
                        const Gpick *init_pick, Gint pet, const Glimit *echo_area,
                        const Gin_data *pick_data)
{
    do_init_pick(GFN_INPK, ws_id, pick_num, init_status, init_pick, pet, echo_vol2(echo_area),
                 pick_data);
}

GKS_API void ginit_pick3(Gint ws_id, Gint pick_num, Gin_status init_status,
                         const Gpick *init_pick, Gint pet, const Glimit3 *echo_vol,
                         const Gin_data *pick_data)
{
    do_init_pick(GFN_INPK3, ws_id, pick_num, init_status, init_pick, pet,
                 echo_vol ? *echo_vol : bad_vol, pick_data);
}

static void do_init_string(int fct, Gint ws_id, Gint string_num, const char *init_string,
                           Gint pet, Glimit3 ev, Gint in_buf_size, Gint init_cur_pos,
                           const Gin_data *string_data)
{
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, GIN_STRING, string_num, &ws);
    if (!d)
        return;
    int e = init_common(ws, GIN_STRING, pet, &ev, string_data);
    if (!e && (in_buf_size < 1 || in_buf_size > GKS_IN_STRING_MAX))
        e = 146;
    size_t n = init_string ? strnlen(init_string, (size_t)GKS_IN_STRING_MAX + 1) : 0;
    if (!e && n > (size_t)in_buf_size)
        e = 154;
    if (!e && (init_cur_pos < 1 || (size_t)init_cur_pos > n + 1))
        e = 152;
    if (e)
        GKS_FAIL(e, fct);
    gks_in_val v = { .status = GIN_STATUS_OK, .str = (char *)(init_string ? init_string : "") };
    if (init_store(d, pet, &ev, string_data, &v))
        GKS_FAIL(300, fct);
    d->buf_size = in_buf_size;
    d->cur_pos = init_cur_pos;
}

GKS_API void ginit_string(Gint ws_id, Gint string_num, const char *init_string, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size, Gint init_cur_pos,
                          const Gin_data *string_data)
{
    do_init_string(GFN_INST, ws_id, string_num, init_string, pet, echo_vol2(echo_area),
                   in_buf_size, init_cur_pos, string_data);
}

GKS_API void ginit_string3(Gint ws_id, Gint string_num, const char *init_string, Gint pet,
                           const Glimit3 *echo_vol, Gint in_buf_size, Gint init_cur_pos,
                           const Gin_data *string_data)
{
    do_init_string(GFN_INST3, ws_id, string_num, init_string, pet,
                   echo_vol ? *echo_vol : bad_vol, in_buf_size, init_cur_pos, string_data);
}

/* ---- SET ... MODE ---- */

static void set_mode(int fct, Gint ws_id, Gin_class cls, Gint num, Gop_mode mode,
                     Gecho_switch echo)
{
    gks_ws *ws;
    if (!input_entry(fct, ws_id, cls, num, &ws))
        return;
    if ((unsigned)mode > GOP_EVENT || (unsigned)echo > GSWITCH_ECHO)
        GKS_FAIL(2000, fct);
    if (gks_in_set_mode(ws, cls, num, mode, echo == GSWITCH_ECHO))
        GKS_FAIL(300, fct);
}

#define GKS_SET_MODE(cname, fct, cls)                                                     \
    GKS_API void cname(Gint ws_id, Gint num, Gop_mode op_mode, Gecho_switch echo_switch) \
    {                                                                                     \
        set_mode(fct, ws_id, cls, num, op_mode, echo_switch);                             \
    }
GKS_SET_MODE(gset_loc_mode, GFN_SLCM, GIN_LOC)
GKS_SET_MODE(gset_stroke_mode, GFN_SSKM, GIN_STROKE)
GKS_SET_MODE(gset_val_mode, GFN_SVLM, GIN_VAL)
GKS_SET_MODE(gset_choice_mode, GFN_SCHM, GIN_CHOICE)
GKS_SET_MODE(gset_pick_mode, GFN_SPKM, GIN_PICK)
GKS_SET_MODE(gset_string_mode, GFN_SSTM, GIN_STRING)
#undef GKS_SET_MODE

/* ---- values out ---- */

static void no_status(Gin_status *s)
{
    if (s)
        *s = GIN_STATUS_NONE;
}

static void loc_out(const gks_in_val *v, Gloc *l)
{
    if (l)
        *l = (Gloc){ v->tnr, { v->pos.x, v->pos.y } };
}

static void loc3_out(const gks_in_val *v, Gint *view_ind, Gloc3 *l)
{
    if (view_ind)
        *view_ind = v->view_ind;
    if (l)
        *l = (Gloc3){ v->tnr, v->pos };
}

/* Stroke points into the caller's array: at most its capacity (num_points on entry). */
static void stroke_out(const gks_in_val *v, Gstroke *s)
{
    if (!s)
        return;
    Gint cap = s->points ? s->num_points : 0, n = 0;
    for (; n < v->n && n < cap; n++)
        s->points[n] = (Gpoint){ v->pts[n].x, v->pts[n].y };
    s->norm_tran_num = v->tnr;
    s->num_points = n;
}

static void stroke3_out(const gks_in_val *v, Gint *view_ind, Gstroke3 *s)
{
    if (view_ind)
        *view_ind = v->view_ind;
    if (!s)
        return;
    Gint cap = s->points ? s->num_points : 0, n = 0;
    for (; n < v->n && n < cap; n++)
        s->points[n] = v->pts[n];
    s->norm_tran_num = v->tnr;
    s->num_points = n;
}

/* string: a buffer of (buffer size + 1) bytes; at most cap characters are written, the
 * device's buffer size now (a queued event may be longer than a buffer INITIALISE STRING
 * has made smaller since). */
static void string_out(const gks_in_val *v, char *string, Gint cap)
{
    if (!string)
        return;
    size_t n = v->str ? strlen(v->str) : 0;
    if (cap >= 0 && n > (size_t)cap)
        n = (size_t)cap;
    if (n)
        memcpy(string, v->str, n);
    string[n] = '\0';
}

static void no_stroke(Gstroke *s)
{
    if (s) {
        s->norm_tran_num = 0;
        s->num_points = 0;
    }
}

static void no_stroke3(Gstroke3 *s)
{
    if (s) {
        s->norm_tran_num = 0;
        s->num_points = 0;
    }
}

/* ---- REQUEST, SAMPLE, GET: one path for every class ---- */

/* Where a REQUEST, SAMPLE or GET answer goes: the caller's pointers (NULL where the function
 * has none or the caller passed none). status: the input status, which a REQUEST always
 * has and a SAMPLE or GET of CHOICE or PICK; with it (checked) a value is written only
 * when the status is OK. Before the input every value is set to "none". */
typedef struct {
    int checked;
    Gin_status *status;
    Gint *view_ind;
    Gloc *loc;
    Gloc3 *loc3;
    Gstroke *stroke;
    Gstroke3 *stroke3;
    Gint cap; /* the stroke's capacity on entry */
    Gfloat *val;
    Gint *choice;
    Gpick *pick;
    char *string;
    Gint str_cap; /* the string buffer size (characters) */
} in_dest;

static void dest_clear(in_dest *o)
{
    no_status(o->status);
    if (o->view_ind)
        *o->view_ind = 0;
    if (o->loc)
        *o->loc = no_loc;
    if (o->loc3)
        *o->loc3 = (Gloc3){ 0, { 0, 0, 0 } };
    if (o->stroke) {
        o->cap = o->stroke->num_points;
        no_stroke(o->stroke);
    }
    if (o->stroke3) {
        o->cap = o->stroke3->num_points;
        no_stroke3(o->stroke3);
    }
    if (o->val)
        *o->val = 0;
    if (o->choice)
        *o->choice = 0;
    if (o->pick)
        *o->pick = no_pick;
    if (o->string)
        *o->string = '\0';
}

static void dest_put(const gks_in_val *v, in_dest *o)
{
    if (o->status)
        *o->status = v->status;
    if (o->checked && v->status != GIN_STATUS_OK)
        return;
    if (o->loc)
        loc_out(v, o->loc);
    if (o->loc3)
        loc3_out(v, o->view_ind, o->loc3);
    if (o->stroke) {
        o->stroke->num_points = o->cap; /* stroke_out's capacity */
        stroke_out(v, o->stroke);
    }
    if (o->stroke3) {
        o->stroke3->num_points = o->cap;
        stroke3_out(v, o->view_ind, o->stroke3);
    }
    if (o->val)
        *o->val = v->val;
    if (o->choice)
        *o->choice = v->choice;
    if (o->pick)
        *o->pick = v->pick;
    string_out(v, o->string, o->str_cap);
}

/* REQUEST (mode GOP_REQ, else 141) or SAMPLE (GOP_SAMPLE, else 142) of device (cls, num)
 * into o; errors reported. */
static void take(int fct, Gint ws_id, Gin_class cls, Gint num, Gop_mode mode, in_dest o)
{
    dest_clear(&o);
    gks_ws *ws;
    gks_indev *d = input_entry(fct, ws_id, cls, num, &ws);
    if (!d)
        return;
    if (d->mode != mode) {
        report(mode == GOP_REQ ? 141 : 142, fct);
        return;
    }
    gks_in_val v = { 0 };
    o.str_cap = d->buf_size;
    if ((mode == GOP_REQ ? gks_in_request : gks_in_sample)(ws, cls, num, &v))
        report(300, fct);
    else
        dest_put(&v, &o);
    gks_in_val_free(&v);
}

#define REQ(fct, cls, ...) take(fct, ws_id, cls, num, GOP_REQ, (in_dest){ .checked = 1, __VA_ARGS__ })
#define SMP(fct, cls, ...) take(fct, ws_id, cls, num, GOP_SAMPLE, (in_dest){ __VA_ARGS__ })

GKS_API void greq_loc(Gint ws_id, Gint num, Gin_status *in_status, Gloc *loc)
{
    REQ(GFN_RQLC, GIN_LOC, .status = in_status, .loc = loc);
}

GKS_API void greq_loc3(Gint ws_id, Gint num, Gin_status *in_status, Gint *view_ind,
                       Gloc3 *loc)
{
    REQ(GFN_RQLC3, GIN_LOC, .status = in_status, .view_ind = view_ind, .loc3 = loc);
}

GKS_API void greq_stroke(Gint ws_id, Gint num, Gin_status *in_status, Gstroke *stroke)
{
    REQ(GFN_RQSK, GIN_STROKE, .status = in_status, .stroke = stroke);
}

GKS_API void greq_stroke3(Gint ws_id, Gint num, Gin_status *in_status, Gint *view_ind,
                          Gstroke3 *stroke)
{
    REQ(GFN_RQSK3, GIN_STROKE, .status = in_status, .view_ind = view_ind, .stroke3 = stroke);
}

GKS_API void greq_val(Gint ws_id, Gint num, Gin_status *in_status, Gfloat *value)
{
    REQ(GFN_RQVL, GIN_VAL, .status = in_status, .val = value);
}

GKS_API void greq_choice(Gint ws_id, Gint num, Gin_status *in_status, Gint *choice)
{
    REQ(GFN_RQCH, GIN_CHOICE, .status = in_status, .choice = choice);
}

GKS_API void greq_pick(Gint ws_id, Gint num, Gin_status *in_status, Gpick *pick)
{
    REQ(GFN_RQPK, GIN_PICK, .status = in_status, .pick = pick);
}

GKS_API void greq_string(Gint ws_id, Gint num, Gin_status *in_status, char *string)
{
    REQ(GFN_RQST, GIN_STRING, .status = in_status, .string = string);
}

GKS_API void gsample_loc(Gint ws_id, Gint num, Gloc *loc)
{
    SMP(GFN_SMLC, GIN_LOC, .loc = loc);
}

GKS_API void gsample_loc3(Gint ws_id, Gint num, Gint *view_ind, Gloc3 *loc)
{
    SMP(GFN_SMLC3, GIN_LOC, .view_ind = view_ind, .loc3 = loc);
}

GKS_API void gsample_stroke(Gint ws_id, Gint num, Gstroke *stroke)
{
    SMP(GFN_SMSK, GIN_STROKE, .stroke = stroke);
}

GKS_API void gsample_stroke3(Gint ws_id, Gint num, Gint *view_ind, Gstroke3 *stroke)
{
    SMP(GFN_SMSK3, GIN_STROKE, .view_ind = view_ind, .stroke3 = stroke);
}

GKS_API void gsample_val(Gint ws_id, Gint num, Gfloat *value)
{
    SMP(GFN_SMVL, GIN_VAL, .val = value);
}

GKS_API void gsample_choice(Gint ws_id, Gint num, Gin_status *in_status, Gint *choice)
{
    SMP(GFN_SMCH, GIN_CHOICE, .checked = 1, .status = in_status, .choice = choice);
}

GKS_API void gsample_pick(Gint ws_id, Gint num, Gin_status *in_status, Gpick *pick)
{
    SMP(GFN_SMPK, GIN_PICK, .checked = 1, .status = in_status, .pick = pick);
}

GKS_API void gsample_string(Gint ws_id, Gint num, char *string)
{
    SMP(GFN_SMST, GIN_STRING, .string = string);
}
#undef REQ
#undef SMP

/* ---- event input ---- */

GKS_API void gawait_event(Gfloat timeout, Gint *ws_id, Gin_class *in_class, Gint *in_num)
{
    Gint w = 0, n = 0;
    Gin_class c = GIN_NONE;
    if (ws_id)
        *ws_id = 0;
    if (in_class)
        *in_class = GIN_NONE;
    if (in_num)
        *in_num = 0;
    if (gks_check_state(GFN_WAIT))
        return;
    if (!(timeout >= 0) || !isfinite(timeout))
        GKS_FAIL(151, GFN_WAIT);
    int e = gks_in_await(timeout, &w, &c, &n);
    if (ws_id)
        *ws_id = w;
    if (in_class)
        *in_class = c;
    if (in_num)
        *in_num = n;
    if (e)
        report(e, GFN_WAIT);
}

GKS_API void gflush_events(Gint ws_id, Gin_class in_class, Gint in_num)
{
    if (gks_check_state(GFN_FLUSH))
        return;
    gks_ws *ws = NULL;
    int e = device_error(ws_id, in_class, in_num, &ws);
    if (e)
        GKS_FAIL(e, GFN_FLUSH);
    gks_in_flush(ws_id, in_class, in_num);
}

/* GET: the current event report's value of class cls into o, or 7/150 reported. */
static void get(int fctid, Gin_class cls, in_dest o)
{
    dest_clear(&o);
    if (gks_check_state(fctid))
        return;
    const gks_in_val *v = gks_in_current(cls, &o.str_cap);
    if (v)
        dest_put(v, &o);
    else
        report(150, fctid);
}

GKS_API void gget_loc(Gloc *loc)
{
    get(GFN_GTLC, GIN_LOC, (in_dest){ .loc = loc });
}

GKS_API void gget_loc3(Gint *view_ind, Gloc3 *loc)
{
    get(GFN_GTLC3, GIN_LOC, (in_dest){ .view_ind = view_ind, .loc3 = loc });
}

GKS_API void gget_stroke(Gstroke *stroke)
{
    get(GFN_GTSK, GIN_STROKE, (in_dest){ .stroke = stroke });
}

GKS_API void gget_stroke3(Gint *view_ind, Gstroke3 *stroke)
{
    get(GFN_GTSK3, GIN_STROKE, (in_dest){ .view_ind = view_ind, .stroke3 = stroke });
}

GKS_API void gget_val(Gfloat *value)
{
    get(GFN_GTVL, GIN_VAL, (in_dest){ .val = value });
}

GKS_API void gget_choice(Gin_status *in_status, Gint *choice)
{
    get(GFN_GTCH, GIN_CHOICE, (in_dest){ .checked = 1, .status = in_status, .choice = choice });
}

GKS_API void gget_pick(Gin_status *in_status, Gpick *pick)
{
    get(GFN_GTPK, GIN_PICK, (in_dest){ .checked = 1, .status = in_status, .pick = pick });
}

GKS_API void gget_string(char *string)
{
    get(GFN_GTST, GIN_STRING, (in_dest){ .string = string });
}

/* ---- inquiries (never call ERROR HANDLING; nothing but *err_ind written on error) ---- */

/* The device state inquiries and the default-data inquiries each run one path for the
 * twelve 2-D and 3-D forms: the checks, then a fill function of the caller's structure.
 * The common part is written by member name (macros: the 3-D structures have their own
 * member lists), the class part by one macro for both forms, whose members have the same
 * names. */

static Glimit echo_area2(const Glimit3 *v)
{
    return (Glimit){ v->x_min, v->x_max, v->y_min, v->y_max };
}

/* The common part of a 3-D device state: mode, echo, pet, echo volume, record. */
#define DEV_ST3(st, d)                                                                     \
    ((st)->op_mode = (d)->mode, (st)->echo_switch = (d)->echo ? GSWITCH_ECHO : GSWITCH_NO_ECHO, \
     (st)->pet = (d)->pet, (st)->echo_vol = (d)->echo_vol, (st)->in_data = (d)->rec)
/* The same for a 2-D one (echo area: the volume's x and y). */
#define DEV_ST(st, d)                                                                      \
    ((st)->dev = (Gin_dev_st){ (d)->mode, (d)->echo ? GSWITCH_ECHO : GSWITCH_NO_ECHO,      \
                               (d)->pet, echo_area2(&(d)->echo_vol), (d)->rec })
/* The class parts. */
#define VAL_ST(st, d)                                                                      \
    ((st)->init_value = (d)->init.val, (st)->low_value = (d)->low, (st)->high_value = (d)->high)
#define CHOICE_ST(st, d) ((st)->init_status = (d)->init.status, (st)->init_choice = (d)->init.choice)
#define PICK_ST(st, d) ((st)->init_status = (d)->init.status, (st)->init_pick = (d)->init.pick)
#define STRING_ST(st, d)                                                                   \
    ((st)->in_buf_size = (d)->buf_size, (st)->init_cur_pos = (d)->cur_pos,                 \
     copy_init_string(d, (st)->init_string, (st)->init_string_size))

/* The initial string into the caller's buffer of size bytes (truncated, NUL-terminated). */
static void copy_init_string(const gks_indev *d, char *buf, size_t size)
{
    const char *s = d->init.str ? d->init.str : "";
    if (!buf || size == 0)
        return;
    size_t n = strlen(s);
    if (n >= size)
        n = size - 1;
    memcpy(buf, s, n);
    buf[n] = '\0';
}

/* SET and REALIZED values are the same: every initial value is representable. */
static void loc_st(const gks_indev *d, void *p)
{
    Gloc_st *st = p;
    DEV_ST(st, d);
    loc_out(&d->init, &st->init_loc);
}

static void loc_st3(const gks_indev *d, void *p)
{
    Gloc_st3 *st = p;
    DEV_ST3(st, d);
    loc3_out(&d->init, &st->init_view_ind, &st->init_loc);
}

static void stroke_st(const gks_indev *d, void *p)
{
    Gstroke_st *st = p;
    DEV_ST(st, d);
    st->in_buf_size = d->buf_size;
    stroke_out(&d->init, &st->init_stroke);
}

static void stroke_st3(const gks_indev *d, void *p)
{
    Gstroke_st3 *st = p;
    DEV_ST3(st, d);
    st->in_buf_size = d->buf_size;
    stroke3_out(&d->init, &st->init_view_ind, &st->init_stroke);
}

static void val_st(const gks_indev *d, void *p)
{
    DEV_ST((Gval_st *)p, d), VAL_ST((Gval_st *)p, d);
}

static void val_st3(const gks_indev *d, void *p)
{
    DEV_ST3((Gval_st3 *)p, d), VAL_ST((Gval_st3 *)p, d);
}

static void choice_st(const gks_indev *d, void *p)
{
    DEV_ST((Gchoice_st *)p, d), CHOICE_ST((Gchoice_st *)p, d);
}

static void choice_st3(const gks_indev *d, void *p)
{
    DEV_ST3((Gchoice_st3 *)p, d), CHOICE_ST((Gchoice_st3 *)p, d);
}

static void pick_st(const gks_indev *d, void *p)
{
    DEV_ST((Gpick_st *)p, d), PICK_ST((Gpick_st *)p, d);
}

static void pick_st3(const gks_indev *d, void *p)
{
    DEV_ST3((Gpick_st3 *)p, d), PICK_ST((Gpick_st3 *)p, d);
}

static void string_st(const gks_indev *d, void *p)
{
    DEV_ST((Gstring_st *)p, d), STRING_ST((Gstring_st *)p, d);
}

static void string_st3(const gks_indev *d, void *p)
{
    DEV_ST3((Gstring_st3 *)p, d), STRING_ST((Gstring_st3 *)p, d);
}

/* A device state inquiry: 7, 20, 25, 38, 140, then 2000 for a type (SET or REALIZED)
 * out of range where the function has one (typed); fill writes st unless it is NULL. */
static void inq_st(Gint ws_id, Gin_class cls, Gint num, int typed, Ginq_type type,
                   Gint *err_ind, void *st, void (*fill)(const gks_indev *, void *))
{
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    gks_ws *ws = NULL;
    if (!e)
        e = device_error(ws_id, cls, num, &ws);
    if (!e && typed && (unsigned)type > GINQ_REALIZED)
        e = 2000;
    set_err(err_ind, e);
    if (!e && st)
        fill(gks_in_dev(ws, cls, num), st);
}
#undef DEV_ST3
#undef DEV_ST
#undef STRING_ST

/* The entry points: a device state inquiry with a type (SET or REALIZED) argument, and
 * one without. */
#define INQ_ST_TYPED(name, T, cls, fill)                                                   \
    GKS_API void name(Gint ws_id, Gint num, Ginq_type type, Gint *err_ind, T *st)          \
    {                                                                                      \
        GKS_INQ_ARGS(err_ind, st);                                                         \
        inq_st(ws_id, cls, num, 1, type, err_ind, st, fill);                               \
    }
#define INQ_ST(name, T, cls, fill)                                                         \
    GKS_API void name(Gint ws_id, Gint num, Gint *err_ind, T *st)                          \
    {                                                                                      \
        GKS_INQ_ARGS(err_ind, st);                                                         \
        inq_st(ws_id, cls, num, 0, GINQ_SET, err_ind, st, fill);                           \
    }
INQ_ST_TYPED(ginq_loc_st, Gloc_st, GIN_LOC, loc_st)
INQ_ST_TYPED(ginq_loc_st3, Gloc_st3, GIN_LOC, loc_st3)
INQ_ST_TYPED(ginq_stroke_st, Gstroke_st, GIN_STROKE, stroke_st)
INQ_ST_TYPED(ginq_stroke_st3, Gstroke_st3, GIN_STROKE, stroke_st3)
INQ_ST(ginq_val_st, Gval_st, GIN_VAL, val_st)
INQ_ST(ginq_val_st3, Gval_st3, GIN_VAL, val_st3)
INQ_ST(ginq_choice_st, Gchoice_st, GIN_CHOICE, choice_st)
INQ_ST(ginq_choice_st3, Gchoice_st3, GIN_CHOICE, choice_st3)
INQ_ST_TYPED(ginq_pick_st, Gpick_st, GIN_PICK, pick_st)
INQ_ST_TYPED(ginq_pick_st3, Gpick_st3, GIN_PICK, pick_st3)
INQ_ST(ginq_string_st, Gstring_st, GIN_STRING, string_st)
INQ_ST(ginq_string_st3, Gstring_st3, GIN_STRING, string_st3)
#undef INQ_ST_TYPED
#undef INQ_ST

/* The default data: the device as OPEN WORKSTATION of the type creates it, with the
 * type's number of prompt/echo types and of choices. */
typedef struct {
    gks_indev d;
    Gint num_pets, max_choices;
} def_ans;

/* The common part: the prompt/echo types 1 .. num_pets into the caller's list (capacity
 * num_ints on entry, count on return), the echo area (2-D) or volume, an empty record. */
static void put_pets(Gint_list *pets, const def_ans *a)
{
    Gint cap = pets->ints ? pets->num_ints : 0;
    for (Gint i = 0; i < a->num_pets && i < cap; i++)
        pets->ints[i] = i + 1;
    pets->num_ints = a->num_pets;
}

#define DEF_IN(def, a)                                                                     \
    (put_pets(&(def)->pets, a), (def)->echo_area = echo_area2(&(a)->d.echo_vol),           \
     (def)->in_data = (Gin_data){ 0 })
#define DEF_IN3(def, a)                                                                    \
    (put_pets(&(def)->pets, a), (def)->echo_vol = (a)->d.echo_vol, (def)->in_data = (Gin_data){ 0 })
/* The class parts. */
#define DEF_BUF(def, a, max) ((def)->max_buf_size = (max), (def)->buf_size = (a)->d.buf_size)
#define DEF_VAL(def, a)                                                                    \
    ((def)->value = (a)->d.init.val, (def)->low_value = (a)->d.low,                        \
     (def)->high_value = (a)->d.high)

static void loc_def(const def_ans *a, void *p)
{
    Gdef_loc *def = p;
    DEF_IN(&def->dev, a);
    def->loc_pos = (Gpoint){ a->d.init.pos.x, a->d.init.pos.y };
}

static void loc_def3(const def_ans *a, void *p)
{
    Gdef_loc3 *def = p;
    DEF_IN3(def, a);
    def->loc_pos = a->d.init.pos;
}

static void stroke_def(const def_ans *a, void *p)
{
    DEF_IN(&((Gdef_stroke *)p)->dev, a), DEF_BUF((Gdef_stroke *)p, a, GKS_IN_STROKE_MAX);
}

static void stroke_def3(const def_ans *a, void *p)
{
    DEF_IN3((Gdef_stroke3 *)p, a), DEF_BUF((Gdef_stroke3 *)p, a, GKS_IN_STROKE_MAX);
}

static void val_def(const def_ans *a, void *p)
{
    DEF_IN(&((Gdef_val *)p)->dev, a), DEF_VAL((Gdef_val *)p, a);
}

static void val_def3(const def_ans *a, void *p)
{
    DEF_IN3(&((Gdef_val3 *)p)->dev, a), DEF_VAL((Gdef_val3 *)p, a);
}

static void choice_def(const def_ans *a, void *p)
{
    DEF_IN(&((Gdef_choice *)p)->dev, a), ((Gdef_choice *)p)->max_choices = a->max_choices;
}

static void choice_def3(const def_ans *a, void *p)
{
    DEF_IN3(&((Gdef_choice3 *)p)->dev, a), ((Gdef_choice3 *)p)->max_choices = a->max_choices;
}

static void pick_def(const def_ans *a, void *p)
{
    DEF_IN((Gdef_in *)p, a);
}

static void pick_def3(const def_ans *a, void *p)
{
    DEF_IN3((Gdef_in3 *)p, a);
}

static void string_def(const def_ans *a, void *p)
{
    DEF_IN(&((Gdef_string *)p)->dev, a), DEF_BUF((Gdef_string *)p, a, GKS_IN_STRING_MAX);
}

static void string_def3(const def_ans *a, void *p)
{
    DEF_IN3(&((Gdef_string3 *)p)->dev, a), DEF_BUF((Gdef_string3 *)p, a, GKS_IN_STRING_MAX);
}
#undef DEF_IN
#undef DEF_IN3
#undef DEF_BUF
#undef DEF_VAL

/* A default-data inquiry: 8, 22, 23, 38, 140; fill writes def unless it is NULL. */
static void inq_def(Gint ws_type, Gin_class cls, Gint num, Gint *err_ind, void *def,
                    void (*fill)(const def_ans *, void *))
{
    Gint e = gks_inq_state(GKS_S_OPEN);
    const gks_ws_desc *desc = NULL;
    if (!e)
        e = type_device_error(ws_type, cls, num, &desc);
    set_err(err_ind, e);
    if (e || !def)
        return;
    def_ans a = { .num_pets = desc->in->max_pet[cls - GIN_LOC],
                  .max_choices = desc->in->max_choices };
    gks_in_dev_default(desc, cls, &a.d);
    fill(&a, def);
}

/* The entry points. */
#define INQ_DEF(name, T, cls, fill)                                                        \
    GKS_API void name(Gint ws_type, Gint num, Gint *err_ind, T *def)                       \
    {                                                                                      \
        GKS_INQ_ARGS(err_ind, def);                                                        \
        inq_def(ws_type, cls, num, err_ind, def, fill);                                    \
    }
INQ_DEF(ginq_def_loc_data, Gdef_loc, GIN_LOC, loc_def)
INQ_DEF(ginq_def_loc_data3, Gdef_loc3, GIN_LOC, loc_def3)
INQ_DEF(ginq_def_stroke_data, Gdef_stroke, GIN_STROKE, stroke_def)
INQ_DEF(ginq_def_stroke_data3, Gdef_stroke3, GIN_STROKE, stroke_def3)
INQ_DEF(ginq_def_val_data, Gdef_val, GIN_VAL, val_def)
INQ_DEF(ginq_def_val_data3, Gdef_val3, GIN_VAL, val_def3)
INQ_DEF(ginq_def_choice_data, Gdef_choice, GIN_CHOICE, choice_def)
INQ_DEF(ginq_def_choice_data3, Gdef_choice3, GIN_CHOICE, choice_def3)
INQ_DEF(ginq_def_pick_data, Gdef_in, GIN_PICK, pick_def)
INQ_DEF(ginq_def_pick_data3, Gdef_in3, GIN_PICK, pick_def3)
INQ_DEF(ginq_def_string_data, Gdef_string, GIN_STRING, string_def)
INQ_DEF(ginq_def_string_data3, Gdef_string3, GIN_STRING, string_def3)
#undef INQ_DEF

GKS_API void ginq_num_avail_in(Gint ws_type, Gint *err_ind, Gnum_in *num_in)
{
    GKS_INQ_ARGS(err_ind, num_in);
    Gint e = gks_inq_state(GKS_S_OPEN);
    const gks_ws_driver *d = NULL;
    if (!e && gks_ws_type_map(ws_type) <= 0)
        e = 22;
    if (!e && !(d = gks_driver_for_type(ws_type)))
        e = 23;
    if (!e && d->desc->cat != GCAT_IN && d->desc->cat != GCAT_OUTIN)
        e = 38;
    set_err(err_ind, e);
    if (e || !num_in)
        return;
    const gks_in_desc *in = d->desc->in;
    *num_in = (Gnum_in){ gks_in_num_devices(in, GIN_LOC), gks_in_num_devices(in, GIN_STROKE),
                         gks_in_num_devices(in, GIN_VAL), gks_in_num_devices(in, GIN_CHOICE),
                         gks_in_num_devices(in, GIN_PICK), gks_in_num_devices(in, GIN_STRING) };
}

GKS_API void ginq_in_overf(Gint *err_ind, Gint *ws_id, Gin_class *in_class, Gint *in_num)
{
    GKS_INQ_ARGS(err_ind, ws_id, in_class, in_num);
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    Gint w = 0, n = 0;
    Gin_class c = GIN_NONE;
    if (!e)
        e = gks_in_overflow(&w, &c, &n);
    set_err(err_ind, e);
    if (e)
        return;
    if (ws_id)
        *ws_id = w;
    if (in_class)
        *in_class = c;
    if (in_num)
        *in_num = n;
}

GKS_API void ginq_more_simult_events(Gint *err_ind, Gsimult_events *simult_events)
{
    GKS_INQ_ARGS(err_ind, simult_events);
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    set_err(err_ind, e);
    if (!e && simult_events)
        *simult_events = gks_in_more_simult() ? GSIMULT_MORE : GSIMULT_NO_MORE;
}
