/* SPDX-License-Identifier: MIT */
/*
 * mpi_maps.c -- draws a triangle on a PNG workstation (file argv[1]) and then lists the
 * MPI libraries mapped into this process (/proc/self/maps: libmpi*, libopen-*, libpmix*,
 * libgks3d-mpi*), one "mapped: PATH" line each. Exit status: 0 if none is mapped, 3 if
 * some are, 1 on a GKS error, 2 on bad arguments. run_maps_test.sh runs it as a serial
 * program and under a launcher's environment.
 */
#include <gks.h>
#include <stdio.h>
#include <string.h>

static int errors;

static void count_errors(Gint err, Gint fn, const char *file)
{
    (void)file;
    fprintf(stderr, "mpi_maps: GKS error %d in function %d\n", (int)err, (int)fn);
    errors++;
}

int main(int argc, char **argv)
{
    if (argc != 2)
        return 2;
    Gpoint tri[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
    Gpoint_list tri_list = { 3, tri };
    remove(argv[1]);
    gset_err_hand(count_errors, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(1, argv[1], GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_fill_colr_ind(2);
    gfill_area(&tri_list);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    if (errors)
        return 1;
    FILE *m = fopen("/proc/self/maps", "r");
    if (!m) {
        perror("mpi_maps: /proc/self/maps");
        return 1;
    }
    static const char *const names[] = { "/libmpi", "/libopen-", "/libpmix", "/libgks3d-mpi" };
    char line[4096], last[4096] = "";
    int found = 0;
    while (fgets(line, sizeof line, m)) {
        const char *path = strchr(line, '/');
        if (!path || strcmp(path, last) == 0)
            continue;
        for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
            if (strstr(path, names[i])) {
                printf("mapped: %s", path);
                found++;
                snprintf(last, sizeof last, "%s", path);
                break;
            }
        }
    }
    fclose(m);
    if (!found)
        printf("mpi_maps: no MPI library mapped\n");
    return found ? 3 : 0;
}
