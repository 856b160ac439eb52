// Trimmed.c: a bicubic NURBS hill (the Red Book's surface) with two holes: a loop made of a
// NURBS curve and a piecewise-linear curve, and a piecewise-linear triangle.
#include "gl.h"

GLfloat ctlpoints[4][4][3];
GLUnurbsObj *theNurb;

void InitSurface(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctlpoints[u][v][0] = 2.0 * ((GLfloat)u - 1.5);
            ctlpoints[u][v][1] = 2.0 * ((GLfloat)v - 1.5);
            ctlpoints[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0 : -3.0;
        }
}

void Init(void)
{
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]){0.7, 0.7, 0.7, 1.0});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (float[]){1.0, 1.0, 1.0, 1.0});
    glMaterialf(GL_FRONT, GL_SHININESS, 100.0);
    glClearColor(0.2, 0.2, 0.3, 1.0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    InitSurface();
    theNurb = gluNewNurbsRenderer();
    gluNurbsProperty(theNurb, GLU_SAMPLING_TOLERANCE, 25.0);
    gluNurbsProperty(theNurb, GLU_DISPLAY_MODE, GLU_FILL);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (GLdouble)w / (GLdouble)h, 3.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0, 0.0, -5.0);
}

void Display(void)
{
    GLfloat knots[8] = {0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0};
    GLfloat edgePt[5][2] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {0.0, 0.0}}; /* counter clockwise */
    GLfloat curvePt[4][2] = {{0.25, 0.5}, {0.25, 0.75}, {0.75, 0.75}, {0.75, 0.5}}; /* clockwise */
    GLfloat curveKnots[8] = {0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0};
    GLfloat pwlPt[3][2] = {{0.75, 0.5}, {0.5, 0.25}, {0.25, 0.5}}; /* clockwise */
    GLfloat trianglePt[4][2] = {{0.1, 0.1}, {0.2, 0.3}, {0.3, 0.1}, {0.1, 0.1}}; /* clockwise */

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(330.0, 1.0, 0.0, 0.0);
    glScalef(0.5, 0.5, 0.5);

    gluBeginSurface(theNurb);
    gluNurbsSurface(theNurb, 8, knots, 8, knots, 4 * 3, 3, &ctlpoints[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluBeginTrim(theNurb);
    gluPwlCurve(theNurb, 5, &edgePt[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(theNurb);
    gluBeginTrim(theNurb);
    gluNurbsCurve(theNurb, 8, curveKnots, 2, &curvePt[0][0], 4, GLU_MAP1_TRIM_2);
    gluPwlCurve(theNurb, 3, &pwlPt[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(theNurb);
    gluBeginTrim(theNurb);
    gluPwlCurve(theNurb, 4, &trianglePt[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(theNurb);
    gluEndSurface(theNurb);

    glPopMatrix();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Trimmed NURBS");
    Init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
