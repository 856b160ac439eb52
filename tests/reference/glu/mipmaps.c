/* Prints what real GLU's gluBuild1DMipmaps, gluBuild1DMipmapLevels, gluBuild2DMipmapLevels
   and gluBuild3DMipmaps(Levels) return, the GL error they leave, and every level they loaded
   (its width and height, its texels read back as RGBA bytes), over OSMesa. Each case:
   "M name args... rc glerror", then "L level width height hex" per level loaded. The input
   comes from the generator below, which src/glu/mipmap_levels.rs's test repeats.
   Build: cc mipmaps.c -lOSMesa -lGLU -lGL */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>
#include <string.h>

static unsigned char in[4096];
static float fin[1024];

static void fill(unsigned seed) {
    unsigned state = seed;
    for (int i = 0; i < 4096; i++) {
        state = state * 1103515245u + 12345u;
        in[i] = (unsigned char)(state >> 16);
    }
    for (int i = 0; i < 1024; i++) fin[i] = in[i] / 255.0f * 1.2f - 0.1f;
}

static void levels(GLenum target, int dims) {
    static unsigned char texels[64 * 64 * 4];
    for (int level = 0; level < 12; level++) {
        GLint w = 0, h = 0;
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
        if (w == 0) continue;
        glGetTexImage(target, level, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        printf("L %d %d %d ", level, w, dims == 1 ? 1 : h);
        for (int i = 0; i < w * h * 4; i++) printf("%02x", texels[i]);
        printf("\n");
    }
}

static GLuint name = 1;

static void fresh(GLenum target) {
    glBindTexture(target, ++name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

static void build1d(GLenum format, GLenum type, int width, int user, int base, int max, int plain, unsigned seed) {
    fill(seed);
    fresh(GL_TEXTURE_1D);
    const void *data = type == GL_FLOAT ? (const void *)fin : (const void *)in;
    GLint rc = plain ? gluBuild1DMipmaps(GL_TEXTURE_1D, GL_RGBA, width, format, type, data)
                     : gluBuild1DMipmapLevels(GL_TEXTURE_1D, GL_RGBA, width, format, type, user, base, max, data);
    printf("M 1d %u %u %d %d %d %d %d %u %d %u\n", format, type, width, user, base, max, plain, seed, rc, glGetError());
    levels(GL_TEXTURE_1D, 1);
}

static void build2d(GLenum format, int width, int height, int user, int base, int max, unsigned seed) {
    fill(seed);
    fresh(GL_TEXTURE_2D);
    GLint rc = gluBuild2DMipmapLevels(GL_TEXTURE_2D, GL_RGBA, width, height, format, GL_UNSIGNED_BYTE, user, base, max, in);
    printf("M 2d %u %d %d %d %d %d %u %d %u\n", format, width, height, user, base, max, seed, rc, glGetError());
    levels(GL_TEXTURE_2D, 2);
}

static void build3d(GLenum format, GLenum type, int w, int h, int d, int user, int base, int max, int plain) {
    fill(1);
    GLint rc = plain ? gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, w, h, d, format, type, in)
                     : gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, w, h, d, format, type, user, base, max, in);
    printf("M 3d %u %u %d %d %d %d %d %d %d %d\n", format, type, w, h, d, user, base, max, plain, rc);
    glGetError();
}

int main(void) {
    static unsigned char buffer[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 4, 4);
    GLenum formats[] = {GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA};
    int widths[] = {1, 2, 5, 8, 13, 16, 33};
    unsigned seed = 1;
    for (unsigned f = 0; f < 5; f++)
        for (unsigned w = 0; w < 7; w++, seed++) {
            build1d(formats[f], GL_UNSIGNED_BYTE, widths[w], 0, 0, 0, 1, seed);
            build1d(formats[f], GL_FLOAT, widths[w], 0, 0, 0, 1, seed);
        }
    /* Levels: the whole chain, a window of it, user levels above 0, and GLU's errors. */
    build1d(GL_RGB, GL_UNSIGNED_BYTE, 16, 0, 0, 4, 0, 40);
    build1d(GL_RGB, GL_UNSIGNED_BYTE, 16, 0, 1, 3, 0, 41);
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 8, 2, 2, 5, 0, 42);
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 8, 2, 3, 4, 0, 43);
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 8, 0, 0, 4, 0, 44);  /* max beyond the chain */
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 8, 1, 0, 2, 0, 45);  /* base below user */
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 8, 0, 2, 1, 0, 46);  /* max below base */
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 0, 0, 47);
    build1d(GL_RGBA, GL_UNSIGNED_BYTE, 0, 0, 0, 0, 1, 48);
    build1d(0x1234, GL_UNSIGNED_BYTE, 8, 0, 0, 3, 0, 49);
    build1d(GL_RGBA, 0x1234, 8, 0, 0, 3, 1, 50);
    build1d(GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 8, 0, 0, 3, 1, 51);
    build1d(GL_RGB, GL_UNSIGNED_INT_8_8_8_8, 8, 0, 0, 3, 1, 52);
    for (unsigned f = 0; f < 5; f++) {
        build2d(formats[f], 8, 4, 0, 0, 3, 60 + f);
        build2d(formats[f], 4, 8, 0, 1, 2, 70 + f);
        build2d(formats[f], 16, 16, 1, 2, 4, 80 + f);
        build2d(formats[f], 1, 8, 0, 0, 3, 90 + f);
    }
    build2d(GL_RGB, 8, 4, 0, 0, 4, 100);   /* max beyond the chain */
    build2d(GL_RGB, 8, 4, 1, 0, 2, 101);   /* base below user */
    build2d(GL_RGB, 0, 4, 0, 0, 0, 102);
    build2d(0x1234, 8, 4, 0, 0, 3, 103);
    /* 3D: argument checks (GLU's return codes). */
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 0, 2, 2, 0, 0, 0, 1);
    build3d(GL_RGB, GL_BITMAP, 2, 2, 2, 0, 0, 0, 1);
    build3d(0x1234, GL_UNSIGNED_BYTE, 2, 2, 2, 0, 0, 0, 1);
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 2, 2, 2, 0, 0, 5, 0);
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 2, 2, 2, 1, 0, 1, 0);
    build3d(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, 2, 2, 2, 0, 0, 1, 0);
    OSMesaDestroyContext(ctx);
    return 0;
}
