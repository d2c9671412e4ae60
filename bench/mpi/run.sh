#!/bin/sh
# SPDX-License-Identifier: MIT
# run.sh BUILD_DIR SCENE... -- bench/mpi/rt_mpi_bench for N = 1, 2 ranks x T = 1, 2 threads
# (SPD corner rays, 513 x 513, best of 3 frames each), printing the load (uptime) before
# each run. docs/MPI.md has the figures of a run and the cost model built on them.
set -eu
build=$1
shift
opts="--oversubscribe"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
for scene in "$@"; do
    for nt in "1 1" "1 2" "2 1" "2 2"; do
        set -- $nt
        echo "uptime: $(uptime)"
        mpirun $opts -n "$1" "$build/bench/mpi/rt_mpi_bench" "$scene" -s 513 -t "$2" -reps 3
    done
done
