//! GL 1.3's texture units (GL_ARB_multitexture), by both names: `glActiveTextureARB` (the core
//! name is with the other state calls), `glClientActiveTexture` and every `glMultiTexCoord`.

use gleval::gl::types::*;

forward! {
    glActiveTextureARB(texture: GLenum) => active_texture;
    glClientActiveTexture(texture: GLenum) => client_active_texture;
    glClientActiveTextureARB(texture: GLenum) => client_active_texture;
    glMultiTexCoord1s(target: GLenum, s: GLshort) => multi_tex_coord1s;
    glMultiTexCoord1i(target: GLenum, s: GLint) => multi_tex_coord1i;
    glMultiTexCoord1f(target: GLenum, s: GLfloat) => multi_tex_coord1f;
    glMultiTexCoord1d(target: GLenum, s: GLdouble) => multi_tex_coord1d;
    glMultiTexCoord2s(target: GLenum, s: GLshort, t: GLshort) => multi_tex_coord2s;
    glMultiTexCoord2i(target: GLenum, s: GLint, t: GLint) => multi_tex_coord2i;
    glMultiTexCoord2f(target: GLenum, s: GLfloat, t: GLfloat) => multi_tex_coord2f;
    glMultiTexCoord2d(target: GLenum, s: GLdouble, t: GLdouble) => multi_tex_coord2d;
    glMultiTexCoord3s(target: GLenum, s: GLshort, t: GLshort, r: GLshort) => multi_tex_coord3s;
    glMultiTexCoord3i(target: GLenum, s: GLint, t: GLint, r: GLint) => multi_tex_coord3i;
    glMultiTexCoord3f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) => multi_tex_coord3f;
    glMultiTexCoord3d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) => multi_tex_coord3d;
    glMultiTexCoord4s(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort) => multi_tex_coord4s;
    glMultiTexCoord4i(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) => multi_tex_coord4i;
    glMultiTexCoord4f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) => multi_tex_coord4f;
    glMultiTexCoord4d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) => multi_tex_coord4d;
    glMultiTexCoord1sARB(target: GLenum, s: GLshort) => multi_tex_coord1s;
    glMultiTexCoord1iARB(target: GLenum, s: GLint) => multi_tex_coord1i;
    glMultiTexCoord1fARB(target: GLenum, s: GLfloat) => multi_tex_coord1f;
    glMultiTexCoord1dARB(target: GLenum, s: GLdouble) => multi_tex_coord1d;
    glMultiTexCoord2sARB(target: GLenum, s: GLshort, t: GLshort) => multi_tex_coord2s;
    glMultiTexCoord2iARB(target: GLenum, s: GLint, t: GLint) => multi_tex_coord2i;
    glMultiTexCoord2fARB(target: GLenum, s: GLfloat, t: GLfloat) => multi_tex_coord2f;
    glMultiTexCoord2dARB(target: GLenum, s: GLdouble, t: GLdouble) => multi_tex_coord2d;
    glMultiTexCoord3sARB(target: GLenum, s: GLshort, t: GLshort, r: GLshort) => multi_tex_coord3s;
    glMultiTexCoord3iARB(target: GLenum, s: GLint, t: GLint, r: GLint) => multi_tex_coord3i;
    glMultiTexCoord3fARB(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) => multi_tex_coord3f;
    glMultiTexCoord3dARB(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) => multi_tex_coord3d;
    glMultiTexCoord4sARB(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort) => multi_tex_coord4s;
    glMultiTexCoord4iARB(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) => multi_tex_coord4i;
    glMultiTexCoord4fARB(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) => multi_tex_coord4f;
    glMultiTexCoord4dARB(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) => multi_tex_coord4d;
}

/// Entry points taking a unit and one fixed-size array (`glMultiTexCoord2fv(target, v)`
/// reads 2 values).
macro_rules! unit_vector {
    ($($name:ident($t:ty; $n:expr) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(target: GLenum, v: *const $t) {
                $crate::context::with_gl(|gl| gl.$method(target, unsafe { $crate::memory::array(v, Some($n)) }))
            }
        })*
    };
}

unit_vector! {
    glMultiTexCoord1sv(GLshort; 1) => multi_tex_coord1sv;
    glMultiTexCoord1iv(GLint; 1) => multi_tex_coord1iv;
    glMultiTexCoord1fv(GLfloat; 1) => multi_tex_coord1fv;
    glMultiTexCoord1dv(GLdouble; 1) => multi_tex_coord1dv;
    glMultiTexCoord2sv(GLshort; 2) => multi_tex_coord2sv;
    glMultiTexCoord2iv(GLint; 2) => multi_tex_coord2iv;
    glMultiTexCoord2fv(GLfloat; 2) => multi_tex_coord2fv;
    glMultiTexCoord2dv(GLdouble; 2) => multi_tex_coord2dv;
    glMultiTexCoord3sv(GLshort; 3) => multi_tex_coord3sv;
    glMultiTexCoord3iv(GLint; 3) => multi_tex_coord3iv;
    glMultiTexCoord3fv(GLfloat; 3) => multi_tex_coord3fv;
    glMultiTexCoord3dv(GLdouble; 3) => multi_tex_coord3dv;
    glMultiTexCoord4sv(GLshort; 4) => multi_tex_coord4sv;
    glMultiTexCoord4iv(GLint; 4) => multi_tex_coord4iv;
    glMultiTexCoord4fv(GLfloat; 4) => multi_tex_coord4fv;
    glMultiTexCoord4dv(GLdouble; 4) => multi_tex_coord4dv;
    glMultiTexCoord1svARB(GLshort; 1) => multi_tex_coord1sv;
    glMultiTexCoord1ivARB(GLint; 1) => multi_tex_coord1iv;
    glMultiTexCoord1fvARB(GLfloat; 1) => multi_tex_coord1fv;
    glMultiTexCoord1dvARB(GLdouble; 1) => multi_tex_coord1dv;
    glMultiTexCoord2svARB(GLshort; 2) => multi_tex_coord2sv;
    glMultiTexCoord2ivARB(GLint; 2) => multi_tex_coord2iv;
    glMultiTexCoord2fvARB(GLfloat; 2) => multi_tex_coord2fv;
    glMultiTexCoord2dvARB(GLdouble; 2) => multi_tex_coord2dv;
    glMultiTexCoord3svARB(GLshort; 3) => multi_tex_coord3sv;
    glMultiTexCoord3ivARB(GLint; 3) => multi_tex_coord3iv;
    glMultiTexCoord3fvARB(GLfloat; 3) => multi_tex_coord3fv;
    glMultiTexCoord3dvARB(GLdouble; 3) => multi_tex_coord3dv;
    glMultiTexCoord4svARB(GLshort; 4) => multi_tex_coord4sv;
    glMultiTexCoord4ivARB(GLint; 4) => multi_tex_coord4iv;
    glMultiTexCoord4fvARB(GLfloat; 4) => multi_tex_coord4fv;
    glMultiTexCoord4dvARB(GLdouble; 4) => multi_tex_coord4dv;
}
