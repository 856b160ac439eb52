// RationalMap.c: rational evaluator maps. Left: a GL_MAP1_VERTEX_4 quadratic arc (weights 1,
// sqrt(2)/2, 1: a quarter circle) drawn four times rotated, a full circle. Right: a
// GL_MAP2_VERTEX_4 rational patch with GL_AUTO_NORMAL (the rational normal correction), lit.
#include "gl.h"

void Display(void)
{
    const float r = 0.70710678f;
    GLfloat arc[3][4] = {{1, 0, 0, 1}, {r, r, 0, r}, {0, 1, 0, 1}};
    GLfloat patch[3][3][4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            GLfloat w = (i == 1 && j == 1) ? 3.0f : ((i == 1 || j == 1) ? 0.6f : 1.0f);
            patch[i][j][0] = (i - 1.0f) * w;
            patch[i][j][1] = (j - 1.0f) * w;
            patch[i][j][2] = ((i == 1) != (j == 1) ? 0.5f : 0.0f) * w;
            patch[i][j][3] = w;
        }
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2, h = glutGet(GLUT_WINDOW_HEIGHT);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-1.2, 1.2, -1.2, 1.2);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glMap1f(GL_MAP1_VERTEX_4, 0, 1, 4, 3, &arc[0][0]);
    glEnable(GL_MAP1_VERTEX_4);
    glMapGrid1f(16, 0, 1);
    glColor3f(0.8, 0.1, 0.1);
    glLineWidth(3);
    for (int k = 0; k < 4; k++) {
        glEvalMesh1(GL_LINE, 0, 16);
        glRotatef(90, 0, 0, 1);
    }

    glViewport(w, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(35, (float)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, -3, 3, 0, 0, 0, 0, 0, 1);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_DEPTH_TEST);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (float[]){0.3, 0.8, 0.4, 1});
    glMap2f(GL_MAP2_VERTEX_4, 0, 1, 12, 3, 0, 1, 4, 3, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_4);
    glMapGrid2f(16, 0, 1, 16, 0, 1);
    glEvalMesh2(GL_FILL, 0, 16, 0, 16);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 200);
    glutCreateWindow("Rational maps");
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
