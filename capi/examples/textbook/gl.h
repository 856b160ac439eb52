// gl.h: what the textbook's programs include; the chapter's helpers and GL/GLU/GLUT.
#pragma once
#include "gll.h"
