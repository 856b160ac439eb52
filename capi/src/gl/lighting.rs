//! Lights, materials, the light model and shading.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::types::*;
use gleval::gl::Gl;

forward! {
    glLightf(light: GLenum, pname: GLenum, param: GLfloat) => light_f;
    glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) => material_f;
    glLightModeli(pname: GLenum, param: GLint) => light_model_i;
    glColorMaterial(face: GLenum, mode: GLenum) => color_material;
    glShadeModel(mode: GLenum) => shade_model;
}

entry! {
    /// `glLightfv`: `Gl::light_fv`.
    unsafe fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(Gl::light_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.light_fv(light, pname, params))
    }
}

entry! {
    /// `glMaterialfv`: `Gl::material_fv`.
    unsafe fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(Gl::material_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.material_fv(face, pname, params))
    }
}

entry! {
    /// `glLightModelfv`: `Gl::light_model_fv`.
    unsafe fn glLightModelfv(pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(Gl::light_model_param_count(pname).unwrap_or(0))) };
        with_gl(|gl| gl.light_model_fv(pname, params))
    }
}
