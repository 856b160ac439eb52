/* Prints every GL call real GLU's quadrics (quad.c) make: glBegin, glEnd, glNormal3f,
   glTexCoord2f, glVertex3f, each float as its 32 bits in hex, and every error the GLU_ERROR
   callback receives. This program defines those five GL functions itself, so libGLU's calls
   land here (the executable's symbols come first in the dynamic linker's lookup) and no GL
   context is needed. tests/it/glu_quadrics.rs runs each case (a "Q" or "C" line, doubles as
   their 64 bits in hex) through gleval and must print the same lines.
   Build: cc quadrics.c -lGLU -lGL -lm */
#include <GL/glu.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* Set where quad.c reads a normal cache it did not fill (GLU_FLAT with GLU_POINT or
   GLU_SILHOUETTE; a sphere's south-pole normal when stacks > slices): those normals are
   whatever was on the stack, so they print as "N ?". */
static int undefined_normals;

static unsigned bits(GLfloat f) {
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

static unsigned long long dbits(GLdouble d) {
    uint64_t u;
    memcpy(&u, &d, 8);
    return (unsigned long long)u;
}

void glBegin(GLenum mode) { printf("B %u\n", mode); }
void glEnd(void) { printf("E\n"); }
void glNormal3f(GLfloat x, GLfloat y, GLfloat z) {
    if (undefined_normals) printf("N ?\n");
    else printf("N %08x %08x %08x\n", bits(x), bits(y), bits(z));
}
void glTexCoord2f(GLfloat s, GLfloat t) { printf("T %08x %08x\n", bits(s), bits(t)); }
void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { printf("V %08x %08x %08x\n", bits(x), bits(y), bits(z)); }

static void error_cb(GLenum code) { printf("ERR %u\n", code); }

static const GLenum styles[] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
static const GLenum normal_modes[] = {GLU_NONE, GLU_FLAT, GLU_SMOOTH};
static const GLenum orientations[] = {GLU_OUTSIDE, GLU_INSIDE};

enum kind { SPHERE, CYLINDER, DISK, PARTIAL };
static const char *kind_names[] = {"sphere", "cylinder", "disk", "partialdisk"};

struct params {
    enum kind kind;
    GLdouble a, b, c, d, e; /* radius / base, top, height / inner, outer / start, sweep */
    GLint n1, n2;           /* slices, stacks or loops */
};

static void draw(GLUquadric *q, const struct params *p) {
    switch (p->kind) {
    case SPHERE: gluSphere(q, p->a, p->n1, p->n2); break;
    case CYLINDER: gluCylinder(q, p->a, p->b, p->c, p->n1, p->n2); break;
    case DISK: gluDisk(q, p->a, p->b, p->n1, p->n2); break;
    case PARTIAL: gluPartialDisk(q, p->a, p->b, p->n1, p->n2, p->d, p->e); break;
    }
}

static int normals_undefined(const struct params *p, GLenum style, GLenum normals) {
    int flat_unfilled = normals == GLU_FLAT && (style == GLU_POINT || style == GLU_SILHOUETTE);
    int clamp = 239;
    int slices = p->n1 > clamp ? clamp : p->n1, stacks = p->n2 > clamp ? clamp : p->n2;
    switch (p->kind) {
    case SPHERE:
        return flat_unfilled || (normals == GLU_SMOOTH && style == GLU_FILL && stacks > slices);
    case CYLINDER: return flat_unfilled;
    default: return 0;
    }
}

/* One case: a fresh quadric in the given modes draws the shape. */
static void run(const struct params *p, GLenum style, GLenum normals, GLenum orient, GLboolean tex) {
    GLUquadric *q = gluNewQuadric();
    undefined_normals = normals_undefined(p, style, normals);
    printf("Q %s %u %u %u %u %016llx %016llx %016llx %016llx %016llx %d %d %d\n", kind_names[p->kind], style,
           normals, orient, tex, dbits(p->a), dbits(p->b), dbits(p->c), dbits(p->d), dbits(p->e), p->n1, p->n2,
           undefined_normals);
    gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)error_cb);
    gluQuadricDrawStyle(q, style);
    gluQuadricNormals(q, normals);
    gluQuadricOrientation(q, orient);
    gluQuadricTexture(q, tex);
    draw(q, p);
    gluDeleteQuadric(q);
}

static void every_mode(const struct params *p) {
    for (int s = 0; s < 4; s++)
        for (int n = 0; n < 3; n++)
            for (int o = 0; o < 2; o++)
                for (int t = 0; t < 2; t++) run(p, styles[s], normal_modes[n], orientations[o], (GLboolean)t);
}

static void some_modes(const struct params *p) {
    for (int s = 0; s < 4; s++) run(p, styles[s], GLU_SMOOTH, GLU_OUTSIDE, GL_TRUE);
    run(p, GLU_FILL, GLU_FLAT, GLU_INSIDE, GL_FALSE);
}

/* A setter with a bad (or good) value on a fresh quadric, then a small sphere that shows
   which modes it kept. */
static void setter(const char *name, GLenum value) {
    GLUquadric *q = gluNewQuadric();
    undefined_normals = 0;
    printf("C %s %u\n", name, value);
    gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)error_cb);
    if (!strcmp(name, "drawstyle")) gluQuadricDrawStyle(q, value);
    else if (!strcmp(name, "normals")) gluQuadricNormals(q, value);
    else if (!strcmp(name, "orientation")) gluQuadricOrientation(q, value);
    else if (!strcmp(name, "texture")) gluQuadricTexture(q, (GLboolean)value);
    else if (!strcmp(name, "callback")) gluQuadricCallback(q, value, (_GLUfuncptr)error_cb);
    gluSphere(q, 1.0, 3, 2);
    gluDeleteQuadric(q);
}

int main(void) {
    double nan = NAN, inf = INFINITY;
    /* Every mode on ordinary shapes. */
    struct params full[] = {
        {SPHERE, 1.0, 0, 0, 0, 0, 8, 6},
        {SPHERE, 0.75, 0, 0, 0, 0, 5, 3},
        {SPHERE, 2.5, 0, 0, 0, 0, 2, 1},
        {CYLINDER, 1.0, 0.5, 2.0, 0, 0, 7, 3},
        {CYLINDER, 0.0, 1.25, 1.5, 0, 0, 4, 1},
        {DISK, 0.5, 1.5, 0, 0, 0, 9, 3},
        {DISK, 0.0, 1.0, 0, 0, 0, 6, 2},
        {PARTIAL, 0.25, 1.0, 0, 30.0, 135.0, 5, 2},
        {PARTIAL, 0.0, 2.0, 0, -45.0, 270.0, 7, 3},
        {PARTIAL, 1.0, 1.0, 0, 10.0, 90.0, 4, 2},
    };
    for (unsigned i = 0; i < sizeof full / sizeof full[0]; i++) every_mode(&full[i]);

    /* Edge cases and errors in a few modes each. */
    struct params edges[] = {
        {SPHERE, 1.0, 0, 0, 0, 0, 4, 9},      /* stacks > slices */
        {SPHERE, 1.0, 0, 0, 0, 0, 300, 2},    /* slices clamped to 239 */
        {SPHERE, 1.0, 0, 0, 0, 0, 3, 400},    /* stacks clamped to 239 */
        {SPHERE, 0.0, 0, 0, 0, 0, 3, 2},      /* a point */
        {SPHERE, 3.0e7, 0, 0, 0, 0, 12, 10},  /* large */
        {SPHERE, 1.0, 0, 0, 0, 0, 1, 2},      /* errors */
        {SPHERE, 1.0, 0, 0, 0, 0, 3, 0},
        {SPHERE, -1.0, 0, 0, 0, 0, 3, 2},
        {SPHERE, 1.0, 0, 0, 0, 0, -5, -5},
        {SPHERE, nan, 0, 0, 0, 0, 3, 2},
        {SPHERE, inf, 0, 0, 0, 0, 3, 2},
        {CYLINDER, 1.0, 1.0, 1.0, 0, 0, 250, 2},
        {CYLINDER, 1.0, 0.0, 0.0, 0, 0, 5, 2}, /* a flat cone: height 0 */
        {CYLINDER, 0.0, 0.0, 0.0, 0, 0, 5, 2}, /* length 0: error */
        {CYLINDER, -1.0, 1.0, 1.0, 0, 0, 5, 2},
        {CYLINDER, 1.0, -1.0, 1.0, 0, 0, 5, 2},
        {CYLINDER, 1.0, 1.0, -1.0, 0, 0, 5, 2},
        {CYLINDER, 1.0, 1.0, 1.0, 0, 0, 1, 2},
        {CYLINDER, 1.0, 1.0, 1.0, 0, 0, 5, 0},
        {CYLINDER, nan, 1.0, 1.0, 0, 0, 3, 1},
        {CYLINDER, 1.0, 1.0, 1.0, 0, 0, 3, 7},
        {DISK, 1.0, 1.0, 0, 0, 0, 5, 2},       /* a circle */
        {DISK, 0.0, 1.0, 0, 0, 0, 3, 1},
        {DISK, 0.5, 1.0, 0, 0, 0, 500, 1},
        {DISK, 0.5, 0.0, 0, 0, 0, 5, 2},       /* errors */
        {DISK, -0.5, 1.0, 0, 0, 0, 5, 2},
        {DISK, 1.5, 1.0, 0, 0, 0, 5, 2},
        {DISK, 0.5, 1.0, 0, 0, 0, 1, 2},
        {DISK, 0.5, 1.0, 0, 0, 0, 5, 0},
        {DISK, 0.5, nan, 0, 0, 0, 5, 1},
        {PARTIAL, 0.5, 1.0, 0, 0.0, -90.0, 4, 2},   /* negative sweep */
        {PARTIAL, 0.5, 1.0, 0, 45.0, 400.0, 4, 1},  /* sweep clamped to 360 */
        {PARTIAL, 0.5, 1.0, 0, 45.0, -400.0, 4, 1}, /* below -360: 360 */
        {PARTIAL, 0.5, 1.0, 0, 45.0, 360.0, 4, 1},
        {PARTIAL, 0.5, 1.0, 0, 45.0, -360.0, 4, 1},
        {PARTIAL, 0.5, 1.0, 0, 45.0, 0.0, 4, 1},
        {PARTIAL, 0.0, 1.0, 0, 1000.0, 10.0, 3, 2},
        {PARTIAL, 0.5, 1.0, 0, nan, 90.0, 3, 1},
        {PARTIAL, 0.5, 1.0, 0, 0.0, nan, 3, 1},
        {PARTIAL, 0.5, 1.0, 0, 0.0, 90.0, 1, 1},
    };
    for (unsigned i = 0; i < sizeof edges / sizeof edges[0]; i++) some_modes(&edges[i]);

    /* Setters: GLU_INVALID_ENUM for a bad mode, which keeps the old one. */
    setter("drawstyle", GLU_POINT);
    setter("drawstyle", GLU_FILL + 100);
    setter("drawstyle", 0);
    setter("normals", GLU_NONE);
    setter("normals", GLU_FLAT);
    setter("normals", GLU_OUTSIDE);
    setter("orientation", GLU_INSIDE);
    setter("orientation", GLU_SMOOTH);
    setter("texture", 1);
    setter("texture", 2);
    setter("texture", 0);
    setter("callback", GLU_ERROR);
    setter("callback", GLU_TESS_ERROR);
    setter("callback", 0);
    return 0;
}
