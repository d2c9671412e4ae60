/* SPDX-License-Identifier: MIT */
/*
 * plot2d.c -- a 2-D scientific plot in the style of the RAL GKS examples: a normalization
 * transformation from the data's window to a viewport, axes with tick marks and labels
 * (TEXT with alignment, up vector for the y label), two curves (solid and dashed
 * POLYLINEs), measured points (POLYMARKER with two marker types), a hatched histogram
 * (FILL AREA, hatch style), a pattern-filled legend box and a CELL ARRAY colour bar.
 * Only GKS 2-D output functions. Usage: plot2d_c [SIZE [PREFIX [png|pdf|svg|ps|eps]]]:
 * SIZE the picture side in pixels (24..2048, default 480; vector types: SIZE x 0.2 mm,
 * their nominal unit in the place of a pixel); writes PREFIXplot2d.<type>.
 */
#include <gks.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef float real;
enum { WS = 1, NP = 61, NH = 10 };
enum { LT_SOLID = 1, LT_DASHED = 2, LT_DOTTED = 3, MK_CIRCLE = 4, MK_DIAG_CROSS = 5 };

static void line2(real x0, real y0, real x1, real y1)
{
    Gpoint p[2] = { { x0, y0 }, { x1, y1 } };
    Gpoint_list l = { 2, p };
    gpolyline(&l);
}

static void text_at(real x, real y, Ghor_text_align h, Gvert_text_align v, const char *s)
{
    Gtext_align a = { h, v };
    gset_text_align(&a);
    Gpoint p = { x, y };
    gtext(&p, s);
}

static void colour(int i, real r, real g, real b)
{
    Gcolr_rep c = { .rgb = { r, g, b } };
    gset_colr_rep(WS, i, &c);
}

int main(int argc, char **argv)
{
    static const char *const names[] = { "png", "pdf", "svg", "ps", "eps" };
    static const Gint types[] = { GWS_TYPE_PNG, GWS_TYPE_PDF, GWS_TYPE_SVG, GWS_TYPE_PS,
                                  GWS_TYPE_EPS };
    int size = 480, t = 0;
    const char *prefix = argc > 2 ? argv[2] : "";
    if (argc > 1) {
        char *end = NULL;
        long v = strtol(argv[1], &end, 10);
        size = *end || v < 24 || v > 2048 ? 0 : (int)v;
    }
    if (argc > 3)
        for (t = 0; t < 5 && strcmp(argv[3], names[t]) != 0; t++)
            ;
    if (size == 0 || t == 5 || strlen(prefix) > 200) {
        fprintf(stderr, "usage: %s [SIZE (24..2048) [PREFIX [png|pdf|svg|ps|eps]]]\n", argv[0]);
        return 2;
    }
    char base[256];
    snprintf(base, sizeof base, "%splot2d", prefix);
    gopen_gks(NULL, 0);
    gopen_ws(WS, "1", types[t]);
    Gescape_in_data in = { { 1, (Gint[]){ WS }, 0, NULL, strlen(base), base } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
    gactivate_ws(WS);
    colour(2, 0.8f, 0.1f, 0.1f);
    colour(3, 0.1f, 0.3f, 0.8f);
    colour(4, 0.3f, 0.6f, 0.2f);
    real side = types[t] == GWS_TYPE_PNG ? (real)size : (real)size * 0.0002f;
    Glimit wsw = { 0.0f, 1.0f, 0.0f, 1.0f }, wsv = { 0.0f, side, 0.0f, side };
    gset_ws_win(WS, &wsw);
    gset_ws_vp(WS, &wsv);

    /* the data window: x in [0, 10], y in [-1.2, 1.2] onto the plot frame */
    Glimit win = { 0.0f, 10.0f, -1.2f, 1.2f }, vp = { 0.15f, 0.92f, 0.15f, 0.85f };
    gset_win(1, &win);
    gset_vp(1, &vp);
    gsel_norm_tran(1);
    gset_clip_ind(GIND_CLIP);

    /* histogram of |f| at integer x: hatched bars */
    gset_fill_int_style(GSTYLE_HATCH);
    gset_fill_style_ind(-3);
    gset_fill_colr_ind(4);
    for (int i = 0; i < NH; i++) {
        real x0 = (real)i + 0.1f, x1 = (real)i + 0.9f;
        real h = 0.9f * expf(-0.15f * (real)i);
        Gpoint b[4] = { { x0, -1.2f }, { x1, -1.2f }, { x1, -1.2f + h }, { x0, -1.2f + h } };
        Gpoint_list l = { 4, b };
        gfill_area(&l);
    }
    /* two curves: a damped sine (solid, width 2) and its envelope (dashed) */
    Gpoint c[NP], e[NP];
    for (int i = 0; i < NP; i++) {
        real x = 10.0f * (real)i / (real)(NP - 1);
        c[i] = (Gpoint){ x, expf(-0.15f * x) * sinf(2.0f * x) };
        e[i] = (Gpoint){ x, expf(-0.15f * x) };
    }
    Gpoint_list cl = { NP, c }, el = { NP, e };
    gset_line_colr_ind(2);
    gset_linewidth(2.0f);
    gpolyline(&cl);
    gset_linewidth(1.0f);
    gset_linetype(LT_DASHED);
    gset_line_colr_ind(3);
    gpolyline(&el);
    gset_linetype(LT_DOTTED);
    for (int i = 0; i < NP; i++)
        e[i].y = -e[i].y;
    gpolyline(&el);
    gset_linetype(LT_SOLID);
    /* measured points: every fifth sample, circles and crosses */
    Gpoint m[13];
    for (int i = 0; i < 13; i++)
        m[i] = c[5 * i];
    Gpoint_list ml = { 13, m };
    gset_marker_colr_ind(1);
    gset_marker_type(MK_CIRCLE);
    gset_marker_size(1.5f);
    gpolymarker(&ml);
    gset_marker_type(MK_DIAG_CROSS);
    gset_marker_size(1.0f);
    gpolymarker(&ml);

    /* axes, ticks and labels (no clipping: labels lie outside the window) */
    gset_clip_ind(GIND_NO_CLIP);
    gset_line_colr_ind(1);
    line2(0.0f, -1.2f, 10.0f, -1.2f);
    line2(0.0f, -1.2f, 0.0f, 1.2f);
    line2(0.0f, 0.0f, 10.0f, 0.0f);
    gset_char_ht(0.07f);
    gset_text_colr_ind(1);
    char lab[16];
    for (int i = 0; i <= 10; i += 2) {
        line2((real)i, -1.2f, (real)i, -1.12f);
        snprintf(lab, sizeof lab, "%d", i);
        text_at((real)i, -1.26f, GHOR_CTR, GVERT_TOP, lab);
    }
    for (int j = -2; j <= 2; j++) {
        real y = 0.5f * (real)j;
        line2(0.0f, y, 0.15f, y);
        snprintf(lab, sizeof lab, "%.1f", (double)y);
        text_at(-0.15f, y, GHOR_RIGHT, GVERT_HALF, lab);
    }
    gset_char_ht(0.08f);
    text_at(5.0f, -1.5f, GHOR_CTR, GVERT_TOP, "time t (s)");
    Gvec up = { -1.0f, 0.0f }, up0 = { 0.0f, 1.0f };
    gset_char_up_vec(&up);
    text_at(-1.2f, 0.0f, GHOR_CTR, GVERT_BOTTOM, "amplitude");
    gset_char_up_vec(&up0);
    gset_char_ht(0.11f);
    text_at(5.0f, 1.3f, GHOR_CTR, GVERT_BASE, "Damped oscillation");

    /* legend in NDC: a pattern-filled box and a cell-array colour bar */
    gsel_norm_tran(0);
    Gint pat[4] = { 2, 0, 0, 3 };
    Gpat_rep pr = { { 2, 2 }, pat };
    gset_pat_rep(WS, 1, &pr);
    gset_fill_int_style(GSTYLE_PAT);
    gset_fill_style_ind(1);
    gset_pat_size(0.02f, 0.02f);
    Gpoint pref = { 0.70f, 0.90f };
    gset_pat_ref_point(&pref);
    Gpoint box[4] = { { 0.70f, 0.90f }, { 0.78f, 0.90f }, { 0.78f, 0.96f }, { 0.70f, 0.96f } };
    Gpoint_list bl = { 4, box };
    gfill_area(&bl);
    Gint cells[8] = { 1, 2, 3, 4, 4, 3, 2, 1 };
    Grect cr = { { 0.80f, 0.90f }, { 0.96f, 0.96f } };
    Gpat_rep ca = { { 4, 2 }, cells };
    gcell_array(&cr, &ca);

    gdeactivate_ws(WS);
    gclose_ws(WS);
    gclose_gks();
    return 0;
}
