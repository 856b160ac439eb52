/* Windows.c: two top-level windows and a subwindow, each with its own context and callbacks,
 * for tools/freeglut_check/windows.sh: the pictures of both windows (the subwindow drawn in
 * place) and the order of the callbacks, with real freeglut under Xvfb and with gleval.
 * Rectangles on whole pixels, so that any rasteriser fills the same pixels. */
#include <GL/glut.h>
#include <stdio.h>

static int first, sub, second;

static void log_event(const char *what, int a, int b)
{
    printf("%s window=%d %d %d\n", what, glutGetWindow(), a, b);
    fflush(stdout);
}

static void pixels(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void reshape(int w, int h) { log_event("reshape", w, h); pixels(w, h); }
static void visibility(int v) { log_event("visibility", v, 0); }

static void display_first(void)
{
    log_event("display", glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT));
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 0);
    glRecti(110, 20, 190, 130);
    glutSwapBuffers();
}

static void display_sub(void)
{
    log_event("display", glutGet(GLUT_WINDOW_X), glutGet(GLUT_WINDOW_Y));
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glRecti(10, 10, 30, 50);
    glutSwapBuffers();
}

static void display_second(void)
{
    log_event("display", glutGet(GLUT_WINDOW_PARENT), glutGet(GLUT_WINDOW_NUM_CHILDREN));
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0, 0, 1);
    glRecti(40, 30, 120, 90);
    glutSwapBuffers();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
    glutInitWindowPosition(0, 0);
    glutInitWindowSize(200, 150);
    first = glutCreateWindow("first");
    glClearColor(0.0f, 0.0f, 0.5f, 1.0f);
    glutDisplayFunc(display_first);
    glutReshapeFunc(reshape);
    glutVisibilityFunc(visibility);
    sub = glutCreateSubWindow(first, 20, 30, 80, 60);
    glClearColor(0.8f, 0.0f, 0.0f, 1.0f);
    glutDisplayFunc(display_sub);
    glutReshapeFunc(reshape);
    glutInitWindowPosition(300, 0);
    glutInitWindowSize(160, 120);
    second = glutCreateWindow("second");
    glClearColor(0.0f, 0.6f, 0.0f, 1.0f);
    glutDisplayFunc(display_second);
    glutReshapeFunc(reshape);
    glutSetWindow(first);
    printf("created %d %d %d current %d\n", first, sub, second, glutGetWindow());
    glutMainLoop();
    return 0;
}
