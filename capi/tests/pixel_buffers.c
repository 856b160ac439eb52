/* GL 2.1's pixel buffer objects (GL_ARB_pixel_buffer_object; GL 2.1 §3.7.4, §4.3.2, §6.1.13)
 * and GL 3.0's glMapBufferRange (GL_ARB_map_buffer_range; GL 3.0 §2.9), built against Mesa and
 * against gleval by capi/tests/against_mesa.sh, which compares what the two print: images
 * uploaded from a buffer bound to GL_PIXEL_UNPACK_BUFFER (glTexImage2D, glTexSubImage2D,
 * glDrawPixels, glBitmap, glPolygonStipple, glPixelMapfv) at an offset, read into one bound to
 * GL_PIXEL_PACK_BUFFER (glReadPixels, glGetTexImage, glGetPolygonStipple, glGetPixelMapfv) and
 * mapped back with glMapBufferRange, the bindings' queries, and the errors of accesses out of
 * the buffer, of a mapped buffer and of wrong glMapBufferRange calls. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#define W 16
#define H 16
static unsigned char buf[W * H * 4];

static void err(const char *what)
{
    printf("%s: err=0x%04x\n", what, glGetError());
}

static void show(const char *what, const unsigned char *p, int n)
{
    printf("%s:", what);
    for (int i = 0; i < n; i++) printf(" %d", p[i]);
    printf(" err=0x%04x\n", glGetError());
}

int main(void)
{
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
    GLuint b[3];
    GLint v = -1;
    glGenBuffers(3, b);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    printf("unpack binding %d err=0x%04x\n", v, glGetError());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[0]);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, b[1]);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    printf("unpack binding %d", v);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &v);
    printf(" pack binding %d err=0x%04x\n", v, glGetError());
    /* The bindings belong to the client pixel-store group. */
    glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPopClientAttrib();
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    printf("unpack binding after pop %d", v);
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPopClientAttrib();
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    printf(", after the vertex-array group's %d err=0x%04x\n", v, glGetError());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[0]);

    /* An unpack buffer of 4 x 4 RGBA texels after 8 bytes of padding. */
    unsigned char texels[8 + 64];
    for (int i = 0; i < 72; i++) texels[i] = (unsigned char)(i * 3);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof texels, texels, GL_STATIC_DRAW);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)8);
    err("teximage from buffer");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)16);
    err("teximage past the end");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)8);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, (void *)0);
    err("texsubimage from buffer");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, (void *)9);
    err("texsubimage past the end");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 5, 5, GL_RGBA, GL_UNSIGNED_BYTE, (void *)9);
    err("texsubimage too large and past the end");
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);

    /* Read back into the pack buffer at an offset, then map it. */
    glBufferData(GL_PIXEL_PACK_BUFFER, 80, NULL, GL_STREAM_READ);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)16);
    err("getteximage into buffer");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)17);
    err("getteximage past the end");
    unsigned char *m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 16, 64, GL_MAP_READ_BIT);
    if (m) show("mapped texels", m, 64); else err("map failed");
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &v);
    GLint p[4] = {-1, -1, -1, -1};
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_MAPPED, p);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_ACCESS, p + 1);
    printf("mapped %d access 0x%x err=0x%04x\n", p[0], p[1], glGetError());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, (void *)16);
    err("getteximage into a mapped buffer");
    printf("unmap %d ", glUnmapBuffer(GL_PIXEL_PACK_BUFFER));
    err("");

    /* glReadPixels into the buffer: the window cleared to a colour. */
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(2, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, (void *)4);
    err("readpixels into buffer");
    glReadPixels(0, 0, 16, 16, GL_RGBA, GL_UNSIGNED_BYTE, (void *)0);
    err("readpixels past the end");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 24, GL_MAP_READ_BIT);
    if (m) show("mapped pixels", m, 24); else err("map failed");
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);

    /* glMapBufferRange's errors, in turn. */
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, -1, 4, GL_MAP_READ_BIT);
    err("negative offset");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, -4, GL_MAP_READ_BIT);
    err("negative length");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 0, GL_MAP_READ_BIT);
    err("length 0");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 76, 8, GL_MAP_READ_BIT);
    err("past the end");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 4, 0);
    err("neither read nor write");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 4, 0x1000 | GL_MAP_READ_BIT);
    err("unknown bit");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 4, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT);
    err("read and invalidate");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 4, GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    err("read and flush explicit");
    m = glMapBufferRange(0x1234, 0, 4, GL_MAP_READ_BIT);
    err("unknown target");
    m = glMapBufferRange(0x1234, -1, 4, 0);
    err("unknown target, negative offset, no access");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, -1, 4, 0);
    err("negative offset and no access");
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 76, 8, 0);
    err("past the end and no access");

    /* Written through a range mapping, with an explicit flush. */
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 8, 8, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT);
    if (m) memset(m, 7, 8);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_ACCESS, p);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_ACCESS_FLAGS, p + 1);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_MAP_OFFSET, p + 2);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_MAP_LENGTH, p + 3);
    printf("access 0x%x flags 0x%x offset %d length %d err=0x%04x\n", p[0], p[1], p[2], p[3], glGetError());
    glFlushMappedBufferRange(GL_PIXEL_PACK_BUFFER, 0, 8);
    err("flush");
    glFlushMappedBufferRange(GL_PIXEL_PACK_BUFFER, 4, 8);
    err("flush past the mapping");
    glFlushMappedBufferRange(GL_PIXEL_PACK_BUFFER, -1, 2);
    err("flush negative offset");
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    glFlushMappedBufferRange(GL_PIXEL_PACK_BUFFER, 0, 2);
    err("flush unmapped");
    unsigned char back[16];
    glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 4, 16, back);
    show("after the write", back, 16);
    m = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, 8, GL_MAP_WRITE_BIT);
    glGetBufferParameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_ACCESS, p);
    printf("write access 0x%x ", p[0]);
    glFlushMappedBufferRange(GL_PIXEL_PACK_BUFFER, 0, 2);
    err("flush without the explicit bit");
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);

    /* glDrawPixels, glBitmap and glPolygonStipple from the unpack buffer. */
    unsigned char src[128];
    for (int i = 0; i < 128; i++) src[i] = (unsigned char)(i & 1 ? 0xAA : 0x55);
    for (int i = 0; i < 16; i++) src[i] = (unsigned char)(40 + 10 * i);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[2]);
    glBufferData(GL_PIXEL_UNPACK_BUFFER, sizeof src, src, GL_STATIC_DRAW);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glRasterPos2f(-1, -1);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, (void *)0);
    err("drawpixels from buffer");
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, (void *)0);
    err("drawpixels past the end");
    unsigned char px[16];
    glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    show("drawn", px, 16);
    glRasterPos2f(0, 0);
    glColor3f(1, 1, 1);
    glBitmap(8, 2, 0, 0, 0, 0, (void *)16);
    err("bitmap from buffer");
    glReadPixels(8, 8, 8, 1, GL_RED, GL_UNSIGNED_BYTE, px);
    show("bitmap row", px, 8);
    glPolygonStipple((void *)0);
    err("stipple from buffer");
    glPolygonStipple((void *)1);
    err("stipple past the end");
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    unsigned char st[128];
    glGetPolygonStipple(st);
    show("stipple", st, 8);
    float map[4] = {0, 0, 0, 0};
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, b[2]);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, (void *)0);
    err("pixel map from buffer");
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, map);
    printf("map %g %g err=0x%04x\n", map[0], map[1], glGetError());
    glDeleteBuffers(3, b);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &v);
    printf("unpack binding after delete %d err=0x%04x\n", v, glGetError());
    OSMesaDestroyContext(c);
    return 0;
}
