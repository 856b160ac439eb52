#!/bin/sh
# One C program built from the same source against real Mesa and against gleval (glevalcc),
# run both ways; their outputs must be identical.
#
#   capi/tests/against_mesa.sh readpixels   glReadPixels: pixels inside drawn rectangles in
#                                           several formats, types and pack modes, and the
#                                           errors of wrong calls (capi/tests/readpixels.c,
#                                           on Mesa through the OSMesa GLUT stand-in)
#   capi/tests/against_mesa.sh osmesa       OSMesa's buffers: pixels after glFinish, glFlush
#                                           and glReadPixels, in RGBA, BGRA and RGB, across
#                                           three contexts (capi/tests/osmesa.c)
#   capi/tests/against_mesa.sh occlusion    GL 1.5's occlusion queries: the samples counted
#                                           (capi/tests/occlusion.c)
#   capi/tests/against_mesa.sh depth_stencil
#                                           GL_EXT_packed_depth_stencil: glReadPixels and
#                                           glDrawPixels of GL_DEPTH_STENCIL, 24_8
#                                           (capi/tests/depth_stencil.c)
#   capi/tests/against_mesa.sh pixel_buffers
#                                           GL 2.1's pixel buffer objects and GL 3.0's
#                                           glMapBufferRange (capi/tests/pixel_buffers.c)
#   capi/tests/against_mesa.sh texture_rectangle
#                                           GL_ARB_texture_rectangle
#                                           (capi/tests/texture_rectangle.c)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
name=$1
out="${CARGO_TARGET_DIR:-$root/target}/capi/$name"
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
mkdir -p "$out"
src="$root/capi/tests/$name.c"
case "$name" in
  readpixels) mesa_libs="$root/tests/reference/pictures/glut_osmesa.c -lOSMesa -lGLU -lGL -lz -lm"; args="--png $out/out.png" ;;
  osmesa | occlusion | depth_stencil | pixel_buffers | texture_rectangle) mesa_libs="-lOSMesa -lGL"; args="" ;;
  *) echo "against_mesa.sh: no program $name"; exit 2 ;;
esac
"$root/capi/glevalcc" -std=gnu99 -O1 -Wall -Werror -o "$out/gleval" "$src" -lm
# shellcheck disable=SC2086 # word lists
cc -std=gnu99 -O1 -w -o "$out/mesa" "$src" $mesa_libs
# shellcheck disable=SC2086
"$out/gleval" $args > "$out/gleval.txt" 2>"$out/gleval.log"
# shellcheck disable=SC2086
"$out/mesa" $args > "$out/mesa.txt"
if diff -u "$out/mesa.txt" "$out/gleval.txt"; then
  echo "$name: $(wc -l < "$out/mesa.txt") lines, identical to Mesa's"
else
  echo "$name: differs from Mesa (above)"; exit 1
fi
