/* fog_coord.c - what Mesa draws with GL 1.4's fog coordinate: an 8x8 red square fogged blue,
 * its fog from each vertex's glFogCoord under GL_FOG_COORD_SRC GL_FOG_COORD (left edge c0,
 * right edge c1), in linear fog (start 0, end 2) and GL_EXP (density 1); the same coordinates
 * from a fog coordinate array; the eye distance under GL_FRAGMENT_DEPTH though coordinates are
 * given; and a glEvalMesh2 patch, whose vertices all take the current coordinate. The pixels of
 * the diagonal; the values are those of `fog_coordinates_are_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   cc fog_coord.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

enum how { IMMEDIATE, ARRAY, EVALUATED };

int main(void)
{
    static const struct { GLenum source, mode; float c0, c1; enum how how; } setups[] = {
        {GL_FOG_COORD, GL_LINEAR, 0, 2, IMMEDIATE},     {GL_FOG_COORD, GL_LINEAR, -2, 2, IMMEDIATE},
        {GL_FOG_COORD, GL_EXP, 0, 3, IMMEDIATE},        {GL_FOG_COORD, GL_LINEAR, 0.5f, 1.5f, ARRAY},
        {GL_FRAGMENT_DEPTH, GL_LINEAR, 0, 2, IMMEDIATE}, {GL_FOG_COORD, GL_LINEAR, 0.5f, 0.5f, EVALUATED},
    };
    static const GLfloat blue[] = {0, 0, 1, 1};
    static const GLfloat patch[] = {-1, -1, 0.5f, 1, -1, 0.5f, -1, 1, 0.5f, 1, 1, 0.5f};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, blue);
    glFogf(GL_FOG_START, 0);
    glFogf(GL_FOG_END, 2);
    glFogf(GL_FOG_DENSITY, 1);
    glColor3f(1, 0, 0);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 2, patch);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(4, 0, 1, 4, 0, 1);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        float c0 = setups[k].c0, c1 = setups[k].c1;
        GLfloat xy[] = {-1, -1, 1, -1, 1, 1, -1, 1}, coords[] = {c0, c1, c1, c0};
        glFogi(GL_FOG_COORD_SRC, setups[k].source);
        glFogi(GL_FOG_MODE, setups[k].mode);
        glClear(GL_COLOR_BUFFER_BIT);
        if (setups[k].how == IMMEDIATE) {
            glBegin(GL_QUADS);
            for (int v = 0; v < 4; v++) {
                glFogCoordf(coords[v]);
                glVertex3f(xy[2 * v], xy[2 * v + 1], -0.5f);
            }
            glEnd();
        } else if (setups[k].how == ARRAY) {
            glVertexPointer(2, GL_FLOAT, 0, xy);
            glFogCoordPointer(GL_FLOAT, 0, coords);
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_FOG_COORD_ARRAY);
            glDrawArrays(GL_QUADS, 0, 4);
            glDisableClientState(GL_VERTEX_ARRAY);
            glDisableClientState(GL_FOG_COORD_ARRAY);
        } else {
            glFogCoordf(c0);
            glEvalMesh2(GL_FILL, 0, 4, 0, 4);
        }
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
