/* SPDX-License-Identifier: MIT */
/*
 * gks_error.c -- error table, the one report function, ERROR HANDLING and ERROR LOGGING.
 */
#include "gks_error.h"
#include "gks_binding.h"
#include "gks_context.h"
#include "gks_state.h"
#include <limits.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

typedef struct { int num; const char *msg; } err_entry;
static const err_entry err_table[] = {
#define GKS_ERR(n, m) { n, m },
#include "gks_errors.def"
#undef GKS_ERR
};

typedef struct { const char *name; unsigned states; } fn_entry;
static const fn_entry fn_table[] = {
#define GKS_FN(id, sym, name, states, mf) [id] = { name, states },
#include "gks_functions.def"
#undef GKS_FN
};

const char *gks_error_message(Gint err_num)
{
    for (size_t i = 0; i < sizeof err_table / sizeof err_table[0]; i++)
        if (err_table[i].num == err_num)
            return err_table[i].msg;
    return "";
}

const char *gks_function_name(Gint func_num)
{
    if (func_num < 0 || (size_t)func_num >= sizeof fn_table / sizeof fn_table[0] ||
        !fn_table[func_num].name)
        return "";
    return fn_table[func_num].name;
}

unsigned gks_function_states(int fctid)
{
    if (fctid < 0 || (size_t)fctid >= sizeof fn_table / sizeof fn_table[0])
        return 0;
    return fn_table[fctid].states;
}

/* ---- threads (docs/ARCHITECTURE.md "Threads") ----
 * GKS belongs to one thread at a time: the one that called OPEN GKS, until CLOSE GKS or
 * EMERGENCY CLOSE GKS. A call from any other thread while GKS is owned is refused before
 * it reads anything of the context: it reports GKS_E_THREAD to the installed ERROR
 * HANDLING procedure (without the error state, which is the owner's; the default handler
 * writes to standard error, not to the owner's error file), an inquiry returns it in its
 * error indicator. Every entry point passes gks_check_state (non-inquiries) or
 * gks_inq_args / gks_inq_state / gks_inq_begin (inquiries) first; the few that pass
 * neither (EMERGENCY CLOSE GKS, SET ERROR HANDLING, ERROR LOGGING, INQUIRE OPERATING STATE,
 * the binding's error report) check gks_thread_mine themselves. A thread is identified by
 * the address of its own thread-local byte (no pthread_t comparison needed). */
static _Atomic uintptr_t gks_owner;          /* 0: GKS is closed and nobody opens it */
/* The initial-exec model: the byte is found at a fixed offset from the thread pointer
 * instead of through __tls_get_addr on every entry point (one byte of the static TLS
 * block that the C library keeps spare for libraries it loads later). */
#if defined(__GNUC__) && defined(__ELF__)
static _Thread_local char gks_thread_self __attribute__((tls_model("initial-exec")));
#else
static _Thread_local char gks_thread_self;
#endif
static _Atomic(Gerr_handler) gks_foreign_handler; /* the handler as a refused call sees it */

static uintptr_t thread_self(void)
{
    return (uintptr_t)&gks_thread_self;
}

int gks_thread_mine(void)
{
    uintptr_t o = atomic_load_explicit(&gks_owner, memory_order_acquire);
    return o == 0 || o == thread_self();
}

int gks_thread_claim(void)
{
    uintptr_t none = 0, self = thread_self();
    return atomic_compare_exchange_strong(&gks_owner, &none, self) || none == self;
}

void gks_thread_release(void)
{
    uintptr_t self = thread_self();
    atomic_compare_exchange_strong(&gks_owner, &self, 0);
}

int gks_thread_refused(int fctid)
{
    Gerr_handler h = atomic_load(&gks_foreign_handler);
    (h ? h : gerr_hand)(GKS_E_THREAD, fctid, NULL);
    return GKS_E_THREAD;
}

void gks_error_note(const char *fmt, ...)
{
    gks_context *c = gks_ctx();
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(c->err.note, sizeof c->err.note, fmt, ap);
    va_end(ap);
}

int gks_error_report(int err_num, int fctid)
{
    gks_context *c = gks_ctx();
    Gerr_handler h = c->err.handler ? c->err.handler : gerr_hand;
    const char *file = c->sl ? c->sl->err_file : NULL;
    unsigned long epoch = c->err.epoch;
    int outer = c->err.in_handler; /* a handler's own call may report: nest */
    c->err.last_error = err_num;
    memcpy(c->err.detail, c->err.note, sizeof c->err.detail);
    c->err.note[0] = '\0';
    c->err.in_handler = 1;
    h(err_num, fctid, file);
    c->err.in_handler = outer;
    return c->err.epoch == epoch;
}

GKS_API const char *gks_error_detail(void)
{
    return gks_ctx()->err.detail;
}

GKS_API void gks_binding_error(int err_num, int fctid)
{
    if (!gks_thread_mine()) {
        gks_thread_refused(fctid);
        return;
    }
    if (gks_error_report(err_num, fctid)) {
    } /* the binding's wrapper returns at once */
}

unsigned long gks_world_epoch(void)
{
    return gks_ctx()->err.epoch;
}

void gks_world_changed(void)
{
    gks_ctx()->err.epoch++;
}

int gks_check_state(int fctid)
{
    /* OPEN GKS claims GKS for its thread (released again if GKS stays closed) */
    if (!(fctid == GFN_OPKS ? gks_thread_claim() : gks_thread_mine()))
        return gks_thread_refused(fctid);
    /* Every non-inquiry entry point passes here: entered from ERROR HANDLING, it may
     * change anything, so the reporting function must not go on. */
    if (gks_ctx()->err.in_handler)
        gks_world_changed();
    gks_ctx()->err.note[0] = '\0'; /* a note belongs to an error of this call */
    unsigned mask = gks_function_states(fctid);
    if (mask & (1u << gks_ctx()->op_st))
        return 0;
    int e = gks_state_error_for(mask);
    if (gks_error_report(e, fctid)) {
    } /* the caller returns on e != 0 anyway */
    return e;
}

int gks_inq_begin(Gint *err_ind, unsigned mask)
{
    if (!err_ind)
        return -1;
    if (!gks_thread_mine())
        return *err_ind = GKS_E_THREAD;
    *err_ind = gks_inq_state(mask);
    return *err_ind;
}

int gks_list_start(Gint start, Gint n)
{
    return start < 0 || (start >= n && !(start == 0 && n == 0)) ? 2002 : 0;
}

gks_list_out gks_list_begin(Gint_list *out, Gint cap, Gint start)
{
    Gint *dst = out ? out->ints : NULL;
    return (gks_list_out){ .dst = dst, .num = out ? &out->num_ints : NULL,
                           .cap = dst ? cap : 0, .start = start };
}

int gks_list_slot(gks_list_out *w)
{
    int k = w->start >= 0 && w->n >= w->start && w->k < w->cap ? w->k++ : -1;
    if (w->n < INT_MAX)
        w->n++;
    return k;
}

void gks_list_put(gks_list_out *w, Gint v)
{
    int k = gks_list_slot(w);
    if (k >= 0)
        w->dst[k] = v;
}

int gks_list_end(gks_list_out *w, Gint *len)
{
    if (len)
        *len = w->n;
    int e = gks_list_start(w->start, w->n);
    if (!e && w->num)
        *w->num = w->k;
    return e;
}

int gks_list_copy(const int *list, int n, Gint cap, Gint start, Gint_list *out, Gint *len)
{
    gks_list_out w = gks_list_begin(out, cap, start);
    for (int i = 0; i < n; i++)
        gks_list_put(&w, list[i]);
    return gks_list_end(&w, len);
}

int gks_list_flags(const unsigned char *def, int lo, int hi, Gint cap, Gint start,
                   Gint_list *out, Gint *len)
{
    gks_list_out w = gks_list_begin(out, cap, start);
    for (int i = lo; i <= hi; i++)
        if (def[i])
            gks_list_put(&w, i);
    return gks_list_end(&w, len);
}

int gks_inq_args(Gint *err_ind, int n, const void *const *p)
{
    if (!err_ind)
        return 1;
    if (!gks_thread_mine()) {
        *err_ind = GKS_E_THREAD;
        return 1;
    }
    for (int i = 0; i < n; i++)
        if (!p[i]) {
            *err_ind = 2003; /* a NULL pointer argument (docs/ERRORS.md) */
            return 1;
        }
    return 0;
}

int gks_inq_state(unsigned mask)
{
    if (!gks_thread_mine())
        return GKS_E_THREAD;
    return (mask & (1u << gks_ctx()->op_st)) ? 0 : gks_state_error_for(mask);
}

GKS_API void gerr_hand(Gint err_num, Gint func_num, const char *err_file)
{
    gerr_log(err_num, func_num, err_file);
}

GKS_API void gerr_log(Gint err_num, Gint func_num, const char *err_file)
{
    (void)err_file; /* the file was opened once at OPEN GKS */
    /* another thread's refused call: standard error, never the owner's error file, and
     * no detail (it belongs to the owner's error being handled) */
    FILE *fp = stderr;
    const char *detail = "";
    if (gks_thread_mine()) {
        if (gks_ctx()->err.fp)
            fp = gks_ctx()->err.fp;
        /* the detail belongs to the error being handled, not to a call outside a handler */
        if (gks_ctx()->err.in_handler)
            detail = gks_ctx()->err.detail;
    }
    fprintf(fp, "GKS ERROR %d in %s: %s%s%s\n", err_num, gks_function_name(func_num),
            gks_error_message(err_num), *detail ? ": " : "", detail);
    fflush(fp);
}

GKS_API void gset_err_hand(Gerr_handler new_hand, Gerr_handler *old_hand)
{
    if (!gks_thread_mine()) {
        gks_thread_refused(-1); /* no function identification */
        return;
    }
    gks_context *c = gks_ctx();
    if (old_hand)
        *old_hand = c->err.handler ? c->err.handler : gerr_hand;
    c->err.handler = (new_hand == gerr_hand) ? NULL : new_hand;
    atomic_store(&gks_foreign_handler, c->err.handler);
}

GKS_API void ginq_err_st(Gint *in_error_handling, Gint *last_err_num)
{
    if (!gks_thread_mine()) /* no error indicator: nothing is written */
        return;
    if (in_error_handling)
        *in_error_handling = gks_ctx()->err.in_handler;
    if (last_err_num)
        *last_err_num = gks_ctx()->err.last_error;
}
