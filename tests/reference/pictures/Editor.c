// Editor.c: a control-point editor of the classic kind. A rational Bezier curve (glMap1f with
// GL_MAP1_VERTEX_4, glEvalMesh1) over six control points drawn as lit gluSphere balls whose size
// shows their weight, the control polygon, labels naming the points and a status line with the
// selected point's coordinates and weight (glutBitmapString). The left button picks a ball through
// selection mode (glSelectBuffer, the name stack, gluPickMatrix) and drags it in the view plane
// (gluProject for its depth, gluUnProject for where it goes); the selected ball wears a yellow
// ring (gluDisk). The right button opens a GLUT menu: the control polygon on or off, the selected
// point heavier, lighter or in the next colour, the points reset, quit.
// The first frame shows the state after a click beside point 2 and the menu's "Heavier" and
// "Next colour" chosen for it (no mouse headless).
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gl.h"

#define NPTS 6
enum { POLYGON = 1, HEAVIER, LIGHTER, COLOUR, RESET, QUIT };

static const GLfloat start[NPTS][3] = {{-3.2, -2.0, 0.0}, {-2.4, 2.4, 0.0}, {-0.8, -2.6, 0.0},
                                       {0.8, 2.6, 0.0},   {2.4, -2.4, 0.0}, {3.2, 2.0, 0.0}};
static const GLfloat palette[4][4] = {
    {1.0, 0.55, 0.15, 1.0}, {0.3, 0.85, 0.35, 1.0}, {0.35, 0.55, 1.0, 1.0}, {0.9, 0.35, 0.85, 1.0}};
static GLfloat ctrl[NPTS][3];
static GLfloat weight[NPTS];
static int colour[NPTS];
static int selected = -1, dragging = 0, polygon = 1, started = 0;
static GLint viewport[4];
static GLUquadric *quad;

static void reset(void)
{
    memcpy(ctrl, start, sizeof ctrl);
    for (int i = 0; i < NPTS; i++) {
        weight[i] = 1.0f;
        colour[i] = 0;
    }
}

/* A ball's radius grows with its point's weight (1/4 .. 4). */
static GLdouble radius(int i)
{
    return 0.1 + 0.08 * weight[i];
}

/* What a menu entry does. */
static void choose(int value)
{
    switch (value) {
    case POLYGON:
        polygon = !polygon;
        break;
    case HEAVIER:
        if (selected >= 0 && weight[selected] < 4.0f)
            weight[selected] *= 2.0f;
        break;
    case LIGHTER:
        if (selected >= 0 && weight[selected] > 0.25f)
            weight[selected] /= 2.0f;
        break;
    case COLOUR:
        if (selected >= 0)
            colour[selected] = (colour[selected] + 1) % 4;
        break;
    case RESET:
        reset();
        break;
    case QUIT:
        exit(0);
    }
}

void Menu(int value)
{
    choose(value);
    glutPostRedisplay();
}

static void init(void)
{
    reset();
    glClearColor(0.12, 0.12, 0.16, 1.0);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){-1.0, 2.0, 3.0, 0.0});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (GLfloat[]){0.6, 0.6, 0.6, 1.0});
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0);
    glEnable(GL_MAP1_VERTEX_4);
    glMapGrid1f(80, 0.0, 1.0);
    quad = gluNewQuadric();
    glutCreateMenu(Menu);
    glutAddMenuEntry("Control polygon on/off", POLYGON);
    glutAddMenuEntry("Heavier (weight x 2)", HEAVIER);
    glutAddMenuEntry("Lighter (weight / 2)", LIGHTER);
    glutAddMenuEntry("Next colour", COLOUR);
    glutAddMenuEntry("Reset points", RESET);
    glutAddMenuEntry("Quit", QUIT);
    glutAttachMenu(GLUT_RIGHT_BUTTON);
}

/* The balls, lit in their colours, or named for selection. */
static void drawBalls(GLenum mode)
{
    for (int i = 0; i < NPTS; i++) {
        if (mode == GL_SELECT)
            glLoadName(i);
        else
            glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, palette[colour[i]]);
        glPushMatrix();
        glTranslatef(ctrl[i][0], ctrl[i][1], ctrl[i][2]);
        gluSphere(quad, radius(i), 16, 12);
        glPopMatrix();
    }
}

/* The ball under window pixel (x, y) (GLUT's y, from the top), or -1: the nearest of the hits in
   a 6 x 6 pixel pick region. */
static int pick(int x, int y)
{
    GLuint buffer[4 * NPTS];
    GLdouble proj[16];
    glSelectBuffer(4 * NPTS, buffer);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(~0u);
    glMatrixMode(GL_PROJECTION);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    glPushMatrix();
    glLoadIdentity();
    gluPickMatrix(x, viewport[3] - y, 6.0, 6.0, viewport);
    glMultMatrixd(proj);
    glMatrixMode(GL_MODELVIEW);
    drawBalls(GL_SELECT);
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
    glGetIntegerv(GL_VIEWPORT, viewport);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4.0, 4.0, -4.0, 4.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    GLfloat hom[NPTS][4];
    char text[80];
    if (!started) {
        /* Point 2, (-0.8, -2.6), is at window (160, 330) from the top: a click 3 pixels right,
           2 up, then two menu entries. */
        started = 1;
        selected = pick(163, 328);
        choose(HEAVIER);
        choose(COLOUR);
    }
    glClear(GL_COLOR_BUFFER_BIT);

    // The curve through the weighted points (x w, y w, z w, w).
    for (int i = 0; i < NPTS; i++) {
        for (int k = 0; k < 3; k++)
            hom[i][k] = ctrl[i][k] * weight[i];
        hom[i][3] = weight[i];
    }
    glMap1f(GL_MAP1_VERTEX_4, 0.0, 1.0, 4, NPTS, &hom[0][0]);
    glColor3f(1.0, 1.0, 1.0);
    glLineWidth(2.0);
    glEvalMesh1(GL_LINE, 0, 80);
    glLineWidth(1.0);
    if (polygon) {
        glColor3f(0.45, 0.55, 0.75);
        glBegin(GL_LINE_STRIP);
        for (int i = 0; i < NPTS; i++)
            glVertex3fv(ctrl[i]);
        glEnd();
    }

    glEnable(GL_LIGHTING);
    drawBalls(GL_RENDER);
    glDisable(GL_LIGHTING);
    if (selected >= 0) {
        glColor3f(1.0, 0.9, 0.1);
        glPushMatrix();
        glTranslatef(ctrl[selected][0], ctrl[selected][1], ctrl[selected][2]);
        gluDisk(quad, radius(selected) + 0.06, radius(selected) + 0.14, 24, 1);
        glPopMatrix();
    }

    // Labels beside the balls, the status line and a hint.
    glColor3f(0.9, 0.9, 0.9);
    for (int i = 0; i < NPTS; i++) {
        GLfloat d = (GLfloat)radius(i) + 0.08f;
        glRasterPos3f(ctrl[i][0] + d, ctrl[i][1] + d, ctrl[i][2]);
        sprintf(text, "P%d", i);
        glutBitmapString(GLUT_BITMAP_HELVETICA_12, (const unsigned char *)text);
    }
    glColor3f(1.0, 0.9, 0.1);
    glRasterPos2f(-3.85, 3.6);
    if (selected >= 0)
        sprintf(text, "P%d at (%.2f, %.2f), weight %g", selected, ctrl[selected][0], ctrl[selected][1],
                weight[selected]);
    else
        sprintf(text, "no point selected");
    glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char *)text);
    glColor3f(0.6, 0.6, 0.7);
    glRasterPos2f(-3.85, -3.85);
    glutBitmapString(GLUT_BITMAP_HELVETICA_10,
                     (const unsigned char *)"left button: pick and drag a ball   right button: menu");
    glFlush();
}

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

/* The selected point follows the pointer at its own depth. */
void Motion(int x, int y)
{
    GLdouble model[16], proj[16], wx, wy, wz, ox, oy, oz;
    if (!dragging)
        return;
    glGetDoublev(GL_MODELVIEW_MATRIX, model);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    GLfloat *p = ctrl[selected];
    gluProject(p[0], p[1], p[2], model, proj, viewport, &wx, &wy, &wz);
    if (gluUnProject(x, viewport[3] - y, wz, model, proj, viewport, &ox, &oy, &oz)) {
        p[0] = (GLfloat)ox;
        p[1] = (GLfloat)oy;
        p[2] = (GLfloat)oz;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Control-point editor");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMouseFunc(Mouse);
    glutMotionFunc(Motion);
    glutMainLoop();
    return 0;
}
