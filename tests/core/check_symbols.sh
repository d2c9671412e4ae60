#!/bin/sh
# SPDX-License-Identifier: MIT
# check_symbols.sh LIB LIST -- the shared library exports exactly the intended symbols
# (the public API of gks.h, the binding and test hooks): nothing internal leaks.
set -eu
lib=$1; list=$2
actual=$(nm -D --defined-only "$lib" | awk '$2=="T"{print $3}' | sort)
if [ "$actual" != "$(sort "$list")" ]; then
    echo "exported symbols differ from $list:"
    printf '%s\n' "$actual" | diff "$list" - || true
    exit 1
fi
echo "exported symbols: $(printf '%s\n' "$actual" | wc -l) as intended"
