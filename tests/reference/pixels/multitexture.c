/* multitexture.c - what Mesa draws with GL 1.3's texture units (GL 1.3 section 3.8.15): each
 * enabled unit applies its environment to the previous unit's result. Three 2x2 textures (A:
 * RGB on unit 0, B: RGBA on unit 1, C: luminance on unit 2), nearest filtered, over an 8x8
 * window covered by one quad whose units' coordinates run 0..1 (glMultiTexCoord2f); the
 * primary colour (0.5, 0.75, 1, 0.5). Set-ups: modulate then add; replace then decal; unit 0
 * disabled (skipped); three units (modulate, add, blend); texgen on unit 1 (object linear, s
 * reversed);
 * a texture matrix on unit 1; GL_COMBINE on unit 1 interpolating between unit 0's texel
 * (GL_TEXTURE0, ARB_texture_env_crossbar) and its own; glDrawPixels textured by unit 1 (unit 0
 * disabled), whose raster coordinates (0.75, 0.25) llvmpipe does not use: it samples texel 0, 0. Printed: the diagonal pixels (i, i), i = 0..7, per set-up, the
 * values of `multitexture_is_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc multitexture.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

static const unsigned char image_a[] = {200, 40, 40, 40, 200, 40, 40, 40, 200, 240, 240, 240};
static const unsigned char image_b[] = {20, 60, 100, 255, 100, 20, 60, 64, 60, 100, 20, 128, 0, 0, 0, 192};
static const unsigned char image_c[] = {51, 102, 153, 204};

static void texture(GLenum unit, GLuint name, GLenum format, const unsigned char *image)
{
    glActiveTexture(unit);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)format, 2, 2, 0, format, GL_UNSIGNED_BYTE, image);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

static void unit(GLenum u, int enabled, GLenum mode)
{
    glActiveTexture(u);
    if (enabled) glEnable(GL_TEXTURE_2D); else glDisable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)mode);
}

static void quad(void)
{
    static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glColor4f(0.5f, 0.75f, 1.0f, 0.5f);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        float s = (corners[k][0] + 1) / 2, t = (corners[k][1] + 1) / 2;
        glMultiTexCoord2f(GL_TEXTURE0, s, t);
        glMultiTexCoord2f(GL_TEXTURE1, s, t);
        glMultiTexCoord2f(GL_TEXTURE2, s, t);
        glVertex2f(corners[k][0], corners[k][1]);
    }
    glEnd();
}

static void print_diagonal(int setup)
{
    printf("set-up %d:", setup);
    for (int i = 0; i < 8; i++) {
        const unsigned char *p = buffer + (i * 8 + i) * 4;
        printf(" [%d, %d, %d, %d]%s", p[0], p[1], p[2], p[3], i < 7 ? "," : "");
    }
    printf("\n");
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    static const GLfloat env[] = {0.25f, 0.5f, 0.75f, 1.0f};
    static const GLfloat plane_s[] = {-0.5f, 0.0f, 0.0f, 0.5f};
    static const GLfloat plane_t[] = {0.0f, 0.5f, 0.0f, 0.5f};
    texture(GL_TEXTURE0, 1, GL_RGB, image_a);
    texture(GL_TEXTURE1, 2, GL_RGBA, image_b);
    texture(GL_TEXTURE2, 3, GL_LUMINANCE, image_c);
    glActiveTexture(GL_TEXTURE2);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    for (int setup = 0; setup < 8; setup++) {
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        unit(GL_TEXTURE2, setup == 3, GL_BLEND);
        glActiveTexture(GL_TEXTURE1);
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        switch (setup) {
        case 0: unit(GL_TEXTURE0, 1, GL_MODULATE); unit(GL_TEXTURE1, 1, GL_ADD); break;
        case 1: unit(GL_TEXTURE0, 1, GL_REPLACE); unit(GL_TEXTURE1, 1, GL_DECAL); break;
        case 2: unit(GL_TEXTURE0, 0, GL_REPLACE); unit(GL_TEXTURE1, 1, GL_MODULATE); break;
        case 3: unit(GL_TEXTURE0, 1, GL_MODULATE); unit(GL_TEXTURE1, 1, GL_ADD); break;
        case 4:
            unit(GL_TEXTURE0, 1, GL_MODULATE);
            unit(GL_TEXTURE1, 1, GL_REPLACE);
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
            glTexGenfv(GL_S, GL_OBJECT_PLANE, plane_s);
            glTexGenfv(GL_T, GL_OBJECT_PLANE, plane_t);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
            break;
        case 5:
            unit(GL_TEXTURE0, 1, GL_MODULATE);
            unit(GL_TEXTURE1, 1, GL_MODULATE);
            glMatrixMode(GL_TEXTURE);
            glTranslatef(0.25f, 0.0f, 0.0f);
            glMatrixMode(GL_MODELVIEW);
            break;
        case 6:
            unit(GL_TEXTURE0, 1, GL_REPLACE);
            unit(GL_TEXTURE1, 1, GL_COMBINE);
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE0);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
            glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_MODULATE);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE);
            break;
        default: break;
        }
        if (setup == 7) {
            static unsigned char white[8 * 8 * 4];
            for (unsigned k = 0; k < sizeof white; k++) white[k] = 255;
            unit(GL_TEXTURE0, 0, GL_REPLACE);
            unit(GL_TEXTURE1, 1, GL_MODULATE);
            glMultiTexCoord2f(GL_TEXTURE1, 0.75f, 0.25f);
            glRasterPos2f(-1, -1);
            glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, white);
        } else {
            quad();
        }
        glFinish();
        print_diagonal(setup);
    }
    return 0;
}
