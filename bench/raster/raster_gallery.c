/* SPDX-License-Identifier: MIT */
/*
 * raster_gallery.c -- renders every primitive and style of the raster module into one
 * picture for visual inspection: the stroke font (src/c/font), hatch styles, pattern, cell array,
 * linetypes and widths, markers, holes, a self-intersecting star and interpenetrating
 * z-buffered triangles. Usage: raster_gallery out.png [ss]
 */
#include "raster.h"
#include "gks_font.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void text(gks_raster_fb *fb, const char *s, double x, double y, double scale,
                 const float rgb[3])
{
    gks_raster_line a = {.rgb = {rgb[0], rgb[1], rgb[2]}, .width = 1, .type = 1};
    for (; *s; s++) {
        gks_glyph g;
        gks_font_get_glyph(1, (unsigned char)*s, &g);
        const double *xy = g.xy;
        for (int k = 0; k < g.n_strokes; k++) {
            gks_raster_pt p[GKS_GLYPH_MAX_POINTS];
            for (int i = 0; i < g.stroke_len[k]; i++)
                p[i] = (gks_raster_pt){x + scale * xy[2 * i], y + scale * xy[2 * i + 1], 0};
            gks_raster_polyline(fb, (size_t)g.stroke_len[k], p, &a);
            xy += 2 * g.stroke_len[k];
        }
        x += scale * g.advance;
    }
}

static void square(gks_raster_pt *p, double x, double y, double s)
{
    p[0] = (gks_raster_pt){x, y, 0};
    p[1] = (gks_raster_pt){x + s, y, 0};
    p[2] = (gks_raster_pt){x + s, y + s, 0};
    p[3] = (gks_raster_pt){x, y + s, 0};
}

int main(int argc, char **argv)
{
    if (argc < 2)
        return 2;
    int ss = argc > 2 ? atoi(argv[2]) : 1;
    gks_raster_fb *fb = gks_raster_fb_create(1000, 760, ss);
    if (!fb)
        return 1;
    const float bg[3] = {1, 1, 1}, ink[3] = {0, 0, 0}, blue[3] = {0.1f, 0.2f, 0.8f};
    gks_raster_fb_clear(fb, bg);
    /* font: the whole printable set at two sizes */
    char line[40];
    for (int row = 0; row < 4; row++) {
        int n = 0;
        for (int c = 32 + row * 24; c < 32 + (row + 1) * 24 && c <= 126; c++)
            line[n++] = (char)c;
        line[n] = 0;
        text(fb, line, 10, 720 - row * 40, 1.4, ink);
    }
    text(fb, "Sphinx of black quartz, judge my vow! 0123456789", 10, 555, 0.8, blue);
    /* hatch styles -1..-6 and -7..-12, a pattern */
    int four = 4;
    for (int h = 1; h <= 12; h++) {
        gks_raster_pt sq[4];
        square(sq, 10 + (h - 1) * 62, 470, 56);
        gks_raster_fill f = {.style = GKS_RASTER_HATCH, .rgb = {0, 0, 0}, .hatch = -h};
        gks_raster_fill_area(fb, 1, &four, sq, &f);
        gks_raster_line a = {.rgb = {0, 0, 0}, .width = 1, .type = 1};
        gks_raster_pt b[5] = {sq[0], sq[1], sq[2], sq[3], sq[0]};
        gks_raster_polyline(fb, 5, b, &a);
    }
    float pat[4 * 3 * 3];
    for (int c = 0; c < 12; c++) {
        pat[3 * c] = (c % 4) / 3.0f;
        pat[3 * c + 1] = (c / 4) / 2.0f;
        pat[3 * c + 2] = 0.6f;
    }
    gks_raster_pt sq[4];
    square(sq, 760, 470, 110);
    gks_raster_fill pf = {.style = GKS_RASTER_PATTERN, .pat_nx = 4, .pat_ny = 3, .pat_rgb = pat,
                          .pat_ref = {760, 470}, .pat_u = {6, 3}, .pat_v = {-2, 7}};
    gks_raster_fill_area(fb, 1, &four, sq, &pf);
    /* cell array, rotated */
    gks_raster_pt o = {900, 470, 0}, pu = {990, 500, 0}, pv = {880, 560, 0};
    gks_raster_cell_array(fb, &o, &pu, &pv, 4, 3, pat, NULL);
    /* linetypes at widths 1, 2.5, 6 */
    for (int t = 1; t <= 4; t++)
        for (int w = 0; w < 3; w++) {
            double width = w == 0 ? 1 : w == 1 ? 2.5 : 6;
            gks_raster_line a = {.rgb = {0.6f, 0, 0}, .width = width, .type = t};
            double y0 = 430 - (t - 1) * 45 - w * 14;
            gks_raster_pt p[4] = {{10, y0, 0}, {150, y0, 0}, {190, y0 - 8, 0}, {300, y0 + 4, 0}};
            gks_raster_polyline(fb, 4, p, &a);
        }
    /* markers 1..5 at sizes 4, 8, 16, 32 */
    for (int t = 1; t <= 5; t++)
        for (int s = 0; s < 4; s++) {
            gks_raster_line a = {.rgb = {0, 0.4f, 0}, .width = s == 3 ? 2 : 1, .type = 1};
            gks_raster_pt p = {340 + s * 45, 420 - (t - 1) * 45, 0};
            gks_raster_markers(fb, 1, &p, t, 4 << s, &a);
        }
    /* polygon with a hole, and a self-intersecting star (even-odd) */
    gks_raster_pt ring[8] = {{560, 260, 0}, {700, 260, 0}, {700, 420, 0}, {560, 420, 0},
                             {600, 300, 0}, {660, 300, 0}, {660, 380, 0}, {600, 380, 0}};
    int counts[2] = {4, 4};
    gks_raster_fill solid = {.style = GKS_RASTER_SOLID, .rgb = {0.9f, 0.6f, 0.1f}};
    gks_raster_fill_area(fb, 2, counts, ring, &solid);
    gks_raster_pt star[5];
    for (int k = 0; k < 5; k++) {
        double a = 3.14159265 / 2 + k * 4 * 3.14159265 / 5;
        star[k] = (gks_raster_pt){820 + 90 * cos(a), 330 + 90 * sin(a), 0};
    }
    int five = 5;
    solid.rgb[0] = 0.2f; solid.rgb[1] = 0.5f; solid.rgb[2] = 0.9f;
    gks_raster_fill_area(fb, 1, &five, star, &solid);
    /* interpenetrating z-buffered triangles, and a hidden-line pass over them */
    gks_raster_pt tr[6] = {{50, 20, 0.1}, {450, 60, 0.9}, {250, 220, 0.5},
                           {50, 180, 0.9}, {450, 40, 0.1}, {300, 210, 0.5}};
    float cols[6] = {0.9f, 0.2f, 0.2f, 0.2f, 0.8f, 0.3f};
    gks_raster_fill zf = {.style = GKS_RASTER_SOLID, .zmode = GKS_RASTER_Z_TEST};
    gks_raster_triangles(fb, 2, tr, cols, &zf);
    gks_raster_fill zo = {.style = GKS_RASTER_SOLID, .zmode = GKS_RASTER_Z_ONLY};
    gks_raster_pt tr2[6];
    for (int k = 0; k < 6; k++)
        tr2[k] = (gks_raster_pt){tr[k].x + 500, tr[k].y, tr[k].z};
    gks_raster_triangles(fb, 2, tr2, NULL, &zo);
    gks_raster_line hl = {.rgb = {0, 0, 0}, .width = 1.5, .type = 1,
                          .zmode = GKS_RASTER_Z_TEST, .zbias = 2e-3f};
    for (int t = 0; t < 2; t++) {
        gks_raster_pt e[4] = {tr2[3 * t], tr2[3 * t + 1], tr2[3 * t + 2], tr2[3 * t]};
        gks_raster_polyline(fb, 4, e, &hl);
    }
    int rc = gks_raster_fb_write_png(fb, argv[1], GKS_RASTER_PNG_FAST);
    gks_raster_fb_free(fb);
    return rc;
}
