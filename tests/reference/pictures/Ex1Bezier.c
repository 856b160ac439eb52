// Seed 004, 9.7.2 exercise 1: a cubic Bezier curve from four control points (examples/ex1_bezier.rs).
#include "gll.h"

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h); // 视口与窗口同大小
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-0.5, 3.5, -1.5, 1.5); // 裁剪窗口包住控制点
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Paint()
{
    glClearColor(1, 1, 1, 1); // 白色背景
    glClear(GL_COLOR_BUFFER_BIT);
    float pts[][3] = { {0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 0, 0} }; // 控制点
    glColor3f(0.6, 0.6, 0.6); // 控制多边形: 灰色
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i < 4; i++) glVertex3fv(pts[i]);
    glEnd();
    glColor3f(1, 0, 0), glPointSize(6);
    gllPoints((float *)pts, 4); // 控制点: 红色
    glColor3f(0, 0, 1), glLineWidth(2);
    gllBezCurve((float *)pts, 4, 100); // 三次Bézier曲线: 蓝色
    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 300);
    glutCreateWindow("三次Bézier曲线");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Paint);
    glutMainLoop();
}
