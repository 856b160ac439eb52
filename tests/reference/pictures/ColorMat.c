// ColorMat.c: GL_COLOR_MATERIAL as the Red Book's colormat.c sets it up: a glMaterial diffuse
// of 0.5, then glColorMaterial and glEnable(GL_COLOR_MATERIAL) with no drawing between. The
// left sphere has no glColor of its own: Mesa 22.3 lights it with the glMaterial's 0.5 (the
// material waits in Mesa's vertex buffer and lands after the enable's copy of the colour,
// white). The right sphere follows a glColor, which changes the colour and so the material.
// Same scene as examples/colormat.rs.
#include "gl.h"

static int width, height;

void Reshape(int w, int h)
{
    width = w;
    height = h;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.2, 1.2, -1.2, 1.2, -2, 2);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void Display(void)
{
    glClearColor(0.1, 0.1, 0.15, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){1, 1, 1, 0});
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]){0.5, 0.5, 0.5, 1});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (float[]){1, 1, 1, 1});
    glMaterialf(GL_FRONT, GL_SHININESS, 25);
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glViewport(0, 0, width / 2, height);
    glutSolidSphere(1.0, 24, 16);
    glColor3f(0.9, 0.3, 0.2);
    glViewport(width / 2, 0, width / 2, height);
    glutSolidSphere(1.0, 24, 16);
    glDisable(GL_COLOR_MATERIAL);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(240, 120);
    glutCreateWindow("Colour material");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
