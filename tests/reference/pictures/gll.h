/* The textbook's gll.h helpers (seed 004, 9.4.2, 9.4.3, 9.6.2), C99. The textbook's own
   listing mixes the names glBezierCurve/gllBezCurve, glPoints/gllPoints, glBCurve/gllBCurve;
   the gll names are used throughout. */
#pragma once
#include "gl.h"

static void gllBezCurve(const float pts[], int npts, int un) {
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, npts, pts);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(un, 0, 1);
    glEvalMesh1(GL_LINE, 0, un);
    glDisable(GL_MAP1_VERTEX_3);
}

static void gllBezSurface(GLenum mode, const float pts[], int uorder, int vorder, int un, int vn) {
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, uorder, 0, 1, 3 * uorder, vorder, pts);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(un, 0, 1, vn, 0, 1);
    glEvalMesh2(mode, 0, un, 0, vn);
    glDisable(GL_MAP2_VERTEX_3);
}

static void gllPoints(const float pts[], int npts) {
    const float *F = pts, *L = pts + 3 * npts;
    glBegin(GL_POINTS);
    for (; F != L; F += 3) glVertex3fv(F);
    glEnd();
}

static void gllUniknots(float knots[], int npts, int order) {
    int nknots = npts + order;
    for (int i = 0; i < nknots; i++) knots[i] = i;
}

static void gllOpenUniknots(float knots[], int npts, int order) {
    int i, nknots = npts + order;
    for (i = 0; i < order; i++) knots[i] = 0;
    for (i = order; i < npts; i++) knots[i] = i - order + 1;
    for (i = npts; i < nknots; i++) knots[i] = npts - order + 1;
}

static void gllBCurve(float knots[], int npts, float pts[], int order, float value) {
    int nknots = npts + order;
    GLUnurbsObj *nobj = gluNewNurbsRenderer();
    gluNurbsProperty(nobj, GLU_SAMPLING_TOLERANCE, value);
    gluBeginCurve(nobj);
    gluNurbsCurve(nobj, nknots, knots, 3, pts, order, GL_MAP1_VERTEX_3);
    gluEndCurve(nobj);
    gluDeleteNurbsRenderer(nobj);
}

static void gllUniBCurve(int npts, float pts[], int order, float value) {
    float knots[npts + order];
    gllUniknots(knots, npts, order);
    gllBCurve(knots, npts, pts, order, value);
}

static void gllOpenUniBCurve(int npts, float pts[], int order, float value) {
    float knots[npts + order];
    gllOpenUniknots(knots, npts, order);
    gllBCurve(knots, npts, pts, order, value);
}

static void gllBSurface(float sknot[], float tknot[], int nspts, int ntpts, float pts[], int sorder, int torder) {
    int nsknots = nspts + sorder, ntknots = ntpts + torder;
    GLUnurbsObj *nobj = gluNewNurbsRenderer();
    gluBeginSurface(nobj);
    gluNurbsSurface(nobj, nsknots, sknot, ntknots, tknot, 3 * ntpts, 3, pts, sorder, torder, GL_MAP2_VERTEX_3);
    gluEndSurface(nobj);
    gluDeleteNurbsRenderer(nobj);
}

static void gllUniBSurface(int nspts, int ntpts, float pts[], int sorder, int torder) {
    float sknot[nspts + sorder], tknot[ntpts + torder];
    gllUniknots(sknot, nspts, sorder);
    gllUniknots(tknot, ntpts, torder);
    gllBSurface(sknot, tknot, nspts, ntpts, pts, sorder, torder);
}

static void gllOpenUniBSurface(int nspts, int ntpts, float pts[], int sorder, int torder) {
    float sknot[nspts + sorder], tknot[ntpts + torder];
    gllOpenUniknots(sknot, nspts, sorder);
    gllOpenUniknots(tknot, ntpts, torder);
    gllBSurface(sknot, tknot, nspts, ntpts, pts, sorder, torder);
}
