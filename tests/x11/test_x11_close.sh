#!/bin/sh
# SPDX-License-Identifier: MIT
# Closes the X11 workstation's window under Xvfb while a REQUEST waits (issue 40 G): by
# WM_DELETE_WINDOW as a window manager does, by destroying it from another client, and by
# killing its connection (xkill). x11_close checks what follows. Skipped (exit 77) with a
# message when Xvfb, xdotool or xkill is missing.
# Usage: test_x11_close.sh <x11_close> <workdir> <xclose>
prog=$1
dir=$2
xclose=$3
. "$(dirname "$0")/xvfb.sh"
xvfb_need Xvfb xdotool xkill
mkdir -p "$dir" && cd "$dir" || exit 1
xvfb_start
for how in wmdelete destroy xkill; do
    rm -f out.txt
    "$prog" >out.txt 2>&1 &
    ppid=$!
    i=0
    while ! grep -q READY out.txt 2>/dev/null; do
        i=$((i + 1)); [ $i -gt 1200 ] && { cat out.txt; echo "FAIL: $how: no window"; exit 1; }
        sleep 0.1
    done
    w=$(xdotool search --sync --name gks3d | head -1)
    i=0 # the REQUEST waits once the title names it
    while [ "$(xdotool getwindowname "$w" 2>/dev/null)" != "gks3d: REQUEST LOCATOR 1" ]; do
        i=$((i + 1)); [ $i -gt 1200 ] && { cat out.txt; echo "FAIL: $how: no REQUEST"; exit 1; }
        sleep 0.1
    done
    case $how in
    xkill) xkill -id "$w" >/dev/null 2>&1 ;;
    *) "$xclose" $how "$w" ;;
    esac
    i=0 # the program ends by itself (80 s at most, on a loaded machine)
    while kill -0 $ppid 2>/dev/null; do
        i=$((i + 1))
        if [ $i -gt 800 ]; then
            kill $ppid; cat out.txt; echo "FAIL: $how: the REQUEST did not end"; exit 1
        fi
        sleep 0.1
    done
    wait $ppid
    rc=$?
    echo "$how: exit status $rc: $(tr '\n' ' ' < out.txt)"
    grep -q "X11 CLOSE PASS" out.txt || echo "FAIL: $how"
done
