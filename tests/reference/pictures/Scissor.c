// Scissor.c: scissored viewports. Four viewports, each cleared through a scissor box of its
// own to its own colour (one with the colour mask letting only red through), each drawing an
// evaluated Bezier curve and its control points; a smaller scissor box then clips a wide curve
// across the whole window; one viewport draws with depth writes off (glDepthMask), so a far
// square drawn after a near one covers it.
#include "gl.h"

static GLfloat curve[4][3] = {{-0.9f, -0.6f, 0}, {-0.4f, 0.9f, 0}, {0.4f, -0.9f, 0}, {0.9f, 0.6f, 0}};

static void init(void)
{
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(30, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glPointSize(5.0f);
}

static void square(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static void pane(int x, int y, const GLfloat clear[4])
{
    glViewport(x, y, 180, 180);
    glScissor(x + 10, y + 10, 160, 160);
    glClearColor(clear[0], clear[1], clear[2], clear[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);
    glEvalMesh1(GL_LINE, 0, 30);
    glColor3f(1.0f, 0.9f, 0.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 4; i++)
        glVertex3fv(curve[i]);
    glEnd();
}

static void display(void)
{
    static const GLfloat colors[4][4] = {
        {0.5f, 0.1f, 0.1f, 1.0f}, {0.1f, 0.4f, 0.1f, 1.0f}, {0.1f, 0.1f, 0.5f, 1.0f}, {0.6f, 0.6f, 0.6f, 1.0f}};
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    pane(0, 180, colors[0]);
    pane(180, 180, colors[1]);
    pane(0, 0, colors[2]);
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
    pane(180, 0, colors[3]);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    glColor3f(0.2f, 0.8f, 1.0f);
    glDepthMask(GL_FALSE);
    square(-0.5f, -0.5f, 0.2f, 0.2f, -0.5f);
    glColor3f(1.0f, 0.4f, 0.0f);
    square(-0.2f, -0.2f, 0.5f, 0.5f, 0.5f);
    glDepthMask(GL_TRUE);

    glViewport(0, 0, 360, 360);
    glScissor(100, 60, 160, 240);
    glLineWidth(3.0f);
    glColor3f(0.9f, 0.2f, 0.9f);
    glEvalMesh1(GL_LINE, 0, 30);
    glLineWidth(1.0f);
    glDisable(GL_SCISSOR_TEST);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(360, 360);
    glutCreateWindow("Scissored viewports");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
