// Specular.c: a lit bicubic patch with a specular material, a positional and a directional
// light, the light model's ambient term, smooth shading and the depth test.
#include "gl.h"

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6 * h / w, 0.6 * h / w, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -6);
    glRotatef(-55, 1, 0, 0);
}

void Display(void)
{
    GLfloat pts[4][4][3];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            pts[i][j][0] = -1.5 + i;
            pts[i][j][1] = -1.5 + j;
            pts[i][j][2] = (i == 1 || i == 2) && (j == 1 || j == 2) ? 1.5 : 0.0;
        }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, (float[]){0.1, 0.1, 0.15, 1});
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){1.5, -1.0, 3.0, 1.0});
    glLightfv(GL_LIGHT0, GL_DIFFUSE, (float[]){0.9, 0.8, 0.7, 1});
    glLightfv(GL_LIGHT0, GL_SPECULAR, (float[]){1, 1, 1, 1});
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.1f);
    glLightfv(GL_LIGHT1, GL_POSITION, (float[]){-1, 1, 1, 0});
    glLightfv(GL_LIGHT1, GL_DIFFUSE, (float[]){0.2, 0.3, 0.6, 1});
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glMaterialfv(GL_FRONT, GL_AMBIENT, (float[]){0.3, 0.3, 0.3, 1});
    glMaterialfv(GL_FRONT, GL_DIFFUSE, (float[]){0.6, 0.6, 0.6, 1});
    glMaterialfv(GL_FRONT, GL_SPECULAR, (float[]){0.9, 0.9, 0.9, 1});
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
    glEnable(GL_AUTO_NORMAL);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &pts[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(30, 0, 1, 30, 0, 1);
    glEvalMesh2(GL_FILL, 0, 30, 0, 30);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(300, 240);
    glutCreateWindow("Specular lighting");
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
