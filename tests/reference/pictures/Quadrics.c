// Quadrics.c: GLU's quadrics in every draw style. A Bezier curve with its control points drawn
// as lit gluSphere balls (the usual way evaluator demos show them), a textured sphere and
// disk, a smooth cone, a flat cylinder facing in, wire and silhouette shapes, partial disks
// filled, as points and as silhouettes.
#include "gl.h"

#define SIZE 16
static GLubyte checker[SIZE][SIZE][3];
static GLUquadric *quad;

static GLfloat ctl[4][3] = {{-2.6, -1.4, 0.0}, {-1.6, 1.6, 0.5}, {0.2, -1.8, -0.5}, {1.2, 1.2, 0.0}};

static void init(void)
{
    for (int i = 0; i < SIZE; i++)
        for (int j = 0; j < SIZE; j++) {
            int on = ((i / 4) + (j / 4)) % 2;
            checker[i][j][0] = (GLubyte)(on ? 250 : 40);
            checker[i][j][1] = (GLubyte)(on ? 200 : 90);
            checker[i][j][2] = (GLubyte)(i * 16);
        }
    glClearColor(0.08, 0.08, 0.12, 1.0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (float[]){2.0, 3.0, 4.0, 0.0});
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, (float[]){0.25, 0.25, 0.25, 1});
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, SIZE, SIZE, 0, GL_RGB, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glMap1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 4, &ctl[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    quad = gluNewQuadric();
}

static void material(float r, float g, float b)
{
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, (float[]){r, g, b, 1});
}

static void at(float x, float y, float z)
{
    glPushMatrix();
    glTranslatef(x, y, z);
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, -1.0, 10.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // The curve, unlit, and its control points as lit balls.
    glColor3f(1.0, 1.0, 0.3);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 40; i++) glEvalCoord1f(i / 40.0f);
    glEnd();
    glEnable(GL_LIGHTING);
    gluQuadricDrawStyle(quad, GLU_FILL);
    gluQuadricNormals(quad, GLU_SMOOTH);
    material(0.9, 0.2, 0.2);
    for (int i = 0; i < 4; i++) {
        at(ctl[i][0], ctl[i][1], ctl[i][2]);
        gluSphere(quad, 0.18, 12, 8);
        glPopMatrix();
    }

    // A textured sphere and a textured disk.
    glEnable(GL_TEXTURE_2D);
    gluQuadricTexture(quad, GL_TRUE);
    material(1.0, 1.0, 1.0);
    at(2.6, 1.4, 0.0);
    glRotatef(-70, 1, 0, 0);
    gluSphere(quad, 0.8, 16, 12);
    glPopMatrix();
    at(-2.9, 1.5, 0.0);
    gluDisk(quad, 0.2, 0.7, 12, 3);
    glPopMatrix();
    gluQuadricTexture(quad, GL_FALSE);
    glDisable(GL_TEXTURE_2D);

    // A smooth cone and a flat cylinder seen from inside.
    material(0.2, 0.6, 0.9);
    at(2.7, -1.6, 0.0);
    glRotatef(-60, 1, 0, 0);
    gluCylinder(quad, 0.6, 0.0, 1.2, 14, 3);
    glPopMatrix();
    gluQuadricNormals(quad, GLU_FLAT);
    gluQuadricOrientation(quad, GLU_INSIDE);
    material(0.3, 0.8, 0.3);
    at(0.9, 2.2, 0.0);
    glRotatef(-75, 1, 0, 0);
    glRotatef(20, 0, 1, 0);
    gluCylinder(quad, 0.5, 0.5, 0.8, 10, 2);
    glPopMatrix();
    gluQuadricOrientation(quad, GLU_OUTSIDE);

    // A filled partial disk, flat.
    material(0.9, 0.6, 0.2);
    at(-0.9, 2.0, 0.0);
    gluPartialDisk(quad, 0.2, 0.7, 10, 2, 30.0, 240.0);
    glPopMatrix();
    glDisable(GL_LIGHTING);

    // Wire, silhouette and point styles, unlit.
    gluQuadricNormals(quad, GLU_NONE);
    gluQuadricDrawStyle(quad, GLU_LINE);
    glColor3f(0.6, 0.9, 1.0);
    at(-0.6, -2.3, 0.0);
    glRotatef(-60, 1, 0, 0);
    gluSphere(quad, 0.6, 10, 6);
    glPopMatrix();
    at(-3.0, -2.4, 0.0);
    glRotatef(-50, 1, 0, 0);
    gluCylinder(quad, 0.4, 0.2, 0.8, 8, 2);
    glPopMatrix();
    gluQuadricDrawStyle(quad, GLU_SILHOUETTE);
    glColor3f(1.0, 0.5, 0.8);
    at(0.9, -0.4, 0.0);
    gluDisk(quad, 0.3, 0.6, 16, 2);
    glPopMatrix();
    at(-1.2, 0.2, 0.0);
    gluPartialDisk(quad, 0.0, 0.5, 8, 2, -45.0, -120.0);
    glPopMatrix();
    gluQuadricDrawStyle(quad, GLU_POINT);
    glPointSize(2.0);
    glColor3f(1.0, 1.0, 1.0);
    at(0.9, -2.4, 0.0);
    gluPartialDisk(quad, 0.1, 0.6, 9, 3, 0.0, 300.0);
    glPopMatrix();
    glPointSize(1.0);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Quadrics");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
