/* Prints gluErrorString for every GL/GLU error code gleval knows, from the real GLU.
   Build: cc error_strings.c -lGLU -lGL -o error_strings */
#include <GL/glu.h>
#include <stdio.h>

static void show(GLenum code) {
    const GLubyte *s = gluErrorString(code);
    printf("%u %s\n", code, s ? (const char *)s : "(null)");
}

int main(void) {
    GLenum gl[] = {0, 0x0500, 0x0501, 0x0502, 0x0503, 0x0504, 0x0505, 100900, 100901, 100902, 100903, 100904};
    for (unsigned i = 0; i < sizeof gl / sizeof gl[0]; i++) show(gl[i]);
    for (GLenum n = 100251; n <= 100287; n++) show(n);
    show(100288);
    return 0;
}
