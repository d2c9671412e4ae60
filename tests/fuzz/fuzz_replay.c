/* SPDX-License-Identifier: MIT */
/*
 * fuzz_replay.c -- runs a libFuzzer target over files given on the command line (the
 * committed corpus), without libFuzzer: a regression test for every input ever found.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int main(int argc, char **argv)
{
    int n = 0;
    for (int i = 1; i < argc; i++) {
        FILE *fp = fopen(argv[i], "rb");
        if (!fp) {
            fprintf(stderr, "fuzz_replay: cannot open %s\n", argv[i]);
            return 1;
        }
        unsigned char *buf = NULL;
        size_t len = 0, cap = 0;
        for (;;) {
            if (len == cap) {
                cap = cap ? 2 * cap : 4096;
                unsigned char *b = realloc(buf, cap);
                if (!b) {
                    free(buf);
                    fclose(fp);
                    return 1;
                }
                buf = b;
            }
            size_t k = fread(buf + len, 1, cap - len, fp);
            if (k == 0)
                break;
            len += k;
        }
        fclose(fp);
        LLVMFuzzerTestOneInput(buf, len);
        free(buf);
        n++;
    }
    printf("fuzz_replay: %d inputs, no crash\n", n);
    return n > 0 ? 0 : 1;
}
