// MipNurbs.c: a mipmapped NURBS surface. A 64×64 checker goes through gluBuild2DMipmaps; a
// bicubic NURBS surface with a GL_MAP2_TEXTURE_COORD_2 companion surface (s, t from 0 to 8)
// recedes into the distance under a perspective projection, so the minification filter
// (LINEAR_MIPMAP_LINEAR) reads the coarse levels.
#include "gl.h"

#define SIZE 64
static GLubyte image[SIZE][SIZE][3];
static GLUnurbsObj *nurb;

static void init(void)
{
    for (int i = 0; i < SIZE; i++)
        for (int j = 0; j < SIZE; j++) {
            int on = ((i / 8) + (j / 8)) % 2;
            image[i][j][0] = (GLubyte)(on ? 250 : 30);
            image[i][j][1] = (GLubyte)(on ? 200 : 60);
            image[i][j][2] = (GLubyte)(on ? 40 : 160);
        }
    glClearColor(0.2, 0.25, 0.3, 1.0);
    glEnable(GL_DEPTH_TEST);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, SIZE, SIZE, GL_RGB, GL_UNSIGNED_BYTE, image);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 24);
    gluNurbsProperty(nurb, GLU_V_STEP, 24);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLdouble)w / (GLdouble)h, 0.5, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, -3.0, 2.0, 0.0, 12.0, 0.0, 0.0, 0.0, 1.0);
}

void Display(void)
{
    GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    GLfloat ctl[4][4][3], tex[2][2][2] = {{{0, 0}, {0, 8}}, {{8, 0}, {8, 8}}};
    GLfloat tknots[4] = {0, 0, 1, 1};
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctl[u][v][0] = -6.0f + 4.0f * u;
            ctl[u][v][1] = -2.0f + 10.0f * v;
            ctl[u][v][2] = (u == 1 || u == 2) && v == 2 ? 1.5f : -0.5f;
        }
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 4, tknots, 4, tknots, 2 * 2, 2, &tex[0][0][0], 2, 2, GL_MAP2_TEXTURE_COORD_2);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Mipmapped NURBS surface");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
