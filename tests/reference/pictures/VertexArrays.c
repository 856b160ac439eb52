// VertexArrays.c: small meshes from client vertex arrays, one cell per glInterleavedArrays
// format (all 14, with GL's default stride, drawn as quads through glDrawElements with
// GLubyte indices), then separate arrays through glDrawElements with GLushort and GLuint
// indices and glDrawArrays with padded strides. Normals light the N3F cells; texture
// coordinates pick a checker texture's squares.
#include "gl.h"
#include <math.h>
#include <string.h>

struct Format { GLenum name; int tex, color, normal, vertex; };   /* color: 0, 3 (3f), 4 (4f), 5 (4ub) */
static const struct Format formats[14] = {
    {GL_V2F, 0, 0, 0, 2}, {GL_V3F, 0, 0, 0, 3}, {GL_C4UB_V2F, 0, 5, 0, 2}, {GL_C4UB_V3F, 0, 5, 0, 3},
    {GL_C3F_V3F, 0, 3, 0, 3}, {GL_N3F_V3F, 0, 0, 1, 3}, {GL_C4F_N3F_V3F, 0, 4, 1, 3}, {GL_T2F_V3F, 2, 0, 0, 3},
    {GL_T4F_V4F, 4, 0, 0, 4}, {GL_T2F_C4UB_V3F, 2, 5, 0, 3}, {GL_T2F_C3F_V3F, 2, 3, 0, 3},
    {GL_T2F_N3F_V3F, 2, 0, 1, 3}, {GL_T2F_C4F_N3F_V3F, 2, 4, 1, 3}, {GL_T4F_C4F_N3F_V4F, 4, 4, 1, 4},
};

static unsigned char blocks[14][12 * 64];
static GLubyte quads[24];
static GLushort triangles[36];
static GLuint strip[8];
static GLfloat positions[12][3];
static GLubyte colors[12][4];
static GLfloat padded[12][5];   /* x, y, z and two unused floats */

static void put(unsigned char **p, const void *v, size_t n) { memcpy(*p, v, n); *p += n; }

/* Grid vertex (i, j) of a 4 x 3 grid in the unit cell. */
static void grid(int i, int j, float *x, float *y)
{
    *x = 0.12f + 0.76f * i / 3.0f;
    *y = 0.12f + 0.76f * j / 2.0f + 0.06f * sinf(1.7f * i + 2.3f * j);
}

static void init(void)
{
    static GLubyte checker[8][8][4];
    for (int s = 0; s < 8; s++)
        for (int t = 0; t < 8; t++) {
            GLubyte c = ((s + t) & 1) ? 255 : 60;
            checker[t][s][0] = c;
            checker[t][s][1] = c;
            checker[t][s][2] = 255;
            checker[t][s][3] = 255;
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, (GLfloat[]){0.3f, 0.5f, 1.0f, 0.0f});
    glClearColor(0.15, 0.15, 0.15, 1.0);

    for (int f = 0; f < 14; f++) {
        unsigned char *p = blocks[f];
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 4; i++) {
                float x, y;
                grid(i, j, &x, &y);
                float w = formats[f].vertex == 4 ? 2.0f : 1.0f;
                GLfloat tex[4] = {(0.05f + 0.3f * i) * w, (0.05f + 0.45f * j) * w, 0.0f, w};
                GLfloat rgba[4] = {i / 3.0f, j / 2.0f, 0.3f + 0.1f * f / 2.0f, 1.0f};
                GLubyte rgba8[4] = {(GLubyte)(255 * rgba[0]), (GLubyte)(255 * rgba[1]), (GLubyte)(255 * rgba[2]), 255};
                GLfloat n[3] = {0.6f * sinf(2.0f * i), 0.6f * cosf(3.0f * j), 0.8f};
                GLfloat v[4] = {x * w, y * w, 0.0f, w};
                if (formats[f].tex)
                    put(&p, tex, sizeof(GLfloat) * formats[f].tex);
                if (formats[f].color == 5)
                    put(&p, rgba8, 4);
                else if (formats[f].color)
                    put(&p, rgba, sizeof(GLfloat) * formats[f].color);
                if (formats[f].normal)
                    put(&p, n, sizeof n);
                put(&p, v, sizeof(GLfloat) * formats[f].vertex);
            }
    }
    int k = 0, t = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            int a = j * 4 + i;
            GLubyte q[4] = {a, a + 1, a + 5, a + 4};
            memcpy(quads + k, q, 4);
            k += 4;
            GLushort tri[6] = {a, a + 1, a + 5, a, a + 5, a + 4};
            memcpy(triangles + t, tri, sizeof tri);
            t += 6;
        }
    for (int i = 0; i < 4; i++) {
        strip[2 * i] = 4 + i;
        strip[2 * i + 1] = i;
    }
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            float x, y;
            grid(i, j, &x, &y);
            int a = j * 4 + i;
            positions[a][0] = padded[a][0] = x;
            positions[a][1] = padded[a][1] = y;
            positions[a][2] = padded[a][2] = 0.0f;
            padded[a][3] = padded[a][4] = 99.0f;
            colors[a][0] = (GLubyte)(80 * i);
            colors[a][1] = 200;
            colors[a][2] = (GLubyte)(120 * j);
            colors[a][3] = 255;
        }
}

void Reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void cell(int k)
{
    glLoadIdentity();
    glTranslatef((float)(k % 4), (float)(3 - k / 4), 0.0f);
}

void Display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    for (int f = 0; f < 14; f++) {
        cell(f);
        glColor3f(0.9f, 0.8f, 0.5f);
        if (formats[f].normal && !formats[f].color)
            glEnable(GL_LIGHTING);
        if (formats[f].tex)
            glEnable(GL_TEXTURE_2D);
        glInterleavedArrays(formats[f].name, 0, blocks[f]);
        glDrawElements(GL_QUADS, 24, GL_UNSIGNED_BYTE, quads);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
    }
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    cell(14);
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_SHORT, triangles);
    cell(15);
    glPushMatrix();
    glTranslatef(0.0f, 0.45f, 0.0f);
    glScalef(1.0f, 0.5f, 1.0f);
    glDrawElements(GL_TRIANGLE_STRIP, 8, GL_UNSIGNED_INT, strip);
    glPopMatrix();
    glDisableClientState(GL_COLOR_ARRAY);
    glColor3f(1.0f, 0.5f, 0.2f);
    glVertexPointer(3, GL_FLOAT, 5 * sizeof(GLfloat), padded);
    glScalef(1.0f, 0.45f, 1.0f);
    glPointSize(4.0f);
    glDrawArrays(GL_POINTS, 0, 12);
    glDrawArrays(GL_LINE_LOOP, 0, 4);
    glFlush();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitWindowSize(400, 400);
    glutCreateWindow("Vertex arrays");
    init();
    glutReshapeFunc(Reshape);
    glutDisplayFunc(Display);
    glutMainLoop();
    return 0;
}
