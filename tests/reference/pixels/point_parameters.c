/* point_parameters.c - the points Mesa draws with GL 1.4's point parameters: one aliased point
 * a frame (32x32, glOrtho(-1, 1, -1, 1, -100, 100), the point at the centre, eye z as given)
 * for each set-up of glPointSize, GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SIZE_MIN and
 * GL_POINT_SIZE_MAX; printed: the number of pixels drawn and their bounding box (x0 y0 x1 y1).
 * The values are those of `point_parameters_are_mesas_on_both_rasterisers` in
 * tests/it/rasterizers.rs.
 *   cc point_parameters.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

#define W 32
static unsigned char buffer[W * W * 4];

int main(void)
{
    static const struct { float size, a, b, c, min, max, z; } setups[] = {
        {8, 1, 0, 0, 0, 255, 0},  {8, 0, 1, 0, 0, 255, -2},   {8, 0, 1, 0, 0, 255, -3},
        {8, 0, 0, 1, 0, 255, -1.5f}, {1, 1, 0, 0, 3, 255, 0}, {8, 1, 0, 0, 0, 5, 0},
        {8, 0, 0, 1, 3, 255, -10}, {1, 1, 0, 0, 7, 2, 0},     {8, 2, 0, 0, 0, 255, 0},
        {6, 0, 1, 0, 0, 255, 2},  {9, 0.5f, 0.25f, 0, 0, 255, -6},
    };
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, W, W);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-1, 1, -1, 1, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    for (unsigned k = 0; k < sizeof setups / sizeof setups[0]; k++) {
        GLfloat attenuation[3] = {setups[k].a, setups[k].b, setups[k].c};
        glPointSize(setups[k].size);
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
        glPointParameterf(GL_POINT_SIZE_MIN, setups[k].min);
        glPointParameterf(GL_POINT_SIZE_MAX, setups[k].max);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_POINTS);
        glVertex3f(0, 0, setups[k].z);
        glEnd();
        glFinish();
        int n = 0, x0 = W, y0 = W, x1 = -1, y1 = -1;
        for (int y = 0; y < W; y++)
            for (int x = 0; x < W; x++)
                if (buffer[(y * W + x) * 4]) {
                    n++;
                    x0 = x < x0 ? x : x0; y0 = y < y0 ? y : y0;
                    x1 = x > x1 ? x : x1; y1 = y > y1 ? y : y1;
                }
        printf("[%d, %d, %d, %d, %d],\n", n, x0, y0, x1, y1);
    }
    return 0;
}
