/* SPDX-License-Identifier: MIT */
/*
 * gks_indev.h -- the core's logical input devices (ISO 7942 4.8, ISO 8805 4.8): the input
 * device state lists of a workstation, the input queue and current event report, the
 * measure process that turns a raw device event (device coordinates, as a driver or an
 * input script delivers it) into a logical input value (locator/stroke through the view
 * and normalization transformations by input priority, pick by correlation with the
 * detectable segments), and the scripted input source (docs/INPUT.md).
 *
 * The core decides: which device is waiting, what a raw event means, where it goes
 * (REQUEST, the sampled measure, the queue). A driver only delivers raw events of its
 * physical devices (gks_ws_driver.input) and draws echoes it is told about.
 */
#ifndef GKS_INDEV_H
#define GKS_INDEV_H
#ifndef GKS3D_BUILDING
#error "internal gks3d header: applications include <gks.h> only"
#endif
#include "gks.h"
#include <stddef.h>

#define GKS_IN_NCLASS 6          /* LOCATOR .. STRING */
#define GKS_IN_QUEUE_MAX GKS_IN_QUEUE_CAPACITY /* input queue capacity (events), gks.h */
#define GKS_IN_STROKE_MAX 1024   /* largest stroke buffer of any device (points) */
#define GKS_IN_STRING_MAX 1024   /* largest string buffer of any device (characters) */
#define GKS_IN_MAX_ACTIVE 32

/* Input facilities of a workstation type (part of its description table): devices per
 * class (index cls - GIN_LOC) and the supported prompt/echo types 1..max_pet[cls]. */
typedef struct gks_in_desc {
    int n_dev[GKS_IN_NCLASS];
    int max_pet[GKS_IN_NCLASS];
    int max_choices;             /* choice numbers 1..max_choices */
} gks_in_desc;

/* The input facilities shared by the workstation types of this implementation. */
extern const gks_in_desc gks_in_desc_std;

/* A raw event of a physical device, in device coordinates (DC3, z 0 if the device is
 * 2-D): what the operator did with the device (class, number) of a workstation. */
typedef struct gks_in_raw {
    Gin_class cls;
    int num;
    int brk;                  /* 1: break (REQUEST returns status NONE) */
    int n;                    /* stroke: points in pts; locator, pick: 1 */
    const double (*pts)[3];   /* DC3 positions (valid until the next raw event) */
    double val;               /* valuator */
    int choice;               /* choice number, 0 = no choice */
    const char *str;          /* string (NUL-terminated) */
} gks_in_raw;

/* A logical input value (a measure), as returned to the application. */
typedef struct gks_in_val {
    Gin_status status;        /* OK, NONE (break) or NO_IN (no choice / no pick) */
    int tnr, view_ind;        /* locator/stroke: normalization transformation, view */
    Gpoint3 pos;              /* locator, WC3 */
    int n;                    /* stroke points */
    Gpoint3 *pts;             /* stroke, WC3 (owned) */
    double val;
    int choice;
    Gpick pick;
    char *str;                /* string (owned, NUL-terminated) */
} gks_in_val;

/* What a driver with interactive devices needs to know to map its mouse and keys and to
 * draw prompts and echoes: the devices that are taking input now. */
typedef struct gks_in_active_dev {
    Gin_class cls;
    int num;
    Gop_mode mode;
    int echo;                 /* 1: echo on */
    int pet;
    Glimit3 echo_vol;         /* DC3 */
    double init_dc[3];        /* locator/stroke: initial position in DC */
    double val, low, high;    /* valuator: current value and range */
    int max_choice;
    int str_buf;              /* string buffer size */
    Gin_data rec;             /* the device's data record (valid during the input call) */
} gks_in_active_dev;

/* The labels of a CHOICE menu (prompt/echo type 3) in data record r: the strings of a
 * record packed by the Fortran binding's GPREC ("GKSR", bindings/fortran), or else r->str
 * cut at NUL and newline characters. Up to max labels: lab[k] points into r, len[k] its
 * length. Returns the number found (0: none). */
int gks_in_menu_labels(const Gin_data *r, const char **lab, int *len, int max);

/* PICK echo support for interactive drivers. gks_in_pick_at: the segment and pick
 * identifier a PICK at DC position dc of ws would return (1), or 0 when nothing is hit.
 * gks_in_seg_outline: the primitives of segment seg as ws shows them, in DC3 (segment
 * transformation, view, workstation transformation), only those with pick identifier
 * pick_id unless it is negative; fn gets a polyline's points, each loop of an area (fill
 * area (set), cell array corners), or a marker set's / a text's positions. Returns the
 * number of primitives passed (0: segment absent, invisible or not on ws). */
typedef enum {
    GKS_IN_OUTLINE_LINE,
    GKS_IN_OUTLINE_AREA,
    GKS_IN_OUTLINE_POINTS
} gks_in_outline_kind;
typedef void (*gks_in_outline_fn)(void *user, gks_in_outline_kind kind, int n,
                                  const double (*dc)[3]);
struct gks_ws;
int gks_in_pick_at(const struct gks_ws *ws, const double dc[3], Gpick *out);
int gks_in_seg_outline(const struct gks_ws *ws, Gint seg, Gint pick_id,
                       gks_in_outline_fn fn, void *user);

typedef struct gks_in_active {
    int n;
    int request;              /* index of the device a REQUEST waits for, -1 none */
    gks_in_active_dev dev[GKS_IN_MAX_ACTIVE];
} gks_in_active;

/* One logical input device's state list (ISO 7942 6.6 input device entries). */
typedef struct gks_indev {
    Gop_mode mode;
    int echo;
    int pet;
    Glimit3 echo_vol;         /* DC3 (2-D initialisation: z from the display space) */
    Gin_data rec;             /* data record (owned copies of its arrays) */
    gks_in_val init;          /* initial value (status for choice and pick) */
    double low, high;         /* valuator range */
    int buf_size;             /* stroke points / string characters */
    int cur_pos;              /* string initial cursor position */
    gks_in_val cur;           /* current measure (SAMPLE) */
} gks_indev;

/* The input part of a workstation state list (category INPUT or OUTIN). */
typedef struct gks_in_ws {
    const gks_in_desc *desc;
    gks_indev *dev[GKS_IN_NCLASS]; /* desc->n_dev[c] devices each */
    struct gks_in_script *script;  /* scripted input, NULL = none */
} gks_in_ws;

struct gks_ws;
struct gks_ws_desc;

/* Creates the input state lists of a workstation being opened (NULL desc: none).
 * Attaches the script named by GKS_INPUT_SCRIPT to the first such workstation opened.
 * Returns 0 or 300. */
int gks_in_ws_open(struct gks_ws *ws, const gks_in_desc *desc);
/* Frees them; removes the workstation's events from the queue and the current event
 * report, and marks an overflow it caused (149). */
void gks_in_ws_close(struct gks_ws *ws);
/* Attaches the input script file `path` (n characters) to ws, replacing any.
 * Returns 0, 182 (not an input workstation, or the file cannot be read) or 300. */
int gks_in_script_attach(struct gks_ws *ws, const char *path, size_t n);

/* The device (class, 1-based num) of ws, or NULL. */
gks_indev *gks_in_dev(struct gks_ws *ws, Gin_class cls, int num);
/* Number of devices of a class on a type's description. */
int gks_in_num_devices(const gks_in_desc *d, Gin_class cls);

/* Default initial values and state of a device of class cls on a type (used at open and
 * by the default-data inquiries). */
void gks_in_dev_default(const struct gks_ws_desc *d, Gin_class cls, gks_indev *dev);

/* Replaces dst by a deep copy of src (0 or 300: dst unchanged). */
int gks_in_val_copy(gks_in_val *dst, const gks_in_val *src);
void gks_in_val_free(gks_in_val *v);
int gks_in_rec_copy(Gin_data *dst, const Gin_data *src);
void gks_in_rec_free(Gin_data *r);

/* Mode change of a device (SET ... MODE): the measure starts from the initial value;
 * leaving EVENT mode keeps queued events (FLUSH removes them). Returns 0 or 300. */
int gks_in_set_mode(struct gks_ws *ws, Gin_class cls, int num, Gop_mode mode, int echo);

/* REQUEST: waits for the device's trigger. *out gets the value (status NONE on break, on
 * an exhausted script with no interactive device, or when the operator gives nothing).
 * Returns 0 or 300. */
int gks_in_request(struct gks_ws *ws, Gin_class cls, int num, gks_in_val *out);
/* SAMPLE: lets pending operator actions happen (one script step), then the measure.
 * Returns 0 or 300. */
int gks_in_sample(struct gks_ws *ws, Gin_class cls, int num, gks_in_val *out);
/* AWAIT EVENT: the next event within timeout seconds moves to the current event report;
 * *ws_id, *cls, *num of it (GIN_NONE if none). Returns 0, 147 (the queue overflowed
 * since the last AWAIT EVENT: reported once, the event is still returned) or 300. */
int gks_in_await(double timeout, Gint *ws_id, Gin_class *cls, Gint *num);
/* The current event report, if it holds a value of class cls (else NULL). */
const gks_in_val *gks_in_current(Gin_class cls);
/* FLUSH DEVICE EVENTS. */
void gks_in_flush(int ws_id, Gin_class cls, int num);
/* INQUIRE INPUT QUEUE OVERFLOW: 0 with the device, 148 or 149; clears the condition. */
int gks_in_overflow(Gint *ws_id, Gin_class *cls, Gint *num);
/* MORE SIMULTANEOUS EVENTS of the current event report. */
int gks_in_more_simult(void);
/* Called at CLOSE GKS: empties the queue, report and overflow condition. */
void gks_in_reset(void);
#endif
