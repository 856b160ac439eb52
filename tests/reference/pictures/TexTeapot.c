// TexTeapot.c: GLUT's teapots as course programs draw them. On the left glutSolidTeapot, lit
// and textured (GLUT's teapot carries (s, t) per patch through GL_MAP2_TEXTURE_COORD_2) with a
// striped image in GL_MODULATE; on the right glutWireTeapot, unlit.
#include "gl.h"

#define SIZE 32
static GLubyte stripes[SIZE][SIZE][3];

static void init(void)
{
    for (int i = 0; i < SIZE; i++)
        for (int j = 0; j < SIZE; j++) {
            int on = (j / 4) % 2;
            stripes[i][j][0] = (GLubyte)(on ? 255 : 90);
            stripes[i][j][1] = (GLubyte)(on ? 230 : 40);
            stripes[i][j][2] = (GLubyte)(on ? 120 : 30);
        }
    glClearColor(0.1, 0.12, 0.16, 1.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){-2.0, 4.0, 5.0, 0.0});
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (GLfloat[]){1.0, 1.0, 1.0, 1.0});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (GLfloat[]){0.5, 0.5, 0.5, 1.0});
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, SIZE, SIZE, 0, GL_RGB, GL_UNSIGNED_BYTE, stripes);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(30.0, (GLdouble)w / (GLdouble)h, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 1.8, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(-1.1, 0.0, 0.0);
    glRotatef(-30.0, 0.0, 1.0, 0.0);
    glEnable(GL_LIGHTING);
    glEnable(GL_TEXTURE_2D);
    glutSolidTeapot(0.9);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.1, 0.0, 0.0);
    glRotatef(40.0, 0.0, 1.0, 0.0);
    glColor3f(0.4, 0.9, 1.0);
    glutWireTeapot(0.9);
    glPopMatrix();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 300);
    glutCreateWindow("GLUT teapots");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
