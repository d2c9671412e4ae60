#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# check_man.sh -- every function of both bindings has a reference page, and every page
# renders without a warning.
#   C functions:        the GKS_API prototypes of include/gks.h
#   FORTRAN 77 names:   the exported names of libgks3d_fortran (the version script the
#                       build writes, MAP) or, without it, the FNAME(lower, UPPER) pairs and
#                       SUBROUTINEs of bindings/fortran (as bindings/fortran/CMakeLists.txt)
# Each name needs MANDIR/man3/<name>.3 (Fortran names in lower case; GGDP shares ggdp.3,
# which must name it), and man3 may hold
# nothing else (page count = function count). Every page of man1, man3 and man7 is rendered
# from MANDIR (so that the .so links resolve as they do when installed) through the pipeline
# that `man --warnings=w -l` runs (preconv, tbl, groff -mandoc -ww -Tutf8), groff called
# directly (a third of man's time a page); any diagnostic fails. A page that is only a .so
# link to another page (most of man3: the Fortran names and the variants of a function)
# would render as that page does: its target must be a page of the three sections that is
# rendered itself, and then is not rendered twice.
# Usage: scripts/check_man.sh [--pages | --render] [SOURCE_DIR [MANDIR [MAP]]]
#   --pages   only the pages' presence (ctest docs_man_pages: depends on the build's options)
#   --render  only the rendering (ctest docs_man_render: the same in every build)
set -euo pipefail
what=all
case ${1:-} in
    --pages) what=pages; shift ;;
    --render) what=render; shift ;;
esac
src=${1:-$(dirname "$0")/..}
mandir=${2:-$src/docs/man}
map=${3:-}
export LC_ALL=C.UTF-8
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

status=0
if [ $what != render ]; then
    grep -oE 'GKS_API +[^(;]*[ *]g[a-z0-9_]+ *\(' "$src/include/gks.h" |
        sed -E 's/.*[ *](g[a-z0-9_]+) *\($/\1/' | sort -u > "$tmp/c"
    if [ -n "$map" ] && [ -f "$map" ]; then
        # the version script: "    gopks_;" (mangled as this compiler does: lower case here)
        sed -nE 's/^ +([A-Za-z0-9_]+);$/\1/p' "$map" | sed -E 's/_+$//' | tr A-Z a-z |
            sort -u > "$tmp/f"
        from="the version script $map"
    else
        { cat "$src"/bindings/fortran/*.c | grep -oE '\([a-z][a-z0-9]*, *[A-Z][A-Z0-9]*[,)]' |
              sed -E 's/^\(([a-z0-9]+), *([A-Z0-9]+).$/\1 \2/' |
              awk 'toupper($1) == $2 { print $1 }'
          for f in "$src"/bindings/fortran/ger*.f; do
              grep -ioE '^      subroutine +g[a-z0-9]+' "$f" | awk '{ print tolower($2) }'
          done; } | grep -v '^gkunam$' | sort -u > "$tmp/f"
        from="bindings/fortran"
    fi
    nc=$(wc -l < "$tmp/c")
    nf=$(wc -l < "$tmp/f")
    # A Fortran name equal to a C name (GGDP, ggdp) shares its page: the page must name both.
    shared=$(comm -12 "$tmp/c" "$tmp/f")
    for n in $shared; do
        up=$(echo "$n" | tr a-z A-Z)
        page="$mandir/man3/$n.3"
        target=$(sed -n '1s/^\.so //p' "$page") # a .so link: the page it names
        [ -z "$target" ] || page="$mandir/$target"
        if ! sed -n '/^\.SH NAME/{n;p;}' "$page" | grep -qw "$up"; then
            echo "check_man: $n.3 is the page of C $n and Fortran $up but does not name $up"
            status=1
        fi
    done
    sort -u "$tmp/c" "$tmp/f" > "$tmp/all"
    (cd "$mandir/man3" && ls) | sed -E 's/\.3$//' | sort > "$tmp/pages"
    missing=$(comm -23 "$tmp/all" "$tmp/pages")
    extra=$(comm -13 "$tmp/all" "$tmp/pages")
    [ -z "$missing" ] || { echo "check_man: functions without a page:" $missing; status=1; }
    [ -z "$extra" ] || { echo "check_man: pages of no function:" $extra; status=1; }
    np=$(wc -l < "$tmp/pages")
    ns=$(echo $shared | wc -w)
    echo "check_man: $nc C functions (include/gks.h), $nf FORTRAN 77 functions ($from), $ns names in both ($(echo $shared)), $np pages in man3 (= $nc + $nf - $ns)"
fi
[ $what != pages ] || exit $status

# The groff command of man-db's pipeline for `man --warnings=w -E UTF-8 -l` (seen with strace):
# preconv -e UTF-8 (-K utf8), tbl (-t), -mtty-char -mandoc -ww -Tutf8; the output is not kept.
render() {
    groff -K utf8 -t -mtty-char -mandoc -ww -Tutf8 "$1" 2>&1 > /dev/null || echo "groff failed"
}
cd "$mandir"
# First the links: a page of the one line ".so manN/target.N" (read in bash: 566 of them).
pages=()
declare -A link
for page in man1/*.1 man3/*.3 man7/*.7; do
    [ -e "$page" ] || continue # no man1 in a build without the programs
    pages+=("$page")
    mapfile -t lines < "$page"
    if [ ${#lines[@]} = 1 ] && [[ ${lines[0]} =~ ^\.so\ (man[137]/[^\ /]+\.[137])$ ]]; then
        link[$page]=${BASH_REMATCH[1]}
    fi
done
nr=0
nl=0
for page in "${pages[@]}"; do
    # A link to a page that exists and is rendered itself (not a link again) is not rendered.
    target=${link[$page]:-}
    if [ -n "$target" ] && [ -f "$target" ] && [ -z "${link[$target]:-}" ]; then
        nl=$((nl + 1))
        continue
    fi
    out=$(render "$page")
    if [ -n "$out" ]; then
        echo "check_man: $page: $out"
        status=1
    fi
    nr=$((nr + 1))
done
echo "check_man: $nr pages rendered with groff -ww -mandoc -Tutf8 (as man --warnings=w -l)," \
     "$nl .so links to them, status $status"
exit $status
