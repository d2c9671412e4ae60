#!/bin/sh
# SPDX-License-Identifier: MIT
# check_mf_items_selftest.sh SRC_DIR WORK_DIR [CC GENERATED_INCLUDE_DIR] -- check_mf_items.sh
# must fail on copies of the sources broken in each way it checks; with a compiler, the
# build's check (src/c/core/store/gks_mf_check.c) must compile on the sources and fail on
# copies whose metafile column contradicts the item table, and a typed hook called with
# wrong arguments must not compile.
set -eu
src=$1 work=$2 cc=${3:-} gen=${4:-}
check=$src/tests/core/check_mf_items.sh
copy() {
    rm -rf "$work"
    mkdir -p "$work/src/c/core/store" "$work/include"
    cp -R "$src/src/c/core/api" "$work/src/c/core/"
    cp "$src/src/c/core/store/gks_mf_items.def" "$src/src/c/core/store/gks_mf_items.h" \
       "$src/src/c/core/store/gks_mf_check.c" "$work/src/c/core/store/"
    cp "$src/include/gks_functions.def" "$src/include/gks.h" "$work/include/"
}
def=$work/include/gks_functions.def
expect_fail() {
    if sh "$check" "$work" >/dev/null 2>&1; then
        echo "selftest: the check passed on a broken copy ($1)" >&2
        exit 1
    fi
}
copy
sh "$check" "$work" >/dev/null
# 1. SET HLHSR MODE's hook removed: its column and row name a function that records nothing.
sed -i '/GKS_MF_WS(SHRM/d' "$work/src/c/core/api/gks_view.c"
expect_fail "column MF_ITEM without a hook"
# 2. CREATE SEGMENT's row removed: its hook and column name no row.
copy
sed -i '/^GKSM_ITEM(81,/d' "$work/src/c/core/store/gks_mf_items.def"
expect_fail "hook without row"
# 3. SET EDGE REPRESENTATION neither recorded nor in the table, its column MF_NO.
copy
sed -i '/^GKSM_ITEM(57,/,/^GKSM_ITEM(58,/{/^GKSM_ITEM(58,/!d}' "$work/src/c/core/store/gks_mf_items.def"
sed -i '/GKS_MF_WS(SEDR/d' "$work/src/c/core/api/gks_attr.c"
sed -i 's/MF_ITEM(EDGE_REP))/MF_NO)/' "$def"
expect_fail "representation not recorded"
# 4. Two rows with one number.
copy
sed -i 's/^GKSM_ITEM(95,/GKSM_ITEM(94,/' "$work/src/c/core/store/gks_mf_items.def"
expect_fail "item number twice"
# 5. CLEAR WORKSTATION records its item, but its column says nothing is recorded.
copy
sed -i 's/MF_ITEM(CLEAR))/MF_NO)/' "$def"
expect_fail "hook in a function whose column is MF_NO"
# 6. A new function without a metafile column.
copy
sed -i 's/^GKS_FN(196,.*/&\nGKS_FN(197, XNEW,  "NEW FUNCTION", GKS_S_OPEN)/' "$def"
expect_fail "function row without a metafile column"
# 7. SET LINETYPE's column names a workstation item, not an attribute.
copy
sed -i 's/MF_STATE(LINETYPE))/MF_STATE(LINE_REP))/' "$def"
expect_fail "MF_STATE of an item of another kind"
# 8. The LINETYPE attribute item claimed by no function.
copy
sed -i 's/MF_STATE(LINETYPE))/MF_NO)/' "$def"
expect_fail "attribute item named by no column"
# 9. UPDATE WORKSTATION's column names the item of CLEAR WORKSTATION.
copy
sed -i 's/MF_ITEM(UPDATE))/MF_ITEM(CLEAR))/' "$def"
expect_fail "MF_ITEM of another function's item"
# 10. WRITE ITEM TO GKSM writes user items, its column says nothing.
copy
sed -i 's/MF_USER)/MF_NO)/' "$def"
expect_fail "user items under MF_NO"
# 11. SET WORKSTATION WINDOW hands its helper another function's item: it records nothing.
copy
sed -i "s/gks_mf_ws_rec_SWKWN,/gks_mf_ws_rec_SWKVP,/" "$work/src/c/core/api/gks_transform.c"
expect_fail "item handed to a helper, but another function's"
msg="11 broken copies refused"
if [ -n "$cc" ]; then
    compile() {
        "$cc" -std=c11 -Wall -Wextra -Werror -DGKS3D_BUILDING -fsyntax-only \
            -I"$work/src/c/core/store" -I"$work/include" -I"$src/src/c/base" -I"$gen" \
            "$work/src/c/core/store/gks_mf_check.c"
    }
    compile_fail() {
        if compile >/dev/null 2>&1; then
            echo "selftest: gks_mf_check.c compiled on a broken copy ($1)" >&2
            exit 1
        fi
    }
    copy
    compile
    sed -i 's/MF_ITEM(CLEAR))/MF_NO)/' "$def"
    compile_fail "a hooked function's column MF_NO"
    copy
    sed -i 's/MF_ITEM(UPDATE))/MF_ITEM(CLEAR))/' "$def"
    compile_fail "MF_ITEM of another function's item"
    copy
    sed -i 's/MF_STATE(LINETYPE))/MF_STATE(LINE_REP))/' "$def"
    compile_fail "MF_STATE of an item of another kind"
    copy
    sed -i 's/MF_PRIM(TEXT3))/MF_PRIM(NO_SUCH_ITEM))/' "$def"
    compile_fail "MF_PRIM of no item"
    msg="$msg, 4 broken copies do not compile"
    # The typed hooks (gks_mf_record.h, generated from the table's formats): the right
    # arguments compile, a pointer for an int or a missing value do not.
    hook() {
        mkdir -p "$work"
        printf '#include "gks_mf_record.h"\nint hook(void) { %s }\n' "$1" > "$work/hook.c"
        "$cc" -std=c11 -Wall -Wextra -Werror -DGKS3D_BUILDING -fsyntax-only \
            -I"$src/src/c/core/store" -I"$src/src/c/core" -I"$src/src/c/base" \
            -I"$src/src/c/ws" -I"$src/src/c/ws/mf" -I"$src/src/c/xform" \
            -I"$src/src/c/raster" -I"$src/include" -I"$gen" "$work/hook.c"
    }
    hook 'return gks_mf_rec_CRSG(0, 1) + gks_mf_ws_rec_SCR(0, 1, 2, 0.1, 0.2, 0.3);'
    for bad in 'static const double m[12]; return gks_mf_rec_CRSG(0, m);' \
               'return gks_mf_ws_rec_SCR(0, 1, 2, 0.1, 0.2);'; do
        if hook "$bad" >/dev/null 2>&1; then
            echo "selftest: a hook call with wrong arguments compiled: $bad" >&2
            exit 1
        fi
    done
    msg="$msg, 2 wrong hook calls do not compile"
fi
rm -rf "$work"
echo "check_mf_items selftest: $msg"
