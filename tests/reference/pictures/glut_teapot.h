/* glut_teapot.h: glutSolidTeapot and glutWireTeapot for the OSMesa GLUT stand-in, drawn as
 * freeglut 3.4 draws them (fg_teapot.c, read for its rules; written anew here): the 10 patches
 * of freeglut's teapot data (fg_teapot_data.h's numbers, as tools/shapes/gen_shapes.py writes
 * them into gleval's src/glut/solids_data.rs), their control points turned upright, scaled by
 * size / 2 and lowered by 1.575; each patch evaluated in float on an 8 x 8 grid (solid) or
 * 10 x 10 (wire) with the Bernstein weights and their derivatives, normals from the cross
 * product of the tangents (the first row of patches 3 and 5 set to +y and -y), the first six
 * patches turned into the four quadrants about y and the others mirrored in z. The normals
 * are those of the first size drawn, as freeglut caches them. Solids are one glDrawElements
 * of GL_TRIANGLES with (u, v) texture coordinates; wires line strips along both directions.
 * tools/freeglut_check/check.sh Teapot.c compares the stand-in with real freeglut. */

#include <math.h>
#include <string.h>

static const float teapot_cp[129][3] = {
    {1.4f, 0.0f, 2.4f},
    {1.4f, -0.784f, 2.4f},
    {0.784f, -1.4f, 2.4f},
    {0.0f, -1.4f, 2.4f},
    {1.3375f, 0.0f, 2.53125f},
    {1.3375f, -0.749f, 2.53125f},
    {0.749f, -1.3375f, 2.53125f},
    {0.0f, -1.3375f, 2.53125f},
    {1.4375f, 0.0f, 2.53125f},
    {1.4375f, -0.805f, 2.53125f},
    {0.805f, -1.4375f, 2.53125f},
    {0.0f, -1.4375f, 2.53125f},
    {1.5f, 0.0f, 2.4f},
    {1.5f, -0.84f, 2.4f},
    {0.84f, -1.5f, 2.4f},
    {0.0f, -1.5f, 2.4f},
    {1.75f, 0.0f, 1.875f},
    {1.75f, -0.98f, 1.875f},
    {0.98f, -1.75f, 1.875f},
    {0.0f, -1.75f, 1.875f},
    {2.0f, 0.0f, 1.35f},
    {2.0f, -1.12f, 1.35f},
    {1.12f, -2.0f, 1.35f},
    {0.0f, -2.0f, 1.35f},
    {2.0f, 0.0f, 0.9f},
    {2.0f, -1.12f, 0.9f},
    {1.12f, -2.0f, 0.9f},
    {0.0f, -2.0f, 0.9f},
    {2.0f, 0.0f, 0.45f},
    {2.0f, -1.12f, 0.45f},
    {1.12f, -2.0f, 0.45f},
    {0.0f, -2.0f, 0.45f},
    {1.5f, 0.0f, 0.225f},
    {1.5f, -0.84f, 0.225f},
    {0.84f, -1.5f, 0.225f},
    {0.0f, -1.5f, 0.225f},
    {1.5f, 0.0f, 0.15f},
    {1.5f, -0.84f, 0.15f},
    {0.84f, -1.5f, 0.15f},
    {0.0f, -1.5f, 0.15f},
    {0.0f, 0.0f, 3.15f},
    {0.0f, -0.002f, 3.15f},
    {0.002f, 0.0f, 3.15f},
    {0.8f, 0.0f, 3.15f},
    {0.8f, -0.45f, 3.15f},
    {0.45f, -0.8f, 3.15f},
    {0.0f, -0.8f, 3.15f},
    {0.0f, 0.0f, 2.85f},
    {0.2f, 0.0f, 2.7f},
    {0.2f, -0.112f, 2.7f},
    {0.112f, -0.2f, 2.7f},
    {0.0f, -0.2f, 2.7f},
    {0.4f, 0.0f, 2.55f},
    {0.4f, -0.224f, 2.55f},
    {0.224f, -0.4f, 2.55f},
    {0.0f, -0.4f, 2.55f},
    {1.3f, 0.0f, 2.55f},
    {1.3f, -0.728f, 2.55f},
    {0.728f, -1.3f, 2.55f},
    {0.0f, -1.3f, 2.55f},
    {1.3f, 0.0f, 2.4f},
    {1.3f, -0.728f, 2.4f},
    {0.728f, -1.3f, 2.4f},
    {0.0f, -1.3f, 2.4f},
    {0.0f, 0.0f, 0.0f},
    {0.0f, -1.425f, 0.0f},
    {0.798f, -1.425f, 0.0f},
    {1.425f, -0.798f, 0.0f},
    {1.425f, 0.0f, 0.0f},
    {0.0f, -1.5f, 0.075f},
    {0.84f, -1.5f, 0.075f},
    {1.5f, -0.84f, 0.075f},
    {1.5f, 0.0f, 0.075f},
    {-1.6f, 0.0f, 2.025f},
    {-1.6f, -0.3f, 2.025f},
    {-1.5f, -0.3f, 2.25f},
    {-1.5f, 0.0f, 2.25f},
    {-2.3f, 0.0f, 2.025f},
    {-2.3f, -0.3f, 2.025f},
    {-2.5f, -0.3f, 2.25f},
    {-2.5f, 0.0f, 2.25f},
    {-2.7f, 0.0f, 2.025f},
    {-2.7f, -0.3f, 2.025f},
    {-3.0f, -0.3f, 2.25f},
    {-3.0f, 0.0f, 2.25f},
    {-2.7f, 0.0f, 1.8f},
    {-2.7f, -0.3f, 1.8f},
    {-3.0f, -0.3f, 1.8f},
    {-3.0f, 0.0f, 1.8f},
    {-2.7f, 0.0f, 1.575f},
    {-2.7f, -0.3f, 1.575f},
    {-3.0f, -0.3f, 1.35f},
    {-3.0f, 0.0f, 1.35f},
    {-2.5f, 0.0f, 1.125f},
    {-2.5f, -0.3f, 1.125f},
    {-2.65f, -0.3f, 0.9375f},
    {-2.65f, 0.0f, 0.9375f},
    {-2.0f, 0.0f, 0.9f},
    {-2.0f, -0.3f, 0.9f},
    {-1.9f, -0.3f, 0.6f},
    {-1.9f, 0.0f, 0.6f},
    {1.7f, 0.0f, 1.425f},
    {1.7f, -0.66f, 1.425f},
    {1.7f, -0.66f, 0.6f},
    {1.7f, 0.0f, 0.6f},
    {2.6f, 0.0f, 1.425f},
    {2.6f, -0.66f, 1.425f},
    {3.1f, -0.66f, 0.825f},
    {3.1f, 0.0f, 0.825f},
    {2.3f, 0.0f, 2.1f},
    {2.3f, -0.25f, 2.1f},
    {2.4f, -0.25f, 2.025f},
    {2.4f, 0.0f, 2.025f},
    {2.7f, 0.0f, 2.4f},
    {2.7f, -0.25f, 2.4f},
    {3.3f, -0.25f, 2.4f},
    {3.3f, 0.0f, 2.4f},
    {2.8f, 0.0f, 2.475f},
    {2.8f, -0.25f, 2.475f},
    {3.525f, -0.25f, 2.49375f},
    {3.525f, 0.0f, 2.49375f},
    {2.9f, 0.0f, 2.475f},
    {2.9f, -0.15f, 2.475f},
    {3.45f, -0.15f, 2.5125f},
    {3.45f, 0.0f, 2.5125f},
    {2.8f, 0.0f, 2.4f},
    {2.8f, -0.15f, 2.4f},
    {3.2f, -0.15f, 2.4f},
    {3.2f, 0.0f, 2.4f},
};

static const int teapot_patch[10][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
    {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27},
    {24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39},
    {40, 41, 42, 40, 43, 44, 45, 46, 47, 47, 47, 47, 48, 49, 50, 51},
    {48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63},
    {64, 64, 64, 64, 65, 66, 67, 68, 69, 70, 71, 72, 39, 38, 37, 36},
    {73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84, 85, 86, 87, 88},
    {85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95, 96, 97, 98, 99, 100},
    {101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116},
    {113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128},
};

#define TEAPOT_MAX_N 10
#define TEAPOT_COPIES 32 /* 6 patches turned 4 times, 4 mirrored twice */

/* The degree-3 Bernstein weight i at x and its derivative, in freeglut's float arithmetic. */
static void teapot_bernstein(int i, float x, float *b, float *d)
{
    float inv = 1.f - x, t;
    switch (i) {
    case 0: t = inv * inv; *b = inv * t; *d = -3 * t; break;
    case 1: t = inv * inv; *b = 3 * x * t; *d = 3 * t - 6 * x * inv; break;
    case 2: t = x * x; *b = 3 * t * inv; *d = 6 * x * inv - 3 * t; break;
    default: t = x * x; *b = x * t; *d = 3 * t; break;
    }
}

/* Patch p at scale: n x n points (row u, column v) and, if norm is not NULL, unit normals. */
static void teapot_patch_eval(int p, float scale, int n, float *vert, float *norm)
{
    float cp[4][4][3], b0[TEAPOT_MAX_N][4], b1[TEAPOT_MAX_N][4];
    int i, j, c, u, v;
    for (i = 0; i < 16; i++) {
        const float *q = teapot_cp[teapot_patch[p][i]];
        cp[i / 4][i % 4][0] = q[0] * scale / 2.f;
        cp[i / 4][i % 4][1] = (q[2] - 1.575f) * scale / 2.f;
        cp[i / 4][i % 4][2] = -q[1] * scale / 2.f;
    }
    for (u = 0; u < n; u++)
        for (i = 0; i < 4; i++)
            teapot_bernstein(i, u / (n - 1.f), &b0[u][i], &b1[u][i]);
    for (u = 0; u < n; u++)
        for (v = 0; v < n; v++) {
            float point[3] = {0, 0, 0}, t1[3] = {0, 0, 0}, t2[3] = {0, 0, 0}, len, *o;
            for (i = 0; i < 4; i++) {
                float r0[3] = {0, 0, 0}, r1[3] = {0, 0, 0};
                for (j = 0; j < 4; j++)
                    for (c = 0; c < 3; c++) {
                        r0[c] += b0[v][j] * cp[i][j][c];
                        r1[c] += b1[v][j] * cp[i][j][c];
                    }
                for (c = 0; c < 3; c++) {
                    point[c] += b0[u][i] * r0[c];
                    t1[c] += b0[u][i] * r1[c];
                    t2[c] += b1[u][i] * r0[c];
                }
            }
            memcpy(vert + 3 * (u * n + v), point, sizeof point);
            if (!norm)
                continue;
            o = norm + 3 * (u * n + v);
            o[0] = t1[1] * t2[2] - t1[2] * t2[1];
            o[1] = t1[2] * t2[0] - t1[0] * t2[2];
            o[2] = t1[0] * t2[1] - t1[1] * t2[0];
            len = (float)sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
            for (c = 0; c < 3; c++)
                o[c] /= len;
        }
    if (norm && (p == 3 || p == 5))
        for (v = 0; v < n; v++) {
            norm[3 * v] = 0.f;
            norm[3 * v + 1] = p == 3 ? 1.f : -1.f;
            norm[3 * v + 2] = 0.f;
        }
}

/* The copies of a patch's n x n values after it in out: three turns about y (p < 6), or the
 * mirror in z with the rows in reverse order. Returns how many patches out now holds. */
static int teapot_copies(int p, int n, float *out)
{
    int k = n * n, i, u;
    if (p < 6) {
        for (i = 0; i < k; i++) {
            const float *s = out + 3 * i;
            float *a = out + 3 * (k + i), *b = out + 3 * (2 * k + i), *c = out + 3 * (3 * k + i);
            a[0] = s[2]; a[1] = s[1]; a[2] = -s[0];
            b[0] = -s[0]; b[1] = s[1]; b[2] = -s[2];
            c[0] = -s[2]; c[1] = s[1]; c[2] = s[0];
        }
        return 4;
    }
    for (u = 0; u < n; u++)
        for (i = 0; i < n; i++) {
            const float *s = out + 3 * ((n - u - 1) * n + i);
            float *d = out + 3 * (k + u * n + i);
            d[0] = s[0]; d[1] = s[1]; d[2] = -s[2];
        }
    return 2;
}

static float teapot_verts[2][TEAPOT_COPIES * TEAPOT_MAX_N * TEAPOT_MAX_N * 3];
static float teapot_norms[2][TEAPOT_COPIES * TEAPOT_MAX_N * TEAPOT_MAX_N * 3];
static float teapot_texcs[TEAPOT_COPIES * TEAPOT_MAX_N * TEAPOT_MAX_N * 2];
static GLushort teapot_index[TEAPOT_COPIES * (TEAPOT_MAX_N - 1) * (TEAPOT_MAX_N - 1) * 6];
static int teapot_normals_made[2];

/* Every copy of every patch at size, in freeglut's order; the normals of the first call. */
static void teapot_make(int wire, int n, float size)
{
    int p, o = 0, made = teapot_normals_made[wire];
    for (p = 0; p < 10; p++) {
        float *v = teapot_verts[wire] + 3 * o * n * n, *nm = teapot_norms[wire] + 3 * o * n * n;
        teapot_patch_eval(p, size, n, v, made ? NULL : nm);
        teapot_copies(p, n, v);
        if (!made)
            teapot_copies(p, n, nm);
        o += p < 6 ? 4 : 2;
    }
    teapot_normals_made[wire] = 1;
}

static void teapot_draw(int wire, float size)
{
    int n = wire ? 10 : 8, p, r, c, o = 0;
    teapot_make(wire, n, size);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, teapot_verts[wire]);
    glNormalPointer(GL_FLOAT, 0, teapot_norms[wire]);
    if (wire) {
        GLushort strip[TEAPOT_MAX_N];
        for (p = 0; p < TEAPOT_COPIES; p++)
            for (c = 0; c < n; c++) {
                for (r = 0; r < n; r++)
                    strip[r] = p * n * n + r * n + c;
                glDrawElements(GL_LINE_STRIP, n, GL_UNSIGNED_SHORT, strip);
            }
        for (p = 0; p < TEAPOT_COPIES; p++)
            for (r = 0; r < n; r++) {
                for (c = 0; c < n; c++)
                    strip[c] = p * n * n + r * n + c;
                glDrawElements(GL_LINE_STRIP, n, GL_UNSIGNED_SHORT, strip);
            }
    } else {
        for (p = 0; p < TEAPOT_COPIES; p++)
            for (r = 0; r < n; r++)
                for (c = 0; c < n; c++) {
                    float *t = teapot_texcs + 2 * (p * n * n + r * n + c);
                    t[0] = r / (n - 1.f);
                    t[1] = c / (n - 1.f);
                }
        for (p = 0; p < TEAPOT_COPIES; p++)
            for (r = 0; r < n - 1; r++)
                for (c = 0; c < n - 1; c++) {
                    GLushort a = p * n * n + r * n + c, b = a + n;
                    GLushort quad[6] = {a, b, b + 1, a, b + 1, a + 1};
                    memcpy(teapot_index + o, quad, sizeof quad);
                    o += 6;
                }
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(2, GL_FLOAT, 0, teapot_texcs);
        glDrawElements(GL_TRIANGLES, o, GL_UNSIGNED_SHORT, teapot_index);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
}

void glutSolidTeapot(double size) { teapot_draw(0, (float)size); }
void glutWireTeapot(double size) { teapot_draw(1, (float)size); }
