/* Prints what real GLU's gluScaleImage writes, for every format GLU takes with every pair of
   GL 1.1 types (GL_BITMAP included), a few sizes (shrinking, growing, exact halving, 1-pixel
   sides) and pixel-store modes (alignment, row length, skips, swapped bytes, LSB first), plus
   its errors. Each case: "S format typein typeout win hin wout hout store rc", then the output
   buffer in hex up to its last written byte (the buffer starts as 0xcd bytes). The input
   comes from the generator below, which tests/it/glu_mipmaps.rs repeats.
   Build: cc scale_image.c -lOSMesa -lGLU -lGL */
#include <GL/osmesa.h>
#include <GL/glu.h>
#include <stdio.h>
#include <string.h>

#define BUF 16384
static unsigned char in[BUF], out[BUF];
static unsigned state;

static unsigned next(void) { state = state * 1103515245u + 12345u; return (state >> 16) & 0xffffu; }

/* Bytes, or floats in [-0.25, 1.25) for GL_FLOAT. */
static void fill(GLenum type, unsigned seed) {
    state = seed;
    if (type == GL_FLOAT) {
        for (int i = 0; i < BUF / 4; i++) {
            float f = next() / 65536.0f * 1.5f - 0.25f;
            memcpy(in + 4 * i, &f, 4);
        }
    } else {
        for (int i = 0; i < BUF; i++) in[i] = (unsigned char)next();
    }
}

/* Pixel-store settings: 0 plain, 1 unpack modes, 2 pack modes, 3 both with swapped bytes. */
static void store(int s) {
    int u = s == 1 || s == 3, p = s == 2 || s == 3;
    glPixelStorei(GL_UNPACK_ALIGNMENT, u ? 8 : 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, u ? 9 : 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, u ? 2 : 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, u ? 3 : 0);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, s == 3);
    glPixelStorei(GL_UNPACK_LSB_FIRST, u);
    glPixelStorei(GL_PACK_ALIGNMENT, p ? 8 : 2);
    glPixelStorei(GL_PACK_ROW_LENGTH, p ? 11 : 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, p ? 1 : 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, p ? 5 : 0);
    glPixelStorei(GL_PACK_SWAP_BYTES, s == 3);
    glPixelStorei(GL_PACK_LSB_FIRST, p);
}

static void run(GLenum format, GLenum tin, GLenum tout, int win, int hin, int wout, int hout, int s, unsigned seed) {
    fill(tin, seed);
    memset(out, 0xcd, BUF);
    store(s);
    GLint rc = gluScaleImage(format, win, hin, tin, in, wout, hout, tout, out);
    printf("S %u %u %u %d %d %d %d %d %u %d\n", format, tin, tout, win, hin, wout, hout, s, seed, rc);
    int end = BUF;
    while (end > 0 && out[end - 1] == 0xcd) end--;
    for (int i = 0; i < end; i++) printf("%02x", out[i]);
    printf("\n");
}

int main(void) {
    static unsigned char buffer[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 4, 4);
    GLenum formats[] = {GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_DEPTH_COMPONENT, GL_RED, GL_GREEN, GL_BLUE,
                        GL_ALPHA, GL_RGB, GL_RGBA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_BGR, GL_BGRA};
    GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT, GL_BITMAP};
    int sizes[][4] = {{5, 3, 3, 2}, {3, 2, 5, 3}, {4, 4, 2, 2}, {2, 3, 7, 1}, {1, 1, 2, 3}, {6, 5, 4, 5}, {7, 2, 3, 4}};
    unsigned seed = 1;
    for (unsigned f = 0; f < sizeof formats / sizeof formats[0]; f++)
        for (unsigned a = 0; a < 8; a++)
            for (unsigned b = 0; b < 8; b++, seed++) {
                int *z = sizes[seed % 7];
                run(formats[f], types[a], types[b], z[0], z[1], z[2], z[3], (int)(seed % 4), seed);
            }
    /* Larger images, plain modes. */
    run(GL_RGB, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, 37, 23, 16, 16, 0, 7);
    run(GL_LUMINANCE_ALPHA, GL_FLOAT, GL_UNSIGNED_SHORT, 13, 29, 40, 9, 0, 8);
    run(GL_RGBA, GL_SHORT, GL_FLOAT, 10, 10, 3, 17, 0, 9);
    /* Errors and empty sizes. */
    run(GL_RGB, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, 0, 3, 2, 2, 0, 1);
    run(GL_RGB, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, -1, 3, 2, 2, 0, 1);
    run(GL_RGB, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, 2, 3, 2, -2, 0, 1);
    run(0x1234, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE, 2, 3, 2, 2, 0, 1);
    run(GL_RGB, GL_DOUBLE, GL_UNSIGNED_BYTE, 2, 3, 2, 2, 0, 1);
    run(GL_RGB, GL_UNSIGNED_BYTE, 0x1234, 2, 3, 2, 2, 0, 1);
    run(GL_RGBA, GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_BYTE, 2, 3, 2, 2, 0, 1);
    run(GL_RGB, GL_UNSIGNED_BYTE, GL_UNSIGNED_INT_8_8_8_8, 2, 3, 2, 2, 0, 1);
    run(0x1234, GL_UNSIGNED_BYTE, GL_UNSIGNED_INT_8_8_8_8, -2, 3, 2, 2, 0, 1);
    OSMesaDestroyContext(ctx);
    return 0;
}
