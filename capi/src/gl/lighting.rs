//! Lights, materials, the light model and shading.

use crate::context::with_gl;
use crate::memory::array;
use gleval::gl::consts::*;
use gleval::gl::types::*;

/// `GL_COLOR_INDEXES` (GL 1.1 table 2.10), a material name `Gl` does not take.
const GL_COLOR_INDEXES: GLenum = 0x1603;

forward! {
    glLightf(light: GLenum, pname: GLenum, param: GLfloat) => light_f;
    glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) => material_f;
    glLightModeli(pname: GLenum, param: GLint) => light_model_i;
    glColorMaterial(face: GLenum, mode: GLenum) => color_material;
    glShadeModel(mode: GLenum) => shade_model;
}

/// Values `glLightfv`, `glMaterialfv` and `glLightModelfv` read for `pname` (GL 1.1 tables
/// 2.8-2.10): colours and positions 4, the spot direction and colour indexes 3, the rest 1.
fn light_values(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT
        | GL_DIFFUSE
        | GL_SPECULAR
        | GL_POSITION
        | GL_EMISSION
        | GL_AMBIENT_AND_DIFFUSE
        | GL_LIGHT_MODEL_AMBIENT => 4,
        GL_SPOT_DIRECTION | GL_COLOR_INDEXES => 3,
        _ => 1,
    }
}

entry! {
    /// `glLightfv`: `Gl::light_fv`.
    unsafe fn glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(light_values(pname))) };
        with_gl(|gl| gl.light_fv(light, pname, params))
    }
}

entry! {
    /// `glMaterialfv`: `Gl::material_fv`.
    unsafe fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(light_values(pname))) };
        with_gl(|gl| gl.material_fv(face, pname, params))
    }
}

entry! {
    /// `glLightModelfv`: `Gl::light_model_fv`.
    unsafe fn glLightModelfv(pname: GLenum, params: *const GLfloat) {
        let params = unsafe { array(params, Some(light_values(pname))) };
        with_gl(|gl| gl.light_model_fv(pname, params))
    }
}
