/* interp.c - run a gleval "call script" against real Mesa (OSMesa) and print
 * what happens: the GL error after each call, query results and the
 * feedback-mode tokens.  The script and output formats are in FORMAT.md.
 *
 * Build: cc -std=c99 -O0 -o interp interp.c -lOSMesa -lGL -lm
 * Usage: interp SCRIPT.calls > SCRIPT.out
 */
#define _POSIX_C_SOURCE 200809L
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <stdarg.h>
#include "interp_arrays.h"

#define W 64
#define H 64
#define FB_SIZE (1 << 22)   /* feedback buffer, in floats */
#define MAX_TOK 4096

static OSMesaContext ctx;
/* Stencil and accumulation bits of the next context (`buffers S A`; a case resets them to 0). */
static int ctx_stencil, ctx_accum;
static GLubyte pixels[W * H * 4];
static GLfloat fb[FB_SIZE];
static int in_begin;        /* between a script `begin` and `end` */
static int defer_errors;    /* `defer_errors on`: only get_error reads the flag */
static int lineno;
static const char *script_name;

/* ---------------------------------------------------------------- enums */
struct enum_name { const char *name; GLenum value; };
#define E(x) { #x, x }
static const struct enum_name enums[] = {
    E(GL_TEXTURE_1D), E(GL_RGB), E(GL_RGBA), E(GL_LUMINANCE), E(GL_LUMINANCE_ALPHA), E(GL_ALPHA), E(GL_TEXTURE_MIN_FILTER), E(GL_TEXTURE_MAG_FILTER), E(GL_TEXTURE_WRAP_S), E(GL_TEXTURE_WRAP_T), E(GL_NEAREST), E(GL_LINEAR), E(GL_LINEAR_MIPMAP_LINEAR), E(GL_NEAREST_MIPMAP_NEAREST), E(GL_REPEAT), E(GL_CLAMP), E(GL_CLAMP_TO_EDGE), E(GL_TEXTURE_ENV), E(GL_TEXTURE_ENV_MODE), E(GL_TEXTURE_ENV_COLOR), E(GL_MODULATE), E(GL_DECAL), E(GL_BLEND), E(GL_REPLACE), E(GL_ADD), E(GL_UNPACK_ALIGNMENT), E(GL_UNPACK_ROW_LENGTH), E(GL_UNPACK_SKIP_ROWS), E(GL_PACK_ALIGNMENT), E(GL_TEXTURE_BINDING_1D), E(GL_TEXTURE_BINDING_2D),
    E(GL_SRC_ALPHA), E(GL_ONE_MINUS_SRC_ALPHA), E(GL_ONE), E(GL_ZERO), E(GL_SRC_ALPHA_SATURATE),
    E(GL_GREATER), E(GL_ALWAYS), E(GL_NEVER), E(GL_FOG_MODE), E(GL_FOG_DENSITY), E(GL_FOG_START),
    E(GL_FOG_END), E(GL_EXP), E(GL_EXP2), E(GL_ALPHA_TEST),
    E(GL_CURRENT_COLOR), E(GL_CURRENT_NORMAL), E(GL_CURRENT_TEXTURE_COORDS),
    E(GL_CURRENT_RASTER_POSITION), E(GL_CURRENT_RASTER_POSITION_VALID), E(GL_CURRENT_RASTER_COLOR),
    E(GL_CURRENT_RASTER_TEXTURE_COORDS), E(GL_CURRENT_RASTER_DISTANCE), E(GL_COLOR_INDEX), E(GL_STENCIL_INDEX),
    E(GL_DEPTH_COMPONENT), E(GL_RED), E(GL_GREEN), E(GL_BLUE), E(GL_BGR), E(GL_BGRA), E(GL_BITMAP),
    E(GL_UNSIGNED_SHORT_5_6_5), E(GL_UNSIGNED_SHORT_4_4_4_4), E(GL_UNSIGNED_BYTE_3_3_2),
    E(GL_UNSIGNED_INT_8_8_8_8_REV), E(GL_UNPACK_LSB_FIRST),
    E(GL_PERSPECTIVE_CORRECTION_HINT), E(GL_POINT_SMOOTH_HINT), E(GL_LINE_SMOOTH_HINT),
    E(GL_POLYGON_SMOOTH_HINT), E(GL_FOG_HINT), E(GL_DONT_CARE), E(GL_FASTEST), E(GL_NICEST), E(GL_HINT_BIT),
    E(GL_S), E(GL_T), E(GL_R), E(GL_Q), E(GL_TEXTURE_GEN_MODE), E(GL_OBJECT_PLANE), E(GL_EYE_PLANE),
    E(GL_OBJECT_LINEAR), E(GL_EYE_LINEAR), E(GL_SPHERE_MAP), E(GL_NORMAL_MAP), E(GL_REFLECTION_MAP),
    E(GL_TEXTURE_GEN_S), E(GL_TEXTURE_GEN_T), E(GL_TEXTURE_GEN_Q),
    E(GL_ENABLE_BIT), E(GL_EVAL_BIT), E(GL_CURRENT_BIT), E(GL_LIGHTING_BIT), E(GL_TEXTURE_BIT),
    E(GL_ALL_ATTRIB_BITS), E(GL_CULL_FACE), E(GL_DEPTH_TEST), E(GL_BLEND), E(GL_FOG),
    E(GL_COMPILE), E(GL_COMPILE_AND_EXECUTE), E(GL_LIST_BASE), E(GL_LIST_INDEX), E(GL_LIST_MODE),
    E(GL_MAX_LIST_NESTING), E(GL_BYTE), E(GL_UNSIGNED_BYTE), E(GL_SHORT), E(GL_UNSIGNED_SHORT), E(GL_INT),
    E(GL_UNSIGNED_INT), E(GL_FLOAT), E(GL_2_BYTES), E(GL_3_BYTES), E(GL_4_BYTES), E(GL_DOUBLE),
    E(GL_MAP1_VERTEX_3), E(GL_MAP1_VERTEX_4), E(GL_MAP1_INDEX), E(GL_MAP1_COLOR_4),
    E(GL_MAP1_NORMAL), E(GL_MAP1_TEXTURE_COORD_1), E(GL_MAP1_TEXTURE_COORD_2),
    E(GL_MAP1_TEXTURE_COORD_3), E(GL_MAP1_TEXTURE_COORD_4),
    E(GL_MAP2_VERTEX_3), E(GL_MAP2_VERTEX_4), E(GL_MAP2_INDEX), E(GL_MAP2_COLOR_4),
    E(GL_MAP2_NORMAL), E(GL_MAP2_TEXTURE_COORD_1), E(GL_MAP2_TEXTURE_COORD_2),
    E(GL_MAP2_TEXTURE_COORD_3), E(GL_MAP2_TEXTURE_COORD_4),
    E(GL_AUTO_NORMAL), E(GL_COEFF), E(GL_ORDER), E(GL_DOMAIN),
    E(GL_POINT), E(GL_LINE), E(GL_FILL),
    E(GL_POINTS), E(GL_LINES), E(GL_LINE_LOOP), E(GL_LINE_STRIP), E(GL_TRIANGLES),
    E(GL_TRIANGLE_STRIP), E(GL_TRIANGLE_FAN), E(GL_QUADS), E(GL_QUAD_STRIP), E(GL_POLYGON),
    E(GL_MAX_EVAL_ORDER), E(GL_MAP1_GRID_DOMAIN), E(GL_MAP1_GRID_SEGMENTS),
    E(GL_MAP2_GRID_DOMAIN), E(GL_MAP2_GRID_SEGMENTS),
    E(GL_TEXTURE0), E(GL_TEXTURE1), E(GL_TEXTURE2), E(GL_TEXTURE3),
    E(GL_TEXTURE4), E(GL_TEXTURE5), E(GL_TEXTURE6), E(GL_TEXTURE7),
    E(GL_TEXTURE_2D), E(GL_LIGHTING), E(GL_NORMALIZE),
    E(GL_LINE_STIPPLE), E(GL_LINE_SMOOTH), E(GL_POINT_SMOOTH), E(GL_POLYGON_OFFSET_FILL),
    E(GL_POLYGON_OFFSET_LINE), E(GL_POLYGON_OFFSET_POINT), E(GL_CLIP_PLANE0), E(GL_CLIP_PLANE1),
    E(GL_CLIP_PLANE2), E(GL_CLIP_PLANE3), E(GL_CLIP_PLANE4), E(GL_CLIP_PLANE5),
    E(GL_LINE_STIPPLE_PATTERN), E(GL_LINE_STIPPLE_REPEAT), E(GL_POLYGON_OFFSET_FACTOR),
    E(GL_POLYGON_OFFSET_UNITS), E(GL_MAX_CLIP_PLANES), E(GL_LINE_BIT), E(GL_POLYGON_BIT),
    E(GL_TRANSFORM_BIT), E(GL_FRONT), E(GL_DIFFUSE), E(GL_SHININESS), E(GL_POLYGON_STIPPLE),
    E(GL_POLYGON_STIPPLE_BIT),
    ARRAYS_ENUMS
    { NULL, 0 }
};

static void die(const char *msg, const char *what)
{
    fprintf(stderr, "%s:%d: %s%s%s\n", script_name, lineno, msg,
            what ? ": " : "", what ? what : "");
    exit(2);
}

/* Components per map target and dimension (1 or 2); 0 for anything else. */
static int map_info(GLenum target, int *dim)
{
    static const struct { GLenum t; int k; } maps[] = {
        { GL_MAP1_VERTEX_3, 3 }, { GL_MAP1_VERTEX_4, 4 }, { GL_MAP1_INDEX, 1 },
        { GL_MAP1_COLOR_4, 4 }, { GL_MAP1_NORMAL, 3 }, { GL_MAP1_TEXTURE_COORD_1, 1 },
        { GL_MAP1_TEXTURE_COORD_2, 2 }, { GL_MAP1_TEXTURE_COORD_3, 3 },
        { GL_MAP1_TEXTURE_COORD_4, 4 },
        { GL_MAP2_VERTEX_3, 3 }, { GL_MAP2_VERTEX_4, 4 }, { GL_MAP2_INDEX, 1 },
        { GL_MAP2_COLOR_4, 4 }, { GL_MAP2_NORMAL, 3 }, { GL_MAP2_TEXTURE_COORD_1, 1 },
        { GL_MAP2_TEXTURE_COORD_2, 2 }, { GL_MAP2_TEXTURE_COORD_3, 3 },
        { GL_MAP2_TEXTURE_COORD_4, 4 },
    };
    for (size_t i = 0; i < sizeof maps / sizeof maps[0]; i++)
        if (maps[i].t == target) {
            *dim = i < 9 ? 1 : 2;
            return maps[i].k;
        }
    *dim = 0;
    return 0;
}

/* ---------------------------------------------------------------- tokens */
static char *tok[MAX_TOK];
static int ntok, pos;

static const char *next(void)
{
    if (pos >= ntok) die("missing argument", NULL);
    return tok[pos++];
}

static int query_enum(const char *s, GLenum *v);

static GLenum arg_enum(void)
{
    const char *s = next();
    for (int i = 0; enums[i].name; i++)
        if (strcmp(enums[i].name, s) == 0) return enums[i].value;
    GLenum q;
    if (query_enum(s, &q)) return q;
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, 0);   /* raw numbers: 0x1234 or 4660 */
    if (*end || errno || end == s) die("unknown enum", s);
    return (GLenum)v;
}

static GLint arg_int(void)
{
    const char *s = next();
    char *end;
    long v = strtol(s, &end, 10);
    if (*end || end == s) die("bad integer", s);
    return (GLint)v;
}

static double arg_double(void)
{
    const char *s = next();
    char *end;
    double v = strtod(s, &end);
    if (*end || end == s) die("bad number", s);
    return v;
}

static float arg_float(void)
{
    const char *s = next();
    char *end;
    float v = strtof(s, &end);
    if (*end || end == s) die("bad number", s);
    return v;
}

/* An array `[a b c]` (or the word `null`).  Returns a zero-padded buffer of at
 * least `need` elements (so Mesa never reads past the end); *given is the
 * number of values written in the script, -1 for null. */
static void *arg_array(int dbl, long need, long *given)
{
    const char *s = next();
    if (strcmp(s, "null") == 0) { *given = -1; return NULL; }
    if (strcmp(s, "[") != 0) die("expected [", s);
    int start = pos, n = 0;
    while (pos < ntok && strcmp(tok[pos], "]") != 0) { pos++; n++; }
    if (pos >= ntok) die("missing ]", NULL);
    pos = start;
    long size = (n > need ? n : need) + 16;
    void *buf = calloc((size_t)size, dbl ? sizeof(double) : sizeof(float));
    for (int i = 0; i < n; i++) {
        if (dbl) ((double *)buf)[i] = arg_double();
        else ((float *)buf)[i] = arg_float();
    }
    pos++;   /* skip ] */
    *given = n;
    return buf;
}

static long clampl(long v, long lo, long hi) { return v < lo ? lo : v > hi ? hi : v; }

/* Floats Mesa reads from the array (at most), computed on sane ranges only. */
static long need1(GLenum target, GLint stride, GLint order)
{
    int dim, k = map_info(target, &dim);
    if (order < 1) return 0;
    return (clampl(order, 1, 64) - 1) * clampl(stride, 0, 1 << 16) + k;
}

static long need2(GLenum target, GLint us, GLint uo, GLint vs, GLint vo)
{
    int dim, k = map_info(target, &dim);
    if (uo < 1 || vo < 1) return 0;
    return (clampl(uo, 1, 64) - 1) * clampl(us, 0, 1 << 16)
         + (clampl(vo, 1, 64) - 1) * clampl(vs, 0, 1 << 16) + k;
}

/* ---------------------------------------------------------------- context */
static void start_feedback(void)
{
    glFeedbackBuffer(FB_SIZE, GL_4D_COLOR_TEXTURE, fb);
    glRenderMode(GL_FEEDBACK);
}

static void new_context(void)
{
    if (ctx) OSMesaDestroyContext(ctx);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, ctx_stencil, ctx_accum, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H))
        die("cannot create OSMesa context", NULL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(0, 0, 2, 2);
    glDisable(GL_LIGHTING);
    start_feedback();
    if (glGetError() != GL_NO_ERROR) die("error while setting up the context", NULL);
    in_begin = 0;
    defer_errors = 0;
}

static void print_vertex(const GLfloat *v)
{
    for (int i = 0; i < 12; i++) printf(" %.9g", v[i]);
}

/* Leave feedback mode, print the tokens, enter feedback mode again. */
static void collect_feedback(void)
{
    /* After a script's own glRenderMode: nothing to collect in selection mode; back to
     * feedback from render mode. */
    GLint mode = GL_FEEDBACK;
    glGetIntegerv(GL_RENDER_MODE, &mode);
    if (mode == GL_SELECT) return;
    if (mode == GL_RENDER) { start_feedback(); return; }
    GLint n = glRenderMode(GL_RENDER);
    if (n < 0) { printf("fb overflow\n"); n = 0; }
    for (GLint i = 0; i < n;) {
        GLenum t = (GLenum)fb[i++];
        int nv = 1;
        switch (t) {
        case GL_POINT_TOKEN: printf("fb point"); break;
        case GL_LINE_TOKEN: printf("fb line"); nv = 2; break;
        case GL_LINE_RESET_TOKEN: printf("fb line_reset"); nv = 2; break;
        case GL_POLYGON_TOKEN: nv = (int)fb[i++]; printf("fb polygon %d", nv); break;
        case GL_BITMAP_TOKEN: printf("fb bitmap"); break;
        case GL_DRAW_PIXEL_TOKEN: printf("fb draw_pixel"); break;
        case GL_COPY_PIXEL_TOKEN: printf("fb copy_pixel"); break;
        case GL_PASS_THROUGH_TOKEN: printf("fb pass_through %.9g\n", fb[i++]); continue;
        default: die("unknown feedback token", NULL);
        }
        for (int v = 0; v < nv; v++, i += 12) print_vertex(&fb[i]);
        printf("\n");
    }
    start_feedback();
    if (!defer_errors && glGetError() != GL_NO_ERROR)
        die("GL error while restarting feedback", NULL);
}

/* ---------------------------------------------------------------- queries */
static char vals[1 << 16];   /* query values printed after err=... */
static size_t vlen;

static void val(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (vlen < sizeof vals)
        vlen += (size_t)vsnprintf(vals + vlen, sizeof vals - vlen, fmt, ap);
    va_end(ap);
}

static void get_map(const char *name, GLenum target, GLenum query)
{
    union { GLfloat f[4096]; GLdouble d[4096]; GLint i[4096]; } buf;
    int dim, k = map_info(target, &dim), count = 0;
    memset(&buf, 0, sizeof buf);
    if (k && query == GL_COEFF) {
        GLint ord[2] = { 0, 0 };
        glGetMapiv(target, GL_ORDER, ord);
        count = dim == 1 ? ord[0] * k : ord[0] * ord[1] * k;
    } else if (k && query == GL_ORDER) {
        count = dim;
    } else if (k && query == GL_DOMAIN) {
        count = 2 * dim;
    }
    if (name[7] == 'f') glGetMapfv(target, query, buf.f);
    else if (name[7] == 'd') glGetMapdv(target, query, buf.d);
    else glGetMapiv(target, query, buf.i);
    for (int i = 0; i < count; i++) {
        if (name[7] == 'f') val(" %.9g", buf.f[i]);
        else if (name[7] == 'd') val(" %.9g", buf.d[i]);
        else val(" %d", buf.i[i]);
    }
}

static int get_count(GLenum pname)
{
    switch (pname) {
    case GL_MAP1_GRID_DOMAIN: return 2;
    case GL_MAP2_GRID_DOMAIN: return 4;
    case GL_MAP2_GRID_SEGMENTS: return 2;
    case GL_CURRENT_RASTER_POSITION: case GL_CURRENT_RASTER_COLOR:
    case GL_CURRENT_RASTER_TEXTURE_COORDS: return 4;
    case GL_CURRENT_COLOR: case GL_CURRENT_TEXTURE_COORDS: case GL_CURRENT_SECONDARY_COLOR: return 4;
    case GL_CURRENT_NORMAL: return 3;
    case GL_COLOR_WRITEMASK: case GL_SCISSOR_BOX: case GL_ACCUM_CLEAR_VALUE: return 4;
    default: return 1;
    }
}

/* ---------------------------------------------------------------- typed calls */
/* The type variants of the per-vertex calls, through their v forms: `typed NAME v...`. */
struct typed_fn { const char *name; int n; const char *type; void (*fn)(const void *); };
static const struct typed_fn typed_fns[] = {
    { "glColor3bv", 3, "b", (void (*)(const void *))glColor3bv },
    { "glColor3sv", 3, "s", (void (*)(const void *))glColor3sv },
    { "glColor3iv", 3, "i", (void (*)(const void *))glColor3iv },
    { "glColor3dv", 3, "d", (void (*)(const void *))glColor3dv },
    { "glColor3ubv", 3, "ub", (void (*)(const void *))glColor3ubv },
    { "glColor3usv", 3, "us", (void (*)(const void *))glColor3usv },
    { "glColor3uiv", 3, "ui", (void (*)(const void *))glColor3uiv },
    { "glColor4bv", 4, "b", (void (*)(const void *))glColor4bv },
    { "glColor4sv", 4, "s", (void (*)(const void *))glColor4sv },
    { "glColor4iv", 4, "i", (void (*)(const void *))glColor4iv },
    { "glColor4dv", 4, "d", (void (*)(const void *))glColor4dv },
    { "glColor4ubv", 4, "ub", (void (*)(const void *))glColor4ubv },
    { "glColor4usv", 4, "us", (void (*)(const void *))glColor4usv },
    { "glColor4uiv", 4, "ui", (void (*)(const void *))glColor4uiv },
    { "glSecondaryColor3bv", 3, "b", (void (*)(const void *))glSecondaryColor3bv },
    { "glSecondaryColor3sv", 3, "s", (void (*)(const void *))glSecondaryColor3sv },
    { "glSecondaryColor3iv", 3, "i", (void (*)(const void *))glSecondaryColor3iv },
    { "glSecondaryColor3fv", 3, "f", (void (*)(const void *))glSecondaryColor3fv },
    { "glSecondaryColor3dv", 3, "d", (void (*)(const void *))glSecondaryColor3dv },
    { "glSecondaryColor3ubv", 3, "ub", (void (*)(const void *))glSecondaryColor3ubv },
    { "glSecondaryColor3usv", 3, "us", (void (*)(const void *))glSecondaryColor3usv },
    { "glSecondaryColor3uiv", 3, "ui", (void (*)(const void *))glSecondaryColor3uiv },
    { "glNormal3bv", 3, "b", (void (*)(const void *))glNormal3bv },
    { "glNormal3sv", 3, "s", (void (*)(const void *))glNormal3sv },
    { "glNormal3iv", 3, "i", (void (*)(const void *))glNormal3iv },
    { "glNormal3dv", 3, "d", (void (*)(const void *))glNormal3dv },
    { "glVertex2dv", 2, "d", (void (*)(const void *))glVertex2dv },
    { "glVertex2iv", 2, "i", (void (*)(const void *))glVertex2iv },
    { "glVertex2sv", 2, "s", (void (*)(const void *))glVertex2sv },
    { "glVertex3dv", 3, "d", (void (*)(const void *))glVertex3dv },
    { "glVertex3iv", 3, "i", (void (*)(const void *))glVertex3iv },
    { "glVertex3sv", 3, "s", (void (*)(const void *))glVertex3sv },
    { "glVertex4dv", 4, "d", (void (*)(const void *))glVertex4dv },
    { "glVertex4iv", 4, "i", (void (*)(const void *))glVertex4iv },
    { "glVertex4sv", 4, "s", (void (*)(const void *))glVertex4sv },
    { "glTexCoord1fv", 1, "f", (void (*)(const void *))glTexCoord1fv },
    { "glTexCoord1dv", 1, "d", (void (*)(const void *))glTexCoord1dv },
    { "glTexCoord1iv", 1, "i", (void (*)(const void *))glTexCoord1iv },
    { "glTexCoord1sv", 1, "s", (void (*)(const void *))glTexCoord1sv },
    { "glTexCoord2fv", 2, "f", (void (*)(const void *))glTexCoord2fv },
    { "glTexCoord2dv", 2, "d", (void (*)(const void *))glTexCoord2dv },
    { "glTexCoord2iv", 2, "i", (void (*)(const void *))glTexCoord2iv },
    { "glTexCoord2sv", 2, "s", (void (*)(const void *))glTexCoord2sv },
    { "glTexCoord3fv", 3, "f", (void (*)(const void *))glTexCoord3fv },
    { "glTexCoord3dv", 3, "d", (void (*)(const void *))glTexCoord3dv },
    { "glTexCoord3iv", 3, "i", (void (*)(const void *))glTexCoord3iv },
    { "glTexCoord3sv", 3, "s", (void (*)(const void *))glTexCoord3sv },
    { "glTexCoord4fv", 4, "f", (void (*)(const void *))glTexCoord4fv },
    { "glTexCoord4dv", 4, "d", (void (*)(const void *))glTexCoord4dv },
    { "glTexCoord4iv", 4, "i", (void (*)(const void *))glTexCoord4iv },
    { "glTexCoord4sv", 4, "s", (void (*)(const void *))glTexCoord4sv },
    { "glRasterPos2sv", 2, "s", (void (*)(const void *))glRasterPos2sv },
    { "glRasterPos3iv", 3, "i", (void (*)(const void *))glRasterPos3iv },
    { "glRasterPos3sv", 3, "s", (void (*)(const void *))glRasterPos3sv },
    { "glRasterPos4dv", 4, "d", (void (*)(const void *))glRasterPos4dv },
    { "glRasterPos4iv", 4, "i", (void (*)(const void *))glRasterPos4iv },
    { "glRasterPos4sv", 4, "s", (void (*)(const void *))glRasterPos4sv },
    { NULL, 0, NULL, NULL }
};

static void run_typed(void)
{
    const char *name = next();
    const struct typed_fn *t = typed_fns;
    while (t->name && strcmp(t->name, name)) t++;
    if (!t->name) die("unknown typed call", name);
    union { GLbyte b[4]; GLubyte ub[4]; GLshort s[4]; GLushort us[4]; GLint i[4]; GLuint ui[4];
            GLfloat f[4]; GLdouble d[4]; } v;
    for (int k = 0; k < t->n; k++) {
        double x = arg_double();
        if (!strcmp(t->type, "b")) v.b[k] = (GLbyte)x;
        else if (!strcmp(t->type, "ub")) v.ub[k] = (GLubyte)x;
        else if (!strcmp(t->type, "s")) v.s[k] = (GLshort)x;
        else if (!strcmp(t->type, "us")) v.us[k] = (GLushort)x;
        else if (!strcmp(t->type, "i")) v.i[k] = (GLint)x;
        else if (!strcmp(t->type, "ui")) v.ui[k] = (GLuint)x;
        else if (!strcmp(t->type, "f")) v.f[k] = (GLfloat)x;
        else v.d[k] = x;
    }
    t->fn(&v);
}

#include "queries.inc.c"
#include "interp_pixels.h"

/* ---------------------------------------------------------------- calls */
#include "interp_arrays.c"
#include "interp_buffers.c"

/* Executes one call; query values (if any) go into `vals`. */
static void run_call(const char *c)
{
    long given = 0;
    vlen = 0;
    vals[0] = '\0';

    if (!strcmp(c, "map1f") || !strcmp(c, "map1d")) {
        GLenum t = arg_enum();
        double u1 = arg_double(), u2 = arg_double();
        GLint stride = arg_int(), order = arg_int();
        int dbl = c[4] == 'd';
        void *p = arg_array(dbl, need1(t, stride, order), &given);
        if (dbl) glMap1d(t, u1, u2, stride, order, p);
        else glMap1f(t, (float)u1, (float)u2, stride, order, p);
        if (given >= 0 && given < need1(t, stride, order))
            die("array shorter than what the call reads", NULL);
        free(p);
    } else if (!strcmp(c, "map2f") || !strcmp(c, "map2d")) {
        GLenum t = arg_enum();
        double u1 = arg_double(), u2 = arg_double();
        GLint us = arg_int(), uo = arg_int();
        double v1 = arg_double(), v2 = arg_double();
        GLint vs = arg_int(), vo = arg_int();
        int dbl = c[4] == 'd';
        long need = need2(t, us, uo, vs, vo);
        void *p = arg_array(dbl, need, &given);
        if (dbl) glMap2d(t, u1, u2, us, uo, v1, v2, vs, vo, p);
        else glMap2f(t, (float)u1, (float)u2, us, uo, (float)v1, (float)v2, vs, vo, p);
        if (given >= 0 && given < need)
            die("array shorter than what the call reads", NULL);
        free(p);
    } else if (!strcmp(c, "map_grid1f")) {
        GLint n = arg_int(); float a = arg_float(), b = arg_float();
        glMapGrid1f(n, a, b);
    } else if (!strcmp(c, "map_grid1d")) {
        GLint n = arg_int(); double a = arg_double(), b = arg_double();
        glMapGrid1d(n, a, b);
    } else if (!strcmp(c, "map_grid2f")) {
        GLint un = arg_int(); float a = arg_float(), b = arg_float();
        GLint vn = arg_int(); float d = arg_float(), e = arg_float();
        glMapGrid2f(un, a, b, vn, d, e);
    } else if (!strcmp(c, "map_grid2d")) {
        GLint un = arg_int(); double a = arg_double(), b = arg_double();
        GLint vn = arg_int(); double d = arg_double(), e = arg_double();
        glMapGrid2d(un, a, b, vn, d, e);
    } else if (!strcmp(c, "eval_coord1f")) {
        glEvalCoord1f(arg_float());
    } else if (!strcmp(c, "eval_coord1d")) {
        glEvalCoord1d(arg_double());
    } else if (!strcmp(c, "eval_coord2f")) {
        float u = arg_float(), v = arg_float();
        glEvalCoord2f(u, v);
    } else if (!strcmp(c, "eval_coord2d")) {
        double u = arg_double(), v = arg_double();
        glEvalCoord2d(u, v);
    } else if (!strcmp(c, "eval_point1")) {
        glEvalPoint1(arg_int());
    } else if (!strcmp(c, "eval_point2")) {
        GLint i = arg_int(), j = arg_int();
        glEvalPoint2(i, j);
    } else if (!strcmp(c, "eval_mesh1")) {
        GLenum m = arg_enum(); GLint i1 = arg_int(), i2 = arg_int();
        glEvalMesh1(m, i1, i2);
    } else if (!strcmp(c, "eval_mesh2")) {
        GLenum m = arg_enum(); GLint i1 = arg_int(), i2 = arg_int();
        GLint j1 = arg_int(), j2 = arg_int();
        glEvalMesh2(m, i1, i2, j1, j2);
    } else if (!strcmp(c, "enable")) {
        glEnable(arg_enum());
    } else if (!strcmp(c, "disable")) {
        glDisable(arg_enum());
    } else if (!strcmp(c, "is_enabled")) {
        val(" %d", (int)glIsEnabled(arg_enum()));
    } else if (!strcmp(c, "begin")) {
        glBegin(arg_enum());
    } else if (!strcmp(c, "end")) {
        glEnd();
    } else if (!strcmp(c, "vertex3f")) {
        float x = arg_float(), y = arg_float(), z = arg_float();
        glVertex3f(x, y, z);
    } else if (!strcmp(c, "vertex4f")) {
        float x = arg_float(), y = arg_float(), z = arg_float(), w = arg_float();
        glVertex4f(x, y, z, w);
    } else if (!strcmp(c, "color4f")) {
        float r = arg_float(), g = arg_float(), b = arg_float(), a = arg_float();
        glColor4f(r, g, b, a);
    } else if (!strcmp(c, "normal3f")) {
        float x = arg_float(), y = arg_float(), z = arg_float();
        glNormal3f(x, y, z);
    } else if (!strcmp(c, "tex_coord4f")) {
        float s = arg_float(), t = arg_float(), r = arg_float(), q = arg_float();
        glTexCoord4f(s, t, r, q);
    } else if (!strcmp(c, "active_texture")) {
        glActiveTexture(arg_enum());
    } else if (!strncmp(c, "get_map", 7) && strlen(c) == 9 && c[8] == 'v'
               && (c[7] == 'f' || c[7] == 'd' || c[7] == 'i')) {
        GLenum t = arg_enum(), q = arg_enum();
        get_map(c, t, q);
    } else if (!strcmp(c, "get_integerv") || !strcmp(c, "get_floatv")) {
        GLenum p = arg_enum();
        GLint iv[16] = { 0 };
        GLfloat fv[16] = { 0 };
        int n = get_count(p);
        if (c[4] == 'i') glGetIntegerv(p, iv); else glGetFloatv(p, fv);
        for (int i = 0; i < n; i++)
            if (c[4] == 'i') val(" %d", iv[i]); else val(" %.9g", fv[i]);
    } else if (!strcmp(c, "new_list")) {
        GLuint list = (GLuint)arg_int();
        GLenum mode = arg_enum();
        glNewList(list, mode);
    } else if (!strcmp(c, "end_list")) {
        glEndList();
    } else if (!strcmp(c, "call_list")) {
        glCallList((GLuint)arg_int());
    } else if (!strcmp(c, "gen_lists")) {
        val(" %u", glGenLists(arg_int()));
    } else if (!strcmp(c, "delete_lists")) {
        GLuint list = (GLuint)arg_int();
        GLsizei range = arg_int();
        glDeleteLists(list, range);
    } else if (!strcmp(c, "is_list")) {
        val(" %d", glIsList((GLuint)arg_int()));
    } else if (!strcmp(c, "list_base")) {
        glListBase((GLuint)arg_int());
    } else if (!strcmp(c, "call_lists")) {
        /* the names as raw bytes, read by GL as `type` says */
        GLsizei n = arg_int();
        GLenum type = arg_enum();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given; i++) bytes[i] = (GLubyte)f[i];
        glCallLists(n, type, f ? (const GLvoid *)bytes : NULL);
        free(f);
    } else if (!strcmp(c, "gen_textures")) {
        GLuint names[16] = { 0 };
        GLsizei n = arg_int();
        glGenTextures(n, names);
        for (int i = 0; i < n && i < 16; i++) val(" %u", names[i]);
    } else if (!strcmp(c, "bind_texture")) {
        GLenum target = arg_enum();
        glBindTexture(target, (GLuint)arg_int());
    } else if (!strcmp(c, "delete_textures")) {
        GLsizei n = arg_int();
        float *f = arg_array(0, 0, &given);
        GLuint names[16] = { 0 };
        for (long i = 0; i < given && i < 16; i++) names[i] = (GLuint)f[i];
        glDeleteTextures(n, names);
        free(f);
    } else if (!strcmp(c, "is_texture")) {
        val(" %d", glIsTexture((GLuint)arg_int()));
    } else if (!strcmp(c, "tex_image_2d") || !strcmp(c, "tex_sub_image_2d")) {
        /* the pixels as numbers: bytes for GL_UNSIGNED_BYTE, floats for GL_FLOAT */
        int sub = c[4] == 's';
        GLenum target = arg_enum();
        /* tex_image_2d: level internalformat width height border;
         * tex_sub_image_2d: level xoffset yoffset width height */
        GLint level = arg_int();
        GLint a = sub ? arg_int() : (GLint)arg_enum();
        GLint b = arg_int(), w = arg_int(), h = arg_int();
        GLenum format = arg_enum(), type = arg_enum();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given; i++) bytes[i] = (GLubyte)f[i];
        const GLvoid *data = f ? (type == GL_FLOAT ? (const GLvoid *)f : (const GLvoid *)bytes) : NULL;
        if (sub) glTexSubImage2D(target, level, a, b, w, h, format, type, data);
        else glTexImage2D(target, level, a, b, w, h, format, type, data);
        free(f);
    } else if (!strcmp(c, "tex_image_3d") || !strcmp(c, "tex_sub_image_3d")) {
        /* as tex_image_2d, with a depth: tex_image_3d T LEVEL INTERNAL W H D BORDER FORMAT TYPE
         * [..]; tex_sub_image_3d T LEVEL X Y Z W H D FORMAT TYPE [..] */
        int sub = c[4] == 's';
        GLenum target = arg_enum();
        GLint level = arg_int(), internal = 0, border = 0, xyz[3] = { 0, 0, 0 };
        if (sub) for (int k = 0; k < 3; k++) xyz[k] = arg_int();
        else internal = (GLint)arg_enum();
        GLint w = arg_int(), h = arg_int(), d = arg_int();
        if (!sub) border = arg_int();
        GLenum format = arg_enum(), type = arg_enum();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given; i++) bytes[i] = (GLubyte)f[i];
        const GLvoid *data = f ? (type == GL_FLOAT ? (const GLvoid *)f : (const GLvoid *)bytes) : NULL;
        if (sub) glTexSubImage3D(target, level, xyz[0], xyz[1], xyz[2], w, h, d, format, type, data);
        else glTexImage3D(target, level, internal, w, h, d, border, format, type, data);
        free(f);
    } else if (!strcmp(c, "tex_parameteri")) {
        GLenum target = arg_enum(), pname = arg_enum();
        glTexParameteri(target, pname, (GLint)arg_enum());
    } else if (!strcmp(c, "tex_envi")) {
        GLenum target = arg_enum(), pname = arg_enum();
        glTexEnvi(target, pname, (GLint)arg_enum());
    } else if (!strcmp(c, "stencil_func")) {
        GLenum f = arg_enum(); GLint r = arg_int(); GLuint m = (GLuint)arg_int();
        glStencilFunc(f, r, m);
    } else if (!strcmp(c, "stencil_op")) {
        GLenum a = arg_enum(), b = arg_enum(), d = arg_enum();
        glStencilOp(a, b, d);
    } else if (!strcmp(c, "stencil_mask")) {
        glStencilMask((GLuint)arg_int());
    } else if (!strcmp(c, "clear_stencil")) {
        glClearStencil(arg_int());
    } else if (!strcmp(c, "accum")) {
        GLenum op = arg_enum(); float v = arg_float();
        glAccum(op, v);
    } else if (!strcmp(c, "clear_accum")) {
        float r = arg_float(), g = arg_float(), b = arg_float(), a = arg_float();
        glClearAccum(r, g, b, a);
    } else if (!strcmp(c, "depth_mask")) {
        glDepthMask((GLboolean)arg_int());
    } else if (!strcmp(c, "color_mask")) {
        GLint r = arg_int(), g = arg_int(), b = arg_int(), a = arg_int();
        glColorMask((GLboolean)r, (GLboolean)g, (GLboolean)b, (GLboolean)a);
    } else if (!strcmp(c, "scissor")) {
        GLint x = arg_int(), y = arg_int(), w = arg_int(), h = arg_int();
        glScissor(x, y, w, h);
    } else if (!strcmp(c, "logic_op")) {
        glLogicOp(arg_enum());
    } else if (!strcmp(c, "draw_buffer")) {
        glDrawBuffer(arg_enum());
    } else if (!strcmp(c, "read_buffer")) {
        glReadBuffer(arg_enum());
    } else if (!strcmp(c, "clear")) {
        glClear((GLbitfield)arg_enum());
    } else if (!strcmp(c, "blend_func")) {
        GLenum sf = arg_enum();
        glBlendFunc(sf, arg_enum());
    } else if (!strcmp(c, "alpha_func")) {
        GLenum func = arg_enum();
        glAlphaFunc(func, arg_float());
    } else if (!strcmp(c, "fogi")) {
        GLenum pname = arg_enum();
        glFogi(pname, (GLint)arg_enum());
    } else if (!strncmp(c, "raster_pos", 10) && strlen(c) == 12 && c[11] == 'f') {
        GLfloat v[4] = { 0, 0, 0, 1 };
        int n = c[10] - '0';
        for (int i = 0; i < n; i++) v[i] = arg_float();
        if (n == 2) glRasterPos2f(v[0], v[1]);
        else if (n == 3) glRasterPos3f(v[0], v[1], v[2]);
        else glRasterPos4f(v[0], v[1], v[2], v[3]);
    } else if (!strcmp(c, "bitmap")) {
        GLsizei w = arg_int(), h = arg_int();
        GLfloat xo = arg_float(), yo = arg_float(), xm = arg_float(), ym = arg_float();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given; i++) bytes[i] = (GLubyte)f[i];
        glBitmap(w, h, xo, yo, xm, ym, f ? bytes : NULL);
        free(f);
    } else if (!strcmp(c, "draw_pixels") || !strcmp(c, "render_draw_pixels")) {
        /* render_draw_pixels draws in render mode, into the colour buffer (feedback resumes
         * after the command, as after any other). */
        if (c[0] == 'r') glRenderMode(GL_RENDER);
        GLsizei w = arg_int(), h = arg_int();
        GLenum format = arg_enum(), type = arg_enum();
        float *f = arg_array(0, 0, &given);
        GLubyte bytes[MAX_TOK];
        for (long i = 0; i < given; i++) bytes[i] = (GLubyte)f[i];
        glDrawPixels(w, h, format, type, f ? (type == GL_FLOAT ? (const GLvoid *)f : (const GLvoid *)bytes) : NULL);
        free(f);
    } else if (!strcmp(c, "hint")) {
        GLenum target = arg_enum();
        glHint(target, arg_enum());
    } else if (!strcmp(c, "typed")) {
        run_typed();
    } else if (!strcmp(c, "tex_geni")) {
        GLenum coord = arg_enum(), pname = arg_enum();
        glTexGeni(coord, pname, (GLint)arg_enum());
    } else if (!strcmp(c, "tex_genfv")) {
        GLenum coord = arg_enum(), pname = arg_enum();
        long given;
        float *f = arg_array(0, 0, &given);
        glTexGenfv(coord, pname, f);
        free(f);
    } else if (!strcmp(c, "get_tex_genfv")) {
        GLenum coord = arg_enum(), pname = arg_enum();
        GLfloat fv[4] = { 0 };
        glGetTexGenfv(coord, pname, fv);
        for (int i = 0; i < (pname == GL_TEXTURE_GEN_MODE ? 1 : 4); i++) val(" %.9g", fv[i]);
    } else if (!strcmp(c, "fogf")) {
        GLenum pname = arg_enum();
        glFogf(pname, arg_float());
    } else if (!strcmp(c, "line_stipple")) {
        GLint factor = arg_int();
        glLineStipple(factor, (GLushort)arg_int());
    } else if (!strcmp(c, "polygon_offset")) {
        GLfloat factor = arg_float();
        glPolygonOffset(factor, arg_float());
    } else if (!strcmp(c, "clip_plane")) {
        GLenum plane = arg_enum();
        long given;
        GLdouble *eq = arg_array(1, 4, &given);
        if (given < 4) die("clip_plane needs 4 values", NULL);
        glClipPlane(plane, eq);
        free(eq);
    } else if (!strcmp(c, "polygon_stipple")) {
        long given;
        float *f = arg_array(0, 128, &given);
        GLubyte mask[128];
        if (given < 128) die("polygon_stipple needs 128 bytes", NULL);
        for (int i = 0; i < 128; i++) mask[i] = (GLubyte)f[i];
        free(f);
        glPolygonStipple(mask);
    } else if (!strcmp(c, "get_clip_plane")) {
        GLdouble eq[4] = { 0, 0, 0, 0 };
        glGetClipPlane(arg_enum(), eq);
        for (int i = 0; i < 4; i++) val(" %.9g", eq[i]);
    } else if (!strncmp(c, "load_transpose_matrix", 21) || !strncmp(c, "mult_transpose_matrix", 21)) {
        /* load_transpose_matrixf|d, mult_transpose_matrixf|d: 16 values, row by row. */
        GLfloat mf[16];
        GLdouble md[16];
        for (int i = 0; i < 16; i++) mf[i] = (GLfloat)(md[i] = arg_double());
        int dbl = c[21] == 'd';
        if (c[0] == 'l') { if (dbl) glLoadTransposeMatrixd(md); else glLoadTransposeMatrixf(mf); }
        else { if (dbl) glMultTransposeMatrixd(md); else glMultTransposeMatrixf(mf); }
    } else if (!strcmp(c, "translatef")) {
        GLfloat x = arg_float(), y = arg_float();
        glTranslatef(x, y, arg_float());
    } else if (!strcmp(c, "rotatef")) {
        GLfloat angle = arg_float(), x = arg_float(), y = arg_float();
        glRotatef(angle, x, y, arg_float());
    } else if (!strcmp(c, "scalef")) {
        GLfloat x = arg_float(), y = arg_float();
        glScalef(x, y, arg_float());
    } else if (!strcmp(c, "matrix_mode")) {
        glMatrixMode(arg_enum());
    } else if (!strcmp(c, "load_identity")) {
        glLoadIdentity();
    } else if (!strcmp(c, "materialf")) {
        GLenum face = arg_enum(), pname = arg_enum();
        glMaterialf(face, pname, arg_float());
    } else if (!strcmp(c, "push_attrib")) {
        glPushAttrib(arg_enum());
    } else if (!strcmp(c, "pop_attrib")) {
        glPopAttrib();
    } else if (!strcmp(c, "pixel_storei")) {
        GLenum pname = arg_enum();
        glPixelStorei(pname, arg_int());
    } else if (!strcmp(c, "texgen_normal")) {
        /* eye-space normal (= object normal with identity modelview) -> s,t,r.
         * Mesa applies texgen only on an enabled unit with a complete texture. */
        static const GLubyte texel[4] = { 255, 255, 255, 255 };
        GLuint tex;
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        glEnable(GL_TEXTURE_2D);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
        glEnable(GL_TEXTURE_GEN_S);
        glEnable(GL_TEXTURE_GEN_T);
        glEnable(GL_TEXTURE_GEN_R);
    } else if (!run_arrays_call(c) && !run_buffers_call(c) && !run_queries_objects_call(c) && !run_queries_call(c) && !run_pixel_call(c)) {
        die("unknown call", c);
    }
}

static void run_line(char *line)
{
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    /* tokenize, making [ and ] separate tokens */
    static char spaced[1 << 20];
    size_t o = 0;
    for (char *p = line; *p && o + 4 < sizeof spaced; p++) {
        if (*p == '[' || *p == ']') { spaced[o++] = ' '; spaced[o++] = *p; spaced[o++] = ' '; }
        else spaced[o++] = *p;
    }
    spaced[o] = '\0';
    ntok = pos = 0;
    for (char *t = strtok(spaced, " \t\r\n"); t; t = strtok(NULL, " \t\r\n")) {
        if (ntok == MAX_TOK) die("line too long", NULL);
        tok[ntok++] = t;
    }
    if (ntok == 0) return;
    const char *c = next();

    if (!strcmp(c, "case")) {
        if (in_begin) die("case starts inside begin/end", NULL);
        ctx_stencil = ctx_accum = 0;
        new_context();
        printf("case %s\n", next());
    } else if (!strcmp(c, "buffers")) {
        /* a fresh context of the case with S stencil and A accumulation bits */
        if (in_begin) die("buffers inside begin/end", NULL);
        ctx_stencil = arg_int();
        ctx_accum = arg_int();
        new_context();
        printf("%d buffers err=-\n", lineno);
    } else if (!strcmp(c, "defer_errors")) {
        const char *v = next();
        if (strcmp(v, "on") && strcmp(v, "off")) die("defer_errors on|off", v);
        defer_errors = v[1] == 'n';
        printf("%d defer_errors err=-\n", lineno);
    } else if (!strcmp(c, "get_error")) {
        printf("%d get_error err=0x%04x\n", lineno, glGetError());
    } else {
        if (!ctx) die("call before the first case", c);
        run_call(c);
        if (!strcmp(c, "begin")) in_begin = 1;
        if (!strcmp(c, "end")) in_begin = 0;
        if (in_begin || defer_errors) printf("%d %s err=-%s\n", lineno, c, vals);
        else printf("%d %s err=0x%04x%s\n", lineno, c, glGetError(), vals);
        if (!in_begin) collect_feedback();
    }
    if (pos != ntok) die("extra arguments", tok[pos]);
}

int main(int argc, char **argv)
{
    if (argc != 2) { fprintf(stderr, "usage: %s SCRIPT.calls\n", argv[0]); return 2; }
    script_name = argv[1];
    FILE *f = fopen(script_name, "r");
    if (!f) die("cannot open", strerror(errno));
    char *line = NULL;
    size_t cap = 0;
    while (getline(&line, &cap, f) >= 0) {
        lineno++;
        run_line(line);
        fflush(stdout);
    }
    if (in_begin) die("script ends inside begin/end", NULL);
    free(line);
    fclose(f);
    if (ctx) OSMesaDestroyContext(ctx);
    return 0;
}
