/* SPDX-License-Identifier: MIT */
/* test_named_constants.c -- the ISO C binding's named line types, marker types and this
 * library's hatch styles (gks.h) in use: every name is a value the PNG workstation lists in
 * its facilities, and setting an attribute by name reads back that value. The values
 * themselves are asserted by the generated test_constants_c (iso_c_constants.txt). */
#include <gks.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

static int contains(const Gint_list *l, Gint v)
{
    for (Gint i = 0; i < l->num_ints; i++)
        if (l->ints[i] == v)
            return 1;
    return 0;
}

static void test_facilities_list_the_names(void **state)
{
    (void)state;
    static const Gint lines[] = { GLINE_SOLID, GLINE_DASH, GLINE_DOT, GLINE_DASH_DOT };
    static const Gint markers[] = { GMARKER_DOT, GMARKER_PLUS, GMARKER_ASTERISK, GMARKER_CIRCLE,
                                    GMARKER_CROSS };
    static const Gint hatches[] = { GHATCH_HOR, GHATCH_VERT, GHATCH_DIAG_45, GHATCH_DIAG_135,
                                    GHATCH_CROSS, GHATCH_DIAG_CROSS, GHATCH_HOR_DENSE,
                                    GHATCH_VERT_DENSE, GHATCH_DIAG_45_DENSE,
                                    GHATCH_DIAG_135_DENSE, GHATCH_CROSS_DENSE,
                                    GHATCH_DIAG_CROSS_DENSE };
    Gint buf[32], err = -1, len = 0;
    gopen_gks(NULL, 0);
    Gline_facs lf = { .types = { 0, buf } };
    ginq_line_facs(GWS_TYPE_PNG, 32, 0, &err, &lf, &len);
    assert_int_equal(err, 0);
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++)
        assert_true(contains(&lf.types, lines[i]));
    Gmarker_facs mf = { .types = { 0, buf } };
    ginq_marker_facs(GWS_TYPE_PNG, 32, 0, &err, &mf, &len);
    assert_int_equal(err, 0);
    for (size_t i = 0; i < sizeof markers / sizeof markers[0]; i++)
        assert_true(contains(&mf.types, markers[i]));
    Gfill_facs ff = { .hatch_styles = { 0, buf } };
    ginq_fill_facs(GWS_TYPE_PNG, 32, 0, &err, &ff, &len);
    assert_int_equal(err, 0);
    assert_int_equal(len, (Gint)(sizeof hatches / sizeof hatches[0]));
    for (size_t i = 0; i < sizeof hatches / sizeof hatches[0]; i++)
        assert_true(contains(&ff.hatch_styles, hatches[i]));
    gclose_gks();
}

static void test_set_by_name_reads_back(void **state)
{
    (void)state;
    Gint err = -1, v = 0;
    gopen_gks(NULL, 0);
    gset_linetype(GLINE_DASH_DOT);
    ginq_linetype(&err, &v);
    assert_int_equal(err, 0);
    assert_int_equal(v, 4);
    gset_marker_type(GMARKER_CIRCLE);
    ginq_marker_type(&err, &v);
    assert_int_equal(v, 4);
    gset_fill_int_style(GSTYLE_HATCH);
    gset_fill_style_ind(GHATCH_DIAG_45);
    ginq_fill_style_ind(&err, &v);
    assert_int_equal(v, -3);
    /* a picture with every hatch style by name, to look at: named_hatches.png */
    gopen_ws(1, "named_hatches", GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_vp(1, &(Glimit){ 0, 240, 0, 160 });
    gset_ws_win(1, &(Glimit){ 0, 1.5, 0, 1 });
    gset_win(1, &(Glimit){ 0, 1.5, 0, 1 });
    gset_vp(1, &(Glimit){ 0, 1.5, 0, 1 });
    gsel_norm_tran(1);
    for (int k = 1; k <= 12; k++) {
        double x = 0.25 * ((k - 1) % 6), y = k <= 6 ? 0.5 : 0.0;
        Gpoint p[4] = { { x + 0.02, y + 0.02 }, { x + 0.23, y + 0.02 }, { x + 0.23, y + 0.48 },
                        { x + 0.02, y + 0.48 } };
        gset_fill_style_ind(-k);
        gfill_area(&(Gpoint_list){ 4, p });
    }
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_facilities_list_the_names),
        cmocka_unit_test(test_set_by_name_reads_back),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
