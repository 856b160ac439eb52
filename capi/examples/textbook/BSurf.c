// BSurf.c
// (Seed 004, 9.6.3, as printed; the page break that printed Paint's closing brace after the
// control points, and its last lines unindented, is undone.)
#include "gll.h"

void Viewport(int x, int y, int w, int h) // 创建视口, 指定投影变换
{
    glViewport(x, y, w, h); // 根据指定位置和大小创建视口
    glMatrixMode(GL_PROJECTION); // 投影矩阵栈
    glLoadIdentity(); // 当前矩阵改为单位矩阵
    // 透视变换(视角30度, 宽高比, 近平面, 远平面)
    gluPerspective(30, (float)w / h, 1, 1000);
    glTranslatef(0.5, 0.5, -14); // 场景右移0.5, 上移0.5, 远移14
    glRotatef(30, -1, 1, 0); // 场景绕(-1, 1, 0)方向旋转30度
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
    // 清除颜色缓存和深度缓存
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2; // 视口宽度
    int h = glutGet(GLUT_WINDOW_HEIGHT); // 视口高度
    float pts[4][4][3] = // 控制点坐标
    {
        {{-3, -3, -3}, {-3, -1, -3}, {-3, 1, -3}, {-3, 3, -3}},
        {{-1, -3, -3}, {-1, -1, 3}, {-1, 1, 3}, {-1, 3, -3}},
        {{1, -3, -3}, {1, -1, 3}, {1, 1, 3}, {1, 3, -3}},
        {{3, -3, -3}, {3, -1, -3}, {3, 1, -3}, {3, 3, -3}}
    };
    Viewport(0, 0, w, h); // 左侧, 均匀B-曲面
    glUniBSurface(4, 4, (float *)pts, 4, 4); // 均匀B-曲面
    glPoints((float *)pts, 4 * 4); // 绘制控制点
    Viewport(w, 0, w, h); // 右侧, 开放均匀B-曲面
    glOpenUniBSurface(4, 4, (float *)pts, 4, 4); // 开放均匀B-曲面
    glPoints((float *)pts, 4 * 4); // 绘制控制点
    glFlush();
}
int main(int argc, char *argv[])
{  glutInit(&argc, argv);
    glutInitWindowSize(500, 200); // 程序窗口大小(5:2)
    glutCreateWindow("B-曲面");
    Hint(); // 初始化(材质属性和光照属性等)
    glutDisplayFunc(Paint);
    glutMainLoop();
}
