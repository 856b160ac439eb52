// FogBlend.c: GL's per-fragment operations on evaluated surfaces. Three viewports show the same
// Bezier surface receding under a perspective projection with fog LINEAR, EXP and EXP2; the
// fourth blends translucent patches (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) over an evaluated curve
// and drops the faintest with the alpha test.
#include "gl.h"

static GLfloat ctl[4][4][3];
static GLfloat curve[4][3] = {{-1.2, -0.8, 0.0}, {-0.4, 1.2, 0.0}, {0.4, -1.2, 0.0}, {1.2, 0.8, 0.0}};

static void init(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctl[u][v][0] = -1.5f + u;
            ctl[u][v][1] = -1.5f + 4.0f * v;
            ctl[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 0.8f : -0.4f;
        }
    glClearColor(0.5, 0.55, 0.6, 1.0);
    glEnable(GL_DEPTH_TEST);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &ctl[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(16, 0.0, 1.0, 16, 0.0, 1.0);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(40, 0.0, 1.0);
    glFogfv(GL_FOG_COLOR, (GLfloat[]){0.5, 0.55, 0.6, 1.0});
}

static void receding(int x, int y, int w, int h, GLenum mode)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLdouble)w / (GLdouble)h, 0.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, -4.0, 1.5, 0.0, 2.0, 0.0, 0.0, 0.0, 1.0);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, mode);
    glFogf(GL_FOG_START, 2.0);
    glFogf(GL_FOG_END, 9.0);
    glFogf(GL_FOG_DENSITY, mode == GL_EXP ? 0.25 : 0.18);
    glColor3f(0.9, 0.3, 0.1);
    glEvalMesh2(GL_FILL, 0, 16, 0, 16);
    glDisable(GL_FOG);
}

static void translucent(int x, int y, int w, int h)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.5, 1.5, -1.5, 1.5, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLineWidth(3.0);
    glColor3f(0.0, 0.0, 0.6);
    glEvalMesh1(GL_LINE, 0, 40);
    glLineWidth(1.0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.2);
    for (int i = 0; i < 4; i++) {
        glColor4f(1.0, 0.8 - 0.2 * i, 0.2 * i, 0.15 + 0.25 * i);
        glRectf(-1.3 + 0.6 * i, -1.0 + 0.3 * i, -0.3 + 0.6 * i, 0.2 + 0.3 * i);
    }
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
}

void Reshape(int w, int h) {}

void Display(void)
{
    int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    glViewport(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    receding(0, h / 2, w / 2, h / 2, GL_LINEAR);
    receding(w / 2, h / 2, w / 2, h / 2, GL_EXP);
    receding(0, 0, w / 2, h / 2, GL_EXP2);
    translucent(w / 2, 0, w / 2, h / 2);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Fog and blending");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
