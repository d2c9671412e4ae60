#!/bin/sh
# SPDX-License-Identifier: MIT
# check_mf_items_selftest.sh SRC_DIR WORK_DIR -- check_mf_items.sh must fail on a copy of
# the sources with a row whose function records nothing, with a hook whose function has no
# row, and with a representation function left out of the table.
set -eu
src=$1 work=$2
check=$src/tests/core/check_mf_items.sh
copy() {
    rm -rf "$work"
    mkdir -p "$work/src/c/core/store" "$work/include"
    cp -R "$src/src/c/core/api" "$work/src/c/core/"
    cp "$src/src/c/core/store/gks_mf_items.def" "$work/src/c/core/store/"
    cp "$src/include/gks_functions.def" "$work/include/"
}
expect_fail() {
    if sh "$check" "$work" >/dev/null 2>&1; then
        echo "selftest: the check passed on a broken copy ($1)" >&2
        exit 1
    fi
}
copy
sh "$check" "$work" >/dev/null
# 1. SET HLHSR MODE's hook removed: its row names a function that records nothing.
sed -i '/GKS_MF_WS(SHRM/d' "$work/src/c/core/api/gks_view.c"
expect_fail "row without hook"
# 2. CREATE SEGMENT's row removed: its hook has no item.
copy
sed -i '/^GKSM_ITEM(81,/d' "$work/src/c/core/store/gks_mf_items.def"
expect_fail "hook without row"
# 3. SET EDGE REPRESENTATION neither recorded nor in the table.
copy
sed -i '/^GKSM_ITEM(57,/,/^GKSM_ITEM(58,/{/^GKSM_ITEM(58,/!d}' "$work/src/c/core/store/gks_mf_items.def"
sed -i '/GKS_MF_WS(SEDR/d' "$work/src/c/core/api/gks_attr.c"
expect_fail "representation not recorded"
# 4. Two rows with one number.
copy
sed -i 's/^GKSM_ITEM(95,/GKSM_ITEM(94,/' "$work/src/c/core/store/gks_mf_items.def"
expect_fail "item number twice"
rm -rf "$work"
echo "check_mf_items selftest: 4 broken copies refused"
