#!/bin/sh
# The textbook chapter's four programs as seed 004 prints them (capi/examples/textbook: BezCurve,
# BezSurf, BCurve, BSurf with the chapter's gll.h, which includes <GL/glut.h>), built with
# capi/glevalcc (warnings on) and run with --png; each picture is compared with the one real
# Mesa renders from the same source (system GL/GLU headers and freeglut's GL/glut.h, linked with
# the OSMesa GLUT stand-in of tests/reference/pictures), with the project's image metric.
#   capi/tests/textbook.sh [OUT_DIR]    (default $CARGO_TARGET_DIR or target, then capi/textbook)
# Also builds BezCurve with pkg-config (capi/gleval.pc). Expects libgleval_c and gleval-compare built (capi/tests/pictures.sh builds them); the same
# CAPI_PROFILE as there.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
book="$root/capi/examples/textbook"
out=${1:-${CARGO_TARGET_DIR:-$root/target}/capi/textbook}
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
mkdir -p "$out"
failed=0
for name in BezCurve BezSurf BCurve BSurf; do
  lower=$(echo "$name" | tr 'A-Z' 'a-z')
  "$root/capi/glevalcc" -std=gnu99 -O1 -Wall -Wno-unused-function -Werror -o "$out/$lower" "$book/$name.c" -lm
  "$out/$lower" --png "$out/$lower.png" 2>"$out/$lower.log"
  cc -std=gnu99 -O1 -w -I"$book" -o "$out/$lower.mesa" "$book/$name.c" \
    "$root/tests/reference/pictures/glut_osmesa.c" -lOSMesa -lGLU -lGL -lz -lm
  "$out/$lower.mesa" --png "$out/$lower.mesa.png"
  printf '%s (textbook): ' "$lower"
  "$GLEVAL_LIB_DIR/gleval-compare" "$out/$lower.mesa.png" "$out/$lower.png" 0.01 || failed=1
done
# The same program built with pkg-config instead of glevalcc.
flags=$(PKG_CONFIG_PATH="$root/capi" pkg-config --cflags --libs --define-variable=libdir="$GLEVAL_LIB_DIR" gleval)
cc -std=gnu99 -O1 -w -o "$out/bezcurve.pc" "$book/BezCurve.c" $flags
"$out/bezcurve.pc" --png "$out/bezcurve.pc.png" 2>/dev/null
printf 'bezcurve (textbook, pkg-config): '
"$GLEVAL_LIB_DIR/gleval-compare" "$out/bezcurve.mesa.png" "$out/bezcurve.pc.png" 0.01 || failed=1
exit $failed
