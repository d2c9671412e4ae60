/* SPDX-License-Identifier: MIT */
/*
 * gks3d_ncarg.c -- the NCAR Graphics profile (libgks3d_ncarg, docs/NCAR.md): what NCAR's
 * utilities (libncarg) expect of NCAR's own GKS beyond ISO GKS. Linked in place of
 * libncarg_gks; a constructor registers the hooks with the core (gks_set_profile,
 * gks_binding.h), so that without this library the core stays ISO GKS.
 *   - initial state: fill area interior style SOLID; colour 0 black, 1 white on every
 *     output workstation opened;
 *   - fill area interior style 4 (NCAR's "solid text fill", PLOTCHAR) drawn as SOLID;
 *   - NCAR's workstation types mapped to this library's (ncarg_ws_type; GKS3D_WS_TYPES
 *     still overrides);
 *   - NCAR's escapes -1388 (save, restore, get, set the attributes of NGSRAT), -1387 and
 *     -1389 (NGMFTC, NGREOP: suspend and reopen a metafile), and the PostScript escapes
 *     -1510 ... -1532 (line style and page onto the vector workstations' ESCAPEs, the
 *     others accepted with no effect, docs/NCAR.md);
 *   - NCAR-internal entry points of libncarg: GZW2NX, GZW2NY (world to NDC).
 */
#include "gks_binding.h"
#include "FC.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FAPI __attribute__((visibility("default")))
#define FNAME(lower, UPPER) FC_GLOBAL(lower, UPPER)
typedef int fint;
typedef float freal;

/* NCAR GKS's workstation types (NCAR GKS manual, "Workstation types"). */
enum {
    NCAR_NCGM = 1,        /* the NCAR Computer Graphics Metafile */
    NCAR_X11_EXIST = 7,   /* X11, an existing window */
    NCAR_X11 = 8,         /* X11, a new window */
    NCAR_PDF_PORT = 11,   /* PDF, portrait */
    NCAR_PDF_LAND = 12,   /* PDF, landscape */
    NCAR_PS_FIRST = 20,   /* 20..31: {colour, mono} x {PS, EPS, EPSI} x {portrait, landscape} */
    NCAR_PS_LAST = 31,
    NCAR_CAIRO_PS = 40,   /* cairo PostScript */
    NCAR_CAIRO_PNG = 41,  /* cairo PNG */
    NCAR_CAIRO_PDF = 42,  /* cairo PDF */
};

static int have_type(Gint type)
{
    Gint err = 0, len = 0, types[64];
    Gint_list l = { 0, types };
    ginq_list_avail_ws_types(64, 0, &err, &l, &len);
    for (int i = 0; !err && i < l.num_ints && i < 64; i++)
        if (types[i] == type)
            return 1;
    return 0;
}

/* NCAR's type to ours. NCGM -> PNG of category OUTPUT (one file per frame, always built,
 * viewable as ctrans's raster output is; PDF with GKS3D_WS_TYPES=1=110). X11 -> the X11
 * window when this build has it and DISPLAY is set, else the PNG files. PostScript,
 * EPS and EPSI -> PS and EPS, PDF -> PDF (A4 portrait: the landscape types are drawn
 * portrait, docs/NCAR.md). Others unchanged. */
static struct {
    Gint from, to; /* the last type mapped (OPEN WORKSTATION maps it just before it calls
                      opened_ws; inquiries map types too, hence both) */
} last_map;

static Gint map_type(Gint t);

static Gint ncarg_ws_type(Gint t)
{
    last_map.from = t;
    last_map.to = map_type(t);
    return last_map.to;
}

/* NCAR's landscape PDF and PostScript types */
static int landscape(Gint t)
{
    return t == NCAR_PDF_LAND || (t >= NCAR_PS_FIRST + 6 && t <= NCAR_PS_LAST);
}

static Gint map_type(Gint t)
{
    if (t == NCAR_NCGM || t == NCAR_CAIRO_PNG)
        return GWS_TYPE_PNG_OUTPUT;
    if (t == NCAR_X11 || t == NCAR_X11_EXIST) {
        const char *d = getenv("DISPLAY");
        return d && *d && have_type(GWS_TYPE_X11) ? GWS_TYPE_X11 : GWS_TYPE_PNG_OUTPUT;
    }
    if (t == NCAR_PDF_PORT || t == NCAR_PDF_LAND || t == NCAR_CAIRO_PDF)
        return GWS_TYPE_PDF;
    if (t == NCAR_CAIRO_PS)
        return GWS_TYPE_PS;
    if (t >= NCAR_PS_FIRST && t <= NCAR_PS_LAST)
        return (t - NCAR_PS_FIRST) % 3 == 0 ? GWS_TYPE_PS : GWS_TYPE_EPS;
    return t;
}

static void ncar_page_reset(void);
static void page_to_ws(Gint ws);

static void ncarg_opened_gks(void)
{
    gset_fill_int_style(GSTYLE_SOLID); /* NCAR GKS's initial interior style */
    ncar_page_reset();
}

/* NCAR's colour table: 0 black (background), 1 white (foreground), on the workstations
 * that have a colour table (OUTPUT, OUTIN, and the MO, which records it). */
static void ncarg_opened_ws(Gint ws_id)
{
    page_to_ws(ws_id); /* first: it reads the type OPEN WORKSTATION mapped */
    Gint err = 0, type = 0;
    char conn[2];
    Gws_cat cat = GCAT_OUT;
    ginq_ws_conn_type(ws_id, (Gint)sizeof conn, &err, conn, &type);
    if (!err)
        ginq_ws_cat(type, &err, &cat);
    if (err || (cat != GCAT_OUT && cat != GCAT_OUTIN && cat != GCAT_MO))
        return;
    const Gcolr_rep black = { { 0, 0, 0 } }, white = { { 1, 1, 1 } };
    gset_colr_rep(ws_id, 0, &black);
    gset_colr_rep(ws_id, 1, &white);
}

static Gint ncarg_fill_int_style(Gint style)
{
    return style == 4 ? (Gint)GSTYLE_SOLID : style; /* PLOTCHAR's solid text fill */
}

/* ----------------------------------------------------------------- escape -1388 */
/* The attributes NGSRAT saves, restores, returns and sets, in NCAR's order:
 * i: clip indicator, linetype, polyline colour, marker type, polymarker colour, text
 *    font, text precision, text colour, text path, horizontal and vertical alignment,
 *    fill interior style, fill style index, fill colour;
 * r: linewidth, marker size, character expansion, spacing, height, up vector x, y. */
typedef struct {
    int i[14];
    Gfloat r[7];
} ncar_attrs;

static ncar_attrs saved;
static int have_saved;

static void get_attrs(ncar_attrs *a)
{
    Gint e;
    Gclip clip;
    Gtext_font_prec fp;
    Gtext_path path;
    Gtext_align al;
    Gfill_int_style fis;
    Gvec up;
    memset(a, 0, sizeof *a);
    ginq_clip(&e, &clip);
    a->i[0] = clip.clip_ind == GIND_CLIP;
    ginq_linetype(&e, &a->i[1]);
    ginq_line_colr_ind(&e, &a->i[2]);
    ginq_marker_type(&e, &a->i[3]);
    ginq_marker_colr_ind(&e, &a->i[4]);
    ginq_text_font_prec(&e, &fp);
    a->i[5] = fp.font;
    a->i[6] = (int)fp.prec;
    ginq_text_colr_ind(&e, &a->i[7]);
    ginq_text_path(&e, &path);
    a->i[8] = (int)path;
    ginq_text_align(&e, &al);
    a->i[9] = (int)al.hor;
    a->i[10] = (int)al.vert;
    ginq_fill_int_style(&e, &fis);
    a->i[11] = (int)fis;
    ginq_fill_style_ind(&e, &a->i[12]);
    ginq_fill_colr_ind(&e, &a->i[13]);
    ginq_linewidth(&e, &a->r[0]);
    ginq_marker_size(&e, &a->r[1]);
    ginq_char_expan(&e, &a->r[2]);
    ginq_char_space(&e, &a->r[3]);
    ginq_char_ht(&e, &a->r[4]);
    ginq_char_up_vec(&e, &up);
    a->r[5] = up.delta_x;
    a->r[6] = up.delta_y;
}

/* Each setter checks its value as the standard says (a bad one is reported, as NCAR's
 * GKS would report it when NGSRAT passes it on). */
static void set_attrs(const ncar_attrs *a)
{
    gset_clip_ind(a->i[0] ? GIND_CLIP : GIND_NO_CLIP);
    gset_linetype(a->i[1]);
    gset_line_colr_ind(a->i[2]);
    gset_marker_type(a->i[3]);
    gset_marker_colr_ind(a->i[4]);
    const Gtext_font_prec fp = { a->i[5], (Gtext_prec)a->i[6] };
    gset_text_font_prec(&fp);
    gset_text_colr_ind(a->i[7]);
    gset_text_path((Gtext_path)a->i[8]);
    const Gtext_align al = { (Ghor_text_align)a->i[9], (Gvert_text_align)a->i[10] };
    gset_text_align(&al);
    gset_fill_int_style((Gfill_int_style)a->i[11]);
    gset_fill_style_ind(a->i[12]);
    gset_fill_colr_ind(a->i[13]);
    gset_linewidth(a->r[0]);
    gset_marker_size(a->r[1]);
    gset_char_expan(a->r[2]);
    gset_char_space(a->r[3]);
    gset_char_ht(a->r[4]);
    const Gvec up = { a->r[5], a->r[6] };
    gset_char_up_vec(&up);
}

/* Fixed-width fields of an 80-column record (NCAR's FORMAT I5 / E16.7): 0 = ok. */
static int field_int(const char *rec, size_t len, size_t at, size_t w, int *v)
{
    char buf[24];
    if (at + w > len || w >= sizeof buf)
        return -1;
    memcpy(buf, rec + at, w);
    buf[w] = '\0';
    char *end;
    long x = strtol(buf, &end, 10);
    while (*end == ' ')
        end++;
    if (*end || end == buf)
        return -1;
    *v = (int)x;
    return 0;
}

static int field_real(const char *rec, size_t len, size_t at, size_t w, Gfloat *v)
{
    char buf[24];
    if (at + w > len || w >= sizeof buf)
        return -1;
    memcpy(buf, rec + at, w);
    buf[w] = '\0';
    for (char *p = buf; *p; p++) /* Fortran's D exponent */
        if (*p == 'D' || *p == 'd')
            *p = 'E';
    char *end;
    *v = (Gfloat)strtod(buf, &end);
    while (*end == ' ')
        end++;
    return *end || end == buf ? -1 : 0;
}

#define REC 80 /* NCAR's record length (CHARACTER*80) */

/* -1388 as NGSRAT of NCAR Graphics 6.1 and later writes it (four records since 2012, the
 * integers 10 wide for ARGB colours): IDR(1) columns 1-5 the option: 0 save, 1 restore,
 * 2 get into ODR(1..4) (7I10 / 7I10 / 5E16.7 / 2E16.7), 3 set from IDR(1) columns 6-75
 * (7I10), IDR(2) (7I10), IDR(3) (5E16.7), IDR(4) (2E16.7). */
static int escape_attrs(const char *d, size_t n, Gescape_out_data *out)
{
    int opt;
    if (!d || n < REC || field_int(d, n, 0, 5, &opt))
        return 182;
    ncar_attrs a;
    size_t cap = out ? out->escape_r1.size : 0;
    if (out)
        out->escape_r1.size = 0;
    switch (opt) {
    case 0:
        get_attrs(&saved);
        have_saved = 1;
        return 0;
    case 1:
        if (!have_saved)
            return 182;
        set_attrs(&saved);
        return 0;
    case 2: {
        if (!out || cap < 4 * REC)
            return 182;
        get_attrs(&a);
        char *o = out->escape_r1.data;
        for (int r = 0; r < 2; r++) {
            char buf[REC + 8];
            int k = 0;
            for (int i = 7 * r; i < 7 * r + 7; i++) { /* wider than I10: '*' as Fortran */
                if (a.i[i] >= -999999999)
                    k += snprintf(buf + k, sizeof buf - (size_t)k, "%10d", a.i[i]);
                else
                    k += snprintf(buf + k, sizeof buf - (size_t)k, "**********");
            }
            memcpy(o + (size_t)r * REC, buf, (size_t)k);
        }
        for (int r = 0; r < 2; r++) {
            char buf[REC + 8];
            int k = 0;
            for (int i = 5 * r; i < (r ? 7 : 5); i++)
                k += snprintf(buf + k, sizeof buf - (size_t)k, "%16.7E", (double)a.r[i]);
            memcpy(o + (size_t)(2 + r) * REC, buf, (size_t)k);
        }
        out->escape_r1.size = 4 * REC;
        return 0;
    }
    case 3:
        if (n < 4 * REC)
            return 182;
        for (int i = 0; i < 14; i++)
            if (field_int(d, n, i < 7 ? 5 + 10 * (size_t)i : REC + 10 * (size_t)(i - 7), 10,
                          &a.i[i]))
                return 182;
        for (int i = 0; i < 7; i++)
            if (field_real(d, n, REC * (size_t)(2 + i / 5) + 16 * (size_t)(i % 5), 16, &a.r[i]))
                return 182;
        set_attrs(&a);
        return 0;
    default:
        return 182;
    }
}

/* Trailing blanks of d[0..n) dropped: the length left. */
static size_t trimmed(const char *d, size_t n)
{
    while (n > 0 && (d[n - 1] == ' ' || d[n - 1] == '\0'))
        n--;
    return n;
}

/* -1387 (NGMFTC): IDR(1) columns 1-5 a workstation identifier: NCAR suspends its NCGM
 * without ending the picture, so that -1389 can append to it. Here CLOSE WORKSTATION: the
 * picture drawn so far is written (a PNG or vector file cannot be appended to later). */
static int escape_suspend(const char *d, size_t n)
{
    int ws;
    if (!d || n < 5 || field_int(d, n, 0, 5, &ws))
        return 182;
    gclose_ws(ws); /* reports 25, 29 itself, as NCAR's GESC does */
    return 0;
}

/* -1389 (NGREOP): IDR(1) 7I5 workstation identifier, connection identifier, type,
 * attribute flag, number of colours, first colour index, option; IDR(2..5) the file name
 * (80, 80, 80, 16 columns); with the flag IDR(6..9) 8I10 and IDR(10..13) 5E16.7 (the last
 * 4E16.7): NCAR's full attribute set; then the colours, 4 per record as 3F6.3. Here OPEN
 * WORKSTATION of that file (the profile maps the type), its colour table, and with the
 * flag the attributes (as -1388 option 3). The reopened file starts anew. */
static int escape_reopen(const char *d, size_t n)
{
    int h[7];
    for (int i = 0; i < 7; i++)
        if (!d || field_int(d, n, 5 * (size_t)i, 5, &h[i]))
            return 182;
    int ws = h[0], type = h[2], flag = h[3], ncol = h[4], first = h[5];
    size_t at = flag ? 13 * REC : 5 * REC; /* the colour records */
    if (ncol < 0 || n < 5 * REC || n < at + (size_t)(ncol + 3) / 4 * REC)
        return 182;
    char name[4 * REC + 1];
    size_t k = 0;
    for (int r = 1; r <= 4; r++) {
        size_t len = r == 4 ? 16 : REC;
        memcpy(name + k, d + (size_t)r * REC, len);
        k += len;
    }
    k = trimmed(name, k);
    name[k] = '\0';
    ncar_attrs a;
    if (flag == 1) {
        static const int ipos[14] = { 1, 3, 4, 6, 7, 9, 10, 11, 12, 13, 14, 16, 17, 18 };
        for (int i = 0; i < 14; i++) {
            int j = ipos[i] - 1; /* IATE(j+1): 8I10 per record from IDR(6) */
            if (field_int(d, n, (size_t)(5 + j / 8) * REC + 10 * (size_t)(j % 8), 10, &a.i[i]))
                return 182;
        }
        for (int i = 0; i < 7; i++) /* RATE(1..7) */
            if (field_real(d, n, (size_t)(9 + i / 5) * REC + 16 * (size_t)(i % 5), 16, &a.r[i]))
                return 182;
    }
    gopen_ws(ws, name, type);
    Gint err = 0, t = 0;
    char conn[2];
    ginq_ws_conn_type(ws, (Gint)sizeof conn, &err, conn, &t);
    if (err)
        return 0; /* OPEN WORKSTATION has reported why */
    for (int i = 0; i < ncol; i++) {
        Gfloat v[3];
        size_t o = at + (size_t)(i / 4) * REC + 18 * (size_t)(i % 4);
        for (int j = 0; j < 3; j++)
            if (field_real(d, n, o + 6 * (size_t)j, 6, &v[j]))
                return 182;
        const Gcolr_rep c = { { v[0], v[1], v[2] } };
        gset_colr_rep(ws, first + i, &c);
    }
    if (flag == 1)
        set_attrs(&a);
    return 0;
}

/* ----------------------------------------- NCAR's PostScript and PDF escapes */
/* NCAR's PostScript/PDF settings (NGSETI/NGSETR 'NO', 'JO', 'CA', 'MI', 'LX'..'UY',
 * 'PX'..'QY', 'PW', 'PH', 'SW', 'SH'), mapped onto this library's vector workstations
 * (PDF, SVG, PS, EPS: gks.h GESC_VEC_*); NCAR's GKS ignores them for other workstation
 * types, and so does the profile. The page position (-1521) and page sizes (-1529 ...
 * -1532) name no workstation: they apply to vector workstations opened after them, as
 * NCAR's PostScript driver takes them when it opens. Until a program gives one, a vector
 * workstation's page is its viewport, as without the profile. */
static struct {
    int set;         /* a page position or size was given */
    Gint rect[4];    /* llx, lly, urx, ury (points): NCAR's default 36 126 576 666 */
    Gint pdf[2];     /* PDF page width, height (-1529, -1530): NCAR's 612 x 792 */
    Gint ps[2];      /* PS page (-1531, -1532) */
} ncar_page;

static void ncar_page_reset(void)
{
    ncar_page.set = 0;
    ncar_page.rect[0] = 36;
    ncar_page.rect[1] = 126;
    ncar_page.rect[2] = 576;
    ncar_page.rect[3] = 666;
    ncar_page.pdf[0] = ncar_page.ps[0] = 612;
    ncar_page.pdf[1] = ncar_page.ps[1] = 792;
}

/* Whether ws is one of the vector workstations (its type, *type). */
static int vector_ws(Gint ws, Gint *type)
{
    Gint err = 0;
    char conn[2];
    *type = 0;
    ginq_ws_conn_type(ws, (Gint)sizeof conn, &err, conn, type);
    return !err && (*type == GWS_TYPE_PDF || *type == GWS_TYPE_SVG || *type == GWS_TYPE_PS ||
                    *type == GWS_TYPE_EPS);
}

/* ESCAPE func of the vector workstation ws with ints (after the workstation identifier)
 * and reals; nothing for other workstations. Errors go through the error handler. */
static void vec_escape(Gint ws, Gint func, const Gint *v, int nv, const Gfloat *r, int nr)
{
    Gint type, ints[7] = { ws };
    if (!vector_ws(ws, &type))
        return;
    for (int i = 0; i < nv && i < 6; i++)
        ints[1 + i] = v[i];
    Gescape_in_data in = { { 1 + nv, ints, nr, r, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

/* The page given so far, onto the vector workstation ws (opened now). */
static void page_to_ws(Gint ws)
{
    Gint type;
    if (!ncar_page.set || !vector_ws(ws, &type))
        return;
    const Gint *pg = type == GWS_TYPE_PDF ? ncar_page.pdf : ncar_page.ps;
    int land = last_map.to == type && landscape(last_map.from); /* the page turned */
    Gint v[6] = { ncar_page.rect[0], ncar_page.rect[1], ncar_page.rect[2], ncar_page.rect[3],
                  pg[land], pg[!land] };
    vec_escape(ws, GESC_VEC_PAGE, v, 6, NULL, 0);
}

/* -1516 ... -1532: 0, or 182 for a record NCAR does not write. */
static int escape_postscript(Gint func_id, const char *d, size_t n)
{
    int ws = 0, i = 0, r4[4];
    Gfloat x = 0;
    switch (func_id) {
    case -1516: /* nominal line width: I5 ws, F9.3 factor in columns 7-15 */
    case -1520: /* miter limit: the same */
        if (field_int(d, n, 0, 5, &ws) || field_real(d, n, 6, 9, &x))
            return 182;
        if (func_id == -1516)
            x = x < 0.01f ? 0.01f : x > 100 ? 100 : x;
        else
            x = x < 1 ? 1 : x > 1000 ? 1000 : x;
        vec_escape(ws, func_id == -1516 ? GESC_VEC_LINE_SCALE : GESC_VEC_MITER_LIMIT, NULL, 0,
                   &x, 1);
        return 0;
    case -1518: /* line join, line cap: I5 ws, I1 0..2 in column 7 */
    case -1519:
        if (field_int(d, n, 0, 5, &ws) || field_int(d, n, 6, 1, &i) || i < 0 || i > 2)
            return 182;
        vec_escape(ws, func_id == -1518 ? GESC_VEC_LINE_JOIN : GESC_VEC_LINE_CAP, &i, 1, NULL,
                   0);
        return 0;
    case -1521: /* page position: 4I9 in columns 2-10, 12-20, 22-30, 32-40 */
        for (int k = 0; k < 4; k++)
            if (field_int(d, n, 1 + 10 * (size_t)k, 9, &r4[k]))
                return 182;
        memcpy(ncar_page.rect, r4, sizeof r4);
        ncar_page.set = 1;
        return 0;
    case -1526: /* page position of an open workstation: I5 ws, 4I9 from column 6 */
        if (field_int(d, n, 0, 5, &ws))
            return 182;
        for (int k = 0; k < 4; k++)
            if (field_int(d, n, 5 + 9 * (size_t)k, 9, &r4[k]))
                return 182;
        vec_escape(ws, GESC_VEC_PAGE, r4, 4, NULL, 0); /* on the page it has */
        return 0;
    case -1529: /* PDF page width, height; PS page width, height: I5 points */
    case -1530:
    case -1531:
    case -1532:
        if (field_int(d, n, 0, 5, &i) || i < 1 || i > 72000)
            return 182;
        (func_id >= -1530 ? ncar_page.pdf : ncar_page.ps)[func_id == -1529 ||
                                                          func_id == -1531 ? 0 : 1] = i;
        ncar_page.set = 1;
        return 0;
    default: /* -1510 ... -1515, -1517, -1522 ... -1525, -1527, -1528: segment copy marks,
                fill and hatch spacing, stack and path limits, background, coordinate
                scale, colour model, EPS box: a workstation identifier, no effect here */
        return field_int(d, n, 0, 5, &ws) ? 182 : 0;
    }
}

/* NCAR's escapes: -1388 save/restore of the attributes, -1387 and -1389 suspend and
 * reopen, -1510 ... -1532 PostScript and PDF (escape_postscript). Other identifiers are
 * not the profile's (-1). */
static int ncarg_escape(Gint func_id, const Gescape_in_data *in, Gescape_out_data *out)
{
    const char *d = in ? in->escape_r1.data : NULL;
    size_t n = in && d ? in->escape_r1.size : 0;
    if (func_id == -1388)
        return escape_attrs(d, n, out);
    if (out)
        out->escape_r1.size = 0; /* the others return nothing */
    if (func_id == -1387)
        return escape_suspend(d, n);
    if (func_id == -1389)
        return escape_reopen(d, n);
    if (func_id >= -1532 && func_id <= -1510)
        return d ? escape_postscript(func_id, d, n) : 182;
    return -1;
}

static const gks_profile ncarg_profile = {
    .opened_gks = ncarg_opened_gks,
    .opened_ws = ncarg_opened_ws,
    .ws_type = ncarg_ws_type,
    .fill_int_style = ncarg_fill_int_style,
    .escape = ncarg_escape,
};

/* Referenced by the link line (-Wl,-u,gks3d_ncarg_profile, gks3d-ncarg.pc) so that a
 * static link takes this object even when the program calls none of its entries. */
FAPI const gks_profile *gks3d_ncarg_profile = &ncarg_profile;

__attribute__((constructor)) static void ncarg_register(void)
{
    gks_set_profile(&ncarg_profile);
}

/* ------------------------------------------------- NCAR-internal entry points */
/* GZW2NX(N, P, Q), GZW2NY(N, P, Q): the N world coordinates P to NDC in Q by the current
 * normalization transformation (x resp. y); NCAR's GKS calls no error for them. */
static void w2n(const fint *n, const freal *p, freal *q, int y)
{
    Gint err = 0, tnr = 0;
    Gtran t;
    ginq_cur_norm_tran_num(&err, &tnr);
    if (!err)
        ginq_norm_tran(tnr, &err, &t);
    double w0 = 0, w1 = 1, v0 = 0, v1 = 1;
    if (!err) {
        w0 = y ? t.win.y_min : t.win.x_min;
        w1 = y ? t.win.y_max : t.win.x_max;
        v0 = y ? t.vp.y_min : t.vp.x_min;
        v1 = y ? t.vp.y_max : t.vp.x_max;
    }
    double s = w1 != w0 ? (v1 - v0) / (w1 - w0) : 1;
    for (fint i = 0; i < *n; i++)
        q[i] = (freal)(v0 + ((double)p[i] - w0) * s);
}

FAPI void FNAME(gzw2nx, GZW2NX)(const fint *n, const freal *p, freal *q)
{
    w2n(n, p, q, 0);
}

FAPI void FNAME(gzw2ny, GZW2NY)(const fint *n, const freal *p, freal *q)
{
    w2n(n, p, q, 1);
}
