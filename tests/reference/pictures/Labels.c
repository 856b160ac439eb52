// Labels.c: text and images at the raster position. A Bezier curve (glMap1f/glEvalMesh1) whose
// control points are labelled with glRasterPos + glutBitmapCharacter in four GLUT fonts, a title
// whose colour is the one current at glRasterPos (not the later glColor), a right-aligned caption
// (glutBitmapLength and a zero-sized glBitmap that moves the raster position back), a label whose
// raster position is clipped (drawn nowhere), a glDrawPixels gradient (RGB rows padded to the
// default alignment of 4) and a luminance checker (alignment 1), and a hand-made glBitmap arrow
// (LSB first, rows padded to 4) compiled into a display list and called three times.
#include <stddef.h>
#include "gl.h"

static GLfloat ctrl[4][3] = {{-3.2, -2.0, 0.0}, {-1.5, 2.6, 0.0}, {1.2, -2.6, 0.0}, {3.0, 1.8, 0.0}};
static GLubyte arrow[12][4];
static GLubyte gradient[16][64];
static GLubyte checker[8][8];
static GLuint arrow_list;

static void label(void *font, const char *s)
{
    while (*s)
        glutBitmapCharacter(font, *s++);
}

static void init(void)
{
    glClearColor(0.1, 0.1, 0.15, 1.0);
    glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &ctrl[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(40, 0.0, 1.0);

    // A 16 x 12 arrow pointing right: a shaft and a triangular head.
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 16; i++) {
            int shaft = i < 9 && j >= 4 && j < 8;
            int d = 2 * j - 11;
            int head = i >= 8 && (d < 0 ? -d : d) < 2 * (15 - i);
            if (shaft || head)
                arrow[j][i / 8] |= 1 << (i % 8);
        }
    // 21 x 16 RGB pixels: 63 bytes a row, padded to 64.
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 21; i++) {
            gradient[j][3 * i] = 12 * i;
            gradient[j][3 * i + 1] = 16 * j;
            gradient[j][3 * i + 2] = 200;
        }
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++)
            checker[j][i] = ((i / 2 + j / 2) % 2) ? 255 : 60;

    arrow_list = glGenLists(1);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glNewList(arrow_list, GL_COMPILE);
    glBitmap(16, 12, 0.0, 6.0, 20.0, 0.0, &arrow[0][0]);
    glEndList();
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4.0, 4.0, -4.0, 4.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    static const char *names[4] = {"P0", "P1", "P2", "P3"};
    void *fonts[4] = {GLUT_BITMAP_HELVETICA_18, GLUT_BITMAP_TIMES_ROMAN_24, GLUT_BITMAP_9_BY_15,
                      GLUT_BITMAP_8_BY_13};
    glClear(GL_COLOR_BUFFER_BIT);

    glColor3f(0.5, 0.5, 0.6);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 4; i++)
        glVertex3fv(ctrl[i]);
    glEnd();
    glColor3f(0.3, 0.9, 1.0);
    glLineWidth(2.0);
    glEvalMesh1(GL_LINE, 0, 40);
    glLineWidth(1.0);
    glPointSize(6.0);
    glColor3f(1.0, 0.3, 0.2);
    glBegin(GL_POINTS);
    for (int i = 0; i < 4; i++)
        glVertex3fv(ctrl[i]);
    glEnd();

    glColor3f(1.0, 1.0, 0.6);
    for (int i = 0; i < 4; i++) {
        glRasterPos2f(ctrl[i][0] + 0.15f, ctrl[i][1] + 0.15f);
        label(fonts[i], names[i]);
    }

    glColor3f(1.0, 0.85, 0.2);
    glRasterPos2f(-3.8, 3.4);
    glColor3f(1.0, 0.0, 0.0); // too late: the raster colour was taken at glRasterPos
    label(GLUT_BITMAP_TIMES_ROMAN_24, "Bezier curve");
    glColor3f(0.8, 0.8, 0.8);
    glRasterPos2f(-3.8, 3.0);
    label(GLUT_BITMAP_HELVETICA_12, "glMap1f + glEvalMesh1, labels by glutBitmapCharacter");

    const char *caption = "right-aligned (Helvetica 10)";
    glColor3f(0.6, 1.0, 0.6);
    glRasterPos2f(3.8, -3.8);
    glBitmap(0, 0, 0.0, 0.0, -(GLfloat)glutBitmapLength(GLUT_BITMAP_HELVETICA_10, (const unsigned char *)caption),
             0.0, NULL);
    label(GLUT_BITMAP_HELVETICA_10, caption);

    glRasterPos2f(4.5, 0.0); // outside the clip volume: the label is not drawn
    label(GLUT_BITMAP_9_BY_15, "hidden");

    glColor3f(1.0, 1.0, 1.0);
    glRasterPos2f(-3.8, -3.5);
    glDrawPixels(21, 16, GL_RGB, GL_UNSIGNED_BYTE, gradient);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2f(-3.2, -3.5);
    glDrawPixels(8, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, checker);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glRasterPos2f(-3.8, -3.0);
    label(GLUT_BITMAP_TIMES_ROMAN_10, "glDrawPixels");

    glColor3f(1.0, 0.5, 1.0);
    glRasterPos2f(0.5, 2.8);
    for (int i = 0; i < 3; i++)
        glCallList(arrow_list);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Labels");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
