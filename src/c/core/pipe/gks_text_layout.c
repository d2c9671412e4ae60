/* SPDX-License-Identifier: MIT */
/*
 * gks_text_layout.c -- TEXT (3) layout with the compiled-in stroke fonts (the font of
 * gks_text_attrs: font 1 or a face derived from it, src/c/font/gks_font.h).
 *
 * Geometry (ISO 7942 5.4.4, applied in the text plane): the character height is the
 * font's cap height; k = char_ht / cap converts font units. Within the plane, u is the
 * unit up vector and b = u turned clockwise by 90 degrees (the base direction). A glyph
 * point (gx, gy) of a character whose origin is (x, y) in the local (b, u) frame lies at
 * x + gx*k*char_expan along b and y + gy*k along u. Character bodies: width = advance,
 * height = top - bottom of the font; char_space*char_ht is added between bodies.
 * Paths: RIGHT/LEFT place bodies along +b / -b on one base line; UP/DOWN stack them
 * along +u / -u, each centred in a column as wide as the widest glyph of the font.
 * Alignment (NORMAL = LEFT/BASE for RIGHT, RIGHT/BASE for LEFT, CENTRE/BASE for UP,
 * CENTRE/TOP for DOWN): the chosen point of the text extent rectangle is moved to the
 * text position. For UP/DOWN, CAP is the cap line of the top character, BASE the base
 * line of the bottom one and HALF midway between them.
 */
#include "gks_text_layout.h"
#include "gks_font.h"
#include <math.h>
#include <string.h>

int gks_text_check(const char *s)
{
    for (; s && *s; s++)
        if ((unsigned char)*s < 32 || (unsigned char)*s > 126)
            return 101;
    return 0;
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

int gks_text_frame3(const double pos[3], const double d0[3], const double d1[3],
                    gks_text_frame *f)
{
    double n0 = sqrt(dot3(d0, d0));
    if (!isfinite(n0) || n0 == 0 || !isfinite(dot3(d1, d1)))
        return -1;
    double ex[3] = { d0[0] / n0, d0[1] / n0, d0[2] / n0 };
    /* ey: the part of d1 perpendicular to ex (Gram-Schmidt), i.e. ez x ex. */
    double p = dot3(d1, ex);
    double ey[3] = { d1[0] - p * ex[0], d1[1] - p * ex[1], d1[2] - p * ex[2] };
    double n1 = sqrt(dot3(ey, ey));
    if (!(n1 > 1e-12 * sqrt(dot3(d1, d1))) || !isfinite(n1))
        return -1;
    for (int i = 0; i < 3; i++) {
        f->org[i] = pos[i];
        f->ex[i] = ex[i];
        f->ey[i] = ey[i] / n1;
    }
    return 0;
}

/* The layout of a string in the local (b, u) frame, before alignment. */
typedef struct {
    double k, kx;           /* font unit -> plane units along u and along b */
    double gap;             /* spacing between bodies */
    double body_h;          /* body height */
    double col_w;           /* column width (UP/DOWN) */
    double box[4];          /* extent x0, x1, y0, y1 */
    double ref[2];          /* alignment point */
    double adv_total;       /* extent length along the path + gap (concatenation) */
    size_t n;
    int font;               /* the face drawn */
    gks_font_metrics m;
    double b[2], u[2];      /* base and up unit vectors in the plane */
} layout;

static double advance_of(int font, int ch)
{
    gks_glyph g;
    gks_font_get_glyph(font, ch, &g);
    return g.advance;
}

/* 0, or -1 when the attributes are degenerate. */
static int layout_init(const gks_text_attrs *a, const char *s, layout *L)
{
    memset(L, 0, sizeof *L);
    double ul = hypot(a->up[0], a->up[1]);
    if (!(ul > 0) || !isfinite(ul) || !(a->char_ht > 0) || !isfinite(a->char_ht) ||
        !(a->char_expan > 0) || !isfinite(a->char_expan) || !isfinite(a->char_space))
        return -1;
    L->font = gks_font_has(a->font) ? a->font : 1;
    gks_font_get_metrics(L->font, &L->m);
    L->u[0] = a->up[0] / ul;
    L->u[1] = a->up[1] / ul;
    L->b[0] = L->u[1];
    L->b[1] = -L->u[0];
    L->k = a->char_ht / L->m.cap;
    L->kx = L->k * a->char_expan;
    L->gap = a->char_space * a->char_ht;
    L->body_h = (L->m.top - L->m.bottom) * L->k;
    L->col_w = L->m.max_advance * L->kx;
    L->n = strlen(s);
    double top = L->m.top * L->k, bot = L->m.bottom * L->k;
    size_t n = L->n;
    int horizontal = a->path == GPATH_RIGHT || a->path == GPATH_LEFT;
    if (horizontal) {
        double w = 0;
        for (size_t i = 0; i < n; i++)
            w += advance_of(L->font, (unsigned char)s[i]) * L->kx;
        if (n > 1)
            w += (double)(n - 1) * L->gap;
        L->box[0] = 0; L->box[1] = w; L->box[2] = bot; L->box[3] = top;
        L->adv_total = w + L->gap;
    } else {
        double h = (double)n * L->body_h + (n > 1 ? (double)(n - 1) * L->gap : 0);
        L->box[0] = 0; L->box[1] = L->col_w; L->box[2] = 0; L->box[3] = h;
        L->adv_total = h + L->gap;
    }
    Ghor_text_align ha = a->align.hor;
    Gvert_text_align va = a->align.vert;
    if (ha == GHOR_NORM)
        ha = a->path == GPATH_RIGHT ? GHOR_LEFT : a->path == GPATH_LEFT ? GHOR_RIGHT : GHOR_CTR;
    if (va == GVERT_NORM)
        va = a->path == GPATH_DOWN ? GVERT_TOP : GVERT_BASE;
    L->ref[0] = ha == GHOR_LEFT ? L->box[0] : ha == GHOR_RIGHT ? L->box[1]
                                                               : 0.5 * (L->box[0] + L->box[1]);
    double base_line, cap_line;
    if (horizontal) {
        base_line = 0;
        cap_line = L->m.cap * L->k;
    } else {
        base_line = -bot;                                   /* bottom body's base line */
        cap_line = L->box[3] - L->body_h - bot + L->m.cap * L->k; /* top body's cap line */
    }
    switch (va) {
    case GVERT_TOP: L->ref[1] = L->box[3]; break;
    case GVERT_CAP: L->ref[1] = cap_line; break;
    case GVERT_HALF: L->ref[1] = 0.5 * (cap_line + base_line); break;
    case GVERT_BOTTOM: L->ref[1] = L->box[2]; break;
    default: L->ref[1] = base_line; break;
    }
    return 0;
}

/* Origin (x on the base line of the body, y of the base line) of character i. */
static void char_origin(const gks_text_attrs *a, const layout *L, size_t i, double adv,
                        double *pen, double *x, double *y)
{
    double bot = L->m.bottom * L->k;
    switch (a->path) {
    case GPATH_RIGHT:
        *x = *pen;
        *y = 0;
        *pen += adv + L->gap;
        break;
    case GPATH_LEFT:
        *pen -= adv;
        *x = *pen;
        *y = 0;
        *pen -= L->gap;
        break;
    case GPATH_UP:
        *x = 0.5 * (L->col_w - adv);
        *y = (double)i * (L->body_h + L->gap) - bot;
        break;
    default: /* DOWN */
        *x = 0.5 * (L->col_w - adv);
        *y = L->box[3] - (double)(i + 1) * L->body_h - (double)i * L->gap - bot;
        break;
    }
}

/* Local (x, y) relative to the alignment point -> WC3. */
static void to_wc(const gks_text_frame *f, const layout *L, double x, double y, double out[3])
{
    x -= L->ref[0];
    y -= L->ref[1];
    double p = x * L->b[0] + y * L->u[0]; /* plane coordinates */
    double q = x * L->b[1] + y * L->u[1];
    for (int i = 0; i < 3; i++)
        out[i] = f->org[i] + p * f->ex[i] + q * f->ey[i];
}

int gks_text_strokes(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                     gks_text_emit emit, void *ctx)
{
    layout L;
    if (!s || layout_init(a, s, &L))
        return 0;
    double pen = a->path == GPATH_LEFT ? L.box[1] : 0;
    double pts[GKS_GLYPH_MAX_POINTS][3];
    for (size_t i = 0; i < L.n; i++) {
        gks_glyph g;
        gks_font_get_glyph(L.font, (unsigned char)s[i], &g);
        double adv = g.advance * L.kx, x0, y0;
        char_origin(a, &L, i, adv, &pen, &x0, &y0);
        int off = 0;
        for (int k = 0; k < g.n_strokes && k < GKS_GLYPH_MAX_STROKES; k++) {
            int len = g.stroke_len[k];
            if (len < 0 || off + len > g.n_points || off + len > GKS_GLYPH_MAX_POINTS)
                break;
            for (int j = 0; j < len; j++)
                to_wc(f, &L, x0 + g.xy[2 * (off + j)] * L.kx, y0 + g.xy[2 * (off + j) + 1] * L.k,
                      pts[j]);
            if (len >= 2) {
                int r = emit(ctx, (size_t)len, (const double (*)[3])pts);
                if (r)
                    return r;
            }
            off += len;
        }
    }
    return 0;
}

int gks_text_place(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                   gks_text_place_fn place, void *ctx)
{
    layout L;
    if (!s || layout_init(a, s, &L))
        return 0;
    double pen = a->path == GPATH_LEFT ? L.box[1] : 0, o[3], ox[3], oy[3], ux[3], uy[3];
    to_wc(f, &L, L.ref[0], L.ref[1], o); /* the plane's origin: the text position */
    to_wc(f, &L, L.ref[0] + L.kx, L.ref[1], ox);
    to_wc(f, &L, L.ref[0], L.ref[1] + L.k, oy);
    for (int i = 0; i < 3; i++) {
        ux[i] = ox[i] - o[i];
        uy[i] = oy[i] - o[i];
    }
    for (size_t i = 0; i < L.n; i++) {
        int ch = (unsigned char)s[i];
        double x0, y0, org[3];
        char_origin(a, &L, i, advance_of(L.font, ch) * L.kx, &pen, &x0, &y0);
        to_wc(f, &L, x0, y0, org);
        int r = place(ctx, ch, org, ux, uy);
        if (r)
            return r;
    }
    return 0;
}

void gks_text_extent(const gks_text_frame *f, const gks_text_attrs *a, const char *s,
                     double corners[4][3], double concat[3])
{
    layout L;
    if (!s || layout_init(a, s, &L)) {
        for (int i = 0; i < 4; i++)
            memcpy(corners[i], f->org, sizeof f->org);
        memcpy(concat, f->org, sizeof f->org);
        return;
    }
    to_wc(f, &L, L.box[0], L.box[2], corners[0]);
    to_wc(f, &L, L.box[1], L.box[2], corners[1]);
    to_wc(f, &L, L.box[1], L.box[3], corners[2]);
    to_wc(f, &L, L.box[0], L.box[3], corners[3]);
    double dx = 0, dy = 0;
    switch (a->path) {
    case GPATH_RIGHT: dx = L.adv_total; break;
    case GPATH_LEFT: dx = -L.adv_total; break;
    case GPATH_UP: dy = L.adv_total; break;
    default: dy = -L.adv_total; break;
    }
    to_wc(f, &L, L.ref[0] + dx, L.ref[1] + dy, concat);
}
