#!/bin/sh
# SPDX-License-Identifier: MIT
# run_mpi_test.sh MPIEXEC FIG3 FRAMES WORKDIR -- the MPI runs of docs/MPI.md, each rank in
# its own directory WORKDIR/<case>/r<rank>, compared with the one-process run in
# WORKDIR/one:
#   1. fig3 (F77) under mpirun -n 2: rank 0 writes every picture byte-identical to the
#      one-process run, rank 1 writes none and traced tiles of the ray-traced frame;
#   2. the animation (4 ray-traced frames), tiles mode: the same, frame by frame;
#   3. the animation with GKS3D_MPI_FRAMES=1: frames 1, 3 written by rank 0, 2, 4 by
#      rank 1, each identical;
#   4. rank 1 does not open its workstation: rank 0 reports GKS error 305 in its error file
#      and a message on stderr after GKS3D_MPI_TIMEOUT (3 s) and still writes identical
#      frames; the run ends (no hang; at most 120 s).
set -u
mpiexec=$1 fig3=$2 frames=$3 work=$4
fail=0
bad() { echo "FAIL: $*"; fail=1; }
rm -rf "$work"
mkdir -p "$work/one"
opts="--oversubscribe -n 2"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
export GKS3D_MPI_REPORT=1

(cd "$work/one" && "$fig3" > fig3.out 2>&1 && "$frames" > frames.out 2>&1) ||
    { echo "FAIL: one-process runs"; exit 1; }

# mpirun CASE PROGRAM: each rank runs PROGRAM in $work/CASE/r<rank>; stderr in CASE.err
mpirun_case() {
    mkdir -p "$work/$1"
    timeout 120 "$mpiexec" $opts sh -c \
        'd=$0/r$OMPI_COMM_WORLD_RANK; mkdir -p "$d" && cd "$d" && exec "$1"' \
        "$work/$1" "$2" > "$work/$1.out" 2> "$work/$1.err"
    rc=$?
    [ $rc = 124 ] && bad "$1: mpirun did not end within 120 s"
    return $rc
}
# same FILE DIR: DIR/FILE exists and equals one/FILE byte for byte
same() {
    if [ ! -f "$work/$2/$1" ]; then bad "$2/$1 missing"
    elif ! cmp -s "$work/one/$1" "$work/$2/$1"; then bad "$2/$1 differs from the one-process run"
    else echo "ok: $2/$1 identical"; fi
}
nopng() {
    n=$(ls "$work/$1" 2>/dev/null | grep -c '\.png$')
    [ "$n" = 0 ] && echo "ok: $1 wrote no picture" || bad "$1 wrote $n pictures"
}
traced() { # traced CASE RANK: the rank traced tiles in some frame
    if grep -Eq "rank $2 of 2: frame [0-9]+: [1-9][0-9]* of" "$work/$1.err"; then
        echo "ok: $1: rank $2 traced tiles"
    else bad "$1: rank $2 traced no tiles"; fi
}

mpirun_case fig3 "$fig3" || bad "fig3: mpirun failed"
for f in $(cd "$work/one" && ls *.png | grep fig3); do same "$f" fig3/r0; done
nopng fig3/r1
traced fig3 1
traced fig3 0

mpirun_case tiles "$frames" || bad "tiles: mpirun failed"
for f in anim.png anim-002.png anim-003.png anim-004.png; do same $f tiles/r0; done
nopng tiles/r1
traced tiles 1

GKS3D_MPI_FRAMES=1 mpirun_case frames "$frames" || bad "frames: mpirun failed"
same anim.png frames/r0
same anim-003.png frames/r0
same anim-002.png frames/r1
same anim-004.png frames/r1
[ "$(ls "$work/frames/r0" | grep -c '\.png$')" = 2 ] || bad "frames: rank 0 wrote other files"

t0=$(date +%s)
MPI_TEST_NO_WS=1 GKS3D_MPI_TIMEOUT=3 mpirun_case fault "$frames" # exit status: see docs/MPI.md
t1=$(date +%s)
echo "fault case: $((t1 - t0)) s"
for f in anim.png anim-002.png anim-003.png anim-004.png; do same $f fault/r0; done
if grep -q 305 "$work/fault/r0/errors.txt" 2>/dev/null; then echo "ok: error 305 logged by rank 0"
else bad "fault: rank 0 logged no error 305"; fi
grep -q "rank 1 did not take part" "$work/fault.err" && echo "ok: message names rank 1" ||
    bad "fault: no message naming rank 1"
[ $fail = 0 ] && echo "all MPI cases passed"
exit $fail
