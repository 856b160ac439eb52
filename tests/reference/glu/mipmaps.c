/* Prints what real GLU's gluBuild1DMipmaps, gluBuild1DMipmapLevels, gluBuild2DMipmapLevels
   and gluBuild3DMipmaps(Levels) return, the GL error they leave, and every level they loaded
   (its width and height, and depth for 3D, its texels read back as RGBA bytes), over OSMesa. Each case:
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

/* The unpack modes of the 3D cases: alignment, row length, image height, skipped rows,
   pixels and images, swap bytes. */
static const int stores[][7] = {
    {1, 0, 0, 0, 0, 0, 0}, /* 0: tightly packed */
    {4, 0, 0, 0, 0, 0, 0}, /* 1: GL's initial alignment */
    {1, 0, 0, 0, 0, 0, 1}, /* 2: swapped bytes */
    {1, 6, 0, 1, 2, 0, 0}, /* 3: a row length, skipped rows and pixels */
    {1, 0, 5, 0, 0, 1, 0}, /* 4: an image height and a skipped image */
    {2, 5, 6, 1, 1, 1, 1}, /* 5: all of them */
};

static void store3d(int s) {
    glPixelStorei(GL_UNPACK_ALIGNMENT, stores[s][0]);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, stores[s][1]);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, stores[s][2]);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, stores[s][3]);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, stores[s][4]);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, stores[s][5]);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, stores[s][6]);
}

/* Every 3D level loaded: "L level width height depth hex". */
static void levels3d(void) {
    static unsigned char texels[64 * 64 * 4];
    for (int level = 0; level < 12; level++) {
        GLint w = 0, h = 0, d = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(GL_TEXTURE_3D, level, GL_TEXTURE_DEPTH, &d);
        if (w == 0) continue;
        glGetTexImage(GL_TEXTURE_3D, level, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        printf("L %d %d %d %d ", level, w, h, d);
        for (int i = 0; i < w * h * d * 4; i++) printf("%02x", texels[i]);
        printf("\n");
    }
}

/* A 3D case: "M 3d format type w h d user base max plain store seed rc glerror", then its
   levels; the unpack modes GLU read are left as they were (printed as a check: "S" and the
   seven values, only where GLU changed them). */
static void build3d(GLenum format, GLenum type, int w, int h, int d, int user, int base, int max, int plain,
                    int store, unsigned seed) {
    fill(seed);
    fresh(GL_TEXTURE_3D);
    store3d(store);
    const void *data = type == GL_FLOAT ? (const void *)fin : (const void *)in;
    GLint rc = plain ? gluBuild3DMipmaps(GL_TEXTURE_3D, GL_RGBA, w, h, d, format, type, data)
                     : gluBuild3DMipmapLevels(GL_TEXTURE_3D, GL_RGBA, w, h, d, format, type, user, base, max, data);
    GLenum error = glGetError();
    printf("M 3d %u %u %d %d %d %d %d %d %d %d %u %d %u\n", format, type, w, h, d, user, base, max, plain, store, seed,
           rc, error);
    GLenum names[] = {GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS,
                      GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_SWAP_BYTES};
    for (int i = 0; i < 7; i++) {
        GLint v = -1;
        glGetIntegerv(names[i], &v);
        if (v != stores[store][i]) printf("S %d %d\n", i, v);
    }
    store3d(0);
    levels3d();
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
    /* 3D: argument checks (GLU's return codes), then GL's answer to a bad internal format. */
    unsigned s3 = 200;
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 0, 2, 2, 0, 0, 0, 1, 0, s3++);
    build3d(GL_RGB, GL_BITMAP, 2, 2, 2, 0, 0, 0, 1, 0, s3++);
    build3d(0x1234, GL_UNSIGNED_BYTE, 2, 2, 2, 0, 0, 0, 1, 0, s3++);
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 2, 2, 2, 0, 0, 5, 0, 0, s3++);
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 2, 2, 2, 1, 0, 1, 0, 0, s3++);
    build3d(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, 2, 2, 2, 0, 0, 1, 0, 0, s3++);
    build3d(GL_BGR, GL_UNSIGNED_BYTE_3_3_2, 2, 2, 2, 0, 0, 1, 1, 0, s3++);
    build3d(GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 2, 2, 2, 0, 0, 1, 1, 0, s3++);
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 5, 5, 5, 0, 0, 0, 0, 0, s3++); /* no level is a power of two */
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 2, 2, 0, 0, 0, 1, 0, 0, s3++);
    /* Every type, RGBA, through the levels form (the image halved as it is) and the plain one
       (scaled to powers of two first where it is not one). */
    GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
    for (unsigned t = 0; t < 7; t++) {
        build3d(GL_RGBA, types[t], 4, 4, 4, 0, 0, 2, 0, 0, s3++);
        build3d(GL_RGBA, types[t], 2, 4, 8, 0, 0, 3, 0, 0, s3++);
        build3d(GL_RGBA, types[t], 8, 2, 1, 0, 0, 3, 0, 0, s3++);  /* one image: GLU's 2D halving */
        build3d(GL_RGBA, types[t], 1, 1, 4, 0, 0, 2, 0, 0, s3++);  /* a column */
        build3d(GL_RGBA, types[t], 4, 1, 2, 0, 0, 2, 0, 0, s3++);  /* a row of images */
        build3d(GL_RGBA, types[t], 1, 4, 2, 0, 0, 2, 0, 0, s3++);
        build3d(GL_RGBA, types[t], 1, 8, 1, 0, 0, 3, 0, 0, s3++);
        build3d(GL_RGBA, types[t], 3, 2, 4, 0, 0, 2, 0, 0, s3++);  /* odd sides halved as they are */
        build3d(GL_RGBA, types[t], 4, 4, 4, 0, 0, 0, 1, 0, s3++);
        build3d(GL_RGBA, types[t], 5, 3, 2, 0, 0, 0, 1, 0, s3++);  /* scaled to 4x4x2 */
        build3d(GL_RGBA, types[t], 3, 2, 6, 0, 0, 0, 1, 0, s3++);  /* scaled to 4x2x8 */
    }
    /* The packed types with their formats. */
    GLenum packed[][2] = {
        {GL_UNSIGNED_BYTE_3_3_2, GL_RGB},         {GL_UNSIGNED_BYTE_2_3_3_REV, GL_RGB},
        {GL_UNSIGNED_SHORT_5_6_5, GL_RGB},        {GL_UNSIGNED_SHORT_5_6_5_REV, GL_RGB},
        {GL_UNSIGNED_SHORT_4_4_4_4, GL_RGBA},     {GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_BGRA},
        {GL_UNSIGNED_SHORT_5_5_5_1, GL_RGBA},     {GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_BGRA},
        {GL_UNSIGNED_INT_8_8_8_8, GL_RGBA},       {GL_UNSIGNED_INT_8_8_8_8_REV, GL_BGRA},
        {GL_UNSIGNED_INT_10_10_10_2, GL_RGBA},    {GL_UNSIGNED_INT_2_10_10_10_REV, GL_BGRA},
    };
    for (unsigned t = 0; t < 12; t++) {
        build3d(packed[t][1], packed[t][0], 4, 4, 4, 0, 0, 2, 0, 0, s3++);
        build3d(packed[t][1], packed[t][0], 4, 2, 1, 0, 0, 2, 0, 0, s3++);
        build3d(packed[t][1], packed[t][0], 1, 1, 4, 0, 0, 2, 0, 0, s3++);
        build3d(packed[t][1], packed[t][0], 4, 1, 2, 0, 0, 2, 0, 0, s3++);
        build3d(packed[t][1], packed[t][0], 1, 4, 2, 0, 0, 2, 0, 0, s3++);
        build3d(packed[t][1], packed[t][0], 2, 2, 2, 0, 0, 0, 1, 0, s3++);
        build3d(packed[t][1], packed[t][0], 5, 3, 2, 0, 0, 0, 1, 0, s3++);
    }
    /* Every format of bytes. */
    GLenum formats3[] = {GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_ALPHA, GL_BGR, GL_BGRA};
    for (unsigned f = 0; f < 7; f++) {
        build3d(formats3[f], GL_UNSIGNED_BYTE, 8, 4, 2, 0, 0, 3, 0, 0, s3++);
        build3d(formats3[f], GL_UNSIGNED_BYTE, 4, 4, 4, 0, 0, 0, 1, 0, s3++);
    }
    /* Level windows and user levels. */
    build3d(GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, 4, 0, 1, 2, 0, 0, s3++);
    build3d(GL_RGBA, GL_UNSIGNED_BYTE, 4, 2, 8, 1, 2, 3, 0, 0, s3++);
    build3d(GL_RGBA, GL_UNSIGNED_BYTE, 4, 2, 8, 2, 2, 5, 0, 0, s3++);
    build3d(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 4, 4, 2, 1, 1, 1, 0, 0, s3++);
    /* The unpack modes (rows that stay whole under GL's own alignment in every level). */
    for (int s = 1; s < 6; s++) {
        build3d(GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, 2, 0, 0, 2, 0, s, s3++);
        build3d(GL_RGBA, GL_UNSIGNED_SHORT, 4, 2, 2, 0, 0, 2, 0, s, s3++);
        build3d(GL_RGBA, GL_INT, 2, 2, 4, 0, 0, 2, 0, s, s3++);
        build3d(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 4, 4, 2, 0, 0, 2, 0, s, s3++);
        build3d(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 4, 2, 1, 0, 0, 2, 0, s, s3++);
        build3d(GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, 2, 0, 0, 0, 1, s, s3++);
        build3d(GL_RGBA, GL_UNSIGNED_SHORT, 5, 3, 2, 0, 0, 0, 1, s, s3++);
        build3d(GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 3, 2, 2, 0, 0, 0, 1, s, s3++);
    }
    build3d(GL_RGB, GL_UNSIGNED_BYTE, 6, 2, 2, 0, 0, 1, 0, 1, s3++);
    build3d(GL_LUMINANCE, GL_UNSIGNED_BYTE, 8, 4, 2, 0, 0, 3, 0, 1, s3++);
    OSMesaDestroyContext(ctx);
    return 0;
}
