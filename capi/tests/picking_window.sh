#!/bin/sh
# The picking program (tests/reference/pictures/Picking.c, built against gleval with glevalcc)
# in a real window under Xvfb, driven with xdotool: a click on control point 3 selects it
# (selection mode), a drag moves it and the curve follows (gluUnProject). Screenshots of the
# window after start, click and drag go to OUT_DIR; the highlighted point's pixels are checked.
#   capi/tests/picking_window.sh [OUT_DIR]      (default target/capi/picking-window)
# Needs Xvfb, xdotool and ImageMagick's import/convert; the library built as for pictures.sh.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/target/capi/picking-window}
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
mkdir -p "$out"
pictures="$root/tests/reference/pictures"
"$root/capi/glevalcc" -std=gnu99 -O1 -w -I"$pictures" -o "$out/picking" "$pictures/Picking.c" -lm
display=:$((90 + $$ % 9))
Xvfb "$display" -screen 0 640x480x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $prog $xvfb 2>/dev/null || true' EXIT
export DISPLAY="$display"
sleep 1
"$out/picking" >"$out/picking.log" 2>&1 &
prog=$!
wid=$(timeout 60 xdotool search --sync --name "Picking control points" | head -1)
sleep 2
shot() { import -window "$wid" "$out/$1.png"; }
# The window's pixel (x, y) from the top, as "r,g,b".
pixel() { convert "$out/$1.png" -format "%[fx:int(255*u.p{$2,$3}.r)],%[fx:int(255*u.p{$2,$3}.g)],%[fx:int(255*u.p{$2,$3}.b)]" info:; }
red() { case $(pixel "$@") in 2[0-9][0-9],[0-9],* | 2[0-9][0-9],[0-9][0-9],*) return 0 ;; *) return 1 ;; esac; }
shot 1-start
red 1-start 200 250 || { echo "start: point 2 (window 200, 250) not highlighted: $(pixel 1-start 200 250)"; exit 1; }
# Control point 3, (2, 3), is at window (300, 50): click it.
xdotool mousemove --window "$wid" 301 51 click 1
sleep 1
shot 2-clicked
red 2-clicked 300 50 || { echo "click: point 3 not highlighted: $(pixel 2-clicked 300 50)"; exit 1; }
red 2-clicked 200 250 && { echo "click: point 2 still highlighted"; exit 1; }
# Drag it to window (350, 100), world (3, 2).
xdotool mousemove --window "$wid" 300 50 mousedown 1
for step in 1 2 3 4 5; do
  xdotool mousemove --window "$wid" $((300 + 10 * step)) $((50 + 10 * step))
  sleep 0.2
done
xdotool mouseup 1
sleep 1
shot 3-dragged
red 3-dragged 350 100 || { echo "drag: the point did not follow to (350, 100): $(pixel 3-dragged 350 100)"; exit 1; }
red 3-dragged 300 50 && { echo "drag: the point stayed at (300, 50)"; exit 1; }
echo "picking window: click selects, drag moves (screenshots in $out)"
