#!/bin/sh
# SPDX-License-Identifier: MIT
# check_symbols.sh LIST LIBGKS3D.so LIBGKS3D.a [LIBGKS3D_FORTRAN.so LIBGKS3D_FORTRAN.a]
# check_symbols.sh --installed LIST PREFIX
# The libraries export exactly the intended names, nothing internal leaks:
#   - libgks3d.so exports (dynamic symbol table) exactly the names of LIST, the public API
#     of gks.h and what the Fortran binding needs (gks_binding.h);
#   - libgks3d.a defines exactly the same global names (internal names are local);
#   - no library has a test hook (gks_alloc_fail_after, gks_alloc_count, gks_test_*), not
#     even as a local symbol: they exist only in the test build, gks3d_test;
#   - libgks3d_fortran.so / .a define only Fortran entry points (gNAME_ as gfortran mangles
#     them), none of the C names;
# and with --installed, for the libraries and headers installed under PREFIX, also:
#   - libgks3d.so has no RUNPATH or RPATH; libgks3d_fortran.so has RUNPATH $ORIGIN (it
#     finds libgks3d.so.0 next to it), none when PREFIX is /usr or /usr/local;
#   - gks3d_version.h is installed and defines GKS3D_VERSION_MAJOR/MINOR/PATCH.
set -eu
fail=0
bad() { echo "FAIL: $*"; fail=1; }

installed=0
if [ "$1" = --installed ]; then
    installed=1; list=$2; prefix=$3
    libdir=$(dirname "$(ls "$prefix"/lib*/libgks3d.so "$prefix"/lib/*/libgks3d.so 2>/dev/null | head -1)")
    [ -d "$libdir" ] || { echo "FAIL: no libgks3d.so under $prefix"; exit 1; }
    so=$libdir/libgks3d.so; ar=$libdir/libgks3d.a
    fso=$libdir/libgks3d_fortran.so; far=$libdir/libgks3d_fortran.a
    [ -e "$fso" ] || fso=""
    [ -e "$far" ] || far=""
else
    list=$1; so=$2; ar=$3; fso=${4:-}; far=${5:-}
fi
want=$(grep -v '^#' "$list" | sed '/^$/d' | sort)

# Names the linker defines in every shared object; not ours to choose.
linker_names='^(_edata|_end|__bss_start|_init|_fini)$'
dyn_names() { nm -D --defined-only "$1" | awk '{print $NF}' | sed 's/@.*//' | grep -Ev "$linker_names" | sort; }
# Global defined names of an archive (nm prints "member:" headers and blank lines).
ar_names() { nm -g --defined-only "$1" | awk 'NF==3{print $3}' | sort; }
hooks='gks_alloc_fail_after|gks_alloc_count|gks_test_|fail_countdown'

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%s\n' "$want" >"$tmp/want"
list_sorted=$tmp/want
compare() { # WHAT ACTUAL
    if [ "$2" != "$want" ]; then
        bad "$1 differs from $list (< intended, > actual):"
        printf '%s\n' "$2" | diff "$list_sorted" - || true
    else
        echo "$1: $(printf '%s\n' "$2" | wc -l) names, as intended"
    fi
}

compare "libgks3d.so exports" "$(dyn_names "$so")"
compare "libgks3d.a global definitions" "$(ar_names "$ar")"

for lib in "$so" "$ar" $fso $far; do
    # every symbol table, the local symbols included (.so: also the static one if kept)
    found=$( { nm -a "$lib" 2>/dev/null || true; nm -D "$lib" 2>/dev/null || true; } |
             awk '{print $NF}' | grep -E "$hooks" | sort -u || true)
    if [ -n "$found" ]; then
        bad "$(basename "$lib") has test hooks: $(echo $found)"
    else
        echo "$(basename "$lib"): no test hooks"
    fi
done

fortran_check() { # WHAT NAMES
    n=$(printf '%s\n' "$2" | sed '/^$/d' | wc -l)
    other=$(printf '%s\n' "$2" | grep -Ev '^g[a-z0-9]*_$' || true)
    cnames=$(printf '%s\n' "$2" | grep -Fx "$want" || true)
    if [ "$n" -lt 100 ]; then
        bad "$1: only $n names"
    elif [ -n "$other$cnames" ]; then
        bad "$1 has names that are not Fortran entry points: $(echo $other $cnames)"
    else
        echo "$1: $n names, all Fortran entry points"
    fi
}
[ -z "$fso" ] || fortran_check "libgks3d_fortran.so exports" "$(dyn_names "$fso")"
[ -z "$far" ] || fortran_check "libgks3d_fortran.a global definitions" "$(ar_names "$far")"

if [ "$installed" = 1 ]; then
    case $(cd "$prefix" && pwd) in /usr|/usr/local) system=1 ;; *) system=0 ;; esac
    for lib in "$libdir"/libgks3d*.so*; do
        [ -f "$lib" ] && [ ! -L "$lib" ] || continue
        rp=$(readelf -d "$lib" | grep -E '\((RUNPATH|RPATH)\)' | sed 's/.*\[\(.*\)\]/\1/' || true)
        want_rp=""
        case $(basename "$lib") in libgks3d_fortran.so*) [ $system = 1 ] || want_rp='$ORIGIN' ;; esac
        if [ "$rp" != "$want_rp" ] || readelf -d "$lib" | grep -q '(RPATH)'; then
            bad "$(basename "$lib") has RUNPATH/RPATH '$rp', expected '${want_rp:-none}'"
        else
            echo "$(basename "$lib"): RUNPATH ${want_rp:-none}, as intended"
        fi
    done
    vh=$prefix/include/gks3d/gks3d_version.h
    if [ ! -f "$vh" ]; then
        bad "gks3d_version.h is not installed"
    else
        for m in MAJOR MINOR PATCH; do
            grep -Eq "^#define GKS3D_VERSION_$m [0-9]+" "$vh" || bad "gks3d_version.h lacks GKS3D_VERSION_$m"
        done
        grep -q '#include "gks3d_version.h"' "$prefix/include/gks3d/gks.h" ||
            bad "gks.h does not include gks3d_version.h"
        [ "$fail" = 1 ] || echo "gks3d_version.h: GKS3D_VERSION_MAJOR/MINOR/PATCH"
    fi
fi
exit $fail
