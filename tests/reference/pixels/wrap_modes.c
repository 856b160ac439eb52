/* wrap_modes.c - what Mesa samples with GL 1.3's GL_CLAMP_TO_BORDER and GL 1.4's
 * GL_MIRRORED_REPEAT beside GL_REPEAT: a 2x2 texture (red, green / blue, white), border colour
 * (1, 0, 1, 1), nearest and linear filters, on an 8x8 square whose coordinates run from -0.5
 * to 1.5 (a quarter outside the texture on each side) and on one whose coordinates run from
 * -1.5 to 2.5; the pixels of the diagonal. The values are those of
 * `wrap_modes_are_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc wrap_modes.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

#ifndef GL_MIRRORED_REPEAT
#define GL_MIRRORED_REPEAT 0x8370
#endif
#ifndef GL_CLAMP_TO_BORDER
#define GL_CLAMP_TO_BORDER 0x812D
#endif

static unsigned char buffer[8 * 8 * 4];

int main(void)
{
    static const struct { GLenum s, t, filter; float reach; } setups[] = {
        {GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_NEAREST, 0.5f},
        {GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_LINEAR, 0.5f},
        {GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT, GL_NEAREST, 1.5f},
        {GL_MIRRORED_REPEAT, GL_MIRRORED_REPEAT, GL_LINEAR, 1.5f},
        {GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER, GL_LINEAR, 0.5f},
        {GL_CLAMP_TO_BORDER, GL_REPEAT, GL_LINEAR, 1.5f},
    };
    static const unsigned char texels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    static const GLfloat border[] = {1, 0, 1, 1};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        float lo = -setups[k].reach, hi = 1 + setups[k].reach;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, setups[k].s);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, setups[k].t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, setups[k].filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, setups[k].filter);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_QUADS);
        glTexCoord2f(lo, lo); glVertex2f(-1, -1);
        glTexCoord2f(hi, lo); glVertex2f(1, -1);
        glTexCoord2f(hi, hi); glVertex2f(1, 1);
        glTexCoord2f(lo, hi); glVertex2f(-1, 1);
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
