#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# run-examples.sh -- set up, build (Release, ./build), run the example programs in
# build/pictures and print the absolute paths of the PNG files they wrote.
#
# The paper's pictures (Fig. 2-5) and the surface example run through the C binding into
# build/pictures and through the Fortran 77 binding into build/pictures/f77; the script
# checks that both wrote byte-identical files. The NFF/OFF viewers run on the SPD teapot and
# the bunny mesh of tests/data (gzip-compressed, see tests/data/README.md). Any other example
# program runs without arguments; one that needs arguments is reported and skipped.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGKS_BUILD_EXAMPLES=ON -DBUILD_TESTING=OFF
cmake --build build -j2

ex=$root/build/examples
out=$root/build/pictures
rm -rf "$out"
mkdir -p "$out/f77"

# run DIR PROGRAM [ARGS...]: runs build/examples/PROGRAM in DIR; 1 if it failed.
run() {
    local dir=$1 prog=$2
    shift 2
    local path
    path=$(find "$ex" -type f -name "$prog" -perm -u+x ! -path '*/CMakeFiles/*' | head -n 1)
    if [ -z "$path" ]; then
        echo "run-examples: $prog not built" >&2
        return 1
    fi
    echo "run-examples: running $prog $*"
    (cd "$dir" && "$path" "$@")
}

status=0
# The paper's pictures and the surface, C then Fortran (default size 480 pixels).
twins=(fig2 fig3 fig4 fig5 surface)
for name in "${twins[@]}"; do
    run "$out" "${name}_c" || status=1
    run "$out/f77" "${name}_f77" || status=1
done
same=0 differ=0
for f in "$out"/f77/*.png; do
    [ -e "$f" ] || continue
    if cmp -s "$f" "$out/$(basename "$f")"; then same=$((same + 1)); else differ=$((differ + 1)); fi
done
echo "run-examples: C and Fortran pictures: $same byte-identical, $differ differ"
[ "$differ" -eq 0 ] || status=1

# The first examples.
for prog in hello_c hello_f77 checkerboard_c; do
    run "$out" "$prog" || status=1
done

# Scene viewers on the project's test data.
data=$root/tests/data
run "$out" nff_view --size 384x384 "$data/spd/teapot.nff.gz" "$out/teapot.png" || status=1
run "$out" mesh_view --size 384x384 --ground "$data/meshes/bunny00.off.gz" "$out/bunny.png" ||
    status=1

# Anything else under build/examples: without arguments, skipped when it needs some.
known=" ${twins[*]/%/_c} ${twins[*]/%/_f77} hello_c hello_f77 checkerboard_c nff_view mesh_view "
while IFS= read -r f; do
    name=$(basename "$f")
    case "$known" in *" $name "*) continue ;; esac
    run "$out" "$name" >/dev/null 2>&1 || echo "run-examples: $name needs arguments: skipped"
done < <(find "$ex" -type f -perm -u+x ! -name '*.so*' ! -name '*.a' ! -name '*.sh' \
         ! -path '*/CMakeFiles/*' | sort)

echo "run-examples: pictures written:"
n=0
while IFS= read -r f; do echo "  $f"; n=$((n + 1)); done < <(find "$out" -name '*.png' | sort)
[ "$n" -gt 0 ] || { echo "run-examples: no PNG file written" >&2; exit 1; }
exit "$status"
