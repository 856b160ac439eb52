/* color_sum.c - what Mesa draws with GL 1.4's colour sum and GL 1.2's separate specular colour:
 * an 8x8 square in each of eleven set-ups, the pixels of the diagonal. The values are those of
 * `color_sum_is_mesas_on_both_rasterisers` in tests/it/rasterizers.rs, which makes the same
 * calls.
 *   0 unlit, GL_COLOR_SUM: colour (0.25, 0.5, 0.125, 0.5) plus secondary (0.5, 0.25, 0.5)
 *   1 the same without GL_COLOR_SUM
 *   2 textured (MODULATE by (128, 255, 64, 255)), then the sum
 *   3 lit (light 0, material specular (0.5, 0.25, 0), shininess 0), textured, separate specular
 *   4 the same with a single colour (the specular term is textured too)
 *   5 as 3 with GL_COLOR_SUM enabled as well (lit, the sum is made either way)
 *   6 unlit sum, then linear fog (start 0, end 2, colour (0, 0, 1)): fog comes after the sum
 *   7 a secondary colour per corner, smooth
 *   8 the same, flat: the quad's last vertex gives both colours
 *   9 as 3 on an evaluator patch (glMap2f, glEvalMesh2)
 *  10 as 0 on the evaluator patch
 *   cc color_sum.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

static void square(void)
{
    static const GLfloat corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    static const GLfloat secondary[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5f, 0.5f, 0}};
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glSecondaryColor3fv(secondary[k]);
        glVertex2fv(corners[k]);
    }
    glEnd();
}

static void quad(void)
{
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
}

static void lit(GLenum control)
{
    static const GLfloat specular[] = {0.5f, 0.25f, 0, 1};
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, control);
    glNormal3f(0, 0, 1);
}

static void textured(void)
{
    static const unsigned char texel[] = {128, 255, 64, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
}

static void patch(void)
{
    static const GLfloat points[2][2][3] = {{{-1, -1, 0}, {1, -1, 0}}, {{-1, 1, 0}, {1, 1, 0}}};
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, &points[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(4, 0, 1, 4, 0, 1);
    glEvalMesh2(GL_FILL, 0, 4, 0, 4);
}

static void draw(int k)
{
    glColor4f(0.25f, 0.5f, 0.125f, 0.5f);
    glSecondaryColor3f(0.5f, 0.25f, 0.5f);
    switch (k) {
    case 0: glEnable(GL_COLOR_SUM); quad(); break;
    case 1: quad(); break;
    case 2: glColor4f(1, 0.5f, 0.5f, 1); textured(); glEnable(GL_COLOR_SUM); quad(); break;
    case 3: textured(); lit(GL_SEPARATE_SPECULAR_COLOR); quad(); break;
    case 4: textured(); lit(GL_SINGLE_COLOR); quad(); break;
    case 5: textured(); lit(GL_SEPARATE_SPECULAR_COLOR); glEnable(GL_COLOR_SUM); quad(); break;
    case 6:
        glEnable(GL_COLOR_SUM);
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_END, 2);
        glFogfv(GL_FOG_COLOR, (const GLfloat[]){0, 0, 1, 1});
        glBegin(GL_QUADS);
        glVertex3f(-1, -1, 0.5f);
        glVertex3f(1, -1, 0.5f);
        glVertex3f(1, 1, -0.5f);
        glVertex3f(-1, 1, -0.5f);
        glEnd();
        break;
    case 7: glEnable(GL_COLOR_SUM); square(); break;
    case 8: glEnable(GL_COLOR_SUM); glShadeModel(GL_FLAT); square(); break;
    case 9: textured(); lit(GL_SEPARATE_SPECULAR_COLOR); patch(); break;
    default: glEnable(GL_COLOR_SUM); patch(); break;
    }
}

int main(void)
{
    for (int k = 0; k < 11; k++) {
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
        if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
        glClear(GL_COLOR_BUFFER_BIT);
        draw(k);
        printf("%d:", k);
        for (int i = 0; i < 8; i++) {
            unsigned char p[4];
            glReadPixels(i, i, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
            printf(" [%d, %d, %d, %d],", p[0], p[1], p[2], p[3]);
        }
        printf("\n");
        if (glGetError() != GL_NO_ERROR) return 1;
        OSMesaDestroyContext(ctx);
    }
    return 0;
}
