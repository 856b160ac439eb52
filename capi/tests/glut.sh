#!/bin/sh
# GLUT's windows and freeglut's calls through the C ABI, built with capi/glevalcc:
# 1. tests/reference/glut/Windows.c (two windows and a subwindow) headless: each window's
#    picture (PATH, PATH-3) equals real freeglut's under Xvfb pixel for pixel
#    (tests/reference/glut/windows-*.png, captured by tools/freeglut_check/windows.sh --save);
# 2. tests/reference/glut/Calls.c: GLUT's X options out of argv, glutGet, GLEW, glutGetProcAddress,
#    the warning handler, window data, and glutMainLoop returning after the close callback;
# 3. tests/reference/glut/Events.c runs headless to the end of its loop;
# 4. tests/reference/glut/Menus.c: menus are the program's, as freeglut prints them (menus.log).
#   capi/tests/glut.sh     (after cargo build -p gleval-c)
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
ref="$here/tests/reference/glut"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc="env GLEVAL_PROFILE=${GLEVAL_PROFILE:-debug} $here/capi/glevalcc -std=gnu99 -Wall -Werror"

$cc -o "$work/windows" "$ref/Windows.c"
"$work/windows" --png "$work/w.png" > "$work/windows.log"
python3 "$here/tools/freeglut_check/cmp.py" "$ref/windows-first.png" "$work/w.png" | tee "$work/cmp1"
python3 "$here/tools/freeglut_check/cmp.py" "$ref/windows-second.png" "$work/w-3.png" | tee "$work/cmp2"
grep -q '^0 of' "$work/cmp1" && grep -q '^0 of' "$work/cmp2"
diff "$ref/windows.log" "$work/windows.log"
echo "glut: Windows.c's windows and callbacks as freeglut's"

$cc -o "$work/menus" "$ref/Menus.c"
"$work/menus" --png "$work/m.png" > "$work/menus.log" 2>/dev/null
diff "$ref/menus.log" "$work/menus.log"
echo "glut: Menus.c's menus are the program's, as freeglut's"

$cc -o "$work/calls" "$ref/Calls.c" -lGLEW
"$work/calls" -geometry 64x48+5+6 mine -direct -sync -gldebug --png "$work/c.png" > "$work/calls.log"
cat > "$work/expected" <<'END'
argc 2: mine
init window 5 6 64 48
warning: WARNING - Display string token not recognized:  bogus
display mode 18
glew before a window 1
glewInit 0 No error, 1.1 1, 2.0 0
glew extensions: fog_coord 1, point_parameters 1, texture_cube_map 1
window 1 size 64 48 version 30400
proc glBegin 1 glutSolidCube 1 glFooBar 0
extension 0
window data 42
warning: glutSetWindow(): window ID 7 not found!
devices keyboard 1 joystick 0 layer 0 game 0
close 1
returned
END
diff "$work/expected" "$work/calls.log"
[ -s "$work/c.png" ]
echo "glut: Calls.c as expected (X options, glutGet, GLEW, handlers, the loop returning)"

$cc -o "$work/events" "$ref/Events.c"
"$work/events" --png "$work/e.png" > "$work/events.log"
tail -2 "$work/events.log" | tr '\n' ' ' | grep -q '^close 1 0 returned 0 0 $'
echo "glut: Events.c closes its window and returns from glutMainLoop headless"

# GLEVAL_DEBUG names each GL error on stderr with the call that raised it, once for a call
# that calls another (glTexImage3DEXT), as MESA_DEBUG has Mesa do; without it, nothing.
cat > "$work/debug.c" <<'END'
#include <GL/glut.h>
int main(int argc, char **argv) {
    glutInit(&argc, argv);
    glutCreateWindow("debug");
    glEnable(0x1234);
    glGetError();
    glTexImage3DEXT(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, 0);
    glTexImage3DEXT(GL_TEXTURE_3D, 0, GL_RGB, 1, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, 0);
    return glGetError() != GL_INVALID_ENUM;
}
END
$cc -o "$work/debug" "$work/debug.c"
GLEVAL_DEBUG=1 "$work/debug" 2> "$work/debug.log"
printf 'gleval: glEnable: GL_INVALID_ENUM\ngleval: glTexImage3DEXT: GL_INVALID_ENUM\n' | diff - "$work/debug.log"
"$work/debug" 2> "$work/quiet.log"
[ ! -s "$work/quiet.log" ]
echo "glut: GLEVAL_DEBUG names each error and its call"

# freeglut's context settings are recorded for glutGet and warn of nothing (freeglut 3.4 prints
# nothing here); a core profile, which gleval does not have, is said once.
cat > "$work/profile.c" <<'END'
#include <GL/freeglut.h>
#include <stdio.h>
int main(int argc, char **argv) {
    glutInitContextVersion(2, 1);
    glutInitContextProfile(argc > 1 ? GLUT_CORE_PROFILE : GLUT_COMPATIBILITY_PROFILE);
    glutInitContextProfile(argc > 1 ? GLUT_CORE_PROFILE : GLUT_COMPATIBILITY_PROFILE);
    glutInit(&argc, argv);
    glutCreateWindow("profile");
    printf("%d %d\n", glutGet(GLUT_INIT_MAJOR_VERSION), glutGet(GLUT_INIT_PROFILE) == (argc > 1 ? GLUT_CORE_PROFILE : GLUT_COMPATIBILITY_PROFILE));
    return 0;
}
END
$cc -o "$work/profile" "$work/profile.c"
[ "$("$work/profile" 2> "$work/profile.log")" = "2 1" ] && [ ! -s "$work/profile.log" ]
"$work/profile" core 2> "$work/core.log" > /dev/null
[ "$(grep -c 'core profile' "$work/core.log")" = 1 ] && [ "$(wc -l < "$work/core.log")" = 1 ]
echo "glut: glutInitContextProfile records the profile and warns of nothing"
