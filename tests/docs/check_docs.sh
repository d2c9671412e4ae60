#!/bin/sh
# SPDX-License-Identifier: MIT
# check_docs.sh ROOT -- checks that keep the documents true to the code (issue 37):
#  1. every workstation type of the list of drivers (src/c/ws/ws_drivers.def)
#     has a C constant GWS_TYPE_* in include/gks.h and a Fortran constant in
#     bindings/fortran/gks3d_par.inc, and appears as a table row "| N | `C` | `F` |" in
#     README.md and in docs/WORKSTATIONS.md;
#  2. every CMake option GKS_WITH_* is named in README.md;
#  3. every repository path a document (each tracked *.md) names exists: words that
#     start with a top-level folder (src/ include/ docs/ ...), globs allowed; a path
#     without extension may name a build product of a source file (bench/rt/rt_smooth:
#     bench/rt/rt_smooth.c); tests/docs/paths_allowed.txt lists the few paths named
#     that are not in the repository on purpose (install-prefix paths), with reasons.
# DOCROOT (default ROOT; the self-test's planted copies): where README.md and the *.md
# documents are read from; the code and the named paths are always ROOT's.
# Prints each offence as "FILE: what"; exit 1 if there is any.
set -u
root=${1:-.}
cd "$root" || exit 2
docroot=${2:-}
fail=0
bad() { echo "$*"; fail=1; }

# --- 1. workstation types ---------------------------------------------------------
# The drivers in the list's rows, then each driver's type number: its source defines it
# either as ".type = GWS_TYPE_X" or through a macro call naming the driver and
# GWS_TYPE_X (e.g. CAIRO_DRIVER(gks_ws_pdf_driver, GWS_TYPE_PDF, ...)).
drivers=$(grep -E '^GKS_WS_DRIVER\(' src/c/ws/ws_drivers.def |
          grep -oE 'gks_ws_[a-z0-9_]+_driver')
[ -n "$drivers" ] || bad "src/c/ws/ws_drivers.def: no GKS_WS_DRIVER row found"
for d in $drivers; do
    src=$(grep -lE "gks_ws_driver +$d\b|^[A-Z_]+\( *$d\b" src/c/ws/*/*.c | head -n 1)
    if [ -z "$src" ]; then bad "$d: no definition found under src/c/ws"; continue; fi
    # the definition: its line and the two after; it names the type or its description
    def=$(grep -A2 -E "gks_ws_driver +$d\b|^[A-Z_]+\( *$d\b" "$src")
    cname=$(echo "$def" | grep -oE 'GWS_TYPE_[A-Z0-9_]+' | head -n 1)
    if [ -z "$cname" ]; then
        desc=$(echo "$def" | grep -oE '[a-z0-9_]+_desc\b' | head -n 1)
        [ -n "$desc" ] && cname=$(grep -A2 -E "gks_ws_desc +$desc\b" "$src" |
                                  grep -oE 'GWS_TYPE_[A-Z0-9_]+' | head -n 1)
    fi
    num=$(grep -oE "\b$cname *= *[0-9]+" include/gks.h | grep -oE '[0-9]+$')
    if [ -z "$num" ]; then bad "include/gks.h: $cname ($d) has no value"; continue; fi
    fname=$(grep -E '^ +PARAMETER' bindings/fortran/gks3d_par.inc |
            grep -oE "\bGWS[A-Z0-9]*=$num\b" | sed 's/=.*//' | head -n 1)
    if [ -z "$fname" ]; then
        bad "bindings/fortran/gks3d_par.inc: no Fortran constant for type $num ($cname)"
        fname=NONE
    fi
    for doc in README.md docs/WORKSTATIONS.md; do
        grep -qE "^\| *$num *\| *\`$cname\` *\| *\`$fname\` *\|" "${docroot:-.}/$doc" ||
            bad "$doc: no table row \"| $num | \`$cname\` | \`$fname\` |\""
    done
done

# --- 2. GKS_WITH_* options in the README -----------------------------------------
for opt in $(grep -rhoE 'option\( *GKS_WITH_[A-Z0-9_]+' --include=CMakeLists.txt \
                 --include='*.cmake' CMakeLists.txt cmake src bindings bench tests 2>/dev/null |
             sed 's/option( *//' | sort -u); do
    grep -q "\b$opt\b" "${docroot:-.}/README.md" || bad "README.md: option $opt not named"
done

# --- 3. paths named in documents ---------------------------------------------------
allowed=tests/docs/paths_allowed.txt
top='(src|include|docs|tests|bench|scripts|bindings|examples|cmake|\.ci)'
if [ -n "$docroot" ]; then
    docs=$(cd "$docroot" && find . -name '*.md' | sed 's|^\./||')
else
    docs=$(git ls-files '*.md' 2>/dev/null || find . -name '*.md' -not -path './build*')
fi
for doc in $docs; do
    # a path: a top-level folder at a word start (not inside another path or URL)
    grep -oE "(^|[^A-Za-z0-9_./-])$top/[A-Za-z0-9_./*{},+-]*[A-Za-z0-9_*}/]" "${docroot:-.}/$doc" |
        sed -E 's/^[^a-z.]//' | sort -u | while read -r p; do
        q=${p%%#*}
        q=${q%/}
        [ -n "$q" ] || continue
        if [ -f "$allowed" ] && grep -qxF "$q" "$allowed"; then continue; fi
        # shell globbing of * and {a,b} (brace lists expanded by hand)
        case $q in
        *'{'*'}'*)
            pre=${q%%\{*}; rest=${q#*\{}; list=${rest%%\}*}; post=${rest#*\}}
            okb=1
            for alt in $(echo "$list" | tr ',' ' '); do
                ls -d $pre$alt$post >/dev/null 2>&1 || okb=0
            done
            [ $okb = 1 ] && continue ;;
        esac
        # shellcheck disable=SC2086
        if ls -d $q >/dev/null 2>&1; then continue; fi
        # or relative to the document's own folder (docs/man/README.md names src/names.txt)
        # shellcheck disable=SC2086
        if ls -d "${docroot:-.}/$(dirname "$doc")"/$q >/dev/null 2>&1; then continue; fi
        found=0
        for ext in c f sh cpp; do
            # shellcheck disable=SC2086
            if ls -d $q.$ext >/dev/null 2>&1; then found=1; break; fi
        done
        [ $found = 1 ] && continue
        echo "$doc: names $p, which does not exist"
        echo x >> "${TMPDIR:-/tmp}/check_docs.$$"
    done
done
if [ -f "${TMPDIR:-/tmp}/check_docs.$$" ]; then fail=1; rm -f "${TMPDIR:-/tmp}/check_docs.$$"; fi

if [ $fail = 0 ]; then echo "check_docs: all documents agree with the code"; fi
exit $fail
