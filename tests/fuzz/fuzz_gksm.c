/* SPDX-License-Identifier: MIT */
/*
 * fuzz_gksm.c -- fuzz target for the GKS metafile reader (untrusted input): the bytes are a
 * metafile; read the header and every item, decoding each data record as integers, reals
 * and strings. libFuzzer entry point; built with clang -fsanitize=fuzzer by
 * scripts/fuzz.sh, and replayed over the committed corpus by the ctest `fuzz_gksm_replay`
 * (fuzz_replay.c) in every build, so a crashing input once found stays a regression test.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "gks_mf_codec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FILE *fp = tmpfile();
    if (!fp)
        return 0;
    if (size && fwrite(data, 1, size, fp) != size) {
        fclose(fp);
        return 0;
    }
    rewind(fp);
    gksm_in m;
    if (gksm_in_open(&m, fp) == 0) {
        char buf[4096];
        for (int items = 0; items < 100000; items++) {
            int type;
            size_t len, got;
            if (gksm_in_peek(&m, &type, &len))
                break;
            if (len > size) /* the reader promised never to claim more than the file holds */
                abort();
            if (gksm_in_read(&m, buf, sizeof buf, &got))
                break;
            gksm_cur c;
            gksm_cur_init(&c, &m, buf, got);
            /* Decode by a pattern chosen by the item type: int, real, string, ... */
            for (int k = 0; gksm_cur_left(&c) > 0; k++) {
                long v;
                double x;
                const char *s;
                size_t n;
                int e = (k + type) % 3 == 0 ? gksm_get_int(&c, &v)
                      : (k + type) % 3 == 1 ? gksm_get_real(&c, &x)
                                            : gksm_get_str(&c, &s, &n);
                if (e)
                    break;
            }
        }
    }
    fclose(fp);
    return 0;
}
