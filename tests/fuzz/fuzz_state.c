/* SPDX-License-Identifier: MIT */
/*
 * fuzz_state.c -- state-machine fuzz target (issue 20 item 5): the input is a program of
 * GKS calls with arguments drawn from hostile values (NaN, Inf, 1e308, 4.9e-324, -0, NULL,
 * negative and huge identifiers), run on null, WISS, PNG (classic and ray-traced) and MO
 * workstations.
 *
 * Input layout: byte 0 chooses the handler (bit 0: EMERGENCY CLOSE GKS from the handler)
 * and byte 1 an allocation to fail (0 none, k: the 16*k-th from now, through the
 * library's fault-injection hook); then each call is an opcode byte and argument bytes.
 *
 * Checked after every call: when it reported an argument or state error (anything but the
 * resource errors 300-308, which the standard lets arrive after part of the work, e.g.
 * CLOSE WORKSTATION closes even when the last write fails) and the handler is passive,
 * the state inquiries (operating state, open/active workstations, their states,
 * deferral and transformations, normalization transformations, clipping, current
 * attributes, segments) must answer exactly as before the call: "no other effect".
 * With the closing handler, GKS must be closed after any reported error. A violation
 * aborts (libFuzzer reports it); crashes and sanitizer reports are bugs too.
 * libFuzzer entry point (scripts/fuzz.sh), replayed over tests/fuzz/corpus_state by the
 * ctest `fuzz_state_replay` in every build.
 */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gks.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
void gks_alloc_fail_after(long n);

static int n_errors, last_err, resource, closing;

static void handler(Gint err, Gint fct, const char *file)
{
    (void)fct;
    (void)file;
    n_errors++;
    last_err = err;
    resource |= err >= 300 && err <= 308;
    if (closing)
        gemergency_close_gks();
}

/* ------------------------------------------------------------------ input reader */
typedef struct {
    const uint8_t *p;
    size_t n, i;
} rd;

static unsigned byte(rd *r)
{
    return r->i < r->n ? r->p[r->i++] : 0;
}

static int ival(rd *r)
{
    static const int v[16] = { 1, 2, 3, 0, -1, 4, 5, 7, 99, 100, 2, 1, 31, 32, INT32_MAX,
                               INT32_MIN };
    return v[byte(r) & 15];
}

static double rval(rd *r)
{
    static const double v[16] = { 0.5, 0.25, 0, 1, -1, 0.75, 2, -0.0, NAN, INFINITY,
                                  -INFINITY, 1e308, -1.7e308, 4.9e-324, 1e-300, 0.1 };
    return v[byte(r) & 15];
}

/* ------------------------------------------------------------------ state snapshot */
#define MAXWS 8
typedef struct {
    Gop_st op;
    Gint e_open, n_open, open[MAXWS], e_act, n_act, act[MAXWS];
    Gint e_tnr, tnr, e_tr[3];
    Gtran3 tr[3];
    Gint e_clip;
    Gclip clip;
    Gint e_li, li, e_fc, fc, e_cht, e_fis;
    Gfloat cht;
    Gfill_int_style fis;
    Gint e_segs, n_segs, segs[MAXWS], e_oseg, oseg;
    struct {
        Gint e_st, e_def, e_tran;
        Gws_st st;
        Gdefer_mode dm;
        Girg_mode irg;
        Gdisp_space_empty empty;
        Gnew_frame_nec_upd nf;
        Gupd_st upd;
        Glimit3 w[2], v[2];
    } ws[MAXWS];
} snapshot;

static void take(snapshot *s)
{
    memset(s, 0, sizeof *s);
    ginq_op_st(&s->op);
    Gint_list l = { 0, s->open };
    ginq_set_open_wss(MAXWS, 0, &s->e_open, &l, &s->n_open);
    l = (Gint_list){ 0, s->act };
    ginq_set_active_wss(MAXWS, 0, &s->e_act, &l, &s->n_act);
    ginq_cur_norm_tran_num(&s->e_tnr, &s->tnr);
    for (int t = 0; t < 3; t++)
        ginq_norm_tran3(t, &s->e_tr[t], &s->tr[t]);
    ginq_clip(&s->e_clip, &s->clip);
    ginq_line_ind(&s->e_li, &s->li);
    ginq_fill_colr_ind(&s->e_fc, &s->fc);
    ginq_char_ht(&s->e_cht, &s->cht);
    ginq_fill_int_style(&s->e_fis, &s->fis);
    l = (Gint_list){ 0, s->segs };
    ginq_set_seg_names(MAXWS, 0, &s->e_segs, &l, &s->n_segs);
    ginq_name_open_seg(&s->e_oseg, &s->oseg);
    for (int w = 1; w < MAXWS; w++) {
        ginq_ws_st(w, &s->ws[w].e_st, &s->ws[w].st);
        ginq_ws_defer_upd_sts(w, &s->ws[w].e_def, &s->ws[w].dm, &s->ws[w].irg,
                              &s->ws[w].empty, &s->ws[w].nf);
        ginq_ws_tran3(w, &s->ws[w].e_tran, &s->ws[w].upd, &s->ws[w].w[0], &s->ws[w].w[1],
                      &s->ws[w].v[0], &s->ws[w].v[1]);
    }
}

/* Bitwise equality (NaN == NaN here: a stored NaN must still be the same NaN). */
static int same(const snapshot *a, const snapshot *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

/* ------------------------------------------------------------------ the calls */
static void points(rd *r, Gpoint *p, int n)
{
    for (int i = 0; i < n; i++)
        p[i] = (Gpoint){ rval(r), rval(r) };
}

static void one_call(rd *r)
{
    static const Gint types[6] = { GWS_TYPE_NULL, GWS_TYPE_WISS, GWS_TYPE_PNG, GWS_TYPE_MO,
                                   GWS_TYPE_MI, 12345 };
    static const char *const conn[4] = { "fz_a", "fz_b.png", "fz.gksm", NULL };
    Gpoint p[6];
    Gpoint3 p3[6];
    unsigned op = byte(r) % 40;
    int ws = (int)(byte(r) % 6) - 1; /* -1..4 */
    switch (op) {
    case 0: gopen_gks(NULL, 0); break;
    case 1: gclose_gks(); break;
    case 2: {
        Gint t = types[byte(r) % 6];
        int e0 = n_errors;
        gopen_ws(ws, conn[byte(r) % 4], t);
        if (t == GWS_TYPE_PNG && n_errors == e0) { /* small pictures keep it fast */
            const Glimit vp = { 0, 16, 0, 16 };
            gset_ws_vp(ws, &vp);
        }
        break;
    }
    case 3: gclose_ws(ws); break;
    case 4: gactivate_ws(ws); break;
    case 5: gdeactivate_ws(ws); break;
    case 6: gclear_ws(ws, (Gctrl_flag)(byte(r) % 3)); break;
    case 7: gupd_ws(ws, (Gupd_regen_flag)(byte(r) % 3)); break;
    case 8: gredraw_all_seg_ws(ws); break;
    case 9: gset_defer_st(ws, (Gdefer_mode)(byte(r) % 5), (Girg_mode)(byte(r) % 3)); break;
    case 10: gmessage(ws, byte(r) & 1 ? "m" : NULL); break;
    case 11: {
        int n = (int)(byte(r) % 6);
        points(r, p, n);
        Gpoint_list l = { n, byte(r) & 7 ? p : NULL };
        gpolyline(&l);
        break;
    }
    case 12: {
        int n = (int)(byte(r) % 6);
        points(r, p, n);
        Gpoint_list l = { n, p };
        gpolymarker(&l);
        break;
    }
    case 13: {
        Gpoint at = { rval(r), rval(r) };
        static const char *const s[4] = { "AB", "", "\x01x", NULL };
        gtext(byte(r) & 7 ? &at : NULL, s[byte(r) % 4]);
        break;
    }
    case 14: {
        int n = (int)(byte(r) % 6);
        points(r, p, n);
        Gpoint_list l = { n, p };
        gfill_area(&l);
        break;
    }
    case 15: {
        int n = (int)(byte(r) % 6);
        for (int i = 0; i < n; i++)
            p3[i] = (Gpoint3){ rval(r), rval(r), rval(r) };
        Gpoint_list3 l = { n, p3 };
        if (byte(r) & 1)
            gfill_area3(&l);
        else
            gpolyline3(&l);
        break;
    }
    case 16: {
        Gint c[4] = { ival(r), 1, 0, 2 };
        Gpat_rep ca = { { ival(r), ival(r) }, c };
        Grect rc = { { rval(r), rval(r) }, { rval(r), rval(r) } };
        if (ca.dims.size_x * (long)ca.dims.size_y > 4)
            ca.dims = (Gint_size){ 2, 2 };
        gcell_array(&rc, byte(r) & 7 ? &ca : NULL);
        break;
    }
    case 17: {
        Glimit w = { rval(r), rval(r), rval(r), rval(r) };
        gset_win(ival(r), &w);
        break;
    }
    case 18: {
        Glimit v = { rval(r), rval(r), rval(r), rval(r) };
        gset_vp(ival(r), &v);
        break;
    }
    case 19: gsel_norm_tran(ival(r)); break;
    case 20: gset_clip_ind((Gclip_ind)(byte(r) % 3)); break;
    case 21: {
        Glimit w = { rval(r), rval(r), rval(r), rval(r) };
        gset_ws_win(ws, &w);
        break;
    }
    case 22: {
        Glimit v = { rval(r) * 16, rval(r) * 16, rval(r) * 16, rval(r) * 16 };
        gset_ws_vp(ws, &v);
        break;
    }
    case 23: gcreate_seg(ival(r)); break;
    case 24: gclose_seg(); break;
    case 25: gdel_seg(ival(r)); break;
    case 26: gdel_seg_ws(ws, ival(r)); break;
    case 27: {
        Gtran_matrix m = { { rval(r), 0, rval(r) }, { 0, rval(r), 0 } };
        gset_seg_tran(ival(r), byte(r) & 7 ? m : NULL);
        break;
    }
    case 28: gset_vis(ival(r), (Gseg_vis)(byte(r) % 3)); break;
    case 29: gset_seg_pri(ival(r), rval(r)); break;
    case 30: grename_seg(ival(r), ival(r)); break;
    case 31: {
        Gtran_matrix m = { { 1, 0, rval(r) }, { 0, 1, 0 } };
        ginsert_seg(ival(r), byte(r) & 7 ? m : NULL);
        break;
    }
    case 32: gassoc_seg_ws(ws, ival(r)); break;
    case 33: gcopy_seg_ws(ws, ival(r)); break;
    case 34: gset_line_ind(ival(r)); break;
    case 35: gset_fill_colr_ind(ival(r)); break;
    case 36: gset_char_ht(rval(r)); break;
    case 37: gset_fill_int_style((Gfill_int_style)(byte(r) % 5)); break;
    case 38: gset_hlhsr_mode(ws, (Gint)(byte(r) % 6)); break;
    default: {
        const Gcolr_rep c = { { rval(r), rval(r), rval(r) } };
        gset_colr_rep(ws, ival(r), byte(r) & 7 ? &c : NULL);
        break;
    }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rd r = { data, size, 0 };
    closing = byte(&r) & 1;
    long fail = (long)byte(&r) * 16;
    gset_err_hand(handler, NULL);
    gemergency_close_gks();
    gks_alloc_fail_after(fail);
    for (int calls = 0; r.i < r.n && calls < 256; calls++) {
        snapshot before, after;
        take(&before);
        int e0 = n_errors;
        resource = 0;
        one_call(&r);
        if (n_errors == e0)
            continue;
        Gop_st st;
        ginq_op_st(&st);
        if (closing && st != GST_GKCL)
            abort(); /* the handler closed GKS: it must stay closed */
        if (closing || resource)
            continue;
        take(&after);
        if (!same(&before, &after)) {
            fprintf(stderr, "fuzz_state: error %d changed the state\n", last_err);
            abort();
        }
    }
    gks_alloc_fail_after(0);
    gemergency_close_gks();
    return 0;
}
