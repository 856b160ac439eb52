/* cube_map.c - what Mesa samples from GL 1.3's cube maps: six 2x2 faces whose texels say the
 * face and the texel (red 40 * face + 20, green 0, 120, 0, 120 and blue 0, 0, 120, 120 for the
 * texels (0, 0), (1, 0), (0, 1), (1, 1)), on an 8x8 square whose (s, t, r) directions point at
 * each face in turn (the square's x and y the other two axes), with the nearest filter and
 * with the linear one, a direction that crosses from +Y to +X along the diagonal, and which
 * texture a unit draws with when its cube map is incomplete. The pixels of the diagonal.
 * The values are those of `cube_maps_are_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc cube_map.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[8 * 8 * 4];

/* The square with direction (s, t, r): component `axis` is `sign`, the next two (in x, y, z
 * order after it) the square's x and y scaled by `sx` and `sy`. */
static void square(int axis, float sign, float sx, float sy)
{
    static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    glBegin(GL_QUADS);
    for (int c = 0; c < 4; c++) {
        float d[3];
        d[axis] = sign;
        d[(axis + 1) % 3] = corners[c][0] * sx;
        d[(axis + 2) % 3] = corners[c][1] * sy;
        glTexCoord3f(d[0], d[1], d[2]);
        glVertex2f(corners[c][0], corners[c][1]);
    }
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
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 8, 8)) return 1;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 1);
    for (int f = 0; f < 6; f++) {
        unsigned char texels[4][3];
        for (int i = 0; i < 4; i++) {
            texels[i][0] = 40 * f + 20;
            texels[i][1] = (i & 1) ? 120 : 0;
            texels[i][2] = (i & 2) ? 120 : 0;
        }
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_CUBE_MAP);
    /* 0-5: each face, nearest. */
    for (int f = 0; f < 6; f++) {
        glClear(GL_COLOR_BUFFER_BIT);
        square(f / 2, (f & 1) ? -1.0f : 1.0f, 1, 1);
        diagonal(f);
    }
    /* 6: +X and 7: -Z, linear. */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0, 1, 1, 1);
    diagonal(6);
    glClear(GL_COLOR_BUFFER_BIT);
    square(2, -1, 1, 1);
    diagonal(7);
    /* 8: (x, 0.5, 0.9 y), +Y in the middle of the diagonal and +X or -X at its ends. */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glClear(GL_COLOR_BUFFER_BIT);
    square(1, 0.5f, 0.9f, 1);
    diagonal(8);
    /* 9: an incomplete cube map (face -Z missing) with GL_TEXTURE_2D enabled too (blue). */
    static const unsigned char blue[3] = {0, 0, 255};
    glBindTexture(GL_TEXTURE_CUBE_MAP, 2);
    for (int f = 0; f < 5; f++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, blue);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 3);
    static const unsigned char green[3] = {0, 255, 0};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, green);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glColor3f(1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0, 1, 1, 1);
    diagonal(9);
    /* 10: the same without GL_TEXTURE_2D. */
    glDisable(GL_TEXTURE_2D);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0, 1, 1, 1);
    diagonal(10);
    /* 11: the cube map made complete: it goes before GL_TEXTURE_2D. */
    glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_RGB, 1, 1, 0, GL_RGB, GL_UNSIGNED_BYTE, blue);
    glEnable(GL_TEXTURE_2D);
    glClear(GL_COLOR_BUFFER_BIT);
    square(0, 1, 1, 1);
    diagonal(11);
    return glGetError() != GL_NO_ERROR;
}
