#!/bin/sh
# SPDX-License-Identifier: MIT
# readme_test.sh MODE SOURCE_DIR BUILD_DIR WORK_DIR -- the programs of README.md's "A first
# program", built and run with the README's own lines against the installed library.
# The README marks each block with "<!-- readme-test: NAME -->" on the line before its
# fence; the block's text becomes WORK_DIR/NAME. MODE:
#   extract    the four blocks (hello.c, hello.f, pkgconfig.sh, CMakeLists.txt) into
#              WORK_DIR/src, and `cmake --install BUILD_DIR` into a fresh WORK_DIR/prefix
#   pkgconfig  run pkgconfig.sh (its /opt/gks3d replaced by the prefix) in a fresh folder:
#              both programs compile, link, run without a GKS ERROR and write their PNG
#              (only the C lines when the build has no Fortran: GKS3D_HAVE_FORTRAN != 1)
#   cmake      configure and build CMakeLists.txt with -DCMAKE_PREFIX_PATH=prefix, run both
#              (exit 77 = skipped: no Fortran in this build, the block needs it)
set -eu
mode=$1 src=$2 build=$3 work=$4
prefix=$work/prefix
fail() { echo "FAIL: $*"; exit 1; }

check_png() { # FILE: a PNG of 1024 x 1024 pixels (the programs' workstation default)
    [ -f "$1" ] || fail "$1 not written"
    sig=$(od -A n -t u1 -N 16 "$1" | tr -s ' \n' ' ')
    [ "$sig" = " 137 80 78 71 13 10 26 10 0 0 0 13 73 72 68 82 " ] || fail "$1 is not a PNG"
    set -- $(od -A n -t u1 -j 16 -N 8 "$1")
    [ "$(( ($1 << 24) + ($2 << 16) + ($3 << 8) + $4 ))x$(( ($5 << 24) + ($6 << 16) + ($7 << 8) + $8 ))" = 1024x1024 ] ||
        fail "png size is not 1024x1024"
}

case $mode in
extract)
    rm -rf "$work/src" "$prefix" && mkdir -p "$work/src"
    for name in hello.c hello.f pkgconfig.sh CMakeLists.txt; do
        awk -v name="$name" '
            $0 == "<!-- readme-test: " name " -->" { want = 1; next }
            want == 1 && /^```/ { want = 2; next }
            want == 2 && /^```/ { want = 3; next }
            want == 2 { print }
            END { if (want != 3) exit 1 }' "$src/README.md" > "$work/src/$name" ||
            fail "README.md has no complete block marked readme-test: $name"
        echo "extracted $name: $(wc -l < "$work/src/$name") lines"
    done
    cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 ||
        { cat "$work/install.log"; fail "install"; }
    echo "installed into $prefix" ;;
pkgconfig)
    run=$work/pkgconfig && rm -rf "$run" && mkdir -p "$run" && cd "$run"
    cp "$work/src/hello.c" "$work/src/hello.f" .
    sed "s#/opt/gks3d#$prefix#g" "$work/src/pkgconfig.sh" > run.sh
    if [ "${GKS3D_HAVE_FORTRAN:-0}" != 1 ]; then
        grep -v gfortran run.sh > run_c.sh && mv run_c.sh run.sh
        echo "no Fortran in this build: the C lines only"
    fi
    echo "--- the README's lines, prefix $prefix:"; cat run.sh
    sh -e run.sh > out.txt 2>&1 || { cat out.txt; fail "the README's pkg-config lines"; }
    cat out.txt
    if grep -q "GKS ERROR" out.txt; then fail "a program reported an error"; fi
    check_png hello.png
    [ "${GKS3D_HAVE_FORTRAN:-0}" != 1 ] || check_png gks1.png
    echo "pkg-config: hello_c wrote hello.png${GKS3D_HAVE_FORTRAN:+, hello_f gks1.png}" ;;
cmake)
    if [ "${GKS3D_HAVE_FORTRAN:-0}" != 1 ]; then
        echo "skipped: the README's CMake project needs Fortran, this build has none"
        exit 77
    fi
    run=$work/cmake && rm -rf "$run" && mkdir -p "$run" && cd "$run"
    cp "$work/src/hello.c" "$work/src/hello.f" "$work/src/CMakeLists.txt" .
    cmake -S . -B build -DCMAKE_PREFIX_PATH="$prefix" > cmake.log 2>&1 &&
        cmake --build build >> cmake.log 2>&1 || { cat cmake.log; fail "the README's CMake lines"; }
    # the installed shared libraries carry no RPATH (README, "Building and linking")
    LD_LIBRARY_PATH=$prefix/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
    export LD_LIBRARY_PATH
    build/hello_c > out.txt 2>&1 && build/hello_f >> out.txt 2>&1 || { cat out.txt; fail "run"; }
    if grep -q "GKS ERROR" out.txt; then cat out.txt; fail "a program reported an error"; fi
    check_png hello.png
    check_png gks1.png
    echo "cmake: hello_c wrote hello.png, hello_f gks1.png" ;;
*)
    fail "unknown mode $mode" ;;
esac
