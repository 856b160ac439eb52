// Seed 004, 9.7.2 exercise 5: the natural cubic spline through the bird's back, each piece
// drawn as a cubic Bezier curve by the evaluators (examples/ex5_bird.rs). The spline is solved
// here in double precision by the same moment method (tridiagonal, Thomas).
#include "gll.h"

#define N 21
static const double X[N] = {0.9, 1.3, 1.9, 2.1, 2.6, 3.0, 3.9, 4.4, 4.7, 5.0, 6.0, 7.0, 8.0, 9.2, 10.5, 11.3, 11.6, 12.0, 12.6, 13.0, 13.3};
static const double Y[N] = {1.3, 1.5, 1.85, 2.1, 2.6, 2.7, 2.4, 2.15, 2.05, 2.1, 2.25, 2.3, 2.25, 1.95, 1.4, 0.9, 0.7, 0.6, 0.5, 0.4, 0.25};

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 14, -1, 4);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Paint()
{
    double h[N - 1], m[N] = {0}, diag[N] = {0}, rhs[N] = {0};
    for (int i = 0; i < N - 1; i++) h[i] = X[i + 1] - X[i];
    for (int i = 1; i < N - 1; i++) { // 自然边界条件 s''(x0) = s''(xn) = 0
        diag[i] = 2 * (h[i - 1] + h[i]);
        rhs[i] = 6 * ((Y[i + 1] - Y[i]) / h[i] - (Y[i] - Y[i - 1]) / h[i - 1]);
        if (i > 1) {
            double f = h[i - 1] / diag[i - 1];
            diag[i] -= f * h[i - 1];
            rhs[i] -= f * rhs[i - 1];
        }
    }
    for (int i = N - 2; i >= 1; i--) m[i] = (rhs[i] - h[i] * m[i + 1]) / diag[i];

    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(0, 0, 1), glLineWidth(2);
    glEnable(GL_MAP1_VERTEX_3);
    for (int i = 0; i < N - 1; i++) { // 每段三次样条 = 一条三次Bézier曲线
        double d0 = -m[i] * h[i] / 2 + (Y[i + 1] - Y[i]) / h[i] - (m[i + 1] - m[i]) * h[i] / 6;
        double d1 = m[i + 1] * h[i] / 2 + (Y[i + 1] - Y[i]) / h[i] - (m[i + 1] - m[i]) * h[i] / 6;
        float pts[4][3] = {
            {X[i], Y[i], 0}, {X[i] + h[i] / 3, Y[i] + h[i] * d0 / 3, 0},
            {X[i + 1] - h[i] / 3, Y[i + 1] - h[i] * d1 / 3, 0}, {X[i + 1], Y[i + 1], 0}};
        glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &pts[0][0]);
        glMapGrid1f(20, 0, 1);
        glEvalMesh1(GL_LINE, 0, 20);
    }
    glColor3f(1, 0, 0), glPointSize(5);
    glBegin(GL_POINTS);
    for (int i = 0; i < N; i++) glVertex2f(X[i], Y[i]);
    glEnd();
    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(600, 300);
    glutCreateWindow("飞鸟外形的自然三次样条");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Paint);
    glutMainLoop();
}
