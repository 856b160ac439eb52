/* fuzz.c: random GL, GLU and GLUT calls through gleval's C ABI: NULL pointers, negative and
 * huge orders, absurd grids, NaN and infinite values, tessellator calls in any order, unknown enums, calls inside glBegin/glEnd
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
static GLUtesselator *tess[2];
static GLUquadric *quads[2];
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
    GL_LIGHTING, GL_LIGHT0, GL_DEPTH_TEST, GL_CULL_FACE, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_BLEND, GL_FOG,
    GL_NORMALIZE, GL_ALPHA_TEST, GL_COLOR_MATERIAL, 0x1234};
static const GLenum pnames[] = {GL_MAX_EVAL_ORDER, GL_MAP1_GRID_DOMAIN, GL_MAP2_GRID_DOMAIN,
    GL_MAP2_GRID_SEGMENTS, GL_CURRENT_RASTER_POSITION, GL_LIST_BASE, 0x1234};
static const GLenum glu_kinds[] = {GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP2_VERTEX_3,
    GL_MAP2_VERTEX_4, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_2, GLU_MAP1_TRIM_2, GLU_MAP1_TRIM_3, 0x1234};
static const GLenum properties[] = {GLU_SAMPLING_TOLERANCE, GLU_DISPLAY_MODE, GLU_CULLING,
    GLU_SAMPLING_METHOD, GLU_U_STEP, GLU_V_STEP, GLU_AUTO_LOAD_MATRIX, GLU_NURBS_MODE, 0x1234};
static const GLenum list_types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT,
    GL_2_BYTES, GL_3_BYTES, GL_4_BYTES, GL_DOUBLE, 0x1234};

static const GLenum array_types[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
    GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE, 0x1234};
static const GLint array_sizes[] = {-1, 0, 1, 2, 3, 4, 5};
static const GLint array_strides[] = {-4, 0, 1, 3, 7, 13, 64, 100};
static const GLint counts[] = {-1, 0, 1, 2, 3, 4, 7, 50, 500};
static const GLenum array_caps[] = {GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY,
    GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY, GL_FOG_COORD_ARRAY, GL_LIGHTING, 0x1234};
static const GLenum formats[] = {GL_V2F, GL_V3F, GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F, GL_N3F_V3F,
    GL_C4F_N3F_V3F, GL_T2F_V3F, GL_T4F_V4F, GL_T2F_C4UB_V3F, GL_T2F_C3F_V3F, GL_T2F_N3F_V3F,
    GL_T2F_C4F_N3F_V3F, GL_T4F_C4F_N3F_V4F, 0x1234};
static const GLenum render_modes[] = {GL_RENDER, GL_SELECT, GL_FEEDBACK, 0x1234};
static GLuint selection[64];
static GLushort indices[600];
static GLuint indices32[600];

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

static void tess_vertex_cb(void *data) { if (data) glVertex3dv((const GLdouble *)data); }
static void tess_error_cb(GLenum code) { (void)gluErrorString(code); }
static void tess_edge_cb(GLboolean flag) { (void)flag; }
static void tess_combine_cb(GLdouble c[3], void *d[4], GLfloat w[4], void **out) {
    (void)c; (void)d; (void)w;
    *out = pick(5) ? (void *)&dbuf[pick(1000) * 3] : NULL;
}
static const GLenum tess_props[] = {GLU_TESS_WINDING_RULE, GLU_TESS_BOUNDARY_ONLY, GLU_TESS_TOLERANCE, 0x1234};
static const double tess_values[] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
    GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO, 0, 1, 0.5, -1, 100135, NAN, 1e300};

/* The polygon tessellator: calls in any order, vertices anywhere in dbuf (NaN every 17th
 * value, so some polygons have NaN coordinates), combine callbacks that answer NULL. */
static void tess_call(void) {
    GLUtesselator *t = pick(8) ? tess[pick(2)] : NULL;
    switch (pick(10)) {
    case 0: gluTessBeginPolygon(t, pick(2) ? (void *)buf : NULL); break;
    case 1: gluTessBeginContour(t); break;
    case 2: case 3: case 4:
        for (int k = pick(12); k > 0; k--) { GLdouble *v = &dbuf[pick(5000) * 3]; gluTessVertex(t, v, v); }
        break;
    case 5: gluTessEndContour(t); break;
    case 6: gluTessEndPolygon(t); break;
    case 7: gluTessProperty(t, ANY(tess_props), ANY(tess_values)); gluTessNormal(t, f(), f(), f()); break;
    case 8: if (pick(2)) gluNextContour(t, GLU_CW); else if (pick(2)) gluBeginPolygon(t); else gluEndPolygon(t); break;
    default:
        switch (pick(6)) {
        case 0: gluTessCallback(t, GLU_TESS_VERTEX, pick(4) ? (_GLUfuncptr)tess_vertex_cb : NULL); break;
        case 1: gluTessCallback(t, GLU_TESS_BEGIN, (_GLUfuncptr)begin_cb); break;
        case 2: gluTessCallback(t, GLU_TESS_END, (_GLUfuncptr)end_cb); break;
        case 3: gluTessCallback(t, GLU_TESS_COMBINE, pick(3) ? (_GLUfuncptr)tess_combine_cb : NULL); break;
        case 4: gluTessCallback(t, GLU_TESS_EDGE_FLAG, pick(2) ? (_GLUfuncptr)tess_edge_cb : NULL); break;
        default: gluTessCallback(t, pick(2) ? GLU_TESS_ERROR : 0x1234, (_GLUfuncptr)tess_error_cb); break;
        }
    }
}

/* Quadrics: any mode (bad ones are GLU_INVALID_ENUM), NaN and infinite sizes, bad counts.
 * Stacks and loops stay small where GLU loops over them unclamped (a cylinder of 2^31 stacks
 * runs as long in GLU); slices and a sphere's stacks are clamped to 239 by GLU itself, and one
 * of a sphere's two counts stays small so that the frame stays quick to render. */
static const GLint slices[] = {-5, -1, 0, 1, 2, 3, 8, 300, 2147483647, -2147483647 - 1};
static const GLint loops[] = {-1, 0, 1, 2, 7};
static const GLenum quadric_modes[] = {GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT, GLU_NONE, GLU_FLAT,
    GLU_SMOOTH, GLU_OUTSIDE, GLU_INSIDE, 0x1234};

static const GLenum image_formats[] = {GL_RGB, GL_RGBA, GL_LUMINANCE, GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_BGRA, 0x1234};
static const GLenum image_types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_UNSIGNED_INT, GL_FLOAT, GL_BITMAP,
    GL_UNSIGNED_SHORT_5_6_5, 0x1234};
static float image_out[4096];

static void quadric_call(void) {
    GLUquadric *q = pick(10) ? quads[pick(2)] : NULL;
    switch (pick(14)) {
    case 9: gluScaleImage(ANY(image_formats), ANY(loops), ANY(loops), ANY(image_types), buf, ANY(loops),
                          ANY(loops), ANY(image_types), image_out); break;
    case 10: gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGB, ANY(slices) % 64, ANY(image_formats), ANY(image_types), buf); break;
    case 11: gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGB, ANY(loops), ANY(loops), ANY(image_formats), GL_UNSIGNED_BYTE,
                                    ANY(loops), ANY(loops), ANY(loops), buf); break;
    /* 3D images of at most 7 on a side, 16 bytes a pixel, 16 rows an image, 3 skipped (the
       image modes of texture_3d_call), and GLU's slips past them: within buf. */
    case 12: gluBuild3DMipmaps(GL_TEXTURE_3D, pick(6) ? GL_RGBA : 0x1234, ANY(loops), ANY(loops), ANY(loops),
                               ANY(image_formats), ANY(image_types), buf); break;
    case 13: gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGB, ANY(loops), ANY(loops), ANY(loops), ANY(image_formats),
                                    ANY(image_types), ANY(loops), ANY(loops), ANY(loops), buf); break;
    case 0: gluQuadricDrawStyle(q, ANY(quadric_modes)); break;
    case 1: gluQuadricNormals(q, ANY(quadric_modes)); break;
    case 2: gluQuadricOrientation(q, ANY(quadric_modes)); break;
    case 3: gluQuadricTexture(q, (GLboolean)pick(3)); break;
    case 4: gluQuadricCallback(q, pick(2) ? GLU_ERROR : 0x1234, pick(3) ? (_GLUfuncptr)error_cb : NULL); break;
    case 5: if (pick(2)) gluSphere(q, f(), ANY(slices), ANY(loops)); else gluSphere(q, f(), ANY(loops), ANY(slices)); break;
    case 6: gluCylinder(q, f(), f(), f(), ANY(slices), ANY(loops)); break;
    case 7: gluDisk(q, f(), f(), ANY(slices), ANY(loops)); break;
    default: gluPartialDisk(q, f(), f(), ANY(slices), ANY(loops), f(), f()); break;
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

/* Vertex arrays into buf (64 KiB: 650 elements of the largest stride and size fit), draws with
 * up to 563 elements, indices below 600; selection buffers too small; the GLU mappings. */
/* GL 1.5's buffer objects with any target, size, offset, usage and access; arrays and element
 * draws then read through them (a pointer is an offset while one is bound); and its occlusion
 * queries. */
static void buffer_call(void) {
    static const GLenum targets_b[] = { GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, 0x1234, GL_TEXTURE_2D,
                                        GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER };
    GLenum target = ANY(targets_b);
    GLsizeiptr size = ANY(counts);
    GLintptr offset = ANY(small);
    switch (pick(10)) {
    case 8: { /* GL 1.5's occlusion queries with any target, name and pname */
              GLuint id = (GLuint)pick(5), ids[3] = { 1, (GLuint)pick(5), 0 };
              GLint v = 0;
              GLenum query_target = pick(4) ? GL_SAMPLES_PASSED : target;
              switch (pick(6)) {
              case 0: glGenQueries(pick(4) - 1, pick(6) ? ids : NULL); break;
              case 1: glBeginQuery(query_target, id); break;
              case 2: glEndQuery(query_target); break;
              case 3: glDeleteQueries(pick(4) - 1, pick(6) ? ids : NULL); break;
              case 4: glGetQueryiv(query_target, GL_QUERY_COUNTER_BITS + (GLenum)pick(3), pick(4) ? &v : NULL); break;
              default: glGetQueryObjectiv(id, GL_QUERY_RESULT + (GLenum)pick(3), pick(4) ? &v : NULL);
                       glGetQueryObjectuiv(id, GL_QUERY_RESULT, pick(4) ? (GLuint *)&v : NULL); glIsQuery(id); break;
              }
              break; }
    case 0: { GLuint b[4]; glGenBuffers(pick(5) - 1, pick(6) ? b : NULL); break; }
    case 1: glBindBuffer(target, (GLuint)pick(6)); break;
    case 2: glBufferData(target, size, pick(3) ? (void *)buf : NULL, GL_STREAM_DRAW + (GLenum)pick(12)); break;
    case 3: glBufferSubData(target, offset, size, pick(8) ? (void *)buf : NULL); break;
    case 4: glGetBufferSubData(target, offset, size, pick(8) ? (void *)buf : NULL); break;
    case 5: { GLubyte *m = glMapBuffer(target, GL_READ_ONLY + (GLenum)pick(4));
              GLint n = 0;
              glGetBufferParameteriv(target, GL_BUFFER_SIZE, &n);
              if (m && n > 0) m[pick(n)] = (GLubyte)pick(256);   /* within the store, while mapped */
              if (pick(2)) glUnmapBuffer(target);
              /* GL 3.0's range maps with any offset, length and access bits */
              m = glMapBufferRange(target, offset - 1, size, (GLbitfield)pick(0x48));
              glGetBufferParameteriv(target, GL_BUFFER_MAP_LENGTH, &n);
              if (m && n > 0) m[pick(n)] = (GLubyte)pick(256);
              glFlushMappedBufferRange(target, offset - 1, ANY(small));
              if (pick(2)) glUnmapBuffer(target);
              break; }
    case 6: { GLuint b[3] = { (GLuint)pick(6), (GLuint)pick(6), 0 }; glDeleteBuffers(pick(4) - 1, pick(6) ? b : NULL); break; }
    case 7: { void *q = NULL; GLint v = 0; glGetBufferPointerv(target, GL_BUFFER_MAP_POINTER + (GLenum)pick(2), pick(4) ? &q : NULL);
              glGetBufferParameteriv(target, GL_BUFFER_SIZE + (GLenum)pick(0x60), pick(4) ? &v : NULL); glIsBuffer((GLuint)pick(6)); break; }
    default: { /* offsets as pointers only where a buffer is bound (else they are addresses) */
               GLint array_buffer = 0, element_buffer = 0;
               glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer);
               glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &element_buffer);
               GLsizei counts_m[2] = { ANY(counts), ANY(counts) };
               const void *offsets[2] = { (const void *)(intptr_t)pick(64), (const void *)(intptr_t)ANY(small) };
               if (array_buffer)
                   glVertexPointer(ANY(array_sizes), ANY(array_types), ANY(array_strides), (const void *)(intptr_t)pick(64));
               if (element_buffer) {
                   /* indices 0 only: the arrays may be client memory, which GL reads unchecked */
                   static const GLubyte zeros[512];
                   glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)sizeof zeros, zeros, GL_STREAM_DRAW);
                   glDrawRangeElements(ANY(modes), 0, (GLuint)pick(64), ANY(counts), GL_UNSIGNED_BYTE + 2 * (GLenum)pick(3), offsets[0]);
                   glMultiDrawElements(ANY(modes), counts_m, GL_UNSIGNED_SHORT, offsets, pick(3));
               }
               break; }
    }
    /* No element buffer outlives the call: array_call's glDrawElements passes client indices.
     * A pixel buffer now and then does: the pixel calls' pointers are offsets into it then. */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    if (pick(4)) {
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    }
}

static void array_call(void) {
    void *p = pick(8) ? (void *)buf : NULL;
    switch (pick(14)) {
    case 11: buffer_call(); break;
    case 0: glVertexPointer(ANY(array_sizes), ANY(array_types), ANY(array_strides), p); break;
    case 1: glColorPointer(ANY(array_sizes), ANY(array_types), ANY(array_strides), p);
            glNormalPointer(ANY(array_types), ANY(array_strides), p); break;
    case 12: if (pick(2)) { /* GL_EXT_vertex_array's forms, the count ignored */
                 glVertexPointerEXT(ANY(array_sizes), ANY(array_types), ANY(array_strides), ANY(counts), p);
                 glColorPointerEXT(ANY(array_sizes), ANY(array_types), ANY(array_strides), ANY(counts), p);
                 glNormalPointerEXT(ANY(array_types), ANY(array_strides), ANY(counts), p);
                 glTexCoordPointerEXT(ANY(array_sizes), ANY(array_types), ANY(array_strides), ANY(counts), p);
                 glIndexPointerEXT(ANY(array_types), ANY(array_strides), ANY(counts), p);
                 glEdgeFlagPointerEXT(ANY(array_strides), ANY(counts), p);
                 void *q = NULL; glGetPointervEXT(GL_VERTEX_ARRAY_POINTER + pick(6), pick(4) ? &q : NULL);
                 glDrawArraysEXT(ANY(modes), ANY(small), ANY(counts)); glArrayElementEXT(pick(700) - 50);
             } else {
                 gluPickMatrix(f(), f(), f(), f(), (GLint[4]){0, 0, 4, 4});
             }
             break;
    case 2: glTexCoordPointer(ANY(array_sizes), ANY(array_types), ANY(array_strides), p);
            glEdgeFlagPointer(ANY(array_strides), p); glIndexPointer(ANY(array_types), ANY(array_strides), p);
            glFogCoordPointer(ANY(array_types), ANY(array_strides), p); break;
    case 3: if (pick(2)) glEnableClientState(ANY(array_caps)); else glDisableClientState(ANY(array_caps)); break;
    case 4: glInterleavedArrays(ANY(formats), ANY(array_strides), p); break;
    case 5: glDrawArrays(ANY(modes), ANY(small), ANY(counts)); break;
    case 6: { GLenum t = pick(2) ? GL_UNSIGNED_SHORT : ANY(list_types);
              const void *ix = t == GL_UNSIGNED_INT ? (const void *)indices32 : (const void *)indices;
              glDrawElements(ANY(modes), ANY(counts), t, pick(8) ? ix : NULL); break; }
    case 7: glArrayElement(pick(700) - 50); glEdgeFlag((GLboolean)pick(3)); break;
    case 8: { void *q = NULL; glGetPointerv(GL_VERTEX_ARRAY_POINTER + pick(6), pick(4) ? &q : NULL);
              if (pick(2)) glPushClientAttrib(pick(2) ? GL_CLIENT_ALL_ATTRIB_BITS : GL_CLIENT_VERTEX_ARRAY_BIT); else glPopClientAttrib(); break; }
    case 9: if (pick(2)) glSelectBuffer(ANY(small), pick(6) ? selection : NULL);
            else glFeedbackBuffer(ANY(small), GL_2D + pick(6), pick(6) ? buf : NULL);
            glRenderMode(ANY(render_modes)); break;
    case 10: switch (pick(5)) { case 0: glInitNames(); break; case 1: glPushName(pick(9)); break;
             case 2: glPopName(); break; case 3: glLoadName(pick(9)); break; default: glPassThrough(f()); } break;
    default: { GLdouble x, y, z, w; GLint view[4] = {ANY(small), ANY(small), ANY(grids), ANY(small)};
               gluProject(f(), f(), f(), dp(), dp(), view, &x, &y, &z);
               gluUnProject(f(), f(), f(), dp(), dp(), view, &x, &y, &z);
               gluUnProject4(f(), f(), f(), f(), dp(), dp(), view, f(), f(), &x, &y, &z, &w);
               gluPickMatrix(f(), f(), f(), f(), view); break; }
    }
}

/* The state queries and the integer and vector parameter forms (issue 26): names around the
 * valid ones, NULL and real buffers (GL writes at most 16 values, an image or stipple into buf). */
static const GLenum query_names[] = {GL_MODELVIEW_MATRIX, GL_VIEWPORT, GL_DEPTH_RANGE, GL_CURRENT_COLOR,
    GL_LINE_WIDTH_RANGE, GL_POLYGON_MODE, GL_FOG_COLOR, GL_STENCIL_BITS, GL_VERTEX_ARRAY, GL_AMBIENT,
    GL_POSITION, GL_SPOT_DIRECTION, GL_SHININESS, GL_TEXTURE_ENV_COLOR, GL_TEXTURE_BORDER_COLOR,
    GL_TEXTURE_PRIORITY, GL_TEXTURE_WIDTH, GL_TEXTURE_INTERNAL_FORMAT, GL_FOG_MODE, 0x1234, 0};
static void query_call(void) {
    GLenum name = ANY(query_names);
    void *out = pick(8) ? (void *)buf : NULL;
    switch (pick(8)) {
    case 0: glGetBooleanv(name, out); glGetDoublev(name, pick(8) ? dbuf : NULL); break;
    case 1: glGetLightfv(GL_LIGHT0 + pick(9), name, out); glGetLightiv(GL_LIGHT0 + pick(9), name, out); break;
    case 2: glGetMaterialfv(GL_FRONT + pick(3), name, out); glGetMaterialiv(GL_FRONT + pick(3), name, out); break;
    case 3: glGetTexParameterfv(pick(2) ? GL_TEXTURE_2D : name, name, out); glGetTexEnviv(GL_TEXTURE_ENV, name, out); break;
    case 4: glGetTexLevelParameteriv(GL_TEXTURE_2D, ANY(small), name, out);
            glGetTexImage(GL_TEXTURE_2D, ANY(small), pick(2) ? GL_RGBA : name, pick(2) ? GL_FLOAT : name, out); break;
    case 5: glGetPolygonStipple(out); glGetTexGendv(GL_S + pick(5), name, pick(8) ? dbuf : NULL); break;
    case 6: glLightiv(GL_LIGHT0 + pick(9), name, out); glMaterialiv(GL_FRONT + pick(3), name, out);
            glLightModeliv(name, out); glLighti(GL_LIGHT0 + pick(9), name, ANY(orders)); break;
    default: glFogiv(name, out); glTexEnviv(GL_TEXTURE_ENV, name, out); glTexParameterfv(GL_TEXTURE_2D, name, out);
             glTexParameteriv(GL_TEXTURE_2D, name, out); glMateriali(GL_BACK, name, ANY(orders)); break;
    }
}

/* Stencil, accumulation, masks, scissor, logic op, draw/read buffers, stencil reads: any values. */
static void fragment_call(void) {
    static const GLenum funcs[] = {GL_NEVER, GL_LESS, GL_ALWAYS, GL_NOTEQUAL, 0x1234};
    static const GLenum ops[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, 0x8507, 0x8508, 0x1234};
    static const GLenum accums[] = {GL_ACCUM, GL_LOAD, GL_ADD, GL_MULT, GL_RETURN, 0x1234};
    static const GLenum buffers[] = {GL_NONE, GL_FRONT, GL_BACK, GL_FRONT_AND_BACK, GL_RIGHT, GL_AUX0, 0x1234};
    static const GLenum fcaps[] = {GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_COLOR_LOGIC_OP, GL_POLYGON_SMOOTH, GL_BLEND};
    static const GLenum factors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_DST_ALPHA, GL_SRC_ALPHA_SATURATE,
        GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, 0x8005, 0x1234};
    static const GLenum equations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN,
        GL_MAX, GL_LOGIC_OP, 0x1234};
    switch (pick(9)) {
    case 7: glBlendFuncSeparate(ANY(factors), ANY(factors), ANY(factors), ANY(factors));
            glBlendEquationSeparate(ANY(equations), ANY(equations)); glBlendEquation(ANY(equations));
            glBlendColor(f(), f(), f(), f());
            glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD + pick(4), f()); break;
    case 0: glStencilFunc(ANY(funcs), ANY(grids), (GLuint)ANY(grids)); glStencilOp(ANY(ops), ANY(ops), ANY(ops)); break;
    case 1: glStencilMask((GLuint)ANY(grids)); glClearStencil(ANY(grids)); glClear(GL_STENCIL_BUFFER_BIT); break;
    case 2: glAccum(ANY(accums), f()); glClearAccum(f(), f(), f(), f()); break;
    case 3: glDepthMask((GLboolean)pick(3)); glColorMask((GLboolean)pick(2), 1, (GLboolean)pick(3), 0); break;
    case 4: glScissor(ANY(grids), ANY(small), ANY(grids), ANY(small)); glLogicOp(GL_CLEAR + pick(18) - 1); break;
    case 5: glDrawBuffer(ANY(buffers)); glReadBuffer(ANY(buffers)); break;
    case 6: if (pick(2)) glEnable(ANY(fcaps)); else glDisable(ANY(fcaps)); break;
    default: if (!pick(8)) glReadPixels(ANY(small), ANY(small), ANY(small), ANY(small), GL_STENCIL_INDEX,
                          pick(2) ? GL_UNSIGNED_BYTE : GL_FLOAT, pick(4) ? (void *)buf : NULL); break;
    }
}

static void state_call(void) {
    switch (pick(15)) {
    case 13: fragment_call(); break;
    case 0: glEnable(ANY(caps)); break;
    case 1: glDisable(ANY(caps)); break;
    case 2: glBegin(ANY(modes)); break;
    case 3: glEnd(); break;
    case 4: glVertex3f(f(), f(), f()); glVertex3fv(fp()); glNormal3fv(fp()); glColor4fv(fp());
            glTexEnvf(pick(2) ? GL_TEXTURE_FILTER_CONTROL : GL_TEXTURE_ENV, GL_TEXTURE_LOD_BIAS, f());
            glTexParameterf(GL_TEXTURE_2D, pick(2) ? GL_TEXTURE_LOD_BIAS : (GLenum)next(), f());
            glFogCoordf(f()); glFogCoordfv(fp()); if (!pick(8)) glFogi(GL_FOG_COORD_SRC, pick(2) ? GL_FOG_COORD : (GLint)next()); break;
    case 5: glGetFloatv(ANY(pnames), pick(6) ? buf : NULL); glGetIntegerv(ANY(pnames), (GLint *)names); query_call(); break;
    case 6: glLightfv(GL_LIGHT0 + pick(9), GL_AMBIENT + pick(10), fp()); glMaterialfv(GL_FRONT + pick(3), GL_EMISSION + pick(4), fp()); break;
    case 7: glNewList(1 + pick(8), pick(2) ? GL_COMPILE : GL_COMPILE_AND_EXECUTE); compiling = 1; break;
    case 8: glEndList(); compiling = 0; glCallList(1 + pick(8)); break;
    case 9: if (!compiling) glCallLists(ANY(small), ANY(list_types), pick(6) ? (void *)buf : NULL); break;
    case 10: glPushMatrix(); glRotatef(f(), f(), f(), f()); glLoadMatrixf(fp()); glPopMatrix(); break;
    case 11: glTexImage2D(GL_TEXTURE_2D, ANY(small), GL_RGB, ANY(small), ANY(small), 0, GL_RGB,
                          pick(2) ? GL_UNSIGNED_BYTE : GL_FLOAT, pick(3) ? (void *)buf : NULL); break;
    case 12: glRasterPos3f(f(), f(), f()); glBitmap(ANY(small), ANY(small), f(), f(), f(), f(), pick(4) ? (GLubyte *)buf : NULL);
             glutBitmapCharacter(pick(2) ? GLUT_BITMAP_HELVETICA_12 : (void *)(intptr_t)pick(4000), pick(300) - 20); break;
    default: glPointParameterf(pick(2) ? GL_POINT_SIZE_MIN + pick(4) : (GLenum)next(), f());
             glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, fp());
             glPointSize(f()); glLineWidth(f()); glViewport(ANY(grids), 0, ANY(small), ANY(grids)); glFogfv(GL_FOG_COLOR, fp()); break;
    }
}

/* The pixel path: zooms of any size, maps of any size, copies and reads from anywhere. */
static const GLenum pixel_pnames[] = {GL_MAP_COLOR, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE,
    GL_GREEN_BIAS, GL_ALPHA_SCALE, GL_DEPTH_SCALE, GL_DEPTH_BIAS, GL_ZOOM_X, 0x1234};
static const GLenum pixel_maps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R,
    GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_A_TO_A, 0x1234};
static const GLint map_sizes[] = {-1, 0, 1, 2, 3, 7, 64, 256, 257};
static const GLenum copy_types[] = {GL_COLOR, GL_DEPTH, GL_STENCIL, 0x1234};
static const GLenum read_formats[] = {GL_RGBA, GL_DEPTH_COMPONENT, GL_LUMINANCE, GL_STENCIL_INDEX, GL_DEPTH_STENCIL};
/* 3D images of bytes at most 16 on a side, 3 images skipped and 16 rows an image: within buf. */
static const GLint side3[] = {-1, 0, 1, 2, 3, 16};
static const GLenum image_modes[] = {GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_PACK_IMAGE_HEIGHT,
    GL_PACK_SKIP_IMAGES};

/* GL 1.3's combiner and the wrap modes of 1.3 and 1.4, with names and values of every kind. */
static const GLenum env_names[] = {GL_TEXTURE_ENV_MODE, GL_COMBINE_RGB, GL_COMBINE_ALPHA, GL_SOURCE0_RGB,
    GL_SOURCE2_ALPHA, GL_OPERAND1_RGB, GL_OPERAND2_ALPHA, GL_RGB_SCALE, GL_ALPHA_SCALE, 0x1234};
static const GLenum env_values[] = {GL_COMBINE, GL_MODULATE, GL_DOT3_RGBA, GL_INTERPOLATE, GL_TEXTURE,
    GL_TEXTURE0 + 3, GL_CONSTANT, GL_PREVIOUS, GL_ONE_MINUS_SRC_COLOR, GL_SRC_ALPHA, 1, 2, 4, 0x1234};
static const GLenum wraps[] = {GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT, GL_CLAMP, GL_REPEAT, 0x1234};

static void combine_call(void) {
    if (pick(2)) glTexEnvi(GL_TEXTURE_ENV, ANY(env_names), (GLint)ANY(env_values));
    else glTexEnvf(GL_TEXTURE_ENV, ANY(env_names), f());
    glTexParameteri(pick(2) ? GL_TEXTURE_2D : GL_TEXTURE_1D, GL_TEXTURE_WRAP_S + pick(2), (GLint)ANY(wraps));
}

/* GL 1.3's units: any unit (valid, beyond the fixed-function ones, beyond every one), each
 * unit's coordinates in several forms, the client unit, and state set on whichever is active. */
static void multitexture_call(void) {
    GLenum unit = GL_TEXTURE0 + (GLenum)pick(12) - (pick(8) ? 0 : 2) + (pick(16) ? 0 : 190);
    switch (pick(6)) {
    case 0: glActiveTexture(unit); break;
    case 1: glClientActiveTextureARB(unit); break;
    case 2: glMultiTexCoord4f(unit, f(), f(), f(), f()); glMultiTexCoord2fv(unit, pick(6) ? fp() : NULL); break;
    case 3: glMultiTexCoord3dARB(unit, f(), f(), f()); glMultiTexCoord1s(unit, (GLshort)pick(100)); break;
    case 4: glEnable(pick(2) ? GL_TEXTURE_2D : GL_TEXTURE_GEN_S + pick(4)); glTexGeni(GL_S + pick(5), GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR); break;
    default: glMatrixMode(GL_TEXTURE); glTranslatef(f(), f(), f()); if (pick(2)) glPushMatrix(); else glPopMatrix();
             glMatrixMode(GL_MODELVIEW); glBindTexture(GL_TEXTURE_2D, (GLuint)pick(4)); break;
    }
}

static void texture_3d_call(void) {
    GLint x = ANY(side3), y = ANY(side3), z = ANY(side3), w = ANY(side3), h = ANY(side3), d = ANY(side3);
    switch (pick(4)) {
    case 0: glPixelStorei(ANY(image_modes), pick(2) ? ANY(side3) : pick(4) - 1); break;
    case 1: glTexImage3D(pick(8) ? GL_TEXTURE_3D : GL_PROXY_TEXTURE_3D, ANY(small) % 4, pick(2) ? GL_RGB : GL_LUMINANCE,
                         w, h, d, pick(3) - 1, pick(2) ? GL_RGB : GL_LUMINANCE, GL_UNSIGNED_BYTE,
                         pick(4) ? (void *)buf : NULL); break;
    case 2: glTexSubImage3D(GL_TEXTURE_3D, pick(3) - 1, x, y, z, w, h, d, GL_RGB, GL_UNSIGNED_BYTE,
                            pick(6) ? (void *)buf : NULL);
            glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, pick(2) ? GL_CLAMP : GL_REPEAT); break;
    default: if (!pick(8)) glCopyTexSubImage3D(GL_TEXTURE_3D, pick(3) - 1, x, y, z, x - 4, y - 4, w, h);
             glTexCoord3f(f(), f(), f()); break;
    }
}

/* GL 1.3's cube maps, GL 1.4's depth textures and shadow comparison, point sprites: face
 * targets, depth and colour formats mixed, depth parameters with any value, sprites drawn. */
static const GLenum cube_internals[] = {GL_RGB, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT32,
    GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8, 0x1234};
static const GLenum cube_formats[] = {GL_RGB, GL_DEPTH_COMPONENT, GL_DEPTH_STENCIL, GL_STENCIL_INDEX};
static const GLenum cube_types[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_INT_24_8, GL_UNSIGNED_SHORT,
    GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
static const GLenum depth_pnames[] = {GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC};
static const GLenum depth_values[] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA, GL_RED, GL_RGBA, GL_NONE,
    GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, GL_NEVER, GL_ALWAYS, 0x1234};
static void cube_depth_sprite_call(void) {
    GLenum face = GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)pick(8) - 1;
    GLenum target = pick(2) ? GL_TEXTURE_2D : pick(2) ? face : pick(2) ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_RECTANGLE;
    GLint w = ANY(side3), h = pick(4) ? w : ANY(side3);
    switch (pick(5)) {
    case 0: glBindTexture(GL_TEXTURE_CUBE_MAP, (GLuint)pick(3) + 10); glEnable(GL_TEXTURE_CUBE_MAP);
            /* GL_ARB_texture_rectangle: any wrap and filter, drawn in texel coordinates */
            glBindTexture(GL_TEXTURE_RECTANGLE, (GLuint)pick(3) + 20);
            glTexParameteri(GL_TEXTURE_RECTANGLE, pick(2) ? GL_TEXTURE_WRAP_S : GL_TEXTURE_MIN_FILTER, ANY(wraps));
            glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_BASE_LEVEL, pick(3) - 1);
            if (pick(2)) glEnable(GL_TEXTURE_RECTANGLE); else glDisable(GL_TEXTURE_RECTANGLE);
            break;
    case 1: glTexImage2D(target, ANY(small) % 3, ANY(cube_internals), w, h, pick(3) - 1, ANY(cube_formats),
                         ANY(cube_types), pick(4) ? (void *)buf : NULL);
            glTexSubImage2D(target, 0, 0, 0, w, h, ANY(cube_formats), ANY(cube_types), pick(4) ? (void *)buf : NULL);
            break;
    case 2: glTexParameteri(pick(3) ? GL_TEXTURE_2D : pick(2) ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_RECTANGLE,
                            ANY(depth_pnames), ANY(depth_values));
            glGetTexImage(target, ANY(small) % 3, pick(2) ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, buf);
            glGetTexImage(target, 0, GL_DEPTH_STENCIL, ANY(cube_types), buf); break;
    case 3: if (!pick(8)) glCopyTexImage2D(target, 0, pick(2) ? GL_DEPTH_COMPONENT : GL_RGB, 0, 0, w, h, 0);
            glTexGeni(GL_S + pick(3), GL_TEXTURE_GEN_MODE, pick(2) ? GL_REFLECTION_MAP : GL_NORMAL_MAP); break;
    default: glTexEnvi(GL_POINT_SPRITE, pick(4) ? GL_COORD_REPLACE : GL_TEXTURE_ENV_MODE, pick(4));
             if (pick(2)) glEnable(GL_POINT_SPRITE); else glDisable(GL_POINT_SPRITE);
             glPointSize(f() * 16.0f);
             glBegin(GL_POINTS); glTexCoord3f(f(), f(), f()); glVertex2f(f(), f()); glEnd(); break;
    }
}

/* The imaging subset (raises GL_INVALID_OPERATION on Mesa and gleval) and the compressed-image
 * calls: any names, NULL or not. */
static void imaging_call(void) {
    GLenum t = (GLenum)next(), fmt = pick(2) ? GL_RGBA : (GLenum)next();
    void *p = pick(4) ? (void *)buf : NULL;
    switch (pick(7)) {
    case 0: glColorTable(t, fmt, ANY(small), fmt, GL_UNSIGNED_BYTE, p); glGetColorTable(t, fmt, GL_FLOAT, p); break;
    case 1: glConvolutionFilter2D(t, fmt, ANY(small), ANY(small), fmt, GL_UNSIGNED_BYTE, p);
            glGetConvolutionParameteriv(t, (GLenum)next(), p); break;
    case 2: glSeparableFilter2D(t, fmt, ANY(small), ANY(small), fmt, GL_FLOAT, p, p);
            glGetSeparableFilter(t, fmt, GL_FLOAT, p, p, p); break;
    case 3: glHistogram(t, ANY(small), fmt, (GLboolean)pick(3)); glGetHistogram(t, GL_TRUE, fmt, GL_FLOAT, p); break;
    case 4: glMinmax(t, fmt, (GLboolean)pick(3)); glGetMinmaxParameterfv(t, (GLenum)next(), p); glResetMinmax(t); break;
    case 5: glCompressedTexImage2D(pick(2) ? GL_TEXTURE_2D : t, ANY(small) - 2, pick(2) ? GL_COMPRESSED_RGB : fmt,
                                   ANY(small), ANY(small), pick(3) - 1, ANY(small) - 4, p);
            glCompressedTexSubImage2D(pick(2) ? GL_TEXTURE_2D : t, ANY(small) - 2, 0, 0, ANY(small), ANY(small), fmt,
                                      ANY(small), p);
            glGetCompressedTexImage(pick(2) ? GL_TEXTURE_2D : t, ANY(small) - 2, p);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_ALPHA + pick(6), ANY(small), ANY(small), 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, p); break;
    default: glCopyColorTable(t, fmt, ANY(small), ANY(small), ANY(small));
             glCopyConvolutionFilter2D(t, fmt, ANY(small), ANY(small), ANY(small), ANY(small)); break;
    }
}

static void pixel_call(void) {
    GLint x = ANY(small) - 8, y = ANY(small) - 8, w = ANY(small), h = ANY(small);
    switch (pick(9)) {
    case 7:
        if (pick(2)) texture_3d_call();
        else if (pick(2)) combine_call();
        else if (pick(2)) multitexture_call();
        else cube_depth_sprite_call();
        break;
    case 0: glPixelZoom(f(), f()); glPixelTransferf(ANY(pixel_pnames), f()); glPixelTransferi(ANY(pixel_pnames), ANY(small)); break;
    case 1: glPixelMapfv(ANY(pixel_maps), ANY(map_sizes), pick(6) ? buf : NULL);
            glPixelMapuiv(ANY(pixel_maps), ANY(map_sizes), pick(6) ? (GLuint *)buf : NULL);
            glPixelMapusv(ANY(pixel_maps), ANY(map_sizes), pick(6) ? (GLushort *)buf : NULL);
            glGetPixelMapfv(ANY(pixel_maps), pick(6) ? buf : NULL); break;
    case 2: glRasterPos2f(f(), f()); glCopyPixels(x, y, ANY(grids), ANY(small), ANY(copy_types)); break;
    case 3: glRasterPos3f(f() * 0.5f, f() * 0.5f, f()); glPixelZoom(f(), f());
            glDrawPixels(w, h, pick(2) ? GL_RGB : GL_COLOR_INDEX, GL_UNSIGNED_BYTE, pick(6) ? (void *)buf : NULL); break;
    /* A copy into a texture draws the whole frame so far: now and then, or thousands of them
     * over a frame of thousands of primitives make a run of minutes. */
    case 4: if (pick(8)) break;
            glCopyTexImage2D(GL_TEXTURE_2D, ANY(small) % 3, pick(2) ? GL_RGB : GL_DEPTH_COMPONENT, x, y, w, h, pick(3) - 1);
            glCopyTexSubImage2D(GL_TEXTURE_2D, 0, x, y, x, y, w, h); break;
    case 5: if (pick(8)) break;
            glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, x, y, w, 0); glCopyTexSubImage1D(GL_TEXTURE_1D, 0, x, x, y, w);
            glTexSubImage1D(GL_TEXTURE_1D, 0, x, w, GL_RGBA, GL_UNSIGNED_BYTE, pick(6) ? (void *)buf : NULL); break;
    case 6: if (!pick(16)) imaging_call();
            if (!pick(8)) glReadPixels(x, y, w, h, ANY(read_formats), ANY(cube_types), pick(6) ? buf : NULL);
            if (!pick(8)) glDrawPixels(w, h, ANY(read_formats), ANY(cube_types), pick(6) ? buf : NULL);
            (void)glAreTexturesResident(w, names, (GLboolean *)dbuf); glPrioritizeTextures(w, names, buf); break;
    default: glIndexf(f()); glIndexfv(fp()); glIndexub((GLubyte)pick(256)); glClearIndex(f()); glIndexMask((GLuint)next()); break;
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
    for (int i = 0; i < 2; i++) tess[i] = gluNewTess();
    for (int i = 0; i < 2; i++) quads[i] = gluNewQuadric();
    for (size_t i = 0; i < sizeof buf / sizeof buf[0]; i++) {
        buf[i] = (i % 17 == 5) ? NAN : (float)((int)(i % 11) - 5) * 0.4f;
        dbuf[i] = buf[i];
    }
    for (int i = 0; i < 600; i++) indices32[i] = indices[i] = (GLushort)((i * 7919) % 600);
    for (unsigned long c = 0; c < calls; c++) {
        switch (pick(8)) {
        case 0: map_call(); break;
        case 1: nurbs_call(); break;
        case 2: tess_call(); break;
        case 3: array_call(); break;
        case 4: pixel_call(); break;
        case 5: quadric_call(); break;
        case 6: glut_call(); break;
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
    glRenderMode(GL_RENDER);
    for (int i = 0; i < 4; i++) gluDeleteNurbsRenderer(nurbs[i]);
    gluDeleteNurbsRenderer(NULL);
    for (int i = 0; i < 2; i++) gluDeleteTess(tess[i]);
    gluDeleteTess(NULL);
    for (int i = 0; i < 2; i++) gluDeleteQuadric(quads[i]);
    gluDeleteQuadric(NULL);
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
