// RubberBand.c: an XOR rubber band with glLogicOp, as drawing programs make it: a Bezier curve
// and its control polygon, then, in the front buffer with GL_XOR, a rubber-band rectangle drawn
// at an old position, drawn again there (which erases it exactly), and drawn at the new one; a
// filled XOR rectangle inverts what lies under it.
#include "gl.h"

static GLfloat curve[4][3] = {{-0.8f, -0.7f, 0}, {-0.5f, 0.9f, 0}, {0.4f, -0.9f, 0}, {0.8f, 0.6f, 0}};

static void init(void)
{
    glClearColor(0.15f, 0.15f, 0.3f, 1.0f);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(40, 0.0f, 1.0f);
}

static void band(float x0, float y0, float x1, float y1)
{
    glBegin(GL_LINE_LOOP);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0.6f, 0.6f, 0.6f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 4; i++)
        glVertex3fv(curve[i]);
    glEnd();
    glColor3f(1.0f, 0.8f, 0.1f);
    glLineWidth(2.0f);
    glEvalMesh1(GL_LINE, 0, 40);
    glLineWidth(1.0f);

    glDrawBuffer(GL_FRONT);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColor3f(1.0f, 1.0f, 1.0f);
    band(-0.6f, -0.5f, 0.1f, 0.3f);
    band(-0.6f, -0.5f, 0.1f, 0.3f);
    band(-0.4f, -0.6f, 0.5f, 0.5f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glRectf(0.2f, 0.1f, 0.7f, 0.8f);
    glDisable(GL_COLOR_LOGIC_OP);
    glDrawBuffer(GL_BACK);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB);
    glutInitWindowSize(300, 300);
    glutCreateWindow("XOR rubber band");
    init();
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
