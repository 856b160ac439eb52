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
. "$root/capi/tests/window_lib.sh"
run_in_xvfb Picking.c picking "Picking control points" ":$((90 + $$ % 9))"
# The highlighted point's red: red at least 200, green under 100.
red() { set -- $(pixel "$@"); [ "$1" -ge 200 ] && [ "$2" -lt 100 ]; }
shot 1-start
red 1-start 200 250 || { echo "start: point 2 (window 200, 250) not highlighted: $(pixel 1-start 200 250)"; exit 1; }
# Control point 3, (2, 3), is at window (300, 50): click it.
xdotool mousemove --window "$wid" 301 51 click 1
sleep 1
shot 2-clicked
red 2-clicked 300 50 || { echo "click: point 3 not highlighted: $(pixel 2-clicked 300 50)"; exit 1; }
red 2-clicked 200 250 && { echo "click: point 2 still highlighted"; exit 1; }
# Drag it to window (350, 100), world (3, 2).
drag 300 50 10 10
shot 3-dragged
red 3-dragged 350 100 || { echo "drag: the point did not follow to (350, 100): $(pixel 3-dragged 350 100)"; exit 1; }
red 3-dragged 300 50 && { echo "drag: the point stayed at (300, 50)"; exit 1; }
echo "picking window: click selects, drag moves (screenshots in $out)"
