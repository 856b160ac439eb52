#!/bin/sh
# OSMesa's buffer semantics against real Mesa: capi/tests/osmesa.c built against Mesa's OSMesa
# and against gleval (glevalcc); their outputs (pixels of the caller's buffers after glFinish,
# glFlush and glReadPixels, in RGBA, BGRA and RGB, across three contexts) must be identical.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out="$root/target/capi/osmesa"
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
mkdir -p "$out"
src="$root/capi/tests/osmesa.c"
"$root/capi/glevalcc" -std=gnu99 -O1 -Wall -Werror -o "$out/gleval" "$src"
cc -std=gnu99 -O1 -w -o "$out/mesa" "$src" -lOSMesa -lGL
"$out/gleval" > "$out/gleval.txt"
"$out/mesa" > "$out/mesa.txt"
if diff -u "$out/mesa.txt" "$out/gleval.txt"; then
  echo "osmesa: $(wc -l < "$out/mesa.txt") lines, identical to Mesa's"
else
  echo "osmesa: differs from Mesa (above)"; exit 1
fi
