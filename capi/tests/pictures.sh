#!/bin/sh
# The reference C programs (tests/reference/pictures/*.c), built unchanged against gleval with
# capi/glevalcc, each rendered with --png and compared with the picture real Mesa rendered from
# the same source (tests/reference/pictures/png/), with the project's image metric.
#
#   capi/tests/pictures.sh [--osmesa] [OUT_DIR]     (default $CARGO_TARGET_DIR or target, then capi/pictures[-osmesa])
#
# With --osmesa each program is built with the reference's own GLUT stand-in over OSMesa
# (tests/reference/pictures/glut_osmesa.c, the harness Mesa's pictures come from: an OSMesa
# buffer, glFinish, its own PNG writer) instead of gleval's GLUT: the whole harness unchanged
# on gleval's OSMesa.
#
# Builds libgleval_c and gleval-compare with the test profile (what `cargo test` builds its
# dependencies with, so CI compiles no dependency twice; set CAPI_PROFILE=release for a release
# build). Fails if a program does not build or run, or differs from Mesa in more than 1% of
# its pixels (the conformance tests' bound).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
pictures="$root/tests/reference/pictures"
harness=""
suffix=""
if [ "${1:-}" = --osmesa ]; then
  harness="$pictures/glut_osmesa.c -lz"
  suffix=-osmesa
  shift
fi
out=${1:-${CARGO_TARGET_DIR:-$root/target}/capi/pictures$suffix}
profile=${CAPI_PROFILE:-test}
dir=debug
[ "$profile" = release ] && dir=release
target=${CARGO_TARGET_DIR:-$root/target}
cargo build --quiet --profile "$profile" -p gleval-c --manifest-path "$root/Cargo.toml"
mkdir -p "$out"
export GLEVAL_LIB_DIR="$target/$dir"
failed=0
for src in "$pictures"/*.c; do
  name=$(basename "$src" .c)
  [ "$name" = glut_osmesa ] && continue
  lower=$(echo "$name" | tr 'A-Z' 'a-z')
  # -I the program's folder: its "gl.h" includes <GL/gl.h> and <GL/glu.h> (gleval's, first on
  # the path) and "glut_osmesa.h", whose GLUT declarations libgleval_c implements.
  # shellcheck disable=SC2086 # $harness is two words or none
  if ! "$root/capi/glevalcc" -std=gnu99 -O1 -w -I"$pictures" -o "$out/$lower" "$src" $harness -lm; then
    echo "$lower: does not build"; failed=1; continue
  fi
  if ! "$out/$lower" --png "$out/$lower.png" 2>"$out/$lower.log"; then
    echo "$lower: failed to run (see $out/$lower.log)"; failed=1; continue
  fi
  printf '%s%s: ' "$lower" "$suffix"
  "$GLEVAL_LIB_DIR/gleval-compare" "$pictures/png/$lower.png" "$out/$lower.png" 0.01 || failed=1
done
exit $failed
