#!/usr/bin/env bash
# run-examples.sh -- set up, build (Release, ./build), run the example programs in
# build/pictures and print the absolute paths of the PNG files they wrote.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGKS_BUILD_EXAMPLES=ON -DBUILD_TESTING=OFF
cmake --build build -j2

# Example programs: the known ones first, then any other executable under build/examples.
known=(hello_c hello_f77)
progs=()
for name in "${known[@]}"; do
    f=$(find build/examples -type f -name "$name" -perm -u+x 2>/dev/null | head -n 1)
    [ -n "$f" ] && progs+=("$root/$f")
done
while IFS= read -r f; do
    case " ${known[*]} " in *" $(basename "$f") "*) continue ;; esac
    progs+=("$root/$f")
done < <(find build/examples -type f -perm -u+x ! -name '*.so*' ! -name '*.sh' ! -path '*/CMakeFiles/*' | sort)
[ ${#progs[@]} -gt 0 ] || { echo "run-examples: no example programs found" >&2; exit 1; }

out=$root/build/pictures
rm -rf "$out"
mkdir -p "$out"
for p in "${progs[@]}"; do
    echo "run-examples: running $(basename "$p")"
    (cd "$out" && "$p")
done
echo "run-examples: pictures written:"
n=0
while IFS= read -r f; do echo "  $f"; n=$((n + 1)); done < <(find "$out" -name '*.png' | sort)
[ "$n" -gt 0 ] || { echo "run-examples: no PNG file written" >&2; exit 1; }
