// ColorMap.c: a bicubic patch whose colour comes from a GL_MAP2_COLOR_4 map (unlit, smooth
// shading), drawn filled on the left; on the right the same maps drawn with partial
// glEvalMesh2 ranges: GL_FILL rows 2..6, GL_LINE columns 4..8, GL_POINT 0..3 x 0..3.
#include "gl.h"

void Viewport(int x, int y, int w, int h)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.0, 2.0, -2.0, 2.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(-40.0, 1.0, 0.0, 0.0);
    glRotatef(20.0, 0.0, 0.0, 1.0);
}

void Display(void)
{
    GLfloat pts[4][4][3];
    GLfloat colors[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 1}}};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            pts[i][j][0] = -1.5 + i;
            pts[i][j][1] = -1.5 + j;
            pts[i][j][2] = ((i + j) % 3 == 0) ? 0.8 : -0.4;
        }
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2, h = glutGet(GLUT_WINDOW_HEIGHT);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &pts[0][0][0]);
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 4, 2, &colors[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(10, 0, 1, 10, 0, 1);

    Viewport(0, 0, w, h);
    glEvalMesh2(GL_FILL, 0, 10, 0, 10);

    Viewport(w, 0, w, h);
    glEvalMesh2(GL_FILL, 0, 10, 2, 6);
    glLineWidth(2);
    glEvalMesh2(GL_LINE, 4, 8, 0, 10);
    glPointSize(4);
    glEvalMesh2(GL_POINT, 0, 3, 0, 3);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 200);
    glutCreateWindow("Colour map and partial meshes");
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
