#!/bin/sh
# Runs the C anchor (real Mesa evaluators and GLU tessellator through OSMesa) and the Rust
# benchmark in one invocation and prints "<case> ours=<M/s> anchor=<M/s> ratio=<x>".
# The typed-API grid cases (grid_N, grid_fresh_N, grid_normals_N) are compared with Mesa's eval_mesh2_N.
# Peak memory of the 4000^2 typed case goes to stderr.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build="$here/../tests/reference/build/bench"
mkdir -p "$build"
cc -std=gnu99 -O2 -o "$build/anchor" "$here/anchor.c" -lOSMesa -lGLU -lGL -lm
(cd "$here/.." && cargo build --release --quiet --example bench)
GALLIUM_DRIVER=llvmpipe "$build/anchor" > "$build/anchor.txt"
"$here/../target/release/examples/bench" > "$build/ours.txt"
awk 'NR == FNR { anchor[$1] = $2; next }
     { key = $1; sub(/^grid_(fresh_|normals_)?/, "eval_mesh2_", key)
       if (key in anchor) printf "%s ours=%.2f anchor=%.2f ratio=%.2f\n", $1, $2 / 1e6, anchor[key] / 1e6, $2 / anchor[key]
       else printf "%s ours=%.2f anchor=- ratio=-\n", $1, $2 / 1e6 }' "$build/anchor.txt" "$build/ours.txt"
