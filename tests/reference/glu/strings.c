/* Prints real GLU's gluGetString for GLU_VERSION, GLU_EXTENSIONS and a bad name, and
   gluCheckExtension for names against extension strings (tab-separated fields: the answer,
   the name, the string). tests/it/glu_errors.rs asks gleval the same.
   Build: cc strings.c -lGLU -lGL -o strings */
#include <GL/glu.h>
#include <stdio.h>

static void get(const char *label, GLenum name) {
    const GLubyte *s = gluGetString(name);
    printf("get\t%s\t%u\t%s\n", label, name, s ? (const char *)s : "(null)");
}

int main(void) {
    get("GLU_VERSION", GLU_VERSION);
    get("GLU_EXTENSIONS", GLU_EXTENSIONS);
    get("0", 0);
    get("GL_VERSION", GL_VERSION);
    get("GLU_VERSION+2", GLU_VERSION + 2);
    const char *strings[] = {"GLU_EXT_nurbs_tessellator GLU_EXT_object_space_tess ", "a  b ", " a", "ab", "", "a\tb"};
    const char *names[] = {"GLU_EXT_nurbs_tessellator", "GLU_EXT_object_space_tess", "GLU_EXT", "a", "b", "a b",
                           "", "ab", "GLU_EXT_object_space_tess "};
    for (unsigned s = 0; s < sizeof strings / sizeof strings[0]; s++)
        for (unsigned n = 0; n < sizeof names / sizeof names[0]; n++)
            printf("check\t%d\t%s\t%s\n", gluCheckExtension((const GLubyte *)names[n], (const GLubyte *)strings[s]),
                   names[n], strings[s]);
    return 0;
}
