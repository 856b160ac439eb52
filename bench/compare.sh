#!/bin/sh
# Runs the C anchor (real Mesa evaluators and GLU tessellator through OSMesa) and the Rust
# benchmark side by side and prints "<case> ours=<M/s> anchor=<M/s> ratio=<x>".
#
#   sh bench/compare.sh [ROUNDS]
#
# Each round runs the anchor and then ours; with several rounds (default 1) every column is the
# median over the rounds, the ratio being the median of each round's own ratio, since the
# machine's speed drifts between rounds (shared cores) more than within one.
# The typed-API grid cases (grid_N, grid_fresh_N, grid_normals_N) are compared with Mesa's eval_mesh2_N.
# The whole_* cases are whole processes (bench/whole_process.sh): each textbook program's headless
# PNG render, the C original on OSMesa against the Rust port, in renders per second.
# cold_first_eval_mesh2_1000 is the first eval_mesh2 of a process (memory fresh from the kernel),
# the median of 5 new processes a side; first_eval_mesh2_1000 repeats it in one process.
# Peak memory of the 4000^2 typed case goes to stderr.
set -eu
rounds=${1:-1}
here=$(cd "$(dirname "$0")" && pwd)
# Cargo's output folder: $CARGO_TARGET_DIR (relative to where this is started, as cargo reads
# it) or the workspace's target/. whole_process.sh reads it from the environment too.
case "${CARGO_TARGET_DIR:-}" in
  "") ;;
  /*) export CARGO_TARGET_DIR ;;
  *) CARGO_TARGET_DIR="$PWD/$CARGO_TARGET_DIR"; export CARGO_TARGET_DIR ;;
esac
release="${CARGO_TARGET_DIR:-$here/../target}/release"
build="$here/../tests/reference/build/bench"
mkdir -p "$build"
cc -std=gnu99 -O2 -o "$build/anchor" "$here/anchor.c" -lOSMesa -lGLU -lGL -lm
(cd "$here/.." && cargo build --release --quiet --example bench --example bezcurve --example bezsurf --example bcurve \
  --example bsurf --example ex1_bezier --example ex2_bspline --example ex3_bspline_n --example ex4_bspline_surface \
  --example ex5_bird)
: > "$build/rounds.txt"
r=1
while [ "$r" -le "$rounds" ]; do
  GALLIUM_DRIVER=llvmpipe "$build/anchor" > "$build/anchor.txt"
  "$release/examples/bench" > "$build/ours.txt"
  sh "$here/whole_process.sh" anchor 5 >> "$build/anchor.txt"
  sh "$here/whole_process.sh" ours 5 >> "$build/ours.txt"
  # The first eval_mesh2 of a process: 5 new processes a side, their median.
  for side in anchor ours; do
    k=0
    while [ "$k" -lt 5 ]; do
      if [ "$side" = anchor ]; then GALLIUM_DRIVER=llvmpipe "$build/anchor" cold
      else BENCH_COLD=1 "$release/examples/bench" first_eval_mesh2_1000; fi
      k=$((k + 1))
    done | sort -k2 -n | awk '{ v[NR] = $0 } END { print v[int((NR + 1) / 2)] }' >> "$build/$side.txt"
  done
  # One line per case and round: case ours anchor (anchor "-" where it has no such case).
  awk 'NR == FNR { anchor[$1] = $2; next }
       { key = $1; sub(/^grid_(fresh_|normals_)?/, "eval_mesh2_", key)
         print $1, $2, (key in anchor) ? anchor[key] : "-" }' "$build/anchor.txt" "$build/ours.txt" >> "$build/rounds.txt"
  r=$((r + 1))
done
awk 'function median(list,   n, a, i, j, t) {
       n = split(list, a, " ")
       for (i = 2; i <= n; i++) { t = a[i]; for (j = i - 1; j >= 1 && a[j] + 0 > t + 0; j--) a[j + 1] = a[j]; a[j + 1] = t }
       return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
     }
     !($1 in seen) { seen[$1] = 1; order[++cases] = $1 }
     { ours[$1] = ours[$1] " " $2
       if ($3 != "-") { anchor[$1] = anchor[$1] " " $3; ratio[$1] = ratio[$1] " " $2 / $3 } }
     END {
       for (k = 1; k <= cases; k++) {
         c = order[k]
         if (c ~ /^whole_/)
           printf "%s ours=%.1f/s anchor=%.1f/s ratio=%.2f\n", c, median(ours[c]), median(anchor[c]), median(ratio[c])
         else if (c in anchor)
           printf "%s ours=%.2f anchor=%.2f ratio=%.2f\n", c, median(ours[c]) / 1e6, median(anchor[c]) / 1e6, median(ratio[c])
         else
           printf "%s ours=%.2f anchor=- ratio=-\n", c, median(ours[c]) / 1e6
       }
     }' "$build/rounds.txt"
