/* SPDX-License-Identifier: MIT */
/*
 * rt_bench -- loads an NFF (SPD) or OFF scene, renders it with gksrt and reports frame time
 * and Mrays/s.
 *   rt_bench FILE [-s SIZE] [-t THREADS] [-corner] [-depth D] [-grid F] [-brute] [-primary]
 *            [-o out.ppm] [-reps N] [-submin N] [-subf F] [-nosub] [-vrcgrid] [-nolbuf] [-progress]
 *            [-leafmin N]
 * NFF: the file's view; SPD procedure with -corner (SIZE+1)^2 eye rays, depth 5.
 * OFF: camera looking at the mesh from +z (of its box centre), one directional light.
 * -primary: primary rays only (rt_intersect on the camera's rays), reports Mrays/s.
 */
#include "gksrt.h"
#include "rt_testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* CPU time of the process: robust against other load on a shared machine (1 thread) */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double wall(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: rt_bench FILE [-s N] [-t T] [-corner] [-depth D] [-grid F] [-brute] [-primary] [-o f.ppm] [-reps N]\n");
        return 2;
    }
    const char *path = argv[1], *out = NULL;
    int size = 512, threads = 1, corner = 0, depth = 5, brute = 0, primary = 0, reps = 1;
    double gridf = 0.0, subf = 0.0;
    int submin = 0, leafmin = 0, nosub = 0, progress = 0, frame = 0, nolbuf = 0;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "-s") && i + 1 < argc) size = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-t") && i + 1 < argc) threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-corner")) corner = 1;
        else if (!strcmp(argv[i], "-depth") && i + 1 < argc) depth = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-grid") && i + 1 < argc) gridf = atof(argv[++i]);
        else if (!strcmp(argv[i], "-brute")) brute = 1;
        else if (!strcmp(argv[i], "-submin") && i + 1 < argc) submin = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-subf") && i + 1 < argc) subf = atof(argv[++i]);
        else if (!strcmp(argv[i], "-leafmin") && i + 1 < argc) leafmin = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-nosub")) nosub = 1;
        else if (!strcmp(argv[i], "-nolbuf")) nolbuf = 1;
        else if (!strcmp(argv[i], "-vrcgrid")) frame = 1;
        else if (!strcmp(argv[i], "-progress")) progress = 1;
        else if (!strcmp(argv[i], "-primary")) primary = 1;
        else if (!strcmp(argv[i], "-o") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "-reps") && i + 1 < argc) reps = atoi(argv[++i]);
    }
    rtu_mesh m;
    double bb[6];
    const double wr0 = wall(); /* whole frame: reading, scene, commit, first render */
    if (rtu_load_scene_vrc(path, &m, bb) != 0) {
        fprintf(stderr, "cannot load %s\n", path);
        return 1;
    }
    rt_scene *sc = rt_scene_new();
    rt_surface s;
    rt_surface_default(&s);
    s.ka = 0.1;
    s.kd = 0.8;
    int sid = rt_scene_add_surface(sc, &s);
    if (!m.nlights) {
        rt_light l = {.type = RT_LIGHT_DIRECTIONAL, .color = {1, 1, 1}, .direction = {-0.3, -0.5, -1}};
        rt_light a = {.type = RT_LIGHT_AMBIENT, .color = {1, 1, 1}};
        rt_scene_add_light(sc, &l);
        rt_scene_add_light(sc, &a);
    }
    if (rtu_mesh_add(&m, sc, sid) != 0) {
        fprintf(stderr, "scene build failed\n");
        return 1;
    }
    rt_build_options bo = {.grid_factor = gridf, .brute_force = brute, .brute_threshold = -1,
                           .no_subgrids = nosub, .sub_min = submin, .sub_factor = subf,
                           .grid_frame = frame, .threads = threads, .leaf_min = leafmin};
    const double wr1 = wall();
    double t0 = now();
    if (rt_scene_commit(sc, &bo) != RT_OK) {
        fprintf(stderr, "commit failed\n");
        return 1;
    }
    double tb = now() - t0;
    const double wr2 = wall();
    rt_grid_info gi;
    if (rt_scene_grid_info(sc, &gi) == RT_OK)
        printf("grid %dx%dx%d%s: %llu cells (%llu empty), %llu refs, %llu subgrids with %llu cells "
               "and %llu refs, max refs per leaf %llu, non-empty volume %.3f, hash %016llx\n",
               gi.res[0], gi.res[1], gi.res[2], gi.rotated ? " (rotated frame)" : "",
               (unsigned long long)gi.cells, (unsigned long long)gi.empty_cells,
               (unsigned long long)gi.refs, (unsigned long long)gi.subgrids,
               (unsigned long long)gi.subcells, (unsigned long long)gi.subrefs,
               (unsigned long long)gi.max_leaf_refs, gi.volume_fill, (unsigned long long)gi.hash);
    if (rt_scene_grid_info(sc, &gi) == RT_OK && gi.res[0] > 0)
        printf("float leaves %llu with %llu lanes, kernel %s\n", (unsigned long long)gi.float_leaves,
               (unsigned long long)gi.float_lanes, gi.simd);
    rtu_view v;
    rtu_nff_view(&m, bb, &v);
    double vm[4][4];
    rtu_view_matrix(&v, vm);
    rt_camera cam;
    int rc = rt_camera_from_view(&cam, vm, v.vp, size, size);
    if (rc != RT_OK) {
        fprintf(stderr, "camera failed %d\n", rc);
        return 1;
    }
    rt_render_options ro;
    rt_render_options_default(&ro);
    ro.threads = threads;
    ro.corner_rays = corner;
    ro.cutoff = 0.0; /* the SPD procedure: no adaptive cut-off */
    ro.max_depth = depth;
    ro.light_buffers = !nolbuf;
    ro.progress = progress;
    memcpy(ro.background, m.bg, sizeof ro.background);
    float *rgb = malloc((size_t)size * size * 3 * sizeof(float));
    rt_stats st;
    memset(&st, 0, sizeof st);
    if (primary) {
        size_t nr = (size_t)size * size;
        rt_ray *rays = malloc(nr * sizeof *rays);
        rt_hit *hits = malloc(nr * sizeof *hits);
        for (int y = 0; y < size; y++)
            for (int x = 0; x < size; x++)
                rt_camera_ray(&cam, x + 0.5, y + 0.5, &rays[(size_t)y * size + x]);
        double best = 1e30;
        for (int r = 0; r < reps; r++) {
            t0 = now();
            rt_intersect(sc, nr, rays, hits);
            double t = now() - t0;
            if (t < best) best = t;
        }
        size_t nh = 0;
        for (size_t k = 0; k < nr; k++) nh += hits[k].prim >= 0;
        printf("%s: %zu prims kept, build %.3f s; primary rays %zu, hits %zu: %.3f s, %.2f Mrays/s\n",
               path, (size_t)m.np, tb, nr, nh, best, nr / best * 1e-6);
        free(rays);
        free(hits);
    } else {
        double best = 1e30, bestw = 1e30, first = 0.0;
        for (int r = 0; r < reps; r++) {
            t0 = now();
            double w0 = wall();
            rt_render(sc, &cam, &ro, rgb, &st);
            double t = now() - t0, tw = wall() - w0;
            if (r == 0)
                first = w0 + tw - wr0;
            if (t < best) best = t;
            if (tw < bestw) bestw = tw;
        }
        printf("whole frame %.3f s wall (%d threads, cold: first render): read + scene %.3f s, "
               "commit %.3f s, render %.3f s\n", first, threads, wr1 - wr0, wr2 - wr1,
               first - (wr2 - wr0));
        uint64_t tot = st.eye_rays + st.shadow_rays + st.reflection_rays + st.refraction_rays;
        printf("%s: prims %llu, build %.3f s, grid cells %llu refs %llu (%.2f/prim), mem %.1f MB\n"
               "frame %.3f s CPU, %.3f s wall (%d threads%s): eye %llu hits %llu shadow %llu refl %llu refr %llu, %.2f Mrays/s\n",
               path, (unsigned long long)st.prims, tb, (unsigned long long)st.grid_cells,
               (unsigned long long)st.grid_refs, st.prims ? (double)st.grid_refs / st.prims : 0.0,
               st.memory_bytes / 1e6, best, bestw, threads, corner ? ", corner rays" : "",
               (unsigned long long)st.eye_rays, (unsigned long long)st.eye_hits,
               (unsigned long long)st.shadow_rays, (unsigned long long)st.reflection_rays,
               (unsigned long long)st.refraction_rays, tot / bestw * 1e-6);
        printf("shadow rays: %llu from light buffers, %llu walked the grid, %llu answered "
               "otherwise (blocker cache, trivially lit)\n",
               (unsigned long long)st.shadow_lbuf, (unsigned long long)st.shadow_walks,
               (unsigned long long)(st.shadow_rays - st.shadow_lbuf - st.shadow_walks));
        printf("reflection rays: %llu from mirror buffers\n", (unsigned long long)st.reflection_mirror);
        if (out) {
            FILE *f = fopen(out, "wb");
            if (f) {
                fprintf(f, "P6\n%d %d\n255\n", size, size);
                for (size_t k = 0; k < (size_t)size * size * 3; k++) {
                    float x = rgb[k];
                    int b = x <= 0 ? 0 : x >= 1 ? 255 : (int)(x * 255 + 0.5);
                    fputc(b, f);
                }
                fclose(f);
            }
        }
    }
    free(rgb);
    rt_scene_free(sc);
    rtu_mesh_free(&m);
    return 0;
}
