/* SPDX-License-Identifier: MIT */
/* test_errfile_streams.c -- gopen_gks("stdout") logs errors to standard output (the ctest
 * pattern checks the message) and creates no file named "stdout" or "stderr". */
#include <gks.h>
#include <stdio.h>
#include <unistd.h>

int main(void)
{
    remove("stdout");
    remove("stderr");
    gopen_gks("stdout", 0);
    gclose_ws(7); /* error 7 (no workstation open), logged to standard output */
    gclose_gks();
    gopen_gks("stderr", 0);
    gclose_gks();
    fflush(stdout);
    if (access("stdout", F_OK) == 0 || access("stderr", F_OK) == 0) {
        printf("a file named stdout or stderr was created\n");
        return 1;
    }
    printf("no stream files\n");
    return 0;
}
