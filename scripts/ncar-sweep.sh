#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# ncar-sweep.sh -- every Fortran example NCAR Graphics' ncargex knows, linked the documented
# way against gks3d (docs/NCAR.md) and run, one at a time:
#   gfortran <NCAR's options> <sources> libncarg.a $(pkg-config --libs gks3d-ncarg) \
#            libncarg_c.a [-lngmath] [NCAR's robj objects]
# and every example also with -L$(ncargpath lib) -lngmath -lpng -lz (the NGMATH examples
# and wmex* need libngmath, mpex15 libpng; Debian's ncargex adds -ngmath for none of the
# Fortran ones, so NCAR's own build of those does not link either), and with the data
# file ncargex feeds it on standard input.
# Prints one line per example -- name, linked, ran (exit status), frames (files written),
# GKS error lines (of gks3d's error file, stdout) -- then a summary and the GKS error lines
# grouped by example.
#
#   scripts/ncar-sweep.sh [-p PREFIX] [-j WORKDIR] [NAME...]
#     -p PREFIX   gks3d installed there (PKG_CONFIG_PATH=PREFIX/lib/pkgconfig,
#                 LD_LIBRARY_PATH=PREFIX/lib); default: pkg-config as set up
#     -j WORKDIR  where the examples are built (default: a fresh temporary directory)
#     NAME...     only these examples (default: all Fortran examples of ncargex whose
#                 source NCAR Graphics installs)
# Needs libncarg-dev, libncarg-bin and ncl-ncarg (scripts/setup.sh). Runs niced, each
# example at most 300 s, without X (DISPLAY unset: NCAR's X11 types become PNG files).
set -uo pipefail

prefix="" work=""
while getopts "p:j:" o; do
    case $o in
        p) prefix=$OPTARG ;;
        j) work=$OPTARG ;;
        *) sed -n '2,20p' "$0"; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
if [ -n "$prefix" ]; then
    export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
    export LD_LIBRARY_PATH="$prefix/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
fi
for t in ncargex ncargpath pkg-config gfortran python3; do
    command -v "$t" >/dev/null || { echo "ncar-sweep: $t not found (scripts/setup.sh)" >&2; exit 1; }
done
gks_libs=$(pkg-config --libs gks3d-ncarg) || { echo "ncar-sweep: no pkg-config module gks3d-ncarg" >&2; exit 1; }
libdir=$(ncargpath lib)
ncarg_a=$libdir/libncarg.a ncarg_c_a=$libdir/libncarg_c.a robj=$libdir/robj
[ -d "$robj" ] || robj=$libdir/ncarg/robj # ncargf77 says this; Debian has the former
[ -f "$ncarg_a" ] || ncarg_a=$libdir/ncarg/libncarg.a
[ -f "$ncarg_c_a" ] || ncarg_c_a=$libdir/ncarg/libncarg_c.a
[ -f "$ncarg_a" ] && [ -f "$ncarg_c_a" ] || { echo "ncar-sweep: libncarg.a not found" >&2; exit 1; }
# Debian installs the examples under /usr/share/doc; ncargex looks in /usr/share/ncarg.
exdir=$(ncargpath examples)
[ -d "$exdir" ] || exdir=/usr/share/doc/libncarg-dev/examples
export NCARG_EXAMPLES=$exdir NCARG_TESTS=$exdir NCARG_TUTORIAL=$exdir
unset DISPLAY GKS3D_WS_TYPES GKS3D_ASF
# ncargf77's Fortran options (NCAR's sources need them with gfortran >= 10)
fflags=(-w -fallow-argument-mismatch -fallow-invalid-boz -fno-second-underscore -fno-range-check)

# The Fortran examples of ncargex: its lists (examples, tests, tutorial, fundamentals,
# PostScript and X11 examples), those whose source is installed; and, from its switch of
# special cases, the file each reads on standard input ("NAME FILE" lines in stdin.txt).
[ -n "$work" ] || work=$(mktemp -d /tmp/ncar-sweep.XXXXXX)
mkdir -p "$work"
python3 - "$(command -v ncargex)" "$exdir" > "$work/names.txt" 2> "$work/stdin.txt" <<'EOF'
import os, re, sys
src = open(sys.argv[1]).read()
cases = []
for line in src.split('\n'):
    m = re.match(r'\s*case\s+(\w+)\s*:', line)
    if m:
        cases.append(m.group(1))
        continue
    m = re.match(r'\s*set\s+stdin_data_file\s*=\s*\((\S+)\)', line)
    if m:
        for c in cases:
            print(c, m.group(1), file=sys.stderr)
    if re.match(r'\s*(breaksw|endsw)\b', line):
        cases = []
txt = src.replace('\\\n', ' ')
var = {}
for m in re.finditer(r'^\s*set\s+(\w+)\s*=\s*\(([^)]*)\)', txt, re.M):
    out = []
    for t in m.group(2).split():
        v = re.fullmatch(r'\$\{?(\w+)\}?', t)
        out += var.get(v.group(1), []) if v else [t]
    var[m.group(1)] = out
seen = []
for k in ['list_fex', 'list_ftst', 'list_fttr', 'list_ffnd', 'list_fpdc', 'list_fps', 'list_fx11']:
    for n in var.get(k, []):
        if n not in seen and os.path.exists(os.path.join(sys.argv[2], n + '.f')):
            seen.append(n)
print('\n'.join(seen))
EOF
names=("$@")
[ ${#names[@]} -gt 0 ] || mapfile -t names < "$work/names.txt"
echo "ncar-sweep: ${#names[@]} examples in $work; gks3d: $gks_libs"
printf '%-10s %-6s %-5s %6s %6s\n' example linked ran frames errors
n_link=0 n_ran=0 n_frames=0 n_err_ex=0 n_err=0
: > "$work/errors.txt"
for ex in "${names[@]}"; do
    d=$work/$ex
    rm -rf "$d" && mkdir -p "$d"
    (cd "$d" && ncargex -n "$ex" > ncargex.txt 2>&1)
    extra=()
    case $ex in # ncargex's special cases (robj objects as ncargf77 adds them)
        tagupw) extra=("$robj/libagupwrtx.o") ;;
        tdashs | tcnsmt | tconan) extra=("$robj/libdashsmth.o") ;;
        tdashl | tcnqck | tconaq) extra=("$robj/libdashline.o" "$robj/libconrcqck.o" "$robj/libconraq.o") ;;
        tdashp | tcnsup | tconas | fdlsmth) extra=("$robj/libdashsupr.o" "$robj/libconrcspr.o" "$robj/libconras.o") ;;
    esac
    srcs=("$d"/*.f)
    linked=no ran=- frames=0 errors=0
    # shellcheck disable=SC2086 # gks_libs: pkg-config's words
    if (cd "$d" && nice -n 10 gfortran "${fflags[@]}" "${srcs[@]}" "${extra[@]}" "$ncarg_a" \
            $gks_libs "$ncarg_c_a" -L"$libdir" -lngmath -lpng -lz -o "$ex" > link.txt 2>&1); then
        linked=yes
        n_link=$((n_link + 1))
        stdin=/dev/null
        f=$(awk -v n="$ex" '$1 == n { print $2; exit }' "$work/stdin.txt")
        [ -n "$f" ] && [ -f "$d/$f" ] && stdin=$d/$f
        (cd "$d" && timeout 300 nice -n 10 "./$ex" < "$stdin" > run.txt 2>&1)
        ran=$?
        [ $ran -eq 0 ] && n_ran=$((n_ran + 1))
        frames=$(find "$d" -maxdepth 1 \( -name '*.png' -o -name '*.pdf' -o -name '*.ps' \
                 -o -name '*.eps' -o -name '*.svg' \) | wc -l)
        n_frames=$((n_frames + frames))
        errors=$(grep -c "GKS ERROR" "$d/run.txt")
        if [ "$errors" -gt 0 ]; then
            n_err_ex=$((n_err_ex + 1))
            n_err=$((n_err + errors))
            grep "GKS ERROR" "$d/run.txt" | sort | uniq -c | sed "s/^/$ex: /" >> "$work/errors.txt"
        fi
        rm -f "$d/$ex" # keep the disk small
    fi
    printf '%-10s %-6s %-5s %6d %6d\n' "$ex" "$linked" "$ran" "$frames" "$errors"
done
echo "summary: ${#names[@]} examples, $n_link linked, $n_ran ran to exit 0, $n_frames files" \
     "written, $n_err_ex with GKS error lines ($n_err lines)"
if [ -s "$work/errors.txt" ]; then
    echo "GKS error lines (count, example):"
    cat "$work/errors.txt"
fi
