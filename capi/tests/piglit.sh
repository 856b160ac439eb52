#!/bin/sh
# piglit, the suite Mesa's CI runs, judges gleval: its OpenGL 1.0 and 1.1 groups (311 tests,
# Debian's prebuilt package) through capi/gleval-run, with GLX under Xvfb and with surfaceless
# EGL (no X server), each result beside the one committed in tests/piglit/expected.tsv. It
# fails if a test that passes there does not pass now, or if a test crashes or hangs; tests
# that pass now and did not before are named (update the file: tests/piglit/README.md).
#
#   capi/tests/piglit.sh [OUT]        # results and each test's output under OUT
#
# Needs python3, Xvfb, libwaffle-1-0 and apt-get download (for the package, fetched once into
# target/piglit).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=${CARGO_TARGET_DIR:-$root/target}
out=${1:-$target/capi/piglit}
profile=${CAPI_PROFILE:-test}
dir=debug
[ "$profile" = release ] && dir=release
cargo build --quiet --profile "$profile" -p gleval-c --manifest-path "$root/Cargo.toml"
export GLEVAL_LIB_DIR="$target/$dir"
run="python3 $root/tests/piglit/run.py"
$run fetch
mkdir -p "$out"
status=0
for platform in glx surfaceless_egl; do
  column=gleval-$( [ $platform = glx ] && echo glx || echo egl )
  $run run --gl gleval --platform $platform --jobs 2 --timeout 60 --out "$out/$column.tsv" --logs "$out/$column-logs"
  $run check "$root/tests/piglit/expected.tsv" "$out/$column.tsv" --column $column || status=1
done
exit $status
