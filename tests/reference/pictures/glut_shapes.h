/* glut_shapes.h: GLUT's solid and wire sphere, cube, cone and torus for the OSMesa GLUT stand-in,
 * drawing what freeglut 3.4 draws (its fg_geometry.c, read to learn its rules, not copied):
 * the same vertices in the same order, the same normals, the same primitives (triangle strips
 * for the round solids, triangles for the cube; line strips, lines and line loops for the
 * wires) and so the same winding. freeglut hands the GL client arrays and glDrawElements; this
 * stand-in sends the same vertices one by one between glBegin and glEnd, and, as drawing from
 * arrays leaves the current normal alone in Mesa, puts the current normal back afterwards.
 *
 * Checked against real freeglut 3.4 (Debian's freeglut3-dev) once, by hand, under Xvfb (not in CI):
 * Shapes.c built on <GL/glut.h> (a double-buffered window, the same Reshape and Display, the back
 * buffer read with glReadPixels) and on this stand-in: 0 of 204800 pixels differ; a second
 * program of odd arguments (3 slices and 2 stacks, a negative radius, size and height, a torus
 * of 2 sides, a one-slice wire cone, zero slices or stacks that draw nothing): 0 of 80000.
 * Both with tools/freeglut_check/check.sh [PROGRAM.c] (Shapes.c by default, OddShapes.c there). */

#include <math.h>
#include <stdlib.h>

/* n + 1 samples of a turn (half a turn if half) from angle 0: freeglut's circle table. A
 * negative n turns clockwise. The angle step is a float, each sample a double sine or cosine
 * rounded to float; the last sample closes the circle exactly. */
static void shapes_circle(float *s, float *c, int n, int half)
{
    int size = abs(n);
    float step = (half ? 1 : 2) * (float)M_PI / (float)(n == 0 ? 1 : n);
    s[0] = 0.0f;
    c[0] = 1.0f;
    for (int i = 1; i < size; i++) {
        s[i] = (float)sin(step * i);
        c[i] = (float)cos(step * i);
    }
    s[size] = half ? 0.0f : s[0];
    c[size] = half ? -1.0f : c[0];
}

static void shapes_vertex(const float n[3], const float v[3])
{
    glNormal3fv(n);
    glVertex3fv(v);
}

/* The sphere: point (stack i, slice j) from the top (i = 0, a pole) to the bottom (i = stacks,
 * the other pole), slices turning clockwise seen from +z. */
static void sphere_point(const float *s1, const float *c1, const float *s2, const float *c2, int stacks,
                         float radius, int i, int j, float n[3], float v[3])
{
    if (i == 0 || i == stacks) {
        n[0] = 0.0f, n[1] = 0.0f, n[2] = i == 0 ? 1.0f : -1.0f;
    } else {
        n[0] = c1[j] * s2[i], n[1] = s1[j] * s2[i], n[2] = c2[i];
    }
    for (int k = 0; k < 3; k++)
        v[k] = n[k] * radius;
    if (i == stacks)
        v[2] = -radius;
}

static void sphere(float radius, int slices, int stacks, int wire)
{
    if (slices < 1 || stacks < 2)
        return;
    float *s1 = malloc(sizeof(float) * (slices + 1)), *c1 = malloc(sizeof(float) * (slices + 1));
    float *s2 = malloc(sizeof(float) * (stacks + 1)), *c2 = malloc(sizeof(float) * (stacks + 1));
    float n[3], v[3];
    shapes_circle(s1, c1, -slices, 0);
    shapes_circle(s2, c2, stacks, 1);
#define P(i, j) (sphere_point(s1, c1, s2, c2, stacks, radius, (i), (j), n, v), shapes_vertex(n, v))
    if (wire) {
        for (int j = 0; j < slices; j++) { /* meridians from pole to pole */
            glBegin(GL_LINE_STRIP);
            for (int i = 0; i <= stacks; i++)
                P(i, j);
            glEnd();
        }
        for (int i = 1; i < stacks; i++) { /* parallels */
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < slices; j++)
                P(i, j);
            glEnd();
        }
    } else {
        for (int i = 0; i < stacks; i++) { /* one strip a band, lower point first */
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j <= slices; j++) {
                P(i + 1, j % slices);
                P(i, j % slices);
            }
            glEnd();
        }
    }
#undef P
    free(s1), free(c1), free(s2), free(c2);
}

/* The cone: its base on z = 0, its apex at z = height; point (ring i, slice j) on the side,
 * ring 0 the base's rim and ring stacks the apex, radius and height stepped in floats. */
static void cone_side(const float *s, const float *c, float base, float height, int stacks, int i, int j,
                      float n[3], float v[3])
{
    float z = 0.0f, r = base;
    float dz = height / (float)stacks, dr = base / (float)stacks;
    float cosn = (float)(height / sqrt(height * height + base * base));
    float sinn = (float)(base / sqrt(height * height + base * base));
    for (int k = 0; k < i; k++)
        z += dz, r -= dr;
    v[0] = c[j] * r, v[1] = s[j] * r, v[2] = z;
    n[0] = c[j] * cosn, n[1] = s[j] * cosn, n[2] = sinn;
}

static void cone(float base, float height, int slices, int stacks, int wire)
{
    if (slices < 1 || stacks < 1)
        return;
    float *s = malloc(sizeof(float) * (slices + 1)), *c = malloc(sizeof(float) * (slices + 1));
    float n[3], v[3];
    const float down[3] = {0.0f, 0.0f, -1.0f}, centre[3] = {0.0f, 0.0f, 0.0f};
    shapes_circle(s, c, -slices, 0);
#define S(i, j) (cone_side(s, c, base, height, stacks, (i), (j), n, v), shapes_vertex(n, v))
    if (wire) {
        glBegin(GL_LINES); /* one line a slice, rim to apex */
        for (int j = 0; j < slices; j++) {
            S(0, j);
            S(stacks, j);
        }
        glEnd();
        for (int i = 0; i < stacks; i++) { /* the rings below the apex */
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < slices; j++)
                S(i, j);
            glEnd();
        }
    } else {
        glBegin(GL_TRIANGLE_STRIP); /* the base, facing down */
        for (int j = 0; j <= slices; j++) {
            float rim[3] = {c[j % slices] * base, s[j % slices] * base, 0.0f};
            shapes_vertex(down, centre);
            shapes_vertex(down, rim);
        }
        glEnd();
        for (int i = 0; i < stacks; i++) { /* one strip a band, lower point first */
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j <= slices; j++) {
                S(i, j % slices);
                S(i + 1, j % slices);
            }
            glEnd();
        }
    }
#undef S
    free(s), free(c);
}

/* The torus around the z axis: point (ring j, side i), rings turning anticlockwise seen from +z,
 * sides clockwise around the tube. */
static void torus_point(const float *sp, const float *cp, const float *st, const float *ct, float inner,
                        float outer, int j, int i, float n[3], float v[3])
{
    float r = outer + ct[i] * inner;
    v[0] = cp[j] * r, v[1] = sp[j] * r, v[2] = st[i] * inner;
    n[0] = cp[j] * ct[i], n[1] = sp[j] * ct[i], n[2] = st[i];
}

static void torus(float inner, float outer, int sides, int rings, int wire)
{
    if (sides < 2 || rings < 2)
        return;
    float *sp = malloc(sizeof(float) * (rings + 1)), *cp = malloc(sizeof(float) * (rings + 1));
    float *st = malloc(sizeof(float) * (sides + 1)), *ct = malloc(sizeof(float) * (sides + 1));
    float n[3], v[3];
    shapes_circle(sp, cp, rings, 0);
    shapes_circle(st, ct, -sides, 0);
#define T(j, i) (torus_point(sp, cp, st, ct, inner, outer, (j), (i), n, v), shapes_vertex(n, v))
    if (wire) {
        for (int j = 0; j < rings; j++) { /* around the tube */
            glBegin(GL_LINE_LOOP);
            for (int i = 0; i < sides; i++)
                T(j, i);
            glEnd();
        }
        for (int i = 0; i < sides; i++) { /* around the axis */
            glBegin(GL_LINE_LOOP);
            for (int j = 0; j < rings; j++)
                T(j, i);
            glEnd();
        }
    } else {
        for (int i = 0; i < sides; i++) { /* one strip a side, all the way round */
            glBegin(GL_TRIANGLE_STRIP);
            for (int j = 0; j <= rings; j++) {
                T(j % rings, i);
                T(j % rings, (i + 1) % sides);
            }
            glEnd();
        }
    }
#undef T
    free(sp), free(cp), free(st), free(ct);
}

/* The cube: six faces, each its outward normal and four corners anticlockwise seen from
 * outside (signs of x, y, z times size / 2); solid as two triangles (0 1 2, 0 2 3) a face. */
static const signed char cube_faces[6][5][3] = {
    {{0, 0, 1}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}},
    {{1, 0, 0}, {1, 1, 1}, {1, -1, 1}, {1, -1, -1}, {1, 1, -1}},
    {{0, 1, 0}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}},
    {{-1, 0, 0}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, -1}, {-1, -1, 1}},
    {{0, -1, 0}, {-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
    {{0, 0, -1}, {1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
};

static void cube(float size, int wire)
{
    static const int order[2][6] = {{0, 1, 2, 0, 2, 3}, {0, 1, 2, 3}};
    for (int f = 0; f < 6; f++) {
        float n[3], v[4][3];
        for (int k = 0; k < 3; k++) {
            n[k] = cube_faces[f][0][k];
            for (int corner = 0; corner < 4; corner++)
                v[corner][k] = size * (0.5f * cube_faces[f][corner + 1][k]);
        }
        if (wire)
            glBegin(GL_LINE_LOOP);
        else if (f == 0)
            glBegin(GL_TRIANGLES);
        for (int k = 0; k < (wire ? 4 : 6); k++)
            shapes_vertex(n, v[order[wire][k]]);
        if (wire || f == 5)
            glEnd();
    }
}

/* Runs a shape and puts the current normal back as it was. */
#define KEEP_NORMAL(call)                                                                                    \
    do {                                                                                                     \
        float kept[4];                                                                                       \
        glGetFloatv(GL_CURRENT_NORMAL, kept);                                                                \
        call;                                                                                                \
        glNormal3fv(kept);                                                                                   \
    } while (0)

void glutSolidSphere(double radius, int slices, int stacks) { KEEP_NORMAL(sphere((float)radius, slices, stacks, 0)); }
void glutWireSphere(double radius, int slices, int stacks) { KEEP_NORMAL(sphere((float)radius, slices, stacks, 1)); }
void glutSolidCube(double size) { KEEP_NORMAL(cube((float)size, 0)); }
void glutWireCube(double size) { KEEP_NORMAL(cube((float)size, 1)); }
void glutSolidCone(double base, double height, int slices, int stacks)
{
    KEEP_NORMAL(cone((float)base, (float)height, slices, stacks, 0));
}
void glutWireCone(double base, double height, int slices, int stacks)
{
    KEEP_NORMAL(cone((float)base, (float)height, slices, stacks, 1));
}
void glutSolidTorus(double inner, double outer, int sides, int rings)
{
    KEEP_NORMAL(torus((float)inner, (float)outer, sides, rings, 0));
}
void glutWireTorus(double inner, double outer, int sides, int rings)
{
    KEEP_NORMAL(torus((float)inner, (float)outer, sides, rings, 1));
}
