/* SPDX-License-Identifier: MIT */
/*
 * gks_error.h -- the one error path: every function that detects an error calls
 * gks_error_report(), which sets the error state, calls the current ERROR HANDLING
 * procedure (gerr_hand or the application's) and returns. Never exits.
 *
 * The handler may change the world: ISO 7942 lets it call EMERGENCY CLOSE GKS, and a
 * careless one may call anything. So gks_error_report() answers whether the caller may
 * go on: it compares the context's world epoch (gks_context.h) before and after the
 * handler. The answer must be used (warn_unused_result, -Werror): a caller that does not
 * return at once on 0 fails to compile. docs/ERRORS.md describes the design.
 */
#ifndef GKS_ERROR_H
#define GKS_ERROR_H
#include "gks_private.h"
#include "gks.h"

#define GKS_MUST_CHECK __attribute__((warn_unused_result))

/* Report error `err_num` detected in function `fctid`. Returns 1 if the world is as it
 * was before the report (the caller may continue: next workstation, next segment), 0 if
 * the handler changed it (GKS closed, a workstation closed, a segment deleted, any other
 * non-inquiry function called): the caller then returns at once, touching nothing it
 * looked up before the report. */
GKS_MUST_CHECK int gks_error_report(int err_num, int fctid);

/* Words for the next report (printf format), e.g. gks_error_note("cannot open \"%s\": %s",
 * path, strerror(errno)): gks_error_report hands them to the handler through
 * gks_error_detail() and ERROR LOGGING writes them; a report clears the note, so a note
 * never describes a later error. Truncated to GKS_ERROR_DETAIL_MAX - 1 bytes. */
void gks_error_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The world epoch: a counter that changes whenever something a caller may hold a
 * pointer to ceases to exist (CLOSE GKS and EMERGENCY CLOSE GKS, CLOSE WORKSTATION, a
 * segment deleted) and whenever a non-inquiry function is entered while ERROR HANDLING
 * runs. Code that calls public functions in a loop (INTERPRET ITEM) compares it. */
unsigned long gks_world_epoch(void);
/* Mark the world changed (the sites listed above). */
void gks_world_changed(void);

/* Threads (gks_error.c, docs/ARCHITECTURE.md): GKS belongs to the thread that opened it
 * until it is closed; another thread's call is refused with GKS_E_THREAD. */
#define GKS_E_THREAD 950
/* 1 if the calling thread may use GKS: it owns it, or nobody does. */
int gks_thread_mine(void);
/* OPEN GKS: claims GKS for the calling thread; 0 if another thread owns it. */
int gks_thread_claim(void);
/* CLOSE GKS, EMERGENCY CLOSE GKS, a failed OPEN GKS: the calling thread gives GKS up. */
void gks_thread_release(void);
/* A refused call: GKS_E_THREAD to the installed ERROR HANDLING procedure (no error state,
 * no error file); returns GKS_E_THREAD. fctid -1: a function without identification. */
int gks_thread_refused(int fctid);

/* Entry-point guard: if the operating state does not allow `fctid`, report the state
 * error and return it; else return 0. Usage:  if (gks_check_state(GFN_PL)) return; */
int gks_check_state(int fctid);

/* For inquiries: the state error number for a function allowed in `mask`, or 0. */
int gks_inq_state(unsigned mask);

/* Inquiry entry: writes the state error (or 0) to *err_ind and returns it; a NULL error
 * indicator returns -1 (the inquiry has nowhere to answer and does nothing). */
int gks_inq_begin(Gint *err_ind, unsigned mask);

/* Inquiry entry for pointer arguments (issue 20 I), the first statement of every ginq_*:
 * returns 1 when the inquiry must return at once, because err_ind is NULL (nothing is
 * written) or one of the n pointers p is NULL (*err_ind = 2003, in every state). */
int gks_inq_args(Gint *err_ind, int n, const void *const *p);
#define GKS_INQ_ARGS(err_ind, ...)                                                         \
    do {                                                                                   \
        const void *const gks_inq_p_[] = { __VA_ARGS__ };                                  \
        if (gks_inq_args((err_ind), (int)(sizeof gks_inq_p_ / sizeof gks_inq_p_[0]),       \
                         gks_inq_p_))                                                      \
            return;                                                                        \
    } while (0)

/* The list rule of every list inquiry (docs/BINDING.md): the answer is the part of the
 * list from the 0-based start position, as much as the application's list holds, and the
 * list's length. A start position outside a list of n elements is 2002, except that an
 * empty list accepts start 0 (only its length is returned). Returns 0 or 2002. */
int gks_list_start(Gint start, Gint n);

/* A list answer written element by element (lists filtered from a table): put every
 * element in order, then end. Elements from position start are stored in dst (room for
 * cap; dst may be NULL) and counted in *num (if num is not NULL). */
typedef struct {
    Gint *dst, *num;
    Gint cap, start, n, k;
} gks_list_out;
gks_list_out gks_list_begin(Gint_list *out, Gint cap, Gint start);
void gks_list_put(gks_list_out *w, Gint v);
/* The same for a list of another element type: the index in the caller's array (room for
 * cap) at which to store the element put, or -1 when it is not stored. */
int gks_list_slot(gks_list_out *w);
/* *len = the elements put; the stored count to *num; returns gks_list_start(start, n). */
int gks_list_end(gks_list_out *w, Gint *len);
/* The whole list[0..n) answered under the list rule: gks_list_end of putting each. */
int gks_list_copy(const int *list, int n, Gint cap, Gint start, Gint_list *out, Gint *len);
/* The indices i in [lo, hi] whose flag def[i] is set (defined table entries), in ascending
 * order, answered under the list rule as gks_list_copy. */
int gks_list_flags(const unsigned char *def, int lo, int hi, Gint cap, Gint start,
                   Gint_list *out, Gint *len);

/* Report as the caller's last action and return (from a void function / with `val`):
 * returning is right whatever the handler did. */
#define GKS_FAIL(err, fct)                                                                 \
    do {                                                                                   \
        if (gks_error_report((err), (fct))) {                                              \
        }                                                                                  \
        return;                                                                            \
    } while (0)
#define GKS_FAIL_RET(err, fct, val)                                                        \
    do {                                                                                   \
        if (gks_error_report((err), (fct))) {                                              \
        }                                                                                  \
        return (val);                                                                      \
    } while (0)
#endif
