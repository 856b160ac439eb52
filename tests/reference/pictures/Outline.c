// Outline.c: GLU's outline display modes on the Red Book hill, unlit: GLU_OUTLINE_POLYGON on the
// left (the tessellation as lines), GLU_OUTLINE_PATCH on the right (patch and trim outlines).
#include "gl.h"

GLfloat ctlpoints[4][4][3];

void Viewport(int x, int y, int w, int h)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)w / (GLdouble)h, 3.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0, 0.0, -5.0);
    glRotatef(330.0, 1.0, 0.0, 0.0);
    glScalef(0.5, 0.5, 0.5);
}

void Surface(GLUnurbsObj *nurb, int trimmed)
{
    GLfloat knots[8] = {0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0};
    GLfloat edgePt[5][2] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {0.0, 0.0}}; /* counter clockwise */
    GLfloat holePt[5][2] = {{0.3, 0.3}, {0.3, 0.7}, {0.7, 0.7}, {0.7, 0.3}, {0.3, 0.3}}; /* clockwise */
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &ctlpoints[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    if (trimmed) {
        gluBeginTrim(nurb);
        gluPwlCurve(nurb, 5, &edgePt[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nurb);
        gluBeginTrim(nurb);
        gluPwlCurve(nurb, 5, &holePt[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nurb);
    }
    gluEndSurface(nurb);
}

void Display(void)
{
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2;
    int h = glutGet(GLUT_WINDOW_HEIGHT);
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctlpoints[u][v][0] = 2.0 * ((GLfloat)u - 1.5);
            ctlpoints[u][v][1] = 2.0 * ((GLfloat)v - 1.5);
            ctlpoints[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0 : -3.0;
        }
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.0, 0.0, 0.6);
    GLUnurbsObj *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 40.0);

    Viewport(0, 0, w, h);
    gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
    Surface(nurb, 0);

    Viewport(w, 0, w, h);
    gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);
    Surface(nurb, 1);

    gluDeleteNurbsRenderer(nurb);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(500, 250);
    glutCreateWindow("GLU outlines");
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
