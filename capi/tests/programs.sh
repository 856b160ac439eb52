#!/bin/sh
# Unchanged programs of the usual toolkits (Xlib + GLX, SDL2, pygame, pyglet, FLTK, PyOpenGL's
# GLUT; sources in capi/tests/programs/), each drawing the same lit bicubic Bezier surface with
# glMap2f + glMapGrid2f + glEvalMesh2 and a glMap1f curve in a 400x400 window, run in real
# windows under their own Xvfb twice: on the system's Mesa (llvmpipe; a plain run) and on
# gleval (capi/gleval-run). A screenshot of each program's own window (ImageMagick's import)
# after it has drawn, and the share of pixels that differ between the two (the project's
# metric, gleval-compare), one line a program. Fails if a program does not build, run, open
# its window or draw, exits with an error, or differs from Mesa by more than 1% of pixels.
# Debian's glxgears is run both ways too (shown, not compared: it animates by the clock) and
# glxinfo -B through gleval-run must name gleval as the vendor.
#   capi/tests/programs.sh [OUT_DIR]      (default target/capi/programs)
# Each program exits by itself after 3 s; the script kills what is left after 10 s more.
#
# Needs (Debian 12 package names; versions that worked):
#   apt: xvfb xdotool imagemagick mesa-utils (glxgears, glxinfo; 8.5.0) libgl1-mesa-dri
#        libgl-dev libx11-dev libsdl2-dev (2.26.5) libfltk1.3-dev (1.3.8) freeglut3-dev
#        (3.4.0, for PyOpenGL's GLUT) binutils (nm, for gleval-run) gcc g++
#   pip: pygame (2.6.1) PyOpenGL (3.1.10) "pyglet<2" (1.5.31)
# The library and gleval-compare are built as the other capi scripts build them (the test
# profile, target/debug; CAPI_PROFILE=release for target/release). PYTHON names the Python
# (default python3).
#
# The threshold: the aim is pixel-exact agreement with Mesa. gleval-compare already forgives
# a one-pixel shift of an edge; what remains above that is rounding of lit colours by one
# level and pixels at silhouette edges. 1% (1600 of 160000 pixels) is room for those and well
# below a real fault of the surface: a wrong normal, light, material or projection, or a
# missing surface, changes 10-40% of the window. The one-pixel curve is only ~470 pixels
# (0.3%), so it is checked on its own: gleval's picture must have as many pure yellow pixels
# as Mesa's within 20%.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$root/target/capi/programs}
src="$root/capi/tests/programs"
threshold=0.01
profile=${CAPI_PROFILE:-test}
dir=debug
[ "$profile" = release ] && dir=release
cargo build --quiet --profile "$profile" -p gleval-c --manifest-path "$root/Cargo.toml"
export GLEVAL_LIB_DIR="${CARGO_TARGET_DIR:-$root/target}/$dir"
metric="$GLEVAL_LIB_DIR/gleval-compare"
python=${PYTHON:-python3}
run="$root/capi/gleval-run"
for need in Xvfb xdotool import convert; do
  command -v "$need" >/dev/null 2>&1 || { echo "programs: $need not found" >&2; exit 1; }
done
[ -x "$metric" ] || { echo "programs: $metric not found" >&2; exit 1; }
[ -f "$GLEVAL_LIB_DIR/libgleval_c.so" ] || { echo "programs: $GLEVAL_LIB_DIR/libgleval_c.so not found" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/*.png "$out"/*.log

# Our own Xvfb on the first free display from one of this run's own (the process id). With
# -noreset: an X server resets when its last client leaves, and refuses connections while it
# does (measured: 423 of 2000 back-to-back XOpenDisplay calls fail without it, none with it).
n=$(( $$ % 300 + 900 ))
while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp -noreset >"$out/xvfb.log" 2>&1 &
xvfb=$!
prog=
trap 'kill $prog $xvfb 2>/dev/null || true' EXIT
export DISPLAY=":$n"
i=0
until xdotool getdisplaygeometry >/dev/null 2>&1; do
  i=$((i + 1))
  [ $i -lt 50 ] || { echo "programs: Xvfb :$n did not start" >&2; cat "$out/xvfb.log" >&2; exit 1; }
  sleep 0.1
done

failed=0
fail() { echo "$1: FAIL: $2"; failed=1; }

# build NAME COMMAND...: builds a program into $out; a failure is reported.
build() {
  name=$1
  shift
  "$@" >"$out/$name.build.log" 2>&1 || { fail "$name" "does not build: $(tail -n 5 "$out/$name.build.log")"; return 1; }
}

# shoot SHOT TITLE WAIT COMMAND...: runs COMMAND (log $out/SHOT.log), waits for its visible
# window titled TITLE, then WAIT seconds for it to draw, takes $out/SHOT.png, and waits for the
# program to end (killed after 10 s). Returns 1, with $why set, if the program ended before
# its window showed, no window showed within 30 s, or it ended with an error; killed, it
# returns 0 with $killed=1.
shoot() {
  shot=$1 title=$2 delay=$3
  shift 3
  why= killed=0 wid=
  "$@" >"$out/$shot.log" 2>&1 &
  prog=$!
  i=0
  while [ -z "$wid" ]; do
    if ! kill -0 "$prog" 2>/dev/null; then
      status=0
      wait "$prog" || status=$?
      prog=
      why="ended (status $status) before its window showed: $(tail -n 5 "$out/$shot.log")"
      return 1
    fi
    i=$((i + 1))
    if [ $i -gt 150 ]; then
      kill "$prog" 2>/dev/null || true
      wait "$prog" 2>/dev/null || true
      prog=
      why="no window titled \"$title\" within 30 s: $(tail -n 5 "$out/$shot.log")"
      return 1
    fi
    wid=$(find_window "$title")
    [ -n "$wid" ] || sleep 0.2
  done
  sleep "$delay"
  import -window "$wid" "$out/$shot.png" 2>>"$out/$shot.log" || why="no screenshot of window $wid"
  i=0
  while kill -0 "$prog" 2>/dev/null && [ $i -lt 100 ]; do
    sleep 0.1
    i=$((i + 1))
  done
  if kill -0 "$prog" 2>/dev/null; then
    killed=1
    kill "$prog" 2>/dev/null || true
    sleep 0.5
    kill -9 "$prog" 2>/dev/null || true
  fi
  status=0
  wait "$prog" || status=$?
  prog=
  # Let the window go before the next program maps its own at the same place.
  i=0
  while [ $i -lt 50 ] && [ -n "$(find_window "$title")" ]; do
    sleep 0.1
    i=$((i + 1))
  done
  [ -z "$why" ] || return 1
  if [ $killed = 0 ] && [ $status != 0 ]; then
    why="exited with status $status: $(tail -n 5 "$out/$shot.log")"
    return 1
  fi
  return 0
}

# find_window TITLE: the id of a viewable window titled TITLE, if any. xdotool's --name does not
# match names stored as UTF-8 WM_NAME (SDL2 in pygame's wheel stores them so); xwininfo does.
find_window() {
  w=$(xdotool search --onlyvisible --name "^$1\$" 2>/dev/null | head -n 1 || true)
  if [ -z "$w" ]; then
    for w in $(xwininfo -root -tree 2>/dev/null | awk -v t="\"$1\":" 'index($0, t) { print $1 }'); do
      if xwininfo -id "$w" 2>/dev/null | grep -q 'Map State: IsViewable'; then echo "$w"; return; fi
    done
    w=
  fi
  echo "$w"
}

# colours PNG: how many distinct colours the picture has (a drawn scene has hundreds).
colours() { convert "$1" -format '%k' info:; }

# yellow PNG: how many pixels are the curve's pure yellow.
yellow() { convert "$1" -fill black +opaque '#ffff00' -fill white -opaque '#ffff00' -format '%[fx:round(mean*w*h)]' info:; }

# judge NAME GLEVAL_SHOT: $out/NAME.mesa.png against $out/GLEVAL_SHOT.png; prints the share of
# differing pixels (and how many are not exactly equal) to stdout in $verdict; 1 if above the
# threshold or not comparable.
judge() {
  verdict=
  for shot in "$1.mesa" "$2"; do
    c=$(colours "$out/$shot.png")
    if [ "$c" -lt 10 ]; then verdict="nothing drawn in $out/$shot.png ($c colours)"; return 1; fi
  done
  size_m=$(identify -format '%wx%h' "$out/$1.mesa.png")
  size_g=$(identify -format '%wx%h' "$out/$2.png")
  if [ "$size_m" != "$size_g" ]; then verdict="window $size_g on gleval, $size_m on Mesa"; return 1; fi
  exact=$(compare -metric AE "$out/$1.mesa.png" "$out/$2.png" null: 2>&1 || true)
  yellow_m=$(yellow "$out/$1.mesa.png")
  yellow_g=$(yellow "$out/$2.png")
  if [ $((yellow_g * 5)) -lt $((yellow_m * 4)) ] || [ $((yellow_g * 5)) -gt $((yellow_m * 6)) ]; then
    verdict="the curve: $yellow_g yellow pixels on gleval, $yellow_m on Mesa; $exact pixels not exactly equal"
    return 1
  fi
  if result=$("$metric" "$out/$1.mesa.png" "$out/$2.png" "$threshold" 2>&1); then
    verdict="$result; $exact pixels not exactly equal; curve $yellow_g yellow pixels (Mesa $yellow_m)"
  else
    case "$result" in
      *"% of pixels differ"*) verdict="$result, above $(awk "BEGIN { print $threshold * 100 }")% (diff: $out/$2.diff.png); $exact pixels not exactly equal" ;;
      *) verdict="gleval-compare: $result" ;;
    esac
    return 1
  fi
}

# program NAME TITLE COMMAND...: the program on Mesa and on gleval, screenshots
# $out/NAME.mesa.png and $out/NAME.gleval.png, compared. If gleval-run refuses the program
# for calls gleval lacks, that fails, and the program is run once more with
# GLEVAL_RUN_CHECK=0 ($out/NAME.gleval-nocheck.png) to show how far it gets.
program() {
  name=$1 title=$2
  shift 2
  if ! shoot "$name.mesa" "$title" 1.5 "$@"; then fail "$name" "on Mesa: $why"; return; fi
  if ! shoot "$name.gleval" "$title" 1.5 "$run" "$@"; then
    if grep -q 'calls what gleval lacks' "$out/$name.gleval.log"; then
      fail "$name" "gleval-run: calls what gleval lacks: $(grep '^  ' "$out/$name.gleval.log" | tr -s ' \n' ' ')"
      if ! GLEVAL_RUN_CHECK=0 shoot "$name.gleval-nocheck" "$title" 1.5 "$run" "$@"; then
        echo "  with GLEVAL_RUN_CHECK=0: $why"
      elif judge "$name" "$name.gleval-nocheck"; then
        echo "  with GLEVAL_RUN_CHECK=0: $verdict"
      else
        echo "  with GLEVAL_RUN_CHECK=0: FAIL: $verdict"
      fi
    else
      fail "$name" "on gleval: $why"
    fi
    return
  fi
  note=
  [ $killed = 0 ] || note=" (did not exit by itself: killed)"
  if judge "$name" "$name.gleval"; then echo "$name: $verdict$note"; else fail "$name" "$verdict$note"; fi
}

cflags="-O1 -Wall -I$src"
if build glx_bezsurf cc $cflags -o "$out/glx_bezsurf" "$src/glx_bezsurf.c" -lGL -lX11 -lm; then
  program glx_bezsurf "bezsurf glx" "$out/glx_bezsurf"
fi
if build sdl2_bezsurf sh -c "cc $cflags -o '$out/sdl2_bezsurf' '$src/sdl2_bezsurf.c' \$(sdl2-config --cflags --libs) -lGL -lm"; then
  program sdl2_bezsurf "bezsurf sdl2" "$out/sdl2_bezsurf"
fi
if build fltk_bezsurf sh -c "g++ $cflags -o '$out/fltk_bezsurf' '$src/fltk_bezsurf.cxx' \$(fltk-config --use-gl --cxxflags --ldflags) -lGL -lm"; then
  program fltk_bezsurf "bezsurf fltk" "$out/fltk_bezsurf"
fi
program pygame_bezsurf "bezsurf pygame" "$python" "$src/pygame_bezsurf.py"
program pyglet_bezsurf "bezsurf pyglet" "$python" "$src/pyglet_bezsurf.py"
program pyopengl_glut_bezsurf "bezsurf glut" "$python" "$src/pyopengl_glut_bezsurf.py"

# glxgears: it animates by the clock, so the two pictures are not compared; both must show
# gears (it never exits by itself: killed after the screenshot).
if command -v glxgears >/dev/null 2>&1; then
  if ! shoot glxgears.mesa glxgears 1.5 glxgears; then fail glxgears "on Mesa: $why"
  elif ! shoot glxgears.gleval glxgears 1.5 "$run" glxgears; then fail glxgears "on gleval: $why"
  else
    c=$(colours "$out/glxgears.gleval.png")
    if [ "$c" -lt 10 ]; then fail glxgears "on gleval: nothing drawn ($c colours)"
    else echo "glxgears: runs on gleval ($c colours; animated, not compared; $("$metric" "$out/glxgears.mesa.png" "$out/glxgears.gleval.png" 2>&1 || true) from Mesa's frame)"
    fi
  fi
fi
# glxinfo -B: the vendor must be gleval's.
if command -v glxinfo >/dev/null 2>&1; then
  glxinfo -B >"$out/glxinfo.mesa.log" 2>&1 || true
  if "$run" glxinfo -B >"$out/glxinfo.gleval.log" 2>&1 && grep -q '^OpenGL vendor string: gleval' "$out/glxinfo.gleval.log"; then
    echo "glxinfo: $(grep '^OpenGL vendor string' "$out/glxinfo.gleval.log"); $(grep '^OpenGL renderer string' "$out/glxinfo.gleval.log" || true)"
  else
    fail glxinfo "no \"OpenGL vendor string: gleval\": $(tail -n 5 "$out/glxinfo.gleval.log")"
  fi
fi

echo "screenshots in $out"
exit $failed
