// EdgeFlags.c: polygons outlined with glPolygonMode(GL_LINE) and GL_POINT, where glEdgeFlag and
// an edge-flag array hide the inner edges of a shape built from triangles, a quad and a polygon
// (GL 1.1 §2.6.2). Mesa applies the flags to strips too: a strip drawn with the flag false
// shows nothing in line mode.
#include "gl.h"

static GLfloat star[8][2] = {{0, 1}, {0.25, 0.25}, {1, 0}, {0.25, -0.25}, {0, -1}, {-0.25, -0.25}, {-1, 0}, {-0.25, 0.25}};
static GLboolean starFlags[8] = {GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE};

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-3.0, 3.0, -3.0, 3.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A hexagon as four triangles whose inner edges are hidden. */
static void hexagon(void)
{
    static const GLfloat v[6][2] = {{-0.4, -0.7}, {0.4, -0.7}, {0.8, 0.0}, {0.4, 0.7}, {-0.4, 0.7}, {-0.8, 0.0}};
    /* fan-like triangles (0 1 2) (0 2 3) (0 3 4) (0 4 5): the edges from 0 inward are hidden */
    glBegin(GL_TRIANGLES);
    for (int k = 1; k <= 4; k++) {
        glEdgeFlag(k == 1 ? GL_TRUE : GL_FALSE); glVertex2fv(v[0]);
        glEdgeFlag(GL_TRUE);                     glVertex2fv(v[k]);
        glEdgeFlag(k == 4 ? GL_TRUE : GL_FALSE); glVertex2fv(v[k + 1]);
    }
    glEnd();
    glEdgeFlag(GL_TRUE);
}

void Display(void)
{
    glClearColor(0.1, 0.1, 0.1, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(2.0);

    glColor3f(1.0, 0.9, 0.3);
    glTranslatef(-1.6, 1.5, 0.0);
    hexagon();

    glColor3f(0.3, 1.0, 0.5);
    glLoadIdentity();
    glTranslatef(1.5, 1.5, 0.0);
    glBegin(GL_QUADS);
    glEdgeFlag(GL_TRUE);  glVertex2f(-0.8, -0.8);
    glEdgeFlag(GL_FALSE); glVertex2f(0.8, -0.8);
    glEdgeFlag(GL_TRUE);  glVertex2f(0.8, 0.8);
    glEdgeFlag(GL_FALSE); glVertex2f(-0.8, 0.8);
    glEnd();
    glEdgeFlag(GL_TRUE);

    glColor3f(0.4, 0.7, 1.0);
    glLoadIdentity();
    glTranslatef(-1.5, -1.5, 0.0);
    glVertexPointer(2, GL_FLOAT, 0, star);
    glEdgeFlagPointer(0, starFlags);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glDrawArrays(GL_POLYGON, 0, 8);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);

    glColor3f(1.0, 0.4, 0.4);
    glLoadIdentity();
    glTranslatef(1.5, -1.5, 0.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(6.0);
    glEdgeFlag(GL_FALSE);
    glDrawArrays(GL_POLYGON, 0, 8);
    glEdgeFlag(GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(1.0);
    glColor3f(0.8, 0.8, 0.8);
    glScalef(0.5, 0.5, 1.0);
    glEdgeFlag(GL_FALSE);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-1.0, -0.5);
    glVertex2f(-1.0, 0.5);
    glVertex2f(0.0, -0.5);
    glVertex2f(0.0, 0.5);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Edge flags");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
