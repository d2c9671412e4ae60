#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs x11_background under its own Xvfb; skipped (exit 77) when Xvfb is missing.
# Usage: test_x11_bg.sh <x11_background> <workdir>
prog=$1
dir=$2
if ! command -v Xvfb >/dev/null 2>&1; then
    echo "SKIP: Xvfb not installed (scripts/setup.sh installs it)"
    exit 77
fi
mkdir -p "$dir" && cd "$dir" || exit 1
rm -f display.txt
Xvfb -displayfd 3 -screen 0 1024x1024x24 -nolisten tcp 3>display.txt >xvfb.log 2>&1 &
xpid=$!
trap 'kill $xpid 2>/dev/null' EXIT
i=0
while [ ! -s display.txt ]; do
    i=$((i + 1)); [ $i -gt 100 ] && { echo "SKIP: Xvfb did not start"; exit 77; }
    sleep 0.1
done
DISPLAY=:$(cat display.txt) "$prog"
