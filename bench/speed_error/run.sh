#!/bin/sh
# SPDX-License-Identifier: MIT
# run.sh -- speed against error of the gksrt render settings (issue 7): renders the
# references and all settings for SPD gears, SPD mount and the bunny mesh (with a mirror
# weight ks 0.3 so that depth and cut-off matter), writes docs/speed_error.csv, the log-log
# plot docs/speed_error.png (gnuplot) and the log docs/bench/speed_error.txt; then the
# tessellation rows (tess_error: a sphere and the surface example's function at 8^2 ... 256^2
# quads, flat and with interpolated normals), appended to the CSV, the log and the plot.
#   bench/speed_error/run.sh [--no-build] [--quick] [BUILD_DIR]
# --quick: 64x64, 4x4-spp reference, 1 repetition (a smoke test; writes into BUILD_DIR only).
# Takes about 10 minutes (pinned to one core, see below), most of it the 256x256, 16x16-spp
# references, which are kept in BUILD_DIR/speed_error-ref (delete it to render them again).
set -eu

SRC=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=""
DO_BUILD=1
QUICK=0
for a in "$@"; do
    case "$a" in
    --no-build) DO_BUILD=0 ;;
    --quick) QUICK=1 ;;
    -h | --help)
        sed -n '3,14p' "$0"
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

if [ "$DO_BUILD" -eq 1 ]; then
    cmake -S "$SRC" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DGKS_BUILD_BENCHMARKS=ON >/dev/null
    cmake --build "$BUILD" --target speed_error tess_error -j2 >/dev/null
fi
EXE="$BUILD/bench/speed_error/speed_error"
[ -x "$EXE" ] || {
    echo "run.sh: $EXE missing" >&2
    exit 1
}

SCENES="gears=$DATA/spd/gears.nff mount=$DATA/spd/mount-tessellated.nff bunny=$DATA/meshes/bunny00.off:0.3"
if [ "$QUICK" -eq 1 ]; then
    DOCS="$BUILD/speed_error-quick"
    mkdir -p "$DOCS/bench"
    ARGS="-s 64 -ref-spp 16 -reps 1"
else
    DOCS="$SRC/docs"
    mkdir -p "$DOCS/bench"
    ARGS="-s 256 -ref-spp 256 -ref-depth 8 -ref-threads 2 -reps 5 -ref-cache $BUILD/speed_error-ref"
    mkdir -p "$BUILD/speed_error-ref"
fi
CSV="$DOCS/speed_error.csv"
# Timings are of one thread: pinned to one core (the last), so that the process does not move
# between the cores of a shared VM, which at times run it at different speeds (the same
# settings then timed 25 % apart within one run). References not yet cached render slower so.
PIN=""
if command -v taskset >/dev/null 2>&1; then
    PIN="taskset -c $(($(nproc) - 1))"
fi
{
    echo "# speed_error (bench/speed_error/run.sh), $(date -u '+%Y-%m-%d %H:%M UTC'), $(uname -m)," \
         "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores shared with other jobs"
    # shellcheck disable=SC2086 # argument lists split on purpose
    $PIN "$EXE" $ARGS -csv "$CSV" $SCENES
} | tee "$DOCS/bench/speed_error.txt"
TESS="$BUILD/bench/speed_error/tess_error"
if [ "$QUICK" -eq 1 ]; then
    TARGS="-s 64 -ref 256 -reps 1"
else
    TARGS="-s 256 -ref 1024 -reps 5"
fi
# shellcheck disable=SC2086 # argument lists split on purpose
$PIN "$TESS" $TARGS -csv "$CSV" | tee -a "$DOCS/bench/speed_error.txt"

if command -v gnuplot >/dev/null 2>&1; then
    gnuplot -e "csv='$CSV'; out='$DOCS/speed_error.png'; scenes='gears mount bunny'; tscenes='sphere-tess surface-tess'" \
        "$SRC/bench/speed_error/plot.gp"
    echo "plot: $DOCS/speed_error.png"
else
    echo "run.sh: gnuplot not found (scripts/setup-bench.sh installs it); no plot" >&2
fi
