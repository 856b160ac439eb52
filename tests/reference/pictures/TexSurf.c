// TexSurf.c: a texture-mapped Bezier surface. glMap2f gives GL_MAP2_VERTEX_3 and
// GL_MAP2_TEXTURE_COORD_2 (s and t from 0 to 2, so GL_REPEAT shows), glEvalMesh2 draws it in
// four viewports, one texture environment each: MODULATE (lit, LINEAR, REPEAT), DECAL
// (NEAREST, CLAMP_TO_EDGE), REPLACE (NEAREST, REPEAT) and BLEND (LINEAR, CLAMP) with two
// texture objects of a procedural image (RGB stripes and a luminance-alpha checker).
#include "gl.h"

#define SIZE 16
static GLubyte stripes[SIZE][SIZE][3];
static GLubyte checker[SIZE][SIZE][2];
static GLuint names[2];

static GLfloat ctl[4][4][3];
static GLfloat texpts[2][2][2] = {{{0.0, 0.0}, {0.0, 2.0}}, {{2.0, 0.0}, {2.0, 2.0}}};

static void make_images(void)
{
    for (int i = 0; i < SIZE; i++)
        for (int j = 0; j < SIZE; j++) {
            stripes[i][j][0] = (GLubyte)(j < SIZE / 2 ? 255 : 40);
            stripes[i][j][1] = (GLubyte)(i * 16);
            stripes[i][j][2] = (GLubyte)(((i / 4) % 2) ? 230 : 20);
            int on = ((i / 4) + (j / 4)) % 2;
            checker[i][j][0] = (GLubyte)(on ? 255 : 60);
            checker[i][j][1] = (GLubyte)(on ? 255 : 120);
        }
}

static void init(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctl[u][v][0] = 2.0f * (u / 3.0f) - 1.0f;
            ctl[u][v][1] = 2.0f * (v / 3.0f) - 1.0f;
            ctl[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 1.0f : -0.3f;
        }
    make_images();
    glClearColor(0.1, 0.1, 0.15, 1.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_LIGHT0);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &ctl[0][0][0]);
    glMap2f(GL_MAP2_TEXTURE_COORD_2, 0, 1, 2, 2, 0, 1, 4, 2, &texpts[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_TEXTURE_COORD_2);
    glMapGrid2f(20, 0.0, 1.0, 20, 0.0, 1.0);

    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, names);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, SIZE, SIZE, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, SIZE, SIZE, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, checker);
    glEnable(GL_TEXTURE_2D);
}

static void quadrant(int i, int w, int h)
{
    glViewport((i % 2) * w / 2, (i / 2) * h / 2, w / 2, h / 2);
}

static void surface(void)
{
    glPushMatrix();
    glRotatef(-50.0, 1.0, 0.0, 0.0);
    glRotatef(20.0, 0.0, 0.0, 1.0);
    glEvalMesh2(GL_FILL, 0, 20, 0, 20);
    glPopMatrix();
}

static void texture(GLuint name, GLenum env, GLenum filter, GLenum wrap)
{
    glBindTexture(GL_TEXTURE_2D, name);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, env);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
}

void Reshape(int w, int h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.6, 1.6, -1.6, 1.6, -4.0, 4.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    glViewport(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    quadrant(0, w, h);
    glEnable(GL_LIGHTING);
    texture(names[0], GL_MODULATE, GL_LINEAR, GL_REPEAT);
    surface();
    glDisable(GL_LIGHTING);

    quadrant(1, w, h);
    glColor3f(1.0, 0.6, 0.2);
    texture(names[0], GL_DECAL, GL_NEAREST, GL_CLAMP_TO_EDGE);
    surface();

    quadrant(2, w, h);
    texture(names[1], GL_REPLACE, GL_NEAREST, GL_REPEAT);
    surface();

    quadrant(3, w, h);
    glColor3f(0.2, 0.4, 1.0);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, (GLfloat[]){1.0, 0.9, 0.2, 1.0});
    texture(names[1], GL_BLEND, GL_LINEAR, GL_CLAMP);
    surface();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Textured Bezier surface");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
