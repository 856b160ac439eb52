// CopyTex.c: textures copied from the window as drawn so far. A small scene (a checkerboard
// square and a triangle) is drawn in the corner, copied into a 64 x 64 texture with
// glCopyTexImage2D, a part of it refreshed with glCopyTexSubImage2D after more drawing, one row
// copied into a 1D texture with glCopyTexImage1D and patched with glTexSubImage1D; then the
// window is cleared and the textures drawn on quads (nearest filtering, four window pixels a
// texel), the 2D one rotated.
#include "gl.h"

static GLuint tex[2];

static void init(void)
{
    glClearColor(0.0, 0.0, 0.0, 1.0);
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
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

static void corner_scene(void)
{
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            if ((i + j) % 2) glColor3f(0.9, 0.9, 0.2);
            else glColor3f(0.2, 0.3, 0.9);
            glRectf(8.0f * i, 8.0f * j, 8.0f * i + 8.0f, 8.0f * j + 8.0f);
        }
    glColor3f(0.9, 0.1, 0.1);
    glBegin(GL_TRIANGLES);
    glVertex2f(4.25, 4.25);
    glVertex2f(60.75, 12.25);
    glVertex2f(20.25, 58.75);
    glEnd();
}

static void Display(void)
{
    static const GLubyte patch[4][4] = {{255, 255, 255, 255}, {0, 0, 0, 255}, {255, 255, 255, 255}, {0, 0, 0, 255}};
    glClear(GL_COLOR_BUFFER_BIT);
    corner_scene();
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 64, 64, 0);
    glColor3f(0.1, 0.9, 0.3);
    glRectf(16.0, 16.0, 48.0, 48.0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 32, 32, 24, 24, 32, 32);
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 20, 64, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage1D(GL_TEXTURE_1D, 0, 28, 4, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 0, 30, 30, 8);

    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(16, 16);
    glTexCoord2f(1, 0); glVertex2f(272, 16);
    glTexCoord2f(1, 1); glVertex2f(272, 272);
    glTexCoord2f(0, 1); glVertex2f(16, 272);
    glEnd();
    glPushMatrix();
    glTranslatef(360.0, 150.0, 0.0);
    glRotatef(30.0, 0.0, 0.0, 1.0);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-60.3, -60.3);
    glTexCoord2f(1, 0); glVertex2f(60.3, -60.3);
    glTexCoord2f(1, 1); glVertex2f(60.3, 60.3);
    glTexCoord2f(0, 1); glVertex2f(-60.3, 60.3);
    glEnd();
    glPopMatrix();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_1D);
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glBegin(GL_QUADS);
    glTexCoord1f(0); glVertex2f(16, 280);
    glTexCoord1f(1); glVertex2f(272, 280);
    glTexCoord1f(1); glVertex2f(272, 296);
    glTexCoord1f(0); glVertex2f(16, 296);
    glEnd();
    glDisable(GL_TEXTURE_1D);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(440, 304);
    glutCreateWindow("Textures copied from the window");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
