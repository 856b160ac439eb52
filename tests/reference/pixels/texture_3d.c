/* texture_3d.c - what Mesa samples from GL 1.2's 3D textures: a 2x2x2 texture of eight colours
 * (image 0: red, green / blue, white; image 1: cyan, magenta / yellow, grey) on an 8x8 square
 * whose s and t run from 0 to 1, at several r and filters and r wraps, with r interpolated
 * across the square, and a mipmapped 4x4x4 texture minified by two; the pixels of the diagonal.
 * The values are those of `texture_3d_is_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc texture_3d.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

static unsigned char buffer[8 * 8 * 4];

struct setup { GLenum filter, wrap_r; GLfloat r0, r1; };

static void square(GLfloat r0, GLfloat r1, GLfloat st)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r0); glVertex2f(-1, -1);
    glTexCoord3f(st, 0, r1); glVertex2f(1, -1);
    glTexCoord3f(st, st, r1); glVertex2f(1, 1);
    glTexCoord3f(0, st, r0); glVertex2f(-1, 1);
    glEnd();
}

static void diagonal(int k)
{
    printf("%d:", k);
    for (int i = 0; i < 8; i++) {
        unsigned char p[4];
        glReadPixels(i, i, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        printf(" [%d, %d, %d, %d],", p[0], p[1], p[2], p[3]);
    }
    printf("\n");
}

int main(void)
{
    static const struct setup setups[] = {
        {GL_NEAREST, GL_REPEAT, 0.25f, 0.25f}, {GL_NEAREST, GL_REPEAT, 0.75f, 0.75f},
        {GL_LINEAR, GL_CLAMP_TO_EDGE, 0.5f, 0.5f}, {GL_LINEAR, GL_CLAMP_TO_EDGE, 0.375f, 0.375f},
        {GL_LINEAR, GL_REPEAT, 0, 0}, {GL_LINEAR, GL_CLAMP, 0, 0}, {GL_LINEAR, GL_CLAMP_TO_EDGE, 0, 1},
        {GL_NEAREST, GL_REPEAT, 0, 1},
    };
    static const unsigned char texels[] = {
        255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255,
        0, 255, 255, 255, 0, 255, 255, 255, 0, 128, 128, 128,
    };
    static const GLfloat border[] = {1, 0, 1, 1};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_3D, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 2, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameterfv(GL_TEXTURE_3D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_3D);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, setups[k].filter);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, setups[k].filter);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, setups[k].wrap_r);
        glClear(GL_COLOR_BUFFER_BIT);
        square(setups[k].r0, setups[k].r1, 1);
        diagonal(k);
    }
    /* Mipmaps: level 0 red, 1 green, 2 blue; s and t run to 4, so each pixel covers two texels
     * of level 0: level 1 is the nearest. */
    unsigned char level[4 * 4 * 4 * 3];
    static const unsigned char colours[3][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
    glBindTexture(GL_TEXTURE_3D, 2);
    for (int l = 0; l < 3; l++) {
        int side = 4 >> l;
        for (int i = 0; i < side * side * side; i++) memcpy(level + 3 * i, colours[l], 3);
        glTexImage3D(GL_TEXTURE_3D, l, GL_RGB, side, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0.5f, 0.5f, 4);
    diagonal(8);
    /* GL_TEXTURE_3D takes precedence over GL_TEXTURE_2D (GL 1.2 §3.8.15). */
    glBindTexture(GL_TEXTURE_2D, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, colours[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0.5f, 0.5f, 1);
    diagonal(9);
    return glGetError() != GL_NO_ERROR;
}
