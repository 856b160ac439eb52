#!/bin/sh
# glReadPixels against real Mesa: capi/tests/readpixels.c built from the same source against
# Mesa (freeglut's header, the OSMesa GLUT stand-in) and against gleval (glevalcc); the two
# outputs (pixels inside the drawn rectangles in several formats, types and pack modes, and
# the errors of wrong calls) must be identical.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out="$root/target/capi/readpixels"
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
mkdir -p "$out"
src="$root/capi/tests/readpixels.c"
"$root/capi/glevalcc" -std=gnu99 -O1 -Wall -Werror -o "$out/gleval" "$src" -lm
cc -std=gnu99 -O1 -w -o "$out/mesa" "$src" "$root/tests/reference/pictures/glut_osmesa.c" -lOSMesa -lGLU -lGL -lz -lm
"$out/gleval" --png "$out/gleval.png" > "$out/gleval.txt" 2>"$out/gleval.log"
"$out/mesa" --png "$out/mesa.png" > "$out/mesa.txt"
if diff -u "$out/mesa.txt" "$out/gleval.txt"; then
  echo "readpixels: $(wc -l < "$out/mesa.txt") lines, identical to Mesa's"
else
  echo "readpixels: differs from Mesa (above)"; exit 1
fi
