#!/bin/sh
# Checks capi/include/GL/{gl,glu,freeglut_std,freeglut_ext}.h (glut.h and freeglut.h include the last two):
# 1. every constant has the value the system's headers give it (Mesa's GL/gl.h and GL/glext.h,
#    GL/glu.h, freeglut's GL/freeglut_std.h and GL/freeglut_ext.h): the values are the API's, so an independent
#    header is the truth to compare with;
# 2. the headers declare exactly the functions libgleval_c exports, so a call gleval lacks
#    does not compile, and nothing implemented is hidden;
# 3. every function of the system's GL/gl.h up to GL 1.1, GL/glu.h, GL/freeglut_std.h and
#    GL/freeglut_ext.h is declared.
#   capi/tests/headers.sh LIBDIR     (the directory holding libgleval_c.so)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
lib="$1/libgleval_c.so"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. Constants: one static assertion each, compiled against the system's headers.
{
  echo '#define GL_GLEXT_PROTOTYPES'
  echo '#include <GL/gl.h>'
  echo '#include <GL/glext.h>'
  echo '#include <GL/glu.h>'
  echo '#include <GL/freeglut_std.h>'
  echo '#include <GL/freeglut_ext.h>'
  sed -n 's/^#define \(GLU\{0,1\}T\{0,1\}_[A-Z0-9_]*\) \([0-9xA-Fa-f]*\)$/#ifdef \1\n_Static_assert(\1 == \2, "\1");\n#else\nMISSING(\1)\n#endif/p' \
    "$here"/include/GL/gl.h "$here"/include/GL/glu.h "$here"/include/GL/freeglut_std.h \
    "$here"/include/GL/freeglut_ext.h
} > "$tmp/consts.c"
missing=$(cc -E -P "$tmp/consts.c" | grep -o 'MISSING([A-Z0-9_]*)' || true)
cc -std=c11 -fsyntax-only -DMISSING\(x\)= "$tmp/consts.c"
echo "headers: $(grep -c _Static_assert "$tmp/consts.c") constants checked against the system headers"
[ -z "$missing" ] || echo "headers: not in the system headers: $missing"

# 2. Declarations against exports.
grep -ho '\b\(gl\|glu\|glut\)[A-Z][A-Za-z0-9]*(' "$here"/include/GL/*.h | tr -d '(' | sort -u > "$tmp/declared"
nm -D --defined-only "$lib" | awk '$2 == "T" {print $3}' | grep '^\(gl\|glu\|glut\)[A-Z]' | grep -v '^glX' | sort -u > "$tmp/exported"
if ! diff "$tmp/declared" "$tmp/exported" > "$tmp/diff"; then
  echo "headers: declared (<) and exported (>) functions differ:"; cat "$tmp/diff"; exit 1
fi
echo "headers: $(wc -l < "$tmp/declared") functions declared, all exported, none more"

# 2b. GLX and EGL: gleval's programs use the system's GL/glx.h and EGL/egl.h (with Xlib's
#     types); every glX and egl function exported is one those headers (or their extension
#     headers) declare, so none has a name of gleval's own.
nm -D --defined-only "$lib" | awk '$2 == "T" {print $3}' | grep '^\(glX\|egl\)[A-Z]' | sort -u > "$tmp/window"
cat /usr/include/GL/glx.h /usr/include/GL/glxext.h /usr/include/EGL/egl.h /usr/include/EGL/eglext.h 2>/dev/null |
  grep -o '\b\(glX\|egl\)[A-Z][A-Za-z0-9]* *(' | tr -d '( ' | sort -u > "$tmp/window_system"
unknown=$(comm -23 "$tmp/window" "$tmp/window_system")
if [ -n "$unknown" ]; then
  echo "headers: exported GLX/EGL functions the system's headers do not declare:"; echo "$unknown"; exit 1
fi
echo "headers: $(wc -l < "$tmp/window") GLX and EGL functions exported, each declared by the system's GL/glx.h or EGL/egl.h"

# 3. The system's GL 1.1 functions (Mesa's GL/gl.h before its "OpenGL 1.2" section), GLU 1.3
#    functions and freeglut functions, all declared here (and so, by 2, exported).
awk '/^ \* OpenGL 1\.2/ {exit} {print}' /usr/include/GL/gl.h | grep -o '\bgl[A-Z][A-Za-z0-9]* *(' | tr -d '( ' | sort -u > "$tmp/system"
lacking=$(comm -23 "$tmp/system" "$tmp/declared")
if [ -n "$lacking" ]; then
  echo "headers: GL 1.1 functions of the system's GL/gl.h not declared here:"; echo "$lacking"; exit 1
fi
echo "headers: all $(wc -l < "$tmp/system") GL 1.1 functions of the system's GL/gl.h declared"
for h in glu freeglut_std freeglut_ext; do
  grep -ho '\b\(glu\|glut\)[A-Z][A-Za-z0-9]* *(' "/usr/include/GL/$h.h" | tr -d '( ' | sort -u > "$tmp/system"
  lacking=$(comm -23 "$tmp/system" "$tmp/declared")
  if [ -n "$lacking" ]; then
    echo "headers: functions of the system's GL/$h.h not declared here:"; echo "$lacking"; exit 1
  fi
  echo "headers: all $(wc -l < "$tmp/system") functions of the system's GL/$h.h declared"
done

# 4. OpenGL 1.2 to 1.5: every core function of the system's GL/gl.h (its "OpenGL 1.2" and
#    "OpenGL 1.3" sections, the imaging subset between them) and GL/glext.h (GL_VERSION_1_2 to
#    GL_VERSION_1_5) declared here (and so, by 2, exported).
{
  awk '/^ \* OpenGL 1\.2/ {p=1} /^ \* GL_ARB_multitexture/ {exit} p' /usr/include/GL/gl.h |
    grep -o '\bgl[A-Z][A-Za-z0-9]* *(' | tr -d '( '
  awk '/^#ifndef GL_VERSION_1_2$/ {p=1} /^#ifndef GL_VERSION_2_0$/ {exit} p' /usr/include/GL/glext.h |
    grep -o 'APIENTRY gl[A-Z][A-Za-z0-9]* *(' | sed 's/APIENTRY //' | tr -d '( '
} | sort -u > "$tmp/core_1_5"
lacking=$(comm -23 "$tmp/core_1_5" "$tmp/declared")
if [ -n "$lacking" ]; then
  echo "headers: GL 1.2-1.5 functions of the system's headers not declared here:"; echo "$lacking"; exit 1
fi
echo "headers: all $(wc -l < "$tmp/core_1_5") GL 1.2-1.5 functions of the system's GL/gl.h and GL/glext.h declared"
