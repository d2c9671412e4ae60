/* SPDX-License-Identifier: MIT */
/*
 * test_metafile.c -- the GKS metafile workstations (MO, MI): round trips (a scene drawn on
 * a PNG workstation directly and the same scene written to a metafile, then interpreted
 * onto a PNG workstation, give identical pixels: no tolerance, the interpreter performs
 * the same functions with the same NDC3 coordinates, reals round-trip exactly), user
 * items, every metafile error number (160..167 and the workstation category errors), and
 * hostile metafiles (truncated at every length, wrong lengths, absurd counts, garbage)
 * which must give errors and never crash. The metafiles written here (mf_*.gksm in the
 * build directory) are the seed corpus of the MI fuzz target (tests/fuzz/corpus_mi).
 */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <cmocka.h>
#include "core_util.h"
#include "item_util.h"
#include "png_util.h"

enum { WS_OUT = 1, WS_MO = 2, WS_MI = 3, WS_NULL = 4 };

static void spit(const char *path, const char *buf, size_t n);

/* ---------------------------------------------------------------- scenes */
typedef void (*scene_fn)(Gint ws);

static void scene_2d(Gint ws)
{
    static Gpoint zig[6] = { { 0.05, 0.9 }, { 0.2, 0.97 }, { 0.35, 0.88 },
                             { 0.5, 0.97 }, { 0.65, 0.9 }, { 1.4, 0.95 } };
    static Gpoint tri[3] = { { 0.05, 0.05 }, { 0.3, 0.05 }, { 0.17, 0.3 } };
    static Gpoint sq[4] = { { 0.35, 0.05 }, { 0.6, 0.05 }, { 0.6, 0.3 }, { 0.35, 0.3 } };
    static Gpoint hex[4] = { { 0.65, 0.05 }, { 0.95, 0.05 }, { 0.95, 0.3 }, { 0.65, 0.3 } };
    static Gpoint outer[4] = { { 0.05, 0.4 }, { 0.4, 0.4 }, { 0.4, 0.7 }, { 0.05, 0.7 } };
    static Gpoint hole[3] = { { 0.1, 0.45 }, { 0.3, 0.45 }, { 0.2, 0.65 } };
    static Gpoint mk[4] = { { 0.5, 0.75 }, { 0.6, 0.75 }, { 0.7, 0.75 }, { 0.8, 0.75 } };
    static Gint cells[6] = { 1, 2, 3, 4, 5, 6 }, pat[4] = { 2, 3, 4, 1 };
    Gcolr_rep c2 = { { 1, 0, 0 } }, c3 = { { 0, 0.6, 0 } }, c4 = { { 0, 0, 1 } },
              c5 = { { 0.9, 0.8, 0.1 } }, c6 = { { 0.3, 0.3, 0.3 } };
    Gint ss[2] = { ws, 2 }; /* anti-aliasing by 2 x 2 supersampling */
    gescape(GESC_PNG_SUPERSAMPLE, &(Gescape_in_data){ { 2, ss, 0, NULL, 0, NULL } }, NULL, NULL);
    gset_ws_win(ws, &(Glimit){ 0, 1, 0, 0.98 });
    gset_ws_vp(ws, &(Glimit){ 0, 1000, 0, 980 });
    gset_colr_rep(ws, 2, &c2);
    gset_colr_rep(ws, 3, &c3);
    gset_colr_rep(ws, 4, &c4);
    gset_colr_rep(ws, 5, &c5);
    gset_colr_rep(ws, 6, &c6);
    gset_line_rep(ws, 2, &(Gline_bundle){ 2, 3.0, 4 });
    gset_fill_rep(ws, 3, &(Gfill_bundle){ GSTYLE_HATCH, -3, 2 });
    gset_pat_rep(ws, 1, &(Gpat_rep){ { 2, 2 }, pat });
    gset_edge_rep(ws, 2, &(Gedge_bundle){ GEDGE_ON, 3, 2.0, 2 });

    /* a non-uniform normalization: window aspect differs from the viewport's */
    gset_win(1, &(Glimit){ 0, 2, 0, 1 });
    gset_vp(1, &(Glimit){ 0.02, 0.98, 0.02, 0.9 });
    gsel_norm_tran(1);
    gset_linetype(2);
    gset_linewidth(2.5);
    gset_line_colr_ind(2);
    Gpoint zz[6];
    for (int i = 0; i < 6; i++)
        zz[i] = (Gpoint){ 2 * zig[i].x, zig[i].y }; /* the last point leaves the viewport */
    gpolyline(&(Gpoint_list){ 6, zz });
    gsel_norm_tran(0);

    gset_marker_type(4);
    gset_marker_size(3);
    gset_marker_colr_ind(3);
    gpolymarker(&(Gpoint_list){ 4, mk });
    /* a non-finite point breaks a polyline and drops a marker, on both paths */
    Gpoint broken[5] = { { 0.05, 0.8 }, { 0.2, 0.85 }, { NAN, 0.5 }, { 0.3, 0.8 },
                         { 0.45, 0.85 } };
    gpolyline(&(Gpoint_list){ 5, broken });
    gpolymarker(&(Gpoint_list){ 5, broken });

    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(4);
    gfill_area(&(Gpoint_list){ 3, tri });
    gset_fill_int_style(GSTYLE_PAT);
    gset_fill_style_ind(1);
    gset_pat_size(0.05, 0.04);
    gset_pat_ref_point(&(Gpoint){ 0.35, 0.05 });
    gfill_area(&(Gpoint_list){ 4, sq });
    gset_fill_ind(3);
    gset_asfs(&(Gasfs){ GASF_BUNDLED, GASF_BUNDLED, GASF_BUNDLED, GASF_INDIV, GASF_INDIV,
                        GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV,
                        GASF_BUNDLED, GASF_BUNDLED, GASF_BUNDLED });
    gfill_area(&(Gpoint_list){ 4, hex });
    gset_line_ind(2);
    gpolyline(&(Gpoint_list){ 3, tri });
    gset_asfs(&(Gasfs){ GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV,
                        GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV, GASF_INDIV,
                        GASF_INDIV, GASF_INDIV, GASF_INDIV });

    Gpoint_list loops[2] = { { 4, outer }, { 3, hole } };
    gset_fill_int_style(GSTYLE_HOLLOW);
    gset_fill_colr_ind(5);
    gset_edge_flag(GEDGE_ON);
    gset_edgetype(4);
    gset_edgewidth(2);
    gset_edge_colr_ind(6);
    gfill_area_set(&(Gpoint_list_list){ 2, loops });

    gset_text_font_prec(&(Gtext_font_prec){ 1, GPREC_STROKE });
    gset_char_ht(0.04);
    gset_char_up_vec(&(Gvec){ -0.3, 1 });
    gset_char_expan(1.3);
    gset_char_space(0.2);
    gset_text_colr_ind(2);
    gset_text_align(&(Gtext_align){ GHOR_CTR, GVERT_HALF });
    gtext(&(Gpoint){ 0.7, 0.55 }, "GKSM 3D");
    gset_text_path(GPATH_DOWN);
    gtext(&(Gpoint){ 0.93, 0.7 }, "Up");

    gset_clip_ind(GIND_NO_CLIP);
    gcell_array(&(Grect){ { 0.45, 0.4 }, { 0.6, 0.5 } }, &(Gpat_rep){ { 3, 2 }, cells });
    gupd_ws(ws, GFLAG_PERFORM);
}

static void scene_segments(Gint ws)
{
    static Gpoint a[4] = { { 0.1, 0.1 }, { 0.4, 0.1 }, { 0.4, 0.4 }, { 0.1, 0.4 } };
    static Gpoint b[3] = { { 0.5, 0.5 }, { 0.9, 0.5 }, { 0.7, 0.9 } };
    Gcolr_rep red = { { 1, 0, 0 } }, blue = { { 0, 0, 1 } };
    gset_colr_rep(ws, 2, &red);
    gset_colr_rep(ws, 3, &blue);
    gset_fill_int_style(GSTYLE_SOLID);
    gcreate_seg(1);
    gset_fill_colr_ind(2);
    gfill_area(&(Gpoint_list){ 4, a });
    gclose_seg();
    gcreate_seg(2);
    gset_fill_colr_ind(3);
    gfill_area(&(Gpoint_list){ 3, b });
    gset_linewidth(3);
    gpolyline(&(Gpoint_list){ 3, b });
    gclose_seg();
    gset_seg_pri(1, 0.9);
    const Gtran_matrix m = { { 1, 0, 0.25 }, { 0, 1, 0.25 } };
    gset_seg_tran(1, m);          /* moves segment 1 over segment 2 (higher priority) */
    gcreate_seg(3);
    gfill_area(&(Gpoint_list){ 3, b });
    gclose_seg();
    gset_vis(3, GSEG_INVIS);
    grename_seg(3, 4);
    gset_highl(2, GSEG_HIGHL);
    gset_det(2, GSEG_DET);
    gcreate_seg(5);
    gpolyline(&(Gpoint_list){ 4, a });
    gclose_seg();
    gdel_seg(5);
    gredraw_all_seg_ws(ws);
}

static void scene_3d(Gint ws)
{
    static Gpoint3 cube_front[4] = { { 0.3, 0.3, 0.7 }, { 0.7, 0.3, 0.7 }, { 0.7, 0.7, 0.7 },
                                     { 0.3, 0.7, 0.7 } };
    static Gpoint3 cube_back[4] = { { 0.2, 0.2, 0.2 }, { 0.6, 0.2, 0.2 }, { 0.6, 0.8, 0.4 },
                                    { 0.2, 0.8, 0.4 } };
    static Gpoint3 line[3] = { { 0.1, 0.1, 0.1 }, { 0.9, 0.5, 0.9 }, { 0.1, 0.9, 0.5 } };
    static Gint cells[4] = { 2, 3, 3, 2 };
    Gcolr_rep red = { { 1, 0, 0 } }, green = { { 0, 0.7, 0 } };
    gset_ws_win3(ws, &(Glimit3){ 0.05, 0.95, 0.05, 0.95, 0, 1 });
    gset_ws_vp3(ws, &(Glimit3){ 10, 1000, 10, 1000, 0, 1 });
    gset_colr_rep(ws, 2, &red);
    gset_colr_rep(ws, 3, &green);
    Gview_rep3 v;
    Gint err;
    Gmatrix3 ori, map;
    geval_view_ori_matrix3(&(Gpoint3){ 0.5, 0.5, 0.5 }, &(Gvec3){ 0.3, 0.4, 1 },
                           &(Gvec3){ 0, 1, 0 }, GCOORD_NDC, &err, ori);
    Gview_map3 vm = { { -0.7, 0.7, -0.7, 0.7 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PERSPECT,
                      { 0, 0, 3 }, 0, -1, 1 };
    geval_view_map_matrix3(&vm, &err, map);
    memcpy(v.ori_matrix, ori, sizeof ori);
    memcpy(v.map_matrix, map, sizeof map);
    v.clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
    v.xy_clip = GIND_CLIP;
    v.back_clip = v.front_clip = GIND_NO_CLIP;
    gset_view_rep3(ws, 1, &v);
    gset_hlhsr_mode(ws, GHLHSR_ZBUFFER);
    gset_view_ind(1);
    gset_hlhsr_id(1);
    gset_win3(1, &(Glimit3){ 0, 1, 0, 1, 0, 1 });
    gset_vp3(1, &(Glimit3){ 0.05, 0.95, 0.05, 0.95, 0.1, 0.9 });
    gsel_norm_tran(1);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gfill_area3(&(Gpoint_list3){ 4, cube_back });
    gset_fill_colr_ind(3);
    gset_pat_ref_point_vecs(&(Gpoint3){ 0, 0, 0 }, (Gvec3[2]){ { 1, 0, 0 }, { 0, 1, 0.5 } });
    gfill_area3(&(Gpoint_list3){ 4, cube_front });
    gset_line_colr_ind(1);
    gpolyline3(&(Gpoint_list3){ 3, line });
    gpolymarker3(&(Gpoint_list3){ 3, line });
    Gpoint_list3 l3[1] = { { 4, cube_front } };
    gset_edge_flag(GEDGE_ON);
    gfill_area_set3(&(Gpoint_list_list3){ 1, l3 });
    gset_char_ht(0.05);
    gtext3(&(Gpoint3){ 0.2, 0.1, 0.5 }, (Gvec3[2]){ { 1, 0, -0.5 }, { 0, 1, 0 } }, "3D text");
    gcell_array3(&(Gparal){ { 0.6, 0.1, 0.3 }, { 0.9, 0.3, 0.6 }, { 0.9, 0.1, 0.6 } },
                 &(Gpat_rep){ { 2, 2 }, cells });
    const Gtran_matrix3 st = { { 0.5, 0, 0, 0.1 }, { 0, 0.5, 0, 0.1 }, { 0, 0, 0.5, 0 } };
    gcreate_seg(7);
    gset_seg_tran3(7, st);
    gfill_area3(&(Gpoint_list3){ 4, cube_front });
    gclose_seg();
}

static void scene_light(Gint ws)
{
    static Gpoint3 floor_[4] = { { 0.1, 0.1, 0.2 }, { 0.9, 0.1, 0.2 }, { 0.9, 0.9, 0.6 },
                                 { 0.1, 0.9, 0.6 } };
    static Gpoint3 wall[3] = { { 0.2, 0.2, 0.5 }, { 0.7, 0.3, 0.8 }, { 0.4, 0.8, 0.7 } };
    Gcolr_rep c = { { 0.8, 0.5, 0.2 } };
    gset_colr_rep(ws, 2, &c);
    gset_hlhsr_mode(ws, GHLHSR_RAYTRACE);
    Glight_src_rep l2 = { GLIGHT_POSITIONAL, { 1, 1, 0.9 }, { 0.5, 0.5, 2 }, { 0, 0, -1 },
                          { 1, 0.1 }, 1, 1 };
    Glight_src_rep l3 = { GLIGHT_DIRECTIONAL, { 0.3, 0.3, 0.6 }, { 0, 0, 0 }, { -1, -1, -1 },
                          { 1, 0 }, 1, 1 };
    gset_light_src_rep(ws, 2, &l2);
    gset_light_src_rep(ws, 3, &l3);
    gset_light_src_state(&(Gint_list){ 2, (Gint[]){ 2, 3 } }, NULL);
    gset_refl_eq(GREFL_AMB_DIFF_SPEC);
    gset_back_refl_eq(GREFL_AMB_DIFF);
    gset_area_props(&(Garea_props){ 0.2, 0.7, 0.5, { 1, 1, 1 }, 20, 0, 1 });
    gset_back_area_props(&(Garea_props){ 0.3, 0.5, 0, { 1, 1, 1 }, 1, 0, 1.5 });
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gfill_area3(&(Gpoint_list3){ 4, floor_ });
    gset_area_props(&(Garea_props){ 0.1, 0.3, 0.9, { 1, 1, 1 }, 50, 0.3, 1.3 });
    gfill_area3(&(Gpoint_list3){ 3, wall });
}

/* Every primitive with data, each flag combination's kind, colours by index and RGB, under
 * a non-uniform normalization, partly clipped at the viewport, some in a segment with a
 * non-uniform segment transformation; z-buffer, colour interpolation in front. */
static void scene_data(Gint ws)
{
    Glimit3 w = { 0, 2, 0, 1, 0, 1 }, v = { 0.05, 0.95, 0.05, 0.95, 0, 1 };
    gset_win3(1, &w);
    gset_vp3(1, &v);
    gsel_norm_tran(1);
    gset_hlhsr_mode(ws, GHLHSR_ZBUFFER);
    Gcolr_rep c2 = { { 0.8, 0.3, 0.1 } }, c3 = { { 0.1, 0.6, 0.9 } };
    gset_colr_rep(ws, 2, &c2);
    gset_colr_rep(ws, 3, &c3);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_int_shad_meth(GSHAD_COLR);
    gset_back_int_shad_meth(GSHAD_NORM);
    /* FILL AREA 3 WITH DATA: vertex RGB and normals, a facet normal; crosses x = 2. */
    Gpoint3 p1[3] = { { 0.1, 0.1, 0.5 }, { 2.4, 0.2, 0.5 }, { 0.5, 0.5, 0.6 } };
    Gcoval c1[3] = { { .rgb = { 1, 0, 0 } }, { .rgb = { 0, 1, 0 } }, { .rgb = { 0, 0, 1 } } };
    Gvec3 n1[3] = { { 0, 0, 1 }, { 0.3, 0, 1 }, { 0, 0.3, 1 } };
    Gfacet_data3 f1 = { .norm = { 0, 0, 1 } };
    gfill_area3_data(GFACET_NORM, GVERT_COORD_COLR_NORM, GCOLR_RGB, &f1,
                     &(Gfacet_vdata3){ 3, p1, c1, n1 });
    /* FILL AREA SET 3 WITH DATA: a square with a hole, vertex colour indices, facet colour. */
    Gpoint3 outer[4] = { { 1.0, 0.55, 0.3 }, { 1.9, 0.55, 0.3 }, { 1.9, 0.95, 0.3 },
                         { 1.0, 0.95, 0.3 } };
    Gpoint3 hole[3] = { { 1.2, 0.6, 0.3 }, { 1.6, 0.6, 0.3 }, { 1.4, 0.8, 0.3 } };
    Gcoval ci4[4] = { { .ind = 2 }, { .ind = 3 }, { .ind = 1 }, { .ind = 2 } };
    Gcoval ci3[3] = { { .ind = 3 }, { .ind = 3 }, { .ind = 2 } };
    Gfacet_vdata3 loops[2] = { { 4, outer, ci4, NULL }, { 3, hole, ci3, NULL } };
    Gfacet_data3 f2 = { .colr = { .ind = 3 } };
    gset_edge_flag(GEDGE_ON);
    gfill_area_set3_data(GFACET_COLR, GVERT_COORD_COLR, GCOLR_INDIRECT, &f2, 2, loops);
    gset_edge_flag(GEDGE_OFF);
    /* TRIANGLE STRIP 3 WITH DATA: facet RGB colours and normals. */
    Gpoint3 ps[6] = { { 0.1, 0.6, 0.2 }, { 0.2, 0.95, 0.25 }, { 0.35, 0.6, 0.3 },
                      { 0.45, 0.95, 0.35 }, { 0.6, 0.6, 0.4 }, { 0.7, 0.95, 0.45 } };
    Gfacet_data3 fs[4] = { { .colr = { .rgb = { 1, 1, 0 } }, .norm = { 0, 0, 1 } },
                           { .colr = { .rgb = { 0, 1, 1 } }, .norm = { 0, 1, 1 } },
                           { .colr = { .rgb = { 1, 0, 1 } }, .norm = { 1, 0, 1 } },
                           { .colr = { .rgb = { 0.5, 0.5, 0.5 } }, .norm = { 0, 0, -1 } } };
    gtri_strip3_data(GFACET_COLR_NORM, GVERT_COORD, GCOLR_RGB, fs,
                     &(Gfacet_vdata3){ 6, ps, NULL, NULL });
    /* In a segment with a non-uniform transformation: QUADRILATERAL MESH 3 WITH DATA
     * (vertex normals, vertex colour indices) and SET OF FILL AREA SET 3 WITH DATA. */
    gcreate_seg(7);
    Gpoint3 pm[12];
    Gvec3 nm[12];
    Gcoval cm[12];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            pm[j * 4 + i] = (Gpoint3){ 0.9 + 0.15 * i, 0.1 + 0.12 * j, 0.4 + 0.05 * i * j };
            nm[j * 4 + i] = (Gvec3){ 0.2 * i - 0.3, 0.1 * j, 1 };
            cm[j * 4 + i].ind = 1 + (i + j) % 3;
        }
    gquad_mesh3_data(GFACET_NONE, GVERT_COORD_COLR_NORM, GCOLR_INDIRECT, &(Gint_size){ 4, 3 },
                     NULL, &(Gfacet_vdata3){ 12, pm, cm, nm });
    Gpoint3 pv[5] = { { 1.5, 0.1, 0.7 }, { 1.9, 0.1, 0.7 }, { 1.9, 0.45, 0.7 },
                      { 1.5, 0.45, 0.7 }, { 1.7, 0.3, 0.9 } };
    Gint a0[3] = { 0, 1, 4 }, a1[3] = { 1, 2, 4 }, a2[4] = { 2, 3, 0, 4 };
    Gint_list l0[1] = { { 3, a0 } }, l1[2] = { { 3, a1 }, { 4, a2 } };
    Gint_list_list sets[2] = { { 1, l0 }, { 2, l1 } };
    Gfacet_data3 fo[2] = { { .norm = { 0, -1, 1 } }, { .norm = { 1, 1, 1 } } };
    Gcoval co[5] = { { .rgb = { 1, 0.5, 0 } }, { .rgb = { 0, 0.5, 1 } }, { .rgb = { 1, 1, 1 } },
                     { .rgb = { 0.2, 0.2, 0.2 } }, { .rgb = { 0, 1, 0 } } };
    gset_of_fill_area_set3_data(GFACET_NORM, GVERT_COORD_COLR, GCOLR_RGB, 2, fo, sets,
                                &(Gfacet_vdata3){ 5, pv, co, NULL });
    gclose_seg();
    Gtran_matrix3 m = { { 1.2, 0, 0, -0.1 }, { 0, 0.6, 0, 0.05 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(7, m);
}

/* ---------------------------------------------------------------- helpers */
static void open_all(void)
{
    reset_gks();
    gopen_gks(NULL, 0);
    capture_reset();
}

/* Interprets every item of the MI onto the active workstations; returns the number of
 * items, stopping at the END item or at an error (*last_err). */
static int interpret_all(Gint mi, int *last_err)
{
    int items = 0;
    *last_err = 0;
    char *buf = NULL;
    for (;;) {
        Gint type = -1, len = -1;
        int before = n_captured;
        gget_item_type(mi, &type, &len);
        if (n_captured != before) {
            *last_err = captured[before].err;
            break;
        }
        buf = realloc(buf, (size_t)len + 1);
        gread_item(mi, len, ITEMN(buf, len));
        if (n_captured != before) {
            *last_err = captured[before].err;
            break;
        }
        items++;
        if (type == 0)
            break;
        if (type > 100)
            continue;
        ginterpret_item(type, len, ITEMN(buf, len));
    }
    free(buf);
    return items;
}

static void draw_direct(scene_fn f, const char *png)
{
    open_all();
    gopen_ws(WS_OUT, png, GWS_TYPE_PNG);
    gactivate_ws(WS_OUT);
    f(WS_OUT);
    gdeactivate_ws(WS_OUT);
    gclose_ws(WS_OUT);
    assert_int_equal(n_captured, 0);
    gclose_gks();
}

static void draw_metafile(scene_fn f, const char *gksm)
{
    open_all();
    gopen_ws(WS_MO, gksm, GWS_TYPE_MO);
    gactivate_ws(WS_MO);
    f(WS_MO);
    gdeactivate_ws(WS_MO);
    gclose_ws(WS_MO);
    assert_int_equal(n_captured, 0);
    gclose_gks();
}

static int interpret_file(const char *gksm, const char *png)
{
    open_all();
    gopen_ws(WS_OUT, png, GWS_TYPE_PNG);
    gactivate_ws(WS_OUT);
    gopen_ws(WS_MI, gksm, GWS_TYPE_MI);
    assert_int_equal(n_captured, 0);
    int err, items = interpret_all(WS_MI, &err);
    assert_int_equal(err, 0);
    assert_int_equal(n_captured, 0);
    gclose_ws(WS_MI);
    gdeactivate_ws(WS_OUT);
    gclose_ws(WS_OUT);
    gclose_gks();
    return items;
}

static void assert_same_png(const char *a, const char *b)
{
    image x, y;
    assert_true(read_png(a, &x));
    assert_true(read_png(b, &y));
    assert_int_equal(x.w, y.w);
    assert_int_equal(x.h, y.h);
    size_t n = (size_t)x.w * (size_t)x.h * 3, diff = 0, ink = 0;
    for (size_t i = 0; i < n; i++) {
        diff += x.rgb[i] != y.rgb[i];
        ink += x.rgb[i] != 255;
    }
    free(x.rgb);
    free(y.rgb);
    assert_true(ink > 1000); /* the scene drew something */
    if (diff)
        fail_msg("%s and %s differ in %zu samples", a, b, diff);
}

static void round_trip(scene_fn f, const char *name)
{
    char png_d[64], png_m[64], gksm[64];
    snprintf(png_d, sizeof png_d, "mf_%s_direct.png", name);
    snprintf(png_m, sizeof png_m, "mf_%s_meta.png", name);
    snprintf(gksm, sizeof gksm, "mf_%s.gksm", name);
    draw_direct(f, png_d);
    draw_metafile(f, gksm);
    int items = interpret_file(gksm, png_m);
    assert_true(items > 10);
    assert_same_png(png_d, png_m);
}

static void test_round_trip_2d(void **u) { (void)u; round_trip(scene_2d, "2d"); }
static void test_round_trip_segments(void **u) { (void)u; round_trip(scene_segments, "seg"); }
static void test_round_trip_3d(void **u) { (void)u; round_trip(scene_3d, "3d"); }
static void test_round_trip_light(void **u) { (void)u; round_trip(scene_light, "light"); }
static void test_round_trip_data(void **u) { (void)u; round_trip(scene_data, "data"); }

/* The items of the primitives with data (and shading methods) of a metafile, in order:
 * type and record characters, one string per item. */
static int data_items(const char *gksm, char **out, int max)
{
    gopen_ws(WS_MI, gksm, GWS_TYPE_MI);
    int n = 0;
    for (;;) {
        Gint type = -1, len = -1;
        gget_item_type(WS_MI, &type, &len);
        if (n_captured || type == 0)
            break;
        char *buf = calloc((size_t)len + 8, 1);
        gread_item(WS_MI, len, ITEMN(buf + 4, len));
        if ((type >= 76 && type <= 80) || type == 86) {
            snprintf(buf, 4, "%03d", type);
            buf[3] = ':';
            if (n < max)
                out[n++] = buf;
            else
                free(buf);
        } else {
            free(buf);
        }
    }
    gclose_ws(WS_MI);
    return n;
}

/* Interpreting a metafile onto an MO writes the same primitive-with-data items again. */
static void test_data_items_equal(void **u)
{
    (void)u;
    draw_metafile(scene_data, "mf_data_a.gksm");
    open_all();
    gopen_ws(WS_MO, "mf_data_b.gksm", GWS_TYPE_MO);
    gactivate_ws(WS_MO);
    gopen_ws(WS_MI, "mf_data_a.gksm", GWS_TYPE_MI);
    int err, items = interpret_all(WS_MI, &err);
    assert_int_equal(err, 0);
    assert_true(items > 10);
    gclose_ws(WS_MI);
    gdeactivate_ws(WS_MO);
    gclose_ws(WS_MO);
    assert_int_equal(n_captured, 0);
    char *a[64], *b[64];
    int na = data_items("mf_data_a.gksm", a, 64), nb = data_items("mf_data_b.gksm", b, 64);
    assert_int_equal(n_captured, 0);
    assert_int_equal(na, nb);
    assert_true(na >= 7); /* 5 primitives, 2 shading methods */
    int kinds = 0;
    for (int i = 0; i < na; i++) {
        if (strcmp(a[i], b[i]))
            fail_msg("item %d differs:\n%.80s\n%.80s", i, a[i], b[i]);
        kinds |= 1 << (atoi(a[i]) - 76);
        free(a[i]);
        free(b[i]);
    }
    assert_int_equal(kinds & 0x1f, 0x1f);
    gclose_gks();
}

/* A metafile in RAL GKS's own field widths (H=1, T=3, L=7, I=4, R=9, reals F9.6) with RAL's
 * 2-D items draws what the same functions draw directly in NDC (transformation 0). */
static void scene_ral_direct(Gint ws)
{
    static Gpoint l[3] = { { 0.125, 0.25 }, { 0.875, 0.5 }, { 0.25, 0.75 } };
    static Gpoint a[3] = { { 0.5, 0.125 }, { 0.75, 0.125 }, { 0.625, 0.375 } };
    gset_colr_rep(ws, 2, &(Gcolr_rep){ { 1, 0, 0 } });
    gset_linetype(2);
    gset_linewidth(3);
    gset_line_colr_ind(2);
    gpolyline(&(Gpoint_list){ 3, l });
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gfill_area(&(Gpoint_list){ 3, a });
}

static void test_ral_items(void **u)
{
    (void)u;
    static const char *items[] = {
        "G 56     31   2 1.000000 0.000000 0.000000",
        "G 22      4   2", "G 23      9 3.000000", "G 24      4   2",
        "G 11     58   3 0.125000 0.250000 0.875000 0.500000 0.250000 0.750000",
        "G 38      4   1", "G 40      4   2",
        "G 61     36 0.000000 1.000000 0.000000 1.000000",
        "G 14     58   3 0.500000 0.125000 0.750000 0.125000 0.625000 0.375000",
        "G  0      0",
    };
    char buf[1024];
    int n = snprintf(buf, sizeof buf, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d",
                     "RAL", "26/11/24", 1, 1, 3, 7, 4, 9, 1, 1, 0, 1);
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++)
        n += snprintf(buf + n, sizeof buf - (size_t)n, "%s", items[i]);
    spit("mf_ral.gksm", buf, (size_t)n);
    draw_direct(scene_ral_direct, "mf_ral_direct.png");
    assert_int_equal(interpret_file("mf_ral.gksm", "mf_ral_meta.png"), 10);
    assert_same_png("mf_ral_direct.png", "mf_ral_meta.png");
}

/* ---------------------------------------------------------------- file contents */
static char *slurp(const char *path, size_t *n)
{
    FILE *fp = fopen(path, "rb");
    assert_non_null(fp);
    char *buf = NULL;
    size_t cap = 0;
    *n = 0;
    for (;;) {
        if (*n == cap) {
            cap = cap ? 2 * cap : 4096;
            buf = realloc(buf, cap + 1);
            assert_non_null(buf);
        }
        size_t k = fread(buf + *n, 1, cap - *n, fp);
        if (!k)
            break;
        *n += k;
    }
    fclose(fp);
    buf[*n] = '\0';
    return buf;
}

static void spit(const char *path, const char *buf, size_t n)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    assert_int_equal(fwrite(buf, 1, n, fp), n);
    fclose(fp);
}

/* Header, one polyline with its attribute items, END; nothing while the MO is inactive. */
static void test_mo_layout(void **u)
{
    (void)u;
    open_all();
    gopen_ws(WS_MO, "mf_layout.gksm", GWS_TYPE_MO);
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gactivate_ws(WS_NULL);
    static Gpoint p[2] = { { 0.25, 0.5 }, { 0.75, 0.5 } };
    gpolyline(&(Gpoint_list){ 2, p }); /* MO open but not active: not recorded */
    gactivate_ws(WS_MO);
    gset_linetype(3);
    gpolyline(&(Gpoint_list){ 2, p });
    gdeactivate_ws(WS_MO);
    gclose_ws(WS_MO);
    assert_int_equal(n_captured, 0);
    gclose_gks();
    size_t n;
    char *s = slurp("mf_layout.gksm", &n);
    assert_true(n > 90);
    assert_memory_equal(s, "GKSM", 4);
    assert_memory_equal(s + 52, " 1 4 3101124 1 1", 16); /* V H T L I R F RI */
    /* one POLYLINE 3 item of 2 points (11 + 6 * 24 characters) */
    const char *pl = strstr(s, "GKSM 17       155");
    assert_non_null(pl);
    assert_null(strstr(pl + 1, "GKSM 17"));
    assert_non_null(strstr(pl, "2.5000000000000000e-01"));
    assert_non_null(strstr(s, "GKSM 22        11          3")); /* LINETYPE 3 */
    assert_memory_equal(s + n - 17, "GKSM  0         0", 17);  /* END */
    free(s);
}

/* WRITE ITEM TO GKSM and reading the user item back. */
static void test_user_items(void **u)
{
    (void)u;
    open_all();
    gopen_ws(WS_MO, "mf_user.gksm", GWS_TYPE_MO);
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gwrite_item(WS_MO, 150, 5, ITEM("hello")); /* no workstation active: state error */
    gactivate_ws(WS_NULL);
    gwrite_item(WS_MO, 150, 5, ITEM("hello")); /* the MO is not active */
    assert_int_equal(n_captured, 2);
    assert_int_equal(captured[0].err, 5);
    assert_int_equal(captured[1].err, 30);
    gactivate_ws(WS_MO);
    capture_reset();
    gwrite_item(WS_NULL, 150, 5, ITEM("hello"));
    gwrite_item(WS_MO, 100, 5, ITEM("hello"));
    gwrite_item(WS_MO, 0, 5, ITEM("hello"));
    gwrite_item(WS_MO, 150, -1, ITEM("hello"));
    gwrite_item(WS_MO, 150, 3, ITEMN(NULL, 0));
    gwrite_item(-1, 150, 3, ITEM("abc"));
    gwrite_item(9, 150, 3, ITEM("abc"));
    assert_int_equal(n_captured, 7);
    const int want[7] = { 32, 160, 160, 161, 161, 20, 25 };
    for (int i = 0; i < 7; i++) {
        assert_int_equal(captured[i].err, want[i]);
        assert_int_equal(captured[i].fct, GFN_WITM);
    }
    capture_reset();
    gwrite_item(WS_MO, 150, 5, ITEM("hello"));
    gwrite_item(WS_MO, 999, 0, ITEM(""));
    gdeactivate_ws(WS_MO);
    gclose_ws(WS_MO);
    gopen_ws(WS_MI, "mf_user.gksm", GWS_TYPE_MI);
    Gint type, len;
    char buf[16] = { 0 };
    gget_item_type(WS_MI, &type, &len);
    assert_int_equal(type, 150);
    assert_int_equal(len, 5);
    gget_item_type(WS_MI, &type, &len); /* the same item again */
    assert_int_equal(type, 150);
    gread_item(WS_MI, 3, RBUF(buf));           /* truncated to 3 characters */
    assert_string_equal(buf, "hel");
    gget_item_type(WS_MI, &type, &len);
    assert_int_equal(type, 999);
    assert_int_equal(len, 0);
    ginterpret_item(150, 5, ITEM("hello"));
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 167);
    assert_int_equal(captured[0].fct, GFN_IITM);
    gread_item(WS_MI, 0, ITEMN(NULL, 0));
    gget_item_type(WS_MI, &type, &len);
    assert_int_equal(type, 0);
    gread_item(WS_MI, 0, ITEMN(NULL, 0));
    capture_reset();
    gget_item_type(WS_MI, &type, &len);
    gread_item(WS_MI, 0, ITEMN(NULL, 0));
    assert_int_equal(n_captured, 2);
    assert_int_equal(captured[0].err, 162);
    assert_int_equal(captured[1].err, 162);
    reset_gks();
}

/* Every other error number of the metafile functions. */
static void test_errors(void **u)
{
    (void)u;
    draw_metafile(scene_segments, "mf_err.gksm");
    open_all();
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gopen_ws(WS_MI, "mf_err.gksm", GWS_TYPE_MI);
    gopen_ws(5, "mf_does_not_exist.gksm", GWS_TYPE_MI);
    gopen_ws(6, "", GWS_TYPE_MO);
    spit("mf_garbage.gksm", "this is not a metafile at all, no no no no", 42);
    gopen_ws(7, "mf_garbage.gksm", GWS_TYPE_MI);
    gactivate_ws(WS_MI);
    assert_int_equal(n_captured, 4);
    assert_int_equal(captured[0].err, 26);
    assert_int_equal(captured[1].err, 21);
    assert_int_equal(captured[2].err, 26);
    assert_int_equal(captured[3].err, 33);
    capture_reset();
    Gint type, len;
    char buf[8];
    gget_item_type(WS_NULL, &type, &len);
    gread_item(WS_NULL, 8, RBUF(buf));
    gread_item(WS_MI, -1, RBUF(buf));
    gread_item(WS_MI, 8, ITEMN(NULL, 0));
    gget_item_type(-3, &type, &len);
    gget_item_type(12, &type, &len);
    const int want[6] = { 34, 34, 166, 166, 20, 25 };
    assert_int_equal(n_captured, 6);
    for (int i = 0; i < 6; i++)
        assert_int_equal(captured[i].err, want[i]);
    capture_reset();
    /* INTERPRET ITEM: 161, 164, 165, 167 (the MI's format: I = 11, R = 24) */
    ginterpret_item(22, -1, ITEM("x"));
    ginterpret_item(22, 4, ITEMN(NULL, 0));
    ginterpret_item(-5, 0, ITEM(""));
    ginterpret_item(10, 0, ITEM(""));
    ginterpret_item(87, 0, ITEM(""));
    ginterpret_item(22, 3, ITEM("abc"));            /* not an integer field */
    ginterpret_item(22, 22, ITEM("          2          3")); /* a field too many */
    ginterpret_item(23, 11, ITEM("          2"));  /* a real field expected */
    ginterpret_item(17, 11, ITEM("  999999999"));  /* absurd count for the record */
    ginterpret_item(17, 11, ITEM("         -4"));
    ginterpret_item(64, 11, ITEM("          7"));  /* clipping volume: record incomplete */
    ginterpret_item(101, 0, ITEM(""));
    const int want2[12] = { 161, 161, 164, 164, 164, 165, 165, 165, 165, 165, 165, 167 };
    assert_int_equal(n_captured, 12);
    for (int i = 0; i < 12; i++) {
        assert_int_equal(captured[i].err, want2[i]);
        assert_int_equal(captured[i].fct, GFN_IITM);
    }
    capture_reset();
    /* an interpreted function reports its own errors: linetype 0 is error 63 */
    ginterpret_item(22, 11, ITEM("          0"));
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 63);
    assert_int_equal(captured[0].fct, GFN_SLN);
    reset_gks();
    /* 163: an item header that is not one */
    size_t n;
    char *s = slurp("mf_err.gksm", &n);
    s[90] = 'X';
    spit("mf_bad_item.gksm", s, n);
    free(s);
    open_all();
    gopen_ws(WS_MI, "mf_bad_item.gksm", GWS_TYPE_MI);
    gget_item_type(WS_MI, &type, &len);
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 163);
    assert_int_equal(captured[0].fct, GFN_GTITM);
    reset_gks();
}

/* Hostile files: every truncation of a real metafile, every single-byte corruption of
 * a sample of its positions, absurd counts in well-formed items. Errors, no crash, and the
 * interpretation ends (no hang). */
static int run_hostile(const char *path)
{
    open_all();
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gactivate_ws(WS_NULL);
    int before = n_captured;
    gopen_ws(WS_MI, path, GWS_TYPE_MI);
    if (n_captured != before)
        return captured[before].err;
    int err;
    interpret_all(WS_MI, &err);
    gemergency_close_gks();
    return err;
}

static void test_hostile(void **u)
{
    (void)u;
    draw_metafile(scene_3d, "mf_hostile_src.gksm");
    size_t n;
    char *s = slurp("mf_hostile_src.gksm", &n);
    int truncations = 0, errors = 0;
    for (size_t k = 0; k < n; k += (k < 200 ? 1 : 37)) {
        spit("mf_hostile.gksm", s, k);
        int e = run_hostile("mf_hostile.gksm");
        truncations++;
        if (k < 90)
            assert_int_equal(e, 26); /* header incomplete: cannot be opened */
        else if (e)
            errors++, assert_true(e == 162 || e == 163);
    }
    assert_true(errors > truncations / 2);
    const char junk[] = { 'X', '9', '-', ' ', '\0', '\n', '.', 'e' };
    for (size_t k = 0; k < n; k += 13) {
        char save = s[k];
        s[k] = junk[k % sizeof junk];
        spit("mf_hostile.gksm", s, n);
        run_hostile("mf_hostile.gksm");
        s[k] = save;
    }
    free(s);
    /* well-formed items with absurd contents */
    static const char *items[] = {
        "GKSM 17        11 999999999",
        "GKSM  9        22          1 2147483647",
        "GKSM  8       238",
        "GKSM 55        33          1      99999      99999",
        "GKSM 70        22          1        999",
        "GKSM  5        11 -999999999",
        "GKSM 43        11          0",
        "GKSM 17 999999999",
        "GKSM 17-9",
        "GKSM999         0",
    };
    char hdr[91];
    snprintf(hdr, sizeof hdr, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", "hostile",
             "26/11/24", 1, 4, 3, 10, 11, 24, 1, 1, 0, 1);
    for (size_t i = 0; i < sizeof items / sizeof items[0]; i++) {
        char buf[256];
        int m = snprintf(buf, sizeof buf, "%s%s", hdr, items[i]);
        spit("mf_hostile.gksm", buf, (size_t)m);
        int e = run_hostile("mf_hostile.gksm");
        assert_true(e == 0 || e == 162 || e == 163);
    }
}

/* The primitives with data from an untrusted file: truncated at many lengths, corrupted,
 * and well-formed items with absurd counts or indices: never a crash nor a leak (the
 * sanitizer build), errors only as the standard's numbers. */
static void test_hostile_data(void **u)
{
    (void)u;
    draw_metafile(scene_data, "mf_hostile_dsrc.gksm");
    size_t n;
    char *s = slurp("mf_hostile_dsrc.gksm", &n);
    for (size_t k = 90; k < n; k += 29) {
        spit("mf_hostile.gksm", s, k);
        int e = run_hostile("mf_hostile.gksm");
        assert_true(e == 0 || e == 162 || e == 163);
    }
    const char junk[] = { 'X', '9', '-', ' ', '\0', '\n', '.', 'e', '7' };
    for (size_t k = 90; k < n; k += 17) {
        char save = s[k];
        s[k] = junk[k % sizeof junk];
        spit("mf_hostile.gksm", s, n);
        run_hostile("mf_hostile.gksm");
        s[k] = save;
    }
    free(s);
    /* Records of item 76..80: header ints (then as many fields as given). */
    static const long recs[][12] = {
        { 7, 0, 0, 0, 2147483647, 1, 1, 3 },        /* vertices beyond the record */
        { 7, 0, 0, 0, 3, 1, 1, -3 },                /* negative count */
        { 7, 9, 0, 0, 3, 1, 1, 3 },                 /* facet flag out of range */
        { 7, 0, 0, 0, 3, 2147483647, 2147483647, 2147483647 },
        { 10, 0, 0, 0, 3, 1, 1, 3, 1, 3, 0 },       /* record incomplete */
    };
    char hdr[91];
    snprintf(hdr, sizeof hdr, "GKSM%-40s%-8s%2d%2d%2d%2d%2d%2d%2d%2d%11d%11d", "hostile",
             "26/11/24", 1, 4, 3, 10, 11, 24, 1, 1, 0, 1);
    for (int item = 76; item <= 80; item++)
        for (size_t i = 0; i < sizeof recs / sizeof recs[0]; i++) {
            char buf[512];
            int nf = (int)recs[i][0], m = snprintf(buf, sizeof buf, "%sGKSM%3d%10d", hdr, item,
                                                   11 * nf);
            for (int f = 1; f <= nf; f++)
                m += snprintf(buf + m, sizeof buf - (size_t)m, "%11ld", recs[i][f]);
            spit("mf_hostile.gksm", buf, (size_t)m);
            int e = run_hostile("mf_hostile.gksm");
            assert_true(e == 0 || e == 162 || e == 163);
        }
    /* A well-formed triangle whose index is out of range: 904 of the function performed. */
    open_all();
    gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
    gactivate_ws(WS_NULL);
    char rec[512];
    int m = 0;
    const long ints[10] = { 0, 0, 0, 3, 1, 1, 3, 1, 3, 0 };
    for (int f = 0; f < 10; f++)
        m += snprintf(rec + m, sizeof rec - (size_t)m, "%11ld", ints[f]);
    const long idx[3] = { 0, 1, 5 };
    m -= 11; /* replace the last index field and add the other two */
    for (int f = 0; f < 3; f++)
        m += snprintf(rec + m, sizeof rec - (size_t)m, "%11ld", idx[f]);
    for (int p = 0; p < 9; p++)
        m += snprintf(rec + m, sizeof rec - (size_t)m, "%24.16e", 0.25 * (p % 4));
    capture_reset();
    ginterpret_item(76, m, ITEMN(rec, m));
    assert_int_equal(n_captured, 1);
    assert_int_equal(captured[0].err, 904);
    assert_int_equal(captured[0].fct, GFN_FA3D);
    gemergency_close_gks();
}

void gks_alloc_fail_after(long n); /* test hook of gks_alloc.c */

/* Fail the 1st, 2nd, ... allocation while writing and while interpreting a metafile:
 * error 300 is reported (not a crash; leaks would fail the sanitizer build), until the
 * run needs no failing allocation at all. */
static void test_storage_overflow(void **u)
{
    (void)u;
    int saw300 = 0, clean = 0;
    for (long k = 1; k < 400 && !clean; k += 2) {
        open_all();
        gopen_ws(WS_MO, "mf_nomem.gksm", GWS_TYPE_MO);
        gactivate_ws(WS_MO);
        gks_alloc_fail_after(k);
        scene_3d(WS_MO);
        gks_alloc_fail_after(0);
        clean = n_captured == 0;
        for (int i = 0; i < n_captured && i < MAX_CAPTURED; i++)
            saw300 += captured[i].err == 300;
        reset_gks();
    }
    assert_true(clean);
    draw_metafile(scene_3d, "mf_nomem.gksm");
    clean = 0;
    for (long k = 1; k < 2000 && !clean; k += 7) {
        open_all();
        gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
        gactivate_ws(WS_NULL);
        gopen_ws(WS_MI, "mf_nomem.gksm", GWS_TYPE_MI);
        gks_alloc_fail_after(k);
        int err;
        interpret_all(WS_MI, &err);
        gks_alloc_fail_after(0);
        clean = 1; /* the null workstation reports 511 (HLHSR mode) in every run */
        for (int i = 0; i < n_captured && i < MAX_CAPTURED; i++) {
            saw300 += captured[i].err == 300;
            clean &= captured[i].err == 511;
        }
        reset_gks();
    }
    assert_true(clean);
    assert_true(saw300 >= 10);
}

/* The primitives with data under storage overflow: every allocation of the data scene
 * (recorded on an MO, stored in a segment, drawn on a null workstation) failed in turn:
 * error 300, never a crash or a leak, until a run needs no failing allocation. */
static void test_storage_overflow_data(void **u)
{
    (void)u;
    int saw300 = 0, clean = 0;
    for (long k = 1; k < 3000 && !clean; k++) {
        open_all();
        gopen_ws(WS_MO, "mf_nomem_d.gksm", GWS_TYPE_MO);
        gactivate_ws(WS_MO);
        gopen_ws(WS_NULL, NULL, GWS_TYPE_NULL);
        gactivate_ws(WS_NULL);
        gks_alloc_fail_after(k);
        scene_data(WS_MO);
        gks_alloc_fail_after(0);
        clean = n_captured == 0;
        for (int i = 0; i < n_captured && i < MAX_CAPTURED; i++)
            saw300 += captured[i].err == 300;
        reset_gks();
    }
    assert_true(clean);
    assert_true(saw300 >= 10);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mo_layout),
        cmocka_unit_test(test_round_trip_2d),
        cmocka_unit_test(test_round_trip_segments),
        cmocka_unit_test(test_round_trip_data),
        cmocka_unit_test(test_data_items_equal),
        cmocka_unit_test(test_hostile_data),
        cmocka_unit_test(test_storage_overflow_data),
        cmocka_unit_test(test_round_trip_3d),
        cmocka_unit_test(test_round_trip_light),
        cmocka_unit_test(test_ral_items),
        cmocka_unit_test(test_user_items),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_storage_overflow),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
