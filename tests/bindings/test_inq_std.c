/* SPDX-License-Identifier: MIT */
/* test_inq_std.c -- the inquiries added to complete the standard's lists: pixel readback
 * from the PNG frame buffer, colour facilities and indices, current attribute sets, 2-D
 * segment attributes, the GKS-3D description table entries, and their errors. */
#include <gks.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

static void open_png(void)
{
    gemergency_close_gks();
    gopen_gks(NULL, 0);
    gopen_ws(1, "inq_std_out", GWS_TYPE_PNG);
    gactivate_ws(1);
    /* A 100x80 image: window = unit square, viewport 100x80 DC (aspect kept: 80x80). */
    gset_ws_vp(1, &(Glimit){ 0, 100, 0, 80 });
}

static void test_pixels(void **state)
{
    (void)state;
    open_png();
    Gint e, c;
    /* Background everywhere: colour index 0. */
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 0);
    assert_int_equal(c, 0);
    /* A solid red square over [0.25, 0.75]^2 (80 pixels across the unit square). */
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(2);
    Gpoint sq[4] = { { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.75, 0.75 }, { 0.25, 0.75 } };
    gfill_area(&(Gpoint_list){ 4, sq });
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 0);
    assert_int_equal(c, 2);
    ginq_pixel(1, &(Gpoint){ 0.1, 0.5 }, &e, &c);
    assert_int_equal(c, 0);
    /* A colour no table entry has any more: invalid (-1); the picture keeps red. */
    gset_colr_rep(1, 2, &(Gcolr_rep){ .rgb = { 0.5, 0.5, 0.5 } });
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(c, -1);
    gset_colr_rep(1, 9, &(Gcolr_rep){ .rgb = { 1, 0, 0 } });
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(c, 9);
    gset_colr_rep(1, 2, &(Gcolr_rep){ .rgb = { 1, 0, 0 } });
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(c, 2); /* the lowest index of that colour */
    /* Outside the display surface: invalid. */
    ginq_pixel(1, &(Gpoint){ 1.5, 0.5 }, &e, &c);
    assert_int_equal(e, 0);
    assert_int_equal(c, -1);

    /* Dimensions: pixels whose centres lie in [0.25, 0.75]^2 -> 40 x 40. */
    Gint_size d;
    ginq_pixel_array_dims(1, &(Grect){ { 0.25, 0.75 }, { 0.75, 0.25 } }, &e, &d);
    assert_int_equal(e, 0);
    assert_int_equal(d.size_x, 40);
    assert_int_equal(d.size_y, 40);

    /* A 4 x 2 array straddling the red square's left edge at pixel 20 (x = 0.25). */
    Gint buf[8], len;
    Gpres_inval inv;
    Gint_list l = { 0, buf };
    ginq_pixel_array(1, &(Gpoint){ 18.5 / 80, 0.5 }, &(Gint_size){ 4, 2 }, 8, 0, &e, &inv,
                     &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 8);
    assert_int_equal(l.num_ints, 8);
    assert_int_equal(inv, GINVAL_ABSENT);
    Gint want[8] = { 0, 0, 2, 2, 0, 0, 2, 2 };
    assert_memory_equal(buf, want, sizeof want);
    /* The list convention: start 5, room for 2. */
    ginq_pixel_array(1, &(Gpoint){ 18.5 / 80, 0.5 }, &(Gint_size){ 4, 2 }, 2, 5, &e, &inv,
                     &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(l.num_ints, 2);
    assert_int_equal(buf[0], 0);
    assert_int_equal(buf[1], 2);
    ginq_pixel_array(1, &(Gpoint){ 0.5, 0.5 }, &(Gint_size){ 4, 2 }, 2, 8, &e, &inv, &l, &len);
    assert_int_equal(e, 2002);
    ginq_pixel_array(1, &(Gpoint){ 0.5, 0.5 }, &(Gint_size){ 0, 2 }, 2, 0, &e, &inv, &l, &len);
    assert_int_equal(e, 91);
    /* Errors: 25 not open, 20 bad id, 40 no readback (null workstation), 7 state. */
    ginq_pixel(2, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 25);
    ginq_pixel(-1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 20);
    gopen_ws(2, NULL, GWS_TYPE_NULL);
    ginq_pixel(2, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 40);
    gopen_ws(3, NULL, GWS_TYPE_WISS);
    ginq_pixel(3, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 39);
    gemergency_close_gks();
    gopen_gks(NULL, 0);
    ginq_pixel(1, &(Gpoint){ 0.5, 0.5 }, &e, &c);
    assert_int_equal(e, 7);
    gclose_gks();
}

static void test_colours(void **state)
{
    (void)state;
    open_png();
    Gint e, len, buf[300];
    Gcolr_facs f;
    ginq_colr_facs(GWS_TYPE_PNG, &e, &f);
    assert_int_equal(e, 0);
    assert_int_equal(f.num_colrs, 256);
    assert_int_equal(f.colr_avail, GAVAIL_COLR);
    assert_int_equal(f.num_pred_inds, 8);
    Gcolr_rep r;
    ginq_pred_colr_rep(GWS_TYPE_PNG, 2, &e, &r);
    assert_int_equal(e, 0);
    assert_true(r.rgb.red == 1 && r.rgb.green == 0 && r.rgb.blue == 0);
    ginq_pred_colr_rep(GWS_TYPE_PNG, 8, &e, &r);
    assert_int_equal(e, 95);
    ginq_pred_colr_rep(GWS_TYPE_PNG, -1, &e, &r);
    assert_int_equal(e, 93);
    ginq_colr_facs(GWS_TYPE_MO, &e, &f);
    assert_int_equal(e, 39);
    ginq_colr_facs(77, &e, &f);
    assert_int_equal(e, 23);
    Gint_list l = { 0, buf };
    ginq_list_colr_inds(1, 300, 0, &e, &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(len, 8);
    gset_colr_rep(1, 40, &(Gcolr_rep){ .rgb = { 0.1, 0.2, 0.3 } });
    ginq_list_colr_inds(1, 300, 0, &e, &l, &len);
    assert_int_equal(len, 9);
    assert_int_equal(buf[8], 40);
    ginq_list_colr_inds(1, 2, 7, &e, &l, &len);
    assert_int_equal(e, 0);
    assert_int_equal(l.num_ints, 2);
    assert_int_equal(buf[0], 7);
    assert_int_equal(buf[1], 40);
    ginq_list_colr_inds(1, 2, 9, &e, &l, &len);
    assert_int_equal(e, 2002);
    gemergency_close_gks();
}

static void test_attr_sets(void **state)
{
    (void)state;
    gemergency_close_gks();
    Gint e;
    Gprim_attrs p;
    ginq_cur_prim_attrs(&e, &p);
    assert_int_equal(e, 8);
    gopen_gks(NULL, 0);
    gset_char_ht(0.05);
    gset_char_up_vec(&(Gvec){ -1, 0 });
    gset_pat_size(0.2, 0.3);
    gset_pat_ref_point(&(Gpoint){ 0.4, 0.6 });
    gset_fill_ind(3);
    ginq_cur_prim_attrs(&e, &p);
    assert_int_equal(e, 0);
    assert_int_equal(p.fill_ind, 3);
    assert_true(p.char_ht == 0.05 && p.char_up_vec.delta_x == -1);
    assert_true(fabs(p.char_base_vec.delta_x) < 1e-12 && fabs(p.char_base_vec.delta_y - 1) < 1e-12);
    assert_true(fabs(p.pat_width_vec.delta_x - 0.2) < 1e-12 && p.pat_width_vec.delta_y == 0);
    assert_true(p.pat_ht_vec.delta_x == 0 && fabs(p.pat_ht_vec.delta_y - 0.3) < 1e-12);
    assert_true(p.pat_ref_point.x == 0.4 && p.pat_ref_point.y == 0.6);
    Gprim_attrs3 p3;
    gset_view_ind(2);
    ginq_cur_prim_attrs3(&e, &p3);
    assert_int_equal(e, 0);
    assert_int_equal(p3.view_ind, 2);
    assert_int_equal(p3.attrs.fill_ind, 3);
    gset_linetype(3);
    gset_asfs(&(Gasfs){ .linetype = GASF_BUNDLED });
    gset_edgewidth(2.5);
    Gindiv_attrs ia;
    ginq_cur_indiv_attrs(&e, &ia);
    assert_int_equal(e, 0);
    assert_int_equal(ia.linetype, 3);
    assert_int_equal(ia.asfs.linetype, GASF_BUNDLED);
    Gindiv_attrs3 ia3;
    ginq_cur_indiv_attrs3(&e, &ia3);
    assert_true(ia3.edgewidth == 2.5 && ia3.attrs.linetype == 3);
    Gtran3 t;
    gset_win3(1, &(Glimit3){ 0, 2, 0, 4, 0, 8 });
    ginq_norm_tran3(1, &e, &t);
    assert_int_equal(e, 0);
    assert_true(t.win.y_max == 4 && t.win.z_max == 8 && t.vp.x_max == 1);
    ginq_norm_tran3(99, &e, &t);
    assert_int_equal(e, 50);
    Gclip3 c;
    gsel_norm_tran(1);
    ginq_clip3(&e, &c);
    assert_int_equal(c.clip_ind, GIND_CLIP);
    assert_true(c.clip_vol.z_max == 1);
    gclose_gks();
}

static void test_segments_and_tables(void **state)
{
    (void)state;
    gemergency_close_gks();
    gopen_gks(NULL, 0);
    gopen_ws(1, NULL, GWS_TYPE_NULL);
    gactivate_ws(1);
    gcreate_seg(5);
    gclose_seg();
    Gtran_matrix m = { { 2, 0, 0.5 }, { 0, 3, 0.25 } };
    gset_seg_tran(5, m);
    Gint e;
    Gseg_attrs a;
    ginq_seg_attrs(5, &e, &a);
    assert_int_equal(e, 0);
    assert_true(a.tran_matrix[0][0] == 2 && a.tran_matrix[0][2] == 0.5 &&
                a.tran_matrix[1][1] == 3 && a.tran_matrix[1][2] == 0.25);
    ginq_seg_attrs(6, &e, &a);
    assert_int_equal(e, 122);

    Gdyn_mod_ws_attrs3 dm;
    ginq_dyn_mod_ws_attrs3(GWS_TYPE_PNG, &e, &dm);
    assert_int_equal(e, 0);
    assert_int_equal(dm.attrs.colr_rep, GDYN_IRG);
    Gdefer_mode dd;
    Girg_mode di;
    ginq_def_defer_sts(GWS_TYPE_PNG, &e, &dd, &di);
    assert_int_equal(dd, GDEFER_ASAP);
    assert_int_equal(di, GIRG_SUPPR);
    Gdyn_mod_seg_attrs ds;
    ginq_dyn_mod_seg_attrs(GWS_TYPE_PNG, &e, &ds);
    assert_int_equal(ds.highl, GDYN_IMM);
    assert_int_equal(ds.tran, GDYN_IRG);
    Gdisp_space_size3 d3;
    ginq_disp_space_size3(GWS_TYPE_PNG_LARGE, &e, &d3);
    assert_int_equal(e, 0);
    assert_int_equal(d3.size_raster.size_x, 8192);
    assert_int_equal(d3.size_raster.size_z, 1);
    Gmax_ws_st_tables3 t3;
    ginq_max_ws_st_tables3(GWS_TYPE_PNG, &e, &t3);
    assert_int_equal(t3.view_reps, GKS_MAX_VIEW_IND);
    assert_int_equal(t3.colr_reps, 256);
    Gint nv;
    ginq_view_facs(GWS_TYPE_PNG, &e, &nv);
    assert_int_equal(nv, 1);
    Gview_rep3 vr;
    ginq_pred_view_rep(GWS_TYPE_PNG, 0, &e, &vr);
    assert_int_equal(e, 0);
    assert_true(vr.ori_matrix[3][3] == 1 && vr.clip_limit.z_max == 1);
    ginq_pred_view_rep(GWS_TYPE_PNG, 1, &e, &vr);
    assert_int_equal(e, 2002);
    ginq_pred_view_rep(GWS_TYPE_PNG, -1, &e, &vr);
    assert_int_equal(e, 514);
    Gint ids[8], modes[8], nid, nm;
    Gint_list li = { 0, ids }, lm = { 0, modes };
    ginq_hlhsr_facs(GWS_TYPE_PNG, 8, 0, &e, &li, &nid, &lm, &nm);
    assert_int_equal(e, 0);
    assert_int_equal(nid, 1);
    assert_int_equal(nm, 5);
    assert_int_equal(modes[4], GHLHSR_RAYTRACE);
    Gint na;
    Gattrs at[5];
    ginq_gdp(GWS_TYPE_PNG, 12345, &e, &na, at);
    assert_int_equal(e, 41);
    Gstore s = NULL;
    gcreate_store(&e, &s);
    assert_int_equal(e, 0);
    assert_non_null(s);
    gdel_store(s);
    gdel_store(NULL);
    gemergency_close_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pixels),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_attr_sets),
        cmocka_unit_test(test_segments_and_tables),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
