# SPDX-License-Identifier: MIT
# xvfb.sh -- sourced by the X11 test scripts (test_x11.sh, test_x11_close.sh,
# test_x11_bg.sh): the one way they start their own X server.
#   xvfb_need TOOL...  skip the test (exit 77) with a message if a tool is missing
#   xvfb_start         an Xvfb of its own, started in the current folder (display.txt,
#                      xvfb.log), DISPLAY exported, killed when the script exits; skip (77)
#                      if it does not start or (with xdotool present) does not answer
#   xvfb_state         whether that Xvfb still runs, and its log's end (for a FAIL message)
xvfb_need() {
    for t in "$@"; do
        if ! command -v "$t" >/dev/null 2>&1; then
            echo "SKIP: $t not installed (scripts/setup.sh installs it)"
            exit 77
        fi
    done
}

# Kills the Xvfb and waits until it has exited: a server still shutting down removes its
# socket (/tmp/.X11-unix/XN) after the next test's server has taken the same display number
# and made that socket, and the next test cannot connect (seen: x11_background right after
# x11_window_closed, "no display for the check").
xvfb_stop() {
    [ -n "${xpid:-}" ] || return 0
    kill "$xpid" 2>/dev/null
    wait "$xpid" 2>/dev/null
}

# Prints whether the test's Xvfb still runs, and its log: for a failure's message.
xvfb_state() {
    if kill -0 "${xpid:-0}" 2>/dev/null; then echo "Xvfb (pid $xpid, :$(cat display.txt)) runs"
    else echo "Xvfb (pid ${xpid:-none}) has exited"; fi
    tail -5 xvfb.log 2>/dev/null
}

xvfb_start() {
    # Xvfb picks a free display itself and writes its number (-displayfd): no race with
    # other X servers started at the same time (parallel tests, other users).
    # -noreset: by default the server resets when its last client disconnects, and a client
    # that connects during that reset is refused (seen: x11_render_turn's second
    # gks3d-render, started right after the first one and xdotool had exited, "no X
    # display to open"); a test's server lives only as long as its test anyway.
    rm -f display.txt
    Xvfb -displayfd 3 -screen 0 1024x1024x24 -nolisten tcp -noreset 3>display.txt \
        >xvfb.log 2>&1 &
    xpid=$!
    trap xvfb_stop EXIT
    i=0
    while [ ! -s display.txt ]; do
        i=$((i + 1)); [ $i -gt 100 ] && { echo "SKIP: Xvfb did not start"; exit 77; }
        sleep 0.1
    done
    DISPLAY=:$(cat display.txt)
    export DISPLAY
    command -v xdotool >/dev/null 2>&1 || return 0
    i=0
    while ! xdotool getmouselocation >/dev/null 2>&1; do
        i=$((i + 1)); [ $i -gt 50 ] && { echo "SKIP: Xvfb did not answer"; exit 77; }
        sleep 0.1
    done
}
