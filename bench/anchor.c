/* The C anchor for bench/compare.sh: real Mesa's evaluators (OSMesa) and GLU's tessellator on
   the same workloads as examples/bench.rs. Rasterisation is culled away (glCullFace
   GL_FRONT_AND_BACK) so the evaluator path is what is timed. Prints "<case> <rate per second>"
   with the median of several runs. Build: cc -O2 anchor.c -lOSMesa -lGLU -lGL -lm */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + t.tv_nsec * 1e-9; }
static int cmp(const void *a, const void *b) { double x = *(const double *)a, y = *(const double *)b; return (x > y) - (x < y); }
static double median(double *t, int n) { qsort(t, n, sizeof *t, cmp); return t[n / 2]; }

static GLfloat patch[4][4][3];
static long tess_vertices;
static void count_vertex(GLfloat *v) { (void)v; tess_vertices++; }

static void mesh2(int n, int runs) {
    double t[16];
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(n, 0, 1, n, 0, 1);
    for (int r = 0; r < runs; r++) {
        double s = now();
        glEvalMesh2(GL_FILL, 0, n, 0, n);
        glFinish();
        t[r] = now() - s;
    }
    printf("eval_mesh2_%d %.0f\n", n, (double)(n + 1) * (n + 1) / median(t, runs));
}

/* 10,000 small bicubic patches in one frame: one glMap2f and one 8x8 glEvalMesh2 each. */
static void patches(int runs) {
    double t[16];
    int count = 10000, n = 8;
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(n, 0, 1, n, 0, 1);
    for (int r = 0; r < runs; r++) {
        double s = now();
        for (int k = 0; k < count; k++) {
            patch[0][0][2] = (k % 7) * 0.1f;
            glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
            glEvalMesh2(GL_FILL, 0, n, 0, n);
        }
        glFinish();
        t[r] = now() - s;
    }
    patch[0][0][2] = 0;
    printf("patches_10000 %.0f\n", (double)count * (n + 1) * (n + 1) / median(t, runs));
}

static void mesh1(int runs) {
    GLfloat curve[11][3];
    for (int i = 0; i < 11; i++) { curve[i][0] = i * 0.1f - 0.5f; curve[i][1] = (i % 3) * 0.2f; curve[i][2] = 0; }
    double t[16];
    int n = 1000000;
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 11, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(n, 0, 1);
    for (int r = 0; r < runs; r++) {
        double s = now();
        glEvalMesh1(GL_LINE, 0, n);
        glFinish();
        t[r] = now() - s;
    }
    printf("eval_mesh1_degree10 %.0f\n", (n + 1) / median(t, runs));
}

/* The first glEvalMesh2 of a fresh context: 1000^2, GL_AUTO_NORMAL, nothing warm (a new OSMesa
   context each run; the context's creation is not timed). */
static void first_mesh2(const char *name, int runs) {
    static unsigned char buf[64 * 64 * 4];
    double t[16];
    int n = 1000;
    OSMesaContext previous = OSMesaGetCurrentContext();
    for (int r = 0; r < runs; r++) {
        OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
        OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT_AND_BACK);
        glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &patch[0][0][0]);
        glEnable(GL_MAP2_VERTEX_3);
        glEnable(GL_AUTO_NORMAL);
        glMapGrid2f(n, 0, 1, n, 0, 1);
        double s = now();
        glEvalMesh2(GL_FILL, 0, n, 0, n);
        glFinish();
        t[r] = now() - s;
        OSMesaMakeCurrent(previous, buf, GL_UNSIGNED_BYTE, 64, 64);
        OSMesaDestroyContext(c);
    }
    printf("%s %.0f\n", name, (double)(n + 1) * (n + 1) / median(t, runs));
}

/* 10,000 curves drawn as the textbook's B-spline programs draw their Bezier pieces: a glMap1f
   of 4 points, then glBegin(GL_LINE_STRIP), 31 glEvalCoord1f, glEnd. */
static void eval_coord_curves(int runs) {
    GLfloat ctl[4][3] = {{-0.5f, 0, 0}, {-0.2f, 0.4f, 0}, {0.2f, -0.4f, 0}, {0.5f, 0, 0}};
    double t[16];
    int count = 10000, n = 30;
    glEnable(GL_MAP1_VERTEX_3);
    for (int r = 0; r < runs; r++) {
        double s = now();
        for (int k = 0; k < count; k++) {
            ctl[0][1] = (k % 5) * 0.1f;
            glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &ctl[0][0]);
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i <= n; i++) glEvalCoord1f((GLfloat)i / n);
            glEnd();
        }
        glFinish();
        t[r] = now() - s;
    }
    glDisable(GL_MAP1_VERTEX_3);
    printf("eval_coord_curves %.0f\n", (double)count * (n + 1) / median(t, runs));
}

static void nurbs(int runs) {
    static GLfloat knots[14], ctl[10][10][3];
    for (int i = 0; i < 14; i++) knots[i] = i;
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++) {
            ctl[i][j][0] = i; ctl[i][j][1] = j; ctl[i][j][2] = ((i * 3 + j * 5) % 7) * 0.3f;
        }
    double t[16];
    GLUnurbs *nb = gluNewNurbsRenderer();
    gluNurbsProperty(nb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nb, GLU_U_STEP, 100);
    gluNurbsProperty(nb, GLU_V_STEP, 100);
    gluNurbsCallback(nb, GLU_NURBS_VERTEX, (void (*)(void))count_vertex);
    for (int r = 0; r < runs; r++) {
        tess_vertices = 0;
        double s = now();
        gluBeginSurface(nb);
        gluNurbsSurface(nb, 14, knots, 14, knots, 30, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
        gluEndSurface(nb);
        t[r] = now() - s;
    }
    printf("nurbs_untrimmed %.0f\n", tess_vertices / median(t, runs));
    gluDeleteNurbsRenderer(nb);
}

/* The trimmed "hills" surface of the red book's trim.c (tests/reference/pictures/Trimmed.c) in
   tessellator mode at domain steps of 300: an outer loop, a hole of a Bezier arc and a
   polyline, and a triangle. */
static void nurbs_trimmed(int runs) {
    static GLfloat hills[4][4][3];
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            hills[u][v][0] = 2.0f * (u - 1.5f);
            hills[u][v][1] = 2.0f * (v - 1.5f);
            hills[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
        }
    GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    GLfloat edge[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    GLfloat curve[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.5f}};
    GLfloat pwl[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
    GLfloat tri[4][2] = {{0.1f, 0.1f}, {0.2f, 0.3f}, {0.3f, 0.1f}, {0.1f, 0.1f}};
    double t[16];
    GLUnurbs *nb = gluNewNurbsRenderer();
    gluNurbsProperty(nb, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(nb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nb, GLU_U_STEP, 300);
    gluNurbsProperty(nb, GLU_V_STEP, 300);
    gluNurbsCallback(nb, GLU_NURBS_VERTEX, (void (*)(void))count_vertex);
    for (int r = 0; r < runs; r++) {
        tess_vertices = 0;
        double s = now();
        gluBeginSurface(nb);
        gluNurbsSurface(nb, 8, knots, 8, knots, 12, 3, &hills[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
        gluBeginTrim(nb);
        gluPwlCurve(nb, 5, &edge[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nb);
        gluBeginTrim(nb);
        gluNurbsCurve(nb, 8, knots, 2, &curve[0][0], 4, GLU_MAP1_TRIM_2);
        gluPwlCurve(nb, 3, &pwl[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nb);
        gluBeginTrim(nb);
        gluPwlCurve(nb, 4, &tri[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(nb);
        gluEndSurface(nb);
        t[r] = now() - s;
    }
    printf("nurbs_trimmed %.0f\n", tess_vertices / median(t, runs));
    gluDeleteNurbsRenderer(nb);
}

/* With the argument "cold": only the first glEvalMesh2 of the process's first fresh context
   (bench/compare.sh runs it in new processes, as the Rust side's BENCH_COLD=1). */
int main(int argc, char **argv) {
    static unsigned char buf[64 * 64 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) { patch[i][j][0] = i / 3.0f - 0.5f; patch[i][j][1] = j / 3.0f - 0.5f; patch[i][j][2] = ((i + j) % 3) * 0.2f; }
    if (argc > 1 && strcmp(argv[1], "cold") == 0) {
        first_mesh2("cold_first_eval_mesh2_1000", 1);
        return 0;
    }
    mesh2(100, 9);
    mesh2(1000, 5);
    mesh2(4000, 3);
    patches(5);
    mesh1(5);
    eval_coord_curves(5);
    first_mesh2("first_eval_mesh2_1000", 5);
    nurbs(5);
    nurbs_trimmed(5);
    return 0;
}
