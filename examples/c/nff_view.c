/* SPDX-License-Identifier: MIT */
/*
 * nff_view.c -- ray traces an NFF scene (Haines' Neutral File Format, the SPD scenes)
 * through the GKS-3D C binding.
 *
 *   nff_view [--threads N] [--spd] [--stats] [--samples N] [--depth N] [--ambient A]
 *            [--tessellate N] [--size WxH] [--smooth] [--zbuffer] scene.nff[.gz] out.png
 *
 * --threads N: tracer threads (0 = all CPUs); --samples N: N = m*m stratified samples per
 * pixel (1..256) instead of the workstation's default (rays at the pixel corners, each pixel
 * the mean of its four; adaptive cut-off 0.01); --depth N: maximum ray depth (eye ray = 1);
 * out.png: the PNG file name
 * (a name without ".png" gets it appended by the workstation).
 *
 * The NFF camera becomes the view orientation and mapping matrices (EVALUATE VIEW ORIENTATION
 * / MAPPING MATRIX 3), the PNG has the NFF resolution (--size overrides it). Mapping of the
 * NFF entities to GKS-3D (details in scene_gks.h):
 *   v  from/at/up -> VRP = from, VPN = from - at, VUP = up; angle -> view window between the
 *      left and right image edges (square pixels); hither -> front plane (= view plane);
 *      back plane just behind the farthest vertex; resolution -> workstation viewport
 *   b  background colour (colour index 0)
 *   l  positional light, no attenuation. A light without colour gets intensity
 *      1/sqrt(number of lights) (white), so that several lights do not saturate.
 *   f  r g b -> fill colour (diffuse colour); Kd -> ambient and diffuse coefficients;
 *      Ks -> specular coefficient (highlight and mirror reflection weight), white specular
 *      colour; Shine -> specular exponent; T -> transparency coefficient; index ->
 *      refraction index (0, used by SPD for opaque surfaces, -> 1). Front = back properties.
 *   p  FILL AREA 3 exactly as given (concave polygons included)
 *   pp FILL AREA 3 of the patch polygon (triangles in the SPD), flat; with --smooth FILL AREA
 *      3 WITH DATA with the patch's vertex normals, interior shading method NORMAL
 * --zbuffer: HLHSR mode z-buffer instead of ray tracing (local shading, no shadows)
 *   s, c  no such GKS primitives: skipped with a warning, or tessellated into FILL AREA 3s
 *      with --tessellate N (N segments around)
 * Ambient light: none by default (NFF has no ambient term; the SPD statistics do not depend
 * on it); --ambient A adds a white ambient light of intensity A.
 *
 * --spd follows the SPD testing procedure (tests/data/README.md): rays at the pixel
 * corners ((w+1)x(h+1) eye rays for a w x h image, i.e. 513x513 for the SPD's 512x512),
 * maximum depth 5, no adaptive cut-off; after the frame it prints
 *   rays eye=<n> eye_hit=<n> reflect=<n> refract=<n> shadow=<n>
 *   time draw=<s> build=<s> render=<s> frame=<s>
 * (draw: the GKS calls; build/render: the tracer's grid build and trace, from the ESCAPE
 * GESC_RT_STATS; frame: the whole UPDATE WORKSTATION). --stats prints them without --spd.
 * Exit status 0, 1 for usage errors, 2 for unreadable scenes, 3 for rendering errors.
 */
#include "scene_gks.h"
#include "scene_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    fprintf(stderr,
            "usage: nff_view [--threads N] [--spd] [--stats] [--samples N] [--depth N]\n"
            "                [--ambient A] [--tessellate N] [--size WxH] [--smooth] [--zbuffer]\n"
            "                scene.nff out.png\n"
            "       nff_view --help\n");
}

/* --help: what the program does, on stdout (exit status 0). */
static void help(void)
{
    printf("nff_view -- ray traces an NFF scene (Haines' Neutral File Format, e.g. the SPD\n"
           "scenes; gzip'd files too) through GKS-3D and writes the picture as a PNG file.\n"
           "\n"
           "usage: nff_view [options] scene.nff[.gz] out.png\n"
           "  --threads N     tracer threads (0: all CPUs; default: the workstation's)\n"
           "  --samples N     N = m*m stratified samples per pixel (1..256) instead of\n"
           "                  rays at the pixel corners with adaptive cut-off\n"
           "  --depth N       maximum ray depth (eye ray = 1)\n"
           "  --ambient A     add a white ambient light of intensity A (0..1)\n"
           "  --tessellate N  draw spheres and cones as FILL AREA 3 with N segments around\n"
           "                  (otherwise skipped with a warning)\n"
           "  --size WxH      picture size in pixels (default: the scene's resolution)\n"
           "  --smooth        patches with vertex normals, smooth shading\n"
           "  --zbuffer       z-buffer instead of ray tracing (no shadows)\n"
           "  --spd           the SPD testing procedure (corner rays, depth 5, no cut-off)\n"
           "                  and the ray statistics\n"
           "  --stats         print the ray statistics and times\n"
           "  --help          this text\n"
           "Exit status: 0; 1 usage error; 2 unreadable scene; 3 rendering error.\n");
}

int main(int argc, char **argv)
{
    scene_gks_options go = { .threads = -1 };
    scene_io_options io;
    scene_io_options_default(&io);
    io.warn = scene_gks_warn_stderr;
    int stats = 0, w = 0, h = 0;
    const char *pos[2];
    int npos = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int bad = 0;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help();
            return 0;
        } else if (strcmp(a, "--spd") == 0) {
            go.spd = stats = 1;
        } else if (strcmp(a, "--stats") == 0) {
            stats = 1;
        } else if (strcmp(a, "--threads") == 0 && v) {
            bad = scene_gks_int_arg(v, 0, 256, &go.threads), i++;
        } else if (strcmp(a, "--samples") == 0 && v) {
            bad = scene_gks_int_arg(v, 1, 256, &go.samples) || !scene_gks_perfect_square(go.samples), i++;
        } else if (strcmp(a, "--depth") == 0 && v) {
            bad = scene_gks_int_arg(v, 1, 64, &go.depth), i++;
        } else if (strcmp(a, "--tessellate") == 0 && v) {
            bad = scene_gks_int_arg(v, 3, 1024, &io.tessellate), i++;
        } else if (strcmp(a, "--smooth") == 0) {
            go.smooth = 1;
        } else if (strcmp(a, "--zbuffer") == 0) {
            go.zbuffer = 1;
        } else if (strcmp(a, "--ambient") == 0 && v) {
            bad = scene_gks_real_arg(v, 0, 1, &go.ambient), i++;
        } else if (strcmp(a, "--size") == 0 && v) {
            bad = scene_gks_size_arg(v, &w, &h), i++;
        } else if (a[0] == '-' && a[1] == '-') {
            usage();
            return 1;
        } else if (npos < 2) {
            pos[npos++] = a;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "nff_view: bad argument near '%s'\n", a);
            usage();
            return 1;
        }
    }
    if (npos != 2) {
        usage();
        return 1;
    }

    scene_io_scene s;
    char err[512];
    if (scene_io_load(pos[0], SCENE_IO_NFF, &io, &s, err, sizeof err) != SCENE_IO_OK) {
        fprintf(stderr, "nff_view: %s\n", err);
        return 2;
    }
    if (!s.view.present) {
        fprintf(stderr, "nff_view: %s: no 'v' (view) block\n", pos[0]);
        scene_io_free(&s);
        return 2;
    }
    if (w > 0) {
        s.view.res_x = w;
        s.view.res_y = h;
    }
    /* lights without colour share the light: 1/sqrt(n) each */
    double li = s.num_lights ? 1 / sqrt((double)s.num_lights) : 1;
    for (size_t i = 0; i < s.num_lights; i++)
        if (!s.lights[i].has_color)
            s.lights[i].color[0] = s.lights[i].color[1] = s.lights[i].color[2] = li;

    const scene_io_scene *list[1] = { &s };
    scene_gks_result res;
    int rc = scene_gks_render(list, 1, &s.view, s.lights, s.num_lights, s.background, pos[1],
                              &go, &res, err, sizeof err);
    scene_io_free(&s);
    if (rc) {
        fprintf(stderr, "nff_view: %s\n", err);
        return 3;
    }
    if (stats) {
        if (!res.have_stats) {
            fprintf(stderr, "nff_view: the workstation gave no ray statistics (GESC_RT_STATS)\n");
            return 3;
        }
        scene_gks_print_stats(&res);
    }
    return 0;
}
