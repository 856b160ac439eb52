/* depth_texture.c - what Mesa samples from GL 1.4's depth textures: a 4x1 GL_DEPTH_COMPONENT
 * texture of depths 0.1, 0.4, 0.6 and 0.9 on an 8x8 square whose s runs from 0 to 1 and
 * whose r runs from r0 at the left to r1 at the right, under each GL_DEPTH_TEXTURE_MODE, with
 * and without GL_ARB_shadow's comparison (GL_TEXTURE_COMPARE_MODE GL_COMPARE_R_TO_TEXTURE)
 * under several functions and filters. The pixels of the diagonal.
 * The values are those of `depth_textures_are_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   cc depth_texture.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

struct setup { GLenum mode, compare, func, filter, env; GLfloat r0, r1; };

static void square(GLfloat r0, GLfloat r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0.5f, r0); glVertex2f(-1, -1);
    glTexCoord3f(1, 0.5f, r1); glVertex2f(1, -1);
    glTexCoord3f(1, 0.5f, r1); glVertex2f(1, 1);
    glTexCoord3f(0, 0.5f, r0); glVertex2f(-1, 1);
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
        {GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_INTENSITY, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_ALPHA, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_RED, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_LUMINANCE, GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_INTENSITY, GL_COMPARE_R_TO_TEXTURE, GL_GREATER, GL_NEAREST, GL_REPLACE, 0, 1},
        {GL_LUMINANCE, GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, GL_LINEAR, GL_REPLACE, 0, 1},
        {GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_NEAREST, GL_MODULATE, 0, 1},
        {GL_LUMINANCE, GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, GL_NEAREST, GL_REPLACE, -1, 2},
        {GL_LUMINANCE, GL_NONE, GL_LEQUAL, GL_LINEAR, GL_REPLACE, 0, 1},
        {GL_ALPHA, GL_COMPARE_R_TO_TEXTURE, GL_LESS, GL_NEAREST, GL_MODULATE, 0.5f, 0.5f},
        {GL_LUMINANCE, GL_COMPARE_R_TO_TEXTURE, GL_ALWAYS, GL_NEAREST, GL_REPLACE, 0, 1},
    };
    static const GLfloat depths[4] = {0.1f, 0.4f, 0.6f, 0.9f};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_2D);
    glColor4f(0.5f, 1, 0.25f, 0.5f);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        const struct setup *s = &setups[k];
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, s->mode);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, s->compare);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, s->func);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, s->filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, s->filter);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, s->env);
        glClear(GL_COLOR_BUFFER_BIT);
        square(s->r0, s->r1);
        diagonal(k);
    }
    return glGetError() != GL_NO_ERROR;
}
