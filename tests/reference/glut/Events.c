/* Events.c: GLUT's main-loop control and input, for tools/freeglut_check/events.sh, which drives
 * it with xdotool under Xvfb with real freeglut and with gleval and compares the logs: the
 * mouse wheel (freeglut's glutMouseWheelFunc, or buttons 3 and 4 without one), keys and their
 * releases, a held key's repeats (on, ignored with glutIgnoreKeyRepeat, off with
 * glutSetKeyRepeat), the window manager's close (glutCloseFunc, GLUT_ACTION_ON_WINDOW_CLOSE)
 * and glutLeaveMainLoop; glutMainLoop returns and the program goes on. */
#include <GL/freeglut.h>
#include <stdio.h>

static int wheel_func = 1;

static void log_event(const char *what, int a, int b)
{
    printf("%s %d %d\n", what, a, b);
    fflush(stdout);
}

static void display(void)
{
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glutSwapBuffers();
}

static void wheel(int wheel, int direction, int x, int y) { (void)x; (void)y; log_event("wheel", wheel, direction); }
static void mouse(int button, int state, int x, int y) { (void)x; (void)y; log_event("mouse", button, state); }
static void key_up(unsigned char key, int x, int y) { (void)x; (void)y; log_event("key_up", key, 0); }
static void close_window(void) { log_event("close", glutGetWindow(), 0); }

static void key(unsigned char key, int x, int y)
{
    (void)x; (void)y;
    log_event("key", key, 0);
    switch (key) {
    case 'w': /* the wheel without its callback: buttons 3 and 4 */
        wheel_func = !wheel_func;
        glutMouseWheelFunc(wheel_func ? wheel : NULL);
        break;
    case 'i': glutIgnoreKeyRepeat(1); break;
    case 'o': glutIgnoreKeyRepeat(0); glutSetKeyRepeat(GLUT_KEY_REPEAT_OFF); break;
    case 'n': glutSetKeyRepeat(GLUT_KEY_REPEAT_ON); break;
    case 'q': glutLeaveMainLoop(); break;
    }
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE);
    glutInitWindowPosition(0, 0);
    glutInitWindowSize(200, 200);
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutCreateWindow("events");
    glutDisplayFunc(display);
    glutMouseWheelFunc(wheel);
    glutMouseFunc(mouse);
    glutKeyboardFunc(key);
    glutKeyboardUpFunc(key_up);
    glutCloseFunc(close_window);
    glutMainLoop();
    /* freeglut has deinitialised itself: no GLUT call is allowed here. */
    log_event("returned", 0, 0);
    return 0;
}
