/* SPDX-License-Identifier: MIT */
/*
 * fuzz_render.c -- fuzz target for gks3d-render's entry (src/tools/gks3d_render.c, included
 * here with its main left out): the bytes are the metafile IN.gksm, rendered as the program
 * renders it, `gks3d-render in.gksm -o out.png --mode M --size 24 --samples 1 --threads 1
 * --frames 1-3 --quiet` (M chosen by the input's size, so every HLHSR mode, ray tracing
 * included, is reached), its files in a private scratch directory (mkdtemp in $TMPDIR or /tmp):
 * after each input the frames are removed and any other file there is a bug (abort), as is
 * GKS left open (the next input would find its workstations: what the first finding was), as are
 * crashes, sanitizer reports, hangs and unbounded allocation; error messages and exit
 * statuses 2 and 4 are expected.
 * libFuzzer entry point (scripts/fuzz.sh, corpus tests/fuzz/corpus_mi: the metafile
 * fuzzer's), replayed over that corpus by the ctest `fuzz_render_replay` in every build.
 */
#define GKS3D_RENDER_NO_MAIN
#include "../../src/tools/gks3d_render.c"

#include <dirent.h>
#include <stdint.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static long n_runs, n_written; /* inputs rendered, and those with status 0 or 4 */

#ifdef FUZZ_RENDER_REPLAY
/* The replay test fails when no input was rendered: the target would test nothing. */
__attribute__((destructor)) static void report_runs(void)
{
    printf("fuzz_render: %ld inputs, %ld rendered\n", n_runs, n_written);
}
#endif

static char dir[512]; /* the scratch directory */
static char in[600], out[600], out2[600], out3[600]; /* its files */

/* Fails (abort) when the scratch directory holds anything but the input. */
static void only_input_left(void)
{
    DIR *d = opendir(dir);
    if (!d)
        abort();
    struct dirent *e;
    while ((e = readdir(d)))
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, "in.gksm")) {
            fprintf(stderr, "fuzz_render: the input wrote %s\n", e->d_name);
            abort();
        }
    closedir(d);
}

/* At exit: the scratch directory removed (the input, then the directory). */
static void scratch_gone(void)
{
    remove(in);
    rmdir(dir);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        const char *t = getenv("TMPDIR");
        snprintf(dir, sizeof dir, "%s/fuzz_render.XXXXXX", t && *t ? t : "/tmp");
        if (!mkdtemp(dir))
            abort();
        snprintf(in, sizeof in, "%s/in.gksm", dir); /* absolute: libFuzzer's paths are */
        snprintf(out, sizeof out, "%s/out.png", dir); /* relative to the current folder */
        snprintf(out2, sizeof out2, "%s/out-002.png", dir);
        snprintf(out3, sizeof out3, "%s/out-003.png", dir);
        atexit(scratch_gone);
        ready = 1;
    }
    FILE *f = fopen(in, "wb");
    if (!f)
        return 0;
    size_t done = size ? fwrite(data, 1, size, f) : 0;
    if (fclose(f) != 0 || done != size)
        return 0;
    static const char *const modes[] = { "none", "hidden-line", "zbuffer", "painter",
                                         "raytrace" };
    char *argv[] = { "gks3d-render", in, "-o", out, "--mode",
                     (char *)modes[size % 5], "--size", "24", "--samples", "1", "--threads",
                     "1", "--frames", "1-3", "--quiet", NULL };
    int rc = render_main((int)(sizeof argv / sizeof argv[0]) - 1, argv);
    n_runs++;
    Gop_st st;
    ginq_op_st(&st);
    if (st != GST_GKCL) { /* the next input would find workstations open (error 24) */
        fprintf(stderr, "fuzz_render: GKS left open (state %d)\n", (int)st);
        abort();
    }
    n_written += rc == 0 || rc == EXIT_ITEMS;
    remove(out);
    remove(out2);
    remove(out3);
    only_input_left();
    return 0;
}
