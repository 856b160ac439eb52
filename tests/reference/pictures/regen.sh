#!/bin/sh
# Renders every reference program with real Mesa (OSMesa + GLU) into png/<name>.png.
#   regen.sh              rewrite png/
#   regen.sh --out DIR    write the PNGs into DIR instead
#   regen.sh --time N     print each program's median frame time over N frames (no PNGs)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out="$here/png"
time=""
case "${1:-}" in
  --out) out="$2" ;;
  --time) time="$2" ;;
esac
build="$here/../build/pictures"
mkdir -p "$build" "$out"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
for src in "$here"/*.c; do
  name=$(basename "$src" .c)
  [ "$name" = glut_osmesa ] && continue
  lower=$(echo "$name" | tr 'A-Z' 'a-z')
  cc -std=gnu99 -O1 -w -I"$here" -o "$build/$lower" "$src" "$here/glut_osmesa.c" -lOSMesa -lGLU -lGL -lz -lm
  if [ -n "$time" ]; then
    printf '%s ' "$lower"; "$build/$lower" --time "$time"
  else
    "$build/$lower" --png "$out/$lower.png"
  fi
done
