/* GL_EXT_packed_depth_stencil's pixel paths (GL 3.0 §4.3.1, §3.7.4): glReadPixels and
 * glDrawPixels of GL_DEPTH_STENCIL in GL_UNSIGNED_INT_24_8, built against Mesa and against gleval
 * by capi/tests/against_mesa.sh, which compares what the two print: four rectangles of known
 * depths and stencil values read back packed (depth in the high 24 bits, stencil in the low 8),
 * with the depth scale and bias and the index shift and offset, a packed image drawn and read
 * back as separate depths and indices, the errors of wrong calls, and depth-and-stencil textures
 * defined, replaced in part and read back packed. */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#define W 32
#define H 32
static unsigned char buf[W * H * 4];

static void rect_at(float x0, float y0, float z, int stencil)
{
    glStencilFunc(GL_ALWAYS, stencil, ~0u);
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x0 + 1, y0, z);
    glVertex3f(x0 + 1, y0 + 1, z);
    glVertex3f(x0, y0 + 1, z);
    glEnd();
}

/* The packed values at the centres of the four quadrants and one pixel of the middle. */
static void show_packed(const char *what)
{
    static const int at[5][2] = {{8, 8}, {24, 8}, {8, 24}, {24, 24}, {16, 16}};
    for (int i = 0; i < 5; i++) {
        GLuint v = 0xDEADBEEF;
        glReadPixels(at[i][0], at[i][1], 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
        printf("%s (%d,%d): 0x%08x err=0x%04x\n", what, at[i][0], at[i][1], v, glGetError());
    }
}

/* A 4 x 2 GL_DEPTH24_STENCIL8 texture from packed texels, read back packed, as depths, after a
 * packed sub-image and after a sub-image of depths alone; the wrong reads' errors. */
static void show_textures(void)
{
    GLuint texels[8], back[8];
    for (int i = 0; i < 8; i++) texels[i] = ((GLuint)(i * 0x111111) << 8) | (GLuint)(0x10 + i);
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 2, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, texels);
    GLint stencil_size = -1;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &stencil_size);
    printf("texture: err=0x%04x stencil size %d\n", glGetError(), stencil_size);
    memset(back, 0xAB, sizeof back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    printf("packed:");
    for (int i = 0; i < 8; i++) printf(" %08x", back[i]);
    printf(" err=0x%04x\n", glGetError());
    float d[8];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    printf("depths: %.6f %.6f %.6f err=0x%04x\n", d[0], d[1], d[7], glGetError());
    GLuint two[2] = {0xFFFFFF01u, 0x80000002u};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, two);
    float half[2] = {0.5f, 0.25f};
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, half);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    /* Mesa leaves the stencil of texels given depths alone undefined (it differs from run to
     * run): their depths only. */
    printf("after the sub-images: %06x %06x", back[0] >> 8, back[1] >> 8);
    for (int i = 2; i < 8; i++) printf(" %08x", back[i]);
    printf(" err=0x%04x\n", glGetError());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT, back);
    printf("packed as float: err=0x%04x\n", glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, half);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    printf("from depths alone: %06x %06x err=0x%04x\n", back[0] >> 8, back[1] >> 8, glGetError());
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, half);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    printf("packed from a depth texture: err=0x%04x\n", glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, two);
    printf("packed into a colour texture: err=0x%04x\n", glGetError());
    glDeleteTextures(2, tex);
}

/* GL_ARB_depth_buffer_float: the window read and drawn in GL_FLOAT_32_UNSIGNED_INT_24_8_REV
 * (a float depth, then a word whose low 8 bits are the stencil index), and textures of
 * GL_DEPTH_COMPONENT32F and GL_DEPTH32F_STENCIL8. */
static void show_float_depths(void)
{
    GLuint pair[4];
    memset(pair, 0xAB, sizeof pair);
    glReadPixels(8, 8, 2, 1, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, pair);
    float d0, d1;
    memcpy(&d0, &pair[0], 4);
    memcpy(&d1, &pair[2], 4);
    printf("read 32f: %.8f %08x %.8f %08x err=0x%04x\n", d0, pair[1], d1, pair[3], glGetError());
    GLuint image[2 * 2 * 2];
    float depths[4] = {0.125f, 0.5f, 1.5f, -0.25f};
    for (int i = 0; i < 4; i++) {
        memcpy(&image[2 * i], &depths[i], 4);
        image[2 * i + 1] = 0xFFFFFF00u | (GLuint)(0x40 + i);
    }
    glRasterPos2f(-1, -1);
    glDrawPixels(2, 2, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, image);
    printf("draw 32f: err=0x%04x\n", glGetError());
    GLuint packed[4];
    glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed);
    printf("drawn 32f: %08x %08x %08x %08x err=0x%04x\n", packed[0], packed[1], packed[2], packed[3], glGetError());
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, pair);
    printf("depth as 32f_24_8_rev: err=0x%04x\n", glGetError());

    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 2, 2, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, image);
    GLint size[2];
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, size);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, size + 1);
    printf("32f_s8 texture: depth %d stencil %d err=0x%04x\n", size[0], size[1], glGetError());
    GLuint back[8];
    memset(back, 0xAB, sizeof back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, back);
    for (int i = 0; i < 4; i++) {
        float d;
        memcpy(&d, &back[2 * i], 4);
        printf(" %.8f/%08x", d, back[2 * i + 1]);
    }
    printf(" err=0x%04x\n", glGetError());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    printf("as 24_8: %08x %08x %08x %08x err=0x%04x\n", back[0], back[1], back[2], back[3], glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, size);
    float f[4];
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, f);
    printf("32f texture: depth %d, %.8f %.8f %.8f %.8f err=0x%04x\n", size[0], f[0], f[1], f[2], f[3], glGetError());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, image);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    printf("24_8 texture from 32f: %08x %08x %08x %08x err=0x%04x\n", back[0], back[1], back[2], back[3], glGetError());
    glDeleteTextures(1, &tex);
}

int main(void)
{
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
    glClearDepth(0);
    glClearStencil(0xfe);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    rect_at(-1, -1, -0.5f, 0x33);
    rect_at(0, -1, -0.25f, 0x66);
    rect_at(-1, 0, 0.25f, 0x99);
    rect_at(0, 0, 0.5f, 0xbb);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    show_packed("drawn");

    /* A 2 x 2 rectangle across the middle, packed, with the pack modes. */
    GLuint four[8];
    memset(four, 0xAB, sizeof four);
    glPixelStorei(GL_PACK_ROW_LENGTH, 3);
    glReadPixels(15, 15, 2, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, four);
    printf("2x2 row length 3: %08x %08x %08x %08x %08x %08x err=0x%04x\n", four[0], four[1], four[2], four[3],
           four[4], four[5], glGetError());
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, 1);
    glReadPixels(8, 8, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, four);
    printf("swapped: %08x err=0x%04x\n", four[0], glGetError());
    glPixelStorei(GL_PACK_SWAP_BYTES, 0);

    /* The transfer: depth scale and bias, index shift and offset. */
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    show_packed("transfer");
    glPixelTransferf(GL_DEPTH_SCALE, 1);
    glPixelTransferf(GL_DEPTH_BIAS, 0);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);

    /* Wrong calls. */
    GLuint v;
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, &v);
    printf("read float: err=0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, &v);
    printf("read ubyte: err=0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_SHORT_5_6_5, &v);
    printf("read 565: err=0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, &v);
    printf("read depth as 24_8: err=0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_24_8, &v);
    printf("read rgba as 24_8: err=0x%04x\n", glGetError());
    glDrawPixels(1, 1, GL_DEPTH_STENCIL, GL_FLOAT, &v);
    printf("draw float: err=0x%04x\n", glGetError());
    glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT_24_8, &v);
    printf("draw stencil as 24_8: err=0x%04x\n", glGetError());
    glBegin(GL_POINTS);
    glReadPixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &v);
    glEnd();
    printf("read inside begin: err=0x%04x\n", glGetError());

    /* A packed image drawn (the raster position's depth is not used: the image's is), with the
     * depth test on and GL_ALWAYS, then read back as depths and indices apart. */
    static GLuint image[W * H];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double d = y < H / 2 ? (x < W / 2 ? 0.25 : 0.375) : (x < W / 2 ? 0.625 : 0.75);
            int s = (y < H / 2 ? (x < W / 2 ? ~0x33 : ~0x66) : (x < W / 2 ? ~0x99 : ~0xbb)) & 0xff;
            image[y * W + x] = (GLuint)s | ((GLuint)(d * (double)0xffffff) << 8);
        }
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glRasterPos2f(-1, -1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDrawPixels(W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    printf("draw packed: err=0x%04x\n", glGetError());
    glDisable(GL_DEPTH_TEST);
    show_packed("drawn packed");
    float d[4];
    GLubyte s[4];
    glReadPixels(8, 8, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, d);
    glReadPixels(24, 24, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, d + 2);
    glReadPixels(8, 8, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    printf("apart: %.6f %.6f %.6f %.6f stencil %d %d %d %d err=0x%04x\n", d[0], d[1], d[2], d[3], s[0], s[1], s[2],
           s[3], glGetError());

    /* Drawn with a stencil write mask and the depth test failing: the depth test does not
     * apply, the mask does (as for GL_STENCIL_INDEX images). */
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
    glStencilMask(0x0f);
    glDrawPixels(W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glStencilMask(0xff);
    glDisable(GL_DEPTH_TEST);
    show_packed("masked, depth never");
    /* The colour buffer is left as it was; the depth mask, the scissor and the transfer. */
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glColor3f(1, 0, 0);
    glRasterPos2f(-1, -1);
    glDepthMask(GL_FALSE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 16, 32);
    glDrawPixels(W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    show_packed("depth mask off, scissor");
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glDrawPixels(W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glPixelTransferf(GL_DEPTH_SCALE, 1);
    glPixelTransferf(GL_DEPTH_BIAS, 0);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    show_packed("drawn with the transfer");
    GLubyte rgba[4];
    glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    printf("colour: %d %d %d %d err=0x%04x\n", rgba[0], rgba[1], rgba[2], rgba[3], glGetError());
    GLubyte st[2];
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glReadPixels(8, 8, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    printf("stencil read with shift and offset: %d %d err=0x%04x\n", st[0], st[1], glGetError());
    /* With zoom: each image pixel covers 2 x 2. */
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glPixelZoom(2, 2);
    glDrawPixels(W / 2, H / 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, image);
    glPixelZoom(1, 1);
    show_packed("zoomed");
    show_textures();
    show_float_depths();
    OSMesaDestroyContext(c);
    return 0;
}
