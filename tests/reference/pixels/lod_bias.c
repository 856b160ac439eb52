/* lod_bias.c - what Mesa samples with GL 1.4's LOD bias: an 8x8 texture whose levels are red
 * (8x8), green (4x4), blue (2x2) and white (1x1), on an 8x8 square whose coordinates run from 0
 * to `scale` (lambda = log2(scale)), with the unit's bias (GL_TEXTURE_FILTER_CONTROL), the
 * object's (GL_TEXTURE_LOD_BIAS), a filter and GL_TEXTURE_MAX_LOD; the pixels of the diagonal.
 * The values are those of `lod_bias_is_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc lod_bias.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

int main(void)
{
    static const struct { GLenum filter; float unit, object, scale, max_lod; } setups[] = {
        {GL_NEAREST_MIPMAP_NEAREST, 1, 0, 1, 1000},    {GL_NEAREST_MIPMAP_NEAREST, 0, 2, 1, 1000},
        {GL_NEAREST_MIPMAP_NEAREST, 1.5f, 1.5f, 1, 1000}, {GL_LINEAR_MIPMAP_LINEAR, 0.5f, 0, 1, 1000},
        {GL_NEAREST_MIPMAP_NEAREST, 20, 0, 1, 1000},   {GL_NEAREST_MIPMAP_NEAREST, -1, 0, 2, 1000},
        {GL_NEAREST_MIPMAP_NEAREST, 2, 0, 1, 1},       {GL_LINEAR_MIPMAP_LINEAR, -0.25f, 1, 1, 1000},
    };
    static const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    static GLubyte level[8 * 8 * 3];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int l = 0, side = 8; l < 4; l++, side /= 2) {
        for (int k = 0; k < side * side * 3; k++) level[k] = colours[l][k % 3];
        glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, level);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        float s = setups[k].scale;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, setups[k].filter);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, setups[k].object);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, setups[k].max_lod);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, setups[k].unit);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(-1, -1);
        glTexCoord2f(s, 0); glVertex2f(1, -1);
        glTexCoord2f(s, s); glVertex2f(1, 1);
        glTexCoord2f(0, s); glVertex2f(-1, 1);
        glEnd();
        printf("        [");
        for (int i = 0; i < 8; i++) {
            unsigned char p[4];
            glReadPixels(i, i, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
            printf("[%d, %d, %d, %d]%s", p[0], p[1], p[2], p[3], i < 7 ? ", " : "");
        }
        printf("],\n");
    }
    return glGetError() != GL_NO_ERROR;
}
