/* GL 1.5's occlusion queries counted (GL 1.5 §4.1.6), built against Mesa and against gleval
 * by capi/tests/against_mesa.sh, which compares what the two print: the samples of a square
 * of 32 x 32 pixels, of a larger square partly behind it with the depth test (48 x 48 less
 * 32 x 32), of points and a line with the colour masked off (still counted), of squares the
 * alpha and the stencil test reject, and of a query open across glFlush (the frame gleval
 * records is drawn then: the query adds both frames' parts). */
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>

static unsigned char buf[64 * 64 * 4];

static void quad(float s, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(-s, -s, z);
    glVertex3f(s, -s, z);
    glVertex3f(s, s, z);
    glVertex3f(-s, s, z);
    glEnd();
}

int main(void)
{
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!c || !OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, 64, 64)) return 1;
    GLuint q[6], r = 0;
    glGenQueries(6, q);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    quad(0.5f, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    quad(0.5f, 0);
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    quad(0.75f, 0.5f);
    glEndQuery(GL_SAMPLES_PASSED);
    quad(1, -0.5f); /* after the end: not counted */
    glColorMask(0, 0, 0, 0);
    glDisable(GL_DEPTH_TEST);
    glBeginQuery(GL_SAMPLES_PASSED, q[2]);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, 0);
    glVertex3f(0.5f, 0.5f, 0);
    glEnd();
    glBegin(GL_LINES);
    glVertex3f(-0.5f, 0.25f, 0);
    glVertex3f(0.5f, 0.25f, 0);
    glEnd();
    glEndQuery(GL_SAMPLES_PASSED);
    glColorMask(1, 1, 1, 1);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glColor4f(1, 1, 1, 0.25f);
    glBeginQuery(GL_SAMPLES_PASSED, q[3]);
    quad(0.5f, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glDisable(GL_ALPHA_TEST);
    glEnable(GL_STENCIL_TEST);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glBeginQuery(GL_SAMPLES_PASSED, q[4]);
    quad(0.5f, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    glDisable(GL_STENCIL_TEST);
    glBeginQuery(GL_SAMPLES_PASSED, q[5]);
    quad(0.5f, 0);
    glFlush();
    quad(0.25f, 0);
    glEndQuery(GL_SAMPLES_PASSED);
    for (int i = 0; i < 6; i++) {
        glGetQueryObjectuiv(q[i], GL_QUERY_RESULT, &r);
        printf("query %d: %u samples\n", i, r);
    }
    GLint available = 0;
    glGetQueryObjectiv(q[5], GL_QUERY_RESULT_AVAILABLE, &available);
    printf("available %d, error 0x%x\n", available, glGetError());
    OSMesaDestroyContext(c);
    return 0;
}
