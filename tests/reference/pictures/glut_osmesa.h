/* A GLUT stand-in for the reference programs: the same calls the textbook uses, but the
   "window" is an OSMesa buffer that glutMainLoop renders once and writes as a PNG
   (--png PATH, default <program>.png), or renders N times with --time N and prints the median
   frame time. */
#ifndef GLUT_OSMESA_H
#define GLUT_OSMESA_H
#define GLUT_RGB 0
#define GLUT_RGBA 0
#define GLUT_SINGLE 0
#define GLUT_DOUBLE 2
#define GLUT_DEPTH 16
#define GLUT_ACCUM 4
#define GLUT_STENCIL 32
#define GLUT_WINDOW_WIDTH 102
#define GLUT_WINDOW_HEIGHT 103
void glutInit(int *argc, char **argv);
void glutInitWindowSize(int w, int h);
void glutInitWindowPosition(int x, int y);
void glutInitDisplayMode(unsigned int mode);
int glutCreateWindow(const char *title);
void glutDisplayFunc(void (*f)(void));
void glutReshapeFunc(void (*f)(int, int));
void glutKeyboardFunc(void (*f)(unsigned char, int, int));
/* Mouse callbacks: accepted, never called (the picture is the first frame). */
#define GLUT_LEFT_BUTTON 0
#define GLUT_DOWN 0
#define GLUT_UP 1
#define GLUT_MIDDLE_BUTTON 1
#define GLUT_RIGHT_BUTTON 2
void glutMouseFunc(void (*f)(int, int, int, int));
void glutMotionFunc(void (*f)(int, int));
/* Menus: built and numbered from 1 as freeglut does, never shown (no mouse headless). */
int glutCreateMenu(void (*f)(int));
void glutAddMenuEntry(const char *label, int value);
void glutAttachMenu(int button);
int glutGet(unsigned int what);
void glutPostRedisplay(void);
void glutSwapBuffers(void);
void glutMainLoop(void);
/* Bitmap fonts: freeglut's handle values; glyphs from glut_fonts.h (tools/fonts/gen.py). */
#define GLUT_BITMAP_9_BY_15 ((void *)0x0002)
#define GLUT_BITMAP_8_BY_13 ((void *)0x0003)
#define GLUT_BITMAP_TIMES_ROMAN_10 ((void *)0x0004)
#define GLUT_BITMAP_TIMES_ROMAN_24 ((void *)0x0005)
#define GLUT_BITMAP_HELVETICA_10 ((void *)0x0006)
#define GLUT_BITMAP_HELVETICA_12 ((void *)0x0007)
#define GLUT_BITMAP_HELVETICA_18 ((void *)0x0008)
void glutBitmapCharacter(void *font, int character);
int glutBitmapWidth(void *font, int character);
int glutBitmapLength(void *font, const unsigned char *string);
void glutBitmapString(void *font, const unsigned char *string);
/* Stroke fonts: freeglut's handle values; glyphs from glut_strokes.h (tools/fonts/gen_stroke.py). */
#define GLUT_STROKE_ROMAN ((void *)0x0000)
#define GLUT_STROKE_MONO_ROMAN ((void *)0x0001)
void glutStrokeCharacter(void *font, int character);
void glutStrokeString(void *font, const unsigned char *string);
int glutStrokeWidth(void *font, int character);
float glutStrokeWidthf(void *font, int character);
int glutStrokeLength(void *font, const unsigned char *string);
float glutStrokeLengthf(void *font, const unsigned char *string);
float glutStrokeHeight(void *font);
void glutSolidTeapot(double size);
void glutWireTeapot(double size);
/* The round solids and the cube, drawn as freeglut 3.4 draws them (glut_shapes.h). */
void glutSolidSphere(double radius, int slices, int stacks);
void glutWireSphere(double radius, int slices, int stacks);
void glutSolidCube(double size);
void glutWireCube(double size);
void glutSolidCone(double base, double height, int slices, int stacks);
void glutWireCone(double base, double height, int slices, int stacks);
void glutSolidTorus(double inner, double outer, int sides, int rings);
void glutWireTorus(double inner, double outer, int sides, int rings);
#endif
