#!/bin/sh
# SPDX-License-Identifier: MIT
# install_test.sh MODE BUILD_DIR WORK_DIR SANITIZE_FLAGS
# Tests of the installed gks3d package. MODE:
#   install   cmake --install BUILD_DIR --prefix WORK_DIR/prefix (fresh)
#   symbols   tests/core/check_symbols.sh --installed on it (exports, hooks, RUNPATH, version)
#   cmake-c   configure, build and run tests/install/consumer_c via find_package(gks3d)
#   pkgconfig compile consumer_c/consumer.c with `pkg-config --cflags --libs gks3d`, run it
#   fortran   configure, build and run tests/install/consumer_f77 via find_package(gks3d)
#             and check the PNG file it writes (exit 77 = skipped: GKS3D_HAVE_FORTRAN != 1)
set -eu
mode=$1 build=$2 work=$3 sanflags=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
prefix=$work/prefix
# The installed shared libraries carry no RPATH; libgks3d_fortran.so needs libgks3d.so.
for d in lib lib64 "lib/$(gcc -print-multiarch 2>/dev/null || true)"; do
    LD_LIBRARY_PATH=$prefix/$d${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
done
export LD_LIBRARY_PATH

png_size() { # FILE -> "WIDTHxHEIGHT" if FILE starts with a PNG signature and IHDR
    sig=$(od -A n -t u1 -N 16 "$1" | tr -s ' \n' ' ')
    [ "$sig" = " 137 80 78 71 13 10 26 10 0 0 0 13 73 72 68 82 " ] || { echo "not a PNG"; return; }
    set -- $(od -A n -t u1 -j 16 -N 8 "$1")
    echo "$(( ($1 << 24) + ($2 << 16) + ($3 << 8) + $4 ))x$(( ($5 << 24) + ($6 << 16) + ($7 << 8) + $8 ))"
}

consumer() { # NAME: configure + build tests/install/NAME against the prefix
    rm -rf "$work/$1"
    cmake -S "$here/$1" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Debug \
          -DCMAKE_C_FLAGS="$sanflags" -DCMAKE_Fortran_FLAGS="$sanflags" \
          -DCMAKE_EXE_LINKER_FLAGS="$sanflags" >"$work/$1.log" 2>&1 || { cat "$work/$1.log"; exit 1; }
    cmake --build "$work/$1" >>"$work/$1.log" 2>&1 || { cat "$work/$1.log"; exit 1; }
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
    echo "installed into $prefix" ;;
symbols)
    sh "$here/../core/check_symbols.sh" --installed "$here/../core/exported_symbols.txt" "$prefix" ;;
cmake-c)
    consumer consumer_c
    cd "$work/consumer_c"
    ./consumer_default "$work/consumer_c/default.png"
    ./consumer_shared "$work/consumer_c/shared.png"
    ./consumer_static "$work/consumer_c/static.png"
    # The static executable must not need libgks3d.so.
    if ldd ./consumer_static | grep -q libgks3d; then echo "consumer_static uses libgks3d.so"; exit 1; fi ;;
pkgconfig)
    PKG_CONFIG_PATH=$(echo "$prefix"/lib*/pkgconfig | tr ' ' ':')
    export PKG_CONFIG_PATH
    flags=$(pkg-config --cflags --libs gks3d)
    echo "pkg-config --cflags --libs gks3d: $flags"
    # A consumer gets only gks3d's own flags (the .pc file is relocatable, so the paths are
    # relative to its directory); libpng's flags go to static links only.
    seen=""
    for f in $flags; do
        case $f in
        -I*/include/gks3d) seen="${seen}I" ;;
        -L*/lib) seen="${seen}L" ;;
        -lgks3d) seen="${seen}l" ;;
        *) echo "pkg-config gks3d: unexpected flag $f for a shared consumer"; exit 1 ;;
        esac
    done
    [ "$seen" = ILl ] || { echo "pkg-config gks3d: expected -I.../include/gks3d -L.../lib -lgks3d"; exit 1; }
    sflags=$(pkg-config --static --libs gks3d)
    echo "pkg-config --static --libs gks3d: $sflags"
    case " $sflags " in
    *" -lpng"*" -lz "*) ;;
    *) echo "pkg-config --static gks3d: libpng and zlib missing"; exit 1 ;;
    esac
    mkdir -p "$work/pkgconfig"
    # libgks3d.a with the flags of --static, the system libraries as usual.
    slibs=$(echo " $sflags " | sed 's/ -lgks3d / -Wl,-Bstatic -lgks3d -Wl,-Bdynamic /')
    # shellcheck disable=SC2086
    ${CC:-cc} $sanflags -std=c11 -o "$work/pkgconfig/consumer_static" "$here/consumer_c/consumer.c" \
        $(pkg-config --cflags gks3d) $slibs
    "$work/pkgconfig/consumer_static" "$work/pkgconfig/pc_static.png"
    if ldd "$work/pkgconfig/consumer_static" | grep -q libgks3d; then
        echo "pkg-config static consumer uses libgks3d.so"; exit 1
    fi
    # shellcheck disable=SC2086
    ${CC:-cc} $sanflags -std=c11 -o "$work/pkgconfig/consumer" "$here/consumer_c/consumer.c" $flags
    "$work/pkgconfig/consumer" "$work/pkgconfig/pc.png"
    if pkg-config --exists gks3d-fortran; then
        echo "pkg-config --cflags --libs gks3d-fortran: $(pkg-config --cflags --libs gks3d-fortran)"
        mkdir -p "$work/pkgconfig/f77" && cd "$work/pkgconfig/f77" && rm -f gks7.png
        # shellcheck disable=SC2046
        ${FC:-gfortran} $sanflags -o consumer_f77 "$here/consumer_f77/consumer.f" \
            $(pkg-config --cflags --libs gks3d-fortran)
        ./consumer_f77
        size=$(png_size gks7.png)
        [ "$size" = 1024x1024 ] || { echo "pkg-config Fortran consumer: gks7.png is $size"; exit 1; }
        echo "pkg-config Fortran consumer: gks7.png OK ($size)"
    fi ;;
fortran)
    ls "$prefix"/lib*/cmake/gks3d/gks3dTargets.cmake >/dev/null
    [ "${GKS3D_HAVE_FORTRAN:-0}" = 1 ] || { echo "skipped: no Fortran binding in this build"; exit 77; }
    grep -q 'gks3d::fortran' "$prefix"/lib*/cmake/gks3d/gks3dTargets.cmake ||
        { echo "gks3d::fortran missing from the installed package"; exit 1; }
    consumer consumer_f77
    cd "$work/consumer_f77"
    for exe in consumer_f77 consumer_f77_static; do
        rm -f gks7.png
        "./$exe"
        size=$(png_size gks7.png)
        [ "$size" = 1024x1024 ] || { echo "$exe: gks7.png is $size, expected 1024x1024"; exit 1; }
        echo "$exe: gks7.png OK ($size)"
    done
    if ldd ./consumer_f77_static | grep -q libgks3d; then echo "consumer_f77_static uses a shared libgks3d"; exit 1; fi ;;
*)
    echo "unknown mode $mode"; exit 2 ;;
esac
