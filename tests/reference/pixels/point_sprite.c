/* point_sprite.c - what Mesa draws for GL_ARB_point_sprite (GL 2.0 §3.3.1): an 8-pixel point
 * at the centre of an 8x8 window, textured with a 2x2 texture (red, green / blue, white) under
 * GL_REPLACE, with GL_COORD_REPLACE on (the texture spans the point, (0, 0) at its upper left)
 * and off (the vertex's texture coordinates, (0.75, 0.25), everywhere); GL_POINT_SMOOTH with
 * sprites (ignored: a square); a sprite on unit 1 only, with unit 0 the same texture; and
 * the diagonal's pixels.
 * The values are those of `point_sprites_are_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   cc point_sprite.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

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

static void point(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);
    glMultiTexCoord2f(GL_TEXTURE0, 0.75f, 0.25f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.75f, 0.25f);
    glVertex2f(0, 0);
    glEnd();
}

int main(void)
{
    static const unsigned char texels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int unit = 0; unit < 2; unit++) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, 1);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, unit ? GL_MODULATE : GL_REPLACE);
    }
    glActiveTexture(GL_TEXTURE0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glPointSize(8);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    point();
    diagonal(0);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    point();
    diagonal(1);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glEnable(GL_POINT_SMOOTH);
    point();
    diagonal(2);
    glDisable(GL_POINT_SMOOTH);
    glDisable(GL_POINT_SPRITE);
    point();
    diagonal(3);
    /* Unit 1 replaces its coordinates, unit 0 does not: (0.75, 0.25) is green on unit 0,
     * modulated by unit 1's texel across the sprite. */
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    point();
    diagonal(4);
    return glGetError() != GL_NO_ERROR;
}
