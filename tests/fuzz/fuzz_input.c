/* SPDX-License-Identifier: MIT */
/*
 * fuzz_input.c -- fuzz target for input scripts (untrusted input, docs/INPUT.md): the bytes
 * are an input script, written to a scratch file in $TMPDIR or /tmp (a script must be a
 * regular file) and attached by ESCAPE -130 to a PNG workstation (16 x 16 pixels, its
 * file beside the script) that
 * shows a detectable segment, so PICK correlates. Device 1 of every class waits in REQUEST
 * mode with small buffers (a stroke of 8 points, a string of 16 characters); device 2 of
 * every class is in EVENT mode, or in SAMPLE mode when the input's length is odd. Each
 * round REQUESTs every class, SAMPLEs or AWAITs events (then GETs the value of the class
 * reported), into buffers of exactly the documented size on the heap, so that AddressSan
 * sees any write past them; every 8th round INITIALISE STRING makes the buffer smaller
 * (issue 40 B). The rounds end when the script is exhausted (every REQUEST returns NONE),
 * or after 64. Errors are expected; crashes, sanitizer reports, hangs and unbounded
 * allocation are bugs. libFuzzer entry point (scripts/fuzz.sh), replayed over
 * tests/fuzz/corpus_input by the ctest `fuzz_input_replay` (fuzz_replay.c) in every build.
 */
#define _GNU_SOURCE
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <gks.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static long n_values; /* values returned with status OK over all inputs */

#ifdef FUZZ_INPUT_REPLAY
/* The replay test fails when the whole corpus returned no value: the target would then
 * test nothing (as when the script was refused). */
__attribute__((destructor)) static void report_values(void)
{
    printf("fuzz_input: %ld values\n", n_values);
}
#endif

static void ignore_errors(Gint err, Gint fct, const char *file)
{
    (void)err;
    (void)fct;
    (void)file;
}

enum { WS = 1, STROKE_BUF = 8, STRING_BUF = 16 };
static const Glimit earea = { 0, 16, 0, 16 };

static void set_mode(Gin_class c, Gint dev, Gop_mode m)
{
    switch (c) {
    case GIN_LOC: gset_loc_mode(WS, dev, m, GSWITCH_ECHO); break;
    case GIN_STROKE: gset_stroke_mode(WS, dev, m, GSWITCH_ECHO); break;
    case GIN_VAL: gset_val_mode(WS, dev, m, GSWITCH_ECHO); break;
    case GIN_CHOICE: gset_choice_mode(WS, dev, m, GSWITCH_ECHO); break;
    case GIN_PICK: gset_pick_mode(WS, dev, m, GSWITCH_ECHO); break;
    default: gset_string_mode(WS, dev, m, GSWITCH_ECHO); break;
    }
}

/* A string buffer of exactly n + 1 bytes on the heap. */
static char *strbuf(Gint n)
{
    return malloc((size_t)n + 1);
}

/* The value of class c of the current event report (GET). */
static void get(Gin_class c, Gint str_buf)
{
    Gin_status st = GIN_STATUS_NONE;
    Gloc loc;
    Gpoint pts[STROKE_BUF];
    Gstroke s = { 0, STROKE_BUF, pts };
    Gfloat v;
    Gint ch;
    Gpick pk;
    char *str;
    switch (c) {
    case GIN_LOC: gget_loc(&loc); break;
    case GIN_STROKE: gget_stroke(&s); break;
    case GIN_VAL: gget_val(&v); break;
    case GIN_CHOICE: gget_choice(&st, &ch); break;
    case GIN_PICK: gget_pick(&st, &pk); break;
    case GIN_STRING:
        if ((str = strbuf(str_buf))) {
            gget_string(str);
            free(str);
        }
        break;
    default: break;
    }
}

/* REQUEST of device 1 of class c: 1 if a value came (status OK). */
static int request(Gin_class c, Gint str_buf)
{
    Gin_status st = GIN_STATUS_NONE;
    Gloc loc;
    Gpoint pts[STROKE_BUF];
    Gstroke s = { 0, STROKE_BUF, pts };
    Gfloat v;
    Gint ch;
    Gpick pk;
    char *str;
    switch (c) {
    case GIN_LOC: greq_loc(WS, 1, &st, &loc); break;
    case GIN_STROKE: greq_stroke(WS, 1, &st, &s); break;
    case GIN_VAL: greq_val(WS, 1, &st, &v); break;
    case GIN_CHOICE: greq_choice(WS, 1, &st, &ch); break;
    case GIN_PICK: greq_pick(WS, 1, &st, &pk); break;
    default:
        if ((str = strbuf(str_buf))) {
            greq_string(WS, 1, &st, str);
            free(str);
        }
        break;
    }
    return st == GIN_STATUS_OK;
}

/* SAMPLE of device 2 of class c. */
static void sample(Gin_class c, Gint str_buf)
{
    Gin_status st;
    Gloc loc;
    Gpoint pts[STROKE_BUF];
    Gstroke s = { 0, STROKE_BUF, pts };
    Gfloat v;
    Gint ch;
    Gpick pk;
    char *str;
    switch (c) {
    case GIN_LOC: gsample_loc(WS, 2, &loc); break;
    case GIN_STROKE: gsample_stroke(WS, 2, &s); break;
    case GIN_VAL: gsample_val(WS, 2, &v); break;
    case GIN_CHOICE: gsample_choice(WS, 2, &st, &ch); break;
    case GIN_PICK: gsample_pick(WS, 2, &st, &pk); break;
    default:
        if ((str = strbuf(str_buf))) {
            gsample_string(WS, 2, str);
            free(str);
        }
        break;
    }
}

static void init_devices(Gint str_buf)
{
    Gloc l = { 0, { 0.5, 0.5 } };
    Gpoint p0 = { 0.5, 0.5 };
    Gstroke s = { 0, 1, &p0 };
    Gpick pk = { 1, 1 };
    for (Gint dev = 1; dev <= 2; dev++) {
        ginit_loc(WS, dev, &l, 1, &earea, NULL);
        ginit_stroke(WS, dev, &s, 1, &earea, STROKE_BUF, NULL);
        ginit_val(WS, dev, 0.5, 1, &earea, 0, 1, NULL);
        ginit_choice(WS, dev, GIN_STATUS_OK, 1, 1, &earea, NULL);
        ginit_pick(WS, dev, GIN_STATUS_NO_IN, &pk, 1, &earea, NULL);
        ginit_string(WS, dev, "", 1, &earea, str_buf, 1, NULL);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char name[512], png[512];
    if (!name[0]) {
        const char *dir = getenv("TMPDIR");
        snprintf(name, sizeof name, "%s/fuzz_input.%ld.txt", dir && *dir ? dir : "/tmp",
                 (long)getpid());
        snprintf(png, sizeof png, "%s/fuzz_input.%ld.png", dir && *dir ? dir : "/tmp",
                 (long)getpid());
    }
    FILE *f = fopen(name, "wb");
    if (!f)
        return 0;
    size_t done = size ? fwrite(data, 1, size, f) : 0;
    if (fclose(f) != 0 || done != size) {
        remove(name);
        return 0;
    }
    gset_err_hand(ignore_errors, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(WS, png, GWS_TYPE_PNG);
    gset_ws_vp(WS, &earea);
    gactivate_ws(WS);
    Gpoint sq[4] = { { 0.25, 0.25 }, { 0.75, 0.25 }, { 0.75, 0.75 }, { 0.25, 0.75 } };
    gcreate_seg(1);
    gset_pick_id(3);
    gfill_area(&(Gpoint_list){ 4, sq });
    gclose_seg();
    gset_det(1, GSEG_DET);
    Gint str_buf = STRING_BUF;
    init_devices(str_buf);
    Gop_mode mode2 = size % 2 ? GOP_SAMPLE : GOP_EVENT;
    for (int c = GIN_LOC; c <= GIN_STRING; c++)
        set_mode((Gin_class)c, 2, mode2);
    Gint id = WS;
    Gescape_in_data in = { { 1, &id, 0, NULL, strlen(name), name } };
    gescape(GESC_INPUT_SCRIPT, &in, NULL, NULL);
    for (int round = 0; round < 64; round++) {
        int got = 0;
        for (int c = GIN_LOC; c <= GIN_STRING; c++)
            got += request((Gin_class)c, str_buf);
        if (mode2 == GOP_SAMPLE) {
            for (int c = GIN_LOC; c <= GIN_STRING; c++)
                sample((Gin_class)c, str_buf);
        } else {
            for (int k = 0; k < 4; k++) {
                Gint ws, num;
                Gin_class cls = GIN_NONE;
                gawait_event(0, &ws, &cls, &num);
                if (cls == GIN_NONE)
                    break;
                got++;
                get(cls, str_buf);
            }
        }
        n_values += got;
        if (round % 8 == 7) { /* a smaller string buffer for queued and later strings */
            str_buf = str_buf > 2 ? str_buf / 2 : STRING_BUF;
            gset_string_mode(WS, 2, GOP_REQ, GSWITCH_ECHO);
            ginit_string(WS, 2, "", 1, &earea, str_buf, 1, NULL);
            ginit_string(WS, 1, "", 1, &earea, str_buf, 1, NULL);
            gset_string_mode(WS, 2, mode2, GSWITCH_ECHO);
        }
        if (!got)
            break; /* the script is exhausted (or only invalid lines are left) */
    }
    gemergency_close_gks();
    remove(name);
    remove(png);
    return 0;
}
