#!/bin/sh
# The control-point editor (tests/reference/pictures/Editor.c, built against gleval with
# glevalcc) in a real window under Xvfb, driven with xdotool: the first frame's selected ball
# (point 2) wears the yellow ring; a click on point 3 moves the ring there (selection mode around
# gluSphere's triangles), a drag moves the ball (gluProject/gluUnProject); the right button opens
# the GLUT menu, "Next colour" turns the selected ball green, "Reset points" puts it back, "Quit"
# ends the program. Screenshots after each step go to OUT_DIR; pixels are checked.
#   capi/tests/editor_window.sh [OUT_DIR]      (default target/capi/editor-window)
# Needs Xvfb, xdotool and ImageMagick's import/convert; the library built as for pictures.sh.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-${CARGO_TARGET_DIR:-$root/target}/capi/editor-window}
. "$root/capi/tests/window_lib.sh"
run_in_xvfb Editor.c editor "Control-point editor" ":$((80 + $$ % 9))"
# The ring's yellow (1, 0.9, 0.1); a green ball (0.3, 0.85, 0.35 lit); an orange one (1, 0.55, 0.15 lit).
yellow() { set -- $(pixel "$@"); [ "$1" -gt 240 ] && [ "$2" -ge 220 ] && [ "$2" -le 240 ] && [ "$3" -lt 40 ]; }
green() { set -- $(pixel "$@"); [ "$2" -gt 150 ] && [ "$2" -gt "$1" ] && [ "$2" -gt "$3" ]; }
orange() { set -- $(pixel "$@"); [ "$1" -gt 200 ] && [ "$1" -gt "$2" ] && [ "$2" -gt "$3" ]; }
fail() { echo "editor window: $*"; exit 1; }
# The middle of menu entry N (1-based) of a menu opened at y: items 27 pixels high (Helvetica
# 18's 23-pixel lines and 4) below a 2-pixel frame.
entry_y() { echo $(($1 + 2 + 27 * ($2 - 1) + 13)); }
# menu_to N: the right button pressed at (60, 150), which opens the menu there, and moved onto
# entry N (still pressed).
menu_to() {
  xdotool mousemove --window "$wid" 60 150 mousedown 3
  sleep 0.3
  xdotool mousemove --window "$wid" 90 "$(entry_y 150 "$1")"
  sleep 0.5
}
# menu_pick N: entry N chosen (the button released on it).
menu_pick() {
  menu_to "$1"
  xdotool mouseup 3
  sleep 1
}

shot 1-start
# Point 2, (-0.8, -2.6), at window (160, 330): heavier (radius 0.26, ring 16 to 20 pixels out), green.
yellow 1-start 178 330 || fail "start: point 2 has no ring: $(pixel 1-start 178 330)"
green 1-start 160 330 || fail "start: point 2 is not green: $(pixel 1-start 160 330)"
# Point 3, (0.8, 2.6), at window (240, 70): click it (its ring 12 to 16 pixels out).
xdotool mousemove --window "$wid" 242 68 click 1
sleep 1
shot 2-clicked
yellow 2-clicked 254 70 || fail "click: point 3 has no ring: $(pixel 2-clicked 254 70)"
yellow 2-clicked 178 330 && fail "click: point 2 still has its ring"
# Drag it to window (300, 120), world (2, 1.6).
drag 240 70 12 10
shot 3-dragged
yellow 3-dragged 314 120 || fail "drag: the ring did not follow to (300, 120): $(pixel 3-dragged 314 120)"
orange 3-dragged 300 120 || fail "drag: no orange ball at (300, 120): $(pixel 3-dragged 300 120)"
yellow 3-dragged 254 70 && fail "drag: the ring stayed at (240, 70)"
# The right button opens the menu at (60, 150); dragging to "Next colour" (entry 4) lights it.
menu_to 4
shot 4-menu
set -- $(pixel 4-menu 64 "$(entry_y 150 4)")
[ "$3" -gt 80 ] && [ "$1" -lt 80 ] || fail "menu: \"Next colour\" is not highlighted: $*"
xdotool mouseup 3
sleep 1
shot 5-colour
green 5-colour 300 120 || fail "menu: the selected ball did not turn green: $(pixel 5-colour 300 120)"
# "Reset points" (entry 5): the ball goes back to (240, 70), orange, still selected.
menu_pick 5
shot 6-reset
orange 6-reset 240 70 || fail "reset: point 3 is not back at (240, 70): $(pixel 6-reset 240 70)"
yellow 6-reset 254 70 || fail "reset: point 3 lost its ring: $(pixel 6-reset 254 70)"
# "Quit" (entry 6) ends the program.
menu_pick 6
kill -0 "$prog" 2>/dev/null && fail "quit: the program is still running"
wait "$prog" || fail "quit: the program exited with status $?"
echo "editor window: click selects, drag moves, the menu recolours, resets and quits (screenshots in $out)"
