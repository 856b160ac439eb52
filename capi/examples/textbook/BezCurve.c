// BezCurve.c
// (Seed 004, 9.4.3, as printed.)
#include "gl.h"

void Reshape(int w, int h) // 窗口变化回调函数
{
    glViewport(0, 0, w, h); // 根据指定位置和大小创建视口
    glMatrixMode(GL_PROJECTION); // 投影矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
    gluOrtho2D(-2.2, 2.2, -1.1, 1.1); // 裁剪窗口，比[-2, 2][ -1, 1]稍大
    glMatrixMode(GL_MODELVIEW); // 视图造型矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
}
void Paint() // 场景绘制函数
{
    glClearColor(1, 1, 1, 1); // 白色背景
    glClear(GL_COLOR_BUFFER_BIT); // 清除颜色缓冲
    // 控制点数组
    float pts[][3] = {{-2, 0, 0}, {-1, 1, 0}, {0, 0, 0}, {1, -1, 0}, {2, 0, 0}};
    int npts = 5, un = 100; // 控制点个数, 参数区间分割数

    glColor3f(0, 0, 1), glLineWidth(2); // 曲线颜色和线宽
    glBezierCurve((float *)pts, npts, un); // Bézier曲线
    glColor3f(1, 0, 0), glPointSize(5); // 控制点颜色和大小
    glPoints((float *)pts, npts); // 控制点

    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 200); // 程序窗口大小(4:2)
    glutCreateWindow("Bézier曲线");
    glutDisplayFunc(Paint);
    glutReshapeFunc(Reshape);
    glutMainLoop();
}
