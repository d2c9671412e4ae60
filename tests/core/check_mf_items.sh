#!/bin/sh
# SPDX-License-Identifier: MIT
# check_mf_items.sh SRC_DIR -- the metafile item table (src/c/core/store/gks_mf_items.def)
# against the function list (include/gks_functions.def) and the recording hooks in
# src/c/core/api: every function a row names exists, every REC row's function calls its
# hook, every hook's function has a row, item numbers are unique, and every SET ...
# REPRESENTATION function is recorded. (A hook whose function has no row does not compile
# either: GKSM_FN_<SYM> is generated from the rows.)
set -eu
src=${1:?usage: check_mf_items.sh SRC_DIR}
items=$src/src/c/core/store/gks_mf_items.def
fns=$src/include/gks_functions.def
api=$src/src/c/core/api
fail=0
err() { echo "check_mf_items: $*" >&2; fail=1; }

# Rows: "type name kind key" (continuation lines and comments ignored).
rows=$(sed -n 's/^GKSM_ITEM(\([0-9]*\), *\([A-Z0-9_]*\), *\([A-Z_]*\), *\([A-Za-z0-9_]*\),.*/\1 \2 \3 \4/p' "$items")
also=$(sed -n 's/^GKSM_ALSO(\([A-Z0-9_]*\), *\([A-Z0-9_]*\), *\([A-Z_]*\)).*/\1 \2 \3/p' "$items")
[ -n "$rows" ] || err "no rows read from $items"

dups=$(echo "$rows" | awk '{print $1}' | sort | uniq -d)
[ -z "$dups" ] || err "item numbers used twice: $dups"

hooks=$(grep -ho 'GKS_MF\(_WS\)\?0\?(\([A-Z0-9_]*\)' "$api"/*.c | sed 's/.*(//' | sort -u)
esc_hooks=$(grep -ho 'gks_mf_escape(GFN_[A-Z0-9_]*' "$api"/*.c | sed 's/.*GFN_//' | sort -u)

recorded=$(printf '%s\n%s\n' "$(echo "$rows" | awk '$3 ~ /^REC_/ {print $4}')" \
                              "$(echo "$also" | awk '{print $1}')" | sed '/^$/d' | sort -u)
for key in $recorded; do
    grep -q "^GKS_FN([0-9 ]*, *$key," "$fns" || err "row names $key, not in gks_functions.def"
done
for key in $(echo "$rows" | awk '$3 == "REC_WS" || $3 == "REC_ALL" {print $4}') \
           $(echo "$also" | awk '{print $1}'); do
    echo "$hooks" | grep -qx "$key" || err "$key has an item row but calls no GKS_MF hook"
done
for key in $(echo "$rows" | awk '$3 == "REC_OWN" {print $4}'); do
    echo "$esc_hooks" | grep -qx "$key" || err "$key (REC_OWN) is never recorded"
done
for key in $hooks $esc_hooks; do
    echo "$recorded" | grep -qx "$key" || err "$key is recorded but has no item row"
done
# Every SET ... REPRESENTATION (a workstation table entry) is part of the picture.
for key in $(sed -n 's/^GKS_FN([0-9 ]*, *\([A-Z0-9_]*\), *"SET [A-Z0-9 ]*REPRESENTATION[ 3]*".*/\1/p' "$fns"); do
    echo "$recorded" | grep -qx "$key" || err "$key (a REPRESENTATION) has no item row"
done
n=$(echo "$rows" | wc -l)
[ $fail -eq 0 ] && echo "check_mf_items: $n items, $(echo "$recorded" | wc -l) recording functions: consistent"
exit $fail
