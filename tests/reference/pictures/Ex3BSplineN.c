// Seed 004, 9.7.2 exercise 3: the uniform cubic B-spline of n >= 4 control points, for 5, 8 and
// 13 points (examples/ex3_bspline_n.rs).
#include "gll.h"

void UniformCubicBSpline(float pts[], int n) // n >= 4 个控制点
{
    glColor3f(0.6, 0.6, 0.6), glLineWidth(1);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < n; i++) glVertex3fv(pts + 3 * i);
    glEnd();
    glColor3f(1, 0, 0), glPointSize(5);
    gllPoints(pts, n);
    glColor3f(0, 0, 1), glLineWidth(2);
    gllUniBCurve(n, pts, 4, 1);
}

void Zigzag(float pts[], int n) // x ∈ [0, 4] 上的锯齿形控制点
{
    for (int i = 0; i < n; i++) {
        pts[3 * i] = 4.0f * i / (n - 1);
        pts[3 * i + 1] = (i % 2 == 0 ? -1.0f : 1.0f) * (0.4f + 0.6f * ((i * 7 % 5) / 4.0f));
        pts[3 * i + 2] = 0;
    }
}

void Paint()
{
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    int w = glutGet(GLUT_WINDOW_WIDTH) / 3, h = glutGet(GLUT_WINDOW_HEIGHT);
    int counts[3] = {5, 8, 13};
    float pts[13 * 3];
    for (int k = 0; k < 3; k++) {
        glViewport(k * w, 0, w, h);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluOrtho2D(-0.3, 4.3, -1.6, 1.6);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        Zigzag(pts, counts[k]);
        UniformCubicBSpline(pts, counts[k]);
    }
    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(900, 300);
    glutCreateWindow("5、8、13个控制点的三次均匀B-样条曲线");
    glutDisplayFunc(Paint);
    glutMainLoop();
}
