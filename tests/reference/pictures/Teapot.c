// Teapot.c: GLUT's solid teapot, lit (glutSolidTeapot: see glut_teapot.h for how the GLUT
// stand-in draws it). Same scene as examples/teapot.rs.
#include "gl.h"

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(30, (double)w / (h > 1 ? h : 1), 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 1.7, 5.4, 0, 0, 0, 0, 1, 0);
}

void Init(void)
{
    glClearColor(0.1, 0.1, 0.15, 1);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){-2, 4, 5, 0});
    glLightfv(GL_LIGHT0, GL_DIFFUSE, (float[]){1, 1, 1, 1});
    glLightfv(GL_LIGHT0, GL_SPECULAR, (float[]){1, 1, 1, 1});
    glMaterialfv(GL_FRONT, GL_AMBIENT, (float[]){0.25, 0.15, 0.05, 1});
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]){0.8, 0.5, 0.2, 1});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (float[]){0.6, 0.6, 0.6, 1});
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(-30, 0, 1, 0);
    glutSolidTeapot(1);
    glPopMatrix();
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(400, 300);
    glutCreateWindow("Utah teapot");
    Init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
