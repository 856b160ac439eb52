#!/bin/sh
# piglit, the suite Mesa's CI runs, judges gleval: its OpenGL 1.0 to 1.5 groups and the groups
# of the extensions GL 1.2 to 1.5 took in (471 tests, tests/piglit/groups.tsv, Debian's
# prebuilt package) through capi/gleval-run, with GLX under Xvfb and with surfaceless EGL (no
# X server), each result beside the one committed in tests/piglit/expected.tsv. It fails if a
# test that passes there does not pass now, or if a test crashes or hangs; tests that pass now
# and did not before are named (update the file: tests/piglit/README.md).
#
#   capi/tests/piglit.sh [OUT]        # results and each test's output under OUT
#   PIGLIT_GROUPS=gl-1.1 capi/tests/piglit.sh    # only the 1.0 and 1.1 groups (311 tests)
#
# Needs python3, Xvfb, libwaffle-1-0 and apt-get download (for the package, fetched once into
# target/piglit).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=${CARGO_TARGET_DIR:-$root/target}
out=${1:-$target/capi/piglit}
groups=${PIGLIT_GROUPS:-all}
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
  $run run --gl gleval --platform $platform --groups "$groups" --jobs 2 --timeout 60 --out "$out/$column.tsv" --logs "$out/$column-logs"
  $run check "$root/tests/piglit/expected.tsv" "$out/$column.tsv" --column $column --groups "$groups" || status=1
done
exit $status
