/* SPDX-License-Identifier: MIT */
/*
 * mesh_view.c -- ray traces an OFF or PLY triangle mesh (ASCII, optionally gzip'd) through
 * the GKS-3D C binding.
 *
 *   mesh_view [--threads N] [--samples N] [--depth N] [--size WxH] [--ground] [--stats]
 *             [--ambient A] [--azimuth DEG] [--normals area|angle] mesh.off|mesh.ply[.gz] out.png
 *
 * Sampling: the workstation's default (rays at the pixel corners, each pixel the mean of its
 * four; cut-off 0.01) unless --samples N asks for N stratified samples per pixel.
 * Each face becomes one FILL AREA 3. The camera (scene_io_frame_view): y up, looking at the
 * bounding-box centre from the front, above and right, 40 degree field of view, the
 * bounding sphere filling the picture; --azimuth turns the camera (and the light) about the
 * vertical axis through the centre, counter-clockwise seen from above. One white positional light above, left of and behind
 * the camera (no attenuation), ambient 0.15 (--ambient). Material: warm light grey, Kd 0.8,
 * Ks 0.2 (highlight and a faint mirror reflection), exponent 30. --ground adds a grey square
 * floor (Kd 0.8, Ks 0.3) under the mesh, four bounding radii wide, which receives its
 * shadow and reflection. Background: a dark blue. Default size 512x512.
 * --stats prints the two statistics lines of nff_view.
 * --normals computes vertex normals from the faces (scene_io_vertex_normals: area- or
 * angle-weighted) and draws the faces WITH DATA, interior shading method NORMAL (smooth).
 */
#include "scene_gks.h"
#include "scene_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void usage(void)
{
    fprintf(stderr, "usage: mesh_view [--threads N] [--samples N] [--depth N] [--size WxH]\n"
                    "                 [--ground] [--stats] [--ambient A] [--azimuth DEG]\n"
                    "                 [--normals area|angle] mesh out.png\n"
                    "       mesh_view --help\n");
}

/* --help: what the program does, on stdout (exit status 0). */
static void help(void)
{
    printf("mesh_view -- ray traces a triangle mesh (OFF or PLY, ASCII, gzip'd too) through\n"
           "GKS-3D, lit from above and seen from the front, and writes the picture as a PNG.\n"
           "\n"
           "usage: mesh_view [options] mesh.off|mesh.ply[.gz] out.png\n"
           "  --threads N          tracer threads (0: all CPUs)\n"
           "  --samples N          N = m*m stratified samples per pixel (1..256) instead of\n"
           "                       rays at the pixel corners with adaptive cut-off\n"
           "  --depth N            maximum ray depth (eye ray = 1)\n"
           "  --size WxH           picture size in pixels (default 512x512)\n"
           "  --ground             a floor under the mesh that takes its shadow and reflection\n"
           "  --ambient A          ambient light intensity (0..1, default 0.15)\n"
           "  --azimuth DEG        turn the camera and the light about the vertical axis\n"
           "  --normals area|angle vertex normals from the faces, smooth shading\n"
           "  --stats              print the ray statistics and times\n"
           "  --help               this text\n"
           "Exit status: 0; 1 usage error; 2 unreadable mesh; 3 rendering error.\n");
}

int main(int argc, char **argv)
{
    scene_gks_options go = { .threads = -1, .ambient = 0.15 };
    scene_io_options io;
    scene_io_options_default(&io);
    io.warn = scene_gks_warn_stderr;
    int stats = 0, ground = 0, w = 512, h = 512, normals = -1;
    double azimuth = 0;
    const char *pos[2];
    int npos = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        int bad = 0;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            help();
            return 0;
        } else if (strcmp(a, "--stats") == 0) {
            stats = 1;
        } else if (strcmp(a, "--ground") == 0) {
            ground = 1;
        } else if (strcmp(a, "--normals") == 0 && v) {
            normals = strcmp(v, "area") == 0 ? 0 : strcmp(v, "angle") == 0 ? 1 : -2;
            bad = normals < 0, i++;
        } else if (strcmp(a, "--threads") == 0 && v) {
            bad = scene_gks_int_arg(v, 0, 256, &go.threads), i++;
        } else if (strcmp(a, "--samples") == 0 && v) {
            bad = scene_gks_int_arg(v, 1, 256, &go.samples) || !scene_gks_perfect_square(go.samples), i++;
        } else if (strcmp(a, "--depth") == 0 && v) {
            bad = scene_gks_int_arg(v, 1, 64, &go.depth), i++;
        } else if (strcmp(a, "--ambient") == 0 && v) {
            bad = scene_gks_real_arg(v, 0, 1, &go.ambient), i++;
        } else if (strcmp(a, "--azimuth") == 0 && v) {
            bad = scene_gks_real_arg(v, -360, 360, &azimuth), i++;
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
            fprintf(stderr, "mesh_view: bad argument near '%s'\n", a);
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
    if (scene_io_load(pos[0], SCENE_IO_AUTO, &io, &s, err, sizeof err) != SCENE_IO_OK) {
        fprintf(stderr, "mesh_view: %s\n", err);
        return 2;
    }
    if (normals >= 0) {
        if (scene_io_vertex_normals(&s, normals) != SCENE_IO_OK) {
            fprintf(stderr, "mesh_view: out of memory\n");
            scene_io_free(&s);
            return 2;
        }
        go.smooth = 1;
    }
    scene_io_view view;
    double lo[3], hi[3];
    if (!scene_io_bounds(&s, lo, hi) || scene_io_frame_view(&s, 40, w, h, &view)) {
        fprintf(stderr, "mesh_view: %s: no faces\n", pos[0]);
        scene_io_free(&s);
        return 2;
    }
    /* one material for the whole mesh (an NFF file keeps its own) */
    if (s.format != SCENE_IO_NFF)
        for (size_t i = 0; i < s.num_materials; i++)
            s.materials[i] = (scene_io_material){ { 0.85, 0.8, 0.72 }, 0.8, 0.2, 30, 0, 1 };

    double c[3], rad = 0;
    for (int a = 0; a < 3; a++) {
        c[a] = 0.5 * (lo[a] + hi[a]);
        rad += 0.25 * (hi[a] - lo[a]) * (hi[a] - lo[a]);
    }
    rad = sqrt(rad);
    if (!(rad > 0))
        rad = 1;
    /* light: above, left of and behind the camera */
    scene_io_light light = { { c[0] - 3 * rad, c[1] + 6 * rad, c[2] + 5 * rad }, { 1, 1, 1 }, 1 };
    /* azimuth: rotate camera and light about the y axis through the centre */
    double ca = cos(azimuth * 3.14159265358979323846 / 180),
           sa = sin(azimuth * 3.14159265358979323846 / 180);
    double *pts[2] = { view.from, light.pos };
    for (int k = 0; k < 2; k++) {
        double x = pts[k][0] - c[0], z = pts[k][2] - c[2];
        pts[k][0] = c[0] + ca * x + sa * z;
        pts[k][2] = c[2] - sa * x + ca * z;
    }

    /* optional floor: a square at the bottom of the box, counter-clockwise seen from above */
    double gy = lo[1] - 1e-3 * rad, e = 4 * rad;
    double gv[12] = { c[0] - e, gy, c[2] - e, c[0] - e, gy, c[2] + e,
                      c[0] + e, gy, c[2] + e, c[0] + e, gy, c[2] - e };
    int gn = 4;
    size_t gstart[2] = { 0, 4 };
    uint32_t gidx[4] = { 0, 1, 2, 3 }, gmat = 0;
    scene_io_material gm = { { 0.6, 0.62, 0.65 }, 0.8, 0.3, 50, 0, 1 };
    scene_io_scene floor = { .format = SCENE_IO_OFF, .num_materials = 1, .materials = &gm,
                             .num_vertices = 4, .vertices = gv, .num_polygons = 1,
                             .poly_nverts = &gn, .poly_start = gstart, .poly_verts = gidx,
                             .poly_material = &gmat };

    const scene_io_scene *list[2] = { &s, &floor };
    const double bg[3] = { 0.1, 0.12, 0.2 };
    scene_gks_result res;
    int rc = scene_gks_render(list, ground ? 2 : 1, &view, &light, 1, bg, pos[1], &go, &res,
                              err, sizeof err);
    scene_io_free(&s);
    if (rc) {
        fprintf(stderr, "mesh_view: %s\n", err);
        return 3;
    }
    if (stats) {
        if (!res.have_stats) {
            fprintf(stderr, "mesh_view: the workstation gave no ray statistics (GESC_RT_STATS)\n");
            return 3;
        }
        scene_gks_print_stats(&res);
    }
    return 0;
}
