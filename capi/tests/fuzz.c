/* fuzz.c: random GL, GLU and GLUT calls through gleval's C ABI: NULL pointers, negative and
 * huge orders, absurd grids, NaN and infinite values, unknown enums, calls inside glBegin/glEnd
 * and inside display lists. The library must never crash, hang or unwind: every call returns,
 * glGetError only ever answers one of GL's codes, and the frame the calls drew renders.
 *
 *   fuzz CALLS SEED --png OUT.png
 *
 * The calls run in the display callback, so that glutMainLoop renders what they drew (NaN
 * vertices and all) to the PNG. Every non-NULL pointer passed addresses at least what the
 * call's own arguments say GL reads (the caller's promise in GL); the arguments themselves
 * are anything. */
#include <GL/freeglut.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static unsigned long calls = 10000, done_calls;
static uint64_t state = 88172645463325252ull;
static unsigned long errors[8];
static float buf[16384];   /* big enough for any layout the pools below allow */
static double dbuf[16384];
static GLuint names[64];
static GLUnurbs *nurbs[4];
/* Between glNewList and glEndList no list is called: a list that calls itself n times runs
 * n^64 calls before GL's nesting limit stops it, in Mesa as here (a hang, not a fault). */
static int compiling;

static uint64_t next(void) { state ^= state << 13; state ^= state >> 7; state ^= state << 17; return state; }
static int pick(int n) { return (int)(next() % (uint64_t)n); }
#define ANY(a) ((a)[pick((int)(sizeof(a) / sizeof((a)[0])))])

static const float floats[] = {0, 1, -1, 0.5f, 2, 1e30f, -1e30f, 1e-30f, NAN, INFINITY, -INFINITY, 3.25f};
static const GLint orders[] = {-3, -1, 0, 1, 2, 3, 4, 7, 30, 31, 100000, -2147483647 - 1, 2147483647};
static const GLint strides[] = {-5, 0, 1, 2, 3, 4, 7, 100};
static const GLint grids[] = {-1, 0, 1, 3, 20, 1 << 30, 2147483647, -2147483647 - 1};
static const GLint small[] = {-1, 0, 1, 2, 3, 16, 63};
static const GLenum targets[] = {GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_NORMAL,
    GL_MAP1_TEXTURE_COORD_2, GL_MAP1_INDEX, GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_MAP2_COLOR_4,
    GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_4, GL_MAP2_INDEX, 0, 0x1234, GL_TEXTURE_2D, 0xFFFFFFFFu};
static const GLenum modes[] = {GL_POINT, GL_LINE, GL_FILL, GL_POINTS, GL_LINES, GL_TRIANGLES,
    GL_QUAD_STRIP, GL_POLYGON, 0x1234, 0};
static const GLenum caps[] = {GL_MAP1_VERTEX_3, GL_MAP2_VERTEX_3, GL_MAP2_NORMAL, GL_AUTO_NORMAL,
    GL_LIGHTING, GL_LIGHT0, GL_DEPTH_TEST, GL_CULL_FACE, GL_TEXTURE_2D, GL_BLEND, GL_FOG,
    GL_NORMALIZE, GL_ALPHA_TEST, GL_COLOR_MATERIAL, 0x1234};
static const GLenum pnames[] = {GL_MAX_EVAL_ORDER, GL_MAP1_GRID_DOMAIN, GL_MAP2_GRID_DOMAIN,
    GL_MAP2_GRID_SEGMENTS, GL_CURRENT_RASTER_POSITION, GL_LIST_BASE, 0x1234};
static const GLenum glu_kinds[] = {GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_2, GLU_MAP1_TRIM_2, GLU_MAP1_TRIM_3, 0x1234};
static const GLenum properties[] = {GLU_SAMPLING_TOLERANCE, GLU_DISPLAY_MODE, GLU_CULLING,
    GLU_SAMPLING_METHOD, GLU_U_STEP, GLU_V_STEP, GLU_AUTO_LOAD_MATRIX, GLU_NURBS_MODE, 0x1234};
static const GLenum list_types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT,
    GL_2_BYTES, GL_3_BYTES, GL_4_BYTES, GL_DOUBLE, 0x1234};

static float f(void) { return ANY(floats); }
static const float *fp(void) { return pick(8) ? buf : NULL; }
static const double *dp(void) { return pick(8) ? dbuf : NULL; }

static void vertex_cb(GLfloat *v) { glVertex3fv(v); }
static void normal_cb(GLfloat *n) { glNormal3fv(n); }
static void begin_cb(GLenum mode) { glBegin(mode); }
static void end_cb(void) { glEnd(); }
static void error_cb(GLenum code) { (void)gluErrorString(code); }
static void vertex_data_cb(GLfloat *v, void *data) { (void)data; glVertex3fv(v); }

static void nurbs_call(void) {
    GLUnurbs *n = pick(6) ? nurbs[pick(4)] : NULL;
    GLint nk = ANY(small), nt = ANY(small), order = ANY(orders) % 9, torder = ANY(orders) % 9;
    switch (pick(9)) {
    case 0: gluNurbsProperty(n, ANY(properties), pick(2) ? f() : (float)ANY(targets)); break;
    case 1: gluBeginCurve(n); break;
    case 2: gluEndCurve(n); break;
    case 3: gluNurbsCurve(n, nk, (float *)fp(), ANY(strides), (float *)fp(), order, ANY(glu_kinds)); break;
    case 4: gluBeginSurface(n); break;
    case 5: gluNurbsSurface(n, nk, (float *)fp(), nt, (float *)fp(), ANY(strides), ANY(strides),
                            (float *)fp(), order, torder, ANY(glu_kinds)); break;
    case 6: gluEndSurface(n); break;
    case 7: if (pick(2)) gluBeginTrim(n); else gluEndTrim(n); break;
    default:
        switch (pick(6)) {
        case 0: gluNurbsCallback(n, GLU_NURBS_VERTEX, pick(4) ? (_GLUfuncptr)vertex_cb : NULL); break;
        case 1: gluNurbsCallback(n, GLU_NURBS_BEGIN, (_GLUfuncptr)begin_cb); break;
        case 2: gluNurbsCallback(n, GLU_NURBS_END, (_GLUfuncptr)end_cb); break;
        case 3: gluNurbsCallback(n, GLU_NURBS_NORMAL, (_GLUfuncptr)normal_cb); break;
        case 4: gluNurbsCallback(n, pick(2) ? GLU_NURBS_ERROR : 0x1234, (_GLUfuncptr)error_cb); break;
        default: gluNurbsCallback(n, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)vertex_data_cb);
                 gluNurbsCallbackData(n, pick(2) ? buf : NULL); break;
        }
    }
}

static void map_call(void) {
    switch (pick(10)) {
    case 0: glMap1f(ANY(targets), f(), f(), ANY(strides), ANY(orders), fp()); break;
    case 1: glMap1d(ANY(targets), f(), f(), ANY(strides), ANY(orders), dp()); break;
    case 2: glMap2f(ANY(targets), f(), f(), ANY(strides), ANY(orders), f(), f(), ANY(strides), ANY(orders), fp()); break;
    case 3: glMap2d(ANY(targets), f(), f(), ANY(strides), ANY(orders), f(), f(), ANY(strides), ANY(orders), dp()); break;
    case 4: glMapGrid1f(ANY(grids), f(), f()); break;
    case 5: glMapGrid2d(ANY(grids), f(), f(), ANY(grids), f(), f()); break;
    case 6: glEvalMesh1(ANY(modes), ANY(grids), ANY(grids)); break;
    case 7: glEvalMesh2(ANY(modes), ANY(small), ANY(grids), ANY(small), ANY(small)); break;
    case 8: glEvalCoord2f(f(), f()); glEvalPoint2(ANY(grids), ANY(small)); glEvalCoord1fv(fp()); break;
    default: glGetMapfv(ANY(targets), GL_COEFF + pick(4), buf); glGetMapiv(ANY(targets), GL_ORDER, pick(4) ? (GLint *)names : NULL); break;
    }
}

static void state_call(void) {
    switch (pick(14)) {
    case 0: glEnable(ANY(caps)); break;
    case 1: glDisable(ANY(caps)); break;
    case 2: glBegin(ANY(modes)); break;
    case 3: glEnd(); break;
    case 4: glVertex3f(f(), f(), f()); glVertex3fv(fp()); glNormal3fv(fp()); glColor4fv(fp()); break;
    case 5: glGetFloatv(ANY(pnames), pick(6) ? buf : NULL); glGetIntegerv(ANY(pnames), (GLint *)names); break;
    case 6: glLightfv(GL_LIGHT0 + pick(9), GL_AMBIENT + pick(10), fp()); glMaterialfv(GL_FRONT + pick(3), GL_EMISSION + pick(4), fp()); break;
    case 7: glNewList(1 + pick(8), pick(2) ? GL_COMPILE : GL_COMPILE_AND_EXECUTE); compiling = 1; break;
    case 8: glEndList(); compiling = 0; glCallList(1 + pick(8)); break;
    case 9: if (!compiling) glCallLists(ANY(small), ANY(list_types), pick(6) ? (void *)buf : NULL); break;
    case 10: glPushMatrix(); glRotatef(f(), f(), f(), f()); glLoadMatrixf(fp()); glPopMatrix(); break;
    case 11: glTexImage2D(GL_TEXTURE_2D, ANY(small), GL_RGB, ANY(small), ANY(small), 0, GL_RGB,
                          pick(2) ? GL_UNSIGNED_BYTE : GL_FLOAT, pick(3) ? (void *)buf : NULL); break;
    case 12: glRasterPos3f(f(), f(), f()); glBitmap(ANY(small), ANY(small), f(), f(), f(), f(), pick(4) ? (GLubyte *)buf : NULL);
             glutBitmapCharacter(pick(2) ? GLUT_BITMAP_HELVETICA_12 : (void *)(intptr_t)pick(4000), pick(300) - 20); break;
    default: glPointSize(f()); glLineWidth(f()); glViewport(ANY(grids), 0, ANY(small), ANY(grids)); glFogfv(GL_FOG_COLOR, fp()); break;
    }
}

/* GLUT's calls with any arguments: windows that do not exist, unknown names, odd shape sizes
 * (small enough to draw: freeglut itself gives up on shapes of more than 65535 vertices). The
 * program's own window is never hidden or destroyed, so that its picture is written. */
static void glut_call(void) {
    static const unsigned char text[] = "glut\nfuzz\x7f\xff";
    double offset[3] = {f(), f(), f()};
    switch (pick(8)) {
    case 0: glutSetWindow(pick(6) - 1); glutPostWindowRedisplay(pick(6) - 1); glutDestroyWindow(2 + pick(5)); break;
    case 1: glutGet(pick(0x300)); glutDeviceGet(pick(0x300)); glutLayerGet(pick(0x400)); glutGameModeGet(pick(10) - 2); break;
    case 2: glutSetOption(pick(0x300), pick(5) - 1); glutSetKeyRepeat(pick(5) - 1); glutIgnoreKeyRepeat(pick(3)); break;
    case 3: glutSolidCylinder(f(), f(), pick(40) - 5, pick(40) - 5); glutWireSierpinskiSponge(pick(7) - 2, pick(4) ? offset : NULL, f()); break;
    /* The tea set is thousands of vertices a call: now and then. */
    case 4: if (!pick(24)) { glutSolidTeacup(f()); glutWireTeaspoon(f()); }
            glutSolidRhombicDodecahedron(); glutWireIcosahedron(); break;
    case 5: glutStrokeString(pick(2) ? GLUT_STROKE_ROMAN : (void *)(intptr_t)pick(4000), pick(4) ? text : NULL);
            glutStrokeCharacter(GLUT_STROKE_MONO_ROMAN, pick(400) - 100); glutBitmapString(GLUT_BITMAP_9_BY_15, text); break;
    case 6: glutSetMenu(pick(4)); glutSetMenuData(buf); glutGetMenuData(); glutSetMenuFont(pick(4), (void *)(intptr_t)pick(12)); break;
    default: glutJoystickSetCenter(pick(4) - 1, pick(4) ? buf : NULL); glutJoystickGetDeadBand(pick(4) - 1, pick(4) - 1);
             glutPositionWindow(pick(100), pick(100)); glutSetCursor(pick(120)); glutWarpPointer(pick(64), pick(64)); break;
    }
}

static void display(void) {
    for (int i = 0; i < 4; i++) nurbs[i] = gluNewNurbsRenderer();
    for (size_t i = 0; i < sizeof buf / sizeof buf[0]; i++) {
        buf[i] = (i % 17 == 5) ? NAN : (float)((int)(i % 11) - 5) * 0.4f;
        dbuf[i] = buf[i];
    }
    for (unsigned long c = 0; c < calls; c++) {
        switch (pick(4)) {
        case 0: map_call(); break;
        case 1: nurbs_call(); break;
        case 2: glut_call(); break;
        default: state_call(); break;
        }
        GLenum e = glGetError();
        if (e != GL_NO_ERROR && (e < GL_INVALID_ENUM || e > GL_OUT_OF_MEMORY)) {
            fprintf(stderr, "fuzz: glGetError gave 0x%x after call %lu\n", e, c);
            exit(1);
        }
        errors[e ? e - GL_INVALID_ENUM + 1 : 0]++;
        done_calls++;
    }
    glEnd();
    glEndList();
    for (int i = 0; i < 4; i++) gluDeleteNurbsRenderer(nurbs[i]);
    gluDeleteNurbsRenderer(NULL);
    printf("fuzz: %lu calls returned; errors: none %lu, enum %lu, value %lu, operation %lu, "
           "overflow %lu, underflow %lu, out of memory %lu\n", done_calls, errors[0], errors[1],
           errors[2], errors[3], errors[4], errors[5], errors[6]);
    fflush(stdout);
}

int main(int argc, char **argv) {
    glutInit(&argc, argv);
    if (argc > 1) calls = strtoul(argv[1], NULL, 10);
    if (argc > 2) state += strtoull(argv[2], NULL, 10) * 0x9E3779B97F4A7C15ull;
    glutInitWindowSize(64, 64);
    glutCreateWindow("fuzz");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
