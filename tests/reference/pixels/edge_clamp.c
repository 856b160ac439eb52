/* edge_clamp.c - what Mesa samples with GL 1.2's GL_CLAMP_TO_EDGE beside GL 1.1's GL_CLAMP: a
 * 2x2 texture (red, green / blue, white), linear filters, border colour (1, 0, 1, 1), on an
 * 8x8 square whose coordinates run from -0.5 to 1.5, so that a quarter of it lies outside the
 * texture on each side; the pixels of the diagonal. The values are those of
 * `edge_clamp_is_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc edge_clamp.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

#ifndef GL_CLAMP_TO_EDGE
#define GL_CLAMP_TO_EDGE 0x812F
#endif

static unsigned char buffer[8 * 8 * 4];

int main(void)
{
    static const GLenum wraps[][2] = {
        {GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE}, {GL_CLAMP, GL_CLAMP}, {GL_CLAMP_TO_EDGE, GL_CLAMP}, {GL_REPEAT, GL_CLAMP_TO_EDGE}};
    static const unsigned char texels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    static const GLfloat border[] = {1, 0, 1, 1};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (unsigned k = 0; k < sizeof wraps / sizeof *wraps; k++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[k][0]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[k][1]);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_QUADS);
        glTexCoord2f(-0.5f, -0.5f); glVertex2f(-1, -1);
        glTexCoord2f(1.5f, -0.5f); glVertex2f(1, -1);
        glTexCoord2f(1.5f, 1.5f); glVertex2f(1, 1);
        glTexCoord2f(-0.5f, 1.5f); glVertex2f(-1, 1);
        glEnd();
        printf("%u:", k);
        for (int i = 0; i < 8; i++) {
            unsigned char p[4];
            glReadPixels(i, i, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
            printf(" [%d, %d, %d, %d],", p[0], p[1], p[2], p[3]);
        }
        printf("\n");
    }
    return glGetError() != GL_NO_ERROR;
}
