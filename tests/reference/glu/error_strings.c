/* Prints gluErrorString for every code in 0..65535 and 100000..100999 (every GL and GLU error
   lies there) that real GLU has a message for; every other code there answers NULL
   (tests/it/glu_errors.rs checks both). Build: cc error_strings.c -lGLU -lGL -o error_strings */
#include <GL/glu.h>
#include <stdio.h>

static void scan(GLenum from, GLenum to) {
    printf("range %u %u\n", from, to);
    for (GLenum code = from; code <= to; code++) {
        const GLubyte *s = gluErrorString(code);
        if (s) printf("%u %s\n", code, (const char *)s);
    }
}

int main(void) {
    scan(0, 65535);
    scan(100000, 100999);
    return 0;
}
