//! `glBegin`/`glEnd`, vertices and the current attributes, rectangles.

use gleval::gl::types::*;

forward! {
    glBegin(mode: GLenum) => begin;
    glEnd() => end;
    glVertex2f(x: GLfloat, y: GLfloat) => vertex2f;
    glVertex2d(x: GLdouble, y: GLdouble) => vertex2d;
    glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat) => vertex3f;
    glVertex3d(x: GLdouble, y: GLdouble, z: GLdouble) => vertex3d;
    glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) => vertex4f;
    glColor3f(r: GLfloat, g: GLfloat, b: GLfloat) => color3f;
    glColor4f(r: GLfloat, g: GLfloat, b: GLfloat, a: GLfloat) => color4f;
    glColor3ub(r: GLubyte, g: GLubyte, b: GLubyte) => color3ub;
    glNormal3f(x: GLfloat, y: GLfloat, z: GLfloat) => normal3f;
    glTexCoord1f(s: GLfloat) => tex_coord1f;
    glTexCoord2f(s: GLfloat, t: GLfloat) => tex_coord2f;
    glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat) => tex_coord3f;
    glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) => tex_coord4f;
    glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) => rectf;
    glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) => rectd;
    glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) => recti;
}

vector! {
    glVertex2fv(GLfloat; 2) => vertex2fv;
    glVertex3fv(GLfloat; 3) => vertex3fv;
    glVertex4fv(GLfloat; 4) => vertex4fv;
    glColor3fv(GLfloat; 3) => color3fv;
    glColor4fv(GLfloat; 4) => color4fv;
    glNormal3fv(GLfloat; 3) => normal3fv;
    glTexCoord2fv(GLfloat; 2) => tex_coord2fv;
}
