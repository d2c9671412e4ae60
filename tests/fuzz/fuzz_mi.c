/* SPDX-License-Identifier: MIT */
/*
 * fuzz_mi.c -- fuzz target for the metafile input workstation (untrusted input): the bytes
 * are opened as a GKS metafile (MI workstation, on a scratch file in $TMPDIR or /tmp: OPEN
 * WORKSTATION accepts regular files only, so an anonymous memory file would be refused), and
 * every item is read with GET ITEM TYPE / READ ITEM and performed with INTERPRET ITEM onto
 * an active null workstation, until the END item or the first read error. Errors are
 * expected; crashes, sanitizer reports, hangs and unbounded allocation are bugs.
 * libFuzzer entry point (scripts/fuzz.sh), replayed over tests/fuzz/corpus_mi by the ctest
 * `fuzz_mi_replay` (fuzz_replay.c) in every build.
 */
#define _GNU_SOURCE
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>
#include <gks.h>

/* A Gitem_data record of n characters at s (include/gks.h: impl_dep holds them). */
#define ITEMN(s, n) (&(Gitem_data){ .data.impl_dep = { (size_t)(n), (void *)(s) } })

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int n_errors; /* errors reported by the current input (the handler has no context) */
static long n_interpreted; /* items interpreted over all inputs */

#ifdef FUZZ_MI_REPLAY
/* The replay test fails when no item of the whole corpus was interpreted: the target would
 * then test nothing (as when OPEN WORKSTATION refused its input file). */
__attribute__((destructor)) static void report_items(void)
{
    printf("fuzz_mi: %ld items interpreted\n", n_interpreted);
}
#endif

static void count_errors(Gint err, Gint fct, const char *file)
{
    (void)err;
    (void)fct;
    (void)file;
    n_errors++;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char name[512];
    if (!name[0]) {
        const char *dir = getenv("TMPDIR");
        snprintf(name, sizeof name, "%s/fuzz_mi.%ld.gksm", dir && *dir ? dir : "/tmp",
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
    gset_err_hand(count_errors, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(1, NULL, GWS_TYPE_NULL);
    gactivate_ws(1);
    n_errors = 0;
    gopen_ws(2, name, GWS_TYPE_MI);
    char *buf = NULL;
    for (int items = 0; n_errors == 0 && items < 100000; items++) {
        Gint type = 0, len = 0;
        gget_item_type(2, &type, &len);
        if (n_errors)
            break;
        if ((size_t)len > size) /* a length the file cannot hold was accepted */
            abort();
        char *b = realloc(buf, (size_t)len + 1);
        if (!b)
            break;
        buf = b;
        gread_item(2, len, ITEMN(buf, len));
        if (n_errors || type == 0)
            break;
        ginterpret_item(type, len, ITEMN(buf, len));
        n_interpreted++;
        n_errors = 0; /* interpretation errors are expected: go on with the next item */
    }
    free(buf);
    gemergency_close_gks();
    remove(name);
    return 0;
}
