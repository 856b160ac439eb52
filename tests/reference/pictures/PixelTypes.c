// PixelTypes.c: the pixel path past bytes and floats. Bottom row: one colour ramp drawn from
// seven client types (GL_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, and the
// packed GL_UNSIGNED_BYTE_3_3_2 and GL_BGRA GL_UNSIGNED_INT_8_8_8_8_REV). Then a depth ramp
// drawn with glDrawPixels and a green quad tested against it; a checker of stencil indices
// drawn with glDrawPixels and a blue quad through the stencil test; a grey ramp drawn with a
// texture bound, coloured by the texel at the raster position's coordinates; an intensity
// texture under GL_MODULATE and GL_BLEND, blended over the background; a texture given with a
// one-texel border (which Mesa strips) under GL_CLAMP and a linear filter; and a colour-index
// bitmap made a texture through the I_TO_R/G/B/A maps.
#include "gl.h"
#include <stdint.h>

#define W 32
#define H 16
static GLbyte bytes[H][W][3];
static GLshort shorts[H][W][3];
static GLushort ushorts[H][W][3];
static GLint ints[H][W][3];
static GLuint uints[H][W][3];
static GLubyte packed332[H][W];
static GLuint packed8888[H][W];
static GLfloat depths[H][96];
static GLubyte stencils[H][96];
static GLubyte greys[H][64];

static void init(void)
{
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double c[3] = {i / 31.0, j / 15.0, 0.5};
            for (int k = 0; k < 3; k++) {
                bytes[j][i][k] = (GLbyte)(c[k] * 127.0 + 0.5);
                shorts[j][i][k] = (GLshort)(c[k] * 32767.0 + 0.5);
                ushorts[j][i][k] = (GLushort)(c[k] * 65535.0 + 0.5);
                ints[j][i][k] = (GLint)(c[k] * 2147483647.0);
                uints[j][i][k] = (GLuint)(c[k] * 4294967295.0);
            }
            packed332[j][i] = (GLubyte)(((i * 7 / 31) << 5) | ((j * 7 / 15) << 2) | 2);
            packed8888[j][i] = (GLuint)(255u << 24 | (uint32_t)(i * 255 / 31) << 16 | (uint32_t)(j * 17) << 8 | 128u);
        }
    for (int j = 0; j < H; j++) {
        for (int i = 0; i < 96; i++) {
            depths[j][i] = i / 95.0f;
            stencils[j][i] = (GLubyte)(((i / 8) + (j / 8)) % 2);
        }
        for (int i = 0; i < 64; i++)
            greys[j][i] = (GLubyte)(4 * i);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glClearColor(0.3, 0.3, 0.3, 1.0);
}

static void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, w, 0.0, h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void quad(int x, int y, int w, int h)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0.0, 0.0);
    glVertex2i(x, y);
    glTexCoord2f(1.0, 0.0);
    glVertex2i(x + w, y);
    glTexCoord2f(1.0, 1.0);
    glVertex2i(x + w, y + h);
    glTexCoord2f(0.0, 1.0);
    glVertex2i(x, y + h);
    glEnd();
}

static void types(void)
{
    glRasterPos2i(8, 8);
    glDrawPixels(W, H, GL_RGB, GL_BYTE, bytes);
    glRasterPos2i(44, 8);
    glDrawPixels(W, H, GL_RGB, GL_SHORT, shorts);
    glRasterPos2i(80, 8);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_SHORT, ushorts);
    glRasterPos2i(116, 8);
    glDrawPixels(W, H, GL_RGB, GL_INT, ints);
    glRasterPos2i(152, 8);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_INT, uints);
    glRasterPos2i(188, 8);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, packed332);
    glRasterPos2i(224, 8);
    glDrawPixels(W, H, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, packed8888);
}

static void depth_and_stencil(void)
{
    glEnable(GL_DEPTH_TEST);
    glColor3f(1.0, 0.0, 0.0);
    glRasterPos2i(8, 32);
    glDrawPixels(96, H, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    glColor3f(0.0, 1.0, 0.0);
    quad(8, 32, 96, H);
    glDisable(GL_DEPTH_TEST);

    glRasterPos2i(140, 32);
    glDrawPixels(96, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencils);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glColor3f(0.2, 0.4, 1.0);
    quad(140, 32, 96, H);
    glDisable(GL_STENCIL_TEST);
}

static void textured_pixels(void)
{
    static GLubyte four[2][2][4] = {{{255, 0, 0, 255}, {0, 255, 0, 255}}, {{0, 0, 255, 255}, {255, 255, 255, 255}}};
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, four);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glColor3f(1.0, 1.0, 1.0);
    glTexCoord2f(0.75, 0.25);
    glRasterPos2i(8, 56);
    glDrawPixels(64, H, GL_LUMINANCE, GL_UNSIGNED_BYTE, greys);
    glTexCoord2f(0.25, 0.75);
    glRasterPos2i(80, 56);
    glDrawPixels(64, H, GL_LUMINANCE, GL_UNSIGNED_BYTE, greys);
    glDisable(GL_TEXTURE_2D);
}

static void intensity(void)
{
    static GLubyte ramp[4][4];
    static GLfloat env[4] = {1.0, 0.5, 0.0, 1.0};
    for (int j = 0; j < 4; j++)
        for (int i = 0; i < 4; i++)
            ramp[j][i] = (GLubyte)(i * 80 + j * 5);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_INTENSITY, 4, 4, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, ramp);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.0, 0.4, 1.0, 1.0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    quad(8, 80, 64, H);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    quad(80, 80, 64, H);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
}

static void border_and_bitmap(void)
{
    static GLubyte bordered[6][6][4];
    static GLfloat yellow[4] = {1.0, 1.0, 0.0, 1.0};
    static GLubyte bits[8] = {0xF0, 0xF0, 0xF0, 0xF0, 0x0F, 0x0F, 0x0F, 0x0F};
    static GLfloat to_r[2] = {0.1, 1.0}, to_g[2] = {0.6, 0.2}, to_b[2] = {0.3, 0.8}, to_a[2] = {1.0, 1.0};
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 6; i++) {
            int edge = i == 0 || j == 0 || i == 5 || j == 5;
            bordered[j][i][0] = edge ? 255 : (GLubyte)(60 * i);
            bordered[j][i][1] = edge ? 0 : (GLubyte)(60 * j);
            bordered[j][i][2] = edge ? 0 : 200;
            bordered[j][i][3] = 255;
        }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, yellow);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 6, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE, bordered);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    quad(8, 104, 64, 48);

    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, to_r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, to_g);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 2, to_b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, to_a);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    quad(80, 104, 64, 48);
    glDisable(GL_TEXTURE_2D);
}

static void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    types();
    depth_and_stencil();
    textured_pixels();
    intensity();
    border_and_bitmap();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_SINGLE | GLUT_RGB | GLUT_DEPTH | GLUT_STENCIL);
    glutInitWindowSize(264, 160);
    glutCreateWindow("Pixel types");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
