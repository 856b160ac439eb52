#!/bin/sh
# Regenerates tests/reference/glut/shapes.txt: what freeglut 3.4 draws for each of its shapes
# (the primitives, their vertices' positions, normals and texture coordinates, as a count and
# a hash of the float bits), read from the arrays freeglut hands Mesa (arrays_dump.c, loaded
# before libGL) in a window on Xvfb. tests/it/glut_shapes.rs draws the same calls with gleval
# and compares. Needs freeglut3-dev and Xvfb (not in CI).
#   sh tools/freeglut_check/shapes.sh
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out="$here/../../tests/reference/glut/shapes.txt"
work=$(mktemp -d)
cc -shared -fPIC -O1 -o "$work/arrays_dump.so" "$here/arrays_dump.c" -ldl
cc -O1 -o "$work/shapes_dump" "$here/shapes_dump.c" -lglut -lGL
Xvfb :96 -screen 0 640x480x24 -noreset >/dev/null 2>&1 &
xvfb=$!
sleep 2
{
  echo "# name primitives vertices fnv1a64 (tools/freeglut_check/shapes.sh, freeglut 3.4 under Xvfb)"
  DISPLAY=:96 LD_PRELOAD="$work/arrays_dump.so" "$work/shapes_dump"
} > "$out"
kill "$xvfb"
rm -rf "$work"
cat "$out"
