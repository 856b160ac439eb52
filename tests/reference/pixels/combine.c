/* combine.c - what Mesa draws with GL 1.3's GL_COMBINE texture environment: a 1x1 texture
 * (0.8, 0.6, 0.4, 0.5) of several base formats, the primary colour (0.5, 0.25, 1, 0.75) and
 * the constant colour (0.9, 0.8, 0.1, 0.3), each combiner function, source and operand, the
 * scales, DOT3; one pixel each. The values are those of `combine_is_mesas_on_both_rasterisers`
 * in tests/it/rasterizers.rs.
 *   cc combine.c -lOSMesa -lGL && GALLIUM_DRIVER=llvmpipe ./a.out */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buffer[2 * 2 * 4];

/* One half of the combiner: function, three sources, three operands, scale. */
struct half { GLenum f, s[3], o[3]; GLfloat scale; };
struct setup { GLenum format; struct half rgb, alpha; };

#define T GL_TEXTURE
#define K GL_CONSTANT
#define P GL_PRIMARY_COLOR
#define V GL_PREVIOUS
#define SC GL_SRC_COLOR
#define MC GL_ONE_MINUS_SRC_COLOR
#define SA GL_SRC_ALPHA
#define MA GL_ONE_MINUS_SRC_ALPHA

int main(void)
{
    static const struct setup setups[] = {
        {GL_RGBA, {GL_MODULATE, {T, V, K}, {SC, SC, SA}, 1}, {GL_MODULATE, {T, V, K}, {SA, SA, SA}, 1}},
        {GL_RGBA, {GL_REPLACE, {K, V, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {K, V, K}, {SA, SA, SA}, 1}},
        {GL_RGBA, {GL_ADD, {T, P, K}, {SC, SC, SA}, 1}, {GL_ADD, {T, P, K}, {SA, SA, SA}, 1}},
        {GL_RGBA, {GL_ADD_SIGNED, {T, P, K}, {SC, SC, SA}, 2}, {GL_ADD_SIGNED, {T, K, K}, {SA, SA, SA}, 2}},
        {GL_RGBA, {GL_INTERPOLATE, {T, P, K}, {SC, SC, SA}, 1}, {GL_INTERPOLATE, {T, P, K}, {SA, SA, SA}, 1}},
        {GL_RGBA, {GL_SUBTRACT, {T, K, K}, {SC, SC, SA}, 1}, {GL_SUBTRACT, {P, T, K}, {SA, SA, SA}, 4}},
        {GL_RGBA, {GL_DOT3_RGB, {T, K, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {P, T, K}, {SA, SA, SA}, 1}},
        {GL_RGBA, {GL_DOT3_RGBA, {T, T, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {P, T, K}, {SA, SA, SA}, 4}},
        {GL_RGBA, {GL_DOT3_RGB, {T, P, K}, {MC, SC, SA}, 4}, {GL_MODULATE, {P, K, K}, {MA, SA, SA}, 2}},
        {GL_RGBA, {GL_MODULATE, {T, K, K}, {MC, SA, SA}, 2}, {GL_MODULATE, {T, K, K}, {MA, MA, SA}, 1}},
        {GL_RGBA, {GL_INTERPOLATE, {K, P, T}, {SC, MC, MA}, 1}, {GL_INTERPOLATE, {K, P, T}, {SA, MA, MA}, 1}},
        {GL_LUMINANCE, {GL_MODULATE, {T, V, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {T, V, K}, {SA, SA, SA}, 1}},
        {GL_ALPHA, {GL_ADD, {T, V, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {T, V, K}, {SA, SA, SA}, 1}},
        {GL_INTENSITY, {GL_ADD, {T, K, K}, {SC, SC, SA}, 1}, {GL_ADD, {T, K, K}, {SA, SA, SA}, 1}},
        {GL_LUMINANCE_ALPHA, {GL_REPLACE, {T, V, K}, {SA, SC, SA}, 1}, {GL_REPLACE, {T, V, K}, {MA, SA, SA}, 1}},
        {GL_RGB, {GL_REPLACE, {GL_TEXTURE0, V, K}, {SC, SC, SA}, 1}, {GL_REPLACE, {GL_TEXTURE0, V, K}, {SA, SA, SA}, 1}},
    };
    static const unsigned char texel[] = {204, 153, 102, 128};
    static const GLfloat constant[] = {0.9f, 0.8f, 0.1f, 0.3f};
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, 2, 2)) return 1;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glEnable(GL_TEXTURE_2D);
    for (unsigned k = 0; k < sizeof setups / sizeof *setups; k++) {
        const struct setup *s = &setups[k];
        /* The texel's components as the format reads them: luminance and intensity from the
         * first byte, alpha from the last. */
        unsigned char image[4] = {texel[0], texel[1], texel[2], texel[3]};
        if (s->format == GL_ALPHA) image[0] = texel[3];
        if (s->format == GL_LUMINANCE_ALPHA) image[1] = texel[3];
        glTexImage2D(GL_TEXTURE_2D, 0, s->format, 1, 1, 0,
                     s->format == GL_ALPHA ? GL_ALPHA : s->format == GL_LUMINANCE_ALPHA ? GL_LUMINANCE_ALPHA
                     : s->format == GL_LUMINANCE || s->format == GL_INTENSITY ? GL_LUMINANCE : GL_RGBA,
                     GL_UNSIGNED_BYTE, image);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, s->rgb.f);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, s->alpha.f);
        for (int i = 0; i < 3; i++) {
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB + i, s->rgb.s[i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA + i, s->alpha.s[i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB + i, s->rgb.o[i]);
            glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA + i, s->alpha.o[i]);
        }
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, s->rgb.scale);
        glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, s->alpha.scale);
        glColor4f(0.5f, 0.25f, 1.0f, 0.75f);
        glRectf(-1, -1, 1, 1);
        unsigned char p[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        printf("        [%d, %d, %d, %d],\n", p[0], p[1], p[2], p[3]);
    }
    return glGetError() != GL_NO_ERROR;
}
