/* SPDX-License-Identifier: MIT */
/*
 * f77_errfile_check.c -- runs f77_errfile (default GERHND -> GERLOG on unit 22) and
 * compares f77_errors.txt line by line with the expected "GKS ERROR n in NAME: message",
 * followed by ": " and the detail for an error about a file.
 * Usage: f77_errfile_check PROGRAM
 */
#define _POSIX_C_SOURCE 200809L
#include "gks.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    static const struct { int err, fct; } want[] = {
        { 23, GFN_OPWK }, { 25, GFN_ACWK }, { 26, GFN_OPWK }, { 1, GFN_OPKS },
        { 2000, GFN_CLRWK },
    };
    /* the detail GERLOG writes after the message (gks_error_detail) */
    static const char *const detail[] = {
        "", "", ": cannot open \"no_such_folder/f.png\": No such file or directory", "", "",
    };
    if (argc != 2) {
        fprintf(stderr, "usage: %s PROGRAM\n", argv[0]);
        return 2;
    }
    remove("f77_errors.txt");
    if (system(argv[1]) != 0) {
        printf("program failed\n");
        return 1;
    }
    FILE *fp = fopen("f77_errors.txt", "r");
    if (!fp) {
        printf("no f77_errors.txt\n");
        return 1;
    }
    int fails = 0;
    size_t n = sizeof want / sizeof want[0], i = 0;
    char line[512], exp[512];
    while (fgets(line, sizeof line, fp)) {
        line[strcspn(line, "\n")] = '\0';
        if (i >= n) {
            printf("extra line: %s\n", line);
            fails++;
            continue;
        }
        snprintf(exp, sizeof exp, "GKS ERROR %d in %s: %s%s", want[i].err,
                 gks_function_name(want[i].fct), gks_error_message(want[i].err), detail[i]);
        if (strcmp(line, exp) != 0) {
            printf("line %zu:\n got  %s\n want %s\n", i + 1, line, exp);
            fails++;
        }
        i++;
    }
    fclose(fp);
    if (i < n) {
        printf("only %zu of %zu lines\n", i, n);
        fails++;
    }
    printf("%d failures\n", fails);
    return fails ? 1 : 0;
}
