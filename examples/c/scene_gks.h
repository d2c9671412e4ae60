/* SPDX-License-Identifier: MIT */
/*
 * scene_gks.h -- draws scene_io scenes through the GKS-3D C binding on a ray-tracing PNG
 * workstation (shared by the examples nff_view and mesh_view).
 *
 * Mapping (all through the public C binding, include/gks.h):
 *   camera  VRP = from, VPN = from - at, VUP = up (EVALUATE VIEW ORIENTATION MATRIX 3);
 *           perspective with the projection reference point at the eye (VRC origin), view
 *           plane = front plane at n = -hither, back plane behind the farthest vertex; the
 *           view window spans the angle between the left and right image EDGES (exactly the
 *           outermost corner rays of the SPD procedure), square pixels, the aspect from the
 *           resolution (EVALUATE VIEW MAPPING MATRIX 3). Workstation window = projection
 *           viewport = [0,ax]x[0,ay] (the larger side 1), workstation viewport = res_x x res_y
 *           device pixels, so the PNG has exactly the scene's resolution. Normalization
 *           transformation 0 with clipping off: NDC3 = world coordinates.
 *   f       fill colour = r g b (a colour index per distinct colour, indices 8..255),
 *           AREA PROPERTIES front and back: ambient = diffuse = Kd, specular = Ks (the
 *           tracer also uses it as the mirror reflection weight), specular colour white,
 *           exponent = Shine, transparency = T, refraction index = index (0 -> 1).
 *           Kd, Ks, T and colours are clamped to [0,1] (with a warning).
 *   l       positional lights 2..64, no attenuation; colour as given (clamped to [0,1]).
 *   ambient light 1 (the predefined ambient entry) with the given intensity, on if > 0.
 *   b       colour index 0 (background: rays that miss everything).
 *   p, pp   FILL AREA 3 exactly as given (vertex normals are not used: flat shading).
 */
#ifndef GKS3D_SCENE_GKS_H
#define GKS3D_SCENE_GKS_H

#include "scene_io.h"

typedef struct scene_gks_options {
    int threads;      /* < 0: library default; 0: all CPUs; n: n threads */
    int spd;          /* 1: SPD procedure: corner rays, depth 5, no cut-off */
    int samples;      /* 0: default; else perfect square 1..256 */
    int depth;        /* 0: default (5 with spd); else 1..64 */
    double ambient;   /* ambient light intensity in [0,1] */
    int quiet;        /* 1: no warnings on stderr */
    int smooth;       /* 1: polygons whose vertices carry normals (NFF "pp", or normals a
                         mesh reader computed) as FILL AREA 3 WITH DATA, interior shading
                         method NORMAL (interpolated); 0: every polygon flat */
    int zbuffer;      /* 1: HLHSR mode z-buffer instead of ray tracing (a preview: local
                         shading only, no ray statistics) */
} scene_gks_options;

typedef struct scene_gks_result {
    int have_stats;           /* 1 when GESC_RT_STATS answered */
    long long stats[8];       /* eye, eye_hit, reflect, refract, shadow, cells, refs, prims */
    double build_s, render_s; /* from GESC_RT_STATS */
    double frame_s;           /* wall time of UPDATE WORKSTATION (the whole trace) */
    double draw_s;            /* wall time of the GKS calls before it */
} scene_gks_result;

/* Draws n scenes (polygons and materials of each) with the given view, lights and
 * background into the PNG file png_path (written at UPDATE WORKSTATION). Returns 0, or -1
 * with a message in err (bad view/resolution, too many lights, a GKS error). */
int scene_gks_render(const scene_io_scene *const *scenes, int n, const scene_io_view *view,
                     const scene_io_light *lights, size_t num_lights, const double bg[3],
                     const char *png_path, const scene_gks_options *opt,
                     scene_gks_result *res, char *err, size_t err_size);

/* Prints the two lines "rays eye=.. eye_hit=.. reflect=.. refract=.. shadow=.." and
 * "time draw=.. build=.. render=.. frame=.." (seconds) to stdout. */
void scene_gks_print_stats(const scene_gks_result *res);

/* Command-line helpers shared by the viewers. */
/* A scene_io warning callback printing to standard error. */
void scene_gks_warn_stderr(void *ctx, const char *msg);
/* Integer option value s in [lo, hi] into *v: 0, or -1 if s is not such an integer. */
int scene_gks_int_arg(const char *s, long lo, long hi, int *v);
/* Real option value s in [lo, hi] into *v: 0, or -1 if s is not such a number. */
int scene_gks_real_arg(const char *s, double lo, double hi, double *v);
/* Image size "WxH", each 1..8192, into *w, *h: 0, or -1 (then *w, *h unchanged). */
int scene_gks_size_arg(const char *s, int *w, int *h);
/* Whether n is a perfect square (samples per pixel are m x m strata). */
int scene_gks_perfect_square(int n);

#endif /* GKS3D_SCENE_GKS_H */
