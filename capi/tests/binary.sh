#!/bin/sh
# Programs already built: the C programs of tests/reference/pictures and the textbook's four
# (capi/examples/textbook), compiled the ordinary way against the system's Mesa and freeglut
# (`cc prog.c -lglut -lGLU -lGL -lm`, their headers, nothing of gleval), then run unchanged on
# gleval through capi/gleval-run with --png. Each picture is scored against real Mesa's with the
# project's image metric (1% bound), and the score must be the one the same source scores when
# built with capi/glevalcc (capi/tests/pictures.sh and capi/tests/textbook.sh, run first, leave
# those pictures).
#
# Also checked: every function gleval's headers declare has the system headers' prototype (the
# same calling convention: a conflicting declaration does not compile); a program that calls
# something gleval lacks is not started, and gleval-run names the symbol.
#
#   capi/tests/binary.sh [OUT_DIR]     (default $CARGO_TARGET_DIR or target, then capi/binary)
#
# Expects libgleval_c and gleval-compare built (capi/tests/pictures.sh builds them); the same
# CAPI_PROFILE as there.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
pictures="$root/tests/reference/pictures"
book="$root/capi/examples/textbook"
target=${CARGO_TARGET_DIR:-$root/target}
out=${1:-$target/capi/binary}
dir=debug
[ "${CAPI_PROFILE:-test}" = release ] && dir=release
export GLEVAL_LIB_DIR="$target/$dir"
compare="$GLEVAL_LIB_DIR/gleval-compare"
export LC_ALL=C
mkdir -p "$out"
failed=0

# 1. Prototypes: gleval's declarations (its headers preprocessed, functions only) after the
# system's headers; a prototype that differs does not compile.
for h in gl glu glut; do
  printf '#include <GL/%s.h>\n' "$h" | cc -E -P -I"$root/capi/include" -x c - |
    tr '\n' ' ' | tr ';' '\n' | grep -E '\b(gl|glu|glut)[A-Z][A-Za-z0-9]* *\(' | grep -v typedef |
    sed 's/^ *//; s/$/;/'
done | sort -u > "$out/declared.h"
{
  echo '#include <GL/gl.h>'
  echo '#include <GL/glu.h>'
  echo '#include <GL/freeglut.h>'
  cat "$out/declared.h"
} > "$out/prototypes.c"
if cc -std=gnu99 -fsyntax-only -Werror "$out/prototypes.c" 2> "$out/prototypes.log"; then
  echo "binary: $(wc -l < "$out/declared.h") prototypes of gleval's headers are the system headers' (Mesa's GL/gl.h, GL/glu.h, freeglut's GL/freeglut.h)"
else
  echo "binary: gleval's prototypes differ from the system headers':"; grep -E 'error' "$out/prototypes.log" | head -20
  failed=1
fi

# 2. The pictures. Their "gl.h" includes <GL/gl.h>, <GL/glu.h> and the OSMesa GLUT stand-in
# glut_osmesa.h (the reference's harness): its guard defined, and freeglut's <GL/freeglut.h>
# included first instead (its GL/freeglut_ext.h declares glutStrokeHeight and
# glutStrokeLengthf), they are the system's GL, GLU and GLUT programs. A call without a
# declaration is an error: C would take it to return int.
score() { # score REFERENCE.png PICTURE.png: the metric's line, or "failed"
  "$compare" "$1" "$2" 0.01 || echo "above 1%"
}
run_one() { # run_one NAME BINARY MESA_PNG GLEVALCC_PNG
  name=$1 bin=$2 mesa=$3 theirs=$4
  # The system's libraries, not gleval's (libGLU.so.1 only where the program calls GLU).
  needed=$(readelf -d "$bin" | sed -n 's/.*NEEDED.*\[\(.*\)\]/\1/p')
  case "$needed" in *libgleval_c*) echo "$name: linked with gleval"; failed=1; return ;; esac
  echo "$needed" | grep -qx 'libGL\.so\.1' && echo "$needed" | grep -q '^libglut\.so\.3' ||
    { echo "$name: not linked with the system's libGL.so.1 and libglut.so.3"; failed=1; return; }
  if ! "$root/capi/gleval-run" "$bin" --png "$bin.png" 2> "$bin.log"; then
    echo "$name: failed to run on gleval (see $bin.log)"; cat "$bin.log"; failed=1; return
  fi
  ours=$(score "$mesa" "$bin.png")
  if [ ! -f "$theirs" ]; then
    echo "$name: $theirs missing (run capi/tests/pictures.sh and capi/tests/textbook.sh first)"; failed=1; return
  fi
  built=$(score "$mesa" "$theirs")
  printf '%s (system build on gleval-run): %s; glevalcc build: %s\n' "$name" "$ours" "$built"
  case "$ours" in *above*) failed=1 ;; esac
  [ "$ours" = "$built" ] || { echo "$name: the scores differ"; failed=1; }
}
for src in "$pictures"/*.c; do
  name=$(basename "$src" .c)
  [ "$name" = glut_osmesa ] && continue
  lower=$(echo "$name" | tr 'A-Z' 'a-z')
  if ! cc -std=gnu99 -O1 -w -I"$pictures" -Werror=implicit-function-declaration -DGLUT_OSMESA_H -include GL/freeglut.h -o "$out/$lower" "$src" \
    -lglut -lGLU -lGL -lm; then
    echo "$lower: does not build against the system's GL, GLU and GLUT"; failed=1; continue
  fi
  run_one "$lower" "$out/$lower" "$pictures/png/$lower.png" "$target/capi/pictures/$lower.png"
done

# 3. The textbook's four as printed (their gll.h includes <GL/glut.h>): scored against the
# picture real Mesa draws from the same source (capi/tests/textbook.sh's .mesa.png).
for name in BezCurve BezSurf BCurve BSurf; do
  lower=$(echo "$name" | tr 'A-Z' 'a-z')
  if ! cc -std=gnu99 -O1 -w -Werror=implicit-function-declaration -I"$book" -o "$out/$lower.book" "$book/$name.c" -lglut -lGLU -lGL -lm; then
    echo "$lower (textbook): does not build against the system's GL, GLU and GLUT"; failed=1; continue
  fi
  run_one "$lower (textbook)" "$out/$lower.book" "$target/capi/textbook/$lower.mesa.png" "$target/capi/textbook/$lower.png"
done

# 4. A call gleval lacks (a GL 4.3 compute dispatch), and a GLX context: named, not started.
# A program that calls what gleval lacks, itself and through a library it links (as piglit
# and FLTK keep their GL calls in libraries): gleval-run names both, and not the GLX call
# gleval serves.
cat > "$out/lacking.c" <<'EOF'
#define GL_GLEXT_PROTOTYPES
#include <GL/glut.h>
#include <GL/glext.h>
#include <GL/glx.h>
void lacking_in_library(void);
int main(int argc, char **argv) {
    glutInit(&argc, argv);
    if (argc > 5) glXGetCurrentContext();
    if (argc > 6) lacking_in_library();
    glDispatchCompute(1, 1, 1);
    return 0;
}
EOF
cat > "$out/liblacking.c" <<'EOF'
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
void lacking_in_library(void) { glDispatchComputeIndirect(0); }
EOF
cc -shared -fPIC -o "$out/liblacking.so" "$out/liblacking.c" -lGL
cc -o "$out/lacking" "$out/lacking.c" -L"$out" -llacking -Wl,-rpath,"$out" -lglut -lGL
if "$root/capi/gleval-run" "$out/lacking" > "$out/lacking.log" 2>&1; then
  echo "lacking: started although gleval lacks glDispatchCompute"; failed=1
elif grep -q '^  glDispatchCompute$' "$out/lacking.log" &&
  grep -q "^  glDispatchComputeIndirect (from $out/liblacking.so)$" "$out/lacking.log" &&
  ! grep -q 'glX' "$out/lacking.log" && ! grep -q 'symbol lookup error' "$out/lacking.log"; then
  echo "lacking: not started, glDispatchCompute and the library's glDispatchComputeIndirect named"
else
  echo "lacking: unexpected message:"; cat "$out/lacking.log"; failed=1
fi
exit $failed
