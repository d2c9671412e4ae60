#!/bin/sh
# SPDX-License-Identifier: MIT
# install_test.sh MODE BUILD_DIR WORK_DIR SANITIZE_FLAGS
# Tests of the installed gks3d package, done as a user does them: the prefix
# (WORK_DIR/prefix) is outside the loader's search path, and LD_LIBRARY_PATH is unset for
# every link and every run (the README's build section documents these link lines). MODE:
#   install        cmake --install BUILD_DIR --prefix WORK_DIR/prefix (fresh)
#   symbols        tests/core/check_symbols.sh --installed on it (exports, hooks, RUNPATH)
#   cmake-c        tests/install/consumer_c via find_package(gks3d): gks3d::gks3d,
#                  gks3d::shared and gks3d::static, built and run
#   cmake-fortran  tests/install/consumer_f77 via find_package(gks3d COMPONENTS Fortran):
#                  gks3d::fortran and gks3d::fortran_static, built and run
#   pkgconfig-c    consumer_c/consumer.c linked with `pkg-config --libs gks3d` (shared) and
#                  `pkg-config --static --libs gks3d` (libgks3d.a), run
#   pkgconfig-fortran  consumer_f77/consumer.f the same way with gks3d-fortran
#   mpi            the installed nff_view under $GKS3D_MPIEXEC -n 2: the installed MPI module
#                  is found beside the installed libgks3d.so (dladdr) and both ranks share the
#                  frame; rank 0 alone writes the picture (exit 77 without the MPI module
#                  or GKS3D_MPIEXEC)
# The Fortran modes exit 77 (skipped) when GKS3D_HAVE_FORTRAN != 1.
set -eu
mode=$1 build=$2 work=$3 sanflags=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
prefix=$work/prefix
# A user's environment: nothing tells the linker or the loader where the prefix is.
unset LD_LIBRARY_PATH LIBRARY_PATH LD_RUN_PATH || true

png_size() { # FILE -> "WIDTHxHEIGHT" if FILE starts with a PNG signature and IHDR
    [ -f "$1" ] || { echo "missing"; return; }
    sig=$(od -A n -t u1 -N 16 "$1" | tr -s ' \n' ' ')
    [ "$sig" = " 137 80 78 71 13 10 26 10 0 0 0 13 73 72 68 82 " ] || { echo "not a PNG"; return; }
    # shellcheck disable=SC2046
    set -- $(od -A n -t u1 -j 16 -N 8 "$1")
    echo "$(( ($1 << 24) + ($2 << 16) + ($3 << 8) + $4 ))x$(( ($5 << 24) + ($6 << 16) + ($7 << 8) + $8 ))"
}
need_fortran() {
    [ "${GKS3D_HAVE_FORTRAN:-0}" = 1 ] || { echo "skipped: no Fortran binding in this build"; exit 77; }
}
run_f77() { # EXE [LIBDIR]: runs the Fortran consumer in its folder (with
    # LD_LIBRARY_PATH=LIBDIR for this run only if given), checks gks7.png
    rm -f gks7.png
    if [ -n "${2:-}" ]; then LD_LIBRARY_PATH=$2 "./$1"; else "./$1"; fi >"$1.out"
    cat "$1.out"
    # GKSVER: the version of the library loaded, as the package says (gks3d.pc).
    v=$(awk '$1 == "GKSVER" { print $2 "." $3 "." $4 }' "$1.out")
    want=$(PKG_CONFIG_PATH=$(echo "$prefix"/lib*/pkgconfig "$prefix"/lib/*/pkgconfig | tr ' ' ':') \
           pkg-config --modversion gks3d)
    [ "$v" = "$want" ] || { echo "$1: GKSVER gives '$v', the package is $want"; exit 1; }
    size=$(png_size gks7.png)
    [ "$size" = 1024x1024 ] || { echo "$1: gks7.png is $size, expected 1024x1024"; exit 1; }
    echo "$1: ran, gks7.png OK ($size)"
}
no_shared_gks() { # EXE: a static consumer must not need any libgks3d*.so
    if ldd "$1" | grep -q 'libgks3d'; then echo "$1 uses a shared libgks3d: $(ldd "$1" | grep libgks3d)"; exit 1; fi
}
consumer() { # NAME: configure + build tests/install/NAME against the prefix
    rm -rf "${work:?}/$1"
    cmake -S "$here/$1" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Debug \
          -DCMAKE_C_FLAGS="$sanflags" -DCMAKE_Fortran_FLAGS="$sanflags" \
          -DCMAKE_EXE_LINKER_FLAGS="$sanflags" >"$work/$1.log" 2>&1 || { cat "$work/$1.log"; exit 1; }
    cmake --build "$work/$1" >>"$work/$1.log" 2>&1 || { cat "$work/$1.log"; exit 1; }
}
pc_setup() {
    PKG_CONFIG_PATH=$(echo "$prefix"/lib*/pkgconfig "$prefix"/lib/*/pkgconfig | tr ' ' ':')
    export PKG_CONFIG_PATH
    libdir=$(pkg-config --variable=libdir gks3d)
    mkdir -p "$work/$mode"
    cd "$work/$mode"
}
# The static form of a pkg-config link line: the archives in place of -lgks3d and
# -lgks3d_fortran (the linker prefers the .so when both are there), as the README says.
static_line() {
    echo " $* " | sed -e 's/ -lgks3d_fortran / -Wl,-Bstatic -lgks3d_fortran -Wl,-Bdynamic /' \
                      -e 's/ -lgks3d / -Wl,-Bstatic -lgks3d -Wl,-Bdynamic /'
}

case $mode in
install)
    rm -rf "$prefix"
    cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 || { cat "$work/install.log"; exit 1; }
    for f in include/gks3d/gks.h include/gks3d/gks_functions.def include/gks3d/gks3d_version.h; do
        [ -f "$prefix/$f" ] || { echo "missing $f"; exit 1; }
    done
    # The tracer's header is internal (src/rt/gksrt.h): never installed.
    [ ! -e "$prefix/include/gks3d/gksrt.h" ] || { echo "gksrt.h is installed"; exit 1; }
    ls "$prefix"/lib*/libgks3d.a "$prefix"/lib*/libgks3d.so* "$prefix"/lib*/cmake/gks3d/gks3dConfig.cmake \
       "$prefix"/lib*/pkgconfig/gks3d.pc >/dev/null
    # libgks3d.a must be self-contained: the code of the internal modules is inside (as
    # local names of its one prelinked object), and none of it is left undefined.
    a=$(ls "$prefix"/lib*/libgks3d.a | head -1)
    for f in gks_xform_ gks_raster_ rt_ ws_ gks_mf_; do
        nm "$a" | grep -q " t $f" || { echo "libgks3d.a lacks the code of ${f}*"; exit 1; }
        if nm -u "$a" | grep -q " U $f"; then echo "libgks3d.a needs ${f}* from outside"; exit 1; fi
    done
    # The MPI module, when built, in <libdir>/gks3d (docs/MPI.md).
    if [ -e "$build/src/c/gks3d/libgks3d-mpi.so" ]; then
        ls "$prefix"/lib*/gks3d/libgks3d-mpi.so >/dev/null || { echo "libgks3d-mpi.so not installed"; exit 1; }
    fi
    for f in LICENSE README.md CHANGELOG.md docs/MPI.md docs/BINDING.md; do
        [ -f "$prefix/share/doc/gks3d/$f" ] || { echo "missing share/doc/gks3d/$f"; exit 1; }
    done
    # The programs run from the prefix with no environment variable (RUNPATH) and say what
    # they do.
    for p in nff_view mesh_view; do
        [ -x "$build/examples/$p" ] || continue # GKS_BUILD_EXAMPLES=OFF: not built
        [ -x "$prefix/bin/$p" ] || { echo "missing bin/$p"; exit 1; }
        "$prefix/bin/$p" --help | grep -q "^$p -- ray traces" || { echo "bin/$p --help failed"; exit 1; }
        echo "bin/$p --help: $("$prefix/bin/$p" --help | head -1)"
    done
    # gks3d-render (src/tools: always built) and its page.
    "$prefix/bin/gks3d-render" --help | grep -q "^gks3d-render -- renders" ||
        { echo "bin/gks3d-render --help failed"; exit 1; }
    [ -f "$prefix/share/man/man1/gks3d-render.1" ] || { echo "missing man1/gks3d-render.1"; exit 1; }
    echo "bin/gks3d-render --help: $("$prefix/bin/gks3d-render" --help | head -1)"
    echo "installed into $prefix" ;;
symbols)
    sh "$here/../core/check_symbols.sh" --installed "$here/../core/exported_symbols.txt" "$prefix" ;;
cmake-c)
    consumer consumer_c
    cd "$work/consumer_c"
    for exe in consumer_default consumer_shared consumer_static; do
        "./$exe" "$work/consumer_c/$exe.png"
        echo "$exe: ran, $exe.png $(png_size "$work/consumer_c/$exe.png")"
    done
    no_shared_gks ./consumer_static ;;
cmake-fortran)
    need_fortran
    grep -q 'gks3d::fortran' "$prefix"/lib*/cmake/gks3d/gks3dTargets.cmake ||
        { echo "gks3d::fortran missing from the installed package"; exit 1; }
    consumer consumer_f77
    cd "$work/consumer_f77"
    # consumer_f77 needs libgks3d_fortran.so, which needs libgks3d.so: found through the
    # program's RUNPATH (CMake) and libgks3d_fortran's own RUNPATH $ORIGIN.
    run_f77 consumer_f77
    run_f77 consumer_f77_static
    no_shared_gks ./consumer_f77_static ;;
pkgconfig-c)
    pc_setup
    flags=$(pkg-config --cflags --libs gks3d)
    echo "pkg-config --cflags --libs gks3d: $flags"
    # A shared consumer gets only gks3d's own flags (libpng's go to static links only).
    seen=""
    for f in $flags; do
        case $f in
        -I*/include/gks3d) seen="${seen}I" ;;
        -L*/lib|-L*/lib/*) seen="${seen}L" ;;
        -lgks3d) seen="${seen}l" ;;
        *) echo "pkg-config gks3d: unexpected flag $f for a shared consumer"; exit 1 ;;
        esac
    done
    [ "$seen" = ILl ] || { echo "pkg-config gks3d: expected -I.../include/gks3d -L.../lib -lgks3d"; exit 1; }
    # Shared, the plain link line; at run time the loader is told where the prefix is.
    # shellcheck disable=SC2086
    ${CC:-cc} $sanflags -std=c11 -o consumer "$here/consumer_c/consumer.c" $flags
    LD_LIBRARY_PATH=$libdir ./consumer pc.png
    echo "shared pkg-config consumer: ran with LD_LIBRARY_PATH=libdir, pc.png $(png_size pc.png)"
    # Shared with -Wl,-rpath,libdir: runs with no environment variable.
    # shellcheck disable=SC2086
    ${CC:-cc} $sanflags -std=c11 -o consumer_rpath "$here/consumer_c/consumer.c" $flags -Wl,-rpath,"$libdir"
    ./consumer_rpath pc_rpath.png
    echo "shared pkg-config consumer, -rpath: ran, pc_rpath.png $(png_size pc_rpath.png)"
    sflags=$(pkg-config --static --libs gks3d)
    echo "pkg-config --static --libs gks3d: $sflags"
    case " $sflags " in
    *" -lpng"*" -lz "*) ;;
    *) echo "pkg-config --static gks3d: libpng and zlib missing"; exit 1 ;;
    esac
    # shellcheck disable=SC2086,SC2046
    ${CC:-cc} $sanflags -std=c11 -o consumer_static "$here/consumer_c/consumer.c" \
        $(pkg-config --cflags gks3d) $(static_line $sflags)
    ./consumer_static pc_static.png
    echo "static pkg-config consumer: ran, pc_static.png $(png_size pc_static.png)"
    no_shared_gks ./consumer_static ;;
pkgconfig-fortran)
    need_fortran
    pc_setup
    flags=$(pkg-config --cflags --libs gks3d-fortran)
    echo "pkg-config --cflags --libs gks3d-fortran: $flags"
    # Shared: the link needs libgks3d.so too (the DT_NEEDED of libgks3d_fortran.so; the
    # linker does not look for it in the -L folders), so the .pc must name it.
    # shellcheck disable=SC2086
    ${FC:-gfortran} $sanflags -o consumer_f77 "$here/consumer_f77/consumer.f" $flags
    run_f77 consumer_f77 "$libdir"
    # With -Wl,-rpath,libdir: runs with no environment variable (libgks3d.so.0, needed by
    # libgks3d_fortran.so, is found through libgks3d_fortran's RUNPATH $ORIGIN: the
    # program's RUNPATH does not apply to its libraries' dependencies).
    # shellcheck disable=SC2086
    ${FC:-gfortran} $sanflags -o consumer_f77_rpath "$here/consumer_f77/consumer.f" $flags -Wl,-rpath,"$libdir"
    run_f77 consumer_f77_rpath
    sflags=$(pkg-config --static --libs gks3d-fortran)
    echo "pkg-config --static --libs gks3d-fortran: $sflags"
    # shellcheck disable=SC2086,SC2046
    ${FC:-gfortran} $sanflags -o consumer_f77_static "$here/consumer_f77/consumer.f" \
        $(pkg-config --cflags gks3d-fortran) $(static_line $sflags)
    run_f77 consumer_f77_static
    no_shared_gks ./consumer_f77_static ;;
mpi)
    [ -e "$build/src/c/gks3d/libgks3d-mpi.so" ] && [ -n "${GKS3D_MPIEXEC:-}" ] &&
        [ -x "$prefix/bin/nff_view" ] ||
        { echo "skipped: no MPI module, mpiexec or nff_view in this build"; exit 77; }
    rm -rf "${work:?}/mpi" && mkdir -p "$work/mpi" && cd "$work/mpi"
    opts="--oversubscribe -n 2"
    [ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
    # GKS3D_MPI_MODULE unset: the module must be found from the installed libgks3d.so.
    # shellcheck disable=SC2086
    GKS3D_MPI_REPORT=1 timeout 120 env -u GKS3D_MPI_MODULE "$GKS3D_MPIEXEC" $opts sh -c \
        'd=r$OMPI_COMM_WORLD_RANK; mkdir -p "$d" && cd "$d" && exec "$0" --size 64x64 "$1" out.png' \
        "$prefix/bin/nff_view" "$here/../data/spd/tetra.nff.gz" >mpi.out 2>mpi.err ||
        { cat mpi.out mpi.err; echo "mpirun of the installed nff_view failed"; exit 1; }
    cat mpi.err
    if grep -q 'cannot be loaded' mpi.err; then echo "the installed MPI module was not loaded"; exit 1; fi
    # Each rank reports the shared frame (GKS3D_MPI_REPORT): its link through the module was
    # up. How many tiles each traced depends on the load (rank 0 may trace all 25 before
    # rank 1's first request), so that is not checked here (mpi_runs does, on larger frames).
    for r in 0 1; do
        grep -Eq "rank $r of 2: frame 1: [0-9]+ of 25 tiles" mpi.err ||
            { echo "rank $r did not share the frame through the MPI module"; exit 1; }
    done
    [ "$(png_size r0/out.png)" = 64x64 ] || { echo "rank 0: out.png is $(png_size r0/out.png)"; exit 1; }
    [ ! -e r1/out.png ] || { echo "rank 1 wrote a picture"; exit 1; }
    echo "installed nff_view under mpirun -n 2: both ranks shared the frame, rank 0 wrote out.png (64x64)" ;;
*)
    echo "unknown mode $mode"; exit 2 ;;
esac
