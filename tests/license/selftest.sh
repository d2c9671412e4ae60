#!/bin/sh
# SPDX-License-Identifier: MIT
# selftest.sh CHECKER WORK_DIR -- the licence check fails, naming the file, on a tree with a
# source file that lacks the SPDX line, and passes once the line is there.
set -eu
checker=$1 work=$2
rm -rf "$work" && mkdir -p "$work/src/sub" "$work/tests/data"
printf '/* SPDX-License-Identifier: MIT */\nint ok;\n' >"$work/src/ok.c"
printf '#!/bin/sh\n# SPDX-License-Identifier: MIT\n' >"$work/src/run.sh"
printf 'int bad;\n' >"$work/src/sub/bad.c"
printf 'add_library(x x.c)\n' >"$work/src/sub/CMakeLists.txt"
printf 'data, own terms\n' >"$work/tests/data/x.c"
if out=$(sh "$checker" "$work" 2>&1); then
    echo "selftest: the check passed on a tree with unlicensed files:"; echo "$out"; exit 1
fi
for f in src/sub/bad.c src/sub/CMakeLists.txt; do
    echo "$out" | grep -qx "  $f" || { echo "selftest: $f not named:"; echo "$out"; exit 1; }
done
for f in src/ok.c src/run.sh tests/data/x.c; do
    if echo "$out" | grep -q "$f"; then echo "selftest: $f named wrongly:"; echo "$out"; exit 1; fi
done
printf '/* SPDX-License-Identifier: MIT */\nint bad;\n' >"$work/src/sub/bad.c"
printf '# SPDX-License-Identifier: MIT\nadd_library(x x.c)\n' >"$work/src/sub/CMakeLists.txt"
sh "$checker" "$work" >/dev/null || { echo "selftest: the check failed on a licensed tree"; exit 1; }
echo "selftest: the licence check names unlicensed files and passes licensed ones"
