/* SPDX-License-Identifier: MIT */
/*
 * gks_light.c -- lighting functions (PHIGS PLUS semantics added to GKS-3D, paper section 5):
 * SET (BACK) AREA PROPERTIES, SET (BACK) REFLECTANCE EQUATION, SET LIGHT SOURCE
 * REPRESENTATION, SET LIGHT SOURCE STATE and their inquiries. Error numbers: PHIGS + 400
 * (docs/ERRORS.md); out-of-range real values without a PHIGS number are 2000.
 */
#include "gks_error.h"
#include "gks_mf_record.h"
#include "gks_state.h"
#include "gks_ws.h"
#include "gks_context.h"
#include <math.h>

static int unit_ok(double v) { return isfinite(v) && v >= 0 && v <= 1; }

static int colour_ok(const Grgb *c)
{
    return unit_ok(c->red) && unit_ok(c->green) && unit_ok(c->blue);
}

/* 0, 96 (colour) or 2000 (other value). */
static int check_props(const Garea_props *p)
{
    if (!p)
        return 2000;
    if (!unit_ok(p->ambient_coef) || !unit_ok(p->diffuse_coef) || !unit_ok(p->specular_coef) ||
        !unit_ok(p->transpar_coef) || !isfinite(p->specular_exp) || p->specular_exp < 0 ||
        !isfinite(p->refr_index) || p->refr_index <= 0)
        return 2000;
    return colour_ok(&p->specular_colr) ? 0 : 96;
}

static void set_props(int fct, int side, const Garea_props *props)
{
    if (gks_check_state(fct))
        return;
    int err = check_props(props);
    if (err)
        GKS_FAIL(err, fct);
    gks_attrs_w()->area_props[side] = *props;
}

GKS_API void gset_area_props(const Garea_props *props) { set_props(GFN_SAPR, 0, props); }
GKS_API void gset_back_area_props(const Garea_props *props) { set_props(GFN_SBAPR, 1, props); }

static void set_refl(int fct, int side, Gint refl_eq)
{
    if (gks_check_state(fct))
        return;
    if (refl_eq < GREFL_NONE || refl_eq > GREFL_AMB_DIFF_SPEC)
        GKS_FAIL(524, fct);
    gks_attrs_w()->refl_eq[side] = refl_eq;
}

GKS_API void gset_refl_eq(Gint refl_eq) { set_refl(GFN_SRFEQ, 0, refl_eq); }
GKS_API void gset_back_refl_eq(Gint refl_eq) { set_refl(GFN_SBRFEQ, 1, refl_eq); }

static int finite3(double a, double b, double c) { return isfinite(a) && isfinite(b) && isfinite(c); }

GKS_API void gset_light_src_rep(Gint ws_id, Gint light_ind, const Glight_src_rep *rep)
{
    if (gks_check_state(GFN_SLSR))
        return;
    gks_ws *ws = gks_ws_checked(GFN_SLSR, ws_id,
                                GKS_WSC_NOT_MI | GKS_WSC_NOT_INPUT | GKS_WSC_NOT_WISS);
    if (!ws)
        return;
    if (light_ind < 1 || light_ind > GKS_MAX_LIGHT_IND)
        GKS_FAIL(529, GFN_SLSR);
    if (!rep)
        GKS_FAIL(2000, GFN_SLSR);
    if (rep->type < GLIGHT_AMBIENT || rep->type > GLIGHT_SPOT)
        GKS_FAIL(531, GFN_SLSR);
    if (rep->type == GLIGHT_SPOT &&
        !(isfinite(rep->spread_angle) && rep->spread_angle >= 0 &&
          rep->spread_angle <= 3.14159265358979323846))
        GKS_FAIL(532, GFN_SLSR);
    if (!colour_ok(&rep->colr))
        GKS_FAIL(96, GFN_SLSR);
    if (!finite3(rep->pos.x, rep->pos.y, rep->pos.z) ||
        !finite3(rep->dir.delta_x, rep->dir.delta_y, rep->dir.delta_z) ||
        !isfinite(rep->atten[0]) || !isfinite(rep->atten[1]) || rep->atten[0] < 0 ||
        rep->atten[1] < 0 || !isfinite(rep->conc_exp) || rep->conc_exp < 0 ||
        !isfinite(rep->spread_angle))
        GKS_FAIL(2000, GFN_SLSR);
    ws->lights[light_ind - 1] = *rep;
    ws->light_defined[light_ind - 1] = 1;
    GKS_MF_WS(SLSR, ws_id, light_ind, rep->type, &rep->colr.red, &rep->pos.x,
              &rep->dir.delta_x, rep->atten, rep->conc_exp, rep->spread_angle);
}

static int list_ok(const Gint_list *l)
{
    if (!l || l->num_ints <= 0)
        return 1;
    if (!l->ints)
        return 0;
    for (int i = 0; i < l->num_ints; i++)
        if (l->ints[i] < 1 || l->ints[i] > GKS_MAX_LIGHT_IND)
            return 0;
    return 1;
}

static uint64_t list_mask(const Gint_list *l)
{
    uint64_t m = 0;
    for (int i = 0; l && i < l->num_ints; i++)
        m |= (uint64_t)1 << (l->ints[i] - 1);
    return m;
}

GKS_API void gset_light_src_state(const Gint_list *activate, const Gint_list *deactivate)
{
    if (gks_check_state(GFN_SLSS))
        return;
    if (!list_ok(activate) || !list_ok(deactivate))
        GKS_FAIL(533, GFN_SLSS);
    uint64_t on = list_mask(activate), off = list_mask(deactivate);
    if (on & off)
        GKS_FAIL(535, GFN_SLSS);
    uint64_t *m = &gks_attrs_w()->light_mask;
    *m = (*m | on) & ~off;
}

GKS_API void ginq_area_props(Gint *err_ind, Garea_props *front, Garea_props *back)
{
    GKS_INQ_ARGS(err_ind, front, back);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    if (front)
        *front = gks_ctx()->sl->attrs.area_props[0];
    if (back)
        *back = gks_ctx()->sl->attrs.area_props[1];
}

GKS_API void ginq_refl_eq(Gint *err_ind, Gint *front, Gint *back)
{
    GKS_INQ_ARGS(err_ind, front, back);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    if (front)
        *front = gks_ctx()->sl->attrs.refl_eq[0];
    if (back)
        *back = gks_ctx()->sl->attrs.refl_eq[1];
}

GKS_API void ginq_light_src_rep(Gint ws_id, Gint light_ind, Gint *err_ind, Glight_src_rep *rep)
{
    GKS_INQ_ARGS(err_ind, rep);
    gks_ws *ws = gks_inq_ws(ws_id, err_ind);
    if (!ws)
        return;
    if (light_ind < 1 || light_ind > GKS_MAX_LIGHT_IND) {
        *err_ind = 529;
        return;
    }
    if (!ws->light_defined[light_ind - 1]) {
        *err_ind = 2002;
        return;
    }
    if (rep)
        *rep = ws->lights[light_ind - 1];
}

GKS_API void ginq_light_src_state(Gint num_elems_appl_list, Gint start_pos, Gint *err_ind,
                                  Gint_list *active, Gint *length_list)
{
    GKS_INQ_ARGS(err_ind, active, length_list);
    if (gks_inq_begin(err_ind, GKS_S_OPEN))
        return;
    uint64_t m = gks_ctx()->sl->attrs.light_mask;
    gks_list_out w = gks_list_begin(active, num_elems_appl_list, start_pos);
    for (int i = 0; i < GKS_MAX_LIGHT_IND; i++)
        if ((m >> i) & 1)
            gks_list_put(&w, i + 1);
    *err_ind = gks_list_end(&w, length_list);
}
