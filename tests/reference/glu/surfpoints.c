/* Prints what GLU hands to the GLU_NURBS_TESSELLATOR callbacks, as the Red Book's surfpoints.c
   prints it (glBegin, glNormal3f, glVertex3f, glEnd, 3 decimals), for untrimmed surfaces under
   several sampling methods and tolerances, a multi-span B-spline sheet, rational and bilinear
   patches, trimmed surfaces (pwl and NURBS trim loops: holes, an island, a notch from the
   border), outlines (GLU_OUTLINE_PATCH) and curves. tests/it/glu_surfpoints.rs runs the same cases through gleval and
   compares the text. Build: cc surfpoints.c -lOSMesa -lGLU -lGL */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>

static void begin_cb(GLenum t) {
    const char *n = t == GL_TRIANGLE_FAN ? "GL_TRIANGLE_FAN" : t == GL_QUAD_STRIP ? "GL_QUAD_STRIP"
        : t == GL_TRIANGLE_STRIP ? "GL_TRIANGLE_STRIP" : t == GL_TRIANGLES ? "GL_TRIANGLES"
        : t == GL_LINE_STRIP ? "GL_LINE_STRIP" : t == GL_LINE_LOOP ? "GL_LINE_LOOP" : "?";
    printf("glBegin(%s)\n", n);
}
static void normal_cb(GLfloat *v) { printf("glNormal3f (%.3f, %.3f, %.3f)\n", v[0], v[1], v[2]); }
static void vertex_cb(GLfloat *v) { printf("glVertex3f (%.3f, %.3f, %.3f)\n", v[0], v[1], v[2]); }
static void end_cb(void) { printf("glEnd()\n"); }

/* The Red Book's surface.c hill: 4x4 bicubic Bezier, z = 3 inside, -3 on the rim. */
static GLfloat hill[4][4][3];
static GLfloat bezier_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
/* A 10x10 bicubic B-spline sheet over uniform knots 0..13 (7x7 Bezier patches). */
static GLfloat sheet_knots[14], sheet[10][10][3];
/* A rational quadratic-by-linear patch: a quarter of a cylinder. */
static GLfloat cyl_uknots[6] = {0, 0, 0, 1, 1, 1}, cyl_vknots[4] = {0, 0, 1, 1};
static GLfloat cyl[3][2][4] = {{{1, 0, -1, 1}, {1, 0, 1, 1}},
                               {{0.7071f, 0.7071f, -0.7071f, 0.7071f}, {0.7071f, 0.7071f, 0.7071f, 0.7071f}},
                               {{0, 1, -1, 1}, {0, 1, 1, 1}}};
/* A bilinear twisted square. */
static GLfloat lin_knots[4] = {0, 0, 1, 1};
static GLfloat twist[2][2][3] = {{{-2, -2, 0}, {-2, 2, 1}}, {{2, -2, 1}, {2, 2, -1}}};
/* Curves: a cubic B-spline of 8 points and a rational quadratic arc. */
static GLfloat curve_knots[12] = {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5};
static GLfloat curve[8][3] = {{-3, 0, 0}, {-2, 2, 0}, {-1, -2, 0}, {0, 2, 0}, {1, -2, 0}, {2, 2, 0}, {3, 0, 0}, {3.6f, 1, 0}};
static GLfloat arc_knots[6] = {0, 0, 0, 1, 1, 1};
static GLfloat arc[3][4] = {{2, 0, 0, 1}, {1.4142f, 1.4142f, 0, 0.7071f}, {0, 2, 0, 1}};

static GLUnurbs *nurbs(GLfloat method, GLfloat tolerance, GLfloat step, int normals) {
    GLUnurbs *n = gluNewNurbsRenderer();
    gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(n, GLU_SAMPLING_METHOD, method);
    gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gluNurbsProperty(n, GLU_PARAMETRIC_TOLERANCE, tolerance);
    gluNurbsProperty(n, GLU_U_STEP, step);
    gluNurbsProperty(n, GLU_V_STEP, step);
    gluNurbsCallback(n, GLU_NURBS_BEGIN, (void (*)(void))begin_cb);
    gluNurbsCallback(n, GLU_NURBS_VERTEX, (void (*)(void))vertex_cb);
    if (normals) gluNurbsCallback(n, GLU_NURBS_NORMAL, (void (*)(void))normal_cb);
    gluNurbsCallback(n, GLU_NURBS_END, (void (*)(void))end_cb);
    return n;
}

/* Each case starts from the same view: a 500x500 window, gluPerspective(45, 1, 3, 8), the
   model 5 units away, turned 330 degrees about x and halved, as surface.c draws its hill. */
static void view(void) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 1.0, 3.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glRotatef(330, 1, 0, 0);
    glScalef(0.5f, 0.5f, 0.5f);
}

enum shape { HILL, SHEET, CYLINDER, TWIST };

/* Trim loops. Each case's name starts with the shape, then the trim: hillhole, sheethole... */
enum trim { NONE, HOLE, ISLAND, NOTCH, DIAMOND, REDBOOK };

static void pwl_loop(GLUnurbs *n, int count, GLfloat *pts) {
    gluBeginTrim(n);
    gluPwlCurve(n, count, pts, 2, GLU_MAP1_TRIM_2);
    gluEndTrim(n);
}

/* The domain's border, counter-clockwise, from (a, a) to (b, b). */
static void border(GLUnurbs *n, GLfloat a, GLfloat b) {
    GLfloat pts[5][2] = {{a, a}, {b, a}, {b, b}, {a, b}, {a, a}};
    pwl_loop(n, 5, &pts[0][0]);
}

/* A clockwise square hole [a, b] x [c, d]. */
static void hole(GLUnurbs *n, GLfloat a, GLfloat b, GLfloat c, GLfloat d) {
    GLfloat pts[5][2] = {{a, c}, {a, d}, {b, d}, {b, c}, {a, c}};
    pwl_loop(n, 5, &pts[0][0]);
}

static void trims(GLUnurbs *n, enum trim t) {
    /* The Red Book's trim.c: a pwl border, then a hole of a cubic NURBS arc and a pwl arc. */
    static GLfloat curve_pt[4][2] = {{0.25f, 0.5f}, {0.25f, 0.75f}, {0.75f, 0.75f}, {0.75f, 0.5f}};
    static GLfloat pwl_pt[3][2] = {{0.75f, 0.5f}, {0.5f, 0.25f}, {0.25f, 0.5f}};
    static GLfloat notch[9][2] = {{0, 0}, {0.3f, 0}, {0.3f, 0.4f}, {0.7f, 0.4f}, {0.7f, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    static GLfloat diamond[5][2] = {{0.5f, 0.2f}, {0.2f, 0.5f}, {0.5f, 0.8f}, {0.8f, 0.5f}, {0.5f, 0.2f}};
    switch (t) {
    case NONE: break;
    case HOLE: border(n, 0, 1); hole(n, 0.25f, 0.75f, 0.25f, 0.75f); break;
    case ISLAND: border(n, 0, 1); hole(n, 0.2f, 0.8f, 0.2f, 0.8f); border(n, 0.4f, 0.6f); break;
    case NOTCH: pwl_loop(n, 9, &notch[0][0]); break;
    case DIAMOND: border(n, 0, 1); pwl_loop(n, 5, &diamond[0][0]); break;
    case REDBOOK:
        border(n, 0, 1);
        gluBeginTrim(n);
        gluNurbsCurve(n, 8, bezier_knots, 2, &curve_pt[0][0], 4, GLU_MAP1_TRIM_2);
        gluPwlCurve(n, 3, &pwl_pt[0][0], 2, GLU_MAP1_TRIM_2);
        gluEndTrim(n);
        break;
    }
}

static GLfloat display_mode = GLU_FILL;

static void trimmed(const char *name, enum shape s, enum trim t, GLfloat method, GLfloat tolerance, GLfloat step, int normals) {
    GLUnurbs *n = nurbs(method, tolerance, step, normals);
    gluNurbsProperty(n, GLU_DISPLAY_MODE, display_mode);
    printf("# %s %s\n", display_mode == GLU_OUTLINE_PATCH ? "outline" : "surface", name);
    view();
    gluBeginSurface(n);
    switch (s) {
    case HILL: gluNurbsSurface(n, 8, bezier_knots, 8, bezier_knots, 12, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3); break;
    case SHEET: gluNurbsSurface(n, 14, sheet_knots, 14, sheet_knots, 30, 3, &sheet[0][0][0], 4, 4, GL_MAP2_VERTEX_3); break;
    case CYLINDER: gluNurbsSurface(n, 6, cyl_uknots, 4, cyl_vknots, 8, 4, &cyl[0][0][0], 3, 2, GL_MAP2_VERTEX_4); break;
    case TWIST: gluNurbsSurface(n, 4, lin_knots, 4, lin_knots, 6, 3, &twist[0][0][0], 2, 2, GL_MAP2_VERTEX_3); break;
    }
    if (s == SHEET && t == HOLE) {
        border(n, 3, 10);
        hole(n, 4.5f, 8.2f, 5.3f, 7.5f);
    } else {
        trims(n, t);
    }
    gluEndSurface(n);
    gluDeleteNurbsRenderer(n);
}

static void surface(const char *name, enum shape s, GLfloat method, GLfloat tolerance, GLfloat step, int normals) {
    trimmed(name, s, NONE, method, tolerance, step, normals);
}

static void curve_case(const char *name, int rational, GLfloat method, GLfloat tolerance, GLfloat step) {
    GLUnurbs *n = nurbs(method, tolerance, step, 0);
    printf("# curve %s\n", name);
    view();
    gluBeginCurve(n);
    if (rational) gluNurbsCurve(n, 6, arc_knots, 4, &arc[0][0], 3, GL_MAP1_VERTEX_4);
    else gluNurbsCurve(n, 12, curve_knots, 3, &curve[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(n);
    gluDeleteNurbsRenderer(n);
}

int main(void) {
    static GLubyte buf[500 * 500 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 500, 500);
    glViewport(0, 0, 500, 500);
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * (u - 1.5f);
            hill[u][v][1] = 2.0f * (v - 1.5f);
            hill[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 3.0f : -3.0f;
        }
    for (int i = 0; i < 14; i++) sheet_knots[i] = (GLfloat)i;
    for (int i = 0; i < 10; i++)
        for (int j = 0; j < 10; j++) {
            sheet[i][j][0] = -3.0f + i * (2.0f / 3.0f);
            sheet[i][j][1] = -3.0f + j * (2.0f / 3.0f);
            sheet[i][j][2] = ((i * 3 + j * 5) % 7) / 3.5f - 1.0f;
        }
    surface("hill_path_length_25", HILL, GLU_PATH_LENGTH, 25, 100, 1);
    surface("hill_path_length_50", HILL, GLU_PATH_LENGTH, 50, 100, 1);
    surface("hill_path_length_120", HILL, GLU_PATH_LENGTH, 120, 100, 1);
    surface("hill_path_length_400", HILL, GLU_PATH_LENGTH, 400, 100, 1);
    surface("hill_path_length_12", HILL, GLU_PATH_LENGTH, 12, 100, 0);
    surface("hill_parametric_error_0.5", HILL, GLU_PARAMETRIC_ERROR, 0.5f, 100, 1);
    surface("hill_parametric_error_4", HILL, GLU_PARAMETRIC_ERROR, 4, 100, 0);
    surface("hill_object_path_length_1", HILL, GLU_OBJECT_PATH_LENGTH, 1, 100, 1);
    surface("hill_object_parametric_error_0.1", HILL, GLU_OBJECT_PARAMETRIC_ERROR, 0.1f, 100, 0);
    surface("hill_domain_distance_6", HILL, GLU_DOMAIN_DISTANCE, 50, 6, 1);
    surface("hill_domain_distance_9", HILL, GLU_DOMAIN_DISTANCE, 50, 9, 0);
    surface("sheet_domain_distance_3", SHEET, GLU_DOMAIN_DISTANCE, 50, 3, 0);
    surface("sheet_path_length_60", SHEET, GLU_PATH_LENGTH, 60, 100, 1);
    surface("sheet_path_length_12", SHEET, GLU_PATH_LENGTH, 12, 100, 0);
    surface("cylinder_parametric_error_0.01", CYLINDER, GLU_PARAMETRIC_ERROR, 0.01f, 100, 1);
    surface("cylinder_path_length_20", CYLINDER, GLU_PATH_LENGTH, 20, 100, 1);
    surface("twist_path_length_30", TWIST, GLU_PATH_LENGTH, 30, 100, 1);
    trimmed("hillhole_path_length_25", HILL, HOLE, GLU_PATH_LENGTH, 25, 100, 1);
    trimmed("hillhole_path_length_120", HILL, HOLE, GLU_PATH_LENGTH, 120, 100, 0);
    trimmed("hillhole_parametric_error_0.5", HILL, HOLE, GLU_PARAMETRIC_ERROR, 0.5f, 100, 1);
    trimmed("hillhole_domain_distance_6", HILL, HOLE, GLU_DOMAIN_DISTANCE, 50, 6, 1);
    trimmed("hillhole_domain_distance_3", HILL, HOLE, GLU_DOMAIN_DISTANCE, 50, 3, 0);
    trimmed("hillisland_path_length_25", HILL, ISLAND, GLU_PATH_LENGTH, 25, 100, 1);
    trimmed("hillnotch_path_length_25", HILL, NOTCH, GLU_PATH_LENGTH, 25, 100, 1);
    trimmed("hilldiamond_path_length_25", HILL, DIAMOND, GLU_PATH_LENGTH, 25, 100, 1);
    trimmed("hillredbook_path_length_25", HILL, REDBOOK, GLU_PATH_LENGTH, 25, 100, 1);
    trimmed("hillredbook_domain_distance_6", HILL, REDBOOK, GLU_DOMAIN_DISTANCE, 50, 6, 0);
    trimmed("sheethole_path_length_60", SHEET, HOLE, GLU_PATH_LENGTH, 60, 100, 1);
    trimmed("sheethole_domain_distance_3", SHEET, HOLE, GLU_DOMAIN_DISTANCE, 50, 3, 0);
    display_mode = GLU_OUTLINE_PATCH;
    surface("hill_path_length_25", HILL, GLU_PATH_LENGTH, 25, 100, 0);
    surface("hill_domain_distance_6", HILL, GLU_DOMAIN_DISTANCE, 50, 6, 0);
    surface("sheet_path_length_60", SHEET, GLU_PATH_LENGTH, 60, 100, 0);
    trimmed("hillredbook_path_length_25", HILL, REDBOOK, GLU_PATH_LENGTH, 25, 100, 0);
    trimmed("sheethole_path_length_60", SHEET, HOLE, GLU_PATH_LENGTH, 60, 100, 0);
    display_mode = GLU_FILL;
    curve_case("bspline_path_length_20", 0, GLU_PATH_LENGTH, 20, 100);
    curve_case("bspline_parametric_error_2", 0, GLU_PARAMETRIC_ERROR, 2, 100);
    curve_case("bspline_domain_distance_4", 0, GLU_DOMAIN_DISTANCE, 50, 4);
    curve_case("arc_path_length_10", 1, GLU_PATH_LENGTH, 10, 100);
    OSMesaDestroyContext(c);
    return 0;
}
