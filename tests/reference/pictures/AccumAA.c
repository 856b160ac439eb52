// AccumAA.c: antialiasing with the accumulation buffer, as the Red Book's accanti.c does it:
// the scene drawn eight times, each shifted by a sub-pixel jitter (the Red Book's jitter.h
// table for 8), accumulated with 1/8 and returned. The scene: a filled triangle and a rotated
// square, an evaluated Bezier curve and its control polygon, with GL_POLYGON_SMOOTH enabled
// (which llvmpipe draws aliased).
#include "gl.h"

static const GLfloat j8[8][2] = {
    {-0.334818f, 0.435331f}, {0.286438f, -0.393495f}, {0.459462f, 0.141540f}, {-0.414498f, -0.192829f},
    {-0.183790f, 0.082102f}, {-0.079263f, -0.317383f}, {0.102254f, 0.299133f}, {0.164216f, -0.054399f},
};
static GLfloat curve[4][3] = {{-0.9f, -0.9f, 0}, {-0.6f, 0.9f, 0}, {0.6f, -0.9f, 0}, {0.9f, 0.7f, 0}};
static int width = 300, height = 300;

static void init(void)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(30, 0.0f, 1.0f);
    glEnable(GL_POLYGON_SMOOTH);
}

static void scene(void)
{
    glColor3f(0.9f, 0.3f, 0.2f);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.8f, -0.2f);
    glVertex2f(0.1f, -0.7f);
    glVertex2f(-0.3f, 0.8f);
    glEnd();
    glPushMatrix();
    glTranslatef(0.45f, 0.35f, 0.0f);
    glRotatef(25.0f, 0.0f, 0.0f, 1.0f);
    glColor3f(0.2f, 0.5f, 1.0f);
    glBegin(GL_QUADS);
    glVertex2f(-0.3f, -0.3f);
    glVertex2f(0.3f, -0.3f);
    glVertex2f(0.3f, 0.3f);
    glVertex2f(-0.3f, 0.3f);
    glEnd();
    glPopMatrix();
    glColor3f(1.0f, 1.0f, 0.3f);
    glEvalMesh1(GL_LINE, 0, 30);
    glColor3f(0.6f, 0.6f, 0.6f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 4; i++)
        glVertex3fv(curve[i]);
    glEnd();
}

static void reshape(int w, int h)
{
    width = w;
    height = h;
    glViewport(0, 0, w, h);
}

static void display(void)
{
    glClear(GL_ACCUM_BUFFER_BIT);
    for (int j = 0; j < 8; j++) {
        glClear(GL_COLOR_BUFFER_BIT);
        glPushMatrix();
        glTranslatef(j8[j][0] * 2.0f / (float)width, j8[j][1] * 2.0f / (float)height, 0.0f);
        scene();
        glPopMatrix();
        glAccum(GL_ACCUM, 1.0f / 8.0f);
    }
    glAccum(GL_RETURN, 1.0f);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_ACCUM);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Accumulation antialiasing");
    init();
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
