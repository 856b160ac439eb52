// BCurve.c
// (Seed 004, 9.6.3, as printed.)
#include "gl.h"

void Viewport(int x, int y, int w, int h) // 创建视口，指定投影变换
{
    glViewport(x, y, w, h); // 根据指定位置和大小创建视口
    glMatrixMode(GL_PROJECTION); // 投影矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
    gluOrtho2D(-0.25, 5.25, -2.2, 2.2); // 裁剪窗口，比[0, 5][ -2, 2]稍大
    glMatrixMode(GL_MODELVIEW); // 视图造型矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
}
void Paint() // 场景绘制函数
{
    glClearColor(1, 1, 1, 1); // 白色背景
    glClear(GL_COLOR_BUFFER_BIT); // 清除颜色缓冲
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2; // 视口宽度
    int h = glutGet(GLUT_WINDOW_HEIGHT); // 视口高度
    float pts[][3] = // 控制点坐标
    { {0, 0, 0}, {1, -2, 0}, {2, 0, 0}, {3, 2, 0}, {4, 0, 0}, {5, -2, 0} };
    int npts = 6, order = 4; // 控制点个数,阶数

    Viewport(0, 0, w, h); // 左视区, 均匀B-曲线
    glColor3f(1, 0, 0), glPointSize(5); // 控制点颜色和大小
    glPoints((float *)pts, npts); // 控制点
    glColor3f(0, 0, 1), glLineWidth(2.5); // 曲线颜色和线宽
    glUniBCurve(npts, (float *)pts, order, 1); // 均匀B-曲线

    Viewport(w, 0, w, h); // 右视区, 开放均匀B-曲线
    glColor3f(1, 0, 0), glPointSize(5); // 控制点颜色和大小
    glPoints((float *)pts, npts); // 控制点
    glColor3f(0, 0, 1), glLineWidth(2.5); // 曲线颜色和线宽
    glOpenUniBCurve(npts, (float *)pts, order, 1); // 开放均匀B-曲线
    glFlush();
}
int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(500, 200); // 程序窗口大小(5:2)
    glutCreateWindow("B-曲线");
    glutDisplayFunc(Paint);
    glutMainLoop();
}
