/* SPDX-License-Identifier: MIT */
/*
 * gks_context.c -- the process's GKS context and the GKS description table.
 */
#include "gks_context.h"
#include "gks_context.h"
#include "gks_xform.h"
#include "ws_driver.h"
#include "gks_legacy.h"

/* The drivers of the list ws_drivers.def, in its order; GKS_WS_WHEN_<when> keeps a row
 * (its table's address and a comma) of an optional dependency only when the dependency is
 * built. */
#define GKS_WS_WHEN_ALWAYS(x) x,
#ifdef GKS_HAVE_CAIRO
#define GKS_WS_WHEN_CAIRO(x) x,
#else
#define GKS_WS_WHEN_CAIRO(x)
#endif
#ifdef GKS_HAVE_X11
#define GKS_WS_WHEN_X11(x) x,
#else
#define GKS_WS_WHEN_X11(x)
#endif
#define GKS_WS_DRIVER(folder, table, when) GKS_WS_WHEN_##when(&table)
static const gks_ws_driver *const driver_list[] = {
#include "ws_drivers.def"
};
#undef GKS_WS_DRIVER

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
