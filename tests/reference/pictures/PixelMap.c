// PixelMap.c: the pixel transfer on glDrawPixels, glCopyPixels and glReadPixels. A grey ramp
// and a colour ramp drawn plainly; through scale and bias; through GL_MAP_COLOR with an
// inverting map, a three-step posterising map and a two-entry threshold map; a colour-index
// image drawn through an I_TO_R/G/B palette with an index offset; a copy through the transfer;
// and a rectangle read back with glReadPixels under a bias, then drawn again plainly.
#include "gl.h"

#define W 128
#define H 16
static GLubyte grey[H][W];
static GLubyte colors[H][W][3];
static GLubyte indices[H][W];

static void init(void)
{
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            grey[j][i] = (GLubyte)(2 * i);
            colors[j][i][0] = (GLubyte)(2 * i);
            colors[j][i][1] = (GLubyte)(16 * j);
            colors[j][i][2] = (GLubyte)(255 - 2 * i);
            indices[j][i] = (GLubyte)(i / 16);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
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

static void both(int y)
{
    glRasterPos2i(8, y);
    glDrawPixels(W, H, GL_LUMINANCE, GL_UNSIGNED_BYTE, grey);
    glRasterPos2i(144, y);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, colors);
}

static void Display(void)
{
    static GLfloat invert[2] = {1.0, 0.0};
    static GLfloat steps[4] = {0.0, 0.33, 0.66, 1.0};
    static GLfloat threshold[2] = {0.1, 0.9};
    static GLfloat identity[2] = {0.0, 1.0};
    static GLfloat pal_r[8] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.5, 0.2, 0.9};
    static GLfloat pal_g[8] = {0.0, 0.5, 1.0, 1.0, 0.0, 0.0, 0.8, 0.9};
    static GLushort pal_b[8] = {0, 0, 0, 0, 65535, 32768, 16384, 65535};
    static GLubyte back[H][W][3];
    glClear(GL_COLOR_BUFFER_BIT);
    both(8);

    glPixelTransferf(GL_RED_SCALE, 0.5);
    glPixelTransferf(GL_GREEN_BIAS, 0.25);
    glPixelTransferf(GL_BLUE_SCALE, -1.0);
    glPixelTransferf(GL_BLUE_BIAS, 1.0);
    both(32);
    glPixelTransferf(GL_RED_SCALE, 1.0);
    glPixelTransferf(GL_GREEN_BIAS, 0.0);
    glPixelTransferf(GL_BLUE_SCALE, 1.0);
    glPixelTransferf(GL_BLUE_BIAS, 0.0);

    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, invert);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, invert);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, identity);
    both(56);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, steps);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 4, steps);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 4, steps);
    both(80);
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, threshold);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, identity);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, threshold);
    both(104);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);

    /* a palette: indices 0..7 shifted by one through I_TO_R/G/B */
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 8, pal_r);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 8, pal_g);
    glPixelMapusv(GL_PIXEL_MAP_I_TO_B, 8, pal_b);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, identity + 1);
    glPixelTransferi(GL_INDEX_OFFSET, 1);
    glRasterPos2i(8, 128);
    glDrawPixels(W, H, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, indices);
    glPixelTransferi(GL_INDEX_OFFSET, 0);

    /* a copy through the transfer */
    glPixelTransferf(GL_RED_BIAS, -0.5);
    glPixelTransferf(GL_GREEN_SCALE, 2.0);
    glRasterPos2i(144, 128);
    glCopyPixels(144, 8, W, H, GL_COLOR);
    glPixelTransferf(GL_RED_BIAS, 0.0);
    glPixelTransferf(GL_GREEN_SCALE, 1.0);

    /* a read under a bias, drawn back plainly */
    glPixelTransferf(GL_BLUE_BIAS, 0.5);
    glReadPixels(8, 8, W, H, GL_RGB, GL_UNSIGNED_BYTE, back);
    glPixelTransferf(GL_BLUE_BIAS, 0.0);
    glRasterPos2i(8, 152);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, back);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(280, 176);
    glutCreateWindow("Pixel maps and transfer");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
