#!/bin/sh
# The whole process of a headless render, as a test suite pays it: each textbook program as
# the C original on real Mesa (OSMesa, tests/reference/pictures) and as its Rust port
# (`--png`), start to exit, alternated. Prints "whole_<program> <renders per second>" for one
# side per line: "anchor" lines first, then "ours", each the median of RUNS runs.
#
#   sh bench/whole_process.sh anchor|ours [RUNS]
set -eu
side=$1
runs=${2:-9}
here=$(cd "$(dirname "$0")" && pwd)
# The Rust ports in cargo's output folder: $CARGO_TARGET_DIR, else the workspace's target/.
release="${CARGO_TARGET_DIR:-$here/../target}/release"
pictures="$here/../tests/reference/pictures"
build="$here/../tests/reference/build/bench"
mkdir -p "$build"
export GALLIUM_DRIVER=llvmpipe LC_ALL=C
# C program : Rust example.
programs="BezCurve:bezcurve BezSurf:bezsurf BCurve:bcurve BSurf:bsurf Ex1Bezier:ex1_bezier Ex2BSpline:ex2_bspline Ex3BSplineN:ex3_bspline_n Ex4BSplineSurface:ex4_bspline_surface Ex5Bird:ex5_bird"
now_ns() { date +%s%N; }
for pair in $programs; do
  c=${pair%%:*}
  rust=${pair#*:}
  lower=$(echo "$c" | tr 'A-Z' 'a-z')
  if [ "$side" = anchor ]; then
    bin="$build/whole_$lower"
    [ -x "$bin" ] || cc -std=gnu99 -O2 -w -I"$pictures" -o "$bin" "$pictures/$c.c" "$pictures/glut_osmesa.c" -lOSMesa -lGLU -lGL -lz -lm
    cmd="$bin --png $build/whole_$lower.png"
  else
    cmd="$release/examples/$rust --png $build/whole_$lower.png"
  fi
  times=""
  i=0
  while [ "$i" -lt "$runs" ]; do
    start=$(now_ns)
    $cmd >/dev/null 2>&1
    end=$(now_ns)
    times="$times $((end - start))"
    i=$((i + 1))
  done
  echo "$times" | tr ' ' '\n' | grep . | sort -n | awk -v name="whole_$lower" '{ t[NR] = $1 } END { printf "%s %.2f\n", name, 1e9 / t[int((NR + 1) / 2)] }'
done
