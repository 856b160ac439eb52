#!/bin/sh
# Checks capi/include/GL/{gl,glu,glut}.h:
# 1. every constant has the value the system's headers give it (Mesa's GL/gl.h and GL/glext.h,
#    GL/glu.h, freeglut's GL/freeglut_std.h): the values are the API's, so an independent
#    header is the truth to compare with;
# 2. the headers declare exactly the functions libgleval_c exports, so a call gleval lacks
#    does not compile, and nothing implemented is hidden.
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
  sed -n 's/^#define \(GLU\{0,1\}T\{0,1\}_[A-Z0-9_]*\) \([0-9xA-Fa-f]*\)$/#ifdef \1\n_Static_assert(\1 == \2, "\1");\n#else\nMISSING(\1)\n#endif/p' \
    "$here"/include/GL/gl.h "$here"/include/GL/glu.h "$here"/include/GL/glut.h
} > "$tmp/consts.c"
missing=$(cc -E -P "$tmp/consts.c" | grep -o 'MISSING([A-Z0-9_]*)' || true)
cc -std=c11 -fsyntax-only -DMISSING\(x\)= "$tmp/consts.c"
echo "headers: $(grep -c _Static_assert "$tmp/consts.c") constants checked against the system headers"
[ -z "$missing" ] || echo "headers: not in the system headers: $missing"

# 2. Declarations against exports.
grep -ho '\b\(gl\|glu\|glut\)[A-Z][A-Za-z0-9]*(' "$here"/include/GL/*.h | tr -d '(' | sort -u > "$tmp/declared"
nm -D --defined-only "$lib" | awk '$2 == "T" {print $3}' | grep '^\(gl\|glu\|glut\)[A-Z]' | sort -u > "$tmp/exported"
if ! diff "$tmp/declared" "$tmp/exported" > "$tmp/diff"; then
  echo "headers: declared (<) and exported (>) functions differ:"; cat "$tmp/diff"; exit 1
fi
echo "headers: $(wc -l < "$tmp/declared") functions declared, all exported, none more"
