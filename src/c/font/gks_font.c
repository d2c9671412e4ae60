/* SPDX-License-Identifier: MIT */
/*
 * gks_font.c -- the compiled-in stroke font: a simplex sans for ASCII 32..126 drawn
 * for this library on an integer grid (cap height 21, x-height 14, base line 0,
 * descender -7, brackets up to 25). Each glyph is its advance width and a string of
 * polylines: points "x,y" separated by blanks, polylines separated by '|'.
 * The bold, seriffed and italic faces (gks_font.h) are computed from these glyphs.
 */
#include "gks_font.h"
#include <math.h>
#include <string.h>

typedef struct glyph_def {
    int advance;
    const char *strokes;
} glyph_def;

#define ROUND_O "9,21 7,20 5,18 4,16 3,13 3,8 4,5 5,3 7,1 9,0 13,0 15,1 17,3 18,5 19,8 " \
                "19,13 18,16 17,18 15,20 13,21 9,21"
#define ROUND_C "18,16 17,18 15,20 13,21 9,21 7,20 5,18 4,16 3,13 3,8 4,5 5,3 7,1 9,0 " \
                "13,0 15,1 17,3 18,5"
#define BOWL_L "15,11 13,13 11,14 8,14 6,13 4,11 3,8 3,6 4,3 6,1 8,0 11,0 13,1 15,3"
#define BOWL_R "4,11 6,13 8,14 11,14 13,13 15,11 16,8 16,6 15,3 13,1 11,0 8,0 6,1 4,3"

static const glyph_def font[95] = {
    /* 32 ' ' */ {16, ""},
    /* 33 ! */ {10, "5,21 5,7|5,2 4,1 5,0 6,1 5,2"},
    /* 34 " */ {14, "4,21 4,14|10,21 10,14"},
    /* 35 # */ {21, "11,25 4,-7|17,25 10,-7|4,12 18,12|3,6 17,6"},
    /* 36 $ */ {20, "8,25 8,-4|12,25 12,-4|17,18 15,20 12,21 8,21 5,20 3,18 3,16 4,14 5,13 "
                    "7,12 13,10 15,9 16,8 17,6 17,3 15,1 12,0 8,0 5,1 3,3"},
    /* 37 % */ {24, "21,21 3,0|8,21 10,19 10,17 9,15 7,14 5,14 3,16 3,18 4,20 6,21 8,21 "
                    "10,20 13,19 16,19 19,20 21,21|17,7 15,6 14,4 14,2 16,0 18,0 20,1 21,3 "
                    "21,5 19,7 17,7"},
    /* 38 & */ {24, "21,12 21,13 20,14 19,14 18,13 17,11 15,6 13,3 11,1 9,0 5,0 3,1 2,2 "
                    "1,4 1,6 2,8 3,9 10,13 11,14 12,16 12,18 11,20 9,21 7,20 6,18 6,16 7,13 "
                    "9,10 14,3 16,1 18,0 20,0 21,1 21,2"},
    /* 39 ' */ {8, "4,21 4,14"},
    /* 40 ( */ {12, "9,25 7,23 5,20 3,16 2,11 2,7 3,2 5,-2 7,-5 9,-7"},
    /* 41 ) */ {12, "3,25 5,23 7,20 9,16 10,11 10,7 9,2 7,-2 5,-5 3,-7"},
    /* 42 * */ {16, "8,21 8,9|3,18 13,12|13,18 3,12"},
    /* 43 + */ {22, "11,18 11,0|2,9 20,9"},
    /* 44 , */ {10, "6,1 5,0 4,1 5,2 6,1 6,-1 5,-3 4,-4"},
    /* 45 - */ {22, "4,9 18,9"},
    /* 46 . */ {10, "5,2 4,1 5,0 6,1 5,2"},
    /* 47 / */ {18, "16,25 2,-7"},
    /* 48 0 */ {20, "9,21 6,20 4,17 3,12 3,9 4,4 6,1 9,0 11,0 14,1 16,4 17,9 17,12 16,17 "
                    "14,20 11,21 9,21"},
    /* 49 1 */ {20, "6,17 8,18 11,21 11,0"},
    /* 50 2 */ {20, "4,16 4,17 5,19 6,20 8,21 12,21 14,20 15,19 16,17 16,15 15,13 13,10 "
                    "3,0 17,0"},
    /* 51 3 */ {20, "5,21 16,21 10,13 13,13 15,12 16,11 17,8 17,6 16,3 14,1 11,0 8,0 5,1 "
                    "4,2 3,4"},
    /* 52 4 */ {20, "13,21 3,7 18,7|13,21 13,0"},
    /* 53 5 */ {20, "15,21 5,21 4,12 5,13 8,14 11,14 14,13 16,11 17,8 17,6 16,3 14,1 11,0 "
                    "8,0 5,1 4,2 3,4"},
    /* 54 6 */ {20, "16,18 15,20 12,21 10,21 7,20 5,17 4,12 4,7 5,3 7,1 10,0 11,0 14,1 "
                    "16,3 17,6 17,7 16,10 14,12 11,13 10,13 7,12 5,10 4,7"},
    /* 55 7 */ {20, "17,21 7,0|3,21 17,21"},
    /* 56 8 */ {20, "8,21 5,20 4,18 4,16 5,14 7,13 11,12 14,11 16,9 17,7 17,4 16,2 15,1 "
                    "12,0 8,0 5,1 4,2 3,4 3,7 4,9 6,11 9,12 13,13 15,14 16,16 16,18 15,20 "
                    "12,21 8,21"},
    /* 57 9 */ {20, "16,14 15,11 13,9 10,8 9,8 6,9 4,11 3,14 3,15 4,18 6,20 9,21 10,21 "
                    "13,20 15,18 16,14 16,9 15,4 13,1 10,0 8,0 5,1 4,3"},
    /* 58 : */ {10, "5,14 4,13 5,12 6,13 5,14|5,2 4,1 5,0 6,1 5,2"},
    /* 59 ; */ {10, "5,14 4,13 5,12 6,13 5,14|6,1 5,0 4,1 5,2 6,1 6,-1 5,-3 4,-4"},
    /* 60 < */ {24, "20,18 4,9 20,0"},
    /* 61 = */ {22, "4,12 18,12|4,6 18,6"},
    /* 62 > */ {24, "4,18 20,9 4,0"},
    /* 63 ? */ {18, "3,16 3,17 4,19 5,20 7,21 11,21 13,20 14,19 15,17 15,15 14,13 13,12 "
                    "9,10 9,7|9,2 8,1 9,0 10,1 9,2"},
    /* 64 @ */ {27, "18,13 17,15 15,16 12,16 10,15 9,14 8,11 8,8 9,6 11,5 14,5 16,6 17,8|"
                    "18,16 17,8 17,6 19,5 21,5 23,7 24,10 24,12 23,15 22,17 20,19 18,20 "
                    "15,21 12,21 9,20 7,19 5,17 4,15 3,12 3,9 4,6 5,4 7,2 9,1 12,0 15,0 "
                    "18,1 20,2 21,3"},
    /* 65 A */ {18, "9,21 1,0|9,21 17,0|4,7 14,7"},
    /* 66 B */ {21, "4,21 4,0|4,21 13,21 16,20 17,19 18,17 18,15 17,13 16,12 13,11|4,11 "
                    "13,11 16,10 17,9 18,7 18,4 17,2 16,1 13,0 4,0"},
    /* 67 C */ {21, ROUND_C},
    /* 68 D */ {21, "4,21 4,0|4,21 11,21 14,20 16,18 17,16 18,13 18,8 17,5 16,3 14,1 "
                    "11,0 4,0"},
    /* 69 E */ {19, "4,21 4,0|4,21 17,21|4,11 12,11|4,0 17,0"},
    /* 70 F */ {18, "4,21 4,0|4,21 17,21|4,11 12,11"},
    /* 71 G */ {21, ROUND_C " 18,8|13,8 18,8"},
    /* 72 H */ {22, "4,21 4,0|18,21 18,0|4,11 18,11"},
    /* 73 I */ {8, "4,21 4,0"},
    /* 74 J */ {16, "12,21 12,5 11,2 10,1 8,0 6,0 4,1 3,2 2,5 2,7"},
    /* 75 K */ {21, "4,21 4,0|18,21 4,7|9,12 18,0"},
    /* 76 L */ {17, "4,21 4,0 16,0"},
    /* 77 M */ {24, "4,0 4,21 12,0 20,21 20,0"},
    /* 78 N */ {22, "4,0 4,21 18,0 18,21"},
    /* 79 O */ {22, ROUND_O},
    /* 80 P */ {21, "4,0 4,21 13,21 16,20 17,19 18,17 18,14 17,12 16,11 13,10 4,10"},
    /* 81 Q */ {22, ROUND_O "|12,4 18,-2"},
    /* 82 R */ {21, "4,0 4,21 13,21 16,20 17,19 18,17 18,15 17,13 16,12 13,11 4,11|"
                    "11,11 18,0"},
    /* 83 S */ {20, "17,18 15,20 12,21 8,21 5,20 3,18 3,16 4,14 5,13 7,12 13,10 15,9 "
                    "16,8 17,6 17,3 15,1 12,0 8,0 5,1 3,3"},
    /* 84 T */ {16, "8,21 8,0|1,21 15,21"},
    /* 85 U */ {22, "4,21 4,6 5,3 7,1 10,0 12,0 15,1 17,3 18,6 18,21"},
    /* 86 V */ {18, "1,21 9,0 17,21"},
    /* 87 W */ {24, "2,21 7,0 12,21 17,0 22,21"},
    /* 88 X */ {20, "3,21 17,0|17,21 3,0"},
    /* 89 Y */ {18, "1,21 9,11 9,0|17,21 9,11"},
    /* 90 Z */ {20, "3,21 17,21 3,0 17,0"},
    /* 91 [ */ {14, "4,25 4,-7|5,25 5,-7|4,25 11,25|4,-7 11,-7"},
    /* 92 \ */ {14, "0,21 14,-3"},
    /* 93 ] */ {14, "9,25 9,-7|10,25 10,-7|3,25 10,25|3,-7 10,-7"},
    /* 94 ^ */ {16, "3,14 8,20 13,14"},
    /* 95 _ */ {16, "0,-2 16,-2"},
    /* 96 ` */ {10, "4,21 7,17"},
    /* 97 a */ {19, "15,14 15,0|" BOWL_L},
    /* 98 b */ {19, "4,21 4,0|" BOWL_R},
    /* 99 c */ {18, BOWL_L},
    /* 100 d */ {19, "15,21 15,0|" BOWL_L},
    /* 101 e */ {18, "3,8 15,8 15,10 14,12 13,13 11,14 8,14 6,13 4,11 3,8 3,6 4,3 6,1 8,0 "
                     "11,0 13,1 15,3"},
    /* 102 f */ {12, "10,21 8,21 6,20 5,17 5,0|2,14 9,14"},
    /* 103 g */ {19, "15,14 15,-2 14,-5 13,-6 11,-7 8,-7 6,-6|" BOWL_L},
    /* 104 h */ {19, "4,21 4,0|4,10 7,13 9,14 12,14 14,13 15,10 15,0"},
    /* 105 i */ {8, "3,21 4,20 5,21 4,22 3,21|4,14 4,0"},
    /* 106 j */ {10, "5,21 6,20 7,21 6,22 5,21|6,14 6,-3 5,-6 3,-7 1,-7"},
    /* 107 k */ {17, "4,21 4,0|14,14 4,4|8,8 15,0"},
    /* 108 l */ {8, "4,21 4,0"},
    /* 109 m */ {30, "4,14 4,0|4,10 7,13 9,14 12,14 14,13 15,10 15,0|15,10 18,13 20,14 "
                     "23,14 25,13 26,10 26,0"},
    /* 110 n */ {19, "4,14 4,0|4,10 7,13 9,14 12,14 14,13 15,10 15,0"},
    /* 111 o */ {19, "8,14 6,13 4,11 3,8 3,6 4,3 6,1 8,0 11,0 13,1 15,3 16,6 16,8 15,11 "
                     "13,13 11,14 8,14"},
    /* 112 p */ {19, "4,14 4,-7|" BOWL_R},
    /* 113 q */ {19, "15,14 15,-7|" BOWL_L},
    /* 114 r */ {13, "4,14 4,0|4,8 5,11 7,13 9,14 12,14"},
    /* 115 s */ {17, "14,11 13,13 10,14 7,14 4,13 3,11 4,9 6,8 11,7 13,6 14,4 14,3 13,1 "
                     "10,0 7,0 4,1 3,3"},
    /* 116 t */ {12, "5,21 5,4 6,1 8,0 10,0|2,14 9,14"},
    /* 117 u */ {19, "4,14 4,4 5,1 7,0 10,0 12,1 15,4|15,14 15,0"},
    /* 118 v */ {16, "2,14 8,0 14,14"},
    /* 119 w */ {22, "3,14 7,0 11,14 15,0 19,14"},
    /* 120 x */ {17, "3,14 14,0|14,14 3,0"},
    /* 121 y */ {16, "2,14 8,0|14,14 8,0 6,-4 4,-6 2,-7 1,-7"},
    /* 122 z */ {17, "3,14 14,14 3,0 14,0"},
    /* 123 { */ {14, "9,25 7,24 6,22 6,14 5,12 3,9 5,6 6,4 6,-4 7,-6 9,-7"},
    /* 124 | */ {8, "4,25 4,-7"},
    /* 125 } */ {14, "5,25 7,24 8,22 8,14 9,12 11,9 9,6 8,4 8,-4 7,-6 5,-7"},
    /* 126 ~ */ {24, "3,7 4,10 6,11 8,11 10,10 14,8 16,7 18,7 20,8 21,11"},
};

/* The metrics of the table (font 1). */
static void base_metrics(gks_font_metrics *m)
{
    int adv = 0;
    for (int i = 0; i < 95; i++)
        if (font[i].advance > adv)
            adv = font[i].advance;
    *m = (gks_font_metrics){.top = 25.0, .cap = 21.0, .half = 10.5, .base = 0.0,
                                   .bottom = -7.0, .max_advance = adv};
}

/* Parse an optionally signed integer at *s; advances *s. */
static int parse_int(const char **s)
{
    int sign = 1, v = 0;
    if (**s == '-') {
        sign = -1;
        (*s)++;
    }
    while (**s >= '0' && **s <= '9')
        v = 10 * v + (*(*s)++ - '0');
    return sign * v;
}

/* The glyph of ch in the table (font 1); '?' and E_ARG for ch outside 32..126. */
static int base_glyph(int ch, gks_glyph *g)
{
    int rc = GKS_FONT_OK;
    if (ch < 32 || ch > 126) {
        rc = GKS_FONT_E_ARG;
        ch = '?';
    }
    const glyph_def *d = &font[ch - 32];
    memset(g, 0, sizeof *g);
    g->advance = d->advance;
    const char *s = d->strokes;
    int in_stroke = 0;
    while (*s && g->n_points < GKS_GLYPH_MAX_POINTS) {
        if (*s == ' ') {
            s++;
            continue;
        }
        if (*s == '|') {
            in_stroke = 0;
            s++;
            continue;
        }
        if (!in_stroke) {
            if (g->n_strokes == GKS_GLYPH_MAX_STROKES)
                break;
            g->n_strokes++;
            in_stroke = 1;
        }
        const char *before = s;
        int x = parse_int(&s);
        if (*s == ',')
            s++;
        int y = parse_int(&s);
        if (s == before) { /* not a number: malformed table entry */
            s++;
            continue;
        }
        g->xy[2 * g->n_points] = x;
        g->xy[2 * g->n_points + 1] = y;
        g->n_points++;
        g->stroke_len[g->n_strokes - 1]++;
    }
    return rc;
}

/* ---- derived faces ---------------------------------------------------------------- */
typedef struct face {
    int font;
    unsigned char serif, bold, italic;
} face;

static const face faces[] = {
    { 1, 0, 0, 0 },    { -101, 0, 0, 0 }, { -102, 0, 1, 0 }, { -104, 1, 0, 0 },
    { -105, 1, 0, 1 }, { -106, 1, 1, 0 }, { -107, 1, 1, 1 },
};
#define N_FACES ((int)(sizeof faces / sizeof faces[0]))
#define BOLD_OFFSET 1.0  /* second stroke, font units to the right */
#define SERIF_HALF 2.0   /* half width of a serif */
#define ITALIC_SHEAR 0.2 /* x += shear * y */

static const face *face_of(int font)
{
    for (int i = 0; i < N_FACES; i++)
        if (faces[i].font == font)
            return &faces[i];
    return NULL;
}

int gks_font_has(int font)
{
    return face_of(font) != NULL;
}

void gks_font_get_metrics(int font, gks_font_metrics *m)
{
    if (!m)
        return;
    base_metrics(m);
    const face *f = face_of(font);
    if (f && f->bold)
        m->max_advance += BOLD_OFFSET;
}

/* Append a polyline of n points (xy pairs) to g; 0 if it does not fit. */
static int add_stroke(gks_glyph *g, int n, const double *xy)
{
    if (g->n_strokes == GKS_GLYPH_MAX_STROKES ||
        g->n_points + n > GKS_GLYPH_MAX_POINTS)
        return 0;
    memcpy(&g->xy[2 * g->n_points], xy, sizeof(double) * 2 * (size_t)n);
    g->stroke_len[g->n_strokes++] = n;
    g->n_points += n;
    return 1;
}

/* Whether (x, y), end point e of a stroke, is also another end point of the glyph's first
 * n strokes (a junction, or the closing point of a loop): no serif there. */
static int joins(const gks_glyph *g, const int *first, int n, int e, double x,
                 double y)
{
    for (int t = 0; t < n; t++) {
        int ends[2] = { first[t], first[t] + g->stroke_len[t] - 1 };
        for (int k = 0; k < 2; k++)
            if (ends[k] != e && g->xy[2 * ends[k]] == x && g->xy[2 * ends[k] + 1] == y)
                return 1;
    }
    return 0;
}

/* Serifs at the free ends of steep strokes on the base, x-height, cap or descender line. */
static void add_serifs(gks_glyph *g)
{
    static const double lines[] = { 0.0, 14.0, 21.0, -7.0 };
    int first[GKS_GLYPH_MAX_STROKES];
    int n_orig = g->n_strokes;
    for (int s = 0, off = 0; s < n_orig; s++) {
        first[s] = off;
        off += g->stroke_len[s];
    }
    for (int s = 0; s < n_orig; s++) {
        int len = g->stroke_len[s];
        if (len < 2)
            continue;
        for (int k = 0; k < 2; k++) {
            int e = k == 0 ? first[s] : first[s] + len - 1;
            int nb = k == 0 ? e + 1 : e - 1;
            double x = g->xy[2 * e], y = g->xy[2 * e + 1];
            double dx = fabs(x - g->xy[2 * nb]), dy = fabs(y - g->xy[2 * nb + 1]);
            int on_line = 0;
            for (int i = 0; i < 4; i++)
                on_line |= y == lines[i];
            if (!on_line || dy == 0 || dy < 2 * dx || joins(g, first, n_orig, e, x, y))
                continue;
            double x0 = fmax(0.0, x - SERIF_HALF), x1 = fmin(g->advance, x + SERIF_HALF);
            if (x1 > x0)
                add_stroke(g, 2, (const double[4]){ x0, y, x1, y });
        }
    }
}

int gks_font_get_glyph(int font, int ch, gks_glyph *g)
{
    if (!g)
        return GKS_FONT_E_ARG;
    int rc = base_glyph(ch, g);
    const face *f = face_of(font);
    if (!f)
        return GKS_FONT_E_ARG;
    if (f->serif)
        add_serifs(g);
    if (f->bold) { /* copies at BOLD_OFFSET / 2 and BOLD_OFFSET to the right */
        int n_orig = g->n_strokes;
        for (int c = 1; c <= 2; c++)
            for (int s = 0, off = 0; s < n_orig; s++) {
                double xy[2 * GKS_GLYPH_MAX_POINTS];
                int len = g->stroke_len[s];
                for (int j = 0; j < len; j++) {
                    xy[2 * j] = g->xy[2 * (off + j)] + 0.5 * c * BOLD_OFFSET;
                    xy[2 * j + 1] = g->xy[2 * (off + j) + 1];
                }
                add_stroke(g, len, xy);
                off += len;
            }
        g->advance += BOLD_OFFSET;
    }
    if (f->italic)
        for (int j = 0; j < g->n_points; j++)
            g->xy[2 * j] += ITALIC_SHEAR * g->xy[2 * j + 1];
    return rc;
}
