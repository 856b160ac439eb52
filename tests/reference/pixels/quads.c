/* quads.c - where Mesa splits a quad into triangles: one 8x8 quad of four colours (red, green,
 * blue, olive, counter-clockwise from the bottom left) drawn seven ways, the pixels of the
 * diagonal from the bottom-left corner (red to blue along a v0-v2 split; through green and olive
 * along v1-v3). The values are those of `quad_diagonals_are_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   0 glBegin/glEnd  1 a display list  2 glDrawArrays  3 glDrawElements  4 glArrayElement
 *   5 glBegin/glEnd with a polygon stipple (all ones)  6 glBegin/glEnd, back faces GL_LINE
 *   cc quads.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

static unsigned char buffer[8 * 8 * 4];
static const GLfloat corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
static const GLfloat colours[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5f, 0.5f, 0}};

static void immediate(void)
{
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glColor3fv(colours[k]);
        glVertex2fv(corners[k]);
    }
    glEnd();
}

int main(void)
{
    static const GLubyte indices[4] = {0, 1, 2, 3};
    GLubyte stipple[128];
    memset(stipple, 0xff, sizeof stipple);
    for (int k = 0; k < 7; k++) {
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
        if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
        glVertexPointer(2, GL_FLOAT, 0, corners);
        glColorPointer(3, GL_FLOAT, 0, colours);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        switch (k) {
        case 0: immediate(); break;
        case 1: glNewList(1, GL_COMPILE); immediate(); glEndList(); glCallList(1); break;
        case 2: glDrawArrays(GL_QUADS, 0, 4); break;
        case 3: glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, indices); break;
        case 4:
            glBegin(GL_QUADS);
            for (int i = 0; i < 4; i++) glArrayElement(i);
            glEnd();
            break;
        case 5: glPolygonStipple(stipple); glEnable(GL_POLYGON_STIPPLE); immediate(); break;
        default: glPolygonMode(GL_BACK, GL_LINE); immediate(); break;
        }
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
