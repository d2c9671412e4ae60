#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# fuzz.sh -- fuzz the untrusted-input readers with libFuzzer for a fixed budget.
#   scripts/fuzz.sh [seconds per target, default 60]
# Installs clang and its libFuzzer runtime from Debian if missing, builds each target with
# -fsanitize=fuzzer,address,undefined, runs it on a copy of the committed corpus
# (tests/fuzz/corpus_*), and on a crash copies the input into the corpus (so the replay
# test `fuzz_*_replay` keeps it as a regression test) and fails.
set -euo pipefail
cd "$(dirname "$0")/.."
budget=${1:-60}

need=()
for p in clang libclang-rt-14-dev; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || need+=("$p")
done
if [ ${#need[@]} -gt 0 ]; then
    sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    export DEBIAN_FRONTEND=noninteractive
    "${sudo[@]}" apt-get update -q
    "${sudo[@]}" apt-get install -y -q --no-install-recommends "${need[@]}"
fi

out=build-fuzz
mkdir -p "$out/include"
# gks.h includes the version header that CMake generates; make it the same way here.
version=$(sed -n 's/^project(gks3d VERSION \([0-9]*\)\.\([0-9]*\)\.\([0-9]*\).*/\1 \2 \3/p' CMakeLists.txt)
read -r vmajor vminor vpatch <<<"$version"
sed -e "s/@PROJECT_VERSION_MAJOR@/$vmajor/" -e "s/@PROJECT_VERSION_MINOR@/$vminor/" \
    -e "s/@PROJECT_VERSION_PATCH@/$vpatch/" -e "s/@PROJECT_VERSION@/$vmajor.$vminor.$vpatch/" \
    include/gks3d_version.h.in >"$out/include/gks3d_version.h"
# Every folder of src/c is a module with its headers next to its sources (src/c/CMakeLists.txt).
incs=()
while IFS= read -r d; do incs+=("-I$d"); done < <(find src/c -type d | sort)
# float-cast-overflow and pointer-overflow named explicitly: gcc's UBSan leaves them out
# (an out-of-range double -> int cast, NULL + 0), clang checks them when asked.
flags=(-g -O1 -fsanitize=fuzzer,address,undefined,float-cast-overflow,pointer-overflow
       -fno-sanitize-recover=undefined,float-cast-overflow,pointer-overflow
       -DGKS3D_BUILDING -DGKS_FAULT_INJECTION -D_POSIX_C_SOURCE=200809L "${incs[@]}" -Iinclude
       -I"$out/include") # GKS_FAULT_INJECTION: the test hooks (fuzz_state fails allocations)
clang "${flags[@]}" tests/fuzz/fuzz_gksm.c src/c/ws/mf/gks_mf_codec.c src/c/base/gks_alloc.c \
    -lm -o "$out/fuzz_gksm"
# The MI workstation target runs the whole library (reader, interpreter, pipeline).
# rt_mpi.c (MPI), ws_cairo.c and ws_x11.c (cairo, X11) are optional drivers built only when
# found (src/rt, src/c/ws CMake); the fuzz builds go without them, as the driver list allows.
mapfile -t lib_srcs < <(find src/c src/rt -name '*.c' -not -name rt_mpi.c -not -name ws_cairo.c -not -name ws_x11.c | sort)
clang "${flags[@]}" -Isrc/rt tests/fuzz/fuzz_mi.c "${lib_srcs[@]}" -lpng -lpthread -lm \
    -o "$out/fuzz_mi"
# The state machine: random call sequences through the whole library.
clang "${flags[@]}" -Isrc/rt tests/fuzz/fuzz_state.c "${lib_srcs[@]}" -lpng -lpthread -lm \
    -o "$out/fuzz_state"
# Input scripts: the script reader and the measure process behind every input function.
clang "${flags[@]}" -Isrc/rt tests/fuzz/fuzz_input.c "${lib_srcs[@]}" -lpng -lpthread -lm \
    -o "$out/fuzz_input"
# gks3d-render's entry (src/tools/gks3d_render.c, included by the target) on metafiles:
# its corpus is the MI target's (corpus_mi), copied to corpus_render below.
clang "${flags[@]}" -Isrc/rt tests/fuzz/fuzz_render.c "${lib_srcs[@]}" -lpng -lpthread -lm \
    -o "$out/fuzz_render"
# The scene readers (NFF, OFF, PLY) of the examples and benchmarks.
clang "${flags[@]}" -Iexamples/c tests/fuzz/fuzz_scene.c examples/c/scene_io.c -lz -lm \
    -o "$out/fuzz_scene"

status=0
for target in gksm mi state input scene render; do
    work="$out/corpus_$target"
    src="tests/fuzz/corpus_$target"
    [ "$target" = render ] && src=tests/fuzz/corpus_mi # the metafile corpus
    rm -rf "$work"
    cp -r "$src" "$work"
    echo "fuzz: $target for ${budget}s"
    # run in a scratch folder: fuzz_state's workstations write files relative to it
    mkdir -p "$out/run_$target"
    if ! (cd "$out/run_$target" && "../fuzz_$target" -max_total_time="$budget" -max_len=65536 \
            -timeout=10 -rss_limit_mb=2048 -artifact_prefix="../$target-" "../corpus_$target" \
            2>"../$target.log"); then
        tail -40 "$out/$target.log"
        for a in "$out/$target-"*; do
            [ -e "$a" ] || continue
            cp "$a" "$src/regress-$(basename "$a")"
            echo "fuzz: kept $a as $src/regress-$(basename "$a")"
        done
        status=1
    else
        grep -E '^#[0-9]+.*(DONE|pulse)' "$out/$target.log" | tail -1
    fi
done
exit $status
