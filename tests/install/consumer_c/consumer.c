/* SPDX-License-Identifier: MIT */
/* consumer.c -- an installed-library consumer: draws on a PNG workstation, then checks
 * that the file argv[1] was written as a PNG of the workstation viewport size (200x100),
 * and that the library loaded is the version of the installed headers.
 * Exit status 0 only if GKS reported no error and the file header is right. */
#include <gks.h>
#include <stdio.h>
#include <string.h>

static int errors;

static void count_errors(Gint err, Gint fn, const char *file)
{
    (void)fn;
    (void)file;
    fprintf(stderr, "consumer: GKS error %d\n", (int)err);
    errors++;
}

static unsigned long be32(const unsigned char *p)
{
    return ((unsigned long)p[0] << 24) | ((unsigned long)p[1] << 16) |
           ((unsigned long)p[2] << 8) | (unsigned long)p[3];
}

int main(int argc, char **argv)
{
    static const unsigned char sig[8] = { 137, 'P', 'N', 'G', 13, 10, 26, 10 };
    Gpoint tri[3] = { { 0.1, 0.1 }, { 0.9, 0.1 }, { 0.5, 0.9 } };
    Gpoint_list tri_list = { 3, tri };
    Glimit ws_vp = { 0, 200, 0, 100 }, ws_win = { 0, 1, 0, 0.5 };
    unsigned char hdr[24];
    FILE *f;

    if (argc != 2)
        return 2;
    int major = -1, minor = -1, patch = -1;
    int version = gks3d_version(&major, &minor, &patch);
    if (version != GKS3D_VERSION || major != GKS3D_VERSION_MAJOR || minor != GKS3D_VERSION_MINOR ||
        patch != GKS3D_VERSION_PATCH || gks3d_version(NULL, NULL, NULL) != version) {
        fprintf(stderr, "consumer: library version %d (%d.%d.%d), headers %s (%d)\n", version,
                major, minor, patch, GKS3D_VERSION_STRING, GKS3D_VERSION);
        return 1;
    }
    printf("consumer: gks3d %s, library and headers agree\n", GKS3D_VERSION_STRING);
    remove(argv[1]);
    gset_err_hand(count_errors, NULL);
    gopen_gks(NULL, 0);
    gopen_ws(1, argv[1], GWS_TYPE_PNG);
    gactivate_ws(1);
    gset_ws_win(1, &ws_win);
    gset_ws_vp(1, &ws_vp);
    gset_fill_colr_ind(2);
    gfill_area(&tri_list);
    gdeactivate_ws(1);
    gclose_ws(1);
    gclose_gks();
    if (errors != 0)
        return 1;
    f = fopen(argv[1], "rb");
    if (f == NULL) {
        fprintf(stderr, "consumer: %s not written\n", argv[1]);
        return 1;
    }
    if (fread(hdr, 1, sizeof hdr, f) != sizeof hdr) {
        fclose(f);
        fprintf(stderr, "consumer: %s too short\n", argv[1]);
        return 1;
    }
    fclose(f);
    if (memcmp(hdr, sig, 8) != 0 || memcmp(hdr + 12, "IHDR", 4) != 0) {
        fprintf(stderr, "consumer: %s is not a PNG file\n", argv[1]);
        return 1;
    }
    if (be32(hdr + 16) != 200 || be32(hdr + 20) != 100) {
        fprintf(stderr, "consumer: %s is %lux%lu, expected 200x100\n", argv[1], be32(hdr + 16),
                be32(hdr + 20));
        return 1;
    }
    printf("consumer: %s OK (200x100 PNG)\n", argv[1]);
    return 0;
}
