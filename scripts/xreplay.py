#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Replays a gks3d input script (docs/INPUT.md) as a user's X events, with xdotool, into
the window of the X11 workstation (type 210, 800 x 800): choice -> digit key, locator and
pick -> button 1 click, stroke -> button 1 per point and button 3 to end, valuator -> keys
+/- (a tenth of the range per key, from start value 1 of range 0..10 as in gksdemo.f) and
Return, string -> typed text and Return. Script positions are DC of a 1024 x 1024 PNG
workstation (y up) and are scaled to the window. A line "#! shot NAME" saves the window
as NAME.png (ImageMagick import). Used to run drastr.f and gksdemo.f under Xvfb.

Usage: xreplay.py SCRIPT WINDOW_ID [DELAY_S [SHOT_DIR]]
"""
import subprocess
import sys
import time

script, win = sys.argv[1], sys.argv[2]
delay = float(sys.argv[3]) if len(sys.argv) > 3 else 0.4
shots = sys.argv[4] if len(sys.argv) > 4 else "."
scale = 800.0 / 1024.0
val = {}


def xd(*a):
    subprocess.run(["xdotool"] + [str(x) for x in a], check=True, stderr=subprocess.DEVNULL)


def click(x, y, button=1):
    wx, wy = int(round(float(x) * scale)), int(round(800 - float(y) * scale))
    xd("mousemove", "--window", win, wx, wy)
    time.sleep(0.05)
    xd("click", "--window", win, button)


for line in open(script):
    if line.startswith("#! shot "):
        time.sleep(1.0)
        subprocess.run(["import", "-window", win, "%s/%s.png" % (shots, line.split()[2])])
        continue
    w = line.split("#")[0].split()
    if not w:
        continue
    if w[0] == "choice":
        xd("key", "--window", win, w[2])
    elif w[0] in ("pick", "locator"):
        click(w[2], w[3])
    elif w[0] == "stroke":
        p = w[2:]
        for i in range(0, len(p), 2):
            click(p[i], p[i + 1])
        click(p[0], p[1], 3)
    elif w[0] == "valuator":
        n = int(round(float(w[2]) - val.get(w[1], 1.0)))
        for _ in range(abs(n)):
            xd("key", "--window", win, "plus" if n > 0 else "minus")
        xd("key", "--window", win, "Return")
        val[w[1]] = float(w[2])
    elif w[0] == "string":
        xd("type", "--window", win, " ".join(w[2:]))
        xd("key", "--window", win, "Return")
    time.sleep(delay)
