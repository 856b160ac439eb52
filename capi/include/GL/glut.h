/* GL/glut.h for gleval: the GLUT calls gleval implements, over its window (winit) or
 * headless: `--png PATH` renders one frame to a PNG, `--time N` prints the median frame
 * time, `--frames N` runs N frames on a virtual 60 Hz clock, `--gpu` tessellates in WGSL.
 * glutInit takes these options out of argv.
 *
 * Written for gleval; the constants are freeglut's (GLUT 3.7's) values (src/glut/consts.rs,
 * checked against the system's freeglut header by capi/tests/headers.sh). Font handles are
 * the small integers freeglut uses where fonts are not symbols. */
#ifndef GLEVAL_GLUT_H
#define GLEVAL_GLUT_H
#define __GLUT_H__
#include <GL/gl.h>
#include <GL/glu.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLUT_API_VERSION 4

/* Bitmap fonts (glutBitmapCharacter). */
#define GLUT_BITMAP_9_BY_15 ((void *)0x0002)
#define GLUT_BITMAP_8_BY_13 ((void *)0x0003)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void *)0x0004)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void *)0x0005)
#define GLUT_BITMAP_HELVETICA_10 ((void *)0x0006)
#define GLUT_BITMAP_HELVETICA_12 ((void *)0x0007)
#define GLUT_BITMAP_HELVETICA_18 ((void *)0x0008)
/* Mouse buttons and states (glutMouseFunc), window entry (glutEntryFunc). */
#define GLUT_LEFT_BUTTON 0
#define GLUT_MIDDLE_BUTTON 1
#define GLUT_RIGHT_BUTTON 2
#define GLUT_DOWN 0
#define GLUT_UP 1
#define GLUT_LEFT 0
#define GLUT_ENTERED 1
/* Special keys (glutSpecialFunc, glutSpecialUpFunc). */
#define GLUT_KEY_F1 1
#define GLUT_KEY_F2 2
#define GLUT_KEY_F3 3
#define GLUT_KEY_F4 4
#define GLUT_KEY_F5 5
#define GLUT_KEY_F6 6
#define GLUT_KEY_F7 7
#define GLUT_KEY_F8 8
#define GLUT_KEY_F9 9
#define GLUT_KEY_F10 10
#define GLUT_KEY_F11 11
#define GLUT_KEY_F12 12
#define GLUT_KEY_LEFT 100
#define GLUT_KEY_UP 101
#define GLUT_KEY_RIGHT 102
#define GLUT_KEY_DOWN 103
#define GLUT_KEY_PAGE_UP 104
#define GLUT_KEY_PAGE_DOWN 105
#define GLUT_KEY_HOME 106
#define GLUT_KEY_END 107
#define GLUT_KEY_INSERT 108
/* Modifier bits (glutGetModifiers). */
#define GLUT_ACTIVE_SHIFT 1
#define GLUT_ACTIVE_CTRL 2
#define GLUT_ACTIVE_ALT 4
/* Display mode bits (glutInitDisplayMode). */
#define GLUT_RGB 0
#define GLUT_RGBA 0
#define GLUT_INDEX 1
#define GLUT_SINGLE 0
#define GLUT_DOUBLE 2
#define GLUT_ACCUM 4
#define GLUT_ALPHA 8
#define GLUT_DEPTH 16
#define GLUT_STENCIL 32
#define GLUT_MULTISAMPLE 128
#define GLUT_STEREO 256
/* glutGet names. */
#define GLUT_WINDOW_X 100
#define GLUT_WINDOW_Y 101
#define GLUT_WINDOW_WIDTH 102
#define GLUT_WINDOW_HEIGHT 103
#define GLUT_WINDOW_DEPTH_SIZE 106
#define GLUT_WINDOW_DOUBLEBUFFER 115
#define GLUT_WINDOW_RGBA 116
#define GLUT_SCREEN_WIDTH 200
#define GLUT_SCREEN_HEIGHT 201
#define GLUT_INIT_WINDOW_X 500
#define GLUT_INIT_WINDOW_Y 501
#define GLUT_INIT_WINDOW_WIDTH 502
#define GLUT_INIT_WINDOW_HEIGHT 503
#define GLUT_INIT_DISPLAY_MODE 504
#define GLUT_ELAPSED_TIME 700

/* Initialisation and the main loop. */
void glutInit(int *argcp, char **argv);
void glutInitWindowSize(int width, int height);
void glutInitWindowPosition(int x, int y);
void glutInitDisplayMode(unsigned int mode);
int glutCreateWindow(const char *title);
void glutMainLoop(void);

/* Callbacks. */
void glutDisplayFunc(void (*func)(void));
void glutReshapeFunc(void (*func)(int width, int height));
void glutKeyboardFunc(void (*func)(unsigned char key, int x, int y));
void glutKeyboardUpFunc(void (*func)(unsigned char key, int x, int y));
void glutSpecialFunc(void (*func)(int key, int x, int y));
void glutSpecialUpFunc(void (*func)(int key, int x, int y));
void glutMouseFunc(void (*func)(int button, int state, int x, int y));
void glutMotionFunc(void (*func)(int x, int y));
void glutPassiveMotionFunc(void (*func)(int x, int y));
void glutEntryFunc(void (*func)(int state));
void glutIdleFunc(void (*func)(void));
void glutTimerFunc(unsigned int msecs, void (*func)(int value), int value);

/* Requests and queries. */
void glutPostRedisplay(void);
void glutSwapBuffers(void);
int glutGet(GLenum what);
int glutGetModifiers(void);
void glutSetWindowTitle(const char *title);
void glutReshapeWindow(int width, int height);
void glutFullScreen(void);

/* Text and the teapot. */
void glutBitmapCharacter(void *font, int character);
void glutBitmapString(void *font, const unsigned char *string);
int glutBitmapWidth(void *font, int character);
int glutBitmapLength(void *font, const unsigned char *string);
int glutBitmapHeight(void *font);
void glutSolidTeapot(GLdouble size);
void glutWireTeapot(GLdouble size);

#ifdef __cplusplus
}
#endif
#endif /* GLEVAL_GLUT_H */
