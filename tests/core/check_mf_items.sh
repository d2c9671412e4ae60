#!/bin/sh
# SPDX-License-Identifier: MIT
# check_mf_items.sh SRC_DIR -- what the metafile records, three ways: the metafile column of
# every function (include/gks_functions.def), the item table
# (src/c/core/store/gks_mf_items.def) and the recording hooks in src/c/core/api. Fails when
# a function row has no metafile column; a column names an item that is not in the table,
# or one of another kind or function; a function whose column is MF_ITEM calls no hook; a
# hook, an ESCAPE encoder or a user-item writer sits in a function whose column does not
# say so; an attribute, state or primitive row is named by no column; item numbers repeat;
# or a SET ... REPRESENTATION is not recorded by a hook. (The build checks the column
# against the rows too: src/c/core/store/gks_mf_check.c.)
set -eu
src=${1:?usage: check_mf_items.sh SRC_DIR}
items=$src/src/c/core/store/gks_mf_items.def
fns=$src/include/gks_functions.def
api=$src/src/c/core/api
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Rows "R type name kind key" and "A key name kind" (GKSM_ALSO); continuation lines and
# comments are ignored.
sed -n 's/^GKSM_ITEM(\([0-9]*\), *\([A-Z0-9_]*\), *\([A-Z_]*\), *\([A-Za-z0-9_]*\),.*/R \1 \2 \3 \4/p' \
    "$items" > "$tmp/in"
sed -n 's/^GKSM_ALSO(\([A-Z0-9_]*\), *\([A-Z0-9_]*\), *\([A-Z_]*\)[,)].*/A \1 \2 \3/p' "$items" >> "$tmp/in"
# Functions "F sym column": the column as written, or "none" for a row without one.
grep -E '^GKS_FN\(' "$fns" | sed -E \
    -e 's/^GKS_FN\( *[0-9]+, *([A-Z0-9_]+), *"[^"]*", *[^,]*, *(MF_[A-Z]+(\([A-Z0-9_]+\))?) *\) *$/F \1 \2/; t' \
    -e 's/^GKS_FN\( *[0-9]+, *([A-Z0-9_]+),.*/F \1 none/' >> "$tmp/in"
# Hooks "H sym" (GKS_MF*, or GKSM_FN_sym / the typed hook gks_mf_(ws_)rec_sym: what a
# function hands to a shared helper that records it), ESCAPE encoders "E sym", user-item
# writers "U sym".
grep -ho 'GKS_MF\(_WS\)\?0\?([A-Z0-9_]*' "$api"/*.c | sed 's/.*(/H /' | sort -u >> "$tmp/in"
grep -ho 'GKSM_FN_[A-Z0-9_]*' "$api"/*.c | sed 's/GKSM_FN_/H /' | sort -u >> "$tmp/in"
grep -ho 'gks_mf_\(ws_\)\?rec_[A-Z0-9_]*' "$api"/*.c | sed 's/gks_mf_\(ws_\)\?rec_/H /' | sort -u \
    >> "$tmp/in"
grep -ho 'gks_mf_escape(GFN_[A-Z0-9_]*' "$api"/*.c | sed 's/.*GFN_/E /' | sort -u >> "$tmp/in"
grep -ho 'gks_mf_user_item(GFN_[A-Z0-9_]*' "$api"/*.c | sed 's/.*GFN_/U /' | sort -u >> "$tmp/in"
# Every SET ... REPRESENTATION (a workstation table entry) is part of the picture: "P sym".
sed -n 's/^GKS_FN([0-9 ]*, *\([A-Z0-9_]*\), *"SET [A-Z0-9 ]*REPRESENTATION[ 3]*".*/P \1/p' "$fns" \
    >> "$tmp/in"

awk '
function err(m) { print "check_mf_items: " m > "/dev/stderr"; bad = 1 }
$1 == "R" { n++; if ($2 in num) err("item number " $2 " used twice"); num[$2] = 1
            kind[$3] = $4; key[$3] = $5; if ($4 ~ /^REC_/) rec[$5 ":" $3] = $4 }
$1 == "A" { rec[$2 ":" $3] = $4; also[$2 ":" $3] = 1 }
$1 == "F" { nf++; col[$2] = $3; order[nf] = $2 }
$1 == "H" { hook[$2] = 1 }
$1 == "E" { esc[$2] = 1 }
$1 == "U" { user[$2] = 1 }
$1 == "P" { rep[$2] = 1 }
END {
    if (n == 0) err("no rows read from the item table")
    if (nf == 0) err("no function rows read from gks_functions.def")
    for (i = 1; i <= nf; i++) {
        s = order[i]; c = col[s]
        if (c == "none") { err(s ": no metafile column (MF_NO, MF_ITEM(item), ...)"); continue }
        if (c !~ /^MF_(NO|PRIMS|USER|(ITEM|STATE|PRIM)\([A-Z0-9_]+\))$/) { err(s ": metafile column " c "?"); continue }
        it = c; sub(/^MF_[A-Z]+\(/, "", it); sub(/\)$/, "", it)
        if (c ~ /^MF_ITEM\(/) {
            recorded++
            if (!((s ":" it) in rec)) err(s ": " c ", but the row of item " it " (or a GKSM_ALSO) does not name " s)
            else if (rec[s ":" it] == "REC_OWN" ? !(s in esc) : !(s in hook)) err(s ": " c ", but " s " calls no recording hook")
        } else if (c ~ /^MF_STATE\(/) {
            recorded++; claimed["S:" it] = 1
            if (kind[it] != "ATTR" && kind[it] != "STATE") err(s ": " c " is not an ATTR or STATE row of the item table")
        } else if (c ~ /^MF_PRIM\(/) {
            recorded++; claimed["P:" it] = 1
            if (kind[it] != "PRIM") err(s ": " c " is not a PRIM row of the item table")
        } else if (c != "MF_NO") {
            recorded++
        }
        if (c == "MF_USER" && !(s in user)) err(s ": MF_USER, but it writes no user item")
        if ((s in user) && c != "MF_USER") err(s " writes user items, but its column is " c)
        if (((s in hook) || (s in esc)) && c !~ /^MF_ITEM\(/) err(s " records an item (hook), but its column is " c)
        if ((s in rep) && c !~ /^MF_ITEM\(/) err(s " (a REPRESENTATION) is not recorded by a hook")
    }
    for (r in rec) {
        split(r, a, ":")
        if (!(a[1] in col)) err("item " a[2] " names " a[1] ", not in gks_functions.def")
        else if (col[a[1]] != "MF_ITEM(" a[2] ")") err(a[1] " writes item " a[2] " (its row), but its column is " col[a[1]])
    }
    for (it in kind) {
        if ((kind[it] == "ATTR" || kind[it] == "STATE") && !(("S:" it) in claimed))
            err("item " it " (" kind[it] ") is named by no function column")
        if (kind[it] == "PRIM" && !(("P:" it) in claimed))
            err("item " it " (PRIM) is named by no function column")
    }
    if (!bad) printf "check_mf_items: %d items, %d functions, %d recorded: consistent\n", n, nf, recorded
    exit bad
}' "$tmp/in"
