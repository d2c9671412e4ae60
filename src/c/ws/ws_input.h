/* SPDX-License-Identifier: MIT */
/*
 * ws_input.h -- what a workstation driver knows of logical input (ISO 7942 4.8): the input
 * facilities of its type, the raw events of its physical devices it delivers, and the
 * devices taking input now that it maps its mouse and keys to and draws prompts and
 * echoes for. The measure process, the device state lists and the queue are the core's
 * (core/gks_indev.h).
 */
#ifndef WS_INPUT_H
#define WS_INPUT_H
#include "gks_private.h"
#include "gks.h"

#define GKS_IN_NCLASS 6          /* LOCATOR .. STRING */
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

/* PICK echo support for interactive drivers, given with the active devices (the core's
 * segment store answers). pick_at: the segment and pick identifier a PICK at DC position
 * dc of ws would return (1), or 0 when nothing is hit. seg_outline: the primitives of
 * segment seg as ws shows them, in DC3 (segment transformation, view, workstation
 * transformation), only those with pick identifier pick_id unless it is negative; fn gets
 * a polyline's points, each loop of an area (fill area (set), cell array corners), or a
 * marker set's / a text's positions. Returns the number of primitives passed (0: segment
 * absent, invisible or not on ws). */
typedef enum {
    GKS_IN_OUTLINE_LINE,
    GKS_IN_OUTLINE_AREA,
    GKS_IN_OUTLINE_POINTS
} gks_in_outline_kind;
typedef void (*gks_in_outline_fn)(void *user, gks_in_outline_kind kind, int n,
                                  const double (*dc)[3]);
struct gks_ws;

typedef struct gks_in_active {
    int n;
    int request;              /* index of the device a REQUEST waits for, -1 none */
    gks_in_active_dev dev[GKS_IN_MAX_ACTIVE];
    int (*pick_at)(const struct gks_ws *ws, const double dc[3], Gpick *out);
    int (*seg_outline)(const struct gks_ws *ws, Gint seg, Gint pick_id, gks_in_outline_fn fn,
                       void *user);
} gks_in_active;
#endif
