/* SPDX-License-Identifier: MIT */
/*
 * test_state_errors.c -- table-driven: every function of gks_functions.def (GKS_FN rows)
 * is called in every reachable operating state; where the state is not allowed, exactly
 * the standard's state error (1..8) is reported with the function's identification and
 * the state lists are unchanged. A GKS_FN row without a call here fails the build
 * (the call table is indexed by the generated GFN_ enum and checked for holes).
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <cmocka.h>
#include "core_util.h"
#include "item_util.h"

enum { GKSM_TEST_ITEM_LINETYPE = 22 }; /* docs/METAFILE.md */

static const Gpoint pts3[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
static const Gpoint_list list3 = { 3, (Gpoint *)pts3 };
static const Glimit unit = { 0, 1, 0, 1 };

static void c_OPKS(void) { gopen_gks(NULL, 0); }
static void c_CLKS(void) { gclose_gks(); }
static void c_OPWK(void) { gopen_ws(7, NULL, GWS_TYPE_NULL); }
static void c_CLWK(void) { gclose_ws(1); }
static void c_ACWK(void) { gactivate_ws(1); }
static void c_DAWK(void) { gdeactivate_ws(1); }
static void c_CLRWK(void) { gclear_ws(1, GFLAG_ALWAYS); }
static void c_RSGWK(void) { gredraw_all_seg_ws(1); }
static void c_UWK(void) { gupd_ws(1, GFLAG_PERFORM); }
static void c_SDS(void) { gset_defer_st(1, GDEFER_BNIL, GIRG_SUPPR); }
static void c_MSG(void) { gmessage(1, "hello"); }
static void c_ESC(void)
{
    Gint ws = 1;
    Gescape_in_data in = { { 1, &ws, 0, NULL, 1, "x" } };
    gescape(GESC_SET_FILE_NAME, &in, NULL, NULL);
}
static void c_PL(void) { gpolyline(&list3); }
static void c_FA(void) { gfill_area(&list3); }
static void c_SPLCI(void) { gset_line_colr_ind(3); }
static void c_SFACI(void) { gset_fill_colr_ind(3); }
static void c_SCR(void) { Gcolr_rep c = { { 0.5, 0.5, 0.5 } }; gset_colr_rep(1, 3, &c); }
static void c_SWN(void) { Glimit w = { -1, 1, -1, 1 }; gset_win(1, &w); }
static void c_SVP(void) { Glimit v = { 0, 0.5, 0, 0.5 }; gset_vp(1, &v); }
static void c_SELNT(void) { gsel_norm_tran(1); }
static void c_SCLIP(void) { gset_clip_ind(GIND_NO_CLIP); }
static void c_SWKWN(void) { gset_ws_win(1, &unit); }
static void c_SWKVP(void) { Glimit v = { 0, 100, 0, 100 }; gset_ws_vp(1, &v); }

static const Gpoint org = { 0, 0 };
static const Gvec zero = { 0, 0 }, one = { 1, 1 };
static const Gpoint3 org3 = { 0, 0, 0 };
static const Gvec3 zero3 = { 0, 0, 0 }, one3 = { 1, 1, 1 }, vpn3 = { 0, 0, 1 }, vup3 = { 0, 1, 0 };
static void c_EVTM(void) { Gtran_matrix m; geval_tran_matrix(&org, &zero, 0.5, &one, GCOORD_NDC, m); }
static void c_ACTM(void)
{
    Gtran_matrix in = { { 1, 0, 0 }, { 0, 1, 0 } }, m;
    gaccum_tran_matrix(in, &org, &zero, 0.5, &one, GCOORD_NDC, m);
}
static void c_EVTM3(void)
{
    Gtran_matrix3 m;
    geval_tran_matrix3(&org3, &zero3, 0.1, 0.2, 0.3, &one3, GCOORD_NDC, m);
}
static void c_ACTM3(void)
{
    Gtran_matrix3 in = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } }, m;
    gaccum_tran_matrix3(in, &org3, &zero3, 0.1, 0.2, 0.3, &one3, GCOORD_NDC, m);
}
/* The evaluate-view utilities report in their error indicator only (ISO 8805): the
 * wrappers check that ERROR HANDLING was not called and hand the indicator to the table
 * check as if it had been reported. */
static void errind_only(Gint err, int fct, int before)
{
    if (n_captured != before)
        fail_msg("function %d called ERROR HANDLING", fct);
    if (err)
        capture_handler(err, fct, NULL);
}
static void c_EVVWM(void)
{
    Gint err = -1;
    Gmatrix3 m;
    int before = n_captured;
    geval_view_ori_matrix3(&org3, &vpn3, &vup3, GCOORD_NDC, &err, m);
    errind_only(err, GFN_EVVWM, before);
}
static void c_EVPJM(void)
{
    Gint err;
    Gmatrix3 m;
    Gview_map3 v = { { 0, 1, 0, 1 }, { 0, 1, 0, 1, 0, 1 }, GPROJ_PARAL, { 0.5, 0.5, 5 }, 0, 0, 1 };
    int before = n_captured;
    err = -1;
    geval_view_map_matrix3(&v, &err, m);
    errind_only(err, GFN_EVPJM, before);
}

static const Gpoint3 tri3[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
static const Gpoint_list3 list3d = { 3, (Gpoint3 *)tri3 };
static void c_PL3(void) { gpolyline3(&list3d); }
static void c_FA3(void) { gfill_area3(&list3d); }
static void c_SVWI(void) { gset_view_ind(1); }
static void c_SVWR(void)
{
    Gview_rep3 r = { .clip_limit = { 0, 1, 0, 1, 0, 1 } };
    for (int i = 0; i < 4; i++)
        r.ori_matrix[i][i] = r.map_matrix[i][i] = 1;
    gset_view_rep3(1, 1, &r);
}
static void c_SHRM(void) { gset_hlhsr_mode(1, GHLHSR_NONE); }
static void c_SW3(void) { Glimit3 w = { -1, 1, -1, 1, -1, 1 }; gset_win3(1, &w); }
static void c_SV3(void) { Glimit3 v = { 0, 0.5, 0, 0.5, 0, 1 }; gset_vp3(1, &v); }
static const Garea_props props = { 0.2, 0.8, 0.1, { 1, 1, 1 }, 2, 0, 1 };
static void c_SAPR(void) { gset_area_props(&props); }
static void c_SBAPR(void) { gset_back_area_props(&props); }
static void c_SRFEQ(void) { gset_refl_eq(GREFL_AMB_DIFF); }
static void c_SBRFEQ(void) { gset_back_refl_eq(GREFL_AMB_DIFF); }
static const Gpoint3 quad4[4] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.1, 0.9, 0.5 }, { 0.9, 0.9, 0.5 } };
static const Gfacet_vdata3 vd3 = { 3, (Gpoint3 *)tri3, NULL, NULL };
static void c_FA3D(void) { gfill_area3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd3); }
static const Gfacet_vdata3 vd4 = { 4, (Gpoint3 *)quad4, NULL, NULL };
static const Gint_size dim22 = { 2, 2 };
static Gint idx3[3] = { 0, 1, 2 };
static Gint_list loop3 = { 3, idx3 };
static const Gint_list_list set1 = { 1, &loop3 };
static void c_FAS3D(void) { gfill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, 1, &vd3); }
static void c_TS3D(void) { gtri_strip3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, NULL, &vd4); }
static void c_QM3D(void) { gquad_mesh3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, &dim22, NULL, &vd4); }
static void c_SFA3D(void) { gset_of_fill_area_set3_data(GFACET_NONE, GVERT_COORD, GCOLR_INDIRECT, 1, NULL, &set1, &vd3); }
static void c_SISM(void) { gset_int_shad_meth(GSHAD_COLR); }
static void c_SBISM(void) { gset_back_int_shad_meth(GSHAD_NORM); }
static void c_SLSR(void)
{
    Glight_src_rep l = { GLIGHT_DIRECTIONAL, { 1, 1, 1 }, { 0, 0, 0 }, { 0, 0, -1 }, { 1, 0 }, 0, 1 };
    gset_light_src_rep(1, 2, &l);
}
static void c_SLSS(void)
{
    Gint on = 2;
    Gint_list a = { 1, &on };
    gset_light_src_state(&a, NULL);
}

/* Output primitives and attributes (issue 3). */
static const Gpoint_list list1 = { 1, (Gpoint *)pts3 };
static void c_PM(void) { gpolymarker(&list1); }
static void c_TX(void) { Gpoint p = { 0.5, 0.5 }; gtext(&p, "GKS"); }
static void c_CA(void)
{
    Gint c[4] = { 1, 2, 3, 4 };
    Grect r = { { 0.1, 0.1 }, { 0.4, 0.4 } };
    Gpat_rep a = { { 2, 2 }, c };
    gcell_array(&r, &a);
}
static void c_GDP(void) { ggdp(&list3, 1, NULL); }
static void c_SPLI(void) { gset_line_ind(2); }
static void c_SLN(void) { gset_linetype(2); }
static void c_SLWSC(void) { gset_linewidth(2.0); }
static void c_SPMI(void) { gset_marker_ind(2); }
static void c_SMK(void) { gset_marker_type(2); }
static void c_SMKSC(void) { gset_marker_size(2.0); }
static void c_SPMCI(void) { gset_marker_colr_ind(2); }
static void c_STXI(void) { gset_text_ind(2); }
static void c_STXFP(void) { Gtext_font_prec f = { 1, GPREC_STROKE }; gset_text_font_prec(&f); }
static void c_SCHXP(void) { gset_char_expan(2.0); }
static void c_SCHSP(void) { gset_char_space(0.5); }
static void c_STXCI(void) { gset_text_colr_ind(2); }
static void c_SCHH(void) { gset_char_ht(0.05); }
static void c_SCHUP(void) { Gvec u = { 1, 0 }; gset_char_up_vec(&u); }
static void c_STXP(void) { gset_text_path(GPATH_UP); }
static void c_STXAL(void) { Gtext_align a = { GHOR_CTR, GVERT_HALF }; gset_text_align(&a); }
static void c_SFAI(void) { gset_fill_ind(2); }
static void c_SFAIS(void) { gset_fill_int_style(GSTYLE_SOLID); }
static void c_SFASI(void) { gset_fill_style_ind(2); }
static void c_SPA(void) { gset_pat_size(0.1, 0.2); }
static void c_SPARF(void) { Gpoint p = { 0.1, 0.2 }; gset_pat_ref_point(&p); }
static void c_SASF(void) { Gasfs a = { 0 }; gset_asfs(&a); }
static void c_SPKID(void) { gset_pick_id(3); }
static void c_SPLR(void) { Gline_bundle b = { 2, 1, 1 }; gset_line_rep(1, 2, &b); }
static void c_SPMR(void) { Gmarker_bundle b = { 2, 1, 1 }; gset_marker_rep(1, 2, &b); }
static void c_STXR(void) { Gtext_bundle b = { { 1, GPREC_STROKE }, 1, 0, 1 }; gset_text_rep(1, 2, &b); }
static void c_SFAR(void) { Gfill_bundle b = { GSTYLE_SOLID, 1, 2 }; gset_fill_rep(1, 2, &b); }
static void c_SPAR(void)
{
    Gint c[2] = { 1, 0 };
    Gpat_rep r = { { 2, 1 }, c };
    gset_pat_rep(1, 4, &r);
}
static void c_PM3(void) { Gpoint_list3 l = { 1, (Gpoint3 *)tri3 }; gpolymarker3(&l); }
static void c_TX3(void)
{
    Gpoint3 p = { 0.5, 0.5, 0.5 };
    Gvec3 d[2] = { { 1, 0, 0 }, { 0, 1, 0 } };
    gtext3(&p, d, "GKS-3D");
}
static void c_FAS(void) { Gpoint_list_list l = { 1, (Gpoint_list *)&list3 }; gfill_area_set(&l); }
static void c_FAS3(void) { Gpoint_list_list3 l = { 1, (Gpoint_list3 *)&list3d }; gfill_area_set3(&l); }
static void c_CA3(void)
{
    Gint c[1] = { 2 };
    Gparal r = { { 0.1, 0.1, 0 }, { 0.4, 0.4, 0 }, { 0.4, 0.1, 0 } };
    Gpat_rep a = { { 1, 1 }, c };
    gcell_array3(&r, &a);
}
static void c_GDP3(void) { ggdp3(&list3d, 1, NULL); }
static void c_SEDFG(void) { gset_edge_flag(GEDGE_ON); }
static void c_SEDT(void) { gset_edgetype(2); }
static void c_SEWSC(void) { gset_edgewidth(2.0); }
static void c_SEDCI(void) { gset_edge_colr_ind(2); }
static void c_SEDI(void) { gset_edge_ind(2); }
static void c_SEDR(void) { Gedge_bundle b = { GEDGE_ON, 2, 1, 1 }; gset_edge_rep(1, 2, &b); }
static void c_SPRPV(void)
{
    Gpoint3 p = { 0, 0, 0 };
    Gvec3 v[2] = { { 1, 0, 0 }, { 0, 0, 1 } };
    gset_pat_ref_point_vecs(&p, v);
}
static void c_SHRID(void) { gset_hlhsr_id(1); }
static void c_ASF3(void) { Gasfs3 a = { { 0 }, 0, 0, 0, 0 }; gset_asfs3(&a); }

static void c_CRSG(void) { gcreate_seg(5); }
static void c_CLSG(void) { gclose_seg(); }
static void c_RENSG(void) { grename_seg(1, 2); }
static void c_DSG(void) { gdel_seg(1); }
static void c_DSGWK(void) { gdel_seg_ws(1, 1); }
static void c_SSGT(void)
{
    const Gtran_matrix m = { { 1, 0, 0.1 }, { 0, 1, 0 } };
    gset_seg_tran(1, m);
}
static void c_SSGT3(void)
{
    const Gtran_matrix3 m = { { 1, 0, 0, 0.1 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
    gset_seg_tran3(1, m);
}
static void c_SVIS(void) { gset_vis(1, GSEG_INVIS); }
static void c_SHLIT(void) { gset_highl(1, GSEG_HIGHL); }
static void c_SSGP(void) { gset_seg_pri(1, 0.5); }
static void c_SDTEC(void) { gset_det(1, GSEG_DET); }
static void c_ASGWK(void) { gassoc_seg_ws(1, 1); }
static void c_SVPIP(void) { gset_vp_in_pri(1, 0, GPRI_HIGHER); }
static void c_SVTIP(void) { gset_view_tran_in_pri(1, 1, 0, GPRI_HIGHER); }
static void c_SWKW3(void)
{
    const Glimit3 w = { 0, 1, 0, 1, 0, 1 };
    gset_ws_win3(1, &w);
}
static void c_SWKV3(void)
{
    const Glimit3 v = { 0, 100, 0, 100, 0, 1 };
    gset_ws_vp3(1, &v);
}
static void c_CSGWK(void) { gcopy_seg_ws(1, 1); }
static void c_INSG(void)
{
    const Gtran_matrix m = { { 1, 0, 0 }, { 0, 1, 0 } };
    ginsert_seg(1, m);
}
static void c_INSG3(void)
{
    const Gtran_matrix3 m = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
    ginsert_seg3(1, m);
}
static void c_WITM(void) { gwrite_item(1, 101, 2, ITEM("ab")); }
static void c_GTITM(void) { Gint t, l; gget_item_type(1, &t, &l); }
static void c_RDITM(void) { char buf[4]; gread_item(1, 4, RBUF(buf)); }
static void c_IITM(void) { ginterpret_item(GKSM_TEST_ITEM_LINETYPE, 11, ITEM("          2")); }

/* Input (gks_input.c): ws 1 is of category OUTPUT, so the allowed states give 38. */
static const Glimit earea = { 0, 100, 0, 100 };
static const Gloc loc0 = { 0, { 0.5, 0.5 } };
static void c_INLC(void) { ginit_loc(1, 1, &loc0, 1, &earea, NULL); }
static void c_INSK(void)
{
    Gstroke s = { 0, 3, (Gpoint *)pts3 };
    ginit_stroke(1, 1, &s, 1, &earea, 10, NULL);
}
static void c_INVL(void) { ginit_val(1, 1, 0.5, 1, &earea, 0, 1, NULL); }
static void c_INCH(void) { ginit_choice(1, 1, GIN_STATUS_OK, 1, 1, &earea, NULL); }
static void c_INPK(void)
{
    Gpick p = { 1, 1 };
    ginit_pick(1, 1, GIN_STATUS_OK, &p, 1, &earea, NULL);
}
static void c_INST(void) { ginit_string(1, 1, "ab", 1, &earea, 10, 1, NULL); }
static void c_SLCM(void) { gset_loc_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_SSKM(void) { gset_stroke_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_SVLM(void) { gset_val_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_SCHM(void) { gset_choice_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_SPKM(void) { gset_pick_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_SSTM(void) { gset_string_mode(1, 1, GOP_REQ, GSWITCH_ECHO); }
static void c_RQLC(void) { Gin_status s; Gloc l; greq_loc(1, 1, &s, &l); }
static void c_RQSK(void)
{
    Gin_status s;
    Gpoint p[4];
    Gstroke k = { 0, 4, p };
    greq_stroke(1, 1, &s, &k);
}
static void c_RQVL(void) { Gin_status s; Gfloat v; greq_val(1, 1, &s, &v); }
static void c_RQCH(void) { Gin_status s; Gint c; greq_choice(1, 1, &s, &c); }
static void c_RQPK(void) { Gin_status s; Gpick p; greq_pick(1, 1, &s, &p); }
static void c_RQST(void) { Gin_status s; char b[16]; greq_string(1, 1, &s, b); }
static void c_SMLC(void) { Gloc l; gsample_loc(1, 1, &l); }
static void c_SMSK(void) { Gpoint p[4]; Gstroke k = { 0, 4, p }; gsample_stroke(1, 1, &k); }
static void c_SMVL(void) { Gfloat v; gsample_val(1, 1, &v); }
static void c_SMCH(void) { Gin_status s; Gint c; gsample_choice(1, 1, &s, &c); }
static void c_SMPK(void) { Gin_status s; Gpick p; gsample_pick(1, 1, &s, &p); }
static void c_SMST(void) { char b[16]; gsample_string(1, 1, b); }
static void c_WAIT(void) { Gint w, n; Gin_class c; gawait_event(0, &w, &c, &n); }
static void c_FLUSH(void) { gflush_events(1, GIN_LOC, 1); }
static void c_GTLC(void) { Gloc l; gget_loc(&l); }
static void c_GTSK(void) { Gpoint p[4]; Gstroke k = { 0, 4, p }; gget_stroke(&k); }
static void c_GTVL(void) { Gfloat v; gget_val(&v); }
static void c_GTCH(void) { Gin_status s; Gint c; gget_choice(&s, &c); }
static void c_GTPK(void) { Gin_status s; Gpick p; gget_pick(&s, &p); }
static void c_GTST(void) { char b[16]; gget_string(b); }
static const Glimit3 evol = { 0, 100, 0, 100, 0, 1 };
static void c_INVL3(void) { ginit_val3(1, 1, 0.5, 1, &evol, 0, 1, NULL); }
static void c_INCH3(void) { ginit_choice3(1, 1, GIN_STATUS_OK, 1, 1, &evol, NULL); }
static void c_INPK3(void)
{
    Gpick p = { 1, 1 };
    ginit_pick3(1, 1, GIN_STATUS_OK, &p, 1, &evol, NULL);
}
static void c_INST3(void) { ginit_string3(1, 1, "ab", 1, &evol, 10, 1, NULL); }
static void c_INLC3(void)
{
    Gloc3 l = { 0, { 0.5, 0.5, 0.5 } };
    ginit_loc3(1, 1, 0, &l, 1, &evol, NULL);
}
static void c_INSK3(void)
{
    Gpoint3 p[1] = { { 0.5, 0.5, 0.5 } };
    Gstroke3 k = { 0, 1, p };
    ginit_stroke3(1, 1, 0, &k, 1, &evol, 10, NULL);
}
static void c_RQLC3(void) { Gin_status s; Gint v; Gloc3 l; greq_loc3(1, 1, &s, &v, &l); }
static void c_RQSK3(void)
{
    Gin_status s;
    Gint v;
    Gpoint3 p[4];
    Gstroke3 k = { 0, 4, p };
    greq_stroke3(1, 1, &s, &v, &k);
}
static void c_SMLC3(void) { Gint v; Gloc3 l; gsample_loc3(1, 1, &v, &l); }
static void c_SMSK3(void) { Gint v; Gpoint3 p[4]; Gstroke3 k = { 0, 4, p }; gsample_stroke3(1, 1, &v, &k); }
static void c_GTLC3(void) { Gint v; Gloc3 l; gget_loc3(&v, &l); }
static void c_GTSK3(void) { Gint v; Gpoint3 p[4]; Gstroke3 k = { 0, 4, p }; gget_stroke3(&v, &k); }

typedef struct { void (*call)(void); unsigned states; const char *name; } row;
#define S(x) (1u << (x))
#define GKS_S_GKCL S(GST_GKCL)
#define GKS_S_GKOP S(GST_GKOP)
#define GKS_S_WSOP S(GST_WSOP)
#define GKS_S_WSAC S(GST_WSAC)
#define GKS_S_SGOP S(GST_SGOP)
#define GKS_S_WSOPEN (GKS_S_WSOP | GKS_S_WSAC | GKS_S_SGOP)
#define GKS_S_OPEN (GKS_S_GKOP | GKS_S_WSOPEN)
#define GKS_FN_RESERVED(id, sym, name)
#define GKS_FN(id, sym, name, states, mf) [id] = { c_##sym, states, name },
static const row rows[] = {
#include "gks_functions.def"
};
#undef GKS_FN
#undef GKS_FN_RESERVED

/* The standard's state error for an allowed-state mask (independent of the library's). */
static int expected_error(unsigned m)
{
    if (m == GKS_S_GKCL) return 1;
    if (m == GKS_S_GKOP) return 2;
    if (m == GKS_S_WSAC) return 3;
    if (m == GKS_S_SGOP) return 4;
    if (m == (GKS_S_WSAC | GKS_S_SGOP)) return 5;
    if (m == (GKS_S_WSOP | GKS_S_WSAC)) return 6;
    if (m == GKS_S_WSOPEN) return 7;
    if (m == GKS_S_OPEN) return 8;
    return -1;
}

static void test_every_function_every_state(void **unused)
{
    (void)unused;
    int checked = 0;
    for (size_t id = 0; id < sizeof rows / sizeof rows[0]; id++) {
        if (!rows[id].call)
            continue; /* reserved identification: no function yet */
        assert_string_equal(gks_function_name((Gint)id), rows[id].name);
        for (Gop_st st = GST_GKCL; st <= GST_SGOP; st++) {
            enter_state(st);
            snapshot before, after;
            take_snapshot(&before);
            rows[id].call();
            if (rows[id].states & S(st)) {
                for (int k = 0; k < n_captured; k++)
                    assert_true(captured[k].err > 8); /* no state error when allowed */
                continue;
            }
            take_snapshot(&after);
            if (n_captured != 1 || captured[0].err != expected_error(rows[id].states) ||
                captured[0].fct != (int)id)
                fail_msg("%s in state %d: got %d errors, first %d (fct %d), want %d",
                         rows[id].name, st, n_captured, n_captured ? captured[0].err : 0,
                         n_captured ? captured[0].fct : -1, expected_error(rows[id].states));
            assert_memory_equal(&before, &after, sizeof before);
            checked++;
        }
    }
    reset_gks();
    assert_true(checked >= 40);
}

int main(void)
{
    const struct CMUnitTest tests[] = { cmocka_unit_test(test_every_function_every_state) };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
