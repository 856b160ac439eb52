// gll.h: the helpers of the textbook chapter (seed 004, 9.4.2, 9.4.3 and 9.6.2) as it prints
// them, with two changes for a compiler: GL, GLU and GLUT come from <GL/glut.h> (the book's
// <gl/freeglut.h> is a Windows path; freeglut's and gleval's GL/glut.h both include GL/gl.h
// and GL/glu.h), and `int nt knots` (a line break in the printed text) reads `ntknots`.
// The listings call the helpers by two names (gllBezCurve and glBezierCurve, gllPoints and
// glPoints, glBCurve, glUniBCurve, ...): both are provided.
#pragma once
#include<stdio.h> // sprintf等
#include<stdlib.h> // 随机数函数等
#include<string.h> // 字符串函数
#include<stdarg.h> // 可变参数
#include<iso646.h> // not, and, or, etc.
#include<complex.h> // 复数函数, 需C99支持
#include<math.h> // floor, ceil, etc.
#include<tgmath.h> // 通用数学函数, 需C99支持
#include<GL/glut.h> // GL, GLU和GLUT函数
#ifndef Complex // gll.h的复数类型, 需C99支持
typedef double _Complex Complex;
#endif

static void gllBezCurve(const float pts[], int npts, int un)
{ // 控制点数组, 控制点个数, 参数区间分割数
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, npts, pts);
  glEnable(GL_MAP1_VERTEX_3); // 启用坐标值计算函数
  glMapGrid1f(un, 0, 1); // 定义一维网格, 将[0, 1]均匀分成un份
  glEvalMesh1(GL_LINE, 0, un); // 计算坐标值并生成对象
  glDisable(GL_MAP1_VERTEX_3); // 禁用坐标值计算函数
}

static void glBezSurface(GLenum mode, const float pts[], int uorder, int vorder,
                 int un, int vn)
{ // 绘制方式, 控制点数组, 控制点列数, 控制点行数, u参数区间分割数, v参数区间分割数
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, uorder, 0, 1, 3 * uorder, vorder,
          pts);
  glEnable(GL_MAP2_VERTEX_3); // 启用坐标值计算函数
  glMapGrid2f(un, 0, 1, vn, 0, 1);
  glEvalMesh2(mode, 0, un, 0, vn); // 计算坐标值并生成对象
  glDisable(GL_MAP2_VERTEX_3); // 禁用坐标值计算函数
}

static void gllPoints(const float pts[], int npts)
{
    const float *F = pts, *L = pts + 3 * npts;
    glBegin(GL_POINTS);
    for(; F != L; F += 3) glVertex3fv(F);
    glEnd();
} // 借鉴了C++ STL的常见做法

static void gllUniknots(float knots[], int npts, int order)
{ // 节点向量, 控制点个数, 阶数
  int nknots = npts + order; // 节点值个数
  for(int i = 0; i < nknots; i++) knots[i] = i; // 生成均匀节点向量
}

static void gllOpenUniknots(float knots[], int npts, int order)
{ // 节点向量, 控制点个数, 阶数
  int i, nknots = npts + order; // 节点值个数
  for(i = 0; i < order; i++) knots[i] = 0; // 0 ≤ i < d
  for(i = order; i < npts; i++) knots[i] = i - order + 1; // d ≤ i ≤ n
  for(i = npts; i < nknots; i++) knots[i] = npts - order + 1; // i > n
}

static void glBCurve(float knots[], int npts, float pts[], int order, float value)
{ // 节点向量, 控制点个数, 控制点数组, 阶数, 采样间隔(像素)
  int nknots = npts + order; // 节点值个数
  GLUnurbsObj *nobj = gluNewNurbsRenderer(); // 创建NURBS对象
  gluNurbsProperty(nobj, GLU_SAMPLING_TOLERANCE, value);
  gluBeginCurve(nobj); // 开始NURBS曲线的定义
  gluNurbsCurve(nobj, nknots, knots, 3, pts, order, GL_MAP1_VERTEX_3);
  gluEndCurve(nobj); // 结束NURBS曲线的定义
  gluDeleteNurbsRenderer(nobj); // 删除NURBS对象
}

// The listings' other names for the helpers above.
#define glBezierCurve gllBezCurve
#define gllBezSurface glBezSurface
#define glPoints gllPoints
#define glUniknots gllUniknots
#define glOpenUniknots gllOpenUniknots
#define gllBCurve glBCurve

static void glUniBCurve(int npts, float pts[], int order, float value)
{ // 控制点个数, 控制点数组, 阶数, 采样间隔(像素)
  float knots[npts + order]; // 节点向量
  glUniknots(knots, npts, order); // 生成均匀节点向量
  glBCurve(knots, npts, pts, order, value); // 绘制B样条曲线
}

static void glOpenUniBCurve(int npts, float pts[], int order, float value)
{ // 控制点个数, 控制点数组, 阶数, 采样间隔(像素)
  float knots[npts + order]; // 节点向量
  glOpenUniknots(knots, npts, order); // 生成开放均匀节点向量
  glBCurve(knots, npts, pts, order, value); // 绘制B样条曲线
}

static void glBSurface(float sknot[], float tknot[], int nspts, int ntpts, float pts[],
                int sorder, int torder)
{ // s节点向量, t节点向量, 控制点行数, 控制点列数, 控制点数组, s阶数, t阶数
  int nsknots = nspts + sorder; // s节点值个数
  int ntknots = ntpts + torder; // t节点值个数
  GLUnurbsObj *nobj = gluNewNurbsRenderer(); // 创建NURBS对象
  gluBeginSurface(nobj); // 曲面定义开始
  gluNurbsSurface(nobj, nsknots, sknot, ntknots, tknot, 3 * ntpts, 3, pts,
                  sorder, torder, GL_MAP2_VERTEX_3);
  gluEndSurface(nobj); // 结束曲面的绘制
  gluDeleteNurbsRenderer(nobj); // 删除NURBS对象
}

#define gllBSurface glBSurface

static void gllUniBSurface(int nspts, int ntpts, float pts[], int sorder, int torder)
{ // 控制点行数, 控制点列数, 控制点数组, s阶数, t阶数
  float sknot[nspts + sorder], tknot[ntpts + torder]; // s节点向量, t节点向量
  gllUniknots(sknot, nspts, sorder); // 生成均匀s节点向量
  gllUniknots(tknot, ntpts, torder); // 生成均匀t节点向量
  gllBSurface(sknot, tknot, nspts, ntpts, pts, sorder, torder); // 绘制B-曲面
}

static void gllOpenUniBSurface(int nspts, int ntpts, float pts[], int sorder, int torder)
{ // 控制点行数, 控制点列数, 控制点数组, s阶数, t阶数
  float sknot[nspts + sorder], tknot[ntpts + torder]; // s节点向量, t节点向量
  gllOpenUniknots(sknot, nspts, sorder); // 生成开放均匀s节点向量
  gllOpenUniknots(tknot, ntpts, torder); // 生成开放均匀t节点向量
  gllBSurface(sknot, tknot, nspts, ntpts, pts, sorder, torder); // 绘制B-曲面
}

#define glUniBSurface gllUniBSurface
#define glOpenUniBSurface gllOpenUniBSurface
