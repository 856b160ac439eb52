#!/bin/sh
# Regenerates the GLU reference outputs from the installed (real) GLU.
# Usage: regen.sh [--out DIR]   (default: this directory)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out="$here"
if [ "${1:-}" = "--out" ]; then out="$2"; fi
build="$here/../build/glu"
mkdir -p "$build" "$out"
cc -std=c99 -O1 -o "$build/error_strings" "$here/error_strings.c" -lGLU -lGL
"$build/error_strings" > "$out/error_strings.txt"
cc -std=c99 -O1 -o "$build/nurbs_errors" "$here/nurbs_errors.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/nurbs_errors" > "$out/nurbs_errors.txt"
cc -std=c99 -O1 -o "$build/tess_counts" "$here/tess_counts.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/tess_counts" > "$out/tess_counts.txt"
cc -std=c99 -O1 -o "$build/surfpoints" "$here/surfpoints.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/surfpoints" > "$out/surfpoints.txt"
cc -std=c99 -O1 -o "$build/tess_calls" "$here/tess_calls.c" -lGLU -lGL -lm
"$build/tess_calls" < "$here/tess_cases.in" > "$out/tess_calls.txt"
cc -std=c99 -O1 -o "$build/project" "$here/project.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/project" > "$out/project.txt"
cc -std=c99 -O1 -o "$build/quadrics" "$here/quadrics.c" -lGLU -lGL -lm
"$build/quadrics" > "$out/quadrics.txt"
cc -std=c99 -O1 -o "$build/strings" "$here/strings.c" -lGLU -lGL
"$build/strings" > "$out/strings.txt"
cc -std=c99 -O1 -o "$build/scale_image" "$here/scale_image.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/scale_image" > "$out/scale_image.txt"
cc -std=c99 -O1 -o "$build/mipmaps" "$here/mipmaps.c" -lOSMesa -lGLU -lGL
GALLIUM_DRIVER=llvmpipe "$build/mipmaps" > "$out/mipmaps.txt"
cc -std=c99 -O1 -o "$build/trimcases" "$here/trimcases.c" -lOSMesa -lGLU -lGL -lm
GALLIUM_DRIVER=llvmpipe "$build/trimcases" > "$out/trimcases.txt"
