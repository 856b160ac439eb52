/* readpixels.c: glReadPixels compared with real Mesa. The same source runs on Mesa (freeglut's
 * header, the OSMesa GLUT stand-in of tests/reference/pictures) and on gleval (glevalcc); it
 * draws rectangles of known colours, reads pixels inside them (where rasterisation rules do not
 * matter) in several formats, types and pack modes, and calls glReadPixels wrongly; both
 * outputs must be identical (capi/tests/against_mesa.sh readpixels).
 *   readpixels --png OUT.png */
#include <GL/glut.h>
#include <stdio.h>
#include <string.h>

#define W 64
#define H 48

static void show_bytes(const char *what, const unsigned char *p, int n) {
    printf("%s:", what);
    for (int i = 0; i < n; i++) printf(" %d", p[i]);
    printf(" err=0x%04x\n", glGetError());
}

static void display(void) {
    glClearColor(0.2f, 0.4f, 0.6f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, W, 0, H);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 0, 0); glRectf(4, 4, 20, 20);
    glColor4f(0, 1, 0.2f, 0.6f); glRectf(30, 4, 60, 20);
    glColor3f(1, 1, 1); glRectf(4, 30, 20, 44);

    unsigned char b[256];
    float f[64];
    unsigned short s[64];
    memset(b, 0xAB, sizeof b);
    glReadPixels(10, 10, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, b); show_bytes("rgba red 2x2", b, 16);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    memset(b, 0xAB, sizeof b);
    glReadPixels(40, 10, 3, 1, GL_RGB, GL_UNSIGNED_BYTE, b); show_bytes("rgb green 3x1 align 1", b, 10);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    memset(b, 0xAB, sizeof b);
    glReadPixels(40, 10, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, b); show_bytes("rgb green 3x2 align 4", b, 24);
    memset(b, 0xAB, sizeof b);
    glReadPixels(8, 34, 2, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, b); show_bytes("luminance white", b, 4);
    glReadPixels(40, 40, 2, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, b); show_bytes("luminance alpha clear", b, 4);
    glReadPixels(40, 10, 1, 1, GL_ALPHA, GL_UNSIGNED_BYTE, b); show_bytes("alpha green", b, 1);
    glReadPixels(40, 10, 1, 1, GL_BLUE, GL_UNSIGNED_BYTE, b); show_bytes("blue green", b, 1);
    glReadPixels(40, 40, 1, 1, GL_RGB, GL_FLOAT, f);
    printf("rgb float clear: %.4f %.4f %.4f err=0x%04x\n", f[0], f[1], f[2], glGetError());
    glReadPixels(40, 40, 1, 1, GL_RGB, GL_UNSIGNED_SHORT, s);
    printf("rgb ushort clear: %d %d %d err=0x%04x\n", s[0], s[1], s[2], glGetError());
    glPixelStorei(GL_PACK_ROW_LENGTH, 4);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    memset(b, 0xAB, sizeof b);
    glReadPixels(10, 10, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, b); show_bytes("rgba skips row length", b, 48);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    memset(b, 0xAB, sizeof b);
    glReadPixels(W - 1, 10, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, b); show_bytes("rgba past the right edge", b, 8);

    glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b); printf("negative width: 0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, b); printf("bad format: 0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, b); printf("bad type: 0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, 0x1234, 0x1234, b); printf("bad format and type: 0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, NULL); printf("NULL pixels: 0x%04x\n", glGetError());
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_BITMAP, b); printf("bitmap type: 0x%04x\n", glGetError());
    glBegin(GL_POINTS);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
    glEnd();
    printf("inside begin/end: 0x%04x\n", glGetError());
    fflush(stdout);
}

int main(int argc, char **argv) {
    glutInit(&argc, argv);
    glutInitWindowSize(W, H);
    glutCreateWindow("readpixels");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
