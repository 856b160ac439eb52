//! The matrix stacks and transformations.

use gleval::gl::types::*;

forward! {
    glMatrixMode(mode: GLenum) => matrix_mode;
    glLoadIdentity() => load_identity;
    glPushMatrix() => push_matrix;
    glPopMatrix() => pop_matrix;
    glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) => translatef;
    glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) => translated;
    glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) => rotatef;
    glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) => rotated;
    glScalef(x: GLfloat, y: GLfloat, z: GLfloat) => scalef;
    glScaled(x: GLdouble, y: GLdouble, z: GLdouble) => scaled;
    glOrtho(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, near: GLdouble, far: GLdouble) => ortho;
    glFrustum(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, near: GLdouble, far: GLdouble) => frustum;
}

vector! {
    glLoadMatrixf(GLfloat; 16) => load_matrixf;
    glMultMatrixf(GLfloat; 16) => mult_matrixf;
    glLoadMatrixd(GLdouble; 16) => load_matrixd;
    glMultMatrixd(GLdouble; 16) => mult_matrixd;
    glLoadTransposeMatrixf(GLfloat; 16) => load_transpose_matrixf;
    glLoadTransposeMatrixd(GLdouble; 16) => load_transpose_matrixd;
    glMultTransposeMatrixf(GLfloat; 16) => mult_transpose_matrixf;
    glMultTransposeMatrixd(GLdouble; 16) => mult_transpose_matrixd;
    glLoadTransposeMatrixfARB(GLfloat; 16) => load_transpose_matrixf;
    glLoadTransposeMatrixdARB(GLdouble; 16) => load_transpose_matrixd;
    glMultTransposeMatrixfARB(GLfloat; 16) => mult_transpose_matrixf;
    glMultTransposeMatrixdARB(GLdouble; 16) => mult_transpose_matrixd;
}
