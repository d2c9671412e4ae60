#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs x11_input interactively under Xvfb, driven by xdotool; skipped (exit 77) with a
# message when Xvfb or xdotool is missing. Usage: test_x11.sh <x11_input> <workdir> <xpeek>
prog=$1
dir=$2
peek=$3
. "$(dirname "$0")/xvfb.sh"
xvfb_need Xvfb xdotool
mkdir -p "$dir" && cd "$dir" || exit 1
xvfb_start
"$prog" interactive >out.txt 2>&1 &
ppid=$!
i=0
while ! grep -q READY out.txt 2>/dev/null; do
    i=$((i + 1)); [ $i -gt 400 ] && { cat out.txt; echo "FAIL: no window"; exit 1; }
    sleep 0.1
done
w=$(xdotool search --sync --name gks3d | head -1)
# the window's title names the REQUEST once its prompt and echo are drawn
wait_title() {
    i=0
    while [ "$(xdotool getwindowname "$w" 2>/dev/null)" != "gks3d: REQUEST $1" ]; do
        i=$((i + 1)); [ $i -gt 300 ] && { cat out.txt; echo "FAIL: no REQUEST $1"; exit 1; }
        sleep 0.1
    done
}
xdotool mousemove --window "$w" 200 600 click 1
# PICK echo (prompt/echo type 1): while the pointer is over the detectable square
# (window pixels 320..480 each way, filled red), its outline is drawn 3 pixels wide in
# the highlight colour 00c0ff; away from it the picture is restored. Checked: a pixel on
# the left edge (320, 400) and one inside (350, 450), which stays red (exact colours:
# the overlay is drawn with Xlib, no anti-aliasing).
wait_title "PICK 1"
sleep 0.3
before=$("$peek" "$w" 320 400 350 450 | tr '\n' ' ')
# poll (a loaded machine delays the redraw): until the pixels are $1 or 5 s passed
peek_until() {
    i=0
    while :; do
        got=$("$peek" "$w" 320 400 350 450 | tr '\n' ' ')
        [ "$got" = "$1" ] && break
        i=$((i + 1)); [ $i -gt 50 ] && break
        sleep 0.1
    done
}
xdotool mousemove --window "$w" 400 400
peek_until "00c0ff ff0000 "
hover=$got
xdotool mousemove --window "$w" 600 150
peek_until "$before"
after=$got
echo "pick echo pixels: before $before hovering $hover after $after"
set -- $hover
[ "$1" = 00c0ff ] || echo "FAIL: pick echo: edge pixel $1 while hovering"
[ "$2" = ff0000 ] || echo "FAIL: pick echo: inside pixel $2 while hovering"
[ "$before" = "$after" ] || echo "FAIL: pick echo: picture not restored"
set -- $before
[ "$1" != 00c0ff ] || echo "FAIL: pick echo: edge highlighted before hovering"
xdotool mousemove --window "$w" 400 400 click 1
sleep 0.3
xdotool windowfocus --sync "$w" 2>/dev/null
xdotool key --window "$w" 3
sleep 0.3
xdotool type --window "$w" gks
xdotool key --window "$w" Return
sleep 0.3
xdotool key --window "$w" Escape
# wait for a line of the program's output
wait_for() {
    i=0
    while ! grep -q "$1" out.txt 2>/dev/null; do
        i=$((i + 1)); [ $i -gt 300 ] && { cat out.txt; echo "FAIL: no $1"; exit 1; }
        sleep 0.1
    done
}
# The menu of CHOICE prompt/echo type 3, drawn at the echo area's top right: check the
# prompt line's and the menu's colours, then click item 2.
wait_for MENU
wait_title "CHOICE 1"
c=$("$peek" "$w" 400 5 720 135)
set -- $c
[ "$1" = ffffcc ] || echo "FAIL: prompt line colour $1"
[ "$2" = f0f0f0 ] || echo "FAIL: menu colour $2"
xdotool mousemove --window "$w" 740 129 click 1
sleep 0.3
# The valuator slider: a click at 3/4 of the track, Return.
xdotool mousemove --window "$w" 615 311 click 1
sleep 0.3
xdotool key --window "$w" Return
sleep 0.3
# A stroke dragged with button 1.
xdotool mousemove --window "$w" 100 700 mousedown 1
for p in "150 675" "200 650" "250 625" "300 600"; do
    sleep 0.1
    xdotool mousemove --window "$w" $p
done
sleep 0.1
xdotool mouseup 1
# The traced square (colour 3, green, lit) is in the window; outside it the background.
wait_for TRACED
wait_title "CHOICE 1"
c=$("$peek" "$w" 400 400 100 700)
set -- $c
[ "$1" != ffffff ] && [ "$1" != 000000 ] || echo "FAIL: traced square pixel $1"
echo "traced pixels: $c"
xdotool key --window "$w" 1
i=0
while kill -0 $ppid 2>/dev/null; do
    i=$((i + 1)); [ $i -gt 100 ] && { kill $ppid; cat out.txt; echo "FAIL: hung"; exit 1; }
    sleep 0.1
done
wait $ppid
rc=$?
cat out.txt
exit $rc
