/* SPDX-License-Identifier: MIT */
/*
 * fuzz_scene.c -- fuzz target for the scene readers (examples/c/scene_io.c: NFF, OFF,
 * PLY; untrusted files the viewers and benchmarks load). The first byte chooses the
 * format (auto-detection or one of the three) and the sphere/cone tessellation, the rest
 * is the file. Errors are expected; crashes, sanitizer reports, hangs and a scene that
 * breaks its own invariants (indices beyond the vertex array, offsets out of order) are
 * bugs. libFuzzer entry point (scripts/fuzz.sh), replayed over tests/fuzz/corpus_scene by
 * the ctest `fuzz_scene_replay` in every build.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include "scene_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    static const scene_io_format fmt[4] = { SCENE_IO_AUTO, SCENE_IO_NFF, SCENE_IO_OFF,
                                            SCENE_IO_PLY };
    scene_io_options o;
    scene_io_options_default(&o);
    o.tessellate = (data[0] >> 2) & 1 ? 3 + (data[0] >> 3) : 0; /* 3..34 segments */
    o.max_bytes = 1u << 20;
    scene_io_scene s;
    char err[128];
    int rc = scene_io_parse((const char *)data + 1, size - 1, "fuzz", fmt[data[0] & 3], &o,
                            &s, err, sizeof err);
    if (rc == SCENE_IO_OK) {
        if (s.num_polygons && (!s.poly_start || s.poly_start[0] != 0))
            abort();
        for (size_t i = 0; i < s.num_polygons; i++) {
            if (s.poly_start[i + 1] < s.poly_start[i] ||
                s.poly_start[i + 1] - s.poly_start[i] != (size_t)s.poly_nverts[i] ||
                s.poly_material[i] >= s.num_materials)
                abort();
            for (size_t k = s.poly_start[i]; k < s.poly_start[i + 1]; k++)
                if (s.poly_verts[k] >= s.num_vertices)
                    abort();
        }
        double lo[3], hi[3];
        scene_io_bounds(&s, lo, hi);
    }
    scene_io_free(&s);
    return 0;
}
