/* GL/glut.h for gleval: GLUT over gleval's windows (winit) or headless: `--png PATH` renders
 * the first frame of every top-level window to PNG (the first window to PATH, window N to
 * PATH with "-N" before its extension), `--time N` prints the median frame time, `--frames N`
 * runs N frames on a virtual 60 Hz clock, `--gpu` tessellates in WGSL. glutInit takes these
 * options, and GLUT's X options, out of argv.
 *
 * As freeglut's GL/glut.h: the GLUT 3.7 API of GL/freeglut_std.h (which includes <stdlib.h>,
 * <GL/gl.h> and <GL/glu.h>); freeglut's extensions are in GL/freeglut.h. */
#ifndef __GLUT_H__
#define __GLUT_H__
#include "freeglut_std.h"
#endif /* __GLUT_H__ */
