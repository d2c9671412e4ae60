#!/bin/sh
# SPDX-License-Identifier: MIT
# check_functions_md.sh SOURCE_DIR OUT -- fails when docs/FUNCTIONS.md is not what
# scripts/gen_functions.sh generates now (regenerate with
# `scripts/gen_functions.sh > docs/FUNCTIONS.md`). OUT: where the fresh copy is written.
set -eu
sh "$1/scripts/gen_functions.sh" "$1" > "$2"
if ! diff -u "$1/docs/FUNCTIONS.md" "$2"; then
    echo "docs/FUNCTIONS.md is stale: run scripts/gen_functions.sh > docs/FUNCTIONS.md" >&2
    exit 1
fi
