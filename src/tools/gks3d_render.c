/* SPDX-License-Identifier: MIT */
/*
 * gks3d_render.c -- gks3d-render: renders a GKS metafile (GKSM, e.g. one recorded with
 * GKS3D_RECORD) again, through the library's own metafile input: an MI workstation, GET ITEM
 * TYPE / READ ITEM / INTERPRET ITEM, onto one output workstation chosen by the output
 * file's extension (PNG, PDF, SVG, PS, EPS), with the HLHSR mode, picture size and
 * ray-tracing settings of the command line in the place of the recorded ones.
 *
 *   gks3d-render IN.gksm -o OUT.EXT [--mode M] [--size W[xH]] [--samples N] [--depth N]
 *                [--aa S] [--threads N] [--frames LIST] [--type T] [--progress] [--quiet]
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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>

enum { WS_IN = 1, WS_OUT = 2 };
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
    int n_ranges;
    int lo[MAX_FRAME_RANGES], hi[MAX_FRAME_RANGES]; /* --frames, 1-based, inclusive */
} options;

static void usage(void)
{
    fprintf(stderr,
            "usage: %s IN.gksm -o OUT.{png,pdf,svg,ps,eps} [--mode M] [--size W[xH]]\n"
            "       [--samples N] [--depth N] [--aa S] [--threads N] [--frames LIST]\n"
            "       [--type T] [--progress] [--quiet]\n"
            "       %s --help\n", prog, prog);
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
           "threads or print are refused; nothing but OUT's frames is written.\n"
           "Exit status: 0; 1 usage error; 2 input missing, unreadable, truncated or not a\n"
           "metafile (nothing written); 3 output error; 4 written, but items of the metafile\n"
           "were refused or invalid (listed on standard error).\n", prog, prog);
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

static int parse(int argc, char **argv, options *o)
{
    *o = (options){ .mode = -1, .samples = -1, .depth = -1, .aa = -1, .threads = -1 };
    const char *type = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int bad = 0;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help();
            exit(0);
        } else if ((strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) && v) {
            o->out = v, i++;
        } else if (strcmp(a, "--type") == 0 && v) {
            type = v, i++;
        } else if (strcmp(a, "--mode") == 0 && v) {
            o->mode = -2;
            for (int m = 0; m < 5; m++)
                if (strcmp(v, mode_names[m]) == 0)
                    o->mode = m;
            bad = o->mode < 0, i++;
        } else if (strcmp(a, "--size") == 0 && v) {
            bad = size_arg(v, &o->width, &o->height), i++;
        } else if (strcmp(a, "--samples") == 0 && v) {
            int r = 0;
            bad = int_arg(v, 1, 256, &o->samples), i++;
            while (!bad && (r + 1) * (r + 1) <= o->samples)
                r++;
            bad = bad || r * r != o->samples;
        } else if (strcmp(a, "--depth") == 0 && v) {
            bad = int_arg(v, 1, 64, &o->depth), i++;
        } else if (strcmp(a, "--aa") == 0 && v) {
            bad = int_arg(v, 1, 4, &o->aa), i++;
        } else if (strcmp(a, "--threads") == 0 && v) {
            bad = int_arg(v, 0, 1024, &o->threads), i++;
        } else if (strcmp(a, "--frames") == 0 && v) {
            bad = frames_arg(v, o), i++;
        } else if (strcmp(a, "--progress") == 0) {
            o->progress = 1;
        } else if (strcmp(a, "--quiet") == 0) {
            o->quiet = 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "%s: unknown option or missing value: %s\n", prog, a);
            return -1;
        } else if (!o->in) {
            o->in = a;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "%s: bad argument near '%s'\n", prog, a);
            return -1;
        }
    }
    if (!o->in || !o->out) {
        fprintf(stderr, "%s: %s\n", prog, !o->in ? "no input file" : "no output file (-o)");
        return -1;
    }
    if (!type) {
        type = strrchr(o->out, '.');
        type = type && !strchr(type, '/') ? type + 1 : "";
    }
    o->type = type_of(type);
    if (!o->type) {
        fprintf(stderr, "%s: output type '%s' unknown: png, pdf, svg, ps or eps\n", prog,
                type);
        return -1;
    }
    if (o->aa > 0 && o->type != GWS_TYPE_PNG) {
        fprintf(stderr, "%s: --aa is for PNG output\n", prog);
        return -1;
    }
    return 0;
}

/* ---------------------------------------------------------------- items */
static int is_primitive(int t)
{
    return (t >= 7 && t <= 9) || (t >= 11 && t <= 19) || (t >= 76 && t <= 80);
}

enum { ITEM_END = 0, ITEM_CLEAR = 1, ITEM_ESCAPE = 6, ITEM_HLHSR = 67, ITEM_WS_VP = 72,
       ITEM_WS_VP3 = 74 };

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
typedef struct {
    const options *o;
    int type;            /* the output workstation's type */
    int n_item_errs;     /* items refused or invalid */
    long item;           /* the current item's number (1-based) */
    int out_failed;
} render;

static void escape_ws(int func, Gint v)
{
    Gint ints[2] = { WS_OUT, v };
    Gescape_in_data in = { { 2, ints, 0, NULL, 0, NULL } };
    gescape(func, &in, NULL, NULL);
}

/* The command line's settings, in the place of what the metafile set. */
static void apply_settings(const options *o)
{
    if (o->mode >= 0)
        gset_hlhsr_mode(WS_OUT, o->mode);
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
    int raster_out = r->type == GWS_TYPE_PNG || r->type == GWS_TYPE_PNG_LARGE;
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
        gset_ws_vp3(WS_OUT, &l);
    } else {
        Glimit l = { (Gfloat)x0, (Gfloat)(x0 + w), (Gfloat)y0, (Gfloat)(y0 + h) };
        gset_ws_vp(WS_OUT, &l);
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

static int run(const options *o, int n_frames, double max_px, int *written)
{
    render r = { .o = o, .type = o->type };
    /* the PNG display space is 1024 pixels; the large PNG workstation has 8192 */
    if (o->type == GWS_TYPE_PNG && (o->width > 1024 || o->height > 1024 ||
                                    (o->width == 0 && max_px > 1024)))
        r.type = GWS_TYPE_PNG_LARGE;
    errs_reset();
    gopen_ws(WS_IN, o->in, GWS_TYPE_MI);
    if (errs.n) {
        say_error(o->in);
        return EXIT_INPUT;
    }
    gopen_ws(WS_OUT, o->out, r.type);
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
        gclose_ws(WS_OUT);
        gclose_ws(WS_IN);
        return EXIT_USAGE;
    }
    gactivate_ws(WS_OUT);
    char *buf = NULL;
    size_t cap = 0;
    int frame = 1, drawn = 0;
    *written = 0;
    for (r.item = 1;; r.item++) {
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
        int keep = wanted(o, frame);
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
            if (!keep)
                continue;
            ++*written;
        }
        double v[6];
        if (type == ITEM_WS_VP || type == ITEM_WS_VP3) {
            int three = type == ITEM_WS_VP3;
            if (!vp_values(buf, (size_t)len, three ? 6 : 4, v)) {
                set_viewport(&r, three, v);
                item_errors(&r, type);
                continue;
            }
        }
        ginterpret_item(type, len, &d);
        item_errors(&r, type);
        if (type == ITEM_HLHSR || type == ITEM_ESCAPE) { /* the command line wins */
            errs_reset();
            apply_settings(o);
            item_errors(&r, type);
        }
        if (r.out_failed)
            break;
    }
    free(buf);
    if (drawn && wanted(o, frame))
        ++*written;
    (void)n_frames;
    errs_reset();
    gdeactivate_ws(WS_OUT);
    gclose_ws(WS_OUT);
    if (errs.n) {
        say_error(o->out);
        r.out_failed = 1;
    }
    errs_reset();
    gclose_ws(WS_IN);
    if (r.out_failed)
        return EXIT_OUTPUT;
    return r.n_item_errs ? EXIT_ITEMS : 0;
}

int main(int argc, char **argv)
{
    options o;
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
    if (!rc)
        rc = run(&o, n_frames, max_px, &written);
    Gop_st st;
    ginq_op_st(&st);
    if (st != GST_GKCL)
        gclose_gks();
    clock_gettime(CLOCK_MONOTONIC, &t1);
    if ((rc == 0 || rc == EXIT_ITEMS) && !o.quiet)
        fprintf(stderr, "%s: %d of %d frame%s written to %s in %.2f s\n", prog, written,
                n_frames, n_frames == 1 ? "" : "s", o.out,
                (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) * 1e-9);
    return rc;
}
