// BezSurf.c
// (Seed 004, 9.4.3, as printed.)
#include "gl.h"
void Viewport(int x, int y, int w, int h) // 创建视口，指定投影变换
{
    glViewport(x, y, w, h); // 根据指定位置和大小创建视口
    glMatrixMode(GL_PROJECTION); // 投影矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
    gluPerspective(30, (float)w / h, 1, 1000);
    // 透视变换(视角30度，宽高比，近平面，远平面)
    glTranslatef(0.25, 0.35, -8.5); // 场景右移0.25，上移0.35，远移8.5
    glMatrixMode(GL_MODELVIEW); // 视图造型矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
}
void Hint() // 初始化(材质属性和光照属性等)
{
    glPointSize(3); // 点的大小
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]) {1, 1, 1, 1}); // 白色材质
    glEnable(GL_AUTO_NORMAL); // 自动计算表面法向量
    glEnable(GL_NORMALIZE); // 自动单位化法向量
    glEnable(GL_LIGHT0); // 启用0号光源
    glEnable(GL_LIGHTING); // 启用光照效果
}
void Paint() // 场景绘制函数
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // 清除颜色缓冲和深度缓冲
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2; // 视口宽度
    int h = glutGet(GLUT_WINDOW_HEIGHT); // 视口高度
    float pts[4][4][3] = // 控制点坐标
    {
        {{ -1.5, -1.5, 4}, { -0.5, -1.5, 2}, { 0.5, -1.5, -1}, { 1.5, -1.5, 2}},
        {{ -1.5, -0.5, 1}, { -0.5, -0.5, 3}, { 0.5, -0.5, 0}, { 1.5, -0.5, -1}},
        {{ -1.5, 0.5, 4}, { -0.5, -0.5, 0}, { 0.5, 0.5, 3}, { 1.5, 0.5, 4}},
        {{ -1.5, 1.5, -2}, { -0.5, 1.5, -2}, { 0.5, 1.5, 0}, { 1.5, 1.5, 1}}
    };

    Viewport(0, 0, w, h); // 左侧用线框模型
    // 构造Bezier曲面(绘制方式, 控制点数组, 列数, 行数, u分割数, v分割数)
    gllBezSurface(GL_LINE, (float *)pts, 4, 4, 20, 20);
    gllPoints((float *)pts, 4 * 4); // 绘制控制点

    Viewport(w, 0, w, h); // 右侧用填充模型
    gllBezSurface(GL_FILL, (float *)pts, 4, 4, 20, 20);
    gllPoints((float *)pts, 4 * 4); // 绘制控制点
    glFlush();
}
int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(500, 200); // 程序窗口大小(5:2)
    glutCreateWindow("Bézier曲面");
    Hint(); // 初始化(材质属性和光照属性等)
    glutDisplayFunc(Paint);
    glutMainLoop();
}
