/* SPDX-License-Identifier: MIT */
/*
 * gks_state.h -- operating states as masks, and the standard's state error numbers.
 */
#ifndef GKS_STATE_H
#define GKS_STATE_H
#include "gks_private.h"
#include "gks.h"

enum {
    GKS_S_GKCL = 1 << GST_GKCL,
    GKS_S_GKOP = 1 << GST_GKOP,
    GKS_S_WSOP = 1 << GST_WSOP,
    GKS_S_WSAC = 1 << GST_WSAC,
    GKS_S_SGOP = 1 << GST_SGOP,
    /* one of WSOP, WSAC, SGOP (error 7) */
    GKS_S_WSOPEN = GKS_S_WSOP | GKS_S_WSAC | GKS_S_SGOP,
    /* one of GKOP, WSOP, WSAC, SGOP (error 8) */
    GKS_S_OPEN = GKS_S_GKOP | GKS_S_WSOPEN,
    GKS_S_ANY = GKS_S_GKCL | GKS_S_OPEN
};

/* The standard's state error for a function allowed in the states of `mask`
 * (1 GKCL, 2 GKOP, 3 WSAC, 4 SGOP, 5 WSAC or SGOP, 6 WSOP or WSAC, 7 WSOP/WSAC/SGOP,
 * 8 GKOP/WSOP/WSAC/SGOP); 0 if the mask allows every state. */
static inline int gks_state_error_for(unsigned mask)
{
    switch (mask) {
    case GKS_S_GKCL: return 1;
    case GKS_S_GKOP: return 2;
    case GKS_S_WSAC: return 3;
    case GKS_S_SGOP: return 4;
    case GKS_S_WSAC | GKS_S_SGOP: return 5;
    case GKS_S_WSOP | GKS_S_WSAC: return 6;
    case GKS_S_WSOPEN: return 7;
    case GKS_S_OPEN: return 8;
    default: return 0;
    }
}

/* The allowed-state mask of function `fctid` (from gks_functions.def). */
unsigned gks_function_states(int fctid);
#endif
