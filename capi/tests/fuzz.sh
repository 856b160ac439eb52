#!/bin/sh
# The C fuzz driver (capi/tests/fuzz.c) for a fixed number of calls and seeds: NULL pointers,
# negative orders, absurd grids, NaN through the C ABI, then the frame rendered to a PNG. Fails
# if a run crashes, does not finish, writes no picture, or the library caught a panic (it
# reports each on stderr: a panic is a bug even though C never sees it).
#   capi/tests/fuzz.sh [CALLS] [SEEDS]     (default 5000 calls, seeds 1..6; seed 1 also --gpu)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
calls=${1:-5000}
seeds=${2:-6}
out="${CARGO_TARGET_DIR:-$root/target}/capi/fuzz"
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
mkdir -p "$out"
"$root/capi/glevalcc" -std=gnu99 -O1 -Wall -Werror -o "$out/fuzz" "$root/capi/tests/fuzz.c" -lm
run() {
  rm -f "$out/fuzz.png"
  if ! timeout 300 "$out/fuzz" "$calls" "$@" --png "$out/fuzz.png" 2>"$out/stderr"; then
    echo "fuzz $*: crashed or timed out"; cat "$out/stderr"; exit 1
  fi
  if grep -q 'failed inside the library' "$out/stderr"; then
    echo "fuzz $*: the library panicked (caught)"; cat "$out/stderr"; exit 1
  fi
  [ -s "$out/fuzz.png" ] || { echo "fuzz $*: no picture"; exit 1; }
}
for seed in $(seq 1 "$seeds"); do
  printf 'seed %s: ' "$seed"; run "$seed"
done
printf 'seed 1, GPU tessellator: '; run 1 --gpu
