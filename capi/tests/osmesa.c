/* OSMesa's buffer semantics, printed for a diff against real Mesa (capi/tests/against_mesa.sh osmesa): what
   a buffer held before is not the framebuffer's start (Mesa starts transparent black and copies
   the whole framebuffer in), frames drawn after a glFinish land on top of the earlier ones,
   other pixel formats (BGRA, RGB), glReadPixels, and more contexts drawing into their own
   buffers. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 8, H = 6 };

static void print(const char *what, const unsigned char *buf, int size) {
    printf("%s:", what);
    /* The corners, the centre and a pixel the second triangle covers; first row the bottom. */
    int spots[][2] = {{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}, {W / 2, H / 2}, {1, 1}, {6, 4}};
    for (size_t k = 0; k < sizeof spots / sizeof *spots; k++) {
        const unsigned char *p = buf + ((size_t)spots[k][1] * W + spots[k][0]) * size;
        printf(" (");
        for (int c = 0; c < size; c++) printf(c ? " %d" : "%d", p[c]);
        printf(")");
    }
    printf("\n");
}

static void triangle(float x0, float y0, float x1, float y1, float x2, float y2, float r, float g, float b) {
    glColor3f(r, g, b);
    glBegin(GL_TRIANGLES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glVertex2f(x2, y2);
    glEnd();
}

int main(void) {
    static unsigned char rgba[W * H * 4], bgra[W * H * 4], rgb[W * H * 3];
    memset(rgba, 40, sizeof rgba);
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!OSMesaMakeCurrent(a, rgba, GL_UNSIGNED_BYTE, W, H)) return 1;
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    triangle(0, 0, 8, 0, 0, 6, 1, 0, 0);
    glFinish();
    print("rgba after one triangle (the buffer held grey)", rgba, 4);
    triangle(8, 6, 0, 6, 8, 0, 0, 1, 0);
    glFlush();
    print("rgba after a second frame", rgba, 4);
    unsigned char read[4] = {0};
    triangle(3, 2, 5, 2, 4, 4, 0, 0, 1);
    glReadPixels(4, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
    printf("glReadPixels at (4, 2): %d %d %d %d\n", read[0], read[1], read[2], read[3]);
    print("rgba after glReadPixels", rgba, 4);

    OSMesaContext b = OSMesaCreateContextExt(OSMESA_BGRA, 24, 0, 0, NULL);
    if (!OSMesaMakeCurrent(b, bgra, GL_UNSIGNED_BYTE, W, H)) return 1;
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    triangle(0, 0, 8, 0, 0, 6, 1, 0.5f, 0);
    glFinish();
    print("bgra", bgra, 4);

    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGB, 24, 0, 0, NULL);
    if (!OSMesaMakeCurrent(c, rgb, GL_UNSIGNED_BYTE, W, H)) return 1;
    glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    print("rgb", rgb, 3);

    /* Back to the first context: its buffer keeps its picture. */
    if (!OSMesaMakeCurrent(a, rgba, GL_UNSIGNED_BYTE, W, H)) return 1;
    glFinish();
    print("rgba again", rgba, 4);
    OSMesaDestroyContext(c);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    return 0;
}
