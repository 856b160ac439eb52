/* glutMainLoop for tools/freeglut_check: the program's display callback runs once in a real
   freeglut window, its back buffer is read with glReadPixels and written as a PPM ($OUT). */
#include <GL/gl.h>
#include <GL/glut.h>
#include <stdio.h>
#include <stdlib.h>
static void (*user_display)(void);
static void (*user_reshape)(int, int);
void fg_display_func(void (*f)(void)) { user_display = f; }
void fg_reshape_func(void (*f)(int, int)) { user_reshape = f; }
void fg_init_display_mode(unsigned int mode) { glutInitDisplayMode(mode | GLUT_DOUBLE); }
static void capture(void) {
    int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    user_display();
    glFinish();
    unsigned char *p = malloc(w * h * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, p);
    const char *out = getenv("OUT") ? getenv("OUT") : "out.ppm";
    FILE *f = fopen(out, "wb");
    fprintf(f, "P6 %d %d 255\n", w, h);
    for (int y = h - 1; y >= 0; y--) fwrite(p + y * w * 3, 1, w * 3, f);
    fclose(f);
    fprintf(stderr, "wrote %s %dx%d: %s\n", out, w, h, (const char *)glGetString(GL_RENDERER));
    exit(0);
}
void fg_main_loop(void) {
    glutReshapeFunc(user_reshape);
    glutDisplayFunc(capture);
    glutMainLoop();
}
