/* SPDX-License-Identifier: MIT */
/*
 * test_png_render.c -- the PNG workstation's rendering (ws_png.c, ws_classic.c) at the
 * driver level: gks_prim values handed to gks_ws_png_driver on a workstation state list
 * built here (identity view, workstation window = NPC unit square, one DC unit = one
 * pixel), the written PNG read back.
 *
 * Exactness: without anti-aliasing every pixel is either untouched or takes a primitive's
 * colour exactly, so structural checks compare exact colours. Reference images
 * (tests/core/ref/NAME.ref.png, painter and hidden-line modes) allow a tolerance: a pixel
 * matches if every channel differs by at most 2, and at most REF_MAX_BAD_PERMILLE of the
 * pixels may mismatch -- pixels whose centres lie within rounding distance of an edge can
 * change sides when a compiler contracts a*b+c into an FMA or evaluates in other precision.
 * On a mismatch NAME.diff.png is written (mismatching pixels red on grey) and
 * NAME.out.png kept. GKS_UPDATE_REFS=1 in the environment rewrites the references.
 */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>
#include "ws_driver.h"
#include "gks_ws.h" /* gks_ws_core_host: the file claims of a workstation */
#include "ws_classic.h"
#include "raster.h"
#include "png_util.h"
#include "gks_alloc.h"

/* The whole picture through gks_raster_fb_resolve_row: width x height 8-bit RGB, row 0 =
 * top (the test's own; the library resolves row by row). */
static int fb_resolve(const gks_raster_fb *fb, unsigned char *rgb8)
{
    if (!fb || !rgb8)
        return GKS_RASTER_E_ARG;
    for (int row = 0; row < fb->height; row++)
        gks_raster_fb_resolve_row(fb, row, rgb8 + (size_t)row * (size_t)fb->width * 3);
    return GKS_RASTER_OK;
}

/* The reference images: tests/core/ref next to this source file. */
static void ref_path(char *buf, size_t n, const char *name)
{
    const char *f = __FILE__, *slash = strrchr(f, '/');
    int dir = slash ? (int)(slash - f) : 0;
    snprintf(buf, n, "%.*s%sref/%s.ref.png", dir, f, slash ? "/" : "", name);
}
#define REF_MAX_BAD_PERMILLE 10

static const Grgb WHITE = { 1, 1, 1 }, BLACK = { 0, 0, 0 }, RED = { 1, 0, 0 },
                  GREEN = { 0, 1, 0 }, BLUE = { 0, 0, 1 };

/* A PNG workstation state list of w x h pixels in HLHSR mode `mode`, opened. */
static gks_ws *ws_new(const char *name, int w, int h, int mode)
{
    gks_ws *ws = calloc(1, sizeof *ws);
    assert_non_null(ws);
    ws->id = 1;
    ws->conn_id = strdup(name);
    ws->drv = &gks_ws_png_driver;
    ws->host = &gks_ws_core_host;
    ws->state = GWS_ACTIVE;
    ws->cur_win = ws->req_win = (Glimit3){ 0, 1, 0, (double)h / w, 0, 1 };
    ws->cur_vp = ws->req_vp = (Glimit3){ 0, w, 0, h, 0, 1 };
    ws->colr = calloc(256, sizeof *ws->colr);
    ws->colr[0] = WHITE;
    for (int v = 0; v <= GKS_MAX_VIEW_IND; v++) {
        Gview_rep3 *r = &ws->views[v];
        for (int i = 0; i < 4; i++)
            for (int j = 0; j < 4; j++)
                r->ori_matrix[i][j] = r->map_matrix[i][j] = i == j;
        r->clip_limit = (Glimit3){ 0, 1, 0, 1, 0, 1 };
        r->xy_clip = r->back_clip = r->front_clip = GIND_CLIP;
    }
    ws->hlhsr_mode = mode;
    char path[256];
    snprintf(path, sizeof path, "%s.png", name);
    unlink(path);
    assert_int_equal(ws->drv->open(ws), 0);
    return ws;
}

/* Writes the picture, closes, reads it back. */
static void ws_finish(gks_ws *ws, image *img)
{
    char path[256];
    snprintf(path, sizeof path, "%s.png", ws->conn_id);
    assert_int_equal(ws->drv->update(ws), 0);
    ws->drv->close(ws);
    assert_true(read_png(path, img));
    unlink(path);
    for (int k = 0; k < ws->n_files; k++) /* frame files claimed by png_update */
        gks_free(ws->files[k]);
    gks_free(ws->files);
    free(ws->colr);
    free(ws->conn_id);
    free(ws);
}

static gks_prim attrs_default(gks_prim_kind kind, Grgb c)
{
    gks_prim p = { .kind = kind, .n_loops = 1, .colour = c };
    p.attrs.linetype = 1;
    p.attrs.linewidth = 1;
    p.attrs.marker_type = 3;
    p.attrs.marker_size = 1;
    p.attrs.int_style = GSTYLE_SOLID;
    p.attrs.edgetype = 1;
    p.attrs.edgewidth = 1;
    p.attrs.edge_colour = BLACK;
    return p;
}

static int draw_area(gks_ws *ws, gks_prim p, int n_loops, const int *counts,
                     const Gpoint3 *pts)
{
    int n = 0;
    for (int k = 0; k < n_loops; k++)
        n += counts[k];
    p.kind = GKS_PRIM_FILL_AREA;
    p.n_loops = n_loops;
    p.loop_counts = counts;
    p.n_points = n;
    p.pts = pts;
    return ws->drv->primitive(ws, &p);
}

static int draw_line(gks_ws *ws, gks_prim p, int n, const Gpoint3 *pts)
{
    p.n_loops = 1;
    p.n_points = n;
    p.pts = pts;
    return ws->drv->primitive(ws, &p);
}

static int is(const image *img, int x, int y, Grgb c)
{
    const unsigned char *q = px(img, x, y);
    return q[0] == lrint(255 * c.red) && q[1] == lrint(255 * c.green) &&
           q[2] == lrint(255 * c.blue);
}

static void expect(const image *img, int x, int y, Grgb c)
{
    if (!is(img, x, y, c)) {
        const unsigned char *q = px(img, x, y);
        fail_msg("pixel (%d,%d) = %d %d %d, want %g %g %g", x, y, q[0], q[1], q[2],
                 255 * c.red, 255 * c.green, 255 * c.blue);
    }
}

static int count_colour(const image *img, Grgb c)
{
    int n = 0;
    for (int y = 0; y < img->h; y++)
        for (int x = 0; x < img->w; x++)
            n += is(img, x, y, c);
    return n;
}

/* Even-odd inside test in DC (pixels). */
static int inside_eo(const double (*p)[2], int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((p[i][1] > y) != (p[j][1] > y) &&
            x < p[j][0] + (y - p[j][1]) * (p[i][0] - p[j][0]) / (p[i][1] - p[j][1]))
            in = !in;
    return in;
}

/* A concave, self-intersecting polygon covers exactly the pixels whose centres it
 * contains (even-odd), in every HLHSR mode that fills. */
static void test_fill_coverage(void **u)
{
    (void)u;
    const int W = 64;
    /* a star-like self-intersecting 7-gon and a concave arrow, in NDC */
    const Gpoint3 star[7] = { { 0.1, 0.13, 0.5 }, { 0.87, 0.41, 0.5 }, { 0.17, 0.83, 0.5 },
                              { 0.53, 0.07, 0.5 }, { 0.71, 0.91, 0.5 }, { 0.05, 0.47, 0.5 },
                              { 0.93, 0.2, 0.5 } };
    int modes[] = { GHLHSR_NONE, GHLHSR_ZBUFFER, GHLHSR_PAINTER };
    for (int m = 0; m < 3; m++) {
        gks_ws *ws = ws_new("t_cover", W, W, modes[m]);
        int c = 7;
        assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, RED), 1, &c, star), 0);
        image img;
        ws_finish(ws, &img);
        double dc[7][2];
        for (int i = 0; i < 7; i++) {
            dc[i][0] = star[i].x * W;
            dc[i][1] = star[i].y * W;
        }
        int n_in = 0;
        for (int y = 0; y < W; y++)
            for (int x = 0; x < W; x++) {
                int in = inside_eo((const double (*)[2])dc, 7, x + 0.5, y + 0.5);
                n_in += in;
                expect(&img, x, y, in ? RED : WHITE);
            }
        assert_true(n_in > 500);
        free(img.rgb);
    }
}

/* View clipping: the xy clip limits [0.25,0.75] remove what lies outside (polygon
 * clipping, the pixels with centres inside the window are kept); with the indicator
 * off only the workstation window clips. The back clip (z_min 0.4) removes a quad
 * lying beyond it. */
static void test_clipping(void **u)
{
    (void)u;
    const int W = 40;
    for (int on = 0; on < 2; on++) {
        gks_ws *ws = ws_new("t_clip", W, W, GHLHSR_NONE);
        ws->views[1].clip_limit = (Glimit3){ 0.25, 0.75, 0.25, 0.75, 0.4, 1 };
        ws->views[1].xy_clip = on ? GIND_CLIP : GIND_NO_CLIP;
        gks_prim p = attrs_default(GKS_PRIM_FILL_AREA, BLUE);
        p.view_ind = 1;
        const Gpoint3 big[4] = { { -5, -5, 0.5 }, { 5, -5, 0.5 }, { 5, 5, 0.5 }, { -5, 5, 0.5 } };
        const Gpoint3 far[4] = { { 0, 0, 0.2 }, { 1, 0, 0.2 }, { 1, 1, 0.2 }, { 0, 1, 0.2 } };
        int c = 4;
        assert_int_equal(draw_area(ws, p, 1, &c, big), 0);
        p.colour = RED;
        assert_int_equal(draw_area(ws, p, 1, &c, far), 0); /* behind the back clip plane */
        /* a line crossing the whole picture */
        gks_prim l = attrs_default(GKS_PRIM_POLYLINE, GREEN);
        l.view_ind = 1;
        const Gpoint3 ln[2] = { { -1, 0.5125, 0.5 }, { 2, 0.5125, 0.5 } };
        assert_int_equal(draw_line(ws, l, 2, ln), 0);
        image img;
        ws_finish(ws, &img);
        assert_int_equal(count_colour(&img, RED), 0);
        for (int y = 0; y < W; y++)
            for (int x = 0; x < W; x++) {
                int in = !on || (x >= 10 && x < 30 && y >= 10 && y < 30);
                /* a thin line includes the pixel holding its clipped end point: the
                 * clip boundary x = 30.0 is that pixel's left edge */
                if (y == 20 && (in || (on && x == 30)))
                    expect(&img, x, y, GREEN);
                else
                    expect(&img, x, y, in ? BLUE : WHITE);
            }
        free(img.rgb);
    }
}

/* Two fill areas piercing each other: z = x and z = 1 - x over the same square; in
 * z-buffer mode each is visible where it is nearer (larger z), whatever the order. */
static void test_zbuffer_interpenetrating(void **u)
{
    (void)u;
    const int W = 32;
    const Gpoint3 a[4] = { { 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 0 } };
    const Gpoint3 b[4] = { { 0, 0, 1 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 1 } };
    for (int order = 0; order < 2; order++) {
        gks_ws *ws = ws_new("t_zbuf", W, W, GHLHSR_ZBUFFER);
        int c = 4;
        assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, order ? RED : BLUE), 1,
                                   &c, order ? a : b), 0);
        assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, order ? BLUE : RED), 1,
                                   &c, order ? b : a), 0);
        image img;
        ws_finish(ws, &img);
        for (int y = 0; y < W; y++)
            for (int x = 0; x < W; x++)
                expect(&img, x, y, x >= W / 2 ? RED : BLUE);
        free(img.rgb);
    }
}

/* Compare with tests/core/ref/NAME.ref.png (tolerance in the file comment). */
static void compare_ref(const image *img, const char *name)
{
    char ref[512], out[512], diff[512];
    ref_path(ref, sizeof ref, name);
    snprintf(out, sizeof out, "%s.out.png", name);
    snprintf(diff, sizeof diff, "%s.diff.png", name);
    unsigned char *top = malloc((size_t)img->w * img->h * 3);
    assert_non_null(top);
    memcpy(top, img->rgb, (size_t)img->w * img->h * 3);
    const char *upd = getenv("GKS_UPDATE_REFS");
    if (upd && strcmp(upd, "1") == 0)
        assert_int_equal(gks_raster_png_write_rgb8(ref, img->w, img->h, top, GKS_RASTER_PNG_LEVEL_MAX), 0);
    image r = { 0, 0, NULL };
    if (!read_png(ref, &r))
        fail_msg("reference %s missing (GKS_UPDATE_REFS=1 creates it)", ref);
    assert_int_equal(r.w, img->w);
    assert_int_equal(r.h, img->h);
    size_t n = (size_t)r.w * r.h, bad = 0;
    unsigned char *d = malloc(3 * n);
    assert_non_null(d);
    for (size_t i = 0; i < n; i++) {
        int ok = 1;
        for (int k = 0; k < 3; k++)
            ok &= abs((int)r.rgb[3 * i + k] - (int)img->rgb[3 * i + k]) <= 2;
        bad += !ok;
        d[3 * i] = ok ? 128 : 255;
        d[3 * i + 1] = d[3 * i + 2] = ok ? 128 : 0;
    }
    if (bad * 1000 > n * REF_MAX_BAD_PERMILLE) {
        gks_raster_png_write_rgb8(diff, r.w, r.h, d, GKS_RASTER_PNG_FAST);
        gks_raster_png_write_rgb8(out, img->w, img->h, top, GKS_RASTER_PNG_FAST);
        fail_msg("%s: %zu of %zu pixels differ from %s (diff in %s)", name, bad, n, ref, diff);
    }
    free(d);
    free(top);
    free(r.rgb);
}

/* Three overlapping triangles, submitted near-to-far, and a line: the painter draws them
 * far-to-near by the mean depth, so the nearest is on top everywhere it covers. */
static void painter_scene(gks_ws *ws)
{
    const Gpoint3 t[3][3] = {
        { { 0.05, 0.1, 0.9 }, { 0.6, 0.2, 0.9 }, { 0.3, 0.8, 0.9 } },   /* near: red */
        { { 0.3, 0.05, 0.5 }, { 0.95, 0.4, 0.5 }, { 0.4, 0.7, 0.5 } },  /* middle: green */
        { { 0.2, 0.4, 0.1 }, { 0.9, 0.6, 0.1 }, { 0.5, 0.95, 0.1 } },   /* far: blue */
    };
    const Grgb col[3] = { RED, GREEN, BLUE };
    int c = 3;
    for (int k = 0; k < 3; k++)
        assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, col[k]), 1, &c, t[k]),
                         0);
    gks_prim l = attrs_default(GKS_PRIM_POLYLINE, BLACK);
    l.attrs.linewidth = 2;
    const Gpoint3 ln[2] = { { 0.02, 0.5, 0.3 }, { 0.98, 0.5, 0.3 } }; /* between blue and green */
    assert_int_equal(draw_line(ws, l, 2, ln), 0);
}

static void test_painter(void **u)
{
    (void)u;
    gks_ws *ws = ws_new("t_painter", 64, 64, GHLHSR_PAINTER);
    painter_scene(ws);
    image img;
    ws_finish(ws, &img);
    /* structural: centroid of each triangle shows the nearest covering colour */
    expect(&img, (int)(0.32 * 64), (int)(0.37 * 64), RED);
    expect(&img, (int)(0.55 * 64), (int)(0.38 * 64), GREEN); /* green over blue */
    expect(&img, (int)(0.55 * 64), (int)(0.75 * 64), BLUE);
    expect(&img, 61, 32, BLACK);  /* the line over nothing */
    expect(&img, 45, 32, GREEN);  /* green hides the line */
    expect(&img, 15, 32, RED);    /* red hides the line */
    compare_ref(&img, "painter");
    free(img.rgb);
    /* z-buffer gives the same picture for this scene (no cyclic overlap) */
    ws = ws_new("t_painter_z", 64, 64, GHLHSR_ZBUFFER);
    painter_scene(ws);
    image iz;
    ws_finish(ws, &iz);
    compare_ref(&iz, "painter");
    free(iz.rgb);
}

/* Hidden line: a far square partly behind a near square, both FILL AREAs, and a line
 * passing behind the near square. Only outlines are drawn; what the near square hides
 * is removed, the rest is visible. */
static void hidden_scene(gks_ws *ws)
{
    const Gpoint3 nearq[4] = { { 0.2, 0.2, 0.8 }, { 0.6, 0.2, 0.8 }, { 0.6, 0.6, 0.8 },
                               { 0.2, 0.6, 0.8 } };
    const Gpoint3 farq[4] = { { 0.4, 0.4, 0.3 }, { 0.85, 0.4, 0.3 }, { 0.85, 0.85, 0.3 },
                              { 0.4, 0.85, 0.3 } };
    /* a tilted quad sharing the near square's right edge, going back in depth */
    const Gpoint3 side[4] = { { 0.6, 0.2, 0.8 }, { 0.75, 0.1, 0.2 }, { 0.75, 0.5, 0.2 },
                              { 0.6, 0.6, 0.8 } };
    int c = 4;
    assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, BLUE), 1, &c, farq), 0);
    assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, RED), 1, &c, nearq), 0);
    assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, BLACK), 1, &c, side), 0);
    const Gpoint3 ln[2] = { { 0.05, 0.3, 0.5 }, { 0.95, 0.3, 0.5 } };
    assert_int_equal(draw_line(ws, attrs_default(GKS_PRIM_POLYLINE, GREEN), 2, ln), 0);
}

static void test_hidden_line(void **u)
{
    (void)u;
    const int W = 80;
    gks_ws *ws = ws_new("t_hidden", W, W, GHLHSR_HIDDEN_LINE);
    hidden_scene(ws);
    image img;
    ws_finish(ws, &img);
    /* interiors are background */
    expect(&img, 30, 30, WHITE);
    expect(&img, 60, 60, WHITE);
    /* near square's outline complete: its bottom edge row y = 16 (0.2*80) */
    for (int x = 17; x < 47; x++)
        expect(&img, x, 16, RED);
    /* far square's bottom edge (y = 32) hidden inside the near square, visible right of
     * the side quad (x > 0.75*80 = 60) */
    for (int x = 34; x < 46; x++)
        assert_false(is(&img, x, 32, BLUE));
    for (int x = 62; x < 67; x++)
        expect(&img, x, 32, BLUE);
    /* its top edge (y = 68) fully visible */
    for (int x = 33; x < 67; x++)
        expect(&img, x, 68, BLUE);
    /* the green line: visible left of the near square, hidden behind it and the side */
    for (int x = 5; x < 15; x++)
        expect(&img, x, 24, GREEN);
    for (int x = 18; x < 46; x++)
        assert_false(is(&img, x, 24, GREEN));
    for (int x = 62; x < 75; x++)
        expect(&img, x, 24, GREEN);
    compare_ref(&img, "hidden_line");
    free(img.rgb);
}

/* The HLHSR mode changed within a frame: areas retained for the painter are drawn as
 * outlines (their clipped boundary) when the picture is composed in hidden-line mode. */
static void test_mode_change(void **u)
{
    (void)u;
    const int W = 40;
    gks_ws *ws = ws_new("t_mchange", W, W, GHLHSR_PAINTER);
    const Gpoint3 q[4] = { { 0.25, 0.25, 0.5 }, { 0.75, 0.25, 0.5 }, { 0.75, 0.75, 0.5 },
                           { 0.25, 0.75, 0.5 } };
    int c = 4;
    assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, RED), 1, &c, q), 0);
    ws->hlhsr_mode = GHLHSR_HIDDEN_LINE;
    image img;
    ws_finish(ws, &img);
    expect(&img, 20, 20, WHITE);
    expect(&img, 20, 10, RED);
    expect(&img, 10, 20, RED);
    expect(&img, 30, 20, RED);
    expect(&img, 20, 30, RED);
    free(img.rgb);
}

/* Linetypes and widths: a horizontal dashed line of width 3 covers 3 rows, 8 on 4 off
 * scaled by the width (24 on, 12 off); dotted 1-pixel line 2 on 4 off. */
static void test_lines(void **u)
{
    (void)u;
    const int W = 120;
    gks_ws *ws = ws_new("t_lines", W, 40, GHLHSR_NONE);
    gks_prim l = attrs_default(GKS_PRIM_POLYLINE, RED);
    l.attrs.linetype = 2;
    l.attrs.linewidth = 3;
    const Gpoint3 a[2] = { { 0, 10.5 / W, 0.5 }, { 1, 10.5 / W, 0.5 } };
    assert_int_equal(draw_line(ws, l, 2, a), 0);
    l.attrs.linetype = 3;
    l.attrs.linewidth = 1;
    l.colour = BLUE;
    const Gpoint3 b[2] = { { 0.5 / W, 30.5 / W, 0.5 }, { 119.5 / W, 30.5 / W, 0.5 } };
    assert_int_equal(draw_line(ws, l, 2, b), 0);
    image img;
    ws_finish(ws, &img);
    for (int x = 0; x < W; x++) {
        int on = x % 36 < 24;
        for (int y = 9; y <= 11; y++)
            expect(&img, x, y, on ? RED : WHITE);
        expect(&img, x, 8, WHITE);
        expect(&img, x, 12, WHITE);
        expect(&img, x, 30, x % 6 < 2 ? BLUE : WHITE);
    }
    free(img.rgb);
}

/* Markers: type 2 (plus) of size factor 3 = 21 px arms centred at the transformed
 * centre; a centre outside the view clip draws nothing even if the marker would reach in. */
static void test_markers(void **u)
{
    (void)u;
    const int W = 60;
    gks_ws *ws = ws_new("t_mark", W, W, GHLHSR_NONE);
    ws->views[0].clip_limit = (Glimit3){ 0, 0.5, 0, 1, 0, 1 };
    gks_prim m = attrs_default(GKS_PRIM_POLYMARKER, BLUE);
    m.attrs.marker_type = 2;
    m.attrs.marker_size = 3;
    const Gpoint3 c[2] = { { 20.5 / W, 30.5 / W, 0.5 }, { 45.5 / W, 30.5 / W, 0.5 } };
    assert_int_equal(draw_line(ws, m, 2, c), 0);
    image img;
    ws_finish(ws, &img);
    int n = count_colour(&img, BLUE);
    /* horizontal arm 21 px + vertical 21 px sharing the centre (+-1 for rounding) */
    assert_in_range(n, 39, 43);
    expect(&img, 20, 30, BLUE);
    expect(&img, 11, 30, BLUE);
    expect(&img, 20, 39, BLUE);
    expect(&img, 20, 34, BLUE);
    expect(&img, 24, 34, WHITE);
    for (int x = 33; x < W; x++)
        expect(&img, x, 30, WHITE);
    free(img.rgb);
}

/* Interiors: hollow draws the boundary only; hatch -1 every 8th row; pattern 2x2 with a
 * cell of 4x4 px from the reference point; FILL AREA SET with a hole and edges. */
static void test_interiors(void **u)
{
    (void)u;
    const int W = 64;
    gks_ws *ws = ws_new("t_int", W, W, GHLHSR_NONE);
    int c = 4;
    const Gpoint3 q1[4] = { { 2.0 / W, 2.0 / W, 0 }, { 30.0 / W, 2.0 / W, 0 },
                            { 30.0 / W, 30.0 / W, 0 }, { 2.0 / W, 30.0 / W, 0 } };
    gks_prim p = attrs_default(GKS_PRIM_FILL_AREA, RED);
    p.attrs.int_style = GSTYLE_HOLLOW;
    assert_int_equal(draw_area(ws, p, 1, &c, q1), 0);
    const Gpoint3 q2[4] = { { 34.0 / W, 2.0 / W, 0 }, { 62.0 / W, 2.0 / W, 0 },
                            { 62.0 / W, 30.0 / W, 0 }, { 34.0 / W, 30.0 / W, 0 } };
    p = attrs_default(GKS_PRIM_FILL_AREA, GREEN);
    p.attrs.int_style = GSTYLE_HATCH;
    p.attrs.style_ind = -1;
    assert_int_equal(draw_area(ws, p, 1, &c, q2), 0);
    const Grgb pat[4] = { RED, GREEN, BLUE, BLACK };
    const Gpoint3 q3[4] = { { 2.0 / W, 34.0 / W, 0 }, { 30.0 / W, 34.0 / W, 0 },
                            { 30.0 / W, 62.0 / W, 0 }, { 2.0 / W, 62.0 / W, 0 } };
    p = attrs_default(GKS_PRIM_FILL_AREA, GREEN);
    p.attrs.int_style = GSTYLE_PAT;
    p.attrs.pat_nx = p.attrs.pat_ny = 2;
    p.attrs.pattern = pat;
    p.attrs.pat_ref = (Gpoint3){ 2.0 / W, 34.0 / W, 0 };
    p.attrs.pat_width = (Gvec3){ 8.0 / W, 0, 0 };
    p.attrs.pat_height = (Gvec3){ 0, 8.0 / W, 0 };
    assert_int_equal(draw_area(ws, p, 1, &c, q3), 0);
    /* fill area set: square with a square hole, edges on (black, width 1) */
    const Gpoint3 fas[8] = { { 34.0 / W, 34.0 / W, 0 }, { 62.0 / W, 34.0 / W, 0 },
                             { 62.0 / W, 62.0 / W, 0 }, { 34.0 / W, 62.0 / W, 0 },
                             { 42.0 / W, 42.0 / W, 0 }, { 54.0 / W, 42.0 / W, 0 },
                             { 54.0 / W, 54.0 / W, 0 }, { 42.0 / W, 54.0 / W, 0 } };
    const int cc[2] = { 4, 4 };
    p = attrs_default(GKS_PRIM_FILL_AREA, BLUE);
    p.attrs.edge_flag = 1;
    assert_int_equal(draw_area(ws, p, 2, cc, fas), 0);
    image img;
    ws_finish(ws, &img);
    /* hollow */
    expect(&img, 15, 15, WHITE);
    expect(&img, 15, 2, RED);
    expect(&img, 2, 15, RED);
    /* hatch: rows y % 8 == 0 inside */
    for (int y = 3; y < 30; y++)
        expect(&img, 45, y, y % 8 == 0 ? GREEN : WHITE);
    /* pattern: cell (i,j) = ((x-2)/4 % 2, (y-34)/4 % 2) */
    for (int y = 35; y < 61; y += 3)
        for (int x = 3; x < 29; x += 3) {
            int i = (x - 2) / 4 % 2, j = (y - 34) / 4 % 2;
            expect(&img, x, y, pat[j * 2 + i]);
        }
    /* fill area set: hole empty, ring blue, edges black */
    expect(&img, 48, 48, WHITE);
    expect(&img, 38, 48, BLUE);
    expect(&img, 48, 34, BLACK);
    expect(&img, 48, 42, BLACK);
    expect(&img, 34, 48, BLACK);
    free(img.rgb);
}

/* Cell array: 4 x 2 cells over [0.25,0.75]^2 of a 64 px image (cells 8 x 16 px),
 * nearest-neighbour; with the clip box x <= 0.5 only the left half. */
static void test_cell_array(void **u)
{
    (void)u;
    const int W = 64;
    const Grgb cells[8] = { RED, GREEN, BLUE, BLACK, GREEN, BLUE, BLACK, RED };
    for (int clip = 0; clip < 2; clip++) {
        gks_ws *ws = ws_new("t_cell", W, W, GHLHSR_ZBUFFER);
        gks_prim p = attrs_default(GKS_PRIM_CELL_ARRAY, BLACK);
        p.cell_p = (Gpoint3){ 0.25, 0.25, 0.5 };
        p.cell_q = (Gpoint3){ 0.75, 0.75, 0.5 };
        p.cell_r = (Gpoint3){ 0.75, 0.25, 0.5 };
        p.cell_nx = 4;
        p.cell_ny = 2;
        p.cells = cells;
        p.clip = clip;
        const double box[6] = { 0, 0.5, 0, 1, 0, 1 };
        memcpy(p.clip_box, box, sizeof box);
        assert_int_equal(ws->drv->primitive(ws, &p), 0);
        image img;
        ws_finish(ws, &img);
        for (int y = 0; y < W; y++)
            for (int x = 0; x < W; x++) {
                int in = x >= 16 && x < 48 && y >= 16 && y < 48 && (!clip || x < 32);
                if (!in) {
                    expect(&img, x, y, WHITE);
                    continue;
                }
                int i = (x - 16) / 8, j = (y - 16) / 16;
                expect(&img, x, y, cells[j * 4 + i]);
            }
        free(img.rgb);
    }
}

/* HLHSR identifier: in z-buffer mode a far primitive with identifier 1 is drawn on top
 * of a nearer one drawn after it. */
static void test_hlhsr_id(void **u)
{
    (void)u;
    const int W = 16;
    gks_ws *ws = ws_new("t_hrid", W, W, GHLHSR_ZBUFFER);
    const Gpoint3 farq[4] = { { 0, 0, 0.1 }, { 1, 0, 0.1 }, { 1, 0.5, 0.1 }, { 0, 0.5, 0.1 } };
    const Gpoint3 nearq[4] = { { 0, 0, 0.9 }, { 1, 0, 0.9 }, { 1, 1, 0.9 }, { 0, 1, 0.9 } };
    int c = 4;
    gks_prim p = attrs_default(GKS_PRIM_FILL_AREA, RED);
    p.attrs.hlhsr_id = 1;
    assert_int_equal(draw_area(ws, p, 1, &c, farq), 0);
    assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, BLUE), 1, &c, nearq), 0);
    image img;
    ws_finish(ws, &img);
    expect(&img, 5, 3, RED);
    expect(&img, 5, 12, BLUE);
    free(img.rgb);
}

/* Anti-aliasing (ESCAPE GESC_PNG_SUPERSAMPLE): a vertical edge at x = 10.5 px gives the
 * pixel column 10 half coverage, i.e. a 50 % mix with 4 x 4 samples; without it the
 * column is either all or nothing. Bad factors report 182. */
static void test_antialias(void **u)
{
    (void)u;
    const int W = 20;
    for (int ss = 1; ss <= 4; ss += 3) {
        gks_ws *ws = ws_new("t_aa", W, W, GHLHSR_NONE);
        Gint ints[2] = { 1, ss };
        Gescape_in_data in = { .num_ints = 2, .ints = ints };
        assert_int_equal(ws->drv->escape(ws, GESC_PNG_SUPERSAMPLE, &in, NULL), 0);
        ints[1] = 5;
        assert_int_equal(ws->drv->escape(ws, GESC_PNG_SUPERSAMPLE, &in, NULL), 182);
        const Gpoint3 q[4] = { { 0, 0, 0 }, { 10.5 / W, 0, 0 }, { 10.5 / W, 1, 0 }, { 0, 1, 0 } };
        int c = 4;
        assert_int_equal(draw_area(ws, attrs_default(GKS_PRIM_FILL_AREA, BLACK), 1, &c, q), 0);
        image img;
        ws_finish(ws, &img);
        expect(&img, 9, 5, BLACK);
        expect(&img, 11, 5, WHITE);
        int v = px(&img, 10, 5)[0];
        if (ss == 1)
            assert_true(v == 0 || v == 255);
        else
            assert_in_range(v, 126, 129);
        free(img.rgb);
    }
}

/* A long dashed polyline (more points than one chunk of the driver) drawn at once and
 * retained (painter) gives the same pixels as the raster module drawing the DC points
 * in one call: the linetype continues across chunks. */
static void test_long_polyline(void **u)
{
    (void)u;
    const int W = 128, N = 10001;
    Gpoint3 *p = malloc(N * sizeof *p);
    gks_raster_pt *d = malloc(N * sizeof *d);
    assert_non_null(p);
    assert_non_null(d);
    for (int i = 0; i < N; i++) {
        double x = 4 + 120.0 * i / (N - 1), y = 64 + 50 * sin(i * 0.05) + (i % 2) * 0.3;
        p[i] = (Gpoint3){ x / W, y / W, 0.5 };
        d[i] = (gks_raster_pt){ x, y, 0.5 };
    }
    gks_raster_fb *fb = gks_raster_fb_create(W, W, 1);
    const float white[3] = { 1, 1, 1 };
    gks_raster_fb_clear(fb, white);
    for (int width = 1; width <= 3; width += 2) {
        gks_raster_fb_clear(fb, white);
        gks_raster_line la = { .rgb = { 1, 0, 0 }, .width = width, .type = 4 };
        assert_int_equal(gks_raster_polyline(fb, N, d, &la), 0);
        unsigned char *want = malloc(3 * W * W);
        fb_resolve(fb, want);
        for (int mode = 0; mode < 2; mode++) {
            gks_ws *ws = ws_new("t_long", W, W, mode ? GHLHSR_PAINTER : GHLHSR_NONE);
            gks_prim l = attrs_default(GKS_PRIM_POLYLINE, RED);
            l.attrs.linetype = 4;
            l.attrs.linewidth = width;
            assert_int_equal(draw_line(ws, l, N, p), 0);
            image img;
            ws_finish(ws, &img);
            size_t bad = 0;
            for (size_t i = 0; i < (size_t)3 * W * W; i++)
                bad += img.rgb[i] != want[i];
            assert_int_equal(bad, 0);
            free(img.rgb);
        }
        free(want);
    }
    gks_raster_fb_free(fb);
    free(p);
    free(d);
}

/* The cached view pipeline follows a change of the view representation within a frame. */
static void test_view_cache(void **u)
{
    (void)u;
    const int W = 20;
    gks_ws *ws = ws_new("t_vcache", W, W, GHLHSR_NONE);
    const Gpoint3 q[4] = { { 0, 0, 0.5 }, { 0.5, 0, 0.5 }, { 0.5, 0.5, 0.5 }, { 0, 0.5, 0.5 } };
    int c = 4;
    gks_prim p = attrs_default(GKS_PRIM_FILL_AREA, RED);
    p.view_ind = 2;
    assert_int_equal(draw_area(ws, p, 1, &c, q), 0);
    ws->views[2].ori_matrix[0][3] = 0.5; /* shift right by 0.5 */
    p.colour = BLUE;
    assert_int_equal(draw_area(ws, p, 1, &c, q), 0);
    image img;
    ws_finish(ws, &img);
    expect(&img, 5, 5, RED);
    expect(&img, 15, 5, BLUE);
    expect(&img, 15, 15, WHITE);
    free(img.rgb);
}

/* Hostile input: NaN/Inf/1e30 coordinates, zero points, inconsistent counts: no crash,
 * nothing drawn or a correct picture, never an error but storage. */
static void test_hostile(void **u)
{
    (void)u;
    const int W = 16;
    int modes[] = { GHLHSR_NONE, GHLHSR_HIDDEN_LINE, GHLHSR_ZBUFFER, GHLHSR_PAINTER };
    for (int m = 0; m < 4; m++) {
        gks_ws *ws = ws_new("t_hostile", W, W, modes[m]);
        const Gpoint3 bad[4] = { { NAN, 0, 0 }, { 1, INFINITY, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
        const Gpoint3 huge[4] = { { -1e30, -1e30, 0.5 }, { 1e30, -1e30, 0.5 },
                                  { 1e30, 1e30, 0.5 }, { -1e30, 1e30, 0.5 } };
        const Gpoint3 big[4] = { { -1e6, -1e6, 0.5 }, { 1e6, -1e6, 0.5 }, { 1e6, 1e6, 0.5 },
                                 { -1e6, 1e6, 0.5 } };
        const Gpoint3 same[3] = { { 0.5, 0.5, 0.5 }, { 0.5, 0.5, 0.5 }, { 0.5, 0.5, 0.5 } };
        int c = 4, c3 = 3, cbig = 1000;
        gks_prim p = attrs_default(GKS_PRIM_FILL_AREA, RED);
        p.attrs.edge_flag = 1;
        assert_int_equal(draw_area(ws, p, 1, &c, bad), 0);
        assert_int_equal(draw_area(ws, p, 1, &c3, same), 0);
        gks_prim q = p;
        q.kind = GKS_PRIM_FILL_AREA;
        q.n_loops = 1;
        q.loop_counts = &cbig; /* counts beyond the points: ignored */
        q.n_points = 4;
        q.pts = huge;
        assert_int_equal(ws->drv->primitive(ws, &q), 0);
        /* 1e30: drawn without crash (the clipper's interpolation at such magnitudes is
         * not exact, so the picture is not checked), then painted over */
        assert_int_equal(draw_area(ws, p, 1, &c, huge), 0);
        assert_int_equal(draw_line(ws, attrs_default(GKS_PRIM_POLYLINE, RED), 4, huge), 0);
        assert_int_equal(draw_line(ws, attrs_default(GKS_PRIM_POLYLINE, RED), 4, bad), 0);
        assert_int_equal(draw_line(ws, attrs_default(GKS_PRIM_POLYLINE, RED), 0, NULL), 0);
        assert_int_equal(draw_line(ws, attrs_default(GKS_PRIM_POLYMARKER, RED), 4, bad), 0);
        gks_prim cell = attrs_default(GKS_PRIM_CELL_ARRAY, RED);
        cell.cell_p = (Gpoint3){ NAN, 0, 0 };
        cell.cell_nx = cell.cell_ny = 1;
        cell.cells = &RED;
        assert_int_equal(ws->drv->primitive(ws, &cell), 0);
        p.attrs.edge_flag = 0;
        p.colour = BLUE;
        assert_int_equal(draw_area(ws, p, 1, &c, big), 0); /* covers everything */
        image img;
        ws_finish(ws, &img);
        if (modes[m] == GHLHSR_HIDDEN_LINE)
            assert_int_equal(count_colour(&img, BLUE), 0); /* outline outside */
        else
            assert_int_equal(count_colour(&img, BLUE), W * W);
        free(img.rgb);
    }
}

/* The workstation description lists modes 0..4. */
static void test_desc(void **u)
{
    (void)u;
    unsigned m = gks_ws_png_driver.desc->hlhsr_modes;
    for (int k = 0; k <= 4; k++)
        assert_true(m >> k & 1);
}

/* --- end to end through the C binding ---------------------------------------------- */
static int e2e_err;
static void e2e_handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    e2e_err = err;
}

/* GKS open, PNG workstation "name" active with a w x h pixel image of NDC [0,1]x[0,h/w]. */
static void e2e_open(const char *name, int w, int h)
{
    char path[256];
    snprintf(path, sizeof path, "%s.png", name);
    unlink(path);
    gemergency_close_gks();
    e2e_err = 0;
    gset_err_hand(e2e_handler, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(1, path, GWS_TYPE_PNG);
    gactivate_ws(1);
    Glimit win = { 0, 1, 0, (double)h / w }, vp = { 0, w, 0, h };
    gset_ws_win(1, &win);
    gset_ws_vp(1, &vp);
    const Gcolr_rep red = { .rgb = RED }, green = { .rgb = GREEN }, blue = { .rgb = BLUE };
    gset_colr_rep(1, 2, &red);
    gset_colr_rep(1, 3, &green);
    gset_colr_rep(1, 4, &blue);
    assert_int_equal(e2e_err, 0);
}

static void e2e_close(const char *name, image *img)
{
    char path[256];
    snprintf(path, sizeof path, "%s.png", name);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    assert_int_equal(e2e_err, 0);
    assert_true(read_png(path, img));
    unlink(path);
}

/* SET HLHSR MODE accepts 1 (hidden line) and 3 (painter) on the PNG workstation; the
 * painter scene through FILL AREA 3 / POLYLINE 3 matches the driver-level reference. */
static void test_e2e_hlhsr_modes(void **u)
{
    (void)u;
    e2e_open("t_e2e_modes", 64, 64);
    gset_hlhsr_mode(1, GHLHSR_HIDDEN_LINE);
    assert_int_equal(e2e_err, 0);
    gset_hlhsr_mode(1, GHLHSR_PAINTER);
    assert_int_equal(e2e_err, 0);
    Gint err = -1, mode = -1;
    ginq_hlhsr_mode(1, &err, &mode);
    assert_int_equal(err, 0);
    gset_fill_int_style(GSTYLE_SOLID);
    Gpoint3 t[3][3] = {
        { { 0.05, 0.1, 0.9 }, { 0.6, 0.2, 0.9 }, { 0.3, 0.8, 0.9 } },
        { { 0.3, 0.05, 0.5 }, { 0.95, 0.4, 0.5 }, { 0.4, 0.7, 0.5 } },
        { { 0.2, 0.4, 0.1 }, { 0.9, 0.6, 0.1 }, { 0.5, 0.95, 0.1 } },
    };
    for (int k = 0; k < 3; k++) {
        gset_fill_colr_ind(2 + k);
        Gpoint_list3 l = { 3, t[k] };
        gfill_area3(&l);
    }
    gset_linewidth(2);
    gset_line_colr_ind(1);
    Gpoint3 ln[2] = { { 0.02, 0.5, 0.3 }, { 0.98, 0.5, 0.3 } };
    Gpoint_list3 ll = { 2, ln };
    gpolyline3(&ll);
    image img;
    e2e_close("t_e2e_modes", &img);
    compare_ref(&img, "painter");
    free(img.rgb);
}

/* POLYMARKER with marker type plus and size factor 2 (14 px arms), TEXT strokes in the
 * text colour, FILL AREA SET with a hole and edges on, CELL ARRAY. */
static void test_e2e_primitives(void **u)
{
    (void)u;
    const int W = 100;
    e2e_open("t_e2e_prims", W, W);
    gset_marker_type(2);
    gset_marker_size(2);
    gset_marker_colr_ind(4);
    Gpoint mc = { 20.5 / W, 80.5 / W };
    Gpoint_list ml = { 1, &mc };
    gpolymarker(&ml);
    /* fill area set: ring around [60,90]^2 with hole [70,80]^2, green, black edges */
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(3);
    gset_edge_flag(GEDGE_ON);
    gset_edge_colr_ind(1);
    Gpoint outer[4] = { { 0.6, 0.6 }, { 0.9, 0.6 }, { 0.9, 0.9 }, { 0.6, 0.9 } };
    Gpoint inner[4] = { { 0.7, 0.7 }, { 0.8, 0.7 }, { 0.8, 0.8 }, { 0.7, 0.8 } };
    Gpoint_list loops[2] = { { 4, outer }, { 4, inner } };
    Gpoint_list_list fas = { 2, loops };
    gfill_area_set(&fas);
    /* cell array 2 x 1 over [0.1,0.5] x [0.1,0.3]: red | blue */
    Gint colr[2] = { 2, 4 };
    Gpat_rep ca = { { 2, 1 }, colr };
    Grect rect = { { 0.1, 0.1 }, { 0.5, 0.3 } };
    gcell_array(&rect, &ca);
    /* text, red, 0.05 high, at (0.1, 0.5) */
    gset_text_colr_ind(2);
    gset_char_ht(0.05);
    Gpoint tp = { 0.1, 0.5 };
    gtext(&tp, "HI");
    image img;
    e2e_close("t_e2e_prims", &img);
    /* marker */
    expect(&img, 20, 80, BLUE);
    expect(&img, 14, 80, BLUE);
    expect(&img, 20, 86, BLUE);
    expect(&img, 24, 84, WHITE);
    /* fill area set */
    expect(&img, 65, 75, GREEN);
    expect(&img, 75, 75, WHITE);
    expect(&img, 75, 60, BLACK);
    expect(&img, 75, 70, BLACK);
    /* cell array: centres x < 30 red, >= 30 blue, rows 10..29 */
    expect(&img, 15, 20, RED);
    expect(&img, 45, 20, BLUE);
    expect(&img, 45, 31, WHITE);
    /* text: red pixels within the text box x 10..~20, y 50..55, none elsewhere */
    int n_red = 0, outside = 0;
    for (int y = 0; y < W; y++)
        for (int x = 0; x < W; x++) {
            if (y < 32 && x < 52)
                continue; /* the cell array */
            if (!is(&img, x, y, RED))
                continue;
            n_red++;
            outside += !(x >= 9 && x <= 22 && y >= 49 && y <= 56);
        }
    assert_true(n_red >= 10);
    assert_int_equal(outside, 0);
    free(img.rgb);
}

/* ESCAPE GESC_PNG_SUPERSAMPLE through gescape: anti-aliased edge pixel. */
static void test_e2e_antialias(void **u)
{
    (void)u;
    e2e_open("t_e2e_aa", 20, 20);
    Gint ints[2] = { 1, 4 };
    Gescape_in_data in = { .num_ints = 2, .ints = ints };
    gescape(GESC_PNG_SUPERSAMPLE, &in, NULL, NULL);
    assert_int_equal(e2e_err, 0);
    ints[1] = 0;
    gescape(GESC_PNG_SUPERSAMPLE, &in, NULL, NULL);
    assert_int_equal(e2e_err, 182);
    e2e_err = 0;
    gset_fill_int_style(GSTYLE_SOLID);
    gset_fill_colr_ind(1);
    Gpoint q[4] = { { 0, 0 }, { 10.5 / 20, 0 }, { 10.5 / 20, 1 }, { 0, 1 } };
    Gpoint_list l = { 4, q };
    gfill_area(&l);
    image img;
    e2e_close("t_e2e_aa", &img);
    expect(&img, 9, 5, BLACK);
    assert_in_range(px(&img, 10, 5)[0], 126, 129);
    free(img.rgb);
}

/* ESCAPE GESC_PNG_COMPRESSION: the fast default and zlib level 9 write the same pixels
 * (PNG is lossless whatever the setting), level 9 no larger a file; values outside 0..9
 * report 182 and change nothing; identifiers past the last one report 180. */
static long e2e_scene_size(const char *name, int compression, image *img)
{
    e2e_open(name, 64, 48);
    if (compression >= 0) {
        Gint ints[2] = { 1, compression };
        Gescape_in_data in = { .num_ints = 2, .ints = ints };
        gescape(GESC_PNG_COMPRESSION, &in, NULL, NULL);
        assert_int_equal(e2e_err, 0);
    }
    gset_fill_int_style(GSTYLE_SOLID);
    for (int k = 0; k < 3; k++) {
        gset_fill_colr_ind(2 + k);
        Gpoint q[3] = { { 0.1 + 0.25 * k, 0.1 }, { 0.5 + 0.2 * k, 0.2 }, { 0.3, 0.7 } };
        Gpoint_list l = { 3, q };
        gfill_area(&l);
    }
    char path[256];
    snprintf(path, sizeof path, "%s.png", name);
    gupd_ws(1, GFLAG_PERFORM);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    e2e_close(name, img);
    return (long)st.st_size;
}

static void test_e2e_compression(void **u)
{
    (void)u;
    image fast, best, dflt;
    long s0 = e2e_scene_size("t_e2e_zfast", GKS_RASTER_PNG_FAST, &fast);
    long s9 = e2e_scene_size("t_e2e_z9", GKS_RASTER_PNG_LEVEL_MAX, &best);
    long sd = e2e_scene_size("t_e2e_zdef", -1, &dflt);
    assert_int_equal(fast.w, best.w);
    assert_int_equal(fast.h, best.h);
    assert_memory_equal(fast.rgb, best.rgb, (size_t)fast.w * fast.h * 3);
    assert_memory_equal(fast.rgb, dflt.rgb, (size_t)fast.w * fast.h * 3);
    assert_int_equal(sd, s0); /* the default is the fast setting */
    assert_true(s9 <= s0);
    free(fast.rgb);
    free(best.rgb);
    free(dflt.rgb);
    e2e_open("t_e2e_zbad", 8, 8);
    Gint ints[2] = { 1, 10 };
    Gescape_in_data in = { .num_ints = 2, .ints = ints };
    gescape(GESC_PNG_COMPRESSION, &in, NULL, NULL);
    assert_int_equal(e2e_err, 182);
    e2e_err = 0;
    ints[1] = -1;
    gescape(GESC_PNG_COMPRESSION, &in, NULL, NULL);
    assert_int_equal(e2e_err, 182);
    e2e_err = 0;
    in.num_ints = 1;
    gescape(GESC_PNG_COMPRESSION, &in, NULL, NULL);
    assert_int_equal(e2e_err, 182);
    e2e_err = 0;
    in.num_ints = 2;
    gescape(GESC_PNG_COMPRESSION - 1, &in, NULL, NULL);
    assert_int_equal(e2e_err, 180);
    e2e_err = 0;
    image img;
    e2e_close("t_e2e_zbad", &img);
    free(img.rgb);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_desc),
        cmocka_unit_test(test_fill_coverage),
        cmocka_unit_test(test_clipping),
        cmocka_unit_test(test_zbuffer_interpenetrating),
        cmocka_unit_test(test_painter),
        cmocka_unit_test(test_hidden_line),
        cmocka_unit_test(test_mode_change),
        cmocka_unit_test(test_lines),
        cmocka_unit_test(test_markers),
        cmocka_unit_test(test_interiors),
        cmocka_unit_test(test_cell_array),
        cmocka_unit_test(test_hlhsr_id),
        cmocka_unit_test(test_antialias),
        cmocka_unit_test(test_long_polyline),
        cmocka_unit_test(test_view_cache),
        cmocka_unit_test(test_hostile),
        cmocka_unit_test(test_e2e_hlhsr_modes),
        cmocka_unit_test(test_e2e_primitives),
        cmocka_unit_test(test_e2e_antialias),
        cmocka_unit_test(test_e2e_compression),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
