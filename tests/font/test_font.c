/* SPDX-License-Identifier: MIT */
/*
 * test_font.c -- the stroke font module (src/c/font): font 1's glyphs and metrics, and the
 * faces derived from it (bold, seriffed, italic) with their rules.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "gks_font.h"

static void test_font(void **state)
{
    (void)state;
    gks_font_metrics m;
    gks_font_get_metrics(1, &m);
    assert_true(m.cap == 21 && m.base == 0 && m.bottom == -7 && m.half == 10.5 && m.top == 25);
    gks_glyph g;
    for (int ch = 32; ch <= 126; ch++) {
        assert_int_equal(gks_font_get_glyph(1, ch, &g), 0);
        assert_true(g.advance >= 8 && g.advance <= m.max_advance);
        if (ch == ' ') {
            assert_int_equal(g.n_strokes, 0);
            continue;
        }
        assert_true(g.n_strokes >= 1);
        int total = 0;
        for (int s = 0; s < g.n_strokes; s++) {
            assert_true(g.stroke_len[s] >= 2);
            total += g.stroke_len[s];
        }
        assert_int_equal(total, g.n_points);
        for (int k = 0; k < g.n_points; k++) {
            assert_true(g.xy[2 * k] >= 0 && g.xy[2 * k] <= g.advance);
            assert_true(g.xy[2 * k + 1] >= m.bottom && g.xy[2 * k + 1] <= m.top);
        }
    }
    /* spot checks: 'I' is one vertical stroke at cap height; 'H' has three */
    gks_font_get_glyph(1, 'I', &g);
    assert_int_equal(g.n_points, 2);
    assert_true(g.xy[1] == 21 && g.xy[3] == 0 && g.xy[0] == g.xy[2]);
    gks_font_get_glyph(1, 'H', &g);
    assert_int_equal(g.n_strokes, 3);
    gks_glyph q;
    gks_font_get_glyph(1, '?', &q);
    assert_int_equal(gks_font_get_glyph(1, 200, &g), GKS_FONT_E_ARG);
    assert_memory_equal(&g, &q, sizeof g);
    assert_int_equal(gks_font_get_glyph(1, 'A', NULL), GKS_FONT_E_ARG);
}

/* The derived faces: bold = three copies, serifs at free steep ends, italic = shear. */
static void test_font_faces(void **state)
{
    (void)state;
    static const int all[] = { 1, -101, -102, -104, -105, -106, -107 };
    gks_font_metrics m1, mb;
    gks_font_get_metrics(1, &m1);
    gks_glyph g, s, q;
    for (int f = 0; f < 7; f++) {
        assert_true(gks_font_has(all[f]));
        gks_font_get_metrics(all[f], &mb);
        for (int ch = 32; ch <= 126; ch++) {
            assert_int_equal(gks_font_get_glyph(all[f], ch, &g), 0);
            assert_true(g.advance <= mb.max_advance);
            int total = 0;
            for (int k = 0; k < g.n_strokes; k++) {
                assert_true(g.stroke_len[k] >= 2);
                total += g.stroke_len[k];
            }
            assert_int_equal(total, g.n_points);
            for (int k = 0; k < g.n_points; k++)
                assert_true(g.xy[2 * k + 1] >= m1.bottom && g.xy[2 * k + 1] <= m1.top);
        }
    }
    assert_false(gks_font_has(-103) || gks_font_has(0) || gks_font_has(2));
    gks_font_get_metrics(-102, &mb);
    assert_true(mb.max_advance == m1.max_advance + 1 && mb.cap == m1.cap);
    /* bold 'I': the stem at x, x + 0.5, x + 1; advance + 1 */
    gks_font_get_glyph(1, 'I', &q);
    gks_font_get_glyph(-102, 'I', &g);
    assert_int_equal(g.n_strokes, 3);
    assert_true(g.advance == q.advance + 1 && g.xy[4] == q.xy[0] + 0.5 && g.xy[8] == q.xy[0] + 1);
    /* seriffed 'I': two serifs, centred on the stem at the cap and base lines */
    gks_font_get_glyph(-104, 'I', &s);
    assert_int_equal(s.n_strokes, 3);
    assert_true(s.xy[5] == 21 && s.xy[7] == 21 && s.xy[4] == q.xy[0] - 2 && s.xy[6] == q.xy[0] + 2);
    assert_true(s.xy[9] == 0 && s.xy[11] == 0);
    /* no serif at a junction ('A' apex) or on a closed loop ('O'); 'A' gets its two feet */
    gks_font_get_glyph(1, 'A', &q);
    gks_font_get_glyph(-104, 'A', &g);
    assert_int_equal(g.n_strokes, q.n_strokes + 2);
    gks_font_get_glyph(1, 'O', &q);
    gks_font_get_glyph(-104, 'O', &g);
    assert_int_equal(g.n_strokes, q.n_strokes);
    /* italic: each point of the seriffed glyph moved by 0.2 * y */
    for (int ch = 33; ch <= 126; ch++) {
        gks_font_get_glyph(-104, ch, &s);
        gks_font_get_glyph(-105, ch, &g);
        assert_int_equal(g.n_points, s.n_points);
        for (int k = 0; k < g.n_points; k++)
            assert_true(fabs(g.xy[2 * k] - (s.xy[2 * k] + 0.2 * s.xy[2 * k + 1])) < 1e-12);
    }
    /* an unknown font: E_ARG and font 1's glyph */
    gks_font_get_glyph(1, 'B', &q);
    assert_int_equal(gks_font_get_glyph(-103, 'B', &g), GKS_FONT_E_ARG);
    assert_memory_equal(&g, &q, sizeof g);
    assert_int_equal(gks_font_get_glyph(-104, 'B', NULL), GKS_FONT_E_ARG);
    /* an unknown font has font 1's metrics; NULL is ignored */
    gks_font_get_metrics(-103, &mb);
    assert_memory_equal(&mb, &m1, sizeof mb);
    gks_font_get_metrics(1, NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_font),
        cmocka_unit_test(test_font_faces),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
