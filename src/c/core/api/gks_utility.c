/* SPDX-License-Identifier: MIT */
/*
 * gks_utility.c -- utility functions: EVALUATE/ACCUMULATE TRANSFORMATION MATRIX (2-D and
 * 3), EVALUATE VIEW ORIENTATION MATRIX 3, EVALUATE VIEW MAPPING MATRIX 3. The math is
 * gks_xform's; this file converts the binding's types, applies the coordinate switch and
 * reports errors. The view evaluation functions report through ERROR HANDLING like every
 * GKS function and also return the error in err_ind (the GKS-3D binding's ERR argument).
 */
#include "gks_context.h"
#include "gks_error.h"
#include "gks_state.h"
#include "gks_xform.h"

/* WC -> NDC3 by the current normalization transformation: points (is_point = 1) are
 * mapped, vectors only scaled (the matrix is diagonal plus translation). With
 * GCOORD_NDC, or a degenerate transformation, they are unchanged. */
static void to_ndc3(Gcoord_switch sw, const double in[3], int is_point, double out[3])
{
    double m[3][4];
    if (sw != GCOORD_WC || gks_cur_norm_matrix(m)) {
        for (int k = 0; k < 3; k++)
            out[k] = in[k];
        return;
    }
    if (is_point)
        gks_xform_mat34_point(m, in, out);
    else
        for (int k = 0; k < 3; k++)
            out[k] = m[k][k] * in[k];
}

static int sw_valid(Gcoord_switch sw)
{
    return sw == GCOORD_WC || sw == GCOORD_NDC;
}

/* A NULL pointer argument without an error of its own is 2003 (docs/ERRORS.md). */
#define GKS_E_NULL_ARG 2003

GKS_API void geval_tran_matrix(const Gpoint *fixed, const Gvec *shift, Gdouble angle,
                               const Gvec *scale, Gcoord_switch sw, Gtran_matrix m)
{
    if (gks_check_state(GFN_EVTM))
        return;
    if (!fixed || !shift || !scale || !m)
        GKS_FAIL(GKS_E_NULL_ARG, GFN_EVTM);
    if (!sw_valid(sw))
        GKS_FAIL(2000, GFN_EVTM);
    double f[3], s[3];
    to_ndc3(sw, (const double[3]){ fixed->x, fixed->y, 0 }, 1, f);
    to_ndc3(sw, (const double[3]){ shift->delta_x, shift->delta_y, 0 }, 0, s);
    int err = gks_xform_eval_tran(f, s, angle, (const double[2]){ scale->delta_x, scale->delta_y }, m);
    if (err)
        GKS_FAIL(err, GFN_EVTM);
}

GKS_API void gaccum_tran_matrix(const Gtran_matrix m_in, const Gpoint *fixed, const Gvec *shift,
                                Gdouble angle, const Gvec *scale, Gcoord_switch sw,
                                Gtran_matrix m_out)
{
    if (gks_check_state(GFN_ACTM))
        return;
    if (!m_in || !fixed || !shift || !scale || !m_out)
        GKS_FAIL(GKS_E_NULL_ARG, GFN_ACTM);
    if (!sw_valid(sw))
        GKS_FAIL(2000, GFN_ACTM);
    double f[3], s[3];
    to_ndc3(sw, (const double[3]){ fixed->x, fixed->y, 0 }, 1, f);
    to_ndc3(sw, (const double[3]){ shift->delta_x, shift->delta_y, 0 }, 0, s);
    int err = gks_xform_accum_tran(m_in, f, s, angle,
                                   (const double[2]){ scale->delta_x, scale->delta_y }, m_out);
    if (err)
        GKS_FAIL(err, GFN_ACTM);
}

GKS_API void geval_tran_matrix3(const Gpoint3 *fixed, const Gvec3 *shift, Gdouble x_ang,
                                Gdouble y_ang, Gdouble z_ang, const Gvec3 *scale,
                                Gcoord_switch sw, Gtran_matrix3 m)
{
    if (gks_check_state(GFN_EVTM3))
        return;
    if (!fixed || !shift || !scale || !m)
        GKS_FAIL(GKS_E_NULL_ARG, GFN_EVTM3);
    if (!sw_valid(sw))
        GKS_FAIL(2000, GFN_EVTM3);
    double f[3], s[3];
    to_ndc3(sw, (const double[3]){ fixed->x, fixed->y, fixed->z }, 1, f);
    to_ndc3(sw, (const double[3]){ shift->delta_x, shift->delta_y, shift->delta_z }, 0, s);
    int err = gks_xform_eval_tran3(f, s, (const double[3]){ x_ang, y_ang, z_ang },
                                   (const double[3]){ scale->delta_x, scale->delta_y, scale->delta_z }, m);
    if (err)
        GKS_FAIL(err, GFN_EVTM3);
}

GKS_API void gaccum_tran_matrix3(const Gtran_matrix3 m_in, const Gpoint3 *fixed,
                                 const Gvec3 *shift, Gdouble x_ang, Gdouble y_ang,
                                 Gdouble z_ang, const Gvec3 *scale, Gcoord_switch sw,
                                 Gtran_matrix3 m_out)
{
    if (gks_check_state(GFN_ACTM3))
        return;
    if (!m_in || !fixed || !shift || !scale || !m_out)
        GKS_FAIL(GKS_E_NULL_ARG, GFN_ACTM3);
    if (!sw_valid(sw))
        GKS_FAIL(2000, GFN_ACTM3);
    double f[3], s[3];
    to_ndc3(sw, (const double[3]){ fixed->x, fixed->y, fixed->z }, 1, f);
    to_ndc3(sw, (const double[3]){ shift->delta_x, shift->delta_y, shift->delta_z }, 0, s);
    int err = gks_xform_accum_tran3(m_in, f, s, (const double[3]){ x_ang, y_ang, z_ang },
                                    (const double[3]){ scale->delta_x, scale->delta_y, scale->delta_z }, m_out);
    if (err)
        GKS_FAIL(err, GFN_ACTM3);
}

GKS_API void geval_view_ori_matrix3(const Gpoint3 *vrp, const Gvec3 *vpn, const Gvec3 *vup,
                                    Gcoord_switch sw, Gint *err_ind, Gmatrix3 m)
{
    /* ISO 8805 (like PHIGS): the evaluate-view utilities report the standard's errors in
     * their error indicator only; ERROR HANDLING is not called. A NULL argument (2003,
     * not an error of the standard) still goes through the one error path. */
    Gint e_ = 0;
    if (!err_ind)
        err_ind = &e_;
    *err_ind = gks_inq_state(GKS_S_OPEN);
    if (*err_ind)
        return;
    if (!vrp || !vpn || !vup || !m) {
        *err_ind = GKS_E_NULL_ARG;
        GKS_FAIL(GKS_E_NULL_ARG, GFN_EVVWM);
    }
    if (!sw_valid(sw)) {
        *err_ind = 2000;
        return;
    }
    double r3[3], n3[3], u3[3];
    to_ndc3(sw, (const double[3]){ vrp->x, vrp->y, vrp->z }, 1, r3);
    to_ndc3(sw, (const double[3]){ vpn->delta_x, vpn->delta_y, vpn->delta_z }, 0, n3);
    to_ndc3(sw, (const double[3]){ vup->delta_x, vup->delta_y, vup->delta_z }, 0, u3);
    *err_ind = gks_xform_eval_view_orientation3(r3, n3, u3, m);
}

GKS_API void geval_view_map_matrix3(const Gview_map3 *map, Gint *err_ind, Gmatrix3 m)
{
    Gint e_ = 0;
    if (!err_ind)
        err_ind = &e_;
    *err_ind = gks_inq_state(GKS_S_OPEN); /* error indicator only, as above */
    if (*err_ind)
        return;
    if (!map || !m) {
        *err_ind = GKS_E_NULL_ARG;
        GKS_FAIL(GKS_E_NULL_ARG, GFN_EVPJM);
    }
    gks_xform_view_map3 v = {
        .window = { map->win.x_min, map->win.x_max, map->win.y_min, map->win.y_max },
        .viewport = { map->proj_vp.x_min, map->proj_vp.x_max, map->proj_vp.y_min,
                      map->proj_vp.y_max, map->proj_vp.z_min, map->proj_vp.z_max },
        .proj_type = (int)map->proj_type,
        .prp = { map->proj_ref_point.x, map->proj_ref_point.y, map->proj_ref_point.z },
        .vpd = map->view_plane, .bpd = map->back_plane, .fpd = map->front_plane,
    };
    *err_ind = gks_xform_eval_view_mapping3(&v, m);
}
