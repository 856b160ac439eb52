// Picking.c: the control points of a Bezier curve picked with the mouse through selection mode
// (glSelectBuffer, the name stack, gluPickMatrix), the picked one drawn highlighted; dragging
// moves it and the curve follows (gluUnProject). The control polygon and the points are drawn
// from a vertex array set once in init(): GL reads it when it draws, so the moved point shows.
// The first frame shows the state after a click beside control point 2 (no mouse headless).
#include "gl.h"

#define NPTS 5
static GLfloat ctrl[NPTS][3] = {{-3.0, -2.0, 0.0}, {-2.0, 2.5, 0.2}, {0.0, -1.0, 0.4}, {2.0, 3.0, 0.6}, {3.2, -2.5, 0.8}};
static GLint viewport[4];
static int selected = -1;
static int clicked = 0;

/* The projection Reshape sets with gluOrtho2D(-4, 4, -4, 4), and the identity modelview. */
static const GLdouble proj[16] = {0.25, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1};
static const GLdouble model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static void init(void)
{
    glClearColor(0.1, 0.1, 0.15, 1.0);
    glVertexPointer(3, GL_FLOAT, 0, ctrl);
    glEnableClientState(GL_VERTEX_ARRAY);
}

static void drawPoints(GLenum mode)
{
    for (int i = 0; i < NPTS; i++) {
        if (mode == GL_SELECT)
            glLoadName(i);
        glBegin(GL_POINTS);
        glArrayElement(i);
        glEnd();
    }
}

/* The control point under window pixel (x, y) (GLUT's y, from the top), or -1: the nearest
   of the hits in an 8 x 8 pixel pick region. */
static int pick(int x, int y)
{
    GLuint buffer[64];
    glSelectBuffer(64, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(~0u);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    gluPickMatrix(x, viewport[3] - y, 8.0, 8.0, viewport);
    gluOrtho2D(-4.0, 4.0, -4.0, 4.0);
    glMatrixMode(GL_MODELVIEW);
    glPointSize(10.0);
    drawPoints(GL_SELECT);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    GLint hits = glRenderMode(GL_RENDER);
    int best = -1;
    GLuint bestDepth = 0xffffffffu;
    GLuint *p = buffer;
    for (int h = 0; h < hits; h++) {
        GLuint names = p[0], zmin = p[1];
        if (names > 0 && zmin <= bestDepth) {
            bestDepth = zmin;
            best = (int)p[3];
        }
        p += 3 + names;
    }
    return best;
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    viewport[0] = 0;
    viewport[1] = 0;
    viewport[2] = w;
    viewport[3] = h;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-4.0, 4.0, -4.0, 4.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    if (!clicked) {
        /* Control point 2 is at window (200, 150): a click 3 pixels right, 2 up. */
        clicked = 1;
        selected = pick(203, viewport[3] - 152);
    }
    glClear(GL_COLOR_BUFFER_BIT);
    glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, NPTS, &ctrl[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(60, 0.0, 1.0);
    glColor3f(1.0, 1.0, 1.0);
    glLineWidth(2.0);
    glEvalMesh1(GL_LINE, 0, 60);
    glLineWidth(1.0);
    glColor3f(0.4, 0.6, 1.0);
    glDrawArrays(GL_LINE_STRIP, 0, NPTS);
    glPointSize(8.0);
    glColor3f(1.0, 1.0, 0.0);
    drawPoints(GL_RENDER);
    if (selected >= 0) {
        glPointSize(14.0);
        glColor3f(1.0, 0.2, 0.2);
        glDrawArrays(GL_POINTS, selected, 1);
    }
    glFlush();
}

static int dragging = 0;

void Mouse(int button, int state, int x, int y)
{
    if (button != GLUT_LEFT_BUTTON)
        return;
    if (state == GLUT_DOWN) {
        selected = pick(x, y);
        dragging = selected >= 0;
    } else {
        dragging = 0;
    }
    glutPostRedisplay();
}

void Motion(int x, int y)
{
    GLdouble ox, oy, oz;
    if (!dragging)
        return;
    if (gluUnProject(x, viewport[3] - y, 0.5, model, proj, viewport, &ox, &oy, &oz)) {
        ctrl[selected][0] = (GLfloat)ox;
        ctrl[selected][1] = (GLfloat)oy;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Picking control points");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMouseFunc(Mouse);
    glutMotionFunc(Motion);
    glutMainLoop();
    return 0;
}
