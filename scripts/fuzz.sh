#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# fuzz.sh -- fuzz the untrusted-input readers with libFuzzer for a fixed budget.
#   scripts/fuzz.sh [seconds per target, default 60]
# Installs clang and its libFuzzer runtime from Debian if missing, builds each target with
# -fsanitize=fuzzer,address,undefined (the library compiled once for all of them), runs each
# on a copy of the committed corpus (tests/fuzz/corpus_*), two targets at a time, and on a
# crash copies the input into the corpus (so the replay test `fuzz_*_replay` keeps it as a
# regression test) and fails.
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
# rt_mpi.c (MPI), ws_cairo.c and ws_x11.c (cairo, X11) are optional drivers built only when
# found (src/rt, src/c/ws CMake); the fuzz builds go without them, as the driver list allows.
mapfile -t lib_srcs < <(find src/c src/rt -name '*.c' -not -name rt_mpi.c -not -name ws_cairo.c -not -name ws_x11.c | sort)
# The library is compiled once (two compilers at a time, one object per source) and linked
# into each target that runs it: the instrumentation (-fsanitize=fuzzer on an object is the
# coverage only; the fuzzer's main comes at the link) is the same for all of them.
# Jobs in the background, two at a time (the machine's two cores): at_most_two before each
# start, wait_all at the end; a job that fails stops the script when waited for (set -e), and
# as the objects and targets of an earlier run are removed first, one whose failure came
# between two waits leaves a file missing that the next link or run needs.
at_most_two() { while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n; done; }
wait_all() { while [ -n "$(jobs -rp)" ]; do wait -n; done; }
rm -rf "$out/obj" "$out"/fuzz_*
mkdir -p "$out/obj"
obj_of() { echo "$out/obj/$(echo "${1%.c}" | tr / _).o"; } # src/c/x/y.c -> obj/src_c_x_y.o
objs=()
for src in "${lib_srcs[@]}"; do objs+=("$(obj_of "$src")"); done
# Largest sources first: the tracer's rt_trace.c alone takes most of a minute here, and
# compiled last (in name order) it kept one core busy while the other had nothing to do.
mapfile -t by_size < <(for src in "${lib_srcs[@]}"; do echo "$(wc -c < "$src") $src"; done |
                       sort -k1,1nr -k2 | cut -d' ' -f2-)
for src in "${by_size[@]}"; do
    at_most_two
    clang "${flags[@]}" -Isrc/rt -c "$src" -o "$(obj_of "$src")" &
done
wait_all
clang "${flags[@]}" tests/fuzz/fuzz_gksm.c "$(obj_of src/c/ws/mf/gks_mf_codec.c)" \
    "$(obj_of src/c/base/gks_alloc.c)" -lm -o "$out/fuzz_gksm"
# The MI workstation target runs the whole library (reader, interpreter, pipeline); the state
# machine random call sequences through it; the input target the script reader and the measure
# process behind every input function; the render target gks3d-render's entry
# (src/tools/gks3d_render.c, included by the target) on metafiles: its corpus is the MI
# target's (corpus_mi), copied to corpus_render below.
for t in mi state input render; do
    at_most_two
    clang "${flags[@]}" -Isrc/rt "tests/fuzz/fuzz_$t.c" "${objs[@]}" -lpng -lpthread -lm \
        -o "$out/fuzz_$t" &
done
# The scene readers (NFF, OFF, PLY) of the examples and benchmarks.
clang "${flags[@]}" -Iexamples/c tests/fuzz/fuzz_scene.c examples/c/scene_io.c -lz -lm \
    -o "$out/fuzz_scene"
wait_all

# Each target fuzzes for the budget in a scratch folder of its own (fuzz_state's workstations
# write files relative to it), two at a time (the machine's two cores); a crash's input is
# copied into the corpus, so that the replay test `fuzz_*_replay` keeps it as a regression test.
fuzz_one() {
    local target=$1 work="$out/corpus_$1" src="tests/fuzz/corpus_$1"
    [ "$target" = render ] && src=tests/fuzz/corpus_mi # the metafile corpus
    rm -rf "$work" "$out/$target.status" "$out/$target-"* # and an earlier run's crash inputs
    cp -r "$src" "$work"
    mkdir -p "$out/run_$target"
    if (cd "$out/run_$target" && "../fuzz_$target" -max_total_time="$budget" -max_len=65536 \
            -timeout=10 -rss_limit_mb=2048 -artifact_prefix="../$target-" "../corpus_$target" \
            2>"../$target.log"); then
        echo ok > "$out/$target.status"
    else
        echo failed > "$out/$target.status"
    fi
}
targets=(gksm mi state input scene render)
for target in "${targets[@]}"; do
    at_most_two # fuzz_one returns 0: its result is in $out/$target.status
    echo "fuzz: $target for ${budget}s"
    fuzz_one "$target" &
done
wait_all
status=0
for target in "${targets[@]}"; do
    src="tests/fuzz/corpus_$target"
    [ "$target" = render ] && src=tests/fuzz/corpus_mi
    if [ "$(cat "$out/$target.status" 2>/dev/null)" = ok ]; then
        echo "fuzz: $target: $(grep -E '^#[0-9]+.*(DONE|pulse)' "$out/$target.log" | tail -1)"
        continue
    fi
    echo "fuzz: $target FAILED"
    tail -40 "$out/$target.log"
    for a in "$out/$target-"*; do
        [ -e "$a" ] || continue
        cp "$a" "$src/regress-$(basename "$a")"
        echo "fuzz: kept $a as $src/regress-$(basename "$a")"
    done
    status=1
done
exit $status
