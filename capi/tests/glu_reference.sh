#!/bin/sh
# GLU reference programs (tests/reference/glu/*.c) that need only GL calls gleval has, built
# unchanged against gleval with capi/glevalcc and run: their output must equal the committed
# output of real GLU 9.0.2, byte for byte (scale_image.c: gluScaleImage under every format,
# type pair and pixel-store mode; strings.c: gluGetString and gluCheckExtension; mipmaps.c:
# gluBuild1D/2D/3DMipmaps(Levels), every level's texels).
#   capi/tests/glu_reference.sh
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
glu="$root/tests/reference/glu"
out="$root/target/capi/glu"
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
mkdir -p "$out"
for name in scale_image strings mipmaps; do
  "$root/capi/glevalcc" -std=c99 -O1 -o "$out/$name" "$glu/$name.c" -lOSMesa -lGLU -lGL
  "$out/$name" > "$out/$name.txt"
  cmp "$glu/$name.txt" "$out/$name.txt"
  echo "glu_reference: $name.c's output is real GLU's"
done
