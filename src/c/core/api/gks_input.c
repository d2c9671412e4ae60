/* SPDX-License-Identifier: MIT */
/*
 * gks_input.c -- the input functions of ISO 7942 5.9 (INITIALISE, SET MODE, REQUEST,
 * SAMPLE, AWAIT EVENT, FLUSH DEVICE EVENTS, GET) and the input inquiries, for an
 * implementation whose workstations have no logical input devices.
 *
 * No workstation type is of category INPUT or OUTIN and no description table lists a
 * logical input device (the GKS level is 2a). Each function performs the standard's
 * checks in the standard's order and ends with the first one that fails: the operating
 * state (7; 8 for the description-table inquiries), then the workstation (20 invalid
 * identifier, 25 not open, 38 neither INPUT nor OUTIN -- the MO, MI and WISS categories
 * included, the standard lists no 31/33/36 for input functions) and the device (140).
 * The checks the standard lists after 140 (prompt/echo type, echo area, data record,
 * initial values, 141/142 mode, 143 level) cannot be reached and are not coded.
 * AWAIT EVENT finds the input queue empty and no device that could fill it, so it returns
 * class NONE at once; GET finds no value in the current event report (150).
 * Output arguments are set to "no input" before any check (REQUEST: status NONE), so a
 * caller never reads stale values. No state list is changed by any function here.
 */
#include "gks_error.h"
#include "gks_state.h"
#include "gks_ws.h"
#include <math.h>

static const Gloc no_loc = { 0, { 0, 0 } };
static const Gpick no_pick = { 0, 0 };

/* Logical input devices of class cls on a workstation type. The description tables of
 * this implementation (ws_driver.h) describe output only: 0 for every type and class. */
static int num_devices(const gks_ws_desc *d, Gin_class cls)
{
    (void)d;
    (void)cls;
    return 0;
}

/* The device checks after the category check: 2000 for a class outside LOC..STRING
 * (FLUSH DEVICE EVENTS), 140 for a device number the type does not have. */
static int device_number_error(const gks_ws_desc *d, Gin_class cls, Gint dev)
{
    if (d->cat != GCAT_IN && d->cat != GCAT_OUTIN)
        return 38;
    if (cls < GIN_LOC || cls > GIN_STRING)
        return 2000;
    if (dev < 1 || dev > num_devices(d, cls))
        return 140;
    return 0;
}

/* Workstation and device of the functions that name an open workstation: 20, 25, 38,
 * (2000,) 140. Never 0 while num_devices is 0. */
static int device_error(Gint ws_id, Gin_class cls, Gint dev)
{
    if (ws_id < 0)
        return 20;
    const gks_ws *ws = gks_ws_lookup(ws_id);
    if (!ws)
        return 25;
    return device_number_error(ws->drv->desc, cls, dev);
}

/* Workstation type and device of the default-data inquiries: 22, 23, 38, 140. */
static int type_device_error(Gint ws_type, Gin_class cls, Gint dev)
{
    if (ws_type <= 0)
        return 22;
    const gks_ws_driver *d = gks_driver_for_type(ws_type);
    if (!d)
        return 23;
    return device_number_error(d->desc, cls, dev);
}

/* Entry of every function that names a device: the state check (7), then the device
 * checks; the first error is reported for fctid. Every path ends in an error, which is
 * returned: there is no device to operate on. */
static int input_entry(int fctid, Gint ws_id, Gin_class cls, Gint dev)
{
    int e = gks_check_state(fctid);
    if (e)
        return e;
    e = device_error(ws_id, cls, dev);
    if (e)
        GKS_FAIL_RET(e, fctid, e);
    return e;
}

/* Entry of the GET functions: state (7), then 150 (no value of the class in the current
 * event report: AWAIT EVENT never delivers one). */
static void get_entry(int fctid)
{
    if (gks_check_state(fctid))
        return;
    GKS_FAIL(150, fctid);
}

static void set_err(Gint *err_ind, Gint e)
{
    if (err_ind)
        *err_ind = e;
}

/* Error indicator of the device state inquiries: 7, 20, 25, 38, 140. */
static Gint inq_device(Gint ws_id, Gin_class cls, Gint dev)
{
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    return e ? e : device_error(ws_id, cls, dev);
}

/* Error indicator of the default-data inquiries: 8, 22, 23, 38, 140. */
static Gint inq_type_device(Gint ws_type, Gin_class cls, Gint dev)
{
    Gint e = gks_inq_state(GKS_S_OPEN);
    return e ? e : type_device_error(ws_type, cls, dev);
}

/* ---- INITIALISE ... (errors 7, 20, 25, 38, 140) ---- */

GKS_API void ginit_loc(Gint ws_id, Gint loc_num, const Gloc *init_loc, Gint pet,
                       const Glimit *echo_area, const Gin_data *loc_data)
{
    (void)init_loc, (void)pet, (void)echo_area, (void)loc_data;
    input_entry(GFN_INLC, ws_id, GIN_LOC, loc_num);
}

GKS_API void ginit_stroke(Gint ws_id, Gint stroke_num, const Gstroke *init_stroke, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size,
                          const Gin_data *stroke_data)
{
    (void)init_stroke, (void)pet, (void)echo_area, (void)in_buf_size, (void)stroke_data;
    input_entry(GFN_INSK, ws_id, GIN_STROKE, stroke_num);
}

GKS_API void ginit_val(Gint ws_id, Gint val_num, Gfloat init_value, Gint pet,
                       const Glimit *echo_area, Gfloat low_value, Gfloat high_value,
                       const Gin_data *val_data)
{
    (void)init_value, (void)pet, (void)echo_area, (void)low_value, (void)high_value;
    (void)val_data;
    input_entry(GFN_INVL, ws_id, GIN_VAL, val_num);
}

GKS_API void ginit_choice(Gint ws_id, Gint choice_num, Gin_status init_status,
                          Gint init_choice, Gint pet, const Glimit *echo_area,
                          const Gin_data *choice_data)
{
    (void)init_status, (void)init_choice, (void)pet, (void)echo_area, (void)choice_data;
    input_entry(GFN_INCH, ws_id, GIN_CHOICE, choice_num);
}

GKS_API void ginit_pick(Gint ws_id, Gint pick_num, Gin_status init_status,
                        const Gpick *init_pick, Gint pet, const Glimit *echo_area,
                        const Gin_data *pick_data)
{
    (void)init_status, (void)init_pick, (void)pet, (void)echo_area, (void)pick_data;
    input_entry(GFN_INPK, ws_id, GIN_PICK, pick_num);
}

GKS_API void ginit_string(Gint ws_id, Gint string_num, const char *init_string, Gint pet,
                          const Glimit *echo_area, Gint in_buf_size, Gint init_cur_pos,
                          const Gin_data *string_data)
{
    (void)init_string, (void)pet, (void)echo_area, (void)in_buf_size, (void)init_cur_pos;
    (void)string_data;
    input_entry(GFN_INST, ws_id, GIN_STRING, string_num);
}

/* ---- SET ... MODE (errors 7, 20, 25, 38, 140) ---- */

#define GKS_SET_MODE(cname, fct, cls)                                                     \
    GKS_API void cname(Gint ws_id, Gint num, Gop_mode op_mode, Gecho_switch echo_switch) \
    {                                                                                     \
        (void)op_mode, (void)echo_switch;                                                 \
        input_entry(fct, ws_id, cls, num);                                                \
    }
GKS_SET_MODE(gset_loc_mode, GFN_SLCM, GIN_LOC)
GKS_SET_MODE(gset_stroke_mode, GFN_SSKM, GIN_STROKE)
GKS_SET_MODE(gset_val_mode, GFN_SVLM, GIN_VAL)
GKS_SET_MODE(gset_choice_mode, GFN_SCHM, GIN_CHOICE)
GKS_SET_MODE(gset_pick_mode, GFN_SPKM, GIN_PICK)
GKS_SET_MODE(gset_string_mode, GFN_SSTM, GIN_STRING)
#undef GKS_SET_MODE

/* ---- REQUEST ... and SAMPLE ... (errors 7, 20, 25, 38, 140) ---- */

static void no_status(Gin_status *s)
{
    if (s)
        *s = GIN_STATUS_NONE;
}

static void no_stroke(Gstroke *s)
{
    if (s) {
        s->norm_tran_num = 0;
        s->num_points = 0;
    }
}

static void no_string(char *s)
{
    if (s)
        *s = '\0';
}

GKS_API void greq_loc(Gint ws_id, Gint loc_num, Gin_status *in_status, Gloc *loc)
{
    no_status(in_status);
    if (loc)
        *loc = no_loc;
    input_entry(GFN_RQLC, ws_id, GIN_LOC, loc_num);
}

GKS_API void greq_stroke(Gint ws_id, Gint stroke_num, Gin_status *in_status, Gstroke *stroke)
{
    no_status(in_status);
    no_stroke(stroke);
    input_entry(GFN_RQSK, ws_id, GIN_STROKE, stroke_num);
}

GKS_API void greq_val(Gint ws_id, Gint val_num, Gin_status *in_status, Gfloat *value)
{
    no_status(in_status);
    if (value)
        *value = 0;
    input_entry(GFN_RQVL, ws_id, GIN_VAL, val_num);
}

GKS_API void greq_choice(Gint ws_id, Gint choice_num, Gin_status *in_status, Gint *choice)
{
    no_status(in_status);
    if (choice)
        *choice = 0;
    input_entry(GFN_RQCH, ws_id, GIN_CHOICE, choice_num);
}

GKS_API void greq_pick(Gint ws_id, Gint pick_num, Gin_status *in_status, Gpick *pick)
{
    no_status(in_status);
    if (pick)
        *pick = no_pick;
    input_entry(GFN_RQPK, ws_id, GIN_PICK, pick_num);
}

GKS_API void greq_string(Gint ws_id, Gint string_num, Gin_status *in_status, char *string)
{
    no_status(in_status);
    no_string(string);
    input_entry(GFN_RQST, ws_id, GIN_STRING, string_num);
}

GKS_API void gsample_loc(Gint ws_id, Gint loc_num, Gloc *loc)
{
    if (loc)
        *loc = no_loc;
    input_entry(GFN_SMLC, ws_id, GIN_LOC, loc_num);
}

GKS_API void gsample_stroke(Gint ws_id, Gint stroke_num, Gstroke *stroke)
{
    no_stroke(stroke);
    input_entry(GFN_SMSK, ws_id, GIN_STROKE, stroke_num);
}

GKS_API void gsample_val(Gint ws_id, Gint val_num, Gfloat *value)
{
    if (value)
        *value = 0;
    input_entry(GFN_SMVL, ws_id, GIN_VAL, val_num);
}

GKS_API void gsample_choice(Gint ws_id, Gint choice_num, Gin_status *in_status, Gint *choice)
{
    no_status(in_status);
    if (choice)
        *choice = 0;
    input_entry(GFN_SMCH, ws_id, GIN_CHOICE, choice_num);
}

GKS_API void gsample_pick(Gint ws_id, Gint pick_num, Gin_status *in_status, Gpick *pick)
{
    no_status(in_status);
    if (pick)
        *pick = no_pick;
    input_entry(GFN_SMPK, ws_id, GIN_PICK, pick_num);
}

GKS_API void gsample_string(Gint ws_id, Gint string_num, char *string)
{
    no_string(string);
    input_entry(GFN_SMST, ws_id, GIN_STRING, string_num);
}

/* ---- event input ---- */

GKS_API void gawait_event(Gfloat timeout, Gint *ws_id, Gin_class *in_class, Gint *in_num)
{
    if (ws_id)
        *ws_id = 0;
    if (in_class)
        *in_class = GIN_NONE;
    if (in_num)
        *in_num = 0;
    if (gks_check_state(GFN_WAIT))
        return;
    if (!isfinite(timeout) || timeout < 0)
        GKS_FAIL(151, GFN_WAIT);
    /* The queue is empty and no device is in EVENT mode: nothing can arrive within the
     * timeout, so the result (class NONE) is returned without waiting. */
}

GKS_API void gflush_events(Gint ws_id, Gin_class in_class, Gint in_num)
{
    input_entry(GFN_FLUSH, ws_id, in_class, in_num);
}

GKS_API void gget_loc(Gloc *loc)
{
    if (loc)
        *loc = no_loc;
    get_entry(GFN_GTLC);
}

GKS_API void gget_stroke(Gstroke *stroke)
{
    no_stroke(stroke);
    get_entry(GFN_GTSK);
}

GKS_API void gget_val(Gfloat *value)
{
    if (value)
        *value = 0;
    get_entry(GFN_GTVL);
}

GKS_API void gget_choice(Gin_status *in_status, Gint *choice)
{
    no_status(in_status);
    if (choice)
        *choice = 0;
    get_entry(GFN_GTCH);
}

GKS_API void gget_pick(Gin_status *in_status, Gpick *pick)
{
    no_status(in_status);
    if (pick)
        *pick = no_pick;
    get_entry(GFN_GTPK);
}

GKS_API void gget_string(char *string)
{
    no_string(string);
    get_entry(GFN_GTST);
}

/* ---- inquiries (never call ERROR HANDLING; nothing but *err_ind written on error) ---- */

GKS_API void ginq_loc_st(Gint ws_id, Gint loc_num, Ginq_type type, Gint *err_ind, Gloc_st *st)
{
    (void)type, (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_LOC, loc_num));
}

GKS_API void ginq_stroke_st(Gint ws_id, Gint stroke_num, Ginq_type type, Gint *err_ind,
                            Gstroke_st *st)
{
    (void)type, (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_STROKE, stroke_num));
}

GKS_API void ginq_val_st(Gint ws_id, Gint val_num, Gint *err_ind, Gval_st *st)
{
    (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_VAL, val_num));
}

GKS_API void ginq_choice_st(Gint ws_id, Gint choice_num, Gint *err_ind, Gchoice_st *st)
{
    (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_CHOICE, choice_num));
}

GKS_API void ginq_pick_st(Gint ws_id, Gint pick_num, Ginq_type type, Gint *err_ind,
                          Gpick_st *st)
{
    (void)type, (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_PICK, pick_num));
}

GKS_API void ginq_string_st(Gint ws_id, Gint string_num, Gint *err_ind, Gstring_st *st)
{
    (void)st;
    set_err(err_ind, inq_device(ws_id, GIN_STRING, string_num));
}

GKS_API void ginq_def_loc_data(Gint ws_type, Gint loc_num, Gint *err_ind, Gdef_loc *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_LOC, loc_num));
}

GKS_API void ginq_def_stroke_data(Gint ws_type, Gint stroke_num, Gint *err_ind,
                                  Gdef_stroke *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_STROKE, stroke_num));
}

GKS_API void ginq_def_val_data(Gint ws_type, Gint val_num, Gint *err_ind, Gdef_val *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_VAL, val_num));
}

GKS_API void ginq_def_choice_data(Gint ws_type, Gint choice_num, Gint *err_ind,
                                  Gdef_choice *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_CHOICE, choice_num));
}

GKS_API void ginq_def_pick_data(Gint ws_type, Gint pick_num, Gint *err_ind, Gdef_in *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_PICK, pick_num));
}

GKS_API void ginq_def_string_data(Gint ws_type, Gint string_num, Gint *err_ind,
                                  Gdef_string *def)
{
    (void)def;
    set_err(err_ind, inq_type_device(ws_type, GIN_STRING, string_num));
}

GKS_API void ginq_num_avail_in(Gint ws_type, Gint *err_ind, Gnum_in *num_in)
{
    Gint e = gks_inq_state(GKS_S_OPEN);
    const gks_ws_driver *d = NULL;
    if (!e && ws_type <= 0)
        e = 22;
    if (!e && !(d = gks_driver_for_type(ws_type)))
        e = 23;
    if (!e && d->desc->cat != GCAT_IN && d->desc->cat != GCAT_OUTIN)
        e = 38;
    set_err(err_ind, e);
    if (e || !num_in)
        return;
    *num_in = (Gnum_in){ num_devices(d->desc, GIN_LOC), num_devices(d->desc, GIN_STROKE),
                         num_devices(d->desc, GIN_VAL), num_devices(d->desc, GIN_CHOICE),
                         num_devices(d->desc, GIN_PICK), num_devices(d->desc, GIN_STRING) };
}

GKS_API void ginq_in_overf(Gint *err_ind, Gint *ws_id, Gin_class *in_class, Gint *in_num)
{
    (void)ws_id, (void)in_class, (void)in_num;
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    /* The queue is always empty, so it has not overflowed since GKS was opened. */
    set_err(err_ind, e ? e : 148);
}

GKS_API void ginq_more_simult_events(Gint *err_ind, Gsimult_events *simult_events)
{
    Gint e = gks_inq_state(GKS_S_WSOPEN);
    set_err(err_ind, e);
    if (!e && simult_events)
        *simult_events = GSIMULT_NO_MORE;
}
