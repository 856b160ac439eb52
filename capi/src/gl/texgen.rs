//! `glTexGen`: texture coordinates generated per vertex (`Gl::tex_gen*`).

use crate::context::with_gl;
use crate::memory::{array, array_mut};
use gleval::gl::types::*;
use gleval::gl::Gl;

forward! {
    glTexGeni(coord: GLenum, pname: GLenum, param: GLint) => tex_geni;
    glTexGenf(coord: GLenum, pname: GLenum, param: GLfloat) => tex_genf;
    glTexGend(coord: GLenum, pname: GLenum, param: GLdouble) => tex_gend;
}

entry! {
    /// `glTexGenfv`.
    unsafe fn glTexGenfv(coord: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(Gl::tex_gen_param_count(pname))) };
        with_gl(|gl| gl.tex_genfv(coord, pname, params))
    }
}

entry! {
    /// `glTexGeniv`.
    unsafe fn glTexGeniv(coord: GLenum, pname: GLenum, params: *const GLint) {
        let params = unsafe { array(params, Some(Gl::tex_gen_param_count(pname))) };
        with_gl(|gl| gl.tex_geniv(coord, pname, params))
    }
}

entry! {
    /// `glTexGendv`.
    unsafe fn glTexGendv(coord: GLenum, pname: GLenum, params: *const GLdouble) {
        let params = unsafe { array(params, Some(Gl::tex_gen_param_count(pname))) };
        with_gl(|gl| gl.tex_gendv(coord, pname, params))
    }
}

entry! {
    /// `glGetTexGenfv`.
    unsafe fn glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut GLfloat) {
        let params = unsafe { array_mut(params, Gl::tex_gen_param_count(pname)) };
        with_gl(|gl| gl.get_tex_genfv(coord, pname, params))
    }
}

entry! {
    /// `glGetTexGeniv`.
    unsafe fn glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, Gl::tex_gen_param_count(pname)) };
        with_gl(|gl| gl.get_tex_geniv(coord, pname, params))
    }
}
