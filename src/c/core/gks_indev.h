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
#include "ws_input.h"
#include <stddef.h>

#define GKS_IN_QUEUE_MAX GKS_IN_QUEUE_CAPACITY /* input queue capacity (events), gks.h */

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
/* The current event report, if it holds a value of class cls (else NULL), and the buffer
 * size its device has now (*buf_size: INITIALISE may have changed it since the event was
 * queued; GET returns at most that many points or characters). */
const gks_in_val *gks_in_current(Gin_class cls, int *buf_size);
/* FLUSH DEVICE EVENTS. */
void gks_in_flush(int ws_id, Gin_class cls, int num);
/* INQUIRE INPUT QUEUE OVERFLOW: 0 with the device, 148 or 149; clears the condition. */
int gks_in_overflow(Gint *ws_id, Gin_class *cls, Gint *num);
/* MORE SIMULTANEOUS EVENTS of the current event report. */
int gks_in_more_simult(void);
/* Called at CLOSE GKS: empties the queue, report and overflow condition. */
void gks_in_reset(void);
#endif
