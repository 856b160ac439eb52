/* Counts the vertices GLU's tessellator mode emits for a few NURBS, with the sampling
   properties given, using fixed sampling matrices (identity modelview, a gluOrtho2D-like
   projection, a 400x400 viewport). tests/it/glu_tessellation.rs draws the same with gleval.
   Build: cc tess_counts.c -lOSMesa -lGLU -lGL */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>

static long vertices, primitives;
static void vcb(GLfloat *v) { (void)v; vertices++; }
static void bcb(GLenum t) { (void)t; primitives++; }

static GLfloat model[16] = {1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1};
/* glOrtho(-2, 2, -2, 2, -10, 10) */
static GLfloat proj[16] = {0.5f,0,0,0, 0,0.5f,0,0, 0,0,-0.1f,0, 0,0,0,1};
static GLint view[4] = {0, 0, 400, 400};

/* Bicubic B-spline 10x10 over knots 0..13 (uniform), a wavy sheet in [-1.5,1.5]^2. */
static GLfloat sknots[14], ctl[10][10][3];
/* Degree-3 curve, 8 points, open uniform knots. */
static GLfloat cknots[12] = {0,0,0,0,1,2,3,4,5,5,5,5};
static GLfloat cctl[8][3] = {{-1.5f,0,0},{-1,1,0},{-0.5f,-1,0},{0,1,0},{0.5f,-1,0},{1,1,0},{1.5f,0,0},{1.8f,0.5f,0}};

static GLUnurbs *make(float method, float tolerance, float step) {
    GLUnurbs *n = gluNewNurbsRenderer();
    gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(n, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
    gluLoadSamplingMatrices(n, model, proj, view);
    gluNurbsProperty(n, GLU_SAMPLING_METHOD, method);
    gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gluNurbsProperty(n, GLU_PARAMETRIC_TOLERANCE, tolerance);
    gluNurbsProperty(n, GLU_U_STEP, step);
    gluNurbsProperty(n, GLU_V_STEP, step);
    gluNurbsCallback(n, GLU_NURBS_VERTEX, (void (*)(void))vcb);
    gluNurbsCallback(n, GLU_NURBS_BEGIN, (void (*)(void))bcb);
    return n;
}

static void surface(const char *name, float method, float tolerance, float step) {
    GLUnurbs *n = make(method, tolerance, step);
    vertices = primitives = 0;
    gluBeginSurface(n);
    gluNurbsSurface(n, 14, sknots, 14, sknots, 30, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(n);
    printf("surface %s %ld %ld\n", name, vertices, primitives);
    gluDeleteNurbsRenderer(n);
}

static void curve(const char *name, float method, float tolerance, float step) {
    GLUnurbs *n = make(method, tolerance, step);
    vertices = primitives = 0;
    gluBeginCurve(n);
    gluNurbsCurve(n, 12, cknots, 3, &cctl[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(n);
    printf("curve %s %ld %ld\n", name, vertices, primitives);
    gluDeleteNurbsRenderer(n);
}

int main(void) {
    static GLubyte buf[64 * 64 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64);
    for (int i = 0; i < 14; i++) sknots[i] = (GLfloat)i;
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++) {
            ctl[i][j][0] = -1.5f + i / 3.0f;
            ctl[i][j][1] = -1.5f + j / 3.0f;
            ctl[i][j][2] = ((i * 3 + j * 5) % 7) / 7.0f - 0.5f;
        }
    curve("path_length_50", GLU_PATH_LENGTH, 50, 100);
    curve("path_length_5", GLU_PATH_LENGTH, 5, 100);
    curve("parametric_error_2", GLU_PARAMETRIC_ERROR, 2, 100);
    curve("domain_distance_10", GLU_DOMAIN_DISTANCE, 50, 10);
    surface("path_length_50", GLU_PATH_LENGTH, 50, 100);
    surface("path_length_10", GLU_PATH_LENGTH, 10, 100);
    surface("parametric_error_1", GLU_PARAMETRIC_ERROR, 1, 100);
    surface("domain_distance_8", GLU_DOMAIN_DISTANCE, 50, 8);
    surface("domain_distance_50", GLU_DOMAIN_DISTANCE, 50, 50);
    OSMesaDestroyContext(c);
    return 0;
}
