# Sourced by the capi/tests/*_window.sh scripts: a C program of tests/reference/pictures built
# against gleval with glevalcc, run in a real window in its own Xvfb and driven with xdotool;
# screenshots of the window and their pixels. The sourcing script sets $root and $out.

# run_in_xvfb SOURCE NAME TITLE DISPLAY: builds SOURCE as $out/NAME, starts Xvfb on DISPLAY
# and the program in it, and waits for the window titled TITLE ($wid; the program is $prog).
# Both are killed when the script exits.
run_in_xvfb() {
  dir=debug
  [ "${CAPI_PROFILE:-test}" = release ] && dir=release
  export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
  mkdir -p "$out"
  pictures="$root/tests/reference/pictures"
  "$root/capi/glevalcc" -std=gnu99 -O1 -w -I"$pictures" -o "$out/$2" "$pictures/$1" -lm
  Xvfb "$4" -screen 0 640x480x24 -noreset >/dev/null 2>&1 &
  xvfb=$!
  prog=
  trap 'kill $prog $xvfb 2>/dev/null || true' EXIT
  export DISPLAY="$4"
  sleep 1
  "$out/$2" >"$out/$2.log" 2>&1 &
  prog=$!
  wid=$(timeout 60 xdotool search --sync --name "$3" | head -1)
  sleep 2
}

# shot NAME: the window to $out/NAME.png.
shot() { import -window "$wid" "$out/$1.png"; }

# pixel NAME X Y: the pixel (X, Y) from the window's top left of shot NAME, as "r g b".
pixel() { convert "$out/$1.png" -format "%[fx:int(255*u.p{$2,$3}.r)] %[fx:int(255*u.p{$2,$3}.g)] %[fx:int(255*u.p{$2,$3}.b)]" info:; }

# drag X Y DX DY: the left button pressed at window (X, Y), moved five steps of (DX, DY) and
# released.
drag() {
  xdotool mousemove --window "$wid" "$1" "$2" mousedown 1
  for step in 1 2 3 4 5; do
    xdotool mousemove --window "$wid" $(($1 + $3 * step)) $(($2 + $4 * step))
    sleep 0.2
  done
  xdotool mouseup 1
  sleep 1
}
