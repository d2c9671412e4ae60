#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs x11_input interactively under Xvfb, driven by xdotool; skipped (exit 77) with a
# message when Xvfb or xdotool is missing. Usage: test_x11.sh <x11_input> <workdir>
prog=$1
dir=$2
for t in Xvfb xdotool; do
    if ! command -v $t >/dev/null 2>&1; then
        echo "SKIP: $t not installed (scripts/setup.sh installs it)"
        exit 77
    fi
done
mkdir -p "$dir" && cd "$dir" || exit 1
# A free display number: one whose lock file does not exist.
n=40
while [ -e /tmp/.X$n-lock ]; do n=$((n + 1)); done
Xvfb :$n -screen 0 1024x1024x24 -nolisten tcp >xvfb.log 2>&1 &
xpid=$!
trap 'kill $xpid 2>/dev/null' EXIT
export DISPLAY=:$n
i=0
while ! xdotool getmouselocation >/dev/null 2>&1; do
    i=$((i + 1)); [ $i -gt 50 ] && { echo "SKIP: Xvfb did not start"; exit 77; }
    sleep 0.1
done
"$prog" interactive >out.txt 2>&1 &
ppid=$!
i=0
while ! grep -q READY out.txt 2>/dev/null; do
    i=$((i + 1)); [ $i -gt 100 ] && { cat out.txt; echo "FAIL: no window"; exit 1; }
    sleep 0.1
done
w=$(xdotool search --sync --name gks3d | head -1)
xdotool mousemove --window "$w" 200 600 click 1
sleep 0.3
xdotool mousemove --window "$w" 400 400 click 1
sleep 0.3
xdotool windowfocus --sync "$w" 2>/dev/null
xdotool key --window "$w" 3
sleep 0.3
xdotool type --window "$w" gks
xdotool key --window "$w" Return
sleep 0.3
xdotool key --window "$w" Escape
i=0
while kill -0 $ppid 2>/dev/null; do
    i=$((i + 1)); [ $i -gt 100 ] && { kill $ppid; cat out.txt; echo "FAIL: hung"; exit 1; }
    sleep 0.1
done
wait $ppid
rc=$?
cat out.txt
exit $rc
