/* GL_ARB_texture_rectangle (GL 3.1 §3.8.1, §3.8.8), built against Mesa and against gleval by
 * capi/tests/against_mesa.sh, which compares what the two print: the target's binding, enable,
 * limit and initial parameters, the errors of what a rectangle texture does not take (levels
 * above 0, borders, repeating wraps, mipmap filters, a base level above 0), its proxy, and a
 * 3 x 2 texture drawn with unnormalised coordinates (texel centres at s = 0.5, 1.5, 2.5), over
 * a 2D texture enabled at once (the rectangle comes first); and GL_ARB_texture_non_power_of_two's
 * 2D textures of any size: a 5 x 3 image's generated mipmaps (2 x 1, then 1 x 1). */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

#define W 12
#define H 8
static unsigned char buf[W * H * 4];

static void err(const char *what)
{
    printf("%s: err=0x%04x\n", what, glGetError());
}

int main(void)
{
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, W, H)) return 1;
    GLint v[4] = {-1, -1, -1, -1}, max2d = 0;
    glGetIntegerv(GL_MAX_RECTANGLE_TEXTURE_SIZE, v);
    glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE, v + 1);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max2d);
    printf("max as 2D's %d binding %d enabled %d err=0x%04x\n", v[0] == max2d, v[1], glIsEnabled(GL_TEXTURE_RECTANGLE),
           glGetError());
    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_RECTANGLE, tex[0]);
    glGetIntegerv(GL_TEXTURE_BINDING_RECTANGLE, v);
    glGetTexParameteriv(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, v + 1);
    glGetTexParameteriv(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_T, v + 2);
    glGetTexParameteriv(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, v + 3);
    printf("bound %d wrap 0x%x 0x%x min 0x%x err=0x%04x\n", v[0], v[1], v[2], v[3], glGetError());
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    err("bound to 2D after");
    static const unsigned char texels[6][4] = {
        {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255},
        {255, 255, 0, 255}, {0, 255, 255, 255}, {255, 0, 255, 255}};
    glTexImage2D(GL_TEXTURE_RECTANGLE, 1, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    err("level 1");
    glTexImage2D(GL_TEXTURE_RECTANGLE, 0, GL_RGBA, 5, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    err("border 1");
    glTexImage1D(GL_TEXTURE_RECTANGLE, 0, GL_RGBA, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    err("1D image");
    glTexImage2D(GL_TEXTURE_RECTANGLE, 0, GL_RGBA, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    err("3 x 2");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_REPEAT);
    err("repeat");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
    err("mirrored repeat");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_CLAMP);
    err("clamp");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    err("clamp to border");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    err("mipmap filter");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    err("nearest");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_BASE_LEVEL, 1);
    err("base level 1");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_BASE_LEVEL, 0);
    err("base level 0");
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_PROXY_TEXTURE_RECTANGLE, 0, GL_RGBA, 300, 7, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_RECTANGLE, 0, GL_TEXTURE_WIDTH, v);
    glGetTexLevelParameteriv(GL_TEXTURE_RECTANGLE, 0, GL_TEXTURE_HEIGHT, v + 1);
    printf("proxy width %d height %d err=0x%04x\n", v[0], v[1], glGetError());
    unsigned char back[24];
    glGetTexImage(GL_TEXTURE_RECTANGLE, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    printf("back %d %d %d %d err=0x%04x\n", back[4], back[5], back[6], back[20], glGetError());

    /* A 2D texture of one white texel on the same unit, both enabled. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    static const unsigned char white[4] = {255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_RECTANGLE);
    printf("enabled %d err=0x%04x\n", glIsEnabled(GL_TEXTURE_RECTANGLE), glGetError());
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    /* Nearest texels here: llvmpipe's bilinear filter weighs in 8-bit fixed point, and where two
     * weights multiply (5/8 x 5/8 between four texels) gleval's float filter is one in 255 off
     * it, for a 2D texture as for a rectangle (measured); the linear row below weighs along s
     * only, where the two agree. */
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(3, 0); glVertex2f(W, 0);
    glTexCoord2f(3, 2); glVertex2f(W, H);
    glTexCoord2f(0, 2); glVertex2f(0, H);
    glEnd();
    glFinish();
    for (int y = 0; y < H; y += 4) {
        printf("row %d:", y);
        for (int x = 0; x < W; x++) printf(" %02x%02x%02x", buf[(y * W + x) * 4], buf[(y * W + x) * 4 + 1], buf[(y * W + x) * 4 + 2]);
        printf("\n");
    }
    /* Linear filtering past the edge: clamped to it. */
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_RECTANGLE, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBegin(GL_QUADS);
    glTexCoord2f(-1, 0.5f); glVertex2f(0, 0);
    glTexCoord2f(4, 0.5f); glVertex2f(W, 0);
    glTexCoord2f(4, 0.5f); glVertex2f(W, H);
    glTexCoord2f(-1, 0.5f); glVertex2f(0, H);
    glEnd();
    glFinish();
    printf("linear:");
    for (int x = 0; x < W; x++) printf(" %02x%02x%02x", buf[x * 4], buf[x * 4 + 1], buf[x * 4 + 2]);
    printf("\n");
    glDisable(GL_TEXTURE_RECTANGLE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(W, 0);
    glTexCoord2f(1, 1); glVertex2f(W, H);
    glTexCoord2f(0, 1); glVertex2f(0, H);
    glEnd();
    glFinish();
    printf("2D alone: %02x%02x%02x err=0x%04x\n", buf[0], buf[1], buf[2], glGetError());

    unsigned char npot[5 * 3 * 4], level[64];
    for (int i = 0; i < 5 * 3 * 4; i++) npot[i] = (unsigned char)(i * 17);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, npot);
    for (int l = 1; l < 3; l++) {
        GLint lw = 0, lh = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, l, GL_TEXTURE_WIDTH, &lw);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, l, GL_TEXTURE_HEIGHT, &lh);
        glGetTexImage(GL_TEXTURE_2D, l, GL_RGBA, GL_UNSIGNED_BYTE, level);
        printf("npot level %d, %d x %d:", l, lw, lh);
        for (int i = 0; i < lw * lh * 4; i++) printf(" %d", level[i]);
        printf(" err=0x%04x\n", glGetError());
    }
    OSMesaDestroyContext(c);
    return 0;
}
