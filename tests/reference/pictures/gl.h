/* The textbook's "gl.h": GL, GLU and (here) the OSMesa GLUT stand-in. */
#include <GL/gl.h>
#include <GL/glu.h>
#include "glut_osmesa.h"
