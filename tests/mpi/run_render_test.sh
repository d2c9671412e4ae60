#!/bin/sh
# SPDX-License-Identifier: MIT
# run_render_test.sh MPIEXEC RENDER FIG3 WORKDIR -- gks3d-render under mpirun -n 2 (issue
# 42; docs/MPI.md): each rank in its own directory WORKDIR/<case>/r<rank>, compared with
# the one-process run in WORKDIR/one:
#   1. tiles mode: frame 3 of the recorded fig3, ray traced at 120 pixels with 4 samples:
#      rank 0 writes out.png byte-identical to the one-process run, rank 1 writes none
#      and traced tiles of it;
#   2. frames mode (GKS3D_MPI_FRAMES=1) with --name 'f-%d.png' --frames 2,3: frame 2 by
#      rank 0 as f-2.png, frame 3 by rank 1 as f-3.png (the rank renames only what it
#      wrote), each identical to the one-process run's.
set -u
mpiexec=$1 render=$2 fig3=$3 work=$4
fail=0
bad() { echo "FAIL: $*"; fail=1; }
rm -rf "$work"
mkdir -p "$work/one"
opts="--oversubscribe -n 2"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
export GKS3D_MPI_REPORT=1
args="--mode raytrace --size 120 --samples 4 --quiet"
(cd "$work/one" && GKS3D_RECORD=../fig3.gksm "$fig3" 80 > fig3.out 2>&1 &&
    "$render" ../fig3.gksm -o out.png --frames 3 $args &&
    "$render" ../fig3.gksm --name 'f-%d.png' --frames 2,3 $args) ||
    { echo "FAIL: one-process runs"; exit 1; }

# mpirun_case CASE ARGS...: each rank runs gks3d-render ARGS in $work/CASE/r<rank>
mpirun_case() {
    c=$1
    shift
    mkdir -p "$work/$c"
    timeout 120 "$mpiexec" $opts sh -c \
        'd=$0/r$OMPI_COMM_WORLD_RANK; mkdir -p "$d" && cd "$d" && exec "$@"' \
        "$work/$c" "$render" "$@" > "$work/$c.out" 2> "$work/$c.err"
    rc=$?
    [ $rc = 124 ] && bad "$c: mpirun did not end within 120 s"
    [ $rc = 0 ] || { bad "$c: exit status $rc"; cat "$work/$c.err"; }
}
same() { # same FILE DIR: DIR/FILE equals one/FILE byte for byte
    if [ ! -f "$work/$2/$1" ]; then bad "$2/$1 missing"
    elif ! cmp -s "$work/one/$1" "$work/$2/$1"; then bad "$2/$1 differs from the one-process run"
    else echo "ok: $2/$1 identical"; fi
}

mpirun_case tiles ../../fig3.gksm -o out.png --frames 3 $args
same out.png tiles/r0
[ "$(ls "$work/tiles/r1" | grep -c '\.png$')" = 0 ] && echo "ok: rank 1 wrote no picture" ||
    bad "tiles: rank 1 wrote pictures"
grep -Eq "rank 1 of 2: frame [0-9]+: [1-9][0-9]* of" "$work/tiles.err" &&
    echo "ok: rank 1 traced tiles" || bad "tiles: rank 1 traced no tiles"

GKS3D_MPI_FRAMES=1 mpirun_case frames ../../fig3.gksm --name 'f-%d.png' --frames 2,3 $args
same f-2.png frames/r0
same f-3.png frames/r1
[ "$(ls "$work/frames/r0" "$work/frames/r1" | grep -c '\.png$')" = 2 ] ||
    bad "frames: other files written: $(ls "$work/frames/r0" "$work/frames/r1")"
[ $fail = 0 ] && echo "gks3d-render under mpirun: all cases passed"
exit $fail
