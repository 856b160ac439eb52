/* arrays_dump.c: an LD_PRELOAD library for tools/freeglut_check/shapes.sh. freeglut 3.4 draws
 * its shapes from client arrays; this records what each glDrawArrays/glDrawElements call
 * draws (the mode, the vertices in order, each vertex's position, normal and texture
 * coordinates as float bits) into a running FNV-1a hash and a count per primitive, printed
 * when the program calls glFinish, then passes every call on to the real libGL. */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static const GLfloat *vp, *np, *tp;
static int tex_on;
static uint64_t hash = 1469598103934665603ull;
static unsigned long prims, verts;

static void mix(const void *p, size_t n)
{
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) { hash ^= b[i]; hash *= 1099511628211ull; }
}

static void vertex(int i)
{
    mix(vp + 3 * i, 12);
    mix(np + 3 * i, 12);
    if (tex_on && tp) mix(tp + 2 * i, 8);
    verts++;
}

static void begin(GLenum mode, GLsizei count)
{
    uint32_t m = mode, c = (uint32_t)count;
    mix(&m, 4);
    mix(&c, 4);
    prims++;
}

#define REAL(name) static __typeof__(&name) real; if (!real) real = (__typeof__(&name))dlsym(RTLD_NEXT, #name)

void glVertexPointer(GLint size, GLenum type, GLsizei stride, const void *p)
{ REAL(glVertexPointer); vp = p; real(size, type, stride, p); }
void glNormalPointer(GLenum type, GLsizei stride, const void *p)
{ REAL(glNormalPointer); np = p; real(type, stride, p); }
void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void *p)
{ REAL(glTexCoordPointer); tp = p; real(size, type, stride, p); }
void glEnableClientState(GLenum a)
{ REAL(glEnableClientState); if (a == GL_TEXTURE_COORD_ARRAY) tex_on = 1; real(a); }
void glDisableClientState(GLenum a)
{ REAL(glDisableClientState); if (a == GL_TEXTURE_COORD_ARRAY) tex_on = 0; real(a); }

void glDrawArrays(GLenum mode, GLint first, GLsizei count)
{
    REAL(glDrawArrays);
    begin(mode, count);
    for (int i = 0; i < count; i++) vertex(first + i);
    real(mode, first, count);
}

void glDrawElements(GLenum mode, GLsizei count, GLenum type, const void *indices)
{
    REAL(glDrawElements);
    begin(mode, count);
    for (int i = 0; i < count; i++) vertex(((const GLushort *)indices)[i]);
    real(mode, count, type, indices);
}

void glFinish(void)
{
    REAL(glFinish);
    printf("%lu %lu %016llx\n", prims, verts, (unsigned long long)hash);
    fflush(stdout);
    hash = 1469598103934665603ull;
    prims = verts = 0;
    real();
}
