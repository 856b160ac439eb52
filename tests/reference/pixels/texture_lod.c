/* texture_lod.c - what Mesa samples under GL 1.2's GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL,
 * GL_TEXTURE_MIN_LOD and GL_TEXTURE_MAX_LOD: a 32x32 texture whose six levels are each one
 * colour, on a square of SIZE x SIZE pixels (lambda = log2(32 / SIZE)); the centre pixel of
 * each case. The values are those of `texture_lod_is_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   cc texture_lod.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>

static unsigned char buffer[32 * 32 * 4];
static const unsigned char colours[6][3] = {
    {255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}, {0, 255, 255}, {255, 0, 255}};

int main(void)
{
    static const struct { int size, base, max; float min_lod, max_lod; GLenum min_filter; } cases[] = {
        {8, 2, 1000, -1000, 1000, GL_NEAREST_MIPMAP_NEAREST},
        {4, 0, 1, -1000, 1000, GL_NEAREST_MIPMAP_NEAREST},
        {32, 0, 1000, 4, 1000, GL_NEAREST_MIPMAP_NEAREST},
        {4, 0, 1000, -1000, 1, GL_NEAREST_MIPMAP_NEAREST},
        {4, 1, 1000, -1000, 1000, GL_NEAREST},
        {8, 3, 2, -1000, 1000, GL_NEAREST_MIPMAP_NEAREST},
        {32, 0, 1000, 2.5f, 1000, GL_NEAREST_MIPMAP_LINEAR},
        {16, 1, 3, -1000, 1000, GL_LINEAR_MIPMAP_LINEAR},
        {2, 2, 1000, 0.5f, 1.5f, GL_NEAREST_MIPMAP_LINEAR},
    };
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 32, 32)) return 1;
    static unsigned char texels[32 * 32 * 3];
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int level = 0; level < 6; level++) {
        int side = 32 >> level;
        for (int i = 0; i < side * side; i++)
            for (int c = 0; c < 3; c++) texels[3 * i + c] = colours[level][c];
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGB, side, side, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glColor3f(0.5f, 0.5f, 0.5f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (unsigned k = 0; k < sizeof cases / sizeof *cases; k++) {
        glClear(GL_COLOR_BUFFER_BIT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, cases[k].base);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, cases[k].max);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, cases[k].min_lod);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, cases[k].max_lod);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, cases[k].min_filter);
        glViewport(0, 0, cases[k].size, cases[k].size);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0); glVertex2f(-1, -1);
        glTexCoord2f(1, 0); glVertex2f(1, -1);
        glTexCoord2f(1, 1); glVertex2f(1, 1);
        glTexCoord2f(0, 1); glVertex2f(-1, 1);
        glEnd();
        unsigned char p[4];
        glReadPixels(cases[k].size / 2, cases[k].size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        printf("%u: %d %d %d %d\n", k, p[0], p[1], p[2], p[3]);
    }
    return glGetError() != GL_NO_ERROR;
}
