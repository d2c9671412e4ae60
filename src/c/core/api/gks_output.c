/* SPDX-License-Identifier: MIT */
/*
 * gks_output.c -- output primitives (ISO 7942 5.3 and their GKS-3D forms): POLYLINE (3),
 * POLYMARKER (3), TEXT (3), FILL AREA (3), FILL AREA SET (3), CELL ARRAY (3), and the
 * entries INTERPRET ITEM (gks_output_rec.h) and the GDPs (gks_gdp.h) draw through. The
 * transformations they go through are set in gks_transform.c.
 *
 * Each primitive: state check, argument checks (standard order), then one call into the
 * output pipeline (core/pipe/gks_pipe.h: normalization, metafile and segment records,
 * clipping, dispatch to the workstations), whose error is reported here.
 */
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_export.h"
#include "gks_gdp.h"
#include "gks_output_rec.h"
#include "gks_pipe.h"
#include "gks_state.h"
#include "gks_text_layout.h"
#include <math.h>
#include <stddef.h>

/* Reports the pipeline's answer err for fctid (nothing for 0 and GKS_PIPE_REPORTED). */
static void report(int fctid, int err)
{
    if (err > 0)
        GKS_FAIL(err, fctid);
}

/* ------------------------------------------------------------ POLYLINE, POLYMARKER, FILL AREA */
/* The point-list primitives: their function ids (2-D, 3-D), the fewest points they take
 * (fewer: 100) and their pipeline entry. */
typedef struct {
    int fct2, fct3, min;
    int (*draw)(int fctid, const gks_rec_xf *xf, const gks_pipe_src *s, size_t n);
} point_prim;

static int pipe_fill_area(int fctid, const gks_rec_xf *xf, const gks_pipe_src *s, size_t n)
{
    return gks_pipe_area(fctid, xf, 1, &n, s, 0);
}

static const point_prim PL = { GFN_PL, GFN_PL3, 2, gks_pipe_polyline };
static const point_prim PM = { GFN_PM, GFN_PM3, 1, gks_pipe_polymarker };
static const point_prim FA = { GFN_FA, GFN_FA3, 3, pipe_fill_area };

static void points_any(const point_prim *k, int fctid, int n, const Gpoint *p2, const Gpoint3 *p3,
                       const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (n < k->min || (!p2 && !p3))
        GKS_FAIL(100, fctid);
    gks_pipe_src s = { p2, p3, NULL };
    report(fctid, k->draw(fctid, xf, &s, (size_t)n));
}

/* The 2-D, 3-D and INTERPRET ITEM (xf the recorded normalization) forms. */
static void points2(const point_prim *k, const Gpoint_list *l)
{
    points_any(k, k->fct2, l ? l->num_points : 0, l ? l->points : NULL, NULL, NULL);
}

static void points3(const point_prim *k, const Gpoint_list3 *l, const gks_rec_xf *xf)
{
    points_any(k, k->fct3, l ? l->num_points : 0, NULL, l ? l->points : NULL, xf);
}

GKS_API void gpolyline(const Gpoint_list *l) { points2(&PL, l); }
GKS_API void gpolyline3(const Gpoint_list3 *l) { points3(&PL, l, NULL); }
void gks_output_rec_polyline3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    points3(&PL, l, xf);
}

GKS_API void gpolymarker(const Gpoint_list *l) { points2(&PM, l); }
GKS_API void gpolymarker3(const Gpoint_list3 *l) { points3(&PM, l, NULL); }
void gks_output_rec_polymarker3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    points3(&PM, l, xf);
}

GKS_API void gfill_area(const Gpoint_list *l) { points2(&FA, l); }
GKS_API void gfill_area3(const Gpoint_list3 *l) { points3(&FA, l, NULL); }
void gks_output_rec_fill_area3(const gks_rec_xf *xf, const Gpoint_list3 *l)
{
    points3(&FA, l, xf);
}

/* ------------------------------------------------------------------ TEXT */
static void text_any(int fctid, const double pos[3], const double d0[3], const double d1[3],
                     const char *str, const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (!str || gks_text_check(str))
        GKS_FAIL(101, fctid);
    report(fctid, gks_pipe_text(fctid, xf, pos, d0, d1, str));
}

GKS_API void gtext(const Gpoint *pos, const char *str)
{
    const double p[3] = { pos ? pos->x : NAN, pos ? pos->y : NAN, 0 };
    text_any(GFN_TX, p, (const double[3]){ 1, 0, 0 }, (const double[3]){ 0, 1, 0 }, str, NULL);
}

static void text3_any(const Gpoint3 *pos, const Gvec3 dir[2], const char *str,
                      const gks_rec_xf *xf)
{
    const double p[3] = { pos ? pos->x : NAN, pos ? pos->y : NAN, pos ? pos->z : NAN };
    double d0[3] = { NAN, NAN, NAN }, d1[3] = { NAN, NAN, NAN };
    if (dir) {
        d0[0] = dir[0].delta_x; d0[1] = dir[0].delta_y; d0[2] = dir[0].delta_z;
        d1[0] = dir[1].delta_x; d1[1] = dir[1].delta_y; d1[2] = dir[1].delta_z;
    }
    text_any(GFN_TX3, p, d0, d1, str, xf);
}

GKS_API void gtext3(const Gpoint3 *pos, const Gvec3 dir[2], const char *str)
{
    text3_any(pos, dir, str, NULL);
}

void gks_output_rec_text3(const gks_rec_xf *xf, const Gpoint3 *pos, const Gvec3 dir[2],
                          const char *str)
{
    text3_any(pos, dir, str, xf);
}

/* ------------------------------------------------------------------ FILL AREA SET */
/* FILL AREA SET (3): the loops are copied into one WC3 array. */
static void fill_area_set_any(int fctid, const Gpoint_list_list *l2, const Gpoint_list_list3 *l3,
                              const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    int nl = l2 ? l2->num_point_lists : l3 ? l3->num_point_lists : 0;
    if (nl < 1 || (l2 && !l2->point_lists) || (l3 && !l3->point_lists))
        GKS_FAIL(100, fctid);
    size_t total = 0;
    for (int k = 0; k < nl; k++) {
        int c = l2 ? l2->point_lists[k].num_points : l3->point_lists[k].num_points;
        int has = l2 ? l2->point_lists[k].points != NULL : l3->point_lists[k].points != NULL;
        if (c < 3 || !has)
            GKS_FAIL(100, fctid);
        total += (size_t)c;
    }
    size_t *cnt = gks_alloc_array((size_t)nl, sizeof *cnt);
    double (*wc)[3] = gks_alloc_array(total, sizeof *wc);
    if (!cnt || !wc) {
        gks_free(cnt);
        gks_free(wc);
        GKS_FAIL(300, fctid);
    }
    size_t off = 0;
    for (int k = 0; k < nl; k++) {
        int c = l2 ? l2->point_lists[k].num_points : l3->point_lists[k].num_points;
        gks_pipe_src s = { l2 ? l2->point_lists[k].points : NULL,
                           l3 ? l3->point_lists[k].points : NULL, NULL };
        for (int i = 0; i < c; i++)
            gks_pipe_src_get(&s, (size_t)i, wc[off + (size_t)i]);
        cnt[k] = (size_t)c;
        off += (size_t)c;
    }
    gks_pipe_src all = { NULL, NULL, (const double (*)[3])wc };
    int err = gks_pipe_area(fctid, xf, (size_t)nl, cnt, &all, 1);
    gks_free(cnt);
    gks_free(wc);
    report(fctid, err);
}

GKS_API void gfill_area_set(const Gpoint_list_list *l)
{
    fill_area_set_any(GFN_FAS, l, NULL, NULL);
}

GKS_API void gfill_area_set3(const Gpoint_list_list3 *l)
{
    fill_area_set_any(GFN_FAS3, NULL, l, NULL);
}

void gks_output_rec_fill_area_set3(const gks_rec_xf *xf, const Gpoint_list_list3 *l)
{
    fill_area_set_any(GFN_FAS3, NULL, l, xf);
}

/* ------------------------------------------------------------------ CELL ARRAY */
static void cell_array_any(int fctid, const double pqr[3][3], const Gpat_rep *ca,
                           const gks_rec_xf *xf)
{
    if (gks_check_state(fctid))
        return;
    if (!ca || !ca->colr_array || ca->dims.size_x < 1 || ca->dims.size_y < 1)
        GKS_FAIL(91, fctid);
    report(fctid, gks_pipe_cell_array(fctid, xf, pqr, ca->dims.size_x, ca->dims.size_y,
                                      ca->colr_array));
}

GKS_API void gcell_array(const Grect *r, const Gpat_rep *ca)
{
    double pqr[3][3] = { { NAN, NAN, 0 }, { NAN, NAN, 0 }, { NAN, NAN, 0 } };
    if (r) {
        pqr[0][0] = r->p.x; pqr[0][1] = r->p.y;
        pqr[1][0] = r->q.x; pqr[1][1] = r->q.y;
        pqr[2][0] = r->q.x; pqr[2][1] = r->p.y; /* R: end of P's row (x direction) */
    }
    cell_array_any(GFN_CA, (const double (*)[3])pqr, ca, NULL);
}

static void cell_array3_any(const Gparal *par, const Gpat_rep *ca, const gks_rec_xf *xf)
{
    double pqr[3][3] = { { NAN, NAN, NAN }, { NAN, NAN, NAN }, { NAN, NAN, NAN } };
    if (par) {
        const Gpoint3 *v[3] = { &par->p, &par->q, &par->r };
        for (int i = 0; i < 3; i++) {
            pqr[i][0] = v[i]->x; pqr[i][1] = v[i]->y; pqr[i][2] = v[i]->z;
        }
    }
    cell_array_any(GFN_CA3, (const double (*)[3])pqr, ca, xf);
}

GKS_API void gcell_array3(const Gparal *par, const Gpat_rep *ca)
{
    cell_array3_any(par, ca, NULL);
}

void gks_output_rec_cell_array3(const gks_rec_xf *xf, const Gparal *par, const Gpat_rep *ca)
{
    cell_array3_any(par, ca, xf);
}

/* ------------------------------------------------------------------ GDP (gks_gdp.c) */
/* A GDP's tessellation, in WC3, through the POLYLINE and FILL AREA paths (segments and
 * the metafile record what is drawn). The caller did the state and argument checks. */
void gks_output_polyline_d3(int fctid, size_t n, const double (*p)[3])
{
    gks_pipe_src s = { NULL, NULL, p };
    report(fctid, gks_pipe_polyline(fctid, NULL, &s, n));
}

void gks_output_area_d3(int fctid, size_t n, const double (*p)[3])
{
    gks_pipe_src s = { NULL, NULL, p };
    report(fctid, gks_pipe_area(fctid, NULL, 1, &n, &s, 0));
}
