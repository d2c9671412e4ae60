#!/bin/sh
# SPDX-License-Identifier: MIT
# run_maps_test.sh MPI_MAPS WORKDIR -- MPI only where the program runs under MPI
# (docs/MPI.md): libgks3d does not link libmpi and loads its MPI module only under an MPI
# launcher.
#   1. a serial run maps no MPI library (mpi_maps reads /proc/self/maps) and draws;
#   2. a launcher's environment (OMPI_COMM_WORLD_SIZE=2) with the module missing
#      (GKS3D_MPI_MODULE names no file): rank 0 prints one line saying why, maps no MPI
#      library and draws the picture alone; rank 1 prints nothing and writes no picture.
set -u
prog=$1 work=$2
fail=0
bad() { echo "FAIL: $*"; fail=1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
# The test runs without a launcher: none of its variables may leak in.
unset OMPI_COMM_WORLD_SIZE OMPI_COMM_WORLD_RANK PMI_SIZE PMI_RANK MV2_COMM_WORLD_SIZE MV2_COMM_WORLD_RANK

"$prog" serial.png >serial.out 2>serial.err
rc=$?
cat serial.out serial.err
[ $rc = 0 ] || bad "serial run: status $rc (3: an MPI library is mapped)"
[ -s serial.png ] || bad "serial run wrote no picture"
[ ! -s serial.err ] || bad "serial run wrote to stderr"

for r in 0 1; do
    OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=$r GKS3D_MPI_MODULE=$work/absent/libgks3d-mpi.so \
        "$prog" rank$r.png >rank$r.out 2>rank$r.err
    rc=$?
    echo "rank $r of 2, no module: status $rc"
    cat rank$r.out rank$r.err
    [ $rc = 0 ] || bad "rank $r without module: status $rc"
done
[ -s rank0.png ] || bad "rank 0 without module wrote no picture"
[ ! -e rank1.png ] || bad "rank 1 without module wrote a picture (rank 0 draws alone)"
[ "$(wc -l <rank0.err)" = 1 ] && grep -q 'MPI module cannot be loaded.*rank 0 draws the pictures alone' rank0.err ||
    bad "rank 0 without module: expected one line saying why on stderr"
[ ! -s rank1.err ] || bad "rank 1 without module wrote to stderr"
[ $fail = 0 ] && echo "all cases passed"
exit $fail
