/* SPDX-License-Identifier: MIT */
/*
 * gks_context.c -- the process's GKS context and the GKS description table.
 */
#include "gks_context.h"
#include "gks_context.h"
#include "gks_xform.h"
#include "ws_driver.h"
#include "gks_legacy.h"

static const gks_ws_driver *const driver_list[] = {
    &gks_ws_null_driver,
    &gks_ws_png_driver,
    &gks_ws_png_large_driver,
    &gks_ws_wiss_driver,
    &gks_ws_mo_driver,
    &gks_ws_mi_driver,
#ifdef GKS_HAVE_CAIRO
    &gks_ws_pdf_driver,
    &gks_ws_svg_driver,
    &gks_ws_ps_driver,
    &gks_ws_eps_driver,
#endif
#ifdef GKS_HAVE_X11
    &gks_ws_x11_driver, /* GKS_WITH_X11 */
#endif
    &gks_ws_png_output_driver, /* last: the earlier types keep their list positions */
};

static const gks_desc_table desc_table = {
    .level = GLEVEL_2C, /* full output, segments, WISS; REQUEST, SAMPLE and EVENT input */
    .n_ws_types = (int)(sizeof driver_list / sizeof driver_list[0]),
    .ws_types = driver_list,
    .max_nums = { GKS_MAX_OPEN_WS, GKS_MAX_ACTIVE_WS, GKS_MAX_OPEN_WS },
    .max_norm_tran = GKS_MAX_NORM_TRAN,
};

/* The one context (the ISO C binding is a procedural API over one GKS instance); reached
 * through gks_ctx (gks_context.h), inline because every entry point asks for it. */
gks_context gks_the_context = { .op_st = GST_GKCL, .desc = &desc_table };

gks_ws *gks_ws_lookup(int ws_id)
{
    gks_state_list *sl = gks_the_context.sl;
    if (!sl)
        return NULL;
    for (int i = 0; i < sl->n_open; i++)
        if (sl->open_ws[i] == ws_id)
            return gks_the_context.ws[i];
    return NULL;
}

const gks_ws_driver *gks_driver_for_type(int ws_type)
{
    ws_type = gks_ws_type_map(ws_type);
    for (int i = 0; i < desc_table.n_ws_types; i++)
        if (driver_list[i]->desc->type == ws_type)
            return driver_list[i];
    return NULL;
}

gks_ws *gks_wiss(void)
{
    gks_state_list *sl = gks_the_context.sl;
    for (int i = 0; sl && i < sl->n_open; i++)
        if (gks_the_context.ws[i]->drv->desc->cat == GCAT_WISS)
            return gks_the_context.ws[i];
    return NULL;
}

int gks_cur_norm_matrix(double m[3][4])
{
    const gks_norm_tran *t = &gks_the_context.sl->tran[gks_the_context.sl->cur_tnr];
    double w[6], v[6];
    gks_limit3_array(&t->win, w);
    gks_limit3_array(&t->vp, v);
    return gks_xform_norm_tran3(w, v, m);
}
