/* Calls.c: freeglut's calls a C program makes around its windows, for capi/tests/glut.sh:
 * GLUT's X options taken out of argv, glutGet before and after a window, GLEW as textbooks
 * use it, glutGetProcAddress, glutExtensionSupported, window and menu data, the message
 * handlers, and glutMainLoop returning with GLUT_ACTION_GLUTMAINLOOP_RETURNS. */
#ifndef NO_GLEW /* -DNO_GLEW: for freeglut where GLEW's headers are not installed */
#include <GL/glew.h>
#endif
#include <GL/freeglut.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static int data = 42;

static void warning(const char *fmt, va_list ap)
{
    printf("warning: ");
    vprintf(fmt, ap);
    printf("\n");
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 0);
    glutSolidTeacup(0.8);
    glutSwapBuffers();
}

static void close_window(void) { printf("close %d\n", glutGetWindow()); }

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    printf("argc %d:", argc);
    for (int i = 1; i < argc; i++) printf(" %s", argv[i]);
    printf("\ninit window %d %d %d %d\n", glutGet(GLUT_INIT_WINDOW_X), glutGet(GLUT_INIT_WINDOW_Y),
           glutGet(GLUT_INIT_WINDOW_WIDTH), glutGet(GLUT_INIT_WINDOW_HEIGHT));
    glutInitWarningFunc(warning);
    glutInitDisplayString("rgb double depth>=16 bogus");
    printf("display mode %d\n", glutGet(GLUT_INIT_DISPLAY_MODE));
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
#ifndef NO_GLEW
    printf("glew before a window %d\n", glewInit());
#endif
    int w = glutCreateWindow("calls");
#ifndef NO_GLEW
    glewExperimental = GL_TRUE;
    GLenum e = glewInit();
    printf("glewInit %d %s, 1.1 %d, 2.0 %d\n", e, (const char *)glewGetErrorString(e), GLEW_VERSION_1_1, GLEW_VERSION_2_0);
    /* GLEW's extension flags follow GL_EXTENSIONS (gleval claims the first two, not the third). */
    printf("glew extensions: fog_coord %d, point_parameters %d, texture_cube_map %d\n", GLEW_EXT_fog_coord,
           GLEW_ARB_point_parameters, GLEW_ARB_texture_cube_map);
#endif
    printf("window %d size %d %d version %d\n", w, glutGet(GLUT_WINDOW_WIDTH), glutGet(GLUT_WINDOW_HEIGHT), glutGet(GLUT_VERSION));
    printf("proc glBegin %d glutSolidCube %d glFooBar %d\n", glutGetProcAddress("glBegin") == (GLUTproc)glBegin,
           glutGetProcAddress("glutSolidCube") == (GLUTproc)glutSolidCube, glutGetProcAddress("glFooBar") != NULL);
    printf("extension %d\n", glutExtensionSupported("GL_EXT_bogus"));
    glutSetWindowData(&data);
    printf("window data %d\n", *(int *)glutGetWindowData());
    glutSetWindow(7);
    printf("devices keyboard %d joystick %d layer %d game %d\n", glutDeviceGet(GLUT_HAS_KEYBOARD),
           glutDeviceGet(GLUT_HAS_JOYSTICK), glutLayerGet(GLUT_OVERLAY_POSSIBLE), glutGameModeGet(GLUT_GAME_MODE_POSSIBLE));
    glutDisplayFunc(display);
    glutCloseFunc(close_window);
    glutMainLoop();
    printf("returned\n");
    return 0;
}
