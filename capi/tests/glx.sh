#!/bin/sh
# GLX and EGL on gleval beside real Mesa: capi/tests/glx/calls.c (good and bad calls, each
# answer printed: return values, X/GLX/EGL errors, drawn pixels) is built against the
# system's libGL, libEGL and Xlib and run twice, on Mesa and through capi/gleval-run, with GLX
# in an Xvfb of its own and with surfaceless EGL (no X server); the outputs must be the same.
# Then the lines where Mesa departs from GLX's specification are checked on gleval alone,
# Debian's glxinfo must print gleval's strings and visuals, and glxgears (run unchanged) must
# draw its three gears headless (--png). Last, capi/tests/glx/fuzz.c's random calls with
# handles that are not handles must end as they began.
#
#   capi/tests/glx.sh [OUT]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=${CARGO_TARGET_DIR:-$root/target}
out=${1:-$target/capi/glx}
profile=${CAPI_PROFILE:-test}
dir=debug
[ "$profile" = release ] && dir=release
cargo build --quiet --profile "$profile" -p gleval-c --manifest-path "$root/Cargo.toml"
export GLEVAL_LIB_DIR="$target/$dir"
run="$root/capi/gleval-run"
mkdir -p "$out"
cc -std=gnu99 -O1 -Wall -o "$out/calls" "$here/glx/calls.c" -lGL -lEGL -lX11 -lpthread
cc -std=gnu99 -O1 -Wall -o "$out/fuzz" "$here/glx/fuzz.c" -lGL -lEGL -lX11 -lpthread

display=:$(( $$ % 400 + 100 ))
Xvfb "$display" -screen 0 640x480x24 -nolisten tcp -noreset >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1
failed=0

same() { # NAME MESA GLEVAL
  if cmp -s "$2" "$3"; then
    echo "glx.sh: $1: gleval answers as Mesa ($(wc -l < "$2") lines)"
  else
    echo "glx.sh: $1: gleval differs from Mesa:"
    diff "$2" "$3" || true
    failed=1
  fi
}

DISPLAY=$display "$out/calls" glx > "$out/glx.mesa.txt" 2>&1
DISPLAY=$display "$run" "$out/calls" glx > "$out/glx.gleval.txt" 2>&1
same "GLX calls" "$out/glx.mesa.txt" "$out/glx.gleval.txt"
env -u DISPLAY "$out/calls" egl > "$out/egl.mesa.txt" 2>&1
env -u DISPLAY "$run" "$out/calls" egl > "$out/egl.gleval.txt" 2>&1
same "EGL calls (surfaceless, no X server)" "$out/egl.mesa.txt" "$out/egl.gleval.txt"

# Where Mesa departs from the specifications, gleval follows them.
DISPLAY=$display "$run" "$out/calls" glx gleval > "$out/glx.strict.txt" 2>&1
for line in \
  "glXMakeCurrent of a context current in another thread: False, X error 10" \
  "glXGetProcAddress(glNoSuchFunction): NULL" \
  "glXUseXFont: GL error 0x0" \
  "front buffer after the swap: pixel 0 0 255 255, GL error 0x0"; do
  if grep -qxF "$line" "$out/glx.strict.txt"; then
    echo "glx.sh: $line"
  else
    echo "glx.sh: expected \"$line\" (see $out/glx.strict.txt)"
    failed=1
  fi
done

DISPLAY=$display "$run" glxinfo > "$out/glxinfo.txt" 2>&1
for want in "OpenGL vendor string: gleval" "OpenGL version string: 1.5 gleval" "8 GLX Visuals" "8 GLXFBConfigs:"; do
  if grep -qF "$want" "$out/glxinfo.txt"; then
    echo "glx.sh: glxinfo: $want"
  else
    echo "glx.sh: glxinfo does not print \"$want\" (see $out/glxinfo.txt)"
    failed=1
  fi
done

rm -f "$out/glxgears.png"
DISPLAY=$display timeout 60 "$run" --png "$out/glxgears.png" glxgears > "$out/glxgears.log" 2>&1 || true
if [ -f "$out/glxgears.png" ]; then
  # The gears' colours (red, green, blue, lit): each covers part of the 300 x 300 window.
  counts=$(convert "$out/glxgears.png" -format "%[fx:mean.r>0.05?1:0] %[fx:mean.g>0.02?1:0] %[fx:mean.b>0.02?1:0]" info:)
  if [ "$counts" = "1 1 1" ]; then
    echo "glx.sh: glxgears drew its red, green and blue gears ($out/glxgears.png)"
  else
    echo "glx.sh: glxgears' picture lacks a gear's colour ($counts; $out/glxgears.png)"
    failed=1
  fi
else
  echo "glx.sh: glxgears wrote no picture (see $out/glxgears.log)"
  failed=1
fi
# Random GLX and EGL calls with handles that are not handles, in two threads (gleval only).
for seed in 1 2 3; do
  if DISPLAY=$display timeout 300 "$run" "$out/fuzz" 3000 $seed > "$out/fuzz.$seed.txt" 2>&1 &&
    ! grep -q 'failed inside the library' "$out/fuzz.$seed.txt"; then
    echo "glx.sh: fuzz seed $seed: $(tail -1 "$out/fuzz.$seed.txt")"
  else
    echo "glx.sh: fuzz seed $seed crashed, hung or panicked:"
    tail -20 "$out/fuzz.$seed.txt"
    failed=1
  fi
done
exit $failed
