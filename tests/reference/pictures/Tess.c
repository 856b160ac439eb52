// Tess.c: the Red Book's tess.c (a rectangle with a triangular hole, compiled into a display
// list through glVertex3dv as the vertex callback; a self-intersecting star with colours
// combined at its intersections, winding rule positive), and the winding rules of tesswind.c
// on three nested squares (odd, nonzero, positive, abs >= 2) and on three overlapping
// contours (nonzero, then its boundary only as line loops).
#include "gl.h"
#include <stdio.h>
#include <stdlib.h>

static GLuint startList;

static void GLAPIENTRY beginCallback(GLenum which) { glBegin(which); }
static void GLAPIENTRY endCallback(void) { glEnd(); }
static void GLAPIENTRY errorCallback(GLenum errorCode)
{
    fprintf(stderr, "Tessellation Error: %s\n", (const char *)gluErrorString(errorCode));
    exit(1);
}
static void GLAPIENTRY vertexCallback(GLvoid *vertex)
{
    const GLdouble *pointer = (GLdouble *)vertex;
    glColor3dv(pointer + 3);
    glVertex3dv(pointer);
}
static void GLAPIENTRY combineCallback(GLdouble coords[3], GLdouble *vertex_data[4], GLfloat weight[4],
                                       GLdouble **dataOut)
{
    GLdouble *vertex = (GLdouble *)malloc(6 * sizeof(GLdouble));
    vertex[0] = coords[0];
    vertex[1] = coords[1];
    vertex[2] = coords[2];
    for (int i = 3; i < 6; i++)
        vertex[i] = weight[0] * vertex_data[0][i] + weight[1] * vertex_data[1][i] + weight[2] * vertex_data[2][i]
                    + weight[3] * vertex_data[3][i];
    *dataOut = vertex;
}

// Intersections of plain GLdouble[3] vertices: a copy of the coordinates.
static void GLAPIENTRY combineXYZ(GLdouble coords[3], void *vertex_data[4], GLfloat weight[4], GLdouble **dataOut)
{
    GLdouble *vertex = (GLdouble *)malloc(3 * sizeof(GLdouble));
    vertex[0] = coords[0];
    vertex[1] = coords[1];
    vertex[2] = coords[2];
    *dataOut = vertex;
}

static GLdouble rects[12][3] = {{50, 50, 0},   {300, 50, 0},  {300, 300, 0}, {50, 300, 0},
                                {100, 100, 0}, {250, 100, 0}, {250, 250, 0}, {100, 250, 0},
                                {150, 150, 0}, {200, 150, 0}, {200, 200, 0}, {150, 200, 0}};
static GLdouble quad1[4][3] = {{50, 150, 0}, {350, 150, 0}, {350, 200, 0}, {50, 200, 0}};
static GLdouble quad2[4][3] = {{100, 100, 0}, {300, 100, 0}, {300, 350, 0}, {100, 350, 0}};
static GLdouble tri2[3][3] = {{200, 50, 0}, {250, 300, 0}, {150, 300, 0}};

static void contour(GLUtesselator *tobj, GLdouble (*v)[3], int n)
{
    gluTessBeginContour(tobj);
    for (int i = 0; i < n; i++)
        gluTessVertex(tobj, v[i], v[i]);
    gluTessEndContour(tobj);
}

// One winding demo at (x, y), scaled into a 100 x 100 cell.
static void winding(GLUtesselator *tobj, GLenum rule, int overlap, GLfloat x, GLfloat y)
{
    glPushMatrix();
    glTranslatef(x, y, 0);
    glScalef(0.25, 0.25, 1);
    gluTessProperty(tobj, GLU_TESS_WINDING_RULE, rule);
    gluTessBeginPolygon(tobj, NULL);
    if (overlap) {
        contour(tobj, quad1, 4);
        contour(tobj, quad2, 4);
        contour(tobj, tri2, 3);
    } else {
        contour(tobj, rects, 4);
        contour(tobj, rects + 4, 4);
        contour(tobj, rects + 8, 4);
    }
    gluTessEndPolygon(tobj);
    glPopMatrix();
}

static void init(void)
{
    GLdouble rect[4][3] = {{50, 50, 0}, {200, 50, 0}, {200, 200, 0}, {50, 200, 0}};
    GLdouble tri[3][3] = {{75, 75, 0}, {125, 175, 0}, {175, 75, 0}};
    static GLdouble star[5][6] = {{250, 50, 0, 1, 0, 1},
                                  {325, 200, 0, 1, 1, 0},
                                  {400, 50, 0, 0, 1, 1},
                                  {250, 150, 0, 1, 0, 0},
                                  {400, 150, 0, 0, 1, 0}};
    glClearColor(0.0, 0.0, 0.0, 0.0);
    startList = glGenLists(3);
    GLUtesselator *tobj = gluNewTess();
    gluTessCallback(tobj, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
    gluTessCallback(tobj, GLU_TESS_BEGIN, (_GLUfuncptr)beginCallback);
    gluTessCallback(tobj, GLU_TESS_END, (_GLUfuncptr)endCallback);
    gluTessCallback(tobj, GLU_TESS_ERROR, (_GLUfuncptr)errorCallback);
    gluTessCallback(tobj, GLU_TESS_COMBINE, (_GLUfuncptr)combineXYZ);

    // A rectangle with a triangular hole inside.
    glNewList(startList, GL_COMPILE);
    glShadeModel(GL_FLAT);
    gluTessBeginPolygon(tobj, NULL);
    gluTessBeginContour(tobj);
    gluTessVertex(tobj, rect[0], rect[0]);
    gluTessVertex(tobj, rect[1], rect[1]);
    gluTessVertex(tobj, rect[2], rect[2]);
    gluTessVertex(tobj, rect[3], rect[3]);
    gluTessEndContour(tobj);
    gluTessBeginContour(tobj);
    gluTessVertex(tobj, tri[0], tri[0]);
    gluTessVertex(tobj, tri[1], tri[1]);
    gluTessVertex(tobj, tri[2], tri[2]);
    gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
    glEndList();

    // The winding rules, in a list of their own.
    glNewList(startList + 2, GL_COMPILE);
    glColor3f(0.9, 0.6, 0.2);
    winding(tobj, GLU_TESS_WINDING_ODD, 0, 0, 250);
    winding(tobj, GLU_TESS_WINDING_NONZERO, 0, 100, 250);
    winding(tobj, GLU_TESS_WINDING_POSITIVE, 0, 200, 250);
    winding(tobj, GLU_TESS_WINDING_ABS_GEQ_TWO, 0, 300, 250);
    glColor3f(0.3, 0.7, 1.0);
    winding(tobj, GLU_TESS_WINDING_NONZERO, 1, 0, 375);
    winding(tobj, GLU_TESS_WINDING_ODD, 1, 100, 375);
    gluTessProperty(tobj, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
    winding(tobj, GLU_TESS_WINDING_NONZERO, 1, 200, 375);
    winding(tobj, GLU_TESS_WINDING_ODD, 1, 300, 375);
    glEndList();

    // A self-intersecting star, coloured at its vertices and at the combined intersections.
    gluTessProperty(tobj, GLU_TESS_BOUNDARY_ONLY, GL_FALSE);
    gluTessCallback(tobj, GLU_TESS_VERTEX, (_GLUfuncptr)vertexCallback);
    gluTessCallback(tobj, GLU_TESS_COMBINE, (_GLUfuncptr)combineCallback);
    gluTessProperty(tobj, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
    glNewList(startList + 1, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    gluTessBeginPolygon(tobj, NULL);
    gluTessBeginContour(tobj);
    for (int i = 0; i < 5; i++)
        gluTessVertex(tobj, star[i], star[i]);
    gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
    glEndList();
    gluDeleteTess(tobj);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0, 1.0, 1.0);
    glCallList(startList);
    glCallList(startList + 1);
    glShadeModel(GL_FLAT);
    glCallList(startList + 2);
    glFlush();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (GLdouble)w, 0.0, (GLdouble)h);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(500, 500);
    glutCreateWindow(argv[0]);
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
