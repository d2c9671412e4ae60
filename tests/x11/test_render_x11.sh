#!/bin/sh
# SPDX-License-Identifier: MIT
# gks3d-render --x11 under its own Xvfb (docs/man/man1/gks3d-render.1, "The window"):
#  1. fig3_c recorded through GKS3D_RECORD; frame 3 shown ray traced (120 pixels, 4
#     samples) in the window; the refined picture (line "# refined") grabbed;
#  2. a drag sent with xdotool turns the view: the refined picture after it differs from
#     the first (imgcmp differ: >= 5 % of the pixels by more than 16 levels);
#  3. key 2 prints the view (the offline command line, C and Fortran SET VIEW
#     REPRESENTATION 3, which compile: cc, and gfortran when installed); the offline render of that command line equals the window's
#     refined picture within the image tests' tolerance (imgcmp same: a channel off by
#     more than 1 level at most in 1 of 1000 pixels; found identical);
#  4. key 1 saves the view to --name's file, the same picture; key 0 ends with status 0;
#  5. closing the window ends it too (status 0).
# Skipped (77) without Xvfb or xdotool.
# Usage: test_render_x11.sh RENDER FIG3 XGRAB IMGCMP DIR CFLAGS (the -I of gks.h)
render=$1 fig3=$2 xgrab=$3 imgcmp=$4 dir=$5 cflags=$6
. "$(dirname "$0")/xvfb.sh"
xvfb_need Xvfb xdotool
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir" || exit 1
xvfb_start
GKS3D_RECORD=fig3.gksm "$fig3" >/dev/null || { echo "FAIL: fig3 not recorded"; exit 1; }
# out.txt made here: the background job's own redirection may come after wait_for's first
# grep (which then failed on the missing file, and the loop ended at once: "no window")
: >out.txt
"$render" fig3.gksm --x11 --frames 3 --size 120 --mode raytrace --samples 4 \
    --name 'saved-%d.png' >out.txt 2>err.txt &
pid=$!
trap 'kill $pid 2>/dev/null; xvfb_stop' EXIT
# waits until out.txt has N lines matching a pattern (120 s: a Debug build on a loaded
# machine takes tens of seconds for a refined picture)
wait_for() {
    i=0
    while [ "$(grep -c "$2" out.txt)" -lt "$1" ]; do
        i=$((i + 1))
        [ $i -gt 1200 ] && { echo "FAIL: no '$2' ($1) in time"; cat out.txt err.txt; exit 1; }
        kill -0 $pid 2>/dev/null || { echo "FAIL: gks3d-render ended"; cat err.txt; exit 1; }
        sleep 0.1
    done
}
wait_for 1 '^# refined'
# the window's title: "gks3d" while it waits for input, else the prompt line's message
win=$(xdotool search --name '^gks3d|^drag: turn' | head -1)
[ -n "$win" ] || { echo "FAIL: no window"; exit 1; }
# the picture: the workstation viewport, 120 x 120 at the window's lower left (800 x 800)
"$xgrab" "$win" 0 680 120 120 before.png || { echo "FAIL: grab of window '$win'"; exit 1; }
n0=$(grep -c '^# refined' out.txt)
xdotool mousemove --window "$win" 40 740 mousedown 1 mousemove --window "$win" 60 735 \
    mousemove --window "$win" 80 730 mousemove --window "$win" 100 725 mouseup 1
# the drag: 60 pixels right, 15 up of the 120-pixel picture (NDC 0.5, 0.125): 90, -22.5
# degrees. On a loaded machine xdotool's motions may come more than 0.3 s apart: the tool
# then refines a view the pointer passed and takes the next motion as a new drag, so the
# view is the one it refined last, once nothing new has come for 2 s.
i=0 same=0 prev=-1
while :; do
    i=$((i + 1))
    [ $i -gt 1200 ] && { echo "FAIL: no refined picture after the drag"; cat out.txt; exit 1; }
    kill -0 $pid 2>/dev/null || { echo "FAIL: gks3d-render ended"; cat err.txt; exit 1; }
    n=$(grep -c '^# \(coarse\|refined\)' out.txt)
    if [ "$n" = "$prev" ]; then same=$((same + 1)); else same=0; fi
    prev=$n
    if [ $same -ge 20 ] && [ "$(grep -c '^# refined' out.txt)" -gt "$n0" ] &&
        grep '^# \(coarse\|refined\)' out.txt | tail -1 | grep -q '^# refined'; then
        break
    fi
    sleep 0.1
done
view=$(grep '^# refined' out.txt | tail -1 | sed 's/^# refined: //')
echo "the drag's view: $view (yaw 90, pitch -22.5 unless a view mid-drag was refined)"
case "$view" in # turned the way the pointer went: right (yaw > 0) and up (pitch < 0)
yaw\ [1-9]*,\ pitch\ -[0-9]*) ;;
*) echo "FAIL: the drag did not turn the view right and up" ;;
esac
# progressive: the coarse pass (1 sample a pixel) of that view came before its refinement
c=$(grep -n "^# coarse: $view," out.txt | tail -1 | cut -d: -f1)
r=$(grep -n "^# refined: $view\$" out.txt | tail -1 | cut -d: -f1)
[ -n "$c" ] && [ "$c" -lt "$r" ] || echo "FAIL: no coarse pass before the refined picture"
"$xgrab" "$win" 0 680 120 120 after.png || { echo "FAIL: grab of window '$win' after"; exit 1; }
"$imgcmp" differ before.png after.png || echo "FAIL: the drag did not change the picture"
xdotool key --window "$win" 2
wait_for 1 '^# offline:'
cmd=$(sed -n 's/^# offline: gks3d-render //p' out.txt)
echo "offline: $cmd"
eval "\"\$render\" $cmd" || echo "FAIL: offline render"
"$imgcmp" same view.png after.png || echo "FAIL: window and offline render differ"
grep -q 'gset_view_rep3(ws, 1, &rep);' out.txt || echo "FAIL: no C call printed"
grep -q 'CALL GSVWR(WKID, 1, VWM, PRM, VCLP' out.txt || echo "FAIL: no Fortran call printed"
# the printed calls compile: C (-Wall -Wextra -Werror) and, with gfortran, Fortran 77
{ echo '#include <gks.h>'; echo 'void f(int ws);'; echo 'void f(int ws) {'
  sed -n '/^\/\* C: SET VIEW/,/^    }$/p' out.txt; echo '}'; } > view.c
cc -fsyntax-only -Wall -Wextra -Werror $cflags view.c || echo "FAIL: the printed C does not compile"
if command -v gfortran >/dev/null 2>&1; then
    { echo '      SUBROUTINE F(WKID)'; echo '      INTEGER WKID'
      sed -n '/^C     Fortran/,/CALL GSVWR/p' out.txt; echo '      END'; } > view.f
    gfortran -std=legacy -fsyntax-only view.f ||
        echo "FAIL: the printed Fortran 77 does not compile"
fi
xdotool key --window "$win" 1
wait_for 1 '^# saved saved-1.png'
"$imgcmp" same view.png saved-1.png || echo "FAIL: the saved view differs"
xdotool key --window "$win" 0
wait $pid
rc=$?
[ $rc -eq 0 ] || echo "FAIL: exit status $rc after key 0"
# 5. closing the window (here: destroyed by xdotool) ends the program too, status 0
# (the server first answers again: the first program and xdotool have just disconnected)
i=0
while ! xdotool getmouselocation >/dev/null 2>&1; do
    i=$((i + 1)); [ $i -gt 100 ] && { echo "FAIL: Xvfb no longer answers"; xvfb_state; exit 1; }
    sleep 0.1
done
"$render" fig3.gksm --x11 --frames 3 --size 60 >out2.txt 2>err2.txt &
pid=$!
i=0
until win=$(xdotool search --name '^gks3d|^drag: turn' | head -1) && [ -n "$win" ]; do
    i=$((i + 1))
    [ $i -gt 1200 ] && { echo "FAIL: no second window"; cat out2.txt err2.txt; exit 1; }
    kill -0 $pid 2>/dev/null ||
        { echo "FAIL: gks3d-render ended before its second window"; cat out2.txt err2.txt
          xvfb_state; exit 1; }
    sleep 0.1
done
sleep 0.5
xdotool windowclose "$win"
i=0
while kill -0 $pid 2>/dev/null; do
    i=$((i + 1)); [ $i -gt 400 ] && { echo "FAIL: the closed window did not end it"; exit 1; }
    sleep 0.1
done
wait $pid
rc2=$?
[ $rc2 -eq 0 ] || { echo "FAIL: exit status $rc2 after the window was closed"; cat err2.txt; }
echo "gks3d-render --x11: exit status $rc, after closing $rc2"
