// Stipple.c: GL's rasterisation modes on evaluated curves and surfaces. Top left: an evaluated
// curve drawn with four line stipples, separate stippled GL_LINES (each restarts the pattern)
// and a wide stippled loop around a bar filled through a polygon stipple of diagonal hatching
// (its rows 20 to 31 empty, so that the pattern shows where the window's row 0 is). Top right:
// smooth points (opaque and translucent) and lines, blended. Bottom left: a lit surface cut by
// a clip plane (given under a rotation, kept in eye space), in fog, under stippled quads, a
// triangle strip and a polygon drawn in GL_LINE mode. Bottom right: a filled surface pushed
// back by polygon offset under its own wire outline, under a smooth stippled line strip, and a
// smooth line and point without blending.
#include "gl.h"

static GLfloat curve[4][3] = {{-1.3, -0.2, 0.0}, {-0.5, 1.0, 0.0}, {0.5, -1.0, 0.0}, {1.3, 0.2, 0.0}};
static GLfloat hill[4][4][3];
static GLint factors[4] = {1, 1, 2, 3};
static GLushort patterns[4] = {0x0F0F, 0x1C47, 0xAAAA, 0x00FF};
static GLubyte hatch[128];

static void init(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = -1.5f + u;
            hill[u][v][1] = -1.5f + v;
            hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 1.5f : -0.3f;
        }
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++)
            if ((x + y) % 8 < 3 && y < 20)
                hatch[4 * y + x / 8] |= (GLubyte)(0x80 >> (x % 8));
    glPolygonStipple(hatch);
    glClearColor(0.95, 0.95, 0.9, 1.0);
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glMapGrid1f(30, 0.0, 1.0);
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 12, 4, 0, 1, 3, 4, &hill[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMapGrid2f(12, 0.0, 1.0, 12, 0.0, 1.0);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
}

static void flat_view(int x, int y, int w, int h)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.5, 1.5, -1.5, 1.5, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void surface_view(int x, int y, int w, int h, double eye_x)
{
    glViewport(x, y, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (GLdouble)w / (GLdouble)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(eye_x, -5.0, 4.0, 0.0, 0.0, 0.2, 0.0, 0.0, 1.0);
}

static void stippled(int x, int y, int w, int h)
{
    flat_view(x, y, w, h);
    glEnable(GL_LINE_STIPPLE);
    for (int i = 0; i < 4; i++) {
        glLineStipple(factors[i], patterns[i]);
        glColor3f(0.25f * i, 0.1f, 0.7f - 0.15f * i);
        glPushMatrix();
        glTranslatef(0.0, 1.1f - 0.55f * i, 0.0);
        glScalef(1.0, 0.35f, 1.0);
        glEvalMesh1(GL_LINE, 0, 30);
        glPopMatrix();
    }
    glLineStipple(2, 0x0F0F);
    glColor3f(0.8, 0.2, 0.1);
    glBegin(GL_LINES);
    for (int k = 0; k < 6; k++) {
        glVertex2f(-1.35f + 0.45f * k, -1.0f);
        glVertex2f(-1.05f + 0.45f * k, -0.7f);
    }
    glEnd();
    glEnable(GL_POLYGON_STIPPLE);
    glColor3f(0.5, 0.7, 0.3);
    glRectf(-1.4, -1.4, 1.4, -1.15);
    glDisable(GL_POLYGON_STIPPLE);
    glLineWidth(3.0);
    glLineStipple(4, 0x3F3F);
    glColor3f(0.1, 0.5, 0.2);
    glBegin(GL_LINE_LOOP);
    glVertex2f(-1.4, -1.4);
    glVertex2f(1.4, -1.4);
    glVertex2f(1.4, -1.15);
    glVertex2f(-1.4, -1.15);
    glEnd();
    glLineWidth(1.0);
    glDisable(GL_LINE_STIPPLE);
}

static void smooth(int x, int y, int w, int h)
{
    flat_view(x, y, w, h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_POINT_SMOOTH);
    for (int i = 0; i < 6; i++) {
        glPointSize(1.0f + 1.5f * i);
        glColor3f(0.1, 0.3f + 0.1f * i, 0.6);
        glBegin(GL_POINTS);
        glVertex2f(-1.25f + 0.5f * i, 1.2f);
        glVertex2f(-1.25f + 0.5f * i + 0.013f, 0.8f);
        glEnd();
    }
    glPointSize(9.0);
    glColor4f(0.9, 0.2, 0.1, 0.4);
    glBegin(GL_POINTS);
    for (int i = 0; i < 3; i++)
        glVertex2f(-0.9f + 0.9f * i, -0.8f);
    glEnd();
    glPointSize(1.0);
    glDisable(GL_POINT_SMOOTH);
    glEnable(GL_LINE_SMOOTH);
    for (int i = 0; i < 3; i++) {
        glLineWidth(1.0f + i);
        glColor3f(0.7f - 0.2f * i, 0.1, 0.2f + 0.2f * i);
        glPushMatrix();
        glTranslatef(0.0, 0.1f - 0.5f * i, 0.0);
        glScalef(1.0, 0.4f, 1.0);
        glEvalMesh1(GL_LINE, 0, 30);
        glPopMatrix();
    }
    glLineWidth(1.0);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_BLEND);
}

static void clipped(int x, int y, int w, int h)
{
    GLdouble cut[4] = {1.0, 0.0, 0.0, 0.4};
    surface_view(x, y, w, h, 1.5);
    glPushMatrix();
    glRotatef(30.0, 0.0, 0.0, 1.0);
    glClipPlane(GL_CLIP_PLANE0, cut);
    glPopMatrix();
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_LIGHTING);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0.9, 0.5, 0.1, 1.0});
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 4.0);
    glFogf(GL_FOG_END, 9.0);
    glFogfv(GL_FOG_COLOR, (GLfloat[]){0.95, 0.95, 0.9, 1.0});
    glEvalMesh2(GL_FILL, 0, 12, 0, 12);
    glDisable(GL_FOG);
    glDisable(GL_LIGHTING);
    glDisable(GL_CLIP_PLANE0);
    flat_view(x, y, w, h);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x0F0F);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.3, 0.2, 0.6);
    glBegin(GL_QUADS);
    glVertex2f(-1.39, 0.81);
    glVertex2f(-0.89, 0.81);
    glVertex2f(-0.89, 1.34);
    glVertex2f(-1.39, 1.34);
    glVertex2f(-0.79, 0.81);
    glVertex2f(-0.29, 0.81);
    glVertex2f(-0.29, 1.34);
    glVertex2f(-0.79, 1.34);
    glEnd();
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(-0.19, 0.81);
    glVertex2f(-0.19, 1.34);
    glVertex2f(0.31, 0.81);
    glVertex2f(0.31, 1.34);
    glEnd();
    glBegin(GL_POLYGON);
    glVertex2f(0.91, 1.34);
    glVertex2f(0.61, 1.16);
    glVertex2f(0.71, 0.81);
    glVertex2f(1.11, 0.81);
    glVertex2f(1.21, 1.16);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_LINE_STIPPLE);
}

static void outlined(int x, int y, int w, int h)
{
    surface_view(x, y, w, h, -1.5);
    glEnable(GL_LIGHTING);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, (GLfloat[]){0.3, 0.5, 0.9, 1.0});
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0, 1.0);
    glEvalMesh2(GL_FILL, 0, 12, 0, 12);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);
    glColor3f(0.0, 0.0, 0.0);
    glEvalMesh2(GL_LINE, 0, 12, 0, 12);
    flat_view(x, y, w, h);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0F0F);
    glLineWidth(2.0);
    glColor3f(0.6, 0.1, 0.3);
    glBegin(GL_LINE_STRIP);
    glVertex2f(-1.37, 0.79);
    glVertex2f(-0.81, 1.35);
    glVertex2f(0.93, 0.83);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    glDisable(GL_BLEND);
    glLineWidth(3.0);
    glBegin(GL_LINES);
    glVertex2f(1.01, 0.83);
    glVertex2f(1.43, 1.07);
    glEnd();
    glLineWidth(1.0);
    glDisable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glPointSize(7.0);
    glBegin(GL_POINTS);
    glVertex2f(1.23, 1.23);
    glEnd();
    glPointSize(1.0);
    glDisable(GL_POINT_SMOOTH);
}

void Reshape(int w, int h) {}

void Display(void)
{
    int w = glutGet(GLUT_WINDOW_WIDTH), h = glutGet(GLUT_WINDOW_HEIGHT);
    glViewport(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    stippled(0, h / 2, w / 2, h / 2);
    smooth(w / 2, h / 2, w / 2, h / 2);
    clipped(0, 0, w / 2, h / 2);
    outlined(w / 2, 0, w / 2, h / 2);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Stipple, smoothing, clip planes, polygon offset");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
