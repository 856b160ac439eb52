// Shapes.c: GLUT's sphere, cube, cone and torus (see glut_shapes.h for how the GLUT stand-in
// draws them), each in a viewport of its own: the solid ones lit, with back faces culled (a
// wrong winding would cull the front), the wire ones unlit. A lit plate drawn after the solid
// cube without a normal of its own is lit with the normal current before the cube, as the
// shapes leave it. Same scene as examples/shapes.rs.
#include "gl.h"

static const float colours[4][4] = {
    {0.9, 0.3, 0.2, 1}, {0.3, 0.8, 0.3, 1}, {0.3, 0.5, 0.95, 1}, {0.9, 0.75, 0.2, 1}};

static void shape(int k, int wire)
{
    switch (k) {
    case 0:
        wire ? glutWireSphere(0.8, 16, 12) : glutSolidSphere(0.8, 16, 12);
        break;
    case 1:
        wire ? glutWireCube(1.1) : glutSolidCube(1.1);
        break;
    case 2:
        glTranslatef(0, -0.6, 0);
        glRotatef(-90, 1, 0, 0);
        wire ? glutWireCone(0.7, 1.4, 16, 6) : glutSolidCone(0.7, 1.4, 16, 6);
        break;
    default:
        glRotatef(-50, 1, 0, 0);
        wire ? glutWireTorus(0.25, 0.6, 12, 24) : glutSolidTorus(0.25, 0.6, 12, 24);
        break;
    }
}

static void cell(int k, int wire)
{
    int w = glutGet(GLUT_WINDOW_WIDTH) / 4, h = glutGet(GLUT_WINDOW_HEIGHT) / 2;
    glViewport(k * w, wire ? 0 : h, w, h);
    glPushMatrix();
    glRotatef(25, 1, 0, 0);
    glRotatef(-35 + 20 * k, 0, 1, 0);
    if (wire) {
        glColor3fv(colours[k]);
    } else {
        glEnable(GL_LIGHTING);
        glEnable(GL_CULL_FACE);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, colours[k]);
    }
    shape(k, wire);
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE);
    glPopMatrix();
}

void Reshape(int w, int h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(30, (double)(w / 4) / (h / 2 > 1 ? h / 2 : 1), 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 0, 4.6, 0, 0, 0, 0, 1, 0);
}

void Init(void)
{
    glClearColor(0.12, 0.12, 0.16, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){-2, 3, 4, 0});
    glLightfv(GL_LIGHT0, GL_SPECULAR, (float[]){1, 1, 1, 1});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (float[]){0.5, 0.5, 0.5, 1});
    glMaterialf(GL_FRONT, GL_SHININESS, 30);
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (int k = 0; k < 4; k++) {
        cell(k, 0);
        cell(k, 1);
    }
    // The plate: lit with the normal set before the cube (0, 0.6, 0.8): the cube's own
    // normals do not stay current.
    int w = glutGet(GLUT_WINDOW_WIDTH) / 4, h = glutGet(GLUT_WINDOW_HEIGHT) / 2;
    glViewport(w, h, w, h);
    glEnable(GL_LIGHTING);
    glNormal3f(0, 0.6, 0.8);
    glPushMatrix();
    glTranslatef(0, -0.9, 0);
    glutSolidCube(0.3);
    glBegin(GL_QUADS);
    glVertex3f(-0.9, -0.1, 0.6);
    glVertex3f(-0.5, -0.1, 0.6);
    glVertex3f(-0.5, 0.1, 0.6);
    glVertex3f(-0.9, 0.1, 0.6);
    glEnd();
    glPopMatrix();
    glDisable(GL_LIGHTING);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(640, 320);
    glutCreateWindow("GLUT shapes");
    Init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
