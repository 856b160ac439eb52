// Lists.c: display lists holding evaluator calls and a NURBS surface, compiled once in init()
// and called under several transforms: a lit bicubic NURBS patch (GLU, compiled as the
// glMap2f/glEvalMesh2 calls GLU makes), a Bezier curve through glMap1f/glEvalMesh1 with its
// control points, a list that calls both, and glCallLists with a list base.
#include "gl.h"

static GLuint lists;

static void init(void)
{
    GLfloat ctl[4][4][3];
    GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    GLfloat curve[4][3] = {{-1, -1, 0.5}, {-0.5, 1, 0.5}, {0.5, -1, 0.5}, {1, 1, 0.5}};
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctl[u][v][0] = 2.0f * (u / 3.0f) - 1.0f;
            ctl[u][v][1] = 2.0f * (v / 3.0f) - 1.0f;
            ctl[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 0.8f : -0.4f;
        }

    glClearColor(0.15, 0.15, 0.2, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);

    GLUnurbsObj *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 12);
    gluNurbsProperty(nurb, GLU_V_STEP, 12);

    lists = glGenLists(3);
    glNewList(lists, GL_COMPILE);
    glEnable(GL_LIGHTING);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0.9, 0.5, 0.2, 1});
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
    glDisable(GL_LIGHTING);
    glEndList();

    glNewList(lists + 1, GL_COMPILE);
    glColor3f(0.2, 0.9, 1.0);
    glLineWidth(2.0);
    glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(30, 0.0, 1.0);
    glEvalMesh1(GL_LINE, 0, 30);
    glPointSize(5.0);
    glColor3f(1.0, 1.0, 0.0);
    glBegin(GL_POINTS);
    for (int i = 0; i < 4; i++)
        glVertex3fv(curve[i]);
    glEnd();
    glEndList();

    glNewList(lists + 2, GL_COMPILE);
    glCallList(lists);
    glCallList(lists + 1);
    glEndList();
    gluDeleteNurbsRenderer(nurb);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4.0, 4.0, -4.0, 4.0, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int i = 0; i < 4; i++) {
        glPushMatrix();
        glTranslatef(i % 2 ? 2.0f : -2.0f, i / 2 ? -2.0f : 2.0f, 0.0f);
        glRotatef(40.0f * i - 60.0f, 1.0f, 0.5f, 0.0f);
        glScalef(0.8f, 0.8f, 0.8f);
        glCallList(lists + 2);
        glPopMatrix();
    }
    glPushMatrix();
    glScalef(0.6f, 0.6f, 0.6f);
    glListBase(lists);
    glCallLists(2, GL_UNSIGNED_BYTE, "\001\000");
    glPopMatrix();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Display lists");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
