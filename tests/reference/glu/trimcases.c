/* Trimmed surfaces whose loops take GLU's rarer ways through sampleMonoPoly (thin regions on a
   two-line grid, convex loops, interior cusps that need a diagonal, several cusps split by
   monoPolyPart): loops along the border, triangular, thin and star-shaped holes, pieces of pwl
   and NURBS curves meeting at cusps, a B-spline outer loop around a pwl circle, under coarse and
   fine samplings. Each case prints its inputs first ("@" lines: the surface and its sampling,
   then every trim loop's curves, floats to 9 significant digits), then what GLU hands to the
   GLU_NURBS_TESSELLATOR callbacks as surfpoints.c prints it. tests/it/glu_trimcases.rs reads
   the inputs, draws them with gleval and compares the text. `trimcases random SEED COUNT`
   prints random cases instead (holes inside the border, some with vertices rounded to a grid),
   for GLEVAL_TRIMCASES=FILE cargo test --test it glu_trimcases: seeds 1 to 6, 300 cases each,
   all match where GLU draws (it draws nothing, and reports nothing, where rounding made a hole
   touch the border or itself; gleval reports GLU's error 28 or 29 there).
   Build: cc trimcases.c -lOSMesa -lGLU -lGL -lm */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

static void begin_cb(GLenum t) {
    const char *n = t == GL_TRIANGLE_FAN ? "GL_TRIANGLE_FAN" : t == GL_QUAD_STRIP ? "GL_QUAD_STRIP"
        : t == GL_TRIANGLE_STRIP ? "GL_TRIANGLE_STRIP" : t == GL_TRIANGLES ? "GL_TRIANGLES"
        : t == GL_LINE_STRIP ? "GL_LINE_STRIP" : t == GL_LINE_LOOP ? "GL_LINE_LOOP" : "?";
    printf("glBegin(%s)\n", n);
}
static void normal_cb(GLfloat *v) { printf("glNormal3f (%.3f, %.3f, %.3f)\n", v[0], v[1], v[2]); }
static void color_cb(GLfloat *v) { printf("glColor4f (%.3f, %.3f, %.3f, %.3f)\n", v[0], v[1], v[2], v[3]); }
static void vertex_cb(GLfloat *v) { printf("glVertex3f (%.3f, %.3f, %.3f)\n", v[0], v[1], v[2]); }
static void end_cb(void) { printf("glEnd()\n"); }
static void error_cb(GLenum e) { printf("error %u\n", e); }

/* The Red Book hill (bicubic Bezier on [0, 1]^2), a quarter cylinder (quadratic in u, linear
   in v, rational) and a bicubic B-spline sheet of 2 x 2 spans on [3, 5]^2. */
static GLfloat hill[4][4][3];
static GLfloat bezier_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static GLfloat cyl_uknots[6] = {0, 0, 0, 1, 1, 1}, lin_knots[4] = {0, 0, 1, 1};
static GLfloat cyl[3][2][4] = {{{1, 0, -1, 1}, {1, 0, 1, 1}},
                               {{0.7071f, 0.7071f, -0.7071f, 0.7071f}, {0.7071f, 0.7071f, 0.7071f, 0.7071f}},
                               {{0, 1, -1, 1}, {0, 1, 1, 1}}};
static GLfloat sheet_knots[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8}, sheet[5][5][3];
/* A bilinear colour map over [0, 1]^2. */
static GLfloat colours[2][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}}, {{0, 0, 1, 1}, {1, 1, 0, 0.5f}}};

static GLUnurbs *n;

static void print_floats(const GLfloat *p, int count) {
    for (int i = 0; i < count; i++) printf(" %.9g", p[i]);
}

/* A case: its name, the surface, the sampling, the callbacks, the display mode. */
static void begin_case(const char *name, const char *shape, const char *method, GLfloat tolerance, GLfloat step,
                       int viewport, int normals, int colour, int outline) {
    GLenum m = method[0] == 'p' ? GLU_PATH_LENGTH : GLU_DOMAIN_DISTANCE;
    printf("# %s\n", name);
    printf("@ surface %s %s %.9g %.9g viewport %d normals %d colour %d outline %d\n", shape, method, tolerance, step,
           viewport, normals, colour, outline);
    glViewport(0, 0, viewport, viewport);
    n = gluNewNurbsRenderer();
    gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(n, GLU_SAMPLING_METHOD, m);
    gluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, tolerance);
    gluNurbsProperty(n, GLU_U_STEP, step);
    gluNurbsProperty(n, GLU_V_STEP, step);
    gluNurbsProperty(n, GLU_DISPLAY_MODE, outline ? GLU_OUTLINE_POLYGON : GLU_FILL);
    gluNurbsCallback(n, GLU_NURBS_BEGIN, (void (*)(void))begin_cb);
    gluNurbsCallback(n, GLU_NURBS_VERTEX, (void (*)(void))vertex_cb);
    if (normals) gluNurbsCallback(n, GLU_NURBS_NORMAL, (void (*)(void))normal_cb);
    if (colour) gluNurbsCallback(n, GLU_NURBS_COLOR, (void (*)(void))color_cb);
    gluNurbsCallback(n, GLU_NURBS_END, (void (*)(void))end_cb);
    gluNurbsCallback(n, GLU_NURBS_ERROR, (void (*)(void))error_cb);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, 1.0, 3.0, 8.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -5);
    glRotatef(330, 1, 0, 0);
    glScalef(0.5f, 0.5f, 0.5f);
    gluBeginSurface(n);
    if (shape[0] == 'h') gluNurbsSurface(n, 8, bezier_knots, 8, bezier_knots, 12, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    else if (shape[0] == 'c') gluNurbsSurface(n, 6, cyl_uknots, 4, lin_knots, 8, 4, &cyl[0][0][0], 3, 2, GL_MAP2_VERTEX_4);
    else gluNurbsSurface(n, 9, sheet_knots, 9, sheet_knots, 15, 3, &sheet[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    if (colour) gluNurbsSurface(n, 4, lin_knots, 4, lin_knots, 8, 4, &colours[0][0][0], 2, 2, GL_MAP2_COLOR_4);
}

static void end_case(void) {
    gluEndSurface(n);
    gluDeleteNurbsRenderer(n);
}

static void loop_begin(void) { printf("@ loop\n"); gluBeginTrim(n); }
static void loop_end(void) { gluEndTrim(n); }

/* The sheet's domain is [3, 5]^2: trims written for [0, 1]^2 are mapped there. */
static GLfloat offset = 0, scale = 1;

static void pwl(int count, const GLfloat *src) {
    GLfloat pts[128];
    for (int i = 0; i < 2 * count; i++) pts[i] = offset + scale * src[i];
    printf("@ pwl");
    print_floats(pts, 2 * count);
    printf("\n");
    gluPwlCurve(n, count, pts, 2, GLU_MAP1_TRIM_2);
}

/* A NURBS trim curve of `order` over `nknots` knots, its points (u, v) or (u, v, w). */
static void nurbs_trim(int nknots, const GLfloat *knots, int order, const GLfloat *src, int rational) {
    int dim = rational ? 3 : 2;
    GLfloat pts[128];
    for (int i = 0; i < nknots - order; i++) {
        GLfloat w = rational ? src[3 * i + 2] : 1;
        for (int c = 0; c < 2; c++) pts[dim * i + c] = offset * w + scale * src[dim * i + c];
        if (rational) pts[3 * i + 2] = w;
    }
    printf("@ nurbs %d %d", order, dim);
    print_floats(knots, nknots);
    printf(" :");
    print_floats(pts, dim * (nknots - order));
    printf("\n");
    gluNurbsCurve(n, nknots, (GLfloat *)knots, dim, pts, order, rational ? GLU_MAP1_TRIM_3 : GLU_MAP1_TRIM_2);
}

/* A closed pwl loop through `count` points (the first repeated at the end). */
static void polygon(int count, const GLfloat (*p)[2]) {
    GLfloat pts[64][2];
    for (int i = 0; i < count; i++) { pts[i][0] = p[i][0]; pts[i][1] = p[i][1]; }
    pts[count][0] = p[0][0];
    pts[count][1] = p[0][1];
    loop_begin();
    pwl(count + 1, &pts[0][0]);
    loop_end();
}

/* The domain's border [a, b]^2, counter-clockwise. */
static void border(GLfloat a, GLfloat b) {
    GLfloat p[4][2] = {{a, a}, {b, a}, {b, b}, {a, b}};
    polygon(4, p);
}

/* A regular polygon (a circle of `count` sides), clockwise when `hole`, radii alternating
   between r and r2 (a star when they differ). */
static void star(GLfloat cu, GLfloat cv, GLfloat r, GLfloat r2, int count, int hole, GLfloat turn) {
    GLfloat p[64][2];
    for (int i = 0; i < count; i++) {
        double a = turn + (hole ? -1 : 1) * 2 * PI * i / count;
        GLfloat rr = (i % 2) ? r2 : r;
        p[i][0] = cu + rr * (GLfloat)cos(a);
        p[i][1] = cv + rr * (GLfloat)sin(a);
    }
    polygon(count, p);
}

/* An outer loop of four pieces: pwl along the bottom, a cubic NURBS line up the right edge,
   pwl along the top, and a cubic NURBS arc bulging into the domain from (0, 1) to (0, 0). */
static void three_edges(GLfloat bulge) {
    static GLfloat bottom[3][2] = {{0, 0}, {0.5f, 0}, {1, 0}};
    static GLfloat right[4][2] = {{1, 0}, {1, 0.3f}, {1, 0.6f}, {1, 1}};
    static GLfloat top[2][2] = {{1, 1}, {0, 1}};
    GLfloat left[4][2] = {{0, 1}, {bulge, 0.7f}, {bulge, 0.3f}, {0, 0}};
    loop_begin();
    pwl(3, &bottom[0][0]);
    nurbs_trim(8, bezier_knots, 4, &right[0][0], 0);
    pwl(2, &top[0][0]);
    nurbs_trim(8, bezier_knots, 4, &left[0][0], 0);
    loop_end();
}

/* The textbook's trimmed surface: a closed cubic B-spline outer loop and a pwl circle hole. */
static void textbook(void) {
    static GLfloat knots[13] = {0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 6, 6, 6};
    static GLfloat pts[9][2] = {{0.5f, 0.02f}, {0.95f, 0.02f}, {0.98f, 0.5f}, {0.98f, 0.98f}, {0.5f, 0.98f},
                                {0.02f, 0.98f}, {0.02f, 0.5f}, {0.02f, 0.02f}, {0.5f, 0.02f}};
    loop_begin();
    nurbs_trim(13, knots, 4, &pts[0][0], 0);
    loop_end();
    star(0.5f, 0.5f, 0.2f, 0.2f, 20, 1, 0);
}

/* A rational quadratic full circle (four quarter arcs) as a hole, clockwise. */
static void rational_circle(GLfloat cu, GLfloat cv, GLfloat r) {
    static GLfloat knots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    GLfloat w = 0.70710678f;
    GLfloat d[9][2] = {{1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}, {1, 0}};
    GLfloat pts[9][3];
    for (int i = 0; i < 9; i++) {
        GLfloat wi = (i % 2) ? w : 1;
        pts[i][0] = (cu + r * d[i][0]) * wi;
        pts[i][1] = (cv + r * d[i][1]) * wi;
        pts[i][2] = wi;
    }
    loop_begin();
    nurbs_trim(12, knots, 3, &pts[0][0], 1);
    loop_end();
}

/* A sawtooth outer loop: the bottom edge a row of `teeth` teeth of height h (cusps pointing
   down and up), the rest the border. */
static void sawtooth(int teeth, GLfloat h) {
    GLfloat p[64][2];
    int k = 0;
    for (int i = 0; i < teeth; i++) {
        p[k][0] = (GLfloat)i / teeth;
        p[k++][1] = 0;
        p[k][0] = (i + 0.5f) / teeth;
        p[k++][1] = h;
    }
    p[k][0] = 1;
    p[k++][1] = 0;
    p[k][0] = 1;
    p[k++][1] = 1;
    p[k][0] = 0;
    p[k++][1] = 1;
    polygon(k, p);
}

/* A comb hole: a bar along u with `teeth` teeth hanging down (clockwise). */
static void comb(GLfloat u0, GLfloat u1, GLfloat v0, GLfloat v1, GLfloat depth, int teeth) {
    GLfloat p[64][2];
    int k = 0;
    /* clockwise: along the top, down the right, back along the bottom with its teeth */
    p[k][0] = u0; p[k++][1] = v1;
    p[k][0] = u1; p[k++][1] = v1;
    p[k][0] = u1; p[k++][1] = v0;
    for (int i = teeth - 1; i >= 0; i--) {
        GLfloat a = u0 + (u1 - u0) * i / teeth, b = u0 + (u1 - u0) * (i + 1) / teeth;
        p[k][0] = (a + b) / 2; p[k++][1] = v0 - depth;
        p[k][0] = a; p[k++][1] = v0;
    }
    polygon(k, p);
}

/* The random polygon of the seed: `count` vertices at random radii (a hole, clockwise). */
static unsigned seed_state;
static GLfloat rnd(void) {
    seed_state = seed_state * 1103515245u + 12345u;
    return (GLfloat)((seed_state >> 8) & 0xffff) / 65536.0f;
}
static GLfloat snap; /* random cases: hole vertices rounded to multiples of this, when set */
static void random_hole(unsigned seed, int count, GLfloat cu, GLfloat cv, GLfloat rmin, GLfloat rmax) {
    GLfloat p[64][2];
    seed_state = seed;
    for (int i = 0; i < count; i++) {
        double a = -2 * PI * (i + 0.8 * rnd()) / count;
        GLfloat r = rmin + (rmax - rmin) * rnd();
        p[i][0] = cu + r * (GLfloat)cos(a);
        p[i][1] = cv + r * (GLfloat)sin(a);
        if (snap > 0) {
            p[i][0] = snap * roundf(p[i][0] / snap);
            p[i][1] = snap * roundf(p[i][1] / snap);
        }
    }
    polygon(count, p);
}

/* Samplings: GLU_PATH_LENGTH in pixels of a 500 (or 200) pixel square viewport, or
   GLU_DOMAIN_DISTANCE steps per unit of u and v. */
struct sampling { const char *name, *method; GLfloat tolerance, step; int viewport; };
static const struct sampling
    pl20s = {"pl20v200", "path_length", 20, 100, 200}, pl25s = {"pl25v200", "path_length", 25, 100, 200},
    pl20 = {"pl20", "path_length", 20, 100, 500}, pl25 = {"pl25", "path_length", 25, 100, 500},
    pl100 = {"pl100", "path_length", 100, 100, 500},
    dd3 = {"dd3", "domain_distance", 50, 3, 500}, dd5 = {"dd5", "domain_distance", 50, 5, 500},
    dd9 = {"dd9", "domain_distance", 50, 9, 500}, dd10 = {"dd10", "domain_distance", 50, 10, 500};
static const struct sampling *sweep[] = {&pl100, &dd3, &dd5, &dd9};
static const struct sampling *wide[] = {&pl20s, &pl25s, &pl20, &pl25, &pl100, &dd3, &dd5, &dd9};
static const struct sampling *issue[] = {&pl20s, &pl25s, &pl100, &dd3, &dd5};
#define COUNT(a) (int)(sizeof a / sizeof a[0])

enum kind { TRI_HOLE, TRI_HOLE2, THREE_EDGES, TEXTBOOK, THIN_TRI, THIN_BAR, STAR, SAWTOOTH, COMB, CIRCLE, RANDOM1,
            RANDOM2, RANDOM3, OVERCOVER, NKINDS };
static const char *kind_names[NKINDS] = {"trihole", "trihole2", "threeedges", "textbook", "thintri", "thinbar", "star",
                                         "sawtooth", "comb", "circle", "random1", "random2", "random3",
                                         "overcover"};

static void trims(enum kind k) {
    static GLfloat tri[3][2] = {{0.3f, 0.3f}, {0.45f, 0.72f}, {0.7f, 0.35f}};
    static GLfloat tri2[3][2] = {{0.2f, 0.6f}, {0.8f, 0.75f}, {0.55f, 0.2f}};
    static GLfloat tri3[3][2] = {{0.35f, 0.3f}, {0.5f, 0.65f}, {0.65f, 0.3f}};
    static GLfloat thin[3][2] = {{0.15f, 0.5f}, {0.85f, 0.53f}, {0.85f, 0.5f}};
    static GLfloat bar[4][2] = {{0.2f, 0.3f}, {0.75f, 0.72f}, {0.78f, 0.69f}, {0.23f, 0.27f}};
    /* A ten-point star hole (found by tests/it/glu_tessellation.rs's random holes) that GLU,
       under ten steps per unit, covers in part: its triangles' area is 0.97665, not the 0.97420
       of the square less the hole. gleval draws GLU's triangles, so the closed form is not the
       test there. */
    static GLfloat overcover[10][2] = {{0.36444646f, 0.3f}, {0.47289985f, 0.17438093f}, {0.31991506f, 0.23870781f},
                                       {0.28008497f, 0.23870781f}, {0.24786174f, 0.26211935f}, {0.23555358f, 0.3f},
                                       {0.24786176f, 0.33788067f}, {0.280085f, 0.3612922f},
                                       {0.33570048f, 0.40987468f}, {0.4439951f, 0.40461856f}};
    switch (k) {
    case TRI_HOLE: border(0, 1); polygon(3, tri); break;
    case TRI_HOLE2: border(0, 1); polygon(3, tri2); break;
    case THREE_EDGES: three_edges(0.25f); polygon(3, tri3); break;
    case TEXTBOOK: textbook(); break;
    case THIN_TRI: border(0, 1); polygon(3, thin); break;
    case THIN_BAR: border(0, 1); polygon(4, bar); break;
    case STAR: border(0, 1); star(0.5f, 0.5f, 0.35f, 0.15f, 10, 1, 0.3f); break;
    case SAWTOOTH: sawtooth(5, 0.2f); star(0.5f, 0.6f, 0.2f, 0.08f, 8, 1, 0.1f); break;
    case COMB: border(0, 1); comb(0.15f, 0.85f, 0.45f, 0.6f, 0.25f, 4); break;
    case CIRCLE: border(0, 1); rational_circle(0.5f, 0.5f, 0.3f); break;
    case RANDOM1: border(0, 1); random_hole(1, 12, 0.5f, 0.5f, 0.1f, 0.4f); break;
    case RANDOM2: border(0, 1); random_hole(7, 20, 0.5f, 0.5f, 0.15f, 0.45f); break;
    case RANDOM3: border(0, 1); random_hole(23, 7, 0.45f, 0.55f, 0.05f, 0.4f); break;
    case OVERCOVER: border(0, 1); polygon(10, overcover); break;
    default: break;
    }
}

static void run(enum kind k, const char *shape, const struct sampling *s, int normals, int colour, int outline) {
    char name[128];
    snprintf(name, sizeof name, "%s_%s_%s%s%s%s", kind_names[k], shape, s->name, normals ? "_n" : "",
             colour ? "_c" : "", outline ? "_o" : "");
    begin_case(name, shape, s->method, s->tolerance, s->step, s->viewport, normals, colour, outline);
    offset = shape[0] == 's' ? 3 : 0;
    scale = shape[0] == 's' ? 2 : 1;
    trims(k);
    end_case();
}

/* `trimcases random SEED COUNT`: COUNT random cases (random holes and stars under random
   samplings) instead of the fixed ones, for searching wider than the committed cases. */
static void random_cases(unsigned seed, int count) {
    static const char *shapes[3] = {"hill", "cylinder", "sheet"};
    for (int i = 0; i < count; i++) {
        char name[64];
        struct sampling s;
        seed_state = seed * 7919u + (unsigned)i * 104729u;
        rnd();
        int dd = rnd() < 0.5f;
        s.method = dd ? "domain_distance" : "path_length";
        s.tolerance = dd ? 50 : 15 + 135 * rnd();
        s.step = dd ? 2 + (int)(12 * rnd()) : 100;
        s.viewport = 500;
        const char *shape = shapes[(int)(3 * rnd()) % 3];
        int holes = 1 + (rnd() < 0.3f);
        unsigned seeds[2];
        int counts[2];
        GLfloat cu[2], cv[2], rmin[2], rmax[2];
        for (int h = 0; h < holes; h++) {
            seeds[h] = (unsigned)(rnd() * 1000000);
            counts[h] = 3 + (int)(18 * rnd());
            GLfloat r = 0.05f + 0.25f * rnd();
            cu[h] = holes == 1 ? 0.3f + 0.4f * rnd() : 0.27f + 0.46f * h;
            cv[h] = 0.3f + 0.4f * rnd();
            rmax[h] = holes == 1 ? r + 0.1f : 0.2f;
            rmin[h] = rmax[h] * rnd();
            /* inside the domain: GLU draws nothing, and reports nothing, for a hole across the border */
            GLfloat room = fminf(fminf(cu[h], 1 - cu[h]), fminf(cv[h], 1 - cv[h])) - 0.02f;
            if (rmax[h] > room) rmax[h] = room;
            if (rmin[h] > rmax[h]) rmin[h] = rmax[h];
        }
        snap = rnd() < 0.4f ? 1.0f / (GLfloat)(2 + (int)(16 * rnd())) : 0;
        snprintf(name, sizeof name, "random_%u_%d", seed, i);
        s.name = name;
        begin_case(name, shape, s.method, s.tolerance, s.step, s.viewport, 0, 0, 0);
        offset = shape[0] == 's' ? 3 : 0;
        scale = shape[0] == 's' ? 2 : 1;
        border(0, 1);
        for (int h = 0; h < holes; h++) random_hole(seeds[h], counts[h], cu[h], cv[h], rmin[h], rmax[h]);
        end_case();
        snap = 0;
    }
}

int main(int argc, char **argv) {
    static GLubyte buf[500 * 500 * 4];
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 500, 500);
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * (u - 1.5f);
            hill[u][v][1] = 2.0f * (v - 1.5f);
            hill[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 3.0f : -3.0f;
        }
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            sheet[i][j][0] = -3.0f + i * 1.5f;
            sheet[i][j][1] = -3.0f + j * 1.5f;
            sheet[i][j][2] = ((i * 3 + j * 5) % 7) / 3.5f - 1.0f;
        }
    if (argc == 4) {
        random_cases((unsigned)atoi(argv[2]), atoi(argv[3]));
        OSMesaDestroyContext(c);
        return 0;
    }
    for (int k = 0; k < NKINDS; k++)
        for (int i = 0; i < COUNT(sweep); i++) run((enum kind)k, "hill", sweep[i], 0, 0, 0);
    /* The cylinder (linear in v) and the sheet (2 x 2 patches) under coarse and fine samplings. */
    for (int i = 0; i < COUNT(wide); i++) {
        run(TRI_HOLE, "cylinder", wide[i], 0, 0, 0);
        run(STAR, "cylinder", wide[i], 0, 0, 0);
        run(COMB, "cylinder", wide[i], 0, 0, 0);
        run(TRI_HOLE, "sheet", wide[i], 0, 0, 0);
        run(STAR, "sheet", wide[i], 0, 0, 0);
        run(RANDOM2, "sheet", wide[i], 0, 0, 0);
    }
    /* The issue's kinds: a triangular hole with a colour map (and normals), the three-edge
       loop with a colour map, at path lengths of 20 to 25 pixels; the textbook program's
       outlined polygons at 100 pixels. */
    for (int i = 0; i < COUNT(issue); i++) {
        run(TRI_HOLE, "hill", issue[i], 1, 1, 0);
        run(THREE_EDGES, "hill", issue[i], 0, 1, 0);
    }
    run(TEXTBOOK, "hill", &pl100, 0, 0, 1);
    run(TEXTBOOK, "hill", &pl100, 1, 0, 1);
    run(OVERCOVER, "hill", &dd10, 0, 0, 0);
    OSMesaDestroyContext(c);
    return 0;
}
