// CopyPixels.c: pixel rectangles copied and zoomed, in the style of the Red Book's image.c: a
// checkerboard drawn with glDrawPixels beside a depth-tested triangle and square, then copied
// with glCopyPixels at zoom 1, zoomed by 2 and 1.5, mirrored by negative zooms (-1, -1 and
// -2, 1), stretched to the window's edge by a huge zoom, copied over itself (the source is read
// before it is written), and the scene's depths copied in the raster colour under the depth
// test. Each copy reads the window as drawn so far.
#include "gl.h"

#define CHECK 64
static GLubyte checker[CHECK][CHECK][3];

static void init(void)
{
    for (int i = 0; i < CHECK; i++)
        for (int j = 0; j < CHECK; j++) {
            int c = ((i & 8) == 0) ^ ((j & 8) == 0);
            checker[i][j][0] = (GLubyte)(c ? 255 : 4 * i);
            checker[i][j][1] = (GLubyte)(c ? 255 : 4 * j);
            checker[i][j][2] = (GLubyte)(c ? 64 : 255 - 4 * i);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glClearColor(0.1, 0.1, 0.25, 1.0);
    glClearDepth(1.0);
}

static void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, w, 0.0, h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void scene(void)
{
    glRasterPos2i(8, 8);
    glDrawPixels(CHECK, CHECK, GL_RGB, GL_UNSIGNED_BYTE, checker);
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.9, 0.2, 0.1);
    glBegin(GL_TRIANGLES);
    glVertex3f(80.25, 10.25, 0.5);
    glVertex3f(140.75, 20.25, -0.5);
    glVertex3f(100.25, 70.75, 0.0);
    glEnd();
    glColor3f(0.2, 0.8, 0.3);
    glBegin(GL_QUADS);
    glVertex3f(100.25, 30.25, 0.2);
    glVertex3f(135.75, 30.25, 0.2);
    glVertex3f(135.75, 65.75, 0.2);
    glVertex3f(100.25, 65.75, 0.2);
    glEnd();
    glDisable(GL_DEPTH_TEST);
}

static void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene();
    /* zoom 1: the whole scene to the right */
    glRasterPos2i(160, 8);
    glCopyPixels(0, 0, 150, 80, GL_COLOR);
    /* zoom 2 and 1.5 */
    glPixelZoom(2.0, 2.0);
    glRasterPos2i(8, 90);
    glCopyPixels(8, 8, 40, 40, GL_COLOR);
    glPixelZoom(1.5, 1.5);
    glRasterPos2i(100, 90);
    glCopyPixels(80, 8, 60, 60, GL_COLOR);
    /* mirrored */
    glPixelZoom(-1.0, -1.0);
    glRasterPos2i(300, 250);
    glCopyPixels(8, 8, 64, 64, GL_COLOR);
    glPixelZoom(-2.0, 1.0);
    glRasterPos2i(300, 260);
    glCopyPixels(8, 8, 32, 32, GL_COLOR);
    /* a huge zoom stretches one column to the window's edge */
    glPixelZoom(1.0e6, 1.0);
    glRasterPos2i(200, 180);
    glCopyPixels(40, 8, 1, 20, GL_COLOR);
    /* overlapping: the source is read before it is written */
    glPixelZoom(1.0, 1.0);
    glRasterPos2i(20, 20);
    glCopyPixels(8, 8, 64, 30, GL_COLOR);
    /* the scene's depths, in the raster colour, where they pass the depth test */
    glEnable(GL_DEPTH_TEST);
    glColor3f(1.0, 0.9, 0.2);
    glRasterPos3f(160.0, 200.0, 0.9);
    glCopyPixels(60, 0, 90, 80, GL_DEPTH);
    glDisable(GL_DEPTH_TEST);
    glPixelZoom(1.0, 1.0);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(320, 300);
    glutCreateWindow("Copied and zoomed pixels");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
