#!/bin/sh
# Renders a reference program twice, with real freeglut (a window on an X server, read back with
# glReadPixels) and with the OSMesa GLUT stand-in, and counts the pixels that differ: the check
# behind glut_shapes.h. Needs freeglut3-dev and Xvfb (not in CI).
#   sh tools/freeglut_check/check.sh [PROGRAM.c]    (default tests/reference/pictures/Shapes.c)
#   sh tools/freeglut_check/check.sh tools/freeglut_check/OddShapes.c
set -eu
here=$(cd "$(dirname "$0")" && pwd)
pictures="$here/../../tests/reference/pictures"
src=${1:-$pictures/Shapes.c}
work=$(mktemp -d)
# A copy of the program in a folder without a gl.h, so that its #include "gl.h" finds the one
# asked for with -I: freeglut's here, or the stand-in's.
cp "$src" "$work/program.c"
cc -std=gnu99 -O1 -w -I"$here" -o "$work/freeglut" "$work/program.c" "$here/fgmain.c" -lglut -lGLU -lGL -lm
cc -std=gnu99 -O1 -w -I"$pictures" -o "$work/osmesa" "$work/program.c" "$pictures/glut_osmesa.c" \
  -lOSMesa -lGLU -lGL -lz -lm
Xvfb :97 -screen 0 1280x1024x24 -noreset >/dev/null 2>&1 &
xvfb=$!
sleep 2
DISPLAY=:97 OUT="$work/freeglut.ppm" "$work/freeglut"
kill "$xvfb"
GALLIUM_DRIVER=llvmpipe LC_ALL=C "$work/osmesa" --png "$work/osmesa.png"
python3 "$here/cmp.py" "$work/freeglut.ppm" "$work/osmesa.png"
rm -rf "$work"
