#!/bin/sh
# SPDX-License-Identifier: MIT
# check_spdx.sh [SOURCE_DIR] -- every source file of the project carries an SPDX licence
# line within its first 3 lines (after a shebang or an opening comment line). Source files
# are C (.c .h .def), Fortran (.f .f90 .inc), CMake (CMakeLists.txt .cmake .cmake.in),
# pkg-config templates (.pc.in), shell (.sh, .ci/run), Python (.py) and gnuplot (.gp).
# tests/data (third-party data with its own terms) is not source and is skipped.
# Files are those known to git when SOURCE_DIR is a git checkout, else all files found;
# CMake build trees inside the source tree (any folder holding a CMakeCache.txt) are skipped.
# Prints every offending file and exits 1 when there is one.
set -eu
src=${1:-$(cd "$(dirname "$0")/../.." && pwd)}
cd "$src"
top=$(git rev-parse --show-toplevel 2>/dev/null || true)
if [ -n "$top" ] && [ "$(cd "$top" && pwd -P)" = "$(pwd -P)" ]; then
    list() { git ls-files --cached --others --exclude-standard; }
else
    list() { find . -path ./.git -prune -o -path './build*' -prune -o -type f -print | sed 's|^\./||'; }
fi
tmp=$(mktemp)
builds=$(mktemp)
trap 'rm -f "$tmp" "$builds"' EXIT
find . -path ./.git -prune -o -name CMakeCache.txt -type f -print |
    sed 's|^\./||; s|CMakeCache\.txt$||' >"$builds"
list | while IFS= read -r f; do
    skip=0
    while IFS= read -r b; do
        [ -n "$b" ] && case $f in "$b"*) skip=1; break ;; esac
    done <"$builds"
    [ "$skip" = 0 ] || continue
    case $f in
    tests/data/*) continue ;;
    *.c | *.h | *.def | *.f | *.f90 | *.inc | CMakeLists.txt | */CMakeLists.txt | *.cmake | \
        *.cmake.in | *.pc.in | *.sh | *.py | *.gp | .ci/run) ;;
    *) continue ;;
    esac
    [ -f "$f" ] || continue # deleted in the work tree but still in the index
    head -n 3 "$f" | grep -q 'SPDX-License-Identifier: MIT' || echo "$f" >>"$tmp"
done
n=$(wc -l <"$tmp")
if [ "$n" -gt 0 ]; then
    echo "check_spdx: $n source file(s) without 'SPDX-License-Identifier: MIT' in the first 3 lines:"
    sed 's/^/  /' "$tmp"
    echo "check_spdx: add the line at the top (C: /* SPDX-License-Identifier: MIT */," \
         "CMake/shell/Python: # SPDX-License-Identifier: MIT, after a shebang;" \
         "fixed-form Fortran: C     SPDX-License-Identifier: MIT; .f90/.inc: ! ...)"
    exit 1
fi
echo "check_spdx: every source file carries the MIT SPDX line"
