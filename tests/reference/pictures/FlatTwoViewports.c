// FlatTwoViewports.c: flat shading, polygon mode, face culling, two viewports.
// The same scene twice, with glShadeModel(GL_FLAT): a curled bicubic patch (like a breaking
// wave: it runs back along the floor, up, and forward again over itself) and two immediate
// triangles with a different colour at each vertex, the left one wound clockwise, the right
// one counter-clockwise.
// Left:  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE), no culling, no lighting; the patch's colour
//        comes from a bilinear colour map, one colour per triangle (flat: the provoking vertex).
// Right: GL_FILL, glFrontFace(GL_CW), glCullFace(GL_BACK), GL_CULL_FACE, lighting with
//        AUTO_NORMAL: EvalMesh2's strips are clockwise in (u, v), so the part of the patch
//        seen from its top side is drawn and the part seen from below is culled; of the two
//        triangles only the clockwise one is drawn. Flat lit facets.
#include "gl.h"

void Viewport(int x, int y, int w, int h)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(38, (float)w / h, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.5, -7, 6, 0, 0.2, 0.2, 0, 0, 1);
}

void Scene()
{
    float pts[4][4][3] = // rows: v (along the curl); columns: u (along x)
    {
        {{-1.5, -1.2, 0.0}, {-0.5, -1.2, 0.2}, {0.5, -1.2, -0.1}, {1.5, -1.2, 0.1}},
        {{-1.5, 2.2, 0.1}, {-0.5, 2.2, 0.0}, {0.5, 2.2, 0.2}, {1.5, 2.2, 0.0}},
        {{-1.5, 1.8, 2.4}, {-0.5, 1.9, 2.2}, {0.5, 1.8, 2.5}, {1.5, 1.9, 2.3}},
        {{-1.5, -0.9, 1.5}, {-0.5, -0.8, 1.7}, {0.5, -0.9, 1.4}, {1.5, -0.8, 1.6}}
    };
    float colors[2][2][4] = {{{1, 0.2, 0.2, 1}, {1, 0.9, 0.1, 1}}, {{0.2, 0.4, 1, 1}, {0.1, 0.9, 0.4, 1}}};

    glNormal3f(0, 0, 1), glColor3f(1, 1, 1); // current values, set before any evaluation
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 4, 0, 1, 12, 4, (float *)pts);
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, (float *)colors);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_COLOR_4);
    glMapGrid2f(8, 0, 1, 10, 0, 1);
    glEvalMesh2(GL_FILL, 0, 8, 0, 10);
    glDisable(GL_MAP2_COLOR_4);
    glDisable(GL_MAP2_VERTEX_3);

    glBegin(GL_TRIANGLES);
    // clockwise as seen from the eye (which looks along +y)
    glColor3f(1, 0, 0), glVertex3f(-2.1, -2, -1.3);
    glColor3f(0, 1, 0), glVertex3f(-1.3, -2, -0.5);
    glColor3f(0, 0, 1), glVertex3f(-0.5, -2, -1.2);
    // counter-clockwise
    glColor3f(1, 1, 0), glVertex3f(0.6, -2, -1.3);
    glColor3f(0, 1, 1), glVertex3f(2.0, -2, -1.2);
    glColor3f(1, 0, 1), glVertex3f(1.2, -2, -0.5);
    glEnd();
}

void Paint()
{
    glClearColor(0.95, 0.95, 0.9, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    int w = glutGet(GLUT_WINDOW_WIDTH) / 2;
    int h = glutGet(GLUT_WINDOW_HEIGHT);
    glShadeModel(GL_FLAT);

    Viewport(0, 0, w, h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_LIGHTING);
    glLineWidth(1);
    Scene();

    Viewport(w, 0, w, h);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
    glEnable(GL_CULL_FACE);
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){-1, -2, 3, 0}); // world coordinates
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_COLOR_MATERIAL); // the colours (map and glColor) drive ambient and diffuse
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    Scene();
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_AUTO_NORMAL);
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glFlush();
}

int main(int argc, char *argv[])
{
    glutInit(&argc, argv);
    glutInitWindowSize(500, 250);
    glutCreateWindow("FlatTwoViewports");
    glutDisplayFunc(Paint);
    glutMainLoop();
}
