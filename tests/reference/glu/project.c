/* gluProject, gluUnProject, gluUnProject4 and gluPickMatrix of the installed GLU on many
 * inputs: random matrices, singular ones (a repeated column, a zero row, all zero), a clip w
 * of zero, degenerate viewports. Every double is printed as its 64 bits in hex, inputs first,
 * so that tests/it reads them back exactly. gluPickMatrix's result is the modelview matrix
 * after it (floats, as GL stores them). */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <stdio.h>
#include <string.h>
#include <stdint.h>

static uint64_t state = 0x9e3779b97f4a7c15ull;
static double rnd(void)
{
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(state >> 11) / 9007199254740992.0) * 4.0 - 2.0;
}

static void hex(double d)
{
    uint64_t b;
    memcpy(&b, &d, 8);
    printf(" %016llx", (unsigned long long)b);
}

static void matrix(double m[16], int kind)
{
    for (int i = 0; i < 16; i++) m[i] = rnd();
    if (kind == 1) for (int i = 0; i < 4; i++) m[4 + i] = m[i];          /* repeated column */
    if (kind == 2) for (int i = 0; i < 4; i++) m[4 * i + 2] = 0.0;       /* zero row */
    if (kind == 3) memset(m, 0, 16 * sizeof(double));
    if (kind == 4) { memset(m, 0, 16 * sizeof(double)); m[0] = m[5] = m[10] = m[15] = 1.0; }
    if (kind == 5) { m[3] = m[7] = m[11] = m[15] = 0.0; }                 /* w row zero */
}

int main(void)
{
    static GLubyte pixels[4 * 4 * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 4, 4)) return 1;
    for (int n = 0; n < 600; n++) {
        double model[16], proj[16], in[4], out[4] = {0, 0, 0, 0};
        GLint view[4] = {(GLint)(rnd() * 50), (GLint)(rnd() * 50), (GLint)(rnd() * 200 + 400), (GLint)(rnd() * 200 + 400)};
        if (n % 37 == 0) view[2] = 0;
        matrix(model, n % 11 == 3 ? 1 : n % 13 == 4 ? 2 : n % 29 == 5 ? 3 : n % 7 == 6 ? 4 : 0);
        matrix(proj, n % 17 == 2 ? 5 : n % 19 == 7 ? 2 : n % 5 == 1 ? 4 : 0);
        for (int i = 0; i < 4; i++) in[i] = rnd();
        if (n % 23 == 9) in[3] = 0.0;
        double nearv = rnd() * 0.5 + 0.5, farv = n % 31 == 8 ? nearv : rnd() + 2.0;
        int r;
        switch (n % 3) {
        case 0: r = gluProject(in[0], in[1], in[2], model, proj, view, &out[0], &out[1], &out[2]); break;
        case 1: r = gluUnProject(in[0] * 300, in[1] * 300, in[2], model, proj, view, &out[0], &out[1], &out[2]); break;
        default:
            r = gluUnProject4(in[0] * 300, in[1] * 300, in[2], in[3], model, proj, view, nearv, farv,
                              &out[0], &out[1], &out[2], &out[3]);
        }
        printf("%d %d", n % 3, r);
        for (int i = 0; i < 16; i++) hex(model[i]);
        for (int i = 0; i < 16; i++) hex(proj[i]);
        printf(" %d %d %d %d", view[0], view[1], view[2], view[3]);
        for (int i = 0; i < 4; i++) hex(in[i]);
        hex(nearv);
        hex(farv);
        for (int i = 0; i < 4; i++) hex(out[i]);
        printf("\n");
    }
    for (int n = 0; n < 100; n++) {
        GLint view[4] = {(GLint)(rnd() * 50), (GLint)(rnd() * 50), (GLint)(rnd() * 200 + 400), (GLint)(rnd() * 200 + 400)};
        double x = (rnd() + 2) * 150, y = (rnd() + 2) * 150, dx = rnd() * 10 + 10, dy = rnd() * 10 + 10;
        if (n % 10 == 3) dx = 0;
        if (n % 10 == 4) dy = -1;
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        gluPickMatrix(x, y, dx, dy, view);
        GLfloat m[16];
        glGetFloatv(GL_MODELVIEW_MATRIX, m);
        printf("pick %d %d %d %d", view[0], view[1], view[2], view[3]);
        hex(x);
        hex(y);
        hex(dx);
        hex(dy);
        for (int i = 0; i < 16; i++) printf(" %.9g", m[i]);
        printf("\n");
    }
    OSMesaDestroyContext(ctx);
    return 0;
}
