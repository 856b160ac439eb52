// LinesPoints.c: GL's aliased wide lines and square points of several sizes, from the
// evaluators (glEvalMesh1 GL_LINE and GL_POINT) and from immediate mode.
#include "gl.h"

void Display(void)
{
    GLfloat curve[4][3] = {{-0.9, -0.2, 0}, {-0.4, 0.25, 0}, {0.2, -0.45, 0}, {0.9, 0.2, 0}};
    GLfloat widths[4] = {1, 2, 3, 5};
    GLfloat sizes[5] = {1, 2, 4, 7, 10};
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(24, 0, 1);
    for (int i = 0; i < 4; i++) {
        glPushMatrix();
        glTranslatef(0, 0.62 - 0.3 * i, 0);
        glScalef(1, 0.5, 1);
        glColor3f(0.1 * i, 0.2, 0.9 - 0.2 * i);
        glLineWidth(widths[i]);
        glEvalMesh1(GL_LINE, 0, 24);
        glPopMatrix();
    }
    for (int i = 0; i < 5; i++) {
        glPointSize(sizes[i]);
        glColor3f(0.9, 0.3 * (i % 2), 0.1);
        glBegin(GL_POINTS);
        glVertex2f(-0.8 + 0.35 * i, -0.72);
        glEnd();
        glPushMatrix();
        glTranslatef(0, -0.5, 0);
        glScalef(1, 0.2, 1);
        glEvalMesh1(GL_POINT, 4 * i, 4 * i + 2);
        glPopMatrix();
    }
    glLineWidth(4);
    glColor3f(0, 0.6, 0);
    glBegin(GL_LINE_LOOP);
    glVertex2f(-0.95, -0.95);
    glVertex2f(0.95, -0.9);
    glVertex2f(0.9, 0.95);
    glVertex2f(-0.9, 0.9);
    glEnd();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Lines and points");
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
