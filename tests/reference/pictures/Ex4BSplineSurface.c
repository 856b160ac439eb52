// Seed 004, 9.7.2 exercise 4: the uniform bicubic B-spline surface of at least 4 x 4 control
// points, for 5 x 4, 8 x 7 and 13 x 10 points (examples/ex4_bspline_surface.rs).
#include "gll.h"
#include <math.h>

void UniformBicubicSurface(int ns, int nt, float pts[])
{
    glEnable(GL_LIGHTING);
    gllUniBSurface(ns, nt, pts, 4, 4);
    glDisable(GL_LIGHTING);
    glColor3f(1, 1, 0);
    gllPoints(pts, ns * nt);
}

void WavyNet(float pts[], int ns, int nt) // [-3, 3]² 上的波浪形控制网格
{
    for (int i = 0; i < ns; i++)
        for (int j = 0; j < nt; j++) {
            float x = -3.0f + 6.0f * i / (ns - 1), y = -3.0f + 6.0f * j / (nt - 1);
            float *p = pts + 3 * (i * nt + j);
            p[0] = x, p[1] = y, p[2] = 1.5f * sinf(0.9f * x) * cosf(0.7f * y);
        }
}

void Init()
{
    glClearColor(0, 0, 0, 1);
    glEnable(GL_DEPTH_TEST);
    glPointSize(3);
    float diffuse[] = {0.9, 0.6, 0.3, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_LIGHT0);
}

void Paint()
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    int w = glutGet(GLUT_WINDOW_WIDTH) / 3, h = glutGet(GLUT_WINDOW_HEIGHT);
    int sizes[3][2] = {{5, 4}, {8, 7}, {13, 10}};
    float pts[13 * 10 * 3];
    for (int k = 0; k < 3; k++) {
        glViewport(k * w, 0, w, h);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluPerspective(30, (double)w / h, 1, 100);
        glTranslatef(0, 0, -16);
        glRotatef(-55, 1, 0, 0);
        glRotatef(20, 0, 0, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        WavyNet(pts, sizes[k][0], sizes[k][1]);
        UniformBicubicSurface(sizes[k][0], sizes[k][1], pts);
    }
    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(900, 300);
    glutCreateWindow("5×4、8×7、13×10个控制点的三次均匀B-样条曲面");
    Init();
    glutDisplayFunc(Paint);
    glutMainLoop();
}
