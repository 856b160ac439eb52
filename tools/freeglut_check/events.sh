#!/bin/sh
# Drives tests/reference/glut/Events.c with xdotool under Xvfb, once on real freeglut and once on
# gleval (a window), and compares the two logs: the mouse wheel with and without
# glutMouseWheelFunc, keys and their releases, a held key's repeats (on; ignored with
# glutIgnoreKeyRepeat; off with glutSetKeyRepeat(GLUT_KEY_REPEAT_OFF)), the window manager's close
# (a WM_DELETE_WINDOW message, wm_close.c) with glutCloseFunc and GLUT_ACTION_GLUTMAINLOOP_RETURNS,
# and glutMainLoop returning. How many repeats a held key makes depends on timing, so a run of
# repeats counts as one "repeated" line. Needs freeglut3-dev, Xvfb, xdotool, libx11-dev and
# gleval's C library (cargo build -p gleval-c); not in CI.
#   sh tools/freeglut_check/events.sh
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root="$here/../.."
work=$(mktemp -d)
src="$root/tests/reference/glut/Events.c"
cc -w -o "$work/freeglut" "$src" -lglut -lGL
GLEVAL_PROFILE=${GLEVAL_PROFILE:-debug} "$root/capi/glevalcc" -w -o "$work/gleval" "$src"
cc -o "$work/wm_close" "$here/wm_close.c" -lX11
Xvfb :94 -screen 0 800x600x24 -noreset >/dev/null 2>&1 &
xvfb=$!
sleep 2
drive() {
  DISPLAY=:94 "$1" > "$2" 2>/dev/null &
  pid=$!
  sleep 6
  w=$(DISPLAY=:94 xdotool search --name '^events$' | head -1)
  x() { DISPLAY=:94 xdotool "$@" 2>/dev/null; sleep 0.3; }
  x windowfocus "$w"
  x mousemove 50 50
  x click 4; x click 4; x click 5
  x key w; x click 5; x key w
  x key a
  x keydown b; sleep 1.2; x keyup b
  x key i
  x keydown c; sleep 1.2; x keyup c
  x key o
  x keydown d; sleep 1.2; x keyup d
  x key n
  DISPLAY=:94 "$work/wm_close" "$w"
  sleep 2
  kill "$pid" 2>/dev/null || true
}
normal() {
  python3 -c '
import sys
lines = [l for l in open(sys.argv[1]).read().split("\n") if l]
out = []
for line in lines:
    pair = out[-2:]
    if line.startswith("key ") and len(pair) == 2 and pair[0] == line and pair[1].startswith("key_up"):
        out[-2:] = [line + " repeated"]
    elif line.startswith("key_up") and out and out[-1].endswith(" repeated"):
        continue
    elif line.startswith("key ") and out and out[-1] == line + " repeated":
        continue
    else:
        out.append(line)
print("\n".join(out))' "$1"
}
drive "$work/freeglut" "$work/freeglut.log"
drive "$work/gleval" "$work/gleval.log"
kill "$xvfb"
normal "$work/freeglut.log" > "$work/a"
normal "$work/gleval.log" > "$work/b"
cat "$work/a"
if diff "$work/a" "$work/b"; then echo "events: the same on freeglut and gleval"; else echo "events: they differ"; fi
rm -rf "$work"
