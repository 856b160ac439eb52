/* GL/freeglut.h for gleval: as freeglut's, the GLUT 3.7 API (GL/freeglut_std.h) and freeglut's
 * extensions (GL/freeglut_ext.h). */
#ifndef __FREEGLUT_H__
#define __FREEGLUT_H__
#include "freeglut_std.h"
#include "freeglut_ext.h"
#endif /* __FREEGLUT_H__ */
