/* GL/osmesa.h for gleval: OSMesa's context calls, so that programs written for off-screen
 * Mesa run on gleval. A context is a gleval GL context made current on the calling thread;
 * what it draws lands in the caller's buffer at glFinish, glFlush and glReadPixels (drawn by
 * gleval's CPU rasteriser; GL_UNSIGNED_BYTE buffers in the RGBA, BGRA, ARGB, RGB and BGR
 * formats, first row at the bottom). Written for gleval; the format values are OSMesa's. */
#ifndef GLEVAL_OSMESA_H
#define GLEVAL_OSMESA_H
#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define OSMESA_COLOR_INDEX GL_COLOR_INDEX
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4
#define OSMESA_RGB_565 0x5

typedef struct osmesa_context *OSMesaContext;

GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits, GLint accumBits, OSMesaContext sharelist);
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);

#ifdef __cplusplus
}
#endif
#endif /* GLEVAL_OSMESA_H */
