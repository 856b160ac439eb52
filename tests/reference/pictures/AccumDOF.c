// AccumDOF.c: depth of field with the accumulation buffer, as the Red Book's dof.c does it:
// eight frames from eye positions jittered on a small lens (accFrustum), all focused on the
// plane z = -5, accumulated with 1/8. Three Bezier patches at depths 3, 5 and 8, each with
// its mesh drawn over it: the middle one sharp, the others blurred.
#include "gl.h"
#include <math.h>

static const GLfloat j8[8][2] = {
    {-0.334818f, 0.435331f}, {0.286438f, -0.393495f}, {0.459462f, 0.141540f}, {-0.414498f, -0.192829f},
    {-0.183790f, 0.082102f}, {-0.079263f, -0.317383f}, {0.102254f, 0.299133f}, {0.164216f, -0.054399f},
};
static GLfloat patch[4][4][3];

/* The Red Book's accFrustum: a frustum moved by (pixdx, pixdy) pixels and the eye by
 * (eyedx, eyedy), keeping the plane at distance focus where it was. */
static void acc_frustum(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top, GLdouble near,
                        GLdouble far, GLdouble eyedx, GLdouble eyedy, GLdouble focus)
{
    GLdouble dx = -(eyedx * near / focus), dy = -(eyedy * near / focus);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(left + dx, right + dx, bottom + dy, top + dy, near, far);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef((GLfloat)-eyedx, (GLfloat)-eyedy, 0.0f);
}

static void init(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            patch[u][v][0] = 2.0f * ((float)u / 3.0f) - 1.0f;
            patch[u][v][1] = 2.0f * ((float)v / 3.0f) - 1.0f;
            patch[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 0.6f : -0.3f;
        }
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 4, 0.0f, 1.0f, 12, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(12, 0.0f, 1.0f, 12, 0.0f, 1.0f);
}

static void patch_at(float x, float z, const GLfloat color[4])
{
    glPushMatrix();
    glTranslatef(x, 0.0f, z);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glScalef(0.7f, 0.7f, 0.7f);
    glColor4fv(color);
    glEvalMesh2(GL_FILL, 0, 12, 0, 12);
    glColor3f(1.0f, 1.0f, 1.0f);
    glEvalMesh2(GL_LINE, 0, 12, 0, 12);
    glPopMatrix();
}

static void display(void)
{
    static const GLfloat red[4] = {0.9f, 0.2f, 0.2f, 1.0f}, green[4] = {0.2f, 0.9f, 0.3f, 1.0f},
                         blue[4] = {0.3f, 0.4f, 1.0f, 1.0f};
    glClear(GL_ACCUM_BUFFER_BIT);
    for (int j = 0; j < 8; j++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        acc_frustum(-0.8, 0.8, -0.6, 0.6, 1.0, 20.0, 0.12 * j8[j][0], 0.12 * j8[j][1], 5.0);
        patch_at(-1.6f, -3.0f, red);
        patch_at(0.0f, -5.0f, green);
        patch_at(2.6f, -8.0f, blue);
        glAccum(GL_ACCUM, 0.125f);
    }
    glAccum(GL_RETURN, 1.0f);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH | GLUT_ACCUM);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Depth of field");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
