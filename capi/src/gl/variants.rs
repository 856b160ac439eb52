//! The type variants of the per-vertex calls (`glColor3b` … `glRasterPos4sv`, `glRect*v`, GL
//! 1.4's `glSecondaryColor3*` with their `EXT` names):
//! `Gl`'s converting forms (`src/gl/variants.rs`), forwarded.

use gleval::gl::types::*;

forward! {
    glColor3b(r: GLbyte, g: GLbyte, b: GLbyte) => color3b;
    glColor3s(r: GLshort, g: GLshort, b: GLshort) => color3s;
    glColor3i(r: GLint, g: GLint, b: GLint) => color3i;
    glColor3d(r: GLdouble, g: GLdouble, b: GLdouble) => color3d;
    glColor3us(r: GLushort, g: GLushort, b: GLushort) => color3us;
    glColor3ui(r: GLuint, g: GLuint, b: GLuint) => color3ui;
    glColor4b(r: GLbyte, g: GLbyte, b: GLbyte, a: GLbyte) => color4b;
    glColor4s(r: GLshort, g: GLshort, b: GLshort, a: GLshort) => color4s;
    glColor4i(r: GLint, g: GLint, b: GLint, a: GLint) => color4i;
    glColor4d(r: GLdouble, g: GLdouble, b: GLdouble, a: GLdouble) => color4d;
    glColor4ub(r: GLubyte, g: GLubyte, b: GLubyte, a: GLubyte) => color4ub;
    glColor4us(r: GLushort, g: GLushort, b: GLushort, a: GLushort) => color4us;
    glColor4ui(r: GLuint, g: GLuint, b: GLuint, a: GLuint) => color4ui;
    glNormal3b(x: GLbyte, y: GLbyte, z: GLbyte) => normal3b;
    glNormal3s(x: GLshort, y: GLshort, z: GLshort) => normal3s;
    glNormal3i(x: GLint, y: GLint, z: GLint) => normal3i;
    glNormal3d(x: GLdouble, y: GLdouble, z: GLdouble) => normal3d;
    glVertex2i(x: GLint, y: GLint) => vertex2i;
    glVertex2s(x: GLshort, y: GLshort) => vertex2s;
    glVertex3i(x: GLint, y: GLint, z: GLint) => vertex3i;
    glVertex3s(x: GLshort, y: GLshort, z: GLshort) => vertex3s;
    glVertex4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) => vertex4d;
    glVertex4i(x: GLint, y: GLint, z: GLint, w: GLint) => vertex4i;
    glVertex4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) => vertex4s;
    glTexCoord1d(s: GLdouble) => tex_coord1d;
    glTexCoord1i(s: GLint) => tex_coord1i;
    glTexCoord1s(s: GLshort) => tex_coord1s;
    glTexCoord2d(s: GLdouble, t: GLdouble) => tex_coord2d;
    glTexCoord2i(s: GLint, t: GLint) => tex_coord2i;
    glTexCoord2s(s: GLshort, t: GLshort) => tex_coord2s;
    glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble) => tex_coord3d;
    glTexCoord3i(s: GLint, t: GLint, r: GLint) => tex_coord3i;
    glTexCoord3s(s: GLshort, t: GLshort, r: GLshort) => tex_coord3s;
    glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) => tex_coord4d;
    glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint) => tex_coord4i;
    glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort) => tex_coord4s;
    glRasterPos2s(x: GLshort, y: GLshort) => raster_pos2s;
    glRasterPos3s(x: GLshort, y: GLshort, z: GLshort) => raster_pos3s;
    glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint) => raster_pos4i;
    glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) => raster_pos4s;
    glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) => rects;
    glSecondaryColor3b(r: GLbyte, g: GLbyte, b: GLbyte) => secondary_color3b;
    glSecondaryColor3s(r: GLshort, g: GLshort, b: GLshort) => secondary_color3s;
    glSecondaryColor3i(r: GLint, g: GLint, b: GLint) => secondary_color3i;
    glSecondaryColor3d(r: GLdouble, g: GLdouble, b: GLdouble) => secondary_color3d;
    glSecondaryColor3ub(r: GLubyte, g: GLubyte, b: GLubyte) => secondary_color3ub;
    glSecondaryColor3us(r: GLushort, g: GLushort, b: GLushort) => secondary_color3us;
    glSecondaryColor3ui(r: GLuint, g: GLuint, b: GLuint) => secondary_color3ui;
    glSecondaryColor3f(r: GLfloat, g: GLfloat, b: GLfloat) => secondary_color3f;
    glSecondaryColor3bEXT(r: GLbyte, g: GLbyte, b: GLbyte) => secondary_color3b;
    glSecondaryColor3sEXT(r: GLshort, g: GLshort, b: GLshort) => secondary_color3s;
    glSecondaryColor3iEXT(r: GLint, g: GLint, b: GLint) => secondary_color3i;
    glSecondaryColor3dEXT(r: GLdouble, g: GLdouble, b: GLdouble) => secondary_color3d;
    glSecondaryColor3ubEXT(r: GLubyte, g: GLubyte, b: GLubyte) => secondary_color3ub;
    glSecondaryColor3usEXT(r: GLushort, g: GLushort, b: GLushort) => secondary_color3us;
    glSecondaryColor3uiEXT(r: GLuint, g: GLuint, b: GLuint) => secondary_color3ui;
    glSecondaryColor3fEXT(r: GLfloat, g: GLfloat, b: GLfloat) => secondary_color3f;
    glFogCoordf(coord: GLfloat) => fog_coordf;
    glFogCoordd(coord: GLdouble) => fog_coordd;
    glFogCoordfEXT(coord: GLfloat) => fog_coordf;
    glFogCoorddEXT(coord: GLdouble) => fog_coordd;
}

vector! {
    glSecondaryColor3bv(GLbyte; 3) => secondary_color3bv;
    glSecondaryColor3sv(GLshort; 3) => secondary_color3sv;
    glSecondaryColor3iv(GLint; 3) => secondary_color3iv;
    glSecondaryColor3dv(GLdouble; 3) => secondary_color3dv;
    glSecondaryColor3ubv(GLubyte; 3) => secondary_color3ubv;
    glSecondaryColor3usv(GLushort; 3) => secondary_color3usv;
    glSecondaryColor3uiv(GLuint; 3) => secondary_color3uiv;
    glSecondaryColor3fv(GLfloat; 3) => secondary_color3fv;
    glSecondaryColor3bvEXT(GLbyte; 3) => secondary_color3bv;
    glSecondaryColor3svEXT(GLshort; 3) => secondary_color3sv;
    glSecondaryColor3ivEXT(GLint; 3) => secondary_color3iv;
    glSecondaryColor3dvEXT(GLdouble; 3) => secondary_color3dv;
    glSecondaryColor3ubvEXT(GLubyte; 3) => secondary_color3ubv;
    glSecondaryColor3usvEXT(GLushort; 3) => secondary_color3usv;
    glSecondaryColor3uivEXT(GLuint; 3) => secondary_color3uiv;
    glSecondaryColor3fvEXT(GLfloat; 3) => secondary_color3fv;
    glFogCoordfv(GLfloat; 1) => fog_coordfv;
    glFogCoorddv(GLdouble; 1) => fog_coorddv;
    glFogCoordfvEXT(GLfloat; 1) => fog_coordfv;
    glFogCoorddvEXT(GLdouble; 1) => fog_coorddv;
    glColor3bv(GLbyte; 3) => color3bv;
    glColor3sv(GLshort; 3) => color3sv;
    glColor3iv(GLint; 3) => color3iv;
    glColor3dv(GLdouble; 3) => color3dv;
    glColor3ubv(GLubyte; 3) => color3ubv;
    glColor3usv(GLushort; 3) => color3usv;
    glColor3uiv(GLuint; 3) => color3uiv;
    glColor4bv(GLbyte; 4) => color4bv;
    glColor4sv(GLshort; 4) => color4sv;
    glColor4iv(GLint; 4) => color4iv;
    glColor4dv(GLdouble; 4) => color4dv;
    glColor4ubv(GLubyte; 4) => color4ubv;
    glColor4usv(GLushort; 4) => color4usv;
    glColor4uiv(GLuint; 4) => color4uiv;
    glNormal3bv(GLbyte; 3) => normal3bv;
    glNormal3sv(GLshort; 3) => normal3sv;
    glNormal3iv(GLint; 3) => normal3iv;
    glNormal3dv(GLdouble; 3) => normal3dv;
    glVertex2dv(GLdouble; 2) => vertex2dv;
    glVertex2iv(GLint; 2) => vertex2iv;
    glVertex2sv(GLshort; 2) => vertex2sv;
    glVertex3dv(GLdouble; 3) => vertex3dv;
    glVertex3iv(GLint; 3) => vertex3iv;
    glVertex3sv(GLshort; 3) => vertex3sv;
    glVertex4dv(GLdouble; 4) => vertex4dv;
    glVertex4iv(GLint; 4) => vertex4iv;
    glVertex4sv(GLshort; 4) => vertex4sv;
    glTexCoord1fv(GLfloat; 1) => tex_coord1fv;
    glTexCoord1dv(GLdouble; 1) => tex_coord1dv;
    glTexCoord1iv(GLint; 1) => tex_coord1iv;
    glTexCoord1sv(GLshort; 1) => tex_coord1sv;
    glTexCoord2dv(GLdouble; 2) => tex_coord2dv;
    glTexCoord2iv(GLint; 2) => tex_coord2iv;
    glTexCoord2sv(GLshort; 2) => tex_coord2sv;
    glTexCoord3fv(GLfloat; 3) => tex_coord3fv;
    glTexCoord3dv(GLdouble; 3) => tex_coord3dv;
    glTexCoord3iv(GLint; 3) => tex_coord3iv;
    glTexCoord3sv(GLshort; 3) => tex_coord3sv;
    glTexCoord4fv(GLfloat; 4) => tex_coord4fv;
    glTexCoord4dv(GLdouble; 4) => tex_coord4dv;
    glTexCoord4iv(GLint; 4) => tex_coord4iv;
    glTexCoord4sv(GLshort; 4) => tex_coord4sv;
    glRasterPos2sv(GLshort; 2) => raster_pos2sv;
    glRasterPos3iv(GLint; 3) => raster_pos3iv;
    glRasterPos3sv(GLshort; 3) => raster_pos3sv;
    glRasterPos4dv(GLdouble; 4) => raster_pos4dv;
    glRasterPos4iv(GLint; 4) => raster_pos4iv;
    glRasterPos4sv(GLshort; 4) => raster_pos4sv;
}

/// `glRect*v`: two corners of 2 values each.
macro_rules! rect_v {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`, 2 values at each pointer.")]
            unsafe fn $name(v1: *const $t, v2: *const $t) {
                let (v1, v2) = unsafe { ($crate::memory::array(v1, Some(2)), $crate::memory::array(v2, Some(2))) };
                $crate::context::with_gl(|gl| gl.$method(v1, v2))
            }
        })*
    };
}

rect_v! {
    glRectfv(GLfloat) => rectfv;
    glRectdv(GLdouble) => rectdv;
    glRectiv(GLint) => rectiv;
    glRectsv(GLshort) => rectsv;
}
