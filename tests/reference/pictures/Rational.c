// Rational.c: a rational NURBS surface, a circle (9 homogeneous control points, weights 1 and
// sqrt(2)/2) swept along z into a cylinder, lit, seen from above at an angle.
#include "gl.h"

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLdouble)w / (GLdouble)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, -5.0, 4.0, 0.0, 0.0, 0.5, 0.0, 0.0, 1.0);
}

void Display(void)
{
    const float r = 0.70710678f;
    GLfloat circle[9][3] = {{1, 0, 1}, {1, 1, r}, {0, 1, 1}, {-1, 1, r}, {-1, 0, 1},
                            {-1, -1, r}, {0, -1, 1}, {1, -1, r}, {1, 0, 1}};
    GLfloat ctl[9][2][4];
    for (int i = 0; i < 9; i++)
        for (int j = 0; j < 2; j++) {
            GLfloat w = circle[i][2];
            ctl[i][j][0] = circle[i][0] * w;
            ctl[i][j][1] = circle[i][1] * w;
            ctl[i][j][2] = (j ? 1.5f : -0.5f) * w;
            ctl[i][j][3] = w;
        }
    GLfloat sknots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    GLfloat tknots[4] = {0, 0, 1, 1};

    glClearColor(0.1, 0.1, 0.1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glLightModelfv(GL_LIGHT_MODEL_TWO_SIDE, (float[]){1});
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]){0.9, 0.6, 0.2, 1});
    glMaterialfv(GL_BACK, GL_DIFFUSE, (float[]){0.2, 0.5, 0.9, 1});

    GLUnurbsObj *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_TOLERANCE, 10.0);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 12, sknots, 4, tknots, 2 * 4, 4, &ctl[0][0][0], 3, 2, GL_MAP2_VERTEX_4);
    gluEndSurface(nurb);
    gluDeleteNurbsRenderer(nurb);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(300, 300);
    glutCreateWindow("Rational NURBS");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
