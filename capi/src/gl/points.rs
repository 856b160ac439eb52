//! GL 1.4's point parameters (`GL_ARB_point_parameters`, `GL_EXT_point_parameters`): the
//! scalar forms pass straight through; the vector forms read as many values as the name takes.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::types::*;
use gleval::gl::Gl;

forward! {
    glPointParameterf(pname: GLenum, param: GLfloat) => point_parameterf;
    glPointParameterfARB(pname: GLenum, param: GLfloat) => point_parameterf;
    glPointParameterfEXT(pname: GLenum, param: GLfloat) => point_parameterf;
    glPointParameteri(pname: GLenum, param: GLint) => point_parameteri;
}

/// The `v` forms: `Gl::point_parameter_count` values of `T` read from `params`.
macro_rules! point_parameter_v {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "` of the values the name takes.")]
            unsafe fn $name(pname: GLenum, params: *const $t) {
                let params = unsafe { array(params, Some(Gl::point_parameter_count(pname))) };
                with_gl(|gl| gl.$method(pname, params))
            }
        })*
    };
}

point_parameter_v! {
    glPointParameterfv(GLfloat) => point_parameterfv;
    glPointParameterfvARB(GLfloat) => point_parameterfv;
    glPointParameterfvEXT(GLfloat) => point_parameterfv;
    glPointParameteriv(GLint) => point_parameteriv;
}
