/* SPDX-License-Identifier: MIT */
/*
 * gks_indev.c -- logical input devices, the input queue and the measure process
 * (gks_indev.h). The entry points of the standard are in gks_input.c; this file owns the
 * behaviour: where a raw device event goes, how device coordinates become a logical
 * value, how long AWAIT EVENT waits.
 *
 * Where a raw event of device D goes (ISO 7942 4.8): D in EVENT mode -> the input queue
 * (full: the event is lost and the overflow noted, see gks_in_await); D in SAMPLE mode ->
 * D's current measure; D in REQUEST mode -> the waiting REQUEST if it waits for D, else
 * nowhere (nobody listens to D). Scripted input replays raw events one by one; a script
 * line is consumed only when its device is taking input (docs/INPUT.md).
 */
#include "gks_indev.h"
#include "gks_alloc.h"
#include "gks_error.h"
#include "gks_seg_store.h"
#include "gks_ws.h"
#include "gks_xform.h"
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* The longest single wait of AWAIT EVENT, in seconds: a longer timeout is waited for in
 * steps of this (issue 40 D: 1e300 s overflowed time_t into a busy loop). */
#define GKS_IN_WAIT_MAX 3600.0

/* Pick aperture: half the side of the square around the pick position, in NPC. */
#define PICK_APERTURE 0.01

/* ---- values and records ---- */

void gks_in_val_free(gks_in_val *v)
{
    gks_free(v->pts);
    gks_free(v->str);
    v->pts = NULL;
    v->str = NULL;
    v->n = 0;
}

int gks_in_val_copy(gks_in_val *dst, const gks_in_val *src)
{
    gks_in_val t = *src;
    t.pts = NULL;
    t.str = NULL;
    if (src->n > 0 && src->pts) {
        if (!(t.pts = gks_alloc_array((size_t)src->n, sizeof *t.pts)))
            return 300;
        memcpy(t.pts, src->pts, (size_t)src->n * sizeof *t.pts);
    } else {
        t.n = 0;
    }
    if (src->str && !(t.str = gks_strdup(src->str))) {
        gks_free(t.pts);
        return 300;
    }
    gks_in_val_free(dst);
    *dst = t;
    return 0;
}

void gks_in_rec_free(Gin_data *r)
{
    gks_free((void *)r->ints);
    gks_free((void *)r->floats);
    gks_free((void *)r->str);
    *r = (Gin_data){ 0 };
}

int gks_in_rec_copy(Gin_data *dst, const Gin_data *src)
{
    Gin_data t = { 0 };
    if (src) {
        t.num_ints = src->ints && src->num_ints > 0 ? src->num_ints : 0;
        t.num_floats = src->floats && src->num_floats > 0 ? src->num_floats : 0;
        t.str_len = src->str ? src->str_len : 0;
    }
    Gint *ti = NULL;
    Gfloat *tf = NULL;
    char *ts = NULL;
    if ((t.num_ints && !(ti = gks_alloc_array((size_t)t.num_ints, sizeof *ti))) ||
        (t.num_floats && !(tf = gks_alloc_array((size_t)t.num_floats, sizeof *tf))) ||
        (t.str_len && !(ts = gks_alloc_array(t.str_len, 1)))) {
        gks_free(ti);
        gks_free(tf);
        return 300;
    }
    if (ti)
        memcpy(ti, src->ints, (size_t)t.num_ints * sizeof *ti);
    if (tf)
        memcpy(tf, src->floats, (size_t)t.num_floats * sizeof *tf);
    if (ts)
        memcpy(ts, src->str, t.str_len);
    t.ints = ti;
    t.floats = tf;
    t.str = ts;
    gks_in_rec_free(dst);
    *dst = t;
    return 0;
}

/* ---- the input queue (part of the GKS state list) ---- */

typedef struct in_event {
    int ws_id;
    Gin_class cls;
    int num;
    gks_in_val v;
} in_event;

struct gks_in_queue {
    in_event ev[GKS_IN_QUEUE_MAX];
    int head, n;
    int blocked;        /* overflowed: nothing is added until the queue has been emptied */
    int report_147;     /* AWAIT EVENT reports 147 once after an overflow */
    int ovf;            /* 0 none, 1 device below, 2 its workstation was closed */
    int ovf_ws, ovf_num;
    Gin_class ovf_cls;
    in_event cur;       /* current event report (cls GIN_NONE: empty) */
};

static struct gks_in_queue *queue(void)
{
    gks_state_list *sl = gks_ctx()->sl;
    if (!sl->inq)
        sl->inq = gks_calloc_array(1, sizeof *sl->inq);
    return sl->inq;
}

static void set_current(struct gks_in_queue *q, in_event *e)
{
    gks_in_val_free(&q->cur.v);
    q->cur = *e;
    *e = (in_event){ 0 };
}

static void enqueue(gks_ws *ws, Gin_class cls, int num, gks_in_val *v)
{
    struct gks_in_queue *q = queue();
    if (!q) {
        gks_in_val_free(v);
        return;
    }
    if (q->blocked || q->n == GKS_IN_QUEUE_MAX) {
        if (!q->blocked) {
            q->blocked = 1;
            q->report_147 = 1;
            q->ovf = 1;
            q->ovf_ws = ws->id;
            q->ovf_cls = cls;
            q->ovf_num = num;
        }
        gks_in_val_free(v);
        return;
    }
    in_event *e = &q->ev[(q->head + q->n++) % GKS_IN_QUEUE_MAX];
    *e = (in_event){ ws->id, cls, num, *v };
    *v = (gks_in_val){ 0 };
}

static int dequeue(struct gks_in_queue *q, in_event *out)
{
    if (q->n == 0)
        return 0;
    *out = q->ev[q->head];
    q->ev[q->head] = (in_event){ 0 };
    q->head = (q->head + 1) % GKS_IN_QUEUE_MAX;
    if (--q->n == 0)
        q->blocked = 0;
    return 1;
}

/* Removes the queued events that match (cls GIN_NONE / num 0: any). */
static void remove_events(int ws_id, Gin_class cls, int num)
{
    struct gks_in_queue *q = gks_ctx()->sl->inq;
    if (!q)
        return;
    int k = 0;
    in_event keep[GKS_IN_QUEUE_MAX];
    in_event e;
    while (dequeue(q, &e)) {
        if (e.ws_id == ws_id && (cls == GIN_NONE || e.cls == cls) && (num == 0 || e.num == num))
            gks_in_val_free(&e.v);
        else
            keep[k++] = e;
    }
    for (int i = 0; i < k; i++)
        q->ev[i] = keep[i];
    q->head = 0;
    q->n = k;
    if (k == 0)
        q->blocked = 0;
}

void gks_in_reset(void)
{
    gks_state_list *sl = gks_ctx()->sl;
    struct gks_in_queue *q = sl ? sl->inq : NULL;
    if (!q)
        return;
    in_event e;
    while (dequeue(q, &e))
        gks_in_val_free(&e.v);
    gks_in_val_free(&q->cur.v);
    gks_free(q);
    sl->inq = NULL;
}

/* ---- scripted input (docs/INPUT.md) ---- */

struct gks_in_script {
    FILE *fp;
    char *path;
    long line_no;
    int have;                 /* a parsed event is waiting in ev */
    int eof;
    char *line;               /* the line being read, whole (any length, never split) */
    size_t len, cap;          /* its characters so far, its storage */
    int line_done;            /* line holds a whole line not parsed yet (storage failed) */
    gks_in_raw ev;
    double (*pts)[3];         /* its points */
    size_t cap_pts;
    char str[GKS_IN_STRING_MAX + 1];
};

static void script_free(struct gks_in_script *s)
{
    if (!s)
        return;
    if (s->fp)
        fclose(s->fp);
    gks_free(s->path);
    gks_free(s->line);
    gks_free(s->pts);
    gks_free(s);
}

/* The script file for reading: a regular file only (through a symbolic link too), the
 * same rule as for output files. A FIFO or device is refused without blocking (O_NONBLOCK:
 * opening a FIFO without a writer would wait for one; /dev/zero or /dev/urandom would feed
 * REQUEST forever). NULL on failure. */
static FILE *open_script(const char *path)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        gks_error_note("cannot open input script \"%s\": %s", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    FILE *fp = NULL;
    if (fstat(fd, &st) != 0)
        gks_error_note("cannot read input script \"%s\": %s", path, strerror(errno));
    else if (!S_ISREG(st.st_mode))
        gks_error_note("input script \"%s\" is not a regular file", path);
    else if (fcntl(fd, F_SETFL, 0) != 0 || !(fp = fdopen(fd, "r")))
        gks_error_note("cannot read input script \"%s\": %s", path, strerror(errno));
    if (!fp)
        close(fd);
    return fp;
}

int gks_in_script_attach(gks_ws *ws, const char *path, size_t n)
{
    if (!ws->in || !path || n == 0)
        return 182;
    struct gks_in_script *s = gks_calloc_array(1, sizeof *s);
    if (!s || !(s->path = gks_strndup(path, n))) {
        gks_free(s);
        return 300;
    }
    if (!(s->fp = open_script(s->path))) {
        script_free(s);
        return 182;
    }
    script_free(ws->in->script);
    ws->in->script = s;
    return 0;
}

static const struct { const char *word; Gin_class cls; int dim; } script_words[] = {
    { "locator", GIN_LOC, 2 }, { "locator3", GIN_LOC, 3 }, { "stroke", GIN_STROKE, 2 },
    { "stroke3", GIN_STROKE, 3 }, { "valuator", GIN_VAL, 0 }, { "choice", GIN_CHOICE, 0 },
    { "pick", GIN_PICK, 2 }, { "string", GIN_STRING, 0 },
};

/* 0, -1 (more points than a stroke buffer can hold: invalid) or -2 (storage). */
static int add_point(struct gks_in_script *s, const double p[3])
{
    if (s->ev.n >= GKS_IN_STROKE_MAX)
        return -1;
    if (gks_grow(&s->pts, &s->cap_pts, (size_t)s->ev.n + 1, sizeof *s->pts))
        return -2;
    memcpy(s->pts[s->ev.n++], p, sizeof s->pts[0]);
    return 0;
}

/* Parses one line into s->ev. 1: an event, 0: blank or comment, -1: invalid, -2: no
 * storage for its points. */
static int parse_line(struct gks_in_script *s, char *line)
{
    char *p = line + strspn(line, " \t\r\n");
    if (*p == '\0' || *p == '#')
        return 0;
    char word[16];
    int used = 0;
    if (sscanf(p, "%15s%n", word, &used) != 1)
        return -1;
    p += used;
    s->ev = (gks_in_raw){ 0 };
    if (strcmp(word, "break") == 0) {
        char cw[16];
        int num = 0;
        if (sscanf(p, "%15s %d", cw, &num) != 2)
            return -1;
        for (size_t i = 0; i < sizeof script_words / sizeof script_words[0]; i++)
            if (strcmp(cw, script_words[i].word) == 0) {
                s->ev.cls = script_words[i].cls;
                s->ev.num = num;
                s->ev.brk = 1;
                return 1;
            }
        return -1;
    }
    size_t k = 0;
    while (k < sizeof script_words / sizeof script_words[0] && strcmp(word, script_words[k].word))
        k++;
    if (k == sizeof script_words / sizeof script_words[0])
        return -1;
    s->ev.cls = script_words[k].cls;
    int dim = script_words[k].dim;
    long num;
    char *end;
    num = strtol(p, &end, 10);
    if (end == p || num < 1 || num > 1000)
        return -1;
    s->ev.num = (int)num;
    p = end;
    switch (s->ev.cls) {
    case GIN_VAL:
        s->ev.val = strtod(p, &end);
        return end != p && isfinite(s->ev.val) ? 1 : -1;
    case GIN_CHOICE:
        num = strtol(p, &end, 10);
        if (end == p || num < 0 || num > 1000000)
            return -1;
        s->ev.choice = (int)num;
        return 1;
    case GIN_STRING: {
        if (*p == ' ' || *p == '\t')
            p++;
        size_t n = strcspn(p, "\r\n");
        if (n > GKS_IN_STRING_MAX)
            n = GKS_IN_STRING_MAX;
        memcpy(s->str, p, n);
        s->str[n] = '\0';
        s->ev.str = s->str;
        return 1;
    }
    default:
        break;
    }
    for (;;) {
        double c[3] = { 0, 0, 0 };
        int i;
        for (i = 0; i < dim; i++) {
            c[i] = strtod(p, &end);
            if (end == p)
                break;
            if (!isfinite(c[i]))
                return -1;
            p = end;
        }
        if (i == 0)
            break;
        if (i < dim)
            return -1;
        int e = add_point(s, c);
        if (e)
            return e;
        if (s->ev.cls != GIN_STROKE)
            break;
    }
    p += strspn(p, " \t\r\n");
    if (*p != '\0' || s->ev.n < 1)
        return -1;
    s->ev.pts = (const double (*)[3])s->pts;
    return 1;
}

/* Reads the rest of the current line into s->line (any length: a line is never split).
 * 1: a whole line (or the last, unended one), 0: end of file, -1: no storage (the part
 * read is kept, the next call goes on from there). */
static int read_line(struct gks_in_script *s)
{
    int c = 0;
    for (;;) {
        if (gks_grow(&s->line, &s->cap, s->len + 2, 1))
            return -1;
        if ((c = getc(s->fp)) == EOF)
            break;
        s->line[s->len++] = (char)c;
        if (c == '\n')
            break;
    }
    s->line[s->len] = '\0';
    return c == '\n' || s->len > 0 ? 1 : 0;
}

/* The next scripted event of ws, without consuming it (NULL: the script is exhausted, or
 * *err = 300: no storage; the line stays and is read again by the next call). Invalid lines
 * and lines for a device the workstation does not have are skipped with a note on standard
 * error, naming the file and line, so no mode ever waits behind them. */
static const gks_in_raw *script_peek(gks_ws *ws, int *err)
{
    struct gks_in_script *s = ws->in->script;
    if (!s || s->eof)
        return NULL;
    if (s->have)
        return &s->ev;
    for (;;) {
        if (!s->line_done) {
            int r = read_line(s);
            if (r < 0) {
                *err = 300;
                return NULL;
            }
            if (r == 0)
                break;
            s->line_done = 1;
            s->line_no++;
        }
        int r = parse_line(s, s->line);
        if (r == -2) {
            *err = 300;
            return NULL;
        }
        s->line_done = 0;
        s->len = 0;
        if (r > 0 && !gks_in_dev(ws, s->ev.cls, s->ev.num)) {
            fprintf(stderr, "gks3d: %s:%ld: input script line ignored: workstation %d has no "
                    "such device\n", s->path, s->line_no, ws->id);
            continue;
        }
        if (r > 0) {
            s->have = 1;
            return &s->ev;
        }
        if (r < 0)
            fprintf(stderr, "gks3d: %s:%ld: input script line ignored\n", s->path, s->line_no);
    }
    s->eof = 1;
    return NULL;
}

static void script_next(struct gks_in_script *s)
{
    s->have = 0;
}

/* ---- workstation input state lists ---- */

int gks_in_num_devices(const gks_in_desc *d, Gin_class cls)
{
    if (!d || cls < GIN_LOC || cls > GIN_STRING)
        return 0;
    return d->n_dev[cls - GIN_LOC];
}

gks_indev *gks_in_dev(gks_ws *ws, Gin_class cls, int num)
{
    if (!ws || !ws->in || num < 1 || num > gks_in_num_devices(ws->in->desc, cls))
        return NULL;
    return &ws->in->dev[cls - GIN_LOC][num - 1];
}

void gks_in_dev_default(const gks_ws_desc *d, Gin_class cls, gks_indev *dev)
{
    *dev = (gks_indev){ 0 };
    dev->mode = GOP_REQ;
    dev->echo = 1;
    dev->pet = 1;
    dev->echo_vol = (Glimit3){ 0, d->dc_x, 0, d->dc_y, 0, 1 };
    dev->init.status = GIN_STATUS_OK;
    dev->init.pos = (Gpoint3){ 0.5, 0.5, 0 };
    dev->low = 0;
    dev->high = 1;
    dev->init.val = 0.5;
    switch (cls) {
    case GIN_STROKE: dev->buf_size = 64; break;
    case GIN_CHOICE: dev->init.status = GIN_STATUS_NO_IN; dev->init.choice = 1; break;
    case GIN_PICK: dev->init.status = GIN_STATUS_NO_IN; break;
    case GIN_STRING: dev->buf_size = 80; dev->cur_pos = 1; break;
    default: break;
    }
}

static void dev_free(gks_indev *d)
{
    gks_in_rec_free(&d->rec);
    gks_in_val_free(&d->init);
    gks_in_val_free(&d->cur);
}

int gks_in_ws_open(gks_ws *ws, const gks_in_desc *desc)
{
    ws->in = NULL;
    if (!desc)
        return 0;
    gks_in_ws *in = gks_calloc_array(1, sizeof *in);
    if (!in)
        return 300;
    in->desc = desc;
    for (int c = 0; c < GKS_IN_NCLASS; c++) {
        if (desc->n_dev[c] == 0)
            continue;
        in->dev[c] = gks_calloc_array((size_t)desc->n_dev[c], sizeof *in->dev[c]);
        if (!in->dev[c]) {
            for (int k = 0; k < c; k++)
                gks_free(in->dev[k]);
            gks_free(in);
            return 300;
        }
        for (int i = 0; i < desc->n_dev[c]; i++) {
            gks_in_dev_default(ws->drv->desc, (Gin_class)(GIN_LOC + c), &in->dev[c][i]);
            in->dev[c][i].cur = in->dev[c][i].init;
        }
    }
    ws->in = in;
    /* Legacy programs cannot issue the ESCAPE: the environment names their script. It
     * goes to the first input workstation opened while no other has it. */
    gks_context *ctx = gks_ctx();
    const char *env = getenv("GKS_INPUT_SCRIPT");
    int taken = 0;
    for (int i = 0; i < ctx->sl->n_open; i++)
        taken |= ctx->ws[i]->in && ctx->ws[i]->in->script;
    if (env && *env && !taken && gks_in_script_attach(ws, env, strlen(env)))
        fprintf(stderr, "gks3d: GKS_INPUT_SCRIPT %s cannot be read\n", env);
    return 0;
}

void gks_in_ws_close(gks_ws *ws)
{
    gks_in_ws *in = ws->in;
    if (!in)
        return;
    remove_events(ws->id, GIN_NONE, 0);
    struct gks_in_queue *q = gks_ctx()->sl->inq;
    if (q && q->cur.ws_id == ws->id && q->cur.cls != GIN_NONE) {
        gks_in_val_free(&q->cur.v);
        q->cur = (in_event){ 0 };
    }
    if (q && q->ovf == 1 && q->ovf_ws == ws->id)
        q->ovf = 2;
    for (int c = 0; c < GKS_IN_NCLASS; c++) {
        for (int i = 0; in->dev[c] && i < in->desc->n_dev[c]; i++)
            dev_free(&in->dev[c][i]);
        gks_free(in->dev[c]);
    }
    script_free(in->script);
    gks_free(in);
    ws->in = NULL;
}

int gks_in_set_mode(gks_ws *ws, Gin_class cls, int num, Gop_mode mode, int echo)
{
    gks_indev *d = gks_in_dev(ws, cls, num);
    gks_in_val v = { 0 };
    if (mode != GOP_REQ && gks_in_val_copy(&v, &d->init))
        return 300;
    gks_in_val_free(&d->cur);
    d->cur = v;
    if (cls == GIN_CHOICE || cls == GIN_PICK)
        d->cur.status = d->init.status;
    d->mode = mode;
    d->echo = echo;
    return 0;
}

/* ---- the measure process: device coordinates -> logical values ---- */

static int dc_to_npc(const gks_ws *ws, const double dc[3], double npc[3])
{
    double m[4][4], inv[4][4];
    if (gks_ws_tran_matrix(ws, m) || gks_xform_invert((const double (*)[4])m, inv))
        return -1;
    gks_xform_point((const double (*)[4])inv, dc, npc);
    /* A 2-D display space has no depth: z comes back as the window's front. */
    if (ws->cur_win.z_min == ws->cur_win.z_max)
        npc[2] = ws->cur_win.z_min;
    return 0;
}

static int inside3(const double p[3], const Glimit3 *l)
{
    const double e = 1e-9;
    return p[0] >= l->x_min - e && p[0] <= l->x_max + e && p[1] >= l->y_min - e &&
           p[1] <= l->y_max + e && p[2] >= l->z_min - e && p[2] <= l->z_max + e;
}

static void view_matrix(const Gview_rep3 *v, double m[4][4])
{
    double a[4][4], b[4][4];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            a[i][j] = v->map_matrix[i][j];
            b[i][j] = v->ori_matrix[i][j];
        }
    gks_xform_multiply((const double (*)[4])a, (const double (*)[4])b, m);
}

/* WC3 of an NDC3 point under transformation t (axis by axis; a zero-extent axis of the
 * viewport maps to the window's minimum). */
static Gpoint3 ndc_to_wc(const gks_norm_tran *t, const double p[3])
{
    const Gfloat w[6] = { t->win.x_min, t->win.x_max, t->win.y_min, t->win.y_max,
                          t->win.z_min, t->win.z_max };
    const Gfloat v[6] = { t->vp.x_min, t->vp.x_max, t->vp.y_min, t->vp.y_max,
                          t->vp.z_min, t->vp.z_max };
    double r[3];
    for (int i = 0; i < 3; i++) {
        double dv = v[2 * i + 1] - v[2 * i];
        r[i] = dv != 0 ? w[2 * i] + (p[i] - v[2 * i]) * (w[2 * i + 1] - w[2 * i]) / dv
                       : w[2 * i];
    }
    return (Gpoint3){ r[0], r[1], r[2] };
}

/* Points (DC3) back to WC3: the highest-priority view whose clip limits contain every
 * point (view transformation input priority), then the highest-priority normalization
 * transformation whose viewport contains them all (viewport input priority). Returns 0,
 * or -1 when no view or transformation takes them (outside the workstation viewport). */
static int dc_to_wc(const gks_ws *ws, int n, const double (*dc)[3], Gpoint3 *out, int *tnr,
                    int *view_ind)
{
    double (*ndc)[3] = gks_alloc_array((size_t)n, sizeof *ndc);
    if (!ndc)
        return -2;
    int vi = -1;
    for (int k = 0; k <= GKS_MAX_VIEW_IND && vi < 0; k++) {
        int v = ws->view_pri[k];
        double m[4][4], inv[4][4];
        view_matrix(&ws->views[v], m);
        if (gks_xform_invert((const double (*)[4])m, inv))
            continue;
        int all = 1;
        for (int i = 0; i < n && all; i++) {
            double npc[3];
            if (dc_to_npc(ws, dc[i], npc)) {
                all = 0;
                break;
            }
            all = inside3(npc, &ws->views[v].clip_limit);
            if (all)
                gks_xform_point((const double (*)[4])inv, npc, ndc[i]);
        }
        if (all)
            vi = v;
    }
    int ti = -1;
    const gks_state_list *sl = gks_ctx()->sl;
    for (int k = 0; k <= GKS_MAX_NORM_TRAN && vi >= 0 && ti < 0; k++) {
        int t = sl->tran_pri[k], all = 1;
        for (int i = 0; i < n && all; i++)
            all = inside3(ndc[i], &sl->tran[t].vp);
        if (all)
            ti = t;
    }
    if (ti >= 0)
        for (int i = 0; i < n; i++)
            out[i] = ndc_to_wc(&sl->tran[ti], ndc[i]);
    gks_free(ndc);
    if (ti < 0)
        return -1;
    *tnr = ti;
    *view_ind = vi;
    return 0;
}

/* Distance from q to the segment a-b in the xy plane. */
static double seg_dist(const double a[2], const double b[2], const double q[2])
{
    double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double ex = a[0] + t * dx - q[0], ey = a[1] + t * dy - q[1];
    return sqrt(ex * ex + ey * ey);
}

/* Does primitive p of segment s, as ws shows it (segment transformation, view), pass
 * within the aperture of the NPC point q? Areas: q inside (even-odd over all loops) or
 * near an edge; lines: near a segment; markers and text: near a point. */
/* Primitive p of segment s as ws shows it, in NPC: its points (NDC3 through the segment
 * transformation and the primitive's view; a cell array's four corners; a text's
 * position), allocated, n of them in *n (NULL: none or no storage). */
static double (*prim_npc(const gks_ws *ws, const gks_segment *s, const gks_seg_prim *p,
                         int *n))[3]
{
    int vi = p->bound->attrs.view_ind;
    if (vi < 0 || vi > GKS_MAX_VIEW_IND)
        vi = 0;
    double vm[4][4], seg4[4][4], m[4][4];
    view_matrix(&ws->views[vi], vm);
    gks_xform_mat34_to_mat4((const double (*)[4])s->tran, seg4);
    gks_xform_multiply((const double (*)[4])vm, (const double (*)[4])seg4, m);
    int npts = p->n_points;
    const Gpoint3 *src = p->pts;
    Gpoint3 one[4];
    if (p->kind == GKS_SEG_CELL_ARRAY) {
        Gpoint3 pp = p->cell_p, qq = p->cell_q, rr = p->cell_r;
        one[0] = pp;
        one[1] = rr;
        one[2] = qq;
        one[3] = (Gpoint3){ pp.x + qq.x - rr.x, pp.y + qq.y - rr.y, pp.z + qq.z - rr.z };
        src = one;
        npts = 4;
    } else if (p->kind == GKS_SEG_TEXT) {
        if (npts < 1 || !p->pts)
            return NULL;
        /* pts[0] is in WC3: map it by the bound normalization */
        double w[3] = { p->pts[0].x, p->pts[0].y, p->pts[0].z }, n3[3];
        gks_xform_mat34_point((const double (*)[4])p->bound->norm, w, n3);
        one[0] = (Gpoint3){ n3[0], n3[1], n3[2] };
        src = one;
        npts = 1;
    }
    *n = 0;
    if (npts <= 0 || !src)
        return NULL;
    double (*xy)[3] = gks_alloc_array((size_t)npts, sizeof *xy);
    if (!xy)
        return NULL;
    for (int i = 0; i < npts; i++) {
        double a[3] = { src[i].x, src[i].y, src[i].z };
        gks_xform_point((const double (*)[4])m, a, xy[i]);
    }
    *n = npts;
    return xy;
}

static int prim_hit(const gks_ws *ws, const gks_segment *s, const gks_seg_prim *p,
                    const double q[2])
{
    int npts;
    double (*xy)[3] = prim_npc(ws, s, p, &npts);
    if (!xy)
        return 0;
    if (p->kind == GKS_SEG_TEXT) {
        /* Text: anywhere within a character height of its position. */
        double r = p->bound->attrs.char_ht > PICK_APERTURE ? p->bound->attrs.char_ht
                                                             : PICK_APERTURE;
        int hit = fabs(xy[0][0] - q[0]) <= r * 4 && fabs(xy[0][1] - q[1]) <= r;
        gks_free(xy);
        return hit;
    }
    int hit = 0;
    if (p->kind == GKS_SEG_POLYMARKER) {
        for (int i = 0; i < npts && !hit; i++)
            hit = fabs(xy[i][0] - q[0]) <= PICK_APERTURE && fabs(xy[i][1] - q[1]) <= PICK_APERTURE;
    } else if (p->kind == GKS_SEG_POLYLINE) {
        for (int i = 0; i + 1 < npts && !hit; i++)
            hit = seg_dist(xy[i], xy[i + 1], q) <= PICK_APERTURE;
        if (npts == 1)
            hit = seg_dist(xy[0], xy[0], q) <= PICK_APERTURE;
    } else { /* areas: loops */
        int nl = p->kind == GKS_SEG_CELL_ARRAY ? 1 : p->n_loops;
        int inside = 0, at = 0;
        for (int l = 0; l < nl; l++) {
            int c = p->kind == GKS_SEG_CELL_ARRAY || !p->loop_counts ? npts : p->loop_counts[l];
            for (int i = 0, j = c - 1; i < c; j = i++) {
                const double *a = xy[at + i], *b = xy[at + j];
                if ((a[1] > q[1]) != (b[1] > q[1]) &&
                    q[0] < (b[0] - a[0]) * (q[1] - a[1]) / (b[1] - a[1]) + a[0])
                    inside = !inside;
                if (seg_dist(a, b, q) <= PICK_APERTURE)
                    hit = 1;
            }
            at += c;
        }
        hit |= inside;
    }
    gks_free(xy);
    return hit;
}

/* Pick correlation: the visible, detectable segment on ws of highest priority (for
 * equal priority the one created last, which is drawn on top) with a primitive hit at
 * the DC position; within it the last primitive drawn that is hit gives the pick id. */
static int pick_at(const gks_ws *ws, const double dc[3], Gpick *out)
{
    double npc[3];
    const gks_seg_store *st = gks_ctx()->sl->segs;
    if (dc_to_npc(ws, dc, npc) || !st || st->n == 0)
        return 0;
    gks_segment **order = gks_alloc_array(st->n, sizeof *order);
    if (!order)
        return 0;
    size_t n = gks_seg_draw_order(st, ws->id, order);
    int found = 0;
    for (size_t k = n; k-- > 0 && !found;) {
        const gks_segment *s = order[k];
        if (!s->vis || !s->det)
            continue;
        for (size_t i = gks_seg_count(s); i-- > 0;) {
            gks_seg_prim p;
            gks_seg_get(s, i, &p);
            if (prim_hit(ws, s, &p, npc)) {
                *out = (Gpick){ s->name, p.bound->attrs.pick_id };
                found = 1;
                break;
            }
        }
    }
    gks_free(order);
    return found;
}

/* gks_in_active.pick_at */
static int seg_pick_at(const gks_ws *ws, const double dc[3], Gpick *out)
{
    return ws && out ? pick_at(ws, dc, out) : 0;
}

/* gks_in_active.seg_outline */
static int seg_outline(const gks_ws *ws, Gint seg, Gint pick_id, gks_in_outline_fn fn,
                       void *user)
{
    const gks_seg_store *st = gks_ctx()->sl->segs;
    double m[4][4];
    if (!ws || !fn || !st || gks_ws_tran_matrix(ws, m))
        return 0;
    const gks_segment *s = gks_seg_find(st, seg);
    if (!s || !s->vis || !gks_seg_on_ws(s, ws->id))
        return 0;
    int drawn = 0;
    for (size_t i = 0; i < gks_seg_count(s); i++) {
        gks_seg_prim p;
        gks_seg_get(s, i, &p);
        if (pick_id >= 0 && p.bound->attrs.pick_id != pick_id)
            continue;
        int n;
        double (*xy)[3] = prim_npc(ws, s, &p, &n);
        if (!xy)
            continue;
        for (int j = 0; j < n; j++) {
            double dc[3];
            gks_xform_point((const double (*)[4])m, xy[j], dc);
            xy[j][0] = dc[0];
            xy[j][1] = dc[1];
            xy[j][2] = dc[2];
        }
        gks_in_outline_kind kind = p.kind == GKS_SEG_POLYLINE     ? GKS_IN_OUTLINE_LINE
                                   : p.kind == GKS_SEG_POLYMARKER ? GKS_IN_OUTLINE_POINTS
                                   : p.kind == GKS_SEG_TEXT       ? GKS_IN_OUTLINE_POINTS
                                                                  : GKS_IN_OUTLINE_AREA;
        if (kind == GKS_IN_OUTLINE_AREA && p.kind != GKS_SEG_CELL_ARRAY && p.loop_counts &&
            p.n_loops > 0) {
            int at = 0;
            for (int l = 0; l < p.n_loops && at + p.loop_counts[l] <= n; l++) {
                fn(user, kind, p.loop_counts[l], (const double (*)[3])(xy + at));
                at += p.loop_counts[l];
            }
        } else {
            fn(user, kind, n, (const double (*)[3])xy);
        }
        drawn++;
        gks_free(xy);
    }
    return drawn;
}

/* The logical value of raw event r for device d. Returns 1 (a value), 0 (the event
 * carries no valid value for the device: ignored) or -1 (storage). */
static int measure(gks_ws *ws, const gks_indev *d, const gks_in_raw *r, gks_in_val *v)
{
    *v = (gks_in_val){ 0 };
    v->status = GIN_STATUS_OK;
    if (r->brk) {
        v->status = GIN_STATUS_NONE;
        return 1;
    }
    switch (r->cls) {
    case GIN_LOC:
    case GIN_STROKE: {
        int n = r->cls == GIN_LOC ? 1 : r->n;
        if (n < 1 || !r->pts)
            return 0;
        if (n > d->buf_size && r->cls == GIN_STROKE)
            n = d->buf_size;
        Gpoint3 *w = gks_alloc_array((size_t)(n > 0 ? n : 1), sizeof *w);
        if (!w)
            return -1;
        int e = n > 0 ? dc_to_wc(ws, n, r->pts, w, &v->tnr, &v->view_ind) : 0;
        if (e) {
            gks_free(w);
            return e == -2 ? -1 : 0;
        }
        if (r->cls == GIN_LOC) {
            v->pos = w[0];
            gks_free(w);
        } else {
            v->n = n;
            v->pts = w;
        }
        return 1;
    }
    case GIN_VAL:
        v->val = r->val < d->low ? d->low : r->val > d->high ? d->high : r->val;
        return 1;
    case GIN_CHOICE:
        v->choice = r->choice;
        if (r->choice < 1 || r->choice > ws->in->desc->max_choices)
            v->status = GIN_STATUS_NO_IN;
        return 1;
    case GIN_PICK:
        if (r->n < 1 || !r->pts || !pick_at(ws, r->pts[0], &v->pick))
            v->status = GIN_STATUS_NO_IN;
        return 1;
    case GIN_STRING: {
        size_t n = r->str ? strlen(r->str) : 0;
        if (n > (size_t)d->buf_size)
            n = (size_t)d->buf_size;
        if (!(v->str = gks_strndup(r->str ? r->str : "", n)))
            return -1;
        return 1;
    }
    default:
        return 0;
    }
}

/* The devices of ws taking input now (for a driver's echo and mapping). */
static void active_list(gks_ws *ws, Gin_class rcls, int rnum, gks_in_active *a)
{
    a->n = 0;
    a->request = -1;
    a->pick_at = seg_pick_at;
    a->seg_outline = seg_outline;
    double m[4][4];
    int have_m = gks_ws_tran_matrix(ws, m) == 0;
    for (int c = 0; c < GKS_IN_NCLASS; c++)
        for (int i = 0; i < ws->in->desc->n_dev[c] && a->n < GKS_IN_MAX_ACTIVE; i++) {
            const gks_indev *d = &ws->in->dev[c][i];
            Gin_class cls = (Gin_class)(GIN_LOC + c);
            int req = cls == rcls && i + 1 == rnum;
            if (d->mode == GOP_REQ && !req)
                continue;
            if (req)
                a->request = a->n;
            gks_in_active_dev *x = &a->dev[a->n++];
            *x = (gks_in_active_dev){ cls, i + 1, d->mode, d->echo, d->pet, d->echo_vol,
                                      { 0, 0, 0 }, d->init.val, d->low, d->high,
                                      ws->in->desc->max_choices, d->buf_size, d->rec };
            if (have_m && (cls == GIN_LOC || cls == GIN_STROKE)) {
                /* The initial position's NDC3 by its transformation, then NPC (view
                 * 0 if the view is gone) and DC. */
                const gks_norm_tran *t = &gks_ctx()->sl->tran[d->init.tnr];
                double w[6], v6[6], nm[3][4], ndc[3], npc[3], vm[4][4];
                gks_limit3_array(&t->win, w);
                gks_limit3_array(&t->vp, v6);
                const Gpoint3 *p0 = cls == GIN_LOC || !d->init.pts ? &d->init.pos : d->init.pts;
                double wc[3] = { p0->x, p0->y, p0->z };
                if (gks_xform_norm_tran3(w, v6, nm) == 0) {
                    gks_xform_mat34_point((const double (*)[4])nm, wc, ndc);
                    view_matrix(&ws->views[d->init.view_ind], vm);
                    gks_xform_point((const double (*)[4])vm, ndc, npc);
                    gks_xform_point((const double (*)[4])m, npc, x->init_dc);
                }
            }
        }
}

/* The next raw event of ws: the script first; else the driver's interactive devices,
 * waiting at most timeout seconds. 1 event, 0 none within timeout, -1 no source, -2 no
 * storage to read the script. */
static int next_raw(gks_ws *ws, Gin_class rcls, int rnum, double timeout, gks_in_raw *r,
                    int *scripted)
{
    int err = 0;
    const gks_in_raw *s = script_peek(ws, &err);
    *scripted = s != NULL;
    if (s) {
        *r = *s;
        return 1;
    }
    if (err)
        return -2;
    if (!ws->drv->input)
        return -1;
    gks_in_active a;
    active_list(ws, rcls, rnum, &a);
    return ws->drv->input(ws, &a, timeout, r);
}

/* Delivers raw event r to its device (EVENT: queue; SAMPLE: measure; REQUEST: *req if
 * the REQUEST waits for it). Returns 1 if it satisfied the REQUEST, 0 otherwise, -1 on
 * storage overflow. */
static int deliver(gks_ws *ws, const gks_in_raw *r, Gin_class rcls, int rnum, gks_in_val *req)
{
    gks_indev *d = gks_in_dev(ws, r->cls, r->num);
    if (!d)
        return 0;
    int is_req = r->cls == rcls && r->num == rnum && d->mode == GOP_REQ;
    if (d->mode == GOP_REQ && !is_req)
        return 0;
    if (d->mode == GOP_SAMPLE && r->brk)
        return 0;
    gks_in_val v;
    int m = measure(ws, d, r, &v);
    if (m <= 0)
        return m;
    if (is_req) {
        gks_in_val_free(req);
        *req = v;
        return 1;
    }
    if (d->mode == GOP_SAMPLE) {
        gks_in_val_free(&d->cur);
        d->cur = v;
    } else if (!r->brk) {
        enqueue(ws, r->cls, r->num, &v);
    } else {
        gks_in_val_free(&v);
    }
    return 0;
}

/* Is the device of r taking input other than by REQUEST (SAMPLE or EVENT mode)? */
static int sampled_or_event(gks_ws *ws, const gks_in_raw *r)
{
    gks_indev *d = gks_in_dev(ws, r->cls, r->num);
    return d && d->mode != GOP_REQ;
}

static double now_s(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int gks_in_request(gks_ws *ws, Gin_class cls, int num, gks_in_val *out)
{
    *out = (gks_in_val){ 0 };
    out->status = GIN_STATUS_NONE;
    for (;;) {
        gks_in_raw r;
        int scripted;
        int k = next_raw(ws, cls, num, 0.1, &r, &scripted);
        if (k == -2)
            return 300;
        if (k < 0)
            return 0; /* no event can come: status NONE */
        if (k == 0)
            continue; /* an interactive device: the operator has not acted yet */
        int d = deliver(ws, &r, cls, num, out);
        if (d < 0)
            return 300; /* a script line stays: the next call reads it again */
        if (scripted)
            script_next(ws->in->script);
        if (d > 0)
            return 0;
    }
}

int gks_in_sample(gks_ws *ws, Gin_class cls, int num, gks_in_val *out)
{
    gks_in_raw r;
    int scripted, err = 0;
    const gks_in_raw *s = script_peek(ws, &err);
    if (err)
        return 300;
    if (s && sampled_or_event(ws, s)) {
        if (deliver(ws, s, GIN_NONE, 0, NULL) < 0)
            return 300;
        script_next(ws->in->script);
    } else if (!s && ws->drv->input) {
        while (next_raw(ws, GIN_NONE, 0, 0, &r, &scripted) > 0)
            if (deliver(ws, &r, GIN_NONE, 0, NULL) < 0)
                return 300;
    }
    *out = (gks_in_val){ 0 };
    return gks_in_val_copy(out, &gks_in_dev(ws, cls, num)->cur);
}

/* Lets every input workstation's sources deliver what they have now (scripts: until a
 * line for a device in REQUEST mode, or one event queued). 1 if an event was queued. */
static int pump_now(int *err)
{
    gks_context *c = gks_ctx();
    struct gks_in_queue *q = queue();
    for (int i = 0; q && i < c->sl->n_open; i++) {
        gks_ws *ws = c->ws[i];
        if (!ws->in)
            continue;
        const gks_in_raw *s;
        while ((s = script_peek(ws, err)) && sampled_or_event(ws, s)) {
            int before = q->n;
            if (deliver(ws, s, GIN_NONE, 0, NULL) < 0) {
                *err = 300; /* the line stays for the next call */
                return 0;
            }
            script_next(ws->in->script);
            if (q->n > before || q->blocked)
                return 1;
        }
        if (*err)
            return 0;
        if (!s && ws->drv->input) {
            gks_in_raw r;
            int scripted;
            while (next_raw(ws, GIN_NONE, 0, 0, &r, &scripted) > 0)
                if (deliver(ws, &r, GIN_NONE, 0, NULL) < 0)
                    *err = 300;
        }
    }
    return q && q->n > 0;
}

static void sleep_s(double s)
{
    struct timespec ts = { (time_t)s, (long)((s - floor(s)) * 1e9) };
    while (nanosleep(&ts, &ts) && errno == EINTR)
        ;
}

/* Waits up to `left` seconds for any interactive device (or sleeps when there is none). */
static void wait_some(double left, int *err)
{
    gks_context *c = gks_ctx();
    int nint = 0;
    for (int i = 0; i < c->sl->n_open; i++)
        nint += c->ws[i]->in && c->ws[i]->drv->input && !script_peek(c->ws[i], err);
    /* Each wait is at most GKS_IN_WAIT_MAX seconds (the caller waits again until its
     * timeout has passed): any finite timeout fits time_t and the driver's timers. */
    if (left > GKS_IN_WAIT_MAX)
        left = GKS_IN_WAIT_MAX;
    if (nint == 0) {
        sleep_s(left);
        return;
    }
    double slice = nint > 1 && left > 0.01 ? 0.01 : left;
    for (int i = 0; i < c->sl->n_open; i++) {
        gks_ws *ws = c->ws[i];
        if (!ws->in || !ws->drv->input || script_peek(ws, err))
            continue;
        gks_in_raw r;
        int scripted;
        int k = next_raw(ws, GIN_NONE, 0, slice, &r, &scripted);
        if (k > 0 && deliver(ws, &r, GIN_NONE, 0, NULL) < 0)
            *err = 300;
        else if (k == -1) /* its devices are gone (a closed window): no busy loop */
            sleep_s(slice);
        return;
    }
}

int gks_in_await(double timeout, Gint *ws_id, Gin_class *cls, Gint *num)
{
    *ws_id = 0;
    *cls = GIN_NONE;
    *num = 0;
    struct gks_in_queue *q = queue();
    if (!q)
        return 300;
    int err = 0;
    double end = now_s() + timeout;
    if (q->n == 0)
        pump_now(&err);
    for (;;) {
        if (q->n > 0 || err)
            break;
        double left = end - now_s();
        if (left <= 0)
            break;
        wait_some(left, &err);
        pump_now(&err);
    }
    in_event e;
    if (dequeue(q, &e)) {
        set_current(q, &e);
        *ws_id = q->cur.ws_id;
        *cls = q->cur.cls;
        *num = q->cur.num;
    } else {
        gks_in_val_free(&q->cur.v);
        q->cur = (in_event){ 0 };
    }
    if (q->report_147) {
        q->report_147 = 0;
        return 147;
    }
    return err;
}

const gks_in_val *gks_in_current(Gin_class cls, int *buf_size)
{
    struct gks_in_queue *q = gks_ctx()->sl->inq;
    if (!q || q->cur.cls != cls || cls == GIN_NONE)
        return NULL;
    const gks_indev *d = gks_in_dev(gks_ws_lookup(q->cur.ws_id), cls, q->cur.num);
    *buf_size = d ? d->buf_size : 0;
    return &q->cur.v;
}

void gks_in_flush(int ws_id, Gin_class cls, int num)
{
    remove_events(ws_id, cls, num);
}

int gks_in_overflow(Gint *ws_id, Gin_class *cls, Gint *num)
{
    struct gks_in_queue *q = gks_ctx()->sl->inq;
    if (!q || q->ovf == 0)
        return 148;
    int r = q->ovf == 2 ? 149 : 0;
    if (!r) {
        *ws_id = q->ovf_ws;
        *cls = q->ovf_cls;
        *num = q->ovf_num;
    }
    q->ovf = 0;
    return r;
}

int gks_in_more_simult(void)
{
    return 0; /* every trigger of this implementation belongs to one device */
}
