#!/bin/sh
# Runs tests/reference/glut/Windows.c (two windows and a subwindow) with real freeglut under
# Xvfb and with gleval headless (--png), and compares the pictures of both windows (the
# subwindow composed in place; ImageMagick's count of differing pixels) and the callbacks'
# order (the program's log). Needs freeglut3-dev, Xvfb, xdotool, ImageMagick and gleval's C
# library built (cargo build -p gleval-c); not in CI.
#   sh tools/freeglut_check/windows.sh          compare
#   sh tools/freeglut_check/windows.sh --save   also keep freeglut's pictures and log as the
#                                               references capi/tests/glut.sh compares with
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root="$here/../.."
work=$(mktemp -d)
src="$root/tests/reference/glut/Windows.c"
cc -w -o "$work/freeglut" "$src" -lglut -lGL
GLEVAL_PROFILE=${GLEVAL_PROFILE:-debug} "$root/capi/glevalcc" -w -o "$work/gleval" "$src"
Xvfb :95 -screen 0 800x600x24 -noreset >/dev/null 2>&1 &
xvfb=$!
sleep 2
DISPLAY=:95 "$work/freeglut" > "$work/freeglut.log" &
prog=$!
sleep 2
for name in first second; do
  DISPLAY=:95 import -window "$(DISPLAY=:95 xdotool search --name "^$name\$")" "$work/freeglut-$name.png"
done
kill "$prog" "$xvfb"
if [ "${1:-}" = --save ]; then
  for name in first second; do convert "$work/freeglut-$name.png" "PNG24:$root/tests/reference/glut/windows-$name.png"; done
  cp "$work/freeglut.log" "$root/tests/reference/glut/windows.log"
fi
"$work/gleval" --png "$work/gleval.png" > "$work/gleval.log"
for pair in first:gleval.png second:gleval-3.png; do
  echo "window ${pair%%:*}: $(compare -metric AE "$work/freeglut-${pair%%:*}.png" "$work/${pair#*:}" null: 2>&1) pixels differ"
done
if diff "$work/freeglut.log" "$work/gleval.log"; then echo "callbacks: the same, in the same order"; fi
rm -rf "$work"
