#!/bin/sh
# Build interp.c against the system Mesa (OSMesa) and run every cases/*.calls script.
#
#   ./regen.sh               regenerate expected/*.out (the committed reference)
#   ./regen.sh --out DIR     write the outputs into DIR instead
#   ./regen.sh --check [DIR] write into DIR (default: ../build/calls/check) and diff
#                            against expected/; exit status 1 if anything differs
#
# Needs a C compiler (CC, default cc) and the OSMesa development files
# (Debian/Ubuntu: apt-get install libosmesa6-dev).  The binary goes to
# tests/reference/build/calls/, which is git-ignored.
set -eu
LC_ALL=C
export LC_ALL
# The references were made with llvmpipe (the default OSMesa driver).  softpipe gives the
# same numbers but hangs in feedback mode once a texture is enabled (texgen_normal).
GALLIUM_DRIVER=llvmpipe
export GALLIUM_DRIVER

here=$(cd "$(dirname "$0")" && pwd)
build="$here/../build/calls"
out="$here/expected"
check=0

case "${1-}" in
    "") ;;
    --out) [ $# -eq 2 ] || { echo "usage: $0 --out DIR" >&2; exit 2; }; out=$2 ;;
    --check) check=1; out=${2-"$build/check"} ;;
    *) echo "usage: $0 [--out DIR | --check [DIR]]" >&2; exit 2 ;;
esac

mkdir -p "$build" "$out"
${CC:-cc} -std=c99 -O1 -Wall -Wextra -o "$build/interp" "$here/interp.c" -lOSMesa -lGL -lm

limit=
if command -v timeout >/dev/null 2>&1; then limit="timeout 300"; fi

for script in "$here"/cases/*.calls; do
    name=$(basename "$script" .calls)
    # run from cases/ so that messages name the script relative to it
    (cd "$here/cases" && $limit "$build/interp" "$name.calls") > "$out/$name.out.tmp"
    mv "$out/$name.out.tmp" "$out/$name.out"
done

if [ "$check" -eq 1 ]; then
    if diff -r -u "$here/expected" "$out"; then
        echo "calls: all outputs match expected/"
    else
        echo "calls: outputs differ from expected/ (see diff above)" >&2
        exit 1
    fi
fi
