// Stencil.c: the stencil buffer four ways, one viewport each. Top left: a diamond written into
// the stencil buffer with colour writes off masks evaluated Bezier curves (GL_EQUAL) and a grid
// drawn outside it (GL_NOTEQUAL). Top right: three discs counted with GL_INCR, coloured by how
// many overlap. Bottom left: a Bezier patch outlined (filled writing 1, then its mesh drawn as
// wide lines where the stencil is not 1). Bottom right: GL_INVERT through a stencil write mask of
// one bit, an XOR of two squares.
#include "gl.h"
#include <math.h>

static GLfloat curve[4][3] = {{-0.9f, -0.5f, 0}, {-0.3f, 0.9f, 0}, {0.3f, -0.9f, 0}, {0.9f, 0.5f, 0}};
static GLfloat patch[4][4][3];

static void init(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            patch[u][v][0] = -0.6f + 0.4f * u + ((v == 1 || v == 2) ? 0.25f : 0.0f);
            patch[u][v][1] = -0.6f + 0.4f * v + ((u == 1 || u == 2) ? -0.25f : 0.0f);
            patch[u][v][2] = 0.0f;
        }
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClearStencil(0);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid1f(40, 0.0f, 1.0f);
    glMapGrid2f(8, 0.0f, 1.0f, 8, 0.0f, 1.0f);
}

static void disc(float x, float y, float r)
{
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(x, y);
    for (int i = 0; i <= 32; i++) {
        float a = 6.2831853f * (float)i / 32.0f;
        glVertex2f(x + r * cosf(a), y + r * sinf(a));
    }
    glEnd();
}

static void square(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

static void masked_curves(void)
{
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_POLYGON);
    glVertex2f(0.0f, -0.85f);
    glVertex2f(0.85f, 0.0f);
    glVertex2f(0.0f, 0.85f);
    glVertex2f(-0.85f, 0.0f);
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glColor3f(1.0f, 0.8f, 0.2f);
    for (int k = -4; k <= 4; k++) {
        glPushMatrix();
        glTranslatef(0.0f, 0.15f * (float)k, 0.0f);
        glEvalMesh1(GL_LINE, 0, 40);
        glPopMatrix();
    }
    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    glColor3f(0.3f, 0.5f, 1.0f);
    glBegin(GL_LINES);
    for (int k = -9; k <= 9; k++) {
        glVertex2f(0.1f * (float)k + 0.03f, -1.0f);
        glVertex2f(0.1f * (float)k + 0.03f, 1.0f);
    }
    glEnd();
}

static void counted_discs(void)
{
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    disc(-0.25f, 0.2f, 0.5f);
    disc(0.25f, 0.2f, 0.5f);
    disc(0.0f, -0.25f, 0.5f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    GLfloat colors[3][3] = {{0.2f, 0.4f, 0.9f}, {0.2f, 0.8f, 0.3f}, {1.0f, 0.3f, 0.2f}};
    for (int n = 1; n <= 3; n++) {
        glStencilFunc(GL_EQUAL, n, 0xFF);
        glColor3fv(colors[n - 1]);
        square(-1.0f, -1.0f, 1.0f, 1.0f);
    }
}

static void outlined_patch(void)
{
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor3f(0.2f, 0.6f, 0.3f);
    glEvalMesh2(GL_FILL, 0, 8, 0, 8);
    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glLineWidth(3.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glEvalMesh2(GL_LINE, 0, 8, 0, 8);
    glLineWidth(1.0f);
}

static void inverted_squares(void)
{
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilMask(0x01);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_INVERT, GL_INVERT, GL_INVERT);
    square(-0.7f, -0.7f, 0.3f, 0.3f);
    square(-0.3f, -0.3f, 0.7f, 0.7f);
    glStencilMask(0xFF);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_EQUAL, 1, 0x01);
    glColor3f(0.9f, 0.5f, 0.9f);
    square(-1.0f, -1.0f, 1.0f, 1.0f);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glViewport(0, 200, 200, 200);
    masked_curves();
    glViewport(200, 200, 200, 200);
    counted_discs();
    glViewport(0, 0, 200, 200);
    outlined_patch();
    glViewport(200, 0, 200, 200);
    inverted_squares();
    glDisable(GL_STENCIL_TEST);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_STENCIL);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Stencil");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
