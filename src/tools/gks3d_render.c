/* SPDX-License-Identifier: MIT */
/*
 * gks3d_render.c -- gks3d-render: renders a GKS metafile (GKSM, e.g. one recorded with
 * GKS3D_RECORD) again, through the library's own metafile input: an MI workstation, GET ITEM
 * TYPE / READ ITEM / INTERPRET ITEM, onto one output workstation chosen by the output
 * file's extension (PNG, PDF, SVG, PS, EPS), with the HLHSR mode, picture size and
 * ray-tracing settings of the command line in the place of the recorded ones.
 *
 *   gks3d-render IN.gksm -o OUT.EXT [--mode M] [--size W[xH]] [--samples N] [--depth N]
 *                [--aa S] [--threads N] [--frames LIST] [--type T] [--view YAW,PITCH]
 *                [--progress] [--quiet]
 *   gks3d-render IN.gksm --name PATTERN [options]      frame N to PATTERN's name for N
 *   gks3d-render IN.gksm --x11 [--name PATTERN.png] [options]   a window to turn
 *
 * Two passes over the file: the first reads every item (GET ITEM TYPE, READ ITEM) and
 * interprets none, so a missing, truncated or malformed file is reported (the reader's
 * error number and its name) before any output file is written; the second interprets.
 * The metafile is untrusted: the MI workstation's escape policy (docs/METAFILE.md,
 * "Untrusted input") is left at its default, so a recorded ESCAPE that names a file, starts
 * threads or prints is refused (error 180); the only files written are OUT's frames.
 * Exit status: 0; 1 usage; 2 input missing, unreadable, truncated or not a metafile
 * (nothing written); 3 output error; 4 written, but items of the metafile were refused or
 * invalid (each reported on standard error, at most 20 lines).
 * Manual page: docs/man/man1/gks3d-render.1.
 */
#include <gks.h>

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

enum { WS_IN = 1, WS_OUT = 2, SEG_ALL = 1 };
enum { EXIT_USAGE = 1, EXIT_INPUT = 2, EXIT_OUTPUT = 3, EXIT_ITEMS = 4 };
enum { MAX_FRAME_RANGES = 64, MAX_REPORTED = 20 };
#define PX_M 0.0002 /* a pixel of a raster recording is 0.2 mm on a vector page, and back */

static const char *prog = "gks3d-render";

/* ---------------------------------------------------------------- errors */
/* The error handler records; the program decides what an error means where it happens.
 * It never calls GKS. */
static struct {
    int n;         /* errors since the last reset */
    int first;     /* the first of them */
    int first_fct;
    char detail[256];
} errs;

static void handler(Gint err, Gint fct, const char *file)
{
    (void)file;
    if (errs.n++ == 0) {
        errs.first = err;
        errs.first_fct = fct;
        snprintf(errs.detail, sizeof errs.detail, "%s", gks_error_detail());
    }
}

static void errs_reset(void)
{
    errs.n = 0;
    errs.first = 0;
    errs.detail[0] = '\0';
}

/* "error N (message)" of the first recorded error, and its detail if any. */
static void say_error(const char *what)
{
    fprintf(stderr, "%s: %s: GKS error %d (%s%s%s)\n", prog, what, errs.first,
            gks_error_message(errs.first), errs.detail[0] ? "; " : "", errs.detail);
}

/* ---------------------------------------------------------------- options */
typedef struct {
    const char *in, *out;
    int type;                 /* output workstation type */
    int mode;                 /* -1: as recorded */
    int width, height;        /* --size (0: as recorded) */
    int samples, depth, aa, threads; /* -1: as recorded / the workstation's */
    int progress, quiet;
    int x11;                  /* --x11: a window to turn instead of a file */
    const char *name;         /* --name PATTERN: frame N's file (one %d conversion) */
    int have_view;            /* --view YAW,PITCH */
    double yaw, pitch;        /* degrees: turns of the recorded view orientations */
    int n_ranges;
    int lo[MAX_FRAME_RANGES], hi[MAX_FRAME_RANGES]; /* --frames, 1-based, inclusive */
} options;

static void usage(void)
{
    fprintf(stderr,
            "usage: %s IN.gksm -o OUT.{png,pdf,svg,ps,eps} [--mode M] [--size W[xH]]\n"
            "       [--samples N] [--depth N] [--aa S] [--threads N] [--frames LIST]\n"
            "       [--type T] [--view YAW,PITCH] [--progress] [--quiet]\n"
            "       %s IN.gksm --name PATTERN [options]\n"
            "       %s IN.gksm --x11 [--name PATTERN.png] [options]\n"
            "       %s --help\n", prog, prog, prog, prog);
}

static void help(void)
{
    printf("%s -- renders a GKS metafile (GKSM; GKS3D_RECORD=FILE.gksm records one from\n"
           "any GKS program) again with gks3d, in any HLHSR mode, to PNG, PDF, SVG, PS or EPS.\n"
           "\n"
           "usage: %s IN.gksm -o OUT.EXT [options]\n"
           "  -o, --output OUT   the output file; its extension (png, pdf, svg, ps, eps) is\n"
           "                     the type. Later frames: PNG, SVG and EPS write OUT-002.EXT,\n"
           "                     OUT-003.EXT, ...; PDF and PS one page per frame\n"
           "  --name PATTERN     instead of -o: frame N to PATTERN with its one %%d or\n"
           "                     %%0wd replaced by N (%%%% a percent sign), e.g.\n"
           "                     out-%%03d.png; the type from its extension\n"
           "  --x11              the frame (the first of --frames) in an X11 window:\n"
           "                     drag with button 1 to turn the view (z-buffer while\n"
           "                     moving, then the final mode; ray tracing 1 sample a\n"
           "                     pixel, then --samples, default 4); key 1 saves the view\n"
           "                     to --name PATTERN.png (default gks3d-view-%%03d.png),\n"
           "                     key 2 prints it (offline command line, C and Fortran\n"
           "                     SET VIEW REPRESENTATION 3), key 3 resets, key 0 quits\n"
           "  --view YAW,PITCH   the recorded views turned (degrees about the view up\n"
           "                     axis, then about its horizontal axis), as key 2 prints\n"
           "  --type T           the type when OUT has another extension\n"
           "  --mode M           HLHSR mode: none, hidden-line, zbuffer, painter, raytrace\n"
           "                     (default: as recorded)\n"
           "  --size W[xH]       picture width (and height) in pixels; without H the\n"
           "                     recorded aspect ratio (vector output: 0.2 mm a pixel)\n"
           "  --samples N        ray tracing: N = m*m samples per pixel (1..256)\n"
           "  --depth N          ray tracing: maximum ray depth (1..64, eye ray = 1)\n"
           "  --aa S             anti-aliasing of PNG output: S x S samples (1..4)\n"
           "  --threads N        tracer threads (0: all CPUs)\n"
           "  --frames LIST      frames to render, e.g. 1,3-5 (default: all)\n"
           "  --progress         the ray tracer's progress on standard error\n"
           "  --quiet            no summary line\n"
           "  --help             this text\n"
           "The metafile is untrusted input: recorded escapes that name files, start\n"
           "threads or print are refused; nothing but OUT's frames (--name's files, the\n"
           "views the window saves) is written.\n"
           "Exit status: 0; 1 usage error; 2 input missing, unreadable, truncated or not a\n"
           "metafile (nothing written); 3 output error (--x11: no display, or built\n"
           "without X11); 4 written, but items of the metafile were refused or invalid\n"
           "(listed on standard error).\n", prog, prog);
}

static int int_arg(const char *s, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return -1;
    *out = (int)v;
    return 0;
}

static int size_arg(const char *s, int *w, int *h)
{
    char *end;
    errno = 0;
    long a = strtol(s, &end, 10), b = 0;
    if (errno || end == s || a < 1 || a > 8192)
        return -1;
    if (*end == 'x' || *end == 'X') {
        const char *t = end + 1;
        b = strtol(t, &end, 10);
        if (errno || end == t || b < 1 || b > 8192)
            return -1;
    }
    if (*end)
        return -1;
    *w = (int)a;
    *h = (int)b;
    return 0;
}

/* A --name pattern: exactly one conversion, %d or %0Nd (N one digit), and "%%" for a
 * percent sign; nothing else is expanded, so a frame's file name comes from the pattern
 * and the frame number alone (never from the metafile). */
static int pattern_ok(const char *p)
{
    int n = 0;
    for (; *p; p++) {
        if (*p != '%')
            continue;
        if (p[1] == '%') {
            p++;
            continue;
        }
        if (p[1] == '0' && isdigit((unsigned char)p[2]))
            p += 2;
        if (p[1] != 'd')
            return 0;
        p++;
        n++;
    }
    return n == 1;
}

/* The file name of frame under a checked pattern; -1 if it does not fit out. */
static int pattern_name(const char *p, int frame, char *out, size_t size)
{
    size_t k = 0;
    for (; *p; p++) {
        char piece[32];
        size_t n = 1;
        piece[0] = *p;
        if (*p == '%' && p[1] == '%') {
            p++;
        } else if (*p == '%') {
            int width = 0;
            if (p[1] == '0')
                width = p[2] - '0', p += 2;
            p++; /* the 'd' */
            n = (size_t)snprintf(piece, sizeof piece, "%0*d", width, frame);
        }
        if (k + n >= size)
            return -1;
        memcpy(out + k, piece, n);
        k += n;
    }
    out[k] = '\0';
    return 0;
}

/* --view YAW,PITCH (degrees, each within +-3600). */
static int view_arg(const char *s, options *o)
{
    char *end;
    o->yaw = strtod(s, &end);
    if (end == s || *end != ',' || !(fabs(o->yaw) <= 3600))
        return -1;
    s = end + 1;
    o->pitch = strtod(s, &end);
    if (end == s || *end || !(fabs(o->pitch) <= 3600))
        return -1;
    o->have_view = 1;
    return 0;
}

static int frames_arg(const char *s, options *o)
{
    o->n_ranges = 0;
    while (*s) {
        char *end;
        long a = strtol(s, &end, 10), b;
        if (end == s || a < 1 || a > INT_MAX)
            return -1;
        b = a;
        if (*end == '-') {
            s = end + 1;
            b = strtol(s, &end, 10);
            if (end == s || b < a || b > INT_MAX)
                return -1;
        }
        if (o->n_ranges == MAX_FRAME_RANGES)
            return -1;
        o->lo[o->n_ranges] = (int)a;
        o->hi[o->n_ranges++] = (int)b;
        if (*end == ',')
            end++;
        else if (*end)
            return -1;
        s = end;
    }
    return o->n_ranges ? 0 : -1;
}

static int wanted(const options *o, int frame)
{
    if (!o->n_ranges)
        return 1;
    for (int i = 0; i < o->n_ranges; i++)
        if (frame >= o->lo[i] && frame <= o->hi[i])
            return 1;
    return 0;
}

static const struct { const char *name; int type; } types[] = {
    { "png", GWS_TYPE_PNG }, { "pdf", GWS_TYPE_PDF }, { "svg", GWS_TYPE_SVG },
    { "ps", GWS_TYPE_PS }, { "eps", GWS_TYPE_EPS },
};
static const char *const mode_names[] = { "none", "hidden-line", "zbuffer", "painter",
                                          "raytrace" };

static int type_of(const char *name)
{
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcasecmp(name, types[i].name) == 0)
            return types[i].type;
    return 0;
}

/* An option with a value (a = "--name", v its value, NULL if none): 0, 1 bad value, -1
 * not one of them. */
static int value_option(const char *a, const char *v, options *o, const char **type)
{
    if (!v)
        return -1;
    if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
        o->out = v;
    } else if (strcmp(a, "--type") == 0) {
        *type = v;
    } else if (strcmp(a, "--mode") == 0) {
        o->mode = -2;
        for (int m = 0; m < 5; m++)
            if (strcmp(v, mode_names[m]) == 0)
                o->mode = m;
        return o->mode < 0;
    } else if (strcmp(a, "--size") == 0) {
        return size_arg(v, &o->width, &o->height) != 0;
    } else if (strcmp(a, "--samples") == 0) {
        int r = 0;
        if (int_arg(v, 1, 256, &o->samples))
            return 1;
        while ((r + 1) * (r + 1) <= o->samples)
            r++;
        return r * r != o->samples;
    } else if (strcmp(a, "--depth") == 0) {
        return int_arg(v, 1, 64, &o->depth) != 0;
    } else if (strcmp(a, "--aa") == 0) {
        return int_arg(v, 1, 4, &o->aa) != 0;
    } else if (strcmp(a, "--threads") == 0) {
        return int_arg(v, 0, 1024, &o->threads) != 0;
    } else if (strcmp(a, "--frames") == 0) {
        return frames_arg(v, o) != 0;
    } else if (strcmp(a, "--name") == 0) {
        o->name = v;
        return !pattern_ok(v);
    } else if (strcmp(a, "--view") == 0) {
        return view_arg(v, o) != 0;
    } else {
        return -1;
    }
    return 0;
}

/* --x11: no output file; --name the PNG files of the saved views. */
static int check_window(options *o, const char *type)
{
    if (o->out || type) {
        fprintf(stderr, "%s: --x11 writes no output file (-o, --type): its key 1 saves "
                "views to --name PATTERN\n", prog);
        return -1;
    }
    if (!o->name)
        o->name = "gks3d-view-%03d.png";
    type = strrchr(o->name, '.');
    if (!type || strcasecmp(type, ".png") != 0) {
        fprintf(stderr, "%s: the views the window saves are PNG: --name PATTERN.png\n", prog);
        return -1;
    }
    o->type = GWS_TYPE_X11;
    if (o->aa > 0) {
        fprintf(stderr, "%s: --aa is for PNG output\n", prog);
        return -1;
    }
    return 0;
}

/* A file output: -o or --name, the type (--type or the extension) and what it allows. */
static int check_output(options *o, const char *type)
{
    if (!!o->out == !!o->name) {
        fprintf(stderr, "%s: %s\n", prog, o->out ? "-o and --name exclude each other"
                                                 : "no output file (-o or --name)");
        return -1;
    }
    if (!type) {
        type = strrchr(o->out ? o->out : o->name, '.');
        type = type && !strchr(type, '/') ? type + 1 : "";
    }
    o->type = type_of(type);
    if (!o->type) {
        fprintf(stderr, "%s: output type '%s' unknown: png, pdf, svg, ps or eps\n", prog,
                type);
        return -1;
    }
    if (o->name && (o->type == GWS_TYPE_PDF || o->type == GWS_TYPE_PS)) {
        fprintf(stderr, "%s: --name is for the types with a file a frame (png, svg, eps); "
                "PDF and PS put the frames on pages of -o\n", prog);
        return -1;
    }
    if (o->aa > 0 && o->type != GWS_TYPE_PNG) {
        fprintf(stderr, "%s: --aa is for PNG output\n", prog);
        return -1;
    }
    return 0;
}

static int parse(int argc, char **argv, options *o)
{
    *o = (options){ .mode = -1, .samples = -1, .depth = -1, .aa = -1, .threads = -1 };
    const char *type = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int bad = value_option(a, v, o, &type);
        if (bad >= 0) {
            i++;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help();
            exit(0);
        } else if (strcmp(a, "--x11") == 0) {
            o->x11 = 1;
        } else if (strcmp(a, "--progress") == 0) {
            o->progress = 1;
        } else if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "%s: unknown option or missing value: %s\n", prog, a);
            return -1;
        } else if (!o->in) {
            o->in = a;
            bad = 0;
        } else {
            bad = 1;
        }
        if (bad > 0) {
            fprintf(stderr, "%s: bad argument near '%s'\n", prog, a);
            return -1;
        }
    }
    if (!o->in) {
        fprintf(stderr, "%s: no input file\n", prog);
        return -1;
    }
    return o->x11 ? check_window(o, type) : check_output(o, type);
}

/* ---------------------------------------------------------------- items */
static int is_primitive(int t)
{
    return (t >= 7 && t <= 9) || (t >= 11 && t <= 19) || (t >= 76 && t <= 80);
}

enum { ITEM_END = 0, ITEM_CLEAR = 1, ITEM_ESCAPE = 6, ITEM_VIEW_REP3 = 58, ITEM_HLHSR = 67,
       ITEM_WS_VP = 72, ITEM_WS_VP3 = 74, ITEM_CREATE_SEG = 81 };

static int has_segments; /* the metafile creates segments of its own (scan) */

/* The n reals of a WORKSTATION VIEWPORT (3) record as this library writes them (decimal
 * numbers separated by blanks); 0, or -1 for any other form (then the item is
 * interpreted as recorded). */
static int vp_values(const char *rec, size_t len, int n, double *v)
{
    char buf[512];
    if (len >= sizeof buf)
        return -1;
    memcpy(buf, rec, len);
    buf[len] = '\0';
    const char *s = buf;
    for (int k = 0; k < n; k++) {
        char *end;
        v[k] = strtod(s, &end);
        if (end == s || !(v[k] > -1e9 && v[k] < 1e9))
            return -1;
        s = end;
    }
    while (isspace((unsigned char)*s))
        s++;
    return *s ? -1 : 0;
}

/* Pass 1: every item read, none interpreted. *frames: the frames (CLEAR items after
 * drawing, and the last one), *max_px: the largest recorded viewport edge in pixels. */
static int scan(const options *o, int *frames, double *max_px)
{
    errs_reset();
    gopen_ws(WS_IN, o->in, GWS_TYPE_MI);
    if (errs.n) {
        say_error(o->in);
        return EXIT_INPUT;
    }
    char *buf = NULL;
    size_t cap = 0;
    long item = 0;
    int drawn = 0, rc = 0;
    *frames = 0;
    *max_px = 0;
    for (;; item++) {
        Gint type = -1, len = 0;
        gget_item_type(WS_IN, &type, &len);
        if (errs.n) {
            char what[64];
            snprintf(what, sizeof what, "item %ld", item + 1);
            fprintf(stderr, "%s: %s: %s\n", prog, o->in,
                    errs.first == 162 ? "the file ends before its END item (truncated?)"
                    : errs.first == 163 ? "an item is malformed or cut short (truncated?)"
                                        : "not readable as a GKS metafile");
            say_error(what);
            rc = EXIT_INPUT;
            break;
        }
        if ((size_t)len + 1 > cap) {
            char *nb = realloc(buf, (size_t)len + 1);
            if (!nb) {
                fprintf(stderr, "%s: out of memory (item of %d characters)\n", prog, len);
                rc = EXIT_INPUT;
                break;
            }
            buf = nb;
            cap = (size_t)len + 1;
        }
        Gitem_data d = { .data.impl_dep = { cap, buf } };
        gread_item(WS_IN, len, &d);
        if (errs.n) {
            say_error(o->in);
            rc = EXIT_INPUT;
            break;
        }
        if (type == ITEM_END)
            break;
        drawn |= is_primitive(type);
        has_segments |= type == ITEM_CREATE_SEG;
        if (type == ITEM_CLEAR && drawn) {
            ++*frames;
            drawn = 0;
        }
        double v[6];
        int n = type == ITEM_WS_VP ? 4 : 6;
        if ((type == ITEM_WS_VP || type == ITEM_WS_VP3) && !vp_values(buf, (size_t)len, n, v)) {
            double w = v[1] - v[0], h = v[3] - v[2];
            if (w > 2 || h > 2) { /* pixels: no page is 2 m */
                if (w > *max_px)
                    *max_px = w;
                if (h > *max_px)
                    *max_px = h;
            }
        }
    }
    if (drawn)
        ++*frames;
    free(buf);
    errs_reset();
    gclose_ws(WS_IN);
    return rc;
}

/* ---------------------------------------------------------------- render */
/* The output workstation: WS_OUT; WS_SAVE while the window (WS_OUT) saves a view. */
enum { WS_SAVE = 3 };
static int ws_out = WS_OUT;
typedef struct {
    const options *o;
    int type;            /* the output workstation's type */
    int n_item_errs;     /* items refused or invalid */
    long item;           /* the current item's number (1-based) */
    int out_failed;
    int last_pending;    /* the last frame is drawn but not yet written (no CLEAR after it) */
} render;

static void escape_ws(int func, Gint v)
{
    Gint ints[2] = { ws_out, v };
    Gescape_in_data in = { { 2, ints, 0, NULL, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

/* The command line's settings, in the place of what the metafile set. */
static void apply_settings(const options *o)
{
    if (o->mode >= 0)
        gset_hlhsr_mode(ws_out, o->mode);
    if (o->samples > 0)
        escape_ws(GESC_RT_SAMPLES, o->samples);
    if (o->depth > 0)
        escape_ws(GESC_RT_MAX_DEPTH, o->depth);
    if (o->aa > 0)
        escape_ws(GESC_PNG_SUPERSAMPLE, o->aa);
    if (o->threads >= 0)
        escape_ws(GESC_RT_THREADS, o->threads);
    if (o->progress)
        escape_ws(GESC_RT_PROGRESS, 1);
}

/* WORKSTATION VIEWPORT (3) of the recording, v, in the output's unit and --size. */
static void set_viewport(const render *r, int three, double *v)
{
    const options *o = r->o;
    int raster_in = v[1] - v[0] > 2 || v[3] - v[2] > 2;
    int raster_out = r->type == GWS_TYPE_PNG || r->type == GWS_TYPE_PNG_LARGE ||
                     r->type == GWS_TYPE_X11;
    double k = raster_in == raster_out ? 1 : raster_out ? 1 / PX_M : PX_M;
    double w = (v[1] - v[0]) * k, h = (v[3] - v[2]) * k;
    if (o->width > 0) {
        double unit = raster_out ? 1 : PX_M;
        double nw = o->width * unit;
        double nh = o->height > 0 ? o->height * unit : (w > 0 ? h * nw / w : nw);
        w = nw;
        h = nh;
    }
    double x0 = v[0] * k, y0 = v[2] * k;
    if (o->width > 0)
        x0 = y0 = 0;
    if (three) {
        Glimit3 l = { (Gfloat)x0, (Gfloat)(x0 + w), (Gfloat)y0, (Gfloat)(y0 + h),
                      (Gfloat)v[4], (Gfloat)v[5] };
        gset_ws_vp3(ws_out, &l);
    } else {
        Glimit l = { (Gfloat)x0, (Gfloat)(x0 + w), (Gfloat)y0, (Gfloat)(y0 + h) };
        gset_ws_vp(ws_out, &l);
    }
}

/* Reports (up to MAX_REPORTED lines) and counts the errors of interpreting one item. */
static void item_errors(render *r, int type)
{
    if (!errs.n)
        return;
    if (errs.first == 303 || errs.first == 26 || errs.first == 300)
        r->out_failed = 1;
    if (r->n_item_errs++ < MAX_REPORTED) {
        char what[96];
        snprintf(what, sizeof what, "%s: item %ld (type %d) %s", r->o->in, r->item, type,
                 errs.first == 180 ? "refused" : "not performed");
        say_error(what);
    } else if (r->n_item_errs == MAX_REPORTED + 1) {
        fprintf(stderr, "%s: %s: more items refused or invalid (not listed)\n", prog,
                r->o->in);
    }
}

/* ---------------------------------------------------------------- views turned */
#define DEG (3.14159265358979323846 / 180)

/* base's orientation turned in VRC3 about the view reference point: R = Rx(pitch) Ry(yaw)
 * applied after the recorded orientation (yaw about the view up axis v, pitch about u). */
static void turn_rep(const Gview_rep3 *base, double yaw, double pitch, Gview_rep3 *out)
{
    double ca = cos(yaw * DEG), sa = sin(yaw * DEG), cb = cos(pitch * DEG),
           sb = sin(pitch * DEG);
    const double r[3][3] = { { ca, 0, sa }, { sb * sa, cb, -sb * ca }, { -cb * sa, sb, cb * ca } };
    *out = *base;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            out->ori_matrix[i][j] = r[i][0] * base->ori_matrix[0][j] +
                                    r[i][1] * base->ori_matrix[1][j] +
                                    r[i][2] * base->ori_matrix[2][j];
}

static int views_seen[GKS_MAX_VIEW_IND + 1]; /* view indices the metafile sets */

/* After a recorded SET VIEW REPRESENTATION 3 (rec: its data record, the view index first):
 * the index noted and, with --view, the representation turned. */
static void recorded_view(const options *o, const char *rec, Gint len)
{
    char num[16];
    size_t n = (size_t)len < sizeof num - 1 ? (size_t)len : sizeof num - 1;
    memcpy(num, rec, n);
    num[n] = '\0';
    long v = strtol(num, NULL, 10);
    if (v < 1 || v > GKS_MAX_VIEW_IND)
        return;
    views_seen[v] = 1;
    if (!o->have_view)
        return;
    Gint e = 0;
    Gview_rep3 b, t;
    ginq_view_rep3(ws_out, (Gint)v, &e, &b);
    if (e)
        return;
    turn_rep(&b, o->yaw, o->pitch, &t);
    gset_view_rep3(ws_out, (Gint)v, &t);
}

/* ---------------------------------------------------------------- interpretation */
/* The frames written, by number (for --name). */
static int *done_frames;
static size_t n_done, cap_done;

/* Rays traced by the frames written, and the tracing's seconds (the summary line). */
static struct {
    double rays, seconds;
} tally;

/* Adds the output workstation's last traced picture (GESC_RT_STATS: eye, reflection,
 * refraction and shadow rays, render seconds) when its HLHSR mode is ray tracing; called
 * after each frame is written. The inquiry's errors are not the metafile's. */
static void tally_frame(void)
{
    Gint err = 1, mode = -1, ws[1] = { ws_out };
    ginq_hlhsr_mode(ws_out, &err, &mode);
    if (err || mode != GHLHSR_RAYTRACE)
        return;
    Gescape_in_data in = { .num_ints = 1, .ints = ws };
    Gstore store = NULL;
    Gescape_out_data *out = NULL;
    gcreate_store(&err, &store);
    if (!err)
        gescape(GESC_RT_STATS, &in, &store, &out);
    if (out && out->num_ints >= 5 && out->num_floats >= 2) {
        tally.rays += (double)out->ints[0] + out->ints[2] + out->ints[3] + out->ints[4];
        tally.seconds += out->floats[1];
    }
    if (store)
        gdel_store(store);
    errs_reset();
}

static void frame_done(int frame)
{
    if (n_done == cap_done) {
        size_t nc = cap_done ? 2 * cap_done : 16;
        int *nd = realloc(done_frames, nc * sizeof *nd);
        if (!nd)
            return; /* --name: that frame keeps the workstation's name (reported) */
        done_frames = nd;
        cap_done = nc;
    }
    done_frames[n_done++] = frame;
}

/* The first frame --frames asks for (the window shows one frame). */
static int first_wanted(const options *o, int n_frames)
{
    for (int f = 1; f <= n_frames; f++)
        if (wanted(o, f))
            return f;
    return 0;
}

/* Interprets WS_IN's items onto ws_out: the frames --frames asks for (window: only
 * frame `only`, its CLEAR items left out), the command line's settings in the place of
 * the recorded ones. 0, or EXIT_INPUT (GKS closed) when the file changed since scan. */
static int interpret(render *r, int only, int *written)
{
    const options *o = r->o;
    char *buf = NULL;
    size_t cap = 0;
    int frame = 1, drawn = 0;
    *written = 0;
    for (r->item = 1;; r->item++) {
        Gint type = -1, len = 0;
        errs_reset();
        gget_item_type(WS_IN, &type, &len);
        if (errs.n) { /* pass 1 read it: the file changed meanwhile */
            say_error(o->in);
            free(buf);
            gemergency_close_gks();
            return EXIT_INPUT;
        }
        if ((size_t)len + 1 > cap) {
            char *nb = realloc(buf, (size_t)len + 1);
            if (!nb) {
                fprintf(stderr, "%s: out of memory\n", prog);
                free(buf);
                gemergency_close_gks();
                return EXIT_INPUT;
            }
            buf = nb;
            cap = (size_t)len + 1;
        }
        Gitem_data d = { .data.impl_dep = { cap, buf } };
        gread_item(WS_IN, len, &d);
        if (errs.n) {
            say_error(o->in);
            free(buf);
            gemergency_close_gks();
            return EXIT_INPUT;
        }
        if (type == ITEM_END)
            break;
        if (type > 100) /* user items: the program's own data, nothing to draw */
            continue;
        int keep = only ? frame == only : wanted(o, frame);
        if (is_primitive(type)) {
            drawn = 1;
            if (!keep)
                continue;
        }
        if (type == ITEM_CLEAR) {
            if (!drawn)
                continue; /* an empty frame is not written */
            drawn = 0;
            frame++;
            if (only && keep)
                break; /* the window's frame is complete */
            if (!keep || only)
                continue;
            ++*written;
            frame_done(frame - 1);
        }
        double v[6];
        if (type == ITEM_WS_VP || type == ITEM_WS_VP3) {
            int three = type == ITEM_WS_VP3;
            if (!vp_values(buf, (size_t)len, three ? 6 : 4, v)) {
                set_viewport(r, three, v);
                item_errors(r, type);
                continue;
            }
        }
        ginterpret_item(type, len, &d);
        item_errors(r, type);
        if (type == ITEM_CLEAR && keep && !only)
            tally_frame(); /* the frame just written */
        if (type == ITEM_VIEW_REP3 && !errs.n)
            recorded_view(o, buf, len);
        if (type == ITEM_HLHSR || type == ITEM_ESCAPE) { /* the command line wins */
            errs_reset();
            apply_settings(o);
            item_errors(r, type);
        }
        if (r->out_failed)
            break;
    }
    free(buf);
    if (!only && drawn && wanted(o, frame)) {
        ++*written;
        frame_done(frame);
        r->last_pending = 1;
    }
    return 0;
}

/* A metafile may end with a segment open (CREATE SEGMENT without CLOSE SEGMENT): GKS
 * refuses to deactivate a workstation then (error 3), so the segment is closed first;
 * otherwise the last frame would not be written (found by fuzz_render). */
static void close_open_segment(void)
{
    Gop_st st;
    ginq_op_st(&st);
    if (st == GST_SGOP)
        gclose_seg();
}

/* --name: the workstation wrote frame k > 1 of the run to B-k.EXT (B: the first frame's
 * name less its extension); each becomes the pattern's name of its frame number. Under an
 * MPI launcher a rank has only the frames it wrote. 0 or EXIT_OUTPUT. */
static int rename_frames(const options *o, const char *first)
{
    const char *dot = strrchr(first, '.');
    size_t nb = dot && !strchr(dot, '/') ? (size_t)(dot - first) : strlen(first);
    int rc = 0, mpi = getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE");
    for (size_t k = 1; k < n_done; k++) {
        char src[PATH_MAX], dst[PATH_MAX];
        if (snprintf(src, sizeof src, "%.*s-%03zu%s", (int)nb, first, k + 1,
                     first + nb) >= (int)sizeof src ||
            pattern_name(o->name, done_frames[k], dst, sizeof dst)) {
            fprintf(stderr, "%s: --name: the name of frame %d is too long\n", prog,
                    done_frames[k]);
            rc = EXIT_OUTPUT;
            continue;
        }
        if (rename(src, dst) != 0 && !(mpi && errno == ENOENT)) {
            fprintf(stderr, "%s: %s -> %s: %s\n", prog, src, dst, strerror(errno));
            rc = EXIT_OUTPUT;
        }
    }
    return rc;
}

static int run(const options *o, double max_px, int *written)
{
    render r = { .o = o, .type = o->type };
    /* the PNG display space is 1024 pixels; the large PNG workstation has 8192 */
    if (o->type == GWS_TYPE_PNG && (o->width > 1024 || o->height > 1024 ||
                                    (o->width == 0 && max_px > 1024)))
        r.type = GWS_TYPE_PNG_LARGE;
    errs_reset();
    n_done = 0;
    gopen_ws(WS_IN, o->in, GWS_TYPE_MI);
    if (errs.n) {
        say_error(o->in);
        return EXIT_INPUT;
    }
    gopen_ws(ws_out, o->out, r.type);
    if (errs.n) {
        say_error(o->out);
        gclose_ws(WS_IN);
        return EXIT_OUTPUT;
    }
    apply_settings(o);
    if (o->width > 0) { /* until the metafile sets a viewport: the size given, square */
        double v[4] = { 0, o->width, 0, o->height > 0 ? o->height : o->width };
        set_viewport(&r, 0, v);
    }
    if (errs.n) {
        say_error("the settings of the command line");
        gclose_ws(ws_out);
        gclose_ws(WS_IN);
        return EXIT_USAGE;
    }
    gactivate_ws(ws_out);
    if (interpret(&r, 0, written))
        return EXIT_INPUT;
    errs_reset();
    close_open_segment();
    if (r.last_pending) { /* the last frame, written now: its rays counted */
        gupd_ws(ws_out, GFLAG_PERFORM);
        if (!errs.n)
            tally_frame();
    }
    gdeactivate_ws(ws_out);
    gclose_ws(ws_out);
    if (errs.n) {
        say_error(o->out);
        r.out_failed = 1;
    }
    errs_reset();
    gclose_ws(WS_IN);
    if (!r.out_failed && o->name && rename_frames(o, o->out))
        r.out_failed = 1;
    if (r.out_failed)
        return EXIT_OUTPUT;
    return r.n_item_errs ? EXIT_ITEMS : 0;
}

/* ---------------------------------------------------------------- the window */
/* --x11: the frame in an X11 window (the library's X11 workstation) that the mouse turns.
 * The tool drives GKS and the window reports through GKS input: LOCATOR 1 in EVENT mode
 * (a button-1 drag triggers it at every pointer position), CHOICE 1 in EVENT mode (keys
 * 0..9). The frame is interpreted into one segment (SEG_ALL), so a turned view is SET
 * VIEW REPRESENTATION 3 and REDRAW ALL SEGMENTS: the z-buffer mode while the pointer moves,
 * then, after STILL seconds without an event, the final mode (ray tracing: 1 sample a
 * pixel first, then --samples). */
#define STILL 0.3
enum { KEY_QUIT = 0, KEY_SAVE = 1, KEY_PRINT = 2, KEY_RESET = 3 };

typedef struct {
    const options *o;
    double max_px;
    Gview_rep3 base[GKS_MAX_VIEW_IND + 1]; /* the recorded views (views_seen) */
    double yaw, pitch;
    int mode, samples; /* the final picture's */
    int saved;         /* views saved so far */
    int frame;         /* the frame shown */
    /* an event AWAIT EVENT gave while the picture was refined, handled next */
    Gin_class pending;
} window;

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* The picture with the views turned, in mode (samples > 0: that many). 0, or the first
 * error (303: the window is gone). */
static int show(window *w, int mode, int samples)
{
    errs_reset();
    for (int v = 1; v <= GKS_MAX_VIEW_IND; v++)
        if (views_seen[v]) {
            Gview_rep3 t;
            turn_rep(&w->base[v], w->yaw, w->pitch, &t);
            gset_view_rep3(WS_OUT, v, &t);
        }
    gset_hlhsr_mode(WS_OUT, mode);
    if (samples > 0)
        escape_ws(GESC_RT_SAMPLES, samples);
    gredraw_all_seg_ws(WS_OUT);
    gupd_ws(WS_OUT, GFLAG_PERFORM);
    return errs.n ? errs.first : 0;
}

static void print_matrix_c(const char *what, const Gmatrix3 m)
{
    printf("        { /* %s */\n", what);
    for (int i = 0; i < 4; i++)
        printf("          { %.17g, %.17g, %.17g, %.17g },\n", m[i][0], m[i][1], m[i][2],
               m[i][3]);
    printf("        },\n");
}

/* A Fortran 77 DATA statement of a 4 x 4 matrix (column by column, as GSVWR reads it),
 * two values a line (fixed form: within column 72). */
static void print_matrix_f(const char *name, const Gmatrix3 m)
{
    printf("      DATA %s /\n", name);
    for (int k = 0; k < 16; k += 2)
        printf("     + %.9E, %.9E%s\n", m[k % 4][k / 4], m[(k + 1) % 4][k / 4],
               k < 14 ? "," : " /");
}

/* Key 2: the view as the command line of an offline render and as GKS calls (C and
 * Fortran 77) that put it into the program. */
static void print_view(const window *w)
{
    const options *o = w->o;
    printf("# gks3d-render: the view turned by yaw %.17g, pitch %.17g degrees\n", w->yaw,
           w->pitch);
    printf("# offline: gks3d-render '%s' --view %.17g,%.17g --frames %d --mode %s", o->in,
           w->yaw, w->pitch, w->frame, mode_names[w->mode]);
    if (w->mode == GHLHSR_RAYTRACE)
        printf(" --samples %d", w->samples);
    if (o->width > 0)
        printf(" --size %dx%d", o->width, o->height > 0 ? o->height : o->width);
    printf(" -o view.png\n");
    for (int v = 1; v <= GKS_MAX_VIEW_IND; v++) {
        if (!views_seen[v])
            continue;
        Gview_rep3 t;
        turn_rep(&w->base[v], w->yaw, w->pitch, &t);
        const Glimit3 *c = &t.clip_limit;
        static const char *const clip[] = { "GIND_NO_CLIP", "GIND_CLIP" };
        printf("/* C: SET VIEW REPRESENTATION 3, view %d (ws: your workstation) */\n", v);
        printf("    {\n        Gview_rep3 rep = {\n");
        print_matrix_c("orientation", t.ori_matrix);
        print_matrix_c("mapping", t.map_matrix);
        printf("        { %.17g, %.17g, %.17g, %.17g, %.17g, %.17g },\n", c->x_min, c->x_max,
               c->y_min, c->y_max, c->z_min, c->z_max);
        printf("        %s, %s, %s };\n", clip[t.xy_clip == GIND_CLIP],
               clip[t.back_clip == GIND_CLIP], clip[t.front_clip == GIND_CLIP]);
        printf("        gset_view_rep3(ws, %d, &rep);\n    }\n", v);
        printf("C     Fortran 77: SET VIEW REPRESENTATION 3, view %d (WKID: yours)\n", v);
        printf("      REAL VWM(4,4), PRM(4,4), VCLP(6)\n");
        print_matrix_f("VWM", t.ori_matrix);
        print_matrix_f("PRM", t.map_matrix);
        printf("      DATA VCLP / %.9E, %.9E,\n     + %.9E, %.9E,\n     + %.9E, %.9E /\n",
               c->x_min, c->x_max, c->y_min, c->y_max, c->z_min, c->z_max);
        printf("      CALL GSVWR(WKID, %d, VWM, PRM, VCLP, %d, %d, %d)\n", v,
               t.xy_clip == GIND_CLIP, t.back_clip == GIND_CLIP, t.front_clip == GIND_CLIP);
    }
    fflush(stdout);
}

/* Key 1: the turned view in the final mode as a PNG file (the --name pattern, numbered
 * by the saves), rendered as the offline command line of print_view renders it. */
static void save_view(window *w)
{
    char file[PATH_MAX];
    if (pattern_name(w->o->name, ++w->saved, file, sizeof file)) {
        fprintf(stderr, "%s: --name: the file name is too long\n", prog);
        return;
    }
    options so = *w->o;
    so.x11 = 0;
    so.out = file;
    so.name = NULL;
    so.type = GWS_TYPE_PNG;
    so.have_view = 1;
    so.yaw = w->yaw;
    so.pitch = w->pitch;
    so.mode = w->mode;
    so.samples = w->mode == GHLHSR_RAYTRACE ? w->samples : -1;
    so.n_ranges = 1;
    so.lo[0] = so.hi[0] = w->frame;
    int written = 0;
    ws_out = WS_SAVE;
    int rc = run(&so, w->max_px, &written);
    ws_out = WS_OUT;
    if (rc == 0 || rc == EXIT_ITEMS)
        printf("# saved %s\n", file);
    else
        fprintf(stderr, "%s: the view was not saved to %s\n", prog, file);
    fflush(stdout);
}

/* The picture refined after the pointer stopped: 0, or 303 (the window is gone). A
 * ray-traced refinement stops after its coarse pass when an event came meanwhile. */
static int refine(window *w)
{
    int e;
    if (w->mode != GHLHSR_RAYTRACE || w->samples <= 1) {
        e = show(w, w->mode, -1);
    } else {
        e = show(w, GHLHSR_RAYTRACE, 1);
        if (e)
            return e;
        printf("# coarse: yaw %.17g, pitch %.17g, 1 sample a pixel\n", w->yaw, w->pitch);
        fflush(stdout);
        Gint ws, num;
        gawait_event(0, &ws, &w->pending, &num);
        if (w->pending != GIN_NONE)
            return 0;
        e = show(w, GHLHSR_RAYTRACE, w->samples);
    }
    printf("# refined: yaw %.17g, pitch %.17g\n", w->yaw, w->pitch);
    fflush(stdout);
    return e;
}

/* The window's event loop, until key 0 or the window is closed. */
static void turn_loop(window *w)
{
    int stale = 1, drag = 0;
    double lx = 0, ly = 0, last = 0;
    for (;;) {
        Gint ws, num;
        Gin_class cls = w->pending;
        w->pending = GIN_NONE;
        errs_reset();
        if (cls == GIN_NONE)
            gawait_event(stale ? STILL : 1, &ws, &cls, &num); /* 1 s: is it still open? */
        if (cls == GIN_LOC) {
            Gloc l;
            gget_loc(&l);
            double x = l.position.x, y = l.position.y;
            if (drag && now_s() - last < STILL) {
                w->yaw += (x - lx) * 180;
                w->pitch -= (y - ly) * 180;
                if (show(w, GHLHSR_ZBUFFER, -1) == 303)
                    return;
                stale = 1;
            }
            drag = 1;
            lx = x, ly = y;
            last = now_s();
        } else if (cls == GIN_CHOICE) {
            Gin_status st;
            Gint c = 0;
            gget_choice(&st, &c);
            if (st != GIN_STATUS_OK || c == KEY_QUIT)
                return;
            if (c == KEY_SAVE)
                save_view(w);
            else if (c == KEY_PRINT)
                print_view(w);
            else if (c == KEY_RESET) {
                w->yaw = w->pitch = 0;
                if (show(w, GHLHSR_ZBUFFER, -1) == 303)
                    return;
                stale = 1;
            }
        } else if (cls == GIN_NONE) {
            drag = 0;
            errs_reset();
            gmessage(WS_OUT, "drag: turn   1: save PNG   2: print view   3: reset   0: quit");
            if (errs.n) /* the window is closed */
                return;
            if (stale) {
                if (refine(w) == 303)
                    return;
                stale = w->pending != GIN_NONE;
            }
        }
    }
}

/* Opens the window and interprets the frame into it; 0 or an exit status. */
static int open_window(window *w)
{
    const options *o = w->o;
    render r = { .o = o, .type = GWS_TYPE_X11 };
    errs_reset();
    gopen_ws(WS_IN, o->in, GWS_TYPE_MI);
    if (errs.n) {
        say_error(o->in);
        return EXIT_INPUT;
    }
    gopen_ws(WS_OUT, "", GWS_TYPE_X11);
    if (errs.n) {
        const char *d = getenv("DISPLAY");
        if (errs.first == 26)
            fprintf(stderr, "%s: --x11: no X display to open ($DISPLAY %s%s%s)\n", prog,
                    d ? "is '" : "is not set", d ? d : "", d ? "'" : "");
        else if (errs.first == 22 || errs.first == 23)
            fprintf(stderr, "%s: --x11: this gks3d is built without X11\n", prog);
        else
            say_error("--x11");
        gclose_ws(WS_IN);
        return EXIT_OUTPUT;
    }
    apply_settings(o);
    if (o->width > 0) {
        double v[4] = { 0, o->width, 0, o->height > 0 ? o->height : o->width };
        set_viewport(&r, 0, v);
    }
    if (errs.n) { /* e.g. --size beyond the window's 800 pixels */
        say_error("--x11: the settings of the command line");
        gclose_ws(WS_OUT);
        gclose_ws(WS_IN);
        return EXIT_USAGE;
    }
    gactivate_ws(WS_OUT);
    if (!has_segments)
        gcreate_seg(SEG_ALL);
    int written = 0;
    if (interpret(&r, w->frame, &written))
        return EXIT_INPUT;
    errs_reset();
    close_open_segment(); /* SEG_ALL, or one the metafile left open */
    gdeactivate_ws(WS_OUT);
    gclose_ws(WS_IN);
    for (int v = 1; v <= GKS_MAX_VIEW_IND; v++) {
        Gint e = 1;
        if (views_seen[v])
            ginq_view_rep3(WS_OUT, v, &e, &w->base[v]);
        views_seen[v] = views_seen[v] && !e;
    }
    Gint e = 0, mode = GHLHSR_ZBUFFER;
    ginq_hlhsr_mode(WS_OUT, &e, &mode);
    w->mode = o->mode >= 0 ? o->mode : mode;
    /* the locator's positions in NDC: transformation 0 first */
    Gint max_tran = 0;
    ginq_max_norm_tran_num(&e, &max_tran);
    for (int t = 1; t <= max_tran; t++)
        gset_vp_in_pri(0, t, GPRI_HIGHER);
    gset_loc_mode(WS_OUT, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    gset_choice_mode(WS_OUT, 1, GOP_EVENT, GSWITCH_NO_ECHO);
    if (errs.n) {
        say_error("--x11: the window's input");
        return EXIT_OUTPUT;
    }
    return r.n_item_errs ? EXIT_ITEMS : 0;
}

static int run_window(const options *o, int n_frames, double max_px)
{
    window w = { .o = o, .max_px = max_px, .samples = o->samples > 0 ? o->samples : 4,
                 .frame = first_wanted(o, n_frames) };
    if (!w.frame) {
        fprintf(stderr, "%s: --frames: no such frame in the file (%d)\n", prog, n_frames);
        return EXIT_USAGE;
    }
    int rc = open_window(&w);
    if (rc && rc != EXIT_ITEMS)
        return rc;
    if (show(&w, GHLHSR_ZBUFFER, -1) != 303)
        turn_loop(&w);
    errs_reset();
    gclose_ws(WS_OUT);
    return rc;
}

/* The program (main), also the entry of the fuzz target tests/fuzz/fuzz_render.c, which
 * includes this file with GKS3D_RENDER_NO_MAIN: every call starts from the same state. */
static int render_main(int argc, char **argv)
{
    options o;
    has_segments = 0;
    memset(views_seen, 0, sizeof views_seen);
    n_done = 0;
    memset(&tally, 0, sizeof tally);
    ws_out = WS_OUT;
    if (parse(argc, argv, &o)) {
        usage();
        return EXIT_USAGE;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    gopen_gks(NULL, 0);
    gset_err_hand(handler, NULL);
    int n_frames = 0, written = 0;
    double max_px = 0;
    int rc = scan(&o, &n_frames, &max_px);
    if (!rc && n_frames == 0) {
        fprintf(stderr, "%s: %s: the metafile draws nothing\n", prog, o.in);
        rc = EXIT_INPUT;
    }
    char first[PATH_MAX];
    if (!rc && !o.x11 && o.name) { /* --name: the first frame written is the pattern's */
        int f = first_wanted(&o, n_frames);
        if (!f || pattern_name(o.name, f, first, sizeof first)) {
            fprintf(stderr, "%s: %s\n", prog, f ? "--name: the file name is too long"
                                                : "--frames: no such frame in the file");
            rc = EXIT_USAGE;
        }
        o.out = first;
    }
    if (!rc && o.x11)
        rc = run_window(&o, n_frames, max_px);
    else if (!rc)
        rc = run(&o, max_px, &written);
    Gop_st st;
    ginq_op_st(&st);
    if (st != GST_GKCL) {
        errs_reset();
        gclose_gks();
        if (errs.n) /* something is still open: all of it closed (files flushed) */
            gemergency_close_gks();
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if ((rc == 0 || rc == EXIT_ITEMS) && !o.quiet && !o.x11) {
        fprintf(stderr, "%s: %d of %d frame%s written to %s in %.2f s", prog, written,
                n_frames, n_frames == 1 ? "" : "s", o.name ? o.name : o.out,
                (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9);
        if (tally.rays > 0) /* this process's rays (under MPI: its tiles) */
            fprintf(stderr, "; %.0f rays traced in %.2f s, %.2f Mrays/s", tally.rays,
                    tally.seconds, tally.seconds > 0 ? tally.rays / tally.seconds * 1e-6 : 0.0);
        fputc('\n', stderr);
    }
    return rc;
}

#ifndef GKS3D_RENDER_NO_MAIN
int main(int argc, char **argv)
{
    return render_main(argc, argv);
}
#endif
