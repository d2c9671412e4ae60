#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs x11_background under its own Xvfb; skipped (exit 77) when Xvfb is missing.
# Usage: test_x11_bg.sh <x11_background> <workdir>
prog=$1
dir=$2
. "$(dirname "$0")/xvfb.sh"
xvfb_need Xvfb
mkdir -p "$dir" && cd "$dir" || exit 1
xvfb_start
"$prog"
