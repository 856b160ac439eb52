/* blend.c - what Mesa's blending writes (GL 1.2's glBlendColor and glBlendEquation, GL 1.4's
 * glBlendFuncSeparate, GL 2.0's glBlendEquationSeparate) into an 8-bit RGBA buffer, one pixel
 * per case: the buffer cleared to (0.2, 0.4, 0.6, 0.8), the constant colour (0.1, 0.3, 0.5,
 * 0.7), a rectangle of colour (0.5, 0.25, 0.9, 0.3) drawn over it. The values are those of
 * `blend_equations_are_mesas_on_both_rasterisers` in tests/it/rasterizers.rs.
 *   cc blend.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[4 * 4 * 4];

int main(void)
{
    static const struct { GLenum factors[4], equations[2]; } cases[] = {
        {{GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA, GL_ONE}, {GL_FUNC_ADD, GL_FUNC_ADD}},
        {{GL_ONE, GL_ONE, GL_ONE, GL_ONE}, {GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_SUBTRACT}},
        {{GL_ZERO, GL_ZERO, GL_ZERO, GL_ZERO}, {GL_MIN, GL_MAX}},
        {{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE}, {GL_MAX, GL_FUNC_ADD}},
        {{GL_ONE, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_SRC_ALPHA_SATURATE}, {GL_FUNC_ADD, GL_FUNC_ADD}},
        {{GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_COLOR, GL_DST_COLOR, GL_ONE_MINUS_DST_ALPHA}, {GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT}},
        {{GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_DST_ALPHA}, {GL_FUNC_ADD, GL_MIN}},
    };
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 4, 4)) return 1;
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glBlendColor(0.1f, 0.3f, 0.5f, 0.7f);
    for (unsigned k = 0; k < sizeof cases / sizeof *cases; k++) {
        glDisable(GL_BLEND);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_BLEND);
        const GLenum *f = cases[k].factors;
        glBlendFuncSeparate(f[0], f[1], f[2], f[3]);
        glBlendEquationSeparate(cases[k].equations[0], cases[k].equations[1]);
        glColor4f(0.5f, 0.25f, 0.9f, 0.3f);
        glRectf(-1, -1, 1, 1);
        unsigned char p[4];
        glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        printf("%u: %d %d %d %d\n", k, p[0], p[1], p[2], p[3]);
    }
    return glGetError() != GL_NO_ERROR;
}
