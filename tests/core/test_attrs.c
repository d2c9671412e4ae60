/* SPDX-License-Identifier: MIT */
/*
 * test_attrs.c -- primitive attributes: defaults, setter/inquiry round trips, every
 * argument error (and the value unchanged after it), workstation representations (SET
 * and REALIZED), description table inquiries, and the aspect source flags observed where
 * it matters: in the primitives the drivers receive (core test hook) and in the pixels of
 * a PNG workstation.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <cmocka.h>
#include "prim_capture.h"
#include "core_util.h"
#include "png_util.h"
#include "cap_fixture.h"

/* ------------------------------------------------------------------ defaults */
static void test_defaults(void **state)
{
    (void)state;
    Gint e, i;
    Gfloat f;
    ginq_line_ind(&e, &i); assert_int_equal(i, 1);
    ginq_linetype(&e, &i); assert_int_equal(i, 1);
    ginq_linewidth(&e, &f); assert_true(f == 1.0);
    ginq_marker_type(&e, &i); assert_int_equal(i, 3);
    ginq_marker_size(&e, &f); assert_true(f == 1.0);
    ginq_marker_colr_ind(&e, &i); assert_int_equal(i, 1);
    Gtext_font_prec fp;
    ginq_text_font_prec(&e, &fp);
    assert_int_equal(fp.font, 1);
    assert_int_equal(fp.prec, GPREC_STRING);
    ginq_char_expan(&e, &f); assert_true(f == 1.0);
    ginq_char_space(&e, &f); assert_true(f == 0.0);
    ginq_char_ht(&e, &f); assert_true(f == 0.01);
    Gvec v;
    ginq_char_up_vec(&e, &v); assert_true(v.delta_x == 0 && v.delta_y == 1);
    ginq_char_base_vec(&e, &v); assert_true(v.delta_x == 1 && v.delta_y == 0);
    Gtext_path tp;
    ginq_text_path(&e, &tp); assert_int_equal(tp, GPATH_RIGHT);
    Gtext_align al;
    ginq_text_align(&e, &al); assert_true(al.hor == GHOR_NORM && al.vert == GVERT_NORM);
    Gfill_int_style is;
    ginq_fill_int_style(&e, &is); assert_int_equal(is, GSTYLE_HOLLOW);
    ginq_fill_style_ind(&e, &i); assert_int_equal(i, 1);
    ginq_pat_size(&e, &v.delta_x, &v.delta_y); assert_true(v.delta_x == 1 && v.delta_y == 1);
    Gpoint3 rp;
    Gvec3 rv[2];
    ginq_pat_ref_point_vecs(&e, &rp, rv);
    assert_true(rp.x == 0 && rp.y == 0 && rp.z == 0 && rv[0].delta_x == 1 && rv[1].delta_y == 1);
    Gasfs3 a;
    ginq_asfs3(&e, &a);
    assert_int_equal(e, 0);
    assert_int_equal(a.asfs.linetype, GASF_INDIV);
    assert_int_equal(a.asfs.fill_colr_ind, GASF_INDIV);
    assert_int_equal(a.edge_colr_ind, GASF_INDIV);
    Gedge_flag ef;
    ginq_edge_flag(&e, &ef); assert_int_equal(ef, GEDGE_OFF);
    ginq_edgetype(&e, &i); assert_int_equal(i, 1);
    ginq_edge_ind(&e, &i); assert_int_equal(i, 1);
    ginq_pick_id(&e, &i); assert_int_equal(i, 0);
    ginq_hlhsr_id(&e, &i); assert_int_equal(i, 0);
    /* Closed GKS: error 8, output untouched. */
    reset_gks();
    i = -77;
    ginq_linetype(&e, &i);
    assert_int_equal(e, 8);
    assert_int_equal(i, -77);
}

/* ------------------------------------------------------------------ round trips */
static void test_individual_round_trips(void **state)
{
    (void)state;
    Gint e, i;
    Gfloat f;
    gset_line_ind(7); ginq_line_ind(&e, &i); assert_int_equal(i, 7);
    gset_linetype(-3); ginq_linetype(&e, &i); assert_int_equal(i, -3);
    gset_linewidth(2.5); ginq_linewidth(&e, &f); assert_true(f == 2.5);
    gset_line_colr_ind(9); ginq_line_colr_ind(&e, &i); assert_int_equal(i, 9);
    gset_marker_ind(4); ginq_marker_ind(&e, &i); assert_int_equal(i, 4);
    gset_marker_type(5); ginq_marker_type(&e, &i); assert_int_equal(i, 5);
    gset_marker_size(0); ginq_marker_size(&e, &f); assert_true(f == 0);
    gset_marker_colr_ind(0); ginq_marker_colr_ind(&e, &i); assert_int_equal(i, 0);
    gset_text_ind(3); ginq_text_ind(&e, &i); assert_int_equal(i, 3);
    Gtext_font_prec fp = { -2, GPREC_CHAR }, fq;
    gset_text_font_prec(&fp); ginq_text_font_prec(&e, &fq);
    assert_true(fq.font == -2 && fq.prec == GPREC_CHAR);
    gset_char_expan(0.5); ginq_char_expan(&e, &f); assert_true(f == 0.5);
    gset_char_space(-0.25); ginq_char_space(&e, &f); assert_true(f == -0.25);
    gset_text_colr_ind(6); ginq_text_colr_ind(&e, &i); assert_int_equal(i, 6);
    gset_char_ht(0.125); ginq_char_ht(&e, &f); assert_true(f == 0.125);
    ginq_char_width(&e, &f); assert_true(f == 0.125);
    Gvec up = { -3, 4 }, v;
    gset_char_up_vec(&up); ginq_char_up_vec(&e, &v); assert_true(v.delta_x == -3 && v.delta_y == 4);
    ginq_char_base_vec(&e, &v);
    assert_true(fabs(v.delta_x - 0.8) < 1e-15 && fabs(v.delta_y - 0.6) < 1e-15);
    gset_text_path(GPATH_LEFT);
    Gtext_path tp;
    ginq_text_path(&e, &tp); assert_int_equal(tp, GPATH_LEFT);
    Gtext_align al = { GHOR_RIGHT, GVERT_BOTTOM }, am;
    gset_text_align(&al); ginq_text_align(&e, &am);
    assert_true(am.hor == GHOR_RIGHT && am.vert == GVERT_BOTTOM);
    gset_fill_ind(11); ginq_fill_ind(&e, &i); assert_int_equal(i, 11);
    gset_fill_int_style(GSTYLE_HATCH);
    Gfill_int_style is;
    ginq_fill_int_style(&e, &is); assert_int_equal(is, GSTYLE_HATCH);
    gset_fill_style_ind(-4); ginq_fill_style_ind(&e, &i); assert_int_equal(i, -4);
    gset_fill_colr_ind(3); ginq_fill_colr_ind(&e, &i); assert_int_equal(i, 3);
    gset_pat_size(0.1, 0.2); ginq_pat_size(&e, &v.delta_x, &v.delta_y);
    assert_true(v.delta_x == 0.1 && v.delta_y == 0.2);
    Gpoint3 rp3 = { 1, 2, 3 }, rq;
    Gvec3 rv[2] = { { 0, 0, 2 }, { 0, 1, 0 } }, rw[2];
    gset_pat_ref_point_vecs(&rp3, rv);
    ginq_pat_ref_point_vecs(&e, &rq, rw);
    assert_true(rq.z == 3 && rw[0].delta_z == 2 && rw[1].delta_y == 1);
    Gpoint rp = { 0.25, 0.75 }, rr;
    gset_pat_ref_point(&rp);
    ginq_pat_ref_point(&e, &rr);
    assert_true(rr.x == 0.25 && rr.y == 0.75);
    ginq_pat_ref_point_vecs(&e, &rq, rw); /* the 2-D function resets z and the vectors */
    assert_true(rq.z == 0 && rw[0].delta_x == 1 && rw[0].delta_z == 0 && rw[1].delta_y == 1);
    gset_pick_id(12); ginq_pick_id(&e, &i); assert_int_equal(i, 12);
    gset_hlhsr_id(1); ginq_hlhsr_id(&e, &i); assert_int_equal(i, 1);
    gset_edge_flag(GEDGE_ON);
    Gedge_flag ef;
    ginq_edge_flag(&e, &ef); assert_int_equal(ef, GEDGE_ON);
    gset_edgetype(4); ginq_edgetype(&e, &i); assert_int_equal(i, 4);
    gset_edgewidth(3); ginq_edgewidth(&e, &f); assert_true(f == 3);
    gset_edge_colr_ind(5); ginq_edge_colr_ind(&e, &i); assert_int_equal(i, 5);
    gset_edge_ind(2); ginq_edge_ind(&e, &i); assert_int_equal(i, 2);
    Gasfs3 a = { { GASF_BUNDLED, GASF_INDIV, GASF_BUNDLED, GASF_INDIV, GASF_BUNDLED,
                   GASF_INDIV, GASF_BUNDLED, GASF_INDIV, GASF_BUNDLED, GASF_INDIV,
                   GASF_BUNDLED, GASF_INDIV, GASF_BUNDLED },
                 GASF_INDIV, GASF_BUNDLED, GASF_INDIV, GASF_BUNDLED }, b;
    gset_asfs3(&a);
    ginq_asfs3(&e, &b);
    assert_memory_equal(&a, &b, sizeof a);
    Gasfs two = { 0 }, got;
    gset_asfs(&two); /* the 2-D function leaves the edge flags */
    ginq_asfs(&e, &got);
    assert_memory_equal(&two, &got, sizeof two);
    ginq_asfs3(&e, &b);
    assert_int_equal(b.edgetype, GASF_BUNDLED);
    assert_int_equal(b.edge_flag, GASF_INDIV);
    expect_no_error();
}

/* ------------------------------------------------------------------ argument errors */
static void test_setter_errors(void **state)
{
    (void)state;
    Gint e, i;
    Gfloat f;
    gset_line_ind(0); expect_error(60, GFN_SPLI);
    gset_linetype(0); expect_error(63, GFN_SLN);
    gset_linewidth(-1); expect_error(65, GFN_SLWSC);
    gset_linewidth(NAN); expect_error(65, GFN_SLWSC);
    gset_line_colr_ind(-1); expect_error(92, GFN_SPLCI);
    gset_marker_ind(-2); expect_error(66, GFN_SPMI);
    gset_marker_type(0); expect_error(69, GFN_SMK);
    gset_marker_size(-0.5); expect_error(71, GFN_SMKSC);
    gset_marker_colr_ind(-1); expect_error(92, GFN_SPMCI);
    gset_text_ind(0); expect_error(72, GFN_STXI);
    Gtext_font_prec f0 = { 0, GPREC_STROKE }, fbad = { 1, (Gtext_prec)7 };
    gset_text_font_prec(&f0); expect_error(75, GFN_STXFP);
    gset_text_font_prec(&fbad); expect_error(2000, GFN_STXFP);
    gset_text_font_prec(NULL); expect_error(75, GFN_STXFP);
    gset_char_expan(0); expect_error(77, GFN_SCHXP);
    gset_char_expan(INFINITY); expect_error(77, GFN_SCHXP);
    gset_char_space(NAN); expect_error(308, GFN_SCHSP);
    gset_text_colr_ind(-5); expect_error(92, GFN_STXCI);
    gset_char_ht(0); expect_error(78, GFN_SCHH);
    gset_char_ht(-1); expect_error(78, GFN_SCHH);
    Gvec z = { 0, 0 }, nanv = { NAN, 1 };
    gset_char_up_vec(&z); expect_error(79, GFN_SCHUP);
    gset_char_up_vec(&nanv); expect_error(79, GFN_SCHUP);
    gset_char_up_vec(NULL); expect_error(79, GFN_SCHUP);
    gset_text_path((Gtext_path)4); expect_error(2000, GFN_STXP);
    Gtext_align bad = { GHOR_LEFT, (Gvert_text_align)6 };
    gset_text_align(&bad); expect_error(2000, GFN_STXAL);
    gset_fill_ind(0); expect_error(80, GFN_SFAI);
    gset_fill_int_style((Gfill_int_style)4); expect_error(2000, GFN_SFAIS);
    gset_fill_style_ind(0); expect_error(84, GFN_SFASI);
    gset_fill_colr_ind(-1); expect_error(92, GFN_SFACI);
    gset_pat_size(0, 1); expect_error(87, GFN_SPA);
    Gpoint pn = { NAN, 0 };
    gset_pat_ref_point(&pn); expect_error(308, GFN_SPARF);
    Gpoint3 p3 = { 0, 0, 0 };
    Gvec3 par[2] = { { 1, 1, 0 }, { 2, 2, 0 } };
    gset_pat_ref_point_vecs(&p3, par); expect_error(2000, GFN_SPRPV);
    Gasfs as = { .linetype = (Gasf)2 };
    gset_asfs(&as); expect_error(2000, GFN_SASF);
    Gasfs3 as3 = { { 0 }, 0, 0, 0, (Gasf)-1 };
    gset_asfs3(&as3); expect_error(2000, GFN_ASF3);
    gset_pick_id(-1); expect_error(97, GFN_SPKID);
    gset_edge_flag((Gedge_flag)2); expect_error(2000, GFN_SEDFG);
    gset_edgetype(0); expect_error(63, GFN_SEDT);
    gset_edgewidth(-2); expect_error(65, GFN_SEWSC);
    gset_edge_colr_ind(-1); expect_error(92, GFN_SEDCI);
    gset_edge_ind(0); expect_error(500, GFN_SEDI);
    /* Values are unchanged after the errors. */
    ginq_line_ind(&e, &i); assert_int_equal(i, 1);
    ginq_linewidth(&e, &f); assert_true(f == 1.0);
    ginq_char_ht(&e, &f); assert_true(f == 0.01);
    Gasfs3 a;
    ginq_asfs3(&e, &a);
    assert_int_equal(a.asfs.linetype, GASF_INDIV);
    assert_int_equal(a.edge_colr_ind, GASF_INDIV);
    ginq_edge_ind(&e, &i); assert_int_equal(i, 1);
    assert_string_equal(gks_error_message(500), "Edge index is invalid");
}

/* ------------------------------------------------------------------ representations */
static void test_representations(void **state)
{
    (void)state;
    Gint e;
    Gline_bundle lb = { 2, 1000.0, 300 }, lg;
    gset_line_rep(1, 6, &lb);
    expect_no_error();
    ginq_line_rep(1, 6, GINQ_SET, &e, &lg);
    assert_int_equal(e, 0);
    assert_true(lg.type == 2 && lg.width == 1000.0 && lg.colr_ind == 300);
    ginq_line_rep(1, 6, GINQ_REALIZED, &e, &lg);
    assert_int_equal(e, 0);
    /* width clamped to the maximum 256 pixels / nominal 1; colour 300 does not exist -> 1 */
    assert_true(lg.type == 2 && lg.width == 256.0 && lg.colr_ind == 1);
    ginq_line_rep(1, 7, GINQ_SET, &e, &lg); assert_int_equal(e, 61);
    ginq_line_rep(1, 0, GINQ_SET, &e, &lg); assert_int_equal(e, 60);
    ginq_line_rep(1, 1, (Ginq_type)5, &e, &lg); assert_int_equal(e, 2000);
    ginq_line_rep(9, 1, GINQ_SET, &e, &lg); assert_int_equal(e, 25);
    ginq_line_rep(-1, 1, GINQ_SET, &e, &lg); assert_int_equal(e, 20);
    /* SET POLYLINE REPRESENTATION errors in order. */
    Gline_bundle z = { 0, 1, 1 }, u = { 9, 1, 1 }, w = { 1, -1, 1 }, c = { 1, 1, -1 };
    gset_line_rep(1, 21, &lb); expect_error(60, GFN_SPLR);
    gset_line_rep(1, 2, &z); expect_error(63, GFN_SPLR);
    gset_line_rep(1, 2, &u); expect_error(64, GFN_SPLR);
    gset_line_rep(1, 2, &w); expect_error(65, GFN_SPLR);
    gset_line_rep(1, 2, &c); expect_error(93, GFN_SPLR);
    gset_line_rep(5, 2, &lb); expect_error(25, GFN_SPLR);
    /* Marker. */
    Gmarker_bundle mb = { 4, 2.0, 2 }, mg, mu = { 6, 1, 1 };
    gset_marker_rep(1, 20, &mb);
    ginq_marker_rep(1, 20, GINQ_SET, &e, &mg);
    assert_true(e == 0 && mg.type == 4 && mg.size == 2.0 && mg.colr_ind == 2);
    ginq_marker_rep(1, 20, GINQ_REALIZED, &e, &mg);
    assert_true(mg.colr_ind == 1); /* index 2 not defined on the null workstation */
    gset_marker_rep(1, 2, &mu); expect_error(70, GFN_SPMR);
    ginq_marker_rep(1, 19, GINQ_SET, &e, &mg); assert_int_equal(e, 67);
    /* Text. */
    Gtext_bundle tb = { { 1, GPREC_CHAR }, 0.5, 0.1, 1 }, tg, tu = { { 7, GPREC_STROKE }, 1, 0, 1 };
    gset_text_rep(1, 8, &tb);
    ginq_text_rep(1, 8, GINQ_SET, &e, &tg);
    assert_true(e == 0 && tg.text_font_prec.prec == GPREC_CHAR && tg.char_expan == 0.5);
    ginq_text_rep(1, 8, GINQ_REALIZED, &e, &tg);
    assert_true(tg.text_font_prec.prec == GPREC_STROKE); /* drawn as STROKE */
    gset_text_rep(1, 8, &tu); expect_error(76, GFN_STXR);
    /* Fill. */
    Gfill_bundle fb = { GSTYLE_HATCH, -3, 1 }, fg, fz = { GSTYLE_HATCH, 0, 1 },
                 fh = { GSTYLE_HATCH, -99, 1 }, fp = { GSTYLE_PAT, -1, 1 };
    gset_fill_rep(1, 9, &fb);
    ginq_fill_rep(1, 9, GINQ_SET, &e, &fg);
    assert_true(e == 0 && fg.int_style == GSTYLE_HATCH && fg.style_ind == -3);
    gset_fill_rep(1, 9, &fz); expect_error(84, GFN_SFAR);
    gset_fill_rep(1, 9, &fp); expect_error(85, GFN_SFAR);
    gset_fill_rep(1, 9, &fh); expect_error(86, GFN_SFAR);
    Gfill_bundle fpat = { GSTYLE_PAT, 17, 1 };
    gset_fill_rep(1, 10, &fpat);
    ginq_fill_rep(1, 10, GINQ_REALIZED, &e, &fg);
    assert_int_equal(fg.style_ind, 1); /* pattern 17 undefined -> pattern 1 */
    /* Edge. */
    Gedge_bundle eb = { GEDGE_ON, 3, 0.5, 0 }, eg;
    gset_edge_rep(1, 4, &eb);
    ginq_edge_rep(1, 4, GINQ_SET, &e, &eg);
    assert_true(e == 0 && eg.flag == GEDGE_ON && eg.type == 3 && eg.width == 0.5 && eg.colr_ind == 0);
    ginq_edge_rep(1, 4, GINQ_REALIZED, &e, &eg);
    assert_true(eg.width == 1.0); /* minimum 1 pixel */
    ginq_edge_rep(1, 5, GINQ_SET, &e, &eg); assert_int_equal(e, 501);
    gset_edge_rep(1, 0, &eb); expect_error(500, GFN_SEDR);
    /* Pattern. */
    Gint pc[6] = { 1, 2, 3, 4, 5, 6 };
    Gpat_rep pr = { { 3, 2 }, pc }, *pg = NULL;
    gset_pat_rep(1, 5, &pr);
    expect_no_error();
    Gstore st = NULL;
    gcreate_store(&e, &st);
    ginq_pat_rep(1, 5, GINQ_SET, &st, &e, &pg);
    assert_int_equal(e, 0);
    assert_true(pg->dims.size_x == 3 && pg->dims.size_y == 2);
    assert_memory_equal(pg->colr_array, pc, sizeof pc);
    ginq_pat_rep(1, 5, GINQ_REALIZED, &st, &e, &pg); /* the store is reused */
    assert_true(pg->colr_array[0] == 1 && pg->colr_array[1] == 1); /* colour 2 undefined -> 1 */
    ginq_pat_rep(1, 5, GINQ_SET, NULL, &e, &pg);
    assert_int_equal(e, 2003); /* no store */
    ginq_pat_rep(1, 6, GINQ_SET, &st, &e, &pg); assert_int_equal(e, 88);
    gdel_store(st);
    Gpat_rep pbad = { { 0, 2 }, pc };
    gset_pat_rep(1, 5, &pbad); expect_error(91, GFN_SPAR);
    pc[3] = -1;
    gset_pat_rep(1, 5, &pr); expect_error(93, GFN_SPAR);
    gset_pat_rep(1, 0, &pr); expect_error(85, GFN_SPAR);
    /* Lists of defined indices: predefined 1..5 plus 6 for polylines. */
    Gint buf[32], len;
    Gint_list l = { 0, buf };
    ginq_list_line_inds(1, 32, 0, &e, &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 6);
    assert_int_equal(buf[5], 6);
    ginq_list_edge_inds(1, 32, 0, &e, &l, &len);
    assert_int_equal(len, 4);
    ginq_list_pat_inds(1, 2, 3, &e, &l, &len);
    assert_int_equal(len, 4);
    assert_int_equal(l.num_ints, 1);
    assert_int_equal(buf[0], 5);
    ginq_list_text_inds(1, 2, 9, &e, &l, &len);
    assert_int_equal(e, 2002);
}

static void test_description_tables(void **state)
{
    (void)state;
    Gint e, len, buf[16];
    Gline_facs lf = { .types = { 0, buf } };
    ginq_line_facs(GWS_TYPE_PNG, 16, 0, &e, &lf, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 4);
    assert_int_equal(lf.types.num_ints, 4);
    assert_int_equal(buf[3], 4);
    assert_true(lf.nom_width == 1 && lf.num_pred_inds == 5);
    Gmarker_facs mf = { .types = { 0, buf } };
    ginq_marker_facs(GWS_TYPE_PNG, 2, 3, &e, &mf, &len);
    assert_int_equal(len, 5);
    assert_int_equal(mf.types.num_ints, 2);
    assert_int_equal(buf[1], 5);
    Gtext_font_prec fp[8];
    Gtext_facs tf = { .num_font_precs = 8, .font_precs = fp };
    ginq_text_facs(GWS_TYPE_PNG, 8, 0, &e, &tf, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 9); /* font 1 in 3 precisions, 6 derived faces in STROKE */
    assert_true(fp[2].font == 1 && fp[2].prec == GPREC_STROKE);
    assert_true(fp[3].font == -101 && fp[5].font == -104 && fp[7].font == -106);
    Gint hs[16];
    Gfill_facs ff = { .hatch_styles = { 0, hs } };
    Gint lh;
    ginq_fill_facs(GWS_TYPE_PNG, 16, 0, &e, &ff, &lh);
    assert_int_equal(e, 0);
    assert_int_equal(ff.num_int_styles, 4);
    assert_int_equal(ff.int_style[3], GSTYLE_HATCH);
    assert_int_equal(lh, 12);
    assert_int_equal(hs[11], -12);
    Gint np;
    ginq_pat_facs(GWS_TYPE_PNG, &e, &np);
    assert_int_equal(np, 3);
    Gedge_facs ef = { .types = { 0, buf } };
    ginq_edge_facs(GWS_TYPE_NULL, 16, 0, &e, &ef, &len);
    assert_int_equal(len, 4);
    assert_int_equal(ef.num_pred_inds, 3);
    Gline_bundle lb;
    ginq_pred_line_rep(GWS_TYPE_PNG, 2, &e, &lb);
    assert_true(e == 0 && lb.type == 2);
    ginq_pred_line_rep(GWS_TYPE_PNG, 6, &e, &lb); assert_int_equal(e, 62);
    ginq_pred_line_rep(GWS_TYPE_PNG, 0, &e, &lb); assert_int_equal(e, 60);
    ginq_pred_line_rep(55, 1, &e, &lb); assert_int_equal(e, 23);
    ginq_pred_line_rep(0, 1, &e, &lb); assert_int_equal(e, 22);
    Gmarker_bundle mb;
    ginq_pred_marker_rep(GWS_TYPE_PNG, 6, &e, &mb); assert_int_equal(e, 68);
    Gtext_bundle tb;
    ginq_pred_text_rep(GWS_TYPE_PNG, 3, &e, &tb);
    assert_true(e == 0 && tb.text_font_prec.prec == GPREC_STROKE);
    /* RAL's CONCOL draws three lines in text bundles 1, 2, 3 and expects three colours. */
    for (Gint i = 1; i <= 5; i++) {
        ginq_pred_text_rep(GWS_TYPE_PNG, i, &e, &tb);
        assert_int_equal(e, 0);
        assert_int_equal(tb.colr_ind, i);
    }
    Gfill_bundle fb;
    ginq_pred_fill_rep(GWS_TYPE_PNG, 4, &e, &fb);
    assert_true(e == 0 && fb.int_style == GSTYLE_HATCH && fb.style_ind == -1);
    ginq_pred_fill_rep(GWS_TYPE_PNG, 9, &e, &fb); assert_int_equal(e, 82);
    Gedge_bundle eb;
    ginq_pred_edge_rep(GWS_TYPE_PNG, 9, &e, &eb); assert_int_equal(e, 502);
    Gstore st = NULL;
    Gpat_rep *pr = NULL;
    gcreate_store(&e, &st);
    ginq_pred_pat_rep(GWS_TYPE_PNG, 1, &st, &e, &pr);
    assert_int_equal(e, 0);
    assert_true(pr->dims.size_x == 2 && pr->dims.size_y == 2 && pr->colr_array[0] == 1 &&
                pr->colr_array[1] == 0);
    ginq_pred_pat_rep(GWS_TYPE_PNG, 2, &st, &e, &pr);
    assert_int_equal(e, 0);
    assert_int_equal(pr->dims.size_x * pr->dims.size_y, 16);
    ginq_pred_pat_rep(GWS_TYPE_PNG, 4, &st, &e, &pr);
    assert_int_equal(e, 89);
    gdel_store(st);
    Gmax_ws_st_tables mt;
    ginq_max_ws_st_tables(GWS_TYPE_PNG, &e, &mt);
    assert_true(e == 0 && mt.line_bundles == 20 && mt.colr_reps == 256 && mt.edge_bundles == 20);
}

/* ------------------------------------------------------------------ ASF at the driver */
static const gks_prim *last(void)
{
    assert_true(cap.n >= 1);
    return &cap.rec[cap.n - 1].p;
}

static void test_asf_resolution_at_driver(void **state)
{
    (void)state;
    gopen_ws(2, "test_attrs_asf", GWS_TYPE_PNG);
    gactivate_ws(2);
    gdeactivate_ws(1); /* only the PNG workstation (8 predefined colours) */
    Gpoint p[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
    Gpoint_list l = { 3, p };
    Gline_bundle lb = { 3, 4.0, 2 };
    gset_line_rep(2, 7, &lb);
    gset_line_ind(7);
    gset_linetype(2);
    gset_linewidth(2.0);
    gset_line_colr_ind(4);
    gpolyline(&l);
    const gks_prim *r = last();
    assert_int_equal(r->attrs.linetype, 2);
    assert_true(r->attrs.linewidth == 2.0);
    assert_true(same_rgb(r->colour, (Grgb){ 0, 0, 1 }));
    Gasfs a = { 0 };
    memset(&a, 0, sizeof a);
    for (Gasf *f = &a.linetype; f <= &a.fill_colr_ind; f++)
        *f = GASF_INDIV;
    a.linetype = GASF_BUNDLED;
    a.line_colr_ind = GASF_BUNDLED;
    gset_asfs(&a);
    gpolyline(&l);
    r = last();
    assert_int_equal(r->attrs.linetype, 3);              /* from bundle 7 */
    assert_true(r->attrs.linewidth == 2.0);              /* individual */
    assert_true(same_rgb(r->colour, (Grgb){ 1, 0, 0 })); /* bundle 7: colour 2 red */
    /* An undefined bundle index uses bundle 1 (solid, colour 1). */
    gset_line_ind(13);
    gpolyline(&l);
    r = last();
    assert_int_equal(r->attrs.linetype, 1);
    assert_true(same_rgb(r->colour, (Grgb){ 0, 0, 0 }));
    /* Unsupported individual linetype -> 1; negative width factor impossible, huge -> 256. */
    a.linetype = GASF_INDIV;
    gset_asfs(&a);
    gset_linetype(-7);
    gset_linewidth(1e9);
    gpolyline(&l);
    r = last();
    assert_int_equal(r->attrs.linetype, 1);
    assert_true(r->attrs.linewidth == 256.0);
    /* Markers: unsupported type -> 3; bundled size and colour. */
    Gmarker_bundle mb = { 4, 3.0, 5 };
    gset_marker_rep(2, 2, &mb);
    gset_marker_ind(2);
    gset_marker_type(42);
    a.marker_size = GASF_BUNDLED;
    a.marker_colr_ind = GASF_BUNDLED;
    gset_asfs(&a);
    gpolymarker(&l);
    r = last();
    assert_int_equal(r->kind, GKS_PRIM_POLYMARKER);
    assert_int_equal(r->attrs.marker_type, 3);
    assert_true(r->attrs.marker_size == 3.0);
    assert_true(same_rgb(r->colour, (Grgb){ 1, 1, 0 }));
    /* Fill: bundled style from the predefined fill bundle 5 (hatch -3), individual colour. */
    gset_fill_ind(5);
    a.fill_int_style = GASF_BUNDLED;
    a.fill_style_ind = GASF_BUNDLED;
    gset_asfs(&a);
    gset_fill_colr_ind(3);
    gfill_area(&l);
    r = last();
    assert_int_equal(r->attrs.int_style, GSTYLE_HATCH);
    assert_int_equal(r->attrs.style_ind, -3);
    assert_true(same_rgb(r->colour, (Grgb){ 0, 1, 0 }));
    /* Pattern: individual PATTERN 1 -> the predefined 2x2 checkerboard as RGB, and the
     * pattern box from the pattern size and reference point (identity normalization). */
    a.fill_int_style = GASF_INDIV;
    a.fill_style_ind = GASF_INDIV;
    gset_asfs(&a);
    gset_fill_int_style(GSTYLE_PAT);
    gset_fill_style_ind(1);
    gset_pat_size(0.1, 0.2);
    Gpoint rp = { 0.3, 0.4 };
    gset_pat_ref_point(&rp);
    gfill_area(&l);
    r = last();
    assert_int_equal(r->attrs.int_style, GSTYLE_PAT);
    assert_int_equal(r->attrs.pat_nx, 2);
    assert_int_equal(r->attrs.pat_ny, 2);
    assert_true(same_rgb(r->attrs.pattern[0], (Grgb){ 0, 0, 0 }));
    assert_true(same_rgb(r->attrs.pattern[1], (Grgb){ 1, 1, 1 }));
    assert_true(r->attrs.pat_ref.x == 0.3 && r->attrs.pat_ref.y == 0.4);
    assert_true(fabs(r->attrs.pat_width.delta_x - 0.1) < 1e-15 && r->attrs.pat_width.delta_y == 0);
    assert_true(fabs(r->attrs.pat_height.delta_y - 0.2) < 1e-15);
    /* Undefined pattern index -> pattern 1. */
    gset_fill_style_ind(19);
    gfill_area(&l);
    assert_int_equal(last()->attrs.pat_nx, 2);
    /* Edges: bundled from the predefined edge bundle 3 (on, solid, width 3). */
    Gpoint_list_list set = { 1, &l };
    Gasfs3 a3 = { a, GASF_BUNDLED, GASF_BUNDLED, GASF_BUNDLED, GASF_INDIV };
    gset_asfs3(&a3);
    gset_edge_ind(3);
    gset_edge_colr_ind(2);
    gfill_area_set(&set);
    r = last();
    assert_int_equal(r->attrs.edge_flag, 1);
    assert_int_equal(r->attrs.edgetype, 1);
    assert_true(r->attrs.edgewidth == 3.0);
    assert_true(same_rgb(r->attrs.edge_colour, (Grgb){ 1, 0, 0 }));
    /* Text colour bundled: predefined text bundle 1 has colour 1. */
    gset_text_colr_ind(2);
    Gpoint pos = { 0.5, 0.5 };
    gtext(&pos, "A");
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 0, 0 }));
    a.text_colr_ind = GASF_BUNDLED;
    gset_asfs(&a);
    gtext(&pos, "A");
    assert_true(same_rgb(last()->colour, (Grgb){ 0, 0, 0 }));
    /* Pick and HLHSR identifiers pass through. */
    gset_pick_id(77);
    gset_hlhsr_id(5);
    gpolyline(&l);
    assert_int_equal(last()->attrs.pick_id, 77);
    assert_int_equal(last()->attrs.hlhsr_id, 5);
    gdeactivate_ws(2);
    gclose_ws(2);
    remove("test_attrs_asf.png");
}

/* The pipeline keeps an area's resolved attributes per workstation while the current
 * attributes and the workstation tables stay the same (gks_area_memo): each kind of change
 * below must reach the next area. Workstations 2 and 18 share a slot of the memo (the
 * identifier modulo 16). */
static void test_area_attrs_kept_and_renewed(void **state)
{
    (void)state;
    gopen_ws(2, "test_attrs_memo2", GWS_TYPE_PNG);
    gactivate_ws(2);
    gdeactivate_ws(1);
    Gpoint p[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
    Gpoint_list l = { 3, p };
    Gpoint_list_list set = { 1, &l };
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 0, 0 }));
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 0, 0 }));
    assert_int_equal(last()->n_points, 3);
    /* the colour table */
    gset_colr_rep(2, 2, &(Gcolr_rep){ { 0.25, 0.5, 0.75 } });
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 0.25, 0.5, 0.75 }));
    /* an individual attribute */
    gset_fill_colr_ind(3);
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 0, 1, 0 }));
    /* a bundle under a bundled aspect, then the bundle changed */
    Gasfs a;
    memset(&a, 0, sizeof a);
    for (Gasf *f = &a.linetype; f <= &a.fill_colr_ind; f++)
        *f = GASF_INDIV;
    a.fill_colr_ind = GASF_BUNDLED;
    gset_asfs(&a);
    Gfill_bundle fb = { GSTYLE_SOLID, 1, 4 };
    gset_fill_rep(2, 6, &fb);
    gset_fill_ind(6);
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 0, 0, 1 }));
    fb.colr_ind = 5;
    gset_fill_rep(2, 6, &fb);
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 1, 0 }));
    /* edges: FILL AREA SET has them, FILL AREA with the same attributes not */
    gset_edge_flag(GEDGE_ON);
    gfill_area_set(&set);
    assert_int_equal(last()->attrs.edge_flag, 1);
    gfill_area(&l);
    assert_int_equal(last()->attrs.edge_flag, 0);
    gfill_area_set(&set);
    assert_int_equal(last()->attrs.edge_flag, 1);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 1, 0 }));
    /* attributes every primitive carries */
    gset_hlhsr_id(9);
    gfill_area(&l);
    assert_int_equal(last()->attrs.hlhsr_id, 9);
    /* a second workstation in the same slot, with its own colour table */
    a.fill_colr_ind = GASF_INDIV;
    gset_asfs(&a);
    gset_fill_colr_ind(5);
    gopen_ws(18, "test_attrs_memo18", GWS_TYPE_PNG);
    gactivate_ws(18);
    gset_colr_rep(18, 5, &(Gcolr_rep){ { 0.5, 0.5, 0.5 } });
    for (int k = 0; k < 2; k++) {
        int n0 = cap.n;
        gfill_area(&l);
        assert_int_equal(cap.n, n0 + 2);
        assert_int_equal(cap.rec[n0].ws_id, 2);
        assert_true(same_rgb(cap.rec[n0].p.colour, (Grgb){ 1, 1, 0 }));
        assert_int_equal(cap.rec[n0 + 1].ws_id, 18);
        assert_true(same_rgb(cap.rec[n0 + 1].p.colour, (Grgb){ 0.5, 0.5, 0.5 }));
    }
    /* workstation 2 closed and opened again: its predefined colours again */
    gset_colr_rep(2, 5, &(Gcolr_rep){ { 0.1, 0.2, 0.3 } });
    gdeactivate_ws(18);
    gfill_area(&l);
    assert_true(same_rgb(last()->colour, (Grgb){ 0.1, 0.2, 0.3 }));
    gdeactivate_ws(2);
    gclose_ws(2);
    gopen_ws(2, "test_attrs_memo2", GWS_TYPE_PNG);
    gactivate_ws(2);
    gfill_area(&l);
    assert_int_equal(cap.rec[cap.n - 1].ws_id, 2);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 1, 0 }));
    /* a pattern (not kept), then solid again */
    gset_fill_int_style(GSTYLE_PAT);
    gset_fill_style_ind(1);
    gfill_area(&l);
    assert_int_equal(last()->attrs.int_style, GSTYLE_PAT);
    assert_int_equal(last()->attrs.pat_nx, 2);
    gset_fill_int_style(GSTYLE_SOLID);
    gfill_area(&l);
    assert_int_equal(last()->attrs.int_style, GSTYLE_SOLID);
    assert_null(last()->attrs.pattern);
    assert_true(same_rgb(last()->colour, (Grgb){ 1, 1, 0 }));
    gdeactivate_ws(2);
    gclose_ws(2);
    gclose_ws(18);
    remove("test_attrs_memo2.png");
    remove("test_attrs_memo18.png");
}

/* The number the core gives an area's resolved attributes (gks_prim.attr_gen), on which a
 * driver may reuse what it made of the last area's attributes: the same while nothing that
 * feeds them changes, a new one after each kind of change below (an individual attribute,
 * an aspect source flag, a bundle representation, the colour table, the lighting and
 * shading attributes, the view index, the identifiers, edges of FILL AREA SET 3 against
 * FILL AREA 3, the workstation opened again), 0 for a pattern (not kept). And over every
 * area received: two areas of one non-zero number have the same attributes. */
static uint64_t area3(void)
{
    Gpoint3 p[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gpoint_list3 l = { 3, p };
    gfill_area3(&l);
    return last()->attr_gen;
}

/* One change: the next area has a new number, kept by the area after it; field says the
 * change reached the primitive (compared with the area before the change). */
#define GEN_CHANGED(change, field)                                                         \
    do {                                                                                   \
        const gks_prim before = *last();                                                   \
        change;                                                                            \
        const uint64_t g_ = area3();                                                       \
        assert_true(g_ != 0 && g_ != before.attr_gen);                                      \
        assert_true(memcmp(&before.field, &last()->field, sizeof before.field) != 0);      \
        assert_true(area3() == g_);                                                        \
    } while (0)

/* The attributes of p, all but the geometry, with the geometry's fields cleared. */
static gks_prim attrs_only(const gks_prim *p)
{
    gks_prim a;
    memcpy(&a, p, sizeof a); /* with its padding: compared bytewise */
    a.n_loops = a.n_points = 0;
    a.loop_counts = NULL;
    a.pts = NULL;
    return a;
}

static void test_area_attr_gen(void **state)
{
    (void)state;
    gopen_ws(2, "test_attrs_gen", GWS_TYPE_PNG);
    gactivate_ws(2);
    gdeactivate_ws(1);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    const uint64_t g0 = area3();
    assert_true(g0 != 0);
    assert_true(area3() == g0);
    /* an individual attribute, the colour table */
    GEN_CHANGED(gset_fill_colr_ind(3), colour);
    GEN_CHANGED(gset_colr_rep(2, 3, &(Gcolr_rep){ { 0.25, 0.5, 0.75 } }), colour);
    /* an aspect source flag, then the bundle it selects */
    Gfill_bundle fb = { GSTYLE_SOLID, 1, 4 };
    gset_fill_rep(2, 6, &fb);
    gset_fill_ind(6);
    Gasfs a;
    memset(&a, 0, sizeof a);
    for (Gasf *f = &a.linetype; f <= &a.fill_colr_ind; f++)
        *f = GASF_INDIV;
    a.fill_colr_ind = GASF_BUNDLED;
    GEN_CHANGED(gset_asfs(&a), colour);
    fb.colr_ind = 5;
    GEN_CHANGED(gset_fill_rep(2, 6, &fb), colour);
    /* the lighting and shading attributes, the view index, the identifiers */
    GEN_CHANGED(gset_area_props(&(Garea_props){ 0.1, 0.7, 0.2, { 1, 1, 1 }, 2, 0, 1 }),
                area_props[0]);
    GEN_CHANGED(gset_back_area_props(&(Garea_props){ 0.3, 0.5, 0, { 1, 0, 1 }, 1, 0, 1 }),
                area_props[1]);
    GEN_CHANGED(gset_refl_eq(GREFL_AMB_DIFF), refl_eq[0]);
    GEN_CHANGED(gset_back_refl_eq(GREFL_AMBIENT), refl_eq[1]);
    Gint on = 2;
    GEN_CHANGED(gset_light_src_state(&(Gint_list){ 1, &on }, NULL), light_mask);
    GEN_CHANGED(gset_int_shad_meth(GSHAD_NORM), shading[0]);
    GEN_CHANGED(gset_view_ind(1), view_ind);
    GEN_CHANGED(gset_hlhsr_id(4), attrs.hlhsr_id);
    GEN_CHANGED(gset_pick_id(8), attrs.pick_id);
    /* edges: FILL AREA SET 3 has them, FILL AREA 3 with the same attributes not */
    gset_edge_flag(GEDGE_ON);
    const uint64_t g_area = area3();
    Gpoint3 p[3] = { { 0.1, 0.1, 0.5 }, { 0.9, 0.1, 0.5 }, { 0.5, 0.9, 0.5 } };
    Gpoint_list3 l = { 3, p };
    gfill_area_set3(&(Gpoint_list_list3){ 1, &l });
    const uint64_t g_set = last()->attr_gen;
    assert_int_equal(last()->attrs.edge_flag, 1);
    assert_true(g_set != 0 && g_set != g_area);
    assert_true(area3() == g_area);
    assert_int_equal(last()->attrs.edge_flag, 0);
    gfill_area_set3(&(Gpoint_list_list3){ 1, &l });
    assert_true(last()->attr_gen == g_set);
    /* the same workstation closed and opened again */
    const uint64_t g_old = area3();
    gdeactivate_ws(2);
    gclose_ws(2);
    gopen_ws(2, "test_attrs_gen", GWS_TYPE_PNG);
    gactivate_ws(2);
    const uint64_t g_new = area3();
    assert_true(g_new != 0 && g_new != g_old);
    /* a pattern: no number */
    gset_fill_int_style(GSTYLE_PAT);
    gset_fill_style_ind(1);
    assert_true(area3() == 0);
    assert_int_equal(last()->attrs.int_style, GSTYLE_PAT);
    gset_fill_int_style(GSTYLE_SOLID);
    assert_true(area3() != 0);
    /* every pair of areas received with one number: the same attributes */
    assert_true(cap.n <= CAP_MAX_PRIMS);
    for (int i = 0; i < cap.n; i++)
        for (int j = i + 1; j < cap.n; j++) {
            if (cap.rec[i].p.attr_gen == 0 || cap.rec[i].p.attr_gen != cap.rec[j].p.attr_gen)
                continue;
            const gks_prim x = attrs_only(&cap.rec[i].p), y = attrs_only(&cap.rec[j].p);
            assert_memory_equal(&x, &y, sizeof x);
        }
    gdeactivate_ws(2);
    gclose_ws(2);
    remove("test_attrs_gen.png");
}

/* The same switch observed in pixels: a solid triangle drawn with the individual colour
 * (blue) and then, after SET ASPECT SOURCE FLAGS, with the bundled one (red, fill bundle
 * 6). Exact colours at the centroid: solid fills have no anti-aliasing here. */
static void test_asf_in_pixels(void **state)
{
    (void)state;
    gdeactivate_ws(1);
    gopen_ws(3, "test_attrs_px", GWS_TYPE_PNG);
    gactivate_ws(3);
    Glimit vp = { 0, 64, 0, 64 };
    gset_ws_vp(3, &vp);
    Gfill_bundle fb = { GSTYLE_SOLID, 1, 2 };
    gset_fill_rep(3, 6, &fb);
    gset_fill_ind(6);
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(4);
    Gpoint left[3] = { { 0.05, 0.1 }, { 0.45, 0.1 }, { 0.25, 0.9 } };
    Gpoint right[3] = { { 0.55, 0.1 }, { 0.95, 0.1 }, { 0.75, 0.9 } };
    Gpoint_list ll = { 3, left }, lr = { 3, right };
    gfill_area(&ll);
    Gasfs a;
    memset(&a, 0, sizeof a);
    for (Gasf *f = &a.linetype; f <= &a.fill_colr_ind; f++)
        *f = GASF_INDIV;
    a.fill_colr_ind = GASF_BUNDLED;
    gset_asfs(&a);
    gfill_area(&lr);
    gupd_ws(3, GFLAG_PERFORM);
    image img;
    assert_true(read_png("test_attrs_px.png", &img));
    assert_int_equal(img.w, 64);
    const unsigned char *b = px(&img, 16, 24), *r = px(&img, 48, 24), *bg = px(&img, 32, 60);
    assert_true(b[0] == 0 && b[1] == 0 && b[2] == 255);
    assert_true(r[0] == 255 && r[1] == 0 && r[2] == 0);
    assert_true(bg[0] == 255 && bg[1] == 255 && bg[2] == 255);
    free(img.rgb);
    gdeactivate_ws(3);
    gclose_ws(3);
    remove("test_attrs_px.png");
}

/* ------------------------------------------------------------------ text extent */
static void extent(const char *s, Gtext_extent *ex)
{
    Gint e;
    Gpoint pos = { 0.2, 0.3 };
    ginq_text_extent(1, &pos, s, &e, ex);
    assert_int_equal(e, 0);
}

static void test_text_extent(void **state)
{
    (void)state;
    gset_char_ht(0.1);
    Gtext_extent a, b, ab;
    extent("A", &a);
    extent("B", &b);
    extent("AB", &ab);
    double wa = a.paral[1].x - a.paral[0].x, wb = b.paral[1].x - b.paral[0].x;
    double wab = ab.paral[1].x - ab.paral[0].x;
    assert_true(wa > 0 && fabs(wab - (wa + wb)) < 1e-12);
    /* Default alignment LEFT/BASE: the extent starts at the position; base line there. */
    assert_true(fabs(ab.paral[0].x - 0.2) < 1e-15);
    assert_true(fabs(ab.paral[0].y - (0.3 - 0.1 * 7.0 / 21.0)) < 1e-12);
    assert_true(fabs(ab.concat_point.x - (0.2 + wab)) < 1e-12 && fabs(ab.concat_point.y - 0.3) < 1e-15);
    /* Spacing adds 0.5 * height between the two bodies, and after the last one. */
    gset_char_space(0.5);
    extent("AB", &ab);
    assert_true(fabs((ab.paral[1].x - ab.paral[0].x) - (wa + wb + 0.05)) < 1e-12);
    assert_true(fabs(ab.concat_point.x - (0.2 + wa + wb + 0.1)) < 1e-12);
    /* Expansion factor 2 doubles the widths (spacing scales with the height only). */
    gset_char_space(0);
    gset_char_expan(2);
    extent("AB", &ab);
    assert_true(fabs((ab.paral[1].x - ab.paral[0].x) - 2 * (wa + wb)) < 1e-12);
    /* Right alignment: the extent ends at the position. */
    gset_char_expan(1);
    Gtext_align al = { GHOR_RIGHT, GVERT_TOP };
    gset_text_align(&al);
    extent("AB", &ab);
    assert_true(fabs(ab.paral[1].x - 0.2) < 1e-15 && fabs(ab.paral[2].y - 0.3) < 1e-15);
    /* Errors. */
    Gint e;
    Gpoint pos = { 0, 0 };
    ginq_text_extent(1, &pos, "	", &e, &ab);
    assert_int_equal(e, 101);
    ginq_text_extent(4, &pos, "x", &e, &ab);
    assert_int_equal(e, 25);
    Gpoint nanpos = { NAN, 0 };
    ginq_text_extent(1, &nanpos, "x", &e, &ab);
    assert_int_equal(e, 308);
    /* TEXT EXTENT 3 in the plane y = const with up = +z: the extent is vertical. */
    al = (Gtext_align){ GHOR_NORM, GVERT_NORM };
    gset_text_align(&al);
    Gpoint3 p3 = { 0, 1, 0 };
    Gvec3 d[2] = { { 1, 0, 0 }, { 0, 0, 1 } };
    Gtext_extent3 e3;
    ginq_text_extent3(1, &p3, d, "AB", &e, &e3);
    assert_int_equal(e, 0);
    assert_true(fabs(e3.paral[2].y - 1) < 1e-15 && fabs(e3.paral[2].z - 0.1 * 25.0 / 21.0) < 1e-12);
    Gvec3 bad[2] = { { 1, 0, 0 }, { 1, 0, 0 } };
    ginq_text_extent3(1, &p3, bad, "AB", &e, &e3);
    assert_int_equal(e, 2000);
}

/* The derived stroke faces (RAL GKS's numbers): accepted in bundles, realized, measured
 * and drawn with strokes of their own; other negative numbers still report 76. */
static int n_strokes_of(const char *s)
{
    cap.n = 0;
    gtext(&(Gpoint){ 0.1, 0.5 }, s);
    expect_no_error();
    return cap.n;
}

static void test_derived_fonts(void **state)
{
    (void)state;
    static const int faces[] = { -101, -102, -104, -105, -106, -107 };
    for (int i = 0; i < 6; i++) {
        gset_text_rep(1, 2, &(Gtext_bundle){ { faces[i], GPREC_STROKE }, 1.0, 0.0, 1 });
        expect_no_error();
        Gint e;
        Gtext_bundle r;
        ginq_text_rep(1, 2, GINQ_REALIZED, &e, &r);
        assert_true(e == 0 && r.text_font_prec.font == faces[i]);
    }
    gset_text_rep(1, 3, &(Gtext_bundle){ { -103, GPREC_STROKE }, 1.0, 0.0, 1 });
    expect_error(76, GFN_STXR);
    /* STRING precision of a derived face is available too (drawn as STROKE). */
    gset_text_rep(1, 3, &(Gtext_bundle){ { -104, GPREC_STRING }, 1.0, 0.0, 1 });
    expect_no_error();

    gset_char_ht(0.1);
    Gtext_extent plain, bold, serif, italic;
    extent("HIH", &plain);
    int n_plain = n_strokes_of("HIH"); /* H: 3 strokes, I: 1 */
    assert_int_equal(n_plain, 7);
    gset_text_font_prec(&(Gtext_font_prec){ -101, GPREC_STROKE });
    assert_int_equal(n_strokes_of("HIH"), 7);
    gset_text_font_prec(&(Gtext_font_prec){ -102, GPREC_STROKE });
    extent("HIH", &bold);
    assert_int_equal(n_strokes_of("HIH"), 21); /* each stroke three times */
    /* bold advances are 1 font unit (0.1 / 21) wider per character */
    double wp = plain.paral[1].x - plain.paral[0].x, wb = bold.paral[1].x - bold.paral[0].x;
    assert_true(fabs(wb - (wp + 3 * 0.1 / 21.0)) < 1e-12);
    gset_text_font_prec(&(Gtext_font_prec){ -104, GPREC_STROKE });
    extent("HIH", &serif);
    /* serifs at the 4 free stem ends of each H and the 2 of I */
    assert_int_equal(n_strokes_of("HIH"), 7 + 10);
    assert_true(fabs((serif.paral[1].x - serif.paral[0].x) - wp) < 1e-12);
    gset_text_font_prec(&(Gtext_font_prec){ -105, GPREC_STROKE });
    extent("HIH", &italic);
    assert_int_equal(n_strokes_of("HIH"), 17);
    assert_true(fabs((italic.paral[1].x - italic.paral[0].x) - wp) < 1e-12);
    gset_text_font_prec(&(Gtext_font_prec){ -106, GPREC_STROKE });
    assert_int_equal(n_strokes_of("HIH"), 51);
    /* an unsupported font falls back to font 1 (ISO 7942 4.4.5) */
    gset_text_font_prec(&(Gtext_font_prec){ -103, GPREC_STROKE });
    expect_no_error();
    assert_int_equal(n_strokes_of("HIH"), 7);
    extent("HIH", &italic);
    assert_true(fabs((italic.paral[1].x - italic.paral[0].x) - wp) < 1e-12);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_defaults, setup, teardown),
        cmocka_unit_test_setup_teardown(test_individual_round_trips, setup, teardown),
        cmocka_unit_test_setup_teardown(test_setter_errors, setup, teardown),
        cmocka_unit_test_setup_teardown(test_representations, setup, teardown),
        cmocka_unit_test_setup_teardown(test_description_tables, setup, teardown),
        cmocka_unit_test_setup_teardown(test_asf_resolution_at_driver, setup, teardown),
        cmocka_unit_test_setup_teardown(test_area_attrs_kept_and_renewed, setup, teardown),
        cmocka_unit_test_setup_teardown(test_area_attr_gen, setup, teardown),
        cmocka_unit_test_setup_teardown(test_asf_in_pixels, setup, teardown),
        cmocka_unit_test_setup_teardown(test_text_extent, setup, teardown),
        cmocka_unit_test_setup_teardown(test_derived_fonts, setup, teardown),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    cap_free();
    return r;
}
